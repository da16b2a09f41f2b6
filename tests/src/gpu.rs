//! One wgpu device for a whole test binary, and running a test kernel on it.
//!
//! This file is compiled into the GPU test targets (`#[path = "src/gpu.rs"] mod gpu;` in `diff.rs`),
//! not into the `rtc_tests` library: wgpu is a dev-dependency, so the library stays GPU-free and the
//! other suites do not build wgpu.
//!
//! The device is created once, on first use ([`gpu`]), from the environment (`WGPU_BACKEND`,
//! `WGPU_ADAPTER_NAME`) with the default adapter request, which picks Mesa's lavapipe on a machine
//! without a GPU. `None` means no adapter exists at all: the GPU suites then print that they skipped.
//!
//! `RTC_DIFF_SOURCE=wgsl` makes the kernels go through naga's WGSL text instead of being handed to
//! wgpu as IR (`WGPU_BACKEND=gl` runs them through naga's GLSL instead of SPIR-V).
//!
//! Invariants: every wgpu call that can fail is inside a validation error scope (errors are returned,
//! never raised through wgpu's default handler, which panics); [`Gpu::run`] maps the output buffer
//! only after the queue is idle.

use rtc_compiler::lower::testgen::{TestKernel, ENTRY_POINT, WORKGROUP_SIZE};
use rtc_tests::difftest::Executor;
use std::borrow::Cow;
use std::sync::OnceLock;

/// The shared device.
pub struct Gpu {
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// What it is (`llvmpipe …` for lavapipe).
    pub info: wgpu::AdapterInfo,
}

/// The device of this test binary, created on first use; `None` if there is no adapter at all.
pub fn gpu() -> Option<&'static Gpu> {
    static GPU: OnceLock<Option<Gpu>> = OnceLock::new();
    GPU.get_or_init(|| {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter =
            pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
                .ok()?;
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("rtc differential tests"),
            required_features: wgpu::Features::empty(),
            required_limits: wgpu::Limits::default(),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&descriptor)).ok()?;
        Some(Gpu {
            device,
            queue,
            info: adapter.get_info(),
        })
    })
    .as_ref()
}

impl Gpu {
    /// Runs the compute entry point `entry` of `source` (workgroup size `workgroup` along x) once per input
    /// element: binding 0 holds `input` (`count` elements), binding 1 receives `count` elements of
    /// `output_stride` bytes, which are returned.
    pub fn run(
        &self,
        source: wgpu::ShaderSource<'static>,
        entry: &str,
        workgroup: u32,
        input: &[u8],
        count: u32,
        output_stride: u32,
    ) -> Result<Vec<u8>, String> {
        use wgpu::util::DeviceExt;
        let d = &self.device;
        let scope = d.push_error_scope(wgpu::ErrorFilter::Validation);
        let shader = d.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(entry),
            source,
        });
        let pipeline = d.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: None,
            module: &shader,
            entry_point: Some(entry),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        });
        let input_buf = d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("input"),
            contents: input,
            usage: wgpu::BufferUsages::STORAGE,
        });
        let out_size = u64::from(count) * u64::from(output_stride);
        let output_buf = d.create_buffer(&wgpu::BufferDescriptor {
            label: Some("output"),
            size: out_size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = d.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: out_size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = d.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output_buf.as_entire_binding(),
                },
            ],
        });
        let mut encoder = d.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(count.div_ceil(workgroup), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output_buf, 0, &readback, 0, out_size);
        self.queue.submit([encoder.finish()]);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("wgpu: {e}"));
        }
        let slice = readback.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        d.poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| format!("poll: {e}"))?;
        let data = slice
            .get_mapped_range()
            .map_err(|e| format!("map: {e}"))?
            .to_vec();
        readback.unmap();
        Ok(data)
    }
}

impl Executor for Gpu {
    fn name(&self) -> String {
        format!(
            "{} ({:?}, {})",
            self.info.name, self.info.backend, self.info.driver_info
        )
    }

    fn run(&self, kernel: TestKernel, input: &[u8], count: u32) -> Result<Vec<u8>, String> {
        let stride = kernel.output.stride;
        let source = if std::env::var("RTC_DIFF_SOURCE").is_ok_and(|v| v == "wgsl") {
            // The WGSL text naga writes for the module, parsed again by wgpu: checks the WGSL
            // writer's output too (otherwise wgpu takes the IR as is).
            let bytes = rtc_compiler::back::write(
                &kernel.module,
                rtc_compiler::back::Target::Wgsl,
                ENTRY_POINT,
                &TestKernel::resources(),
            )
            .map_err(|e| e.to_string())?;
            let text = String::from_utf8(bytes).map_err(|e| e.to_string())?;
            wgpu::ShaderSource::Wgsl(Cow::Owned(text))
        } else {
            wgpu::ShaderSource::Naga(Cow::Owned(kernel.module))
        };
        Gpu::run(
            self,
            source,
            ENTRY_POINT,
            WORKGROUP_SIZE,
            input,
            count,
            stride,
        )
    }
}
