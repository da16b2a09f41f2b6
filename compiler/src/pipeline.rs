//! The compile pipeline: every phase from source files to the five target outputs, in order, in one
//! function ([`compile`]).
//!
//! Each phase is a function from data to data plus diagnostics (or a typed error); [`compile`] only
//! calls them in order, stops at the first that fails and records how long each took. The phases:
//!
//! | # | phase | function | data in → data out |
//! |---|---|---|---|
//! | 1 | check the user's files | [`driver::check_paths`] | paths → [`Checked`] (sources, HIR, diagnostics) |
//! | 2 | choose the scene, link it | [`link_scene`] | HIR (+ the JSON of the scene's glTF `model` files) → [`SceneId`], [`Linked`] (kernel configuration) |
//! | 3 | check again, with the kernel | [`driver::check_paths_with_std`] | paths + `std/kernel/` + `rtc:abi`, `rtc:config` → [`Checked`] |
//! | 4 | link again | [`link_scene`] | the second HIR (model files not read again) → [`SceneId`], [`Linked`] |
//! | 5 | lower the render kernel | [`kernel::lower_kernel`] | HIR + link plan → validated, compacted `naga::Module`, bindings |
//! | 6 | lower the bounds kernel (custom geometry only) | [`kernel::lower_kernel`] | the same → `naga::Module` |
//! | 7 | write the targets asked for | [`write_targets`] | modules → WGSL, SPIR-V, HLSL, MSL, GLSL, `manifest.json` |
//!
//! **Why check and link twice.** The framework kernel (`stdlib/kernel/*.rt`) imports `rtc:config`,
//! whose constants (stack sizes, `MAX_DEPTH`, feature switches) are array sizes and folded `if`s in the
//! kernel's code, so the kernel can only be checked once they are known; they come from linking the
//! scene (phase 2), which needs the user's program checked (phase 1). Phase 1 also reports the user's
//! mistakes without the kernel in the way. Phase 3 checks a new program (the user's files plus the
//! kernel), whose struct and function handles are not phase 1's, so phase 4 links again to express the
//! plan in those handles; program ids are the same (same keys, same registry), and so is the
//! configuration. Parsing is not repeated when [`Options::cache`] holds a cache.
//!
//! Callers: `rtc compile` asks for targets and writes [`Compiled::outputs`] to files; the runtime and
//! the other commands use [`kernel::compile_scene`] (this function without targets) and hand the naga
//! modules to wgpu; `rtc watch` writes targets later with [`write_targets`].

use crate::back::{self, BackendError, Target};
use crate::diag::Diagnostic;
use crate::driver::{self, Checked, Options};
use crate::kernel::wavefront::Stage;
use crate::kernel::{
    self, generated, wavefront, CompileFailure, CompiledScene, ExecModel, KernelOptions,
    StageKernel, BOUNDS_ENTRY, KERNEL_ROOTS, RENDER_ENTRY,
};
use crate::link::{registry::Registry, LinkOptions, Linked};
use crate::sema::hir::{ProgramKind, SceneId};
use std::path::PathBuf;

/// What to compile.
#[derive(Clone, Debug)]
pub struct Request<'a> {
    /// The root files (a folder stands for its `.rt` files).
    pub paths: &'a [PathBuf],
    /// Which scene, when the files declare several.
    pub scene: Option<&'a str>,
    /// Compiler options (standard library, cache).
    pub options: &'a Options,
    /// Link options (the unspecialised kernel).
    pub link: &'a LinkOptions,
    /// Kernel options (a debug kernel).
    pub kernel: &'a KernelOptions,
    /// The targets to write in phase 7; none stops after the naga modules.
    pub targets: &'a [Target],
}

/// One file of the output: a target's code for one kernel, or `manifest.json`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Output {
    /// The file name: `kernel.wgsl`, `bounds.spv`, …, `manifest.json`.
    pub name: String,
    /// Its contents (text as UTF-8, SPIR-V as little-endian words).
    pub bytes: Vec<u8>,
}

/// What [`compile`] returns when phases 1 to 6 succeed.
#[derive(Debug)]
pub struct Compiled {
    /// The checked program, link plan and kernel modules.
    pub scene: CompiledScene,
    /// Phase 7: the outputs of [`Request::targets`] (see [`write_targets`]), or why a target could
    /// not be written (a function too large for it, E0806, or an internal error).
    pub outputs: Result<Vec<Output>, BackendError>,
}

