//! The canonical BVH: a binary tree of boxes over primitive indices, the one structure every
//! builder produces and every converter ([`crate::gpu::flatten`]) and statistic reads.
//!
//! # Layout invariants (checked by [`Bvh::validate`])
//!
//! 1. `nodes` is never empty. Node 0 is the root. A BVH over zero primitives is a single leaf
//!    with `count == 0` and the empty box [`Aabb::EMPTY`], which every ray misses.
//! 2. **Sibling pairs, depth-first.** The two children of an inner node are adjacent: left at
//!    `left`, right at `left + 1`. Pairs are laid out in depth-first pre-order: the root's pair
//!    is `(1, 2)`; the descendants of the left child all come before the right child's pair.
//!    A traversal that descends into the left child therefore walks forward through memory, and
//!    a subtree is one contiguous range of pairs. Every node is reachable from the root exactly
//!    once, so `nodes.len() == 2 * leaf_count - 1`.
//! 3. **Leaves cover the primitive list in order.** Visiting leaves in depth-first order, leaf
//!    `k` owns `prim_indices[first .. first + count]` and `first` is the sum of the counts of the
//!    leaves before it; the ranges tile `prim_indices` exactly. Every leaf except the empty
//!    root has `1 <= count`.
//! 4. **Boxes nest.** Every box is finite with `min <= max`, and a child's box lies inside its
//!    parent's box. A leaf's box holds the boxes of its primitives (for spatial splits: the part
//!    of the primitive that the leaf is responsible for; see [`Bvh::has_spatial_splits`]).
//! 5. `prim_indices` holds indices into the builder's input (`< input_count`). Without spatial
//!    splits each accepted primitive appears exactly once; with them a primitive may appear in
//!    several leaves. Rejected input primitives (see [`crate::input`]) never appear.
//! 6. Depth (edges from the root) never exceeds [`MAX_DEPTH`].

use bytemuck::Zeroable;
use glam::Vec3;

use crate::aabb::Aabb;
use crate::preset::SahCost;

/// Upper bound on [`Bvh::max_depth`] for every BVH this crate builds or accepts. The builders
/// stay below it by switching from SAH splits to median splits deep in the tree (see
/// [`mod@crate::build`]); a GPU traversal stack of [`Bvh::max_depth`] entries is always enough.
pub const MAX_DEPTH: u32 = 128;

/// What a node is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodeKind {
    /// An inner node; children at `nodes[left]` and `nodes[left + 1]`.
    Inner {
        /// Index of the left child; the right child follows it.
        left: u32,
    },
    /// A leaf owning `prim_indices[first .. first + count]`.
    Leaf {
        /// First slot in [`Bvh::prim_indices`].
        first: u32,
        /// Number of slots.
        count: u32,
    },
}

/// One node of the canonical BVH: a box and a [`NodeKind`], stored in 32 bytes (the build of a
/// 10M-triangle scene holds about 11M of them). Read it with [`BvhNode::aabb`] and
/// [`BvhNode::kind`].
#[derive(Clone, Copy, Debug, PartialEq, Zeroable)]
#[repr(C)]
pub struct BvhNode {
    pub(crate) min: Vec3,
    /// Inner: left child. Leaf: first slot.
    pub(crate) index: u32,
    pub(crate) max: Vec3,
    /// Leaf: slot count. Inner: [`BvhNode::INNER`].
    pub(crate) count: u32,
}

static_assertions::assert_eq_size!(BvhNode, [u8; 32]);

impl BvhNode {
    /// `count` of an inner node (leaf counts never reach it: see [`crate::GpuNode::MAX_LEAF_COUNT`]).
    pub(crate) const INNER: u32 = u32::MAX;

    /// An inner node whose children are at `left` and `left + 1`.
    #[inline]
    pub fn inner(aabb: Aabb, left: u32) -> Self {
        Self {
            min: aabb.min.into(),
            index: left,
            max: aabb.max.into(),
            count: Self::INNER,
        }
    }

