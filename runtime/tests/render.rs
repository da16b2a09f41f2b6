//! End-to-end renders: a scene written in the language (`scenes/render/*.rt`, its constants set to
//! this file's values), compiled by `compile_scene`, rendered by the runtime on whatever adapter
//! exists (lavapipe on CI), checked against numbers computed by hand.
//!
//! The scene is a quad lit by a point light, seen straight from above through a 90° pinhole with
//! one sample per pixel (so the ray goes through the pixel centre, no jitter). For a pixel whose
//! ray hits the quad at `p`, the Lambert value is `albedo / π · I / |L − p|² · cos θ` with
//! `cos θ = (L − p)·n / |L − p|`. It must match within a relative 1e-4 (f32 arithmetic on the GPU:
//! the hit point from barycentrics, a normalised light direction, `INV_PI` as an f32). A pixel whose
//! ray misses sees the background colour, exactly.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::{float, vec3f, SceneFile};
use common::{gpu_or_skip, temp_dir};

use rtc_runtime::gpu::TileConfig;
use rtc_runtime::render::{RenderOptions, Renderer};

const SIZE: u32 = 33;
const ALBEDO: [f64; 3] = [0.5, 0.25, 1.0];
const BACKGROUND: [f32; 3] = [0.25, 0.5, 0.75];
const LIGHT_Y: f64 = 2.0;
const INTENSITY: f64 = 4.0;
const CAMERA_Y: f64 = 3.0;

/// `scenes/render/lit_quad.rt` with this file's constants.
fn lit_quad() -> SceneFile {
    with_constants(SceneFile::open("render/lit_quad.rt"))
}

/// Sets the constants both scenes share to this file's values, so the analytic expectations and
/// the scenes cannot drift apart.
fn with_constants(file: SceneFile) -> SceneFile {
    file.set("SIZE", format!("{SIZE}u"))
        .set("CAMERA_Y", float(CAMERA_Y))
        .set("LIGHT_Y", float(LIGHT_Y))
        .set("INTENSITY", float(INTENSITY))
        .set("ALBEDO", vec3f(ALBEDO))
        .set("BACKGROUND", vec3f(BACKGROUND.map(f64::from)))
}

/// Where the centre ray of pixel `(x, y)` meets the plane y = 0, by the pinhole's formula: with
/// this camera `dir = (ndc.x, -1, ndc.y)`.
fn ground_point(x: u32, y: u32) -> (f64, f64) {
    let ndc = |i: u32| (f64::from(i) + 0.5) / f64::from(SIZE) * 2.0 - 1.0;
    (CAMERA_Y * ndc(x), CAMERA_Y * ndc(y))
}

/// The analytic Lambert value at ground point `(px, pz)` (normal +y).
fn lambert(px: f64, pz: f64) -> [f64; 3] {
    let dist2 = px * px + LIGHT_Y * LIGHT_Y + pz * pz;
    let cos = LIGHT_Y / dist2.sqrt();
    let e = INTENSITY / dist2 * cos / std::f64::consts::PI;
    ALBEDO.map(|a| a * e)
}

