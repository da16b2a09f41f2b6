//! Debug kernels (`KernelOptions::debug`), the data behind `rtc bvh --heatmap` and the BVH
//! visualizer: per pixel, the BVH nodes a camera ray visits and the primitives it tests, and the
//! camera rays themselves.
//!
//! The scene (`scenes/debug/row.rt`) is five unit cubes (`cube_mesh()`, 12 triangles each) in a row
//! along x, with a camera whose `@ray_generation` returns one hand-written ray per pixel from a
//! constant table the test sets to [`RAYS`] (every float written as its exact bits). The expected counts come from a CPU copy of the kernel's traversal order (`intersect_scene`
//! and `intersect_mesh` in `stdlib/kernel/trace.rt`, over the quantised mesh records of
//! `rtc_bvh::quantized`: near child first, far child deferred, a
//! deferred node visited when popped even if the closest hit lies before it) run over the
//! renderer's own node, instance and triangle arrays. The rays are axis-aligned and pass at least 0.05 (in face coordinates) from every
//! triangle edge, so no box or triangle decision is within rounding of its boundary: counts must
//! match exactly, `t` within a relative 1e-6, object indices exactly.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::scene::{exact_f32_array, exact_vec3f_array, SceneFile};
use common::{gpu_or_skip, temp_dir};

use rtc_bvh::quantized::{Child, QuantizedBvh};
use rtc_bvh::Aabb;
use rtc_compiler::kernel::{CompiledScene, DebugMode, KernelOptions};
use rtc_runtime::render::{RenderOptions, Renderer};
use rtc_runtime::scene::{Entities, GpuInstance};

/// `(origin, direction)` of each pixel's ray.
const RAYS: [([f32; 3], [f32; 3]); 7] = [
    // From the left along +x: the cube at x = 0, t = 9.
    ([-10.0, 0.3, 0.1], [1.0, 0.0, 0.0]),
    // From the right along -x: the cube at x = 16, t = 13.
    ([30.0, 0.3, 0.1], [-1.0, 0.0, 0.0]),
    // From above along -y: the cube at x = 4, t = 9.
    ([4.2, 10.0, 0.3], [0.0, -1.0, 0.0]),
    // Above everything, along +y: misses the scene's box (no node visited).
    ([0.0, 10.0, 10.0], [0.0, 1.0, 0.0]),
    // Between the cubes at x = 0 and x = 4 along +z: inside the scene's box, hits nothing.
    ([2.0, 0.3, -10.0], [0.0, 0.0, 1.0]),
    // From inside the cube at x = 8, along +x: its +x face from inside, t = 0.8.
    ([8.2, 0.3, 0.1], [1.0, 0.0, 0.0]),
    // Along the row, direction not normalised (length 2): the cube at x = 0, t = 4.5.
    ([-10.0, -0.2, -0.35], [2.0, 0.0, 0.0]),
];

/// The x of each cube's centre (objects `c0` … `c4`).
const CUBES: [f32; 5] = [0.0, 4.0, 8.0, 12.0, 16.0];

/// `scenes/debug/row.rt` with [`RAYS`] and [`CUBES`], every float as its exact bits.
fn scene_file() -> SceneFile {
    SceneFile::open("debug/row.rt")
        .set("RAY_COUNT", format!("{}u", RAYS.len()))
        .set("ORIGINS", exact_vec3f_array(RAYS.iter().map(|r| r.0)))
        .set("DIRS", exact_vec3f_array(RAYS.iter().map(|r| r.1)))
        .set("CUBES", exact_f32_array(CUBES))
}

fn compile(dir: &std::path::Path, debug: DebugMode) -> CompiledScene {
    scene_file().compile_with(
        dir,
        &KernelOptions {
            debug: Some(debug),
            ..KernelOptions::default()
        },
    )
}

/// `1 / d` with components below `1e-30` replaced by `±1e-30`, for the reference's slab test (the
/// kernel's own box test, `box_ray`'s padded one in the BVH's frame, visits the same nodes on
/// these rays: the test compares the counts).
fn safe_inverse(d: [f32; 3]) -> [f32; 3] {
    d.map(|c| {
        let s = if c < 0.0 { -1.0 } else { 1.0 };
        let c = if c.abs() < 1e-30 { s * 1e-30 } else { c };
        1.0 / c
    })
}

