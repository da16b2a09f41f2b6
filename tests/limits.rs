//! Resource limits (issue 21, item 4): nothing the checker accepts fails later as an internal
//! compiler error.
//!
//! Each case is a scene whose material calls a function `big(x: f32) -> f32` (or uses a struct)
//! built to sit near a limit: big local arrays, constant arrays, structs, huge loop bounds, deep
//! nesting, chains of calls. Every case is compiled (`compile_scene`, which checks, links and
//! lowers) and, when that succeeds, written for all five targets. The test asserts that each
//! case ends as expected, either accepted and written everywhere, or rejected with the expected
//! located diagnostic (E0803, E0804, E0805, or the parser's nesting limit E0202), and never with
//! an ICE.

use rtc_compiler::back::{self, Target};
use rtc_compiler::diag::codes;
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene, BOUNDS_ENTRY, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::Severity;

/// The scene around a case: `big` is reached from the closest-hit program of the material `Big`.
fn scene(items: &str) -> String {
    format!(
        r#"import "std/cameras/pinhole.rt";
import "std/lights/point.rt";
import "std/miss/gradient.rt";

{items}

@material
struct Big {{
    k: f32 = 1.0,
}}

@closest_hit
fn big_shade(m: Big, ray: Ray, hit: Hit) -> vec3f {{
    return vec3f(big(m.k));
}}

scene limits {{
    settings {{ width: 8, height: 8, samples: 1, max_depth: 1 }}
    camera Pinhole {{ position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0), fov: 40.0 }}
    background SkyGradient {{}}
    object floor {{ geometry: quad_mesh(), material: Big {{}} }}
    light key PointLight {{ position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }}
}}
"#
    )
}

/// `n` nested `if` blocks around `inner`.
fn nested_ifs(n: usize, inner: &str) -> String {
    let mut s = String::new();
    for i in 0..n {
        s.push_str(&format!("if x > {i}.0 {{\n"));
    }
    s.push_str(inner);
    for _ in 0..n {
        s.push_str("}\n");
    }
    s
}

/// A chain of `n` structs, each holding the previous one and an array.
fn struct_chain(n: usize) -> String {
    let mut s = String::from("struct S0 { a: array<f32, 4u> }\n");
    for i in 1..n {
        s.push_str(&format!(
            "struct S{i} {{ inner: S{}, a: array<f32, 2u> }}\n",
            i - 1
        ));
    }
    s
}

/// The cases: a name, the items of the file, and the code the checker must report (`None`: the
/// program is accepted and must compile for every target).
fn cases() -> Vec<(&'static str, String, Option<codes::Code>)> {
    let f = |body: &str| format!("fn big(x: f32) -> f32 {{\n{body}\n}}");
    vec![
        (
            "local array within the budget",
            f("var a: array<f32, 2000u>;\n\
               for i in 0u..2000u { a[i] = f32(i) * x; }\n\
               return a[1999];"),
            None,
        ),
        (
            "local array over the private-memory budget",
            f("var a: array<vec4f, 1000000u>;\na[3] = vec4f(x);\nreturn a[3].x;"),
            Some(codes::E0804),
        ),
        (
            "local array over the largest type",
            f("var a: array<vec4f, 1000000000u>;\nreturn x;"),
            Some(codes::E0803),
        ),
        (
            "let of a zero array over the budget",
            f("let a = array<f32, 100000u>();\nreturn a[7] + x;"),
            Some(codes::E0804),
        ),
        (
            "constant array within the constant bound",
            "const T: array<f32, 60000u> = array<f32, 60000u>();\n".to_string()
                + &f("return T[7] + x;"),
            None,
        ),
        (
            "constant array of explicit elements",
            "const T: array<vec3f, 3u> = array<vec3f, 3u>(vec3f(1.0), vec3f(2.0), vec3f(3.0));\n"
                .to_string()
                + &f("return T[u32(x) % 3u].y;"),
            None,
        ),
        (
            "constant array over the constant bound",
            "const T: array<f32, 100000u> = array<f32, 100000u>();\n".to_string()
                + &f("return T[7] + x;"),
            Some(codes::E0805),
        ),
        (
            "constant array of 2^32 - 1 elements",
            "const BIG: array<f32, 4294967295u> = array<f32, 4294967295u>();\n".to_string()
                + &f("return BIG[0] + x;"),
            Some(codes::E0803),
        ),
        (
            "nested arrays over the largest type",
            f("var a: array<array<f32, 65536u>, 65536u>;\nreturn x;"),
            Some(codes::E0803),
        ),
        (
            "nested arrays within the budget",
            f("var a: array<array<array<f32, 4u>, 4u>, 4u>;\n\
               a[1][2][3] = x;\nreturn a[1][2][3];"),
            None,
        ),
        (
            "struct over the largest type",
            "struct Huge { a: array<vec4f, 5000000u>, b: array<vec4f, 5000000u> }\n".to_string()
                + &f("return x;"),
            Some(codes::E0803),
        ),
        (
            "deep chain of structs",
            struct_chain(40) + &f("var s: S39;\ns.a[1] = x;\nreturn s.a[1];"),
            None,
        ),
        (
            "calls whose arrays add up over the budget",
            "fn helper(x: f32) -> f32 {\nvar a: array<f32, 1500u>;\na[1] = x;\nreturn a[1];\n}\n"
                .to_string()
                + &f("var b: array<f32, 1000u>;\nb[0] = helper(x);\nreturn b[0];"),
            Some(codes::E0804),
        ),
        (
            "calls whose arrays fit the budget",
            "fn helper(x: f32) -> f32 {\nvar a: array<f32, 1000u>;\na[1] = x;\nreturn a[1];\n}\n"
                .to_string()
                + &f("var b: array<f32, 500u>;\nb[0] = helper(x);\nreturn b[0];"),
            None,
        ),
        (
            "a loop of 2^32 - 1 iterations",
            f("var s = 0.0;\n\
               for i in 0u..4294967295u { s += f32(i); if s > x { break; } }\n\
               return s;"),
            None,
        ),
        (
            "loops nested 32 deep",
            f(&format!(
                "var s = 0.0;\n{}\nreturn s;",
                (0..32).fold("s += x;".to_string(), |inner, i| format!(
                    "for i{i} in 0u..2u {{ {inner} }}"
                ))
            )),
            None,
        ),
        (
            "ifs nested 100 deep",
            f(&format!(
                "var s = x;\n{}\nreturn s;",
                nested_ifs(100, "s += 1.0;\n")
            )),
            None,
        ),
        (
            "ifs nested 200 deep, past the parser's nesting limit",
            f(&format!(
                "var s = x;\n{}\nreturn s;",
                nested_ifs(200, "s += 1.0;\n")
            )),
            Some(codes::E0202),
        ),
        (
            "a function of 2000 statements",
            f(&format!(
                "let v0 = x;\n{}\nreturn v1999;",
                (1..2000)
                    .map(|i| format!("let v{i} = v{} * 0.5 + 1.0;", i - 1))
                    .collect::<Vec<_>>()
                    .join("\n")
            )),
            None,
        ),
    ]
}

