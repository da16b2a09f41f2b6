//! Polyfills: helper functions for built-ins and operators whose naga meaning differs between targets
//! or from the spec, or that naga does not have.
//!
//! Each [`Polyfill`] is an ordinary naga function built with [`FnBuilder`], appended to the module the
//! first time it is used and memoised ([`Lowerer::polyfill`]), so it precedes every caller and is
//! emitted once, only when used. Helpers may call other helpers (built first). They carry
//! `Span::UNDEFINED`: they have no DSL source.
//!
//! The semantics, and why each exists:
//! - `is_nan`, `is_inf`, `is_finite` test the bit pattern (`bitcast<u32>(x) & 0x7fffffff` against
//!   `0x7f800000`): WGSL has no such functions, and comparisons like `x != x` are folded away by
//!   fast-math compilers.
//! - integer `/` and `%`: a zero divisor gives the left operand for `/` and 0 for `%`, and `i32::MIN / -1` gives `i32::MIN`
//!   (`% -1` gives 0). naga's SPIR-V, HLSL and MSL writers guard division but make `x % 0` zero (as
//!   WGSL does), naga's GLSL writer does not guard at all, and GLSL's `%` is undefined for negative
//!   operands; the helpers (signed remainder as `a - d * (a / d)`) make all five targets agree with
//!   the spec.
//! - float → integer conversion saturates (NaN gives 0): naga clamps for SPIR-V, HLSL and MSL but not
//!   for GLSL, and the result for NaN is otherwise undefined.
//! - `normalize` of a vector whose squared length is below the smallest normal `f32` (|v| < 1.1e-19:
//!   zero, or flushed to zero on some GPUs) is the zero vector, never NaN.
//! - `inverse` (absent from WGSL) by cofactors; a matrix whose determinant is exactly zero gives zero.
//! - the geometry helpers and transforms of spec/builtins.md; see each builder.
//!
//! Invariant: a helper's signature depends only on its [`Polyfill`] key.

use super::builder::{FnBuilder, TypeCache};
use super::types::vector_size;
use super::{LowerError, Lowerer};
use crate::sema::hir::StructId;
use crate::sema::types::ScalarKind;
use crate::source::Span;
use naga::{
    BinaryOperator as Bo, Expression, Function, Handle, Literal, MathFunction as Mf,
    ScalarKind as Sk, Statement, Type, VectorSize,
};
use std::collections::BTreeMap;

/// A helper function lowering emits on demand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Polyfill {
    /// `is_nan` of `f32` (width 1) or `vecNf`.
    IsNan(u8),
    /// `is_inf`.
    IsInf(u8),
    /// `is_finite`.
    IsFinite(u8),
    /// Saturating `f32 → i32`/`u32` conversion, element-wise.
    FloatToInt {
        /// 1 for scalars, else the vector size.
        width: u8,
        /// To `i32` (else `u32`).
        signed: bool,
    },
    /// Integer division with the spec's results for a zero divisor and `MIN / -1`.
    Div {
        /// 1 for scalars, else the vector size.
        width: u8,
        /// `i32` (else `u32`).
        signed: bool,
    },
    /// Integer remainder, likewise.
    Rem {
        /// 1 for scalars, else the vector size.
        width: u8,
        /// `i32` (else `u32`).
        signed: bool,
    },
    /// `normalize` of a `vecNf`.
    Normalize(u8),
    /// `inverse` of a `matNxNf`.
    Inverse(u8),
    /// `transform_point`
    TransformPoint,
    /// `transform_dir`
    TransformDir,
    /// `orthonormal_basis`
    OrthonormalBasis,
    /// `intersect_triangle`
    IntersectTriangle,
    /// `intersect_aabb`
    IntersectAabb,
    /// `sample_cosine_hemisphere`
    SampleCosineHemisphere,
    /// `sample_uniform_sphere`
    SampleUniformSphere,
    /// `luminance`
    Luminance,
    /// `translate`
    Translate,
    /// `scale` (of a `vec3f`; a scalar is splatted by the caller)
    Scale,
    /// `rotate_x`
    RotateX,
    /// `rotate_y`
    RotateY,
    /// `rotate_z`
    RotateZ,
    /// `rotate`
    Rotate,
}

type H = Handle<Expression>;
const U: naga::Span = naga::Span::UNDEFINED;

