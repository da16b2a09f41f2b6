//! What a scene's glTF `model` files hold, as far as linking cares: which `KHR_lights_punctual`
//! light types, which material alpha modes, and whether a perspective camera occurs; so a scene
//! with a `model` entry links only the standard-library types ([`MODEL_TYPES`]) its files bring.
//!
//! The file is found with the runtime's rules ([`crate::confine`]: the scene's folder, then the
//! asset roots of [`super::LinkOptions::asset_roots`]), or, with [`super::LinkOptions::memory`],
//! looked up in that in-memory file set (inside the scene's folder only), and only its JSON is read: a `.glb`'s JSON
//! chunk is cut out with checked lengths, deserialised by `gltf-json` and not validated (its
//! validator can panic on hostile input; the runtime validates when it imports the file). No
//! buffer or image is read.
//!
//! Guarantees:
//! - **What is linked is a superset of what the runtime imports** (`rtc_runtime`'s
//!   `scene/models.rs`): every light of the extension's list counts, whether a node uses it or
//!   not; the alpha mode of every material that any mesh primitive names counts (glTF's default
//!   material, opaque, for a primitive that names none); any perspective camera counts.
//! - **A file that cannot be found, read or parsed links everything** ([`ModelRead::NotRead`],
//!   with the reason): the kernel is then the unspecialised one of earlier releases, and the
//!   runtime, which reads the file again, reports the problem as a located diagnostic at the
//!   `model` entry (E0903 outside the allowed folders, the asset errors otherwise). The compile
//!   never fails because of a model file.
//! - No input panics: lengths from the file use checked arithmetic, indices are looked up with
//!   `get`.

use std::collections::BTreeSet;
use std::path::Path;

use gltf::json::extensions::scene::khr_lights_punctual::Type;
use gltf::json::{self, validation::Checked};

use crate::confine::{resolve_scene_path, AssetRoots};
use crate::sema::hir::{Model, Program, SceneDesc};
use crate::source::{MemoryFiles, Span};

/// What one of [`MODEL_TYPES`] stands for in a glTF file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ModelPart {
    /// A material with `alphaMode` `OPAQUE` and no texture but the base colour's.
    OpaqueMaterial,
    /// A material with `alphaMode` `OPAQUE` and a metallic-roughness, emissive or occlusion
    /// texture, or a `KHR_texture_transform` on any texture.
    MappedMaterial,
    /// A material with `alphaMode` `MASK` or `BLEND` (the any-hit path: a cutoff, or stochastic
    /// coverage) and no texture but the base colour's.
    MaskedMaterial,
    /// A `MASK` or `BLEND` material with more textures or a transform (as `MappedMaterial`).
    MaskedMappedMaterial,
    /// An `OPAQUE` material with a normal texture, a texture on uv set 1, or vertex colours
    /// (`COLOR_0` on a primitive that uses it): the per-vertex extras ([`is_detailed`]).
    DetailMaterial,
    /// A `MASK` or `BLEND` material that needs the per-vertex extras.
    MaskedDetailMaterial,
    /// A `KHR_lights_punctual` point light.
    PointLight,
    /// A `KHR_lights_punctual` directional light.
    DirectionalLight,
    /// A `KHR_lights_punctual` spot light.
    SpotLight,
    /// A perspective camera (used only when the scene has no `camera` entry).
    PerspectiveCamera,
    /// An `OPAQUE` material with `doubleSided: false` (glTF's default material among them): its
    /// objects cull back faces in traversal (`KernelConfig::cull_back_faces`). Not a type: it
    /// switches a kernel feature on.
    SingleSidedMaterial,
    /// An `OPAQUE` material with `KHR_materials_transmission` (factor above 0): a
    /// `GltfTransmissiveMaterial`, which spawns a reflected or refracted ray.
    TransmissiveMaterial,
}

