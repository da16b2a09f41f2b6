//! glTF materials → [`GltfMaterial`], and their base-colour images → [`TextureData`].
//!
//! Invariants: each glTF material and each glTF image is converted at most once, on first use
//! ([`Materials`] caches the mapping), so `ModelScene::materials` and `::textures` hold only what
//! the scene uses, in first-use order. Textures other than the base colour (normal, occlusion,
//! emissive, metallic-roughness maps) are ignored with a warning, and so is a file's use of
//! `KHR_texture_transform` (as of any extension we do not read, see `nodes.rs`); sampler
//! settings (filters, wrap modes) are ignored silently, as nearly every file has them. A
//! base-colour texture on a uv set other than 0 is kept, with a warning, and sampled with set 0.
//! A base-colour image file that cannot be read is [`AssetError::MissingFile`] naming the material
//! and the image ([`GltfItem::BaseColorImage`]).

use std::collections::HashMap;

use gltf::json;
use gltf::json::validation::Checked;

use super::buffers::{dangling, image_bytes};
use super::{AlphaMode, Ctx, GltfMaterial};
use crate::assets::texture::decode_image;
use crate::assets::{AssetError, GltfItem, TextureData};

/// The converted materials and textures, with the glTF → rtc index maps.
#[derive(Default)]
pub(super) struct Materials {
    pub materials: Vec<GltfMaterial>,
    pub textures: Vec<TextureData>,
    material_index: HashMap<usize, usize>,
    default_material: Option<usize>,
    image_index: HashMap<usize, usize>,
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
        let mut ignored = Vec::new();
        if pbr.metallic_roughness_texture.is_some() {
            ignored.push("metallic-roughness");
        }
        if json.normal_texture.is_some() {
            ignored.push("normal");
        }
        if json.occlusion_texture.is_some() {
            ignored.push("occlusion");
        }
        if json.emissive_texture.is_some() {
            ignored.push("emissive");
        }
        if !ignored.is_empty() {
            warnings.push(format!(
                "materials[{m}]: {} texture(s) ignored (only base colour is imported)",
                ignored.join(", ")
            ));
        }
        let base_color_texture = match &pbr.base_color_texture {
            None => None,
            Some(info) => {
                if info.tex_coord != 0 {
                    warnings.push(format!(
                        "materials[{m}]: base colour texture uses TEXCOORD_{}, sampled with TEXCOORD_0",
                        info.tex_coord
                    ));
                }
                let texture = ctx
                    .root
                    .textures
                    .get(info.index.value())
                    .ok_or_else(|| dangling(ctx, GltfItem::Texture(info.index.value())))?;
                let image = texture.source.value();
                Some(self.texture(ctx, image, warnings).map_err(|e| match e {
                    // Name the material too: that is what the user knows the texture by.
                    AssetError::MissingFile {
                        path, file, source, ..
                    } => AssetError::MissingFile {
                        path,
                        item: GltfItem::BaseColorImage { material: m, image },
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
                        item: Some(GltfItem::BaseColorImage { material: m, image }),
                        written,
                        problem,
                    },
                    other => other,
                })?)
            }
        };
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
            base_color: pbr.base_color_factor.0,
            base_color_texture,
            metallic: pbr.metallic_factor.0,
            roughness: pbr.roughness_factor.0,
            emissive: json.emissive_factor.0.map(|c| c * strength),
            alpha_mode,
            alpha_cutoff: json.alpha_cutoff.map_or(0.5, |c| c.0),
            double_sided: json.double_sided,
        })
    }

    /// The index in `textures` of glTF image `image`, decoding it on first use.
    /// A texture whose texels held NaN or infinities (replaced by 0) adds a warning.
    fn texture(
        &mut self,
        ctx: &Ctx<'_>,
        image: usize,
        warnings: &mut Vec<String>,
    ) -> Result<usize, AssetError> {
        if let Some(&index) = self.image_index.get(&image) {
            return Ok(index);
        }
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
        self.textures.push(texture);
        let index = self.textures.len() - 1;
        self.image_index.insert(image, index);
        Ok(index)
    }
}
