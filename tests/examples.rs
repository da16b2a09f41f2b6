//! Every example renders and matches its committed reference image.
//!
//! **Which scenes.** Every `.rt` file directly inside an `examples/NAME/` folder that declares a scene
//! is rendered, each of its scenes separately (files without a scene, imported by others, are skipped).
//! **Which reference.** Next to the file: `reference.png` for `scene.rt` with one scene;
//! `reference-STEM.png` for another file `STEM.rt` with one scene (`examples/cameras/orthographic.rt`
//! → `reference-orthographic.png`); `reference-STEM-SCENE.png` for each scene of a file with several.
//!
//! **How.** Each scene is compiled by `compile_scene_with` (with the wavefront model's stage kernels)
//! and rendered by the runtime's `Renderer` with both execution models, megakernel and wavefront,
//! exactly as `rtc render --size WxH --spp N --exec MODEL` does (the same `RenderOptions::size` and `samples` overrides,
//! and its default `flatten`, so the static objects of a scene share one world-space BVH), at
//! [`WIDTH`] pixels wide, the height keeping the scene's aspect ratio, with the scene's samples per
//! pixel capped at [`MAX_SPP`] (the seed is the scene's, so the noise is the same every run). The image
//! is encoded as the PNG writer does (clamp, sRGB, 8 bits) and compared with the reference's bytes.
//!
//! **Metric and tolerance**, on 8-bit channel values: the PSNR (peak 255) must be at least
//! [`MIN_PSNR_DB`] and at most [`MAX_OUTLIER_FRACTION`] of the channels may differ by more than
//! [`OUTLIER_LEVELS`] levels. On lavapipe two renders of every example are bit-identical (PSNR ∞, no
//! channel off; measured by rendering every example twice), so the tolerance only leaves room for other
//! drivers' float rounding (a shadow ray flipping at an edge changes a few pixels a lot, hence the
//! outlier fraction rather than a maximum). Every render must also be free of NaN and infinity: the
//! kernel's count of non-finite samples and the image's non-finite pixels must both be zero. The two
//! execution models' renders are also compared with each other under the same metric (on lavapipe
//! they are bit-identical for every example).
//!
//! **Blessing.** `RTC_BLESS=1 cargo test -p rtc-tests --test examples` writes every reference anew (a
//! missing reference fails with that command). `RTC_EXAMPLES=a,b` limits the run (and the blessing) to
//! the example folders named. On a mismatch the render is written to the temp folder and the failure
//! message says where.
//!
//! **The stdlib programs the examples use** are also checked against values computed by hand, on
//! small scenes in `tests/scenes/examples/` (see the section at the end): a sphere light lights like a
//! point light of the same intensity, a spot light is a point light inside its cone and dark outside,
//! a directional light and an analytic box give the cosine law and the exact shadow, a sphere is hit
//! from inside, and `BvhMesh` finds the same nearest hits as the built-in mesh geometry. They are
//! compiled and rendered by the runtime's test harness (`runtime/tests/common/`), which also checks
//! every file of `tests/scenes/` without a GPU, as the runtime's `scene_files` test does its own.
//!
//! Every GPU test skips only when there is no GPU adapter at all, and then says so on stderr.

/// The GPU test harness the runtime's suites share (adapter, scene files, pixel checks); its scene
/// files here are those of `tests/scenes/` (see `runtime/tests/common/scene.rs`).
#[path = "../runtime/tests/common/mod.rs"]
mod common;

use common::scene::{const_value_range, SceneFile};
use common::{gpu_or_skip, temp_dir};
use std::path::{Path, PathBuf};
use std::time::Instant;

