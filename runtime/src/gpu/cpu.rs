//! The host CPU, for every speed figure rtc prints: on a CPU driver (lavapipe, llvmpipe, WARP) the
//! kernel's speed depends on the CPU's vector units far more than on anything else, so a rays/s
//! figure means little without the CPU model and whether it has AVX2 and AVX-512 (issue 23: the
//! same commit runs the thesis workload 2.5–4 times slower on an AVX2-only core than on one with
//! AVX-512).
//!
//! Guarantees: [`HostCpu::detect`] never fails; the model comes from `/proc/cpuinfo` where that
//! exists (else the architecture's name), the vector features from the running CPU
//! (`is_x86_feature_detected!`), and the thread count from `std::thread::available_parallelism`.
//! Mesa's own overrides of what llvmpipe may use or do (`GALLIUM_OVERRIDE_CPU_CAPS`,
//! `LP_NATIVE_VECTOR_WIDTH`, `GALLIVM_PERF`) are named when set, since they change the code
//! lavapipe generates without changing the CPU.
//!
//! [`apply_lavapipe_defaults`] makes rtc's two settings for the driver, each only where the
//! environment does not set the variable itself:
//! - 128-bit SIMD batches (`LP_NATIVE_VECTOR_WIDTH=128`) for lavapipe releases before Mesa 26,
//!   and for later ones on x86-64 CPUs without AVX-512. Before Mesa 26 it halves the driver's
//!   compile of every kernel and leaves images byte-identical and frames about as fast. Mesa 26
//!   compiles storage loads to LLVM gathers, which LLVM emits as gather instructions with AVX-512
//!   and, on CPUs it does not count as fast at gathering (AMD Zen 3), as one tested branch and load
//!   per lane: there 128 bits make the compile shorter, while with AVX-512 they would make frames
//!   slower, so that case is left alone. On a CPU without AVX-512 wider batches run most frames
//!   faster, so a render known to be long ([`WIDE_MIN_SAMPLES`]) keeps Mesa's own width there.
//! - 512-bit batches ([`WIDEST_WIDTH`]) from Mesa 26 on, on a CPU whose AVX-512 units are 512
//!   bits wide (AMD Zen 5), for a render known to be long ([`WIDEST_MIN_SAMPLES`]): there they run
//!   every example's frame 0.71 to 0.92 times as long (one 1.02) and compile it longer.
//! - The quick JIT ([`CpuJit::Quick`], `GALLIVM_PERF=nopt`: LLVM's optimisation passes off) when
//!   the caller asks for it, which `rtc` does for renders too small for optimised code to repay its
//!   compile (a preview, a first pixel). Images stay byte-identical; kernels compile in a third to
//!   a half of the time and run 1.1 to 3.9 times slower.
//!
//! - A shader cache of its own for each SIMD width on lavapipe before Mesa 26
//!   (`MESA_SHADER_CACHE_DIR`, [`width_cache_dir`]), where Mesa's cache key leaves the width out: a
//!   kernel compiled at 256 bits was found again by a 128-bit process and run at 256 bits (and the
//!   other way round), whatever `LP_NATIVE_VECTOR_WIDTH` and the summary's `host:` line said.
//!
//! Both are measured in docs/bench/compile.md and docs/bench/lavapipe.md. [`HostCpu`]'s line says
//! when a value is rtc's choice rather than the user's.

use std::fmt;
use std::sync::OnceLock;

/// The variable of llvmpipe's SIMD width (bits per batch: 256 is Mesa's default on AVX2 and
/// AVX-512 CPUs, 8 invocations a batch).
pub const VECTOR_WIDTH_VAR: &str = "LP_NATIVE_VECTOR_WIDTH";

/// The width [`apply_lavapipe_defaults`] gives lavapipe releases before [`NARROW_BEFORE_MESA`].
pub const NARROW_WIDTH: &str = "128";

/// The variable of Mesa's shader cache directory (`mesa_shader_cache_db` and the like go inside it).
pub const CACHE_DIR_VAR: &str = "MESA_SHADER_CACHE_DIR";

/// The first Mesa release whose lavapipe keeps its own width on a CPU with AVX-512, and whose
/// shader cache keys include the width. Mesa 25 turns each storage-buffer load into a loop over the
/// batch's lanes, so a kernel's LLVM code grows with the batch: at 128 bits (4 lanes) every
/// example compiles 1.6 to 2.8 times faster, with byte-identical images and frame times of 0.70 to
/// 1.14 of the 256-bit frame with AVX-512 and 0.95 to 1.19 without (AMD Zen 3). Mesa 26.1 compiles
/// those loads to one gather: with AVX-512 its compile gains little from 4 lanes and its frames
/// lose (the thesis frame 1.39 times slower); without AVX-512 see [`lavapipe_loads_per_lane`].
pub const NARROW_BEFORE_MESA: u32 = 26;

/// The variable of llvmpipe's performance switches; [`QUICK_JIT`] is the one rtc sets.
pub const JIT_VAR: &str = "GALLIVM_PERF";

/// [`JIT_VAR`]'s value that turns LLVM's optimisation passes off in llvmpipe's JIT (Mesa hashes
/// the switches into its shader cache's key, so quick and optimised code never mix there).
pub const QUICK_JIT: &str = "nopt";

