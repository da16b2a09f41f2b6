//! The full-precision node layout, [`GpuNode`], and [`flatten`], the only converter from the
//! canonical [`Bvh`] to it. The CPU reference in [`crate::traverse`] reads any BVH in it. The GPU
//! kernel reads every BVH (scene and object level) in the quantised layout of
//! [`crate::quantized`], whose 32-byte records ([`crate::NodeRecord`]) the kernel's node buffer
//! declares as its `GpuNode` struct (same size, alignment and field offsets as this one).
//!
//! # Layout of the node buffer
//!
//! * Node 0 is the root. If the BVH has more than one node, node 1 is a **padding node** (a
//!   leaf over zero primitives with the empty, inverted box, never referenced), so that every
//!   sibling pair starts at an even index: with the buffer's base 64-byte aligned (wgpu aligns
//!   buffers to at least 256 bytes) each pair is exactly one aligned 64-byte block, and a
//!   traversal step that tests both children reads one block.
//! * Canonical node `i >= 1` is GPU node `i + 1`; the depth-first sibling-pair order of
//!   [`crate::bvh`] is kept, so descending into a left child walks forward through memory.
//! * Leaves index into the **reordered** primitive list: slot `s` is primitive
//!   [`Bvh::prim_indices`]`[s]` of the input, and a GPU primitive buffer built with
//!   [`Bvh::reorder`] can be read at `s` directly.
//! * An empty BVH is one node: a leaf over zero primitives with the inverted box, which every
//!   ray misses; there is no zero-sized buffer to special-case.
//!
//! # Bits of [`GpuNode`] (32 bytes, 16-byte aligned)
//!
//! | bytes | field | inner node | leaf |
//! |---|---|---|---|
//! | 0..12 | `min` | box minimum | box minimum |
//! | 12..16 | `a` | index of the left child; the right child is `a + 1`; `a` is even and `>= 2` | first slot in the reordered primitive list |
//! | 16..28 | `max` | box maximum | box maximum |
//! | 28..32 | `b` | bit 31 = 0; bits 0..=30 = 0 (reserved) | bit 31 = 1 ([`GpuNode::LEAF_BIT`]); bits 0..=30 = primitive count ([`GpuNode::COUNT_MASK`]) |
//!
//! Boxes are finite. Only the padding node and the empty root have `min > max` (all `+f32::MAX`
//! vs `-f32::MAX`). In WGSL the struct is `struct GpuNode { min: vec3<f32>, a: u32, max:
//! vec3<f32>, b: u32 }`, which has the same size (32), alignment (16) and offsets (0, 12, 16,
//! 28) under the storage-buffer layout rules.

use bytemuck::{Pod, Zeroable};
use rayon::prelude::*;

use crate::aabb::Aabb;
use crate::bvh::{Bvh, BvhNode};

/// One node of the GPU node buffer; see the module docs for every bit.
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
#[repr(C, align(16))]
pub struct GpuNode {
    /// Box minimum.
    pub min: [f32; 3],
    /// Inner: left child index (right child is `a + 1`). Leaf: first primitive slot.
    pub a: u32,
    /// Box maximum.
    pub max: [f32; 3],
    /// Bit 31: leaf flag. Leaf: bits 0..=30 hold the primitive count. Inner: 0.
    pub b: u32,
}

static_assertions::assert_eq_size!(GpuNode, [u8; 32]);
static_assertions::const_assert_eq!(std::mem::align_of::<GpuNode>(), 16);
static_assertions::const_assert_eq!(std::mem::offset_of!(GpuNode, min), 0);
static_assertions::const_assert_eq!(std::mem::offset_of!(GpuNode, a), 12);
static_assertions::const_assert_eq!(std::mem::offset_of!(GpuNode, max), 16);
static_assertions::const_assert_eq!(std::mem::offset_of!(GpuNode, b), 28);

impl GpuNode {
    /// Bit 31 of `b`: set for leaves.
    pub const LEAF_BIT: u32 = 1 << 31;
    /// Bits 0..=30 of `b`: a leaf's primitive count.
    pub const COUNT_MASK: u32 = !Self::LEAF_BIT;
    /// Largest primitive count a leaf can encode.
    pub const MAX_LEAF_COUNT: u32 = Self::COUNT_MASK;

    /// The padding node at index 1 (and the shape of an empty root): a leaf over nothing with
    /// the inverted box.
    pub const PADDING: GpuNode = GpuNode {
        min: [f32::MAX; 3],
        a: 0,
        max: [-f32::MAX; 3],
        b: Self::LEAF_BIT,
    };

    /// True for a leaf.
    #[inline(always)]
    pub fn is_leaf(&self) -> bool {
        self.b & Self::LEAF_BIT != 0
    }

    /// A leaf's primitive count (0 for inner nodes).
    #[inline(always)]
    pub fn count(&self) -> u32 {
        if self.is_leaf() {
            self.b & Self::COUNT_MASK
        } else {
            0
        }
    }

    /// The node's box.
    #[inline(always)]
    pub fn aabb(&self) -> Aabb {
        Aabb {
            min: self.min.into(),
            max: self.max.into(),
        }
    }

    #[inline]
    fn from_canonical(n: &BvhNode) -> Self {
        let (a, b) = if n.count == BvhNode::INNER {
            // Canonical children at (left, left + 1) with left >= 1 shift by one for the padding.
            (n.index + 1, 0)
        } else {
            debug_assert!(n.count <= Self::MAX_LEAF_COUNT);
            (n.index, Self::LEAF_BIT | n.count)
        };
        Self {
            min: n.min.into(),
            a,
            max: n.max.into(),
            b,
        }
    }
}

/// Node counts from which [`flatten`] converts in parallel.
const PAR_FLATTEN_MIN: usize = 1 << 15;

/// Converts the canonical BVH to the GPU node buffer (see the module docs). The primitive list
/// that goes with it is [`Bvh::prim_indices`] (or the primitives reordered by
/// [`Bvh::reorder`]); the traversal stack needs [`Bvh::max_depth`] entries.
pub fn flatten(bvh: &Bvh) -> Vec<GpuNode> {
    let nodes = bvh.nodes();
    let convert = |i: usize| match i {
        0 => GpuNode::from_canonical(&nodes[0]),
        1 => GpuNode::PADDING,
        _ => GpuNode::from_canonical(&nodes[i - 1]),
    };
    let len = if nodes.len() > 1 { nodes.len() + 1 } else { 1 };
    if len < PAR_FLATTEN_MIN {
        (0..len).map(convert).collect()
    } else {
        (0..len)
            .into_par_iter()
            .with_min_len(PAR_FLATTEN_MIN / 4)
            .map(convert)
            .collect()
    }
}
