//! The GPU node layout and the tree invariants: `GpuNode` against naga's WGSL layout rules,
//! the bits written by `flatten`, the depth-first sibling-pair order, leaf ranges, primitive
//! coverage, depth bounds, SAH arithmetic, layout validation, build determinism, and the
//! quantised mesh layout (`rtc_bvh::quantized`).

mod common;

use glam::Vec3;
use rtc_bvh::quantized::{quantize, Child, QuantizeError, QuantizedBvh, MAX_LEAF_COUNT};
use rtc_bvh::{
    build, flatten, Aabb, BuildInput, BuildPreset, Bvh, BvhNode, GpuNode, LayoutError, NodeKind,
    SahCost, MAX_DEPTH,
};

/// The WGSL twin of [`GpuNode`] that the traversal kernel declares.
const GPU_NODE_WGSL: &str = "struct GpuNode { min: vec3<f32>, a: u32, max: vec3<f32>, b: u32 }\n\
                             @group(0) @binding(0) var<storage, read> nodes: array<GpuNode>;";

#[test]
fn gpu_node_matches_the_wgsl_layout() {
    let module = naga::front::wgsl::parse_str(GPU_NODE_WGSL).expect("valid WGSL");
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).expect("layout");
    let (handle, ty) = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some("GpuNode"))
        .expect("GpuNode type");
    let naga::TypeInner::Struct { members, span } = &ty.inner else {
        panic!("GpuNode is not a struct");
    };
    assert_eq!(*span as usize, size_of::<GpuNode>());
    assert_eq!(layouter[handle].size as usize, size_of::<GpuNode>());
    assert_eq!(
        naga::proc::Alignment::new(align_of::<GpuNode>() as u32),
        Some(layouter[handle].alignment)
    );
    let rust = [
        ("min", std::mem::offset_of!(GpuNode, min)),
        ("a", std::mem::offset_of!(GpuNode, a)),
        ("max", std::mem::offset_of!(GpuNode, max)),
        ("b", std::mem::offset_of!(GpuNode, b)),
    ];
    assert_eq!(members.len(), rust.len());
    for (m, (name, offset)) in members.iter().zip(rust) {
        assert_eq!(m.name.as_deref(), Some(name));
        assert_eq!(m.offset as usize, offset, "offset of {name}");
    }
    assert_eq!(size_of::<GpuNode>(), 32);
}

/// Checks every bit `flatten` writes against the canonical tree.
fn check_flattened(bvh: &Bvh) {
    let canon = bvh.nodes();
    let gpu = flatten(bvh);
    assert_eq!(gpu.len(), if canon.len() > 1 { canon.len() + 1 } else { 1 });
    if canon.len() > 1 {
        assert_eq!(gpu[1], GpuNode::PADDING, "node 1 is the padding node");
    }
    let gpu_index = |i: usize| if i == 0 { 0 } else { i + 1 };
    for (i, n) in canon.iter().enumerate() {
        let g = gpu[gpu_index(i)];
        let b = n.aabb();
        assert_eq!(
            (g.min, g.max),
            (<[f32; 3]>::from(b.min), <[f32; 3]>::from(b.max))
        );
        match n.kind() {
            NodeKind::Inner { left } => {
                assert!(!g.is_leaf());
                assert_eq!(g.b, 0, "inner nodes keep b zero");
                assert_eq!(g.a as usize, gpu_index(left as usize));
                assert_eq!(g.a % 2, 0, "sibling pairs start at even indices");
            }
            NodeKind::Leaf { first, count } => {
                assert!(g.is_leaf());
                assert_eq!(g.b, GpuNode::LEAF_BIT | count);
                assert_eq!((g.a, g.count()), (first, count));
            }
        }
    }
}

/// Walks the GPU nodes in depth-first pre-order and checks the pair order, the leaf tiling and
/// the depth.
fn check_depth_first(bvh: &Bvh) {
    let gpu = flatten(bvh);
    let mut next_pair = 2u32;
    let mut next_slot = 0u32;
    let mut max_depth = 0;
    let mut stack = vec![(0u32, 0u32)];
    while let Some((i, d)) = stack.pop() {
        max_depth = max_depth.max(d);
        let n = gpu[i as usize];
        if n.is_leaf() {
            assert_eq!(n.a, next_slot, "leaf ranges follow depth-first order");
            next_slot += n.count();
        } else {
            assert_eq!(n.a, next_pair, "children are the next pair in pre-order");
            next_pair += 2;
            // Children lie inside the parent.
            for c in [n.a, n.a + 1] {
                assert!(n.aabb().contains(&gpu[c as usize].aabb()));
            }
            stack.push((n.a + 1, d + 1));
            stack.push((n.a, d + 1));
        }
    }
    assert_eq!(next_slot as usize, bvh.prim_indices().len());
    assert_eq!(max_depth, bvh.max_depth());
    assert!(bvh.max_depth() <= MAX_DEPTH);
}

