//! The kernel's features beyond plain closest-hit traversal (issue 4), each on a scene of
//! `scenes/kernel_features/` with its own test programs, rendered on whatever adapter exists (lavapipe on CI):
//!
//! - `@any_hit` for alpha: a cut-out whose program rejects half of its surface; the rejected hits are
//!   ignored (the floor behind shows through), the accepted ones are seen. Exact colours.
//! - `@any_hit` for shadow rays: blockers invisible to camera rays, one that casts no shadow at all
//!   (a fog boundary), one cut in half, one cut elsewhere; a floor point is dark exactly where some
//!   blocker accepts its shadow ray. Exact 0 or 1.
//! - media: nested closed boxes with `@medium` programs (Beer–Lambert absorption) and boundaries that
//!   let rays through; a camera inside the outer box (its rays start in that medium) and one
//!   outside it. Every ray enters and leaves media at hits; the transmittance must be
//!   `exp(-Σ σᵢ dᵢ)` over the segments, within 1e-4 relative.
//! - custom geometry whose `@intersection` walks its own mesh BVH with `mesh_node` and
//!   `mesh_triangle`: it must see what the built-in mesh geometry sees (hit or miss for every pixel,
//!   `t` within 1e-5 relative, geometric normal within 1e-5 except at most 1% of the pixels, where
//!   a ray through a shared edge may take either triangle).
//!
//! - the wavefront execution model against the megakernel, on every scene of the suite in small
//!   tiles (bit-identical on lavapipe), with its shadow rays traced in the shadow stage and in the
//!   shade stage (then the same rays counted); on a shading step whose second shadow query depends on
//!   the first answer (replayed until exact), and past the shadow queries one step records (warned);
//!   a camera of several samples a pass, whose later samples start in later rounds.
//! - a `@light` program whose shadow queries depend on each other's answers: the megakernel defers
//!   them to `sample_light` and runs the program again until every answer is known, so it must
//!   give the wavefront model's image pixel for pixel; past `LIGHT_QUERIES` queries in one light
//!   sample the megakernel warns.
//!
//! - `sample_light_unoccluded`: a light's sample as if nothing blocked it, with no ray traced, and
//!   `sample_light_above`: a light's sample that is 0 without a ray below the surface and traced
//!   above it, in both models, with one light type and with two.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::SceneFile;
use common::{gpu_or_skip, temp_dir};

use rtc_compiler::kernel::ShadowRays;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::RenderOptions;

/// Compiles `file` and renders it with one sample; asserts that no sample was NaN or infinite.
fn render(gpu: &Gpu, name: &str, file: &SceneFile) -> LinearImage {
    let dir = temp_dir("features", name);
    let compiled = file.compile(&dir);
    let options = RenderOptions {
        samples: Some(1),
        ..RenderOptions::default()
    };
    let (image, _) = common::scene::render(gpu, &compiled, options, name);
    image
}

/// A scene file of `scenes/kernel_features/`.
fn scene(name: &str) -> SceneFile {
    SceneFile::open(&format!("kernel_features/{name}.rt"))
}

fn px(img: &LinearImage, x: u32, y: u32) -> [f32; 3] {
    let p = img.get(x, y).expect("pixel inside the image");
    [p[0], p[1], p[2]]
}

/// Image side of the `Down` scenes (scenes `cut_out` and `shadows`, which import `down.rt`, a camera
/// looking straight down (-y) from y = 10 with parallel rays through the pixel centres over
/// `x, z ∈ [-3, 3]`): 24 pixels over 6 units, pixel centres at `-2.875 + 0.25 k`, so
/// none lies on a cut at x = 0 or x = -1.5, on z = 0, or on an edge of the quads.
const SIDE: u32 = 24;

/// World x (or z) of pixel column (or row) `i`.
fn coord(i: u32) -> f64 {
    (f64::from(i) + 0.5) / f64::from(SIDE) * 6.0 - 3.0
}

#[test]
fn an_any_hit_cut_out_hides_only_what_it_accepts() {
    let Some(gpu) = gpu_or_skip("an_any_hit_cut_out_hides_only_what_it_accepts") else {
        return;
    };
    let file = scene("cut_out").set("SIDE", format!("{SIDE}u"));
    let img = render(&gpu, "cut-out", &file);
    for y in 0..SIDE {
        for x in 0..SIDE {
            let (wx, wz) = (coord(x), coord(y));
            let want = if wz < 0.0 && wx > 0.0 {
                [1.0, 0.0, 0.0] // the accepted half of the cut-out
            } else if wx < 2.0 {
                [0.0, 1.0, 0.0] // the floor, through the hole or beside the cut-out
            } else {
                [0.0, 0.0, 1.0]
            };
            assert_eq!(
                px(&img, x, y),
                want,
                "pixel ({x}, {y}) at x = {wx}, z = {wz}"
            );
        }
    }
}

#[test]
fn shadow_rays_stop_at_the_first_hit_an_any_hit_accepts() {
    let Some(gpu) = gpu_or_skip("shadow_rays_stop_at_the_first_hit_an_any_hit_accepts") else {
        return;
    };
    let file = scene("shadows").set("SIDE", format!("{SIDE}u"));
    let img = render(&gpu, "shadows", &file);
    let mut dark = 0;
    for y in 0..SIDE {
        for x in 0..SIDE {
            let (wx, wz) = (coord(x), coord(y));
            let blocked = (wz < 0.0 && wx > 0.0) || wx < -1.5;
            let v = if blocked { 0.0 } else { 1.0 };
            dark += usize::from(blocked);
            assert_eq!(
                px(&img, x, y),
                [v, v, v],
                "pixel ({x}, {y}) at x = {wx}, z = {wz}"
            );
        }
    }
    assert!(dark > 0 && dark < (SIDE * SIDE) as usize);
}

