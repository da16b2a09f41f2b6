//! Module-level items: collection into the program's arenas, name lookup across modules, type
//! expressions, and the on-demand resolution of struct fields, constants, field defaults and
//! function signatures.
//!
//! Invariants:
//! - Ids follow module load order, then item order, so they are stable for a given input.
//! - Struct fields, constants and defaults are computed at most once each (their [`State`] goes
//!   `Todo → InProgress → Done`); meeting an `InProgress` one again is a cycle, reported once as E0801.
//! - Lookups never allocate on success; suggestions are computed only when a name is missing.

use super::consteval::EvalError;
use super::error::{CallGraphError, ExprError, LimitError, NameError, NameKind};
use super::expr::{Checker, Mode};
use super::hir::{self, ConstValue, Field, ModuleId, StructId};
use super::types::{ScalarKind, Type, TypeId, TypeTable};
use super::{ix, Ctx, Def, Found, ModScope, State, TypeCtor};
use crate::diag::suggest;
use crate::source::Span;
use crate::syntax::ast;
use la_arena::{Idx, RawIdx};

/// Phase 1: gives every item an id and builds each module's scope.
pub(crate) fn collect(cx: &mut Ctx) {
    let src = cx.src;
    for (mi, m) in src.iter().enumerate() {
        let module = ModuleId(mi as u32);
        let mut scope = ModScope::default();
        let mut info = hir::Module {
            file: m.ast.file,
            name: m.name.clone(),
            path: m.path.clone(),
            imports: m.imports.clone(),
            is_prelude: m.is_prelude,
            is_root: m.is_root,
            structs: Vec::new(),
            consts: Vec::new(),
            functions: Vec::new(),
            scenes: Vec::new(),
        };
        for item in &m.ast.items {
            let (name, def) = match &item.kind {
                ast::ItemKind::Struct(s) => {
                    let id = cx.p.structs.alloc(hir::Struct {
                        name: s.name.name.clone(),
                        module,
                        span: s.name.span,
                        doc: item.doc.clone(),
                        role: None,
                        fields: Vec::new(),
                        programs: Vec::new(),
                    });
                    cx.structs_ast.push((module, item, s));
                    cx.fields_state.push(State::Todo);
                    cx.defaults_state.push(State::Todo);
                    info.structs.push(id);
                    (&s.name, Def::Struct(id))
                }
                ast::ItemKind::Const(c) => {
                    let id = cx.p.consts.alloc(hir::Const {
                        name: c.name.name.clone(),
                        module,
                        ty: TypeTable::ERROR,
                        value: ConstValue::Error,
                        span: c.name.span,
                    });
                    cx.consts_ast.push((module, c));
                    cx.const_state.push(State::Todo);
                    info.consts.push(id);
                    (&c.name, Def::Const(id))
                }
                ast::ItemKind::Fn(f) => {
                    let id = cx.p.functions.alloc(hir::Function {
                        name: f.name.name.clone(),
                        module,
                        span: f.name.span,
                        doc: item.doc.clone(),
                        params: Vec::new(),
                        ret: TypeTable::VOID,
                        body: hir::Body::default(),
                        block: hir::Block::default(),
                        program: None,
                        callees: Vec::new(),
                    });
                    cx.fns_ast.push((module, item, f));
                    cx.sig_state.push(State::Todo);
                    cx.sigs.push(super::Sig {
                        params: Vec::new(),
                        ret: TypeTable::ERROR,
                        span: f.name.span,
                    });
                    info.functions.push(id);
                    (&f.name, Def::Fn(id))
                }
                ast::ItemKind::Scene(s) => {
                    let id = cx.p.scenes.alloc(hir::SceneDesc {
                        name: s.name.name.clone(),
                        module,
                        span: s.name.span,
                        settings: hir::Settings::default(),
                        camera: None,
                        background: None,
                        objects: Vec::new(),
                        lights: Vec::new(),
                        models: Vec::new(),
                        animation: Vec::new(),
                    });
                    cx.scenes_ast.push((module, s));
                    info.scenes.push(id);
                    (&s.name, Def::Scene(id))
                }
                ast::ItemKind::Error => continue,
            };
            if let Some((_, first)) = scope.items.get(name.name.as_str()) {
                cx.err(NameError::Duplicate {
                    span: name.span,
                    first: *first,
                    name: name.name.clone(),
                });
            } else {
                scope.items.insert(name.name.as_str(), (def, name.span));
            }
        }
        cx.scopes.push(scope);
        cx.p.modules.push(info);
    }
    find_framework(cx);
}

