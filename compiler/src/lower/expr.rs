//! HIR expressions to naga expressions, in the context of one function ([`FnCx`]).
//!
//! Invariants:
//! - Expressions are appended through the function's [`FnBuilder`], in evaluation order, so each is
//!   emitted where the HIR evaluates it (left to right, operands before operators, arguments before
//!   calls); naga evaluates an expression at its `Emit`.
//! - Locals: a parameter is its `FunctionArgument`, a `let` is the value expression itself (named, so
//!   the written code shows the `let`), a `var` or `for` variable is a `LocalVariable` read with `Load`.
//! - Places (`var`s and fields, components and elements of one) are pointer chains (`AccessIndex` /
//!   `Access` on the local's pointer). Reading a field or element of a place loads through the chain
//!   rather than loading the whole aggregate.
//! - Dynamic indices are clamped into range before use (`min(i, n - 1)` for `u32`,
//!   `clamp(i, 0, n - 1)` for `i32`), so an out-of-range index reads or writes the nearest element on
//!   every target, whatever bounds-check policy the back end applies. A dynamically indexed array or
//!   matrix *value* is first copied into a local (naga allows dynamic matrix indices only behind a
//!   pointer, and SPIR-V needs a variable for arrays anyway).
//! - `&&` and `||` short-circuit: when the right operand may have an effect (calls a user function or an
//!   intrinsic) it is evaluated inside an `if` that stores into a local `bool`; otherwise both sides are
//!   evaluated and combined with naga's logical operator, which is equivalent and reads better.

use super::builder::FnBuilder;
use super::types::{scalar, vector_size};
use super::{CallLowering, FunctionCall, Intrinsics, LowerError, Lowerer, Polyfill};
use crate::sema::hir::{
    BinaryOp, ConstValue, ExprId, ExprKind, FnId, Function, Literal, LocalId, Program, Scalar,
    UnaryOp,
};
use crate::sema::types::{ScalarKind, Type, TypeId, TypeTable};
use crate::source::Span;
use naga::{BinaryOperator as Bo, Expression, Handle};

/// How a local is reached.
#[derive(Clone, Copy, Debug)]
pub(super) enum LocalValue {
    /// An immutable value (parameter, `let`).
    Value(Handle<Expression>),
    /// A pointer to a `LocalVariable` (`var`, `for` variable).
    Pointer(Handle<Expression>),
}

/// An index: known at compile time, or an expression already clamped into range.
#[derive(Clone, Copy, Debug)]
enum Index {
    Const(u32),
    Dynamic(Handle<Expression>),
}

/// The state of lowering one function.
pub(super) struct FnCx<'l, 'p> {
    pub lw: &'l mut Lowerer<'p>,
    pub hooks: &'l mut dyn Intrinsics,
    pub fb: FnBuilder,
    pub program: &'p Program,
    pub func: &'p Function,
    pub fn_id: FnId,
    pub locals: Vec<Option<LocalValue>>,
}

fn local_index(l: LocalId) -> usize {
    u32::from(l.into_raw()) as usize
}

