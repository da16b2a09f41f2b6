//! Vector and matrix built-ins and the transforms.

use super::super::gen::{any_f32, f32_in, whole, Rng};
use super::super::{refs, ulp_of, Args, Spec, Tol};
use super::*;

/// `dot cross length distance normalize reflect refract face_forward`.
pub fn vector_builtins() -> Vec<Spec> {
    let mut specs = Vec::new();
    for w in [2usize, 3, 4] {
        let t = ty("f32", w);
        specs.push(
            Spec::new(
                &format!("dot_{t}"),
                src(
                    &format!("dot_{t}"),
                    &[t.clone(), t.clone()],
                    "f32",
                    "dot(a0, a1)",
                ),
                N,
                vec![f32_in(w, -100.0, 100.0), f32_in(w, -100.0, 100.0)],
                Tol::bound(),
                |a: &Args| fv64([dot64(&fs(a, 0), &fs(a, 1))]),
            )
            .with_bound(move |a: &Args| {
                let mag: f64 = fs(a, 0)
                    .iter()
                    .zip(fs(a, 1))
                    .map(|(x, y)| f64::from((x * y).abs()))
                    .sum();
                vec![w as f64 * ulp_of(mag)]
            }),
        );
        specs.push(Spec::new(
            &format!("length_{t}"),
            src(
                &format!("length_{t}"),
                std::slice::from_ref(&t),
                "f32",
                "length(a0)",
            ),
            N,
            vec![f32_in(w, -1e6, 1e6)],
            Tol::ulp(3),
            |a: &Args| fv64([dot64(&fs(a, 0), &fs(a, 0)).sqrt()]),
        ));
        specs.push(Spec::new(
            &format!("distance_{t}"),
            src(
                &format!("distance_{t}"),
                &[t.clone(), t.clone()],
                "f32",
                "distance(a0, a1)",
            ),
            N,
            vec![f32_in(w, -100.0, 100.0), f32_in(w, -100.0, 100.0)],
            Tol::ulp(3).or_abs(1e-5),
            |a: &Args| {
                let d: Vec<f32> = fs(a, 0).iter().zip(fs(a, 1)).map(|(x, y)| x - y).collect();
                fv64([dot64(&d, &d).sqrt()])
            },
        ));
        // Zero vectors (and vectors whose squared length underflows) normalise to zero.
        let norm_param = whole(w, move |r: &mut Rng| match r.below(8) {
            0 => fv(vec![0.0; w]),
            1 => fv((0..w).map(|_| r.range(-1.0, 1.0) * 1e-25)),
            _ => fv((0..w).map(|_| r.wide().clamp(-1e18, 1e18))),
        });
        specs.push(Spec::new(
            &format!("normalize_{t}"),
            src(
                &format!("normalize_{t}"),
                std::slice::from_ref(&t),
                &t,
                "normalize(a0)",
            ),
            N,
            vec![norm_param],
            Tol::abs(1e-6),
            move |a: &Args| {
                let v = fs(a, 0);
                let len2: f32 = v.iter().map(|x| x * x).sum();
                if len2 >= f32::MIN_POSITIVE {
                    let len = dot64(&v, &v).sqrt();
                    fv64(v.iter().map(|x| f64::from(*x) / len))
                } else {
                    fv(vec![0.0; w])
                }
            },
        ));
    }
    specs.push(
        Spec::new(
            "cross_vec3f",
            src(
                "cross_vec3f",
                &["vec3f".into(), "vec3f".into()],
                "vec3f",
                "cross(a0, a1)",
            ),
            N,
            vec![f32_in(3, -100.0, 100.0), f32_in(3, -100.0, 100.0)],
            Tol::bound(),
            |a: &Args| {
                let (p, q) = (fs(a, 0), fs(a, 1));
                let c = |i: usize, j: usize| {
                    f64::from(p[i]) * f64::from(q[j]) - f64::from(p[j]) * f64::from(q[i])
                };
                fv64([c(1, 2), c(2, 0), c(0, 1)])
            },
        )
        .with_bound(|a: &Args| {
            let (p, q) = (fs(a, 0), fs(a, 1));
            let m = |i: usize, j: usize| f64::from((p[i] * q[j]).abs() + (p[j] * q[i]).abs());
            vec![
                2.0 * ulp_of(m(1, 2)),
                2.0 * ulp_of(m(2, 0)),
                2.0 * ulp_of(m(0, 1)),
            ]
        }),
    );
    specs.push(Spec::new(
        "reflect_vec3f",
        src(
            "reflect_vec3f",
            &["vec3f".into(), "vec3f".into()],
            "vec3f",
            "reflect(a0, a1)",
        ),
        N,
        vec![f32_in(3, -1.0, 1.0), unit_param(3)],
        Tol::abs(2e-6),
        |a: &Args| {
            let (i, n) = (fs(a, 0), fs(a, 1));
            let d = dot64(&n, &i);
            fv64((0..3).map(|k| f64::from(i[k]) - 2.0 * d * f64::from(n[k])))
        },
    ));
    // Unit incident and normal, relative indices around 1; total internal reflection gives zero.
    specs.push(Spec::new(
        "refract_vec3f",
        src(
            "refract_vec3f",
            &["vec3f".into(), "vec3f".into(), "f32".into()],
            "vec3f",
            "refract(a0, a1, a2)",
        ),
        N,
        vec![unit_param(3), unit_param(3), f32_in(1, 0.5, 2.0)],
        Tol::abs(2e-5),
        |a: &Args| {
            let (i, n, eta) = (fs(a, 0), fs(a, 1), f64_of(a[2][0]));
            let d = dot64(&n, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            if k < 0.0 {
                fv(vec![0.0; 3])
            } else {
                fv64((0..3).map(|c| eta * f64::from(i[c]) - (eta * d + k.sqrt()) * f64::from(n[c])))
            }
        },
    ));
    specs.push(Spec::new(
        "face_forward_vec3f",
        src(
            "face_forward_vec3f",
            &["vec3f".into(), "vec3f".into(), "vec3f".into()],
            "vec3f",
            "face_forward(a0, a1, a2)",
        ),
        N,
        // Random directions (no edge values): the sign of a dot product that rounds to zero is not
        // specified.
        vec![
            whole(3, |r: &mut Rng| fv((0..3).map(|_| r.range(-10.0, 10.0)))),
            unit_param(3),
            unit_param(3),
        ],
        Tol::EXACT,
        |a: &Args| {
            let (n, i, r) = (fs(a, 0), fs(a, 1), fs(a, 2));
            let s = if dot64(&r, &i) < 0.0 { 1.0 } else { -1.0 };
            fv(n.iter().map(|x| x * s))
        },
    ));
    specs
}

/// `transpose determinant inverse` and the transforms.
pub fn matrix_builtins() -> Vec<Spec> {
    let mut specs = Vec::new();
    for (c, r) in [(2usize, 3usize), (4, 4)] {
        let t = format!("mat{c}x{r}f");
        let tt = format!("mat{r}x{c}f");
        specs.push(Spec::new(
            &format!("transpose_{t}"),
            src(
                &format!("transpose_{t}"),
                std::slice::from_ref(&t),
                &tt,
                "transpose(a0)",
            ),
            N,
            vec![f32_in(c * r, -100.0, 100.0)],
            Tol::EXACT,
            move |a: &Args| {
                let m = fs(a, 0);
                fv((0..r)
                    .flat_map(|i| (0..c).map(move |j| (i, j)))
                    .map(|(i, j)| m[j * r + i]))
            },
        ));
    }
    for n in [2usize, 3, 4] {
        let t = format!("mat{n}x{n}f");
        specs.push(
            Spec::new(
                &format!("determinant_{t}"),
                src(
                    &format!("determinant_{t}"),
                    std::slice::from_ref(&t),
                    "f32",
                    "determinant(a0)",
                ),
                N,
                vec![f32_in(n * n, -2.0, 2.0)],
                Tol::bound(),
                move |a: &Args| fv64([refs::det(&refs::mat(n, n, &fs(a, 0)))]),
            )
            .with_bound(move |a: &Args| {
                // Rounding of the expansion: a few ULPs of the largest term's magnitude.
                let m = fs(a, 0);
                let big = m.iter().fold(0f32, |acc, v| acc.max(v.abs()));
                vec![
                    8.0 * ulp_of(f64::from(big).powi(n as i32) * (1..=n).product::<usize>() as f64),
                ]
            }),
        );
        // Inverses of well-conditioned matrices, and of singular ones (all zeros).
        let inv_param = whole(n * n, move |r: &mut Rng| {
            let singular = r.below(5) == 0;
            fv(matrix(r, n, n, singular))
        });
        specs.push(
            Spec::new(
                &format!("inverse_{t}"),
                src(
                    &format!("inverse_{t}"),
                    std::slice::from_ref(&t),
                    &t,
                    "inverse(a0)",
                ),
                N,
                vec![inv_param],
                Tol::bound(),
                move |a: &Args| {
                    let m = refs::mat(n, n, &fs(a, 0));
                    match refs::inverse(&m) {
                        Some(inv) if refs::det(&m).abs() > 1e-9 => fv(refs::flat(&inv)),
                        _ => fv(vec![0.0; n * n]),
                    }
                },
            )
            .with_bound(move |a: &Args| {
                let m = refs::mat(n, n, &fs(a, 0));
                let big = refs::inverse(&m).map_or(0.0, |inv| {
                    inv.iter().flatten().fold(0f64, |acc, v| acc.max(v.abs()))
                });
                vec![1e-6 * big.max(1e-30); n * n]
            }),
        );
    }
    // Transforms: column-major, right-handed, degrees.
    let m4 = |m: refs::M| fv(refs::flat(&m));
    specs.push(Spec::new(
        "identity_m",
        "fn identity_m(k: f32) -> mat4x4f { return identity(); }\n".into(),
        N,
        vec![any_f32(1)],
        Tol::EXACT,
        move |_: &Args| m4(refs::identity4()),
    ));
    specs.push(Spec::new(
        "translate_m",
        src("translate_m", &["vec3f".into()], "mat4x4f", "translate(a0)"),
        N,
        vec![any_f32(3)],
        Tol::EXACT,
        move |a: &Args| {
            let v = fs(a, 0);
            let mut m = refs::identity4();
            m[3] = vec![f64::from(v[0]), f64::from(v[1]), f64::from(v[2]), 1.0];
            m4(m)
        },
    ));
    for (name, arg) in [("scale_s", "f32"), ("scale_v", "vec3f")] {
        specs.push(Spec::new(
            name,
            src(name, &[arg.into()], "mat4x4f", "scale(a0)"),
            N,
            vec![any_f32(if arg == "f32" { 1 } else { 3 })],
            Tol::EXACT,
            move |a: &Args| {
                let v = fs(a, 0);
                let mut m = refs::identity4();
                for k in 0..3 {
                    m[k][k] = f64::from(v[k.min(v.len() - 1)]);
                }
                m4(m)
            },
        ));
    }
    for (name, axis) in [
        ("rotate_x", [1.0, 0.0, 0.0]),
        ("rotate_y", [0.0, 1.0, 0.0]),
        ("rotate_z", [0.0, 0.0, 1.0]),
    ] {
        specs.push(Spec::new(
            &format!("{name}_m"),
            src(
                &format!("{name}_m"),
                &["f32".into()],
                "mat4x4f",
                &format!("{name}(a0)"),
            ),
            N,
            vec![f32_in(1, -720.0, 720.0)],
            Tol::abs(2e-6),
            move |a: &Args| m4(refs::rotate(axis, f64_of(a[0][0]))),
        ));
    }
    let axis = whole(3, |r: &mut Rng| {
        if r.below(10) == 0 {
            fv(vec![0.0; 3])
        } else {
            fv((0..3).map(|_| r.range(-5.0, 5.0)))
        }
    });
    specs.push(Spec::new(
        "rotate_m",
        src(
            "rotate_m",
            &["vec3f".into(), "f32".into()],
            "mat4x4f",
            "rotate(a0, a1)",
        ),
        N,
        vec![axis, f32_in(1, -360.0, 360.0)],
        Tol::abs(3e-6),
        move |a: &Args| {
            let v = fs(a, 0);
            m4(refs::rotate(
                [f64::from(v[0]), f64::from(v[1]), f64::from(v[2])],
                f64_of(a[1][0]),
            ))
        },
    ));
    for (name, w) in [("transform_point", 1.0), ("transform_dir", 0.0)] {
        specs.push(Spec::new(
            &format!("{name}_m"),
            src(
                &format!("{name}_m"),
                &["mat4x4f".into(), "vec3f".into()],
                "vec3f",
                &format!("{name}(a0, a1)"),
            ),
            N,
            vec![f32_in(16, -10.0, 10.0), f32_in(3, -100.0, 100.0)],
            Tol::abs(2e-4).or_rel(1e-6),
            move |a: &Args| {
                let m = refs::mat(4, 4, &fs(a, 0));
                let p: Vec<f64> = fs(a, 1).iter().map(|x| f64::from(*x)).chain([w]).collect();
                fv64(refs::mul_vec(&m, &p).into_iter().take(3))
            },
        ));
    }
    specs.push(Spec::new(
        "orthonormal_basis_m",
        src(
            "orthonormal_basis_m",
            &["vec3f".into()],
            "mat3x3f",
            "orthonormal_basis(a0)",
        ),
        N,
        vec![whole(3, |r: &mut Rng| {
            // Include the poles, where the construction switches sign.
            match r.below(6) {
                0 => fv([0.0, 0.0, 1.0]),
                1 => fv([0.0, 0.0, -1.0]),
                2 => fv([0.0, 0.0, -0.0]),
                _ => fv(unit(r, 3)),
            }
        })],
        Tol::abs(1e-6),
        |a: &Args| {
            let n = fs(a, 0);
            let b = refs::orthonormal_basis([n[0], n[1], n[2]]);
            fv(b.iter().flatten().copied())
        },
    ));
    specs
}
