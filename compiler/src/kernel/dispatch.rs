//! Generated code of the kernel: binding globals, struct loaders and the dispatch switches.
//!
//! - **Globals**: one naga global variable per ABI binding, created the first time something reads it,
//!   so a kernel declares exactly the bindings it reaches.
//! - **Loaders**: `load_<Struct>(offset: u32) -> Struct` rebuilds a role struct's instance from the
//!   `params` words at the offsets of [`crate::layout`] (the same offsets the runtime packs with).
//! - **Dispatchers** (the thesis's "switch collections", Appendix B): for each program kind, a function
//!   `dispatch_<kind>(type_id, offset, args…)` that switches on the type id, loads the instance and calls
//!   the program. A kind with one program is a direct call; a kind with none returns zero. Every switch
//!   has a `default` (naga requires one), which returns zero.
//!
//! Invariants: generated functions are created once (memoised) and only when reached; their handles come
//! after the handles of the functions they call, as naga requires.

use crate::abi::{self, BindingDesc, Element, FieldType};
use crate::back::ResourceKind;
use crate::layout;
use crate::lower::builder::{FnBuilder, TypeCache};
use crate::lower::LowerError;
use crate::sema::hir::{Program, StructId};
use crate::sema::types::{ScalarKind, Type as HirType, TypeId};
use naga::{
    AddressSpace, Expression, GlobalVariable, Handle, Literal, ResourceBinding, Scalar, Span,
    Statement, StorageAccess, Type, TypeInner,
};
use std::collections::BTreeMap;

/// The lowering context of the kernel module.
pub type LowerCx<'p> = crate::lower::Lowerer<'p>;

/// A kernel-assembly failure (an internal error: the kernel or the ABI is inconsistent).
pub fn kernel_error(message: impl Into<String>) -> LowerError {
    LowerError::Validation {
        message: format!("kernel assembly: {}", message.into()),
        span: None,
    }
}

/// Generated functions and globals of one kernel module.
#[derive(Default)]
pub struct Generated {
    globals: BTreeMap<u32, Handle<GlobalVariable>>,
    private: BTreeMap<&'static str, Handle<GlobalVariable>>,
    loaders: BTreeMap<StructId, Handle<naga::Function>>,
    /// Dispatchers, by program kind.
    pub dispatchers: BTreeMap<crate::sema::hir::ProgramKind, Handle<naga::Function>>,
    helpers: BTreeMap<&'static str, Handle<naga::Function>>,
}

fn naga_scalar(t: FieldType) -> (Option<naga::VectorSize>, Scalar) {
    match t {
        FieldType::U32 => (None, Scalar::U32),
        FieldType::F32 => (None, Scalar::F32),
        FieldType::Vec2U32 => (Some(naga::VectorSize::Bi), Scalar::U32),
        FieldType::Vec3F32 => (Some(naga::VectorSize::Tri), Scalar::F32),
        FieldType::Vec3U32 => (Some(naga::VectorSize::Tri), Scalar::U32),
        FieldType::Vec4F32 => (Some(naga::VectorSize::Quad), Scalar::F32),
        FieldType::Vec4U32 => (Some(naga::VectorSize::Quad), Scalar::U32),
    }
}

fn field_type(m: &mut naga::Module, t: FieldType) -> Handle<Type> {
    match naga_scalar(t) {
        (None, s) => TypeCache::scalar(m, s),
        (Some(size), s) => TypeCache::vector(m, size, s),
    }
}

/// The language struct that mirrors an ABI struct (declared in `rtc:abi`).
pub fn abi_struct(program: &Program, name: &str) -> Option<StructId> {
    program
        .structs
        .iter()
        .find(|(_, s)| {
            s.name == name && program.modules[s.module.index()].name == super::generated::ABI_MODULE
        })
        .map(|(id, _)| id)
}