/// How much optimisation a CPU driver's JIT (llvmpipe, under lavapipe and Mesa's GL) gives a
/// kernel. GPU drivers ignore it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CpuJit {
    /// LLVM's optimisation passes on (Mesa's default): the fastest frames.
    #[default]
    Optimized,
    /// LLVM's optimisation passes off ([`JIT_VAR`]` = `[`QUICK_JIT`]): every kernel compiles in
    /// a third to a half of the time and runs 1.8 to 3.9 times slower on Mesa 25, 1.1 to 2.2 times
    /// on Mesa 26, with byte-identical images. For work too small to repay an optimised compile
    /// ([`QUICK_JIT_MAX_SAMPLES`]).
    Quick,
}

/// The most samples (pixels times samples per pixel) a render may have for
/// [`CpuJit::for_samples`] to choose [`CpuJit::Quick`]: 128 K, e.g. 362x362 at 1 spp or 64x48 at
/// 42 spp. Measured on every example with both execution models (docs/bench/compile.md,
/// "The quick JIT for small renders (2026-12-04)"), the quick JIT saves more compile time than its slower
/// frames cost up to 213 K samples at least (Mesa 25, wavefront, glass_mirror; the path tracers,
/// whose samples are several rays each, come next at 222 K) and up to 0.5 to 7 M for most; the
/// bound keeps a margin below the smallest.
pub const QUICK_JIT_MAX_SAMPLES: u64 = 1 << 17;

/// The most samples a still render through the megakernel of a scene with secondary rays may have
/// for [`CpuJit::for_render`] to choose [`CpuJit::Quick`]: 384 K, e.g. 640x600 at 1 spp or
/// 320x240 at 5. The megakernel's smallest break-even among such examples is 0.48 M samples
/// (cornell_path, Mesa 25; 0.54 M on Mesa 26), the largest 4.0 M (shading); the bound keeps a
/// margin of 1.2 below the smallest (docs/bench/compile.md, "The quick JIT for a scene's own size
/// (2026-12-04)").
pub const QUICK_JIT_MAX_SAMPLES_SECONDARY: u64 = 3 << 17;

/// The same bound for a megakernel without secondary rays (every sample a camera ray and its
/// shadow rays): 768 K, e.g. 1024x768 at 1 spp. The smallest break-even among such examples is
/// 1.02 M samples (cornell_box, Mesa 25; 1.96 M on Mesa 26, thesis_scene), the largest 7.4 M
/// (gltf_scene); the bound keeps a margin of 1.3.
pub const QUICK_JIT_MAX_SAMPLES_PRIMARY: u64 = 3 << 18;

/// The most samples (pixels times samples per pixel) a still `rtc render` on a CPU adapter may
/// have for a scene left at `EXEC_AUTO` to run the wavefront model: 16 K, e.g. 128x128 at 1 spp or
/// 64x48 at 5 spp. Such a render's time is its kernels' compile, and the wavefront's stage kernels
/// compile faster than the megakernel for 12 of the 13 examples (cold, Mesa 25, 64x48 at 1 spp:
/// 0.6 to 1.9 s against 0.7 to 3.4 s; glass_mirror is the exception, 0.98 against 0.65 s). Its
/// slower frames catch up from about 65 K samples on the closest examples (cornell_path and hello
/// at 128x128 and 4 spp: 1.25 against 1.30 s, 0.93 against 0.95 s); the bound keeps a margin of
/// four below that (docs/bench/compile.md, "The wavefront model for small renders (2026-12-04)").
/// With uniform tables, light scenes keep the megakernel
/// ([`WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES`]).
pub const WAVEFRONT_PREVIEW_MAX_SAMPLES: u64 = 1 << 14;

/// On a driver that gets uniform tables (`scene::prefers_uniform_tables`: lavapipe whose loads
/// are per-lane code), the smallest megakernel, in
/// `rtc_compiler::kernel::weight::inlined_weight`, for which a render of at most
/// [`WAVEFRONT_PREVIEW_MAX_SAMPLES`] runs the wavefront model when the scene's geometry is small
/// and built in (`rtc_compiler::kernel::small_built_in_geometry`, so that its
/// BVH records go to a uniform table too). With both tables a megakernel's inlined traversals
/// compile about twice as fast, and a light one then compiles faster than the five stage kernels:
/// cold, Mesa 25.0.7, 64x48 at 1 spp, the examples' megakernels of weight 5,777 to 12,796
/// (glass_mirror to lights) took 0.34 to 0.70 s against 0.40 to 0.96 s for their stage kernels,
/// and the next heavier, three_spheres (15,838), 1.01 against 0.73 s (docs/bench/compile.md,
/// "Which model compiles faster, with uniform tables (2026-12-04)"). The bound lies between.
/// The box test made once per ray and BVH (2026-12-07) added about 900 to every weight (lights
/// 14,008, three_spheres 16,448), and the bound moved with them from 14,000; measured again then
/// (Zen 3, cold, three alternated, "pipelines"): lights' megakernel 860 / 892 / 1,135 ms against
/// its stage kernels' 953 / 967 / 983, three_spheres' 1,121 / 1,135 / 1,138 against 1,041 /
/// 1,115 / 1,156.
pub const WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES: u64 = 15_000;

impl CpuJit {
    /// [`CpuJit::Quick`] for a render of at most [`QUICK_JIT_MAX_SAMPLES`] samples, else
    /// [`CpuJit::Optimized`] (also when the count is unknown: `None`).
    pub fn for_samples(samples: Option<u64>) -> Self {
        match samples {
            Some(n) if n <= QUICK_JIT_MAX_SAMPLES => CpuJit::Quick,
            _ => CpuJit::Optimized,
        }
    }

