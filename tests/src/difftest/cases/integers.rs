//! Integer built-ins, float classification and `select`/`any`/`all`, bit packing.

use super::super::gen::{any_bool, any_f32, any_i32, any_u32, f32_in, Param};
use super::super::{refs, Args, Sc, Spec, Tol};
use super::*;

/// The integer built-ins on `i32`, `u32`, `vec3i` and `vec3u`.
pub fn integer_builtins() -> Vec<Spec> {
    let mut specs = Vec::new();
    for kind in ["i32", "u32"] {
        for width in [1usize, 3] {
            let t = ty(kind, width);
            let signed = kind == "i32";
            let p = |n: usize| -> Vec<(String, Param<'static>)> {
                (0..n).map(|_| (t.clone(), any_int(kind, width))).collect()
            };
            let int = move |v: i64| {
                if signed {
                    Sc::I(v as i32)
                } else {
                    Sc::U(v as u32)
                }
            };
            let val = move |s: Sc| {
                if signed {
                    i64::from(s.i())
                } else {
                    i64::from(s.u())
                }
            };
            let exact = Tol::EXACT;
            specs.push(cw(
                &format!("abs_{t}"),
                "abs(a0)",
                p(1),
                &t,
                width,
                exact,
                move |x| int(val(x[0]).abs()),
            ));
            if signed {
                specs.push(cw(
                    &format!("sign_{t}"),
                    "sign(a0)",
                    p(1),
                    &t,
                    width,
                    exact,
                    |x| Sc::I(x[0].i().signum()),
                ));
            }
            specs.push(cw(
                &format!("min_{t}"),
                "min(a0, a1)",
                p(2),
                &t,
                width,
                exact,
                move |x| int(val(x[0]).min(val(x[1]))),
            ));
            specs.push(cw(
                &format!("max_{t}"),
                "max(a0, a1)",
                p(2),
                &t,
                width,
                exact,
                move |x| int(val(x[0]).max(val(x[1]))),
            ));
            specs.push(cw(
                &format!("clamp_{t}"),
                "clamp(a0, a1, a2)",
                p(3),
                &t,
                width,
                exact,
                move |x| int(val(x[0]).max(val(x[1])).min(val(x[2]))),
            ));
            specs.push(cw(
                &format!("count_ones_{t}"),
                "count_ones(a0)",
                p(1),
                &t,
                width,
                exact,
                move |x| int(i64::from(x[0].u().count_ones())),
            ));
            specs.push(cw(
                &format!("reverse_bits_{t}"),
                "reverse_bits(a0)",
                p(1),
                &t,
                width,
                exact,
                move |x| int(i64::from(x[0].u().reverse_bits())),
            ));
            specs.push(cw(
                &format!("first_leading_bit_{t}"),
                "first_leading_bit(a0)",
                p(1),
                &t,
                width,
                exact,
                move |x| {
                    if signed {
                        Sc::I(refs::first_leading_bit_i32(x[0].i()))
                    } else {
                        Sc::U(refs::first_leading_bit_u32(x[0].u()))
                    }
                },
            ));
            specs.push(cw(
                &format!("first_trailing_bit_{t}"),
                "first_trailing_bit(a0)",
                p(1),
                &t,
                width,
                exact,
                move |x| int(i64::from(refs::first_trailing_bit_u32(x[0].u()) as i32)),
            ));
        }
        // Integer dot products wrap.
        let t = ty(kind, 3);
        let signed = kind == "i32";
        specs.push(Spec::new(
            &format!("dot_{t}"),
            src(
                &format!("dot_{t}"),
                &[t.clone(), t.clone()],
                kind,
                "dot(a0, a1)",
            ),
            N,
            vec![any_int(kind, 3), any_int(kind, 3)],
            Tol::EXACT,
            move |a: &Args| {
                let s = (0..3).fold(0u32, |acc, c| {
                    acc.wrapping_add(a[0][c].u().wrapping_mul(a[1][c].u()))
                });
                vec![if signed { Sc::I(s as i32) } else { Sc::U(s) }]
            },
        ));
    }
    specs
}

