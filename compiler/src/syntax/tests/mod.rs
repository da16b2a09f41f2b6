//! Tests of the lexer and the parser, with a small S-expression printer of the AST so that
//! expectations read like the source (`a + b * c` ⇒ `(+ a (* b c))`).

mod exprs;
mod items;
mod lexer;
mod limits;
mod recovery;

use super::ast::*;
use super::error::SyntaxError;
use crate::diag::Diagnostic;
use crate::source::FileId;

/// Parses a whole file.
pub(super) fn parse(src: &str) -> (Module, Vec<Diagnostic>) {
    super::parse(FileId(0), src)
}

/// The codes of a file's diagnostics, in order.
pub(super) fn codes(src: &str) -> Vec<&'static str> {
    parse(src).1.iter().map(|d| d.code.0).collect()
}

/// The typed errors of a file.
pub(super) fn errors(src: &str) -> Vec<SyntaxError> {
    super::parse_errors(FileId(0), src).1
}

/// An expression, as an S-expression, with the codes of any errors.
pub(super) fn expr(src: &str) -> (String, Vec<&'static str>) {
    let text = format!("const X = {src};");
    let (m, diags) = parse(&text);
    let out = match m.items.first().map(|i| &i.kind) {
        Some(ItemKind::Const(c)) => Printer { m: &m }.expr(c.value),
        _ => "NO-CONST".to_string(),
    };
    (out, diags.iter().map(|d| d.code.0).collect())
}

/// An expression that must parse without errors, as an S-expression.
pub(super) fn ok_expr(src: &str) -> String {
    let (s, codes) = expr(src);
    assert!(codes.is_empty(), "errors {codes:?} in `{src}`");
    s
}

/// The statements of a function body, as S-expressions joined with `; `.
pub(super) fn stmts(src: &str) -> (String, Vec<&'static str>) {
    let text = format!("fn f() {{\n{src}\n}}");
    let (m, diags) = parse(&text);
    let out = match m.items.first().map(|i| &i.kind) {
        Some(ItemKind::Fn(f)) => Printer { m: &m }.stmts(&f.body),
        _ => "NO-FN".to_string(),
    };
    (out, diags.iter().map(|d| d.code.0).collect())
}

/// Statements that must parse without errors.
pub(super) fn ok_stmts(src: &str) -> String {
    let (s, codes) = stmts(src);
    assert!(codes.is_empty(), "errors {codes:?} in `{src}`");
    s
}

/// Prints AST nodes as S-expressions.
pub(super) struct Printer<'m> {
    pub m: &'m Module,
}

