//! The process exit codes of `rtc`, in one place (see the crate docs for what each means).

/// How a command ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// Nothing wrong (warnings allowed): 0.
    Success,
    /// Errors in the user's files, or a failure to do what was asked: 1.
    Failure,
    /// The command line cannot be acted on: 2 (the code clap uses for bad arguments).
    Usage,
    /// An internal compiler error, i.e. a bug in rtc: 101 (the code of a Rust panic).
    Ice,
}

impl Exit {
    /// The numeric exit code.
    pub fn code(self) -> u8 {
        match self {
            Exit::Success => 0,
            Exit::Failure => 1,
            Exit::Usage => 2,
            Exit::Ice => 101,
        }
    }
}

impl From<Exit> for std::process::ExitCode {
    fn from(exit: Exit) -> std::process::ExitCode {
        std::process::ExitCode::from(exit.code())
    }
}