/// `is_nan`, `is_inf`, `is_finite` (bit tests, so exact on NaNs and infinities whatever the
/// compiler's float mode), `select`, `any`, `all`.
pub fn classification_and_select() -> Vec<Spec> {
    let mut specs = Vec::new();
    for width in [1usize, 4] {
        let t = ty("f32", width);
        let b = ty("bool", width);
        for (name, f) in [
            ("is_nan", f32::is_nan as fn(f32) -> bool),
            ("is_inf", f32::is_infinite),
            ("is_finite", f32::is_finite),
        ] {
            specs.push(cw(
                &format!("{name}_{t}"),
                &format!("{name}(a0)"),
                vec![(t.clone(), any_f32(width))],
                &b,
                width,
                Tol::EXACT,
                move |x| Sc::B(f(x[0].f())),
            ));
        }
    }
    specs.push(cw(
        "select_f32",
        "select(a0, a1, a2)",
        vec![
            ("f32".into(), any_f32(1)),
            ("f32".into(), any_f32(1)),
            ("bool".into(), any_bool(1)),
        ],
        "f32",
        1,
        Tol::EXACT,
        |x| if x[2].b() { x[1] } else { x[0] },
    ));
    specs.push(cw(
        "select_vec3i",
        "select(a0, a1, a2)",
        vec![
            ("vec3i".into(), any_i32(3)),
            ("vec3i".into(), any_i32(3)),
            ("vec3b".into(), any_bool(3)),
        ],
        "vec3i",
        3,
        Tol::EXACT,
        |x| if x[2].b() { x[1] } else { x[0] },
    ));
    specs.push(cw(
        "select_vec4f_scalar",
        "select(a0, a1, a2)",
        vec![
            ("vec4f".into(), any_f32(4)),
            ("vec4f".into(), any_f32(4)),
            ("bool".into(), any_bool(1)),
        ],
        "vec4f",
        4,
        Tol::EXACT,
        |x| if x[2].b() { x[1] } else { x[0] },
    ));
    for (name, all) in [("any", false), ("all", true)] {
        specs.push(Spec::new(
            &format!("{name}_vec3b"),
            src(
                &format!("{name}_vec3b"),
                &["vec3b".into()],
                "bool",
                &format!("{name}(a0)"),
            ),
            N,
            vec![any_bool(3)],
            Tol::EXACT,
            move |a: &Args| {
                let bits = a[0].iter().map(|s| s.b());
                vec![Sc::B(if all {
                    bits.clone().all(|b| b)
                } else {
                    bits.clone().any(|b| b)
                })]
            },
        ));
    }
    specs
}

/// `pack_*`/`unpack_*`: unorm 4×8, snorm 2×16 and binary16 2×16, `x` in the low bits.
pub fn bit_packing() -> Vec<Spec> {
    let mut specs = Vec::new();
    // Packed fields are compared after unpacking them in the DSL, within 1: the rounding of
    // `v * 255` and `v * 32767` at ties may differ from WGSL's `floor(0.5 + …)`.
    specs.push(Spec::new(
        "pack_unorm",
        "fn pack_unorm(v: vec4f) -> vec4f {
            let p = pack_unorm4x8(v);
            return vec4f(f32(p & 255u), f32((p >> 8u) & 255u), f32((p >> 16u) & 255u), f32(p >> 24u));
        }\n"
        .into(),
        N,
        vec![f32_in(4, -0.5, 1.5)],
        Tol::abs(1.0),
        |a: &Args| fv(fs(a, 0).iter().map(|v| (0.5 + 255.0 * v.clamp(0.0, 1.0)).floor())),
    ));
    specs.push(Spec::new(
        "unpack_unorm",
        src(
            "unpack_unorm",
            &["u32".into()],
            "vec4f",
            "unpack_unorm4x8(a0)",
        ),
        N,
        vec![any_u32(1)],
        Tol::ulp(1),
        |a: &Args| fv((0..4).map(|i| ((a[0][0].u() >> (8 * i)) & 0xff) as f32 / 255.0)),
    ));
    specs.push(Spec::new(
        "pack_snorm",
        "fn pack_snorm(v: vec2f) -> vec2f {
            let p = pack_snorm2x16(v);
            return vec2f(f32(bitcast<i32>(p << 16u) >> 16u), f32(bitcast<i32>(p) >> 16u));
        }\n"
        .into(),
        N,
        vec![f32_in(2, -1.5, 1.5)],
        Tol::abs(1.0),
        |a: &Args| {
            fv(fs(a, 0)
                .iter()
                .map(|v| (0.5 + 32767.0 * v.clamp(-1.0, 1.0)).floor()))
        },
    ));
    specs.push(Spec::new(
        "unpack_snorm",
        src(
            "unpack_snorm",
            &["u32".into()],
            "vec2f",
            "unpack_snorm2x16(a0)",
        ),
        N,
        vec![any_u32(1)],
        Tol::ulp(1),
        |a: &Args| {
            let w = a[0][0].u();
            fv([w as u16, (w >> 16) as u16].map(|h| (f32::from(h as i16) / 32767.0).max(-1.0)))
        },
    ));
    specs.push(Spec::new(
        "pack_half",
        src("pack_half", &["vec2f".into()], "u32", "pack_half2x16(a0)"),
        N,
        vec![filtered(any_f32(2), |v| v.is_finite() && v.abs() < 65504.0)],
        Tol::EXACT,
        |a: &Args| {
            let v = fs(a, 0);
            vec![Sc::U(
                u32::from(refs::f32_to_f16(v[0])) | (u32::from(refs::f32_to_f16(v[1])) << 16),
            )]
        },
    ));
    specs.push(Spec::new(
        "unpack_half",
        src(
            "unpack_half",
            &["u32".into()],
            "vec2f",
            "unpack_half2x16(a0)",
        ),
        N,
        vec![any_u32(1)],
        Tol::EXACT,
        |a: &Args| {
            let w = a[0][0].u();
            fv([
                refs::f16_to_f32(w as u16),
                refs::f16_to_f32((w >> 16) as u16),
            ])
        },
    ));
    specs
}
