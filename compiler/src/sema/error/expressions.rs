//! Rendering the errors of modules and imports ([`ModuleError`]: E0108, E0301, E0302), of names
//! ([`NameError`]: E0203, E0303–E0307, E0413) and of types and expressions ([`ExprError`]: E04xx),
//! one exhaustive match per group.

use super::{err, list, CtorError, ExprError, ModuleError, NameError, NameKind, R};
use crate::diag::{codes, Diagnostic};
use crate::sema::builtins;
use crate::sema::consteval::NotConst;
use crate::sema::types::{ScalarKind, Type, TypeId};
use crate::source::Span;

impl ModuleError {
    pub(super) fn render(&self) -> Diagnostic {
        use ModuleError as E;
        match self {
            E::InvalidUtf8 { file, offset } => err(
                codes::E0108,
                "the file is not valid UTF-8",
                Span::new(*file, *offset, *offset),
            )
            .with_label("the first invalid byte is here")
            .with_help("save the file as UTF-8"),
            E::ImportNotFound { span, path, close } => {
                let d = err(
                    codes::E0301,
                    format!("cannot find the module `{path}`"),
                    *span,
                )
                .with_label("no such file");
                if close.is_empty() {
                    d
                } else {
                    d.with_help(format!(
                        "a file with a similar name exists in that folder: {}",
                        list(close)
                    ))
                }
            }
            E::Unreadable { span, path, reason } => err(
                codes::E0301,
                format!("cannot read `{path}`: {reason}"),
                *span,
            ),
            E::ImportCycle { span, chain } => err(codes::E0302, "import cycle", *span)
                .with_label("this import closes a cycle")
                .with_note(format!("the imports form a cycle: {}", chain.join(" → ")))
                .with_help("move what both modules need into a third module that both import"),
        }
    }
}

impl NameError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use NameError as E;
        match self {
            E::UnknownAttribute { span, name } => {
                err(codes::E0203, format!("unknown attribute `@{name}`"), *span).with_help(
                    "the attributes are the struct roles `@camera`, `@geometry`, `@material`, \
                     `@light`, `@background` and the program kinds `@ray_generation`, \
                     `@intersection`, `@bounds`, `@any_hit`, `@closest_hit`, `@secondary_rays`, \
                     `@medium`, `@light`, `@miss`",
                )
            }
            E::Undefined {
                span,
                name,
                suggestion,
                elsewhere,
            } => {
                let d = err(
                    codes::E0303,
                    format!("cannot find `{name}` in this scope"),
                    *span,
                )
                .with_label("not found");
                match (elsewhere, suggestion) {
                    (Some(m), _) => d.with_help(format!(
                        "`{name}` is declared in `{m}`, which this module does not import \
                         (imports are not transitive)"
                    )),
                    (None, Some(s)) => {
                        d.with_help(format!("a name with a similar spelling exists: `{s}`"))
                    }
                    (None, None) => d,
                }
            }
            E::DefinedLater { span, name, def } => err(
                codes::E0303,
                format!("cannot find `{name}` in this scope"),
                *span,
            )
            .with_label("used before its `let`")
            .with_secondary(*def, "defined here, later in the scene")
            .with_help("a scene `let` is visible to the entries after it; move it up"),
            E::Duplicate { span, first, name } => {
                err(codes::E0304, format!("`{name}` is defined twice"), *span)
                    .with_label(format!("`{name}` redefined here"))
                    .with_secondary(*first, "first defined here")
            }
            E::Ambiguous {
                span,
                name,
                modules,
                defs,
            } => err(codes::E0305, format!("`{name}` is ambiguous"), *span)
                .with_label(format!(
                    "imported from both `{}` and `{}`",
                    modules[0], modules[1]
                ))
                .with_secondary(defs[0], format!("`{name}` in `{}`", modules[0]))
                .with_secondary(defs[1], format!("`{name}` in `{}`", modules[1]))
                .with_help(
                    "rename one of them (a declaration in this module would take precedence)",
                ),
            E::NotAValue { span, name, kind } => {
                let d = err(
                    codes::E0306,
                    format!("expected a value, found {} `{name}`", kind.describe()),
                    *span,
                )
                .with_label("not a value");
                match kind {
                    NameKind::Struct => {
                        d.with_help(format!("write a struct literal: `{name} {{ … }}`"))
                    }
                    NameKind::Function | NameKind::Builtin => {
                        d.with_note("functions are not values; call it with `(…)`")
                    }
                    NameKind::Type | NameKind::Const | NameKind::Local | NameKind::Scene => d,
                }
            }
            E::NotAType { span, name, kind } => err(
                codes::E0306,
                format!("expected a type, found {} `{name}`", kind.describe()),
                *span,
            )
            .with_label("not a type"),
            E::NotAStruct { span, name, kind } => err(
                codes::E0306,
                format!("expected a struct, found {} `{name}`", kind.describe()),
                *span,
            )
            .with_label("not a struct"),
            E::BadGenerics {
                span,
                name,
                expected,
            } => err(
                codes::E0413,
                format!("invalid generic arguments for `{name}`"),
                *span,
            )
            .with_label(format!("`{name}` takes {expected}")),
            E::UnknownField {
                span,
                ty,
                field,
                suggestion,
                decl,
            } => {
                let mut d = err(
                    codes::E0307,
                    format!("no field `{field}` on {}", r.ty(*ty)),
                    *span,
                )
                .with_label("unknown field");
                if let Some(decl) = decl {
                    d = d.with_secondary(*decl, format!("{} declared here", r.ty(*ty)));
                }
                match suggestion {
                    Some(s) => d.with_help(format!("did you mean `{s}`?")),
                    None => d,
                }
            }
        }
    }
}