impl ModelPart {
    /// Every part, in order.
    pub const ALL: [ModelPart; 12] = [
        ModelPart::OpaqueMaterial,
        ModelPart::MappedMaterial,
        ModelPart::MaskedMaterial,
        ModelPart::MaskedMappedMaterial,
        ModelPart::DetailMaterial,
        ModelPart::MaskedDetailMaterial,
        ModelPart::PointLight,
        ModelPart::DirectionalLight,
        ModelPart::SpotLight,
        ModelPart::PerspectiveCamera,
        ModelPart::SingleSidedMaterial,
        ModelPart::TransmissiveMaterial,
    ];

    /// How `manifest.json` names it.
    pub fn name(self) -> &'static str {
        match self {
            ModelPart::OpaqueMaterial => "opaque material",
            ModelPart::MappedMaterial => "opaque material with more textures",
            ModelPart::MaskedMaterial => "alpha-masked or blended material",
            ModelPart::MaskedMappedMaterial => {
                "alpha-masked or blended material with more textures"
            }
            ModelPart::DetailMaterial => {
                "opaque material with a normal map, a second uv set or vertex colours"
            }
            ModelPart::MaskedDetailMaterial => {
                "alpha-masked or blended material with a normal map, a second uv set or vertex colours"
            }
            ModelPart::PointLight => "point light",
            ModelPart::DirectionalLight => "directional light",
            ModelPart::SpotLight => "spot light",
            ModelPart::PerspectiveCamera => "perspective camera",
            ModelPart::SingleSidedMaterial => "single-sided opaque material",
            ModelPart::TransmissiveMaterial => "transmissive material",
        }
    }
}

/// A standard-library role struct a `model` entry may become.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ModelType {
    /// Its module (`std/…`).
    pub module: &'static str,
    /// The struct's name.
    pub name: &'static str,
    /// What in the file it stands for.
    pub part: ModelPart,
}

/// The standard-library role structs a scene's `model` entries become: the glTF materials (opaque,
/// and alpha-masked or blended with an `@any_hit` program), the `KHR_lights_punctual` lights, and the camera
/// (used only when the scene has no `camera` entry). The driver loads these modules for any scene
/// with a `model` entry; [`super::link`] links those whose part a file of the scene holds.
pub const MODEL_TYPES: &[ModelType] = &[
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfMaterial",
        part: ModelPart::OpaqueMaterial,
    },
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfMappedMaterial",
        part: ModelPart::MappedMaterial,
    },
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfMaskedMaterial",
        part: ModelPart::MaskedMaterial,
    },
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfMaskedMappedMaterial",
        part: ModelPart::MaskedMappedMaterial,
    },
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfDetailMaterial",
        part: ModelPart::DetailMaterial,
    },
    ModelType {
        module: "std/materials/gltf.rt",
        name: "GltfMaskedDetailMaterial",
        part: ModelPart::MaskedDetailMaterial,
    },
    ModelType {
        module: "std/materials/gltf_transmission.rt",
        name: "GltfTransmissiveMaterial",
        part: ModelPart::TransmissiveMaterial,
    },
    ModelType {
        module: "std/lights/point.rt",
        name: "PointLight",
        part: ModelPart::PointLight,
    },
    ModelType {
        module: "std/lights/directional.rt",
        name: "DirectionalLight",
        part: ModelPart::DirectionalLight,
    },
    ModelType {
        module: "std/lights/spot.rt",
        name: "SpotLight",
        part: ModelPart::SpotLight,
    },
    ModelType {
        module: "std/cameras/pinhole.rt",
        name: "Pinhole",
        part: ModelPart::PerspectiveCamera,
    },
];

/// What reading one model file at compile time gave.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ModelRead {
    /// The parts the file holds.
    Read(BTreeSet<ModelPart>),
    /// Why it could not be read; everything is linked for it.
    NotRead(String),
}

impl ModelRead {
    /// Whether the file may bring `part` (always, when it was not read).
    pub fn brings(&self, part: ModelPart) -> bool {
        match self {
            ModelRead::Read(parts) => parts.contains(&part),
            ModelRead::NotRead(_) => true,
        }
    }
}

