//! Analytic checks of the standard-library materials and of the path-tracing program set, rendered on
//! whatever adapter exists (lavapipe on CI).
//!
//! The scenes are files of `scenes/materials/`, their varied numbers set by the tests. They use a test camera that shoots parallel rays along -z through the pixel centres
//! (`Ortho`), so every ray meets the slabs below at exactly normal incidence, and a test background
//! (`Split`) that shows one colour to rays going -z (through the slab) and another to rays going +z
//! (reflected back). The expectations, each derived in the test's doc:
//!
//! - glass (`std/materials/glass.rt`, exact dielectric Fresnel, at normal incidence
//!   `R = ((n - 1) / (n + 1))²`): a slab seen through `max_depth = D` generations transmits
//!   `(1 - R)² Σ_{k < ⌊D/2⌋} R^{2k}` and reflects `R + (1 - R)² R Σ_{k < ⌊(D-1)/2⌋} R^{2k}`, which tend
//!   to `(1 - R) / (1 + R)` and `2R / (1 + R)`;
//! - the Fresnel functions of glass on the GPU: `fresnel_dielectric` against the exact formula in
//!   f64 at 64 angles for five relative indices (entering and leaving glass, total internal reflection
//!   included), `fresnel_schlick` against Schlick's;
//! - a glass ball (analytic sphere) against an independent f64 ray tree of the same ball with exact
//!   Fresnel: the mean of the ball's pixels within 0.2 % per channel (Schlick's Fresnel, which glass
//!   used before, is 3.6 % off in red and 37 % in green), and `PathGlass` (`std/path/glass.rt`, one
//!   sampled lobe per hit) on the same ball within 4 standard errors at 256 spp;
//! - mirror: exactly `tint × background`;
//! - fog (`std/materials/fog.rt`, no lights): a slab of density σ and thickness d transmits `e^(-σd)`
//!   of the background, for σ from 1e-3 to 1e4, monotone in σ (no banding), never NaN;
//! - fog around a point light: the in-scattered light matches the single-scattering integral
//!   (Simpson's rule in f64), unbiased and converged to a stated relative error;
//! - unlit texture (texture × tint), emissive (one-sided), translucent (the thesis's weights, counted
//!   generation by generation) and Blinn-Phong (its formula under a point light) exactly;
//! - energy: under a white sky no material returns more than 1;
//! - the path tracer: a diffuse plane under a parallel square `QuadLight` converges to the analytic
//!   `albedo · L · F` (F the form factor from the point to the rectangle) as samples grow, and an
//!   `Emissive` lamp at the light's place does not add to it (no double counting).
//!
//! Every render must be free of NaN and infinities (`nonfinite_samples == 0`). A test skips only when
//! there is no adapter at all, and then says so on stderr.

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::{float, SceneFile};
use common::{gpu_or_skip, temp_dir};

use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::RenderOptions;

/// Compiles `file` (a scene of `scenes/materials/`, which import its test camera and background from
/// `ortho_split.rt`) and renders it at `samples` samples per pixel; asserts that no sample was NaN or
/// infinite.
fn render(gpu: &Gpu, name: &str, file: &SceneFile, samples: u32) -> LinearImage {
    let dir = temp_dir("materials", name);
    let compiled = file.compile(&dir);
    let options = RenderOptions {
        samples: Some(samples),
        ..RenderOptions::default()
    };
    let (image, _) = common::scene::render(gpu, &compiled, options, name);
    image
}

/// A scene file of `scenes/materials/`.
fn scene(name: &str) -> SceneFile {
    SceneFile::open(&format!("materials/{name}.rt"))
}

/// The densities of the fog checks, one per column of the image, as the `SIGMAS` of a scene.
fn sigmas() -> String {
    let list: Vec<String> = SIGMAS.iter().map(|s| float(*s)).collect();
    format!("array<f32, {}>({})", SIGMAS.len(), list.join(", "))
}

fn assert_finite_and_bounded(name: &str, img: &LinearImage, max: f32) {
    for (i, p) in img.pixels().iter().enumerate() {
        for c in &p[..3] {
            assert!(
                c.is_finite() && *c >= 0.0 && *c <= max,
                "{name}: pixel {i} has {c} (allowed [0, {max}])"
            );
        }
    }
}

