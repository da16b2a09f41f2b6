//! Textures on the CPU: images decoded into the exact `u32` words of the GPU's texel buffer.
//!
//! # Layout (the kernel decodes it the same way)
//!
//! A [`TextureData`] of `width × height` texels holds `width * height * words_per_texel` words,
//! row-major, **top row first** (texel `(x, y)` starts at word `(y * width + x) *
//! words_per_texel`), so uv `(0, 0)` is the top-left corner as in the
//! [module conventions](super).
//!
//! - [`TextureFormat::Rgba8Srgb`], one word per texel: bits 0–7 red, 8–15 green, 16–23 blue,
//!   24–31 alpha, i.e. the RGBA bytes in little-endian order (`u32::from_le_bytes([r, g, b, a])`).
//!   WGSL's `unpack4x8unorm(word)` gives `(r, g, b, a) / 255`. Red, green and blue are
//!   sRGB-encoded and must be decoded to linear ([`srgb_to_linear`]); alpha is linear.
//! - [`TextureFormat::Rgba8Unorm`]: the same packing, all four channels linear (glTF's data
//!   textures: metallic-roughness, occlusion, normal maps). [`TextureData::linear`] makes one
//!   of an `Rgba8Srgb` texture by relabelling it; the words do not change.
//! - [`TextureFormat::Rgba16F`], two words per texel: word 0 = `f16(r) | f16(g) << 16`, word 1 =
//!   `f16(b) | f16(a) << 16` (IEEE binary16 bit patterns), so `unpack2x16float(word0)` is
//!   `(r, g)` and `unpack2x16float(word1)` is `(b, a)`. Values are linear. On packing, NaN
//!   becomes 0 and values beyond ±65504 (the largest f16) are clamped to it, so no texel is ever
//!   NaN or infinite. A decoded image's NaN and infinite channels are replaced by 0 before
//!   packing and counted in [`TextureData::nonfinite_texels`], which the scene stage reports as
//!   a warning naming the file.
//!
//! # Which format an image gets
//!
//! PNG and JPEG (8 or 16 bits per channel, grey or colour, with or without alpha) become
//! `Rgba8Srgb` (16-bit channels are rounded to 8 bits; grey is replicated; missing alpha is 1).
//! HDR and EXR (floating point) become `Rgba16F`. [`solid_texture`] is `Rgba16F` so a colour is
//! stored linearly, without an sRGB round trip, and may exceed 1. The entity stage then stores
//! `Rgba8Srgb` textures decoded, as `Rgba16F` ([`TextureData::decoded_srgb`]), while they fit its
//! budget (`scene::SrgbTextures`): the kernel's lookup then reads two words a texel and decodes
//! nothing.
//!
//! Invariants: `words.len() == width * height * format.words_per_texel()`; `1 <= width, height
//! <= MAX_TEXTURE_SIZE`, and a decoder allocates at most [`MAX_DECODE_BYTES`]. Decoding never panics on bad bytes; it returns [`AssetError`].

use std::io::Cursor;
use std::path::Path;

use half::f16;
use image::{DynamicImage, ImageFormat, ImageReader};

use super::AssetError;

/// The largest width or height of a texture, in texels.
pub const MAX_TEXTURE_SIZE: u32 = 16384;

/// The most memory a decoder may allocate for one image: twice a 16384² RGBA8 image, so any
/// 8-bit image within [`MAX_TEXTURE_SIZE`] decodes, and a float image up to about 11585² (a
/// crafted header cannot make the decoder allocate more).
pub const MAX_DECODE_BYTES: u64 = 2 << 30;

/// How a texel is packed into words (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TextureFormat {
    /// One word per texel: sRGB-encoded red, green, blue and linear alpha, 8 bits each.
    Rgba8Srgb,
    /// One word per texel: linear red, green, blue and alpha, 8 bits each.
    Rgba8Unorm,
    /// Two words per texel: linear red, green, blue, alpha as IEEE half floats.
    Rgba16F,
}

