//! glTF materials → [`GltfMaterial`], and their images → [`TextureData`] with their samplers.
//!
//! Invariants: each glTF material is converted at most once and each glTF image decoded at most
//! once, on first use ([`Materials`] caches the mappings), so `ModelScene::materials` and
//! `::textures` hold only what the scene uses, in first-use order; a texture is one (image,
//! sampler, linear-or-sRGB) triple (base colour and emissive are sRGB, metallic-roughness and
//! occlusion and normal linear data), labelled uniquely in `texture_labels`. Imported: base
//! colour, metallic-roughness, emissive, occlusion and normal textures, each with its sampler
//! (wrap modes, magnification filter; see [`Sampler`] for why there is no minification filter),
//! its `KHR_texture_transform` and its uv set (0 or 1); whether a primitive using the material
//! has `COLOR_0`; `KHR_materials_transmission`'s factor and `KHR_materials_ior` (see
//! `transmission` and `ior` below). Not imported, with a warning naming the material: uv sets
//! past 1 (such a texture is sampled with set 0). An image
//! file that cannot be read is [`AssetError::MissingFile`] naming the material, the texture and
//! the image ([`GltfItem::BaseColorImage`], [`GltfItem::MaterialImage`]).

use std::collections::HashMap;

use gltf::json;
use gltf::json::validation::Checked;

use super::buffers::{dangling, image_bytes};
use super::{AlphaMode, Ctx, GltfMaterial, UvTransform, UV_IDENTITY};
use crate::assets::texture::decode_image;
use crate::assets::{AssetError, GltfItem, Sampler, TextureData, TextureSlot, Wrap};

/// The converted materials and textures, with the glTF → rtc index maps.
#[derive(Default)]
pub(super) struct Materials {
    pub materials: Vec<GltfMaterial>,
    pub textures: Vec<TextureData>,
    /// `ModelScene::texture_labels`.
    pub texture_labels: Vec<String>,
    material_index: HashMap<usize, usize>,
    default_material: Option<usize>,
    /// (glTF image, sampler, read as linear data) → index in `textures`.
    image_index: HashMap<(usize, Sampler, bool), usize>,
}

impl Materials {
    /// The index in `materials` of glTF material `m` (`None`: the default material), converting
    /// it on first use.
    pub fn get(
        &mut self,
        ctx: &Ctx<'_>,
        m: Option<usize>,
        warnings: &mut Vec<String>,
    ) -> Result<usize, AssetError> {
        let Some(m) = m else {
            return Ok(*self.default_material.get_or_insert_with(|| {
                self.materials.push(GltfMaterial {
                    name: Some("default".to_owned()),
                    vertex_colors: has_vertex_colors(ctx.root, None),
                    ..GltfMaterial::default()
                });
                self.materials.len() - 1
            }));
        };
        if let Some(&index) = self.material_index.get(&m) {
            return Ok(index);
        }
        let json = ctx
            .root
            .materials
            .get(m)
            .ok_or_else(|| dangling(ctx, GltfItem::Material(m)))?;
        let material = self.convert(ctx, m, json, warnings)?;
        self.materials.push(material);
        let index = self.materials.len() - 1;
        self.material_index.insert(m, index);
        Ok(index)
    }

