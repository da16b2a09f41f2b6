//! The renderer in the page (cargo feature `renderer`, wasm only): `rtc-runtime` on the
//! browser's WebGPU through wgpu's `webgpu` backend. The runtime's scene building, BVHs, buffer
//! packing and tiled dispatch run unchanged; only its waits differ there (see `rtc-runtime`'s
//! `Gpu::scoped`, `read_buffer_async`, `Renderer::image_async`).
//!
//! JavaScript: `await initGpu()` once (one device per page, WebGPU's default limits, no raised
//! limit requested), then `new WebRenderer(files, entry, options)`, `accumulate(passes)` (submits
//! and returns at once; stats as a plain object) and `await readRgba8()` (the running mean as
//! tone-mapped sRGB RGBA8 bytes, `width * height * 4`, for an `ImageData`); `orbit`, `pan`, `zoom`
//! `resetView` and `setView` move a camera that has `position` and `look_at` (`canOrbit`; `view`
//! reads it) and restart the accumulation.
//!
//! Guarantees: nothing blocks (no `pollster`, no blocking poll); every failure is a thrown
//! `Error` with the runtime's message, never a panic; a call while a read-back is pending throws
//! rather than waits. Not yet: asset files (OBJ/glTF/textures) from memory, the wavefront model
//! and custom-geometry bounds (both read back synchronously), drawing straight into a canvas.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use rtc_runtime::gpu::{AdapterChoice, Gpu, GpuOptions, PipelineCacheConfig};
use rtc_runtime::image_out::{to_srgb8, ToneMap};
use rtc_runtime::orbit::{self, read_orbit, Orbit};
use rtc_runtime::render::{RenderOptions, Renderer};
use wasm_bindgen::prelude::*;

use crate::{files_from_js, options_from_js, paths_from_js, to_js, Compiler};

thread_local! {
    /// The page's one device ([`init_gpu`]); leaked once, so renderers may borrow it for good.
    static GPU: Cell<Option<&'static Gpu>> = const { Cell::new(None) };
}

/// Creates the page's WebGPU device (once; later calls return at once) and returns the
/// adapter's description.
#[wasm_bindgen(js_name = initGpu)]
pub async fn init_gpu() -> Result<String, JsError> {
    if let Some(gpu) = GPU.with(Cell::get) {
        return Ok(gpu.description().to_string());
    }
    let options = GpuOptions {
        pipeline_cache: PipelineCacheConfig::Off,
    };
    let gpu = Gpu::with_options_async(&AdapterChoice::default(), &options)
        .await
        .map_err(|e| JsError::new(&e.to_string()))?;
    gpu.record_uncaptured_errors();
    let gpu: &'static Gpu = Box::leak(Box::new(gpu));
    GPU.with(|g| g.set(Some(gpu)));
    Ok(gpu.description().to_string())
}

/// A compiled scene ready to render on the page's device.
#[wasm_bindgen]
pub struct WebRenderer {
    renderer: Rc<RefCell<Renderer<'static>>>,
    size: [u32; 2],
    /// The scene's own camera as an orbit (`None`: no `position`/`look_at`), and the current one.
    home: Option<Orbit>,
    view: Cell<Option<Orbit>>,
}

