//! Linear RGBA `f32` images: output as EXR (HDR) and PNG (tone-mapped sRGB), input from both,
//! and image metrics for reference comparisons.
//!
//! Conventions and invariants:
//! - A [`LinearImage`] holds scene-linear RGBA, row-major, top row first, `width * height`
//!   pixels. [`LinearImage::from_accumulation`] turns the GPU's accumulation buffer
//!   (rgb = radiance sum, a = sample count) into one (rgb / count, alpha 1).
//! - **No NaN or infinity ever reaches a written file.** Both writers work on a sanitised copy:
//!   a pixel with any non-finite channel becomes opaque black `[0, 0, 0, 1]`, and the writers
//!   return how many pixels that was ([`WriteReport`]); reporting it is the caller's job.
//! - EXR stores the linear values unchanged as 32-bit float RGBA.
//! - PNG is 8-bit sRGB RGB (no alpha): `exposure` (in stops, a factor `2^exposure`), then a tone
//!   curve ([`ToneCurve`]; the default [`ToneCurve::Clamp`] clips to `[0, 1]`), then the sRGB
//!   transfer function, then rounding to the nearest of 256 levels.
//! - Reading EXR/HDR gives linear values as stored. Reading PNG/JPEG decodes sRGB back to linear,
//!   which recovers the *tone-mapped display* values, not the original radiance.
//! - Metrics ([`compare`]) are over RGB only (alpha ignored) and skip pixels that are non-finite
//!   in either image, counting them instead.

use std::path::{Path, PathBuf};

/// Offset in the relative MSE denominator, `(t - r)^2 / (r^2 + REL_MSE_EPSILON)`, which keeps
/// black reference pixels from dominating (the value commonly used in denoising papers).
pub const REL_MSE_EPSILON: f64 = 1e-2;

/// Why an image operation failed.
#[derive(Debug, thiserror::Error)]
pub enum ImageError {
    /// The pixel data does not match the dimensions.
    #[error("a {width}x{height} image needs {} pixels, got {found}", u64::from(*width) * u64::from(*height))]
    PixelCount {
        /// Width.
        width: u32,
        /// Height.
        height: u32,
        /// Pixels supplied.
        found: usize,
    },
    /// Two images to compare differ in size.
    #[error("cannot compare a {}x{} image with a {}x{} reference", test.0, test.1, reference.0, reference.1)]
    DimensionMismatch {
        /// The test image's size.
        test: (u32, u32),
        /// The reference's size.
        reference: (u32, u32),
    },
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    File {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The codec failed.
    #[error("{path}: {source}")]
    Codec {
        /// The file.
        path: PathBuf,
        /// The codec's error.
        source: image::ImageError,
    },
}

/// Scene-linear RGBA image, row-major, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearImage {
    width: u32,
    height: u32,
    pixels: Vec<[f32; 4]>,
}

impl LinearImage {
    /// An image from `width * height` pixels.
    pub fn new(width: u32, height: u32, pixels: Vec<[f32; 4]>) -> Result<Self, ImageError> {
        if pixels.len() as u64 != u64::from(width) * u64::from(height) {
            return Err(ImageError::PixelCount {
                width,
                height,
                found: pixels.len(),
            });
        }
        Ok(Self {
            width,
            height,
            pixels,
        })
    }

    /// An image with every pixel set to `value`.
    pub fn filled(width: u32, height: u32, value: [f32; 4]) -> Self {
        Self {
            width,
            height,
            pixels: vec![value; width as usize * height as usize],
        }
    }

