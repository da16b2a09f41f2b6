//! rtc embedded in a host wgpu application: the host owns the window, the instance, the surface,
//! the device and queue and its command encoders; rtc gets the host's device
//! ([`Gpu::from_device`]), builds one [`Renderer`] for a scene, and each frame renders into the
//! accumulation buffer, which the host resolves into a texture it owns ([`Renderer::resolve_into`],
//! recorded into the host's encoder) and draws over the window with its own fullscreen-triangle
//! pipeline. Each frame the camera orbits the scene's look-at point (`Renderer::set_field` on the
//! camera's `position`) and the objects spin in place (`Renderer::set_transform` on every object
//! but those named `floor` or `ground`: the scene-level BVH is rebuilt, no object's), then one pass
//! is added (`Renderer::accumulate(1)`), so every frame is a fresh one-sample image (a change
//! restarts the accumulation); the example prints the frame pacing.
//!
//! ```text
//! cargo run --release -p rtc-runtime --example embed -- [SCENE.rt] [--size WxH] [--frames N]
//!     [--headless] [--still] [--report-every N] [--save PNG]
//! ```
//!
//! - `SCENE.rt`: the scene (default: `examples/thesis_scene/scene.rt`, its 17 bunnies);
//! - `--size WxH`: the image size (default 320x180; the window opens at this size);
//! - `--frames N`: stop after N frames (default: until the window is closed; 60 headless);
//! - `--headless`: no window: draw into an offscreen texture, as a test or CI without a display;
//! - `--still`: move nothing: each frame adds one sample per pixel to the running accumulation
//!   (progressive refinement in the host's texture);
//! - `--report-every N`: print min/mean/max milliseconds per frame every N frames (default 10);
//! - `--save PNG`: write the last frame drawn to a PNG file (in a window, read from the surface
//!   itself when it allows copies, so it shows what the window shows).
//!
//! A frame's time covers the host's whole frame: moving the camera and the objects, the render
//! (which waits for the GPU), recording and submitting the resolve and the draw, and (headless)
//! waiting for them, so the figures are the pacing an application would see.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use glam::{Mat4, Vec3};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, CompiledScene, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::sema::hir::{ConstValue, Scalar};
use rtc_runtime::gpu::{required_limits, Gpu, GpuOptions};
use rtc_runtime::image_out::ToneMap;
use rtc_runtime::render::{FieldTarget, RenderOptions, Renderer};
use rtc_runtime::resolve::ResolveTarget;
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::window::{Window, WindowId};

/// The command line.
struct Args {
    scene: PathBuf,
    size: [u32; 2],
    frames: Option<u64>,
    headless: bool,
    report_every: u64,
    save: Option<PathBuf>,
    still: bool,
}

const USAGE: &str = "usage: embed [SCENE.rt] [--size WxH] [--frames N] [--headless] [--still] \
                     [--report-every N] [--save PNG]";

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        scene: Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/thesis_scene/scene.rt"),
        size: [320, 180],
        frames: None,
        headless: false,
        report_every: 10,
        save: None,
        still: false,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or(format!("{name} needs a value\n{USAGE}"));
        match arg.as_str() {
            "--headless" => args.headless = true,
            "--still" => args.still = true,
            "--frames" => {
                let v = value("--frames")?;
                args.frames = Some(
                    v.parse()
                        .map_err(|_| format!("--frames {v}: not a count"))?,
                );
            }
            "--report-every" => {
                let v = value("--report-every")?;
                args.report_every = v
                    .parse::<u64>()
                    .map_err(|_| format!("--report-every {v}: not a count"))?
                    .max(1);
            }
            "--size" => {
                let v = value("--size")?;
                let parsed = v
                    .split_once('x')
                    .and_then(|(w, h)| Some([w.parse().ok()?, h.parse().ok()?]))
                    .filter(|[w, h]: &[u32; 2]| *w > 0 && *h > 0);
                args.size = parsed.ok_or(format!("--size {v}: expected WxH, e.g. 320x180"))?;
            }
            "--save" => args.save = Some(PathBuf::from(value("--save")?)),
            "-h" | "--help" => return Err(USAGE.to_string()),
            flag if flag.starts_with('-') => return Err(format!("unknown option {flag}\n{USAGE}")),
            path => args.scene = PathBuf::from(path),
        }
    }
    if args.headless && args.frames.is_none() {
        args.frames = Some(60);
    }
    Ok(args)
}

