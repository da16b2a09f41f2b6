//! Scene animation (spec/animation.md): `animate` entries checked and evaluated to [`Track`]s.
//!
//! A track's target is resolved against the scene's final objects and named lights (so an
//! `animate` entry may come before the object it moves), its keys are constant expressions checked
//! against the target's type, and its motion over time is checked against what the target can take.
//!
//! Invariants of the tracks of a scene without errors: every target index is in range; keyed
//! tracks have at least one key, finite times `>= 0` in strictly increasing order, and values of
//! the target's type (`mat4x4f` for an object, each invertible as E0708 asks; camera keys pass
//! E0709); `Linear`/`Smooth` keys are of an interpolable type (`f32`, float vectors, `mat4x4f`);
//! `Spin` axes have unit length; `Move` targets an object or a `vec3f` field; no two tracks set one
//! field. The values at a time are computed by the runtime (`rtc_runtime::animation`).

use super::error::{ExprError, SceneError};
use super::expr::Checker;
use super::hir::{
    ConstValue, Instance, Interp, Motion, Scalar, SceneDesc, StructId, Track, TrackTarget,
};
use super::types::TypeTable;
use crate::diag::{codes, suggest, Diagnostic};
use crate::sema::error::SemaError;
use crate::source::Span;
use crate::syntax::ast;

const MOTIONS: &[&str] = &["keys", "spin", "move"];
const INTERPS: &[&str] = &["linear", "step", "smooth"];

/// One `animate` entry as written.
pub(super) struct Entry<'a> {
    pub target: &'a [ast::Ident],
    pub motion: &'a ast::AnimMotion,
    pub span: Span,
}

/// The names `animate` targets are looked up by, besides the objects' own.
pub(super) struct Names<'a> {
    /// Parallel to the scene's lights: each light's name, if given.
    pub lights: &'a [Option<String>],
    /// Names of objects and lights that could not be evaluated (already reported).
    pub broken: &'a [&'a str],
}

fn built(d: Diagnostic) -> SemaError {
    SemaError::Built(Box::new(d))
}

/// What a target resolved to: the track target, the type its values take, its name as written
/// and, for a field, the instance holding it.
struct Resolved {
    target: TrackTarget,
    ty: super::types::TypeId,
    shown: String,
}

/// Checks every `animate` entry of a scene and appends its tracks to `desc.animation`.
pub(super) fn check(ck: &mut Checker, desc: &mut SceneDesc, names: &Names, entries: &[Entry]) {
    // Field tracks already given: (target, where).
    let mut seen: Vec<(TrackTarget, Span)> = Vec::new();
    for entry in entries {
        let head = entry.target.first().map_or(entry.span, |t| t.span);
        let target_span = match entry.target {
            [a, .., b] => a.span.to(b.span),
            _ => head,
        };
        let broken = entry
            .target
            .first()
            .is_some_and(|t| names.broken.contains(&t.name.as_str()));
        let resolved = if broken {
            None
        } else {
            resolve(ck, desc, names.lights, entry.target, target_span)
        };
        let Some(r) = resolved else {
            check_exprs_only(ck, entry.motion);
            continue;
        };
        if !matches!(r.target, TrackTarget::Object(_)) {
            if let Some((_, first)) = seen.iter().find(|(t, _)| *t == r.target) {
                ck.err(SceneError::DuplicateEntry {
                    span: target_span,
                    first: *first,
                    what: format!("a track of `{}`", r.shown),
                });
                check_exprs_only(ck, entry.motion);
                continue;
            }
            seen.push((r.target.clone(), target_span));
        }
        let motion = match entry.motion {
            ast::AnimMotion::Keys {
                word,
                interp,
                keys,
                span,
            } => keyed(ck, desc, &r, word, interp.as_ref(), keys, *span),
            ast::AnimMotion::Over { name, args, span } => over(ck, &r, name, args, *span),
        };
        if let Some(motion) = motion {
            desc.animation.push(Track {
                target: r.target,
                motion,
                span: entry.span,
            });
        }
    }
}

/// Checks the expressions of a motion whose target could not be resolved (their own errors).
fn check_exprs_only(ck: &mut Checker, motion: &ast::AnimMotion) {
    match motion {
        ast::AnimMotion::Keys { keys, .. } => check_keys_only(ck, keys),
        ast::AnimMotion::Over { args, .. } => {
            for a in args {
                ck.expr(*a, None);
            }
        }
    }
}

fn check_keys_only(ck: &mut Checker, keys: &[ast::Keyframe]) {
    for k in keys {
        ck.expect(k.time, TypeTable::F32);
        ck.expr(k.value, None);
    }
}

