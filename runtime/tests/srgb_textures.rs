//! 8-bit sRGB textures on the GPU, stored decoded at upload (linear half floats, the default) and
//! stored encoded (decoded by the kernel at each lookup): both give every byte value's sRGB
//! decoding, on whatever adapter exists (lavapipe on CI); a test skips only when there is no
//! adapter at all, and says so.
//!
//! The texture is 16×16 with all 256 byte values in red (texel `(x, y)` has red `16y + x`, green
//! `255 - red` and blue `97 · red mod 256`). An orthographic camera looks straight down on
//! `quad_mesh()` (the square [-1, 1]² in the xz-plane, uv `((x + 1) / 2, (z + 1) / 2)`) through a
//! 2 × 2 window, 16×16 pixels, so pixel `(px, py)` hits uv `((px + 0.5) / 16, (py + 0.5) / 16)`,
//! the centre of texel `(px, py)`, where the bilinear lookup is that texel; the unlit material
//! shows it unlit. Expected values are decoded here in `f64`. Tolerances: encoded, `1e-4`
//! absolute (the kernel's `f32` `pow`, as `gltf_textures.rs`); decoded, the half float's
//! rounding, `2^-11` of the value, plus `1e-6`.

mod common;

use common::image::{srgb_to_linear, PixelCheck, Tolerance};
use common::{gpu_or_skip, temp_dir};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::render::RenderOptions;
use rtc_runtime::scene::SrgbTextures;

const SIDE: u32 = 16;

/// The sRGB bytes of texel `(x, y)`.
fn texel(x: u32, y: u32) -> [u8; 4] {
    let r = (SIDE * y + x) as u8;
    [r, 255 - r, r.wrapping_mul(97), 255]
}

#[test]
fn srgb_textures_decoded_at_upload_or_by_the_kernel_give_every_byte_its_linear_value() {
    let Some(gpu) = gpu_or_skip(
        "srgb_textures_decoded_at_upload_or_by_the_kernel_give_every_byte_its_linear_value",
    ) else {
        return;
    };
    let dir = temp_dir("srgb_textures", "bytes");
    let raw: Vec<u8> = (0..SIDE)
        .flat_map(|y| (0..SIDE).flat_map(move |x| texel(x, y)))
        .collect();
    let png: image::RgbaImage = image::ImageBuffer::from_raw(SIDE, SIDE, raw).unwrap();
    png.save(dir.join("bytes.png")).unwrap();
    let scene = format!(
        "import \"std/cameras/orthographic.rt\";\n\
         import \"std/materials/unlit_texture.rt\";\n\
         scene bytes {{\n\
             settings {{ width: {SIDE}, height: {SIDE}, samples: 1 }}\n\
             camera Orthographic {{ position: vec3f(0.0, 5.0, 0.0), look_at: vec3f(0.0), \
                                    up: vec3f(0.0, 0.0, -1.0), height: 2.0 }}\n\
             object quad {{ geometry: quad_mesh(), \
                            material: UnlitTexture {{ texture: load_image(\"bytes.png\") }} }}\n\
         }}\n"
    );
    let path = dir.join("scene.rt");
    std::fs::write(&path, scene).unwrap();
    let compiled = match compile_scene_with(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions::default(),
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "the test scene does not compile:\n{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    };
    let cases = [
        (
            SrgbTextures::Decoded,
            1,
            Tolerance {
                abs: 1e-6,
                rel: 1.0 / 2048.0,
            },
        ),
        (SrgbTextures::Encoded, 0, Tolerance::abs(1e-4)),
    ];
    for (mode, decoded, tolerance) in cases {
        let what = format!("{mode:?}");
        let options = RenderOptions {
            srgb_textures: mode,
            ..RenderOptions::default()
        };
        let (image, stats) = common::scene::render(&gpu, &compiled, options, &what);
        assert_eq!(
            stats.decoded_textures, decoded,
            "{what}: textures stored decoded"
        );
        let mut check = PixelCheck::new(&what);
        for py in 0..SIDE {
            for px in 0..SIDE {
                let want = texel(px, py).map(|c| srgb_to_linear(f64::from(c) / 255.0));
                check.pixel((px, py), image.get(px, py).unwrap(), &want[..3], tolerance);
            }
        }
        assert_eq!(check.checked(), (SIDE * SIDE * 3) as usize);
        check.assert();
    }
}