/// One `model` entry of the linked scene and what its file holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModelLink {
    /// The path as the scene wrote it (relative to the scene's folder).
    pub path: String,
    /// The entry's string.
    pub span: Span,
    /// What the file holds.
    pub read: ModelRead,
}

/// Reads every `model` entry of `desc` (a scene of `program`), each file once; an entry whose
/// path is in `known` (an earlier link of the same scene: the pipeline links twice) is not read
/// again.
pub fn read_models(
    program: &Program,
    desc: &SceneDesc,
    options: &super::LinkOptions,
    known: &[ModelLink],
) -> Vec<ModelLink> {
    let scene_file = program
        .modules
        .get(desc.module.index())
        .and_then(|m| m.path.as_deref());
    let scene_dir = scene_file.and_then(Path::parent).unwrap_or(Path::new(""));
    let mut out: Vec<ModelLink> = Vec::with_capacity(desc.models.len());
    for (i, model) in desc.models.iter().enumerate() {
        let written = written_path(model, scene_dir);
        let earlier = desc.models[..i]
            .iter()
            .position(|m| m.path == model.path)
            .and_then(|j| out.get(j))
            .or_else(|| known.iter().find(|k| k.path == written));
        let read = match earlier {
            Some(first) => first.read.clone(),
            None => match &options.memory {
                Some(files) => read_model_in(files, &model.path, scene_dir),
                None => read_model(&model.path, scene_dir, &options.asset_roots),
            },
        };
        out.push(ModelLink {
            path: written,
            span: model.span,
            read,
        });
    }
    out
}

/// The path of `model` as written in the scene (its compiled path less the scene's folder).
fn written_path(model: &Model, scene_dir: &Path) -> String {
    let written = if scene_dir.as_os_str().is_empty() {
        &model.path
    } else {
        model.path.strip_prefix(scene_dir).unwrap_or(&model.path)
    };
    written.to_string_lossy().into_owned()
}

/// Reads what one model file holds, or why not.
pub fn read_model(compiled: &Path, scene_dir: &Path, roots: &AssetRoots) -> ModelRead {
    let file = match resolve_scene_path(compiled, scene_dir, roots) {
        Ok(f) => f,
        Err((written, problem)) => {
            return ModelRead::NotRead(format!("`{written}` {problem}"));
        }
    };
    let bytes = match std::fs::read(&file) {
        Ok(b) => b,
        Err(e) => return ModelRead::NotRead(format!("`{}` cannot be read: {e}", file.display())),
    };
    match parts_of(&bytes) {
        Ok(parts) => ModelRead::Read(parts),
        Err(why) => ModelRead::NotRead(format!("`{}` {why}", file.display())),
    }
}

/// [`read_model`] from an in-memory file set: the file must be in the set and, lexically, inside
/// the scene's folder.
pub fn read_model_in(files: &MemoryFiles, compiled: &Path, scene_dir: &Path) -> ModelRead {
    let file = MemoryFiles::normalize(compiled);
    let dir = MemoryFiles::normalize(scene_dir);
    let written = file
        .strip_prefix(&dir)
        .unwrap_or(&file)
        .display()
        .to_string();
    if compiled.has_root() || !file.starts_with(&dir) || file.starts_with("..") {
        return ModelRead::NotRead(format!("`{written}` is outside the scene's folder"));
    }
    let Some(bytes) = files.get(&file) else {
        return ModelRead::NotRead(format!(
            "`{written}` is not among the files given to the compiler (in memory)"
        ));
    };
    match parts_of(bytes) {
        Ok(parts) => ModelRead::Read(parts),
        Err(why) => ModelRead::NotRead(format!("`{written}` {why}")),
    }
}

