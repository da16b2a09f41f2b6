//! Resolving the accumulation buffer on the GPU, into a texture or buffer a host application owns:
//! the image of a render without reading it back ([`Resolver`], used by
//! [`crate::render::Renderer::resolve_into`]).
//!
//! The input is an accumulation buffer as the kernels write it: per pixel a `vec4<f32>` (rgb =
//! radiance sum, a = sample count), row-major, `width * height` entries. One compute dispatch
//! (8 x 8 workgroups, one invocation per pixel) writes the target; the host records it into its
//! own command encoder, or the resolver submits it alone. Nothing blocks and nothing is read back.
//!
//! Targets and what they receive ([`ResolveTarget`]):
//! - an `rgba8unorm` storage texture or a buffer of packed `u32`s ([`BufferFormat::Srgb8`]): the
//!   bytes `rtc render` writes to PNG ([`crate::image_out::to_srgb8`]): the mean (`rgb / a`, black
//!   without samples), a pixel with any non-finite channel black, then the [`ToneMap`] (exposure,
//!   curve), the sRGB transfer function in the shader, and rounding to the nearest of 256 levels;
//!   alpha 255. The GPU's `pow` may differ from the CPU's in the last bits, so a byte can differ by
//!   1 where the value lies on a rounding boundary.
//! - an `rgba16float` or `rgba32float` storage texture, or a buffer of `vec4<f32>`
//!   ([`BufferFormat::LinearF32`]): the linear mean as [`crate::image_out::LinearImage`] holds it
//!   after sanitising (non-finite pixels black), alpha 1, no tone mapping (the values EXR gets).
//!   `rgba16float` rounds to half precision (relative error below 2^-10: Vulkan lets drivers
//!   round toward zero; values above 65504 become infinite).
//!
//! Guarantees: a target of the wrong format, size or usage, a misaligned or short buffer, and a
//! short accumulation buffer are typed [`ResolveError`]s found before anything is recorded;
//! everything stays within WebGPU's default limits (one uniform, one storage buffer read, one
//! storage texture or buffer written).

#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing
    )
)]

use std::num::NonZeroU64;
use std::sync::{Arc, Mutex, PoisonError};

use wgpu::util::DeviceExt;

use crate::gpu::Gpu;
use crate::image_out::{ToneCurve, ToneMap};

/// Where a resolve writes.
#[derive(Clone, Copy, Debug)]
pub enum ResolveTarget<'a> {
    /// A 2D texture of exactly the image's size with `TextureUsages::STORAGE_BINDING`, of format
    /// `Rgba8Unorm` (display bytes) or `Rgba16Float` / `Rgba32Float` (linear); mip level 0 and
    /// array layer 0 are written.
    Texture(&'a wgpu::Texture),
    /// A buffer with `BufferUsages::STORAGE`: `width * height` pixels, row-major, from `offset`
    /// (a multiple of the device's `min_storage_buffer_offset_alignment`, 256 by default).
    Buffer {
        /// The buffer.
        buffer: &'a wgpu::Buffer,
        /// Where the first pixel goes, in bytes.
        offset: u64,
        /// What each pixel becomes.
        format: BufferFormat,
    },
}

/// The pixel format of a [`ResolveTarget::Buffer`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BufferFormat {
    /// 4 bytes a pixel, R, G, B, A in memory order: the PNG's sRGB bytes, alpha 255.
    Srgb8,
    /// 16 bytes a pixel: the linear mean as four `f32`, alpha 1.
    LinearF32,
}

impl BufferFormat {
    /// Bytes per pixel.
    pub fn bytes_per_pixel(self) -> u64 {
        match self {
            Self::Srgb8 => 4,
            Self::LinearF32 => 16,
        }
    }
}

