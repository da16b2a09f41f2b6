//! Lexical and syntax errors, and their one conversion to [`Diagnostic`]s.
//!
//! The lexer and the parser record [`SyntaxError`]s: typed variants with spans and the few pieces of
//! text a message needs (a misspelt name, the token that was found). Nothing is formatted until
//! [`SyntaxError::to_diagnostic`], the only place that chooses codes, wording, labels and help lines
//! (its longer arms delegate to the helpers in `messages`).
//!
//! Invariants:
//! - Every variant maps to exactly one code from [`crate::diag::codes`] (`E01xx` lexical, `E02xx`
//!   syntax, `E0308` for a late import, `E0414` for a call of something that is not a name,
//!   `E0701` for an unknown scene entry).
//! - Messages follow rustc: lower case, no trailing period, the offending token in backquotes.

mod messages;

use super::token::TokenKind;
use crate::diag::{codes, Diagnostic};
use crate::source::Span;

/// The attributes the parser knows (spec/programs.md). Anything else is `E0203`.
pub const KNOWN_ATTRIBUTES: &[&str] = &[
    "ray_generation",
    "intersection",
    "bounds",
    "any_hit",
    "closest_hit",
    "secondary_rays",
    "light",
    "miss",
    "medium",
    "camera",
    "geometry",
    "material",
    "background",
];

/// The words that start a scene entry (`let` is a keyword; the others are contextual).
pub const SCENE_ENTRIES: &[&str] = &[
    "settings",
    "camera",
    "background",
    "let",
    "object",
    "light",
    "model",
    "animate",
];

/// The token the parser found where it expected something else.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// Its kind.
    pub kind: TokenKind,
    /// Its text, cut to a readable length (empty at the end of the file).
    pub text: String,
}

impl Found {
    /// The token of kind `kind` whose text is `text`.
    pub fn new(kind: TokenKind, text: &str) -> Found {
        Found {
            kind,
            text: messages::cut(text),
        }
    }

    fn describe(&self) -> String {
        match self.kind {
            TokenKind::Eof => "end of file".to_string(),
            k if k.is_keyword() => format!("keyword `{}`", self.text),
            TokenKind::Str => format!("string literal {}", self.text),
            _ => format!("`{}`", self.text),
        }
    }
}

/// What the parser expected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// This token.
    Token(TokenKind),
    /// One of these tokens.
    OneOf(&'static [TokenKind]),
    /// An expression.
    Expression,
    /// A type.
    Type,
    /// A name.
    Ident,
    /// A field name after `.`.
    FieldName,
    /// An item (`fn`, `struct`, `const`, `scene`, `import`).
    Item,
    /// A statement.
    Statement,
    /// A scene entry.
    SceneEntry,
    /// A motion after an `animate` target.
    Motion,
    /// A string literal (an import or model path).
    Path,
}

impl Expected {
    fn describe(self) -> String {
        match self {
            Expected::Token(k) => k.describe().to_string(),
            Expected::OneOf(ks) => {
                let names: Vec<&str> = ks.iter().map(|k| k.describe()).collect();
                match names.split_last() {
                    Some((last, rest)) if !rest.is_empty() => {
                        format!("{} or {last}", rest.join(", "))
                    }
                    Some((last, _)) => last.to_string(),
                    None => "a token".to_string(),
                }
            }
            Expected::Expression => "an expression".to_string(),
            Expected::Type => "a type".to_string(),
            Expected::Ident => "an identifier".to_string(),
            Expected::FieldName => "a field name".to_string(),
            Expected::Item => "an item".to_string(),
            Expected::Statement => "a statement".to_string(),
            Expected::SceneEntry => "a scene entry".to_string(),
            Expected::Motion => "a motion (`keys { … }`, `spin(…)` or `move(…)`)".to_string(),
            Expected::Path => "a string literal".to_string(),
        }
    }
}

