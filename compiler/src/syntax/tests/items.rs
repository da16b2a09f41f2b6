//! Items, statements, scenes, attributes and doc comments on valid input.

use super::{ok_stmts, parse, stmts, Printer};
use crate::syntax::ast::*;

#[test]
fn statements() {
    assert_eq!(ok_stmts("let x = 1;"), "(let x 1)");
    assert_eq!(ok_stmts("let x: f32 = 1.0;"), "(let x :f32 1.0)");
    assert_eq!(ok_stmts("var v: vec3<f32>;"), "(var v :vec3<f32>)");
    assert_eq!(ok_stmts("var n = 0u;"), "(var n 0u)");
    assert_eq!(ok_stmts("x = 2;"), "(= x 2)");
    assert_eq!(ok_stmts("v.x += 1.0;"), "(+= (. v x) 1.0)");
    assert_eq!(ok_stmts("a[i] <<= 2u;"), "(<<= ([] a i) 2u)");
    assert_eq!(ok_stmts("v.xy = w;"), "(= (. v xy) w)");
    assert_eq!(ok_stmts("(x) = 1;"), "(= (paren x) 1)");
    assert_eq!(ok_stmts("f(x);"), "(call f x)");
    assert_eq!(ok_stmts("return;"), "(return)");
    assert_eq!(ok_stmts("return a + 1;"), "(return (+ a 1))");
    assert_eq!(
        ok_stmts("loop { break; continue; }"),
        "(loop {break; continue})"
    );
    assert_eq!(
        ok_stmts("while i < n { i += 1u; }"),
        "(while (< i n) {(+= i 1u)})"
    );
    assert_eq!(
        ok_stmts("for i in 0u..n { f(i); }"),
        "(for i 0u n {(call f i)})"
    );
    assert_eq!(ok_stmts("for i in 0..10 {}"), "(for i 0 10 {})");
    assert_eq!(ok_stmts("{ let a = 1; }"), "{(let a 1)}");
    let want = "(var a :array<f32, =3> (call array<f32, =3> 1.0 2.0 3.0))";
    assert_eq!(
        ok_stmts("var a: array<f32, 3> = array<f32, 3>(1.0, 2.0, 3.0);"),
        want
    );
    assert_eq!(
        ok_stmts("let m: array<vec3<f32>, 2>= x;"),
        "(let m :array<vec3<f32>, =2> x)"
    );
}

#[test]
fn if_else_chains() {
    assert_eq!(ok_stmts("if a { f(); }"), "(if a {(call f)})");
    assert_eq!(ok_stmts("if a {} else {}"), "(if a {} else {})");
    assert_eq!(
        ok_stmts("if a { x = 1; } else if b { x = 2; } else { x = 3; }"),
        "(if a {(= x 1)} else {(if b {(= x 2)} else {(= x 3)})})"
    );
    // The condition's `{` is the block's, not a struct literal's.
    assert_eq!(ok_stmts("if x == P {}"), "(if (== x P) {})");
    assert_eq!(ok_stmts("while go {}"), "(while go {})");
    assert_eq!(
        ok_stmts("if p == (P { a: 1.0 }) {}"),
        "(if (== p (paren (struct P (a 1.0)))) {})"
    );
    assert_eq!(
        ok_stmts("if f(P { a: 1.0 }) {}"),
        "(if (call f (struct P (a 1.0))) {})"
    );
    // `else if` is an else block holding one `if`, with the same span.
    let (m, _) = parse("fn f() { if a {} else if b {} }");
    let ItemKind::Fn(f) = &m.items[0].kind else {
        panic!("not a fn")
    };
    let StmtKind::If {
        else_block: Some(b),
        ..
    } = &f.body.stmts[0].kind
    else {
        panic!("not an if/else")
    };
    assert_eq!(b.stmts.len(), 1);
    assert_eq!(b.span, b.stmts[0].span);
}