use rtc_compiler::driver::{check_paths, Options};
use rtc_compiler::kernel::{compile_scene_with, ExecModel, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::{read_image, to_srgb8, write_png, LinearImage, ToneMap};
use rtc_runtime::render::{RenderOptions, Renderer};
use rtc_tests::paths::{display_relative, repo_root};

/// Width of the test renders, in pixels.
const WIDTH: u32 = 128;
/// Most samples per pixel a test render takes.
const MAX_SPP: u32 = 16;
/// Lowest PSNR, in dB for 8-bit channels (peak 255).
const MIN_PSNR_DB: f64 = 40.0;
/// A channel off by more than this many 8-bit levels is an outlier.
const OUTLIER_LEVELS: u8 = 16;
/// Largest fraction of channels that may be outliers.
const MAX_OUTLIER_FRACTION: f64 = 0.002;

fn bless() -> bool {
    std::env::var_os("RTC_BLESS").is_some_and(|v| v != "0" && !v.is_empty())
}

/// The example folders to run: all, or those `RTC_EXAMPLES` names.
fn example_dirs() -> Vec<PathBuf> {
    let only: Option<Vec<String>> = std::env::var("RTC_EXAMPLES")
        .ok()
        .filter(|s| !s.trim().is_empty())
        .map(|s| s.split(',').map(|n| n.trim().to_owned()).collect());
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(repo_root().join("examples"))
        .expect("examples/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.is_dir())
        .filter(|p| {
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
            only.as_ref()
                .is_none_or(|only| name.is_some_and(|n| only.contains(&n)))
        })
        .collect();
    dirs.sort();
    dirs
}

/// One scene to render: its file, its name, and where its reference lives.
struct Case {
    file: PathBuf,
    scene: String,
    reference: PathBuf,
}

/// The scenes of the `.rt` files directly in `dir`, with their references (see the module docs).
fn cases_in(dir: &Path, failures: &mut Vec<String>) -> Vec<Case> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("an example folder")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "rt"))
        .collect();
    files.sort();
    let mut cases = Vec::new();
    for file in files {
        let checked = check_paths(std::slice::from_ref(&file), &Options::default());
        let Some(program) = checked.program.as_ref().filter(|_| !checked.has_errors()) else {
            failures.push(format!(
                "{}: does not check:\n{}",
                display_relative(&file),
                rtc_tests::render::render_relative(&checked)
            ));
            continue;
        };
        let scenes: Vec<String> = program
            .modules
            .iter()
            .filter(|m| m.is_root)
            .flat_map(|m| m.scenes.iter().map(|&s| program.scenes[s].name.clone()))
            .collect();
        let stem = file
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        for scene in &scenes {
            let name = match (scenes.len(), stem.as_str()) {
                (1, "scene") => "reference.png".to_owned(),
                (1, _) => format!("reference-{stem}.png"),
                _ => format!("reference-{stem}-{scene}.png"),
            };
            cases.push(Case {
                file: file.clone(),
                scene: scene.clone(),
                reference: dir.join(name),
            });
        }
    }
    cases
}

/// How far two 8-bit RGB images are apart.
struct Difference {
    psnr: f64,
    outliers: usize,
    max: u8,
    channels: usize,
}

fn difference(test: &[u8], reference: &[u8]) -> Difference {
    let mut sum_sq = 0.0f64;
    let mut outliers = 0;
    let mut max = 0u8;
    for (&a, &b) in test.iter().zip(reference) {
        let d = a.abs_diff(b);
        sum_sq += f64::from(d) * f64::from(d);
        outliers += usize::from(d > OUTLIER_LEVELS);
        max = max.max(d);
    }
    let mse = sum_sq / test.len().max(1) as f64;
    let psnr = if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0 * 255.0 / mse).log10()
    };
    Difference {
        psnr,
        outliers,
        max,
        channels: test.len(),
    }
}

