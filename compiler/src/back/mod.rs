//! Back ends: a validated `naga::Module` to WGSL, SPIR-V, HLSL, MSL and GLSL.
//!
//! This is the last phase and the only one that talks to naga's writers. For every target it
//! 1. validates the module with `ValidationFlags::all()` **and that back end's own
//!    `supported_capabilities()`**, so a construct the target cannot express becomes a clear error
//!    instead of a back-end panic (naga 30 panics on f64 in MSL, for one);
//! 2. writes the code with binding maps derived from the same binding list (group/binding →
//!    HLSL registers, MSL buffer slots, GLSL `layout(binding = …)`), so every output is usable as is;
//! 3. runs the writer under `catch_unwind`, so a writer bug is an internal error, never a crash.
//!
//! Invariants: the outputs are deterministic (the same module gives byte-identical code), and a
//! failure is always a [`BackendError`] naming the target.

mod listing;

pub use listing::naga_listing;

use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use std::collections::BTreeMap;
use std::panic::AssertUnwindSafe;

/// A code-generation target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    /// WebGPU Shading Language.
    Wgsl,
    /// SPIR-V 1.3 binary for Vulkan 1.1.
    SpirV,
    /// HLSL shader model 6.0.
    Hlsl,
    /// Metal Shading Language 2.1.
    Msl,
    /// GLSL 4.50 core, compute.
    Glsl,
}

impl Target {
    /// Every target, in a fixed order.
    pub const ALL: [Target; 5] = [
        Target::Wgsl,
        Target::SpirV,
        Target::Hlsl,
        Target::Msl,
        Target::Glsl,
    ];

    /// The name used on the command line (`--target wgsl,spirv,…`).
    pub fn name(self) -> &'static str {
        match self {
            Target::Wgsl => "wgsl",
            Target::SpirV => "spirv",
            Target::Hlsl => "hlsl",
            Target::Msl => "msl",
            Target::Glsl => "glsl",
        }
    }

    /// Parses a command-line name.
    pub fn from_name(name: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == name)
    }

    /// The file `rtc compile` writes for this target.
    pub fn file_name(self) -> &'static str {
        match self {
            Target::Wgsl => "kernel.wgsl",
            Target::SpirV => "kernel.spv",
            Target::Hlsl => "kernel.hlsl",
            Target::Msl => "kernel.metal",
            Target::Glsl => "kernel.comp",
        }
    }

    /// The capabilities naga's writer for this target supports.
    pub fn capabilities(self) -> Capabilities {
        match self {
            Target::Wgsl => naga::back::wgsl::supported_capabilities(),
            Target::SpirV => naga::back::spv::supported_capabilities(),
            Target::Hlsl => naga::back::hlsl::supported_capabilities(),
            Target::Msl => naga::back::msl::supported_capabilities(),
            Target::Glsl => naga::back::glsl::supported_capabilities(),
        }
    }
}

/// How a resource is bound, as far as the back ends care.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResourceKind {
    /// A uniform buffer.
    Uniform,
    /// A read-only storage buffer.
    StorageRead,
    /// A read-write storage buffer.
    StorageReadWrite,
}

/// One binding of the kernel, from the ABI table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resource {
    /// Bind group.
    pub group: u32,
    /// Binding within the group.
    pub binding: u32,
    /// Kind.
    pub kind: ResourceKind,
}

/// The most values one function may give names to for the MSL target (see
/// [`BackendError::TooLarge`]).
///
/// naga 30's Metal writer forgets the names of a block's values at the block's end with
/// `IndexMap::shift_remove`, first name first, which moves every later entry: time quadratic in
/// the number of named values of one function (at 30,000 about 3 s in a debug build, at 100,000
/// minutes). Up to this bound the writer takes well under a second in a release build.
pub const MSL_MAX_NAMED_VALUES: usize = 32_768;

/// Why a target could not be written.
#[derive(Clone, Debug, PartialEq)]
pub enum BackendError {
    /// A function is too large for this target's writer (a user limit, not a bug: reported as
    /// E0806 at `span`).
    TooLarge {
        /// The target.
        target: Target,
        /// The function's name.
        function: String,
        /// The number of named values the writer would keep for it.
        values: usize,
        /// The most it accepts.
        limit: usize,
        /// The naga span of the function's first value with a span (maps back to DSL source).
        span: Option<naga::Span>,
    },
    /// The module is invalid, or uses something this target cannot express.
    Validation {
        /// The target being validated for.
        target: Target,
        /// naga's message, with the error chain.
        message: String,
        /// The naga span of the first error, if any (maps back to DSL source).
        span: Option<naga::Span>,
    },
    /// naga's writer returned an error.
    Writer {
        /// The target.
        target: Target,
        /// naga's message.
        message: String,
    },
    /// naga's writer panicked (a bug in naga or in the IR we built).
    Panic {
        /// The target.
        target: Target,
        /// The panic message.
        message: String,
    },
}

