//! Loading the assets a scene names, each once: meshes (`load_mesh`, the procedural meshes) and
//! textures (`load_image`, `solid_texture`), keyed by what they are rather than where they were
//! written, so two `load_mesh("bunny.obj")` in a scene give one mesh (and one BVH).
//!
//! glTF models add their meshes and images directly ([`AssetCache::insert_mesh`],
//! [`AssetCache::insert_texture`]); a model image is keyed by the path `file.glb#images[i]`, which
//! is also what the model's material instances name it by.
//!
//! Invariants: the n-th distinct asset gets index n, in order of first use, so ids are
//! deterministic. A file is only read once its path passed `assets::confine` (inside the scene's
//! folder or an asset root); a refused path is [`AssetError::Escape`](crate::assets::AssetError)
//! at the scene's string (E0903). A texture whose texels held NaN or infinities (replaced by 0 on
//! load) adds a warning naming the file and the count.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rtc_compiler::sema::hir::{ConstValue, MeshAsset, TextureAsset};

use super::store::{AssetStore, Stamp, Version};
use super::SceneError;
use crate::assets::confine::{self, resolve_scene_path};
use crate::assets::model::parse_gltf_with;
use crate::assets::model::ModelScene;
use crate::assets::texture::decode_image;
use crate::assets::{self, parse_obj, AssetError, AssetRoots, MeshData, TextureData};

/// A file's bytes (from the disk, or from memory as `roots` say), read once: the loaders parse
/// them and the store hashes them.
fn read(file: &Path, roots: &AssetRoots) -> Result<Vec<u8>, AssetError> {
    confine::read(file, roots).map_err(|source| AssetError::Read {
        path: file.to_owned(),
        source,
    })
}