/// Why a resolve could not be recorded.
#[derive(Debug, thiserror::Error)]
pub enum ResolveError {
    /// The texture's format cannot be written by the resolve pass.
    #[error(
        "cannot resolve into a {format:?} texture\nhelp: use Rgba8Unorm (sRGB-encoded display \
         bytes), Rgba16Float or Rgba32Float (linear); sRGB formats cannot be storage textures"
    )]
    UnsupportedFormat {
        /// The texture's format.
        format: wgpu::TextureFormat,
    },
    /// The target was created without the usage the pass needs.
    #[error("the resolve target {what} lacks {usage} usage\nhelp: add {usage} to its usages")]
    MissingUsage {
        /// `texture` or `buffer`.
        what: &'static str,
        /// The usage flag, as wgpu names it.
        usage: &'static str,
    },
    /// The texture is not a single-sampled 2D texture.
    #[error("cannot resolve into a {dimension:?} texture with {samples} samples: it must be 2D with 1 sample")]
    NotTwoDimensional {
        /// Its dimension.
        dimension: wgpu::TextureDimension,
        /// Its sample count.
        samples: u32,
    },
    /// The texture's size is not the image's.
    #[error(
        "the resolve target is {}x{}, the image {}x{}\nhelp: create the texture with the \
         renderer's size (`Renderer::size`)",
        target[0], target[1], image[0], image[1]
    )]
    SizeMismatch {
        /// The texture's width and height.
        target: [u32; 2],
        /// The image's.
        image: [u32; 2],
    },
    /// The buffer region is too short for the image.
    #[error("the resolve buffer holds {have} bytes from offset {offset}, the image needs {need}")]
    BufferTooSmall {
        /// Bytes from `offset` to the buffer's end.
        have: u64,
        /// Bytes the image needs.
        need: u64,
        /// The offset asked for.
        offset: u64,
    },
    /// The buffer offset is not aligned as storage bindings must be.
    #[error("the resolve buffer offset {offset} is not a multiple of {alignment} (the device's min_storage_buffer_offset_alignment)")]
    Misaligned {
        /// The offset asked for.
        offset: u64,
        /// The device's alignment.
        alignment: u32,
    },
    /// The accumulation buffer is shorter than `width * height` pixels.
    #[error("the accumulation buffer holds {have} bytes, a {width}x{height} image needs {need}")]
    AccumulationTooSmall {
        /// Its size in bytes.
        have: u64,
        /// Bytes needed.
        need: u64,
        /// Image width.
        width: u32,
        /// Image height.
        height: u32,
    },
    /// The image is larger than one storage binding of the device may be.
    #[error("a {width}x{height} image needs {need} bytes in one storage binding, the device allows {limit}")]
    TooLarge {
        /// Image width.
        width: u32,
        /// Image height.
        height: u32,
        /// Bytes needed.
        need: u64,
        /// The device's `max_storage_buffer_binding_size`.
        limit: u64,
    },
    /// The kernel declares no accumulation buffer, so there is nothing to resolve.
    #[error("internal error: the render kernel declares no `accum` buffer")]
    NoAccumulation,
    /// wgpu rejected the pass's pipeline or bind group.
    #[error("wgpu error while recording the resolve pass: {0}")]
    Wgpu(String),
}

/// The kinds of output, one pipeline each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Output {
    Rgba8Texture,
    Rgba16FloatTexture,
    Rgba32FloatTexture,
    Srgb8Buffer,
    LinearBuffer,
}

impl Output {
    const ALL: [Output; 5] = [
        Output::Rgba8Texture,
        Output::Rgba16FloatTexture,
        Output::Rgba32FloatTexture,
        Output::Srgb8Buffer,
        Output::LinearBuffer,
    ];

    fn index(self) -> usize {
        Self::ALL.iter().position(|o| *o == self).unwrap_or(0)
    }

