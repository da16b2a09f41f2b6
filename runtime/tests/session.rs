//! The long-lived renderer as a session (issue 17): accumulation that continues across calls,
//! field writes and moves that upload only what changed, and kernel replacements that keep every
//! asset and object-level BVH. Scenes: `scenes/session/`. Images are compared exactly (the same
//! passes draw the same random numbers and add in the same order) unless a tolerance is stated.

mod common;

use common::scene::{vec3f, SceneFile};
use common::{gpu_or_skip, temp_dir};
use glam::{Mat4, Vec3};
use rtc_compiler::kernel::CompiledScene;
use rtc_compiler::kernel::ExecModel;
use rtc_compiler::sema::hir::{ConstValue, Scalar};
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::{preview_size, FieldTarget, RenderOptions, Renderer};

const TRI_OBJ: &str = "v -0.4 0 0\nv 0.4 0 0\nv 0 0.9 0.1\nf 1 2 3\n";

/// The stage compiled in `dir` (with `tri.obj` written next to it the first time), constants
/// overridden.
fn stage(dir: &std::path::Path, set: &[(&str, [f64; 3])]) -> CompiledScene {
    let obj = dir.join("tri.obj");
    if !obj.exists() {
        std::fs::write(obj, TRI_OBJ).expect("write tri.obj");
    }
    let mut file = SceneFile::open("session/stage.rt");
    for (name, v) in set {
        file = file.set(name, vec3f(*v));
    }
    file.compile(dir)
}

fn vec3(v: [f32; 3]) -> ConstValue {
    ConstValue::Vector {
        len: 3,
        comps: [
            Scalar::F32(v[0]),
            Scalar::F32(v[1]),
            Scalar::F32(v[2]),
            Scalar::F32(0.0),
        ],
    }
}

fn fresh(gpu: &rtc_runtime::gpu::Gpu, compiled: &CompiledScene, samples: u32) -> LinearImage {
    let options = RenderOptions {
        samples: Some(samples),
        ..RenderOptions::default()
    };
    let mut r = Renderer::new(gpu, compiled, options).expect("renderer");
    r.render(&mut |_, _| {}).expect("render").image
}

fn assert_same(what: &str, a: &LinearImage, b: &LinearImage) {
    assert_eq!(
        (a.width(), a.height()),
        (b.width(), b.height()),
        "{what}: size"
    );
    let differ = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(x, y)| x != y)
        .count();
    assert_eq!(differ, 0, "{what}: {differ} pixels differ");
}

#[test]
fn four_single_passes_accumulate_to_the_four_pass_render() {
    let Some(gpu) = gpu_or_skip("four_single_passes_accumulate_to_the_four_pass_render") else {
        return;
    };
    let dir = temp_dir("session", "accumulate");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let whole = r.render(&mut |_, _| {}).expect("render");
    assert_eq!(whole.stats.samples, 4);
    r.reset_accumulation();
    for k in 1..=4 {
        let stats = r.accumulate(1, &mut |_, _| {}).expect("accumulate");
        assert_eq!(stats.samples, 1);
        assert_eq!(stats.accumulated_samples, k);
        assert_eq!(r.accumulated_samples(), k);
    }
    let image = r.image().expect("image");
    assert_same(
        "accumulate(1) x 4 against render at 4 spp",
        &image,
        &whole.image,
    );
    // One pass is not the 4-pass image: the passes draw different numbers.
    r.reset_accumulation();
    r.accumulate(1, &mut |_, _| {}).expect("accumulate");
    let one = r.image().expect("image");
    assert!(
        one.pixels() != whole.image.pixels(),
        "a thin lens and an area light make passes differ"
    );
}