/// Every phase of compiling one scene, in order (see the module doc for the table).
pub fn compile(request: &Request<'_>) -> Result<Compiled, Box<CompileFailure>> {
    let mut timings = Timings::default();
    let paths = request.paths;

    // 1. Check the user's files alone.
    let first = timings.time("check the user's files", || {
        driver::check_paths(paths, request.options)
    });
    // 2. Choose the scene and link it: the kernel configuration the kernel is checked with.
    let t = Start::now();
    let mut registry = Registry::default();
    let (first, _, linked) = link_scene(first, request, &mut registry, None)?;
    timings.push("link", t);

    // 3. Check again, with the kernel and the modules generated from the link plan (why twice: see
    //    the module doc).
    let kernel_options = request.options_with_kernel(&linked);
    drop(first);
    let second = timings.time("check with the kernel", || {
        driver::check_paths_with_std(paths, KERNEL_ROOTS, &kernel_options)
    });
    // 4. Link again: the same plan in the second program's handles.
    let (checked, scene, linked) = link_scene(second, request, &mut registry, Some(&linked))?;

    // 5. Lower the render kernel (validated, compacted).
    let render = timings.time("lower the render kernel", || {
        kernel::lower_kernel(&checked, &linked, "render_invocation", RENDER_ENTRY)
    });
    let (render, bindings) = match render {
        Ok(r) => r,
        Err(d) => return Err(failure(checked, vec![*d])),
    };
    // 6. Lower the bounds kernel, when the scene has custom geometry.
    let bounds = if linked.config.has_custom_geometry {
        let bounds = timings.time("lower the bounds kernel", || {
            kernel::lower_kernel(&checked, &linked, "compute_bounds", BOUNDS_ENTRY)
        });
        match bounds {
            Ok((module, _)) => Some(module),
            Err(d) => return Err(failure(checked, vec![*d])),
        }
    } else {
        None
    };
    // 6b. Lower the wavefront model's stage kernels, when the scene runs with it.
    let setting = checked
        .program
        .as_ref()
        .map_or(0, |p| p.scenes[scene].settings.exec);
    let render_weight = kernel::weight::inlined_weight(&render, RENDER_ENTRY).unwrap_or(0);
    let light_megakernel = render_weight < request.kernel.wavefront_min_weight
        && checked
            .program
            .as_ref()
            .is_some_and(|p| kernel::small_built_in_geometry(&p.scenes[scene]));
    // A debug kernel is a megakernel (`rtc bvh`'s passes), whatever the scene asks for.
    let exec = match request.kernel.debug {
        Some(_) => ExecModel::Megakernel,
        // `EXEC_AUTO` (no choice, setting 0) keeps a light megakernel of small geometry.
        None if request.kernel.exec.is_none() && setting == 0 && light_megakernel => {
            ExecModel::Megakernel
        }
        None => ExecModel::resolve(request.kernel.exec, setting, request.kernel.auto),
    };
    let stages = if exec == ExecModel::Wavefront {
        // The render's samples: its size and samples per pixel as the caller sets them, else the
        // scene's own.
        let own = checked.program.as_ref().map(|p| p.scenes[scene].settings);
        let [w, h] = request
            .kernel
            .render_size
            .or(own.map(|s| [s.width, s.height]))
            .unwrap_or([0, 0]);
        let spp = request
            .kernel
            .render_spp
            .or(own.map(|s| s.samples))
            .unwrap_or(0);
        let samples = u64::from(w) * u64::from(h) * u64::from(spp);
        let shadow_rays = request.kernel.shadow_rays.for_samples(samples);
        let accumulate = samples > wavefront::SHADE_ACCUMULATES_MIN_SAMPLES;
        let lowered = timings.time("lower the stage kernels", || {
            let mut stages = Vec::with_capacity(wavefront::STAGES.len());
            // The shade stage comes before the shadow stage, and says whether there is one.
            let mut shade_traces = false;
            for stage in wavefront::STAGES {
                let (module, bindings) = match stage {
                    Stage::Shade => {
                        let (module, bindings, traces) =
                            kernel::lower_shade_stage(&checked, &linked, shadow_rays, accumulate)?;
                        shade_traces = traces;
                        (module, bindings)
                    }
                    Stage::Shadow if shade_traces => continue,
                    _ => kernel::lower_kernel(&checked, &linked, stage.root(), stage.entry())?,
                };
                stages.push(StageKernel {
                    stage,
                    module,
                    bindings,
                });
            }
            Ok::<_, Box<Diagnostic>>(stages)
        });
        match lowered {
            Ok(s) => Some(s),
            Err(d) => return Err(failure(checked, vec![*d])),
        }
    } else {
        None
    };
    let path_words = wavefront::path_words(&linked.config);
    let samples_per_pass = checked
        .program
        .as_ref()
        .and_then(|p| {
            let cam = p.scenes[scene].camera.as_ref()?;
            p.program_for(cam.struct_id, ProgramKind::RayGeneration)
                .map(|e| e.samples.max(1))
        })
        .unwrap_or(1);
    let mut compiled = CompiledScene {
        checked,
        scene,
        linked,
        render,
        bounds,
        bindings,
        samples_per_pass,
        stages,
        path_words,
        exec,
        render_weight,
        timings: Vec::new(),
    };

    // 7. Write the targets asked for.
    let outputs = if request.targets.is_empty() {
        Ok(Vec::new())
    } else {
        timings.time("write the targets", || {
            write_targets(&compiled, request.targets)
        })
    };
    compiled.timings = timings.0;
    Ok(Compiled {
        scene: compiled,
        outputs,
    })
}

