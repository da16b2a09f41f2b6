//! `rtc check <files or folders>…`: parses and type-checks `.rt` files and everything they import,
//! and reports every diagnostic. Folders are searched recursively for `*.rt` files (hidden folders,
//! whose names start with `.`, and symbolic links to folders are skipped); a file named explicitly is
//! checked whatever its extension. All files are checked together, as the roots of one compilation, so
//! each module is read and checked once.
//!
//! A path that does not exist, or a folder without `.rt` files, is a usage error (exit code 2): nothing
//! was checked.
//!
//! `--assets` goes one step further, still without a GPU: when the sources check without errors, every
//! scene declared in a root file is linked and its assets are loaded as `rtc render` would load them
//! (meshes, images, glTF files, with their BVHs built), so a broken or escaping asset is reported
//! before anything is rendered. A root that is a glTF file (`.gltf`, `.glb`) is loaded through the
//! scene `rtc render` would write for it.

use super::render::{self, model};
use super::Context;
use crate::args::AssetArgs;
use crate::args::MessageFormat;
use crate::exit::Exit;
use crate::report;
use rtc_compiler::link::LinkOptions;
use rtc_runtime::assets::AssetRoots;
use rtc_runtime::scene::{Entities, EntityOptions};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// Arguments of `rtc check`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Files or folders to check (folders are searched recursively for `*.rt` files).
    #[arg(required = true, value_name = "PATH")]
    pub paths: Vec<PathBuf>,
    /// How to print diagnostics: human-readable text on stderr, or JSON lines on stdout.
    #[arg(long, value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
    /// Also link every scene of the root files and load its assets (meshes, images, glTF files)
    /// as `rtc render` would, without a GPU.
    #[arg(long)]
    pub assets: bool,
    /// Where assets may come from besides each scene's folder (with `--assets`).
    #[command(flatten)]
    pub roots: AssetArgs,
}

/// Runs `rtc check`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    let roots = match collect_roots(&args.paths) {
        Ok(roots) => roots,
        Err(message) => return report::usage_error(&message, ctx.color),
    };
    if args.assets {
        return check_assets(&roots, args, ctx);
    }
    let checked = rtc_compiler::driver::check_paths(&roots, &ctx.options);
    report::diagnostics(
        &checked.sources,
        &checked.diagnostics,
        args.message_format,
        ctx.color,
        "check",
    )
}

