//! Packing the scene's role-struct instances into the `params` words.
//!
//! Every instance is packed with the compiler's own `layout::pack_into`, so the words are exactly
//! where the generated loader functions read them; this file only decides where each instance
//! starts (a multiple of 4 words, i.e. 16 bytes, the largest alignment of any field) and resolves
//! `mesh`/`texture` handles to the word offsets of their records.
//!
//! Invariants: an instance occupies `layout(ty).size / 4` words from its offset; identical instances
//! of one struct (same words) are stored once; a handle the records do not know is an error, never
//! a silent 0.

use std::collections::HashMap;

use rtc_compiler::layout::{self, Handles};
use rtc_compiler::sema::hir::{Instance, MeshAsset, Program, StructId, TextureAsset};
use rtc_compiler::sema::types::Type;

use super::assets_cache::{MeshKey, TextureKey};
use super::SceneError;

/// Instances start at multiples of this many words.
pub(super) const INSTANCE_ALIGN_WORDS: usize = 4;

/// Resolves handles to record offsets, remembering whether one was missing.
struct RecordHandles<'a> {
    meshes: &'a HashMap<MeshKey, u32>,
    textures: &'a HashMap<TextureKey, u32>,
    missing: Option<&'static str>,
}

impl Handles for RecordHandles<'_> {
    fn mesh(&mut self, asset: &MeshAsset) -> u32 {
        match self.meshes.get(&MeshKey::of(asset)) {
            Some(&offset) => offset,
            None => {
                self.missing = Some("mesh");
                0
            }
        }
    }

    fn texture(&mut self, asset: &TextureAsset) -> u32 {
        match self.textures.get(&TextureKey::of(asset)) {
            Some(&offset) => offset,
            None => {
                self.missing = Some("texture");
                0
            }
        }
    }
}

/// The `params` words under construction.
#[derive(Default)]
pub(super) struct ParamsBuilder {
    pub words: Vec<u32>,
    pub mesh_records: HashMap<MeshKey, u32>,
    pub texture_records: HashMap<TextureKey, u32>,
    dedup: HashMap<(StructId, Vec<u32>), u32>,
}

impl ParamsBuilder {
    /// Current length, as a word offset.
    pub fn offset(&self) -> Result<u32, SceneError> {
        u32::try_from(self.words.len()).map_err(|_| SceneError::TooLarge {
            what: "parameter words",
            count: self.words.len() as u64,
        })
    }

    /// Appends raw words (a record or a table, laid out by `gpu_types::record`); returns their
    /// offset.
    pub fn push_words(&mut self, words: &[u32]) -> Result<u32, SceneError> {
        let at = self.offset()?;
        self.words.extend_from_slice(words);
        Ok(at)
    }

    /// Packs `inst` (at a 4-word boundary, or where an identical one already is); returns its
    /// offset and its length in words.
    pub fn push_instance(
        &mut self,
        program: &Program,
        inst: &Instance,
    ) -> Result<(u32, u32), SceneError> {
        let words = pack_instance(program, inst, &self.mesh_records, &self.texture_records)?;
        let len = words.len() as u32;
        let key = (inst.struct_id, words);
        if let Some(&at) = self.dedup.get(&key) {
            return Ok((at, len));
        }
        let aligned = self.words.len().next_multiple_of(INSTANCE_ALIGN_WORDS);
        self.words.resize(aligned, 0);
        let at = self.offset()?;
        self.words.extend_from_slice(&key.1);
        self.dedup.insert(key, at);
        Ok((at, len))
    }
}

/// The type of a struct in the program's type table.
pub(super) fn struct_type(
    program: &Program,
    s: StructId,
) -> Result<rtc_compiler::sema::types::TypeId, SceneError> {
    program
        .types
        .iter()
        .find(|(_, t)| *t == Type::Struct(s))
        .map(|(id, _)| id)
        .ok_or_else(|| SceneError::NoStructType {
            name: program.structs[s].name.clone(),
        })
}

/// The words of one instance, exactly `layout(ty).size / 4` of them.
pub(super) fn pack_instance(
    program: &Program,
    inst: &Instance,
    meshes: &HashMap<MeshKey, u32>,
    textures: &HashMap<TextureKey, u32>,
) -> Result<Vec<u32>, SceneError> {
    let ty = struct_type(program, inst.struct_id)?;
    let mut out = vec![0u32; (layout::layout(program, ty).size / 4) as usize];
    let mut handles = RecordHandles {
        meshes,
        textures,
        missing: None,
    };
    let fields = &program.structs[inst.struct_id].fields;
    for ((field, value), offset) in fields
        .iter()
        .zip(&inst.fields)
        .zip(layout::field_offsets(program, ty))
    {
        layout::pack_into(
            program,
            field.ty,
            value,
            &mut out,
            (offset / 4) as usize,
            &mut handles,
        );
    }
    match handles.missing {
        Some(what) => Err(SceneError::UnresolvedHandle { what }),
        None => Ok(out),
    }
}
