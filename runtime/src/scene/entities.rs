//! The scene-entity stage: a scene description turned into plain CPU data ready for upload.
//!
//! [`Entities::build`] runs, in order:
//! 1. load every asset once ([`AssetCache`]): object meshes, the scene's glTF models (`models.rs`:
//!    their meshes, images, and the objects, lights and camera they bring), and every
//!    `mesh`/`texture` value in any instance's fields;
//! 2. check the camera (the scene's, else the first model's);
//! 3. build one BLAS per distinct mesh (counted in [`EntityStats::blas_builds`]), quantise it into
//!    `nodes` (the node layout of `rtc_bvh::quantized`: a header, then one record per inner
//!    node), and encode its triangle slots (`encode.rs`);
//! 4. concatenate the textures' texels;
//! 5. write `params`: mesh and texture records, then every instance, then the light table;
//! 6. validate the objects' transforms, and with [`EntityOptions::flatten`] build one world-space
//!    BVH per group of static objects (`flatten.rs`);
//! 7. build the TLAS (a leaf per object not flattened and one per group), unless custom-geometry bounds must come from the GPU first
//!    ([`Entities::needs_bounds`]; the GPU stage calls [`Entities::set_custom_bounds`] and then
//!    [`Entities::rebuild_tlas`]).
//!
//! Moving objects: [`Entities::set_transform`] changes one object and marks the TLAS stale;
//! [`Entities::refresh`] rebuilds only the TLAS (never a BLAS), rewrites `instances` and the medium
//! table, and bumps only the [`Versions`] of what changed, which is what the GPU stage compares.
//!
//! Invariants: every index written for the GPU fits a `u32` (checked, [`SceneError::TooLarge`]);
//! `nodes[..tlas_root]` are the BLASes and never change after `build` (all BVHs are in the
//! quantised layout of `rtc_bvh::quantized`); `instances` is in TLAS leaf
//! order; versions come from one process-wide counter, so two `Entities` never share a version.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use web_time::Instant;

use glam::{Mat4, Vec3, Vec4};
use rtc_bvh::quantized::quantize;
use rtc_bvh::{build, build_with_params, Aabb, BuildInput, BuildPreset, NodeRecord};
use rtc_compiler::abi;
use rtc_compiler::link::Linked;
use rtc_compiler::sema::hir::{
    Geometry, Instance, Program, ProgramKind, SceneDesc, Settings, StructId, TrackTarget,
};
use rtc_compiler::Span;

use super::assets_cache::AssetCache;
use super::encode::{encode_mesh, link_extras};
use super::flatten::{self, FlatGroup};
use super::gpu_types::{record, FrameUniforms, GpuInstance};
use super::models;
use super::params::ParamsBuilder;
use super::store::{AssetStore, BuiltMesh};
use super::SceneError;
use crate::assets::{AssetRoots, MeshData, Sampler, TextureFormat, Wrap};

/// Options of the entity stage.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EntityOptions {
    /// The BVH builder preset, for every BLAS and the TLAS.
    pub bvh: BuildPreset,
    /// Folders besides the scene's own that its assets may come from (`--asset-root`).
    pub asset_roots: AssetRoots,
    /// Flatten static objects with meshes of their own into shared world-space BVHs
    /// (`flatten.rs`): for one-shot renders. Moving a flattened object undoes it.
    pub flatten: bool,
    /// How 8-bit sRGB textures are stored in `texels` ([`SrgbTextures`]).
    pub srgb_textures: SrgbTextures,
}

/// How the entity stage stores 8-bit sRGB textures (PNG, JPEG, glTF colour textures) in `texels`.
///
/// Decoding an sRGB texel takes the kernel three `pow`s, and a bilinear lookup reads four texels:
/// on lavapipe, storing them decoded made a frame of the thesis scene's textured floor alone about
/// 13 % shorter (docs/bench/lavapipe.md, "Texture lookups: sRGB stored decoded, one division per axis (2026-12-07, evening)"). Stored decoded, as linear half floats,
/// a texel is two words read and no arithmetic, at twice the memory; renderers on CPUs make the
/// same trade (Mitsuba converts bitmaps to linear floats on load; pbrt-v4 decodes 8-bit sRGB
/// through a 256-entry table).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SrgbTextures {
    /// Decoded to linear `Rgba16F` ([`crate::assets::TextureData::decoded_srgb`]) while every
    /// texture of the scene, decoded ones counted twice, fits in [`LINEAR_TEXEL_BUDGET`] bytes;
    /// textures are taken in the scene's texture order, and one that does not fit stays 8-bit.
    #[default]
    Decoded,
    /// Kept 8-bit sRGB and decoded by the kernel at each lookup (`RTC_SRGB_TEXTURES=encoded`).
    Encoded,
}

/// The environment variable that keeps 8-bit sRGB textures encoded (`encoded`) for comparisons;
/// any other value, or none, leaves [`SrgbTextures::Decoded`].
pub const SRGB_TEXTURES_ENV: &str = "RTC_SRGB_TEXTURES";

impl SrgbTextures {
    /// [`SrgbTextures::Encoded`] if [`SRGB_TEXTURES_ENV`] says `encoded`, else the default.
    pub fn from_env() -> Self {
        match std::env::var(SRGB_TEXTURES_ENV).as_deref() {
            Ok("encoded") => SrgbTextures::Encoded,
            _ => SrgbTextures::Decoded,
        }
    }
}

/// Which textures [`SrgbTextures::Decoded`] stores decoded, from each texture's `(is 8-bit sRGB,
/// bytes)` in the scene's order: every 8-bit sRGB texture whose decoding (twice its bytes) keeps
/// all textures within `budget` bytes, in order; one that does not fit stays 8-bit and a later,
/// smaller one may still be decoded.
pub(super) fn textures_to_decode(
    textures: impl Iterator<Item = (bool, u64)> + Clone,
    budget: u64,
) -> Vec<bool> {
    let mut total: u64 = textures
        .clone()
        .map(|(_, bytes)| bytes)
        .fold(0, u64::saturating_add);
    textures
        .map(|(srgb, bytes)| {
            let grown = total.saturating_add(bytes);
            let decode = srgb && grown <= budget;
            if decode {
                total = grown;
            }
            decode
        })
        .collect()
}

/// The most bytes of `texels` up to which [`SrgbTextures::Decoded`] stores sRGB textures decoded:
/// half of WebGPU's default 128 MiB storage binding, so a scene whose 8-bit textures are close to
/// the limit still binds them, and the doubled upload stays bounded.
pub const LINEAR_TEXEL_BUDGET: u64 = 64 << 20;

/// A type id and the word offset of an instance in `params`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TypedOffset {
    /// The type's id from the link plan.
    pub type_id: u32,
    /// Word offset in `params`.
    pub offset: u32,
    /// Its struct (for field writes).
    pub struct_id: Option<StructId>,
    /// Its words in `params`.
    pub words: u32,
}

/// Which role-struct instance of the scene a field write goes to
/// ([`Entities::set_field`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FieldTarget {
    /// The camera.
    Camera,
    /// The background.
    Background,
    /// Light `i` (scene `light` entries in order, then the models' lights).
    Light(usize),
    /// The material of object `i` (scene `object` entries in order, then model instances).
    Material(usize),
}

