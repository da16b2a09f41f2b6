//! Operators (integer and float arithmetic, comparisons, matrices) and conversions.

use super::super::gen::{any_bool, any_f32, any_i32, any_u32, f32_in, Param};
use super::super::{refs, ulp_of, Args, Sc, Spec, Tol};
use super::*;

/// A named operator case: function name, DSL expression, reference.
type OpCase<T> = (&'static str, &'static str, fn(T) -> T);
/// A named binary float operator case with its tolerance.
type FloatOpCase = (&'static str, &'static str, Tol, fn(f32, f32) -> f32);

/// A binary operator on two operands of `kind` (`i32`/`u32`, width 1 or 2), by a reference on `i64`
/// bit patterns.
pub fn int_op(
    name: &str,
    kind: &str,
    width: usize,
    expr: &str,
    rhs_kind: &str,
    r: fn(i64, i64, bool) -> i64,
) -> Spec {
    let t = ty(kind, width);
    let rt = ty(rhs_kind, width);
    let signed = kind == "i32";
    let rhs_signed = rhs_kind == "i32";
    cw(
        &format!("{name}_{t}"),
        expr,
        vec![
            (t.clone(), any_int(kind, width)),
            (rt, any_int(rhs_kind, width)),
        ],
        &t,
        width,
        Tol::EXACT,
        move |x| {
            let a = if signed {
                i64::from(x[0].i())
            } else {
                i64::from(x[0].u())
            };
            let b = if rhs_signed {
                i64::from(x[1].i())
            } else {
                i64::from(x[1].u())
            };
            let v = r(a, b, signed);
            if signed {
                Sc::I(v as i32)
            } else {
                Sc::U(v as u32)
            }
        },
    )
}

