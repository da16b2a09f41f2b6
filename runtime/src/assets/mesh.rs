//! [`MeshData`]: an indexed triangle mesh on the CPU, the one mesh entity every loader produces.
//!
//! Conventions (see the [module docs](super) for the whole list): right-handed y-up space,
//! counter-clockwise front faces (the geometric normal is `cross(p1 - p0, p2 - p0)`), uv origin
//! at the image's top-left with v pointing down.
//!
//! Invariants of a mesh that passed [`MeshData::validate`]:
//! - every index is `< positions.len()`, and `positions.len()` fits a `u32`;
//! - every position is finite;
//! - `normals` and `uvs`, when present, have one entry per position; so do the `uvs1` and
//!   `colors` of [`VertexExtras`], and its `tangents` have one entry per triangle.
//!
//! [`VertexExtras`] (a second uv set, vertex colours, tangents) are `None` for a mesh that has
//! none of them, which is then encoded for the GPU exactly as a mesh without them always was
//! (`scene::encode`). Tangents are kept per triangle corner because MikkTSpace
//! ([`MeshData::generate_tangents`]) gives one per corner, not per vertex.
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
    /// The attributes only some meshes have (`None`: none of them).
    pub extras: Option<VertexExtras>,
}

/// Per-vertex attributes beyond position, normal and the first uv set, which only meshes that
/// need them carry (glTF's `TEXCOORD_1`, `COLOR_0`, `TANGENT`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VertexExtras {
    /// The second uv set, one per position (origin top-left, v down).
    pub uvs1: Option<Vec<[f32; 2]>>,
    /// Linear RGBA vertex colours, one per position (RGB sets get alpha 1).
    pub colors: Option<Vec<[f32; 4]>>,
    /// Tangents per triangle corner: a unit xyz and in w the bitangent sign (±1), so that
    /// `bitangent = w · normal × tangent` (glTF's convention). A zero xyz marks a corner without
    /// a usable tangent (degenerate uvs), which shading treats as "no normal map here".
    pub tangents: Option<Vec<[[f32; 4]; 3]>>,
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
            extras: None,
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
        if let Some(extras) = &self.extras {
            if let Some(uvs1) = &extras.uvs1 {
                check_count("uvs1", n, uvs1.len())?;
            }
            if let Some(colors) = &extras.colors {
                check_count("colors", n, colors.len())?;
            }
            if let Some(tangents) = &extras.tangents {
                check_count("tangents", self.indices.len(), tangents.len())?;
            }
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

    /// Per-corner tangents from per-vertex ones (glTF's `TANGENT`: xyz, w = bitangent sign): each
    /// normalised, its w made ±1; a zero or non-finite one becomes the zero "no tangent" marker.
    pub fn corner_tangents(&self, per_vertex: &[[f32; 4]]) -> Vec<[[f32; 4]; 3]> {
        self.indices
            .iter()
            .map(|tri| {
                tri.map(|i| {
                    per_vertex
                        .get(i as usize)
                        .map_or([0.0; 4], |&[x, y, z, w]| unit_tangent([x, y, z], w))
                })
            })
            .collect()
    }

    /// MikkTSpace tangents per triangle corner (the glTF spec's rule for a normal-mapped mesh
    /// without tangents), from positions, `normals` (made present first) and `uvs` (`uv_set` 1:
    /// the second set). `None` when the mesh has no such uvs. The corners of a triangle without
    /// uv area (or whose tangent is not finite) get the zero marker rather than a NaN.
    pub fn generate_tangents(&mut self, uv_set: u32) -> Option<Vec<[[f32; 4]; 3]>> {
        self.ensure_normals();
        let uvs = match uv_set {
            0 => self.uvs.as_ref()?,
            _ => self.extras.as_ref()?.uvs1.as_ref()?,
        };
        let normals = self.normals.as_ref()?;
        let mut geometry = Mikk {
            positions: &self.positions,
            normals,
            uvs,
            indices: &self.indices,
            out: vec![[[0.0; 4]; 3]; self.indices.len()],
        };
        if !mikktspace::generate_tangents(&mut geometry) {
            return None;
        }
        // MikkTSpace gives a triangle without uv area some tangent anyway; glTF has none for it.
        let mut out = geometry.out;
        for (tri, corners) in self.indices.iter().zip(out.iter_mut()) {
            let [a, b, c] = tri.map(|i| uvs.get(i as usize).copied().unwrap_or_default());
            let (d1, d2) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
            let area = d1[0] * d2[1] - d1[1] * d2[0];
            if area.is_nan() || area.abs() <= 1e-12 {
                *corners = [[0.0; 4]; 3];
            }
        }
        Some(out)
    }

    /// The box around all positions (empty for a mesh without vertices).
    pub fn bounds(&self) -> Bounds {
        Bounds::from_points(self.positions.iter().map(|p| Vec3::from(*p)))
    }
}

/// A tangent made unit with w = ±1, or the zero marker when it has no direction.
fn unit_tangent(xyz: [f32; 3], w: f32) -> [f32; 4] {
    match Vec3::from(xyz).try_normalize() {
        Some(t) => [t.x, t.y, t.z, if w < 0.0 { -1.0 } else { 1.0 }],
        None => [0.0; 4],
    }
}

/// A mesh as the `mikktspace` crate reads it, with the per-corner tangents it writes.
struct Mikk<'a> {
    positions: &'a [[f32; 3]],
    normals: &'a [[f32; 3]],
    uvs: &'a [[f32; 2]],
    indices: &'a [[u32; 3]],
    out: Vec<[[f32; 4]; 3]>,
}

impl Mikk<'_> {
    fn index(&self, face: usize, vert: usize) -> usize {
        self.indices
            .get(face)
            .and_then(|t| t.get(vert))
            .map_or(usize::MAX, |&i| i as usize)
    }
}

impl mikktspace::Geometry for Mikk<'_> {
    fn num_faces(&self) -> usize {
        self.indices.len()
    }
    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }
    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.positions
            .get(self.index(face, vert))
            .copied()
            .unwrap_or_default()
    }
    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.normals
            .get(self.index(face, vert))
            .copied()
            .unwrap_or(FALLBACK_NORMAL)
    }
    /// MikkTSpace's uv space has v up (its bitangent follows v); glTF's v points down the image
    /// while its normal textures have +y up, so v is flipped here to get glTF's bitangent sign.
    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        let [u, v] = self
            .uvs
            .get(self.index(face, vert))
            .copied()
            .unwrap_or_default();
        [u, 1.0 - v]
    }
    fn set_tangent_encoded(&mut self, tangent: [f32; 4], face: usize, vert: usize) {
        let [x, y, z, w] = tangent;
        let t = if [x, y, z, w].iter().all(|c| c.is_finite()) {
            unit_tangent([x, y, z], w)
        } else {
            [0.0; 4]
        };
        if let Some(slot) = self.out.get_mut(face).and_then(|f| f.get_mut(vert)) {
            *slot = t;
        }
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
