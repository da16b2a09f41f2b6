//! The errors and warnings of module loading and semantic analysis, and their conversion to
//! [`Diagnostic`]s, in one place: each phase has its own error enum, rendered once, at the edge.
//!
//! Variants carry spans and typed data (types as [`TypeId`]s, built-ins as [`Builtin`]s, program kinds,
//! names); all wording, labels, notes and help lines are decided here, in [`SemaError::to_diagnostic`],
//! which renders types through the program's type table and reads source snippets for help lines such
//! as "convert with `f32(b)`".
//!
//! Layout: [`SemaError`] has one variant per group of errors, each group an enum of its own
//! ([`ModuleError`], [`NameError`], [`ExprError`], [`StmtError`], [`ProgramError`], [`SceneError`],
//! [`CallGraphError`], [`LimitError`], [`Warning`]) with a `From` impl, so a check reports
//! `cx.err(ExprError::Mismatch { … })`. This file holds the types, the shared rendering helpers and
//! the match over the groups; [`expressions`] renders the groups of modules, names and expressions
//! (E0108–E04xx), [`programs`] those of statements, programs, scenes, the call graph and the static
//! limits, and the warnings.
//!
//! Invariants: every variant maps to exactly one code of `diag::codes`; every match from an error
//! variant to its rendering is exhaustive, with no catch-all arm, so a new variant does not compile
//! until it is rendered; an error variant is never created for an operand of the error type (the
//! checker suppresses cascades before it gets here).

mod expressions;
mod programs;

use super::builtins::Builtin;
use super::consteval::NotConst;
use super::hir::{LocalKind, Program, ProgramKind, Role};
use super::types::{ScalarKind, Type, TypeId};
use crate::diag::{codes, Diagnostic};
use crate::source::{FileId, SourceMap, Span};

/// What kind of thing a name denotes (for E0306 and E0414).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NameKind {
    /// A struct.
    Struct,
    /// A built-in type.
    Type,
    /// A function.
    Function,
    /// A built-in function.
    Builtin,
    /// A constant.
    Const,
    /// A local.
    Local,
    /// A scene.
    Scene,
}

impl NameKind {
    pub(super) fn describe(self) -> &'static str {
        match self {
            NameKind::Struct => "struct",
            NameKind::Type => "type",
            NameKind::Function => "function",
            NameKind::Builtin => "built-in function",
            NameKind::Const => "constant",
            NameKind::Local => "variable",
            NameKind::Scene => "scene",
        }
    }
}

/// Why a constructor call is wrong (E0409).
#[derive(Clone, Debug, PartialEq)]
pub enum CtorError {
    /// Components do not add up.
    Count {
        /// How many the type needs.
        expected: u32,
        /// How many were given.
        found: u32,
    },
    /// A component of the wrong scalar type.
    Component {
        /// The element type.
        expected: TypeId,
        /// The component's type.
        found: TypeId,
    },
    /// `S(…)` for a struct `S`.
    Struct,
    /// A conversion between types that do not convert.
    Convert {
        /// The source type.
        from: TypeId,
    },
    /// `bitcast` between types of different sizes, or to/from a non-32-bit type.
    Bitcast {
        /// The source type.
        from: TypeId,
    },
    /// `array(…)` with no elements.
    EmptyArray,
    /// `T(…)` for a type that cannot be constructed (handles, strings).
    NotConstructible,
}

/// Why an attribute argument is wrong (E0606).
#[derive(Clone, Debug, PartialEq)]
pub enum AttrArgError {
    /// The attribute takes no arguments.
    NoArgs,
    /// An argument name that the attribute does not know.
    Unknown(String),
    /// `samples = N` with `N` not a positive `u32` constant.
    Samples,
}

/// Why a loop cannot bound spawned rays (E0802).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unbounded {
    /// Inside `while`.
    While,
    /// Inside `loop`.
    Loop,
    /// Inside a `for` whose bounds are not constant.
    For,
}

/// What a scene expected where it found a value of the wrong role (E0702).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// An instance of a struct with this role.
    Role(Role),
    /// A mesh or a `@geometry` instance.
    Geometry,
}

/// An error of loading a module: reading a file or following its imports (E0108, E0301, E0302).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum ModuleError {
    InvalidUtf8 {
        file: FileId,
        offset: u32,
    },
    ImportNotFound {
        span: Span,
        path: String,
        close: Vec<String>,
    },
    Unreadable {
        span: Span,
        path: String,
        reason: String,
    },
    ImportCycle {
        span: Span,
        chain: Vec<String>,
    },
}