/// Integer arithmetic: wrapping `+ - *`, division by zero (the left operand) and remainder by zero (0),
/// `i32::MIN / -1`, shifts modulo 32, bit operators, negation, comparisons, compound assignment.
pub fn integer_operators() -> Vec<Spec> {
    let mut specs = Vec::new();
    for kind in ["i32", "u32"] {
        for width in [1usize, 2] {
            specs.push(int_op("add", kind, width, "a0 + a1", kind, |a, b, _| {
                a.wrapping_add(b)
            }));
            specs.push(int_op("sub", kind, width, "a0 - a1", kind, |a, b, _| {
                a.wrapping_sub(b)
            }));
            specs.push(int_op("mul", kind, width, "a0 * a1", kind, |a, b, _| {
                a.wrapping_mul(b)
            }));
            specs.push(int_op("div", kind, width, "a0 / a1", kind, |a, b, s| {
                if s {
                    i64::from(refs::div_i32(a as i32, b as i32))
                } else {
                    i64::from(refs::div_u32(a as u32, b as u32))
                }
            }));
            specs.push(int_op("rem", kind, width, "a0 % a1", kind, |a, b, s| {
                if s {
                    i64::from(refs::rem_i32(a as i32, b as i32))
                } else {
                    i64::from(refs::rem_u32(a as u32, b as u32))
                }
            }));
            specs.push(int_op("shl", kind, width, "a0 << a1", "u32", |a, b, _| {
                i64::from((a as u32).wrapping_shl(b as u32))
            }));
            specs.push(int_op("shr", kind, width, "a0 >> a1", "u32", |a, b, s| {
                if s {
                    i64::from((a as i32).wrapping_shr(b as u32))
                } else {
                    i64::from((a as u32).wrapping_shr(b as u32))
                }
            }));
            specs.push(int_op("and", kind, width, "a0 & a1", kind, |a, b, _| a & b));
            specs.push(int_op("or", kind, width, "a0 | a1", kind, |a, b, _| a | b));
            specs.push(int_op("xor", kind, width, "a0 ^ a1", kind, |a, b, _| a ^ b));
            specs.push(int_op("not", kind, width, "~a0", kind, |a, _, _| !a));
        }
    }
    // Literal divisors take naga's operators directly, except -1 and 0 (and `%` on i32, which stays a
    // helper because GLSL's `%` is undefined for negative operands).
    let lit: [OpCase<i32>; 6] = [
        ("div_lit_i32", "a0 / -7", |x| refs::div_i32(x, -7)),
        ("rem_lit_i32", "a0 % -7", |x| refs::rem_i32(x, -7)),
        ("div_m1_i32", "a0 / -1", |x| refs::div_i32(x, -1)),
        ("rem_m1_i32", "a0 % -1", |x| refs::rem_i32(x, -1)),
        ("div_0_i32", "a0 / 0", |x| refs::div_i32(x, 0)),
        ("rem_0_i32", "a0 % 0", |x| refs::rem_i32(x, 0)),
    ];
    for (name, expr, r) in lit {
        specs.push(cw(
            name,
            expr,
            vec![("i32".into(), any_i32(1))],
            "i32",
            1,
            Tol::EXACT,
            move |x| Sc::I(r(x[0].i())),
        ));
    }
    let lit_u: [OpCase<u32>; 3] = [
        ("div_lit_u32", "a0 / 7u", |x| x / 7),
        ("rem_lit_u32", "a0 % 7u", |x| x % 7),
        ("div_0_u32", "a0 / 0u", |x| refs::div_u32(x, 0)),
    ];
    for (name, expr, r) in lit_u {
        specs.push(cw(
            name,
            expr,
            vec![("u32".into(), any_u32(1))],
            "u32",
            1,
            Tol::EXACT,
            move |x| Sc::U(r(x[0].u())),
        ));
    }
    specs.push(int_op("neg", "i32", 1, "-a0", "i32", |a, _, _| {
        a.wrapping_neg()
    }));
    specs.push(int_op("neg", "i32", 2, "-a0", "i32", |a, _, _| {
        a.wrapping_neg()
    }));
    // Comparisons give bool vectors.
    for (name, op) in [
        ("lt", "<"),
        ("le", "<="),
        ("eq", "=="),
        ("ne", "!="),
        ("gt", ">"),
        ("ge", ">="),
    ] {
        specs.push(cw(
            &format!("cmp_{name}_vec4i"),
            &format!("a0 {op} a1"),
            vec![("vec4i".into(), any_i32(4)), ("vec4i".into(), any_i32(4))],
            "vec4b",
            4,
            Tol::EXACT,
            move |x| {
                let (a, b) = (x[0].i(), x[1].i());
                Sc::B(match name {
                    "lt" => a < b,
                    "le" => a <= b,
                    "eq" => a == b,
                    "ne" => a != b,
                    "gt" => a > b,
                    _ => a >= b,
                })
            },
        ));
    }
    // Compound assignment evaluates the place once and applies the operator.
    specs.push(Spec::new(
        "compound_i32",
        "fn compound_i32(a: i32, b: i32) -> vec4i {
            var v = vec4i(a);
            v.x += b; v.y -= b; v.z *= b; v.w /= b;
            var k = a;
            k %= b; k <<= 3u; k >>= 1u; k ^= b; k |= 1; k &= -3;
            return v + vec4i(k, 0, 0, 0);
        }\n"
        .into(),
        N,
        vec![any_i32(1), any_i32(1)],
        Tol::EXACT,
        |a: &Args| {
            let (x, y) = (a[0][0].i(), a[1][0].i());
            let mut k = refs::rem_i32(x, y);
            k = k.wrapping_shl(3).wrapping_shr(1) ^ y;
            k = (k | 1) & -3;
            vec![
                Sc::I(x.wrapping_add(y).wrapping_add(k)),
                Sc::I(x.wrapping_sub(y)),
                Sc::I(x.wrapping_mul(y)),
                Sc::I(refs::div_i32(x, y)),
            ]
        },
    ));
    specs
}

