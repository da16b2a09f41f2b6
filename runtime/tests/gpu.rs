//! GPU tests of the runtime's core on whatever adapter exists (lavapipe on CI, `WGPU_BACKEND=gl`
//! for llvmpipe): exact round trips from WGSL text and from a naga module, tiled dispatch
//! coverage, buffer re-upload statistics, limit errors, and typed errors instead of panics.
//!
//! A test skips only when there is no adapter at all, and then says so on stderr.

mod common;

use common::gpu_or_skip;
use rtc_runtime::gpu::{
    create_kernel, dispatch_once, list_adapters, read_buffer, read_vec4_f32, AdapterChoice,
    AdapterError, BindingDesc, BindingKind, BufferError, BufferLimits, BufferSet, DispatchError,
    Gpu, KernelDesc, KernelSource, PipelineError, TileConfig, TileDispatcher, UploadOutcome,
    TILE_PARAMS_WGSL,
};
use rtc_runtime::image_out::LinearImage;

const ROUND_TRIP_WGSL: &str = "
struct Params { scale: f32, offset: u32, count: u32, pad: u32 }
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> input: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> output: array<vec4<f32>>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if i >= params.count { return; }
    output[i] = input[i] * params.scale + vec4<f32>(f32(i + params.offset), -f32(i), 0.5, 1.0);
}
";

const COUNT: u32 = 1000;

fn round_trip_bindings() -> Vec<BindingDesc> {
    vec![
        BindingDesc::new(0, "params", BindingKind::Uniform, 16),
        BindingDesc::new(1, "input", BindingKind::StorageRead, 16),
        BindingDesc::new(2, "output", BindingKind::StorageReadWrite, 16),
    ]
}

/// Runs the round-trip kernel from `source` and checks every value exactly.
fn round_trip(gpu: &Gpu, source: KernelSource<'_>) {
    let bindings = round_trip_bindings();
    let kernel = create_kernel(
        gpu,
        KernelDesc {
            label: "round trip",
            source,
            entry_point: "main",
            bindings: &bindings,
            tile_binding: None,
        },
    )
    .expect("kernel");
    eprintln!("pipeline timings: {:?}", kernel.timings());
    assert_eq!(kernel.workgroup_size(), [64, 1, 1]);

    let mut set = BufferSet::new(gpu, "round trip");
    let params: [u32; 4] = [2.0f32.to_bits(), 7, COUNT, 0];
    set.upload(gpu, &bindings[0], bytemuck::cast_slice(&params))
        .expect("params");
    let input: Vec<[f32; 4]> = (0..COUNT)
        .map(|i| [i as f32 * 0.25, 1.0, 2.0, -3.0])
        .collect();
    set.upload(gpu, &bindings[1], bytemuck::cast_slice(&input))
        .expect("input");
    set.ensure_zeroed(gpu, &bindings[2], u64::from(COUNT) * 16)
        .expect("output");

    let ms = dispatch_once(gpu, &kernel, &set, [COUNT.div_ceil(64), 1, 1]).expect("dispatch");
    eprintln!("dispatch: {ms:.3} ms");
    let out = read_vec4_f32(gpu, &set, 2).expect("read back");
    assert_eq!(out.len(), COUNT as usize);
    for (i, got) in out.iter().enumerate() {
        let f = i as f32;
        let want = [f * 0.5 + f + 7.0, 2.0 - f, 4.5, -5.0];
        assert_eq!(*got, want, "element {i}");
    }
    assert!(gpu.take_uncaptured_errors().is_empty());
}

#[test]
fn wgsl_round_trip_is_exact() {
    let Some(gpu) = gpu_or_skip("wgsl_round_trip_is_exact") else {
        return;
    };
    eprintln!("init timings: {:?}", gpu.init_timings());
    round_trip(&gpu, KernelSource::Wgsl(ROUND_TRIP_WGSL.into()));
}

#[test]
fn naga_module_round_trip_is_exact() {
    let Some(gpu) = gpu_or_skip("naga_module_round_trip_is_exact") else {
        return;
    };
    let module = naga::front::wgsl::parse_str(ROUND_TRIP_WGSL).expect("test WGSL parses");
    round_trip(&gpu, KernelSource::Naga(Box::new(module)));
}

