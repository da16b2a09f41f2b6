//! Blocks and statements (spec/statements.md).
//!
//! A block is `{ stmt* }`. Statement recovery skips to the next `;` (consumed), `}` or statement
//! keyword. An item keyword inside a block is read two ways: written at column 0 it is taken as the
//! next item of the file, so the block is reported as unclosed and ends there (the usual cause is a
//! missing `}`); indented, it is a nested item, reported as `E0206`, parsed and dropped.
//!
//! Invariants:
//! - `else if` is an `else` block holding exactly one `If` statement, with the block's span equal to
//!   the statement's.
//! - An assignment's target is a name, field, index or parenthesised place as written, or an error
//!   node (invalid targets are reported as `E0205` and replaced); multi-component swizzles are
//!   accepted here and rejected by semantic analysis.
//! - Every statement's span includes its trailing `;`.

use super::exprs::{assign_op, starts_expr, ASSIGN_OPS};
use super::{Parser, Restrict, ITEM_START, STMT_KEYWORDS};
use crate::source::Span;
use crate::syntax::ast::{BinaryOp, Block, ExprId, ExprKind, Stmt, StmtKind, TypeExprKind};
use crate::syntax::error::{CondContext, Expected, Hint, Nesting, Place, SyntaxError};
use crate::syntax::token::{TokenKind, TokenSet};

/// Where statement recovery stops.
const STMT_RECOVERY: TokenSet =
    TokenSet::new(&[TokenKind::Semi, TokenKind::RBrace]).union(STMT_KEYWORDS);