    /// A leaf over `count` slots starting at `first`.
    #[inline]
    pub fn leaf(aabb: Aabb, first: u32, count: u32) -> Self {
        Self {
            min: aabb.min.into(),
            index: first,
            max: aabb.max.into(),
            count: count.min(Self::INNER - 1),
        }
    }

    /// The node's box.
    #[inline]
    pub fn aabb(&self) -> Aabb {
        Aabb::new(self.min, self.max)
    }

    /// Inner node or leaf.
    #[inline]
    pub fn kind(&self) -> NodeKind {
        if self.count == Self::INNER {
            NodeKind::Inner { left: self.index }
        } else {
            NodeKind::Leaf {
                first: self.index,
                count: self.count,
            }
        }
    }

    /// True for a leaf.
    #[inline]
    pub fn is_leaf(&self) -> bool {
        self.count != Self::INNER
    }

    /// The same node with the left-child index moved by `node_delta` (inner nodes) or the first
    /// slot moved by `slot_delta` (leaves): used when a subtree built on its own is spliced into
    /// the final vectors.
    #[inline]
    pub(crate) fn relinked(mut self, node_delta: u32, slot_delta: u32) -> Self {
        self.index += if self.count == Self::INNER {
            node_delta
        } else {
            slot_delta
        };
        self
    }
}

/// A broken layout invariant (see the module docs), with the offending node.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LayoutError {
    /// `nodes` is empty.
    NoNodes,
    /// A child index does not follow the depth-first pair order (or is out of range).
    ChildOrder {
        /// The inner node.
        node: u32,
        /// Its stored left child.
        left: u32,
        /// Where the layout requires it.
        expected: u32,
    },
    /// Some nodes are not reachable from the root.
    Unreachable {
        /// Reachable nodes.
        reached: usize,
        /// Stored nodes.
        total: usize,
    },
    /// A leaf range does not continue where the previous one ended, is empty, holds more than
    /// [`crate::GpuNode::MAX_LEAF_COUNT`] slots, or runs past `prim_indices`.
    LeafRange {
        /// The leaf.
        node: u32,
        /// Its first slot.
        first: u32,
        /// Its count.
        count: u32,
        /// Where the range must start.
        expected_first: u32,
    },
    /// The leaf ranges do not cover `prim_indices` exactly.
    UncoveredSlots {
        /// Slots covered by leaves.
        covered: usize,
        /// Length of `prim_indices`.
        total: usize,
    },
    /// A box is not finite or has `min > max` (other than the empty root).
    BadBox {
        /// The node.
        node: u32,
    },
    /// A child box is not inside its parent's box.
    ChildOutsideParent {
        /// The child node.
        node: u32,
    },
    /// A primitive index is not below the input count.
    PrimOutOfRange {
        /// Slot in `prim_indices`.
        slot: u32,
        /// The stored index.
        prim: u32,
    },
    /// The tree is deeper than [`MAX_DEPTH`].
    TooDeep {
        /// Its depth.
        depth: u32,
    },
}

impl std::fmt::Display for LayoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid BVH layout: {self:?}")
    }
}

impl std::error::Error for LayoutError {}

/// Node and leaf statistics of a BVH.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhStats {
    /// All nodes.
    pub node_count: usize,
    /// Leaves.
    pub leaf_count: usize,
    /// Longest root-to-leaf path in edges (see [`Bvh::max_depth`]).
    pub max_depth: u32,
    /// Mean references per leaf.
    pub avg_leaf_size: f32,
    /// Largest leaf.
    pub max_leaf_size: u32,
    /// Length of the primitive index list (more than the primitive count with spatial splits).
    pub prim_refs: usize,
    /// [`Bvh::sah_cost`] with [`SahCost::STANDARD`].
    pub sah_cost: f32,
}

/// The canonical binary BVH. See the module docs for its invariants; every constructor
/// establishes them.
#[derive(Clone, Debug)]
pub struct Bvh {
    nodes: Vec<BvhNode>,
    prim_indices: Vec<u32>,
    input_count: usize,
    spatial_splits: bool,
}

