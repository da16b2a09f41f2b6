//! Differential execution: run DSL functions on a GPU over many inputs and compare every result with a
//! reference computed in Rust, within a stated tolerance.
//!
//! A [`Suite`] is one DSL source, checked once. [`Suite::case`] lowers one of its functions with the
//! test entry point of `rtc_compiler::lower::testgen`, validates and writes the module for all five
//! targets (so a lowering one back end rejects is caught even though only one runs), packs the inputs
//! by the kernel's layout, runs one dispatch through an [`Executor`] (the wgpu device of the test
//! binary), unpacks the results and compares them with the reference.
//!
//! Comparison rules (the tolerance column of spec/builtins.md):
//! - integers and booleans are exact;
//! - floats: a NaN reference needs a NaN result; an infinite one the same infinity; otherwise the
//!   result passes if it is within any bound of its [`Tol`] (ULPs, absolute, relative; none means
//!   exact), with `-0.0 == 0.0`;
//! - denormals: a GPU may flush them (lavapipe does, see the report). A result also passes if it
//!   matches the reference evaluated on the inputs with denormals flushed to zero, or if the reference
//!   is denormal and the result is zero. Such passes are counted ([`Report::flushed`]).
//! - flushed intermediates: WGSL lets every operation flush a subnormal input or result, so a
//!   builtin made of several operations (`mix`, `dot`, `cross`, `normalize`, `fma` lowered as a
//!   multiply and an add) may lose a subnormal product inside it, and the result then differs from
//!   the reference by far more than its ULP bound (`normalize` of a vector whose components square
//!   to subnormals, for one). On a device that flushes subnormal results (probed once per device
//!   with `MIN_POSITIVE * 0.5`, see [`flushes_subnormals`]; Mesa 26's lavapipe does, 25.0's does
//!   not), inputs with a float component of magnitude below 2^-63, whose square is subnormal, need
//!   only be finite where the reference is finite, and are counted as flushed.
//!
//! Invariant: a case never panics on bad GPU output; every mismatch is reported with its inputs.

pub mod cases;
pub mod gen;
pub mod refs;

use rtc_compiler::back::{self, Target};
use rtc_compiler::driver::{check_text, Checked, Options};
use rtc_compiler::lower::testgen::{test_entry, IoLayout, TestKernel, ENTRY_POINT};
use rtc_compiler::lower::NoIntrinsics;
use rtc_compiler::sema::types::ScalarKind;

/// A scalar value of an input or a result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sc {
    /// `f32`
    F(f32),
    /// `i32`
    I(i32),
    /// `u32`
    U(u32),
    /// `bool`
    B(bool),
}

impl Sc {
    /// The value as an `f32` (integers converted, bools 0/1).
    pub fn f(self) -> f32 {
        match self {
            Sc::F(v) => v,
            Sc::I(v) => v as f32,
            Sc::U(v) => v as f32,
            Sc::B(b) => f32::from(u8::from(b)),
        }
    }
    /// The value as an `i32` (bits of a `u32`).
    pub fn i(self) -> i32 {
        match self {
            Sc::I(v) => v,
            Sc::U(v) => v as i32,
            Sc::F(v) => v as i32,
            Sc::B(b) => i32::from(b),
        }
    }
    /// The value as a `u32` (bits of an `i32`).
    pub fn u(self) -> u32 {
        match self {
            Sc::U(v) => v,
            Sc::I(v) => v as u32,
            Sc::F(v) => v as u32,
            Sc::B(b) => u32::from(b),
        }
    }
    /// The value as a `bool`.
    pub fn b(self) -> bool {
        match self {
            Sc::B(b) => b,
            other => other.u() != 0,
        }
    }
    fn bits(self) -> u32 {
        match self {
            Sc::F(v) => v.to_bits(),
            Sc::I(v) => v as u32,
            Sc::U(v) => v,
            Sc::B(b) => u32::from(b),
        }
    }
    fn from_bits(bits: u32, kind: ScalarKind) -> Sc {
        match kind {
            ScalarKind::F32 => Sc::F(f32::from_bits(bits)),
            ScalarKind::I32 => Sc::I(bits as i32),
            ScalarKind::U32 => Sc::U(bits),
            ScalarKind::Bool => Sc::B(bits != 0),
        }
    }
    /// Denormal floats flushed to zero (keeping the sign).
    pub fn ftz(self) -> Sc {
        match self {
            Sc::F(v) if v.is_subnormal() => Sc::F(0.0f32.copysign(v)),
            other => other,
        }
    }
}