/// `rtc check --assets`: each root on its own (a glTF file through its written scene), then each of
/// its scenes linked and its assets loaded. Stops at the first root with errors.
fn check_assets(roots: &[PathBuf], args: &Args, ctx: &Context) -> Exit {
    let folders = match args.roots.roots() {
        Ok(r) => r,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    for root in roots {
        let synth = if model::is_model(root) {
            match model::synthesize(root, &folders) {
                Ok(s) => Some(s),
                Err(e) => return render::fail(&e.to_string(), ctx),
            }
        } else {
            None
        };
        let path = synth.as_ref().map_or(root, |s| &s.path);
        let checked = rtc_compiler::driver::check_paths(std::slice::from_ref(path), &ctx.options);
        if checked.has_errors() || checked.program.is_none() {
            return report::diagnostics(
                &checked.sources,
                &checked.diagnostics,
                args.message_format,
                ctx.color,
                "check",
            );
        }
        let names: Vec<String> = checked.program.as_ref().map_or(Vec::new(), |p| {
            p.scenes
                .iter()
                .filter(|(_, s)| p.modules[s.module.index()].is_root)
                .map(|(_, s)| s.name.clone())
                .collect()
        });
        let _ = report::diagnostics(
            &checked.sources,
            &checked.diagnostics,
            args.message_format,
            ctx.color,
            "check",
        );
        // A bare glTF file's scene names it relative to its folder, searched first (as in render).
        let asset_roots = synth
            .as_ref()
            .map_or_else(|| folders.clone(), |s| s.asset_roots(&folders));
        for name in &names {
            let exit = load_scene_assets(path, name, &asset_roots, args, ctx);
            if exit != Exit::Success {
                return exit;
            }
        }
    }
    Exit::Success
}

/// Links the scene `name` of `path` and loads its assets; reports what goes wrong.
fn load_scene_assets(
    path: &Path,
    name: &str,
    asset_roots: &AssetRoots,
    args: &Args,
    ctx: &Context,
) -> Exit {
    let compiled = match rtc_compiler::kernel::compile_scene(
        &[path.to_path_buf()],
        Some(name),
        &ctx.options,
        &LinkOptions {
            asset_roots: asset_roots.clone(),
            ..LinkOptions::default()
        },
    ) {
        Ok(c) => c,
        Err(f) => {
            return report::diagnostics(
                &f.checked.sources,
                &f.diagnostics,
                args.message_format,
                ctx.color,
                "check",
            )
        }
    };
    let Some(program) = compiled.checked.program.as_ref() else {
        return render::fail(&format!("`{}` could not be linked", path.display()), ctx);
    };
    let desc = &program.scenes[compiled.scene];
    let options = EntityOptions {
        asset_roots: asset_roots.clone(),
        ..EntityOptions::default()
    };
    match Entities::build(program, desc, &compiled.linked, &options) {
        Ok(entities) => {
            for w in entities.warnings() {
                render::warn(w, ctx);
            }
            Exit::Success
        }
        // An asset error points at the scene's string that names the asset (E0902).
        Err(e) => match e.to_diagnostic() {
            Some(d) => report::diagnostics(
                &compiled.checked.sources,
                std::slice::from_ref(&d),
                args.message_format,
                ctx.color,
                "check",
            ),
            None => render::fail(&e.to_string(), ctx),
        },
    }
}

/// The root files named by the command line: files as given, folders expanded to their `.rt` files in
/// sorted order; each file once (by canonical path), in the order first named.
pub fn collect_roots(paths: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let mut roots = Vec::new();
    for path in paths {
        let meta = std::fs::metadata(path)
            .map_err(|e| format!("cannot read `{}`: {e}", path.display()))?;
        if meta.is_dir() {
            let before = roots.len();
            walk(path, &mut roots)?;
            if roots.len() == before {
                return Err(format!("no `.rt` files in `{}`", path.display()));
            }
        } else {
            roots.push(path.clone());
        }
    }
    let mut seen = HashSet::new();
    roots.retain(|p| seen.insert(std::fs::canonicalize(p).unwrap_or_else(|_| p.clone())));
    Ok(roots)
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> Result<(), String> {
    let read_err = |e: std::io::Error| format!("cannot read `{}`: {e}", dir.display());
    let mut entries = std::fs::read_dir(dir)
        .map_err(read_err)?
        .collect::<Result<Vec<_>, _>>()
        .map_err(read_err)?;
    entries.sort_by_key(|e| e.file_name());
    for entry in entries {
        let path = entry.path();
        let file_type = entry.file_type().map_err(read_err)?;
        if file_type.is_dir() {
            if !entry.file_name().to_string_lossy().starts_with('.') {
                walk(&path, out)?;
            }
        } else if path.extension().is_some_and(|e| e == "rt") && path.is_file() {
            // `is_file` follows a symbolic link to a file; links to folders are not followed.
            out.push(path);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::collect_roots;
    use std::path::PathBuf;

    #[test]
    fn folders_are_walked_sorted_and_deduplicated() {
        let dir = std::env::temp_dir().join(format!("rtc-cli-walk-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::create_dir_all(dir.join(".hidden")).unwrap();
        for f in ["b.rt", "a.rt", "notes.txt", "sub/c.rt", ".hidden/d.rt"] {
            std::fs::write(dir.join(f), "").unwrap();
        }
        let roots = collect_roots(&[dir.join("b.rt"), dir.clone()]).unwrap();
        let names: Vec<PathBuf> = roots
            .iter()
            .map(|p| p.strip_prefix(&dir).unwrap().to_path_buf())
            .collect();
        assert_eq!(
            names,
            [PathBuf::from("b.rt"), "a.rt".into(), "sub/c.rt".into()]
        );
        assert!(collect_roots(&[dir.join("missing.rt")]).is_err());
        assert!(collect_roots(&[dir.join(".hidden").join("..").join("sub")]).is_ok());
        std::fs::create_dir_all(dir.join("empty")).unwrap();
        assert!(collect_roots(&[dir.join("empty")])
            .unwrap_err()
            .contains("no `.rt` files"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
