//! Scenes on the GPU: from the compiler's scene description to the buffers the kernel reads.
//!
//! Three stages, kept apart (ARCHITECTURE invariant 7):
//!
//! 1. **Scene description**: the compiler's checked, evaluated [`SceneDesc`] (with the program it
//!    belongs to and the link plan [`Linked`] that gives every used type its id). Nothing here parses.
//! 2. **Scene entities** ([`Entities`], `entities.rs`): assets loaded once each ([`assets`]), one
//!    object-level BVH per distinct mesh, objects with their transforms, every role-struct instance
//!    packed into `params`, the light and medium tables, the scene-level BVH. Plain CPU data, no
//!    GPU: the whole stage is unit-tested without an adapter. Moving an object
//!    ([`Entities::set_transform`]) rebuilds only the scene-level BVH.
//! 3. **GPU objects** ([`GpuScene`], `upload.rs`): one persistent [`BufferSet`] entry per ABI
//!    binding the kernel declares, re-uploaded only when its entity data changed. It knows nothing
//!    of file formats or of the language.
//!
//! [`assets`]: crate::assets
//! [`SceneDesc`]: rtc_compiler::sema::hir::SceneDesc
//! [`Linked`]: rtc_compiler::link::Linked
//! [`BufferSet`]: crate::gpu::BufferSet
//!
//! # The GPU scene format (the contract with the kernel, `stdlib/kernel/`)
//!
//! Every layout is defined once, in the ABI table `rtc_compiler::abi`: bindings and structs
//! (`FRAME`, `TILE`, `NODE` with its views `NODE_HEADER`/`NODE_INNER`, `INSTANCE`), the records in
//! array bindings (`MESH`, `TEXTURE`, `LIGHT_ENTRY`, `MEDIUM_ENTRY` in `params`; `TRIANGLE`,
//! `ATTRIBUTE` slots), the BVH reference bits (`NODE_REFERENCE`) and every constant (instance
//! flags, `MESH_GEOMETRY`, texture formats, counter indices). The kernel reads them through the
//! generated `rtc:abi` module, `manifest.json` lists them for other hosts, and the encoders here
//! write them with `gpu_types::record` offsets and constants taken from the table (compile-time
//! asserts in `gpu_types.rs`). What follows is what the runtime puts where, not the layouts.
//!
//! - **`nodes`** ([`rtc_bvh::NodeRecord`]s; bits in `rtc_bvh::quantized`): every BVH converted
//!   with `rtc_bvh::quantized::quantize`, concatenated: first one object-level BVH
//!   (BLAS) per distinct mesh, in order of first use, **built once per mesh and shared by all
//!   objects using it**; then the scene-level BVH (TLAS) over the objects' world-space boxes, **one
//!   object per leaf** (built with `BuildPreset::single_leaf_params`; the kernel tests a TLAS
//!   leaf's object without a loop). With [`EntityOptions::flatten`], the BVHs of the groups of
//!   flattened static objects (`flatten.rs`) follow the meshes' and come before the TLAS. A BVH
//!   whose first record is at index `base` has its header
//!   (quantisation frame and root reference) at `base` and its inner-node record `r` at
//!   `base + r`. The TLAS comes last so that rebuilding it (its record count may change) never
//!   moves a BLAS. `FrameUniforms.tlas_root` is the TLAS's header.
//! - **`instances`** ([`GpuInstance`]): one per object in the TLAS, **in TLAS leaf
//!   order**: a TLAS leaf's slots index this array directly, and slot `s` holds the object
//!   `tlas.prim_indices()[s]`. `geometry_type` is `MESH_GEOMETRY` for a mesh, else the custom
//!   geometry type's id; `blas_root` is the mesh BVH's header record; `triangle_offset` the mesh's
//!   first triangle slot; `flags` the material's `FLAG_*`; `object` the scene `object` entries in
//!   order, then model instances. An object whose world box is empty or not finite (an empty mesh,
//!   invalid custom bounds) is left out of the TLAS and therefore of this array; `object` keeps its
//!   index. A group of flattened objects is one TLAS leaf whose record has identity transforms,
//!   the group's BVH and in `object` the slot of its first member; the members' records (identity
//!   transforms, their own materials, flags and `object`) follow every TLAS slot, group by group.
//! - **`triangles`** and **`attributes`**: one `TRIANGLE` and one `ATTRIBUTE` record per triangle
//!   slot, per mesh in BLAS leaf order from the mesh's `slot_base` (see `encode.rs`). Slots, not
//!   triangles: with the `quality` preset's spatial splits a triangle may occupy several slots. A
//!   slot's `v1.w` is 0, except in a flattened group's slots, where it is the member's index in the
//!   group plus one (the kernel then reports the hit on the member's record).
//! - **`params`** (`u32` words), in this order: a `MESH` record for every `mesh` value and a
//!   `TEXTURE` record for every `texture` value of the scene, whose word offsets are what
//!   `layout::Handles` gives the packer; then every role-struct instance (camera, background,
//!   custom geometries, materials, lights), packed with `rtc_compiler::layout::pack_into`, each
//!   starting at a multiple of 4 words (identical instances of one type share one copy); then the
//!   light table (`light_count` `LIGHT_ENTRY`s, scene order); last the medium table
//!   (`medium_count` `MEDIUM_ENTRY`s: objects whose material has `@medium`, in object order), last
//!   because it follows the TLAS order. Type ids are `Linked::type_of(struct).id`.
//! - **`texels`**: every texture's words ([`TextureData`](crate::assets::TextureData)) concatenated;
//!   a texture record's `texel_base` is its first word.
//! - **`frame`** ([`FrameUniforms`]): `samples_per_pass` (the camera's), `total_samples` (the
//!   scene's `samples` or an override), `seed`, `tlas_root`, `instance_count`, the light and medium
//!   tables, camera and background type ids and offsets (background 0/0 without one), the
//!   wavefront model's `path_slots` and the megakernel's `passes_per_dispatch`.
//! - **`tile`**: `gpu::TileParams`, written by the tile dispatcher; `frame` is the pass index (of
//!   the first of the dispatch's `FrameUniforms::passes_per_dispatch` passes).
//! - **`accum`**: `width * height` `vec4f` (rgb = radiance sum, a = sample count), zeroed before the
//!   first pass of a render. **`counters`**: `COUNTER_WORDS` `u32`, zeroed with it (indices
//!   `COUNTER_NONFINITE`, `COUNTER_RAYS`).
//! - **Custom geometry bounds**: when the scene has custom geometry, `instances` is first uploaded
//!   in object order (slot `i` = object `i`, `instance_count` = the object count) and the compiler's
//!   `bounds` kernel runs one invocation per object, writing the object-space box of custom-geometry
//!   object `i` to `accum[2i].xyz` (min) and `accum[2i + 1].xyz` (max); the runtime reads them back,
//!   transforms them to world space and only then builds the TLAS.
//!
//! Exactly the bindings the kernel declares are created and bound (the kernel of a scene may lack
//! some, e.g. `texels` without textures).

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

