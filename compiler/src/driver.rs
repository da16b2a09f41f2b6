//! The compiler driver: the phases in order, as one list.
//!
//! `check_*` loads the root files and everything they import (plus the prelude), parses each file once,
//! and runs semantic analysis over the module graph. It returns the source map (for rendering
//! diagnostics), all diagnostics sorted by position, and the checked program.
//!
//! The phases of [`check`], in order:
//! 1. load: the prelude, the roots, then every import, transitively (each file read and parsed once,
//!    keyed by its canonical path; E0108, E0301);
//! 2. import cycles (E0302);
//! 3. [`sema::analyze`]: names, types, constants, programs, bodies, call graph, scenes;
//! 4. render every error as a [`Diagnostic`], sorted.
//!
//! Module names shown in diagnostics are the paths as given for roots, `std/…` for the standard
//! library, and the importer's folder joined with the import path for other imports.

use crate::diag::{self, suggest, Diagnostic};
use crate::sema::error::SemaError;
use crate::sema::hir::{self, ModuleId};
use crate::sema::{self, SourceModule};
use crate::source::{FileId, SourceMap, Span};
use crate::syntax;
use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};

/// Options shared by every command.
#[derive(Clone, Debug)]
pub struct Options {
    /// The standard library folder (`std/…` imports resolve here; `prelude.rt` lives here).
    pub stdlib_dir: PathBuf,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            stdlib_dir: default_stdlib_dir(),
        }
    }
}

/// `RTC_STDLIB` if set, else the `stdlib/` folder of this source tree.
pub fn default_stdlib_dir() -> PathBuf {
    match std::env::var_os("RTC_STDLIB") {
        Some(dir) => PathBuf::from(dir),
        None => Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join("stdlib"),
    }
}

/// The result of checking.
#[derive(Debug, Default)]
pub struct Checked {
    /// Every file read.
    pub sources: SourceMap,
    /// Every diagnostic, sorted by file and position.
    pub diagnostics: Vec<Diagnostic>,
    /// The typed program, when there are no errors (warnings allowed).
    pub program: Option<hir::Program>,
}

impl Checked {
    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        crate::diag::has_errors(&self.diagnostics)
    }
}

/// Checks the given root files (a folder stands for every `.rt` file in it) and everything they
/// import.
pub fn check_paths(paths: &[PathBuf], options: &Options) -> Checked {
    let mut roots: Vec<Root> = Vec::new();
    for p in paths {
        if p.is_dir() {
            let mut files: Vec<PathBuf> = std::fs::read_dir(p)
                .into_iter()
                .flatten()
                .flatten()
                .map(|e| e.path())
                .filter(|f| f.extension().is_some_and(|x| x == "rt") && f.is_file())
                .collect();
            files.sort();
            roots.extend(files.into_iter().map(Root::Path));
        } else {
            roots.push(Root::Path(p.clone()));
        }
    }
    check(roots, options)
}

/// Checks one in-memory file named `name` (imports resolve relative to `name`'s folder).
pub fn check_text(name: &str, text: &str, options: &Options) -> Checked {
    check(
        vec![Root::Text(name.to_string(), text.to_string())],
        options,
    )
}

/// A root module: a file on disk, or text with a name.
enum Root {
    Path(PathBuf),
    Text(String, String),
}

/// The phases, in order.
fn check(roots: Vec<Root>, options: &Options) -> Checked {
    let mut l = Loader {
        options,
        sources: SourceMap::new(),
        modules: Vec::new(),
        by_path: HashMap::new(),
        syntax: Vec::new(),
        errors: Vec::new(),
        edges: Vec::new(),
    };
    let prelude = l.load_prelude();
    for r in roots {
        l.load_root(r);
    }
    l.load_imports();
    l.check_cycles();
    let (program, errors) = sema::analyze(&l.modules, prelude);
    let mut diagnostics = l.syntax;
    diagnostics.extend(
        l.errors
            .iter()
            .chain(&errors)
            .map(|e| e.to_diagnostic(&program, &l.sources)),
    );
    diag::sort(&mut diagnostics);
    let ok = !diag::has_errors(&diagnostics);
    Checked {
        sources: l.sources,
        diagnostics,
        program: ok.then_some(program),
    }
}