#[test]
fn rays_enter_and_leave_nested_media_at_hits() {
    let Some(gpu) = gpu_or_skip("rays_enter_and_leave_nested_media_at_hits") else {
        return;
    };
    const SA: f64 = 0.05;
    const SB: f64 = 0.3;
    let file = scene("nested_media")
        .set("SIGMA_OUTER", format!("{SA:?}"))
        .set("SIGMA_INNER", format!("{SB:?}"));
    let img = render(&gpu, "nested-media", &file);
    let mut check = PixelCheck::new(
        "nested media: exp(-Σ σᵢ dᵢ); row 0 from inside the outer box (path 10 to its far wall), \
         row 1 from outside it (path 30), row 2 from inside the inner box (path 6: 1 in the inner \
         box, then 5 in the outer medium, which a probe finds when the ray leaves the inner box)",
    );
    for row in 0..3u32 {
        // The part outside the outer box (from z = 20 to z = 10) is in no medium.
        let in_outer = [10.0, 20.0, 6.0][row as usize];
        for x in 0..8u32 {
            let through_inner = x < 4;
            let d_inner = match (through_inner, row) {
                (false, _) => 0.0,
                (true, 2) => 1.0,
                (true, _) => 2.0,
            };
            let want = (-SA * (in_outer - d_inner) - SB * d_inner).exp();
            let got = img.get(x, row).expect("pixel");
            check.pixel((x, row), got, &[want; 3], Tolerance::rel(1e-4));
        }
    }
    check.assert();
}

#[test]
fn custom_geometry_walking_its_mesh_bvh_sees_what_the_mesh_geometry_sees() {
    let Some(gpu) =
        gpu_or_skip("custom_geometry_walking_its_mesh_bvh_sees_what_the_mesh_geometry_sees")
    else {
        return;
    };
    // `walker.rt`: a probe material reporting `(t, geometric normal x, geometric normal y)`, and a
    // sphere mesh seen through the built-in mesh geometry and through a custom geometry that walks
    // the mesh's BVH itself.
    let builtin = render(
        &gpu,
        "walker-builtin",
        &scene("walker").scene("walker_builtin"),
    );
    let custom = render(
        &gpu,
        "walker-custom",
        &scene("walker").scene("walker_custom"),
    );
    let (mut hits, mut normal_mismatches) = (0, 0);
    for y in 0..32 {
        for x in 0..32 {
            let (b, c) = (px(&builtin, x, y), px(&custom, x, y));
            assert_eq!(b[0] < 0.0, c[0] < 0.0, "pixel ({x}, {y}): hit or miss");
            if b[0] < 0.0 {
                continue;
            }
            hits += 1;
            assert!(
                (b[0] - c[0]).abs() <= 1e-5 * b[0],
                "pixel ({x}, {y}): t {} (mesh) vs {} (custom)",
                b[0],
                c[0]
            );
            if (b[1] - c[1]).abs() > 1e-5 || (b[2] - c[2]).abs() > 1e-5 {
                normal_mismatches += 1;
            }
        }
    }
    eprintln!("{hits} hits, {normal_mismatches} normals differ");
    assert!(
        hits > 200,
        "the ball covers a good part of the image ({hits} hits)"
    );
    assert!(
        normal_mismatches * 100 <= hits,
        "{normal_mismatches} of {hits} normals differ"
    );
}

/// `file` compiled into `dir` with the wavefront model's stage kernels beside the megakernel.
fn compile_with_stages(
    file: &SceneFile,
    dir: &std::path::Path,
) -> rtc_compiler::kernel::CompiledScene {
    compile_with_stages_placing(file, dir, ShadowRays::Stage, true)
}

/// The scene's stage kernels with its shadow rays traced where `shadow_rays` says (the tests of
/// the replay use the shadow stage, [`compile_with_stages`], whatever the scene would choose).
fn compile_with_stages_placing(
    file: &SceneFile,
    dir: &std::path::Path,
    shadow_rays: ShadowRays,
    large: bool,
) -> rtc_compiler::kernel::CompiledScene {
    use rtc_compiler::kernel::{ExecModel, KernelOptions};
    // `large`: a render larger than `SHADE_ACCUMULATES_MIN_SAMPLES`, so that a shade stage whose
    // samples end in their first step accumulates a listed tile's samples itself; else one of
    // 64 x 48, whose shade stage leaves them to the finish stage.
    let compiled = file.compile_with(
        dir,
        &KernelOptions {
            exec: Some(ExecModel::Wavefront),
            shadow_rays,
            render_size: Some(if large { [256, 256] } else { [64, 48] }),
            render_spp: Some(1),
            ..KernelOptions::default()
        },
    );
    assert_eq!(
        compiled.has_shadow_stage(),
        shadow_rays == ShadowRays::Stage
    );
    // Only a shade stage that replays its steps itself holds that loop.
    assert_eq!(
        compiled.replays_in_shade_stage(),
        shadow_rays == ShadowRays::Replay
    );
    compiled
}

/// Renders `file` with both execution models, in 16 × 16 tiles (so a size that is not a multiple
/// of 16 has smaller edge tiles, whose path records must not see the state a larger tile left),
/// and returns (megakernel, wavefront) images and the wavefront render's statistics.
fn both_models(
    gpu: &Gpu,
    name: &str,
    file: &SceneFile,
    size: [u32; 2],
) -> (LinearImage, LinearImage, rtc_runtime::render::RenderStats) {
    both_models_placing(gpu, name, file, size, ShadowRays::Stage)
}

/// [`both_models`], with the wavefront model's shadow rays traced where `shadow_rays` says.
fn both_models_placing(
    gpu: &Gpu,
    name: &str,
    file: &SceneFile,
    size: [u32; 2],
    shadow_rays: ShadowRays,
) -> (LinearImage, LinearImage, rtc_runtime::render::RenderStats) {
    both_models_in_tiles(gpu, name, file, size, shadow_rays, [16, 16])
}