/// An error of name resolution: attributes, scopes, imports, generics and fields (E0203, E0303–E0307, E0413).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum NameError {
    UnknownAttribute {
        span: Span,
        name: String,
    },
    Undefined {
        span: Span,
        name: String,
        suggestion: Option<String>,
        elsewhere: Option<String>,
    },
    DefinedLater {
        span: Span,
        name: String,
        def: Span,
    },
    Duplicate {
        span: Span,
        first: Span,
        name: String,
    },
    Ambiguous {
        span: Span,
        name: String,
        modules: [String; 2],
        defs: [Span; 2],
    },
    NotAValue {
        span: Span,
        name: String,
        kind: NameKind,
    },
    NotAType {
        span: Span,
        name: String,
        kind: NameKind,
    },
    NotAStruct {
        span: Span,
        name: String,
        kind: NameKind,
    },
    BadGenerics {
        span: Span,
        name: String,
        expected: &'static str,
    },
    UnknownField {
        span: Span,
        ty: TypeId,
        field: String,
        suggestion: Option<String>,
        decl: Option<Span>,
    },
}

/// An error of typing an expression (E04xx).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum ExprError {
    Mismatch {
        span: Span,
        expected: TypeId,
        found: TypeId,
    },
    BadOperands {
        span: Span,
        op: &'static str,
        lhs: TypeId,
        rhs: TypeId,
        lhs_span: Span,
        rhs_span: Span,
    },
    BadUnary {
        span: Span,
        op: &'static str,
        ty: TypeId,
    },
    Arity {
        span: Span,
        name: String,
        expected: Vec<usize>,
        found: usize,
        decl: Option<Span>,
    },
    NoOverload {
        span: Span,
        func: Builtin,
        args: Vec<TypeId>,
    },
    BadSwizzle {
        span: Span,
        ty: TypeId,
        swizzle: String,
    },
    NotIndexable {
        span: Span,
        ty: TypeId,
    },
    IndexOutOfRange {
        span: Span,
        index: i64,
        len: u32,
        ty: TypeId,
    },
    MissingFields {
        span: Span,
        ty: TypeId,
        missing: Vec<String>,
        decl: Span,
    },
    DuplicateField {
        span: Span,
        first: Span,
        name: String,
    },
    BadConstructor {
        span: Span,
        ty: TypeId,
        reason: CtorError,
    },
    BadArraySize {
        span: Span,
        found: TypeId,
        value: Option<i64>,
    },
    LiteralRange {
        span: Span,
        ty: TypeId,
    },
    NotConst {
        span: Span,
        what: NotConst,
        context: &'static str,
    },
    SceneOnly {
        span: Span,
        func: Builtin,
    },
    TypeNotAllowed {
        span: Span,
        ty: TypeId,
        context: &'static str,
    },
    /// A struct declared without fields (E0416): WGSL, SPIR-V and the other targets have no
    /// empty structs.
    EmptyStruct {
        span: Span,
        name: String,
    },
    NotCallable {
        span: Span,
        name: String,
        kind: NameKind,
    },
}

/// An error of a statement (E0205, E05xx).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum StmtError {
    AssignImmutable {
        span: Span,
        name: String,
        kind: Option<LocalKind>,
        decl: Span,
    },
    BadAssignTarget {
        span: Span,
        multi_swizzle: bool,
    },
    OutsideLoop {
        span: Span,
        keyword: &'static str,
    },
    MissingReturn {
        span: Span,
        ret: TypeId,
        end: Span,
    },
    ReturnMismatch {
        span: Span,
        expected: Option<TypeId>,
    },
    ConditionNotBool {
        span: Span,
        found: TypeId,
    },
    BadRange {
        span: Span,
        start: TypeId,
        end: TypeId,
    },
}

/// An error of a program or a role struct declaration (E06xx).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum ProgramError {
    Signature {
        span: Span,
        kind: ProgramKind,
        struct_name: String,
        found: String,
    },
    MisplacedAttribute {
        span: Span,
        attr: String,
        item: &'static str,
        hint: Option<&'static str>,
    },
    NotRoleStruct {
        span: Span,
        kind: ProgramKind,
        found: TypeId,
        found_role: Option<Role>,
    },
    IntrinsicNotAllowed {
        span: Span,
        func: Builtin,
        kind: ProgramKind,
        chain: Vec<String>,
        program: Span,
    },
    NotStorable {
        span: Span,
        ty: TypeId,
        role: Role,
    },
    BadAttributeArg {
        span: Span,
        attr: String,
        reason: AttrArgError,
    },
    DuplicateProgram {
        span: Span,
        first: Span,
        kind: ProgramKind,
        ty: TypeId,
    },
    TwoRoles {
        span: Span,
        first: Span,
    },
}