/// Renders one case with both execution models, compares each render with the reference (or
/// blesses the megakernel's) and the two renders with each other; an error message on failure.
fn run_case(gpu: &Gpu, case: &Case, out_dir: &Path) -> Result<String, String> {
    let what = format!("{} (scene `{}`)", display_relative(&case.file), case.scene);
    let compiled = compile_scene_with(
        std::slice::from_ref(&case.file),
        Some(&case.scene),
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions {
            exec: Some(ExecModel::Wavefront),
            ..KernelOptions::default()
        },
    )
    .map_err(|f| {
        format!(
            "{what}: does not compile:\n{}",
            rtc_tests::render::render_list(&f.checked.sources, &f.diagnostics)
        )
    })?;
    let program = compiled
        .checked
        .program
        .as_ref()
        .ok_or_else(|| format!("{what}: compiled without a program"))?;
    let settings = &program.scenes[compiled.scene].settings;
    let height = ((u64::from(WIDTH) * u64::from(settings.height) + u64::from(settings.width) / 2)
        / u64::from(settings.width.max(1)))
    .max(1) as u32;
    let spp = settings.samples.min(MAX_SPP);
    let mut lines = Vec::new();
    let mut images = Vec::new();
    for exec in [ExecModel::Megakernel, ExecModel::Wavefront] {
        let what = format!("{what} [{}]", exec.name());
        let options = RenderOptions {
            size: Some([WIDTH, height]),
            samples: Some(spp),
            exec: Some(exec),
            // As `rtc render` does by default (its `--no-flatten` keeps one BVH per object).
            flatten: true,
            ..RenderOptions::default()
        };
        let (line, image) = render_case(gpu, case, &compiled, options, &what, out_dir)?;
        lines.push(line);
        images.push(image);
    }
    if let [mega, wave] = &images[..] {
        let tone = ToneMap::default();
        let d = difference(&to_srgb8(mega, &tone).0, &to_srgb8(wave, &tone).0);
        let outlier_fraction = d.outliers as f64 / d.channels.max(1) as f64;
        let line = format!(
            "{what}: wavefront against megakernel: PSNR {:.1} dB, {} channels off by more than {OUTLIER_LEVELS}",
            d.psnr, d.outliers
        );
        if d.psnr < MIN_PSNR_DB || outlier_fraction > MAX_OUTLIER_FRACTION {
            return Err(format!("{line}: the execution models disagree"));
        }
        lines.push(line);
    }
    Ok(lines.join("\n"))
}

/// Renders one case with `options` and compares it with the reference (or blesses it, the
/// megakernel's render only); the summary line and the image.
fn render_case(
    gpu: &Gpu,
    case: &Case,
    compiled: &rtc_compiler::kernel::CompiledScene,
    options: RenderOptions,
    what: &str,
    out_dir: &Path,
) -> Result<(String, LinearImage), String> {
    let start = Instant::now();
    let [_, height] = options.size.unwrap_or([WIDTH, WIDTH]);
    let exec = options.exec.unwrap_or_default();
    let result = Renderer::new(gpu, compiled, options)
        .and_then(|mut r| r.render(&mut |_, _| {}))
        .map_err(|e| format!("{what}: does not render: {e}"))?;
    let nonfinite_pixels = result.image.count_nonfinite();
    if result.stats.nonfinite_samples > 0 || nonfinite_pixels > 0 {
        return Err(format!(
            "{what}: {} non-finite samples, {nonfinite_pixels} non-finite pixels",
            result.stats.nonfinite_samples
        ));
    }
    let tone = ToneMap::default();
    let summary = format!(
        "{what}: {WIDTH}x{height}, {} spp, {:.1} s",
        result.stats.samples,
        start.elapsed().as_secs_f64()
    );
    if bless() {
        if exec == ExecModel::Megakernel {
            write_png(&case.reference, &result.image, &tone)
                .map_err(|e| format!("{what}: cannot bless: {e}"))?;
        }
        return Ok((format!("{summary}, blessed"), result.image));
    }
    let bless_help = format!(
        "RTC_BLESS=1 RTC_EXAMPLES={} cargo test -p rtc-tests --test examples",
        case.file
            .parent()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default()
    );
    if !case.reference.is_file() {
        return Err(format!(
            "{what}: no reference image {}; write it with `{bless_help}` (and look at it)",
            display_relative(&case.reference)
        ));
    }
    let reference = read_image(&case.reference).map_err(|e| format!("{what}: {e}"))?;
    if (reference.width(), reference.height()) != (WIDTH, height) {
        return Err(format!(
            "{what}: the reference is {}x{}, the render {WIDTH}x{height}; re-bless with `{bless_help}`",
            reference.width(),
            reference.height()
        ));
    }
    let (test_bytes, _) = to_srgb8(&result.image, &tone);
    let (reference_bytes, _) = to_srgb8(&reference, &tone);
    let d = difference(&test_bytes, &reference_bytes);
    let outlier_fraction = d.outliers as f64 / d.channels.max(1) as f64;
    let summary = format!(
        "{summary}, PSNR {:.1} dB, {} channels off by more than {OUTLIER_LEVELS}, largest {}",
        d.psnr, d.outliers, d.max
    );
    if d.psnr < MIN_PSNR_DB || outlier_fraction > MAX_OUTLIER_FRACTION {
        let stem = case
            .reference
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let example = case
            .file
            .parent()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let actual = out_dir.join(format!("{example}-{stem}-{}-actual.png", exec.name()));
        let _ = write_png(&actual, &result.image, &tone);
        return Err(format!(
            "{summary}: differs from {} (need PSNR ≥ {MIN_PSNR_DB} dB and at most {:.1}% outliers); \
             the render is at {}; if the change is intended, `{bless_help}`",
            display_relative(&case.reference),
            MAX_OUTLIER_FRACTION * 100.0,
            actual.display()
        ));
    }
    Ok((summary, result.image))
}