/// [`both_models_placing`] in tiles of `tile` pixels.
fn both_models_in_tiles(
    gpu: &Gpu,
    name: &str,
    file: &SceneFile,
    size: [u32; 2],
    shadow_rays: ShadowRays,
    [tile_width, tile_height]: [u32; 2],
) -> (LinearImage, LinearImage, rtc_runtime::render::RenderStats) {
    use rtc_compiler::kernel::ExecModel;
    use rtc_runtime::gpu::TileConfig;
    let dir = temp_dir("features", name);
    let compiled = compile_with_stages_placing(file, &dir, shadow_rays, true);
    let options = |exec| RenderOptions {
        size: Some(size),
        samples: Some(1),
        tiles: Some(TileConfig {
            tile_width,
            tile_height,
            tiles_per_batch: 1,
        }),
        exec: Some(exec),
        ..RenderOptions::default()
    };
    let (mega, mega_stats) = common::scene::render(
        gpu,
        &compiled,
        options(ExecModel::Megakernel),
        &format!("{name} (megakernel)"),
    );
    let (wave, stats) = common::scene::render(
        gpu,
        &compiled,
        options(ExecModel::Wavefront),
        &format!("{name} (wavefront)"),
    );
    assert_eq!(stats.exec, ExecModel::Wavefront);
    assert!(stats.rounds > 0, "{name}: no wavefront round ran");
    // A shade stage that traces its shadow rays traces the megakernel's rays, each counted once
    // (the shadow stage traces a replayed step's discarded queries too, and none past the limit).
    if shadow_rays == ShadowRays::Shade {
        assert_eq!(
            stats.rays_traced, mega_stats.rays_traced,
            "{name}: rays traced"
        );
    }
    (mega, wave, stats)
}

/// Small tables in uniform buffers (`rtc_runtime::scene::UniformTables`; by default on lavapipe
/// whose loads are per-lane code, forced on and off here): every pixel is the one the storage buffers give, in
/// both execution models, on scenes with any-hit shadows, a custom geometry whose program walks
/// its mesh's BVH (`nodes` read by user code), nested media and the path loop. A scene with more
/// objects than one uniform buffer holds (600 × 128 bytes) keeps `instances` in storage and still
/// gets `nodes` as a uniform table.
#[test]
fn uniform_tables_change_no_pixel() {
    let Some(gpu) = gpu_or_skip("uniform_tables_change_no_pixel") else {
        return;
    };
    use rtc_compiler::kernel::ExecModel;
    use rtc_runtime::scene::TablePlacement;
    // Tiny blockers that cast no shadow, in a row above the scene.
    let many: String = (0..600)
        .map(|i| {
            format!(
                "    object extra{i} {{ geometry: quad_mesh(), material: Blocker {{ casts: 0.0 }}, \
                 transform: translate(vec3f({}, 5.0, 0.0)) * scale(0.001) }}\n",
                common::scene::float(f64::from(i) * 0.01 - 3.0)
            )
        })
        .collect();
    let both: &[&str] = &["nodes", "instances"];
    let cases = [
        ("shadows", scene("shadows"), both),
        ("walker", scene("walker").scene("walker_custom"), both),
        ("nested", scene("nested_media"), both),
        ("path_loop", scene("path_loop").scene("path_loop"), both),
        (
            "many_objects",
            scene("shadows").append_to_last_scene(&many),
            &["nodes"][..],
        ),
    ];
    for (name, file, placed) in cases {
        let dir = temp_dir("features", &format!("tables_{name}"));
        let compiled = compile_with_stages(&file, &dir);
        for exec in [ExecModel::Megakernel, ExecModel::Wavefront] {
            let options = |uniform_tables| RenderOptions {
                size: Some([24, 20]),
                samples: Some(2),
                exec: Some(exec),
                uniform_tables,
                ..RenderOptions::default()
            };
            let what = format!("{name} ({exec:?})");
            let (storage, s) = common::scene::render(
                &gpu,
                &compiled,
                options(TablePlacement::Storage),
                &format!("{what}, storage"),
            );
            let (uniform, u) = common::scene::render(
                &gpu,
                &compiled,
                options(TablePlacement::Uniform),
                &format!("{what}, uniform tables"),
            );
            assert!(
                s.uniform_tables.is_empty(),
                "{what}: {:?}",
                s.uniform_tables
            );
            assert_eq!(u.uniform_tables, placed, "{what}");
            let differing = storage
                .pixels()
                .iter()
                .zip(uniform.pixels())
                .filter(|(a, b)| a.map(f32::to_bits) != b.map(f32::to_bits))
                .count();
            assert_eq!(differing, 0, "{what}: pixels differ between the placements");
        }
    }
}

/// `RenderOptions::stage_times` (`RTC_STAGE_TIMES` in `rtc render`): each stage's dispatches are
/// waited for and timed alone, every stage kernel gets a time, and the image is the one the plain
/// rounds render, bit for bit.
#[test]
fn timing_the_wavefront_stages_changes_nothing_but_the_report() {
    let Some(gpu) = gpu_or_skip("timing_the_wavefront_stages_changes_nothing_but_the_report")
    else {
        return;
    };
    use rtc_compiler::kernel::ExecModel;
    let dir = temp_dir("features", "stage_times");
    let compiled = compile_with_stages(&scene("shadows").set("SIDE", "40u"), &dir);
    let options = |stage_times| RenderOptions {
        size: Some([40, 28]),
        samples: Some(2),
        exec: Some(ExecModel::Wavefront),
        stage_times,
        ..RenderOptions::default()
    };
    let (plain, plain_stats) = common::scene::render(&gpu, &compiled, options(false), "plain");
    let (timed, stats) = common::scene::render(&gpu, &compiled, options(true), "timed");
    assert!(
        plain_stats.stage_ms.is_empty(),
        "{:?}",
        plain_stats.stage_ms
    );
    let labels: Vec<&str> = stats.stage_ms.iter().map(|(l, _)| l.as_str()).collect();
    assert_eq!(
        labels,
        [
            "rtc wf_count",
            "rtc wf_compact",
            "rtc wf_trace",
            "rtc wf_shade",
            "rtc wf_shadow",
            "rtc wf_finish"
        ]
    );
    for (label, ms) in &stats.stage_ms {
        assert!(ms.is_finite() && *ms > 0.0, "{label}: {ms} ms");
    }
    assert_eq!(stats.rounds, plain_stats.rounds);
    let off = differing(&plain, &timed, 0.0);
    assert!(off.is_empty(), "{} pixels differ", off.len());
}