/// The parts a glTF or GLB file's bytes hold.
pub fn parts_of(bytes: &[u8]) -> Result<BTreeSet<ModelPart>, String> {
    let text = json_chunk(bytes)?;
    let text = text.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(text);
    let root: json::Root =
        json::deserialize::from_slice(text).map_err(|e| format!("is not glTF JSON: {e}"))?;
    Ok(parts_of_root(&root))
}

/// Whether a material needs `GltfMappedMaterial` (or `GltfMaskedMappedMaterial`): it has a metallic-roughness, emissive
/// or occlusion texture, or a `KHR_texture_transform` on any of its textures. The runtime's
/// import (`GltfMaterial::is_mapped`) decides the same way.
pub fn is_mapped(m: &json::Material) -> bool {
    let transformed = |e: Option<&json::extensions::texture::Info>| {
        e.is_some_and(|e| e.texture_transform.is_some())
    };
    let pbr = &m.pbr_metallic_roughness;
    pbr.metallic_roughness_texture.is_some()
        || m.emissive_texture.is_some()
        || m.occlusion_texture.is_some()
        || pbr
            .base_color_texture
            .as_ref()
            .is_some_and(|t| transformed(t.extensions.as_ref()))
}

/// Whether glTF material `index` (`None`: the default material, `m` its JSON when it has one)
/// needs `GltfDetailMaterial` (or `GltfMaskedDetailMaterial`): a normal texture, a texture on
/// uv set 1 (`texCoord`, or `KHR_texture_transform`'s), or `COLOR_0` on a primitive that uses
/// it. The runtime's import (`GltfMaterial::is_detailed`) decides the same way.
pub fn is_detailed(root: &json::Root, index: Option<usize>, m: Option<&json::Material>) -> bool {
    let colors = root.meshes.iter().flat_map(|m| &m.primitives).any(|p| {
        p.material.map(|i| i.value()) == index
            && p.attributes
                .contains_key(&Checked::Valid(json::mesh::Semantic::Colors(0)))
    });
    let Some(m) = m else { return colors };
    let info = |i: Option<&json::texture::Info>| {
        i.is_some_and(|i| {
            i.extensions
                .as_ref()
                .and_then(|e| e.texture_transform.as_ref())
                .and_then(|t| t.tex_coord)
                .unwrap_or(i.tex_coord)
                == 1
        })
    };
    let other = |set: u32, e: Option<&json::extensions::material::OcclusionTexture>| {
        e.and_then(|e| e.others.get("KHR_texture_transform"))
            .and_then(|t| t.get("texCoord"))
            .and_then(|c| c.as_u64())
            .map_or(set, |c| u32::try_from(c).unwrap_or(u32::MAX))
            == 1
    };
    let normal_set = |n: &json::material::NormalTexture| {
        n.extensions
            .as_ref()
            .and_then(|e| e.others.get("KHR_texture_transform"))
            .and_then(|t| t.get("texCoord"))
            .and_then(|c| c.as_u64())
            .map_or(n.tex_coord, |c| u32::try_from(c).unwrap_or(u32::MAX))
    };
    let pbr = &m.pbr_metallic_roughness;
    colors
        || m.normal_texture.is_some()
        || info(pbr.base_color_texture.as_ref())
        || info(pbr.metallic_roughness_texture.as_ref())
        || info(m.emissive_texture.as_ref())
        || m.occlusion_texture
            .as_ref()
            .is_some_and(|o| other(o.tex_coord, o.extensions.as_ref()))
        || m.normal_texture
            .as_ref()
            .is_some_and(|n| normal_set(n) == 1)
}

/// Whether an `OPAQUE` material is a `GltfTransmissiveMaterial`: its `KHR_materials_transmission`
/// factor is above 0 (the runtime's `GltfMaterial::transmission` decides alike).
pub fn is_transmissive(m: &json::Material) -> bool {
    m.extensions
        .as_ref()
        .and_then(|e| e.transmission.as_ref())
        .is_some_and(|t| t.transmission_factor.0 > 0.0)
}

