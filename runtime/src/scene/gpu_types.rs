//! Host mirrors of the ABI's GPU structs ([`FrameUniforms`], [`GpuInstance`]), the layout of any
//! [`abi`] struct computed from the table itself, and the record offsets ([`record`]) and constants
//! the encoders use, taken from the table.
//!
//! The ABI table (`rtc_compiler::abi`) is the one definition of every struct the kernel and the host
//! share. This file does not restate it: [`struct_size`] and [`field_offset`] (the table's own
//! `const fn`s, re-exported) compute the WGSL storage-buffer layout (scalars aligned to 4, `vec2` to
//! 8, `vec3` and `vec4` to 16; a struct's size rounded up to its largest alignment) straight from
//! [`abi::StructDesc`], and compile-time asserts tie
//! every field of the Rust mirrors to it. A unit test builds the same structs as naga types and checks
//! sizes and offsets with `naga::proc::Layouter`, and the mirror of the tile uniform,
//! `gpu::TileParams`, is checked against [`abi::TILE`] the same way.
//!
//! Compile-time asserts also tie `rtc_bvh::quantized`'s records and reference bits, the texel
//! formats and the slot encoders to the table.
//!
//! Invariants: the mirrors are `#[repr(C)]` + `bytemuck::Pod`, without implicit padding; a change to
//! the ABI table that the mirrors or encoders do not follow fails to compile.

use bytemuck::{Pod, Zeroable};
use rtc_compiler::abi;

pub use rtc_compiler::abi::{element_size, field_offset, struct_align, struct_size};

/// `FrameUniforms` ([`abi::FRAME`]): per-scene constants, one uniform buffer.
///
/// Every field is a `u32`; offsets follow the ABI field order (4 bytes apart). See the field docs
/// for what the runtime writes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct FrameUniforms {
    /// Samples per pixel one pass takes (`CompiledScene::samples_per_pass`).
    pub samples_per_pass: u32,
    /// Samples per pixel in total (the scene's `samples`, or the override).
    pub total_samples: u32,
    /// The scene's `seed`.
    pub seed: u32,
    /// Index of the scene-level BVH's header record in `nodes` (`rtc_bvh::quantized`).
    pub tlas_root: u32,
    /// Entries of `instances` (objects in the scene-level BVH).
    pub instance_count: u32,
    /// Lights in the light table.
    pub light_count: u32,
    /// Word offset in `params` of the light table (`light_count` pairs `[type_id, offset]`).
    pub light_table: u32,
    /// Entries of the medium table.
    pub medium_count: u32,
    /// Word offset in `params` of the medium table (instance slots of objects with a `@medium`
    /// material).
    pub medium_table: u32,
    /// Type id of the camera.
    pub camera_type: u32,
    /// Word offset of the camera instance in `params`.
    pub camera_offset: u32,
    /// Type id of the background (0 without one; the kernel then never reads it).
    pub background_type: u32,
    /// Word offset of the background instance (0 without one).
    pub background_offset: u32,
    /// Path slots of the wavefront model's `paths` per tile (the stride of its chunk-major
    /// records, the same for every tile; 0 for the megakernel, which has none).
    pub path_slots: u32,
    /// Passes one dispatch of the megakernel adds (`Renderer::render` batches a still render's
    /// passes: each invocation runs `passes_per_dispatch × samples_per_pass` samples of its
    /// pixel, adding each pass to `accum` as a dispatch of its own would); 1 for the stage
    /// kernels, which ignore it.
    pub passes_per_dispatch: u32,
}