/// A pass whose every path ends in a tile's first round (no secondary rays, no shadow stage, one
/// sample a pass: `shadows.rt` with its shadow rays traced or replayed in the shade stage) runs
/// one round a tile without the count and compact stages: the host lists the tile itself
/// (`wavefront::LIST_TILE`; the listed stages take the tile's slots in `tile_place`'s permuted
/// runs of 512), and the shade stage adds each sample to the image and starts the slot again, so
/// no finish stage runs. 80 x 56 in 64 x 48 tiles, a tile of six whole runs and three smaller
/// ones, two passes of one sample: every slot is listed once a pass, every ray is the
/// megakernel's and so is the image, bit for bit. With a shadow stage the paths end in the first
/// round too (the round runs the shadow stage and the shade stage's replay), but a step whose
/// queries depend on each other may take more, so the count and compact stages list the slots,
/// and find none at the round's end, and the finish stage accumulates.
#[test]
fn a_pass_whose_paths_end_in_one_round_lists_no_tile() {
    let Some(gpu) = gpu_or_skip("a_pass_whose_paths_end_in_one_round_lists_no_tile") else {
        return;
    };
    use rtc_compiler::kernel::ExecModel;
    use rtc_runtime::gpu::TileConfig;
    let file = scene("shadows").set("SIDE", "80u");
    // (shadow rays, compiled for a large render, the shade stage accumulates, a listing): with a
    // shadow stage the rounds list their paths; without, the host lists the tile, and the shade
    // stage of a large render's kernels accumulates the samples where a small one's leaves them
    // to the finish stage (and, with the record's first chunk known in a listed tile, counts the
    // camera ray the trace stage left to it).
    for (shadow_rays, large, accumulates, listing) in [
        (ShadowRays::Shade, true, true, false),
        (ShadowRays::Replay, true, true, false),
        (ShadowRays::Shade, false, false, false),
        (ShadowRays::Replay, false, false, false),
        (ShadowRays::Stage, true, false, true),
    ] {
        let dir = temp_dir("features", &format!("tile_list_{shadow_rays:?}_{large}"));
        let compiled = compile_with_stages_placing(&file, &dir, shadow_rays, large);
        assert_eq!(compiled.shade_accumulates(), accumulates, "{shadow_rays:?}");
        let options = |exec| RenderOptions {
            size: Some([80, 56]),
            samples: Some(2),
            tiles: Some(TileConfig {
                tile_width: 64,
                tile_height: 48,
                tiles_per_batch: 1,
            }),
            exec: Some(exec),
            stage_times: true,
            ..RenderOptions::default()
        };
        let what = format!("{shadow_rays:?}, large {large}");
        let (mega, mega_stats) =
            common::scene::render(&gpu, &compiled, options(ExecModel::Megakernel), &what);
        let (wave, stats) =
            common::scene::render(&gpu, &compiled, options(ExecModel::Wavefront), &what);
        let labels: Vec<&str> = stats.stage_ms.iter().map(|(l, _)| l.as_str()).collect();
        assert_eq!(
            labels.contains(&"rtc wf_count") && labels.contains(&"rtc wf_compact"),
            listing,
            "{what}: {labels:?}"
        );
        assert_eq!(
            labels.contains(&"rtc wf_finish"),
            !accumulates,
            "{what}: {labels:?}"
        );
        assert_eq!(stats.rounds, 2 * 4, "{what}: one round a tile and pass");
        assert_eq!(stats.slot_rounds, 2 * 80 * 56, "{what}");
        assert_eq!(stats.listed_slots, 2 * 80 * 56, "{what}");
        if shadow_rays != ShadowRays::Stage {
            assert_eq!(stats.rays_traced, mega_stats.rays_traced, "{what}: rays");
        }
        let off = differing(&mega, &wave, 0.0);
        assert!(off.is_empty(), "{what}: {} pixels differ", off.len());
    }
}

/// Pixels where two images differ by more than `tolerance` in some channel.
fn differing(a: &LinearImage, b: &LinearImage, tolerance: f32) -> Vec<(u32, u32)> {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    let mut out = Vec::new();
    for y in 0..a.height() {
        for x in 0..a.width() {
            let (p, q) = (px(a, x, y), px(b, x, y));
            if (0..3).any(|c| (p[c] - q[c]).abs() > tolerance) {
                out.push((x, y));
            }
        }
    }
    out
}

