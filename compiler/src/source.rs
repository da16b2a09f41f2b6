//! Source files and spans.
//!
//! Every file the compiler reads (user sources, stdlib modules, the framework kernel) is added to one
//! [`SourceMap`] and gets a [`FileId`]. A [`Span`] is a byte range inside one file. Spans are the only way
//! diagnostics and lowered IR refer back to source text.
//!
//! Invariants:
//! - `Span::lo <= Span::hi <= len(file)`, and both fall on UTF-8 character boundaries of the file's text
//!   (the lexer only produces such spans; [`SourceMap::line_col`] tolerates any value anyway).
//! - A `FileId` is an index into the map that created it and is never reused.
//! - Line and column lookups take time independent of the file's size (a binary search over line
//!   starts, and a character count of at most [`CHAR_BLOCK`] bytes), so reporting many diagnostics
//!   on one very long line stays linear.
//!
//! [`MemoryFiles`] is a file set held in memory (the compiler in WebAssembly, which has no file
//! system): given as [`crate::driver::Options::memory`], every file the compiler would read (roots,
//! imports, the standard library, registry files, `model` files) is looked up in it instead.

use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// Index of a file in a [`SourceMap`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct FileId(pub u32);

/// A byte range `lo..hi` in one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// The file the range is in.
    pub file: FileId,
    /// First byte.
    pub lo: u32,
    /// One past the last byte.
    pub hi: u32,
}

impl Span {
    /// A span covering `lo..hi` of `file`.
    pub fn new(file: FileId, lo: u32, hi: u32) -> Span {
        Span { file, lo, hi }
    }

    /// The smallest span covering both (which must be in the same file; otherwise `self` is returned).
    pub fn to(self, other: Span) -> Span {
        if self.file != other.file {
            return self;
        }
        Span {
            file: self.file,
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// An empty span at the end of this one.
    pub fn end(self) -> Span {
        Span {
            file: self.file,
            lo: self.hi,
            hi: self.hi,
        }
    }

    /// Byte range as `usize`s, for slicing the file's text.
    pub fn range(self) -> std::ops::Range<usize> {
        self.lo as usize..self.hi as usize
    }
}

/// Characters are counted from checkpoints this many bytes apart (see [`SourceFile::char_index`]).
pub const CHAR_BLOCK: usize = 512;

/// One source file: its display name, its path on disk (if any) and its text.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// Name shown in diagnostics (a path relative to the working directory, or `std/…` for stdlib files).
    pub name: String,
    /// Where the file was read from, if it came from disk.
    pub path: Option<PathBuf>,
    /// The text.
    pub text: String,
    line_starts: Vec<u32>,
    /// `char_starts[k]`: the number of characters that start in the first `k * CHAR_BLOCK` bytes
    /// (empty for an ASCII text, where characters are bytes).
    char_starts: Vec<u32>,
    /// Where the file starts in the one address space shared by all files of the map (see
    /// [`SourceMap::to_global`]).
    base: u32,
}

impl SourceFile {
    /// Byte offsets of the first byte of each line.
    pub fn line_starts(&self) -> &[u32] {
        &self.line_starts
    }

    /// The number of characters that start before byte `offset` (clamped to the text), counted from
    /// the nearest checkpoint: at most [`CHAR_BLOCK`] bytes are looked at.
    pub fn char_index(&self, offset: usize) -> usize {
        let offset = offset.min(self.text.len());
        if self.char_starts.is_empty() {
            return offset;
        }
        let block = offset / CHAR_BLOCK;
        let before = self.char_starts.get(block).copied().unwrap_or(0) as usize;
        before + count_char_starts(&self.text.as_bytes()[block * CHAR_BLOCK..offset])
    }

    /// The 0-based line of byte `offset` (clamped to the text).
    pub fn line_index(&self, offset: usize) -> usize {
        let offset = offset.min(self.text.len()) as u32;
        match self.line_starts.binary_search(&offset) {
            Ok(l) => l,
            Err(l) => l - 1,
        }
    }

    /// The byte range of 0-based line `line`, with its line break; `None` past the last line.
    pub fn line_range(&self, line: usize) -> Option<std::ops::Range<usize>> {
        let start = *self.line_starts.get(line)? as usize;
        let end = self
            .line_starts
            .get(line + 1)
            .map(|&e| e as usize)
            .unwrap_or(self.text.len());
        Some(start..end)
    }
}

/// Bytes that start a UTF-8 character (all but continuation bytes `0b10xx_xxxx`).
fn count_char_starts(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b & 0xC0) != 0x80).count()
}