#[test]
fn a_lit_quad_matches_the_analytic_lambert_value() {
    let Some(gpu) = gpu_or_skip("a_lit_quad_matches_the_analytic_lambert_value") else {
        return;
    };
    let dir = temp_dir("render", "lit-quad");
    let compiled = lit_quad().compile(&dir);
    let mut renderer = Renderer::new(
        &gpu,
        &compiled,
        RenderOptions {
            tiles: Some(TileConfig {
                tile_width: 16,
                tile_height: 16,
                tiles_per_batch: 4,
            }),
            ..RenderOptions::default()
        },
    )
    .expect("renderer");
    let result = renderer.render(&mut |_, _| {}).expect("render");
    let s = &result.stats;
    eprintln!(
        "lit quad {}x{}: BVH build {:.3} ms, upload {:.3} ms, render {:.3} ms, pipelines {:.1} ms, \
         {:.3} M primary rays/s",
        s.width,
        s.height,
        s.bvh_build_ms,
        s.upload_ms,
        s.render_ms,
        s.pipeline_ms,
        s.rays_per_second / 1e6
    );
    assert_eq!(s.nonfinite_samples, 0);
    assert_eq!((s.objects, s.instances, s.triangles), (1, 1, 2));
    assert_eq!((s.samples, s.passes, s.tiles), (1, 1, 9));

    let img = &result.image;
    let mut checked_hits = 0;
    let mut checked_misses = 0;
    let mut check = PixelCheck::new("lit quad: Lambert (relative 1e-4) and background (exact)");
    for y in 0..SIZE {
        for x in 0..SIZE {
            let (px, pz) = ground_point(x, y);
            let got = img.get(x, y).expect("pixel");
            // Keep clear of the quad's edge, where a pixel centre could fall either way.
            let inside = px.abs().max(pz.abs());
            if inside < 0.95 {
                check.pixel((x, y), got, &lambert(px, pz), Tolerance::rel(1e-4));
                checked_hits += 1;
            } else if inside > 1.05 {
                check.pixel((x, y), got, &BACKGROUND.map(f64::from), Tolerance::EXACT);
                checked_misses += 1;
            }
        }
    }
    check.assert();
    // The centre pixel looks straight down at the point under the light: albedo / π · I / 4.
    let centre = img.get(SIZE / 2, SIZE / 2).expect("centre");
    let want = ALBEDO.map(|a| a / std::f64::consts::PI);
    eprintln!("centre pixel {centre:?}, analytic {want:?}");
    assert!(
        checked_hits > 50 && checked_misses > 500,
        "{checked_hits} hits, {checked_misses} misses"
    );
    // A second render of the same scene uploads nothing and gives the same image.
    let again = renderer.render(&mut |_, _| {}).expect("second render");
    eprintln!(
        "second render: {:.3} ms, {:.3} M primary rays/s, buffers written: {:?}",
        again.stats.render_ms,
        again.stats.rays_per_second / 1e6,
        again.stats.buffers_written
    );
    assert_eq!(again.image, result.image);
    assert!(again.stats.buffers_written.is_empty());
}

/// The render kernel spreads each tile's workgroups over the tile by a permutation of their order
/// (`render_invocation`); whatever the tile shape (partial edge workgroups, one workgroup, a prime
/// number of them, tiles narrower than a workgroup), every pixel is rendered exactly once, so the
/// image is the same bit for bit.
#[test]
fn every_tile_shape_renders_every_pixel_once() {
    let Some(gpu) = gpu_or_skip("every_tile_shape_renders_every_pixel_once") else {
        return;
    };
    let dir = temp_dir("render", "tile-shapes");
    let compiled = lit_quad().compile(&dir);
    let render = |tile_width, tile_height, tiles_per_batch| {
        let tiles = TileConfig {
            tile_width,
            tile_height,
            tiles_per_batch,
        };
        let mut renderer = Renderer::new(
            &gpu,
            &compiled,
            RenderOptions {
                tiles: Some(tiles),
                ..RenderOptions::default()
            },
        )
        .expect("renderer");
        renderer.render(&mut |_, _| {}).expect("render").image
    };
    // 33 x 33 pixels in one tile: 5 x 5 = 25 workgroups, the last row and column partial.
    let reference = render(33, 33, 1);
    for px in reference.pixels() {
        assert_eq!(px[3], 1.0, "every pixel has exactly one sample");
    }
    // Tiles are clipped at the image's edge. 16 x 16: 2 x 2 workgroups, and 1-pixel-wide edge
    // tiles; 16 x 8: 2 x 1; 24 x 40: 3 x 5 = 15 workgroups; 8 x 40: 5 (a prime); 5 x 3 and
    // 8 x 8: tiles of one workgroup or less.
    for (w, h, batch) in [
        (16, 16, 4),
        (16, 8, 4),
        (24, 40, 2),
        (8, 40, 3),
        (5, 3, 64),
        (8, 8, 9),
    ] {
        let image = render(w, h, batch);
        assert!(
            image == reference,
            "{w} x {h} tiles give a different image from one 33 x 33 tile"
        );
    }
}

/// A custom geometry (an analytic ball written in the scene file) goes through the compiler's bounds
/// kernel: if its box were lost or wrong, the ball would be missing from the scene-level BVH and
/// the pixels would show the background.
fn lit_ball() -> SceneFile {
    with_constants(SceneFile::open("render/lit_ball.rt"))
}

