//! Rendering the errors of statements ([`StmtError`]: E0205, E05xx), programs ([`ProgramError`]:
//! E06xx), scenes ([`SceneError`]: E0701–E0705), the call graph ([`CallGraphError`]: E0801, E0802)
//! and the static limits ([`LimitError`]: E0803–E0805), the warnings ([`Warning`]: W0001–W0003), and
//! the scene choice (E0706); one exhaustive match per group.

use super::{
    err, expected_signature, list, AttrArgError, CallGraphError, Expected, LimitError,
    ProgramError, SceneError, StmtError, Unbounded, Warning, R,
};
use crate::diag::{codes, Diagnostic};
use crate::sema::builtins::Builtin;
use crate::sema::hir::{LocalKind, ProgramKind};
use crate::sema::types::{ScalarKind, Type};
use crate::source::Span;

impl StmtError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use StmtError as E;
        match self {
            E::AssignImmutable {
                span,
                name,
                kind,
                decl,
            } => {
                let what = match kind {
                    Some(LocalKind::Param) => "parameter",
                    Some(LocalKind::For) => "loop variable",
                    Some(LocalKind::Let | LocalKind::Var) => "immutable binding",
                    None => "constant",
                };
                let d = err(
                    codes::E0501,
                    format!("cannot assign to {what} `{name}`"),
                    *span,
                )
                .with_label("assigned here")
                .with_secondary(*decl, format!("`{name}` declared here"));
                match kind {
                    Some(LocalKind::Let) => {
                        d.with_help(format!("declare it with `var {name}` to make it mutable"))
                    }
                    Some(LocalKind::Param) => d.with_help(format!(
                        "copy it into a variable first: `var {name}_ = {name};`"
                    )),
                    Some(LocalKind::Var | LocalKind::For) | None => d,
                }
            }
            E::BadAssignTarget {
                span,
                multi_swizzle,
            } => {
                if *multi_swizzle {
                    err(
                        codes::E0205,
                        "cannot assign to a swizzle of several components",
                        *span,
                    )
                    .with_label("several components")
                    .with_help("assign the components one by one, or the whole vector")
                } else {
                    err(codes::E0205, "invalid assignment target", *span)
                        .with_label("not a variable, field, component or element")
                }
            }
            E::OutsideLoop { span, keyword } => {
                err(codes::E0502, format!("`{keyword}` outside a loop"), *span).with_label(format!(
                    "`{keyword}` is only valid in `for`, `while` and `loop`"
                ))
            }
            E::MissingReturn { span, ret, end } => err(
                codes::E0503,
                "this function may end without returning a value",
                *span,
            )
            .with_label(format!("returns {}", r.ty(*ret)))
            .with_secondary(*end, "the end of the body is reachable")
            .with_help("add a `return` on every path"),
            E::ReturnMismatch { span, expected } => match expected {
                Some(t) => err(
                    codes::E0504,
                    format!("`return` needs a value of type {}", r.ty(*t)),
                    *span,
                )
                .with_label("no value"),
                None => err(
                    codes::E0504,
                    "this function returns nothing, but `return` has a value",
                    *span,
                )
                .with_label("unexpected value")
                .with_help("add a return type (`-> T`) or remove the value"),
            },
            E::ConditionNotBool { span, found } => {
                let d = err(codes::E0505, "a condition must be a `bool`", *span)
                    .with_label(format!("this is {}", r.ty(*found)));
                match r.p.types.get(*found) {
                    Type::Scalar(k) if k.is_numeric() => d.with_help(format!(
                        "there is no truthiness; compare explicitly: `{} != {}`",
                        r.snippet(*span),
                        match k {
                            ScalarKind::F32 => "0.0",
                            ScalarKind::U32 => "0u",
                            ScalarKind::I32 | ScalarKind::Bool => "0",
                        }
                    )),
                    Type::Vector {
                        scalar: ScalarKind::Bool,
                        ..
                    } => d.with_help("reduce it with `all(…)` or `any(…)`"),
                    _ => d,
                }
            }
            E::BadRange { span, start, end } => err(
                codes::E0506,
                format!(
                    "a `for` range needs two `i32`s or two `u32`s, found {} and {}",
                    r.ty(*start),
                    r.ty(*end)
                ),
                *span,
            )
            .with_label("invalid range"),
        }
    }
}

