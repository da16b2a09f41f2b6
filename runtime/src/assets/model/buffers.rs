//! The bytes behind a glTF document: buffers, buffer views and images, from the `.glb` binary
//! chunk, `data:` URIs (base64) or files relative to the glTF file.
//!
//! Invariants: buffer `i` of [`load`]'s result holds at least `buffers[i].byteLength` bytes;
//! [`view_bytes`] only returns ranges that lie inside their buffer. A referenced file that cannot
//! be read is [`AssetError::MissingFile`] naming it. Only relative paths (percent-decoded) and
//! `data:` URIs are followed; other schemes (`http:`, `file:`) are refused, and a path must stay
//! inside the glTF file's folder or an asset root (`assets::confine`: no absolute paths, drive
//! letters, backslashes, `..` or symlinks leading out), else [`AssetError::Escape`].

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use gltf::json;

use super::Ctx;
use crate::assets::confine::{self, AssetRoots, Search};
use crate::assets::{AssetError, GltfItem, UriProblem};

/// Loads every buffer of the document. The first buffer without a URI takes the `.glb` binary
/// chunk.
pub(super) fn load(
    root: &json::Root,
    mut blob: Option<Vec<u8>>,
    path: &Path,
    roots: &AssetRoots,
) -> Result<Vec<Vec<u8>>, AssetError> {
    let mut buffers = Vec::with_capacity(root.buffers.len());
    for (i, buffer) in root.buffers.iter().enumerate() {
        let item = GltfItem::Buffer(i);
        let data = match &buffer.uri {
            Some(uri) => read_uri(uri, path, roots, item)?.0,
            None => blob.take().ok_or_else(|| AssetError::Uri {
                path: path.to_owned(),
                item,
                uri: String::new(),
                problem: UriProblem::NoData,
            })?,
        };
        if (data.len() as u64) < buffer.byte_length.0 {
            return Err(AssetError::BufferTooShort {
                path: path.to_owned(),
                item,
                declared: buffer.byte_length.0,
                actual: data.len() as u64,
            });
        }
        buffers.push(data);
    }
    Ok(buffers)
}

/// The bytes of buffer view `index`, checked against its buffer.
pub(super) fn view_bytes<'a>(ctx: &Ctx<'a>, index: usize) -> Result<&'a [u8], AssetError> {
    let item = GltfItem::BufferView(index);
    let view = ctx
        .root
        .buffer_views
        .get(index)
        .ok_or_else(|| dangling(ctx, item))?;
    let data = ctx
        .buffers
        .get(view.buffer.value())
        .ok_or_else(|| dangling(ctx, item))?;
    let start = view.byte_offset.map_or(0, |o| o.0);
    let end = start.saturating_add(view.byte_length.0);
    usize::try_from(start)
        .ok()
        .zip(usize::try_from(end).ok())
        .and_then(|(s, e)| data.get(s..e))
        .ok_or(AssetError::AccessorOutOfRange {
            path: ctx.path.to_owned(),
            item,
            needed: end,
            available: data.len() as u64,
        })
}

/// The encoded bytes of image `index` and the name to use for it in errors: the image file for
/// an external image, `model.glb#images[i]` for an embedded one.
pub(super) fn image_bytes<'a>(
    ctx: &Ctx<'a>,
    index: usize,
) -> Result<(Cow<'a, [u8]>, PathBuf), AssetError> {
    let item = GltfItem::Image(index);
    let image = ctx
        .root
        .images
        .get(index)
        .ok_or_else(|| dangling(ctx, item))?;
    let embedded_label = || {
        let mut label = ctx.path.as_os_str().to_owned();
        label.push(format!("#images[{index}]"));
        PathBuf::from(label)
    };
    if let Some(view) = image.buffer_view {
        return Ok((
            Cow::Borrowed(view_bytes(ctx, view.value())?),
            embedded_label(),
        ));
    }
    let Some(uri) = &image.uri else {
        return Err(AssetError::InvalidGltf {
            path: ctx.path.to_owned(),
            problems: vec![(format!("images[{index}]"), json::validation::Error::Missing)],
        });
    };
    let (bytes, file) = read_uri(uri, ctx.path, ctx.roots, item)?;
    Ok((Cow::Owned(bytes), file.unwrap_or_else(embedded_label)))
}

/// An index the validator should have caught; reported, never panicked on.
pub(super) fn dangling(ctx: &Ctx<'_>, item: GltfItem) -> AssetError {
    AssetError::InvalidGltf {
        path: ctx.path.to_owned(),
        problems: vec![(item.to_string(), json::validation::Error::IndexOutOfBounds)],
    }
}

