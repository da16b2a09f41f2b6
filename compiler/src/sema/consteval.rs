//! Constant evaluation: a typed HIR expression to a [`ConstValue`], with GPU semantics.
//!
//! Used for `const` items, struct field defaults, array sizes, attribute arguments, constant indices
//! and every value in a scene. The checker has already typed the expression, so evaluation only meets
//! well-typed operands; anything that is not constant (a local, a call to a user function, a
//! non-constant built-in) stops evaluation with [`EvalError::NotConst`] at that sub-expression, which
//! the caller reports as E0412.
//!
//! Semantics (as the GPU computes them, spec/expressions.md):
//! - `i32`/`u32` arithmetic wraps; integer division by zero gives the left operand, remainder by zero
//!   gives 0; `i32::MIN / -1` is `i32::MIN`; shift amounts are taken modulo 32.
//! - `f32` arithmetic is IEEE binary32 in Rust's `f32` (the built-in functions in [`super::constmath`]).
//! - Conversions: float to int truncates toward zero and saturates (NaN gives 0); int to float rounds
//!   to nearest; `bool(x)` is `x != 0`.
//!
//! An operation on finite `f32` operands whose result is infinite or NaN (`1e30 * 1e30`, `0.0 / 0.0`,
//! `sqrt(-1.0)`) stops evaluation with [`EvalError::NonFinite`] at that operation (E0415): such a
//! value would reach the GPU as a NaN sample. An infinity written on purpose (the prelude's `INF`,
//! a `bitcast`) is kept, and so is arithmetic on it.
//!
//! Invariant: evaluation never panics, whatever HIR it is given; ill-typed input (which the checker
//! never produces) yields [`EvalError::Silent`].

use super::builtins::Builtin;
use super::constmath;
use super::hir::{
    BinaryOp, Body, Const, ConstValue, ExprId, ExprKind, Literal, Scalar, Struct, UnaryOp,
};
use super::types::{ScalarKind, Type, TypeId, TypeTable};
use crate::source::Span;
use la_arena::Arena;
use std::path::Path;

/// What evaluation needs besides the expression.
pub struct Env<'a> {
    /// The program's types.
    pub types: &'a TypeTable,
    /// Every struct (for zero values).
    pub structs: &'a Arena<Struct>,
    /// Every constant, with the values computed so far.
    pub consts: &'a Arena<Const>,
    /// The folder asset paths are relative to (the scene's file's folder), if in a scene.
    pub base_dir: Option<&'a Path>,
}

/// Why a value could not be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum EvalError {
    /// This sub-expression is not constant.
    NotConst {
        /// Where.
        span: Span,
        /// What it is.
        what: NotConst,
    },
    /// An operation on finite operands gave an infinite or NaN `f32` (E0415).
    NonFinite {
        /// The operation.
        span: Span,
        /// NaN rather than infinite.
        nan: bool,
    },
    /// Something already reported (an error expression or constant).
    Silent,
    /// An array value with more than [`MAX_CONST_SCALARS`] scalars (E0805).
    TooLarge {
        /// The expression that builds it.
        span: Span,
        /// Its number of scalars.
        scalars: u64,
    },
}

/// The most scalars (numbers and booleans, counting every vector, matrix, array and struct
/// component) a constant value may have. Evaluation refuses a larger array value before building
/// any of it, so a constant never allocates more than this many elements (each a few dozen bytes),
/// and the constants lowered into the kernel stay small.
pub const MAX_CONST_SCALARS: u64 = 65_536;

/// The number of scalars in a value of type `ty` (saturating; handles count as one, and so does a
/// struct without fields, so that an array's count is never below its length, which bounds what
/// its zero value allocates; a struct that contains itself, an error of its own, counts as empty
/// inside itself).
pub fn scalar_count(env: &Env, ty: TypeId) -> u64 {
    count_in(env, ty, &mut Vec::new())
}

