//! Benchmark scenes and cameras: OBJ loading from `shared/models`, the replicated 10M-triangle
//! dragon, and exact ports of the cameras and primary rays of `shared/bench/benchlib.py`
//! (`THESIS_CAMERA`, `auto_camera`, `primary_rays`), so that the rays traced here are the rays
//! Embree traces in `embree_bench.py`.
//!
//! Invariant: every float operation that numpy does in `float32` is done in `f32` here and
//! every `float64` one in `f64`, in the same order, so the rays are bit-identical to
//! `benchlib.primary_rays` (checked with `--print-camera` on every model).

use std::path::{Path, PathBuf};

use glam::{DVec3, Vec3};
use rtc_bvh::traverse::Ray;

/// Image size and vertical field of view of `benchlib.py`.
pub const W: usize = 1920;
/// Image height.
pub const H: usize = 1080;
const VFOV_DEG: f64 = 45.0;

/// A pinhole camera as in `benchlib.py`.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    pub eye: DVec3,
    pub target: DVec3,
    pub up: DVec3,
    pub vfov_deg: f64,
}

/// `benchlib.THESIS_CAMERA`.
pub const THESIS_CAMERA: Camera = Camera {
    eye: DVec3::new(0.0, 0.55, 0.9),
    target: DVec3::new(0.0, 0.02, -0.05),
    up: DVec3::new(0.0, 1.0, 0.0),
    vfov_deg: VFOV_DEG,
};

/// A triangle mesh as loaded.
pub struct Mesh {
    pub vertices: Vec<Vec3>,
    pub indices: Vec<[u32; 3]>,
}

impl Mesh {
    /// The triangle soup (what traversal and obvhs read).
    pub fn triangles(&self) -> Vec<[Vec3; 3]> {
        self.indices
            .iter()
            .map(|t| t.map(|i| self.vertices[i as usize]))
            .collect()
    }
}

/// `shared/models`: `$RTC_MODELS`, else relative to this crate.
pub fn models_dir() -> PathBuf {
    std::env::var_os("RTC_MODELS")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/models"))
}

/// Loads every mesh of an OBJ file into one mesh (tobj, `GPU_LOAD_OPTIONS`).
pub fn load_obj(path: &Path) -> Result<Mesh, String> {
    let (models, _) = tobj::load_obj(path, &tobj::GPU_LOAD_OPTIONS)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let mut mesh = Mesh {
        vertices: Vec::new(),
        indices: Vec::new(),
    };
    for m in models {
        let base = mesh.vertices.len() as u32;
        mesh.vertices.extend(
            m.mesh
                .positions
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0], p[1], p[2])),
        );
        mesh.indices.extend(
            m.mesh
                .indices
                .chunks_exact(3)
                .map(|t| [t[0] + base, t[1] + base, t[2] + base]),
        );
    }
    Ok(mesh)
}

/// `copies` copies of `mesh` on a grid in x/z (4 per row), spaced 1.1 times the mesh extent:
/// the "10 million triangle" scene from 12 dragons.
pub fn replicate(mesh: &Mesh, copies: usize) -> Mesh {
    let (lo, hi) = bounds(&mesh.vertices);
    let step = (hi - lo) * 1.1;
    let mut out = Mesh {
        vertices: Vec::with_capacity(mesh.vertices.len() * copies),
        indices: Vec::with_capacity(mesh.indices.len() * copies),
    };
    for k in 0..copies {
        let offset = Vec3::new((k % 4) as f32 * step.x, 0.0, (k / 4) as f32 * step.z);
        let base = out.vertices.len() as u32;
        out.vertices
            .extend(mesh.vertices.iter().map(|v| *v + offset));
        out.indices
            .extend(mesh.indices.iter().map(|t| t.map(|i| i + base)));
    }
    out
}

fn bounds(v: &[Vec3]) -> (Vec3, Vec3) {
    v.iter().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    )
}

/// `benchlib.auto_camera(v)`.
pub fn auto_camera(vertices: &[Vec3]) -> Camera {
    let (lo, hi) = bounds(vertices);
    // float32: c = (lo + hi) / 2; r = norm(hi - lo) / 2. numpy's float32 dot inside `norm`
    // sums as x² + (y² + z²); that order reproduces it bit for bit on every model in
    // shared/models (a left-to-right sum differs in the last bit for the bunny).
    let c = (lo + hi) / 2.0;
    let d = hi - lo;
    let r = f64::from((d.x * d.x + (d.y * d.y + d.z * d.z)).sqrt() / 2.0);
    let dirn = DVec3::new(0.3, 0.35, 1.0);
    let dirn = dirn / dirn.length();
    let dist = r / (VFOV_DEG / 2.0).to_radians().tan() * 0.8;
    Camera {
        eye: c.as_dvec3() + dirn * dist,
        target: c.as_dvec3(),
        up: DVec3::Y,
        vfov_deg: VFOV_DEG,
    }
}

/// `benchlib.primary_rays(cam)`: one ray per pixel centre, row-major from the top left.
pub fn primary_rays(cam: &Camera, w: usize, h: usize) -> Vec<Ray> {
    let eye = cam.eye;
    let fwd = (cam.target - eye) / (cam.target - eye).length();
    let right = fwd.cross(cam.up);
    let right = right / right.length();
    let up = right.cross(fwd);
    let th = (cam.vfov_deg.to_radians() / 2.0).tan();
    let tw = th * w as f64 / h as f64;
    let origin = eye.as_vec3();
    let mut rays = Vec::with_capacity(w * h);
    for j in 0..h {
        let y = (1.0 - (j as f64 + 0.5) / h as f64 * 2.0) * th;
        for i in 0..w {
            let x = ((i as f64 + 0.5) / w as f64 * 2.0 - 1.0) * tw;
            let d = fwd + x * right + y * up;
            rays.push(Ray::new(origin, (d / d.length()).as_vec3()));
        }
    }
    rays
}
