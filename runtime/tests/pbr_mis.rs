//! The glTF metallic-roughness BRDF of the standard library (`std/materials/pbr.rt`), its path-traced
//! material (`std/path/pbr.rt`) and the path set's multiple importance sampling (`std/path/lamp.rt`,
//! `std/path/bounce.rt`), checked against values computed here in f64, on whatever adapter exists
//! (lavapipe on CI):
//!
//! - `pbr_eval` and `pbr_pdf` on the GPU against the glTF spec's formulas (appendix B) at 64 light
//!   angles for four (metallic, roughness) pairs, 2e-4 relative;
//! - white furnace: `PathPbr` planes under a white sky return their directional albedo (the BRDF
//!   integrated here by quadrature), within four standard errors of the pixel means, and never more
//!   than 1: unbiased importance sampling with `pbr_sample` / `pbr_pdf` and no energy gain; and a
//!   `PathPbr` sphere, whose pixels see every view angle from normal incidence to grazing, returns
//!   the albedo at each pixel's angle (rings of view angle, four standard errors);
//! - MIS: a glossy plane under a small bright quad light, and under a sphere light, each rendered with
//!   the light's lamp (MIS, power heuristic) and with the light sampled alone, at equal samples: both
//!   converge to the same image (means within 2 %), and the MIS RMSE against an independent
//!   2048-spp reference is at least 1.5 times lower.
//!
//! Every render must be free of NaN and infinities (`nonfinite_samples == 0`, asserted by
//! `common::scene::render`). A test skips only when there is no adapter at all, and says so.

mod common;

use common::image::{PixelCheck, Tolerance};
use common::scene::{float, SceneFile};
use common::{gpu_or_skip, temp_dir};

use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::RenderOptions;

use std::f64::consts::PI;

/// Compiles `file` (a scene of `scenes/materials/`) and renders it at `samples` samples per pixel.
fn render(gpu: &Gpu, name: &str, file: &SceneFile, samples: u32) -> LinearImage {
    let dir = temp_dir("pbr_mis", name);
    let compiled = file.compile(&dir);
    let options = RenderOptions {
        samples: Some(samples),
        ..RenderOptions::default()
    };
    let (image, _) = common::scene::render(gpu, &compiled, options, name);
    image
}

type V3 = [f64; 3];

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    a.map(|c| c / l)
}

/// `α²` as the stdlib clamps it (`α ≥ 1e-3`).
fn alpha2(roughness: f64) -> f64 {
    let a = (roughness * roughness).max(1e-3);
    a * a
}

/// `f (n·l)` of the glTF BRDF (spec appendix B) for one channel of base colour `base`, `n = +z`.
fn brdf_cos(base: f64, metallic: f64, roughness: f64, v: V3, l: V3) -> f64 {
    let (ndv, ndl) = (v[2], l[2]);
    if ndv <= 0.0 || ndl <= 0.0 {
        return 0.0;
    }
    let a2 = alpha2(roughness);
    let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
    let ndh = h[2];
    let f0 = 0.04 + (base - 0.04) * metallic;
    let f = f0 + (1.0 - f0) * (1.0 - dot(v, h)).powi(5);
    let d = a2 / (PI * (ndh * ndh * (a2 - 1.0) + 1.0).powi(2));
    let vis = 0.5
        / (ndl * (ndv * ndv * (1.0 - a2) + a2).sqrt() + ndv * (ndl * ndl * (1.0 - a2) + a2).sqrt());
    let diffuse = (1.0 - f) * base * (1.0 - metallic) / PI;
    (diffuse + f * d * vis) * ndl
}

/// Rec. 709 luminance (the stdlib's `luminance`).
fn luminance(c: V3) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

/// The density of `pbr_sample`: the specular chance times the GGX visible-normal density, plus the
/// rest times the cosine density.
fn pdf(base: V3, metallic: f64, roughness: f64, v: V3, l: V3) -> f64 {
    let (ndv, ndl) = (v[2], l[2]);
    if ndv <= 0.0 || ndl <= 0.0 {
        return 0.0;
    }
    let k = (1.0 - ndv).powi(5);
    let f = base.map(|b| {
        let f0 = 0.04 + (b - 0.04) * metallic;
        f0 + (1.0 - f0) * k
    });
    let ws = luminance(f);
    let wd = luminance([0, 1, 2].map(|i| base[i] * (1.0 - metallic) * (1.0 - f[i])));
    let ps = if wd <= 0.0 {
        1.0
    } else if ws <= 0.0 {
        0.0
    } else {
        (ws / (ws + wd)).clamp(0.1, 0.9)
    };
    let a2 = alpha2(roughness);
    let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
    let d = a2 / (PI * (h[2] * h[2] * (a2 - 1.0) + 1.0).powi(2));
    let spec = d * 0.5 / (ndv + (a2 + (1.0 - a2) * ndv * ndv).sqrt());
    ps * spec + (1.0 - ps) * ndl / PI
}

