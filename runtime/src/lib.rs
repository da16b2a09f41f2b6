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
//! Invariants of the whole crate: it never exits the process and never panics on run-time
//! failures; every fallible operation returns a typed error (`thiserror` enums, one per module).
//! It contains no `unsafe` code (the workspace denies it).

pub mod assets;
pub mod bvh_view;
pub mod gpu;
pub mod image_out;
pub mod render;
pub mod resolve;
pub mod scene;
