//! The typed high-level IR: what semantic analysis produces and lowering to naga IR consumes.
//!
//! A [`Program`] is every module of one compilation (the roots, everything they import and the prelude)
//! flattened into one set of arenas: [`Program::structs`], [`Program::consts`],
//! [`Program::functions`] and [`Program::scenes`]. Ids are stable: they follow the order in which
//! modules were loaded and items were written, so the same input gives the same ids.
//!
//! # Invariants of a program without errors
//!
//! (`driver::Checked::program` is `Some` only when no error was reported; the checker builds the same
//! structures while it works, with [`TypeTable::ERROR`], [`ExprKind::Error`] and [`ConstValue::Error`]
//! standing in for what a diagnostic already covers.)
//!
//! - **Every expression is typed.** [`Expr::ty`] is the resolved type; it is never `ERROR`, and it is
//!   `VOID` only for a call to a function without a return type used as a statement.
//! - **No unresolved names.** A name is a [`LocalId`], a [`ConstId`], a [`FnId`] or a [`Builtin`];
//!   a type is a [`TypeId`] of the program's [`TypeTable`].
//! - **No untyped literals.** Every [`Literal`] has its concrete type (`1` in `x * 1` with `x: f32` is
//!   `Literal::F32(1.0)`); literal range checks are done.
//! - **Nothing implicit.** Struct literals are [`ExprKind::Compose`] with every field in declaration
//!   order (which is also their evaluation order, spec/expressions.md), omitted fields filled with
//!   their default as [`ExprKind::Value`]; a scalar operand of a
//!   vector operator is wrapped in [`ExprKind::Splat`] (the scalar factor of a matrix product is not:
//!   naga multiplies matrices by scalars); a matrix built from scalars is composed of column vectors.
//! - **Structured control flow.** `for` loops stay [`StmtKind::For`] (the end is evaluated once, before
//!   the first iteration); compound assignment stays `(place, op, value)`, whose `op` applied to the
//!   place's and the value's types gives the place's type. Places are locals declared with `var`, or
//!   fields, single components or elements of one.
//! - **Constants are evaluated.** Every [`Const`], field default and scene value is a [`ConstValue`],
//!   computed with GPU semantics (wrapping 32-bit integers, f32 arithmetic).
//! - **Callees come before callers in [`Program::fn_order`].** It is a topological order of the call
//!   graph (which has no cycles: recursion is rejected with E0801), as naga requires. It lists every
//!   function once.
//! - **Programs are exact.** Each [`ProgramEntry`] names a function whose signature is the one its
//!   [`ProgramKind`] demands and a struct whose [`Role`] allows that kind; a struct has at most one
//!   program of each kind; intrinsics are only reachable from the program kinds that may call them; a
//!   `@secondary_rays` program's [`ProgramEntry::spawn_bound`] bounds the rays one call may spawn.
//! - **Evaluation order is the tree's.** Operands, arguments and components are evaluated left to
//!   right as they appear in the HIR; `&&` and `||` short-circuit; the only side effects are calls
//!   (user functions and intrinsics such as `rand` and `spawn`).
//! - **Scenes are values.** Every [`SceneDesc`] holds evaluated instances of role structs; its camera is
//!   present unless a glTF `model` is expected to provide one.

use super::builtins::Builtin;
use super::types::{TypeId, TypeTable};
use crate::source::{FileId, Span};
use la_arena::{Arena, Idx};
use std::path::PathBuf;

pub mod print;
mod scene;
pub use scene::*;

pub use crate::syntax::ast::{BinaryOp, UnaryOp};

/// Handle of a struct in [`Program::structs`].
pub type StructId = Idx<Struct>;
/// Handle of a constant in [`Program::consts`].
pub type ConstId = Idx<Const>;
/// Handle of a function in [`Program::functions`].
pub type FnId = Idx<Function>;
/// Handle of a scene in [`Program::scenes`].
pub type SceneId = Idx<SceneDesc>;
/// Handle of an expression in a [`Body`].
pub type ExprId = Idx<Expr>;
/// Handle of a local (parameter, `let`, `var` or `for` variable) in a [`Body`].
pub type LocalId = Idx<Local>;

/// Index of a module in [`Program::modules`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModuleId(pub u32);