/// What changed in place since the GPU copy was last brought up to date (`GpuScene::upload`
/// clears it, [`Entities::clear_dirty`]), so that an upload can write ranges, not whole
/// buffers. Each part holds the version its ranges are relative to; an upload may use them only
/// when the GPU holds exactly that version, and writes the whole buffer otherwise.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dirty {
    /// `params` word ranges written since version `.0`.
    pub params: Option<(u64, Vec<std::ops::Range<usize>>)>,
    /// `nodes` records from `.1` on changed since version `.0` (the ones before did not).
    pub nodes: Option<(u64, usize)>,
}

/// A distinct mesh with its BLAS (quantised into [`Entities::nodes`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MeshEntity {
    /// What the scene named (a path, `cube_mesh()`, …).
    pub source: String,
    /// Vertices of the mesh.
    pub vertices: u32,
    /// Triangles of the mesh.
    pub triangles: u32,
    /// Triangle slots in `triangles` (more than `triangles` with spatial splits, fewer if some were
    /// rejected as non-finite).
    pub slots: u32,
    /// Index of the BLAS's header record in `nodes` (`rtc_bvh::quantized`).
    pub node_base: u32,
    /// Records of the BLAS (its header and one per inner node).
    pub node_count: u32,
    /// First triangle slot.
    pub triangle_base: u32,
    /// The mesh's object-space box (empty for a mesh without accepted triangles).
    pub bounds: Aabb,
    /// Depth of its BLAS.
    pub depth: u32,
}

/// A texture in `texels`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextureEntity {
    /// What the scene named.
    pub source: String,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// Packing.
    pub format: TextureFormat,
    /// First word in `texels`.
    pub texel_base: u32,
    /// Wrap modes and filter.
    pub sampler: Sampler,
}

/// The `texture.sampler` word of `sampler` (`rtc:abi`'s `TEXTURE_WRAP_*` and `TEXTURE_NEAREST`).
fn sampler_word(sampler: Sampler) -> u32 {
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => 0,
        Wrap::ClampToEdge => abi::TEXTURE_WRAP_CLAMP,
        Wrap::MirroredRepeat => abi::TEXTURE_WRAP_MIRROR,
    };
    let nearest = if sampler.nearest {
        abi::TEXTURE_NEAREST
    } else {
        0
    };
    wrap(sampler.wrap_u) | (wrap(sampler.wrap_v) << abi::TEXTURE_WRAP_V_SHIFT) | nearest
}

/// The object-space box of a custom geometry, as far as it is known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CustomBounds {
    /// Not computed yet (the bounds kernel has not run).
    Unknown,
    /// The program's box.
    Known(Aabb),
    /// The program returned no usable box (NaN, or min > max): the object is left out of the TLAS.
    Invalid,
}

/// An object's geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ObjectGeometry {
    /// A triangle mesh: index into [`Entities::meshes`].
    Mesh {
        /// The mesh.
        mesh: usize,
    },
    /// An instance of a `@geometry` struct.
    Custom {
        /// Its type id and parameters.
        geometry: TypedOffset,
        /// Its object-space box.
        bounds: CustomBounds,
    },
}

/// An object of the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectEntity {
    /// Its name, if the scene gave one.
    pub name: Option<String>,
    /// The scene entry.
    pub span: Span,
    /// Its geometry.
    pub geometry: ObjectGeometry,
    /// Its material.
    pub material: TypedOffset,
    /// [`GpuInstance`] flags of the material.
    pub flags: u32,
    /// Object to world.
    pub transform: Mat4,
    /// World to object (the inverse of `transform`).
    pub inverse: Mat4,
}

/// An entry of the scene-level BVH.
#[derive(Clone, Copy, Debug)]
enum Entry {
    /// An object with its own BVH (or custom geometry).
    Object(usize),
    /// A group of flattened objects (index into `Entities::flat`).
    Group(usize),
}

/// A light: type id and parameters (world space; lights have no transform).
pub type LightEntity = TypedOffset;

/// Version numbers of the data behind each buffer; a new number means new contents.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Versions {
    /// `nodes` (BLASes and TLAS).
    pub nodes: u64,
    /// `instances` (TLAS order).
    pub instances: u64,
    /// `triangles`.
    pub triangles: u64,
    /// `attributes`.
    pub attributes: u64,
    /// `params`.
    pub params: u64,
    /// `texels`.
    pub texels: u64,
}

/// What building the entities did and cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EntityStats {
    /// BLAS builds so far (one per distinct mesh; moving objects adds none).
    pub blas_builds: u32,
    /// TLAS builds so far.
    pub tlas_builds: u32,
    /// Milliseconds loading assets.
    pub load_ms: f64,
    /// Milliseconds building and flattening BLASes and encoding triangles.
    pub blas_ms: f64,
    /// Milliseconds of the last TLAS build (including instance records and the medium table).
    pub tlas_ms: f64,
    /// Milliseconds packing `params`.
    pub pack_ms: f64,
    /// Distinct triangles in memory (sum over distinct meshes).
    pub triangles: u64,
    /// Triangles as rendered (sum over objects: instancing counts a mesh once per object).
    pub instanced_triangles: u64,
    /// Deepest BLAS.
    pub max_blas_depth: u32,
    /// Depth of the TLAS.
    pub tlas_depth: u32,
    /// Objects now flattened into shared world-space BVHs ([`EntityOptions::flatten`]).
    pub flattened_objects: u32,
    /// Those shared BVHs.
    pub flat_bvhs: u32,
    /// 8-bit sRGB textures stored decoded as linear half floats ([`SrgbTextures::Decoded`]).
    pub decoded_textures: u32,
}

/// The scene's entities: everything the GPU stage uploads, as plain data.
#[derive(Debug)]
pub struct Entities {
    scene_name: String,
    settings: Settings,
    preset: BuildPreset,
    meshes: Vec<MeshEntity>,
    textures: Vec<TextureEntity>,
    objects: Vec<ObjectEntity>,
    lights: Vec<LightEntity>,
    camera: TypedOffset,
    background: Option<TypedOffset>,
    params: Vec<u32>,
    light_table: u32,
    medium_table: u32,
    medium_count: u32,
    nodes: Vec<NodeRecord>,
    blas_nodes: u32,
    triangles: Vec<[f32; 4]>,
    attributes: Vec<[u32; 4]>,
    /// Shared with the asset store, which hands the same words to a rebuild over the same
    /// textures (`AssetStore::texels`).
    texels: Arc<[u32]>,
    tlas_order: Option<Vec<u32>>,
    /// The TLAS root's exact box (the header's quantisation frame is a little larger).
    tlas_bounds: Aabb,
    tlas_stale: bool,
    instances: Vec<GpuInstance>,
    versions: Versions,
    stats: EntityStats,
    stacks: (u32, u32),
    warnings: Vec<String>,
    dirty: Dirty,
    /// The objects glTF node animations move (object indices into `objects`).
    motions: Vec<models::ModelMotion>,
    /// Groups of flattened static objects (`flatten.rs`), each one scene-level leaf.
    flat: Vec<FlatGroup>,
}

