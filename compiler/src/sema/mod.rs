//! Semantic analysis: name resolution, types, constants, programs, scenes and the call graph, from the
//! parsed modules to the typed HIR ([`hir::Program`]).
//!
//! Entry point: [`analyze`]. Its phases, in order (each a function of its own module):
//!
//! 1. [`items::collect`]: every module's items get ids; module scopes are built (E0304).
//! 2. [`items::resolve_structs`]: struct field types (array sizes are constants), struct containment
//!    cycles (E0801), type sizes ([`limits`], E0803).
//! 3. [`items::resolve_consts`] and [`items::resolve_defaults`]: constants and field defaults,
//!    evaluated (E0412, E0801 for cycles). Both are also computed on demand, in whatever order uses
//!    need them; the states in [`Ctx`] make each computed once and detect cycles.
//! 4. [`items::resolve_signatures`]: parameter and return types of every function.
//! 5. [`programs::check_attributes`]: struct roles, program attributes and signatures (E06xx).
//! 6. [`stmt::check_bodies`]: every function body to HIR (E04xx, E05xx, warnings).
//! 7. [`callgraph::analyze`]: recursion (E0801), callee-first order, intrinsics by program kind
//!    (E0604), spawn bounds (E0802), private memory per call chain ([`limits`], E0804).
//! 8. [`scenes::check_scenes`]: scenes to evaluated [`hir::SceneDesc`]s (E07xx).
//!
//! Name lookup follows spec/modules.md: block scopes, then the module's own items, then the items of
//! directly imported modules (two different ones: E0305), then the prelude module and the built-in
//! types and functions.
//!
//! Invariant: an expression of the error type never produces a further diagnostic; every diagnostic
//! comes from a [`error::SemaError`] rendered in `error/`.

mod access;
mod animation;
pub mod builtins;
mod call;
mod callgraph;
pub mod consteval;
mod constmath;
pub mod error;
mod expr;
pub mod hir;
mod items;
pub mod limits;
mod programs;
pub mod scenes;
pub mod sizes;
mod stmt;
pub mod types;

#[cfg(test)]
mod tests;

use crate::source::Span;
use crate::syntax::ast;
use error::SemaError;
use hir::{ConstId, FnId, ModuleId, Program, SceneId, StructId};
use la_arena::Idx;
use std::collections::HashMap;
use std::path::PathBuf;

/// One parsed module, as the driver hands it over.
#[derive(Debug)]
pub struct SourceModule {
    /// The syntax tree.
    pub ast: ast::Module,
    /// The display name.
    pub name: String,
    /// Where it was read from.
    pub path: Option<PathBuf>,
    /// The modules its imports name (those that were found), in order.
    pub imports: Vec<ModuleId>,
    /// Whether it is the prelude.
    pub is_prelude: bool,
    /// Whether it was named as a root.
    pub is_root: bool,
}

/// A module-level definition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Def {
    Struct(StructId),
    Const(ConstId),
    Fn(FnId),
    Scene(SceneId),
}

/// A built-in type name used as a type or a constructor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TypeCtor {
    Scalar(types::ScalarKind),
    Vector {
        size: u8,
        scalar: Option<types::ScalarKind>,
    },
    Matrix {
        cols: u8,
        rows: u8,
        short: bool,
    },
    Array,
    Texture,
    Mesh,
    String,
    Bitcast,
}

/// What a name denotes at module level.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Found {
    Def(Def),
    Builtin(builtins::Builtin),
    Type(TypeCtor),
    Ambiguous([(ModuleId, Span); 2]),
    None,
}

/// Lazy computation state of a constant, a struct's fields or a struct's defaults.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub(crate) enum State {
    #[default]
    Todo,
    InProgress,
    Done,
}

/// A function's parameter and return types, known before bodies are checked.
#[derive(Clone, Debug)]
pub(crate) struct Sig {
    pub params: Vec<types::TypeId>,
    pub ret: types::TypeId,
    pub span: Span,
}

/// The items of one module by name.
#[derive(Default)]
pub(crate) struct ModScope<'a> {
    pub items: HashMap<&'a str, (Def, Span)>,
}

/// The shared state of analysis: the program under construction, the syntax it comes from, the
/// on-demand states and the errors.
pub(crate) struct Ctx<'a> {
    pub src: &'a [SourceModule],
    pub p: Program,
    pub scopes: Vec<ModScope<'a>>,
    pub prelude: Option<ModuleId>,
    pub errors: Vec<SemaError>,
    pub structs_ast: Vec<(ModuleId, &'a ast::Item, &'a ast::StructDecl)>,
    pub consts_ast: Vec<(ModuleId, &'a ast::ConstDecl)>,
    pub fns_ast: Vec<(ModuleId, &'a ast::Item, &'a ast::FnDecl)>,
    pub scenes_ast: Vec<(ModuleId, &'a ast::SceneDecl)>,
    pub fields_state: Vec<State>,
    pub defaults_state: Vec<State>,
    pub const_state: Vec<State>,
    pub const_stack: Vec<ConstId>,
    pub sigs: Vec<Sig>,
    pub sig_state: Vec<State>,
}

/// The index of an arena handle.
pub(crate) fn ix<T>(id: Idx<T>) -> usize {
    u32::from(id.into_raw()) as usize
}

impl<'a> Ctx<'a> {
    pub fn err(&mut self, e: impl Into<SemaError>) {
        self.errors.push(e.into());
    }

    pub fn module_ast(&self, m: ModuleId) -> &'a ast::Module {
        let src: &'a [SourceModule] = self.src;
        &src[m.index()].ast
    }
}

/// Checks every module and builds the HIR. `prelude` is the prelude's index in `modules`, if it was
/// loaded. Returns the program (complete only if no error was reported) and every error and warning.
pub fn analyze(modules: &[SourceModule], prelude: Option<ModuleId>) -> (Program, Vec<SemaError>) {
    let mut cx = Ctx {
        src: modules,
        p: Program::default(),
        scopes: Vec::new(),
        prelude,
        errors: Vec::new(),
        structs_ast: Vec::new(),
        consts_ast: Vec::new(),
        fns_ast: Vec::new(),
        scenes_ast: Vec::new(),
        fields_state: Vec::new(),
        defaults_state: Vec::new(),
        const_state: Vec::new(),
        const_stack: Vec::new(),
        sigs: Vec::new(),
        sig_state: Vec::new(),
    };
    items::collect(&mut cx);
    items::resolve_structs(&mut cx);
    items::resolve_consts(&mut cx);
    items::resolve_defaults(&mut cx);
    items::resolve_signatures(&mut cx);
    programs::check_attributes(&mut cx);
    stmt::check_bodies(&mut cx);
    callgraph::analyze(&mut cx);
    scenes::check_scenes(&mut cx);
    (cx.p, cx.errors)
}
