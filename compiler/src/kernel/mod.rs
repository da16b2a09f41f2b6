//! Kernel assembly: from checked sources and a scene to the scene's specialised `naga::Module`.
//!
//! [`compile_scene`] is the whole compile of one scene, as a list of phases:
//! 1. check the user's files (`driver::check_paths`);
//! 2. choose the scene and link it (`link::link`): used types with registry ids, kernel configuration;
//! 3. check again with the framework kernel (`stdlib/kernel/`) and the generated modules `rtc:abi` and
//!    `rtc:config` (see [`generated`]), so the kernel's array sizes and feature switches are the scene's;
//! 4. lower the kernel's entry points, which pulls in exactly the programs, dispatchers, loaders and
//!    bindings the scene reaches;
//! 5. validate.
//!
//! The result, [`CompiledScene`], is what `rtc compile` writes out and what the runtime runs.

pub mod dispatch;
mod entry;
pub mod generated;
pub mod intrinsics;
pub mod manifest;

use crate::abi::BindingDesc;
use crate::diag::Diagnostic;
use crate::driver::{Checked, Options};
use crate::link::{LinkOptions, Linked};
use crate::lower::{LowerError, Lowerer};
use crate::sema::hir::{Program, ProgramKind, SceneId};
use intrinsics::KernelHooks;
use std::path::PathBuf;

/// A compiled scene: the checked program, the link plan and the kernel modules.
#[derive(Debug)]
pub struct CompiledScene {
    /// The checked program (with the framework kernel), its sources and warnings.
    pub checked: Checked,
    /// The scene that was compiled.
    pub scene: SceneId,
    /// The link plan.
    pub linked: Linked,
    /// The render kernel: entry point [`RENDER_ENTRY`].
    pub render: naga::Module,
    /// The bounds kernel (entry point [`BOUNDS_ENTRY`]), when the scene has custom geometry.
    pub bounds: Option<naga::Module>,
    /// The bindings the render kernel declares, in binding order.
    pub bindings: Vec<&'static BindingDesc>,
    /// Samples per pixel one pass of the render kernel takes (the camera program's `samples`).
    pub samples_per_pass: u32,
    /// How long each phase of the compile took, in milliseconds, in order.
    pub timings: Vec<(&'static str, f64)>,
}

fn ms_since(t: std::time::Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The render kernel's entry point.
pub const RENDER_ENTRY: &str = "render";
/// The bounds kernel's entry point.
pub const BOUNDS_ENTRY: &str = "bounds";
/// Workgroup size of the render kernel (pixels in x and y).
pub const RENDER_WORKGROUP: [u32; 2] = [8, 8];
/// Workgroup size of the bounds kernel (objects).
pub const BOUNDS_WORKGROUP: u32 = 64;

/// What a debug kernel writes to the accumulation buffer instead of radiance. A debug kernel
/// traces one camera ray per pixel (the pass's first sample; no shading, no secondary or shadow
/// rays) and adds one `vec4f` per pixel to `accum` (a zeroed buffer after one pass holds exactly
/// that value). Normal kernels (`None`) contain none of this code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DebugMode {
    /// `x` = BVH nodes visited (scene level and object level: one per node the traversal loop
    /// enters, the root included, not counting a scene root the ray misses), `y` = primitives
    /// tested (triangles and `@intersection` calls), `z` = `t` of the closest accepted hit or -1,
    /// `w` = the hit object's index in the scene (`Hit.instance`) or -1.
    Counts,
    /// `xyz` = the camera ray's origin (world space), `w` = its `tmin`.
    RayOrigin,
    /// `xyz` = the camera ray's direction as the camera program returned it (not renormalised),
    /// `w` = its `tmax` (`+inf` when unbounded).
    RayDirection,
}

/// Options of the kernel itself (beyond the link plan).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct KernelOptions {
    /// Build a debug kernel that writes [`DebugMode`] values instead of radiance.
    pub debug: Option<DebugMode>,
}

/// Why a scene could not be compiled: the diagnostics (with the sources to render them).
#[derive(Debug)]
pub struct CompileFailure {
    /// Everything that was checked, for rendering the diagnostics.
    pub checked: Checked,
    /// The errors (and warnings).
    pub diagnostics: Vec<Diagnostic>,
}

/// The framework kernel's files, checked with every scene.
pub const KERNEL_ROOTS: &[&str] = &["std/kernel/trace.rt"];