/// A help line attached to an [`SyntaxError::Expected`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Hint {
    /// `if x = 1 {`
    UseEqEq,
    /// `fn f(x) {`
    ParamNeedsType {
        /// The parameter's name.
        name: String,
    },
    /// A stray `;`.
    RemoveSemicolon,
    /// A `;` after a scene entry.
    SceneEntryNoSemicolon,
    /// `for i in range(n)`
    RangeSyntax,
    /// `let mut x`
    UseVar,
    /// `let x;`
    LetNeedsValue,
    /// `x as f32`
    ConvertWithCall,
    /// `v.length()`
    CallByName,
    /// `[1, 2, 3]`
    ArrayConstructor,
    /// `Foo { a }`
    FieldShorthand {
        /// The field's name.
        name: String,
    },
    /// `v.0`
    VectorComponents,
    /// `if x return;`
    NeedsBraces,
    /// A missing `,` between two list elements on different lines.
    AddComma,
}

impl Hint {
    fn text(&self) -> String {
        match self {
            Hint::UseEqEq => "use `==` to compare".to_string(),
            Hint::ParamNeedsType { name } => format!("parameters need a type: `{name}: f32`"),
            Hint::RemoveSemicolon => "remove this `;`".to_string(),
            Hint::SceneEntryNoSemicolon => {
                "scene entries other than `let` do not end with `;`".to_string()
            }
            Hint::RangeSyntax => {
                "a `for` loop runs over a range: `for i in 0..n { … }`".to_string()
            }
            Hint::UseVar => "a variable that changes is declared with `var`".to_string(),
            Hint::LetNeedsValue => {
                "a `let` needs a value; declare a variable that starts at zero with `var name: T;`"
                    .to_string()
            }
            Hint::ConvertWithCall => "convert with the type's name: `f32(x)`".to_string(),
            Hint::CallByName => {
                "functions are called by name: `length(v)`, not `v.length()`".to_string()
            }
            Hint::ArrayConstructor => "array values are written `array(a, b, c)`".to_string(),
            Hint::FieldShorthand { name } => format!("write `{name}: {name}`"),
            Hint::VectorComponents => {
                "vector components are `.x`, `.y`, `.z` and `.w`; elements are `a[i]`".to_string()
            }
            Hint::NeedsBraces => "the body must be a block in braces: `{ … }`".to_string(),
            Hint::AddComma => "add `,` here".to_string(),
        }
    }
}

/// What is wrong with a malformed number literal (`E0104`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NumberProblem {
    /// `0x` or `0b` without digits.
    NoDigits {
        /// `"0x"` or `"0b"`.
        prefix: &'static str,
    },
    /// `1e`, `1e+`.
    NoExponentDigits,
    /// `1.`
    TrailingDot {
        /// The digits before the dot.
        digits: String,
    },
    /// `.5`
    LeadingDot {
        /// The digits after the dot.
        digits: String,
    },
    /// `1.0.0`
    SecondDot,
    /// `0b102`
    BadBinaryDigit,
}

/// The type a literal does not fit (`E0105`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RangeTy {
    /// An unsuffixed integer beyond 64 bits.
    U64,
    /// An `i`-suffixed literal beyond `i32` (beyond 2^31, or 2^31 without a leading `-`).
    I32,
    /// A `u`-suffixed literal beyond `u32`.
    U32,
    /// A float literal too large for any float type.
    Float,
}

/// What kind of literal a wrong suffix was attached to (`E0106`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SuffixOn {
    /// A decimal integer (may take `i`, `u` or `f`).
    Decimal,
    /// A hex or binary integer (may take `i` or `u`).
    HexOrBinary,
    /// A float (may take `f`).
    Float,
}

/// Where an item-like construct appeared that cannot appear there (`E0206`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// At the top level of the file.
    TopLevel,
    /// Inside a block.
    Block,
    /// Inside a struct body.
    Struct,
    /// Inside a scene.
    Scene,
}

/// The construct whose condition held a struct literal (`E0204`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CondContext {
    /// `if cond {`
    If,
    /// `while cond {`
    While,
    /// `for i in a..b {`
    For,
}

/// What was nested too deeply (`E0202`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Nesting {
    /// Expressions (parentheses, calls, operators).
    Expression,
    /// Blocks and statements.
    Block,
    /// Type expressions.
    Type,
}

