//! Whole functions: control flow, structs and arrays.

use super::super::gen::{any_f32, any_i32, any_u32, f32_in, one, whole, Rng};
use super::super::{refs, Args, Sc, Spec, Tol};
use super::*;

/// `if`/`else` chains, `for` with `break`/`continue`, `while`, `loop`, early returns, nested loops,
/// short-circuit operators (also with calls on the right), calls between functions.
pub fn control_flow() -> Vec<Spec> {
    let mut specs = Vec::new();
    specs.push(Spec::new(
        "classify",
        "fn classify(x: f32) -> i32 {
            if x < -1.0 {
                return -2;
            } else if x < 0.0 {
                return -1;
            } else if x == 0.0 {
                return 0;
            } else if x <= 1.0 {
                return 1;
            }
            return 2;
        }\n"
        .into(),
        N,
        vec![any_f32(1)],
        Tol::EXACT,
        |a: &Args| {
            let x = a[0][0].f();
            vec![Sc::I(if x < -1.0 {
                -2
            } else if x < 0.0 {
                -1
            } else if x == 0.0 {
                0
            } else if x <= 1.0 {
                1
            } else {
                2
            })]
        },
    ));
    // The example of spec/statements.md.
    specs.push(Spec::new(
        "sum_to",
        "fn sum_to(n: u32) -> u32 {
            var total = 0u;
            for i in 0u..n {
                if i % 2u == 0u {
                    continue;
                }
                total += i;
            }
            var k = 0u;
            loop {
                k += 1u;
                if k > 3u {
                    break;
                }
            }
            while total > 100u {
                total /= 2u;
            }
            return total + k;
        }\n"
        .into(),
        N,
        vec![one(|r: &mut Rng| Sc::U(r.below(300) as u32))],
        Tol::EXACT,
        |a: &Args| {
            let n = a[0][0].u();
            let mut total = (0..n).filter(|i| i % 2 == 1).sum::<u32>();
            while total > 100 {
                total /= 2;
            }
            vec![Sc::U(total + 4)]
        },
    ));
    specs.push(Spec::new(
        "collatz",
        "fn collatz(n: u32) -> u32 {
            var steps = 0u;
            var x = n;
            while x > 1u && steps < 500u {
                if x % 2u == 0u {
                    x = x / 2u;
                } else {
                    x = 3u * x + 1u;
                }
                steps += 1u;
            }
            return steps;
        }\n"
        .into(),
        N,
        vec![any_u32(1)],
        Tol::EXACT,
        |a: &Args| {
            let (mut x, mut steps) = (a[0][0].u(), 0u32);
            while x > 1 && steps < 500 {
                x = if x % 2 == 0 {
                    x / 2
                } else {
                    x.wrapping_mul(3).wrapping_add(1)
                };
                steps += 1;
            }
            vec![Sc::U(steps)]
        },
    ));
    specs.push(Spec::new(
        "first_multiple",
        "fn first_multiple(a: i32, b: i32) -> i32 {
            for i in a..b {
                if i % 7 == 0 && i != 0 {
                    return i;
                }
            }
            return -1;
        }\n"
        .into(),
        N,
        vec![
            one(|r: &mut Rng| Sc::I(r.range(-50.0, 50.0) as i32)),
            one(|r: &mut Rng| Sc::I(r.range(-50.0, 60.0) as i32)),
        ],
        Tol::EXACT,
        |a: &Args| {
            let (lo, hi) = (a[0][0].i(), a[1][0].i());
            vec![Sc::I(
                (lo..hi).find(|i| i % 7 == 0 && *i != 0).unwrap_or(-1),
            )]
        },
    ));
    specs.push(Spec::new(
        "nested_loops",
        "fn nested_loops(n: i32) -> i32 {
            var acc = 0;
            for i in 0..n {
                for j in 0..i {
                    if j == 3 {
                        break;
                    }
                    acc += j;
                }
                if i == 10 {
                    continue;
                }
                acc += 1;
                var t = 0;
                t += i;
                acc += t;
            }
            return acc;
        }\n"
        .into(),
        N,
        vec![one(|r: &mut Rng| Sc::I(r.range(-5.0, 40.0) as i32))],
        Tol::EXACT,
        |a: &Args| {
            let n = a[0][0].i();
            let mut acc = 0;
            for i in 0..n.max(0) {
                for j in 0..i {
                    if j == 3 {
                        break;
                    }
                    acc += j;
                }
                if i == 10 {
                    continue;
                }
                acc += 1 + i;
            }
            vec![Sc::I(acc)]
        },
    ));
    // `&&` and `||` short-circuit: the right side is not evaluated (its division by zero would be
    // harmless anyway, so the helper call is what matters for the lowering path).
    specs.push(Spec::new(
        "logic",
        "fn positive(x: i32) -> bool { return x > 0; }
        fn logic(a: i32, b: i32) -> vec4b {
            let p = a != 0 && 100 / a > b;
            let q = a == 0 || positive(b);
            let r = positive(a) && positive(b) || !positive(a - b);
            return vec4b(p, q, r, p != q);
        }\n"
        .into(),
        N,
        vec![any_i32(1), any_i32(1)],
        Tol::EXACT,
        |a: &Args| {
            let (x, y) = (a[0][0].i(), a[1][0].i());
            let p = x != 0 && refs::div_i32(100, x) > y;
            let q = x == 0 || y > 0;
            let r = x > 0 && y > 0 || x.wrapping_sub(y) <= 0;
            vec![Sc::B(p), Sc::B(q), Sc::B(r), Sc::B(p != q)]
        },
    ));
    specs
}

