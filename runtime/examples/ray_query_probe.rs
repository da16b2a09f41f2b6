//! How fast the driver's own ray queries (`VK_KHR_ray_query` through wgpu's experimental
//! `EXPERIMENTAL_RAY_QUERY`) trace the thesis workload, next to rtc's compute traversal: the same
//! camera as `examples/thesis_scene/scene.rt`, 1920x1080 camera rays, and for each hit one
//! occlusion ray to each of the scene's two point lights, on the flattened 105,980-triangle
//! scene of `../shared/models/thesis-scene-106k.obj` (one BLAS, one instance), as Embree traces it.
//! A performance aid for the traversal backend decision (docs/bench/lavapipe.md), not a test;
//! the kernel does no shading, so its time is traversal only:
//! `cargo run --release -p rtc-runtime --example ray_query_probe [path/to/scene.obj]`.
//!
//! wgpu gates ray queries behind `ExperimentalFeatures`, whose constructor is `unsafe` (the API
//! may change between releases); this example is the one place that opts in.
#![allow(unsafe_code)]

use rtc_runtime::gpu::{AdapterChoice, Gpu};
use std::time::Instant;
use wgpu::util::DeviceExt;

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;

const SHADER: &str = r#"
enable wgpu_ray_query;

@group(0) @binding(0) var scene: acceleration_structure;
@group(0) @binding(1) var<storage, read> positions: array<f32>;
@group(0) @binding(2) var<storage, read> indices: array<u32>;
@group(0) @binding(3) var<storage, read_write> out: array<u32>;

fn vertex(i: u32) -> vec3f {
    return vec3f(positions[i * 3u], positions[i * 3u + 1u], positions[i * 3u + 2u]);
}

fn occluded(origin: vec3f, to: vec3f) -> bool {
    let d = to - origin;
    let dist = length(d);
    var rq: ray_query;
    // Opaque, terminate on the first hit: an any-hit query.
    rayQueryInitialize(&rq, scene, RayDesc(0x5u, 0xffu, 0.0, dist * (1.0 - 1e-5), origin, d / dist));
    rayQueryProceed(&rq);
    return rayQueryGetCommittedIntersection(&rq).kind != RAY_QUERY_INTERSECTION_NONE;
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3u) {
    if id.x >= 1920u || id.y >= 1080u {
        return;
    }
    let size = vec2f(1920.0, 1080.0);
    let position = vec3f(0.0, 0.55, 0.9);
    let ndc = (vec2f(id.xy) + 0.5) / size * 2.0 - 1.0;
    let forward = normalize(vec3f(0.0, 0.02, -0.05) - position);
    let right = normalize(cross(forward, vec3f(0.0, 1.0, 0.0)));
    let up = cross(right, forward);
    let h = tan(radians(45.0) * 0.5);
    let dir = normalize(forward + right * (ndc.x * h * size.x / size.y) - up * (ndc.y * h));
    var rq: ray_query;
    rayQueryInitialize(&rq, scene, RayDesc(0x1u, 0xffu, 0.0, 1e30, position, dir));
    rayQueryProceed(&rq);
    let hit = rayQueryGetCommittedIntersection(&rq);
    var result = 0u;
    if hit.kind != RAY_QUERY_INTERSECTION_NONE {
        let tri = hit.primitive_index;
        let a = vertex(indices[tri * 3u]);
        let b = vertex(indices[tri * 3u + 1u]);
        let c = vertex(indices[tri * 3u + 2u]);
        let p = a + (b - a) * hit.barycentrics.x + (c - a) * hit.barycentrics.y;
        var n = normalize(cross(b - a, c - a));
        if dot(n, dir) > 0.0 {
            n = -n;
        }
        let m = max(max(abs(p.x), abs(p.y)), max(abs(p.z), 10.0));
        let origin = p + n * (m * (1.0 / 65536.0));
        result = 1u;
        if !occluded(origin, vec3f(-0.8, 1.5, 0.8)) {
            result |= 2u;
        }
        if !occluded(origin, vec3f(0.9, 1.2, -0.5)) {
            result |= 4u;
        }
    }
    out[id.y * 1920u + id.x] = result;
}
"#;

/// Positions and triangle indices of an OBJ file's `v` and `f` lines (polygons fanned).
fn load_obj(path: &str) -> Result<(Vec<f32>, Vec<u32>), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut positions = Vec::new();
    let mut indices = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let bad = || format!("{path}:{}: not a vertex or face this probe reads", n + 1);
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                for w in words.take(3) {
                    positions.push(w.parse::<f32>().map_err(|_| bad())?);
                }
            }
            Some("f") => {
                let mut face = Vec::new();
                for w in words {
                    let i = w.split('/').next().and_then(|i| i.parse::<u32>().ok());
                    face.push(i.and_then(|i| i.checked_sub(1)).ok_or_else(bad)?);
                }
                for k in 1..face.len().saturating_sub(1) {
                    indices.extend([face[0], face[k], face[k + 1]]);
                }
            }
            _ => {}
        }
    }
    Ok((positions, indices))
}

