//! Inputs for differential tests: a seeded generator, edge values, and argument lists that start with
//! combinations of edge values and continue with random draws.
//!
//! Invariant: the same seed gives the same inputs on every machine (splitmix64, no global state).

use super::{Args, Sc};

/// A small seeded random number generator (splitmix64).
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator with this seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    /// 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// 32 random bits.
    pub fn u32(&mut self) -> u32 {
        (self.next_u64() >> 32) as u32
    }
    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
    /// A float in `[0, 1)`.
    pub fn unit(&mut self) -> f32 {
        (self.u32() >> 8) as f32 / (1u32 << 24) as f32
    }
    /// A float in `[lo, hi)`.
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
    /// A finite float of any magnitude from 1e-30 to 1e30, either sign (log-uniform).
    pub fn wide(&mut self) -> f32 {
        let mag = 10f32.powf(self.range(-30.0, 30.0));
        if self.u32() & 1 == 0 {
            mag
        } else {
            -mag
        }
    }
    /// Any float: random bits (including NaNs, infinities and denormals, rarely).
    pub fn bits_f32(&mut self) -> f32 {
        f32::from_bits(self.u32())
    }
}

/// Float edge values: zeros, ones, infinities, NaN, denormals, the extremes.
pub const F32_EDGES: &[f32] = &[
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    -0.5,
    2.0,
    -3.0,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::NAN,
    f32::MIN_POSITIVE,
    -f32::MIN_POSITIVE,
    1.0e-40,
    -1.0e-40,
    1.4e-45,
    f32::MAX,
    f32::MIN,
    f32::EPSILON,
    std::f32::consts::PI,
    -std::f32::consts::FRAC_PI_2,
    1.0e10,
    -1.0e-10,
];

/// `i32` edge values.
pub const I32_EDGES: &[i32] = &[
    0,
    1,
    -1,
    2,
    -2,
    7,
    -7,
    31,
    32,
    33,
    i32::MIN,
    i32::MAX,
    i32::MIN + 1,
    i32::MAX - 1,
    65536,
    -65536,
];

/// `u32` edge values.
pub const U32_EDGES: &[u32] = &[
    0,
    1,
    2,
    7,
    31,
    32,
    33,
    0x8000_0000,
    0x7fff_ffff,
    u32::MAX,
    u32::MAX - 1,
    65536,
];

/// How to draw one parameter: its component count, its edge values, and a random draw.
pub struct Param<'a> {
    /// Components (1 for scalars).
    pub width: usize,
    /// Edge values tried first (in combination with the other parameters' edges).
    pub edges: Vec<Sc>,
    /// A random component.
    pub draw: Box<dyn FnMut(&mut Rng) -> Sc + 'a>,
}

/// Any `f32`: edges, then a mix of wide-range values, values in `[-4, 4]` and random bit patterns.
pub fn any_f32(width: usize) -> Param<'static> {
    Param {
        width,
        edges: F32_EDGES.iter().map(|v| Sc::F(*v)).collect(),
        draw: Box::new(|r: &mut Rng| {
            Sc::F(match r.below(10) {
                0 => r.bits_f32(),
                1..=4 => r.wide(),
                _ => r.range(-4.0, 4.0),
            })
        }),
    }
}

/// A finite `f32` in `[lo, hi]`: the edges inside the range and the bounds, then uniform values.
pub fn f32_in(width: usize, lo: f32, hi: f32) -> Param<'static> {
    let mut edges: Vec<Sc> = F32_EDGES
        .iter()
        .copied()
        .filter(|v| (lo..=hi).contains(v))
        .map(Sc::F)
        .collect();
    edges.extend([Sc::F(lo), Sc::F(hi)]);
    Param {
        width,
        edges,
        draw: Box::new(move |r: &mut Rng| Sc::F(r.range(lo, hi))),
    }
}

/// Any `i32`: edges, then small values and random bits.
pub fn any_i32(width: usize) -> Param<'static> {
    Param {
        width,
        edges: I32_EDGES.iter().map(|v| Sc::I(*v)).collect(),
        draw: Box::new(|r: &mut Rng| {
            Sc::I(if r.below(2) == 0 {
                r.range(-100.0, 100.0) as i32
            } else {
                r.u32() as i32
            })
        }),
    }
}

/// Any `u32`: edges, then small values and random bits.
pub fn any_u32(width: usize) -> Param<'static> {
    Param {
        width,
        edges: U32_EDGES.iter().map(|v| Sc::U(*v)).collect(),
        draw: Box::new(|r: &mut Rng| {
            Sc::U(if r.below(2) == 0 {
                r.below(200) as u32
            } else {
                r.u32()
            })
        }),
    }
}

/// Any `bool`.
pub fn any_bool(width: usize) -> Param<'static> {
    Param {
        width,
        edges: vec![Sc::B(false), Sc::B(true)],
        draw: Box::new(|r: &mut Rng| Sc::B(r.u32() & 1 == 1)),
    }
}

/// A parameter whose whole value is drawn at once (unit vectors, matrices, structs): `draw` returns
/// all `width` components; no edges.
pub fn whole<'a>(width: usize, mut draw: impl FnMut(&mut Rng) -> Vec<Sc> + 'a) -> Param<'a> {
    // Components are drawn one at a time; the closure refills a buffer of one whole value.
    let mut buf: Vec<Sc> = Vec::new();
    Param {
        width,
        edges: Vec::new(),
        draw: Box::new(move |r: &mut Rng| {
            if buf.is_empty() {
                buf = draw(r);
                buf.reverse();
            }
            buf.pop().unwrap_or(Sc::F(0.0))
        }),
    }
}

/// `n` argument lists for `params` (at least `n`, at most `n` plus the edge combinations): first
/// every combination of edge values (capped at 4096, vector components rotating through the edges),
/// then random draws.
pub fn args(seed: u64, n: usize, mut params: Vec<Param<'_>>) -> Vec<Args> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(n);
    if params.iter().all(|p| !p.edges.is_empty()) {
        let total: usize = params.iter().map(|p| p.edges.len()).product();
        for k in 0..total.min(4096) {
            let mut rest = k;
            let mut a = Vec::with_capacity(params.len());
            for p in &params {
                let i = rest % p.edges.len();
                rest /= p.edges.len();
                a.push(
                    (0..p.width)
                        .map(|c| p.edges[(i + c * 5) % p.edges.len()])
                        .collect(),
                );
            }
            out.push(a);
        }
    }
    let target = n.max(out.len() + n / 4);
    while out.len() < target {
        let a = params
            .iter_mut()
            .map(|p| (0..p.width).map(|_| (p.draw)(&mut rng)).collect())
            .collect();
        out.push(a);
    }
    out
}

/// A scalar parameter drawn by `draw`, without edges.
pub fn one<'a>(draw: impl FnMut(&mut Rng) -> Sc + 'a) -> Param<'a> {
    Param {
        width: 1,
        edges: Vec::new(),
        draw: Box::new(draw),
    }
}