/// Compiles the scene as `rtc render` does (`cli/src/cmd/render.rs`), printing its diagnostics.
fn compile(path: &Path) -> Result<CompiledScene, String> {
    let compiled = compile_scene_with(
        &[path.to_path_buf()],
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions::default(),
    )
    .map_err(|failure| {
        rtc_compiler::diag::render_human(&failure.checked.sources, &failure.diagnostics, false)
    })?;
    if !compiled.checked.diagnostics.is_empty() {
        eprint!(
            "{}",
            rtc_compiler::diag::render_human(
                &compiled.checked.sources,
                &compiled.checked.diagnostics,
                false
            )
        );
    }
    Ok(compiled)
}

/// A `vec3f` field of the scene's camera, by name.
fn camera_vec3(compiled: &CompiledScene, field: &str) -> Option<Vec3> {
    let program = compiled.checked.program.as_ref()?;
    let camera = program.scenes[compiled.scene].camera.as_ref()?;
    let index = program.structs[camera.struct_id].field_index(field)?;
    match camera.fields.get(index)? {
        ConstValue::Vector {
            len: 3,
            comps: [Scalar::F32(x), Scalar::F32(y), Scalar::F32(z), _],
        } => Some(Vec3::new(*x, *y, *z)),
        _ => None,
    }
}

/// What moves: the camera around `center`, and the objects `spinning` about their own up axis.
struct Motion {
    /// `--still`: nothing moves, and each frame adds a sample to the running accumulation.
    still: bool,
    center: Vec3,
    start: Vec3,
    spinning: Vec<(usize, Mat4)>,
}

impl Motion {
    fn new(compiled: &CompiledScene, renderer: &Renderer<'_>, still: bool) -> Motion {
        let start = camera_vec3(compiled, "position").unwrap_or(Vec3::new(0.0, 1.0, 3.0));
        let center = camera_vec3(compiled, "look_at").unwrap_or(Vec3::ZERO);
        let objects = renderer.entities().objects();
        let mut spinning: Vec<(usize, Mat4)> = objects
            .iter()
            .enumerate()
            .filter(|(_, o)| !matches!(o.name.as_deref(), Some("floor" | "ground")))
            .map(|(i, o)| (i, o.transform))
            .collect();
        if spinning.is_empty() {
            spinning.extend(objects.first().map(|o| (0, o.transform)));
        }
        Motion {
            still,
            center,
            start,
            spinning,
        }
    }

