//! The records the host writes into the kernel's plain-array bindings, and every constant and bit
//! field of the ABI: the one definition the kernel's `rtc:abi` module, the runtime's encoders and
//! `manifest.json` are all derived from.
//!
//! A [`RecordDesc`] is a fixed-size record in one binding: `params` records (mesh, texture, light
//! table entry, medium table entry) are addressed by the word offset of their first word; the slot
//! records of `triangles` and `attributes` by their slot index (element `slot * stride + offset`).
//! The kernel reads a field with the generated accessor `<record>_<field>(address)`, which the
//! lowering expands to exactly that one load (no function call is emitted).
//!
//! The BVH node records of `nodes` are structs ([`super::NODE`], viewed as [`NODE_HEADER`] or
//! [`NODE_INNER`]); their child references are the bit fields of [`NODE_REFERENCE`].
//!
//! Invariants: field offsets lie inside the record's stride and do not overlap (unit test); every
//! constant has a unique name; the bit fields of one word are disjoint and cover it.

use super::{Field, FieldType, StructDesc};

/// How a record is addressed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Addressing {
    /// By the word offset of its first word in `params` (element `address + offset`).
    WordOffset,
    /// By its slot index (element `address * stride + offset`).
    Slot,
}

/// One field of a record: `offset` elements from the record's start.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordField {
    /// Its name (the accessor is `<record>_<field>`).
    pub name: &'static str,
    /// Offset in elements of the binding (words for `params`, `vec4`s for slots).
    pub offset: u32,
    /// Its type: the binding's element type.
    pub ty: FieldType,
    /// What it holds.
    pub doc: &'static str,
}

/// A fixed-size record in one of the kernel's array bindings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordDesc {
    /// Its name (the prefix of its accessors; upper-cased, of its `_STRIDE` constant).
    pub name: &'static str,
    /// The binding it lives in ([`super::BINDINGS`]).
    pub binding: &'static str,
    /// How the kernel addresses it.
    pub addressing: Addressing,
    /// Its size in elements of the binding.
    pub stride: u32,
    /// Its fields, by offset.
    pub fields: &'static [RecordField],
    /// What it is, where it is and who writes it.
    pub doc: &'static str,
}

impl RecordDesc {
    /// The field called `name`.
    pub fn field(&self, name: &str) -> Option<&'static RecordField> {
        self.fields.iter().find(|f| f.name == name)
    }

    /// The offset of field `name`, or `u32::MAX` when there is none (for `const` contexts on the
    /// host, which assert the offset is inside the stride).
    pub const fn offset_of(&self, name: &str) -> u32 {
        let mut rest = self.fields;
        while let Some((f, tail)) = rest.split_first() {
            if super::same_name(f.name, name) {
                return f.offset;
            }
            rest = tail;
        }
        u32::MAX
    }

    /// The name of the stride constant in `rtc:abi`.
    pub fn stride_const(&self) -> String {
        format!("{}_STRIDE", self.name.to_ascii_uppercase())
    }
}

const fn word(name: &'static str, offset: u32, doc: &'static str) -> RecordField {
    RecordField {
        name,
        offset,
        ty: FieldType::U32,
        doc,
    }
}

/// A mesh value of the scene (`mesh` in the language is its word offset in `params`).
pub const MESH: RecordDesc = RecordDesc {
    name: "mesh",
    binding: "params",
    addressing: Addressing::WordOffset,
    stride: 4,
    fields: &[
        word("node_base", 0, "index in `nodes` of the mesh BVH's header record"),
        word("slot_base", 1, "the mesh's first triangle slot in `triangles` and `attributes`"),
        word("slot_count", 2, "the mesh's triangle slots (a triangle may occupy several)"),
        word("reserved", 3, "0"),
    ],
    doc: "a `mesh` value: where its BVH and its triangle slots are (params, written first, one per mesh in the scene)",
};