impl Bvh {
    /// The BVH over nothing: one empty leaf.
    pub fn empty(input_count: usize) -> Self {
        Self {
            nodes: vec![BvhNode::leaf(Aabb::EMPTY, 0, 0)],
            prim_indices: Vec::new(),
            input_count,
            spatial_splits: false,
        }
    }

    /// Builder output, trusted (checked in debug builds).
    pub(crate) fn from_builder(
        nodes: Vec<BvhNode>,
        prim_indices: Vec<u32>,
        input_count: usize,
        spatial_splits: bool,
    ) -> Self {
        let bvh = Self {
            nodes,
            prim_indices,
            input_count,
            spatial_splits,
        };
        debug_assert_eq!(bvh.validate(), Ok(()));
        bvh
    }

    /// Wraps nodes and indices made elsewhere (a converted tree from another builder, say),
    /// checking every layout invariant. `input_count` is the number of input primitives the
    /// indices refer to; `spatial_splits` says whether a primitive may appear in several leaves.
    pub fn from_raw(
        nodes: Vec<BvhNode>,
        prim_indices: Vec<u32>,
        input_count: usize,
        spatial_splits: bool,
    ) -> Result<Self, LayoutError> {
        let bvh = Self {
            nodes,
            prim_indices,
            input_count,
            spatial_splits,
        };
        bvh.validate()?;
        Ok(bvh)
    }

    /// The nodes, root first, in the depth-first sibling-pair order.
    pub fn nodes(&self) -> &[BvhNode] {
        &self.nodes
    }

    /// Input primitive index of every leaf slot.
    pub fn prim_indices(&self) -> &[u32] {
        &self.prim_indices
    }

    /// Number of input primitives (accepted or rejected) the BVH was built over.
    pub fn input_count(&self) -> usize {
        self.input_count
    }

    /// True when the builder used spatial splits, so a primitive may be referenced by several
    /// leaves and a leaf's box may cut through a primitive.
    pub fn has_spatial_splits(&self) -> bool {
        self.spatial_splits
    }

    /// True when the BVH holds no primitive.
    pub fn is_empty(&self) -> bool {
        self.prim_indices.is_empty()
    }

    /// Box of the whole BVH ([`Aabb::EMPTY`] for an empty one).
    pub fn root_aabb(&self) -> Aabb {
        self.nodes[0].aabb()
    }

    /// `items` reordered by the primitive index list, so that leaf slot `i` can read
    /// `result[i]` directly instead of `items[prim_indices[i]]` (the GPU primitive buffer).
    pub fn reorder<T: Clone>(&self, items: &[T]) -> Vec<T> {
        self.prim_indices
            .iter()
            .map(|&p| items[p as usize].clone())
            .collect()
    }

    /// Calls `f(node index, depth)` for every node in depth-first pre-order.
    fn for_each_node(&self, mut f: impl FnMut(u32, u32)) {
        let mut stack = vec![(0u32, 0u32)];
        while let Some((i, depth)) = stack.pop() {
            f(i, depth);
            if let NodeKind::Inner { left } = self.nodes[i as usize].kind() {
                stack.push((left + 1, depth + 1));
                stack.push((left, depth + 1));
            }
        }
    }

    /// Longest root-to-leaf path, in edges (a lone root leaf has depth 0). A traversal stack of
    /// this many entries suffices for the near-first traversal in [`crate::traverse`]: at a node
    /// of depth `d` the stack holds at most one deferred sibling per ancestor, so at most `d`.
    pub fn max_depth(&self) -> u32 {
        let mut max = 0;
        self.for_each_node(|_, d| max = max.max(d));
        max
    }