/// `GpuInstance` ([`abi::INSTANCE`]): one object of the scene, 128 bytes.
///
/// | bytes | field | contents |
/// |---|---|---|
/// | 0..48 | `world_to_object` | rows 0..3 of the inverse of the object-to-world matrix; translation in `w` |
/// | 48..96 | `object_to_world` | rows 0..3 of the object-to-world matrix; translation in `w` |
/// | 96 | `geometry_type` | [`GpuInstance::MESH_GEOMETRY`] for a triangle mesh, else the custom geometry type's id |
/// | 100 | `geometry_offset` | word offset of the custom geometry instance in `params` (0 for meshes) |
/// | 104 | `material_type` | the material type's id |
/// | 108 | `material_offset` | word offset of the material instance in `params` |
/// | 112 | `blas_root` | index in `nodes` of the mesh BVH's header record (`rtc_bvh::quantized`; 0 for custom geometry) |
/// | 116 | `triangle_offset` | first triangle slot of the mesh in `triangles` (0 for custom geometry) |
/// | 120 | `flags` | [`GpuInstance::FLAG_ANY_HIT`], [`GpuInstance::FLAG_SECONDARY_RAYS`], [`GpuInstance::FLAG_MEDIUM`], [`GpuInstance::FLAG_CULL_BACK`] |
/// | 124 | `object` | the object's index in the scene (scene `object` entries in order, then model instances); in a flattened group's record, the slot of its first member's record |
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuInstance {
    /// Rows of the world-to-object affine transform.
    pub world_to_object: [[f32; 4]; 3],
    /// Rows of the object-to-world affine transform.
    pub object_to_world: [[f32; 4]; 3],
    /// [`GpuInstance::MESH_GEOMETRY`] or a custom geometry type id.
    pub geometry_type: u32,
    /// Word offset of the custom geometry instance.
    pub geometry_offset: u32,
    /// Material type id.
    pub material_type: u32,
    /// Word offset of the material instance.
    pub material_offset: u32,
    /// Root node of the mesh BVH.
    pub blas_root: u32,
    /// First triangle slot of the mesh.
    pub triangle_offset: u32,
    /// Material feature bits.
    pub flags: u32,
    /// The object's index in the scene.
    pub object: u32,
}

impl GpuInstance {
    /// `geometry_type` of a built-in triangle mesh ([`abi::MESH_GEOMETRY`]).
    pub const MESH_GEOMETRY: u32 = abi::MESH_GEOMETRY;
    /// `flags`: the material has an `@any_hit` program ([`abi::FLAG_ANY_HIT`]).
    pub const FLAG_ANY_HIT: u32 = abi::FLAG_ANY_HIT;
    /// `flags`: the material has a `@secondary_rays` program ([`abi::FLAG_SECONDARY_RAYS`]).
    pub const FLAG_SECONDARY_RAYS: u32 = abi::FLAG_SECONDARY_RAYS;
    /// `flags`: the material has a `@medium` program ([`abi::FLAG_MEDIUM`]).
    pub const FLAG_MEDIUM: u32 = abi::FLAG_MEDIUM;
    /// `flags`: traversal ignores hits on the back faces ([`abi::FLAG_CULL_BACK`]).
    pub const FLAG_CULL_BACK: u32 = abi::FLAG_CULL_BACK;
}

/// Element offsets of the ABI's records ([`abi::records`]) for the encoders, each looked up in the
/// table at compile time (a field the table lacks fails to compile).
pub mod record {
    use rtc_compiler::abi;

    /// Words of a mesh record.
    pub const MESH_WORDS: usize = abi::MESH.stride as usize;
    /// `mesh.node_base`
    pub const MESH_NODE_BASE: usize = abi::MESH.offset_of("node_base") as usize;
    /// `mesh.slot_base`
    pub const MESH_SLOT_BASE: usize = abi::MESH.offset_of("slot_base") as usize;
    /// `mesh.slot_count`
    pub const MESH_SLOT_COUNT: usize = abi::MESH.offset_of("slot_count") as usize;
    /// Words of a texture record.
    pub const TEXTURE_WORDS: usize = abi::TEXTURE.stride as usize;
    /// `texture.texel_base`
    pub const TEXTURE_TEXEL_BASE: usize = abi::TEXTURE.offset_of("texel_base") as usize;
    /// `texture.width`
    pub const TEXTURE_WIDTH: usize = abi::TEXTURE.offset_of("width") as usize;
    /// `texture.height`
    pub const TEXTURE_HEIGHT: usize = abi::TEXTURE.offset_of("height") as usize;
    /// `texture.format`
    pub const TEXTURE_FORMAT: usize = abi::TEXTURE.offset_of("format") as usize;
    /// `texture.sampler`
    pub const TEXTURE_SAMPLER: usize = abi::TEXTURE.offset_of("sampler") as usize;
    /// Words of a light table entry.
    pub const LIGHT_ENTRY_WORDS: usize = abi::LIGHT_ENTRY.stride as usize;
    /// `light_entry.type_id`
    pub const LIGHT_ENTRY_TYPE_ID: usize = abi::LIGHT_ENTRY.offset_of("type_id") as usize;
    /// `light_entry.offset`
    pub const LIGHT_ENTRY_OFFSET: usize = abi::LIGHT_ENTRY.offset_of("offset") as usize;
    /// Words of a medium table entry.
    pub const MEDIUM_ENTRY_WORDS: usize = abi::MEDIUM_ENTRY.stride as usize;
    /// `medium_entry.slot`
    pub const MEDIUM_ENTRY_SLOT: usize = abi::MEDIUM_ENTRY.offset_of("slot") as usize;
    /// `vec4f`s of a triangle slot in `triangles`.
    pub const TRIANGLE_VEC4S: usize = abi::TRIANGLE.stride as usize;
    /// `vec4u`s of a triangle slot in `attributes`.
    pub const ATTRIBUTE_VEC4S: usize = abi::ATTRIBUTE.stride as usize;
    /// `vec4u`s of a slot's `VERTEX_EXTRA` record in `attributes`.
    pub const VERTEX_EXTRA_VEC4S: usize = abi::VERTEX_EXTRA.stride as usize;

