//! Lexer tests: token streams, literals and lexical errors.

use crate::source::FileId;
use crate::syntax::ast::{FloatSuffix, IntSuffix, Literal};
use crate::syntax::lexer::{decode_number, tokenize, unescape};
use crate::syntax::token::TokenKind::{self, *};

/// Kinds and texts of the tokens of `src` (without the final `Eof`).
fn toks(src: &str) -> Vec<(TokenKind, &str)> {
    let (tokens, _) = tokenize(FileId(0), src);
    tokens
        .iter()
        .filter(|t| t.kind != Eof)
        .map(|t| (t.kind, &src[t.span.range()]))
        .collect()
}

fn kinds(src: &str) -> Vec<TokenKind> {
    toks(src).into_iter().map(|(k, _)| k).collect()
}

/// Error codes of lexing `src`.
fn lex_codes(src: &str) -> Vec<&'static str> {
    let (_, diags) = crate::syntax::lex(FileId(0), src);
    diags.iter().map(|d| d.code.0).collect()
}

fn int(value: u64, suffix: Option<IntSuffix>) -> Literal {
    Literal::Int { value, suffix }
}

fn float(value: f64, suffix: Option<FloatSuffix>) -> Literal {
    Literal::Float { value, suffix }
}

#[test]
fn punctuation_longest_match() {
    assert_eq!(
        kinds("( ) { } [ ] < > , ; : . .. -> @ ="),
        vec![
            LParen, RParen, LBrace, RBrace, LBracket, RBracket, Lt, Gt, Comma, Semi, Colon, Dot,
            DotDot, Arrow, At, Eq
        ]
    );
    assert_eq!(
        kinds("+ - * / % ! ~ & | ^ && || << >> == != <= >="),
        vec![
            Plus, Minus, Star, Slash, Percent, Bang, Tilde, Amp, Pipe, Caret, AmpAmp, PipePipe,
            Shl, Shr, EqEq, Ne, Le, Ge
        ]
    );
    assert_eq!(
        kinds("+= -= *= /= %= &= |= ^= <<= >>="),
        vec![PlusEq, MinusEq, StarEq, SlashEq, PercentEq, AmpEq, PipeEq, CaretEq, ShlEq, ShrEq]
    );
    assert_eq!(kinds("a->b"), vec![Ident, Arrow, Ident]);
    assert_eq!(kinds("x<<=1"), vec![Ident, ShlEq, Int]);
    assert_eq!(kinds("a<=-b"), vec![Ident, Le, Minus, Ident]);
}

#[test]
fn keywords_and_contextual_keywords() {
    assert_eq!(
        kinds("as break const continue else false fn for if import in let loop return scene struct true var while"),
        vec![
            As, Break, Const, Continue, Else, False, Fn, For, If, Import, In, Let, Loop, Return,
            Scene, Struct, True, Var, While
        ]
    );
    assert_eq!(
        kinds("settings camera background object light model"),
        vec![Ident; 6]
    );
    assert_eq!(
        toks("_x1 fnord f32"),
        vec![(Ident, "_x1"), (Ident, "fnord"), (Ident, "f32")]
    );
}

#[test]
fn numbers_and_ranges() {
    assert_eq!(toks("0..10"), vec![(Int, "0"), (DotDot, ".."), (Int, "10")]);
    assert_eq!(
        toks("1.0..2.5"),
        vec![(Float, "1.0"), (DotDot, ".."), (Float, "2.5")]
    );
    assert_eq!(toks("v.x"), vec![(Ident, "v"), (Dot, "."), (Ident, "x")]);
    assert_eq!(toks("a.0"), vec![(Ident, "a"), (Dot, "."), (Int, "0")]);
    assert_eq!(toks("1.x"), vec![(Int, "1"), (Dot, "."), (Ident, "x")]);
    assert_eq!(
        toks("1e-3 2f 1.5e3f 1E+2"),
        vec![
            (Float, "1e-3"),
            (Float, "2f"),
            (Float, "1.5e3f"),
            (Float, "1E+2")
        ]
    );
    assert_eq!(
        toks("0xffu 0b101i 1_000"),
        vec![(Int, "0xffu"), (Int, "0b101i"), (Int, "1_000")]
    );
    assert_eq!(toks("x-1"), vec![(Ident, "x"), (Minus, "-"), (Int, "1")]);
    assert_eq!(toks("1e"), vec![(Int, "1e")]);
}

