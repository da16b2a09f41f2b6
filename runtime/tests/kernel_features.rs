//! The kernel's features beyond plain closest-hit traversal (issue 4), each on a scene written here
//! with its own test programs, rendered on whatever adapter exists (lavapipe on CI):
//!
//! - `@any_hit` for alpha: a cut-out whose program rejects half of its surface; the rejected hits are
//!   ignored (the floor behind shows through), the accepted ones are seen. Exact colours.
//! - `@any_hit` for shadow rays: blockers invisible to camera rays, one that casts no shadow at all
//!   (a fog boundary), one cut in half, one cut elsewhere; a floor point is dark exactly where some
//!   blocker accepts its shadow ray. Exact 0 or 1.
//! - media: nested closed boxes with `@medium` programs (Beer–Lambert absorption) and boundaries that
//!   let rays through; a camera inside the outer box (its rays start in that medium) and one
//!   outside it. Every ray enters and leaves media at hits; the transmittance must be
//!   `exp(-Σ σᵢ dᵢ)` over the segments, within 1e-4 relative.
//! - custom geometry whose `@intersection` walks its own mesh BVH with `mesh_node` and
//!   `mesh_triangle`: it must see what the built-in mesh geometry sees (hit or miss for every pixel,
//!   `t` within 1e-5 relative, geometric normal within 1e-5 except at most 1% of the pixels, where
//!   a ray through a shared edge may take either triangle).
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::gpu_or_skip;
use std::path::PathBuf;

use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene, CompiledScene};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::{RenderOptions, Renderer};

