//! The abstract syntax tree of one `.rt` file.
//!
//! The AST is what the parser produces and name resolution consumes. It records what was written,
//! with spans, and nothing inferred: names are unresolved [`Ident`]s, types are unresolved
//! [`TypeExpr`]s, literals keep their suffixes.
//!
//! Invariants:
//! - Expressions and type expressions live in the per-module arenas [`Module::exprs`] and
//!   [`Module::types`] and are referred to by [`ExprId`] / [`TyId`]; a handle is only meaningful with the
//!   module that holds it.
//! - Every node has a span in the module's file. Spans of a parent cover its children.
//! - Syntax errors never leave holes: the parser puts [`ExprKind::Error`], [`TypeExprKind::Error`],
//!   [`StmtKind::Error`] or [`ItemKind::Error`] where it recovered (a scene entry it cannot make
//!   sense of is left out), and has already reported a diagnostic there, so later phases skip error
//!   nodes silently (no cascades). The arena may also hold expressions that no node refers to (the
//!   operands of a construct replaced by an error node, such as `a < b < c`).
//! - Depth is bounded, so later phases may recurse: an expression tree is at most
//!   [`crate::syntax::MAX_EXPR_DEPTH`] (256) nodes deep, and blocks, generic types and parenthesised
//!   or delimited sub-expressions nest at most [`crate::syntax::MAX_DEPTH`] (128) levels.

use crate::source::{FileId, Span};
use la_arena::{Arena, Idx};

/// Handle of an expression in [`Module::exprs`].
pub type ExprId = Idx<Expr>;
/// Handle of a type expression in [`Module::types`].
pub type TyId = Idx<TypeExpr>;

/// A name as written, with its span.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Ident {
    /// The text of the identifier.
    pub name: String,
    /// Where it was written.
    pub span: Span,
}

/// One parsed file.
#[derive(Clone, Debug, Default)]
pub struct Module {
    /// The file this module was parsed from.
    pub file: FileId,
    /// `import "path";` declarations, in order.
    pub imports: Vec<Import>,
    /// Top-level items, in order.
    pub items: Vec<Item>,
    /// All expressions of the module.
    pub exprs: Arena<Expr>,
    /// All type expressions of the module.
    pub types: Arena<TypeExpr>,
}

/// `import "std/materials/lambert.rt";`
#[derive(Clone, Debug, PartialEq)]
pub struct Import {
    /// The path as written (escapes resolved).
    pub path: String,
    /// The span of the string literal.
    pub path_span: Span,
    /// The whole declaration.
    pub span: Span,
}

/// `@name` or `@name(args)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Attribute {
    /// The attribute's name, without the `@`.
    pub name: Ident,
    /// Arguments, if parenthesised (empty for `@name` and `@name()`).
    pub args: Vec<AttrArg>,
    /// From the `@` to the closing parenthesis or the name.
    pub span: Span,
}

/// An attribute argument: `expr` or `name = expr`.
#[derive(Clone, Debug, PartialEq)]
pub struct AttrArg {
    /// The name, for `name = expr`.
    pub name: Option<Ident>,
    /// The value.
    pub value: ExprId,
    /// The whole argument.
    pub span: Span,
}

/// A top-level item with its attributes and doc comment.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// Attributes written before the item.
    pub attrs: Vec<Attribute>,
    /// `///` doc comment lines before the item, joined with `\n`, leading `/// ` removed.
    pub doc: Option<String>,
    /// What the item is.
    pub kind: ItemKind,
    /// From the first attribute (or keyword) to the end of the item.
    pub span: Span,
}

/// The kinds of top-level items.
#[derive(Clone, Debug, PartialEq)]
pub enum ItemKind {
    /// `fn name(params) -> ret { body }`
    Fn(FnDecl),
    /// `struct Name { fields }`
    Struct(StructDecl),
    /// `const NAME: T = value;`
    Const(ConstDecl),
    /// `scene name { entries }`
    Scene(SceneDecl),
    /// Something the parser could not make sense of (already reported).
    Error,
}