#[test]
fn every_example_matches_its_reference_image() {
    let Some(gpu) = gpu_or_skip("every_example_matches_its_reference_image") else {
        return;
    };
    let out_dir = common::temp_dir("examples", "renders");
    let mut failures = Vec::new();
    let mut cases = Vec::new();
    for dir in example_dirs() {
        cases.extend(cases_in(&dir, &mut failures));
    }
    assert!(
        !cases.is_empty() || !failures.is_empty(),
        "no example scene found"
    );
    for case in &cases {
        match run_case(&gpu, case, &out_dir) {
            Ok(line) => eprintln!("{line}"),
            Err(message) => {
                eprintln!("FAILED {message}");
                failures.push(message);
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} example scenes failed:\n\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n\n")
    );
}

#[test]
fn the_difference_measures_psnr_and_outliers() {
    let same = difference(&[10, 20, 30], &[10, 20, 30]);
    assert_eq!((same.psnr, same.outliers, same.max), (f64::INFINITY, 0, 0));
    // One channel of 100 off by 255: MSE 650.25, PSNR 10 log10(100) = 20 dB.
    let mut a = vec![0u8; 100];
    let b = a.clone();
    a[7] = 255;
    let d = difference(&a, &b);
    assert!((d.psnr - 20.0).abs() < 1e-9, "{}", d.psnr);
    assert_eq!((d.outliers, d.max, d.channels), (1, 255, 100));
}

// ---------------------------------------------------------------------------------------------------
// The standard-library programs the examples use, against values computed by hand.
//
// Each scene is a file of `tests/scenes/examples/` that imports `looking_down.rt`: 33 × 33 pixels seen
// straight down from `(0, CAM_Y, 0)` through a 90° `Pinhole` whose image-up is -z, so the ray of pixel
// `(x, y)` at offset `(u, v)` inside it is `(ndc_x, -1, ndc_y)` with `ndc = (pixel + offset) / 33 · 2
// - 1`, and meets the floor `y = 0` at `CAM_Y · (ndc_x, ndc_y)`. With one sample per pixel the offset
// is ½ (the centre); with more it is random, and the expected value is the mean over the pixel,
// computed here on an 8 × 8 grid. The floor is a Lambert quad of albedo 1, so a lit floor point shows
// `E / π` for irradiance `E`. The meshes a scene loads are written by its test next to it.

/// The image side, as `looking_down.rt` declares it.
const SIZE: u32 = 33;
/// The camera's height, as `looking_down.rt` declares it.
const CAM_Y: f64 = 3.0;

/// The scene file `tests/scenes/examples/<name>.rt`.
fn analytic_scene(name: &str) -> SceneFile {
    SceneFile::open(&format!("examples/{name}.rt"))
}

/// Compiles `file` in a fresh folder named after `name`, next to the `assets` (`(file name,
/// contents)`) its scene loads, and renders it as its settings say; panics with the diagnostics or
/// the runtime's error, and on any NaN or infinite sample.
fn render(gpu: &Gpu, name: &str, file: &SceneFile, assets: &[(&str, &str)]) -> LinearImage {
    let dir = temp_dir("examples", name);
    for (asset, contents) in assets {
        std::fs::write(dir.join(asset), contents).expect("asset file");
    }
    let compiled = file.compile(&dir);
    let (image, _) = common::scene::render(gpu, &compiled, RenderOptions::default(), name);
    image
}

/// Every scene file of `tests/scenes/` checks as `rtc check` would, before the tests set any of its
/// constants. Needs no GPU.
#[test]
fn every_test_scene_file_checks() {
    common::scene::assert_every_scene_file_checks(7);
}

/// Each folder of `tests/scenes/` belongs to a suite of this crate (`examples/` to this file).
#[test]
fn every_scene_folder_is_named_after_a_test_suite() {
    common::scene::assert_every_scene_folder_is_a_suite();
}

/// The image side and camera height the checks below compute with are those of the scenes' shared
/// camera file.
#[test]
fn the_analytic_scenes_look_down_as_the_checks_assume() {
    let camera = analytic_scene("looking_down");
    let value = |name: &str| {
        let (start, end) = const_value_range(camera.text(), name)
            .unwrap_or_else(|| panic!("looking_down.rt declares no {name}"));
        camera.text()[start..end].trim().to_owned()
    };
    assert_eq!(value("SIZE"), format!("{SIZE}u"));
    assert_eq!(value("CAM_Y"), format!("{CAM_Y:?}"));
}

/// The floor point seen at offset `(u, v)` of pixel `(x, y)`.
fn floor_point(x: u32, y: u32, u: f64, v: f64) -> [f64; 3] {
    let ndc = |i: u32, o: f64| (f64::from(i) + o) / f64::from(SIZE) * 2.0 - 1.0;
    [CAM_Y * ndc(x, u), 0.0, CAM_Y * ndc(y, v)]
}

/// `f` at the centre of pixel `(x, y)` (one sample), or its mean over the pixel (several).
fn expected(x: u32, y: u32, samples: u32, f: &dyn Fn([f64; 3]) -> f64) -> f64 {
    if samples == 1 {
        return f(floor_point(x, y, 0.5, 0.5));
    }
    let n = 8;
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            let o = |k: i32| (f64::from(k) + 0.5) / f64::from(n);
            sum += f(floor_point(x, y, o(i), o(j)));
        }
    }
    sum / f64::from(n * n)
}