/// Without spatial splits every primitive is referenced exactly once and every leaf box holds
/// its primitives' boxes; with them, at least once.
fn check_coverage(bvh: &Bvh, tris: &[[Vec3; 3]]) {
    let mut seen = vec![0u32; tris.len()];
    for &p in bvh.prim_indices() {
        seen[p as usize] += 1;
    }
    if bvh.has_spatial_splits() {
        assert!(seen.iter().all(|&s| s >= 1));
    } else {
        assert!(seen.iter().all(|&s| s == 1));
        for n in bvh.nodes() {
            if let NodeKind::Leaf { first, count } = n.kind() {
                for &p in &bvh.prim_indices()[first as usize..(first + count) as usize] {
                    assert!(n.aabb().contains(&Aabb::from_triangle(&tris[p as usize])));
                }
            }
        }
    }
}

#[test]
fn flattened_trees_keep_every_invariant() {
    let scenes = [
        ("sphere", common::sphere(Vec3::ZERO, 1.0, 16, 24)),
        ("soup", common::soup(5000, 1)),
        ("thesis-like", common::thesis_like()),
    ];
    for (name, tris) in &scenes {
        for preset in BuildPreset::ALL {
            let bvh = build(BuildInput::Triangles(tris), preset);
            bvh.validate()
                .unwrap_or_else(|e| panic!("{name} {preset:?}: {e}"));
            check_flattened(&bvh);
            check_depth_first(&bvh);
            check_coverage(&bvh, tris);
            let s = bvh.stats();
            assert_eq!(s.node_count, 2 * s.leaf_count - 1);
            assert_eq!(s.prim_refs, bvh.prim_indices().len());
            assert!(s.max_leaf_size <= preset.params().max_leaf_size);
            assert!(s.sah_cost.is_finite() && s.sah_cost >= 1.0);
        }
    }
}

#[test]
fn quality_splits_long_slivers_and_fast_does_not() {
    let tris = common::soup(5000, 1);
    assert!(!build(BuildInput::Triangles(&tris), BuildPreset::Fast).has_spatial_splits());
    let q = build(BuildInput::Triangles(&tris), BuildPreset::Quality);
    assert!(q.has_spatial_splits(), "the slivers should be split");
    assert!(q.prim_indices().len() > tris.len());
    // The duplication budget holds.
    let budget = BuildPreset::Quality
        .params()
        .spatial_splits
        .unwrap()
        .max_duplication;
    assert!(q.prim_indices().len() as f32 <= tris.len() as f32 * (1.0 + budget));
}

#[test]
fn the_size_split_isolates_a_large_floor() {
    // Two huge floor triangles whose centroids lie in opposite corners, and small spheres in
    // the middle: the best tree keeps the floor in one leaf right below the root, SAH about 3.
    let tris = common::thesis_like();
    for preset in BuildPreset::ALL {
        let bvh = build(BuildInput::Triangles(&tris), preset);
        let root = bvh.nodes()[0];
        let NodeKind::Inner { left } = root.kind() else {
            panic!("root is a leaf")
        };
        let floor_leaf = bvh.nodes()[left as usize..left as usize + 2]
            .iter()
            .any(|n| {
                matches!(n.kind(), NodeKind::Leaf { count: 2, first } if {
                    let mut p = bvh.prim_indices()[first as usize..first as usize + 2].to_vec();
                    p.sort();
                    p == [0, 1]
                })
            });
        assert!(
            floor_leaf,
            "{preset:?}: the floor is a child leaf of the root"
        );
        let sah = bvh.sah_cost(SahCost::STANDARD);
        assert!(sah < 3.2, "{preset:?}: SAH {sah}");
    }
}

