//! [`MeshData`]: an indexed triangle mesh on the CPU, the one mesh entity every loader produces.
//!
//! Conventions (see the [module docs](super) for the whole list): right-handed y-up space,
//! counter-clockwise front faces (the geometric normal is `cross(p1 - p0, p2 - p0)`), uv origin
//! at the image's top-left with v pointing down.
//!
//! Invariants of a mesh that passed [`MeshData::validate`]:
//! - every index is `< positions.len()`, and `positions.len()` fits a `u32`;
//! - every position is finite;
//! - `normals` and `uvs`, when present, have one entry per position.
//!
//! Degenerate triangles (zero area, or a repeated index) are valid: they are counted in
//! [`MeshReport`] and kept, so triangle ids stay those of the file. They contribute nothing to
//! smooth normals and a ray never hits them.

use glam::Vec3;

use super::{Bounds, MeshError};

/// The normal given to a vertex that no non-degenerate triangle touches.
const FALLBACK_NORMAL: [f32; 3] = [0.0, 1.0, 0.0];

/// An indexed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit shading normals, one per position, when known.
    pub normals: Option<Vec<[f32; 3]>>,
    /// Texture coordinates, one per position, when known (origin top-left, v down).
    pub uvs: Option<Vec<[f32; 2]>>,
    /// Triangles as three vertex indices, counter-clockwise seen from the front.
    pub indices: Vec<[u32; 3]>,
}

/// What [`MeshData::validate`] found in a valid mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshReport {
    /// Number of vertices.
    pub vertices: usize,
    /// Number of triangles, degenerate ones included.
    pub triangles: usize,
    /// Triangles with zero area or a repeated index (kept, never hit).
    pub degenerate_triangles: usize,
    /// Normals or uvs with a NaN or infinite component (normals are repaired by
    /// [`MeshData::ensure_normals`]).
    pub non_finite_attributes: usize,
}

impl MeshData {
    /// A mesh with positions and triangles only.
    pub fn new(positions: Vec<[f32; 3]>, indices: Vec<[u32; 3]>) -> Self {
        Self {
            positions,
            normals: None,
            uvs: None,
            indices,
        }
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len()
    }

    /// Checks the invariants listed in the module docs and counts degenerate triangles.
    pub fn validate(&self) -> Result<MeshReport, MeshError> {
        let n = self.positions.len();
        if u32::try_from(n).is_err() {
            return Err(MeshError::TooManyVertices(n));
        }
        if let Some(normals) = &self.normals {
            check_count("normals", n, normals.len())?;
        }
        if let Some(uvs) = &self.uvs {
            check_count("uvs", n, uvs.len())?;
        }
        if let Some((vertex, &position)) = self
            .positions
            .iter()
            .enumerate()
            .find(|(_, p)| !p.iter().all(|c| c.is_finite()))
        {
            return Err(MeshError::NonFinitePosition { vertex, position });
        }
        let mut degenerate_triangles = 0;
        for (triangle, tri) in self.indices.iter().enumerate() {
            let mut p = [Vec3::ZERO; 3];
            for (corner, &index) in p.iter_mut().zip(tri) {
                let pos = self
                    .positions
                    .get(index as usize)
                    .ok_or(MeshError::IndexOutOfRange {
                        triangle,
                        index,
                        vertex_count: n,
                    })?;
                *corner = Vec3::from(*pos);
            }
            let [a, b, c] = *tri;
            let area2 = (p[1] - p[0]).cross(p[2] - p[0]).length_squared();
            if a == b || b == c || a == c || area2 == 0.0 {
                degenerate_triangles += 1;
            }
        }
        let non_finite = |v: &[f32]| !v.iter().all(|c| c.is_finite());
        let non_finite_attributes = self
            .normals
            .iter()
            .flatten()
            .filter(|v| non_finite(&v[..]))
            .count()
            + self
                .uvs
                .iter()
                .flatten()
                .filter(|v| non_finite(&v[..]))
                .count();
        Ok(MeshReport {
            vertices: n,
            triangles: self.indices.len(),
            degenerate_triangles,
            non_finite_attributes,
        })
    }

    /// Area-weighted smooth vertex normals: each vertex gets the normalised sum of the
    /// (unnormalised, so area-weighted) geometric normals of the triangles that use it. A vertex
    /// that no non-degenerate triangle uses gets `+y`. Out-of-range indices are skipped.
    pub fn smooth_normals(&self) -> Vec<[f32; 3]> {
        let mut sums = vec![Vec3::ZERO; self.positions.len()];
        for tri in &self.indices {
            let [Some(a), Some(b), Some(c)] = tri.map(|i| self.positions.get(i as usize)) else {
                continue;
            };
            let (a, b, c) = (Vec3::from(*a), Vec3::from(*b), Vec3::from(*c));
            let n = (b - a).cross(c - a);
            if !n.is_finite() {
                continue;
            }
            for &i in tri {
                if let Some(sum) = sums.get_mut(i as usize) {
                    *sum += n;
                }
            }
        }
        sums.into_iter()
            .map(|s| s.try_normalize().map_or(FALLBACK_NORMAL, |n| n.to_array()))
            .collect()
    }

    /// Makes `normals` present and unit length: computes [`smooth_normals`](Self::smooth_normals)
    /// when there are none, and otherwise normalises the given ones, replacing any that are
    /// zero, non-finite or missing (wrong count) by the smooth normal.
    pub fn ensure_normals(&mut self) {
        let given = match self.normals.take() {
            Some(given) if given.len() == self.positions.len() => given,
            _ => {
                self.normals = Some(self.smooth_normals());
                return;
            }
        };
        let mut smooth: Option<Vec<[f32; 3]>> = None;
        let mut out = given;
        for (i, n) in out.iter_mut().enumerate() {
            match Vec3::from(*n).try_normalize() {
                Some(unit) => *n = unit.to_array(),
                None => {
                    let smooth = smooth.get_or_insert_with(|| self.smooth_normals());
                    *n = smooth.get(i).copied().unwrap_or(FALLBACK_NORMAL);
                }
            }
        }
        self.normals = Some(out);
    }

    /// The box around all positions (empty for a mesh without vertices).
    pub fn bounds(&self) -> Bounds {
        Bounds::from_points(self.positions.iter().map(|p| Vec3::from(*p)))
    }
}

fn check_count(attribute: &'static str, expected: usize, found: usize) -> Result<(), MeshError> {
    if expected == found {
        Ok(())
    } else {
        Err(MeshError::AttributeCount {
            attribute,
            expected,
            found,
        })
    }
}