/// Irradiance at floor point `p` (normal +y) from an isotropic point source of intensity `i` at `l`.
fn point_irradiance(p: [f64; 3], l: [f64; 3], i: f64) -> f64 {
    let d = [l[0] - p[0], l[1] - p[1], l[2] - p[2]];
    let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    i * (d[1] / d2.sqrt()).max(0.0) / d2
}

fn red(img: &LinearImage, x: u32, y: u32) -> f64 {
    f64::from(img.get(x, y).expect("pixel")[0])
}

/// A sphere light lying wholly above the floor's horizon lights it exactly like a point light of the
/// same intensity at its centre (`E = π L sin²α cos θ = I cos θ / d²`), so the floor under a large
/// `SphereLight` (radius 1 at height 2) must match the point-light formula: within 3% per pixel
/// (256 samples; the estimator's spread is a few per cent per sample) and 0.5% on average.
#[test]
fn a_sphere_light_lights_like_a_point_light_of_the_same_intensity() {
    let Some(gpu) = gpu_or_skip("a_sphere_light_lights_like_a_point_light_of_the_same_intensity")
    else {
        return;
    };
    let spp = 256;
    let file = analytic_scene("sphere_light").set("SAMPLES", format!("{spp}u"));
    let img = render(&gpu, "sphere_light", &file, &[]);
    let (mut sum_got, mut sum_want, mut checked) = (0.0, 0.0, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let c = floor_point(x, y, 0.5, 0.5);
            if c[0].abs().max(c[2].abs()) > 0.85 {
                continue; // the quad's edge crosses the pixel
            }
            let want = expected(x, y, spp, &|p| {
                point_irradiance(p, [0.0, 2.0, 0.0], 4.0) / std::f64::consts::PI
            });
            let got = red(&img, x, y);
            assert!(
                (got - want).abs() <= 0.03 * want,
                "pixel ({x}, {y}): {got}, want {want}"
            );
            sum_got += got;
            sum_want += want;
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked} pixels checked");
    let ratio = sum_got / sum_want;
    eprintln!("sphere light: {checked} pixels, mean ratio to the analytic value {ratio:.5}");
    assert!((ratio - 1.0).abs() < 0.005, "mean ratio {ratio}");
}

