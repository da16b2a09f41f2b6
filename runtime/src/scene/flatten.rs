//! Flattening static objects: the triangles of objects that nothing moves, each with a mesh of its
//! own, baked into world space and put in one shared object-level BVH.
//!
//! Why: a scene of many small objects (a Cornell box: five quads, two cubes and a lamp) spends a
//! good part of each ray in the scene level: a scene-level leaf per object, each with its
//! transform and its BVH's header. One BVH over all their triangles is what Embree, Mitsuba and
//! Cycles' final renders trace for such geometry. Flattening is the renderer's choice for one-shot
//! renders (`EntityOptions::flatten`); live sessions keep one BVH per object, so that any object
//! can move without a BVH build (Cycles makes the same split between its viewport and final BVHs).
//!
//! What may be flattened ([`plan`]): a mesh object whose mesh no other object uses or has at most
//! [`SHARED_MESH_TRIANGLES`] triangles (a copy per object costs little), whose material
//! has no `@any_hit` or `@medium` program (their traversal and tables address one object's
//! transform), whose mesh carries no extra vertex data (tangents are object-space), whose
//! transform does not mirror, that no animation track or glTF animation moves and whose world box
//! is finite. Objects are grouped by their `FLAG_CULL_BACK` bit (traversal reads it from the
//! group); a group needs at least two objects.
//!
//! The group's records ([`build_group`]): its triangles in world space (normals under the inverse
//! transpose, renormalised), one BVH built over them (with spatial splits up to
//! [`QUALITY_TRIANGLES`], [`preset`]). Each slot's `TRIANGLE` record keeps in
//! `v0.w` the triangle's index in its own mesh (what a hit reports as `primitive`) and holds in
//! `v1.w` the member's index in the group plus one (`v1.w` is 0 in every other mesh). The kernel
//! (`intersect_mesh` in `stdlib/kernel/trace.rt`) reports a hit on such a slot as a hit on the
//! member's own instance record, which `Entities` places at the group record's `object` plus the
//! member's index, with identity transforms; so shading sees the object's own material, flags and
//! `instance` index, and the image differs from the unflattened one only by the rounding of the
//! baked vertices and normals.
//!
//! The objects keep their own BVHs (built anyway, or shared), so moving one only drops the groups.
//!
//! Invariants: a group's members are distinct object indices, each in one group; nothing here
//! panics on any mesh (indices out of range read the origin, as the encoder does).

use glam::{Mat3, Mat4, Vec3};
use rtc_bvh::{Aabb, BuildPreset};

use super::gpu_types::{record, GpuInstance};
use super::store::BuiltMesh;
use super::SceneError;
use crate::assets::MeshData;

/// A group of flattened objects: their BVH (records in `nodes` from `node_base`) and triangle
/// slots (from `triangle_base`), and the members in the order of their tags.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatGroup {
    /// Object indices of the members; member `k`'s slots carry the tag `k + 1`.
    pub members: Vec<usize>,
    /// The group's `FLAG_CULL_BACK` bit (shared by every member).
    pub flags: u32,
    /// Index of the BVH's header record in `nodes`.
    pub node_base: u32,
    /// First triangle slot.
    pub triangle_base: u32,
    /// The world box of every member's triangles.
    pub bounds: Aabb,
}

/// One object as the planner sees it.
pub struct Candidate<'a> {
    /// Its mesh (`None` for custom geometry).
    pub mesh: Option<(usize, &'a MeshData)>,
    /// Its material's flags.
    pub flags: u32,
    /// Object to world.
    pub transform: Mat4,
    /// Whether an animation moves it.
    pub moves: bool,
}

/// The most triangles of a mesh that several objects use and that is still flattened (copied once
/// per object): small meshes gain nothing from instancing, large ones keep it.
pub const SHARED_MESH_TRIANGLES: usize = 1024;

/// The groups of objects that may be flattened (see the module docs), members in object order.
pub fn plan(objects: &[Candidate]) -> Vec<(u32, Vec<usize>)> {
    let mut uses = std::collections::HashMap::new();
    for o in objects {
        if let Some((mesh, _)) = o.mesh {
            *uses.entry(mesh).or_insert(0usize) += 1;
        }
    }
    let mut groups: Vec<(u32, Vec<usize>)> = Vec::new();
    for (index, o) in objects.iter().enumerate() {
        let Some((mesh, data)) = o.mesh else { continue };
        let blocked = GpuInstance::FLAG_ANY_HIT | GpuInstance::FLAG_MEDIUM;
        let own = uses.get(&mesh) == Some(&1) || data.indices.len() <= SHARED_MESH_TRIANGLES;
        let eligible = own
            && o.flags & blocked == 0
            && data.extras.is_none()
            && !data.indices.is_empty()
            && !o.moves
            && o.transform.determinant() > 0.0
            && o.transform.is_finite();
        if !eligible {
            continue;
        }
        let cull = o.flags & GpuInstance::FLAG_CULL_BACK;
        match groups.iter_mut().find(|(f, _)| *f == cull) {
            Some((_, members)) => members.push(index),
            None => groups.push((cull, vec![index])),
        }
    }
    groups.retain(|(_, members)| members.len() >= 2);
    groups
}

