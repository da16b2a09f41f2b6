//! The node hierarchy of a glTF scene → instances, cameras and lights in world space.
//!
//! Invariants: the walk is iterative (no recursion, so no depth limit is needed) and visits each
//! node at most once; a node reached a second time (a cycle, or a child shared by two parents,
//! both invalid glTF) is skipped with a warning. A node's world transform is its parent's world
//! transform times its local one (`matrix`, or translation · rotation · scale). Each glTF mesh is
//! converted once (`mesh_cache` in [`build`]), so nodes sharing a mesh share its `MeshData`.

use std::collections::hash_map::{Entry, HashMap};
use std::sync::Arc;

use glam::{Mat4, Quat, Vec3};
use gltf::json;
use gltf::json::validation::Checked;

use super::animation;
use super::materials::Materials;
use super::{
    primitive, Ctx, GltfCamera, GltfLight, LightKind, MeshInstance, ModelScene, Projection,
};
use crate::assets::AssetError;

/// The glTF extensions whose data is imported. Others listed in `extensionsUsed` get a warning;
/// one listed in `extensionsRequired` was already refused by validation.
const SUPPORTED_EXTENSIONS: [&str; 5] = [
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_texture_transform",
];

/// Builds the [`ModelScene`] of the document's default scene.
pub(super) fn build(ctx: &Ctx<'_>) -> Result<ModelScene, AssetError> {
    let mut scene = ModelScene::default();
    let mut materials = Materials::default();
    // glTF mesh → its converted primitives as (mesh index, glTF material).
    let mut mesh_cache: HashMap<usize, Vec<(usize, Option<usize>)>> = HashMap::new();
    let root = ctx.root;

    let ignored: Vec<&str> = root
        .extensions_used
        .iter()
        .map(String::as_str)
        .filter(|e| !SUPPORTED_EXTENSIONS.contains(e))
        .collect();
    if !ignored.is_empty() {
        // Name what each ignored extension is on (read from the JSON text: `gltf-json` drops
        // extensions it does not know); those found on nothing are listed together.
        let users = extension_users(ctx.json, &ignored);
        let mut unplaced = Vec::new();
        for (ext, on) in ignored.iter().zip(&users) {
            if on.is_empty() {
                unplaced.push(*ext);
            } else {
                scene.warnings.push(format!(
                    "extension {ext} ignored (the file does not require it): on {}",
                    on.join(", ")
                ));
            }
        }
        if !unplaced.is_empty() {
            scene.warnings.push(format!(
                "extension(s) {} ignored (the file does not require them)",
                unplaced.join(", ")
            ));
        }
    }
    for (i, skin) in root.skins.iter().enumerate() {
        let users: Vec<String> = root
            .nodes
            .iter()
            .enumerate()
            .filter(|(_, node)| node.skin.is_some_and(|s| s.value() == i))
            .map(|(n, _)| format!("nodes[{n}]"))
            .collect();
        let name = skin
            .name
            .as_ref()
            .map(|n| format!(" (`{n}`)"))
            .unwrap_or_default();
        scene.warnings.push(if users.is_empty() {
            format!("skins[{i}]{name} is not imported (no node uses it)")
        } else {
            format!(
                "skins[{i}]{name} is not imported: the mesh(es) of {} are drawn unposed, placed by their node",
                users.join(", ")
            )
        });
    }

    let roots = scene_roots(root, &mut scene.warnings);
    let mut visited = vec![false; root.nodes.len()];
    // Each scene node's parent, as the walk reached it (for the animation).
    let mut parents: Vec<Option<usize>> = vec![None; root.nodes.len()];
    let mut order: Vec<usize> = Vec::new();
    let mut stack: Vec<(usize, Mat4, Option<usize>)> = roots
        .iter()
        .rev()
        .map(|&n| (n, Mat4::IDENTITY, None))
        .collect();
    while let Some((n, parent, parent_node)) = stack.pop() {
        let Some(node) = root.nodes.get(n) else {
            continue; // validated: cannot happen
        };
        match visited.get_mut(n) {
            Some(seen) if !*seen => {
                *seen = true;
                order.push(n);
                if let Some(slot) = parents.get_mut(n) {
                    *slot = parent_node;
                }
            }
            _ => {
                scene.warnings.push(format!(
                    "nodes[{n}] is reached more than once (a cycle or a shared child), skipped there"
                ));
                continue;
            }
        }
        let world = parent * local_transform(node, n, &mut scene.warnings);
        if !world.is_finite() {
            scene.warnings.push(format!(
                "nodes[{n}] has a non-finite world transform, skipped with its children"
            ));
            continue;
        }
        if let Some(mesh) = node.mesh {
            let m = mesh.value();
            let converted = match mesh_cache.entry(m) {
                Entry::Occupied(e) => e.into_mut(),
                Entry::Vacant(e) => e.insert(convert_mesh(ctx, m, &mut scene)?),
            };
            for &(mesh, gltf_material) in converted.iter() {
                let material = materials.get(ctx, gltf_material, &mut scene.warnings)?;
                if material == scene.material_labels.len() {
                    scene
                        .material_labels
                        .push(material_label(root, gltf_material));
                }
                scene.instances.push(MeshInstance {
                    mesh,
                    material,
                    transform: world,
                    node: n,
                });
            }
        }
        if let Some(camera) = node.camera {
            if let Some(camera) = convert_camera(root, camera.value(), world, &mut scene.warnings) {
                scene.cameras.push(camera);
            }
        }
        if let Some(light) = node
            .extensions
            .as_ref()
            .and_then(|e| e.khr_lights_punctual.as_ref())
        {
            if let Some(light) = convert_light(root, light.light.value(), world) {
                scene.lights.push(light);
            }
        }
        for child in node.children.iter().flatten().rev() {
            stack.push((child.value(), world, Some(n)));
        }
    }
    scene.animation = animation::read(ctx, &parents, &order, &mut scene.warnings).map(Arc::new);
    scene.materials = materials.materials;
    scene.textures = materials.textures;
    scene.texture_labels = materials.texture_labels;
    Ok(scene)
}