const TILED_WGSL: &str = "
@group(0) @binding(0) var<uniform> tile: TileParams;
@group(0) @binding(1) var<storage, read_write> acc: array<vec4<f32>>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if any(gid.xy >= tile.extent) { return; }
    let p = tile.origin + gid.xy;
    let i = p.y * tile.image_size.x + p.x;
    acc[i] = acc[i] + vec4<f32>(f32(p.x), f32(p.y), f32(tile.tile_index * 100u + tile.frame), 1.0);
}
";

#[test]
fn tiled_dispatch_covers_an_odd_image_exactly_once() {
    let Some(gpu) = gpu_or_skip("tiled_dispatch_covers_an_odd_image_exactly_once") else {
        return;
    };
    let (width, height) = (37u32, 23u32);
    let pixels = (width * height) as usize;
    let bindings = [
        BindingDesc::new(0, "tile", BindingKind::Uniform, 0),
        BindingDesc::new(1, "acc", BindingKind::StorageReadWrite, 16),
    ];
    let source = format!("{TILE_PARAMS_WGSL}{TILED_WGSL}");
    let kernel = create_kernel(
        &gpu,
        KernelDesc {
            label: "tiled",
            source: KernelSource::Wgsl(source.into()),
            entry_point: "main",
            bindings: &bindings,
            tile_binding: Some(0),
        },
    )
    .expect("kernel");

    // Five sentinel pixels after the image catch any write outside it.
    let mut initial = vec![[0f32; 4]; pixels];
    initial.extend([[-1f32; 4]; 5]);
    let mut set = BufferSet::new(&gpu, "tiled");
    set.upload(&gpu, &bindings[1], bytemuck::cast_slice(&initial))
        .expect("acc");

    let config = TileConfig {
        tile_width: 16,
        tile_height: 16,
        tiles_per_batch: 4,
    };
    let mut dispatcher = TileDispatcher::new(config);
    for frame in 0..2u32 {
        let mut calls = Vec::new();
        let report = dispatcher
            .dispatch(
                &gpu,
                &kernel,
                &set,
                [width, height],
                frame,
                &mut |done, total| calls.push((done, total)),
            )
            .expect("tiled dispatch");
        assert_eq!((report.tiles, report.batches), (6, 2));
        assert_eq!(calls, [(0, 6), (4, 6), (6, 6)]);
        eprintln!("frame {frame}: {report:?}");
    }

    let acc = read_vec4_f32(&gpu, &set, 1).expect("read back");
    assert_eq!(acc.len(), pixels + 5);
    for y in 0..height {
        for x in 0..width {
            let tile = (y / 16) * 3 + x / 16;
            // Two frames: sums of (x, y, tile*100 + frame) for frames 0 and 1, two samples.
            let want = [2.0 * x as f32, 2.0 * y as f32, (200 * tile + 1) as f32, 2.0];
            assert_eq!(acc[(y * width + x) as usize], want, "pixel ({x}, {y})");
        }
    }
    assert!(acc[pixels..].iter().all(|p| *p == [-1.0; 4]), "sentinels");

    let image = LinearImage::from_accumulation(width, height, &acc).expect("resolve");
    assert_eq!(image.get(36, 22), Some([36.0, 22.0, 500.5, 1.0]));
}