static NEXT_VERSION: AtomicU64 = AtomicU64::new(1);

/// A version number never handed out before in this process.
fn next_version() -> u64 {
    NEXT_VERSION.fetch_add(1, Ordering::Relaxed)
}

fn to_u32(what: &'static str, n: usize) -> Result<u32, SceneError> {
    u32::try_from(n).map_err(|_| SceneError::TooLarge {
        what,
        count: n as u64,
    })
}

fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// The link plan's id for a struct the scene uses.
fn type_id(program: &Program, linked: &Linked, s: StructId) -> Result<u32, SceneError> {
    linked
        .type_of(s)
        .map(|t| t.id)
        .ok_or_else(|| SceneError::Unlinked {
            name: program.structs[s].name.clone(),
        })
}

/// The [`GpuInstance`] flags of a material type.
fn material_flags(linked: &Linked, s: StructId) -> u32 {
    let Some(t) = linked.type_of(s) else { return 0 };
    t.programs.iter().fold(0, |flags, (kind, _)| {
        flags
            | match kind {
                ProgramKind::AnyHit => GpuInstance::FLAG_ANY_HIT,
                ProgramKind::SecondaryRays => GpuInstance::FLAG_SECONDARY_RAYS,
                ProgramKind::Medium => GpuInstance::FLAG_MEDIUM,
                _ => 0,
            }
    })
}

/// Checks an object-to-world matrix and returns its inverse. (The compiler refuses such
/// transforms in a scene with a located E0708; this catches those of glTF nodes and models.)
fn invert_transform(m: &Mat4) -> Result<Mat4, &'static str> {
    if !m.is_finite() {
        return Err("has a NaN or infinite entry");
    }
    if m.row(3) != Vec4::W {
        return Err("is not affine (its last row is not 0, 0, 0, 1)");
    }
    let det = m.determinant();
    if det == 0.0 || !det.is_finite() {
        return Err(if m.as_dmat4().determinant() == 0.0 {
            "is singular (it flattens the object), so rays cannot be moved into object space"
        } else {
            "scales the object too far for single precision (its determinant under- or \
             overflows f32), so rays cannot be moved into object space"
        });
    }
    let inverse = m.inverse();
    if !inverse.is_finite() {
        return Err("cannot be inverted in single precision");
    }
    Ok(inverse)
}

/// The three top rows of an affine matrix (translation in `w`).
fn rows(m: &Mat4) -> [[f32; 4]; 3] {
    [
        m.row(0).to_array(),
        m.row(1).to_array(),
        m.row(2).to_array(),
    ]
}

/// The world box of an object-space box: its 8 corners transformed. A non-finite box stays the
/// infinite box (the BVH builder clamps it); an empty box stays empty.
pub(super) fn transform_box(b: &Aabb, m: &Mat4) -> Aabb {
    if b.is_empty() {
        return Aabb::EMPTY;
    }
    if !b.is_finite() {
        return Aabb::new(Vec3::NEG_INFINITY, Vec3::INFINITY);
    }
    let (lo, hi) = (Vec3::from(b.min), Vec3::from(b.max));
    let mut out = Aabb::EMPTY;
    for i in 0..8 {
        let corner = Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        out.grow_point(m.transform_point3(corner).into());
    }
    out
}

/// The ranges where two word slices of the same length differ (runs closer than 16 words
/// merged).
fn changed_ranges(old: &[u32], new: &[u32]) -> Vec<std::ops::Range<usize>> {
    let mut out: Vec<std::ops::Range<usize>> = Vec::new();
    for (i, _) in old.iter().zip(new).enumerate().filter(|(_, (a, b))| a != b) {
        match out.last_mut() {
            Some(last) if i <= last.end + 16 => last.end = i + 1,
            _ => out.push(i..i + 1),
        }
    }
    out
}

/// Builds, quantises and encodes the object-level BVH of one mesh (`name` for errors).
fn build_mesh(name: &str, data: &MeshData, preset: BuildPreset) -> Result<BuiltMesh, SceneError> {
    let vertices: &[Vec3] = bytemuck::cast_slice(&data.positions);
    let bvh = build(
        BuildInput::Indexed {
            vertices,
            indices: &data.indices,
        },
        preset,
    );
    let quantized = quantize(&bvh).map_err(|source| SceneError::MeshLayout {
        mesh: name.to_string(),
        source,
    })?;
    let mut records = Vec::with_capacity(quantized.record_count());
    quantized.append_records(&mut records);
    let mut triangles = Vec::new();
    let mut attributes = Vec::new();
    let mut extras = Vec::new();
    encode_mesh(data, &bvh, &mut triangles, &mut attributes, &mut extras);
    Ok(BuiltMesh {
        records,
        triangles,
        attributes,
        extras,
        slots: to_u32("triangle slots", bvh.prim_indices().len())?,
        bounds: bvh.root_aabb(),
        depth: bvh.max_depth(),
    })
}

impl Entities {
    /// Builds the entities of `scene` (a scene of `program`, linked as `linked`).
    pub fn build(
        program: &Program,
        scene: &SceneDesc,
        linked: &Linked,
        options: &EntityOptions,
    ) -> Result<Entities, SceneError> {
        Self::build_with_store(program, scene, linked, options, &mut AssetStore::new())
    }

    /// [`build`](Self::build), taking assets and object-level BVHs from `store` where their
    /// inputs did not change and putting there what it had to load or build.
    pub fn build_with_store(
        program: &Program,
        scene: &SceneDesc,
        linked: &Linked,
        options: &EntityOptions,
        store: &mut AssetStore,
    ) -> Result<Entities, SceneError> {
        let scene_file = program
            .modules
            .get(scene.module.index())
            .and_then(|m| m.path.as_deref());
        let mut cache = AssetCache::new(scene_file, options.asset_roots.clone());
        cache.store = std::mem::take(store);
        let built = Self::build_in(program, scene, linked, options, &mut cache);
        *store = std::mem::take(&mut cache.store);
        built
    }