impl ExprError {
    pub(super) fn render(&self, r: &R) -> Diagnostic {
        use ExprError as E;
        match self {
            E::Mismatch {
                span,
                expected,
                found,
            } => {
                let d = err(codes::E0401, "mismatched types", *span).with_label(format!(
                    "expected {}, found {}",
                    r.ty(*expected),
                    r.ty(*found)
                ));
                match r.conversion(*found, *expected, *span) {
                    Some(h) => d.with_help(h),
                    None => d,
                }
            }
            E::BadOperands {
                span,
                op,
                lhs,
                rhs,
                lhs_span,
                rhs_span,
            } => {
                let d = err(
                    codes::E0402,
                    format!("cannot apply `{op}` to {} and {}", r.ty(*lhs), r.ty(*rhs)),
                    *span,
                )
                .with_label(format!(
                    "{} {op} {}",
                    r.p.type_name(*lhs),
                    r.p.type_name(*rhs)
                ));
                match operand_help(r, *lhs, *rhs, *lhs_span, *rhs_span) {
                    Some(h) => d.with_help(h),
                    None => d,
                }
            }
            E::BadUnary { span, op, ty } => err(
                codes::E0402,
                format!("cannot apply unary `{op}` to {}", r.ty(*ty)),
                *span,
            )
            .with_label(format!("{op}{}", r.p.type_name(*ty))),
            E::Arity {
                span,
                name,
                expected,
                found,
                decl,
            } => {
                let exp: Vec<String> = expected.iter().map(|n| n.to_string()).collect();
                let plural = |n: usize| if n == 1 { "argument" } else { "arguments" };
                let last = expected.last().copied().unwrap_or(0);
                let mut d = err(
                    codes::E0403,
                    format!(
                        "`{name}` takes {} {}, but {found} {} given",
                        exp.join(" or "),
                        plural(last),
                        if *found == 1 { "was" } else { "were" }
                    ),
                    *span,
                )
                .with_label(format!("{found} {}", plural(*found)));
                if let Some(decl) = decl {
                    d = d.with_secondary(*decl, format!("`{name}` declared here"));
                }
                d
            }
            E::NoOverload { span, func, args } => {
                let (sigs, wheres) = builtins::signatures(*func);
                let found: Vec<String> = args.iter().map(|a| r.p.type_name(*a)).collect();
                let mut d = err(
                    codes::E0404,
                    format!(
                        "no overload of `{}` takes ({})",
                        func.name(),
                        found.join(", ")
                    ),
                    *span,
                )
                .with_label("no matching overload")
                .with_note(format!("the overloads are:\n    {}", sigs.join("\n    ")));
                for w in wheres {
                    d = d.with_note(format!("where {w}"));
                }
                d
            }
            E::BadSwizzle { span, ty, swizzle } => err(
                codes::E0405,
                format!("invalid swizzle `{swizzle}` on {}", r.ty(*ty)),
                *span,
            )
            .with_label("invalid swizzle")
            .with_help(format!(
                "a swizzle takes one to four of {}, from one set only",
                match r.p.types.width(*ty) {
                    Some(2) => "`x y` or of `r g`",
                    Some(3) => "`x y z` or of `r g b`",
                    _ => "`x y z w` or of `r g b a`",
                }
            )),
            E::NotIndexable { span, ty } => err(
                codes::E0406,
                format!("cannot index a value of type {}", r.ty(*ty)),
                *span,
            )
            .with_label("not an array, vector or matrix"),
            E::IndexOutOfRange {
                span,
                index,
                len,
                ty,
            } => err(
                codes::E0406,
                format!("index {index} is out of range for {}", r.ty(*ty)),
                *span,
            )
            .with_label(format!("valid indices are 0 to {}", len.saturating_sub(1))),
            E::MissingFields {
                span,
                ty,
                missing,
                decl,
            } => err(
                codes::E0407,
                format!(
                    "missing {} {} in {} literal",
                    if missing.len() == 1 {
                        "field"
                    } else {
                        "fields"
                    },
                    list(missing),
                    r.ty(*ty)
                ),
                *span,
            )
            .with_label(format!("missing {}", list(missing)))
            .with_secondary(*decl, format!("{} declared here", r.ty(*ty)))
            .with_help("fields without a default must be given"),
            E::DuplicateField { span, first, name } => err(
                codes::E0408,
                format!("field `{name}` is given twice"),
                *span,
            )
            .with_label("given again here")
            .with_secondary(*first, "first given here"),
            E::BadConstructor { span, ty, reason } => ctor_diag(r, *span, *ty, reason),
            E::BadArraySize { span, found, value } => {
                let d = err(
                    codes::E0410,
                    "an array size must be a positive constant of type `i32` or `u32`",
                    *span,
                );
                match (value, r.p.types.get(*found)) {
                    (Some(v), _) => d.with_label(format!("this is {v}")),
                    (None, Type::Scalar(k)) if k.is_integer() => d.with_label("not a constant"),
                    (None, _) => d.with_label(format!("this is {}", r.ty(*found))),
                }
            }
            E::LiteralRange { span, ty } => {
                let text = r.snippet(*span);
                let is_float = text.contains(['.', 'e', 'E']) && !text.starts_with("0x");
                let label = match r.p.types.get(*ty) {
                    Type::Scalar(k) if k.is_integer() && is_float => "not an integer".to_string(),
                    _ => format!("out of range for {}", r.ty(*ty)),
                };
                err(
                    codes::E0411,
                    format!("the literal `{text}` does not fit {}", r.ty(*ty)),
                    *span,
                )
                .with_label(label)
            }
            E::NotConst {
                span,
                what,
                context,
            } => {
                let what = match what {
                    NotConst::Local => "a variable".to_string(),
                    NotConst::Call => "a call to a user function".to_string(),
                    NotConst::Builtin(b) => format!("a call to `{}`", b.name()),
                };
                err(
                    codes::E0412,
                    format!("{context} must be a constant expression"),
                    *span,
                )
                .with_label(format!("{what} is not constant"))
                .with_note(
                    "constant expressions are literals, constants, constructors, struct literals, \
                     operators and the built-ins marked const",
                )
            }
            E::SceneOnly { span, func } => err(
                codes::E0412,
                format!("`{}` can only be used in a scene", func.name()),
                *span,
            )
            .with_label("not in a scene")
            .with_note("assets are made by scenes and passed to programs in role structs"),
            E::TypeNotAllowed { span, ty, context } => err(
                codes::E0413,
                format!("{} cannot be used {context}", r.ty(*ty)),
                *span,
            )
            .with_label("not allowed here"),
            E::EmptyStruct { span, name } => err(
                codes::E0416,
                format!("struct `{name}` has no fields"),
                *span,
            )
            .with_label("declared without fields")
            .with_note("GPU code has no empty structs (WGSL, SPIR-V and the other targets forbid them)")
            .with_help("give it a field; a material without parameters can hold an unused one, e.g. `unused: f32 = 0.0`"),
            E::NotCallable { span, name, kind } => err(
                codes::E0414,
                format!("`{name}` is a {}, not a function", kind.describe()),
                *span,
            )
            .with_label("called here"),
        }
    }
}

