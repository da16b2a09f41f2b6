//! The spec suite: the language reference must say what the compiler does.
//!
//! - Every ` ```rt ` block of `spec/*.md` is checked with `check_text`, named `spec/<file>.md:<line>`
//!   (the line of its opening fence) so `std/…` imports resolve against the standard library: a plain
//!   `rt` block must check without errors, an `rt fail CODE` block must report `CODE` as its first
//!   error. Failures name the chapter and line of the block and show the diagnostics.
//! - `spec/diagnostics.md`'s table lists exactly the codes of `codes::ALL`, with the same summaries.

use rtc_compiler::diag::codes;
use rtc_compiler::driver::{check_text, Options};
use rtc_tests::paths::{display_relative, files_with_extension, repo_root};
use rtc_tests::spec::{code_table, extract, Expect};

#[test]
fn spec_code_blocks() {
    let options = Options::default();
    let mut failures = Vec::new();
    let mut count = 0;
    for md in files_with_extension(&repo_root().join("spec"), "md") {
        let name = display_relative(&md);
        let text = std::fs::read_to_string(&md).unwrap_or_default();
        let (blocks, errors) = extract(&name, &text);
        failures.extend(errors);
        for block in blocks {
            count += 1;
            let (block_name, code, opts) = (block.name(), block.code.clone(), options.clone());
            let result = rtc_tests::run_with_stack(rtc_tests::CHECK_STACK, move || {
                check_text(&block_name, &code, &opts)
            });
            let checked = match result {
                Ok(c) => c,
                Err(panic) => {
                    failures.push(format!("{}: the checker {panic}", block.name()));
                    continue;
                }
            };
            let first_error = checked.diagnostics.iter().find(|d| d.is_error());
            let problem = match (&block.expect, first_error) {
                (Expect::Ok, None) => None,
                (Expect::Ok, Some(_)) => {
                    Some("must check without errors, but reported:".to_owned())
                }
                (Expect::Fail(want), Some(d)) if d.code.0 == want => None,
                (Expect::Fail(want), Some(d)) => Some(format!(
                    "must fail with {want} first, but the first error is {}:",
                    d.code.0
                )),
                (Expect::Fail(want), None) => Some(format!(
                    "must fail with {want}, but checks without errors{}",
                    if checked.diagnostics.is_empty() {
                        ""
                    } else {
                        ":"
                    }
                )),
            };
            if let Some(problem) = problem {
                failures.push(format!(
                    "{} {problem}\n{}",
                    block.name(),
                    rtc_tests::render::render_relative(&checked)
                ));
            }
        }
    }
    assert!(count > 0, "no ```rt blocks found in spec/");
    assert!(
        failures.is_empty(),
        "{} of {count} spec blocks failed (blocks are named by their fence line; the line numbers of \
         their diagnostics count from the line after the fence):\n\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn diagnostics_table_matches_the_code_table() {
    let path = repo_root().join("spec/diagnostics.md");
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    let rows = code_table(&text);
    let mut problems = Vec::new();
    for (code, summary) in codes::ALL {
        let found: Vec<&(usize, String, String)> =
            rows.iter().filter(|(_, c, _)| c == code.0).collect();
        match found.as_slice() {
            [] => problems.push(format!(
                "{} is missing: add `| {} | {summary} |`",
                code.0, code.0
            )),
            [(line, _, s)] if s != summary => problems.push(format!(
                "spec/diagnostics.md:{line}: {} says `{s}`, codes.rs says `{summary}`",
                code.0
            )),
            [_] => {}
            many => problems.push(format!(
                "{} is listed {} times (lines {:?})",
                code.0,
                many.len(),
                many.iter().map(|r| r.0).collect::<Vec<_>>()
            )),
        }
    }
    for (line, code, _) in &rows {
        if !codes::ALL.iter().any(|(c, _)| c.0 == code) {
            problems.push(format!(
                "spec/diagnostics.md:{line}: {code} is not in codes::ALL"
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "spec/diagnostics.md and compiler/src/diag/codes.rs disagree:\n{}",
        problems.join("\n")
    );
}
