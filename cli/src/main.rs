//! The `rtc` command line: parses the arguments, runs one subcommand, and turns its outcome into an
//! exit code. This binary is the only place in the workspace that prints.
//!
//! Exit codes (documented in `spec/diagnostics.md`):
//! - `0`: success (warnings allowed);
//! - `1`: errors in the user's files (diagnostics were printed);
//! - `2`: a usage error of the command line (clap's own code for bad arguments, kept for ours too);
//! - `101`: an internal compiler error. The command runs on a worker thread inside
//!   [`std::panic::catch_unwind`]; a panic that escapes the compiler (always a bug: user mistakes are
//!   diagnostics) is reported as `error[ICE]` and asks for a bug report. It is the last resort, never
//!   the way a user error is reported; `cli/tests/cli.rs` checks that bad inputs do not get there.
//!
//! Layout: [`args`] holds the clap definitions shared by all subcommands, [`cmd`] one module per
//! subcommand, [`report`] prints diagnostics and the summary line, [`term`] decides on colour and
//! writes to the terminal.

mod args;
mod cmd;
mod exit;
mod report;
mod term;

use clap::Parser;
use exit::Exit;
use std::panic::{self, AssertUnwindSafe};
use std::process::ExitCode;
use std::sync::{Arc, Mutex};

/// Stack size of the thread that runs a command. The compiler caps its own recursion (and the fuzz
/// test checks it within 8 MiB); the extra room is a safety margin, not a requirement.
const WORKER_STACK: usize = 64 << 20;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        // `--help` and `--version` exit with 0, bad arguments with 2 (after printing the usage).
        Err(e) => e.exit(),
    };
    // Before any other thread or GPU instance exists: lavapipe reads these when it loads. A
    // render whose JIT depends on its compiled scene applies them itself, before its GPU work.
    if let Some(jit) = cli.command.cpu_jit().filter(|_| cli.command.uses_gpu()) {
        rtc_runtime::gpu::apply_lavapipe_defaults(jit, cli.command.known_samples());
    }
    run_guarded(cli).into()
}

/// Runs the command on a worker thread, turning a panic into an internal compiler error.
fn run_guarded(cli: args::Cli) -> Exit {
    let panic_info: Arc<Mutex<Option<String>>> = Arc::default();
    let hook_info = Arc::clone(&panic_info);
    panic::set_hook(Box::new(move |info| {
        let message = payload_text(info.payload());
        let location = info
            .location()
            .map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()))
            .unwrap_or_else(|| "unknown location".to_owned());
        let backtrace = match std::env::var_os("RUST_BACKTRACE") {
            Some(v) if v != "0" => format!("\n{}", std::backtrace::Backtrace::force_capture()),
            _ => String::new(),
        };
        if let Ok(mut slot) = hook_info.lock() {
            *slot = Some(format!("{message}\n  --> {location}{backtrace}"));
        }
    }));

    let color = term::use_color(cli.global.color);
    let worker = std::thread::Builder::new()
        .name("rtc".to_owned())
        .stack_size(WORKER_STACK)
        .spawn(move || panic::catch_unwind(AssertUnwindSafe(|| cmd::run(cli))));
    let outcome = match worker {
        Ok(handle) => handle.join(),
        Err(e) => {
            term::eprint(&format!("error: cannot start the worker thread: {e}\n"));
            return Exit::Failure;
        }
    };
    match outcome {
        Ok(Ok(exit)) => exit,
        Ok(Err(payload)) | Err(payload) => {
            let detail = panic_info
                .lock()
                .ok()
                .and_then(|mut slot| slot.take())
                .unwrap_or_else(|| payload_text(payload.as_ref()));
            report::ice(&detail, color);
            Exit::Ice
        }
    }
}

/// The message of a panic payload (`&str` or `String`; anything else is unknown).
fn payload_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".to_owned()
    }
}