    /// Moves the camera and the objects to where they are at `frame`.
    fn apply(&self, renderer: &mut Renderer<'_>, frame: u64) -> Result<(), String> {
        let t = frame as f32;
        // A full orbit every 360 frames, a full turn of each object every 120.
        let orbit = Mat4::from_rotation_y(t.to_radians());
        let p = self.center + orbit.transform_vector3(self.start - self.center);
        let position = ConstValue::Vector {
            len: 3,
            comps: [
                Scalar::F32(p.x),
                Scalar::F32(p.y),
                Scalar::F32(p.z),
                Scalar::F32(0.0),
            ],
        };
        renderer
            .set_field(FieldTarget::Camera, "position", &position)
            .map_err(|e| e.to_string())?;
        for (i, (object, base)) in self.spinning.iter().enumerate() {
            let phase = i as f32 * 0.7;
            let spin = Mat4::from_rotation_y(t * 3.0_f32.to_radians() + phase);
            renderer
                .set_transform(*object, *base * spin)
                .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}

/// Milliseconds per frame, reported every `every` frames, with the parts rtc's figures name.
struct Pacing {
    every: u64,
    frames: u64,
    window: Vec<f64>,
    all: Vec<f64>,
    last: Option<Instant>,
    /// Over the window: the passes' GPU time, the scene-level BVH rebuilds, the uploads (ms).
    parts: [f64; 3],
    /// The last frame's accumulated samples per pixel and BLAS builds so far.
    spp: u32,
    blas_builds: u32,
}

impl Pacing {
    fn new(every: u64) -> Pacing {
        Pacing {
            every,
            frames: 0,
            window: Vec::new(),
            all: Vec::new(),
            last: None,
            parts: [0.0; 3],
            spp: 0,
            blas_builds: 0,
        }
    }

    /// Starts timing the first frame.
    fn start(&mut self) {
        self.last = Some(Instant::now());
    }

    /// Records the end of a frame (the time since the previous frame's end, or since
    /// [`Pacing::start`]).
    fn frame_done(&mut self, stats: &FrameStats) {
        self.parts[0] += stats.render_ms;
        self.parts[1] += stats.bvh_ms;
        self.parts[2] += stats.upload_ms;
        self.spp = stats.spp;
        self.blas_builds = stats.blas_builds;
        let now = Instant::now();
        if let Some(last) = self.last {
            let ms = (now - last).as_secs_f64() * 1e3;
            self.window.push(ms);
            self.all.push(ms);
        }
        self.last = Some(now);
        self.frames += 1;
        if self.window.len() as u64 >= self.every {
            let n = self.window.len() as f64;
            println!(
                "frames {:>5}: {}; means: pass {:.1} ms, scene BVH {:.2} ms, upload {:.2} ms; \
                 {} spp accumulated, {} BLAS builds",
                self.frames,
                summary(&self.window),
                self.parts[0] / n,
                self.parts[1] / n,
                self.parts[2] / n,
                self.spp,
                self.blas_builds
            );
            self.window.clear();
            self.parts = [0.0; 3];
        }
    }

    fn finish(&self) {
        if !self.all.is_empty() {
            println!("all {} frames: {}", self.frames, summary(&self.all));
        }
    }
}

fn summary(ms: &[f64]) -> String {
    let min = ms.iter().copied().fold(f64::INFINITY, f64::min);
    let max = ms.iter().copied().fold(0.0, f64::max);
    let mean = ms.iter().sum::<f64>() / ms.len().max(1) as f64;
    format!(
        "ms per frame min {min:.1} mean {mean:.1} max {max:.1} ({:.1} fps)",
        1e3 / mean
    )
}

/// What one frame's pass cost, from rtc's figures.
struct FrameStats {
    render_ms: f64,
    bvh_ms: f64,
    upload_ms: f64,
    spp: u32,
    blas_builds: u32,
}

/// The host's draw: a fullscreen triangle sampling the resolved texture.
const BLIT: &str = r"
struct Out { @builtin(position) pos: vec4f, @location(0) uv: vec2f };

@vertex
fn vs(@builtin(vertex_index) i: u32) -> Out {
    let uv = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
    var out: Out;
    out.pos = vec4f(uv * vec2f(2.0, -2.0) + vec2f(-1.0, 1.0), 0.0, 1.0);
    out.uv = uv;
    return out;
}

@group(0) @binding(0) var image: texture_2d<f32>;
@group(0) @binding(1) var nearest: sampler;

@fragment
fn fs(in: Out) -> @location(0) vec4f {
    return vec4f(textureSample(image, nearest, in.uv).rgb, 1.0);
}
";

/// Everything the host keeps per frame: the texture rtc resolves into and the blit to `format`.
struct Host {
    /// Written by the resolve (sRGB-encoded bytes in `Rgba8Unorm`).
    resolved: wgpu::Texture,
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
}

impl Host {
    fn new(device: &wgpu::Device, [width, height]: [u32; 2], format: wgpu::TextureFormat) -> Host {
        // The resolve writes sRGB-encoded bytes into an Rgba8Unorm storage texture. A sRGB target
        // re-encodes what the fragment shader returns, so it samples through an Rgba8UnormSrgb
        // view (decoding); a plain target gets the bytes as they are.
        let resolved = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("host: resolved image"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[wgpu::TextureFormat::Rgba8UnormSrgb],
        });
        let view = resolved.create_view(&wgpu::TextureViewDescriptor {
            format: Some(if format.is_srgb() {
                wgpu::TextureFormat::Rgba8UnormSrgb
            } else {
                wgpu::TextureFormat::Rgba8Unorm
            }),
            // Sampled only: an sRGB view cannot be a storage binding.
            usage: Some(wgpu::TextureUsages::TEXTURE_BINDING),
            ..wgpu::TextureViewDescriptor::default()
        });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("host: blit"),
            source: wgpu::ShaderSource::Wgsl(BLIT.into()),
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("host: blit"),
            layout: None,
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("host: nearest"),
            ..Default::default()
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("host: blit"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&sampler),
                },
            ],
        });
        Host {
            resolved,
            pipeline,
            bind_group,
        }
    }

    /// One frame: moves things, renders one sample, and records the resolve and the draw into
    /// `target` on one encoder of the host's, submitted on the host's queue.
    fn frame(
        &self,
        gpu: &Gpu,
        renderer: &mut Renderer<'_>,
        motion: &Motion,
        frame: u64,
        target: &wgpu::TextureView,
    ) -> Result<FrameStats, String> {
        if !motion.still {
            motion.apply(renderer, frame)?;
        }
        // One pass: a fresh image after the moves above, one more sample per pixel when still.
        let stats = renderer
            .accumulate(1, &mut |_, _| {})
            .map_err(|e| e.to_string())?;
        let mut encoder = gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("host: frame"),
            });
        renderer
            .resolve_into(
                ResolveTarget::Texture(&self.resolved),
                &ToneMap::default(),
                Some(&mut encoder),
            )
            .map_err(|e| e.to_string())?;
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("host: blit"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &self.bind_group, &[]);
            pass.draw(0..3, 0..1);
        }
        gpu.queue().submit([encoder.finish()]);
        Ok(FrameStats {
            render_ms: stats.render_ms,
            bvh_ms: stats.bvh_build_ms,
            upload_ms: stats.upload_ms,
            spp: renderer.accumulated_samples(),
            blas_builds: stats.blas_builds,
        })
    }
}

