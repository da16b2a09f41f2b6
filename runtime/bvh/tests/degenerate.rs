//! Degenerate inputs over every preset and both input kinds: empty input, one primitive, equal
//! centroids, zero-area and sliver triangles, huge, infinite and NaN coordinates, flat boxes.
//!
//! Invariants under test: no panic; the BVH validates; every box is finite; rejected primitives
//! (see `rtc_bvh::input`) are never referenced and accepted ones always are; traversal of the
//! flattened nodes never panics and agrees with brute force over the accepted triangles.

mod common;

use glam::Vec3;
use rtc_bvh::input::{sanitize_aabb, triangle_aabb};
use rtc_bvh::quantized::quantize;
use rtc_bvh::traverse::{closest_hit, closest_hit_brute_force, closest_hit_quantized, Ray};
use rtc_bvh::{build, flatten, Aabb, BuildInput, BuildPreset, Bvh, GpuNode, MAX_COORD};

const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;

/// Structural checks shared by all cases.
fn check_bvh(bvh: &Bvh, accepted: &[bool], name: &str) {
    bvh.validate().unwrap_or_else(|e| panic!("{name}: {e}"));
    for n in flatten(bvh) {
        assert!(
            n.min.iter().chain(&n.max).all(|c| c.is_finite()),
            "{name}: non-finite node {n:?}"
        );
    }
    let mut seen = vec![0u32; accepted.len()];
    for &p in bvh.prim_indices() {
        seen[p as usize] += 1;
    }
    for (i, (&s, &ok)) in seen.iter().zip(accepted).enumerate() {
        if !ok {
            assert_eq!(s, 0, "{name}: rejected primitive {i} is referenced");
        } else if bvh.has_spatial_splits() {
            assert!(s >= 1, "{name}: primitive {i} is not referenced");
        } else {
            assert_eq!(s, 1, "{name}: primitive {i} referenced {s} times");
        }
    }
}

fn check_triangles(name: &str, tris: &[[Vec3; 3]]) {
    let accepted: Vec<bool> = tris.iter().map(|t| triangle_aabb(t).is_some()).collect();
    // Brute force over the accepted triangles only (rejected ones are never hit by design).
    let kept: Vec<[Vec3; 3]> = tris
        .iter()
        .zip(&accepted)
        .map(|(t, &ok)| if ok { *t } else { [Vec3::ZERO; 3] })
        .collect();
    let finite: Vec<[Vec3; 3]> = kept
        .iter()
        .filter(|t| t.iter().all(|v| v.is_finite()))
        .copied()
        .collect();
    let rays = if finite.is_empty() {
        vec![
            Ray::new(Vec3::ZERO, Vec3::X),
            Ray::new(Vec3::splat(0.5), -Vec3::Y),
        ]
    } else {
        common::rays(&finite, 64, 11)
    };
    for preset in BuildPreset::ALL {
        let bvh = build(BuildInput::Triangles(tris), preset);
        let label = format!("{name} {preset:?}");
        check_bvh(&bvh, &accepted, &label);
        let nodes = flatten(&bvh);
        let quantized = quantize(&bvh).unwrap();
        for r in &rays {
            let got = closest_hit(&nodes, bvh.prim_indices(), tris, r);
            let want = closest_hit_brute_force(&kept, r).filter(|h| accepted[h.prim as usize]);
            assert_eq!(got, want, "{label}: ray {r:?}");
            let got = closest_hit_quantized(&quantized, bvh.prim_indices(), tris, r);
            assert_eq!(got, want, "{label}: quantised, ray {r:?}");
        }
    }
}

fn check_boxes(name: &str, boxes: &[Aabb]) {
    let accepted: Vec<bool> = boxes.iter().map(|b| sanitize_aabb(b).is_some()).collect();
    for preset in BuildPreset::ALL {
        let bvh = build(BuildInput::Aabbs(boxes), preset);
        check_bvh(&bvh, &accepted, &format!("{name} {preset:?}"));
        assert!(!bvh.has_spatial_splits(), "{name}: boxes are never split");
        // Every accepted box lies inside the root box (after clamping).
        for b in boxes.iter().filter_map(sanitize_aabb) {
            assert!(
                bvh.root_aabb().contains(&b),
                "{name}: {b:?} outside the root"
            );
        }
    }
}

fn tri(a: [f32; 3], b: [f32; 3], c: [f32; 3]) -> [Vec3; 3] {
    [Vec3::from(a), Vec3::from(b), Vec3::from(c)]
}

#[test]
fn empty_input() {
    check_triangles("empty", &[]);
    check_boxes("empty", &[]);
    let bvh = build(BuildInput::Triangles(&[]), BuildPreset::Fast);
    assert!(bvh.is_empty());
    assert_eq!(bvh.max_depth(), 0);
    assert_eq!(bvh.sah_cost(rtc_bvh::SahCost::STANDARD), 0.0);
    let nodes = flatten(&bvh);
    assert_eq!(
        nodes,
        vec![GpuNode::PADDING],
        "the empty BVH is one empty leaf"
    );
    // A ray through everything hits nothing.
    let r = Ray::new(Vec3::splat(-1e6), Vec3::ONE);
    assert_eq!(closest_hit(&nodes, bvh.prim_indices(), &[], &r), None);
}

#[test]
fn one_primitive() {
    check_triangles(
        "one",
        &[tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])],
    );
    check_boxes("one", &[Aabb::new(Vec3::ZERO, Vec3::ONE)]);
}

