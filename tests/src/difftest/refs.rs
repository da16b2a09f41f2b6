//! CPU references for the built-ins whose meaning is more than one `std` call: integer edge
//! semantics, conversions, bit counting, matrices, transforms and the geometry helpers.
//!
//! Each follows spec/builtins.md (and types.md, expressions.md) literally; where the spec leaves a
//! choice to the implementation (the order of a formula), the comment says which formula the GPU
//! code uses. Matrices are column-major `[column][row]`.

/// `a / b` for `i32`: a zero divisor gives `a`; `MIN / -1` gives `MIN`.
pub fn div_i32(a: i32, b: i32) -> i32 {
    if b == 0 {
        a
    } else {
        a.wrapping_div(b)
    }
}

/// `a % b` for `i32`: a zero divisor gives 0; `MIN % -1` gives 0; truncated (sign of `a`).
pub fn rem_i32(a: i32, b: i32) -> i32 {
    if b == 0 {
        0
    } else {
        a.wrapping_rem(b)
    }
}

/// `a / b` for `u32`: a zero divisor gives `a`.
pub fn div_u32(a: u32, b: u32) -> u32 {
    a.checked_div(b).unwrap_or(a)
}

/// `a % b` for `u32`: a zero divisor gives 0.
pub fn rem_u32(a: u32, b: u32) -> u32 {
    a.checked_rem(b).unwrap_or(0)
}

/// `i32(x)` of an `f32`: truncation, saturating to the `f32` values nearest the range
/// (`2147483520.0` is the largest below 2^31), NaN gives 0.
pub fn f32_to_i32(x: f32) -> i32 {
    if x.is_nan() {
        0
    } else {
        x.clamp(-2_147_483_648.0, 2_147_483_520.0) as i32
    }
}

/// `u32(x)` of an `f32`, likewise (`4294967040.0` is the largest below 2^32).
pub fn f32_to_u32(x: f32) -> u32 {
    if x.is_nan() {
        0
    } else {
        x.clamp(0.0, 4_294_967_040.0) as u32
    }
}

/// `first_leading_bit` of an `i32`: the highest bit that differs from the sign bit, -1 for 0 and -1.
pub fn first_leading_bit_i32(x: i32) -> i32 {
    let y = if x < 0 { !x } else { x } as u32;
    if y == 0 {
        -1
    } else {
        31 - y.leading_zeros() as i32
    }
}

/// `first_leading_bit` of a `u32`: the highest set bit, `u32::MAX` for 0.
pub fn first_leading_bit_u32(x: u32) -> u32 {
    if x == 0 {
        u32::MAX
    } else {
        31 - x.leading_zeros()
    }
}

/// `first_trailing_bit`: the lowest set bit, all ones for 0.
pub fn first_trailing_bit_u32(x: u32) -> u32 {
    if x == 0 {
        u32::MAX
    } else {
        x.trailing_zeros()
    }
}

/// A column-major matrix of up to 4×4 in `f64`.
pub type M = Vec<Vec<f64>>;

/// The matrix with `cols` columns of `rows` rows from column-major components.
pub fn mat(cols: usize, rows: usize, comps: &[f32]) -> M {
    (0..cols)
        .map(|c| (0..rows).map(|r| f64::from(comps[c * rows + r])).collect())
        .collect()
}

/// Column-major components of a matrix as `f32`.
pub fn flat(m: &M) -> Vec<f32> {
    m.iter().flatten().map(|v| *v as f32).collect()
}

/// `a * b`.
pub fn mul(a: &M, b: &M) -> M {
    let rows = a[0].len();
    b.iter()
        .map(|col| {
            (0..rows)
                .map(|r| col.iter().enumerate().map(|(k, v)| a[k][r] * v).sum())
                .collect()
        })
        .collect()
}

/// `m * v` (a column vector).
pub fn mul_vec(m: &M, v: &[f64]) -> Vec<f64> {
    let rows = m[0].len();
    (0..rows)
        .map(|r| m.iter().zip(v).map(|(col, x)| col[r] * x).sum())
        .collect()
}

