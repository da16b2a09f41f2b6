//! Lowering: typed HIR straight to one `naga::Module`, without WGSL text.
//!
//! The one entry is [`lower`]: it lowers the functions reachable from some roots into a new module,
//! lets the caller build what surrounds them (an entry point: the kernel's `render` and `bounds`, the
//! test entry point of [`testgen`]) through the [`Lowerer`], and validates the result. All IR
//! construction goes through [`builder::FnBuilder`], the one place that handles `Statement::Emit`.
//!
//! # Invariants
//!
//! - **Callees first.** [`Lowerer::ensure_function`] lowers a function's callees (and the polyfills it
//!   uses) as their first calls are reached, depth first, and appends the function itself only when
//!   its body is done, so every `Call` refers to a lower handle, as naga requires. Only what is
//!   reachable from the requested functions is emitted.
//! - **Memoised and deterministic.** Each HIR function, constant, type and polyfill becomes at most one
//!   naga item; maps that decide emission order are `IndexMap`s or follow HIR order, so the same HIR
//!   gives a byte-identical module (hash maps are used for lookups only).
//! - **Spans are global.** Every naga expression, statement, local and function made from HIR carries the
//!   DSL span as a `SourceMap::to_global` range; a validation error maps back with
//!   [`error::validate`]. Compiler-made helpers (polyfills, the test entry point) carry
//!   `Span::UNDEFINED`.
//! - **Target independence.** Where naga's back ends disagree with each other or with the spec
//!   (integer division and remainder by zero and `%` of negative operands, float→int saturation and
//!   NaN, shift amounts, `clamp` with `lo > hi`, out-of-range dynamic indices, NaN tests, float `!=`
//!   with NaN, `abs` of `u32` in GLSL, the missing `inverse` in WGSL), lowering emits explicit code
//!   (the `polyfill` module, `!(a == b)` for float `!=`) so all five targets compute the spec's
//!   result. `tests/diff.rs` runs every built-in through SPIR-V (Vulkan), GLSL (`WGPU_BACKEND=gl`) and
//!   WGSL text (`RTC_DIFF_SOURCE=wgsl`).
//! - **No panics.** Every failure is a [`LowerError`], reported as an internal compiler error.
//!
//! # Intrinsics
//!
//! The framework intrinsics (`spawn`, `rand`, `sample_light`, `mesh_node`, …) depend on the kernel's
//! bindings and execution model, which this module does not know. Every call to one goes through the
//! [`Intrinsics`] hook passed to [`Lowerer::ensure_function`]; [`NoIntrinsics`] rejects them all. The
//! hook also sees every call of a user-level function first ([`Intrinsics::lower_call`]), for the
//! kernel's functions declared with placeholder bodies.

pub mod builder;
mod builtins;
mod consts;
mod error;
mod expr;
mod geometry;
mod polyfill;
mod stmt;
pub mod testgen;
mod types;

pub use error::{capabilities, validate, LowerError, Unsupported};
pub use polyfill::Polyfill;

use crate::sema::builtins::Builtin;
use crate::sema::hir::{ConstId, FnId, Program};
use crate::sema::types::TypeId;
use crate::source::{SourceMap, Span};
use builder::FnBuilder;
use indexmap::IndexMap;
use naga::{Expression, Function, Handle};
use std::collections::HashMap;

/// One call of a framework intrinsic, as the [`Intrinsics`] hook sees it.
#[derive(Clone, Copy, Debug)]
pub struct IntrinsicCall<'a> {
    /// Which intrinsic.
    pub builtin: Builtin,
    /// The lowered arguments, in order (already emitted in the caller).
    pub args: &'a [Handle<Expression>],
    /// The HIR types of the arguments.
    pub arg_types: &'a [TypeId],
    /// The HIR result type (`TypeTable::VOID` for `spawn`).
    pub ret: TypeId,
    /// The function being lowered.
    pub caller: FnId,
    /// The call's span, as a global naga span.
    pub span: naga::Span,
}

/// A call of a user-level function, as the [`Intrinsics`] hook sees it.
#[derive(Clone, Copy, Debug)]
pub struct FunctionCall<'a> {
    /// The callee.
    pub callee: FnId,
    /// The lowered arguments, in order (already emitted in the caller).
    pub args: &'a [Handle<Expression>],
    /// The function being lowered.
    pub caller: FnId,
    /// The call's span, as a global naga span.
    pub span: naga::Span,
}