    /// The WGSL declaration of the output at binding 2, and the statement that stores pixel
    /// `i` at `xy` (`mean`: the sanitised linear mean; `display`: the PNG's bytes as `vec3<u32>`).
    fn wgsl(self) -> (&'static str, &'static str) {
        match self {
            Output::Rgba8Texture => (
                "@group(0) @binding(2) var target_tex: texture_storage_2d<rgba8unorm, write>;",
                "textureStore(target_tex, xy, vec4<f32>(vec3<f32>(display(m)) / 255.0, 1.0));",
            ),
            Output::Rgba16FloatTexture => (
                "@group(0) @binding(2) var target_tex: texture_storage_2d<rgba16float, write>;",
                "textureStore(target_tex, xy, vec4<f32>(m, 1.0));",
            ),
            Output::Rgba32FloatTexture => (
                "@group(0) @binding(2) var target_tex: texture_storage_2d<rgba32float, write>;",
                "textureStore(target_tex, xy, vec4<f32>(m, 1.0));",
            ),
            Output::Srgb8Buffer => (
                "@group(0) @binding(2) var<storage, read_write> target_buf: array<u32>;",
                "let b = display(m); target_buf[i] = b.r | (b.g << 8u) | (b.b << 16u) | 0xff000000u;",
            ),
            Output::LinearBuffer => (
                "@group(0) @binding(2) var<storage, read_write> target_buf: array<vec4<f32>>;",
                "target_buf[i] = vec4<f32>(m, 1.0);",
            ),
        }
    }

    fn binding_type(self) -> wgpu::BindingType {
        let texture = |format| wgpu::BindingType::StorageTexture {
            access: wgpu::StorageTextureAccess::WriteOnly,
            format,
            view_dimension: wgpu::TextureViewDimension::D2,
        };
        let buffer = wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: false },
            has_dynamic_offset: false,
            min_binding_size: None,
        };
        match self {
            Output::Rgba8Texture => texture(wgpu::TextureFormat::Rgba8Unorm),
            Output::Rgba16FloatTexture => texture(wgpu::TextureFormat::Rgba16Float),
            Output::Rgba32FloatTexture => texture(wgpu::TextureFormat::Rgba32Float),
            Output::Srgb8Buffer | Output::LinearBuffer => buffer,
        }
    }
}