#[test]
fn pbr_eval_and_pdf_match_the_gltf_formulas_on_the_gpu() {
    let Some(gpu) = gpu_or_skip("pbr_eval_and_pdf_match_the_gltf_formulas_on_the_gpu") else {
        return;
    };
    let img = render(
        &gpu,
        "pbr-probe",
        &SceneFile::open("materials/pbr_probe.rt"),
        1,
    );
    let rows = [(0.0, 0.5), (1.0, 0.3), (0.5, 0.8), (0.0, 0.1)];
    let base = [0.9, 0.5, 0.2];
    let tv = 0.698_131_7f64;
    let v = [tv.sin(), 0.0, tv.cos()];
    let mut check = PixelCheck::new("pbr_eval (red, blue channel in green) and pbr_pdf (blue)");
    let mut peak = 0.0f64;
    for (y, (metallic, roughness)) in (0u32..).zip(rows) {
        for x in 0..64u32 {
            // The column's angle as the GPU computes it from the pixel centre (f32).
            let c = f64::from((x as f32 + 0.5) / 64.0);
            let theta = 1.5 * c;
            let az = f64::from(std::f32::consts::PI);
            let l = [theta.sin() * az.cos(), theta.sin() * az.sin(), theta.cos()];
            let want = [
                brdf_cos(base[0], metallic, roughness, v, l),
                brdf_cos(base[2], metallic, roughness, v, l),
                pdf(base, metallic, roughness, v, l),
            ];
            peak = peak.max(want[2]);
            // f32 arithmetic (powers, square roots, a normalised half vector): 2e-4 relative,
            // 1e-6 absolute; the sharp lobe (α = 0.01) turns the f32 rounding of n·h (6e-8) into
            // up to 4 · 6e-8 / α² = 2.4e-3 of D near its peak: 3e-3 there.
            let tol = Tolerance {
                abs: 1e-6,
                rel: if roughness < 0.2 { 3e-3 } else { 2e-4 },
            };
            check.pixel((x, y), img.get(x, y).expect("pixel"), &want, tol);
        }
    }
    check.assert();
    // The glossy row reaches the specular peak (the reflection of v is at θ = 0.70, azimuth π).
    assert!(peak > 1.0, "the sharpest row's pdf peaks at only {peak}");
}

/// The directional albedo `∫ f (n·l) dl` at normal incidence (`v = n`), one channel, by the midpoint
/// rule in `θ` with 400 000 steps (the sharpest lobe here, α = 0.04, spans thousands of them).
fn albedo_normal(base: f64, metallic: f64, roughness: f64) -> f64 {
    let steps = 400_000;
    let dt = 0.5 * PI / f64::from(steps);
    let mut sum = 0.0;
    for i in 0..steps {
        let t = (f64::from(i) + 0.5) * dt;
        let l = [t.sin(), 0.0, t.cos()];
        sum += brdf_cos(base, metallic, roughness, [0.0, 0.0, 1.0], l) * t.sin();
    }
    2.0 * PI * sum * dt
}

#[test]
fn path_pbr_returns_its_directional_albedo_under_a_white_sky() {
    let Some(gpu) = gpu_or_skip("path_pbr_returns_its_directional_albedo_under_a_white_sky") else {
        return;
    };
    // (base, metallic, roughness) per column, as the scene's `MATERIALS`.
    let materials = [
        (1.0, 0.0, 1.0),
        (1.0, 0.0, 0.5),
        (1.0, 0.0, 0.2),
        (1.0, 1.0, 1.0),
        (1.0, 1.0, 0.5),
        (0.5, 1.0, 0.3),
    ];
    let list: Vec<String> = materials
        .iter()
        .map(|(b, m, r)| format!("vec3f({}, {}, {})", float(*b), float(*m), float(*r)))
        .collect();
    let file = SceneFile::open("materials/pbr_furnace.rt")
        .set("MATERIALS", format!("array<vec3f, 6>({})", list.join(", ")));
    let img = render(&gpu, "pbr-furnace", &file, 256);
    for p in img.pixels() {
        for c in &p[..3] {
            // One sample's weight `f cos / pdf` may pass 1 (the mixture density is not exactly
            // proportional to `f cos`); the mean of a pixel's 256 stays near the albedo.
            assert!(
                c.is_finite() && *c >= 0.0 && *c <= 1.1,
                "a furnace pixel has {c}"
            );
        }
    }
    for (col, (base, metallic, roughness)) in materials.into_iter().enumerate() {
        let want = albedo_normal(base, metallic, roughness);
        // The column's pixels: x in 8 col + 1 .. 8 col + 7 (the plane is 0.9 of its 1-unit column).
        let mut values = Vec::new();
        for y in 0..4u32 {
            for x in 8 * col as u32 + 1..8 * col as u32 + 7 {
                values.push(f64::from(img.get(x, y).expect("pixel")[0]));
            }
        }
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let var = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0);
        let se = (var / n).sqrt();
        eprintln!(
            "furnace base {base} metallic {metallic} roughness {roughness}: got {mean:.5} ± {se:.5}, \
             directional albedo {want:.5}"
        );
        assert!(want <= 1.0, "the BRDF itself gains energy: {want}");
        assert!(
            mean <= 1.0 + 4.0 * se,
            "column {col} returns {mean} ± {se} > 1"
        );
        // Four standard errors of the mean of the column's pixel means, plus 2e-3 for f32 sums.
        assert!(
            (mean - want).abs() <= 4.0 * se + 2e-3,
            "column {col}: mean {mean} ± {se}, want {want}"
        );
    }
    // A rough white dielectric: about 1 minus the light its single-scattering specular lobe loses.
    let white = albedo_normal(1.0, 0.0, 1.0);
    assert!(
        white > 0.9 && white <= 1.0,
        "rough white dielectric: {white}"
    );
}

