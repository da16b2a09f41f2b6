//! The ray-geometry built-ins as polyfill helpers: `intersect_triangle` and `intersect_aabb`.
//!
//! Both follow the CPU reference of `rtc-bvh` (`runtime/bvh/src/traverse.rs`) so the GPU and the CPU
//! agree on what is hit:
//! - direction components smaller than `f32::MIN_POSITIVE` in magnitude count as zero (what a GPU that
//!   flushes denormals sees anyway);
//! - a ray with a non-finite origin or direction, or a zero direction, hits nothing;
//! - no NaN reaches a decision: axes parallel to a slab are decided by comparing the origin with the slab.
//!
//! `intersect_triangle` is the watertight test of Woop, Benthin and Wald (JCGT 2(1), 2013), both faces,
//! degenerate triangles never hit, `t` in `[ray.tmin, ray.tmax]`. It returns the prelude's
//! `Intersection`: on a hit `t`, the unit geometric normal `normalize(cross(v1 - v0, v2 - v0))` (the
//! winding's side, not flipped toward the ray) and `uv` = the barycentric weights of `v1` and `v2`; on a
//! miss the struct's defaults (`t = INF`, normal `(0, 0, 1)`, `uv = 0`). The reference recomputes edge
//! functions that are exactly zero in double precision; WGSL and MSL have no `f64`, so the GPU decides
//! those (measure-zero) cases in `f32`.
//!
//! `intersect_aabb` is the exact slab test: `vec2(entry, exit)` with `entry = max(near, ray.tmin)`,
//! `exit = min(far, ray.tmax)`; a miss has `entry > exit`. (The BVH traversal's conservative scaling of
//! the exit distance is the kernel's business, not this built-in's.)

use super::polyfill::{framework_field, framework_types, ray_type, Pf, Polyfill};
use super::{LowerError, Lowerer};
use crate::sema::types::ScalarKind;
use naga::{BinaryOperator as Bo, Function, Literal, MathFunction as Mf};

type H = naga::Handle<naga::Expression>;

/// The fields of `Ray` the helpers read, as member indices.
struct RayFields {
    origin: u32,
    dir: u32,
    tmin: u32,
    tmax: u32,
}

fn ray_fields(lw: &Lowerer<'_>) -> Result<RayFields, LowerError> {
    let ray = lw.program().framework.ray;
    Ok(RayFields {
        origin: framework_field(lw, ray, "origin")?,
        dir: framework_field(lw, ray, "dir")?,
        tmin: framework_field(lw, ray, "tmin")?,
        tmax: framework_field(lw, ray, "tmax")?,
    })
}

