//! Robustness: the lexer, parser and checker never panic, hang or overflow the stack, whatever the
//! input. (cargo-fuzz needs a nightly toolchain that the project does not require, so this is a
//! time-bounded random test on stable instead, with the same kinds of input a fuzzer would try.)
//!
//! Each test runs its inputs in a **child process** (this same test binary, re-run with
//! `RTC_FUZZ_CHILD=<mode>`), because a stack overflow aborts the whole process and cannot be caught.
//! In the child, every input is checked on a thread with an 8 MiB stack and a per-input timeout; a
//! panic or timeout ends the child with a message. Before each input the child writes it to a scratch
//! file, so when the child dies in any way the parent copies that input to
//! `tests/fuzz/artifacts/<mode>-<hash>.rt` (git-ignored), prints its path and fails. Reproduce with
//! `cargo run -p rtc -- check tests/fuzz/artifacts/<file>`.
//!
//! - `random_inputs`: for `RTC_FUZZ_SECONDS` seconds (default 5; CI sets 60) cycles through random
//!   bytes (as lossy text through `check_text`, and as raw bytes, invalid UTF-8 included, through a
//!   file and `check_paths`), token soups of the language's tokens and keywords, randomly nested
//!   constructs, and mutations of every stdlib, example, UI and spec file (byte flips, deletions,
//!   duplications, insertions, splices between files, truncation). `RTC_FUZZ_SEED` fixes the seed
//!   (printed on failure); `RTC_FUZZ_TIMEOUT` sets the per-input timeout in seconds (default 5).
//! - Fixed degenerate inputs, each in bounded time: 100,000 nested parentheses, 100,000 unary minuses,
//!   100,000 nested blocks (all must end in diagnostics, e.g. E0202, not a crash), a 10 MB file of
//!   valid code (must check without errors) and 10 MB of random bytes and of random text.
//!
//! Run longer with `RTC_FUZZ_SECONDS=600 cargo test -p rtc-tests --release --test fuzz -- --nocapture`.

use rtc_compiler::driver::{check_paths, check_text, Checked, Options};
use rtc_tests::fuzzgen::{self, Feed, Rng};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const CHILD_ENV: &str = "RTC_FUZZ_CHILD";
const WORK_ENV: &str = "RTC_FUZZ_WORK";
const SEED_ENV: &str = "RTC_FUZZ_SEED";
/// The depth of the fixed nesting cases.
const DEPTH: usize = 100_000;
/// The size of the fixed big files.
const BIG: usize = 10 << 20;

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(default)
}

fn fuzz_seconds() -> u64 {
    env_u64("RTC_FUZZ_SECONDS", 5)
}

fn input_timeout() -> Duration {
    Duration::from_secs(env_u64("RTC_FUZZ_TIMEOUT", 5))
}

// ---------------------------------------------------------------------------------------------
// The tests (parents)

#[test]
fn random_inputs() {
    let secs = fuzz_seconds();
    parent(
        "random",
        Duration::from_secs(secs + 2 * input_timeout().as_secs() + 60),
    );
}

#[test]
fn deep_parentheses() {
    parent("deep_parens", Duration::from_secs(120));
}

#[test]
fn deep_unary_minus() {
    parent("deep_unary", Duration::from_secs(120));
}

#[test]
fn deep_blocks() {
    parent("deep_blocks", Duration::from_secs(120));
}

#[test]
fn big_valid_file() {
    parent("big_valid", Duration::from_secs(300));
}

#[test]
fn big_random_files() {
    parent("big_random", Duration::from_secs(300));
}

/// The harness itself catches what it must: a stack overflow, a panic and a hang each fail the run
/// and save the input.
#[test]
fn harness_catches_overflow_panic_and_hang() {
    let dir = std::env::temp_dir().join(format!("rtc-fuzz-selftest-{}", std::process::id()));
    let cases = [
        ("selftest_overflow", "killed by signal"),
        ("selftest_panic", "found a panic"),
        ("selftest_hang", "took too long"),
    ];
    for (mode, expect) in cases {
        let result = run_child(
            mode,
            Duration::from_secs(60),
            &dir,
            &[("RTC_FUZZ_TIMEOUT", "1")],
        );
        let failure = result.expect_err(mode);
        eprintln!("{failure}\n");
        assert!(failure.contains(expect), "{mode}: {failure}");
        assert!(failure.contains("is saved in"), "{mode}: {failure}");
    }
    let saved = std::fs::read_dir(&dir).map(|d| d.count()).unwrap_or(0);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(saved >= 1, "no artifact saved");
}