/// Fresnel reflectance at normal incidence, in f64: `((n - 1) / (n + 1))²`.
fn fresnel_normal(ior: f64) -> f64 {
    let r0 = (1.0 - ior) / (1.0 + ior);
    r0 * r0
}

/// Transmittance and reflectance of a slab seen through `depth` generations of secondary rays.
///
/// The camera ray (depth 0) meets the front face and spawns the reflected ray and the refracted one
/// (depth 1); a ray spawns only while its depth is below `depth`, and one that reaches `depth` on a
/// glass face returns black. A path through the slab with `k` internal round trips leaves from the
/// back face as a ray of depth `2k + 2`, so it is counted when `2k + 2 <= depth`; a path back out of
/// the front face after `k` round trips has depth `2k + 3`. Each refraction weighs `1 - R`, each
/// reflection `R`.
fn slab_series(r: f64, depth: u32) -> (f64, f64) {
    let through = (0..depth / 2).map(|k| r.powi(2 * k as i32)).sum::<f64>();
    let back = (0..(depth.saturating_sub(1) / 2))
        .map(|k| r.powi(2 * k as i32))
        .sum::<f64>();
    let t = (1.0 - r).powi(2) * through;
    let refl = r + (1.0 - r).powi(2) * r * back;
    (t, refl)
}

#[test]
fn a_glass_slab_at_normal_incidence_matches_the_fresnel_series() {
    let Some(gpu) = gpu_or_skip("a_glass_slab_at_normal_incidence_matches_the_fresnel_series")
    else {
        return;
    };
    let ior = 1.5;
    let r = fresnel_normal(ior);
    // Red shows what came through the slab, green what came back from it.
    for depth in [2u32, 5, 16] {
        let file = scene("glass_slab")
            .set("MAX_DEPTH", format!("{depth}u"))
            .set("IOR", float(ior));
        let img = render(&gpu, &format!("glass-d{depth}"), &file, 1);
        let (t, refl) = slab_series(r, depth);
        eprintln!(
            "glass slab, max_depth {depth}: want T = {t:.7}, R = {refl:.7}, T + R = {:.7}",
            t + refl
        );
        // 2e-6 absolute: f32 sums; blue exactly 0.
        let mut check = PixelCheck::new(format!("glass slab, max_depth {depth}: (T, R, 0)"));
        for y in 0..img.height() {
            for x in 0..img.width() {
                let p = img.get(x, y).expect("pixel");
                check.pixel((x, y), p, &[t, refl], Tolerance::abs(2e-6));
                check.channel((x, y), 2, f64::from(p[2]), 0.0, Tolerance::EXACT);
            }
        }
        check.assert();
    }
    // With many generations the series reach the closed forms of the infinite slab.
    let (t, refl) = slab_series(r, 16);
    assert!(
        (t - (1.0 - r) / (1.0 + r)).abs() < 1e-12 && (refl - 2.0 * r / (1.0 + r)).abs() < 1e-12
    );
}

/// Exact unpolarised Fresnel reflectance in f64 for incidence cosine `ci` and relative index `eta`
/// (`n_incident / n_transmitted`): the mean of `((η cos i - cos t) / (η cos i + cos t))²` and
/// `((cos i - η cos t) / (cos i + η cos t))²`; 1 past the critical angle.
fn fresnel_exact(ci: f64, eta: f64) -> f64 {
    let sin2_t = eta * eta * (1.0 - ci * ci);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let ct = (1.0 - sin2_t).sqrt();
    let rs = (eta * ci - ct) / (eta * ci + ct);
    let rp = (ci - eta * ct) / (ci + eta * ct);
    0.5 * (rs * rs + rp * rp)
}

