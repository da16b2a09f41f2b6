//! Attributes, struct roles and program signatures (spec/programs.md).
//!
//! A struct takes at most one role (`@camera`, `@geometry`, `@material`, `@light`, `@background`;
//! E0608) and its fields must be storable (E0605). A function takes at most one program attribute; its
//! signature must be exactly the kind's (E0601), its first parameter a struct of the kind's role
//! (E0603), and a struct has at most one program of a kind (E0607). `@ray_generation(samples = N)` is
//! the only attribute with an argument (E0606). Attributes on other items are E0602; unknown names
//! E0203.
//!
//! Invariant: a [`ProgramEntry`] is recorded only for a program whose signature is exactly right, so
//! lowering can rely on the parameter and return types of every entry.

use super::error::{AttrArgError, ProgramError};
use super::expr::{Checker, Mode};
use super::hir::{self, ConstValue, FnId, ProgramEntry, ProgramKind, Role, Scalar, StructId};
use super::types::{ScalarKind, Type, TypeId, TypeTable};
use super::Ctx;
use crate::source::Span;
use crate::syntax::ast;
use la_arena::{Idx, RawIdx};

/// Phase 5: roles, storable fields, program attributes and signatures.
pub(crate) fn check_attributes(cx: &mut Ctx) {
    let structs = cx.structs_ast.clone();
    for (i, (_, item, _)) in structs.iter().enumerate() {
        let id: StructId = Idx::from_raw(RawIdx::from_u32(i as u32));
        struct_attrs(cx, id, item);
    }
    for (i, (module, _, decl)) in cx.structs_ast.clone().into_iter().enumerate() {
        let id: StructId = Idx::from_raw(RawIdx::from_u32(i as u32));
        let Some(role) = cx.p.structs[id].role else {
            continue;
        };
        for (f, fd) in cx.p.structs[id].fields.clone().iter().zip(&decl.fields) {
            if !storable(&cx.p, f.ty) {
                let span = cx.module_ast(module).types[fd.ty].span;
                cx.err(ProgramError::NotStorable {
                    span,
                    ty: f.ty,
                    role,
                });
            }
        }
    }
    let src = cx.src;
    for item in src.iter().flat_map(|m| m.ast.items.iter()) {
        let what = match item.kind {
            ast::ItemKind::Const(_) => "a constant",
            ast::ItemKind::Scene(_) => "a scene",
            _ => continue,
        };
        for a in &item.attrs {
            misplaced(cx, a, what, None);
        }
    }
    let fns = cx.fns_ast.clone();
    for (i, (module, item, decl)) in fns.into_iter().enumerate() {
        let id: FnId = Idx::from_raw(RawIdx::from_u32(i as u32));
        fn_attrs(cx, id, module, item, decl);
    }
}

fn is_known_attr(name: &str) -> bool {
    Role::from_name(name).is_some() || ProgramKind::from_name(name).is_some()
}

fn misplaced(cx: &mut Ctx, a: &ast::Attribute, item: &'static str, hint: Option<&'static str>) {
    if !is_known_attr(&a.name.name) {
        return; // the parser reported it (E0203)
    }
    cx.err(ProgramError::MisplacedAttribute {
        span: a.span,
        attr: a.name.name.clone(),
        item,
        hint,
    });
}

fn no_args(cx: &mut Ctx, a: &ast::Attribute) {
    if let Some(arg) = a.args.first() {
        cx.err(ProgramError::BadAttributeArg {
            span: arg.span,
            attr: a.name.name.clone(),
            reason: AttrArgError::NoArgs,
        });
    }
}

fn struct_attrs(cx: &mut Ctx, id: StructId, item: &ast::Item) {
    let mut first: Option<Span> = None;
    for a in &item.attrs {
        match Role::from_name(&a.name.name) {
            Some(role) => {
                no_args(cx, a);
                match first {
                    Some(f) => cx.err(ProgramError::TwoRoles {
                        span: a.span,
                        first: f,
                    }),
                    None => {
                        first = Some(a.span);
                        cx.p.structs[id].role = Some(role);
                    }
                }
            }
            None => misplaced(
                cx,
                a,
                "a struct",
                Some("program attributes go on functions"),
            ),
        }
    }
}