/// The host's device on `adapter`: rtc's required limits, with the adapter's own buffer sizes so
/// large scenes fit.
fn host_device(adapter: &wgpu::Adapter) -> Result<(wgpu::Device, wgpu::Queue), String> {
    let own = adapter.limits();
    let limits = wgpu::Limits {
        max_storage_buffer_binding_size: own.max_storage_buffer_binding_size,
        max_buffer_size: own.max_buffer_size,
        ..required_limits()
    };
    pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("host device"),
        required_limits: limits,
        ..wgpu::DeviceDescriptor::default()
    }))
    .map_err(|e| format!("no device: {e}"))
}

/// Compiles the scene and builds the renderer on the host's device (leaked: it lives as long as
/// the application).
fn setup(
    args: &Args,
    adapter: &wgpu::Adapter,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
) -> Result<(&'static Gpu, Renderer<'static>, Motion), String> {
    let start = Instant::now();
    let compiled = compile(&args.scene)?;
    let gpu = Gpu::from_device(
        adapter.clone(),
        device.clone(),
        queue.clone(),
        &GpuOptions::from_env(),
    )
    .map_err(|e| e.to_string())?;
    let gpu: &'static Gpu = Box::leak(Box::new(gpu));
    let options = RenderOptions {
        size: Some(args.size),
        ..RenderOptions::default()
    };
    let renderer = Renderer::new(gpu, &compiled, options).map_err(|e| e.to_string())?;
    let motion = Motion::new(&compiled, &renderer, args.still);
    println!(
        "{} on {}: {}x{}, {} objects ({} spinning), set up in {:.0} ms",
        args.scene.display(),
        gpu.description(),
        args.size[0],
        args.size[1],
        renderer.entities().objects().len(),
        motion.spinning.len(),
        start.elapsed().as_secs_f64() * 1e3
    );
    Ok((gpu, renderer, motion))
}

