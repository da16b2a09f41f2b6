//! Scenes (spec/scenes.md): entries checked against the declared structs and evaluated to constants.
//!
//! Every value in a scene is a constant expression checked by the same [`Checker`] as code (so
//! `Glass { ior: "x" }` is E0401 at `"x"`), in [`Mode::Scene`], where the asset constructors are
//! allowed and asset paths resolve relative to the scene's file. A scene `let` binds an evaluated
//! value visible to the entries after it.
//!
//! Invariants of a [`SceneDesc`] without errors: the camera, background, lights and materials are
//! instances of structs of the right role with every field evaluated; settings are in range; object
//! names are unique; the camera is present unless a `model` is expected to bring one.

use super::error::{Expected, ExprError, SceneError};
use super::expr::{Binding, Checker, Mode};
use super::hir::{
    ConstValue, Geometry, Instance, Model, Object, Program, Role, SceneChoiceError, SceneDesc,
    SceneId, Settings, IDENTITY,
};
use super::types::{Type, TypeTable};
use super::Ctx;
use crate::source::Span;
use crate::syntax::ast;
use la_arena::{Idx, RawIdx};

const SETTINGS: &[&str] = &[
    "width",
    "height",
    "samples",
    "max_depth",
    "max_rays_per_hit",
    "roulette_depth",
    "seed",
    "exec",
    "fps",
    "frames",
];
/// The largest image side, in pixels, of a scene's `width`/`height` and of the command line's `--size`.
pub const MAX_IMAGE_SIDE: u32 = 16384;
/// The most samples per pixel of a scene's `samples` and of the command line's `--spp`.
pub const MAX_SAMPLES: u32 = 1 << 20;
/// The most frames per second of a scene's `fps` and of the command line's `--fps`.
pub const MAX_FPS: u32 = 1000;
/// The most frames of a scene's `frames` (and of a derived frame count).
pub const MAX_FRAMES: u32 = 1_000_000;

const OBJECT_FIELDS: &[&str] = &["geometry", "material", "transform"];
const MODEL_FIELDS: &[&str] = &["transform"];

/// Phase 8: every scene.
pub(crate) fn check_scenes(cx: &mut Ctx) {
    let scenes = cx.scenes_ast.clone();
    for (i, (module, decl)) in scenes.into_iter().enumerate() {
        let id: SceneId = Idx::from_raw(RawIdx::from_u32(i as u32));
        let desc = check_scene(cx, module, decl, cx.p.scenes[id].clone());
        cx.p.scenes[id] = desc;
    }
}

/// Remembers the first occurrence of a once-only entry; reports E0705 for the next ones.
fn once(ck: &mut Checker, slot: &mut Option<Span>, span: Span, what: &str) -> bool {
    match slot {
        Some(first) => {
            ck.err(SceneError::DuplicateEntry {
                span,
                first: *first,
                what: what.to_string(),
            });
            false
        }
        None => {
            *slot = Some(span);
            true
        }
    }
}

fn entry_head(span: Span, len: u32) -> Span {
    Span::new(span.file, span.lo, span.lo.saturating_add(len).min(span.hi))
}