    /// The JIT for a still render of `samples` samples in all whose kernels are known: the
    /// wavefront model's stage kernels (`wavefront`) get [`CpuJit::Quick`] up to
    /// [`QUICK_JIT_MAX_SAMPLES`], as [`CpuJit::for_samples`] gives; a megakernel up to
    /// [`QUICK_JIT_MAX_SAMPLES_SECONDARY`] when its scene spawns secondary rays, else up to
    /// [`QUICK_JIT_MAX_SAMPLES_PRIMARY`]. Larger renders get [`CpuJit::Optimized`].
    pub fn for_render(samples: u64, wavefront: bool, secondary_rays: bool) -> Self {
        let bound = if wavefront {
            QUICK_JIT_MAX_SAMPLES
        } else if secondary_rays {
            QUICK_JIT_MAX_SAMPLES_SECONDARY
        } else {
            QUICK_JIT_MAX_SAMPLES_PRIMARY
        };
        if samples <= bound {
            CpuJit::Quick
        } else {
            CpuJit::Optimized
        }
    }
}

/// The variables [`apply_lavapipe_defaults`] set (the environment had none of them).
static APPLIED: OnceLock<Vec<&'static str>> = OnceLock::new();

/// rtc's settings for a CPU driver, each made only where the environment does not set the
/// variable (an empty value counts as set: `LP_NATIVE_VECTOR_WIDTH=` keeps Mesa's own choice):
/// - [`VECTOR_WIDTH_VAR`]` = `[`NARROW_WIDTH`] when the machine's Vulkan CPU adapter is lavapipe
///   from a Mesa release before [`NARROW_BEFORE_MESA`], or from a later one on an x86-64 CPU
///   without AVX-512 ([`lavapipe_loads_per_lane`]); on a CPU without AVX-512 only for work of
///   unknown size or below [`WIDE_MIN_SAMPLES`] (`samples`: what the process will render, when
///   known);
/// - [`VECTOR_WIDTH_VAR`]` = `[`WIDEST_WIDTH`] when that adapter is from [`NARROW_BEFORE_MESA`] on,
///   the CPU runs AVX-512 at full width and the render has at least [`WIDEST_MIN_SAMPLES`]
///   (`widest_width`);
/// - [`JIT_VAR`]` = `[`QUICK_JIT`] when `jit` is [`CpuJit::Quick`] and the machine has a Vulkan
///   lavapipe adapter;
/// - [`CACHE_DIR_VAR`] to [`width_cache_dir`]'s directory for the width when [`VECTOR_WIDTH_VAR`]
///   is set (by the user or as above) on lavapipe before [`NARROW_BEFORE_MESA`], whose shader
///   cache keys leave the width out (Mesa 26's keep it), and neither `MESA_SHADER_CACHE_DIR` nor
///   `MESA_GLSL_CACHE_DIR` is set: kernels compiled at one width are never run at another.
///
/// Returns the names it set. It asks the Vulkan driver first (a Vulkan instance made and dropped;
/// lavapipe reads the width again for every instance, the JIT switches once per process, hence the
/// JIT variable is set before that and taken back when no lavapipe answers), so it costs one
/// adapter enumeration. Call it before the program's first wgpu `Instance` and while no other
/// thread runs, first thing in `main` (or, as `rtc render` does to choose the JIT from the compiled
/// scene's size, on the one thread left running before any GPU work): changing the environment
/// while another thread reads it is undefined behaviour in most C libraries. Later calls change
/// nothing. Drivers other than llvmpipe ignore both variables.
#[cfg(not(target_arch = "wasm32"))]
pub fn apply_lavapipe_defaults(jit: CpuJit, samples: Option<u64>) -> &'static [&'static str] {
    APPLIED.get_or_init(|| {
        let quick = jit == CpuJit::Quick && std::env::var_os(JIT_VAR).is_none();
        if quick {
            std::env::set_var(JIT_VAR, QUICK_JIT);
        }
        let info = lavapipe_driver_info();
        let mut set = Vec::new();
        if quick && info.is_some() {
            set.push(JIT_VAR);
        } else if quick {
            std::env::remove_var(JIT_VAR);
        }
        let avx512 = lavapipe_has_avx512(|name| std::env::var_os(name));
        // `/proc/cpuinfo` is read only where the answer matters: lavapipe not given 128 bits.
        let full_width = || {
            let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
            full_width_avx512(&cpuinfo, avx512)
        };
        let width = info.as_deref().and_then(|info| {
            if narrow_width(info, avx512, samples) {
                Some(NARROW_WIDTH)
            } else if widest_width(info, full_width(), samples) {
                Some(WIDEST_WIDTH)
            } else {
                None
            }
        });
        if let Some(width) = width.filter(|_| std::env::var_os(VECTOR_WIDTH_VAR).is_none()) {
            std::env::set_var(VECTOR_WIDTH_VAR, width);
            set.push(VECTOR_WIDTH_VAR);
        }
        // Releases before Mesa 26 leave the width out of their shader cache's key.
        let unkeyed = info
            .as_deref()
            .and_then(mesa_major)
            .is_some_and(|major| major < NARROW_BEFORE_MESA);
        if unkeyed {
            // Mesa makes only the last directory of the path; without it the cache is off.
            if let Some(dir) = width_cache_dir(|name| std::env::var_os(name))
                .filter(|dir| std::fs::create_dir_all(dir).is_ok())
            {
                std::env::set_var(CACHE_DIR_VAR, dir);
                set.push(CACHE_DIR_VAR);
            }
        }
        set
    })
}