#[test]
fn buffer_set_reuploads_only_what_changed() {
    let Some(gpu) = gpu_or_skip("buffer_set_reuploads_only_what_changed") else {
        return;
    };
    let nodes = BindingDesc::new(1, "nodes", BindingKind::StorageRead, 0);
    let camera = BindingDesc::new(0, "camera", BindingKind::Uniform, 0);
    let prims = BindingDesc::new(2, "prims", BindingKind::StorageRead, 0);
    let mut a: Vec<u8> = (0..1000u32).map(|i| (i % 251) as u8).collect();
    let cam = [1u8; 16];
    let c = vec![7u8; 4096];

    let mut set = BufferSet::new(&gpu, "stats");
    set.begin_frame();
    assert_eq!(set.upload(&gpu, &nodes, &a), Ok(UploadOutcome::Reallocated));
    assert_eq!(
        set.upload(&gpu, &camera, &cam),
        Ok(UploadOutcome::Reallocated)
    );
    assert_eq!(
        set.upload_generation(&gpu, &prims, &c, 1),
        Ok(UploadOutcome::Reallocated)
    );
    let s = set.stats();
    assert_eq!(s.bytes_uploaded, 1000 + 16 + 4096);
    assert_eq!((s.buffers_uploaded, s.buffers_allocated), (3, 3));

    // Nothing changed: nothing is uploaded.
    set.begin_frame();
    assert_eq!(set.upload(&gpu, &nodes, &a), Ok(UploadOutcome::Unchanged));
    assert_eq!(
        set.upload(&gpu, &camera, &cam),
        Ok(UploadOutcome::Unchanged)
    );
    assert_eq!(
        set.upload_generation(&gpu, &prims, &c, 1),
        Ok(UploadOutcome::Unchanged)
    );
    let s = set.stats();
    assert_eq!(s.bytes_uploaded, 0);
    assert_eq!((s.buffers_unchanged, s.buffers_allocated), (3, 0));

    // One byte changes: that buffer alone is re-uploaded, in place.
    set.begin_frame();
    a[500] ^= 0xff;
    assert_eq!(set.upload(&gpu, &nodes, &a), Ok(UploadOutcome::Uploaded));
    assert_eq!(
        set.upload(&gpu, &camera, &cam),
        Ok(UploadOutcome::Unchanged)
    );
    // A generation counter is trusted: same generation, no upload, even with new bytes.
    let c2 = vec![9u8; 4096];
    assert_eq!(
        set.upload_generation(&gpu, &prims, &c2, 1),
        Ok(UploadOutcome::Unchanged)
    );
    assert_eq!(set.stats().bytes_uploaded, 1000);
    assert_eq!(
        set.upload_generation(&gpu, &prims, &c2, 2),
        Ok(UploadOutcome::Uploaded)
    );
    assert_eq!(set.stats().bytes_uploaded, 1000 + 4096);
    assert_eq!(set.stats().buffers_allocated, 0);

    // Growing reallocates; shrinking reuses the buffer and binds the smaller size.
    set.begin_frame();
    let big = vec![3u8; 2000];
    assert_eq!(
        set.upload(&gpu, &nodes, &big),
        Ok(UploadOutcome::Reallocated)
    );
    let small = vec![5u8; 502];
    assert_eq!(
        set.upload(&gpu, &nodes, &small),
        Ok(UploadOutcome::Uploaded)
    );
    assert_eq!(set.bound_size(1), Some(504));
    assert_eq!(set.allocated_bytes(), 2000 + 16 + 4096);
    let s = set.stats();
    assert_eq!((s.buffers_allocated, s.bytes_allocated), (1, 2000));
    assert_eq!(s.bytes_uploaded, 2000 + 504);

    // The bytes really arrived.
    let buffer = set.buffer(1).expect("nodes buffer");
    assert_eq!(read_buffer(&gpu, buffer, 502).expect("read"), small);
    let prims_buffer = set.buffer(2).expect("prims buffer");
    assert_eq!(read_buffer(&gpu, prims_buffer, 4096).expect("read"), c2);

    // Clearing zero-fills on the GPU.
    set.clear(&gpu, 1).expect("clear");
    assert_eq!(
        read_buffer(&gpu, set.buffer(1).expect("nodes"), 502).expect("read"),
        vec![0u8; 502]
    );
}

