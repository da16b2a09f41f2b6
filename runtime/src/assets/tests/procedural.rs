//! The procedural meshes: counts, unit outward normals, winding, uvs, closedness.

use std::collections::HashMap;

use glam::Vec3;

use crate::assets::{cube_mesh, quad_mesh, sphere_mesh, MeshData, MAX_SPHERE_SUBDIVISIONS};

/// Checks what every procedural mesh promises: valid, no degenerate triangle, unit normals, uvs
/// in range, and each triangle's geometric normal agreeing with its vertices' shading normals.
fn check_common(mesh: &MeshData) {
    let report = mesh.validate().unwrap();
    assert_eq!(report.degenerate_triangles, 0);
    assert_eq!(report.non_finite_attributes, 0);
    let normals = mesh.normals.as_ref().expect("normals");
    let uvs = mesh.uvs.as_ref().expect("uvs");
    for n in normals {
        assert!((Vec3::from(*n).length() - 1.0).abs() < 1e-5, "{n:?}");
    }
    for uv in uvs {
        // u may reach 1 + a little on the sphere's seam copies only up to 1.5.
        assert!(
            (0.0..=1.5).contains(&uv[0]) && (0.0..=1.0).contains(&uv[1]),
            "{uv:?}"
        );
    }
    for tri in &mesh.indices {
        let p = tri.map(|i| Vec3::from(mesh.positions[i as usize]));
        let geometric = (p[1] - p[0]).cross(p[2] - p[0]);
        for &i in tri {
            assert!(
                geometric.dot(Vec3::from(normals[i as usize])) > 0.0,
                "winding of {tri:?}"
            );
        }
    }
}

/// Every edge, after merging vertices at equal positions, is used by exactly two triangles, once
/// in each direction (closed and consistently oriented).
fn assert_closed(mesh: &MeshData) {
    let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
    let welded: Vec<u32> = mesh
        .positions
        .iter()
        .map(|p| {
            let key = p.map(f32::to_bits);
            let next = ids.len() as u32;
            *ids.entry(key).or_insert(next)
        })
        .collect();
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for tri in &mesh.indices {
        let t = tri.map(|i| welded[i as usize]);
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1, "directed edge {a}->{b} used {n} times");
        assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} is open");
    }
    // Euler characteristic of a sphere: V - E + F = 2.
    let (v, e, f) = (
        ids.len() as i64,
        edges.len() as i64 / 2,
        mesh.indices.len() as i64,
    );
    assert_eq!(v - e + f, 2);
}

#[test]
fn quad_is_the_unit_square_facing_up() {
    let quad = quad_mesh();
    check_common(&quad);
    assert_eq!((quad.vertex_count(), quad.triangle_count()), (4, 2));
    let b = quad.bounds();
    assert_eq!(
        (b.min, b.max),
        (Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0))
    );
    assert!(quad.normals.unwrap().iter().all(|n| *n == [0.0, 1.0, 0.0]));
    // Top-left texel at (-1, 0, -1).
    let uvs = quad.uvs.unwrap();
    assert_eq!(uvs[0], [0.0, 0.0]);
    assert_eq!(quad.positions[0], [-1.0, 0.0, -1.0]);
}

#[test]
fn cube_has_24_vertices_outward_normals_and_is_closed() {
    let cube = cube_mesh();
    check_common(&cube);
    assert_eq!((cube.vertex_count(), cube.triangle_count()), (24, 12));
    let b = cube.bounds();
    assert_eq!((b.min, b.max), (Vec3::splat(-1.0), Vec3::splat(1.0)));
    let normals = cube.normals.as_ref().unwrap();
    for (p, n) in cube.positions.iter().zip(normals) {
        // The normal is the axis on which the vertex is at ±1, pointing outwards.
        let (p, n) = (Vec3::from(*p), Vec3::from(*n));
        assert_eq!(p.dot(n), 1.0);
    }
    // Each face has the whole image: uvs (0,0), (1,0), (1,1), (0,1).
    for face in cube.uvs.as_ref().unwrap().chunks(4) {
        assert_eq!(face, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    }
    // The +z face seen from outside: the top-left corner is at (-1, 1, 1).
    let front = cube
        .normals
        .as_ref()
        .unwrap()
        .iter()
        .position(|n| *n == [0.0, 0.0, 1.0])
        .unwrap();
    assert_eq!(cube.positions[front], [-1.0, 1.0, 1.0]);
    assert_closed(&cube);
}

#[test]
fn sphere_counts_normals_and_closedness() {
    for n in 0..=3u32 {
        let sphere = sphere_mesh(n);
        check_common(&sphere);
        assert_eq!(sphere.triangle_count(), 20 * 4usize.pow(n));
        for (p, normal) in sphere
            .positions
            .iter()
            .zip(sphere.normals.as_ref().unwrap())
        {
            assert!((Vec3::from(*p).length() - 1.0).abs() < 1e-6);
            assert_eq!(p, normal);
        }
        // Before the uv seam split: 10·4ⁿ + 2 distinct positions.
        let distinct: std::collections::HashSet<[u32; 3]> = sphere
            .positions
            .iter()
            .map(|p| p.map(f32::to_bits))
            .collect();
        assert_eq!(distinct.len(), 10 * 4usize.pow(n) + 2);
        assert_closed(&sphere);
    }
}

#[test]
fn sphere_uvs_do_not_wrap_within_a_triangle() {
    let sphere = sphere_mesh(3);
    let uvs = sphere.uvs.as_ref().unwrap();
    for tri in &sphere.indices {
        let us = tri.map(|i| uvs[i as usize][0]);
        let spread = us.iter().cloned().fold(f32::MIN, f32::max)
            - us.iter().cloned().fold(f32::MAX, f32::min);
        assert!(spread < 0.3, "triangle {tri:?} spans u {us:?}");
    }
    // u = 0.5 - atan2(z, x) / 2π (mod 1 for seam copies), v = acos(y) / π, except at the poles.
    for (p, uv) in sphere.positions.iter().zip(uvs) {
        let expected_v = p[1].clamp(-1.0, 1.0).acos() / std::f32::consts::PI;
        assert!((uv[1] - expected_v).abs() < 1e-5);
        if p[0].abs() < 1e-6 && p[2].abs() < 1e-6 {
            continue;
        }
        let expected_u = 0.5 - p[2].atan2(p[0]) / (2.0 * std::f32::consts::PI);
        let d = (uv[0] - expected_u).rem_euclid(1.0);
        assert!(
            !(1e-5..=1.0 - 1e-5).contains(&d),
            "{p:?}: u {} vs {expected_u}",
            uv[0]
        );
    }
}

#[test]
fn sphere_subdivisions_are_clamped_and_output_is_deterministic() {
    assert_eq!(MAX_SPHERE_SUBDIVISIONS, 8);
    // Asking for far more than the limit gives the limit (checked at a cheap level: the clamp
    // is `min`, so comparing the triangle count formula suffices).
    assert_eq!(sphere_mesh(2), sphere_mesh(2));
    let capped = sphere_mesh(u32::MAX);
    assert_eq!(
        capped.triangle_count(),
        20 * 4usize.pow(MAX_SPHERE_SUBDIVISIONS)
    );
}