/// The shader cache directory for lavapipe's SIMD width in an environment read through `var`:
/// `rtc/mesa-lp<width>` in the directory Mesa would use (`$XDG_CACHE_HOME`, else `$HOME/.cache`),
/// for a non-empty [`VECTOR_WIDTH_VAR`] of digits only; `None` when the width is Mesa's own
/// (unset or empty), when the user chose a cache directory (`MESA_SHADER_CACHE_DIR` or the older
/// `MESA_GLSL_CACHE_DIR`), or when there is no home to put it in. Mesa 25's lavapipe keys its
/// shader cache by the driver build, the CPU's features and `GALLIVM_PERF`, not by the width, so a
/// kernel compiled at 256 bits by one process was found again and run at 256 bits by a 128-bit one
/// (measured: `LP_NATIVE_VECTOR_WIDTH=256 rtc render examples/hello/scene.rt` compiled in 970 ms,
/// then the same render at rtc's 128 bits took 86 ms of "pipelines", a cache hit;
/// docs/bench/lavapipe.md, "One shader cache per SIMD width (2026-12-06, night)").
pub fn width_cache_dir(
    var: impl Fn(&str) -> Option<std::ffi::OsString>,
) -> Option<std::path::PathBuf> {
    let width = var(VECTOR_WIDTH_VAR)?;
    let width = width.to_str()?;
    if width.is_empty() || !width.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    if var(CACHE_DIR_VAR).is_some() || var("MESA_GLSL_CACHE_DIR").is_some() {
        return None;
    }
    let non_empty = |name: &str| var(name).filter(|v| !v.is_empty());
    let home = non_empty("XDG_CACHE_HOME")
        .map(std::path::PathBuf::from)
        .or_else(|| non_empty("HOME").map(|h| std::path::PathBuf::from(h).join(".cache")))?;
    Some(home.join("rtc").join(format!("mesa-lp{width}")))
}

/// The variables [`apply_lavapipe_defaults`] set in this process (empty before it runs). A child
/// process that may run on another driver, or render other work, should not inherit them: remove
/// them from its environment, and its own `main` chooses for its driver and work.
pub fn lavapipe_defaults_applied() -> &'static [&'static str] {
    APPLIED.get().map_or(&[], Vec::as_slice)
}

/// The `driver_info` of the first Vulkan CPU adapter that is llvmpipe (lavapipe), e.g.
/// `Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)`.
#[cfg(not(target_arch = "wasm32"))]
fn lavapipe_driver_info() -> Option<String> {
    let vulkan = super::AdapterChoice {
        backend: Some(wgpu::Backend::Vulkan),
        ..super::AdapterChoice::default()
    };
    super::list_adapters(&vulkan)
        .into_iter()
        .find(|a| a.device_type == wgpu::DeviceType::Cpu && a.name.starts_with("llvmpipe"))
        .map(|a| a.driver_info)
}

/// Whether lavapipe with this `driver_info`, on this machine, compiles storage-buffer loads to
/// code per lane of a SIMD batch, where rtc gives it 128-bit batches ([`apply_lavapipe_defaults`])
/// and small tables in uniform buffers (`scene::prefers_uniform_tables`). See `loads_per_lane`.
pub fn lavapipe_loads_per_lane(driver_info: &str) -> bool {
    loads_per_lane(
        driver_info,
        lavapipe_has_avx512(|name| std::env::var_os(name)),
    )
}

/// Whether lavapipe with this `driver_info` compiles storage-buffer loads to code per lane: Mesa
/// before [`NARROW_BEFORE_MESA`] (a loop over the lanes, a bounds check and a branch a word), and
/// later releases when their code may not use AVX-512 (`avx512` false: see `lavapipe_has_avx512`).
/// Mesa 26 compiles loads to LLVM gathers, which LLVM emits as gather instructions with AVX-512
/// and, without it, only on CPUs it counts as fast at them (Intel's since Skylake); on the others
/// as one tested branch and load per lane (AMD Zen 3, `GALLIVM_DEBUG=asm`: 4 `vpgatherdd` against
/// 2,711 `testb` in hello's kernel). There 128 bits compiled every example measured 1.2 to 1.5
/// times faster and ran its megakernel frame 0.75 to 1.02 times as long (the thesis scene 1.08),
/// its stage kernels 0.80 to 0.92 (the thesis scene 1.20), and uniform tables then made frames
/// 0.71 to 0.99 times as long, images byte-identical (docs/bench/lavapipe.md,
/// "Per-lane loads on CPUs without AVX-512 (2026-12-07)"). An Intel CPU without AVX-512 counts as
/// per-lane too; not measured there. A string without a Mesa version is not lavapipe's.
fn loads_per_lane(driver_info: &str, avx512: bool) -> bool {
    mesa_major(driver_info).is_some_and(|major| major < NARROW_BEFORE_MESA || !avx512)
}

/// The fewest samples (pixels times samples per pixel) of a render for which rtc leaves lavapipe
/// its own SIMD width on a CPU without AVX-512 (see `narrow_width`): 2^25 (33.5 M), e.g. 1920x1080
/// at 17 spp or 4096x4096 at 2. There (AMD Zen 3) 256-bit batches run most frames faster than
/// 128-bit ones but compile every kernel 1.3 to 2.0 times longer (optimised JIT, cold), so they pay
/// only for long work: 256 / 128-bit frame on Mesa 25.0.7 0.80 (cameras) to 1.05 (shading), on
/// Mesa 26.1.6 0.67 (lights) to 1.05 (cornell_path); the compile repaid after 7 M (cornell_path) to
/// 31 M samples (thesis_scene) for six of nine examples on Mesa 25 (gltf_scene 168 M, pbr_path
/// 145 M, shading never), and after 1.7 M (hello) to 10 M (gltf_scene) for five of nine on Mesa 26
/// (not for cornell_path, pbr_path and shading, whose frames are 1 to 5 % slower at 256 bits, nor
/// for the thesis scene's 1 to 6 %). The thesis scene at 17 spp, cold, Mesa 25: 21.9 s at 256 bits
/// against 22.8 s at 128. So one still render of any example's own size, a preview and the first
/// pixel keep 128 bits; `rtc render` counts an animation's samples over all its frames (every
/// shard alike, so that shards stay byte-identical to the unsharded render). Measured on
/// 2026-12-07:
/// docs/bench/lavapipe.md, "The SIMD width by the size of the render (2026-12-07, later)".
pub const WIDE_MIN_SAMPLES: u64 = 1 << 25;

