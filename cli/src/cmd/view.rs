//! `rtc view <scene.rt>`: a window showing the scene as it renders, refined progressively, with an
//! orbit camera, reloading programs and scene on every save.
//!
//! How it works:
//! - the scene is compiled and watched by the same [`Session`] as `rtc watch` (no code is written);
//!   a save reloads it, prints what changed and each phase's time, and keeps the camera; a scene
//!   left at `EXEC_AUTO` runs the megakernel (`rtc watch` runs the wavefront model);
//! - the image is rendered by one long-lived [`Renderer`] (the runtime's live session) on its
//!   compute device ([`Gpu`]), progressively: each step adds one pass (the camera program's
//!   samples per pixel) to the running accumulation and shows the average, until the scene's
//!   `samples` (or `--spp`); a camera move writes the camera's fields in place and starts the
//!   accumulation again at one pass; a reload replaces the renderer's kernels, keeping every
//!   asset, object-level BVH and unchanged buffer, and the camera the user set;
//! - the window (winit) is drawn through a wgpu surface ([`present::Presenter`]): the last image is
//!   uploaded to a texture and drawn over the whole window;
//! - the camera: drag with the left button to orbit around the point looked at, with the right or
//!   middle button to pan, scroll to zoom. It works on cameras with `position` and `look_at` fields
//!   (the standard library's pinhole and thin-lens cameras); for others the window only shows;
//! - an animated scene (spec/animation.md) plays in a loop of its `frames` at its `fps`, one fresh
//!   pass a step at the time the clock shows; space pauses it (the paused frame then refines like
//!   a still scene) and plays it again; a camera the user moved stays where they put it;
//! - while the camera moves, each step shows the new view at once: when a whole pass takes longer
//!   than 40 ms ([`PREVIEW_BUDGET_MS`](rtc_runtime::render::PREVIEW_BUDGET_MS): a CPU driver, a
//!   large image), the step renders one pass at 1/2, 1/4 or 1/8 of the width and height
//!   ([`Renderer::preview`], the smallest reduction that fits the budget, judged by the last whole
//!   pass) and shows it scaled up; once the camera has stayed still for [`SETTLE`] after a
//!   preview, the accumulation starts at the whole size (`--preview` fixes the reduction or turns
//!   it off);
//! - the title shows the samples per pixel accumulated, the time of the last step (one pass,
//!   its read-back and display) and the primary rays per second of its pass.
//!
//! Without a display (neither `DISPLAY` nor `WAYLAND_DISPLAY` set, or one that cannot be opened) it
//! says so and exits with code 1; a scene with errors exits with code 1 after its diagnostics; errors
//! after the window opened are printed and the window stays (the last good image is kept).
//!
//! For tests: `--screenshot FILE` writes what the window shows after every new frame is drawn (read
//! back from the window's surface, at the window's size; where the surface cannot be read, the image
//! uploaded to it) and prints `[view] screenshot N …`; `--exit-after-frames N` closes the window
//! after `N` frames. Escape, `q`, closing the window and Ctrl-C end it with code 0.

mod present;

use super::render::{output_format, write_image, Format};
use super::watch::{describe, update_dirs, Session, Status};
use super::Context;
use crate::args::RenderArgs;
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::kernel::CompiledScene;
use rtc_runtime::assets::AssetRoots;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::{srgb_to_linear, LinearImage};
use rtc_runtime::orbit::{read_orbit, write_orbit, Orbit};
use rtc_runtime::render::{preview_factor, RenderOptions, Renderer};
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant, SystemTime};
use winit::application::ApplicationHandler;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// Arguments of `rtc view`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file (its imports and assets are watched and reloaded).
    #[arg(value_name = "SCENE.rt")]
    pub path: PathBuf,
    /// Scene, size, samples, GPU and asset folders.
    #[command(flatten)]
    pub render: RenderArgs,
    /// The execution model.
    #[command(flatten)]
    pub exec: crate::args::ExecArgs,
    /// Write the image shown to this `.png` or `.exr` after every frame (for tests).
    #[arg(long, value_name = "FILE", hide = true)]
    pub screenshot: Option<PathBuf>,
    /// Close the window after this many frames (for tests).
    #[arg(long, value_name = "N", hide = true)]
    pub exit_after_frames: Option<u32>,
    /// While the camera moves: `auto` shows each move at 1/2, 1/4 or 1/8 of the width and height
    /// when a whole pass is slower than 40 ms (the smallest reduction that fits 40 ms), `off`
    /// always at the whole size, a number N (1 to 64) always at 1/N.
    #[arg(long, value_name = "auto|off|N", default_value = "auto", value_parser = parse_preview)]
    pub preview: Preview,
}

