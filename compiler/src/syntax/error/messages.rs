//! The wording of the longer syntax diagnostics: helpers of [`super::SyntaxError::to_diagnostic`],
//! one per variant, taking the variant's data.
//!
//! Invariant: user text quoted in a message goes through [`cut`], so a megabyte-long identifier
//! cannot make a megabyte-long message.

use super::{
    CondContext, Expected, Found, Hint, Nesting, NumberProblem, Place, RangeTy, SuffixOn,
    KNOWN_ATTRIBUTES,
};
use crate::diag::{codes, Diagnostic};
use crate::source::Span;
use crate::syntax::token::TokenKind;

/// Longest user text quoted in a message; longer text is cut with `…`.
const MAX_QUOTED: usize = 32;

/// User text cut to a readable length for a message.
pub(super) fn cut(s: &str) -> String {
    if s.chars().count() > MAX_QUOTED {
        let mut t: String = s.chars().take(MAX_QUOTED).collect();
        t.push('…');
        t
    } else {
        s.to_string()
    }
}

pub(super) fn unknown_char(ch: char, span: Span) -> Diagnostic {
    let d = Diagnostic::error(
        codes::E0101,
        format!("unknown character `{}`", ch.escape_debug()),
        span,
    )
    .with_label("cannot start a token");
    match ch {
        '\u{201c}' | '\u{201d}' | '\'' => {
            d.with_help("strings are written in straight double quotes: `\"…\"`")
        }
        c if c.is_alphabetic() => {
            d.with_help("identifiers are made of ASCII letters, digits and `_`")
        }
        _ => d,
    }
}

pub(super) fn malformed_number(problem: &NumberProblem, span: Span) -> Diagnostic {
    let d = Diagnostic::error(codes::E0104, "malformed number literal", span);
    match problem {
        NumberProblem::NoDigits { prefix } => d
            .with_label(format!("`{prefix}` needs digits after it"))
            .with_help(if *prefix == "0x" {
                "write hex digits after `0x`, as in `0xff`"
            } else {
                "write binary digits after `0b`, as in `0b101`"
            }),
        NumberProblem::NoExponentDigits => d
            .with_label("the exponent has no digits")
            .with_help("write digits after `e`, as in `1e3` or `2.5e-4`"),
        NumberProblem::TrailingDot { digits } => d
            .with_label("a float literal needs digits after `.`")
            .with_help(format!("write `{}.0`", cut(digits))),
        NumberProblem::LeadingDot { digits } => d
            .with_label("a float literal needs digits before `.`")
            .with_help(format!("write `0.{}`", cut(digits))),
        NumberProblem::SecondDot => d.with_label("a number has at most one `.`"),
        NumberProblem::BadBinaryDigit => d
            .with_label("binary literals have only the digits 0 and 1")
            .with_help("write the number in decimal or hex instead"),
    }
}

pub(super) fn out_of_range(ty: RangeTy, span: Span) -> Diagnostic {
    let (message, label, note) = match ty {
        RangeTy::U64 => (
            "integer literal is too large",
            "does not fit in 64 bits",
            "the largest integer type is `u32` (at most 4294967295)",
        ),
        RangeTy::I32 => (
            "integer literal out of range for `i32`",
            "does not fit in `i32`",
            "`i32` holds -2147483648 to 2147483647",
        ),
        RangeTy::U32 => (
            "integer literal out of range for `u32`",
            "does not fit in `u32`",
            "`u32` holds 0 to 4294967295",
        ),
        RangeTy::Float => (
            "float literal is too large",
            "this is infinite",
            "the largest `f32` is about 3.4e38",
        ),
    };
    Diagnostic::error(codes::E0105, message, span)
        .with_label(label)
        .with_note(note)
}

pub(super) fn unknown_suffix(suffix: &str, on: SuffixOn, span: Span) -> Diagnostic {
    let help = match on {
        SuffixOn::Decimal => "integer literals take the suffix `i` (i32), `u` (u32) or `f` (f32)",
        SuffixOn::HexOrBinary => "hex and binary literals take the suffix `i` (i32) or `u` (u32)",
        SuffixOn::Float => "float literals take only the suffix `f` (f32)",
    };
    let d = Diagnostic::error(
        codes::E0106,
        format!("invalid suffix `{}` on a number literal", cut(suffix)),
        span,
    )
    .with_label("unknown suffix");
    match (suffix, on) {
        ("i32" | "u32", SuffixOn::Decimal | SuffixOn::HexOrBinary) | ("f32", SuffixOn::Decimal) => {
            d.with_help(format!("the suffix for `{suffix}` is `{}`", &suffix[..1]))
        }
        ("f32", SuffixOn::Float) => d.with_help("the suffix for `f32` is `f`"),
        _ => d.with_help(help),
    }
}

pub(super) fn invalid_escape(ch: Option<char>, span: Span) -> Diagnostic {
    let message = match ch {
        Some(c) => format!("unknown escape `\\{}` in a string", c.escape_debug()),
        None => "a `\\` at the end of a string line".to_string(),
    };
    Diagnostic::error(codes::E0107, message, span)
        .with_label("unknown escape")
        .with_help("the escapes are `\\\"`, `\\\\`, `\\n` and `\\t`")
}

