//! Every test scene file (`runtime/tests/scenes/**/*.rt`) checks without errors, as `rtc check` would
//! check it, so a scene a GPU test renders is a valid `.rt` file as it stands, before the test
//! overrides any of its constants, and each scene folder belongs to a suite (see `common/scene.rs`
//! for the convention; `tests/examples.rs` runs the same checks on `tests/scenes/`). Needs no GPU.
//!
//! Also checks the harness on its own: constant substitution and pixel checks.

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::{const_value_range, SceneFile};

#[test]
fn every_test_scene_file_checks() {
    common::scene::assert_every_scene_file_checks(10);
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
    common::scene::assert_every_scene_folder_is_a_suite();
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