/// One lexical or syntax error.
#[derive(Clone, Debug, PartialEq)]
pub enum SyntaxError {
    /// `E0101`: a character that cannot start a token (a run of them is reported once).
    UnknownChar {
        /// The first character of the run.
        ch: char,
        /// The run.
        span: Span,
    },
    /// `E0102`: `/*` without its `*/`.
    UnterminatedComment {
        /// The opening `/*` that is not closed.
        span: Span,
    },
    /// `E0103`: a string literal without its closing `"` on the same line.
    UnterminatedString {
        /// From the opening `"` to the end of the line.
        span: Span,
    },
    /// `E0104`: a malformed number literal.
    MalformedNumber {
        /// What is wrong.
        problem: NumberProblem,
        /// The literal.
        span: Span,
    },
    /// `E0105`: a literal too large for its type.
    NumberOutOfRange {
        /// The type it does not fit.
        ty: RangeTy,
        /// The literal.
        span: Span,
    },
    /// `E0106`: an unknown literal suffix.
    UnknownSuffix {
        /// The suffix as written.
        suffix: String,
        /// The kind of literal.
        on: SuffixOn,
        /// The suffix.
        span: Span,
    },
    /// `E0107`: an escape other than `\" \\ \n \t`.
    InvalidEscape {
        /// The character after the backslash (`None` at the end of the line).
        ch: Option<char>,
        /// The escape.
        span: Span,
    },
    /// `E0201`: something else was expected.
    Expected {
        /// What was expected.
        expected: Expected,
        /// What was found.
        found: Found,
        /// The found token (an empty span at the end of the file).
        span: Span,
        /// A help line, where one helps.
        hint: Option<Hint>,
    },
    /// `E0201`: a `;` (or `,`) missing at the end of a line.
    Missing {
        /// The missing token.
        token: TokenKind,
        /// Empty span just after the previous token.
        span: Span,
        /// The token on the next line.
        found: Found,
        /// Its span.
        found_span: Span,
    },
    /// `E0201`: `x as f32`.
    AsCast {
        /// The `as` keyword.
        span: Span,
    },
    /// `E0414`: `(…)` after something that is not a function name, such as `v.length()`.
    CallOfNonName {
        /// The callee expression.
        span: Span,
        /// Whether it looks like a method call (`x.f(…)`).
        method: bool,
    },
    /// `E0201`: a closing delimiter missing.
    Unclosed {
        /// The closing delimiter that was expected.
        close: TokenKind,
        /// What was found instead.
        found: Found,
        /// The found token.
        span: Span,
        /// The opening delimiter.
        open: Span,
    },
    /// `E0201`: `a < b < c`.
    ChainedComparison {
        /// The second comparison operator.
        span: Span,
        /// The first one.
        first: Span,
    },
    /// `E0201`: `var x;`.
    VarNeedsTypeOrValue {
        /// The variable's name.
        name: String,
        /// The statement.
        span: Span,
    },
    /// `E0202`: nesting beyond the parser's limit.
    TooDeep {
        /// What was nested.
        what: Nesting,
        /// The token where the limit was reached.
        span: Span,
    },
    /// `E0203`: an attribute that is not known.
    UnknownAttribute {
        /// Its name.
        name: String,
        /// The closest known attribute, if one is close.
        suggestion: Option<&'static str>,
        /// The attribute's name.
        span: Span,
    },
    /// `E0204`: `if x == Foo { a: 1.0 } {`.
    StructLitInCondition {
        /// Where the literal is.
        context: CondContext,
        /// The struct's name.
        name: String,
        /// The literal.
        span: Span,
    },
    /// `E0205`: `f() = 1`.
    InvalidAssignTarget {
        /// The left-hand side.
        span: Span,
        /// The assignment operator.
        op_span: Span,
    },
    /// `E0206`: an item (or `let`) where it cannot appear.
    MisplacedItem {
        /// Its keyword (`fn`, `struct`, `const`, `scene`, `import`, `let`, `var`, or `@`).
        keyword: TokenKind,
        /// Where it appeared.
        place: Place,
        /// The keyword.
        span: Span,
    },
    /// `E0308`: an import after an item.
    ImportAfterItem {
        /// The import.
        span: Span,
        /// The first item of the file.
        first_item: Span,
    },
    /// `E0701`: an unknown word at the start of a scene entry.
    UnknownSceneEntry {
        /// The word.
        name: String,
        /// The closest entry keyword, if one is close.
        suggestion: Option<&'static str>,
        /// The word.
        span: Span,
    },
}