/// A texture value of the scene (`texture` in the language is its word offset in `params`).
pub const TEXTURE: RecordDesc = RecordDesc {
    name: "texture",
    binding: "params",
    addressing: Addressing::WordOffset,
    stride: 5,
    fields: &[
        word("texel_base", 0, "the texture's first word in `texels`"),
        word("width", 1, "width in texels"),
        word("height", 2, "height in texels"),
        word("format", 3, "TEXTURE_FORMAT_RGBA8_SRGB, _RGBA8_UNORM or _RGBA16F"),
        word(
            "sampler",
            4,
            "wrap mode of u (bits 0-1) and v (bits 2-3: TEXTURE_WRAP_*), TEXTURE_NEAREST; 0 = repeat, bilinear",
        ),
    ],
    doc: "a `texture` value: where its texels are, its size, format and sampler state (params, after the mesh records)",
};

/// An entry of the light table (`FrameUniforms.light_table`, `light_count` entries).
pub const LIGHT_ENTRY: RecordDesc = RecordDesc {
    name: "light_entry",
    binding: "params",
    addressing: Addressing::WordOffset,
    stride: 2,
    fields: &[
        word("type_id", 0, "the light type's id"),
        word("offset", 1, "word offset of the light instance in `params`"),
    ],
    doc: "one light of the scene, in scene order (params, at `FrameUniforms.light_table`)",
};

/// An entry of the medium table (`FrameUniforms.medium_table`, `medium_count` entries).
pub const MEDIUM_ENTRY: RecordDesc = RecordDesc {
    name: "medium_entry",
    binding: "params",
    addressing: Addressing::WordOffset,
    stride: 1,
    fields: &[word(
        "slot",
        0,
        "slot in `instances` of an object whose material has `@medium`",
    )],
    doc: "one object with a `@medium` material, in object order (params, last, at `FrameUniforms.medium_table`)",
};

/// A triangle slot's vertex positions.
pub const TRIANGLE: RecordDesc = RecordDesc {
    name: "triangle",
    binding: "triangles",
    addressing: Addressing::Slot,
    stride: 3,
    fields: &[
        RecordField {
            name: "v0",
            offset: 0,
            ty: FieldType::Vec4F32,
            doc: "first vertex (object space) in xyz; w: the triangle's index in its mesh, as bits",
        },
        RecordField {
            name: "v1",
            offset: 1,
            ty: FieldType::Vec4F32,
            doc: "second vertex in xyz; w = 0, or in a slot of flattened static objects the object's \
                  index in the group plus one, as bits (its record is the group record's `object` plus that \
                  index minus one)",
        },
        RecordField {
            name: "v2",
            offset: 2,
            ty: FieldType::Vec4F32,
            doc: "third vertex in xyz; w = 0",
        },
    ],
    doc: "one triangle slot of a mesh, in the mesh BVH's leaf order from the mesh's `slot_base`",
};

/// A triangle slot's shading attributes.
pub const ATTRIBUTE: RecordDesc = RecordDesc {
    name: "attribute",
    binding: "attributes",
    addressing: Addressing::Slot,
    stride: 2,
    fields: &[
        RecordField {
            name: "normals_uv0",
            offset: 0,
            ty: FieldType::Vec4U32,
            doc: "octahedral normals of the 3 vertices (snorm16x2 each), then the first vertex's uv (f16x2)",
        },
        RecordField {
            name: "uv12",
            offset: 1,
            ty: FieldType::Vec4U32,
            doc: "uvs of the second and third vertices (f16x2 each), then the index in `attributes` of the slot's `vertex_extra` record (0: none), then 0",
        },
    ],
    doc: "one triangle slot's normals and uvs, parallel to `triangles`",
};