/// The arguments of one call: one list of scalar components per parameter.
pub type Args = Vec<Vec<Sc>>;

/// A reference: the expected result components for some arguments.
pub type Reference = dyn Fn(&Args) -> Vec<Sc>;

/// Per result component, an absolute error bound computed from the arguments ([`Tol::bound`]).
pub type Bound = dyn Fn(&Args) -> Vec<f64>;

/// A float tolerance: a result passes within any of the bounds given; none given means exact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tol {
    /// Units in the last place.
    pub ulp: Option<u32>,
    /// Absolute error.
    pub abs: Option<f64>,
    /// Error relative to the reference's magnitude.
    pub rel: Option<f64>,
    /// Whether the per-component absolute bound of [`Spec::bound`] applies (bounds the spec states
    /// in terms of the arguments: "1 ULP of `max(|a|, |b|)`" for `mix`, "`3 + 2|x|` ULP" for `exp`).
    pub bound: bool,
}

impl Tol {
    /// Exact (floats compare equal, `-0 == 0`).
    pub const EXACT: Tol = Tol {
        ulp: None,
        abs: None,
        rel: None,
        bound: false,
    };
    /// `n` ULPs.
    pub const fn ulp(n: u32) -> Tol {
        Tol {
            ulp: Some(n),
            ..Tol::EXACT
        }
    }
    /// An absolute bound.
    pub const fn abs(e: f64) -> Tol {
        Tol {
            abs: Some(e),
            ..Tol::EXACT
        }
    }
    /// A relative bound.
    pub const fn rel(e: f64) -> Tol {
        Tol {
            rel: Some(e),
            ..Tol::EXACT
        }
    }
    /// The per-component bounds of [`Spec::bound`].
    pub const fn bound() -> Tol {
        Tol {
            bound: true,
            ..Tol::EXACT
        }
    }
    /// This tolerance, also passing within `n` ULPs.
    pub const fn or_ulp(mut self, n: u32) -> Tol {
        self.ulp = Some(n);
        self
    }
    /// This tolerance, also passing within `e` absolute.
    pub const fn or_abs(mut self, e: f64) -> Tol {
        self.abs = Some(e);
        self
    }
    /// This tolerance, also passing within `e` relative.
    pub const fn or_rel(mut self, e: f64) -> Tol {
        self.rel = Some(e);
        self
    }
}

/// Distance in ULPs between two finite floats of the same sign class (`u64::MAX` across NaN).
pub fn ulp_diff(a: f32, b: f32) -> u64 {
    if a.is_nan() || b.is_nan() {
        return u64::MAX;
    }
    let key = |x: f32| {
        let bits = x.to_bits() as i32;
        // Monotonic map of floats to integers (-0 and +0 both to 0).
        i64::from(if bits < 0 { i32::MIN - bits } else { bits })
    };
    key(a).abs_diff(key(b))
}

/// The ULP of a magnitude (the spacing of `f32`s at `|m|`; the smallest denormal for 0).
pub fn ulp_of(m: f64) -> f64 {
    let m = (m.abs() as f32).min(f32::MAX);
    let next = f32::from_bits(m.to_bits() + 1);
    f64::from(next) - f64::from(m)
}

/// How one float result compares with a reference; `bound` is the absolute bound for [`Tol::bound`].
fn float_ok(got: f32, want: f32, tol: &Tol, bound: f64) -> bool {
    if want.is_nan() {
        return got.is_nan();
    }
    if got.is_nan() {
        return false;
    }
    if want.is_infinite() || got.is_infinite() {
        return got == want;
    }
    if got == want {
        return true;
    }
    let err = (f64::from(got) - f64::from(want)).abs();
    tol.ulp.is_some_and(|n| ulp_diff(got, want) <= u64::from(n))
        || tol.abs.is_some_and(|e| err <= e)
        || tol.rel.is_some_and(|e| err <= e * f64::from(want).abs())
        || (tol.bound && err <= bound)
}

fn scalar_ok(got: Sc, want: Sc, tol: &Tol, bound: f64) -> bool {
    match (got, want) {
        (Sc::F(g), Sc::F(w)) => float_ok(g, w, tol, bound),
        (g, w) => g.bits() == w.bits(),
    }
}

