//! What a storage-buffer load costs on the chosen adapter: a chain of 64 dependent, divergent loads
//! per invocation from a 512 KiB buffer, by load shape (scalars, `vec3`, `vec4`), printed as
//! nanoseconds per step of one 8-lane SIMD batch. A performance aid for kernel layout decisions
//! (docs/bench/lavapipe.md), not a test:
//! `cargo run --release -p rtc-runtime --example load_costs`.
//!
//! On Mesa 22.3's lavapipe every load becomes a loop over the lanes with a bounds check per
//! component, so the cost is about a fixed part per load plus a part per component; Mesa 25's is
//! cheaper per component (ARCHITECTURE.md has both sets of figures). Adjacent loads are merged,
//! but still fetched one 32-bit component per lane at a time, so the cost grows with the words
//! loaded; the `vec4<u64>` cases (run where the adapter has `SHADER_INT64`, on a device of their
//! own) fetch two words per lane at a time. The `64K` and `half lanes` cases compare a storage
//! buffer with a uniform buffer of the same 64 KiB, with every lane loading and with a random half
//! of them: lavapipe tests each lane's mask bit with a branch before a storage load, and a random
//! mask makes those branches mispredict; its uniform-buffer gathers have no such branch.
use rtc_runtime::gpu::{AdapterChoice, Gpu};
use std::time::Instant;
use wgpu::util::DeviceExt;