/// A triangle slot's extra vertex attributes, for meshes that have them (glTF `TANGENT`,
/// `TEXCOORD_1`, `COLOR_0`): addressed by the index its `ATTRIBUTE` record holds.
pub const VERTEX_EXTRA: RecordDesc = RecordDesc {
    name: "vertex_extra",
    binding: "attributes",
    addressing: Addressing::WordOffset,
    stride: 3,
    fields: &[
        RecordField {
            name: "tangents",
            offset: 0,
            ty: FieldType::Vec4U32,
            doc: "octahedral tangents of the 3 vertices (snorm16x2 each), then flags: bit k set when vertex k's bitangent sign is negative, bit 3 + k when it has a tangent",
        },
        RecordField {
            name: "uv1",
            offset: 1,
            ty: FieldType::Vec4U32,
            doc: "second uv set of the 3 vertices (f16x2 each), then 0",
        },
        RecordField {
            name: "colors",
            offset: 2,
            ty: FieldType::Vec4U32,
            doc: "linear RGBA colours of the 3 vertices (unorm8x4 each, white without colours), then 0",
        },
    ],
    doc: "a triangle slot's tangents, second uvs and colours (in `attributes`, after every slot's `attribute` record; only meshes that have them)",
};

/// Every record, in the order `params` holds the params-resident ones.
pub const RECORDS: &[&RecordDesc] = &[
    &MESH,
    &TEXTURE,
    &LIGHT_ENTRY,
    &MEDIUM_ENTRY,
    &TRIANGLE,
    &ATTRIBUTE,
    &VERTEX_EXTRA,
];

/// A BVH header record (record 0 of every BVH in `nodes`): the `GpuNode` viewed as header.
pub const NODE_HEADER: StructDesc = StructDesc {
    name: "NodeHeader",
    doc: "record 0 of a BVH: the quantisation frame (a bound q on axis i is origin[i] + q * scale[i]) and the root's child reference",
    fields: &[
        Field {
            name: "origin",
            ty: FieldType::Vec3F32,
        },
        Field {
            name: "root",
            ty: FieldType::U32,
        },
        Field {
            name: "scale",
            ty: FieldType::Vec3F32,
        },
        Field {
            name: "reserved",
            ty: FieldType::U32,
        },
    ],
};

/// An inner-node record (record `r >= 1` of a BVH): both children's quantised boxes and references.
pub const NODE_INNER: StructDesc = StructDesc {
    name: "NodeInner",
    doc: "record r >= 1 of a BVH: both children of one inner node; a box is six 16-bit bounds packed low half first [lo.x | lo.y << 16, lo.z | hi.x << 16, hi.y | hi.z << 16]",
    fields: &[
        Field {
            name: "left_box",
            ty: FieldType::Vec3U32,
        },
        Field {
            name: "left",
            ty: FieldType::U32,
        },
        Field {
            name: "right_box",
            ty: FieldType::Vec3U32,
        },
        Field {
            name: "right",
            ty: FieldType::U32,
        },
    ],
};

/// One bit field of a 32-bit word: `(word >> shift) & mask`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct BitField {
    /// Its name.
    pub name: &'static str,
    /// Position of its lowest bit.
    pub shift: u32,
    /// Its mask after shifting.
    pub mask: u32,
    /// What it holds.
    pub doc: &'static str,
}

/// A 32-bit word made of bit fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct BitFieldsDesc {
    /// Its name.
    pub name: &'static str,
    /// Its fields (disjoint, together covering the word).
    pub fields: &'static [BitField],
    /// What it is.
    pub doc: &'static str,
}

/// A BVH child reference (`NodeHeader.root`, `NodeInner.left`/`right`): with `leaf` clear, the
/// whole word is an inner node's record index (`>= 1`) relative to the BVH's header.
pub const NODE_REFERENCE: BitFieldsDesc = BitFieldsDesc {
    name: "node_reference",
    doc: "a BVH child reference: leaf clear: the word is the inner node's record index (>= 1) relative to the BVH's header; leaf set: count and first give the leaf's slots",
    fields: &[
        BitField {
            name: "first",
            shift: 0,
            mask: (1 << 27) - 1,
            doc: "a leaf's first slot (triangle slot relative to the mesh's slot_base, or instance slot)",
        },
        BitField {
            name: "count",
            shift: 27,
            mask: 15,
            doc: "a leaf's slot count",
        },
        BitField {
            name: "leaf",
            shift: 31,
            mask: 1,
            doc: "set: a leaf",
        },
    ],
};