/// What the hook did with a call of a user-level function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CallLowering {
    /// Nothing: lowering lowers the callee (once) and calls it.
    Default,
    /// The hook lowered the call; the result expression, if the callee returns a value.
    Done(Option<Handle<Expression>>),
}

/// The hook through which every framework intrinsic is lowered.
///
/// Lowering evaluates the arguments, then calls [`Intrinsics::lower`] with the function builder of the
/// caller. An implementation appends whatever it needs: expressions and statements through `fb`
/// (e.g. `fb.call(...)` of a kernel helper, loads from the kernel's globals), types, globals and helper
/// functions through `cx` (e.g. [`Lowerer::ty`], [`Lowerer::module_mut`]; a helper function appended
/// now precedes the caller, as naga requires). It returns the result expression, or `None` for an
/// intrinsic without a result (`spawn`). It may return an error; [`LowerError::Unsupported`] with
/// [`Unsupported::Intrinsic`] is the conventional "not available here".
///
/// [`Intrinsics::lower_call`] sees every call of a user-level function first, so functions the kernel
/// declares with placeholder bodies (`rtc:abi`'s buffer loads, dispatch calls) can be lowered to
/// kernel code instead; such a callee is then never lowered itself.
///
/// Re-entrancy: a hook that needs a language function (a kernel helper written in the language)
/// lowers it with `cx.ensure_function(f, self)`, passing itself, so that the intrinsics inside that
/// function go through the hook too.
pub trait Intrinsics {
    /// Lowers one intrinsic call.
    fn lower(
        &mut self,
        cx: &mut Lowerer<'_>,
        fb: &mut FnBuilder,
        call: &IntrinsicCall<'_>,
    ) -> Result<Option<Handle<Expression>>, LowerError>;

    /// Lowers a call of a user-level function, or leaves it to lowering ([`CallLowering::Default`],
    /// what the default implementation does).
    fn lower_call(
        &mut self,
        cx: &mut Lowerer<'_>,
        fb: &mut FnBuilder,
        call: &FunctionCall<'_>,
    ) -> Result<CallLowering, LowerError> {
        let _ = (cx, fb, call);
        Ok(CallLowering::Default)
    }
}

/// The hook without a kernel: every intrinsic is an error ([`Unsupported::Intrinsic`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct NoIntrinsics;

impl Intrinsics for NoIntrinsics {
    fn lower(
        &mut self,
        cx: &mut Lowerer<'_>,
        _fb: &mut FnBuilder,
        call: &IntrinsicCall<'_>,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        Err(LowerError::Unsupported {
            what: Unsupported::Intrinsic(call.builtin),
            span: cx.dsl_span(call.span),
        })
    }
}

/// The lowering context: the program, the module being built and the memo tables.
pub struct Lowerer<'p> {
    program: &'p Program,
    sources: &'p SourceMap,
    module: naga::Module,
    layouter: naga::proc::Layouter,
    /// HIR type → naga type (lookups only).
    types: HashMap<TypeId, Handle<naga::Type>>,
    /// HIR function → naga function, in emission order.
    functions: IndexMap<FnId, Handle<Function>>,
    /// HIR constant → naga constant (`None`: not expressible as a naga constant, inlined instead).
    consts: HashMap<ConstId, Option<Handle<naga::Constant>>>,
    /// Polyfill helpers, in emission order.
    polyfills: IndexMap<Polyfill, Handle<Function>>,
    /// Private globals holding the bits of non-finite floats (lookups only).
    float_bits: HashMap<u32, Handle<naga::GlobalVariable>>,
    /// Functions being lowered (a cycle guard).
    in_progress: Vec<FnId>,
}

/// What [`lower`] returns.
#[derive(Debug)]
pub struct Lowered<T> {
    /// The module (validated).
    pub module: naga::Module,
    /// naga's analysis of it.
    pub info: naga::valid::ModuleInfo,
    /// The naga function of every lowered HIR function, callees first.
    pub functions: IndexMap<FnId, Handle<Function>>,
    /// What `finish` returned.
    pub finished: T,
}