/// A spot light pointing straight down is a point light inside its inner cone (relative 1e-4, one
/// sample through each pixel centre), black outside its outer cone, and in between no brighter than
/// the point light.
#[test]
fn a_spot_light_is_a_point_light_inside_its_cone_and_dark_outside() {
    let Some(gpu) = gpu_or_skip("a_spot_light_is_a_point_light_inside_its_cone_and_dark_outside")
    else {
        return;
    };
    let img = render(&gpu, "spot_light", &analytic_scene("spot_light"), &[]);
    let (mut inside, mut outside, mut between) = (0, 0, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let p = floor_point(x, y, 0.5, 0.5);
            let angle = (p[0].hypot(p[2]) / 2.0).atan().to_degrees();
            let point = point_irradiance(p, [0.0, 2.0, 0.0], 4.0) / std::f64::consts::PI;
            let got = red(&img, x, y);
            if angle < 19.9 {
                assert!(
                    (got - point).abs() <= 1e-4 * point,
                    "pixel ({x}, {y}) at {angle:.2}°: {got}, want {point}"
                );
                inside += 1;
            } else if angle > 30.1 {
                assert_eq!(got, 0.0, "pixel ({x}, {y}) at {angle:.2}°");
                outside += 1;
            } else {
                assert!(
                    (0.0..=point * (1.0 + 1e-4)).contains(&got),
                    "pixel ({x}, {y}) at {angle:.2}°: {got}, point light {point}"
                );
                between += 1;
            }
        }
    }
    assert!(
        inside > 20 && outside > 500 && between > 20,
        "{inside} {outside} {between}"
    );
}

/// Whether the segment from `o` along `d` (for `t` in `(0, tmax)`) meets the box `[lo, hi]`.
fn segment_hits_box(
    o: [f64; 3],
    d: [f64; 3],
    tmax: f64,
    lo: [f64; 3],
    hi: [f64; 3],
) -> Option<f64> {
    let (mut t0, mut t1) = (0.0f64, tmax);
    for a in 0..3 {
        if d[a] == 0.0 {
            if o[a] < lo[a] || o[a] > hi[a] {
                return None;
            }
            continue;
        }
        let (u, v) = ((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]);
        t0 = t0.max(u.min(v));
        t1 = t1.min(u.max(v));
    }
    (t0 <= t1).then_some(t0)
}