/// All files of one compilation.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// Adds a file and returns its id.
    pub fn add(
        &mut self,
        name: impl Into<String>,
        path: Option<PathBuf>,
        text: impl Into<String>,
    ) -> FileId {
        let text = text.into();
        let mut line_starts = vec![0u32];
        for (i, b) in text.bytes().enumerate() {
            if b == b'\n' {
                line_starts.push(i as u32 + 1);
            }
        }
        let char_starts = if text.is_ascii() {
            Vec::new()
        } else {
            text.as_bytes()
                .chunks(CHAR_BLOCK)
                .scan(0u32, |n, chunk| {
                    let before = *n;
                    *n += count_char_starts(chunk) as u32;
                    Some(before)
                })
                .collect()
        };
        let id = FileId(self.files.len() as u32);
        let base = self
            .files
            .last()
            .map(|f| f.base.saturating_add(f.text.len() as u32).saturating_add(1))
            .unwrap_or(0);
        self.files.push(SourceFile {
            name: name.into(),
            path,
            text,
            line_starts,
            char_starts,
            base,
        });
        id
    }

    /// The file with this id.
    ///
    /// # Panics
    /// If the id did not come from this map (a compiler bug, never a user error).
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    /// All files, in the order they were added.
    pub fn files(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files
            .iter()
            .enumerate()
            .map(|(i, f)| (FileId(i as u32), f))
    }

    /// The id of the file read from `path`, if it was added.
    pub fn find_path(&self, path: &Path) -> Option<FileId> {
        self.files()
            .find(|(_, f)| f.path.as_deref() == Some(path))
            .map(|(id, _)| id)
    }

    /// Number of files.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    /// Whether no file was added.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// 1-based line and column (in characters) of a byte offset. Offsets past the end clamp to the end.
    pub fn line_col(&self, file: FileId, offset: u32) -> (usize, usize) {
        let f = self.get(file);
        let offset = (offset as usize).min(f.text.len());
        let line = f.line_index(offset);
        let start = f.line_starts[line] as usize;
        let mut col_start = offset;
        while col_start > start && !f.text.is_char_boundary(col_start) {
            col_start -= 1;
        }
        let col = f.char_index(col_start) - f.char_index(start);
        (line + 1, col + 1)
    }

    /// A span as one `(start, end)` range of an address space shared by all files of this map, so that
    /// spans can be stored where there is no room for a file id (naga's arenas) and mapped back with
    /// [`SourceMap::from_global`].
    pub fn to_global(&self, span: Span) -> (u32, u32) {
        let base = self
            .files
            .get(span.file.0 as usize)
            .map(|f| f.base)
            .unwrap_or(0);
        (base.saturating_add(span.lo), base.saturating_add(span.hi))
    }

    /// The span of a global range made by [`SourceMap::to_global`]; `None` if it falls in no file.
    pub fn from_global(&self, start: u32, end: u32) -> Option<Span> {
        let idx = match self.files.binary_search_by_key(&start, |f| f.base) {
            Ok(i) => i,
            Err(0) => return None,
            Err(i) => i - 1,
        };
        let f = &self.files[idx];
        let len = f.text.len() as u32;
        let lo = start - f.base;
        if lo > len {
            return None;
        }
        Some(Span {
            file: FileId(idx as u32),
            lo,
            hi: end.saturating_sub(f.base).clamp(lo, len),
        })
    }

    /// The text a span covers (empty if the span is out of range).
    pub fn snippet(&self, span: Span) -> &str {
        self.get(span.file).text.get(span.range()).unwrap_or("")
    }
}

/// Files held in memory, by path: what the compiler reads instead of the disk when
/// [`crate::driver::Options::memory`] is set.
///
/// Paths are normalised lexically ([`MemoryFiles::normalize`]: `.` dropped, `a/../` folded, `\\`
/// kept as written) both when a file is added and when it is looked up, so `examples/hello/./scene.rt`
/// and `examples/hello/scene.rt` are one file. Nothing here touches the file system. A folder exists
/// when some file lies under it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MemoryFiles {
    files: BTreeMap<PathBuf, Arc<[u8]>>,
}

impl MemoryFiles {
    /// An empty set.
    pub fn new() -> MemoryFiles {
        MemoryFiles::default()
    }

    /// Adds (or replaces) the file at `path`.
    pub fn insert(&mut self, path: impl AsRef<Path>, bytes: impl Into<Vec<u8>>) {
        let bytes: Vec<u8> = bytes.into();
        self.files
            .insert(MemoryFiles::normalize(path.as_ref()), bytes.into());
    }

