//! `rtc render --frames/--fps/--shard`: which frames of a scene's animation this process renders,
//! and where each goes (docs/animation.md).
//!
//! Everything here is parsed and checked before anything is compiled; a bad value is a usage
//! error with a message, never a panic. The frames of a shard are a pure function of the range
//! and the shard, so `N` processes with shards `0/N` … `N-1/N` render every frame exactly once.

use std::path::{Path, PathBuf};

/// `--frames`: which frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameRange {
    /// `all`: frames 0 to the scene's `frames` − 1.
    All,
    /// Frames `start` to `end` − 1.
    Span {
        /// The first frame.
        start: u32,
        /// One past the last frame.
        end: u32,
    },
}

/// The environment variables `--shard auto/N` reads its index from, in order: Kubernetes
/// Indexed Jobs, then Slurm job arrays.
pub const SHARD_ENV: [&str; 2] = ["JOB_COMPLETION_INDEX", "SLURM_ARRAY_TASK_ID"];

/// `--shard I/N`: every `count`-th frame of the range, starting at its `index`-th.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// `I`, below `count`.
    pub index: u32,
    /// `N`, at least 1.
    pub count: u32,
}

/// Parses `--frames`: `A..B` (A to B−1), `A..=B` (A to B), `N` (one frame) or `all`.
pub fn parse_frames(text: &str) -> Result<FrameRange, String> {
    let text = text.trim();
    if text == "all" {
        return Ok(FrameRange::All);
    }
    let number = |s: &str| -> Result<u32, String> {
        s.trim().parse::<u32>().map_err(|_| {
            format!("--frames `{text}`: `{s}` is not a frame number (a whole number from 0)")
        })
    };
    let (start, end) = if let Some((a, b)) = text.split_once("..=") {
        let end = number(b)?
            .checked_add(1)
            .ok_or_else(|| format!("--frames `{text}`: the last frame is too large"))?;
        (number(a)?, end)
    } else if let Some((a, b)) = text.split_once("..") {
        (number(a)?, number(b)?)
    } else {
        let n = number(text)?;
        (n, n.saturating_add(1))
    };
    if end <= start {
        return Err(format!(
            "--frames `{text}` holds no frame: the end must be after the start (`A..B` is A to \
             B-1, `A..=B` is A to B)"
        ));
    }
    Ok(FrameRange::Span { start, end })
}

/// Parses `--shard I/N` (`I` may be `auto`: read from [`SHARD_ENV`] through `env`).
pub fn parse_shard(text: &str, env: &dyn Fn(&str) -> Option<String>) -> Result<Shard, String> {
    let Some((i, n)) = text.split_once('/') else {
        return Err(format!(
            "--shard `{text}`: write `I/N` (this process renders frames I, I+N, I+2N, …), or \
             `auto/N`"
        ));
    };
    let count: u32 = n
        .trim()
        .parse()
        .map_err(|_| format!("--shard `{text}`: `{n}` is not a shard count"))?;
    if count == 0 {
        return Err(format!(
            "--shard `{text}`: the shard count must be at least 1"
        ));
    }
    let (index_text, from) = if i.trim() == "auto" {
        match SHARD_ENV.iter().find_map(|v| env(v).map(|x| (x, *v))) {
            Some((x, v)) => (x, Some(v)),
            None => {
                return Err(format!(
                    "--shard `{text}`: neither {} is set (set by Kubernetes Indexed Jobs and \
                     Slurm job arrays); give the index, as in `--shard 0/{count}`",
                    SHARD_ENV.join(" nor ")
                ))
            }
        }
    } else {
        (i.to_string(), None)
    };
    let shown = match from {
        Some(v) => format!("{v}={index_text}"),
        None => format!("`{index_text}`"),
    };
    let index: u32 = index_text
        .trim()
        .parse()
        .map_err(|_| format!("--shard `{text}`: {shown} is not a shard index"))?;
    if index >= count {
        return Err(format!(
            "--shard `{text}`: the index {shown} must be below the count {count} (shards are \
             numbered from 0)"
        ));
    }
    Ok(Shard { index, count })
}

