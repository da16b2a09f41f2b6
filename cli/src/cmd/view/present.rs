//! The window's side of `rtc view`: a wgpu surface on the winit window, with its own device, and one
//! render pass that draws the last image over the whole window.
//!
//! The image is tone-mapped and sRGB-encoded on the CPU (the same mapping as the PNGs `rtc render`
//! writes) and uploaded to an 8-bit texture; the texture's format matches the surface's encoding
//! (sRGB or not), so the bytes on screen are the bytes of the PNG. The surface has its own instance
//! and device (a surface belongs to the instance that made it), separate from the compute device of
//! the runtime; the images cross over as bytes, which costs little at preview sizes.
//!
//! Screenshots (`rtc view --screenshot`) are read back from the surface texture itself after it was
//! drawn, when the surface allows copies from it (`COPY_SRC`; lavapipe's X11 surfaces do), so they
//! show what the window shows, at the window's size.
//!
//! Nothing here panics on a surface that is lost, outdated or timed out: that frame is skipped (and
//! the surface configured again when needed).

use rtc_runtime::image_out::{to_srgb8, LinearImage, ToneMap};
use std::sync::Arc;
use winit::window::Window;

const SHADER: &str = r"
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

/// A surface, its device, and the texture of the image shown.
pub struct Presenter {
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    pipeline: wgpu::RenderPipeline,
    sampler: wgpu::Sampler,
    texture_format: wgpu::TextureFormat,
    /// The image's texture and its bind group, once an image was uploaded.
    image: Option<(wgpu::Texture, wgpu::BindGroup)>,
    /// Whether [`Presenter::draw`] reads the drawn frame back.
    readback: bool,
}

/// A frame read back from the surface: RGBA, 8 bits, sRGB-encoded, row-major.
pub struct Capture {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub rgba: Vec<u8>,
}

