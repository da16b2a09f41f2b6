//! Exact object splits for small nodes, where binning would cost more than it saves: nodes of
//! at most [`TINY_NODE_MAX`] references try every bipartition, nodes of at most
//! [`SMALL_NODE_MAX`] sweep their references sorted by centroid.
//!
//! # Invariants
//!
//! * Both searches price exactly the candidates they return, with the same unnormalised cost as
//!   the binned search (`half_area(left) * n_left + half_area(right) * n_right` in `f64`).
//! * Sorting is stable and ties are broken by position, so the result is deterministic.
//! * The returned boxes are the exact unions of the references on each side.

use crate::aabb::Aabb;
use crate::input::PrimRef;

use super::split::{NodeInfo, ObjectChoice, ObjectHow};

/// Nodes with at most this many references try every bipartition ([`find_tiny`]).
pub(crate) const TINY_NODE_MAX: usize = 4;

/// Nodes with at most this many references are split by an exact sweep ([`find_sorted`]).
pub(crate) const SMALL_NODE_MAX: usize = 16;

/// Exhaustive SAH for `2 <= n <= TINY_NODE_MAX` references: every way to cut them into two
/// non-empty sets (at most 7), not only cuts along an axis.
pub(crate) fn find_tiny(refs: &[PrimRef]) -> Option<ObjectChoice> {
    let n = refs.len();
    debug_assert!((2..=TINY_NODE_MAX).contains(&n));
    let full = (1usize << n) - 1;
    // Box of every subset, by its bit mask.
    let mut sub = [Aabb::EMPTY; 1 << TINY_NODE_MAX];
    for m in 1..=full {
        let low = m & m.wrapping_neg();
        sub[m] = sub[m ^ low].union(&refs[low.trailing_zeros() as usize].aabb());
    }
    let mut best: Option<(f64, usize)> = None;
    // Masks holding reference 0 enumerate each bipartition once.
    for m in (1..full).step_by(2) {
        let rest = full ^ m;
        let cost = f64::from(sub[m].half_area()) * f64::from(m.count_ones())
            + f64::from(sub[rest].half_area()) * f64::from(rest.count_ones());
        if best.is_none_or(|b| cost < b.0) {
            best = Some((cost, m));
        }
    }
    best.map(|(cost, m)| ObjectChoice {
        cost,
        left: sub[m],
        right: sub[full ^ m],
        how: ObjectHow::Subset { mask: m as u32 },
    })
}

/// Moves the references whose bit is set in `mask` to the front (stably) and returns their
/// count.
pub(crate) fn apply_subset(refs: &mut [PrimRef], mask: u32) -> usize {
    let n = refs.len();
    let copy: [PrimRef; TINY_NODE_MAX] = std::array::from_fn(|i| refs[i.min(n - 1)]);
    let mut k = 0;
    for take in [true, false] {
        for (i, r) in copy[..n].iter().enumerate() {
            if (mask >> i & 1 == 1) == take {
                refs[k] = *r;
                k += 1;
            }
        }
    }
    mask.count_ones() as usize
}

/// Exact sweep for `TINY_NODE_MAX < n <= SMALL_NODE_MAX` references: along each axis (or only
/// the widest centroid axis when `all_axes` is false), sorted by centroid, every one of the
/// `n - 1` cuts is priced.
pub(crate) fn find_sorted(
    refs: &[PrimRef],
    info: &NodeInfo,
    all_axes: bool,
) -> Option<ObjectChoice> {
    const N: usize = SMALL_NODE_MAX;
    let n = refs.len();
    debug_assert!((2..=N).contains(&n));
    let mut boxes = [Aabb::EMPTY; N];
    let mut keys = [[0.0f32; N]; 3];
    for (i, r) in refs.iter().enumerate() {
        boxes[i] = r.aabb();
        let c = r.centroid2();
        (keys[0][i], keys[1][i], keys[2][i]) = (c.x, c.y, c.z);
    }
    let extent = info.centroid_bounds.extent();
    let widest = extent.max_position();
    let mut best: Option<ObjectChoice> = None;
    let mut order = [0u8; N];
    let mut right_box = [Aabb::EMPTY; N];
    let mut right_cost = [0.0f64; N];
    for axis in 0..3 {
        if extent[axis] <= 0.0 || !(all_axes || axis == widest) {
            continue;
        }
        sort_small(&mut order[..n], &keys[axis]);
        let mut acc = Aabb::EMPTY;
        for k in (1..n).rev() {
            acc.grow(&boxes[order[k] as usize]);
            right_box[k] = acc;
            right_cost[k] = f64::from(acc.half_area()) * (n - k) as f64;
        }
        let mut acc = Aabb::EMPTY;
        for k in 1..n {
            acc.grow(&boxes[order[k - 1] as usize]);
            let cost = f64::from(acc.half_area()) * k as f64 + right_cost[k];
            if best.as_ref().is_none_or(|b| cost < b.cost) {
                best = Some(ObjectChoice {
                    cost,
                    left: acc,
                    right: right_box[k],
                    how: ObjectHow::Sorted { order, cut: k },
                });
            }
        }
    }
    best
}

/// Reorders `refs` so that position `i` holds the former `refs[order[i]]`.
pub(crate) fn apply_order(refs: &mut [PrimRef], order: &[u8; SMALL_NODE_MAX]) {
    let n = refs.len();
    let sorted: [PrimRef; SMALL_NODE_MAX] =
        std::array::from_fn(|i| refs[order[i.min(n - 1)] as usize]);
    refs.copy_from_slice(&sorted[..n]);
}

/// Fills `order` with `0..len` sorted by `keys` (insertion sort: stable, and fast for the at
/// most [`SMALL_NODE_MAX`] elements of a small node).
fn sort_small(order: &mut [u8], keys: &[f32; SMALL_NODE_MAX]) {
    for (i, o) in order.iter_mut().enumerate() {
        *o = i as u8;
    }
    for i in 1..order.len() {
        let x = order[i];
        let kx = keys[x as usize];
        let mut j = i;
        while j > 0 && keys[order[j - 1] as usize] > kx {
            order[j] = order[j - 1];
            j -= 1;
        }
        order[j] = x;
    }
}