/// The slab test of a box given by its corners: entry distance, or `None` for a miss
/// within `[tmin, tmax]`.
fn slab_box(
    min: [f32; 3],
    max: [f32; 3],
    o: [f32; 3],
    inv: [f32; 3],
    tmin: f32,
    tmax: f32,
) -> Option<f32> {
    let mut enter = tmin;
    let mut exit = tmax;
    for a in 0..3 {
        let t0 = (min[a] - o[a]) * inv[a];
        let t1 = (max[a] - o[a]) * inv[a];
        enter = enter.max(t0.min(t1));
        exit = exit.min(t0.max(t1));
    }
    (enter <= exit).then_some(enter)
}

/// Möller–Trumbore in `f64`: `t` of a hit in `[tmin, tmax]`, never for edge-on triangles.
fn triangle(v: [[f32; 4]; 3], o: [f32; 3], d: [f32; 3], tmin: f32, tmax: f32) -> Option<f32> {
    let p = |i: usize| [f64::from(v[i][0]), f64::from(v[i][1]), f64::from(v[i][2])];
    let (p0, p1, p2) = (p(0), p(1), p(2));
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (o, d) = (o.map(f64::from), d.map(f64::from));
    let (e1, e2) = (sub(p1, p0), sub(p2, p0));
    let pv = cross(d, e2);
    let det = dot(e1, pv);
    if det.abs() < 1e-12 {
        return None;
    }
    let s = sub(o, p0);
    let u = dot(s, pv) / det;
    let q = cross(s, e1);
    let w = dot(d, q) / det;
    let t = dot(e2, q) / det;
    let inside = u >= 0.0 && w >= 0.0 && u + w <= 1.0;
    (inside && t >= f64::from(tmin) && t <= f64::from(tmax)).then_some(t as f32)
}

/// What the kernel reports for one ray: nodes, primitives, `t` and object (or -1s).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Counts {
    nodes: u32,
    primitives: u32,
    t: f32,
    object: f32,
}

fn transform(rows: &[[f32; 4]; 3], v: [f32; 3], w: f32) -> [f32; 3] {
    rows.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2] + r[3] * w)
}

/// The kernel's loop over one BVH's quantised records (`rtc_bvh::quantized`): near child first,
/// far child deferred, a deferred node visited when popped; `leaf(first, count, best, counts)`
/// tests a leaf. Every visit (inner record or leaf) counts as a node, as `debug_count` does.
fn traverse(
    bvh: &QuantizedBvh,
    o: [f32; 3],
    inv: [f32; 3],
    best: &mut f32,
    c: &mut Counts,
    leaf: &mut dyn FnMut(u32, u32, &mut f32, &mut Counts),
) {
    let mut stack = Vec::new();
    let mut child = Child::decode(bvh.header.root);
    loop {
        c.nodes += 1;
        let mut next = None;
        match child {
            Child::Leaf { first, count } => leaf(first, count, best, c),
            Child::Inner(record) => {
                let [(lb, l), (rb, r)] = bvh.children(record);
                let t = *best;
                let hit = |b: Aabb| slab_box(b.min.into(), b.max.into(), o, inv, 0.0, t);
                next = match (hit(lb), hit(rb)) {
                    (Some(tl), Some(tr)) => {
                        let (near, far) = if tr < tl { (r, l) } else { (l, r) };
                        stack.push(far);
                        Some(near)
                    }
                    (Some(_), None) => Some(l),
                    (None, Some(_)) => Some(r),
                    (None, None) => None,
                };
            }
        }
        match next.or_else(|| stack.pop()) {
            Some(b) => child = b,
            None => return,
        }
    }
}