pub(super) fn intersect_aabb(lw: &mut Lowerer<'_>) -> Result<Function, LowerError> {
    let ray_t = ray_type(lw)?;
    let rf = ray_fields(lw)?;
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let v2 = lw.sv_type(2, ScalarKind::F32);
    let mut f = Pf::new(
        lw,
        "intersect_aabb",
        &[("ray", ray_t), ("min", v3), ("max", v3)],
        v2,
    );
    let (ray, lo, hi) = (f.arg(0), f.arg(1), f.arg(2));
    let o = f.at(ray, rf.origin);
    let d = f.at(ray, rf.dir);
    let tmin = f.at(ray, rf.tmin);
    let tmax = f.at(ray, rf.tmax);
    let ad = f.m(Mf::Abs, &[d]);
    let tiny_limit = f.splat_lit(3, Literal::F32(f32::MIN_POSITIVE));
    let parallel = f.bin(Bo::Less, ad, tiny_limit);
    let parallel = f.name(parallel, "parallel");
    let ones = f.splat_lit(3, Literal::F32(1.0));
    let safe_d = f.sel(parallel, ones, d);
    let inv = f.div(ones, safe_d);
    let inv = f.name(inv, "inv_dir");
    let lo_o = f.sub(lo, o);
    let hi_o = f.sub(hi, o);
    let t0 = f.mul(lo_o, inv);
    let t1 = f.mul(hi_o, inv);
    let near = f.m(Mf::Min, &[t0, t1]);
    let far = f.m(Mf::Max, &[t0, t1]);
    // Parallel axes: no constraint when the origin is inside the slab (boundary included), else a miss.
    let in_lo = f.bin(Bo::LessEqual, lo, o);
    let in_hi = f.bin(Bo::LessEqual, o, hi);
    let inside = f.bin(Bo::And, in_lo, in_hi);
    let inf = f.splat_lit(3, Literal::F32(f32::INFINITY));
    let ninf = f.splat_lit(3, Literal::F32(f32::NEG_INFINITY));
    let near_par = f.sel(inside, ninf, inf);
    let far_par = f.sel(inside, inf, ninf);
    let near = f.sel(parallel, near_par, near);
    let near = f.name(near, "near");
    let far = f.sel(parallel, far_par, far);
    let far = f.name(far, "far");
    let (nx, ny, nz) = (f.at(near, 0), f.at(near, 1), f.at(near, 2));
    let (fx, fy, fz) = (f.at(far, 0), f.at(far, 1), f.at(far, 2));
    let e = f.m(Mf::Max, &[nx, ny]);
    let e = f.m(Mf::Max, &[e, nz]);
    let entry = f.m(Mf::Max, &[e, tmin]);
    let x = f.m(Mf::Min, &[fx, fy]);
    let x = f.m(Mf::Min, &[x, fz]);
    let exit = f.m(Mf::Min, &[x, tmax]);
    let r = f.compose(v2, vec![entry, exit]);
    Ok(f.ret(r))
}