    fn build_in(
        program: &Program,
        scene: &SceneDesc,
        linked: &Linked,
        options: &EntityOptions,
        cache: &mut AssetCache,
    ) -> Result<Entities, SceneError> {
        let mut stats = EntityStats::default();
        let mut warnings = Vec::new();

        // 2. Assets, each once.
        let start = Instant::now();
        let mut object_meshes = Vec::with_capacity(scene.objects.len());
        for obj in &scene.objects {
            object_meshes.push(match &obj.geometry {
                Geometry::Mesh(asset) => Some(cache.mesh(asset)?),
                Geometry::Custom(_) => None,
            });
        }
        let models = models::import(program, linked, scene, cache)?;
        warnings.extend(models.warnings.iter().cloned());
        let model_materials = models.objects.iter().map(|o| &o.material);
        for inst in all_instances(scene)
            .chain(model_materials)
            .chain(&models.lights)
            .chain(&models.camera)
        {
            for value in &inst.fields {
                cache.scan(value)?;
            }
        }
        let Some(camera) = scene.camera.as_ref().or(models.camera.as_ref()) else {
            return Err(SceneError::NoCamera {
                scene: scene.name.clone(),
            });
        };
        warnings.append(&mut cache.warnings);
        stats.load_ms = ms_since(start);

        // 3. One BLAS per distinct mesh, triangles in leaf order.
        let start = Instant::now();
        let mut nodes: Vec<NodeRecord> = Vec::new();
        let mut triangles = Vec::new();
        let mut attributes = Vec::new();
        // The meshes with extras and the range of their attribute records: their extras are
        // placed after the loop.
        let mut with_extras = Vec::new();
        let mut meshes = Vec::with_capacity(cache.meshes.len());
        for (key, data, version) in &cache.meshes {
            let built = match cache.store.blas(key, options.bvh, *version) {
                Some(built) => built,
                None => {
                    let built = Arc::new(build_mesh(&key.describe(), data, options.bvh)?);
                    stats.blas_builds += 1;
                    cache
                        .store
                        .put_blas(key.clone(), options.bvh, *version, Arc::clone(&built));
                    built
                }
            };
            let node_base = to_u32("BVH nodes", nodes.len())?;
            let triangle_base = to_u32("triangle slots", triangles.len() / record::TRIANGLE_VEC4S)?;
            stats.max_blas_depth = stats.max_blas_depth.max(built.depth);
            stats.triangles += data.indices.len() as u64;
            meshes.push(MeshEntity {
                source: key.describe(),
                vertices: to_u32("vertices", data.positions.len())?,
                triangles: to_u32("triangles", data.indices.len())?,
                slots: built.slots,
                node_base,
                node_count: to_u32("BVH nodes", built.records.len())?,
                triangle_base,
                bounds: built.bounds,
                depth: built.depth,
            });
            nodes.extend_from_slice(&built.records);
            triangles.extend_from_slice(&built.triangles);
            let start = attributes.len();
            attributes.extend_from_slice(&built.attributes);
            if !built.extras.is_empty() {
                with_extras.push((start..attributes.len(), built));
            }
        }
        to_u32("triangle slots", triangles.len())?;
        stats.blas_ms = ms_since(start);

        // 4. Texels: 8-bit sRGB textures decoded to half floats while they fit the budget (the
        //    store keeps each decoded copy for the next build).
        let mut texel_words = 0usize;
        let mut parts = Vec::with_capacity(cache.textures.len());
        let mut textures = Vec::with_capacity(cache.textures.len());
        let budget = match options.srgb_textures {
            SrgbTextures::Decoded => LINEAR_TEXEL_BUDGET,
            SrgbTextures::Encoded => 0,
        };
        let decode = textures_to_decode(
            cache.textures.iter().map(|(_, data)| {
                (
                    data.format == TextureFormat::Rgba8Srgb,
                    4 * data.words.len() as u64,
                )
            }),
            budget,
        );
        for ((key, data), decode) in cache.textures.iter().zip(decode) {
            let decoded = if decode {
                cache.store.decoded_texture(key, data)
            } else {
                None
            };
            stats.decoded_textures += u32::from(decoded.is_some());
            let data = decoded.unwrap_or_else(|| Arc::clone(data));
            textures.push(TextureEntity {
                source: key.describe(),
                width: data.width,
                height: data.height,
                format: data.format,
                texel_base: to_u32("texel words", texel_words)?,
                sampler: data.sampler,
            });
            texel_words += data.words.len();
            parts.push(data);
        }
        to_u32("texel words", texel_words)?;
        let texels = cache.store.texels(&parts);

        // 5. params: records, instances, light table.
        let start = Instant::now();
        let mut params = ParamsBuilder::default();
        for ((key, _, _), mesh) in cache.meshes.iter().zip(&meshes) {
            let mut record = [0; record::MESH_WORDS];
            record[record::MESH_NODE_BASE] = mesh.node_base;
            record[record::MESH_SLOT_BASE] = mesh.triangle_base;
            record[record::MESH_SLOT_COUNT] = mesh.slots;
            let at = params.push_words(&record)?;
            params.mesh_records.insert(key.clone(), at);
        }
        for ((key, _), tex) in cache.textures.iter().zip(&textures) {
            let mut record = [0; record::TEXTURE_WORDS];
            record[record::TEXTURE_TEXEL_BASE] = tex.texel_base;
            record[record::TEXTURE_WIDTH] = tex.width;
            record[record::TEXTURE_HEIGHT] = tex.height;
            record[record::TEXTURE_FORMAT] = match tex.format {
                TextureFormat::Rgba8Srgb => abi::TEXTURE_FORMAT_RGBA8_SRGB,
                TextureFormat::Rgba8Unorm => abi::TEXTURE_FORMAT_RGBA8_UNORM,
                TextureFormat::Rgba16F => abi::TEXTURE_FORMAT_RGBA16F,
            };
            record[record::TEXTURE_SAMPLER] = sampler_word(tex.sampler);
            let at = params.push_words(&record)?;
            params.texture_records.insert(key.clone(), at);
        }
        let typed =
            |params: &mut ParamsBuilder, inst: &Instance| -> Result<TypedOffset, SceneError> {
                let (offset, words) = params.push_instance(program, inst)?;
                Ok(TypedOffset {
                    type_id: type_id(program, linked, inst.struct_id)?,
                    offset,
                    struct_id: Some(inst.struct_id),
                    words,
                })
            };
        let camera = typed(&mut params, camera)?;
        let background = match &scene.background {
            Some(bg) => Some(typed(&mut params, bg)?),
            None => None,
        };
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (index, (obj, mesh)) in scene.objects.iter().zip(object_meshes).enumerate() {
            let geometry = match (&obj.geometry, mesh) {
                (Geometry::Custom(inst), _) => ObjectGeometry::Custom {
                    geometry: typed(&mut params, inst)?,
                    bounds: CustomBounds::Unknown,
                },
                (Geometry::Mesh(_), Some(mesh)) => ObjectGeometry::Mesh { mesh },
                (Geometry::Mesh(_), None) => ObjectGeometry::Mesh { mesh: 0 },
            };
            let material = typed(&mut params, &obj.material)?;
            let transform = Mat4::from_cols_array_2d(&obj.transform);
            let inverse =
                invert_transform(&transform).map_err(|reason| SceneError::BadTransform {
                    object: index,
                    name: obj.name.clone(),
                    reason,
                })?;
            if let ObjectGeometry::Mesh { mesh } = geometry {
                stats.instanced_triangles += meshes.get(mesh).map_or(0, |m| u64::from(m.triangles));
            }
            objects.push(ObjectEntity {
                name: obj.name.clone(),
                span: obj.span,
                geometry,
                material,
                flags: material_flags(linked, obj.material.struct_id),
                transform,
                inverse,
            });
        }
        for (index, obj) in models.objects.iter().enumerate() {
            let index = index + scene.objects.len();
            let name = Some(obj.name.clone());
            let inverse =
                invert_transform(&obj.transform).map_err(|reason| SceneError::BadTransform {
                    object: index,
                    name: name.clone(),
                    reason,
                })?;
            stats.instanced_triangles += meshes.get(obj.mesh).map_or(0, |m| u64::from(m.triangles));
            objects.push(ObjectEntity {
                name,
                span: obj.span,
                geometry: ObjectGeometry::Mesh { mesh: obj.mesh },
                material: typed(&mut params, &obj.material)?,
                flags: material_flags(linked, obj.material.struct_id) | obj.cull,
                transform: obj.transform,
                inverse,
            });
        }
        // Model objects follow the scene's own, so their motions' indices shift by those.
        let motions: Vec<models::ModelMotion> = models
            .motions
            .iter()
            .map(|m| models::ModelMotion {
                object: m.object + scene.objects.len(),
                ..m.clone()
            })
            .collect();
        to_u32("objects", objects.len())?;
        let mut lights = Vec::with_capacity(scene.lights.len() + models.lights.len());
        for light in scene.lights.iter().chain(&models.lights) {
            lights.push(typed(&mut params, light)?);
        }
        let table: Vec<u32> = lights
            .iter()
            .flat_map(|l| {
                let mut entry = [0; record::LIGHT_ENTRY_WORDS];
                entry[record::LIGHT_ENTRY_TYPE_ID] = l.type_id;
                entry[record::LIGHT_ENTRY_OFFSET] = l.offset;
                entry
            })
            .collect();
        let light_table = params.push_words(&table)?;
        let medium_table = params.offset()?;
        stats.pack_ms = ms_since(start);

        // 3b. Static objects flattened into shared BVHs, after every mesh's BVH.
        let mut flat = Vec::new();
        if options.flatten {
            let start = Instant::now();
            let mut moves = vec![false; objects.len()];
            let animated = scene.animation.iter().filter_map(|t| match t.target {
                TrackTarget::Object(i) => Some(i),
                _ => None,
            });
            for i in animated.chain(motions.iter().map(|m| m.object)) {
                if let Some(m) = moves.get_mut(i) {
                    *m = true;
                }
            }
            let candidates: Vec<flatten::Candidate> = objects
                .iter()
                .enumerate()
                .map(|(i, o)| flatten::Candidate {
                    mesh: match o.geometry {
                        ObjectGeometry::Mesh { mesh } => {
                            cache.meshes.get(mesh).map(|(_, data, _)| (mesh, &**data))
                        }
                        ObjectGeometry::Custom { .. } => None,
                    },
                    flags: o.flags,
                    transform: o.transform,
                    moves: moves.get(i).copied().unwrap_or(false),
                })
                .collect();
            for (flags, members) in flatten::plan(&candidates) {
                let inputs: Vec<(&MeshData, Mat4)> = members
                    .iter()
                    .filter_map(|&i| {
                        let c = candidates.get(i)?;
                        Some((c.mesh?.1, c.transform))
                    })
                    .collect();
                let built = flatten::build_group(&inputs, |merged| {
                    let preset = flatten::preset(merged.indices.len(), options.bvh);
                    build_mesh("the flattened static objects", merged, preset)
                })?;
                stats.max_blas_depth = stats.max_blas_depth.max(built.depth);
                let group = FlatGroup {
                    members,
                    flags,
                    node_base: to_u32("BVH nodes", nodes.len())?,
                    triangle_base: to_u32(
                        "triangle slots",
                        triangles.len() / record::TRIANGLE_VEC4S,
                    )?,
                    bounds: built.bounds,
                };
                nodes.extend_from_slice(&built.records);
                triangles.extend_from_slice(&built.triangles);
                attributes.extend_from_slice(&built.attributes);
                to_u32("triangle slots", triangles.len())?;
                to_u32("attribute records", attributes.len())?;
                flat.push(group);
            }
            stats.blas_ms += ms_since(start);
        }
        // Extras go after every slot's records, the flattened groups' included (`encode::link_extras`).
        for (range, built) in with_extras {
            let base = to_u32("attribute records", attributes.len())?;
            if let Some(records) = attributes.get_mut(range) {
                link_extras(records, base);
            }
            attributes.extend_from_slice(&built.extras);
        }
        // Every object-level BVH is built by now, the flattened groups' included.
        if stats.max_blas_depth > linked.config.blas_stack {
            warnings.push(format!(
                "a mesh BVH is {} levels deep, deeper than the kernel's traversal stack ({}): \
                 some triangles may be missed",
                stats.max_blas_depth, linked.config.blas_stack
            ));
        }
        let blas_nodes = to_u32("BVH nodes", nodes.len())?;

        let v = next_version();
        let mut entities = Entities {
            scene_name: scene.name.clone(),
            settings: scene.settings,
            preset: options.bvh,
            meshes,
            textures,
            objects,
            lights,
            camera,
            background,
            params: params.words,
            light_table,
            medium_table,
            medium_count: 0,
            nodes,
            blas_nodes,
            triangles,
            attributes,
            texels,
            tlas_order: None,
            tlas_bounds: Aabb::EMPTY,
            tlas_stale: true,
            instances: Vec::new(),
            versions: Versions {
                nodes: v,
                instances: v,
                triangles: v,
                attributes: v,
                params: v,
                texels: v,
            },
            stats,
            stacks: (linked.config.tlas_stack, linked.config.blas_stack),
            warnings,
            dirty: Dirty::default(),
            motions,
            flat,
        };
        if !entities.needs_bounds() {
            entities.rebuild_tlas()?;
        }
        Ok(entities)
    }

