//! Expressions: precedence climbing over the table of spec/expressions.md.
//!
//! Binding powers, loosest first: `||` 1, `&&` 2, comparisons 3 (non-associative), `|` 4, `^` 5,
//! `&` 6, `<< >>` 7, `+ -` 8, `* / %` 9; then prefix `- ! ~`, then postfix calls, fields and indexing.
//! Binary operators of one level associate to the left, so a chain is built by a loop, not by
//! recursion; prefix operators are collected in a loop too. Recursion happens only into delimited
//! sub-expressions (`( )`, `[ ]`, call arguments, struct literal fields, generic arguments), each
//! through [`Parser::expr`], which counts depth.
//!
//! Two ambiguities are resolved here:
//! - `name<` starts generic arguments only for the built-in generic names ([`GENERIC_NAMES`]:
//!   `vec2 vec3 vec4 mat2x2 … mat4x4 array bitcast`), which are the only generic callees; for any
//!   other name `<` is "less than". A local variable named `array` cannot be compared with `<`.
//! - `Name {` starts a struct literal, except where [`Restrict::no_struct`] says the `{` is a block's
//!   (conditions and `for` ranges); there `Name { field:` is reported as `E0204` and parsed as a
//!   struct literal anyway.

use super::{Parser, Restrict, STMT_KEYWORDS};
use crate::syntax::ast::{
    BinaryOp, ExprId, ExprKind, FieldInit, Ident, IntSuffix, Literal, UnaryOp,
};
use crate::syntax::error::{Expected, Hint, Nesting, NumberProblem, RangeTy, SyntaxError};
use crate::syntax::lexer;
use crate::syntax::token::{TokenKind, TokenSet};

/// The names that take generic arguments in expressions.
pub(super) const GENERIC_NAMES: &[&str] = &[
    "vec2", "vec3", "vec4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2",
    "mat4x3", "mat4x4", "array", "bitcast",
];

/// Binding power of the comparisons.
const CMP_BP: u8 = 3;

/// Tokens at which a missing expression is reported without consuming the token: they end or
/// delimit something the caller handles.
const EXPR_FOLLOW: TokenSet = TokenSet::new(&[
    TokenKind::Semi,
    TokenKind::Comma,
    TokenKind::RParen,
    TokenKind::RBracket,
    TokenKind::RBrace,
    TokenKind::LBrace,
    TokenKind::DotDot,
    TokenKind::Eq,
    TokenKind::Eof,
    TokenKind::Else,
    TokenKind::Fn,
    TokenKind::Struct,
    TokenKind::Const,
    TokenKind::Scene,
    TokenKind::Import,
    TokenKind::At,
    TokenKind::Gt,
    TokenKind::Shr,
])
.union(STMT_KEYWORDS)
.union(ASSIGN_OPS);

/// Assignment operators (never part of an expression).
pub(super) const ASSIGN_OPS: TokenSet = TokenSet::new(&[
    TokenKind::PlusEq,
    TokenKind::MinusEq,
    TokenKind::StarEq,
    TokenKind::SlashEq,
    TokenKind::PercentEq,
    TokenKind::AmpEq,
    TokenKind::PipeEq,
    TokenKind::CaretEq,
    TokenKind::ShlEq,
    TokenKind::ShrEq,
]);

/// The infix operator of a token and its binding power, under the restrictions.
fn binop(kind: TokenKind, r: Restrict) -> Option<(BinaryOp, u8)> {
    use TokenKind as T;
    Some(match kind {
        T::PipePipe => (BinaryOp::Or, 1),
        T::AmpAmp => (BinaryOp::And, 2),
        T::EqEq => (BinaryOp::Eq, CMP_BP),
        T::Ne => (BinaryOp::Ne, CMP_BP),
        T::Lt => (BinaryOp::Lt, CMP_BP),
        T::Le => (BinaryOp::Le, CMP_BP),
        T::Gt if !r.no_gt => (BinaryOp::Gt, CMP_BP),
        T::Ge if !r.no_gt => (BinaryOp::Ge, CMP_BP),
        T::Pipe => (BinaryOp::BitOr, 4),
        T::Caret => (BinaryOp::BitXor, 5),
        T::Amp => (BinaryOp::BitAnd, 6),
        T::Shl => (BinaryOp::Shl, 7),
        T::Shr if !r.no_gt => (BinaryOp::Shr, 7),
        T::Plus => (BinaryOp::Add, 8),
        T::Minus => (BinaryOp::Sub, 8),
        T::Star => (BinaryOp::Mul, 9),
        T::Slash => (BinaryOp::Div, 9),
        T::Percent => (BinaryOp::Rem, 9),
        _ => return None,
    })
}