/// A function under construction with the few shorthands the helpers need.
pub(super) struct Pf<'a, 'p> {
    pub(super) lw: &'a mut Lowerer<'p>,
    pub(super) fb: FnBuilder,
}

fn type_suffix(width: u8, kind: ScalarKind) -> String {
    if width <= 1 {
        kind.name().to_string()
    } else {
        format!("vec{width}{}", kind.suffix())
    }
}

impl<'a, 'p> Pf<'a, 'p> {
    pub(super) fn new(
        lw: &'a mut Lowerer<'p>,
        name: &str,
        args: &[(&str, Handle<Type>)],
        ret: Handle<Type>,
    ) -> Self {
        Pf {
            lw,
            fb: FnBuilder::new(name, args, Some(ret)),
        }
    }
    pub(super) fn arg(&mut self, i: u32) -> H {
        self.fb.arg(i)
    }
    pub(super) fn f(&mut self, v: f32) -> H {
        self.lw.f32_expr(&mut self.fb, v)
    }
    pub(super) fn u(&mut self, v: u32) -> H {
        self.fb.literal(Literal::U32(v))
    }
    pub(super) fn lit(&mut self, l: Literal) -> H {
        self.fb.literal(l)
    }
    /// A constant of `width` components.
    pub(super) fn splat_lit(&mut self, width: u8, l: Literal) -> H {
        let v = match l {
            Literal::F32(x) => self.f(x),
            other => self.lit(other),
        };
        match vector_size(width) {
            Some(size) => self.fb.splat(size, v, U),
            None => v,
        }
    }
    pub(super) fn bin(&mut self, op: Bo, a: H, b: H) -> H {
        self.fb.binary(op, a, b, U)
    }
    pub(super) fn add(&mut self, a: H, b: H) -> H {
        self.bin(Bo::Add, a, b)
    }
    pub(super) fn sub(&mut self, a: H, b: H) -> H {
        self.bin(Bo::Subtract, a, b)
    }
    pub(super) fn mul(&mut self, a: H, b: H) -> H {
        self.bin(Bo::Multiply, a, b)
    }
    pub(super) fn div(&mut self, a: H, b: H) -> H {
        self.bin(Bo::Divide, a, b)
    }
    pub(super) fn m(&mut self, fun: Mf, args: &[H]) -> H {
        self.fb.math(fun, args, U)
    }
    pub(super) fn at(&mut self, base: H, i: u32) -> H {
        self.fb.access_index(base, i, U)
    }
    pub(super) fn sel(&mut self, cond: H, accept: H, reject: H) -> H {
        self.fb.select(cond, accept, reject, U)
    }
    pub(super) fn compose(&mut self, ty: Handle<Type>, parts: Vec<H>) -> H {
        self.fb.compose(ty, parts, U)
    }
    pub(super) fn name(&mut self, h: H, name: &str) -> H {
        self.fb.name(h, name);
        h
    }
    pub(super) fn ty_f(&mut self, width: u8) -> Handle<Type> {
        self.lw.sv_type(width, ScalarKind::F32)
    }
    pub(super) fn ret(mut self, value: H) -> Function {
        self.fb.ret(Some(value), U);
        self.fb.finish()
    }
    /// `bitcast<u32>(x) & 0x7fffffff`, element-wise: the magnitude bits of a float.
    pub(super) fn magnitude_bits(&mut self, x: H, width: u8) -> H {
        let bits = self.fb.cast(x, Sk::Uint, None, U);
        let mask = self.splat_lit(width, Literal::U32(0x7fff_ffff));
        self.bin(Bo::And, bits, mask)
    }
    /// `(x, y, z)` as a `vec3f`.
    pub(super) fn vec3(&mut self, x: H, y: H, z: H) -> H {
        let t = self.ty_f(3);
        self.compose(t, vec![x, y, z])
    }
    /// A 4×4 matrix from its columns, each given as four components.
    pub(super) fn mat4(&mut self, cols: [[H; 4]; 4]) -> H {
        let v4 = self.ty_f(4);
        let m4 = TypeCache::matrix(&mut self.lw.module, VectorSize::Quad, VectorSize::Quad);
        let columns = cols
            .into_iter()
            .map(|c| self.compose(v4, c.to_vec()))
            .collect();
        self.compose(m4, columns)
    }
    /// A call of another helper.
    pub(super) fn call(&mut self, p: Polyfill, args: Vec<H>) -> Result<H, LowerError> {
        let f = self.lw.polyfill(p)?;
        self.fb
            .call(f, args, true, U)
            .ok_or(LowerError::InvalidHir {
                what: "a polyfill without a result",
                span: Span::default(),
            })
    }
}

