//! The call graph: recursion (E0801), the callee-first function order, intrinsics reachable from
//! program kinds that may not call them (E0604), and the static bound on rays spawned per
//! `@secondary_rays` call (E0802).
//!
//! The graph's edges are the [`ExprKind::Call`]s of each body. Depth-first search is iterative (no
//! stack overflow on long call chains); each back edge is one cycle, reported at the call that closes
//! it. [`Program::fn_order`](super::hir::Program::fn_order) is the DFS post-order without back edges,
//! so every callee precedes its callers.
//!
//! Spawn bound: a `spawn` counts 1, a call to a helper counts the helper's bound; each is multiplied by
//! the trip counts of the enclosing `for` loops with constant bounds. Inside `while`, `loop` or a `for`
//! with non-constant bounds, a spawning call cannot be bounded and is recorded as a site for E0802.
//! Both branches of an `if` count (an upper bound).

use super::builtins::Builtin;
use super::consteval::{self, Env};
use super::error::{CallGraphError, ProgramError, Unbounded};
use super::hir::{BinaryOp, Block, Body, ExprId, ExprKind, FnId, LocalId, ProgramKind, StmtKind};
use super::stmt::const_trip_count;
use super::{ix, Ctx};
use crate::source::Span;
use la_arena::{Idx, RawIdx};
use std::collections::HashSet;

/// Phase 7: recursion, order, intrinsics, spawn bounds.
pub(crate) fn analyze(cx: &mut Ctx) {
    let n = cx.p.functions.len();
    let mut edges: Vec<Vec<(FnId, Span)>> = vec![Vec::new(); n];
    let mut intrinsics: Vec<Vec<(Builtin, Span)>> = vec![Vec::new(); n];
    for (id, f) in cx.p.functions.iter() {
        for (_, e) in f.body.exprs.iter() {
            match &e.kind {
                ExprKind::Call { func, .. } => edges[ix(id)].push((*func, e.span)),
                ExprKind::Builtin { func, .. } if func.is_restricted() => {
                    intrinsics[ix(id)].push((*func, e.span));
                }
                _ => {}
            }
        }
    }
    for (id, f) in cx.p.functions.iter_mut() {
        let mut callees: Vec<FnId> = edges[ix(id)].iter().map(|(c, _)| *c).collect();
        callees.sort_unstable();
        callees.dedup();
        f.callees = callees;
    }
    let order = order_and_cycles(cx, &edges);
    check_intrinsics(cx, &edges, &intrinsics);
    spawn_bounds(cx, &order);
    additive_secondaries(cx);
    super::sizes::private_memory(cx, &order, &edges);
    cx.p.fn_order = order;
}

fn fn_id(i: usize) -> FnId {
    Idx::from_raw(RawIdx::from_u32(i as u32))
}

/// Iterative DFS: reports each back edge as a cycle and returns the post-order.
fn order_and_cycles(cx: &mut Ctx, edges: &[Vec<(FnId, Span)>]) -> Vec<FnId> {
    let n = edges.len();
    let mut color = vec![0u8; n]; // 0 new, 1 on the stack, 2 done
    let mut order = Vec::with_capacity(n);
    let mut stack: Vec<(usize, usize)> = Vec::new();
    for root in 0..n {
        if color[root] != 0 {
            continue;
        }
        color[root] = 1;
        stack.push((root, 0));
        while let Some(&mut (node, ref mut next)) = stack.last_mut() {
            if let Some(&(callee, span)) = edges[node].get(*next) {
                *next += 1;
                let c = ix(callee);
                match color[c] {
                    0 => {
                        color[c] = 1;
                        stack.push((c, 0));
                    }
                    1 => {
                        let start = stack.iter().position(|(x, _)| *x == c).unwrap_or(0);
                        let mut cycle: Vec<String> = stack[start..]
                            .iter()
                            .map(|(x, _)| cx.p.functions[fn_id(*x)].name.clone())
                            .collect();
                        cycle.push(cx.p.functions[callee].name.clone());
                        cx.err(CallGraphError::Recursion {
                            span,
                            cycle,
                            what: "function",
                        });
                    }
                    _ => {}
                }
            } else {
                color[node] = 2;
                order.push(fn_id(node));
                stack.pop();
            }
        }
    }
    order
}

/// E0604: every restricted intrinsic reachable from a program kind that may not call it.
fn check_intrinsics(
    cx: &mut Ctx,
    edges: &[Vec<(FnId, Span)>],
    intrinsics: &[Vec<(Builtin, Span)>],
) {
    let mut reported: HashSet<(Span, ProgramKind)> = HashSet::new();
    let programs: Vec<(FnId, ProgramKind)> =
        cx.p.functions
            .iter()
            .filter_map(|(id, f)| f.program.map(|k| (id, k)))
            .collect();
    for (root, kind) in programs {
        let mut visited = vec![false; edges.len()];
        let mut stack: Vec<(usize, usize)> = vec![(ix(root), 0)];
        visited[ix(root)] = true;
        visit_intrinsics(cx, ix(root), kind, &stack, intrinsics, &mut reported, root);
        while let Some(&mut (node, ref mut next)) = stack.last_mut() {
            if let Some(&(callee, _)) = edges[node].get(*next) {
                *next += 1;
                let c = ix(callee);
                if !visited[c] {
                    visited[c] = true;
                    stack.push((c, 0));
                    visit_intrinsics(cx, c, kind, &stack, intrinsics, &mut reported, root);
                }
            } else {
                stack.pop();
            }
        }
        if kind == ProgramKind::AnyHit {
            let absorbs = visited
                .iter()
                .enumerate()
                .any(|(i, v)| *v && intrinsics[i].iter().any(|(b, _)| *b == Builtin::Absorb));
            for entry in cx.p.programs.iter_mut().filter(|p| p.func == root) {
                entry.absorbs = absorbs;
            }
        }
    }
}

