//! Binned SAH object splits (Wald 2007, "On fast Construction of SAH-based Bounding Volume
//! Hierarchies") for nodes too large for the exact sweeps of [`super::small`], and the in-place
//! partition that applies them.
//!
//! # How a node is priced
//!
//! The doubled centroids of the node's references are mapped into `bins` equal slabs per axis
//! of the centroid box ([`BinMap`]). One pass accumulates each bin's box and count on all three
//! axes (in parallel for large nodes); a sweep from each side then prices every plane between
//! two non-empty bins. Two or four accumulators take references in turn, which shortens the
//! chains of dependent updates when neighbouring references fall into the same bin.
//!
//! Two additions to Wald's scheme:
//!
//! * **Size split** ([`find_size`]): where a node holds a reference larger than a sixteenth of
//!   the node, cuts between size classes ("large ones left, small ones right") are priced as
//!   well. A plane cannot group large primitives whose centroids lie far apart (a ground quad
//!   under a model); the SAH rewards doing so.
//! * **Sampling**: nodes of at least [`SAMPLED_BINNING_MIN`] references bin every
//!   [`SAMPLE_STRIDE`]-th one (the top levels of a multi-million-triangle build are
//!   memory-bound); the partition then measures the exact child boxes.
//!
//! # Invariants
//!
//! * Partitioning uses the same bin map as binning ([`BinMap::bin_on`] equals a lane of
//!   [`BinMap::bin`]), so the counts and boxes found while binning are exactly those of the two
//!   halves (for a sampled node, the boxes are measured by the partition instead).
//! * Costs are unnormalised SAH costs in `f64` (a sample's counts scaled by the stride), so they
//!   compare with the costs of every other split search.
//! * Parallel binning and partitioning split the work by position only, so the result does not
//!   depend on the number of threads.

use bytemuck::Zeroable;
use glam::{BVec3A, Vec3A};
use rayon::prelude::*;

use super::split::{NodeInfo, ObjectChoice, ObjectHow};
use crate::aabb::Aabb;
use crate::input::PrimRef;

/// Largest bin count a preset may ask for.
pub const MAX_BINS: usize = 64;

/// Nodes with at least this many references are binned in parallel.
const PAR_BINNING_MIN: usize = 1 << 16;

/// Chunk size of parallel binning.
const PAR_BINNING_CHUNK: usize = 1 << 14;

/// Maps a doubled centroid to a bin on each axis.
///
/// The bin is `round((c2 - origin) * scale - 0.5)` clamped to `0..=last`, which is the floor of
/// the scaled coordinate except exactly on bin boundaries: monotone in `c2`, which is all the
/// sweep needs. The rounding adds `2^23` and reads the integer from the low mantissa bits, so the
/// whole map stays in SIMD registers (no saturating float-to-int casts). [`BinMap::bin`] and
/// [`BinMap::bin_on`] perform the same IEEE operations, so binning and partitioning agree on
/// every reference.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BinMap {
    origin: Vec3A,
    scale: Vec3A,
    last: Vec3A,
    /// Axes along which the centroids can be told apart.
    pub usable: [bool; 3],
}

/// `2^23`: adding it to a float in `[0, 2^22)` rounds it to an integer held in the low mantissa
/// bits.
const ROUND_MAGIC: f32 = 8_388_608.0;
const MANTISSA_MASK: u32 = 0x007f_ffff;

impl BinMap {
    pub(crate) fn new(centroid_bounds: &Aabb, bins: usize) -> Self {
        let extent = centroid_bounds.extent();
        let mut scale = Vec3A::ZERO;
        let mut usable = [false; 3];
        for axis in 0..3 {
            // Wald's k1 = bins * (1 - eps) / extent keeps the largest centroid in the last bin.
            let s = bins as f32 * (1.0 - 1e-6) / extent[axis];
            if extent[axis] > 0.0 && s.is_finite() {
                scale[axis] = s;
                usable[axis] = true;
            }
        }
        Self {
            origin: centroid_bounds.min,
            scale,
            last: Vec3A::splat((bins - 1) as f32),
            usable,
        }
    }