#[test]
fn the_fresnel_functions_of_glass_match_their_formulas_on_the_gpu() {
    let Some(gpu) = gpu_or_skip("the_fresnel_functions_of_glass_match_their_formulas_on_the_gpu")
    else {
        return;
    };
    let img = render(&gpu, "fresnel", &scene("fresnel"), 1);
    // The rows' relative indices as the scene writes them (f32).
    let etas = [0.6666667f32, 1.5, 0.7518797, 2.42, 1.0];
    let mut check = PixelCheck::new("fresnel_dielectric (red) and fresnel_schlick (green)");
    let mut tir = 0;
    for (y, eta) in (0u32..).zip(etas) {
        let eta = f64::from(eta);
        for x in 0..64u32 {
            let c = (f64::from(x) + 0.5) / 64.0;
            let f = fresnel_exact(c, eta);
            let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
            let schlick = r0 + (1.0 - r0) * (1.0 - c).powi(5);
            // Near the critical angle the exact term is steep (a square root of the distance to
            // it): skip the cosines within 0.01 of it, where f32 rounding of `c` moves F visibly.
            let critical = if eta > 1.0 {
                (1.0 - 1.0 / (eta * eta)).sqrt()
            } else {
                -1.0
            };
            if (c - critical).abs() < 0.01 {
                continue;
            }
            if f == 1.0 {
                tir += 1;
            }
            let got = img.get(x, y).expect("pixel");
            // f32 arithmetic: 1e-5 relative, 2e-6 absolute; total internal reflection exactly 1.
            let tol = Tolerance {
                abs: 2e-6,
                rel: 1e-5,
            };
            check.pixel((x, y), got, &[f, schlick, 0.0], tol);
        }
    }
    check.assert();
    // Leaving glass past 41.8° (c < 0.745) and diamond past 24.4° (c < 0.911): 47 + 58 columns.
    assert!(tir > 90, "only {tir} pixels past the critical angle");
}

/// One ray of the test's glass ball in f64: the ball has radius 1 around the origin and index `ior`;
/// `inside` says which side the ray starts on. Mirrors `std/materials/glass.rt` with exact Fresnel
/// and the renderer's depth rule (a ray of depth `depth` hitting the ball spawns rays only while
/// `depth < max_depth`, else it returns black); a ray leaving the ball returns `background(dir)`.
fn ball_ray(
    o: [f64; 3],
    d: [f64; 3],
    depth: u32,
    max_depth: u32,
    inside: bool,
    ior: f64,
) -> [f64; 3] {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let background = |d: [f64; 3]| {
        let ahead = if d[2] < 0.0 { 1.0 } else { 0.0 };
        [ahead, 1.0 - ahead, 0.5 + 0.5 * d[0]]
    };
    let b = dot(o, d);
    let disc = b * b - (dot(o, o) - 1.0);
    let t = if disc >= 0.0 {
        let s = disc.sqrt();
        [-b - s, -b + s].into_iter().find(|t| *t > 1e-9)
    } else {
        None
    };
    let Some(t) = t else {
        return background(d);
    };
    if depth >= max_depth {
        return [0.0; 3];
    }
    let p = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
    let (n, eta) = if inside {
        (p.map(|c| -c), ior)
    } else {
        (p, 1.0 / ior)
    };
    let ci = (-dot(d, n)).min(1.0);
    let refl = [0, 1, 2].map(|i| d[i] + 2.0 * ci * n[i]);
    let k = 1.0 - eta * eta * (1.0 - ci * ci);
    if k < 0.0 {
        return ball_ray(p, refl, depth + 1, max_depth, inside, ior);
    }
    let through = [0, 1, 2].map(|i| eta * d[i] + (eta * ci - k.sqrt()) * n[i]);
    let f = fresnel_exact(ci, eta);
    let a = ball_ray(p, refl, depth + 1, max_depth, inside, ior);
    let b = ball_ray(p, through, depth + 1, max_depth, !inside, ior);
    [0, 1, 2].map(|i| f * a[i] + (1.0 - f) * b[i])
}

/// The mean over the ball's pixels of `img` and of the exact-Fresnel ray tree (`ball_ray`), the
/// number of those pixels, and the largest difference of one channel inside `r² < 0.9`.
fn ball_means(img: &LinearImage, size: u32, max_depth: u32) -> ([f64; 3], [f64; 3], u32, f64) {
    let mut got = [0.0f64; 3];
    let mut want = [0.0f64; 3];
    let mut n = 0;
    let mut worst = 0.0f64;
    for y in 0..size {
        for x in 0..size {
            let ndc = |i: u32| (f64::from(i) + 0.5) / f64::from(size) * 2.0 - 1.0;
            let (px, py) = (ndc(x), -ndc(y));
            if px * px + py * py >= 1.0 {
                continue;
            }
            let w = ball_ray([px, py, 5.0], [0.0, 0.0, -1.0], 0, max_depth, false, 1.5);
            let g = img.get(x, y).expect("pixel");
            for c in 0..3 {
                got[c] += f64::from(g[c]);
                want[c] += w[c];
                if px * px + py * py < 0.9 {
                    worst = worst.max((f64::from(g[c]) - w[c]).abs());
                }
            }
            n += 1;
        }
    }
    (
        got.map(|s| s / f64::from(n)),
        want.map(|s| s / f64::from(n)),
        n,
        worst,
    )
}

