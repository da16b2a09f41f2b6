//! Function bodies: statements, scopes, places, and the structural control-flow facts that give
//! E0502 (`break` outside a loop), E0503 (a path without `return`), W0001 (unused variables) and W0003
//! (unreachable code).
//!
//! "Always returns" is structural, not a data-flow analysis: a block returns if one of its statements
//! does; `if` returns if both branches do; a `loop` without a `break` of its own never ends, so it
//! counts as returning; `for` and `while` never count (their body may not run). A statement after one
//! that always leaves the block (`return`, `break`, `continue`, or an `if`/block/loop that always does)
//! is unreachable; one W0003 per block, at the first such statement.
//!
//! Invariant: parameters and locals live in the function's [`Body`](crate::sema::hir::Body); a local is in scope from the
//! statement after its declaration to the end of its block.

use super::error::{ExprError, StmtError, Warning};
use super::expr::{binary_type, is_abstract, Binding, Checker, Mode, Splat};
use super::hir::{self, BinaryOp, ExprId, ExprKind, FnId, LocalId, LocalKind, Stmt, StmtKind};
use super::types::{TypeId, TypeTable};
use super::{ix, Ctx};
use crate::source::Span;
use crate::syntax::ast;
use la_arena::{Idx, RawIdx};

/// Control-flow facts of a statement or block.
#[derive(Clone, Copy, Debug, Default)]
struct Flow {
    /// Every path through it ends in `return` (or never ends).
    returns: bool,
    /// Every path leaves it (`return`, `break`, `continue`, or never ends).
    diverges: bool,
}

/// Phase 6: checks every function body.
pub(crate) fn check_bodies(cx: &mut Ctx) {
    let fns = cx.fns_ast.clone();
    for (i, (module, _, decl)) in fns.into_iter().enumerate() {
        let id: FnId = Idx::from_raw(RawIdx::from_u32(i as u32));
        let body = std::mem::take(&mut cx.p.functions[id].body);
        let params = cx.p.functions[id].params.clone();
        let ret = cx.p.functions[id].ret;
        let mut ck = Checker::new(cx, module, Mode::Function);
        ck.body = body;
        ck.ret = ret;
        for (p, pd) in params.iter().zip(&decl.params) {
            ck.scopes.push(pd.name.name.as_str(), Binding::Local(*p));
        }
        let (block, flow) = ck.block(&decl.body);
        if !flow.returns && ret != TypeTable::VOID && !TypeTable::is_error(ret) {
            let end = decl.body.span.end();
            let end = Span::new(end.file, end.lo.saturating_sub(1), end.hi);
            ck.err(StmtError::MissingReturn {
                span: decl.name.span,
                ret,
                end,
            });
        }
        ck.warn_unused();
        let body = std::mem::take(&mut ck.body);
        let f = &mut cx.p.functions[id];
        f.body = body;
        f.block = block;
    }
}

fn compound_str(op: BinaryOp) -> &'static str {
    use BinaryOp::*;
    match op {
        Add => "+=",
        Sub => "-=",
        Mul => "*=",
        Div => "/=",
        Rem => "%=",
        BitAnd => "&=",
        BitOr => "|=",
        BitXor => "^=",
        Shl => "<<=",
        Shr => ">>=",
        other => other.as_str(),
    }
}

/// Why an expression is not a place.
enum NotPlace {
    Multi,
    Other,
    Const(hir::ConstId),
}