    fn convert(
        &mut self,
        ctx: &Ctx<'_>,
        m: usize,
        json: &json::Material,
        warnings: &mut Vec<String>,
    ) -> Result<GltfMaterial, AssetError> {
        let pbr = &json.pbr_metallic_roughness;
        let named = material_name(m, json);
        let mut uv_transforms = [UV_IDENTITY; 5];
        let sets = slot_uv_sets(json);
        let uv_sets = sets
            .iter()
            .enumerate()
            .filter(|(_, &s)| s == 1)
            .fold(0, |bits, (k, _)| bits | (1 << k));
        let transform_of = |info: Option<&json::texture::Info>| {
            info.and_then(|i| texture_info(i).transform)
                .unwrap_or(UV_IDENTITY)
        };
        uv_transforms[0] = transform_of(pbr.base_color_texture.as_ref());
        let base_color_transformed = pbr
            .base_color_texture
            .as_ref()
            .is_some_and(|i| texture_info(i).transform.is_some());
        uv_transforms[1] = transform_of(pbr.metallic_roughness_texture.as_ref());
        uv_transforms[2] = transform_of(json.emissive_texture.as_ref());
        let base_color_texture = pbr
            .base_color_texture
            .as_ref()
            .map(|info| {
                self.slot(
                    ctx,
                    (m, &named),
                    Slot::BaseColor,
                    texture_info(info),
                    warnings,
                )
            })
            .transpose()?;
        let metallic_roughness_texture = pbr
            .metallic_roughness_texture
            .as_ref()
            .map(|info| {
                self.slot(
                    ctx,
                    (m, &named),
                    Slot::MetallicRoughness,
                    texture_info(info),
                    warnings,
                )
            })
            .transpose()?;
        let emissive_texture = json
            .emissive_texture
            .as_ref()
            .map(|info| {
                self.slot(
                    ctx,
                    (m, &named),
                    Slot::Emissive,
                    texture_info(info),
                    warnings,
                )
            })
            .transpose()?;
        let occlusion_texture = json
            .occlusion_texture
            .as_ref()
            .map(|o| {
                // `gltf-json` has no typed field for the extension on an occlusion texture;
                // it is among the `others`.
                let info = occlusion_info(o);
                uv_transforms[3] = info.transform.unwrap_or(UV_IDENTITY);
                self.slot(ctx, (m, &named), Slot::Occlusion, info, warnings)
            })
            .transpose()?;
        let normal_texture = json
            .normal_texture
            .as_ref()
            .map(|n| {
                let info = normal_info(n);
                uv_transforms[4] = info.transform.unwrap_or(UV_IDENTITY);
                self.slot(ctx, (m, &named), Slot::Normal, info, warnings)
            })
            .transpose()?;
        let occlusion_strength = json
            .occlusion_texture
            .as_ref()
            .map_or(1.0, |o| o.strength.0);
        let strength = json
            .extensions
            .as_ref()
            .and_then(|e| e.emissive_strength.as_ref())
            .map_or(1.0, |s| s.emissive_strength.0);
        let alpha_mode = match json.alpha_mode {
            Checked::Valid(json::material::AlphaMode::Opaque) | Checked::Invalid => {
                AlphaMode::Opaque
            }
            Checked::Valid(json::material::AlphaMode::Mask) => AlphaMode::Mask,
            Checked::Valid(json::material::AlphaMode::Blend) => AlphaMode::Blend,
        };
        Ok(GltfMaterial {
            name: json.name.clone(),
            index: Some(m),
            base_color: pbr.base_color_factor.0,
            base_color_texture,
            metallic: pbr.metallic_factor.0,
            roughness: pbr.roughness_factor.0,
            metallic_roughness_texture,
            emissive: json.emissive_factor.0.map(|c| c * strength),
            emissive_texture,
            occlusion_texture,
            occlusion_strength,
            normal_texture,
            normal_scale: json.normal_texture.as_ref().map_or(1.0, |n| n.scale),
            uv_transforms,
            uv_sets,
            vertex_colors: has_vertex_colors(ctx.root, Some(m)),
            base_color_transformed,
            alpha_mode,
            alpha_cutoff: json.alpha_cutoff.map_or(0.5, |c| c.0),
            double_sided: json.double_sided,
            transmission: transmission(json, &named, warnings),
            ior: ior(json),
        })
    }

    /// The index in `textures` of the texture of slot `slot` of material `m` (`named` in
    /// messages), warning about what of it is not imported (another uv set, a texture transform).
    fn slot(
        &mut self,
        ctx: &Ctx<'_>,
        (m, named): (usize, &str),
        slot: Slot,
        info: SlotInfo,
        warnings: &mut Vec<String>,
    ) -> Result<usize, AssetError> {
        let what = slot.describe();
        if info.tex_coord > 1 {
            warnings.push(format!(
                "{named}: its {what} texture uses TEXCOORD_{}, sampled with TEXCOORD_0 (uv sets 0 \
                 and 1 are imported)",
                info.tex_coord
            ));
        }
        let texture = ctx
            .root
            .textures
            .get(info.texture)
            .ok_or_else(|| dangling(ctx, GltfItem::Texture(info.texture)))?;
        let image = texture.source.value();
        let sampler = texture
            .sampler
            .map(|i| sampler(ctx, i.value()))
            .transpose()?
            .unwrap_or_default();
        let index = |i: usize| u32::try_from(i).unwrap_or(u32::MAX);
        let other = |slot| GltfItem::MaterialImage {
            material: index(m),
            slot,
            image: index(image),
        };
        let item = match slot {
            Slot::BaseColor => GltfItem::BaseColorImage { material: m, image },
            Slot::MetallicRoughness => other(TextureSlot::MetallicRoughness),
            Slot::Emissive => other(TextureSlot::Emissive),
            Slot::Occlusion => other(TextureSlot::Occlusion),
            Slot::Normal => other(TextureSlot::Normal),
        };
        let linear = matches!(
            slot,
            Slot::MetallicRoughness | Slot::Occlusion | Slot::Normal
        );
        self.texture(ctx, (image, sampler, linear), warnings)
            .map_err(|e| match e {
                // Name the material too: that is what the user knows the texture by.
                AssetError::MissingFile {
                    path, file, source, ..
                } => AssetError::MissingFile {
                    path,
                    item,
                    file,
                    source,
                },
                AssetError::Escape {
                    path,
                    written,
                    problem,
                    ..
                } => AssetError::Escape {
                    path,
                    item: Some(item),
                    written,
                    problem,
                },
                other => other,
            })
    }