#[test]
fn the_wavefront_model_renders_what_the_megakernel_renders() {
    let Some(gpu) = gpu_or_skip("the_wavefront_model_renders_what_the_megakernel_renders") else {
        return;
    };
    // Every feature scene of this suite (any-hit cut-outs and shadows, nested media with a camera
    // inside, custom geometry walking its BVH), and shadow rays through fog, at 40 x 28 in 16 x 16
    // tiles. The two models run the same operations in the same order, so on lavapipe the images
    // are bit-identical; the tolerance (1e-5 absolute on values of order 1) leaves room for
    // another driver contracting differently in two kernels. The three ways of tracing the
    // wavefront model's shadow rays: in the shadow stage (replayed), in the shade stage where
    // they are made, and in the shade stage replaying the step.
    let scenes = [
        ("cut_out", scene("cut_out").set("SIDE", "40u")),
        ("shadows", scene("shadows").set("SIDE", "40u")),
        ("nested_media", scene("nested_media")),
        ("walker_builtin", scene("walker").scene("walker_builtin")),
        ("walker_custom", scene("walker").scene("walker_custom")),
        ("dependent_shadows", scene("dependent_shadows")),
        ("path_loop", scene("path_loop").scene("path_loop")),
        // Shadow rays through fog (`absorb`): transmittances recorded per query.
        (
            "fog_shadow_through",
            SceneFile::open("materials/fog_shadow.rt").scene("through"),
        ),
        (
            "fog_shadow_inside",
            SceneFile::open("materials/fog_shadow.rt").scene("inside"),
        ),
    ];
    for (name, file) in scenes {
        for shadow_rays in [ShadowRays::Stage, ShadowRays::Shade, ShadowRays::Replay] {
            let (mega, wave, _) = both_models_placing(&gpu, name, &file, [40, 28], shadow_rays);
            let off = differing(&mega, &wave, 1e-5);
            assert!(
                off.is_empty(),
                "{name} ({shadow_rays:?}): {} pixels differ between the models, first {:?}",
                off.len(),
                &off[..off.len().min(8)]
            );
        }
    }
}

/// The wavefront model's compaction: each round's listed stages run over the slots still running
/// and no others, and a tile's rounds end with its last path (the round lists the next round's
/// slots at its end). `listed.rt` at 32 x 32 in 16 x 16 tiles: the left tiles' paths are one ray
/// (the background), the right tiles' two (a mirror, then the background). A left tile takes one
/// round (its 256 paths), a right tile two (256, 256): 6 rounds, 1,536 slots over them, every
/// one listed. An implementation that listed idle slots (or lost running ones), or ran a round
/// that finds nothing, would count otherwise, or change the image.
#[test]
fn the_listed_stages_run_over_the_running_paths_only() {
    let Some(gpu) = gpu_or_skip("the_listed_stages_run_over_the_running_paths_only") else {
        return;
    };
    let (mega, wave, stats) = both_models(&gpu, "listed", &scene("listed"), [32, 32]);
    assert_eq!(stats.rounds, 6);
    assert_eq!(stats.slot_rounds, 2 * 256 + 4 * 256);
    assert_eq!(stats.listed_slots, 2 * 256 + 2 * 512);
    assert_eq!(stats.rays_traced, 1024 + 512);
    let off = differing(&mega, &wave, 0.0);
    assert!(off.is_empty(), "{} pixels differ", off.len());
    for y in 0..32 {
        for x in 0..32 {
            let want = if x < 16 {
                [0.0, 0.0, 1.0]
            } else {
                [0.0, 0.0, 0.5]
            };
            assert_eq!(px(&wave, x, y), want, "pixel ({x}, {y})");
        }
    }
}

/// The count and compact stages of a tile's later rounds list the running slots of the list the
/// round before made when it holds at most half the tile, else of the tile (two lists in turn,
/// `LIST_SELECTOR` and `list_source` in `stdlib/kernel/wavefront.rt`; the entries placed in
/// permuted runs, `list_place`). `listed.rt` at 32 x 32 in one tile: the first round lists all
/// 1,024 slots, the second the right half's 512 (from the tile, as the first list holds it
/// all), and the listing at its end reads that list (16 of each row of 32: an entry's place is no
/// slot's index) and finds none. `samples.rt`, three samples a pass, in one tile: the left half's
/// slots run three rounds, the mirror's six, the edge column's in between (jittered samples), so
/// the later rounds list from lists of about half the tile, in turn. A listing that read the
/// wrong list, a stale length or a wrong place would lose or repeat slots: the counts or the
/// image (the megakernel's, bit for bit) would differ (reading list 0 for list 1 leaves 199
/// pixels different).
#[test]
fn later_rounds_list_from_the_last_list() {
    let Some(gpu) = gpu_or_skip("later_rounds_list_from_the_last_list") else {
        return;
    };
    let (mega, wave, stats) = both_models_in_tiles(
        &gpu,
        "listed_one_tile",
        &scene("listed"),
        [32, 32],
        ShadowRays::Stage,
        [32, 32],
    );
    assert_eq!(stats.rounds, 2);
    assert_eq!(stats.slot_rounds, 2 * 1024);
    assert_eq!(stats.listed_slots, 1024 + 512);
    assert_eq!(stats.rays_traced, 1024 + 512);
    let off = differing(&mega, &wave, 0.0);
    assert!(off.is_empty(), "{} pixels differ", off.len());
    assert_eq!(px(&wave, 3, 7), [0.0, 0.0, 1.0]);
    assert_eq!(px(&wave, 29, 7), [0.0, 0.0, 0.5]);

    let (mega, wave, stats) = both_models_in_tiles(
        &gpu,
        "samples_one_tile",
        &scene("samples"),
        [32, 32],
        ShadowRays::Stage,
        [32, 32],
    );
    assert_eq!(stats.rounds, 6, "the mirror's slots: 3 samples of 2 rays");
    // Every slot runs its left-half rounds at least; the mirror's half (some 15 to 16 columns,
    // the edge's pixels part of the time) three more.
    assert!(
        (3 * 1024 + 3 * 15 * 32..=3 * 1024 + 3 * 17 * 32).contains(&stats.listed_slots),
        "listed {}",
        stats.listed_slots
    );
    let off = differing(&mega, &wave, 0.0);
    assert!(off.is_empty(), "{} pixels differ", off.len());
}