/// The entry point of the child process; does nothing when run as an ordinary test.
#[test]
fn child_process_entry_point() {
    if let Ok(mode) = std::env::var(CHILD_ENV) {
        child(&mode);
    }
}

/// Runs `mode` in a child process and fails (saving the input it died on) unless it exits cleanly
/// within `limit`.
fn parent(mode: &str, limit: Duration) {
    let artifacts = rtc_tests::paths::repo_root().join("tests/fuzz/artifacts");
    match run_child(mode, limit, &artifacts, &[]) {
        Ok(summary) => eprintln!("{summary}"),
        Err(failure) => panic!("{failure}"),
    }
}

/// Runs `mode` in a child process with the extra environment `env`. Returns the child's summary
/// lines, or a failure report (after saving the input it died on under `artifacts`).
fn run_child(
    mode: &str,
    limit: Duration,
    artifacts: &Path,
    env: &[(&str, &str)],
) -> Result<String, String> {
    let work = std::env::temp_dir().join(format!("rtc-fuzz-{}-{mode}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).expect("create a scratch folder");
    let seed = std::env::var(SEED_ENV)
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map(|d| d.as_nanos() as u64)
                .unwrap_or(1)
        });
    let out_path = work.join("child.out");
    let out = std::fs::File::create(&out_path).expect("create the child's log");
    let err = out.try_clone().expect("share the child's log");
    let exe = std::env::current_exe().expect("find the test binary");
    let started = Instant::now();
    let mut child = Command::new(exe)
        .args([
            "child_process_entry_point",
            "--exact",
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD_ENV, mode)
        .env(WORK_ENV, &work)
        .env(SEED_ENV, seed.to_string())
        .envs(env.iter().copied())
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err)
        .spawn()
        .expect("start the child process");
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if started.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => panic!("waiting for the child failed: {e}"),
        }
    };
    let log = std::fs::read_to_string(&out_path).unwrap_or_default();
    // libtest may print "test child_process_entry_point ... " before the child's first line.
    let summary: Vec<&str> = log
        .lines()
        .filter_map(|l| l.find("fuzz: ").map(|at| &l[at..]))
        .collect();
    if status.is_some_and(|s| s.success()) {
        let _ = std::fs::remove_dir_all(&work);
        return Ok(summary.join("\n"));
    }
    let how = match status {
        None => format!("did not finish within {limit:?} and was killed"),
        Some(s) => describe_exit(s),
    };
    let artifact = save_artifact(mode, &work.join("current.rt"), artifacts);
    let tail: String = {
        let chars: Vec<char> = log.chars().collect();
        chars[chars.len().saturating_sub(6000)..].iter().collect()
    };
    let _ = std::fs::remove_dir_all(&work);
    Err(format!(
        "fuzz mode `{mode}` (seed {seed}): the child process {how}.\n{artifact}\n\
         reproduce the run with RTC_FUZZ_SEED={seed}; the child's output ends with:\n{tail}"
    ))
}

fn describe_exit(status: std::process::ExitStatus) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            let name = match sig {
                6 => " (SIGABRT: a stack overflow or an abort)",
                9 => " (SIGKILL: out of memory?)",
                11 => " (SIGSEGV)",
                _ => "",
            };
            return format!("was killed by signal {sig}{name}");
        }
    }
    match status.code() {
        Some(3) => "found a panic".to_owned(),
        Some(4) => "found an input that took too long".to_owned(),
        Some(c) => format!("exited with code {c}"),
        None => "ended abnormally".to_owned(),
    }
}