/// The directional albedo at view angle `acos(cos_v)`: `∫ f (n·l) dl` over the hemisphere by the
/// midpoint rule, 1200 steps in `θ` and 600 in `φ` (over `0..π`, doubled: the lobe is symmetric
/// about the plane of `v` and `n`).
fn albedo_at(base: f64, metallic: f64, roughness: f64, cos_v: f64) -> f64 {
    let v = [(1.0 - cos_v * cos_v).max(0.0).sqrt(), 0.0, cos_v];
    let (nt, np) = (1200, 600);
    let (dt, dp) = (0.5 * PI / f64::from(nt), PI / f64::from(np));
    let mut sum = 0.0;
    for i in 0..nt {
        let t = (f64::from(i) + 0.5) * dt;
        let (st, ct) = t.sin_cos();
        for j in 0..np {
            let p = (f64::from(j) + 0.5) * dp;
            let l = [st * p.cos(), st * p.sin(), ct];
            sum += brdf_cos(base, metallic, roughness, v, l) * st;
        }
    }
    2.0 * sum * dt * dp
}

#[test]
fn path_pbr_on_a_sphere_returns_its_albedo_at_every_view_angle_under_a_white_sky() {
    let Some(gpu) = gpu_or_skip(
        "path_pbr_on_a_sphere_returns_its_albedo_at_every_view_angle_under_a_white_sky",
    ) else {
        return;
    };
    // A rough metal and a rough white dielectric: smooth lobes, so the quadrature above is exact
    // to well below the tolerance, and the grazing rim (where single-scattering GGX loses the
    // most energy) is covered.
    for (base, metallic, roughness) in [(1.0, 1.0, 0.5), (1.0, 0.0, 1.0)] {
        let file = SceneFile::open("materials/pbr_furnace_sphere.rt").set(
            "MATERIAL",
            format!(
                "vec3f({}, {}, {})",
                float(base),
                float(metallic),
                float(roughness)
            ),
        );
        let img = render(&gpu, "pbr-furnace-sphere", &file, 256);
        // The albedo at 41 view cosines, interpolated linearly between them.
        let table: Vec<f64> = (0..=40)
            .map(|k| albedo_at(base, metallic, roughness, (f64::from(k) / 40.0).max(1e-3)))
            .collect();
        let want_at = |c: f64| {
            let x = c.clamp(0.0, 1.0) * 40.0;
            let k = (x.floor() as usize).min(39);
            let f = x - k as f64;
            table[k] * (1.0 - f) + table[k + 1] * f
        };
        // Four rings of view angle, from the centre to r = 0.97 (cos_v 0.24).
        let mut rings = vec![(Vec::new(), 0.0f64); 4];
        for y in 0..32u32 {
            for x in 0..32u32 {
                let px = (f64::from(x) + 0.5) / 16.0 - 1.0;
                let py = (f64::from(y) + 0.5) / 16.0 - 1.0;
                let r = (px * px + py * py).sqrt();
                let value = f64::from(img.get(x, y).expect("pixel")[0]);
                assert!(
                    value.is_finite() && (0.0..=1.1).contains(&value),
                    "{base} {metallic} {roughness}: pixel ({x}, {y}) has {value}"
                );
                if r >= 0.97 {
                    continue;
                }
                let ring = ((r / 0.97) * 4.0).floor() as usize;
                let cos_v = (1.0 - r * r).sqrt();
                rings[ring].0.push(value);
                rings[ring].1 += want_at(cos_v);
            }
        }
        for (i, (values, want_sum)) in rings.iter().enumerate() {
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let want = want_sum / n;
            let var = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0);
            let se = (var / n).sqrt();
            eprintln!(
                "sphere furnace {base} {metallic} {roughness}, ring {i}: got {mean:.5} ± {se:.5}, \
                 albedo {want:.5}"
            );
            assert!(want <= 1.0, "the BRDF itself gains energy: {want}");
            // The pixels' spread includes the albedo's change across the ring, so `se` is a
            // generous bound; 3e-3 covers f32 sums and the table's interpolation.
            assert!(
                (mean - want).abs() <= 4.0 * se + 3e-3,
                "{base} {metallic} {roughness}, ring {i}: mean {mean} ± {se}, want {want}"
            );
        }
    }
}