#[test]
fn functions_and_structs() {
    let src = "
/// Shades.
/// Two lines.
@closest_hit
fn shade(m: Matte, ray: Ray, hit: Hit,) -> vec3f {
    return m.albedo;
}

@material
/// After the attribute.
struct Matte {
    /// The colour.
    albedo: vec3f = vec3f(0.8),
    rough: f32,
}

const N: u32 = 4u;
const M = 2;
";
    let (m, diags) = parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(m.items.len(), 4);
    let shade = &m.items[0];
    assert_eq!(shade.doc.as_deref(), Some("Shades.\nTwo lines."));
    assert_eq!(shade.attrs[0].name.name, "closest_hit");
    assert_eq!(
        &src[shade.span.range()].lines().next(),
        &Some("@closest_hit")
    );
    let ItemKind::Fn(f) = &shade.kind else {
        panic!("not a fn")
    };
    assert_eq!(f.name.name, "shade");
    let params: Vec<&str> = f.params.iter().map(|p| p.name.name.as_str()).collect();
    assert_eq!(params, ["m", "ray", "hit"]);
    assert_eq!(Printer { m: &m }.ty(f.ret.unwrap()), "vec3f");
    let matte = &m.items[1];
    assert_eq!(matte.doc.as_deref(), Some("After the attribute."));
    let ItemKind::Struct(s) = &matte.kind else {
        panic!("not a struct")
    };
    assert_eq!(s.fields[0].doc.as_deref(), Some("The colour."));
    assert_eq!(s.fields[1].doc, None);
    assert!(s.fields[0].default.is_some());
    assert!(matches!(&m.items[3].kind, ItemKind::Const(c) if c.ty.is_none()));
}

#[test]
fn attributes_with_arguments() {
    let (m, diags) = parse("@ray_generation(samples = 4, 2)\nfn g() {}");
    assert!(diags.is_empty());
    let a = &m.items[0].attrs[0];
    assert_eq!(a.args.len(), 2);
    assert_eq!(
        a.args[0].name.as_ref().map(|n| n.name.as_str()),
        Some("samples")
    );
    assert!(a.args[1].name.is_none());
}

#[test]
fn imports() {
    let (m, diags) = parse("import \"std/a.rt\";\nimport \"b\";\nfn f() {}");
    assert!(diags.is_empty());
    let paths: Vec<&str> = m.imports.iter().map(|i| i.path.as_str()).collect();
    assert_eq!(paths, ["std/a.rt", "b"]);
}

#[test]
fn scenes() {
    let src = r#"
scene two {
    settings { width: 320, height: 240, }
    camera Pinhole { position: vec3f(0.0, 1.5, 5.0), fov: 40.0 }
    background SkyGradient {}
    let grey = Lambert { albedo: vec3f(0.5) };
    object floor { geometry: quad_mesh(), material: grey, transform: scale(10.0) }
    object { geometry: cube_mesh(), material: grey }
    light key PointLight { position: vec3f(2.0, 4.0, 3.0) }
    light PointLight {}
    model "a.glb" { transform: identity() }
    model "b.gltf"
    animate floor keys smooth { 0.0: identity(), 1.5: scale(2.0), }
    animate camera.fov spin(a, 2.0)
}
"#;
    let (m, diags) = parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    let ItemKind::Scene(s) = &m.items[0].kind else {
        panic!("not a scene")
    };
    let p = Printer { m: &m };
    let got: Vec<String> = s
        .entries
        .iter()
        .map(|e| match &e.kind {
            SceneEntryKind::Settings(f) => format!("settings {}", f.len()),
            SceneEntryKind::Camera(e) => format!("camera {}", p.expr(*e)),
            SceneEntryKind::Background(e) => format!("background {}", p.expr(*e)),
            SceneEntryKind::Let { name, .. } => format!("let {}", name.name),
            SceneEntryKind::Object { name, fields } => {
                format!(
                    "object {:?} {}",
                    name.as_ref().map(|n| &n.name),
                    fields.len()
                )
            }
            SceneEntryKind::Light { name, value } => {
                format!(
                    "light {:?} {}",
                    name.as_ref().map(|n| &n.name),
                    p.expr(*value)
                )
            }
            SceneEntryKind::Model { path, fields, .. } => format!("model {path} {}", fields.len()),
            SceneEntryKind::Animate { target, motion } => {
                let t: Vec<&str> = target.iter().map(|i| i.name.as_str()).collect();
                let m = match motion {
                    AnimMotion::Keys {
                        word, interp, keys, ..
                    } => {
                        let keys: Vec<String> = keys
                            .iter()
                            .map(|k| format!("{}: {}", p.expr(k.time), p.expr(k.value)))
                            .collect();
                        let interp = interp.as_ref().map(|i| i.name.as_str());
                        format!("{} {interp:?} {}", word.name, keys.join(", "))
                    }
                    AnimMotion::Over { name, args, .. } => {
                        let args: Vec<String> = args.iter().map(|a| p.expr(*a)).collect();
                        format!("{}({})", name.name, args.join(", "))
                    }
                };
                format!("animate {} {m}", t.join("."))
            }
            SceneEntryKind::Error => "ERR".to_string(),
        })
        .collect();
    assert_eq!(
        got,
        [
            "settings 2",
            "camera (struct Pinhole (position (call vec3f 0.0 1.5 5.0)) (fov 40.0))",
            "background (struct SkyGradient)",
            "let grey",
            "object Some(\"floor\") 3",
            "object None 2",
            "light Some(\"key\") (struct PointLight (position (call vec3f 2.0 4.0 3.0)))",
            "light None (struct PointLight)",
            "model a.glb 1",
            "model b.gltf 0",
            "animate floor keys Some(\"smooth\") 0.0: (call identity), 1.5: (call scale 2.0)",
            "animate camera.fov spin(a, 2.0)",
        ]
    );
    // Contextual keywords are ordinary names elsewhere.
    assert_eq!(
        ok_stmts("let camera = light + model;"),
        "(let camera (+ light model))"
    );
}