    /// Resolves an accumulation buffer (rgb = sum, a = sample count) into mean radiance with
    /// alpha 1; pixels with no samples are black. Extra trailing entries (buffer padding) are
    /// ignored; too few is an error.
    pub fn from_accumulation(
        width: u32,
        height: u32,
        accumulation: &[[f32; 4]],
    ) -> Result<Self, ImageError> {
        let count = width as usize * height as usize;
        let Some(used) = accumulation.get(..count) else {
            return Err(ImageError::PixelCount {
                width,
                height,
                found: accumulation.len(),
            });
        };
        let pixels = used
            .iter()
            .map(|&[r, g, b, n]| {
                if n > 0.0 {
                    [r / n, g / n, b / n, 1.0]
                } else {
                    [0.0, 0.0, 0.0, 1.0]
                }
            })
            .collect();
        Ok(Self {
            width,
            height,
            pixels,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The pixels, row-major.
    pub fn pixels(&self) -> &[[f32; 4]] {
        &self.pixels
    }

    /// The pixels, row-major, mutable.
    pub fn pixels_mut(&mut self) -> &mut [[f32; 4]] {
        &mut self.pixels
    }

    /// The pixel at `(x, y)`, if inside.
    pub fn get(&self, x: u32, y: u32) -> Option<[f32; 4]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.pixels
            .get(y as usize * self.width as usize + x as usize)
            .copied()
    }

    /// How many pixels have a NaN or infinite channel.
    pub fn count_nonfinite(&self) -> usize {
        self.pixels.iter().filter(|p| !is_finite(p)).count()
    }

    /// Replaces every pixel with a non-finite channel by opaque black; returns how many.
    pub fn sanitize(&mut self) -> usize {
        let mut count = 0;
        for p in &mut self.pixels {
            if !is_finite(p) {
                *p = [0.0, 0.0, 0.0, 1.0];
                count += 1;
            }
        }
        count
    }

    /// A sanitised copy and the number of pixels replaced.
    fn sanitized(&self) -> (Self, usize) {
        let mut copy = self.clone();
        let count = copy.sanitize();
        (copy, count)
    }
}

fn is_finite(p: &[f32; 4]) -> bool {
    p.iter().all(|c| c.is_finite())
}

/// What a writer did besides writing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriteReport {
    /// Pixels with NaN/Inf that were written as black instead.
    pub nonfinite_pixels: usize,
}

/// The curve that maps exposed linear values to `[0, 1]` before sRGB encoding (per channel).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ToneCurve {
    /// `clamp(x, 0, 1)`: exact for values already in range (the default; reference images in
    /// `[0, 1]` round-trip through PNG to 8-bit precision).
    #[default]
    Clamp,
    /// Reinhard's `x / (1 + x)`: never clips, compresses everything.
    Reinhard,
    /// Krzysztof Narkowicz's fit of the ACES filmic curve,
    /// `x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)`, clamped to `[0, 1]`.
    AcesFitted,
}

/// How linear radiance becomes display values for PNG.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ToneMap {
    /// Exposure in stops: values are multiplied by `2^exposure` first.
    pub exposure: f32,
    /// The curve applied after exposure.
    pub curve: ToneCurve,
}

impl ToneMap {
    /// Maps one linear channel value to a display value in `[0, 1]` (before sRGB encoding).
    /// NaN and negative input map to 0, `+inf` to 1.
    pub fn apply(&self, value: f32) -> f32 {
        // `f32::max` drops NaN, so NaN (and negative) input becomes 0 here.
        let x = (value * self.exposure.exp2()).max(0.0);
        if x == f32::INFINITY {
            return 1.0;
        }
        let y = match self.curve {
            ToneCurve::Clamp => x,
            ToneCurve::Reinhard => x / (1.0 + x),
            ToneCurve::AcesFitted => (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14),
        };
        // Huge finite x can overflow the rational curves to inf/inf = NaN; that is saturation.
        if y.is_nan() {
            1.0
        } else {
            y.clamp(0.0, 1.0)
        }
    }
}

