//! HIR statements and function bodies to naga statements.
//!
//! Invariants:
//! - Structured control flow maps one to one: `if` → `If`; `loop` → `Loop`; `while c { b }` →
//!   `Loop { if !c { break; } b }`; `for i in a..b { body }` → `var i = a;` with `b` evaluated once
//!   before the loop, `Loop { if i >= end { break; } body; continuing { i = i + 1; } }`, so `continue`
//!   runs the increment (naga's `Continue` jumps to `continuing`).
//! - A `var` stores its initial value (or zero) where it is declared, not in the `LocalVariable`'s
//!   initialiser: that runs once per call, but a `var` inside a loop starts over on every iteration.
//! - Statements after `return`, `break` or `continue` in the same block are dead (W0003) and are not
//!   lowered.
//! - `if` on a constant condition (a literal or a `const` item: the link step's configuration
//!   constants) lowers only the taken branch, so code guarded by a disabled feature disappears.
//! - Every function body ends with a `Return`: a function whose last statement is not one gets
//!   `return;`, or `return` of the zero value of its result type on a path the checker proved
//!   unreachable (E0503 guarantees a value is returned on every path).

use super::builder::FnBuilder;
use super::expr::{FnCx, LocalValue};
use super::{Intrinsics, LowerError, Lowerer};
use crate::sema::hir::{
    Block, ConstValue, ExprId, ExprKind, FnId, Literal, LocalId, Scalar, Stmt, StmtKind,
};
use crate::sema::types::ScalarKind;
use naga::{BinaryOperator as Bo, Expression, Statement};

/// Lowers the body of HIR function `f` to a naga function (not yet appended to the module).
pub(super) fn lower_function(
    lw: &mut Lowerer<'_>,
    hooks: &mut dyn Intrinsics,
    f: FnId,
) -> Result<naga::Function, LowerError> {
    let program = lw.program;
    let func = &program.functions[f];
    let mut args = Vec::with_capacity(func.params.len());
    for &p in &func.params {
        let local = &func.body.locals[p];
        args.push((local.name.as_str(), lw.ty_at(local.ty, local.span)?));
    }
    let ret = lw.value_ty(func.ret, func.span)?;
    let fb = FnBuilder::new(&func.name, &args, ret);
    let mut cx = FnCx {
        lw,
        hooks,
        fb,
        program,
        func,
        fn_id: f,
        locals: vec![None; func.body.locals.len()],
    };
    for (i, &p) in func.params.iter().enumerate() {
        let h = cx.fb.arg(i as u32);
        cx.set_local(p, LocalValue::Value(h));
    }
    cx.block(&func.block)?;
    if !cx.fb.terminated() {
        let end = cx.lw.span(func.block.span.end());
        let value = ret.map(|t| cx.fb.expr(Expression::ZeroValue(t), end));
        cx.fb.ret(value, end);
    }
    Ok(cx.fb.finish())
}

impl FnCx<'_, '_> {
    /// Lowers the statements of a block into the current naga block, up to the first one that leaves it.
    pub fn block(&mut self, block: &Block) -> Result<(), LowerError> {
        for s in &block.stmts {
            self.stmt(s)?;
            if self.fb.terminated() {
                break;
            }
        }
        Ok(())
    }

    /// Lowers a block into a new naga block.
    fn nested(&mut self, block: &Block) -> Result<naga::Block, LowerError> {
        self.fb.push_block();
        let r = self.block(block);
        let b = self.fb.pop_block();
        r.map(|()| b)
    }

    fn stmt(&mut self, s: &Stmt) -> Result<(), LowerError> {
        let span = self.lw.span(s.span);
        match &s.kind {
            StmtKind::Let { local, value } => {
                let h = self.expr(*value)?;
                let name = &self.func.body.locals[*local].name;
                if !name.is_empty() && name != "_" {
                    self.fb.name(h, name);
                }
                self.set_local(*local, LocalValue::Value(h));
            }
            StmtKind::Var { local, value } => self.var(*local, *value, span)?,
            StmtKind::Assign { place, op, value } => {
                let p = self.place(*place)?.ok_or(LowerError::InvalidHir {
                    what: "an assignment to something that is not a place",
                    span: s.span,
                })?;
                let v = match op {
                    None => self.expr(*value)?,
                    Some(op) => {
                        let cur = self.fb.load(p, span);
                        let r = self.expr(*value)?;
                        let (pt, vt) = (self.hir_ty(*place), self.hir_ty(*value));
                        self.binary(*op, pt, vt, cur, r, span)?
                    }
                };
                self.fb.store(p, v, span);
            }
            StmtKind::Expr(e) => {
                self.value(*e)?;
            }
            StmtKind::If {
                cond,
                then_block,
                else_block,
            } => match self.const_bool(*cond) {
                Some(true) => self.block(then_block)?,
                Some(false) => {
                    if let Some(b) = else_block {
                        self.block(b)?;
                    }
                }
                None => {
                    let c = self.expr(*cond)?;
                    let accept = self.nested(then_block)?;
                    let reject = match else_block {
                        Some(b) => self.nested(b)?,
                        None => naga::Block::new(),
                    };
                    self.fb.stmt(
                        Statement::If {
                            condition: c,
                            accept,
                            reject,
                        },
                        span,
                    );
                }
            },
            StmtKind::For {
                var,
                start,
                end,
                body,
            } => self.for_loop(*var, *start, *end, body, span)?,
            StmtKind::While { cond, body } => {
                self.fb.push_block();
                let r = self.while_body(*cond, body, span);
                let b = self.fb.pop_block();
                r?;
                self.push_loop(b, naga::Block::new(), span);
            }
            StmtKind::Loop { body } => {
                let b = self.nested(body)?;
                self.push_loop(b, naga::Block::new(), span);
            }
            StmtKind::Break => self.fb.stmt(Statement::Break, span),
            StmtKind::Continue => self.fb.stmt(Statement::Continue, span),
            StmtKind::Return(value) => {
                let v = match value {
                    Some(e) => self.value(*e)?,
                    None => None,
                };
                self.fb.ret(v, span);
            }
            StmtKind::Block(b) => self.block(b)?,
        }
        Ok(())
    }