/// A function declaration (plain function or program).
#[derive(Clone, Debug, PartialEq)]
pub struct FnDecl {
    /// The function's name.
    pub name: Ident,
    /// Parameters in order.
    pub params: Vec<Param>,
    /// The return type, if `-> T` was written.
    pub ret: Option<TyId>,
    /// The body.
    pub body: Block,
}

/// `name: T`
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// The parameter's name.
    pub name: Ident,
    /// Its type.
    pub ty: TyId,
    /// The whole parameter.
    pub span: Span,
}

/// A struct declaration. Its role (`@material`, …) comes from the item's attributes.
#[derive(Clone, Debug, PartialEq)]
pub struct StructDecl {
    /// The struct's name.
    pub name: Ident,
    /// Fields in order.
    pub fields: Vec<FieldDecl>,
}

/// `name: T` or `name: T = default` inside a struct.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldDecl {
    /// `///` doc comment lines before the field.
    pub doc: Option<String>,
    /// The field's name.
    pub name: Ident,
    /// Its type.
    pub ty: TyId,
    /// Its default value (a constant expression), if any.
    pub default: Option<ExprId>,
    /// The whole field.
    pub span: Span,
}

/// `const NAME: T = value;` (the type may be omitted).
#[derive(Clone, Debug, PartialEq)]
pub struct ConstDecl {
    /// The constant's name.
    pub name: Ident,
    /// Its declared type, if written.
    pub ty: Option<TyId>,
    /// Its value (a constant expression).
    pub value: ExprId,
}

/// `{ stmts }`
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Block {
    /// Statements in order.
    pub stmts: Vec<Stmt>,
    /// From `{` to `}`.
    pub span: Span,
}

/// A statement with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    /// What the statement is.
    pub kind: StmtKind,
    /// The whole statement, including a trailing `;`.
    pub span: Span,
}

/// The kinds of statements.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// `let name: T = value;` (immutable; the type may be omitted).
    Let {
        /// The binding's name.
        name: Ident,
        /// Its declared type, if written.
        ty: Option<TyId>,
        /// Its value.
        value: ExprId,
    },
    /// `var name: T = value;` (mutable; type or value may be omitted, not both).
    Var {
        /// The variable's name.
        name: Ident,
        /// Its declared type, if written.
        ty: Option<TyId>,
        /// Its initial value, if written (zero otherwise).
        value: Option<ExprId>,
    },
    /// `target = value;` or `target op= value;`
    Assign {
        /// What is assigned to (a variable, field, component or element).
        target: ExprId,
        /// For compound assignment (`+=` …), the operator.
        op: Option<BinaryOp>,
        /// The value.
        value: ExprId,
    },
    /// An expression followed by `;` (normally a call).
    Expr(ExprId),
    /// `if cond { then } else { … }`; `else if` is an `else` block holding one `If` statement.
    If {
        /// The condition.
        cond: ExprId,
        /// The block taken when it is true.
        then_block: Block,
        /// The `else` block, if any.
        else_block: Option<Block>,
    },
    /// `for var in start..end { body }` (half-open integer range).
    For {
        /// The loop variable (immutable in the body).
        var: Ident,
        /// First value.
        start: ExprId,
        /// One past the last value.
        end: ExprId,
        /// The body.
        body: Block,
    },
    /// `while cond { body }`
    While {
        /// The condition, tested before each iteration.
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
    /// A nested `{ … }` block.
    Block(Block),
    /// A statement the parser could not make sense of (already reported).
    Error,
}

/// An expression with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What the expression is.
    pub kind: ExprKind,
    /// Where it was written.
    pub span: Span,
}

