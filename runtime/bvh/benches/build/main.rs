//! `cargo bench -p rtc-bvh --bench build -- [--quick] [--runs N] [--scenes a,b] [--no-obvhs]
//! [--no-trace] [--no-gate] [--embree /tmp/embree.json]`
//!
//! For each scene (bunny, armadillo, dragon, thesis, and "dragon10m": 12 dragons, 10.5M
//! triangles) and each builder (every rtc-bvh preset; obvhs's fastest and highest-quality
//! presets): the build time (median), the SAH cost with the same constants for all
//! ([`rtc_bvh::SahCost::STANDARD`]), the tree statistics, and the CPU trace throughput of the
//! 1920x1080 primary rays of `shared/bench/benchlib.py` (the cameras of the Embree anchor)
//! through the same reference traversal, so tree quality shows as trace speed. With
//! `--embree`, the JSON written by `shared/bench/embree_bench.py` in the same session is read
//! and the ratios to Embree are printed.
//!
//! Invariants:
//! * rtc-bvh builds start from the vertex and index buffers (like Embree's commit) and their
//!   time includes input preparation, the build and the conversion to the GPU mesh layout
//!   (`rtc_bvh::quantized::quantize`, what the runtime uploads); obvhs builds
//!   start from its own triangle type (conversion not timed) and include its AABB generation.
//! * Every timing block is preceded by a load gate (waits while other processes keep more than
//!   half a core busy) and reports how busy other processes were *during* the block.
//! * Timings are medians over at least `--runs` runs and at least one second of runs (at most
//!   50), after warm-up runs.
//! * Every builder's closest hits are compared with the first builder's: `t`, primitive and
//!   barycentrics must agree for every ray; a mismatch is printed.

mod load;
mod obvhs_adapter;
mod scenes;

use std::time::{Duration, Instant};

use rayon::prelude::*;
use rtc_bvh::quantized::quantize;
use rtc_bvh::traverse::{closest_hit, Hit, Ray};
use rtc_bvh::{build, flatten, BuildInput, BuildPreset, Bvh, GpuNode};

use scenes::{Camera, Mesh};

struct Options {
    runs: usize,
    trace_runs: usize,
    min_time: Duration,
    scenes: Vec<String>,
    obvhs: bool,
    gate_tries: u32,
    trace: bool,
    embree: Option<String>,
    print_camera: bool,
}

fn parse_args() -> Options {
    let mut o = Options {
        runs: 5,
        trace_runs: 3,
        min_time: Duration::from_secs(1),
        scenes: ["bunny", "armadillo", "dragon", "thesis", "dragon10m"]
            .map(String::from)
            .to_vec(),
        obvhs: true,
        gate_tries: 6,
        trace: true,
        embree: None,
        print_camera: false,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => {
                o.runs = 1;
                o.trace_runs = 1;
                o.min_time = Duration::ZERO;
            }
            "--runs" => o.runs = args.next().and_then(|v| v.parse().ok()).unwrap_or(o.runs),
            "--scenes" => {
                if let Some(v) = args.next() {
                    o.scenes = v.split(',').map(String::from).collect();
                }
            }
            "--no-obvhs" => o.obvhs = false,
            "--no-gate" => o.gate_tries = 0,
            "--no-trace" => o.trace = false,
            "--embree" => o.embree = args.next(),
            "--print-camera" => o.print_camera = true,
            _ => {} // `cargo bench` passes `--bench`; ignore what we do not know.
        }
    }
    o
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// A timed block: median ms, number of runs, and what other processes did meanwhile.
struct Timing {
    ms: f64,
    runs: usize,
    load: String,
}

/// Waits for a quiet machine, warms up, then times `f` for at least `min_runs` runs and at
/// least `min_time` (at most 50 runs; a single run for calls over five seconds). Returns the
/// timing and the last result.
fn measure<T>(label: &str, o: &Options, min_runs: usize, mut f: impl FnMut() -> T) -> (Timing, T) {
    let gate = load::gate(label, 0.5, o.gate_tries, Duration::from_secs(20));
    let t0 = Instant::now();
    let mut out = f();
    let first = t0.elapsed();
    let runs = if first > Duration::from_secs(5) {
        1
    } else {
        drop(out);
        out = f(); // second warm-up: allocator and thread pool settle
        let by_time = (o.min_time.as_secs_f64() / first.as_secs_f64().max(1e-6)).ceil() as usize;
        by_time.clamp(min_runs.max(1), 50.max(min_runs))
    };
    let during = load::Window::start();
    let mut ts = Vec::with_capacity(runs);
    for _ in 0..runs {
        drop(out);
        let t = Instant::now();
        out = f();
        ts.push(t.elapsed().as_secs_f64() * 1e3);
    }
    let others = during.others_busy_cores();
    let load = match others {
        Some(b) if b > 0.5 => format!("NOISY: others {b:.2} cores ({gate})"),
        Some(b) => format!("others {b:.2} cores"),
        None => gate,
    };
    (
        Timing {
            ms: median(ts),
            runs,
            load,
        },
        out,
    )
}

