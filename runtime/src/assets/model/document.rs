//! glTF bytes → validated `gltf::json::Root` (plus the `.glb` binary chunk).
//!
//! Invariants of the returned root: it passed `gltf-json`'s validator, so every index in it is in
//! range, every `Checked` value is `Valid`, and every required extension is one we enabled.
//!
//! One rule of `gltf-json`'s validator is relaxed to the specification's: an accessor without a
//! `bufferView` and without `sparse` is all zeros, not an error (`viewless_accessor`).
//!
//! Two things are done here and not left to the `gltf` crate, because it would panic:
//! - The `.glb` container is split by [`split_glb`], which checks every length against the file
//!   (`gltf`'s `Glb::from_slice` subtracts the header size from the declared length unchecked).
//! - Before validating, [`precheck`] makes sure each primitive's `POSITION` accessor index is in
//!   range: `gltf-json`'s primitive validation hook indexes `accessors` with it unchecked.

use std::path::Path;

use gltf::json::{self, validation::Checked, validation::Validate};

use crate::assets::{AssetError, GlbProblem};
use json::validation::Error as ValidationError;

/// The glTF binary container's magic bytes.
const GLB_MAGIC: &[u8; 4] = b"glTF";
const CHUNK_JSON: u32 = u32::from_le_bytes(*b"JSON");
const CHUNK_BIN: u32 = u32::from_le_bytes(*b"BIN\0");

/// Parses and validates a `.gltf` (JSON) or `.glb` (binary container) file's bytes.
pub(super) fn parse(
    bytes: &[u8],
    path: &Path,
) -> Result<(json::Root, Option<Vec<u8>>), AssetError> {
    let (json_bytes, blob) = if bytes.starts_with(GLB_MAGIC) {
        split_glb(bytes).map_err(|problem| AssetError::Glb {
            path: path.to_owned(),
            problem,
        })?
    } else {
        (bytes, None)
    };
    let json_bytes = json_bytes
        .strip_prefix(b"\xEF\xBB\xBF")
        .unwrap_or(json_bytes);
    let first = json_bytes.iter().find(|b| !b.is_ascii_whitespace());
    if first != Some(&b'{') {
        return Err(AssetError::UnsupportedFormat {
            path: path.to_owned(),
            found: "neither a .glb container nor a JSON object".to_owned(),
        });
    }
    let root: json::Root =
        json::deserialize::from_slice(json_bytes).map_err(|source| AssetError::BadJson {
            path: path.to_owned(),
            source,
        })?;
    let mut problems = precheck(&root);
    if problems.is_empty() {
        root.validate(&root, json::Path::new, &mut |at, error| {
            let at = at().to_string();
            // `gltf-json` requires a `bufferView` on an accessor without `sparse`, but the
            // specification says such an accessor is zeros (`accessor.rs` reads it so).
            if !viewless_accessor(&at, &error) {
                problems.push((at, error));
            }
        });
    }
    if !problems.is_empty() {
        return Err(AssetError::InvalidGltf {
            path: path.to_owned(),
            problems,
        });
    }
    Ok((root, blob.map(<[u8]>::to_vec)))
}

/// Whether a validation problem is `gltf-json`'s refusal of an accessor without a `bufferView`
/// (`accessors[i].bufferView` missing), which glTF 2.0 allows: "When undefined, the accessor
/// MUST be initialized with zeros".
fn viewless_accessor(at: &str, error: &ValidationError) -> bool {
    matches!(error, ValidationError::Missing)
        && at
            .strip_prefix("accessors[")
            .and_then(|rest| rest.strip_suffix("].bufferView"))
            .is_some_and(|index| index.bytes().all(|b| b.is_ascii_digit()))
}

/// The problems `gltf-json`'s validator would panic on instead of reporting.
fn precheck(root: &json::Root) -> Vec<(String, ValidationError)> {
    let mut problems = Vec::new();
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let position = primitive
                .attributes
                .get(&Checked::Valid(json::mesh::Semantic::Positions));
            if let Some(index) = position {
                if index.value() >= root.accessors.len() {
                    problems.push((
                        format!("meshes[{m}].primitives[{p}].attributes.POSITION"),
                        ValidationError::IndexOutOfBounds,
                    ));
                }
            }
        }
    }
    problems
}

/// Splits a `.glb` file into its JSON chunk and its first binary chunk, checking every length.
/// Chunks of unknown type are skipped, as the specification asks.
pub(super) fn split_glb(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), GlbProblem> {
    let word = |at: usize| -> Option<u32> {
        let b = bytes.get(at..at.checked_add(4)?)?;
        Some(u32::from_le_bytes(b.try_into().ok()?))
    };
    let (Some(version), Some(declared)) = (word(4), word(8)) else {
        return Err(GlbProblem::NoHeader(bytes.len()));
    };
    if version != 2 {
        return Err(GlbProblem::Version(version));
    }
    let declared = declared as usize;
    let body = bytes
        .get(12..declared)
        .filter(|_| declared <= bytes.len())
        .ok_or(GlbProblem::Truncated {
            declared: declared as u64,
            actual: bytes.len() as u64,
        })?;

    let mut json = None;
    let mut bin = None;
    let mut at = 0usize;
    let mut index = 0usize;
    while at < body.len() {
        let header = |k: usize| -> Option<u32> {
            let start = at.checked_add(4 * k)?;
            let b = body.get(start..start.checked_add(4)?)?;
            Some(u32::from_le_bytes(b.try_into().ok()?))
        };
        let (Some(length), Some(kind)) = (header(0), header(1)) else {
            return Err(GlbProblem::ChunkTooLong {
                index,
                declared: 8,
                available: (body.len() - at) as u64,
            });
        };
        let start = at + 8;
        let data = start
            .checked_add(length as usize)
            .and_then(|end| body.get(start..end))
            .ok_or(GlbProblem::ChunkTooLong {
                index,
                declared: u64::from(length),
                available: body.len().saturating_sub(start) as u64,
            })?;
        match (index, kind) {
            (0, CHUNK_JSON) => json = Some(data),
            (0, _) => return Err(GlbProblem::NoJsonChunk),
            (_, CHUNK_BIN) if bin.is_none() => bin = Some(data),
            _ => {}
        }
        // The declared length includes the chunk's padding to 4 bytes.
        at = start + data.len();
        index += 1;
    }
    let json = json.ok_or(GlbProblem::NoJsonChunk)?;
    Ok((json, bin))
}
