//! The asset store: what loading and BVH building produced, kept across rebuilds of a scene's
//! entities so that a recompiled program (`Renderer::replace_kernel`) or a reloaded scene reuses
//! every mesh, texture, glTF file and object-level BVH whose inputs did not change.
//!
//! An entry is keyed by what the scene names (the same keys as the per-build [`AssetCache`]: a
//! file's resolved path, a procedural mesh's parameters, a solid colour) and stamped with the
//! file's length and modification time ([`Stamp`]); a file whose stamp changed is read again, as
//! `make` and `cargo` decide. Object-level BVHs are keyed by mesh, stamp and builder preset.
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
use crate::assets::model::ModelScene;
use crate::assets::{MeshData, TextureData};

/// What identifies a file's version without reading it: its length and modification time
/// (`None` for data that comes from no file, such as a procedural mesh).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Stamp(Option<(u64, Option<SystemTime>)>);

impl Stamp {
    /// The stamp of data that comes from no file.
    pub const NONE: Stamp = Stamp(None);

    /// The stamp of the file at `path` now (a file that cannot be read gets a stamp no read
    /// file has, so it is never taken from the store).
    pub fn of(path: &Path) -> Stamp {
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
    /// `ATTRIBUTE` records of its slots.
    pub attributes: Vec<[u32; 4]>,
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
    /// Lookups answered from the store.
    pub reused: u32,
}

/// Assets and object-level BVHs kept across entity builds (see the module docs).
#[derive(Debug, Default)]
pub struct AssetStore {
    meshes: HashMap<MeshKey, (Stamp, Arc<MeshData>)>,
    textures: HashMap<TextureKey, (Stamp, Arc<TextureData>)>,
    models: HashMap<PathBuf, (Stamp, Arc<ModelScene>)>,
    blas: HashMap<(MeshKey, BuildPreset), (Stamp, Arc<BuiltMesh>)>,
    counters: StoreCounters,
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

    pub(super) fn mesh(&mut self, key: &MeshKey, stamp: Stamp) -> Option<Arc<MeshData>> {
        let hit = self
            .meshes
            .get(key)
            .filter(|(s, _)| *s == stamp)
            .map(|(_, d)| Arc::clone(d));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    pub(super) fn put_mesh(&mut self, key: MeshKey, stamp: Stamp, data: Arc<MeshData>, read: bool) {
        self.counters.meshes_read += u32::from(read);
        self.meshes.insert(key, (stamp, data));
    }

    pub(super) fn texture(&mut self, key: &TextureKey, stamp: Stamp) -> Option<Arc<TextureData>> {
        let hit = self
            .textures
            .get(key)
            .filter(|(s, _)| *s == stamp)
            .map(|(_, d)| Arc::clone(d));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    pub(super) fn put_texture(
        &mut self,
        key: TextureKey,
        stamp: Stamp,
        data: Arc<TextureData>,
        read: bool,
    ) {
        self.counters.images_read += u32::from(read);
        self.textures.insert(key, (stamp, data));
    }

    pub(super) fn model(&mut self, path: &Path, stamp: Stamp) -> Option<Arc<ModelScene>> {
        let hit = self
            .models
            .get(path)
            .filter(|(s, _)| *s == stamp)
            .map(|(_, d)| Arc::clone(d));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    pub(super) fn put_model(&mut self, path: PathBuf, stamp: Stamp, data: Arc<ModelScene>) {
        self.counters.models_read += 1;
        self.models.insert(path, (stamp, data));
    }

    pub(super) fn blas(
        &mut self,
        key: &MeshKey,
        preset: BuildPreset,
        stamp: Stamp,
    ) -> Option<Arc<BuiltMesh>> {
        let hit = self
            .blas
            .get(&(key.clone(), preset))
            .filter(|(s, _)| *s == stamp)
            .map(|(_, b)| Arc::clone(b));
        self.counters.reused += u32::from(hit.is_some());
        hit
    }

    pub(super) fn put_blas(
        &mut self,
        key: MeshKey,
        preset: BuildPreset,
        stamp: Stamp,
        built: Arc<BuiltMesh>,
    ) {
        self.counters.blas_builds += 1;
        self.blas.insert((key, preset), (stamp, built));
    }
}