impl ProgramError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use ProgramError as E;
        match self {
            E::Signature {
                span,
                kind,
                struct_name,
                found,
            } => err(
                codes::E0601,
                format!("this `@{}` program has the wrong signature", kind.name()),
                *span,
            )
            .with_label(format!("found `{found}`"))
            .with_note(format!(
                "a `@{}` program has the signature `{}`",
                kind.name(),
                expected_signature(*kind, struct_name)
            )),
            E::MisplacedAttribute {
                span,
                attr,
                item,
                hint,
            } => {
                let d = err(
                    codes::E0602,
                    format!("`@{attr}` cannot be used on {item}"),
                    *span,
                )
                .with_label("misplaced attribute");
                match hint {
                    Some(h) => d.with_help(*h),
                    None => d,
                }
            }
            E::NotRoleStruct {
                span,
                kind,
                found,
                found_role,
            } => {
                let role = kind.role().name();
                let d = err(
                    codes::E0603,
                    format!(
                        "the first parameter of a `@{}` program must be a `@{role}` struct",
                        kind.name()
                    ),
                    *span,
                );
                match found_role {
                    Some(fr) => {
                        d.with_label(format!("{} is a `@{}` struct", r.ty(*found), fr.name()))
                    }
                    None => d
                        .with_label(format!("{} has no `@{role}` role", r.ty(*found)))
                        .with_help(format!("declare the struct with `@{role}`")),
                }
            }
            E::IntrinsicNotAllowed {
                span,
                func,
                kind,
                chain,
                program,
            } => {
                let allowed = allowed_kinds(*func);
                let mut d = err(
                    codes::E0604,
                    format!(
                        "`{}` cannot be called from a `@{}` program",
                        func.name(),
                        kind.name()
                    ),
                    *span,
                )
                .with_label(format!("not allowed in `@{}`", kind.name()))
                .with_secondary(*program, format!("the `@{}` program", kind.name()));
                if chain.len() > 1 {
                    d = d.with_note(format!(
                        "called through {} → `{}`",
                        chain
                            .iter()
                            .map(|c| format!("`{c}`"))
                            .collect::<Vec<_>>()
                            .join(" → "),
                        func.name()
                    ));
                }
                d.with_note(format!("`{}` may be called from {allowed}", func.name()))
            }
            E::NotStorable { span, ty, role } => err(
                codes::E0605,
                format!(
                    "a field of a `@{}` struct cannot have type {}",
                    role.name(),
                    r.ty(*ty)
                ),
                *span,
            )
            .with_label("not storable in scene data")
            .with_note(
                "fields of role structs are scalars, vectors, matrices, arrays and structs of \
                 those, `texture` and `mesh`",
            ),
            E::BadAttributeArg { span, attr, reason } => {
                let (msg, help) = match reason {
                    AttrArgError::NoArgs => (format!("`@{attr}` takes no arguments"), None),
                    AttrArgError::Unknown(n) => (
                        format!("`@{attr}` has no argument `{n}`"),
                        (attr == "ray_generation").then_some("the only argument is `samples = N`"),
                    ),
                    AttrArgError::Samples => (
                        "`samples` must be a positive `u32` constant".to_string(),
                        Some("write e.g. `@ray_generation(samples = 4)`"),
                    ),
                };
                let d = err(codes::E0606, msg, *span).with_label("invalid argument");
                match help {
                    Some(h) => d.with_help(h),
                    None => d,
                }
            }
            E::DuplicateProgram {
                span,
                first,
                kind,
                ty,
            } => err(
                codes::E0607,
                format!("{} has two `@{}` programs", r.ty(*ty), kind.name()),
                *span,
            )
            .with_label("second program")
            .with_secondary(*first, "first program")
            .with_help("a struct has at most one program of each kind"),
            E::TwoRoles { span, first } => {
                err(codes::E0608, "a struct has at most one role", *span)
                    .with_label("second role")
                    .with_secondary(*first, "first role")
            }
        }
    }
}