/// `--preview`: how camera moves are shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preview {
    /// Reduced by what the last whole pass took ([`preview_factor`]).
    Auto,
    /// Always this reduction of width and height (1: none).
    Factor(u32),
}

fn parse_preview(text: &str) -> Result<Preview, String> {
    match text {
        "auto" => Ok(Preview::Auto),
        "off" => Ok(Preview::Factor(1)),
        n => match n.parse::<u32>() {
            Ok(f @ 1..=64) => Ok(Preview::Factor(f)),
            _ => Err("expected `auto`, `off` or a whole number from 1 to 64".to_string()),
        },
    }
}

/// How long the camera must stay still after a preview before a whole-size pass starts (which
/// then holds the window for a whole pass): a drag that pauses briefly keeps getting previews.
const SETTLE: Duration = Duration::from_millis(120);

/// What the file watcher and the Ctrl-C handler send to the event loop.
#[derive(Debug)]
enum UserEvent {
    Files(Vec<PathBuf>),
    Stop,
}

/// The camera after a reload: the user's while they moved it (and the new scene still has an orbit
/// camera), else the one in the file.
fn camera_after_reload(
    moved: bool,
    user: Option<Orbit>,
    from_file: Option<Orbit>,
) -> Option<Orbit> {
    match (moved, user, from_file) {
        (true, Some(user), Some(_)) => Some(user),
        _ => from_file,
    }
}

/// Which mouse button drags, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Drag {
    Orbit,
    Pan,
}

struct App<'a> {
    args: &'a Args,
    ctx: &'a Context,
    session: Session,
    /// The compute device, for the life of the process (the renderer borrows it).
    gpu: &'static Gpu,
    /// The scene's renderer, built at the first step and kept.
    renderer: Option<Renderer<'static>>,
    /// Whether the session compiled again since the renderer's kernels were made.
    stale_kernel: bool,
    /// Whether the next step starts a new accumulation (the camera moved, or a reload).
    fresh: bool,
    /// Whether the user moved the camera since the last step (then the step may be a preview).
    moving: bool,
    /// Render time of the last whole pass (what a preview's reduction is chosen by).
    pass_ms: Option<f64>,
    /// After a preview: the whole-size pass waits until then for the camera to stay still.
    settle_until: Option<Instant>,
    /// Scene time of an animated scene.
    clock: Clock,
    /// The length of the glTF node animations of the scene's models (seconds; known once the
    /// renderer is built).
    model_length: f32,
    watcher: Option<notify::RecommendedWatcher>,
    dirs: BTreeSet<PathBuf>,
    window: Option<Arc<Window>>,
    presenter: Option<present::Presenter>,
    /// The image shown.
    image: Option<LinearImage>,
    /// Samples per pixel of the next step; `None`: refined as far as asked, nothing to do.
    next_spp: Option<u32>,
    /// Samples per pixel to refine to.
    target_spp: u32,
    orbit: Option<Orbit>,
    /// Whether the user moved the camera (then a reload keeps it; else the file's camera is used).
    moved: bool,
    drag: Option<Drag>,
    cursor: Option<(f64, f64)>,
    pending: Vec<PathBuf>,
    last_event: Instant,
    frames: u32,
    /// Whether the last frame rendered was not drawn into the window yet.
    undrawn: bool,
    status: String,
    exit: Exit,
}

const DEBOUNCE: Duration = Duration::from_millis(15);

