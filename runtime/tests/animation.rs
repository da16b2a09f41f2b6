//! Scene animation through one renderer (issue 17, spec/animation.md): applying each frame's state
//! with `rtc_runtime::animation` moves objects without building a BLAS (the renderer's counter),
//! every frame differs from the one before, and a frame is the same image whether the renderer
//! reached it after other frames or rendered it first, which is what lets `rtc render --shard`
//! give byte-identical frames. Scene: `scenes/animation/turntable.rt`.

mod common;

use common::scene::SceneFile;
use common::{gpu_or_skip, temp_dir};
use rtc_runtime::animation::{apply, evaluate, frame_time};
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::{RenderOptions, Renderer};

fn bits(image: &LinearImage) -> Vec<u32> {
    image
        .pixels()
        .iter()
        .flat_map(|p| p.iter().map(|c| c.to_bits()))
        .collect()
}

#[test]
fn an_animation_builds_no_blas_and_frames_do_not_depend_on_the_ones_before() {
    let Some(gpu) = gpu_or_skip("an_animation_builds_no_blas") else {
        return;
    };
    let dir = temp_dir("animation", "turntable");
    let compiled = SceneFile::open("animation/turntable.rt").compile(&dir);
    let program = compiled.checked.program.as_ref().expect("program");
    let desc = &program.scenes[compiled.scene];
    assert_eq!(
        desc.settings.frames, 9,
        "1 s at 8 fps, the last key's frame included"
    );

    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let mut frames = Vec::new();
    let mut setup_builds = None;
    for frame in 0..desc.settings.frames {
        let state = evaluate(desc, frame_time(frame, desc.settings.fps));
        assert_eq!(state.transforms.len(), 2, "box and ball");
        assert_eq!(state.fields.len(), 2, "camera position and light intensity");
        apply(&mut renderer, &state).expect("apply");
        let result = renderer.render(&mut |_, _| {}).expect("render");
        let builds = *setup_builds.get_or_insert(result.stats.blas_builds);
        assert_eq!(
            result.stats.blas_builds, builds,
            "frame {frame} built a BLAS"
        );
        frames.push(bits(&result.image));
    }
    assert_eq!(setup_builds, Some(3), "quad, cube and sphere, once");
    for f in 1..frames.len() {
        assert_ne!(
            frames[f],
            frames[f - 1],
            "frames {f} and {} are one image",
            f - 1
        );
    }
    // Frame 5 first, in a renderer of its own: the same bits as after frames 0..=4.
    let mut fresh = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    apply(
        &mut fresh,
        &evaluate(desc, frame_time(5, desc.settings.fps)),
    )
    .expect("apply");
    let image = fresh.render(&mut |_, _| {}).expect("render").image;
    assert_eq!(
        bits(&image),
        frames[5],
        "frame 5 depends on the frames before it"
    );
}

