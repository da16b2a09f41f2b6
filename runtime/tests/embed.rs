//! Embedding rtc in a host wgpu application: a [`Gpu`] on the test's own device
//! ([`Gpu::from_device`]), and the accumulation resolved on the GPU into textures and buffers the
//! test owns ([`Renderer::resolve_into`], [`Resolver`]), read back and compared with the CPU path
//! (`LinearImage` and `to_srgb8`, what `rtc render` writes to EXR and PNG).
//!
//! Tolerances: the 8-bit targets within 1 per channel of the PNG's bytes (the GPU's `pow` may land
//! on the other side of a rounding boundary); `rgba16float` within half precision of the linear
//! image: one step of half precision (relative 2^-10, as Vulkan lets a driver round toward zero,
//! lavapipe does; plus 1e-7 absolute for half's subnormals); `rgba32float` and the `f32`
//! buffer within 4 ulp-scale relative error (1e-6: the GPU's division need not round exactly).

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::SceneFile;
use common::temp_dir;
use rtc_compiler::sema::hir::{ConstValue, Scalar};
use rtc_runtime::gpu::{required_limits, FromDeviceError, Gpu, GpuOptions, PipelineCacheConfig};
use rtc_runtime::image_out::{to_srgb8, LinearImage, ToneCurve, ToneMap};
use rtc_runtime::render::{FieldTarget, RenderError, RenderOptions, Renderer};
use rtc_runtime::resolve::{BufferFormat, ResolveError, ResolveTarget, Resolver};

/// The host's side: an adapter, and a device created with `limits`; `None` (with a `SKIPPED`
/// line) when there is no adapter at all.
fn host_device(
    test: &str,
    limits: wgpu::Limits,
) -> Option<(wgpu::Adapter, wgpu::Device, wgpu::Queue)> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        match pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
        {
            Ok(a) => a,
            Err(e) => {
                eprintln!("SKIPPED {test}: no GPU adapter at all: {e}");
                return None;
            }
        };
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("host device"),
        required_limits: limits,
        ..wgpu::DeviceDescriptor::default()
    }))
    .expect("the host's device");
    eprintln!("{test}: running on {}", adapter.get_info().name);
    Some((adapter, device, queue))
}

/// A [`Gpu`] on a host device with [`required_limits`].
fn host_gpu(test: &str) -> Option<Gpu> {
    let (adapter, device, queue) = host_device(test, required_limits())?;
    let options = GpuOptions {
        pipeline_cache: PipelineCacheConfig::Off,
    };
    Some(Gpu::from_device(adapter, device, queue, &options).expect("from_device"))
}

/// A texture the host owns, written by the resolve and copied out by the test.
fn target_texture(
    gpu: &Gpu,
    [width, height]: [u32; 2],
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    gpu.device().create_texture(&wgpu::TextureDescriptor {
        label: Some("host target"),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

/// Maps `buffer` (MAP_READ) and returns its bytes.
fn map_bytes(gpu: &Gpu, buffer: &wgpu::Buffer) -> Vec<u8> {
    let slice = buffer.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map"));
    gpu.wait_idle().expect("poll");
    let bytes = slice.get_mapped_range().expect("mapped").to_vec();
    buffer.unmap();
    bytes
}

/// The rows of `texture` (`bytes_per_pixel` each pixel), tightly packed, after `encoder`'s commands.
fn read_texture(
    gpu: &Gpu,
    mut encoder: wgpu::CommandEncoder,
    texture: &wgpu::Texture,
    bytes_per_pixel: u32,
) -> Vec<u8> {
    let (width, height) = (texture.width(), texture.height());
    let row = width * bytes_per_pixel;
    let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let staging = gpu.device().create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: u64::from(padded) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: Some(height),
            },
        },
        texture.size(),
    );
    gpu.queue().submit([encoder.finish()]);
    let bytes = map_bytes(gpu, &staging);
    bytes
        .chunks(padded as usize)
        .flat_map(|r| r[..row as usize].to_vec())
        .collect()
}

