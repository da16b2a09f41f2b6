//! Tidy checks over the whole repository (after rust-analyzer's `tidy` tests): every Rust file of
//! every crate and every `.rt` file of the standard library, the examples and the GPU test scenes
//! starts with a `//!` module doc, and every intra-repository reference the documentation names exists:
//!
//! - a path in a comment or a Markdown file that starts at a top-level folder (`compiler/…`,
//!   `runtime/…`, `stdlib/…`, `docs/…`, …) or that names a source file relative to an enclosing
//!   folder (`sema/consteval.rs` from inside `compiler/src/`);
//! - a section of a Markdown file named as `FILE.md, "Heading"` or linked as `FILE.md#anchor`;
//! - "ARCHITECTURE invariant N" (N within the numbered list of ARCHITECTURE.md's "Invariants");
//! - no numbered rule of a style guide the repository does not hold.
//!
//! Test fixtures (`tests/ui`, `tests/corpus`, codegen goldens) are text a test feeds the compiler,
//! not documentation, and are skipped, as are Markdown code blocks.

use std::path::{Path, PathBuf};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ has a parent")
        .to_path_buf()
}

/// Folders that hold no documentation of ours: build output, fixtures, third-party files.
const SKIPPED: &[&str] = &[
    "target",
    ".git",
    "node_modules",
    "tests/ui",
    "tests/corpus",
    "tests/codegen/out",
    "out",
];

/// Top-level entries a path in the documentation may start with.
const TOP_LEVEL: &[&str] = &[
    ".ci/",
    "compiler/",
    "runtime/",
    "cli/",
    "stdlib/",
    "examples/",
    "spec/",
    "tests/",
    "docs/",
];

/// Extensions of files whose names the documentation cites.
const CITED_EXTENSIONS: &[&str] = &["rs", "rt", "md", "sh", "py", "toml"];

fn walk(root: &Path, dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let p = entry.path();
        let rel = p
            .strip_prefix(root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        // npm's folders anywhere (web/node_modules after `npm ci`), not only at the top.
        let npm = p.file_name().is_some_and(|n| n == "node_modules");
        if SKIPPED.iter().any(|s| rel == *s) || rel.starts_with("target") || npm {
            continue;
        }
        if p.is_dir() {
            walk(root, &p, out);
        } else {
            out.push(p);
        }
    }
}

fn files() -> Vec<PathBuf> {
    let root = repo_root();
    let mut out = Vec::new();
    walk(&root, &root, &mut out);
    out.sort();
    out
}

fn rel(p: &Path) -> String {
    p.strip_prefix(repo_root())
        .unwrap()
        .to_string_lossy()
        .replace('\\', "/")
}

fn extension(p: &Path) -> &str {
    p.extension().and_then(|e| e.to_str()).unwrap_or("")
}

#[test]
fn every_source_file_starts_with_a_module_doc() {
    let files = files();
    let sources: Vec<_> = files
        .iter()
        .filter(|p| {
            let r = rel(p);
            extension(p) == "rs"
                || (extension(p) == "rt"
                    && [
                        "stdlib/",
                        "examples/",
                        "runtime/tests/scenes/",
                        "tests/scenes/",
                    ]
                    .iter()
                    .any(|d| r.starts_with(d)))
        })
        .collect();
    assert!(
        sources.len() > 200,
        "only {} source files found",
        sources.len()
    );
    let missing: Vec<_> = sources
        .iter()
        .filter(|p| {
            let text = std::fs::read_to_string(p).unwrap_or_default();
            !text.trim_start().starts_with("//!")
        })
        .map(|p| rel(p))
        .collect();
    assert!(
        missing.is_empty(),
        "files without a `//!` module doc: {missing:#?}"
    );
}

/// The documentation of a file as lines `(line number, text)`: comments of code files, the text of
/// Markdown files outside code blocks.
fn doc_lines(p: &Path, text: &str) -> Vec<(usize, String)> {
    let ext = extension(p);
    let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let mut out = Vec::new();
    let mut fenced = false;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start();
        let doc = match ext {
            "md" => {
                if t.starts_with("```") {
                    fenced = !fenced;
                    continue;
                }
                (!fenced).then(|| line.to_string())
            }
            "rs" | "rt" => t.starts_with("//").then(|| {
                t.trim_start_matches('/')
                    .trim_start_matches('!')
                    .to_string()
            }),
            "sh" | "toml" | "py" => t
                .starts_with('#')
                .then(|| t.trim_start_matches('#').to_string()),
            _ if name == "run" => t
                .starts_with('#')
                .then(|| t.trim_start_matches('#').to_string()),
            _ => None,
        };
        if let Some(d) = doc {
            out.push((i + 1, d));
        }
    }
    out
}

fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || "_./{},*-".contains(c)
}

/// Expands one level of `{a,b}` in a cited path.
fn expand_braces(token: &str) -> Vec<String> {
    if let (Some(open), Some(close)) = (token.find('{'), token.find('}')) {
        if open < close {
            return token[open + 1..close]
                .split(',')
                .map(|alt| format!("{}{alt}{}", &token[..open], &token[close + 1..]))
                .collect();
        }
    }
    vec![token.to_string()]
}

