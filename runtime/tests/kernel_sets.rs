//! Kernel sets ([`Gpu::create_kernels`]) on a real adapter (skipped, saying so, where none exists):
//! reuse across sets counted by the pipeline-creation counters (an edit to one kernel recompiles
//! only that kernel), results in order with one failure not stopping the others, the on-disk
//! pipeline cache written and read by a second `Gpu` (or reported as unsupported where the driver
//! keeps nothing in it, as lavapipe does), and a corrupt cache file ignored with a warning.
//!
//! Each test uses its own `Gpu`, so the per-`Gpu` counter is exact while other tests run; the
//! process-wide counter is only checked to have grown at least as much.

mod common;

use common::{gpu_or_skip, gpu_with_or_skip, temp_dir};
use rtc_runtime::gpu::{
    pipelines_created, BindingDesc, BindingKind, Gpu, GpuOptions, KernelDesc, KernelOrigin,
    KernelSource, PipelineCacheConfig, PipelineCacheStatus, PipelineError,
};
use std::path::Path;

/// A small kernel; `factor` makes distinct modules.
fn wgsl(factor: f32) -> String {
    format!(
        "@group(0) @binding(0) var<storage, read_write> data: array<f32>;\n\
         @compute @workgroup_size(64)\n\
         fn main(@builtin(global_invocation_id) id: vec3<u32>) {{\n\
             if id.x < arrayLength(&data) {{ data[id.x] = data[id.x] * {factor:?}; }}\n\
         }}\n"
    )
}

fn bindings() -> Vec<BindingDesc> {
    vec![BindingDesc::new(
        0,
        "data",
        BindingKind::StorageReadWrite,
        4,
    )]
}

fn desc<'a>(label: &'a str, text: String, bindings: &'a [BindingDesc]) -> KernelDesc<'a> {
    KernelDesc {
        label,
        source: KernelSource::Wgsl(text.into()),
        entry_point: "main",
        bindings,
        tile_binding: None,
    }
}

/// Two "materials" and a shared "traversal" kernel; the second set edits one material.
#[test]
fn an_edit_recompiles_only_the_kernels_that_contain_it() {
    let Some(gpu) = gpu_or_skip("an_edit_recompiles_only_the_kernels_that_contain_it") else {
        return;
    };
    let b = bindings();
    let global_before = pipelines_created();
    let first = gpu.create_kernels(vec![
        desc("traverse", wgsl(1.5), &b),
        desc("shade lambert", wgsl(2.5), &b),
        desc("shade mirror", wgsl(3.5), &b),
    ]);
    assert_eq!(first.len(), 3);
    for k in &first {
        let k = k.as_ref().expect("valid kernel");
        assert_eq!(k.origin(), KernelOrigin::Compiled, "{}", k.label());
        // The driver was involved: a pipeline and its warm-up dispatch.
        assert!(k.report().timings.pipeline_ms > 0.0, "{:?}", k.report());
        assert!(k.report().warm_up_ms > 0.0, "{:?}", k.report());
    }
    assert_eq!(gpu.pipelines_created(), 3);

    // The mirror's code changed; the traversal and Lambert kernels did not.
    let second = gpu.create_kernels(vec![
        desc("traverse", wgsl(1.5), &b),
        desc("shade lambert", wgsl(2.5), &b),
        desc("shade mirror", wgsl(4.5), &b),
    ]);
    let origins: Vec<(String, KernelOrigin)> = second
        .iter()
        .map(|k| {
            let k = k.as_ref().expect("valid kernel");
            (k.label().to_string(), k.origin())
        })
        .collect();
    assert_eq!(
        origins,
        [
            ("traverse".to_string(), KernelOrigin::MemoryCache),
            ("shade lambert".to_string(), KernelOrigin::MemoryCache),
            ("shade mirror".to_string(), KernelOrigin::Compiled),
        ]
    );
    assert_eq!(
        gpu.pipelines_created(),
        4,
        "one changed kernel, one pipeline"
    );
    let reused = second[0].as_ref().expect("valid").report();
    assert_eq!(reused.timings.pipeline_ms, 0.0);
    assert_eq!(reused.warm_up_ms, 0.0);
    assert_eq!(reused.driver_ms(), 0.0);
    // The reused kernel is the same pipeline object.
    assert_eq!(
        first[0].as_ref().expect("valid").pipeline(),
        second[0].as_ref().expect("valid").pipeline()
    );
    assert!(pipelines_created() >= global_before + 4);
}

/// Results come back in order; a bad kernel is an error in its slot only.
#[test]
fn one_failure_does_not_stop_the_set() {
    let Some(gpu) = gpu_or_skip("one_failure_does_not_stop_the_set") else {
        return;
    };
    let b = bindings();
    let set = gpu.create_kernels(vec![
        desc("good one", wgsl(5.5), &b),
        desc("broken", "fn main( {".to_string(), &b),
        desc("good two", wgsl(6.5), &b),
        desc("undeclared", wgsl(7.5), &[]),
    ]);
    assert_eq!(set.len(), 4);
    assert_eq!(set[0].as_ref().expect("valid").label(), "good one");
    assert!(matches!(&set[1], Err(PipelineError::Parse { label, .. }) if label == "broken"));
    assert_eq!(set[2].as_ref().expect("valid").label(), "good two");
    assert!(
        matches!(&set[3], Err(PipelineError::UndeclaredBinding { label, binding: 0, .. }) if label == "undeclared")
    );
    assert_eq!(gpu.pipelines_created(), 2);
    assert!(gpu.create_kernels(Vec::new()).is_empty());
}