fn check_scene<'a>(
    cx: &mut Ctx<'a>,
    module: super::hir::ModuleId,
    decl: &'a ast::SceneDecl,
    mut desc: SceneDesc,
) -> SceneDesc {
    let src = cx.src;
    let base_dir = src[module.index()].path.as_deref().and_then(|p| p.parent());
    let mut ck = Checker::new(cx, module, Mode::Scene);
    ck.base_dir = base_dir;
    let (mut settings, mut camera, mut background) = (None, None, None);
    // Where `max_rays_per_hit` was written, if it was.
    let mut spawn_setting = None;
    let mut names: Vec<(&str, Span)> = Vec::new();
    // Parallel to `desc.lights`: each light's name, if given.
    let mut light_names: Vec<Option<String>> = Vec::new();
    let mut animate = Vec::new();
    // Names of objects and lights that could not be evaluated (already reported).
    let mut broken: Vec<&str> = Vec::new();
    // Whether `frames` was written (else it is derived from the keys).
    let mut frames_written = false;
    for entry in &decl.entries {
        if let ast::SceneEntryKind::Let { name, .. } = &entry.kind {
            ck.later.push((name.name.as_str(), name.span));
        }
    }
    ck.later.reverse();
    for entry in &decl.entries {
        match &entry.kind {
            ast::SceneEntryKind::Settings(fields) => {
                if once(
                    &mut ck,
                    &mut settings,
                    entry_head(entry.span, 8),
                    "`settings`",
                ) {
                    (desc.settings, spawn_setting) = check_settings(&mut ck, fields);
                    frames_written = fields.iter().any(|f| f.name.name == "frames");
                }
            }
            ast::SceneEntryKind::Camera(e) => {
                if once(
                    &mut ck,
                    &mut camera,
                    entry_head(entry.span, 6),
                    "the camera",
                ) {
                    desc.camera = instance(&mut ck, *e, Role::Camera);
                    if let Some(cam) = &desc.camera {
                        let ast = ck.ast;
                        let field_span = |name: &str| struct_field_span(ast, *e, name);
                        for err in super::limits::camera(&ck.cx.p, cam, &field_span) {
                            ck.err(err);
                        }
                    }
                }
            }
            ast::SceneEntryKind::Background(e) => {
                if once(
                    &mut ck,
                    &mut background,
                    entry_head(entry.span, 10),
                    "the background",
                ) {
                    desc.background = instance(&mut ck, *e, Role::Background);
                }
            }
            ast::SceneEntryKind::Let { name, value } => {
                ck.later.pop();
                let id = ck.expr(*value, None);
                let ty = ck.ty(id);
                let v = ck.eval_const(id);
                ck.scopes.push(name.name.as_str(), Binding::Value(ty, v));
            }
            ast::SceneEntryKind::Object { name, fields } => {
                if let Some(n) = name {
                    match names.iter().find(|(x, _)| *x == n.name) {
                        Some((_, first)) => ck.err(SceneError::DuplicateEntry {
                            span: n.span,
                            first: *first,
                            what: format!("object `{}`", n.name),
                        }),
                        None => names.push((n.name.as_str(), n.span)),
                    }
                }
                match object(&mut ck, name.as_ref(), fields, entry.span) {
                    Some(o) => desc.objects.push(o),
                    None => broken.extend(name.as_ref().map(|n| n.name.as_str())),
                }
            }
            ast::SceneEntryKind::Light { name, value } => {
                if let Some(n) = name {
                    match names.iter().find(|(x, _)| *x == n.name) {
                        Some((_, first)) => ck.err(SceneError::DuplicateEntry {
                            span: n.span,
                            first: *first,
                            what: format!("the name `{}`", n.name),
                        }),
                        None => names.push((n.name.as_str(), n.span)),
                    }
                }
                match instance(&mut ck, *value, Role::Light) {
                    Some(l) => {
                        desc.lights.push(l);
                        light_names.push(name.as_ref().map(|n| n.name.clone()));
                    }
                    None => broken.extend(name.as_ref().map(|n| n.name.as_str())),
                }
            }
            ast::SceneEntryKind::Animate { target, motion } => {
                animate.push(super::animation::Entry {
                    target,
                    motion,
                    span: entry.span,
                });
            }
            ast::SceneEntryKind::Model {
                path,
                path_span,
                fields,
            } => {
                let mut transform = IDENTITY;
                for f in known_fields(&mut ck, fields, "model field", MODEL_FIELDS) {
                    transform = check_transform(&mut ck, f.value).unwrap_or(IDENTITY);
                }
                let path = match base_dir {
                    Some(d) => d.join(path),
                    None => std::path::PathBuf::from(path),
                };
                desc.models.push(Model {
                    path,
                    transform,
                    span: *path_span,
                });
            }
            ast::SceneEntryKind::Error => {}
        }
    }
    let names = super::animation::Names {
        lights: &light_names,
        broken: &broken,
    };
    super::animation::check(&mut ck, &mut desc, &names, &animate);
    if !frames_written {
        desc.settings.frames = super::animation::derived_frames(&desc);
    }
    if desc.settings.max_depth > 0 {
        let mut warned = Vec::new();
        for o in &desc.objects {
            let m = o.material.struct_id;
            if warned.contains(&m) {
                continue;
            }
            warned.push(m);
            let s = desc.settings.max_rays_per_hit;
            let w = super::limits::spawn_over_limit(&ck.cx.p, m, s, o.material.span, spawn_setting);
            if let Some(w) = w {
                ck.err(w);
            }
        }
    }
    if camera.is_none() && desc.models.is_empty() {
        ck.err(SceneError::MissingEntry {
            span: decl.name.span,
            what: "camera",
            place: format!("scene `{}`", decl.name.name),
        });
    }
    desc
}

