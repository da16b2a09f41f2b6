//! Linking a scene: which types and programs the kernel for one scene needs, with stable ids, and the
//! kernel's configuration.
//!
//! Input: a checked [`hir::Program`] and one of its scenes. Output: a [`Linked`] plan that lowering
//! follows to build the scene's kernel:
//! - the **used types** per role (the scene's camera and background, its objects' custom geometries and
//!   materials, its lights, and the standard-library types its glTF `model` files hold: [`model`]
//!   reads each file's JSON), each with its id from the [`registry`] and its programs;
//! - the **kernel configuration** ([`KernelConfig`]): stack depth from the scene's `max_depth`, the
//!   per-hit ray array size from the largest spawn bound of the used `@secondary_rays` programs (clamped
//!   by `max_rays_per_hit`), and which features the scene uses at all (secondary rays, any-hit, custom
//!   geometry, triangle meshes, media, a background);
//! - what was **left out** and why, and what each model file held, for `manifest.json`.
//!
//! With [`LinkOptions::all_programs`], every role struct of the program is linked (the unspecialised
//! kernel, for comparison) and every feature is on.
//!
//! Invariants: the plan is deterministic (types sorted by registry id; for the same model files);
//! the model types linked cover what the runtime makes of the files as they were read (a file not
//! read links them all); every used type has every
//! program its role requires, otherwise linking reports E0901 at the scene entry that uses it.

pub mod model;
pub mod registry;

pub use model::{ModelLink, ModelPart, ModelRead, ModelType, MODEL_TYPES};

use crate::confine::AssetRoots;
use crate::diag::{codes, Diagnostic};
use crate::sema::hir::{self, ConstValue, ProgramKind, Role, SceneId, StructId};
use crate::source::Span;
use registry::Registry;
use std::collections::BTreeMap;

/// Options of the link step.
#[derive(Clone, Debug, Default)]
pub struct LinkOptions {
    /// Link every role struct and program of the program, not only what the scene uses.
    pub all_programs: bool,
    /// The folders besides the scene's own that a `model` file may be read from (the runtime's
    /// `--asset-root`s): the link step reads each model file's glTF metadata with the runtime's
    /// rules ([`model`]), so a render must pass the roots it renders with.
    pub asset_roots: AssetRoots,
    /// Read `model` files from this in-memory set instead of the disk (the compiler in
    /// WebAssembly; [`crate::driver::Options::memory`]); a file not in it is not read.
    pub memory: Option<std::sync::Arc<crate::source::MemoryFiles>>,
}

/// A type the kernel dispatches on.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkedType {
    /// The struct.
    pub struct_id: StructId,
    /// Its role.
    pub role: Role,
    /// Its id in the dispatch switches and instance records (from the registry).
    pub id: u32,
    /// Its registry key (`material:std/materials/lambert.rt::Lambert`).
    pub key: String,
    /// Its programs, in [`ProgramKind`] order.
    pub programs: Vec<(ProgramKind, hir::FnId)>,
}

