//! The traversal kernel on its own, before any material is involved: known rays against known boxes,
//! triangles and instances, rendered on whatever adapter exists (lavapipe on CI) and compared pixel by
//! pixel with a reference computed here in `f64`.
//!
//! The scenes are `scenes/traversal/rays.rt` and `dispatch.rt`, their ray tables set by the tests: a
//! `@camera` whose `@ray_generation` program returns the test ray of `pixel.x` (each hand-written ray
//! a constant `RAY_i` of the file, every float written as its exact bits), a `@material` whose `@closest_hit` returns
//! `vec3f(hit.t, f32(hit.instance), f32(hit.primitive))`, and a `@background` whose `@miss` returns
//! the sentinel `vec3f(-1.0)`. The image is one row, one ray per pixel, one sample per pixel; it is
//! written as a 32-bit float EXR and read back before the comparison.
//!
//! Tolerances: the instance and triangle indices must be exact; `t` is exact for axis-aligned rays
//! against the unrotated objects `box`, `big` and `floor` (translations, scales 2 and 4), and within a relative 1e-5 otherwise (spec/builtins.md's
//! tolerance of `intersect_triangle`; the pseudo-random rays always use the tolerance); the object `small` (scale 0.5) is measured 1 ulp off. Rays whose reference hit is within 1e-3 (in face coordinates)
//! of an edge or a triangle's diagonal, or whose two nearest surfaces are within a relative 1e-4, are
//! ambiguous in `f32`: the hand-written rays are asserted not to be, the pseudo-random ones are
//! skipped when they are.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::scene::{exact_ray, SceneFile};
use common::{gpu_or_skip, temp_dir};

use glam::{DMat4, DVec3};
use rtc_compiler::kernel::CompiledScene;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::{read_image, write_exr, LinearImage};
use rtc_runtime::render::{RenderOptions, Renderer};

/// Renders `compiled` (one sample per pixel), round-trips the image through an EXR file in `dir`.
/// With `flatten`, the static objects are flattened into one world-space BVH
/// (`RenderOptions::flatten`), which must not change what any ray hits.
fn render(
    gpu: &Gpu,
    compiled: &CompiledScene,
    dir: &std::path::Path,
    flatten: bool,
) -> LinearImage {
    let mut renderer = Renderer::new(
        gpu,
        compiled,
        RenderOptions {
            samples: Some(1),
            flatten,
            ..RenderOptions::default()
        },
    )
    .expect("renderer");
    let result = renderer.render(&mut |_, _| {}).expect("render");
    let s = &result.stats;
    eprintln!(
        "{} rays: pipelines {:.1} ms, render {:.3} ms, flattened {:?}",
        s.width, s.pipeline_ms, s.render_ms, s.flattened
    );
    assert_eq!(s.nonfinite_samples, 0);
    if flatten {
        assert!(
            s.flattened.0 >= 5 && s.flattened.1 == 1,
            "flattened {:?}",
            s.flattened
        );
    }
    let exr = dir.join("out.exr");
    write_exr(&exr, &result.image).expect("write EXR");
    let back = read_image(&exr).expect("read EXR");
    assert_eq!(back.pixels(), result.image.pixels(), "EXR round trip");
    back
}

/// One test ray.
#[derive(Clone, Copy, Debug)]
struct TestRay {
    what: &'static str,
    origin: [f32; 3],
    dir: [f32; 3],
    tmin: f32,
    tmax: f32,
}

fn ray(what: &'static str, origin: [f32; 3], dir: [f32; 3]) -> TestRay {
    TestRay {
        what,
        origin,
        dir,
        tmin: 0.0,
        tmax: f32::INFINITY,
    }
}