/// The animation clock: scene time in seconds, playing or paused, looping over the scene's
/// `frames / fps` seconds.
#[derive(Clone, Copy, Debug)]
struct Clock {
    playing: bool,
    /// When playing: the instant scene time `at` was read.
    since: Instant,
    /// Scene time at `since` (the paused time while paused).
    at: f32,
}

impl Clock {
    fn new(playing: bool) -> Clock {
        Clock {
            playing,
            since: Instant::now(),
            at: 0.0,
        }
    }

    /// Scene time now, wrapped into `[0, length)` when `length` is positive.
    fn now(&self, length: f32) -> f32 {
        let t = if self.playing {
            self.at + self.since.elapsed().as_secs_f32()
        } else {
            self.at
        };
        if length > 0.0 {
            t.rem_euclid(length)
        } else {
            t
        }
    }

    /// Pauses at the current time, or plays on from it.
    fn toggle(&mut self, length: f32) {
        self.at = self.now(length);
        self.since = Instant::now();
        self.playing = !self.playing;
    }
}

/// The loop length of a scene's animation in seconds (`frames / fps`), 0 without one (its
/// models' glTF animations are the renderer's: `App::model_length`).
fn animation_length(compiled: &CompiledScene) -> f32 {
    compiled
        .checked
        .program
        .as_ref()
        .map(|p| &p.scenes[compiled.scene])
        .filter(|d| rtc_runtime::animation::is_animated(d))
        .map_or(0.0, |d| {
            d.settings.frames as f32 / d.settings.fps.max(1) as f32
        })
}

