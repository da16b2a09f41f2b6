//! One glTF mesh primitive → one [`MeshData`].
//!
//! Read: `POSITION` (`VEC3` of `F32`), `NORMAL` (`VEC3` of `F32`), `TEXCOORD_0` (`VEC2` of `F32`,
//! or normalised `U8`/`U16`), `indices` (`SCALAR` of `U8`/`U16`/`U32`; without them every three
//! vertices are a triangle). Into [`VertexExtras`], only when the primitive's material needs them
//! (so a mesh that does not keeps the GPU encoding it always had): `TEXCOORD_1` (as
//! `TEXCOORD_0`) when one of the material's textures reads uv set 1; `COLOR_0` (`VEC3`/`VEC4` of
//! `F32` or normalised `U8`/`U16`) always; tangents when the material has a normal texture: the
//! file's `TANGENT` (`VEC4` of `F32`, w = bitangent sign), else generated with MikkTSpace from the
//! normal texture's uv set (the glTF spec's rule). An extra attribute of the wrong type is
//! dropped with a warning (the mesh still renders); `COLOR_1` and further colour sets are named
//! in a warning. Joints and weights are not read (skins are warned about where nodes are read).
//!
//! Invariants: only mode `TRIANGLES` is converted (others return `None` with a warning, as does a
//! primitive without triangles); an index past the vertices is
//! [`AssetError::IndexOutOfRange`]; a trailing partial triangle is dropped with a warning; the
//! result passed [`MeshData::validate`] and has unit normals.

use gltf::json::accessor::{ComponentType, Type};
use gltf::json::mesh::{Mode, Primitive, Semantic};
use gltf::json::validation::Checked;

use super::accessor::{self, Expect};
use super::{materials, Ctx};
use crate::assets::{AssetError, GltfItem, MeshData, VertexExtras};

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
const TEXCOORD_1: Expect = Expect {
    usage: "TEXCOORD_1",
    ..TEXCOORD
};
const TANGENT: Expect = Expect {
    usage: "TANGENT",
    description: "VEC4 of F32",
    ty: Type::Vec4,
    component: |c, _| c == ComponentType::F32,
};
/// `COLOR_0` components: `F32`, or normalised `U8`/`U16`.
fn color_component(c: ComponentType, normalized: bool) -> bool {
    c == ComponentType::F32 || (normalized && matches!(c, ComponentType::U8 | ComponentType::U16))
}
const COLOR_RGB: Expect = Expect {
    usage: "COLOR_0",
    description: "VEC3 or VEC4 of F32, or of normalized U8 or U16",
    ty: Type::Vec3,
    component: color_component,
};
const COLOR_RGBA: Expect = Expect {
    ty: Type::Vec4,
    ..COLOR_RGB
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
    let further_colors: Vec<String> = primitive
        .attributes
        .keys()
        .filter_map(|k| match k {
            Checked::Valid(Semantic::Colors(n)) if *n > 0 => Some(format!("COLOR_{n}")),
            _ => None,
        })
        .collect();
    if !further_colors.is_empty() {
        warnings.push(format!(
            "{item}: {} not imported (only COLOR_0 multiplies the base colour)",
            further_colors.join(", ")
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
    let needs = materials::attribute_needs(ctx, primitive.material.map(|m| m.value()));
    let vertices = positions.len();
    // An extra attribute that cannot be read or has the wrong count is dropped with a warning.
    let mut extra = |name: &str, read: Result<Option<Vec<[f32; 4]>>, AssetError>| match read {
        Ok(Some(v)) if v.len() == vertices => Some(v),
        Ok(Some(v)) => {
            warnings.push(format!(
                "{item}: its {name} has {} elements for {vertices} vertices, ignored",
                v.len()
            ));
            None
        }
        Ok(None) => None,
        Err(e) => {
            warnings.push(format!("{item}: its {name} is ignored: {e}"));
            None
        }
    };
    let mut missing_uv1 = false;
    let uvs1 = if needs.uv1 {
        let read = attribute(Semantic::TexCoords(1))
            .map(|i| accessor::read::<f32, 2>(ctx, i, &TEXCOORD_1, |x| x as f32))
            .transpose()
            .map(|v| v.map(|v| v.into_iter().map(|[u, v]| [u, v, 0.0, 0.0]).collect()));
        let uvs1: Option<Vec<[f32; 2]>> =
            extra("TEXCOORD_1", read).map(|v| v.into_iter().map(|[u, v, ..]| [u, v]).collect());
        if uvs1.is_none() {
            missing_uv1 = true;
        }
        uvs1
    } else {
        None
    };
    let colors = attribute(Semantic::Colors(0)).and_then(|i| extra("COLOR_0", read_color(ctx, i)));
    let file_tangents = match needs.normal_uv {
        Some(_) => attribute(Semantic::Tangents).and_then(|i| {
            extra(
                "TANGENT",
                accessor::read::<f32, 4>(ctx, i, &TANGENT, |x| x as f32).map(Some),
            )
        }),
        None => None,
    };
    if missing_uv1 {
        warnings.push(format!(
            "{item}: its material samples a texture with TEXCOORD_1, which the primitive lacks \
             (those textures read uv (0, 0))"
        ));
    }
    let mut mesh = MeshData {
        positions,
        normals,
        uvs,
        indices,
        extras: None,
    };
    mesh.validate().map_err(|source| AssetError::Mesh {
        path: ctx.path.to_owned(),
        item: Some(item),
        source,
    })?;
    mesh.ensure_normals();
    if uvs1.is_some() || colors.is_some() || needs.normal_uv.is_some() {
        mesh.extras = Some(VertexExtras {
            uvs1,
            colors,
            tangents: None,
        });
    }
    if let Some(set) = needs.normal_uv {
        let tangents = match file_tangents {
            Some(t) => Some(mesh.corner_tangents(&t)),
            None => {
                let generated = mesh.generate_tangents(set);
                if generated.is_none() {
                    warnings.push(format!(
                        "{item}: no TANGENT and no TEXCOORD_{set} to generate tangents from; its \
                         material's normal texture is not applied"
                    ));
                }
                generated
            }
        };
        if let Some(extras) = mesh.extras.as_mut() {
            extras.tangents = tangents;
        }
    }
    Ok(Some(mesh))
}

/// `COLOR_0` accessor `index` as linear RGBA (RGB gets alpha 1); `Ok(None)` never (the option
/// is for [`convert`]'s helper).
fn read_color(ctx: &Ctx<'_>, index: usize) -> Result<Option<Vec<[f32; 4]>>, AssetError> {
    let vec3 = ctx
        .root
        .accessors
        .get(index)
        .is_some_and(|a| a.type_ == Checked::Valid(Type::Vec3));
    if vec3 {
        let rgb: Vec<[f32; 3]> = accessor::read(ctx, index, &COLOR_RGB, |x| x as f32)?;
        Ok(Some(
            rgb.into_iter().map(|[r, g, b]| [r, g, b, 1.0]).collect(),
        ))
    } else {
        accessor::read(ctx, index, &COLOR_RGBA, |x| x as f32).map(Some)
    }
}
