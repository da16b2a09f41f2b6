//! The asset store: what loading and BVH building produced, kept across rebuilds of a scene's
//! entities so that a recompiled program (`Renderer::replace_kernel`) or a reloaded scene reuses
//! every mesh, texture, glTF file and object-level BVH whose inputs did not change.
//!
//! An entry is keyed by what the scene names (the same keys as the per-build [`AssetCache`]: a
//! file's resolved path, a procedural mesh's parameters, a solid colour) and identified by the
//! file's **content hash**; its length and modification time ([`Stamp`]) decide, without reading
//! the file, whether the hash can have changed. A file whose stamp changed is hashed again: same
//! content, and the entry (and its object-level BVH) is kept under the new stamp; new content,
//! and it is loaded again. Object-level BVHs are keyed by mesh, content and builder preset, and
//! the decoded copies of 8-bit sRGB textures (`scene::SrgbTextures`) by the texture they were
//! decoded from, so an unchanged texture is decoded once over any number of rebuilds. The last
//! build's `texels` (every texture's words, concatenated) is kept with the textures it was made
//! of, so a rebuild over the same textures shares it instead of copying and comparing it.
//!
//! Invariants: the store never holds data of a file whose current stamp differs from the one it
//! was read with (every lookup compares stamps first); counters only grow, so a caller can tell
//! "nothing was read, nothing was built" by comparing two snapshots ([`StoreCounters`]).
//!
//! [`AssetCache`]: super::assets_cache::AssetCache

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;

use rtc_bvh::{Aabb, BuildPreset, NodeRecord};

use super::assets_cache::{MeshKey, TextureKey};
use crate::assets::confine;
use crate::assets::model::ModelScene;
use crate::assets::{AssetRoots, MeshData, TextureData};

/// What identifies a file's version without reading it: its length and modification time
/// (`None` for data that comes from no file, such as a procedural mesh).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Stamp(Option<(u64, Option<SystemTime>)>);

/// The content hash of bytes read from a file.
fn hash_bytes(bytes: &[u8]) -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = foldhash::quality::FixedState::with_seed(0x7274_635f_6173_7365).build_hasher();
    h.write(bytes);
    h.finish()
}

/// A file's content hash (`None` for a file that cannot be read, which then never matches a
/// stored entry's).
fn content_hash((path, roots): FileIn<'_>) -> Option<u64> {
    confine::read(path, roots)
        .ok()
        .map(|bytes| hash_bytes(&bytes))
}

/// A resolved file and where it is read from (the disk, or memory: [`AssetRoots::in_memory`]).
pub(super) type FileIn<'a> = (&'a Path, &'a AssetRoots);

impl Stamp {
    /// The stamp of data that comes from no file.
    pub const NONE: Stamp = Stamp(None);

    /// The stamp of the file at `path` now (a file that cannot be read gets a stamp no read
    /// file has, so it is never taken from the store). A file held in memory has no time: its
    /// content hash stands in for its length, so equal stamps still mean equal content.
    pub fn of(path: &Path, roots: &AssetRoots) -> Stamp {
        if let Some(files) = roots.memory() {
            return match files.get(path) {
                Some(bytes) => Stamp(Some((hash_bytes(bytes), None))),
                None => Stamp(Some((u64::MAX, None))),
            };
        }
        match std::fs::metadata(path) {
            Ok(m) => Stamp(Some((m.len(), m.modified().ok()))),
            Err(_) => Stamp(Some((u64::MAX, None))),
        }
    }
}

/// One mesh's object-level BVH, quantised, with its triangle slots encoded.
#[derive(Debug)]
pub struct BuiltMesh {
    /// The BVH records (header first), relative to the BVH's own base.
    pub records: Vec<NodeRecord>,
    /// `TRIANGLE` records of its slots.
    pub triangles: Vec<[f32; 4]>,
    /// `ATTRIBUTE` records of its slots (their `extra` words relative to `extras`: see
    /// `encode::link_extras`).
    pub attributes: Vec<[u32; 4]>,
    /// `VERTEX_EXTRA` records of its slots (empty for a mesh without extras).
    pub extras: Vec<[u32; 4]>,
    /// Triangle slots.
    pub slots: u32,
    /// Its object-space box.
    pub bounds: Aabb,
    /// Depth of the BVH.
    pub depth: u32,
}

