//! Spatial splits for triangle input (SBVH: Stich, Friedrich, Dietrich 2009, "Spatial Splits
//! in Bounding Volume Hierarchies"). Where the best object split leaves two children that
//! overlap by more than a preset fraction of the root's area, the node is also split by planes
//! through space: a triangle that crosses the plane is clipped, and each side gets a reference
//! with the box of its part. This is what large triangles (the floor of the thesis scene, long
//! slivers, architectural walls) need: their boxes stop covering everything.
//!
//! # Method
//!
//! * [`find`] bins the references into `bins` equal slabs of the node box per axis. A reference
//!   that spans several slabs is clipped against each inner plane, and each slab gets the box of
//!   its part ("chopped binning"); entry and exit counters record where it starts and ends. A
//!   sweep then prices every plane; a plane is a candidate only if the references it would
//!   duplicate fit the node's duplication budget.
//! * [`apply`] distributes the references; one that straddles the chosen plane is either split
//!   or, if that is cheaper, kept whole on one side ("reference unsplitting", section 4.4 of the
//!   paper). The children's references go to new storage, left then right.
//!
//! # Invariants
//!
//! * **Conservative fragments.** A fragment's box holds the part of the triangle inside the
//!   reference's region and the half-space: vertices on the side, plus the plane crossings of
//!   the edges, each padded by a few ulps of the edge's coordinates against rounding in the
//!   interpolation, then intersected with the reference's box. So every point of a triangle lies
//!   in the box of some leaf that references it, and traversal finds every hit.
//! * Every child is non-empty (otherwise [`apply`] returns `None` and the node falls back to an
//!   object split), and a split never creates more extra references than the budget it is given.
//! * Binning and distribution use the same [`Grid`], so a reference counted as straddling while
//!   pricing is the one treated as straddling when applying.

use bytemuck::Zeroable;
use glam::{Vec3, Vec3A};
use rayon::prelude::*;

use crate::aabb::Aabb;
use crate::input::PrimRef;

use super::binned::MAX_BINS;
use super::split::{NodeInfo, Partition};

/// Nodes with at least this many references are binned in parallel.
const PAR_SPATIAL_MIN: usize = 1 << 15;

/// Chunk size of parallel spatial binning.
const PAR_SPATIAL_CHUNK: usize = 1 << 13;

/// Relative padding of a clipped edge point, in units of the larger endpoint magnitude (a few
/// ulps: the interpolation rounds at most a handful of times).
const CLIP_PAD: f32 = 8.0 * f32::EPSILON;

/// Settings and triangle access for spatial splits within one build.
pub(crate) struct SpatialCtx<'a> {
    /// Spatial splits are priced only where the children of the best object split overlap by
    /// more than this half area (`min_overlap` of the preset times the root's half area).
    pub min_overlap: f32,
    /// Slabs per axis.
    pub bins: usize,
    /// The triangle of an input index.
    pub triangle: &'a (dyn Fn(u32) -> Option<[Vec3; 3]> + Sync),
}

/// Equal slabs over a node box on each axis.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid {
    origin: Vec3A,
    width: Vec3A,
    inv: Vec3A,
    n: usize,
}

impl Grid {
    fn new(bounds: &Aabb, n: usize) -> Self {
        let extent = bounds.extent();
        let mut inv = Vec3A::ZERO;
        for axis in 0..3 {
            let s = n as f32 / extent[axis];
            if extent[axis] > 0.0 && s.is_finite() {
                inv[axis] = s;
            }
        }
        Self {
            origin: bounds.min,
            width: extent / n as f32,
            inv,
            n,
        }
    }

    fn usable(&self, axis: usize) -> bool {
        self.inv[axis] > 0.0
    }

    /// Slab holding coordinate `x` on `axis` (saturating).
    #[inline]
    fn bin(&self, x: f32, axis: usize) -> usize {
        (((x - self.origin[axis]) * self.inv[axis]) as usize).min(self.n - 1)
    }

    /// The plane between slab `k - 1` and slab `k`.
    #[inline]
    fn plane(&self, axis: usize, k: usize) -> f32 {
        self.origin[axis] + self.width[axis] * k as f32
    }
}

/// Chopped bins of all three axes.
#[derive(Clone, Debug, Zeroable)]
pub(crate) struct SpatialBins {
    bounds: [[Aabb; MAX_BINS]; 3],
    entries: [[u32; MAX_BINS]; 3],
    exits: [[u32; MAX_BINS]; 3],
}