impl Lowerer<'_> {
    /// The helper function `p`, built and appended on first use.
    pub fn polyfill(&mut self, p: Polyfill) -> Result<Handle<Function>, LowerError> {
        if let Some(h) = self.polyfills.get(&p) {
            return Ok(*h);
        }
        let f = build(self, p)?;
        let h = self.module.functions.append(f, U);
        self.polyfills.insert(p, h);
        Ok(h)
    }

    /// The naga type of a framework struct of the prelude.
    fn framework_struct(
        &mut self,
        s: Option<StructId>,
        what: &'static str,
    ) -> Result<Handle<Type>, LowerError> {
        let s = s.ok_or(LowerError::InvalidHir {
            what,
            span: Span::default(),
        })?;
        let id = self
            .program
            .types
            .iter()
            .find(|(_, t)| *t == crate::sema::types::Type::Struct(s))
            .map(|(id, _)| id)
            .ok_or(LowerError::InvalidHir {
                what,
                span: Span::default(),
            })?;
        self.ty(id)
    }

    /// The index of field `name` of framework struct `s`.
    fn field(&self, s: Option<StructId>, name: &str) -> Result<u32, LowerError> {
        s.and_then(|s| self.program.structs[s].field_index(name))
            .map(|i| i as u32)
            .ok_or(LowerError::InvalidHir {
                what: "a prelude struct without a field the built-ins need",
                span: Span::default(),
            })
    }
}

fn build(lw: &mut Lowerer<'_>, p: Polyfill) -> Result<Function, LowerError> {
    match p {
        Polyfill::IsNan(w) | Polyfill::IsInf(w) | Polyfill::IsFinite(w) => Ok(classify(lw, p, w)),
        Polyfill::FloatToInt { width, signed } => Ok(float_to_int(lw, width, signed)),
        Polyfill::Div { width, signed } => Ok(int_div(lw, width, signed, false)),
        Polyfill::Rem { width, signed } => Ok(int_div(lw, width, signed, true)),
        Polyfill::Normalize(w) => Ok(normalize(lw, w)),
        Polyfill::Inverse(n) => Ok(inverse(lw, n)),
        Polyfill::TransformPoint | Polyfill::TransformDir => {
            Ok(transform(lw, p == Polyfill::TransformPoint))
        }
        Polyfill::OrthonormalBasis => Ok(orthonormal_basis(lw)),
        Polyfill::IntersectTriangle => super::geometry::intersect_triangle(lw),
        Polyfill::IntersectAabb => super::geometry::intersect_aabb(lw),
        Polyfill::SampleCosineHemisphere => sample_cosine_hemisphere(lw),
        Polyfill::SampleUniformSphere => Ok(sample_uniform_sphere(lw)),
        Polyfill::Luminance => Ok(luminance(lw)),
        Polyfill::Translate | Polyfill::Scale => Ok(translate_scale(lw, p == Polyfill::Scale)),
        Polyfill::RotateX | Polyfill::RotateY | Polyfill::RotateZ => Ok(rotate_axis(lw, p)),
        Polyfill::Rotate => Ok(rotate(lw)),
    }
}

fn classify(lw: &mut Lowerer<'_>, p: Polyfill, w: u8) -> Function {
    let (name, op) = match p {
        Polyfill::IsNan(_) => ("is_nan", Bo::Greater),
        Polyfill::IsInf(_) => ("is_inf", Bo::Equal),
        _ => ("is_finite", Bo::Less),
    };
    let t = lw.sv_type(w, ScalarKind::F32);
    let r = lw.sv_type(w, ScalarKind::Bool);
    let mut f = Pf::new(
        lw,
        &format!("{name}_{}", type_suffix(w, ScalarKind::F32)),
        &[("x", t)],
        r,
    );
    let x = f.arg(0);
    let bits = f.magnitude_bits(x, w);
    let inf = f.splat_lit(w, Literal::U32(0x7f80_0000));
    let v = f.bin(op, bits, inf);
    f.ret(v)
}