impl std::fmt::Display for BackendError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BackendError::TooLarge {
                target,
                function,
                values,
                limit,
                ..
            } => write!(
                f,
                "function `{function}` names {values} values, more than the {} writer handles \
                 ({limit})",
                target.name()
            ),
            BackendError::Validation {
                target, message, ..
            } => {
                write!(
                    f,
                    "the generated {} code does not validate: {message}",
                    target.name()
                )
            }
            BackendError::Writer { target, message } => {
                write!(f, "naga's {} writer failed: {message}", target.name())
            }
            BackendError::Panic { target, message } => {
                write!(f, "naga's {} writer panicked: {message}", target.name())
            }
        }
    }
}

impl std::error::Error for BackendError {}

/// Formats a naga error with its chain of sources.
fn error_chain(e: &dyn std::error::Error) -> String {
    let mut s = e.to_string();
    let mut src = e.source();
    while let Some(inner) = src {
        s.push_str(": ");
        s.push_str(&inner.to_string());
        src = inner.source();
    }
    s
}

/// Validates `module` with every check and the given capabilities.
pub fn validate(
    module: &naga::Module,
    target: Target,
    caps: Capabilities,
) -> Result<ModuleInfo, BackendError> {
    Validator::new(ValidationFlags::all(), caps)
        .validate(module)
        .map_err(|e| BackendError::Validation {
            target,
            message: error_chain(e.as_inner()),
            span: e.spans().next().map(|(span, _)| *span),
        })
}

fn panic_message(p: Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// Runs a writer, turning a panic into [`BackendError::Panic`].
fn guarded<T>(
    target: Target,
    f: impl FnOnce() -> Result<T, BackendError>,
) -> Result<T, BackendError> {
    match std::panic::catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => Err(BackendError::Panic {
            target,
            message: panic_message(p),
        }),
    }
}

fn writer_err(target: Target) -> impl Fn(&dyn std::error::Error) -> BackendError {
    move |e| BackendError::Writer {
        target,
        message: error_chain(e),
    }
}

/// Writes `module` for `target`. `entry_point` is the compute entry point to write (GLSL and MSL write
/// one entry point per file); `resources` are the module's bindings.
///
/// Returns the file's bytes: UTF-8 text, or SPIR-V words in little-endian order.
pub fn write(
    module: &naga::Module,
    target: Target,
    entry_point: &str,
    resources: &[Resource],
) -> Result<Vec<u8>, BackendError> {
    let info = validate(module, target, target.capabilities())?;
    if target == Target::Msl {
        check_named_values(module, &info, target, MSL_MAX_NAMED_VALUES)?;
    }
    guarded(target, || match target {
        Target::Wgsl => write_wgsl(module, &info),
        Target::SpirV => write_spirv(module, &info, entry_point),
        Target::Hlsl => write_hlsl(module, &info, entry_point, resources),
        Target::Msl => write_msl(module, &info, entry_point, resources),
        Target::Glsl => write_glsl(module, &info, entry_point, resources),
    })
}

impl BackendError {
    /// The located diagnostic (E0806) of a user limit; `None` for an internal error (a bug in rtc)
    /// or a span that maps to no file of `sources`.
    pub fn limit_diagnostic(&self, sources: &crate::SourceMap) -> Option<crate::Diagnostic> {
        let BackendError::TooLarge {
            target,
            function,
            values,
            limit,
            span,
        } = self
        else {
            return None;
        };
        let r = span.as_ref()?.to_range()?;
        let at = sources.from_global(r.start as u32, r.end as u32)?;
        Some(
            crate::Diagnostic::error(
                crate::diag::codes::E0806,
                format!(
                    "function `{function}` is too large for the {} target",
                    target.name()
                ),
                at,
            )
            .with_label(format!(
                "the function's {values} named values start here; the {} writer takes at most \
                 {limit}",
                target.name()
            ))
            .with_help(
                "split the function into smaller functions, or leave this target out with \
                 `--target`",
            ),
        )
    }
}