/// The parts a parsed glTF document holds (see the module docs for what counts).
pub fn parts_of_root(root: &json::Root) -> BTreeSet<ModelPart> {
    let mut parts = BTreeSet::new();
    for primitive in root.meshes.iter().flat_map(|m| &m.primitives) {
        let index = primitive.material.map(|i| i.value());
        let material = index.and_then(|i| root.materials.get(i));
        let masked = matches!(
            material.map(|m| m.alpha_mode),
            Some(Checked::Valid(
                json::material::AlphaMode::Mask | json::material::AlphaMode::Blend
            ))
        );
        // A transmissive material takes precedence over a detailed one (its dielectric has no
        // normal map), as in the runtime's import (`runtime/src/scene/models.rs`).
        let transmissive = !masked && material.is_some_and(is_transmissive);
        parts.insert(if transmissive {
            ModelPart::TransmissiveMaterial
        } else if is_detailed(root, index, material) {
            if masked {
                ModelPart::MaskedDetailMaterial
            } else {
                ModelPart::DetailMaterial
            }
        } else if masked && material.is_some_and(is_mapped) {
            ModelPart::MaskedMappedMaterial
        } else if masked {
            ModelPart::MaskedMaterial
        } else if material.is_some_and(is_mapped) {
            ModelPart::MappedMaterial
        } else {
            ModelPart::OpaqueMaterial
        });
        // glTF's default material (no `material`) is single-sided too. A transmissive material
        // is never culled: its refracted rays leave through the back faces.
        if !masked && !transmissive && !material.is_some_and(|m| m.double_sided) {
            parts.insert(ModelPart::SingleSidedMaterial);
        }
    }
    let lights = root
        .extensions
        .as_ref()
        .and_then(|e| e.khr_lights_punctual.as_ref())
        .map(|l| l.lights.as_slice())
        .unwrap_or(&[]);
    for light in lights {
        match light.type_ {
            Checked::Valid(Type::Point) => parts.insert(ModelPart::PointLight),
            Checked::Valid(Type::Directional) => parts.insert(ModelPart::DirectionalLight),
            Checked::Valid(Type::Spot) => parts.insert(ModelPart::SpotLight),
            Checked::Invalid => false,
        };
    }
    if root.cameras.iter().any(|c| {
        matches!(c.type_, Checked::Valid(json::camera::Type::Perspective))
            || c.perspective.is_some()
    }) {
        parts.insert(ModelPart::PerspectiveCamera);
    }
    parts
}