fn count_in(env: &Env, ty: TypeId, open: &mut Vec<super::hir::StructId>) -> u64 {
    match env.types.get(ty) {
        Type::Vector { size, .. } => u64::from(size),
        Type::Matrix { cols, rows } => u64::from(cols) * u64::from(rows),
        Type::Array { elem, len } => count_in(env, elem, open).saturating_mul(u64::from(len)),
        Type::Struct(s) if open.contains(&s) => 0,
        Type::Struct(s) => {
            open.push(s);
            let n = env.structs[s]
                .fields
                .iter()
                .fold(0u64, |n, f| n.saturating_add(count_in(env, f.ty, open)));
            open.pop();
            n.max(1)
        }
        _ => 1,
    }
}

/// [`EvalError::TooLarge`] if a value of array or struct type `ty` has more than
/// [`MAX_CONST_SCALARS`].
fn bounded(env: &Env, ty: TypeId, span: Span) -> Result<(), EvalError> {
    if !matches!(env.types.get(ty), Type::Array { .. } | Type::Struct(_)) {
        return Ok(());
    }
    match scalar_count(env, ty) {
        n if n > MAX_CONST_SCALARS => Err(EvalError::TooLarge { span, scalars: n }),
        _ => Ok(()),
    }
}

/// Whether `v` holds an infinite or NaN `f32` anywhere (components, fields, elements, a solid
/// texture's colour).
pub fn has_nonfinite(v: &ConstValue) -> bool {
    any_f32(v, &|x| !x.is_finite())
}

fn any_f32(v: &ConstValue, f: &dyn Fn(f32) -> bool) -> bool {
    let scalar = |s: &Scalar| matches!(s, Scalar::F32(x) if f(*x));
    match v {
        ConstValue::Scalar(s) => scalar(s),
        ConstValue::Vector { len, comps } => comps.iter().take(usize::from(*len)).any(scalar),
        ConstValue::Matrix { data, .. } => data.iter().flatten().any(|x| f(*x)),
        ConstValue::Array(items) | ConstValue::Struct { fields: items, .. } => {
            items.iter().any(|i| any_f32(i, f))
        }
        ConstValue::Texture(super::hir::TextureAsset::Solid(c)) => c.iter().any(|x| f(*x)),
        _ => false,
    }
}

/// `result`, unless finite operands gave a non-finite value there ([`EvalError::NonFinite`]).
fn finite(span: Span, operands_finite: bool, result: ConstValue) -> Res {
    if operands_finite && has_nonfinite(&result) {
        Err(EvalError::NonFinite {
            span,
            nan: any_f32(&result, &f32::is_nan),
        })
    } else {
        Ok(result)
    }
}

/// The kinds of non-constant expressions.
#[derive(Clone, Debug, PartialEq)]
pub enum NotConst {
    /// A local variable or parameter.
    Local,
    /// A call to a user function.
    Call,
    /// A built-in that is not constant.
    Builtin(Builtin),
}

type Res = Result<ConstValue, EvalError>;