/// The contents of a STORAGE buffer, copied out after `encoder`'s commands.
fn read_buffer(gpu: &Gpu, mut encoder: wgpu::CommandEncoder, buffer: &wgpu::Buffer) -> Vec<u8> {
    let staging = gpu.device().create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: buffer.size(),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
    gpu.queue().submit([encoder.finish()]);
    map_bytes(gpu, &staging)
}

fn encoder(gpu: &Gpu) -> wgpu::CommandEncoder {
    gpu.device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("host"),
        })
}

/// Asserts `got` (RGBA bytes) within 1 of the PNG's bytes for `image` (alpha 255).
fn assert_srgb8(what: &str, got: &[u8], image: &LinearImage, tone: &ToneMap) {
    let (want, _) = to_srgb8(image, tone);
    assert_eq!(got.len() / 4, want.len() / 3, "{what}: pixel count");
    let mut check = PixelCheck::new(what);
    let width = image.width();
    for (i, (g, w)) in got.chunks(4).zip(want.chunks(3)).enumerate() {
        let at = ((i as u32) % width, (i as u32) / width);
        for c in 0..3 {
            check.channel(at, c, f64::from(g[c]), f64::from(w[c]), Tolerance::abs(1.0));
        }
        check.channel(at, 3, f64::from(g[3]), 255.0, Tolerance::EXACT);
    }
    check.assert();
}

/// Asserts `got` (RGBA floats) against the linear image within `tol`, alpha 1.
fn assert_linear(what: &str, got: &[[f32; 4]], image: &LinearImage, tol: Tolerance) {
    assert_eq!(got.len(), image.pixels().len(), "{what}: pixel count");
    let mut check = PixelCheck::new(what);
    let width = image.width();
    for (i, (g, w)) in got.iter().zip(image.pixels()).enumerate() {
        let at = ((i as u32) % width, (i as u32) / width);
        let want: Vec<f64> = w.iter().map(|&c| f64::from(c)).collect();
        check.pixel(at, *g, &want, tol);
    }
    check.assert();
}

fn f32s(bytes: &[u8]) -> Vec<[f32; 4]> {
    bytemuck::cast_slice::<u8, f32>(bytes)
        .chunks(4)
        .map(|c| [c[0], c[1], c[2], c[3]])
        .collect()
}

fn f16s(bytes: &[u8]) -> Vec<[f32; 4]> {
    bytemuck::cast_slice::<u8, u16>(bytes)
        .chunks(4)
        .map(|c| std::array::from_fn(|i| half::f16::from_bits(c[i]).to_f32()))
        .collect()
}

const HALF: Tolerance = Tolerance {
    abs: 1e-7,
    rel: 1.0 / 1024.0,
};
const SINGLE: Tolerance = Tolerance {
    abs: 1e-9,
    rel: 1e-6,
};

