//! The ABI between the generated kernel and any host: every binding and every GPU struct layout, once.
//!
//! The kernel assembly reads this table to create naga global variables and struct types; the runtime
//! reads it to create wgpu bind group layouts and to pack buffers; `manifest.json` carries the same
//! facts (with offsets computed by `naga::proc::Layouter`) for other hosts. No binding number or struct
//! offset is written anywhere else (ARCHITECTURE invariant 2).
//!
//! Layout rules: all structs follow WGSL's storage/uniform layout (std430-like: `vec3` aligned to 16,
//! scalars to 4). Host-side mirrors are `#[repr(C)]` + `Pod` structs with size asserts, and a test in the
//! runtime compares them with the layouts computed here.
//!
//! Invariants:
//! - Bindings are all in group 0, numbered densely from 0 in [`BINDINGS`] order.
//! - At most 8 storage buffers plus 2 uniform buffers, within WebGPU's default of 8 storage buffers per
//!   stage, so the kernel runs on every adapter.
//! - A binding that the kernel of a scene does not use is not declared in that kernel (see the link step);
//!   hosts bind exactly the bindings the manifest lists.

use crate::back::{Resource, ResourceKind};

/// The type of a field of an ABI struct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldType {
    /// `u32`
    U32,
    /// `f32`
    F32,
    /// `vec2<u32>`
    Vec2U32,
    /// `vec3<f32>`
    Vec3F32,
    /// `vec4<f32>`
    Vec4F32,
    /// `vec4<u32>`
    Vec4U32,
}

/// A field of an ABI struct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Field {
    /// The field's name in the generated code and the manifest.
    pub name: &'static str,
    /// Its type.
    pub ty: FieldType,
}

const fn f(name: &'static str, ty: FieldType) -> Field {
    Field { name, ty }
}

/// A struct shared by the kernel and the host.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StructDesc {
    /// Its name in the generated code.
    pub name: &'static str,
    /// Fields in order.
    pub fields: &'static [Field],
    /// What it is, for the manifest.
    pub doc: &'static str,
}

/// Per-tile constants: which pixels one dispatch covers (a uniform buffer bound with a dynamic
/// offset per tile; the runtime's `gpu::TileParams` mirrors it).
pub const TILE: StructDesc = StructDesc {
    name: "TileParams",
    doc: "per-dispatch tile: top-left pixel, extent (clipped at the image edge), image size, tile index, pass",
    fields: &[
        f("origin", FieldType::Vec2U32),
        f("extent", FieldType::Vec2U32),
        f("image_size", FieldType::Vec2U32),
        f("tile_index", FieldType::U32),
        f("frame", FieldType::U32),
    ],
};

/// Per-scene constants (a uniform buffer): sampling, the scene-level BVH root, and where the scene's
/// tables are in `params`.
pub const FRAME: StructDesc = StructDesc {
    name: "FrameUniforms",
    doc: "per-scene constants: sampling, the scene-level BVH root, and where the scene's tables are in `params`",
    fields: &[
        f("samples_per_pass", FieldType::U32),
        f("total_samples", FieldType::U32),
        f("seed", FieldType::U32),
        f("tlas_root", FieldType::U32),
        f("instance_count", FieldType::U32),
        f("light_count", FieldType::U32),
        f("light_table", FieldType::U32),
        f("medium_count", FieldType::U32),
        f("medium_table", FieldType::U32),
        f("camera_type", FieldType::U32),
        f("camera_offset", FieldType::U32),
        f("background_type", FieldType::U32),
        f("background_offset", FieldType::U32),
    ],
};

/// A BVH record, scene or object level (32 bytes; the layout is `rtc_bvh::quantized`'s).
pub const NODE: StructDesc = StructDesc {
    name: "GpuNode",
    doc: "BVH record: a header (quantisation origin in `min`, root reference in `a`, step size in `max`) or an \
          inner node (both children's 16-bit boxes as the bits of `min` and `max`, their references in `a` and `b`)",
    fields: &[f("min", FieldType::Vec3F32), f("a", FieldType::U32), f("max", FieldType::Vec3F32), f("b", FieldType::U32)],
};

/// One object of the scene (an instance of a geometry with a material and a transform).
pub const INSTANCE: StructDesc = StructDesc {
    name: "GpuInstance",
    doc: "object: world-to-object and object-to-world affine transforms (3 rows each), geometry and material \
          ids and parameter offsets, flags, and the object's index in the scene",
    fields: &[
        f("world_to_object_0", FieldType::Vec4F32),
        f("world_to_object_1", FieldType::Vec4F32),
        f("world_to_object_2", FieldType::Vec4F32),
        f("object_to_world_0", FieldType::Vec4F32),
        f("object_to_world_1", FieldType::Vec4F32),
        f("object_to_world_2", FieldType::Vec4F32),
        f("geometry_type", FieldType::U32),
        f("geometry_offset", FieldType::U32),
        f("material_type", FieldType::U32),
        f("material_offset", FieldType::U32),
        f("blas_root", FieldType::U32),
        f("triangle_offset", FieldType::U32),
        f("flags", FieldType::U32),
        f("object", FieldType::U32),
    ],
};

