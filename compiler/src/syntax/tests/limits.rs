//! Robustness: nesting limits, huge inputs, and property tests that nothing panics.

use super::{check_spans, codes, parse};
use crate::syntax::ast::*;
use crate::syntax::MAX_EXPR_DEPTH;
use proptest::prelude::*;

/// Runs `f` on a thread with a small stack (1 MiB), so that a recursion bug shows up as a crash
/// here rather than only on a user's deeply nested file.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(f)
        .expect("spawn a test thread")
        .join()
        .expect("the parser must not overflow its stack")
}

/// The deepest expression tree in the module, computed without recursion.
fn max_expr_depth(m: &Module) -> usize {
    let mut depth = vec![0usize; m.exprs.len()];
    // Children are allocated before their parents, so one pass in arena order suffices.
    for (id, e) in m.exprs.iter() {
        let kids: Vec<ExprId> = match &e.kind {
            ExprKind::Unary { operand, .. } => vec![*operand],
            ExprKind::Binary { lhs, rhs, .. } => vec![*lhs, *rhs],
            ExprKind::Call { args, .. } => args.clone(),
            ExprKind::Field { base, .. } => vec![*base],
            ExprKind::Index { base, index } => vec![*base, *index],
            ExprKind::StructLit { fields, .. } => fields.iter().map(|f| f.value).collect(),
            ExprKind::Paren(inner) => vec![*inner],
            _ => vec![],
        };
        let i = u32::from(id.into_raw()) as usize;
        depth[i] = 1 + kids
            .iter()
            .map(|k| depth[u32::from(k.into_raw()) as usize])
            .max()
            .unwrap_or(0);
    }
    depth.into_iter().max().unwrap_or(0)
}

fn deep(open: &str, middle: &str, close: &str, n: usize) -> String {
    format!(
        "fn f() {{\n    let x = {}{middle}{};\n}}\nfn g() {{}}\n",
        open.repeat(n),
        close.repeat(n)
    )
}

#[test]
fn deep_nesting_is_one_error() {
    let n = 100_000;
    let cases = [
        deep("(", "x", ")", n),
        deep("(", "x", "", n),
        deep("-", "x", "", n),
        deep("!~-", "x", "", n),
        deep("f(", "x", ")", n),
        deep("a[", "x", "]", n),
        deep("P { a: ", "x", " }", n),
        deep("x + ", "x", "", n),
        deep("", "x", " * x", n),
        deep("vec3<", "f32", ">", n),
        format!("fn f() {{\n{}\n}}\nfn g() {{}}\n", "{".repeat(n)),
        format!(
            "fn f() {{\n{}{}\n}}\nfn g() {{}}\n",
            "{".repeat(n),
            "}".repeat(n)
        ),
        format!(
            "fn f() {{\n    if a {{}}{}\n}}\nfn g() {{}}\n",
            " else if a {}".repeat(n)
        ),
        format!(
            "fn f() -> {}f32{} {{}}\nfn g() {{}}\n",
            "array<".repeat(n),
            ", 2>".repeat(n)
        ),
        format!(
            "fn f() {{}}\nstruct S {{\n{}\n}}\nfn g() {{}}\n",
            " struct T {".repeat(n)
        ),
    ];
    for src in cases {
        let head: String = src.chars().skip(13).take(24).collect();
        let (m, codes) = on_small_stack(move || {
            let (m, d) = parse(&src);
            (m, d.iter().map(|d| d.code.0).collect::<Vec<_>>())
        });
        // Nested items are each reported as misplaced before the limit is reached.
        let codes: Vec<&str> = codes.into_iter().filter(|&c| c != "E0206").collect();
        assert_eq!(codes, vec!["E0202"], "for `{head}…`");
        assert!(max_expr_depth(&m) <= MAX_EXPR_DEPTH as usize);
        let names: Vec<&str> = m
            .items
            .iter()
            .filter_map(|i| match &i.kind {
                ItemKind::Fn(f) => Some(f.name.name.as_str()),
                _ => None,
            })
            .collect();
        assert_eq!(names, ["f", "g"], "for `{head}…`");
    }
}

#[test]
fn unbalanced_brackets_do_not_recurse() {
    let src = format!("fn f() {{ let x = {}; }}", "[".repeat(100_000));
    let c = on_small_stack(move || codes(&src));
    assert_eq!(c, vec!["E0201"]);
    let src = "}".repeat(100_000) + ")".repeat(100_000).as_str();
    assert_eq!(on_small_stack(move || codes(&src)), vec!["E0201"]);
}

#[test]
fn moderate_nesting_is_fine() {
    let src = deep("(", "x", ")", 100);
    assert!(codes(&src).is_empty());
    let src = deep("x + ", "x", "", 200);
    assert!(codes(&src).is_empty());
}