/// A glTF quad (`anim.gltf` + `anim.bin`) on node 0, which a LINEAR translation channel moves
/// from x = -1 at 0 s to x = +1 at 1 s; node 1, its child, carries the quad again 1.5 above.
fn write_animated_gltf(dir: &std::path::Path) {
    let mut bin: Vec<u8> = Vec::new();
    let f = |bin: &mut Vec<u8>, xs: &[f32]| bin.extend(xs.iter().flat_map(|x| x.to_le_bytes()));
    // 0: positions (48 bytes), a 1×1 quad in the xy plane facing +z.
    f(
        &mut bin,
        &[
            -0.5, -0.5, 0.0, 0.5, -0.5, 0.0, 0.5, 0.5, 0.0, -0.5, 0.5, 0.0,
        ],
    );
    // 48: indices (12 bytes).
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    // 60: key times (8 bytes); 68: translations (24 bytes).
    f(&mut bin, &[0.0, 1.0]);
    f(&mut bin, &[-1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    std::fs::write(dir.join("anim.bin"), &bin).expect("anim.bin");
    let gltf = r#"{
        "asset": {"version": "2.0"},
        "buffers": [{"uri": "anim.bin", "byteLength": 92}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 12},
            {"buffer": 0, "byteOffset": 60, "byteLength": 8},
            {"buffer": 0, "byteOffset": 68, "byteLength": 24}
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0.0], "max": [0.5, 0.5, 0.0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
             "min": [0.0], "max": [1.0]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}
        ],
        "materials": [{"pbrMetallicRoughness": {"metallicFactor": 0.0}, "doubleSided": true}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "nodes": [
            {"mesh": 0, "children": [1]},
            {"mesh": 0, "translation": [0.0, 1.5, 0.0]}
        ],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
        "animations": [{
            "samplers": [{"input": 2, "output": 3, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]
        }]
    }"#;
    std::fs::write(dir.join("anim.gltf"), gltf).expect("anim.gltf");
}

#[test]
fn a_gltf_node_animation_moves_its_meshes_without_building_a_blas() {
    let Some(gpu) = gpu_or_skip("a_gltf_node_animation_moves_its_meshes") else {
        return;
    };
    let dir = temp_dir("animation", "gltf");
    write_animated_gltf(&dir);
    let scene = dir.join("scene.rt");
    std::fs::write(
        &scene,
        r#"import "std/cameras/pinhole.rt";
import "std/lights/directional.rt";
import "std/miss/constant.rt";
scene s {
    settings { width: 24, height: 16, samples: 1, max_depth: 0, fps: 4 }
    camera Pinhole { position: vec3f(0.0, 0.75, 5.0), look_at: vec3f(0.0, 0.75, 0.0) }
    background ConstantBackground { color: vec3f(0.0) }
    light sun DirectionalLight { direction: vec3f(0.0, 0.0, -1.0), intensity: 3.0 }
    model "anim.gltf" { transform: translate(vec3f(0.0, 0.0, -1.0)) }
}
"#,
    )
    .expect("scene.rt");
    let compiled = rtc_compiler::kernel::compile_scene(
        std::slice::from_ref(&scene),
        None,
        &rtc_compiler::driver::Options::default(),
        &rtc_compiler::link::LinkOptions::default(),
    )
    .unwrap_or_else(|f| {
        panic!(
            "{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        )
    });
    let program = compiled.checked.program.as_ref().expect("program");
    let desc = &program.scenes[compiled.scene];
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    assert!(rtc_runtime::animation::is_animated_with(desc, &renderer));
    assert!(
        !rtc_runtime::animation::is_animated(desc),
        "no `animate` entry"
    );
    assert_eq!(
        rtc_runtime::animation::frame_count(desc, &renderer, 4),
        5,
        "1 s at 4 fps, the last key's frame included"
    );

    // At 0.5 s node 0 is at x = 0 (halfway from -1 to +1), under the entry's translation, and
    // node 1 (its child) 1.5 above it: exact matrices (tolerance 1e-6).
    apply(&mut renderer, &evaluate(desc, 0.5)).expect("apply");
    let moved: Vec<(String, glam::Vec3)> = renderer
        .entities()
        .objects()
        .iter()
        .map(|o| {
            (
                o.name.clone().unwrap_or_default(),
                o.transform.w_axis.truncate(),
            )
        })
        .collect();
    assert_eq!(moved.len(), 2, "{moved:?}");
    for (name, want) in [
        ("#nodes[0]", glam::Vec3::new(0.0, 0.0, -1.0)),
        ("#nodes[1]", glam::Vec3::new(0.0, 1.5, -1.0)),
    ] {
        let (_, got) = moved
            .iter()
            .find(|(n, _)| n.ends_with(name))
            .unwrap_or_else(|| panic!("no object {name} in {moved:?}"));
        assert!(got.abs_diff_eq(want, 1e-6), "{name}: {got} != {want}");
    }

    let mut images = Vec::new();
    let mut stats = Vec::new();
    for frame in [0, 4] {
        let state = evaluate(desc, frame_time(frame, 4));
        apply(&mut renderer, &state).expect("apply");
        let result = renderer.render(&mut |_, _| {}).expect("render");
        images.push(result.image);
        stats.push(result.stats);
    }
    assert_eq!(stats[0].blas_builds, 1, "one quad mesh, two instances");
    assert_eq!(
        stats[1].blas_builds, stats[0].blas_builds,
        "moving the nodes built no BLAS"
    );
    assert!(
        stats[1].tlas_builds > stats[0].tlas_builds,
        "the TLAS was rebuilt"
    );
    // Lit pixels' mean column: the quads sit left of centre at 0 s and right of it at 1 s.
    let centroid = |image: &LinearImage| {
        let (w, _) = (image.width(), image.height());
        let (mut sum, mut n) = (0.0f64, 0.0f64);
        for (i, p) in image.pixels().iter().enumerate() {
            if p[0] + p[1] + p[2] > 0.05 {
                sum += (i as u32 % w) as f64;
                n += 1.0;
            }
        }
        assert!(n > 0.0, "nothing lit");
        sum / n
    };
    let (a, b) = (centroid(&images[0]), centroid(&images[1]));
    assert!(a < 11.5 && b > 11.5 && b - a > 4.0, "centroids {a} → {b}");
}