/// Evaluates `expr` of `body`.
pub fn eval(body: &Body, expr: ExprId, env: &Env) -> Res {
    let e = &body.exprs[expr];
    match &e.kind {
        ExprKind::Literal(l) => Ok(match l {
            Literal::Bool(b) => ConstValue::Scalar(Scalar::Bool(*b)),
            Literal::I32(v) => ConstValue::Scalar(Scalar::I32(*v)),
            Literal::U32(v) => ConstValue::Scalar(Scalar::U32(*v)),
            Literal::F32(v) => ConstValue::Scalar(Scalar::F32(*v)),
            Literal::String(s) => ConstValue::String(s.clone()),
        }),
        ExprKind::Local(_) => Err(EvalError::NotConst {
            span: e.span,
            what: NotConst::Local,
        }),
        ExprKind::Const(c) => match &env.consts[*c].value {
            ConstValue::Error => Err(EvalError::Silent),
            v => Ok(v.clone()),
        },
        ExprKind::Value(v) => match v {
            ConstValue::Error => Err(EvalError::Silent),
            v => Ok(v.clone()),
        },
        ExprKind::Unary { op, operand } => {
            let a = eval(body, *operand, env)?;
            let ok = !has_nonfinite(&a);
            finite(e.span, ok, unary(*op, a)?)
        }
        ExprKind::Binary { op, lhs, rhs } => {
            let a = eval(body, *lhs, env)?;
            // `&&` and `||` short-circuit, as at run time.
            match (op, &a) {
                (BinaryOp::And, ConstValue::Scalar(Scalar::Bool(false)))
                | (BinaryOp::Or, ConstValue::Scalar(Scalar::Bool(true))) => return Ok(a),
                _ => {}
            }
            let b = eval(body, *rhs, env)?;
            let ok = !has_nonfinite(&a) && !has_nonfinite(&b);
            finite(e.span, ok, binary(*op, a, b)?)
        }
        ExprKind::Call { .. } => Err(EvalError::NotConst {
            span: e.span,
            what: NotConst::Call,
        }),
        ExprKind::Builtin { func, args } => {
            if !func.info().is_const {
                return Err(EvalError::NotConst {
                    span: e.span,
                    what: NotConst::Builtin(*func),
                });
            }
            let mut vals = Vec::with_capacity(args.len());
            for a in args {
                vals.push(eval(body, *a, env)?);
            }
            let arg_span = |i: usize| args.get(i).map(|a| body.exprs[*a].span);
            let ok = !vals.iter().any(has_nonfinite);
            let v = constmath::call(*func, &vals, env.base_dir, arg_span(0).unwrap_or(e.span))
                .ok_or(EvalError::Silent)?;
            finite(e.span, ok, v)
        }
        ExprKind::Compose { components } => {
            bounded(env, e.ty, e.span)?;
            let mut vals = Vec::with_capacity(components.len());
            for c in components {
                vals.push(eval(body, *c, env)?);
            }
            compose(env, e.ty, vals)
        }
        ExprKind::Splat { value } => {
            let v = eval(body, *value, env)?;
            match (env.types.get(e.ty), v) {
                (Type::Vector { size, .. }, ConstValue::Scalar(s)) => Ok(ConstValue::Vector {
                    len: size,
                    comps: [s; 4],
                }),
                _ => Err(EvalError::Silent),
            }
        }
        ExprKind::Zero => {
            bounded(env, e.ty, e.span)?;
            zero(env, e.ty).ok_or(EvalError::Silent)
        }
        ExprKind::Convert { arg } => {
            let to = env.types.scalar_kind(e.ty).ok_or(EvalError::Silent)?;
            map1(&eval(body, *arg, env)?, |s| Some(convert(s, to)))
        }
        ExprKind::Bitcast { arg } => {
            let to = env.types.scalar_kind(e.ty).ok_or(EvalError::Silent)?;
            map1(&eval(body, *arg, env)?, |s| bitcast(s, to))
        }
        ExprKind::Field { base, index } => match eval(body, *base, env)? {
            ConstValue::Struct { fields, .. } => fields
                .into_iter()
                .nth(*index as usize)
                .ok_or(EvalError::Silent),
            _ => Err(EvalError::Silent),
        },
        ExprKind::Swizzle { base, pattern, len } => match eval(body, *base, env)? {
            ConstValue::Vector { len: n, comps } => {
                let pick = |i: u8| comps[usize::from(i.min(n - 1))];
                if *len == 1 {
                    Ok(ConstValue::Scalar(pick(pattern[0])))
                } else {
                    let mut out = [Scalar::Bool(false); 4];
                    for (o, p) in out.iter_mut().zip(pattern).take(usize::from(*len)) {
                        *o = pick(*p);
                    }
                    Ok(ConstValue::Vector {
                        len: *len,
                        comps: out,
                    })
                }
            }
            _ => Err(EvalError::Silent),
        },
        ExprKind::Index { base, index } => {
            let b = eval(body, *base, env)?;
            let i = eval(body, *index, env)?;
            index_value(b, &i).ok_or(EvalError::Silent)
        }
        ExprKind::Error => Err(EvalError::Silent),
    }
}