    /// The index in `textures` of glTF image `image` read through `sampler`, as linear data or
    /// as sRGB colour, decoding the image on first use (an image used in two ways is decoded
    /// once and stored twice). A texture whose texels held NaN or infinities (replaced by 0)
    /// adds a warning.
    fn texture(
        &mut self,
        ctx: &Ctx<'_>,
        key: (usize, Sampler, bool),
        warnings: &mut Vec<String>,
    ) -> Result<usize, AssetError> {
        let (image, sampler, linear) = key;
        if let Some(&index) = self.image_index.get(&key) {
            return Ok(index);
        }
        let decoded = self
            .image_index
            .iter()
            .find(|((i, _, _), _)| *i == image)
            .and_then(|(_, &t)| self.textures.get(t));
        let texture = match decoded {
            Some(texture) => texture.clone(),
            None => self.decode(ctx, image, warnings)?,
        };
        let mut texture = if linear {
            texture.linear()
        } else {
            texture.srgb()
        };
        texture.sampler = sampler;
        self.textures.push(texture);
        self.texture_labels.push(texture_label(key));
        let index = self.textures.len() - 1;
        self.image_index.insert(key, index);
        Ok(index)
    }

    /// Decodes glTF image `image`, warning when texels held NaN or infinities.
    fn decode(
        &mut self,
        ctx: &Ctx<'_>,
        image: usize,
        warnings: &mut Vec<String>,
    ) -> Result<TextureData, AssetError> {
        let (bytes, label) = image_bytes(ctx, image)?;
        let texture = decode_image(&bytes, &label)?;
        if texture.nonfinite_texels > 0 {
            warnings.push(format!(
                "images[{image}] (`{}`): {} of {} texels hold NaN or infinite values; they were \
                 replaced by 0",
                label.display(),
                texture.nonfinite_texels,
                texture.texel_count()
            ));
        }
        Ok(texture)
    }
}

/// A texture of a material.
#[derive(Clone, Copy)]
enum Slot {
    BaseColor,
    MetallicRoughness,
    Emissive,
    Occlusion,
    Normal,
}

impl Slot {
    fn describe(self) -> &'static str {
        match self {
            Self::BaseColor => "base colour",
            Self::MetallicRoughness => "metallic-roughness",
            Self::Emissive => "emissive",
            Self::Occlusion => "occlusion",
            Self::Normal => "normal",
        }
    }
}

/// What a material says about one of its textures.
struct SlotInfo {
    texture: usize,
    /// The uv set (`KHR_texture_transform`'s `texCoord` overrides the texture info's).
    tex_coord: u32,
    /// Its `KHR_texture_transform`, if any.
    transform: Option<UvTransform>,
}

/// What the primitives of a material need besides positions, normals and `TEXCOORD_0`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct AttributeNeeds {
    /// Some texture reads uv set 1.
    pub uv1: bool,
    /// The uv set of its normal texture, when it has one (tangents are then needed).
    pub normal_uv: Option<u32>,
}

/// What primitives with glTF material `material` (`None`: the default material) need.
pub(super) fn attribute_needs(ctx: &Ctx<'_>, material: Option<usize>) -> AttributeNeeds {
    let Some(json) = material.and_then(|m| ctx.root.materials.get(m)) else {
        return AttributeNeeds::default();
    };
    let sets = slot_uv_sets(json);
    AttributeNeeds {
        uv1: sets.contains(&1),
        normal_uv: json
            .normal_texture
            .as_ref()
            .map(|n| normal_info(n).tex_coord.min(1)),
    }
}