#[test]
fn a_glass_ball_converges_to_the_exact_fresnel_reference() {
    let Some(gpu) = gpu_or_skip("a_glass_ball_converges_to_the_exact_fresnel_reference") else {
        return;
    };
    let img = render(&gpu, "glass-ball", &scene("glass_ball"), 1);
    let (got, want, n, worst) = ball_means(&img, 32, 8);
    eprintln!("glass ball, {n} pixels: mean {got:?}, exact-Fresnel reference {want:?}, worst pixel inside r² < 0.9 off by {worst:.2e}");
    assert_eq!(n, 812, "pixels on the ball");
    for c in 0..3 {
        let rel = (got[c] / want[c] - 1.0).abs();
        assert!(
            rel < 0.002,
            "channel {c}: mean {} against the exact-Fresnel reference {} ({:.3} % off; allowed 0.2 %)",
            got[c],
            want[c],
            rel * 100.0
        );
    }
    // Away from the rim each pixel agrees to f32 precision of the ray tree.
    assert!(worst < 1e-3, "a pixel inside r² < 0.9 is off by {worst}");
}

/// `PathGlass` (one lobe sampled per hit) on the same ball at 256 spp converges to the same means:
/// each sample's channel lies in [0, 1], so its standard deviation is at most `√(m (1 - m))` for a
/// mean `m`; the mean of the ball's 812 × 256 samples must lie within 4 such standard errors (about
/// 0.3 % of the red mean, 3 % of the green one; Schlick's Fresnel is 3.6 % and 37 % off).
#[test]
fn path_glass_with_one_sampled_lobe_converges_to_the_same_ball() {
    let Some(gpu) = gpu_or_skip("path_glass_with_one_sampled_lobe_converges_to_the_same_ball")
    else {
        return;
    };
    let spp = 256u32;
    let file = scene("path_glass_ball").set("SPP", format!("{spp}u"));
    let img = render(&gpu, "path-glass-ball", &file, spp);
    let (got, want, n, _) = ball_means(&img, 32, 8);
    eprintln!(
        "path glass ball, {n} pixels at {spp} spp: mean {got:?}, exact-Fresnel reference {want:?}"
    );
    assert_eq!(n, 812, "pixels on the ball");
    let samples = f64::from(n * spp);
    for c in 0..3 {
        let sigma = (want[c] * (1.0 - want[c])).max(0.0).sqrt() / samples.sqrt();
        assert!(
            (got[c] - want[c]).abs() < 4.0 * sigma,
            "channel {c}: mean {} against the exact-Fresnel reference {} (allowed ±{:.2e}, 4 standard errors)",
            got[c],
            want[c],
            4.0 * sigma
        );
    }
}

#[test]
fn a_mirror_reflects_its_tint_times_what_it_sees() {
    let Some(gpu) = gpu_or_skip("a_mirror_reflects_its_tint_times_what_it_sees") else {
        return;
    };
    let img = render(&gpu, "mirror", &scene("mirror"), 1);
    let want = [0.5f32 * 0.3, 0.7 * 0.6, 0.9 * 0.9].map(f64::from);
    // Relative 1e-6: one f32 product.
    let mut check = PixelCheck::new("mirror: tint × background");
    for y in 0..img.height() {
        for x in 0..img.width() {
            let p = img.get(x, y).expect("pixel");
            check.pixel((x, y), p, &want, Tolerance::rel(1e-6));
        }
    }
    check.assert();
}

/// The densities of the fog checks, one per column of the image.
const SIGMAS: [f64; 8] = [1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4];