/// The files the buffers and images of the glTF file `gltf_path` (parsed: `root`) name, resolved
/// and confined as [`read_uri`] would read them; `data:` URIs, other schemes and refused paths
/// are left out (reading the model reports those).
pub(super) fn external_files(
    root: &json::Root,
    gltf_path: &Path,
    roots: &AssetRoots,
) -> Vec<PathBuf> {
    let folder = gltf_path.parent().unwrap_or_else(|| Path::new(""));
    let uris = root
        .buffers
        .iter()
        .filter_map(|b| b.uri.as_deref())
        .chain(root.images.iter().filter_map(|i| i.uri.as_deref()));
    let mut files = Vec::new();
    for uri in uris {
        if confine::has_scheme(uri) {
            continue;
        }
        let Some(relative) = percent_decode(uri) else {
            continue;
        };
        if let Ok(file) = confine::resolve(&relative, folder, roots, Search::BaseOnly) {
            if !files.contains(&file) {
                files.push(file);
            }
        }
    }
    files
}

/// The bytes a URI refers to, and the file it named (`None` for `data:` URIs).
fn read_uri(
    uri: &str,
    gltf_path: &Path,
    roots: &AssetRoots,
    item: GltfItem,
) -> Result<(Vec<u8>, Option<PathBuf>), AssetError> {
    let fail = |problem| AssetError::Uri {
        path: gltf_path.to_owned(),
        item,
        uri: uri.chars().take(64).collect(),
        problem,
    };
    if let Some(rest) = uri.strip_prefix("data:") {
        let (media, data) = rest
            .split_once(',')
            .ok_or_else(|| fail(UriProblem::BadBase64))?;
        if !media.ends_with(";base64") {
            return Err(fail(UriProblem::BadBase64));
        }
        let bytes = decode_base64(data).ok_or_else(|| fail(UriProblem::BadBase64))?;
        return Ok((bytes, None));
    }
    // `file:` URIs and drive letters are paths trying to leave the folder: `confine` refuses
    // them as escapes; any other scheme is one we do not fetch.
    let file_like = uri
        .get(..5)
        .is_some_and(|s| s.eq_ignore_ascii_case("file:"))
        || matches!(uri.as_bytes(), [d, b':', ..] if d.is_ascii_alphabetic());
    if confine::has_scheme(uri) && !file_like {
        return Err(fail(UriProblem::UnsupportedScheme));
    }
    let relative = percent_decode(uri).ok_or_else(|| fail(UriProblem::BadPercentEncoding))?;
    let folder = gltf_path.parent().unwrap_or_else(|| Path::new(""));
    let file = confine::resolve(&relative, folder, roots, Search::BaseOnly).map_err(|problem| {
        AssetError::Escape {
            path: gltf_path.to_owned(),
            item: Some(item),
            written: uri.chars().take(200).collect(),
            problem: Box::new(problem),
        }
    })?;
    match confine::read(&file, roots) {
        Ok(bytes) => Ok((bytes, Some(file))),
        Err(source) => Err(AssetError::MissingFile {
            path: gltf_path.to_owned(),
            item,
            file,
            source,
        }),
    }
}

/// Decodes `%xx` escapes; `None` for a malformed escape or a result that is not UTF-8.
pub(crate) fn percent_decode(s: &str) -> Option<String> {
    if !s.contains('%') {
        return Some(s.to_owned());
    }
    let mut out = Vec::with_capacity(s.len());
    let mut bytes = s.bytes();
    while let Some(b) = bytes.next() {
        if b == b'%' {
            let hi = hex_value(bytes.next()?)?;
            let lo = hex_value(bytes.next()?)?;
            out.push(hi << 4 | lo);
        } else {
            out.push(b);
        }
    }
    String::from_utf8(out).ok()
}

fn hex_value(c: u8) -> Option<u8> {
    match c {
        b'0'..=b'9' => Some(c - b'0'),
        b'a'..=b'f' => Some(c - b'a' + 10),
        b'A'..=b'F' => Some(c - b'A' + 10),
        _ => None,
    }
}

/// Decodes base64 (standard or URL-safe alphabet, padding optional); `None` on any other
/// character or an impossible length.
pub(crate) fn decode_base64(s: &str) -> Option<Vec<u8>> {
    let s = s.trim_end_matches('=');
    if s.len() % 4 == 1 {
        return None;
    }
    let mut out = Vec::with_capacity(s.len() / 4 * 3 + 2);
    let (mut acc, mut bits) = (0u32, 0u32);
    for c in s.bytes() {
        let v = match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' | b'-' => 62,
            b'/' | b'_' => 63,
            _ => return None,
        };
        acc = (acc << 6) | u32::from(v);
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    Some(out)
}