/// The uv set of each texture of `json` in the order of `GltfMaterial::uv_transforms` (a missing
/// texture reads set 0; sets past 1 count as 0, as they are sampled).
fn slot_uv_sets(json: &json::Material) -> [u32; 5] {
    let pbr = &json.pbr_metallic_roughness;
    let of = |i: Option<&json::texture::Info>| i.map_or(0, |i| texture_info(i).tex_coord);
    let occlusion = json
        .occlusion_texture
        .as_ref()
        .map_or(0, |o| occlusion_info(o).tex_coord);
    let normal = json
        .normal_texture
        .as_ref()
        .map_or(0, |n| normal_info(n).tex_coord);
    [
        of(pbr.base_color_texture.as_ref()),
        of(pbr.metallic_roughness_texture.as_ref()),
        of(json.emissive_texture.as_ref()),
        occlusion,
        normal,
    ]
    .map(|s| if s == 1 { 1 } else { 0 })
}

/// Whether a primitive of some mesh of `root` with material `material` (`None`: the default
/// material) has `COLOR_0` (the link step decides the same way).
pub(super) fn has_vertex_colors(root: &json::Root, material: Option<usize>) -> bool {
    root.meshes.iter().flat_map(|m| &m.primitives).any(|p| {
        p.material.map(|i| i.value()) == material
            && p.attributes
                .contains_key(&Checked::Valid(json::mesh::Semantic::Colors(0)))
    })
}

fn occlusion_info(o: &json::material::OcclusionTexture) -> SlotInfo {
    let transform = o
        .extensions
        .as_ref()
        .and_then(|e| e.others.get("KHR_texture_transform"))
        .and_then(|v| {
            serde_json::from_value::<json::extensions::texture::TextureTransform>(v.clone()).ok()
        });
    SlotInfo {
        texture: o.index.value(),
        tex_coord: transform
            .as_ref()
            .and_then(|t| t.tex_coord)
            .unwrap_or(o.tex_coord),
        transform: transform
            .as_ref()
            .map(|t| uv_transform(t.offset.0, t.rotation.0, t.scale.0)),
    }
}

fn normal_info(n: &json::material::NormalTexture) -> SlotInfo {
    let transform = n
        .extensions
        .as_ref()
        .and_then(|e| e.others.get("KHR_texture_transform"))
        .and_then(|v| {
            serde_json::from_value::<json::extensions::texture::TextureTransform>(v.clone()).ok()
        });
    SlotInfo {
        texture: n.index.value(),
        tex_coord: transform
            .as_ref()
            .and_then(|t| t.tex_coord)
            .unwrap_or(n.tex_coord),
        transform: transform
            .as_ref()
            .map(|t| uv_transform(t.offset.0, t.rotation.0, t.scale.0)),
    }
}

fn texture_info(info: &json::texture::Info) -> SlotInfo {
    let transform = info
        .extensions
        .as_ref()
        .and_then(|e| e.texture_transform.as_ref());
    SlotInfo {
        texture: info.index.value(),
        tex_coord: transform
            .and_then(|t| t.tex_coord)
            .unwrap_or(info.tex_coord),
        transform: transform.map(|t| uv_transform(t.offset.0, t.rotation.0, t.scale.0)),
    }
}

/// `KHR_texture_transform`'s `translation × rotation × scale` as rows (the extension's GLSL:
/// `rotation = mat3(cos, sin, 0, -sin, cos, 0, 0, 0, 1)`, column-major), so
/// `u' = cos·sx·u − sin·sy·v + ox` and `v' = sin·sx·u + cos·sy·v + oy`. Non-finite numbers
/// (which the JSON cannot hold, but a reader might produce) give the identity.
pub(super) fn uv_transform(offset: [f32; 2], rotation: f32, scale: [f32; 2]) -> UvTransform {
    let (s, c) = rotation.sin_cos();
    let rows = [
        [c * scale[0], -s * scale[1], offset[0]],
        [s * scale[0], c * scale[1], offset[1]],
    ];
    if rows.iter().flatten().all(|x| x.is_finite()) {
        rows
    } else {
        UV_IDENTITY
    }
}