/// A quantised box bound: 16 bits, two per word.
pub const NODE_BOUND: BitFieldsDesc = BitFieldsDesc {
    name: "node_bound_pair",
    doc: "a word of a quantised box: two 16-bit bounds, the first in the low half",
    fields: &[
        BitField {
            name: "low",
            shift: 0,
            mask: 0xffff,
            doc: "the first bound",
        },
        BitField {
            name: "high",
            shift: 16,
            mask: 0xffff,
            doc: "the second bound",
        },
    ],
};

/// Every bit-field word.
pub const BIT_FIELDS: &[&BitFieldsDesc] = &[&NODE_REFERENCE, &NODE_BOUND];

const fn bits(desc: &BitFieldsDesc, index: usize) -> BitField {
    desc.fields[index]
}

/// `NodeReference.leaf` as a mask on the word.
pub const NODE_LEAF_BIT: u32 = bits(&NODE_REFERENCE, 2).mask << bits(&NODE_REFERENCE, 2).shift;
/// Position of a leaf reference's slot count.
pub const NODE_COUNT_SHIFT: u32 = bits(&NODE_REFERENCE, 1).shift;
/// A leaf reference's slot count mask (after shifting): the largest slot count.
pub const NODE_COUNT_MASK: u32 = bits(&NODE_REFERENCE, 1).mask;
/// A leaf reference's first-slot mask: the largest first slot.
pub const NODE_FIRST_MASK: u32 = bits(&NODE_REFERENCE, 0).mask;
/// Bits of one quantised bound.
pub const NODE_BOUND_BITS: u32 = bits(&NODE_BOUND, 1).shift;
/// The largest quantised bound (the mask of one bound).
pub const NODE_BOUND_MAX: u32 = bits(&NODE_BOUND, 0).mask;
/// `GpuInstance.geometry_type` of a built-in triangle mesh.
pub const MESH_GEOMETRY: u32 = 0xffff_ffff;
/// `GpuInstance.flags`: the material has an `@any_hit` program.
pub const FLAG_ANY_HIT: u32 = 1;
/// `GpuInstance.flags`: the material has a `@secondary_rays` program.
pub const FLAG_SECONDARY_RAYS: u32 = 2;
/// `GpuInstance.flags`: the material has a `@medium` program.
pub const FLAG_MEDIUM: u32 = 4;
/// `GpuInstance.flags`: traversal ignores hits on the object's back faces (a single-sided glTF
/// material; the kernel tests it only when `CULL_BACK_FACES`). Back and front are those of
/// `Hit.front_face`: a hit is on the back when the ray runs along the triangle's geometric normal
/// in world space (the object-space normal under the inverse transpose, so a mirroring transform
/// keeps the front, as glTF's reversed winding under a negative determinant asks); for a shadow
/// ray the sides swap (the light looks the other way).
pub const FLAG_CULL_BACK: u32 = 8;
/// `texture.format`: 8-bit sRGB RGBA, one word per texel (unorm4x8, red in the low byte).
pub const TEXTURE_FORMAT_RGBA8_SRGB: u32 = 0;
/// `texture.format`: linear RGBA half floats, two words per texel (f16x2 red/green, blue/alpha).
pub const TEXTURE_FORMAT_RGBA16F: u32 = 1;
/// `texture.format`: 8-bit linear RGBA, one word per texel (packed as `TEXTURE_FORMAT_RGBA8_SRGB`).
pub const TEXTURE_FORMAT_RGBA8_UNORM: u32 = 2;
/// Words per texel of `TEXTURE_FORMAT_RGBA16F`.
pub const RGBA16F_TEXEL_WORDS: u32 = 2;
/// `texture.sampler`: the mask of one axis's wrap mode (u in bits 0-1, v shifted by
/// `TEXTURE_WRAP_V_SHIFT`); wrap mode 0 is repeat.
pub const TEXTURE_WRAP_MASK: u32 = 3;
/// `texture.sampler`: the shift of v's wrap mode.
pub const TEXTURE_WRAP_V_SHIFT: u32 = 2;
/// `texture.sampler` wrap mode: coordinates are clamped to the edge texels.
pub const TEXTURE_WRAP_CLAMP: u32 = 1;
/// `texture.sampler` wrap mode: the texture repeats mirrored every other period.
pub const TEXTURE_WRAP_MIRROR: u32 = 2;
/// `texture.sampler`: nearest-texel lookup instead of bilinear.
pub const TEXTURE_NEAREST: u32 = 16;
/// Index in `counters` of the count of non-finite samples replaced by zero.
pub const COUNTER_NONFINITE: u32 = 0;
/// Index in `counters` of the count of rays traced (camera, secondary and shadow).
pub const COUNTER_RAYS: u32 = 1;
/// Index in `counters` of the wavefront model's count of shadow queries beyond the
/// `SHADOW_QUERIES` one shading step can record (each was answered "unoccluded").
pub const COUNTER_SHADOW_OVERFLOW: u32 = 3;
/// Words of `counters` the host allocates (and zeroes with `accum`).
pub const COUNTER_WORDS: u32 = 4;