/// Runs a test kernel on a device.
pub trait Executor {
    /// A name for reports (the adapter).
    fn name(&self) -> String;
    /// Runs `kernel` once per element of `input` (`count` elements); returns the output buffer.
    fn run(&self, kernel: TestKernel, input: &[u8], count: u32) -> Result<Vec<u8>, String>;
}

/// The outcome of one case.
#[derive(Debug, Default)]
pub struct Report {
    /// `suite::function`.
    pub name: String,
    /// Inputs run.
    pub inputs: usize,
    /// Mismatches, described (at most a few are kept).
    pub failures: Vec<String>,
    /// Number of mismatching inputs.
    pub failed: usize,
    /// Results that passed only with denormals flushed.
    pub flushed: usize,
    /// The largest ULP distance seen between a finite result and its finite reference.
    pub max_ulp: u64,
    /// The largest absolute error seen between a finite result and its finite reference.
    pub max_abs: f64,
    /// The largest error relative to the reference's magnitude (for references of magnitude ≥ 1e-30).
    pub max_rel: f64,
}

/// Whether `exec`'s device flushes subnormal results to zero: `MIN_POSITIVE * 0.5` computed on it
/// (an `f32` input, so the product is not folded at compile time). Probed once per device name.
pub fn flushes_subnormals(exec: &dyn Executor) -> bool {
    use std::collections::HashMap;
    use std::sync::{Mutex, OnceLock};
    static PROBED: OnceLock<Mutex<HashMap<String, bool>>> = OnceLock::new();
    let name = exec.name();
    let probed = PROBED.get_or_init(Default::default);
    if let Some(known) = probed.lock().ok().and_then(|m| m.get(&name).copied()) {
        return known;
    }
    let suite = Suite::new(
        "subnormal_probe",
        "fn halve(a: f32, b: f32) -> f32 { return a * b; }",
    );
    let bytes: Vec<u8> = [f32::MIN_POSITIVE, 0.5]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    let flushes = suite
        .kernel("halve")
        .and_then(|k| exec.run(k, &bytes, 1))
        .ok()
        .and_then(|out| out.get(0..4).map(|w| [w[0], w[1], w[2], w[3]]))
        .is_some_and(|w| f32::from_le_bytes(w) == 0.0);
    if let Ok(mut m) = probed.lock() {
        m.insert(name, flushes);
    }
    flushes
}

/// Whether an input has a float component `x` with `0 < |x| < 2^-63`, so `x * x` (and `x` times any
/// factor of magnitude at most 1) is subnormal.
fn in_flush_zone(args: &Args) -> bool {
    let limit = 2f32.powi(-63);
    args.iter()
        .flatten()
        .any(|s| matches!(s, Sc::F(x) if *x != 0.0 && x.abs() < limit))
}

/// Whether `got` is finite exactly where `want` is (the same NaNs and infinities).
fn same_finiteness(got: &[Sc], want: &[Sc]) -> bool {
    got.len() == want.len()
        && got.iter().zip(want).all(|(g, w)| match (g, w) {
            (Sc::F(g), Sc::F(w)) => {
                g.is_nan() == w.is_nan() && (g.is_infinite() == w.is_infinite())
            }
            (g, w) => g.bits() == w.bits(),
        })
}

/// A DSL source, checked once, whose functions are run as cases.
pub struct Suite {
    name: String,
    checked: Checked,
}