impl Request<'_> {
    /// The options of phase 3: the request's, plus the generated modules `rtc:abi` and `rtc:config`
    /// (the scene's kernel configuration).
    fn options_with_kernel(&self, linked: &Linked) -> Options {
        let mut opts = self.options.clone();
        opts.generated
            .insert(generated::ABI_MODULE.to_string(), generated::abi_module());
        opts.generated.insert(
            generated::CONFIG_MODULE.to_string(),
            generated::config_module_with(&linked.config, self.kernel.debug),
        );
        opts
    }
}

/// Phases 2 and 4: chooses the scene of a checked program and links it. `registry` is loaded from
/// the scene's registry file in phase 2 (`earlier` is `None`) and reused as it is in phase 4, so
/// both links give the same ids; phase 4 also reuses what phase 2 read from the scene's glTF
/// `model` files (`earlier`'s [`Linked::models`]). A failure keeps `checked` for rendering the
/// diagnostics.
pub fn link_scene(
    checked: Checked,
    request: &Request<'_>,
    registry: &mut Registry,
    earlier: Option<&Linked>,
) -> Result<(Checked, SceneId, Linked), Box<CompileFailure>> {
    let Some(program) = checked.program.as_ref() else {
        let d = checked.diagnostics.clone();
        return Err(failure(checked, d));
    };
    let scene = match program.select_scene(request.scene) {
        Ok(s) => s,
        Err(e) => {
            let mut checked = checked;
            let d = kernel::scene_choice_diagnostic(&e, &mut checked, request.paths);
            return Err(failure(checked, vec![d]));
        }
    };
    if earlier.is_none() {
        let path = kernel::registry_path(program, scene);
        let key = kernel::registry_key(program, scene);
        *registry = match &request.options.memory {
            Some(files) => {
                let text = files.get(&path).map(String::from_utf8_lossy);
                crate::link::registry::load_scene_text(text.as_deref(), &key).0
            }
            None => crate::link::registry::load_scene(&path, &key).0,
        };
    }
    let known = earlier.map_or(&[][..], |l| l.models.as_slice());
    // In memory, `model` files are read from the same file set as the sources.
    let in_memory;
    let link = match &request.options.memory {
        Some(files) if request.link.memory.is_none() => {
            in_memory = LinkOptions {
                memory: Some(files.clone()),
                ..request.link.clone()
            };
            &in_memory
        }
        _ => request.link,
    };
    match crate::link::link_again(program, scene, registry, link, known) {
        Ok(linked) => Ok((checked, scene, linked)),
        Err(d) => Err(failure(checked, d)),
    }
}

/// Phase 7: the render kernel (and the bounds kernel and the wavefront stage kernels, if any:
/// `wf_trace.wgsl`, …) for every target in `targets`, then
/// `manifest.json`, in that order. The back ends are independent: each output is written on its own
/// thread; the result does not depend on it.
pub fn write_targets(
    compiled: &CompiledScene,
    targets: &[Target],
) -> Result<Vec<Output>, BackendError> {
    let resources = crate::abi::resources(compiled.bindings.iter().copied());
    let mut modules = vec![("kernel", &compiled.render, RENDER_ENTRY, resources.clone())];
    if let Some(b) = &compiled.bounds {
        modules.push(("bounds", b, BOUNDS_ENTRY, resources));
    }
    for s in compiled.stages.iter().flatten() {
        let resources = crate::abi::resources(s.bindings.iter().copied());
        modules.push((s.stage.entry(), &s.module, s.stage.entry(), resources));
    }
    let jobs: Vec<_> = modules
        .iter()
        .flat_map(|m| targets.iter().map(move |&t| (m, t)))
        .collect();
    type Job<'m> = (
        &'m (&'m str, &'m naga::Module, &'m str, Vec<back::Resource>),
        Target,
    );
    fn write_one(
        &((stem, module, entry, ref resources), t): &Job<'_>,
    ) -> Result<Output, BackendError> {
        let bytes = back::write(module, t, entry, resources)?;
        let ext = t.file_name().rsplit('.').next().unwrap_or("out");
        Ok(Output {
            name: format!("{stem}.{ext}"),
            bytes,
        })
    }
    // WebAssembly has no threads: the outputs are written one after another there.
    let results: Vec<Result<Output, BackendError>> = if cfg!(target_arch = "wasm32") {
        jobs.iter().map(write_one).collect()
    } else {
        std::thread::scope(|scope| {
            let handles: Vec<_> = jobs
                .iter()
                .map(|job| scope.spawn(move || write_one(job)))
                .collect();
            handles
                .into_iter()
                // A panic here is a bug outside naga's writers (those are caught by `back::write`):
                // it goes on as the panic it is.
                .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
                .collect()
        })
    };
    let mut outputs = results.into_iter().collect::<Result<Vec<_>, _>>()?;
    outputs.push(Output {
        name: "manifest.json".to_string(),
        bytes: kernel::manifest::manifest_json(compiled).into_bytes(),
    });
    Ok(outputs)
}