/// `file` (`scenes/traversal/rays.rt` or `dispatch.rt`) with its rays `RAY_0`, `RAY_1`, … set to
/// `hand`, every float as its exact bits. The file must declare exactly as many.
fn with_rays(mut file: SceneFile, hand: &[TestRay]) -> SceneFile {
    for (i, r) in hand.iter().enumerate() {
        file = file.set(
            &format!("RAY_{i}"),
            exact_ray(r.origin, r.tmin, r.dir, r.tmax),
        );
    }
    let n = hand.len();
    assert!(
        !file.declares(&format!("RAY_{n}")),
        "the scene file has more hand rays than the test's {n}"
    );
    file
}

/// The centres of [`objects`], which the pseudo-random rays aim at (integers: exact).
const CENTRES: [[f32; 3]; 6] = [
    [0.0, 0.0, -10.0],
    [5.0, 0.0, 0.0],
    [-5.0, 0.0, 0.0],
    [0.0, 5.0, 0.0],
    [0.0, -5.0, -6.0],
    [0.0, -5.0, 0.0],
];

fn mix_bits(x: u32) -> u32 {
    let mut h = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    h = ((h >> ((h >> 28) + 4)) ^ h).wrapping_mul(277_803_737);
    (h >> 22) ^ h
}

fn grid(key: u32, lo: f32, steps: u32) -> f32 {
    (mix_bits(key) % steps) as f32 * 0.125 + lo
}

/// The program's `random_ray(i)`, with the same (exact) `f32` arithmetic.
fn random_ray(i: u32) -> TestRay {
    let k = i * 8;
    let origin = [
        grid(k, -12.0, 193),
        grid(k + 1, -8.0, 145),
        grid(k + 2, -14.0, 209),
    ];
    let c = CENTRES[(i % CENTRES.len() as u32) as usize];
    let mut dir = [0.0f32; 3];
    for a in 0..3 {
        dir[a] = c[a] + grid(k + 3 + a as u32, -1.25, 21) - origin[a];
    }
    if i % 4 == 3 {
        dir[(i / 4 % 3) as usize] = 0.0;
    }
    ray("pseudo-random", origin, dir)
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    /// `cube_mesh()`: [-1, 1]³, face f (+x, -x, +y, -y, +z, -z) has triangles 2f and 2f + 1.
    Cube,
    /// `quad_mesh()`: [-1, 1]² in y = 0, triangles 0 (z ≥ x) and 1.
    Quad,
}

struct Object {
    name: &'static str,
    shape: Shape,
    /// The transform as the scene writes it.
    source: &'static str,
    /// The same transform.
    matrix: DMat4,
    /// Whether `t` is asserted exact for axis-aligned rays (translations and the scales measured
    /// exact; the others within 1e-5 relative).
    exact: bool,
}

fn objects() -> Vec<Object> {
    let t = |x: f64, y: f64, z: f64| DMat4::from_translation(DVec3::new(x, y, z));
    vec![
        Object {
            name: "box",
            shape: Shape::Cube,
            source: "translate(vec3f(0.0, 0.0, -10.0))",
            matrix: t(0.0, 0.0, -10.0),
            exact: true,
        },
        // Four instances of the one cube mesh with different transforms.
        Object {
            name: "small",
            shape: Shape::Cube,
            source: "translate(vec3f(5.0, 0.0, 0.0)) * scale(0.5)",
            matrix: t(5.0, 0.0, 0.0) * DMat4::from_scale(DVec3::splat(0.5)),
            // Measured: t = 14.500001 for 14.5 (1 ulp; the object-space direction is 2, and the
            // watertight test's scaled determinant rounds), within the 1e-5 tolerance.
            exact: false,
        },
        Object {
            name: "turned",
            shape: Shape::Cube,
            source: "translate(vec3f(-5.0, 0.0, 0.0)) * rotate_y(30.0) * scale(vec3f(1.0, 2.0, 1.0))",
            matrix: t(-5.0, 0.0, 0.0)
                * DMat4::from_rotation_y(30f64.to_radians())
                * DMat4::from_scale(DVec3::new(1.0, 2.0, 1.0)),
            exact: false,
        },
        Object {
            name: "big",
            shape: Shape::Cube,
            source: "translate(vec3f(0.0, 5.0, 0.0)) * scale(2.0)",
            matrix: t(0.0, 5.0, 0.0) * DMat4::from_scale(DVec3::splat(2.0)),
            exact: true,
        },
        Object {
            name: "tilted",
            shape: Shape::Cube,
            source: "translate(vec3f(0.0, -5.0, -6.0)) * rotate(vec3f(1.0, 1.0, 0.0), 40.0) * scale(0.75)",
            matrix: t(0.0, -5.0, -6.0)
                * DMat4::from_axis_angle(DVec3::new(1.0, 1.0, 0.0).normalize(), 40f64.to_radians())
                * DMat4::from_scale(DVec3::splat(0.75)),
            exact: false,
        },
        Object {
            name: "floor",
            shape: Shape::Quad,
            source: "translate(vec3f(0.0, -5.0, 0.0)) * scale(4.0)",
            matrix: t(0.0, -5.0, 0.0) * DMat4::from_scale(DVec3::splat(4.0)),
            exact: true,
        },
    ]
}

