//! Error recovery: every error reported once, no cascades, the rest of the file still parsed.

use super::{codes, errors, parse, stmts};
use crate::syntax::ast::*;
use crate::syntax::error::SyntaxError;

fn fn_names(m: &Module) -> Vec<&str> {
    m.items
        .iter()
        .filter_map(|i| match &i.kind {
            ItemKind::Fn(f) => Some(f.name.name.as_str()),
            _ => None,
        })
        .collect()
}

#[test]
fn missing_semicolon_at_end_of_line() {
    let src = "fn f() {\n    let x = 1\n    let y = 2;\n}";
    let (m, diags) = parse(src);
    assert_eq!(diags.len(), 1);
    let d = &diags[0];
    assert_eq!(d.code.0, "E0201");
    assert_eq!(d.message, "expected `;`, found keyword `let`");
    assert_eq!(d.help.as_deref(), Some("add `;` here"));
    // An empty span just after `1`, as rustc does.
    assert_eq!(d.primary.span.lo, d.primary.span.hi);
    assert_eq!(
        &src[..d.primary.span.lo as usize],
        "fn f() {\n    let x = 1"
    );
    let ItemKind::Fn(f) = &m.items[0].kind else {
        panic!("not a fn")
    };
    assert_eq!(f.body.stmts.len(), 2);
    let (s, _) = stmts("return 1\n");
    assert_eq!(s, "(return 1)");
}

#[test]
fn junk_before_semicolon_is_skipped() {
    let (s, c) = stmts("let x = 1 2 3;\nlet y = 4;");
    assert_eq!(c, vec!["E0201"]);
    assert_eq!(s, "(let x 1); (let y 4)");
}

#[test]
fn every_error_in_the_file_is_reported() {
    let src = "
fn a() {
    let x = ;
}
fn b(y) {
    return y;
}
fn c() {
    if x = 1 {
    }
}
fn d() {
    f() = 2;
}
";
    let (m, diags) = parse(src);
    let codes: Vec<&str> = diags.iter().map(|d| d.code.0).collect();
    assert_eq!(codes, ["E0201", "E0201", "E0201", "E0205"]);
    assert_eq!(
        diags[1].help.as_deref(),
        Some("parameters need a type: `y: f32`")
    );
    assert_eq!(diags[2].help.as_deref(), Some("use `==` to compare"));
    assert_eq!(fn_names(&m), ["a", "b", "c", "d"]);
}

#[test]
fn an_unclosed_block_ends_at_the_next_item() {
    let src = "fn a() {\n    let x = 1;\n\nfn b() {\n    return;\n}\n";
    let (m, diags) = parse(src);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].message, "expected `}`, found keyword `fn`");
    assert_eq!(diags[0].secondary[0].message, "unclosed delimiter");
    assert_eq!(fn_names(&m), ["a", "b"]);
}

#[test]
fn unclosed_at_end_of_file_is_one_error() {
    assert_eq!(codes("fn f() { let x = (1 + "), vec!["E0201"]);
    assert_eq!(codes("fn f() { g(1, "), vec!["E0201"]);
    assert_eq!(codes("struct S { a: f32"), vec!["E0201"]);
    assert_eq!(codes("scene s { camera C {"), vec!["E0201"]);
    assert_eq!(codes("const X = vec3<f32"), vec!["E0201"]);
}

#[test]
fn top_level_junk_is_one_error() {
    let (m, diags) = parse("fn a() {}\n) ) + 1 2 3 ]\nfn b() {}");
    assert_eq!(diags.len(), 1);
    assert_eq!(diags[0].message, "expected an item, found `)`");
    assert_eq!(fn_names(&m), ["a", "b"]);
    assert_eq!(codes("struct S { a: f32 };"), vec!["E0201"]);
}

#[test]
fn list_recovery() {
    assert_eq!(stmts("f(a b, c);").1, vec!["E0201"]);
    assert_eq!(stmts("f(a b, c);").0, "(call f a c)");
    // A missing `,` at the end of a line is assumed.
    let src = "struct S {\n    a: f32\n    b: f32,\n}";
    let (m, diags) = parse(src);
    assert_eq!(diags.len(), 1);
    assert_eq!(diags[0].help.as_deref(), Some("add `,` here"));
    let ItemKind::Struct(s) = &m.items[0].kind else {
        panic!("not a struct")
    };
    assert_eq!(s.fields.len(), 2);
    // `Foo { a }` is read as `Foo { a: a }` after the error.
    let (s, c) = stmts("let p = P { a, b: 1 };");
    assert_eq!(c, vec!["E0201"]);
    assert_eq!(s, "(let p (struct P (a a) (b 1)))");
}

#[test]
fn struct_literal_in_condition() {
    let (s, c) = stmts("if x == Foo { a: 1.0 } {\n    f();\n}");
    assert_eq!(c, vec!["E0204"]);
    assert_eq!(s, "(if (== x (struct Foo (a 1.0))) {(call f)})");
    assert_eq!(stmts("while Foo { a: 1.0 }.ok {}").1, vec!["E0204"]);
    assert_eq!(stmts("for i in 0..N { a: 1 }.n {}").1, vec!["E0204"]);
    let e = errors("fn f() { if x == Foo { a: 1.0 } {} }");
    assert!(matches!(&e[0], SyntaxError::StructLitInCondition { name, .. } if name == "Foo"));
}