impl SpatialBins {
    /// Scratch bins, zeroed lazily; [`SpatialBins::reset`] initialises what a node uses.
    pub(crate) fn new() -> Box<SpatialBins> {
        bytemuck::zeroed_box()
    }

    fn reset(&mut self, n: usize) {
        for axis in 0..3 {
            self.bounds[axis][..n].fill(Aabb::EMPTY);
            self.entries[axis][..n].fill(0);
            self.exits[axis][..n].fill(0);
        }
    }

    fn merge(&mut self, o: &SpatialBins, n: usize) {
        for axis in 0..3 {
            for i in 0..n {
                self.bounds[axis][i].grow(&o.bounds[axis][i]);
                self.entries[axis][i] += o.entries[axis][i];
                self.exits[axis][i] += o.exits[axis][i];
            }
        }
    }

    fn add(&mut self, r: &PrimRef, grid: &Grid, ctx: &SpatialCtx<'_>) {
        let b = r.aabb();
        let mut tri = None;
        for axis in (0..3).filter(|&a| grid.usable(a)) {
            let lo = grid.bin(b.min[axis], axis);
            let hi = grid.bin(b.max[axis], axis);
            self.entries[axis][lo] += 1;
            self.exits[axis][hi] += 1;
            if lo == hi {
                self.bounds[axis][lo].grow(&b);
                continue;
            }
            let t = *tri.get_or_insert_with(|| (ctx.triangle)(r.id()));
            let mut rest = b;
            for k in lo..hi {
                let (lb, rb) = split_box(t.as_ref(), &rest, axis, grid.plane(axis, k + 1));
                self.bounds[axis][k].grow(&lb);
                rest = rb;
            }
            self.bounds[axis][hi].grow(&rest);
        }
    }

    fn fill(&mut self, refs: &[PrimRef], grid: &Grid, ctx: &SpatialCtx<'_>) {
        let n = grid.n;
        self.reset(n);
        if refs.len() < PAR_SPATIAL_MIN {
            for r in refs {
                self.add(r, grid, ctx);
            }
            return;
        }
        let partial = refs
            .par_chunks(PAR_SPATIAL_CHUNK)
            .map(|chunk| {
                let mut bins = SpatialBins::new();
                bins.reset(n);
                for r in chunk {
                    bins.add(r, grid, ctx);
                }
                bins
            })
            .reduce_with(|mut a, b| {
                a.merge(&b, n);
                a
            });
        if let Some(p) = partial {
            self.merge(&p, n);
        }
    }
}

/// A priced spatial split.
pub(crate) struct SpatialChoice {
    /// `half_area(left) * n_left + half_area(right) * n_right`.
    pub cost: f64,
    grid: Grid,
    axis: usize,
    /// References starting in slabs `< pos` go left, those ending in slabs `>= pos` go right.
    pos: usize,
    left: Aabb,
    right: Aabb,
    left_count: u32,
    right_count: u32,
}

/// The boxes of the parts of a triangle (or, without one, of the box `b` itself) on either side
/// of the plane `axis = pos`, each within `b`. See the module docs for why they are
/// conservative.
pub(crate) fn split_box(tri: Option<&[Vec3; 3]>, b: &Aabb, axis: usize, pos: f32) -> (Aabb, Aabb) {
    let (mut l, mut r) = (*b, *b);
    l.max[axis] = l.max[axis].min(pos);
    r.min[axis] = r.min[axis].max(pos);
    let Some(tri) = tri else {
        return (l, r);
    };
    let (mut tl, mut tr) = (Aabb::EMPTY, Aabb::EMPTY);
    for i in 0..3 {
        let v0 = Vec3A::from(tri[i]);
        let v1 = Vec3A::from(tri[(i + 1) % 3]);
        let (p0, p1) = (v0[axis], v1[axis]);
        if p0 <= pos {
            tl.grow_point(v0);
        }
        if p0 >= pos {
            tr.grow_point(v0);
        }
        if (p0 < pos && pos < p1) || (p1 < pos && pos < p0) {
            let t = (pos - p0) / (p1 - p0);
            let x = v0 + (v1 - v0) * t;
            let pad = v0.abs().max(v1.abs()) * CLIP_PAD;
            let (mut lo, mut hi) = (x - pad, x + pad);
            lo[axis] = pos;
            hi[axis] = pos;
            for p in [lo, hi] {
                tl.grow_point(p);
                tr.grow_point(p);
            }
        }
    }
    (l.intersection(&tl), r.intersection(&tr))
}