/// The index value of a constant `i32`/`u32` (negative indices are out of range, as `None`).
pub fn as_index(v: &ConstValue) -> Option<u32> {
    match v {
        ConstValue::Scalar(Scalar::I32(i)) => u32::try_from(*i).ok(),
        ConstValue::Scalar(Scalar::U32(u)) => Some(*u),
        _ => None,
    }
}

/// `base[index]`, clamping a dynamic index as the GPU does.
fn index_value(base: ConstValue, index: &ConstValue) -> Option<ConstValue> {
    let i = match index {
        ConstValue::Scalar(Scalar::I32(i)) => (*i).max(0) as usize,
        ConstValue::Scalar(Scalar::U32(u)) => *u as usize,
        _ => return None,
    };
    match base {
        ConstValue::Array(mut elems) => {
            let i = i.min(elems.len().checked_sub(1)?);
            Some(elems.swap_remove(i))
        }
        ConstValue::Vector { len, comps } => {
            Some(ConstValue::Scalar(comps[i.min(usize::from(len) - 1)]))
        }
        ConstValue::Matrix { cols, rows, data } => {
            let c = i.min(usize::from(cols) - 1);
            Some(vector_f32(&data[c][..usize::from(rows)]))
        }
        _ => None,
    }
}

/// A vector of f32 from a slice of 2 to 4 values.
pub fn vector_f32(v: &[f32]) -> ConstValue {
    let mut comps = [Scalar::F32(0.0); 4];
    for (c, x) in comps.iter_mut().zip(v) {
        *c = Scalar::F32(*x);
    }
    ConstValue::Vector {
        len: v.len() as u8,
        comps,
    }
}

/// The zero value of a type; `None` for a type without one, and for a struct that contains
/// itself (an error of its own, E0801), which has no finite value.
pub fn zero(env: &Env, ty: TypeId) -> Option<ConstValue> {
    zero_in(env, ty, &mut Vec::new())
}

fn zero_in(env: &Env, ty: TypeId, open: &mut Vec<super::hir::StructId>) -> Option<ConstValue> {
    Some(match env.types.get(ty) {
        Type::Scalar(k) => ConstValue::Scalar(zero_scalar(k)),
        Type::Vector { size, scalar } => ConstValue::Vector {
            len: size,
            comps: [zero_scalar(scalar); 4],
        },
        Type::Matrix { cols, rows } => ConstValue::Matrix {
            cols,
            rows,
            data: [[0.0; 4]; 4],
        },
        Type::Array { elem, len } => {
            let z = zero_in(env, elem, open)?;
            ConstValue::Array(vec![z; len as usize])
        }
        Type::Struct(s) if open.contains(&s) => return None,
        Type::Struct(s) => {
            open.push(s);
            let fields = env.structs[s]
                .fields
                .iter()
                .map(|f| zero_in(env, f.ty, open))
                .collect::<Option<Vec<_>>>();
            open.pop();
            ConstValue::Struct {
                id: s,
                fields: fields?,
            }
        }
        _ => return None,
    })
}

fn zero_scalar(k: ScalarKind) -> Scalar {
    match k {
        ScalarKind::Bool => Scalar::Bool(false),
        ScalarKind::I32 => Scalar::I32(0),
        ScalarKind::U32 => Scalar::U32(0),
        ScalarKind::F32 => Scalar::F32(0.0),
    }
}