fn float_to_int(lw: &mut Lowerer<'_>, w: u8, signed: bool) -> Function {
    let kind = if signed {
        ScalarKind::I32
    } else {
        ScalarKind::U32
    };
    let t = lw.sv_type(w, ScalarKind::F32);
    let r = lw.sv_type(w, kind);
    let name = format!(
        "{}_from_{}",
        type_suffix(w, kind),
        type_suffix(w, ScalarKind::F32)
    );
    let mut f = Pf::new(lw, &name, &[("x", t)], r);
    let x = f.arg(0);
    // The largest f32 below 2^31 and below 2^32: the bounds of exactly representable results.
    let (lo, hi, zero) = if signed {
        (-2_147_483_648.0, 2_147_483_520.0, Literal::I32(0))
    } else {
        (0.0, 4_294_967_040.0, Literal::U32(0))
    };
    let lo = f.splat_lit(w, Literal::F32(lo));
    let hi = f.splat_lit(w, Literal::F32(hi));
    let above = f.m(Mf::Max, &[x, lo]);
    let clamped = f.m(Mf::Min, &[above, hi]);
    let converted = f.fb.cast(
        clamped,
        if signed { Sk::Sint } else { Sk::Uint },
        Some(4),
        U,
    );
    let bits = f.magnitude_bits(x, w);
    let inf = f.splat_lit(w, Literal::U32(0x7f80_0000));
    let nan = f.bin(Bo::Greater, bits, inf);
    let zero = f.splat_lit(w, zero);
    let v = f.sel(nan, zero, converted);
    f.ret(v)
}

fn int_div(lw: &mut Lowerer<'_>, w: u8, signed: bool, rem: bool) -> Function {
    let kind = if signed {
        ScalarKind::I32
    } else {
        ScalarKind::U32
    };
    let t = lw.sv_type(w, kind);
    let name = format!(
        "{}_{}",
        if rem { "rem" } else { "div" },
        type_suffix(w, kind)
    );
    let mut f = Pf::new(lw, &name, &[("a", t), ("b", t)], t);
    let (a, b) = (f.arg(0), f.arg(1));
    let (zero, one) = if signed {
        (Literal::I32(0), Literal::I32(1))
    } else {
        (Literal::U32(0), Literal::U32(1))
    };
    let zero = f.splat_lit(w, zero);
    let one = f.splat_lit(w, one);
    let by_zero = f.bin(Bo::Equal, b, zero);
    let by_zero = f.name(by_zero, "by_zero");
    let mut divisor = f.sel(by_zero, one, b);
    if signed {
        // `MIN / -1` overflows: divide by 1 instead (MIN / 1 = MIN, MIN % 1 = 0).
        let min = f.splat_lit(w, Literal::I32(i32::MIN));
        let minus_one = f.splat_lit(w, Literal::I32(-1));
        let a_min = f.bin(Bo::Equal, a, min);
        let b_m1 = f.bin(Bo::Equal, b, minus_one);
        let overflow = f.bin(Bo::And, a_min, b_m1);
        divisor = f.sel(overflow, one, divisor);
    }
    let divisor = f.name(divisor, "divisor");
    let v = if rem {
        // `a - d * (a / d)`: truncated, like naga's `%`, but also defined for negative operands in
        // GLSL (whose `%` is not).
        let r = if signed {
            let q = f.div(a, divisor);
            let dq = f.mul(divisor, q);
            f.sub(a, dq)
        } else {
            f.bin(Bo::Modulo, a, divisor)
        };
        // Remainder by zero is 0 (spec/expressions.md, as in WGSL).
        f.sel(by_zero, zero, r)
    } else {
        f.div(a, divisor)
    };
    f.ret(v)
}

fn normalize(lw: &mut Lowerer<'_>, w: u8) -> Function {
    let t = lw.sv_type(w, ScalarKind::F32);
    let mut f = Pf::new(lw, &format!("normalize_vec{w}f"), &[("v", t)], t);
    let v = f.arg(0);
    let len2 = f.m(Mf::Dot, &[v, v]);
    // Squared lengths below the smallest normal float count as zero: the result is then the same on
    // GPUs that flush denormals and on those that keep them (whose normalisation of such vectors
    // is inaccurate anyway).
    let smallest = f.f(f32::MIN_POSITIVE);
    let nonzero = f.bin(Bo::GreaterEqual, len2, smallest);
    let unit = f.m(Mf::Normalize, &[v]);
    let zeros = f.splat_lit(w, Literal::F32(0.0));
    let r = f.sel(nonzero, unit, zeros);
    f.ret(r)
}

