//! Type expressions and generic argument lists.
//!
//! `type = name ('<' generic_arg (',' generic_arg)* ','? '>')?`. The only generic types are the
//! built-in `vecN<T>`, `matCxR<T>`, `array<T, N>` (and the callee `bitcast<T>`), so the parser reads
//! the **first** generic argument as a type and every further one as a constant expression (the
//! size of an array). This resolves the spec's `generic_arg = type | const_expr` ambiguity without
//! guessing from names: `array<f32, N>` gives `[Type(f32), Expr(N)]`.
//!
//! `>>` closes two lists (`array<vec3<f32>, 2>>`…): [`Parser::eat_gt`] splits `>>`, `>=` and `>>=`
//! in place, consuming only their first `>`.
//!
//! Invariant: type nesting counts towards [`super::MAX_DEPTH`].

use super::{Parser, Restrict};
use crate::source::Span;
use crate::syntax::ast::{GenericArg, TyId, TypeExpr, TypeExprKind};
use crate::syntax::error::{Expected, Nesting};
use crate::syntax::token::{Token, TokenKind, TokenSet};

/// Tokens at which a missing type is reported without consuming the token.
const TYPE_FOLLOW: TokenSet = TokenSet::new(&[
    TokenKind::Comma,
    TokenKind::RParen,
    TokenKind::Eq,
    TokenKind::Semi,
    TokenKind::LBrace,
    TokenKind::RBrace,
    TokenKind::Gt,
    TokenKind::Shr,
    TokenKind::Ge,
    TokenKind::ShrEq,
    TokenKind::Eof,
]);

impl Parser<'_> {
    /// A type expression.
    pub(super) fn ty(&mut self) -> TyId {
        let lo = self.span();
        if !self.at(TokenKind::Ident) {
            self.expected(Expected::Type, None);
            let span = if TYPE_FOLLOW.contains(self.kind()) || self.at_item_line() {
                self.prev_end()
            } else {
                self.bump()
            };
            return self.alloc_ty(TypeExprKind::Error, span);
        }
        if !self.enter(Nesting::Type) {
            let span = self.since(lo);
            return self.alloc_ty(TypeExprKind::Error, span);
        }
        let name = self.ident();
        let generics = if self.at(TokenKind::Lt) {
            self.generic_args()
        } else {
            Vec::new()
        };
        self.leave();
        let span = self.since(lo);
        self.alloc_ty(TypeExprKind::Named { name, generics }, span)
    }

    fn alloc_ty(&mut self, kind: TypeExprKind, span: Span) -> TyId {
        self.m.types.alloc(TypeExpr { kind, span })
    }

    /// `< type, expr, … >`, at the `<`.
    pub(super) fn generic_args(&mut self) -> Vec<GenericArg> {
        let open = self.bump();
        let mut args = Vec::new();
        let stop = TokenSet::new(&[
            TokenKind::Comma,
            TokenKind::Gt,
            TokenKind::Shr,
            TokenKind::Ge,
            TokenKind::ShrEq,
            TokenKind::LParen,
            TokenKind::RParen,
            TokenKind::Semi,
            TokenKind::LBrace,
            TokenKind::RBrace,
            TokenKind::Eq,
        ]);
        loop {
            if self.at_gt() || self.at(TokenKind::Eof) {
                break;
            }
            let before = self.pos;
            let arg = if args.is_empty() {
                GenericArg::Type(self.ty())
            } else {
                let r = Restrict {
                    no_gt: true,
                    ..Restrict::NONE
                };
                GenericArg::Expr(self.expr(r))
            };
            args.push(arg);
            if self.eat(TokenKind::Comma).is_some() {
                continue;
            }
            if self.at_gt() {
                break;
            }
            self.expected(Expected::OneOf(&[TokenKind::Comma, TokenKind::Gt]), None);
            self.recover(stop);
            if self.eat(TokenKind::Comma).is_none() || self.pos == before {
                break;
            }
        }
        if !self.eat_gt() {
            self.expect_close(TokenKind::Gt, open);
        }
        args
    }

    /// Whether the current token begins with `>`.
    fn at_gt(&self) -> bool {
        matches!(
            self.kind(),
            TokenKind::Gt | TokenKind::Shr | TokenKind::Ge | TokenKind::ShrEq
        )
    }

    /// Consumes one `>`: a whole `>` token, or the first character of `>>`, `>=`, `>>=` (the token
    /// becomes the rest: `>`, `=`, `>=`).
    pub(super) fn eat_gt(&mut self) -> bool {
        let rest = match self.kind() {
            TokenKind::Gt => {
                self.bump();
                return true;
            }
            TokenKind::Shr => TokenKind::Gt,
            TokenKind::Ge => TokenKind::Eq,
            TokenKind::ShrEq => TokenKind::Ge,
            _ => return false,
        };
        let span = self.span();
        let i = self.pos.min(self.toks.len() - 1);
        self.toks[i] = Token {
            kind: rest,
            span: Span::new(span.file, span.lo + 1, span.hi),
        };
        self.prev_hi = span.lo + 1;
        true
    }
}