/// A binding whose minimum size is above its data (as a uniform table's 64 KiB is): a new
/// buffer, zeroed by wgpu, gets only the data; a shorter upload zeroes what the longer one left
/// and writes nothing beyond it; the bound size stays the minimum.
#[test]
fn the_padding_of_a_large_minimum_is_not_uploaded() {
    let Some(gpu) = gpu_or_skip("the_padding_of_a_large_minimum_is_not_uploaded") else {
        return;
    };
    let table = BindingDesc::new(3, "table", BindingKind::StorageRead, 4096);
    let mut set = BufferSet::new(&gpu, "padding");
    set.begin_frame();
    assert_eq!(
        set.upload(&gpu, &table, &[1u8; 256]),
        Ok(UploadOutcome::Reallocated)
    );
    assert_eq!(set.stats().bytes_uploaded, 256);
    assert_eq!(set.bound_size(3), Some(4096));
    set.begin_frame();
    assert_eq!(
        set.upload(&gpu, &table, &[2u8; 62]),
        Ok(UploadOutcome::Uploaded)
    );
    assert_eq!(
        set.stats().bytes_uploaded,
        256,
        "62 bytes, then zeros up to 256"
    );
    let mut want = vec![2u8; 62];
    want.resize(4096, 0);
    assert_eq!(
        read_buffer(&gpu, set.buffer(3).expect("table"), 4096).expect("read"),
        want
    );
    set.begin_frame();
    assert_eq!(
        set.upload(&gpu, &table, &[3u8; 8]),
        Ok(UploadOutcome::Uploaded)
    );
    assert_eq!(
        set.stats().bytes_uploaded,
        64,
        "8 bytes, then zeros up to 64"
    );
}

#[test]
fn oversized_data_is_a_typed_error_naming_the_binding() {
    let Some(gpu) = gpu_or_skip("oversized_data_is_a_typed_error_naming_the_binding") else {
        return;
    };
    let mut set = BufferSet::new(&gpu, "tiny").with_limits(BufferLimits {
        max_storage_buffer_binding_size: 256,
        max_uniform_buffer_binding_size: 64,
        max_buffer_size: 1 << 20,
    });
    let nodes = BindingDesc::new(3, "nodes", BindingKind::StorageRead, 0);
    assert_eq!(
        set.upload(&gpu, &nodes, &[0u8; 256]),
        Ok(UploadOutcome::Reallocated)
    );
    let error = set
        .upload(&gpu, &nodes, &[0u8; 257])
        .expect_err("over the limit");
    assert_eq!(
        error,
        BufferError::TooLarge {
            binding: 3,
            name: "nodes".into(),
            size: 257,
            limit: 256,
            limit_name: "max_storage_buffer_binding_size",
        }
    );
    let text = error.to_string();
    for needle in [
        "binding 3",
        "`nodes`",
        "257",
        "256",
        "max_storage_buffer_binding_size",
    ] {
        assert!(text.contains(needle), "{needle:?} missing in {text:?}");
    }
    // The old contents stay bound; nothing was uploaded.
    assert_eq!(set.bound_size(3), Some(256));

    let camera = BindingDesc::new(0, "camera", BindingKind::Uniform, 0);
    assert!(matches!(
        set.upload(&gpu, &camera, &[0u8; 80]),
        Err(BufferError::TooLarge { limit: 64, .. })
    ));
    assert!(set.buffer(0).is_none());
    let acc = BindingDesc::new(4, "acc", BindingKind::StorageReadWrite, 0);
    assert!(matches!(
        set.ensure_zeroed(&gpu, &acc, 1024),
        Err(BufferError::TooLarge { size: 1024, .. })
    ));

    // The device got the adapter's own limits, not wgpu's defaults.
    let limits = gpu.limits();
    let adapter = gpu.adapter().limits();
    eprintln!("limits: {limits:?}");
    assert_eq!(
        limits.max_storage_buffer_binding_size,
        adapter.max_storage_buffer_binding_size
    );
    assert_eq!(limits.max_buffer_size, adapter.max_buffer_size);
    assert_eq!(
        limits.max_storage_buffers_per_shader_stage,
        adapter.max_storage_buffers_per_shader_stage
    );
    assert_eq!(
        BufferLimits::of(&gpu).max_buffer_size,
        adapter.max_buffer_size
    );
}

fn kernel_error(
    gpu: &Gpu,
    source: &str,
    bindings: &[BindingDesc],
    tile: Option<u32>,
) -> PipelineError {
    create_kernel(
        gpu,
        KernelDesc {
            label: "bad",
            source: KernelSource::Wgsl(source.into()),
            entry_point: "main",
            bindings,
            tile_binding: tile,
        },
    )
    .expect_err("kernel creation must fail")
}