/// Running totals of the store's work, for reports and tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StoreCounters {
    /// Mesh files (OBJ) read.
    pub meshes_read: u32,
    /// Image files read.
    pub images_read: u32,
    /// glTF files read.
    pub models_read: u32,
    /// Object-level BVHs built.
    pub blas_builds: u32,
    /// 8-bit sRGB textures decoded to linear half floats (`TextureData::decoded_srgb`).
    pub textures_decoded: u32,
    /// Concatenations of the textures' words into a scene's `texels` (the store keeps the last).
    pub texel_concatenations: u32,
    /// Lookups answered from the store.
    pub reused: u32,
}

/// A scene's `texels` and the textures they concatenate, in order.
type Texels = (Vec<Arc<TextureData>>, Arc<[u32]>);

/// Assets and object-level BVHs kept across entity builds (see the module docs).
#[derive(Debug, Default)]
pub struct AssetStore {
    meshes: HashMap<MeshKey, Entry<MeshData>>,
    textures: HashMap<TextureKey, Entry<TextureData>>,
    models: HashMap<PathBuf, Entry<ModelScene>>,
    /// Object-level BVHs by mesh and preset, with the content they were built from.
    blas: HashMap<(MeshKey, BuildPreset), (Version, Arc<BuiltMesh>)>,
    /// Textures stored decoded, each with the texture it was decoded from (kept alive, so the
    /// same allocation is the same data).
    decoded: HashMap<TextureKey, (Arc<TextureData>, Arc<TextureData>)>,
    /// The last `texels` made, with the textures it concatenates (kept alive, as above).
    texels: Option<Texels>,
    counters: StoreCounters,
}

/// What a stored entry was made from: the stamp it was last seen with and its content hash.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Version {
    stamp: Stamp,
    hash: Option<u64>,
}

impl Version {
    /// The version of data that comes from no file.
    pub const NONE: Version = Version {
        stamp: Stamp::NONE,
        hash: None,
    };

    /// The version of `bytes`, read from a file whose stamp was `stamp`.
    pub(super) fn of_bytes(stamp: Stamp, bytes: &[u8]) -> Version {
        Version {
            stamp,
            hash: Some(hash_bytes(bytes)),
        }
    }

    /// Whether two versions name the same content: equal hashes, or (without a hash) equal
    /// stamps.
    fn same_content(&self, other: &Version) -> bool {
        match (self.hash, other.hash) {
            (Some(a), Some(b)) => a == b,
            (None, None) => self.stamp == other.stamp,
            _ => false,
        }
    }
}

#[derive(Debug)]
struct Entry<T> {
    version: Version,
    data: Arc<T>,
}

/// The entry of `key` if it is still current for `file` (`None`: no file, the stamp alone
/// decides): same stamp, or a new stamp over the same content (then the stamp is updated).
fn current<K: std::hash::Hash + Eq, T>(
    map: &mut HashMap<K, Entry<T>>,
    key: &K,
    stamp: Stamp,
    file: Option<FileIn<'_>>,
) -> Option<(Version, Arc<T>)> {
    let entry = map.get_mut(key)?;
    if entry.version.stamp != stamp {
        let hash = content_hash(file?);
        if hash.is_none() || hash != entry.version.hash {
            return None;
        }
        entry.version.stamp = stamp;
    }
    Some((entry.version, Arc::clone(&entry.data)))
}

impl AssetStore {
    /// An empty store.
    pub fn new() -> AssetStore {
        AssetStore::default()
    }

    /// What the store has done so far.
    pub fn counters(&self) -> StoreCounters {
        self.counters
    }

    /// Drops everything kept (the counters stay).
    pub fn clear(&mut self) {
        let counters = self.counters;
        *self = AssetStore {
            counters,
            ..AssetStore::default()
        };
    }