/// `materials[m]`, with its name when it has one: `materials[2] (`Visor`)`.
fn material_name(m: usize, json: &json::Material) -> String {
    match &json.name {
        Some(name) => format!("materials[{m}] (`{name}`)"),
        None => format!("materials[{m}]"),
    }
}

/// `images[i]`, with the sampler's settings after a `~` when they are not the default, and
/// `~linear` for data read without sRGB decoding: unique per texture.
fn texture_label((image, sampler, linear): (usize, Sampler, bool)) -> String {
    let data = if linear { "~linear" } else { "" };
    if sampler == Sampler::default() {
        return format!("images[{image}]{data}");
    }
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => "repeat",
        Wrap::ClampToEdge => "clamp",
        Wrap::MirroredRepeat => "mirror",
    };
    let filter = if sampler.nearest { "nearest" } else { "linear" };
    format!(
        "images[{image}]~{},{},{filter}{data}",
        wrap(sampler.wrap_u),
        wrap(sampler.wrap_v)
    )
}

/// glTF sampler `index` as a [`Sampler`]: `wrapS`/`wrapT` as they are; nearest filtering when
/// `magFilter` is `NEAREST` (or, without a `magFilter`, when `minFilter` is `NEAREST` or
/// `NEAREST_MIPMAP_*`). A ray has no footprint, so there is no separate minification filter and
/// no mipmapping (see [`Sampler`]).
fn sampler(ctx: &Ctx<'_>, index: usize) -> Result<Sampler, AssetError> {
    use json::texture::{MagFilter, MinFilter, WrappingMode};
    let json = ctx
        .root
        .samplers
        .get(index)
        .ok_or_else(|| dangling(ctx, GltfItem::Sampler(index)))?;
    let wrap = |w: &Checked<WrappingMode>| match w {
        Checked::Valid(WrappingMode::ClampToEdge) => Wrap::ClampToEdge,
        Checked::Valid(WrappingMode::MirroredRepeat) => Wrap::MirroredRepeat,
        Checked::Valid(WrappingMode::Repeat) | Checked::Invalid => Wrap::Repeat,
    };
    let nearest = match (json.mag_filter, json.min_filter) {
        (Some(Checked::Valid(mag)), _) => mag == MagFilter::Nearest,
        (None, Some(Checked::Valid(min))) => matches!(
            min,
            MinFilter::Nearest | MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
        ),
        _ => false,
    };
    Ok(Sampler {
        wrap_u: wrap(&json.wrap_s),
        wrap_v: wrap(&json.wrap_t),
        nearest,
    })
}

/// `KHR_materials_transmission`'s factor (clamped to 0..=1; 0 without the extension), warning
/// about what of it is not imported: its texture, and transmission on a `MASK` or `BLEND`
/// material (which stays masked or blended, without transmission).
fn transmission(json: &json::Material, named: &str, warnings: &mut Vec<String>) -> f32 {
    let Some(t) = json
        .extensions
        .as_ref()
        .and_then(|e| e.transmission.as_ref())
    else {
        return 0.0;
    };
    let factor = t.transmission_factor.0;
    let factor = if factor.is_finite() {
        factor.clamp(0.0, 1.0)
    } else {
        0.0
    };
    if t.transmission_texture.is_some() {
        warnings.push(format!(
            "{named}: its transmission texture is not imported (the factor {factor:.3} applies \
             everywhere)"
        ));
    }
    if factor > 0.0
        && !matches!(
            json.alpha_mode,
            Checked::Valid(json::material::AlphaMode::Opaque)
        )
    {
        warnings.push(format!(
            "{named}: KHR_materials_transmission is not imported on a MASK or BLEND material"
        ));
        return 0.0;
    }
    if factor > 0.0 {
        warnings.push(format!(
            "{named}: transmission {factor:.3} is a smooth dielectric mixed with the opaque \
             shading (roughness shapes only the opaque part; a transmissive material is never \
             back-face culled)"
        ));
    }
    factor
}

/// `KHR_materials_ior`'s index, clamped to 1..=4 (1.5 without the extension or for a value that
/// is not a finite number; glTF's 0, "fully reflective", becomes 4).
fn ior(json: &json::Material) -> f32 {
    let Some(ior) = json.extensions.as_ref().and_then(|e| e.ior.as_ref()) else {
        return 1.5;
    };
    let v = ior.ior.0;
    if !v.is_finite() {
        1.5
    } else if v == 0.0 {
        4.0
    } else {
        v.clamp(1.0, 4.0)
    }
}
