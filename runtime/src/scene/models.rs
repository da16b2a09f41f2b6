//! A scene's `model "file.glb" { transform: … }` entries → objects, lights and a camera made of the
//! standard-library role structs the compiler linked for them (`rtc_compiler::link::MODEL_TYPES`;
//! the link step read the file's metadata and linked only the types it holds).
//!
//! What each part of a glTF file becomes:
//! - every triangle primitive → one mesh in the [`AssetCache`] (key [`MeshKey::Model`]), so it gets
//!   **one object-level BVH however many nodes instance it**;
//! - every node instancing a primitive → one object, object-to-world = the entry's `transform` ×
//!   the node's world transform, named `file.glb#nodes[i]`;
//! - every used material → a `GltfMaterial` (`stdlib/materials/gltf.rt`; `GltfMappedMaterial`
//!   when it has more textures or a transform, `GltfMaterial::is_mapped`;
//!   `GltfDetailMaterial` when it has a normal texture, a texture on uv set 1 or vertex colours,
//!   `GltfMaskedMaterial` / `GltfMaskedMappedMaterial` / `GltfMaskedDetailMaterial` for
//!   `alphaMode: MASK` (its `alpha_cutoff`) and `BLEND`
//!   (`blend` 1: stochastic coverage), with `double_sided`; `GltfTransmissiveMaterial` for an
//!   opaque material with `KHR_materials_transmission` (before the detailed one); the objects of
//!   an opaque, non-transmissive single-sided material cull back faces in traversal instead
//!   (`GpuInstance::FLAG_CULL_BACK`; under a mirroring node transform glTF reverses the winding,
//!   which keeps the front on the same side of the surface, the side of the inverse-transposed
//!   normal that `Hit.front_face` uses, so the flag is the same)):
//!   base colour factor and texture, metallic and roughness factors and their texture, emissive
//!   factor and texture, occlusion texture and strength (a texture the material lacks is
//!   `solid_texture(vec4f(1.0))`). Each texture enters the cache under the path
//!   `file.glb#<label>` (`ModelScene::texture_labels`: `images[i]`, plus its sampler and
//!   linearity when they are not the default), which is how the instance's `texture` fields
//!   refer to it;
//! - `KHR_lights_punctual` lights → `PointLight`, `DirectionalLight` or `SpotLight`
//!   (`stdlib/lights/`), glTF's intensity as is (candela for point and spot, whose strength falls
//!   off with the inverse square of the distance; lux for directional), the cone angles in
//!   degrees;
//! - the first perspective camera of the first model that has one → a `Pinhole`, when the scene
//!   has no `camera` entry (`fov` = `yfov` in degrees, looking along the camera's -z).
//!
//! Invariants: an instance is only made of a type the link plan holds; a file that needs another
//! (it changed after the scene was compiled) is [`SceneError::ModelUnlinked`], an internal error
//! naming the file and the type, before anything refers to the type's id. The file and everything
//! it refers to stay inside the scene's folder or an asset
//! root (`assets::confine`); the entry's span is the span of every instance made here (errors point at the
//! `model` string); a glTF file named by several entries is read once; what the import skips or
//! approximates is a warning (the file's own, prefixed with its name), never silent.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{Mat4, Vec3};
use rtc_compiler::link::{model_type, Linked, MODEL_TYPES};
use rtc_compiler::sema::hir::{
    ConstValue, Instance, Model, Program, Scalar, SceneDesc, StructId, TextureAsset,
};
use rtc_compiler::Span;

use super::assets_cache::{AssetCache, MeshKey, TextureKey};
use super::gpu_types::GpuInstance;
use super::store::Version;
use super::SceneError;
use crate::assets::model::{AlphaMode, LightKind, ModelScene, NodeAnimation, Projection};
use crate::assets::solid_texture;

/// An object a model brings.
pub(super) struct ModelObject {
    /// `file.glb#nodes[i]`.
    pub name: String,
    /// The `model` entry's string.
    pub span: Span,
    /// Index of its mesh in the asset cache.
    pub mesh: usize,
    /// Its `GltfMaterial`.
    pub material: Instance,
    /// Object to world.
    pub transform: Mat4,
    /// `GpuInstance::FLAG_CULL_BACK` for an opaque single-sided material, else 0.
    pub cull: u32,
}