fn cached_gpu(test: &str, dir: &Path) -> Option<Gpu> {
    gpu_with_or_skip(
        test,
        &GpuOptions {
            pipeline_cache: PipelineCacheConfig::Dir(dir.to_path_buf()),
        },
    )
}

/// The cache file of `dir` (exactly one).
fn cache_file(dir: &Path) -> std::path::PathBuf {
    let files: Vec<_> = std::fs::read_dir(dir)
        .expect("the cache folder exists")
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    assert_eq!(
        files.len(),
        1,
        "one cache file, no temporary left: {files:?}"
    );
    files.into_iter().next().expect("one file")
}

/// A second `Gpu` reads what the first wrote. Where the driver keeps pipelines in its cache the
/// kernel comes from the disk cache; where it keeps nothing (lavapipe) the status says so and
/// the kernel is compiled.
#[test]
fn the_disk_cache_is_written_and_read_by_a_second_gpu() {
    let dir = temp_dir("kernel_sets", "disk");
    let Some(gpu) = cached_gpu("the_disk_cache_is_written_and_read_by_a_second_gpu", &dir) else {
        return;
    };
    let b = bindings();
    let status = gpu.pipeline_cache_status();
    if let PipelineCacheStatus::Unsupported { reason } = &status {
        // Not Vulkan: nothing is written.
        assert!(!reason.contains("keeps no pipelines"), "{reason}");
        assert!(!dir.exists() || std::fs::read_dir(&dir).expect("dir").next().is_none());
        eprintln!("the adapter has no pipeline cache: {reason}");
        return;
    }
    assert!(
        matches!(&status, PipelineCacheStatus::Active { kernels: 0, .. }),
        "{status:?}"
    );
    let first = gpu.create_kernels(vec![desc("cached", wgsl(8.5), &b)]);
    assert_eq!(
        first[0].as_ref().expect("valid").origin(),
        KernelOrigin::Compiled
    );
    let file = cache_file(&dir);
    let bytes = std::fs::read(&file).expect("readable");
    assert_eq!(&bytes[..8], b"RTCPIPE1");
    assert!(gpu.take_warnings().is_empty());
    drop(first);
    drop(gpu);

    let second = cached_gpu("second gpu", &dir).expect("the adapter is still there");
    assert!(second.take_warnings().is_empty());
    let set = second.create_kernels(vec![desc("cached", wgsl(8.5), &b)]);
    let kernel = set[0].as_ref().expect("valid");
    match second.pipeline_cache_status() {
        PipelineCacheStatus::Active { kernels, bytes, .. } => {
            assert_eq!(kernels, 1);
            assert!(bytes > 0);
            assert_eq!(kernel.origin(), KernelOrigin::DiskCache);
        }
        PipelineCacheStatus::Unsupported { reason } => {
            assert!(reason.contains("keeps no pipelines"), "{reason}");
            assert_eq!(kernel.origin(), KernelOrigin::Compiled);
        }
        PipelineCacheStatus::Off => panic!("the cache was configured"),
    }
    assert_eq!(second.pipelines_created(), 1);
}

/// A damaged cache file (a flipped byte, a cut, garbage) is ignored with a warning naming it; the
/// kernels are created all the same and the next write replaces the file.
#[test]
fn a_corrupt_cache_file_is_ignored_with_a_warning() {
    let dir = temp_dir("kernel_sets", "corrupt");
    let Some(gpu) = cached_gpu("a_corrupt_cache_file_is_ignored_with_a_warning", &dir) else {
        return;
    };
    if matches!(
        gpu.pipeline_cache_status(),
        PipelineCacheStatus::Unsupported { .. }
    ) {
        eprintln!("the adapter has no pipeline cache; nothing to corrupt");
        return;
    }
    let b = bindings();
    assert!(gpu.create_kernels(vec![desc("damaged", wgsl(9.5), &b)])[0].is_ok());
    drop(gpu);
    let file = cache_file(&dir);
    let good = std::fs::read(&file).expect("readable");

    let mut flipped = good.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 0x40;
    let damages: [(&str, Vec<u8>); 3] = [
        ("flipped", flipped),
        ("cut", good[..good.len() / 2].to_vec()),
        ("garbage", b"not a cache at all".to_vec()),
    ];
    for (what, bytes) in damages {
        std::fs::write(&file, &bytes).expect("write the damaged file");
        let gpu = cached_gpu(what, &dir).expect("the adapter is still there");
        let warnings = gpu.take_warnings();
        assert_eq!(warnings.len(), 1, "{what}: {warnings:?}");
        assert!(
            warnings[0].starts_with("ignoring the pipeline cache")
                && warnings[0].contains(&file.display().to_string()),
            "{what}: {warnings:?}"
        );
        let set = gpu.create_kernels(vec![desc("damaged", wgsl(9.5), &b)]);
        assert_eq!(
            set[0].as_ref().expect("created all the same").origin(),
            KernelOrigin::Compiled,
            "{what}"
        );
        let rewritten = std::fs::read(&file).expect("rewritten");
        assert_eq!(
            &rewritten[..8],
            b"RTCPIPE1",
            "{what}: the next write replaces it"
        );
    }
}