#[test]
fn a_fog_slab_transmits_exp_minus_sigma_d_for_densities_from_1e_minus_3_to_1e4() {
    let Some(gpu) = gpu_or_skip("a_fog_slab_transmits_exp_minus_sigma_d") else {
        return;
    };
    // Eight slabs of thickness 0.5 side by side (x in [i - 4, i - 3]), each seen by 4 columns.
    let thickness = 0.5;
    let file = scene("fog_slabs")
        .set("SIGMAS", sigmas())
        .set("HALF_THICKNESS", float(thickness / 2.0));
    let img = render(&gpu, "fog-slabs", &file, 2);
    let ahead = [1.0, 0.5, 0.25];
    let mut check = PixelCheck::new("fog slabs: e^(-σd) × background");
    for y in 0..4 {
        let mut previous = f32::INFINITY;
        for x in 0..32u32 {
            let sigma = SIGMAS[(x / 4) as usize];
            let tr = (-sigma * thickness).exp();
            let p = img.get(x, y).expect("pixel");
            // The kernel offsets a spawned ray's origin off the surface at each face by twice a
            // bound of the hit point's rounding error (about 20 ulps of the extent, 4 here, since
            // issue 21; 2^-16 of it before), so the path in the fog is at most 1.3e-4 shorter: a
            // relative error of at most σ · 1.3e-4, allowed on top of 1e-3 (f32 `exp`); for
            // σ >= 100, e^(-σd) is below 2e-22 and the absolute bound decides.
            let tol = Tolerance {
                abs: 1e-7,
                rel: 1e-3 + sigma * 1.3e-4,
            };
            check.pixel((x, y), p, &ahead.map(|a| a * tr), tol);
            // No banding: the transmitted red never grows with σ along a row.
            assert!(p[0] <= previous, "σ = {sigma:e}: {} after {previous}", p[0]);
            previous = p[0];
        }
    }
    check.assert();
}

#[test]
fn fog_that_never_ends_stays_finite_and_lit_fog_stays_bounded() {
    let Some(gpu) = gpu_or_skip("fog_that_never_ends_stays_finite") else {
        return;
    };
    // One-sided fog boundaries (quads facing the camera): a ray that crosses one is inside fog with
    // nothing to leave it by, so the medium program sees t = INF. A point light sits in the fog.
    let file = scene("fog_endless").set("SIGMAS", sigmas());
    let img = render(&gpu, "fog-endless", &file.clone().scene("endless"), 8);
    // With t = INF nothing of the background comes through; what remains is the light scattered
    // from the point light, one sample of `(1 - T) I e^(-σr) / (4π r²)` with `r >= 0.14` on every
    // ray (the rows pass at least that far from the light), so below 1 / (4π · 0.0196) ≈ 4.1.
    assert_finite_and_bounded("fog-endless", &img, 4.1);
    // The same scene without the light (`endless_dark` in the same file).
    let img = render(&gpu, "fog-endless-dark", &file.scene("endless_dark"), 1);
    for p in img.pixels() {
        assert_eq!(
            &p[..3],
            &[0.0, 0.0, 0.0],
            "endless fog without lights hides the background"
        );
    }
}

#[test]
fn nothing_returns_more_than_it_receives_under_a_white_sky() {
    let Some(gpu) = gpu_or_skip("nothing_returns_more_than_it_receives_under_a_white_sky") else {
        return;
    };
    // Columns: glass, a perfect mirror, translucent (weights summing to 1), fog, and two diffuse
    // planes of the path-tracing set in front of everything (albedo 1 and 0.6: under a uniform white
    // sky a convex diffuse surface returns exactly its albedo, the furnace test).
    let img = render(&gpu, "furnace", &scene("furnace"), 16);
    // f32 sums of 16 samples of weights at most 1: 1 + 1e-5.
    assert_finite_and_bounded("furnace", &img, 1.0 + 1e-5);
    for y in 0..4 {
        // Column centres of the diffuse planes: x = 1.5 and 2.5 map to pixels 36..40 and 44..48.
        for (x, albedo) in [(38u32, 1.0f32), (46, 0.6)] {
            let p = img.get(x, y).expect("pixel");
            for c in &p[..3] {
                assert!(
                    (c - albedo).abs() < 1e-5,
                    "diffuse albedo {albedo} under a white sky: {c}"
                );
            }
        }
        // The glass column loses only what the depth limit cuts (R^12 and beyond): close to 1.
        let g = img.get(4, y).expect("pixel")[0];
        assert!(g > 0.99, "glass under a white sky: {g}");
    }
}