/// An error of a scene (E0701–E0705).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum SceneError {
    UnknownEntry {
        span: Span,
        name: String,
        place: &'static str,
        known: &'static [&'static str],
    },
    WrongRole {
        span: Span,
        expected: Expected,
        found: TypeId,
        found_role: Option<Role>,
    },
    MissingEntry {
        span: Span,
        what: &'static str,
        place: String,
    },
    SettingRange {
        span: Span,
        key: &'static str,
        value: u32,
        lo: u32,
        hi: u32,
    },
    DuplicateEntry {
        span: Span,
        first: Span,
        what: String,
    },
}

/// An error found on the call graph: recursion and unbounded spawns (E0801, E0802).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum CallGraphError {
    Recursion {
        span: Span,
        cycle: Vec<String>,
        what: &'static str,
    },
    UnboundedSpawn {
        span: Span,
        why: Unbounded,
        loop_span: Span,
        program: String,
    },
}

/// A static size limit exceeded (E0803–E0805).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum LimitError {
    /// A type larger than [`crate::sema::sizes::MAX_TYPE_BYTES`].
    TypeTooLarge { span: Span, ty: TypeId, bytes: u64 },
    /// Aggregate locals (with those of the callees, deepest chain) over the private-memory budget.
    PrivateMemory {
        /// The local that crosses the budget, or the call that does.
        span: Span,
        function: String,
        bytes: u64,
        /// The callee whose chain is added, when the call crosses the budget.
        callee: Option<(String, u64)>,
    },
    /// A constant value with more scalars than [`crate::sema::consteval::MAX_CONST_SCALARS`].
    ConstTooLarge { span: Span, scalars: u64 },
}

/// A warning of semantic analysis (W0001–W0003).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum Warning {
    UnusedVariable { span: Span, name: String },
    UnusedValue { span: Span },
    Unreachable { span: Span, cause: Span },
}

/// An error or warning of loading or semantic analysis: one variant per group, each group an enum
/// with its own exhaustive rendering.
#[derive(Clone, Debug, PartialEq)]
pub enum SemaError {
    /// An error of loading a module: reading a file or following its imports (E0108, E0301, E0302).
    Module(ModuleError),
    /// An error of name resolution: attributes, scopes, imports, generics and fields (E0203, E0303–E0307, E0413).
    Name(NameError),
    /// An error of typing an expression (E04xx).
    Expr(ExprError),
    /// An error of a statement (E0205, E05xx).
    Stmt(StmtError),
    /// An error of a program or a role struct declaration (E06xx).
    Program(ProgramError),
    /// An error of a scene (E0701–E0705).
    Scene(SceneError),
    /// An error found on the call graph: recursion and unbounded spawns (E0801, E0802).
    CallGraph(CallGraphError),
    /// A static size limit exceeded (E0803–E0805).
    Limit(LimitError),
    /// A warning of semantic analysis (W0001–W0003).
    Warning(Warning),
    /// A diagnostic built where it was found (the scene value checks of `sema::limits`), error or
    /// warning by its severity.
    Built(Box<crate::diag::Diagnostic>),
}

/// `impl From<Group> for SemaError`, so that a check writes `cx.err(ExprError::Mismatch { … })`.
macro_rules! from_group {
    ($($group:ident => $variant:ident),* $(,)?) => {$(
        impl From<$group> for SemaError {
            fn from(e: $group) -> Self {
                SemaError::$variant(e)
            }
        }
    )*};
}

from_group! {
    ModuleError => Module,
    NameError => Name,
    ExprError => Expr,
    StmtError => Stmt,
    ProgramError => Program,
    SceneError => Scene,
    CallGraphError => CallGraph,
    LimitError => Limit,
    Warning => Warning,
}

pub(super) fn list(items: &[String]) -> String {
    let q: Vec<String> = items.iter().map(|s| format!("`{s}`")).collect();
    match q.len() {
        0 => String::new(),
        1 => q[0].clone(),
        n => format!("{} and {}", q[..n - 1].join(", "), q[n - 1]),
    }
}

