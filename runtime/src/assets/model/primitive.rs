//! One glTF mesh primitive → one [`MeshData`].
//!
//! Read: `POSITION` (`VEC3` of `F32`), `NORMAL` (`VEC3` of `F32`), `TEXCOORD_0` (`VEC2` of `F32`,
//! or normalised `U8`/`U16`), `indices` (`SCALAR` of `U8`/`U16`/`U32`; without them every three
//! vertices are a triangle). Other attributes (tangents, colours, joints, weights, further uv
//! sets) are not read; `COLOR_0` gets a warning naming the primitive and its material (further
//! uv sets are named by the materials that use them, tangents matter only for normal maps,
//! which are not imported and warned about).
//!
//! Invariants: only mode `TRIANGLES` is converted (others return `None` with a warning, as does a
//! primitive without triangles); an index past the vertices is
//! [`AssetError::IndexOutOfRange`]; a trailing partial triangle is dropped with a warning; the
//! result passed [`MeshData::validate`] and has unit normals.

use gltf::json::accessor::{ComponentType, Type};
use gltf::json::mesh::{Mode, Primitive, Semantic};
use gltf::json::validation::Checked;

use super::accessor::{self, Expect};
use super::Ctx;
use crate::assets::{AssetError, GltfItem, MeshData};

const POSITION: Expect = Expect {
    usage: "POSITION",
    description: "VEC3 of F32",
    ty: Type::Vec3,
    component: |c, _| c == ComponentType::F32,
};
const NORMAL: Expect = Expect {
    usage: "NORMAL",
    description: "VEC3 of F32",
    ty: Type::Vec3,
    component: |c, _| c == ComponentType::F32,
};
const TEXCOORD: Expect = Expect {
    usage: "TEXCOORD_0",
    description: "VEC2 of F32, or of normalized U8 or U16",
    ty: Type::Vec2,
    component: |c, normalized| {
        c == ComponentType::F32
            || (normalized && matches!(c, ComponentType::U8 | ComponentType::U16))
    },
};
const INDICES: Expect = Expect {
    usage: "indices",
    description: "SCALAR of U8, U16 or U32",
    ty: Type::Scalar,
    component: |c, normalized| {
        !normalized
            && matches!(
                c,
                ComponentType::U8 | ComponentType::U16 | ComponentType::U32
            )
    },
};

/// Converts primitive `p` of mesh `m`; `Ok(None)` (with a warning) when it is skipped.
pub(super) fn convert(
    ctx: &Ctx<'_>,
    m: usize,
    p: usize,
    primitive: &Primitive,
    warnings: &mut Vec<String>,
) -> Result<Option<MeshData>, AssetError> {
    let item = GltfItem::Primitive {
        mesh: m,
        primitive: p,
    };
    match primitive.mode {
        Checked::Valid(Mode::Triangles) => {}
        Checked::Valid(mode) => {
            warnings.push(format!(
                "{item}: mode {mode:?} is not supported (only triangles), skipped"
            ));
            return Ok(None);
        }
        Checked::Invalid => {
            warnings.push(format!("{item}: unknown mode, skipped"));
            return Ok(None);
        }
    }
    if primitive.targets.as_ref().is_some_and(|t| !t.is_empty()) {
        warnings.push(format!(
            "{item}: morph targets are ignored (base shape used)"
        ));
    }
    let attribute = |s: Semantic| {
        primitive
            .attributes
            .get(&Checked::Valid(s))
            .map(|i| i.value())
    };
    if attribute(Semantic::Colors(0)).is_some() {
        let material = primitive.material.map_or_else(
            || "the default material".to_owned(),
            |i| format!("materials[{}]", i.value()),
        );
        warnings.push(format!(
            "{item}: its COLOR_0 vertex colours are not imported (the base colour of {material} \
             is not multiplied by them)"
        ));
    }
    let Some(position) = attribute(Semantic::Positions) else {
        warnings.push(format!("{item}: no POSITION attribute, skipped"));
        return Ok(None);
    };
    let positions: Vec<[f32; 3]> = accessor::read(ctx, position, &POSITION, |x| x as f32)?;
    let normals = attribute(Semantic::Normals)
        .map(|i| accessor::read(ctx, i, &NORMAL, |x| x as f32))
        .transpose()?;
    let uvs = attribute(Semantic::TexCoords(0))
        .map(|i| accessor::read(ctx, i, &TEXCOORD, |x| x as f32))
        .transpose()?;

    let flat: Vec<u32> = match primitive.indices {
        Some(i) => accessor::read(ctx, i.value(), &INDICES, |x| x as u32)?
            .into_iter()
            .map(|[i]| i)
            .collect(),
        None => (0..u32::try_from(positions.len()).unwrap_or(u32::MAX)).collect(),
    };
    if flat.len() % 3 != 0 {
        warnings.push(format!(
            "{item}: {} indices are not a whole number of triangles; the last {} dropped",
            flat.len(),
            flat.len() % 3
        ));
    }
    if let Some(&index) = flat.iter().find(|&&i| i as usize >= positions.len()) {
        return Err(AssetError::IndexOutOfRange {
            path: ctx.path.to_owned(),
            item,
            index,
            vertex_count: positions.len(),
        });
    }
    let indices: Vec<[u32; 3]> = flat
        .chunks_exact(3)
        .filter_map(|t| <[u32; 3]>::try_from(t).ok())
        .collect();
    if indices.is_empty() {
        warnings.push(format!("{item}: no triangles, skipped"));
        return Ok(None);
    }
    let mut mesh = MeshData {
        positions,
        normals,
        uvs,
        indices,
    };
    mesh.validate().map_err(|source| AssetError::Mesh {
        path: ctx.path.to_owned(),
        item: Some(item),
        source,
    })?;
    mesh.ensure_normals();
    Ok(Some(mesh))
}