impl App<'_> {
    fn fail(&mut self, event_loop: &ActiveEventLoop, message: &str) {
        term::eprint(&format!(
            "{}: {message}\n",
            term::paint("error", 31, self.ctx.color)
        ));
        self.exit = Exit::Failure;
        event_loop.exit();
    }

    /// Starts refining again from one pass.
    fn restart(&mut self) {
        self.next_spp = Some(1);
        self.fresh = true;
    }

    /// The scene's own sample count (or `--spp`).
    fn wanted_spp(&self) -> u32 {
        self.args.render.spp.samples.unwrap_or_else(|| {
            self.session
                .last()
                .and_then(|c| {
                    let p = c.checked.program.as_ref()?;
                    Some(p.scenes[c.scene].settings.samples)
                })
                .unwrap_or(1)
                .max(1)
        })
    }

    /// Reloads after file events; keeps the camera the user set.
    fn reload(&mut self) {
        let paths = std::mem::take(&mut self.pending);
        let started = SystemTime::now();
        let reload = self.session.reload(&paths);
        term::eprint(&reload.messages);
        if reload.status == Status::Unchanged {
            return;
        }
        term::print(&describe(&reload, self.ctx.color));
        if let Some(w) = self.watcher.as_mut() {
            let added = update_dirs(w, &mut self.dirs, &self.session, self.ctx);
            // What changed in a new folder before it was watched sent no event: reload it soon.
            self.pending = self.session.missed(&added, started);
            self.last_event = Instant::now();
        }
        if matches!(reload.status, Status::Built | Status::Rerendered) {
            let from_file = self.session.last().and_then(read_orbit);
            self.orbit = camera_after_reload(self.moved, self.orbit, from_file);
            self.target_spp = self.wanted_spp();
            self.stale_kernel = true;
            self.restart();
        }
    }

    /// Adds one pass to the accumulation (after bringing the renderer up to date) and shows it.
    fn step(&mut self, event_loop: &ActiveEventLoop) {
        if self.next_spp.is_none() {
            return;
        }
        let factor = match (std::mem::take(&mut self.moving), self.args.preview) {
            (false, _) => 1,
            (true, Preview::Auto) => preview_factor(self.pass_ms),
            (true, Preview::Factor(f)) => f,
        };
        let t = Instant::now();
        let result = self.advance(factor);
        let frame_ms = t.elapsed().as_secs_f64() * 1e3;
        let (stats, image) = match result {
            Ok(r) => r,
            Err(e) => {
                term::eprint(&format!(
                    "{}: {e}\n",
                    term::paint("error", 31, self.ctx.color)
                ));
                self.next_spp = None;
                return;
            }
        };
        let spp = stats.accumulated_samples;
        if factor == 1 {
            self.pass_ms = Some(stats.render_ms);
            self.settle_until = None;
        } else {
            self.settle_until = Some(Instant::now() + SETTLE);
        }
        let length = self
            .session
            .last()
            .map_or(0.0, animation_length)
            .max(self.model_length);
        let playing = length > 0.0 && self.clock.playing;
        self.next_spp = (playing || spp < self.target_spp).then_some(spp + stats.samples_per_pass);
        self.frames += 1;
        let shown = if factor > 1 {
            format!("1/{factor} preview ({}x{})", stats.width, stats.height)
        } else {
            format!("{spp} spp")
        };
        self.status = format!(
            "{shown}, {frame_ms:.0} ms/frame, {:.2} M rays/s",
            stats.rays_per_second / 1e6
        );
        if length > 0.0 {
            let t = self.clock.now(length);
            let state = if playing { "playing" } else { "paused" };
            self.status.push_str(&format!(", {state} at {t:.2} s"));
        }
        if let (Some(p), Some(w)) = (&mut self.presenter, &self.window) {
            if let Err(e) = p.upload(&image) {
                term::eprint(&format!(
                    "{}: cannot show the image: {e}\n",
                    term::paint("error", 31, self.ctx.color)
                ));
            }
            w.set_title(&format!(
                "rtc view: {} ({})",
                self.args.path.display(),
                self.status
            ));
            w.request_redraw();
        }
        term::print(&format!("[view] frame {}: {}\n", self.frames, self.status));
        self.image = Some(image);
        self.undrawn = true;
        if self.window.is_none() {
            self.after_draw(event_loop, None);
        }
    }

    /// Brings the renderer up to date (built at the first step, kernels replaced after a
    /// reload, the camera written after a move), adds one pass and reads the image back; with
    /// `factor` above 1, renders a preview at `1 / factor` of the size instead (which ends the
    /// accumulation: the next pass starts it afresh).
    fn advance(
        &mut self,
        factor: u32,
    ) -> Result<(rtc_runtime::render::RenderStats, LinearImage), rtc_runtime::render::RenderError>
    {
        let orbit = self.orbit;
        let target = self.target_spp;
        let Some(compiled) = self.session.last_mut() else {
            return Err(rtc_runtime::render::RenderError::KernelSet);
        };
        if let Some(orbit) = orbit {
            write_orbit(compiled, orbit);
        }
        let compiled = &*compiled;
        match &mut self.renderer {
            Some(r) if self.stale_kernel => r.replace_kernel(compiled)?,
            Some(r) if self.fresh => {
                if let Some(orbit) = orbit {
                    rtc_runtime::orbit::apply(r, orbit)?;
                }
            }
            Some(_) => {}
            None => {
                let options = RenderOptions {
                    size: self.args.render.scene.image_size(),
                    samples: Some(target),
                    // Checked to be folders in `run`.
                    asset_roots: AssetRoots::new(
                        self.args.render.assets.asset_roots.iter().cloned(),
                    ),
                    ..RenderOptions::default()
                };
                self.renderer = Some(Renderer::new(self.gpu, compiled, options)?);
            }
        }
        self.stale_kernel = false;
        let Some(r) = self.renderer.as_mut() else {
            return Err(rtc_runtime::render::RenderError::KernelSet);
        };
        let model_length = r.model_animation_length();
        if model_length > 0.0 && self.model_length == 0.0 && animation_length(compiled) == 0.0 {
            term::print(&format!(
                "[view] the model is animated: playing its {model_length:.2} s in a loop (space pauses and refines)\n"
            ));
        }
        self.model_length = model_length;
        let length = animation_length(compiled).max(model_length);
        if (length > 0.0 || r.has_model_animation()) && (self.clock.playing || self.fresh) {
            if let Some(program) = compiled.checked.program.as_ref() {
                let desc = &program.scenes[compiled.scene];
                let t = self.clock.now(length);
                rtc_runtime::animation::apply(r, &rtc_runtime::animation::evaluate(desc, t))?;
                if let (true, Some(orbit)) = (self.moved, orbit) {
                    rtc_runtime::orbit::apply(r, orbit)?;
                }
            }
        }
        if std::mem::take(&mut self.fresh) {
            r.reset_accumulation();
            if let Some(o) = orbit {
                let v = |a: [f32; 3]| format!("({:.3}, {:.3}, {:.3})", a[0], a[1], a[2]);
                term::print(&format!(
                    "[view] camera at {} looking at {}\n",
                    v(o.position),
                    v(o.look_at)
                ));
            }
        }
        if factor > 1 {
            let preview = r.preview(factor)?;
            return Ok((preview.stats, preview.image));
        }
        let stats = r.accumulate(1, &mut |_, _| {})?;
        let image = r.image()?;
        Ok((stats, image))
    }

    /// After a new frame was drawn: the screenshot, and the end after `--exit-after-frames`.
    fn after_draw(&mut self, event_loop: &ActiveEventLoop, capture: Option<present::Capture>) {
        self.undrawn = false;
        if let Some(path) = &self.args.screenshot {
            let format = output_format(path).unwrap_or(Format::Png);
            // What the window shows, read back from its surface; else the image uploaded to it.
            let captured = capture.and_then(|c| {
                let pixels = c
                    .rgba
                    .chunks_exact(4)
                    .map(|p| {
                        let f = |b: u8| srgb_to_linear(f32::from(b) / 255.0);
                        [f(p[0]), f(p[1]), f(p[2]), 1.0]
                    })
                    .collect();
                LinearImage::new(c.width, c.height, pixels).ok()
            });
            let (image, what) = match (&captured, &self.image) {
                (Some(c), _) => (Some(c), "the window"),
                (None, image) => (image.as_ref(), "the image shown"),
            };
            if let Some(image) = image {
                match write_image(path, format, image) {
                    Ok(_) => term::print(&format!(
                        "[view] screenshot {} of {what}: {}\n",
                        self.frames, self.status
                    )),
                    Err(e) => term::eprint(&format!(
                        "{}: screenshot: {e}\n",
                        term::paint("error", 31, self.ctx.color)
                    )),
                }
            }
        }
        if self
            .args
            .exit_after_frames
            .is_some_and(|n| self.frames >= n)
        {
            event_loop.exit();
        }
    }
}

