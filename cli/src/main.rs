//! The `rtc` command line.
fn main() {}