/// Form factor from a point to the rectangle `[0, x] × [0, y]` (signed) in a parallel plane at unit
/// height, the corner right above the point.
fn corner_form_factor(x: f64, y: f64) -> f64 {
    let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    (x / sx * (y / sx).atan() + y / sy * (x / sy).atan()) / (2.0 * std::f64::consts::PI)
}

/// Form factor from a point at `(px, py)` on the plane z = 0 (facing +z) to the rectangle
/// `[x0, x1] × [y0, y1]` at height `h` facing it.
fn rect_form_factor(px: f64, py: f64, [x0, x1, y0, y1]: [f64; 4], h: f64) -> f64 {
    let f = |x: f64, y: f64| corner_form_factor((x - px) / h, (y - py) / h);
    f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)
}

/// Mean over pixels of `(got - want)²`, and the mean of `got / want`.
fn errors(img: &LinearImage, want: &[f64]) -> (f64, f64) {
    let n = want.len() as f64;
    let mut se = 0.0;
    let mut ratio = 0.0;
    for (p, w) in img.pixels().iter().zip(want) {
        let g = f64::from(p[0]);
        se += (g - w) * (g - w);
        ratio += g / w;
    }
    ((se / n).sqrt(), ratio / n)
}

#[test]
fn the_path_tracer_converges_to_the_analytic_light_of_a_quad() {
    let Some(gpu) = gpu_or_skip("the_path_tracer_converges_to_the_analytic_light_of_a_quad") else {
        return;
    };
    // A grey diffuse plane z = 0 under a 1 x 1 quad light at z = 0.5 facing it, plus the visible lamp
    // (an `Emissive` quad just behind the light) that the plane's bounce rays hit: counting it would
    // add about the same again. The camera starts between the plane and the lamp.
    let (albedo, radiance, h, size) = (0.5, 2.0, 0.5, 16u32);
    let file = scene("quad_light")
        .set("SIZE", format!("{size}u"))
        .set("ALBEDO", float(albedo))
        .set("RADIANCE", float(radiance))
        .set("LIGHT_Z", float(h));
    // Pixel (x, y) sees the plane at (ndc.x, -ndc.y); its radiance is albedo / π · E with
    // E = π L F, i.e. albedo · L · F.
    let mut want = Vec::new();
    for y in 0..size {
        for x in 0..size {
            let ndc = |i: u32| (f64::from(i) + 0.5) / f64::from(size) * 2.0 - 1.0;
            let f = rect_form_factor(ndc(x), -ndc(y), [-0.5, 0.5, -0.5, 0.5], h);
            want.push(albedo * radiance * f);
        }
    }
    let mut rmse = Vec::new();
    for spp in [4u32, 64] {
        let img = render(&gpu, &format!("quad-light-{spp}"), &file, spp);
        let (e, ratio) = errors(&img, &want);
        eprintln!("quad light at {spp} spp: RMSE {e:.5}, mean got/want {ratio:.5}");
        rmse.push((spp, e, ratio));
    }
    let (_, e4, _) = rmse[0];
    let (_, e64, ratio64) = rmse[1];
    // Unbiased: the mean ratio over 256 pixels at 64 spp is within 2% of 1 (the relative standard
    // deviation of one light sample is about 0.6 here, so the mean's is about 0.6 / √(64·256) = 0.5%).
    assert!(
        (ratio64 - 1.0).abs() < 0.02,
        "mean ratio {ratio64} at 64 spp"
    );
    // Converging: 16 times the samples divides the RMSE by about 4; ask for at least 2.5.
    assert!(e64 * 2.5 < e4, "RMSE {e4} at 4 spp, {e64} at 64 spp");
}

/// The single-scattering integral of a ray through fog past a point light, by Simpson's rule: rays
/// along -z at `(x, y)` cross the fog from z = `half` to z = -`half`; the light of intensity `i` is at
/// the origin, and its light is attenuated inside the fog too (the shadow rays `absorb`).
fn inscatter_past_point_light(x: f64, y: f64, half: f64, sigma: f64, i: f64) -> f64 {
    let n = 20_000;
    let d = 2.0 * half;
    let step = d / f64::from(n);
    let f = |s: f64| {
        let z = half - s;
        let r2 = x * x + y * y + z * z;
        sigma * (-sigma * s).exp() * i * (-sigma * r2.sqrt()).exp()
            / r2
            / (4.0 * std::f64::consts::PI)
    };
    let mut sum = f(0.0) + f(d);
    for k in 1..n {
        let w = if k % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(step * f64::from(k));
    }
    sum * step / 3.0
}