/// What identifies a mesh (the span of the string that named it does not).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(super) enum MeshKey {
    File(PathBuf),
    Quad,
    Cube,
    Sphere(u32),
    /// Primitive `mesh` (in `ModelScene::meshes` order) of a glTF file; `label` says which
    /// (`meshes[2].primitives[0]`, from `ModelScene::mesh_labels`).
    Model {
        path: PathBuf,
        mesh: usize,
        label: String,
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
            MeshKey::Model { path, label, .. } => format!("{}#{label}", path.display()),
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

/// Meshes and textures loaded so far, in order of first use, each with the stamp of the file it
/// came from; what is not in `store` yet is loaded and put there.
#[derive(Default)]
pub(super) struct AssetCache {
    pub meshes: Vec<(MeshKey, Arc<MeshData>, Version)>,
    pub textures: Vec<(TextureKey, Arc<TextureData>)>,
    /// Assets and BVHs kept across builds (the caller's, moved in for the build).
    pub store: AssetStore,
    /// What loading found and repaired (non-finite texels), one sentence each.
    pub warnings: Vec<String>,
    mesh_index: HashMap<MeshKey, usize>,
    texture_index: HashMap<TextureKey, usize>,
    /// The scene file (for errors) and its folder.
    scene_file: PathBuf,
    scene_dir: PathBuf,
    /// Where else assets may come from.
    pub roots: AssetRoots,
}

impl AssetCache {
    /// An empty cache for the scene in `scene_file` (its folder is where paths are resolved);
    /// `roots` are the other folders assets may come from.
    pub fn new(scene_file: Option<&Path>, roots: AssetRoots) -> AssetCache {
        let scene_file = scene_file.map(Path::to_path_buf).unwrap_or_default();
        let scene_dir = scene_file
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        AssetCache {
            scene_file,
            scene_dir,
            roots,
            ..AssetCache::default()
        }
    }

    /// The file to read for a path the scene names, checked to stay inside the allowed folders.
    pub fn confined(&self, compiled: &Path) -> Result<PathBuf, AssetError> {
        resolve_scene_path(compiled, &self.scene_dir, &self.roots).map_err(|(written, problem)| {
            AssetError::Escape {
                path: self.scene_file.clone(),
                item: None,
                written,
                problem: Box::new(problem),
            }
        })
    }

    /// The index of a mesh, loading it on first use (or taking it from the store).
    pub fn mesh(&mut self, asset: &MeshAsset) -> Result<usize, SceneError> {
        let key = MeshKey::of(asset);
        if let Some(&i) = self.mesh_index.get(&key) {
            return Ok(i);
        }
        let file = match asset {
            MeshAsset::File { path, span } => {
                Some(self.confined(path).map_err(|source| SceneError::Asset {
                    span: Some(*span),
                    source,
                })?)
            }
            _ => None,
        };
        let stamp = file
            .as_deref()
            .map_or(Stamp::NONE, |f| Stamp::of(f, &self.roots));
        let (version, data) =
            match self
                .store
                .mesh(&key, stamp, file.as_deref().map(|f| (f, &self.roots)))
            {
                Some(hit) => hit,
                None => {
                    let (mut data, version) = match (asset, &file) {
                        (MeshAsset::File { span, .. }, Some(file)) => {
                            let at_span = |source| SceneError::Asset {
                                span: Some(*span),
                                source,
                            };
                            let bytes = read(file, &self.roots).map_err(at_span)?;
                            let data = parse_obj(&bytes, file).map_err(at_span)?;
                            (data, Version::of_bytes(stamp, &bytes))
                        }
                        (MeshAsset::Quad, _) => (assets::quad_mesh(), Version::NONE),
                        (MeshAsset::Cube, _) => (assets::cube_mesh(), Version::NONE),
                        (MeshAsset::Sphere { subdivisions }, _) => {
                            (assets::sphere_mesh(*subdivisions), Version::NONE)
                        }
                        (MeshAsset::File { .. }, None) => (MeshData::default(), Version::NONE),
                    };
                    data.ensure_normals();
                    let data = Arc::new(data);
                    self.store
                        .put_mesh(key.clone(), version, Arc::clone(&data), file.is_some());
                    (version, data)
                }
            };
        let i = self.meshes.len();
        self.meshes.push((key.clone(), data, version));
        self.mesh_index.insert(key, i);
        Ok(i)
    }

    /// The index of a mesh that does not come from the scene's text (a glTF model's, made from
    /// the model file of `version`), made by `make` on first use unless the store has it.
    pub fn insert_mesh(
        &mut self,
        key: MeshKey,
        version: Version,
        make: impl FnOnce() -> MeshData,
    ) -> usize {
        if let Some(&i) = self.mesh_index.get(&key) {
            return i;
        }
        let data = match self.store.derived_mesh(&key, version) {
            Some(data) => data,
            None => {
                let mut data = make();
                data.ensure_normals();
                let data = Arc::new(data);
                self.store
                    .put_mesh(key.clone(), version, Arc::clone(&data), false);
                data
            }
        };
        let i = self.meshes.len();
        self.meshes.push((key.clone(), data, version));
        self.mesh_index.insert(key, i);
        i
    }

    /// A glTF file (confined already), read once per content, and its version.
    pub fn model(&mut self, file: &Path) -> Result<(Version, Arc<ModelScene>), AssetError> {
        let stamp = Stamp::of(file, &self.roots);
        if let Some(hit) = self.store.model((file, &self.roots), stamp) {
            return Ok(hit);
        }
        let bytes = read(file, &self.roots)?;
        let model = Arc::new(parse_gltf_with(&bytes, file, &self.roots)?);
        let version = Version::of_bytes(stamp, &bytes);
        self.store
            .put_model(file.to_path_buf(), version, Arc::clone(&model));
        Ok((version, model))
    }

    /// The index of a texture that does not come from the scene's text (a glTF model's image,
    /// keyed `file.glb#images[i]`, made from the model file of `version`), made by `make` on
    /// first use unless the store has it.
    pub fn insert_texture(
        &mut self,
        key: TextureKey,
        version: Version,
        make: impl FnOnce() -> TextureData,
    ) -> usize {
        if let Some(&i) = self.texture_index.get(&key) {
            return i;
        }
        let data = match self.store.derived_texture(&key, version) {
            Some(data) => data,
            None => {
                let data = Arc::new(make());
                self.store
                    .put_texture(key.clone(), version, Arc::clone(&data), false);
                data
            }
        };
        let i = self.textures.len();
        self.textures.push((key.clone(), data));
        self.texture_index.insert(key, i);
        i
    }

    /// The index of a texture, loading it on first use (or taking it from the store).
    pub fn texture(&mut self, asset: &TextureAsset) -> Result<usize, SceneError> {
        let key = TextureKey::of(asset);
        if let Some(&i) = self.texture_index.get(&key) {
            return Ok(i);
        }
        let file = match asset {
            TextureAsset::File { path, span } => {
                Some(self.confined(path).map_err(|source| SceneError::Asset {
                    span: Some(*span),
                    source,
                })?)
            }
            TextureAsset::Solid(_) => None,
        };
        let stamp = file
            .as_deref()
            .map_or(Stamp::NONE, |f| Stamp::of(f, &self.roots));
        let data = match self
            .store
            .texture(&key, stamp, file.as_deref().map(|f| (f, &self.roots)))
        {
            Some(data) => data,
            None => {
                let (data, version) = match (asset, &file) {
                    (TextureAsset::File { path, span }, Some(file)) => {
                        let at_span = |source| SceneError::Asset {
                            span: Some(*span),
                            source,
                        };
                        let bytes = read(file, &self.roots).map_err(at_span)?;
                        let data = decode_image(&bytes, file).map_err(at_span)?;
                        if data.nonfinite_texels > 0 {
                            self.warnings.push(nonfinite_warning(path, &data));
                        }
                        (data, Version::of_bytes(stamp, &bytes))
                    }
                    (TextureAsset::Solid(c), _) => (assets::solid_texture(*c), Version::NONE),
                    (TextureAsset::File { .. }, None) => {
                        (assets::solid_texture([0.0; 4]), Version::NONE)
                    }
                };
                let data = Arc::new(data);
                self.store
                    .put_texture(key.clone(), version, Arc::clone(&data), file.is_some());
                data
            }
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

/// The warning for a texture whose NaN or infinite texels were replaced by 0.
pub(super) fn nonfinite_warning(path: &Path, data: &TextureData) -> String {
    format!(
        "{}: {} of {} texels hold NaN or infinite values; they were replaced by 0",
        path.display(),
        data.nonfinite_texels,
        data.texel_count()
    )
}
