//! The constant built-in functions, evaluated in f32 as the GPU computes them, and matrix arithmetic.
//!
//! Each function here implements the formula that spec/builtins.md gives (the GPU's result is within
//! the tolerance listed there); f32 math uses Rust's `f32` functions. Arguments are well typed (the
//! checker resolved the overload); anything else gives `None`, never a panic.
//!
//! Transforms are column-major 4×4 matrices (`data[c][r]`) acting on column vectors; rotations are
//! right-handed, in degrees.

use super::builtins::Builtin;
use super::consteval::{
    components, f32_of, from_components, map1, map2, scalar_binary, vector_f32,
};
use super::hir::{BinaryOp, ConstValue, MeshAsset, Scalar, TextureAsset, IDENTITY};
use crate::source::Span;
use std::path::Path;

type M4 = [[f32; 4]; 4];

fn f(v: f32) -> Scalar {
    Scalar::F32(v)
}

fn float1(v: &ConstValue, op: impl Fn(f32) -> f32) -> Option<ConstValue> {
    map1(v, |s| match s {
        Scalar::F32(x) => Some(f(op(x))),
        _ => None,
    })
    .ok()
}

fn float2(a: &ConstValue, b: &ConstValue, op: impl Fn(f32, f32) -> f32) -> Option<ConstValue> {
    map2(a, b, |x, y| match (x, y) {
        (Scalar::F32(x), Scalar::F32(y)) => Some(f(op(x, y))),
        _ => None,
    })
    .ok()
}

fn float3(
    a: &ConstValue,
    b: &ConstValue,
    c: &ConstValue,
    op: impl Fn(f32, f32, f32) -> f32,
) -> Option<ConstValue> {
    let (w, ca) = components(a)?;
    let (_, cb) = components(b)?;
    let (wc, cc) = components(c)?;
    let mut out = ca;
    for i in 0..usize::from(w) {
        // A scalar third argument (`mix(a, b, t)` with `t: f32`) applies to every component.
        let z = if wc == 1 { cc[0] } else { cc[i] };
        out[i] = f(op(f32_of(ca[i]), f32_of(cb[i]), f32_of(z)));
    }
    Some(from_components(w, out))
}

fn floats(v: &ConstValue) -> Option<Vec<f32>> {
    let (w, cs) = components(v)?;
    Some(cs[..usize::from(w)].iter().map(|s| f32_of(*s)).collect())
}