#[test]
fn bad_kernels_are_typed_errors() {
    let Some(gpu) = gpu_or_skip("bad_kernels_are_typed_errors") else {
        return;
    };
    let good = round_trip_bindings();
    let e = kernel_error(&gpu, "fn main( {", &good, None);
    assert!(matches!(e, PipelineError::Parse { .. }), "{e}");

    let e = kernel_error(&gpu, ROUND_TRIP_WGSL, &good[..2], None);
    assert!(
        matches!(e, PipelineError::UndeclaredBinding { binding: 2, ref name, .. } if name == "output"),
        "{e}"
    );

    let mut wrong = good.clone();
    wrong[2].kind = BindingKind::StorageRead;
    let e = kernel_error(&gpu, ROUND_TRIP_WGSL, &wrong, None);
    assert!(
        matches!(e, PipelineError::KindMismatch { binding: 2, .. }),
        "{e}"
    );

    let mut dup = good.clone();
    dup[1].binding = 0;
    let e = kernel_error(&gpu, ROUND_TRIP_WGSL, &dup, None);
    assert!(
        matches!(e, PipelineError::DuplicateBinding { binding: 0, .. }),
        "{e}"
    );

    let e = kernel_error(&gpu, ROUND_TRIP_WGSL, &good, Some(1));
    assert!(
        matches!(e, PipelineError::BadTileBinding { binding: 1, .. }),
        "{e}"
    );

    let e = kernel_error(
        &gpu,
        &ROUND_TRIP_WGSL.replace("fn main", "fn other"),
        &good,
        None,
    );
    assert!(matches!(e, PipelineError::MissingEntryPoint { .. }), "{e}");

    // wgpu's own validation (min_binding_size below the shader's 16-byte struct) is caught by
    // the error scopes instead of panicking.
    let mut small = good.clone();
    small[0].min_size = 4;
    let e = kernel_error(&gpu, ROUND_TRIP_WGSL, &small, None);
    assert!(
        matches!(
            e,
            PipelineError::Wgpu {
                stage: "compute pipeline",
                ..
            }
        ),
        "{e}"
    );
    assert!(gpu.take_uncaptured_errors().is_empty());
}

#[test]
fn dispatch_misuse_is_a_typed_error() {
    let Some(gpu) = gpu_or_skip("dispatch_misuse_is_a_typed_error") else {
        return;
    };
    let bindings = round_trip_bindings();
    let kernel = create_kernel(
        &gpu,
        KernelDesc {
            label: "round trip",
            source: KernelSource::Wgsl(ROUND_TRIP_WGSL.into()),
            entry_point: "main",
            bindings: &bindings,
            tile_binding: None,
        },
    )
    .expect("kernel");
    let mut set = BufferSet::new(&gpu, "partial");
    let e = dispatch_once(&gpu, &kernel, &set, [1, 1, 1]).expect_err("no buffers");
    assert!(
        matches!(
            e,
            DispatchError::Buffer(BufferError::Missing { binding: 0, .. })
        ),
        "{e}"
    );
    let e = TileDispatcher::new(TileConfig::default())
        .dispatch(&gpu, &kernel, &set, [8, 8], 0, &mut |_, _| {})
        .expect_err("no tile binding");
    assert!(matches!(e, DispatchError::NoTileBinding { .. }), "{e}");
    let empty_tiles = TileConfig {
        tile_width: 0,
        ..TileConfig::default()
    };
    let e = TileDispatcher::new(empty_tiles)
        .dispatch(&gpu, &kernel, &set, [8, 8], 0, &mut |_, _| {})
        .expect_err("zero-width tiles");
    assert!(matches!(e, DispatchError::BadTileConfig { .. }), "{e}");

    // A storage buffer where the kernel wants a uniform.
    let as_storage = BindingDesc::new(0, "params", BindingKind::StorageRead, 16);
    set.upload(&gpu, &as_storage, &[0u8; 16]).expect("upload");
    set.upload(&gpu, &bindings[1], &[0u8; 16]).expect("upload");
    set.ensure_zeroed(&gpu, &bindings[2], 16).expect("alloc");
    let e = dispatch_once(&gpu, &kernel, &set, [1, 1, 1]).expect_err("wrong kind");
    assert!(
        matches!(e, DispatchError::BufferKind { binding: 0, .. }),
        "{e}"
    );

    let limit = gpu.limits().max_compute_workgroups_per_dimension;
    let e = dispatch_once(&gpu, &kernel, &set, [limit + 1, 1, 1]).expect_err("too many");
    assert!(matches!(e, DispatchError::TooManyWorkgroups { .. }), "{e}");
    assert!(gpu.take_uncaptured_errors().is_empty());
}

