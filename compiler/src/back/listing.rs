//! A readable listing of a naga module (`rtc compile --emit naga`): the module as naga's WGSL writer
//! prints it, each item preceded by a comment with its naga handle.
//!
//! naga's arenas are what the IR refers to (`Handle<Function>` 3, global 2, …), while WGSL names
//! are what a reader sees; the listing shows both. It starts with a summary (how many types,
//! constants, globals, functions and entry points), then the WGSL text in which every struct, named
//! constant, global, function and entry point is preceded by `// type [i]`, `// constant [i]`,
//! `// global [i]`, `// function [i]` or `// entry point [i]`.
//!
//! Guarantees: deterministic (the WGSL writer is, and the handles follow the arenas' order, which is
//! the order the writer prints items in: structs, named constants, globals, functions, entry
//! points); the code is exactly what `--target wgsl` writes, comments aside. Where the count of
//! items of a kind the writer printed differs from the module's (a struct naga declares for itself,
//! say), that kind is left unannotated rather than annotated wrongly.

use super::{validate, BackendError, Target};

/// The listing of `module` (see the module doc). Fails like the WGSL target does.
pub fn naga_listing(module: &naga::Module) -> Result<String, BackendError> {
    let info = validate(module, Target::Wgsl, Target::Wgsl.capabilities())?;
    let wgsl =
        naga::back::wgsl::write_string(module, &info, naga::back::wgsl::WriterFlags::empty())
            .map_err(|e| super::writer_err(Target::Wgsl)(&e))?;

    let structs: Vec<usize> = module
        .types
        .iter()
        .filter(|(_, t)| matches!(t.inner, naga::TypeInner::Struct { .. }))
        .map(|(h, _)| h.index())
        .collect();
    let constants: Vec<usize> = module
        .constants
        .iter()
        .filter(|(_, c)| c.name.is_some())
        .map(|(h, _)| h.index())
        .collect();
    let globals: Vec<usize> = module
        .global_variables
        .iter()
        .map(|(h, _)| h.index())
        .collect();
    // Functions, then entry points: the writer prints both as top-level `fn`.
    let functions: Vec<String> = module
        .functions
        .iter()
        .map(|(h, _)| format!("function [{}]", h.index()))
        .chain((0..module.entry_points.len()).map(|i| format!("entry point [{i}]")))
        .collect();

    let lines: Vec<&str> = wgsl.lines().collect();
    let starts = |prefix: &str| -> usize { lines.iter().filter(|l| l.starts_with(prefix)).count() };
    let global_lines = lines.iter().filter(|l| is_global(l)).count();
    let fn_lines = lines.iter().filter(|l| is_fn(l)).count();
    let mut labels = Labels {
        structs: (starts("struct ") == structs.len()).then_some(structs.iter()),
        constants: (starts("const ") == constants.len()).then_some(constants.iter()),
        globals: (global_lines == globals.len()).then_some(globals.iter()),
        functions: (fn_lines == functions.len()).then_some(functions.iter()),
    };

    let mut out = format!(
        "// naga module: types {}, constants {}, globals {}, functions {}, entry points {}\n\
         // (WGSL as `--target wgsl` writes it; `// kind [i]` is the naga handle of the item below)\n\n",
        module.types.len(),
        module.constants.len(),
        module.global_variables.len(),
        module.functions.len(),
        module.entry_points.len()
    );
    // Attributes (an entry point's, a global's binding) come on the lines before the item: the
    // label goes above them.
    let mut pending: Vec<&str> = Vec::new();
    for line in lines {
        if line.starts_with('@') {
            pending.push(line);
            continue;
        }
        let label = if line.starts_with("struct ") {
            labels
                .structs
                .as_mut()
                .and_then(Iterator::next)
                .map(|i| format!("type [{i}]"))
        } else if line.starts_with("const ") {
            labels
                .constants
                .as_mut()
                .and_then(Iterator::next)
                .map(|i| format!("constant [{i}]"))
        } else if is_global(line) {
            labels
                .globals
                .as_mut()
                .and_then(Iterator::next)
                .map(|i| format!("global [{i}]"))
        } else if is_fn(line) {
            labels.functions.as_mut().and_then(Iterator::next).cloned()
        } else {
            None
        };
        if let Some(label) = label {
            out.push_str("// ");
            out.push_str(&label);
            out.push('\n');
        }
        for p in pending.drain(..) {
            out.push_str(p);
            out.push('\n');
        }
        out.push_str(line);
        out.push('\n');
    }
    for p in pending {
        out.push_str(p);
        out.push('\n');
    }
    Ok(out)
}

/// The handles still to be printed, per kind; `None` for a kind left unannotated.
struct Labels<'a> {
    structs: Option<std::slice::Iter<'a, usize>>,
    constants: Option<std::slice::Iter<'a, usize>>,
    globals: Option<std::slice::Iter<'a, usize>>,
    functions: Option<std::slice::Iter<'a, String>>,
}

/// A global variable's line (`var<…> name: T;`, after its `@group(…) @binding(…)` line), at top
/// level.
fn is_global(line: &str) -> bool {
    line.starts_with("var<") || line.starts_with("var ")
}

/// A function's (or entry point's) first line, at top level.
fn is_fn(line: &str) -> bool {
    line.starts_with("fn ")
}