/// The compound-assignment operator of a token (`+=` gives `Add`).
pub(super) fn assign_op(kind: TokenKind) -> Option<BinaryOp> {
    use TokenKind as T;
    Some(match kind {
        T::PlusEq => BinaryOp::Add,
        T::MinusEq => BinaryOp::Sub,
        T::StarEq => BinaryOp::Mul,
        T::SlashEq => BinaryOp::Div,
        T::PercentEq => BinaryOp::Rem,
        T::AmpEq => BinaryOp::BitAnd,
        T::PipeEq => BinaryOp::BitOr,
        T::CaretEq => BinaryOp::BitXor,
        T::ShlEq => BinaryOp::Shl,
        T::ShrEq => BinaryOp::Shr,
        _ => return None,
    })
}

fn prefix_op(kind: TokenKind) -> Option<UnaryOp> {
    match kind {
        TokenKind::Minus => Some(UnaryOp::Neg),
        TokenKind::Bang => Some(UnaryOp::Not),
        TokenKind::Tilde => Some(UnaryOp::BitNot),
        _ => None,
    }
}

/// Whether a token can start an expression.
pub(super) fn starts_expr(kind: TokenKind) -> bool {
    kind.is_literal()
        || matches!(
            kind,
            TokenKind::Ident
                | TokenKind::LParen
                | TokenKind::Minus
                | TokenKind::Bang
                | TokenKind::Tilde
        )
}