    /// Bin of the doubled centroid `c2` on one axis; equal to `self.bin(c2)[axis]`.
    #[inline(always)]
    pub(crate) fn bin_on(&self, c2: Vec3A, axis: usize) -> u32 {
        let x = (c2[axis] - self.origin[axis]) * self.scale[axis] - 0.5;
        (x.max(0.0).min(self.last[axis]) + ROUND_MAGIC).to_bits() & MANTISSA_MASK
    }

    /// Bin of the doubled centroid `c2` on every axis (0 on unusable axes).
    #[inline(always)]
    pub(crate) fn bin(&self, c2: Vec3A) -> [u32; 3] {
        let x = (c2 - self.origin) * self.scale - Vec3A::splat(0.5);
        let r = x.max(Vec3A::ZERO).min(self.last) + Vec3A::splat(ROUND_MAGIC);
        r.to_array().map(|f| f.to_bits() & MANTISSA_MASK)
    }
}

/// Boxes and reference counts of the bins of all three axes. Only the first `bins` entries of
/// each axis are used; [`Bins::reset`] clears exactly those, so one `Bins` is reused for every
/// node of a sequential subtree instead of clearing (or copying) all [`MAX_BINS`] per node.
#[derive(Clone, Debug, Zeroable)]
pub(crate) struct Bins {
    pub bounds: [[Aabb; MAX_BINS]; 3],
    pub counts: [[u32; MAX_BINS]; 3],
    /// Largest reference half area seen (for the size split).
    pub max_area: f32,
}

impl Bins {
    /// Scratch bins. Zeroed lazily (`calloc`): [`Bins::reset`] initialises what a node uses.
    pub(crate) fn new() -> Box<Bins> {
        bytemuck::zeroed_box()
    }

    fn reset(&mut self, n_bins: usize) {
        self.max_area = 0.0;
        for axis in 0..3 {
            self.bounds[axis][..n_bins].fill(Aabb::EMPTY);
            self.counts[axis][..n_bins].fill(0);
        }
    }

    #[inline(always)]
    fn add(&mut self, map: &BinMap, r: &PrimRef) {
        let b = map.bin(r.centroid2());
        let aabb = r.aabb();
        self.max_area = self.max_area.max(r.area());
        for (axis, &i) in b.iter().enumerate() {
            self.bounds[axis][i as usize].grow(&aabb);
            self.counts[axis][i as usize] += 1;
        }
    }

    fn merge(&mut self, other: &Bins, n_bins: usize) {
        self.max_area = self.max_area.max(other.max_area);
        for axis in 0..3 {
            for i in 0..n_bins {
                self.bounds[axis][i].grow(&other.bounds[axis][i]);
                self.counts[axis][i] += other.counts[axis][i];
            }
        }
    }

    /// Bins every `stride`-th reference into `self` and the `extra` accumulators in turn, then
    /// merges them into `self`. Spatially coherent references often fall into the same bins;
    /// each accumulator breaks the chain of dependent load-min-store updates on one bin. Four
    /// accumulators for dense nodes of at least [`QUAD_BINNING_MIN`] references, two otherwise
    /// (merging costs `bins` unions per accumulator).
    fn fill_interleaved(
        &mut self,
        extra: &mut Extra,
        refs: &[PrimRef],
        map: &BinMap,
        n_bins: usize,
        stride: usize,
    ) {
        let [a, b, c] = extra;
        self.reset(n_bins);
        a.reset(n_bins);
        if stride == 1 && refs.len() >= QUAD_BINNING_MIN {
            b.reset(n_bins);
            c.reset(n_bins);
            let mut quads = refs.chunks_exact(4);
            for q in &mut quads {
                self.add(map, &q[0]);
                a.add(map, &q[1]);
                b.add(map, &q[2]);
                c.add(map, &q[3]);
            }
            for r in quads.remainder() {
                self.add(map, r);
            }
            self.merge(b, n_bins);
            self.merge(c, n_bins);
        } else {
            let mut it = refs.iter().step_by(stride);
            while let Some(r) = it.next() {
                self.add(map, r);
                if let Some(r) = it.next() {
                    a.add(map, r);
                }
            }
        }
        self.merge(a, n_bins);
    }

