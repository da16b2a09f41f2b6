//! Evaluated constants ([`ConstValue`]) as naga expressions.
//!
//! Two forms, chosen for readable output:
//! - a `const` item becomes a named naga [`naga::Constant`] (`const PI: f32 = 3.1415927f;` in WGSL) when
//!   its value can be written as a fully evaluated naga constant expression;
//! - otherwise, and for values written in place ([`crate::sema::hir::ExprKind::Value`]: defaults filled into
//!   struct literals), the value is built inline in the function: literals, `Compose`, or `ZeroValue`
//!   when every bit is zero.
//!
//! Invariants:
//! - naga rejects NaN and infinite literals, so a non-finite `f32` is written as `bitcast<f32>` of a
//!   private `u32` global holding its bits (a bit cast of a literal would be a WGSL constant
//!   expression, which may not be infinite). That is not a valid naga *constant* initialiser, so
//!   constants holding one (the prelude's `INF`, a default `tmax`) are inlined in each function that
//!   uses them instead.
//! - The shape of every composite comes from the HIR type, not from the value, so a value and its type
//!   that disagree are an [`LowerError::InvalidHir`], never a malformed module.

use super::builder::FnBuilder;
use super::{LowerError, Lowerer, Unsupported};
use crate::sema::hir::{ConstId, ConstValue, Scalar};
use crate::sema::types::{Type, TypeId};
use crate::source::Span;
use naga::{Expression, Handle, Literal};

/// A scalar as a naga literal, or `None` for a non-finite float.
pub(super) fn literal(s: Scalar) -> Option<Literal> {
    Some(match s {
        Scalar::Bool(b) => Literal::Bool(b),
        Scalar::I32(v) => Literal::I32(v),
        Scalar::U32(v) => Literal::U32(v),
        Scalar::F32(v) if v.is_finite() => Literal::F32(v),
        Scalar::F32(_) => return None,
    })
}

/// Whether every bit of the value is zero (so it can be written as a zero value).
fn all_zero(v: &ConstValue) -> bool {
    match v {
        ConstValue::Scalar(s) => match *s {
            Scalar::Bool(b) => !b,
            Scalar::I32(x) => x == 0,
            Scalar::U32(x) => x == 0,
            Scalar::F32(x) => x.to_bits() == 0,
        },
        ConstValue::Vector { len, comps } => comps
            .iter()
            .take(usize::from(*len))
            .all(|c| all_zero(&ConstValue::Scalar(*c))),
        ConstValue::Matrix { data, .. } => data.iter().flatten().all(|x| x.to_bits() == 0),
        ConstValue::Array(elems) => elems.iter().all(all_zero),
        ConstValue::Struct { fields, .. } => fields.iter().all(all_zero),
        _ => false,
    }
}

/// Whether every float in the value is finite (so it can be a naga constant).
fn all_finite(v: &ConstValue) -> bool {
    match v {
        ConstValue::Scalar(Scalar::F32(x)) => x.is_finite(),
        ConstValue::Scalar(_) => true,
        ConstValue::Vector { len, comps } => comps
            .iter()
            .take(usize::from(*len))
            .all(|c| all_finite(&ConstValue::Scalar(*c))),
        ConstValue::Matrix { data, .. } => data.iter().flatten().all(|x| x.is_finite()),
        ConstValue::Array(elems) => elems.iter().all(all_finite),
        ConstValue::Struct { fields, .. } => fields.iter().all(all_finite),
        _ => false,
    }
}

/// Where a constant's parts are appended: a function (through its builder) or the module's global
/// expressions (for naga constants).
trait Sink {
    fn push(&mut self, lw: &mut Lowerer<'_>, e: Expression, span: naga::Span)
        -> Handle<Expression>;
}

struct Local<'f>(&'f mut FnBuilder);

impl Sink for Local<'_> {
    fn push(
        &mut self,
        _lw: &mut Lowerer<'_>,
        e: Expression,
        span: naga::Span,
    ) -> Handle<Expression> {
        self.0.expr(e, span)
    }
}

struct Global;