impl ApplicationHandler<UserEvent> for App<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_some() {
            return;
        }
        let [w, h] = match (self.args.render.scene.image_size(), self.session.last()) {
            (Some(s), _) => s,
            (None, Some(c)) => c
                .checked
                .program
                .as_ref()
                .map(|p| {
                    let s = &p.scenes[c.scene].settings;
                    [s.width, s.height]
                })
                .unwrap_or([512, 512]),
            (None, None) => [512, 512],
        };
        let attributes = Window::default_attributes()
            .with_title(format!("rtc view: {}", self.args.path.display()))
            .with_inner_size(winit::dpi::PhysicalSize::new(w.max(1), h.max(1)));
        let window = match event_loop.create_window(attributes) {
            Ok(w) => Arc::new(w),
            Err(e) => return self.fail(event_loop, &format!("cannot open a window: {e}")),
        };
        match present::Presenter::new(Arc::clone(&window), self.args.screenshot.is_some()) {
            Ok(p) => self.presenter = Some(p),
            Err(e) => return self.fail(event_loop, &format!("cannot draw into the window: {e}")),
        }
        self.window = Some(window);
        self.restart();
    }

    fn user_event(&mut self, event_loop: &ActiveEventLoop, event: UserEvent) {
        match event {
            UserEvent::Stop => event_loop.exit(),
            UserEvent::Files(paths) => {
                for p in paths {
                    if self.session.is_relevant(&p) && !self.pending.contains(&p) {
                        self.pending.push(p);
                        self.last_event = Instant::now();
                    }
                }
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                if let Some(p) = &mut self.presenter {
                    p.resize(size.width, size.height);
                }
            }
            WindowEvent::RedrawRequested => {
                let drawn = match &mut self.presenter {
                    Some(p) => p.draw(),
                    None => Ok(None),
                };
                match drawn {
                    Ok(capture) if self.undrawn => self.after_draw(event_loop, capture),
                    Ok(_) => {}
                    Err(e) => term::eprint(&format!(
                        "{}: cannot draw the window: {e}\n",
                        term::paint("warning", 33, self.ctx.color)
                    )),
                }
            }
            // Presses only: not the repeats of a held key, nor the presses winit makes up for
            // keys already down when the window gains focus.
            WindowEvent::KeyboardInput {
                event,
                is_synthetic: false,
                ..
            } if event.state == ElementState::Pressed && !event.repeat => match event.logical_key {
                Key::Named(NamedKey::Escape) => event_loop.exit(),
                Key::Character(c) if c.as_str() == "q" => event_loop.exit(),
                Key::Named(NamedKey::Space) => {
                    let length = self
                        .session
                        .last()
                        .map_or(0.0, animation_length)
                        .max(self.model_length);
                    if length > 0.0 {
                        self.clock.toggle(length);
                        let state = if self.clock.playing {
                            "playing"
                        } else {
                            "paused"
                        };
                        term::print(&format!(
                            "[view] {state} at {:.2} s\n",
                            self.clock.now(length)
                        ));
                        self.restart();
                    }
                }
                _ => {}
            },
            WindowEvent::MouseInput { state, button, .. } => {
                self.drag = match (state, button) {
                    (ElementState::Pressed, MouseButton::Left) => Some(Drag::Orbit),
                    (ElementState::Pressed, MouseButton::Right | MouseButton::Middle) => {
                        Some(Drag::Pan)
                    }
                    _ => None,
                };
            }
            WindowEvent::CursorMoved { position, .. } => {
                let now = (position.x, position.y);
                if let (Some(drag), Some(before), Some(orbit)) =
                    (self.drag, self.cursor, self.orbit.as_mut())
                {
                    let dx = (now.0 - before.0) as f32;
                    let dy = (now.1 - before.1) as f32;
                    match drag {
                        Drag::Orbit => orbit.orbit(dx * 0.01, dy * 0.01),
                        Drag::Pan => orbit.pan(dx * 0.002, dy * 0.002),
                    }
                    self.moved = true;
                    self.moving = true;
                    self.restart();
                }
                self.cursor = Some(now);
            }
            WindowEvent::MouseWheel { delta, .. } => {
                let lines = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                };
                if let Some(orbit) = self.orbit.as_mut() {
                    orbit.zoom(0.9f32.powf(lines));
                    self.moved = true;
                    self.moving = true;
                    self.restart();
                }
            }
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if !self.pending.is_empty() {
            let quiet_at = self.last_event + DEBOUNCE;
            if Instant::now() >= quiet_at {
                self.reload();
            } else {
                event_loop.set_control_flow(ControlFlow::WaitUntil(quiet_at));
                return;
            }
        }
        if self.window.is_some() && self.next_spp.is_some() {
            if let Some(until) = self.settle_until.filter(|_| !self.moving) {
                if Instant::now() < until {
                    event_loop.set_control_flow(ControlFlow::WaitUntil(until));
                    return;
                }
            }
            self.step(event_loop);
        }
        event_loop.set_control_flow(if self.next_spp.is_some() {
            ControlFlow::Poll
        } else {
            ControlFlow::Wait
        });
    }
}