#[test]
fn invalid_assignment_targets() {
    assert_eq!(stmts("f() = 1;").1, vec!["E0205"]);
    assert_eq!(stmts("1 = x;").1, vec!["E0205"]);
    assert_eq!(stmts("a + b += 1;").1, vec!["E0205"]);
    assert_eq!(stmts("f() = 1;").0, "(= ERR 1)");
    // Places are fine, including swizzles (sema rejects multi-component ones).
    assert_eq!(
        stmts("v.xy = w; a[0].x = 1.0; (x) = 2;").1,
        Vec::<&str>::new()
    );
}

#[test]
fn misplaced_items() {
    assert_eq!(codes("let x = 1;\nfn f() {}"), vec!["E0206"]);
    assert_eq!(codes("var x = 1;"), vec!["E0206"]);
    let m = parse("fn f() {\n    fn g() {}\n    let x = 1;\n}\nfn h() {}").0;
    assert_eq!(fn_names(&m), ["f", "h"]);
    assert_eq!(
        codes("fn f() {\n    fn g() {}\n    let x = 1;\n}\nfn h() {}"),
        vec!["E0206"]
    );
    assert_eq!(codes("fn f() {\n    import \"x\";\n}"), vec!["E0206"]);
    assert_eq!(
        codes("struct S {\n    a: f32,\n    fn g() {}\n}"),
        vec!["E0206"]
    );
    assert_eq!(codes("scene s {\n    struct T {}\n}"), vec!["E0206"]);
}

#[test]
fn import_after_item_is_reported_and_kept() {
    let (m, diags) = parse("fn f() {}\nimport \"late.rt\";\n");
    assert_eq!(diags.len(), 1);
    assert_eq!(diags[0].code.0, "E0308");
    assert_eq!(m.imports.len(), 1);
    assert_eq!(m.imports[0].path, "late.rt");
}

#[test]
fn unknown_attributes() {
    let (m, diags) = parse("@closest_hti\nfn f() {}\n@frobnicate\nfn g() {}");
    assert_eq!(diags.len(), 2);
    assert_eq!(diags[0].code.0, "E0203");
    assert_eq!(diags[0].message, "unknown attribute `@closest_hti`");
    assert_eq!(
        diags[0].help.as_deref(),
        Some("did you mean `@closest_hit`?")
    );
    assert!(diags[1].help.is_none());
    assert_eq!(diags[1].notes.len(), 1);
    // The attribute is kept: whether it is useful is sema's business.
    assert_eq!(m.items[0].attrs[0].name.name, "closest_hti");
}

#[test]
fn scene_recovery() {
    let src =
        "scene s {\n    lights key P {}\n    camera C {}\n    foo;\n    object o { a: 1 };\n}";
    let (m, diags) = parse(src);
    let codes: Vec<&str> = diags.iter().map(|d| d.code.0).collect();
    assert_eq!(codes, ["E0701", "E0701", "E0201"]);
    assert_eq!(diags[0].help.as_deref(), Some("did you mean `light`?"));
    let ItemKind::Scene(s) = &m.items[0].kind else {
        panic!("not a scene")
    };
    assert_eq!(s.entries.len(), 2);
}

#[test]
fn var_needs_type_or_value() {
    let (s, c) = stmts("var x;\nx = 1;");
    assert_eq!(c, vec!["E0201"]);
    assert_eq!(s, "(var x :ERRTY); (= x 1)");
    let (s, c) = stmts("let x;");
    assert_eq!(c, vec!["E0201"]);
    assert_eq!(s, "(let x ERR)");
}

#[test]
fn unknown_characters_do_not_cascade() {
    assert_eq!(codes("fn f() { let x = é; }"), vec!["E0101"]);
    assert_eq!(codes("fn f() { let é = 1; }"), vec!["E0101"]);
    assert_eq!(codes("fn f() { let x = 1 # 2; }"), vec!["E0101"]);
}

#[test]
fn unterminated_strings_and_comments_do_not_cascade() {
    assert_eq!(codes("fn g() {\n    let s = \"open;\n}"), vec!["E0103"]);
    assert_eq!(codes("fn g() {\n    /* open"), vec!["E0102"]);
    // The path of an unterminated import is still usable.
    let (m, diags) = parse("import \"std/a.rt\nfn f() {}");
    assert_eq!(diags.len(), 1);
    assert_eq!(m.imports[0].path, "std/a.rt");
    // An import without a path is not recorded.
    let (m, diags) = parse("import std/a;\nfn f() {}");
    assert_eq!(diags.len(), 1);
    assert!(m.imports.is_empty());
}

#[test]
fn helpful_errors() {
    let (s, c) = stmts("let x = .5;");
    assert_eq!((s.as_str(), c), ("(let x 0.5)", vec!["E0104"]));
    let e = parse("const X = 1.;").1;
    assert_eq!(e[0].help.as_deref(), Some("write `1.0`"));
    assert_eq!(
        stmts("let x = y as f32;"),
        ("(let x ERR)".to_string(), vec!["E0201"])
    );
    assert_eq!(stmts("let l = v.length();").1, vec!["E0414"]);
    assert_eq!(stmts("let l = v.0;").1, vec!["E0201"]);
    assert_eq!(stmts("let a = [1, 2];").1, vec!["E0201"]);
    assert_eq!(
        stmts("let mut x = 1;"),
        ("(let x 1)".to_string(), vec!["E0201"])
    );
    assert_eq!(stmts("for i in range(10) {}").1, vec!["E0201"]);
    assert_eq!(stmts("if x return;").1, vec!["E0201"]);
    assert_eq!(
        stmts("let x = * 3;"),
        ("(let x 3)".to_string(), vec!["E0201"])
    );
    assert_eq!(stmts(";").1, vec!["E0201"]);
}
