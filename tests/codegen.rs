//! Golden snapshots of the code rtc emits, for all five targets.
//!
//! Cases:
//! - every `tests/codegen/<name>.rt` declares `fn test_fn(…)`; it is lowered with the test entry point
//!   of `rtc_compiler::lower::testgen` (inputs and outputs through storage buffers);
//! - every example scene (`examples/<name>/scene.rt`) is compiled to its specialised kernel.
//!
//! Each module is compacted (`naga::compact`, so names and order are stable) and written for every
//! target to `tests/codegen/out/<name>/kernel.{wgsl,spv,hlsl,metal,comp}`; the test fails on any
//! difference from the committed files. `RTC_BLESS=1 cargo test -p rtc-tests --test codegen` rewrites
//! them; review with `git diff tests/codegen/out` and commit. CI also runs `git diff --exit-code` on the
//! folder after the tests.

use rtc_compiler::back::{self, Resource, ResourceKind, Target};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{self, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::lower::{testgen, NoIntrinsics};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn bless() -> bool {
    std::env::var_os("RTC_BLESS").is_some_and(|v| v != "0")
}

/// Compares (or, when blessing, writes) the five outputs of `module`; returns the differences.
fn snapshot(name: &str, module: &naga::Module, entry: &str, resources: &[Resource]) -> Vec<String> {
    let dir = root().join("tests/codegen/out").join(name);
    let mut problems = Vec::new();
    for t in Target::ALL {
        let bytes = match back::write(module, t, entry, resources) {
            Ok(b) => b,
            Err(e) => {
                problems.push(format!("{name}: {}: {e}", t.name()));
                continue;
            }
        };
        let ext = t.file_name().rsplit('.').next().unwrap_or("out");
        let path = dir.join(format!("kernel.{ext}"));
        if bless() {
            std::fs::create_dir_all(&dir).expect("create the snapshot folder");
            std::fs::write(&path, &bytes).expect("write a snapshot");
            continue;
        }
        match std::fs::read(&path) {
            Ok(old) if old == bytes => {}
            Ok(old) => {
                let first = old
                    .iter()
                    .zip(&bytes)
                    .position(|(a, b)| a != b)
                    .unwrap_or(old.len().min(bytes.len()));
                let line = bytes[..first].iter().filter(|&&b| b == b'\n').count() + 1;
                problems.push(format!(
                    "{}: differs from the snapshot (first difference near line {line}; {} bytes now, {} before)",
                    path.display(),
                    bytes.len(),
                    old.len()
                ));
            }
            Err(_) => problems.push(format!(
                "{}: no snapshot (run with RTC_BLESS=1)",
                path.display()
            )),
        }
    }
    problems
}

fn rt_cases() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("tests/codegen"))
        .expect("tests/codegen")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "rt"))
        .collect();
    v.sort();
    v
}

#[test]
fn small_functions_match_their_snapshots() {
    let mut problems = Vec::new();
    let cases = rt_cases();
    assert!(
        cases.len() >= 4,
        "expected the codegen cases in tests/codegen/"
    );
    for path in cases {
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let checked =
            rtc_compiler::driver::check_paths(std::slice::from_ref(&path), &Options::default());
        let Some(program) = checked.program.as_ref() else {
            problems.push(format!(
                "{name}: does not check:\n{}",
                rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false)
            ));
            continue;
        };
        let Some((f, _)) = program.functions.iter().find(|(_, f)| f.name == "test_fn") else {
            problems.push(format!("{name}: no `test_fn`"));
            continue;
        };
        let mut kernel = match testgen::test_entry(program, &checked.sources, f, &mut NoIntrinsics)
        {
            Ok(k) => k,
            Err(e) => {
                problems.push(format!("{name}: lowering failed: {e:?}"));
                continue;
            }
        };
        naga::compact::compact(&mut kernel.module, naga::compact::KeepUnused::No);
        let entry = kernel
            .module
            .entry_points
            .first()
            .map(|e| e.name.clone())
            .unwrap_or_default();
        let resources = [
            Resource {
                group: 0,
                binding: 0,
                kind: ResourceKind::StorageRead,
            },
            Resource {
                group: 0,
                binding: 1,
                kind: ResourceKind::StorageReadWrite,
            },
        ];
        problems.extend(snapshot(&name, &kernel.module, &entry, &resources));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn example_kernels_match_their_snapshots() {
    let mut problems = Vec::new();
    let mut examples: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .expect("examples/")
        .flatten()
        .map(|e| e.path().join("scene.rt"))
        .filter(|p| p.is_file())
        .collect();
    examples.sort();
    for path in examples {
        let name = path
            .parent()
            .and_then(|p| p.file_name())
            .map(|n| format!("example_{}", n.to_string_lossy()))
            .unwrap_or_default();
        let c = match kernel::compile_scene(
            std::slice::from_ref(&path),
            None,
            &Options::default(),
            &LinkOptions::default(),
        ) {
            Ok(c) => c,
            Err(f) => {
                problems.push(format!(
                    "{name}:\n{}",
                    rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
                ));
                continue;
            }
        };
        let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
        problems.extend(snapshot(&name, &c.render, RENDER_ENTRY, &resources));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The listings of `rtc compile --emit hir` and `--emit naga` (`rtc_compiler::sema::hir::print`,
/// `back::naga_listing`), against golden files: for every small case, its module's HIR
/// (`out/<name>/program.hir`) and its test kernel's naga listing (`out/<name>/kernel.naga`); for the
/// hello example, its scene file's HIR (`out/example_hello/scene.hir`: a scene, evaluated). Files are
/// named relative to this crate's folder (the tests' working folder), so module names in the
/// listings do not depend on where the repository is. `RTC_BLESS=1` rewrites them.
#[test]
fn listings_match_their_goldens() {
    use rtc_compiler::sema::hir::{print, ModuleId, Program};
    use rtc_tests::golden::check_golden;
    let out = root().join("tests/codegen/out");
    let root_module = |p: &Program| {
        let i = p.modules.iter().position(|m| m.is_root).unwrap_or(0);
        print::module(p, ModuleId(i as u32))
    };
    let mut problems = Vec::new();
    for path in rt_cases() {
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let file = Path::new("codegen").join(path.file_name().unwrap_or_default());
        let checked = rtc_compiler::driver::check_paths(&[file], &Options::default());
        let Some(program) = checked.program.as_ref() else {
            problems.push(format!("{name}: does not check"));
            continue;
        };
        problems.extend(check_golden(
            &out.join(&name).join("program.hir"),
            &root_module(program),
        ));
        let Some((f, _)) = program.functions.iter().find(|(_, f)| f.name == "test_fn") else {
            problems.push(format!("{name}: no `test_fn`"));
            continue;
        };
        match testgen::test_entry(program, &checked.sources, f, &mut NoIntrinsics) {
            Ok(mut kernel) => {
                naga::compact::compact(&mut kernel.module, naga::compact::KeepUnused::No);
                match back::naga_listing(&kernel.module) {
                    Ok(text) => {
                        problems.extend(check_golden(&out.join(&name).join("kernel.naga"), &text))
                    }
                    Err(e) => problems.push(format!("{name}: {e}")),
                }
            }
            Err(e) => problems.push(format!("{name}: lowering failed: {e:?}")),
        }
    }
    let hello = PathBuf::from("../examples/hello/scene.rt");
    let checked = rtc_compiler::driver::check_paths(&[hello], &Options::default());
    match checked.program.as_ref() {
        Some(p) => problems.extend(check_golden(
            &out.join("example_hello/scene.hir"),
            &root_module(p),
        )),
        None => problems.push("examples/hello does not check".to_string()),
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