/// A still render with the megakernel runs several passes a dispatch
/// (`rtc_runtime::render::passes_per_dispatch`); each pass is still added to `accum` as a dispatch
/// of its own adds it, so the image is the one of the passes accumulated one at a time, bit for
/// bit, the rays counted are the same, and `frame_index()` still numbers each sample's pass. Two
/// scenes: a path loop (its lanes start their next sample as soon as a path ends) and the stage
/// (the back-tracking `trace`).
#[test]
fn a_still_render_adds_several_passes_a_dispatch_as_single_passes_add_them() {
    let Some(gpu) =
        gpu_or_skip("a_still_render_adds_several_passes_a_dispatch_as_single_passes_add_them")
    else {
        return;
    };
    let dir = temp_dir("session", "passes");
    std::fs::write(dir.join("tri.obj"), TRI_OBJ).expect("write tri.obj");
    let megakernel = rtc_compiler::kernel::KernelOptions {
        exec: Some(ExecModel::Megakernel),
        ..Default::default()
    };
    for (file, path_loop, passes) in [
        ("session/passes.rt", true, 6),
        ("session/stage.rt", false, 4),
    ] {
        let compiled = SceneFile::open(file).compile_with(&dir, &megakernel);
        assert_eq!(compiled.exec, ExecModel::Megakernel, "{file}");
        assert_eq!(compiled.linked.config.path_loop, path_loop, "{file}");
        let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
        let whole = r.render(&mut |_, _| {}).expect("render");
        assert_eq!(whole.stats.passes, passes, "{file}");
        assert_eq!(
            whole.stats.passes_per_dispatch, passes,
            "{file}: one dispatch"
        );
        r.reset_accumulation();
        let mut rays = 0;
        for _ in 0..passes {
            let stats = r.accumulate(1, &mut |_, _| {}).expect("accumulate");
            assert_eq!(stats.passes_per_dispatch, 1);
            rays += stats.rays_traced;
        }
        assert_same(
            &format!("{file}: one dispatch of {passes} passes against {passes} of one"),
            &r.image().expect("image"),
            &whole.image,
        );
        assert_eq!(rays, whole.stats.rays_traced, "{file}: rays counted");
        if path_loop {
            // The panel in the middle shows 0.1 times the pass number: the mean of passes 0 to 5.
            let p = whole.image.pixels()[8 * 24 + 12];
            assert!(
                (p[0] - 0.25).abs() < 1e-6,
                "{file}: the panel's pixel is {p:?}, not the mean pass number 2.5 times 0.1"
            );
        }
    }
}

#[test]
fn a_camera_write_restarts_the_accumulation_and_moves_the_view() {
    let Some(gpu) = gpu_or_skip("a_camera_write_restarts_the_accumulation_and_moves_the_view")
    else {
        return;
    };
    let dir = temp_dir("session", "camera");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    r.accumulate(3, &mut |_, _| {}).expect("accumulate");
    assert_eq!(r.accumulated_samples(), 3);
    r.set_field(FieldTarget::Camera, "position", &vec3([1.0, 1.5, 3.5]))
        .expect("set the camera");
    assert_eq!(r.accumulated_samples(), 0, "a camera write restarts");
    let stats = r.accumulate(2, &mut |_, _| {}).expect("accumulate");
    assert_eq!(stats.accumulated_samples, 2);
    assert_eq!(
        stats.buffers_written,
        vec!["params"],
        "only the camera's words"
    );
    assert_eq!(stats.bytes_uploaded, 12, "one vec3f");
    let moved = stage(&dir, &[("CAMERA", [1.0, 1.5, 3.5])]);
    assert_same(
        "camera written in place against a scene compiled with it",
        &r.image().expect("image"),
        &fresh(&gpu, &moved, 2),
    );
}

