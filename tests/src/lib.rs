//! Shared helpers of the integration suites: where the repository is, how `.rt` files are found,
//! how diagnostics are rendered with machine-independent file names, golden files and their diffs,
//! the UI cases and their inline annotations, the spec's code blocks, and the fuzz inputs.
//!
//! The test targets (`ui.rs`, `spec.rs`, `stdlib.rs`, `fuzz.rs` next to this crate's `Cargo.toml`)
//! are thin: they call into these modules, which have their own unit tests.

pub mod fuzzgen;
pub mod golden;
pub mod paths;
pub mod render;
pub mod spec;
pub mod ui;

use rtc_compiler::driver::Checked;

/// Runs `f` on a new thread with `stack` bytes of stack and returns its result, or the panic's message.
///
/// Every suite checks programs this way, so that a deep input hits the compiler's own recursion caps
/// rather than the test harness's small default stack, and one panicking case does not hide the others.
pub fn run_with_stack<T: Send + 'static>(
    stack: usize,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    let handle = std::thread::Builder::new()
        .stack_size(stack)
        .spawn(f)
        .map_err(|e| format!("cannot spawn a checker thread: {e}"))?;
    handle.join().map_err(|payload| panic_message(&*payload))
}

/// The message of a panic payload.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        format!("panicked: {s}")
    } else if let Some(s) = payload.downcast_ref::<String>() {
        format!("panicked: {s}")
    } else {
        "panicked with a non-string payload".to_owned()
    }
}

/// The stack the suites give the checker: the same 8 MiB as a program's main thread on Linux.
pub const CHECK_STACK: usize = 8 << 20;

/// `(errors, warnings)` of a check.
pub fn counts(checked: &Checked) -> (usize, usize) {
    use rtc_compiler::Severity;
    let n = |s| {
        checked
            .diagnostics
            .iter()
            .filter(|d| d.severity == s)
            .count()
    };
    (n(Severity::Error), n(Severity::Warning))
}
pub mod difftest;