/// The fields among `fields` whose names are in `known` (E0701 for others, E0408 for repeats).
fn known_fields<'a>(
    ck: &mut Checker,
    fields: &'a [ast::FieldInit],
    place: &'static str,
    known: &'static [&'static str],
) -> Vec<&'a ast::FieldInit> {
    known_fields_counting(ck, fields, place, known).0
}

/// As [`known_fields`], also saying whether an unknown field was written.
fn known_fields_counting<'a>(
    ck: &mut Checker,
    fields: &'a [ast::FieldInit],
    place: &'static str,
    known: &'static [&'static str],
) -> (Vec<&'a ast::FieldInit>, bool) {
    let mut out: Vec<&ast::FieldInit> = Vec::new();
    let mut unknown = false;
    for f in fields {
        if !known.contains(&f.name.name.as_str()) {
            ck.err(SceneError::UnknownEntry {
                span: f.name.span,
                name: f.name.name.clone(),
                place,
                known,
            });
            ck.expr(f.value, None);
            unknown = true;
            continue;
        }
        if let Some(first) = out.iter().find(|x| x.name.name == f.name.name) {
            ck.err(ExprError::DuplicateField {
                span: f.name.span,
                first: first.name.span,
                name: f.name.name.clone(),
            });
            continue;
        }
        out.push(f);
    }
    (out, unknown)
}

/// The span of the value of field `name` in the struct literal `e` (through parentheses), if it
/// is one and the field is written.
fn struct_field_span(ast: &ast::Module, e: ast::ExprId, name: &str) -> Option<Span> {
    match &ast.exprs[e].kind {
        ast::ExprKind::Paren(inner) => struct_field_span(ast, *inner, name),
        ast::ExprKind::StructLit { fields, .. } => fields
            .iter()
            .find(|f| f.name.name == name)
            .map(|f| ast.exprs[f.value].span),
        _ => None,
    }
}

/// The settings, and where `max_rays_per_hit` was written (for W0004).
fn check_settings(ck: &mut Checker, fields: &[ast::FieldInit]) -> (Settings, Option<Span>) {
    let mut s = Settings::default();
    let mut spawn_setting = None;
    for f in known_fields(ck, fields, "setting", SETTINGS) {
        let id = ck.expect(f.value, TypeTable::U32);
        let v = match ck.eval_const(id) {
            ConstValue::Scalar(super::hir::Scalar::U32(v)) => v,
            _ => continue,
        };
        let (key, lo, hi, slot): (&'static str, u32, u32, &mut u32) = match f.name.name.as_str() {
            "width" => ("width", 1, MAX_IMAGE_SIDE, &mut s.width),
            "height" => ("height", 1, MAX_IMAGE_SIDE, &mut s.height),
            "samples" => ("samples", 1, MAX_SAMPLES, &mut s.samples),
            "max_depth" => ("max_depth", 0, 64, &mut s.max_depth),
            "max_rays_per_hit" => ("max_rays_per_hit", 1, 64, &mut s.max_rays_per_hit),
            "roulette_depth" => ("roulette_depth", 0, 64, &mut s.roulette_depth),
            "exec" => ("exec", 0, 2, &mut s.exec),
            "fps" => ("fps", 1, MAX_FPS, &mut s.fps),
            "frames" => ("frames", 1, MAX_FRAMES, &mut s.frames),
            _ => ("seed", 0, u32::MAX, &mut s.seed),
        };
        if v < lo || v > hi {
            let span = ck.span(id);
            ck.err(SceneError::SettingRange {
                span,
                key,
                value: v,
                lo,
                hi,
            });
        } else {
            *slot = v;
            if key == "max_rays_per_hit" {
                spawn_setting = Some(ck.span(id));
            }
        }
    }
    (s, spawn_setting)
}

/// An instance of a struct with `role` (E0702 for another role or a non-struct).
fn instance(ck: &mut Checker, e: ast::ExprId, role: Role) -> Option<Instance> {
    let id = ck.expr(e, None);
    let ty = ck.ty(id);
    if TypeTable::is_error(ty) {
        return None;
    }
    let found_role = ck.cx.p.struct_of(ty).and_then(|s| ck.cx.p.structs[s].role);
    if found_role != Some(role) {
        let span = ck.span(id);
        ck.err(SceneError::WrongRole {
            span,
            expected: Expected::Role(role),
            found: ty,
            found_role,
        });
        return None;
    }
    to_instance(ck.eval_const(id), ck.span(id))
}