/// The sRGB transfer function (linear `[0, 1]` to encoded `[0, 1]`).
pub fn linear_to_srgb(x: f32) -> f32 {
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// The inverse sRGB transfer function (encoded `[0, 1]` to linear).
pub fn srgb_to_linear(x: f32) -> f32 {
    if x <= 0.040_45 {
        x / 12.92
    } else {
        ((x + 0.055) / 1.055).powf(2.4)
    }
}

/// Tone-maps and sRGB-encodes `image` into 8-bit RGB bytes (row-major, 3 per pixel), on a
/// sanitised copy; returns the bytes and the count of non-finite pixels.
pub fn to_srgb8(image: &LinearImage, tone: &ToneMap) -> (Vec<u8>, usize) {
    let (clean, nonfinite) = image.sanitized();
    let mut bytes = Vec::with_capacity(clean.pixels.len() * 3);
    for p in &clean.pixels {
        for &c in &p[..3] {
            let encoded = linear_to_srgb(tone.apply(c));
            // In [0, 255.5) after the clamp in `apply`, so the cast cannot wrap.
            bytes.push((encoded * 255.0 + 0.5).floor().clamp(0.0, 255.0) as u8);
        }
    }
    (bytes, nonfinite)
}

/// Writes `image` as 8-bit sRGB PNG after tone mapping (see the module docs).
pub fn write_png(
    path: impl AsRef<Path>,
    image: &LinearImage,
    tone: &ToneMap,
) -> Result<WriteReport, ImageError> {
    let path = path.as_ref();
    let (bytes, nonfinite_pixels) = to_srgb8(image, tone);
    image::save_buffer_with_format(
        path,
        &bytes,
        image.width,
        image.height,
        image::ExtendedColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(|source| codec_error(path, source))?;
    Ok(WriteReport { nonfinite_pixels })
}

/// Writes `image` as 32-bit float RGBA OpenEXR with linear values (non-finite pixels as black).
pub fn write_exr(path: impl AsRef<Path>, image: &LinearImage) -> Result<WriteReport, ImageError> {
    let path = path.as_ref();
    let (clean, nonfinite_pixels) = image.sanitized();
    let floats: Vec<f32> = clean.pixels.iter().flatten().copied().collect();
    let bytes: &[u8] = bytemuck::cast_slice(&floats);
    image::save_buffer_with_format(
        path,
        bytes,
        image.width,
        image.height,
        image::ExtendedColorType::Rgba32F,
        image::ImageFormat::OpenExr,
    )
    .map_err(|source| codec_error(path, source))?;
    Ok(WriteReport { nonfinite_pixels })
}

/// Reads an EXR, HDR, PNG or JPEG file into linear RGBA (format guessed from the content, then
/// the extension). 8/16-bit formats are decoded from sRGB; float formats are taken as linear.
/// Non-finite values in the file are kept (count them with [`LinearImage::count_nonfinite`]).
pub fn read_image(path: impl AsRef<Path>) -> Result<LinearImage, ImageError> {
    let path = path.as_ref();
    let reader = image::ImageReader::open(path)
        .and_then(image::ImageReader::with_guessed_format)
        .map_err(|source| ImageError::File {
            path: path.to_path_buf(),
            source,
        })?;
    let decoded = reader
        .decode()
        .map_err(|source| codec_error(path, source))?;
    let is_float = matches!(
        decoded.color(),
        image::ColorType::Rgb32F | image::ColorType::Rgba32F
    );
    let rgba = decoded.to_rgba32f();
    let (width, height) = rgba.dimensions();
    let pixels = rgba
        .pixels()
        .map(|p| {
            let [r, g, b, a] = p.0;
            if is_float {
                [r, g, b, a]
            } else {
                [srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a]
            }
        })
        .collect();
    LinearImage::new(width, height, pixels)
}

fn codec_error(path: &Path, source: image::ImageError) -> ImageError {
    ImageError::Codec {
        path: path.to_path_buf(),
        source,
    }
}

/// How far a test image is from a reference (RGB channels of finite pixels only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageMetrics {
    /// Root of the mean squared channel difference.
    pub rmse: f64,
    /// Mean of `(t - r)^2 / (r^2 + REL_MSE_EPSILON)` over channels.
    pub rel_mse: f64,
    /// `10 log10(1 / mse)` for a peak value of 1; infinite for identical images.
    pub psnr: f64,
    /// Largest absolute channel difference.
    pub max_abs_diff: f64,
    /// Pixels compared (finite in both images).
    pub compared_pixels: usize,
    /// Pixels with a non-finite channel in the test image.
    pub nonfinite_test: usize,
    /// Pixels with a non-finite channel in the reference.
    pub nonfinite_reference: usize,
}

/// Compares `test` against `reference`. With no pixel comparable (empty or all non-finite) the
/// error measures are NaN, so any threshold check on them fails.
pub fn compare(test: &LinearImage, reference: &LinearImage) -> Result<ImageMetrics, ImageError> {
    if (test.width, test.height) != (reference.width, reference.height) {
        return Err(ImageError::DimensionMismatch {
            test: (test.width, test.height),
            reference: (reference.width, reference.height),
        });
    }
    let mut sum_sq = 0.0f64;
    let mut sum_rel = 0.0f64;
    let mut max_abs = 0.0f64;
    let mut compared = 0usize;
    for (t, r) in test.pixels.iter().zip(&reference.pixels) {
        if !is_finite(t) || !is_finite(r) {
            continue;
        }
        compared += 1;
        for c in 0..3 {
            let (tv, rv) = (f64::from(t[c]), f64::from(r[c]));
            let d = tv - rv;
            sum_sq += d * d;
            sum_rel += d * d / (rv * rv + REL_MSE_EPSILON);
            max_abs = max_abs.max(d.abs());
        }
    }
    let (rmse, rel_mse, psnr, max_abs_diff) = if compared == 0 {
        (f64::NAN, f64::NAN, f64::NAN, f64::NAN)
    } else {
        let n = (compared * 3) as f64;
        let mse = sum_sq / n;
        let psnr = if mse == 0.0 {
            f64::INFINITY
        } else {
            -10.0 * mse.log10()
        };
        (mse.sqrt(), sum_rel / n, psnr, max_abs)
    };
    Ok(ImageMetrics {
        rmse,
        rel_mse,
        psnr,
        max_abs_diff,
        compared_pixels: compared,
        nonfinite_test: test.count_nonfinite(),
        nonfinite_reference: reference.count_nonfinite(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A path in the system temp dir, unique per process and test; the file is removed when
    /// the guard drops.
    struct TempFile(PathBuf);

    impl TempFile {
        fn new(name: &str) -> Self {
            let file = format!("rtc-runtime-test-{}-{name}", std::process::id());
            Self(std::env::temp_dir().join(file))
        }
    }

    impl Drop for TempFile {
        fn drop(&mut self) {
            let _ = std::fs::remove_file(&self.0);
        }
    }

    impl AsRef<Path> for TempFile {
        fn as_ref(&self) -> &Path {
            &self.0
        }
    }

    fn temp_path(name: &str) -> TempFile {
        TempFile::new(name)
    }

    fn gradient(width: u32, height: u32) -> LinearImage {
        let pixels = (0..width * height)
            .map(|i| {
                let x = (i % width) as f32 / width as f32;
                let y = (i / width) as f32 / height as f32;
                [x, y, 0.25 + 8.0 * x * y, 1.0]
            })
            .collect();
        LinearImage::new(width, height, pixels).expect("sizes match")
    }

    #[test]
    fn exr_round_trip_is_exact() {
        let mut img = gradient(13, 7);
        img.pixels_mut()[5] = [1e-7, 65504.0, 3.5e5, 0.5];
        let path = temp_path("round_trip.exr");
        let report = write_exr(&path, &img).expect("write exr");
        assert_eq!(report.nonfinite_pixels, 0);
        let back = read_image(&path).expect("read exr");
        assert_eq!(back, img);
    }

    #[test]
    fn png_round_trip_within_quantisation() {
        // Values that are exactly representable as 8-bit sRGB survive the round trip.
        let pixels = (0..256u32)
            .map(|i| {
                let v = srgb_to_linear(i as f32 / 255.0);
                [v, srgb_to_linear(((255 - i) as f32) / 255.0), v * 0.0, 1.0]
            })
            .collect();
        let img = LinearImage::new(16, 16, pixels).expect("sizes match");
        let path = temp_path("round_trip.png");
        write_png(&path, &img, &ToneMap::default()).expect("write png");
        let back = read_image(&path).expect("read png");
        assert_eq!((back.width(), back.height()), (16, 16));
        let m = compare(&back, &img).expect("same size");
        assert!(m.max_abs_diff < 1e-6, "{m:?}");

        // An arbitrary gradient is within half an 8-bit sRGB step.
        let img = gradient(31, 9);
        let path = temp_path("gradient.png");
        write_png(&path, &img, &ToneMap::default()).expect("write png");
        let back = read_image(&path).expect("read png");
        for (a, b) in back.pixels().iter().zip(img.pixels()) {
            for c in 0..3 {
                let want = linear_to_srgb(b[c].clamp(0.0, 1.0));
                let got = linear_to_srgb(a[c]);
                assert!((want - got).abs() <= 0.5 / 255.0 + 1e-6, "{a:?} vs {b:?}");
            }
            assert_eq!(a[3], 1.0);
        }
    }

    #[test]
    fn nan_and_inf_never_reach_a_file() {
        let mut img = LinearImage::filled(4, 3, [0.5, 0.5, 0.5, 1.0]);
        img.pixels_mut()[0] = [f32::NAN, 0.5, 0.5, 1.0];
        img.pixels_mut()[5] = [0.5, f32::INFINITY, 0.5, 1.0];
        img.pixels_mut()[11] = [0.5, 0.5, 0.5, f32::NEG_INFINITY];
        assert_eq!(img.count_nonfinite(), 3);

        let exr = temp_path("nan.exr");
        assert_eq!(write_exr(&exr, &img).expect("write").nonfinite_pixels, 3);
        let back = read_image(&exr).expect("read");
        assert_eq!(back.count_nonfinite(), 0);
        assert_eq!(back.pixels()[0], [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(back.pixels()[5], [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(back.pixels()[1], [0.5, 0.5, 0.5, 1.0]);

        let png = temp_path("nan.png");
        let report = write_png(&png, &img, &ToneMap::default()).expect("write");
        assert_eq!(report.nonfinite_pixels, 3);
        let back = read_image(&png).expect("read");
        assert_eq!(back.pixels()[0], [0.0, 0.0, 0.0, 1.0]);

        // The caller's image is untouched; sanitising in place counts the same pixels.
        assert_eq!(img.count_nonfinite(), 3);
        assert_eq!(img.sanitize(), 3);
        assert_eq!(img.count_nonfinite(), 0);
    }

    #[test]
    fn metrics_on_known_inputs() {
        let test = LinearImage::filled(4, 4, [0.5, 0.5, 0.5, 1.0]);
        let reference = LinearImage::filled(4, 4, [0.25, 0.25, 0.25, 0.0]);
        let m = compare(&test, &reference).expect("same size");
        assert_eq!(m.compared_pixels, 16);
        assert!((m.rmse - 0.25).abs() < 1e-12);
        assert!((m.max_abs_diff - 0.25).abs() < 1e-12);
        assert!((m.psnr - 20.0 * 4f64.log10()).abs() < 1e-9, "{}", m.psnr);
        assert!((m.rel_mse - 0.0625 / (0.0625 + REL_MSE_EPSILON)).abs() < 1e-12);

        let same = compare(&test, &test).expect("same size");
        assert_eq!(same.rmse, 0.0);
        assert_eq!(same.psnr, f64::INFINITY);
        assert_eq!(same.rel_mse, 0.0);

        // One pixel off by 1 in one channel of 4 pixels: mse = 1 / 12.
        let a = LinearImage::filled(2, 2, [0.0; 4]);
        let mut b = a.clone();
        b.pixels_mut()[3][1] = 1.0;
        let m = compare(&b, &a).expect("same size");
        assert!((m.rmse - (1.0f64 / 12.0).sqrt()).abs() < 1e-12);
        assert!((m.rel_mse - (1.0 / REL_MSE_EPSILON) / 12.0).abs() < 1e-9);
        assert_eq!(m.max_abs_diff, 1.0);

        // Non-finite pixels are skipped and counted.
        let mut c = a.clone();
        c.pixels_mut()[0][0] = f32::NAN;
        let m = compare(&c, &a).expect("same size");
        assert_eq!(
            (m.compared_pixels, m.nonfinite_test, m.nonfinite_reference),
            (3, 1, 0)
        );
        assert_eq!(m.rmse, 0.0);

        let all_nan = LinearImage::filled(1, 1, [f32::NAN; 4]);
        assert!(compare(&all_nan, &all_nan)
            .expect("same size")
            .rmse
            .is_nan());
        assert!(matches!(
            compare(&a, &LinearImage::filled(3, 2, [0.0; 4])),
            Err(ImageError::DimensionMismatch { .. })
        ));
    }

    #[test]
    fn tone_curves_are_monotonic_and_bounded() {
        for curve in [ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::AcesFitted] {
            let tone = ToneMap {
                exposure: 0.0,
                curve,
            };
            let mut last = -1.0;
            for i in 0..=400 {
                let y = tone.apply(i as f32 * 0.05);
                assert!((0.0..=1.0).contains(&y), "{curve:?}: {y}");
                assert!(y >= last, "{curve:?} not monotonic at {i}");
                last = y;
            }
            assert_eq!(tone.apply(f32::NAN), 0.0);
            assert_eq!(tone.apply(-3.0), 0.0);
        }
        let clamp = ToneMap::default();
        assert_eq!(clamp.apply(0.3), 0.3);
        assert_eq!(clamp.apply(7.0), 1.0);
        let one_stop = ToneMap {
            exposure: 1.0,
            curve: ToneCurve::Clamp,
        };
        assert_eq!(one_stop.apply(0.25), 0.5);
        let reinhard = ToneMap {
            exposure: 0.0,
            curve: ToneCurve::Reinhard,
        };
        assert_eq!(reinhard.apply(1.0), 0.5);
        assert_eq!(reinhard.apply(f32::INFINITY), 1.0);
        assert_eq!(reinhard.apply(f32::MAX), 1.0);
        let aces = ToneMap {
            exposure: 0.0,
            curve: ToneCurve::AcesFitted,
        };
        assert_eq!(aces.apply(f32::MAX), 1.0);
    }

    #[test]
    fn srgb_transfer_round_trips() {
        for i in 0..=255 {
            let e = i as f32 / 255.0;
            assert!((linear_to_srgb(srgb_to_linear(e)) - e).abs() < 1e-6);
        }
        assert_eq!(linear_to_srgb(0.0), 0.0);
        assert!((linear_to_srgb(1.0) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn accumulation_resolves_to_means() {
        let acc = [[2.0, 4.0, 6.0, 2.0], [1.0, 1.0, 1.0, 0.0], [9.0; 4]];
        let img = LinearImage::from_accumulation(2, 1, &acc).expect("enough entries");
        assert_eq!(img.pixels(), &[[1.0, 2.0, 3.0, 1.0], [0.0, 0.0, 0.0, 1.0]]);
        assert!(LinearImage::from_accumulation(2, 2, &acc).is_err());
        assert!(LinearImage::new(2, 2, vec![[0.0; 4]; 3]).is_err());
        assert_eq!(img.get(1, 0), Some([0.0, 0.0, 0.0, 1.0]));
        assert_eq!(img.get(2, 0), None);
    }
}
