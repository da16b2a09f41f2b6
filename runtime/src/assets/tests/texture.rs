//! Images: PNG/JPEG → `Rgba8Srgb`, HDR/EXR → `Rgba16F`, exact texel words, limits, bad files.

use std::path::Path;

use image::{ImageBuffer, Luma, Rgb, Rgba};

use super::{assert_close, TempDir};
use crate::assets::texture::{decode_image, pack_f16x2, srgb_to_linear, unpack_f16x2};
use crate::assets::{
    load_image, solid_texture, AssetError, Sampler, TextureData, TextureFormat, Wrap,
    MAX_TEXTURE_SIZE,
};

#[test]
fn png_rgba8_words_are_little_endian_rgba() {
    let dir = TempDir::new("tex");
    let pixels: Vec<u8> = vec![
        255, 0, 0, 255, /**/ 0, 255, 0, 128, /**/ 0, 0, 255, 0, //
        1, 2, 3, 4, /**/ 10, 20, 30, 40, /**/ 250, 251, 252, 253,
    ];
    let img: ImageBuffer<Rgba<u8>, _> = ImageBuffer::from_raw(3, 2, pixels.clone()).unwrap();
    let path = dir.path().join("rgba.png");
    img.save(&path).unwrap();
    let tex = load_image(&path).unwrap();
    assert_eq!(
        (tex.width, tex.height, tex.format),
        (3, 2, TextureFormat::Rgba8Srgb)
    );
    let expected: Vec<u32> = pixels
        .chunks(4)
        .map(|c| {
            u32::from(c[0]) | u32::from(c[1]) << 8 | u32::from(c[2]) << 16 | u32::from(c[3]) << 24
        })
        .collect();
    assert_eq!(tex.words, expected);
    // Row 0 is the top row of the image; texel() decodes sRGB to linear.
    assert_eq!(tex.texel(0, 0), Some([1.0, 0.0, 0.0, 1.0]));
    let t = tex.texel(1, 1).unwrap();
    assert_close(t[0], srgb_to_linear(10.0 / 255.0), 1e-7);
    assert_close(t[1], srgb_to_linear(20.0 / 255.0), 1e-7);
    assert_close(t[3], 40.0 / 255.0, 1e-7);
    assert_eq!(tex.texel(3, 0), None);
    assert_eq!(tex.texel(0, 2), None);
}

#[test]
fn grey_rgb_and_16_bit_pngs_become_rgba8() {
    let dir = TempDir::new("tex");
    let grey: ImageBuffer<Luma<u8>, _> = ImageBuffer::from_raw(2, 1, vec![0u8, 200]).unwrap();
    grey.save(dir.path().join("grey.png")).unwrap();
    let tex = load_image(dir.path().join("grey.png")).unwrap();
    assert_eq!(tex.words, vec![0xff00_0000, 0xffc8_c8c8]);

    let rgb: ImageBuffer<Rgb<u8>, _> = ImageBuffer::from_raw(1, 1, vec![1u8, 2, 3]).unwrap();
    rgb.save(dir.path().join("rgb.png")).unwrap();
    assert_eq!(
        load_image(dir.path().join("rgb.png")).unwrap().words,
        vec![0xff03_0201]
    );

    let deep: ImageBuffer<Rgba<u16>, _> =
        ImageBuffer::from_raw(1, 1, vec![65535u16, 0, 32896, 65535]).unwrap();
    deep.save(dir.path().join("deep.png")).unwrap();
    let tex = load_image(dir.path().join("deep.png")).unwrap();
    assert_eq!(tex.format, TextureFormat::Rgba8Srgb);
    assert_eq!(tex.words, vec![0xff80_00ff]);
}

#[test]
fn jpeg_decodes_to_rgba8() {
    let dir = TempDir::new("tex");
    let img: ImageBuffer<Rgb<u8>, _> = ImageBuffer::from_fn(8, 8, |_, _| Rgb([200, 100, 50]));
    let path = dir.path().join("flat.jpg");
    img.save(&path).unwrap();
    let tex = load_image(&path).unwrap();
    assert_eq!(
        (tex.width, tex.height, tex.format),
        (8, 8, TextureFormat::Rgba8Srgb)
    );
    for w in &tex.words {
        let [r, g, b, a] = w.to_le_bytes();
        assert!(
            r.abs_diff(200) <= 3 && g.abs_diff(100) <= 3 && b.abs_diff(50) <= 3,
            "{w:#x}"
        );
        assert_eq!(a, 255);
    }
}