/// Inverse by the adjugate: `inverse[c][r] = cofactor(row c, column r) / det`, with the minors'
/// determinants memoised so that the 2×2 ones are shared (a 4×4 needs 36 products for them).
fn inverse(lw: &mut Lowerer<'_>, n: u8) -> Function {
    let size = vector_size(n).unwrap_or(VectorSize::Quad);
    let mt = TypeCache::matrix(&mut lw.module, size, size);
    let col_t = lw.sv_type(n, ScalarKind::F32);
    let mut f = Pf::new(lw, &format!("inverse_mat{n}x{n}f"), &[("m", mt)], mt);
    let m = f.arg(0);
    let n = usize::from(n);
    // a[r][c] = m[c][r]
    let mut a = vec![vec![m; n]; n];
    for c in 0..n {
        let col = f.at(m, c as u32);
        for (r, row) in a.iter_mut().enumerate() {
            row[c] = f.at(col, r as u32);
        }
    }
    let mut memo: BTreeMap<(Vec<usize>, Vec<usize>), H> = BTreeMap::new();
    let all: Vec<usize> = (0..n).collect();
    let det = minor_det(&mut f, &a, &all, &all, &mut memo);
    let det = f.name(det, "det");
    // A singular matrix gives zero.
    let zero = f.f(0.0);
    let singular = f.bin(Bo::Equal, det, zero);
    f.fb.push_block();
    let z = f.fb.expr(Expression::ZeroValue(mt), U);
    f.fb.ret(Some(z), U);
    let accept = f.fb.pop_block();
    f.fb.stmt(
        Statement::If {
            condition: singular,
            accept,
            reject: naga::Block::new(),
        },
        U,
    );
    let one = f.f(1.0);
    let inv_det = f.div(one, det);
    let mut columns = Vec::with_capacity(n);
    for c in 0..n {
        let mut comps = Vec::with_capacity(n);
        for r in 0..n {
            // Cofactor of a at (row c, column r).
            let rows: Vec<usize> = all.iter().copied().filter(|&i| i != c).collect();
            let cols: Vec<usize> = all.iter().copied().filter(|&j| j != r).collect();
            let minor = minor_det(&mut f, &a, &rows, &cols, &mut memo);
            let signed = if (r + c) % 2 == 1 {
                f.fb.unary(naga::UnaryOperator::Negate, minor, U)
            } else {
                minor
            };
            comps.push(f.mul(signed, inv_det));
        }
        columns.push(f.compose(col_t, comps));
    }
    let result = f.compose(mt, columns);
    f.ret(result)
}

/// The determinant of the submatrix of `a` on `rows` × `cols`, by expansion along its first row.
fn minor_det(
    f: &mut Pf<'_, '_>,
    a: &[Vec<H>],
    rows: &[usize],
    cols: &[usize],
    memo: &mut BTreeMap<(Vec<usize>, Vec<usize>), H>,
) -> H {
    if let Some(h) = memo.get(&(rows.to_vec(), cols.to_vec())) {
        return *h;
    }
    let h = match (rows, cols) {
        ([r], [c]) => a[*r][*c],
        ([r0, r1], [c0, c1]) => {
            let p = f.mul(a[*r0][*c0], a[*r1][*c1]);
            let q = f.mul(a[*r0][*c1], a[*r1][*c0]);
            f.sub(p, q)
        }
        _ => {
            let (r0, rest) = rows.split_first().map_or((0, &[][..]), |(r, s)| (*r, s));
            let mut acc: Option<H> = None;
            for (j, &c) in cols.iter().enumerate() {
                let sub_cols: Vec<usize> = cols.iter().copied().filter(|&k| k != c).collect();
                let minor = minor_det(f, a, rest, &sub_cols, memo);
                let term = f.mul(a[r0][c], minor);
                acc = Some(match acc {
                    None => term,
                    Some(s) if j % 2 == 1 => f.sub(s, term),
                    Some(s) => f.add(s, term),
                });
            }
            acc.unwrap_or_else(|| f.f(0.0))
        }
    };
    memo.insert((rows.to_vec(), cols.to_vec()), h);
    h
}

