//! The stdlib suite: every `.rt` file under `stdlib/` and `examples/` checks without errors, each as
//! the root of its own compilation (so each file's imports are complete on their own); and all stdlib
//! files together as the roots of one compilation (so they do not clash when a program imports several).

use rtc_compiler::driver::{check_paths, Options};
use rtc_tests::paths::{display_relative, stdlib_and_examples};
use rtc_tests::render::render_relative;

#[test]
fn every_stdlib_and_example_file_checks() {
    let files = stdlib_and_examples();
    assert!(!files.is_empty(), "no .rt files under stdlib/");
    let mut failures = Vec::new();
    let mut roots = vec![];
    for file in &files {
        roots.push(vec![file.clone()]);
    }
    let stdlib_dir = rtc_tests::paths::repo_root().join("stdlib");
    roots.push(
        files
            .iter()
            .filter(|f| f.starts_with(&stdlib_dir))
            .cloned()
            .collect(),
    );
    for set in roots {
        let what = if set.len() == 1 {
            display_relative(&set[0])
        } else {
            format!("all {} stdlib files together", set.len())
        };
        let options = Options::default();
        let result =
            rtc_tests::run_with_stack(rtc_tests::CHECK_STACK, move || check_paths(&set, &options));
        match result {
            Ok(checked) if checked.has_errors() => {
                failures.push(format!("{what}: has errors\n{}", render_relative(&checked)))
            }
            Ok(_) => {}
            Err(panic) => failures.push(format!("{what}: the checker {panic}")),
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n\n{}",
        failures.len(),
        failures.join("\n")
    );
}