#[test]
fn exr_and_hdr_become_rgba16f() {
    let dir = TempDir::new("tex");
    let values = vec![0.5f32, 1.0, 2.0, 1.0, /**/ 1000.0, 0.25, 0.0, 0.5];
    let img: ImageBuffer<Rgba<f32>, _> = ImageBuffer::from_raw(2, 1, values.clone()).unwrap();
    let path = dir.path().join("hdr.exr");
    img.save(&path).unwrap();
    let tex = load_image(&path).unwrap();
    assert_eq!(
        (tex.width, tex.height, tex.format),
        (2, 1, TextureFormat::Rgba16F)
    );
    assert_eq!(tex.words.len(), 4);
    // These values are exact in f16, so the words are known bit patterns.
    assert_eq!(tex.words[0], pack_f16x2(0.5, 1.0));
    assert_eq!(tex.words[0], 0x3c00_3800);
    assert_eq!(tex.words[1], 0x3c00_4000);
    assert_eq!(tex.texel(1, 0), Some([1000.0, 0.25, 0.0, 0.5]));

    let rgb: ImageBuffer<Rgb<f32>, _> =
        ImageBuffer::from_raw(1, 1, vec![4.0f32, 0.5, 0.125]).unwrap();
    let path = dir.path().join("sky.hdr");
    rgb.save(&path).unwrap();
    let tex = load_image(&path).unwrap();
    assert_eq!(tex.format, TextureFormat::Rgba16F);
    // Radiance HDR stores a shared exponent; these values are representable exactly.
    assert_eq!(tex.texel(0, 0), Some([4.0, 0.5, 0.125, 1.0]));
}

#[test]
fn f16_packing_clamps_and_drops_nan() {
    assert_eq!(unpack_f16x2(pack_f16x2(1e9, -1e9)), [65504.0, -65504.0]);
    assert_eq!(
        unpack_f16x2(pack_f16x2(f32::NAN, f32::INFINITY)),
        [0.0, 65504.0]
    );
    assert_eq!(unpack_f16x2(pack_f16x2(-2.5, 0.0)), [-2.5, 0.0]);
    // The first value is in the low half (WGSL unpack2x16float order).
    assert_eq!(pack_f16x2(1.0, 0.0), 0x0000_3c00);
}

#[test]
fn solid_texture_is_one_linear_texel() {
    let tex = solid_texture([0.25, 0.5, 2.0, 1.0]);
    assert_eq!(
        tex,
        TextureData {
            width: 1,
            height: 1,
            format: TextureFormat::Rgba16F,
            words: vec![pack_f16x2(0.25, 0.5), pack_f16x2(2.0, 1.0)],
            nonfinite_texels: 0,
            sampler: Sampler::default(),
        }
    );
    assert_eq!(tex.texel(0, 0), Some([0.25, 0.5, 2.0, 1.0]));
    assert_eq!(tex.texel_count(), 1);
}