/// A camera of several samples a pass: with a camera of three (`samples.rt`: jittered rays, a
/// mirror's edge through a column of pixels) a slot is back at the camera after each sample but a
/// pass's last, and the trace stage of the next round makes its next camera ray (a slot at
/// `STATUS_CAMERA`). One pass of three samples, in 16 x 16 tiles: the
/// image is the megakernel's, bit for bit, and the jitter shows (most of the edge column's pixels
/// lie strictly between the background's blue and the mirror's half of it: a pixel's three
/// samples all fall on one side of the edge with probability about 1/4).
#[test]
fn a_camera_of_several_samples_a_pass_gets_them_all_in_later_rounds() {
    let Some(gpu) = gpu_or_skip("a_camera_of_several_samples_a_pass_gets_them_all_in_later_rounds")
    else {
        return;
    };
    let file = scene("samples");
    let dir = temp_dir("features", "samples");
    let compiled = compile_with_stages(&file, &dir);
    assert_eq!(compiled.samples_per_pass, 3);
    let (mega, wave, stats) = both_models(&gpu, "samples", &file, [32, 32]);
    assert_eq!((stats.samples, stats.passes), (3, 1));
    let off = differing(&mega, &wave, 0.0);
    assert!(off.is_empty(), "{} pixels differ", off.len());
    let edge: Vec<f32> = (0..32).map(|y| px(&wave, 16, y)[2]).collect();
    assert!(edge.iter().all(|&b| (0.5..=1.0).contains(&b)), "{edge:?}");
    let mixed = edge.iter().filter(|&&b| b > 0.5 && b < 1.0).count();
    assert!(
        mixed >= 8,
        "{mixed} of the edge column's pixels mix both: {edge:?}"
    );
}

/// The path loop (`KernelConfig::path_loop`: no frames, a throughput, Russian roulette by it)
/// against the back-tracking stack on the same box (`path_loop.rt`: diffuse walls, a glass and a
/// mirror ball, an area light and a visible lamp; in scene `path_stack` the walls' material is
/// not additive in `secondary`, which keeps the stack). The two estimators draw their random
/// numbers in another order, so the images differ by noise only: at 256 samples per pixel the
/// image means agree within 1.5 % per channel (the means' own noise is about 0.3 %), and no
/// sample is NaN or infinite (`render` asserts it).
#[test]
fn the_path_loop_estimates_what_the_stack_estimates() {
    let Some(gpu) = gpu_or_skip("the_path_loop_estimates_what_the_stack_estimates") else {
        return;
    };
    let mean = |name: &str, want_loop: bool| {
        let dir = temp_dir("features", name);
        let file = scene("path_loop").scene(name).set("SAMPLES", "256u");
        let compiled = file.compile(&dir);
        assert_eq!(compiled.linked.config.path_loop, want_loop, "{name}");
        let (img, _) = common::scene::render(&gpu, &compiled, RenderOptions::default(), name);
        let mut sum = [0.0f64; 3];
        for y in 0..img.height() {
            for x in 0..img.width() {
                for (c, v) in px(&img, x, y).into_iter().enumerate() {
                    sum[c] += f64::from(v);
                }
            }
        }
        sum.map(|s| s / f64::from(img.width() * img.height()))
    };
    let looped = mean("path_loop", true);
    let stacked = mean("path_stack", false);
    for c in 0..3 {
        let rel = (looped[c] - stacked[c]).abs() / stacked[c];
        assert!(
            rel <= 0.015,
            "channel {c}: path loop mean {}, stack mean {} (relative difference {rel:.4})",
            looped[c],
            stacked[c]
        );
    }
}

#[test]
fn a_shading_step_whose_queries_depend_on_answers_is_replayed_until_exact() {
    let Some(gpu) =
        gpu_or_skip("a_shading_step_whose_queries_depend_on_answers_is_replayed_until_exact")
    else {
        return;
    };
    // `dependent_shadows.rt`: the later queries' directions depend on the first answer, so a
    // pixel whose slanted way up is blocked records a query on the first run that the replay does
    // not make again; its colours (red where the way up is clear, blue 0.5 or 1 where it is
    // blocked) must come out as the megakernel's, pixel for pixel, and both branches must occur on
    // the floor (the slabs, green, do not count).
    // Both ways of replaying: the shadow stage, and the shade stage tracing the queries itself.
    let file = scene("dependent_shadows").set("SIDE", "24u");
    for shadow_rays in [ShadowRays::Stage, ShadowRays::Replay] {
        let (mega, wave, stats) =
            both_models_placing(&gpu, "dependent_shadows", &file, [SIDE, SIDE], shadow_rays);
        let off = differing(&mega, &wave, 1e-5);
        assert!(
            off.is_empty(),
            "{shadow_rays:?}: {} pixels differ: {:?}",
            off.len(),
            off
        );
        let mut branches = [0usize; 2];
        for y in 0..SIDE {
            for x in 0..SIDE {
                let p = px(&wave, x, y);
                if p == [0.0, 0.0, 1.0] || p == [0.0, 1.0, 0.0] {
                    continue; // the background, a slab
                }
                branches[usize::from(p[0] == 0.0)] += 1;
            }
        }
        assert!(
            branches[0] > 0 && branches[1] > 0,
            "{shadow_rays:?}: both branches must occur: {branches:?}"
        );
        assert!(
            stats.warnings.is_empty(),
            "{shadow_rays:?}: no query overflowed: {:?}",
            stats.warnings
        );
    }
}

