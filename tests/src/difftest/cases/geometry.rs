//! The geometry helpers: ray–triangle and ray–box tests, sampling, luminance.

use super::super::gen::{f32_in, whole, Param, Rng};
use super::super::{refs, Args, Sc, Spec, Tol};
use super::*;

/// `intersect_triangle intersect_aabb sample_cosine_hemisphere sample_uniform_sphere luminance`.
pub fn geometry_builtins() -> Vec<Spec> {
    let mut specs = Vec::new();
    // Rays aimed at points inside the triangle (hits), random rays (mostly misses), rays with zero
    // direction components, and limited [tmin, tmax].
    let ray_tri = whole(11 + 9, |r: &mut Rng| {
        let tri = [v3(r, -5.0, 5.0), v3(r, -5.0, 5.0), v3(r, -5.0, 5.0)];
        let origin = v3(r, -10.0, 10.0);
        let dir = match r.below(3) {
            0 => v3(r, -1.0, 1.0),
            1 => dir_with_zeros(r),
            _ => {
                let (u, v) = (r.range(0.02, 0.96), r.range(0.02, 0.96));
                let (u, v) = if u + v > 0.98 {
                    (0.98 - v, 0.98 - u)
                } else {
                    (u, v)
                };
                let p: Vec<f32> = (0..3)
                    .map(|k| (1.0 - u - v) * tri[0][k] + u * tri[1][k] + v * tri[2][k])
                    .collect();
                let s = r.range(0.1, 3.0);
                [
                    (p[0] - origin[0]) * s,
                    (p[1] - origin[1]) * s,
                    (p[2] - origin[2]) * s,
                ]
            }
        };
        let (tmin, tmax) = match r.below(4) {
            0 => (r.range(0.0, 1.0), r.range(1.0, 10.0)),
            _ => (0.0, f32::INFINITY),
        };
        let mut v = ray_comps(origin, dir, tmin, tmax);
        v.extend(fv(tri.into_iter().flatten()));
        v
    });
    specs.push(
        Spec::new(
            "intersect_triangle_t",
            "fn intersect_triangle_t(ray: Ray, tri: Triangle) -> Intersection {
                return intersect_triangle(ray, tri);
            }\n"
            .into(),
            N,
            vec![
                // The whole draw is split over the two parameters.
                Param {
                    width: 11,
                    edges: Vec::new(),
                    draw: Box::new(|_| Sc::F(0.0)),
                },
                Param {
                    width: 9,
                    edges: Vec::new(),
                    draw: Box::new(|_| Sc::F(0.0)),
                },
            ],
            Tol::bound(),
            |a: &Args| {
                let t = fs(a, 1);
                let tri = [[t[0], t[1], t[2]], [t[3], t[4], t[5]], [t[6], t[7], t[8]]];
                let (t, n, uv) = refs::intersect_triangle(&ray_of(a, 0), tri);
                let mut v = vec![Sc::F(t)];
                v.extend(fv(n));
                v.extend(fv(uv));
                v
            },
        )
        .with_inputs_from(ray_tri, &[11, 9])
        .with_bound(|a: &Args| {
            let t = fs(a, 1);
            let tri = [[t[0], t[1], t[2]], [t[3], t[4], t[5]], [t[6], t[7], t[8]]];
            let (t, _, _) = refs::intersect_triangle(&ray_of(a, 0), tri);
            vec![
                1e-5 * f64::from(t.abs()).max(1.0),
                1e-6,
                1e-6,
                1e-6,
                1e-5,
                1e-5,
            ]
        }),
    );
    let ray_box = whole(11 + 6, |r: &mut Rng| {
        let lo = v3(r, -5.0, 5.0);
        let hi = [
            lo[0] + r.range(0.0, 4.0),
            lo[1] + r.range(0.0, 4.0),
            lo[2] + r.range(0.0, 4.0),
        ];
        let origin = match r.below(3) {
            0 => [
                (lo[0] + hi[0]) * 0.5,
                (lo[1] + hi[1]) * 0.5,
                (lo[2] + hi[2]) * 0.5,
            ],
            _ => v3(r, -10.0, 10.0),
        };
        let dir = dir_with_zeros(r);
        let (tmin, tmax) = match r.below(3) {
            0 => (r.range(0.0, 2.0), r.range(2.0, 20.0)),
            _ => (0.0, f32::INFINITY),
        };
        let mut v = ray_comps(origin, dir, tmin, tmax);
        v.extend(fv(lo));
        v.extend(fv(hi));
        v
    });
    specs.push(
        Spec::new(
            "intersect_aabb_t",
            src(
                "intersect_aabb_t",
                &["Ray".into(), "vec3f".into(), "vec3f".into()],
                "vec2f",
                "intersect_aabb(a0, a1, a2)",
            ),
            N,
            vec![
                Param {
                    width: 11,
                    edges: Vec::new(),
                    draw: Box::new(|_| Sc::F(0.0)),
                },
                Param {
                    width: 3,
                    edges: Vec::new(),
                    draw: Box::new(|_| Sc::F(0.0)),
                },
                Param {
                    width: 3,
                    edges: Vec::new(),
                    draw: Box::new(|_| Sc::F(0.0)),
                },
            ],
            Tol::ulp(4).or_abs(1e-6),
            |a: &Args| {
                let (lo, hi) = (fs(a, 1), fs(a, 2));
                fv(refs::intersect_aabb(
                    &ray_of(a, 0),
                    [lo[0], lo[1], lo[2]],
                    [hi[0], hi[1], hi[2]],
                ))
            },
        )
        .with_inputs_from(ray_box, &[11, 3, 3]),
    );
    let uv = || whole(2, |r: &mut Rng| fv([r.unit(), r.unit()]));
    specs.push(Spec::new(
        "sample_uniform_sphere_t",
        src(
            "sample_uniform_sphere_t",
            &["vec2f".into()],
            "vec3f",
            "sample_uniform_sphere(a0)",
        ),
        N,
        vec![uv()],
        Tol::abs(2e-6),
        |a: &Args| {
            let u = fs(a, 0);
            fv64(refs::sample_uniform_sphere([
                f64::from(u[0]),
                f64::from(u[1]),
            ]))
        },
    ));
    specs.push(Spec::new(
        "sample_cosine_hemisphere_t",
        src(
            "sample_cosine_hemisphere_t",
            &["vec3f".into(), "vec2f".into()],
            "vec3f",
            "sample_cosine_hemisphere(a0, a1)",
        ),
        N,
        vec![unit_param(3), uv()],
        Tol::abs(4e-6),
        |a: &Args| {
            let (n, u) = (fs(a, 0), fs(a, 1));
            fv64(refs::sample_cosine_hemisphere(
                [n[0], n[1], n[2]],
                [f64::from(u[0]), f64::from(u[1])],
            ))
        },
    ));
    specs.push(Spec::new(
        "luminance_t",
        src("luminance_t", &["vec3f".into()], "f32", "luminance(a0)"),
        N,
        vec![f32_in(3, 0.0, 100.0)],
        Tol::ulp(4).or_abs(1e-7),
        |a: &Args| {
            let c = fs(a, 0);
            fv64([0.2126 * f64::from(c[0]) + 0.7152 * f64::from(c[1]) + 0.0722 * f64::from(c[2])])
        },
    ));
    specs
}
