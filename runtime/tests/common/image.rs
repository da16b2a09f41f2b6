//! Image assertions: compare a rendered image, pixel by pixel and channel by channel, with expected
//! values and a stated tolerance, and fail with the figures that matter.
//!
//! A channel passes when `|got − want| <= abs + rel · |want|` ([`Tolerance`]); a NaN never passes.
//! [`PixelCheck`] collects every comparison, then [`PixelCheck::assert`] fails when more channels are
//! over than allowed (none unless [`PixelCheck::allow_over`] says otherwise), and the message states
//! the tolerance, how many channels were checked and over, the worst absolute and relative errors
//! (relative to `|want|`; the absolute error where `want` is 0) and where, and the first few
//! failures with their values.

use std::fmt::Write as _;

/// The sRGB transfer function, decoding (IEC 61966-2-1), in `f64`: the independent reference the
/// texture tests compare the kernel's and the runtime's decodings with.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// How far a value may be from its expectation: `abs + rel · |want|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Absolute part.
    pub abs: f64,
    /// Part relative to the expected value.
    pub rel: f64,
}

impl Tolerance {
    /// Exactly equal.
    pub const EXACT: Tolerance = Tolerance { abs: 0.0, rel: 0.0 };

    /// Within `abs`.
    pub fn abs(abs: f64) -> Tolerance {
        Tolerance { abs, rel: 0.0 }
    }

    /// Within `rel` of the expected value.
    pub fn rel(rel: f64) -> Tolerance {
        Tolerance { abs: 0.0, rel }
    }

    /// The largest allowed difference from `want`.
    pub fn allowed(&self, want: f64) -> f64 {
        self.abs + self.rel * want.abs()
    }
}

/// One failed channel comparison.
#[derive(Clone, Debug)]
struct Miss {
    pixel: (u32, u32),
    channel: usize,
    got: f64,
    want: f64,
    allowed: f64,
}

/// A running comparison of pixels with their expectations (see the module docs).
#[derive(Clone, Debug)]
pub struct PixelCheck {
    what: String,
    checked: usize,
    max_over: usize,
    misses: Vec<Miss>,
    over: usize,
    worst_abs: (f64, (u32, u32), usize),
    worst_rel: (f64, (u32, u32), usize),
}

/// How many failures the message lists.
const LISTED: usize = 8;

impl PixelCheck {
    /// A check named `what` (printed in the failure message) that allows no channel over.
    pub fn new(what: impl Into<String>) -> PixelCheck {
        PixelCheck {
            what: what.into(),
            checked: 0,
            max_over: 0,
            misses: Vec::new(),
            over: 0,
            worst_abs: (0.0, (0, 0), 0),
            worst_rel: (0.0, (0, 0), 0),
        }
    }

    /// Allows up to `count` channels over their tolerance.
    pub fn allow_over(mut self, count: usize) -> PixelCheck {
        self.max_over = count;
        self
    }

    /// Compares channel `channel` of pixel `(x, y)`: `got` against `want` within `tol`.
    pub fn channel(
        &mut self,
        (x, y): (u32, u32),
        channel: usize,
        got: f64,
        want: f64,
        tol: Tolerance,
    ) {
        self.checked += 1;
        let diff = (got - want).abs();
        let rel = if want == 0.0 { diff } else { diff / want.abs() };
        if diff > self.worst_abs.0 || diff.is_nan() {
            self.worst_abs = (diff, (x, y), channel);
        }
        if rel > self.worst_rel.0 || rel.is_nan() {
            self.worst_rel = (rel, (x, y), channel);
        }
        let allowed = tol.allowed(want);
        // A NaN on either side fails.
        let within = diff <= allowed;
        if !within {
            self.over += 1;
            if self.misses.len() < LISTED {
                self.misses.push(Miss {
                    pixel: (x, y),
                    channel,
                    got,
                    want,
                    allowed,
                });
            }
        }
    }

    /// Compares the first `want.len()` channels of pixel `(x, y)` with `want`, each within `tol`.
    pub fn pixel(&mut self, at: (u32, u32), got: [f32; 4], want: &[f64], tol: Tolerance) {
        for (c, w) in want.iter().enumerate() {
            self.channel(at, c, f64::from(got[c]), *w, tol);
        }
    }

    /// How many channels were compared.
    pub fn checked(&self) -> usize {
        self.checked
    }

    /// Fails unless at most the allowed number of channels were over their tolerance.
    pub fn assert(&self) {
        if self.over <= self.max_over {
            return;
        }
        let mut msg = format!(
            "{}: {} of {} channels over their tolerance ({} allowed); worst absolute error {:e} at \
             pixel {:?} channel {}, worst relative error {:e} at pixel {:?} channel {}",
            self.what,
            self.over,
            self.checked,
            self.max_over,
            self.worst_abs.0,
            self.worst_abs.1,
            self.worst_abs.2,
            self.worst_rel.0,
            self.worst_rel.1,
            self.worst_rel.2,
        );
        for m in &self.misses {
            let _ = write!(
                msg,
                "\n  pixel {:?} channel {}: got {}, want {} (allowed difference {:e})",
                m.pixel, m.channel, m.got, m.want, m.allowed
            );
        }
        panic!("{msg}");
    }
}