/// Whether a type may be stored in scene data.
pub(crate) fn storable(p: &hir::Program, ty: TypeId) -> bool {
    storable_in(p, ty, &mut Vec::new())
}

/// [`storable`], with the structs being visited (a struct that contains itself is reported as
/// recursion elsewhere; here it must not recurse forever).
fn storable_in(p: &hir::Program, ty: TypeId, visiting: &mut Vec<hir::StructId>) -> bool {
    match p.types.get(ty) {
        Type::Error
        | Type::Scalar(_)
        | Type::Vector { .. }
        | Type::Matrix { .. }
        | Type::Texture
        | Type::Mesh => true,
        Type::Array { elem, .. } => storable_in(p, elem, visiting),
        Type::Struct(s) => {
            if visiting.contains(&s) {
                return true;
            }
            visiting.push(s);
            let ok = p.structs[s]
                .fields
                .iter()
                .all(|f| storable_in(p, f.ty, visiting));
            visiting.pop();
            ok
        }
        Type::Void | Type::String => false,
    }
}

/// The `samples = N` argument of `@ray_generation`.
fn samples_arg(cx: &mut Ctx, module: hir::ModuleId, a: &ast::Attribute) -> u32 {
    let mut samples = 1;
    for arg in &a.args {
        match &arg.name {
            Some(n) if n.name == "samples" => {}
            Some(n) => {
                cx.err(ProgramError::BadAttributeArg {
                    span: n.span,
                    attr: a.name.name.clone(),
                    reason: AttrArgError::Unknown(n.name.clone()),
                });
                continue;
            }
            None => {
                cx.err(ProgramError::BadAttributeArg {
                    span: arg.span,
                    attr: a.name.name.clone(),
                    reason: AttrArgError::Samples,
                });
                continue;
            }
        }
        let mut ck = Checker::new(cx, module, Mode::Const("an attribute argument"));
        let id = ck.expr(arg.value, Some(ScalarKind::U32));
        let ty = ck.ty(id);
        let value = ck.eval_const(id);
        match value {
            ConstValue::Scalar(Scalar::U32(n)) if n > 0 => samples = n,
            ConstValue::Error if TypeTable::is_error(ty) => {}
            _ => {
                let span = cx.module_ast(module).exprs[arg.value].span;
                cx.err(ProgramError::BadAttributeArg {
                    span,
                    attr: a.name.name.clone(),
                    reason: AttrArgError::Samples,
                });
            }
        }
    }
    samples
}

fn fn_attrs(cx: &mut Ctx, id: FnId, module: hir::ModuleId, item: &ast::Item, decl: &ast::FnDecl) {
    let mut kind: Option<(ProgramKind, Span)> = None;
    let mut samples = 1;
    for a in &item.attrs {
        match ProgramKind::from_name(&a.name.name) {
            Some(k) if kind.is_none() => {
                kind = Some((k, a.span));
                if k == ProgramKind::RayGeneration {
                    samples = samples_arg(cx, module, a);
                } else {
                    no_args(cx, a);
                }
            }
            Some(_) => misplaced(
                cx,
                a,
                "a function that already has a program attribute",
                Some("a function is at most one program"),
            ),
            None => misplaced(cx, a, "a function", Some("role attributes go on structs")),
        }
    }
    let Some((kind, _)) = kind else { return };
    cx.p.functions[id].program = Some(kind);
    check_signature(cx, id, module, decl, kind, samples);
}

