//! How often the lanes of a SIMD batch are at the same BVH record: a CPU model of the kernel's
//! object-level loop (`intersect_mesh` in `stdlib/kernel/trace.rt`: the nearer child first, the
//! farther pushed, a pop when both miss) over one mesh's quantised BVH, for camera rays of a
//! 256x256 view of the mesh, `WIDTH` neighbouring pixels of a row to a batch (lavapipe's lanes in
//! an 8 x 8 workgroup). Each lane runs its own sequence of records; the batch's iteration `k`
//! has every lane still running at its record `k`. Prints the share of iterations whose running
//! lanes are all at one record (where one load could serve the batch) and the lanes' utilisation.
//!
//! `cargo run --release -p rtc-bvh --example coherence -- MESH.obj [WIDTH]` (WIDTH 4 by default;
//! `examples/thesis_scene/bunny-6k.obj` for the figures cited).
//! Measured with it: docs/bench/lavapipe.md, "Six things tried on Zen 5, none kept (2026-12-08)".

use glam::Vec3;
use rtc_bvh::quantized::{quantize, Child, QuantizedBvh};
use rtc_bvh::traverse::{intersect_aabb, intersect_triangle, PreparedRay, Ray};
use rtc_bvh::{build, BuildInput, BuildPreset};

/// The view's size in pixels.
const SIDE: usize = 256;

fn main() {
    let mut args = std::env::args().skip(1);
    let (Some(path), width) = (args.next(), args.next()) else {
        eprintln!("usage: coherence MESH.obj [WIDTH]");
        std::process::exit(2);
    };
    let width = match width.map_or(Ok(4), |w| w.parse::<usize>()) {
        Ok(w) if (1..=64).contains(&w) && SIDE % w == 0 => w,
        _ => {
            eprintln!("error: WIDTH must divide {SIDE} (1 to 64)");
            std::process::exit(2);
        }
    };
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let models = match tobj::load_obj(&path, &options) {
        Ok((models, _)) => models,
        Err(e) => {
            eprintln!("error: {path}: {e}");
            std::process::exit(1);
        }
    };
    let mut tris = Vec::new();
    for m in &models {
        let p = &m.mesh.positions;
        let vertex = |i: u32| -> Option<Vec3> {
            let i = 3 * i as usize;
            Some(Vec3::new(*p.get(i)?, *p.get(i + 1)?, *p.get(i + 2)?))
        };
        for t in m.mesh.indices.chunks_exact(3) {
            if let (Some(a), Some(b), Some(c)) = (vertex(t[0]), vertex(t[1]), vertex(t[2])) {
                tris.push([a, b, c]);
            }
        }
    }
    let bvh = build(BuildInput::Triangles(&tris), BuildPreset::Fast);
    let q = match quantize(&bvh) {
        Ok(q) => q,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let camera = Camera::looking_at(&bvh.root_aabb());
    let walk = |px: usize, py: usize| records(&q, bvh.prim_indices(), &tris, &camera.ray(px, py));

    let (mut iterations, mut shared, mut lane_steps) = (0u64, 0u64, 0u64);
    for py in 0..SIDE {
        for px in (0..SIDE).step_by(width) {
            let lanes: Vec<Vec<u32>> = (px..px + width).map(|x| walk(x, py)).collect();
            let steps = lanes.iter().map(Vec::len).max().unwrap_or(0);
            for k in 0..steps {
                let mut running = lanes.iter().filter_map(|s| s.get(k));
                let Some(first) = running.next() else {
                    continue;
                };
                let mut count = 1u64;
                let mut same = true;
                for r in running {
                    count += 1;
                    same &= r == first;
                }
                iterations += 1;
                lane_steps += count;
                shared += u64::from(same);
            }
        }
    }
    let share = |a: u64, b: u64| 100.0 * a as f64 / b.max(1) as f64;
    println!(
        "{path}: {} triangles, {width} lanes a batch, {iterations} batch iterations: all running lanes at one record in {:.1} %, lane utilisation {:.1} %",
        tris.len(),
        share(shared, iterations),
        share(lane_steps, iterations * width as u64),
    );
}

/// A pinhole camera looking at a box's centre from 1.2 of its diagonal away.
struct Camera {
    eye: Vec3,
    forward: Vec3,
    right: Vec3,
    up: Vec3,
}

impl Camera {
    fn looking_at(b: &rtc_bvh::Aabb) -> Camera {
        let centre = Vec3::from(b.center());
        let eye = centre + Vec3::new(0.3, 0.2, 1.0).normalize() * b.extent().length() * 1.2;
        let forward = (centre - eye).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        Camera {
            eye,
            forward,
            right,
            up,
        }
    }

    /// The ray through the centre of pixel `(px, py)`.
    fn ray(&self, px: usize, py: usize) -> Ray {
        let sx = (px as f32 + 0.5) / SIDE as f32 * 2.0 - 1.0;
        let sy = 1.0 - (py as f32 + 0.5) / SIDE as f32 * 2.0;
        let dir = (self.forward + (self.right * sx + self.up * sy) * 0.6).normalize();
        Ray::new(self.eye, dir)
    }
}

/// The child references the kernel's loop is at, one an iteration, for the closest hit of `ray`.
fn records(q: &QuantizedBvh, prims: &[u32], tris: &[[Vec3; 3]], ray: &Ray) -> Vec<u32> {
    let mut out = Vec::new();
    let Some(r) = PreparedRay::new(ray) else {
        return out;
    };
    let mut best = f32::INFINITY;
    let mut stack: Vec<u32> = Vec::new();
    let mut child = q.header.root;
    loop {
        out.push(child);
        match Child::decode(child) {
            Child::Leaf { first, count } => {
                for slot in first..first + count {
                    let tri = prims.get(slot as usize).and_then(|&p| tris.get(p as usize));
                    if let Some(h) = tri.and_then(|t| intersect_triangle(&r, t, best)) {
                        best = best.min(h.0);
                    }
                }
            }
            Child::Inner(record) => {
                let [(lb, l), (rb, rr)] = q.children(record);
                let tl = intersect_aabb(&r, lb.min, lb.max, best);
                let tr = intersect_aabb(&r, rb.min, rb.max, best);
                match (tl, tr) {
                    (Some(a), Some(b)) => {
                        let (near, far) = if b < a { (rr, l) } else { (l, rr) };
                        stack.push(far.encode());
                        child = near.encode();
                        continue;
                    }
                    (Some(_), None) => {
                        child = l.encode();
                        continue;
                    }
                    (None, Some(_)) => {
                        child = rr.encode();
                        continue;
                    }
                    (None, None) => {}
                }
            }
        }
        match stack.pop() {
            Some(next) => child = next,
            None => return out,
        }
    }
}