    /// SAH cost of the whole tree: `sum over inner nodes of traversal * A(n) + sum over leaves
    /// of intersection * count * A(n)`, divided by `A(root)`, where `A` is the surface area. A
    /// root of zero area (all primitives on a point or a line) weighs every node by 1. An empty
    /// BVH costs 0.
    pub fn sah_cost(&self, cost: SahCost) -> f32 {
        if self.is_empty() {
            return 0.0;
        }
        let root_area = f64::from(self.root_aabb().half_area());
        let mut total = 0.0f64;
        for n in &self.nodes {
            let w = if root_area > 0.0 {
                f64::from(n.aabb().half_area()) / root_area
            } else {
                1.0
            };
            total += w * match n.kind() {
                NodeKind::Inner { .. } => f64::from(cost.traversal),
                NodeKind::Leaf { count, .. } => f64::from(cost.intersection) * f64::from(count),
            };
        }
        total as f32
    }

    /// Node counts, depth, leaf sizes and SAH cost.
    pub fn stats(&self) -> BvhStats {
        let mut leaf_count = 0;
        let mut max_leaf_size = 0;
        for n in &self.nodes {
            if let NodeKind::Leaf { count, .. } = n.kind() {
                leaf_count += 1;
                max_leaf_size = max_leaf_size.max(count);
            }
        }
        BvhStats {
            node_count: self.nodes.len(),
            leaf_count,
            max_depth: self.max_depth(),
            avg_leaf_size: self.prim_indices.len() as f32 / leaf_count.max(1) as f32,
            max_leaf_size,
            prim_refs: self.prim_indices.len(),
            sah_cost: self.sah_cost(SahCost::STANDARD),
        }
    }

    /// Checks every invariant of the module docs.
    pub fn validate(&self) -> Result<(), LayoutError> {
        if self.nodes.is_empty() {
            return Err(LayoutError::NoNodes);
        }
        if self.is_empty() && self.nodes.len() == 1 {
            // The empty BVH: one leaf over nothing.
            return match self.nodes[0].kind() {
                NodeKind::Leaf { count: 0, .. } => Ok(()),
                _ => Err(LayoutError::UncoveredSlots {
                    covered: 0,
                    total: 0,
                }),
            };
        }
        for (slot, &prim) in self.prim_indices.iter().enumerate() {
            if prim as usize >= self.input_count {
                return Err(LayoutError::PrimOutOfRange {
                    slot: slot as u32,
                    prim,
                });
            }
        }
        let mut next_pair = 1u32;
        let mut next_slot = 0u32;
        let mut reached = 0usize;
        // (node, depth, parent box)
        let mut stack = vec![(0u32, 0u32, None::<Aabb>)];
        while let Some((i, depth, parent)) = stack.pop() {
            reached += 1;
            if depth > MAX_DEPTH {
                return Err(LayoutError::TooDeep { depth });
            }
            let node = &self.nodes[i as usize];
            let b = node.aabb();
            if !b.is_finite() || b.is_empty() {
                return Err(LayoutError::BadBox { node: i });
            }
            if parent.is_some_and(|p| !p.contains(&b)) {
                return Err(LayoutError::ChildOutsideParent { node: i });
            }
            match node.kind() {
                NodeKind::Inner { left } => {
                    if left != next_pair || left as usize + 1 >= self.nodes.len() {
                        return Err(LayoutError::ChildOrder {
                            node: i,
                            left,
                            expected: next_pair,
                        });
                    }
                    next_pair += 2;
                    stack.push((left + 1, depth + 1, Some(b)));
                    stack.push((left, depth + 1, Some(b)));
                }
                NodeKind::Leaf { first, count } => {
                    let end = u64::from(first) + u64::from(count);
                    if first != next_slot
                        || count == 0
                        || count > crate::gpu::GpuNode::MAX_LEAF_COUNT
                        || end > self.prim_indices.len() as u64
                    {
                        return Err(LayoutError::LeafRange {
                            node: i,
                            first,
                            count,
                            expected_first: next_slot,
                        });
                    }
                    next_slot += count;
                }
            }
        }
        if reached != self.nodes.len() {
            return Err(LayoutError::Unreachable {
                reached,
                total: self.nodes.len(),
            });
        }
        if next_slot as usize != self.prim_indices.len() {
            return Err(LayoutError::UncoveredSlots {
                covered: next_slot as usize,
                total: self.prim_indices.len(),
            });
        }
        Ok(())
    }
}