#[test]
fn a_custom_geometry_goes_through_the_bounds_kernel() {
    let Some(gpu) = gpu_or_skip("a_custom_geometry_goes_through_the_bounds_kernel") else {
        return;
    };
    let dir = temp_dir("render", "lit-ball");
    let compiled = lit_ball().compile(&dir);
    assert!(
        compiled.bounds.is_some(),
        "a bounds kernel for custom geometry"
    );
    let mut renderer = Renderer::new(&gpu, &compiled, RenderOptions::default()).expect("renderer");
    // The box the bounds kernel computed (radius 0.25 scaled by 2 around y = 0.5), in world space,
    // is the scene-level BVH's root.
    let e = renderer.entities();
    let root = e.tlas_bounds();
    assert_eq!(
        (root.min.to_array(), root.max.to_array()),
        ([-0.5, 0.0, -0.5], [0.5, 1.0, 0.5])
    );
    let result = renderer.render(&mut |_, _| {}).expect("render");
    let s = &result.stats;
    eprintln!(
        "lit ball: bounds kernel {:.3} ms, BVH build {:.3} ms, upload {:.3} ms, render {:.3} ms",
        s.bounds_ms, s.bvh_build_ms, s.upload_ms, s.render_ms
    );
    assert_eq!(s.nonfinite_samples, 0);
    assert_eq!(s.instances, 1);

    // World-space ball: centre (0, 0.5, 0), radius 0.5.
    let (cy, r) = (0.5f64, 0.5f64);
    let mut hits = 0;
    let mut misses_in_box = 0usize;
    let mut check = PixelCheck::new("lit ball: Lambert (relative 1e-4) and background (exact)");
    for y in 0..SIZE {
        for x in 0..SIZE {
            let (gx, gz) = ground_point(x, y);
            // Ray (0, CAMERA_Y, 0) + s (gx, -CAMERA_Y, gz) / CAMERA_Y.
            let d = [gx / CAMERA_Y, -1.0, gz / CAMERA_Y];
            let o = [0.0, CAMERA_Y - cy, 0.0];
            let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let h = o[1] * d[1];
            let c = o[1] * o[1] - r * r;
            let disc = h * h - a * c;
            let got = img_px(&result.image, x, y);
            if disc < -1e-3 {
                // A ray that misses the ball sees the background, inside its box or not (an
                // `@intersection` miss, `t = INF`, never counts as a hit).
                check.pixel((x, y), got, &BACKGROUND.map(f64::from), Tolerance::EXACT);
                misses_in_box += usize::from(in_box(x, y));
                continue;
            }
            if disc < 1e-3 {
                continue; // the silhouette: either way
            }
            let s = (-h - disc.sqrt()) / a;
            let p = [d[0] * s, CAMERA_Y + d[1] * s, d[2] * s];
            let n = [p[0] / r, (p[1] - cy) / r, p[2] / r];
            let l = [-p[0], LIGHT_Y - p[1], -p[2]];
            let dist2 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
            let cos = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / dist2.sqrt();
            if cos < 0.05 {
                continue; // near the terminator, shadow-ray offsets decide
            }
            let e = INTENSITY / dist2 * cos / std::f64::consts::PI;
            check.pixel((x, y), got, &ALBEDO.map(|a| a * e), Tolerance::rel(1e-4));
            hits += 1;
        }
    }
    check.assert();
    assert!(hits > 25, "{hits} pixels on the ball checked");
    assert!(
        misses_in_box > 10,
        "{misses_in_box} pixels in the ball's box but off the ball checked"
    );
}

/// Whether the centre ray of pixel `(x, y)` enters the ball's world box `[-0.5, 0.5] × [0, 1] ×
/// [-0.5, 0.5]`. Going down, the ray moves away from the axis, so it enters exactly when it
/// crosses the top face (y = 1) inside the square; there it is at `ground · (CAMERA_Y - 1) /
/// CAMERA_Y`.
fn in_box(x: u32, y: u32) -> bool {
    let (gx, gz) = ground_point(x, y);
    gx.abs().max(gz.abs()) * (CAMERA_Y - 1.0) / CAMERA_Y <= 0.5 + 1e-3
}

fn img_px(img: &rtc_runtime::image_out::LinearImage, x: u32, y: u32) -> [f32; 4] {
    img.get(x, y).expect("pixel")
}