impl TextureFormat {
    /// `u32` words per texel.
    pub const fn words_per_texel(self) -> usize {
        match self {
            Self::Rgba8Srgb | Self::Rgba8Unorm => 1,
            Self::Rgba16F => 2,
        }
    }
}

/// How texture coordinates outside `[0, 1)` map into the texture, per axis (glTF's `wrapS`/`wrapT`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    /// The texture repeats (`fract(u)`).
    #[default]
    Repeat,
    /// Coordinates are clamped to the edge texels.
    ClampToEdge,
    /// The texture repeats, mirrored every other period.
    MirroredRepeat,
}

/// How `sample(t, uv)` reads a texture: the wrap mode of `u` and of `v`, and nearest-texel or
/// bilinear filtering. The default (repeat, bilinear) is what every texture had before samplers
/// existed, and what images named in a scene get.
///
/// There is no minification filter: a ray carries no footprint (no ray differentials or cones),
/// so there is no mip level to choose; several samples per pixel average the footprint instead.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Sampler {
    /// Wrap mode of `u` (horizontal).
    pub wrap_u: Wrap,
    /// Wrap mode of `v` (vertical, pointing down the image).
    pub wrap_v: Wrap,
    /// Nearest-texel lookup (`true`) or bilinear interpolation (`false`).
    pub nearest: bool,
}

/// A decoded texture, in the GPU's texel-buffer layout (see the [module docs](self)), with the
/// sampler state `sample` uses for it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextureData {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// The packing of each texel.
    pub format: TextureFormat,
    /// The packed texels, row-major, top row first.
    pub words: Vec<u32>,
    /// How many texels of the decoded file had a NaN or infinite channel (replaced by 0).
    pub nonfinite_texels: u64,
    /// Wrap modes and filter.
    pub sampler: Sampler,
}

impl TextureData {
    /// Number of texels.
    pub fn texel_count(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// The texel at column `x`, row `y` (row 0 at the top), decoded to linear RGBA exactly as the
    /// kernel decodes it; `None` outside the texture.
    pub fn texel(&self, x: u32, y: u32) -> Option<[f32; 4]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let wpt = self.format.words_per_texel();
        let start = (y as usize)
            .checked_mul(self.width as usize)?
            .checked_add(x as usize)?
            .checked_mul(wpt)?;
        let words = self.words.get(start..start.checked_add(wpt)?)?;
        Some(match (self.format, words) {
            (TextureFormat::Rgba8Srgb, &[w]) => {
                let [r, g, b, a] = w.to_le_bytes().map(|c| f32::from(c) / 255.0);
                [srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a]
            }
            (TextureFormat::Rgba8Unorm, &[w]) => w.to_le_bytes().map(|c| f32::from(c) / 255.0),
            (TextureFormat::Rgba16F, &[rg, ba]) => {
                let [r, g] = unpack_f16x2(rg);
                let [b, a] = unpack_f16x2(ba);
                [r, g, b, a]
            }
            _ => return None,
        })
    }

    /// This texture with its colour channels read as linear values (glTF's data textures):
    /// `Rgba8Srgb` becomes `Rgba8Unorm`; float textures are linear already.
    pub fn linear(mut self) -> Self {
        if self.format == TextureFormat::Rgba8Srgb {
            self.format = TextureFormat::Rgba8Unorm;
        }
        self
    }

