//! The UI suite: every case under `tests/ui/` is checked, its diagnostics are compared with its golden
//! `.stderr` file and with the `//~ CODE` annotations in its source (see `rtc_tests::ui` for the
//! layout and the rules). All failing cases are listed together, with a unified diff for each golden
//! mismatch.
//!
//! - `RTC_BLESS=1 cargo test -p rtc-tests --test ui` rewrites the golden files (annotations are still
//!   checked: they are written by hand).
//! - `RTC_UI_FILTER=types/` runs only the cases whose name contains the text.
//!
//! A second test requires at least one case for every code of `codes::ALL` except `ICE`, `E0901` and
//! `E0902` (which need a linked scene or assets), and prints the codes that have none.

use rtc_compiler::diag::codes;
use rtc_compiler::driver::Options;
use rtc_tests::paths::repo_root;
use rtc_tests::ui::{annotated_codes, discover, run_case};

#[test]
fn ui_cases() {
    let ui_dir = repo_root().join("tests/ui");
    let (cases, problems) = discover(&ui_dir);
    let filter = std::env::var("RTC_UI_FILTER").unwrap_or_default();
    let options = Options::default();
    let mut report = String::new();
    let mut failed = 0;
    let mut ran = 0;
    for case in cases.iter().filter(|c| c.name.contains(&filter)) {
        ran += 1;
        let failures = run_case(case, &options);
        if !failures.is_empty() {
            failed += 1;
            report.push_str(&format!(
                "\n---- {} ({}) ----\n",
                case.name,
                rtc_tests::paths::display_relative(&case.root)
            ));
            for f in failures {
                report.push_str(&f);
                if !f.ends_with('\n') {
                    report.push('\n');
                }
            }
        }
    }
    for p in &problems {
        report.push_str(&format!("layout: {p}\n"));
    }
    eprintln!("ui: {ran} cases, {failed} failing");
    assert!(
        failed == 0 && problems.is_empty(),
        "{failed} of {ran} UI cases failed, {} layout problems:\n{report}",
        problems.len()
    );
}

#[test]
fn every_code_has_a_ui_case() {
    let (cases, _) = discover(&repo_root().join("tests/ui"));
    let covered = annotated_codes(&cases);
    // Codes that `check` cannot produce: they come from compiling or loading one scene, and
    // cli/tests/cli.rs covers them through `rtc compile` (ICE has its own CLI test); E0806 comes
    // from a target's writer (tests/limits.rs and `back`'s unit tests).
    let exempt = [
        codes::ICE,
        codes::E0706,
        codes::E0806,
        codes::E0901,
        codes::E0902,
        codes::E0903,
    ];
    let missing: Vec<String> = codes::ALL
        .iter()
        .filter(|(code, _)| !exempt.contains(code) && !covered.contains_key(code.0))
        .map(|(code, summary)| format!("  {} {summary}", code.0))
        .collect();
    assert!(
        missing.is_empty(),
        "{} codes have no UI case annotated with them (add tests/ui/<category>/<name>.rt with \
         `//~ CODE`):\n{}",
        missing.len(),
        missing.join("\n")
    );
}