    /// Bytes of one record of `desc` (its stride times its binding's element size).
    pub const fn bytes(desc: &abi::RecordDesc) -> u64 {
        let element = match abi::binding(desc.binding) {
            Some(b) => super::element_size(b.element),
            None => 0,
        };
        desc.stride as u64 * element as u64
    }
}

// Every record offset the encoders use names a field of the table (`offset_of` is `u32::MAX` for
// a name it lacks).
const _: () = {
    use record::*;
    assert!(MESH_NODE_BASE < MESH_WORDS);
    assert!(MESH_SLOT_BASE < MESH_WORDS);
    assert!(MESH_SLOT_COUNT < MESH_WORDS);
    assert!(TEXTURE_TEXEL_BASE < TEXTURE_WORDS);
    assert!(TEXTURE_WIDTH < TEXTURE_WORDS);
    assert!(TEXTURE_HEIGHT < TEXTURE_WORDS);
    assert!(TEXTURE_FORMAT < TEXTURE_WORDS);
    assert!(TEXTURE_SAMPLER < TEXTURE_WORDS);
    assert!(LIGHT_ENTRY_TYPE_ID < LIGHT_ENTRY_WORDS && LIGHT_ENTRY_OFFSET < LIGHT_ENTRY_WORDS);
    assert!(MEDIUM_ENTRY_SLOT < MEDIUM_ENTRY_WORDS);
};

// The encoders write the triangle and attribute slots field by field in this order (`encode.rs`).
const _: () = assert!(abi::TRIANGLE.offset_of("v0") == 0);
const _: () = assert!(abi::TRIANGLE.offset_of("v1") == 1);
const _: () = assert!(abi::TRIANGLE.offset_of("v2") == 2);
const _: () = assert!(record::TRIANGLE_VEC4S == 3);
const _: () = assert!(abi::ATTRIBUTE.offset_of("normals_uv0") == 0);
const _: () = assert!(abi::ATTRIBUTE.offset_of("uv12") == 1);
const _: () = assert!(record::ATTRIBUTE_VEC4S == 2);
// `encode::extra_entries` writes tangents, second uvs, colours, in that order.
const _: () = assert!(record::VERTEX_EXTRA_VEC4S == 3);
const _: () = assert!(abi::VERTEX_EXTRA.offset_of("tangents") == 0);
const _: () = assert!(abi::VERTEX_EXTRA.offset_of("uv1") == 1);
const _: () = assert!(abi::VERTEX_EXTRA.offset_of("colors") == 2);
const _: () = assert!(record::bytes(&abi::TRIANGLE) == 48);
const _: () = assert!(record::bytes(&abi::ATTRIBUTE) == 32);
// The texel words of each format (`assets::texture`).
const _: () = assert!(
    crate::assets::TextureFormat::Rgba16F.words_per_texel() == abi::RGBA16F_TEXEL_WORDS as usize
);
const _: () = assert!(crate::assets::TextureFormat::Rgba8Srgb.words_per_texel() == 1);
const _: () = assert!(crate::assets::TextureFormat::Rgba8Unorm.words_per_texel() == 1);