/// Compiles `text` (written as `scene.rt` in a fresh folder) and renders it with one sample.
fn render(gpu: &Gpu, name: &str, text: &str) -> LinearImage {
    let dir: PathBuf =
        std::env::temp_dir().join(format!("rtc-features-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("scene.rt");
    std::fs::write(&path, text).expect("scene file");
    let compiled: CompiledScene = match compile_scene(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions::default(),
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "{name}: compile failed:\n{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    };
    let mut renderer = Renderer::new(
        gpu,
        &compiled,
        RenderOptions {
            samples: Some(1),
            ..RenderOptions::default()
        },
    )
    .expect("renderer");
    let result = renderer.render(&mut |_, _| {}).expect("render");
    assert_eq!(
        result.stats.nonfinite_samples, 0,
        "{name}: non-finite samples"
    );
    let _ = std::fs::remove_dir_all(&dir);
    result.image
}

fn px(img: &LinearImage, x: u32, y: u32) -> [f32; 3] {
    let p = img.get(x, y).expect("pixel inside the image");
    [p[0], p[1], p[2]]
}

/// A camera looking straight down (-y) from y = 10 with parallel rays through the pixel centres over
/// `x, z ∈ [-half, half]`; the background is blue and a plain material returns its colour.
const DOWN: &str = r#"
@camera
struct Down {
    half: f32 = 3.0,
}

@ray_generation
fn down_ray(c: Down, pixel: vec2u, sample: u32) -> Ray {
    let size = image_size();
    let u = (f32(pixel.x) + 0.5) / f32(size.x) * 2.0 - 1.0;
    let v = (f32(pixel.y) + 0.5) / f32(size.y) * 2.0 - 1.0;
    return Ray { origin: vec3f(u * c.half, 10.0, v * c.half), dir: vec3f(0.0, -1.0, 0.0) };
}

@background
struct Blue {
    unused: f32 = 0.0,
}

@miss
fn blue(b: Blue, ray: Ray) -> vec3f {
    return vec3f(0.0, 0.0, 1.0);
}

@material
struct Plain {
    color: vec3f = vec3f(0.0, 1.0, 0.0),
}

@closest_hit
fn plain(m: Plain, ray: Ray, hit: Hit) -> vec3f {
    return m.color;
}
"#;

/// Image side of the `Down` scenes: 24 pixels over 6 units, pixel centres at `-2.875 + 0.25 k`, so
/// none lies on a cut at x = 0 or x = -1.5, on z = 0, or on an edge of the quads.
const SIDE: u32 = 24;

/// World x (or z) of pixel column (or row) `i`.
fn coord(i: u32) -> f64 {
    (f64::from(i) + 0.5) / f64::from(SIDE) * 6.0 - 3.0
}

#[test]
fn an_any_hit_cut_out_hides_only_what_it_accepts() {
    let Some(gpu) = gpu_or_skip("an_any_hit_cut_out_hides_only_what_it_accepts") else {
        return;
    };
    let text = format!(
        r#"{DOWN}
/// Accepts hits with x > 0 only: its other half is a hole.
@material
struct CutOut {{
    color: vec3f = vec3f(1.0, 0.0, 0.0),
}}

@any_hit
fn cut_out_keep(m: CutOut, ray: Ray, hit: Hit) -> bool {{
    return hit.position.x > 0.0;
}}

@closest_hit
fn cut_out_shade(m: CutOut, ray: Ray, hit: Hit) -> vec3f {{
    return m.color;
}}

scene cut_out {{
    settings {{ width: {SIDE}, height: {SIDE}, samples: 1 }}
    camera Down {{}}
    background Blue {{}}
    // The cut-out above the floor, covering z < 0; the floor covers x < 2.
    object sheet {{ geometry: quad_mesh(), material: CutOut {{}}, transform: translate(vec3f(0.0, 1.0, -1.5)) * scale(vec3f(3.0, 1.0, 1.5)) }}
    object floor {{ geometry: quad_mesh(), material: Plain {{}}, transform: translate(vec3f(-0.5, 0.0, 0.0)) * scale(vec3f(2.5, 1.0, 3.0)) }}
}}
"#
    );
    let img = render(&gpu, "cut-out", &text);
    for y in 0..SIDE {
        for x in 0..SIDE {
            let (wx, wz) = (coord(x), coord(y));
            let want = if wz < 0.0 && wx > 0.0 {
                [1.0, 0.0, 0.0] // the accepted half of the cut-out
            } else if wx < 2.0 {
                [0.0, 1.0, 0.0] // the floor, through the hole or beside the cut-out
            } else {
                [0.0, 0.0, 1.0]
            };
            assert_eq!(
                px(&img, x, y),
                want,
                "pixel ({x}, {y}) at x = {wx}, z = {wz}"
            );
        }
    }
}

#[test]
fn shadow_rays_stop_at_the_first_hit_an_any_hit_accepts() {
    let Some(gpu) = gpu_or_skip("shadow_rays_stop_at_the_first_hit_an_any_hit_accepts") else {
        return;
    };
    let text = format!(
        r#"{DOWN}
/// Invisible to camera rays; for shadow rays it accepts hits with `above < x < below`, and none
/// when `casts` is 0.
@material
struct Blocker {{
    above: f32 = -1000.0,
    below: f32 = 1000.0,
    casts: f32 = 1.0,
}}

@any_hit
fn blocker_keep(m: Blocker, ray: Ray, hit: Hit) -> bool {{
    if ray.kind != RAY_SHADOW || m.casts == 0.0 {{
        return false;
    }}
    return hit.position.x > m.above && hit.position.x < m.below;
}}

@closest_hit
fn blocker_shade(m: Blocker, ray: Ray, hit: Hit) -> vec3f {{
    return vec3f(1.0, 0.0, 1.0);
}}

/// White where the way straight up is clear, black where something blocks it.
@material
struct Sunlit {{
    unused: f32 = 0.0,
}}

@closest_hit
fn sunlit(m: Sunlit, ray: Ray, hit: Hit) -> vec3f {{
    return vec3f(shadow(hit.position, hit.geometric_normal, vec3f(0.0, 1.0, 0.0), 100.0));
}}

scene shadows {{
    settings {{ width: {SIDE}, height: {SIDE}, samples: 1 }}
    camera Down {{}}
    background Blue {{}}
    object floor {{ geometry: quad_mesh(), material: Sunlit {{}}, transform: scale(vec3f(3.0, 1.0, 3.0)) }}
    // z < 0: blocks where x > 0.
    object half {{ geometry: quad_mesh(), material: Blocker {{ above: 0.0 }}, transform: translate(vec3f(0.0, 1.0, -1.5)) * scale(vec3f(3.0, 1.0, 1.5)) }}
    // z > 0: casts no shadow at all (below a blocker that would).
    object clear {{ geometry: quad_mesh(), material: Blocker {{ casts: 0.0 }}, transform: translate(vec3f(0.0, 2.0, 1.5)) * scale(vec3f(3.0, 1.0, 1.5)) }}
    // Everywhere, above the others: blocks where x < -1.5.
    object strip {{ geometry: quad_mesh(), material: Blocker {{ below: -1.5 }}, transform: translate(vec3f(0.0, 3.0, 0.0)) * scale(vec3f(3.0, 1.0, 3.0)) }}
}}
"#
    );
    let img = render(&gpu, "shadows", &text);
    let mut dark = 0;
    for y in 0..SIDE {
        for x in 0..SIDE {
            let (wx, wz) = (coord(x), coord(y));
            let blocked = (wz < 0.0 && wx > 0.0) || wx < -1.5;
            let v = if blocked { 0.0 } else { 1.0 };
            dark += usize::from(blocked);
            assert_eq!(
                px(&img, x, y),
                [v, v, v],
                "pixel ({x}, {y}) at x = {wx}, z = {wz}"
            );
        }
    }
    assert!(dark > 0 && dark < (SIDE * SIDE) as usize);
}

#[test]
fn rays_enter_and_leave_nested_media_at_hits() {
    let Some(gpu) = gpu_or_skip("rays_enter_and_leave_nested_media_at_hits") else {
        return;
    };
    const SA: f64 = 0.05;
    const SB: f64 = 0.3;
    let text = format!(
        r#"
/// Row 0: rays along -z from z = 0 (inside the outer box); row 1: from z = 20 (outside it). Column
/// `i` at x = i - 3.5, y = 0.3.
@camera
struct Rows {{
    unused: f32 = 0.0,
}}

@ray_generation
fn rows_ray(c: Rows, pixel: vec2u, sample: u32) -> Ray {{
    let z = select(0.0, 20.0, pixel.y == 1u);
    return Ray {{ origin: vec3f(f32(pixel.x) - 3.5, 0.3, z), dir: vec3f(0.0, 0.0, -1.0) }};
}}

@background
struct White {{
    unused: f32 = 0.0,
}}

@miss
fn white(b: White, ray: Ray) -> vec3f {{
    return vec3f(1.0);
}}

/// An absorbing volume with a boundary that lets rays through unchanged.
@material
struct Absorber {{
    sigma: f32 = 0.1,
}}

@secondary_rays
fn absorber_rays(m: Absorber, ray: Ray, hit: Hit) {{
    spawn(ray.dir, vec3f(1.0));
}}

@closest_hit
fn absorber_shade(m: Absorber, ray: Ray, hit: Hit, secondary: vec3f) -> vec3f {{
    return secondary;
}}

@medium
fn absorber_medium(m: Absorber, ray: Ray, t: f32, radiance: vec3f) -> vec3f {{
    return radiance * exp(-m.sigma * t * length(ray.dir));
}}

scene nested {{
    settings {{ width: 8, height: 2, samples: 1, max_depth: 6 }}
    camera Rows {{}}
    background White {{}}
    // [-10, 10]³ around everything.
    object outer {{ geometry: cube_mesh(), material: Absorber {{ sigma: {SA:?} }}, transform: scale(10.0) }}
    // x in [-4, 0], y in [-2, 2], z in [-5, -3]: in front of the left half of the rays.
    object inner {{ geometry: cube_mesh(), material: Absorber {{ sigma: {SB:?} }}, transform: translate(vec3f(-2.0, 0.0, -4.0)) * scale(vec3f(2.0, 2.0, 1.0)) }}
}}
"#
    );
    let img = render(&gpu, "nested-media", &text);
    for row in 0..2u32 {
        // From the origin to the outer box's far wall at z = -10.
        let length = if row == 0 { 10.0 } else { 30.0 };
        // The part outside the outer box (from z = 20 to z = 10) is in no medium.
        let in_outer = if row == 0 { 10.0 } else { 20.0 };
        for x in 0..8u32 {
            let through_inner = x < 4;
            let d_inner = if through_inner { 2.0 } else { 0.0 };
            let want = (-SA * (in_outer - d_inner) - SB * d_inner).exp();
            let got = px(&img, x, row);
            for (c, g) in got.iter().enumerate() {
                let rel = (f64::from(*g) - want).abs() / want;
                assert!(
                    rel <= 1e-4,
                    "row {row} (path length {length}), column {x}, channel {c}: got {g}, want {want}"
                );
            }
        }
    }
}

/// A probe material reporting `(t, geometric normal x, geometric normal y)`, a sentinel background,
/// a pinhole camera, and a custom geometry that walks its mesh's BVH itself.
fn walker_scene(geometry: &str) -> String {
    format!(
        r#"
import "std/cameras/pinhole.rt";

@background
struct Sentinel {{
    unused: f32 = 0.0,
}}

@miss
fn sentinel(b: Sentinel, ray: Ray) -> vec3f {{
    return vec3f(-1.0);
}}

@material
struct Probe {{
    unused: f32 = 0.0,
}}

@closest_hit
fn probe(m: Probe, ray: Ray, hit: Hit) -> vec3f {{
    return vec3f(hit.t, hit.geometric_normal.x, hit.geometric_normal.y);
}}

/// A mesh traversed by this program: its BVH with `mesh_node`, its triangles with
/// `mesh_triangle`, nearest child first, with a fixed stack.
@geometry
struct Walker {{
    mesh: mesh,
}}

fn walker_enter(ray: Ray, n: BvhNode, tmax: f32) -> f32 {{
    let span = intersect_aabb(ray, n.min, n.max);
    return select(INF, span.x, span.x <= span.y && span.x <= tmax);
}}

@intersection
fn walker_hit(g: Walker, ray: Ray) -> Intersection {{
    var best = Intersection {{}};
    var r = ray;
    var stack: array<u32, 64>;
    var sp = 0u;
    var node = mesh_node(g.mesh, 0u);
    if walker_enter(r, node, r.tmax) == INF {{
        return best;
    }}
    loop {{
        if node.count > 0u {{
            for k in 0u..node.count {{
                let hit = intersect_triangle(r, mesh_triangle(g.mesh, node.first + k));
                if hit.t < best.t {{
                    best = hit;
                    r.tmax = hit.t;
                }}
            }}
        }} else {{
            let tl = walker_enter(r, mesh_node(g.mesh, node.first), r.tmax);
            let tr = walker_enter(r, mesh_node(g.mesh, node.first + 1u), r.tmax);
            if tl < INF && tr < INF && sp < 64u {{
                stack[sp] = select(node.first, node.first + 1u, tl <= tr);
                sp += 1u;
            }}
            if tl < INF || tr < INF {{
                node = mesh_node(g.mesh, select(node.first + 1u, node.first, tl <= tr));
                continue;
            }}
        }}
        if sp == 0u {{
            break;
        }}
        sp -= 1u;
        node = mesh_node(g.mesh, stack[sp]);
    }}
    return best;
}}

@bounds
fn walker_bounds(g: Walker) -> Aabb {{
    return mesh_bounds(g.mesh);
}}

scene walker {{
    settings {{ width: 32, height: 32, samples: 1 }}
    camera Pinhole {{ position: vec3f(0.3, 0.4, 4.0), look_at: vec3f(0.0, 0.0, 0.0), fov: 45.0 }}
    background Sentinel {{}}
    object ball {{ geometry: {geometry}, material: Probe {{}}, transform: rotate_y(20.0) * scale(vec3f(1.2, 1.0, 0.8)) }}
}}
"#
    )
}

#[test]
fn custom_geometry_walking_its_mesh_bvh_sees_what_the_mesh_geometry_sees() {
    let Some(gpu) =
        gpu_or_skip("custom_geometry_walking_its_mesh_bvh_sees_what_the_mesh_geometry_sees")
    else {
        return;
    };
    let builtin = render(&gpu, "walker-builtin", &walker_scene("sphere_mesh(3u)"));
    let custom = render(
        &gpu,
        "walker-custom",
        &walker_scene("Walker { mesh: sphere_mesh(3u) }"),
    );
    let (mut hits, mut normal_mismatches) = (0, 0);
    for y in 0..32 {
        for x in 0..32 {
            let (b, c) = (px(&builtin, x, y), px(&custom, x, y));
            assert_eq!(b[0] < 0.0, c[0] < 0.0, "pixel ({x}, {y}): hit or miss");
            if b[0] < 0.0 {
                continue;
            }
            hits += 1;
            assert!(
                (b[0] - c[0]).abs() <= 1e-5 * b[0],
                "pixel ({x}, {y}): t {} (mesh) vs {} (custom)",
                b[0],
                c[0]
            );
            if (b[1] - c[1]).abs() > 1e-5 || (b[2] - c[2]).abs() > 1e-5 {
                normal_mismatches += 1;
            }
        }
    }
    eprintln!("{hits} hits, {normal_mismatches} normals differ");
    assert!(
        hits > 200,
        "the ball covers a good part of the image ({hits} hits)"
    );
    assert!(
        normal_mismatches * 100 <= hits,
        "{normal_mismatches} of {hits} normals differ"
    );
}