/// The shader, with `{OUTPUT}` and `{STORE}` filled in per [`Output`]. The tone curve and the
/// sanitising follow `image_out::ToneMap::apply` and `LinearImage::sanitize` step by step.
const SHADER: &str = r"
struct Params {
    width: u32,
    height: u32,
    // 2^exposure, computed on the CPU as ToneMap::apply does.
    scale: f32,
    // 0 clamp, 1 Reinhard, 2 ACES fitted.
    curve: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> accum: array<vec4<f32>>;
{OUTPUT}

// Decided on the bits: compilers may assume floats are finite and fold `x != x`.
fn is_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// The mean of pixel i; black without samples or with a non-finite channel.
fn mean(i: u32) -> vec3<f32> {
    let s = accum[i];
    if s.a > 0.0 {
        let m = s.rgb / s.a;
        if is_finite(m.r) && is_finite(m.g) && is_finite(m.b) {
            return m;
        }
    }
    return vec3<f32>(0.0);
}

// ToneMap::apply for a finite value.
fn tone(v: f32) -> f32 {
    let x = max(v * params.scale, 0.0);
    if !is_finite(x) {
        return 1.0;
    }
    var y = x;
    if params.curve == 1u {
        y = x / (1.0 + x);
    } else if params.curve == 2u {
        y = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    }
    if !is_finite(y) {
        return 1.0;
    }
    return clamp(y, 0.0, 1.0);
}

fn linear_to_srgb(x: f32) -> f32 {
    if x <= 0.0031308 {
        return 12.92 * x;
    }
    return 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// The 8-bit sRGB value of one channel, as to_srgb8 rounds it.
fn byte(v: f32) -> u32 {
    return u32(clamp(floor(linear_to_srgb(tone(v)) * 255.0 + 0.5), 0.0, 255.0));
}

fn display(m: vec3<f32>) -> vec3<u32> {
    return vec3<u32>(byte(m.r), byte(m.g), byte(m.b));
}

@compute @workgroup_size(8, 8)
fn resolve(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= params.width || id.y >= params.height {
        return;
    }
    let i = id.y * params.width + id.x;
    let xy = vec2<i32>(id.xy);
    let m = mean(i);
    {STORE}
}
";

/// The uniform of one resolve (16 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct Params {
    width: u32,
    height: u32,
    scale: f32,
    curve: u32,
}

/// A created resolve pipeline.
#[derive(Debug)]
struct Pipeline {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::ComputePipeline,
}

/// The resolve pass: one small compute pipeline per target kind, created on first use and kept.
#[derive(Debug, Default)]
pub struct Resolver {
    pipelines: Mutex<[Option<Arc<Pipeline>>; 5]>,
}

impl Resolver {
    /// A resolver with no pipeline yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Records the resolve of `accumulation` (a `width x height` image, see the module docs)
    /// into `target` on `encoder`, tone-mapping display targets with `tone`. The host submits
    /// the encoder; the pass reads `accumulation` as it is when the commands run.
    pub fn encode(
        &self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        accumulation: &wgpu::Buffer,
        [width, height]: [u32; 2],
        target: ResolveTarget<'_>,
        tone: &ToneMap,
    ) -> Result<(), ResolveError> {
        let pixels = u64::from(width) * u64::from(height);
        let limit = gpu.limits().max_storage_buffer_binding_size;
        let need = pixels * 16;
        if need > accumulation.size() {
            return Err(ResolveError::AccumulationTooSmall {
                have: accumulation.size(),
                need,
                width,
                height,
            });
        }
        if need > limit {
            return Err(ResolveError::TooLarge {
                width,
                height,
                need,
                limit,
            });
        }
        let (output, view) = match target {
            ResolveTarget::Texture(texture) => {
                let output = texture_output(texture, [width, height])?;
                let view = texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("rtc resolve target"),
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_mip_level: 0,
                    mip_level_count: Some(1),
                    base_array_layer: 0,
                    array_layer_count: Some(1),
                    ..wgpu::TextureViewDescriptor::default()
                });
                (output, Some(view))
            }
            ResolveTarget::Buffer {
                buffer,
                offset,
                format,
            } => {
                check_buffer(gpu, buffer, offset, format, [width, height])?;
                let output = match format {
                    BufferFormat::Srgb8 => Output::Srgb8Buffer,
                    BufferFormat::LinearF32 => Output::LinearBuffer,
                };
                (output, None)
            }
        };
        let pipeline = self.pipeline(gpu, output)?;
        let params = Params {
            width,
            height,
            scale: tone.exposure.exp2(),
            curve: match tone.curve {
                ToneCurve::Clamp => 0,
                ToneCurve::Reinhard => 1,
                ToneCurve::AcesFitted => 2,
            },
        };
        let device = gpu.device();
        let (bind_group, error) = gpu.scoped(|| {
            let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("rtc resolve params"),
                contents: bytemuck::bytes_of(&params),
                usage: wgpu::BufferUsages::UNIFORM,
            });
            let target_resource = match (&view, target) {
                (Some(view), _) => wgpu::BindingResource::TextureView(view),
                (
                    None,
                    ResolveTarget::Buffer {
                        buffer,
                        offset,
                        format,
                    },
                ) => wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset,
                    size: NonZeroU64::new(pixels * format.bytes_per_pixel()),
                }),
                // A texture target always has its view.
                (None, ResolveTarget::Texture(_)) => return None,
            };
            Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("rtc resolve"),
                layout: &pipeline.layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: uniform.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                            buffer: accumulation,
                            offset: 0,
                            size: NonZeroU64::new(need),
                        }),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: target_resource,
                    },
                ],
            }))
        });
        if let Some(message) = error {
            return Err(ResolveError::Wgpu(message));
        }
        let Some(bind_group) = bind_group else {
            return Err(ResolveError::Wgpu("no view of the target texture".into()));
        };
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("rtc resolve"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipeline.pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(width.div_ceil(8), height.div_ceil(8), 1);
        Ok(())
    }

    /// The pipeline for `output`, created on first use.
    fn pipeline(&self, gpu: &Gpu, output: Output) -> Result<Arc<Pipeline>, ResolveError> {
        let mut pipelines = self
            .pipelines
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        let slot = pipelines
            .get_mut(output.index())
            .ok_or_else(|| ResolveError::Wgpu("no pipeline slot".into()))?;
        if let Some(p) = slot {
            return Ok(Arc::clone(p));
        }
        let (decl, store) = output.wgsl();
        let source = SHADER.replace("{OUTPUT}", decl).replace("{STORE}", store);
        let device = gpu.device();
        let (created, error) = gpu.scoped(|| {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("rtc resolve"),
                source: wgpu::ShaderSource::Wgsl(source.into()),
            });
            let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty,
                count: None,
            };
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("rtc resolve"),
                entries: &[
                    entry(
                        0,
                        wgpu::BindingType::Buffer {
                            ty: wgpu::BufferBindingType::Uniform,
                            has_dynamic_offset: false,
                            min_binding_size: NonZeroU64::new(std::mem::size_of::<Params>() as u64),
                        },
                    ),
                    entry(
                        1,
                        wgpu::BindingType::Buffer {
                            ty: wgpu::BufferBindingType::Storage { read_only: true },
                            has_dynamic_offset: false,
                            min_binding_size: NonZeroU64::new(16),
                        },
                    ),
                    entry(2, output.binding_type()),
                ],
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("rtc resolve"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("rtc resolve"),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some("resolve"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                cache: None,
            });
            Pipeline { layout, pipeline }
        });
        if let Some(message) = error {
            return Err(ResolveError::Wgpu(message));
        }
        let created = Arc::new(created);
        *slot = Some(Arc::clone(&created));
        Ok(created)
    }
}