mod assets_cache;
mod encode;
mod entities;
mod fields;
mod flatten;
mod gpu_types;
mod models;
mod params;
mod store;
mod tables;
mod upload;

#[cfg(test)]
mod tests;

/// The naming of a too-large binding's largest part, for the asset tests.
#[cfg(test)]
pub(crate) mod upload_for_tests {
    pub(crate) use super::upload::{name_the_largest_part, COUNTER_BYTES};
}

pub use encode::{decode_octahedral, octahedral, pack_snorm2x16, unpack_snorm2x16};
pub use entities::{
    Dirty, Entities, EntityOptions, EntityStats, FieldTarget, LightEntity, MeshEntity,
    ObjectEntity, ObjectGeometry, SrgbTextures, TextureEntity, TypedOffset, Versions,
    LINEAR_TEXEL_BUDGET, SRGB_TEXTURES_ENV,
};
pub use gpu_types::{
    element_size, field_offset, struct_align, struct_size, FrameUniforms, GpuInstance,
};
pub use store::{AssetStore, BuiltMesh, Stamp, StoreCounters, Version};
pub use tables::{
    prefers_uniform_tables, TablePlacement, UniformTables, UNIFORM_TABLES_ENV, UNIFORM_TABLE_BYTES,
};
pub use upload::{runtime_binding, Counters, GpuScene, UploadReport};

use rtc_compiler::diag::{codes, Diagnostic};
use rtc_compiler::Span;

use crate::assets::AssetError;
use crate::gpu::{BufferError, DispatchError};