impl Parser<'_> {
    /// Parses an expression (one nesting level deeper).
    pub(super) fn expr(&mut self, r: Restrict) -> ExprId {
        let lo = self.span();
        if !self.enter(Nesting::Expression) {
            let span = self.since(lo);
            return self.error_expr(span);
        }
        let e = self.binary(0, r);
        self.leave();
        e
    }

    /// Binary operators binding at least as tightly as `min_bp`.
    fn binary(&mut self, min_bp: u8, r: Restrict) -> ExprId {
        let mut lhs = self.unary(r);
        // The operator of the comparison that produced `lhs` in this loop, for `a < b < c`.
        let mut comparison = None;
        loop {
            if self.at(TokenKind::As) {
                lhs = self.as_cast(lhs);
                continue;
            }
            let Some((op, bp)) = binop(self.kind(), r) else {
                break;
            };
            if bp < min_bp {
                break;
            }
            let op_span = self.bump();
            let rhs = self.binary(bp + 1, r);
            let span = self.expr_span(lhs).to(self.expr_span(rhs));
            if bp == CMP_BP {
                if let Some(first) = comparison.take() {
                    self.report(SyntaxError::ChainedComparison {
                        span: op_span,
                        first,
                    });
                    lhs = self.error_expr(span);
                    continue;
                }
                comparison = Some(op_span);
            } else {
                comparison = None;
            }
            let depth = 1 + self.depth_of(lhs).max(self.depth_of(rhs));
            if depth > super::MAX_EXPR_DEPTH {
                self.too_deep(Nesting::Expression, op_span);
                self.skip_rest(self.expr_stop(r));
                let span = self.since(span);
                return self.error_expr(span);
            }
            lhs = self.alloc(ExprKind::Binary { op, lhs, rhs }, span);
        }
        lhs
    }

    /// Tokens that end an expression under the restrictions, for skipping the rest of one.
    fn expr_stop(&self, r: Restrict) -> TokenSet {
        let mut stop = TokenSet::new(&[TokenKind::DotDot]).union(ASSIGN_OPS);
        if r.no_struct.is_some() {
            stop = stop.union(TokenSet::new(&[TokenKind::LBrace]));
        }
        if r.no_gt {
            stop = stop.union(TokenSet::new(&[
                TokenKind::Gt,
                TokenKind::Shr,
                TokenKind::Ge,
                TokenKind::ShrEq,
            ]));
        }
        stop
    }

    /// `x as T`: reported, the type skipped, the whole an error node.
    fn as_cast(&mut self, lhs: ExprId) -> ExprId {
        let as_span = self.bump();
        self.report(SyntaxError::AsCast { span: as_span });
        self.last_error_pos = self.pos;
        if self.at(TokenKind::Ident) {
            self.ty();
        }
        let span = self.since(self.expr_span(lhs));
        self.error_expr(span)
    }

    /// Prefix operators, collected in a loop, applied to a postfix expression.
    fn unary(&mut self, r: Restrict) -> ExprId {
        let mut ops = Vec::new();
        while let Some(op) = prefix_op(self.kind()) {
            let span = self.bump();
            ops.push((op, span));
            if ops.len() as u32 >= super::MAX_EXPR_DEPTH {
                self.too_deep(Nesting::Expression, span);
                self.skip_rest(self.expr_stop(r));
                let span = self.since(ops[0].1);
                return self.error_expr(span);
            }
        }
        let negated = ops.last().is_some_and(|(op, _)| *op == UnaryOp::Neg);
        let mut e = self.postfix(r, negated);
        for (op, op_span) in ops.into_iter().rev() {
            let span = op_span.to(self.expr_span(e));
            e = self.alloc(ExprKind::Unary { op, operand: e }, span);
        }
        e
    }

    /// A primary expression followed by `.field`, `[index]` (and misplaced `(…)`).
    fn postfix(&mut self, r: Restrict, negated: bool) -> ExprId {
        let mut e = self.primary(r, negated);
        loop {
            let lo = self.expr_span(e);
            match self.kind() {
                TokenKind::Dot => {
                    self.bump();
                    if self.at(TokenKind::Ident) {
                        let field = self.ident();
                        let span = lo.to(field.span);
                        e = self.alloc(ExprKind::Field { base: e, field }, span);
                    } else if matches!(self.kind(), TokenKind::Int | TokenKind::Float) {
                        self.expected(Expected::FieldName, Some(Hint::VectorComponents));
                        let end = self.bump();
                        e = self.error_expr(lo.to(end));
                    } else {
                        self.expected(Expected::FieldName, None);
                        let span = self.since(lo);
                        e = self.error_expr(span);
                    }
                }
                TokenKind::LBracket => {
                    let open = self.bump();
                    let index = self.expr(Restrict::NONE);
                    self.expect_close(TokenKind::RBracket, open);
                    let span = self.since(lo);
                    e = self.alloc(ExprKind::Index { base: e, index }, span);
                }
                TokenKind::LParen => {
                    let method = matches!(self.m.exprs[e].kind, ExprKind::Field { .. });
                    if !matches!(self.m.exprs[e].kind, ExprKind::Error) {
                        self.report(SyntaxError::CallOfNonName { span: lo, method });
                    }
                    self.call_args();
                    let span = self.since(lo);
                    e = self.error_expr(span);
                }
                _ => return e,
            }
        }
    }

    fn primary(&mut self, r: Restrict, negated: bool) -> ExprId {
        let lo = self.span();
        match self.kind() {
            TokenKind::Int | TokenKind::Float => {
                let span = self.bump();
                let (lit, _) = lexer::decode_number(self.text(span));
                if let Literal::Int {
                    value,
                    suffix: Some(IntSuffix::I),
                } = lit
                {
                    if value == 1 << 31 && !negated {
                        self.report(SyntaxError::NumberOutOfRange {
                            ty: RangeTy::I32,
                            span,
                        });
                    }
                }
                self.alloc(ExprKind::Lit(lit), span)
            }
            TokenKind::Str => {
                let span = self.bump();
                let s = lexer::unescape(self.text(span));
                self.alloc(ExprKind::Lit(Literal::String(s)), span)
            }
            TokenKind::True | TokenKind::False => {
                let value = self.at(TokenKind::True);
                let span = self.bump();
                self.alloc(ExprKind::Lit(Literal::Bool(value)), span)
            }
            TokenKind::Ident => self.name_expr(r),
            TokenKind::LParen => {
                let open = self.bump();
                let inner = self.expr(Restrict::NONE);
                self.expect_close(TokenKind::RParen, open);
                let span = self.since(lo);
                self.alloc(ExprKind::Paren(inner), span)
            }
            TokenKind::Dot if self.nth(1) == TokenKind::Int && self.tok(1).span.lo == lo.hi => {
                // `.5`
                self.bump();
                let digits_span = self.bump();
                let digits = self.text(digits_span).to_string();
                let span = lo.to(digits_span);
                let value = format!("0.{}", digits.replace('_', ""))
                    .parse::<f64>()
                    .unwrap_or(0.0);
                self.report(SyntaxError::MalformedNumber {
                    problem: NumberProblem::LeadingDot { digits },
                    span,
                });
                let lit = Literal::Float {
                    value,
                    suffix: None,
                };
                self.alloc(ExprKind::Lit(lit), span)
            }
            TokenKind::LBracket => {
                self.expected(Expected::Expression, Some(Hint::ArrayConstructor));
                self.bump();
                self.recover(TokenSet::new(&[TokenKind::RBracket]));
                self.eat(TokenKind::RBracket);
                let span = self.since(lo);
                self.error_expr(span)
            }
            k if binop(k, Restrict::NONE).is_some() => {
                // Stray operators (`let x = * 3;`): report, skip them, and read what follows.
                self.expected(Expected::Expression, None);
                while binop(self.kind(), Restrict::NONE).is_some()
                    || prefix_op(self.kind()).is_some()
                {
                    self.bump();
                }
                if matches!(
                    self.kind(),
                    TokenKind::Ident | TokenKind::LParen | TokenKind::Int | TokenKind::Float
                ) {
                    self.last_error_pos = self.pos;
                    let e = self.postfix(r, false);
                    let span = self.since(lo);
                    self.m.exprs[e].span = span;
                    e
                } else {
                    let span = self.since(lo);
                    self.error_expr(span)
                }
            }
            k => {
                self.expected(Expected::Expression, None);
                if EXPR_FOLLOW.contains(k) || self.at_item_line() {
                    self.error_expr(self.prev_end())
                } else {
                    let span = self.bump();
                    self.error_expr(span)
                }
            }
        }
    }

    /// A name, a call `f(…)`, a generic call `vec3<f32>(…)` or a struct literal `Name { … }`.
    fn name_expr(&mut self, r: Restrict) -> ExprId {
        let func = self.ident();
        let lo = func.span;
        if self.at(TokenKind::Lt) && GENERIC_NAMES.contains(&func.name.as_str()) {
            let generics = self.generic_args();
            if !self.at(TokenKind::LParen) {
                self.expected(Expected::Token(TokenKind::LParen), None);
                let span = self.since(lo);
                return self.error_expr(span);
            }
            let args = self.call_args();
            let span = self.since(lo);
            let kind = ExprKind::Call {
                func,
                generics: Some(generics),
                args,
            };
            return self.alloc(kind, span);
        }
        match self.kind() {
            TokenKind::LParen => {
                let args = self.call_args();
                let span = self.since(lo);
                let kind = ExprKind::Call {
                    func,
                    generics: None,
                    args,
                };
                self.alloc(kind, span)
            }
            TokenKind::LBrace => match r.no_struct {
                None => self.struct_lit(func),
                Some(context)
                    if self.nth(1) == TokenKind::Ident && self.nth(2) == TokenKind::Colon =>
                {
                    let e = self.struct_lit(func.clone());
                    let span = self.expr_span(e);
                    self.report(SyntaxError::StructLitInCondition {
                        context,
                        name: func.name,
                        span,
                    });
                    e
                }
                Some(_) => self.alloc(ExprKind::Name(func), lo),
            },
            _ => self.alloc(ExprKind::Name(func), lo),
        }
    }

    /// `( args )`, at the `(`.
    pub(super) fn call_args(&mut self) -> Vec<ExprId> {
        let open = self.bump();
        let stop = TokenSet::new(&[TokenKind::Semi, TokenKind::RBrace]).union(STMT_KEYWORDS);
        let args = self.list(TokenKind::RParen, stop, None, |p| {
            Some(p.expr(Restrict::NONE))
        });
        self.expect_close(TokenKind::RParen, open);
        args
    }

    /// `Name { field: value, … }`, at the `{`.
    fn struct_lit(&mut self, name: Ident) -> ExprId {
        let lo = name.span;
        let fields = self.field_inits();
        let span = self.since(lo);
        self.alloc(ExprKind::StructLit { name, fields }, span)
    }

    /// `{ name: value, … }` (struct literals, scene settings, objects, models), at the `{`.
    pub(super) fn field_inits(&mut self) -> Vec<FieldInit> {
        let open = self.bump();
        let stop = TokenSet::new(&[TokenKind::Semi]).union(STMT_KEYWORDS);
        let fields = self.list(
            TokenKind::RBrace,
            stop,
            Some(TokenKind::Ident),
            Parser::field_init,
        );
        self.expect_close(TokenKind::RBrace, open);
        fields
    }

    fn field_init(&mut self) -> Option<FieldInit> {
        let name = self.expect_ident()?;
        if !self.at(TokenKind::Colon) {
            if matches!(self.kind(), TokenKind::Comma | TokenKind::RBrace) {
                // `Foo { a }`: report, and read it as `a: a`.
                let hint = Hint::FieldShorthand {
                    name: name.name.clone(),
                };
                self.expected(Expected::Token(TokenKind::Colon), Some(hint));
                let value = self.alloc(ExprKind::Name(name.clone()), name.span);
                let span = name.span;
                return Some(FieldInit { name, value, span });
            }
            self.expected(Expected::Token(TokenKind::Colon), None);
            return None;
        }
        self.bump();
        let value = self.expr(Restrict::NONE);
        let span = self.since(name.span);
        Some(FieldInit { name, value, span })
    }
}
