//! Wavefront OBJ → [`MeshData`], through `tobj` (`load_mesh` in the language).
//!
//! What is read: `v`, `vt`, `vn` and `f` (polygons are fan-triangulated; all groups and objects
//! are merged into one mesh); points and two-vertex lines are skipped; materials (`mtllib`,
//! `usemtl`) are ignored and `.mtl` files are never opened. The result is single-indexed (one
//! index per distinct position/uv/normal combination).
//!
//! Invariants:
//! - The returned mesh passed [`MeshData::validate`] and has unit normals: normals from the file
//!   are kept when every vertex has one, otherwise smooth normals are computed for the whole
//!   mesh. uvs are kept when any part of the file has them (vertices without one get `(0, 0)`),
//!   with v flipped (`v' = 1 - v`) to the top-left origin of the [module conventions](super).
//! - **`tobj` is only given input it survives.** It resolves relative (negative) face indices
//!   and then does unchecked index arithmetic, which overflows (a panic in debug builds, a wrong
//!   lookup in release) for an index before the first vertex or absurdly far past the last.
//!   [`check_face_indices`] rejects those first, with the line number, and also rejects text
//!   that is not UTF-8.

use std::path::Path;

use super::{AssetError, MeshData, MeshError};

/// Reads a Wavefront OBJ file as one triangle mesh.
///
/// `v`, `vt`, `vn` and `f` are read (polygons fan-triangulated, all groups merged); points, lines
/// and materials are ignored. Normals from the file are kept when every vertex has one,
/// otherwise smooth normals are computed; uvs are flipped to the top-left origin (`v' = 1 - v`).
/// Out-of-range face indices are [`AssetError::ObjIndex`] with the line.
pub fn load_obj(path: impl AsRef<Path>) -> Result<MeshData, AssetError> {
    let path = path.as_ref();
    let bytes = std::fs::read(path).map_err(|source| AssetError::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_obj(&bytes, path)
}

/// [`load_obj`] on the file's bytes; `path` is only used in errors.
pub(crate) fn parse_obj(bytes: &[u8], path: &Path) -> Result<MeshData, AssetError> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes
            .get(..e.valid_up_to())
            .map_or(0, |b| b.iter().filter(|&&c| c == b'\n').count())
            + 1;
        AssetError::UnsupportedFormat {
            path: path.to_owned(),
            found: format!("binary data, not OBJ text (invalid UTF-8 on line {line})"),
        }
    })?;
    check_face_indices(text, path)?;

    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|source| AssetError::Obj {
        path: path.to_owned(),
        line: None,
        source,
    })?;
    let mesh = merge_models(&models, path)?;
    mesh.validate().map_err(|source| AssetError::Mesh {
        path: path.to_owned(),
        item: None,
        source,
    })?;
    let mut mesh = mesh;
    mesh.ensure_normals();
    Ok(mesh)
}