/// Float arithmetic on every kind of input (NaN, infinities, denormals, signed zeros), comparisons
/// (false with NaN, except `!=`), and `%` (truncated).
pub fn float_operators() -> Vec<Spec> {
    let mut specs = Vec::new();
    let div_tol = Tol::ulp(3);
    let ops: [FloatOpCase; 4] = [
        ("add", "a0 + a1", Tol::EXACT, |a, b| a + b),
        ("sub", "a0 - a1", Tol::EXACT, |a, b| a - b),
        ("mul", "a0 * a1", Tol::EXACT, |a, b| a * b),
        ("div", "a0 / a1", div_tol, |a, b| a / b),
    ];
    for (name, expr, tol, r) in ops {
        for width in [1usize, 4] {
            let t = ty("f32", width);
            specs.push(cw(
                &format!("{name}_{t}"),
                expr,
                vec![(t.clone(), any_f32(width)), (t.clone(), any_f32(width))],
                &t,
                width,
                tol,
                move |x| Sc::F(r(x[0].f(), x[1].f())),
            ));
        }
    }
    specs.push(cw(
        "neg_f32",
        "-a0",
        vec![("f32".into(), any_f32(1))],
        "f32",
        1,
        Tol::EXACT,
        |x| Sc::F(-x[0].f()),
    ));
    // `%` is truncated: `x - y * trunc(x / y)`, evaluated as such on GPUs (the quotient rounded).
    let rem = cw(
        "rem_f32",
        "a0 % a1",
        vec![
            ("f32".into(), f32_in(1, -100.0, 100.0)),
            (
                "f32".into(),
                filtered(f32_in(1, -10.0, 10.0), |v| v.abs() > 1e-3),
            ),
        ],
        "f32",
        1,
        Tol::bound(),
        |x| {
            let (a, b) = (x[0].f(), x[1].f());
            Sc::F(a - b * (a / b).trunc())
        },
    );
    specs.push(cw_bound(rem, 1, |a| 2.0 * ulp_of(f64::from(a[0]))));
    for (name, op) in [
        ("lt", "<"),
        ("le", "<="),
        ("eq", "=="),
        ("ne", "!="),
        ("gt", ">"),
        ("ge", ">="),
    ] {
        specs.push(cw(
            &format!("cmp_{name}_vec4f"),
            &format!("a0 {op} a1"),
            vec![("vec4f".into(), any_f32(4)), ("vec4f".into(), any_f32(4))],
            "vec4b",
            4,
            Tol::EXACT,
            move |x| {
                let (a, b) = (x[0].f(), x[1].f());
                Sc::B(match name {
                    "lt" => a < b,
                    "le" => a <= b,
                    "eq" => a == b,
                    "ne" => a != b,
                    "gt" => a > b,
                    _ => a >= b,
                })
            },
        ));
    }
    // Matrix arithmetic.
    specs.push(Spec::new(
        "mat_ops",
        "fn mat_ops(a: mat3x3f, b: mat3x3f, s: f32) -> mat3x3f { return a * b + a * s - b; }\n"
            .into(),
        N,
        vec![
            f32_in(9, -4.0, 4.0),
            f32_in(9, -4.0, 4.0),
            f32_in(1, -4.0, 4.0),
        ],
        Tol::abs(2e-5),
        |a: &Args| {
            let (m, n) = (refs::mat(3, 3, &fs(a, 0)), refs::mat(3, 3, &fs(a, 1)));
            let s = f64_of(a[2][0]);
            let p = refs::mul(&m, &n);
            fv64((0..9).map(|k| p[k / 3][k % 3] + m[k / 3][k % 3] * s - n[k / 3][k % 3]))
        },
    ));
    specs.push(Spec::new(
        "mat_vec",
        "fn mat_vec(m: mat4x4f, v: vec4f, w: vec3f, n: mat3x3f) -> vec4f {
            let r = w * n;
            return m * v + vec4f(r, -r.x);
        }\n"
        .into(),
        N,
        vec![
            f32_in(16, -4.0, 4.0),
            f32_in(4, -4.0, 4.0),
            f32_in(3, -4.0, 4.0),
            f32_in(9, -4.0, 4.0),
        ],
        Tol::abs(2e-5),
        |a: &Args| {
            let m = refs::mat(4, 4, &fs(a, 0));
            let v: Vec<f64> = fs(a, 1).iter().map(|x| f64::from(*x)).collect();
            let w: Vec<f64> = fs(a, 2).iter().map(|x| f64::from(*x)).collect();
            let n = refs::mat(3, 3, &fs(a, 3));
            // Row vector times matrix: component c is dot(w, column c).
            let r: Vec<f64> = (0..3)
                .map(|c| (0..3).map(|k| w[k] * n[c][k]).sum())
                .collect();
            let mv = refs::mul_vec(&m, &v);
            fv64([mv[0] + r[0], mv[1] + r[1], mv[2] + r[2], mv[3] - r[0]])
        },
    ));
    specs
}