#[test]
fn too_large_image_is_rejected_before_decoding() {
    let dir = TempDir::new("tex");
    let wide: ImageBuffer<Luma<u8>, _> = ImageBuffer::new(MAX_TEXTURE_SIZE + 1, 1);
    let path = dir.path().join("wide.png");
    wide.save(&path).unwrap();
    match load_image(&path) {
        Err(AssetError::ImageTooLarge {
            width, height, max, ..
        }) => {
            assert_eq!(
                (width, height, max),
                (MAX_TEXTURE_SIZE + 1, 1, MAX_TEXTURE_SIZE)
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_images_are_errors() {
    let label = Path::new("bad.png");
    // Not an image at all.
    assert!(matches!(
        decode_image(b"hello, world", label),
        Err(AssetError::UnsupportedFormat { .. })
    ));
    // A format we do not read (BMP magic).
    let bmp = decode_image(b"BM\x3a\0\0\0\0\0\0\0\x36\0\0\0\x28\0\0\0", label);
    assert!(
        matches!(&bmp, Err(AssetError::UnsupportedFormat { found, .. }) if found.contains("Bmp")),
        "{bmp:?}"
    );
    // A truncated PNG.
    let dir = TempDir::new("tex");
    let img: ImageBuffer<Rgb<u8>, _> =
        ImageBuffer::from_fn(16, 16, |x, y| Rgb([x as u8, y as u8, 7]));
    let path = dir.path().join("ok.png");
    img.save(&path).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    for cut in [8, 20, 40, bytes.len() - 20] {
        let err = decode_image(&bytes[..cut], label).unwrap_err();
        assert!(
            matches!(err, AssetError::ImageDecode { .. }),
            "cut {cut}: {err:?}"
        );
        assert!(err.to_string().starts_with("bad.png: "), "{err}");
    }
    // Missing file.
    assert!(matches!(
        load_image("/nonexistent/rtc/t.png"),
        Err(AssetError::Read { .. })
    ));
}

#[test]
fn wrap_modes_map_every_index_into_the_texture() {
    let n = 3;
    let got = |w: Wrap| (-4..7).map(|x| w.apply(x, n)).collect::<Vec<_>>();
    // x:                         -4 -3 -2 -1  0  1  2  3  4  5  6
    assert_eq!(got(Wrap::Repeat), [2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0]);
    assert_eq!(got(Wrap::ClampToEdge), [0, 0, 0, 0, 0, 1, 2, 2, 2, 2, 2]);
    assert_eq!(got(Wrap::MirroredRepeat), [2, 2, 1, 0, 0, 1, 2, 2, 1, 0, 0]);
}

/// A 2×1 linear texture: black, then white (red channel), with `sampler`.
fn black_white(sampler: Sampler) -> TextureData {
    TextureData {
        width: 2,
        height: 1,
        format: TextureFormat::Rgba8Unorm,
        words: vec![0xff00_0000, 0xffff_ffff],
        nonfinite_texels: 0,
        sampler,
    }
}

#[test]
fn sampling_follows_the_wrap_mode_and_filter() {
    let red = |t: &TextureData, u: f32| t.sample([u, 0.5])[0];
    let repeat = black_white(Sampler::default());
    // Texel centres at u = 0.25 (black) and 0.75 (white); halfway between them 0.5, and at the
    // seam u = 0 (repeat: between the last and the first texel) 0.5 too.
    assert_close(red(&repeat, 0.25), 0.0, 1e-6);
    assert_close(red(&repeat, 0.5), 0.5, 1e-6);
    assert_close(red(&repeat, 0.0), 0.5, 1e-6);
    assert_close(red(&repeat, 1.25), 0.0, 1e-6);
    let clamp = black_white(Sampler {
        wrap_u: Wrap::ClampToEdge,
        ..Sampler::default()
    });
    assert_close(red(&clamp, 0.0), 0.0, 1e-6);
    assert_close(red(&clamp, 1.0), 1.0, 1e-6);
    assert_close(red(&clamp, 3.7), 1.0, 1e-6);
    assert_close(red(&clamp, -2.0), 0.0, 1e-6);
    let mirror = black_white(Sampler {
        wrap_u: Wrap::MirroredRepeat,
        nearest: true,
        ..Sampler::default()
    });
    // Nearest, mirrored: [0, 1) black white, [1, 2) white black.
    assert_eq!(red(&mirror, 0.2), 0.0);
    assert_eq!(red(&mirror, 0.7), 1.0);
    assert_eq!(red(&mirror, 1.2), 1.0);
    assert_eq!(red(&mirror, 1.7), 0.0);
    assert_eq!(red(&mirror, -0.2), 0.0);
    // Linear data is not sRGB-decoded; the same words as sRGB are.
    let srgb = black_white(Sampler::default()).srgb();
    assert_eq!(srgb.format, TextureFormat::Rgba8Srgb);
    assert_eq!(srgb.clone().linear().format, TextureFormat::Rgba8Unorm);
}

#[test]
fn decoded_srgb_textures_hold_each_byte_as_the_nearest_half_float_of_its_linear_value() {
    // 256 texels: red takes every byte value, green its complement, blue another order, alpha too.
    let words: Vec<u32> = (0..=255u8)
        .map(|r| u32::from_le_bytes([r, 255 - r, r.wrapping_mul(97), r.wrapping_add(3)]))
        .collect();
    let sampler = Sampler {
        wrap_u: Wrap::ClampToEdge,
        ..Sampler::default()
    };
    let srgb = TextureData {
        width: 16,
        height: 16,
        format: TextureFormat::Rgba8Srgb,
        words,
        nonfinite_texels: 0,
        sampler,
    };
    let decoded = srgb.decoded_srgb().expect("an sRGB texture decodes");
    assert_eq!(
        (
            decoded.width,
            decoded.height,
            decoded.format,
            decoded.sampler
        ),
        (16, 16, TextureFormat::Rgba16F, sampler)
    );
    assert_eq!(decoded.words.len(), 2 * srgb.words.len());
    let half = |x: f32| half::f16::from_f32(x).to_f32();
    for y in 0..16 {
        for x in 0..16 {
            let want = srgb.texel(x, y).unwrap();
            let got = decoded.texel(x, y).unwrap();
            // Exactly the half float nearest the 8-bit texel's decoding (alpha: byte / 255).
            assert_eq!(got, want.map(half), "texel ({x}, {y})");
            for (g, w) in got.iter().zip(want) {
                assert!(
                    (g - w).abs() <= w.abs() / 2048.0,
                    "texel ({x}, {y}): {g} against {w}"
                );
            }
        }
    }
    assert_eq!(
        decoded.texel(0, 0).unwrap(),
        [0.0, 1.0, 0.0, half(3.0 / 255.0)]
    );
    // Only 8-bit sRGB textures decode.
    assert!(srgb.clone().linear().decoded_srgb().is_none());
    assert!(decoded.decoded_srgb().is_none());
    assert!(solid_texture([0.5; 4]).decoded_srgb().is_none());
}