/// A named `u32` constant of the ABI.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Constant {
    /// Its name in `rtc:abi` and the manifest.
    pub name: &'static str,
    /// Its value.
    pub value: u32,
    /// What it means.
    pub doc: &'static str,
}

const fn c(name: &'static str, value: u32, doc: &'static str) -> Constant {
    Constant { name, value, doc }
}

/// Every constant of the ABI (the record strides are generated from [`RECORDS`] besides these).
pub const CONSTANTS: &[Constant] = &[
    c(
        "NODE_LEAF_BIT",
        NODE_LEAF_BIT,
        "a BVH child reference with this bit set is a leaf",
    ),
    c(
        "NODE_COUNT_SHIFT",
        NODE_COUNT_SHIFT,
        "position of a leaf reference's slot count",
    ),
    c(
        "NODE_COUNT_MASK",
        NODE_COUNT_MASK,
        "mask of a leaf reference's slot count, after shifting",
    ),
    c(
        "NODE_FIRST_MASK",
        NODE_FIRST_MASK,
        "mask of a leaf reference's first slot",
    ),
    c(
        "NODE_BOUND_BITS",
        NODE_BOUND_BITS,
        "bits of one quantised box bound (two per word, low half first)",
    ),
    c(
        "NODE_BOUND_MAX",
        NODE_BOUND_MAX,
        "the largest quantised bound: the far side of a BVH's quantisation frame",
    ),
    c(
        "MESH_GEOMETRY",
        MESH_GEOMETRY,
        "GpuInstance.geometry_type of a built-in triangle mesh",
    ),
    c(
        "FLAG_ANY_HIT",
        FLAG_ANY_HIT,
        "GpuInstance.flags: the material has an @any_hit program",
    ),
    c(
        "FLAG_SECONDARY_RAYS",
        FLAG_SECONDARY_RAYS,
        "GpuInstance.flags: the material has a @secondary_rays program",
    ),
    c(
        "FLAG_MEDIUM",
        FLAG_MEDIUM,
        "GpuInstance.flags: the material has a @medium program",
    ),
    c(
        "FLAG_CULL_BACK",
        FLAG_CULL_BACK,
        "GpuInstance.flags: traversal ignores hits on the object's back faces",
    ),
    c(
        "TEXTURE_FORMAT_RGBA8_SRGB",
        TEXTURE_FORMAT_RGBA8_SRGB,
        "texture.format: 8-bit sRGB RGBA, one word per texel",
    ),
    c(
        "TEXTURE_FORMAT_RGBA16F",
        TEXTURE_FORMAT_RGBA16F,
        "texture.format: linear RGBA half floats, two words per texel",
    ),
    c(
        "TEXTURE_FORMAT_RGBA8_UNORM",
        TEXTURE_FORMAT_RGBA8_UNORM,
        "texture.format: 8-bit linear RGBA, one word per texel",
    ),
    c(
        "RGBA16F_TEXEL_WORDS",
        RGBA16F_TEXEL_WORDS,
        "words per texel of TEXTURE_FORMAT_RGBA16F",
    ),
    c(
        "TEXTURE_WRAP_MASK",
        TEXTURE_WRAP_MASK,
        "texture.sampler: mask of one axis's wrap mode (u in bits 0-1; 0 = repeat)",
    ),
    c(
        "TEXTURE_WRAP_V_SHIFT",
        TEXTURE_WRAP_V_SHIFT,
        "texture.sampler: shift of v's wrap mode",
    ),
    c(
        "TEXTURE_WRAP_CLAMP",
        TEXTURE_WRAP_CLAMP,
        "texture.sampler wrap mode: clamp to the edge texels",
    ),
    c(
        "TEXTURE_WRAP_MIRROR",
        TEXTURE_WRAP_MIRROR,
        "texture.sampler wrap mode: mirrored repeat",
    ),
    c(
        "TEXTURE_NEAREST",
        TEXTURE_NEAREST,
        "texture.sampler: nearest-texel lookup instead of bilinear",
    ),
    c(
        "COUNTER_NONFINITE",
        COUNTER_NONFINITE,
        "counters index: samples that were not finite and were replaced by zero",
    ),
    c(
        "COUNTER_RAYS",
        COUNTER_RAYS,
        "counters index: rays traced (camera, secondary and shadow)",
    ),
    c(
        "COUNTER_SHADOW_OVERFLOW",
        COUNTER_SHADOW_OVERFLOW,
        "counters index (wavefront): shadow queries beyond what one shading step records, answered unoccluded",
    ),
    c("COUNTER_WORDS", COUNTER_WORDS, "words of counters"),
];

