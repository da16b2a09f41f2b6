//! The differential test cases, by group: each group is a list of [`Spec`]s (DSL source, inputs,
//! reference, tolerance) that `tests/diff.rs` runs on the GPU as one test.
//!
//! The cases are GPU-free data, so this crate's own tests check every case's source, lower it with
//! the test entry point and write it for all five targets, on any machine.
//!
//! Invariants: every function runs over at least [`N`] inputs, edge values first; the tolerance of
//! every float built-in is the one spec/builtins.md states (the bounds that depend on the arguments
//! are computed per input, see [`Tol::bound`]).

pub mod geometry;
pub mod integers;
pub mod linalg;
pub mod numbers;
pub mod operators;
pub mod programs;

use super::gen::{any_f32, any_i32, any_u32, whole, Param, Rng};
use super::{refs, Args, Sc, Spec, Tol};

/// Inputs per function (at least).
pub const N: usize = 1000;

/// A group of cases: its name (the test's) and the function listing them.
pub type Group = (&'static str, fn() -> Vec<Spec>);

/// Every group.
pub fn groups() -> Vec<Group> {
    vec![
        ("float_builtins", numbers::float_builtins),
        ("integer_builtins", integers::integer_builtins),
        (
            "classification_and_select",
            integers::classification_and_select,
        ),
        ("bit_packing", integers::bit_packing),
        ("integer_operators", operators::integer_operators),
        ("float_operators", operators::float_operators),
        ("conversions", operators::conversions),
        ("vector_builtins", linalg::vector_builtins),
        ("matrix_builtins", linalg::matrix_builtins),
        ("geometry_builtins", geometry::geometry_builtins),
        ("control_flow", programs::control_flow),
        ("structs_and_arrays", programs::structs_and_arrays),
    ]
}

/// Component `c` of parameter `i` (a scalar parameter broadcasts).
pub fn comp(a: &Args, i: usize, c: usize) -> Sc {
    let p = &a[i];
    if p.len() == 1 {
        p[0]
    } else {
        p[c]
    }
}

/// The `i`th parameter's components as `f32`s.
pub fn fs(a: &Args, i: usize) -> Vec<f32> {
    a[i].iter().map(|s| s.f()).collect()
}

/// `f32` components.
pub fn fv(v: impl IntoIterator<Item = f32>) -> Vec<Sc> {
    v.into_iter().map(Sc::F).collect()
}

/// `f64` values rounded to `f32` components.
pub fn fv64(v: impl IntoIterator<Item = f64>) -> Vec<Sc> {
    v.into_iter().map(|x| Sc::F(x as f32)).collect()
}

/// The DSL name of a scalar or vector type of kind `f32`, `i32`, `u32` or `bool`.
pub fn ty(kind: &str, width: usize) -> String {
    match width {
        1 => kind.to_string(),
        w => format!("vec{w}{}", &kind[..1]),
    }
}

/// A function `fn {func}(a0: T0, …) -> R { return {expr}; }`.
pub fn src(func: &str, types: &[String], ret: &str, expr: &str) -> String {
    let decl: Vec<String> = types
        .iter()
        .enumerate()
        .map(|(i, t)| format!("a{i}: {t}"))
        .collect();
    format!(
        "fn {func}({}) -> {ret} {{ return {expr}; }}\n",
        decl.join(", ")
    )
}

/// A component-wise function: the reference applied to every component of the result (`width`).
pub fn cw(
    func: &str,
    expr: &str,
    params: Vec<(String, Param<'static>)>,
    ret: &str,
    width: usize,
    tol: Tol,
    r: impl Fn(&[Sc]) -> Sc + 'static,
) -> Spec {
    let (types, ps): (Vec<String>, Vec<Param<'static>>) = params.into_iter().unzip();
    let arity = types.len();
    Spec::new(
        func,
        src(func, &types, ret, expr),
        N,
        ps,
        tol,
        move |a: &Args| {
            (0..width)
                .map(|c| {
                    let xs: Vec<Sc> = (0..arity).map(|i| comp(a, i, c)).collect();
                    r(&xs)
                })
                .collect()
        },
    )
}

/// The absolute bound of [`Tol::bound`], per component of a component-wise function.
pub fn cw_bound(spec: Spec, width: usize, bound: fn(&[f32]) -> f64) -> Spec {
    let arity = spec.inputs.first().map_or(0, Vec::len);
    spec.with_bound(move |a: &Args| {
        (0..width)
            .map(|c| {
                let xs: Vec<f32> = (0..arity).map(|i| comp(a, i, c).f()).collect();
                bound(&xs)
            })
            .collect()
    })
}

/// Any float but NaN.
pub fn no_nan(width: usize) -> Param<'static> {
    filtered(any_f32(width), |v| !v.is_nan())
}

/// Any finite float.
pub fn finite(width: usize) -> Param<'static> {
    filtered(any_f32(width), f32::is_finite)
}

/// Positive floats, finite or not (`+inf` among the edges), wide range.
pub fn positive(width: usize) -> Param<'static> {
    filtered(any_f32(width), |v| v > 0.0)
}

