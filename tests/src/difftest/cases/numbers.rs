//! The float functions of spec/builtins.md's "Numbers" table, on `f32` and `vec4f`.

use super::super::gen::{any_f32, f32_in, Param};
use super::super::{ulp_of, Sc, Spec, Tol};
use super::*;

/// A float function of one to three arguments, tested on `f32` and `vec4f`.
pub struct FloatFn {
    name: &'static str,
    arity: usize,
    domain: fn(usize, usize) -> Param<'static>,
    tol: Tol,
    reference: fn(&[f32]) -> f32,
    /// The absolute bound of [`Tol::bound`], from one component of each argument.
    bound: Option<fn(&[f32]) -> f64>,
}

/// A [`FloatFn`] without a bound.
pub fn fl(
    name: &'static str,
    arity: usize,
    domain: fn(usize, usize) -> Param<'static>,
    tol: Tol,
    reference: fn(&[f32]) -> f32,
) -> FloatFn {
    FloatFn {
        name,
        arity,
        domain,
        tol,
        reference,
        bound: None,
    }
}

impl FloatFn {
    fn bounded(mut self, bound: fn(&[f32]) -> f64) -> FloatFn {
        self.bound = Some(bound);
        self
    }
}

/// Positive normal floats (and `+inf`): denormal arguments of `log` are outside its domain.
pub fn positive_normal(width: usize) -> Param<'static> {
    filtered(any_f32(width), |v| v >= f32::MIN_POSITIVE)
}

/// `atan2` arguments: not both (nearly) zero, where the result is unspecified.
pub fn atan2_arg(width: usize, i: usize) -> Param<'static> {
    if i == 0 {
        f32_in(width, -10.0, 10.0)
    } else {
        filtered(f32_in(width, -10.0, 10.0), |v| v.abs() >= 1e-3)
    }
}

/// `f(x)` rounded from `f64`.
pub fn r64(x: f32, f: fn(f64) -> f64) -> f32 {
    f(f64::from(x)) as f32
}

/// `sin` and `cos`.
pub fn trig_tol() -> Tol {
    Tol::abs(2e-6)
}

/// `exp2`.
pub fn exp_tol() -> Tol {
    Tol::ulp(3).or_rel(1e-6)
}

/// `sinh`, `cosh`, `tanh`: relative, and absolute near zero (they are computed from `exp`).
pub fn hyp_tol() -> Tol {
    Tol::rel(1e-5).or_abs(1e-6)
}

/// `log`, `log2`: relative, and 2^-21 absolute near 1 (Vulkan's bound).
pub fn log_tol() -> Tol {
    Tol::ulp(3).or_rel(1e-6).or_abs(4.8e-7)
}

const PI: f32 = std::f32::consts::PI;