/// Phases 1–3: checks the user's files, links the scene and checks again with the kernel.
pub fn check_with_kernel(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
) -> Result<(Checked, SceneId, Linked), Box<CompileFailure>> {
    check_with_kernel_timed(
        paths,
        scene,
        options,
        link_options,
        &KernelOptions::default(),
        &mut Vec::new(),
    )
}

/// [`check_with_kernel`], recording the time of each phase in `timings`.
pub fn check_with_kernel_timed(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
    kernel_options: &KernelOptions,
    timings: &mut Vec<(&'static str, f64)>,
) -> Result<(Checked, SceneId, Linked), Box<CompileFailure>> {
    let t = std::time::Instant::now();
    let fail = |checked: Checked, diagnostics: Vec<Diagnostic>| {
        Box::new(CompileFailure {
            checked,
            diagnostics,
        })
    };
    let first = crate::driver::check_paths(paths, options);
    timings.push(("check the user's files", ms_since(t)));
    let t = std::time::Instant::now();
    let Some(program) = first.program.as_ref() else {
        let d = first.diagnostics.clone();
        return Err(fail(first, d));
    };
    let scene_id = match program.select_scene(scene) {
        Ok(s) => s,
        Err(e) => {
            let mut first = first;
            let d = vec![scene_choice_diagnostic(&e, &mut first, paths)];
            return Err(fail(first, d));
        }
    };
    let registry_path = registry_path(program, scene_id);
    let (mut registry, _) =
        crate::link::registry::load_scene(&registry_path, &registry_key(program, scene_id));
    let linked = match crate::link::link(program, scene_id, &mut registry, link_options) {
        Ok(l) => l,
        Err(d) => return Err(fail(first, d)),
    };
    timings.push(("link", ms_since(t)));
    let t = std::time::Instant::now();
    let mut opts = options.clone();
    opts.generated
        .insert(generated::ABI_MODULE.to_string(), generated::abi_module());
    opts.generated.insert(
        generated::CONFIG_MODULE.to_string(),
        generated::config_module_with(&linked.config, kernel_options.debug),
    );
    let second = crate::driver::check_paths_with_std(paths, KERNEL_ROOTS, &opts);
    timings.push(("check with the kernel", ms_since(t)));
    let Some(program) = second.program.as_ref() else {
        let d = second.diagnostics.clone();
        return Err(fail(second, d));
    };
    // Ids are the same (same keys, same registry); struct and function handles are the second check's.
    let scene_id = match program.select_scene(scene) {
        Ok(s) => s,
        Err(e) => {
            let mut second = second;
            let d = vec![scene_choice_diagnostic(&e, &mut second, paths)];
            return Err(fail(second, d));
        }
    };
    let linked = match crate::link::link(program, scene_id, &mut registry, link_options) {
        Ok(l) => l,
        Err(d) => return Err(fail(second, d)),
    };
    Ok((second, scene_id, linked))
}

/// E0706 for an ambiguous or unknown scene name; E0703 when the files declare no scene at all.
/// Both are located in the user's files: an unknown name at the scenes there are, no scene at the
/// start of the (first) user file, or, when `paths` held no `.rt` file at all (an empty folder),
/// at an empty source named after `paths`, added to `checked`'s sources for the purpose.
fn scene_choice_diagnostic(
    e: &crate::sema::hir::SceneChoiceError,
    checked: &mut Checked,
    paths: &[PathBuf],
) -> Diagnostic {
    use crate::sema::hir::SceneChoiceError as C;
    let program = checked.program.as_ref();
    let root_file = program.and_then(|p| p.modules.iter().find(|m| m.is_root).map(|m| m.file));
    let scenes: Vec<crate::source::Span> = program
        .map(|p| {
            p.scenes
                .iter()
                .filter(|(_, s)| p.modules[s.module.index()].is_root)
                .map(|(_, s)| s.span)
                .collect()
        })
        .unwrap_or_default();
    let shown: Vec<String> = paths.iter().map(|p| format!("`{}`", p.display())).collect();
    let shown = shown.join(", ");
    match e {
        C::NotFound { name, available } => {
            let names: Vec<String> = available.iter().map(|n| format!("`{n}`")).collect();
            let message = format!("no scene named `{name}` in {shown}");
            match scenes.split_first() {
                Some((first, rest)) => {
                    let mut d = Diagnostic::error(crate::diag::codes::E0706, message, *first)
                        .with_label(format!("a scene, not `{name}`"));
                    for s in rest {
                        d = d.with_secondary(*s, "another scene");
                    }
                    d.with_help(format!(
                        "the scenes are {}; choose one with `--scene NAME`",
                        names.join(", ")
                    ))
                }
                None => no_scene(checked, root_file, &shown, message),
            }
        }
        _ => e.to_diagnostic().unwrap_or_else(|| {
            let message = format!("there is no scene to compile in {shown}");
            no_scene(checked, root_file, &shown, message)
        }),
    }
}

/// E0703 (no scene) at the start of `file`, or of an empty source named `shown` when the paths
/// gave no file.
fn no_scene(
    checked: &mut Checked,
    file: Option<crate::source::FileId>,
    shown: &str,
    message: String,
) -> Diagnostic {
    let (file, help) = match file {
        Some(f) => (
            f,
            "declare one: `scene name { camera …  object … }` (see spec/scenes.md)".to_string(),
        ),
        None => (
            checked
                .sources
                .add(shown.trim_matches('`').to_string(), None, String::new()),
            format!("{shown} holds no `.rt` file; give a scene file, or a folder of them"),
        ),
    };
    Diagnostic::error(
        crate::diag::codes::E0703,
        message,
        crate::source::Span::new(file, 0, 0),
    )
    .with_help(help)
}

/// Writes the scene's program registry (its part of `rtc.registry.json` beside its file) if it
/// changed.
pub fn save_registry(c: &CompiledScene) -> std::io::Result<()> {
    let Some(program) = c.checked.program.as_ref() else {
        return Ok(());
    };
    let path = registry_path(program, c.scene);
    let key = registry_key(program, c.scene);
    let (mut registry, _) = crate::link::registry::load_scene(&path, &key);
    // Re-linking against the file's registry records exactly the ids this compile used.
    let _ = crate::link::link(program, c.scene, &mut registry, &LinkOptions::default());
    crate::link::registry::save_scene(&path, &key, &registry)
}

/// The scene's key in its registry file: the declaring file's name and the scene's name.
pub fn registry_key(program: &crate::sema::hir::Program, scene: SceneId) -> String {
    let s = &program.scenes[scene];
    let file = program.modules[s.module.index()]
        .path
        .as_deref()
        .and_then(std::path::Path::file_name)
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    crate::link::registry::scene_key(&file, &s.name)
}

/// The registry file of a scene: `rtc.registry.json` in the folder of the file that declares it.
pub fn registry_path(program: &crate::sema::hir::Program, scene: SceneId) -> PathBuf {
    let module = &program.modules[program.scenes[scene].module.index()];
    module
        .path
        .as_deref()
        .and_then(std::path::Path::parent)
        .unwrap_or(std::path::Path::new("."))
        .join(crate::link::registry::FILE_NAME)
}

/// Compiles the scene `scene` (or the only scene) of the given root files.
pub fn compile_scene(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
) -> Result<CompiledScene, Box<CompileFailure>> {
    compile_scene_with(
        paths,
        scene,
        options,
        link_options,
        &KernelOptions::default(),
    )
}

/// [`compile_scene`] with kernel options (a debug kernel: [`KernelOptions::debug`]).
pub fn compile_scene_with(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
    kernel_options: &KernelOptions,
) -> Result<CompiledScene, Box<CompileFailure>> {
    let mut timings = Vec::new();
    let (checked, scene_id, linked) = check_with_kernel_timed(
        paths,
        scene,
        options,
        link_options,
        kernel_options,
        &mut timings,
    )?;
    let built = match checked.program.as_ref() {
        Some(program) => lower_kernels(program, &checked.sources, &linked, &mut timings),
        None => Err(dispatch::kernel_error("the checked program is missing")),
    };
    match built {
        Ok((render, bounds, bindings)) => {
            let samples_per_pass = checked
                .program
                .as_ref()
                .and_then(|p| {
                    let cam = p.scenes[scene_id].camera.as_ref()?;
                    p.program_for(cam.struct_id, ProgramKind::RayGeneration)
                        .map(|e| e.samples.max(1))
                })
                .unwrap_or(1);
            Ok(CompiledScene {
                checked,
                scene: scene_id,
                linked,
                render,
                bounds,
                bindings,
                samples_per_pass,
                timings,
            })
        }
        Err(e) => {
            let d = match checked.program.as_ref() {
                Some(p) => e.to_diagnostic(p),
                None => Diagnostic::error(
                    crate::diag::codes::ICE,
                    e.to_string(),
                    crate::source::Span::default(),
                ),
            };
            Err(Box::new(CompileFailure {
                checked,
                diagnostics: vec![d],
            }))
        }
    }
}

/// Phases 4 and 5: lowers the render kernel (and the bounds kernel when the scene has custom geometry)
/// and validates them.
/// The modules [`lower_kernels`] builds: render, bounds (if any), and the render kernel's bindings.
type Kernels = (
    naga::Module,
    Option<naga::Module>,
    Vec<&'static BindingDesc>,
);

fn lower_kernels(
    program: &Program,
    sources: &crate::source::SourceMap,
    linked: &Linked,
    timings: &mut Vec<(&'static str, f64)>,
) -> Result<Kernels, LowerError> {
    let t = std::time::Instant::now();
    let render_invocation = intrinsics::kernel_fn(program, "render_invocation")?;
    let mut hooks = KernelHooks {
        program,
        linked,
        config: linked.config,
        generated: dispatch::Generated::default(),
    };
    let mut cx = Lowerer::new(program, sources);
    let f = cx.ensure_function(render_invocation, &mut hooks)?;
    entry::render_entry(&mut cx, f)?;
    let bindings = hooks.generated.used_bindings();
    let mut render = cx.into_module();
    timings.push(("lower to naga IR", ms_since(t)));
    let t = std::time::Instant::now();
    crate::lower::validate(&render, sources)?;
    // Compaction drops types and constants nothing uses, so outputs (and their snapshots) change only
    // when the code does.
    naga::compact::compact(&mut render, naga::compact::KeepUnused::No);
    timings.push(("validate and compact", ms_since(t)));
    let t = std::time::Instant::now();

    let bounds = if linked.config.has_custom_geometry {
        let compute_bounds = intrinsics::kernel_fn(program, "compute_bounds")?;
        let mut hooks = KernelHooks {
            program,
            linked,
            config: linked.config,
            generated: dispatch::Generated::default(),
        };
        let mut cx = Lowerer::new(program, sources);
        let f = cx.ensure_function(compute_bounds, &mut hooks)?;
        entry::bounds_entry(&mut cx, f)?;
        let mut module = cx.into_module();
        crate::lower::validate(&module, sources)?;
        naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
        Some(module)
    } else {
        None
    };
    if bounds.is_some() {
        timings.push(("bounds kernel", ms_since(t)));
    }
    Ok((render, bounds, bindings))
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

    #[test]
    fn the_kernel_checks_with_a_scene() {
        let r = check_with_kernel(
            &[example("hello")],
            None,
            &Options::default(),
            &LinkOptions::default(),
        );
        match r {
            Ok((checked, _, linked)) => {
                assert!(checked.program.is_some());
                assert!(linked.config.has_secondary_rays);
                assert_eq!(linked.config.max_spawn, 1);
            }
            Err(f) => panic!(
                "{}",
                crate::diag::render_human(&f.checked.sources, &f.diagnostics, false)
            ),
        }
    }

    /// The scene-level traversal stack holds one entry per object but one (a binary BVH over `n`
    /// objects has at most `n - 1` inner nodes on a path); a scene whose glTF models bring objects
    /// the compiler cannot count gets the builder's depth bound.
    #[test]
    fn the_scene_level_stack_is_sized_by_the_object_count() {
        let config = |name: &str| match check_with_kernel(
            &[example(name)],
            None,
            &Options::default(),
            &LinkOptions::default(),
        ) {
            Ok((_, _, linked)) => linked.config,
            Err(f) => panic!(
                "{}",
                crate::diag::render_human(&f.checked.sources, &f.diagnostics, false)
            ),
        };
        // 17 bunnies and a floor.
        assert_eq!(config("thesis_scene").tlas_stack, 17);
        assert_eq!(
            config("thesis_scene").blas_stack,
            crate::link::MAX_BVH_DEPTH
        );
        assert_eq!(config("gltf_scene").tlas_stack, crate::link::MAX_BVH_DEPTH);
    }
}

#[cfg(test)]
mod compile_tests {
    use super::*;
    use crate::back::Target;

    #[test]
    fn hello_compiles_to_every_target() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/hello/scene.rt");
        let c = match compile_scene(&[path], None, &Options::default(), &LinkOptions::default()) {
            Ok(c) => c,
            Err(f) => panic!(
                "{}",
                crate::diag::render_human(&f.checked.sources, &f.diagnostics, false)
            ),
        };
        let resources = crate::abi::resources(c.bindings.iter().copied());
        for t in Target::ALL {
            if let Err(e) = crate::back::write(&c.render, t, RENDER_ENTRY, &resources) {
                panic!("{}: {e}", t.name());
            }
        }
    }
}