impl<'a> Checker<'_, 'a> {
    fn warn_unused(&mut self) {
        let mut warns = Vec::new();
        for (id, l) in self.body.locals.iter() {
            let used = self.uses.get(ix(id)).copied().unwrap_or(0) > 0;
            if !used
                && l.kind != LocalKind::Param
                && !l.name.starts_with('_')
                && !TypeTable::is_error(l.ty)
            {
                warns.push(Warning::UnusedVariable {
                    span: l.span,
                    name: l.name.clone(),
                });
            }
        }
        for w in warns {
            self.err(w);
        }
    }

    fn block(&mut self, b: &'a ast::Block) -> (hir::Block, Flow) {
        let mark = self.scopes.len();
        let mut stmts = Vec::with_capacity(b.stmts.len());
        let mut flow = Flow::default();
        let mut cause: Option<Span> = None;
        let mut warned = false;
        for s in &b.stmts {
            if let (Some(c), false) = (cause, warned) {
                if !matches!(s.kind, ast::StmtKind::Error) {
                    self.err(Warning::Unreachable {
                        span: s.span,
                        cause: c,
                    });
                    warned = true;
                }
            }
            let (st, f) = self.stmt(s);
            if let Some(kind) = st {
                stmts.push(Stmt { kind, span: s.span });
            }
            if f.diverges && cause.is_none() {
                cause = Some(s.span);
            }
            flow.returns |= f.returns;
            flow.diverges |= f.diverges;
        }
        self.scopes.truncate(mark);
        (
            hir::Block {
                stmts,
                span: b.span,
            },
            flow,
        )
    }

    fn local_init(
        &mut self,
        ty: Option<ast::TyId>,
        value: Option<ast::ExprId>,
    ) -> (TypeId, Option<ExprId>) {
        let declared = ty.map(|t| {
            let ty = self.cx.resolve_type(self.module, t);
            let span = self.ast.types[t].span;
            self.cx.forbid_string(ty, span);
            ty
        });
        let v = value.map(|v| match declared {
            Some(t) => self.expect(v, t),
            None => self.expr(v, None),
        });
        let ty = match (declared, v) {
            (Some(t), _) => t,
            (None, Some(v)) => self.ty(v),
            (None, None) => TypeTable::ERROR,
        };
        if ty == TypeTable::VOID {
            let span = v.map(|v| self.span(v)).unwrap_or_default();
            self.err(ExprError::TypeNotAllowed {
                span,
                ty,
                context: "as a value (the function returns nothing)",
            });
            return (TypeTable::ERROR, v);
        }
        (ty, v)
    }

    fn stmt(&mut self, s: &'a ast::Stmt) -> (Option<StmtKind>, Flow) {
        let none = Flow::default();
        let kind = match &s.kind {
            ast::StmtKind::Let { name, ty, value } => {
                let (ty, v) = self.local_init(*ty, Some(*value));
                let local = self.declare(name, ty, LocalKind::Let);
                let value = v.unwrap_or_else(|| self.error_expr(s.span));
                StmtKind::Let { local, value }
            }
            ast::StmtKind::Var { name, ty, value } => {
                let (ty, value) = self.local_init(*ty, *value);
                let local = self.declare(name, ty, LocalKind::Var);
                StmtKind::Var { local, value }
            }
            ast::StmtKind::Assign { target, op, value } => {
                self.assign(*target, *op, *value, s.span)
            }
            ast::StmtKind::Expr(e) => {
                let id = self.expr(*e, None);
                let ty = self.ty(id);
                let is_call = matches!(self.ast.exprs[*e].kind, ast::ExprKind::Call { .. });
                if !is_call && ty != TypeTable::VOID && !TypeTable::is_error(ty) {
                    self.err(Warning::UnusedValue {
                        span: self.span(id),
                    });
                }
                StmtKind::Expr(id)
            }
            ast::StmtKind::If {
                cond,
                then_block,
                else_block,
            } => {
                let cond = self.condition(*cond);
                let (then_block, tf) = self.block(then_block);
                let (else_block, ef) = match else_block {
                    Some(b) => {
                        let (b, f) = self.block(b);
                        (Some(b), Some(f))
                    }
                    None => (None, None),
                };
                let flow = match ef {
                    Some(ef) => Flow {
                        returns: tf.returns && ef.returns,
                        diverges: tf.diverges && ef.diverges,
                    },
                    None => none,
                };
                return (
                    Some(StmtKind::If {
                        cond,
                        then_block,
                        else_block,
                    }),
                    flow,
                );
            }
            ast::StmtKind::For {
                var,
                start,
                end,
                body,
            } => self.for_loop(var, *start, *end, body),
            ast::StmtKind::While { cond, body } => {
                let cond = self.condition(*cond);
                self.loops.push(false);
                let (body, _) = self.block(body);
                self.loops.pop();
                StmtKind::While { cond, body }
            }
            ast::StmtKind::Loop { body } => {
                self.loops.push(false);
                let (body, _) = self.block(body);
                let broke = self.loops.pop().unwrap_or(true);
                let flow = Flow {
                    returns: !broke,
                    diverges: !broke,
                };
                return (Some(StmtKind::Loop { body }), flow);
            }
            ast::StmtKind::Break | ast::StmtKind::Continue => {
                let is_break = matches!(s.kind, ast::StmtKind::Break);
                match self.loops.last_mut() {
                    Some(b) => *b |= is_break,
                    None => self.err(StmtError::OutsideLoop {
                        span: s.span,
                        keyword: if is_break { "break" } else { "continue" },
                    }),
                }
                let kind = if is_break {
                    StmtKind::Break
                } else {
                    StmtKind::Continue
                };
                return (
                    Some(kind),
                    Flow {
                        returns: false,
                        diverges: true,
                    },
                );
            }
            ast::StmtKind::Return(v) => {
                let ret = self.ret;
                let value = match (v, ret == TypeTable::VOID) {
                    (Some(v), true) => {
                        let id = self.expr(*v, None);
                        self.err(StmtError::ReturnMismatch {
                            span: self.span(id),
                            expected: None,
                        });
                        Some(id)
                    }
                    (Some(v), false) => Some(self.expect(*v, ret)),
                    (None, false) => {
                        if !TypeTable::is_error(ret) {
                            self.err(StmtError::ReturnMismatch {
                                span: s.span,
                                expected: Some(ret),
                            });
                        }
                        None
                    }
                    (None, true) => None,
                };
                return (
                    Some(StmtKind::Return(value)),
                    Flow {
                        returns: true,
                        diverges: true,
                    },
                );
            }
            ast::StmtKind::Block(b) => {
                let (b, f) = self.block(b);
                return (Some(StmtKind::Block(b)), f);
            }
            ast::StmtKind::Error => return (None, none),
        };
        (Some(kind), none)
    }

    /// A condition of `if` or `while` (E0505 unless `bool`).
    fn condition(&mut self, e: ast::ExprId) -> ExprId {
        let id = self.expr(e, None);
        let ty = self.ty(id);
        if ty != TypeTable::BOOL && !TypeTable::is_error(ty) {
            self.err(StmtError::ConditionNotBool {
                span: self.span(id),
                found: ty,
            });
        }
        id
    }

    fn for_loop(
        &mut self,
        var: &'a ast::Ident,
        start: ast::ExprId,
        end: ast::ExprId,
        body: &'a ast::Block,
    ) -> StmtKind {
        let (sa, ea) = (is_abstract(self.ast, start), is_abstract(self.ast, end));
        let (s, e) = match (sa, ea) {
            (true, false) => {
                let e = self.expr(end, None);
                let h = self.hint_of(self.ty(e));
                (self.expr(start, h), e)
            }
            (false, true) => {
                let s = self.expr(start, None);
                let h = self.hint_of(self.ty(s));
                (s, self.expr(end, h))
            }
            _ => (self.expr(start, None), self.expr(end, None)),
        };
        let (st, et) = (self.ty(s), self.ty(e));
        let ok = st == et && (st == TypeTable::I32 || st == TypeTable::U32);
        let ty = if ok {
            st
        } else {
            if !TypeTable::is_error(st) && !TypeTable::is_error(et) {
                self.err(StmtError::BadRange {
                    span: self.span(s).to(self.span(e)),
                    start: st,
                    end: et,
                });
            }
            TypeTable::ERROR
        };
        let mark = self.scopes.len();
        let v = self.declare(var, ty, LocalKind::For);
        self.loops.push(false);
        let (body, _) = self.block(body);
        self.loops.pop();
        self.scopes.truncate(mark);
        StmtKind::For {
            var: v,
            start: s,
            end: e,
            body,
        }
    }

    /// The local a place is rooted at, or why it is not a place.
    fn place_root(&self, id: ExprId) -> Result<Option<LocalId>, NotPlace> {
        match &self.body.exprs[id].kind {
            ExprKind::Local(l) => Ok(Some(*l)),
            ExprKind::Field { base, .. } | ExprKind::Index { base, .. } => self.place_root(*base),
            ExprKind::Swizzle { base, len, .. } => {
                if *len > 1 {
                    Err(NotPlace::Multi)
                } else {
                    self.place_root(*base)
                }
            }
            ExprKind::Const(c) => Err(NotPlace::Const(*c)),
            ExprKind::Error => Ok(None),
            _ => Err(NotPlace::Other),
        }
    }

    fn assign(
        &mut self,
        target: ast::ExprId,
        op: Option<BinaryOp>,
        value: ast::ExprId,
        span: Span,
    ) -> StmtKind {
        let place = self.expr(target, None);
        let pt = self.ty(place);
        let pspan = self.span(place);
        match self.place_root(place) {
            Ok(Some(l)) => {
                if op.is_none() {
                    self.unuse_local(l);
                }
                let local = &self.body.locals[l];
                if local.kind != LocalKind::Var {
                    let err = StmtError::AssignImmutable {
                        span: pspan,
                        name: local.name.clone(),
                        kind: Some(local.kind),
                        decl: local.span,
                    };
                    self.err(err);
                }
            }
            Ok(None) => {}
            Err(NotPlace::Const(c)) => {
                let k = &self.cx.p.consts[c];
                let err = StmtError::AssignImmutable {
                    span: pspan,
                    name: k.name.clone(),
                    kind: None,
                    decl: k.span,
                };
                self.err(err);
            }
            Err(NotPlace::Multi) => self.err(StmtError::BadAssignTarget {
                span: pspan,
                multi_swizzle: true,
            }),
            Err(NotPlace::Other) => self.err(StmtError::BadAssignTarget {
                span: pspan,
                multi_swizzle: false,
            }),
        }
        let hint = self.hint_of(pt);
        let mut v = self.expr(value, hint);
        let vt = self.ty(v);
        match op {
            None => {
                self.coerce(v, pt);
            }
            Some(op) if !TypeTable::is_error(pt) && !TypeTable::is_error(vt) => {
                match binary_type(&mut self.cx.p.types, op, pt, vt) {
                    Some((ty, Splat::None)) if ty == pt => {}
                    Some((ty, Splat::Rhs)) if ty == pt => v = self.splat(v, pt),
                    _ => {
                        let rhs_span = self.span(v);
                        self.err(ExprError::BadOperands {
                            span,
                            op: compound_str(op),
                            lhs: pt,
                            rhs: vt,
                            lhs_span: pspan,
                            rhs_span,
                        });
                    }
                }
            }
            Some(_) => {}
        }
        StmtKind::Assign {
            place,
            op,
            value: v,
        }
    }
}

/// The trip count of `for` bounds that are both constant (used for spawn bounds).
pub(crate) fn const_trip_count(start: &hir::ConstValue, end: &hir::ConstValue) -> Option<u64> {
    use hir::{ConstValue as C, Scalar as S};
    let (a, b) = match (start, end) {
        (C::Scalar(S::I32(a)), C::Scalar(S::I32(b))) => (i64::from(*a), i64::from(*b)),
        (C::Scalar(S::U32(a)), C::Scalar(S::U32(b))) => (i64::from(*a), i64::from(*b)),
        _ => return None,
    };
    Some((b - a).max(0) as u64)
}
