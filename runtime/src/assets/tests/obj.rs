//! OBJ loading: round trips through small generated files, attribute rules, bad input.

use std::path::Path;

use super::{assert_close3, TempDir};
use crate::assets::obj::parse_obj;
use crate::assets::{cube_mesh, load_obj, AssetError, MeshData};

fn parse(text: &str) -> Result<MeshData, AssetError> {
    parse_obj(text.as_bytes(), Path::new("test.obj"))
}

/// Writes a mesh as OBJ text (`v`, optional `vt` with v flipped back to OBJ's upward v,
/// optional `vn`, and `f` lines with 1-based indices).
fn to_obj(mesh: &MeshData) -> String {
    let mut s = String::from("# written by the rtc asset tests\no mesh\n");
    for p in &mesh.positions {
        s += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for uv in mesh.uvs.iter().flatten() {
        s += &format!("vt {} {}\n", uv[0], 1.0 - uv[1]);
    }
    for n in mesh.normals.iter().flatten() {
        s += &format!("vn {} {} {}\n", n[0], n[1], n[2]);
    }
    for tri in &mesh.indices {
        let corner = |i: u32| {
            let i = i + 1;
            match (mesh.uvs.is_some(), mesh.normals.is_some()) {
                (true, true) => format!("{i}/{i}/{i}"),
                (true, false) => format!("{i}/{i}"),
                (false, true) => format!("{i}//{i}"),
                (false, false) => format!("{i}"),
            }
        };
        s += &format!(
            "f {} {} {}\n",
            corner(tri[0]),
            corner(tri[1]),
            corner(tri[2])
        );
    }
    s
}

#[test]
fn round_trip_positions_only_computes_normals() {
    let dir = TempDir::new("obj");
    let path = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let mesh = load_obj(&path).unwrap();
    assert_eq!(
        mesh.positions,
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    );
    assert_eq!(mesh.indices, vec![[0, 1, 2]]);
    assert!(mesh.uvs.is_none());
    for n in mesh.normals.unwrap() {
        assert_close3(n, [0.0, 0.0, 1.0], 1e-6);
    }
}

#[test]
fn round_trip_cube_with_uvs_and_normals() {
    let cube = cube_mesh();
    let dir = TempDir::new("obj");
    let path = dir.write("cube.obj", to_obj(&cube));
    let loaded = load_obj(&path).unwrap();
    // tobj numbers vertices in order of first use, so compare triangle corners, not arrays.
    assert_eq!(loaded.vertex_count(), 24);
    assert_eq!(loaded.triangle_count(), 12);
    let corner = |m: &MeshData, t: usize, k: usize| {
        let i = m.indices[t][k] as usize;
        (
            m.positions[i],
            m.normals.as_ref().unwrap()[i],
            m.uvs.as_ref().unwrap()[i],
        )
    };
    for t in 0..12 {
        for k in 0..3 {
            assert_eq!(corner(&loaded, t, k), corner(&cube, t, k));
        }
    }
}

#[test]
fn texture_v_is_flipped_to_top_left_origin() {
    let mesh =
        parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0.25\nvt 0 1\nf 1/1 2/2 3/3\n").unwrap();
    assert_eq!(mesh.uvs.unwrap(), vec![[0.0, 1.0], [1.0, 0.75], [0.0, 0.0]]);
}

#[test]
fn polygons_are_triangulated_and_groups_merged() {
    let text = "\
v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n\
g quad\nf 1 2 3 4\n\
g penta\nf 1 2 5 3 4\n\
l 1 2\np 3\n";
    let mesh = parse(text).unwrap();
    assert_eq!(mesh.triangle_count(), 2 + 3);
    mesh.validate().unwrap();
}

#[test]
fn relative_indices_work() {
    let mesh = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n").unwrap();
    assert_eq!(mesh.indices, vec![[0, 1, 2]]);
}

#[test]
fn partial_normals_are_replaced_by_smooth_ones() {
    // Only the first face has normals (pointing the wrong way): they are not trusted.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 -1\nf 1//1 2//1 3//1\nf 2 4 3\n";
    let mesh = parse(text).unwrap();
    for n in mesh.normals.unwrap() {
        assert_close3(n, [0.0, 0.0, 1.0], 1e-6);
    }
}

#[test]
fn materials_are_ignored_without_reading_mtl_files() {
    let mesh =
        parse("mtllib missing.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    assert_eq!(mesh.triangle_count(), 1);
}

#[test]
fn out_of_range_indices_name_the_line() {
    let cases = [
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, 4, 3),
        ("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3, -3, 2),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, 0, 3),
        // A relative uv index before the first uv: tobj's arithmetic would overflow.
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-5 2/1 3/1\n",
            5,
            -5,
            1,
        ),
        // An absurd absolute normal index.
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//9223372036854775807 2//1 3//1\n",
            5,
            i64::MAX,
            1,
        ),
    ];
    for (text, want_line, want_index, want_count) in cases {
        match parse(text) {
            Err(AssetError::ObjIndex {
                line, index, count, ..
            }) => {
                assert_eq!(
                    (line, index, count),
                    (want_line, want_index, want_count),
                    "{text}"
                );
            }
            other => panic!("{text}: {other:?}"),
        }
    }
    let message = parse("v 0 0 0\nf 1 2 3\n").unwrap_err().to_string();
    assert!(
        message.starts_with("test.obj:2: face index 3 refers to a position"),
        "{message}"
    );
}