fn to_instance(v: ConstValue, span: Span) -> Option<Instance> {
    match v {
        ConstValue::Struct { id, fields } => Some(Instance {
            struct_id: id,
            fields,
            span,
        }),
        _ => None,
    }
}

/// A transform, which the runtime must be able to invert in `f32` (E0708).
fn check_transform(ck: &mut Checker, e: ast::ExprId) -> Option<[[f32; 4]; 4]> {
    let id = ck.expect(e, TypeTable::MAT4);
    match ck.eval_const(id) {
        ConstValue::Matrix { data, .. } => {
            if let Some(err) = super::limits::transform(&data, ck.span(id)) {
                ck.err(err);
                return None;
            }
            Some(data)
        }
        _ => None,
    }
}

fn object(
    ck: &mut Checker,
    name: Option<&ast::Ident>,
    fields: &[ast::FieldInit],
    span: Span,
) -> Option<Object> {
    let (mut geometry, mut material, mut transform) = (None, None, Some(IDENTITY));
    let (mut has_geometry, mut has_material) = (false, false);
    let (known, typo) = known_fields_counting(ck, fields, "object field", OBJECT_FIELDS);
    for f in known {
        match f.name.name.as_str() {
            "geometry" => {
                has_geometry = true;
                geometry = geometry_value(ck, f.value);
            }
            "material" => {
                has_material = true;
                material = instance(ck, f.value, Role::Material);
            }
            _ => transform = check_transform(ck, f.value),
        }
    }
    let place = match name {
        Some(n) => format!("object `{}`", n.name),
        None => "this object".to_string(),
    };
    let at = name.map_or(entry_head(span, 6), |n| n.span);
    for (has, what) in [(has_geometry, "geometry"), (has_material, "material")] {
        // After a misspelt field, the missing one is most likely that typo: say it once.
        if !has && !typo {
            ck.err(SceneError::MissingEntry {
                span: at,
                what,
                place: place.clone(),
            });
        }
    }
    Some(Object {
        name: name.map(|n| n.name.clone()),
        geometry: geometry?,
        material: material?,
        transform: transform?,
        span,
    })
}

fn geometry_value(ck: &mut Checker, e: ast::ExprId) -> Option<Geometry> {
    let id = ck.expr(e, None);
    let ty = ck.ty(id);
    let span = ck.span(id);
    match ck.cx.p.types.get(ty) {
        Type::Error => None,
        Type::Mesh => match ck.eval_const(id) {
            ConstValue::Mesh(m) => Some(Geometry::Mesh(m)),
            _ => None,
        },
        Type::Struct(s) if ck.cx.p.structs[s].role == Some(Role::Geometry) => {
            to_instance(ck.eval_const(id), span).map(Geometry::Custom)
        }
        _ => {
            let found_role = ck.cx.p.struct_of(ty).and_then(|s| ck.cx.p.structs[s].role);
            ck.err(SceneError::WrongRole {
                span,
                expected: Expected::Geometry,
                found: ty,
                found_role,
            });
            None
        }
    }
}

/// The scene to render: the one called `name`, or the only one of the root modules.
pub fn select_scene(p: &Program, name: Option<&str>) -> Result<SceneId, SceneChoiceError> {
    let roots: Vec<(SceneId, &SceneDesc)> = p
        .scenes
        .iter()
        .filter(|(_, s)| p.modules[s.module.index()].is_root)
        .collect();
    match name {
        Some(n) => roots
            .iter()
            .find(|(_, s)| s.name == n)
            .map(|(id, _)| *id)
            .ok_or_else(|| SceneChoiceError::NotFound {
                name: n.to_string(),
                available: roots.iter().map(|(_, s)| s.name.clone()).collect(),
            }),
        None => match roots.as_slice() {
            [] => Err(SceneChoiceError::NoScene),
            [(id, _)] => Ok(*id),
            _ => Err(SceneChoiceError::Ambiguous {
                scenes: roots
                    .iter()
                    .map(|(_, s)| (s.name.clone(), s.span))
                    .collect(),
            }),
        },
    }
}