/// [`BackendError::TooLarge`] for the first function (or entry point) in which more than `limit`
/// values would get a name in the written code: the emitted values the lowering named (`let`s) and
/// those the writers store in a temporary because they are used more than once.
pub fn check_named_values(
    module: &naga::Module,
    info: &ModuleInfo,
    target: Target,
    limit: usize,
) -> Result<(), BackendError> {
    let functions = module.functions.iter().map(|(h, f)| (f, &info[h])).chain(
        module
            .entry_points
            .iter()
            .enumerate()
            .map(|(i, ep)| (&ep.function, info.get_entry_point(i))),
    );
    for (f, fi) in functions {
        if f.expressions.len() <= limit {
            continue;
        }
        let values = f
            .expressions
            .iter()
            .filter(|(h, e)| {
                !e.needs_pre_emit()
                    && (f.named_expressions.contains_key(h)
                        || fi[*h].ref_count >= e.bake_ref_count())
            })
            .count();
        if values > limit {
            let span = f
                .expressions
                .iter()
                .map(|(h, _)| f.expressions.get_span(h))
                .find(|s| s.is_defined());
            return Err(BackendError::TooLarge {
                target,
                function: f.name.clone().unwrap_or_default(),
                values,
                limit,
                span,
            });
        }
    }
    Ok(())
}

fn write_wgsl(module: &naga::Module, info: &ModuleInfo) -> Result<Vec<u8>, BackendError> {
    let text = naga::back::wgsl::write_string(module, info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| writer_err(Target::Wgsl)(&e))?;
    Ok(text.into_bytes())
}

fn write_spirv(
    module: &naga::Module,
    info: &ModuleInfo,
    entry_point: &str,
) -> Result<Vec<u8>, BackendError> {
    use naga::back::spv;
    let options = spv::Options {
        lang_version: (1, 3),
        flags: spv::WriterFlags::empty(),
        ..spv::Options::default()
    };
    let pipeline = spv::PipelineOptions {
        shader_stage: naga::ShaderStage::Compute,
        entry_point: entry_point.into(),
    };
    let words = spv::write_vec(module, info, &options, Some(&pipeline))
        .map_err(|e| writer_err(Target::SpirV)(&e))?;
    Ok(words.iter().flat_map(|w| w.to_le_bytes()).collect())
}

fn write_hlsl(
    module: &naga::Module,
    info: &ModuleInfo,
    entry_point: &str,
    resources: &[Resource],
) -> Result<Vec<u8>, BackendError> {
    use naga::back::hlsl;
    let mut binding_map = hlsl::BindingMap::new();
    for r in resources {
        binding_map.insert(
            naga::ResourceBinding {
                group: r.group,
                binding: r.binding,
            },
            hlsl::BindTarget {
                space: r.group as u8,
                register: r.binding,
                binding_array_size: None,
                dynamic_storage_buffer_offsets_index: None,
                restrict_indexing: false,
            },
        );
    }
    let options = hlsl::Options {
        shader_model: hlsl::ShaderModel::V6_0,
        binding_map,
        fake_missing_bindings: false,
        ..hlsl::Options::default()
    };
    let pipeline = hlsl::PipelineOptions {
        entry_point: Some((naga::ShaderStage::Compute, entry_point.into())),
    };
    let mut out = String::new();
    hlsl::Writer::new(&mut out, &options, &pipeline)
        .write(module, info, None)
        .map_err(|e| writer_err(Target::Hlsl)(&e))?;
    Ok(out.into_bytes())
}

fn write_msl(
    module: &naga::Module,
    info: &ModuleInfo,
    entry_point: &str,
    resources: &[Resource],
) -> Result<Vec<u8>, BackendError> {
    use naga::back::msl;
    let mut map = msl::BindingMap::new();
    let mut max_slot = 0u8;
    for r in resources {
        let slot = u8::try_from(r.binding).unwrap_or(u8::MAX);
        max_slot = max_slot.max(slot);
        map.insert(
            naga::ResourceBinding {
                group: r.group,
                binding: r.binding,
            },
            msl::BindTarget {
                buffer: Some(slot),
                mutable: r.kind == ResourceKind::StorageReadWrite,
                ..msl::BindTarget::default()
            },
        );
    }
    let mut per_entry_point_map = BTreeMap::new();
    per_entry_point_map.insert(
        entry_point.to_string(),
        msl::EntryPointResources {
            resources: map,
            immediates_buffer: None,
            sizes_buffer: Some(max_slot.saturating_add(1)),
        },
    );
    let options = msl::Options {
        lang_version: (2, 1),
        per_entry_point_map,
        fake_missing_bindings: false,
        ..msl::Options::default()
    };
    let pipeline = msl::PipelineOptions {
        entry_point: Some((naga::ShaderStage::Compute, entry_point.into())),
        ..msl::PipelineOptions::default()
    };
    let (text, _) = msl::write_string(module, info, &options, &pipeline)
        .map_err(|e| writer_err(Target::Msl)(&e))?;
    Ok(text.into_bytes())
}