fn dot(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn scalar_f(x: f32) -> ConstValue {
    ConstValue::Scalar(f(x))
}

fn first_leading_bit(s: Scalar) -> Option<Scalar> {
    Some(match s {
        Scalar::U32(x) => Scalar::U32(if x == 0 {
            u32::MAX
        } else {
            31 - x.leading_zeros()
        }),
        Scalar::I32(x) => {
            let y = if x < 0 { !x } else { x } as u32;
            Scalar::I32(if y == 0 {
                -1
            } else {
                31 - y.leading_zeros() as i32
            })
        }
        _ => return None,
    })
}

fn first_trailing_bit(s: Scalar) -> Option<Scalar> {
    Some(match s {
        Scalar::U32(x) => Scalar::U32(if x == 0 { u32::MAX } else { x.trailing_zeros() }),
        Scalar::I32(x) => Scalar::I32(if x == 0 {
            -1
        } else {
            x.trailing_zeros() as i32
        }),
        _ => return None,
    })
}

fn int1(v: &ConstValue, op_u: fn(u32) -> u32) -> Option<ConstValue> {
    map1(v, |s| match s {
        Scalar::U32(x) => Some(Scalar::U32(op_u(x))),
        Scalar::I32(x) => Some(Scalar::I32(op_u(x as u32) as i32)),
        _ => None,
    })
    .ok()
}

fn numeric2(a: &ConstValue, b: &ConstValue, max: bool) -> Option<ConstValue> {
    map2(a, b, |x, y| {
        Some(match (x, y) {
            (Scalar::F32(x), Scalar::F32(y)) => f(if max { x.max(y) } else { x.min(y) }),
            (Scalar::I32(x), Scalar::I32(y)) => Scalar::I32(if max { x.max(y) } else { x.min(y) }),
            (Scalar::U32(x), Scalar::U32(y)) => Scalar::U32(if max { x.max(y) } else { x.min(y) }),
            _ => return None,
        })
    })
    .ok()
}

fn smoothstep(lo: f32, hi: f32, x: f32) -> f32 {
    let t = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

fn mat(v: &ConstValue) -> Option<(u8, u8, M4)> {
    match v {
        ConstValue::Matrix { cols, rows, data } => Some((*cols, *rows, *data)),
        _ => None,
    }
}

fn m4(data: M4) -> ConstValue {
    ConstValue::Matrix {
        cols: 4,
        rows: 4,
        data,
    }
}

/// Evaluates a constant built-in. `first_arg` is the span of the first argument (the path string of
/// `load_mesh`/`load_image`); `base_dir` is the scene file's folder.
pub fn call(
    b: Builtin,
    a: &[ConstValue],
    base_dir: Option<&Path>,
    first_arg: Span,
) -> Option<ConstValue> {
    use Builtin as B;
    let x = a.first();
    let arg = |i: usize| a.get(i);
    match b {
        B::Abs => map1(x?, |s| {
            Some(match s {
                Scalar::F32(v) => f(v.abs()),
                Scalar::I32(v) => Scalar::I32(v.wrapping_abs()),
                s => s,
            })
        })
        .ok(),
        B::Sign => map1(x?, |s| {
            Some(match s {
                Scalar::F32(v) => f(if v > 0.0 {
                    1.0
                } else if v < 0.0 {
                    -1.0
                } else {
                    0.0
                }),
                Scalar::I32(v) => Scalar::I32(v.signum()),
                _ => return None,
            })
        })
        .ok(),
        B::Min => numeric2(x?, arg(1)?, false),
        B::Max => numeric2(x?, arg(1)?, true),
        B::Clamp => numeric2(&numeric2(x?, arg(1)?, true)?, arg(2)?, false),
        B::Saturate => float1(x?, |v| v.clamp(0.0, 1.0)),
        B::Floor => float1(x?, f32::floor),
        B::Ceil => float1(x?, f32::ceil),
        B::Round => float1(x?, f32::round_ties_even),
        B::Trunc => float1(x?, f32::trunc),
        B::Fract => float1(x?, |v| v - v.floor()),
        B::Sqrt => float1(x?, f32::sqrt),
        B::InverseSqrt => float1(x?, |v| 1.0 / v.sqrt()),
        B::Pow => float2(x?, arg(1)?, f32::powf),
        B::Exp => float1(x?, f32::exp),
        B::Exp2 => float1(x?, f32::exp2),
        B::Log => float1(x?, f32::ln),
        B::Log2 => float1(x?, f32::log2),
        B::Sin => float1(x?, f32::sin),
        B::Cos => float1(x?, f32::cos),
        B::Tan => float1(x?, f32::tan),
        B::Asin => float1(x?, f32::asin),
        B::Acos => float1(x?, f32::acos),
        B::Atan => float1(x?, f32::atan),
        B::Atan2 => float2(x?, arg(1)?, f32::atan2),
        B::Sinh => float1(x?, f32::sinh),
        B::Cosh => float1(x?, f32::cosh),
        B::Tanh => float1(x?, f32::tanh),
        B::Radians => float1(x?, f32::to_radians),
        B::Degrees => float1(x?, f32::to_degrees),
        B::Mix => float3(x?, arg(1)?, arg(2)?, |a, b, t| a + (b - a) * t),
        B::Step => float2(x?, arg(1)?, |edge, v| if v >= edge { 1.0 } else { 0.0 }),
        B::Smoothstep => float3(x?, arg(1)?, arg(2)?, smoothstep),
        B::Fma => float3(x?, arg(1)?, arg(2)?, f32::mul_add),
        B::Select => select(x?, arg(1)?, arg(2)?),
        B::IsNan => map1(x?, |s| Some(Scalar::Bool(f32_of(s).is_nan()))).ok(),
        B::IsInf => map1(x?, |s| Some(Scalar::Bool(f32_of(s).is_infinite()))).ok(),
        B::IsFinite => map1(x?, |s| Some(Scalar::Bool(f32_of(s).is_finite()))).ok(),
        B::CountOnes => int1(x?, u32::count_ones),
        B::ReverseBits => int1(x?, u32::reverse_bits),
        B::FirstLeadingBit => map1(x?, first_leading_bit).ok(),
        B::FirstTrailingBit => map1(x?, first_trailing_bit).ok(),
        B::Dot => {
            let (w, ca) = components(x?)?;
            let (_, cb) = components(arg(1)?)?;
            let mut acc = ConstValue::Scalar(scalar_binary(BinaryOp::Mul, ca[0], cb[0])?);
            for i in 1..usize::from(w) {
                let p = scalar_binary(BinaryOp::Mul, ca[i], cb[i])?;
                if let ConstValue::Scalar(s) = acc {
                    acc = ConstValue::Scalar(scalar_binary(BinaryOp::Add, s, p)?);
                }
            }
            Some(acc)
        }
        B::Cross => {
            let (p, q) = (floats(x?)?, floats(arg(1)?)?);
            Some(vector_f32(&[
                p[1] * q[2] - p[2] * q[1],
                p[2] * q[0] - p[0] * q[2],
                p[0] * q[1] - p[1] * q[0],
            ]))
        }
        B::Length => {
            let v = floats(x?)?;
            Some(scalar_f(dot(&v, &v).sqrt()))
        }
        B::Distance => {
            let (p, q) = (floats(x?)?, floats(arg(1)?)?);
            let d: Vec<f32> = p.iter().zip(&q).map(|(a, b)| a - b).collect();
            Some(scalar_f(dot(&d, &d).sqrt()))
        }
        B::Normalize => {
            let v = floats(x?)?;
            let len = dot(&v, &v).sqrt();
            let inv = if len > 0.0 { 1.0 / len } else { 0.0 };
            Some(vector_f32(&v.iter().map(|c| c * inv).collect::<Vec<_>>()))
        }
        B::Reflect => {
            let (i, n) = (floats(x?)?, floats(arg(1)?)?);
            let d = dot(&n, &i);
            Some(vector_f32(
                &i.iter()
                    .zip(&n)
                    .map(|(a, b)| a - 2.0 * d * b)
                    .collect::<Vec<_>>(),
            ))
        }
        B::Refract => {
            let (i, n) = (floats(x?)?, floats(arg(1)?)?);
            let eta = f32_of(components(arg(2)?)?.1[0]);
            let d = dot(&n, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            let out: Vec<f32> = if k < 0.0 {
                vec![0.0; i.len()]
            } else {
                i.iter()
                    .zip(&n)
                    .map(|(a, b)| eta * a - (eta * d + k.sqrt()) * b)
                    .collect()
            };
            Some(vector_f32(&out))
        }
        B::FaceForward => {
            let (n, i, r) = (floats(x?)?, floats(arg(1)?)?, floats(arg(2)?)?);
            let s = if dot(&r, &i) < 0.0 { 1.0 } else { -1.0 };
            Some(vector_f32(&n.iter().map(|c| c * s).collect::<Vec<_>>()))
        }
        B::Any | B::All => {
            let (w, cs) = components(x?)?;
            let bits = cs[..usize::from(w)]
                .iter()
                .map(|s| matches!(s, Scalar::Bool(true)));
            let r = if b == B::Any {
                bits.into_iter().any(|v| v)
            } else {
                bits.into_iter().all(|v| v)
            };
            Some(ConstValue::Scalar(Scalar::Bool(r)))
        }
        B::Transpose => {
            let (c, r, d) = mat(x?)?;
            let mut t = [[0.0; 4]; 4];
            for (i, col) in t.iter_mut().enumerate().take(usize::from(r)) {
                for (j, v) in col.iter_mut().enumerate().take(usize::from(c)) {
                    *v = d[j][i];
                }
            }
            Some(ConstValue::Matrix {
                cols: r,
                rows: c,
                data: t,
            })
        }
        B::Determinant => {
            let (n, _, d) = mat(x?)?;
            Some(scalar_f(determinant(usize::from(n), &d)))
        }
        B::Inverse => {
            let (n, _, d) = mat(x?)?;
            Some(ConstValue::Matrix {
                cols: n,
                rows: n,
                data: inverse(usize::from(n), &d),
            })
        }
        B::TransformPoint | B::TransformDir => {
            let (_, _, m) = mat(x?)?;
            let p = floats(arg(1)?)?;
            let w = if b == B::TransformPoint { 1.0 } else { 0.0 };
            let v = [p[0], p[1], p[2], w];
            let out: Vec<f32> = (0..3)
                .map(|r| (0..4).map(|c| m[c][r] * v[c]).sum())
                .collect();
            Some(vector_f32(&out))
        }
        B::OrthonormalBasis => {
            let n = floats(x?)?;
            let sign = 1.0f32.copysign(n[2]);
            let a = -1.0 / (sign + n[2]);
            let bb = n[0] * n[1] * a;
            let t = [1.0 + sign * n[0] * n[0] * a, sign * bb, -sign * n[0], 0.0];
            let bt = [bb, sign + n[1] * n[1] * a, -n[1], 0.0];
            let nn = [n[0], n[1], n[2], 0.0];
            Some(ConstValue::Matrix {
                cols: 3,
                rows: 3,
                data: [t, bt, nn, [0.0; 4]],
            })
        }
        B::Identity => Some(m4(IDENTITY)),
        B::Translate => {
            let v = floats(x?)?;
            let mut m = IDENTITY;
            m[3] = [v[0], v[1], v[2], 1.0];
            Some(m4(m))
        }
        B::Scale => {
            let v = floats(x?)?;
            let s = if v.len() == 1 {
                [v[0]; 3]
            } else {
                [v[0], v[1], v[2]]
            };
            let mut m = IDENTITY;
            for (i, col) in m.iter_mut().enumerate().take(3) {
                col[i] = s[i];
            }
            Some(m4(m))
        }
        B::RotateX | B::RotateY | B::RotateZ => {
            let axis = match b {
                B::RotateX => [1.0, 0.0, 0.0],
                B::RotateY => [0.0, 1.0, 0.0],
                _ => [0.0, 0.0, 1.0],
            };
            Some(m4(rotation(axis, f32_of(components(x?)?.1[0]))))
        }
        B::Rotate => {
            let v = floats(x?)?;
            let deg = f32_of(components(arg(1)?)?.1[0]);
            Some(m4(rotation([v[0], v[1], v[2]], deg)))
        }
        B::LoadMesh => Some(ConstValue::Mesh(MeshAsset::File {
            path: asset_path(x?, base_dir)?,
            span: first_arg,
        })),
        B::QuadMesh => Some(ConstValue::Mesh(MeshAsset::Quad)),
        B::CubeMesh => Some(ConstValue::Mesh(MeshAsset::Cube)),
        B::SphereMesh => match x? {
            ConstValue::Scalar(Scalar::U32(n)) => {
                Some(ConstValue::Mesh(MeshAsset::Sphere { subdivisions: *n }))
            }
            _ => None,
        },
        B::LoadImage => Some(ConstValue::Texture(TextureAsset::File {
            path: asset_path(x?, base_dir)?,
            span: first_arg,
        })),
        B::SolidTexture => {
            let c = floats(x?)?;
            Some(ConstValue::Texture(TextureAsset::Solid([
                c[0], c[1], c[2], c[3],
            ])))
        }
        _ => None,
    }
}

fn asset_path(v: &ConstValue, base_dir: Option<&Path>) -> Option<std::path::PathBuf> {
    match v {
        ConstValue::String(s) => Some(match base_dir {
            Some(d) => d.join(s),
            None => Path::new(s).to_path_buf(),
        }),
        _ => None,
    }
}

fn select(fv: &ConstValue, tv: &ConstValue, cond: &ConstValue) -> Option<ConstValue> {
    match cond {
        ConstValue::Scalar(Scalar::Bool(c)) => Some(if *c { tv.clone() } else { fv.clone() }),
        _ => {
            let (w, cf) = components(fv)?;
            let (_, ct) = components(tv)?;
            let (_, cc) = components(cond)?;
            let mut out = cf;
            for i in 0..usize::from(w) {
                if cc[i] == Scalar::Bool(true) {
                    out[i] = ct[i];
                }
            }
            Some(from_components(w, out))
        }
    }
}

/// Rotation by `deg` degrees about `axis` (normalised here), right-handed.
fn rotation(axis: [f32; 3], deg: f32) -> M4 {
    let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    if len == 0.0 {
        return IDENTITY;
    }
    let [x, y, z] = axis.map(|c| c / len);
    let (s, c) = deg.to_radians().sin_cos();
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y + s * z, t * x * z - s * y, 0.0],
        [t * x * y - s * z, t * y * y + c, t * y * z + s * x, 0.0],
        [t * x * z + s * y, t * y * z - s * x, t * z * z + c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

fn determinant(n: usize, m: &M4) -> f32 {
    match n {
        2 => m[0][0] * m[1][1] - m[1][0] * m[0][1],
        3 => {
            m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2])
                - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2])
                + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2])
        }
        _ => (0..4)
            .map(|c| {
                let sign = if c % 2 == 0 { 1.0 } else { -1.0 };
                sign * m[c][0] * determinant(3, &minor(m, c, 0))
            })
            .sum(),
    }
}