/// The fewest samples (pixels times samples per pixel) of a render for which rtc gives lavapipe
/// 512-bit batches ([`WIDEST_WIDTH`], 16 invocations a batch) on a CPU whose AVX-512 units are
/// 512 bits wide (`full_width_avx512`): 2^23 (8.4 M), e.g. 1920x1080 at 5 spp. Measured on AMD
/// Zen 5 (EPYC, family 26 model 2) with Mesa 26.1.6, every example, alternated: the 512-bit frame
/// is 0.71 (lights) to 0.92 (shading) of the 256-bit one, the thesis scene's 0.83, the path
/// tracers' 0.86 to 0.90, glass_mirror's 1.02 (43 ms frames), images byte-identical; but every
/// kernel's optimised compile takes 37 to 516 ms longer (cold; fog 887 → 1,404 ms, the thesis
/// scene 299 → 385), repaid after 0.7 M (cornell_path) to 6.6 M samples (cameras). The bound keeps
/// a margin of 1.28 above the largest. On Zen 4, whose AVX-512 runs 512-bit operations in two
/// 256-bit halves, the thesis frame was 0.92 and the path tracers equal or slower, so it keeps
/// Mesa's 256 (docs/bench/lavapipe.md, "512-bit batches on Zen 5 (2026-12-07, night)").
pub const WIDEST_MIN_SAMPLES: u64 = 1 << 23;

/// The width [`apply_lavapipe_defaults`] gives lavapipe from [`NARROW_BEFORE_MESA`] on for renders
/// of at least [`WIDEST_MIN_SAMPLES`] on a CPU with full-width AVX-512 (`full_width_avx512`).
pub const WIDEST_WIDTH: &str = "512";

/// Whether [`apply_lavapipe_defaults`] gives lavapipe with this `driver_info` [`WIDEST_WIDTH`]
/// batches for a render of `samples` samples: from [`NARROW_BEFORE_MESA`] on (whose loads are
/// gathers; before it each load is a loop over the batch's lanes, whose code grows with the
/// batch), on a CPU with full-width AVX-512 (`full_width`), for a render known to have at least
/// [`WIDEST_MIN_SAMPLES`] (a session of frames not counted ahead keeps Mesa's own width, as it
/// does on CPUs without AVX-512).
#[cfg(not(target_arch = "wasm32"))]
fn widest_width(driver_info: &str, full_width: bool, samples: Option<u64>) -> bool {
    full_width
        && mesa_major(driver_info).is_some_and(|major| major >= NARROW_BEFORE_MESA)
        && samples.is_some_and(|n| n >= WIDEST_MIN_SAMPLES)
}

/// Whether llvmpipe may use AVX-512 (`lavapipe_has_avx512`) on a CPU known to run 512-bit
/// operations at full width, read from a `/proc/cpuinfo` text: AMD's family 26 (Zen 5). Measured
/// on the EPYC (family 26 model 2); the laptop parts of that family that run AVX-512 in two halves
/// (Strix Point) were not, nor Intel's CPUs, which keep Mesa's width.
#[cfg(not(target_arch = "wasm32"))]
fn full_width_avx512(cpuinfo: &str, avx512: bool) -> bool {
    avx512
        && cpuinfo_field(cpuinfo, "vendor_id") == Some("AuthenticAMD")
        && family_model(cpuinfo).is_some_and(|(family, _)| family == 26)
}

/// Whether [`apply_lavapipe_defaults`] gives lavapipe with this `driver_info` 128-bit batches for a
/// render of `samples` samples (`None`: unknown, or a session of frames not counted ahead, such as
/// `rtc view`): wherever its loads are per-lane code (`loads_per_lane`), except on a CPU without
/// AVX-512 for a render of at least [`WIDE_MIN_SAMPLES`]. With AVX-512 (Mesa 25) 256 bits do not
/// run frames faster (0.70 to 1.14 of the 128-bit frame, docs/bench/lavapipe.md), so every render
/// keeps 128 there.
#[cfg(not(target_arch = "wasm32"))]
fn narrow_width(driver_info: &str, avx512: bool, samples: Option<u64>) -> bool {
    loads_per_lane(driver_info, avx512) && (avx512 || samples.is_none_or(|n| n < WIDE_MIN_SAMPLES))
}

/// Whether llvmpipe may compile for AVX-512 in an environment read through `var`: the CPU has
/// AVX-512F and `GALLIUM_OVERRIDE_CPU_CAPS` is unset (each of its values, `nosse` to `avx`, leaves
/// AVX-512 out). `true` off x86-64, where nothing here applies.
fn lavapipe_has_avx512(var: impl Fn(&str) -> Option<std::ffi::OsString>) -> bool {
    if !cfg!(target_arch = "x86_64") {
        return true;
    }
    vector_features().contains(&"AVX-512") && var("GALLIUM_OVERRIDE_CPU_CAPS").is_none()
}

/// The major version of `Mesa X.Y.Z…` in a driver string.
fn mesa_major(driver_info: &str) -> Option<u32> {
    let rest = &driver_info[driver_info.find("Mesa ")? + "Mesa ".len()..];
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    digits.parse().ok()
}