/// Prices a spatial split of the node (in parallel for large nodes). `None` when no plane has
/// references on both sides within `budget` duplicates.
pub(crate) fn find(
    refs: &[PrimRef],
    info: &NodeInfo,
    ctx: &SpatialCtx<'_>,
    budget: usize,
    bins: &mut SpatialBins,
) -> Option<SpatialChoice> {
    let grid = Grid::new(&info.bounds, ctx.bins);
    bins.fill(refs, &grid, ctx);
    let n = refs.len() as u64;
    let mut best: Option<SpatialChoice> = None;
    let mut right_box = [Aabb::EMPTY; MAX_BINS];
    let mut right_count = [0u32; MAX_BINS];
    for axis in (0..3).filter(|&a| grid.usable(a)) {
        let mut acc = Aabb::EMPTY;
        let mut count = 0u32;
        for k in (1..grid.n).rev() {
            acc.grow(&bins.bounds[axis][k]);
            count += bins.exits[axis][k];
            right_box[k] = acc;
            right_count[k] = count;
        }
        let mut acc = Aabb::EMPTY;
        let mut count = 0u32;
        for k in 1..grid.n {
            acc.grow(&bins.bounds[axis][k - 1]);
            count += bins.entries[axis][k - 1];
            let rc = right_count[k];
            let dups = (u64::from(count) + u64::from(rc)).saturating_sub(n);
            if count == 0 || rc == 0 || dups > budget as u64 {
                continue;
            }
            let cost = f64::from(acc.half_area()) * f64::from(count)
                + f64::from(right_box[k].half_area()) * f64::from(rc);
            if best.as_ref().is_none_or(|b| cost < b.cost) {
                best = Some(SpatialChoice {
                    cost,
                    grid,
                    axis,
                    pos: k,
                    left: acc,
                    right: right_box[k],
                    left_count: count,
                    right_count: rc,
                });
            }
        }
    }
    best
}

/// Applies a spatial split: returns the children's references (left then right, new storage),
/// the partition, and the number of extra references; `None` if a side would be empty.
pub(crate) fn apply(
    refs: &[PrimRef],
    info: &NodeInfo,
    s: &SpatialChoice,
    ctx: &SpatialCtx<'_>,
) -> Option<(Vec<PrimRef>, Partition, usize)> {
    let (axis, grid) = (s.axis, &s.grid);
    let plane = grid.plane(axis, s.pos);
    let (nl, nr) = (f64::from(s.left_count), f64::from(s.right_count));
    let (al, ar) = (
        f64::from(s.left.half_area()),
        f64::from(s.right.half_area()),
    );
    let split_cost = al * nl + ar * nr;
    let mut left = Vec::with_capacity(s.left_count as usize);
    let mut right = Vec::with_capacity(s.right_count as usize);
    let mut dups = 0;
    for r in refs {
        let b = r.aabb();
        let lo = grid.bin(b.min[axis], axis);
        let hi = grid.bin(b.max[axis], axis);
        if hi < s.pos {
            left.push(*r);
        } else if lo >= s.pos {
            right.push(*r);
        } else {
            // Reference unsplitting: keep it whole on one side when that is cheaper.
            let whole_left = f64::from(s.left.union(&b).half_area()) * nl + ar * (nr - 1.0);
            let whole_right = al * (nl - 1.0) + f64::from(s.right.union(&b).half_area()) * nr;
            if whole_left <= split_cost.min(whole_right) {
                left.push(*r);
            } else if whole_right <= split_cost {
                right.push(*r);
            } else {
                let tri = (ctx.triangle)(r.id());
                let (lb, rb) = split_box(tri.as_ref(), &b, axis, plane);
                match (lb.is_empty(), rb.is_empty()) {
                    (false, false) => {
                        left.push(PrimRef::new(&lb, r.id()));
                        right.push(PrimRef::new(&rb, r.id()));
                        dups += 1;
                    }
                    (false, true) => left.push(*r),
                    _ => right.push(*r),
                }
            }
        }
    }
    if left.is_empty() || right.is_empty() {
        return None;
    }
    let mid = left.len();
    left.append(&mut right);
    let depth = info.depth + 1;
    let part = Partition {
        mid,
        left: NodeInfo::of(&left[..mid], depth),
        right: NodeInfo::of(&left[mid..], depth),
    };
    Some((left, part, dups))
}