#[test]
fn a_material_write_changes_one_object_and_uploads_only_its_words() {
    let Some(gpu) = gpu_or_skip("a_material_write_changes_one_object_and_uploads_only_its_words")
    else {
        return;
    };
    let dir = temp_dir("session", "material");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    r.render(&mut |_, _| {}).expect("render");
    // `left` and `right` share one instance (identical values): the first write gives `left` its
    // own copy, which moves the medium table and writes `params` whole once.
    r.set_field(FieldTarget::Material(1), "albedo", &vec3([0.2, 0.3, 0.9]))
        .expect("set albedo");
    let first = r.accumulate(4, &mut |_, _| {}).expect("accumulate");
    assert!(first.buffers_written.contains(&"params"));
    assert_same(
        "left's albedo written in place against a scene compiled with it",
        &r.image().expect("image"),
        &fresh(&gpu, &stage(&dir, &[("LEFT", [0.2, 0.3, 0.9])]), 4),
    );
    // Now the instance is its own: a second write uploads its three words and nothing else.
    r.set_field(FieldTarget::Material(1), "albedo", &vec3([0.9, 0.1, 0.1]))
        .expect("set albedo");
    let second = r.accumulate(4, &mut |_, _| {}).expect("accumulate");
    assert_eq!(second.buffers_written, vec!["params"]);
    assert_eq!(second.bytes_uploaded, 12, "one vec3f");
    assert_same(
        "a second write",
        &r.image().expect("image"),
        &fresh(&gpu, &stage(&dir, &[("LEFT", [0.9, 0.1, 0.1])]), 4),
    );
}

#[test]
fn bad_field_writes_are_errors_that_change_nothing() {
    let Some(gpu) = gpu_or_skip("bad_field_writes_are_errors_that_change_nothing") else {
        return;
    };
    let dir = temp_dir("session", "bad_fields");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let before = r.render(&mut |_, _| {}).expect("render").image;
    let cases: Vec<(FieldTarget, &str, ConstValue, &str)> = vec![
        (
            FieldTarget::Camera,
            "zoom",
            vec3([0.0; 3]),
            "has no field `zoom`",
        ),
        (
            FieldTarget::Camera,
            "fov",
            vec3([0.0; 3]),
            "`ThinLens.fov` is a `f32`",
        ),
        (
            FieldTarget::Light(3),
            "intensity",
            vec3([0.0; 3]),
            "no light 3",
        ),
        (
            FieldTarget::Material(9),
            "albedo",
            vec3([0.0; 3]),
            "no object 9",
        ),
    ];
    for (target, field, value, want) in cases {
        let err = r
            .set_field(target, field, &value)
            .expect_err("a bad write fails")
            .to_string();
        assert!(err.contains(want), "{target:?}.{field}: {err}");
    }
    let after = r.render(&mut |_, _| {}).expect("render").image;
    assert_same("after refused writes", &after, &before);
}

#[test]
fn moving_objects_rebuilds_only_the_scene_level() {
    let Some(gpu) = gpu_or_skip("moving_objects_rebuilds_only_the_scene_level") else {
        return;
    };
    let dir = temp_dir("session", "motion");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let first = r.accumulate(1, &mut |_, _| {}).expect("accumulate");
    let builds = first.blas_builds;
    assert_eq!(builds, 3, "tri.obj, the quad and the sphere");
    // The nodes' data (a uniform table's buffer is 64 KiB whatever its data).
    let nodes_bytes = std::mem::size_of_val(r.entities().nodes()) as u64;
    for frame in 0..8 {
        let angle = frame as f32 * 0.3;
        let spin = Mat4::from_translation(Vec3::new(0.0, 0.5, -0.5))
            * Mat4::from_rotation_y(angle)
            * Mat4::from_scale(Vec3::splat(0.5));
        assert_eq!(r.object_index("ball"), Some(3));
        r.set_transform(3, spin).expect("move the ball");
        r.set_transform(
            1,
            Mat4::from_translation(Vec3::new(-0.8, 0.1 * frame as f32, 0.0)),
        )
        .expect("move left");
        let s = r.accumulate(1, &mut |_, _| {}).expect("accumulate");
        assert_eq!(
            s.blas_builds, builds,
            "frame {frame}: no object-level BVH rebuilt"
        );
        assert_eq!(s.accumulated_samples, 1, "a move restarts the accumulation");
        for name in &s.buffers_written {
            assert!(
                ["nodes", "instances"].contains(name),
                "frame {frame}: {name} uploaded"
            );
        }
        assert!(
            s.bytes_uploaded < nodes_bytes / 2,
            "frame {frame}: {} bytes uploaded, the nodes are {nodes_bytes}",
            s.bytes_uploaded
        );
    }
    assert_eq!(r.store().counters().blas_builds, builds);
}