/// Mesa's variables that change what llvmpipe compiles for, or how (`GALLIVM_PERF=nopt` turns
/// LLVM's optimisation passes off); named in [`HostCpu`]'s line when set.
const MESA_CPU_VARIABLES: [&str; 3] = ["GALLIUM_OVERRIDE_CPU_CAPS", VECTOR_WIDTH_VAR, JIT_VAR];

/// The machine a figure was measured on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HostCpu {
    /// The model name, e.g. `AMD EPYC 7B13`.
    pub model: String,
    /// The CPU's family and model numbers (`cpu family`, `model` in `/proc/cpuinfo`), which tell
    /// apart the generations a virtual machine's model name hides (`AMD EPYC` is family 25 for
    /// Zen 3 and Zen 4, 26 for Zen 5, and lavapipe's speed differs between them); `None` where
    /// `/proc/cpuinfo` does not say.
    pub family_model: Option<(u32, u32)>,
    /// Hardware threads this process may use.
    pub threads: usize,
    /// The vector extensions that decide a CPU driver's speed, present on this CPU: `AVX2`,
    /// `AVX-512` (x86-64 only; empty elsewhere).
    pub vector: Vec<&'static str>,
    /// Mesa variables that restrict what llvmpipe uses (`NAME=value`), set in this process; those
    /// [`apply_lavapipe_defaults`] set are marked `(rtc's default)`.
    pub mesa_overrides: Vec<String>,
}

impl HostCpu {
    /// Reads the running machine's CPU.
    pub fn detect() -> Self {
        let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
        let model = model_name(&cpuinfo).unwrap_or_else(|| std::env::consts::ARCH.to_string());
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let mesa_overrides = MESA_CPU_VARIABLES
            .iter()
            .filter_map(|name| {
                let value = std::env::var(name).ok()?;
                let ours = lavapipe_defaults_applied().contains(name);
                (!value.is_empty()).then(|| match (ours, *name == JIT_VAR) {
                    (false, _) => format!("{name}={value}"),
                    (true, false) => format!("{name}={value} (rtc's default)"),
                    (true, true) => format!("{name}={value} (rtc's quick JIT for a small render)"),
                })
            })
            .collect();
        Self {
            model,
            family_model: family_model(&cpuinfo),
            threads,
            vector: vector_features(),
            mesa_overrides,
        }
    }

    /// `AVX2 and AVX-512`, `AVX2, no AVX-512`, or `no AVX2` (x86-64); `None` on other architectures.
    pub fn vector_summary(&self) -> Option<String> {
        if !cfg!(target_arch = "x86_64") {
            return None;
        }
        let avx2 = self.vector.contains(&"AVX2");
        let avx512 = self.vector.contains(&"AVX-512");
        Some(
            match (avx2, avx512) {
                (true, true) => "AVX2 and AVX-512",
                (true, false) => "AVX2, no AVX-512",
                (false, true) => "AVX-512, no AVX2",
                (false, false) => "no AVX2, no AVX-512",
            }
            .to_string(),
        )
    }
}

impl fmt::Display for HostCpu {
    /// One line: `AMD EPYC 7B13 (family 25 model 1), 2 threads, AVX2 and AVX-512` (and
    /// `; GALLIUM_OVERRIDE_CPU_CAPS=avx` when such a variable is set).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.model)?;
        if let Some((family, model)) = self.family_model {
            write!(f, " (family {family} model {model})")?;
        }
        write!(
            f,
            ", {} thread{}",
            self.threads,
            if self.threads == 1 { "" } else { "s" }
        )?;
        if let Some(v) = self.vector_summary() {
            write!(f, ", {v}")?;
        }
        if !self.mesa_overrides.is_empty() {
            write!(f, "; {}", self.mesa_overrides.join(" "))?;
        }
        Ok(())
    }
}

/// The value of the first `name` line of a `/proc/cpuinfo` text, trimmed; `None` when there is
/// none or it is empty.
fn cpuinfo_field<'a>(cpuinfo: &'a str, name: &str) -> Option<&'a str> {
    cpuinfo.lines().find_map(|line| {
        let (key, value) = line.split_once(':')?;
        (key.trim() == name && !value.trim().is_empty()).then(|| value.trim())
    })
}

/// The first `model name` line of a `/proc/cpuinfo` text, trimmed; `None` when there is none.
fn model_name(cpuinfo: &str) -> Option<String> {
    cpuinfo_field(cpuinfo, "model name").map(str::to_string)
}

/// The `cpu family` and `model` numbers of a `/proc/cpuinfo` text (x86); `None` unless both are
/// there and decimal.
fn family_model(cpuinfo: &str) -> Option<(u32, u32)> {
    let number = |name| cpuinfo_field(cpuinfo, name)?.parse().ok();
    Some((number("cpu family")?, number("model")?))
}

#[cfg(target_arch = "x86_64")]
fn vector_features() -> Vec<&'static str> {
    let mut v = Vec::new();
    if std::arch::is_x86_feature_detected!("avx2") {
        v.push("AVX2");
    }
    if std::arch::is_x86_feature_detected!("avx512f") {
        v.push("AVX-512");
    }
    v
}