fn find_framework(cx: &mut Ctx) {
    let Some(p) = cx.prelude else { return };
    let get = |name: &str| match cx.scopes[p.index()].items.get(name) {
        Some((Def::Struct(s), _)) => Some(*s),
        _ => None,
    };
    cx.p.framework = hir::Framework {
        ray: get("Ray"),
        hit: get("Hit"),
        intersection: get("Intersection"),
        aabb: get("Aabb"),
        light_sample: get("LightSample"),
        bvh_node: get("BvhNode"),
        triangle: get("Triangle"),
    };
}

/// The built-in type called `name`.
pub(crate) fn builtin_type(name: &str) -> Option<TypeCtor> {
    let scalar = |c: char| match c {
        'f' => Some(ScalarKind::F32),
        'i' => Some(ScalarKind::I32),
        'u' => Some(ScalarKind::U32),
        'b' => Some(ScalarKind::Bool),
        _ => None,
    };
    let dim = |c: u8| (b'2'..=b'4').contains(&c).then_some(c - b'0');
    Some(match name {
        "bool" => TypeCtor::Scalar(ScalarKind::Bool),
        "i32" => TypeCtor::Scalar(ScalarKind::I32),
        "u32" => TypeCtor::Scalar(ScalarKind::U32),
        "f32" => TypeCtor::Scalar(ScalarKind::F32),
        "texture" => TypeCtor::Texture,
        "mesh" => TypeCtor::Mesh,
        "string" => TypeCtor::String,
        "array" => TypeCtor::Array,
        "bitcast" => TypeCtor::Bitcast,
        _ => {
            let b = name.as_bytes();
            if let Some(rest) = name.strip_prefix("vec") {
                let size = dim(*rest.as_bytes().first()?)?;
                match rest.len() {
                    1 => TypeCtor::Vector { size, scalar: None },
                    2 => TypeCtor::Vector {
                        size,
                        scalar: Some(scalar(rest[1..].chars().next()?)?),
                    },
                    _ => return None,
                }
            } else if name.starts_with("mat") && (6..=7).contains(&b.len()) && b[4] == b'x' {
                let (cols, rows) = (dim(b[3])?, dim(b[5])?);
                match b.get(6) {
                    None => TypeCtor::Matrix {
                        cols,
                        rows,
                        short: false,
                    },
                    Some(b'f') => TypeCtor::Matrix {
                        cols,
                        rows,
                        short: true,
                    },
                    Some(_) => return None,
                }
            } else {
                return None;
            }
        }
    })
}

/// Every built-in type name (for suggestions).
const BUILTIN_TYPE_NAMES: &[&str] = &[
    "bool", "i32", "u32", "f32", "vec2f", "vec3f", "vec4f", "vec2i", "vec3i", "vec4i", "vec2u",
    "vec3u", "vec4u", "vec2b", "vec3b", "vec4b", "mat2x2f", "mat3x3f", "mat4x4f", "mat2x3f",
    "mat2x4f", "mat3x2f", "mat3x4f", "mat4x2f", "mat4x3f", "array", "texture", "mesh",
];