/// What a binding's elements are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Element {
    /// One struct (uniform buffers).
    Struct(&'static StructDesc),
    /// A runtime-sized array of structs.
    StructArray(&'static StructDesc),
    /// A runtime-sized array of a plain type.
    Array(FieldType),
    /// A runtime-sized array of `atomic<u32>`.
    Atomics,
}

/// One binding of the kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BindingDesc {
    /// The binding number (group 0).
    pub binding: u32,
    /// The variable's name in the generated code and the manifest.
    pub name: &'static str,
    /// Uniform, read-only or read-write storage.
    pub kind: ResourceKind,
    /// Its elements.
    pub element: Element,
    /// What it holds, for the manifest.
    pub doc: &'static str,
}

/// Every binding the kernel can have, in binding order.
pub const BINDINGS: &[BindingDesc] = &[
    BindingDesc {
        binding: 0,
        name: "frame",
        kind: ResourceKind::Uniform,
        element: Element::Struct(&FRAME),
        doc: "per-dispatch constants",
    },
    BindingDesc {
        binding: 1,
        name: "tile",
        kind: ResourceKind::Uniform,
        element: Element::Struct(&TILE),
        doc: "the tile of this dispatch (bound with a dynamic offset)",
    },
    BindingDesc {
        binding: 2,
        name: "nodes",
        kind: ResourceKind::StorageRead,
        element: Element::StructArray(&NODE),
        doc: "the scene-level BVH and every mesh's object-level BVH, concatenated",
    },
    BindingDesc {
        binding: 3,
        name: "instances",
        kind: ResourceKind::StorageRead,
        element: Element::StructArray(&INSTANCE),
        doc: "the scene's objects",
    },
    BindingDesc {
        binding: 4,
        name: "triangles",
        kind: ResourceKind::StorageRead,
        element: Element::Array(FieldType::Vec4F32),
        doc: "triangle vertex positions in object space, 3 vec4 per triangle in BVH leaf order (w of the first: the mesh's triangle index, as bits)",
    },
    BindingDesc {
        binding: 5,
        name: "attributes",
        kind: ResourceKind::StorageRead,
        element: Element::Array(FieldType::Vec4U32),
        doc: "per triangle, 2 vec4u: octahedral normals of the 3 vertices (snorm16x2) and their uvs (f16x2)",
    },
    BindingDesc {
        binding: 6,
        name: "params",
        kind: ResourceKind::StorageRead,
        element: Element::Array(FieldType::U32),
        doc: "instance data of every camera, geometry, material and light type, the light and medium tables, mesh and texture records, as 32-bit words",
    },
    BindingDesc {
        binding: 7,
        name: "texels",
        kind: ResourceKind::StorageRead,
        element: Element::Array(FieldType::U32),
        doc: "every texture's texels (rgba8 sRGB, or rgba16f as 2 words)",
    },
    BindingDesc {
        binding: 8,
        name: "accum",
        kind: ResourceKind::StorageReadWrite,
        element: Element::Array(FieldType::Vec4F32),
        doc: "per pixel: rgb = sum of sample radiance, a = sample count",
    },
    BindingDesc {
        binding: 9,
        name: "counters",
        kind: ResourceKind::StorageReadWrite,
        element: Element::Atomics,
        doc: "atomic counters: [0] = samples that were not finite (NaN or infinite) and were replaced by zero, [1] = rays traced (camera, secondary and shadow)",
    },
];

/// The back ends' view of a set of bindings.
pub fn resources<'a>(bindings: impl IntoIterator<Item = &'a BindingDesc>) -> Vec<Resource> {
    bindings
        .into_iter()
        .map(|b| Resource {
            group: 0,
            binding: b.binding,
            kind: b.kind,
        })
        .collect()
}

/// The binding with this name.
pub fn binding(name: &str) -> Option<&'static BindingDesc> {
    BINDINGS.iter().find(|b| b.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bindings_are_dense_and_fit_webgpu_defaults() {
        for (i, b) in BINDINGS.iter().enumerate() {
            assert_eq!(b.binding as usize, i, "{} is out of order", b.name);
        }
        let storage = BINDINGS
            .iter()
            .filter(|b| b.kind != ResourceKind::Uniform)
            .count();
        assert!(
            storage <= 8,
            "{storage} storage buffers exceed WebGPU's default limit of 8"
        );
    }
}