#[test]
fn number_values() {
    assert_eq!(decode_number("42"), (int(42, None), None));
    assert_eq!(decode_number("1_000_000").0, int(1_000_000, None));
    assert_eq!(decode_number("0xFFu").0, int(255, Some(IntSuffix::U)));
    assert_eq!(
        decode_number("0x7f800000u").0,
        int(0x7f80_0000, Some(IntSuffix::U))
    );
    assert_eq!(decode_number("0b1010i").0, int(10, Some(IntSuffix::I)));
    assert_eq!(decode_number("0x1f").0, int(31, None));
    assert_eq!(decode_number("3i").0, int(3, Some(IntSuffix::I)));
    assert_eq!(decode_number("2f").0, float(2.0, Some(FloatSuffix::F)));
    assert_eq!(
        decode_number("1.5e3f").0,
        float(1500.0, Some(FloatSuffix::F))
    );
    assert_eq!(decode_number("1e-3").0, float(0.001, None));
    assert_eq!(decode_number("1.1920929e-7").0, float(1.1920929e-7, None));
    assert_eq!(
        decode_number("18446744073709551615"),
        (int(u64::MAX, None), None)
    );
    assert_eq!(
        decode_number("2147483648i"),
        (int(1 << 31, Some(IntSuffix::I)), None)
    );
    assert_eq!(decode_number("4294967295u").1, None);
}

#[test]
fn literal_errors() {
    assert_eq!(lex_codes("0x"), vec!["E0104"]);
    assert_eq!(lex_codes("0b"), vec!["E0104"]);
    assert_eq!(lex_codes("0b102"), vec!["E0104"]);
    assert_eq!(lex_codes("1e"), vec!["E0104"]);
    assert_eq!(lex_codes("1.0e"), vec!["E0104"]);
    assert_eq!(lex_codes("1.0.0"), vec!["E0104"]);
    assert_eq!(lex_codes("x = 1.;"), vec!["E0104"]);
    assert_eq!(lex_codes("18446744073709551616"), vec!["E0105"]);
    assert_eq!(lex_codes("3000000000i"), vec!["E0105"]);
    assert_eq!(lex_codes("4294967296u"), vec!["E0105"]);
    assert_eq!(lex_codes("1e999"), vec!["E0105"]);
    assert_eq!(lex_codes("1q"), vec!["E0106"]);
    assert_eq!(lex_codes("2.0u"), vec!["E0106"]);
    assert_eq!(lex_codes("0xffz"), vec!["E0106"]);
    assert_eq!(lex_codes("1u32"), vec!["E0106"]);
    // The suffix is reported at the suffix.
    let (_, d) = crate::syntax::lex(FileId(0), "12q");
    assert_eq!((d[0].primary.span.lo, d[0].primary.span.hi), (2, 3));
}

#[test]
fn strings() {
    assert_eq!(toks(r#""a b" x"#), vec![(Str, r#""a b""#), (Ident, "x")]);
    assert_eq!(unescape(r#""a\"b\\c\nd\te""#), "a\"b\\c\nd\te");
    assert_eq!(lex_codes(r#""bad \q escape""#), vec!["E0107"]);
    assert_eq!(lex_codes("\"never closed\nlet x = 1;"), vec!["E0103"]);
    // An unterminated string ends at the end of its line: the next line lexes normally.
    assert_eq!(kinds("\"open\nlet"), vec![Str, Let]);
    assert_eq!(
        lex_codes(r#""é ünïcode is fine in strings""#),
        Vec::<&str>::new()
    );
}

#[test]
fn comments() {
    assert_eq!(kinds("a // b c\nd"), vec![Ident, Ident]);
    assert_eq!(kinds("a /* b /* nested */ c */ d"), vec![Ident, Ident]);
    assert_eq!(lex_codes("a /* b /* c */"), vec!["E0102"]);
    assert_eq!(
        toks("/// doc\nfn"),
        vec![(DocComment, "/// doc"), (Fn, "fn")]
    );
    assert_eq!(kinds("//// not doc\n//! not doc either\nfn"), vec![Fn]);
    assert_eq!(kinds("/* é */ x // ü"), vec![Ident]);
}

#[test]
fn unknown_characters() {
    let (tokens, diags) = crate::syntax::lex(FileId(0), "let é = 1;");
    assert_eq!(diags.len(), 1);
    assert_eq!(diags[0].code.0, "E0101");
    assert_eq!(diags[0].message, "unknown character `é`");
    assert!(tokens.iter().any(|t| t.kind == Unknown));
    // A run of unknown characters is one error.
    assert_eq!(lex_codes("a #$? b"), vec!["E0101"]);
    assert_eq!(lex_codes("a # $ b"), vec!["E0101", "E0101"]);
    // Identifiers are ASCII.
    assert_eq!(lex_codes("café"), vec!["E0101"]);
    assert_eq!(lex_codes("\u{feff}fn"), Vec::<&str>::new());
}

#[test]
fn spans_are_exact() {
    let src = "let  xy = 0x1f;";
    let (tokens, _) = tokenize(FileId(0), src);
    let spans: Vec<(u32, u32)> = tokens.iter().map(|t| (t.span.lo, t.span.hi)).collect();
    assert_eq!(
        spans,
        vec![(0, 3), (5, 7), (8, 9), (10, 14), (14, 15), (15, 15)]
    );
}