impl<'a> Ctx<'a> {
    /// Looks `name` up at module level in `module` (own items, direct imports, prelude, built-ins).
    pub fn lookup(&self, module: ModuleId, name: &str) -> Found {
        let m = module.index();
        if let Some((d, _)) = self.scopes[m].items.get(name) {
            return Found::Def(*d);
        }
        let mut hit: Option<(ModuleId, Def, Span)> = None;
        for &imp in &self.src[m].imports {
            if let Some((d, s)) = self.scopes[imp.index()].items.get(name) {
                match hit {
                    Some((pm, pd, ps)) if pd != *d => {
                        return Found::Ambiguous([(pm, ps), (imp, *s)]);
                    }
                    Some(_) => {}
                    None => hit = Some((imp, *d, *s)),
                }
            }
        }
        if let Some((_, d, _)) = hit {
            return Found::Def(d);
        }
        if let Some(p) = self.prelude {
            if p != module {
                if let Some((d, _)) = self.scopes[p.index()].items.get(name) {
                    return Found::Def(*d);
                }
            }
        }
        if let Some(t) = builtin_type(name) {
            return Found::Type(t);
        }
        match super::builtins::Builtin::from_name(name) {
            Some(b) => Found::Builtin(b),
            None => Found::None,
        }
    }