struct Scene {
    name: &'static str,
    key: &'static str,
    mesh: Mesh,
    camera: Camera,
}

fn load_scene(name: &str) -> Result<Scene, String> {
    let dir = scenes::models_dir();
    let file = |f: &str| scenes::load_obj(&dir.join(f));
    let (key, name, mesh): (&'static str, &'static str, Mesh) = match name {
        "bunny" => ("bunny", "bunny", file("stanford-bunny.obj")?),
        "armadillo" => ("armadillo", "armadillo", file("armadillo-100k.obj")?),
        "dragon" => ("dragon", "dragon", file("stanford-dragon.obj")?),
        "thesis" => ("thesis", "thesis", file("thesis-scene-106k.obj")?),
        "dragon10m" => (
            "dragon10m",
            "dragon x12",
            scenes::replicate(&file("stanford-dragon.obj")?, 12),
        ),
        other => return Err(format!("unknown scene {other}")),
    };
    let camera = if key == "thesis" {
        scenes::THESIS_CAMERA
    } else {
        scenes::auto_camera(&mesh.vertices)
    };
    Ok(Scene {
        name,
        key,
        mesh,
        camera,
    })
}

struct Row {
    builder: String,
    build: Timing,
    bvh: Bvh,
}

/// The measured results of one scene, for the Embree summary.
struct SceneResult {
    key: &'static str,
    rows: Vec<(String, f64, f32, f64)>, // builder, build ms, SAH, Mrays/s
}

fn trace_all(
    nodes: &[GpuNode],
    bvh: &Bvh,
    tris: &[[glam::Vec3; 3]],
    rays: &[Ray],
) -> Vec<Option<Hit>> {
    rays.par_chunks(4096)
        .flat_map_iter(|c| {
            c.iter()
                .map(|r| closest_hit(nodes, bvh.prim_indices(), tris, r))
        })
        .collect()
}

fn bench_scene(scene: &Scene, o: &Options) -> SceneResult {
    let tris = scene.mesh.triangles();
    println!(
        "\n== {}: {} triangles, {} vertices",
        scene.name,
        tris.len(),
        scene.mesh.vertices.len()
    );
    let input = BuildInput::Indexed {
        vertices: &scene.mesh.vertices,
        indices: &scene.mesh.indices,
    };
    let mut rows = Vec::new();
    for preset in BuildPreset::ALL {
        let label = format!("rtc {}", preset.name());
        let (build, (bvh, _records)) = measure(&label, o, o.runs, || {
            let bvh = build(input, preset);
            // What the runtime does with a mesh's BVH: its quantised node records.
            let records = quantize(&bvh).map(|q| q.to_records());
            (bvh, records)
        });
        rows.push(Row {
            builder: label,
            build,
            bvh,
        });
    }
    if o.obvhs {
        let otris = obvhs_adapter::triangles(&tris);
        for (label, params) in obvhs_adapter::PRESETS {
            let (build, b) = measure(label, o, o.runs, || obvhs_adapter::build(&otris, params));
            rows.push(Row {
                builder: label.to_string(),
                build,
                bvh: obvhs_adapter::convert(&b, tris.len()),
            });
        }
    }
    let rays = scenes::primary_rays(&scene.camera, scenes::W, scenes::H);
    if o.print_camera {
        let c = &scene.camera;
        println!(
            "camera eye {:?} target {:?}",
            c.eye.to_array(),
            c.target.to_array()
        );
        for i in [
            0,
            scenes::W * (scenes::H / 2) + scenes::W / 2,
            rays.len() - 1,
        ] {
            println!(
                "ray {i}: origin {:?} dir {:?}",
                rays[i].origin.to_array(),
                rays[i].dir.to_array()
            );
        }
    }
    println!(
        "{:<16} {:>9} {:>4} {:>7} {:>9} {:>6} {:>5} {:>7} {:>8} {:>6}  load during build / trace",
        "builder",
        "build ms",
        "runs",
        "SAH",
        "nodes",
        "depth",
        "leaf",
        "refs/tri",
        "Mrays/s",
        "hit%"
    );
    let mut reference: Option<Vec<Option<Hit>>> = None;
    let mut result = SceneResult {
        key: scene.key,
        rows: Vec::new(),
    };
    for row in &rows {
        let s = row.bvh.stats();
        let nodes = flatten(&row.bvh);
        let (mrays, hit_pct, trace_load) = if o.trace {
            let (t, hits) = measure(&row.builder, o, o.trace_runs, || {
                trace_all(&nodes, &row.bvh, &tris, &rays)
            });
            let hit = hits.iter().filter(|h| h.is_some()).count() as f64 / hits.len() as f64;
            match &reference {
                None => reference = Some(hits),
                Some(r) => {
                    let bad = r.iter().zip(&hits).filter(|(a, b)| a != b).count();
                    if bad > 0 {
                        println!("   !! {bad} rays differ from the first builder's closest hits");
                    }
                }
            }
            (rays.len() as f64 / (t.ms * 1e3), 100.0 * hit, t.load)
        } else {
            (f64::NAN, f64::NAN, "not traced".to_string())
        };
        println!(
            "{:<16} {:>9.1} {:>4} {:>7.2} {:>9} {:>6} {:>5.2} {:>7.3} {:>8.2} {:>6.1}  {} / {}",
            row.builder,
            row.build.ms,
            row.build.runs,
            s.sah_cost,
            s.node_count,
            s.max_depth,
            s.avg_leaf_size,
            s.prim_refs as f64 / tris.len() as f64,
            mrays,
            hit_pct,
            row.build.load,
            trace_load
        );
        result
            .rows
            .push((row.builder.clone(), row.build.ms, s.sah_cost, mrays));
    }
    result
}