#[test]
fn stdlib_and_examples_parse_cleanly() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut seen = 0;
    for dir in ["stdlib", "examples"] {
        let mut stack = vec![root.join(dir)];
        while let Some(d) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&d) else {
                continue;
            };
            for e in entries.flatten() {
                let path = e.path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|x| x == "rt") {
                    let text = std::fs::read_to_string(&path).unwrap_or_default();
                    let (m, diags) = parse(&text);
                    assert!(diags.is_empty(), "{}: {diags:?}", path.display());
                    super::check_spans(&m);
                    seen += 1;
                }
            }
        }
    }
    assert!(seen > 0);
}

#[test]
fn spec_examples_parse_cleanly() {
    // Every ```rt block of the spec that is not expected to fail with a syntax code.
    let spec = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../spec");
    let Ok(entries) = std::fs::read_dir(&spec) else {
        return;
    };
    let mut blocks = 0;
    for e in entries.flatten() {
        let text = std::fs::read_to_string(e.path()).unwrap_or_default();
        let mut in_block = None;
        let mut code = String::new();
        for line in text.lines() {
            if let Some(info) = line.strip_prefix("```") {
                match in_block.take() {
                    None if info.starts_with("rt") => {
                        in_block = Some(info.to_string());
                        code.clear();
                    }
                    None => {}
                    Some(info) => {
                        let syntax_fail = info.contains("E01") || info.contains("E02");
                        if !syntax_fail {
                            let (_, diags) = parse(&code);
                            assert!(diags.is_empty(), "{:?} block:\n{code}\n{diags:?}", e.path());
                            blocks += 1;
                        }
                    }
                }
            } else if in_block.is_some() {
                code.push_str(line);
                code.push('\n');
            }
        }
    }
    assert!(blocks > 10);
}

#[test]
fn stmt_spans_include_semicolons() {
    let src = "fn f() {\n    let x = 1;\n    x += 2;\n}";
    let (m, _) = parse(src);
    let ItemKind::Fn(f) = &m.items[0].kind else {
        panic!("not a fn")
    };
    let texts: Vec<&str> = f.body.stmts.iter().map(|s| &src[s.span.range()]).collect();
    assert_eq!(texts, ["let x = 1;", "x += 2;"]);
    assert_eq!(&src[f.body.span.range()], &src[7..]);
    assert_eq!(stmts("f();").0, "(call f)");
}
