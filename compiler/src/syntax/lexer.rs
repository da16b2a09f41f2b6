//! The lexer: source text to [`Token`]s, plus the decoders of literal text.
//!
//! [`tokenize`] implements spec/lexical.md in one pass over the bytes. It never fails: every problem
//! becomes a [`SyntaxError`] and lexing goes on (an unknown character is skipped as an
//! [`TokenKind::Unknown`] token, a bad literal still becomes a literal token).
//!
//! Invariants:
//! - Every iteration of the main loop consumes at least one byte, so lexing is linear in the input.
//! - Token spans start and end on character boundaries (non-ASCII characters only occur inside
//!   comments, strings and `Unknown` runs, which are consumed whole characters at a time).
//! - The output ends with one `Eof` token.
//!
//! Decisions where the spec leaves room:
//! - A string literal ends at the end of its line: a missing `"` is reported there (`E0103`) rather
//!   than swallowing the rest of the file.
//! - Hex and binary digits may be separated by `_` after the first digit, like decimal ones.
//! - `//!` and `////…` are ordinary comments; only exactly `///` starts a doc comment.
//! - A byte-order mark at the very start of the file is skipped.
//! - A run of adjacent characters that cannot start a token is one `Unknown` token and one `E0101`.

use super::ast::{FloatSuffix, IntSuffix, Literal};
use super::error::{NumberProblem, RangeTy, SuffixOn, SyntaxError};
use super::token::{Token, TokenKind};
use crate::source::{FileId, Span};

/// Splits `text` into tokens, reporting lexical errors. Doc comments and unknown-character runs are
/// included as tokens ([`TokenKind::DocComment`], [`TokenKind::Unknown`]); other comments and
/// whitespace are not.
pub fn tokenize(file: FileId, text: &str) -> (Vec<Token>, Vec<SyntaxError>) {
    let mut lx = Lexer {
        text,
        bytes: text.as_bytes(),
        pos: 0,
        file,
        tokens: Vec::with_capacity(text.len() / 4 + 1),
        errors: Vec::new(),
    };
    if text.starts_with('\u{feff}') {
        lx.pos = '\u{feff}'.len_utf8();
    }
    lx.run();
    let end = text.len() as u32;
    lx.tokens.push(Token {
        kind: TokenKind::Eof,
        span: Span::new(file, end, end),
    });
    (lx.tokens, lx.errors)
}