impl SyntaxError {
    /// The primary span.
    pub fn span(&self) -> Span {
        use SyntaxError::*;
        match self {
            UnknownChar { span, .. }
            | UnterminatedComment { span }
            | UnterminatedString { span }
            | MalformedNumber { span, .. }
            | NumberOutOfRange { span, .. }
            | UnknownSuffix { span, .. }
            | InvalidEscape { span, .. }
            | Expected { span, .. }
            | Missing { span, .. }
            | AsCast { span }
            | CallOfNonName { span, .. }
            | Unclosed { span, .. }
            | ChainedComparison { span, .. }
            | VarNeedsTypeOrValue { span, .. }
            | TooDeep { span, .. }
            | UnknownAttribute { span, .. }
            | StructLitInCondition { span, .. }
            | InvalidAssignTarget { span, .. }
            | MisplacedItem { span, .. }
            | ImportAfterItem { span, .. }
            | UnknownSceneEntry { span, .. } => *span,
        }
    }

    /// The diagnostic shown to the user: the one place codes and wording are chosen.
    pub fn to_diagnostic(&self) -> Diagnostic {
        use messages as m;
        use SyntaxError::*;
        match self {
            UnknownChar { ch, span } => m::unknown_char(*ch, *span),
            UnterminatedComment { span } => {
                Diagnostic::error(codes::E0102, "unterminated block comment", *span)
                    .with_label("this comment is never closed")
                    .with_note("block comments nest: every `/*` needs its own `*/`")
            }
            UnterminatedString { span } => {
                Diagnostic::error(codes::E0103, "unterminated string literal", *span)
                    .with_label("this string has no closing `\"`")
                    .with_help("close the string with `\"` before the end of the line")
            }
            MalformedNumber { problem, span } => m::malformed_number(problem, *span),
            NumberOutOfRange { ty, span } => m::out_of_range(*ty, *span),
            UnknownSuffix { suffix, on, span } => m::unknown_suffix(suffix, *on, *span),
            InvalidEscape { ch, span } => m::invalid_escape(*ch, *span),
            Expected {
                expected,
                found,
                span,
                hint,
            } => m::expected(*expected, found, *span, hint.as_ref()),
            Missing {
                token,
                span,
                found,
                found_span,
            } => m::missing(*token, *span, found, *found_span),
            AsCast { span } => Diagnostic::error(codes::E0201, "there are no `as` casts", *span)
                .with_label("`as` is reserved")
                .with_help(Hint::ConvertWithCall.text()),
            CallOfNonName { span, method } => m::call_of_non_name(*span, *method),
            Unclosed {
                close,
                found,
                span,
                open,
            } => m::unclosed(*close, found, *span, *open),
            ChainedComparison { span, first } => Diagnostic::error(
                codes::E0201,
                "comparison operators cannot be chained",
                *span,
            )
            .with_label("second comparison")
            .with_secondary(*first, "first comparison")
            .with_help("use `&&` to combine comparisons, as in `a < b && b < c`"),
            VarNeedsTypeOrValue { name, span } => m::var_needs_type_or_value(name, *span),
            TooDeep { what, span } => m::too_deep(*what, *span),
            UnknownAttribute {
                name,
                suggestion,
                span,
            } => m::unknown_attribute(name, *suggestion, *span),
            StructLitInCondition {
                context,
                name,
                span,
            } => m::struct_lit_in_condition(*context, name, *span),
            InvalidAssignTarget { span, op_span } => Diagnostic::error(
                codes::E0205,
                "invalid left-hand side of assignment",
                *span,
            )
            .with_label("cannot assign to this expression")
            .with_secondary(*op_span, "assignment here")
            .with_help(
                "assign to a variable, a field (`s.f`), a component (`v.x`) or an element (`a[i]`)",
            ),
            MisplacedItem {
                keyword,
                place,
                span,
            } => m::misplaced_item(*keyword, *place, *span),
            ImportAfterItem { span, first_item } => {
                Diagnostic::error(codes::E0308, "imports must come before all items", *span)
                    .with_label("import after an item")
                    .with_secondary(*first_item, "first item")
                    .with_help("move this import to the top of the file")
            }
            UnknownSceneEntry {
                name,
                suggestion,
                span,
            } => m::unknown_scene_entry(name, *suggestion, *span),
        }
    }
}