    /// Bins every `stride`-th reference of `refs` into `self` (in parallel for large nodes);
    /// `extra` are scratch accumulators.
    pub(crate) fn fill(
        &mut self,
        extra: &mut Extra,
        refs: &[PrimRef],
        map: &BinMap,
        n_bins: usize,
        stride: usize,
    ) {
        if refs.len() < PAR_BINNING_MIN {
            self.fill_interleaved(extra, refs, map, n_bins, stride);
            return;
        }
        let partial = refs
            .par_chunks(PAR_BINNING_CHUNK)
            .map(|chunk| {
                let mut bins = Bins::new();
                bins.fill_interleaved(&mut Bins::extra(), chunk, map, n_bins, stride);
                bins
            })
            .reduce_with(|mut a, b| {
                a.merge(&b, n_bins);
                a
            });
        self.reset(n_bins);
        if let Some(p) = partial {
            self.merge(&p, n_bins);
        }
    }

    /// Scratch accumulators for [`Bins::fill`].
    pub(crate) fn extra() -> Extra {
        [Bins::new(), Bins::new(), Bins::new()]
    }
}

/// The extra accumulators of interleaved binning.
pub(crate) type Extra = [Box<Bins>; 3];

/// Nodes with at least this many references are binned into four accumulators.
const QUAD_BINNING_MIN: usize = 256;

/// Prices every plane between non-empty bins on every usable axis and returns the cheapest
/// object split, or `None` when no plane has references on both sides (every centroid in one
/// bin). Moving a plane across empty bins changes nothing, so only non-empty bins are swept and
/// the work per node is `O(min(n, bins))` per axis after binning.
pub(crate) fn find(
    refs: &[PrimRef],
    info: &NodeInfo,
    n_bins: usize,
    bins: &mut Bins,
    extra: &mut Extra,
) -> Option<ObjectChoice> {
    let map = BinMap::new(&info.centroid_bounds, n_bins);
    // Very large nodes (the memory-bound top of a multi-million-reference build) choose their
    // plane from a sample; the partition then computes the exact child boxes.
    let stride = if refs.len() >= SAMPLED_BINNING_MIN {
        SAMPLE_STRIDE
    } else {
        1
    };
    bins.fill(extra, refs, &map, n_bins, stride);
    let mut best = find_planes(bins, &map, n_bins, stride > 1);
    if bins.max_area > SIZE_SPLIT_MIN_RATIO * info.bounds.half_area() {
        if let Some(s) = find_size(refs, bins.max_area) {
            if best.as_ref().is_none_or(|b| s.cost < b.cost) {
                best = Some(s);
            }
        }
    }
    best
}

/// Nodes with at least this many references are binned from every [`SAMPLE_STRIDE`]-th one.
const SAMPLED_BINNING_MIN: usize = 1 << 17;

/// Sampling stride of very large nodes.
const SAMPLE_STRIDE: usize = 4;

/// The plane sweep of [`find`]; `sampled` marks bins filled from a sample.
fn find_planes(bins: &Bins, map: &BinMap, n_bins: usize, sampled: bool) -> Option<ObjectChoice> {
    let map = *map;
    let scale = if sampled { SAMPLE_STRIDE as f64 } else { 1.0 };
    let mut best: Option<ObjectChoice> = None;
    // Per axis: the non-empty bins, compacted, and the sweep from the right over them.
    let mut index = [0usize; MAX_BINS];
    let mut right_box = [Aabb::EMPTY; MAX_BINS];
    let mut right_cost = [0.0f64; MAX_BINS];
    for axis in (0..3).filter(|&a| map.usable[a]) {
        let (bounds, counts) = (&bins.bounds[axis], &bins.counts[axis]);
        let mut m = 0;
        for (i, &c) in counts[..n_bins].iter().enumerate() {
            if c > 0 {
                index[m] = i;
                m += 1;
            }
        }
        let mut acc = Aabb::EMPTY;
        let mut count = 0u32;
        for j in (1..m).rev() {
            acc.grow(&bounds[index[j]]);
            count += counts[index[j]];
            right_box[j] = acc;
            right_cost[j] = f64::from(acc.half_area()) * f64::from(count);
        }
        let mut acc = Aabb::EMPTY;
        let mut count = 0u32;
        for j in 1..m {
            acc.grow(&bounds[index[j - 1]]);
            count += counts[index[j - 1]];
            // A sample's counts are scaled up so that the cost compares with full-count costs.
            let cost = (f64::from(acc.half_area()) * f64::from(count) + right_cost[j]) * scale;
            if best.as_ref().is_none_or(|b| cost < b.cost) {
                best = Some(ObjectChoice {
                    cost,
                    left: acc,
                    right: right_box[j],
                    how: ObjectHow::Binned {
                        map,
                        axis,
                        pos: index[j],
                        left_count: count,
                        sampled,
                    },
                });
            }
        }
    }
    best
}