/// For each of `extensions`, the parts of the glTF JSON text `json` whose `extensions` object
/// (anywhere inside them, e.g. a material's texture reference) holds it: `materials[2]
/// (`Glass`)`, `meshes[0].primitives[1]`, or `the file` for the root's own. Empty lists when the
/// text cannot be parsed (it was parsed before, so it can).
fn extension_users(json: &[u8], extensions: &[&str]) -> Vec<Vec<String>> {
    use serde_json::Value;
    let mut users = vec![Vec::new(); extensions.len()];
    let Ok(Value::Object(root)) = serde_json::from_slice::<Value>(json) else {
        return users;
    };
    // Whether `v` or anything inside it has an `extensions` object holding `ext` (bounded
    // depth: glTF nests a handful of levels; deeper is someone's `extras`).
    fn holds(v: &Value, ext: &str, depth: u32) -> bool {
        if depth > 8 {
            return false;
        }
        match v {
            Value::Object(map) => map.iter().any(|(k, x)| {
                (k == "extensions" && x.get(ext).is_some())
                    || (k != "extras" && holds(x, ext, depth + 1))
            }),
            Value::Array(items) => items.iter().any(|x| holds(x, ext, depth + 1)),
            _ => false,
        }
    }
    let label = |kind: &str, i: usize, item: &Value| match item.get("name").and_then(Value::as_str)
    {
        Some(name) => format!("{kind}[{i}] (`{name}`)"),
        None => format!("{kind}[{i}]"),
    };
    for (e, ext) in extensions.iter().enumerate() {
        let Some(on) = users.get_mut(e) else { continue };
        if root
            .get("extensions")
            .is_some_and(|x| x.get(*ext).is_some())
        {
            on.push("the file".to_owned());
        }
        for (kind, items) in &root {
            let Value::Array(items) = items else { continue };
            for (i, item) in items.iter().enumerate() {
                if kind == "meshes" {
                    let prims = item.get("primitives").and_then(Value::as_array);
                    for (p, prim) in prims.into_iter().flatten().enumerate() {
                        if holds(prim, ext, 0) {
                            on.push(format!("meshes[{i}].primitives[{p}]"));
                        }
                    }
                } else if holds(item, ext, 0) {
                    on.push(label(kind, i, item));
                }
            }
        }
    }
    users
}

/// How a material is named in messages: `materials[3] (`Red`)`, or glTF's default material.
fn material_label(root: &json::Root, m: Option<usize>) -> String {
    match m {
        None => "glTF's default material".to_owned(),
        Some(m) => match root.materials.get(m).and_then(|x| x.name.as_ref()) {
            Some(name) => format!("materials[{m}] (`{name}`)"),
            None => format!("materials[{m}]"),
        },
    }
}

