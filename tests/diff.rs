//! Differential execution of lowered DSL functions on a GPU (Mesa's lavapipe on machines without one)
//! against references computed in Rust, within the tolerances of spec/builtins.md.
//!
//! Each test checks one DSL source, lowers each of its functions with the test entry point, validates
//! and writes it for all five targets, runs it once over at least 1,000 inputs (edge values first:
//! zeros of both signs, ±1, infinities, NaN, denormals, the integer extremes) and compares. Every case
//! prints one line: inputs, the largest error seen, how many results passed only with denormals
//! flushed (`cargo test --test diff -- --nocapture` shows them). Without any adapter, each test prints
//! that it skipped and passes.

#[path = "src/gpu.rs"]
mod gpu;

use rtc_tests::difftest::cases;
use rtc_tests::difftest::{run_specs, Sc, Spec, Tol};

/// The device, or `None` after printing that `test` skipped.
fn device(test: &str) -> Option<&'static gpu::Gpu> {
    let g = gpu::gpu();
    match g {
        Some(g) => println!("{test}: on {}", rtc_tests::difftest::Executor::name(g)),
        None => println!(
            "SKIPPED {test}: no GPU adapter (install Mesa's lavapipe: mesa-vulkan-drivers)"
        ),
    }
    g
}

fn run(test: &str, specs: &[Spec]) {
    if let Some(gpu) = device(test) {
        run_specs(gpu, test, specs).finish();
    }
}

macro_rules! groups {
    ($($(#[$doc:meta])* $name:ident => $cases:path;)*) => {
        $( $(#[$doc])* #[test] fn $name() { run(stringify!($name), &$cases()); } )*
    };
}

groups! {
    /// Every float function of the "Numbers" table, on `f32` and `vec4f`.
    float_builtins => cases::numbers::float_builtins;
    /// The integer built-ins on `i32`, `u32`, `vec3i`, `vec3u`.
    integer_builtins => cases::integers::integer_builtins;
    /// `is_nan`, `is_inf`, `is_finite`, `select`, `any`, `all`.
    classification_and_select => cases::integers::classification_and_select;
    /// `pack_*` and `unpack_*`.
    bit_packing => cases::integers::bit_packing;
    /// Wrapping arithmetic, division and remainder by zero, `MIN / -1`, shifts modulo 32, bit operators.
    integer_operators => cases::operators::integer_operators;
    /// Float arithmetic on NaN, infinities, denormals and signed zeros; comparisons; matrices.
    float_operators => cases::operators::float_operators;
    /// Saturating float → int, rounding int → float, bit casts, `bool(x)`.
    conversions => cases::operators::conversions;
    /// `dot cross length distance normalize reflect refract face_forward`.
    vector_builtins => cases::linalg::vector_builtins;
    /// `transpose determinant inverse`, the transforms, `orthonormal_basis`.
    matrix_builtins => cases::linalg::matrix_builtins;
    /// `intersect_triangle intersect_aabb sample_* luminance`.
    geometry_builtins => cases::geometry::geometry_builtins;
    /// `if`/`else` chains, loops with `break`/`continue`, early returns, short-circuit operators.
    control_flow => cases::programs::control_flow;
    /// Nested structs with defaults, struct parameters, arrays, clamped dynamic indices.
    structs_and_arrays => cases::programs::structs_and_arrays;
}

/// What the device does with denormals (printed), checked against what the spec guarantees: either
/// the exact result or the result with denormal inputs and outputs flushed to zero.
#[test]
fn denormals() {
    let Some(gpu) = device("denormals") else {
        return;
    };
    let tiny = f32::MIN_POSITIVE;
    // Each case: name, expression, inputs, and the expression on the CPU (which keeps denormals),
    // so the flushed reference is the same expression on the flushed inputs.
    type Op = fn(f32, f32) -> f32;
    let cases: [(&str, &str, [f32; 2], Op); 4] = [
        ("halve_normal", "a * b", [tiny, 0.5], |a, b| a * b),
        ("add_denormals", "a + b", [1e-40, 1e-40], |a, b| a + b),
        ("denormal_times_big", "a * b", [1e-40, 1e30], |a, b| a * b),
        ("pass_through", "a + b * 0.0", [1e-40, 1.0], |a, b| {
            a + b * 0.0
        }),
    ];
    let mut src_text = String::new();
    for (name, expr, _, _) in cases {
        src_text.push_str(&format!(
            "fn {name}(a: f32, b: f32) -> f32 {{ return {expr}; }}\n"
        ));
    }
    let suite = rtc_tests::difftest::Suite::new("denormals", &src_text);
    let mut failures = Vec::new();
    for (name, _, [a, b], op) in cases {
        let exact = op(a, b);
        let inputs = vec![vec![vec![Sc::F(a)], vec![Sc::F(b)]]; 64];
        let report = suite.case(
            gpu,
            name,
            &inputs,
            Tol::EXACT,
            &move |args: &rtc_tests::difftest::Args| match (args[0][0], args[1][0]) {
                (Sc::F(x), Sc::F(y)) => vec![Sc::F(op(x, y))],
                _ => vec![Sc::F(f32::NAN)],
            },
            None,
        );
        let kernel = suite.kernel(name).expect("lowers");
        let bytes: Vec<u8> = [a, b].iter().flat_map(|v| v.to_le_bytes()).collect();
        let out = rtc_tests::difftest::Executor::run(gpu, kernel, &bytes, 1).unwrap_or_default();
        let got = out
            .get(0..4)
            .map(|w| f32::from_le_bytes([w[0], w[1], w[2], w[3]]))
            .unwrap_or(f32::NAN);
        println!(
            "denormals: {name}({a:e}, {b:e}) = {got:e} (exact {exact:e}) -> {}",
            if got == exact {
                "kept"
            } else if got == 0.0 {
                "flushed"
            } else {
                "other"
            }
        );
        if report.failed > 0 {
            failures.extend(report.failures);
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
