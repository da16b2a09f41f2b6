//! Cross-target checks: every example, and a scene that links every standard-library program, is
//! compiled to all five targets (the megakernel, the bounds kernel and the wavefront model's seven
//! stage kernels), and each output is given to an independent validator:
//!
//! | target | check |
//! |---|---|
//! | SPIR-V | `spirv-val --target-env vulkan1.1` |
//! | GLSL | `glslangValidator -V` to SPIR-V, then `spirv-val` |
//! | WGSL | re-parsed and validated by naga; and Tint (`tint` on PATH) where available |
//! | HLSL | Slang's compiler library (`tests/tools/slangc.py` run by `$RTC_SLANG_PYTHON` or `python3`; `.ci/run` installs slangpy in a virtual environment) where available |
//! | MSL | no compiler exists on Linux: only naga's own validation for the MSL capabilities |
//!
//! With `CI=true`, `spirv-val` and `glslangValidator` must be present (`.ci/run` installs them); an
//! optional validator that is missing is reported by name, never silently skipped.

use rtc_compiler::back::{self, Target};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{self, CompiledScene, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "../runtime/tests/common/scratch.rs"]
mod scratch;

use scratch::Scratch;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn have(tool: &str) -> bool {
    Command::new(tool).arg("--version").output().is_ok()
}

fn required(tool: &str) -> bool {
    let present = have(tool);
    if !present {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "`{tool}` is required in CI (.ci/run installs it)"
        );
        eprintln!("SKIPPED {tool}: not installed (apt-get install spirv-tools glslang-tools)");
    }
    present
}

/// The Python that has slangpy: `RTC_SLANG_PYTHON` (set by `.ci/run`), else `python3`.
fn slang_python() -> String {
    std::env::var("RTC_SLANG_PYTHON").unwrap_or_else(|_| "python3".to_string())
}