fn main() {
    let gpu = Gpu::new(&AdapterChoice::default()).expect("adapter");
    // A device of its own, with `SHADER_INT64` where the adapter has it (rtc's does not ask for it).
    let int64 = gpu
        .adapter()
        .features()
        .contains(wgpu::Features::SHADER_INT64);
    let (device, queue) =
        pollster::block_on(gpu.adapter().request_device(&wgpu::DeviceDescriptor {
            required_features: if int64 {
                wgpu::Features::SHADER_INT64
            } else {
                wgpu::Features::empty()
            },
            required_limits: gpu.adapter().limits(),
            ..Default::default()
        }))
        .expect("device");
    device.on_uncaptured_error(std::sync::Arc::new(|e: wgpu::Error| println!("ERR {e}")));
    let device = &device;
    let threads = std::thread::available_parallelism().map_or(1.0, |n| n.get() as f64);
    println!("{} ({threads} cores)", gpu.description().name);
    let n: u32 = 1 << 15; // vec4s: 512 KiB
    let data: Vec<u32> = (0..n * 4)
        .map(|i| i.wrapping_mul(2654435761) >> 17)
        .collect();
    let buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&data),
        usage: wgpu::BufferUsages::STORAGE,
    });
    // The first 64 KiB of the same data, as a uniform buffer.
    let ubo = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&data[..16384]),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 4 << 20,
        usage: wgpu::BufferUsages::STORAGE,
        mapped_at_creation: false,
    });
    let cases = [
        ("no load", "let v = vec4u(i * 3u, i ^ 7u, i + 5u, i >> 1u);"),
        ("1 x u32", "let v = vec4u(s[i * 4u]);"),
        ("4 x u32", "let v = vec4u(s[i * 4u], s[i * 4u + 1u], s[i * 4u + 2u], s[i * 4u + 3u]);"),
        ("1 x vec4u", "let v = q[i];"),
        ("1 x vec3u", "let v = vec4u(q[i].xyz, 0u);"),
        ("2 x vec4u", "let v = q[i] + q[i ^ 1u];"),
        ("3 x vec4u", "let j = i & 0x7ffcu; let v = q[j] + q[j + 1u] + q[j + 2u];"),
        ("4 x vec4u", "let j = i & 0x7ffcu; let v = q[j] + q[j + 1u] + q[j + 2u] + q[j + 3u];"),
        ("1 x vec4<u64>", "let w = d[(i & 0x7ffeu) >> 1u]; let v = vec4u(u32(w.x), u32(w.y >> 32u), u32(w.z), u32(w.w >> 32u));"),
        ("2 x vec4<u64>", "let j = (i & 0x7ffcu) >> 1u; let w = d[j] + d[j + 1u]; let v = vec4u(u32(w.x), u32(w.y >> 32u), u32(w.z), u32(w.w >> 32u));"),
        ("ssbo 2 x vec4u 64K", "let j = i & 0xffeu; let v = q[j] + q[j + 1u];"),
        ("ubo 2 x vec4u 64K", "let j = i & 0xffeu; let v = u[j] + u[j + 1u];"),
        ("ssbo half lanes", "let j = i & 0xffeu; var v = vec4u(i, i, i, i); if ((i >> 5u) & 1u) == 0u { v = q[j] + q[j + 1u]; }"),
        ("ubo half lanes", "let j = i & 0xffeu; var v = vec4u(i, i, i, i); if ((i >> 5u) & 1u) == 0u { v = u[j] + u[j + 1u]; }"),
        ("ssbo 2 x vec4u 16K", "let j = i & 0x3feu; let v = q[j] + q[j + 1u];"),
        ("wg 2 x vec4u 16K", "let j = i & 0x3feu; let v = w[j] + w[j + 1u];"),
        ("ssbo half lanes 16K", "let j = i & 0x3feu; var v = vec4u(i, i, i, i); if ((i >> 5u) & 1u) == 0u { v = q[j] + q[j + 1u]; }"),
        ("wg half lanes 16K", "let j = i & 0x3feu; var v = vec4u(i, i, i, i); if ((i >> 5u) & 1u) == 0u { v = w[j] + w[j + 1u]; }"),
        ("8 x u32", "let v = vec4u(s[i * 4u], s[i * 4u + 1u], s[i * 4u + 2u], s[i * 4u + 3u]) + vec4u(s[i * 4u + 4u], s[i * 4u + 5u], s[i * 4u + 6u], s[i * 4u + 7u]);"),
    ];
    for (name, body) in cases {
        let wide = body.contains("d[");
        if wide && !int64 {
            println!("{name:20} skipped: the adapter has no SHADER_INT64");
            continue;
        }
        let decl = if wide {
            "@group(0) @binding(3) var<storage, read> d: array<vec4<u64>>;"
        } else if body.contains("u[") {
            "@group(0) @binding(4) var<uniform> u: array<vec4u, 4096>;"
        } else if body.contains("w[") {
            "var<workgroup> w: array<vec4u, 1024>;"
        } else {
            ""
        };
        // A workgroup array is filled from `q` by the group's invocations before the chain.
        let fill = if body.contains("w[") {
            "for (var k = lid; k < 1024u; k += 64u) { w[k] = q[k]; }\n    workgroupBarrier();"
        } else {
            ""
        };
        let src = format!(
            "@group(0) @binding(0) var<storage, read> s: array<u32>;
@group(0) @binding(1) var<storage, read> q: array<vec4u>;
@group(0) @binding(2) var<storage, read_write> out: array<u32>;
{decl}
@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) g: vec3u, @builtin(local_invocation_index) lid: u32) {{
    {fill}
    let id = g.y * 1024u + g.x;
    var i = (id * 2654435761u) & 0x7ffeu;
    var acc = 0u;
    for (var k = 0u; k < 64u; k++) {{
        {body}
        acc += v.x + v.y + v.z + v.w;
        i = (v.x + v.w + i * 1664525u + 1013904223u) & 0x7ffeu;
    }}
    out[id] = acc;
}}"
        );
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(name),
            source: wgpu::ShaderSource::Wgsl(src.clone().into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(name),
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        let layout = pipeline.get_bind_group_layout(0);
        let mut entries = vec![wgpu::BindGroupEntry {
            binding: 2,
            resource: out.as_entire_binding(),
        }];
        if src.contains("s[") {
            entries.push(wgpu::BindGroupEntry {
                binding: 0,
                resource: buf.as_entire_binding(),
            });
        }
        if body.contains("u[") {
            entries.push(wgpu::BindGroupEntry {
                binding: 4,
                resource: ubo.as_entire_binding(),
            });
        }
        if wide {
            entries.push(wgpu::BindGroupEntry {
                binding: 3,
                resource: buf.as_entire_binding(),
            });
        }
        if src.contains("q[") || src.contains("w[") {
            entries.push(wgpu::BindGroupEntry {
                binding: 1,
                resource: buf.as_entire_binding(),
            });
        }
        let bg = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &layout,
            entries: &entries,
        });
        let mut best = f64::MAX;
        for _ in 0..3 {
            let mut enc = device.create_command_encoder(&Default::default());
            {
                let mut pass = enc.begin_compute_pass(&Default::default());
                pass.set_pipeline(&pipeline);
                pass.set_bind_group(0, &bg, &[]);
                pass.dispatch_workgroups(128, 128, 1);
            }
            let t = Instant::now();
            queue.submit([enc.finish()]);
            device
                .poll(wgpu::PollType::wait_indefinitely())
                .expect("poll");
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
        }
        // 1M invocations x 64 steps in 8-lane batches, spread over every core.
        let per_step = best * 1e6 * threads / (131_072.0 * 64.0);
        println!("{name:20} {best:8.1} ms  {per_step:6.1} ns per 8-lane step on one core");
    }
}