/// The output kind for a texture target, after checking its format, dimension, usage and size.
fn texture_output(texture: &wgpu::Texture, image: [u32; 2]) -> Result<Output, ResolveError> {
    let output = match texture.format() {
        wgpu::TextureFormat::Rgba8Unorm => Output::Rgba8Texture,
        wgpu::TextureFormat::Rgba16Float => Output::Rgba16FloatTexture,
        wgpu::TextureFormat::Rgba32Float => Output::Rgba32FloatTexture,
        format => return Err(ResolveError::UnsupportedFormat { format }),
    };
    if texture.dimension() != wgpu::TextureDimension::D2 || texture.sample_count() != 1 {
        return Err(ResolveError::NotTwoDimensional {
            dimension: texture.dimension(),
            samples: texture.sample_count(),
        });
    }
    if !texture
        .usage()
        .contains(wgpu::TextureUsages::STORAGE_BINDING)
    {
        return Err(ResolveError::MissingUsage {
            what: "texture",
            usage: "TextureUsages::STORAGE_BINDING",
        });
    }
    let target = [texture.width(), texture.height()];
    if target != image {
        return Err(ResolveError::SizeMismatch { target, image });
    }
    Ok(output)
}

/// Checks a buffer target's usage, alignment and length.
fn check_buffer(
    gpu: &Gpu,
    buffer: &wgpu::Buffer,
    offset: u64,
    format: BufferFormat,
    [width, height]: [u32; 2],
) -> Result<(), ResolveError> {
    if !buffer.usage().contains(wgpu::BufferUsages::STORAGE) {
        return Err(ResolveError::MissingUsage {
            what: "buffer",
            usage: "BufferUsages::STORAGE",
        });
    }
    let alignment = gpu.device().limits().min_storage_buffer_offset_alignment;
    if offset % u64::from(alignment.max(1)) != 0 {
        return Err(ResolveError::Misaligned { offset, alignment });
    }
    let need = u64::from(width) * u64::from(height) * format.bytes_per_pixel();
    let have = buffer.size().saturating_sub(offset);
    if need > have {
        return Err(ResolveError::BufferTooSmall { have, need, offset });
    }
    let limit = gpu.limits().max_storage_buffer_binding_size;
    if need > limit {
        return Err(ResolveError::TooLarge {
            width,
            height,
            need,
            limit,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_output_fills_the_shader() {
        for output in Output::ALL {
            let (decl, store) = output.wgsl();
            let source = SHADER.replace("{OUTPUT}", decl).replace("{STORE}", store);
            let module = naga::front::wgsl::parse_str(&source)
                .unwrap_or_else(|e| panic!("{output:?}: {}", e.emit_to_string(&source)));
            naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::default(),
            )
            .validate(&module)
            .unwrap_or_else(|e| panic!("{output:?}: {e:?}"));
            assert_eq!(Output::ALL[output.index()], output);
        }
    }
}