/// The 3×3 minor of a 4×4 matrix without column `col` and row `row`.
fn minor(m: &M4, col: usize, row: usize) -> M4 {
    let mut out = [[0.0; 4]; 4];
    for (oc, c) in (0..4).filter(|&c| c != col).enumerate() {
        for (or, r) in (0..4).filter(|&r| r != row).enumerate() {
            out[oc][or] = m[c][r];
        }
    }
    out
}

/// The inverse by Gauss–Jordan elimination with partial pivoting; a singular matrix gives zeros.
fn inverse(n: usize, m: &M4) -> M4 {
    // Work on rows: a[r][c] = m[c][r], augmented with the identity.
    let mut a = [[0.0f32; 8]; 4];
    for (r, row) in a.iter_mut().enumerate().take(n) {
        for c in 0..n {
            row[c] = m[c][r];
        }
        row[n + r] = 1.0;
    }
    for col in 0..n {
        let Some(pivot) = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
        else {
            return [[0.0; 4]; 4];
        };
        if a[pivot][col] == 0.0 {
            return [[0.0; 4]; 4];
        }
        a.swap(col, pivot);
        let p = a[col][col];
        for v in a[col].iter_mut().take(2 * n) {
            *v /= p;
        }
        for r in 0..n {
            if r != col {
                let factor = a[r][col];
                let pivot_row = a[col];
                for (v, pv) in a[r].iter_mut().zip(pivot_row).take(2 * n) {
                    *v -= factor * pv;
                }
            }
        }
    }
    let mut out = [[0.0; 4]; 4];
    for (c, col) in out.iter_mut().enumerate().take(n) {
        for (r, v) in col.iter_mut().enumerate().take(n) {
            *v = a[r][n + c];
        }
    }
    out
}

