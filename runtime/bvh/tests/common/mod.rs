//! Test fixtures shared by the integration tests: small meshes generated in code (a sphere, a
//! random soup with slivers, a miniature of the thesis scene), the optional decimated bunny from
//! `shared/models`, a seeded random number generator and ray generators.
//!
//! Invariant: everything here is deterministic (fixed seeds) and small enough for debug-mode
//! tests that finish in seconds; big meshes stay in the benchmark.

#![allow(dead_code)]

use std::path::PathBuf;

use glam::Vec3;
use rtc_bvh::traverse::Ray;

/// xorshift64* — deterministic and dependency-free.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `[0, 1)`.
    pub fn f32(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.f32()
    }

    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    pub fn vec3(&mut self, lo: Vec3, hi: Vec3) -> Vec3 {
        Vec3::new(
            self.range(lo.x, hi.x),
            self.range(lo.y, hi.y),
            self.range(lo.z, hi.z),
        )
    }

    /// A random direction (not normalised).
    pub fn dir(&mut self) -> Vec3 {
        loop {
            let d = self.vec3(Vec3::splat(-1.0), Vec3::splat(1.0));
            if d.length_squared() > 1e-4 {
                return d;
            }
        }
    }
}

/// A UV sphere.
pub fn sphere(center: Vec3, radius: f32, stacks: u32, slices: u32) -> Vec<[Vec3; 3]> {
    let p = |i: u32, j: u32| {
        let th = std::f32::consts::PI * i as f32 / stacks as f32;
        let ph = 2.0 * std::f32::consts::PI * j as f32 / slices as f32;
        center + radius * Vec3::new(th.sin() * ph.cos(), th.cos(), th.sin() * ph.sin())
    };
    let mut tris = Vec::new();
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if i != 0 {
                tris.push([a, b, d]);
            }
            if i + 1 != stacks {
                tris.push([b, c, d]);
            }
        }
    }
    tris
}

/// Random small triangles in the unit cube, plus a few long slivers crossing it (the case
/// spatial splits are for).
pub fn soup(n: usize, seed: u64) -> Vec<[Vec3; 3]> {
    let mut rng = Rng::new(seed);
    let mut tris = Vec::with_capacity(n + 8);
    for _ in 0..n {
        let c = rng.vec3(Vec3::ZERO, Vec3::ONE);
        let s = 0.05;
        tris.push([
            c,
            c + rng.vec3(Vec3::splat(-s), Vec3::splat(s)),
            c + rng.vec3(Vec3::splat(-s), Vec3::splat(s)),
        ]);
    }
    for _ in 0..8 {
        let a = rng.vec3(Vec3::ZERO, Vec3::ONE);
        let b = rng.vec3(Vec3::ZERO, Vec3::ONE);
        tris.push([a, b, b + Vec3::splat(0.01)]);
    }
    tris
}

/// A miniature thesis scene: a 20x20 floor quad (2 triangles) at y = 0 with 4x3 spheres
/// standing on it.
pub fn thesis_like() -> Vec<[Vec3; 3]> {
    let h = 10.0;
    let (a, b, c, d) = (
        Vec3::new(-h, 0.0, -h),
        Vec3::new(h, 0.0, -h),
        Vec3::new(h, 0.0, h),
        Vec3::new(-h, 0.0, h),
    );
    let mut tris = vec![[a, b, c], [a, c, d]];
    for i in 0..4 {
        for k in 0..3 {
            let center = Vec3::new(-0.4 + 0.25 * i as f32, 0.1, -0.3 + 0.25 * k as f32);
            tris.extend(sphere(center, 0.1, 8, 12));
        }
    }
    tris
}

/// `shared/models/bunny-6k.obj` as a triangle soup, or `None` (with a message) when the models
/// folder is not there.
pub fn bunny_6k() -> Option<Vec<[Vec3; 3]>> {
    let path = std::env::var_os("RTC_MODELS")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/models"))
        .join("bunny-6k.obj");
    if !path.exists() {
        println!("skipping bunny-6k: {} not found", path.display());
        return None;
    }
    let (models, _) = tobj::load_obj(&path, &tobj::GPU_LOAD_OPTIONS).ok()?;
    let mut tris = Vec::new();
    for m in models {
        let v: Vec<Vec3> = m
            .mesh
            .positions
            .chunks_exact(3)
            .map(|p| Vec3::new(p[0], p[1], p[2]))
            .collect();
        tris.extend(
            m.mesh
                .indices
                .chunks_exact(3)
                .map(|t| [v[t[0] as usize], v[t[1] as usize], v[t[2] as usize]]),
        );
    }
    Some(tris)
}

/// Box of the triangles.
pub fn bounds(tris: &[[Vec3; 3]]) -> (Vec3, Vec3) {
    tris.iter().flatten().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    )
}

/// `n` rays of four kinds: random origin and direction; aimed at a random point of a random
/// triangle; axis-aligned (zero direction components) from a vertex coordinate; and grazing
/// along the plane of a vertex.
pub fn rays(tris: &[[Vec3; 3]], n: usize, seed: u64) -> Vec<Ray> {
    let mut rng = Rng::new(seed);
    let (lo, hi) = bounds(tris);
    let pad = (hi - lo).max(Vec3::splat(1e-3)) * 0.5;
    let (olo, ohi) = (lo - pad, hi + pad);
    let axes = [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z];
    (0..n)
        .map(|i| match i % 4 {
            0 => Ray::new(rng.vec3(olo, ohi), rng.dir()),
            1 => {
                let t = tris[rng.below(tris.len())];
                let (u, v) = (rng.f32(), rng.f32());
                let (u, v) = if u + v > 1.0 {
                    (1.0 - u, 1.0 - v)
                } else {
                    (u, v)
                };
                let target = t[0] + (t[1] - t[0]) * u + (t[2] - t[0]) * v;
                let o = rng.vec3(olo, ohi);
                Ray::new(o, target - o)
            }
            2 => {
                // Axis-aligned through a vertex coordinate: exercises zero direction components
                // and origins on slab boundaries.
                let d = axes[rng.below(6)];
                let v = tris[rng.below(tris.len())][rng.below(3)];
                let mut o = rng.vec3(olo, ohi);
                for a in 0..3 {
                    if d[a] == 0.0 && rng.f32() < 0.5 {
                        o[a] = v[a];
                    }
                }
                Ray::new(o, d)
            }
            _ => {
                // In the plane y = vertex.y (flat boxes, edge-on triangles).
                let v = tris[rng.below(tris.len())][rng.below(3)];
                let mut o = rng.vec3(olo, ohi);
                o.y = v.y;
                let mut d = rng.dir();
                d.y = 0.0;
                if d.length_squared() == 0.0 {
                    d = Vec3::X;
                }
                Ray {
                    origin: o,
                    dir: d,
                    tmin: rng.range(0.0, 0.1),
                    tmax: rng.range(0.5, 40.0),
                }
            }
        })
        .collect()
}
