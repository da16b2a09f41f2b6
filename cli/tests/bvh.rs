//! End-to-end tests of `rtc bvh` on lavapipe (skipped, saying so, where no adapter exists): the
//! level-0 box of a one-object scene is drawn exactly on its projected edges, an unknown
//! `--object` lists the scene's objects, and the heat map is brighter where there is geometry.

mod common;

use common::{no_gpu, rtc, s, scratch, text};
use rtc_runtime::image_out::{read_image, LinearImage};
use std::path::{Path, PathBuf};

const W: u32 = 96;
const H: u32 = 72;
const POS: [f32; 3] = [2.5, 1.8, 4.0];
const FOV: f32 = 50.0;

/// A unit cube ([-1, 1]³) seen by a pinhole camera at `POS` looking at the origin.
fn cube_scene(dir: &Path) -> PathBuf {
    let file = dir.join("cube.rt");
    std::fs::write(
        &file,
        format!(
            "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
             import \"std/lights/point.rt\";\n\
             scene cube {{\n    settings {{ width: {W}, height: {H}, samples: 1, max_depth: 0 }}\n    \
             camera Pinhole {{ position: vec3f({:.1}, {:.1}, {:.1}), look_at: vec3f(0.0), fov: {FOV:.1} }}\n    \
             object box {{ geometry: cube_mesh(), material: Lambert {{ albedo: vec3f(0.5) }} }}\n    \
             light PointLight {{ position: vec3f(2.0, 4.0, 3.0), intensity: 20.0 }}\n}}\n",
            POS[0], POS[1], POS[2]
        ),
    )
    .expect("write the scene");
    file
}

type V = [f32; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V, b: V) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm(a: V) -> V {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// Pixel coordinates of a world point, with the projection of `std/cameras/pinhole.rt`.
fn project(p: V) -> [f32; 2] {
    let forward = norm(sub([0.0; 3], POS));
    let right = norm(cross(forward, [0.0, 1.0, 0.0]));
    let up = cross(right, forward);
    let h = (FOV.to_radians() * 0.5).tan();
    let aspect = W as f32 / H as f32;
    let v = sub(p, POS);
    let z = dot(v, forward);
    let nx = dot(v, right) / z / (h * aspect);
    let ny = -dot(v, up) / z / h;
    [(nx + 1.0) * 0.5 * W as f32, (ny + 1.0) * 0.5 * H as f32]
}

fn seg_dist(p: [f32; 2], a: [f32; 2], b: [f32; 2]) -> f32 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let u = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0);
    ((p[0] - a[0] - u * d[0]).powi(2) + (p[1] - a[1] - u * d[1]).powi(2)).sqrt()
}

/// The 12 projected edges of [-1, 1]³.
fn edges() -> Vec<([f32; 2], [f32; 2])> {
    let corner = |i: u32| {
        [
            if i & 1 != 0 { 1.0 } else { -1.0 },
            if i & 2 != 0 { 1.0 } else { -1.0 },
            if i & 4 != 0 { 1.0 } else { -1.0 },
        ]
    };
    let mut out = Vec::new();
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                out.push((project(corner(i)), project(corner(i | bit))));
            }
        }
    }
    out
}

fn lit(image: &LinearImage, x: u32, y: u32) -> Option<[f32; 4]> {
    image.get(x, y).filter(|p| p[0] + p[1] + p[2] > 0.0)
}