#[test]
fn adapter_selection_reports_and_filters() {
    let Some(gpu) = gpu_or_skip("adapter_selection_reports_and_filters") else {
        return;
    };
    let described = gpu.description().to_string();
    assert!(!gpu.description().name.is_empty());
    assert!(described.contains(&gpu.description().backend.to_string()));
    let all = list_adapters(&AdapterChoice::default());
    eprintln!("adapters:");
    for adapter in &all {
        eprintln!("  {adapter}");
    }
    assert!(all.contains(gpu.description()));

    let choice = AdapterChoice {
        name_substring: Some("no-such-adapter-anywhere".into()),
        ..AdapterChoice::default()
    };
    match Gpu::new(&choice) {
        Err(AdapterError::NoMatch { available, .. }) => assert_eq!(available.len(), all.len()),
        other => panic!("expected NoMatch, got {other:?}"),
    }

    // The chosen adapter can be chosen again by name and backend.
    let again = Gpu::new(&AdapterChoice {
        name_substring: Some(gpu.description().name.clone()),
        backend: Some(gpu.description().backend),
        force_cpu: false,
    })
    .expect("same adapter");
    assert_eq!(again.description(), gpu.description());
}

/// A kernel created again from the same module and bindings is the cached pipeline (no shader
/// module, no driver compile), and still computes the right values; a changed module or binding
/// list is compiled anew.
#[test]
fn an_unchanged_kernel_is_reused_and_a_changed_one_is_not() {
    let Some(gpu) = gpu_or_skip("an_unchanged_kernel_is_reused_and_a_changed_one_is_not") else {
        return;
    };
    let make = |wgsl: &str, bindings: &[BindingDesc]| {
        create_kernel(
            &gpu,
            KernelDesc {
                label: "cache probe",
                source: KernelSource::Wgsl(wgsl.into()),
                entry_point: "main",
                bindings,
                tile_binding: None,
            },
        )
        .expect("the probe kernel is valid")
    };
    let bindings = round_trip_bindings();
    // A module no other test creates, so the first creation below is a miss.
    let first_text = ROUND_TRIP_WGSL.replace("0.5, 1.0", "0.25, 1.0");
    let first = make(&first_text, &bindings);
    assert!(first.timings().shader_module_ms > 0.0 && first.timings().pipeline_ms > 0.0);

    let again = make(&first_text, &bindings);
    assert_eq!(
        again.timings().shader_module_ms,
        0.0,
        "{:?}",
        again.timings()
    );
    assert_eq!(again.timings().pipeline_ms, 0.0, "{:?}", again.timings());

    let changed = make(
        &ROUND_TRIP_WGSL.replace("0.5, 1.0", "0.125, 1.0"),
        &bindings,
    );
    assert!(
        changed.timings().pipeline_ms > 0.0,
        "a changed module must be compiled"
    );
    let mut other_bindings = bindings.clone();
    other_bindings[1].min_size = 32;
    let rebound = make(&first_text, &other_bindings);
    assert!(
        rebound.timings().pipeline_ms > 0.0,
        "changed bindings must be compiled"
    );

    // The reused pipeline still runs: the whole round trip through the cache.
    round_trip(&gpu, KernelSource::Wgsl(ROUND_TRIP_WGSL.into()));
    round_trip(&gpu, KernelSource::Wgsl(ROUND_TRIP_WGSL.into()));
}