impl<'p> FnCx<'_, 'p> {
    pub fn types(&self) -> &'p TypeTable {
        &self.program.types
    }

    pub fn hir_ty(&self, e: ExprId) -> TypeId {
        self.func.body.exprs[e].ty
    }

    pub fn hir_span(&self, e: ExprId) -> Span {
        self.func.body.exprs[e].span
    }

    pub fn invalid(&self, what: &'static str, span: Span) -> LowerError {
        LowerError::InvalidHir { what, span }
    }

    pub fn set_local(&mut self, l: LocalId, v: LocalValue) {
        let i = local_index(l);
        if self.locals.len() <= i {
            self.locals.resize(i + 1, None);
        }
        self.locals[i] = Some(v);
    }

    fn local(&self, l: LocalId, span: Span) -> Result<LocalValue, LowerError> {
        self.locals
            .get(local_index(l))
            .copied()
            .flatten()
            .ok_or(LowerError::InvalidHir {
                what: "a local used before its declaration",
                span,
            })
    }

    /// Lowers an expression that has a value.
    pub fn expr(&mut self, id: ExprId) -> Result<Handle<Expression>, LowerError> {
        let span = self.hir_span(id);
        self.value(id)?
            .ok_or_else(|| self.invalid("a call without a result used as a value", span))
    }

    /// Lowers an expression; `None` for a call of a function without a result.
    pub fn value(&mut self, id: ExprId) -> Result<Option<Handle<Expression>>, LowerError> {
        let program = self.program;
        let e = &self.func.body.exprs[id];
        let span = self.lw.span(e.span);
        let ty = e.ty;
        let h = match &e.kind {
            ExprKind::Literal(l) => self.literal(l, e.span)?,
            ExprKind::Local(l) => match self.local(*l, e.span)? {
                LocalValue::Value(h) => h,
                LocalValue::Pointer(p) => self.fb.load(p, span),
            },
            ExprKind::Const(c) => match self.lw.constant(*c)? {
                Some(h) => self.fb.expr(Expression::Constant(h), span),
                None => {
                    let item = &program.consts[*c];
                    self.lw
                        .value_expr(&mut self.fb, &item.value, item.ty, e.span)?
                }
            },
            ExprKind::Value(v) => self.lw.value_expr(&mut self.fb, v, ty, e.span)?,
            ExprKind::Unary { op, operand } => self.unary(*op, *operand, span)?,
            ExprKind::Binary { op, lhs, rhs } => match op {
                BinaryOp::And | BinaryOp::Or => self.short_circuit(*op, *lhs, *rhs, span)?,
                _ => {
                    let l = self.expr(*lhs)?;
                    let r = self.expr(*rhs)?;
                    let (lt, rt) = (self.hir_ty(*lhs), self.hir_ty(*rhs));
                    self.binary(*op, lt, rt, l, r, span)?
                }
            },
            ExprKind::Call { func, args } => return self.call(*func, args, ty, span),
            ExprKind::Builtin { func, args } => return self.builtin(*func, args, ty, id),
            ExprKind::Compose { components } => {
                let mut parts = Vec::with_capacity(components.len());
                for c in components {
                    parts.push(self.expr(*c)?);
                }
                let t = self.lw.ty_at(ty, e.span)?;
                self.fb.compose(t, parts, span)
            }
            ExprKind::Splat { value } => {
                let v = self.expr(*value)?;
                match self.types().get(ty) {
                    Type::Vector { size, .. } => {
                        let size = vector_size(size)
                            .ok_or_else(|| self.invalid("a splat to a bad vector size", e.span))?;
                        self.fb.splat(size, v, span)
                    }
                    _ => v,
                }
            }
            ExprKind::Zero => {
                let t = self.lw.ty_at(ty, e.span)?;
                self.fb.expr(Expression::ZeroValue(t), span)
            }
            ExprKind::Convert { arg } => self.convert(*arg, ty, span)?,
            ExprKind::Bitcast { arg } => {
                let v = self.expr(*arg)?;
                let kind = self
                    .types()
                    .scalar_kind(ty)
                    .ok_or_else(|| self.invalid("a bitcast to a non-numeric type", e.span))?;
                self.fb.cast(v, scalar(kind).kind, None, span)
            }
            ExprKind::Field { base, index } => match self.place(id)? {
                Some(p) => self.fb.load(p, span),
                None => {
                    let b = self.expr(*base)?;
                    self.fb.access_index(b, *index, span)
                }
            },
            ExprKind::Swizzle { base, pattern, len } => {
                if *len == 1 {
                    if let Some(p) = self.place(id)? {
                        return Ok(Some(self.fb.load(p, span)));
                    }
                }
                let b = self.expr(*base)?;
                self.swizzle(b, *pattern, *len, span)
            }
            ExprKind::Index { base, index } => match self.place(id)? {
                Some(p) => self.fb.load(p, span),
                None => self.index_value(*base, *index, span)?,
            },
            ExprKind::Error => return Err(self.invalid("an error expression", e.span)),
        };
        Ok(Some(h))
    }

    fn literal(&mut self, l: &Literal, span: Span) -> Result<Handle<Expression>, LowerError> {
        let s = match *l {
            Literal::Bool(b) => Scalar::Bool(b),
            Literal::I32(v) => Scalar::I32(v),
            Literal::U32(v) => Scalar::U32(v),
            Literal::F32(v) => Scalar::F32(v),
            Literal::String(_) => {
                return Err(LowerError::Unsupported {
                    what: super::Unsupported::Constant,
                    span,
                })
            }
        };
        Ok(self.scalar_const(s))
    }

    /// A scalar constant in the function (non-finite floats as bit casts).
    pub fn scalar_const(&mut self, s: Scalar) -> Handle<Expression> {
        match super::consts::literal(s) {
            Some(lit) => self.fb.literal(lit),
            None => match s {
                Scalar::F32(v) => self.lw.f32_expr(&mut self.fb, v),
                _ => self.fb.literal(naga::Literal::U32(0)),
            },
        }
    }

    /// A constant of a scalar or vector type `ty` with every component `s` (a splat for vectors).
    pub fn splat_const(&mut self, ty: TypeId, s: Scalar) -> Handle<Expression> {
        let v = self.scalar_const(s);
        match self.types().get(ty) {
            Type::Vector { size, .. } => match vector_size(size) {
                Some(size) => self.fb.splat(size, v, naga::Span::UNDEFINED),
                None => v,
            },
            _ => v,
        }
    }

    fn swizzle(
        &mut self,
        b: Handle<Expression>,
        pattern: [u8; 4],
        len: u8,
        span: naga::Span,
    ) -> Handle<Expression> {
        use naga::SwizzleComponent as C;
        if len == 1 {
            return self.fb.access_index(b, u32::from(pattern[0]), span);
        }
        let comp = |i: u8| match i {
            1 => C::Y,
            2 => C::Z,
            3 => C::W,
            _ => C::X,
        };
        let size = vector_size(len).unwrap_or(naga::VectorSize::Quad);
        self.fb.expr(
            Expression::Swizzle {
                size,
                vector: b,
                pattern: pattern.map(comp),
            },
            span,
        )
    }

    /// The pointer to a place expression, or `None` if `id` is not (part of) a `var`.
    pub fn place(&mut self, id: ExprId) -> Result<Option<Handle<Expression>>, LowerError> {
        let e = &self.func.body.exprs[id];
        let span = self.lw.span(e.span);
        Ok(match &e.kind {
            ExprKind::Local(l) => match self.local(*l, e.span)? {
                LocalValue::Pointer(p) => Some(p),
                LocalValue::Value(_) => None,
            },
            ExprKind::Field { base, index } => match self.place(*base)? {
                Some(p) => Some(self.fb.access_index(p, *index, span)),
                None => None,
            },
            ExprKind::Swizzle {
                base,
                pattern,
                len: 1,
            } => match self.place(*base)? {
                Some(p) => Some(self.fb.access_index(p, u32::from(pattern[0]), span)),
                None => None,
            },
            ExprKind::Index { base, index } => match self.place(*base)? {
                Some(p) => {
                    let len = self.indexable_len(self.hir_ty(*base), e.span)?;
                    Some(match self.index(*index, len)? {
                        Index::Const(k) => self.fb.access_index(p, k, span),
                        Index::Dynamic(i) => self.fb.access(p, i, span),
                    })
                }
                None => None,
            },
            _ => None,
        })
    }

    fn indexable_len(&self, ty: TypeId, span: Span) -> Result<u32, LowerError> {
        match self.types().get(ty) {
            Type::Array { len, .. } => Ok(len),
            Type::Vector { size, .. } => Ok(u32::from(size)),
            Type::Matrix { cols, .. } => Ok(u32::from(cols)),
            _ => Err(self.invalid("indexing a type that has no elements", span)),
        }
    }

    /// A constant index (clamped at compile time), or the index clamped into `0..len` at run time.
    fn index(&mut self, index: ExprId, len: u32) -> Result<Index, LowerError> {
        let last = len.saturating_sub(1);
        let e = &self.func.body.exprs[index];
        let known = match &e.kind {
            ExprKind::Literal(Literal::I32(v)) => Some(i64::from(*v)),
            ExprKind::Literal(Literal::U32(v)) => Some(i64::from(*v)),
            ExprKind::Value(ConstValue::Scalar(Scalar::I32(v))) => Some(i64::from(*v)),
            ExprKind::Value(ConstValue::Scalar(Scalar::U32(v))) => Some(i64::from(*v)),
            ExprKind::Const(c) => match self.program.consts[*c].value {
                ConstValue::Scalar(Scalar::I32(v)) => Some(i64::from(v)),
                ConstValue::Scalar(Scalar::U32(v)) => Some(i64::from(v)),
                _ => None,
            },
            _ => None,
        };
        if let Some(k) = known {
            return Ok(Index::Const(k.clamp(0, i64::from(last)) as u32));
        }
        let span = self.lw.span(e.span);
        let i = self.expr(index)?;
        let clamped = match self.types().get(e.ty) {
            Type::Scalar(ScalarKind::I32) => {
                let lo = self.fb.literal(naga::Literal::I32(0));
                let hi = self.fb.literal(naga::Literal::I32(last as i32));
                self.fb.math(naga::MathFunction::Clamp, &[i, lo, hi], span)
            }
            _ => {
                let hi = self.fb.literal(naga::Literal::U32(last));
                self.fb.math(naga::MathFunction::Min, &[i, hi], span)
            }
        };
        Ok(Index::Dynamic(clamped))
    }

    /// `base[index]` where `base` is not a place.
    fn index_value(
        &mut self,
        base: ExprId,
        index: ExprId,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let bty = self.hir_ty(base);
        let len = self.indexable_len(bty, self.hir_span(base))?;
        let b = self.expr(base)?;
        match self.index(index, len)? {
            Index::Const(k) => Ok(self.fb.access_index(b, k, span)),
            Index::Dynamic(i) => match self.types().get(bty) {
                Type::Vector { .. } => Ok(self.fb.access(b, i, span)),
                _ => {
                    // Arrays and matrices are indexed dynamically through a pointer.
                    let t = self.lw.ty_at(bty, self.hir_span(base))?;
                    let tmp = self.fb.local_at("indexed", t, Some(b), span);
                    let p = self.fb.access(tmp, i, span);
                    Ok(self.fb.load(p, span))
                }
            },
        }
    }

    fn unary(
        &mut self,
        op: UnaryOp,
        operand: ExprId,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let ty = self.hir_ty(operand);
        let v = self.expr(operand)?;
        Ok(match (op, self.types().get(ty)) {
            (UnaryOp::Neg, Type::Matrix { .. }) => {
                let m1 = self.fb.literal(naga::Literal::F32(-1.0));
                self.fb.binary(Bo::Multiply, v, m1, span)
            }
            (UnaryOp::Neg, _) if self.types().scalar_kind(ty) == Some(ScalarKind::U32) => {
                let zero = self.splat_const(ty, Scalar::U32(0));
                self.fb.binary(Bo::Subtract, zero, v, span)
            }
            (UnaryOp::Neg, _) => self.fb.unary(naga::UnaryOperator::Negate, v, span),
            (UnaryOp::Not, _) => self.fb.unary(naga::UnaryOperator::LogicalNot, v, span),
            (UnaryOp::BitNot, _) => self.fb.unary(naga::UnaryOperator::BitwiseNot, v, span),
        })
    }

    /// `l op r` for every operator but `&&` and `||`; `lt` and `rt` are the operands' HIR types.
    pub fn binary(
        &mut self,
        op: BinaryOp,
        lt: TypeId,
        rt: TypeId,
        l: Handle<Expression>,
        r: Handle<Expression>,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let kind = self.types().scalar_kind(lt);
        let is_int = kind.is_some_and(ScalarKind::is_integer);
        let nop = match op {
            BinaryOp::Add => Bo::Add,
            BinaryOp::Sub => Bo::Subtract,
            BinaryOp::Mul => Bo::Multiply,
            // GLSL leaves `%` of negative operands undefined, so a signed remainder always goes
            // through the helper.
            BinaryOp::Div if is_int && self.safe_divisor(r) => Bo::Divide,
            BinaryOp::Rem if kind == Some(ScalarKind::U32) && self.safe_divisor(r) => Bo::Modulo,
            BinaryOp::Div | BinaryOp::Rem if is_int => {
                let width = self.types().width(lt).unwrap_or(1);
                let signed = kind == Some(ScalarKind::I32);
                let p = if op == BinaryOp::Div {
                    Polyfill::Div { width, signed }
                } else {
                    Polyfill::Rem { width, signed }
                };
                return self.call_polyfill(p, vec![l, r], span);
            }
            BinaryOp::Div => Bo::Divide,
            BinaryOp::Rem => Bo::Modulo,
            BinaryOp::Eq => Bo::Equal,
            BinaryOp::Ne if kind == Some(ScalarKind::F32) => return Ok(self.float_ne(l, r, span)),
            BinaryOp::Ne => Bo::NotEqual,
            BinaryOp::Lt => Bo::Less,
            BinaryOp::Le => Bo::LessEqual,
            BinaryOp::Gt => Bo::Greater,
            BinaryOp::Ge => Bo::GreaterEqual,
            BinaryOp::And => Bo::LogicalAnd,
            BinaryOp::Or => Bo::LogicalOr,
            BinaryOp::BitAnd => Bo::And,
            BinaryOp::BitOr => Bo::InclusiveOr,
            BinaryOp::BitXor if kind == Some(ScalarKind::Bool) => Bo::NotEqual,
            BinaryOp::BitXor => Bo::ExclusiveOr,
            BinaryOp::Shl | BinaryOp::Shr => {
                let amount = self.shift_amount(rt, r, span);
                let nop = if op == BinaryOp::Shl {
                    Bo::ShiftLeft
                } else {
                    Bo::ShiftRight
                };
                return Ok(self.fb.binary(nop, l, amount, span));
            }
        };
        Ok(self.fb.binary(nop, l, r, span))
    }

    /// `l != r` on floats as `!(l == r)`, true when either is NaN (IEEE): naga writes `!=` as SPIR-V's
    /// ordered `OpFOrdNotEqual`, which is false for NaN, while the other targets' `!=` is true.
    fn float_ne(
        &mut self,
        l: Handle<Expression>,
        r: Handle<Expression>,
        span: naga::Span,
    ) -> Handle<Expression> {
        let eq = self.fb.binary(Bo::Equal, l, r, span);
        self.fb.unary(naga::UnaryOperator::LogicalNot, eq, span)
    }

    /// Whether an integer divisor is a literal for which naga's `/` and `%` already mean the spec's
    /// result on every target: not zero, and not -1 (which overflows for `i32::MIN`).
    fn safe_divisor(&self, r: Handle<Expression>) -> bool {
        matches!(
            self.fb.function().expressions[r],
            Expression::Literal(naga::Literal::U32(1..))
        ) || matches!(
            self.fb.function().expressions[r],
            Expression::Literal(naga::Literal::I32(v)) if v != 0 && v != -1
        )
    }

    /// A shift amount taken modulo 32: folded for a literal, masked with `& 31u` otherwise.
    fn shift_amount(
        &mut self,
        rt: TypeId,
        r: Handle<Expression>,
        span: naga::Span,
    ) -> Handle<Expression> {
        if let Expression::Literal(naga::Literal::U32(v)) = self.fb.function().expressions[r] {
            return self.fb.literal(naga::Literal::U32(v & 31));
        }
        let mask = self.splat_const(rt, Scalar::U32(31));
        self.fb.binary(Bo::And, r, mask, span)
    }

    fn short_circuit(
        &mut self,
        op: BinaryOp,
        lhs: ExprId,
        rhs: ExprId,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let l = self.expr(lhs)?;
        if !self.has_effects(rhs) {
            let r = self.expr(rhs)?;
            let nop = if op == BinaryOp::And {
                Bo::LogicalAnd
            } else {
                Bo::LogicalOr
            };
            return Ok(self.fb.binary(nop, l, r, span));
        }
        let bool_ty = self.lw.ty(TypeTable::BOOL)?;
        let tmp = self.fb.local_at("short_circuit", bool_ty, Some(l), span);
        self.fb.push_block();
        let r = self.expr(rhs)?;
        self.fb.store(tmp, r, span);
        let evaluate_rhs = self.fb.pop_block();
        let (accept, reject) = if op == BinaryOp::And {
            (evaluate_rhs, naga::Block::new())
        } else {
            (naga::Block::new(), evaluate_rhs)
        };
        self.fb.stmt(
            naga::Statement::If {
                condition: l,
                accept,
                reject,
            },
            span,
        );
        Ok(self.fb.load(tmp, span))
    }

    /// Whether evaluating `id` may have an effect: it calls a user function or an intrinsic.
    pub fn has_effects(&self, id: ExprId) -> bool {
        let e = &self.func.body.exprs[id];
        let any = |ids: &[ExprId]| ids.iter().any(|c| self.has_effects(*c));
        match &e.kind {
            ExprKind::Call { .. } => true,
            ExprKind::Builtin { func, args } => super::builtins::is_intrinsic(*func) || any(args),
            ExprKind::Unary { operand, .. } => self.has_effects(*operand),
            ExprKind::Binary { lhs, rhs, .. } => any(&[*lhs, *rhs]),
            ExprKind::Compose { components } => any(components),
            ExprKind::Splat { value } => self.has_effects(*value),
            ExprKind::Convert { arg } | ExprKind::Bitcast { arg } => self.has_effects(*arg),
            ExprKind::Field { base, .. } | ExprKind::Swizzle { base, .. } => {
                self.has_effects(*base)
            }
            ExprKind::Index { base, index } => any(&[*base, *index]),
            ExprKind::Literal(_)
            | ExprKind::Local(_)
            | ExprKind::Const(_)
            | ExprKind::Value(_)
            | ExprKind::Zero
            | ExprKind::Error => false,
        }
    }

    /// Element-wise conversion of `arg` to the scalar kind of `ty` (see types.md, "Conversions").
    fn convert(
        &mut self,
        arg: ExprId,
        ty: TypeId,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let aty = self.hir_ty(arg);
        let v = self.expr(arg)?;
        let (Some(from), Some(to)) = (self.types().scalar_kind(aty), self.types().scalar_kind(ty))
        else {
            return Err(self.invalid("a conversion of a non-numeric type", self.hir_span(arg)));
        };
        let width = self.types().width(ty).unwrap_or(1);
        Ok(match (from, to) {
            _ if from == to => v,
            (_, ScalarKind::Bool) => {
                let zero = match from {
                    ScalarKind::I32 => Scalar::I32(0),
                    ScalarKind::U32 => Scalar::U32(0),
                    _ => Scalar::F32(0.0),
                };
                let z = self.splat_const(aty, zero);
                if from == ScalarKind::F32 {
                    self.float_ne(v, z, span)
                } else {
                    self.fb.binary(Bo::NotEqual, v, z, span)
                }
            }
            (ScalarKind::Bool, _) => {
                let (zero, one) = match to {
                    ScalarKind::I32 => (Scalar::I32(0), Scalar::I32(1)),
                    ScalarKind::U32 => (Scalar::U32(0), Scalar::U32(1)),
                    _ => (Scalar::F32(0.0), Scalar::F32(1.0)),
                };
                let z = self.splat_const(ty, zero);
                let o = self.splat_const(ty, one);
                self.fb.select(v, o, z, span)
            }
            (ScalarKind::F32, ScalarKind::I32 | ScalarKind::U32) => {
                let p = Polyfill::FloatToInt {
                    width,
                    signed: to == ScalarKind::I32,
                };
                self.call_polyfill(p, vec![v], span)?
            }
            _ => self.fb.cast(v, scalar(to).kind, Some(4), span),
        })
    }

    /// Calls a user function.
    fn call(
        &mut self,
        func: FnId,
        args: &[ExprId],
        ret: TypeId,
        span: naga::Span,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        let mut values = Vec::with_capacity(args.len());
        for a in args {
            values.push(self.expr(*a)?);
        }
        let call = FunctionCall {
            callee: func,
            args: &values,
            caller: self.fn_id,
            span,
        };
        if let CallLowering::Done(result) = self.hooks.lower_call(self.lw, &mut self.fb, &call)? {
            return Ok(result);
        }
        let callee = self.lw.ensure_function(func, &mut *self.hooks)?;
        let has_result = self.types().get(ret) != Type::Void;
        Ok(self.fb.call(callee, values, has_result, span))
    }

    /// Calls a polyfill helper (built on first use) and returns its result.
    pub fn call_polyfill(
        &mut self,
        p: Polyfill,
        args: Vec<Handle<Expression>>,
        span: naga::Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let f = self.lw.polyfill(p)?;
        self.fb
            .call(f, args, true, span)
            .ok_or(LowerError::InvalidHir {
                what: "a polyfill without a result",
                span: Span::default(),
            })
    }
}