fn transform(lw: &mut Lowerer<'_>, point: bool) -> Function {
    let m4 = TypeCache::matrix(&mut lw.module, VectorSize::Quad, VectorSize::Quad);
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let v4 = lw.sv_type(4, ScalarKind::F32);
    let (name, arg) = if point {
        ("transform_point", "p")
    } else {
        ("transform_dir", "d")
    };
    let mut f = Pf::new(lw, name, &[("m", m4), (arg, v3)], v3);
    let (m, p) = (f.arg(0), f.arg(1));
    let w = f.f(if point { 1.0 } else { 0.0 });
    let h = f.compose(v4, vec![p, w]);
    let r = f.mul(m, h);
    let xyz = f.fb.expr(
        Expression::Swizzle {
            size: VectorSize::Tri,
            vector: r,
            pattern: [
                naga::SwizzleComponent::X,
                naga::SwizzleComponent::Y,
                naga::SwizzleComponent::Z,
                naga::SwizzleComponent::X,
            ],
        },
        U,
    );
    f.ret(xyz)
}

/// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": columns `t`, `b`, `n`.
fn orthonormal_basis(lw: &mut Lowerer<'_>) -> Function {
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let m3 = TypeCache::matrix(&mut lw.module, VectorSize::Tri, VectorSize::Tri);
    let mut f = Pf::new(lw, "orthonormal_basis", &[("n", v3)], m3);
    let n = f.arg(0);
    let (x, y, z) = (f.at(n, 0), f.at(n, 1), f.at(n, 2));
    // copysign(1.0, n.z): the sign bit decides, so -0.0 counts as negative.
    let zbits = f.fb.cast(z, Sk::Uint, None, U);
    let sign_bit = f.u(0x8000_0000);
    let neg_bits = f.bin(Bo::And, zbits, sign_bit);
    let zero_u = f.u(0);
    let negative = f.bin(Bo::NotEqual, neg_bits, zero_u);
    let (one, minus_one) = (f.f(1.0), f.f(-1.0));
    let sign = f.sel(negative, minus_one, one);
    let sign = f.name(sign, "sign");
    let sz = f.add(sign, z);
    let a = f.div(minus_one, sz);
    let a = f.name(a, "a");
    let xy = f.mul(x, y);
    let b = f.mul(xy, a);
    let b = f.name(b, "b");
    // t = (1 + sign * x * x * a, sign * b, -sign * x)
    let sx = f.mul(sign, x);
    let sxx = f.mul(sx, x);
    let sxxa = f.mul(sxx, a);
    let t0 = f.add(one, sxxa);
    let t1 = f.mul(sign, b);
    let t2 = f.fb.unary(naga::UnaryOperator::Negate, sx, U);
    let t = f.vec3(t0, t1, t2);
    // b = (b, sign + y * y * a, -y)
    let yy = f.mul(y, y);
    let yya = f.mul(yy, a);
    let b1 = f.add(sign, yya);
    let b2 = f.fb.unary(naga::UnaryOperator::Negate, y, U);
    let bt = f.vec3(b, b1, b2);
    let r = f.compose(m3, vec![t, bt, n]);
    f.ret(r)
}

fn sample_uniform_sphere(lw: &mut Lowerer<'_>) -> Function {
    let v2 = lw.sv_type(2, ScalarKind::F32);
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let mut f = Pf::new(lw, "sample_uniform_sphere", &[("u", v2)], v3);
    let u = f.arg(0);
    let (ux, uy) = (f.at(u, 0), f.at(u, 1));
    // z = 1 - 2 u.x, r = sqrt(max(0, 1 - z z)), phi = 2 pi u.y
    let (one, two, zero) = (f.f(1.0), f.f(2.0), f.f(0.0));
    let two_ux = f.mul(two, ux);
    let z = f.sub(one, two_ux);
    let z = f.name(z, "z");
    let zz = f.mul(z, z);
    let s = f.sub(one, zz);
    let s = f.m(Mf::Max, &[s, zero]);
    let r = f.m(Mf::Sqrt, &[s]);
    let r = f.name(r, "r");
    let tau = f.f(std::f32::consts::TAU);
    let phi = f.mul(tau, uy);
    let phi = f.name(phi, "phi");
    let (c, sn) = (f.m(Mf::Cos, &[phi]), f.m(Mf::Sin, &[phi]));
    let (x, y) = (f.mul(r, c), f.mul(r, sn));
    let v = f.vec3(x, y, z);
    f.ret(v)
}

