//! The builders: one entry point, [`build`], which turns an input and a preset into the
//! canonical [`Bvh`].
//!
//! # Pipeline
//!
//! 1. [`crate::input`] sanitises the primitives into `PrimRef`s (parallel for large inputs).
//! 2. A top-down recursion decides every node (`split::decide`): leaf, object split (exact for
//!    small nodes, `small`; binned SAH for large ones, `binned`) or, for triangles with a
//!    preset that enables them, spatial split (`spatial`). Object splits partition the
//!    reference array **in place**; a spatial split moves the node's references into new
//!    storage, because it creates extra ones.
//! 3. Large nodes run their two halves as a `rayon::join`, so both cores work from the first
//!    split on; nodes of at most `SEQ_SUBTREE_MAX` references are built sequentially, each into
//!    its own node vector (already in the final depth-first pair layout) and its own primitive
//!    list, to which every leaf appends the ids of its references.
//! 4. `assemble` splices the per-task vectors under the few parallel top nodes, in one
//!    parallel copy.
//!
//! # Invariants
//!
//! * A leaf's slots are the ids its node's references held when it became a leaf, written once
//!   and in depth-first leaf order, so the leaf ranges tile the primitive list by construction.
//!   Where spatial splits put two fragments of one triangle into the same leaf, the leaf lists
//!   the triangle once.
//! * Extra references from spatial splits are bounded: each node receives a duplication budget
//!   and hands what it does not use to its children in proportion to their sizes, so the total
//!   never exceeds `max_duplication * accepted primitives`, and the split of the budget (like
//!   everything else) depends only on the input.
//! * The output does not depend on thread scheduling: `rayon::join` only decides *when* a half
//!   is built, never what is built. Builds are deterministic.
//! * The result satisfies every invariant of [`crate::bvh`]; debug builds re-check them with
//!   [`Bvh::validate`].

mod binned;
mod small;
mod spatial;
mod split;

pub use binned::MAX_BINS;

use std::sync::atomic::{AtomicBool, Ordering};

use glam::Vec3;

use crate::aabb::Aabb;
use crate::bvh::{Bvh, BvhNode};
use crate::input::{self, PrimRef, Prims};
use crate::preset::{BuildParams, BuildPreset};
use spatial::SpatialCtx;
use split::{Ctx, Decision, NodeInfo, Scratch};

/// Subtrees of at most this many references are built sequentially into one node vector.
const SEQ_SUBTREE_MAX: usize = 4096;

/// What to build a BVH over.
#[derive(Clone, Copy, Debug)]
pub enum BuildInput<'a> {
    /// A triangle soup; primitive `i` is `tris[i]`.
    Triangles(&'a [[Vec3; 3]]),
    /// An indexed triangle mesh; primitive `i` is the triangle `indices[i]`.
    Indexed {
        /// Vertex positions.
        vertices: &'a [Vec3],
        /// One index triple per triangle.
        indices: &'a [[u32; 3]],
    },
    /// Arbitrary boxes (instances for a scene-level BVH, custom-geometry bounds); primitive `i`
    /// is `boxes[i]`. Spatial splits never apply.
    Aabbs(&'a [Aabb]),
}

impl BuildInput<'_> {
    /// Number of input primitives.
    pub fn len(&self) -> usize {
        match self {
            BuildInput::Triangles(t) => t.len(),
            BuildInput::Indexed { indices, .. } => indices.len(),
            BuildInput::Aabbs(b) => b.len(),
        }
    }

    /// True for an input without primitives.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Triangle `id`, for spatial splits (`None` for boxes and bad indices).
    fn triangle(&self, id: u32) -> Option<[Vec3; 3]> {
        match self {
            BuildInput::Triangles(t) => t.get(id as usize).copied(),
            BuildInput::Indexed { vertices, indices } => {
                input::indexed_triangle(vertices, indices, id as usize)
            }
            BuildInput::Aabbs(_) => None,
        }
    }
}

/// Builds the canonical BVH over `input` with the settings of `preset`.
///
/// Never panics on degenerate input (empty input, a single primitive, equal centroids, flat or
/// huge boxes, NaN or infinite coordinates: see [`crate::input`] for what is skipped or
/// clamped). Panics only if the input holds `2^32` or more primitives.
pub fn build(input: BuildInput<'_>, preset: BuildPreset) -> Bvh {
    build_with_params(input, &preset.params())
}