/// Prints build-time and trace-speed ratios to the Embree figures in `path`.
fn embree_summary(path: &str, results: &[SceneResult]) {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => return println!("\n(no Embree comparison: {path}: {e})"),
    };
    let json: serde_json::Value = match serde_json::from_str(&text) {
        Ok(j) => j,
        Err(e) => return println!("\n(no Embree comparison: {path}: {e})"),
    };
    println!("\n== ratios to Embree 4 (embreex, {path}); build: Embree commit median, trace: Embree primary (closest hit with hit record), 2 threads");
    println!(
        "{:<12} {:<16} {:>10} {:>10} {:>8} {:>10} {:>10} {:>8}",
        "scene", "builder", "build ms", "embree ms", "ratio", "Mrays/s", "embree", "ratio"
    );
    let scenes = json["scenes"].as_array().cloned().unwrap_or_default();
    for r in results {
        let Some(e) = scenes.iter().find(|s| s["scene"] == r.key) else {
            continue;
        };
        let e_build = e["build_commit_s"]["median"].as_f64().unwrap_or(f64::NAN) * 1e3;
        let e_rays = e["per_threads"]["2"]["mrays_s"]["primary"]
            .as_f64()
            .unwrap_or(f64::NAN);
        for (builder, ms, _, mrays) in &r.rows {
            println!(
                "{:<12} {:<16} {:>10.1} {:>10.1} {:>8.2} {:>10.2} {:>10.2} {:>8.2}",
                r.key,
                builder,
                ms,
                e_build,
                ms / e_build,
                mrays,
                e_rays,
                mrays / e_rays
            );
        }
    }
}

fn main() {
    let o = parse_args();
    println!(
        "rtc-bvh build benchmark: {} rayon threads, >= {} build runs (median, >= {:.0} s of runs), >= {} trace runs, {}x{} primary rays",
        rayon::current_num_threads(),
        o.runs,
        o.min_time.as_secs_f64(),
        o.trace_runs,
        scenes::W,
        scenes::H
    );
    let mut results = Vec::new();
    for name in &o.scenes {
        let t0 = Instant::now();
        match load_scene(name) {
            Ok(scene) => {
                println!(
                    "(loaded {} in {:.1} s)",
                    scene.name,
                    t0.elapsed().as_secs_f64()
                );
                results.push(bench_scene(&scene, &o));
            }
            Err(e) => println!("\n== {name}: skipped ({e})"),
        }
    }
    if let Some(path) = &o.embree {
        embree_summary(path, &results);
    }
}