/// Level 0 of a one-object scene is the object's world box: every drawn pixel is within 1.5 px
/// of a projected cube edge and red (level 0), and every visible stretch of every edge has a drawn
/// pixel within 1.5 px.
#[test]
fn level_zero_box_is_drawn_on_the_projected_edges() {
    let dir = scratch("bvh", "edges");
    let scene = cube_scene(&dir);
    let out_png = dir.join("boxes.png");
    let out = rtc(&[
        "bvh",
        s(&scene),
        "--level",
        "0",
        "--boxes-only",
        "-o",
        s(&out_png),
    ]);
    if no_gpu(&out) {
        return;
    }
    assert!(out.status.success(), "{}", text(&out));
    assert!(text(&out).contains("levels: 0 red"), "{}", text(&out));
    let image = read_image(&out_png).expect("read the picture");
    assert_eq!((image.width(), image.height()), (W, H));
    let edges = edges();
    let mut drawn = Vec::new();
    for y in 0..H {
        for x in 0..W {
            let Some(p) = lit(&image, x, y) else { continue };
            let c = [x as f32 + 0.5, y as f32 + 0.5];
            let d = edges
                .iter()
                .map(|&(a, b)| seg_dist(c, a, b))
                .fold(f32::INFINITY, f32::min);
            assert!(d <= 1.5, "pixel ({x}, {y}) is drawn {d} px from every edge");
            assert!(p[0] > 0.8 && p[1] < 0.1 && p[2] < 0.1, "not red: {p:?}");
            drawn.push(c);
        }
    }
    assert!(drawn.len() > 150, "only {} edge pixels", drawn.len());
    for &(a, b) in &edges {
        for k in 0..=10 {
            let u = k as f32 / 10.0;
            let q = [a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u];
            if q[0] < 1.0 || q[1] < 1.0 || q[0] > W as f32 - 1.0 || q[1] > H as f32 - 1.0 {
                continue;
            }
            assert!(
                drawn
                    .iter()
                    .any(|p| (p[0] - q[0]).abs() <= 1.5 && (p[1] - q[1]).abs() <= 1.5),
                "nothing drawn near {q:?} on the edge {a:?}-{b:?}"
            );
        }
    }
}

#[test]
fn unknown_object_lists_the_names_and_too_deep_a_level_names_the_deepest() {
    let dir = scratch("bvh", "names");
    let scene = cube_scene(&dir);
    let png = dir.join("x.png");
    let out = rtc(&["bvh", s(&scene), "--object", "nope", "-o", s(&png)]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let t = text(&out);
    assert!(
        t.contains("no object named `nope`; its objects are: `box`"),
        "{t}"
    );
    assert!(!t.contains("panicked"), "{t}");
    assert!(!png.exists());
    let out = rtc(&["bvh", s(&scene), "--level", "40", "-o", s(&png)]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("level 40 is deeper than the BVH"),
        "{}",
        text(&out)
    );
    // The object's own BVH, by name, works.
    let out = rtc(&["bvh", s(&scene), "--object", "box", "-o", s(&png)]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        text(&out).contains("object-level BVH of `box`"),
        "{}",
        text(&out)
    );
}

/// In the nodes panel (left, at x = 6, y = 16: see `rtc_runtime::bvh_view::heatmap`), the pixel
/// at the cube's centre is brighter than a corner pixel whose ray misses everything.
#[test]
fn heat_map_is_brighter_on_geometry() {
    let dir = scratch("bvh", "heat");
    let scene = cube_scene(&dir);
    let png = dir.join("heat.png");
    let out = rtc(&["bvh", s(&scene), "--heatmap", "-o", s(&png)]);
    if no_gpu(&out) {
        return;
    }
    assert!(out.status.success(), "{}", text(&out));
    let t = text(&out);
    assert!(
        t.contains("nodes visited") && t.contains("primitives tested"),
        "{t}"
    );
    let image = read_image(&png).expect("read the heat map");
    assert_eq!(image.width(), 2 * W + 18);
    let lum = |x: u32, y: u32| {
        let p = image.get(6 + x, 16 + y).expect("inside the panel");
        p[0] + p[1] + p[2]
    };
    let centre = project([0.0; 3]);
    let on = lum(centre[0] as u32, centre[1] as u32);
    let off = lum(1, 1);
    assert!(on > off + 0.05, "on the cube {on}, off it {off}");
    // The primitives panel too.
    let lum2 = |x: u32, y: u32| {
        let p = image.get(12 + W + x, 16 + y).expect("inside the panel");
        p[0] + p[1] + p[2]
    };
    assert!(lum2(centre[0] as u32, centre[1] as u32) > lum2(1, 1) + 0.05);
}