impl Presenter {
    /// A surface on `window` and a device that can draw to it.
    /// With `readback`, [`Presenter::draw`] also returns what it drew, when the surface allows it.
    pub fn new(window: Arc<Window>, readback: bool) -> Result<Presenter, String> {
        let size = window.inner_size();
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let surface = instance
            .create_surface(window)
            .map_err(|e| format!("no surface: {e}"))?;
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::default(),
            force_fallback_adapter: false,
            compatible_surface: Some(&surface),
            apply_limit_buckets: false,
        }))
        .map_err(|e| format!("no adapter can draw to this window: {e}"))?;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("rtc view"),
            required_features: wgpu::Features::empty(),
            required_limits:
                wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits()),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::default(),
            trace: wgpu::Trace::Off,
        }))
        .map_err(|e| format!("no device: {e}"))?;
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or("the adapter cannot present to this window")?;
        // Prefer a plain (non-sRGB) 8-bit format: the bytes uploaded are already sRGB-encoded.
        let caps = surface.get_capabilities(&adapter);
        if let Some(f) = caps.formats.iter().find(|f| !f.is_srgb()) {
            config.format = *f;
        }
        config.present_mode = wgpu::PresentMode::AutoVsync;
        let eight_bit = matches!(
            config.format,
            wgpu::TextureFormat::Rgba8Unorm
                | wgpu::TextureFormat::Rgba8UnormSrgb
                | wgpu::TextureFormat::Bgra8Unorm
                | wgpu::TextureFormat::Bgra8UnormSrgb
        );
        let readback = readback && eight_bit && caps.usages.contains(wgpu::TextureUsages::COPY_SRC);
        if readback {
            config.usage |= wgpu::TextureUsages::COPY_SRC;
        }
        surface.configure(&device, &config);
        let texture_format = if config.format.is_srgb() {
            wgpu::TextureFormat::Rgba8UnormSrgb
        } else {
            wgpu::TextureFormat::Rgba8Unorm
        };
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("rtc view blit"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("rtc view blit"),
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
                    format: config.format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("rtc view nearest"),
            ..Default::default()
        });
        Ok(Presenter {
            surface,
            device,
            queue,
            config,
            pipeline,
            sampler,
            texture_format,
            image: None,
            readback,
        })
    }

    /// The window's new size.
    pub fn resize(&mut self, width: u32, height: u32) {
        if width == 0 || height == 0 {
            return;
        }
        self.config.width = width;
        self.config.height = height;
        self.surface.configure(&self.device, &self.config);
    }

    /// Uploads `image` (tone-mapped, sRGB-encoded) as the image to draw.
    pub fn upload(&mut self, image: &LinearImage) -> Result<(), String> {
        let (w, h) = (image.width(), image.height());
        let (rgb, _) = to_srgb8(image, &ToneMap::default());
        let mut rgba = Vec::with_capacity(rgb.len() / 3 * 4);
        for px in rgb.chunks_exact(3) {
            rgba.extend_from_slice(px);
            rgba.push(255);
        }
        let size = wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        };
        let reuse = self
            .image
            .as_ref()
            .is_some_and(|(t, _)| t.width() == w && t.height() == h);
        if !reuse {
            let texture = self.device.create_texture(&wgpu::TextureDescriptor {
                label: Some("rtc view image"),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: self.texture_format,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
            let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("rtc view image"),
                layout: &self.pipeline.get_bind_group_layout(0),
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(&view),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::Sampler(&self.sampler),
                    },
                ],
            });
            self.image = Some((texture, bind_group));
        }
        let Some((texture, _)) = &self.image else {
            return Err("no texture".to_owned());
        };
        self.queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            &rgba,
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * w),
                rows_per_image: Some(h),
            },
            size,
        );
        Ok(())
    }

    /// Draws the image over the whole window and presents it; returns the frame read back when
    /// asked for at creation and possible. A frame the surface cannot give is skipped.
    pub fn draw(&mut self) -> Result<Option<Capture>, String> {
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f)
            | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(&self.device, &self.config);
                return Ok(None);
            }
            other => return Err(format!("no frame to draw into ({other:?})")),
        };
        let view = frame
            .texture
            .create_view(&wgpu::TextureViewDescriptor::default());
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("rtc view"),
            });
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("rtc view"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
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
            if let Some((_, bind_group)) = &self.image {
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, bind_group, &[]);
                pass.draw(0..3, 0..1);
            }
        }
        let (width, height) = (frame.texture.width(), frame.texture.height());
        // Rows of a texture-to-buffer copy are padded to 256 bytes.
        let row = (4 * width).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let staging = self.readback.then(|| {
            let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("rtc view screenshot"),
                size: u64::from(row) * u64::from(height),
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            encoder.copy_texture_to_buffer(
                frame.texture.as_image_copy(),
                wgpu::TexelCopyBufferInfo {
                    buffer: &buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(row),
                        rows_per_image: Some(height),
                    },
                },
                frame.texture.size(),
            );
            buffer
        });
        self.queue.submit([encoder.finish()]);
        self.queue.present(frame);
        let Some(staging) = staging else {
            return Ok(None);
        };
        let (sender, receiver) = std::sync::mpsc::channel();
        staging.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = sender.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| format!("waiting for the screenshot: {e}"))?;
        match receiver.recv() {
            Ok(Ok(())) => {}
            Ok(Err(e)) => return Err(format!("cannot map the screenshot: {e}")),
            Err(e) => return Err(format!("cannot map the screenshot: {e}")),
        }
        let bgra = matches!(
            self.config.format,
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        );
        let mut rgba = Vec::with_capacity(4 * width as usize * height as usize);
        {
            let view = staging
                .get_mapped_range(..)
                .map_err(|e| format!("cannot read the screenshot: {e}"))?;
            for y in 0..height as usize {
                let start = y * row as usize;
                let Some(line) = view.get(start..start + 4 * width as usize) else {
                    return Err("the screenshot is shorter than the frame".to_owned());
                };
                for px in line.chunks_exact(4) {
                    if bgra {
                        rgba.extend_from_slice(&[px[2], px[1], px[0], px[3]]);
                    } else {
                        rgba.extend_from_slice(px);
                    }
                }
            }
        }
        staging.unmap();
        Ok(Some(Capture {
            width,
            height,
            rgba,
        }))
    }
}