/// Malley's method: a uniform disk sample lifted to the hemisphere about `n`.
fn sample_cosine_hemisphere(lw: &mut Lowerer<'_>) -> Result<Function, LowerError> {
    let v2 = lw.sv_type(2, ScalarKind::F32);
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let mut f = Pf::new(lw, "sample_cosine_hemisphere", &[("n", v3), ("u", v2)], v3);
    let (n, u) = (f.arg(0), f.arg(1));
    let (ux, uy) = (f.at(u, 0), f.at(u, 1));
    let (one, zero) = (f.f(1.0), f.f(0.0));
    let r = f.m(Mf::Sqrt, &[ux]);
    let r = f.name(r, "r");
    let tau = f.f(std::f32::consts::TAU);
    let phi = f.mul(tau, uy);
    let phi = f.name(phi, "phi");
    let (c, s) = (f.m(Mf::Cos, &[phi]), f.m(Mf::Sin, &[phi]));
    let (x, y) = (f.mul(r, c), f.mul(r, s));
    let rest = f.sub(one, ux);
    let rest = f.m(Mf::Max, &[rest, zero]);
    let z = f.m(Mf::Sqrt, &[rest]);
    let local = f.vec3(x, y, z);
    let local = f.name(local, "local");
    let basis = f.call(Polyfill::OrthonormalBasis, vec![n])?;
    let basis = f.name(basis, "basis");
    let v = f.mul(basis, local);
    Ok(f.ret(v))
}

fn luminance(lw: &mut Lowerer<'_>) -> Function {
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let f32t = lw.sv_type(1, ScalarKind::F32);
    let mut f = Pf::new(lw, "luminance", &[("c", v3)], f32t);
    let c = f.arg(0);
    // Rec. 709 primaries.
    let (r, g, b) = (f.f(0.2126), f.f(0.7152), f.f(0.0722));
    let weights = f.vec3(r, g, b);
    let v = f.m(Mf::Dot, &[c, weights]);
    f.ret(v)
}

fn translate_scale(lw: &mut Lowerer<'_>, scale: bool) -> Function {
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let m4 = TypeCache::matrix(&mut lw.module, VectorSize::Quad, VectorSize::Quad);
    let name = if scale { "scale" } else { "translate" };
    let mut f = Pf::new(lw, name, &[("v", v3)], m4);
    let v = f.arg(0);
    let (x, y, z) = (f.at(v, 0), f.at(v, 1), f.at(v, 2));
    let (o, l) = (f.f(0.0), f.f(1.0));
    let m = if scale {
        f.mat4([[x, o, o, o], [o, y, o, o], [o, o, z, o], [o, o, o, l]])
    } else {
        f.mat4([[l, o, o, o], [o, l, o, o], [o, o, l, o], [x, y, z, l]])
    };
    f.ret(m)
}

/// `rotate_x`, `rotate_y`, `rotate_z`: right-handed rotations by `deg` degrees.
fn rotate_axis(lw: &mut Lowerer<'_>, p: Polyfill) -> Function {
    let f32t = lw.sv_type(1, ScalarKind::F32);
    let m4 = TypeCache::matrix(&mut lw.module, VectorSize::Quad, VectorSize::Quad);
    let name = match p {
        Polyfill::RotateX => "rotate_x",
        Polyfill::RotateY => "rotate_y",
        _ => "rotate_z",
    };
    let mut f = Pf::new(lw, name, &[("deg", f32t)], m4);
    let deg = f.arg(0);
    let rad = f.m(Mf::Radians, &[deg]);
    let (s, c) = (f.m(Mf::Sin, &[rad]), f.m(Mf::Cos, &[rad]));
    let s = f.name(s, "s");
    let c = f.name(c, "c");
    let ns = f.fb.unary(naga::UnaryOperator::Negate, s, U);
    let (o, l) = (f.f(0.0), f.f(1.0));
    let m = match p {
        Polyfill::RotateX => f.mat4([[l, o, o, o], [o, c, s, o], [o, ns, c, o], [o, o, o, l]]),
        Polyfill::RotateY => f.mat4([[c, o, ns, o], [o, l, o, o], [s, o, c, o], [o, o, o, l]]),
        _ => f.mat4([[c, s, o, o], [ns, c, o, o], [o, o, l, o], [o, o, o, l]]),
    };
    f.ret(m)
}

