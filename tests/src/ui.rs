//! UI cases: programs that must fail in a given way, with inline expectations and golden output.
//!
//! Layout (under `tests/ui/`):
//! - `<category>/<name>.rt` is a case; its golden output is `<category>/<name>.stderr`.
//! - `<category>/<case>/main.rt` (a folder with a `main.rt`) is a multi-file case: `main.rt` is the
//!   root, the other files are reached by its imports; the golden output is `<case>/main.stderr`.
//!
//! Annotations: a comment `//~ E0401` at the end of a line expects a diagnostic with that code whose
//! primary span starts on that line; `//~^ E0401` expects it one line above, `//~^^` two above, and
//! so on. Several codes may follow one marker (`//~ E0401 E0303`, commas allowed); every word after
//! the marker must be a known code from `codes::ALL` (warnings `W…` included). Annotations may sit in
//! any `.rt` file of a case.
//!
//! Invariants checked for every case: it has at least one annotation (a UI case without an error is a
//! mistake); every error and warning the checker reports is annotated, and every annotation is matched
//! by exactly one reported diagnostic (notes are not annotated); the diagnostics, rendered without
//! colour and with repository-relative file names (see [`crate::render`]), equal the golden file.

use crate::paths::{files_with_extension, relative_to_root};
use crate::render::{primary_location, relative_map, render_relative};
use rtc_compiler::driver::{check_paths, Options};
use rtc_compiler::Severity;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One UI case.
#[derive(Clone, Debug)]
pub struct Case {
    /// `category/name`, for messages.
    pub name: String,
    /// The root file given to the checker.
    pub root: PathBuf,
    /// Every `.rt` file of the case (annotations may be in any of them).
    pub files: Vec<PathBuf>,
    /// The golden file with the rendered diagnostics.
    pub golden: PathBuf,
}

/// Finds every case under `ui_dir`, sorted by name. The second list holds layout problems (a folder
/// without `main.rt`, a golden file without a case, a case outside a category folder).
pub fn discover(ui_dir: &Path) -> (Vec<Case>, Vec<String>) {
    let mut cases = Vec::new();
    let mut problems = Vec::new();
    let mut goldens_used = Vec::new();
    for category in sorted_entries(ui_dir) {
        if !category.is_dir() {
            if category
                .extension()
                .is_some_and(|e| e == "rt" || e == "stderr")
            {
                problems.push(format!(
                    "{}: UI files belong in a category folder, tests/ui/<category>/",
                    rel(&category)
                ));
            }
            continue;
        }
        let cat_name = file_name(&category);
        for entry in sorted_entries(&category) {
            let name = format!("{cat_name}/{}", file_name(&entry));
            if entry.is_dir() {
                let main = entry.join("main.rt");
                if main.is_file() {
                    let golden = entry.join("main.stderr");
                    goldens_used.push(golden.clone());
                    cases.push(Case {
                        name,
                        root: main,
                        files: files_with_extension(&entry, "rt"),
                        golden,
                    });
                } else {
                    problems.push(format!(
                        "{}: a multi-file case needs a main.rt",
                        rel(&entry)
                    ));
                }
            } else if entry.extension().is_some_and(|e| e == "rt") {
                let golden = entry.with_extension("stderr");
                goldens_used.push(golden.clone());
                cases.push(Case {
                    name: name.trim_end_matches(".rt").to_owned(),
                    root: entry.clone(),
                    files: vec![entry],
                    golden,
                });
            }
        }
    }
    for golden in files_with_extension(ui_dir, "stderr") {
        if !goldens_used.contains(&golden) {
            problems.push(format!(
                "{}: golden file without a case (delete it, or add its .rt)",
                rel(&golden)
            ));
        }
    }
    (cases, problems)
}

fn sorted_entries(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| rd.flatten().map(|e| e.path()).collect())
        .unwrap_or_default();
    v.sort();
    v
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

fn rel(p: &Path) -> String {
    crate::paths::display_relative(p)
}

/// An expected diagnostic: `code` with its primary span starting on `line` of `file`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Expected {
    /// The file, relative to the repository root.
    pub file: String,
    /// 1-based line the diagnostic must start on.
    pub line: usize,
    /// The code, e.g. `E0401`.
    pub code: String,
}

/// A reported error or warning, located as [`Expected`] is.
#[derive(Clone, Debug)]
pub struct Reported {
    /// The file (its name in the relative source map).
    pub file: String,
    /// 1-based line of the primary span's start.
    pub line: usize,
    /// The code.
    pub code: String,
    /// The headline, to help read mismatches.
    pub message: String,
}

/// The annotations of one file's text: `(line, code)` pairs, or messages for malformed ones.
pub fn parse_annotations(text: &str) -> (Vec<(usize, String)>, Vec<String>) {
    let known: Vec<&str> = rtc_compiler::diag::codes::ALL
        .iter()
        .map(|(c, _)| c.0)
        .collect();
    let mut found = Vec::new();
    let mut errors = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let written_on = index + 1;
        let Some(at) = line.find("//~") else {
            continue;
        };
        let rest = &line[at + 3..];
        let up = rest.chars().take_while(|&c| c == '^').count();
        let words: Vec<&str> = rest[up..]
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .collect();
        if up >= written_on {
            errors.push(format!(
                "line {written_on}: `//~{}` points above the first line",
                "^".repeat(up)
            ));
            continue;
        }
        if words.is_empty() {
            errors.push(format!("line {written_on}: `//~` without a code"));
        }
        for w in words {
            if known.contains(&w) {
                found.push((written_on - up, w.to_owned()));
            } else {
                errors.push(format!(
                    "line {written_on}: `{w}` after `//~` is not a diagnostic code of codes::ALL"
                ));
            }
        }
    }
    (found, errors)
}