/// A renderer that flattens its static objects (`RenderOptions::flatten`, what `rtc render` does)
/// renders what one without flattening does, up to the rounding of the baked vertices; moving a
/// flattened object drops the flattening without building a BVH, and from then on its frames are
/// bit for bit those of the renderer that never flattened.
#[test]
fn a_flattened_renderer_matches_a_plain_one_and_a_move_undoes_the_flattening() {
    let Some(gpu) =
        gpu_or_skip("a_flattened_renderer_matches_a_plain_one_and_a_move_undoes_the_flattening")
    else {
        return;
    };
    let dir = temp_dir("session", "flatten");
    let compiled = stage(&dir, &[]);
    let flat_options = RenderOptions {
        flatten: true,
        ..RenderOptions::default()
    };
    let mut flat = Renderer::new(&gpu, &compiled, flat_options).expect("renderer");
    let mut plain = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let a = flat.render(&mut |_, _| {}).expect("render");
    let b = plain.render(&mut |_, _| {}).expect("render");
    assert_eq!(
        a.stats.flattened,
        (4, 1),
        "the floor, both triangles and the ball"
    );
    assert_eq!(b.stats.flattened, (0, 0));
    // Up to the rounding of the baked vertices and normals: every channel within 1e-3 of the
    // plain render's (relative to the image's largest value), but for at most 2 pixels (a
    // shadow ray that grazes an edge may flip).
    let peak = b
        .image
        .pixels()
        .iter()
        .flat_map(|p| p[..3].iter())
        .fold(0f32, |m, &v| m.max(v));
    let off = a
        .image
        .pixels()
        .iter()
        .zip(b.image.pixels())
        .filter(|(x, y)| (0..3).any(|c| (x[c] - y[c]).abs() > 1e-3 * peak))
        .count();
    assert!(
        off <= 2,
        "{off} pixels differ by more than 1e-3 of the peak {peak}"
    );
    let builds = a.stats.blas_builds;

    let spin = Mat4::from_translation(Vec3::new(0.0, 0.5, -0.5))
        * Mat4::from_rotation_y(0.7)
        * Mat4::from_scale(Vec3::splat(0.5));
    for r in [&mut flat, &mut plain] {
        r.set_transform(3, spin).expect("move the ball");
    }
    let a = flat.accumulate(1, &mut |_, _| {}).expect("accumulate");
    let b = plain.accumulate(1, &mut |_, _| {}).expect("accumulate");
    assert_eq!(
        a.flattened,
        (0, 0),
        "moving a flattened object drops the flattening"
    );
    assert_eq!(a.blas_builds, builds, "and builds no BVH");
    let a = flat.render(&mut |_, _| {}).expect("render");
    let b2 = plain.render(&mut |_, _| {}).expect("render");
    assert_eq!(b.accumulated_samples, 1);
    assert_same("after the move", &a.image, &b2.image);
}

