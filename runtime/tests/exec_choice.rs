//! The execution model `rtc render` gives a small render of a scene left at `EXEC_AUTO` on a driver
//! that gets uniform tables (lavapipe before Mesa 26, or on a CPU without AVX-512): the megakernel for a light kernel over small,
//! built-in geometry, the wavefront model otherwise. Checked on every example against the model
//! whose cold compile was measured shorter there (docs/bench/compile.md, "Which model compiles
//! faster, with uniform tables (2026-12-04)"), and against the rules that make the choice:
//! explicit choices and scene settings win, and the bound 0 (no tables) always means the
//! wavefront model. Compile only: no GPU.

use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{
    compile_scene_with, small_built_in_geometry, ExecModel, KernelOptions, SMALL_GEOMETRY_TRIANGLES,
};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::gpu::WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES;
use std::path::{Path, PathBuf};

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../examples/{name}/scene.rt"))
}

/// The model `EXEC_AUTO` resolves to, with the auto model `auto`, the bound `min_weight` and the
/// command line's `exec`; with the kernel's weight and whether its geometry is small and built in.
fn resolve(path: &Path, exec: Option<ExecModel>, min_weight: u64) -> (ExecModel, u64, bool) {
    let compiled = compile_scene_with(
        &[path.to_path_buf()],
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions {
            exec,
            auto: ExecModel::Wavefront,
            wavefront_min_weight: min_weight,
            ..KernelOptions::default()
        },
    )
    .unwrap_or_else(|f| panic!("{} does not compile: {:?}", path.display(), f.diagnostics));
    let program = compiled.checked.program.as_ref().expect("a program");
    let small = small_built_in_geometry(&program.scenes[compiled.scene]);
    assert_eq!(
        compiled.stages.is_some(),
        compiled.exec == ExecModel::Wavefront,
        "{}: stage kernels are built exactly for the wavefront model",
        path.display()
    );
    (compiled.exec, compiled.render_weight, small)
}

#[test]
fn every_example_gets_the_model_that_compiled_faster_with_uniform_tables() {
    // Cold, Mesa 25.0.7, 64x48 at 1 spp: the megakernel compiled faster for these ...
    let megakernel = [
        "cameras",
        "cornell_box",
        "cornell_path",
        "glass_mirror",
        "hello",
        "lambert_only",
        "lights",
    ];
    // ... and the stage kernels for these (pbr_path within 10 % either way).
    let wavefront = [
        "fog",
        "gltf_scene",
        "pbr_path",
        "shading",
        "thesis_scene",
        "three_spheres",
    ];
    for (names, expected) in [
        (&megakernel[..], ExecModel::Megakernel),
        (&wavefront[..], ExecModel::Wavefront),
    ] {
        for name in names {
            let (exec, weight, small) = resolve(
                &example(name),
                None,
                WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES,
            );
            assert_eq!(
                exec, expected,
                "{name}: weight {weight}, small built-in geometry {small}"
            );
            // Without tables the stage kernels compile faster for every example.
            assert_eq!(resolve(&example(name), None, 0).0, ExecModel::Wavefront);
        }
    }
}

#[test]
fn heavy_geometry_or_an_explicit_choice_keeps_its_model() {
    // thesis_scene's megakernel is light (weight below the bound) but its bunny is read from a
    // file: its BVH records do not fit a uniform table, so its traversals compile slowly.
    let (exec, weight, small) = resolve(
        &example("thesis_scene"),
        None,
        WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES,
    );
    assert!(
        weight < WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES,
        "weight {weight}"
    );
    assert!(!small);
    assert_eq!(exec, ExecModel::Wavefront);

    // `--exec` wins over the rule either way.
    let hello = example("hello");
    for model in [ExecModel::Megakernel, ExecModel::Wavefront] {
        assert_eq!(
            resolve(
                &hello,
                Some(model),
                WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES
            )
            .0,
            model
        );
    }

    // A scene of one built-in sphere too fine for a 64 KiB table (sphere_mesh(5): 20,480
    // triangles) keeps the wavefront model; sphere_mesh(3) (1,280) does not.
    let dir = std::env::temp_dir().join(format!("rtc-exec-choice-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (subdivisions, expected) in [(3u32, ExecModel::Megakernel), (5, ExecModel::Wavefront)] {
        assert_eq!(
            subdivisions == 3,
            20 * 4u64.pow(subdivisions) <= SMALL_GEOMETRY_TRIANGLES
        );
        let path = dir.join(format!("sphere{subdivisions}.rt"));
        std::fs::write(
            &path,
            format!(
                "import \"std/cameras/pinhole.rt\";\n\
                 import \"std/materials/lambert.rt\";\n\
                 import \"std/lights/point.rt\";\n\
                 scene s {{\n\
                     camera Pinhole {{ position: vec3f(0.0, 0.0, 3.0), look_at: vec3f(0.0), fov: 40.0 }}\n\
                     object ball {{ geometry: sphere_mesh({subdivisions}u), material: Lambert {{ albedo: vec3f(0.8) }} }}\n\
                     light PointLight {{ position: vec3f(2.0), color: vec3f(1.0), intensity: 10.0 }}\n\
                 }}\n"
            ),
        )
        .expect("write the scene");
        let (exec, weight, _) = resolve(&path, None, WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES);
        assert!(
            weight < WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES,
            "weight {weight}"
        );
        assert_eq!(exec, expected, "sphere_mesh({subdivisions}u)");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