impl Suite {
    /// Checks `src`; panics with the diagnostics if it has errors (a bug in the test).
    pub fn new(name: &str, src: &str) -> Suite {
        let checked = check_text(&format!("{name}.rt"), src, &Options::default());
        if checked.program.is_none() {
            let msg =
                rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false);
            panic!("the test source `{name}` does not check:\n{msg}");
        }
        Suite {
            name: name.to_string(),
            checked,
        }
    }

    /// Lowers function `func` with the test entry point and writes it for every target.
    pub fn kernel(&self, func: &str) -> Result<TestKernel, String> {
        let program = self.checked.program.as_ref().ok_or("no program")?;
        let id = program
            .functions
            .iter()
            .find(|(_, f)| f.name == func)
            .map(|(id, _)| id)
            .ok_or_else(|| format!("no function `{func}`"))?;
        let kernel = test_entry(program, &self.checked.sources, id, &mut NoIntrinsics)
            .map_err(|e| format!("lowering `{func}`: {e}"))?;
        for target in Target::ALL {
            back::write(
                &kernel.module,
                target,
                ENTRY_POINT,
                &TestKernel::resources(),
            )
            .map_err(|e| format!("`{func}`: {e}"))?;
        }
        Ok(kernel)
    }

    /// Runs `func` over `inputs` and compares with `reference` within `tol`.
    pub fn case(
        &self,
        exec: &dyn Executor,
        func: &str,
        inputs: &[Args],
        tol: Tol,
        reference: &Reference,
        bound: Option<&Bound>,
    ) -> Report {
        let mut report = Report {
            name: format!("{}::{func}", self.name),
            inputs: inputs.len(),
            ..Report::default()
        };
        let fail = |report: &mut Report, msg: String| {
            report.failed += 1;
            if report.failures.len() < 8 {
                report.failures.push(msg);
            }
        };
        let kernel = match self.kernel(func) {
            Ok(k) => k,
            Err(e) => {
                fail(&mut report, e);
                return report;
            }
        };
        let (input_layout, output_layout) = (kernel.input.clone(), kernel.output.clone());
        let bytes = match pack(&input_layout, inputs) {
            Ok(b) => b,
            Err(e) => {
                fail(&mut report, e);
                return report;
            }
        };
        let out = match exec.run(kernel, &bytes, inputs.len() as u32) {
            Ok(o) => o,
            Err(e) => {
                fail(&mut report, e);
                return report;
            }
        };
        let flushing = flushes_subnormals(exec);
        for (i, args) in inputs.iter().enumerate() {
            let got = unpack(&output_layout, &out, i);
            let want = reference(args);
            let flushed_args: Args = args
                .iter()
                .map(|a| a.iter().map(|s| s.ftz()).collect())
                .collect();
            let want_ftz = reference(&flushed_args);
            if got.len() != want.len() {
                fail(
                    &mut report,
                    format!(
                        "{func}{args:?}: {} results, reference has {}",
                        got.len(),
                        want.len()
                    ),
                );
                continue;
            }
            let scales = bound.map(|f| f(args)).unwrap_or_default();
            let sc = |k: usize| scales.get(k).copied().unwrap_or(0.0);
            let plain = got
                .iter()
                .zip(&want)
                .enumerate()
                .all(|(k, (g, w))| scalar_ok(*g, *w, &tol, sc(k)));
            let flushed = || {
                got.iter()
                    .zip(&want_ftz)
                    .zip(&want)
                    .enumerate()
                    .all(|(k, ((g, wf), w))| {
                        scalar_ok(*g, *wf, &tol, sc(k))
                            || scalar_ok(*g, w.ftz(), &tol, sc(k))
                            || scalar_ok(*g, wf.ftz(), &tol, sc(k))
                    })
            };
            for (g, w) in got.iter().zip(&want) {
                if let (Sc::F(g), Sc::F(w)) = (g, w) {
                    if g.is_finite() && w.is_finite() && !w.is_subnormal() {
                        let err = (f64::from(*g) - f64::from(*w)).abs();
                        report.max_ulp = report.max_ulp.max(ulp_diff(*g, *w));
                        report.max_abs = report.max_abs.max(err);
                        if w.abs() >= 1e-30 {
                            report.max_rel = report.max_rel.max(err / f64::from(*w).abs());
                        }
                    }
                }
            }
            if plain {
                // Passed as is.
            } else if flushed() || (flushing && in_flush_zone(args) && same_finiteness(&got, &want))
            {
                report.flushed += 1;
            } else {
                fail(
                    &mut report,
                    format!("{func}{args:?}\n      got  {got:?}\n      want {want:?}"),
                );
            }
        }
        report
    }
}

/// Packs inputs into the input array's bytes.
fn pack(layout: &IoLayout, inputs: &[Args]) -> Result<Vec<u8>, String> {
    let stride = layout.stride as usize;
    let mut bytes = vec![0u8; stride * inputs.len().max(1)];
    for (i, args) in inputs.iter().enumerate() {
        let base = i * stride;
        for (m, arg) in layout.members.iter().zip(args) {
            if m.slots.len() != arg.len() {
                return Err(format!(
                    "parameter `{}` has {} components, the input gives {}",
                    m.name,
                    m.slots.len(),
                    arg.len()
                ));
            }
            for (slot, v) in m.slots.iter().zip(arg) {
                let at = base + slot.offset as usize;
                bytes[at..at + 4].copy_from_slice(&v.bits().to_le_bytes());
            }
        }
    }
    Ok(bytes)
}