#[test]
fn sah_cost_of_a_hand_built_tree() {
    // Root over two unit cubes at x = 0 and x = 2: root box 3x1x1 (half area 7), each child
    // half area 3. Cost = 1 (root) + 3/7 + 3/7 (one primitive per leaf).
    let a = Aabb::new(Vec3::ZERO, Vec3::ONE);
    let b = Aabb::new(Vec3::new(2.0, 0.0, 0.0), Vec3::new(3.0, 1.0, 1.0));
    let nodes = vec![
        BvhNode::inner(a.union(&b), 1),
        BvhNode::leaf(a, 0, 1),
        BvhNode::leaf(b, 1, 1),
    ];
    let bvh = Bvh::from_raw(nodes, vec![0, 1], 2, false).unwrap();
    let cost = bvh.sah_cost(SahCost::STANDARD);
    assert!((cost - (1.0 + 6.0 / 7.0)).abs() < 1e-6, "{cost}");
    assert_eq!(bvh.max_depth(), 1);
    // The builder minimising the standard cost finds the same tree (split cost 1 + 6/7 below the
    // leaf's 2). Fast prices a traversal step at 1.5 (1.5 + 6/7 > 2) and keeps one leaf.
    let built = build(BuildInput::Aabbs(&[a, b]), BuildPreset::Quality);
    assert!((built.sah_cost(SahCost::STANDARD) - cost).abs() < 1e-6);
    let fast = build(BuildInput::Aabbs(&[a, b]), BuildPreset::Fast);
    assert_eq!(fast.nodes().len(), 1);
    assert_eq!(fast.sah_cost(SahCost::STANDARD), 2.0);
}

#[test]
fn from_raw_rejects_broken_layouts() {
    let a = Aabb::new(Vec3::ZERO, Vec3::ONE);
    let b = Aabb::new(Vec3::new(2.0, 0.0, 0.0), Vec3::new(3.0, 1.0, 1.0));
    let root = BvhNode::inner(a.union(&b), 1);
    let ok = || vec![root, BvhNode::leaf(a, 0, 1), BvhNode::leaf(b, 1, 1)];
    assert!(Bvh::from_raw(ok(), vec![0, 1], 2, false).is_ok());
    assert!(matches!(
        Bvh::from_raw(vec![], vec![], 0, false),
        Err(LayoutError::NoNodes)
    ));
    let mut bad = ok();
    bad[0] = BvhNode::inner(a.union(&b), 2);
    assert!(matches!(
        Bvh::from_raw(bad, vec![0, 1], 2, false),
        Err(LayoutError::ChildOrder { .. })
    ));
    let mut bad = ok();
    bad[2] = BvhNode::leaf(b, 0, 1);
    assert!(matches!(
        Bvh::from_raw(bad, vec![0, 1], 2, false),
        Err(LayoutError::LeafRange { .. })
    ));
    assert!(matches!(
        Bvh::from_raw(ok(), vec![0, 5], 2, false),
        Err(LayoutError::PrimOutOfRange { .. })
    ));
    let mut bad = ok();
    bad[1] = BvhNode::leaf(Aabb::new(Vec3::ZERO, Vec3::splat(9.0)), 0, 1);
    assert!(matches!(
        Bvh::from_raw(bad, vec![0, 1], 2, false),
        Err(LayoutError::ChildOutsideParent { .. })
    ));
    let mut bad = ok();
    bad.push(BvhNode::leaf(a, 0, 1));
    assert!(matches!(
        Bvh::from_raw(bad, vec![0, 1], 2, false),
        Err(LayoutError::Unreachable { .. })
    ));
}

#[test]
fn builds_are_deterministic_across_thread_counts() {
    // Large enough for parallel subtrees, binning and partitioning (at least 2^16 references
    // at the root), and for parallel spatial binning (2^15) with the quality preset; kept as
    // small as that allows, since this runs in debug builds.
    for (preset, n) in [(BuildPreset::Fast, 66_000), (BuildPreset::Quality, 33_000)] {
        let tris = common::soup(n, 9);
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let four = rayon::ThreadPoolBuilder::new()
            .num_threads(4)
            .build()
            .unwrap();
        let a = one.install(|| build(BuildInput::Triangles(&tris), preset));
        let b = four.install(|| build(BuildInput::Triangles(&tris), preset));
        assert_eq!(a.nodes(), b.nodes(), "{preset:?}");
        assert_eq!(a.prim_indices(), b.prim_indices(), "{preset:?}");
    }
}