    /// An `Rgba8Srgb` texture decoded to linear `Rgba16F` (twice the words), or `None` for any
    /// other format. Each channel is [`srgb_to_linear`] (alpha `a / 255`) rounded once to the
    /// nearest half float, so a lookup returns what the kernel's decoding of the 8-bit texel
    /// returns up to that rounding (a relative 2^-11), without the kernel's three `pow`s a texel.
    pub fn decoded_srgb(&self) -> Option<TextureData> {
        if self.format != TextureFormat::Rgba8Srgb {
            return None;
        }
        let half = |x: f32| f16::from_f32(x).to_bits();
        let colour: [u16; 256] = std::array::from_fn(|k| half(srgb_to_linear(k as f32 / 255.0)));
        let alpha: [u16; 256] = std::array::from_fn(|k| half(k as f32 / 255.0));
        // Every byte indexes a 256-entry table: `get` never misses.
        let at =
            |table: &[u16; 256], c: u8| u32::from(table.get(usize::from(c)).copied().unwrap_or(0));
        let mut words = vec![0; self.words.len() * 2];
        for (pair, &w) in words.chunks_exact_mut(2).zip(&self.words) {
            let [r, g, b, a] = w.to_le_bytes();
            if let [rg, ba] = pair {
                *rg = at(&colour, r) | at(&colour, g) << 16;
                *ba = at(&colour, b) | at(&alpha, a) << 16;
            }
        }
        Some(TextureData {
            width: self.width,
            height: self.height,
            format: TextureFormat::Rgba16F,
            words,
            nonfinite_texels: self.nonfinite_texels,
            sampler: self.sampler,
        })
    }

    /// The inverse of [`TextureData::linear`]: `Rgba8Unorm` becomes `Rgba8Srgb`.
    pub fn srgb(mut self) -> Self {
        if self.format == TextureFormat::Rgba8Unorm {
            self.format = TextureFormat::Rgba8Srgb;
        }
        self
    }

    /// `sample(t, uv)` as the kernel computes it (`stdlib/kernel/support.rt`), for tests and
    /// tools: the sampler's wrap modes and filter, bilinear between texel centres.
    pub fn sample(&self, uv: [f32; 2]) -> [f32; 4] {
        let (w, h) = (self.width.max(1) as f32, self.height.max(1) as f32);
        let at = |x: i64, y: i64| {
            let xi = self.sampler.wrap_u.apply(x, i64::from(self.width.max(1)));
            let yi = self.sampler.wrap_v.apply(y, i64::from(self.height.max(1)));
            self.texel(xi as u32, yi as u32).unwrap_or([0.0; 4])
        };
        if self.sampler.nearest {
            return at((uv[0] * w).floor() as i64, (uv[1] * h).floor() as i64);
        }
        let (px, py) = (uv[0] * w - 0.5, uv[1] * h - 0.5);
        let (fx, fy) = (px.floor(), py.floor());
        let (tx, ty) = (px - fx, py - fy);
        let (x, y) = (fx as i64, fy as i64);
        let mix = |a: [f32; 4], b: [f32; 4], t: f32| {
            let mut out = a;
            for ((o, a), b) in out.iter_mut().zip(a).zip(b) {
                *o = a + (b - a) * t;
            }
            out
        };
        let top = mix(at(x, y), at(x + 1, y), tx);
        let bottom = mix(at(x, y + 1), at(x + 1, y + 1), tx);
        mix(top, bottom, ty)
    }
}

impl Wrap {
    /// Integer texel coordinate `x` mapped into `[0, n)` (`n >= 1`).
    pub fn apply(self, x: i64, n: i64) -> i64 {
        match self {
            Self::Repeat => x.rem_euclid(n),
            Self::ClampToEdge => x.clamp(0, n - 1),
            Self::MirroredRepeat => {
                let m = x.rem_euclid(2 * n);
                if m >= n {
                    2 * n - 1 - m
                } else {
                    m
                }
            }
        }
    }
}

/// The sRGB transfer function, decoding (IEC 61966-2-1): encoded `[0, 1]` → linear `[0, 1]`.
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Packs two floats as IEEE half floats, the first in the low 16 bits (WGSL `pack2x16float`),
/// with NaN → 0 and clamping to ±65504.
pub fn pack_f16x2(lo: f32, hi: f32) -> u32 {
    let bits = |x: f32| {
        let x = if x.is_nan() {
            0.0
        } else {
            x.clamp(-f16::MAX.to_f32(), f16::MAX.to_f32())
        };
        u32::from(f16::from_f32(x).to_bits())
    };
    bits(lo) | (bits(hi) << 16)
}

