//! The parser: tokens to an [`ast::Module`], with error recovery.
//!
//! Recursive descent for items, statements, types and scenes ([`items`], [`stmts`], [`types`],
//! [`scene`]); precedence climbing for expressions ([`exprs`]). This file holds the cursor over the
//! tokens, error reporting, recovery and the depth limits that every part shares.
//!
//! # Recovery
//!
//! Parsing never stops early. Where the input does not fit the grammar, the parser reports one
//! [`SyntaxError`], puts an error node in the tree and resynchronises:
//! - **Missing tokens** are reported and assumed (`let x = 1` + newline: "expected `;`", go on).
//! - **Junk** is skipped by [`Parser::recover`] up to a token of a *recovery set* chosen by the caller
//!   (`;` and `}` for statements, `,` and the closer for lists, the item keywords at the top level).
//!   Skipping steps over balanced `()`/`[]`/`{}` groups, and always stops at an item keyword or `@`
//!   written at the start of a line (column 0), the surest sign of a new item: an unclosed `{` then
//!   costs one error, not the rest of the file.
//! - **Cascades are suppressed**: at most one error is reported per token position, none while
//!   skipping, and none at a token right after an unknown character (the lexer reported that).
//!
//! # Limits
//!
//! Recursion is capped at [`MAX_DEPTH`] nested expressions, blocks or types; beyond it the parser
//! reports `E0202` once per item and skips the rest of the construct. Independently, every
//! expression tree is at most [`MAX_EXPR_DEPTH`] nodes deep (long operator chains such as
//! `a + a + … + a` or `- - - … x` grow trees without recursion), so later phases may recurse over
//! expressions freely.
//!
//! Invariants:
//! - Every loop consumes a token or exits; every skipped token is skipped once: parsing is linear.
//! - The cursor never moves past the final `Eof` token.
//! - Every node's span covers its children's spans.

mod exprs;
mod items;
mod scene;
mod stmts;
mod types;

use super::ast::{self, Expr, ExprId, ExprKind, Ident, Module};
use super::error::{Expected, Found, Hint, Nesting, SyntaxError};
use super::token::{Token, TokenKind, TokenSet};
use crate::source::{FileId, Span};

/// Most nested expressions (parentheses, calls, indexing, struct literals), blocks or generic types
/// the parser descends into.
pub const MAX_DEPTH: u32 = 128;

/// Deepest expression tree the parser builds.
pub const MAX_EXPR_DEPTH: u32 = 256;

/// Parses a token stream (as produced by [`super::lexer::tokenize`]) into a module. `lex_errors` are
/// the lexer's errors: syntax errors right after an unterminated string or comment, or after an
/// unknown character, are cascades of those and are not reported.
pub fn parse_tokens(
    file: FileId,
    text: &str,
    tokens: Vec<Token>,
    lex_errors: &[SyntaxError],
) -> (Module, Vec<SyntaxError>) {
    let mut quiet_after: Vec<u32> = lex_errors
        .iter()
        .filter_map(|e| match e {
            SyntaxError::UnterminatedString { span }
            | SyntaxError::UnterminatedComment { span } => Some(span.hi),
            _ => None,
        })
        .collect();
    quiet_after.sort_unstable();
    let mut p = Parser::new(file, text, tokens, &quiet_after);
    p.module();
    (p.m, p.errors)
}

/// Items keywords (and `@`): at the start of a line, they always end skipping.
const ITEM_START: TokenSet = TokenSet::new(&[
    TokenKind::Fn,
    TokenKind::Struct,
    TokenKind::Const,
    TokenKind::Scene,
    TokenKind::Import,
    TokenKind::At,
]);

/// Keywords that start a statement.
const STMT_KEYWORDS: TokenSet = TokenSet::new(&[
    TokenKind::Let,
    TokenKind::Var,
    TokenKind::If,
    TokenKind::For,
    TokenKind::While,
    TokenKind::Loop,
    TokenKind::Return,
    TokenKind::Break,
    TokenKind::Continue,
]);