/// `p` with edges and draws restricted to `keep` (a rejected draw is redrawn).
pub fn filtered(mut p: Param<'static>, keep: fn(f32) -> bool) -> Param<'static> {
    p.edges.retain(|s| keep(s.f()));
    let mut draw = p.draw;
    p.draw = Box::new(move |r: &mut Rng| loop {
        let v = draw(r);
        if keep(v.f()) {
            return v;
        }
    });
    p
}

/// A component as `f64`.
pub fn f64_of(s: Sc) -> f64 {
    f64::from(s.f())
}

/// An integer parameter of kind `i32` or `u32`.
pub fn any_int(kind: &str, width: usize) -> Param<'static> {
    if kind == "i32" {
        any_i32(width)
    } else {
        any_u32(width)
    }
}

/// A random unit vector of `width` components.
pub fn unit(r: &mut Rng, width: usize) -> Vec<f32> {
    loop {
        let v: Vec<f32> = (0..width).map(|_| r.range(-1.0, 1.0)).collect();
        let len = v.iter().map(|x| x * x).sum::<f32>().sqrt();
        if len > 0.1 && len <= 1.0 {
            return v.iter().map(|x| x / len).collect();
        }
    }
}

/// A parameter of random unit vectors.
pub fn unit_param(width: usize) -> Param<'static> {
    whole(width, move |r: &mut Rng| fv(unit(r, width)))
}

/// The dot product in `f64`.
pub fn dot64(a: &[f32], b: &[f32]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| f64::from(*x) * f64::from(*y))
        .sum()
}

/// A random matrix of `cols` × `rows` with entries in `[-2, 2]`; square ones are made diagonally
/// dominant (well conditioned) unless `singular`, which duplicates a column of small integers.
pub fn matrix(r: &mut Rng, cols: usize, rows: usize, singular: bool) -> Vec<f32> {
    let mut m: Vec<f32> = (0..cols * rows).map(|_| r.range(-2.0, 2.0)).collect();
    if singular {
        for v in m.iter_mut() {
            *v = (*v * 2.0).round();
        }
        let (a, b) = (r.below(cols), r.below(cols));
        let b = if a == b { (a + 1) % cols } else { b };
        for k in 0..rows {
            m[b * rows + k] = m[a * rows + k];
        }
    } else if cols == rows {
        for c in 0..cols {
            let s = if m[c * rows + c] < 0.0 { -1.0 } else { 1.0 };
            m[c * rows + c] += s * 2.0 * cols as f32;
        }
    }
    m
}

/// A `Ray` parameter's components (origin, tmin, dir, tmax, depth, kind, medium).
pub fn ray_comps(origin: [f32; 3], dir: [f32; 3], tmin: f32, tmax: f32) -> Vec<Sc> {
    let mut v = fv(origin);
    v.push(Sc::F(tmin));
    v.extend(fv(dir));
    v.push(Sc::F(tmax));
    v.extend([Sc::U(0), Sc::U(0), Sc::U(0)]);
    v
}

/// Parameter `i` as a `Ray`.
pub fn ray_of(a: &Args, i: usize) -> refs::Ray {
    let v = fs(a, i);
    refs::Ray {
        origin: [v[0], v[1], v[2]],
        tmin: v[3],
        dir: [v[4], v[5], v[6]],
        tmax: v[7],
    }
}

/// A random point of the cube `[lo, hi)³`.
pub fn v3(r: &mut Rng, lo: f32, hi: f32) -> [f32; 3] {
    [r.range(lo, hi), r.range(lo, hi), r.range(lo, hi)]
}

/// A direction with some components exactly zero (axis-parallel rays) or denormal.
pub fn dir_with_zeros(r: &mut Rng) -> [f32; 3] {
    let mut d = v3(r, -1.0, 1.0);
    match r.below(4) {
        0 => d[r.below(3)] = 0.0,
        1 => {
            let k = r.below(3);
            d[k] = 0.0;
            d[(k + 1) % 3] = 0.0;
        }
        2 => d[r.below(3)] = 1e-40,
        _ => {}
    }
    d
}

#[cfg(test)]
mod tests {
    use super::groups;
    use crate::difftest::Suite;

    /// Every case checks, lowers with the test entry point and writes for all five targets (no GPU
    /// needed), and has enough inputs.
    #[test]
    fn every_case_lowers_for_every_target() {
        for (name, cases) in groups() {
            let specs = cases();
            let src: Vec<&str> = specs.iter().map(|s| s.src.as_str()).collect();
            let suite = Suite::new(name, &src.join("\n"));
            for s in &specs {
                assert!(
                    s.inputs.len() >= super::N,
                    "{name}::{}: {} inputs",
                    s.func,
                    s.inputs.len()
                );
                if let Err(e) = suite.kernel(&s.func) {
                    panic!("{name}::{}: {e}", s.func);
                }
            }
        }
    }
}