fn visit_intrinsics(
    cx: &mut Ctx,
    node: usize,
    kind: ProgramKind,
    path: &[(usize, usize)],
    intrinsics: &[Vec<(Builtin, Span)>],
    reported: &mut HashSet<(Span, ProgramKind)>,
    root: FnId,
) {
    for &(b, span) in &intrinsics[node] {
        if b.info().allowed.allows(kind) || !reported.insert((span, kind)) {
            continue;
        }
        let chain: Vec<String> = path
            .iter()
            .map(|(x, _)| cx.p.functions[fn_id(*x)].name.clone())
            .collect();
        let program = cx.p.functions[root].span;
        cx.err(ProgramError::IntrinsicNotAllowed {
            span,
            func: b,
            kind,
            chain,
            program,
        });
    }
}

/// The spawn bound of one function.
#[derive(Clone, Debug, Default)]
struct SpawnInfo {
    count: u64,
    sites: Vec<(Span, Unbounded, Span)>,
}

/// The loop context of a statement: the product of constant trip counts, or why it is unbounded.
#[derive(Clone, Copy)]
enum Mult {
    Bounded(u64),
    Unbounded(Unbounded, Span),
}

struct SpawnWalk<'b> {
    body: &'b Body,
    env: Env<'b>,
    infos: &'b [SpawnInfo],
    out: SpawnInfo,
}

impl SpawnWalk<'_> {
    fn calls(&self, e: ExprId, out: &mut Vec<ExprId>) {
        let expr = &self.body.exprs[e];
        match &expr.kind {
            ExprKind::Call { args, .. } => {
                out.push(e);
                args.iter().for_each(|a| self.calls(*a, out));
            }
            ExprKind::Builtin { func, args } => {
                if *func == Builtin::Spawn {
                    out.push(e);
                }
                args.iter().for_each(|a| self.calls(*a, out));
            }
            ExprKind::Compose { components } => components.iter().for_each(|a| self.calls(*a, out)),
            ExprKind::Unary { operand: x, .. }
            | ExprKind::Splat { value: x }
            | ExprKind::Convert { arg: x }
            | ExprKind::Bitcast { arg: x }
            | ExprKind::Field { base: x, .. }
            | ExprKind::Swizzle { base: x, .. } => self.calls(*x, out),
            ExprKind::Binary { lhs, rhs, .. } => {
                self.calls(*lhs, out);
                self.calls(*rhs, out);
            }
            ExprKind::Index { base, index } => {
                self.calls(*base, out);
                self.calls(*index, out);
            }
            _ => {}
        }
    }

    fn count(&mut self, exprs: &[ExprId], mult: Mult) {
        let mut calls = Vec::new();
        for e in exprs {
            self.calls(*e, &mut calls);
        }
        for c in calls {
            let span = self.body.exprs[c].span;
            let (unit, sites) = match &self.body.exprs[c].kind {
                ExprKind::Call { func, .. } => {
                    let info = &self.infos[ix(*func)];
                    (info.count, info.sites.as_slice())
                }
                _ => (1, &[][..]),
            };
            self.out.sites.extend_from_slice(sites);
            if unit == 0 {
                continue;
            }
            match mult {
                Mult::Bounded(m) => {
                    self.out.count = self.out.count.saturating_add(m.saturating_mul(unit));
                }
                Mult::Unbounded(why, l) => self.out.sites.push((span, why, l)),
            }
        }
    }

    fn block(&mut self, b: &Block, mult: Mult) {
        for s in &b.stmts {
            match &s.kind {
                StmtKind::Let { value, .. } => self.count(&[*value], mult),
                StmtKind::Var { value, .. } => self.count(value.as_slice(), mult),
                StmtKind::Assign { place, value, .. } => self.count(&[*place, *value], mult),
                StmtKind::Expr(e) => self.count(&[*e], mult),
                StmtKind::Return(v) => self.count(v.as_slice(), mult),
                StmtKind::If {
                    cond,
                    then_block,
                    else_block,
                } => {
                    self.count(&[*cond], mult);
                    // Only one branch runs: the bound is the larger of the two, not their sum.
                    let before = self.out.count;
                    self.block(then_block, mult);
                    let then_count = self.out.count - before;
                    self.out.count = before;
                    if let Some(e) = else_block {
                        self.block(e, mult);
                    }
                    let else_count = self.out.count - before;
                    self.out.count = before.saturating_add(then_count.max(else_count));
                }
                StmtKind::For {
                    start, end, body, ..
                } => {
                    self.count(&[*start, *end], mult);
                    let a = consteval::eval(self.body, *start, &self.env);
                    let z = consteval::eval(self.body, *end, &self.env);
                    let trip = match (a, z) {
                        (Ok(a), Ok(z)) => const_trip_count(&a, &z),
                        _ => None,
                    };
                    let header = Span::new(s.span.file, s.span.lo, self.body.exprs[*end].span.hi);
                    let inner = match (mult, trip) {
                        (Mult::Bounded(m), Some(t)) => Mult::Bounded(m.saturating_mul(t)),
                        (Mult::Bounded(_), None) => Mult::Unbounded(Unbounded::For, header),
                        (u, _) => u,
                    };
                    self.block(body, inner);
                }
                StmtKind::While { cond, body } => {
                    let header = Span::new(s.span.file, s.span.lo, self.body.exprs[*cond].span.hi);
                    let inner = Mult::Unbounded(Unbounded::While, header);
                    self.count(&[*cond], inner);
                    self.block(body, inner);
                }
                StmtKind::Loop { body } => {
                    let header = Span::new(s.span.file, s.span.lo, s.span.lo + 4);
                    self.block(body, Mult::Unbounded(Unbounded::Loop, header));
                }
                StmtKind::Block(b) => self.block(b, mult),
                StmtKind::Break | StmtKind::Continue => {}
            }
        }
    }
}

