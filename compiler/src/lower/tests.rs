//! Lowering tests without a GPU: programs checked from text, lowered, validated and written for every
//! target. (Their results on a GPU are checked by `tests/diff.rs`.)

use super::testgen::{test_entry, TestKernel};
use super::*;
use crate::back::{self, Target};
use crate::driver::{check_text, Checked, Options};

fn checked(src: &str) -> Checked {
    let c = check_text("test.rt", src, &Options::default());
    assert!(!c.has_errors(), "{:#?}", c.diagnostics);
    c
}

fn fn_id(p: &Program, name: &str) -> FnId {
    p.functions
        .iter()
        .find(|(_, f)| f.name == name)
        .map(|(id, _)| id)
        .unwrap_or_else(|| panic!("no function {name}"))
}

/// Lowers `name` with a test entry point and writes every target; returns the WGSL.
fn lower_entry(src: &str, name: &str) -> String {
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let k = test_entry(p, &c.sources, fn_id(p, name), &mut NoIntrinsics)
        .unwrap_or_else(|e| panic!("{e}"));
    let mut wgsl = String::new();
    for t in Target::ALL {
        let out = back::write(&k.module, t, testgen::ENTRY_POINT, &TestKernel::resources())
            .unwrap_or_else(|e| panic!("{}: {e}", t.name()));
        if t == Target::Wgsl {
            wgsl = String::from_utf8(out).expect("utf8");
        }
    }
    wgsl
}

const LOOPS: &str = r#"
fn f(a: i32, b: i32) -> i32 {
    var acc = 0;
    for i in 0..b {
        if i % 2 == 0 { continue; }
        acc += a / i;
    }
    while acc > 100 { acc -= 7; }
    loop { acc += 1; if acc > 3 { break; } }
    return acc << 3u;
}
"#;

#[test]
fn control_flow_maps_to_structured_naga() {
    let wgsl = lower_entry(LOOPS, "f");
    // `for`: the increment in `continuing`, so `continue` runs it.
    assert!(wgsl.contains("continuing {"), "{wgsl}");
    // Integer division goes through the helper (a zero divisor gives the left operand), emitted once.
    assert_eq!(wgsl.matches("fn div_i32").count(), 1, "{wgsl}");
    assert_eq!(wgsl.matches("fn rem_i32").count(), 1, "{wgsl}");
    // A literal shift amount below 32 is used as is.
    assert!(wgsl.contains("<< 3u"), "{wgsl}");
}

#[test]
fn output_is_deterministic() {
    let a = lower_entry(LOOPS, "f");
    let b = lower_entry(LOOPS, "f");
    assert_eq!(a, b);
}

#[test]
fn only_reachable_functions_are_emitted() {
    let src = "
fn helper(x: f32) -> f32 { return normalize(vec3f(x, 1.0, 0.0)).x; }
fn unused(x: f32) -> f32 { return f32(is_nan(x)); }
fn f(x: f32) -> f32 { return helper(x) + helper(2.0 * x); }
";
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let lowered = lower(
        p,
        &c.sources,
        &[fn_id(p, "f")],
        &mut NoIntrinsics,
        |_, _| Ok(()),
    )
    .expect("lowers");
    let names: Vec<&str> = lowered
        .module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .collect();
    assert_eq!(names, ["normalize_vec3f", "helper", "f"]);
    // Callees precede callers.
    let order: Vec<FnId> = lowered.functions.keys().copied().collect();
    assert_eq!(order, [fn_id(p, "helper"), fn_id(p, "f")]);
}

#[test]
fn an_intrinsic_without_a_kernel_is_an_internal_error_at_the_call() {
    let src = "fn f(x: f32) -> f32 {\n    return x * rand();\n}\n";
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let err = lower(
        p,
        &c.sources,
        &[fn_id(p, "f")],
        &mut NoIntrinsics,
        |_, _| Ok(()),
    )
    .expect_err("no rand");
    assert!(
        matches!(
            err,
            LowerError::Unsupported {
                what: Unsupported::Intrinsic(Builtin::Rand),
                ..
            }
        ),
        "{err:?}"
    );
    let d = err.to_diagnostic(p);
    assert_eq!(d.code, crate::diag::codes::ICE);
    assert_eq!(c.sources.snippet(d.primary.span), "rand()");
}

/// A hook that lowers `rand()` to a constant and every call of `placeholder` to its argument.
struct TestHook;

impl Intrinsics for TestHook {
    fn lower(
        &mut self,
        _cx: &mut Lowerer<'_>,
        fb: &mut FnBuilder,
        call: &IntrinsicCall<'_>,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        assert_eq!(call.builtin, Builtin::Rand);
        Ok(Some(fb.literal(naga::Literal::F32(0.25))))
    }