/// The compile-time constants of the kernel for one scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KernelConfig {
    /// Generations of secondary rays below a camera ray.
    pub max_depth: u32,
    /// Size of a frame's spawned-ray arrays.
    pub max_spawn: u32,
    /// Frames of the secondary-ray stack.
    pub stack_size: u32,
    /// Entries of the scene-level traversal stack.
    pub tlas_stack: u32,
    /// Entries of the object-level traversal stack.
    pub blas_stack: u32,
    /// Some used material has a `@secondary_rays` program (and `max_depth > 0`).
    pub has_secondary_rays: bool,
    /// Secondary rays run as an iterative path loop instead of the back-tracking stack: every
    /// `@secondary_rays` program spawns at most one ray, every such material's `@closest_hit` is
    /// additive in `secondary` (`ProgramEntry::additive_secondary`), and no material has a
    /// `@medium`. A hit is then shaded before its ray is traced, and the ray's weight is carried
    /// as the path's throughput (no frames); the result is the same estimator.
    pub path_loop: bool,
    /// With `path_loop`: depth of the first ray Russian roulette may end (the scene's
    /// `roulette_depth`; 0: never).
    pub roulette_depth: u32,
    /// With `path_loop`: the megakernel starts a lane's next sample as soon as its path ends
    /// (`render_pixel`), because one material type continues paths. Where several do, a lane's
    /// bounces fall out of step with its neighbours' and a SIMD batch runs several materials'
    /// code a step, which cost more than the idle lanes it saves (pbr_path on lavapipe: 0.89 and
    /// 0.91 of the frame without it; cornell_path 0.86 and 0.83 with it).
    pub regenerate_paths: bool,
    /// Some used material has an `@any_hit` program.
    pub has_any_hit: bool,
    /// Some object has a custom (`@geometry`) geometry.
    pub has_custom_geometry: bool,
    /// Some object is a triangle mesh (or a model brings meshes).
    pub has_meshes: bool,
    /// Some material reads per-vertex extras (tangents, a second uv set, colours: a glTF
    /// `GltfDetailMaterial`), so `finish_hit` keeps what they need (`hit_extra_store`).
    pub has_vertex_extras: bool,
    /// Some used material has a `@medium` program.
    pub has_media: bool,
    /// Some used material's `@any_hit` program calls `absorb`: shadow rays sum the optical depth
    /// of the media they cross and `shadow` returns the transmittance.
    pub has_absorb: bool,
    /// The scene has a background.
    pub has_background: bool,
    /// Some object may cull back faces in traversal (`GpuInstance` `FLAG_CULL_BACK`): a model file of the scene holds an opaque single-sided material
    /// ([`ModelPart::SingleSidedMaterial`]).
    pub cull_back_faces: bool,
}

impl KernelConfig {
    /// The configuration of the kernel with every feature on (`--all-programs`, and checking the
    /// kernel on its own).
    pub fn unspecialised() -> KernelConfig {
        KernelConfig {
            max_depth: 4,
            max_spawn: 4,
            stack_size: 4,
            tlas_stack: MAX_BVH_DEPTH,
            blas_stack: MAX_BVH_DEPTH,
            has_secondary_rays: true,
            path_loop: false,
            roulette_depth: 2,
            regenerate_paths: false,
            has_any_hit: true,
            has_custom_geometry: true,
            has_meshes: true,
            has_vertex_extras: true,
            has_media: true,
            has_absorb: true,
            has_background: true,
            cull_back_faces: true,
        }
    }
}

/// The deepest BVH the traversal stacks can handle; the BVH builder guarantees it.
pub const MAX_BVH_DEPTH: u32 = 64;

/// Entries the scene-level traversal stack needs: a binary BVH over `n` objects has at most `n - 1`
/// inner nodes on a path from its root, and the stack holds at most one deferred child per inner
/// node of the path; so `n - 1` (at least 1), and at most [`MAX_BVH_DEPTH`]. A scene with glTF
/// `model` entries gets `MAX_BVH_DEPTH`: their objects are only known when the files are read.
/// (The object-level stack stays at `MAX_BVH_DEPTH`: meshes are read after the kernel is
/// compiled.)
pub fn tlas_stack_bound(desc: &hir::SceneDesc) -> u32 {
    if !desc.models.is_empty() {
        return MAX_BVH_DEPTH;
    }
    let objects = u32::try_from(desc.objects.len()).unwrap_or(u32::MAX);
    objects.saturating_sub(1).clamp(1, MAX_BVH_DEPTH)
}

/// Something left out of the kernel, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LeftOut {
    /// `program`, `type` or `feature`.
    pub kind: &'static str,
    /// What (a program or type name, or a feature).
    pub name: String,
    /// Why.
    pub reason: String,
}

/// The link plan for one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Linked {
    /// The scene.
    pub scene: SceneId,
    /// Used types, by role, sorted by id.
    pub types: BTreeMap<Role, Vec<LinkedType>>,
    /// The kernel's constants.
    pub config: KernelConfig,
    /// What was left out.
    pub left_out: Vec<LeftOut>,
    /// The scene's `model` entries and what their files hold (what decided the model types
    /// linked).
    pub models: Vec<ModelLink>,
    /// The model types linked because of those entries, in [`MODEL_TYPES`] order (a type the
    /// scene also names in an entry of its own is linked either way).
    pub model_types: Vec<&'static str>,
}

