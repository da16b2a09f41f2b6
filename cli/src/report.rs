//! Printing what a command found: diagnostics (human text on stderr, or JSON lines on stdout), the
//! summary line in the style of cargo, usage errors and internal compiler errors.
//!
//! Diagnostics are rendered only by `rtc_compiler::diag::{render_human, render_json}`; this module
//! decides where they go and what the summary says.

use crate::args::MessageFormat;
use crate::exit::Exit;
use crate::term;
use rtc_compiler::diag::{self, Diagnostic, Severity};
use rtc_compiler::SourceMap;

/// Prints every diagnostic and the summary line; returns [`Exit::Failure`] when there is an error.
/// `verb` names what failed in the summary (`check` → "could not check").
pub fn diagnostics(
    sources: &SourceMap,
    diags: &[Diagnostic],
    format: MessageFormat,
    color: bool,
    verb: &str,
) -> Exit {
    match format {
        MessageFormat::Human => term::eprint(&diag::render_human(sources, diags, color)),
        MessageFormat::Json => term::print(&diag::render_json(sources, diags)),
    }
    let errors = count(diags, Severity::Error);
    let warnings = count(diags, Severity::Warning);
    if let Some(line) = summary(verb, errors, warnings, color) {
        term::eprint(&line);
    }
    if errors > 0 {
        Exit::Failure
    } else {
        Exit::Success
    }
}

fn count(diags: &[Diagnostic], severity: Severity) -> usize {
    diags.iter().filter(|d| d.severity == severity).count()
}

fn plural(n: usize, word: &str) -> String {
    if n == 1 {
        format!("1 {word}")
    } else {
        format!("{n} {word}s")
    }
}

/// The last line of a run: `error: could not check: 3 errors, 1 warning`, or
/// `warning: 2 warnings emitted`, or nothing when there is nothing to say.
pub fn summary(verb: &str, errors: usize, warnings: usize, color: bool) -> Option<String> {
    if errors > 0 {
        let mut counts = plural(errors, "error");
        if warnings > 0 {
            counts.push_str(", ");
            counts.push_str(&plural(warnings, "warning"));
        }
        Some(format!(
            "{}: could not {verb}: {counts}\n",
            term::paint("error", 31, color)
        ))
    } else if warnings > 0 {
        Some(format!(
            "{}: {} emitted\n",
            term::paint("warning", 33, color),
            plural(warnings, "warning")
        ))
    } else {
        None
    }
}

/// Reports a command line that cannot be acted on; returns [`Exit::Usage`].
pub fn usage_error(message: &str, color: bool) -> Exit {
    term::eprint(&format!("{}: {message}\n", term::paint("error", 31, color)));
    Exit::Usage
}

/// Reports an internal compiler error (a panic that escaped a command). `detail` is the panic's
/// message and location, and its backtrace when `RUST_BACKTRACE` asked for one.
pub fn ice(detail: &str, color: bool) {
    let backtrace_hint = if std::env::var_os("RUST_BACKTRACE").is_some_and(|v| v != "0") {
        ""
    } else {
        "note: run with `RUST_BACKTRACE=1` for a backtrace\n"
    };
    term::eprint(&format!(
        "{}: internal compiler error: {detail}\n\
         note: this is a bug in rtc {}, not in your program; please report it with the input that \
         triggered it\n{backtrace_hint}",
        term::paint("error[ICE]", 31, color),
        env!("CARGO_PKG_VERSION"),
    ));
}

#[cfg(test)]
mod tests {
    use super::summary;

    #[test]
    fn summary_like_cargo() {
        assert_eq!(summary("check", 0, 0, false), None);
        assert_eq!(
            summary("check", 3, 1, false).as_deref(),
            Some("error: could not check: 3 errors, 1 warning\n")
        );
        assert_eq!(
            summary("check", 1, 0, false).as_deref(),
            Some("error: could not check: 1 error\n")
        );
        assert_eq!(
            summary("check", 0, 2, false).as_deref(),
            Some("warning: 2 warnings emitted\n")
        );
        assert_eq!(
            summary("check", 2, 0, true).as_deref(),
            Some("\x1b[1;31merror\x1b[0m: could not check: 2 errors\n")
        );
    }
}