fn slang_available() -> bool {
    Command::new(slang_python())
        .args(["-c", "import slangpy"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
}

fn run(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd
        .output()
        .map_err(|e| format!("{what}: cannot run: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "{what} rejected the output:\n{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// Validates every target of one compiled scene; returns the failures.
fn check_all_targets(name: &str, c: &CompiledScene, dir: &Path) -> Vec<String> {
    let mut failures = Vec::new();
    let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
    std::fs::create_dir_all(dir).expect("temp dir");
    let mut modules = vec![("kernel", &c.render, RENDER_ENTRY, resources.clone())];
    if let Some(b) = &c.bounds {
        modules.push(("bounds", b, kernel::BOUNDS_ENTRY, resources));
    }
    for s in c.stages.iter().flatten() {
        let resources = rtc_compiler::abi::resources(s.bindings.iter().copied());
        modules.push((s.stage.entry(), &s.module, s.stage.entry(), resources));
    }
    for (stem, module, entry, resources) in modules {
        for t in Target::ALL {
            let bytes = match back::write(module, t, entry, &resources) {
                Ok(b) => b,
                Err(e) => {
                    failures.push(format!("{name}/{stem}.{}: {e}", t.name()));
                    continue;
                }
            };
            let ext = t.file_name().rsplit('.').next().unwrap_or("out");
            let path = dir.join(format!("{stem}.{ext}"));
            std::fs::write(&path, &bytes).expect("write output");
            let result = match t {
                Target::SpirV if required("spirv-val") => run(
                    Command::new("spirv-val")
                        .args(["--target-env", "vulkan1.1"])
                        .arg(&path),
                    "spirv-val",
                ),
                Target::Glsl if required("glslangValidator") && required("spirv-val") => {
                    let spv = dir.join(format!("{stem}.glsl.spv"));
                    run(
                        Command::new("glslangValidator")
                            .args(["-V", "--target-env", "vulkan1.1", "-S", "comp", "-o"])
                            .arg(&spv)
                            .arg(&path),
                        "glslangValidator",
                    )
                    .and_then(|_| {
                        run(
                            Command::new("spirv-val")
                                .args(["--target-env", "vulkan1.1"])
                                .arg(&spv),
                            "spirv-val (GLSL)",
                        )
                    })
                }
                Target::Wgsl => {
                    let text = String::from_utf8_lossy(&bytes);
                    let reparsed = naga::front::wgsl::parse_str(&text)
                        .map_err(|e| format!("naga re-parse: {}", e.emit_to_string(&text)))
                        .and_then(|m| {
                            naga::valid::Validator::new(
                                naga::valid::ValidationFlags::all(),
                                Target::Wgsl.capabilities(),
                            )
                            .validate(&m)
                            .map(|_| ())
                            .map_err(|e| format!("naga re-validation: {e:?}"))
                        });
                    reparsed.and_then(|_| {
                        if have("tint") {
                            run(
                                Command::new("tint")
                                    .args(["-f", "wgsl", "-o"])
                                    .arg(dir.join("tint.wgsl"))
                                    .arg(&path),
                                "tint",
                            )
                        } else {
                            eprintln!("SKIPPED tint: not on PATH");
                            Ok(())
                        }
                    })
                }
                Target::Hlsl => {
                    if slang_available() {
                        let script = root().join("tests/tools/slangc.py");
                        run(
                            Command::new(slang_python())
                                .arg(script)
                                .arg(&path)
                                .args([
                                    "-target", "spirv", "-entry", entry, "-stage", "compute", "-o",
                                ])
                                .arg(dir.join(format!("{stem}.slang.spv"))),
                            "slang (HLSL)",
                        )
                    } else {
                        // `.ci/run` installs slangpy and sets RTC_SLANG_PYTHON: in CI the check must run.
                        assert!(
                            !(std::env::var("CI").as_deref() == Ok("true")
                                && std::env::var_os("RTC_SLANG_PYTHON").is_some()),
                            "RTC_SLANG_PYTHON is set but cannot import slangpy"
                        );
                        eprintln!("SKIPPED slang: `pip install slangpy` to compile HLSL");
                        Ok(())
                    }
                }
                _ => Ok(()),
            };
            if let Err(e) = result {
                failures.push(format!("{name}/{stem}.{}: {e}", t.name()));
            }
        }
    }
    failures
}

/// Compiles with the wavefront model's stage kernels too, so every stage is validated.
fn compile(paths: &[PathBuf], all: bool) -> CompiledScene {
    match kernel::compile_scene_with(
        paths,
        None,
        &Options::default(),
        &LinkOptions {
            all_programs: all,
            ..LinkOptions::default()
        },
        &kernel::KernelOptions {
            exec: Some(kernel::ExecModel::Wavefront),
            ..kernel::KernelOptions::default()
        },
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    }
}

fn examples() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .expect("examples/")
        .flatten()
        .map(|e| e.path().join("scene.rt"))
        .filter(|p| p.is_file())
        .collect();
    v.sort();
    v
}

#[test]
fn every_example_passes_every_validator() {
    let tmp = Scratch::new(&format!("targets-{}", std::process::id()));
    let mut failures = Vec::new();
    for ex in examples() {
        let name = ex
            .parent()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let c = compile(std::slice::from_ref(&ex), false);
        failures.extend(check_all_targets(&name, &c, &tmp.join(&name)));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// Every standard-library module except the prelude and the kernel, as `std/…` import paths.
fn stdlib_modules() -> Vec<String> {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<String>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .expect("stdlib")
            .flatten()
            .map(|e| e.path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "kernel") {
                    walk(&p, base, out);
                }
            } else if p.extension().is_some_and(|e| e == "rt")
                && p.file_name().is_some_and(|n| n != "prelude.rt")
            {
                let rel = p
                    .strip_prefix(base)
                    .expect("under stdlib")
                    .to_string_lossy()
                    .replace('\\', "/");
                out.push(format!("std/{rel}"));
            }
        }
    }
    let base = root().join("stdlib");
    let mut out = Vec::new();
    walk(&base, &base, &mut out);
    out
}

#[test]
fn every_stdlib_program_passes_every_validator() {
    // A scene importing every standard-library module, compiled unspecialised (--all-programs), links
    // every program of the standard library into one kernel. The import list is generated, so a new
    // stdlib module is covered without editing this test.
    let tmp = Scratch::new(&format!("targets-std-{}", std::process::id()));
    let modules = stdlib_modules();
    assert!(modules.len() >= 7, "found only {modules:?}");
    let mut text: String = modules
        .iter()
        .map(|m| format!("import \"{m}\";\n"))
        .collect();
    text.push_str(
        "scene all_stdlib {\n    camera Pinhole {}\n    object o { geometry: cube_mesh(), material: Lambert {} }\n}\n",
    );
    let scene = tmp.join("all_stdlib.rt");
    std::fs::write(&scene, text).expect("write the scene");
    let c = compile(&[scene], true);
    let failures = check_all_targets("all_stdlib", &c, &tmp);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