/// Builds with explicit settings. Prefer [`build`] with a preset; this exists so that the
/// benchmark can explore settings before they become a preset.
///
/// # Panics
///
/// If `params.bins` is not in `2..=MAX_BINS` or `params.max_leaf_size` is 0.
pub fn build_with_params(input: BuildInput<'_>, params: &BuildParams) -> Bvh {
    assert!(
        (2..=MAX_BINS).contains(&params.bins) && params.max_leaf_size >= 1,
        "rtc-bvh: invalid build parameters {params:?}"
    );
    let prims = match input {
        BuildInput::Triangles(t) => input::triangle_refs(t),
        BuildInput::Indexed { vertices, indices } => input::indexed_refs(vertices, indices),
        BuildInput::Aabbs(b) => input::aabb_refs(b),
    };
    let Prims {
        mut refs,
        bounds,
        centroid_bounds,
        input_count,
    } = prims;
    if refs.is_empty() {
        return Bvh::empty(input_count);
    }
    let triangle = |id: u32| input.triangle(id);
    let spatial = match params.spatial_splits {
        Some(s) if !matches!(input, BuildInput::Aabbs(_)) => Some(SpatialCtx {
            min_overlap: s.min_overlap * bounds.half_area(),
            bins: params.bins,
            triangle: &triangle,
        }),
        _ => None,
    };
    let budget = params.spatial_splits.map_or(0, |s| {
        (f64::from(s.max_duplication.max(0.0)) * refs.len() as f64) as usize
    });
    let task = Task {
        info: NodeInfo {
            bounds,
            centroid_bounds,
            depth: 0,
        },
        budget,
    };
    let ctx = Ctx { params, spatial };
    let used_spatial = AtomicBool::new(false);
    let tree = subtree(&mut refs, task, &ctx, &used_spatial);
    drop(refs);
    let (nodes, prim_indices) = assemble(tree);
    Bvh::from_builder(
        nodes,
        prim_indices,
        input_count,
        used_spatial.load(Ordering::Relaxed),
    )
}

/// A node waiting to be decided.
#[derive(Clone, Copy, Debug)]
struct Task {
    info: NodeInfo,
    /// Extra references the subtree may create by spatial splits.
    budget: usize,
}

impl Task {
    /// The children's tasks: the unused budget is shared in proportion to the child sizes.
    fn children(&self, part: &split::Partition, total: usize, used: usize) -> (Task, Task) {
        let rest = self.budget.saturating_sub(used);
        let left = (rest as u128 * part.mid as u128 / total.max(1) as u128) as usize;
        (
            Task {
                info: part.left,
                budget: left,
            },
            Task {
                info: part.right,
                budget: rest - left,
            },
        )
    }
}

/// A built part of the tree: a finished node vector (root at 0, depth-first pair layout, child
/// and slot indices relative to the vectors) with its primitive list, or an inner node whose
/// halves were built in parallel.
enum Subtree {
    Nodes {
        nodes: Vec<BvhNode>,
        prims: Vec<u32>,
    },
    Split {
        bounds: Aabb,
        children: Box<[Subtree; 2]>,
    },
}

/// Builds the subtree over `refs`.
fn subtree(refs: &mut [PrimRef], task: Task, ctx: &Ctx<'_>, used_spatial: &AtomicBool) -> Subtree {
    let n = refs.len();
    let mut scratch = Scratch::new();
    if n <= SEQ_SUBTREE_MAX {
        let mut nodes = Vec::with_capacity(n + n / 2);
        let mut prims = Vec::with_capacity(n);
        nodes.push(BvhNode::leaf(task.info.bounds, 0, 0));
        let mut out = Output {
            nodes: &mut nodes,
            prims: &mut prims,
            dedupe: ctx.spatial.is_some(),
        };
        build_sequential(refs, task, ctx, &mut scratch, &mut out, 0, used_spatial);
        return Subtree::Nodes { nodes, prims };
    }
    let (a, b) = match split::decide(refs, &task.info, task.budget, ctx, &mut scratch) {
        Decision::Leaf => {
            let mut nodes = vec![BvhNode::leaf(task.info.bounds, 0, 0)];
            let mut prims = Vec::with_capacity(n);
            let mut out = Output {
                nodes: &mut nodes,
                prims: &mut prims,
                dedupe: ctx.spatial.is_some(),
            };
            out.leaf(0, &task.info.bounds, refs);
            return Subtree::Nodes { nodes, prims };
        }
        Decision::InPlace(part) => {
            let (lt, rt) = task.children(&part, n, 0);
            let (l, r) = refs.split_at_mut(part.mid);
            rayon::join(
                || subtree(l, lt, ctx, used_spatial),
                || subtree(r, rt, ctx, used_spatial),
            )
        }
        Decision::Spatial {
            refs: mut owned,
            part,
            dups,
        } => {
            used_spatial.store(true, Ordering::Relaxed);
            let (lt, rt) = task.children(&part, owned.len(), dups);
            let (l, r) = owned.split_at_mut(part.mid);
            rayon::join(
                || subtree(l, lt, ctx, used_spatial),
                || subtree(r, rt, ctx, used_spatial),
            )
        }
    };
    Subtree::Split {
        bounds: task.info.bounds,
        children: Box::new([a, b]),
    }
}

/// Where a sequential build writes.
struct Output<'a> {
    nodes: &'a mut Vec<BvhNode>,
    prims: &'a mut Vec<u32>,
    /// Whether a leaf may hold two fragments of one primitive (spatial splits).
    dedupe: bool,
}