/// Copies the input the child was working on to `dir`; returns a line saying where.
fn save_artifact(mode: &str, current: &Path, dir: &Path) -> String {
    let Ok(bytes) = std::fs::read(current) else {
        return "(no input was being checked, so nothing was saved)".to_owned();
    };
    // FNV-1a, to name the file after its content.
    let hash = bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    let path = dir.join(format!("{mode}-{hash:016x}.rt"));
    match std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&path, &bytes)) {
        Ok(()) => format!(
            "the input ({} bytes) is saved in {}; try `cargo run -p rtc -- check {}`",
            bytes.len(),
            path.display(),
            rtc_tests::paths::display_relative(&path)
        ),
        Err(e) => format!("could not save the input to {}: {e}", path.display()),
    }
}

// ---------------------------------------------------------------------------------------------
// The child

/// Runs the inputs of `mode`. Exits the process with 3 on a panic, 4 on a timeout.
fn child(mode: &str) {
    let work = PathBuf::from(std::env::var(WORK_ENV).unwrap_or_else(|_| ".".into()));
    let seed = env_u64(SEED_ENV, 1);
    let mut runner = Runner {
        current: work.join("current.rt"),
        options: Options::default(),
        fault: match mode {
            "selftest_overflow" => Some(Fault::Overflow),
            "selftest_panic" => Some(Fault::Panic),
            "selftest_hang" => Some(Fault::Hang),
            _ => None,
        },
    };
    let mut rng = Rng::new(seed);
    let long = Duration::from_secs(60);
    match mode {
        "random" => random(&mut runner, &mut rng, Duration::from_secs(fuzz_seconds())),
        "deep_parens" => runner.fixed(mode, Feed::Text(fuzzgen::deep_parens(DEPTH)), long, false),
        "deep_unary" => runner.fixed(mode, Feed::Text(fuzzgen::deep_unary(DEPTH)), long, false),
        "deep_blocks" => runner.fixed(mode, Feed::Text(fuzzgen::deep_blocks(DEPTH)), long, false),
        "big_valid" => {
            let long = Duration::from_secs(240);
            runner.fixed(mode, Feed::Text(fuzzgen::big_valid(BIG)), long, true);
        }
        "big_random" => {
            let long = Duration::from_secs(120);
            let bytes = fuzzgen::big_random(&mut rng, BIG);
            runner.fixed("big_random (bytes)", Feed::Bytes(bytes), long, false);
            let text = fuzzgen::big_random_text(&mut rng, BIG);
            runner.fixed("big_random (text)", Feed::Text(text), long, false);
        }
        _ if runner.fault.is_some() => {
            runner.fixed(
                mode,
                Feed::Text("fn f() {}".to_owned()),
                input_timeout(),
                false,
            );
        }
        other => {
            eprintln!("unknown fuzz mode {other}");
            std::process::exit(2);
        }
    }
}

struct Runner {
    /// The scratch file holding the input being checked (the parent saves it if the child dies).
    current: PathBuf,
    options: Options,
    /// A failure to inject instead of checking, to test this harness itself.
    fault: Option<Fault>,
}

/// The failures the harness must catch, injected by the `selftest_*` modes.
#[derive(Clone, Copy, Debug)]
enum Fault {
    Overflow,
    Panic,
    Hang,
}

impl Fault {
    fn trigger(self) -> Checked {
        match self {
            Fault::Overflow => {
                fn deeper(n: u64) -> u64 {
                    let pad = std::hint::black_box([n; 64]);
                    if pad[1] == u64::MAX {
                        return 0;
                    }
                    deeper(pad[1] + 1) + pad[0]
                }
                std::hint::black_box(deeper(0));
                Checked::default()
            }
            #[allow(clippy::panic)]
            Fault::Panic => panic!("injected by the self-test"),
            Fault::Hang => loop {
                std::thread::sleep(Duration::from_secs(1));
            },
        }
    }
}