/// Whether this process can hope to open a window, and if not, why.
fn display_missing() -> Option<&'static str> {
    if cfg!(any(
        target_os = "linux",
        target_os = "freebsd",
        target_os = "openbsd"
    )) {
        let set = |v: &str| std::env::var_os(v).is_some_and(|x| !x.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") {
            return Some("neither DISPLAY nor WAYLAND_DISPLAY is set");
        }
    }
    None
}

fn no_display(reason: &str, ctx: &Context) -> Exit {
    term::eprint(&format!(
        "{}: `rtc view` needs a display, and there is none: {reason}\n\
         help: run it in a desktop session, or under a virtual display (`xvfb-run rtc view …`); \
         `rtc watch SCENE -o preview.png` renders previews on every save without a window\n",
        term::paint("error", 31, ctx.color)
    ));
    Exit::Failure
}

/// The event loop, allowed off the main thread (`rtc` runs its commands on a worker thread).
fn event_loop() -> Result<EventLoop<UserEvent>, winit::error::EventLoopError> {
    let mut builder = EventLoop::<UserEvent>::with_user_event();
    #[cfg(any(target_os = "linux", target_os = "freebsd", target_os = "openbsd"))]
    {
        use winit::platform::wayland::EventLoopBuilderExtWayland;
        use winit::platform::x11::EventLoopBuilderExtX11;
        EventLoopBuilderExtX11::with_any_thread(&mut builder, true);
        EventLoopBuilderExtWayland::with_any_thread(&mut builder, true);
    }
    builder.build()
}