#[test]
fn fog_around_a_point_light_scatters_the_analytic_amount() {
    let Some(gpu) = gpu_or_skip("fog_around_a_point_light_scatters_the_analytic_amount") else {
        return;
    };
    // A fog box 2 deep around a point light, seen against black: every pixel is in-scattered light
    // only. Pixel centres pass at least 1/16 from the light, where the integrand peaks at 256 times
    // its value a unit away: the equiangular half of the sampling keeps this converging.
    let (sigma, intensity, size) = (0.5, 1.0, 16u32);
    let file = scene("fog_glow")
        .set("SIZE", format!("{size}u"))
        .set("SIGMA", float(sigma))
        .set("INTENSITY", float(intensity));
    let img = render(&gpu, "fog-glow", &file, 64);
    let ndc = |i: u32| (f64::from(i) + 0.5) / f64::from(size) * 2.0 - 1.0;
    let mut want = Vec::new();
    for y in 0..size {
        for x in 0..size {
            want.push(inscatter_past_point_light(
                ndc(x),
                -ndc(y),
                1.0,
                sigma,
                intensity,
            ));
        }
    }
    let (rmse, ratio) = errors(&img, &want);
    let rel = (img
        .pixels()
        .iter()
        .zip(&want)
        .map(|(p, w)| (f64::from(p[0]) / w - 1.0).powi(2))
        .sum::<f64>()
        / want.len() as f64)
        .sqrt();
    eprintln!(
        "fog glow at 64 spp: RMSE {rmse:.5}, relative RMS error {rel:.4}, mean got/want {ratio:.5}"
    );
    // Unbiased: the mean ratio over 256 pixels within 2%. Converged: the relative RMS error of a
    // pixel below 5% at 64 spp (measured 3.4% with the MIS of the stdlib fog; free-flight sampling
    // alone gives 6.7%, its RMSE 2.4 times larger).
    assert!((ratio - 1.0).abs() < 0.02, "mean got/want {ratio}");
    assert!(rel < 0.05, "relative RMS error {rel}");
}

/// What a white Lambert square at z = 0 (normal +z) sends back from a light in the unit direction
/// `dir` with `radiance`, through a transmittance `t`: `1/π · radiance · cos θ · t`.
fn lambert_lit(dir: [f64; 3], radiance: f64, t: f64) -> f64 {
    std::f64::consts::FRAC_1_PI * radiance * dir[2].max(0.0) * t
}

#[test]
fn shadow_rays_through_fog_carry_its_transmittance() {
    let Some(gpu) = gpu_or_skip("shadow_rays_through_fog_carry_its_transmittance") else {
        return;
    };
    // `fog_shadow.rt`: a white Lambert square under an ortho camera (8 x 8 pixels over [-1, 1]²),
    // lit through fog of albedo 0 (pure absorption), so each pixel is deterministic:
    // - through: a point light at (10, 0, 1) behind the slab x in [4, 6]; the shadow ray from
    //   (x, y, 0) is inside the slab for 2/(10 - x) of its length L: T = e^(-σ 2L/(10 - x));
    // - sun: a directional light along -(1, 0, 0.25): inside the slab 2 |d| / d.x of its way;
    // - inside: fog around everything, a point light at (0.5, 0.25, 2): the shadow ray starts and
    //   ends in the fog (T = e^(-σ L)) and the camera ray crosses 5 units of it (e^(-5σ)).
    // Before `absorb`, shadow rays went through fog unattenuated (T = 1 here). Densities from thin
    // (1e-4: T within 1e-3 of 1, where `σ t` of entry and exit must cancel) to dense (1e3: exactly 0).
    for sigma in [1e-4, 0.5, 1e3] {
        shadow_rays_through_fog_at(&gpu, sigma);
    }
}

