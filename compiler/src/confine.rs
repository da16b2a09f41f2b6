//! Where assets may be read from: the paths a scene (`load_mesh`, `load_image`, `model`) or a
//! glTF file (buffer and image URIs) names are confined to the referring file's folder and the
//! folders the user names (`--asset-root DIR`, [`AssetRoots`]).
//!
//! The rules live in the compiler because two readers must apply the same ones: the runtime,
//! which reads every asset (`rtc_runtime::assets` re-exports this module), and the link step,
//! which reads a `model` file's glTF metadata to link only what it holds (`link::model`). No
//! GPU is involved.
//!
//! # Rules (`resolve`)
//!
//! - The path as written must be relative, with `/` between folders: an absolute path, a drive
//!   letter (`C:`), a URI scheme (`file:`, …), a backslash or an empty path is refused before
//!   anything is looked up ([`PathProblem`]). glTF URIs are percent-decoded first, so `%2e%2e`
//!   is `..` and `%2F` a `/`.
//! - It is resolved against the referring file's folder (`base`); for scene paths, when no file is
//!   there, against each asset root in order (so `--asset-root shared/models` lets a scene write
//!   `load_mesh("bunny.obj")`).
//! - The file found is canonicalised (every symlink and `..` followed) and must lie inside the
//!   canonicalised base folder or one of the canonicalised asset roots; otherwise
//!   [`PathProblem::Outside`]. So `..` may move around inside an allowed folder but never out of
//!   it, and a symlink inside the folder that points outside is refused. The canonical path is
//!   what is then read.
//! - A path that names no existing file resolves to its candidate in the base folder, whose read
//!   then fails with the usual "cannot be read" error naming it (nothing outside is revealed:
//!   only existence inside the candidate location is probed).
//!
//! # Assets held in memory
//!
//! [`AssetRoots::in_memory`] makes every asset come from a [`MemoryFiles`] set instead of the
//! disk (the renderer in a web page, whose assets were fetched from URLs or dropped by the user).
//! The same rules hold, applied to the paths alone: the written path is checked as above, joined
//! to the base folder and normalised lexically (`a/../` folded), and must then lie inside the base
//! folder or a root, with no `..` left in front; there are no symlinks to follow. [`read`] reads a
//! resolved path from wherever the roots say, so the one reader code serves both.

use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

use std::fmt;

use crate::source::MemoryFiles;

/// The folders besides the referring file's own that assets may be read from (the CLI's
/// `--asset-root`, repeatable), and whether they are read from the disk or from files held in
/// memory ([`AssetRoots::in_memory`]). Roots that do not exist contain nothing.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AssetRoots {
    roots: Vec<PathBuf>,
    memory: Option<Arc<MemoryFiles>>,
}

impl AssetRoots {
    /// No extra folder: assets only from the referring file's folder.
    pub fn none() -> AssetRoots {
        AssetRoots::default()
    }

    /// These folders, in the order they are searched.
    pub fn new(roots: impl IntoIterator<Item = PathBuf>) -> AssetRoots {
        AssetRoots {
            roots: roots.into_iter().collect(),
            memory: None,
        }
    }

    /// Every asset from `files` rather than the disk (see the [module docs](self)), under the same
    /// confinement; no extra folder.
    pub fn in_memory(files: Arc<MemoryFiles>) -> AssetRoots {
        AssetRoots {
            roots: Vec::new(),
            memory: Some(files),
        }
    }

    /// The files assets come from when they are held in memory (`None`: the disk).
    pub fn memory(&self) -> Option<&MemoryFiles> {
        self.memory.as_deref()
    }

    /// The folders, as given.
    pub fn folders(&self) -> &[PathBuf] {
        &self.roots
    }
}

/// Why a path named by a scene or a glTF file may not be read (see the [module docs](self)).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathProblem {
    /// An empty path.
    Empty,
    /// An absolute path (`/etc/passwd`).
    Absolute,
    /// A Windows drive letter (`C:`).
    DriveLetter,
    /// A backslash (`..\x`): folders are separated by `/`.
    Backslash,
    /// A URI with a scheme other than `data:` (`file:///…`, `http://…`).
    Uri,
    /// The file found lies outside every allowed folder (after `..` and symlinks are followed).
    Outside {
        /// The file, canonicalised.
        resolved: PathBuf,
        /// The folders it may be in: the referring file's, then the asset roots.
        allowed: Vec<PathBuf>,
    },
}

impl fmt::Display for PathProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty => f.write_str("is empty"),
            Self::Absolute => f.write_str("is an absolute path"),
            Self::DriveLetter => f.write_str("starts with a drive letter"),
            Self::Backslash => f.write_str("contains a backslash (separate folders with `/`)"),
            Self::Uri => f.write_str("is a URI (only relative paths and data: URIs are read)"),
            Self::Outside { resolved, .. } => write!(
                f,
                "leads to `{}` (following `..` and symbolic links), outside the allowed folders",
                resolved.display()
            ),
        }
    }
}

impl PathProblem {
    /// The folders a path must stay in, for a help line (empty for problems of the path's form).
    pub fn allowed(&self) -> &[PathBuf] {
        match self {
            Self::Outside { allowed, .. } => allowed,
            _ => &[],
        }
    }
}

/// Whether a path that is not found in the base folder is looked for in the asset roots too.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// Only the base folder (glTF URIs: the specification resolves them against the file).
    BaseOnly,
    /// The base folder, then each root (scene paths).
    BaseThenRoots,
}

