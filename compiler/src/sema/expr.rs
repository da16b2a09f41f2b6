//! Expressions: from the AST to typed HIR, with literal inference and the operator rules.
//!
//! The [`Checker`] is shared by function bodies, constant expressions (`const` items, field defaults,
//! array sizes, attribute arguments) and scene values; its [`Mode`] says which. Checking is
//! bidirectional in one small way: an untyped literal takes a *hint* (a scalar kind) from its context,
//! as spec/types.md says — the declared type, the other operand of a binary operator (which is therefore
//! checked first when only one side is an untyped literal), a parameter or constructor element type.
//! Without a hint, an integer literal is `i32` and a float literal `f32`.
//!
//! Invariants:
//! - Every AST expression becomes exactly one HIR expression (parentheses become their inner
//!   expression) with its type; errors become [`ExprKind::Error`] of type [`TypeTable::ERROR`].
//! - No rule reports an error about an operand of the error type (no cascades).
//! - A scalar operand of a vector operator is wrapped in an explicit [`ExprKind::Splat`].

use super::consteval::{self, EvalError};
use super::error::{ExprError, LimitError, NameError, NameKind, SemaError};
use super::hir::{
    BinaryOp, Body, ConstValue, ExprId, ExprKind, Literal, LocalId, LocalKind, ModuleId, UnaryOp,
};
use super::types::{ScalarKind, Type, TypeId, TypeTable};
use super::{ix, Ctx, Def, Found, TypeCtor};
use crate::source::Span;
use crate::syntax::ast;
use std::collections::HashMap;
use std::path::Path;

/// What an expression is checked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Mode {
    /// A function body.
    Function,
    /// A constant expression outside scenes; the text names the context for E0412.
    Const(&'static str),
    /// A scene value (constant, and scene-only built-ins allowed).
    Scene,
}

/// A name bound in a block scope.
#[derive(Clone, Debug)]
pub(crate) enum Binding {
    /// A local of the body.
    Local(LocalId),
    /// A scene `let`: an evaluated value.
    Value(TypeId, ConstValue),
}

/// The block scopes of a body: the bindings in declaration order (a block ends by truncating to
/// its start) and, per name, the positions of its bindings, so a lookup takes constant time
/// however many locals are in scope.
#[derive(Default)]
pub(crate) struct Scopes<'a> {
    stack: Vec<(&'a str, Binding)>,
    by_name: HashMap<&'a str, Vec<usize>>,
}

impl<'a> Scopes<'a> {
    /// Binds `name` (shadowing any earlier binding of it).
    pub fn push(&mut self, name: &'a str, b: Binding) {
        self.by_name.entry(name).or_default().push(self.stack.len());
        self.stack.push((name, b));
    }

    /// The number of bindings, a mark for [`Scopes::truncate`].
    pub fn len(&self) -> usize {
        self.stack.len()
    }

    /// Removes the bindings made since `mark`.
    pub fn truncate(&mut self, mark: usize) {
        while self.stack.len() > mark {
            if let Some((name, _)) = self.stack.pop() {
                if let Some(v) = self.by_name.get_mut(name) {
                    v.pop();
                }
            }
        }
    }

    /// The innermost binding of `name`.
    pub fn get(&self, name: &str) -> Option<&Binding> {
        let &i = self.by_name.get(name)?.last()?;
        self.stack.get(i).map(|(_, b)| b)
    }

    /// The names in scope, innermost first.
    pub fn names(&self) -> impl Iterator<Item = &'a str> + '_ {
        self.stack.iter().rev().map(|(n, _)| *n)
    }
}

/// The literal-type hint of an expression's context.
pub(crate) type Hint = Option<ScalarKind>;

