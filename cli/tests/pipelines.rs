//! Pipeline accounting end to end (skipped, saying so, where no adapter exists): `rtc render`
//! prints one line per kernel and the state of the on-disk pipeline cache, and a second process
//! with the same cache folder either takes the kernel from the disk cache or says the cache is
//! unsupported (lavapipe keeps nothing in it); `rtc compile --timings` prints the compiler's phases
//! and the driver's per-kernel time; `rtc bench --compile` measures a scene in a child process and
//! writes JSON that parses; `rtc` sets lavapipe's SIMD width on Mesa 25 unless the user did, and
//! gives small renders lavapipe's quick JIT, with the same image, unless told otherwise.

mod common;

use common::{no_gpu, s, scratch, text};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SCENE: &str = r#"import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/lights/point.rt";
import "std/miss/gradient.rt";

scene small {
    settings { width: 16, height: 16, samples: 1, max_depth: 1 }
    camera Pinhole { position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0), fov: 40.0 }
    background SkyGradient {}
    let grey = Lambert { albedo: vec3f(0.5) };
    object floor { geometry: quad_mesh(), material: grey, transform: scale(10.0) }
    light key PointLight { position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }
}
"#;

fn scene(dir: &Path) -> PathBuf {
    let path = dir.join("small.rt");
    std::fs::write(&path, SCENE).expect("write the scene");
    path
}

/// `rtc` with the pipeline cache in `cache`.
fn rtc_cached(args: &[&str], cache: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env("NO_COLOR", "1")
        .env("RTC_PIPELINE_CACHE", cache)
        .output()
        .expect("run rtc")
}

/// The kernel line of `label` in a summary.
fn kernel_line<'a>(summary: &'a str, label: &str) -> &'a str {
    summary
        .lines()
        .find(|l| l.trim_start().starts_with(label) && l.contains("(driver "))
        .unwrap_or_else(|| panic!("no kernel line for {label}:\n{summary}"))
}

#[test]
fn render_reports_kernels_and_the_disk_cache_on_a_second_run() {
    let dir = scratch("pipelines", "render");
    let cache = dir.join("cache");
    let scene = scene(&dir);
    let png = dir.join("out.png");
    let args = ["render", s(&scene), "-o", s(&png)];
    let first = rtc_cached(&args, &cache);
    if no_gpu(&first) {
        return;
    }
    let t1 = text(&first);
    assert!(first.status.success(), "{t1}");
    assert!(kernel_line(&t1, "rtc render").contains("compiled"), "{t1}");
    assert!(t1.contains("    pipeline cache: "), "{t1}");

    let second = rtc_cached(&args, &cache);
    let t2 = text(&second);
    assert!(second.status.success(), "{t2}");
    let line = kernel_line(&t2, "rtc render");
    if t2.contains("pipeline cache: unsupported") {
        // Vulkan drivers that keep nothing in VkPipelineCache (lavapipe), or another backend.
        assert!(
            t2.contains("keeps no pipelines") || t2.contains("Vulkan only"),
            "{t2}"
        );
        assert!(line.contains("compiled"), "{t2}");
    } else {
        assert!(line.contains("reused (disk cache)"), "{t2}");
        assert!(t2.contains("1 kernel and"), "{t2}");
    }
    // No temporary file is left beside the cache file.
    let files: Vec<_> = std::fs::read_dir(&cache)
        .map(|d| d.filter_map(Result::ok).map(|e| e.path()).collect())
        .unwrap_or_default();
    assert!(files.len() <= 1, "{files:?}");
}

/// `rtc render` of the small scene at 8x8 to `name` with `extra` arguments, and Mesa's variable
/// `var` as given (`None`: unset).
fn render_small(dir: &Path, name: &str, extra: &[&str], var: (&str, Option<&str>)) -> Output {
    let scene = scene(dir);
    let png = dir.join(name);
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rtc"));
    cmd.args(["render", s(&scene), "-o", s(&png), "--size", "8x8"])
        .args(extra)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env("NO_COLOR", "1")
        .env_remove(var.0);
    if let Some(value) = var.1 {
        cmd.env(var.0, value);
    }
    cmd.output().expect("run rtc")
}

/// The first line of a summary that starts with `start`.
fn summary_line(t: &str, start: &str) -> String {
    t.lines()
        .find(|l| l.starts_with(start))
        .map(str::to_owned)
        .unwrap_or_else(|| panic!("no `{start}` line in\n{t}"))
}

/// The Mesa major version in an adapter line (`… driver llvmpipe Mesa 25.0.7-2~bpo12+1 …`).
fn mesa_major(adapter: &str) -> Option<u32> {
    let rest = &adapter[adapter.find("Mesa ")? + 5..];
    rest.split('.').next()?.parse().ok()
}