impl SceneError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use SceneError as E;
        match self {
            E::UnknownEntry {
                span,
                name,
                place,
                known,
            } => {
                let d = err(codes::E0701, format!("unknown {place} `{name}`"), *span)
                    .with_label(format!("not a known {place}"));
                match crate::diag::suggest::closest(name, known.iter().copied()) {
                    Some(s) => d.with_help(format!("did you mean `{s}`?")),
                    None => d.with_help(format!(
                        "the known ones are {}",
                        list(&known.iter().map(|k| k.to_string()).collect::<Vec<_>>())
                    )),
                }
            }
            E::WrongRole {
                span,
                expected,
                found,
                found_role,
            } => {
                let want = match expected {
                    Expected::Role(role) => format!("a `@{}` instance", role.name()),
                    Expected::Geometry => "a mesh or a `@geometry` instance".to_string(),
                };
                let got = match found_role {
                    Some(fr) => format!("{} is a `@{}` struct", r.ty(*found), fr.name()),
                    None => format!("found {}", r.ty(*found)),
                };
                err(codes::E0702, format!("expected {want}"), *span).with_label(got)
            }
            E::MissingEntry { span, what, place } => {
                err(codes::E0703, format!("{place} has no {what}"), *span)
                    .with_label(format!("missing {what}"))
            }
            E::SettingRange {
                span,
                key,
                value,
                lo,
                hi,
            } => {
                let d = err(
                    codes::E0704,
                    format!("`{key}` must be in {lo} ..= {hi}"),
                    *span,
                )
                .with_label(format!("this is {value}"));
                if *key == "exec" {
                    d.with_help("write `EXEC_AUTO`, `EXEC_MEGAKERNEL` or `EXEC_WAVEFRONT`")
                } else {
                    d
                }
            }
            E::DuplicateEntry { span, first, what } => {
                err(codes::E0705, format!("{what} is given twice"), *span)
                    .with_label("given again here")
                    .with_secondary(*first, "first given here")
            }
        }
    }
}

impl CallGraphError {
    pub(super) fn render(&self) -> Diagnostic {
        use CallGraphError as E;
        match self {
            E::Recursion { span, cycle, what } => err(
                codes::E0801,
                format!(
                    "{what} `{}` depends on itself",
                    cycle.first().map(String::as_str).unwrap_or("")
                ),
                *span,
            )
            .with_label("recursive use here")
            .with_note(format!(
                "the cycle is {}",
                cycle
                    .iter()
                    .map(|c| format!("`{c}`"))
                    .collect::<Vec<_>>()
                    .join(" → ")
            ))
            .with_note(if *what == "function" {
                "GPUs have no call stack; trace secondary rays with `spawn` instead of recursion"
            } else {
                "a value cannot be defined in terms of itself"
            }),
            E::UnboundedSpawn {
                span,
                why,
                loop_span,
                program,
            } => {
                let l = match why {
                    Unbounded::While => "a `while` loop",
                    Unbounded::Loop => "a `loop`",
                    Unbounded::For => "a `for` loop with non-constant bounds",
                };
                err(
                    codes::E0802,
                    format!("the rays spawned by `{program}` cannot be bounded"),
                    *span,
                )
                .with_label(format!("spawns inside {l}"))
                .with_secondary(*loop_span, "this loop has no constant trip count")
                .with_help("spawn in a `for` loop with constant bounds, e.g. `for i in 0u..4u`")
            }
        }
    }
}