pub(super) fn expected(
    expected: Expected,
    found: &Found,
    span: Span,
    hint: Option<&Hint>,
) -> Diagnostic {
    let exp = expected.describe();
    let d = Diagnostic::error(
        codes::E0201,
        format!("expected {exp}, found {}", found.describe()),
        span,
    )
    .with_label(format!("expected {exp}"));
    match hint {
        Some(h) => d.with_help(h.text()),
        None => d,
    }
}

pub(super) fn missing(token: TokenKind, span: Span, found: &Found, found_span: Span) -> Diagnostic {
    Diagnostic::error(
        codes::E0201,
        format!("expected {}, found {}", token.describe(), found.describe()),
        span,
    )
    .with_label(format!("expected {}", token.describe()))
    .with_secondary(found_span, "unexpected token")
    .with_help(format!("add {} here", token.describe()))
}

pub(super) fn unclosed(close: TokenKind, found: &Found, span: Span, open: Span) -> Diagnostic {
    Diagnostic::error(
        codes::E0201,
        format!("expected {}, found {}", close.describe(), found.describe()),
        span,
    )
    .with_label(format!("expected {}", close.describe()))
    .with_secondary(open, "unclosed delimiter")
}

pub(super) fn call_of_non_name(span: Span, method: bool) -> Diagnostic {
    let d = Diagnostic::error(
        codes::E0414,
        "only functions can be called, by their name",
        span,
    )
    .with_label("this is not a function name");
    if method {
        d.with_help(Hint::CallByName.text())
    } else {
        d
    }
}

pub(super) fn var_needs_type_or_value(name: &str, span: Span) -> Diagnostic {
    Diagnostic::error(
        codes::E0201,
        format!("variable `{}` needs a type or a value", cut(name)),
        span,
    )
    .with_help(format!(
        "write `var {0}: f32;` (starts at zero) or `var {0} = 0.0;`",
        cut(name)
    ))
}

pub(super) fn too_deep(what: Nesting, span: Span) -> Diagnostic {
    let message = match what {
        Nesting::Expression => "expression nested too deeply",
        Nesting::Block => "blocks nested too deeply",
        Nesting::Type => "type nested too deeply",
    };
    Diagnostic::error(codes::E0202, message, span)
        .with_label("nesting limit reached here")
        .with_note(format!(
            "the parser accepts at most {} levels of nesting, and expressions at most {} deep",
            crate::syntax::MAX_DEPTH,
            crate::syntax::MAX_EXPR_DEPTH
        ))
        .with_help("split it into `let` bindings or helper functions")
}

pub(super) fn unknown_attribute(
    name: &str,
    suggestion: Option<&'static str>,
    span: Span,
) -> Diagnostic {
    let d = Diagnostic::error(
        codes::E0203,
        format!("unknown attribute `@{}`", cut(name)),
        span,
    )
    .with_label("not a known attribute");
    match suggestion {
        Some(s) => d.with_help(format!("did you mean `@{s}`?")),
        None => d.with_note(format!(
            "the attributes are {}",
            KNOWN_ATTRIBUTES
                .iter()
                .map(|a| format!("`@{a}`"))
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}

pub(super) fn struct_lit_in_condition(context: CondContext, name: &str, span: Span) -> Diagnostic {
    let place = match context {
        CondContext::If => "in an `if` condition",
        CondContext::While => "in a `while` condition",
        CondContext::For => "in a `for` range",
    };
    Diagnostic::error(
        codes::E0204,
        format!("struct literals are not allowed {place}"),
        span,
    )
    .with_label("its `{` would start the block")
    .with_help(format!(
        "parenthesise the struct literal: `({} {{ … }})`",
        cut(name)
    ))
}

pub(super) fn misplaced_item(keyword: TokenKind, place: Place, span: Span) -> Diagnostic {
    let what = match keyword {
        TokenKind::At => "an attributed item".to_string(),
        k => format!("`{}`", k.describe().trim_matches('`')),
    };
    let inside = match place {
        Place::TopLevel => {
            return Diagnostic::error(
                codes::E0206,
                format!("{what} cannot appear at the top level of a file"),
                span,
            )
            .with_label("not an item")
            .with_help("declare a module-level constant with `const NAME: T = value;`");
        }
        Place::Block => "a block",
        Place::Struct => "a struct",
        Place::Scene => "a scene",
    };
    let help = if keyword == TokenKind::Import {
        "imports go at the top of the file"
    } else {
        "move it to the top level of the file"
    };
    Diagnostic::error(
        codes::E0206,
        format!("{what} cannot appear inside {inside}"),
        span,
    )
    .with_label("items are only allowed at the top level")
    .with_help(help)
}

pub(super) fn unknown_scene_entry(
    name: &str,
    suggestion: Option<&'static str>,
    span: Span,
) -> Diagnostic {
    let d = Diagnostic::error(
        codes::E0701,
        format!("unknown scene entry `{}`", cut(name)),
        span,
    )
    .with_label("not a scene entry");
    match suggestion {
        Some(s) => d.with_help(format!("did you mean `{s}`?")),
        None => d.with_note(
            "a scene entry starts with `settings`, `camera`, `background`, `let`, `object`, \
             `light` or `model`",
        ),
    }
}
