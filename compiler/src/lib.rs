//! `rtc-compiler`: the rtc language from source text to GPU code, without a GPU.
//!
//! The pipeline, one entry function per phase ([`pipeline::compile`] calls them in order):
//! `source` files → `syntax` (lexer, parser, AST) → `sema` (modules and imports, name resolution,
//! types, program signatures, scenes, recursion) → typed HIR → `link` (the scene's programs and kernel
//! configuration) → `kernel` + `lower` to naga IR → `back` ends (WGSL, SPIR-V, HLSL, MSL, GLSL). Every phase returns data plus [`diag::Diagnostic`]s; nothing here prints, exits or panics on
//! user input.
//!
//! Guarantees:
//! - No `unsafe`, no GPU dependency: the compiler builds and is tested on any machine.
//! - User mistakes become diagnostics with a stable code, a span and, where it helps, a help line.

#![forbid(unsafe_code)]
// Docs are built with `--document-private-items`: links from module docs to private helpers are
// meant for readers of the code.
#![allow(rustdoc::private_intra_doc_links)]
#![cfg_attr(
    not(test),
    warn(
        clippy::panic,
        clippy::todo,
        clippy::dbg_macro,
        clippy::print_stdout,
        clippy::print_stderr,
        clippy::unwrap_used
    )
)]

pub mod abi;
pub mod back;
pub mod cache;
pub mod confine;
pub mod diag;
pub mod driver;
pub mod kernel;
pub mod layout;
pub mod link;
pub mod lower;
pub mod pipeline;
pub mod sema;
pub mod source;
pub mod syntax;

pub use diag::{Diagnostic, Severity};
pub use source::{FileId, SourceMap, Span};