/// Whether the `host:` line of a summary names a CPU whose llvmpipe code may not use AVX-512, where
/// lavapipe's loads are per-lane code from any Mesa release (`gpu::lavapipe_loads_per_lane`).
fn per_lane_cpu(summary: &str) -> bool {
    let host = summary_line(summary, "host: ");
    host.contains("no AVX-512") || host.contains("GALLIUM_OVERRIDE_CPU_CAPS")
}

/// `rtc` gives lavapipe before Mesa 26, and later releases on a CPU without AVX-512, 128-bit
/// batches unless the user chose a width, says so on the host line, and the driver gets it
/// (llvmpipe's adapter name states its width); on other drivers it sets nothing.
#[test]
fn render_sets_llvmpipe_width_where_it_helps_unless_the_user_did() {
    let dir = scratch("pipelines", "width");
    // The optimising JIT, so that the width is the host line's last setting.
    let width = |w| {
        render_small(
            &dir,
            "width.png",
            &["--cpu-jit", "optimized"],
            ("LP_NATIVE_VECTOR_WIDTH", w),
        )
    };
    let ours = width(None);
    if no_gpu(&ours) {
        return;
    }
    let t = text(&ours);
    assert!(ours.status.success(), "{t}");
    let host = summary_line(&t, "host: ");
    let adapter = summary_line(&t, "adapter: ");
    let lavapipe = adapter.contains("llvmpipe") && adapter.contains("(vulkan,");
    let narrow = lavapipe && mesa_major(&adapter).is_some_and(|m| m < 26 || per_lane_cpu(&t));
    if narrow {
        assert!(
            host.ends_with("; LP_NATIVE_VECTOR_WIDTH=128 (rtc's default)"),
            "{t}"
        );
        assert!(adapter.contains("128 bits"), "{t}");
    } else {
        assert!(!host.contains("LP_NATIVE_VECTOR_WIDTH"), "{t}");
    }

    let users = width(Some("256"));
    let t = text(&users);
    assert!(users.status.success(), "{t}");
    assert!(
        summary_line(&t, "host: ").ends_with("; LP_NATIVE_VECTOR_WIDTH=256"),
        "{t}"
    );
    if lavapipe {
        assert!(summary_line(&t, "adapter: ").contains("256 bits"), "{t}");
    }
}

/// `rtc render` of the small scene at 8x8 to `name` with `extra` arguments and `GALLIVM_PERF` as
/// given (`None`: unset).
fn render_jit(dir: &Path, name: &str, extra: &[&str], perf: Option<&str>) -> Output {
    render_small(dir, name, extra, ("GALLIVM_PERF", perf))
}

/// A still render whose `--size` and `--spp` are small gets lavapipe's quick JIT (LLVM's
/// optimisation off) on lavapipe, says so on the host line, and writes the same image byte for
/// byte as the optimising JIT; so does one whose scene's own size and samples are small, or whose
/// count is within the bound of its compiled kernels; `--cpu-jit optimized`, a count past that
/// bound and a user's `GALLIVM_PERF` keep rtc out of it.
#[test]
fn small_renders_get_the_quick_jit_and_the_same_image() {
    let dir = scratch("pipelines", "jit");
    let quick = render_jit(&dir, "quick.png", &["--spp", "1"], None);
    if no_gpu(&quick) {
        return;
    }
    let t = text(&quick);
    assert!(quick.status.success(), "{t}");
    let adapter = summary_line(&t, "adapter: ");
    let ours = "GALLIVM_PERF=nopt (rtc's quick JIT for a small render)";
    if adapter.contains("llvmpipe") && adapter.contains("(vulkan,") {
        assert!(summary_line(&t, "host: ").contains(ours), "{t}");
    }

    let optimized = render_jit(
        &dir,
        "optimized.png",
        &["--spp", "1", "--cpu-jit", "optimized"],
        None,
    );
    let t = text(&optimized);
    assert!(optimized.status.success(), "{t}");
    assert!(!summary_line(&t, "host: ").contains("GALLIVM_PERF"), "{t}");
    let a = std::fs::read(dir.join("quick.png")).expect("the quick JIT's image");
    let b = std::fs::read(dir.join("optimized.png")).expect("the optimising JIT's image");
    assert!(a == b, "the two JITs' images differ");

    // The scene's own samples decide once it is compiled: 8x8 at its 1 spp is small.
    let own = render_jit(&dir, "own.png", &[], None);
    let t = text(&own);
    assert!(own.status.success(), "{t}");
    if adapter.contains("llvmpipe") && adapter.contains("(vulkan,") {
        assert!(summary_line(&t, "host: ").contains(ours), "{t}");
    }
    // So does a count above the bound of unknown kernels: this megakernel without secondary
    // rays gets the quick JIT up to QUICK_JIT_MAX_SAMPLES_PRIMARY, and the optimising one past it.
    let bound = rtc_runtime::gpu::QUICK_JIT_MAX_SAMPLES_PRIMARY / 64;
    for (spp, quick) in [(bound, true), (bound + 1, false)] {
        let spp = spp.to_string();
        let r = render_jit(
            &dir,
            "large.png",
            &["--spp", &spp, "--exec", "megakernel"],
            None,
        );
        let t = text(&r);
        assert!(r.status.success(), "{t}");
        let host = summary_line(&t, "host: ");
        if adapter.contains("llvmpipe") && adapter.contains("(vulkan,") {
            assert_eq!(host.contains(ours), quick, "{spp} spp: {t}");
        } else {
            assert!(!host.contains("GALLIVM_PERF"), "{t}");
        }
    }

    let users = render_jit(&dir, "users.png", &["--spp", "1"], Some("brilinear"));
    let t = text(&users);
    assert!(users.status.success(), "{t}");
    assert!(
        summary_line(&t, "host: ").ends_with("GALLIVM_PERF=brilinear"),
        "{t}"
    );
}

