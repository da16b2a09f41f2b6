//! Loading the assets a scene names, each once: meshes (`load_mesh`, the procedural meshes) and
//! textures (`load_image`, `solid_texture`), keyed by what they are rather than where they were
//! written, so two `load_mesh("bunny.obj")` in a scene give one mesh (and one BVH).
//!
//! glTF models add their meshes and images directly ([`AssetCache::insert_mesh`],
//! [`AssetCache::insert_texture`]); a model image is keyed by the path `file.glb#images[i]`, which
//! is also what the model's material instances name it by.
//!
//! Invariant: the n-th distinct asset gets index n, in order of first use, so ids are deterministic.

use std::collections::HashMap;
use std::path::PathBuf;

use rtc_compiler::sema::hir::{ConstValue, MeshAsset, TextureAsset};

use super::SceneError;
use crate::assets::{self, MeshData, TextureData};

/// What identifies a mesh (the span of the string that named it does not).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(super) enum MeshKey {
    File(PathBuf),
    Quad,
    Cube,
    Sphere(u32),
    /// Primitive `mesh` (in `ModelScene::meshes` order) of a glTF file.
    Model {
        path: PathBuf,
        mesh: usize,
    },
}

impl MeshKey {
    pub(super) fn of(asset: &MeshAsset) -> Self {
        match asset {
            MeshAsset::File { path, .. } => MeshKey::File(path.clone()),
            MeshAsset::Quad => MeshKey::Quad,
            MeshAsset::Cube => MeshKey::Cube,
            MeshAsset::Sphere { subdivisions } => MeshKey::Sphere(*subdivisions),
        }
    }

    /// A short description for statistics and errors.
    pub(super) fn describe(&self) -> String {
        match self {
            MeshKey::File(p) => p.display().to_string(),
            MeshKey::Quad => "quad_mesh()".into(),
            MeshKey::Cube => "cube_mesh()".into(),
            MeshKey::Sphere(n) => format!("sphere_mesh({n})"),
            MeshKey::Model { path, mesh } => format!("{}#mesh {mesh}", path.display()),
        }
    }
}

/// What identifies a texture (a solid colour by its bits, so `-0.0` and `0.0` differ harmlessly).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(super) enum TextureKey {
    File(PathBuf),
    Solid([u32; 4]),
}

impl TextureKey {
    pub(super) fn of(asset: &TextureAsset) -> Self {
        match asset {
            TextureAsset::File { path, .. } => TextureKey::File(path.clone()),
            TextureAsset::Solid(c) => TextureKey::Solid(c.map(f32::to_bits)),
        }
    }

    pub(super) fn describe(&self) -> String {
        match self {
            TextureKey::File(p) => p.display().to_string(),
            TextureKey::Solid(c) => format!("solid_texture({:?})", c.map(f32::from_bits)),
        }
    }
}

/// Meshes and textures loaded so far, in order of first use.
#[derive(Default)]
pub(super) struct AssetCache {
    pub meshes: Vec<(MeshKey, MeshData)>,
    pub textures: Vec<(TextureKey, TextureData)>,
    mesh_index: HashMap<MeshKey, usize>,
    texture_index: HashMap<TextureKey, usize>,
}

impl AssetCache {
    /// The index of a mesh, loading it on first use.
    pub fn mesh(&mut self, asset: &MeshAsset) -> Result<usize, SceneError> {
        let key = MeshKey::of(asset);
        if let Some(&i) = self.mesh_index.get(&key) {
            return Ok(i);
        }
        let mut data = match asset {
            MeshAsset::File { path, span } => {
                assets::load_obj(path).map_err(|source| SceneError::Asset {
                    span: Some(*span),
                    source,
                })?
            }
            MeshAsset::Quad => assets::quad_mesh(),
            MeshAsset::Cube => assets::cube_mesh(),
            MeshAsset::Sphere { subdivisions } => assets::sphere_mesh(*subdivisions),
        };
        data.ensure_normals();
        let i = self.meshes.len();
        self.meshes.push((key.clone(), data));
        self.mesh_index.insert(key, i);
        Ok(i)
    }

    /// The index of a mesh that does not come from the scene's text (a glTF model's), made by
    /// `make` on first use.
    pub fn insert_mesh(&mut self, key: MeshKey, make: impl FnOnce() -> MeshData) -> usize {
        if let Some(&i) = self.mesh_index.get(&key) {
            return i;
        }
        let mut data = make();
        data.ensure_normals();
        let i = self.meshes.len();
        self.meshes.push((key.clone(), data));
        self.mesh_index.insert(key, i);
        i
    }

    /// The index of a texture that does not come from the scene's text (a glTF model's image,
    /// keyed `file.glb#images[i]`), made by `make` on first use.
    pub fn insert_texture(&mut self, key: TextureKey, make: impl FnOnce() -> TextureData) -> usize {
        if let Some(&i) = self.texture_index.get(&key) {
            return i;
        }
        let i = self.textures.len();
        self.textures.push((key.clone(), make()));
        self.texture_index.insert(key, i);
        i
    }

    /// The index of a texture, loading it on first use.
    pub fn texture(&mut self, asset: &TextureAsset) -> Result<usize, SceneError> {
        let key = TextureKey::of(asset);
        if let Some(&i) = self.texture_index.get(&key) {
            return Ok(i);
        }
        let data = match asset {
            TextureAsset::File { path, span } => {
                assets::load_image(path).map_err(|source| SceneError::Asset {
                    span: Some(*span),
                    source,
                })?
            }
            TextureAsset::Solid(c) => assets::solid_texture(*c),
        };
        let i = self.textures.len();
        self.textures.push((key.clone(), data));
        self.texture_index.insert(key, i);
        Ok(i)
    }

    /// Loads every mesh and texture a value refers to (recursively through arrays and structs).
    pub fn scan(&mut self, value: &ConstValue) -> Result<(), SceneError> {
        match value {
            ConstValue::Mesh(m) => self.mesh(m).map(|_| ()),
            ConstValue::Texture(t) => self.texture(t).map(|_| ()),
            ConstValue::Array(items) => items.iter().try_for_each(|v| self.scan(v)),
            ConstValue::Struct { fields, .. } => fields.iter().try_for_each(|v| self.scan(v)),
            _ => Ok(()),
        }
    }
}