#[test]
fn a_render_resolves_into_host_textures_and_buffers_as_the_cpu_path_writes_it() {
    let Some(gpu) = host_gpu("resolve") else {
        return;
    };
    let dir = temp_dir("embed", "resolve");
    let compiled = SceneFile::open("embed/lit_quad.rt").compile(&dir);
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let image = renderer.render(&mut |_, _| {}).expect("render").image;
    let size = renderer.size();
    assert_eq!(size, [19, 13]);
    let above_one = image
        .pixels()
        .iter()
        .filter(|p| p[..3].iter().any(|&c| c > 1.0))
        .count();
    let below_one = image
        .pixels()
        .iter()
        .filter(|p| p[..3].iter().all(|&c| c < 1.0))
        .count();
    assert!(
        above_one > 0 && below_one > 0,
        "the scene must test clamping: {above_one} pixels above 1, {below_one} below"
    );

    // rgba8unorm, recorded into the host's encoder, with the default tone map and a non-trivial one.
    for tone in [
        ToneMap::default(),
        ToneMap {
            exposure: -1.5,
            curve: ToneCurve::AcesFitted,
        },
        ToneMap {
            exposure: 0.5,
            curve: ToneCurve::Reinhard,
        },
    ] {
        let texture = target_texture(&gpu, size, wgpu::TextureFormat::Rgba8Unorm);
        let mut enc = encoder(&gpu);
        renderer
            .resolve_into(ResolveTarget::Texture(&texture), &tone, Some(&mut enc))
            .expect("resolve rgba8unorm");
        let got = read_texture(&gpu, enc, &texture, 4);
        assert_srgb8(
            &format!("rgba8unorm texture, {tone:?}"),
            &got,
            &image,
            &tone,
        );
    }

    // rgba16float and rgba32float, submitted by the renderer itself (no encoder).
    let tone = ToneMap::default();
    let texture = target_texture(&gpu, size, wgpu::TextureFormat::Rgba16Float);
    renderer
        .resolve_into(ResolveTarget::Texture(&texture), &tone, None)
        .expect("resolve rgba16float");
    let got = f16s(&read_texture(&gpu, encoder(&gpu), &texture, 8));
    assert_linear("rgba16float texture", &got, &image, HALF);
    let texture = target_texture(&gpu, size, wgpu::TextureFormat::Rgba32Float);
    renderer
        .resolve_into(ResolveTarget::Texture(&texture), &tone, None)
        .expect("resolve rgba32float");
    let got = f32s(&read_texture(&gpu, encoder(&gpu), &texture, 16));
    assert_linear("rgba32float texture", &got, &image, SINGLE);

    // Buffers, at an aligned offset.
    let offset = u64::from(gpu.device().limits().min_storage_buffer_offset_alignment);
    let pixels = u64::from(size[0] * size[1]);
    for format in [BufferFormat::Srgb8, BufferFormat::LinearF32] {
        let buffer = gpu.device().create_buffer(&wgpu::BufferDescriptor {
            label: Some("host buffer"),
            size: offset + pixels * format.bytes_per_pixel(),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let mut enc = encoder(&gpu);
        renderer
            .resolve_into(
                ResolveTarget::Buffer {
                    buffer: &buffer,
                    offset,
                    format,
                },
                &tone,
                Some(&mut enc),
            )
            .expect("resolve into a buffer");
        let bytes = read_buffer(&gpu, enc, &buffer);
        let got = &bytes[offset as usize..];
        match format {
            BufferFormat::Srgb8 => assert_srgb8("sRGB8 buffer", got, &image, &tone),
            BufferFormat::LinearF32 => assert_linear("f32 buffer", &f32s(got), &image, SINGLE),
        }
    }
    assert!(gpu.take_uncaptured_errors().is_empty());
}

/// The resolve reads the running accumulation: after a camera move and two `accumulate(1)` calls
/// it shows the same two-sample average that `image()` reads back.
#[test]
fn the_resolve_follows_the_running_accumulation() {
    let Some(gpu) = host_gpu("running accumulation") else {
        return;
    };
    let dir = temp_dir("embed", "running");
    let compiled = SceneFile::open("embed/lit_quad.rt").compile(&dir);
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    renderer.accumulate(1, &mut |_, _| {}).expect("first pass");
    let before = renderer.image().expect("image");
    let moved = ConstValue::Vector {
        len: 3,
        comps: [
            Scalar::F32(0.4),
            Scalar::F32(1.8),
            Scalar::F32(0.3),
            Scalar::F32(0.0),
        ],
    };
    renderer
        .set_field(FieldTarget::Camera, "position", &moved)
        .expect("move the camera");
    for _ in 0..2 {
        renderer.accumulate(1, &mut |_, _| {}).expect("pass");
    }
    assert_eq!(renderer.accumulated_samples(), 2);
    let image = renderer.image().expect("image");
    assert_ne!(image, before, "the camera move changed nothing");
    let texture = target_texture(&gpu, renderer.size(), wgpu::TextureFormat::Rgba32Float);
    let mut enc = encoder(&gpu);
    renderer
        .resolve_into(
            ResolveTarget::Texture(&texture),
            &ToneMap::default(),
            Some(&mut enc),
        )
        .expect("resolve");
    let got = f32s(&read_texture(&gpu, enc, &texture, 16));
    assert_linear("running accumulation", &got, &image, SINGLE);
}

/// Accumulation values the scene cannot make: no samples, NaN and infinite sums, a NaN count,
/// huge and tiny values, negatives; resolved by a bare [`Resolver`] against the CPU path.
#[test]
fn the_resolve_pass_treats_edge_values_as_the_cpu_path_does() {
    let Some(gpu) = host_gpu("edge values") else {
        return;
    };
    let nan = f32::NAN;
    let inf = f32::INFINITY;
    let accum: Vec<[f32; 4]> = vec![
        [0.0, 0.0, 0.0, 0.0],
        [1.0, 2.0, 3.0, 0.0],
        [nan, 0.5, 0.5, 1.0],
        [inf, 0.5, 0.5, 2.0],
        [0.5, 0.5, 0.5, nan],
        [-1.0, 0.25, 0.5, 1.0],
        [3e38, 3e38, 1e-30, 1.0],
        [0.002, 0.0031308, 0.004, 1.0],
        [0.5, 0.7, 0.9, 3.0],
        [1e6, 2.0, 0.999, 4.0],
        [0.0, 0.0, 0.0, inf],
        [0.1, 0.2, 0.3, 1e-40],
    ];
    let size = [4, 3];
    let image = LinearImage::from_accumulation(size[0], size[1], &accum).expect("image");
    let device = gpu.device();
    let accum_buffer = wgpu::util::DeviceExt::create_buffer_init(
        device,
        &wgpu::util::BufferInitDescriptor {
            label: Some("accum"),
            contents: bytemuck::cast_slice(&accum),
            usage: wgpu::BufferUsages::STORAGE,
        },
    );
    let resolver = Resolver::new();
    for tone in [
        ToneMap::default(),
        ToneMap {
            exposure: 2.0,
            curve: ToneCurve::AcesFitted,
        },
        ToneMap {
            exposure: 0.0,
            curve: ToneCurve::Reinhard,
        },
    ] {
        let texture = target_texture(&gpu, size, wgpu::TextureFormat::Rgba8Unorm);
        let mut enc = encoder(&gpu);
        resolver
            .encode(
                &gpu,
                &mut enc,
                &accum_buffer,
                size,
                ResolveTarget::Texture(&texture),
                &tone,
            )
            .expect("resolve");
        let got = read_texture(&gpu, enc, &texture, 4);
        assert_srgb8(&format!("edge values, {tone:?}"), &got, &image, &tone);
    }
    let mut clean = image.clone();
    clean.sanitize();
    let texture = target_texture(&gpu, size, wgpu::TextureFormat::Rgba32Float);
    let mut enc = encoder(&gpu);
    resolver
        .encode(
            &gpu,
            &mut enc,
            &accum_buffer,
            size,
            ResolveTarget::Texture(&texture),
            &ToneMap::default(),
        )
        .expect("resolve");
    let got = f32s(&read_texture(&gpu, enc, &texture, 16));
    assert_linear("edge values, linear", &got, &clean, SINGLE);
}

#[test]
fn bad_targets_are_typed_errors_before_anything_is_recorded() {
    let Some(gpu) = host_gpu("bad targets") else {
        return;
    };
    let dir = temp_dir("embed", "bad_targets");
    let compiled = SceneFile::open("embed/lit_quad.rt")
        .set("SAMPLES", "1u")
        .compile(&dir);
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    renderer.render(&mut |_, _| {}).expect("render");
    let tone = ToneMap::default();
    let resolve = |target| match renderer.resolve_into(target, &tone, None) {
        Err(RenderError::Resolve(e)) => e,
        other => panic!("expected a resolve error, got {other:?}"),
    };

    let wrong_size = target_texture(&gpu, [8, 8], wgpu::TextureFormat::Rgba8Unorm);
    let e = resolve(ResolveTarget::Texture(&wrong_size));
    assert!(
        matches!(
            e,
            ResolveError::SizeMismatch {
                target: [8, 8],
                image: [19, 13]
            }
        ),
        "{e}"
    );

    let srgb = gpu.device().create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: 19,
            height: 13,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8UnormSrgb,
        usage: wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    let e = resolve(ResolveTarget::Texture(&srgb));
    assert!(matches!(e, ResolveError::UnsupportedFormat { .. }), "{e}");
    assert!(e.to_string().contains("help: use Rgba8Unorm"), "{e}");

    let sampled_only = gpu.device().create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: srgb.size(),
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba16Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    let e = resolve(ResolveTarget::Texture(&sampled_only));
    assert!(
        matches!(
            e,
            ResolveError::MissingUsage {
                what: "texture",
                ..
            }
        ),
        "{e}"
    );

    let short = gpu.device().create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 19 * 13 * 4 - 4,
        usage: wgpu::BufferUsages::STORAGE,
        mapped_at_creation: false,
    });
    let e = resolve(ResolveTarget::Buffer {
        buffer: &short,
        offset: 0,
        format: BufferFormat::Srgb8,
    });
    assert!(matches!(e, ResolveError::BufferTooSmall { .. }), "{e}");
    let e = resolve(ResolveTarget::Buffer {
        buffer: &short,
        offset: 4,
        format: BufferFormat::Srgb8,
    });
    assert!(
        matches!(e, ResolveError::Misaligned { offset: 4, .. }),
        "{e}"
    );
    assert!(gpu.take_uncaptured_errors().is_empty());
}

