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

use std::path::{Path, PathBuf};

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
    /// Where the file starts in the one address space shared by all files of the map (see
    /// [`SourceMap::to_global`]).
    base: u32,
}

impl SourceFile {
    /// Byte offsets of the first byte of each line.
    pub fn line_starts(&self) -> &[u32] {
        &self.line_starts
    }
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
        let line = match f.line_starts.binary_search(&(offset as u32)) {
            Ok(l) => l,
            Err(l) => l - 1,
        };
        let start = f.line_starts[line] as usize;
        let mut col_start = offset;
        while col_start > start && !f.text.is_char_boundary(col_start) {
            col_start -= 1;
        }
        let col = f.text[start..col_start].chars().count();
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

#[cfg(test)]
mod tests {
    use super::*;

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