/// Checks expressions of one body (or one constant expression) of one module.
pub(crate) struct Checker<'c, 'a> {
    pub cx: &'c mut Ctx<'a>,
    pub module: ModuleId,
    pub ast: &'a ast::Module,
    pub body: Body,
    pub mode: Mode,
    pub scopes: Scopes<'a>,
    /// Reads of each local (indexed by local).
    pub uses: Vec<u32>,
    /// Asset paths in scenes are relative to this folder.
    pub base_dir: Option<&'a Path>,
    /// The function's return type.
    pub ret: TypeId,
    /// One entry per enclosing loop: whether a `break` targets it.
    pub loops: Vec<bool>,
    /// In a scene: the `let`s not yet reached, the next one last.
    pub later: Vec<(&'a str, Span)>,
}

/// Whether an expression is made only of untyped literals (and operators on them).
pub(crate) fn is_abstract(ast: &ast::Module, e: ast::ExprId) -> bool {
    match &ast.exprs[e].kind {
        ast::ExprKind::Lit(ast::Literal::Int { suffix: None, .. })
        | ast::ExprKind::Lit(ast::Literal::Float { suffix: None, .. }) => true,
        ast::ExprKind::Paren(x) => is_abstract(ast, *x),
        ast::ExprKind::Unary {
            op: UnaryOp::Neg,
            operand,
        } => is_abstract(ast, *operand),
        ast::ExprKind::Binary { op, lhs, rhs } => {
            is_arith(*op) && is_abstract(ast, *lhs) && is_abstract(ast, *rhs)
        }
        _ => false,
    }
}

/// Whether an untyped expression contains a float literal (then it defaults to `f32`).
fn contains_float(ast: &ast::Module, e: ast::ExprId) -> bool {
    match &ast.exprs[e].kind {
        ast::ExprKind::Lit(ast::Literal::Float { .. }) => true,
        ast::ExprKind::Paren(x) => contains_float(ast, *x),
        ast::ExprKind::Unary { operand, .. } => contains_float(ast, *operand),
        ast::ExprKind::Binary { lhs, rhs, .. } => {
            contains_float(ast, *lhs) || contains_float(ast, *rhs)
        }
        _ => false,
    }
}

/// The default kind of an untyped expression.
pub(crate) fn abstract_default(ast: &ast::Module, e: ast::ExprId) -> ScalarKind {
    if contains_float(ast, e) {
        ScalarKind::F32
    } else {
        ScalarKind::I32
    }
}

fn is_arith(op: BinaryOp) -> bool {
    use BinaryOp::*;
    matches!(op, Add | Sub | Mul | Div | Rem)
}

fn is_comparison(op: BinaryOp) -> bool {
    use BinaryOp::*;
    matches!(op, Eq | Ne | Lt | Le | Gt | Ge)
}

/// Which operand of a vector–scalar operator is splatted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Splat {
    None,
    Lhs,
    Rhs,
}

/// The result type of `lhs op rhs` (spec/expressions.md), or `None` if the operator does not apply.
pub(crate) fn binary_type(
    types: &mut TypeTable,
    op: BinaryOp,
    lhs: TypeId,
    rhs: TypeId,
) -> Option<(TypeId, Splat)> {
    use BinaryOp::*;
    let (l, r) = (types.get(lhs), types.get(rhs));
    let num = |k: ScalarKind| k.is_numeric();
    let bool_of = |types: &mut TypeTable, t: Type| match t {
        Type::Vector { size, .. } => types.scalar_or_vector(size, ScalarKind::Bool),
        _ => TypeTable::BOOL,
    };
    match op {
        Add | Sub | Mul | Div | Rem => match (l, r) {
            (Type::Scalar(a), Type::Scalar(b)) if a == b && num(a) => Some((lhs, Splat::None)),
            (Type::Vector { scalar: a, .. }, Type::Vector { scalar: b, .. })
                if lhs == rhs && num(a) && num(b) =>
            {
                Some((lhs, Splat::None))
            }
            (Type::Vector { scalar: a, .. }, Type::Scalar(b)) if a == b && num(a) => {
                Some((lhs, Splat::Rhs))
            }
            (Type::Scalar(a), Type::Vector { scalar: b, .. }) if a == b && num(a) => {
                Some((rhs, Splat::Lhs))
            }
            (Type::Matrix { .. }, Type::Matrix { .. }) if matches!(op, Add | Sub) && lhs == rhs => {
                Some((lhs, Splat::None))
            }
            (Type::Matrix { cols, rows }, Type::Matrix { cols: c2, rows: r2 })
                if op == Mul && cols == r2 =>
            {
                Some((types.intern(Type::Matrix { cols: c2, rows }), Splat::None))
            }
            (
                Type::Matrix { cols, rows },
                Type::Vector {
                    size,
                    scalar: ScalarKind::F32,
                },
            ) if op == Mul && cols == size => {
                Some((types.scalar_or_vector(rows, ScalarKind::F32), Splat::None))
            }
            (
                Type::Vector {
                    size,
                    scalar: ScalarKind::F32,
                },
                Type::Matrix { cols, rows },
            ) if op == Mul && rows == size => {
                Some((types.scalar_or_vector(cols, ScalarKind::F32), Splat::None))
            }
            (Type::Matrix { .. }, Type::Scalar(ScalarKind::F32)) if op == Mul => {
                Some((lhs, Splat::None))
            }
            (Type::Scalar(ScalarKind::F32), Type::Matrix { .. }) if op == Mul => {
                Some((rhs, Splat::None))
            }
            _ => None,
        },
        Eq | Ne | Lt | Le | Gt | Ge => {
            let ordered = !matches!(op, Eq | Ne);
            match l {
                Type::Scalar(k) | Type::Vector { scalar: k, .. }
                    if lhs == rhs && (!ordered || num(k)) =>
                {
                    Some((bool_of(types, l), Splat::None))
                }
                _ => None,
            }
        }
        And | Or => (lhs == TypeTable::BOOL && rhs == TypeTable::BOOL)
            .then_some((TypeTable::BOOL, Splat::None)),
        BitAnd | BitOr | BitXor => match l {
            Type::Scalar(_) | Type::Vector { .. } if lhs == rhs => Some((lhs, Splat::None)),
            _ => None,
        },
        Shl | Shr => match (l, r) {
            (Type::Scalar(a), Type::Scalar(ScalarKind::U32)) if a.is_integer() => {
                Some((lhs, Splat::None))
            }
            (
                Type::Vector { size, scalar: a },
                Type::Vector {
                    size: s2,
                    scalar: ScalarKind::U32,
                },
            ) if a.is_integer() && size == s2 => Some((lhs, Splat::None)),
            _ => None,
        },
    }
}

