//! Writing to the terminal: whether to use colour, and writes that survive a closed pipe.
//!
//! `rtc check … | head` must not turn into an internal error: a write to a closed stdout or stderr is
//! dropped silently instead of panicking the way `println!` would.

use crate::args::ColorChoice;
use std::io::{IsTerminal, Write};

/// Whether to colour what goes to stderr.
pub fn use_color(choice: ColorChoice) -> bool {
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => {
            let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
            !no_color && std::io::stderr().is_terminal()
        }
    }
}

/// Writes `text` to stderr as is.
pub fn eprint(text: &str) {
    let mut err = std::io::stderr().lock();
    let _ = err.write_all(text.as_bytes());
    let _ = err.flush();
}

/// Writes `text` to stdout as is.
pub fn print(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes());
    let _ = out.flush();
}

/// `word` in bold and the given ANSI colour (`31` red, `33` yellow) when `color` is set.
pub fn paint(word: &str, ansi: u8, color: bool) -> String {
    if color {
        format!("\x1b[1;{ansi}m{word}\x1b[0m")
    } else {
        word.to_owned()
    }
}