    /// The closest module-level name to `name` visible in `module`, plus `extra` (locals).
    pub fn suggest<'n>(
        &'n self,
        module: ModuleId,
        name: &str,
        extra: impl Iterator<Item = &'n str>,
    ) -> Option<String> {
        let m = module.index();
        let own = self.scopes[m].items.keys().copied();
        let imported = self.src[m]
            .imports
            .iter()
            .chain(self.prelude.iter())
            .flat_map(|i| self.scopes[i.index()].items.keys().copied());
        let builtins = super::builtins::TABLE.iter().map(|b| b.name);
        suggest::closest(
            name,
            extra
                .chain(own)
                .chain(imported)
                .chain(builtins)
                .chain(BUILTIN_TYPE_NAMES.iter().copied()),
        )
        .map(str::to_string)
    }

    /// Reports a failed lookup: E0303 for a missing name, E0305 for an ambiguous one.
    pub fn report_lookup(&mut self, module: ModuleId, ident: &ast::Ident, found: Found) {
        match found {
            Found::Ambiguous([(m1, s1), (m2, s2)]) => {
                let err = NameError::Ambiguous {
                    span: ident.span,
                    name: ident.name.clone(),
                    modules: [
                        self.src[m1.index()].name.clone(),
                        self.src[m2.index()].name.clone(),
                    ],
                    defs: [s1, s2],
                };
                self.err(err);
            }
            _ => self.undefined(module, ident, &[]),
        }
    }

    /// E0303 for `ident`, suggesting a close name (`locals` included) or the module declaring it.
    pub fn undefined(&mut self, module: ModuleId, ident: &ast::Ident, locals: &[&str]) {
        let suggestion = self.suggest(module, &ident.name, locals.iter().copied());
        let elsewhere = self
            .scopes
            .iter()
            .position(|s| s.items.contains_key(ident.name.as_str()))
            .map(|m| self.src[m].name.clone());
        self.err(NameError::Undefined {
            span: ident.span,
            name: ident.name.clone(),
            suggestion,
            elsewhere,
        });
    }

    /// Resolves a type expression written in `module`.
    pub fn resolve_type(&mut self, module: ModuleId, ty: ast::TyId) -> TypeId {
        let ast = self.module_ast(module);
        let te = &ast.types[ty];
        let ast::TypeExprKind::Named { name, generics } = &te.kind else {
            return TypeTable::ERROR;
        };
        let found = self.lookup(module, &name.name);
        match found {
            Found::Def(Def::Struct(s)) => {
                if !generics.is_empty() {
                    self.bad_generics(te.span, &name.name, "no generic arguments");
                }
                self.p.types.intern(Type::Struct(s))
            }
            Found::Def(def) => {
                let kind = match def {
                    Def::Fn(_) => NameKind::Function,
                    Def::Const(_) => NameKind::Const,
                    _ => NameKind::Scene,
                };
                self.err(NameError::NotAType {
                    span: name.span,
                    name: name.name.clone(),
                    kind,
                });
                TypeTable::ERROR
            }
            Found::Builtin(_) | Found::Type(TypeCtor::Bitcast) => {
                self.err(NameError::NotAType {
                    span: name.span,
                    name: name.name.clone(),
                    kind: NameKind::Builtin,
                });
                TypeTable::ERROR
            }
            Found::Type(ctor) => self.builtin_type_expr(module, ctor, name, generics, te.span),
            Found::None | Found::Ambiguous(_) => {
                self.report_lookup(module, name, found);
                TypeTable::ERROR
            }
        }
    }

    fn bad_generics(&mut self, span: Span, name: &str, expected: &'static str) {
        self.err(NameError::BadGenerics {
            span,
            name: name.to_string(),
            expected,
        });
    }

    /// A generic argument that must be a type.
    fn generic_type(&mut self, module: ModuleId, arg: &ast::GenericArg) -> Option<TypeId> {
        match arg {
            ast::GenericArg::Type(t) => Some(self.resolve_type(module, *t)),
            ast::GenericArg::Expr(_) => None,
        }
    }

    fn builtin_type_expr(
        &mut self,
        module: ModuleId,
        ctor: TypeCtor,
        name: &ast::Ident,
        generics: &[ast::GenericArg],
        span: Span,
    ) -> TypeId {
        let scalar_arg = |cx: &mut Ctx, g: &[ast::GenericArg]| -> Option<Option<ScalarKind>> {
            let [arg] = g else { return None };
            let t = cx.generic_type(module, arg)?;
            if TypeTable::is_error(t) {
                return Some(None);
            }
            match cx.p.types.get(t) {
                Type::Scalar(k) => Some(Some(k)),
                _ => None,
            }
        };
        match ctor {
            TypeCtor::Scalar(k) if generics.is_empty() => TypeTable::scalar(k),
            TypeCtor::Texture if generics.is_empty() => TypeTable::TEXTURE,
            TypeCtor::Mesh if generics.is_empty() => TypeTable::MESH,
            TypeCtor::String if generics.is_empty() => TypeTable::STRING,
            TypeCtor::Vector {
                size,
                scalar: Some(k),
            } if generics.is_empty() => self.p.types.scalar_or_vector(size, k),
            TypeCtor::Vector { size, scalar: None } => match scalar_arg(self, generics) {
                Some(Some(k)) => self.p.types.scalar_or_vector(size, k),
                Some(None) => TypeTable::ERROR,
                None => {
                    self.bad_generics(span, &name.name, "one scalar type, as in `vec3<f32>`");
                    TypeTable::ERROR
                }
            },
            TypeCtor::Matrix { cols, rows, short } => {
                let ok = if short {
                    generics.is_empty()
                } else {
                    matches!(
                        scalar_arg(self, generics),
                        Some(Some(ScalarKind::F32)) | Some(None)
                    )
                };
                if ok {
                    self.p.types.intern(Type::Matrix { cols, rows })
                } else {
                    self.bad_generics(span, &name.name, "`<f32>` (matrices are of `f32`)");
                    TypeTable::ERROR
                }
            }
            TypeCtor::Array => {
                let [elem, size] = generics else {
                    self.bad_generics(
                        span,
                        "array",
                        "an element type and a size, as in `array<f32, 4>`",
                    );
                    return TypeTable::ERROR;
                };
                let Some(elem) = self.generic_type(module, elem) else {
                    self.bad_generics(
                        span,
                        "array",
                        "an element type first, as in `array<f32, 4>`",
                    );
                    return TypeTable::ERROR;
                };
                let len = self.array_size(module, size);
                match len {
                    Some(len)
                        if !TypeTable::is_error(elem) && self.check_array_size(elem, len, span) =>
                    {
                        self.p.types.intern(Type::Array { elem, len })
                    }
                    _ => TypeTable::ERROR,
                }
            }
            _ => {
                self.bad_generics(span, &name.name, "no generic arguments");
                TypeTable::ERROR
            }
        }
    }

    /// The size argument of `array<T, N>`: a positive `i32`/`u32` constant (E0410).
    pub fn array_size(&mut self, module: ModuleId, arg: &ast::GenericArg) -> Option<u32> {
        let ast = self.module_ast(module);
        let (span, ty, value) = match arg {
            // A bare name in a generic list parses as a type; as a size it names a constant.
            ast::GenericArg::Type(t) => {
                let te = &ast.types[*t];
                let ast::TypeExprKind::Named { name, generics } = &te.kind else {
                    return None;
                };
                match self.lookup(module, &name.name) {
                    Found::Def(Def::Const(c)) if generics.is_empty() => {
                        let ty = self.ensure_const(c, name.span);
                        (te.span, ty, self.p.consts[c].value.clone())
                    }
                    _ => {
                        let ty = self.resolve_type(module, *t);
                        if !TypeTable::is_error(ty) {
                            self.err(ExprError::BadArraySize {
                                span: te.span,
                                found: ty,
                                value: None,
                            });
                        }
                        return None;
                    }
                }
            }
            ast::GenericArg::Expr(e) => {
                let span = ast.exprs[*e].span;
                let mut ck = Checker::new(self, module, Mode::Const("an array size"));
                let id = ck.expr(*e, None);
                let ty = ck.body.exprs[id].ty;
                match ck.try_eval(id) {
                    Ok(v) => (span, ty, v),
                    Err(EvalError::Silent) => return None,
                    Err(EvalError::TooLarge { span, scalars }) => {
                        ck.err(LimitError::ConstTooLarge { span, scalars });
                        return None;
                    }
                    Err(EvalError::NotConst { .. } | EvalError::NonFinite { .. }) => {
                        (span, ty, ConstValue::Error)
                    }
                }
            }
        };
        if TypeTable::is_error(ty) {
            return None;
        }
        let v = match value {
            ConstValue::Scalar(hir::Scalar::I32(i)) => Some(i64::from(i)),
            ConstValue::Scalar(hir::Scalar::U32(u)) => Some(i64::from(u)),
            _ => None,
        };
        match v {
            Some(n) if n > 0 => Some(n as u32),
            _ => {
                self.err(ExprError::BadArraySize {
                    span,
                    found: ty,
                    value: v,
                });
                None
            }
        }
    }

    /// Resolves the fields of struct `s` (once).
    pub fn ensure_fields(&mut self, s: StructId) {
        let i = ix(s);
        if self.fields_state[i] != State::Todo {
            return;
        }
        self.fields_state[i] = State::InProgress;
        let (module, _, decl) = self.structs_ast[i];
        let mut fields: Vec<Field> = Vec::with_capacity(decl.fields.len());
        for f in &decl.fields {
            if let Some(first) = fields.iter().find(|x| x.name == f.name.name) {
                let first = first.span;
                self.err(NameError::Duplicate {
                    span: f.name.span,
                    first,
                    name: f.name.name.clone(),
                });
                continue;
            }
            let ty = self.resolve_type(module, f.ty);
            fields.push(Field {
                name: f.name.name.clone(),
                ty,
                default: None,
                span: f.name.span,
                doc: f.doc.clone(),
            });
        }
        self.p.structs[s].fields = fields;
        self.fields_state[i] = State::Done;
        let ty = self.p.types.intern(Type::Struct(s));
        let bytes = self.type_size(ty);
        if bytes > super::sizes::MAX_TYPE_BYTES {
            let span = self.p.structs[s].span;
            self.err(LimitError::TypeTooLarge { span, ty, bytes });
        }
    }

    /// The type of constant `c`, evaluating it first if needed. `use_span` is where it is used (for
    /// the cycle diagnostic).
    pub fn ensure_const(&mut self, c: hir::ConstId, use_span: Span) -> TypeId {
        let i = ix(c);
        match self.const_state[i] {
            State::Done => return self.p.consts[c].ty,
            State::InProgress => {
                let start = self.const_stack.iter().position(|x| *x == c).unwrap_or(0);
                let mut cycle: Vec<String> = self.const_stack[start..]
                    .iter()
                    .map(|x| self.p.consts[*x].name.clone())
                    .collect();
                cycle.push(self.p.consts[c].name.clone());
                self.err(CallGraphError::Recursion {
                    span: use_span,
                    cycle,
                    what: "constant",
                });
                return TypeTable::ERROR;
            }
            State::Todo => {}
        }
        self.const_state[i] = State::InProgress;
        self.const_stack.push(c);
        let (module, decl) = self.consts_ast[i];
        let declared = match decl.ty {
            Some(t) => {
                let ty = self.resolve_type(module, t);
                self.forbid_string(ty, self.module_ast(module).types[t].span);
                Some(ty)
            }
            None => None,
        };
        let mut ck = Checker::new(self, module, Mode::Const("the value of a constant"));
        let id = match declared {
            Some(t) => ck.expect(decl.value, t),
            None => ck.expr(decl.value, None),
        };
        let ty = declared.unwrap_or(ck.body.exprs[id].ty);
        let value = ck.eval_const(id);
        self.const_stack.pop();
        self.p.consts[c].ty = ty;
        self.p.consts[c].value = value;
        self.const_state[i] = State::Done;
        ty
    }

    /// Evaluates the defaults of struct `s` (once). False if they depend on themselves (reported).
    pub fn ensure_defaults(&mut self, s: StructId, use_span: Span) -> bool {
        let i = ix(s);
        match self.defaults_state[i] {
            State::Done => return true,
            State::InProgress => {
                let name = self.p.structs[s].name.clone();
                self.err(CallGraphError::Recursion {
                    span: use_span,
                    cycle: vec![name.clone(), name],
                    what: "struct",
                });
                return false;
            }
            State::Todo => {}
        }
        self.ensure_fields(s);
        self.defaults_state[i] = State::InProgress;
        let (module, _, decl) = self.structs_ast[i];
        for f in &decl.fields {
            let Some(default) = f.default else { continue };
            let Some(fi) = self.p.structs[s].field_index(&f.name.name) else {
                continue;
            };
            if self.p.structs[s].fields[fi].span != f.name.span {
                continue; // a duplicate field, already reported
            }
            let ty = self.p.structs[s].fields[fi].ty;
            let mut ck = Checker::new(self, module, Mode::Const("a field default"));
            let id = ck.expect(default, ty);
            let value = ck.eval_const(id);
            self.p.structs[s].fields[fi].default = Some(value);
        }
        self.defaults_state[i] = State::Done;
        true
    }

    /// E0413 for `string` outside scenes.
    pub fn forbid_string(&mut self, ty: TypeId, span: Span) {
        if self.contains_string(ty) {
            self.err(ExprError::TypeNotAllowed {
                span,
                ty,
                context: "outside scenes (strings are only asset paths)",
            });
        }
    }

    /// Whether a type is or contains `string`.
    pub fn contains_string(&self, ty: TypeId) -> bool {
        match self.p.types.get(ty) {
            Type::String => true,
            Type::Array { elem, .. } => self.contains_string(elem),
            _ => false,
        }
    }
}