impl Output<'_> {
    /// Writes a leaf over `refs` to `nodes[slot]`, appending their ids (each once).
    fn leaf(&mut self, slot: usize, bounds: &Aabb, refs: &[PrimRef]) {
        let first = self.prims.len();
        for r in refs {
            let id = r.id();
            if !(self.dedupe && self.prims[first..].contains(&id)) {
                self.prims.push(id);
            }
        }
        let count = (self.prims.len() - first) as u32;
        self.nodes[slot] = BvhNode::leaf(*bounds, first as u32, count);
    }

    /// Writes an inner node to `nodes[slot]` and reserves its child pair; returns the left
    /// child's index.
    fn inner(&mut self, slot: usize, bounds: &Aabb, part: &split::Partition) -> usize {
        let left = self.nodes.len();
        self.nodes[slot] = BvhNode::inner(*bounds, left as u32);
        self.nodes.push(BvhNode::leaf(part.left.bounds, 0, 0));
        self.nodes.push(BvhNode::leaf(part.right.bounds, 0, 0));
        left
    }
}

/// Builds the subtree over `refs` into `out`, writing its root to `out.nodes[slot]` and
/// appending its descendants in depth-first pair order.
fn build_sequential(
    refs: &mut [PrimRef],
    task: Task,
    ctx: &Ctx<'_>,
    scratch: &mut Scratch,
    out: &mut Output<'_>,
    slot: usize,
    used_spatial: &AtomicBool,
) {
    let n = refs.len();
    match split::decide(refs, &task.info, task.budget, ctx, scratch) {
        Decision::Leaf => out.leaf(slot, &task.info.bounds, refs),
        Decision::InPlace(part) => {
            let left = out.inner(slot, &task.info.bounds, &part);
            let (lt, rt) = task.children(&part, n, 0);
            let (l, r) = refs.split_at_mut(part.mid);
            build_sequential(l, lt, ctx, scratch, out, left, used_spatial);
            build_sequential(r, rt, ctx, scratch, out, left + 1, used_spatial);
        }
        Decision::Spatial {
            refs: mut owned,
            part,
            dups,
        } => {
            used_spatial.store(true, Ordering::Relaxed);
            let left = out.inner(slot, &task.info.bounds, &part);
            let (lt, rt) = task.children(&part, owned.len(), dups);
            let (l, r) = owned.split_at_mut(part.mid);
            build_sequential(l, lt, ctx, scratch, out, left, used_spatial);
            build_sequential(r, rt, ctx, scratch, out, left + 1, used_spatial);
        }
    }
}

/// Nodes below the root of `tree`, and primitive slots of `tree`.
fn sizes(tree: &Subtree) -> (usize, usize) {
    match tree {
        Subtree::Nodes { nodes, prims } => (nodes.len() - 1, prims.len()),
        Subtree::Split { children, .. } => {
            let (a, b) = (sizes(&children[0]), sizes(&children[1]));
            (2 + a.0 + b.0, a.1 + b.1)
        }
    }
}

/// Flattens a [`Subtree`] into one node vector in depth-first pair layout and one primitive
/// list in leaf order. Both are allocated once and filled in parallel, one subtree per task.
fn assemble(tree: Subtree) -> (Vec<BvhNode>, Vec<u32>) {
    let (desc, slots) = sizes(&tree);
    // Zeroed (calloc) storage: every element is overwritten by `emit`, and the pages are
    // zeroed lazily, in parallel, as `emit` first touches them.
    let mut nodes: Vec<BvhNode> = bytemuck::zeroed_vec(1 + desc);
    let mut prims = vec![0u32; slots];
    let (root, desc) = nodes.split_at_mut(1);
    emit(tree, &mut root[0], desc, 1, &mut prims, 0);
    (nodes, prims)
}

/// Writes the root of `tree` to `root`, its descendants to `desc` (whose first element is
/// node `base`), and its primitive slots to `prims` (whose first element is slot `slot_base`).
fn emit(
    tree: Subtree,
    root: &mut BvhNode,
    desc: &mut [BvhNode],
    base: u32,
    prims: &mut [u32],
    slot_base: u32,
) {
    match tree {
        Subtree::Nodes { nodes: v, prims: p } => {
            // Vector index i >= 1 lands at base + i - 1; slot j at slot_base + j.
            let delta = base - 1;
            *root = v[0].relinked(delta, slot_base);
            for (d, n) in desc.iter_mut().zip(&v[1..]) {
                *d = n.relinked(delta, slot_base);
            }
            prims.copy_from_slice(&p);
        }
        Subtree::Split { bounds, children } => {
            *root = BvhNode::inner(bounds, base);
            let [a, b] = *children;
            let (a_desc, a_slots) = sizes(&a);
            let (pair, rest) = desc.split_at_mut(2);
            let (ra, rb) = pair.split_at_mut(1);
            let (da, db) = rest.split_at_mut(a_desc);
            let (pa, pb) = prims.split_at_mut(a_slots);
            let base_b = base + 2 + a_desc as u32;
            let slots_b = slot_base + a_slots as u32;
            rayon::join(
                || emit(a, &mut ra[0], da, base + 2, pa, slot_base),
                || emit(b, &mut rb[0], db, base_b, pb, slots_b),
            );
        }
    }
}