struct Loader<'o> {
    options: &'o Options,
    sources: SourceMap,
    modules: Vec<SourceModule>,
    by_path: HashMap<PathBuf, ModuleId>,
    syntax: Vec<Diagnostic>,
    errors: Vec<SemaError>,
    /// Per module: the modules its imports name, with the span of each path.
    edges: Vec<Vec<(ModuleId, Span)>>,
}

impl Loader<'_> {
    /// Adds a file and parses it (E0108 for invalid UTF-8, then it is empty).
    fn add(&mut self, name: String, path: Option<PathBuf>, bytes: Vec<u8>) -> ModuleId {
        let (text, bad) = match String::from_utf8(bytes) {
            Ok(t) => (t, None),
            Err(e) => {
                let at = e.utf8_error().valid_up_to();
                (String::from_utf8_lossy(e.as_bytes()).into_owned(), Some(at))
            }
        };
        let file = self.sources.add(name.clone(), path.clone(), text);
        let ast = match bad {
            Some(at) => {
                self.errors.push(SemaError::InvalidUtf8 {
                    file,
                    offset: at as u32,
                });
                syntax::ast::Module {
                    file,
                    ..Default::default()
                }
            }
            None => {
                let (ast, diags) = syntax::parse(file, &self.sources.get(file).text);
                self.syntax.extend(diags);
                ast
            }
        };
        let id = ModuleId(self.modules.len() as u32);
        self.modules.push(SourceModule {
            ast,
            name,
            path,
            imports: Vec::new(),
            is_prelude: false,
            is_root: false,
        });
        self.edges.push(Vec::new());
        id
    }

    /// A file that could not be read, as an empty module whose name says so (for the diagnostic).
    fn unreadable(&mut self, name: String, reason: String) {
        let file: FileId = self.sources.add(name.clone(), None, String::new());
        self.errors.push(SemaError::Unreadable {
            span: Span::new(file, 0, 0),
            path: name,
            reason,
        });
    }

    /// Loads `path` once (by canonical path).
    fn load_file(&mut self, name: String, path: &Path) -> Result<ModuleId, std::io::Error> {
        let canon = path.canonicalize()?;
        if let Some(id) = self.by_path.get(&canon) {
            return Ok(*id);
        }
        let bytes = std::fs::read(path)?;
        let id = self.add(name, Some(path.to_path_buf()), bytes);
        self.by_path.insert(canon, id);
        Ok(id)
    }

    fn load_prelude(&mut self) -> Option<ModuleId> {
        let path = self.options.stdlib_dir.join("prelude.rt");
        match self.load_file("std/prelude.rt".to_string(), &path) {
            Ok(id) => {
                self.modules[id.index()].is_prelude = true;
                Some(id)
            }
            Err(e) => {
                self.unreadable(path.display().to_string(), e.to_string());
                None
            }
        }
    }

    fn load_root(&mut self, root: Root) {
        let id = match root {
            Root::Path(p) => match self.load_file(p.display().to_string(), &p) {
                Ok(id) => id,
                Err(e) => return self.unreadable(p.display().to_string(), e.to_string()),
            },
            Root::Text(name, text) => {
                let path = PathBuf::from(&name);
                let id = self.add(name, Some(path.clone()), text.into_bytes());
                if let Ok(canon) = path.canonicalize() {
                    self.by_path.entry(canon).or_insert(id);
                }
                id
            }
        };
        self.modules[id.index()].is_root = true;
    }

    /// Resolves every import of every module, loading new files as they are found.
    fn load_imports(&mut self) {
        let mut next = 0;
        while next < self.modules.len() {
            let m = ModuleId(next as u32);
            next += 1;
            let imports: Vec<(String, Span)> = self.modules[m.index()]
                .ast
                .imports
                .iter()
                .map(|i| (i.path.clone(), i.path_span))
                .collect();
            for (path, span) in imports {
                if let Some(target) = self.resolve_import(m, &path, span) {
                    self.edges[m.index()].push((target, span));
                    let list = &mut self.modules[m.index()].imports;
                    if !list.contains(&target) {
                        list.push(target);
                    }
                }
            }
        }
    }

    fn resolve_import(&mut self, from: ModuleId, path: &str, span: Span) -> Option<ModuleId> {
        let importer = &self.modules[from.index()];
        let (file, name) = match path.strip_prefix("std/") {
            Some(rest) => (self.options.stdlib_dir.join(rest), format!("std/{rest}")),
            None => {
                let base = importer
                    .path
                    .as_deref()
                    .and_then(Path::parent)
                    .unwrap_or(Path::new(""));
                let dir_name = Path::new(&importer.name).parent().unwrap_or(Path::new(""));
                (base.join(path), normalize(&dir_name.join(path)))
            }
        };
        let (file, name) = if file.is_file() || file.extension().is_some() {
            (file, name)
        } else {
            (file.with_extension("rt"), format!("{name}.rt"))
        };
        if !file.is_file() {
            let close = close_files(&file);
            self.errors.push(SemaError::ImportNotFound {
                span,
                path: path.to_string(),
                close,
            });
            return None;
        }
        match self.load_file(name, &file) {
            Ok(id) => Some(id),
            Err(e) => {
                self.errors.push(SemaError::Unreadable {
                    span,
                    path: path.to_string(),
                    reason: e.to_string(),
                });
                None
            }
        }
    }

    /// E0302 for every import that closes a cycle.
    fn check_cycles(&mut self) {
        let n = self.modules.len();
        let mut color = vec![0u8; n];
        for root in 0..n {
            if color[root] != 0 {
                continue;
            }
            let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
            color[root] = 1;
            while let Some(&mut (node, ref mut i)) = stack.last_mut() {
                match self.edges[node].get(*i).copied() {
                    Some((target, span)) => {
                        *i += 1;
                        let t = target.index();
                        match color[t] {
                            0 => {
                                color[t] = 1;
                                stack.push((t, 0));
                            }
                            1 => {
                                let start = stack.iter().position(|(x, _)| *x == t).unwrap_or(0);
                                let mut chain: Vec<String> = stack[start..]
                                    .iter()
                                    .map(|(x, _)| self.modules[*x].name.clone())
                                    .collect();
                                chain.push(self.modules[t].name.clone());
                                self.errors.push(SemaError::ImportCycle { span, chain });
                            }
                            _ => {}
                        }
                    }
                    None => {
                        color[node] = 2;
                        stack.pop();
                    }
                }
            }
        }
    }
}

/// `a/./b/../c` → `a/c`, lexically.
fn normalize(p: &Path) -> String {
    let mut out: Vec<String> = Vec::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if out.last().is_some_and(|l| l != "..") {
                    out.pop();
                } else {
                    out.push("..".to_string());
                }
            }
            other => out.push(other.as_os_str().to_string_lossy().into_owned()),
        }
    }
    out.join("/")
}

/// `.rt` files in the folder of `missing` whose names are close to its name.
fn close_files(missing: &Path) -> Vec<String> {
    let Some(dir) = missing.parent() else {
        return Vec::new();
    };
    let Some(want) = missing
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
    else {
        return Vec::new();
    };
    let names: Vec<String> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".rt"))
        .collect();
    let limit = (want.len() / 3).max(1);
    let mut close: Vec<(usize, &String)> = names
        .iter()
        .filter_map(|n| suggest::distance_at_most(&want, n, limit).map(|d| (d, n)))
        .collect();
    close.sort();
    close.into_iter().take(3).map(|(_, n)| n.clone()).collect()
}
