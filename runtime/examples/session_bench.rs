//! The live session's costs against rebuilding, measured in one run (issue 17's benchmarks):
//!
//! 1. **camera move**: a 1-spp frame after moving the camera through one long-lived renderer
//!    (`set_field` + `accumulate(1)` + `image`) against what `rtc view` did before, a fresh
//!    `Renderer::new` + `render` at 1 spp of the scene with the same camera written into its
//!    description (assets read, every BVH built, every buffer uploaded; the pipelines come from
//!    the process's kernel cache either way); `RTC_BENCH_DETAIL=1` prints each run's parts; and
//!    what `rtc view` shows during a drag, a camera move and a preview (`Renderer::preview` at the
//!    reduction `preview_factor` picks for the whole pass measured; 1 means none) read back;
//! 2. **moving objects**: a 1-spp frame after `set_transform` on every object against a static
//!    1-spp frame (nothing changed), both through the session;
//! 3. **scene level**: `N` instances (default 10,000) of one mesh in a generated scene, all moved,
//!    then the scene-level rebuild (TLAS build and instance records) and its upload, without a
//!    render.
//!
//! `cargo run --release -p rtc-runtime --example session_bench -- [SCENE.rt | --mesh FILE.obj]
//! [--size WxH] [--runs N] [--instances N]` (default: `examples/thesis_scene/scene.rt` at 960x540,
//! 7 runs, alternating the two sides of each ratio; medians reported; `--mesh` renders one OBJ
//! mesh on a floor instead, e.g. `../shared/models/stanford-dragon.obj`, where rebuilding means
//! parsing the file and building its BVH again). Prints a table and a JSON line.

use std::path::{Path, PathBuf};
use std::time::Instant;

use glam::{Mat4, Vec3};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene, CompiledScene};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::sema::hir::{ConstValue, Scalar};
use rtc_runtime::gpu::{AdapterChoice, Gpu};
use rtc_runtime::render::{preview_factor, FieldTarget, RenderOptions, Renderer};

fn compile(path: &Path) -> Result<CompiledScene, String> {
    compile_scene(
        &[path.to_path_buf()],
        None,
        &Options::default(),
        &LinkOptions::default(),
    )
    .map_err(|f| rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false))
}

fn vec3(v: Vec3) -> ConstValue {
    ConstValue::Vector {
        len: 3,
        comps: [
            Scalar::F32(v.x),
            Scalar::F32(v.y),
            Scalar::F32(v.z),
            Scalar::F32(0.0),
        ],
    }
}

/// Writes `position` into the compiled scene's camera (what a fresh renderer reads).
fn set_camera_position(compiled: &mut CompiledScene, position: Vec3) -> Result<(), String> {
    let scene = compiled.scene;
    let program = compiled.checked.program.as_mut().ok_or("no program")?;
    let camera = program.scenes[scene]
        .camera
        .as_ref()
        .ok_or("the scene has no camera entry")?;
    let index = program.structs[camera.struct_id]
        .field_index("position")
        .ok_or("the camera has no `position`")?;
    if let Some(camera) = program.scenes[scene].camera.as_mut() {
        if let Some(f) = camera.fields.get_mut(index) {
            *f = vec3(position);
        }
    }
    Ok(())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

struct Args {
    scene: PathBuf,
    mesh: Option<PathBuf>,
    size: [u32; 2],
    runs: usize,
    instances: usize,
}

fn args() -> Result<Args, String> {
    let mut a = Args {
        scene: PathBuf::from("examples/thesis_scene/scene.rt"),
        mesh: None,
        size: [960, 540],
        runs: 7,
        instances: 10_000,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "--size" => {
                let v = value("--size")?;
                let (w, h) = v.split_once('x').ok_or("--size WxH")?;
                a.size = [
                    w.parse().map_err(|_| "--size WxH")?,
                    h.parse().map_err(|_| "--size WxH")?,
                ];
            }
            "--runs" => a.runs = value("--runs")?.parse().map_err(|_| "--runs N")?,
            "--mesh" => a.mesh = Some(PathBuf::from(value("--mesh")?)),
            "--instances" => {
                a.instances = value("--instances")?.parse().map_err(|_| "--instances N")?
            }
            other => a.scene = PathBuf::from(other),
        }
    }
    Ok(a)
}