impl ModuleId {
    /// The index as `usize`.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// The whole checked program.
#[derive(Debug, Default)]
pub struct Program {
    /// Every type.
    pub types: TypeTable,
    /// Every module, in load order (the prelude first).
    pub modules: Vec<Module>,
    /// Every struct of every module.
    pub structs: Arena<Struct>,
    /// Every constant, evaluated.
    pub consts: Arena<Const>,
    /// Every function (plain functions and programs).
    pub functions: Arena<Function>,
    /// Every scene, evaluated.
    pub scenes: Arena<SceneDesc>,
    /// Every program (a function with a program attribute), in declaration order.
    pub programs: Vec<ProgramEntry>,
    /// Every function, callees before callers.
    pub fn_order: Vec<FnId>,
    /// The prelude's framework structs.
    pub framework: Framework,
}

/// The framework structs declared in the prelude, looked up once by name.
#[derive(Clone, Copy, Debug, Default)]
pub struct Framework {
    /// `Ray`
    pub ray: Option<StructId>,
    /// `Hit`
    pub hit: Option<StructId>,
    /// `Intersection`
    pub intersection: Option<StructId>,
    /// `Aabb`
    pub aabb: Option<StructId>,
    /// `LightSample`
    pub light_sample: Option<StructId>,
    /// `BvhNode`
    pub bvh_node: Option<StructId>,
    /// `Triangle`
    pub triangle: Option<StructId>,
}

/// One source file's items.
#[derive(Clone, Debug)]
pub struct Module {
    /// The file.
    pub file: FileId,
    /// Its display name (`std/…` for the standard library).
    pub name: String,
    /// Where it was read from, if from disk.
    pub path: Option<PathBuf>,
    /// Modules imported directly, in order.
    pub imports: Vec<ModuleId>,
    /// Whether this is `stdlib/prelude.rt`.
    pub is_prelude: bool,
    /// Whether this is a root (named on the command line), not only imported.
    pub is_root: bool,
    /// Its structs, in order.
    pub structs: Vec<StructId>,
    /// Its constants, in order.
    pub consts: Vec<ConstId>,
    /// Its functions, in order.
    pub functions: Vec<FnId>,
    /// Its scenes, in order.
    pub scenes: Vec<SceneId>,
}

/// What a role struct's instances are (`@material`, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Role {
    /// `@camera`
    Camera,
    /// `@geometry`
    Geometry,
    /// `@material`
    Material,
    /// `@light`
    Light,
    /// `@background`
    Background,
}

impl Role {
    /// The attribute's name without `@`.
    pub fn name(self) -> &'static str {
        match self {
            Role::Camera => "camera",
            Role::Geometry => "geometry",
            Role::Material => "material",
            Role::Light => "light",
            Role::Background => "background",
        }
    }

    /// The role named by an attribute.
    pub fn from_name(name: &str) -> Option<Role> {
        Some(match name {
            "camera" => Role::Camera,
            "geometry" => Role::Geometry,
            "material" => Role::Material,
            "light" => Role::Light,
            "background" => Role::Background,
            _ => return None,
        })
    }
}

/// The kinds of programs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ProgramKind {
    /// `@ray_generation`
    RayGeneration,
    /// `@intersection`
    Intersection,
    /// `@bounds`
    Bounds,
    /// `@any_hit`
    AnyHit,
    /// `@closest_hit`
    ClosestHit,
    /// `@secondary_rays`
    SecondaryRays,
    /// `@medium`
    Medium,
    /// `@light`
    Light,
    /// `@miss`
    Miss,
}

impl ProgramKind {
    /// Every kind, in table order.
    pub const ALL: [ProgramKind; 9] = [
        ProgramKind::RayGeneration,
        ProgramKind::Intersection,
        ProgramKind::Bounds,
        ProgramKind::AnyHit,
        ProgramKind::ClosestHit,
        ProgramKind::SecondaryRays,
        ProgramKind::Medium,
        ProgramKind::Light,
        ProgramKind::Miss,
    ];