impl Linked {
    /// The linked type of a struct, if it is used.
    pub fn type_of(&self, s: StructId) -> Option<&LinkedType> {
        self.types.values().flatten().find(|t| t.struct_id == s)
    }

    /// Every used program, in a deterministic order.
    pub fn programs(&self) -> impl Iterator<Item = (ProgramKind, hir::FnId, &LinkedType)> {
        self.types
            .values()
            .flatten()
            .flat_map(|t| t.programs.iter().map(move |&(k, f)| (k, f, t)))
    }
}

/// The registry namespace of a role.
fn namespace(role: Role) -> &'static str {
    role.name()
}

/// The registry key of a struct.
pub fn type_key(program: &hir::Program, s: StructId) -> String {
    let st = &program.structs[s];
    let module = &program.modules[st.module.index()].name;
    let role = st.role.map(Role::name).unwrap_or("plain");
    format!("{role}:{module}::{}", st.name)
}

/// The struct of one of [`MODEL_TYPES`] in `program`, if its module was loaded.
pub fn model_type(program: &hir::Program, module: &str, name: &str) -> Option<StructId> {
    program.structs.iter().find_map(|(s, st)| {
        (st.name == name && program.modules[st.module.index()].name == module).then_some(s)
    })
}

/// The programs a role requires.
fn required(role: Role) -> &'static [ProgramKind] {
    match role {
        Role::Camera => &[ProgramKind::RayGeneration],
        Role::Geometry => &[ProgramKind::Intersection, ProgramKind::Bounds],
        Role::Material => &[ProgramKind::ClosestHit],
        Role::Light => &[ProgramKind::Light],
        Role::Background => &[ProgramKind::Miss],
    }
}

/// Links `scene` of `program`, updating `registry`.
pub fn link(
    program: &hir::Program,
    scene: SceneId,
    registry: &mut Registry,
    options: &LinkOptions,
) -> Result<Linked, Vec<Diagnostic>> {
    link_again(program, scene, registry, options, &[])
}

