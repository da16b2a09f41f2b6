//! Values the checker accepts only within what the GPU and the runtime can use, so that nothing is
//! clamped, dropped or turned into NaN later without a word (issue 21). Each check builds its
//! diagnostic here, located at the user's expression:
//!
//! - E0415: a constant operation on finite operands whose `f32` result is infinite or NaN
//!   (`1e30 * 1e30`, `0.0 / 0.0`; found by [`super::consteval`]).
//! - E0707: `sphere_mesh(n)` above [`MAX_SPHERE_SUBDIVISIONS`] (the runtime would clamp it).
//! - E0708: an object or model transform that is not affine, is singular, or whose inverse does
//!   not fit in `f32` (`scale(1e-30)`), which the runtime needs to move rays into object space.
//! - E0709: a camera parameter that makes every ray NaN: the range table [`CAMERA_RANGES`] for
//!   fields of `@camera` structs by name (`fov`, `height`, `aperture`, `focus_distance`), and the
//!   view frame (`position`, `look_at`, `up`: a zero-length or non-finite view direction, an `up`
//!   parallel to it). The rules go by field name and type, so a user's camera with these fields
//!   gets them too.
//! - W0004: a scene's `max_rays_per_hit` below the spawn bound of a `@secondary_rays` program of a
//!   material it uses: the rays a call spawns after the first `max_rays_per_hit` are dropped.

use super::error::SemaError;
use super::hir::{ConstValue, Instance, Program, ProgramKind, Scalar};
use crate::diag::{codes, Diagnostic};
use crate::source::Span;

/// The largest `sphere_mesh` subdivision level. Level 8 is 1,310,720 triangles and about 660k
/// vertices, already far finer than any image needs; each level has four times the triangles.
pub const MAX_SPHERE_SUBDIVISIONS: u32 = 8;

fn built(d: Diagnostic) -> SemaError {
    SemaError::Built(Box::new(d))
}

/// E0415 at an operation whose finite operands gave a non-finite value.
pub(crate) fn non_finite(span: Span, nan: bool) -> SemaError {
    let (what, label) = if nan {
        ("NaN", "this is NaN (not a number)")
    } else {
        ("infinite", "this overflows `f32` to infinity")
    };
    built(
        Diagnostic::error(
            codes::E0415,
            format!("this constant operation on finite values is {what}"),
            span,
        )
        .with_label(label)
        .with_help(
            "the value would reach the GPU as NaN samples; keep constants within `f32` \
             (about ±3.4e38), or write the prelude's `INF` where an infinity is meant",
        ),
    )
}

/// E0707 for `sphere_mesh(n)` with `n` above [`MAX_SPHERE_SUBDIVISIONS`], at the argument.
pub(crate) fn sphere_subdivisions(n: u32, span: Span) -> Option<SemaError> {
    (n > MAX_SPHERE_SUBDIVISIONS).then(|| {
        built(
            Diagnostic::error(
                codes::E0707,
                format!("`sphere_mesh` takes at most {MAX_SPHERE_SUBDIVISIONS} subdivisions"),
                span,
            )
            .with_label(format!("this is {n}"))
            .with_help(format!(
                "level {MAX_SPHERE_SUBDIVISIONS} already has 1,310,720 triangles and each level \
                 has four times the triangles of the one before; use at most \
                 `sphere_mesh({MAX_SPHERE_SUBDIVISIONS}u)`"
            )),
        )
    })
}

/// E0708 for a transform (`data[column][row]`) the runtime could not invert in `f32`.
pub(crate) fn transform(data: &[[f32; 4]; 4], span: Span) -> Option<SemaError> {
    let error = |label: String, help: &str| {
        Some(built(
            Diagnostic::error(
                codes::E0708,
                "this transform cannot be used to place an object",
                span,
            )
            .with_label(label)
            .with_help(help.to_string()),
        ))
    };
    if data.iter().flatten().any(|x| !x.is_finite()) {
        return error(
            "it has a NaN or infinite entry".to_string(),
            "rays are moved into object space by the inverse transform, which needs finite entries",
        );
    }
    if data[0][3] != 0.0 || data[1][3] != 0.0 || data[2][3] != 0.0 || data[3][3] != 1.0 {
        return error(
            "it is not affine (its last row is not 0, 0, 0, 1)".to_string(),
            "build it from `translate`, `rotate`, `rotate_x/y/z` and `scale`",
        );
    }
    let det64 = det3(data, f64::from);
    if det64 == 0.0 {
        return error(
            "it is singular: it flattens the object onto a plane, a line or a point".to_string(),
            "rays are moved into object space by the inverse transform, which a singular \
             transform does not have; give every axis a non-zero scale",
        );
    }
    if !inverse_fits_f32(data) {
        let side = if det64.abs() < 1.0 { "small" } else { "large" };
        return error(
            format!(
                "its determinant is {det64:.1e}, too {side} for `f32`: it cannot be inverted in \
                 single precision"
            ),
            "rays are moved into object space by the inverse transform, computed in `f32`; keep \
             each axis's scale between about 1e-12 and 1e12 (or change the scene's units)",
        );
    }
    None
}