impl LimitError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use LimitError as E;
        match self {
            E::TypeTooLarge { span, ty, bytes } => err(
                codes::E0803,
                format!("the type {} is too large", r.ty(*ty)),
                *span,
            )
            .with_label(format!("this type takes {}", bytes_text(*bytes)))
            .with_note(format!(
                "no value may exceed {}: the largest storage buffer binding WebGPU guarantees, \
                 which holds the scene's parameters",
                bytes_text(crate::sema::sizes::MAX_TYPE_BYTES)
            ))
            .with_help("use fewer or smaller elements"),
            E::PrivateMemory {
                span,
                function,
                bytes,
                callee,
            } => {
                let budget = bytes_text(crate::sema::sizes::PRIVATE_MEMORY_BUDGET);
                let label = match callee {
                    None => format!(
                        "the arrays and structs of `{function}` take {} up to here",
                        bytes_text(*bytes)
                    ),
                    Some((c, cb)) => format!(
                        "with this call to `{c}` ({} with its callees), `{function}` needs {}",
                        bytes_text(*cb),
                        bytes_text(*bytes)
                    ),
                };
                err(
                    codes::E0804,
                    format!(
                        "`{function}` needs more than the {budget} of private memory one invocation has"
                    ),
                    *span,
                )
                .with_label(label)
                .with_note(format!(
                    "each GPU thread keeps its local arrays and structs in private memory; user \
                     functions get {budget}, with their callees (spec/types.md, \"Size limits\")"
                ))
                .with_help("use smaller arrays, or keep large data in the scene (a `mesh` or `texture`)")
            }
            E::ConstTooLarge { span, scalars } => err(
                codes::E0805,
                "this constant is too large to evaluate",
                *span,
            )
            .with_label(format!("a value of {scalars} scalars"))
            .with_note(format!(
                "constant values have at most {} scalars (numbers and booleans)",
                crate::sema::consteval::MAX_CONST_SCALARS
            ))
            .with_help("build large arrays in a function at run time instead of as a constant"),
        }
    }
}

impl Warning {
    pub(super) fn render(&self) -> Diagnostic {
        use Warning as E;
        match self {
            E::UnusedVariable { span, name } => {
                Diagnostic::warning(codes::W0001, format!("unused variable `{name}`"), *span)
                    .with_label("never read")
                    .with_help(format!(
                        "if this is intentional, prefix it with an underscore: `_{name}`"
                    ))
            }
            E::UnusedValue { span } => Diagnostic::warning(
                codes::W0002,
                "the value of this expression is unused",
                *span,
            )
            .with_label("value dropped"),
            E::Unreachable { span, cause } => {
                Diagnostic::warning(codes::W0003, "unreachable code", *span)
                    .with_label("never executed")
                    .with_secondary(*cause, "any code after this is unreachable")
            }
        }
    }
}

fn allowed_kinds(func: Builtin) -> String {
    let kinds: Vec<String> = ProgramKind::ALL
        .iter()
        .filter(|k| func.info().allowed.allows(**k))
        .map(|k| format!("`@{}`", k.name()))
        .collect();
    kinds.join(", ")
}

impl crate::sema::hir::SceneChoiceError {
    /// The diagnostic for a failed scene choice (E0706), or `None` when there is no scene at all.
    pub fn to_diagnostic(&self) -> Option<Diagnostic> {
        use crate::sema::hir::SceneChoiceError as C;
        match self {
            C::NoScene => None,
            C::Ambiguous { scenes } => {
                let (first, rest) = scenes.split_first()?;
                let (_, second) = rest.first()?;
                let mut d = Diagnostic::error(codes::E0706, "more than one scene", *second)
                    .with_label("another scene")
                    .with_secondary(first.1, "a scene");
                for (_, s) in rest.iter().skip(1) {
                    d = d.with_secondary(*s, "another scene");
                }
                let names: Vec<String> = scenes.iter().map(|(n, _)| n.clone()).collect();
                Some(d.with_help(format!("choose one with `--scene NAME`: {}", list(&names))))
            }
            C::NotFound { name, available } => Some(
                Diagnostic::error(
                    codes::E0706,
                    format!("no scene named `{name}`"),
                    Span::default(),
                )
                .with_help(format!("the scenes are {}", list(available))),
            ),
        }
    }
}

/// A byte count as "N bytes", or in KiB/MiB/GiB when exact enough to be readable.
fn bytes_text(b: u64) -> String {
    const KIB: u64 = 1024;
    match b {
        b if b >= KIB * KIB * KIB => {
            format!("{:.1} GiB ({b} bytes)", b as f64 / (KIB * KIB * KIB) as f64)
        }
        b if b >= KIB * KIB => format!("{:.1} MiB ({b} bytes)", b as f64 / (KIB * KIB) as f64),
        b if b >= KIB => format!("{:.1} KiB ({b} bytes)", b as f64 / KIB as f64),
        b => format!("{b} bytes"),
    }
}