/// The CPU copy of the kernel's closest-hit traversal, counting as the debug kernel does.
fn reference(e: &Entities, origin: [f32; 3], dir: [f32; 3]) -> Counts {
    let nodes = e.nodes();
    let instances: &[GpuInstance] = e.instances();
    let tris = e.triangles();
    let mut c = Counts {
        nodes: 0,
        primitives: 0,
        t: -1.0,
        object: -1.0,
    };
    let mut best = f32::INFINITY;
    let inv = safe_inverse(dir);
    let tlas = QuantizedBvh::from_records(&nodes[e.tlas_root() as usize..]).expect("a TLAS header");
    // The kernel first tests the TLAS's whole quantisation frame.
    let frame = tlas.header.frame();
    if slab_box(frame.min.into(), frame.max.into(), origin, inv, 0.0, best).is_none() {
        return c;
    }
    traverse(
        &tlas,
        origin,
        inv,
        &mut best,
        &mut c,
        &mut |first, count, best, c| {
            for slot in first..first + count {
                let inst = &instances[slot as usize];
                assert_eq!(inst.geometry_type, GpuInstance::MESH_GEOMETRY);
                let o = transform(&inst.world_to_object, origin, 1.0);
                let d = transform(&inst.world_to_object, dir, 0.0);
                let blas = QuantizedBvh::from_records(&nodes[inst.blas_root as usize..])
                    .expect("a BLAS header");
                traverse(
                    &blas,
                    o,
                    safe_inverse(d),
                    best,
                    c,
                    &mut |first, count, best, c| {
                        for k in 0..count {
                            c.primitives += 1;
                            let prim = (inst.triangle_offset + first + k) as usize;
                            let v = [tris[3 * prim], tris[3 * prim + 1], tris[3 * prim + 2]];
                            if let Some(t) = triangle(v, o, d, 0.0, *best) {
                                *best = t;
                                c.t = t;
                                c.object = inst.object as f32;
                            }
                        }
                    },
                );
            }
        },
    );
    c
}

#[test]
fn debug_counts_match_the_cpu_traversal() {
    let Some(gpu) = gpu_or_skip("debug_counts_match_the_cpu_traversal") else {
        return;
    };
    let dir = temp_dir("debug", "counts");
    let compiled = compile(&dir, DebugMode::Counts);
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    let pixels = renderer.render_debug().expect("debug render");
    assert_eq!(pixels.len(), RAYS.len() * 2, "one value per pixel");
    let e = renderer.entities();
    let expected_t = [9.0, 13.0, 9.0, -1.0, -1.0, 0.8, 4.5];
    let expected_object = [0.0, 4.0, 1.0, -1.0, -1.0, 2.0, 0.0];
    for (i, (o, d)) in RAYS.iter().enumerate() {
        let got = pixels[i];
        let want = reference(e, *o, *d);
        eprintln!("ray {i}: kernel {got:?}, reference {want:?}");
        assert_eq!(got[0], want.nodes as f32, "ray {i}: nodes visited");
        assert_eq!(got[1], want.primitives as f32, "ray {i}: primitives tested");
        assert_eq!(got[3], expected_object[i], "ray {i}: object");
        assert_eq!(want.object, expected_object[i], "ray {i}: reference object");
        let t = expected_t[i];
        assert!(
            (got[2] - t).abs() <= 1e-6 * t.abs(),
            "ray {i}: t = {} (expected {t})",
            got[2]
        );
    }
    // The ray that misses the scene's box visits nothing; every ray that enters it visits at
    // least the scene root, and one that hits a cube visits at least a BLAS root and tests at
    // least one of the cube's triangles.
    assert_eq!(pixels[3][..2], [0.0, 0.0]);
    assert!(pixels[4][0] >= 1.0);
    for i in [0, 1, 2, 5, 6] {
        assert!(pixels[i][0] >= 2.0 && pixels[i][1] >= 1.0, "ray {i}");
        assert!(pixels[i][1] <= 12.0 * CUBES.len() as f32, "ray {i}");
    }
    // Pixels of the second row use the default ray (straight up from above the scene).
    for (i, p) in pixels[RAYS.len()..].iter().enumerate() {
        assert_eq!(*p, [0.0, 0.0, -1.0, -1.0], "row 1, pixel {i}");
    }
}

#[test]
fn debug_rays_are_the_camera_rays() {
    let Some(gpu) = gpu_or_skip("debug_rays_are_the_camera_rays") else {
        return;
    };
    let dir = temp_dir("debug", "rays");
    for mode in [DebugMode::RayOrigin, DebugMode::RayDirection] {
        let compiled = compile(&dir, mode);
        let mut renderer =
            Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
        let pixels = renderer.render_debug().expect("debug render");
        assert_eq!(pixels.len(), RAYS.len() * 2);
        for (i, (o, d)) in RAYS.iter().enumerate() {
            let want = match mode {
                DebugMode::RayOrigin => [o[0], o[1], o[2], 0.0],
                _ => [d[0], d[1], d[2], f32::INFINITY],
            };
            assert_eq!(pixels[i], want, "{mode:?}, ray {i}");
        }
    }
}