#[test]
fn shadow_queries_beyond_what_a_step_records_are_warned_about() {
    let Some(gpu) = gpu_or_skip("shadow_queries_beyond_what_a_step_records_are_warned_about")
    else {
        return;
    };
    let limit = rtc_compiler::kernel::wavefront::SHADOW_QUERIES;
    // Both ways of replaying: the shadow stage, and the shade stage tracing the queries itself.
    for shadow_rays in [ShadowRays::Stage, ShadowRays::Replay] {
        // At the limit: no warning, and the image is the megakernel's.
        let file = scene("many_shadows").set("QUERIES", format!("{limit}u"));
        let (mega, wave, stats) =
            both_models_placing(&gpu, "many_shadows_at_limit", &file, [16, 16], shadow_rays);
        assert!(
            stats.warnings.is_empty(),
            "{shadow_rays:?}: {:?}",
            stats.warnings
        );
        assert!(differing(&mega, &wave, 1e-5).is_empty(), "{shadow_rays:?}");
        // Over it: every query past the limit is answered "unoccluded", counted and named in a
        // warning (the slab shadows some of the later directions, so the image may be brighter).
        let file = scene("many_shadows").set("QUERIES", format!("{}u", limit + 4));
        let (_, wave, stats) = both_models_placing(
            &gpu,
            "many_shadows_over_limit",
            &file,
            [16, 16],
            shadow_rays,
        );
        let warning = stats
            .warnings
            .iter()
            .find(|w| w.contains("answered \"unoccluded\""))
            .unwrap_or_else(|| {
                panic!("{shadow_rays:?}: no overflow warning: {:?}", stats.warnings)
            });
        // 4 extra queries for each floor pixel of each of the runs of its one shading step.
        assert!(warning.contains(&limit.to_string()), "{warning}");
        assert_eq!(wave.count_nonfinite(), 0);
    }
}

#[test]
fn a_material_edit_recompiles_only_the_shade_stage() {
    use rtc_compiler::kernel::{ExecModel, KernelOptions};
    let Some(gpu) = gpu_or_skip("a_material_edit_recompiles_only_the_shade_stage") else {
        return;
    };
    // The same scene twice, the second with one constant of its material's closest-hit code
    // changed: of the stage kernels only the shade stage holds closest-hit programs, so only it
    // is created again; the others come from the kernel set's memory cache (counted by this
    // `Gpu`'s pipeline-creation counter, exact while other tests run).
    let options = KernelOptions {
        exec: Some(ExecModel::Wavefront),
        ..KernelOptions::default()
    };
    let dir = temp_dir("features", "material_edit");
    let first = scene("dependent_shadows").compile_with(&dir, &options);
    let stages = first.stages.as_ref().map_or(0, Vec::len);
    assert!(stages >= 6, "{stages} stage kernels");
    let before = gpu.pipelines_created();
    let kernels = rtc_runtime::render::create_scene_kernels(
        &gpu,
        &first,
        ExecModel::Wavefront,
        false,
        Default::default(),
    )
    .expect("stage kernels");
    assert_eq!(kernels.render.len(), stages);
    assert_eq!(
        gpu.pipelines_created() - before,
        stages as u64,
        "a cold set compiles every stage"
    );
    let edited = scene("dependent_shadows")
        .set("TINT", "0.25")
        .compile_with(&dir, &options);
    let before = gpu.pipelines_created();
    let again = rtc_runtime::render::create_scene_kernels(
        &gpu,
        &edited,
        ExecModel::Wavefront,
        false,
        Default::default(),
    )
    .expect("stage kernels");
    assert_eq!(
        gpu.pipelines_created() - before,
        1,
        "only the shade stage holds the edited material"
    );
    let compiled: Vec<&str> = again
        .render
        .iter()
        .filter(|k| k.report().origin == rtc_runtime::gpu::KernelOrigin::Compiled)
        .map(|k| k.label())
        .collect();
    assert_eq!(compiled, ["rtc wf_shade"]);
}

#[test]
fn a_light_programs_dependent_queries_are_answered_as_if_traced_in_place() {
    let Some(gpu) =
        gpu_or_skip("a_light_programs_dependent_queries_are_answered_as_if_traced_in_place")
    else {
        return;
    };
    // `light_shadows.rt`, scene `branchy_light`: the light's later queries depend on its first
    // answer, and it and the material draw random numbers around them. The megakernel defers the
    // light program's queries to `sample_light` and runs it again until every answer is known;
    // the wavefront model replays the whole shading step. Both must give the same image, pixel
    // for pixel, with both branches present and no query left unanswered.
    let file = SceneFile::open("kernel_features/light_shadows.rt").scene("branchy_light");
    let (mega, wave, stats) = both_models(&gpu, "branchy_light", &file, [SIDE, SIDE]);
    let off = differing(&mega, &wave, 1e-5);
    assert!(off.is_empty(), "{} pixels differ: {:?}", off.len(), off);
    let mut branches = [0usize; 2];
    for y in 0..SIDE {
        for x in 0..SIDE {
            let p = px(&mega, x, y);
            if p == [0.0, 0.0, 1.0] || p == [0.0, 1.0, 0.0] {
                continue; // the background, a slab
            }
            // Red 1 where the way up is clear; at most 0.25 + 0.125 where it is blocked.
            branches[usize::from(p[0] < 0.5)] += 1;
        }
    }
    assert!(
        branches[0] > 0 && branches[1] > 0,
        "both branches must occur: {branches:?}"
    );
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    assert_eq!(mega.count_nonfinite(), 0);
}

#[test]
fn a_light_sample_past_the_queries_it_records_is_warned_about() {
    use rtc_compiler::kernel::ExecModel;
    let Some(gpu) = gpu_or_skip("a_light_sample_past_the_queries_it_records_is_warned_about")
    else {
        return;
    };
    let many = |queries: u32| {
        SceneFile::open("kernel_features/light_shadows.rt")
            .scene("many_light")
            .set("QUERIES", format!("{queries}u"))
    };
    // Within what a wavefront shading step records: both models give the same image.
    let steps = rtc_compiler::kernel::wavefront::SHADOW_QUERIES;
    let (mega, wave, stats) = both_models(&gpu, "many_light_step", &many(steps), [16, 16]);
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    assert!(differing(&mega, &wave, 1e-5).is_empty());
    // The megakernel answers `LIGHT_QUERIES` queries of one light sample exactly, and warns past
    // them, naming the limit.
    let limit = rtc_compiler::kernel::intrinsics::LIGHT_QUERIES;
    let megakernel = |name: &str, queries: u32| {
        let dir = temp_dir("features", name);
        let compiled = many(queries).compile(&dir);
        let options = RenderOptions {
            samples: Some(1),
            exec: Some(ExecModel::Megakernel),
            ..RenderOptions::default()
        };
        let (image, stats) = common::scene::render(&gpu, &compiled, options, name);
        assert_eq!(image.count_nonfinite(), 0, "{name}");
        stats
    };
    let at = megakernel("many_light_at_limit", limit);
    assert!(at.warnings.is_empty(), "{:?}", at.warnings);
    let over = megakernel("many_light_over_limit", limit + 4);
    let warning = over
        .warnings
        .iter()
        .find(|w| w.contains("answered \"unoccluded\""))
        .unwrap_or_else(|| panic!("no overflow warning: {:?}", over.warnings));
    assert!(
        warning.contains("light program") && warning.contains(&limit.to_string()),
        "{warning}"
    );
}