/// Phase 2: every struct's fields, then containment cycles.
pub(crate) fn resolve_structs(cx: &mut Ctx) {
    let ids: Vec<StructId> = cx.p.structs.iter().map(|(id, _)| id).collect();
    for &s in &ids {
        cx.ensure_fields(s);
        let (module, _, decl) = cx.structs_ast[ix(s)];
        if decl.fields.is_empty() {
            let st = &cx.p.structs[s];
            let (span, name) = (st.span, st.name.clone());
            cx.err(ExprError::EmptyStruct { span, name });
        }
        let plain = cx.structs_ast[ix(s)]
            .1
            .attrs
            .iter()
            .all(|a| hir::Role::from_name(&a.name.name).is_none());
        if plain {
            for (f, fd) in cx.p.structs[s].fields.clone().iter().zip(&decl.fields) {
                let span = cx.module_ast(module).types[fd.ty].span;
                cx.forbid_string(f.ty, span);
            }
        }
    }
    // Containment cycles: a struct may not contain itself by value.
    let mut state = vec![State::Todo; ids.len()];
    let mut stack: Vec<StructId> = Vec::new();
    for &s in &ids {
        containment_dfs(cx, s, &mut state, &mut stack);
    }
}

fn struct_in(types: &TypeTable, ty: TypeId) -> Option<StructId> {
    match types.get(ty) {
        Type::Struct(s) => Some(s),
        Type::Array { elem, .. } => struct_in(types, elem),
        _ => None,
    }
}