fn failure(checked: Checked, diagnostics: Vec<Diagnostic>) -> Box<CompileFailure> {
    Box::new(CompileFailure {
        checked,
        diagnostics,
    })
}

/// When a phase started. WebAssembly (`wasm32-unknown-unknown`) has no clock without its host
/// (`std::time::Instant::now` panics there): there every phase takes 0 ms.
#[derive(Clone, Copy)]
struct Start(#[cfg(not(target_arch = "wasm32"))] std::time::Instant);

impl Start {
    #[cfg(not(target_arch = "wasm32"))]
    fn now() -> Start {
        Start(std::time::Instant::now())
    }

    #[cfg(target_arch = "wasm32")]
    fn now() -> Start {
        Start()
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn elapsed_ms(self) -> f64 {
        self.0.elapsed().as_secs_f64() * 1e3
    }

    #[cfg(target_arch = "wasm32")]
    fn elapsed_ms(self) -> f64 {
        0.0
    }
}

/// How long each phase took, in milliseconds, in order.
#[derive(Default)]
struct Timings(Vec<(&'static str, f64)>);

impl Timings {
    fn push(&mut self, name: &'static str, start: Start) {
        self.0.push((name, start.elapsed_ms()));
    }

    fn time<T>(&mut self, name: &'static str, phase: impl FnOnce() -> T) -> T {
        let start = Start::now();
        let out = phase();
        self.push(name, start);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example(name: &str) -> PathBuf {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../examples")
            .join(name)
            .join("scene.rt")
    }

    fn compile_example(name: &str, targets: &[Target]) -> Compiled {
        let paths = [example(name)];
        let request = Request {
            paths: &paths,
            scene: None,
            options: &Options::default(),
            link: &LinkOptions::default(),
            kernel: &KernelOptions::default(),
            targets,
        };
        match compile(&request) {
            Ok(c) => c,
            Err(f) => panic!(
                "{}",
                crate::diag::render_human(&f.checked.sources, &f.diagnostics, false)
            ),
        }
    }

    #[test]
    fn the_kernel_checks_with_a_scene() {
        let c = compile_example("hello", &[]);
        assert!(c.scene.checked.program.is_some());
        assert!(c.scene.linked.config.has_secondary_rays);
        assert_eq!(c.scene.linked.config.max_spawn, 1);
        assert_eq!(c.outputs, Ok(Vec::new()));
        let phases: Vec<&str> = c.scene.timings.iter().map(|(n, _)| *n).collect();
        assert_eq!(
            phases,
            [
                "check the user's files",
                "link",
                "check with the kernel",
                "lower the render kernel"
            ]
        );
    }

    /// The scene-level traversal stack holds one entry per object but one (a binary BVH over `n`
    /// objects has at most `n - 1` inner nodes on a path); a scene whose glTF models bring objects
    /// the compiler cannot count gets the builder's depth bound.
    #[test]
    fn the_scene_level_stack_is_sized_by_the_object_count() {
        let config = |name: &str| compile_example(name, &[]).scene.linked.config;
        // 17 bunnies and a floor.
        let thesis = config("thesis_scene");
        assert_eq!(thesis.tlas_stack, 17);
        assert_eq!(thesis.blas_stack, crate::link::MAX_BVH_DEPTH);
        assert_eq!(config("gltf_scene").tlas_stack, crate::link::MAX_BVH_DEPTH);
    }

    #[test]
    fn hello_compiles_to_every_target() {
        let c = compile_example("hello", &Target::ALL);
        let outputs = c.outputs.unwrap_or_else(|e| panic!("{e}"));
        let names: Vec<&str> = outputs.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "kernel.wgsl",
                "kernel.spv",
                "kernel.hlsl",
                "kernel.metal",
                "kernel.comp",
                "manifest.json"
            ]
        );
        // The same as writing each target on its own.
        let resources = crate::abi::resources(c.scene.bindings.iter().copied());
        for (t, out) in Target::ALL.into_iter().zip(&outputs) {
            let alone = back::write(&c.scene.render, t, RENDER_ENTRY, &resources);
            assert_eq!(alone.as_ref(), Ok(&out.bytes), "{}", t.name());
        }
    }
}