#[test]
fn identical_centroids() {
    // 100 copies of one triangle, and 50 concentric boxes: no plane separates them.
    let t = tri([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    check_triangles("copies", &vec![t; 100]);
    let boxes: Vec<Aabb> = (1..=50)
        .map(|i| Aabb::new(Vec3::splat(-(i as f32)), Vec3::splat(i as f32)))
        .collect();
    check_boxes("concentric", &boxes);
    check_boxes("points", &vec![Aabb::new(Vec3::ONE, Vec3::ONE); 40]);
}

#[test]
fn zero_area_and_slivers() {
    let mut tris = vec![
        tri([0.0; 3], [0.0; 3], [0.0; 3]),                 // a point
        tri([0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]),   // collinear
        tri([0.0; 3], [1.0, 0.0, 0.0], [0.5, 1e-30, 0.0]), // sliver
        tri([0.0, 0.0, 0.0], [1000.0, 0.0, 0.0], [0.0, 1e-3, 0.0]), // long sliver
    ];
    tris.extend(common::sphere(Vec3::splat(0.5), 0.3, 6, 8));
    check_triangles("slivers", &tris);
}

#[test]
fn flat_boxes_and_axis_aligned_triangles() {
    // A flat grid of axis-aligned triangles (every box has zero extent in y).
    let mut tris = Vec::new();
    for i in 0..10 {
        for k in 0..10 {
            let (x, z) = (i as f32, k as f32);
            tris.push(tri([x, 0.0, z], [x + 1.0, 0.0, z], [x + 1.0, 0.0, z + 1.0]));
            tris.push(tri([x, 0.0, z], [x + 1.0, 0.0, z + 1.0], [x, 0.0, z + 1.0]));
        }
    }
    check_triangles("flat grid", &tris);
    let boxes: Vec<Aabb> = (0..30)
        .map(|i| {
            Aabb::new(
                Vec3::new(i as f32, 0.0, 0.0),
                Vec3::new(i as f32 + 1.0, 0.0, 1.0),
            )
        })
        .collect();
    check_boxes("flat boxes", &boxes);
}

#[test]
fn huge_infinite_and_nan_coordinates() {
    let mut tris = common::sphere(Vec3::ZERO, 1.0, 6, 8);
    tris.push(tri([NAN, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]));
    tris.push(tri([INF, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]));
    tris.push(tri([-INF, -INF, -INF], [INF, INF, INF], [0.0, 1.0, 0.0]));
    tris.push(tri([1e30, 0.0, 0.0], [-1e30, 0.0, 0.0], [0.0, 1e30, 0.0]));
    tris.push(tri(
        [MAX_COORD, 0.0, 0.0],
        [-MAX_COORD, 0.0, 0.5],
        [0.0, 0.0, MAX_COORD],
    )); // accepted
    tris.push(tri([1.0, 2.0, 3.0], [1.0, 2.0, 3.5], [1.5, 2.0, 3.0]));
    check_triangles("huge/inf/nan", &tris);
    let all_bad = vec![tri([NAN; 3], [NAN; 3], [NAN; 3]); 5];
    check_triangles("all nan", &all_bad);

    let boxes = vec![
        Aabb::new(Vec3::splat(-INF), Vec3::splat(INF)),
        Aabb::new(Vec3::splat(-1e30), Vec3::splat(1e30)),
        Aabb::new(Vec3::new(0.0, NAN, 0.0), Vec3::ONE),
        Aabb::new(Vec3::ONE, Vec3::ZERO), // inverted
        Aabb::new(Vec3::ZERO, Vec3::ONE),
        Aabb::new(Vec3::splat(f32::MAX), Vec3::splat(f32::MAX)),
        Aabb::new(Vec3::new(-INF, 0.0, 0.0), Vec3::new(0.0, 1.0, 1.0)),
    ];
    check_boxes("huge/inf/nan boxes", &boxes);
    check_boxes(
        "many infinite",
        &vec![Aabb::new(Vec3::splat(-INF), Vec3::splat(INF)); 20],
    );
}

#[test]
fn bad_indices_are_skipped() {
    let vertices = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    let indices = [[0, 1, 2], [0, 1, 9], [1, 2, 3], [u32::MAX, 0, 1]];
    for preset in BuildPreset::ALL {
        let bvh = build(
            BuildInput::Indexed {
                vertices: &vertices,
                indices: &indices,
            },
            preset,
        );
        check_bvh(&bvh, &[true, false, true, false], "bad indices");
    }
}

#[test]
fn rays_with_degenerate_directions_do_not_panic() {
    let tris = common::sphere(Vec3::ZERO, 1.0, 6, 8);
    let bvh = build(BuildInput::Triangles(&tris), BuildPreset::Fast);
    let nodes = flatten(&bvh);
    let o = Vec3::new(0.0, 0.0, -3.0);
    let bad = [
        Ray::new(o, Vec3::ZERO),
        Ray::new(o, Vec3::new(NAN, 0.0, 1.0)),
        Ray::new(Vec3::new(INF, 0.0, 0.0), Vec3::Z),
        Ray::new(o, Vec3::new(1e-45, 0.0, 0.0)), // denormal only: flushed to zero
        Ray {
            origin: o,
            dir: Vec3::Z,
            tmin: 2.0,
            tmax: 1.0,
        },
        Ray {
            origin: o,
            dir: Vec3::Z,
            tmin: NAN,
            tmax: 1.0,
        },
    ];
    for r in &bad {
        assert_eq!(
            closest_hit(&nodes, bvh.prim_indices(), &tris, r),
            None,
            "{r:?}"
        );
    }
    // A denormal component next to a normal one is flushed, not fatal.
    let r = Ray::new(o, Vec3::new(1e-40, 0.0, 1.0));
    assert_eq!(
        closest_hit(&nodes, bvh.prim_indices(), &tris, &r),
        closest_hit_brute_force(&tris, &r)
    );
    assert!(closest_hit(&nodes, bvh.prim_indices(), &tris, &r).is_some());
}