/// The determinant of the linear part, in the type `f` converts to.
fn det3<T>(m: &[[f32; 4]; 4], f: impl Fn(f32) -> T) -> T
where
    T: Copy + std::ops::Mul<Output = T> + std::ops::Sub<Output = T> + std::ops::Add<Output = T>,
{
    let a = |c: usize, r: usize| f(m[c][r]);
    a(0, 0) * (a(1, 1) * a(2, 2) - a(2, 1) * a(1, 2))
        - a(1, 0) * (a(0, 1) * a(2, 2) - a(2, 1) * a(0, 2))
        + a(2, 0) * (a(0, 1) * a(1, 2) - a(1, 1) * a(0, 2))
}

/// Whether the affine inverse computed in `f32` (as the runtime does) is finite with a non-zero
/// determinant.
fn inverse_fits_f32(m: &[[f32; 4]; 4]) -> bool {
    let det = det3(m, |x| x);
    if det == 0.0 || !det.is_finite() {
        return false;
    }
    let inv_det = 1.0 / det;
    let a = |c: usize, r: usize| m[c][r];
    let mut inv = [[0.0f32; 3]; 3];
    for (r, row) in inv.iter_mut().enumerate() {
        for (c, out) in row.iter_mut().enumerate() {
            // The cofactor of (c, r) (transposed: the adjugate).
            let (c1, c2) = ((r + 1) % 3, (r + 2) % 3);
            let (r1, r2) = ((c + 1) % 3, (c + 2) % 3);
            *out = (a(c1, r1) * a(c2, r2) - a(c2, r1) * a(c1, r2)) * inv_det;
        }
    }
    let t = [m[3][0], m[3][1], m[3][2]];
    let tinv: Vec<f32> = inv
        .iter()
        .map(|row| -(row[0] * t[0] + row[1] * t[1] + row[2] * t[2]))
        .collect();
    inv.iter().flatten().chain(&tinv).all(|x| x.is_finite())
}