/// A node is also priced by reference size ([`find_size`]) when it holds a reference whose half
/// area exceeds this fraction of the node's.
const SIZE_SPLIT_MIN_RATIO: f32 = 1.0 / 16.0;

/// Size classes of [`find_size`]: class `c` holds references whose half area is within a factor
/// `2^c` (by exponent) below the node's largest; the last class takes everything smaller.
pub(crate) const SIZE_CLASSES: u32 = 8;

/// Size class of a reference whose half area has biased exponent `exp`, in a node whose largest
/// half area has biased exponent `max_exp`.
#[inline(always)]
pub(crate) fn size_class(r: &PrimRef, max_exp: u32) -> u32 {
    (max_exp.saturating_sub(r.area().to_bits() >> 23)).min(SIZE_CLASSES - 1)
}

/// Object split by size: large references on one side, small ones on the other. No plane can
/// group primitives that are large but far apart, like the two triangles of a ground quad whose
/// centroids lie in opposite corners with a detailed model between them (the thesis scene);
/// this split puts them in one child and the model in the other, which the SAH rewards.
/// References are classed by the exponent of their half area relative to the largest one
/// ([`size_class`]), and every cut between classes is priced.
fn find_size(refs: &[PrimRef], max_area: f32) -> Option<ObjectChoice> {
    const C: usize = SIZE_CLASSES as usize;
    let max_exp = max_area.to_bits() >> 23;
    let mut bounds = [Aabb::EMPTY; C];
    let mut counts = [0u32; C];
    for r in refs {
        let c = size_class(r, max_exp) as usize;
        bounds[c].grow(&r.aabb());
        counts[c] += 1;
    }
    let mut best: Option<ObjectChoice> = None;
    for k in 1..C {
        let (mut l, mut r) = (Aabb::EMPTY, Aabb::EMPTY);
        let (mut nl, mut nr) = (0u32, 0u32);
        for c in 0..C {
            if c < k {
                l.grow(&bounds[c]);
                nl += counts[c];
            } else {
                r.grow(&bounds[c]);
                nr += counts[c];
            }
        }
        if nl == 0 || nr == 0 {
            continue;
        }
        let cost =
            f64::from(l.half_area()) * f64::from(nl) + f64::from(r.half_area()) * f64::from(nr);
        if best.as_ref().is_none_or(|b| cost < b.cost) {
            best = Some(ObjectChoice {
                cost,
                left: l,
                right: r,
                how: ObjectHow::Size {
                    max_exp,
                    cut: k as u32,
                    left_count: nl,
                },
            });
        }
    }
    best
}

/// Result of a partition: the left count, the doubled-centroid bounds of both sides, and (when
/// asked for) the boxes of both sides.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sides {
    pub mid: usize,
    pub centroids: [Aabb; 2],
    pub boxes: [Aabb; 2],
}

impl Sides {
    fn union(&self, o: &Sides) -> Sides {
        Sides {
            mid: self.mid + o.mid,
            centroids: [0, 1].map(|k| self.centroids[k].union(&o.centroids[k])),
            boxes: [0, 1].map(|k| self.boxes[k].union(&o.boxes[k])),
        }
    }
}