fn compose(env: &Env, ty: TypeId, vals: Vec<ConstValue>) -> Res {
    match env.types.get(ty) {
        Type::Vector { size, .. } => {
            let mut comps = [Scalar::Bool(false); 4];
            let mut n = 0usize;
            for v in &vals {
                let (w, cs) = components(v).ok_or(EvalError::Silent)?;
                for c in cs.iter().take(usize::from(w)) {
                    *comps.get_mut(n).ok_or(EvalError::Silent)? = *c;
                    n += 1;
                }
            }
            Ok(ConstValue::Vector { len: size, comps })
        }
        Type::Matrix { cols, rows } => {
            let mut data = [[0.0f32; 4]; 4];
            for (c, v) in vals.iter().enumerate() {
                let (_, cs) = components(v).ok_or(EvalError::Silent)?;
                let col = data.get_mut(c).ok_or(EvalError::Silent)?;
                for (dst, src) in col.iter_mut().zip(cs).take(usize::from(rows)) {
                    *dst = f32_of(src);
                }
            }
            Ok(ConstValue::Matrix { cols, rows, data })
        }
        Type::Array { .. } => Ok(ConstValue::Array(vals)),
        Type::Struct(id) => Ok(ConstValue::Struct { id, fields: vals }),
        _ => Err(EvalError::Silent),
    }
}

/// Width (1 for scalars) and components of a scalar or vector value.
pub fn components(v: &ConstValue) -> Option<(u8, [Scalar; 4])> {
    match v {
        ConstValue::Scalar(s) => Some((1, [*s; 4])),
        ConstValue::Vector { len, comps } => Some((*len, *comps)),
        _ => None,
    }
}

/// A scalar (width 1) or vector value.
pub fn from_components(width: u8, comps: [Scalar; 4]) -> ConstValue {
    if width == 1 {
        ConstValue::Scalar(comps[0])
    } else {
        ConstValue::Vector { len: width, comps }
    }
}

/// The value of an f32 scalar (0 for others).
pub fn f32_of(s: Scalar) -> f32 {
    match s {
        Scalar::F32(f) => f,
        _ => 0.0,
    }
}

/// Applies `f` to every component.
pub fn map1(v: &ConstValue, f: impl Fn(Scalar) -> Option<Scalar>) -> Res {
    let (w, cs) = components(v).ok_or(EvalError::Silent)?;
    let mut out = cs;
    for o in out.iter_mut().take(usize::from(w)) {
        *o = f(*o).ok_or(EvalError::Silent)?;
    }
    Ok(from_components(w, out))
}

/// Applies `f` to every pair of components (the operands have equal widths).
pub fn map2(a: &ConstValue, b: &ConstValue, f: impl Fn(Scalar, Scalar) -> Option<Scalar>) -> Res {
    let (w, ca) = components(a).ok_or(EvalError::Silent)?;
    let (wb, cb) = components(b).ok_or(EvalError::Silent)?;
    if w != wb {
        return Err(EvalError::Silent);
    }
    let mut out = ca;
    for i in 0..usize::from(w) {
        out[i] = f(ca[i], cb[i]).ok_or(EvalError::Silent)?;
    }
    Ok(from_components(w, out))
}

/// Converts a scalar to another kind, as `f32(x)`, `i32(x)`, `u32(x)`, `bool(x)` do.
pub fn convert(s: Scalar, to: ScalarKind) -> Scalar {
    match (s, to) {
        (Scalar::Bool(b), ScalarKind::Bool) => Scalar::Bool(b),
        (Scalar::Bool(b), ScalarKind::I32) => Scalar::I32(i32::from(b)),
        (Scalar::Bool(b), ScalarKind::U32) => Scalar::U32(u32::from(b)),
        (Scalar::Bool(b), ScalarKind::F32) => Scalar::F32(f32::from(u8::from(b))),
        (Scalar::I32(i), ScalarKind::Bool) => Scalar::Bool(i != 0),
        (Scalar::I32(i), ScalarKind::I32) => Scalar::I32(i),
        (Scalar::I32(i), ScalarKind::U32) => Scalar::U32(i as u32),
        (Scalar::I32(i), ScalarKind::F32) => Scalar::F32(i as f32),
        (Scalar::U32(u), ScalarKind::Bool) => Scalar::Bool(u != 0),
        (Scalar::U32(u), ScalarKind::I32) => Scalar::I32(u as i32),
        (Scalar::U32(u), ScalarKind::U32) => Scalar::U32(u),
        (Scalar::U32(u), ScalarKind::F32) => Scalar::F32(u as f32),
        (Scalar::F32(f), ScalarKind::Bool) => Scalar::Bool(f != 0.0),
        (Scalar::F32(f), ScalarKind::I32) => Scalar::I32(f as i32),
        (Scalar::F32(f), ScalarKind::U32) => Scalar::U32(f as u32),
        (Scalar::F32(f), ScalarKind::F32) => Scalar::F32(f),
    }
}

