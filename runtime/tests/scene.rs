//! GPU tests of the scene's GPU stage and of the renderer's plumbing, on whatever adapter exists
//! (lavapipe on CI). Scenes are files of `scenes/scene/`, checked and linked by the compiler.
//!
//! - buffers hold exactly the entities' bytes (read back and compared);
//! - moving an object re-uploads `nodes` and `instances` only (per-binding outcomes and bytes);
//! - data above a (faked) device limit is the buffer set's typed error, naming the binding;
//! - the renderer, driven by small hand-written kernels that follow the ABI (so this runs before the
//!   compiler emits real ones): tiles and passes, `TileParams.frame` = pass index, accumulation
//!   averaging, counters, the bounds kernel feeding the scene-level BVH, progress over all passes.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::gpu_or_skip;
use common::scene::SceneFile;
use glam::{Mat4, Vec3};
use rtc_bvh::quantized::QuantizedBvh;
use rtc_compiler::abi::{self, StructDesc};
use rtc_compiler::driver::{check_text, Checked, Options};
use rtc_compiler::kernel::CompiledScene;
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions, Linked};
use rtc_compiler::sema::hir::Program;
use rtc_runtime::gpu::{read_buffer, BufferError, BufferLimits, Gpu, TileConfig, UploadOutcome};
use rtc_runtime::render::{RenderError, RenderOptions, Renderer};
use rtc_runtime::scene::{Entities, EntityOptions, GpuScene, SceneError};

/// Checks and links `file` (its text as is: it imports only the standard library).
fn checked(file: &SceneFile) -> (Checked, Linked) {
    let name = file.path().display().to_string();
    let checked = check_text(&name, file.text(), &Options::default());
    assert!(
        !checked.has_errors(),
        "{}",
        rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false)
    );
    let program = checked.program.as_ref().expect("program");
    let scene = program.select_scene(file.scene_name()).expect("the scene");
    let linked = link(
        program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .expect("links");
    (checked, linked)
}

fn entities(program: &Program, linked: &Linked) -> Entities {
    Entities::build(
        program,
        &program.scenes[linked.scene],
        linked,
        &EntityOptions::default(),
    )
    .expect("entities")
}

/// A scene file of `scenes/scene/`.
fn scene_file(name: &str) -> SceneFile {
    SceneFile::open(&format!("scene/{name}.rt"))
}

fn all_bindings() -> Vec<&'static abi::BindingDesc> {
    abi::BINDINGS.iter().collect()
}

fn read_words(gpu: &Gpu, scene: &GpuScene, name: &str, bytes: usize) -> Vec<u8> {
    let b = abi::binding(name).expect("binding");
    let buffer = scene.buffers().buffer(b.binding).expect("buffer");
    read_buffer(gpu, buffer, bytes as u64).expect("read back")
}

