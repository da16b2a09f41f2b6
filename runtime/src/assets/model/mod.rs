//! glTF 2.0 (`.gltf` with external or embedded buffers, and `.glb`) → [`ModelScene`], the scene
//! entities of a `model "file.glb"` entry.
//!
//! # The pipeline, in order ([`load_gltf`])
//!
//! 1. `document::parse`: split a `.glb` container (our own checked parser), parse the JSON into
//!    `gltf::json::Root`, pre-check what `gltf-json`'s validator would index unchecked, then run
//!    the validator (every index in range, required properties present, required extensions
//!    supported).
//! 2. `buffers::load`: every buffer's bytes (the `.glb` binary chunk, a `data:` URI, or a file
//!    relative to the glTF file, which must stay inside its folder or an asset root:
//!    `assets::confine`), each at least its declared length.
//! 3. `nodes::walk`: the default scene (or the first; without scenes, every parentless node),
//!    depth first, children in order, accumulating world transforms. Each node with a mesh adds
//!    one [`MeshInstance`] per primitive; each camera and `KHR_lights_punctual` light is placed
//!    in world space. Then `animation::read` reads the first animation's channels
//!    ([`NodeAnimation`], evaluated per frame as rigid node motion; animations after the first
//!    and `weights` channels are skipped with a warning).
//! 4. On first use, `primitive::convert` turns a glTF primitive into a [`MeshData`] through the
//!    checked accessor reader (`accessor.rs`), and `materials::convert` a glTF material into a
//!    [`GltfMaterial`], decoding its images into [`TextureData`]s with their samplers.
//!
//! We work on the JSON level (`gltf::json`) rather than through the `gltf` crate's wrapper types
//! and readers, because those index and slice without checking (they panic on an accessor that
//! overruns its buffer, a count of zero, a spot light without its `spot` object, …).
//!
//! # Invariants of a [`ModelScene`]
//!
//! - One [`MeshData`] per *used* glTF primitive of mode `TRIANGLES`, converted once however many
//!   nodes use it: instancing is [`MeshInstance`]s sharing a `mesh` index. Other modes, morph
//!   targets, skins, animations after the first and extensions other than `KHR_lights_punctual`,
//!   `KHR_materials_emissive_strength`, `KHR_materials_ior`, `KHR_materials_transmission` and
//!   `KHR_texture_transform` are skipped with a warning
//!   naming what they are on (an unsupported extension the file *requires* is an error).
//! - Every `MeshInstance::mesh` and `::material` and every texture of a `GltfMaterial` is
//!   a valid index into `meshes`, `materials` and `textures`. Primitives without a material use
//!   glTF's default material, appended to `materials` when needed.
//! - Transforms are finite object-to-world matrices (a node whose transform is not finite is
//!   skipped with its subtree, with a warning).
//! - glTF and rtc share conventions (right-handed, y-up, counter-clockwise front faces, uv origin
//!   top-left), so no coordinate is changed on import.

mod accessor;
pub mod animation;
mod buffers;
mod document;
mod materials;
mod nodes;
mod primitive;
mod report;

pub use report::report;

/// The URI decoders, for the tests.
#[cfg(test)]
pub(crate) mod buffers_for_tests {
    pub(crate) use super::buffers::{decode_base64, percent_decode};
}

use std::path::Path;
use std::sync::Arc;

use glam::{Mat4, Vec3};

pub use animation::NodeAnimation;

use super::{AssetError, AssetRoots, Bounds, MeshData, TextureData};