#[test]
fn an_unoccluded_light_sample_ignores_blockers_and_traces_no_ray() {
    use rtc_compiler::kernel::ExecModel;
    let Some(gpu) = gpu_or_skip("an_unoccluded_light_sample_ignores_blockers_and_traces_no_ray")
    else {
        return;
    };
    // `unoccluded.rt`: red is `sample_light`, 0 under the blocker (x < 0) and 1 elsewhere; green
    // is `sample_light_unoccluded`, 1 everywhere; blue is `sample_light_above` on the side the
    // light is on (red again) plus twice that on the other side (0). Every camera ray hits the
    // floor, whose shading traces one shadow ray for `sample_light` and one for the sample above
    // the lit side, none for the others: 3 rays a pixel. With one light type (the
    // light program traces in place) and two (the megakernel defers its queries), both models.
    const SIDE: u32 = 16;
    for scene_name in ["unoccluded_one", "unoccluded_two"] {
        let file = scene("unoccluded")
            .scene(scene_name)
            .set("SIDE", format!("{SIDE}u"));
        let dir = temp_dir("features", scene_name);
        let compiled = compile_with_stages(&file, &dir);
        for exec in [ExecModel::Megakernel, ExecModel::Wavefront] {
            let name = format!("{scene_name} ({})", exec.name());
            let options = RenderOptions {
                samples: Some(1),
                exec: Some(exec),
                ..RenderOptions::default()
            };
            let (img, stats) = common::scene::render(&gpu, &compiled, options, &name);
            for y in 0..SIDE {
                for x in 0..SIDE {
                    let wx = -2.8125 + 0.375 * f64::from(x);
                    let seen = if wx < 0.0 { 0.0 } else { 1.0 };
                    assert_eq!(
                        px(&img, x, y),
                        [seen, 1.0, seen],
                        "{name}: pixel ({x}, {y})"
                    );
                }
            }
            assert_eq!(
                stats.rays_traced,
                3 * u64::from(SIDE * SIDE),
                "{name}: an unoccluded sample, or one below the surface, traced a ray"
            );
        }
    }
}

/// `rand()` draws an Owen-scrambled Sobol sequence padded in pairs (`stdlib/kernel/support.rt`):
/// over a pixel's 16 samples, the points of each pair of dimensions form a (0, 4, 2)-net, so each
/// of three elementary intervals of area 1/16 (`sampler.rt`) holds exactly one of them and every
/// pixel's mean is exactly 1/16 in every channel, in the first pair and a later one, with both
/// execution models. Independent random numbers would put 0, 2 or more points in an interval in
/// about 62 % of the pixels. A pair that straddles two of the sequence's pairs (`SHIFT`) is still
/// stratified in its first coordinate (channel 0 exact: every dimension is), but its two
/// coordinates come from independently scrambled pairs: some pixels are off 1/16 in channels 1
/// and 2, and the means over the 256 pixels are within four standard errors (0.015) of 1/16.
#[test]
fn random_numbers_are_stratified_in_every_pair_of_dimensions() {
    use rtc_compiler::kernel::{ExecModel, KernelOptions};
    let Some(gpu) = gpu_or_skip("random_numbers_are_stratified_in_every_pair_of_dimensions") else {
        return;
    };
    let render_16 = |pair: u32, shift: u32, exec: ExecModel| {
        let name = format!("sampler_{pair}_{shift}_{}", exec.name());
        let dir = temp_dir("features", &name);
        let file = scene("sampler")
            .set("PAIR", format!("{pair}u"))
            .set("SHIFT", format!("{shift}u"));
        let compiled = file.compile_with(
            &dir,
            &KernelOptions {
                exec: Some(ExecModel::Wavefront),
                ..KernelOptions::default()
            },
        );
        let options = RenderOptions {
            samples: Some(16),
            exec: Some(exec),
            ..RenderOptions::default()
        };
        let (image, _) = common::scene::render(&gpu, &compiled, options, &name);
        assert_eq!((image.width(), image.height()), (16, 16));
        image
    };
    for exec in [ExecModel::Megakernel, ExecModel::Wavefront] {
        for pair in [0, 3] {
            let image = render_16(pair, 0, exec);
            for (i, p) in image.pixels().iter().enumerate() {
                assert_eq!(
                    [p[0], p[1], p[2]],
                    [0.0625; 3],
                    "pair {pair} ({}): pixel {i} is not stratified",
                    exec.name()
                );
            }
        }
    }
    let image = render_16(1, 1, ExecModel::Megakernel);
    let pixels = image.pixels();
    assert!(
        pixels.iter().all(|p| p[0] == 0.0625),
        "every dimension is stratified on its own"
    );
    for c in [1, 2] {
        let off = pixels.iter().filter(|p| p[c] != 0.0625).count();
        assert!(off > 0, "channel {c}: straddling pairs look stratified");
        let mean = pixels.iter().map(|p| f64::from(p[c])).sum::<f64>() / pixels.len() as f64;
        assert!(
            (mean - 0.0625).abs() < 0.015,
            "channel {c}: mean {mean} over the pixels, want 1/16 within 0.015"
        );
    }
}