fn containment_dfs(cx: &mut Ctx, s: StructId, state: &mut [State], stack: &mut Vec<StructId>) {
    if state[ix(s)] != State::Todo {
        return;
    }
    state[ix(s)] = State::InProgress;
    stack.push(s);
    let (module, _, decl) = cx.structs_ast[ix(s)];
    let fields: Vec<(TypeId, Span)> = cx.p.structs[s]
        .fields
        .iter()
        .zip(&decl.fields)
        .map(|(f, fd)| (f.ty, cx.module_ast(module).types[fd.ty].span))
        .collect();
    for (ty, span) in fields {
        let Some(inner) = struct_in(&cx.p.types, ty) else {
            continue;
        };
        match state[ix(inner)] {
            State::InProgress => {
                let start = stack.iter().position(|x| *x == inner).unwrap_or(0);
                let mut cycle: Vec<String> = stack[start..]
                    .iter()
                    .map(|x| cx.p.structs[*x].name.clone())
                    .collect();
                cycle.push(cx.p.structs[inner].name.clone());
                cx.err(CallGraphError::Recursion {
                    span,
                    cycle,
                    what: "struct",
                });
            }
            State::Todo => containment_dfs(cx, inner, state, stack),
            State::Done => {}
        }
    }
    stack.pop();
    state[ix(s)] = State::Done;
}