/// The kinds of expressions.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A literal.
    Lit(Literal),
    /// A name: a local, parameter, constant or (as a callee) function.
    Name(Ident),
    /// `op operand`
    Unary {
        /// The operator.
        op: UnaryOp,
        /// The operand.
        operand: ExprId,
    },
    /// `lhs op rhs`
    Binary {
        /// The operator.
        op: BinaryOp,
        /// Left operand.
        lhs: ExprId,
        /// Right operand.
        rhs: ExprId,
    },
    /// `func(args)`, `func<generics>(args)`: function calls, built-ins, and type constructors and
    /// conversions such as `vec3f(1.0)`, `vec3<f32>(x)`, `array<f32, 3>(a, b, c)`, `bitcast<u32>(x)`.
    /// Generic arguments are only parsed after the built-in generic names (`vec2` … `vec4`,
    /// `mat2x2` … `mat4x4`, `array`, `bitcast`); after any other name `<` is "less than".
    Call {
        /// The called name.
        func: Ident,
        /// Generic arguments in `<…>`, if written.
        generics: Option<Vec<GenericArg>>,
        /// Arguments in order.
        args: Vec<ExprId>,
    },
    /// `base.field`: a struct field or a vector swizzle (`v.xy`, `c.rgb`).
    Field {
        /// The value accessed.
        base: ExprId,
        /// The field or swizzle name.
        field: Ident,
    },
    /// `base[index]`
    Index {
        /// The value indexed.
        base: ExprId,
        /// The index.
        index: ExprId,
    },
    /// `Name { field: value, … }`; omitted fields take the struct's defaults.
    StructLit {
        /// The struct's name.
        name: Ident,
        /// Fields in the order written.
        fields: Vec<FieldInit>,
    },
    /// `( inner )`: kept so that spans and the struct-literal rule are faithful.
    Paren(ExprId),
    /// An expression the parser could not make sense of (already reported).
    Error,
}

/// A generic argument: a type (`vec3<f32>`) or a constant expression (the size in `array<f32, 3>`).
///
/// The parser reads the **first** argument of a list as a type and every further one as an
/// expression (the only generic with two arguments is `array<T, N>`), so `array<f32, N>` gives
/// `[Type(f32), Expr(N)]` whatever `N` names.
#[derive(Clone, Debug, PartialEq)]
pub enum GenericArg {
    /// A type.
    Type(TyId),
    /// A constant expression.
    Expr(ExprId),
}

/// `name: value` in a struct literal, in scene settings or in an object.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldInit {
    /// The field's name.
    pub name: Ident,
    /// Its value.
    pub value: ExprId,
    /// The whole `name: value`.
    pub span: Span,
}

/// A literal as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Literal {
    /// `true` or `false`.
    Bool(bool),
    /// An integer literal; `value` is the magnitude as written (range checks happen in sema, once the
    /// type is known).
    Int {
        /// The value.
        value: u64,
        /// `i` or `u`, if written.
        suffix: Option<IntSuffix>,
    },
    /// A float literal (`1.0`, `1e-3`, `2f`).
    Float {
        /// The value, parsed as f64.
        value: f64,
        /// `f`, if written.
        suffix: Option<FloatSuffix>,
    },
    /// A string literal (only meaningful as an asset path, e.g. `mesh("bunny.obj")`).
    String(String),
}

/// Suffix of an integer literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntSuffix {
    /// `i`: `i32`.
    I,
    /// `u`: `u32`.
    U,
}

/// Suffix of a float literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FloatSuffix {
    /// `f`: `f32`.
    F,
}

/// Prefix operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UnaryOp {
    /// `-x`
    Neg,
    /// `!x` (bool)
    Not,
    /// `~x` (integers)
    BitNot,
}

/// Infix operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BinaryOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `%`
    Rem,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `&&` (short-circuit)
    And,
    /// `||` (short-circuit)
    Or,
    /// `&`
    BitAnd,
    /// `|`
    BitOr,
    /// `^`
    BitXor,
    /// `<<`
    Shl,
    /// `>>`
    Shr,
}

impl BinaryOp {
    /// The operator as written.
    pub fn as_str(self) -> &'static str {
        use BinaryOp::*;
        match self {
            Add => "+",
            Sub => "-",
            Mul => "*",
            Div => "/",
            Rem => "%",
            Eq => "==",
            Ne => "!=",
            Lt => "<",
            Le => "<=",
            Gt => ">",
            Ge => ">=",
            And => "&&",
            Or => "||",
            BitAnd => "&",
            BitOr => "|",
            BitXor => "^",
            Shl => "<<",
            Shr => ">>",
        }
    }
}