struct Lexer<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    file: FileId,
    tokens: Vec<Token>,
    errors: Vec<SyntaxError>,
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_continue(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Whether `c` can start a token (or is whitespace, or starts a comment).
fn can_start_token(c: char) -> bool {
    c.is_ascii_alphanumeric()
        || matches!(
            c,
            '_' | ' '
                | '\t'
                | '\r'
                | '\n'
                | '"'
                | '('
                | ')'
                | '{'
                | '}'
                | '['
                | ']'
                | '<'
                | '>'
                | ','
                | ';'
                | ':'
                | '.'
                | '-'
                | '@'
                | '='
                | '+'
                | '*'
                | '/'
                | '%'
                | '!'
                | '~'
                | '&'
                | '|'
                | '^'
        )
}

impl Lexer<'_> {
    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn span(&self, lo: usize, hi: usize) -> Span {
        Span::new(self.file, lo as u32, hi as u32)
    }

    fn push(&mut self, kind: TokenKind, lo: usize) {
        let span = self.span(lo, self.pos);
        self.tokens.push(Token { kind, span });
    }

    fn run(&mut self) {
        while self.pos < self.bytes.len() {
            let start = self.pos;
            let b = self.bytes[self.pos];
            match b {
                b' ' | b'\t' | b'\r' | b'\n' => self.pos += 1,
                b'/' if self.peek(1) == b'/' => self.line_comment(),
                b'/' if self.peek(1) == b'*' => self.block_comment(),
                b'"' => self.string(),
                b'0'..=b'9' => self.number(),
                _ if is_ident_start(b) => self.ident(),
                _ if b.is_ascii() && can_start_token(b as char) => self.punct(),
                _ => self.unknown(),
            }
            debug_assert!(self.pos > start, "the lexer must make progress");
        }
    }

    fn line_comment(&mut self) {
        let lo = self.pos;
        let end = self.bytes[lo..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(self.bytes.len(), |n| lo + n);
        self.pos = end;
        let is_doc = self.bytes.get(lo + 2) == Some(&b'/') && self.bytes.get(lo + 3) != Some(&b'/');
        if is_doc {
            let hi = if end > lo && self.bytes[end - 1] == b'\r' {
                end - 1
            } else {
                end
            };
            let span = self.span(lo, hi);
            self.tokens.push(Token {
                kind: TokenKind::DocComment,
                span,
            });
        }
    }

    fn block_comment(&mut self) {
        let lo = self.pos;
        self.pos += 2;
        let mut depth = 1usize;
        while self.pos < self.bytes.len() {
            match (self.bytes[self.pos], self.peek(1)) {
                (b'/', b'*') => {
                    depth += 1;
                    self.pos += 2;
                }
                (b'*', b'/') => {
                    depth -= 1;
                    self.pos += 2;
                    if depth == 0 {
                        return;
                    }
                }
                _ => self.pos += 1,
            }
        }
        let span = self.span(lo, lo + 2);
        self.errors.push(SyntaxError::UnterminatedComment { span });
    }

    fn ident(&mut self) {
        let lo = self.pos;
        while self.pos < self.bytes.len() && is_ident_continue(self.bytes[self.pos]) {
            self.pos += 1;
        }
        let kind = TokenKind::keyword(&self.text[lo..self.pos]).unwrap_or(TokenKind::Ident);
        self.push(kind, lo);
    }

    fn unknown(&mut self) {
        let lo = self.pos;
        let mut first = None;
        while let Some(c) = self.text.get(self.pos..).and_then(|s| s.chars().next()) {
            if can_start_token(c) {
                break;
            }
            first.get_or_insert(c);
            self.pos += c.len_utf8();
        }
        if self.pos == lo {
            // Not reachable for valid UTF-8 text, but never loop forever.
            self.pos += 1;
        }
        let span = self.span(lo, self.pos);
        self.errors.push(SyntaxError::UnknownChar {
            ch: first.unwrap_or('\u{fffd}'),
            span,
        });
        self.push(TokenKind::Unknown, lo);
    }

    fn string(&mut self) {
        let lo = self.pos;
        self.pos += 1;
        loop {
            match self.bytes.get(self.pos).copied() {
                None | Some(b'\n') => {
                    let mut hi = self.pos;
                    if hi > lo + 1 && self.bytes[hi - 1] == b'\r' {
                        hi -= 1;
                    }
                    let span = self.span(lo, hi);
                    self.errors.push(SyntaxError::UnterminatedString { span });
                    self.push(TokenKind::Str, lo);
                    return;
                }
                Some(b'"') => {
                    self.pos += 1;
                    self.push(TokenKind::Str, lo);
                    return;
                }
                Some(b'\\') => {
                    let esc = self.pos;
                    match self.text.get(esc + 1..).and_then(|s| s.chars().next()) {
                        Some('"' | '\\' | 'n' | 't') => self.pos += 2,
                        // `\` at the end of the line: the string is unterminated, reported above.
                        None | Some('\n') | Some('\r') => self.pos += 1,
                        Some(c) => {
                            self.pos += 1 + c.len_utf8();
                            let span = self.span(esc, self.pos);
                            self.errors
                                .push(SyntaxError::InvalidEscape { ch: Some(c), span });
                        }
                    }
                }
                Some(b) => {
                    // Step over a whole character.
                    self.pos += utf8_len(b);
                }
            }
        }
    }

    fn number(&mut self) {
        let lo = self.pos;
        self.pos = scan_number(self.bytes, lo);
        let text = &self.text[lo..self.pos];
        let (lit, problem) = decode_number(text);
        if let Some(p) = problem {
            let span = self.span(lo + p.lo, lo + p.hi);
            self.errors.push(p.into_error(span));
        }
        let kind = match lit {
            Literal::Float { .. } => TokenKind::Float,
            _ => TokenKind::Int,
        };
        self.push(kind, lo);
    }

    fn punct(&mut self) {
        use TokenKind::*;
        let lo = self.pos;
        let (kind, len) = match (self.peek(0), self.peek(1), self.peek(2)) {
            (b'<', b'<', b'=') => (ShlEq, 3),
            (b'>', b'>', b'=') => (ShrEq, 3),
            (b'.', b'.', _) => (DotDot, 2),
            (b'-', b'>', _) => (Arrow, 2),
            (b'&', b'&', _) => (AmpAmp, 2),
            (b'|', b'|', _) => (PipePipe, 2),
            (b'<', b'<', _) => (Shl, 2),
            (b'>', b'>', _) => (Shr, 2),
            (b'=', b'=', _) => (EqEq, 2),
            (b'!', b'=', _) => (Ne, 2),
            (b'<', b'=', _) => (Le, 2),
            (b'>', b'=', _) => (Ge, 2),
            (b'+', b'=', _) => (PlusEq, 2),
            (b'-', b'=', _) => (MinusEq, 2),
            (b'*', b'=', _) => (StarEq, 2),
            (b'/', b'=', _) => (SlashEq, 2),
            (b'%', b'=', _) => (PercentEq, 2),
            (b'&', b'=', _) => (AmpEq, 2),
            (b'|', b'=', _) => (PipeEq, 2),
            (b'^', b'=', _) => (CaretEq, 2),
            (b'(', _, _) => (LParen, 1),
            (b')', _, _) => (RParen, 1),
            (b'{', _, _) => (LBrace, 1),
            (b'}', _, _) => (RBrace, 1),
            (b'[', _, _) => (LBracket, 1),
            (b']', _, _) => (RBracket, 1),
            (b'<', _, _) => (Lt, 1),
            (b'>', _, _) => (Gt, 1),
            (b',', _, _) => (Comma, 1),
            (b';', _, _) => (Semi, 1),
            (b':', _, _) => (Colon, 1),
            (b'.', _, _) => (Dot, 1),
            (b'-', _, _) => (Minus, 1),
            (b'@', _, _) => (At, 1),
            (b'=', _, _) => (Eq, 1),
            (b'+', _, _) => (Plus, 1),
            (b'*', _, _) => (Star, 1),
            (b'/', _, _) => (Slash, 1),
            (b'%', _, _) => (Percent, 1),
            (b'!', _, _) => (Bang, 1),
            (b'~', _, _) => (Tilde, 1),
            (b'&', _, _) => (Amp, 1),
            (b'|', _, _) => (Pipe, 1),
            (b'^', _, _) => (Caret, 1),
            // `can_start_token` admits nothing else here; treat anything else as unknown.
            _ => {
                self.unknown();
                return;
            }
        };
        self.pos += len;
        self.push(kind, lo);
    }
}

/// Length of the UTF-8 sequence starting with byte `b` (1 for continuation bytes, which never start
/// a character in valid text).
fn utf8_len(b: u8) -> usize {
    match b {
        0xf0..=0xff => 4,
        0xe0..=0xef => 3,
        0xc0..=0xdf => 2,
        _ => 1,
    }
}

/// The end of the number literal starting at `lo` (a digit): digits, one fraction, an exponent and a
/// suffix, plus the malformed extras the decoder reports (`1.`, `1.0.0`).
fn scan_number(b: &[u8], lo: usize) -> usize {
    let at = |i: usize| b.get(i).copied().unwrap_or(0);
    let digits = |mut i: usize| {
        while at(i).is_ascii_digit() || at(i) == b'_' {
            i += 1;
        }
        i
    };
    let suffix = |mut i: usize| {
        while is_ident_continue(at(i)) {
            i += 1;
        }
        i
    };
    if at(lo) == b'0' && matches!(at(lo + 1), b'x' | b'b') {
        return suffix(lo + 2);
    }
    let mut i = digits(lo);
    if at(i) == b'.' {
        if at(i + 1).is_ascii_digit() {
            i = digits(i + 1);
            while at(i) == b'.' && at(i + 1).is_ascii_digit() {
                i = digits(i + 1);
            }
        } else if at(i + 1) != b'.' && !is_ident_start(at(i + 1)) {
            return i + 1;
        }
    }
    if matches!(at(i), b'e' | b'E') {
        if at(i + 1).is_ascii_digit() {
            i = digits(i + 1);
        } else if matches!(at(i + 1), b'+' | b'-') && at(i + 2).is_ascii_digit() {
            i = digits(i + 2);
        }
    }
    suffix(i)
}

/// A problem with a number literal, at a byte range relative to the literal's start.
#[derive(Clone, Debug, PartialEq)]
pub struct NumberError {
    /// First byte of the problem, relative to the literal.
    pub lo: usize,
    /// One past its last byte.
    pub hi: usize,
    kind: NumberErrorKind,
}

#[derive(Clone, Debug, PartialEq)]
enum NumberErrorKind {
    Malformed(NumberProblem),
    Range(RangeTy),
    Suffix(String, SuffixOn),
}

impl NumberError {
    fn into_error(self, span: Span) -> SyntaxError {
        match self.kind {
            NumberErrorKind::Malformed(problem) => SyntaxError::MalformedNumber { problem, span },
            NumberErrorKind::Range(ty) => SyntaxError::NumberOutOfRange { ty, span },
            NumberErrorKind::Suffix(suffix, on) => SyntaxError::UnknownSuffix { suffix, on, span },
        }
    }
}

/// Decodes the text of a number token into its value, with the first problem found, if any. The
/// value is a best effort when there is a problem (the parser uses it to keep going).
///
/// The `i` suffix admits magnitudes up to 2^31 here, because `-2147483648i` is the operator `-`
/// applied to `2147483648i`; the parser reports 2^31 when it is not negated.
pub fn decode_number(text: &str) -> (Literal, Option<NumberError>) {
    let b = text.as_bytes();
    let whole = |kind| NumberError {
        lo: 0,
        hi: text.len(),
        kind,
    };
    if b.len() >= 2 && b[0] == b'0' && matches!(b[1], b'x' | b'b') {
        return decode_radix(text);
    }
    let at = |i: usize| b.get(i).copied().unwrap_or(0);
    let mut i = 0;
    while at(i).is_ascii_digit() || at(i) == b'_' {
        i += 1;
    }
    let int_end = i;
    let mut is_float = false;
    let mut problem = None;
    let mut value_end;
    if at(i) == b'.' && at(i + 1).is_ascii_digit() {
        is_float = true;
        i += 1;
        while at(i).is_ascii_digit() || at(i) == b'_' {
            i += 1;
        }
        value_end = i;
        if at(i) == b'.' {
            let lo = i;
            while at(i) == b'.' || at(i).is_ascii_digit() || at(i) == b'_' {
                i += 1;
            }
            problem = Some(NumberError {
                lo,
                hi: i,
                kind: NumberErrorKind::Malformed(NumberProblem::SecondDot),
            });
        }
    } else if at(i) == b'.' {
        // `1.`: the scanner only includes the dot in this malformed case.
        let digits = text[..i].replace('_', "");
        let value = digits.parse::<f64>().unwrap_or(0.0);
        return (
            Literal::Float {
                value,
                suffix: None,
            },
            Some(whole(NumberErrorKind::Malformed(
                NumberProblem::TrailingDot { digits },
            ))),
        );
    } else {
        value_end = i;
    }
    let mut has_exponent = false;
    if matches!(at(i), b'e' | b'E')
        && (at(i + 1).is_ascii_digit()
            || (matches!(at(i + 1), b'+' | b'-') && at(i + 2).is_ascii_digit()))
    {
        is_float = true;
        has_exponent = true;
        i += if at(i + 1).is_ascii_digit() { 1 } else { 2 };
        while at(i).is_ascii_digit() || at(i) == b'_' {
            i += 1;
        }
        if problem.is_none() {
            value_end = i;
        }
    }
    let suffix = &text[i..];
    let mut float_suffix = None;
    let mut int_suffix = None;
    if !suffix.is_empty() && problem.is_none() {
        match suffix {
            "f" => {
                is_float = true;
                float_suffix = Some(FloatSuffix::F);
            }
            "i" if !is_float => int_suffix = Some(IntSuffix::I),
            "u" if !is_float => int_suffix = Some(IntSuffix::U),
            s if !has_exponent && s.starts_with(['e', 'E']) => {
                problem = Some(whole(NumberErrorKind::Malformed(
                    NumberProblem::NoExponentDigits,
                )));
            }
            s => {
                let on = if is_float {
                    SuffixOn::Float
                } else {
                    SuffixOn::Decimal
                };
                problem = Some(NumberError {
                    lo: i,
                    hi: text.len(),
                    kind: NumberErrorKind::Suffix(s.to_string(), on),
                });
            }
        }
    }
    if is_float {
        let digits = &text[..value_end];
        let value = if digits.contains('_') {
            digits.replace('_', "").parse::<f64>()
        } else {
            digits.parse::<f64>()
        }
        .unwrap_or(0.0);
        if value.is_infinite() && problem.is_none() {
            problem = Some(whole(NumberErrorKind::Range(RangeTy::Float)));
        }
        let lit = Literal::Float {
            value,
            suffix: float_suffix,
        };
        return (lit, problem);
    }
    let (value, overflow) = accumulate(&text[..int_end], 10);
    if problem.is_none() {
        problem =
            range_problem(value, overflow, int_suffix).map(|ty| whole(NumberErrorKind::Range(ty)));
    }
    (
        Literal::Int {
            value,
            suffix: int_suffix,
        },
        problem,
    )
}

fn decode_radix(text: &str) -> (Literal, Option<NumberError>) {
    let b = text.as_bytes();
    let (radix, prefix) = if b[1] == b'x' { (16, "0x") } else { (2, "0b") };
    let mut i = 2;
    let is_digit = |c: u8| {
        if radix == 16 {
            c.is_ascii_hexdigit()
        } else {
            c.is_ascii_digit()
        }
    };
    while i < b.len() && (is_digit(b[i]) || b[i] == b'_') {
        i += 1;
    }
    let digits = &text[2..i];
    let suffix_text = &text[i..];
    let whole = |kind| NumberError {
        lo: 0,
        hi: text.len(),
        kind,
    };
    let mut problem = None;
    if !digits.bytes().any(|c| c != b'_') {
        problem = Some(whole(NumberErrorKind::Malformed(NumberProblem::NoDigits {
            prefix,
        })));
    } else if radix == 2 && digits.bytes().any(|c| c.is_ascii_digit() && c > b'1') {
        problem = Some(whole(NumberErrorKind::Malformed(
            NumberProblem::BadBinaryDigit,
        )));
    }
    let suffix = match suffix_text {
        "" => None,
        "i" => Some(IntSuffix::I),
        "u" => Some(IntSuffix::U),
        s => {
            if problem.is_none() {
                problem = Some(NumberError {
                    lo: i,
                    hi: text.len(),
                    kind: NumberErrorKind::Suffix(s.to_string(), SuffixOn::HexOrBinary),
                });
            }
            None
        }
    };
    let (value, overflow) = accumulate(digits, radix);
    if problem.is_none() {
        problem =
            range_problem(value, overflow, suffix).map(|ty| whole(NumberErrorKind::Range(ty)));
    }
    (Literal::Int { value, suffix }, problem)
}

/// The digits' value (saturating at `u64::MAX`) and whether it overflowed 64 bits.
fn accumulate(digits: &str, radix: u32) -> (u64, bool) {
    let mut value: u64 = 0;
    let mut overflow = false;
    for c in digits.chars() {
        let Some(d) = c.to_digit(radix) else {
            continue;
        };
        match value
            .checked_mul(u64::from(radix))
            .and_then(|v| v.checked_add(u64::from(d)))
        {
            Some(v) => value = v,
            None => {
                overflow = true;
                value = u64::MAX;
            }
        }
    }
    (value, overflow)
}

fn range_problem(value: u64, overflow: bool, suffix: Option<IntSuffix>) -> Option<RangeTy> {
    match suffix {
        _ if overflow => Some(match suffix {
            None => RangeTy::U64,
            Some(IntSuffix::I) => RangeTy::I32,
            Some(IntSuffix::U) => RangeTy::U32,
        }),
        Some(IntSuffix::I) if value > 1 << 31 => Some(RangeTy::I32),
        Some(IntSuffix::U) if value > u64::from(u32::MAX) => Some(RangeTy::U32),
        _ => None,
    }
}

/// The value of a string token's text (with its quotes): escapes resolved, unknown escapes kept as
/// written, backslash included (the lexer has reported them), a missing closing quote tolerated.
pub fn unescape(text: &str) -> String {
    let inner = text.strip_prefix('"').unwrap_or(text);
    let mut out = String::with_capacity(inner.len());
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => break,
            '\\' => match chars.next() {
                Some('n') => out.push('\n'),
                Some('t') => out.push('\t'),
                Some(c @ ('"' | '\\')) => out.push(c),
                Some(c) => {
                    out.push('\\');
                    out.push(c);
                }
                None => break,
            },
            c => out.push(c),
        }
    }
    out
}
