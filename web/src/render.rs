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
//! rather than waits. Assets (OBJ, images, glTF files and the files they name) come from the
//! files given or, with `await loadRenderer(files, entry, options, fetchFile)`, from a function
//! the page gives (URLs next to the page, dropped files); either way under the desktop's
//! confinement (rtc-compiler's `confine`, applied to paths in memory). Not yet: the wavefront
//! model (its rounds read back mid-frame), drawing straight into a canvas. Custom geometry (its
//! bounds kernel's boxes are read back once, at setup) renders through `loadRenderer`, which
//! awaits that read-back; `new WebRenderer` cannot and says so.

use std::cell::{Cell, RefCell};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::Arc;

use rtc_compiler::kernel::CompiledScene;
use rtc_compiler::source::MemoryFiles;
use rtc_runtime::assets::{model, AssetRoots};
use rtc_runtime::gpu::{AdapterChoice, Gpu, GpuOptions, PipelineCacheConfig};
use rtc_runtime::image_out::{to_srgb8, ToneMap};
use rtc_runtime::orbit::{self, read_orbit, Orbit};
use rtc_runtime::render::{RenderOptions, Renderer};
use wasm_bindgen::prelude::*;

use crate::{
    files_from_js, options_from_js, paths_from_js, render_failure, scene_assets, to_js,
    CompileOptions, Compiler,
};

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
    /// `options`: the compile options plus `{ width?, height?, samples? }`. Every asset the scene
    /// loads (OBJ, images, glTF files and what they name) must be among `files`, under the paths
    /// the scene names them by (relative to its folder); [`load_renderer`] fetches them instead.
    #[wasm_bindgen(constructor)]
    pub fn new(files: JsValue, entry: JsValue, options: JsValue) -> Result<WebRenderer, JsError> {
        let gpu = page_gpu()?;
        let request = RenderRequest::from_js(&files, &entry, &options)?;
        let compiled = Compiler::new()
            .compile_scene(request.files.clone(), &request.roots, &request.compile)
            .map_err(|rendered| JsError::new(&rendered))?;
        WebRenderer::prepare(gpu, &compiled, &request)
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
            "passes_per_dispatch": stats.passes_per_dispatch,
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

/// The page's device, or the error saying to create it first.
fn page_gpu() -> Result<&'static Gpu, JsError> {
    GPU.with(Cell::get)
        .ok_or_else(|| JsError::new("call `await initGpu()` before creating a WebRenderer"))
}

/// What a renderer is made from: the files (the standard library added), the scene's root
/// files, the compile options and the image's size and samples.
struct RenderRequest {
    files: MemoryFiles,
    roots: Vec<String>,
    compile: CompileOptions,
    size: Option<[u32; 2]>,
    samples: Option<u32>,
}

