//! Tokens: what the lexer produces and the parser consumes.
//!
//! A [`Token`] is a [`TokenKind`] and a [`Span`]; its text is the span's slice of the source. Literal
//! values are not stored in tokens: [`super::lexer::decode_number`] and [`super::lexer::unescape`]
//! decode a literal's text (the lexer has already reported any problem with it), so `TokenKind` stays a
//! plain `Copy + Eq` tag that fits in a [`TokenSet`] bit set.
//!
//! Invariants:
//! - Every token stream ends with exactly one [`TokenKind::Eof`] token (an empty span at the end).
//! - Spans are non-empty (except `Eof`), in increasing order, non-overlapping, on character boundaries.
//! - Keywords are only the reserved words of spec/lexical.md; the contextual scene keywords
//!   (`settings camera background object light model`) are [`TokenKind::Ident`]s.

use crate::source::Span;

/// One token: its kind and where it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// What the token is.
    pub kind: TokenKind,
    /// Where it is.
    pub span: Span,
}

macro_rules! token_kinds {
    ($($(#[$m:meta])* $name:ident => $text:literal,)*) => {
        /// The kinds of tokens. Fieldless, so that sets of kinds are bit sets.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[repr(u8)]
        pub enum TokenKind {
            $( $(#[$m])* #[doc = $text] $name, )*
        }

        impl TokenKind {
            /// How the token is shown in messages: the punctuation or keyword itself in backquotes,
            /// or a description (`identifier`, `integer literal`, …).
            pub fn describe(self) -> &'static str {
                match self { $( TokenKind::$name => $text, )* }
            }
        }
    };
}

token_kinds! {
    /// An identifier (including the contextual scene keywords).
    Ident => "identifier",
    /// An integer literal such as `42`, `0xffu`, `1_000i`.
    Int => "integer literal",
    /// A float literal such as `1.0`, `1e-3`, `2f`.
    Float => "float literal",
    /// A string literal.
    Str => "string literal",
    /// A `///` doc comment (the parser attaches it to the following item or field).
    DocComment => "doc comment",
    /// A run of characters that cannot start a token (already reported, `E0101`).
    Unknown => "unknown character",
    /// The end of the file.
    Eof => "end of file",

    /// `as`
    As => "`as`",
    /// `break`
    Break => "`break`",
    /// `const`
    Const => "`const`",
    /// `continue`
    Continue => "`continue`",
    /// `else`
    Else => "`else`",
    /// `false`
    False => "`false`",
    /// `fn`
    Fn => "`fn`",
    /// `for`
    For => "`for`",
    /// `if`
    If => "`if`",
    /// `import`
    Import => "`import`",
    /// `in`
    In => "`in`",
    /// `let`
    Let => "`let`",
    /// `loop`
    Loop => "`loop`",
    /// `return`
    Return => "`return`",
    /// `scene`
    Scene => "`scene`",
    /// `struct`
    Struct => "`struct`",
    /// `true`
    True => "`true`",
    /// `var`
    Var => "`var`",
    /// `while`
    While => "`while`",

    /// `(`
    LParen => "`(`",
    /// `)`
    RParen => "`)`",
    /// `{`
    LBrace => "`{`",
    /// `}`
    RBrace => "`}`",
    /// `[`
    LBracket => "`[`",
    /// `]`
    RBracket => "`]`",
    /// `,`
    Comma => "`,`",
    /// `;`
    Semi => "`;`",
    /// `:`
    Colon => "`:`",
    /// `.`
    Dot => "`.`",
    /// `..`
    DotDot => "`..`",
    /// `->`
    Arrow => "`->`",
    /// `@`
    At => "`@`",
    /// `=`
    Eq => "`=`",
    /// `+`
    Plus => "`+`",
    /// `-`
    Minus => "`-`",
    /// `*`
    Star => "`*`",
    /// `/`
    Slash => "`/`",
    /// `%`
    Percent => "`%`",
    /// `!`
    Bang => "`!`",
    /// `~`
    Tilde => "`~`",
    /// `&`
    Amp => "`&`",
    /// `|`
    Pipe => "`|`",
    /// `^`
    Caret => "`^`",
    /// `&&`
    AmpAmp => "`&&`",
    /// `||`
    PipePipe => "`||`",
    /// `<<`
    Shl => "`<<`",
    /// `>>`
    Shr => "`>>`",
    /// `==`
    EqEq => "`==`",
    /// `!=`
    Ne => "`!=`",
    /// `<`
    Lt => "`<`",
    /// `<=`
    Le => "`<=`",
    /// `>`
    Gt => "`>`",
    /// `>=`
    Ge => "`>=`",
    /// `+=`
    PlusEq => "`+=`",
    /// `-=`
    MinusEq => "`-=`",
    /// `*=`
    StarEq => "`*=`",
    /// `/=`
    SlashEq => "`/=`",
    /// `%=`
    PercentEq => "`%=`",
    /// `&=`
    AmpEq => "`&=`",
    /// `|=`
    PipeEq => "`|=`",
    /// `^=`
    CaretEq => "`^=`",
    /// `<<=`
    ShlEq => "`<<=`",
    /// `>>=`
    ShrEq => "`>>=`",
}

impl TokenKind {
    /// The keyword spelled `text`, if it is one (contextual scene keywords are not).
    pub fn keyword(text: &str) -> Option<TokenKind> {
        use TokenKind::*;
        Some(match text {
            "as" => As,
            "break" => Break,
            "const" => Const,
            "continue" => Continue,
            "else" => Else,
            "false" => False,
            "fn" => Fn,
            "for" => For,
            "if" => If,
            "import" => Import,
            "in" => In,
            "let" => Let,
            "loop" => Loop,
            "return" => Return,
            "scene" => Scene,
            "struct" => Struct,
            "true" => True,
            "var" => Var,
            "while" => While,
            _ => return None,
        })
    }

    /// Whether this is a reserved keyword.
    pub fn is_keyword(self) -> bool {
        (TokenKind::As as u8..=TokenKind::While as u8).contains(&(self as u8))
    }

    /// Whether this is a literal (`1`, `1.0`, `"s"`, `true`, `false`).
    pub fn is_literal(self) -> bool {
        matches!(
            self,
            TokenKind::Int | TokenKind::Float | TokenKind::Str | TokenKind::True | TokenKind::False
        )
    }
}

/// A set of token kinds, as a bit set (there are fewer than 128 kinds).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct TokenSet(u128);

impl TokenSet {
    /// The empty set.
    pub const EMPTY: TokenSet = TokenSet(0);

    /// The set of the given kinds.
    pub const fn new(kinds: &[TokenKind]) -> TokenSet {
        let mut bits = 0u128;
        let mut i = 0;
        while i < kinds.len() {
            bits |= 1u128 << kinds[i] as u8;
            i += 1;
        }
        TokenSet(bits)
    }

    /// Both sets together.
    pub const fn union(self, other: TokenSet) -> TokenSet {
        TokenSet(self.0 | other.0)
    }

    /// Whether `kind` is in the set.
    pub const fn contains(self, kind: TokenKind) -> bool {
        self.0 & (1u128 << kind as u8) != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_fit_in_a_set() {
        assert!((TokenKind::ShrEq as u8) < 128);
        let set = TokenSet::new(&[TokenKind::Semi, TokenKind::ShrEq]);
        assert!(set.contains(TokenKind::Semi));
        assert!(set.contains(TokenKind::ShrEq));
        assert!(!set.contains(TokenKind::Comma));
    }

    #[test]
    fn keywords() {
        assert_eq!(TokenKind::keyword("while"), Some(TokenKind::While));
        assert_eq!(TokenKind::keyword("camera"), None);
        assert!(TokenKind::Scene.is_keyword());
        assert!(!TokenKind::Ident.is_keyword());
        assert!(!TokenKind::LParen.is_keyword());
    }
}