/// Everything a glTF file contributes to a scene.
#[derive(Clone, Debug, Default)]
pub struct ModelScene {
    /// One mesh per used glTF primitive.
    pub meshes: Vec<MeshData>,
    /// What each of `meshes` is in the file, for messages: `meshes[2].primitives[0] (`Wheel`)`.
    pub mesh_labels: Vec<String>,
    /// What each of `materials` is in the file, for messages and the report: `materials[3]
    /// (`Red`)`, or `glTF's default material`.
    pub material_labels: Vec<String>,
    /// Placed meshes; several may share a mesh.
    pub instances: Vec<MeshInstance>,
    /// The used materials (glTF's default material last, when a primitive has none).
    pub materials: Vec<GltfMaterial>,
    /// The decoded images of the materials, one per (image, sampler) pair used, each with its
    /// sampler.
    pub textures: Vec<TextureData>,
    /// What each of `textures` is in the file, unique per texture: `images[3]`, or
    /// `images[3]~clamp,mirror,nearest` when its sampler is not the default (repeat, bilinear).
    pub texture_labels: Vec<String>,
    /// The cameras of the scene's nodes, in node order; the first is the default camera.
    pub cameras: Vec<GltfCamera>,
    /// The `KHR_lights_punctual` lights of the scene's nodes, in node order.
    pub lights: Vec<GltfLight>,
    /// The file's first animation (rigid node motion), if it has one with a usable channel.
    pub animation: Option<Arc<NodeAnimation>>,
    /// What was skipped or approximated, one sentence each.
    pub warnings: Vec<String>,
}

impl ModelScene {
    /// The world-space box around all instances (empty when there are none), for framing the
    /// model with a camera.
    pub fn bounds(&self) -> Bounds {
        let mesh_bounds: Vec<Bounds> = self.meshes.iter().map(MeshData::bounds).collect();
        self.instances
            .iter()
            .filter_map(|i| Some(mesh_bounds.get(i.mesh)?.transformed(&i.transform)))
            .fold(Bounds::EMPTY, Bounds::union)
    }

    /// The default camera: the first one in the scene.
    pub fn default_camera(&self) -> Option<&GltfCamera> {
        self.cameras.first()
    }
}

/// A mesh placed in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshInstance {
    /// Index into [`ModelScene::meshes`].
    pub mesh: usize,
    /// Index into [`ModelScene::materials`].
    pub material: usize,
    /// Object-to-world transform (the node's world transform).
    pub transform: Mat4,
    /// The glTF node it comes from.
    pub node: usize,
}

/// How a material treats alpha (glTF `alphaMode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AlphaMode {
    /// Alpha is ignored.
    #[default]
    Opaque,
    /// Alpha below `alpha_cutoff` is fully transparent, otherwise opaque.
    Mask,
    /// Alpha blends.
    Blend,
}

/// An affine map of texture coordinates, as two rows: `u' = r0 · (u, v, 1)`,
/// `v' = r1 · (u, v, 1)` (`KHR_texture_transform`: `translation × rotation × scale`).
pub type UvTransform = [[f32; 3]; 2];

/// The identity [`UvTransform`].
pub const UV_IDENTITY: UvTransform = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];

/// A glTF metallic-roughness material.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfMaterial {
    /// The material's name, if any.
    pub name: Option<String>,
    /// Its index in the file's `materials` (`None`: glTF's default material).
    pub index: Option<usize>,
    /// Linear RGBA base colour factor (multiplies the texture).
    pub base_color: [f32; 4],
    /// Index into [`ModelScene::textures`] of the base-colour image (sRGB). Every texture is
    /// sampled with `TEXCOORD_0`.
    pub base_color_texture: Option<usize>,
    /// Metalness factor, 0..=1.
    pub metallic: f32,
    /// Perceptual roughness factor, 0..=1.
    pub roughness: f32,
    /// Index into [`ModelScene::textures`] of the metallic-roughness image (linear; blue =
    /// metalness, green = roughness, each multiplying its factor).
    pub metallic_roughness_texture: Option<usize>,
    /// Linear emitted radiance factor (times `KHR_materials_emissive_strength`).
    pub emissive: [f32; 3],
    /// Index into [`ModelScene::textures`] of the emissive image (sRGB), multiplying `emissive`.
    pub emissive_texture: Option<usize>,
    /// Index into [`ModelScene::textures`] of the occlusion image (linear; red).
    pub occlusion_texture: Option<usize>,
    /// How much the occlusion image darkens: `1 + strength (red - 1)`.
    pub occlusion_strength: f32,
    /// Index into [`ModelScene::textures`] of the tangent-space normal image (linear).
    pub normal_texture: Option<usize>,
    /// The normal texture's `scale` (multiplies the x and y of the tangent-space normal).
    pub normal_scale: f32,
    /// The `KHR_texture_transform` of each texture: base colour, metallic-roughness, emissive,
    /// occlusion, normal, in that order ([`UV_IDENTITY`] without one).
    pub uv_transforms: [UvTransform; 5],
    /// Which textures read uv set 1 (`TEXCOORD_1`): bit `k` for texture `k` in the order of
    /// `uv_transforms`; the others read set 0.
    pub uv_sets: u32,
    /// Whether a primitive that uses it has `COLOR_0` vertex colours (multiplying the base
    /// colour and alpha; a mesh without them counts as white).
    pub vertex_colors: bool,
    /// Whether its base-colour texture has a `KHR_texture_transform` (even the identity).
    pub base_color_transformed: bool,
    /// How alpha is used.
    pub alpha_mode: AlphaMode,
    /// The cutoff of [`AlphaMode::Mask`].
    pub alpha_cutoff: f32,
    /// Whether back faces are lit like front faces.
    pub double_sided: bool,
    /// `KHR_materials_transmission`'s factor, 0..=1 (0: none; above 0, with
    /// [`AlphaMode::Opaque`]: a `GltfTransmissiveMaterial`).
    pub transmission: f32,
    /// `KHR_materials_ior`'s index of refraction, clamped to 1..=4 (1.5 without it).
    pub ior: f32,
}