/// Phase 3a: every constant.
pub(crate) fn resolve_consts(cx: &mut Ctx) {
    let ids: Vec<hir::ConstId> = cx.p.consts.iter().map(|(id, _)| id).collect();
    for c in ids {
        let span = cx.p.consts[c].span;
        cx.ensure_const(c, span);
    }
}

/// Phase 3b: every struct's field defaults.
pub(crate) fn resolve_defaults(cx: &mut Ctx) {
    let ids: Vec<StructId> = cx.p.structs.iter().map(|(id, _)| id).collect();
    for s in ids {
        let span = cx.p.structs[s].span;
        cx.ensure_defaults(s, span);
    }
}

/// Phase 4: every function's parameter and return types; parameters become the body's first locals.
pub(crate) fn resolve_signatures(cx: &mut Ctx) {
    for i in 0..cx.fns_ast.len() {
        cx.ensure_sig(Idx::from_raw(RawIdx::from_u32(i as u32)));
    }
}

impl Ctx<'_> {
    /// The signature of `f`, resolving it first if needed (a call in an array size or a constant can
    /// need it before phase 4). A signature that depends on itself reads as erroneous.
    pub fn ensure_sig(&mut self, f: hir::FnId) -> &super::Sig {
        let i = ix(f);
        if self.sig_state[i] == State::Todo {
            self.sig_state[i] = State::InProgress;
            self.resolve_sig(f);
            self.sig_state[i] = State::Done;
        }
        &self.sigs[i]
    }

    fn resolve_sig(&mut self, id: hir::FnId) {
        let (module, _, decl) = self.fns_ast[ix(id)];
        let ast = self.module_ast(module);
        let mut body = hir::Body::default();
        let mut params = Vec::with_capacity(decl.params.len());
        for (pi, p) in decl.params.iter().enumerate() {
            if let Some(first) = decl.params[..pi]
                .iter()
                .find(|q| q.name.name == p.name.name)
            {
                self.err(NameError::Duplicate {
                    span: p.name.span,
                    first: first.name.span,
                    name: p.name.name.clone(),
                });
            }
            let ty = self.resolve_type(module, p.ty);
            self.forbid_string(ty, ast.types[p.ty].span);
            params.push(body.locals.alloc(hir::Local {
                name: p.name.name.clone(),
                ty,
                kind: hir::LocalKind::Param,
                span: p.name.span,
            }));
        }
        let ret = match decl.ret {
            Some(t) => {
                let ty = self.resolve_type(module, t);
                self.forbid_string(ty, ast.types[t].span);
                ty
            }
            None => TypeTable::VOID,
        };
        self.sigs[ix(id)] = super::Sig {
            params: params.iter().map(|l| body.locals[*l].ty).collect(),
            ret,
            span: decl.name.span,
        };
        let f = &mut self.p.functions[id];
        f.params = params;
        f.ret = ret;
        f.body = body;
    }
}
