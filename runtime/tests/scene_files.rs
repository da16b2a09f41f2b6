//! Every test scene file (`runtime/tests/**/*.rt`) checks without errors, as `rtc check` would check
//! it, so a scene a GPU test renders is a valid `.rt` file as it stands, before the test overrides
//! any of its constants (see `common/scene.rs` for the convention). Needs no GPU.
//!
//! Also checks the harness on its own: constant substitution and pixel checks.

mod common;

use std::path::{Path, PathBuf};

use common::image::{PixelCheck, Tolerance};
use common::scene::{const_value_range, scenes_dir, SceneFile};
use rtc_compiler::driver::{check_paths, Options};

/// The `.rt` files under `dir`, recursively, sorted.
fn rt_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rt_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rt") {
            out.push(path);
        }
    }
}

#[test]
fn every_test_scene_file_checks() {
    let mut files = Vec::new();
    rt_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests"),
        &mut files,
    );
    assert!(
        files.len() >= 10,
        "only {} test scene files found under runtime/tests",
        files.len()
    );
    let mut failures = Vec::new();
    for file in &files {
        let checked = check_paths(std::slice::from_ref(file), &Options::default());
        let rendered =
            rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false);
        if checked.has_errors() || checked.program.is_none() {
            failures.push(format!("{}:\n{rendered}", file.display()));
        } else if !checked.diagnostics.is_empty() {
            eprintln!("{}: warnings:\n{rendered}", file.display());
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} test scene files do not check:\n{}",
        failures.len(),
        files.len(),
        failures.join("\n")
    );
}

#[test]
fn a_constant_override_replaces_only_that_constants_value() {
    let text =
        "const A: u32 = 1u;\nconst AB: vec2f = vec2f(\n    1.0, 2.0);\n  const B: f32 = 2.0;\n";
    let (s, e) = const_value_range(text, "AB").expect("AB");
    assert_eq!(&text[s..e], " vec2f(\n    1.0, 2.0)");
    let (s, e) = const_value_range(text, "B").expect("B");
    assert_eq!(&text[s..e], " 2.0");
    assert_eq!(const_value_range(text, "C"), None);
    assert_eq!(const_value_range(text, "ABC"), None);
}

#[test]
fn every_scene_folder_is_named_after_a_test_suite() {
    let tests = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    for entry in std::fs::read_dir(scenes_dir())
        .expect("runtime/tests/scenes")
        .flatten()
    {
        if !entry.path().is_dir() {
            continue; // README.md
        }
        let suite = entry.file_name().to_string_lossy().into_owned();
        assert!(
            tests.join(format!("{suite}.rs")).is_file(),
            "runtime/tests/scenes/{suite}/ belongs to no test suite runtime/tests/{suite}.rs"
        );
    }
}

#[test]
#[should_panic(expected = "declares no `const NOT_THERE")]
fn overriding_a_constant_the_file_lacks_fails() {
    let _ = SceneFile::open("render/lit_quad.rt").set("NOT_THERE", 1);
}

#[test]
fn a_pixel_check_counts_the_channels_over_and_states_the_errors() {
    let mut check = PixelCheck::new("demo");
    check.pixel(
        (0, 0),
        [1.0, 2.0, 3.0, 1.0],
        &[1.0, 2.0, 3.0],
        Tolerance::EXACT,
    );
    check.channel((1, 0), 0, 1.0005, 1.0, Tolerance::rel(1e-3));
    check.channel((2, 0), 1, 1.01, 1.0, Tolerance::rel(1e-3));
    check.channel((3, 0), 2, f64::NAN, 1.0, Tolerance::abs(1.0));
    assert_eq!(check.checked(), 6);
    let message = std::panic::catch_unwind(|| check.assert())
        .expect_err("two channels are over")
        .downcast::<String>()
        .expect("a formatted message");
    assert!(
        message.contains("demo: 2 of 6 channels over their tolerance (0 allowed)")
            && message.contains("pixel (2, 0) channel 1: got 1.01, want 1")
            && message.contains("pixel (3, 0) channel 2: got NaN"),
        "{message}"
    );
    check.allow_over(2).assert();
}