/// A scene of one OBJ mesh (copied into a temporary folder) on a floor, seen from the front of
/// its box, lit by a point light.
fn one_mesh(mesh: &Path) -> Result<PathBuf, String> {
    let data = rtc_runtime::assets::load_obj(mesh).map_err(|e| e.to_string())?;
    let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for p in &data.positions {
        lo = lo.min(Vec3::from(*p));
        hi = hi.max(Vec3::from(*p));
    }
    let (c, r) = ((lo + hi) * 0.5, (hi - lo).length() * 0.5);
    let dir = std::env::temp_dir().join(format!("rtc-session-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    std::fs::copy(mesh, dir.join("mesh.obj")).map_err(|e| e.to_string())?;
    let v = |v: Vec3| format!("vec3f({:.5}, {:.5}, {:.5})", v.x, v.y, v.z);
    let text = format!(
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
         import \"std/lights/point.rt\";\nimport \"std/miss/constant.rt\";\n\
         scene one_mesh {{\n    settings {{ width: 960, height: 540, samples: 1, max_depth: 0 }}\n\
         camera Pinhole {{ position: {}, look_at: {}, fov: 40.0 }}\n\
         background ConstantBackground {{ color: vec3f(0.1) }}\n\
         object floor {{ geometry: quad_mesh(), material: Lambert {{}}, transform: translate({}) * scale({:.5}) }}\n\
         object model {{ geometry: load_mesh(\"mesh.obj\"), material: Lambert {{ albedo: vec3f(0.7, 0.6, 0.5) }} }}\n\
         light PointLight {{ position: {}, intensity: {:.5} }}\n}}\n",
        v(c + Vec3::new(0.0, 0.6 * r, 2.8 * r)),
        v(c),
        v(Vec3::new(c.x, lo.y, c.z)),
        4.0 * r,
        v(c + Vec3::new(r, 3.0 * r, 2.0 * r)),
        20.0 * r * r
    );
    let path = dir.join("one_mesh.rt");
    std::fs::write(&path, text).map_err(|e| e.to_string())?;
    Ok(path)
}

/// A scene of `n` spheres on a grid, one mesh, written into a temporary folder.
fn many_instances(n: usize) -> Result<PathBuf, String> {
    let dir = std::env::temp_dir().join(format!("rtc-session-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let side = (n as f64).sqrt().ceil() as usize;
    let mut text = String::from(
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
         import \"std/lights/point.rt\";\nimport \"std/miss/constant.rt\";\n\
         scene many {\n    settings { width: 64, height: 64, samples: 1, max_depth: 0 }\n\
         camera Pinhole { position: vec3f(0.0, 50.0, 120.0), look_at: vec3f(0.0) }\n\
         let ball = sphere_mesh(1u);\n",
    );
    for i in 0..n {
        let (x, z) = ((i % side) as f32 - side as f32 / 2.0, (i / side) as f32);
        text.push_str(&format!(
            "    object {{ geometry: ball, material: Lambert {{}}, transform: translate(vec3f({x:.1}, 0.0, {z:.1})) * scale(0.4) }}\n"
        ));
    }
    text.push_str(
        "    light PointLight { position: vec3f(0.0, 80.0, 0.0), intensity: 1000.0 }\n}\n",
    );
    let path = dir.join("many.rt");
    std::fs::write(&path, text).map_err(|e| e.to_string())?;
    Ok(path)
}

fn run() -> Result<(), String> {
    let a = args()?;
    let gpu = Gpu::new(&AdapterChoice::default()).map_err(|e| e.to_string())?;
    println!("adapter: {}", gpu.description());
    let scene = match &a.mesh {
        Some(mesh) => one_mesh(mesh)?,
        None => a.scene.clone(),
    };
    let mut compiled = compile(&scene)?;
    let one = RenderOptions {
        size: Some(a.size),
        samples: Some(1),
        ..RenderOptions::default()
    };
    let mut session = Renderer::new(&gpu, &compiled, one.clone()).map_err(|e| e.to_string())?;
    session.render(&mut |_, _| {}).map_err(|e| e.to_string())?;
    let objects = session.entities().objects().len();
    let blas_before = session.store().counters().blas_builds;

    // 1. Camera move through the session, against a fresh renderer (alternating), and the preview
    // `rtc view` shows during a drag.
    let (mut moved, mut fresh) = (Vec::new(), Vec::new());
    let (mut previewed, mut pass_ms) = (Vec::new(), None);
    for run in 0..a.runs {
        let angle = run as f32 * 0.05;
        let position = Vec3::new(0.9 * angle.sin(), 0.55, 0.9 * angle.cos());
        let t = Instant::now();
        session
            .set_field(FieldTarget::Camera, "position", &vec3(position))
            .map_err(|e| e.to_string())?;
        let s = session
            .accumulate(1, &mut |_, _| {})
            .map_err(|e| e.to_string())?;
        let t2 = Instant::now();
        session.image().map_err(|e| e.to_string())?;
        if std::env::var_os("RTC_BENCH_DETAIL").is_some() {
            eprintln!(
                "session: render {:.1} upload {:.1} readback(image) {:.1} total {:.1}",
                s.render_ms,
                s.upload_ms,
                ms(t2),
                ms(t)
            );
        }
        moved.push(ms(t));
        pass_ms = Some(s.render_ms);
        let factor = preview_factor(pass_ms);
        let t = Instant::now();
        session
            .set_field(FieldTarget::Camera, "position", &vec3(position * 1.01))
            .map_err(|e| e.to_string())?;
        session.preview(factor).map_err(|e| e.to_string())?;
        previewed.push(ms(t));
        // The fresh renderer gets the same camera, written into the scene description.
        set_camera_position(&mut compiled, position)?;
        let t = Instant::now();
        let mut r = Renderer::new(&gpu, &compiled, one.clone()).map_err(|e| e.to_string())?;
        let t3 = Instant::now();
        let f = r.render(&mut |_, _| {}).map_err(|e| e.to_string())?;
        if std::env::var_os("RTC_BENCH_DETAIL").is_some() {
            eprintln!(
                "fresh: new {:.1} render {:.1} upload {:.1} readback {:.1} total {:.1}",
                t3.duration_since(t).as_secs_f64() * 1e3,
                f.stats.render_ms,
                f.stats.upload_ms,
                f.stats.readback_ms,
                ms(t)
            );
        }
        fresh.push(ms(t));
    }
    let (moved, fresh, previewed) = (median(moved), median(fresh), median(previewed));
    let factor = preview_factor(pass_ms);

    // 2. Every object moving against a static frame (alternating).
    let placements: Vec<Mat4> = session
        .entities()
        .objects()
        .iter()
        .map(|o| o.transform)
        .collect();
    let (mut still, mut moving) = (Vec::new(), Vec::new());
    let mut tlas_ms = Vec::new();
    for run in 0..a.runs {
        session.reset_accumulation();
        let t = Instant::now();
        session
            .accumulate(1, &mut |_, _| {})
            .map_err(|e| e.to_string())?;
        session.image().map_err(|e| e.to_string())?;
        still.push(ms(t));
        let t = Instant::now();
        for (i, p) in placements.iter().enumerate().skip(1) {
            let turn = Mat4::from_rotation_y(0.2 * (run + 1) as f32);
            let (_, _, at) = p.to_scale_rotation_translation();
            let spin = Mat4::from_translation(at) * turn * Mat4::from_translation(-at) * *p;
            session.set_transform(i, spin).map_err(|e| e.to_string())?;
        }
        let s = session
            .accumulate(1, &mut |_, _| {})
            .map_err(|e| e.to_string())?;
        session.image().map_err(|e| e.to_string())?;
        moving.push(ms(t));
        tlas_ms.push(s.bvh_build_ms);
    }
    let (still, moving, tlas) = (median(still), median(moving), median(tlas_ms));
    let blas_after = session.store().counters().blas_builds;

    // 3. The scene level of many instances.
    let many_path = many_instances(a.instances)?;
    let many = compile(&many_path)?;
    let mut big =
        Renderer::new(&gpu, &many, RenderOptions::default()).map_err(|e| e.to_string())?;
    big.accumulate(1, &mut |_, _| {})
        .map_err(|e| e.to_string())?;
    let base: Vec<Mat4> = big
        .entities()
        .objects()
        .iter()
        .map(|o| o.transform)
        .collect();
    let (mut rebuild, mut upload) = (Vec::new(), Vec::new());
    for run in 0..a.runs {
        let lift = Mat4::from_translation(Vec3::new(0.0, 0.01 * (run + 1) as f32, 0.0));
        for (i, m) in base.iter().enumerate() {
            big.set_transform(i, lift * *m).map_err(|e| e.to_string())?;
        }
        let s = big
            .accumulate(0, &mut |_, _| {})
            .map_err(|e| e.to_string())?;
        rebuild.push(s.bvh_build_ms);
        upload.push(s.upload_ms);
    }
    let (rebuild, upload) = (median(rebuild), median(upload));
    let _ = std::fs::remove_dir_all(many_path.parent().unwrap_or(Path::new("/nonexistent")));
    if a.mesh.is_some() {
        let _ = std::fs::remove_dir_all(scene.parent().unwrap_or(Path::new("/nonexistent")));
    }

    let [w, h] = a.size;
    println!(
        "scene: {} at {w}x{h}, {} runs, medians",
        a.mesh.as_ref().unwrap_or(&a.scene).display(),
        a.runs
    );
    println!(
        "camera move, 1 spp:   session {moved:8.1} ms   fresh Renderer::new + render {fresh:8.1} ms   ratio {:.1}x",
        fresh / moved
    );
    println!(
        "camera move, preview: 1/{factor} of width and height {previewed:8.1} ms   ratio to fresh {:.1}x",
        fresh / previewed
    );
    println!(
        "{} objects moving:    {moving:8.1} ms   static frame {still:8.1} ms   ratio {:.3}x   (TLAS rebuild {tlas:.2} ms; BLAS builds during motion: {})",
        objects.saturating_sub(1),
        moving / still,
        blas_after - blas_before
    );
    println!(
        "scene level, {} instances moved: TLAS rebuild {rebuild:.2} ms, upload {upload:.2} ms",
        a.instances
    );
    println!(
        "{{\"scene\":\"{}\",\"size\":[{w},{h}],\"camera_move_ms\":{moved:.2},\"fresh_ms\":{fresh:.2},\"preview_factor\":{factor},\"preview_ms\":{previewed:.2},\"moving_ms\":{moving:.2},\"static_ms\":{still:.2},\"tlas_ms\":{tlas:.3},\"blas_builds_in_motion\":{},\"instances\":{},\"scene_level_rebuild_ms\":{rebuild:.3},\"scene_level_upload_ms\":{upload:.3}}}",
        a.mesh.as_ref().unwrap_or(&a.scene).display(),
        blas_after - blas_before,
        a.instances
    );
    Ok(())
}

fn main() {
    // What `rtc view` does first (the settings it measures against): rtc's lavapipe defaults for
    // a session of frames whose samples are not known ahead. Before any thread or wgpu instance.
    rtc_runtime::gpu::apply_lavapipe_defaults(rtc_runtime::gpu::CpuJit::Optimized, None);
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
