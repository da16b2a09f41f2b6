//! The BVH traversal against brute force: for every preset and several meshes, random rays
//! (including axis-aligned and grazing ones) must give exactly the brute-force closest hit
//! (same `t`, primitive and barycentrics, bit for bit) and the same any-hit answer, in both node
//! layouts (`flatten`'s and the quantised mesh layout).
//!
//! Invariant under test: traversal never loses a hit (conservative boxes, robust slab test,
//! spatial-split fragments that cover their triangles) and the closest-hit tie rule makes the
//! answer independent of the tree.

mod common;

use glam::Vec3;
use rtc_bvh::quantized::quantize;
use rtc_bvh::traverse::{
    any_hit, any_hit_brute_force, any_hit_quantized, closest_hit, closest_hit_brute_force,
    closest_hit_quantized,
};
use rtc_bvh::{build, flatten, BuildInput, BuildPreset};

fn check(name: &str, tris: &[[Vec3; 3]], n_rays: usize) {
    let rays = common::rays(tris, n_rays, 7);
    let expected: Vec<_> = rays
        .iter()
        .map(|r| closest_hit_brute_force(tris, r))
        .collect();
    let expected_any: Vec<_> = rays.iter().map(|r| any_hit_brute_force(tris, r)).collect();
    let hits = expected.iter().filter(|h| h.is_some()).count();
    assert!(
        hits > n_rays / 4,
        "{name}: too few hits ({hits}) to mean anything"
    );
    for preset in BuildPreset::ALL {
        let bvh = build(BuildInput::Triangles(tris), preset);
        bvh.validate().unwrap();
        let nodes = flatten(&bvh);
        let quantized = quantize(&bvh).unwrap();
        for (i, r) in rays.iter().enumerate() {
            let got = closest_hit(&nodes, bvh.prim_indices(), tris, r);
            assert_eq!(
                got, expected[i],
                "{name} {preset:?}: closest hit of ray {i} {r:?}"
            );
            let got_any = any_hit(&nodes, bvh.prim_indices(), tris, r);
            assert_eq!(
                got_any, expected_any[i],
                "{name} {preset:?}: any hit of ray {i} {r:?}"
            );
            let got = closest_hit_quantized(&quantized, bvh.prim_indices(), tris, r);
            assert_eq!(
                got, expected[i],
                "{name} {preset:?}: quantised closest hit of ray {i} {r:?}"
            );
            let got_any = any_hit_quantized(&quantized, bvh.prim_indices(), tris, r);
            assert_eq!(
                got_any, expected_any[i],
                "{name} {preset:?}: quantised any hit of ray {i} {r:?}"
            );
        }
    }
}

#[test]
fn sphere_matches_brute_force() {
    check("sphere", &common::sphere(Vec3::ZERO, 1.0, 24, 32), 400);
}

#[test]
fn soup_with_slivers_matches_brute_force() {
    check("soup", &common::soup(3000, 3), 400);
}

#[test]
fn thesis_like_scene_matches_brute_force() {
    check("thesis-like", &common::thesis_like(), 400);
}

#[test]
fn bunny_6k_matches_brute_force() {
    if let Some(tris) = common::bunny_6k() {
        check("bunny-6k", &tris, 300);
    }
}

#[test]
fn indexed_input_gives_the_same_tree_as_a_soup() {
    let tris = common::sphere(Vec3::ZERO, 1.0, 12, 16);
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for t in &tris {
        let base = vertices.len() as u32;
        vertices.extend_from_slice(t);
        indices.push([base, base + 1, base + 2]);
    }
    for preset in BuildPreset::ALL {
        let a = build(BuildInput::Triangles(&tris), preset);
        let b = build(
            BuildInput::Indexed {
                vertices: &vertices,
                indices: &indices,
            },
            preset,
        );
        assert_eq!(a.nodes(), b.nodes());
        assert_eq!(a.prim_indices(), b.prim_indices());
    }
}