impl Parser<'_> {
    /// `{ stmts }`. Without a `{`, reports it and returns an empty block (nothing consumed).
    pub(super) fn block(&mut self) -> Block {
        let lo = self.span();
        if !self.at(TokenKind::LBrace) {
            self.expected(Expected::Token(TokenKind::LBrace), Some(Hint::NeedsBraces));
            return Block {
                stmts: Vec::new(),
                span: self.prev_end(),
            };
        }
        if !self.enter(Nesting::Block) {
            return Block {
                stmts: Vec::new(),
                span: self.since(lo),
            };
        }
        let open = self.bump();
        let mut stmts = Vec::new();
        loop {
            if matches!(self.kind(), TokenKind::RBrace | TokenKind::Eof) || self.at_item_line() {
                break;
            }
            let before = self.pos;
            stmts.push(self.stmt());
            if self.pos == before {
                self.bump();
            }
        }
        self.expect_close(TokenKind::RBrace, open);
        self.leave();
        Block {
            stmts,
            span: self.since(lo),
        }
    }

    /// One statement.
    fn stmt(&mut self) -> Stmt {
        let lo = self.span();
        let kind = match self.kind() {
            TokenKind::Let => self.let_stmt(),
            TokenKind::Var => self.var_stmt(),
            TokenKind::If => self.if_stmt(),
            TokenKind::For => self.for_stmt(),
            TokenKind::While => {
                self.bump();
                let cond = self.cond(CondContext::While);
                let body = self.block();
                StmtKind::While { cond, body }
            }
            TokenKind::Loop => {
                self.bump();
                StmtKind::Loop { body: self.block() }
            }
            TokenKind::Break | TokenKind::Continue => {
                let is_break = self.at(TokenKind::Break);
                self.bump();
                self.expect_semi();
                if is_break {
                    StmtKind::Break
                } else {
                    StmtKind::Continue
                }
            }
            TokenKind::Return => {
                self.bump();
                let value = if matches!(self.kind(), TokenKind::Semi | TokenKind::RBrace) {
                    None
                } else {
                    Some(self.expr(Restrict::NONE))
                };
                self.expect_semi();
                StmtKind::Return(value)
            }
            TokenKind::LBrace => StmtKind::Block(self.block()),
            TokenKind::Semi => {
                self.expected(Expected::Statement, Some(Hint::RemoveSemicolon));
                self.bump();
                StmtKind::Error
            }
            k if ITEM_START.contains(k) => {
                self.report(SyntaxError::MisplacedItem {
                    keyword: k,
                    place: Place::Block,
                    span: lo,
                });
                self.nested_item();
                StmtKind::Error
            }
            k if starts_expr(k) => self.expr_stmt(),
            _ => {
                self.expected(Expected::Statement, None);
                self.recover(STMT_RECOVERY);
                self.eat(TokenKind::Semi);
                StmtKind::Error
            }
        };
        Stmt {
            kind,
            span: self.since(lo),
        }
    }

    /// `let name (: T)? = value;`
    fn let_stmt(&mut self) -> StmtKind {
        self.bump();
        if self.cur_text() == "mut" && self.nth(1) == TokenKind::Ident {
            self.bump();
            self.expected(
                Expected::OneOf(&[TokenKind::Colon, TokenKind::Eq]),
                Some(Hint::UseVar),
            );
        }
        let Some(name) = self.expect_ident() else {
            return self.skip_stmt();
        };
        let ty = self.eat(TokenKind::Colon).map(|_| self.ty());
        let value = if self.eat(TokenKind::Eq).is_some() {
            self.expr(Restrict::NONE)
        } else {
            let hint = self.at(TokenKind::Semi).then_some(Hint::LetNeedsValue);
            self.expected(Expected::Token(TokenKind::Eq), hint);
            if !self.at(TokenKind::Semi) {
                self.recover(STMT_RECOVERY);
            }
            self.error_expr(self.prev_end())
        };
        self.expect_semi();
        StmtKind::Let { name, ty, value }
    }

    /// `var name (: T)? (= value)?;`
    fn var_stmt(&mut self) -> StmtKind {
        let lo = self.bump();
        let Some(name) = self.expect_ident() else {
            return self.skip_stmt();
        };
        let mut ty = self.eat(TokenKind::Colon).map(|_| self.ty());
        let value = self.eat(TokenKind::Eq).map(|_| self.expr(Restrict::NONE));
        if ty.is_none() && value.is_none() {
            if self.at(TokenKind::Semi) {
                let span = lo.to(self.span());
                self.report(SyntaxError::VarNeedsTypeOrValue {
                    name: name.name.clone(),
                    span,
                });
                self.last_error_pos = self.pos;
            } else {
                self.expected(
                    Expected::OneOf(&[TokenKind::Colon, TokenKind::Eq, TokenKind::Semi]),
                    None,
                );
            }
            // Keep the name bound, with a type that later phases skip silently.
            let span = self.prev_end();
            ty = Some(self.m.types.alloc(crate::syntax::ast::TypeExpr {
                kind: TypeExprKind::Error,
                span,
            }));
        }
        self.expect_semi();
        StmtKind::Var { name, ty, value }
    }

    /// Skips a statement that cannot be parsed (the error is reported).
    fn skip_stmt(&mut self) -> StmtKind {
        self.recover(STMT_RECOVERY);
        self.eat(TokenKind::Semi);
        StmtKind::Error
    }

    /// `if cond { … } (else (if … | { … }))?`
    fn if_stmt(&mut self) -> StmtKind {
        self.bump();
        let cond = self.cond(CondContext::If);
        let then_block = self.block();
        let mut else_block = None;
        if self.eat(TokenKind::Else).is_some() {
            if self.at(TokenKind::If) {
                let lo = self.span();
                if self.enter(Nesting::Block) {
                    let kind = self.if_stmt();
                    self.leave();
                    let span = self.since(lo);
                    else_block = Some(Block {
                        stmts: vec![Stmt { kind, span }],
                        span,
                    });
                }
            } else if self.at(TokenKind::LBrace) {
                else_block = Some(self.block());
            } else {
                self.expected(Expected::OneOf(&[TokenKind::LBrace, TokenKind::If]), None);
            }
        }
        StmtKind::If {
            cond,
            then_block,
            else_block,
        }
    }

    /// The condition of `if`/`while`: no struct literals; `=` is taken for `==` after an error.
    fn cond(&mut self, context: CondContext) -> ExprId {
        let r = Restrict {
            no_struct: Some(context),
            ..Restrict::NONE
        };
        let lhs = self.expr(r);
        if !self.at(TokenKind::Eq) {
            return lhs;
        }
        self.expected(Expected::Token(TokenKind::LBrace), Some(Hint::UseEqEq));
        self.bump();
        let rhs = self.expr(r);
        let span = self.expr_span(lhs).to(self.expr_span(rhs));
        let kind = ExprKind::Binary {
            op: BinaryOp::Eq,
            lhs,
            rhs,
        };
        self.alloc(kind, span)
    }

    /// `for name in start..end { … }`
    fn for_stmt(&mut self) -> StmtKind {
        self.bump();
        let to_block = TokenSet::new(&[TokenKind::LBrace, TokenKind::Semi, TokenKind::RBrace]);
        let Some(var) = self.expect_ident() else {
            self.recover(to_block);
            self.block();
            return StmtKind::Error;
        };
        if !self.expect(TokenKind::In) {
            self.recover(to_block);
            self.block();
            return StmtKind::Error;
        }
        let r = Restrict {
            no_struct: Some(CondContext::For),
            ..Restrict::NONE
        };
        let start = self.expr(r);
        let end = if self.eat(TokenKind::DotDot).is_some() {
            self.expr(r)
        } else {
            self.expected(Expected::Token(TokenKind::DotDot), Some(Hint::RangeSyntax));
            self.recover(to_block);
            self.error_expr(self.prev_end())
        };
        let body = self.block();
        StmtKind::For {
            var,
            start,
            end,
            body,
        }
    }

    /// `expr;`, `place = expr;` or `place op= expr;`
    fn expr_stmt(&mut self) -> StmtKind {
        let target = self.expr(Restrict::NONE);
        let op = if self.at(TokenKind::Eq) {
            None
        } else if ASSIGN_OPS.contains(self.kind()) {
            assign_op(self.kind())
        } else {
            self.expect_semi();
            return StmtKind::Expr(target);
        };
        let op_span = self.bump();
        let target = self.checked_target(target, op_span);
        let value = self.expr(Restrict::NONE);
        self.expect_semi();
        StmtKind::Assign { target, op, value }
    }

    /// The target itself if it can be assigned to; otherwise `E0205` and an error node.
    fn checked_target(&mut self, target: ExprId, op_span: Span) -> ExprId {
        let mut e = target;
        loop {
            match &self.m.exprs[e].kind {
                ExprKind::Paren(inner) => e = *inner,
                ExprKind::Name(_)
                | ExprKind::Field { .. }
                | ExprKind::Index { .. }
                | ExprKind::Error => return target,
                _ => break,
            }
        }
        let span = self.expr_span(target);
        self.report(SyntaxError::InvalidAssignTarget { span, op_span });
        self.error_expr(span)
    }

    /// An item where only statements may be: parsed (for its own errors) and dropped.
    pub(super) fn nested_item(&mut self) {
        if !self.enter(Nesting::Block) {
            return;
        }
        if self.at(TokenKind::Import) {
            let _ = self.import();
        } else {
            self.item();
        }
        self.leave();
    }
}