/// The determinant of a square matrix (Laplace expansion).
pub fn det(m: &M) -> f64 {
    let n = m.len();
    if n == 1 {
        return m[0][0];
    }
    (0..n)
        .map(|c| {
            let minor: M = (0..n)
                .filter(|&k| k != c)
                .map(|k| m[k][1..].to_vec())
                .collect();
            let sign = if c % 2 == 0 { 1.0 } else { -1.0 };
            sign * m[c][0] * det(&minor)
        })
        .sum()
}

/// The inverse by Gauss–Jordan elimination in `f64`; `None` if singular.
pub fn inverse(m: &M) -> Option<M> {
    let n = m.len();
    // Rows of [A | I], A[r][c] = m[c][r].
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|r| {
            let mut row: Vec<f64> = (0..n).map(|c| m[c][r]).collect();
            row.extend((0..n).map(|c| if c == r { 1.0 } else { 0.0 }));
            row
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col] == 0.0 {
            return None;
        }
        a.swap(col, pivot);
        let p = a[col][col];
        for v in a[col].iter_mut() {
            *v /= p;
        }
        for r in 0..n {
            if r != col {
                let factor = a[r][col];
                let pivot_row = a[col].clone();
                for (v, pv) in a[r].iter_mut().zip(pivot_row) {
                    *v -= factor * pv;
                }
            }
        }
    }
    Some(
        (0..n)
            .map(|c| (0..n).map(|r| a[r][n + c]).collect())
            .collect(),
    )
}

/// The 4×4 identity.
pub fn identity4() -> M {
    (0..4)
        .map(|c| (0..4).map(|r| if r == c { 1.0 } else { 0.0 }).collect())
        .collect()
}

/// `rotate(axis, deg)`: Rodrigues' formula about the normalised axis, right-handed; a zero axis gives
/// the identity.
pub fn rotate(axis: [f64; 3], deg: f64) -> M {
    let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    if len == 0.0 {
        return identity4();
    }
    let [x, y, z] = axis.map(|c| c / len);
    let (s, c) = deg.to_radians().sin_cos();
    let t = 1.0 - c;
    vec![
        vec![t * x * x + c, t * x * y + s * z, t * x * z - s * y, 0.0],
        vec![t * x * y - s * z, t * y * y + c, t * y * z + s * x, 0.0],
        vec![t * x * z + s * y, t * y * z - s * x, t * z * z + c, 0.0],
        vec![0.0, 0.0, 0.0, 1.0],
    ]
}

/// `orthonormal_basis(n)` (Duff et al. 2017), in `f32` as the GPU computes it: columns `t`, `b`, `n`.
pub fn orthonormal_basis(n: [f32; 3]) -> [[f32; 3]; 3] {
    let sign = 1.0f32.copysign(n[2]);
    let a = -1.0 / (sign + n[2]);
    let b = n[0] * n[1] * a;
    [
        [1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]],
        [b, sign + n[1] * n[1] * a, -n[1]],
        n,
    ]
}

/// `sample_uniform_sphere(u)`: `z = 1 - 2 u.x`, `phi = 2 pi u.y`.
pub fn sample_uniform_sphere(u: [f64; 2]) -> [f64; 3] {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = std::f64::consts::TAU * u[1];
    [r * phi.cos(), r * phi.sin(), z]
}

/// `sample_cosine_hemisphere(n, u)`: a disk sample `(sqrt(u.x), 2 pi u.y)` lifted to the hemisphere,
/// in the basis of [`orthonormal_basis`].
pub fn sample_cosine_hemisphere(n: [f32; 3], u: [f64; 2]) -> [f64; 3] {
    let r = u[0].sqrt();
    let phi = std::f64::consts::TAU * u[1];
    let local = [r * phi.cos(), r * phi.sin(), (1.0 - u[0]).max(0.0).sqrt()];
    let b = orthonormal_basis(n);
    (0..3)
        .map(|row| (0..3).map(|c| f64::from(b[c][row]) * local[c]).sum())
        .collect::<Vec<f64>>()
        .try_into()
        .unwrap_or([0.0; 3])
}