#[wasm_bindgen]
impl WebRenderer {
    /// Compiles the scene of `entry` from `files` (as `compile` takes them) and prepares it.
    /// `options`: the compile options plus `{ width?, height?, samples? }`.
    #[wasm_bindgen(constructor)]
    pub fn new(files: JsValue, entry: JsValue, options: JsValue) -> Result<WebRenderer, JsError> {
        let gpu = GPU
            .with(Cell::get)
            .ok_or_else(|| JsError::new("call `await initGpu()` before creating a WebRenderer"))?;
        let files = files_from_js(&files)?;
        let roots = paths_from_js(&entry)?;
        if roots.is_empty() {
            return Err(JsError::new(
                "WebRenderer: `entry` must name the scene's file",
            ));
        }
        let compile_options = options_from_js(&options)?;
        let number = |key: &str| -> Result<Option<u32>, JsError> {
            if options.is_undefined() || options.is_null() {
                return Ok(None);
            }
            let v = js_sys::Reflect::get(&options, &JsValue::from_str(key))
                .map_err(|_| JsError::new("`options` must be an object"))?;
            if v.is_undefined() || v.is_null() {
                return Ok(None);
            }
            match v.as_f64() {
                Some(n) if n >= 1.0 && n <= f64::from(u32::MAX) && n.fract() == 0.0 => {
                    Ok(Some(n as u32))
                }
                _ => Err(JsError::new(&format!("`{key}` must be a positive integer"))),
            }
        };
        let size = match (number("width")?, number("height")?) {
            (Some(w), Some(h)) => Some([w, h]),
            (None, None) => None,
            _ => return Err(JsError::new("give both `width` and `height`, or neither")),
        };
        let samples = number("samples")?;
        let compiled = Compiler::new()
            .compile_scene(files, &roots, &compile_options)
            .map_err(|rendered| JsError::new(&rendered))?;
        let render_options = RenderOptions {
            size,
            samples,
            ..RenderOptions::default()
        };
        let renderer = Renderer::new(gpu, &compiled, render_options)
            .map_err(|e| JsError::new(&e.to_string()))?;
        let size = renderer.size();
        let home = read_orbit(&compiled);
        Ok(WebRenderer {
            renderer: Rc::new(RefCell::new(renderer)),
            size,
            home,
            view: Cell::new(home),
        })
    }

    /// Whether the camera can be moved (`orbit`, `pan`, `zoom`): the scene's camera has
    /// `position` and `look_at` fields (the standard pinhole and thin-lens cameras).
    #[wasm_bindgen(getter, js_name = canOrbit)]
    pub fn can_orbit(&self) -> bool {
        self.home.is_some()
    }

    /// Turns the camera around the point it looks at by `yaw` (about the world's y axis) and
    /// `pitch` (up and down, kept off the poles), in radians; the accumulation restarts.
    pub fn orbit(&self, yaw: f32, pitch: f32) -> Result<(), JsError> {
        self.move_camera(|o| o.orbit(yaw, pitch))
    }

    /// Moves the camera and the point it looks at across the view by `dx`, `dy` times their
    /// distance; the accumulation restarts.
    pub fn pan(&self, dx: f32, dy: f32) -> Result<(), JsError> {
        self.move_camera(|o| o.pan(dx, dy))
    }

    /// Moves the camera toward the point it looks at to `factor` times the distance (below 1
    /// zooms in); the accumulation restarts.
    pub fn zoom(&self, factor: f32) -> Result<(), JsError> {
        self.move_camera(|o| o.zoom(factor))
    }

    /// The camera as `{ position: [x, y, z], lookAt: [x, y, z] }`, or `undefined` when it cannot
    /// move (`canOrbit` is false).
    #[wasm_bindgen(getter)]
    pub fn view(&self) -> Result<JsValue, JsError> {
        match self.view.get() {
            Some(o) => to_js(&serde_json::json!({ "position": o.position, "lookAt": o.look_at })),
            None => Ok(JsValue::UNDEFINED),
        }
    }

    /// Puts the camera at `position` looking at `look_at` (three numbers each), as `view` gives
    /// them (a page keeps the user's camera across an edit this way); the accumulation restarts.
    #[wasm_bindgen(js_name = setView)]
    pub fn set_view(&self, position: Vec<f32>, look_at: Vec<f32>) -> Result<(), JsError> {
        let (Ok(position), Ok(look_at)) = (
            <[f32; 3]>::try_from(position.as_slice()),
            <[f32; 3]>::try_from(look_at.as_slice()),
        ) else {
            return Err(JsError::new(
                "setView takes two arrays of three numbers: position and lookAt",
            ));
        };
        self.move_camera(|o| *o = Orbit { position, look_at })
    }

    /// Puts the camera back where the scene has it; the accumulation restarts.
    #[wasm_bindgen(js_name = resetView)]
    pub fn reset_view(&self) -> Result<(), JsError> {
        let home = self.home;
        self.move_camera(|o| {
            if let Some(h) = home {
                *o = h;
            }
        })
    }