/// Nested structs with defaults, struct parameters and results, field and element assignment,
/// arrays as values (copies), dynamic indices in and out of range (clamped, never out of bounds),
/// matrix columns and vector components by dynamic index.
pub fn structs_and_arrays() -> Vec<Spec> {
    let mut specs = Vec::new();
    let structs = "struct Inner {
            a: f32 = 1.5,
            b: vec2f = vec2f(2.0, 3.0),
        }
        struct Outer {
            inner: Inner,
            k: i32 = 7,
            arr: array<f32, 3> = array<f32, 3>(1.0, 2.0, 3.0),
        }\n";
    specs.push(Spec::new(
        "nested",
        format!(
            "{structs}
        fn nested(x: f32, i: i32) -> vec4f {{
            var o = Outer {{ inner: Inner {{ a: x }} }};
            o.inner.b.y += x;
            o.k = o.k * i;
            let c = o;
            o.arr[1] = 5.0;
            o.inner = Inner {{ b: vec2f(x) }};
            return vec4f(c.inner.a + c.inner.b.y, f32(c.k), o.arr[1] + c.arr[1], o.inner.a + o.inner.b.x);
        }}\n"
        ),
        N,
        vec![f32_in(1, -100.0, 100.0), one(|r: &mut Rng| Sc::I(r.range(-100.0, 100.0) as i32))],
        Tol::ulp(1),
        |a: &Args| {
            let (x, i) = (a[0][0].f(), a[1][0].i());
            vec![Sc::F(x + (3.0 + x)), Sc::F((7 * i) as f32), Sc::F(7.0), Sc::F(1.5 + x)]
        },
    ));
    specs.push(Spec::new(
        "pass_struct",
        // The structs come with the previous spec (the specs form one source).
        "
        fn pass_struct(o: Outer, s: f32) -> Outer {
            var r = o;
            r.inner.a *= s;
            r.arr[2] = r.arr[0] + r.arr[1];
            r.k = -r.k;
            return r;
        }\n"
        .into(),
        N,
        // Outer: inner.a, inner.b (2), k, arr (3).
        vec![
            whole(7, |r: &mut Rng| {
                let mut v = fv([
                    r.range(-10.0, 10.0),
                    r.range(-10.0, 10.0),
                    r.range(-10.0, 10.0),
                ]);
                v.push(Sc::I(r.u32() as i32));
                v.extend(fv([
                    r.range(-10.0, 10.0),
                    r.range(-10.0, 10.0),
                    r.range(-10.0, 10.0),
                ]));
                v
            }),
            f32_in(1, -4.0, 4.0),
        ],
        Tol::EXACT,
        |a: &Args| {
            let o = &a[0];
            let s = a[1][0].f();
            vec![
                Sc::F(o[0].f() * s),
                o[1],
                o[2],
                Sc::I(o[3].i().wrapping_neg()),
                o[4],
                o[5],
                Sc::F(o[4].f() + o[5].f()),
            ]
        },
    ));
    // Out-of-range dynamic indices read and write the nearest element (clamped).
    specs.push(Spec::new(
        "indexing",
        "fn indexing(i: i32, j: u32, v: vec4f, m: mat3x3f) -> vec4f {
            var a = array<f32, 4>(10.0, 20.0, 30.0, 40.0);
            a[i] = a[i] + 1.0;
            let b = array<vec2f, 3>(vec2f(1.0, 2.0), vec2f(3.0, 4.0), vec2f(5.0, 6.0));
            let col = m[i];
            return vec4f(a[j] + a[3], b[i].y + b[j].x, v[j] + v[i], col.y + m[j].z);
        }\n"
        .into(),
        N,
        vec![
            one(|r: &mut Rng| Sc::I(r.range(-6.0, 8.0) as i32)),
            any_u32(1),
            f32_in(4, -10.0, 10.0),
            f32_in(9, -10.0, 10.0),
        ],
        Tol::ulp(1),
        |a: &Args| {
            let (i, j) = (a[0][0].i(), a[1][0].u());
            let ci = |n: usize| i.clamp(0, n as i32 - 1) as usize;
            let cj = |n: usize| (j as usize).min(n - 1);
            let mut arr = [10.0f32, 20.0, 30.0, 40.0];
            arr[ci(4)] += 1.0;
            let b = [[1.0f32, 2.0], [3.0, 4.0], [5.0, 6.0]];
            let (v, m) = (fs(a, 2), fs(a, 3));
            vec![
                Sc::F(arr[cj(4)] + arr[3]),
                Sc::F(b[ci(3)][1] + b[cj(3)][0]),
                Sc::F(v[cj(4)] + v[ci(4)]),
                Sc::F(m[ci(3) * 3 + 1] + m[cj(3) * 3 + 2]),
            ]
        },
    ));
    specs.push(Spec::new(
        "array_param",
        "fn array_param(a: array<i32, 5>, i: i32) -> i32 {
            var b = a;
            b[i] = 100;
            var sum = 0;
            for k in 0..5 {
                sum += b[k] * (k + 1);
            }
            return sum + a[i];
        }\n"
        .into(),
        N,
        vec![
            whole(5, |r: &mut Rng| {
                (0..5)
                    .map(|_| Sc::I(r.range(-1000.0, 1000.0) as i32))
                    .collect()
            }),
            one(|r: &mut Rng| Sc::I(r.range(-3.0, 8.0) as i32)),
        ],
        Tol::EXACT,
        |a: &Args| {
            let src: Vec<i32> = a[0].iter().map(|s| s.i()).collect();
            let i = a[1][0].i().clamp(0, 4) as usize;
            let mut b = src.clone();
            b[i] = 100;
            let sum: i32 = b.iter().enumerate().map(|(k, v)| v * (k as i32 + 1)).sum();
            vec![Sc::I(sum + src[i])]
        },
    ));
    specs
}