/// `--headless`: the same frames into an offscreen texture, waited for one by one.
fn run_headless(args: &Args) -> Result<(), String> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .map_err(|e| format!("no adapter: {e}"))?;
    let (device, queue) = host_device(&adapter)?;
    let (gpu, mut renderer, motion) = setup(args, &adapter, &device, &queue)?;
    let format = wgpu::TextureFormat::Rgba8UnormSrgb;
    let [width, height] = args.size;
    let offscreen = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("host: offscreen frame"),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = offscreen.create_view(&wgpu::TextureViewDescriptor::default());
    let host = Host::new(&device, args.size, format);
    let mut pacing = Pacing::new(args.report_every);
    pacing.start();
    for frame in 0..args.frames.unwrap_or(60) {
        let stats = host.frame(gpu, &mut renderer, &motion, frame, &view)?;
        gpu.wait_idle().map_err(|e| e.to_string())?;
        pacing.frame_done(&stats);
    }
    pacing.finish();
    if let Some(path) = &args.save {
        save(gpu, &offscreen, path)?;
        println!("last frame written to {}", path.display());
    }
    Ok(())
}

/// Writes `texture` (8-bit RGBA or BGRA, sRGB-encoded) to a PNG.
fn save(gpu: &Gpu, texture: &wgpu::Texture, path: &Path) -> Result<(), String> {
    let bgra = matches!(
        texture.format(),
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
    );
    let (width, height) = (texture.width(), texture.height());
    let row = (4 * width).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = gpu.device().create_buffer(&wgpu::BufferDescriptor {
        label: Some("host: readback"),
        size: u64::from(row) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = gpu
        .device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: Some(height),
            },
        },
        texture.size(),
    );
    gpu.queue().submit([encoder.finish()]);
    buffer.slice(..).map_async(wgpu::MapMode::Read, |_| {});
    gpu.wait_idle().map_err(|e| e.to_string())?;
    let mapped = buffer
        .slice(..)
        .get_mapped_range()
        .map_err(|e| e.to_string())?;
    let mut rgba: Vec<u8> = mapped
        .chunks(row as usize)
        .flat_map(|r| r[..4 * width as usize].to_vec())
        .collect();
    if bgra {
        rgba.chunks_exact_mut(4).for_each(|px| px.swap(0, 2));
    }
    image::save_buffer(path, &rgba, width, height, image::ExtendedColorType::Rgba8)
        .map_err(|e| e.to_string())
}

/// The windowed application: winit drives the frames, one per redraw.
struct App {
    args: Args,
    state: Option<Windowed>,
    error: Option<String>,
}

struct Windowed {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    gpu: &'static Gpu,
    renderer: Renderer<'static>,
    motion: Motion,
    host: Host,
    frame: u64,
    pacing: Pacing,
    /// `--frames` and `--save`.
    args_frames: Option<u64>,
    save: Option<PathBuf>,
}