/// Parses a swizzle name against a vector of `size` components.
pub(crate) fn parse_swizzle(name: &str, size: u8) -> Option<([u8; 4], u8)> {
    let sets = ["xyzw", "rgba"];
    if name.is_empty() || name.len() > 4 {
        return None;
    }
    for set in sets {
        let mut pattern = [0u8; 4];
        let mut ok = true;
        for (i, c) in name.chars().enumerate() {
            match set.find(c) {
                Some(p) if (p as u8) < size => pattern[i] = p as u8,
                _ => {
                    ok = false;
                    break;
                }
            }
        }
        if ok {
            return Some((pattern, name.len() as u8));
        }
    }
    None
}

impl<'c, 'a> Checker<'c, 'a> {
    /// A checker for one body or constant expression of `module`.
    pub fn new(cx: &'c mut Ctx<'a>, module: ModuleId, mode: Mode) -> Checker<'c, 'a> {
        let ast = cx.module_ast(module);
        Checker {
            cx,
            module,
            ast,
            body: Body::default(),
            mode,
            scopes: Scopes::default(),
            uses: Vec::new(),
            base_dir: None,
            ret: TypeTable::VOID,
            loops: Vec::new(),
            later: Vec::new(),
        }
    }

    pub fn alloc(&mut self, kind: ExprKind, ty: TypeId, span: Span) -> ExprId {
        self.body.exprs.alloc(super::hir::Expr { kind, ty, span })
    }

    pub fn ty(&self, id: ExprId) -> TypeId {
        self.body.exprs[id].ty
    }

    pub fn span(&self, id: ExprId) -> Span {
        self.body.exprs[id].span
    }

    pub fn error_expr(&mut self, span: Span) -> ExprId {
        self.alloc(ExprKind::Error, TypeTable::ERROR, span)
    }

    pub fn err(&mut self, e: impl Into<SemaError>) {
        self.cx.err(e);
    }

    /// The literal hint a value of type `ty` gives.
    pub fn hint_of(&self, ty: TypeId) -> Hint {
        self.cx.p.types.scalar_kind(ty)
    }

    /// Checks `e` and requires type `ty` (E0401 otherwise).
    pub fn expect(&mut self, e: ast::ExprId, ty: TypeId) -> ExprId {
        let id = self.expr(e, self.hint_of(ty));
        self.coerce(id, ty);
        id
    }

    /// Reports E0401 unless `id` has type `ty` (or either is the error type).
    pub fn coerce(&mut self, id: ExprId, ty: TypeId) -> bool {
        let found = self.ty(id);
        if found == ty || TypeTable::is_error(found) || TypeTable::is_error(ty) {
            return true;
        }
        let span = self.span(id);
        self.err(ExprError::Mismatch {
            span,
            expected: ty,
            found,
        });
        false
    }