    /// The image width in pixels.
    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.size[0]
    }

    /// The image height in pixels.
    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.size[1]
    }

    /// Samples per pixel of one pass.
    #[wasm_bindgen(js_name = samplesPerPass)]
    pub fn samples_per_pass(&self) -> Result<u32, JsError> {
        Ok(self.borrow()?.samples_per_pass())
    }

    /// Adds `passes` passes to the running accumulation (submitted, not waited for) and returns
    /// the runtime's stats (its traced-ray count is 0 on the web). Errors of earlier GPU calls,
    /// reported by the browser since, are thrown here.
    pub fn accumulate(&self, passes: u32) -> Result<JsValue, JsError> {
        let mut renderer = self
            .renderer
            .try_borrow_mut()
            .map_err(|_| JsError::new("the renderer is busy (await the pending read-back)"))?;
        let stats = renderer
            .accumulate(passes, &mut |_, _| {})
            .map_err(|e| JsError::new(&e.to_string()))?;
        to_js(&serde_json::json!({
            "adapter": stats.adapter,
            "width": stats.width,
            "height": stats.height,
            "samples": stats.samples,
            "passes": stats.passes,
            "tiles": stats.tiles,
            "accumulatedSamples": stats.accumulated_samples,
            "renderMs": stats.render_ms,
            "bvhBuildMs": stats.bvh_build_ms,
            "pipelineMs": stats.pipeline_ms,
            "uploadMs": stats.upload_ms,
            "warnings": stats.warnings,
        }))
    }

    /// Starts the accumulation afresh.
    #[wasm_bindgen(js_name = resetAccumulation)]
    pub fn reset_accumulation(&self) -> Result<(), JsError> {
        self.renderer
            .try_borrow_mut()
            .map_err(|_| JsError::new("the renderer is busy (await the pending read-back)"))?
            .reset_accumulation();
        Ok(())
    }

    /// The running mean, tone-mapped as `rtc render` writes PNGs, as RGBA8 bytes (alpha 255),
    /// row-major from the top left: a promise of a `Uint8Array`.
    #[wasm_bindgen(js_name = readRgba8)]
    pub fn read_rgba8(&self) -> js_sys::Promise {
        let renderer = Rc::clone(&self.renderer);
        // The shared borrow is held across the await on purpose: while the read-back is pending,
        // `accumulate` and `resetAccumulation` (which borrow mutably) throw "busy" instead.
        #[allow(clippy::await_holding_refcell_ref)]
        let read = async move {
            let renderer = renderer
                .try_borrow()
                .map_err(|_| JsValue::from_str("the renderer is busy"))?;
            let image = renderer
                .image_async()
                .await
                .map_err(|e| JsValue::from(JsError::new(&e.to_string())))?;
            let (rgb, _) = to_srgb8(&image, &ToneMap::default());
            let mut rgba = Vec::with_capacity(rgb.len() / 3 * 4);
            for p in rgb.chunks_exact(3) {
                rgba.extend_from_slice(&[p[0], p[1], p[2], 255]);
            }
            Ok(js_sys::Uint8Array::from(rgba.as_slice()).into())
        };
        wasm_bindgen_futures::future_to_promise(read)
    }
}

impl WebRenderer {
    /// Changes the orbit with `change` and writes it into the renderer's camera; an error if the
    /// camera has no orbit, the arguments are not finite or the renderer is busy.
    fn move_camera(&self, change: impl FnOnce(&mut Orbit)) -> Result<(), JsError> {
        let Some(mut view) = self.view.get() else {
            return Err(JsError::new(
                "this scene's camera has no `position` and `look_at` to move",
            ));
        };
        change(&mut view);
        if !view
            .position
            .iter()
            .chain(&view.look_at)
            .all(|v| v.is_finite())
        {
            return Err(JsError::new("the camera move must be finite"));
        }
        let mut renderer = self
            .renderer
            .try_borrow_mut()
            .map_err(|_| JsError::new("the renderer is busy (await the pending read-back)"))?;
        orbit::apply(&mut renderer, view).map_err(|e| JsError::new(&e.to_string()))?;
        self.view.set(Some(view));
        Ok(())
    }

    fn borrow(&self) -> Result<std::cell::Ref<'_, Renderer<'static>>, JsError> {
        self.renderer
            .try_borrow()
            .map_err(|_| JsError::new("the renderer is busy"))
    }
}