fn shadow_rays_through_fog_at(gpu: &Gpu, sigma: f64) {
    let file = scene("fog_shadow").set("SIGMA", float(sigma));
    let at = |i: u32| (f64::from(i) + 0.5) / 8.0 * 2.0 - 1.0;
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    // f32 lighting and `exp`, the shadow ray 1e-5 short of the light: 1e-4 relative.
    let tol = Tolerance {
        abs: 1e-7,
        rel: 1e-4,
    };
    for name in ["through", "sun", "inside"] {
        let img = render(
            gpu,
            &format!("fog-shadow-{name}"),
            &file.clone().scene(name),
            1,
        );
        let mut check = PixelCheck::new(format!(
            "fog shadow ({name}, σ = {sigma:e}): Lambert lit through fog"
        ));
        for yi in 0..8u32 {
            for xi in 0..8u32 {
                let (x, y) = (at(xi), -at(yi));
                let want = match name {
                    "through" => {
                        let d = [10.0 - x, -y, 1.0];
                        let l = norm(d);
                        let t = (-sigma * 2.0 * l / (10.0 - x)).exp();
                        lambert_lit(d.map(|c| c / l), 100.0 / (l * l), t)
                    }
                    "sun" => {
                        let d = [1.0, 0.0, 0.25];
                        let l = norm(d);
                        let t = (-sigma * 2.0 * l).exp();
                        lambert_lit(d.map(|c| c / l), 1.0, t)
                    }
                    _ => {
                        let d = [0.5 - x, 0.25 - y, 2.0];
                        let l = norm(d);
                        let t = (-sigma * (l + 5.0)).exp();
                        lambert_lit(d.map(|c| c / l), 10.0 / (l * l), t)
                    }
                };
                let p = img.get(xi, yi).expect("pixel");
                check.pixel((xi, yi), p, &[want, want, want], tol);
            }
        }
        check.assert();
    }
}

#[test]
fn the_simple_materials_match_their_formulas() {
    let Some(gpu) = gpu_or_skip("the_simple_materials_match_their_formulas") else {
        return;
    };
    // Five columns, 1.6 wide, centred on x = -4, -2, 0, 2, 4 (4 pixels per unit). Texture values are
    // exact in the half floats `solid_texture` stores. A point light at (4, 0, 1) lights them all;
    // only Blinn-Phong (and the translucent's weight-0 direct term) uses it.
    let img = render(&gpu, "simple", &scene("simple"), 1);
    let pi = std::f64::consts::PI;
    let mut checked = [0usize; 5];
    let mut check = PixelCheck::new("simple materials (columns of 10 pixels from the left)");
    for y in 0..4u32 {
        for x in 0..40u32 {
            let px = (f64::from(x) + 0.5) / 4.0 - 5.0;
            let py = 0.5 - (f64::from(y) + 0.5) / 4.0;
            let column = ((px + 5.0) / 2.0).floor() as usize;
            let centre = column as f64 * 2.0 - 4.0;
            if (px - centre).abs() > 0.7 {
                continue;
            }
            let want: [f64; 3] = match column {
                // Unlit: texture × tint.
                0 => [0.5, 0.5, 0.375],
                // Emissive: colour × intensity toward its front, nothing from behind.
                1 => [0.5, 1.0, 2.0],
                2 => [0.0, 0.0, 0.0],
                // Translucent with max_depth 2: through twice (0.6²) ahead; reflected once (0.3)
                // behind; the ray reflected inside reaches the depth limit (black).
                3 => [0.36, 0.3, 0.0],
                // Blinn-Phong: I/r² (n·l) (kd/π + ks (s + 8)/(8π) (n·h)^s), v = n = +z.
                _ => {
                    let to = [4.0 - px, -py, 1.0];
                    let d2 = to[0] * to[0] + to[1] * to[1] + to[2] * to[2];
                    let l = to.map(|c| c / d2.sqrt());
                    let hv = [l[0], l[1], l[2] + 1.0];
                    let nh = hv[2] / (hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]).sqrt();
                    let v = l[2] / d2 * (0.5 / pi + 0.25 * 24.0 / (8.0 * pi) * nh.powi(16));
                    [v; 3]
                }
            };
            let got = img.get(x, y).expect("pixel");
            // Relative 2e-4 (f32 `pow` and normalisations) or 1e-6 absolute.
            let tol = Tolerance {
                abs: 1e-6,
                rel: 2e-4,
            };
            check.pixel((x, y), got, &want, tol);
            checked[column] += 1;
        }
    }
    check.assert();
    assert!(
        checked.iter().all(|&n| n >= 16),
        "pixels checked per column: {checked:?}"
    );
}