// The node records and reference bits of `rtc_bvh::quantized` are the ABI's.
const _: () = assert!(rtc_bvh::quantized::LEAF_BIT == abi::NODE_LEAF_BIT);
const _: () = assert!(rtc_bvh::quantized::COUNT_SHIFT == abi::NODE_COUNT_SHIFT);
const _: () = assert!(rtc_bvh::quantized::MAX_LEAF_COUNT == abi::NODE_COUNT_MASK);
const _: () = assert!(rtc_bvh::quantized::MAX_FIRST == abi::NODE_FIRST_MASK);
const _: () = assert!(std::mem::size_of::<rtc_bvh::NodeRecord>() == struct_size(&abi::NODE));
const _: () = assert!(std::mem::align_of::<rtc_bvh::NodeRecord>() == struct_align(&abi::NODE));
const _: () = assert!(struct_size(&abi::NODE_HEADER) == struct_size(&abi::NODE));
const _: () = assert!(struct_size(&abi::NODE_INNER) == struct_size(&abi::NODE));

macro_rules! assert_field {
    ($ty:ty, $field:ident, $desc:expr, $name:literal) => {
        const _: () = assert!(std::mem::offset_of!($ty, $field) == field_offset(&$desc, $name));
    };
}

const _: () = assert!(std::mem::size_of::<FrameUniforms>() == struct_size(&abi::FRAME));
const _: () = assert!(abi::FRAME.fields.len() == 15);
assert_field!(
    FrameUniforms,
    samples_per_pass,
    abi::FRAME,
    "samples_per_pass"
);
assert_field!(FrameUniforms, total_samples, abi::FRAME, "total_samples");
assert_field!(FrameUniforms, seed, abi::FRAME, "seed");
assert_field!(FrameUniforms, tlas_root, abi::FRAME, "tlas_root");
assert_field!(FrameUniforms, instance_count, abi::FRAME, "instance_count");
assert_field!(FrameUniforms, light_count, abi::FRAME, "light_count");
assert_field!(FrameUniforms, light_table, abi::FRAME, "light_table");
assert_field!(FrameUniforms, medium_count, abi::FRAME, "medium_count");
assert_field!(FrameUniforms, medium_table, abi::FRAME, "medium_table");
assert_field!(FrameUniforms, camera_type, abi::FRAME, "camera_type");
assert_field!(FrameUniforms, camera_offset, abi::FRAME, "camera_offset");
assert_field!(
    FrameUniforms,
    background_type,
    abi::FRAME,
    "background_type"
);
assert_field!(
    FrameUniforms,
    background_offset,
    abi::FRAME,
    "background_offset"
);
assert_field!(FrameUniforms, path_slots, abi::FRAME, "path_slots");
assert_field!(
    FrameUniforms,
    passes_per_dispatch,
    abi::FRAME,
    "passes_per_dispatch"
);

const _: () = assert!(std::mem::size_of::<GpuInstance>() == struct_size(&abi::INSTANCE));
const _: () = assert!(std::mem::size_of::<GpuInstance>() == 128);
const _: () = assert!(std::mem::align_of::<GpuInstance>() == struct_align(&abi::INSTANCE));
const _: () = assert!(abi::INSTANCE.fields.len() == 14);
assert_field!(
    GpuInstance,
    world_to_object,
    abi::INSTANCE,
    "world_to_object_0"
);
const _: () = assert!(field_offset(&abi::INSTANCE, "world_to_object_1") == 16);
const _: () = assert!(field_offset(&abi::INSTANCE, "world_to_object_2") == 32);
assert_field!(
    GpuInstance,
    object_to_world,
    abi::INSTANCE,
    "object_to_world_0"
);
const _: () = assert!(field_offset(&abi::INSTANCE, "object_to_world_1") == 64);
const _: () = assert!(field_offset(&abi::INSTANCE, "object_to_world_2") == 80);
assert_field!(GpuInstance, geometry_type, abi::INSTANCE, "geometry_type");
assert_field!(
    GpuInstance,
    geometry_offset,
    abi::INSTANCE,
    "geometry_offset"
);
assert_field!(GpuInstance, material_type, abi::INSTANCE, "material_type");
assert_field!(
    GpuInstance,
    material_offset,
    abi::INSTANCE,
    "material_offset"
);
assert_field!(GpuInstance, blas_root, abi::INSTANCE, "blas_root");
assert_field!(
    GpuInstance,
    triangle_offset,
    abi::INSTANCE,
    "triangle_offset"
);
assert_field!(GpuInstance, flags, abi::INSTANCE, "flags");
assert_field!(GpuInstance, object, abi::INSTANCE, "object");