    /// Evaluates a checked expression without reporting anything.
    pub fn try_eval(&self, id: ExprId) -> Result<ConstValue, EvalError> {
        let env = consteval::Env {
            types: &self.cx.p.types,
            structs: &self.cx.p.structs,
            consts: &self.cx.p.consts,
            base_dir: self.base_dir,
        };
        consteval::eval(&self.body, id, &env)
    }

    /// Evaluates a checked constant expression; a non-constant part is E0412.
    pub fn eval_const(&mut self, id: ExprId) -> ConstValue {
        match self.try_eval(id) {
            Ok(v) => v,
            Err(EvalError::Silent) => ConstValue::Error,
            Err(EvalError::NonFinite { span, nan }) => {
                self.err(super::limits::non_finite(span, nan));
                ConstValue::Error
            }
            Err(EvalError::TooLarge { span, scalars }) => {
                self.err(LimitError::ConstTooLarge { span, scalars });
                ConstValue::Error
            }
            Err(EvalError::NotConst { span, what }) => {
                let context = match self.mode {
                    Mode::Const(c) => c,
                    _ => "a scene value",
                };
                self.err(ExprError::NotConst {
                    span,
                    what,
                    context,
                });
                ConstValue::Error
            }
        }
    }

    /// The innermost binding of `name` in the block scopes.
    pub fn lookup_local(&self, name: &str) -> Option<&Binding> {
        self.scopes.get(name)
    }

    /// Declares a local in the innermost scope.
    pub fn declare(&mut self, name: &'a ast::Ident, ty: TypeId, kind: LocalKind) -> LocalId {
        let id = self.body.locals.alloc(super::hir::Local {
            name: name.name.clone(),
            ty,
            kind,
            span: name.span,
        });
        self.scopes.push(name.name.as_str(), Binding::Local(id));
        id
    }

    pub fn use_local(&mut self, l: LocalId) {
        let i = ix(l);
        if self.uses.len() <= i {
            self.uses.resize(i + 1, 0);
        }
        self.uses[i] += 1;
    }

    /// Undoes one read of `l` (the root of a plain assignment's place is written, not read).
    pub fn unuse_local(&mut self, l: LocalId) {
        if let Some(u) = self.uses.get_mut(ix(l)) {
            *u = u.saturating_sub(1);
        }
    }

    /// Checks one expression.
    pub fn expr(&mut self, e: ast::ExprId, hint: Hint) -> ExprId {
        let ast = self.ast;
        let node = &ast.exprs[e];
        let span = node.span;
        match &node.kind {
            ast::ExprKind::Lit(lit) => self.literal(lit, false, hint, span),
            ast::ExprKind::Name(ident) => self.name(ident),
            ast::ExprKind::Unary { op, operand } => self.unary(*op, *operand, hint, span),
            ast::ExprKind::Binary { op, lhs, rhs } => self.binary(*op, *lhs, *rhs, hint, span),
            ast::ExprKind::Call {
                func,
                generics,
                args,
            } => self.call(func, generics.as_deref(), args, hint, span),
            ast::ExprKind::Field { base, field } => self.field(*base, field, span),
            ast::ExprKind::Index { base, index } => self.index(*base, *index, span),
            ast::ExprKind::StructLit { name, fields } => self.struct_lit(name, fields, span),
            ast::ExprKind::Paren(inner) => self.expr(*inner, hint),
            ast::ExprKind::Error => self.error_expr(span),
        }
    }