/// A directional light gives the floor `intensity · cos θ` everywhere, and an analytic `Box` floating
/// above the floor casts a sharp shadow exactly where a ray toward the light meets the box; the box's
/// top face (seen head-on by the centre pixel's ray, which has two zero direction components) is lit
/// with the same cosine. Pixels within 0.02 of a shadow or box edge are left out; the rest must match
/// within a relative 1e-4, or be exactly 0 in shadow.
#[test]
fn a_directional_light_and_a_box_cast_the_analytic_shadow() {
    let Some(gpu) = gpu_or_skip("a_directional_light_and_a_box_cast_the_analytic_shadow") else {
        return;
    };
    let img = render(&gpu, "directional", &analytic_scene("directional"), &[]);
    let (lo, hi) = ([-0.5, 0.75, -0.5], [0.5, 1.25, 0.5]);
    let to_light = [
        -std::f64::consts::FRAC_1_SQRT_2,
        std::f64::consts::FRAC_1_SQRT_2,
        0.0,
    ];
    let lit = 2.0 * to_light[1] / std::f64::consts::PI;
    let (mut on_box, mut shadowed, mut lit_floor) = (0, 0, 0);
    // A pixel is near an edge when growing and shrinking the box by `g` disagree on whether its
    // camera ray or its shadow ray meets the box.
    let near_edge = |p: [f64; 3], g: f64| {
        let grown = (lo.map(|v| v - g), hi.map(|v| v + g));
        let shrunk = (lo.map(|v| v + g), hi.map(|v| v - g));
        let cam = [0.0, CAM_Y, 0.0];
        let d = [p[0], -CAM_Y, p[2]];
        let seen = |b: ([f64; 3], [f64; 3])| segment_hits_box(cam, d, 1.0, b.0, b.1).is_some();
        let shade =
            |b: ([f64; 3], [f64; 3])| segment_hits_box(p, to_light, 100.0, b.0, b.1).is_some();
        seen(grown) != seen(shrunk) || shade(grown) != shade(shrunk)
    };
    for y in 0..SIZE {
        for x in 0..SIZE {
            let p = floor_point(x, y, 0.5, 0.5);
            if near_edge(p, 0.02) {
                continue;
            }
            let got = red(&img, x, y);
            let cam = [0.0, CAM_Y, 0.0];
            let d = [p[0], -CAM_Y, p[2]];
            if let Some(t) = segment_hits_box(cam, d, 1.0, lo, hi) {
                // Seen through the box's top face (y = 1.25): lit by the same cosine.
                assert!(
                    ((cam[1] + d[1] * t) - 1.25).abs() < 1e-9,
                    "pixel ({x}, {y}) sees a side"
                );
                assert!(
                    (got - lit).abs() <= 1e-4 * lit,
                    "box pixel ({x}, {y}): {got}, want {lit}"
                );
                on_box += 1;
            } else if segment_hits_box(p, to_light, 100.0, lo, hi).is_some() {
                assert_eq!(got, 0.0, "shadow pixel ({x}, {y})");
                shadowed += 1;
            } else {
                assert!(
                    (got - lit).abs() <= 1e-4 * lit,
                    "floor pixel ({x}, {y}): {got}, want {lit}"
                );
                lit_floor += 1;
            }
        }
    }
    let centre = red(&img, SIZE / 2, SIZE / 2);
    assert!(
        (centre - lit).abs() <= 1e-4 * lit,
        "the centre pixel hits the top face: {centre}"
    );
    assert!(
        on_box > 20 && shadowed > 15 && lit_floor > 300,
        "{on_box} {shadowed} {lit_floor}"
    );
}

/// Seen from its centre, an analytic `Sphere` surrounds the camera: every ray starts inside and hits
/// the far side, at distance `radius`, facing the point light at the camera, so every pixel shows
/// `I / r² / π` (relative 1e-4).
#[test]
fn a_sphere_is_hit_from_inside() {
    let Some(gpu) = gpu_or_skip("a_sphere_is_hit_from_inside") else {
        return;
    };
    let img = render(&gpu, "inside", &analytic_scene("inside"), &[]);
    let want = 1.0 / std::f64::consts::PI;
    for y in 0..SIZE {
        for x in 0..SIZE {
            let got = img.get(x, y).expect("pixel");
            assert!(
                (f64::from(got[0]) - want).abs() <= 1e-4 * want && got[0] == got[1],
                "pixel ({x}, {y}): {got:?}, want {want} in every channel"
            );
        }
    }
}

/// A soup of 300 random triangles in `[-1, 1]³` as OBJ text, each with its own flat normal, so both
/// mesh paths shade a hit identically and only the choice of the nearest triangle matters.
/// Deterministic (a fixed linear congruential generator).
fn triangle_soup() -> String {
    let mut state = 0x2545_f491_u32;
    let mut next = || {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        f64::from(state >> 8) / f64::from(1u32 << 24) * 2.0 - 1.0
    };
    let mut obj = String::new();
    for i in 0..300 {
        let c = [next(), next(), next()];
        let v: Vec<[f64; 3]> = (0..3)
            .map(|_| {
                [
                    c[0] + 0.3 * next(),
                    c[1] + 0.3 * next(),
                    c[2] + 0.3 * next(),
                ]
            })
            .collect();
        let (e1, e2) = (
            [v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]],
            [v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]],
        );
        let n = [
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        ];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt().max(1e-12);
        for p in &v {
            obj.push_str(&format!("v {} {} {}\n", p[0], p[1], p[2]));
        }
        obj.push_str(&format!(
            "vn {} {} {}\n",
            n[0] / len,
            n[1] / len,
            n[2] / len
        ));
        let (a, n) = (3 * i + 1, i + 1);
        obj.push_str(&format!("f {a}//{n} {}//{n} {}//{n}\n", a + 1, a + 2));
    }
    obj
}

