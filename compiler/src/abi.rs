//! The ABI between the generated kernel and any host: every binding, every GPU struct layout, every
//! record the host packs into an array binding and every flag and bit constant, once.
//!
//! Structs and bindings are here; records (mesh, texture, light and medium table entries in `params`,
//! triangle and attribute slots), the BVH node views and bit fields, and the constants are in
//! [`records`] (re-exported). The role structs' packing in `params` is the language's type layout,
//! `crate::layout`.
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

pub mod records;
pub use records::*;

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
    /// `vec3<u32>`
    Vec3U32,
    /// `vec4<f32>`
    Vec4F32,
    /// `vec4<u32>`
    Vec4U32,
}

impl FieldType {
    /// Its name in the language (and WGSL's short alias): `u32`, `vec3f`, …
    pub const fn name(self) -> &'static str {
        match self {
            FieldType::U32 => "u32",
            FieldType::F32 => "f32",
            FieldType::Vec2U32 => "vec2u",
            FieldType::Vec3F32 => "vec3f",
            FieldType::Vec3U32 => "vec3u",
            FieldType::Vec4F32 => "vec4f",
            FieldType::Vec4U32 => "vec4u",
        }
    }
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
        f("path_slots", FieldType::U32),
        f("passes_per_dispatch", FieldType::U32),
    ],
};

/// A BVH record, scene or object level (32 bytes; the layout is `rtc_bvh::quantized`'s): read as
/// [`NODE_HEADER`] (record 0 of a BVH) or [`NODE_INNER`] (records 1..) with `bitcast`.
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
          ids and parameter offsets, flags, and the object's index in the scene (in the record of a group of \
          flattened static objects: the slot of its first member's record)",
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

/// Every struct of the ABI: the bindings' structs and the two views of a BVH record.
pub const STRUCTS: &[&StructDesc] = &[&FRAME, &TILE, &NODE, &NODE_HEADER, &NODE_INNER, &INSTANCE];

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
        doc: "atomic counters: [0] = samples that were not finite (NaN or infinite) and were replaced by zero, [1] = rays traced (camera, secondary and shadow), [3] = wavefront shadow queries beyond what a shading step records",
    },
    BindingDesc {
        binding: 10,
        name: "paths",
        kind: ResourceKind::StorageReadWrite,
        element: Element::Array(FieldType::Vec4U32),
        doc: "the wavefront model's path state: one record of `PATH_WORDS` words (a multiple of 4) per pixel of the tile, stored in 4-word chunks, chunk-major (chunk `c` of slot `i` at element `c * path_slots + i`), then one chunk whose first word the stages set while a path runs",
    },
];

// Layout under WGSL's storage-buffer rules, computed from the table (the runtime's unit test checks it
// against `naga::proc::Layouter`).

/// Size and alignment in bytes of an ABI field type under WGSL's storage layout.
pub const fn field_layout(ty: FieldType) -> (usize, usize) {
    match ty {
        FieldType::U32 | FieldType::F32 => (4, 4),
        FieldType::Vec2U32 => (8, 8),
        FieldType::Vec3F32 | FieldType::Vec3U32 => (12, 16),
        FieldType::Vec4F32 | FieldType::Vec4U32 => (16, 16),
    }
}

const fn round_up(x: usize, align: usize) -> usize {
    x.div_ceil(align) * align
}

/// Byte offset of field `index` of `s` (the struct's size for `index == fields.len()` before the
/// final rounding; `usize::MAX` beyond that).
pub const fn field_offset_at(s: &StructDesc, index: usize) -> usize {
    if index > s.fields.len() {
        return usize::MAX;
    }
    let mut offset = 0;
    let mut i = 0;
    let mut rest = s.fields;
    while let Some((field, tail)) = rest.split_first() {
        let (size, align) = field_layout(field.ty);
        offset = round_up(offset, align);
        if i == index {
            return offset;
        }
        offset += size;
        i += 1;
        rest = tail;
    }
    offset
}

/// Byte offset of the field called `name` in `s`, or `usize::MAX` when there is none (so a
/// compile-time assert against a Rust offset fails).
pub const fn field_offset(s: &StructDesc, name: &str) -> usize {
    let mut i = 0;
    let mut rest = s.fields;
    while let Some((field, tail)) = rest.split_first() {
        if same_name(field.name, name) {
            return field_offset_at(s, i);
        }
        i += 1;
        rest = tail;
    }
    usize::MAX
}

/// Alignment of `s` in bytes (its largest field alignment, at least 4).
pub const fn struct_align(s: &StructDesc) -> usize {
    let mut align = 4;
    let mut rest = s.fields;
    while let Some((field, tail)) = rest.split_first() {
        let (_, a) = field_layout(field.ty);
        if a > align {
            align = a;
        }
        rest = tail;
    }
    align
}

/// Size of `s` in bytes (the end of its last field, rounded up to its alignment).
pub const fn struct_size(s: &StructDesc) -> usize {
    round_up(field_offset_at(s, s.fields.len()), struct_align(s))
}

/// Size in bytes of one element of a binding (the struct of a uniform, one array element).
pub const fn element_size(e: Element) -> usize {
    match e {
        Element::Struct(s) | Element::StructArray(s) => struct_size(s),
        Element::Array(t) => field_layout(t).0,
        Element::Atomics => 4,
    }
}

/// Byte-wise string equality in `const` contexts.
pub(crate) const fn same_name(a: &str, b: &str) -> bool {
    let (mut a, mut b) = (a.as_bytes(), b.as_bytes());
    loop {
        match (a.split_first(), b.split_first()) {
            (None, None) => return true,
            (Some((x, at)), Some((y, bt))) if *x == *y => {
                a = at;
                b = bt;
            }
            _ => return false,
        }
    }
}

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
pub const fn binding(name: &str) -> Option<&'static BindingDesc> {
    let mut rest = BINDINGS;
    while let Some((b, tail)) = rest.split_first() {
        if same_name(b.name, name) {
            return Some(b);
        }
        rest = tail;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bindings_are_dense_and_fit_webgpu_defaults() {
        for (i, b) in BINDINGS.iter().enumerate() {
            assert_eq!(b.binding as usize, i, "{} is out of order", b.name);
        }
        // The megakernel can declare every binding but the wavefront model's `paths`; each
        // wavefront stage declares its own subset, at most 8 storage buffers too (checked for every
        // example in `kernel::wavefront`'s tests).
        let storage = BINDINGS
            .iter()
            .filter(|b| b.kind != ResourceKind::Uniform && b.name != "paths")
            .count();
        assert!(
            storage <= 8,
            "{storage} storage buffers exceed WebGPU's default limit of 8"
        );
    }
}