/// The parameter types after the first, and the return type, of a program kind.
fn expected_rest(p: &hir::Program, kind: ProgramKind, types: &mut TypeTable) -> Vec<Vec<TypeId>> {
    let st = |s: Option<StructId>, types: &mut TypeTable| match s {
        Some(s) => types.intern(Type::Struct(s)),
        None => TypeTable::ERROR,
    };
    let fw = p.framework;
    let ray = st(fw.ray, types);
    let hit = st(fw.hit, types);
    let (f32_, v3, v2u, u32_) = (
        TypeTable::F32,
        TypeTable::VEC3F,
        TypeTable::VEC2U,
        TypeTable::U32,
    );
    // Each alternative lists the parameters after the first, then the return type last.
    match kind {
        ProgramKind::RayGeneration => vec![vec![v2u, u32_, ray]],
        ProgramKind::Intersection => vec![vec![ray, st(fw.intersection, types)]],
        ProgramKind::Bounds => vec![vec![st(fw.aabb, types)]],
        ProgramKind::AnyHit => vec![vec![ray, hit, TypeTable::BOOL]],
        ProgramKind::ClosestHit => vec![vec![ray, hit, v3], vec![ray, hit, v3, v3]],
        ProgramKind::SecondaryRays => vec![vec![ray, hit, TypeTable::VOID]],
        ProgramKind::Medium => vec![vec![ray, f32_, v3, v3]],
        ProgramKind::Light => vec![vec![v3, v3, st(fw.light_sample, types)]],
        ProgramKind::Miss => vec![vec![ray, v3]],
    }
}

fn check_signature(
    cx: &mut Ctx,
    id: FnId,
    module: hir::ModuleId,
    decl: &ast::FnDecl,
    kind: ProgramKind,
    samples: u32,
) {
    let sig = &cx.sigs[super::ix(id)];
    let (params, ret) = (sig.params.clone(), sig.ret);
    if params.iter().any(|t| TypeTable::is_error(*t)) || TypeTable::is_error(ret) {
        return;
    }
    let ast = cx.module_ast(module);
    // The first parameter decides the struct.
    let first = params.first().copied();
    let struct_id = match first.map(|t| cx.p.types.get(t)) {
        Some(Type::Struct(s)) if cx.p.structs[s].role == Some(kind.role()) => Some(s),
        Some(_) => {
            let t = first.unwrap_or(TypeTable::ERROR);
            let found_role = cx.p.struct_of(t).and_then(|s| cx.p.structs[s].role);
            cx.err(ProgramError::NotRoleStruct {
                span: ast.types[decl.params[0].ty].span,
                kind,
                found: t,
                found_role,
            });
            return;
        }
        None => None,
    };
    let struct_name = match struct_id {
        Some(s) => cx.p.structs[s].name.clone(),
        None => match kind.role() {
            Role::Camera => "C",
            Role::Geometry => "G",
            Role::Material => "M",
            Role::Light => "L",
            Role::Background => "B",
        }
        .to_string(),
    };
    let mut types = std::mem::take(&mut cx.p.types);
    let alts = expected_rest(&cx.p, kind, &mut types);
    cx.p.types = types;
    let mut actual: Vec<TypeId> = params.iter().skip(1).copied().collect();
    actual.push(ret);
    let matched = match struct_id {
        Some(_) => alts.iter().position(|alt| *alt == actual),
        None => None,
    };
    let (Some(s), Some(alt)) = (struct_id, matched) else {
        let found = render_signature(cx, decl, &params, ret);
        cx.err(ProgramError::Signature {
            span: decl.name.span,
            kind,
            struct_name,
            found,
        });
        return;
    };
    if let Some(prev) = cx.p.structs[s].program(kind) {
        let first = cx.p.functions[prev].span;
        let ty = cx.p.types.intern(Type::Struct(s));
        cx.err(ProgramError::DuplicateProgram {
            span: decl.name.span,
            first,
            kind,
            ty,
        });
        return;
    }
    cx.p.structs[s].programs.push((kind, id));
    cx.p.programs.push(ProgramEntry {
        kind,
        func: id,
        struct_id: s,
        samples,
        spawn_bound: 0,
        wants_secondary: kind == ProgramKind::ClosestHit && alt == 1,
        additive_secondary: false,
        absorbs: false,
    });
}

fn render_signature(cx: &Ctx, decl: &ast::FnDecl, params: &[TypeId], ret: TypeId) -> String {
    let ps: Vec<String> = decl
        .params
        .iter()
        .zip(params)
        .map(|(p, t)| format!("{}: {}", p.name.name, cx.p.type_name(*t)))
        .collect();
    let r = if ret == TypeTable::VOID {
        String::new()
    } else {
        format!(" -> {}", cx.p.type_name(ret))
    };
    format!("fn({}){r}", ps.join(", "))
}