/// Runs `rtc view`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    if let Some(path) = &args.screenshot {
        if let Err(e) = crate::args::image_output(path, "the screenshot") {
            return report::usage_error(&e, ctx.color);
        }
    }
    let choice = match args.render.adapter.choice() {
        Ok(c) => c,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    // The roots are made again for each render (`App::render`); here they are only checked.
    if let Err(e) = args.render.assets.roots() {
        return report::usage_error(&e, ctx.color);
    }
    if !args.path.is_file() {
        return report::usage_error(
            &format!("cannot read `{}`: no such file", args.path.display()),
            ctx.color,
        );
    }
    if let Some(reason) = display_missing() {
        return no_display(reason, ctx);
    }
    let mut session = Session::new(
        &args.path,
        args.render.scene.name.clone(),
        &ctx.options,
        Vec::new(),
        None,
        None,
        ctx.color,
    )
    .with_exec(args.exec.model())
    // Every frame of a view counts: the megakernel's are faster (the thesis scene at 960 x 540
    // on lavapipe: half the wavefront model's), for the same time to the first one.
    .with_auto(rtc_compiler::kernel::ExecModel::Megakernel);
    let started = SystemTime::now();
    let first = session.reload(&[]);
    term::eprint(&first.messages);
    if first.status != Status::Built {
        return Exit::Failure;
    }
    term::print(&describe(&first, ctx.color));

    let event_loop = match event_loop() {
        Ok(l) => l,
        Err(e) => return no_display(&e.to_string(), ctx),
    };
    let gpu: &'static Gpu = match Gpu::new(&choice) {
        Ok(g) => Box::leak(Box::new(g)),
        Err(e) => {
            term::eprint(&format!("{}: {e}\n", term::paint("error", 31, ctx.color)));
            return Exit::Failure;
        }
    };
    term::print(&format!("adapter: {}\n", gpu.description()));
    term::print(&format!("host: {}\n", rtc_runtime::gpu::HostCpu::detect()));

    let proxy = event_loop.create_proxy();
    let stop = proxy.clone();
    if let Err(e) = ctrlc::set_handler(move || {
        let _ = stop.send_event(UserEvent::Stop);
    }) {
        term::eprint(&format!(
            "{}: cannot catch Ctrl-C: {e}\n",
            term::paint("warning", 33, ctx.color)
        ));
    }
    let files = proxy.clone();
    let watcher = notify::recommended_watcher(move |res: notify::Result<notify::Event>| {
        if let Ok(event) = res {
            if !matches!(event.kind, notify::EventKind::Access(_)) {
                let _ = files.send_event(UserEvent::Files(event.paths));
            }
        }
    });
    let watcher = match watcher {
        Ok(w) => Some(w),
        Err(e) => {
            term::eprint(&format!(
                "{}: cannot watch files, no hot reload: {e}\n",
                term::paint("warning", 33, ctx.color)
            ));
            None
        }
    };
    let orbit = session.last().and_then(read_orbit);
    let mut app = App {
        args,
        ctx,
        target_spp: 1,
        session,
        gpu,
        renderer: None,
        stale_kernel: false,
        fresh: true,
        clock: Clock::new(true),
        model_length: 0.0,
        watcher,
        dirs: BTreeSet::new(),
        window: None,
        presenter: None,
        image: None,
        next_spp: None,
        orbit,
        moved: false,
        moving: false,
        pass_ms: None,
        settle_until: None,
        drag: None,
        cursor: None,
        pending: Vec::new(),
        last_event: Instant::now(),
        frames: 0,
        undrawn: false,
        status: String::new(),
        exit: Exit::Success,
    };
    app.target_spp = app.wanted_spp();
    if let Some(w) = app.watcher.as_mut() {
        let added = update_dirs(w, &mut app.dirs, &app.session, ctx);
        app.pending = app.session.missed(&added, started);
    }
    if orbit.is_none() {
        term::print(
            "[view] this camera has no `position` and `look_at`: the mouse does not move it\n",
        );
    }
    if let Some(length) = app
        .session
        .last()
        .map(animation_length)
        .filter(|&l| l > 0.0)
    {
        term::print(&format!(
            "[view] the scene is animated: playing its {length:.2} s in a loop (space pauses and refines)\n"
        ));
    }
    if let Err(e) = event_loop.run_app(&mut app) {
        term::eprint(&format!(
            "{}: the window's event loop failed: {e}\n",
            term::paint("error", 31, ctx.color)
        ));
        return Exit::Failure;
    }
    term::print("[view] closed\n");
    app.exit
}