/// Restrictions on what an expression may contain, by context.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Restrict {
    /// `Name {` does not start a struct literal (conditions of `if`/`while`, `for` ranges); the
    /// context is reported with `E0204` if one is written anyway.
    pub no_struct: Option<super::error::CondContext>,
    /// `>` (and `>>`, `>=`) end the expression: inside generic arguments.
    pub no_gt: bool,
}

impl Restrict {
    pub const NONE: Restrict = Restrict {
        no_struct: None,
        no_gt: false,
    };
}

pub(super) struct Parser<'t> {
    text: &'t str,
    file: FileId,
    /// Tokens without doc comments and unknown characters; ends with `Eof`.
    toks: Vec<Token>,
    /// `(token index, doc text)` for tokens preceded by `///` lines, sorted by index.
    docs: Vec<(u32, String)>,
    /// Indices of tokens that directly follow an unknown character, an unterminated string or an
    /// unterminated comment (errors there are cascades of the lexical error).
    after_unknown: Vec<u32>,
    pos: usize,
    /// End of the previous token (for "missing `;`" spans).
    prev_hi: u32,
    m: Module,
    errors: Vec<SyntaxError>,
    /// Token index of the last reported error; a second one there is suppressed.
    last_error_pos: usize,
    depth: u32,
    /// Tree depth of each expression, by arena index.
    expr_depth: Vec<u32>,
    /// Whether `E0202` was reported in the current item.
    too_deep_reported: bool,
}

impl<'t> Parser<'t> {
    fn new(file: FileId, text: &'t str, tokens: Vec<Token>, quiet_after: &[u32]) -> Parser<'t> {
        let mut toks = Vec::with_capacity(tokens.len());
        let mut docs = Vec::new();
        let mut after_unknown = Vec::new();
        let mut pending_doc: Option<String> = None;
        let mut unknown_before = false;
        let mut quiet = quiet_after.iter().peekable();
        for t in tokens {
            match t.kind {
                TokenKind::DocComment => {
                    let line = text.get(t.span.range()).unwrap_or("");
                    let line = line.strip_prefix("///").unwrap_or(line);
                    let line = line.strip_prefix(' ').unwrap_or(line);
                    match &mut pending_doc {
                        Some(doc) => {
                            doc.push('\n');
                            doc.push_str(line);
                        }
                        None => pending_doc = Some(line.to_string()),
                    }
                }
                TokenKind::Unknown => unknown_before = true,
                _ => {
                    let index = toks.len() as u32;
                    if let Some(doc) = pending_doc.take() {
                        docs.push((index, doc));
                    }
                    let mut after_lex_error = std::mem::take(&mut unknown_before);
                    while quiet.next_if(|&&at| at <= t.span.lo).is_some() {
                        after_lex_error = true;
                    }
                    if after_lex_error {
                        after_unknown.push(index);
                    }
                    toks.push(t);
                }
            }
        }
        if toks.last().map(|t| t.kind) != Some(TokenKind::Eof) {
            let end = text.len() as u32;
            toks.push(Token {
                kind: TokenKind::Eof,
                span: Span::new(file, end, end),
            });
        }
        Parser {
            text,
            file,
            toks,
            docs,
            after_unknown,
            pos: 0,
            prev_hi: 0,
            m: Module {
                file,
                ..Module::default()
            },
            errors: Vec::new(),
            last_error_pos: usize::MAX,
            depth: 0,
            expr_depth: Vec::new(),
            too_deep_reported: false,
        }
    }

    // ---- cursor ----

    fn tok(&self, n: usize) -> Token {
        let i = (self.pos + n).min(self.toks.len() - 1);
        self.toks[i]
    }

    /// The current token's kind.
    fn kind(&self) -> TokenKind {
        self.tok(0).kind
    }

    /// The kind of the token `n` ahead of the current one.
    fn nth(&self, n: usize) -> TokenKind {
        self.tok(n).kind
    }

    /// The current token's span.
    fn span(&self) -> Span {
        self.tok(0).span
    }

    fn at(&self, kind: TokenKind) -> bool {
        self.kind() == kind
    }

    /// The source text of a span.
    fn text(&self, span: Span) -> &'t str {
        self.text.get(span.range()).unwrap_or("")
    }

