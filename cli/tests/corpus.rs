//! The malformed-input corpus (`tests/corpus/`): hundreds of bad and extreme inputs given to the
//! `rtc` binary as a user would give them, each with its expected diagnostic.
//!
//! Layout: `tests/corpus/<category>/` holds the cases of one kind of input (`sources`, `scenes`,
//! `gltf`, `images`, `meshes`, `cli`). A case is either
//! - a single file `<name>.rt`, run as `rtc check <name>.rt`, with its golden output in
//!   `<name>.expected`; or
//! - a folder `<name>/` with an `args` file (one line of whitespace-separated arguments to `rtc`;
//!   lines starting with `#` are comments) and the input files it names, with its golden output in
//!   `<name>/expected`.
//!
//! Each case runs in a scratch copy of its file or folder (so outputs never land in the
//! repository), without colour, with a time limit of [`CASE_TIMEOUT`]. The golden output is the exit
//! code and standard error, with the scratch folder's path written as `$CASE` and durations
//! (`12.3 ms`, `4 s`) as `<time>`; standard output is not compared (it holds the adapter's name and
//! timings on render commands). `RTC_BLESS=1` writes the goldens anew; `RTC_CORPUS_FILTER=gltf/`
//! runs only the cases whose name contains the text.
//!
//! Invariants checked for every case, whatever its golden says: the process ended by itself within
//! the time limit, not by a signal, not with the internal-error exit code 101, and printed no panic
//! or "internal compiler error"; and its standard error is not empty unless it succeeded. For every
//! case that `rtc check` accepts (exit code 0: warnings at most), `rtc compile` must also succeed
//! for all five targets, so nothing the checker accepts becomes an internal error later.
//!
//! Cases that render need a GPU adapter; where the machine has none at all, those cases are
//! skipped, saying so on stderr (lavapipe provides one on CI).

mod common;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The longest a case may run.
const CASE_TIMEOUT: Duration = Duration::from_secs(120);

/// One corpus case.
struct Case {
    /// `category/name`.
    name: String,
    /// The file or folder copied into the scratch folder.
    source: PathBuf,
    /// The arguments given to `rtc`, relative to the scratch folder.
    args: Vec<String>,
    /// The golden output.
    golden: PathBuf,
}

/// What one run printed and how it ended.
struct Run {
    /// The exit code, or `None` when a signal ended the process.
    code: Option<i32>,
    stderr: String,
    timed_out: bool,
}

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/corpus")
}