/// [`link`], reusing what an earlier link of the same scene read from its model files (`known`,
/// that link's [`Linked::models`]), so a file is read once per compile.
pub fn link_again(
    program: &hir::Program,
    scene: SceneId,
    registry: &mut Registry,
    options: &LinkOptions,
    known: &[ModelLink],
) -> Result<Linked, Vec<Diagnostic>> {
    let desc = &program.scenes[scene];
    // Used structs, each with the span of the first scene entry that uses it.
    let mut used: BTreeMap<StructId, Span> = BTreeMap::new();
    let mut note = |s: StructId, span: Span| {
        used.entry(s).or_insert(span);
    };
    if let Some(cam) = &desc.camera {
        note(cam.struct_id, cam.span);
    }
    if let Some(bg) = &desc.background {
        note(bg.struct_id, bg.span);
    }
    let mut has_meshes = !desc.models.is_empty();
    let mut has_custom = false;
    for obj in &desc.objects {
        match &obj.geometry {
            hir::Geometry::Mesh(_) => has_meshes = true,
            hir::Geometry::Custom(inst) => {
                has_custom = true;
                note(inst.struct_id, inst.span);
            }
        }
        note(obj.material.struct_id, obj.material.span);
    }
    for light in &desc.lights {
        note(light.struct_id, light.span);
    }
    // A model type is linked when some model file of the scene brings its part (every one, for a
    // file that could not be read), at the first such entry; the camera only for a scene without
    // a `camera` entry.
    let models = model::read_models(program, desc, options, known);
    let mut model_types = Vec::new();
    for t in MODEL_TYPES {
        if t.part == ModelPart::PerspectiveCamera && desc.camera.is_some() {
            continue;
        }
        let Some(first) = models.iter().find(|m| m.read.brings(t.part)) else {
            continue;
        };
        if let Some(s) = model_type(program, t.module, t.name) {
            note(s, first.span);
            model_types.push(t.name);
        }
    }
    if options.all_programs {
        for (s, st) in program.structs.iter() {
            if st.role.is_some() {
                note(s, st.span);
            }
        }
    }

    let mut errors = Vec::new();
    for (&s, &span) in &used {
        let st = &program.structs[s];
        let Some(role) = st.role else { continue };
        for &kind in required(role) {
            if st.program(kind).is_none() {
                errors.push(
                    Diagnostic::error(
                        codes::E0901,
                        format!("`{}` has no `@{}` program", st.name, kind.name()),
                        span,
                    )
                    .with_label(format!("this {} needs one", role.name()))
                    .with_secondary(st.span, format!("`{}` is declared here", st.name))
                    .with_help(format!(
                        "add a function `@{} fn …(value: {}, …)` (see spec/programs.md)",
                        kind.name(),
                        st.name
                    )),
                );
            }
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }

    // Ids from the registry, per role namespace.
    let mut keys: BTreeMap<Role, Vec<(String, StructId)>> = BTreeMap::new();
    for &s in used.keys() {
        if let Some(role) = program.structs[s].role {
            keys.entry(role)
                .or_default()
                .push((type_key(program, s), s));
        }
    }
    let mut types: BTreeMap<Role, Vec<LinkedType>> = BTreeMap::new();
    for (role, list) in keys {
        registry.sync(namespace(role), list.iter().map(|(k, _)| k.as_str()));
        let mut linked: Vec<LinkedType> = list
            .into_iter()
            .map(|(key, s)| {
                let mut programs = program.structs[s].programs.clone();
                programs.sort_by_key(|(k, _)| *k);
                LinkedType {
                    struct_id: s,
                    role,
                    id: registry.id(namespace(role), &key).unwrap_or(u32::MAX),
                    key,
                    programs,
                }
            })
            .collect();
        linked.sort_by_key(|t| t.id);
        types.insert(role, linked);
    }

    let materials = types.get(&Role::Material).map(Vec::as_slice).unwrap_or(&[]);
    let has = |kind: ProgramKind| {
        materials
            .iter()
            .any(|t| t.programs.iter().any(|(k, _)| *k == kind))
    };
    let max_depth = desc.settings.max_depth;
    let spawn_bound = materials
        .iter()
        .filter_map(|t| program.program_for(t.struct_id, ProgramKind::SecondaryRays))
        .map(|p| p.spawn_bound)
        .max()
        .unwrap_or(0);
    let has_secondary_rays =
        (has(ProgramKind::SecondaryRays) && max_depth > 0) || options.all_programs;
    let max_spawn = spawn_bound.min(desc.settings.max_rays_per_hit).max(1);
    let has_media = has(ProgramKind::Medium) || options.all_programs;
    // Every material that spawns rays folds their radiance in additively.
    let additive = materials.iter().all(|t| {
        program
            .program_for(t.struct_id, ProgramKind::SecondaryRays)
            .is_none()
            || program
                .program_for(t.struct_id, ProgramKind::ClosestHit)
                .is_some_and(|p| p.additive_secondary)
    });
    let path_loop = has_secondary_rays && max_spawn == 1 && !has_media && additive;
    let continuing = materials
        .iter()
        .filter(|t| {
            program
                .program_for(t.struct_id, ProgramKind::SecondaryRays)
                .is_some()
        })
        .count();
    let config = KernelConfig {
        max_depth,
        max_spawn,
        stack_size: max_depth.max(1),
        tlas_stack: tlas_stack_bound(desc),
        blas_stack: MAX_BVH_DEPTH,
        has_secondary_rays,
        path_loop,
        roulette_depth: desc.settings.roulette_depth,
        regenerate_paths: path_loop && continuing == 1,
        has_any_hit: has(ProgramKind::AnyHit) || options.all_programs,
        has_custom_geometry: has_custom || options.all_programs,
        has_meshes: has_meshes || options.all_programs,
        has_vertex_extras: model_types
            .iter()
            .any(|n| matches!(*n, "GltfDetailMaterial" | "GltfMaskedDetailMaterial"))
            || options.all_programs,
        has_media,
        has_absorb: materials.iter().any(|t| {
            program
                .program_for(t.struct_id, ProgramKind::AnyHit)
                .is_some_and(|p| p.absorbs)
        }) || options.all_programs,
        has_background: desc.background.is_some() || options.all_programs,
        cull_back_faces: models
            .iter()
            .any(|m| m.read.brings(ModelPart::SingleSidedMaterial))
            || options.all_programs,
    };

    let mut left_out = Vec::new();
    for (s, st) in program.structs.iter() {
        if st.role.is_some() && !used.contains_key(&s) {
            let reason = model_absence(program, s, desc, &models)
                .unwrap_or_else(|| format!("the scene uses no `{}`", st.name));
            for (kind, f) in &st.programs {
                left_out.push(LeftOut {
                    kind: "program",
                    name: format!("@{} {}", kind.name(), program.functions[*f].name),
                    reason: reason.clone(),
                });
            }
        }
    }
    let features = [
        (
            config.has_secondary_rays,
            "secondary rays",
            "no material of the scene spawns rays (or max_depth is 0)",
        ),
        (
            config.has_any_hit,
            "any-hit filtering",
            "no material of the scene has an @any_hit program",
        ),
        (
            config.has_custom_geometry,
            "custom geometry",
            "every object is a triangle mesh",
        ),
        (
            config.has_meshes,
            "triangle meshes",
            "no object is a triangle mesh",
        ),
        (
            config.has_media,
            "media",
            "no material of the scene has a @medium program",
        ),
        (
            config.has_absorb,
            "absorbing shadow rays",
            "no @any_hit program of the scene calls absorb: shadow rays are blocked or not",
        ),
        (
            config.has_background,
            "background",
            "the scene has no background: misses are black",
        ),
        (
            config.cull_back_faces || desc.models.is_empty(),
            "back-face culling",
            "no model file of the scene holds an opaque single-sided material",
        ),
    ];
    for (on, name, why) in features {
        if !on {
            left_out.push(LeftOut {
                kind: "feature",
                name: name.to_string(),
                reason: why.to_string(),
            });
        }
    }
    Ok(Linked {
        scene,
        types,
        config,
        left_out,
        models,
        model_types,
    })
}

/// Why a model type was not linked for a scene with `model` entries (`None` for other structs
/// and scenes).
fn model_absence(
    program: &hir::Program,
    s: StructId,
    desc: &hir::SceneDesc,
    models: &[ModelLink],
) -> Option<String> {
    if models.is_empty() {
        return None;
    }
    let t = MODEL_TYPES
        .iter()
        .find(|t| model_type(program, t.module, t.name) == Some(s))?;
    Some(
        if t.part == ModelPart::PerspectiveCamera && desc.camera.is_some() {
            "the scene has a `camera` entry, so no model camera is used".to_owned()
        } else {
            format!("no model file of the scene holds a {}", t.part.name())
        },
    )
}

/// Every instance of the scene that lowering and the runtime pack into `params`, in a fixed order.
pub fn scene_instances(desc: &hir::SceneDesc) -> Vec<&hir::Instance> {
    let mut v: Vec<&hir::Instance> = Vec::new();
    v.extend(desc.camera.iter());
    v.extend(desc.background.iter());
    for obj in &desc.objects {
        if let hir::Geometry::Custom(inst) = &obj.geometry {
            v.push(inst);
        }
        v.push(&obj.material);
    }
    v.extend(desc.lights.iter());
    v
}

/// Whether a constant value refers to a texture (so the kernel needs the texel buffer).
pub fn uses_textures(value: &ConstValue) -> bool {
    match value {
        ConstValue::Texture(_) => true,
        ConstValue::Array(items) => items.iter().any(uses_textures),
        ConstValue::Struct { fields, .. } => fields.iter().any(uses_textures),
        _ => false,
    }
}