/// The root nodes to render: the default scene's, else the first scene's, else every node that
/// is nobody's child.
fn scene_roots(root: &json::Root, warnings: &mut Vec<String>) -> Vec<usize> {
    let chosen = root
        .scene
        .and_then(|s| root.scenes.get(s.value()))
        .or_else(|| root.scenes.first());
    if let Some(scene) = chosen {
        return scene.nodes.iter().map(|n| n.value()).collect();
    }
    if root.nodes.is_empty() {
        return Vec::new();
    }
    warnings.push("the file has no scene; showing every node that has no parent".to_owned());
    let mut is_child = vec![false; root.nodes.len()];
    for child in root.nodes.iter().flat_map(|n| n.children.iter().flatten()) {
        if let Some(flag) = is_child.get_mut(child.value()) {
            *flag = true;
        }
    }
    (0..root.nodes.len())
        .filter(|&n| !is_child.get(n).copied().unwrap_or(true))
        .collect()
}

/// A node's transform relative to its parent.
fn local_transform(node: &json::Node, n: usize, warnings: &mut Vec<String>) -> Mat4 {
    if let Some(matrix) = node.matrix {
        return Mat4::from_cols_array(&matrix);
    }
    let translation = Vec3::from(node.translation.unwrap_or([0.0; 3]));
    let scale = Vec3::from(node.scale.unwrap_or([1.0; 3]));
    let rotation = match node.rotation {
        None => Quat::IDENTITY,
        Some(json::scene::UnitQuaternion([x, y, z, w])) => {
            let q = Quat::from_xyzw(x, y, z, w);
            if q.is_finite() && q.length_squared() > 0.0 {
                q.normalize()
            } else {
                warnings.push(format!("nodes[{n}] has an invalid rotation, ignored"));
                Quat::IDENTITY
            }
        }
    };
    Mat4::from_scale_rotation_translation(scale, rotation, translation)
}

/// Converts every triangle primitive of glTF mesh `m` into `scene.meshes`.
fn convert_mesh(
    ctx: &Ctx<'_>,
    m: usize,
    scene: &mut ModelScene,
) -> Result<Vec<(usize, Option<usize>)>, AssetError> {
    let mut converted = Vec::new();
    let Some(mesh) = ctx.root.meshes.get(m) else {
        return Ok(converted);
    };
    for (p, prim) in mesh.primitives.iter().enumerate() {
        if let Some(data) = primitive::convert(ctx, m, p, prim, &mut scene.warnings)? {
            scene.meshes.push(data);
            scene.mesh_labels.push(match &mesh.name {
                Some(name) => format!("meshes[{m}].primitives[{p}] (`{name}`)"),
                None => format!("meshes[{m}].primitives[{p}]"),
            });
            converted.push((scene.meshes.len() - 1, prim.material.map(|i| i.value())));
        }
    }
    Ok(converted)
}

fn convert_camera(
    root: &json::Root,
    c: usize,
    transform: Mat4,
    warnings: &mut Vec<String>,
) -> Option<GltfCamera> {
    let camera = root.cameras.get(c)?;
    let projection = match (&camera.type_, &camera.perspective, &camera.orthographic) {
        (Checked::Valid(json::camera::Type::Perspective), Some(p), _) => Projection::Perspective {
            yfov: p.yfov,
            aspect: p.aspect_ratio,
            znear: p.znear,
            zfar: p.zfar,
        },
        (Checked::Valid(json::camera::Type::Orthographic), _, Some(o)) => {
            Projection::Orthographic {
                xmag: o.xmag,
                ymag: o.ymag,
                znear: o.znear,
                zfar: o.zfar,
            }
        }
        _ => {
            warnings.push(format!(
                "cameras[{c}]: its type does not match its projection object, skipped"
            ));
            return None;
        }
    };
    Some(GltfCamera {
        name: camera.name.clone(),
        projection,
        transform,
    })
}

fn convert_light(root: &json::Root, l: usize, transform: Mat4) -> Option<GltfLight> {
    use json::extensions::scene::khr_lights_punctual::Type;
    let light = root
        .extensions
        .as_ref()?
        .khr_lights_punctual
        .as_ref()?
        .lights
        .get(l)?;
    let kind = match (&light.type_, &light.spot) {
        (Checked::Valid(Type::Point), _) => LightKind::Point,
        (Checked::Valid(Type::Directional), _) => LightKind::Directional,
        (Checked::Valid(Type::Spot), Some(spot)) => LightKind::Spot {
            inner_cone_angle: spot.inner_cone_angle,
            outer_cone_angle: spot.outer_cone_angle,
        },
        // Validated: a spot light has its `spot` object and the type is known.
        _ => return None,
    };
    Some(GltfLight {
        name: light.name.clone(),
        kind,
        color: light.color,
        intensity: light.intensity,
        range: light.range,
        position: transform.transform_point3(Vec3::ZERO),
        direction: transform
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or(Vec3::NEG_Z),
    })
}