pub(super) fn intersect_triangle(lw: &mut Lowerer<'_>) -> Result<Function, LowerError> {
    let types = framework_types(lw)?;
    let (ray_t, tri_t, isect_t) = (types.ray, types.triangle, types.intersection);
    let rf = ray_fields(lw)?;
    let fw = lw.program().framework;
    let [v0i, v1i, v2i] = [
        framework_field(lw, fw.triangle, "v0")?,
        framework_field(lw, fw.triangle, "v1")?,
        framework_field(lw, fw.triangle, "v2")?,
    ];
    let isect = &lw.program().structs;
    let isect_fields: Vec<String> = fw
        .intersection
        .map(|s| isect[s].fields.iter().map(|f| f.name.clone()).collect())
        .unwrap_or_default();
    let v3 = lw.sv_type(3, ScalarKind::F32);
    let v2 = lw.sv_type(2, ScalarKind::F32);
    let mut f = Pf::new(
        lw,
        "intersect_triangle",
        &[("ray", ray_t), ("tri", tri_t)],
        isect_t,
    );
    let (ray, tri) = (f.arg(0), f.arg(1));
    let o = f.at(ray, rf.origin);
    let d0 = f.at(ray, rf.dir);
    let tmin = f.at(ray, rf.tmin);
    let tmax = f.at(ray, rf.tmax);
    let p0 = f.at(tri, v0i);
    let p1 = f.at(tri, v1i);
    let p2 = f.at(tri, v2i);

    let valid = finite_ray(&mut f, o, d0);

    let Axes { d, kx, ky, kz, dz } = dominant_axes(&mut f, d0);
    let zero = f.f(0.0);

    // Shear constants.
    let dx = f.fb.access(d, kx, naga::Span::UNDEFINED);
    let dy = f.fb.access(d, ky, naga::Span::UNDEFINED);
    let sx = f.div(dx, dz);
    let sy = f.div(dy, dz);
    let one = f.f(1.0);
    let sz = f.div(one, dz);
    let (sx, sy, sz) = (f.name(sx, "sx"), f.name(sy, "sy"), f.name(sz, "sz"));

    // Vertices relative to the origin, sheared so that the ray runs along +z.
    let mut sheared = Vec::with_capacity(3);
    for p in [p0, p1, p2] {
        let rel = f.sub(p, o);
        let px = f.fb.access(rel, kx, naga::Span::UNDEFINED);
        let py = f.fb.access(rel, ky, naga::Span::UNDEFINED);
        let pz = f.fb.access(rel, kz, naga::Span::UNDEFINED);
        let sxz = f.mul(sx, pz);
        let syz = f.mul(sy, pz);
        let x = f.sub(px, sxz);
        let y = f.sub(py, syz);
        let z = f.mul(sz, pz);
        sheared.push((x, y, z));
    }
    let [(ax, ay, az), (bx, by, bz), (cx, cy, cz)] = [sheared[0], sheared[1], sheared[2]];
    // Scaled barycentrics: the edge functions at the origin.
    let mut edge = |p: naga::Handle<naga::Expression>, q, r, s, name: &str| {
        let pq = f.mul(p, q);
        let rs = f.mul(r, s);
        let e = f.sub(pq, rs);
        f.name(e, name)
    };
    let u = edge(cx, by, cy, bx, "u");
    let v = edge(ax, cy, ay, cx, "v");
    let w = edge(bx, ay, by, ax, "w");
    let (u_neg, v_neg, w_neg) = (
        f.bin(Bo::Less, u, zero),
        f.bin(Bo::Less, v, zero),
        f.bin(Bo::Less, w, zero),
    );
    let (u_pos, v_pos, w_pos) = (
        f.bin(Bo::Greater, u, zero),
        f.bin(Bo::Greater, v, zero),
        f.bin(Bo::Greater, w, zero),
    );
    let any_neg = f.bin(Bo::LogicalOr, u_neg, v_neg);
    let any_neg = f.bin(Bo::LogicalOr, any_neg, w_neg);
    let any_pos = f.bin(Bo::LogicalOr, u_pos, v_pos);
    let any_pos = f.bin(Bo::LogicalOr, any_pos, w_pos);
    let outside = f.bin(Bo::LogicalAnd, any_neg, any_pos);
    let uv = f.add(u, v);
    let det = f.add(uv, w);
    let det = f.name(det, "det");
    let degenerate = f.bin(Bo::Equal, det, zero);
    let rcp = f.div(one, det);
    let uaz = f.mul(u, az);
    let vbz = f.mul(v, bz);
    let wcz = f.mul(w, cz);
    let s1 = f.add(uaz, vbz);
    let s2 = f.add(s1, wcz);
    let t = f.mul(s2, rcp);
    let t = f.name(t, "t");
    let after_min = f.bin(Bo::GreaterEqual, t, tmin);
    let before_max = f.bin(Bo::LessEqual, t, tmax);
    let in_range = f.bin(Bo::LogicalAnd, after_min, before_max);
    // Also false for a NaN `t` (overflowing coordinates) and a zero direction (dz == 0 gives NaN or
    // infinite shears, whose `t` is NaN or whose edge test fails; `valid` covers the rest).
    let not_outside = f.fb.unary(
        naga::UnaryOperator::LogicalNot,
        outside,
        naga::Span::UNDEFINED,
    );
    let not_degenerate = f.fb.unary(
        naga::UnaryOperator::LogicalNot,
        degenerate,
        naga::Span::UNDEFINED,
    );
    let dz_nonzero = f.bin(Bo::NotEqual, dz, zero);
    let hit = f.bin(Bo::LogicalAnd, valid, dz_nonzero);
    let hit = f.bin(Bo::LogicalAnd, hit, not_outside);
    let hit = f.bin(Bo::LogicalAnd, hit, not_degenerate);
    let hit = f.bin(Bo::LogicalAnd, hit, in_range);
    let hit = f.name(hit, "hit");

    let e1 = f.sub(p1, p0);
    let e2 = f.sub(p2, p0);
    let n = f.m(Mf::Cross, &[e1, e2]);
    let n = f.call(Polyfill::Normalize(3), vec![n])?;
    let bu = f.mul(v, rcp);
    let bv = f.mul(w, rcp);
    let bary = f.compose(v2, vec![bu, bv]);

    let inf = f.f(f32::INFINITY);
    let t_out = f.sel(hit, t, inf);
    let (z0, z1) = (f.f(0.0), f.f(1.0));
    let up = f.compose(v3, vec![z0, z0, z1]);
    let n_out = f.sel(hit, n, up);
    let zero2 = f.splat_lit(2, Literal::F32(0.0));
    let uv_out = f.sel(hit, bary, zero2);
    let mut members = Vec::with_capacity(isect_fields.len());
    for name in &isect_fields {
        members.push(match name.as_str() {
            "t" => t_out,
            "normal" => n_out,
            "uv" => uv_out,
            _ => {
                return Err(LowerError::InvalidHir {
                    what: "the prelude struct `Intersection` has an unexpected field",
                    span: crate::source::Span::default(),
                })
            }
        });
    }
    let r = f.compose(isect_t, members);
    Ok(f.ret(r))
}

