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