/// One member's mesh in world space.
struct Baked {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    uvs: Vec<[f32; 2]>,
}

fn bake(data: &MeshData, transform: &Mat4) -> Baked {
    let positions = data
        .positions
        .iter()
        .map(|&p| transform.transform_point3(Vec3::from(p)).to_array())
        .collect();
    let object_normals = match &data.normals {
        Some(n) if n.len() == data.positions.len() => n.clone(),
        _ => data.smooth_normals(),
    };
    let normal_matrix = Mat3::from_mat4(*transform).inverse().transpose();
    let normals = object_normals
        .iter()
        .map(|&n| {
            let n = Vec3::from(n);
            let w = (normal_matrix * n).normalize_or_zero();
            if w == Vec3::ZERO || !w.is_finite() {
                n.to_array()
            } else {
                w.to_array()
            }
        })
        .collect();
    let uvs = match &data.uvs {
        Some(uv) if uv.len() == data.positions.len() => uv.clone(),
        _ => vec![[0.0; 2]; data.positions.len()],
    };
    Baked {
        positions,
        normals,
        uvs,
    }
}

/// Builds one group's BVH and records with `build` (the renderer's mesh builder) over its members'
/// triangles in world space, then writes each slot's tags (see the module docs). `members` are
/// `(mesh, object-to-world)` in tag order.
pub fn build_group(
    members: &[(&MeshData, Mat4)],
    build: impl FnOnce(&MeshData) -> Result<BuiltMesh, SceneError>,
) -> Result<BuiltMesh, SceneError> {
    let mut merged = MeshData {
        positions: Vec::new(),
        normals: Some(Vec::new()),
        uvs: Some(Vec::new()),
        indices: Vec::new(),
        extras: None,
    };
    // The first merged triangle of each member.
    let mut starts = Vec::with_capacity(members.len());
    for (data, transform) in members {
        let baked = bake(data, transform);
        let base = merged.positions.len() as u32;
        starts.push(merged.indices.len() as u32);
        merged.positions.extend(baked.positions);
        if let Some(n) = merged.normals.as_mut() {
            n.extend(baked.normals);
        }
        if let Some(uv) = merged.uvs.as_mut() {
            uv.extend(baked.uvs);
        }
        let count = data.positions.len() as u32;
        // An index out of range stays out of range (the encoder reads the origin for it).
        let shift = |i: u32| if i < count { base + i } else { u32::MAX };
        merged.indices.extend(
            data.indices
                .iter()
                .map(|t| [shift(t[0]), shift(t[1]), shift(t[2])]),
        );
    }
    let mut built = build(&merged)?;
    for slot in built.triangles.chunks_mut(record::TRIANGLE_VEC4S) {
        let t = slot.first().map_or(0, |v0| v0[3].to_bits());
        // The member whose triangles start at or before `t`.
        let k = starts.partition_point(|&s| s <= t).saturating_sub(1);
        let start = starts.get(k).copied().unwrap_or(0);
        if let Some(v0) = slot.get_mut(0) {
            v0[3] = f32::from_bits(t - start);
        }
        if let Some(v1) = slot.get_mut(1) {
            v1[3] = f32::from_bits(k as u32 + 1);
        }
    }
    Ok(built)
}

/// The most triangles of a group whose BVH is built with spatial splits whatever the renderer's
/// preset: a group is made of whole objects (walls, boxes, floors), whose large triangles are what
/// splits help with, and a group this small builds in milliseconds. On the Cornell box (76
/// triangles) its frame is about 4 % shorter than with the `fast` preset (Mesa 25.0.7,
/// docs/bench/README.md).
pub const QUALITY_TRIANGLES: usize = 16_384;

/// The preset of a group of `triangles` triangles when the renderer's is `preset`.
pub fn preset(triangles: usize, preset: BuildPreset) -> BuildPreset {
    if triangles <= QUALITY_TRIANGLES {
        BuildPreset::Quality
    } else {
        preset
    }
}

/// The instance record of the group (the scene-level leaf): identity transforms, the group's BVH,
/// and in `object` the slot of its first member's record.
pub fn group_record(group: &FlatGroup, first_member_slot: u32) -> GpuInstance {
    GpuInstance {
        world_to_object: IDENTITY_ROWS,
        object_to_world: IDENTITY_ROWS,
        geometry_type: GpuInstance::MESH_GEOMETRY,
        geometry_offset: 0,
        material_type: 0,
        material_offset: 0,
        blas_root: group.node_base,
        triangle_offset: group.triangle_base,
        flags: group.flags,
        object: first_member_slot,
    }
}

/// The rows of the identity transform as `GpuInstance` stores them.
pub const IDENTITY_ROWS: [[f32; 4]; 3] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
];