/// `scenes/traversal/rays.rt` with `hand`, `random` pseudo-random rays aimed at [`CENTRES`]; asserts
/// that the file's objects are `objects`, in order, with the same transforms.
fn rays_scene(hand: &[TestRay], random: u32, objects: &[Object]) -> SceneFile {
    let mut file = with_rays(SceneFile::open("traversal/rays.rt"), hand)
        .set("RANDOM_RAYS", format!("{random}u"));
    for (j, c) in CENTRES.iter().enumerate() {
        file = file.set(
            &format!("CENTRE_{j}"),
            format!("vec3f({:?}, {:?}, {:?})", c[0], c[1], c[2]),
        );
    }
    assert!(!file.declares(&format!("CENTRE_{}", CENTRES.len())));
    let mut at = 0;
    for o in objects {
        let geometry = match o.shape {
            Shape::Cube => "cube_mesh()",
            Shape::Quad => "quad_mesh()",
        };
        let line = format!(
            "    object {} {{ geometry: {geometry}, material: probe, transform: {} }}\n",
            o.name, o.source
        );
        let found = file.text()[at..].find(&line).unwrap_or_else(|| {
            panic!("scenes/traversal/rays.rt lacks, after the objects before it:\n{line}")
        });
        at += found + line.len();
    }
    file
}

/// (outward normal, image right, image up) of the cube's faces, as `cube_mesh()` builds them.
const FACES: [([f64; 3], [f64; 3], [f64; 3]); 6] = [
    ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]),
    ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
    ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
    ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
    ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
];

/// A surface hit of the reference.
#[derive(Clone, Copy, Debug)]
struct RefHit {
    t: f64,
    object: usize,
    primitive: u32,
    /// Distance (in face coordinates) to the nearest edge or diagonal.
    margin: f64,
}

/// Every hit of the object-space ray `(o, d)` with `object`'s shape, any `t`.
fn shape_hits(shape: Shape, o: DVec3, d: DVec3, object: usize, out: &mut Vec<RefHit>) {
    match shape {
        Shape::Cube => {
            for (f, (n, right, up)) in FACES.iter().enumerate() {
                let (n, right, up) = (DVec3::from(*n), DVec3::from(*right), DVec3::from(*up));
                let dn = d.dot(n);
                if dn == 0.0 {
                    continue; // parallel to the face: the watertight test never hits it
                }
                let t = (1.0 - o.dot(n)) / dn;
                let p = o + d * t;
                let (u, v) = ((p.dot(right) + 1.0) * 0.5, (1.0 - p.dot(up)) * 0.5);
                if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
                    continue;
                }
                // Triangles (top-left, bottom-left, bottom-right) and (top-left, bottom-right,
                // top-right): the first covers v ≥ u.
                let primitive = 2 * f as u32 + u32::from(u > v);
                let margin = u.min(1.0 - u).min(v).min(1.0 - v).min((u - v).abs());
                out.push(RefHit {
                    t,
                    object,
                    primitive,
                    margin,
                });
            }
        }
        Shape::Quad => {
            if d.y == 0.0 {
                return;
            }
            let t = -o.y / d.y;
            let p = o + d * t;
            if p.x.abs() > 1.0 || p.z.abs() > 1.0 {
                return;
            }
            // Triangles (0, 3, 2) = (-1,-1), (-1,1), (1,1) in (x, z), i.e. z ≥ x, and (0, 2, 1).
            let primitive = u32::from(p.x > p.z);
            let margin = ((1.0 - p.x.abs())
                .min(1.0 - p.z.abs())
                .min((p.x - p.z).abs()))
                * 0.5;
            out.push(RefHit {
                t,
                object,
                primitive,
                margin,
            });
        }
    }
}