    /// A literal, negated if `neg` (`-1` is one literal, so `-2147483648` fits `i32`).
    fn literal(&mut self, lit: &ast::Literal, neg: bool, hint: Hint, span: Span) -> ExprId {
        let out_of_range = |ck: &mut Self, ty: TypeId| {
            ck.err(ExprError::LiteralRange { span, ty });
            ck.error_expr(span)
        };
        match lit {
            ast::Literal::Bool(b) => {
                self.alloc(ExprKind::Literal(Literal::Bool(*b)), TypeTable::BOOL, span)
            }
            ast::Literal::String(s) => {
                if self.mode != Mode::Scene {
                    self.err(ExprError::TypeNotAllowed {
                        span,
                        ty: TypeTable::STRING,
                        context: "outside scenes (strings are only asset paths)",
                    });
                    return self.error_expr(span);
                }
                self.alloc(
                    ExprKind::Literal(Literal::String(s.clone())),
                    TypeTable::STRING,
                    span,
                )
            }
            ast::Literal::Int { value, suffix } => {
                let kind = match suffix {
                    Some(ast::IntSuffix::I) => ScalarKind::I32,
                    Some(ast::IntSuffix::U) => ScalarKind::U32,
                    None => match hint {
                        Some(k) if k.is_numeric() => k,
                        _ => ScalarKind::I32,
                    },
                };
                // A suffixed literal beyond what its suffix allows was reported by the lexer (E0105).
                let lexer_limit = match suffix {
                    Some(ast::IntSuffix::I) => Some(1u64 << 31),
                    Some(ast::IntSuffix::U) => Some(u64::from(u32::MAX)),
                    None => None,
                };
                if lexer_limit.is_some_and(|l| *value > l) {
                    return self.error_expr(span);
                }
                let v = i128::from(*value) * if neg { -1 } else { 1 };
                let lit = match kind {
                    ScalarKind::I32 => i32::try_from(v).ok().map(Literal::I32),
                    ScalarKind::U32 => u32::try_from(v).ok().map(Literal::U32),
                    _ => Some(Literal::F32(v as f32)),
                };
                let ty = TypeTable::scalar(kind);
                match lit {
                    Some(l) => self.alloc(ExprKind::Literal(l), ty, span),
                    None => out_of_range(self, ty),
                }
            }
            ast::Literal::Float { value, suffix } => {
                let v = if neg { -*value } else { *value };
                if suffix.is_none() {
                    if let Some(k) = hint.filter(|k| k.is_integer()) {
                        return out_of_range(self, TypeTable::scalar(k));
                    }
                }
                if v.is_finite() && (v as f32).is_infinite() {
                    return out_of_range(self, TypeTable::F32);
                }
                self.alloc(
                    ExprKind::Literal(Literal::F32(v as f32)),
                    TypeTable::F32,
                    span,
                )
            }
        }
    }

    fn name(&mut self, ident: &'a ast::Ident) -> ExprId {
        let span = ident.span;
        match self.lookup_local(&ident.name).cloned() {
            Some(Binding::Local(l)) => {
                self.use_local(l);
                let ty = self.body.locals[l].ty;
                return self.alloc(ExprKind::Local(l), ty, span);
            }
            Some(Binding::Value(ty, v)) => return self.alloc(ExprKind::Value(v), ty, span),
            None => {}
        }
        let found = self.cx.lookup(self.module, &ident.name);
        let kind = match found {
            Found::Def(Def::Const(c)) => {
                let ty = self.cx.ensure_const(c, span);
                if TypeTable::is_error(ty) {
                    return self.error_expr(span);
                }
                return self.alloc(ExprKind::Const(c), ty, span);
            }
            Found::Def(Def::Struct(_)) => NameKind::Struct,
            Found::Def(Def::Fn(_)) => NameKind::Function,
            Found::Def(Def::Scene(_)) => NameKind::Scene,
            Found::Builtin(_) | Found::Type(TypeCtor::Bitcast) => NameKind::Builtin,
            Found::Type(_) => NameKind::Type,
            Found::None | Found::Ambiguous(_) => {
                if let Some((_, def)) = self.later.iter().find(|(n, _)| *n == ident.name) {
                    let def = *def;
                    self.err(NameError::DefinedLater {
                        span,
                        name: ident.name.clone(),
                        def,
                    });
                } else if let Found::None = found {
                    // The innermost names only: suggestions stay cheap in a body of any length.
                    let mut locals: Vec<&str> = self.scopes.names().take(1024).collect();
                    locals.reverse();
                    self.cx.undefined(self.module, ident, &locals);
                } else {
                    self.cx.report_lookup(self.module, ident, found);
                }
                return self.error_expr(span);
            }
        };
        self.err(NameError::NotAValue {
            span,
            name: ident.name.clone(),
            kind,
        });
        self.error_expr(span)
    }