/// Unpacks [`pack_f16x2`] (WGSL `unpack2x16float`).
pub fn unpack_f16x2(word: u32) -> [f32; 2] {
    let [a, b, c, d] = word.to_le_bytes();
    [
        f16::from_le_bytes([a, b]).to_f32(),
        f16::from_le_bytes([c, d]).to_f32(),
    ]
}

/// A 1×1 texture of one linear colour (`Rgba16F`, see the [module docs](self)).
pub fn solid_texture(color: [f32; 4]) -> TextureData {
    let [r, g, b, a] = color;
    TextureData {
        width: 1,
        height: 1,
        format: TextureFormat::Rgba16F,
        words: vec![pack_f16x2(r, g), pack_f16x2(b, a)],
        nonfinite_texels: 0,
        sampler: Sampler::default(),
    }
}

/// Reads a PNG, JPEG, HDR or EXR file (recognised by its content, not its name).
pub fn load_image(path: impl AsRef<Path>) -> Result<TextureData, AssetError> {
    let path = path.as_ref();
    let bytes = std::fs::read(path).map_err(|source| AssetError::Read {
        path: path.to_owned(),
        source,
    })?;
    decode_image(&bytes, path)
}

/// [`load_image`] on bytes; `label` names the image in errors (a file, or `model.glb#images[2]`).
pub(crate) fn decode_image(bytes: &[u8], label: &Path) -> Result<TextureData, AssetError> {
    let decode_error = |source| AssetError::ImageDecode {
        path: label.to_owned(),
        source,
    };
    let format = image::guess_format(bytes).map_err(|_| AssetError::UnsupportedFormat {
        path: label.to_owned(),
        found: "not a PNG, JPEG, HDR or EXR image".to_owned(),
    })?;
    if !matches!(
        format,
        ImageFormat::Png | ImageFormat::Jpeg | ImageFormat::Hdr | ImageFormat::OpenExr
    ) {
        return Err(AssetError::UnsupportedFormat {
            path: label.to_owned(),
            found: format!("{format:?} image (expected PNG, JPEG, HDR or EXR)"),
        });
    }
    let (width, height) = ImageReader::with_format(Cursor::new(bytes), format)
        .into_dimensions()
        .map_err(decode_error)?;
    if width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE || width == 0 || height == 0 {
        return Err(AssetError::ImageTooLarge {
            path: label.to_owned(),
            width,
            height,
            max: MAX_TEXTURE_SIZE,
        });
    }
    let mut reader = ImageReader::with_format(Cursor::new(bytes), format);
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_TEXTURE_SIZE);
    limits.max_image_height = Some(MAX_TEXTURE_SIZE);
    limits.max_alloc = Some(MAX_DECODE_BYTES);
    reader.limits(limits);
    let image = reader.decode().map_err(decode_error)?;
    Ok(from_dynamic(image))
}

fn from_dynamic(image: DynamicImage) -> TextureData {
    let (width, height) = (image.width(), image.height());
    let float = matches!(
        image,
        DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_)
    );
    if float {
        let rgba = image.into_rgba32f();
        let mut nonfinite_texels = 0u64;
        let finite = |x: f32| if x.is_finite() { x } else { 0.0 };
        let words = rgba
            .pixels()
            .flat_map(|p| {
                let [r, g, b, a] = p.0;
                if !p.0.iter().all(|c| c.is_finite()) {
                    nonfinite_texels += 1;
                }
                [
                    pack_f16x2(finite(r), finite(g)),
                    pack_f16x2(finite(b), finite(a)),
                ]
            })
            .collect();
        TextureData {
            width,
            height,
            format: TextureFormat::Rgba16F,
            words,
            nonfinite_texels,
            sampler: Sampler::default(),
        }
    } else {
        let rgba = image.into_rgba8();
        let words = rgba
            .as_raw()
            .chunks_exact(4)
            .filter_map(|c| <[u8; 4]>::try_from(c).ok())
            .map(u32::from_le_bytes)
            .collect();
        TextureData {
            width,
            height,
            format: TextureFormat::Rgba8Srgb,
            words,
            nonfinite_texels: 0,
            sampler: Sampler::default(),
        }
    }
}

