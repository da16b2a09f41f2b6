//! Rendering diagnostics for golden files, with file names that do not depend on the machine.
//!
//! The driver names a file after the path it was given (here absolute, because the working directory
//! of `cargo test` is this crate's folder, not the repository root), or `std/…` for the standard
//! library. Rather than rely on the working directory or on the driver's naming, the suites
//! post-process the result:
//! - [`relative_map`] rebuilds the [`SourceMap`] in the same order (so every `FileId` stays valid)
//!   and renames each file whose path exists on disk inside the repository to that path relative to
//!   the repository root (`tests/ui/types/mismatch.rt`). Names that start with `std/` are kept as the
//!   driver chose them, and so are in-memory texts (`spec/types.md:53`).
//! - [`scrub`] removes the absolute repository path from everything else in the rendered text
//!   (messages and notes that quote file names).
//!
//! This works whatever paths the suites pass to `check_paths` and whatever the working directory is.

use crate::paths::{relative_to_root, repo_root};
use rtc_compiler::driver::Checked;
use rtc_compiler::{Diagnostic, FileId, SourceMap};
use std::path::Path;

/// A copy of `map` whose on-disk files inside the repository are named relative to its root.
pub fn relative_map(map: &SourceMap) -> SourceMap {
    let mut out = SourceMap::new();
    for (_, file) in map.files() {
        let name = match &file.path {
            _ if file.name.starts_with("std/") => file.name.clone(),
            // Only a path that exists is a file on disk: in-memory texts may carry their name as
            // a path (`spec/types.md:53`).
            Some(path) if path.is_file() => {
                relative_to_root(path).unwrap_or_else(|| file.name.clone())
            }
            // An in-memory file named by an absolute path: shorten it too.
            _ if Path::new(&file.name).is_absolute() => {
                relative_to_root(Path::new(&file.name)).unwrap_or_else(|| file.name.clone())
            }
            _ => file.name.clone(),
        };
        out.add(name, file.path.clone(), file.text.clone());
    }
    out
}

/// Removes the absolute path of the repository from `text` (`/…/rtc/tests/NAME.rt` → `tests/NAME.rt`),
/// together with any extra slashes in front of it (`//…/rtc/tests/NAME.rt` → `tests/NAME.rt`).
pub fn scrub(text: &str) -> String {
    let mut roots = vec![repo_root().to_string_lossy().into_owned()];
    if let Some(raw) = Path::new(env!("CARGO_MANIFEST_DIR")).parent() {
        roots.push(raw.to_string_lossy().into_owned());
    }
    let mut out = text.to_owned();
    for root in roots {
        let needle = format!("{}/", root.trim_end_matches('/'));
        let mut result = String::with_capacity(out.len());
        let mut rest = out.as_str();
        while let Some(at) = rest.find(&needle) {
            result.push_str(rest[..at].trim_end_matches('/'));
            rest = &rest[at + needle.len()..];
        }
        result.push_str(rest);
        out = result;
    }
    out
}

/// The diagnostics of `checked`, rendered without colour and with repository-relative names.
pub fn render_relative(checked: &Checked) -> String {
    render_list(&checked.sources, &checked.diagnostics)
}

/// `diags` (whose spans are in `map`), rendered as [`render_relative`] does.
pub fn render_list(map: &SourceMap, diags: &[Diagnostic]) -> String {
    let map = relative_map(map);
    scrub(&rtc_compiler::diag::render_human(&map, diags, false))
}

/// Where a diagnostic's primary span starts: `(file name, 1-based line)`, using `map`'s names.
pub fn primary_location(map: &SourceMap, diag: &Diagnostic) -> (String, usize) {
    let file: FileId = diag.primary.span.file;
    if (file.0 as usize) >= map.len() {
        return (format!("<file {} not in the source map>", file.0), 0);
    }
    let (line, _) = map.line_col(file, diag.primary.span.lo);
    (map.get(file).name.clone(), line)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_become_repository_relative() {
        let root = repo_root();
        let mut map = SourceMap::new();
        map.add(
            root.join("stdlib/prelude.rt").display().to_string(),
            Some(root.join("stdlib/prelude.rt")),
            "",
        );
        map.add(
            "std/cameras/pinhole.rt",
            Some(root.join("stdlib/cameras/pinhole.rt")),
            "",
        );
        map.add("memory.rt", None, "");
        map.add("spec/types.md:53", Some("spec/types.md:53".into()), "");
        map.add("/elsewhere/x.rt", Some("/elsewhere/x.rt".into()), "");
        let rel = relative_map(&map);
        let names: Vec<&str> = rel.files().map(|(_, f)| f.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "stdlib/prelude.rt",
                "std/cameras/pinhole.rt",
                "memory.rt",
                "spec/types.md:53",
                "/elsewhere/x.rt"
            ]
        );
        assert_eq!(
            scrub(&format!("cannot read `{}/a.rt`", root.display())),
            "cannot read `a.rt`"
        );
        assert_eq!(
            scrub(&format!("a cycle: /{0}/a.rt → //{0}/b.rt", root.display())),
            "a cycle: a.rt → b.rt"
        );
    }
}