/// What the reference expects for one ray.
#[derive(Debug)]
enum Expect {
    Miss,
    Hit(RefHit),
    /// Too close to an edge or to a tie between two surfaces to be decided in `f32`.
    Ambiguous(String),
}

fn reference(r: &TestRay, objects: &[Object]) -> Expect {
    let o = DVec3::from(r.origin.map(f64::from));
    let d = DVec3::from(r.dir.map(f64::from));
    let mut hits = Vec::new();
    for (i, obj) in objects.iter().enumerate() {
        let inv = obj.matrix.inverse();
        shape_hits(
            obj.shape,
            inv.transform_point3(o),
            inv.transform_vector3(d),
            i,
            &mut hits,
        );
    }
    hits.retain(|h| h.t >= f64::from(r.tmin) && h.t <= f64::from(r.tmax));
    hits.sort_by(|a, b| a.t.total_cmp(&b.t));
    let Some(&first) = hits.first() else {
        return Expect::Miss;
    };
    if first.margin < 1e-3 {
        return Expect::Ambiguous(format!("{first:?} is near an edge"));
    }
    if let Some(second) = hits.get(1) {
        if (second.t - first.t).abs() <= 1e-4 * first.t.abs() {
            return Expect::Ambiguous(format!("{first:?} ties with {second:?}"));
        }
    }
    Expect::Hit(first)
}

/// Whether every component of the ray is axis-aligned (one non-zero direction component).
fn axis_aligned(r: &TestRay) -> bool {
    r.dir.iter().filter(|c| **c != 0.0).count() == 1
}