fn main() {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "../shared/models/thesis-scene-106k.obj".to_string());
    let (positions, indices) = match load_obj(&path) {
        Ok(mesh) => mesh,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let gpu = Gpu::new(&AdapterChoice::default()).expect("adapter");
    let adapter = gpu.adapter();
    println!("{}", gpu.description().name);
    let features = wgpu::Features::EXPERIMENTAL_RAY_QUERY;
    if !adapter.features().contains(features) {
        println!("the adapter has no EXPERIMENTAL_RAY_QUERY");
        return;
    }
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_features: features,
        required_limits: adapter.limits(),
        // SAFETY: opting in to wgpu's experimental ray-query API, which is what this probe measures.
        experimental_features: unsafe { wgpu::ExperimentalFeatures::enabled() },
        ..Default::default()
    }))
    .expect("device");
    device.on_uncaptured_error(std::sync::Arc::new(|e: wgpu::Error| println!("ERR {e}")));
    let wait = || {
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("poll");
    };
    let triangles = (indices.len() / 3) as u32;
    println!("{path}: {triangles} triangles");

    let storage = |data: &[u8], extra: wgpu::BufferUsages| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: data,
            usage: wgpu::BufferUsages::STORAGE | extra,
        })
    };
    let vertex_buffer = storage(
        bytemuck::cast_slice(&positions),
        wgpu::BufferUsages::BLAS_INPUT,
    );
    let index_buffer = storage(
        bytemuck::cast_slice(&indices),
        wgpu::BufferUsages::BLAS_INPUT,
    );
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(WIDTH * HEIGHT) * 4,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(WIDTH * HEIGHT) * 4,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });

    let size = wgpu::BlasTriangleGeometrySizeDescriptor {
        vertex_format: wgpu::VertexFormat::Float32x3,
        vertex_count: (positions.len() / 3) as u32,
        index_format: Some(wgpu::IndexFormat::Uint32),
        index_count: Some(indices.len() as u32),
        flags: wgpu::AccelerationStructureGeometryFlags::OPAQUE,
    };
    let blas = device.create_blas(
        &wgpu::CreateBlasDescriptor {
            label: None,
            flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
            update_mode: wgpu::AccelerationStructureUpdateMode::Build,
        },
        wgpu::BlasGeometrySizeDescriptors::Triangles {
            descriptors: vec![size.clone()],
        },
    );
    let mut tlas = device.create_tlas(&wgpu::CreateTlasDescriptor {
        label: None,
        max_instances: 1,
        flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
        update_mode: wgpu::AccelerationStructureUpdateMode::Build,
    });
    tlas[0] = Some(wgpu::TlasInstance::new(
        &blas,
        [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0],
        0,
        0xff,
    ));
    let start = Instant::now();
    let mut encoder = device.create_command_encoder(&Default::default());
    encoder.build_acceleration_structures(
        [&wgpu::BlasBuildEntry {
            blas: &blas,
            geometry: wgpu::BlasGeometries::TriangleGeometries(vec![wgpu::BlasTriangleGeometry {
                size: &size,
                vertex_buffer: &vertex_buffer,
                first_vertex: 0,
                vertex_stride: 12,
                index_buffer: Some(&index_buffer),
                first_index: Some(0),
                transform_buffer: None,
                transform_buffer_offset: None,
            }]),
        }],
        [&tlas],
    );
    queue.submit([encoder.finish()]);
    wait();
    println!(
        "acceleration structures built in {:.1} ms",
        start.elapsed().as_secs_f64() * 1e3
    );

    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ray query probe"),
        source: wgpu::ShaderSource::Wgsl(SHADER.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::AccelerationStructure(&tlas),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: vertex_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: index_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: out.as_entire_binding(),
            },
        ],
    });
    let mut times = Vec::new();
    for _ in 0..6 {
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(WIDTH.div_ceil(8), HEIGHT.div_ceil(8), 1);
        }
        let start = Instant::now();
        queue.submit([encoder.finish()]);
        wait();
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    // The first dispatch warms up; the median of the other five.
    let mut warm = times[1..].to_vec();
    warm.sort_by(f64::total_cmp);
    let median = warm[warm.len() / 2];

    let mut encoder = device.create_command_encoder(&Default::default());
    encoder.copy_buffer_to_buffer(&out, 0, &readback, 0, None);
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |r| r.expect("map"));
    wait();
    let flags: Vec<u32> =
        bytemuck::cast_slice(&readback.get_mapped_range(..).expect("range")).to_vec();
    let hits = flags.iter().filter(|&&f| f & 1 != 0).count();
    let lit = [2, 4].map(|bit| flags.iter().filter(|&&f| f & bit != 0).count());
    let rays = WIDTH as usize * HEIGHT as usize + 2 * hits;
    println!(
        "frame {median:.1} ms (median of 5; all: {times:.1?}): {hits} camera hits, \
         {} and {} of them lit, {rays} rays, {:.2} M rays/s",
        lit[0],
        lit[1],
        rays as f64 / median / 1e3
    );
}