impl Generated {
    /// The global variable of an ABI binding, declared on first use.
    pub fn binding(
        &mut self,
        cx: &mut LowerCx<'_>,
        program: &Program,
        desc: &'static BindingDesc,
    ) -> Result<Handle<GlobalVariable>, LowerError> {
        if let Some(&g) = self.globals.get(&desc.binding) {
            return Ok(g);
        }
        let struct_ty =
            |cx: &mut LowerCx<'_>, s: &abi::StructDesc| -> Result<Handle<Type>, LowerError> {
                let id = abi_struct(program, s.name)
                    .ok_or_else(|| kernel_error(format!("`{}` is missing from rtc:abi", s.name)))?;
                cx.ty(struct_type_id(program, id)?)
            };
        let ty = match desc.element {
            Element::Struct(s) => struct_ty(cx, s)?,
            Element::StructArray(s) => {
                let base = struct_ty(cx, s)?;
                TypeCache::runtime_array(cx.module_mut(), base)
            }
            Element::Array(t) => {
                let m = cx.module_mut();
                let base = field_type(m, t);
                TypeCache::runtime_array(m, base)
            }
            Element::Atomics => {
                let m = cx.module_mut();
                let atomic = m.types.insert(
                    Type {
                        name: None,
                        inner: TypeInner::Atomic(Scalar::U32),
                    },
                    Span::UNDEFINED,
                );
                TypeCache::runtime_array(m, atomic)
            }
        };
        let space = match desc.kind {
            ResourceKind::Uniform => AddressSpace::Uniform,
            ResourceKind::StorageRead => AddressSpace::Storage {
                access: StorageAccess::LOAD,
            },
            ResourceKind::StorageReadWrite => AddressSpace::Storage {
                access: StorageAccess::LOAD | StorageAccess::STORE,
            },
        };
        let g = cx.module_mut().global_variables.append(
            GlobalVariable {
                name: Some(desc.name.to_string()),
                space,
                binding: Some(ResourceBinding {
                    group: 0,
                    binding: desc.binding,
                }),
                ty,
                init: None,
                memory_decorations: Default::default(),
            },
            Span::UNDEFINED,
        );
        self.globals.insert(desc.binding, g);
        Ok(g)
    }

    /// The bindings declared so far, in binding order.
    pub fn used_bindings(&self) -> Vec<&'static BindingDesc> {
        abi::BINDINGS
            .iter()
            .filter(|b| self.globals.contains_key(&b.binding))
            .collect()
    }

    /// A private (per-invocation) global variable, declared on first use.
    pub fn private(
        &mut self,
        cx: &mut LowerCx<'_>,
        name: &'static str,
        ty: Handle<Type>,
    ) -> Handle<GlobalVariable> {
        *self.private.entry(name).or_insert_with(|| {
            cx.module_mut().global_variables.append(
                GlobalVariable {
                    name: Some(name.to_string()),
                    space: AddressSpace::Private,
                    binding: None,
                    ty,
                    init: None,
                    memory_decorations: Default::default(),
                },
                Span::UNDEFINED,
            )
        })
    }

    /// A memoised helper function.
    pub fn helper(
        &mut self,
        name: &'static str,
        build: impl FnOnce(&mut Self) -> Result<Handle<naga::Function>, LowerError>,
    ) -> Result<Handle<naga::Function>, LowerError> {
        if let Some(&f) = self.helpers.get(name) {
            return Ok(f);
        }
        let f = build(self)?;
        self.helpers.insert(name, f);
        Ok(f)
    }

    /// `load_<S>(offset: u32) -> S`: the instance of `s` at word `offset` of `params`.
    pub fn loader(
        &mut self,
        cx: &mut LowerCx<'_>,
        program: &Program,
        s: StructId,
    ) -> Result<Handle<naga::Function>, LowerError> {
        if let Some(&f) = self.loaders.get(&s) {
            return Ok(f);
        }
        let params = self.binding(cx, program, abi_binding("params")?)?;
        let ty = struct_type_id(program, s)?;
        let result = cx.ty(ty)?;
        let u32_ty = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        let name = format!("load_{}", program.structs[s].name);
        let mut fb = FnBuilder::new(&name, &[("offset", u32_ty)], Some(result));
        let base = fb.arg(0);
        let value = load_value(cx, program, &mut fb, params, ty, base, 0)?;
        fb.stmt(Statement::Return { value: Some(value) }, Span::UNDEFINED);
        let f = cx
            .module_mut()
            .functions
            .append(fb.finish(), Span::UNDEFINED);
        self.loaders.insert(s, f);
        Ok(f)
    }
}

/// The ABI binding with this name.
pub fn abi_binding(name: &str) -> Result<&'static BindingDesc, LowerError> {
    abi::binding(name).ok_or_else(|| kernel_error(format!("no ABI binding `{name}`")))
}

/// The type id of a struct.
pub fn struct_type_id(program: &Program, s: StructId) -> Result<TypeId, LowerError> {
    program
        .types
        .iter()
        .find(|(_, t)| *t == HirType::Struct(s))
        .map(|(t, _)| t)
        .ok_or_else(|| kernel_error(format!("struct `{}` has no type", program.structs[s].name)))
}

/// `params[base + word]` as a u32 expression.
fn word(
    fb: &mut FnBuilder,
    params: Handle<GlobalVariable>,
    base: Handle<Expression>,
    word: u32,
) -> Handle<Expression> {
    let g = fb.expr(Expression::GlobalVariable(params), Span::UNDEFINED);
    let k = fb.expr(Expression::Literal(Literal::U32(word)), Span::UNDEFINED);
    let index = fb.expr(
        Expression::Binary {
            op: naga::BinaryOperator::Add,
            left: base,
            right: k,
        },
        Span::UNDEFINED,
    );
    let ptr = fb.expr(Expression::Access { base: g, index }, Span::UNDEFINED);
    fb.load(ptr, Span::UNDEFINED)
}