use rtc_bvh::quantized::{QuantizedHeader, QuantizedNode};
const _: () = assert!(std::mem::size_of::<QuantizedHeader>() == struct_size(&abi::NODE_HEADER));
assert_field!(QuantizedHeader, origin, abi::NODE_HEADER, "origin");
assert_field!(QuantizedHeader, root, abi::NODE_HEADER, "root");
assert_field!(QuantizedHeader, scale, abi::NODE_HEADER, "scale");
assert_field!(QuantizedHeader, reserved, abi::NODE_HEADER, "reserved");
const _: () = assert!(std::mem::size_of::<QuantizedNode>() == struct_size(&abi::NODE_INNER));
assert_field!(QuantizedNode, left_box, abi::NODE_INNER, "left_box");
assert_field!(QuantizedNode, left, abi::NODE_INNER, "left");
assert_field!(QuantizedNode, right_box, abi::NODE_INNER, "right_box");
assert_field!(QuantizedNode, right, abi::NODE_INNER, "right");
// The header's and inner node's fields overlay the kernel's `GpuNode` view.
const _: () = assert!(field_offset(&abi::NODE, "a") == field_offset(&abi::NODE_HEADER, "root"));
const _: () = assert!(field_offset(&abi::NODE, "max") == field_offset(&abi::NODE_HEADER, "scale"));
const _: () = assert!(field_offset(&abi::NODE, "a") == field_offset(&abi::NODE_INNER, "left"));
const _: () = assert!(field_offset(&abi::NODE, "b") == field_offset(&abi::NODE_INNER, "right"));
const _: () =
    assert!(field_offset(&abi::NODE, "max") == field_offset(&abi::NODE_INNER, "right_box"));

const _: () = assert!(std::mem::size_of::<crate::gpu::TileParams>() == struct_size(&abi::TILE));
assert_field!(crate::gpu::TileParams, origin, abi::TILE, "origin");
assert_field!(crate::gpu::TileParams, extent, abi::TILE, "extent");
assert_field!(crate::gpu::TileParams, image_size, abi::TILE, "image_size");
assert_field!(crate::gpu::TileParams, tile_index, abi::TILE, "tile_index");
assert_field!(crate::gpu::TileParams, frame, abi::TILE, "frame");

#[cfg(test)]
mod tests {
    use super::*;
    use naga::{Scalar, Span, StructMember, Type, TypeInner, VectorSize};
    use rtc_compiler::abi::{FieldType, StructDesc};

    /// Builds `s` as a naga struct, members placed with the Layouter's alignments (as any naga front
    /// end does), and returns `(size, [(name, offset)])` as the Layouter sees them.
    fn naga_layout(s: &StructDesc) -> (u32, Vec<(String, u32)>) {
        let mut module = naga::Module::default();
        let member_types: Vec<_> = s
            .fields
            .iter()
            .map(|f| {
                let (size, scalar) = match f.ty {
                    FieldType::U32 => (None, Scalar::U32),
                    FieldType::F32 => (None, Scalar::F32),
                    FieldType::Vec2U32 => (Some(VectorSize::Bi), Scalar::U32),
                    FieldType::Vec3F32 => (Some(VectorSize::Tri), Scalar::F32),
                    FieldType::Vec3U32 => (Some(VectorSize::Tri), Scalar::U32),
                    FieldType::Vec4F32 => (Some(VectorSize::Quad), Scalar::F32),
                    FieldType::Vec4U32 => (Some(VectorSize::Quad), Scalar::U32),
                };
                let inner = match size {
                    None => TypeInner::Scalar(scalar),
                    Some(size) => TypeInner::Vector { size, scalar },
                };
                module
                    .types
                    .insert(Type { name: None, inner }, Span::UNDEFINED)
            })
            .collect();
        let mut layouter = naga::proc::Layouter::default();
        layouter
            .update(module.to_ctx())
            .expect("member types lay out");
        let mut offset = 0u32;
        let mut align = naga::proc::Alignment::ONE;
        let mut members = Vec::new();
        for (f, &ty) in s.fields.iter().zip(&member_types) {
            let l = layouter[ty];
            offset = l.alignment.round_up(offset);
            align = align.max(l.alignment);
            members.push(StructMember {
                name: Some(f.name.to_string()),
                ty,
                binding: None,
                offset,
            });
            offset += l.size;
        }
        let span = align.round_up(offset);
        let handle = module.types.insert(
            Type {
                name: Some(s.name.to_string()),
                inner: TypeInner::Struct { members, span },
            },
            Span::UNDEFINED,
        );
        layouter.update(module.to_ctx()).expect("struct lays out");
        let TypeInner::Struct { members, .. } = &module.types[handle].inner else {
            unreachable!("inserted a struct")
        };
        let offsets = members
            .iter()
            .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
            .collect();
        (layouter[handle].size, offsets)
    }