    /// Whether some custom-geometry object's bounds are still unknown (the GPU stage must run the
    /// bounds kernel and call [`set_custom_bounds`](Self::set_custom_bounds) before the TLAS).
    pub fn needs_bounds(&self) -> bool {
        self.objects.iter().any(|o| {
            matches!(
                o.geometry,
                ObjectGeometry::Custom {
                    bounds: CustomBounds::Unknown,
                    ..
                }
            )
        })
    }

    /// Whether any object has custom geometry.
    pub fn has_custom_geometry(&self) -> bool {
        self.objects
            .iter()
            .any(|o| matches!(o.geometry, ObjectGeometry::Custom { .. }))
    }

    /// Sets the object-space box of custom-geometry object `object` (`None`, or a box with NaN or
    /// `min > max`: the program gave no usable box, and the object is left out). Marks the TLAS
    /// stale. Ignored for mesh objects.
    pub fn set_custom_bounds(
        &mut self,
        object: usize,
        bounds: Option<Aabb>,
    ) -> Result<(), SceneError> {
        let count = self.objects.len();
        let obj = self
            .objects
            .get_mut(object)
            .ok_or(SceneError::NoSuchObject { object, count })?;
        if let ObjectGeometry::Custom { bounds: b, .. } = &mut obj.geometry {
            *b = match bounds {
                Some(bx) if !bx.min.is_nan() && !bx.max.is_nan() && !bx.is_empty() => {
                    CustomBounds::Known(bx)
                }
                _ => CustomBounds::Invalid,
            };
            self.tlas_stale = true;
        }
        Ok(())
    }