/// The expected signature of a program kind, with `S` the struct's name.
pub fn expected_signature(kind: ProgramKind, s: &str) -> String {
    let first = kind.role().name();
    match kind {
        ProgramKind::RayGeneration => format!("fn({first}: {s}, pixel: vec2u, sample: u32) -> Ray"),
        ProgramKind::Intersection => format!("fn({first}: {s}, ray: Ray) -> Intersection"),
        ProgramKind::Bounds => format!("fn({first}: {s}) -> Aabb"),
        ProgramKind::AnyHit => format!("fn({first}: {s}, ray: Ray, hit: Hit) -> bool"),
        ProgramKind::ClosestHit => format!(
            "fn({first}: {s}, ray: Ray, hit: Hit) -> vec3f` or `fn({first}: {s}, ray: Ray, hit: Hit, secondary: vec3f) -> vec3f"
        ),
        ProgramKind::SecondaryRays => format!("fn({first}: {s}, ray: Ray, hit: Hit)"),
        ProgramKind::Medium => {
            format!("fn({first}: {s}, ray: Ray, t: f32, radiance: vec3f) -> vec3f")
        }
        ProgramKind::Light => {
            format!("fn({first}: {s}, position: vec3f, normal: vec3f) -> LightSample")
        }
        ProgramKind::Miss => format!("fn({first}: {s}, ray: Ray) -> vec3f"),
    }
}

pub(super) fn err(code: codes::Code, message: impl Into<String>, span: Span) -> Diagnostic {
    Diagnostic::error(code, message, span)
}

pub(super) struct R<'a> {
    pub(super) p: &'a Program,
    pub(super) src: &'a SourceMap,
}

impl R<'_> {
    pub(super) fn ty(&self, t: TypeId) -> String {
        format!("`{}`", self.p.type_name(t))
    }

    pub(super) fn snippet(&self, span: Span) -> &str {
        if (span.file.0 as usize) < self.src.len() {
            self.src.snippet(span)
        } else {
            ""
        }
    }

    /// "convert with `f32(x)`" when a value of `from` can be converted to `to`.
    pub(super) fn conversion(&self, from: TypeId, to: TypeId, span: Span) -> Option<String> {
        let t = &self.p.types;
        let text = self.snippet(span);
        if text.is_empty() {
            return None;
        }
        let text = if text.contains(' ') {
            format!("({text})")
        } else {
            text.to_string()
        };
        match (t.get(from), t.get(to)) {
            (Type::Scalar(a), Type::Scalar(b)) if a != b => {
                Some(format!("convert with `{}({text})`", b.name()))
            }
            (
                Type::Vector {
                    size: s1,
                    scalar: a,
                },
                Type::Vector {
                    size: s2,
                    scalar: b,
                },
            ) if s1 == s2 && a != b => {
                Some(format!("convert with `{}({text})`", self.p.type_name(to)))
            }
            (Type::Scalar(a), Type::Vector { scalar: b, .. }) if a == b => Some(format!(
                "make a vector with `{}({text})`",
                self.p.type_name(to)
            )),
            (Type::String, Type::Scalar(k)) => Some(format!(
                "write a number such as `{}`",
                match k {
                    ScalarKind::F32 => "1.5",
                    ScalarKind::U32 => "1u",
                    ScalarKind::I32 => "1",
                    ScalarKind::Bool => "true",
                }
            )),
            _ => None,
        }
    }
}

impl SemaError {
    /// Whether this is a warning.
    pub fn is_warning(&self) -> bool {
        match self {
            SemaError::Warning(_) => true,
            SemaError::Built(d) => !d.is_error(),
            SemaError::Module(_)
            | SemaError::Name(_)
            | SemaError::Expr(_)
            | SemaError::Stmt(_)
            | SemaError::Program(_)
            | SemaError::Scene(_)
            | SemaError::CallGraph(_)
            | SemaError::Limit(_) => false,
        }
    }

    /// The diagnostic shown to the user: each group renders its own variants, with one exhaustive
    /// match per group and no catch-all, so a new variant does not compile until it has a rendering.
    pub fn to_diagnostic(&self, p: &Program, src: &SourceMap) -> Diagnostic {
        let r = &R { p, src };
        match self {
            SemaError::Module(e) => e.render(),
            SemaError::Name(e) => e.render(r),
            SemaError::Expr(e) => e.render(r),
            SemaError::Stmt(e) => e.render(r),
            SemaError::Program(e) => e.render(r),
            SemaError::Scene(e) => e.render(r),
            SemaError::CallGraph(e) => e.render(),
            SemaError::Limit(e) => e.render(r),
            SemaError::Warning(e) => e.render(),
            SemaError::Built(d) => (**d).clone(),
        }
    }
}
