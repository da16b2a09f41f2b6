//! The per-node decision shared by every builder: price the best object split (exhaustive,
//! sorted sweep or binned, by node size), price a spatial split where the object split leaves
//! the children overlapping, compare both with a leaf, and apply the winner.
//!
//! # Invariants
//!
//! * Costs are unnormalised SAH costs of the two children (`sum half_area * count`) in `f64`,
//!   computed from finite `f32` half areas, so no cost is NaN and every comparison is total.
//! * A node with more than `max_leaf_size` references is always split, and every split leaves
//!   at least one reference on each side. The recursion terminates: an object split makes both
//!   children smaller; a spatial split that creates `d` extra references costs the subtree `d`
//!   of its duplication budget, so `references + budget` of each child is below the parent's.
//! * From [`SAH_DEPTH_LIMIT`] on, splits are median splits, which halve the count: the depth
//!   stays below `SAH_DEPTH_LIMIT + 32 <= MAX_DEPTH`.
//! * The decision depends only on the node's references and settings, never on thread timing.

use crate::aabb::Aabb;
use crate::input::PrimRef;
use crate::preset::BuildParams;

use super::binned::{self, BinMap, Bins};
use super::small;
use super::spatial::{self, SpatialBins, SpatialCtx};

/// Below this depth splits minimise the SAH; at and beyond it they are median splits.
pub(crate) const SAH_DEPTH_LIMIT: u32 = 64;

/// What is known about a node before it is split.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NodeInfo {
    /// Union of the reference boxes.
    pub bounds: Aabb,
    /// Union of the doubled centroids.
    pub centroid_bounds: Aabb,
    /// Edges from the root.
    pub depth: u32,
}

impl NodeInfo {
    /// Info of a set of references at `depth`.
    pub(crate) fn of(refs: &[PrimRef], depth: u32) -> Self {
        let (bounds, centroid_bounds) = crate::input::ref_bounds(refs);
        Self {
            bounds,
            centroid_bounds,
            depth,
        }
    }
}

/// A split node: the left child holds `refs[..mid]`, the right one `refs[mid..]`.
pub(crate) struct Partition {
    pub mid: usize,
    pub left: NodeInfo,
    pub right: NodeInfo,
}

/// A priced object split that has not been applied yet.
pub(crate) struct ObjectChoice {
    /// `half_area(left) * n_left + half_area(right) * n_right`.
    pub cost: f64,
    pub left: Aabb,
    pub right: Aabb,
    pub how: ObjectHow,
}

/// How to apply an [`ObjectChoice`].
pub(crate) enum ObjectHow {
    /// The references whose bit is set in `mask` go left (tiny nodes).
    Subset { mask: u32 },
    /// `order[..cut]` go left, `order[cut..]` right (small nodes, sorted along one axis).
    Sorted {
        order: [u8; small::SMALL_NODE_MAX],
        cut: usize,
    },
    /// References of size class below `cut` go left (see `binned::find_size`).
    Size {
        max_exp: u32,
        cut: u32,
        left_count: u32,
    },
    /// References whose centroid bin on `axis` is below `pos` go left (binned nodes).
    Binned {
        map: BinMap,
        axis: usize,
        pos: usize,
        left_count: u32,
        /// The bins saw a sample: counts and boxes are estimates, the partition measures.
        sampled: bool,
    },
}

/// Per-task scratch memory, reused by every node the task splits.
pub(crate) struct Scratch {
    pub bins: Box<Bins>,
    /// Extra accumulators for binning.
    pub extra: binned::Extra,
    /// Allocated on the first spatial split attempt.
    pub spatial: Option<Box<SpatialBins>>,
}

impl Scratch {
    pub(crate) fn new() -> Self {
        Self {
            bins: Bins::new(),
            extra: Bins::extra(),
            spatial: None,
        }
    }
}

/// What to do with a node.
pub(crate) enum Decision {
    /// Make a leaf of all references.
    Leaf,
    /// Split in place (the references were reordered).
    InPlace(Partition),
    /// Spatial split: the children's references, left then right, in new storage; `dups` of
    /// them are extra references created by splitting.
    Spatial {
        refs: Vec<PrimRef>,
        part: Partition,
        dups: usize,
    },
}

/// Everything a node decision needs besides the node itself.
pub(crate) struct Ctx<'a> {
    pub params: &'a BuildParams,
    /// Spatial splits, for triangle input with a preset that enables them.
    pub spatial: Option<SpatialCtx<'a>>,
}

/// True when a leaf is at least as cheap as splitting with children cost `split_cost` (the
/// unnormalised `sum half_area * count` of the children), and allowed by the leaf size limit.
pub(crate) fn leaf_is_cheaper(
    params: &BuildParams,
    bounds: &Aabb,
    count: usize,
    split_cost: Option<f64>,
) -> bool {
    if count <= 1 {
        return true;
    }
    if count > params.max_leaf_size as usize {
        return false;
    }
    let Some(children) = split_cost else {
        return true;
    };
    let area = f64::from(bounds.half_area());
    let c = params.cost;
    let leaf = f64::from(c.intersection) * count as f64 * area;
    let split = f64::from(c.traversal) * area + f64::from(c.intersection) * children;
    leaf <= split
}