    /// Moves object `object`: `transform` is its new object-to-world matrix (affine, invertible).
    /// Only the TLAS goes stale; call [`refresh`](Self::refresh) (the renderer does) to rebuild it.
    pub fn set_transform(&mut self, object: usize, transform: Mat4) -> Result<(), SceneError> {
        let count = self.objects.len();
        let obj = self
            .objects
            .get_mut(object)
            .ok_or(SceneError::NoSuchObject { object, count })?;
        let inverse = invert_transform(&transform).map_err(|reason| SceneError::BadTransform {
            object,
            name: obj.name.clone(),
            reason,
        })?;
        obj.transform = transform;
        obj.inverse = inverse;
        // A flattened object that moves undoes the flattening: every object gets its own BVH
        // (kept from the build) back, and the groups' records are left unused.
        if self.flat.iter().any(|g| g.members.contains(&object)) {
            self.flat.clear();
        }
        self.tlas_stale = true;
        Ok(())
    }

    /// Whether a glTF model's node animation moves some object.
    pub fn has_model_animation(&self) -> bool {
        !self.motions.is_empty()
    }

    /// The longest glTF node animation of the scene's models, in seconds (0 without one).
    pub fn model_animation_length(&self) -> f32 {
        self.motions
            .iter()
            .map(|m| m.animation.duration)
            .fold(0.0, f32::max)
    }

    /// The object-to-world matrix at `t` seconds of each object a glTF node animation moves
    /// (each file's animation evaluated once). Pure: the same `t` gives the same matrices.
    pub fn model_transforms_at(&self, t: f32) -> Vec<(usize, Mat4)> {
        let mut evaluated: Vec<(&Arc<crate::assets::model::NodeAnimation>, Vec<Mat4>)> = Vec::new();
        let mut out = Vec::with_capacity(self.motions.len());
        for m in &self.motions {
            if !evaluated.iter().any(|(k, _)| Arc::ptr_eq(k, &m.animation)) {
                evaluated.push((&m.animation, m.animation.evaluate(t)));
            }
            let world = evaluated
                .iter()
                .find(|(k, _)| Arc::ptr_eq(k, &m.animation))
                .and_then(|(_, w)| w.get(m.node));
            if let Some(w) = world {
                out.push((m.object, m.entry * *w));
            }
        }
        out
    }

    /// Takes over the versions of `old` (the entities this rebuild replaces, whose data is on
    /// the GPU) for every buffer whose data is the same, so that nothing unchanged is uploaded
    /// again; when only the scene-level BVH's records differ and the node count is the same,
    /// marks just those for upload.
    pub fn inherit_versions(&mut self, old: &Entities) {
        let ov = old.versions;
        if self.triangles == old.triangles {
            self.versions.triangles = ov.triangles;
        }
        if self.attributes == old.attributes {
            self.versions.attributes = ov.attributes;
        }
        if Arc::ptr_eq(&self.texels, &old.texels) || self.texels == old.texels {
            self.versions.texels = ov.texels;
        }
        if self.params == old.params {
            self.versions.params = ov.params;
        } else if self.params.len() == old.params.len() {
            let changed = changed_ranges(&old.params, &self.params);
            self.dirty.params = Some((ov.params, changed));
        }
        let blas = self.blas_nodes as usize;
        if self.nodes == old.nodes {
            self.versions.nodes = ov.nodes;
        } else if self.nodes.len() == old.nodes.len()
            && self.blas_nodes == old.blas_nodes
            && self.nodes.get(..blas) == old.nodes.get(..blas)
        {
            self.dirty.nodes = Some((ov.nodes, blas));
        }
    }

    /// Forgets the range bookkeeping and gives every buffer a new version (after the GPU copy
    /// was lost, everything is uploaded again).
    pub fn force_full_upload(&mut self) {
        let v = next_version();
        self.versions = Versions {
            nodes: v,
            instances: v,
            triangles: v,
            attributes: v,
            params: v,
            texels: v,
        };
        self.dirty = Dirty::default();
    }

    /// The changes since the last [`clear_dirty`](Self::clear_dirty).
    pub fn dirty(&self) -> &Dirty {
        &self.dirty
    }

    /// Forgets the changes (the GPU copy is up to date).
    pub fn clear_dirty(&mut self) {
        self.dirty = Dirty::default();
    }

    /// Bumps the `params` version after a change: `range` when only those words changed in
    /// place, `None` when more did (the next upload writes it all).
    fn params_changed(&mut self, range: Option<std::ops::Range<usize>>) {
        let old = self.versions.params;
        self.versions.params = next_version();
        self.dirty.params = match (range, self.dirty.params.take()) {
            (Some(r), Some((base, mut ranges))) => {
                ranges.push(r);
                Some((base, ranges))
            }
            (Some(r), None) => Some((old, vec![r])),
            (None, _) => None,
        };
    }

    /// The instance a field write to `target` goes to.
    pub fn instance(&self, target: FieldTarget) -> Result<TypedOffset, SceneError> {
        let missing = |what: String| SceneError::NoSuchInstance { what };
        match target {
            FieldTarget::Camera => Ok(self.camera),
            FieldTarget::Background => self.background.ok_or_else(|| missing("background".into())),
            FieldTarget::Light(i) => self
                .lights
                .get(i)
                .copied()
                .ok_or_else(|| missing(format!("light {i} (it has {})", self.lights.len()))),
            FieldTarget::Material(i) => self
                .objects
                .get(i)
                .map(|o| o.material)
                .ok_or_else(|| missing(format!("object {i} (it has {})", self.objects.len()))),
        }
    }

    /// Writes `words` at word `at` of `target`'s instance in `params`. An instance shared with
    /// another target (identical instances are stored once) is first copied, so the write
    /// changes `target` alone. Only the words written are marked for upload (plus, after a copy,
    /// the whole of `params` once).
    pub fn write_instance(
        &mut self,
        target: FieldTarget,
        at: u32,
        words: &[u32],
    ) -> Result<(), SceneError> {
        let inst = self.instance(target)?;
        let end = at as usize + words.len();
        if end > inst.words as usize {
            return Err(SceneError::TooLarge {
                what: "instance words",
                count: end as u64,
            });
        }
        let offset = if self.users_of(inst.offset) > 1 {
            self.unshare(target, inst)?
        } else {
            inst.offset
        };
        let start = offset as usize + at as usize;
        let Some(slot) = self.params.get_mut(start..start + words.len()) else {
            return Err(SceneError::TooLarge {
                what: "parameter words",
                count: (start + words.len()) as u64,
            });
        };
        if slot != words {
            slot.copy_from_slice(words);
            self.params_changed(Some(start..start + words.len()));
        }
        Ok(())
    }

    /// How many targets (camera, background, lights, materials, custom geometries) use the
    /// instance at `offset`.
    fn users_of(&self, offset: u32) -> usize {
        let custom = self.objects.iter().filter_map(|o| match o.geometry {
            ObjectGeometry::Custom { geometry, .. } => Some(geometry),
            ObjectGeometry::Mesh { .. } => None,
        });
        std::iter::once(self.camera)
            .chain(self.background)
            .chain(self.lights.iter().copied())
            .chain(self.objects.iter().map(|o| o.material))
            .chain(custom)
            .filter(|t| t.offset == offset)
            .count()
    }