/// The JSON of a `.gltf` file (the bytes) or of a `.glb` container (its first chunk, which the
/// format requires to be JSON), every length checked against the file.
fn json_chunk(bytes: &[u8]) -> Result<&[u8], String> {
    if !bytes.starts_with(b"glTF") {
        return Ok(bytes);
    }
    let word = |at: usize| -> Option<u32> {
        let b = bytes.get(at..at.checked_add(4)?)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let truncated = || "is a truncated .glb container".to_owned();
    let length = word(12).ok_or_else(truncated)? as usize;
    let kind = word(16).ok_or_else(truncated)?;
    if kind != u32::from_le_bytes(*b"JSON") {
        return Err("is a .glb container whose first chunk is not JSON".to_owned());
    }
    bytes
        .get(20..20usize.checked_add(length).ok_or_else(truncated)?)
        .ok_or_else(truncated)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parts(text: &str) -> Vec<ModelPart> {
        parts_of(text.as_bytes())
            .unwrap_or_else(|e| panic!("{e}"))
            .into_iter()
            .collect()
    }

    const ASSET: &str = r#""asset": {"version": "2.0"}"#;

    #[test]
    fn lights_materials_and_cameras_are_found() {
        let text = format!(
            r#"{{ {ASSET},
            "extensionsUsed": ["KHR_lights_punctual"],
            "extensions": {{"KHR_lights_punctual": {{"lights": [{{"type": "point"}}, {{"type": "spot", "spot": {{}}}}]}}}},
            "materials": [{{"alphaMode": "MASK"}}, {{"alphaMode": "OPAQUE"}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 0}},
                                        {{"attributes": {{"POSITION": 0}}, "material": 1}}]}}],
            "cameras": [{{"type": "perspective", "perspective": {{"yfov": 1.0, "znear": 0.1}}}}]
            }}"#
        );
        assert_eq!(
            parts(&text),
            [
                ModelPart::OpaqueMaterial,
                ModelPart::MaskedMaterial,
                ModelPart::PointLight,
                ModelPart::SpotLight,
                ModelPart::PerspectiveCamera,
                ModelPart::SingleSidedMaterial
            ]
        );
    }

    #[test]
    fn an_opaque_material_with_more_textures_or_a_transform_is_mapped() {
        let text = format!(
            r#"{{ {ASSET}, "materials": [
                {{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}},
                {{"emissiveTexture": {{"index": 0}}}},
                {{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0,
                    "extensions": {{"KHR_texture_transform": {{"offset": [0.5, 0]}}}}}}}}}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 0}}]}},
                       {{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 1}}]}},
                       {{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 2}}]}}] }}"#
        );
        assert_eq!(
            parts(&text),
            [
                ModelPart::OpaqueMaterial,
                ModelPart::MappedMaterial,
                ModelPart::SingleSidedMaterial
            ]
        );
    }

    #[test]
    fn a_blended_material_takes_the_any_hit_path() {
        let text = format!(
            r#"{{ {ASSET}, "materials": [{{"alphaMode": "BLEND"}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 0}}]}}] }}"#
        );
        assert_eq!(parts(&text), [ModelPart::MaskedMaterial]);
    }

    #[test]
    fn a_transmissive_material_is_its_own_part_and_never_culled() {
        let text = format!(
            r#"{{ {ASSET}, "materials": [
                {{"extensions": {{"KHR_materials_transmission": {{"transmissionFactor": 1.0}},
                                 "KHR_materials_ior": {{"ior": 1.33}}}}}},
                {{"extensions": {{"KHR_materials_transmission": {{"transmissionFactor": 0.0}}}},
                  "doubleSided": true}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 0}},
                                        {{"attributes": {{"POSITION": 0}}, "material": 1}}]}}] }}"#
        );
        assert_eq!(
            parts(&text),
            [ModelPart::OpaqueMaterial, ModelPart::TransmissiveMaterial]
        );
    }

    #[test]
    fn a_primitive_without_material_is_opaque_and_unused_materials_do_not_count() {
        let text = format!(
            r#"{{ {ASSET}, "materials": [{{"alphaMode": "MASK"}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}] }}"#
        );
        // glTF's default material is opaque and single-sided.
        assert_eq!(
            parts(&text),
            [ModelPart::OpaqueMaterial, ModelPart::SingleSidedMaterial]
        );
        assert_eq!(parts(&format!("{{ {ASSET} }}")), []);
    }

    #[test]
    fn a_glb_container_is_cut_with_checked_lengths() {
        let json = format!(r#"{{ {ASSET}, "cameras": [{{"type": "perspective"}}] }}"#);
        let mut glb = b"glTF".to_vec();
        glb.extend(2u32.to_le_bytes());
        glb.extend(0u32.to_le_bytes());
        glb.extend((json.len() as u32).to_le_bytes());
        glb.extend(b"JSON");
        glb.extend(json.as_bytes());
        assert_eq!(
            parts_of(&glb).map(|p| p.into_iter().collect::<Vec<_>>()),
            Ok(vec![ModelPart::PerspectiveCamera])
        );
        for cut in [4, 13, 19, 21, glb.len() - 1] {
            assert!(parts_of(&glb[..cut]).is_err(), "cut at {cut}");
        }
        let mut huge = glb.clone();
        huge[12..16].copy_from_slice(&u32::MAX.to_le_bytes());
        assert!(parts_of(&huge).is_err());
        assert!(parts_of(b"not json").is_err());
    }
}