    fn lower_call(
        &mut self,
        cx: &mut Lowerer<'_>,
        _fb: &mut FnBuilder,
        call: &FunctionCall<'_>,
    ) -> Result<CallLowering, LowerError> {
        if cx.program().functions[call.callee].name == "placeholder" {
            return Ok(CallLowering::Done(call.args.first().copied()));
        }
        Ok(CallLowering::Default)
    }
}

#[test]
fn the_hook_lowers_intrinsics_and_intercepts_calls() {
    let src = "
fn placeholder(x: f32) -> f32 { return 0.0; }
fn g(x: f32) -> f32 { return x + rand(); }
fn f(x: f32) -> f32 { return placeholder(g(x)); }
";
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let lowered = lower(
        p,
        &c.sources,
        &[fn_id(p, "f")],
        &mut TestHook,
        |_, _| Ok(()),
    )
    .expect("lowers");
    let names: Vec<&str> = lowered
        .module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .collect();
    assert_eq!(names, ["g", "f"], "the intercepted callee is never lowered");
}

#[test]
fn naga_spans_map_back_to_dsl_source() {
    let src = "fn f(a: f32, b: f32) -> f32 {\n    return a * b + 1.0;\n}\n";
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let mut lw = Lowerer::new(p, &c.sources);
    let h = lw
        .ensure_function(fn_id(p, "f"), &mut NoIntrinsics)
        .expect("lowers");
    let func = &lw.module().functions[h];
    let snippets: Vec<&str> = func
        .expressions
        .iter()
        .filter(|(_, e)| matches!(e, Expression::Binary { .. }))
        .map(|(e, _)| lw.dsl_span(func.expressions.get_span(e)))
        .map(|s| c.sources.snippet(s))
        .collect();
    assert_eq!(snippets, ["a * b", "a * b + 1.0"]);

    // A module naga rejects is an internal error at the DSL span of what naga rejected: here the
    // function's result type is made wrong, so the returned value is invalid.
    let mut module = lw.into_module();
    let u32_ty = builder::TypeCache::scalar(&mut module, naga::Scalar::U32);
    if let Some(r) = module.functions[h].result.as_mut() {
        r.ty = u32_ty;
    }
    let err = validate(&module, &c.sources).expect_err("invalid");
    let span = err.span().expect("a span");
    assert_eq!(c.sources.snippet(span), "a * b + 1.0");
    let d = err.to_diagnostic(p);
    assert_eq!(d.code, crate::diag::codes::ICE);
    assert!(d.message.contains("invalid IR"), "{}", d.message);
}

#[test]
fn structs_get_layout_offsets() {
    let src = "
struct S { a: f32, b: vec3f, c: u32, d: mat3x3f, e: array<vec2f, 3> }
fn f(s: S) -> S { return s; }
";
    let c = checked(src);
    let p = c.program.as_ref().expect("program");
    let k = test_entry(p, &c.sources, fn_id(p, "f"), &mut NoIntrinsics).expect("lowers");
    let s = &k.input.members[0];
    let offsets: Vec<u32> = s.slots.iter().map(|slot| slot.offset).collect();
    // a at 0, b at 16 (vec3 aligned to 16), c at 28, d at 32 (columns 16 apart), e at 80 (stride 8).
    let mut want = vec![0, 16, 20, 24, 28];
    for col in 0..3 {
        want.extend([32 + 16 * col, 36 + 16 * col, 40 + 16 * col]);
    }
    for el in 0..3 {
        want.extend([80 + 8 * el, 84 + 8 * el]);
    }
    assert_eq!(offsets, want);
    assert_eq!(k.input.stride, 112);
}

#[test]
fn constants_become_named_naga_constants_unless_not_finite() {
    let src = "
const K: vec3f = vec3f(1.0, 2.0, 3.0);
fn f(x: f32) -> f32 { let r = Ray { origin: K, dir: K }; return r.tmax + K.y + x + INF; }
";
    let wgsl = lower_entry(src, "f");
    assert!(wgsl.contains("const K: vec3<f32>"), "{wgsl}");
    // INF cannot be a naga constant (no infinite literals) nor a WGSL constant expression: it is a
    // bit cast of a private variable where used.
    assert!(
        wgsl.contains("var<private> F32_INF: u32 = 2139095040u;"),
        "{wgsl}"
    );
    assert!(!wgsl.contains("bitcast<f32>(2139095040u)"), "{wgsl}");
}