impl GltfMaterial {
    /// Whether an opaque material of this kind needs `GltfMappedMaterial` (a texture besides the
    /// base colour's, or a texture transform), decided as the link step's `is_mapped` decides
    /// from the JSON, so the type it needs was linked.
    pub fn is_mapped(&self) -> bool {
        self.metallic_roughness_texture.is_some()
            || self.emissive_texture.is_some()
            || self.occlusion_texture.is_some()
            || self.base_color_transformed
    }

    /// Whether it needs `GltfDetailMaterial` (or `GltfMaskedDetailMaterial`): a normal texture,
    /// a texture on uv set 1, or vertex colours, which need the per-vertex data only such
    /// materials read; decided as the link step's `is_detailed` decides from the JSON.
    pub fn is_detailed(&self) -> bool {
        self.normal_texture.is_some() || self.uv_sets != 0 || self.vertex_colors
    }
}

impl Default for GltfMaterial {
    /// glTF's default material: white, fully metallic and rough, opaque, single-sided.
    fn default() -> Self {
        Self {
            name: None,
            index: None,
            base_color: [1.0; 4],
            base_color_texture: None,
            metallic: 1.0,
            roughness: 1.0,
            metallic_roughness_texture: None,
            emissive: [0.0; 3],
            emissive_texture: None,
            occlusion_texture: None,
            occlusion_strength: 1.0,
            normal_texture: None,
            normal_scale: 1.0,
            uv_transforms: [UV_IDENTITY; 5],
            uv_sets: 0,
            vertex_colors: false,
            base_color_transformed: false,
            alpha_mode: AlphaMode::Opaque,
            alpha_cutoff: 0.5,
            double_sided: false,
            transmission: 0.0,
            ior: 1.5,
        }
    }
}

/// A camera's projection (glTF units: radians, scene units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// A pinhole camera.
    Perspective {
        /// Vertical field of view in radians.
        yfov: f32,
        /// Width / height, if the file fixes it (otherwise the image's).
        aspect: Option<f32>,
        /// Near plane distance.
        znear: f32,
        /// Far plane distance; `None` is infinite.
        zfar: Option<f32>,
    },
    /// An orthographic camera.
    Orthographic {
        /// Half the view's width.
        xmag: f32,
        /// Half the view's height.
        ymag: f32,
        /// Near plane distance.
        znear: f32,
        /// Far plane distance.
        zfar: f32,
    },
}

/// A camera placed in the world. In its own frame it looks down -z with +y up.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfCamera {
    /// The camera's name, if any.
    pub name: Option<String>,
    /// The projection.
    pub projection: Projection,
    /// Camera-to-world transform (the node's world transform).
    pub transform: Mat4,
}

impl GltfCamera {
    /// The eye position in world space.
    pub fn position(&self) -> Vec3 {
        self.transform.transform_point3(Vec3::ZERO)
    }

    /// The unit viewing direction in world space.
    pub fn forward(&self) -> Vec3 {
        self.transform
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or(Vec3::NEG_Z)
    }