/// Lowers `roots` and everything they call into a new module, then lets `finish` add what surrounds
/// them (it gets the roots' naga functions, in order; an entry point calling them, say), and validates
/// the module. This is the only way into lowering: every caller (the kernel, the test entry point,
/// tests) goes through it.
pub fn lower<T>(
    program: &Program,
    sources: &SourceMap,
    roots: &[FnId],
    intrinsics: &mut dyn Intrinsics,
    finish: impl FnOnce(&mut Lowerer<'_>, &[Handle<Function>]) -> Result<T, LowerError>,
) -> Result<Lowered<T>, LowerError> {
    let mut cx = Lowerer::new(program, sources);
    let mut handles = Vec::with_capacity(roots.len());
    for &f in roots {
        handles.push(cx.ensure_function(f, intrinsics)?);
    }
    let finished = finish(&mut cx, &handles)?;
    let functions = cx.functions.clone();
    let module = cx.into_module();
    let info = validate(&module, sources)?;
    Ok(Lowered {
        module,
        info,
        functions,
        finished,
    })
}

impl<'p> Lowerer<'p> {
    /// A lowerer building a new, empty module (private: [`lower`] is the entry).
    fn new(program: &'p Program, sources: &'p SourceMap) -> Lowerer<'p> {
        Lowerer {
            program,
            sources,
            module: naga::Module::default(),
            layouter: naga::proc::Layouter::default(),
            types: HashMap::new(),
            functions: IndexMap::new(),
            consts: HashMap::new(),
            polyfills: IndexMap::new(),
            float_bits: HashMap::new(),
            in_progress: Vec::new(),
        }
    }

    /// The program being lowered.
    pub fn program(&self) -> &'p Program {
        self.program
    }

    /// The source map the spans refer to.
    pub fn sources(&self) -> &'p SourceMap {
        self.sources
    }

    /// The module built so far.
    pub fn module(&self) -> &naga::Module {
        &self.module
    }

    /// The module built so far, to add globals, types or functions (appended items come after
    /// everything lowered so far).
    pub fn module_mut(&mut self) -> &mut naga::Module {
        &mut self.module
    }

    /// The finished module (not validated; [`lower`] validates it).
    fn into_module(self) -> naga::Module {
        self.module
    }

    /// The naga function of `f`, if it was lowered.
    pub fn function(&self, f: FnId) -> Option<Handle<Function>> {
        self.functions.get(&f).copied()
    }

    /// Every lowered HIR function and its naga function, callees first.
    pub fn functions(&self) -> &IndexMap<FnId, Handle<Function>> {
        &self.functions
    }

    /// A DSL span as a naga span (a global range of the source map).
    pub fn span(&self, span: Span) -> naga::Span {
        let (start, end) = self.sources.to_global(span);
        naga::Span::new(start, end)
    }

    /// A naga span made by [`Lowerer::span`] back as a DSL span (the default span if it is undefined).
    pub fn dsl_span(&self, span: naga::Span) -> Span {
        span.to_range()
            .and_then(|r| self.sources.from_global(r.start as u32, r.end as u32))
            .unwrap_or_default()
    }

    /// Lowers `f` (after its callees) unless it is already lowered, and returns its naga function.
    pub fn ensure_function(
        &mut self,
        f: FnId,
        intrinsics: &mut dyn Intrinsics,
    ) -> Result<Handle<Function>, LowerError> {
        if let Some(h) = self.functions.get(&f) {
            return Ok(*h);
        }
        let program = self.program;
        let func = &program.functions[f];
        if self.in_progress.contains(&f) {
            return Err(LowerError::Recursion {
                func: f,
                span: func.span,
            });
        }
        self.in_progress.push(f);
        let result = self.lower_new_function(f, intrinsics);
        self.in_progress.pop();
        let naga_fn = result?;
        let handle = self.module.functions.append(naga_fn, self.span(func.span));
        self.functions.insert(f, handle);
        Ok(handle)
    }

    /// Lowers `f`'s body. Callees are lowered when their first call is reached (unless the hook
    /// lowers the call), so each is appended before `f`, which is appended after its body is done.
    fn lower_new_function(
        &mut self,
        f: FnId,
        intrinsics: &mut dyn Intrinsics,
    ) -> Result<Function, LowerError> {
        stmt::lower_function(self, intrinsics, f)
    }
}

#[cfg(test)]
mod tests;