    fn var(
        &mut self,
        local: LocalId,
        value: Option<ExprId>,
        span: naga::Span,
    ) -> Result<(), LowerError> {
        let l = &self.func.body.locals[local];
        let ty = self.lw.ty_at(l.ty, l.span)?;
        let init = match value {
            Some(v) => self.expr(v)?,
            None => self.fb.expr(Expression::ZeroValue(ty), span),
        };
        let lspan = self.lw.span(l.span);
        let ptr = self.fb.local_at(&l.name, ty, Some(init), lspan);
        self.set_local(local, LocalValue::Pointer(ptr));
        Ok(())
    }

    /// The value of a condition known at compile time (a literal or a `const` item).
    fn const_bool(&self, cond: ExprId) -> Option<bool> {
        match &self.func.body.exprs[cond].kind {
            ExprKind::Literal(Literal::Bool(b)) => Some(*b),
            ExprKind::Value(ConstValue::Scalar(Scalar::Bool(b))) => Some(*b),
            ExprKind::Const(c) => match self.program.consts[*c].value {
                ConstValue::Scalar(Scalar::Bool(b)) => Some(b),
                _ => None,
            },
            _ => None,
        }
    }

    /// `if !cond { break; }` followed by the body, in the current (loop body) block.
    fn while_body(
        &mut self,
        cond: ExprId,
        body: &Block,
        span: naga::Span,
    ) -> Result<(), LowerError> {
        let c = self.expr(cond)?;
        let stop = self.fb.unary(naga::UnaryOperator::LogicalNot, c, span);
        self.break_if(stop, span);
        self.block(body)
    }

    /// `if cond { break; }`
    fn break_if(&mut self, cond: naga::Handle<Expression>, span: naga::Span) {
        self.fb.push_block();
        self.fb.stmt(Statement::Break, span);
        let brk = self.fb.pop_block();
        self.fb.stmt(
            Statement::If {
                condition: cond,
                accept: brk,
                reject: naga::Block::new(),
            },
            span,
        );
    }

    fn push_loop(&mut self, body: naga::Block, continuing: naga::Block, span: naga::Span) {
        self.fb.stmt(
            Statement::Loop {
                body,
                continuing,
                break_if: None,
            },
            span,
        );
    }

    fn for_loop(
        &mut self,
        var: LocalId,
        start: ExprId,
        end: ExprId,
        body: &Block,
        span: naga::Span,
    ) -> Result<(), LowerError> {
        let l = &self.func.body.locals[var];
        let ty = self.lw.ty_at(l.ty, l.span)?;
        let one = match self.types().scalar_kind(l.ty) {
            Some(ScalarKind::I32) => naga::Literal::I32(1),
            _ => naga::Literal::U32(1),
        };
        let s = self.expr(start)?;
        let e = self.expr(end)?;
        if !matches!(
            self.fb.function().expressions[e],
            Expression::Literal(_) | Expression::Constant(_)
        ) {
            self.fb.name(e, "end");
        }
        let lspan = self.lw.span(l.span);
        let ptr = self.fb.local_at(&l.name, ty, Some(s), lspan);
        self.set_local(var, LocalValue::Pointer(ptr));

        self.fb.push_block();
        let cur = self.fb.load(ptr, span);
        let done = self.fb.binary(Bo::GreaterEqual, cur, e, span);
        self.break_if(done, span);
        let r = self.block(body);
        let loop_body = self.fb.pop_block();
        r?;

        self.fb.push_block();
        let cur = self.fb.load(ptr, span);
        let one = self.fb.literal(one);
        let next = self.fb.binary(Bo::Add, cur, one, span);
        self.fb.store(ptr, next, span);
        let continuing = self.fb.pop_block();
        self.push_loop(loop_body, continuing, span);
        Ok(())
    }
}