/// `v` as written in a message: plain when that is short, otherwise in scientific notation.
fn number(v: f32) -> String {
    if v == 0.0 || (1e-4..1e7).contains(&v.abs()) || !v.is_finite() {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A range a camera field must be in.
#[derive(Clone, Copy, Debug)]
pub enum Range {
    /// Strictly between the two bounds.
    Open(f32, f32),
    /// Greater than zero.
    Positive,
    /// Zero or more.
    NonNegative,
}

/// The `f32` fields of `@camera` structs that are checked, by name, with their range and what
/// they are (spec/scenes.md, "Checked values").
pub const CAMERA_RANGES: &[(&str, Range, &str)] = &[
    (
        "fov",
        Range::Open(0.0, 180.0),
        "the vertical field of view, in degrees",
    ),
    (
        "height",
        Range::Positive,
        "the height of the view, in world units",
    ),
    ("aperture", Range::NonNegative, "the lens diameter"),
    (
        "focus_distance",
        Range::Positive,
        "the distance of the sharp plane",
    ),
];

/// E0709 for the camera `inst`; `field_span` gives where a field was written (`None`: it took its
/// default, and the instance's span is used).
pub(crate) fn camera(
    p: &Program,
    inst: &Instance,
    field_span: &dyn Fn(&str) -> Option<Span>,
) -> Vec<SemaError> {
    let st = &p.structs[inst.struct_id];
    let value = |name: &str| st.field_index(name).and_then(|i| inst.fields.get(i));
    let at = |name: &str| field_span(name).unwrap_or(inst.span);
    let mut out = Vec::new();
    let mut report = |name: &str, label: String, help: String| {
        out.push(built(
            Diagnostic::error(
                codes::E0709,
                format!("the camera's `{name}` makes every ray invalid"),
                at(name),
            )
            .with_label(label)
            .with_help(help),
        ));
    };
    for &(name, range, what) in CAMERA_RANGES {
        let Some(ConstValue::Scalar(Scalar::F32(v))) = value(name) else {
            continue;
        };
        let (ok, bounds) = match range {
            Range::Open(lo, hi) => (*v > lo && *v < hi, format!("between {lo} and {hi}")),
            Range::Positive => (*v > 0.0 && v.is_finite(), "greater than 0".to_string()),
            Range::NonNegative => (*v >= 0.0 && v.is_finite(), "0 or more".to_string()),
        };
        // A field of view must also survive `tan(radians(fov) * 0.5)` in f32.
        let ok = ok && (name != "fov" || (v.to_radians() * 0.5).tan() > 0.0);
        if !ok {
            report(
                name,
                format!("this is {}", number(*v)),
                format!("`{name}` is {what}: it must be {bounds} (and not underflow in `f32`)"),
            );
        }
    }
    let vec3 = |name: &str| match value(name) {
        Some(ConstValue::Vector { len: 3, comps }) => {
            let mut v = [0.0f32; 3];
            for (o, c) in v.iter_mut().zip(comps) {
                *o = match c {
                    Scalar::F32(x) => *x,
                    _ => return None,
                };
            }
            Some(v)
        }
        _ => None,
    };
    let dot = |a: [f32; 3], b: [f32; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let usable = |v: [f32; 3]| {
        let l = dot(v, v);
        l > 0.0 && l.is_finite()
    };
    let (Some(pos), Some(look)) = (vec3("position"), vec3("look_at")) else {
        return out;
    };
    let forward = [look[0] - pos[0], look[1] - pos[1], look[2] - pos[2]];
    if !usable(forward) {
        report(
            "look_at",
            "the view direction `look_at - position` has no usable length".to_string(),
            "`look_at` must differ from `position` by a distance `f32` can square (neither \
             zero nor beyond about 1e19)"
                .to_string(),
        );
        return out;
    }
    let Some(up) = vec3("up") else {
        return out;
    };
    if !usable(up) {
        report(
            "up",
            "`up` has no usable length".to_string(),
            "give `up` a direction, e.g. `vec3f(0.0, 1.0, 0.0)`".to_string(),
        );
        return out;
    }
    // The sine of the angle between them, in f64: near zero, `cross(forward, up)` is noise.
    let f = forward.map(f64::from);
    let u = up.map(f64::from);
    let cross = [
        f[1] * u[2] - f[2] * u[1],
        f[2] * u[0] - f[0] * u[2],
        f[0] * u[1] - f[1] * u[0],
    ];
    let len = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let sine = len(cross) / (len(f) * len(u));
    if sine < 1e-4 {
        report(
            "up",
            "`up` is parallel to the view direction `look_at - position`".to_string(),
            "the camera's roll is undefined when it looks along `up`; choose an `up` across the \
             view direction, e.g. `vec3f(0.0, 0.0, -1.0)` when looking straight down"
                .to_string(),
        );
    }
    out
}

/// W0004 when `max_rays_per_hit` is below the spawn bound of the `@secondary_rays` program of
/// material struct `material` (used at `use_span`); `setting` is where `max_rays_per_hit` was
/// written, if it was.
pub(crate) fn spawn_over_limit(
    p: &Program,
    material: super::hir::StructId,
    max_rays_per_hit: u32,
    use_span: Span,
    setting: Option<Span>,
) -> Option<SemaError> {
    let entry = p.program_for(material, ProgramKind::SecondaryRays)?;
    let bound = entry.spawn_bound;
    if bound <= max_rays_per_hit {
        return None;
    }
    let program = &p.functions[entry.func].name;
    let st = &p.structs[material].name;
    let message = format!(
        "`{program}` (of `{st}`) spawns up to {bound} rays per hit, but `max_rays_per_hit` is \
         {max_rays_per_hit}"
    );
    let mut dropped =
        format!("the rays it spawns after the first {max_rays_per_hit} in one call are dropped");
    if st == "Glass" {
        dropped.push_str(" (here the refracted ray, after the reflected one)");
    }
    let d = match setting {
        Some(s) => Diagnostic::warning(codes::W0004, message, s)
            .with_label(dropped)
            .with_secondary(use_span, format!("`{st}` used here")),
        None => Diagnostic::warning(codes::W0004, message, use_span).with_label(format!(
            "{dropped} (`max_rays_per_hit` defaults to {max_rays_per_hit})"
        )),
    };
    Some(built(d.with_help(format!(
        "set `max_rays_per_hit: {bound}u` in the scene's `settings` to trace them all"
    ))))
}
