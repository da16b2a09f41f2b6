//! obvhs as a competitor: builds a `Bvh2` with one of its presets and converts it into the
//! canonical [`Bvh`], so that SAH cost and trace speed are measured with the same cost constants
//! and the same traversal code as rtc-bvh's own trees.
//!
//! Invariant: the conversion keeps obvhs's tree shape and boxes exactly; it only renumbers the
//! nodes into the depth-first sibling-pair order and rebuilds the primitive list in leaf order
//! (checked by [`Bvh::from_raw`]).

use glam::Vec3;
use obvhs::bvh2::Bvh2;
use obvhs::triangle::Triangle;
use obvhs::BvhBuildParams;
use rtc_bvh::{Aabb, Bvh, BvhNode};

/// The obvhs presets measured: its fastest and its highest-quality one.
pub const PRESETS: [(&str, BvhBuildParams); 2] = [
    ("obvhs fastest", BvhBuildParams::fastest_build()),
    ("obvhs very_slow", BvhBuildParams::very_slow_build()),
];

/// The triangles in obvhs's format (not timed).
pub fn triangles(tris: &[[Vec3; 3]]) -> Vec<Triangle> {
    tris.iter()
        .map(|t| Triangle {
            v0: t[0].into(),
            v1: t[1].into(),
            v2: t[2].into(),
        })
        .collect()
}

/// One obvhs build (this is what is timed).
pub fn build(tris: &[Triangle], params: BvhBuildParams) -> Bvh2 {
    let mut core = std::time::Duration::ZERO;
    obvhs::bvh2::builder::build_bvh2_from_tris(tris, params, &mut core)
}

/// The obvhs tree as a canonical BVH.
pub fn convert(b: &Bvh2, input_count: usize) -> Bvh {
    let aabb = |i: usize| {
        let a = b.nodes[i].aabb();
        Aabb {
            min: a.min,
            max: a.max,
        }
    };
    let mut nodes = vec![BvhNode::leaf(aabb(0), 0, 0)];
    let mut prims = Vec::with_capacity(b.primitive_indices.len());
    // (obvhs node, canonical slot), depth first, left child first.
    let mut stack = vec![(0usize, 0usize)];
    while let Some((src, dst)) = stack.pop() {
        let n = &b.nodes[src];
        if n.is_leaf() {
            let first = prims.len() as u32;
            let range = n.first_index as usize..(n.first_index + n.prim_count) as usize;
            prims.extend_from_slice(&b.primitive_indices[range]);
            nodes[dst] = BvhNode::leaf(aabb(src), first, n.prim_count);
        } else {
            let left = nodes.len();
            let c = n.first_index as usize;
            nodes[dst] = BvhNode::inner(aabb(src), left as u32);
            nodes.push(BvhNode::leaf(aabb(c), 0, 0));
            nodes.push(BvhNode::leaf(aabb(c + 1), 0, 0));
            stack.push((c + 1, left + 1));
            stack.push((c, left));
        }
    }
    match Bvh::from_raw(nodes, prims, input_count, b.uses_spatial_splits) {
        Ok(bvh) => bvh,
        Err(e) => panic!("obvhs tree does not convert: {e}"),
    }
}