/// Everything the scene's models bring.
#[derive(Default)]
pub(super) struct ModelParts {
    /// Objects, model by model, in node order.
    pub objects: Vec<ModelObject>,
    /// Light instances, model by model.
    pub lights: Vec<Instance>,
    /// A `Pinhole` from the first model's first perspective camera (only looked for when the
    /// scene has no camera).
    pub camera: Option<Instance>,
    /// The objects a glTF animation moves.
    pub motions: Vec<ModelMotion>,
    /// What was skipped or approximated.
    pub warnings: Vec<String>,
}

/// An object a model's node animation moves: at time `t` its object-to-world matrix is
/// `entry × animation.evaluate(t)[node]` (rigid motion: its mesh and BVH stay as they are).
#[derive(Clone, Debug)]
pub(crate) struct ModelMotion {
    /// The object: an index into [`ModelParts::objects`] here, into the scene's objects once
    /// the entities hold it.
    pub object: usize,
    /// The glTF node.
    pub node: usize,
    /// The `model` entry's transform.
    pub entry: Mat4,
    /// The file's animation.
    pub animation: Arc<NodeAnimation>,
}

/// The program and link plan instances are made for.
#[derive(Clone, Copy)]
struct Types<'a> {
    program: &'a Program,
    linked: &'a Linked,
}

/// Reads every model of `scene` (a scene of `program`, linked as `linked`) into `cache` and makes
/// its instances.
pub(super) fn import(
    program: &Program,
    linked: &Linked,
    scene: &SceneDesc,
    cache: &mut AssetCache,
) -> Result<ModelParts, SceneError> {
    let mut parts = ModelParts::default();
    // Each file once, with the name messages give it: the file read, which may lie in an asset
    // root rather than next to the scene.
    let mut loaded: HashMap<PathBuf, (Arc<ModelScene>, String, Version)> = HashMap::new();
    for model in &scene.models {
        if !loaded.contains_key(&model.path) {
            let file = cache
                .confined(&model.path)
                .map_err(|source| SceneError::Asset {
                    span: Some(model.span),
                    source,
                })?;
            let (stamp, data) = cache.model(&file).map_err(|source| SceneError::Asset {
                span: Some(model.span),
                source,
            })?;
            let name = file.display().to_string();
            parts
                .warnings
                .extend(data.warnings.iter().map(|w| format!("{name}: {w}")));
            loaded.insert(model.path.clone(), (data, name, stamp));
        }
        if let Some((data, name, stamp)) = loaded.get(&model.path) {
            import_one(
                Types { program, linked },
                model,
                (name, data, *stamp),
                scene.camera.is_none(),
                cache,
                &mut parts,
            )?;
        }
    }
    Ok(parts)
}

/// The struct of a model type, by name, which model `file` needs: it must be in the link plan
/// (the link step linked it when it read the file), else [`SceneError::ModelUnlinked`].
fn struct_of(types: Types<'_>, file: &str, name: &str) -> Result<StructId, SceneError> {
    let unlinked = || SceneError::ModelUnlinked {
        model: file.to_owned(),
        name: name.to_owned(),
    };
    let t = MODEL_TYPES
        .iter()
        .find(|t| t.name == name)
        .ok_or_else(unlinked)?;
    model_type(types.program, t.module, t.name)
        .filter(|&s| types.linked.type_of(s).is_some())
        .ok_or_else(unlinked)
}

fn f32_value(x: f32) -> ConstValue {
    ConstValue::Scalar(Scalar::F32(x))
}

fn vec_value<const N: usize>(v: [f32; N]) -> ConstValue {
    let mut comps = [Scalar::F32(0.0); 4];
    for (c, x) in comps.iter_mut().zip(v) {
        *c = Scalar::F32(x);
    }
    ConstValue::Vector {
        len: N as u8,
        comps,
    }
}