#[test]
fn buffers_hold_the_entities_and_moves_reupload_only_nodes_and_instances() {
    let Some(gpu) = gpu_or_skip("moves_reupload_only_nodes_and_instances") else {
        return;
    };
    let (c, l) = checked(&scene_file("rows").scene("row"));
    let program = c.program.as_ref().expect("program");
    let mut e = entities(program, &l);
    let mut scene = GpuScene::new(&gpu, &all_bindings());
    // The scene-level BVH (the last nodes) has one object per leaf: the kernel tests a leaf's
    // object `a` without a loop.
    let tlas = QuantizedBvh::from_records(&e.nodes()[e.tlas_root() as usize..]).unwrap();
    let leaves: Vec<u32> = tlas.leaves().iter().map(|&(_, _, count)| count).collect();
    assert_eq!(leaves, vec![1; 8]);

    let frame = e.frame_uniforms(1, 4);
    let first = scene.upload(&gpu, &mut e, &frame, 64 * 64).expect("upload");
    for (name, outcome) in &first.outcomes {
        assert_eq!(*outcome, UploadOutcome::Reallocated, "{name} is new");
    }
    // Byte-exact contents.
    let check = |scene: &GpuScene, e: &Entities| {
        let nodes: &[u8] = bytemuck::cast_slice(e.nodes());
        assert_eq!(read_words(&gpu, scene, "nodes", nodes.len()), nodes);
        let inst: &[u8] = bytemuck::cast_slice(e.instances());
        assert_eq!(read_words(&gpu, scene, "instances", inst.len()), inst);
        let tris: &[u8] = bytemuck::cast_slice(e.triangles());
        assert_eq!(read_words(&gpu, scene, "triangles", tris.len()), tris);
        let attrs: &[u8] = bytemuck::cast_slice(e.attributes());
        assert_eq!(read_words(&gpu, scene, "attributes", attrs.len()), attrs);
        let params: &[u8] = bytemuck::cast_slice(e.params());
        assert_eq!(read_words(&gpu, scene, "params", params.len()), params);
    };
    check(&scene, &e);

    let again = scene.upload(&gpu, &mut e, &frame, 64 * 64).expect("upload");
    assert!(
        again.written().is_empty(),
        "nothing changed: {:?}",
        again.written()
    );
    assert_eq!(again.stats.bytes_uploaded, 0);

    let before = e.stats().blas_builds;
    e.set_transform(3, Mat4::from_translation(Vec3::new(0.0, 7.0, 0.0)))
        .expect("move");
    e.refresh().expect("TLAS");
    assert_eq!(e.stats().blas_builds, before);
    let frame = e.frame_uniforms(1, 4);
    let moved = scene.upload(&gpu, &mut e, &frame, 64 * 64).expect("upload");
    assert_eq!(moved.written(), ["nodes", "instances"]);
    for name in ["triangles", "attributes", "params", "texels", "frame"] {
        assert_eq!(
            moved.outcome(name),
            Some(UploadOutcome::Unchanged),
            "{name}"
        );
    }
    let expected = (std::mem::size_of_val(e.nodes()) + std::mem::size_of_val(e.instances()))
        .next_multiple_of(4) as u64;
    assert!(moved.stats.bytes_uploaded <= expected + 8);
    assert_eq!(moved.stats.buffers_uploaded, 2);
    check(&scene, &e);
    assert!(gpu.take_uncaptured_errors().is_empty());
}

#[test]
fn data_above_a_binding_limit_is_a_typed_error_naming_it() {
    let Some(gpu) = gpu_or_skip("data_above_a_binding_limit") else {
        return;
    };
    let (c, l) = checked(&scene_file("rows").scene("pair"));
    let program = c.program.as_ref().expect("program");
    let mut e = entities(program, &l);
    let triangles = std::mem::size_of_val(e.triangles()) as u64;
    let nodes = std::mem::size_of_val(e.nodes()) as u64;
    // Room for everything but the triangles.
    let limit = nodes.max(4096).next_multiple_of(256);
    assert!(
        triangles > limit,
        "the test needs triangles ({triangles}) above {limit}"
    );
    let mut scene = GpuScene::new(&gpu, &all_bindings()).with_limits(BufferLimits {
        max_storage_buffer_binding_size: limit,
        max_uniform_buffer_binding_size: 1 << 16,
        max_buffer_size: 1 << 30,
    });
    let frame = e.frame_uniforms(1, 1);
    let err = scene
        .upload(&gpu, &mut e, &frame, 16)
        .expect_err("too large");
    // The binding holds meshes, so the error also names the largest of them.
    match &err {
        SceneError::BindingTooLarge {
            source:
                BufferError::TooLarge {
                    name,
                    limit: l,
                    size,
                    ..
                },
            part,
        } => {
            assert_eq!(name, "triangles");
            assert_eq!((*l, *size), (limit, triangles));
            assert!(part.contains("sphere_mesh(2)"), "{part}");
        }
        other => panic!("unexpected error {other}"),
    }
    let text = err.to_string();
    assert!(
        text.contains("`triangles`")
            && text.contains(&limit.to_string())
            && text.contains("the mesh `sphere_mesh(2)`"),
        "{text}"
    );
}

/// WGSL for an ABI struct, generated from the table (no layout written twice).
fn wgsl_struct(s: &StructDesc) -> String {
    let fields: Vec<String> = s
        .fields
        .iter()
        .map(|f| format!("    {}: {},", f.name, f.ty.name()))
        .collect();
    format!("struct {} {{\n{}\n}}\n", s.name, fields.join("\n"))
}