#[test]
fn replacing_the_kernel_reads_no_file_and_builds_no_blas() {
    let Some(gpu) = gpu_or_skip("replacing_the_kernel_reads_no_file_and_builds_no_blas") else {
        return;
    };
    let dir = temp_dir("session", "replace");
    let compiled = stage(&dir, &[]);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let first = r.render(&mut |_, _| {}).expect("render").stats;
    assert_eq!(first.files_read, 1, "tri.obj");
    let edited = stage(&dir, &[("RIGHT", [0.1, 0.2, 0.9])]);
    r.replace_kernel(&edited).expect("replace");
    let after = r.render(&mut |_, _| {}).expect("render");
    assert_eq!(after.stats.files_read, 1, "no mesh read again");
    assert_eq!(
        after.stats.blas_builds, first.blas_builds,
        "no BLAS built again"
    );
    for name in ["triangles", "attributes", "nodes"] {
        assert!(
            !after.stats.buffers_written.contains(&name),
            "{name} was uploaded again: {:?}",
            after.stats.buffers_written
        );
    }
    assert_same(
        "after a kernel replacement against a fresh renderer",
        &after.image,
        &fresh(&gpu, &edited, 4),
    );
    // A file saved again with the same content is hashed, not loaded: nothing is rebuilt.
    std::thread::sleep(std::time::Duration::from_millis(20));
    std::fs::write(dir.join("tri.obj"), TRI_OBJ).expect("save again");
    r.replace_kernel(&edited).expect("replace");
    let same = r.render(&mut |_, _| {}).expect("render").stats;
    assert_eq!(same.files_read, 1, "same content: not loaded again");
    assert_eq!(same.blas_builds, first.blas_builds, "same content: no BLAS");
    // A changed file is loaded again, and only its BLAS is built.
    std::fs::write(dir.join("tri.obj"), format!("{TRI_OBJ}# edited\n")).expect("edit");
    r.replace_kernel(&edited).expect("replace");
    let third = r.render(&mut |_, _| {}).expect("render").stats;
    assert_eq!(third.files_read, 2, "the edited tri.obj");
    assert_eq!(third.blas_builds, first.blas_builds + 1, "its BLAS only");
}

#[test]
fn a_kernel_replacement_of_a_custom_geometry_scene_runs_the_bounds_kernel_again() {
    let Some(gpu) =
        gpu_or_skip("a_kernel_replacement_of_a_custom_geometry_scene_runs_the_bounds_kernel_again")
    else {
        return;
    };
    let dir = temp_dir("session", "custom");
    let ball = |albedo: [f64; 3]| {
        SceneFile::open("render/lit_ball.rt")
            .set("SIZE", "17u")
            .set("ALBEDO", vec3f(albedo))
            .compile(&dir)
    };
    let mut r =
        Renderer::new(&gpu, &ball([0.5, 0.25, 1.0]), RenderOptions::default()).expect("renderer");
    r.render(&mut |_, _| {}).expect("render");
    let edited = ball([1.0, 0.5, 0.0]);
    r.replace_kernel(&edited).expect("replace");
    let after = r.render(&mut |_, _| {}).expect("render").image;
    assert_same(
        "a custom-geometry scene after a kernel replacement",
        &after,
        &fresh(&gpu, &edited, 1),
    );
    // A light's field written in place equals the scene compiled with it.
    r.set_field(
        FieldTarget::Light(0),
        "intensity",
        &ConstValue::Scalar(Scalar::F32(9.0)),
    )
    .expect("set intensity");
    r.render(&mut |_, _| {}).expect("render");
    let brighter = SceneFile::open("render/lit_ball.rt")
        .set("SIZE", "17u")
        .set("ALBEDO", vec3f([1.0, 0.5, 0.0]))
        .set("INTENSITY", "9.0")
        .compile(&dir);
    assert_same(
        "a light's intensity written in place",
        &r.image().expect("image"),
        &fresh(&gpu, &brighter, 1),
    );
    // A move of the ball: the scene level only.
    r.set_transform(
        0,
        Mat4::from_translation(Vec3::new(0.3, 0.5, 0.0)) * Mat4::from_scale(Vec3::splat(2.0)),
    )
    .expect("move");
    let moved = r.render(&mut |_, _| {}).expect("render");
    assert!(moved.image.pixels() != after.pixels(), "the ball moved");
}