/// Rodrigues' rotation about `axis` (normalised here; a zero axis gives the identity).
fn rotate(lw: &mut Lowerer<'_>) -> Function {
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let f32t = lw.sv_type(1, ScalarKind::F32);
    let m4 = TypeCache::matrix(&mut lw.module, VectorSize::Quad, VectorSize::Quad);
    let mut f = Pf::new(lw, "rotate", &[("axis", v3), ("deg", f32t)], m4);
    let (axis, deg) = (f.arg(0), f.arg(1));
    let (o, l) = (f.f(0.0), f.f(1.0));
    let len = f.m(Mf::Length, &[axis]);
    let len = f.name(len, "len");
    let degenerate = f.bin(Bo::Equal, len, o);
    f.fb.push_block();
    let id = f.mat4([[l, o, o, o], [o, l, o, o], [o, o, l, o], [o, o, o, l]]);
    f.fb.ret(Some(id), U);
    let accept = f.fb.pop_block();
    f.fb.stmt(
        Statement::If {
            condition: degenerate,
            accept,
            reject: naga::Block::new(),
        },
        U,
    );
    let (ax, ay, az) = (f.at(axis, 0), f.at(axis, 1), f.at(axis, 2));
    let (x, y, z) = (f.div(ax, len), f.div(ay, len), f.div(az, len));
    let rad = f.m(Mf::Radians, &[deg]);
    let (s, c) = (f.m(Mf::Sin, &[rad]), f.m(Mf::Cos, &[rad]));
    let s = f.name(s, "s");
    let c = f.name(c, "c");
    let t = f.sub(l, c);
    let t = f.name(t, "t");
    let (tx, ty, tz) = (f.mul(t, x), f.mul(t, y), f.mul(t, z));
    let (sx, sy, sz) = (f.mul(s, x), f.mul(s, y), f.mul(s, z));
    let txx = f.mul(tx, x);
    let txy = f.mul(tx, y);
    let txz = f.mul(tx, z);
    let tyy = f.mul(ty, y);
    let tyz = f.mul(ty, z);
    let tzz = f.mul(tz, z);
    let m00 = f.add(txx, c);
    let m01 = f.add(txy, sz);
    let m02 = f.sub(txz, sy);
    let m10 = f.sub(txy, sz);
    let m11 = f.add(tyy, c);
    let m12 = f.add(tyz, sx);
    let m20 = f.add(txz, sy);
    let m21 = f.sub(tyz, sx);
    let m22 = f.add(tzz, c);
    let m = f.mat4([
        [m00, m01, m02, o],
        [m10, m11, m12, o],
        [m20, m21, m22, o],
        [o, o, o, l],
    ]);
    f.ret(m)
}

/// The naga types of the prelude's `Ray`, `Triangle` and `Intersection`.
pub(super) struct FrameworkTypes {
    pub ray: Handle<Type>,
    pub triangle: Handle<Type>,
    pub intersection: Handle<Type>,
}

/// Framework struct types, for the geometry helpers.
pub(super) fn framework_types(lw: &mut Lowerer<'_>) -> Result<FrameworkTypes, LowerError> {
    let fw = lw.program.framework;
    Ok(FrameworkTypes {
        ray: lw.framework_struct(fw.ray, "the prelude struct `Ray` is missing")?,
        triangle: lw.framework_struct(fw.triangle, "the prelude struct `Triangle` is missing")?,
        intersection: lw.framework_struct(
            fw.intersection,
            "the prelude struct `Intersection` is missing",
        )?,
    })
}

/// The index of a field of a framework struct.
pub(super) fn framework_field(
    lw: &Lowerer<'_>,
    s: Option<StructId>,
    name: &str,
) -> Result<u32, LowerError> {
    lw.field(s, name)
}

/// The `Ray` type, for `intersect_aabb`.
pub(super) fn ray_type(lw: &mut Lowerer<'_>) -> Result<Handle<Type>, LowerError> {
    let fw = lw.program.framework;
    lw.framework_struct(fw.ray, "the prelude struct `Ray` is missing")
}