fn sorted(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    v.sort();
    v
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Every case under `tests/corpus`, and the layout problems found (a folder without `args`, a
/// golden without a case, a file that is neither).
fn discover() -> (Vec<Case>, Vec<String>) {
    let mut cases = Vec::new();
    let mut problems = Vec::new();
    for category in sorted(&corpus_dir()) {
        if !category.is_dir() {
            if !matches!(file_name(&category).as_str(), "README.md" | "generate.py") {
                problems.push(format!("{}: not in a category folder", category.display()));
            }
            continue;
        }
        let cat = file_name(&category);
        for entry in sorted(&category) {
            let fname = file_name(&entry);
            if entry.is_dir() {
                let args_file = entry.join("args");
                let Ok(text) = std::fs::read_to_string(&args_file) else {
                    problems.push(format!("{cat}/{fname}: a folder case needs an `args` file"));
                    continue;
                };
                let args: Vec<String> = text
                    .lines()
                    .filter(|l| !l.trim_start().starts_with('#'))
                    .flat_map(|l| l.split_whitespace())
                    .map(str::to_owned)
                    .collect();
                if args.is_empty() {
                    problems.push(format!("{cat}/{fname}: `args` is empty"));
                    continue;
                }
                cases.push(Case {
                    name: format!("{cat}/{fname}"),
                    source: entry.clone(),
                    args,
                    golden: entry.join("expected"),
                });
            } else if fname.ends_with(".rt") {
                cases.push(Case {
                    name: format!("{cat}/{fname}"),
                    source: entry.clone(),
                    args: vec!["check".into(), fname.clone()],
                    golden: entry.with_extension("expected"),
                });
            } else if fname.ends_with(".expected") {
                let rt = entry.with_extension("rt");
                if !rt.is_file() {
                    problems.push(format!("{cat}/{fname}: a golden file without its case"));
                }
            } else {
                problems.push(format!(
                    "{cat}/{fname}: neither a `.rt` case, its `.expected`, nor a case folder"
                ));
            }
        }
    }
    (cases, problems)
}

/// Copies `from` (a file or a folder) into `to` (an existing folder).
fn copy_into(from: &Path, to: &Path) {
    if from.is_dir() {
        for entry in sorted(from) {
            let dest = to.join(file_name(&entry));
            if entry.is_dir() {
                std::fs::create_dir_all(&dest).expect("create a folder");
                copy_into(&entry, &dest);
            } else {
                std::fs::copy(&entry, &dest).expect("copy a case file");
            }
        }
    } else {
        std::fs::copy(from, to.join(file_name(from))).expect("copy a case file");
    }
}

/// Runs `rtc args` in `dir` with the time limit.
fn run(dir: &Path, args: &[String]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(dir)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env("NO_COLOR", "1")
        .env_remove("RTC_STDLIB")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start rtc");
    // Read stderr on a thread so a chatty child never blocks on a full pipe.
    let mut err = child.stderr.take().expect("stderr pipe");
    let reader = std::thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = std::io::Read::read_to_end(&mut err, &mut buf);
        buf
    });
    let start = Instant::now();
    let (status, timed_out) = loop {
        match child.try_wait().expect("wait for rtc") {
            Some(status) => break (Some(status), false),
            None if start.elapsed() > CASE_TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                break (None, true);
            }
            None => std::thread::sleep(Duration::from_millis(20)),
        }
    };
    let stderr = String::from_utf8_lossy(&reader.join().unwrap_or_default()).into_owned();
    Run {
        code: status.and_then(|s| s.code()),
        stderr,
        timed_out,
    }
}

/// `text` with `dir` written as `$CASE` and durations as `<time>`.
fn normalise(text: &str, dir: &Path) -> String {
    let mut t = text.replace(&dir.display().to_string(), "$CASE");
    if let Ok(canon) = dir.canonicalize() {
        t = t.replace(&canon.display().to_string(), "$CASE");
    }
    // Durations: a number followed by ` ms` or ` s` (word-bounded).
    let mut out = String::with_capacity(t.len());
    let bytes = t.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let starts_number =
            bytes[i].is_ascii_digit() && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric());
        if starts_number {
            let mut j = i;
            while j < bytes.len() && (bytes[j].is_ascii_digit() || bytes[j] == b'.') {
                j += 1;
            }
            let rest = &t[j..];
            let unit = [" ms", " s"].into_iter().find(|u| {
                rest.starts_with(u)
                    && !rest[u.len()..]
                        .chars()
                        .next()
                        .is_some_and(|c| c.is_alphanumeric())
            });
            if let Some(u) = unit {
                out.push_str("<time>");
                i = j + u.len();
                continue;
            }
            out.push_str(&t[i..j]);
            i = j;
            continue;
        }
        let c = t[i..].chars().next().expect("a char");
        out.push(c);
        i += c.len_utf8();
    }
    out
}

/// The exit code as the golden files write it.
fn exit_text(code: Option<i32>) -> String {
    code.map_or("signal".to_owned(), |c| c.to_string())
}

/// Whether a run ended in an internal error: exit code 101 (a panic), or a panic or an internal
/// compiler error in what it printed.
fn is_internal_error(code: Option<i32>, stderr: &str) -> bool {
    code == Some(101)
        || stderr.contains("panicked")
        || stderr.contains("error[ICE]")
        || stderr.contains("internal compiler error")
}

fn needs_gpu(args: &[String]) -> bool {
    matches!(
        args.first().map(String::as_str),
        Some("render" | "bench" | "bvh" | "view" | "watch")
    )
}