/// Checks the quantised mesh layout against the canonical tree: one record per inner node (record
/// `r` for canonical pair `r`), references that name the same children, leaf ranges unchanged, and
/// boxes that contain the exact ones whichever way the kernel rounds `origin + q * scale`.
fn check_quantized(bvh: &Bvh, name: &str) {
    let q = quantize(bvh).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(q.to_records().len(), q.nodes.len() + 1);
    assert_eq!(
        QuantizedBvh::from_records(&q.to_records()).as_ref(),
        Some(&q)
    );
    let nodes = bvh.nodes();
    let inner = nodes.iter().filter(|n| !n.is_leaf()).count();
    assert_eq!(q.nodes.len(), inner, "{name}: one record per inner node");
    // Walk both trees together.
    let mut stack = vec![(0usize, Child::decode(q.header.root))];
    let mut next_record = 1;
    let h = q.header;
    while let Some((i, child)) = stack.pop() {
        match (nodes[i].kind(), child) {
            (NodeKind::Leaf { first, count }, Child::Leaf { first: f, count: c }) => {
                assert_eq!((first, count), (f, c), "{name}: leaf {i}");
                assert_ne!(
                    Child::Leaf { first, count }.encode(),
                    u32::MAX,
                    "{name}: marker"
                );
            }
            (NodeKind::Inner { left }, Child::Inner(record)) => {
                assert_eq!(
                    record,
                    left.div_ceil(2),
                    "{name}: record r is canonical pair r"
                );
                next_record += 1;
                let n = q.node(record);
                // Right first, so the left subtree is walked first (pre-order).
                for (k, (packed, bits)) in [(n.left_box, n.left), (n.right_box, n.right)]
                    .into_iter()
                    .enumerate()
                    .rev()
                {
                    let exact = nodes[left as usize + k].aabb();
                    let lo = [packed[0] & 0xffff, packed[0] >> 16, packed[1] & 0xffff];
                    let hi = [packed[1] >> 16, packed[2] & 0xffff, packed[2] >> 16];
                    for a in 0..3 {
                        let point = |b: u32| {
                            let twice = h.origin[a] + b as f32 * h.scale[a];
                            let fused = (b as f32).mul_add(h.scale[a], h.origin[a]);
                            (twice.min(fused), twice.max(fused))
                        };
                        assert!(
                            point(lo[a]).1 <= exact.min[a],
                            "{name}: low bound, axis {a}"
                        );
                        assert!(
                            point(hi[a]).0 >= exact.max[a],
                            "{name}: high bound, axis {a}"
                        );
                        assert!(lo[a] <= hi[a]);
                    }
                    stack.push((left as usize + k, Child::decode(bits)));
                }
            }
            (kind, child) => panic!("{name}: node {i} is {kind:?} but its reference is {child:?}"),
        }
    }
    assert_eq!(next_record as usize, inner + 1);
}

#[test]
fn quantized_mesh_layout_keeps_the_tree_and_conservative_boxes() {
    let offset = |tris: Vec<[Vec3; 3]>, by: Vec3, scale: f32| -> Vec<[Vec3; 3]> {
        tris.into_iter()
            .map(|t| t.map(|v| v * scale + by))
            .collect()
    };
    let scenes = [
        ("sphere", common::sphere(Vec3::ZERO, 1.0, 16, 24)),
        ("soup", common::soup(5000, 1)),
        ("thesis-like", common::thesis_like()),
        // Far from the origin and small: bounds are coarser than one rounding step of the origin.
        (
            "far and small",
            offset(
                common::sphere(Vec3::ZERO, 1.0, 8, 12),
                Vec3::splat(1e6),
                1e-3,
            ),
        ),
        (
            "tiny",
            offset(common::sphere(Vec3::ZERO, 1.0, 8, 12), Vec3::ZERO, 1e-30),
        ),
        ("huge", offset(common::soup(500, 3), Vec3::ZERO, 1e15)),
        (
            "flat",
            vec![
                [Vec3::ZERO, Vec3::X, Vec3::Z],
                [Vec3::X, Vec3::X + Vec3::Z, Vec3::Z],
            ],
        ),
    ];
    for (name, tris) in &scenes {
        for preset in BuildPreset::ALL {
            let bvh = build(BuildInput::Triangles(tris), preset);
            check_quantized(&bvh, &format!("{name} {preset:?}"));
        }
    }
    let empty = quantize(&build(BuildInput::Triangles(&[]), BuildPreset::Fast)).unwrap();
    assert!(empty.nodes.is_empty());
    assert_eq!(
        Child::decode(empty.header.root),
        Child::Leaf { first: 0, count: 0 }
    );
}

#[test]
fn quantized_layout_rejects_leaves_it_cannot_encode() {
    let tris = common::soup(64, 5);
    let mut params = BuildPreset::Fast.params();
    params.max_leaf_size = 64;
    params.cost = SahCost {
        traversal: 1e6,
        intersection: 1.0,
    };
    let bvh = rtc_bvh::build_with_params(BuildInput::Triangles(&tris), &params);
    let biggest = bvh.stats().max_leaf_size;
    if biggest > MAX_LEAF_COUNT {
        let e = quantize(&bvh).unwrap_err();
        assert_eq!(
            e,
            QuantizeError::LeafTooLarge {
                count: biggest as u32
            }
        );
        assert!(e.to_string().contains("at most 15"), "{e}");
    } else {
        panic!("the build should make one large leaf, made {biggest}");
    }
}