fn write_glsl(
    module: &naga::Module,
    info: &ModuleInfo,
    entry_point: &str,
    resources: &[Resource],
) -> Result<Vec<u8>, BackendError> {
    use naga::back::glsl;
    let mut binding_map = glsl::BindingMap::new();
    for r in resources {
        binding_map.insert(
            naga::ResourceBinding {
                group: r.group,
                binding: r.binding,
            },
            u8::try_from(r.binding).unwrap_or(u8::MAX),
        );
    }
    let options = glsl::Options {
        version: glsl::Version::Desktop(450),
        writer_flags: glsl::WriterFlags::empty(),
        binding_map,
        zero_initialize_workgroup_memory: true,
    };
    let pipeline = glsl::PipelineOptions {
        shader_stage: naga::ShaderStage::Compute,
        entry_point: entry_point.into(),
        multiview: None,
    };
    let mut out = String::new();
    let policies = naga::proc::BoundsCheckPolicies::default();
    glsl::Writer::new(&mut out, module, info, &options, &pipeline, policies)
        .and_then(|mut w| w.write())
        .map_err(|e| writer_err(Target::Glsl)(&e))?;
    Ok(out.into_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    const KERNEL: &str = r#"
struct Params { count: u32, scale: f32 }
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> input: array<f32>;
@group(0) @binding(2) var<storage, read_write> output: array<vec4<f32>>;

fn pick(id: u32) -> f32 {
    switch id % 3u {
        case 0u: { return 1.0; }
        case 1u, 2u: { return 2.0; }
        default: { return 0.0; }
    }
}

@compute @workgroup_size(64)
fn render(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count { return; }
    var stack: array<u32, 8>;
    stack[gid.x % 8u] = gid.x;
    output[gid.x] = vec4<f32>(input[gid.x] * params.scale * pick(stack[gid.x % 8u]));
}
"#;

    const RESOURCES: [Resource; 3] = [
        Resource {
            group: 0,
            binding: 0,
            kind: ResourceKind::Uniform,
        },
        Resource {
            group: 0,
            binding: 1,
            kind: ResourceKind::StorageRead,
        },
        Resource {
            group: 0,
            binding: 2,
            kind: ResourceKind::StorageReadWrite,
        },
    ];

    #[test]
    fn every_target_writes() {
        let module = naga::front::wgsl::parse_str(KERNEL).expect("test kernel parses");
        for target in Target::ALL {
            let bytes = write(&module, target, "render", &RESOURCES)
                .unwrap_or_else(|e| panic!("{}: {e}", target.name()));
            assert!(!bytes.is_empty());
            if target == Target::SpirV {
                assert_eq!(
                    &bytes[..4],
                    &0x0723_0203u32.to_le_bytes(),
                    "SPIR-V magic number"
                );
            }
        }
        let glsl =
            String::from_utf8(write(&module, Target::Glsl, "render", &RESOURCES).unwrap()).unwrap();
        assert!(
            glsl.contains("binding = 2"),
            "GLSL has explicit bindings:\n{glsl}"
        );
    }

    #[test]
    fn output_is_deterministic() {
        let module = naga::front::wgsl::parse_str(KERNEL).unwrap();
        for target in Target::ALL {
            assert_eq!(
                write(&module, target, "render", &RESOURCES).unwrap(),
                write(&module, target, "render", &RESOURCES).unwrap()
            );
        }
    }

    #[test]
    fn unsupported_feature_is_an_error_not_a_panic() {
        // f64 is accepted by SPIR-V but not by MSL (whose writer panics on it when not validated).
        let mut module = naga::Module::default();
        let f64_ty = module.types.insert(
            naga::Type {
                name: None,
                inner: naga::TypeInner::Scalar(naga::Scalar::F64),
            },
            naga::Span::UNDEFINED,
        );
        module.global_variables.append(
            naga::GlobalVariable {
                name: Some("x".into()),
                space: naga::AddressSpace::Private,
                binding: None,
                ty: f64_ty,
                init: None,
                memory_decorations: Default::default(),
            },
            naga::Span::UNDEFINED,
        );
        let err = write(&module, Target::Msl, "render", &[]).unwrap_err();
        assert!(
            matches!(
                err,
                BackendError::Validation {
                    target: Target::Msl,
                    ..
                }
            ),
            "{err:?}"
        );
    }
}