    /// The stored mesh of `key` if still current (see [`current`]).
    pub(super) fn mesh(
        &mut self,
        key: &MeshKey,
        stamp: Stamp,
        file: Option<FileIn<'_>>,
    ) -> Option<(Version, Arc<MeshData>)> {
        let hit = current(&mut self.meshes, key, stamp, file);
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// Stores a mesh of `version` (`read`: just read from its file).
    pub(super) fn put_mesh(
        &mut self,
        key: MeshKey,
        version: Version,
        data: Arc<MeshData>,
        read: bool,
    ) {
        self.counters.meshes_read += u32::from(read);
        self.meshes.insert(key, Entry { version, data });
    }

    /// The stored mesh of `key` made from a file of `version` (a glTF file's primitive).
    pub(super) fn derived_mesh(
        &mut self,
        key: &MeshKey,
        version: Version,
    ) -> Option<Arc<MeshData>> {
        let hit = self
            .meshes
            .get(key)
            .filter(|e| e.version.same_content(&version))
            .map(|e| Arc::clone(&e.data));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// The stored texture of `key` made from a file of `version` (a glTF file's image).
    pub(super) fn derived_texture(
        &mut self,
        key: &TextureKey,
        version: Version,
    ) -> Option<Arc<TextureData>> {
        let hit = self
            .textures
            .get(key)
            .filter(|e| e.version.same_content(&version))
            .map(|e| Arc::clone(&e.data));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// The stored texture of `key` if still current.
    pub(super) fn texture(
        &mut self,
        key: &TextureKey,
        stamp: Stamp,
        file: Option<FileIn<'_>>,
    ) -> Option<Arc<TextureData>> {
        let hit = current(&mut self.textures, key, stamp, file).map(|(_, d)| d);
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// Stores a texture of `version` (`read`: just read from its file).
    pub(super) fn put_texture(
        &mut self,
        key: TextureKey,
        version: Version,
        data: Arc<TextureData>,
        read: bool,
    ) {
        self.counters.images_read += u32::from(read);
        self.textures.insert(key, Entry { version, data });
    }

    /// The stored glTF file at `path` if still current.
    pub(super) fn model(
        &mut self,
        (path, roots): FileIn<'_>,
        stamp: Stamp,
    ) -> Option<(Version, Arc<ModelScene>)> {
        let hit = current(
            &mut self.models,
            &path.to_path_buf(),
            stamp,
            Some((path, roots)),
        );
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// Stores a glTF file just read, of `version`.
    pub(super) fn put_model(&mut self, path: PathBuf, version: Version, data: Arc<ModelScene>) {
        self.counters.models_read += 1;
        self.models.insert(path, Entry { version, data });
    }

    /// The object-level BVH of `key` built with `preset` from the mesh of `version`.
    pub(super) fn blas(
        &mut self,
        key: &MeshKey,
        preset: BuildPreset,
        version: Version,
    ) -> Option<Arc<BuiltMesh>> {
        let hit = self
            .blas
            .get(&(key.clone(), preset))
            .filter(|(v, _)| v.same_content(&version))
            .map(|(_, b)| Arc::clone(b));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    /// `data`, the texture of `key`, decoded to linear half floats
    /// (`TextureData::decoded_srgb`; `None` for a texture that is not 8-bit sRGB): the copy
    /// decoded before when `data` is the very texture it was decoded from (the store hands out the
    /// same `Arc` while a file's content is unchanged), else decoded now and kept.
    pub(super) fn decoded_texture(
        &mut self,
        key: &TextureKey,
        data: &Arc<TextureData>,
    ) -> Option<Arc<TextureData>> {
        if let Some((source, decoded)) = self.decoded.get(key) {
            if Arc::ptr_eq(source, data) {
                self.counters.reused += 1;
                return Some(Arc::clone(decoded));
            }
        }
        let decoded = Arc::new(data.decoded_srgb()?);
        self.counters.textures_decoded += 1;
        self.decoded
            .insert(key.clone(), (Arc::clone(data), Arc::clone(&decoded)));
        Some(decoded)
    }

    /// The words of `parts`, concatenated in order: the last concatenation when `parts` are the
    /// very textures it was made of, else made now and kept in its place.
    pub(super) fn texels(&mut self, parts: &[Arc<TextureData>]) -> Arc<[u32]> {
        if let Some((made_of, texels)) = &self.texels {
            if made_of.len() == parts.len()
                && made_of.iter().zip(parts).all(|(a, b)| Arc::ptr_eq(a, b))
            {
                self.counters.reused += 1;
                return Arc::clone(texels);
            }
        }
        let mut words = Vec::with_capacity(parts.iter().map(|p| p.words.len()).sum());
        for part in parts {
            words.extend_from_slice(&part.words);
        }
        let texels: Arc<[u32]> = words.into();
        self.counters.texel_concatenations += 1;
        self.texels = Some((parts.to_vec(), Arc::clone(&texels)));
        texels
    }

    /// Stores an object-level BVH just built.
    pub(super) fn put_blas(
        &mut self,
        key: MeshKey,
        preset: BuildPreset,
        version: Version,
        built: Arc<BuiltMesh>,
    ) {
        self.counters.blas_builds += 1;
        self.blas.insert((key, preset), (version, built));
    }
}