    /// The attribute's name without `@`.
    pub fn name(self) -> &'static str {
        match self {
            ProgramKind::RayGeneration => "ray_generation",
            ProgramKind::Intersection => "intersection",
            ProgramKind::Bounds => "bounds",
            ProgramKind::AnyHit => "any_hit",
            ProgramKind::ClosestHit => "closest_hit",
            ProgramKind::SecondaryRays => "secondary_rays",
            ProgramKind::Medium => "medium",
            ProgramKind::Light => "light",
            ProgramKind::Miss => "miss",
        }
    }

    /// The kind named by an attribute.
    pub fn from_name(name: &str) -> Option<ProgramKind> {
        ProgramKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// The role of the struct a program of this kind belongs to.
    pub fn role(self) -> Role {
        match self {
            ProgramKind::RayGeneration => Role::Camera,
            ProgramKind::Intersection | ProgramKind::Bounds => Role::Geometry,
            ProgramKind::AnyHit
            | ProgramKind::ClosestHit
            | ProgramKind::SecondaryRays
            | ProgramKind::Medium => Role::Material,
            ProgramKind::Light => Role::Light,
            ProgramKind::Miss => Role::Background,
        }
    }
}

/// A struct.
#[derive(Clone, Debug)]
pub struct Struct {
    /// Its name.
    pub name: String,
    /// The module declaring it.
    pub module: ModuleId,
    /// The span of its name.
    pub span: Span,
    /// Its doc comment.
    pub doc: Option<String>,
    /// Its role, if it has a role attribute.
    pub role: Option<Role>,
    /// Its fields, in order.
    pub fields: Vec<Field>,
    /// Its programs, one per kind at most, in declaration order.
    pub programs: Vec<(ProgramKind, FnId)>,
}

impl Struct {
    /// The index of the field called `name`.
    pub fn field_index(&self, name: &str) -> Option<usize> {
        self.fields.iter().position(|f| f.name == name)
    }

    /// The program of this kind, if the struct has one.
    pub fn program(&self, kind: ProgramKind) -> Option<FnId> {
        self.programs
            .iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, f)| *f)
    }
}

/// A struct field.
#[derive(Clone, Debug)]
pub struct Field {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: TypeId,
    /// Its default value, if declared.
    pub default: Option<ConstValue>,
    /// The span of its name.
    pub span: Span,
    /// Its doc comment.
    pub doc: Option<String>,
}

/// A `const` item.
#[derive(Clone, Debug)]
pub struct Const {
    /// Its name.
    pub name: String,
    /// The module declaring it.
    pub module: ModuleId,
    /// Its type.
    pub ty: TypeId,
    /// Its value.
    pub value: ConstValue,
    /// The span of its name.
    pub span: Span,
}

/// A function: a plain function or a program.
#[derive(Clone, Debug)]
pub struct Function {
    /// Its name.
    pub name: String,
    /// The module declaring it.
    pub module: ModuleId,
    /// The span of its name.
    pub span: Span,
    /// Its doc comment.
    pub doc: Option<String>,
    /// Parameters, in order (locals of [`Function::body`]).
    pub params: Vec<LocalId>,
    /// The return type ([`TypeTable::VOID`] if none).
    pub ret: TypeId,
    /// Expressions and locals.
    pub body: Body,
    /// The statements.
    pub block: Block,
    /// Its program attribute, if it is a program.
    pub program: Option<ProgramKind>,
    /// The user functions it calls directly, sorted, without duplicates.
    pub callees: Vec<FnId>,
}

/// The arenas of one function body (or of one constant expression while it is checked).
#[derive(Clone, Debug, Default)]
pub struct Body {
    /// Expressions.
    pub exprs: Arena<Expr>,
    /// Locals.
    pub locals: Arena<Local>,
}

/// A local binding.
#[derive(Clone, Debug)]
pub struct Local {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: TypeId,
    /// How it was declared.
    pub kind: LocalKind,
    /// The span of its name.
    pub span: Span,
}

/// How a local was declared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LocalKind {
    /// A function parameter (immutable).
    Param,
    /// `let` (immutable).
    Let,
    /// `var` (mutable).
    Var,
    /// The variable of a `for` loop (immutable).
    For,
}

/// A typed expression.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Its type.
    pub ty: TypeId,
    /// Where it was written.
    pub span: Span,
}

/// A literal of a concrete type.
#[derive(Clone, Debug, PartialEq)]
pub enum Literal {
    /// `true`, `false`
    Bool(bool),
    /// An `i32`.
    I32(i32),
    /// A `u32`.
    U32(u32),
    /// An `f32`.
    F32(f32),
    /// A string (only in scenes).
    String(String),
}