/// Every float function with its domain, tolerance and reference.
pub fn float_fns() -> Vec<FloatFn> {
    vec![
        fl("abs", 1, |w, _| any_f32(w), Tol::EXACT, |a| a[0].abs()),
        fl(
            "sign",
            1,
            |w, _| no_nan(w),
            Tol::EXACT,
            |a| {
                if a[0] > 0.0 {
                    1.0
                } else if a[0] < 0.0 {
                    -1.0
                } else {
                    0.0
                }
            },
        ),
        fl(
            "saturate",
            1,
            |w, _| no_nan(w),
            Tol::EXACT,
            |a| a[0].clamp(0.0, 1.0),
        ),
        fl("floor", 1, |w, _| any_f32(w), Tol::EXACT, |a| a[0].floor()),
        fl("ceil", 1, |w, _| any_f32(w), Tol::EXACT, |a| a[0].ceil()),
        fl(
            "round",
            1,
            |w, _| any_f32(w),
            Tol::EXACT,
            |a| a[0].round_ties_even(),
        ),
        fl("trunc", 1, |w, _| any_f32(w), Tol::EXACT, |a| a[0].trunc()),
        fl(
            "fract",
            1,
            |w, _| finite(w),
            Tol::EXACT,
            |a| a[0] - a[0].floor(),
        ),
        fl(
            "sqrt",
            1,
            |w, _| any_f32(w),
            Tol::ulp(1),
            |a| r64(a[0], f64::sqrt),
        ),
        fl(
            "inverse_sqrt",
            1,
            |w, _| positive(w),
            Tol::ulp(2),
            |a| r64(a[0], |x| 1.0 / x.sqrt()),
        ),
        fl(
            "exp",
            1,
            |w, _| f32_in(w, -87.0, 88.0),
            Tol::bound(),
            |a| r64(a[0], f64::exp),
        )
        .bounded(|a| (3.0 + 2.0 * f64::from(a[0].abs())) * ulp_of(f64::from(a[0]).exp())),
        fl(
            "exp2",
            1,
            |w, _| f32_in(w, -126.0, 127.0),
            exp_tol(),
            |a| r64(a[0], f64::exp2),
        ),
        fl(
            "log",
            1,
            |w, _| positive_normal(w),
            log_tol(),
            |a| r64(a[0], f64::ln),
        ),
        fl(
            "log2",
            1,
            |w, _| positive_normal(w),
            log_tol(),
            |a| r64(a[0], f64::log2),
        ),
        fl(
            "sin",
            1,
            |w, _| f32_in(w, -PI, PI),
            trig_tol(),
            |a| r64(a[0], f64::sin),
        ),
        fl(
            "cos",
            1,
            |w, _| f32_in(w, -PI, PI),
            trig_tol(),
            |a| r64(a[0], f64::cos),
        ),
        fl(
            "tan",
            1,
            |w, _| f32_in(w, -PI, PI),
            trig_tol().or_ulp(4),
            |a| r64(a[0], f64::tan),
        ),
        fl(
            "asin",
            1,
            |w, _| f32_in(w, -1.0, 1.0),
            Tol::abs(5e-4),
            |a| r64(a[0], f64::asin),
        ),
        fl(
            "acos",
            1,
            |w, _| f32_in(w, -1.0, 1.0),
            Tol::abs(3e-4),
            |a| r64(a[0], f64::acos),
        ),
        fl(
            "atan",
            1,
            |w, _| finite(w),
            Tol::abs(4e-6),
            |a| r64(a[0], f64::atan),
        ),
        fl(
            "sinh",
            1,
            |w, _| f32_in(w, -10.0, 10.0),
            hyp_tol(),
            |a| r64(a[0], f64::sinh),
        ),
        fl(
            "cosh",
            1,
            |w, _| f32_in(w, -10.0, 10.0),
            hyp_tol(),
            |a| r64(a[0], f64::cosh),
        ),
        fl(
            "tanh",
            1,
            |w, _| f32_in(w, -10.0, 10.0),
            hyp_tol(),
            |a| r64(a[0], f64::tanh),
        ),
        fl(
            "radians",
            1,
            |w, _| finite(w),
            Tol::ulp(1),
            |a| r64(a[0], f64::to_radians),
        ),
        fl(
            "degrees",
            1,
            |w, _| f32_in(w, -1e30, 1e30),
            Tol::ulp(1),
            |a| r64(a[0], f64::to_degrees),
        ),
        fl("min", 2, |w, _| no_nan(w), Tol::EXACT, |a| a[0].min(a[1])),
        fl("max", 2, |w, _| no_nan(w), Tol::EXACT, |a| a[0].max(a[1])),
        fl(
            "pow",
            2,
            |w, i| {
                if i == 0 {
                    f32_in(w, 1e-6, 100.0)
                } else {
                    f32_in(w, -8.0, 8.0)
                }
            },
            Tol::bound(),
            |a| (f64::from(a[0]).powf(f64::from(a[1]))) as f32,
        )
        .bounded(|a| {
            let (x, y) = (f64::from(a[0]), f64::from(a[1]));
            (3.0 + (y * x.log2()).abs()) * ulp_of(x.powf(y))
        }),
        fl("atan2", 2, atan2_arg, Tol::abs(4e-6), |a| {
            (f64::from(a[0]).atan2(f64::from(a[1]))) as f32
        }),
        fl(
            "step",
            2,
            |w, _| no_nan(w),
            Tol::EXACT,
            |a| {
                if a[1] >= a[0] {
                    1.0
                } else {
                    0.0
                }
            },
        ),
        fl(
            "clamp",
            3,
            |w, _| no_nan(w),
            Tol::EXACT,
            |a| a[0].max(a[1]).min(a[2]),
        ),
        fl(
            "mix",
            3,
            |w, i| {
                if i == 2 {
                    f32_in(w, 0.0, 1.0)
                } else {
                    f32_in(w, -100.0, 100.0)
                }
            },
            Tol::bound(),
            |a| {
                let (x, y, t) = (f64::from(a[0]), f64::from(a[1]), f64::from(a[2]));
                (x + (y - x) * t) as f32
            },
        )
        .bounded(|a| 2.0 * ulp_of(f64::from(a[0].abs().max(a[1].abs())))),
        fl(
            "smoothstep",
            3,
            |w, i| match i {
                0 => f32_in(w, -10.0, -0.5),
                1 => f32_in(w, 0.5, 10.0),
                _ => f32_in(w, -12.0, 12.0),
            },
            Tol::ulp(4).or_abs(2.4e-7),
            |a| {
                let (lo, hi, x) = (f64::from(a[0]), f64::from(a[1]), f64::from(a[2]));
                let t = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
                (t * t * (3.0 - 2.0 * t)) as f32
            },
        ),
        fl(
            "fma",
            3,
            |w, _| f32_in(w, -100.0, 100.0),
            Tol::bound(),
            |a| a[0].mul_add(a[1], a[2]),
        )
        .bounded(|a| ulp_of(f64::from((a[0] * a[1]).abs() + a[2].abs()))),
    ]
}