#[cfg(not(target_arch = "x86_64"))]
fn vector_features() -> Vec<&'static str> {
    Vec::new()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_simd_width_gets_a_shader_cache_of_its_own() {
        use std::ffi::OsString;
        use std::path::PathBuf;
        fn env<'a>(pairs: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<OsString> + 'a {
            move |name: &str| {
                pairs
                    .iter()
                    .find(|(n, _)| *n == name)
                    .map(|(_, v)| OsString::from(v))
            }
        }
        let home = [("HOME", "/home/u"), (VECTOR_WIDTH_VAR, "128")];
        assert_eq!(
            width_cache_dir(env(&home)),
            Some(PathBuf::from("/home/u/.cache/rtc/mesa-lp128"))
        );
        let xdg = [
            ("HOME", "/home/u"),
            ("XDG_CACHE_HOME", "/c"),
            (VECTOR_WIDTH_VAR, "256"),
        ];
        assert_eq!(
            width_cache_dir(env(&xdg)),
            Some(PathBuf::from("/c/rtc/mesa-lp256"))
        );
        // Mesa's own width, the user's cache directory, no home, or a width that is not a number:
        // nothing.
        for pairs in [
            &[("HOME", "/home/u")][..],
            &[("HOME", "/home/u"), (VECTOR_WIDTH_VAR, "")],
            &[
                ("HOME", "/home/u"),
                (VECTOR_WIDTH_VAR, "128"),
                (CACHE_DIR_VAR, "/m"),
            ],
            &[
                ("HOME", "/home/u"),
                (VECTOR_WIDTH_VAR, "128"),
                ("MESA_GLSL_CACHE_DIR", "/m"),
            ],
            &[(VECTOR_WIDTH_VAR, "128")],
            &[("HOME", ""), (VECTOR_WIDTH_VAR, "128")],
            &[("HOME", "/home/u"), (VECTOR_WIDTH_VAR, "../x")],
        ] {
            assert_eq!(width_cache_dir(env(pairs)), None, "{pairs:?}");
        }
    }

    #[test]
    fn the_model_name_is_the_first_model_line() {
        let text = "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC 7B13\n\
                    processor\t: 1\nmodel name\t: AMD EPYC 7B13\n";
        assert_eq!(model_name(text).as_deref(), Some("AMD EPYC 7B13"));
        assert_eq!(model_name("processor : 0\nmodel name :   \n"), None);
        assert_eq!(model_name(""), None);
        assert_eq!(
            family_model("vendor_id\t: AuthenticAMD\ncpu family\t: 26\nmodel\t\t: 2\nmodel name\t: AMD EPYC\n"),
            Some((26, 2))
        );
        // `model name` is not `model`; an absent or odd number gives nothing.
        assert_eq!(
            family_model("cpu family\t: 26\nmodel name\t: AMD EPYC\n"),
            None
        );
        assert_eq!(family_model("cpu family\t: 0x1a\nmodel\t\t: 2\n"), None);
        assert_eq!(family_model(""), None);
    }

    #[test]
    fn the_line_names_model_threads_vectors_and_overrides() {
        let cpu = HostCpu {
            model: "AMD EPYC 7B13".into(),
            family_model: Some((25, 1)),
            threads: 2,
            vector: vec!["AVX2"],
            mesa_overrides: vec!["GALLIUM_OVERRIDE_CPU_CAPS=avx".into()],
        };
        let line = cpu.to_string();
        if cfg!(target_arch = "x86_64") {
            assert_eq!(
                line,
                "AMD EPYC 7B13 (family 25 model 1), 2 threads, AVX2, no AVX-512; \
                 GALLIUM_OVERRIDE_CPU_CAPS=avx"
            );
        } else {
            assert_eq!(
                line,
                "AMD EPYC 7B13 (family 25 model 1), 2 threads; GALLIUM_OVERRIDE_CPU_CAPS=avx"
            );
        }
        let unknown = HostCpu {
            model: "aarch64".into(),
            family_model: None,
            threads: 1,
            vector: Vec::new(),
            mesa_overrides: Vec::new(),
        };
        assert!(unknown.to_string().starts_with("aarch64, 1 thread"));
    }

    #[test]
    fn lavapipe_loads_per_lane_before_mesa_26_and_without_avx512() {
        assert_eq!(mesa_major("Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"), Some(25));
        assert_eq!(mesa_major("Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)"), Some(26));
        assert_eq!(mesa_major("Mesa 22.3.6"), Some(22));
        for avx512 in [true, false] {
            assert!(loads_per_lane(
                "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)",
                avx512
            ));
            assert!(loads_per_lane("Mesa 22.3.6", avx512));
            // No version, or not Mesa: nothing.
            assert!(!loads_per_lane("", avx512));
            assert!(!loads_per_lane("Mesa devel", avx512));
            assert!(!loads_per_lane("535.104.05", avx512));
        }
        // Mesa 26 on: only where llvmpipe may not use AVX-512.
        assert!(!loads_per_lane("Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)", true));
        assert!(!loads_per_lane("Mesa 27.0.0-devel", true));
        assert!(loads_per_lane("Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)", false));
        assert!(loads_per_lane("Mesa 27.0.0-devel", false));
    }

    #[test]
    fn long_renders_keep_mesas_width_only_without_avx512() {
        let mesa_25 = "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)";
        let mesa_26 = "Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)";
        let long = Some(WIDE_MIN_SAMPLES);
        let short = Some(WIDE_MIN_SAMPLES - 1);
        for samples in [None, short, long] {
            // With AVX-512: Mesa 25 always narrow, Mesa 26 never.
            assert!(narrow_width(mesa_25, true, samples));
            assert!(!narrow_width(mesa_26, true, samples));
            // Not lavapipe: nothing.
            assert!(!narrow_width("535.104.05", false, samples));
        }
        // Without AVX-512: narrow unless the render is known to be long.
        for info in [mesa_25, mesa_26] {
            assert!(narrow_width(info, false, None));
            assert!(narrow_width(info, false, short));
            assert!(!narrow_width(info, false, long));
        }
        // 1920x1080 at 16 spp is just below the bound, at 17 spp above it (as its docs say).
        let full_hd = |spp: u64| Some(1920 * 1080 * spp);
        assert!(narrow_width(mesa_25, false, full_hd(16)));
        assert!(!narrow_width(mesa_25, false, full_hd(17)));
    }

    #[test]
    fn long_renders_get_512_bits_only_on_full_width_avx512_from_mesa_26() {
        let mesa_25 = "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)";
        let mesa_26 = "Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)";
        let long = Some(WIDEST_MIN_SAMPLES);
        let short = Some(WIDEST_MIN_SAMPLES - 1);
        assert!(widest_width(mesa_26, true, long));
        assert!(widest_width("Mesa 27.0.0-devel", true, long));
        // A shorter render, or one of unknown size: Mesa's width.
        assert!(!widest_width(mesa_26, true, short));
        assert!(!widest_width(mesa_26, true, None));
        // Mesa 25 (per-lane loops), another CPU, or not lavapipe: never.
        assert!(!widest_width(mesa_25, true, long));
        assert!(!widest_width(mesa_26, false, long));
        assert!(!widest_width("535.104.05", true, long));
        // 1920x1080 at 4 spp is just below the bound, at 5 spp above it (as its docs say).
        let full_hd = |spp: u64| Some(1920 * 1080 * spp);
        assert!(!widest_width(mesa_26, true, full_hd(4)));
        assert!(widest_width(mesa_26, true, full_hd(5)));
        // The two rules never both hold: 512 bits need AVX-512 and Mesa 26, where loads are gathers.
        for info in [mesa_25, mesa_26] {
            for samples in [None, short, long] {
                for avx512 in [true, false] {
                    assert!(
                        !(narrow_width(info, avx512, samples)
                            && widest_width(info, avx512, samples))
                    );
                }
            }
        }
    }

    #[test]
    fn full_width_avx512_is_amds_family_26() {
        let cpu = |vendor: &str, family: &str| {
            format!(
                "processor\t: 0\nvendor_id\t: {vendor}\ncpu family\t: {family}\nmodel\t\t: 2\n\
                 model name\t: AMD EPYC\nflags\t\t: avx2 avx512f\n"
            )
        };
        assert!(full_width_avx512(&cpu("AuthenticAMD", "26"), true));
        // llvmpipe kept off AVX-512 (a caps override), Zen 4 and Zen 3, Intel, or no cpuinfo.
        assert!(!full_width_avx512(&cpu("AuthenticAMD", "26"), false));
        assert!(!full_width_avx512(&cpu("AuthenticAMD", "25"), true));
        assert!(!full_width_avx512(&cpu("GenuineIntel", "6"), true));
        assert!(!full_width_avx512(&cpu("GenuineIntel", "26"), true));
        assert!(!full_width_avx512("", true));
    }

    #[test]
    fn a_cpu_caps_override_keeps_llvmpipe_off_avx512() {
        let caps = |name: &str| {
            (name == "GALLIUM_OVERRIDE_CPU_CAPS").then(|| std::ffi::OsString::from("avx"))
        };
        assert!(!lavapipe_has_avx512(caps) || !cfg!(target_arch = "x86_64"));
        let none = |_: &str| None;
        assert_eq!(
            lavapipe_has_avx512(none),
            !cfg!(target_arch = "x86_64") || vector_features().contains(&"AVX-512")
        );
    }

    #[test]
    fn only_small_renders_get_the_quick_jit() {
        assert_eq!(CpuJit::for_samples(Some(64 * 48)), CpuJit::Quick);
        assert_eq!(CpuJit::for_samples(Some(256 * 256 * 2)), CpuJit::Quick);
        assert_eq!(
            CpuJit::for_samples(Some(256 * 256 * 2 + 1)),
            CpuJit::Optimized
        );
        assert_eq!(CpuJit::for_samples(Some(512 * 512)), CpuJit::Optimized);
        assert_eq!(CpuJit::for_samples(Some(1920 * 1080)), CpuJit::Optimized);
        assert_eq!(CpuJit::for_samples(None), CpuJit::Optimized);
    }

    #[test]
    fn a_known_render_gets_the_bound_of_its_kernels() {
        // The wavefront model's stage kernels: the bound of an unknown kernel.
        assert_eq!(CpuJit::for_render(1 << 17, true, false), CpuJit::Quick);
        assert_eq!(
            CpuJit::for_render((1 << 17) + 1, true, false),
            CpuJit::Optimized
        );
        // A megakernel with secondary rays: hello and shading at their own size and samples
        // (320x240 at 4 spp, 320x240 at 5).
        assert_eq!(
            CpuJit::for_render(320 * 240 * 5, false, true),
            CpuJit::Quick
        );
        assert_eq!(
            CpuJit::for_render(640 * 640, false, true),
            CpuJit::Optimized
        );
        // Without: gltf_scene's 480x320 at 4 spp, but not the thesis scene's 1080p frame.
        assert_eq!(
            CpuJit::for_render(480 * 320 * 4, false, false),
            CpuJit::Quick
        );
        assert_eq!(CpuJit::for_render(1024 * 768, false, false), CpuJit::Quick);
        assert_eq!(
            CpuJit::for_render(1920 * 1080, false, false),
            CpuJit::Optimized
        );
    }

    #[test]
    fn detection_does_not_fail() {
        let cpu = HostCpu::detect();
        assert!(!cpu.model.is_empty());
        assert!(cpu.threads >= 1);
    }
}