impl UnaryOp {
    /// The operator as written.
    pub fn as_str(self) -> &'static str {
        match self {
            UnaryOp::Neg => "-",
            UnaryOp::Not => "!",
            UnaryOp::BitNot => "~",
        }
    }
}

/// A type as written: `f32`, `vec3f`, `vec3<f32>`, `array<T, N>`, `Lambert`.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeExpr {
    /// What was written.
    pub kind: TypeExprKind,
    /// Where.
    pub span: Span,
}

/// The kinds of type expressions.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeExprKind {
    /// A name with optional generic arguments.
    Named {
        /// The type's name.
        name: Ident,
        /// Generic arguments in `<…>` (empty if none were written).
        generics: Vec<GenericArg>,
    },
    /// A type the parser could not make sense of (already reported).
    Error,
}

/// `scene name { entries }`: a declarative scene, checked against the declared structs.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDecl {
    /// The scene's name.
    pub name: Ident,
    /// Entries in order.
    pub entries: Vec<SceneEntry>,
}

/// One entry of a scene, with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneEntry {
    /// What the entry is.
    pub kind: SceneEntryKind,
    /// The whole entry.
    pub span: Span,
}

/// The kinds of scene entries.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneEntryKind {
    /// `settings { width: 256, height: 256, samples: 4, … }`
    Settings(Vec<FieldInit>),
    /// `camera Pinhole { … }`: an instance of a `@camera` struct.
    Camera(ExprId),
    /// `background Sky { … }`: an instance of a `@background` struct.
    Background(ExprId),
    /// `let name = value;`: a named value (typically a material instance) used by later entries.
    Let {
        /// The name.
        name: Ident,
        /// The value.
        value: ExprId,
    },
    /// `object name { geometry: …, material: …, transform: … }` (the name is optional).
    Object {
        /// The object's name, if given.
        name: Option<Ident>,
        /// Its fields.
        fields: Vec<FieldInit>,
    },
    /// `light name PointLight { … }` (the name is optional): an instance of a `@light` struct.
    Light {
        /// The light's name, if given.
        name: Option<Ident>,
        /// The light instance.
        value: ExprId,
    },
    /// `model "file.glb" { transform: … }`: everything in a glTF file.
    Model {
        /// The path as written.
        path: String,
        /// The span of the string literal.
        path_span: Span,
        /// Its fields (`transform`, …).
        fields: Vec<FieldInit>,
    },
    /// `animate target motion` (spec/animation.md): `target` is `object`, `camera.field`,
    /// `background.field` or `light.field`, by name.
    Animate {
        /// One name, or two with a `.` between them.
        target: Vec<Ident>,
        /// The motion.
        motion: AnimMotion,
    },
    /// An entry the parser could not make sense of (already reported).
    Error,
}

/// The motion of an `animate` entry.
#[derive(Clone, Debug, PartialEq)]
pub enum AnimMotion {
    /// `keys interp? { time: value, … }`
    Keys {
        /// The word before the block, `keys` when well written (sema reports another).
        word: Ident,
        /// The interpolation's name, if written.
        interp: Option<Ident>,
        /// The keys in source order.
        keys: Vec<Keyframe>,
        /// The word `keys` through the closing `}`.
        span: Span,
    },
    /// `name(args)`: a motion over time such as `spin(axis, degrees_per_second)`.
    Over {
        /// The motion's name.
        name: Ident,
        /// Its arguments.
        args: Vec<ExprId>,
        /// The whole call.
        span: Span,
    },
}

/// `time: value` in a `keys { … }` block.
#[derive(Clone, Debug, PartialEq)]
pub struct Keyframe {
    /// Seconds.
    pub time: ExprId,
    /// The value at that time.
    pub value: ExprId,
}