/// Whether `token` is a path the documentation cites (rather than words joined by a slash). Not
/// cited: paths outside the repository (`../shared/…`, `shared/bench/…`: the project's sibling
/// folder), placeholders (`examples/NAME/`, `$PWD/…`) and build outputs `.gitignore` names.
fn cites_a_path(token: &str, ignored: &[String]) -> bool {
    // The repository's top-level documents are cited by bare name (`ARCHITECTURE.md`).
    let top_document =
        token.ends_with(".md") && token.chars().next().is_some_and(|c| c.is_ascii_uppercase());
    if top_document && !token.contains('/') {
        return true;
    }
    if !token.contains('/') || token.starts_with('/') || token.contains("//") {
        return false;
    }
    if token.starts_with("shared/") {
        return false;
    }
    if ignored.iter().any(|i| token.starts_with(i.as_str())) {
        return false;
    }
    if TOP_LEVEL.iter().any(|t| token.starts_with(t)) {
        return true;
    }
    let last = token.rsplit('/').next().unwrap_or("");
    last.rsplit_once('.')
        .is_some_and(|(stem, ext)| !stem.is_empty() && CITED_EXTENSIONS.contains(&ext))
}

/// A `../` path cited by `file`, as a path from the repository root, or `None` when it leaves the
/// repository (the project's sibling `shared/` folder, for instance).
fn within_repo(file: &Path, token: &str) -> Option<String> {
    let mut parts: Vec<String> = rel(file.parent()?)
        .split('/')
        .filter(|p| !p.is_empty())
        .map(String::from)
        .collect();
    for seg in token.split('/') {
        match seg {
            ".." => {
                parts.pop()?;
            }
            "." | "" => {}
            s => parts.push(s.to_string()),
        }
    }
    Some(parts.join("/"))
}

/// Whether a path that does not exist is a placeholder (`examples/NAME/`, `FILE.md`).
fn has_placeholder(path: &str) -> bool {
    path.split('/').any(|seg| {
        let stem = seg.split('.').next().unwrap_or("");
        stem.len() > 1 && stem.chars().all(|c| c.is_ascii_uppercase() || c == '_')
    })
}

/// Whether a cited path exists: from the repository root, or relative to the citing file's folder
/// or any folder above it (or its `src/`), as a crate's docs cite its own modules.
fn resolves(root: &Path, file: &Path, cited: &str) -> bool {
    let cited = cited.trim_end_matches(['.', ',']);
    // Import paths: `std/…` is the standard library's folder.
    if let Some(rest) = cited.strip_prefix("std/") {
        let p = root.join("stdlib").join(rest);
        return p.exists() || p.with_extension("rt").exists();
    }
    // A glob: its folder must exist.
    if let Some(star) = cited.find('*') {
        let dir = &cited[..cited[..star].rfind('/').map_or(0, |i| i + 1)];
        return dir.is_empty() || resolves(root, file, dir);
    }
    if root.join(cited).exists() {
        return true;
    }
    // A crate's docs cite its own modules; the test crates cite the other crates' modules.
    let crate_sources = [
        "compiler/src",
        "runtime/src",
        "runtime/bvh/src",
        "cli/src",
        "tests/src",
    ];
    if crate_sources
        .iter()
        .any(|c| root.join(c).join(cited).exists())
    {
        return true;
    }
    let mut dir = file.parent();
    while let Some(d) = dir {
        if d.join(cited).exists() || d.join("src").join(cited).exists() {
            return true;
        }
        if d == root {
            break;
        }
        dir = d.parent();
    }
    false
}

fn headings(md: &str) -> Vec<String> {
    let mut fenced = false;
    md.lines()
        .filter(|l| {
            if l.trim_start().starts_with("```") {
                fenced = !fenced;
            }
            !fenced && l.starts_with('#')
        })
        .map(|l| normalise(l.trim_start_matches('#')))
        .collect()
}

/// The file a cited Markdown path names: from the citing file's folder, else from the root.
fn target_of(root: &Path, file: &Path, cited: &str) -> PathBuf {
    let beside = file.parent().unwrap_or(root).join(cited);
    if beside.exists() {
        beside
    } else {
        root.join(cited)
    }
}

/// What is wrong with the section a Markdown citation names, if anything: `after` is the text
/// right after the cited path, `#anchor` (a link) or `, "Heading"` (prose).
fn section_problem(target: &Path, after: &str) -> Option<String> {
    let anchor = after.strip_prefix('#').map(|a| {
        a.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '-' || *c == '_')
            .collect::<String>()
    });
    let quoted = after
        .trim_start_matches([',', ' ', '(', '\'', 's'])
        .strip_prefix('"')
        .and_then(|q| q.find('"').map(|end| &q[..end]));
    if anchor.is_none() && quoted.is_none() {
        return None;
    }
    let headings = headings(&std::fs::read_to_string(target).unwrap_or_default());
    if let Some(anchor) = anchor {
        if !headings.iter().any(|h| slug(h) == anchor) {
            return Some(format!("has no heading for #{anchor}"));
        }
    }
    let heading = quoted?;
    (!headings.contains(&normalise(heading))).then(|| format!("has no section \"{heading}\""))
}

