//! Syntax: the lexer, the parser and the AST of one `.rt` file.
//!
//! Entry point: [`parse`], which never fails: it returns an [`ast::Module`] (with error nodes where it
//! recovered) and every lexical and syntax diagnostic of the file. [`lex`] exposes the token stream
//! for tests and tools.
//!
//! Layout: [`token`] (kinds and sets) → [`lexer`] (text to tokens, literal decoding) → `parser`
//! (tokens to [`ast`], with recovery; one file per syntactic category) → [`error`] (the error enum
//! and its single conversion to diagnostics).
//!
//! Guarantees, on any input (including random bytes read as lossy UTF-8): no panic, no stack
//! overflow (nesting is capped at [`MAX_DEPTH`], expression trees at [`MAX_EXPR_DEPTH`]), no hang,
//! time linear in the input's size. Diagnostics are returned in source order.

pub mod ast;
pub mod error;
pub mod lexer;
mod parser;
pub mod token;

#[cfg(test)]
mod tests;

use crate::diag::Diagnostic;
use crate::source::FileId;
pub use parser::{MAX_DEPTH, MAX_EXPR_DEPTH};
pub use token::{Token, TokenKind};

/// Parses one file. Never panics, whatever the input; reports every syntax error, not only the first.
pub fn parse(file: FileId, text: &str) -> (ast::Module, Vec<Diagnostic>) {
    let (module, errors) = parse_errors(file, text);
    (
        module,
        errors
            .iter()
            .map(error::SyntaxError::to_diagnostic)
            .collect(),
    )
}

/// Like [`parse`], with the errors as typed [`error::SyntaxError`]s (sorted by position).
pub fn parse_errors(file: FileId, text: &str) -> (ast::Module, Vec<error::SyntaxError>) {
    let (tokens, mut errors) = lexer::tokenize(file, text);
    let (module, parse_errors) = parser::parse_tokens(file, text, tokens, &errors);
    errors.extend(parse_errors);
    errors.sort_by_key(|e| {
        let s = e.span();
        (s.lo, s.hi)
    });
    (module, errors)
}

/// Splits one file into tokens (including [`TokenKind::DocComment`] and [`TokenKind::Unknown`]
/// tokens, ending with [`TokenKind::Eof`]), with the lexical diagnostics.
pub fn lex(file: FileId, text: &str) -> (Vec<Token>, Vec<Diagnostic>) {
    let (tokens, errors) = lexer::tokenize(file, text);
    (
        tokens,
        errors
            .iter()
            .map(error::SyntaxError::to_diagnostic)
            .collect(),
    )
}