    /// The bytes of the file at `path`, if there is one.
    pub fn get(&self, path: &Path) -> Option<&[u8]> {
        self.files
            .get(&MemoryFiles::normalize(path))
            .map(|b| &b[..])
    }

    /// Whether a file is at `path`.
    pub fn is_file(&self, path: &Path) -> bool {
        self.get(path).is_some()
    }

    /// Whether some file lies under the folder `path` (the empty path is the top folder).
    pub fn is_dir(&self, path: &Path) -> bool {
        let dir = MemoryFiles::normalize(path);
        self.files
            .keys()
            .any(|f| f != &dir && (dir.as_os_str().is_empty() || f.starts_with(&dir)))
    }

    /// The files directly in the folder `path`, sorted.
    pub fn files_in(&self, path: &Path) -> Vec<PathBuf> {
        let dir = MemoryFiles::normalize(path);
        self.files
            .keys()
            .filter(|f| f.parent().unwrap_or(Path::new("")) == dir)
            .cloned()
            .collect()
    }

    /// Every path, sorted.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.keys().map(PathBuf::as_path)
    }

    /// Number of files.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    /// Whether the set is empty.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// `a/./b/../c` → `a/c`, lexically (a leading `..` that cannot fold is kept).
    pub fn normalize(path: &Path) -> PathBuf {
        let mut out = PathBuf::new();
        for c in path.components() {
            match c {
                Component::CurDir => {}
                Component::ParentDir => {
                    let last_is_name =
                        matches!(out.components().next_back(), Some(Component::Normal(_)));
                    if last_is_name {
                        out.pop();
                    } else {
                        out.push("..");
                    }
                }
                other => out.push(other.as_os_str()),
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_files_normalise_paths_and_list_folders() {
        let mut files = MemoryFiles::new();
        files.insert("examples/hello/./scene.rt", "scene");
        files.insert("examples/hello/lib/../util.rt", "util");
        files.insert("examples/other/scene.rt", "other");
        assert_eq!(
            files.get(Path::new("examples/hello/scene.rt")),
            Some(&b"scene"[..])
        );
        assert!(files.is_file(Path::new("examples/hello/util.rt")));
        assert!(files.is_dir(Path::new("examples")));
        assert!(files.is_dir(Path::new("")));
        assert!(!files.is_dir(Path::new("examples/hello/scene.rt")));
        assert_eq!(
            files.files_in(Path::new("examples/hello")),
            vec![
                PathBuf::from("examples/hello/scene.rt"),
                PathBuf::from("examples/hello/util.rt")
            ]
        );
        assert_eq!(
            MemoryFiles::normalize(Path::new("../a/./b/..")),
            PathBuf::from("../a")
        );
    }

    #[test]
    fn line_col_counts_characters() {
        let mut map = SourceMap::new();
        let f = map.add("a.rt", None, "ab\nçd\n");
        assert_eq!(map.line_col(f, 0), (1, 1));
        assert_eq!(map.line_col(f, 3), (2, 1));
        assert_eq!(map.line_col(f, 5), (2, 2)); // after the two-byte 'ç'
        assert_eq!(map.line_col(f, 100), (3, 1));
    }

    #[test]
    fn columns_on_a_long_line_agree_with_a_plain_count() {
        // Multi-byte characters straddle the checkpoint blocks.
        let text: String = "aé€😀".repeat(3 * CHAR_BLOCK / 5) + "\nxé";
        let mut map = SourceMap::new();
        let f = map.add("a.rt", None, text.clone());
        for (offset, _) in text.char_indices().step_by(97).chain([(text.len(), ' ')]) {
            let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
            let expected = text[line_start..offset].chars().count() + 1;
            assert_eq!(
                map.line_col(f, offset as u32).1,
                expected,
                "offset {offset}"
            );
        }
    }

    #[test]
    fn global_spans_round_trip() {
        let mut map = SourceMap::new();
        let a = map.add("a.rt", None, "fn a() {}");
        let b = map.add("b.rt", None, "fn bb() {}");
        for span in [
            Span::new(a, 0, 2),
            Span::new(a, 9, 9),
            Span::new(b, 3, 5),
            Span::new(b, 0, 10),
        ] {
            let (s, e) = map.to_global(span);
            assert_eq!(map.from_global(s, e), Some(span));
        }
        assert_eq!(map.from_global(1000, 1001), None);
    }
}