fn operand_help(r: &R, lhs: TypeId, rhs: TypeId, ls: Span, rs: Span) -> Option<String> {
    let t = &r.p.types;
    let (lk, rk) = (t.scalar_kind(lhs)?, t.scalar_kind(rhs)?);
    let (lw, rw) = (t.width(lhs)?, t.width(rhs)?);
    if lk == rk || !lk.is_numeric() || !rk.is_numeric() {
        return None;
    }
    // Convert the integer operand to float; otherwise the right operand to the left's kind.
    let (span, kind, width) = if lk.is_integer() && rk == ScalarKind::F32 {
        (ls, rk, lw)
    } else {
        (rs, lk, rw)
    };
    let name = if width == 1 {
        kind.name().to_string()
    } else {
        format!("vec{width}{}", kind.suffix())
    };
    let text = r.snippet(span);
    if text.is_empty() {
        return None;
    }
    Some(format!("convert with `{name}({text})`"))
}

fn ctor_diag(r: &R, span: Span, ty: TypeId, reason: &CtorError) -> Diagnostic {
    let err = |m: String| Diagnostic::error(codes::E0409, m, span);
    let name = r.ty(ty);
    match reason {
        CtorError::Count { expected, found } => err(format!(
            "{name} needs {expected} components, but {found} were given"
        ))
        .with_label(format!("{found} components")),
        CtorError::Component { expected, found } => {
            let d = err(format!(
                "{name} is built from {} components",
                r.ty(*expected)
            ))
            .with_label(format!("this is {}", r.ty(*found)));
            match r.conversion(*found, *expected, span) {
                Some(h) => d.with_help(h),
                None => d,
            }
        }
        CtorError::Struct => err(format!("a struct {name} cannot be called like a function"))
            .with_label("not a constructor")
            .with_help(format!(
                "write a struct literal: `{} {{ field: value, … }}`",
                r.p.type_name(ty)
            )),
        CtorError::Convert { from } => err(format!("cannot convert {} to {name}", r.ty(*from)))
            .with_label("invalid conversion"),
        CtorError::Bitcast { from } => err(format!("cannot bitcast {} to {name}", r.ty(*from)))
            .with_label("different sizes")
            .with_note("`bitcast` reinterprets 32-bit scalars and vectors of the same width"),
        CtorError::EmptyArray => err("an array needs at least one element".to_string())
            .with_label("no elements")
            .with_help("write the type to make a zero array: `array<f32, 4>()`"),
        CtorError::NotConstructible => {
            err(format!("values of {name} cannot be constructed")).with_label("not constructible")
        }
    }
}