impl RenderRequest {
    /// The arguments of `new WebRenderer(files, entry, options)`, checked.
    fn from_js(files: &JsValue, entry: &JsValue, options: &JsValue) -> Result<Self, JsError> {
        let files = files_from_js(files)?;
        let roots = paths_from_js(entry)?;
        if roots.is_empty() {
            return Err(JsError::new(
                "WebRenderer: `entry` must name the scene's file",
            ));
        }
        let compile = options_from_js(options)?;
        let number = |key: &str| -> Result<Option<u32>, JsError> {
            if options.is_undefined() || options.is_null() {
                return Ok(None);
            }
            let v = js_sys::Reflect::get(options, &JsValue::from_str(key))
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
        Ok(RenderRequest {
            files,
            roots,
            compile,
            size,
            samples,
        })
    }
}

impl RenderRequest {
    /// The renderer's options: the size and samples asked for, assets from the files.
    fn render_options(&self) -> RenderOptions {
        RenderOptions {
            size: self.size,
            samples: self.samples,
            asset_roots: AssetRoots::in_memory(Arc::new(self.files.clone())),
            ..RenderOptions::default()
        }
    }
}

/// How many rounds [`load_renderer`] fetches for at most: the scene's files, then the files its
/// glTF models name, with room to spare.
const FETCH_ROUNDS: usize = 8;

/// Like `new WebRenderer(files, entry, options)`, but the assets the scene loads are fetched
/// rather than given: whenever the scene (or a glTF file it loads) names a file that `files`
/// lacks, `fetchFile(path)` is called with the path (relative to the folder the scene's paths
/// are, confined to the scene's folder as on the desktop: never a path outside it) and must give
/// (or promise) its bytes (`Uint8Array`, `ArrayBuffer` or a string), or `null` when there is no
/// such file. The page passes one that fetches URLs next to it or looks in the files the user
/// dropped. Rounds: the scene's meshes, images and models, then the buffers and images the
/// models name; each round's fetches run at once. A file that cannot be had gives the renderer's
/// usual error naming it.
#[wasm_bindgen(js_name = loadRenderer)]
pub async fn load_renderer(
    files: JsValue,
    entry: JsValue,
    options: JsValue,
    fetch_file: js_sys::Function,
) -> Result<WebRenderer, JsError> {
    let gpu = page_gpu()?;
    let mut request = RenderRequest::from_js(&files, &entry, &options)?;
    let compiler = Compiler::new();
    let mut asked = BTreeSet::new();
    let mut round = 0;
    loop {
        round += 1;
        let result =
            compiler.compile_scene_full(request.files.clone(), &request.roots, &request.compile);
        let shared = Arc::new(request.files.clone());
        let roots = AssetRoots::in_memory(Arc::clone(&shared));
        let mut wanted = scene_assets(&result, &shared);
        for file in wanted.clone() {
            if let Some(bytes) = shared.get(&file) {
                wanted.extend(model::external_files(bytes, &file, &roots));
            }
        }
        let missing: Vec<PathBuf> = wanted
            .into_iter()
            .filter(|f| !shared.is_file(f) && !asked.contains(f))
            .collect();
        if missing.is_empty() || round > FETCH_ROUNDS {
            let compiled = result.map_err(|f| JsError::new(&render_failure(&f)))?;
            let renderer = Renderer::new_async(gpu, &compiled, request.render_options())
                .await
                .map_err(|e| JsError::new(&e.to_string()))?;
            return Ok(WebRenderer::from_renderer(renderer, &compiled));
        }
        // Start every fetch, then wait for each.
        let mut pending = Vec::new();
        for file in &missing {
            let path = JsValue::from_str(&file.to_string_lossy());
            let answer = fetch_file
                .call1(&JsValue::NULL, &path)
                .map_err(|e| fetch_error(file, &e))?;
            let promise = js_sys::Promise::resolve(&answer);
            pending.push((file.clone(), wasm_bindgen_futures::JsFuture::from(promise)));
        }
        for (file, answer) in pending {
            let value = answer.await.map_err(|e| fetch_error(&file, &e))?;
            if let Some(bytes) = bytes_from_js(&value) {
                request.files.insert(&file, bytes);
            } else if !(value.is_null() || value.is_undefined()) {
                return Err(JsError::new(&format!(
                    "fetchFile(`{}`) must give a Uint8Array, an ArrayBuffer, a string or null",
                    file.display()
                )));
            }
            asked.insert(file);
        }
    }
}

/// The error of a `fetchFile` call that threw or rejected.
fn fetch_error(file: &Path, e: &JsValue) -> JsError {
    let why = e
        .dyn_ref::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .or_else(|| e.as_string())
        .unwrap_or_else(|| "it failed".into());
    JsError::new(&format!("fetchFile(`{}`): {why}", file.display()))
}

/// The bytes of a `Uint8Array`, `ArrayBuffer` or string.
fn bytes_from_js(value: &JsValue) -> Option<Vec<u8>> {
    if let Some(text) = value.as_string() {
        Some(text.into_bytes())
    } else if let Some(a) = value.dyn_ref::<js_sys::Uint8Array>() {
        Some(a.to_vec())
    } else {
        value
            .dyn_ref::<js_sys::ArrayBuffer>()
            .map(|b| js_sys::Uint8Array::new(b).to_vec())
    }
}

impl WebRenderer {
    /// The renderer of a compiled scene, its assets read from `request.files` (a scene with
    /// custom geometry fails: its bounds are read back, which only [`load_renderer`] awaits).
    fn prepare(
        gpu: &'static Gpu,
        compiled: &CompiledScene,
        request: &RenderRequest,
    ) -> Result<WebRenderer, JsError> {
        let renderer = Renderer::new(gpu, compiled, request.render_options())
            .map_err(|e| JsError::new(&e.to_string()))?;
        Ok(WebRenderer::from_renderer(renderer, compiled))
    }

    fn from_renderer(renderer: Renderer<'static>, compiled: &CompiledScene) -> WebRenderer {
        let size = renderer.size();
        let home = read_orbit(compiled);
        WebRenderer {
            renderer: Rc::new(RefCell::new(renderer)),
            size,
            home,
            view: Cell::new(home),
        }
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
