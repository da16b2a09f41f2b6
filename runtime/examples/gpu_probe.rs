//! Prints what the runtime's GPU core sees and how fast it is: adapters, the chosen one, its
//! limits, context creation time, pipeline creation time, a 1920×1080 tiled dispatch of a
//! 64-FMA kernel, read-back, and upload/re-upload of 64 MiB.
//!
//! Run: `cargo run -p rtc-runtime --example gpu_probe -- [ADAPTER]`, where `ADAPTER` is an
//! `--adapter` value such as `gl` or `cpu,vulkan`. Set `MESA_SHADER_CACHE_DISABLE=true` to time
//! pipeline creation without Mesa's disk cache.

use std::time::Instant;

use rtc_runtime::gpu::{
    create_kernel, list_adapters, read_vec4_f32, AdapterChoice, BindingDesc, BindingKind,
    BufferSet, Gpu, KernelDesc, KernelSource, TileConfig, TileDispatcher, TILE_PARAMS_WGSL,
};
use rtc_runtime::image_out::LinearImage;

const KERNEL: &str = "
@group(0) @binding(0) var<uniform> tile: TileParams;
@group(0) @binding(1) var<storage, read_write> acc: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> big: array<u32>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if any(gid.xy >= tile.extent) { return; }
    let p = tile.origin + gid.xy;
    let i = p.y * tile.image_size.x + p.x;
    var a = f32(p.x) / f32(tile.image_size.x);
    let b = f32(p.y) / f32(tile.image_size.y) + f32(big[i % arrayLength(&big)] & 1u);
    for (var k = 0u; k < 64u; k++) { a = fma(a, b, 0.25); }
    acc[i] = acc[i] + vec4<f32>(a, b, f32(tile.frame), 1.0);
}
";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let choice: AdapterChoice = std::env::args().nth(1).unwrap_or_default().parse()?;
    println!("adapters ({}):", choice);
    for adapter in list_adapters(&choice) {
        println!("  {adapter}");
    }
    let gpu = Gpu::new(&choice)?;
    println!("chosen: {}", gpu.description());
    println!("limits: {:?}", gpu.limits());
    let t = gpu.init_timings();
    println!(
        "init: instance {:.1} ms, adapter {:.1} ms, device {:.1} ms",
        t.instance_ms, t.adapter_ms, t.device_ms
    );

    let (width, height) = (1920u32, 1080u32);
    let bindings = [
        BindingDesc::new(0, "tile", BindingKind::Uniform, 0),
        BindingDesc::new(1, "acc", BindingKind::StorageReadWrite, 16),
        BindingDesc::new(2, "big", BindingKind::StorageRead, 4),
    ];
    let kernel = create_kernel(
        &gpu,
        KernelDesc {
            label: "probe",
            source: KernelSource::Wgsl(format!("{TILE_PARAMS_WGSL}{KERNEL}").into()),
            entry_point: "main",
            bindings: &bindings,
            tile_binding: Some(0),
        },
    )?;
    let p = kernel.timings();
    println!(
        "pipeline: parse {:.2} ms, validate {:.2} ms, shader module {:.2} ms, pipeline {:.2} ms",
        p.parse_ms, p.validate_ms, p.shader_module_ms, p.pipeline_ms
    );

    let mut set = BufferSet::new(&gpu, "probe");
    let big: Vec<u32> = (0..16u32 << 20).collect();
    for round in 0..2 {
        set.begin_frame();
        set.upload(&gpu, &bindings[2], bytemuck::cast_slice(&big))?;
        set.ensure_zeroed(&gpu, &bindings[1], u64::from(width * height) * 16)?;
        let s = set.stats();
        println!(
            "upload round {round}: {} bytes in {:.1} ms (CPU side: hash + staging)",
            s.bytes_uploaded, s.upload_ms
        );
    }

    let mut dispatcher = TileDispatcher::default();
    for config in [
        TileConfig::for_adapter(gpu.description()),
        TileConfig::default(),
        TileConfig {
            tile_width: 128,
            tile_height: 128,
            tiles_per_batch: 4,
        },
        TileConfig {
            tile_width: width,
            tile_height: height,
            tiles_per_batch: 1,
        },
    ] {
        dispatcher.set_config(config);
        for frame in 0..3 {
            let report =
                dispatcher.dispatch(&gpu, &kernel, &set, [width, height], frame, &mut |_, _| {})?;
            println!(
                "dispatch {}x{} tiles, batch {}: frame {frame}: {} tiles, {} batches, flush {:.1} ms, dispatch {:.1} ms",
                config.tile_width, config.tile_height, config.tiles_per_batch,
                report.tiles, report.batches, report.flush_ms, report.dispatch_ms
            );
        }
    }

    let start = Instant::now();
    let acc = read_vec4_f32(&gpu, &set, 1)?;
    println!(
        "read-back of {} bytes: {:.1} ms",
        acc.len() * 16,
        start.elapsed().as_secs_f64() * 1e3
    );
    let image = LinearImage::from_accumulation(width, height, &acc)?;
    println!(
        "pixel (1919, 1079) = {:?}",
        image.get(width - 1, height - 1)
    );
    Ok(())
}
