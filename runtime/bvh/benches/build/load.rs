//! A port of `benchlib.load_gate`: before a timing block, measure how many cores other
//! processes keep busy (from `/proc/stat` over an idle window of this process) and wait while
//! it is above a threshold, so that figures are taken on a quiet machine or marked as noisy.
//!
//! [`Window`] measures the same quantity *during* a timing block: busy time of the whole machine
//! (`/proc/stat`) minus this process's own CPU time (`/proc/self/stat`), both in clock ticks.
//!
//! Invariant: the gate only sleeps and reads `/proc`; on systems without it, it reports
//! "unknown" and never waits.

use std::time::Duration;

fn cpu_jiffies() -> Option<(u64, u64)> {
    let stat = std::fs::read_to_string("/proc/stat").ok()?;
    let line = stat.lines().next()?;
    let vals: Vec<u64> = line
        .split_whitespace()
        .skip(1)
        .take(8)
        .filter_map(|v| v.parse().ok())
        .collect();
    if vals.len() < 8 {
        return None;
    }
    let total: u64 = vals.iter().sum();
    let idle = vals[3] + vals[4];
    Some((total - idle, total))
}

/// Cores kept busy by other processes over a `window` in which this process only sleeps.
pub fn others_busy_cores(window: Duration) -> Option<f64> {
    let (b0, t0) = cpu_jiffies()?;
    std::thread::sleep(window);
    let (b1, t1) = cpu_jiffies()?;
    let ncpu = std::thread::available_parallelism().map_or(1, |n| n.get()) as f64;
    Some((b1 - b0) as f64 / (t1 - t0).max(1) as f64 * ncpu)
}

/// Waits (up to `tries` times `wait`) while others keep more than `threshold` cores busy.
/// Returns a short note for the report.
pub fn gate(label: &str, threshold: f64, tries: u32, wait: Duration) -> String {
    let mut busy = None;
    for i in 0..=tries {
        busy = others_busy_cores(Duration::from_secs(1));
        match busy {
            Some(b) if b > threshold && i < tries => {
                println!(
                    "[load] {label}: others busy {b:.2} cores; waiting {} s",
                    wait.as_secs()
                );
                std::thread::sleep(wait);
            }
            _ => break,
        }
    }
    match busy {
        Some(b) if b > threshold => format!("NOISY (others busy {b:.2} cores)"),
        Some(b) => format!("quiet (others busy {b:.2} cores)"),
        None => "load unknown".to_string(),
    }
}

/// This process's user + system CPU time in clock ticks.
fn own_jiffies() -> Option<u64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which is in parentheses and may hold spaces).
    let rest = stat.rsplit(')').next()?;
    let f: Vec<&str> = rest.split_whitespace().collect();
    Some(f.get(11)?.parse::<u64>().ok()? + f.get(12)?.parse::<u64>().ok()?)
}

/// A measurement window: how many cores other processes kept busy between [`Window::start`]
/// and [`Window::others_busy_cores`].
pub struct Window {
    start: Option<(u64, u64, u64)>,
}

impl Window {
    pub fn start() -> Self {
        let start = cpu_jiffies()
            .zip(own_jiffies())
            .map(|((b, t), o)| (b, t, o));
        Self { start }
    }

    pub fn others_busy_cores(&self) -> Option<f64> {
        let (b0, t0, o0) = self.start?;
        let (b1, t1) = cpu_jiffies()?;
        let o1 = own_jiffies()?;
        let ncpu = std::thread::available_parallelism().map_or(1, |n| n.get()) as f64;
        let others = (b1 - b0).saturating_sub(o1 - o0);
        Some(others as f64 / (t1 - t0).max(1) as f64 * ncpu)
    }
}