/// The kinds of expressions.
#[derive(Clone, Debug)]
pub enum ExprKind {
    /// A literal.
    Literal(Literal),
    /// A local.
    Local(LocalId),
    /// A `const` item.
    Const(ConstId),
    /// A constant value written in place: a default filled into a struct literal, a scene `let`.
    Value(ConstValue),
    /// `op operand`.
    Unary {
        /// The operator.
        op: UnaryOp,
        /// The operand.
        operand: ExprId,
    },
    /// `lhs op rhs`; the operands have equal types except for matrix products, matrix scaling and
    /// shifts (whose right operand is `u32` or `vecNu`).
    Binary {
        /// The operator.
        op: BinaryOp,
        /// Left operand.
        lhs: ExprId,
        /// Right operand.
        rhs: ExprId,
    },
    /// A call to a user function.
    Call {
        /// The callee.
        func: FnId,
        /// Arguments, one per parameter.
        args: Vec<ExprId>,
    },
    /// A call to a built-in function or intrinsic (one of its overloads, resolved by the types).
    Builtin {
        /// The built-in.
        func: Builtin,
        /// Arguments.
        args: Vec<ExprId>,
    },
    /// A value of type `ty` built from parts: a vector from scalars and vectors whose sizes add up, a
    /// matrix from its column vectors, an array from its elements, a struct from all its fields in
    /// declaration order.
    Compose {
        /// The parts.
        components: Vec<ExprId>,
    },
    /// A vector of `ty` with every component equal to `value` (a scalar).
    Splat {
        /// The scalar.
        value: ExprId,
    },
    /// The zero value of `ty` (`vec3f()`, `var x: f32;`).
    Zero,
    /// Element-wise conversion of a scalar or vector to the scalar kind of `ty` (same width).
    Convert {
        /// The value converted.
        arg: ExprId,
    },
    /// `bitcast<ty>(arg)`: the same 32-bit pattern read as `ty`.
    Bitcast {
        /// The value reinterpreted.
        arg: ExprId,
    },
    /// A struct field.
    Field {
        /// The struct value.
        base: ExprId,
        /// The field's index in declaration order.
        index: u32,
    },
    /// A swizzle of 1 to 4 components of a vector (`v.x` has one component and a scalar type).
    Swizzle {
        /// The vector.
        base: ExprId,
        /// Component indices (0..size), the first `len` used.
        pattern: [u8; 4],
        /// How many components, 1..=4.
        len: u8,
    },
    /// `base[index]` on an array, a vector or a matrix (a column); `index` is `i32` or `u32`.
    Index {
        /// The value indexed.
        base: ExprId,
        /// The index.
        index: ExprId,
    },
    /// An expression that already produced a diagnostic.
    Error,
}

/// `{ … }`
#[derive(Clone, Debug, Default)]
pub struct Block {
    /// Statements in order.
    pub stmts: Vec<Stmt>,
    /// From `{` to `}`.
    pub span: Span,
}

/// A statement.
#[derive(Clone, Debug)]
pub struct Stmt {
    /// What it is.
    pub kind: StmtKind,
    /// Where it was written.
    pub span: Span,
}

/// The kinds of statements.
#[derive(Clone, Debug)]
pub enum StmtKind {
    /// `let x = value;`
    Let {
        /// The new local.
        local: LocalId,
        /// Its value.
        value: ExprId,
    },
    /// `var x = value;` (or zero, without a value).
    Var {
        /// The new local.
        local: LocalId,
        /// Its initial value; `None` means zero.
        value: Option<ExprId>,
    },
    /// `place = value;` or `place op= value;`
    Assign {
        /// A place (see the module doc).
        place: ExprId,
        /// The operator of a compound assignment.
        op: Option<BinaryOp>,
        /// The value.
        value: ExprId,
    },
    /// An expression evaluated for its effect.
    Expr(ExprId),
    /// `if cond { … } else { … }`
    If {
        /// A `bool`.
        cond: ExprId,
        /// Taken when true.
        then_block: Block,
        /// Taken when false.
        else_block: Option<Block>,
    },
    /// `for var in start..end { body }`, both bounds of the variable's type (`i32` or `u32`).
    For {
        /// The loop variable.
        var: LocalId,
        /// First value.
        start: ExprId,
        /// One past the last value, evaluated once.
        end: ExprId,
        /// The body.
        body: Block,
    },
    /// `while cond { body }`
    While {
        /// A `bool`.
        cond: ExprId,
        /// The body.
        body: Block,
    },
    /// `loop { body }`
    Loop {
        /// The body.
        body: Block,
    },
    /// `break;`
    Break,
    /// `continue;`
    Continue,
    /// `return;` or `return value;`
    Return(Option<ExprId>),
    /// A nested block.
    Block(Block),
}