/// Grows `left` or `right` by `a` without a branch.
#[inline(always)]
fn grow_masked(left: &mut Aabb, right: &mut Aabb, m: BVec3A, min: Vec3A, max: Vec3A) {
    left.min = left.min.min(Vec3A::select(m, min, left.min));
    left.max = left.max.max(Vec3A::select(m, max, left.max));
    right.min = right.min.min(Vec3A::select(m, right.min, min));
    right.max = right.max.max(Vec3A::select(m, right.max, max));
}

/// Moves the references for which `goes_left` holds to the front, and measures both sides (the
/// boxes only when `BOXES`).
///
/// Branch-free Lomuto scan: every element is swapped with the first right-side element and the
/// boundary advances by the predicate, so the (unpredictable) predicate never steers a branch.
/// Invariant at step `j`: `refs[..i]` go left, `refs[i..j]` go right.
fn partition_seq<const BOXES: bool>(
    refs: &mut [PrimRef],
    goes_left: &impl Fn(&PrimRef) -> bool,
) -> Sides {
    let [mut cl, mut cr] = [Aabb::EMPTY; 2];
    let [mut bl, mut br] = [Aabb::EMPTY; 2];
    let mut i = 0;
    for j in 0..refs.len() {
        let r = refs[j];
        let left = goes_left(&r);
        let m = BVec3A::splat(left);
        let c = r.centroid2();
        grow_masked(&mut cl, &mut cr, m, c, c);
        if BOXES {
            grow_masked(&mut bl, &mut br, m, r.min(), r.max());
        }
        refs[j] = refs[i];
        refs[i] = r;
        i += usize::from(left);
    }
    Sides {
        mid: i,
        centroids: [cl, cr],
        boxes: [bl, br],
    }
}

/// [`partition_seq`] for large arrays: both halves are partitioned in parallel, giving
/// `[L1 R1 L2 R2]`, then the shorter of `R1` and `L2` is swapped with the far end of the other,
/// giving `[L R]`. Order within a side does not matter, so this is as valid as the sequential
/// scan, and deterministic.
fn partition_par<const BOXES: bool>(
    refs: &mut [PrimRef],
    goes_left: &(impl Fn(&PrimRef) -> bool + Sync),
) -> Sides {
    if refs.len() < PAR_PARTITION_MIN {
        return partition_seq::<BOXES>(refs, goes_left);
    }
    let half = refs.len() / 2;
    let (x, y) = refs.split_at_mut(half);
    let (a, b) = rayon::join(
        || partition_par::<BOXES>(x, goes_left),
        || partition_par::<BOXES>(y, goes_left),
    );
    let k = (half - a.mid).min(b.mid);
    x[a.mid..a.mid + k].swap_with_slice(&mut y[b.mid - k..b.mid]);
    a.union(&b)
}

/// Arrays at least this long are partitioned in parallel.
const PAR_PARTITION_MIN: usize = 1 << 16;

/// Splits `refs` in place: references of size class below `cut` move to the front.
pub(crate) fn partition_size(refs: &mut [PrimRef], max_exp: u32, cut: u32) -> Sides {
    partition_par::<false>(refs, &|r: &PrimRef| size_class(r, max_exp) < cut)
}

/// Splits `refs` in place: references whose centroid bin on `axis` is below `pos` move to the
/// front. With `boxes`, the exact boxes of both sides are measured too (for sampled bins).
pub(crate) fn partition(
    refs: &mut [PrimRef],
    map: &BinMap,
    axis: usize,
    pos: usize,
    boxes: bool,
) -> Sides {
    let pos = pos as u32;
    macro_rules! on_axis {
        ($a:literal) => {
            if boxes {
                partition_par::<true>(refs, &|r: &PrimRef| map.bin_on(r.centroid2(), $a) < pos)
            } else {
                partition_par::<false>(refs, &|r: &PrimRef| map.bin_on(r.centroid2(), $a) < pos)
            }
        };
    }
    match axis {
        0 => on_axis!(0),
        1 => on_axis!(1),
        _ => on_axis!(2),
    }
}
