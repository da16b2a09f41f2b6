//! The asset stage: file formats in, plain CPU-side scene entities out.
//!
//! This is the middle stage of ARCHITECTURE invariant 7 (scene description → **scene
//! entities** → GPU objects). It reads Wavefront OBJ, glTF 2.0 and images, builds the scene-only
//! built-in meshes of `spec/scenes.md`, and returns plain data: [`MeshData`], [`TextureData`] and
//! [`ModelScene`]. It knows nothing of GPUs, buffers or BVHs; the GPU stage knows nothing of file
//! formats.
//!
//! | entry | what |
//! |---|---|
//! | [`load_obj`] | a Wavefront OBJ file as one triangle [`MeshData`] (`load_mesh` in the language) |
//! | [`quad_mesh`], [`cube_mesh`], [`sphere_mesh`] | the procedural meshes of `spec/scenes.md` |
//! | [`load_image`] | a PNG, JPEG, HDR or EXR file as a [`TextureData`] |
//! | [`solid_texture`] | a 1×1 [`TextureData`] |
//! | [`load_gltf`] | a `.gltf`/`.glb` file as a [`ModelScene`] (meshes, instances, materials, textures, cameras, lights) |
//!
//! # Conventions (shared by every loader and by the kernels that read the data)
//!
//! - **Right-handed, y-up** world space, as glTF and all test meshes in `shared/models` use.
//!   Files are not rotated on import.
//! - **Front faces wind counter-clockwise** when seen from the side the geometric normal
//!   `cross(p1 - p0, p2 - p0)` points to. Shading normals, when present, are unit length.
//! - **Texture coordinates have their origin at the top-left corner of the image, with v
//!   pointing down the rows** (glTF's convention; texel row 0 is the top row). OBJ stores v
//!   upwards, so [`load_obj`] flips it (`v' = 1 - v`).
//! - Meshes are indexed triangle lists with `u32` indices ([`MeshData`]); every loader calls
//!   [`MeshData::validate`] and fills in missing normals (area-weighted smooth normals), so a
//!   loaded mesh always has unit normals.
//! - Textures are row-major, top row first, packed into `u32` words exactly as the GPU's texel
//!   buffer holds them; see [`texture`] for the bit layout of each [`TextureFormat`].
//!
//! # Invariants
//!
//! - **No input panics.** Every loader returns [`AssetError`] for bad input: a file that cannot be
//!   read, an unsupported format, bad JSON, a truncated `.glb`, a missing referenced file (named),
//!   an accessor or index out of range, an oversized image. Non-test code here is checked by
//!   clippy's `unwrap_used`, `expect_used`, `panic` and `indexing_slicing` lints (denied below),
//!   and byte offsets from files are computed with checked arithmetic. Third-party parsers are
//!   only handed input they are known to survive (see `obj.rs` and `model/document.rs`).
//! - Errors name the file they are about; the runtime never exits the process.
//! - **Assets stay inside the folders they were given** ([`confine`]): a path in a scene or a
//!   glTF file is relative and resolves (symlinks followed) inside the referring file's folder or
//!   an [`AssetRoots`] folder; anything else is [`AssetError::Escape`].
//! - What a loader skips (an unsupported glTF primitive mode, an ignored texture) is a warning in
//!   [`ModelScene::warnings`], never silent and never fatal.

#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing,
        clippy::todo,
        clippy::unimplemented
    )
)]

mod bounds;
pub mod confine;
mod error;
mod mesh;
pub mod model;
mod obj;
mod procedural;
pub mod texture;

#[cfg(test)]
mod tests;

pub use bounds::Bounds;
pub use confine::AssetRoots;
pub(crate) use error::display_folder;
pub use error::{
    AssetError, CountProblem, GlbProblem, GltfItem, MeshError, PathProblem, TextureSlot, UriProblem,
};
pub use mesh::{MeshData, MeshReport, VertexExtras};
pub use model::{
    load_gltf, load_gltf_with, AlphaMode, GltfCamera, GltfLight, GltfMaterial, LightKind,
    MeshInstance, ModelScene, Projection,
};
pub use obj::load_obj;
pub(crate) use obj::parse_obj;
pub use procedural::{cube_mesh, quad_mesh, sphere_mesh, MAX_SPHERE_SUBDIVISIONS};
pub use texture::{
    load_image, solid_texture, Sampler, TextureData, TextureFormat, Wrap, MAX_TEXTURE_SIZE,
};