/// An instance of struct `name`, which model `file` needs, with the given fields, the others at
/// their declared defaults.
fn instance(
    types: Types<'_>,
    file: &str,
    name: &str,
    span: Span,
    fields: &[(&str, ConstValue)],
) -> Result<Instance, SceneError> {
    let struct_id = struct_of(types, file, name)?;
    let decl = &types.program.structs[struct_id];
    let values = decl
        .fields
        .iter()
        .map(|f| {
            fields
                .iter()
                .find(|(n, _)| *n == f.name)
                .map(|(_, v)| v.clone())
                .or_else(|| f.default.clone())
                // A field without a default that we do not set: the stdlib struct changed under us.
                .ok_or_else(|| SceneError::Unlinked {
                    name: format!("{name}.{}", f.name),
                })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Instance {
        struct_id,
        fields: values,
        span,
    })
}

/// The path under which the texture labelled `label` (`ModelScene::texture_labels`) of `file` is
/// in the texture cache: `file.glb#images[i]`, with its sampler after a `~` when not the default.
fn texture_path(file: &Path, label: &str) -> PathBuf {
    let mut path = file.as_os_str().to_owned();
    path.push(format!("#{label}"));
    PathBuf::from(path)
}

fn import_one(
    types: Types<'_>,
    model: &Model,
    (name, data, stamp): (&str, &ModelScene, Version),
    wants_camera: bool,
    cache: &mut AssetCache,
    parts: &mut ModelParts,
) -> Result<(), SceneError> {
    let entry = Mat4::from_cols_array_2d(&model.transform);
    let span = model.span;

    let mut meshes = Vec::with_capacity(data.meshes.len());
    for (i, mesh) in data.meshes.iter().enumerate() {
        let key = MeshKey::Model {
            path: model.path.clone(),
            mesh: i,
            label: data
                .mesh_labels
                .get(i)
                .cloned()
                .unwrap_or_else(|| format!("mesh {i}")),
        };
        meshes.push(cache.insert_mesh(key, stamp, || mesh.clone()));
    }
    let mut textures = Vec::with_capacity(data.textures.len());
    for (i, texture) in data.textures.iter().enumerate() {
        let label = data
            .texture_labels
            .get(i)
            .cloned()
            .unwrap_or_else(|| format!("textures[{i}]"));
        let path = texture_path(&model.path, &label);
        cache.insert_texture(TextureKey::File(path.clone()), stamp, || texture.clone());
        textures.push(ConstValue::Texture(TextureAsset::File { path, span }));
    }
    let white = [1.0f32; 4];
    cache.insert_texture(
        TextureKey::Solid(white.map(f32::to_bits)),
        Version::NONE,
        || solid_texture(white),
    );

    let mut materials = Vec::with_capacity(data.materials.len());
    let mut culls = Vec::with_capacity(data.materials.len());
    for m in &data.materials {
        // A texture the material lacks is white, which leaves its factor as it is.
        let texture = |t: Option<usize>| {
            t.and_then(|t| textures.get(t).cloned())
                .unwrap_or(ConstValue::Texture(TextureAsset::Solid(white)))
        };
        let mut fields = vec![
            ("base_color", vec_value(m.base_color)),
            ("base_texture", texture(m.base_color_texture)),
            ("metallic", f32_value(m.metallic)),
            ("roughness", f32_value(m.roughness)),
            ("metal_rough_texture", texture(m.metallic_roughness_texture)),
            ("emissive", vec_value(m.emissive)),
            ("emissive_texture", texture(m.emissive_texture)),
            ("occlusion_texture", texture(m.occlusion_texture)),
            ("occlusion_strength", f32_value(m.occlusion_strength)),
        ];
        let detailed = m.is_detailed();
        if detailed {
            // No normal texture: scale 0 leaves the normal as it is (see gltf.rt).
            let scale = if m.normal_texture.is_some() {
                m.normal_scale
            } else {
                0.0
            };
            fields.push(("normal_texture", texture(m.normal_texture)));
            fields.push(("normal_scale", f32_value(scale)));
            fields.push(("uv_sets", ConstValue::Scalar(Scalar::U32(m.uv_sets))));
        }
        let slots = ["base", "metal_rough", "emissive", "occlusion", "normal"];
        let rows: Vec<(String, ConstValue)> = slots
            .iter()
            .zip(&m.uv_transforms)
            .flat_map(|(slot, [u, v])| {
                [
                    (format!("{slot}_uv_u"), vec_value(*u)),
                    (format!("{slot}_uv_v"), vec_value(*v)),
                ]
            })
            .collect();
        fields.extend(rows.iter().map(|(n, v)| (n.as_str(), v.clone())));
        let sided = ConstValue::Scalar(Scalar::U32(u32::from(m.double_sided)));
        let kind = match m.alpha_mode {
            AlphaMode::Mask | AlphaMode::Blend => {
                fields.push(("alpha_cutoff", f32_value(m.alpha_cutoff)));
                fields.push(("double_sided", sided));
                if m.alpha_mode == AlphaMode::Blend {
                    fields.push(("blend", ConstValue::Scalar(Scalar::U32(1))));
                }
                if detailed {
                    "GltfMaskedDetailMaterial"
                } else if m.is_mapped() {
                    "GltfMaskedMappedMaterial"
                } else {
                    "GltfMaskedMaterial"
                }
            }
            AlphaMode::Opaque if m.transmission > 0.0 => {
                fields.push(("transmission", f32_value(m.transmission)));
                fields.push(("ior", f32_value(m.ior)));
                "GltfTransmissiveMaterial"
            }
            AlphaMode::Opaque => {
                // The fields it lacks (other textures, transforms) are left out by `instance`.
                if detailed {
                    "GltfDetailMaterial"
                } else if m.is_mapped() {
                    "GltfMappedMaterial"
                } else {
                    "GltfMaterial"
                }
            }
        };
        materials.push(instance(types, name, kind, span, &fields)?);
        culls.push(m.alpha_mode == AlphaMode::Opaque && !m.double_sided && m.transmission <= 0.0);
    }
    for inst in &data.instances {
        let (Some(&mesh), Some(material)) = (meshes.get(inst.mesh), materials.get(inst.material))
        else {
            continue; // guaranteed by ModelScene's invariants
        };
        if let Some(animation) = data.animation.as_ref().filter(|a| a.moves(inst.node)) {
            parts.motions.push(ModelMotion {
                object: parts.objects.len(),
                node: inst.node,
                entry,
                animation: Arc::clone(animation),
            });
        }
        parts.objects.push(ModelObject {
            name: format!("{name}#nodes[{}]", inst.node),
            span,
            mesh,
            material: material.clone(),
            transform: entry * inst.transform,
            cull: if culls.get(inst.material).copied().unwrap_or(false) {
                GpuInstance::FLAG_CULL_BACK
            } else {
                0
            },
        });
    }

    for light in &data.lights {
        let position = entry.transform_point3(light.position);
        let direction = entry
            .transform_vector3(light.direction)
            .normalize_or(Vec3::NEG_Y);
        let common = [
            ("color", vec_value(light.color)),
            ("intensity", f32_value(light.intensity)),
        ];
        let range = f32_value(light.range.unwrap_or(0.0));
        let made = match light.kind {
            LightKind::Point => {
                let mut fields = vec![
                    ("position", vec_value(position.to_array())),
                    ("range", range),
                ];
                fields.extend(common.iter().cloned());
                instance(types, name, "PointLight", span, &fields)?
            }
            LightKind::Directional => {
                let mut fields = vec![("direction", vec_value(direction.to_array()))];
                fields.extend(common.iter().cloned());
                instance(types, name, "DirectionalLight", span, &fields)?
            }
            LightKind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => {
                let mut fields = vec![
                    ("position", vec_value(position.to_array())),
                    ("direction", vec_value(direction.to_array())),
                    ("range", range),
                    ("inner_angle", f32_value(inner_cone_angle.to_degrees())),
                    ("outer_angle", f32_value(outer_cone_angle.to_degrees())),
                ];
                fields.extend(common.iter().cloned());
                instance(types, name, "SpotLight", span, &fields)?
            }
        };
        parts.lights.push(made);
    }

    if wants_camera && parts.camera.is_none() {
        let perspective = data.cameras.iter().find_map(|c| match c.projection {
            Projection::Perspective { yfov, .. } => Some((c, yfov)),
            Projection::Orthographic { .. } => None,
        });
        if let Some((camera, yfov)) = perspective {
            let position = entry.transform_point3(camera.position());
            let forward = entry
                .transform_vector3(camera.forward())
                .normalize_or(Vec3::NEG_Z);
            let up = entry.transform_vector3(camera.up()).normalize_or(Vec3::Y);
            parts.camera = Some(instance(
                types,
                name,
                "Pinhole",
                span,
                &[
                    ("position", vec_value(position.to_array())),
                    ("look_at", vec_value((position + forward).to_array())),
                    ("up", vec_value(up.to_array())),
                    ("fov", f32_value(yfov.to_degrees())),
                ],
            )?);
        } else if !data.cameras.is_empty() {
            parts.warnings.push(format!(
                "{name}: only orthographic cameras, which are not imported"
            ));
        }
    }
    Ok(())
}