/// Matrix `+`, `-`, `*` with matrices, vectors and scalars.
pub fn matrix_binary(op: BinaryOp, a: &ConstValue, b: &ConstValue) -> Option<ConstValue> {
    match (a, b) {
        (
            ConstValue::Matrix {
                cols,
                rows,
                data: x,
            },
            ConstValue::Matrix {
                data: y, cols: c2, ..
            },
        ) => {
            if op == BinaryOp::Mul {
                // (rows × cols) · (cols × c2)
                let mut out = [[0.0; 4]; 4];
                for (j, col) in out.iter_mut().enumerate().take(usize::from(*c2)) {
                    for (i, v) in col.iter_mut().enumerate().take(usize::from(*rows)) {
                        *v = (0..usize::from(*cols)).map(|k| x[k][i] * y[j][k]).sum();
                    }
                }
                return Some(ConstValue::Matrix {
                    cols: *c2,
                    rows: *rows,
                    data: out,
                });
            }
            let mut out = *x;
            for (oc, yc) in out.iter_mut().zip(y) {
                for (o, v) in oc.iter_mut().zip(yc) {
                    *o = match op {
                        BinaryOp::Add => *o + v,
                        BinaryOp::Sub => *o - v,
                        _ => return None,
                    };
                }
            }
            Some(ConstValue::Matrix {
                cols: *cols,
                rows: *rows,
                data: out,
            })
        }
        (ConstValue::Matrix { cols, rows, data }, ConstValue::Vector { .. }) => {
            let v = floats(b)?;
            let out: Vec<f32> = (0..usize::from(*rows))
                .map(|r| (0..usize::from(*cols)).map(|c| data[c][r] * v[c]).sum())
                .collect();
            Some(vector_f32(&out))
        }
        (ConstValue::Vector { .. }, ConstValue::Matrix { cols, rows, data }) => {
            let v = floats(a)?;
            let out: Vec<f32> = (0..usize::from(*cols))
                .map(|c| (0..usize::from(*rows)).map(|r| data[c][r] * v[r]).sum())
                .collect();
            Some(vector_f32(&out))
        }
        (ConstValue::Matrix { cols, rows, data }, ConstValue::Scalar(Scalar::F32(s)))
        | (ConstValue::Scalar(Scalar::F32(s)), ConstValue::Matrix { cols, rows, data }) => {
            let mut out = *data;
            out.iter_mut().flatten().for_each(|v| *v *= s);
            Some(ConstValue::Matrix {
                cols: *cols,
                rows: *rows,
                data: out,
            })
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sf(v: f32) -> ConstValue {
        ConstValue::Scalar(Scalar::F32(v))
    }

    fn call0(b: Builtin, a: &[ConstValue]) -> Option<ConstValue> {
        call(b, a, None, Span::default())
    }

    #[test]
    fn math_functions() {
        assert_eq!(call0(Builtin::Sqrt, &[sf(4.0)]), Some(sf(2.0)));
        assert_eq!(call0(Builtin::Round, &[sf(2.5)]), Some(sf(2.0)));
        assert_eq!(call0(Builtin::Fract, &[sf(-0.25)]), Some(sf(0.75)));
        assert_eq!(
            call0(Builtin::Normalize, &[vector_f32(&[0.0, 0.0, 0.0])]),
            Some(vector_f32(&[0.0, 0.0, 0.0]))
        );
        assert_eq!(
            call0(Builtin::Normalize, &[vector_f32(&[3.0, 0.0, 4.0])]),
            Some(vector_f32(&[0.6, 0.0, 0.8]))
        );
        assert_eq!(
            call0(
                Builtin::Mix,
                &[vector_f32(&[0.0, 2.0]), vector_f32(&[2.0, 4.0]), sf(0.5)]
            ),
            Some(vector_f32(&[1.0, 3.0]))
        );
        assert_eq!(
            call0(Builtin::Clamp, &[sf(3.0), sf(0.0), sf(1.0)]),
            Some(sf(1.0))
        );
        assert_eq!(
            call0(
                Builtin::FirstLeadingBit,
                &[ConstValue::Scalar(Scalar::U32(0x10))]
            ),
            Some(ConstValue::Scalar(Scalar::U32(4)))
        );
    }

    #[test]
    fn transforms_compose() {
        let t = call0(Builtin::Translate, &[vector_f32(&[1.0, 2.0, 3.0])]).unwrap();
        let s = call0(Builtin::Scale, &[sf(2.0)]).unwrap();
        let m = matrix_binary(BinaryOp::Mul, &t, &s).unwrap();
        let p = call0(
            Builtin::TransformPoint,
            &[m.clone(), vector_f32(&[1.0, 1.0, 1.0])],
        );
        assert_eq!(p, Some(vector_f32(&[3.0, 4.0, 5.0])));
        let inv = call0(Builtin::Inverse, std::slice::from_ref(&m)).unwrap();
        let id = matrix_binary(BinaryOp::Mul, &m, &inv).unwrap();
        assert_eq!(id, m4(IDENTITY));
        let r = call0(Builtin::RotateZ, &[sf(90.0)]).unwrap();
        let x = call0(Builtin::TransformDir, &[r, vector_f32(&[1.0, 0.0, 0.0])]).unwrap();
        let ConstValue::Vector { comps, .. } = x else {
            panic!("not a vector")
        };
        assert!((f32_of(comps[1]) - 1.0).abs() < 1e-6 && f32_of(comps[0]).abs() < 1e-6);
        assert_eq!(call0(Builtin::Determinant, &[s]), Some(sf(8.0)));
    }
}