/// A still render whose `--size` and `--spp` make at most `WAVEFRONT_PREVIEW_MAX_SAMPLES` samples
/// runs the wavefront model on a CPU adapter (its stage kernels compile faster), says so, and
/// writes the megakernel's image byte for byte; `--exec megakernel` and an unknown sample count
/// keep the megakernel, as a GPU adapter does. On lavapipe before Mesa 26, which gets uniform
/// tables, this scene's light megakernel (below `WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES`) is
/// kept and the summary says why; with `RTC_UNIFORM_TABLES=off` the wavefront model runs again.
#[test]
fn small_renders_on_a_cpu_adapter_run_the_wavefront_model_with_the_same_image() {
    let dir = scratch("pipelines", "auto-exec");
    let render =
        |name: &str, extra: &[&str]| render_small(&dir, name, extra, ("RTC_UNIFORM_TABLES", None));
    let auto = render("auto.png", &["--spp", "1"]);
    if no_gpu(&auto) {
        return;
    }
    let t = text(&auto);
    assert!(auto.status.success(), "{t}");
    let adapter = summary_line(&t, "adapter: ");
    let cpu = adapter.contains(", CPU,");
    let tables = cpu
        && adapter.starts_with("adapter: llvmpipe")
        && adapter.contains("(vulkan,")
        && mesa_major(&adapter).is_some_and(|m| m < 26 || per_lane_cpu(&t));
    let wavefront_note = "exec: wavefront (a render of at most 16384 samples on a CPU adapter";
    if tables {
        let note = "exec: megakernel (a render of at most 16384 samples on lavapipe with uniform \
                    tables: a megakernel of weight ";
        assert!(t.contains(note), "{t}");
        assert!(kernel_line(&t, "rtc render").contains("compiled"), "{t}");
        let storage = render_small(
            &dir,
            "storage.png",
            &["--spp", "1"],
            ("RTC_UNIFORM_TABLES", Some("off")),
        );
        let ts = text(&storage);
        assert!(storage.status.success(), "{ts}");
        assert!(ts.contains(wavefront_note), "{ts}");
        assert!(
            kernel_line(&ts, "rtc wf_shade").contains("compiled"),
            "{ts}"
        );
        let a = std::fs::read(dir.join("auto.png")).expect("the megakernel's image");
        let b = std::fs::read(dir.join("storage.png")).expect("the wavefront model's image");
        assert!(a == b, "the two models' images differ");
    } else if cpu {
        assert!(t.contains(wavefront_note), "{t}");
        assert!(kernel_line(&t, "rtc wf_shade").contains("compiled"), "{t}");
    } else {
        assert!(!t.contains("exec: "), "{t}");
        assert!(kernel_line(&t, "rtc render").contains("compiled"), "{t}");
    }

    let mega = render("mega.png", &["--spp", "1", "--exec", "megakernel"]);
    let t = text(&mega);
    assert!(mega.status.success(), "{t}");
    assert!(!t.contains("exec: "), "{t}");
    assert!(kernel_line(&t, "rtc render").contains("compiled"), "{t}");
    let a = std::fs::read(dir.join("auto.png")).expect("the automatic model's image");
    let b = std::fs::read(dir.join("mega.png")).expect("the megakernel's image");
    assert!(a == b, "the two models' images differ");

    // The scene's own samples are not known before its compile: the megakernel.
    let unknown = render("unknown.png", &[]);
    let t = text(&unknown);
    assert!(unknown.status.success(), "{t}");
    assert!(!t.contains("exec: "), "{t}");
    assert!(kernel_line(&t, "rtc render").contains("compiled"), "{t}");
    // 8x8 at 300 spp (19,200 samples) is over the bound.
    let big = render("big.png", &["--spp", "300"]);
    let t = text(&big);
    assert!(big.status.success(), "{t}");
    assert!(!t.contains("exec: "), "{t}");
}