#[test]
fn forward_references_within_the_file_are_allowed() {
    let mesh = parse("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n").unwrap();
    assert_eq!(mesh.triangle_count(), 1);
}

#[test]
fn parse_errors_are_reported() {
    assert!(matches!(parse("v 0 zero 0\n"), Err(AssetError::Obj { .. })));
    assert!(matches!(
        parse("v 0 0 0\nf 1/x 1 1\n"),
        Err(AssetError::Obj { .. })
    ));
    let binary = parse_obj(&[0x89, b'P', b'N', b'G', 0xff, 0xfe], Path::new("x.obj"));
    assert!(
        matches!(binary, Err(AssetError::UnsupportedFormat { .. })),
        "{binary:?}"
    );
}

#[test]
fn empty_file_is_an_empty_mesh() {
    let mesh = parse("# nothing\n").unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (0, 0));
    assert!(mesh.bounds().is_empty());
}

#[test]
fn missing_file_names_the_file() {
    let err = load_obj("/nonexistent/rtc/mesh.obj").unwrap_err();
    assert!(matches!(err, AssetError::Read { .. }));
    assert!(
        err.to_string().contains("/nonexistent/rtc/mesh.obj"),
        "{err}"
    );
    assert_eq!(err.path(), Path::new("/nonexistent/rtc/mesh.obj"));
}

#[test]
fn non_finite_positions_are_rejected() {
    let err = parse("v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n").unwrap_err();
    assert!(matches!(err, AssetError::Mesh { .. }), "{err:?}");
}

#[test]
fn shared_test_mesh_loads_with_its_readme_counts() {
    // `shared/models` (or `$RTC_MODELS`) is outside the repository; without it there is nothing
    // to check here, and the generated-file tests above still cover the loader.
    let dir = std::env::var_os("RTC_MODELS")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/models"));
    let path = dir.join("bunny-6k.obj");
    if !path.exists() {
        eprintln!("{} not found; skipping", path.display());
        return;
    }
    let mesh = load_obj(&path).unwrap();
    assert_eq!((mesh.triangle_count(), mesh.vertex_count()), (6234, 3137));
    let report = mesh.validate().unwrap();
    assert!(report.degenerate_triangles < 10, "{report:?}");
    let size = mesh.bounds().size();
    assert!(
        size.max_element() > 0.1 && size.max_element() < 0.3,
        "{size}"
    );
}