fn spawn_bounds(cx: &mut Ctx, order: &[FnId]) {
    let mut infos = vec![SpawnInfo::default(); cx.p.functions.len()];
    for &f in order {
        let func = &cx.p.functions[f];
        let mut walk = SpawnWalk {
            body: &func.body,
            env: Env {
                types: &cx.p.types,
                structs: &cx.p.structs,
                consts: &cx.p.consts,
                base_dir: None,
            },
            infos: &infos,
            out: SpawnInfo::default(),
        };
        walk.block(&func.block, Mult::Bounded(1));
        let mut out = walk.out;
        let mut seen = HashSet::new();
        out.sites.retain(|s| seen.insert(s.0));
        infos[ix(f)] = out;
    }
    let mut reported = HashSet::new();
    for i in 0..cx.p.programs.len() {
        let entry = cx.p.programs[i];
        if entry.kind != ProgramKind::SecondaryRays {
            continue;
        }
        let info = &infos[ix(entry.func)];
        cx.p.programs[i].spawn_bound = u32::try_from(info.count).unwrap_or(u32::MAX);
        let program = cx.p.functions[entry.func].name.clone();
        for &(span, why, loop_span) in &info.sites {
            if reported.insert(span) {
                cx.err(CallGraphError::UnboundedSpawn {
                    span,
                    why,
                    loop_span,
                    program: program.clone(),
                });
            }
        }
    }
}

/// Sets `ProgramEntry::additive_secondary` of every `@closest_hit` that takes `secondary`.
fn additive_secondaries(cx: &mut Ctx) {
    for i in 0..cx.p.programs.len() {
        let entry = cx.p.programs[i];
        if entry.kind != ProgramKind::ClosestHit || !entry.wants_secondary {
            continue;
        }
        let func = &cx.p.functions[entry.func];
        let Some(&secondary) = func.params.get(3) else {
            continue;
        };
        cx.p.programs[i].additive_secondary = is_additive(func, secondary);
    }
}

/// Whether every `return` of `func` is `E + secondary`, `secondary + E` or `secondary`, and those
/// are the only reads of the local `secondary` (so no `E` reads it).
fn is_additive(func: &super::hir::Function, secondary: LocalId) -> bool {
    let reads = |e: ExprId| matches!(func.body.exprs[e].kind, ExprKind::Local(l) if l == secondary);
    let mut returns = Vec::new();
    collect_returns(&func.block, &mut returns);
    let mut matched = 0usize;
    for r in returns {
        let Some(e) = r else {
            return false;
        };
        if reads(e) {
            matched += 1;
            continue;
        }
        match func.body.exprs[e].kind {
            ExprKind::Binary {
                op: BinaryOp::Add,
                lhs,
                rhs,
            } if reads(lhs) || reads(rhs) => matched += 1,
            _ => return false,
        }
    }
    let total = func.body.exprs.iter().filter(|(id, _)| reads(*id)).count();
    matched > 0 && matched == total
}

/// The values of every `return` in `b`, nested blocks included.
fn collect_returns(b: &Block, out: &mut Vec<Option<ExprId>>) {
    for s in &b.stmts {
        match &s.kind {
            StmtKind::Return(v) => out.push(*v),
            StmtKind::If {
                then_block,
                else_block,
                ..
            } => {
                collect_returns(then_block, out);
                if let Some(e) = else_block {
                    collect_returns(e, out);
                }
            }
            StmtKind::For { body, .. } | StmtKind::While { body, .. } | StmtKind::Loop { body } => {
                collect_returns(body, out);
            }
            StmtKind::Block(b) => collect_returns(b, out),
            _ => {}
        }
    }
}