/// Whether the ray's origin and direction are finite (bit tests: no NaN comparison involved).
fn finite_ray(f: &mut Pf<'_, '_>, o: H, d: H) -> H {
    let inf_bits = f.splat_lit(3, Literal::U32(0x7f80_0000));
    let ob = f.magnitude_bits(o, 3);
    let db = f.magnitude_bits(d, 3);
    let o_finite = f.bin(Bo::Less, ob, inf_bits);
    let d_finite = f.bin(Bo::Less, db, inf_bits);
    let all = |f: &mut Pf<'_, '_>, argument| {
        f.fb.expr(
            naga::Expression::Relational {
                fun: naga::RelationalFunction::All,
                argument,
            },
            naga::Span::UNDEFINED,
        )
    };
    let o_ok = all(f, o_finite);
    let d_ok = all(f, d_finite);
    f.bin(Bo::LogicalAnd, o_ok, d_ok)
}

/// The direction with tiny components flushed, and the axes of the watertight test.
struct Axes {
    d: H,
    kx: H,
    ky: H,
    kz: H,
    dz: H,
}

/// Flushes tiny direction components; `kz` is the dominant axis (the first largest), `kx` and `ky`
/// the next ones, swapped when `d[kz] < 0` to keep the winding.
fn dominant_axes(f: &mut Pf<'_, '_>, d0: H) -> Axes {
    let ad0 = f.m(Mf::Abs, &[d0]);
    let tiny_limit = f.splat_lit(3, Literal::F32(f32::MIN_POSITIVE));
    let tiny = f.bin(Bo::Less, ad0, tiny_limit);
    let zeros = f.splat_lit(3, Literal::F32(0.0));
    let d = f.sel(tiny, zeros, d0);
    let d = f.name(d, "dir");
    let ad = f.m(Mf::Abs, &[d]);
    let (ax, ay, az) = (f.at(ad, 0), f.at(ad, 1), f.at(ad, 2));
    let (k0, k1, k2) = (f.u(0), f.u(1), f.u(2));
    let y_gt = f.bin(Bo::Greater, ay, ax);
    let kz = f.sel(y_gt, k1, k0);
    let mxy = f.sel(y_gt, ay, ax);
    let z_gt = f.bin(Bo::Greater, az, mxy);
    let kz = f.sel(z_gt, k2, kz);
    let kz = f.name(kz, "kz");
    let kz1 = f.add(kz, k1);
    let kz_is_2 = f.bin(Bo::Equal, kz, k2);
    let kx = f.sel(kz_is_2, k0, kz1);
    let kz2 = f.add(kz, k2);
    let kzm1 = f.sub(kz, k1);
    let kz_ge_1 = f.bin(Bo::GreaterEqual, kz, k1);
    let ky = f.sel(kz_ge_1, kzm1, kz2);
    let dz = f.fb.access(d, kz, naga::Span::UNDEFINED);
    let dz = f.name(dz, "dz");
    let zero = f.f(0.0);
    let flip = f.bin(Bo::Less, dz, zero);
    let kx2 = f.sel(flip, ky, kx);
    let ky2 = f.sel(flip, kx, ky);
    Axes {
        d,
        kx: f.name(kx2, "kx"),
        ky: f.name(ky2, "ky"),
        kz,
        dz,
    }
}