/// The components of the `i`th result.
fn unpack(layout: &IoLayout, bytes: &[u8], i: usize) -> Vec<Sc> {
    let base = i * layout.stride as usize;
    let mut out = Vec::new();
    for m in &layout.members {
        for slot in &m.slots {
            let at = base + slot.offset as usize;
            let word = bytes
                .get(at..at + 4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .unwrap_or(0);
            out.push(Sc::from_bits(word, slot.kind));
        }
    }
    out
}

/// Collects the reports of a test and fails it at the end if any case failed.
#[derive(Default)]
pub struct Results {
    reports: Vec<Report>,
}

impl Results {
    /// Adds a report.
    pub fn add(&mut self, r: Report) {
        self.reports.push(r);
    }

    /// Prints a line per case (inputs, worst error, denormal flushes) and panics listing the failures.
    pub fn finish(self) {
        let mut failed = Vec::new();
        for r in &self.reports {
            println!(
                "{:<40} {:>6} inputs  worst {:>4} ulp {:<9.2e} abs {:<9.2e} rel  flushed {:<4} {}",
                r.name,
                r.inputs,
                r.max_ulp.min(9999),
                r.max_abs,
                r.max_rel,
                r.flushed,
                if r.failed == 0 {
                    "ok".to_string()
                } else {
                    format!("FAILED ({})", r.failed)
                }
            );
            if r.failed > 0 {
                failed.push(format!("{}:\n    {}", r.name, r.failures.join("\n    ")));
            }
        }
        assert!(failed.is_empty(), "mismatches:\n{}", failed.join("\n"));
    }
}

/// One function to test: its DSL text, its inputs, its reference and tolerance.
pub struct Spec {
    /// The DSL function's name.
    pub func: String,
    /// The DSL source defining it (and whatever it needs).
    pub src: String,
    /// The inputs.
    pub inputs: Vec<Args>,
    /// The float tolerance.
    pub tol: Tol,
    /// The reference.
    pub reference: Box<Reference>,
    /// Per result component, the absolute error bound of [`Tol::bound`].
    pub bound: Option<Box<Bound>>,
}

impl Spec {
    /// A spec whose inputs are drawn by `params` (at least `n`; the seed derives from the name, so
    /// inputs are stable).
    pub fn new(
        func: &str,
        src: String,
        n: usize,
        params: Vec<gen::Param<'_>>,
        tol: Tol,
        reference: impl Fn(&Args) -> Vec<Sc> + 'static,
    ) -> Spec {
        let seed = func.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
        });
        Spec {
            func: func.to_string(),
            src,
            inputs: gen::args(seed, n, params),
            tol,
            reference: Box::new(reference),
            bound: None,
        }
    }

    /// Replaces the inputs by `n` draws of one whole parameter split into parameters of `widths`
    /// components (for values drawn together: a ray aimed at a triangle, a box and a ray through it).
    pub fn with_inputs_from(mut self, mut whole: gen::Param<'_>, widths: &[usize]) -> Spec {
        let n = self.inputs.len();
        let mut rng = gen::Rng::new(self.inputs.len() as u64 ^ 0x5eed);
        self.inputs = (0..n)
            .map(|_| {
                let all: Vec<Sc> = (0..whole.width).map(|_| (whole.draw)(&mut rng)).collect();
                let mut at = 0;
                widths
                    .iter()
                    .map(|w| {
                        let part = all[at..at + w].to_vec();
                        at += w;
                        part
                    })
                    .collect()
            })
            .collect();
        self
    }

    /// Sets the per-component bounds of [`Tol::bound`].
    pub fn with_bound(mut self, bound: impl Fn(&Args) -> Vec<f64> + 'static) -> Spec {
        self.bound = Some(Box::new(bound));
        self
    }
}

/// Checks the specs' sources as one suite `name` and runs every spec.
pub fn run_specs(exec: &dyn Executor, name: &str, specs: &[Spec]) -> Results {
    let src: String = specs
        .iter()
        .map(|s| s.src.as_str())
        .collect::<Vec<_>>()
        .join("\n");
    let suite = Suite::new(name, &src);
    let mut results = Results::default();
    for s in specs {
        results.add(suite.case(
            exec,
            &s.func,
            &s.inputs,
            s.tol,
            &*s.reference,
            s.bound.as_deref(),
        ));
    }
    results
}