    /// Gives `target` its own copy of `inst`, placed before the medium table (which moves up);
    /// returns the copy's offset.
    fn unshare(&mut self, target: FieldTarget, inst: TypedOffset) -> Result<u32, SceneError> {
        let words: Vec<u32> = self
            .params
            .get(inst.offset as usize..(inst.offset + inst.words) as usize)
            .map(<[u32]>::to_vec)
            .unwrap_or_default();
        let media = self.params.split_off(self.medium_table as usize);
        let at = self.params.len().next_multiple_of(4);
        self.params.resize(at, 0);
        self.params.extend_from_slice(&words);
        self.medium_table = to_u32("parameter words", self.params.len())?;
        self.params.extend_from_slice(&media);
        to_u32("parameter words", self.params.len())?;
        let at = to_u32("parameter words", at)?;
        match target {
            FieldTarget::Camera => self.camera.offset = at,
            FieldTarget::Background => {
                if let Some(b) = &mut self.background {
                    b.offset = at;
                }
            }
            FieldTarget::Light(i) => {
                if let Some(l) = self.lights.get_mut(i) {
                    l.offset = at;
                }
                let entry = self.light_table as usize
                    + i * record::LIGHT_ENTRY_WORDS
                    + record::LIGHT_ENTRY_OFFSET;
                if let Some(w) = self.params.get_mut(entry) {
                    *w = at;
                }
            }
            FieldTarget::Material(i) => {
                if let Some(o) = self.objects.get_mut(i) {
                    o.material.offset = at;
                }
                for slot in &mut self.instances {
                    if slot.object as usize == i {
                        slot.material_offset = at;
                    }
                }
                self.versions.instances = next_version();
            }
        }
        self.params_changed(None);
        Ok(at)
    }

    /// Rebuilds the TLAS if an object moved or bounds changed since the last build; returns
    /// whether it did.
    pub fn refresh(&mut self) -> Result<bool, SceneError> {
        if !self.tlas_stale {
            return Ok(false);
        }
        self.rebuild_tlas()?;
        Ok(true)
    }

    /// Builds the TLAS over the objects' world boxes, rewrites `nodes[tlas_root..]`, the instance
    /// records (in TLAS leaf order) and the medium table. BLASes are not touched.
    pub fn rebuild_tlas(&mut self) -> Result<(), SceneError> {
        if let Some(object) = self.objects.iter().position(|o| {
            matches!(
                o.geometry,
                ObjectGeometry::Custom {
                    bounds: CustomBounds::Unknown,
                    ..
                }
            )
        }) {
            return Err(SceneError::MissingBounds { object });
        }
        let start = Instant::now();
        // The scene level's entries: every object not flattened, then each flattened group.
        let mut flattened = vec![false; self.objects.len()];
        for g in &self.flat {
            for &m in &g.members {
                if let Some(f) = flattened.get_mut(m) {
                    *f = true;
                }
            }
        }
        let mut entries: Vec<Entry> = (0..self.objects.len())
            .filter(|&i| !flattened.get(i).copied().unwrap_or(false))
            .map(Entry::Object)
            .collect();
        entries.extend((0..self.flat.len()).map(Entry::Group));
        let boxes: Vec<Aabb> = entries
            .iter()
            .map(|e| match *e {
                Entry::Object(o) => self
                    .objects
                    .get(o)
                    .map_or(Aabb::EMPTY, |o| self.world_box(o)),
                Entry::Group(g) => self.flat.get(g).map_or(Aabb::EMPTY, |g| g.bounds),
            })
            .collect();
        // One object per leaf: the kernel's scene-level leaf step tests `a` alone.
        let tlas = build_with_params(BuildInput::Aabbs(&boxes), &self.preset.single_leaf_params());
        self.stats.tlas_builds += 1;
        self.stats.tlas_depth = tlas.max_depth();
        // One-object leaves always fit a reference; only an object count beyond 2^27 does not.
        let records = quantize(&tlas).map_err(|_| SceneError::TooLarge {
            what: "objects",
            count: boxes.len() as u64,
        })?;
        to_u32(
            "BVH nodes",
            self.blas_nodes as usize + records.record_count(),
        )?;
        let (old_len, old_version) = (self.nodes.len(), self.versions.nodes);
        self.nodes.truncate(self.blas_nodes as usize);
        records.append_records(&mut self.nodes);
        self.dirty.nodes = if self.nodes.len() == old_len {
            let from = self.blas_nodes as usize;
            Some(match self.dirty.nodes {
                Some((base, f)) => (base, f.min(from)),
                None => (old_version, from),
            })
        } else {
            None
        };
        // Slots: the scene-level leaves in leaf order, then the flattened groups' members
        // (group by group, in tag order), whose records a group's `object` points at.
        let leaves = tlas.prim_indices().len();
        let mut first_member = Vec::with_capacity(self.flat.len());
        let mut next = leaves;
        for g in &self.flat {
            first_member.push(next);
            next += g.members.len();
        }
        to_u32("objects", next)?;
        let mut order = Vec::with_capacity(next);
        let mut instances = Vec::with_capacity(next);
        for &e in tlas.prim_indices() {
            match entries.get(e as usize) {
                Some(&Entry::Object(o)) => {
                    order.push(o as u32);
                    instances.push(self.instance_record(o));
                }
                Some(&Entry::Group(g)) => {
                    order.push(u32::MAX);
                    let first = first_member.get(g).copied().unwrap_or(0) as u32;
                    instances.push(match self.flat.get(g) {
                        Some(group) => flatten::group_record(group, first),
                        None => GpuInstance::default(),
                    });
                }
                None => {
                    order.push(u32::MAX);
                    instances.push(GpuInstance::default());
                }
            }
        }
        for g in &self.flat {
            for &m in &g.members {
                order.push(m as u32);
                instances.push(GpuInstance {
                    world_to_object: flatten::IDENTITY_ROWS,
                    object_to_world: flatten::IDENTITY_ROWS,
                    ..self.instance_record(m)
                });
            }
        }
        self.instances = instances;
        self.stats.flattened_objects = self.flat.iter().map(|g| g.members.len() as u32).sum();
        self.stats.flat_bvhs = self.flat.len() as u32;

        // The medium table lists instance slots, which follow the TLAS order.
        let mut slot_of = vec![u32::MAX; self.objects.len()];
        for (slot, &o) in order.iter().enumerate() {
            if let Some(s) = slot_of.get_mut(o as usize) {
                *s = slot as u32;
            }
        }
        let media: Vec<u32> = self
            .objects
            .iter()
            .zip(&slot_of)
            .filter(|(o, &slot)| o.flags & GpuInstance::FLAG_MEDIUM != 0 && slot != u32::MAX)
            .flat_map(|(_, &slot)| {
                let mut entry = [0; record::MEDIUM_ENTRY_WORDS];
                entry[record::MEDIUM_ENTRY_SLOT] = slot;
                entry
            })
            .collect();
        let table_start = self.medium_table as usize;
        if self.params.get(table_start..) != Some(&media[..]) {
            let same_len = self.params.len() == table_start + media.len();
            self.params.truncate(table_start);
            self.params.extend_from_slice(&media);
            to_u32("parameter words", self.params.len())?;
            let range = table_start..self.params.len();
            self.params_changed(same_len.then_some(range));
        }
        self.medium_count = (media.len() / record::MEDIUM_ENTRY_WORDS) as u32;

        if self.stats.tlas_depth > self.stacks.0 {
            let warning = format!(
                "the scene BVH is {} levels deep, deeper than the kernel's traversal stack ({}): \
                 some objects may be missed",
                self.stats.tlas_depth, self.stacks.0
            );
            if !self.warnings.contains(&warning) {
                self.warnings.push(warning);
            }
        }
        self.tlas_order = Some(order);
        self.tlas_bounds = tlas.root_aabb();
        self.tlas_stale = false;
        let v = next_version();
        self.versions.nodes = v;
        self.versions.instances = v;
        self.stats.tlas_ms = ms_since(start);
        Ok(())
    }