/// A ray as the prelude's `Ray` fields the helpers read.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// Origin.
    pub origin: [f32; 3],
    /// Direction.
    pub dir: [f32; 3],
    /// Smallest `t`.
    pub tmin: f32,
    /// Largest `t`.
    pub tmax: f32,
}

fn sub3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `intersect_aabb(ray, min, max)`: the exact slab test; see `lower/geometry.rs`.
pub fn intersect_aabb(ray: &Ray, lo: [f32; 3], hi: [f32; 3]) -> [f32; 2] {
    let mut entry = f32::NEG_INFINITY;
    let mut exit = f32::INFINITY;
    for k in 0..3 {
        let d = ray.dir[k];
        let (near, far) = if d.abs() < f32::MIN_POSITIVE {
            if lo[k] <= ray.origin[k] && ray.origin[k] <= hi[k] {
                (f32::NEG_INFINITY, f32::INFINITY)
            } else {
                (f32::INFINITY, f32::NEG_INFINITY)
            }
        } else {
            let inv = 1.0 / d;
            let t0 = (lo[k] - ray.origin[k]) * inv;
            let t1 = (hi[k] - ray.origin[k]) * inv;
            (t0.min(t1), t0.max(t1))
        };
        entry = entry.max(near);
        exit = exit.min(far);
    }
    [entry.max(ray.tmin), exit.min(ray.tmax)]
}

/// `intersect_triangle(ray, tri)` as `(t, normal, uv)`: the watertight test in `f32` (the CPU reference
/// of `rtc-bvh` without its double-precision fallback for edge functions that are exactly zero), both
/// faces; a miss is `(INF, (0, 0, 1), (0, 0))`.
pub fn intersect_triangle(ray: &Ray, tri: [[f32; 3]; 3]) -> (f32, [f32; 3], [f32; 2]) {
    let miss = (f32::INFINITY, [0.0, 0.0, 1.0], [0.0, 0.0]);
    if !ray.origin.iter().chain(&ray.dir).all(|v| v.is_finite()) {
        return miss;
    }
    let d = ray
        .dir
        .map(|c| if c.abs() < f32::MIN_POSITIVE { 0.0 } else { c });
    let ad = d.map(f32::abs);
    let mut kz = 0;
    let mut max = ad[0];
    if ad[1] > max {
        max = ad[1];
        kz = 1;
    }
    if ad[2] > max {
        kz = 2;
    }
    let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
    if d[kz] < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    if d[kz] == 0.0 {
        return miss;
    }
    let (sx, sy, sz) = (d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
    let rel = tri.map(|p| sub3(p, ray.origin));
    let sh = rel.map(|p| (p[kx] - sx * p[kz], p[ky] - sy * p[kz], sz * p[kz]));
    let [(ax, ay, az), (bx, by, bz), (cx, cy, cz)] = sh;
    let u = cx * by - cy * bx;
    let v = ax * cy - ay * cx;
    let w = bx * ay - by * ax;
    if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
        return miss;
    }
    let det = u + v + w;
    if det == 0.0 {
        return miss;
    }
    let rcp = 1.0 / det;
    let t = (u * az + v * bz + w * cz) * rcp;
    if !(t >= ray.tmin && t <= ray.tmax) {
        return miss;
    }
    let e1 = sub3(tri[1], tri[0]);
    let e2 = sub3(tri[2], tri[0]);
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    let len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    let n = if len2 > 0.0 {
        let inv = 1.0 / len2.sqrt();
        n.map(|c| c * inv)
    } else {
        [0.0; 3]
    };
    (t, n, [v * rcp, w * rcp])
}

/// An `f32` as IEEE binary16 bits, rounded to nearest even (overflow to infinity; NaN stays NaN).
pub fn f32_to_f16(x: f32) -> u16 {
    let bits = x.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exp = ((bits >> 23) & 0xff) as i32;
    let man = bits & 0x7f_ffff;
    if exp == 0xff {
        return sign | 0x7c00 | if man != 0 { 0x200 } else { 0 };
    }
    let e = exp - 127 + 15;
    if e >= 0x1f {
        return sign | 0x7c00;
    }
    if e <= 0 {
        // A binary16 denormal (or zero): shift the full mantissa into place, rounding to even.
        if e < -10 {
            return sign;
        }
        let m = man | 0x80_0000;
        let shift = (14 - e) as u32;
        let half = 1u32 << (shift - 1);
        let rest = m & ((1 << shift) - 1);
        let mut r = m >> shift;
        if rest > half || (rest == half && r & 1 == 1) {
            r += 1;
        }
        return sign | r as u16;
    }
    let rest = man & 0x1fff;
    let mut r = ((e as u32) << 10) | (man >> 13);
    if rest > 0x1000 || (rest == 0x1000 && r & 1 == 1) {
        r += 1;
    }
    sign | r as u16
}

