//! `rtc-runtime`: the thin wgpu runtime of rtc (scenes, BVHs, GPU buffers, dispatch, images).
//!
//! The crate is layered so that each layer knows nothing of the ones above it:
//!
//! - [`gpu`]: the language-independent GPU core. Adapter selection ([`gpu::Gpu`]), compute
//!   pipelines with explicit bind group layouts ([`gpu::Kernel`]), persistent per-binding buffers
//!   that re-upload only what changed ([`gpu::BufferSet`]), tiled dispatch with progress and
//!   read-back ([`gpu::TileDispatcher`]).
//! - [`image_out`]: linear RGBA `f32` images, EXR/PNG output and input, and image metrics.
//! - [`assets`]: file formats in (OBJ, glTF, images), plain CPU-side meshes and textures out.
//! - [`scene`]: a compiled scene's description → scene entities (meshes with their BVHs, objects,
//!   packed parameters) → the GPU buffers the kernel reads; the module docs are the GPU scene
//!   format.
//! - [`render`]: from a `CompiledScene` to an image: entities, uploads, pipelines, passes of tiled
//!   dispatch, read-back, statistics.
//! - [`resolve`]: the accumulation buffer to a texture or buffer a host application owns, on the
//!   GPU (tone-mapped sRGB bytes as in the PNG, or linear floats), recorded into the host's encoder.
//!
//! # Embedding in a host application
//!
//! A host that has its own wgpu device gives it to rtc ([`gpu::Gpu::from_device`]; create the
//! device with [`gpu::required_limits`]), renders a compiled scene with a [`render::Renderer`],
//! and resolves the image into a texture or buffer it owns, in its own command encoder
//! ([`render::Renderer::resolve_into`]); rtc creates no window, instance or second device.
//! `examples/embed.rs` does this every frame in a winit window. On lavapipe before Mesa 26 (and
//! on CPUs without AVX-512) a host may call [`gpu::apply_lavapipe_defaults`] first thing in
//! `main`, as `rtc` does, to halve the driver's compile of every kernel (it sets `LP_NATIVE_VECTOR_WIDTH=128` unless that is set,
//! or, on a CPU without AVX-512, unless the samples it is given make a long render; with
//! [`gpu::CpuJit::Quick`] it also turns LLVM's optimisation off, for work too small to repay it).
//!
//! ```
//! use rtc_compiler::driver::Options;
//! use rtc_compiler::kernel::compile_scene;
//! use rtc_compiler::link::LinkOptions;
//! use rtc_runtime::gpu::{required_limits, Gpu, GpuOptions};
//! use rtc_runtime::image_out::ToneMap;
//! use rtc_runtime::render::{RenderOptions, Renderer};
//! use rtc_runtime::resolve::ResolveTarget;
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! // The host's side: its instance, adapter, device and queue.
//! let instance =
//!     wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
//! let adapter = match pollster::block_on(instance.request_adapter(&Default::default())) {
//!     Ok(adapter) => adapter,
//!     Err(_) => return Ok(()), // no GPU at all: nothing to embed into
//! };
//! let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
//!     required_limits: required_limits(),
//!     ..Default::default()
//! }))?;
//!
//! // rtc on the host's device (the handles are cheap clones; the host keeps its own).
//! let gpu = Gpu::from_device(adapter, device.clone(), queue.clone(), &GpuOptions::from_env())?;
//!
//! // A scene from a string. The compiler reads scenes from files (imports resolve from the
//! // scene's folder), so the text goes into a file first.
//! let scene = r#"
//!     import "std/cameras/pinhole.rt";
//!     import "std/materials/lambert.rt";
//!     import "std/lights/point.rt";
//!     scene tiny {
//!         settings { width: 16, height: 8, samples: 1 }
//!         camera Pinhole { position: vec3f(0.0, 2.0, 2.0), look_at: vec3f(0.0), fov: 60.0 }
//!         object floor { geometry: quad_mesh(), material: Lambert { albedo: vec3f(0.8) } }
//!         light PointLight { position: vec3f(0.0, 1.0, 0.0), intensity: 2.0 }
//!     }
//! "#;
//! let dir = std::env::temp_dir().join(format!("rtc-doc-embed-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let path = dir.join("tiny.rt");
//! std::fs::write(&path, scene)?;
//! let compiled = compile_scene(&[path], None, &Options::default(), &LinkOptions::default())
//!     .map_err(|failure| {
//!         rtc_compiler::diag::render_human(&failure.checked.sources, &failure.diagnostics, false)
//!     })?;
//!
//! // Render, then resolve into the host's texture in the host's encoder.
//! let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default())?;
//! renderer.render(&mut |_done, _total| {})?;
//! let [width, height] = renderer.size();
//! let texture = device.create_texture(&wgpu::TextureDescriptor {
//!     label: Some("host texture"),
//!     size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
//!     mip_level_count: 1,
//!     sample_count: 1,
//!     dimension: wgpu::TextureDimension::D2,
//!     format: wgpu::TextureFormat::Rgba8Unorm, // the PNG's sRGB bytes
//!     usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING,
//!     view_formats: &[],
//! });
//! let mut encoder = device.create_command_encoder(&Default::default());
//! renderer.resolve_into(ResolveTarget::Texture(&texture), &ToneMap::default(), Some(&mut encoder))?;
//! // … the host's own passes sampling `texture` …
//! queue.submit([encoder.finish()]);
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok(())
//! # }
//! ```
//!
//! Invariants of the whole crate: it never exits the process and never panics on run-time
//! failures; every fallible operation returns a typed error (`thiserror` enums, one per module).
//! It contains no `unsafe` code (the workspace denies it).

// The docs shared by both builds link native-only items (`Gpu::new`, `Gpu::with_options`),
// which the web build (wasm32) does not have.
#![cfg_attr(target_arch = "wasm32", allow(rustdoc::broken_intra_doc_links))]

pub mod animation;
pub mod assets;
pub mod bvh_view;
pub mod gpu;
pub mod image_out;
pub mod orbit;
pub mod render;
pub mod resolve;
pub mod scene;