    /// The world box of an object (empty when it has none: it is then left out of the TLAS).
    fn world_box(&self, o: &ObjectEntity) -> Aabb {
        let local = match o.geometry {
            ObjectGeometry::Mesh { mesh } => {
                self.meshes.get(mesh).map_or(Aabb::EMPTY, |m| m.bounds)
            }
            ObjectGeometry::Custom {
                bounds: CustomBounds::Known(b),
                ..
            } => b,
            ObjectGeometry::Custom { .. } => Aabb::EMPTY,
        };
        transform_box(&local, &o.transform)
    }

    /// The GPU record of object `index`.
    fn instance_record(&self, index: usize) -> GpuInstance {
        let Some(o) = self.objects.get(index) else {
            return GpuInstance::default();
        };
        let (geometry_type, geometry_offset, blas_root, triangle_offset) = match o.geometry {
            ObjectGeometry::Mesh { mesh } => {
                let (root, first) = self
                    .meshes
                    .get(mesh)
                    .map_or((0, 0), |m| (m.node_base, m.triangle_base));
                (GpuInstance::MESH_GEOMETRY, 0, root, first)
            }
            ObjectGeometry::Custom { geometry, .. } => (geometry.type_id, geometry.offset, 0, 0),
        };
        GpuInstance {
            world_to_object: rows(&o.inverse),
            object_to_world: rows(&o.transform),
            geometry_type,
            geometry_offset,
            material_type: o.material.type_id,
            material_offset: o.material.offset,
            blas_root,
            triangle_offset,
            flags: o.flags,
            // Fits: checked against u32 when the objects were built.
            object: index as u32,
        }
    }

    /// Instance records in object order (slot `i` = object `i`), for the bounds kernel.
    pub fn instances_in_object_order(&self) -> Vec<GpuInstance> {
        (0..self.objects.len())
            .map(|i| self.instance_record(i))
            .collect()
    }

    /// Instance records in TLAS leaf order (empty before the first TLAS build).
    pub fn instances(&self) -> &[GpuInstance] {
        &self.instances
    }

    /// The object in each instance slot (`tlas.prim_indices()`), once the TLAS is built.
    pub fn tlas_order(&self) -> Option<&[u32]> {
        self.tlas_order.as_deref()
    }

    /// Every BVH node: the BLASes, then the TLAS from [`tlas_root`](Self::tlas_root).
    pub fn nodes(&self) -> &[NodeRecord] {
        &self.nodes
    }

    /// The scene-level BVH's root box, exactly (empty before the first build and for an empty
    /// scene).
    pub fn tlas_bounds(&self) -> Aabb {
        self.tlas_bounds
    }

    /// Index of the TLAS's header record in [`nodes`](Self::nodes) (`rtc_bvh::quantized`).
    pub fn tlas_root(&self) -> u32 {
        self.blas_nodes
    }

    /// The `triangles` buffer's contents.
    pub fn triangles(&self) -> &[[f32; 4]] {
        &self.triangles
    }

    /// The `attributes` buffer's contents.
    pub fn attributes(&self) -> &[[u32; 4]] {
        &self.attributes
    }

    /// The `params` words.
    pub fn params(&self) -> &[u32] {
        &self.params
    }

    /// The `texels` words.
    pub fn texels(&self) -> &[u32] {
        &self.texels
    }

    /// Word offset of the light table.
    pub fn light_table(&self) -> u32 {
        self.light_table
    }

    /// Word offset and length of the medium table.
    pub fn medium_table(&self) -> (u32, u32) {
        (self.medium_table, self.medium_count)
    }

    /// The frame uniforms for the current TLAS.
    pub fn frame_uniforms(&self, samples_per_pass: u32, total_samples: u32) -> FrameUniforms {
        let background = self.background.unwrap_or_default();
        FrameUniforms {
            samples_per_pass,
            total_samples,
            seed: self.settings.seed,
            tlas_root: self.blas_nodes,
            // Fits: at most the object count, checked against u32.
            instance_count: self.instances.len() as u32,
            light_count: self.lights.len() as u32,
            light_table: self.light_table,
            medium_count: self.medium_count,
            medium_table: self.medium_table,
            camera_type: self.camera.type_id,
            camera_offset: self.camera.offset,
            background_type: background.type_id,
            background_offset: background.offset,
            path_slots: 0,
            passes_per_dispatch: 1,
        }
    }

    /// The distinct meshes, in order of first use.
    pub fn meshes(&self) -> &[MeshEntity] {
        &self.meshes
    }

    /// The distinct textures, in order of first use.
    pub fn textures(&self) -> &[TextureEntity] {
        &self.textures
    }

    /// The objects, in scene order.
    pub fn objects(&self) -> &[ObjectEntity] {
        &self.objects
    }

    /// The lights, in scene order.
    pub fn lights(&self) -> &[LightEntity] {
        &self.lights
    }

    /// The camera.
    pub fn camera(&self) -> TypedOffset {
        self.camera
    }

    /// The background, if any.
    pub fn background(&self) -> Option<TypedOffset> {
        self.background
    }

    /// The scene's settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The scene's name.
    pub fn scene_name(&self) -> &str {
        &self.scene_name
    }

    /// Current versions of the buffer contents.
    pub fn versions(&self) -> Versions {
        self.versions
    }

    /// What building cost so far.
    pub fn stats(&self) -> EntityStats {
        self.stats
    }

    /// Problems that do not stop a render (BVHs deeper than the kernel's stacks).
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }
}

/// Every role-struct instance of a scene (the ones whose fields may hold assets).
fn all_instances(scene: &SceneDesc) -> impl Iterator<Item = &Instance> {
    scene
        .camera
        .iter()
        .chain(scene.background.iter())
        .chain(scene.objects.iter().flat_map(|o| {
            let geometry = match &o.geometry {
                Geometry::Custom(inst) => Some(inst),
                Geometry::Mesh(_) => None,
            };
            geometry.into_iter().chain(std::iter::once(&o.material))
        }))
        .chain(scene.lights.iter())
}
