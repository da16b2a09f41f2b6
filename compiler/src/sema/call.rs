//! Calls: user functions, built-in functions (overload resolution), and type names used as
//! constructors and conversions (`vec3f(…)`, `mat3x3f(…)`, `array<f32, 3>(…)`, `f32(x)`,
//! `bitcast<u32>(x)`).
//!
//! Invariants: arguments are always checked, even when the callee is wrong (so mistakes inside them
//! are reported and locals count as used); a call with an argument of the error type reports nothing
//! more and has the error type.

use super::builtins::{self, Builtin, Resolution};
use super::error::{CtorError, ExprError, NameError, NameKind};
use super::expr::{is_abstract, Checker, Hint, Mode};
use super::hir::{ConstValue, ExprId, ExprKind, FnId, Scalar};
use super::types::{ScalarKind, Type, TypeId, TypeTable};
use super::{Def, Found, TypeCtor};
use crate::source::Span;
use crate::syntax::ast;

impl<'a> Checker<'_, 'a> {
    /// Checks arguments whose callee is unusable, and returns an error expression.
    fn args_then_error(&mut self, args: &[ast::ExprId], span: Span) -> ExprId {
        for a in args {
            self.expr(*a, None);
        }
        self.error_expr(span)
    }

    fn any_error(&self, ids: &[ExprId]) -> bool {
        ids.iter().any(|i| TypeTable::is_error(self.ty(*i)))
    }

    /// Checks arguments in two passes: typed ones first, then untyped literals with the hint `hint`
    /// computes from the known types.
    fn args_two_pass(
        &mut self,
        args: &[ast::ExprId],
        hint: impl Fn(&Self, usize, &[Option<TypeId>]) -> Hint,
    ) -> Vec<ExprId> {
        let mut ids: Vec<Option<ExprId>> = vec![None; args.len()];
        let mut known: Vec<Option<TypeId>> = vec![None; args.len()];
        for (i, a) in args.iter().enumerate() {
            if !is_abstract(self.ast, *a) {
                let id = self.expr(*a, None);
                known[i] = Some(self.ty(id));
                ids[i] = Some(id);
            }
        }
        for (i, a) in args.iter().enumerate() {
            if ids[i].is_none() {
                let h = hint(self, i, &known);
                ids[i] = Some(self.expr(*a, h));
            }
        }
        ids.into_iter().flatten().collect()
    }

    /// `func(args)` with optional generic arguments.
    pub fn call(
        &mut self,
        func: &'a ast::Ident,
        generics: Option<&'a [ast::GenericArg]>,
        args: &'a [ast::ExprId],
        _hint: Hint,
        span: Span,
    ) -> ExprId {
        if let Some(b) = self.lookup_local(&func.name) {
            if let super::expr::Binding::Local(l) = b {
                let l = *l;
                self.use_local(l);
            }
            self.err(ExprError::NotCallable {
                span: func.span,
                name: func.name.clone(),
                kind: NameKind::Local,
            });
            return self.args_then_error(args, span);
        }
        let found = self.cx.lookup(self.module, &func.name);
        match found {
            Found::Def(Def::Fn(f)) => self.user_call(f, func, generics, args, span),
            Found::Def(Def::Struct(s)) => {
                let ty = self.cx.p.types.intern(Type::Struct(s));
                self.err(ExprError::BadConstructor {
                    span: func.span,
                    ty,
                    reason: CtorError::Struct,
                });
                self.args_then_error(args, span)
            }
            Found::Def(def @ (Def::Const(_) | Def::Scene(_))) => {
                let kind = if matches!(def, Def::Const(_)) {
                    NameKind::Const
                } else {
                    NameKind::Scene
                };
                self.err(ExprError::NotCallable {
                    span: func.span,
                    name: func.name.clone(),
                    kind,
                });
                self.args_then_error(args, span)
            }
            Found::Builtin(b) => {
                if generics.is_some() {
                    self.bad_generics(func, "no generic arguments");
                }
                self.builtin_call(b, func, args, span)
            }
            Found::Type(ctor) => self.construct(ctor, func, generics, args, span),
            Found::None | Found::Ambiguous(_) => {
                self.cx.report_lookup(self.module, func, found);
                self.args_then_error(args, span)
            }
        }
    }

    fn bad_generics(&mut self, func: &ast::Ident, expected: &'static str) {
        self.err(NameError::BadGenerics {
            span: func.span,
            name: func.name.clone(),
            expected,
        });
    }

    fn user_call(
        &mut self,
        f: FnId,
        func: &ast::Ident,
        generics: Option<&[ast::GenericArg]>,
        args: &[ast::ExprId],
        span: Span,
    ) -> ExprId {
        if generics.is_some() {
            self.bad_generics(func, "no generic arguments");
        }
        let sig = self.cx.ensure_sig(f);
        let (params, ret, decl) = (sig.params.clone(), sig.ret, sig.span);
        if TypeTable::is_error(ret) {
            return self.args_then_error(args, span);
        }
        let mut ids = Vec::with_capacity(args.len());
        for (i, a) in args.iter().enumerate() {
            ids.push(match params.get(i) {
                Some(t) => self.expect(*a, *t),
                None => self.expr(*a, None),
            });
        }
        if args.len() != params.len() {
            self.err(ExprError::Arity {
                span,
                name: func.name.clone(),
                expected: vec![params.len()],
                found: args.len(),
                decl: Some(decl),
            });
            return self.error_expr(span);
        }
        if self.any_error(&ids) || TypeTable::is_error(ret) {
            return self.error_expr(span);
        }
        self.alloc(ExprKind::Call { func: f, args: ids }, ret, span)
    }

    fn builtin_call(
        &mut self,
        b: Builtin,
        func: &ast::Ident,
        args: &[ast::ExprId],
        span: Span,
    ) -> ExprId {
        let n = args.len();
        let ids = self.args_two_pass(args, |ck, i, known| {
            builtins::literal_hint(b, n, i, known, &ck.cx.p.types)
        });
        if b.info().allowed == builtins::Allowed::SceneOnly && self.mode != Mode::Scene {
            self.err(ExprError::SceneOnly {
                span: func.span,
                func: b,
            });
            return self.error_expr(span);
        }
        if self.any_error(&ids) {
            return self.error_expr(span);
        }
        let tys: Vec<TypeId> = ids.iter().map(|i| self.ty(*i)).collect();
        let fw = self.cx.p.framework;
        match builtins::resolve(b, &tys, &fw, &mut self.cx.p.types) {
            Resolution::Match { ret, .. } => {
                if b == Builtin::SphereMesh {
                    if let (Some(&arg), true) = (ids.first(), self.mode == Mode::Scene) {
                        if let Ok(ConstValue::Scalar(Scalar::U32(n))) = self.try_eval(arg) {
                            let at = self.span(arg);
                            if let Some(e) = super::limits::sphere_subdivisions(n, at) {
                                self.err(e);
                                return self.error_expr(span);
                            }
                        }
                    }
                }
                self.alloc(ExprKind::Builtin { func: b, args: ids }, ret, span)
            }
            Resolution::Arity => {
                let mut expected: Vec<usize> =
                    b.info().overloads.iter().map(|o| o.params.len()).collect();
                expected.sort_unstable();
                expected.dedup();
                self.err(ExprError::Arity {
                    span,
                    name: func.name.clone(),
                    expected,
                    found: n,
                    decl: None,
                });
                self.error_expr(span)
            }
            Resolution::NoMatch => {
                self.err(ExprError::NoOverload {
                    span,
                    func: b,
                    args: tys,
                });
                self.error_expr(span)
            }
        }
    }

    fn ctor_error(&mut self, span: Span, ty: TypeId, reason: CtorError) -> ExprId {
        self.err(ExprError::BadConstructor { span, ty, reason });
        self.error_expr(span)
    }

    /// A generic argument that must be a type.
    fn generic_ty(&mut self, g: &ast::GenericArg) -> Option<TypeId> {
        match g {
            ast::GenericArg::Type(t) => Some(self.cx.resolve_type(self.module, *t)),
            ast::GenericArg::Expr(_) => None,
        }
    }

    fn construct(
        &mut self,
        ctor: TypeCtor,
        func: &'a ast::Ident,
        generics: Option<&'a [ast::GenericArg]>,
        args: &'a [ast::ExprId],
        span: Span,
    ) -> ExprId {
        match ctor {
            TypeCtor::Scalar(k) => {
                if generics.is_some() {
                    self.bad_generics(func, "no generic arguments");
                }
                self.scalar_ctor(k, args, span)
            }
            TypeCtor::Vector { size, scalar } => {
                let scalar = match (scalar, generics) {
                    (s, None) => s,
                    (None, Some([g])) => match self.generic_ty(g).map(|t| self.cx.p.types.get(t)) {
                        Some(Type::Scalar(k)) => Some(k),
                        Some(Type::Error) => return self.args_then_error(args, span),
                        _ => {
                            self.bad_generics(func, "one scalar type, as in `vec3<f32>`");
                            return self.args_then_error(args, span);
                        }
                    },
                    _ => {
                        self.bad_generics(func, "no generic arguments");
                        return self.args_then_error(args, span);
                    }
                };
                self.vector_ctor(size, scalar, args, span)
            }
            TypeCtor::Matrix { cols, rows, short } => {
                let ok = match generics {
                    None => true,
                    Some([g]) if !short => self.generic_ty(g) == Some(TypeTable::F32),
                    _ => false,
                };
                if !ok {
                    self.bad_generics(func, "`<f32>` (matrices are of `f32`)");
                    return self.args_then_error(args, span);
                }
                self.matrix_ctor(cols, rows, args, span)
            }
            TypeCtor::Array => self.array_ctor(func, generics, args, span),
            TypeCtor::Bitcast => self.bitcast(func, generics, args, span),
            TypeCtor::Texture | TypeCtor::Mesh | TypeCtor::String => {
                let ty = match ctor {
                    TypeCtor::Texture => TypeTable::TEXTURE,
                    TypeCtor::Mesh => TypeTable::MESH,
                    _ => TypeTable::STRING,
                };
                for a in args {
                    self.expr(*a, None);
                }
                self.ctor_error(span, ty, CtorError::NotConstructible)
            }
        }
    }

    fn scalar_ctor(&mut self, k: ScalarKind, args: &[ast::ExprId], span: Span) -> ExprId {
        let ty = TypeTable::scalar(k);
        match args {
            [] => self.alloc(ExprKind::Zero, ty, span),
            [a] => {
                let x = self.expr(*a, Some(k));
                let at = self.ty(x);
                match self.cx.p.types.get(at) {
                    Type::Error => self.error_expr(span),
                    Type::Scalar(_) => self.alloc(ExprKind::Convert { arg: x }, ty, span),
                    _ => self.ctor_error(span, ty, CtorError::Convert { from: at }),
                }
            }
            _ => {
                for a in args {
                    self.expr(*a, Some(k));
                }
                self.ctor_error(
                    span,
                    ty,
                    CtorError::Count {
                        expected: 1,
                        found: args.len() as u32,
                    },
                )
            }
        }
    }

    fn vector_ctor(
        &mut self,
        size: u8,
        scalar: Option<ScalarKind>,
        args: &[ast::ExprId],
        span: Span,
    ) -> ExprId {
        let ids = match scalar {
            Some(k) => args.iter().map(|a| self.expr(*a, Some(k))).collect(),
            None => self.args_two_pass(args, |ck, i, known| {
                known
                    .iter()
                    .flatten()
                    .find_map(|t| ck.cx.p.types.scalar_kind(*t))
                    .or_else(|| Some(super::expr::abstract_default(ck.ast, args[i])))
            }),
        };
        if self.any_error(&ids) {
            return self.error_expr(span);
        }
        let k = scalar
            .or_else(|| {
                ids.first()
                    .and_then(|i| self.cx.p.types.scalar_kind(self.ty(*i)))
            })
            .unwrap_or(ScalarKind::I32);
        let ty = self.cx.p.types.scalar_or_vector(size, k);
        let elem = TypeTable::scalar(k);
        if ids.is_empty() {
            return self.alloc(ExprKind::Zero, ty, span);
        }
        if let [x] = ids[..] {
            let xt = self.ty(x);
            match self.cx.p.types.get(xt) {
                Type::Scalar(xk) if xk == k => {
                    return self.alloc(ExprKind::Splat { value: x }, ty, span);
                }
                Type::Vector { size: s, .. } if s == size => {
                    return self.alloc(ExprKind::Convert { arg: x }, ty, span);
                }
                _ => {}
            }
        }
        let mut total = 0u32;
        for &x in &ids {
            let xt = self.ty(x);
            match self.cx.p.types.get(xt) {
                Type::Scalar(xk) | Type::Vector { scalar: xk, .. } if xk == k => {
                    total += u32::from(self.cx.p.types.width(xt).unwrap_or(1));
                }
                _ => {
                    let xs = self.span(x);
                    return self.ctor_error(
                        xs,
                        ty,
                        CtorError::Component {
                            expected: elem,
                            found: xt,
                        },
                    );
                }
            }
        }
        if total != u32::from(size) {
            return self.ctor_error(
                span,
                ty,
                CtorError::Count {
                    expected: u32::from(size),
                    found: total,
                },
            );
        }
        self.alloc(ExprKind::Compose { components: ids }, ty, span)
    }

    fn matrix_ctor(&mut self, cols: u8, rows: u8, args: &[ast::ExprId], span: Span) -> ExprId {
        let ids: Vec<ExprId> = args
            .iter()
            .map(|a| self.expr(*a, Some(ScalarKind::F32)))
            .collect();
        if self.any_error(&ids) {
            return self.error_expr(span);
        }
        let ty = self.cx.p.types.intern(Type::Matrix { cols, rows });
        let col_ty = self.cx.p.types.scalar_or_vector(rows, ScalarKind::F32);
        if ids.is_empty() {
            return self.alloc(ExprKind::Zero, ty, span);
        }
        if let [x] = ids[..] {
            if self.ty(x) == ty {
                return x;
            }
        }
        let tys: Vec<TypeId> = ids.iter().map(|i| self.ty(*i)).collect();
        if ids.len() == usize::from(cols) && tys.iter().all(|t| *t == col_ty) {
            return self.alloc(ExprKind::Compose { components: ids }, ty, span);
        }
        let n = usize::from(cols) * usize::from(rows);
        if tys.iter().all(|t| *t == TypeTable::F32) {
            if ids.len() != n {
                return self.ctor_error(
                    span,
                    ty,
                    CtorError::Count {
                        expected: n as u32,
                        found: ids.len() as u32,
                    },
                );
            }
            // From scalars in column order: compose each column first.
            let columns: Vec<ExprId> = ids
                .chunks(usize::from(rows))
                .map(|c| {
                    let s = self.span(c[0]).to(self.span(c[c.len() - 1]));
                    self.alloc(
                        ExprKind::Compose {
                            components: c.to_vec(),
                        },
                        col_ty,
                        s,
                    )
                })
                .collect();
            return self.alloc(
                ExprKind::Compose {
                    components: columns,
                },
                ty,
                span,
            );
        }
        let (bad, found) = ids
            .iter()
            .zip(&tys)
            .find(|(_, t)| **t != col_ty && **t != TypeTable::F32)
            .map(|(i, t)| (self.span(*i), *t))
            .unwrap_or((span, tys[0]));
        self.ctor_error(
            bad,
            ty,
            CtorError::Component {
                expected: col_ty,
                found,
            },
        )
    }

    fn array_ctor(
        &mut self,
        func: &ast::Ident,
        generics: Option<&[ast::GenericArg]>,
        args: &[ast::ExprId],
        span: Span,
    ) -> ExprId {
        let (elem, len) = match generics {
            None => (None, None),
            Some([t]) => match self.generic_ty(t) {
                Some(t) => (Some(t), None),
                None => {
                    self.bad_generics(func, "an element type and a size, as in `array<f32, 4>`");
                    return self.args_then_error(args, span);
                }
            },
            Some([t, n]) => {
                let elem = self.generic_ty(t);
                let len = self.cx.array_size(self.module, n);
                match (elem, len) {
                    (Some(e), Some(l)) if TypeTable::is_error(e) => (Some(e), Some(l)),
                    (Some(e), Some(l)) => {
                        if !self.cx.check_array_size(e, l, span) {
                            return self.args_then_error(args, span);
                        }
                        (Some(e), Some(l))
                    }
                    (None, _) => {
                        self.bad_generics(
                            func,
                            "an element type and a size, as in `array<f32, 4>`",
                        );
                        return self.args_then_error(args, span);
                    }
                    _ => return self.args_then_error(args, span),
                }
            }
            Some(_) => {
                self.bad_generics(func, "an element type and a size, as in `array<f32, 4>`");
                return self.args_then_error(args, span);
            }
        };
        if elem.is_some_and(TypeTable::is_error) {
            return self.args_then_error(args, span);
        }
        let ids = match elem {
            Some(e) => args.iter().map(|a| self.expect(*a, e)).collect::<Vec<_>>(),
            None => {
                let first = self.args_two_pass(args, |ck, i, known| {
                    known
                        .iter()
                        .flatten()
                        .find_map(|t| ck.cx.p.types.scalar_kind(*t))
                        .or_else(|| Some(super::expr::abstract_default(ck.ast, args[i])))
                });
                if let Some(&f) = first.first() {
                    let et = self.ty(f);
                    for &x in &first[1..] {
                        self.coerce(x, et);
                    }
                }
                first
            }
        };
        if self.any_error(&ids) {
            return self.error_expr(span);
        }
        let elem = match elem.or_else(|| ids.first().map(|i| self.ty(*i))) {
            Some(e) => e,
            None => {
                return self.ctor_error(span, TypeTable::ERROR, CtorError::EmptyArray);
            }
        };
        if ids.is_empty() {
            if let Some(len) = len {
                let ty = self
                    .cx
                    .p
                    .types
                    .intern(super::types::Type::Array { elem, len });
                return self.alloc(ExprKind::Zero, ty, span);
            }
            return self.ctor_error(span, TypeTable::ERROR, CtorError::EmptyArray);
        }
        let n = ids.len() as u32;
        let ty = self.cx.p.types.intern(Type::Array {
            elem,
            len: len.unwrap_or(n),
        });
        if let Some(len) = len {
            if len != n {
                return self.ctor_error(
                    span,
                    ty,
                    CtorError::Count {
                        expected: len,
                        found: n,
                    },
                );
            }
        }
        self.alloc(ExprKind::Compose { components: ids }, ty, span)
    }

    fn bitcast(
        &mut self,
        func: &ast::Ident,
        generics: Option<&[ast::GenericArg]>,
        args: &[ast::ExprId],
        span: Span,
    ) -> ExprId {
        let target = match generics {
            Some([g]) => self.generic_ty(g),
            _ => None,
        };
        let Some(to) = target else {
            self.bad_generics(func, "one type, as in `bitcast<u32>(x)`");
            return self.args_then_error(args, span);
        };
        // An untyped argument keeps its own kind (a float literal is an f32); an untyped integer is
        // read as a u32 when the target is, else as an i32.
        let hint = match (args.first(), self.cx.p.types.scalar_kind(to)) {
            (Some(a), _) if super::expr::abstract_default(self.ast, *a) == ScalarKind::F32 => {
                ScalarKind::F32
            }
            (_, Some(ScalarKind::U32)) => ScalarKind::U32,
            _ => ScalarKind::I32,
        };
        let [a] = args else {
            for a in args {
                self.expr(*a, Some(hint));
            }
            return self.ctor_error(
                span,
                to,
                CtorError::Count {
                    expected: 1,
                    found: args.len() as u32,
                },
            );
        };
        let x = self.expr(*a, Some(hint));
        let from = self.ty(x);
        if TypeTable::is_error(from) || TypeTable::is_error(to) {
            return self.error_expr(span);
        }
        let t = &self.cx.p.types;
        let ok = match (
            t.scalar_kind(from),
            t.scalar_kind(to),
            t.width(from),
            t.width(to),
        ) {
            (Some(a), Some(b), Some(wa), Some(wb)) => a.is_numeric() && b.is_numeric() && wa == wb,
            _ => false,
        };
        if !ok {
            return self.ctor_error(span, to, CtorError::Bitcast { from });
        }
        self.alloc(ExprKind::Bitcast { arg: x }, to, span)
    }
}