impl Runner {
    /// Checks one input on an 8 MiB stack; exits the process on a panic or when `timeout` passes.
    fn run(&mut self, what: &str, feed: Feed, timeout: Duration) -> Checked {
        if let Err(e) = std::fs::write(&self.current, feed.bytes()) {
            eprintln!("cannot write {}: {e}", self.current.display());
            std::process::exit(2);
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let options = self.options.clone();
        let path = self.current.clone();
        let fault = self.fault;
        let spawned = std::thread::Builder::new()
            .stack_size(rtc_tests::CHECK_STACK)
            .spawn(move || {
                let result = std::panic::catch_unwind(move || match (fault, feed) {
                    (Some(fault), _) => fault.trigger(),
                    (None, Feed::Text(text)) => check_text("fuzz.rt", &text, &options),
                    (None, Feed::Bytes(_)) => check_paths(&[path], &options),
                });
                let _ = tx.send(result.map_err(|p| rtc_tests::panic_message(&*p)));
            });
        if let Err(e) = spawned {
            eprintln!("cannot spawn a checker thread: {e}");
            std::process::exit(2);
        }
        match rx.recv_timeout(timeout) {
            Ok(Ok(checked)) => checked,
            Ok(Err(panic)) => {
                eprintln!("fuzz: {what}: the checker {panic}");
                std::process::exit(3);
            }
            Err(_) => {
                eprintln!("fuzz: {what}: no result after {timeout:?}");
                std::process::exit(4);
            }
        }
    }

    /// Runs one fixed input and prints its time; `must_pass` inputs must check without errors.
    fn fixed(&mut self, what: &str, feed: Feed, timeout: Duration, must_pass: bool) {
        let len = feed.bytes().len();
        let started = Instant::now();
        let checked = self.run(what, feed, timeout);
        let (errors, warnings) = rtc_tests::counts(&checked);
        let first: Vec<&str> = checked
            .diagnostics
            .iter()
            .take(3)
            .map(|d| d.code.0)
            .collect();
        println!(
            "fuzz: {what}: {len} bytes checked in {:.2?}: {errors} errors, {warnings} warnings \
             (first codes {first:?})",
            started.elapsed()
        );
        if must_pass && errors > 0 {
            let shown = rtc_tests::render::render_list(
                &checked.sources,
                &checked.diagnostics[..checked.diagnostics.len().min(5)],
            );
            eprintln!("fuzz: {what}: valid code reported errors:\n{shown}");
            std::process::exit(5);
        }
    }
}

/// Random inputs for `budget`, cycling through the generators.
fn random(runner: &mut Runner, rng: &mut Rng, budget: Duration) {
    let corpus = fuzzgen::corpus();
    let timeout = input_timeout();
    let started = Instant::now();
    let names = [
        "bytes as text",
        "raw bytes",
        "token soup",
        "deep mix",
        "mutation",
        "raw mutation",
    ];
    let mut counts = [0usize; 6];
    let mut slowest = (Duration::ZERO, "");
    let mut i = 0;
    while started.elapsed() < budget {
        let kind = i % names.len();
        i += 1;
        let feed = match kind {
            0 => {
                Feed::Text(String::from_utf8_lossy(&fuzzgen::random_bytes(rng, 8192)).into_owned())
            }
            1 => Feed::Bytes(fuzzgen::random_bytes(rng, 8192)),
            2 => Feed::Text(fuzzgen::token_soup(rng, 2000)),
            3 => Feed::Text(fuzzgen::deep_mix(rng, 3000)),
            _ if corpus.is_empty() => Feed::Text(fuzzgen::token_soup(rng, 200)),
            4 => {
                let base = &rng.pick(&corpus).1;
                let bytes = fuzzgen::mutate(rng, base, &corpus);
                Feed::Text(String::from_utf8_lossy(&bytes).into_owned())
            }
            _ => {
                let base = &rng.pick(&corpus).1;
                Feed::Bytes(fuzzgen::mutate(rng, base, &corpus))
            }
        };
        let one = Instant::now();
        runner.run(names[kind], feed, timeout);
        if one.elapsed() > slowest.0 {
            slowest = (one.elapsed(), names[kind]);
        }
        counts[kind] += 1;
    }
    let total: usize = counts.iter().sum();
    let per_kind: Vec<String> = names
        .iter()
        .zip(counts)
        .map(|(n, c)| format!("{c} {n}"))
        .collect();
    println!(
        "fuzz: random: {total} inputs in {:.1?} ({}); corpus of {} files; slowest input {:.2?} ({})",
        started.elapsed(),
        per_kind.join(", "),
        corpus.len(),
        slowest.0,
        slowest.1
    );
}