/// A device created with wgpu's downlevel limits has room for 4 storage buffers, half of what a
/// kernel binds: `from_device` names that limit instead of failing later in pipeline creation.
#[test]
fn a_device_below_the_required_limits_is_refused_with_what_it_lacks() {
    let Some((adapter, device, queue)) = host_device("limits", wgpu::Limits::downlevel_defaults())
    else {
        return;
    };
    let options = GpuOptions {
        pipeline_cache: PipelineCacheConfig::Off,
    };
    match Gpu::from_device(adapter, device, queue, &options) {
        Err(e @ FromDeviceError::Unsupported { .. }) => {
            let text = e.to_string();
            assert!(
                text.contains("`max_storage_buffers_per_shader_stage` is 4, rtc needs at least 8"),
                "{text}"
            );
        }
        Ok(_) => panic!("a device with 4 storage buffers per stage was accepted"),
    }
}

/// wgpu keeps one uncaptured-error handler per device and cannot chain them: `from_device` leaves
/// the host's in place (errors outside any scope reach the host, not rtc), and
/// `record_uncaptured_errors` replaces it with rtc's recording one when the host asks.
#[test]
fn the_hosts_uncaptured_error_handler_stays_until_the_host_opts_in() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;
    let Some((adapter, device, queue)) = host_device("uncaptured errors", required_limits()) else {
        return;
    };
    let host_errors = Arc::new(AtomicUsize::new(0));
    let sink = Arc::clone(&host_errors);
    device.on_uncaptured_error(Arc::new(move |_| {
        sink.fetch_add(1, Ordering::SeqCst);
    }));
    let options = GpuOptions {
        pipeline_cache: PipelineCacheConfig::Off,
    };
    let gpu = Gpu::from_device(adapter, device.clone(), queue, &options).expect("from_device");
    // An invalid buffer (MAP_READ may only go with COPY_DST), outside any error scope.
    let invalid = |label| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: 16,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        })
    };
    let _first = invalid("invalid, for the host");
    assert_eq!(host_errors.load(Ordering::SeqCst), 1);
    assert!(gpu.take_uncaptured_errors().is_empty());

    gpu.record_uncaptured_errors();
    let _second = invalid("invalid, for rtc");
    assert_eq!(host_errors.load(Ordering::SeqCst), 1);
    let recorded = gpu.take_uncaptured_errors();
    assert_eq!(recorded.len(), 1, "{recorded:?}");
}
