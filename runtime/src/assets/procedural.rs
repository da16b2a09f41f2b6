//! The procedural meshes of `spec/scenes.md`: `quad_mesh()`, `cube_mesh()`, `sphere_mesh(n)`.
//!
//! Invariants (checked by the tests): every mesh passes [`MeshData::validate`] with no degenerate
//! triangle, has unit normals and uvs, and winds counter-clockwise seen from outside (the
//! geometric normal agrees with the shading normal). The cube and the sphere are closed: after
//! merging vertices at equal positions, every edge is shared by exactly two triangles. Output is
//! deterministic (no hash-map iteration order leaks into it).

use std::collections::HashMap;
use std::f32::consts::PI;

use glam::Vec3;

use super::MeshData;

/// The largest `sphere_mesh` subdivision level, the compiler's (which refuses larger ones in a
/// scene, E0707); larger requests that reach this function anyway are clamped to it. Level 8 is
/// 1,310,720 triangles and about 660k vertices (≈ 30 MB on the CPU), already far finer than any
/// image needs.
pub const MAX_SPHERE_SUBDIVISIONS: u32 = rtc_compiler::sema::limits::MAX_SPHERE_SUBDIVISIONS;

/// The square [-1, 1]² in the xz-plane (y = 0), normal +y: 4 vertices, 2 triangles.
///
/// uv = ((x + 1) / 2, (z + 1) / 2): seen from above with -z at the top, the image lies on the
/// quad upright (its top-left texel at (-1, 0, -1)).
pub fn quad_mesh() -> MeshData {
    let positions = vec![
        [-1.0, 0.0, -1.0],
        [1.0, 0.0, -1.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
    ];
    let uvs = positions
        .iter()
        .map(|p: &[f32; 3]| [(p[0] + 1.0) * 0.5, (p[2] + 1.0) * 0.5]);
    MeshData {
        uvs: Some(uvs.collect()),
        normals: Some(vec![[0.0, 1.0, 0.0]; 4]),
        positions,
        indices: vec![[0, 3, 2], [0, 2, 1]],
        extras: None,
    }
}

/// The cube [-1, 1]³: 24 vertices (4 per face, so each face has its own normal and uvs),
/// 12 triangles, outward normals.
///
/// Each face carries the whole image, upright when the face is seen from outside with +y up
/// (for the top and bottom faces: with -z, respectively +z, up).
pub fn cube_mesh() -> MeshData {
    // (outward normal, image right, image up), with right × up = normal.
    const FACES: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    ];
    // Corners top-left, top-right, bottom-right, bottom-left, as (u, v).
    const CORNERS: [[f32; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mut mesh = MeshData {
        normals: Some(Vec::with_capacity(24)),
        uvs: Some(Vec::with_capacity(24)),
        ..MeshData::default()
    };
    for (face, (n, right, up)) in (0u32..).zip(FACES) {
        let (n, right, up) = (Vec3::from(n), Vec3::from(right), Vec3::from(up));
        for [u, v] in CORNERS {
            let p = n + (2.0 * u - 1.0) * right + (1.0 - 2.0 * v) * up;
            mesh.positions.push(p.to_array());
            mesh.normals.get_or_insert_with(Vec::new).push(n.to_array());
            mesh.uvs.get_or_insert_with(Vec::new).push([u, v]);
        }
        let b = 4 * face;
        // Top-left → bottom-left → bottom-right is counter-clockwise seen from outside.
        mesh.indices.push([b, b + 3, b + 2]);
        mesh.indices.push([b, b + 2, b + 1]);
    }
    mesh
}

/// A unit icosphere: the icosahedron with each triangle split in four `subdivisions` times
/// (clamped to [`MAX_SPHERE_SUBDIVISIONS`]) and the vertices pushed onto the unit sphere.
///
/// Normals are the positions (smooth). uvs are spherical:
/// `u = 0.5 - atan2(z, x) / 2π` (increasing eastwards seen from outside, seam in the -x half of
/// the xy-plane), `v = acos(y) / π` (0 at the north pole +y). Vertices on the seam are
/// duplicated so no triangle's uvs wrap around, and each triangle at a pole gets its own pole
/// vertex with the mean u of its other corners. Before that split there are `10·4ⁿ + 2`
/// vertices and there are always `20·4ⁿ` triangles.
pub fn sphere_mesh(subdivisions: u32) -> MeshData {
    let (positions, indices) = icosphere(subdivisions.min(MAX_SPHERE_SUBDIVISIONS));
    let mut mesh = MeshData {
        uvs: Some(positions.iter().map(|&p| spherical_uv(p)).collect()),
        positions: positions.iter().map(|p| p.to_array()).collect(),
        normals: None,
        indices,
        extras: None,
    };
    split_uv_seams(&mut mesh);
    mesh.normals = Some(mesh.positions.clone());
    mesh
}

/// Positions on the unit sphere and triangles of the subdivided icosahedron.
fn icosphere(subdivisions: u32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let t = (1.0 + 5.0_f32.sqrt()) / 2.0;
    let mut positions: Vec<Vec3> = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
    .into_iter()
    .map(|p| Vec3::from(p).normalize())
    .collect();
    let mut indices: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::with_capacity(indices.len() * 3 / 2);
        let mut midpoint = |a: u32, b: u32, positions: &mut Vec<Vec3>| -> u32 {
            let key = (a.min(b), a.max(b));
            *midpoints.entry(key).or_insert_with(|| {
                let pa = positions.get(a as usize).copied().unwrap_or(Vec3::Y);
                let pb = positions.get(b as usize).copied().unwrap_or(Vec3::Y);
                positions.push((pa + pb).normalize_or(Vec3::Y));
                // At most 10·4⁸ + 2 vertices, far below u32::MAX.
                u32::try_from(positions.len() - 1).unwrap_or(u32::MAX)
            })
        };
        let mut next = Vec::with_capacity(indices.len() * 4);
        for [a, b, c] in indices {
            let ab = midpoint(a, b, &mut positions);
            let bc = midpoint(b, c, &mut positions);
            let ca = midpoint(c, a, &mut positions);
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        indices = next;
    }
    (positions, indices)
}

fn spherical_uv(p: Vec3) -> [f32; 2] {
    // `+ 0.0` turns -0.0 into +0.0, so points on the seam all get u = 0.
    let u = 0.5 - (p.z + 0.0).atan2(p.x) / (2.0 * PI);
    let v = p.y.clamp(-1.0, 1.0).acos() / PI;
    [u, v]
}

fn is_pole(p: [f32; 3]) -> bool {
    p[0].abs() < 1e-6 && p[2].abs() < 1e-6
}

/// Duplicates seam and pole vertices so that no triangle's u wraps around (see [`sphere_mesh`]).
fn split_uv_seams(mesh: &mut MeshData) {
    let Some(uvs) = mesh.uvs.as_mut() else {
        return;
    };
    let positions = &mut mesh.positions;
    // Original vertex → its copy with u + 1.
    let mut shifted: HashMap<u32, u32> = HashMap::new();
    for tri in &mut mesh.indices {
        let corners = corners(positions, uvs, tri);
        let (lo, hi) = corners
            .iter()
            .filter(|(p, _)| !is_pole(*p))
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), (_, uv)| {
                (lo.min(uv[0]), hi.max(uv[0]))
            });
        if hi - lo > 0.5 {
            for (slot, (p, [u, v])) in tri.iter_mut().zip(corners) {
                if !is_pole(p) && u < 0.5 {
                    *slot = match shifted.get(slot) {
                        Some(&copy) => copy,
                        None => {
                            let copy = push_vertex(positions, uvs, p, [u + 1.0, v]);
                            shifted.insert(*slot, copy);
                            copy
                        }
                    };
                }
            }
        }
        let corners = self::corners(positions, uvs, tri);
        let (sum, n) = corners
            .iter()
            .filter(|(p, _)| !is_pole(*p))
            .fold((0.0, 0.0), |(sum, n), (_, uv)| (sum + uv[0], n + 1.0));
        let mean_u = if n > 0.0 { sum / n } else { 0.5 };
        for (slot, (p, [_, v])) in tri.iter_mut().zip(corners) {
            if is_pole(p) {
                *slot = push_vertex(positions, uvs, p, [mean_u, v]);
            }
        }
    }
}

fn corners(positions: &[[f32; 3]], uvs: &[[f32; 2]], tri: &[u32; 3]) -> [([f32; 3], [f32; 2]); 3] {
    tri.map(|i| {
        let p = positions.get(i as usize).copied().unwrap_or_default();
        let uv = uvs.get(i as usize).copied().unwrap_or_default();
        (p, uv)
    })
}

fn push_vertex(
    positions: &mut Vec<[f32; 3]>,
    uvs: &mut Vec<[f32; 2]>,
    p: [f32; 3],
    uv: [f32; 2],
) -> u32 {
    positions.push(p);
    uvs.push(uv);
    // Bounded by the subdivision limit, far below u32::MAX.
    u32::try_from(positions.len() - 1).unwrap_or(u32::MAX)
}