impl Printer<'_> {
    pub fn expr(&self, e: ExprId) -> String {
        let node = &self.m.exprs[e];
        match &node.kind {
            ExprKind::Lit(l) => lit(l),
            ExprKind::Name(n) => n.name.clone(),
            ExprKind::Unary { op, operand } => format!("({} {})", op.as_str(), self.expr(*operand)),
            ExprKind::Binary { op, lhs, rhs } => {
                format!("({} {} {})", op.as_str(), self.expr(*lhs), self.expr(*rhs))
            }
            ExprKind::Call {
                func,
                generics,
                args,
            } => {
                let mut s = format!("(call {}", func.name);
                if let Some(g) = generics {
                    s.push('<');
                    let gs: Vec<String> = g.iter().map(|g| self.generic(g)).collect();
                    s.push_str(&gs.join(", "));
                    s.push('>');
                }
                for a in args {
                    s.push(' ');
                    s.push_str(&self.expr(*a));
                }
                s.push(')');
                s
            }
            ExprKind::Field { base, field } => format!("(. {} {})", self.expr(*base), field.name),
            ExprKind::Index { base, index } => {
                format!("([] {} {})", self.expr(*base), self.expr(*index))
            }
            ExprKind::StructLit { name, fields } => {
                let mut s = format!("(struct {}", name.name);
                for f in fields {
                    s.push_str(&format!(" ({} {})", f.name.name, self.expr(f.value)));
                }
                s.push(')');
                s
            }
            ExprKind::Paren(inner) => format!("(paren {})", self.expr(*inner)),
            ExprKind::Error => "ERR".to_string(),
        }
    }

    fn generic(&self, g: &GenericArg) -> String {
        match g {
            GenericArg::Type(t) => self.ty(*t),
            GenericArg::Expr(e) => format!("={}", self.expr(*e)),
        }
    }

    pub fn ty(&self, t: TyId) -> String {
        match &self.m.types[t].kind {
            TypeExprKind::Named { name, generics } if generics.is_empty() => name.name.clone(),
            TypeExprKind::Named { name, generics } => {
                let gs: Vec<String> = generics.iter().map(|g| self.generic(g)).collect();
                format!("{}<{}>", name.name, gs.join(", "))
            }
            TypeExprKind::Error => "ERRTY".to_string(),
        }
    }

    pub fn stmts(&self, b: &Block) -> String {
        let v: Vec<String> = b.stmts.iter().map(|s| self.stmt(s)).collect();
        v.join("; ")
    }

    fn block(&self, b: &Block) -> String {
        format!("{{{}}}", self.stmts(b))
    }

    pub fn stmt(&self, s: &Stmt) -> String {
        let opt_ty = |t: &Option<TyId>| t.map(|t| format!(" :{}", self.ty(t))).unwrap_or_default();
        match &s.kind {
            StmtKind::Let { name, ty, value } => {
                format!("(let {}{} {})", name.name, opt_ty(ty), self.expr(*value))
            }
            StmtKind::Var { name, ty, value } => {
                let v = value
                    .map(|v| format!(" {}", self.expr(v)))
                    .unwrap_or_default();
                format!("(var {}{}{v})", name.name, opt_ty(ty))
            }
            StmtKind::Assign { target, op, value } => format!(
                "({}= {} {})",
                op.map(|o| o.as_str()).unwrap_or(""),
                self.expr(*target),
                self.expr(*value)
            ),
            StmtKind::Expr(e) => self.expr(*e),
            StmtKind::If {
                cond,
                then_block,
                else_block,
            } => {
                let e = else_block
                    .as_ref()
                    .map(|b| format!(" else {}", self.block(b)))
                    .unwrap_or_default();
                format!("(if {} {}{e})", self.expr(*cond), self.block(then_block))
            }
            StmtKind::For {
                var,
                start,
                end,
                body,
            } => format!(
                "(for {} {} {} {})",
                var.name,
                self.expr(*start),
                self.expr(*end),
                self.block(body)
            ),
            StmtKind::While { cond, body } => {
                format!("(while {} {})", self.expr(*cond), self.block(body))
            }
            StmtKind::Loop { body } => format!("(loop {})", self.block(body)),
            StmtKind::Break => "break".to_string(),
            StmtKind::Continue => "continue".to_string(),
            StmtKind::Return(v) => match v {
                Some(v) => format!("(return {})", self.expr(*v)),
                None => "(return)".to_string(),
            },
            StmtKind::Block(b) => self.block(b),
            StmtKind::Error => "ERR".to_string(),
        }
    }
}

fn lit(l: &Literal) -> String {
    match l {
        Literal::Bool(b) => b.to_string(),
        Literal::Int { value, suffix } => format!(
            "{value}{}",
            match suffix {
                Some(IntSuffix::I) => "i",
                Some(IntSuffix::U) => "u",
                None => "",
            }
        ),
        Literal::Float { value, suffix } => {
            format!("{value:?}{}", if suffix.is_some() { "f" } else { "" })
        }
        Literal::String(s) => format!("{s:?}"),
    }
}

/// Checks that every node's span covers its children's, for every expression in the module.
pub(super) fn check_spans(m: &Module) {
    let covers = |outer: crate::source::Span, inner: crate::source::Span| {
        outer.lo <= inner.lo && inner.hi <= outer.hi
    };
    for (_, e) in m.exprs.iter() {
        let children: Vec<ExprId> = match &e.kind {
            ExprKind::Unary { operand, .. } => vec![*operand],
            ExprKind::Binary { lhs, rhs, .. } => vec![*lhs, *rhs],
            ExprKind::Call { args, .. } => args.clone(),
            ExprKind::Field { base, .. } => vec![*base],
            ExprKind::Index { base, index } => vec![*base, *index],
            ExprKind::StructLit { fields, .. } => fields.iter().map(|f| f.value).collect(),
            ExprKind::Paren(inner) => vec![*inner],
            _ => vec![],
        };
        for c in children {
            assert!(
                covers(e.span, m.exprs[c].span),
                "span {:?} of {:?} does not cover child {:?}",
                e.span,
                e.kind,
                m.exprs[c]
            );
        }
    }
}
