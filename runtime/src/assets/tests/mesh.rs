//! `MeshData`: validation, smooth normals, normal repair, bounds.

use glam::Vec3;

use super::assert_close3;
use crate::assets::{Bounds, MeshData, MeshError};

fn two_triangles() -> MeshData {
    // A unit square in the xy-plane facing +z, split along its diagonal.
    MeshData::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
}

#[test]
fn valid_mesh_reports_counts() {
    let report = two_triangles().validate().unwrap();
    assert_eq!((report.vertices, report.triangles), (4, 2));
    assert_eq!(report.degenerate_triangles, 0);
    assert_eq!(report.non_finite_attributes, 0);
}

#[test]
fn index_out_of_range_is_an_error() {
    let mut mesh = two_triangles();
    mesh.indices.push([0, 1, 4]);
    assert_eq!(
        mesh.validate(),
        Err(MeshError::IndexOutOfRange {
            triangle: 2,
            index: 4,
            vertex_count: 4
        })
    );
}

#[test]
fn non_finite_position_is_an_error() {
    let mut mesh = two_triangles();
    mesh.positions[2][1] = f32::NAN;
    assert!(matches!(
        mesh.validate(),
        Err(MeshError::NonFinitePosition { vertex: 2, .. })
    ));
    mesh.positions[2][1] = f32::INFINITY;
    assert!(matches!(
        mesh.validate(),
        Err(MeshError::NonFinitePosition { vertex: 2, .. })
    ));
}

#[test]
fn attribute_counts_must_match() {
    let mut mesh = two_triangles();
    mesh.uvs = Some(vec![[0.0; 2]; 3]);
    assert_eq!(
        mesh.validate(),
        Err(MeshError::AttributeCount {
            attribute: "uvs",
            expected: 4,
            found: 3
        })
    );
    mesh.uvs = None;
    mesh.normals = Some(vec![[0.0, 0.0, 1.0]; 5]);
    assert!(matches!(
        mesh.validate(),
        Err(MeshError::AttributeCount {
            attribute: "normals",
            ..
        })
    ));
}

#[test]
fn degenerate_triangles_are_counted_and_kept() {
    let mut mesh = two_triangles();
    mesh.indices.push([1, 1, 2]); // repeated index
    mesh.positions.push([2.0, 0.0, 0.0]);
    mesh.indices.push([0, 1, 4]); // collinear: zero area
    let report = mesh.validate().unwrap();
    assert_eq!(report.triangles, 4);
    assert_eq!(report.degenerate_triangles, 2);
    assert_eq!(mesh.indices.len(), 4);
}

#[test]
fn non_finite_attributes_are_counted() {
    let mut mesh = two_triangles();
    mesh.normals = Some(vec![
        [0.0, 0.0, 1.0],
        [f32::NAN, 0.0, 1.0],
        [0.0; 3],
        [0.0, 0.0, 1.0],
    ]);
    mesh.uvs = Some(vec![[0.0, f32::INFINITY], [0.0; 2], [0.0; 2], [0.0; 2]]);
    assert_eq!(mesh.validate().unwrap().non_finite_attributes, 2);
}

#[test]
fn smooth_normals_are_area_weighted_and_unit() {
    // Vertex 0 is shared by a large triangle facing +z and a small one facing +x.
    let mesh = MeshData::new(
        vec![
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [0.0, 4.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        vec![[0, 1, 2], [0, 3, 4]],
    );
    let normals = mesh.smooth_normals();
    // Area 8 along +z and 0.5 along +x: the normal leans 16:1 towards +z.
    assert_close3(normals[0], Vec3::new(1.0, 0.0, 16.0).normalize(), 1e-6);
    assert_close3(normals[1], [0.0, 0.0, 1.0], 1e-6);
    assert_close3(normals[3], [1.0, 0.0, 0.0], 1e-6);
    for n in normals {
        assert!((Vec3::from(n).length() - 1.0).abs() < 1e-6);
    }
}

#[test]
fn unused_vertex_gets_the_fallback_normal() {
    let mut mesh = two_triangles();
    mesh.positions.push([5.0, 5.0, 5.0]);
    assert_eq!(mesh.smooth_normals()[4], [0.0, 1.0, 0.0]);
}

#[test]
fn ensure_normals_computes_or_repairs() {
    let mut mesh = two_triangles();
    mesh.ensure_normals();
    for n in mesh.normals.as_ref().unwrap() {
        assert_close3(*n, [0.0, 0.0, 1.0], 1e-6);
    }
    // Given normals are normalised; zero and NaN ones replaced by the smooth normal.
    mesh.normals = Some(vec![
        [0.0, 0.0, 2.0],
        [0.0; 3],
        [f32::NAN; 3],
        [0.0, 3.0, 0.0],
    ]);
    mesh.ensure_normals();
    let normals = mesh.normals.unwrap();
    assert_eq!(
        normals,
        vec![
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 0.0]
        ]
    );
}

#[test]
fn bounds_of_mesh_and_transforms() {
    let mesh = two_triangles();
    let b = mesh.bounds();
    assert_eq!((b.min, b.max), (Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0)));
    let moved = b.transformed(&glam::Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)));
    assert_eq!(
        (moved.min, moved.max),
        (Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 3.0, 3.0))
    );
    let rotated = b.transformed(&glam::Mat4::from_rotation_z(std::f32::consts::FRAC_PI_2));
    assert_close3(rotated.min, [-1.0, 0.0, 0.0], 1e-6);
    assert_close3(rotated.max, [0.0, 1.0, 0.0], 1e-6);

    assert!(MeshData::default().bounds().is_empty());
    assert!(Bounds::EMPTY.transformed(&glam::Mat4::IDENTITY).is_empty());
    assert_eq!(Bounds::EMPTY.union(b), b);
    assert_eq!(b.union(Bounds::EMPTY), b);
    assert_eq!(Bounds::EMPTY.size(), Vec3::ZERO);
    // Non-finite points do not poison the box.
    assert_eq!(b.grow(Vec3::NAN), b);
}