fn bitcast(s: Scalar, to: ScalarKind) -> Option<Scalar> {
    let bits = match s {
        Scalar::I32(i) => i as u32,
        Scalar::U32(u) => u,
        Scalar::F32(f) => f.to_bits(),
        Scalar::Bool(_) => return None,
    };
    Some(match to {
        ScalarKind::I32 => Scalar::I32(bits as i32),
        ScalarKind::U32 => Scalar::U32(bits),
        ScalarKind::F32 => Scalar::F32(f32::from_bits(bits)),
        ScalarKind::Bool => return None,
    })
}

fn unary(op: UnaryOp, v: ConstValue) -> Res {
    if let (UnaryOp::Neg, ConstValue::Matrix { cols, rows, data }) = (op, &v) {
        let mut d = *data;
        d.iter_mut().flatten().for_each(|x| *x = -*x);
        return Ok(ConstValue::Matrix {
            cols: *cols,
            rows: *rows,
            data: d,
        });
    }
    map1(&v, |s| {
        Some(match (op, s) {
            (UnaryOp::Neg, Scalar::I32(i)) => Scalar::I32(i.wrapping_neg()),
            (UnaryOp::Neg, Scalar::F32(f)) => Scalar::F32(-f),
            (UnaryOp::Not, Scalar::Bool(b)) => Scalar::Bool(!b),
            (UnaryOp::BitNot, Scalar::I32(i)) => Scalar::I32(!i),
            (UnaryOp::BitNot, Scalar::U32(u)) => Scalar::U32(!u),
            _ => return None,
        })
    })
}

/// `a op b` on scalars of one kind (or an integer and a `u32` shift amount).
pub fn scalar_binary(op: BinaryOp, a: Scalar, b: Scalar) -> Option<Scalar> {
    use BinaryOp::*;
    use Scalar as S;
    Some(match (a, b) {
        (S::I32(x), S::U32(s)) if matches!(op, Shl | Shr) => S::I32(if op == Shl {
            x.wrapping_shl(s)
        } else {
            x.wrapping_shr(s)
        }),
        (S::U32(x), S::U32(s)) if matches!(op, Shl | Shr) => S::U32(if op == Shl {
            x.wrapping_shl(s)
        } else {
            x.wrapping_shr(s)
        }),
        (S::I32(x), S::I32(y)) => match op {
            Add => S::I32(x.wrapping_add(y)),
            Sub => S::I32(x.wrapping_sub(y)),
            Mul => S::I32(x.wrapping_mul(y)),
            Div => S::I32(if y == 0 { x } else { x.wrapping_div(y) }),
            Rem => S::I32(if y == 0 { 0 } else { x.wrapping_rem(y) }),
            BitAnd => S::I32(x & y),
            BitOr => S::I32(x | y),
            BitXor => S::I32(x ^ y),
            _ => compare(op, x.partial_cmp(&y)?)?,
        },
        (S::U32(x), S::U32(y)) => match op {
            Add => S::U32(x.wrapping_add(y)),
            Sub => S::U32(x.wrapping_sub(y)),
            Mul => S::U32(x.wrapping_mul(y)),
            Div => S::U32(x.checked_div(y).unwrap_or(x)),
            Rem => S::U32(x.checked_rem(y).unwrap_or(0)),
            BitAnd => S::U32(x & y),
            BitOr => S::U32(x | y),
            BitXor => S::U32(x ^ y),
            _ => compare(op, x.partial_cmp(&y)?)?,
        },
        (S::F32(x), S::F32(y)) => match op {
            Add => S::F32(x + y),
            Sub => S::F32(x - y),
            Mul => S::F32(x * y),
            Div => S::F32(x / y),
            Rem => S::F32(x % y),
            Eq => S::Bool(x == y),
            Ne => S::Bool(x != y),
            Lt => S::Bool(x < y),
            Le => S::Bool(x <= y),
            Gt => S::Bool(x > y),
            Ge => S::Bool(x >= y),
            _ => return None,
        },
        (S::Bool(x), S::Bool(y)) => S::Bool(match op {
            Eq => x == y,
            Ne => x != y,
            And | BitAnd => x && y,
            Or | BitOr => x || y,
            BitXor => x ^ y,
            _ => return None,
        }),
        _ => return None,
    })
}