/// Root mean square of `a - b` in the red channel over all pixels, and the mean of each.
fn rmse(a: &LinearImage, b: &[f64]) -> (f64, f64, f64) {
    let n = b.len() as f64;
    let (mut se, mut ma, mut mb) = (0.0, 0.0, 0.0);
    for (p, w) in a.pixels().iter().zip(b) {
        let g = f64::from(p[0]);
        se += (g - w) * (g - w);
        ma += g;
        mb += w;
    }
    ((se / n).sqrt(), ma / n, mb / n)
}

/// Renders the MIS scene and the single-strategy scene named (of `mis_lamp.rt`) at `spp` and a
/// 2048-spp reference of each with seeds of their own; prints and returns (MIS RMSE, single-strategy
/// RMSE) against the MIS reference, after checking that both converge to the same mean.
fn mis_against_light_only(gpu: &Gpu, mis_scene: &str, light_scene: &str, spp: u32) -> (f64, f64) {
    let file = SceneFile::open("materials/mis_lamp.rt");
    let run = |scene: &str, seed: &str, spp: u32| {
        let f = file.clone().set("SEED", seed).scene(scene);
        render(gpu, &format!("{scene}-{seed}-{spp}"), &f, spp)
    };
    // The references, with seeds of their own (independent of the renders they judge).
    let reference: Vec<f64> = run(mis_scene, "101u", 2048)
        .pixels()
        .iter()
        .map(|p| f64::from(p[0]))
        .collect();
    let light_ref = run(light_scene, "202u", 2048);
    let mis = run(mis_scene, "7u", spp);
    let light = run(light_scene, "7u", spp);
    let (e_mis, m_mis, m_ref) = rmse(&mis, &reference);
    let (e_light, m_light, _) = rmse(&light, &reference);
    let (_, m_light_ref, _) = rmse(&light_ref, &reference);
    eprintln!(
        "{mis_scene} vs {light_scene} at {spp} spp: RMSE {e_mis:.5} vs {e_light:.5} (ratio {:.2}); \
         means: reference {m_ref:.5}, MIS {m_mis:.5}, {light_scene} {m_light:.5}, {light_scene} at \
         2048 spp {m_light_ref:.5}",
        e_light / e_mis
    );
    // Unbiased, both ways: the light-only image converges to the MIS reference's mean within 2 %
    // (light-only at 2048 spp keeps about 1 % noise in the mean of its highlight), and MIS at `spp`
    // is within 2 % of it too.
    assert!(
        (m_light_ref / m_ref - 1.0).abs() < 0.02,
        "{light_scene}: mean {m_light_ref} against the MIS reference {m_ref}"
    );
    assert!(
        (m_mis / m_ref - 1.0).abs() < 0.02,
        "{mis_scene}: mean {m_mis} at {spp} spp against the reference {m_ref}"
    );
    (e_mis, e_light)
}

#[test]
fn mis_beats_light_sampling_alone_on_a_glossy_plane_under_a_small_bright_light() {
    let Some(gpu) =
        gpu_or_skip("mis_beats_light_sampling_alone_on_a_glossy_plane_under_a_small_bright_light")
    else {
        return;
    };
    // MIS is clearly better where the glossy lobe (α = 0.0225) is narrower than the light: at
    // least 1.5 times lower RMSE at 16 spp (measured: 5.1 for the quad, 2.2 for the sphere).
    for (mis, light) in [("mis", "light_only"), ("sphere_mis", "sphere_light_only")] {
        let (e_mis, e_light) = mis_against_light_only(&gpu, mis, light, 16);
        assert!(
            e_mis * 1.5 < e_light,
            "{mis}: RMSE at 16 spp: MIS {e_mis}, light only {e_light}"
        );
    }
    // And against the BSDF's sampling alone (the lamp is emissive geometry that no light samples).
    let (e_mis, e_bsdf) = mis_against_light_only(&gpu, "mis", "bsdf_only", 16);
    assert!(
        e_mis < e_bsdf,
        "RMSE at 16 spp: MIS {e_mis}, BSDF sampling only {e_bsdf}"
    );
}