/// Conversions: float to integer saturates (NaN gives 0), integer to float rounds to nearest,
/// `i32`/`u32` reinterpret, `bool(x)` is `x != 0`, bit casts keep every bit.
pub fn conversions() -> Vec<Spec> {
    let mut specs = Vec::new();
    let one = |name: &str, from: &str, to: &str, p: Param<'static>, r: fn(Sc) -> Sc| {
        cw(
            name,
            &format!("{to}(a0)"),
            vec![(from.to_string(), p)],
            to,
            1,
            Tol::EXACT,
            move |x| r(x[0]),
        )
    };
    specs.push(one("i32_of_f32", "f32", "i32", any_f32(1), |x| {
        Sc::I(refs::f32_to_i32(x.f()))
    }));
    specs.push(one("u32_of_f32", "f32", "u32", any_f32(1), |x| {
        Sc::U(refs::f32_to_u32(x.f()))
    }));
    specs.push(one("f32_of_i32", "i32", "f32", any_i32(1), |x| {
        Sc::F(x.i() as f32)
    }));
    specs.push(one("f32_of_u32", "u32", "f32", any_u32(1), |x| {
        Sc::F(x.u() as f32)
    }));
    specs.push(one("u32_of_i32", "i32", "u32", any_i32(1), |x| {
        Sc::U(x.i() as u32)
    }));
    specs.push(one("i32_of_u32", "u32", "i32", any_u32(1), |x| {
        Sc::I(x.u() as i32)
    }));
    specs.push(one("bool_of_f32", "f32", "bool", any_f32(1), |x| {
        Sc::B(x.f() != 0.0)
    }));
    specs.push(one("bool_of_i32", "i32", "bool", any_i32(1), |x| {
        Sc::B(x.i() != 0)
    }));
    specs.push(one("bool_of_u32", "u32", "bool", any_u32(1), |x| {
        Sc::B(x.u() != 0)
    }));
    specs.push(one("f32_of_bool", "bool", "f32", any_bool(1), |x| {
        Sc::F(f32::from(u8::from(x.b())))
    }));
    specs.push(one("i32_of_bool", "bool", "i32", any_bool(1), |x| {
        Sc::I(i32::from(x.b()))
    }));
    specs.push(one("u32_of_bool", "bool", "u32", any_bool(1), |x| {
        Sc::U(u32::from(x.b()))
    }));
    specs.push(cw(
        "vec3i_of_vec3f",
        "vec3i(a0)",
        vec![("vec3f".into(), any_f32(3))],
        "vec3i",
        3,
        Tol::EXACT,
        |x| Sc::I(refs::f32_to_i32(x[0].f())),
    ));
    specs.push(cw(
        "vec2u_of_vec2f",
        "vec2u(a0)",
        vec![("vec2f".into(), any_f32(2))],
        "vec2u",
        2,
        Tol::EXACT,
        |x| Sc::U(refs::f32_to_u32(x[0].f())),
    ));
    specs.push(cw(
        "vec4f_of_vec4u",
        "vec4f(a0)",
        vec![("vec4u".into(), any_u32(4))],
        "vec4f",
        4,
        Tol::EXACT,
        |x| Sc::F(x[0].u() as f32),
    ));
    specs.push(cw(
        "vec3b_of_vec3i",
        "vec3b(a0)",
        vec![("vec3i".into(), any_i32(3))],
        "vec3b",
        3,
        Tol::EXACT,
        |x| Sc::B(x[0].i() != 0),
    ));
    specs.push(cw(
        "bits_of_f32",
        "bitcast<u32>(a0)",
        vec![("f32".into(), filtered(any_f32(1), |v| !v.is_nan()))],
        "u32",
        1,
        Tol::EXACT,
        |x| Sc::U(x[0].f().to_bits()),
    ));
    specs.push(cw(
        "f32_of_bits",
        "bitcast<f32>(a0)",
        vec![("u32".into(), any_u32(1))],
        "f32",
        1,
        Tol::EXACT,
        |x| Sc::F(f32::from_bits(x[0].u())),
    ));
    specs.push(cw(
        "i32_of_bits",
        "bitcast<i32>(a0)",
        vec![("u32".into(), any_u32(1))],
        "i32",
        1,
        Tol::EXACT,
        |x| Sc::I(x[0].u() as i32),
    ));
    specs.push(cw(
        "vec2u_of_vec2f_bits",
        "bitcast<vec2u>(a0)",
        vec![("vec2f".into(), filtered(any_f32(2), |v| !v.is_nan()))],
        "vec2u",
        2,
        Tol::EXACT,
        |x| Sc::U(x[0].f().to_bits()),
    ));
    specs
}