/// A codec's error in words for a user: the format, what is wrong, and the codec's detail only
/// when it is a sentence (some codecs print Rust debug text such as
/// `ChunkType { type: IDAT, critical: true, … }` or `Corrupt deflate stream. BadZlibHeader`).
pub(crate) fn describe_image_error(e: &image::ImageError) -> String {
    use image::error::ImageFormatHint;
    use image::ImageError as E;
    let format_name = |hint: ImageFormatHint| match hint {
        ImageFormatHint::Exact(ImageFormat::Png) => "PNG".to_owned(),
        ImageFormatHint::Exact(ImageFormat::Jpeg) => "JPEG".to_owned(),
        ImageFormatHint::Exact(ImageFormat::Hdr) => "Radiance HDR".to_owned(),
        ImageFormatHint::Exact(ImageFormat::OpenExr) => "OpenEXR".to_owned(),
        ImageFormatHint::Exact(f) => f
            .extensions_str()
            .first()
            .map_or_else(|| "image".to_owned(), |ext| ext.to_ascii_uppercase()),
        _ => "image".to_owned(),
    };
    match e {
        E::Decoding(d) => {
            let format = format_name(d.format_hint());
            let detail = std::error::Error::source(d).map(|s| s.to_string());
            match detail.as_deref().and_then(humanize_codec_detail) {
                Some(detail) => format!("the {format} data is corrupt: {detail}"),
                None => format!("the {format} data is corrupt or truncated"),
            }
        }
        E::Limits(_) => format!(
            "decoding it would need more memory than the {} MiB allowed for one image",
            MAX_DECODE_BYTES >> 20
        ),
        E::Unsupported(u) => {
            let text = u.to_string();
            if text.contains('{') {
                format!(
                    "it uses a feature of the {} format that is not supported",
                    format_name(u.format_hint())
                )
            } else {
                format!("not supported: {text}")
            }
        }
        E::IoError(io) if io.kind() == std::io::ErrorKind::UnexpectedEof => {
            "the file ends before the image does (truncated?)".to_owned()
        }
        E::IoError(io) => format!("the image data cannot be read: {io}"),
        E::Parameter(p) => format!("bad image parameters: {p}"),
        E::Encoding(_) => "the image could not be encoded".to_owned(),
    }
}

/// A codec's detail message as a sentence, or `None` when it is (or holds) Rust debug text.
fn humanize_codec_detail(detail: &str) -> Option<String> {
    let detail = detail.trim();
    if detail.starts_with("Corrupt deflate stream") {
        return Some("its compressed pixel data is damaged".to_owned());
    }
    // `ChunkType { type: IDAT, critical: true, … }` → `IDAT`.
    let mut text = detail.to_owned();
    while let Some(start) = text.find("ChunkType {") {
        let Some(rest) = text.get(start..) else { break };
        let name = rest
            .split_once("type: ")
            .and_then(|(_, after)| after.split([',', ' ']).next())
            .unwrap_or("a")
            .to_owned();
        let Some(end) = rest.find('}') else { break };
        text.replace_range(start..start + end + 1, &name);
    }
    if text.starts_with("CRC error") {
        return Some(format!(
            "a checksum does not match, the file is damaged ({})",
            text.trim_end_matches('.')
        ));
    }
    if text.is_empty() || text.contains(['{', '}']) {
        return None;
    }
    Some(text.trim_end_matches('.').to_owned())
}