#[cfg(test)]
mod tests {
    use super::*;
    use rtc_runtime::render::PREVIEW_BUDGET_MS;

    #[test]
    fn a_reload_keeps_a_moved_camera_and_follows_the_file_otherwise() {
        let user = Orbit {
            position: [1.0, 2.0, 3.0],
            look_at: [0.0; 3],
        };
        let file = Orbit {
            position: [0.0, 0.0, 9.0],
            look_at: [0.0; 3],
        };
        assert_eq!(
            camera_after_reload(true, Some(user), Some(file)),
            Some(user)
        );
        assert_eq!(
            camera_after_reload(false, Some(user), Some(file)),
            Some(file)
        );
        // A camera without `position`/`look_at` now: nothing to keep.
        assert_eq!(camera_after_reload(true, Some(user), None), None);
    }

    #[test]
    fn a_move_is_shown_reduced_just_enough_to_fit_the_budget() {
        // Before any whole pass, and for passes within the budget: the whole size.
        assert_eq!(preview_factor(None), 1);
        assert_eq!(preview_factor(Some(f64::NAN)), 1);
        assert_eq!(preview_factor(Some(12.0)), 1);
        assert_eq!(preview_factor(Some(PREVIEW_BUDGET_MS)), 1);
        // A quarter of the pixels up to 4 times the budget, a sixteenth up to 16 times.
        assert_eq!(preview_factor(Some(PREVIEW_BUDGET_MS + 1.0)), 2);
        assert_eq!(preview_factor(Some(4.0 * PREVIEW_BUDGET_MS)), 2);
        assert_eq!(preview_factor(Some(430.0)), 4);
        assert_eq!(preview_factor(Some(16.0 * PREVIEW_BUDGET_MS + 1.0)), 8);
        assert_eq!(preview_factor(Some(1e9)), 8);
    }

    #[test]
    fn preview_takes_auto_off_or_a_factor() {
        assert_eq!(parse_preview("auto"), Ok(Preview::Auto));
        assert_eq!(parse_preview("off"), Ok(Preview::Factor(1)));
        assert_eq!(parse_preview("4"), Ok(Preview::Factor(4)));
        assert_eq!(parse_preview("64"), Ok(Preview::Factor(64)));
        for bad in ["0", "65", "-2", "2.5", "", "fast"] {
            assert!(parse_preview(bad).is_err(), "{bad:?}");
        }
    }
}