/// A heading's anchor as GitHub makes it: lower case, punctuation dropped, spaces as hyphens.
fn slug(heading: &str) -> String {
    heading
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| {
            if c == ' ' {
                '-'
            } else {
                c.to_ascii_lowercase()
            }
        })
        .collect()
}

fn normalise(s: &str) -> String {
    s.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .trim_matches(|c: char| c == '`' || c == '*')
        .to_lowercase()
}

/// The number of items of ARCHITECTURE.md's numbered "Invariants" list.
fn invariant_count(root: &Path) -> usize {
    let text = std::fs::read_to_string(root.join("ARCHITECTURE.md")).unwrap();
    let section = text
        .split("\n## Invariants")
        .nth(1)
        .expect("ARCHITECTURE.md has an Invariants section");
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .filter(|l| {
            let digits: String = l.chars().take_while(|c| c.is_ascii_digit()).collect();
            !digits.is_empty() && l[digits.len()..].starts_with(". ")
        })
        .count()
}

#[test]
fn every_reference_in_the_documentation_exists() {
    let root = repo_root();
    let invariants = invariant_count(&root);
    assert!(
        invariants >= 6,
        "ARCHITECTURE.md lists {invariants} invariants"
    );
    let ignored: Vec<String> = std::fs::read_to_string(root.join(".gitignore"))
        .unwrap_or_default()
        .lines()
        .filter(|l| l.starts_with('/'))
        .map(|l| l.trim_start_matches('/').to_string())
        .collect();
    let mut broken = Vec::new();
    let mut checked = 0;
    for file in files() {
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue;
        };
        let lines = doc_lines(&file, &text);
        if lines.is_empty() {
            continue;
        }
        // Comments wrap: join consecutive documentation lines so a reference split over two lines
        // reads as one.
        let joined: String = lines.iter().map(|(_, l)| format!("{l} ")).collect();
        let line_of = |offset: usize| {
            let mut at = 0;
            for (n, l) in &lines {
                at += l.len() + 1;
                if at > offset {
                    return *n;
                }
            }
            lines.last().map_or(0, |(n, _)| *n)
        };
        let here = rel(&file);
        let mut start = None;
        for (i, c) in joined.char_indices().chain([(joined.len(), ' ')]) {
            match (is_path_char(c), start) {
                (true, None) => start = Some(i),
                (false, Some(s)) => {
                    start = None;
                    let token = joined[s..i].trim_end_matches(['.', ',']);
                    let after_url = joined[..s].ends_with(':');
                    // A relative import in an example (`import "../shared/fog.rt";`) names the
                    // reader's files, not ours; `std/…` imports are checked.
                    let example_import =
                        joined[..s].ends_with("import \"") && !token.starts_with("std/");
                    if after_url
                        || example_import
                        || joined[..s].ends_with('$')
                        || !cites_a_path(token, &ignored)
                    {
                        continue;
                    }
                    // `../…`: relative to the citing file; outside the repository is not ours.
                    let token = if token.starts_with("../") {
                        match within_repo(&file, token) {
                            Some(t) => t,
                            None => continue,
                        }
                    } else {
                        token.to_string()
                    };
                    for cited in expand_braces(&token) {
                        checked += 1;
                        if !resolves(&root, &file, &cited) {
                            if has_placeholder(&cited) {
                                continue;
                            }
                            broken.push(format!("{here}:{}: `{cited}` does not exist", line_of(s)));
                            continue;
                        }
                        if cited.ends_with(".md") {
                            let target = target_of(&root, &file, &cited);
                            if let Some(problem) = section_problem(&target, &joined[i..]) {
                                broken.push(format!("{here}:{}: `{cited}` {problem}", line_of(s)));
                            }
                        }
                    }
                }
                _ => {}
            }
        }
        for (n, line) in &lines {
            if line.contains(concat!("STYLE", " rule")) && !root.join("STYLE.md").exists() {
                broken.push(format!(
                    "{here}:{n}: cites a numbered style rule, but the repository holds no STYLE.md"
                ));
            }
        }
        let words: Vec<&str> = joined.split_whitespace().collect();
        for w in words.windows(3) {
            if w[0].trim_start_matches('(').starts_with("ARCHITECTURE")
                && w[1].starts_with("invariant")
            {
                let n: String = w[2].chars().take_while(|c| c.is_ascii_digit()).collect();
                if let Ok(n) = n.parse::<usize>() {
                    if n == 0 || n > invariants {
                        broken.push(format!(
                            "{here}: cites ARCHITECTURE invariant {n}; there are {invariants}"
                        ));
                    }
                }
            }
        }
    }
    assert!(checked > 100, "only {checked} references found");
    assert!(
        broken.is_empty(),
        "broken references:\n{}",
        broken.join("\n")
    );
}