fn scalar_from_word(
    fb: &mut FnBuilder,
    w: Handle<Expression>,
    kind: ScalarKind,
) -> Handle<Expression> {
    match kind {
        ScalarKind::U32 => w,
        ScalarKind::I32 => fb.expr(
            Expression::As {
                expr: w,
                kind: naga::ScalarKind::Sint,
                convert: None,
            },
            Span::UNDEFINED,
        ),
        ScalarKind::F32 => fb.expr(
            Expression::As {
                expr: w,
                kind: naga::ScalarKind::Float,
                convert: None,
            },
            Span::UNDEFINED,
        ),
        ScalarKind::Bool => {
            let zero = fb.expr(Expression::Literal(Literal::U32(0)), Span::UNDEFINED);
            fb.expr(
                Expression::Binary {
                    op: naga::BinaryOperator::NotEqual,
                    left: w,
                    right: zero,
                },
                Span::UNDEFINED,
            )
        }
    }
}

/// Builds the value of type `ty` stored at word `base + first` of `params`.
fn load_value(
    cx: &mut LowerCx<'_>,
    program: &Program,
    fb: &mut FnBuilder,
    params: Handle<GlobalVariable>,
    ty: TypeId,
    base: Handle<Expression>,
    first: u32,
) -> Result<Handle<Expression>, LowerError> {
    let naga_ty = cx.ty(ty)?;
    Ok(match program.types.get(ty) {
        HirType::Scalar(k) => {
            let w = word(fb, params, base, first);
            scalar_from_word(fb, w, k)
        }
        HirType::Texture | HirType::Mesh => word(fb, params, base, first),
        HirType::Vector { size, scalar } => {
            let comps = (0..size as u32)
                .map(|i| {
                    let w = word(fb, params, base, first + i);
                    scalar_from_word(fb, w, scalar)
                })
                .collect();
            fb.expr(
                Expression::Compose {
                    ty: naga_ty,
                    components: comps,
                },
                Span::UNDEFINED,
            )
        }
        HirType::Matrix { cols, rows } => {
            let col_ty = program_vec_f32(cx, rows);
            let stride = if rows == 2 { 2 } else { 4 };
            let mut columns = Vec::new();
            for c in 0..cols as u32 {
                let comps = (0..rows as u32)
                    .map(|r| {
                        let w = word(fb, params, base, first + c * stride + r);
                        scalar_from_word(fb, w, ScalarKind::F32)
                    })
                    .collect();
                columns.push(fb.expr(
                    Expression::Compose {
                        ty: col_ty,
                        components: comps,
                    },
                    Span::UNDEFINED,
                ));
            }
            fb.expr(
                Expression::Compose {
                    ty: naga_ty,
                    components: columns,
                },
                Span::UNDEFINED,
            )
        }
        HirType::Array { elem, len } => {
            let l = layout::layout(program, elem);
            let stride = l.size.div_ceil(l.align) * l.align / 4;
            let mut items = Vec::new();
            for i in 0..len {
                items.push(load_value(
                    cx,
                    program,
                    fb,
                    params,
                    elem,
                    base,
                    first + i * stride,
                )?);
            }
            fb.expr(
                Expression::Compose {
                    ty: naga_ty,
                    components: items,
                },
                Span::UNDEFINED,
            )
        }
        HirType::Struct(s) => {
            let offsets = layout::field_offsets(program, ty);
            let mut fields = Vec::new();
            for (f, off) in program.structs[s].fields.iter().zip(offsets) {
                fields.push(load_value(
                    cx,
                    program,
                    fb,
                    params,
                    f.ty,
                    base,
                    first + off / 4,
                )?);
            }
            fb.expr(
                Expression::Compose {
                    ty: naga_ty,
                    components: fields,
                },
                Span::UNDEFINED,
            )
        }
        HirType::Error | HirType::Void | HirType::String => {
            return Err(kernel_error(format!(
                "cannot load a value of type {}",
                program.type_name(ty)
            )))
        }
    })
}

fn program_vec_f32(cx: &mut LowerCx<'_>, rows: u8) -> Handle<Type> {
    let size = match rows {
        2 => naga::VectorSize::Bi,
        3 => naga::VectorSize::Tri,
        _ => naga::VectorSize::Quad,
    };
    TypeCache::vector(cx.module_mut(), size, Scalar::F32)
}