impl App {
    fn open(&self, event_loop: &ActiveEventLoop) -> Result<Windowed, String> {
        let [width, height] = self.args.size;
        let window = event_loop
            .create_window(
                Window::default_attributes()
                    .with_title("rtc embedded")
                    .with_inner_size(winit::dpi::PhysicalSize::new(width, height)),
            )
            .map_err(|e| format!("no window: {e}"))?;
        let window = Arc::new(window);
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let surface = instance
            .create_surface(Arc::clone(&window))
            .map_err(|e| format!("no surface: {e}"))?;
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            compatible_surface: Some(&surface),
            ..wgpu::RequestAdapterOptions::default()
        }))
        .map_err(|e| format!("no adapter can draw to this window: {e}"))?;
        let (device, queue) = host_device(&adapter)?;
        let size = window.inner_size();
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or("the adapter cannot present to this window")?;
        let copyable = surface
            .get_capabilities(&adapter)
            .usages
            .contains(wgpu::TextureUsages::COPY_SRC);
        if self.args.save.is_some() {
            if copyable {
                config.usage |= wgpu::TextureUsages::COPY_SRC;
            } else {
                eprintln!("embed: this surface cannot be copied from; --save is ignored");
            }
        }
        surface.configure(&device, &config);
        let (gpu, renderer, motion) = setup(&self.args, &adapter, &device, &queue)?;
        let host = Host::new(&device, self.args.size, config.format);
        let mut pacing = Pacing::new(self.args.report_every);
        pacing.start();
        Ok(Windowed {
            window,
            surface,
            config,
            gpu,
            renderer,
            motion,
            host,
            frame: 0,
            pacing,
            args_frames: self.args.frames,
            save: self.args.save.clone(),
        })
    }
}

impl Windowed {
    fn draw(&mut self) -> Result<(), String> {
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f)
            | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(self.gpu.device(), &self.config);
                return Ok(());
            }
            other => return Err(format!("no frame to draw into ({other:?})")),
        };
        let view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor::default());
        let stats = self.host.frame(
            self.gpu,
            &mut self.renderer,
            &self.motion,
            self.frame,
            &view,
        )?;
        // Timed here: the interval between frames still holds the previous present.
        self.pacing.frame_done(&stats);
        let last = self.args_frames.is_some_and(|n| self.frame + 1 >= n);
        if let (true, Some(path)) = (last, &self.save) {
            if self.config.usage.contains(wgpu::TextureUsages::COPY_SRC) {
                save(self.gpu, &frame.texture, path)?;
                println!("last frame written to {}", path.display());
            }
        }
        self.window.pre_present_notify();
        self.gpu.queue().present(frame);
        self.frame += 1;
        Ok(())
    }
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.state.is_some() {
            return;
        }
        match self.open(event_loop) {
            Ok(state) => {
                state.window.request_redraw();
                self.state = Some(state);
            }
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(state) = &mut self.state else { return };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) if size.width > 0 && size.height > 0 => {
                state.config.width = size.width;
                state.config.height = size.height;
                state.surface.configure(state.gpu.device(), &state.config);
            }
            WindowEvent::RedrawRequested => {
                if let Err(e) = state.draw() {
                    self.error = Some(e);
                    event_loop.exit();
                    return;
                }
                if self.args.frames.is_some_and(|n| state.frame >= n) {
                    event_loop.exit();
                } else {
                    state.window.request_redraw();
                }
            }
            _ => {}
        }
    }
}

fn run_windowed(args: Args) -> Result<(), String> {
    let event_loop = EventLoop::new().map_err(|e| format!("no event loop (no display?): {e}"))?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut app = App {
        args,
        state: None,
        error: None,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| format!("event loop: {e}"))?;
    if let Some(state) = &app.state {
        state.pacing.finish();
    }
    app.error.map_or(Ok(()), Err)
}

fn main() -> std::process::ExitCode {
    // What `rtc` does first: 128-bit batches on lavapipe before Mesa 26 (half the compile time
    // there) and on CPUs without AVX-512, unless LP_NATIVE_VECTOR_WIDTH is set (the samples to
    // come are not known: a session of frames); optimised kernels, since the example renders
    // frame after frame. Before any thread or wgpu instance exists.
    rtc_runtime::gpu::apply_lavapipe_defaults(rtc_runtime::gpu::CpuJit::Optimized, None);
    let result = parse_args().and_then(|args| {
        if args.headless {
            run_headless(&args)
        } else {
            run_windowed(args)
        }
    });
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("embed: {e}");
            std::process::ExitCode::FAILURE
        }
    }
}