    fn unary(&mut self, op: UnaryOp, operand: ast::ExprId, hint: Hint, span: Span) -> ExprId {
        if op == UnaryOp::Neg {
            if let ast::ExprKind::Lit(
                lit @ (ast::Literal::Int { .. } | ast::Literal::Float { .. }),
            ) = &self.ast.exprs[operand].kind
            {
                return self.literal(lit, true, hint, span);
            }
        }
        let x = self.expr(operand, hint);
        let ty = self.ty(x);
        if TypeTable::is_error(ty) {
            return self.alloc(ExprKind::Unary { op, operand: x }, ty, span);
        }
        let ok = match (op, self.cx.p.types.get(ty)) {
            (UnaryOp::Neg, Type::Scalar(k) | Type::Vector { scalar: k, .. }) => {
                matches!(k, ScalarKind::I32 | ScalarKind::F32)
            }
            (UnaryOp::Not, Type::Scalar(k) | Type::Vector { scalar: k, .. }) => {
                k == ScalarKind::Bool
            }
            (UnaryOp::BitNot, Type::Scalar(k) | Type::Vector { scalar: k, .. }) => k.is_integer(),
            _ => false,
        };
        if !ok {
            self.err(ExprError::BadUnary {
                span,
                op: op.as_str(),
                ty,
            });
            return self.error_expr(span);
        }
        self.alloc(ExprKind::Unary { op, operand: x }, ty, span)
    }

    /// Checks both operands of a binary operator, giving an untyped side the other side's type.
    pub fn operands(
        &mut self,
        op: BinaryOp,
        lhs: ast::ExprId,
        rhs: ast::ExprId,
        hint: Hint,
    ) -> (ExprId, ExprId) {
        let h = if is_comparison(op) || matches!(op, BinaryOp::And | BinaryOp::Or) {
            None
        } else {
            hint
        };
        if matches!(op, BinaryOp::Shl | BinaryOp::Shr) {
            let l = self.expr(lhs, h);
            let r = self.expr(rhs, Some(ScalarKind::U32));
            return (l, r);
        }
        let (la, ra) = (is_abstract(self.ast, lhs), is_abstract(self.ast, rhs));
        match (la, ra) {
            (true, false) => {
                let r = self.expr(rhs, h);
                let k = self.hint_of(self.ty(r));
                let l = self.expr(lhs, k.or(h));
                (l, r)
            }
            (false, true) => {
                let l = self.expr(lhs, h);
                let k = self.hint_of(self.ty(l));
                let r = self.expr(rhs, k.or(h));
                (l, r)
            }
            (true, true) => {
                let k = h.or_else(|| {
                    Some(
                        if abstract_default(self.ast, lhs) == ScalarKind::F32
                            || abstract_default(self.ast, rhs) == ScalarKind::F32
                        {
                            ScalarKind::F32
                        } else {
                            ScalarKind::I32
                        },
                    )
                });
                (self.expr(lhs, k), self.expr(rhs, k))
            }
            (false, false) => (self.expr(lhs, h), self.expr(rhs, h)),
        }
    }

    /// Wraps a scalar operand in a splat to the vector type `ty`.
    pub fn splat(&mut self, value: ExprId, ty: TypeId) -> ExprId {
        let span = self.span(value);
        self.alloc(ExprKind::Splat { value }, ty, span)
    }

    fn binary(
        &mut self,
        op: BinaryOp,
        lhs: ast::ExprId,
        rhs: ast::ExprId,
        hint: Hint,
        span: Span,
    ) -> ExprId {
        let (l, r) = self.operands(op, lhs, rhs, hint);
        let (lt, rt) = (self.ty(l), self.ty(r));
        if TypeTable::is_error(lt) || TypeTable::is_error(rt) {
            return self.alloc(
                ExprKind::Binary { op, lhs: l, rhs: r },
                TypeTable::ERROR,
                span,
            );
        }
        match binary_type(&mut self.cx.p.types, op, lt, rt) {
            Some((ty, splat)) => {
                let (l, r) = match splat {
                    Splat::None => (l, r),
                    Splat::Lhs => (self.splat(l, ty), r),
                    Splat::Rhs => (l, self.splat(r, ty)),
                };
                self.alloc(ExprKind::Binary { op, lhs: l, rhs: r }, ty, span)
            }
            None => {
                let (lhs_span, rhs_span) = (self.span(l), self.span(r));
                self.err(ExprError::BadOperands {
                    span,
                    op: op.as_str(),
                    lhs: lt,
                    rhs: rt,
                    lhs_span,
                    rhs_span,
                });
                self.error_expr(span)
            }
        }
    }
}