/// A file of about `bytes` bytes of realistic code.
fn big_file(bytes: usize) -> String {
    let unit = r#"
/// A material.
@material
struct Mat_N {
    albedo: vec3f = vec3f(0.8, 0.5, 0.25),
    rough: f32 = 0.5,
}

@closest_hit
fn shade_N(m: Mat_N, ray: Ray, hit: Hit) -> vec3f {
    var color = vec3f(0.0);
    for i in 0u..light_count() {
        let l = sample_light(i, hit.position, hit.geometric_normal);
        color += m.albedo / PI * l.radiance * max(dot(hit.normal, l.dir), 0.0);
    }
    if color.x > 1.0 && !hit.front_face {
        color = color * 0.5 + vec3f(m.rough) - array<f32, 2>(1.0, 2.0)[1u];
    } else if hit.t < 0.001 {
        return vec3f(0.0);
    }
    return color;
}
"#;
    let mut s = String::with_capacity(bytes + unit.len() + 64);
    let mut i = 0;
    while s.len() < bytes {
        s.push_str(&unit.replace("_N", &format!("_{i}")));
        i += 1;
    }
    s.push_str("scene big {\n    camera C {}\n    object o { geometry: cube_mesh(), material: Mat_0 {} }\n}\n");
    s
}

#[test]
fn ten_megabytes_parse_quickly() {
    let src = big_file(10 << 20);
    let start = std::time::Instant::now();
    let (m, diags) = parse(&src);
    let secs = start.elapsed().as_secs_f64();
    assert!(diags.is_empty());
    assert!(m.items.len() > 10_000);
    let mb = src.len() as f64 / (1 << 20) as f64;
    eprintln!(
        "parsed {mb:.1} MiB ({} items, {} expressions) in {secs:.2} s: {:.1} MiB/s",
        m.items.len(),
        m.exprs.len(),
        mb / secs
    );
    // Generous: a debug build on a loaded machine. Linear time is what matters.
    assert!(secs < 20.0, "parsing 10 MiB took {secs:.1} s");
}

#[test]
fn ten_megabytes_of_garbage() {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let bytes: Vec<u8> = (0..(10 << 20))
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 32) as u8
        })
        .collect();
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let start = std::time::Instant::now();
    let (_, diags) = parse(&text);
    assert!(!diags.is_empty());
    assert!(start.elapsed().as_secs_f64() < 20.0);
}

/// Token texts for soups: every kind of token, plus some that start recovery.
const SOUP: &[&str] = &[
    "fn",
    "struct",
    "const",
    "scene",
    "import",
    "let",
    "var",
    "if",
    "else",
    "for",
    "in",
    "while",
    "loop",
    "break",
    "continue",
    "return",
    "as",
    "true",
    "false",
    "x",
    "vec3",
    "array",
    "bitcast",
    "P",
    "light",
    "camera",
    "object",
    "model",
    "settings",
    "background",
    "1",
    "2u",
    "1.5",
    "0x1f",
    "\"s\"",
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    "<",
    ">",
    ">>",
    ">=",
    ">>=",
    ",",
    ";",
    ":",
    ".",
    "..",
    "->",
    "@",
    "=",
    "==",
    "+",
    "-",
    "*",
    "/",
    "%",
    "!",
    "~",
    "&",
    "|",
    "^",
    "&&",
    "||",
    "+=",
    "<<=",
    "\n",
    "///d\n",
    "é",
    "/*",
    "*/",
    "\"",
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_text_never_panics(s in "\\PC{0,200}") {
        let (m, diags) = parse(&s);
        check_spans(&m);
        for d in &diags {
            prop_assert!(d.primary.span.hi as usize <= s.len());
            prop_assert!(s.is_char_boundary(d.primary.span.lo as usize));
        }
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        let text = String::from_utf8_lossy(&bytes);
        let (m, _) = parse(&text);
        check_spans(&m);
    }

    #[test]
    fn token_soups_never_panic(
        toks in prop::collection::vec(prop::sample::select(SOUP), 0..120),
        glue in prop::sample::select(&[" ", "", "\n"][..]),
    ) {
        let text = toks.join(glue);
        let (m, diags) = parse(&text);
        check_spans(&m);
        prop_assert!(max_expr_depth(&m) <= MAX_EXPR_DEPTH as usize);
        for d in &diags {
            prop_assert!(d.primary.span.lo <= d.primary.span.hi);
            prop_assert!(d.primary.span.hi as usize <= text.len());
        }
    }

    #[test]
    fn prefixes_of_valid_code_never_panic(cut in 0usize..900) {
        let src = big_file(1);
        let end = (0..=cut.min(src.len())).rev().find(|&i| src.is_char_boundary(i)).unwrap_or(0);
        let (m, _) = parse(&src[..end]);
        check_spans(&m);
    }
}