/// The constant called `name`.
pub fn constant(name: &str) -> Option<u32> {
    CONSTANTS.iter().find(|c| c.name == name).map(|c| c.value)
}

/// A record accessor of `rtc:abi`: reads field `field` of `record`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Accessor {
    /// The record.
    pub record: &'static RecordDesc,
    /// The field.
    pub field: &'static RecordField,
}

impl Accessor {
    /// The accessor's function name, `<record>_<field>`.
    pub fn name(&self) -> String {
        format!("{}_{}", self.record.name, self.field.name)
    }
}

/// Every record accessor, in table order.
pub fn accessors() -> impl Iterator<Item = Accessor> {
    RECORDS.iter().flat_map(|r| {
        r.fields.iter().map(move |f| Accessor {
            record: r,
            field: f,
        })
    })
}

/// The accessor called `name`.
pub fn accessor(name: &str) -> Option<Accessor> {
    accessors().find(|a| a.name() == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_fit_their_stride_and_bindings() {
        for r in RECORDS {
            let b = super::super::binding(r.binding).expect("record binding exists");
            let element = match b.element {
                super::super::Element::Array(t) => t,
                other => panic!("{}: binding {} holds {other:?}", r.name, r.binding),
            };
            let mut seen = vec![false; r.stride as usize];
            for f in r.fields {
                assert_eq!(f.ty, element, "{}.{}", r.name, f.name);
                let slot = seen
                    .get_mut(f.offset as usize)
                    .expect("offset inside the stride");
                assert!(!*slot, "{}.{} overlaps", r.name, f.name);
                *slot = true;
            }
        }
    }

    #[test]
    fn bit_fields_are_disjoint_and_cover_the_word() {
        for d in BIT_FIELDS {
            let mut covered = 0u64;
            for f in d.fields {
                let m = u64::from(f.mask) << f.shift;
                assert!(m <= u64::from(u32::MAX), "{}.{}", d.name, f.name);
                assert_eq!(covered & m, 0, "{}.{} overlaps", d.name, f.name);
                covered |= m;
            }
            assert_eq!(
                covered,
                u64::from(u32::MAX),
                "{} leaves bits unused",
                d.name
            );
        }
    }

    #[test]
    fn names_are_unique() {
        let mut names: Vec<String> = CONSTANTS.iter().map(|c| c.name.to_string()).collect();
        names.extend(RECORDS.iter().map(|r| r.stride_const()));
        names.extend(accessors().map(|a| a.name()));
        let n = names.len();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), n);
        assert_eq!(NODE_LEAF_BIT, 0x8000_0000);
        assert_eq!(NODE_FIRST_MASK, 0x7ff_ffff);
    }
}