impl Sink for Global {
    fn push(
        &mut self,
        lw: &mut Lowerer<'_>,
        e: Expression,
        span: naga::Span,
    ) -> Handle<Expression> {
        lw.module.global_expressions.append(e, span)
    }
}

impl Lowerer<'_> {
    /// The naga constant of a `const` item, or `None` when its value must be inlined (see the module
    /// doc).
    pub(super) fn constant(
        &mut self,
        c: ConstId,
    ) -> Result<Option<Handle<naga::Constant>>, LowerError> {
        if let Some(h) = self.consts.get(&c) {
            return Ok(*h);
        }
        let program = self.program;
        let item = &program.consts[c];
        let handle = if all_finite(&item.value) {
            let span = self.span(item.span);
            let ty = self.ty_at(item.ty, item.span)?;
            let init = self.build_value(&mut Global, &item.value, item.ty, item.span, span)?;
            Some(self.module.constants.append(
                naga::Constant {
                    name: Some(item.name.clone()),
                    ty,
                    init,
                },
                span,
            ))
        } else {
            None
        };
        self.consts.insert(c, handle);
        Ok(handle)
    }

    /// A constant value of HIR type `ty` built inline in the function of `fb`.
    pub(super) fn value_expr(
        &mut self,
        fb: &mut FnBuilder,
        value: &ConstValue,
        ty: TypeId,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let nspan = self.span(span);
        self.build_value(&mut Local(fb), value, ty, span, nspan)
    }

    /// An `f32` in a function, finite or not (non-finite values as `bitcast<f32>` of a private
    /// global holding the bits; see [`Lowerer::float_bits_global`]).
    pub(super) fn f32_expr(&mut self, fb: &mut FnBuilder, v: f32) -> Handle<Expression> {
        if v.is_finite() {
            fb.literal(Literal::F32(v))
        } else {
            let g = self.float_bits_global(v.to_bits());
            let gp = fb.expr(Expression::GlobalVariable(g), naga::Span::UNDEFINED);
            let bits = fb.load(gp, naga::Span::UNDEFINED);
            fb.cast(bits, naga::ScalarKind::Float, None, naga::Span::UNDEFINED)
        }
    }

    /// A private `u32` global initialised to `bits`, one per bit pattern, for non-finite floats.
    ///
    /// naga rejects NaN and infinite literals, and `bitcast<f32>(0x7f800000u)` of a literal is a WGSL
    /// constant expression, which must not evaluate to a non-finite value (Tint and Dawn reject it).
    /// Reading the bits from a variable makes the bit cast a run-time expression on every target.
    pub(super) fn float_bits_global(&mut self, bits: u32) -> Handle<naga::GlobalVariable> {
        if let Some(g) = self.float_bits.get(&bits) {
            return *g;
        }
        let u32_ty = super::builder::TypeCache::scalar(&mut self.module, naga::Scalar::U32);
        let init = self.module.global_expressions.append(
            Expression::Literal(Literal::U32(bits)),
            naga::Span::UNDEFINED,
        );
        let f = f32::from_bits(bits);
        let name = match (f.is_nan(), f.is_sign_negative()) {
            (true, _) => format!("F32_NAN_{bits:08X}"),
            (false, false) => "F32_INF".to_string(),
            (false, true) => "F32_NEG_INF".to_string(),
        };
        let g = self.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(name),
                space: naga::AddressSpace::Private,
                binding: None,
                ty: u32_ty,
                init: Some(init),
                memory_decorations: Default::default(),
            },
            naga::Span::UNDEFINED,
        );
        self.float_bits.insert(bits, g);
        g
    }

    fn build_value(
        &mut self,
        sink: &mut dyn Sink,
        value: &ConstValue,
        ty: TypeId,
        span: Span,
        nspan: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let mismatch = LowerError::InvalidHir {
            what: "a constant whose value does not match its type",
            span,
        };
        let hty = self.program.types.get(ty);
        if !matches!(value, ConstValue::Scalar(_)) && all_zero(value) {
            let t = self.ty_at(ty, span)?;
            return Ok(sink.push(self, Expression::ZeroValue(t), nspan));
        }
        match (value, hty) {
            (ConstValue::Scalar(s), Type::Scalar(_) | Type::Texture | Type::Mesh) => {
                Ok(self.scalar_value(sink, *s, nspan))
            }
            (ConstValue::Vector { len, comps }, Type::Vector { size, .. }) if *len == size => {
                let mut parts = Vec::with_capacity(usize::from(size));
                for c in comps.iter().take(usize::from(size)) {
                    parts.push(self.scalar_value(sink, *c, nspan));
                }
                let t = self.ty_at(ty, span)?;
                Ok(sink.push(
                    self,
                    Expression::Compose {
                        ty: t,
                        components: parts,
                    },
                    nspan,
                ))
            }
            (ConstValue::Matrix { cols, rows, data }, Type::Matrix { cols: c, rows: r })
                if (*cols, *rows) == (c, r) =>
            {
                let col_ty = self.sv_type(r, crate::sema::types::ScalarKind::F32);
                let mut columns = Vec::with_capacity(usize::from(c));
                for column in data.iter().take(usize::from(c)) {
                    let mut parts = Vec::with_capacity(usize::from(r));
                    for x in column.iter().take(usize::from(r)) {
                        parts.push(self.scalar_value(sink, Scalar::F32(*x), nspan));
                    }
                    columns.push(sink.push(
                        self,
                        Expression::Compose {
                            ty: col_ty,
                            components: parts,
                        },
                        nspan,
                    ));
                }
                let t = self.ty_at(ty, span)?;
                Ok(sink.push(
                    self,
                    Expression::Compose {
                        ty: t,
                        components: columns,
                    },
                    nspan,
                ))
            }
            (ConstValue::Array(elems), Type::Array { elem, len })
                if elems.len() == len as usize =>
            {
                let mut parts = Vec::with_capacity(elems.len());
                for e in elems {
                    parts.push(self.build_value(sink, e, elem, span, nspan)?);
                }
                let t = self.ty_at(ty, span)?;
                Ok(sink.push(
                    self,
                    Expression::Compose {
                        ty: t,
                        components: parts,
                    },
                    nspan,
                ))
            }
            (ConstValue::Struct { id, fields }, Type::Struct(s))
                if *id == s && fields.len() == self.program.structs[s].fields.len() =>
            {
                let program = self.program;
                let mut parts = Vec::with_capacity(fields.len());
                for (v, f) in fields.iter().zip(&program.structs[s].fields) {
                    parts.push(self.build_value(sink, v, f.ty, span, nspan)?);
                }
                let t = self.ty_at(ty, span)?;
                Ok(sink.push(
                    self,
                    Expression::Compose {
                        ty: t,
                        components: parts,
                    },
                    nspan,
                ))
            }
            (
                ConstValue::Mesh(_)
                | ConstValue::Texture(_)
                | ConstValue::String(_)
                | ConstValue::Error,
                _,
            ) => Err(LowerError::Unsupported {
                what: Unsupported::Constant,
                span,
            }),
            _ => Err(mismatch),
        }
    }

    fn scalar_value(
        &mut self,
        sink: &mut dyn Sink,
        s: Scalar,
        span: naga::Span,
    ) -> Handle<Expression> {
        match (literal(s), s) {
            (Some(lit), _) => sink.push(self, Expression::Literal(lit), span),
            (None, Scalar::F32(v)) => {
                // Only function sinks see non-finite values (naga constants are finite).
                let g = self.float_bits_global(v.to_bits());
                let gp = sink.push(self, Expression::GlobalVariable(g), span);
                let bits = sink.push(self, Expression::Load { pointer: gp }, span);
                sink.push(
                    self,
                    Expression::As {
                        expr: bits,
                        kind: naga::ScalarKind::Float,
                        convert: None,
                    },
                    span,
                )
            }
            // `literal` only fails for floats.
            (None, _) => sink.push(self, Expression::Literal(Literal::U32(0)), span),
        }
    }
}