    /// The unit up direction in world space.
    pub fn up(&self) -> Vec3 {
        self.transform
            .transform_vector3(Vec3::Y)
            .normalize_or(Vec3::Y)
    }
}

/// The kind of a `KHR_lights_punctual` light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// Emits in all directions from `position`; intensity in candela.
    Point,
    /// A cone around `direction` from `position`; intensity in candela.
    Spot {
        /// Angle in radians from the axis where the falloff begins.
        inner_cone_angle: f32,
        /// Angle in radians from the axis where the light ends.
        outer_cone_angle: f32,
    },
    /// Parallel light along `direction`; intensity in lux.
    Directional,
}

/// A `KHR_lights_punctual` light placed in the world.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfLight {
    /// The light's name, if any.
    pub name: Option<String>,
    /// Point, spot or directional.
    pub kind: LightKind,
    /// Linear RGB colour.
    pub color: [f32; 3],
    /// Brightness (candela for point and spot, lux for directional).
    pub intensity: f32,
    /// Distance where the light's influence ends; `None` is infinite.
    pub range: Option<f32>,
    /// World-space position (meaningless for directional lights).
    pub position: Vec3,
    /// Unit world-space direction the light shines in (the node's -z; unused for point lights).
    pub direction: Vec3,
}

/// Reads a glTF 2.0 file (`.gltf` or `.glb`, told apart by content) and everything it refers to.
/// See the [module docs](self) for what is imported and what is skipped.
/// The files its buffers and images name must lie inside the file's own folder.
pub fn load_gltf(path: impl AsRef<Path>) -> Result<ModelScene, AssetError> {
    load_gltf_with(path, &AssetRoots::none())
}

/// [`load_gltf`], also letting buffers and images come from the folders `roots` (`--asset-root`).
pub fn load_gltf_with(
    path: impl AsRef<Path>,
    roots: &AssetRoots,
) -> Result<ModelScene, AssetError> {
    let path = path.as_ref();
    let bytes = super::confine::read(path, roots).map_err(|source| AssetError::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_gltf_with(&bytes, path, roots)
}

/// The files a glTF file (its bytes; `path` is where it is) names for its buffers and images,
/// resolved and confined against its folder (and `roots`) as reading it would: what a host that
/// fetches files (the web page) must fetch before the model can be read. `data:` URIs and paths
/// that would be refused are not listed; a file that is not glTF names nothing.
pub fn external_files(bytes: &[u8], path: &Path, roots: &AssetRoots) -> Vec<std::path::PathBuf> {
    match document::parse(bytes, path) {
        Ok((root, _)) => buffers::external_files(&root, path, roots),
        Err(_) => Vec::new(),
    }
}

/// [`load_gltf`] on the file's bytes; `path` names the file in errors and its folder is where
/// relative URIs are resolved (and must stay).
#[cfg(test)]
pub(crate) fn parse_gltf(bytes: &[u8], path: &Path) -> Result<ModelScene, AssetError> {
    parse_gltf_with(bytes, path, &AssetRoots::none())
}

/// [`load_gltf_with`] on the file's bytes; `path` names the file in errors and its folder is where
/// relative URIs are resolved (and must stay, or in one of `roots`).
pub(crate) fn parse_gltf_with(
    bytes: &[u8],
    path: &Path,
    roots: &AssetRoots,
) -> Result<ModelScene, AssetError> {
    let (root, blob) = document::parse(bytes, path)?;
    let buffers = buffers::load(&root, blob, path, roots)?;
    // The JSON text (a `.glb`'s first chunk; the container was checked by `document::parse`).
    let json = if bytes.starts_with(b"glTF") {
        document::split_glb(bytes).map_or(&[][..], |(json, _)| json)
    } else {
        bytes
    };
    let ctx = Ctx {
        path,
        json,
        root: &root,
        buffers: &buffers,
        roots,
    };
    nodes::build(&ctx)
}

/// What every conversion step reads: the file's name, its validated JSON and its buffers.
struct Ctx<'a> {
    path: &'a Path,
    /// The JSON text, for what `gltf-json` does not keep (extensions it does not know).
    json: &'a [u8],
    roots: &'a AssetRoots,
    root: &'a gltf::json::Root,
    buffers: &'a [Vec<u8>],
}