/// Matches annotations against reports; returns one message per mismatch (empty when all agree).
pub fn compare(expected: &[Expected], reported: &[Reported]) -> Vec<String> {
    let mut unmatched: Vec<Option<&Reported>> = reported.iter().map(Some).collect();
    let mut missing = Vec::new();
    for e in expected {
        let hit = unmatched
            .iter_mut()
            .find(|r| r.is_some_and(|r| r.file == e.file && r.line == e.line && r.code == e.code));
        match hit {
            Some(slot) => *slot = None,
            None => missing.push(e),
        }
    }
    let mut out = Vec::new();
    for e in missing {
        let on_line: Vec<String> = reported
            .iter()
            .filter(|r| r.file == e.file && r.line == e.line)
            .map(|r| r.code.clone())
            .collect();
        let got = if on_line.is_empty() {
            "nothing on this line".to_owned()
        } else {
            format!("{} on this line", on_line.join(", "))
        };
        out.push(format!(
            "{}:{}: expected {}, got {got}",
            e.file, e.line, e.code
        ));
    }
    for r in unmatched.into_iter().flatten() {
        out.push(format!(
            "{}:{}: unexpected {} `{}` (not annotated: add `//~ {}` on that line)",
            r.file, r.line, r.code, r.message, r.code
        ));
    }
    out
}

/// Reads a case's annotations, checks its root and compares; returns every failure message.
pub fn run_case(case: &Case, options: &Options) -> Vec<String> {
    let mut failures = Vec::new();
    let mut expected = Vec::new();
    for file in &case.files {
        let bytes = match std::fs::read(file) {
            Ok(b) => b,
            Err(e) => {
                failures.push(format!("cannot read {}: {e}", rel(file)));
                continue;
            }
        };
        let name = relative_to_root(file).unwrap_or_else(|| rel(file));
        let (found, errors) = parse_annotations(&String::from_utf8_lossy(&bytes));
        failures.extend(errors.into_iter().map(|e| format!("{name}: {e}")));
        expected.extend(found.into_iter().map(|(line, code)| Expected {
            file: name.clone(),
            line,
            code,
        }));
    }
    if expected.is_empty() && failures.is_empty() {
        failures.push(
            "no `//~ CODE` annotation: a UI case must expect at least one diagnostic".to_owned(),
        );
    }
    expected.sort();

    let root = case.root.clone();
    let opts = options.clone();
    let checked =
        match crate::run_with_stack(crate::CHECK_STACK, move || check_paths(&[root], &opts)) {
            Ok(c) => c,
            Err(panic) => {
                failures.push(format!("the checker {panic}"));
                return failures;
            }
        };
    let map = relative_map(&checked.sources);
    let reported: Vec<Reported> = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity != Severity::Note)
        .map(|d| {
            let (file, line) = primary_location(&map, d);
            Reported {
                file,
                line,
                code: d.code.0.to_owned(),
                message: d.message.clone(),
            }
        })
        .collect();
    failures.extend(compare(&expected, &reported));
    if let Some(diff) = crate::golden::check_golden(&case.golden, &render_relative(&checked)) {
        failures.push(diff);
    }
    failures
}

/// For every code, the cases whose annotations expect it.
pub fn annotated_codes(cases: &[Case]) -> BTreeMap<String, Vec<String>> {
    let mut map: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for case in cases {
        for file in &case.files {
            let text =
                String::from_utf8_lossy(&std::fs::read(file).unwrap_or_default()).into_owned();
            for (_, code) in parse_annotations(&text).0 {
                let users = map.entry(code).or_default();
                if !users.contains(&case.name) {
                    users.push(case.name.clone());
                }
            }
        }
    }
    map
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn annotations_point_at_lines() {
        let text = "let a = 1; //~ E0401\nfoo();\n//~^ W0002, E0303\n\n//~^^ E0101\n";
        let (found, errors) = parse_annotations(text);
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(
            found,
            [
                (1, "E0401".to_owned()),
                (2, "W0002".to_owned()),
                (2, "E0303".to_owned()),
                (3, "E0101".to_owned())
            ]
        );
    }

    #[test]
    fn malformed_annotations_are_reported() {
        let (found, errors) = parse_annotations("//~^ E0401\nx //~ E401\ny //~\n");
        assert!(found.is_empty());
        assert_eq!(errors.len(), 3, "{errors:?}");
        assert!(errors[0].contains("above the first line"));
        assert!(errors[1].contains("`E401`"));
        assert!(errors[2].contains("without a code"));
    }

    #[test]
    fn compare_reports_both_directions() {
        let exp = |line, code: &str| Expected {
            file: "a.rt".into(),
            line,
            code: code.into(),
        };
        let rep = |line, code: &str| Reported {
            file: "a.rt".into(),
            line,
            code: code.into(),
            message: "m".into(),
        };
        assert!(compare(&[exp(1, "E0401")], &[rep(1, "E0401")]).is_empty());
        let out = compare(
            &[exp(1, "E0401"), exp(2, "E0303")],
            &[rep(1, "E0402"), rep(1, "E0401"), rep(1, "E0401")],
        );
        assert_eq!(
            out,
            [
                "a.rt:2: expected E0303, got nothing on this line",
                "a.rt:1: unexpected E0402 `m` (not annotated: add `//~ E0402` on that line)",
                "a.rt:1: unexpected E0401 `m` (not annotated: add `//~ E0401` on that line)",
            ]
        );
    }
}