/// Half area of the overlap of the two children of `o`, or of the whole node when no object
/// split exists (every centroid equal: the references lie on top of each other).
fn overlap(o: Option<&ObjectChoice>, info: &NodeInfo) -> f32 {
    match o {
        Some(o) => {
            let i = o.left.intersection(&o.right);
            if i.is_empty() {
                0.0
            } else {
                i.half_area()
            }
        }
        None => info.bounds.half_area(),
    }
}

/// Decides a node over `refs` that may create at most `budget` extra references.
pub(crate) fn decide(
    refs: &mut [PrimRef],
    info: &NodeInfo,
    budget: usize,
    ctx: &Ctx<'_>,
    scratch: &mut Scratch,
) -> Decision {
    let n = refs.len();
    let params = ctx.params;
    if n <= 1 {
        return Decision::Leaf;
    }
    if info.depth >= SAH_DEPTH_LIMIT {
        return if n > params.max_leaf_size as usize {
            Decision::InPlace(median_split(refs, info))
        } else {
            Decision::Leaf
        };
    }
    let object = if n <= small::TINY_NODE_MAX {
        small::find_tiny(refs)
    } else if n <= small::SMALL_NODE_MAX {
        small::find_sorted(refs, info, params.sweep_all_axes)
    } else {
        binned::find(
            refs,
            info,
            params.bins,
            &mut scratch.bins,
            &mut scratch.extra,
        )
    };
    let spatial = match &ctx.spatial {
        Some(sc) if budget > 0 && overlap(object.as_ref(), info) > sc.min_overlap => {
            let bins = scratch.spatial.get_or_insert_with(SpatialBins::new);
            spatial::find(refs, info, sc, budget, bins)
        }
        _ => None,
    };
    let object_cost = object.as_ref().map(|o| o.cost);
    let best_cost = match (object_cost, spatial.as_ref().map(|s| s.cost)) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    if leaf_is_cheaper(params, &info.bounds, n, best_cost) {
        return Decision::Leaf;
    }
    if let (Some(s), Some(sc)) = (&spatial, &ctx.spatial) {
        if object_cost.is_none_or(|o| s.cost < o) {
            if let Some((refs, part, dups)) = spatial::apply(refs, info, s, sc) {
                return Decision::Spatial { refs, part, dups };
            }
        }
    }
    Decision::InPlace(match object {
        Some(o) => apply_object(refs, info, o),
        None => median_split(refs, info),
    })
}

/// Applies a priced object split.
fn apply_object(refs: &mut [PrimRef], info: &NodeInfo, o: ObjectChoice) -> Partition {
    let centroids = |part: &[PrimRef]| {
        part.iter().fold(Aabb::EMPTY, |mut c, r| {
            c.grow_point(r.centroid2());
            c
        })
    };
    let (mut left, mut right) = (o.left, o.right);
    let (mid, cl, cr) = match o.how {
        ObjectHow::Subset { mask } => {
            let mid = small::apply_subset(refs, mask);
            (mid, centroids(&refs[..mid]), centroids(&refs[mid..]))
        }
        ObjectHow::Sorted { order, cut } => {
            small::apply_order(refs, &order);
            (cut, centroids(&refs[..cut]), centroids(&refs[cut..]))
        }
        ObjectHow::Binned {
            map,
            axis,
            pos,
            left_count,
            sampled,
        } => {
            let s = binned::partition(refs, &map, axis, pos, sampled);
            if sampled {
                [left, right] = s.boxes;
            } else {
                debug_assert_eq!(s.mid, left_count as usize, "binning and partition disagree");
            }
            (s.mid, s.centroids[0], s.centroids[1])
        }
        ObjectHow::Size {
            max_exp,
            cut,
            left_count,
        } => {
            let s = binned::partition_size(refs, max_exp, cut);
            debug_assert_eq!(
                s.mid, left_count as usize,
                "size binning and partition disagree"
            );
            (s.mid, s.centroids[0], s.centroids[1])
        }
    };
    let depth = info.depth + 1;
    Partition {
        mid,
        left: NodeInfo {
            bounds: left,
            centroid_bounds: cl,
            depth,
        },
        right: NodeInfo {
            bounds: right,
            centroid_bounds: cr,
            depth,
        },
    }
}

/// Splits `refs` in place at the median along the widest centroid axis (any order when every
/// centroid is equal). Both halves are non-empty for `refs.len() >= 2`.
pub(crate) fn median_split(refs: &mut [PrimRef], info: &NodeInfo) -> Partition {
    let axis = info.centroid_bounds.extent().max_position();
    let mid = refs.len() / 2;
    refs.select_nth_unstable_by(mid, |a, b| {
        a.centroid2()[axis].total_cmp(&b.centroid2()[axis])
    });
    Partition {
        mid,
        left: NodeInfo::of(&refs[..mid], info.depth + 1),
        right: NodeInfo::of(&refs[mid..], info.depth + 1),
    }
}