/// Checks one case; returns its failures (empty when it passed) and whether it was skipped.
fn check_case(case: &Case) -> (Vec<String>, bool) {
    let scratch = std::env::temp_dir().join(format!(
        "rtc-corpus-{}-{}",
        std::process::id(),
        case.name.replace('/', "-")
    ));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).expect("create a scratch folder");
    copy_into(&case.source, &scratch);
    let r = run(&scratch, &case.args);
    let mut failures = Vec::new();
    let stderr = normalise(&r.stderr, &scratch);
    if needs_gpu(&case.args) && r.code == Some(1) && stderr.contains("no GPU adapter found") {
        eprintln!("SKIPPED {}: no GPU adapter at all", case.name);
        let _ = std::fs::remove_dir_all(&scratch);
        return (failures, true);
    }
    if r.timed_out {
        failures.push(format!("ran past {CASE_TIMEOUT:?}"));
    } else if r.code.is_none() {
        failures.push("ended by a signal (a crash or an abort)".into());
    }
    if is_internal_error(r.code, &stderr) {
        failures.push(format!("an internal error or panic:\n{stderr}"));
    }
    if r.code != Some(0) && stderr.trim().is_empty() {
        failures.push("failed without a word on stderr".into());
    }
    let mut actual = String::new();
    let _ = writeln!(actual, "exit: {}", exit_text(r.code));
    actual.push_str(&stderr);
    // Nothing `check` accepts may become an internal error in `compile`: every `.rt` root that
    // checks is compiled for all five targets, and how that ends is part of the golden output.
    let is_check = case.args.first().map(String::as_str) == Some("check");
    if is_check && r.code == Some(0) {
        for root in case.args[1..].iter().filter(|a| a.ends_with(".rt")) {
            let args: Vec<String> = ["compile", root, "-o", "rtc-out"].map(String::from).into();
            let c = run(&scratch, &args);
            let c_err = normalise(&c.stderr, &scratch);
            if c.timed_out || c.code.is_none() || is_internal_error(c.code, &c_err) {
                failures.push(format!(
                    "`rtc check` accepts it but `rtc compile` ended with {:?}:\n{c_err}",
                    c.code
                ));
            }
            let _ = writeln!(
                actual,
                "--- rtc compile {root}\nexit: {}",
                exit_text(c.code)
            );
            actual.push_str(&c_err);
        }
    }
    if let Some(e) = rtc_tests::golden::check_golden(&case.golden, &actual) {
        failures.push(e);
    }
    let _ = std::fs::remove_dir_all(&scratch);
    (failures, false)
}

#[test]
fn corpus() {
    let (cases, problems) = discover();
    assert!(
        problems.is_empty(),
        "corpus layout:\n{}",
        problems.join("\n")
    );
    let filter = std::env::var("RTC_CORPUS_FILTER").unwrap_or_default();
    let chosen: Vec<&Case> = cases.iter().filter(|c| c.name.contains(&filter)).collect();
    if filter.is_empty() {
        assert!(
            cases.len() >= 150,
            "the corpus has {} cases; it must keep at least 150",
            cases.len()
        );
    }
    // Two workers: the cases are independent processes, and CI has two cores.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(case) = chosen.get(i) else { break };
                let outcome = check_case(case);
                results.lock().expect("results").push((i, outcome));
            });
        }
    });
    let mut results = results.into_inner().expect("results");
    results.sort_by_key(|(i, _)| *i);
    let mut failed = Vec::new();
    let mut skipped = 0;
    for (i, (f, skip)) in results {
        skipped += usize::from(skip);
        if !f.is_empty() {
            failed.push(format!("--- {}\n{}", chosen[i].name, f.join("\n")));
        }
    }
    eprintln!(
        "corpus: {} cases, {} failed, {} skipped (no adapter)",
        chosen.len(),
        failed.len(),
        skipped
    );
    assert!(failed.is_empty(), "{}", failed.join("\n\n"));
}