/// Why a scene could not be turned into entities or GPU buffers.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// An asset the scene names cannot be loaded (E0902), or its path leads outside the allowed
    /// folders (E0903).
    #[error("{source}")]
    Asset {
        /// The string in the scene that names it, when known.
        span: Option<Span>,
        /// The loader's error (it names the file).
        source: AssetError,
    },
    /// The scene has no camera (only possible when a model was to bring one and has none).
    #[error(
        "the scene `{scene}` has no camera: add a `camera` entry (its models have no perspective \
         camera)"
    )]
    NoCamera {
        /// The scene's name.
        scene: String,
    },
    /// The compile step handed over no checked program (its diagnostics had errors).
    #[error("the compiled scene carries no checked program")]
    NoProgram,
    /// The link plan has no id for a type the scene uses: the plan is not this scene's (a bug in
    /// the caller or the compiler).
    #[error("internal error: the link plan has no id for `{name}`, which the scene uses")]
    Unlinked {
        /// The struct's name.
        name: String,
    },
    /// A glTF `model` file needs a type the link step did not link: the file changed between
    /// the compile, which read its metadata, and the render (or the link step has a bug).
    #[error(
        "internal error: `{model}` needs `{name}`, which the scene's kernel was not linked with \
         (the link step links what the file held when the scene was compiled; did the file \
         change since? compile the scene again)"
    )]
    ModelUnlinked {
        /// The model file.
        model: String,
        /// The struct it needs.
        name: String,
    },
    /// A struct the scene uses has no type in the program's type table (a compiler bug).
    #[error("internal error: `{name}` has no type in the program's type table")]
    NoStructType {
        /// The struct's name.
        name: String,
    },
    /// A `mesh` or `texture` value was met while packing that the asset scan did not see (a bug).
    #[error("internal error: the asset scan missed a {what} value while packing parameters")]
    UnresolvedHandle {
        /// `mesh` or `texture`.
        what: &'static str,
    },
    /// An object's transform cannot be used.
    #[error("object {}: its transform {reason}", object_label(*object, name.as_deref()))]
    BadTransform {
        /// The object's index.
        object: usize,
        /// Its name, if it has one.
        name: Option<String>,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// An object index out of range.
    #[error("there is no object {object}: the scene has {count}")]
    NoSuchObject {
        /// The index asked for.
        object: usize,
        /// How many objects there are.
        count: usize,
    },
    /// The TLAS was requested while custom-geometry bounds are still unknown.
    #[error("object {object} has custom geometry whose bounds have not been computed (run the bounds kernel first)")]
    MissingBounds {
        /// The first such object.
        object: usize,
    },
    /// The scene is too large for 32-bit GPU indices.
    #[error("the scene's {what} need {count} entries, more than 32-bit GPU indices can address")]
    TooLarge {
        /// What overflowed.
        what: &'static str,
        /// How many.
        count: u64,
    },
    /// A mesh's BVH does not fit the quantised mesh node layout (`rtc_bvh::quantized`).
    #[error("mesh {mesh}: {source}")]
    MeshLayout {
        /// The mesh's source.
        mesh: String,
        /// The layout limit it exceeds.
        source: rtc_bvh::quantized::QuantizeError,
    },
    /// A buffer could not be created or written (including data above a device limit).
    #[error(transparent)]
    Buffer(#[from] BufferError),
    /// A binding holding meshes or textures exceeds a device limit; names the largest part.
    #[error("{source}; the largest part of it is {part}")]
    BindingTooLarge {
        /// The buffer error (it names the binding, the size and the limit).
        source: BufferError,
        /// The largest mesh (its file, and for a glTF model `file.glb#meshes[m].primitives[p]`) or
        /// texture in it.
        part: String,
    },
    /// Reading a buffer back failed.
    #[error(transparent)]
    ReadBack(#[from] DispatchError),
    /// A field write named an instance the scene does not have.
    #[error("the scene has no {what}")]
    NoSuchInstance {
        /// `background`, `light 3`, `object 7`.
        what: String,
    },
    /// A field write named a field the instance's struct does not have.
    #[error("`{ty}` has no field `{field}`; its fields are {}", fields.join(", "))]
    NoSuchField {
        /// The struct.
        ty: String,
        /// The field asked for.
        field: String,
        /// Its fields.
        fields: Vec<String>,
    },
    /// A field write's value is not of the field's type (or is an asset handle, which only a
    /// rebuild can change).
    #[error("`{ty}.{field}` is a `{expected}`: {problem}")]
    FieldValue {
        /// The struct.
        ty: String,
        /// The field.
        field: String,
        /// The field's type.
        expected: String,
        /// What is wrong with the value.
        problem: String,
    },
}

fn object_label(index: usize, name: Option<&str>) -> String {
    match name {
        Some(n) => format!("`{n}` (#{index})"),
        None => format!("#{index}"),
    }
}

impl SceneError {
    /// The error as a diagnostic at the scene's source, when it is about something written there
    /// (an asset that cannot be read: E0902; an asset path leading outside the allowed folders:
    /// E0903). Render it with the compile's source map.
    pub fn to_diagnostic(&self) -> Option<Diagnostic> {
        match self {
            SceneError::Asset {
                span: Some(span),
                source:
                    source @ AssetError::Escape {
                        item,
                        written,
                        problem,
                        ..
                    },
            } => {
                let what = match item {
                    Some(item) => format!("{item} of `{}`", source.path().display()),
                    None => "the path".to_owned(),
                };
                let allowed = problem.allowed();
                let help = if allowed.is_empty() {
                    "write a path relative to the scene's (or the glTF file's) folder, with `/` \
                     between folders; files elsewhere need their folder named with \
                     `--asset-root DIR`"
                        .to_owned()
                } else {
                    format!(
                        "move the file into {}, or name its folder with `--asset-root DIR`",
                        allowed
                            .iter()
                            .map(|a| format!("`{}`", crate::assets::display_folder(a)))
                            .collect::<Vec<_>>()
                            .join(" or ")
                    )
                };
                Some(
                    Diagnostic::error(codes::E0903, format!("{what} `{written}` {problem}"), *span)
                        .with_label("named here")
                        .with_note(source.to_string())
                        .with_help(help),
                )
            }
            SceneError::Asset {
                span: Some(span),
                source,
            } => Some(
                Diagnostic::error(
                    codes::E0902,
                    format!("cannot load `{}`", source.path().display()),
                    *span,
                )
                .with_label("named here")
                .with_note(source.to_string()),
            ),
            _ => None,
        }
    }
}