    fn check(s: &StructDesc, rust_size: usize, rust_offsets: &[(&str, usize)]) {
        let (size, offsets) = naga_layout(s);
        assert_eq!(size as usize, rust_size, "size of {}", s.name);
        assert_eq!(size as usize, struct_size(s), "struct_size({})", s.name);
        for (name, offset) in &offsets {
            assert_eq!(
                *offset as usize,
                field_offset(s, name),
                "{}.{name}: field_offset",
                s.name
            );
        }
        for (name, want) in rust_offsets {
            let found = offsets
                .iter()
                .find(|(n, _)| n == name)
                .unwrap_or_else(|| panic!("{}.{name} is not in the ABI", s.name));
            assert_eq!(found.1 as usize, *want, "{}.{name}", s.name);
        }
    }

    #[test]
    fn mirrors_match_naga_layouts_of_the_abi() {
        use std::mem::{offset_of, size_of};
        check(
            &abi::FRAME,
            size_of::<FrameUniforms>(),
            &[
                (
                    "samples_per_pass",
                    offset_of!(FrameUniforms, samples_per_pass),
                ),
                ("total_samples", offset_of!(FrameUniforms, total_samples)),
                ("seed", offset_of!(FrameUniforms, seed)),
                ("tlas_root", offset_of!(FrameUniforms, tlas_root)),
                ("instance_count", offset_of!(FrameUniforms, instance_count)),
                ("light_count", offset_of!(FrameUniforms, light_count)),
                ("light_table", offset_of!(FrameUniforms, light_table)),
                ("medium_count", offset_of!(FrameUniforms, medium_count)),
                ("medium_table", offset_of!(FrameUniforms, medium_table)),
                ("camera_type", offset_of!(FrameUniforms, camera_type)),
                ("camera_offset", offset_of!(FrameUniforms, camera_offset)),
                (
                    "background_type",
                    offset_of!(FrameUniforms, background_type),
                ),
                (
                    "background_offset",
                    offset_of!(FrameUniforms, background_offset),
                ),
                ("path_slots", offset_of!(FrameUniforms, path_slots)),
                (
                    "passes_per_dispatch",
                    offset_of!(FrameUniforms, passes_per_dispatch),
                ),
            ],
        );
        let w2o = offset_of!(GpuInstance, world_to_object);
        let o2w = offset_of!(GpuInstance, object_to_world);
        check(
            &abi::INSTANCE,
            size_of::<GpuInstance>(),
            &[
                ("world_to_object_0", w2o),
                ("world_to_object_1", w2o + 16),
                ("world_to_object_2", w2o + 32),
                ("object_to_world_0", o2w),
                ("object_to_world_1", o2w + 16),
                ("object_to_world_2", o2w + 32),
                ("geometry_type", offset_of!(GpuInstance, geometry_type)),
                ("geometry_offset", offset_of!(GpuInstance, geometry_offset)),
                ("material_type", offset_of!(GpuInstance, material_type)),
                ("material_offset", offset_of!(GpuInstance, material_offset)),
                ("blas_root", offset_of!(GpuInstance, blas_root)),
                ("triangle_offset", offset_of!(GpuInstance, triangle_offset)),
                ("flags", offset_of!(GpuInstance, flags)),
                ("object", offset_of!(GpuInstance, object)),
            ],
        );
        check(&abi::NODE, size_of::<rtc_bvh::NodeRecord>(), &[]);
        check(
            &abi::NODE_HEADER,
            size_of::<QuantizedHeader>(),
            &[
                ("origin", offset_of!(QuantizedHeader, origin)),
                ("root", offset_of!(QuantizedHeader, root)),
                ("scale", offset_of!(QuantizedHeader, scale)),
                ("reserved", offset_of!(QuantizedHeader, reserved)),
            ],
        );
        check(
            &abi::NODE_INNER,
            size_of::<QuantizedNode>(),
            &[
                ("left_box", offset_of!(QuantizedNode, left_box)),
                ("left", offset_of!(QuantizedNode, left)),
                ("right_box", offset_of!(QuantizedNode, right_box)),
                ("right", offset_of!(QuantizedNode, right)),
            ],
        );
    }