fn unknown_target(span: Span, message: String, label: &str, help: String) -> SemaError {
    built(
        Diagnostic::error(codes::E0710, message, span)
            .with_label(label.to_string())
            .with_help(help),
    )
}

fn names_help(what: &str, name: &str, names: &[&str]) -> String {
    match suggest::closest(name, names.iter().copied()) {
        Some(s) => format!("did you mean `{s}`?"),
        None if names.is_empty() => format!("this scene has no named {what}"),
        None => format!(
            "the scene's {what}s are {}",
            names
                .iter()
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

fn resolve(
    ck: &mut Checker,
    desc: &SceneDesc,
    light_names: &[Option<String>],
    target: &[ast::Ident],
    span: Span,
) -> Option<Resolved> {
    let object_names: Vec<&str> = desc
        .objects
        .iter()
        .filter_map(|o| o.name.as_deref())
        .collect();
    let light_list: Vec<&str> = light_names.iter().filter_map(|n| n.as_deref()).collect();
    let object = |n: &str| {
        desc.objects
            .iter()
            .position(|o| o.name.as_deref() == Some(n))
    };
    let light = |n: &str| light_names.iter().position(|l| l.as_deref() == Some(n));
    match target {
        [name] => {
            let n = name.name.as_str();
            if let Some(i) = object(n) {
                return Some(Resolved {
                    target: TrackTarget::Object(i),
                    ty: TypeTable::MAT4,
                    shown: n.to_string(),
                });
            }
            let (message, help) = if matches!(n, "camera" | "background") || light(n).is_some() {
                (
                    format!("`{n}` is animated field by field"),
                    format!("name the field, for example `animate {n}.position keys {{ … }}`"),
                )
            } else {
                (
                    format!("no object named `{n}` in this scene"),
                    names_help("object", n, &object_names),
                )
            };
            ck.err(unknown_target(
                span,
                message,
                "not an animation target",
                help,
            ));
            None
        }
        [owner, field] => {
            let o = owner.name.as_str();
            let (inst, kind): (Option<&Instance>, _) = match o {
                "camera" => (desc.camera.as_ref(), 0),
                "background" => (desc.background.as_ref(), 1),
                _ => match light(o) {
                    Some(l) => (desc.lights.get(l), 2 + l),
                    None => {
                        let (message, help) = if object(o).is_some() {
                            (
                                format!("object `{o}` has no fields to animate"),
                                format!(
                                    "an object moves as a whole: `animate {o} keys {{ … }}`, \
                                     `animate {o} spin(…)` or `animate {o} move(…)`"
                                ),
                            )
                        } else {
                            (
                                format!("no light named `{o}` in this scene"),
                                names_help("light", o, &light_list),
                            )
                        };
                        ck.err(unknown_target(
                            span,
                            message,
                            "not an animation target",
                            help,
                        ));
                        return None;
                    }
                },
            };
            let Some(inst) = inst else {
                // A camera brought by a model, or no background: nothing to animate.
                let message = format!("this scene has no `{o}` entry to animate");
                let help = format!("add a `{o}` entry to the scene");
                ck.err(unknown_target(
                    span,
                    message,
                    "not an animation target",
                    help,
                ));
                return None;
            };
            let sid: StructId = inst.struct_id;
            let st = &ck.cx.p.structs[sid];
            let Some(fi) = st.field_index(&field.name) else {
                let names: Vec<&str> = st.fields.iter().map(|f| f.name.as_str()).collect();
                let message = format!("`{}` has no field `{}`", st.name, field.name);
                let help = names_help("field", &field.name, &names).replace("scene's", "struct's");
                ck.err(unknown_target(field.span, message, "no such field", help));
                return None;
            };
            let ty = st.fields[fi].ty;
            let name = field.name.clone();
            let target = match kind {
                0 => TrackTarget::Camera { field: fi, name },
                1 => TrackTarget::Background { field: fi, name },
                k => TrackTarget::Light {
                    light: k - 2,
                    field: fi,
                    name,
                },
            };
            Some(Resolved {
                target,
                ty,
                shown: format!("{o}.{}", field.name),
            })
        }
        _ => None,
    }
}

fn interpolable(ty: super::types::TypeId) -> bool {
    [
        TypeTable::F32,
        TypeTable::VEC2F,
        TypeTable::VEC3F,
        TypeTable::VEC4F,
        TypeTable::MAT4,
    ]
    .contains(&ty)
}

#[allow(clippy::too_many_arguments)]
fn keyed(
    ck: &mut Checker,
    desc: &SceneDesc,
    r: &Resolved,
    word: &ast::Ident,
    interp: Option<&ast::Ident>,
    keys: &[ast::Keyframe],
    span: Span,
) -> Option<Motion> {
    if word.name != "keys" {
        ck.err(SceneError::UnknownEntry {
            span: word.span,
            name: word.name.clone(),
            place: "motion",
            known: MOTIONS,
        });
        check_keys_only(ck, keys);
        return None;
    }
    let mut ok = true;
    let interp = match interp.map(|i| (i.name.as_str(), i.span)) {
        None | Some(("linear", _)) => Interp::Linear,
        Some(("step", _)) => Interp::Step,
        Some(("smooth", _)) => Interp::Smooth,
        Some((other, at)) => {
            ck.err(SceneError::UnknownEntry {
                span: at,
                name: other.to_string(),
                place: "interpolation",
                known: INTERPS,
            });
            ok = false;
            Interp::Linear
        }
    };
    let ty_name = ck.cx.p.type_name(r.ty);
    if interp != Interp::Step && !interpolable(r.ty) {
        ck.err(built(
            Diagnostic::error(
                codes::E0712,
                format!(
                    "`{}` is a `{ty_name}`, which cannot be interpolated",
                    r.shown
                ),
                word.span,
            )
            .with_label("these keys would be blended")
            .with_help(
                "use `keys step { … }`: each key's value holds until the next key".to_string(),
            ),
        ));
        ok = false;
    }
    if keys.is_empty() {
        ck.err(built(
            Diagnostic::error(codes::E0711, "this track has no keys", span)
                .with_label("no keys")
                .with_help("give at least one key, `time: value`, such as `keys { 0.0: … }`"),
        ));
        return None;
    }
    let mut times = Vec::with_capacity(keys.len());
    let mut values = Vec::with_capacity(keys.len());
    let mut prev: Option<(f32, Span)> = None;
    for k in keys {
        let tid = ck.expect(k.time, TypeTable::F32);
        let tspan = ck.span(tid);
        let t = match ck.eval_const(tid) {
            ConstValue::Scalar(Scalar::F32(t)) => Some(t),
            _ => None,
        };
        let hint = ck.hint_of(r.ty);
        let vid = ck.expr(k.value, hint);
        let vty = ck.ty(vid);
        let vspan = ck.span(vid);
        let value = if TypeTable::is_error(vty) {
            None
        } else if vty != r.ty {
            let found = ck.cx.p.type_name(vty);
            ck.err(built(
                Diagnostic::error(
                    codes::E0712,
                    format!("a `{found}` key on a track of `{}`", r.shown),
                    vspan,
                )
                .with_label(format!("this key is a `{found}`"))
                .with_help(format!(
                    "every key of `{}` is a `{ty_name}`, the type of what it animates",
                    r.shown
                )),
            ));
            None
        } else {
            match ck.eval_const(vid) {
                ConstValue::Error => None,
                v => {
                    if check_value(ck, desc, r, &v, vspan) {
                        Some(v)
                    } else {
                        None
                    }
                }
            }
        };
        if let Some(t) = t {
            if !t.is_finite() || t < 0.0 {
                let message = if t.is_finite() {
                    "a key at a negative time"
                } else {
                    "a key at a time that is not a finite number"
                };
                ck.err(built(
                    Diagnostic::error(codes::E0711, message, tspan)
                        .with_label(format!("{t} s"))
                        .with_help("times are seconds from the start of the animation, 0 or more"),
                ));
                ok = false;
            } else if let Some((p, pspan)) = prev {
                if t == p {
                    ck.err(built(
                        Diagnostic::error(codes::E0711, "two keys at one time", tspan)
                            .with_label(format!("a second key at {t} s"))
                            .with_secondary(pspan, "the first")
                            .with_help("remove one of them, or move it to another time"),
                    ));
                    ok = false;
                } else if t < p {
                    ck.err(built(
                        Diagnostic::error(codes::E0711, "keys out of order", tspan)
                            .with_label(format!("{t} s comes after {p} s"))
                            .with_secondary(pspan, "the key before it")
                            .with_help("write the keys in increasing time"),
                    ));
                    ok = false;
                }
            }
            if t.is_finite() {
                prev = Some((t, tspan));
            }
        }
        match (t, value) {
            (Some(t), Some(v)) => {
                times.push(t);
                values.push(v);
            }
            _ => ok = false,
        }
    }
    ok.then_some(Motion::Keys {
        times,
        values,
        interp,
    })
}

/// The checks a key value gets in its place: an object's transform E0708, a camera field E0709.
fn check_value(ck: &mut Checker, desc: &SceneDesc, r: &Resolved, v: &ConstValue, at: Span) -> bool {
    match (&r.target, v) {
        (TrackTarget::Object(_), ConstValue::Matrix { data, .. }) => {
            match super::limits::transform(data, at) {
                Some(e) => {
                    ck.err(e);
                    false
                }
                None => true,
            }
        }
        (TrackTarget::Camera { field, .. }, _) => {
            let Some(cam) = &desc.camera else {
                return true;
            };
            let mut cam = cam.clone();
            cam.fields[*field] = v.clone();
            let errors = super::limits::camera(&ck.cx.p, &cam, &|_| Some(at));
            let ok = errors.is_empty();
            for e in errors {
                ck.err(e);
            }
            ok
        }
        _ => true,
    }
}

fn vec3(v: &ConstValue) -> Option<[f32; 3]> {
    match v {
        ConstValue::Vector { len: 3, comps } => {
            let f = |s: &Scalar| match s {
                Scalar::F32(x) => Some(*x),
                _ => None,
            };
            Some([f(&comps[0])?, f(&comps[1])?, f(&comps[2])?])
        }
        _ => None,
    }
}

fn over(
    ck: &mut Checker,
    r: &Resolved,
    name: &ast::Ident,
    args: &[ast::ExprId],
    span: Span,
) -> Option<Motion> {
    let n = name.name.as_str();
    let params: &[_] = match n {
        "spin" => &[TypeTable::VEC3F, TypeTable::F32, TypeTable::VEC3F],
        "move" => &[TypeTable::VEC3F],
        _ => {
            ck.err(SceneError::UnknownEntry {
                span: name.span,
                name: n.to_string(),
                place: "motion",
                known: MOTIONS,
            });
            for a in args {
                ck.expr(*a, None);
            }
            return None;
        }
    };
    let fits = match (n, &r.target) {
        (_, TrackTarget::Object(_)) => true,
        ("move", _) => r.ty == TypeTable::VEC3F,
        _ => false,
    };
    if !fits {
        let help = if n == "move" {
            "`move` moves an object or changes a `vec3f` field; use `keys { … }` for this field"
        } else {
            "`spin` turns an object; use `keys { … }` for a field"
        };
        ck.err(built(
            Diagnostic::error(
                codes::E0712,
                format!(
                    "`{n}` cannot animate `{}`, a `{}`",
                    r.shown,
                    ck.cx.p.type_name(r.ty)
                ),
                name.span,
            )
            .with_label("not a motion of this target")
            .with_help(help),
        ));
        for a in args {
            ck.expr(*a, None);
        }
        return None;
    }
    let counts = if n == "spin" { vec![2, 3] } else { vec![1] };
    if !counts.contains(&args.len()) {
        ck.err(ExprError::Arity {
            span,
            name: n.to_string(),
            expected: counts,
            found: args.len(),
            decl: None,
        });
        for a in args {
            ck.expr(*a, None);
        }
        return None;
    }
    let mut values = Vec::new();
    for (a, ty) in args.iter().zip(params) {
        let id = ck.expect(*a, *ty);
        values.push((ck.eval_const(id), ck.span(id)));
    }
    let v0 = vec3(&values[0].0)?;
    match n {
        "spin" => {
            let len = (v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2]).sqrt();
            if !(len.is_finite() && len > 0.0) {
                ck.err(built(
                    Diagnostic::error(codes::E0712, "a spin axis with no length", values[0].1)
                        .with_label("this axis")
                        .with_help("give a direction such as `vec3f(0.0, 1.0, 0.0)`"),
                ));
                return None;
            }
            let degrees_per_second = match values[1].0 {
                ConstValue::Scalar(Scalar::F32(d)) => d,
                _ => return None,
            };
            let pivot = match values.get(2) {
                Some((v, _)) => vec3(v)?,
                None => [0.0; 3],
            };
            Some(Motion::Spin {
                axis: [v0[0] / len, v0[1] / len, v0[2] / len],
                degrees_per_second,
                pivot,
            })
        }
        _ => Some(Motion::Move { velocity: v0 }),
    }
}

/// The frame count of a scene that does not set `frames`: enough frames at `fps` to reach the
/// last key of any track (the frame at the last key's time included), at least 1.
pub(super) fn derived_frames(desc: &SceneDesc) -> u32 {
    let last = desc
        .animation
        .iter()
        .filter_map(|t| match &t.motion {
            Motion::Keys { times, .. } => times.last().copied(),
            _ => None,
        })
        .fold(0.0f32, f32::max);
    let frames = (f64::from(last) * f64::from(desc.settings.fps)).floor() + 1.0;
    frames.clamp(1.0, f64::from(super::scenes::MAX_FRAMES)) as u32
}