/// A stand-in render kernel: every sample of pass `k` adds `background + k` (the background colour
/// read from `params` through `frame`), one counter tick per pass from pixel (0, 0), and the
/// instance count in alpha's place of nothing (written to `.w` of pixel (1, 0) as a sample count).
fn render_wgsl() -> String {
    format!(
        "{}{}
@group(0) @binding(0) var<uniform> frame: FrameUniforms;
@group(0) @binding(1) var<uniform> tile: TileParams;
@group(0) @binding(6) var<storage, read> params: array<u32>;
@group(0) @binding(8) var<storage, read_write> accum: array<vec4<f32>>;
@group(0) @binding(9) var<storage, read_write> counters: array<atomic<u32>>;

@compute @workgroup_size(8, 8)
fn render(@builtin(global_invocation_id) gid: vec3<u32>) {{
    if any(gid.xy >= tile.extent) {{ return; }}
    let p = tile.origin + gid.xy;
    let i = p.y * tile.image_size.x + p.x;
    let o = frame.background_offset;
    let bg = vec3<f32>(bitcast<f32>(params[o]), bitcast<f32>(params[o + 1u]), bitcast<f32>(params[o + 2u]));
    let n = f32(frame.samples_per_pass);
    for (var k = 0u; k < frame.passes_per_dispatch; k++) {{
        accum[i] += vec4<f32>(bg * n + vec3<f32>(f32(tile.frame + k)), n);
        if i == 0u {{ atomicAdd(&counters[0], 1u); }}
    }}
}}
",
        wgsl_struct(&abi::FRAME),
        wgsl_struct(&abi::TILE)
    )
}

/// A stand-in bounds kernel: a custom geometry's box is `±radius` (its first parameter word).
fn bounds_wgsl() -> String {
    format!(
        "{}{}
@group(0) @binding(0) var<uniform> frame: FrameUniforms;
@group(0) @binding(3) var<storage, read> instances: array<GpuInstance>;
@group(0) @binding(6) var<storage, read> params: array<u32>;
@group(0) @binding(8) var<storage, read_write> accum: array<vec4<f32>>;

@compute @workgroup_size(64)
fn bounds(@builtin(global_invocation_id) gid: vec3<u32>) {{
    let i = gid.x;
    if i >= frame.instance_count {{ return; }}
    let inst = instances[i];
    if inst.geometry_type == 0xffffffffu {{ return; }}
    let r = bitcast<f32>(params[inst.geometry_offset]);
    accum[2u * i] = vec4<f32>(-r, -r, -r, 0.0);
    accum[2u * i + 1u] = vec4<f32>(r, r, r, 0.0);
}}
",
        wgsl_struct(&abi::FRAME),
        wgsl_struct(&abi::INSTANCE)
    )
}

/// A `CompiledScene` around hand-written kernels (what `compile_scene` returns, minus the
/// compiler's kernels).
fn stand_in(file: &SceneFile, samples_per_pass: u32) -> CompiledScene {
    let (checked, linked) = checked(file);
    let parse = |src: &str| naga::front::wgsl::parse_str(src).expect("stand-in kernel parses");
    let render = parse(&render_wgsl());
    let bounds = linked
        .config
        .has_custom_geometry
        .then(|| parse(&bounds_wgsl()));
    let names = ["frame", "tile", "params", "accum", "counters"];
    CompiledScene {
        scene: linked.scene,
        checked,
        linked,
        render,
        bounds,
        bindings: names
            .iter()
            .map(|n| abi::binding(n).expect("ABI binding"))
            .collect(),
        samples_per_pass,
        stages: None,
        path_words: 0,
        exec: rtc_compiler::kernel::ExecModel::Megakernel,
        render_weight: 0,
        timings: Vec::new(),
    }
}