    /// `gpu::TileParams` (the dispatcher's record) is the ABI's `TileParams`: same fields, same
    /// order, same offsets, same size.
    #[test]
    fn tile_params_match_the_abi_field_list() {
        use crate::gpu::TileParams;
        use std::mem::{offset_of, size_of};
        let rust = [
            ("origin", offset_of!(TileParams, origin)),
            ("extent", offset_of!(TileParams, extent)),
            ("image_size", offset_of!(TileParams, image_size)),
            ("tile_index", offset_of!(TileParams, tile_index)),
            ("frame", offset_of!(TileParams, frame)),
        ];
        let names: Vec<&str> = abi::TILE.fields.iter().map(|f| f.name).collect();
        assert_eq!(names, rust.map(|(n, _)| n), "field order");
        check(&abi::TILE, size_of::<TileParams>(), &rust);
        // And the WGSL text the dispatcher documents parses to the same layout.
        let module = naga::front::wgsl::parse_str(crate::gpu::TILE_PARAMS_WGSL).expect("parses");
        let (_, ty) = module
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some("TileParams"))
            .expect("declared");
        let TypeInner::Struct { members, .. } = &ty.inner else {
            panic!("a struct")
        };
        let wgsl: Vec<(String, usize)> = members
            .iter()
            .map(|m| (m.name.clone().unwrap_or_default(), m.offset as usize))
            .collect();
        let want: Vec<(String, usize)> = rust.iter().map(|(n, o)| (n.to_string(), *o)).collect();
        assert_eq!(wgsl, want);
    }

    #[test]
    fn element_sizes() {
        let size = |name: &str| element_size(abi::binding(name).expect("binding").element);
        assert_eq!(size("frame"), 60);
        assert_eq!(size("tile"), 32);
        assert_eq!(size("nodes"), 32);
        assert_eq!(size("instances"), 128);
        assert_eq!(size("triangles"), 16);
        assert_eq!(size("attributes"), 16);
        assert_eq!(size("params"), 4);
        assert_eq!(size("texels"), 4);
        assert_eq!(size("accum"), 16);
        assert_eq!(size("counters"), 4);
    }

    /// Every `u32` constant and record accessor of the generated `rtc:abi` module (what the kernel
    /// reads) against the values and offsets the runtime encodes with.
    #[test]
    fn generated_rtc_abi_matches_the_runtime_encoders() {
        use rtc_compiler::kernel::generated::{abi_module, parse};
        let text = abi_module();
        let runtime: Vec<(&str, u32)> = vec![
            ("NODE_LEAF_BIT", rtc_bvh::quantized::LEAF_BIT),
            ("NODE_COUNT_SHIFT", rtc_bvh::quantized::COUNT_SHIFT),
            ("NODE_COUNT_MASK", rtc_bvh::quantized::MAX_LEAF_COUNT),
            ("NODE_FIRST_MASK", rtc_bvh::quantized::MAX_FIRST),
            ("NODE_BOUND_BITS", 16),
            ("NODE_BOUND_MAX", 0xffff),
            ("MESH_GEOMETRY", GpuInstance::MESH_GEOMETRY),
            ("FLAG_ANY_HIT", GpuInstance::FLAG_ANY_HIT),
            ("FLAG_SECONDARY_RAYS", GpuInstance::FLAG_SECONDARY_RAYS),
            ("FLAG_MEDIUM", GpuInstance::FLAG_MEDIUM),
            ("FLAG_CULL_BACK", GpuInstance::FLAG_CULL_BACK),
            ("TEXTURE_FORMAT_RGBA8_SRGB", 0),
            ("TEXTURE_FORMAT_RGBA16F", 1),
            ("TEXTURE_FORMAT_RGBA8_UNORM", 2),
            (
                "RGBA16F_TEXEL_WORDS",
                crate::assets::TextureFormat::Rgba16F.words_per_texel() as u32,
            ),
            ("TEXTURE_WRAP_MASK", 3),
            ("TEXTURE_WRAP_V_SHIFT", 2),
            ("TEXTURE_WRAP_CLAMP", 1),
            ("TEXTURE_WRAP_MIRROR", 2),
            ("TEXTURE_NEAREST", 16),
            ("COUNTER_NONFINITE", 0),
            ("COUNTER_RAYS", 1),
            ("COUNTER_SHADOW_OVERFLOW", 3),
            (
                "COUNTER_WORDS",
                (crate::scene::upload_for_tests::COUNTER_BYTES / 4) as u32,
            ),
            ("MESH_STRIDE", record::MESH_WORDS as u32),
            ("TEXTURE_STRIDE", record::TEXTURE_WORDS as u32),
            ("LIGHT_ENTRY_STRIDE", record::LIGHT_ENTRY_WORDS as u32),
            ("MEDIUM_ENTRY_STRIDE", record::MEDIUM_ENTRY_WORDS as u32),
            ("TRIANGLE_STRIDE", record::TRIANGLE_VEC4S as u32),
            ("ATTRIBUTE_STRIDE", record::ATTRIBUTE_VEC4S as u32),
            ("VERTEX_EXTRA_STRIDE", record::VERTEX_EXTRA_VEC4S as u32),
        ];
        let generated = parse::constants(&text);
        let as_owned: Vec<(String, u32)> =
            runtime.iter().map(|(n, v)| (n.to_string(), *v)).collect();
        assert_eq!(generated, as_owned);
        // Which format word the texture encoder writes for each format, as the kernel tests it.
        assert_eq!(abi::TEXTURE_FORMAT_RGBA8_SRGB, 0);
        assert_eq!(abi::TEXTURE_FORMAT_RGBA16F, 1);

        // Accessors: (name, load, stride, offset) as the encoders lay the records out.
        let want: Vec<(&str, &str, usize, usize)> = vec![
            ("mesh_node_base", "load_param", 1, record::MESH_NODE_BASE),
            ("mesh_slot_base", "load_param", 1, record::MESH_SLOT_BASE),
            ("mesh_slot_count", "load_param", 1, record::MESH_SLOT_COUNT),
            ("mesh_reserved", "load_param", 1, 3),
            (
                "texture_texel_base",
                "load_param",
                1,
                record::TEXTURE_TEXEL_BASE,
            ),
            ("texture_width", "load_param", 1, record::TEXTURE_WIDTH),
            ("texture_height", "load_param", 1, record::TEXTURE_HEIGHT),
            ("texture_format", "load_param", 1, record::TEXTURE_FORMAT),
            ("texture_sampler", "load_param", 1, record::TEXTURE_SAMPLER),
            (
                "light_entry_type_id",
                "load_param",
                1,
                record::LIGHT_ENTRY_TYPE_ID,
            ),
            (
                "light_entry_offset",
                "load_param",
                1,
                record::LIGHT_ENTRY_OFFSET,
            ),
            (
                "medium_entry_slot",
                "load_param",
                1,
                record::MEDIUM_ENTRY_SLOT,
            ),
            // `encode.rs` pushes v0, v1, v2 per slot, then the two attribute words.
            (
                "triangle_v0",
                "load_triangle_vertex",
                record::TRIANGLE_VEC4S,
                0,
            ),
            (
                "triangle_v1",
                "load_triangle_vertex",
                record::TRIANGLE_VEC4S,
                1,
            ),
            (
                "triangle_v2",
                "load_triangle_vertex",
                record::TRIANGLE_VEC4S,
                2,
            ),
            (
                "attribute_normals_uv0",
                "load_attribute",
                record::ATTRIBUTE_VEC4S,
                0,
            ),
            (
                "attribute_uv12",
                "load_attribute",
                record::ATTRIBUTE_VEC4S,
                1,
            ),
            // Addressed by the index an `attribute` record holds (stride 1: no multiplier).
            ("vertex_extra_tangents", "load_attribute", 1, 0),
            ("vertex_extra_uv1", "load_attribute", 1, 1),
            ("vertex_extra_colors", "load_attribute", 1, 2),
        ];
        let got: Vec<(String, String, usize, usize)> = parse::accessors(&text)
            .into_iter()
            .map(|a| (a.name, a.load, a.stride as usize, a.offset as usize))
            .collect();
        let want: Vec<(String, String, usize, usize)> = want
            .into_iter()
            .map(|(n, l, s, o)| (n.to_string(), l.to_string(), s, o))
            .collect();
        assert_eq!(got, want);
    }
}
