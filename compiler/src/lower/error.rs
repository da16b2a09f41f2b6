//! Errors of lowering, and their one conversion to a [`Diagnostic`].
//!
//! Invariants:
//! - Lowering never sees a user mistake: the checker has reported those, and `driver::Checked::program`
//!   exists only without errors. Every [`LowerError`] is therefore a bug in rtc (or a construct the
//!   lowering does not support yet) and becomes an internal compiler error ([`codes::ICE`]) pointing at
//!   the DSL span where lowering stopped.
//! - A naga validation failure of a finished module carries the span naga recorded, which lowering
//!   stored as a global range of the [`SourceMap`] (`SourceMap::to_global`), mapped back here with
//!   `SourceMap::from_global`.

use crate::diag::{codes, Diagnostic};
use crate::sema::builtins::Builtin;
use crate::sema::hir::{FnId, Program};
use crate::sema::types::TypeId;
use crate::source::{SourceMap, Span};

/// What lowering does not support.
#[derive(Clone, Debug, PartialEq)]
pub enum Unsupported {
    /// A framework intrinsic, and the [`super::Intrinsics`] hook did not lower it.
    Intrinsic(Builtin),
    /// A built-in that cannot appear in GPU code (a scene-only asset constructor).
    SceneOnly(Builtin),
    /// A type without a GPU representation (`string`, the error type, `void` as a value).
    Type(TypeId),
    /// A constant that cannot be written in GPU code (a string, an asset).
    Constant,
    /// The test entry point cannot pass this type through a storage buffer.
    TestIo(TypeId),
}

/// Why lowering failed. Each variant is an internal compiler error (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub enum LowerError {
    /// Something lowering does not support, at `span`.
    Unsupported {
        /// What.
        what: Unsupported,
        /// Where in the DSL source.
        span: Span,
    },
    /// The HIR breaks one of its invariants (an error node, a place that is not a place, …).
    InvalidHir {
        /// Which invariant, in words.
        what: &'static str,
        /// Where.
        span: Span,
    },
    /// A call cycle reached lowering (the checker rejects recursion with E0801).
    Recursion {
        /// A function on the cycle.
        func: FnId,
        /// Its name's span.
        span: Span,
    },
    /// naga rejected the module lowering produced.
    Validation {
        /// naga's message with its chain of causes.
        message: String,
        /// The DSL span naga's error points at, if it maps back to a file.
        span: Option<Span>,
    },
}

impl LowerError {
    /// The DSL span of the error, if it has one.
    pub fn span(&self) -> Option<Span> {
        match self {
            LowerError::Unsupported { span, .. }
            | LowerError::InvalidHir { span, .. }
            | LowerError::Recursion { span, .. } => Some(*span),
            LowerError::Validation { span, .. } => *span,
        }
    }

    /// The error as an internal-compiler-error diagnostic. `program` names types and functions.
    pub fn to_diagnostic(&self, program: &Program) -> Diagnostic {
        let message = match self {
            LowerError::Unsupported { what, .. } => match what {
                Unsupported::Intrinsic(b) => format!(
                    "the intrinsic `{}` is not available in this context (no kernel provides it)",
                    b.name()
                ),
                Unsupported::SceneOnly(b) => {
                    format!("`{}` can only be evaluated in a scene", b.name())
                }
                Unsupported::Type(t) => format!(
                    "the type `{}` has no GPU representation",
                    program.type_name(*t)
                ),
                Unsupported::Constant => "a constant that cannot be written in GPU code".into(),
                Unsupported::TestIo(t) => format!(
                    "the test entry point cannot pass `{}` through a buffer",
                    program.type_name(*t)
                ),
            },
            LowerError::InvalidHir { what, .. } => format!("malformed HIR: {what}"),
            LowerError::Recursion { func, .. } => format!(
                "the call graph has a cycle through `{}`",
                program.functions[*func].name
            ),
            LowerError::Validation { message, .. } => {
                format!("the compiler produced invalid IR: {message}")
            }
        };
        let span = self.span().unwrap_or_default();
        Diagnostic::error(
            codes::ICE,
            format!("internal compiler error: {message}"),
            span,
        )
        .with_note("this is a bug in rtc; please report it with the program that triggered it")
    }
}

impl std::fmt::Display for LowerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LowerError::Unsupported { what, .. } => write!(f, "unsupported: {what:?}"),
            LowerError::InvalidHir { what, .. } => write!(f, "malformed HIR: {what}"),
            LowerError::Recursion { func, .. } => write!(f, "call cycle through {func:?}"),
            LowerError::Validation { message, .. } => {
                write!(f, "the compiler produced invalid IR: {message}")
            }
        }
    }
}

impl std::error::Error for LowerError {}

/// The capabilities lowered code may use: naga's defaults (what WebGPU guarantees) and
/// `SHADER_FLOAT16_IN_FLOAT32` for `pack_half2x16`/`unpack_half2x16` (core WGSL, every back end
/// writes them; wgpu lacks it only on GL devices without `SHADER_F16_IN_F32`).
pub fn capabilities() -> naga::valid::Capabilities {
    naga::valid::Capabilities::default() | naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32
}

/// Validates a finished module with every check naga has and [`capabilities`], mapping an error's
/// span back to DSL source.
pub fn validate(
    module: &naga::Module,
    sources: &SourceMap,
) -> Result<naga::valid::ModuleInfo, LowerError> {
    use naga::valid::{ValidationFlags, Validator};
    Validator::new(ValidationFlags::all(), capabilities())
        .validate(module)
        .map_err(|e| {
            // naga lists the spans from the outermost (the function) inwards; the innermost one is
            // the construct it rejected.
            let span = e
                .spans()
                .filter_map(|(span, _)| span.to_range())
                .filter_map(|r| sources.from_global(r.start as u32, r.end as u32))
                .last();
            LowerError::Validation {
                message: error_chain(e.as_inner()),
                span,
            }
        })
}

/// A naga error with its chain of sources.
fn error_chain(e: &dyn std::error::Error) -> String {
    let mut s = e.to_string();
    let mut src = e.source();
    while let Some(inner) = src {
        s.push_str(": ");
        s.push_str(&inner.to_string());
        src = inner.source();
    }
    s
}