/// Every float function of spec/builtins.md's "Numbers" table, on `f32` and `vec4f`.
pub fn float_builtins() -> Vec<Spec> {
    let mut specs = Vec::new();
    for fun in float_fns() {
        for width in [1usize, 4] {
            let t = ty("f32", width);
            let args: Vec<String> = (0..fun.arity).map(|i| format!("a{i}")).collect();
            let params = (0..fun.arity)
                .map(|i| (t.clone(), (fun.domain)(width, i)))
                .collect();
            let reference = fun.reference;
            let spec = cw(
                &format!("{}_{t}", fun.name),
                &format!("{}({})", fun.name, args.join(", ")),
                params,
                &t,
                width,
                fun.tol,
                move |xs| {
                    let v: Vec<f32> = xs.iter().map(|s| s.f()).collect();
                    Sc::F(reference(&v))
                },
            );
            specs.push(match fun.bound {
                Some(bound) => cw_bound(spec, width, bound),
                None => spec,
            });
        }
    }
    // mix with a scalar weight.
    let mix_t = cw(
        "mix_scalar_t",
        "mix(a0, a1, a2)",
        vec![
            ("vec3f".into(), f32_in(3, -100.0, 100.0)),
            ("vec3f".into(), f32_in(3, -100.0, 100.0)),
            ("f32".into(), f32_in(1, 0.0, 1.0)),
        ],
        "vec3f",
        3,
        Tol::bound(),
        |xs| {
            let (x, y, t) = (f64_of(xs[0]), f64_of(xs[1]), f64_of(xs[2]));
            Sc::F((x + (y - x) * t) as f32)
        },
    );
    specs.push(cw_bound(mix_t, 3, |a| {
        2.0 * ulp_of(f64::from(a[0].abs().max(a[1].abs())))
    }));
    specs
}