/// A mesh traversed by `BvhMesh`'s `@intersection` program finds the hits the built-in mesh geometry
/// finds (the same watertight test on the same object-space triangles): a soup of 300 overlapping
/// flat-shaded triangles, lit by a point light, looks the same both ways (relative 1e-3, the built-in
/// path's normals being stored as 16-bit octahedral pairs), and an icosphere (smooth-shaded by one,
/// flat by the other) covers exactly the same pixels.
#[test]
fn a_bvh_mesh_finds_the_hits_of_the_built_in_mesh() {
    let Some(gpu) = gpu_or_skip("a_bvh_mesh_finds_the_hits_of_the_built_in_mesh") else {
        return;
    };
    let soup = triangle_soup();
    let assets = [("soup.obj", soup.as_str())];
    let file = analytic_scene("bvh_mesh");
    let built_in = render(&gpu, "mesh", &file.clone().scene("mesh"), &assets);
    let custom = render(&gpu, "bvh_mesh", &file.scene("bvh_mesh"), &assets);
    let (mut soup_pixels, mut ball_pixels, mut hits) = (0, 0, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let (a, b) = (
                built_in.get(x, y).expect("pixel"),
                custom.get(x, y).expect("pixel"),
            );
            let (a_hit, b_hit) = (a[..3] != [1.0; 3], b[..3] != [1.0; 3]);
            assert_eq!(a_hit, b_hit, "pixel ({x}, {y}): {a:?} vs {b:?}");
            hits += usize::from(a_hit);
            // The soup is on the right (x > 0), the ball on the left.
            if a_hit && floor_point(x, y, 0.5, 0.5)[0] > -0.35 {
                for c in 0..3 {
                    let (va, vb) = (f64::from(a[c]), f64::from(b[c]));
                    assert!(
                        (va - vb).abs() <= 1e-3 * va.max(vb) + 1e-7,
                        "soup pixel ({x}, {y}): {a:?} vs {b:?}"
                    );
                }
                soup_pixels += 1;
            } else if a_hit {
                ball_pixels += 1;
            }
        }
    }
    assert!(
        soup_pixels > 100 && ball_pixels > 30,
        "{soup_pixels} soup and {ball_pixels} ball pixels of {hits} hits"
    );
}

/// A shading normal that leans away from the viewer but lies on the geometric normal's side (as
/// interpolated normals do near a silhouette) still shades with the light it faces: the stdlib
/// materials orient the shading normal by the geometric one, not by the view direction (which
/// flipped it and turned such pixels black). The floor quad's normals all lean toward +x,
/// `normalize(1, 0.2, 0)`; the right part of the image sees them from behind, and a point light at
/// `(4, 1, 0)` lights them: every floor pixel must show `I (n · l) / (π d²)` within 1e-3.
#[test]
fn a_shading_normal_leaning_away_from_the_viewer_is_still_lit() {
    let Some(gpu) = gpu_or_skip("a_shading_normal_leaning_away_from_the_viewer_is_still_lit")
    else {
        return;
    };
    let quad =
        "v -4 0 -4\nv -4 0 4\nv 4 0 4\nv 4 0 -4\nvn 1 0.2 0\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
    let img = render(
        &gpu,
        "leaning_normals",
        &analytic_scene("leaning_normals"),
        &[("leaning.obj", quad)],
    );
    let len = (1.0f64 + 0.04).sqrt();
    let n = [1.0 / len, 0.2 / len, 0.0];
    let (mut away, mut checked) = (0, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let p = floor_point(x, y, 0.5, 0.5);
            let d = [4.0 - p[0], 1.0 - p[1], -p[2]];
            let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let cos = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / d2.sqrt();
            let want = 5.0 * cos.max(0.0) / d2 / std::f64::consts::PI;
            let got = red(&img, x, y);
            assert!(
                (got - want).abs() <= 1e-3 * want + 1e-6,
                "pixel ({x}, {y}): {got} instead of {want}"
            );
            // The view direction from the camera at (0, 3, 0) to p, against the shading normal.
            let view = [p[0], -CAM_Y, p[2]];
            if n[0] * view[0] + n[1] * view[1] > 0.0 && want > 0.0 {
                away += 1;
            }
            checked += 1;
        }
    }
    assert!(
        away > 50,
        "only {away} of {checked} pixels see the normal from behind"
    );
}
