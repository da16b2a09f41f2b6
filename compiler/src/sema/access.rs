//! Field access, swizzles, indexing and struct literals.
//!
//! Invariants: a struct literal becomes a [`ExprKind::Compose`] with one component per field in
//! declaration order (omitted fields as their [`ExprKind::Value`] default), or an error expression
//! after E0307/E0407/E0408; a constant index is checked against the length (E0406); a swizzle of one
//! component has the scalar type.

use super::error::{ExprError, NameError, NameKind};
use super::expr::{parse_swizzle, Checker};
use super::hir::{ConstValue, ExprId, ExprKind};
use super::types::{ScalarKind, Type, TypeTable};
use super::{Def, Found};
use crate::diag::suggest;
use crate::source::Span;
use crate::syntax::ast;

impl<'a> Checker<'_, 'a> {
    pub(super) fn field(&mut self, base: ast::ExprId, field: &ast::Ident, span: Span) -> ExprId {
        let b = self.expr(base, None);
        let ty = self.ty(b);
        match self.cx.p.types.get(ty) {
            Type::Error => self.error_expr(span),
            Type::Struct(s) => {
                self.cx.ensure_fields(s);
                let st = &self.cx.p.structs[s];
                match st.field_index(&field.name) {
                    Some(i) => {
                        let fty = st.fields[i].ty;
                        self.alloc(
                            ExprKind::Field {
                                base: b,
                                index: i as u32,
                            },
                            fty,
                            span,
                        )
                    }
                    None => {
                        let suggestion = suggest::closest(
                            &field.name,
                            st.fields.iter().map(|f| f.name.as_str()),
                        )
                        .map(str::to_string);
                        let decl = Some(st.span);
                        self.err(NameError::UnknownField {
                            span: field.span,
                            ty,
                            field: field.name.clone(),
                            suggestion,
                            decl,
                        });
                        self.error_expr(span)
                    }
                }
            }
            Type::Vector { size, scalar } => match parse_swizzle(&field.name, size) {
                Some((pattern, len)) => {
                    let rty = self.cx.p.types.scalar_or_vector(len, scalar);
                    self.alloc(
                        ExprKind::Swizzle {
                            base: b,
                            pattern,
                            len,
                        },
                        rty,
                        span,
                    )
                }
                None => {
                    self.err(ExprError::BadSwizzle {
                        span: field.span,
                        ty,
                        swizzle: field.name.clone(),
                    });
                    self.error_expr(span)
                }
            },
            _ => {
                self.err(NameError::UnknownField {
                    span: field.span,
                    ty,
                    field: field.name.clone(),
                    suggestion: None,
                    decl: None,
                });
                self.error_expr(span)
            }
        }
    }

    pub(super) fn index(&mut self, base: ast::ExprId, index: ast::ExprId, span: Span) -> ExprId {
        let b = self.expr(base, None);
        let i = self.expr(index, None);
        let (bt, it) = (self.ty(b), self.ty(i));
        if TypeTable::is_error(bt) {
            return self.error_expr(span);
        }
        let (elem, len) = match self.cx.p.types.get(bt) {
            Type::Array { elem, len } => (elem, len),
            Type::Vector { size, scalar } => (TypeTable::scalar(scalar), u32::from(size)),
            Type::Matrix { cols, rows } => (
                self.cx.p.types.scalar_or_vector(rows, ScalarKind::F32),
                u32::from(cols),
            ),
            _ => {
                self.err(ExprError::NotIndexable {
                    span: self.span(b),
                    ty: bt,
                });
                return self.error_expr(span);
            }
        };
        if TypeTable::is_error(it) {
            return self.error_expr(span);
        }
        if it != TypeTable::I32 && it != TypeTable::U32 {
            self.coerce(i, TypeTable::U32);
            return self.error_expr(span);
        }
        if let Ok(v) = self.try_eval(i) {
            let idx = match v {
                ConstValue::Scalar(super::hir::Scalar::I32(x)) => i64::from(x),
                ConstValue::Scalar(super::hir::Scalar::U32(x)) => i64::from(x),
                _ => 0,
            };
            if idx < 0 || idx >= i64::from(len) {
                self.err(ExprError::IndexOutOfRange {
                    span: self.span(i),
                    index: idx,
                    len,
                    ty: bt,
                });
                return self.error_expr(span);
            }
        }
        self.alloc(ExprKind::Index { base: b, index: i }, elem, span)
    }

    pub(super) fn struct_lit(
        &mut self,
        name: &'a ast::Ident,
        fields: &'a [ast::FieldInit],
        span: Span,
    ) -> ExprId {
        let found = self.cx.lookup(self.module, &name.name);
        let s = match found {
            Found::Def(Def::Struct(s)) => s,
            other => {
                let kind = match other {
                    Found::Def(Def::Fn(_)) => Some(NameKind::Function),
                    Found::Def(Def::Const(_)) => Some(NameKind::Const),
                    Found::Def(Def::Scene(_)) => Some(NameKind::Scene),
                    Found::Builtin(_) => Some(NameKind::Builtin),
                    Found::Type(_) => Some(NameKind::Type),
                    _ => None,
                };
                match kind {
                    Some(kind) => self.err(NameError::NotAStruct {
                        span: name.span,
                        name: name.name.clone(),
                        kind,
                    }),
                    None => self.cx.report_lookup(self.module, name, other),
                }
                for f in fields {
                    self.expr(f.value, None);
                }
                return self.error_expr(span);
            }
        };
        self.cx.ensure_fields(s);
        if !self.cx.ensure_defaults(s, name.span) {
            for f in fields {
                self.expr(f.value, None);
            }
            return self.error_expr(span);
        }
        let ty = self.cx.p.types.intern(Type::Struct(s));
        let n = self.cx.p.structs[s].fields.len();
        let mut given: Vec<Option<(ExprId, Span)>> = vec![None; n];
        let mut ok = true;
        for f in fields {
            let st = &self.cx.p.structs[s];
            let Some(i) = st.field_index(&f.name.name) else {
                let suggestion =
                    suggest::closest(&f.name.name, st.fields.iter().map(|x| x.name.as_str()))
                        .map(str::to_string);
                let decl = Some(st.span);
                self.err(NameError::UnknownField {
                    span: f.name.span,
                    ty,
                    field: f.name.name.clone(),
                    suggestion,
                    decl,
                });
                self.expr(f.value, None);
                ok = false;
                continue;
            };
            let fty = st.fields[i].ty;
            let v = self.expect(f.value, fty);
            if TypeTable::is_error(self.ty(v)) {
                ok = false;
            }
            if let Some((_, first)) = given[i] {
                self.err(ExprError::DuplicateField {
                    span: f.name.span,
                    first,
                    name: f.name.name.clone(),
                });
                ok = false;
                continue;
            }
            given[i] = Some((v, f.name.span));
        }
        let mut components = Vec::with_capacity(n);
        let mut missing = Vec::new();
        for (i, g) in given.iter().enumerate() {
            let field = &self.cx.p.structs[s].fields[i];
            match (g, &field.default) {
                (Some((v, _)), _) => components.push(*v),
                (None, Some(d)) => {
                    let (d, fty) = (d.clone(), field.ty);
                    components.push(self.alloc(ExprKind::Value(d), fty, span));
                }
                (None, None) => missing.push(field.name.clone()),
            }
        }
        if !missing.is_empty() {
            let decl = self.cx.p.structs[s].span;
            self.err(ExprError::MissingFields {
                span: name.span.to(span),
                ty,
                missing,
                decl,
            });
            return self.error_expr(span);
        }
        if !ok {
            return self.error_expr(span);
        }
        self.alloc(ExprKind::Compose { components }, ty, span)
    }
}