/// Resolves `written` (already percent-decoded for a URI) against `base` and checks that it stays
/// inside `base` or a root (see the [module docs](self)). Returns the path to read.
pub fn resolve(
    written: &str,
    base: &Path,
    roots: &AssetRoots,
    search: Search,
) -> Result<PathBuf, PathProblem> {
    check_written(written)?;
    if let Some(files) = &roots.memory {
        return resolve_in_memory(files, written, base, roots, search);
    }
    let base = if base.as_os_str().is_empty() {
        Path::new(".")
    } else {
        base
    };
    let first = base.join(written);
    let mut candidates = vec![first.clone()];
    if search == Search::BaseThenRoots {
        candidates.extend(roots.roots.iter().map(|r| r.join(written)));
    }
    let Some(found) = candidates
        .iter()
        .find_map(|c| std::fs::canonicalize(c).ok())
    else {
        return Ok(first);
    };
    let allowed: Vec<PathBuf> = std::iter::once(base)
        .chain(roots.roots.iter().map(PathBuf::as_path))
        .filter_map(|r| std::fs::canonicalize(r).ok())
        .collect();
    if allowed.iter().any(|r| found.starts_with(r)) {
        Ok(found)
    } else {
        Err(PathProblem::Outside {
            resolved: found,
            allowed: std::iter::once(base.to_path_buf())
                .chain(roots.roots.iter().cloned())
                .collect(),
        })
    }
}

/// [`resolve`] over files held in memory: lexical, with the same answers (see the module docs).
fn resolve_in_memory(
    files: &MemoryFiles,
    written: &str,
    base: &Path,
    roots: &AssetRoots,
    search: Search,
) -> Result<PathBuf, PathProblem> {
    let first = MemoryFiles::normalize(&base.join(written));
    let mut candidates = vec![first.clone()];
    if search == Search::BaseThenRoots {
        candidates.extend(
            roots
                .roots
                .iter()
                .map(|r| MemoryFiles::normalize(&r.join(written))),
        );
    }
    let found = candidates
        .into_iter()
        .find(|c| files.is_file(c))
        .unwrap_or_else(|| first.clone());
    let inside = |folder: &Path| {
        let folder = MemoryFiles::normalize(folder);
        found.starts_with(&folder)
            && !found
                .components()
                .any(|c| matches!(c, Component::ParentDir | Component::RootDir))
    };
    if std::iter::once(base)
        .chain(roots.roots.iter().map(PathBuf::as_path))
        .any(inside)
    {
        Ok(found)
    } else {
        Err(PathProblem::Outside {
            resolved: found,
            allowed: std::iter::once(base.to_path_buf())
                .chain(roots.roots.iter().cloned())
                .collect(),
        })
    }
}

/// Reads a file [`resolve`] returned, from the disk or from the files in memory, as `roots` say.
/// A file missing from memory is an [`std::io::ErrorKind::NotFound`] error saying so.
pub fn read(path: &Path, roots: &AssetRoots) -> std::io::Result<Vec<u8>> {
    match &roots.memory {
        Some(files) => files.get(path).map(<[u8]>::to_vec).ok_or_else(|| {
            std::io::Error::new(
                std::io::ErrorKind::NotFound,
                "not among the files given (in memory)",
            )
        }),
        None => std::fs::read(path),
    }
}

/// The checks on the path as written, before the file system is asked anything.
fn check_written(written: &str) -> Result<(), PathProblem> {
    if written.is_empty() {
        return Err(PathProblem::Empty);
    }
    if written.contains('\\') {
        return Err(PathProblem::Backslash);
    }
    if matches!(written.as_bytes(), [d, b':', ..] if d.is_ascii_alphabetic()) {
        return Err(PathProblem::DriveLetter);
    }
    if has_scheme(written) {
        return Err(PathProblem::Uri);
    }
    let path = Path::new(written);
    if written.starts_with('/')
        || path.is_absolute()
        || path
            .components()
            .any(|c| matches!(c, Component::RootDir | Component::Prefix(_)))
    {
        return Err(PathProblem::Absolute);
    }
    Ok(())
}

/// Whether a string starts with a URI scheme (`[A-Za-z][A-Za-z0-9+.-]*:`).
pub fn has_scheme(uri: &str) -> bool {
    let Some((scheme, _)) = uri.split_once(':') else {
        return false;
    };
    let mut chars = scheme.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '.' | '-'))
}

/// Resolves a scene's asset path: `compiled` is the compiler's path (the written string joined to
/// the scene's folder `scene_dir`, so one that does not start with the folder was written
/// absolute). On failure, the path as written and what is wrong with it.
pub fn resolve_scene_path(
    compiled: &Path,
    scene_dir: &Path,
    roots: &AssetRoots,
) -> Result<PathBuf, (String, PathProblem)> {
    let written = if scene_dir.as_os_str().is_empty() {
        Some(compiled).filter(|p| !p.has_root())
    } else {
        compiled.strip_prefix(scene_dir).ok()
    };
    let Some(written) = written else {
        return Err((compiled.display().to_string(), PathProblem::Absolute));
    };
    let written = written.to_string_lossy();
    resolve(&written, scene_dir, roots, Search::BaseThenRoots)
        .map_err(|problem| (written.chars().take(200).collect(), problem))
}