/// Runs `f` on a thread with the stack the CLI gives the compiler (`rtc`'s `WORKER_STACK`), not
/// the test harness's 2 MiB.
fn on_cli_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(f)
        .expect("spawn the worker")
        .join()
        .unwrap_or_else(|p| std::panic::resume_unwind(p));
}

#[test]
fn accepted_programs_compile_for_every_target_and_rejected_ones_are_located() {
    on_cli_stack(accepted_or_located);
}

fn accepted_or_located() {
    let dir = std::env::temp_dir().join(format!("rtc-limits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary folder");
    let mut failures = Vec::new();
    for (i, (name, items, expected)) in cases().into_iter().enumerate() {
        let path = dir.join(format!("case{i}.rt"));
        std::fs::write(&path, scene(&items)).expect("write the case");
        let result = compile_scene(
            std::slice::from_ref(&path),
            None,
            &Options::default(),
            &LinkOptions::default(),
        );
        match (result, expected) {
            (Ok(c), None) => {
                let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
                let mut modules = vec![(&c.render, RENDER_ENTRY)];
                if let Some(b) = &c.bounds {
                    modules.push((b, BOUNDS_ENTRY));
                }
                for (module, entry) in modules {
                    for t in Target::ALL {
                        if let Err(e) = back::write(module, t, entry, &resources) {
                            failures.push(format!("{name}: {}: {e}", t.name()));
                        }
                    }
                }
            }
            (Ok(_), Some(code)) => {
                failures.push(format!("{name}: accepted, expected {}", code.0));
            }
            (Err(f), expected) => {
                let text =
                    rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false);
                let errors: Vec<_> = f
                    .diagnostics
                    .iter()
                    .filter(|d| d.severity == Severity::Error)
                    .collect();
                if errors.iter().any(|d| d.code == codes::ICE) {
                    failures.push(format!("{name}: internal compiler error\n{text}"));
                } else if errors.iter().any(|d| {
                    f.checked.sources.get(d.primary.span.file).path.as_deref()
                        != Some(path.as_path())
                }) {
                    failures.push(format!("{name}: an error outside the case's file\n{text}"));
                } else if expected.is_none_or(|c| !errors.iter().any(|d| d.code == c)) {
                    failures.push(format!(
                        "{name}: expected {}, got\n{text}",
                        expected.map_or("no error", |c| c.0)
                    ));
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// A function with more named values than the MSL writer handles is refused for that target with
/// E0806, located in the function (naga's Metal writer is quadratic in them; `back` bounds it).
#[test]
fn a_function_too_large_for_msl_is_a_located_error() {
    on_cli_stack(too_large_for_msl);
}

fn too_large_for_msl() {
    let dir = std::env::temp_dir().join(format!("rtc-limits-msl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary folder");
    let path = dir.join("big.rt");
    let n = back::MSL_MAX_NAMED_VALUES + 10;
    let body = (1..n)
        .map(|i| format!("    let v{i} = v{} * 0.5 + 1.0;\n", i - 1))
        .collect::<String>();
    let items = format!(
        "fn big(x: f32) -> f32 {{\n    let v0 = x;\n{body}    return v{};\n}}",
        n - 1
    );
    std::fs::write(&path, scene(&items)).expect("write the case");
    let c = match compile_scene(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions::default(),
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    };
    let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
    let err = back::write(&c.render, Target::Msl, RENDER_ENTRY, &resources)
        .expect_err("MSL refuses the function");
    let d = err
        .limit_diagnostic(&c.checked.sources)
        .unwrap_or_else(|| panic!("not a located limit: {err}"));
    assert_eq!(d.code, codes::E0806);
    assert_eq!(
        c.checked.sources.get(d.primary.span.file).path.as_deref(),
        Some(path.as_path())
    );
    // The first value of `big` the writer names: `v1`'s (line 7; `v0 = x` is the argument).
    assert_eq!(
        c.checked
            .sources
            .line_col(d.primary.span.file, d.primary.span.lo)
            .0,
        7,
        "{d:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