#[test]
fn compile_timings_print_phases_and_driver_times() {
    let dir = scratch("pipelines", "timings");
    let scene = scene(&dir);
    let out_dir = dir.join("out");
    let off = Path::new("off");
    let phases = rtc_cached(
        &[
            "compile",
            s(&scene),
            "--out",
            s(&out_dir),
            "--target",
            "wgsl",
            "--timings",
        ],
        off,
    );
    let t = text(&phases);
    assert!(phases.status.success(), "{t}");
    assert!(t.contains("compiler phases:\n"), "{t}");
    assert!(t.contains("  lower the render kernel "), "{t}");
    assert!(t.contains("  total "), "{t}");
    assert!(!t.contains("driver ("), "{t}");

    let driver = rtc_cached(
        &[
            "compile",
            s(&scene),
            "--out",
            s(&out_dir),
            "--target",
            "wgsl",
            "--timings",
            "driver",
        ],
        off,
    );
    let t = text(&driver);
    assert!(driver.status.success(), "{t}");
    assert!(t.contains("compiler phases:\n"), "{t}");
    if t.contains("no GPU adapter could be had") {
        eprintln!("SKIPPED the driver part: no adapter\n{t}");
    } else {
        assert!(kernel_line(&t, "rtc render").contains("compiled"), "{t}");
        assert!(t.contains("pipeline cache: off"), "{t}");
    }
}

#[test]
fn bench_compile_measures_a_scene_in_a_child() {
    let dir = scratch("pipelines", "bench");
    let scene = scene(&dir);
    let json = dir.join("compile.json");
    let out = rtc_cached(
        &["bench", "--compile", s(&scene), "--json", s(&json)],
        Path::new("off"),
    );
    let t = text(&out);
    if t.contains("no GPU adapter found") {
        eprintln!("SKIPPED: no GPU adapter at all\n{t}");
        return;
    }
    assert!(out.status.success(), "{t}");
    assert!(
        t.contains("cold compile (MESA_SHADER_CACHE_DISABLE=true"),
        "{t}"
    );
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("JSON written"))
            .expect("JSON parses");
    // One row per execution model: the megakernel's one kernel, the wavefront model's five stages
    // (the scene's shade stage traces its shadow rays: it has no shadow stage).
    let cold = value["cold"].as_array().expect("cold rows");
    assert_eq!(cold.len(), 2, "{value}");
    for (row, (exec, labels)) in cold.iter().zip([
        ("megakernel", &["rtc render"][..]),
        (
            "wavefront",
            &[
                "rtc wf_count",
                "rtc wf_compact",
                "rtc wf_trace",
                "rtc wf_shade",
                "rtc wf_finish",
            ][..],
        ),
    ]) {
        assert_eq!(row["example"], "small");
        assert_eq!(row["exec"], exec);
        let first_pixel = row["first_pixel_ms"].as_f64().expect("a time");
        let pipelines = row["pipelines_ms"].as_f64().expect("pipelines parsed");
        assert!(pipelines > 0.0 && pipelines < first_pixel, "{value}");
        let kernels = row["kernels"].as_array().expect("kernels");
        let got: Vec<&str> = kernels
            .iter()
            .map(|k| k["label"].as_str().unwrap_or(""))
            .collect();
        assert_eq!(got, labels, "{value}");
        assert!(kernels.iter().all(|k| k["origin"] == "compiled"), "{value}");
    }
    // A single file has no thesis scene to edit.
    assert_eq!(value["material_edit"].as_array().map(Vec::len), Some(0));
}

#[test]
fn bench_compile_usage_errors() {
    let off = Path::new("off");
    let out = rtc_cached(&["bench", "--compile", "--exec", "sideways"], off);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let out = rtc_cached(&["bench"], off);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let out = rtc_cached(&["bench", "--exec", "megakernel", "x.rt"], off);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let out = rtc_cached(&["bench", "--compile", "/no/such/folder"], off);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("/no/such/folder"), "{}", text(&out));
}
