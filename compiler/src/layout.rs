//! Host-shareable layout of language types, and packing of constant values into 32-bit words.
//!
//! Instance data of every role struct (camera, geometry, material, light, background) lives in the
//! kernel's `params: array<u32>` buffer. This module decides where each field goes — WGSL's storage
//! layout rules (scalars aligned to 4, `vec2` to 8, `vec3` and `vec4` to 16, matrices as arrays of
//! column vectors, arrays with a stride rounded up to the element's alignment, structs aligned to their
//! largest member) — and packs [`ConstValue`]s accordingly. The generated loader functions read words
//! at exactly these offsets, and the runtime packs with [`pack`]: one layout, computed in one place.
//!
//! Representation: `f32` and `i32` as their bits, `bool` as 0 or 1, `texture` and `mesh` handles as the
//! word offset of their record in `params` (resolved by the caller through [`Handles`]).
//!
//! Invariants: offsets and sizes are multiples of 4; a packed value occupies exactly `size / 4` words.

use crate::sema::hir::{ConstValue, MeshAsset, Program, Scalar, TextureAsset};
use crate::sema::types::{ScalarKind, Type, TypeId};

/// Size and alignment of a type, in bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Size in bytes (a multiple of the alignment for arrays and structs).
    pub size: u32,
    /// Alignment in bytes.
    pub align: u32,
}

fn round_up(x: u32, align: u32) -> u32 {
    x.div_ceil(align) * align
}

/// The layout of `ty`.
pub fn layout(program: &Program, ty: TypeId) -> Layout {
    match program.types.get(ty) {
        Type::Scalar(_) | Type::Texture | Type::Mesh => Layout { size: 4, align: 4 },
        Type::Vector { size, .. } => match size {
            2 => Layout { size: 8, align: 8 },
            3 => Layout {
                size: 12,
                align: 16,
            },
            _ => Layout {
                size: 16,
                align: 16,
            },
        },
        Type::Matrix { cols, rows } => {
            let col = if rows == 2 {
                Layout { size: 8, align: 8 }
            } else {
                Layout {
                    size: 16,
                    align: 16,
                }
            };
            Layout {
                size: col.size * cols as u32,
                align: col.align,
            }
        }
        Type::Array { elem, len } => {
            let e = layout(program, elem);
            Layout {
                size: round_up(e.size, e.align) * len,
                align: e.align,
            }
        }
        Type::Struct(s) => {
            let mut offset = 0;
            let mut align = 4;
            for f in &program.structs[s].fields {
                let l = layout(program, f.ty);
                offset = round_up(offset, l.align) + l.size;
                align = align.max(l.align);
            }
            Layout {
                size: round_up(offset.max(4), align),
                align,
            }
        }
        Type::Error | Type::Void | Type::String => Layout { size: 4, align: 4 },
    }
}

/// Byte offsets of a struct's fields.
pub fn field_offsets(program: &Program, ty: TypeId) -> Vec<u32> {
    let Type::Struct(s) = program.types.get(ty) else {
        return Vec::new();
    };
    let mut offset = 0;
    program.structs[s]
        .fields
        .iter()
        .map(|f| {
            let l = layout(program, f.ty);
            offset = round_up(offset, l.align);
            let at = offset;
            offset += l.size;
            at
        })
        .collect()
}

/// Resolves handle values to the word offsets of their records in `params`.
pub trait Handles {
    /// The record offset of a mesh.
    fn mesh(&mut self, asset: &MeshAsset) -> u32;
    /// The record offset of a texture.
    fn texture(&mut self, asset: &TextureAsset) -> u32;
}

/// Handles that are all 0 (for code paths that never meet handles, and tests).
pub struct NoHandles;

impl Handles for NoHandles {
    fn mesh(&mut self, _: &MeshAsset) -> u32 {
        0
    }
    fn texture(&mut self, _: &TextureAsset) -> u32 {
        0
    }
}

fn scalar_word(s: Scalar) -> u32 {
    match s {
        Scalar::Bool(b) => b as u32,
        Scalar::I32(i) => i as u32,
        Scalar::U32(u) => u,
        Scalar::F32(f) => f.to_bits(),
    }
}

/// Packs `value` of type `ty` into `out`, starting at word `base` (the caller has sized `out`).
pub fn pack_into(
    program: &Program,
    ty: TypeId,
    value: &ConstValue,
    out: &mut [u32],
    base: usize,
    h: &mut dyn Handles,
) {
    let mut put = |i: usize, w: u32| {
        if let Some(slot) = out.get_mut(base + i) {
            *slot = w;
        }
    };
    match (program.types.get(ty), value) {
        (Type::Scalar(_), ConstValue::Scalar(s)) => put(0, scalar_word(*s)),
        (Type::Vector { size, .. }, ConstValue::Vector { comps, .. }) => {
            for (i, c) in comps.iter().take(size as usize).enumerate() {
                put(i, scalar_word(*c));
            }
        }
        (Type::Matrix { cols, rows }, ConstValue::Matrix { data, .. }) => {
            let col_words = if rows == 2 { 2 } else { 4 };
            for (c, column) in data.iter().take(cols as usize).enumerate() {
                for (r, v) in column.iter().take(rows as usize).enumerate() {
                    put(c * col_words + r, v.to_bits());
                }
            }
        }
        (Type::Array { elem, .. }, ConstValue::Array(items)) => {
            let e = layout(program, elem);
            let stride = (round_up(e.size, e.align) / 4) as usize;
            for (i, item) in items.iter().enumerate() {
                pack_into(program, elem, item, out, base + i * stride, h);
            }
        }
        (Type::Struct(s), ConstValue::Struct { fields, .. }) => {
            let offsets = field_offsets(program, ty);
            for ((f, v), off) in program.structs[s].fields.iter().zip(fields).zip(offsets) {
                pack_into(program, f.ty, v, out, base + (off / 4) as usize, h);
            }
        }
        (Type::Texture, ConstValue::Texture(t)) => put(0, h.texture(t)),
        (Type::Mesh, ConstValue::Mesh(m)) => put(0, h.mesh(m)),
        _ => {}
    }
}

/// Packs a value of type `ty` into a new word vector of exactly its size.
pub fn pack(program: &Program, ty: TypeId, value: &ConstValue, h: &mut dyn Handles) -> Vec<u32> {
    let mut out = vec![0u32; (layout(program, ty).size / 4) as usize];
    pack_into(program, ty, value, &mut out, 0, h);
    out
}

/// The scalar kind stored at a word, for loaders: `bool` is stored as a `u32`.
pub fn stored_kind(kind: ScalarKind) -> ScalarKind {
    if kind == ScalarKind::Bool {
        ScalarKind::U32
    } else {
        kind
    }
}
