//! Expression tests: the precedence table, postfix forms, generics and struct literals.

use super::{expr, ok_expr};

#[test]
fn precedence_follows_the_table() {
    let cases = [
        ("a + b * c", "(+ a (* b c))"),
        ("a * b + c", "(+ (* a b) c)"),
        ("a - b - c", "(- (- a b) c)"),
        ("a / b % c", "(% (/ a b) c)"),
        ("a << b + c", "(<< a (+ b c))"),
        ("a & b << c", "(& a (<< b c))"),
        ("a ^ b & c", "(^ a (& b c))"),
        ("a | b ^ c", "(| a (^ b c))"),
        ("a == b | c", "(== a (| b c))"),
        ("a && b == c", "(&& a (== b c))"),
        ("a || b && c", "(|| a (&& b c))"),
        ("a || b || c", "(|| (|| a b) c)"),
        ("a < b && c >= d", "(&& (< a b) (>= c d))"),
        ("a >> 2u", "(>> a 2u)"),
        ("-a * b", "(* (- a) b)"),
        ("!a && b", "(&& (! a) b)"),
        ("~a & b", "(& (~ a) b)"),
        ("--a", "(- (- a))"),
        ("-a.b", "(- (. a b))"),
        ("-f(x)[0]", "(- ([] (call f x) 0))"),
        ("(a + b) * c", "(* (paren (+ a b)) c)"),
        ("a * -b", "(* a (- b))"),
        ("a != b", "(!= a b)"),
    ];
    for (src, want) in cases {
        assert_eq!(ok_expr(src), want, "in `{src}`");
    }
}

#[test]
fn comparisons_do_not_chain() {
    let (s, codes) = expr("a < b < c");
    assert_eq!(codes, vec!["E0201"]);
    assert_eq!(s, "ERR");
    assert_eq!(expr("a == b != c").1, vec!["E0201"]);
    assert_eq!(expr("a < b + c > d").1, vec!["E0201"]);
    // Parentheses make it fine (the types are sema's business).
    assert_eq!(ok_expr("(a < b) == c"), "(== (paren (< a b)) c)");
    assert_eq!(ok_expr("a < b && b < c"), "(&& (< a b) (< b c))");
}

#[test]
fn literals() {
    assert_eq!(ok_expr("1"), "1");
    assert_eq!(ok_expr("1u"), "1u");
    assert_eq!(ok_expr("1.5"), "1.5");
    assert_eq!(ok_expr("2f"), "2.0f");
    assert_eq!(ok_expr("1e3"), "1000.0");
    assert_eq!(ok_expr("true"), "true");
    assert_eq!(ok_expr("\"a\\tb\""), "\"a\\tb\"");
    // `-2147483648i` is the negation of a literal that is in range only when negated.
    assert_eq!(ok_expr("-2147483648i"), "(- 2147483648i)");
    assert_eq!(expr("2147483648i").1, vec!["E0105"]);
    assert_eq!(expr("-3000000000i").1, vec!["E0105"]);
}

#[test]
fn calls_fields_indexing() {
    assert_eq!(ok_expr("f()"), "(call f)");
    assert_eq!(ok_expr("f(a, b,)"), "(call f a b)");
    assert_eq!(ok_expr("v.xyz"), "(. v xyz)");
    assert_eq!(ok_expr("a[i][j].x"), "(. ([] ([] a i) j) x)");
    assert_eq!(ok_expr("m.n.o"), "(. (. m n) o)");
    assert_eq!(ok_expr("f(g(x), h[1])"), "(call f (call g x) ([] h 1))");
}

#[test]
fn generic_calls() {
    assert_eq!(ok_expr("vec3<f32>(x)"), "(call vec3<f32> x)");
    assert_eq!(
        ok_expr("array<f32, 3>(a, b, c)"),
        "(call array<f32, =3> a b c)"
    );
    assert_eq!(ok_expr("bitcast<u32>(x)"), "(call bitcast<u32> x)");
    assert_eq!(
        ok_expr("bitcast<f32>(0x7f800000u)"),
        "(call bitcast<f32> 2139095040u)"
    );
    assert_eq!(
        ok_expr("array<vec3<f32>, 2>(a, b)"),
        "(call array<vec3<f32>, =2> a b)"
    );
    assert_eq!(
        ok_expr("array<array<f32, 2>, N * 2>()"),
        "(call array<array<f32, =2>, =(* N 2)>)"
    );
    assert_eq!(
        ok_expr("array<f32, (N > 2)>()"),
        "(call array<f32, =(paren (> N 2))>)"
    );
    assert_eq!(ok_expr("array(a, b)"), "(call array a b)");
    // Any other name followed by `<` is a comparison.
    assert_eq!(ok_expr("a < b"), "(< a b)");
    assert_eq!(expr("foo < f32 > (x)").1, vec!["E0201"]);
}

#[test]
fn struct_literals() {
    assert_eq!(ok_expr("P { a: 1.0, b: x }"), "(struct P (a 1.0) (b x))");
    assert_eq!(ok_expr("P {}"), "(struct P)");
    assert_eq!(
        ok_expr("P { a: Q { b: 1 }, }"),
        "(struct P (a (struct Q (b 1))))"
    );
    assert_eq!(ok_expr("P { a: 1 }.a"), "(. (struct P (a 1)) a)");
}

#[test]
fn spans_cover_children() {
    let src = "const X = -(a + b * f(c, d[1]).x) << P { q: ~1 }.q;";
    let (m, diags) = super::parse(src);
    assert!(diags.is_empty());
    super::check_spans(&m);
    let crate::syntax::ast::ItemKind::Const(c) = &m.items[0].kind else {
        panic!("not a const");
    };
    let span = m.exprs[c.value].span;
    assert_eq!(
        &src[span.range()],
        "-(a + b * f(c, d[1]).x) << P { q: ~1 }.q"
    );
    assert_eq!(&src[m.items[0].span.range()], src);
}