/// Merges `tobj`'s per-group meshes into one, applying the attribute rules of the module docs.
fn merge_models(models: &[tobj::Model], path: &Path) -> Result<MeshData, AssetError> {
    let vertex_total: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
    let triangle_total: usize = models.iter().map(|m| m.mesh.indices.len() / 3).sum();
    let too_many = || AssetError::Mesh {
        path: path.to_owned(),
        item: None,
        source: MeshError::TooManyVertices(vertex_total),
    };
    if u32::try_from(vertex_total).is_err() {
        return Err(too_many());
    }
    let all_normals = models
        .iter()
        .all(|m| m.mesh.normals.len() == m.mesh.positions.len());
    let any_uvs = models.iter().any(|m| !m.mesh.texcoords.is_empty());

    let mut positions = Vec::with_capacity(vertex_total);
    let mut normals = Vec::with_capacity(if all_normals { vertex_total } else { 0 });
    let mut uvs = Vec::with_capacity(if any_uvs { vertex_total } else { 0 });
    let mut indices = Vec::with_capacity(triangle_total);
    for model in models {
        let mesh = &model.mesh;
        let base = u32::try_from(positions.len()).map_err(|_| too_many())?;
        positions.extend(triples(&mesh.positions));
        if all_normals {
            normals.extend(triples(&mesh.normals));
        }
        if any_uvs {
            let count = mesh.positions.len() / 3;
            if mesh.texcoords.len() == 2 * count {
                uvs.extend(
                    mesh.texcoords
                        .chunks_exact(2)
                        .filter_map(|c| <[f32; 2]>::try_from(c).ok())
                        .map(|[u, v]| [u, 1.0 - v]),
                );
            } else {
                uvs.resize(uvs.len() + count, [0.0, 0.0]);
            }
        }
        for tri in mesh.indices.chunks_exact(3) {
            if let Ok(tri) = <[u32; 3]>::try_from(tri) {
                // An overflow here means an index past u32::MAX, out of range anyway;
                // `validate` reports it.
                indices.push(tri.map(|i| i.saturating_add(base)));
            }
        }
    }
    Ok(MeshData {
        positions,
        normals: all_normals.then_some(normals),
        uvs: any_uvs.then_some(uvs),
        indices,
        extras: None,
    })
}

fn triples(flat: &[f32]) -> impl Iterator<Item = [f32; 3]> + '_ {
    flat.chunks_exact(3)
        .filter_map(|c| <[f32; 3]>::try_from(c).ok())
}

/// Rejects face (`f`) and line (`l`) indices that `tobj` cannot handle safely: relative indices
/// reaching before the first element defined so far, absolute indices past the last element of
/// the whole file (`tobj` resolves those when a group ends), and position index 0. Counts
/// `v`/`vt`/`vn` lines exactly as `tobj` does (by the first whitespace-separated word). An
/// absolute `vt`/`vn` index in a file without any `vt`/`vn` is allowed: `tobj` ignores it.
fn check_face_indices(text: &str, path: &Path) -> Result<(), AssetError> {
    const KINDS: [&str; 3] = ["a position", "a texture coordinate", "a normal"];
    // Elements seen so far, and the largest absolute index used (with its line).
    let mut counts = [0usize; 3];
    let mut max_used: [Option<(u64, usize)>; 3] = [None; 3];
    let error = |line: usize, index: i64, kind: usize, count: usize| AssetError::ObjIndex {
        path: path.to_owned(),
        line,
        index,
        kind: KINDS.get(kind).copied().unwrap_or("an element"),
        count,
    };
    for (line_no, line) in text.lines().enumerate() {
        let line_no = line_no + 1;
        let mut words = line.split_whitespace();
        let kind = match words.next() {
            Some("v") => 0,
            Some("vt") => 1,
            Some("vn") => 2,
            Some("f" | "l") => 3,
            _ => continue,
        };
        if let Some(count) = counts.get_mut(kind) {
            *count += 1;
            continue;
        }
        for word in words {
            for ((k, part), &count) in word.split('/').enumerate().zip(&counts) {
                let Ok(x) = part.parse::<i64>() else {
                    continue; // empty (`1//3`) or malformed: tobj reports the latter
                };
                if x < 0 {
                    if x.unsigned_abs() > count as u64 {
                        return Err(error(line_no, x, k, count));
                    }
                } else if x == 0 {
                    if k == 0 {
                        return Err(error(line_no, x, k, count));
                    }
                } else if let Some(slot) = max_used.get_mut(k) {
                    let x = x.unsigned_abs();
                    if slot.is_none_or(|(m, _)| x > m) {
                        *slot = Some((x, line_no));
                    }
                }
            }
        }
    }
    for ((k, used), &total) in max_used.iter().enumerate().zip(&counts) {
        if let Some((x, line)) = *used {
            if x > total as u64 && (k == 0 || total > 0) {
                return Err(error(line, i64::try_from(x).unwrap_or(i64::MAX), k, total));
            }
        }
    }
    Ok(())
}