/// A value of a scalar type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scalar {
    /// `bool`
    Bool(bool),
    /// `i32`
    I32(i32),
    /// `u32`
    U32(u32),
    /// `f32`
    F32(f32),
}

/// A triangle mesh named by a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshAsset {
    /// `load_mesh("path")`: a Wavefront OBJ file, the path resolved relative to the scene's file.
    File {
        /// The resolved path.
        path: PathBuf,
        /// The string in the scene (for errors when loading).
        span: Span,
    },
    /// `quad_mesh()`
    Quad,
    /// `cube_mesh()`
    Cube,
    /// `sphere_mesh(n)`
    Sphere {
        /// Subdivisions of the icosahedron.
        subdivisions: u32,
    },
}

/// A texture named by a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureAsset {
    /// `load_image("path")`, the path resolved relative to the scene's file.
    File {
        /// The resolved path.
        path: PathBuf,
        /// The string in the scene.
        span: Span,
    },
    /// `solid_texture(color)`
    Solid([f32; 4]),
}

/// An evaluated constant.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstValue {
    /// A scalar.
    Scalar(Scalar),
    /// A vector: the first `len` components are used, all of one scalar kind.
    Vector {
        /// 2, 3 or 4.
        len: u8,
        /// Components.
        comps: [Scalar; 4],
    },
    /// A matrix of f32, column-major.
    Matrix {
        /// Number of columns.
        cols: u8,
        /// Number of rows.
        rows: u8,
        /// `data[c][r]`; unused entries are zero.
        data: [[f32; 4]; 4],
    },
    /// An array's elements.
    Array(Vec<ConstValue>),
    /// A struct's fields in declaration order.
    Struct {
        /// The struct.
        id: StructId,
        /// Its fields.
        fields: Vec<ConstValue>,
    },
    /// A `mesh` handle.
    Mesh(MeshAsset),
    /// A `texture` handle.
    Texture(TextureAsset),
    /// A string.
    String(String),
    /// A value that could not be computed (already reported). Never in a program without errors.
    Error,
}

/// A program: a function with a program attribute, and the struct it belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ProgramEntry {
    /// What kind.
    pub kind: ProgramKind,
    /// The function.
    pub func: FnId,
    /// The struct of its first parameter.
    pub struct_id: StructId,
    /// For `@ray_generation`: samples per pixel and pass (`samples = N`, default 1); 1 otherwise.
    pub samples: u32,
    /// For `@secondary_rays`: the most rays one call can spawn; 0 otherwise.
    pub spawn_bound: u32,
    /// For `@closest_hit`: whether it takes the `secondary: vec3f` parameter.
    pub wants_secondary: bool,
    /// For a `@closest_hit` that takes `secondary`: whether its result is `E + secondary` with `E`
    /// independent of `secondary` (every `return` is `E + secondary`, `secondary + E` or
    /// `secondary`, and `secondary` is read nowhere else). The kernel may then shade such a hit
    /// before its secondary ray is traced and carry the ray's weight as a path throughput
    /// (`KernelConfig::path_loop`).
    pub additive_secondary: bool,
    /// For `@any_hit`: whether it calls `absorb` (directly or through helpers), so shadow rays
    /// are attenuated by the media whose boundaries it sees (`KernelConfig::has_absorb`).
    pub absorbs: bool,
}

impl Program {
    /// The name of a type as the user writes it.
    pub fn type_name(&self, ty: TypeId) -> String {
        self.types.display(ty, &|s| self.structs[s].name.clone())
    }

    /// The struct of a struct type.
    pub fn struct_of(&self, ty: TypeId) -> Option<StructId> {
        match self.types.get(ty) {
            super::types::Type::Struct(s) => Some(s),
            _ => None,
        }
    }

    /// The program of this kind for this struct, if any.
    pub fn program_for(&self, s: StructId, kind: ProgramKind) -> Option<&ProgramEntry> {
        self.programs
            .iter()
            .find(|p| p.struct_id == s && p.kind == kind)
    }

    /// The scene to render: the one called `name`, or the only one when `name` is `None`.
    pub fn select_scene(&self, name: Option<&str>) -> Result<SceneId, SceneChoiceError> {
        super::scenes::select_scene(self, name)
    }
}