#[test]
fn the_wavefront_model_accumulates_and_takes_edits_like_the_megakernel() {
    let Some(gpu) =
        gpu_or_skip("the_wavefront_model_accumulates_and_takes_edits_like_the_megakernel")
    else {
        return;
    };
    let dir = temp_dir("session", "wavefront");
    std::fs::write(dir.join("tri.obj"), TRI_OBJ).expect("write tri.obj");
    let wavefront = rtc_compiler::kernel::KernelOptions {
        exec: Some(rtc_compiler::kernel::ExecModel::Wavefront),
        ..Default::default()
    };
    let compiled = SceneFile::open("session/stage.rt").compile_with(&dir, &wavefront);
    assert_eq!(compiled.exec, rtc_compiler::kernel::ExecModel::Wavefront);
    let mut r = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let whole = r.render(&mut |_, _| {}).expect("render");
    r.reset_accumulation();
    for _ in 0..4 {
        r.accumulate(1, &mut |_, _| {}).expect("accumulate");
    }
    assert_same(
        "wavefront: accumulate(1) x 4 against render at 4 spp",
        &r.image().expect("image"),
        &whole.image,
    );
    assert_same(
        "wavefront against the megakernel",
        &whole.image,
        &fresh(&gpu, &stage(&dir, &[]), 4),
    );
    r.set_field(FieldTarget::Camera, "position", &vec3([1.0, 1.5, 3.5]))
        .expect("set the camera");
    r.accumulate(2, &mut |_, _| {}).expect("accumulate");
    assert_same(
        "wavefront: camera written in place",
        &r.image().expect("image"),
        &fresh(&gpu, &stage(&dir, &[("CAMERA", [1.0, 1.5, 3.5])]), 2),
    );
}

#[test]
fn a_preview_is_the_first_pass_at_a_smaller_size_and_restarts_the_accumulation() {
    let Some(gpu) =
        gpu_or_skip("a_preview_is_the_first_pass_at_a_smaller_size_and_restarts_the_accumulation")
    else {
        return;
    };
    let dir = temp_dir("session", "preview");
    stage(&dir, &[]);
    for exec in [ExecModel::Megakernel, ExecModel::Wavefront] {
        let kernel = rtc_compiler::kernel::KernelOptions {
            exec: Some(exec),
            ..Default::default()
        };
        let compiled = SceneFile::open("session/stage.rt").compile_with(&dir, &kernel);
        assert_eq!(compiled.exec, exec);
        let options = RenderOptions::default();
        let mut r = Renderer::new(&gpu, &compiled, options.clone()).expect("renderer");
        assert_eq!(r.size(), [24, 16]);
        r.accumulate(2, &mut |_, _| {}).expect("accumulate");
        // 24 x 16 at 1/2 and at 1/5 (rounded up: 5 x 4).
        for (factor, size) in [(2, [12, 8]), (5, [5, 4])] {
            assert_eq!(preview_size(r.size(), factor), size);
            let preview = r.preview(factor).expect("preview");
            assert_eq!(
                r.accumulated_samples(),
                0,
                "a preview ends the accumulation"
            );
            assert_eq!([preview.stats.width, preview.stats.height], size);
            let mut small = Renderer::new(
                &gpu,
                &compiled,
                RenderOptions {
                    size: Some(size),
                    ..options.clone()
                },
            )
            .expect("renderer at the preview's size");
            small.accumulate(1, &mut |_, _| {}).expect("accumulate");
            assert_same(
                &format!("{exec:?} preview at 1/{factor} against one pass at {size:?}"),
                &preview.image,
                &small.image().expect("image"),
            );
        }
        // The next pass starts afresh at the whole size: the first pass of a new renderer.
        let stats = r.accumulate(1, &mut |_, _| {}).expect("accumulate");
        assert_eq!(stats.accumulated_samples, 1);
        let mut whole = Renderer::new(&gpu, &compiled, options).expect("renderer");
        whole.accumulate(1, &mut |_, _| {}).expect("accumulate");
        assert_same(
            &format!("{exec:?} the pass after a preview against a first pass"),
            &r.image().expect("image"),
            &whole.image().expect("image"),
        );
    }
}