/// IEEE binary16 bits as an `f32` (exact).
pub fn f16_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exp = i32::from((h >> 10) & 0x1f);
    let man = f32::from(h & 0x3ff);
    match exp {
        0 => sign * man * 2f32.powi(-24),
        0x1f if man == 0.0 => sign * f32::INFINITY,
        0x1f => f32::NAN,
        e => sign * (1.0 + man / 1024.0) * 2f32.powi(e - 15),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::difftest::gen::Rng;
    use glam::{Vec3, Vec3A};
    use rtc_bvh::traverse::{self, PreparedRay};

    fn v3(r: &mut Rng, lo: f32, hi: f32) -> [f32; 3] {
        [r.range(lo, hi), r.range(lo, hi), r.range(lo, hi)]
    }

    /// The GPU built-ins' references agree with rtc-bvh's CPU traversal tests: the same hits, `t`
    /// and barycentrics (the reference differs only on edge functions that are exactly zero, which
    /// rtc-bvh recomputes in double precision; those inputs are skipped).
    #[test]
    fn triangle_and_box_tests_match_rtc_bvh() {
        let mut r = Rng::new(7);
        let (mut hits, mut misses) = (0, 0);
        for _ in 0..20_000 {
            let tri = [
                v3(&mut r, -5.0, 5.0),
                v3(&mut r, -5.0, 5.0),
                v3(&mut r, -5.0, 5.0),
            ];
            let origin = v3(&mut r, -10.0, 10.0);
            let dir = if r.below(2) == 0 {
                v3(&mut r, -1.0, 1.0)
            } else {
                // Aimed at a point of the triangle (barycentrics in (0, 1)).
                let (u, v) = (r.unit(), r.unit());
                let (u, v) = if u + v > 1.0 {
                    (1.0 - u, 1.0 - v)
                } else {
                    (u, v)
                };
                let p: Vec<f32> = (0..3)
                    .map(|k| (1.0 - u - v) * tri[0][k] + u * tri[1][k] + v * tri[2][k])
                    .collect();
                [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]]
            };
            let ray = Ray {
                origin,
                dir,
                tmin: 0.0,
                tmax: f32::INFINITY,
            };
            let Some(prepared) =
                PreparedRay::new(&traverse::Ray::new(Vec3::from(origin), Vec3::from(dir)))
            else {
                continue;
            };
            let cpu = traverse::intersect_triangle(&prepared, &tri.map(Vec3::from), f32::INFINITY);
            let (t, _, uv) = intersect_triangle(&ray, tri);
            match cpu {
                Some((ct, cu, cv)) => {
                    hits += 1;
                    assert_eq!((t, uv), (ct, [cu, cv]), "{ray:?} {tri:?}");
                }
                None => {
                    misses += 1;
                    assert_eq!(t, f32::INFINITY, "{ray:?} {tri:?}");
                }
            }
            // The slab test: rtc-bvh's entry distance (conservative exit) agrees on hits.
            let (lo, hi) = (v3(&mut r, -5.0, 0.0), v3(&mut r, 0.0, 5.0));
            let [entry, exit] = intersect_aabb(&ray, lo, hi);
            let cpu = traverse::intersect_aabb(
                &prepared,
                Vec3A::from(lo),
                Vec3A::from(hi),
                f32::INFINITY,
            );
            if entry <= exit {
                assert_eq!(cpu, Some(entry), "{ray:?} {lo:?} {hi:?}");
            }
        }
        assert!(hits > 5000 && misses > 5000, "{hits} hits, {misses} misses");
    }
}