/// The frames of `start..end` that `shard` renders, in order.
pub fn shard_frames(start: u32, end: u32, shard: Shard) -> Vec<u32> {
    (start..end)
        .skip(shard.index as usize)
        .step_by(shard.count as usize)
        .collect()
}

/// Where `%d` or `%0Nd` is in a file name pattern: (byte start, byte end, width).
fn placeholder(name: &str) -> Option<(usize, usize, usize)> {
    let at = name.find('%')?;
    let rest = &name[at + 1..];
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    if !rest[digits.len()..].starts_with('d') {
        return None;
    }
    let width = digits.parse().unwrap_or(0);
    Some((at, at + 1 + digits.len() + 1, width))
}

/// Whether `path`'s file name has a frame-number placeholder (`%d`, `%04d`).
pub fn has_placeholder(path: &Path) -> bool {
    path.file_name()
        .and_then(|n| n.to_str())
        .and_then(placeholder)
        .is_some()
}

/// `path` with its placeholder replaced by `frame` (as is when it has none).
pub fn frame_path(path: &Path, frame: u32) -> PathBuf {
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
        return path.to_path_buf();
    };
    match placeholder(name) {
        Some((a, b, width)) => {
            let file = format!("{}{frame:0width$}{}", &name[..a], &name[b..]);
            path.with_file_name(file)
        }
        None => path.to_path_buf(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_ranges() {
        assert_eq!(
            parse_frames("0..24"),
            Ok(FrameRange::Span { start: 0, end: 24 })
        );
        assert_eq!(
            parse_frames("3..=5"),
            Ok(FrameRange::Span { start: 3, end: 6 })
        );
        assert_eq!(parse_frames("7"), Ok(FrameRange::Span { start: 7, end: 8 }));
        assert_eq!(parse_frames("all"), Ok(FrameRange::All));
        for bad in [
            "5..2",
            "4..4",
            "a..3",
            "-1..3",
            "",
            "1..2..3",
            "0..=4294967295",
        ] {
            assert!(parse_frames(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn shards() {
        let none = |_: &str| None;
        assert_eq!(parse_shard("1/3", &none), Ok(Shard { index: 1, count: 3 }));
        for bad in ["3/3", "0/0", "1", "x/2", "1/y", "auto/2"] {
            assert!(parse_shard(bad, &none).is_err(), "{bad}");
        }
        let k8s = |v: &str| (v == "JOB_COMPLETION_INDEX").then(|| "2".to_string());
        assert_eq!(
            parse_shard("auto/4", &k8s),
            Ok(Shard { index: 2, count: 4 })
        );
        let slurm = |v: &str| (v == "SLURM_ARRAY_TASK_ID").then(|| "5".to_string());
        let e = parse_shard("auto/4", &slurm).unwrap_err();
        assert!(e.contains("SLURM_ARRAY_TASK_ID=5"), "{e}");
        // Every frame exactly once over the shards.
        let mut all: Vec<u32> = (0..3)
            .flat_map(|i| shard_frames(2, 12, Shard { index: i, count: 3 }))
            .collect();
        all.sort();
        assert_eq!(all, (2..12).collect::<Vec<_>>());
        assert_eq!(shard_frames(2, 12, Shard { index: 1, count: 3 }), [3, 6, 9]);
    }

    #[test]
    fn paths() {
        let p = Path::new("out/frame_%04d.png");
        assert!(has_placeholder(p));
        assert_eq!(frame_path(p, 7), Path::new("out/frame_0007.png"));
        assert_eq!(frame_path(Path::new("f%d.png"), 12), Path::new("f12.png"));
        assert!(!has_placeholder(Path::new("out%/a.png")));
        assert!(!has_placeholder(Path::new("a%x.png")));
        assert_eq!(frame_path(Path::new("a.png"), 3), Path::new("a.png"));
    }
}