    /// The current token's text.
    fn cur_text(&self) -> &'t str {
        self.text(self.span())
    }

    /// An empty span just after the previous token.
    fn prev_end(&self) -> Span {
        Span::new(self.file, self.prev_hi, self.prev_hi)
    }

    /// A span from `lo` to the end of the previous token.
    fn since(&self, lo: Span) -> Span {
        Span::new(self.file, lo.lo, self.prev_hi.max(lo.lo))
    }

    /// Consumes the current token (never the final `Eof`) and returns its span.
    fn bump(&mut self) -> Span {
        let span = self.span();
        if self.pos + 1 < self.toks.len() {
            self.pos += 1;
            self.prev_hi = span.hi;
        }
        span
    }

    /// Consumes the current token if it is `kind`.
    fn eat(&mut self, kind: TokenKind) -> Option<Span> {
        if self.at(kind) {
            Some(self.bump())
        } else {
            None
        }
    }

    /// Whether the current token starts its line, without indentation.
    fn at_column_zero(&self) -> bool {
        let lo = self.span().lo as usize;
        lo == 0 || self.text.as_bytes().get(lo - 1) == Some(&b'\n')
    }

    /// Whether the current token is an item keyword or `@` at column 0: a new item, whatever the
    /// nesting says.
    fn at_item_line(&self) -> bool {
        ITEM_START.contains(self.kind()) && self.at_column_zero()
    }

    /// Whether a line break separates the previous token from the current one.
    fn on_new_line(&self) -> bool {
        let lo = self.span().lo as usize;
        let hi = (self.prev_hi as usize).min(lo);
        self.text.as_bytes()[hi..lo].contains(&b'\n')
    }

    /// The part of `span` on its first line (for labels on long items).
    fn first_line(&self, span: Span) -> Span {
        let bytes = self.text.as_bytes();
        let hi = (span.hi as usize).min(bytes.len());
        let lo = (span.lo as usize).min(hi);
        let end = bytes[lo..hi]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(hi, |n| lo + n);
        Span::new(span.file, span.lo, end as u32)
    }

    /// The identifier at the cursor (which must be an `Ident` token), consumed.
    fn ident(&mut self) -> Ident {
        let span = self.bump();
        Ident {
            name: self.text(span).to_string(),
            span,
        }
    }

    /// The identifier at the cursor, or an "expected identifier" error (nothing consumed).
    fn expect_ident(&mut self) -> Option<Ident> {
        if self.at(TokenKind::Ident) {
            Some(self.ident())
        } else {
            self.expected(Expected::Ident, None);
            None
        }
    }

    /// The doc comment attached to the token at index `index`, if any.
    fn doc_at(&self, index: usize) -> Option<String> {
        self.docs
            .binary_search_by_key(&(index as u32), |(i, _)| *i)
            .ok()
            .map(|i| self.docs[i].1.clone())
    }

    // ---- errors ----

    /// Reports an error at the current token, unless one was already reported there.
    fn error_here(&mut self, e: SyntaxError) {
        if self.pos == self.last_error_pos
            || self.after_unknown.binary_search(&(self.pos as u32)).is_ok()
        {
            return;
        }
        self.last_error_pos = self.pos;
        self.errors.push(e);
    }

    /// Reports an error that is not about the current token (always reported).
    fn report(&mut self, e: SyntaxError) {
        self.errors.push(e);
    }

    /// What the current token is, for messages.
    fn found(&self) -> Found {
        Found::new(self.kind(), self.cur_text())
    }

    /// Reports "expected …, found …" at the current token.
    fn expected(&mut self, expected: Expected, hint: Option<Hint>) {
        let e = SyntaxError::Expected {
            expected,
            found: self.found(),
            span: self.span(),
            hint,
        };
        self.error_here(e);
    }

    /// Consumes `kind`, or reports that it is missing (consuming nothing).
    fn expect(&mut self, kind: TokenKind) -> bool {
        if self.eat(kind).is_some() {
            return true;
        }
        self.expected(Expected::Token(kind), None);
        false
    }

    /// Consumes the closing delimiter `close` of a group opened at `open`, or reports it missing.
    fn expect_close(&mut self, close: TokenKind, open: Span) -> bool {
        if self.eat(close).is_some() {
            return true;
        }
        let e = SyntaxError::Unclosed {
            close,
            found: self.found(),
            span: self.span(),
            open,
        };
        self.error_here(e);
        false
    }

    /// Reports a token missing at the end of the previous one (`;` or `,` at the end of a line).
    fn missing(&mut self, token: TokenKind) {
        let e = SyntaxError::Missing {
            token,
            span: self.prev_end(),
            found: self.found(),
            found_span: self.span(),
        };
        self.error_here(e);
    }

    /// Consumes the `;` that ends a statement. A `;` missing at the end of a line is reported and
    /// assumed; junk before it on the same line is reported and skipped.
    fn expect_semi(&mut self) {
        if self.eat(TokenKind::Semi).is_some() {
            return;
        }
        if self.on_new_line() || matches!(self.kind(), TokenKind::RBrace | TokenKind::Eof) {
            self.missing(TokenKind::Semi);
            return;
        }
        self.expected(Expected::Token(TokenKind::Semi), None);
        self.recover(TokenSet::new(&[TokenKind::Semi, TokenKind::RBrace]).union(STMT_KEYWORDS));
        self.eat(TokenKind::Semi);
    }

    // ---- recovery ----

    /// Skips tokens until one in `stop` outside any group, an item keyword at column 0, or the end of
    /// the file. Groups in `()`, `[]`, `{}` are skipped whole. Reports nothing.
    ///
    /// If anything was skipped, an error at the token where skipping stopped is suppressed too: it
    /// would be about the same broken construct ("expected `)`" after skipping a bad argument).
    fn recover(&mut self, stop: TokenSet) {
        let mut nest = 0usize;
        let start = self.pos;
        loop {
            let k = self.kind();
            if k == TokenKind::Eof || self.at_item_line() || (nest == 0 && stop.contains(k)) {
                if self.pos != start {
                    self.last_error_pos = self.pos;
                }
                return;
            }
            match k {
                TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => nest += 1,
                TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => {
                    nest = nest.saturating_sub(1)
                }
                _ => {}
            }
            self.bump();
        }
    }

    /// Skips the rest of a construct that is too deep (or an expression that cannot continue): up to
    /// a `;`, `,` or closing delimiter outside any group.
    fn skip_rest(&mut self, extra: TokenSet) {
        let stop = TokenSet::new(&[
            TokenKind::Semi,
            TokenKind::Comma,
            TokenKind::RParen,
            TokenKind::RBracket,
            TokenKind::RBrace,
        ])
        .union(extra);
        self.recover(stop);
    }

    // ---- depth ----

    /// Enters one level of nesting, or reports `E0202` (once per item), skips the construct at the
    /// cursor and returns `false`.
    fn enter(&mut self, what: Nesting) -> bool {
        if self.depth < MAX_DEPTH {
            self.depth += 1;
            return true;
        }
        self.too_deep(what, self.span());
        // Skip the construct: the group at the cursor, or up to the end of the expression.
        match self.kind() {
            TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => {
                self.bump();
                let mut nest = 1usize;
                while nest > 0 && !self.at(TokenKind::Eof) && !self.at_item_line() {
                    match self.kind() {
                        TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => nest += 1,
                        TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => nest -= 1,
                        _ => {}
                    }
                    self.bump();
                }
                self.last_error_pos = self.pos;
            }
            _ => self.skip_rest(TokenSet::EMPTY),
        }
        false
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// Reports `E0202` unless it was already reported in this item.
    fn too_deep(&mut self, what: Nesting, span: Span) {
        if !self.too_deep_reported {
            self.too_deep_reported = true;
            self.report(SyntaxError::TooDeep { what, span });
        }
    }

    // ---- lists ----

    /// A comma-separated list up to `close` (not consumed). `elem` parses one element, or reports an
    /// error and returns `None`. Recovery skips to the next `,` or `close`; a list also ends at a
    /// token of `stop`. When `elem_start` is given, an element that starts on a new line without a
    /// `,` before it is reported as a missing `,` and parsed.
    pub(super) fn list<T>(
        &mut self,
        close: TokenKind,
        stop: TokenSet,
        elem_start: Option<TokenKind>,
        mut elem: impl FnMut(&mut Self) -> Option<T>,
    ) -> Vec<T> {
        let mut out = Vec::new();
        let seps = TokenSet::new(&[TokenKind::Comma, close]).union(stop);
        loop {
            let k = self.kind();
            if k == close || k == TokenKind::Eof || stop.contains(k) || self.at_item_line() {
                break;
            }
            let before = self.pos;
            let item = elem(self);
            let ok = item.is_some();
            out.extend(item);
            if self.eat(TokenKind::Comma).is_some() || self.at(close) {
                continue;
            }
            if ok && Some(self.kind()) == elem_start && self.on_new_line() {
                self.missing(TokenKind::Comma);
                continue;
            }
            if stop.contains(self.kind()) || self.at(TokenKind::Eof) || self.at_item_line() {
                // The list is cut short: the caller reports the missing closer.
                break;
            }
            if ok || self.pos == before {
                let expected = Expected::OneOf(comma_or(close));
                self.expected(expected, None);
            }
            self.recover(seps);
            self.eat(TokenKind::Comma);
            if self.pos == before {
                break;
            }
        }
        out
    }

    // ---- expressions in the arena ----

    /// Tree depth of an expression.
    fn depth_of(&self, e: ExprId) -> u32 {
        let i = u32::from(e.into_raw()) as usize;
        self.expr_depth.get(i).copied().unwrap_or(1)
    }

    /// Tree depth a node of this kind would have.
    fn depth_for(&self, kind: &ExprKind) -> u32 {
        let children = match kind {
            ExprKind::Lit(_) | ExprKind::Name(_) | ExprKind::Error => 0,
            ExprKind::Unary { operand, .. } => self.depth_of(*operand),
            ExprKind::Binary { lhs, rhs, .. } => self.depth_of(*lhs).max(self.depth_of(*rhs)),
            ExprKind::Call { args, generics, .. } => {
                let g = generics.iter().flatten().map(|g| match g {
                    ast::GenericArg::Expr(e) => self.depth_of(*e),
                    ast::GenericArg::Type(_) => 0,
                });
                args.iter()
                    .map(|a| self.depth_of(*a))
                    .chain(g)
                    .max()
                    .unwrap_or(0)
            }
            ExprKind::Field { base, .. } => self.depth_of(*base),
            ExprKind::Index { base, index } => self.depth_of(*base).max(self.depth_of(*index)),
            ExprKind::StructLit { fields, .. } => fields
                .iter()
                .map(|f| self.depth_of(f.value))
                .max()
                .unwrap_or(0),
            ExprKind::Paren(inner) => self.depth_of(*inner),
        };
        children + 1
    }

    /// Adds an expression to the arena. A node that would make the tree deeper than
    /// [`MAX_EXPR_DEPTH`] becomes an error node (reported as `E0202`).
    fn alloc(&mut self, kind: ExprKind, span: Span) -> ExprId {
        let mut depth = self.depth_for(&kind);
        let kind = if depth > MAX_EXPR_DEPTH {
            self.too_deep(Nesting::Expression, span);
            depth = 1;
            ExprKind::Error
        } else {
            kind
        };
        self.expr_depth.push(depth);
        self.m.exprs.alloc(Expr { kind, span })
    }

    /// An error expression.
    fn error_expr(&mut self, span: Span) -> ExprId {
        self.alloc(ExprKind::Error, span)
    }

    fn expr_span(&self, e: ExprId) -> Span {
        self.m.exprs[e].span
    }
}

/// `[`,`, close]` as a static slice, for messages.
fn comma_or(close: TokenKind) -> &'static [TokenKind] {
    match close {
        TokenKind::RParen => &[TokenKind::Comma, TokenKind::RParen],
        TokenKind::RBrace => &[TokenKind::Comma, TokenKind::RBrace],
        TokenKind::RBracket => &[TokenKind::Comma, TokenKind::RBracket],
        _ => &[TokenKind::Comma, TokenKind::Gt],
    }
}