#[test]
fn renderer_runs_passes_of_tiles_and_averages() {
    let Some(gpu) = gpu_or_skip("renderer_runs_passes_of_tiles_and_averages") else {
        return;
    };
    let compiled = stand_in(&scene_file("ball"), 2);
    let tiles = TileConfig {
        tile_width: 16,
        tile_height: 16,
        tiles_per_batch: 2,
    };
    let mut renderer = Renderer::new(
        &gpu,
        &compiled,
        RenderOptions {
            tiles: Some(tiles),
            ..RenderOptions::default()
        },
    )
    .expect("renderer");

    // The bounds kernel ran: the ball's box (radius 2 at x = 10) bounds the scene-level BVH, and
    // the ball with an inverted box was left out.
    let e = renderer.entities();
    assert_eq!(e.instances().len(), 2);
    let root = e.tlas_bounds();
    assert_eq!((root.min.x, root.max.x), (-1.0, 12.0));
    assert_eq!((root.min.y, root.max.y), (-2.0, 2.0));

    // 7 samples at 2 per pass: 4 passes of 3 × 2 tiles.
    assert_eq!(renderer.total_tiles(), 4 * 6);
    let mut seen = Vec::new();
    let result = renderer
        .render(&mut |done, total| seen.push((done, total)))
        .expect("render");
    let s = &result.stats;
    assert_eq!((s.passes, s.samples, s.samples_per_pass), (4, 8, 2));
    // A still render runs the four passes in one dispatch of each tile.
    assert_eq!(s.passes_per_dispatch, 4);
    assert_eq!(s.tiles, 6);
    assert_eq!(s.nonfinite_samples, 4, "one counter tick per pass");
    assert_eq!(s.primary_rays, 37 * 23 * 8);
    assert_eq!((s.objects, s.instances), (3, 2));
    assert!(s.rays_per_second > 0.0);
    assert!(s.buffers_written.contains(&"params"));
    assert_eq!(seen.first(), Some(&(0, 24)));
    assert_eq!(seen.last(), Some(&(24, 24)));
    assert!(seen.windows(2).all(|w| w[0].0 <= w[1].0), "{seen:?}");

    // Mean over passes k = 0..4 of (bg * 2 + k) / 2 per sample: bg + 0.75.
    let img = &result.image;
    assert_eq!((img.width(), img.height()), (37, 23));
    for px in img.pixels() {
        assert_eq!(*px, [1.0, 1.25, 1.5, 1.0]);
    }

    // A second render starts from zero and uploads nothing new.
    let again = renderer.render(&mut |_, _| {}).expect("render again");
    assert_eq!(again.image, result.image);
    assert!(
        again.stats.buffers_written.is_empty(),
        "{:?}",
        again.stats.buffers_written
    );
    assert_eq!(again.stats.bvh_build_ms, 0.0);

    // Moving the floor rebuilds the TLAS only; the frame's samples override takes effect.
    renderer
        .set_transform(1, Mat4::from_translation(Vec3::new(0.0, -5.0, 0.0)))
        .expect("move");
    let moved = renderer.render(&mut |_, _| {}).expect("render moved");
    assert_eq!(moved.stats.blas_builds, 1);
    assert_eq!(
        moved.stats.tlas_builds, 2,
        "after the bounds, after the move"
    );
    assert_eq!(renderer.entities().tlas_bounds().min.y, -5.0);
    assert!(gpu.take_uncaptured_errors().is_empty());
}

#[test]
fn renderer_errors_are_typed() {
    let Some(gpu) = gpu_or_skip("renderer_errors_are_typed") else {
        return;
    };
    let file = scene_file("empty");
    let compiled = stand_in(&file, 1);
    let zero = RenderOptions {
        size: Some([0, 5]),
        ..RenderOptions::default()
    };
    assert!(matches!(
        Renderer::new(&gpu, &compiled, zero),
        Err(RenderError::BadSize {
            width: 0,
            height: 5
        })
    ));
    let none = RenderOptions {
        samples: Some(0),
        ..RenderOptions::default()
    };
    assert!(matches!(
        Renderer::new(&gpu, &compiled, none),
        Err(RenderError::NoSamples)
    ));
    // A kernel without the tile uniform cannot be dispatched in tiles.
    let mut no_tile = stand_in(&file, 1);
    no_tile.bindings.retain(|b| b.name != "tile");
    assert!(matches!(
        Renderer::new(&gpu, &no_tile, RenderOptions::default()),
        Err(RenderError::NoTileBinding)
    ));
    // A binding list that lacks one the kernel uses is the pipeline's typed error.
    let mut missing = stand_in(&file, 1);
    missing.bindings.retain(|b| b.name != "params");
    assert!(matches!(
        Renderer::new(&gpu, &missing, RenderOptions::default()),
        Err(RenderError::Pipeline(_))
    ));
    // The size override is used, and an empty scene renders the background only.
    let small = RenderOptions {
        size: Some([3, 2]),
        samples: Some(1),
        ..RenderOptions::default()
    };
    let mut r = Renderer::new(&gpu, &compiled, small).expect("renderer");
    let out = r.render(&mut |_, _| {}).expect("render");
    assert_eq!((out.image.width(), out.image.height()), (3, 2));
    assert_eq!(out.stats.instances, 0);
}