/// Checks every pixel; returns how many rays hit and missed.
fn check(
    img: &LinearImage,
    rays: &[TestRay],
    first_pixel: u32,
    objects: &[Object],
    strict: bool,
) -> (usize, usize) {
    let (mut hits, mut misses) = (0, 0);
    let mut failures = Vec::new();
    for (x, r) in (first_pixel..).zip(rays) {
        let got = img.get(x, 0).expect("pixel");
        let got = [got[0], got[1], got[2]];
        match reference(r, objects) {
            Expect::Ambiguous(why) => {
                assert!(
                    !strict,
                    "hand-written ray {x} ({}) is ambiguous: {why}",
                    r.what
                );
            }
            Expect::Miss => {
                misses += 1;
                if got != [-1.0; 3] {
                    failures.push(format!(
                        "ray {x} ({}) {r:?}: want a miss, got {got:?}",
                        r.what
                    ));
                }
            }
            Expect::Hit(h) => {
                hits += 1;
                // Exact for the hand-written axis-aligned rays (unit directions, `t` an integer or a
                // half); a pseudo-random direction's length rounds (measured: 1.8000001 for 1.8).
                let exact = strict && axis_aligned(r) && objects[h.object].exact;
                let t_ok = if exact {
                    f64::from(got[0]) == h.t
                } else {
                    (f64::from(got[0]) - h.t).abs() <= 1e-5 * h.t.abs()
                };
                if !t_ok || got[1] != h.object as f32 || got[2] != h.primitive as f32 {
                    failures.push(format!(
                        "ray {x} ({}) {r:?}: want t = {} ({}), object {} ({}), triangle {}; got {got:?}",
                        r.what,
                        h.t,
                        if exact { "exact" } else { "1e-5 relative" },
                        h.object,
                        objects[h.object].name,
                        h.primitive
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    (hits, misses)
}

/// The hand-written rays: each is one of the cases the kernel must get right.
fn hand_rays() -> Vec<TestRay> {
    let before = |x: f32| f32::from_bits(x.to_bits() - 1);
    let after = |x: f32| f32::from_bits(x.to_bits() + 1);
    let front = [0.3, -0.6, 0.0];
    let down = [0.0, 0.0, -1.0];
    vec![
        // Axis-parallel rays (two zero direction components) hitting and missing boxes.
        ray("axis -z hits box front face", front, down),
        ray("axis -z passes beside box", [1.5, 0.0, 0.0], down),
        ray(
            "axis +y hits big's bottom",
            [0.5, 0.0, 0.7],
            [0.0, 1.0, 0.0],
        ),
        ray(
            "axis +y passes beside big",
            [2.5, 0.0, 0.7],
            [0.0, 1.0, 0.0],
        ),
        ray("axis -y hits floor", [0.5, 0.0, 0.25], [0.0, -1.0, 0.0]),
        ray(
            "axis -y hits floor (other triangle)",
            [-0.5, 0.0, 0.25],
            [0.0, -1.0, 0.0],
        ),
        ray(
            "axis +x from far left, misses",
            [-20.0, 2.5, 0.0],
            [1.0, 0.0, 0.0],
        ),
        ray(
            "axis -x with negative zero components",
            [20.0, 0.1, 0.2],
            [-1.0, -0.0, -0.0],
        ),
        // Rays starting inside a box hit its inside faces.
        ray("inside small, toward +x", [5.0, 0.2, 0.1], [1.0, 0.0, 0.0]),
        ray("inside box, toward -y", [0.3, 0.0, -10.4], [0.0, -1.0, 0.0]),
        ray("inside big, oblique", [0.1, 5.2, 0.3], [0.3, 1.0, -0.2]),
        // Inclusive [tmin, tmax]: the front face is at t = 9 exactly.
        TestRay {
            tmax: 9.0,
            ..ray("tmax exactly at the front face", front, down)
        },
        TestRay {
            tmax: before(9.0),
            ..ray("tmax just before the front face", front, down)
        },
        TestRay {
            tmax: after(9.0),
            ..ray("tmax just after the front face", front, down)
        },
        TestRay {
            tmin: 9.0,
            ..ray("tmin exactly at the front face", front, down)
        },
        TestRay {
            tmin: after(9.0),
            ..ray("tmin just after the front face: the back face", front, down)
        },
        TestRay {
            tmin: after(9.0),
            tmax: before(11.0),
            ..ray("between the faces: nothing", front, down)
        },
        TestRay {
            tmin: 11.0,
            tmax: 11.0,
            ..ray("empty range exactly at the back face", front, down)
        },
        // Instances of one mesh: the index must be the right one.
        ray("turned, oblique", [-4.6, 0.3, 10.0], [0.0, -0.05, -1.0]),
        ray("turned from above", [-5.2, 10.0, 0.1], [0.0, -1.0, 0.0]),
        ray("tilted from above", [0.1, 0.0, -6.1], [0.0, -1.0, 0.0]),
        ray("tilted, oblique", [3.0, -3.0, -3.0], [-0.9, -0.6, -0.8]),
        // Nearest of several: both orders along the same line (turned, then small, and back).
        ray(
            "+x: turned before small",
            [-20.0, 0.1, 0.1],
            [1.0, 0.0, 0.0],
        ),
        ray(
            "-x: small before turned",
            [20.0, 0.1, 0.15],
            [-1.0, 0.0, 0.0],
        ),
        ray(
            "-y: big before the floor",
            [0.5, 20.0, 0.7],
            [0.0, -1.0, 0.0],
        ),
        ray(
            "-z through box from behind the camera",
            [0.3, -0.6, 30.0],
            down,
        ),
        // Grazing: in the floor's plane, and along the box's +x face.
        ray("in the floor's plane", [-10.0, -5.0, 0.5], [1.0, 0.0, 0.0]),
        ray(
            "in the floor's plane, diagonal",
            [-10.0, -5.0, -9.0],
            [1.0, 0.0, 1.0],
        ),
        ray(
            "along the box's +y face plane, beside it",
            [-10.0, 1.0, -12.0],
            [1.0, 0.0, 0.0],
        ),
    ]
}

/// How many pseudo-random rays follow the hand-written ones.
const RANDOM_RAYS: u32 = 256;

#[test]
fn known_rays_hit_what_the_reference_hits() {
    let Some(gpu) = gpu_or_skip("known_rays_hit_what_the_reference_hits") else {
        return;
    };
    let objects = objects();
    let hand = hand_rays();
    let dir = temp_dir("traversal", "rays");
    let compiled = rays_scene(&hand, RANDOM_RAYS, &objects).compile(&dir);
    // Without and with the objects flattened into one world-space BVH: the same hits, objects
    // and triangles.
    for flatten in [false, true] {
        let img = render(&gpu, &compiled, &dir, flatten);
        let (hits, misses) = check(&img, &hand, 0, &objects, true);
        eprintln!("hand-written rays (flatten {flatten}): {hits} hits and {misses} misses checked");
        assert!(hits >= 20 && misses >= 6, "{hits} hits, {misses} misses");
        let random: Vec<TestRay> = (0..RANDOM_RAYS).map(random_ray).collect();
        let (hits, misses) = check(&img, &random, hand.len() as u32, &objects, false);
        eprintln!(
            "pseudo-random rays (flatten {flatten}): {hits} hits and {misses} misses checked"
        );
        assert!(hits >= 100 && misses >= 20, "{hits} hits, {misses} misses");
    }
}

/// Dispatch (`scenes/traversal/dispatch.rt`): three material types declared only in the scene file (no Rust code knows them), one
/// of them used twice with different parameters, and the probe material; each object covers its
/// own pixel, and every pixel shows exactly its object's constant.
#[test]
fn each_material_id_reaches_its_program() {
    let Some(gpu) = gpu_or_skip("each_material_id_reaches_its_program") else {
        return;
    };
    let down = [0.0, 0.0, -1.0];
    let hand = [
        ray("red 3", [-6.0, 0.3, 0.0], down),
        ray("green", [-2.0, 0.3, 0.0], down),
        ray("blue", [2.0, 0.3, 0.0], down),
        ray("red 9", [6.0, 0.3, 0.0], down),
        ray("probe", [10.0, 0.3, 0.0], down),
        ray("nothing", [14.0, 0.3, 0.0], down),
    ];
    let dir = temp_dir("traversal", "dispatch");
    let compiled = with_rays(SceneFile::open("traversal/dispatch.rt"), &hand).compile(&dir);
    let materials = compiled
        .linked
        .types
        .values()
        .flatten()
        .filter(|t| t.role.name() == "material")
        .count();
    assert_eq!(materials, 4, "Red, Green, Blue and HitProbe are linked");
    // The probe's triangle: the +z face (triangles 8, 9) at face coordinates u = 0.5, v = 0.35.
    let want: [[f32; 3]; 6] = [
        [3.0, 0.0, 0.0],
        [0.0, 5.0, 0.5],
        [0.0, 0.0, 7.0],
        [9.0, 0.0, 0.0],
        [9.0, 4.0, 9.0],
        [-1.0; 3],
    ];
    // Flattened, the five cubes share one world-space BVH and each hit still reaches its own
    // object's material and parameters.
    for flatten in [false, true] {
        let img = render(&gpu, &compiled, &dir, flatten);
        for (x, (w, r)) in (0u32..).zip(want.iter().zip(&hand)) {
            let got = img.get(x, 0).expect("pixel");
            assert_eq!(&got[..3], w, "pixel {x} ({}), flatten {flatten}", r.what);
        }
    }
}
