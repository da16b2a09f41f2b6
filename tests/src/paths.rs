//! Where things are: the repository root and the `.rt` files under a folder.
//!
//! Invariant: every path returned here is absolute (rooted at [`repo_root`]), and listings are sorted,
//! so test output does not depend on the working directory or on the file system's order.

use std::path::{Path, PathBuf};

/// The repository root (the parent of this crate's folder).
pub fn repo_root() -> PathBuf {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let root = here.parent().unwrap_or(here);
    std::fs::canonicalize(root).unwrap_or_else(|_| root.to_path_buf())
}

/// `path` relative to the repository root with `/` separators, or `None` if it is outside it.
/// A relative `path` is taken relative to the working directory.
pub fn relative_to_root(path: &Path) -> Option<String> {
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().ok()?.join(path)
    };
    let abs = std::fs::canonicalize(&abs).unwrap_or(abs);
    let rel = abs.strip_prefix(repo_root()).ok()?;
    Some(
        rel.components()
            .map(|c| c.as_os_str().to_string_lossy())
            .collect::<Vec<_>>()
            .join("/"),
    )
}

/// `path` relative to the repository root (see [`relative_to_root`]), or as is if outside it.
pub fn display_relative(path: &Path) -> String {
    relative_to_root(path).unwrap_or_else(|| path.display().to_string())
}

/// Every file under `dir` (recursively) whose name ends in `.ext`, sorted; empty if `dir` is missing.
pub fn files_with_extension(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    walk(dir, ext, &mut out);
    out.sort();
    out
}

fn walk(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        match entry.file_type() {
            Ok(t) if t.is_dir() => walk(&path, ext, out),
            Ok(_) if path.extension().is_some_and(|e| e == ext) => out.push(path),
            _ => {}
        }
    }
}

/// Every `.rt` file under `stdlib/` and `examples/`, sorted.
pub fn stdlib_and_examples() -> Vec<PathBuf> {
    let root = repo_root();
    let mut files = files_with_extension(&root.join("stdlib"), "rt");
    files.extend(files_with_extension(&root.join("examples"), "rt"));
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_holds_the_workspace() {
        let root = repo_root();
        assert!(root.join("Cargo.toml").is_file());
        assert!(root.join("spec").is_dir());
        assert_eq!(
            display_relative(&root.join("spec/README.md")),
            "spec/README.md"
        );
    }
}