fn compare(op: BinaryOp, ord: std::cmp::Ordering) -> Option<Scalar> {
    use std::cmp::Ordering::*;
    Some(Scalar::Bool(match op {
        BinaryOp::Eq => ord == Equal,
        BinaryOp::Ne => ord != Equal,
        BinaryOp::Lt => ord == Less,
        BinaryOp::Le => ord != Greater,
        BinaryOp::Gt => ord == Greater,
        BinaryOp::Ge => ord != Less,
        _ => return None,
    }))
}

fn binary(op: BinaryOp, a: ConstValue, b: ConstValue) -> Res {
    match (&a, &b) {
        (ConstValue::Matrix { .. }, _) | (_, ConstValue::Matrix { .. }) => {
            constmath::matrix_binary(op, &a, &b).ok_or(EvalError::Silent)
        }
        _ => map2(&a, &b, |x, y| scalar_binary(op, x, y)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_semantics() {
        use BinaryOp::*;
        let i = Scalar::I32;
        let u = Scalar::U32;
        assert_eq!(scalar_binary(Add, i(i32::MAX), i(1)), Some(i(i32::MIN)));
        assert_eq!(scalar_binary(Div, i(7), i(0)), Some(i(7)));
        assert_eq!(scalar_binary(Rem, i(7), i(0)), Some(i(0)));
        assert_eq!(scalar_binary(Div, i(i32::MIN), i(-1)), Some(i(i32::MIN)));
        assert_eq!(scalar_binary(Sub, u(0), u(1)), Some(u(u32::MAX)));
        assert_eq!(scalar_binary(Shl, u(1), u(33)), Some(u(2)));
        assert_eq!(scalar_binary(Shr, i(-8), u(1)), Some(i(-4)));
        assert_eq!(scalar_binary(Lt, i(-1), i(0)), Some(Scalar::Bool(true)));
    }

    #[test]
    fn conversions() {
        assert_eq!(convert(Scalar::F32(-1.7), ScalarKind::I32), Scalar::I32(-1));
        assert_eq!(
            convert(Scalar::F32(1e20), ScalarKind::I32),
            Scalar::I32(i32::MAX)
        );
        assert_eq!(convert(Scalar::F32(-3.0), ScalarKind::U32), Scalar::U32(0));
        assert_eq!(
            convert(Scalar::F32(f32::NAN), ScalarKind::U32),
            Scalar::U32(0)
        );
        assert_eq!(
            convert(Scalar::I32(-1), ScalarKind::U32),
            Scalar::U32(u32::MAX)
        );
        assert_eq!(
            convert(Scalar::U32(2), ScalarKind::Bool),
            Scalar::Bool(true)
        );
        assert_eq!(
            bitcast(Scalar::U32(0x7f80_0000), ScalarKind::F32),
            Some(Scalar::F32(f32::INFINITY))
        );
    }

    #[test]
    fn vectors_and_indexing() {
        let v = vector_f32(&[1.0, 2.0, 3.0]);
        let w = map2(&v, &v, |a, b| scalar_binary(BinaryOp::Mul, a, b));
        assert_eq!(w, Ok(vector_f32(&[1.0, 4.0, 9.0])));
        let idx = ConstValue::Scalar(Scalar::U32(7));
        assert_eq!(
            index_value(v, &idx),
            Some(ConstValue::Scalar(Scalar::F32(3.0)))
        );
    }
}
