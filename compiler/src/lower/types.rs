//! HIR types to naga types.
//!
//! Invariants:
//! - Each HIR type maps to one naga type, memoised ([`Lowerer::ty`]); naga's `UniqueArena` interns the
//!   anonymous ones (scalars, vectors, matrices, arrays) anyway, structs are named and unique per HIR
//!   struct.
//! - Struct members get explicit offsets computed with `naga::proc::Layouter` after their member types
//!   are in the arena: each member at the next multiple of its alignment, the struct's size rounded up
//!   to its largest member alignment. These are WGSL's storage (std430-like) rules, so a struct without
//!   `bool` members is host-shareable and its layout is what the host packs.
//! - The handle types `texture` and `mesh` are `u32` (offsets of their records in the kernel's
//!   parameter buffer). `string`, `void` and the error type have no GPU representation.

use super::builder::TypeCache;
use super::{LowerError, Lowerer, Unsupported};
use crate::sema::hir::StructId;
use crate::sema::types::{ScalarKind, Type, TypeId};
use crate::source::Span;
use naga::{Handle, Scalar, StructMember, TypeInner, VectorSize};

/// The naga scalar of a scalar kind.
pub(super) fn scalar(kind: ScalarKind) -> Scalar {
    match kind {
        ScalarKind::Bool => Scalar::BOOL,
        ScalarKind::I32 => Scalar::I32,
        ScalarKind::U32 => Scalar::U32,
        ScalarKind::F32 => Scalar::F32,
    }
}

/// The naga vector size of a width 2..=4 (`None` for 1 and anything else).
pub(super) fn vector_size(width: u8) -> Option<VectorSize> {
    match width {
        2 => Some(VectorSize::Bi),
        3 => Some(VectorSize::Tri),
        4 => Some(VectorSize::Quad),
        _ => None,
    }
}

impl Lowerer<'_> {
    /// The naga type of a HIR type (lowered and memoised on first use).
    pub fn ty(&mut self, id: TypeId) -> Result<Handle<naga::Type>, LowerError> {
        self.ty_at(id, Span::default())
    }

    /// [`Lowerer::ty`], reporting an unsupported type at `span`.
    pub(super) fn ty_at(
        &mut self,
        id: TypeId,
        span: Span,
    ) -> Result<Handle<naga::Type>, LowerError> {
        if let Some(h) = self.types.get(&id) {
            return Ok(*h);
        }
        let unsupported = || LowerError::Unsupported {
            what: Unsupported::Type(id),
            span,
        };
        let h = match self.program.types.get(id) {
            Type::Scalar(k) => TypeCache::scalar(&mut self.module, scalar(k)),
            Type::Vector { size, scalar: k } => {
                let size = vector_size(size).ok_or_else(unsupported)?;
                TypeCache::vector(&mut self.module, size, scalar(k))
            }
            Type::Matrix { cols, rows } => {
                let c = vector_size(cols).ok_or_else(unsupported)?;
                let r = vector_size(rows).ok_or_else(unsupported)?;
                TypeCache::matrix(&mut self.module, c, r)
            }
            Type::Array { elem, len } => {
                let base = self.ty_at(elem, span)?;
                let layout = self.layout(base);
                let stride = layout.alignment.round_up(layout.size);
                self.module.types.insert(
                    naga::Type {
                        name: None,
                        inner: TypeInner::Array {
                            base,
                            size: naga::ArraySize::Constant(
                                std::num::NonZeroU32::new(len).ok_or_else(unsupported)?,
                            ),
                            stride,
                        },
                    },
                    naga::Span::UNDEFINED,
                )
            }
            Type::Struct(s) => self.struct_type(s, span)?,
            Type::Texture | Type::Mesh => TypeCache::scalar(&mut self.module, Scalar::U32),
            Type::Error | Type::Void | Type::String => return Err(unsupported()),
        };
        self.types.insert(id, h);
        Ok(h)
    }

    /// The naga type of a HIR type used as a value: [`Lowerer::ty`], or `None` for `void`.
    pub(super) fn value_ty(
        &mut self,
        id: TypeId,
        span: Span,
    ) -> Result<Option<Handle<naga::Type>>, LowerError> {
        if self.program.types.get(id) == Type::Void {
            return Ok(None);
        }
        self.ty_at(id, span).map(Some)
    }

    fn struct_type(&mut self, s: StructId, span: Span) -> Result<Handle<naga::Type>, LowerError> {
        let program = self.program;
        let st = &program.structs[s];
        let mut member_types = Vec::with_capacity(st.fields.len());
        for field in &st.fields {
            member_types.push(self.ty_at(field.ty, span)?);
        }
        let fields = st
            .fields
            .iter()
            .zip(member_types)
            .map(|(f, ty)| (f.name.as_str(), ty));
        let struct_span = self.span(st.span);
        Ok(self.layout_struct(Some(&st.name), fields, struct_span))
    }

    /// Appends a named struct type whose members are laid out by naga's layouter (see the module doc).
    pub(super) fn layout_struct<'n>(
        &mut self,
        name: Option<&str>,
        fields: impl IntoIterator<Item = (&'n str, Handle<naga::Type>)>,
        span: naga::Span,
    ) -> Handle<naga::Type> {
        self.update_layouts();
        let mut offset = 0u32;
        let mut align = naga::proc::Alignment::ONE;
        let mut members = Vec::new();
        for (name, ty) in fields {
            let layout = self.layout(ty);
            offset = layout.alignment.round_up(offset);
            members.push(StructMember {
                name: Some(name.to_string()),
                ty,
                binding: None,
                offset,
            });
            offset = offset.saturating_add(layout.size);
            align = align.max(layout.alignment);
        }
        self.module.types.insert(
            naga::Type {
                name: name.map(str::to_string),
                inner: TypeInner::Struct {
                    members,
                    span: align.round_up(offset.max(1)),
                },
            },
            span,
        )
    }

    /// Brings the layouter up to date with the type arena (it only computes new types' layouts).
    /// Returns whether every type has a layout.
    pub(super) fn update_layouts(&mut self) -> bool {
        // Every type we insert has its members inserted first, so this cannot fail on our types; if a
        // starting module had a malformed type, the validator reports it later.
        self.layouter.update(self.module.to_ctx()).is_ok()
    }

    /// Size and alignment of a naga type, per naga's layouter (4 bytes, aligned to 4, for a type the
    /// layouter rejects; the validator reports such a module anyway).
    pub fn layout(&mut self, ty: Handle<naga::Type>) -> naga::proc::TypeLayout {
        if self.update_layouts() {
            self.layouter[ty]
        } else {
            naga::proc::TypeLayout {
                size: 4,
                alignment: naga::proc::Alignment::FOUR,
            }
        }
    }

    /// A scalar or vector type of `width` components of `kind` (for polyfills and the test entry).
    pub(super) fn sv_type(&mut self, width: u8, kind: ScalarKind) -> Handle<naga::Type> {
        match vector_size(width) {
            Some(size) => TypeCache::vector(&mut self.module, size, scalar(kind)),
            None => TypeCache::scalar(&mut self.module, scalar(kind)),
        }
    }
}
