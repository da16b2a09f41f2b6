//! A compute entry point that runs one HIR function over a buffer of inputs: for tests and tools
//! (differential testing against CPU references, benchmarking single functions).
//!
//! For `fn f(a: A, b: B, …) -> R`, [`test_entry`] builds a module holding `f` (and what it calls) and
//!
//! ```wgsl
//! struct Input { a: A, b: B, … }           // bool → u32 (0 or 1), vecNb → vecNu
//! struct Output { result: R }
//! @group(0) @binding(0) var<storage, read> input: array<Input>;
//! @group(0) @binding(1) var<storage, read_write> output: array<Output>;
//! @compute @workgroup_size(64)
//! fn main(@builtin(global_invocation_id) id: vec3<u32>) {
//!     let index = id.x;
//!     if index >= arrayLength(&input) { return; }
//!     output[index].result = f(input[index].a, input[index].b, …);
//! }
//! ```
//!
//! and describes both element layouts ([`IoLayout`]) down to each scalar's byte offset, so the host packs
//! and unpacks without knowing WGSL's layout rules.
//!
//! Invariants: parameters and the result may be scalars, vectors, matrices, `texture`/`mesh` handles,
//! arrays of those, and structs of those without `bool` fields (anything else is
//! [`Unsupported::TestIo`]); the element structs follow naga's layouter (see `types.rs`), and the slots
//! list every scalar in declaration order (vector components, then matrix columns, array elements and
//! struct fields in order).

use super::builder::{FnBuilder, TypeCache};
use super::types::vector_size;
use super::{lower, Intrinsics, LowerError, Lowerer, Unsupported};
use crate::back::{Resource, ResourceKind};
use crate::sema::hir::{FnId, Program};
use crate::sema::types::{ScalarKind, Type, TypeId};
use crate::source::{SourceMap, Span};
use naga::{Expression, Handle, Literal, Statement, TypeInner};

/// The entry point's name.
pub const ENTRY_POINT: &str = "main";
/// Invocations per workgroup (along x).
pub const WORKGROUP_SIZE: u32 = 64;
/// Binding (group 0) of the read-only input array.
pub const INPUT_BINDING: u32 = 0;
/// Binding (group 0) of the read-write output array.
pub const OUTPUT_BINDING: u32 = 1;

/// One scalar of an element: where it is and what it is (`Bool` is stored as a `u32` 0 or 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IoSlot {
    /// Byte offset from the start of the element.
    pub offset: u32,
    /// The scalar's kind.
    pub kind: ScalarKind,
}

/// One member of an element (a parameter, or the result).
#[derive(Clone, Debug, PartialEq)]
pub struct IoMember {
    /// The parameter's name (`result` for the result).
    pub name: String,
    /// Its HIR type.
    pub ty: TypeId,
    /// Byte offset in the element.
    pub offset: u32,
    /// Byte size.
    pub size: u32,
    /// Every scalar, in declaration order.
    pub slots: Vec<IoSlot>,
}

/// The layout of one array element.
#[derive(Clone, Debug, PartialEq)]
pub struct IoLayout {
    /// Bytes from one element to the next.
    pub stride: u32,
    /// The members in order.
    pub members: Vec<IoMember>,
}

/// A module that runs one function over an input buffer.
#[derive(Debug)]
pub struct TestKernel {
    /// The validated module.
    pub module: naga::Module,
    /// The input element (one per invocation).
    pub input: IoLayout,
    /// The output element.
    pub output: IoLayout,
}

impl TestKernel {
    /// The two bindings, for `back::write`.
    pub fn resources() -> [Resource; 2] {
        [
            Resource {
                group: 0,
                binding: INPUT_BINDING,
                kind: ResourceKind::StorageRead,
            },
            Resource {
                group: 0,
                binding: OUTPUT_BINDING,
                kind: ResourceKind::StorageReadWrite,
            },
        ]
    }
}

/// Builds the test module for function `f` (see the module doc).
pub fn test_entry(
    program: &Program,
    sources: &SourceMap,
    f: FnId,
    intrinsics: &mut dyn Intrinsics,
) -> Result<TestKernel, LowerError> {
    let lowered = lower(
        program,
        sources,
        &[f],
        intrinsics,
        |lw, roots| match roots {
            [callee] => entry_point(lw, f, *callee),
            _ => Err(LowerError::InvalidHir {
                what: "a test entry point for other than one function",
                span: program.functions[f].span,
            }),
        },
    )?;
    let (input, output) = lowered.finished;
    Ok(TestKernel {
        module: lowered.module,
        input,
        output,
    })
}

/// Builds the entry point calling `callee` (the naga function of `f`) and the two buffers; returns
/// the input and output element layouts.
fn entry_point(
    lw: &mut Lowerer<'_>,
    f: FnId,
    callee: Handle<naga::Function>,
) -> Result<(IoLayout, IoLayout), LowerError> {
    let program = lw.program;
    let func = &program.functions[f];

    let mut params = Vec::new();
    for &p in &func.params {
        let local = &func.body.locals[p];
        params.push((
            local.name.clone(),
            local.ty,
            io_type(lw, local.ty, local.span)?,
        ));
    }
    if params.is_empty() {
        let u = TypeCache::scalar(&mut lw.module, naga::Scalar::U32);
        params.push(("unused".to_string(), crate::sema::types::TypeTable::U32, u));
    }
    let ret_ty = func.ret;
    if program.types.get(ret_ty) == Type::Void {
        return Err(LowerError::Unsupported {
            what: Unsupported::TestIo(ret_ty),
            span: func.span,
        });
    }
    let ret_io = io_type(lw, ret_ty, func.span)?;
    let input_t = lw.layout_struct(
        Some("Input"),
        params.iter().map(|(n, _, t)| (n.as_str(), *t)),
        naga::Span::UNDEFINED,
    );
    let output_t = lw.layout_struct(Some("Output"), [("result", ret_io)], naga::Span::UNDEFINED);
    let input_arr = TypeCache::runtime_array(&mut lw.module, input_t);
    let output_arr = TypeCache::runtime_array(&mut lw.module, output_t);
    let global = |lw: &mut Lowerer<'_>, name: &str, ty, binding, access| {
        lw.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(name.to_string()),
                space: naga::AddressSpace::Storage { access },
                binding: Some(naga::ResourceBinding { group: 0, binding }),
                ty,
                init: None,
                memory_decorations: Default::default(),
            },
            naga::Span::UNDEFINED,
        )
    };
    let input_g = global(
        lw,
        "input",
        input_arr,
        INPUT_BINDING,
        naga::StorageAccess::LOAD,
    );
    let output_g = global(
        lw,
        "output",
        output_arr,
        OUTPUT_BINDING,
        naga::StorageAccess::LOAD | naga::StorageAccess::STORE,
    );

    let u = naga::Span::UNDEFINED;
    let vec3u = TypeCache::vector(&mut lw.module, naga::VectorSize::Tri, naga::Scalar::U32);
    let mut fb = FnBuilder::new(ENTRY_POINT, &[("id", vec3u)], None);
    let id = fb.arg(0);
    let index = fb.access_index(id, 0, u);
    fb.name(index, "index");
    let input_ptr = fb.expr(Expression::GlobalVariable(input_g), u);
    let output_ptr = fb.expr(Expression::GlobalVariable(output_g), u);
    let len = fb.expr(Expression::ArrayLength(input_ptr), u);
    let past_end = fb.binary(naga::BinaryOperator::GreaterEqual, index, len, u);
    fb.push_block();
    fb.ret(None, u);
    let stop = fb.pop_block();
    fb.stmt(
        Statement::If {
            condition: past_end,
            accept: stop,
            reject: naga::Block::new(),
        },
        u,
    );
    let element = fb.access(input_ptr, index, u);
    let mut args = Vec::new();
    for (k, &p) in func.params.iter().enumerate() {
        let ty = func.body.locals[p].ty;
        let member = fb.access_index(element, k as u32, u);
        let raw = fb.load(member, u);
        args.push(from_io(lw, &mut fb, raw, ty)?);
    }
    let result = fb
        .call(callee, args, true, u)
        .ok_or(LowerError::InvalidHir {
            what: "a test function without a result",
            span: func.span,
        })?;
    let stored = to_io(lw, &mut fb, result, ret_ty)?;
    let out_element = fb.access(output_ptr, index, u);
    let out_member = fb.access_index(out_element, 0, u);
    fb.store(out_member, stored, u);
    let mut main = fb.finish();
    if let Some(arg) = main.arguments.first_mut() {
        arg.binding = Some(naga::Binding::BuiltIn(naga::BuiltIn::GlobalInvocationId));
    }
    lw.module.entry_points.push(naga::EntryPoint {
        name: ENTRY_POINT.to_string(),
        stage: naga::ShaderStage::Compute,
        early_depth_test: None,
        workgroup_size: [WORKGROUP_SIZE, 1, 1],
        workgroup_size_overrides: None,
        function: main,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });

    let input = io_layout(lw, input_t, params.iter().map(|(_, t, _)| *t).collect());
    let output = io_layout(lw, output_t, vec![ret_ty]);
    Ok((input, output))
}

/// The naga type a value of HIR type `ty` has in a buffer: `bool` becomes `u32`.
fn io_type(lw: &mut Lowerer<'_>, ty: TypeId, span: Span) -> Result<Handle<naga::Type>, LowerError> {
    let program = lw.program;
    match program.types.get(ty) {
        Type::Scalar(ScalarKind::Bool) => Ok(lw.sv_type(1, ScalarKind::U32)),
        Type::Vector {
            size,
            scalar: ScalarKind::Bool,
        } => Ok(lw.sv_type(size, ScalarKind::U32)),
        Type::Array { elem, len } => {
            let base = io_type(lw, elem, span)?;
            let layout = lw.layout(base);
            let stride = layout.alignment.round_up(layout.size);
            let size = std::num::NonZeroU32::new(len).ok_or(LowerError::Unsupported {
                what: Unsupported::TestIo(ty),
                span,
            })?;
            Ok(lw.module.types.insert(
                naga::Type {
                    name: None,
                    inner: TypeInner::Array {
                        base,
                        size: naga::ArraySize::Constant(size),
                        stride,
                    },
                },
                naga::Span::UNDEFINED,
            ))
        }
        Type::Struct(s) => {
            if program.structs[s]
                .fields
                .iter()
                .any(|f| contains_bool(program, f.ty))
            {
                return Err(LowerError::Unsupported {
                    what: Unsupported::TestIo(ty),
                    span,
                });
            }
            lw.ty_at(ty, span)
        }
        _ => lw.ty_at(ty, span),
    }
}

fn contains_bool(program: &Program, ty: TypeId) -> bool {
    match program.types.get(ty) {
        Type::Scalar(k) | Type::Vector { scalar: k, .. } => k == ScalarKind::Bool,
        Type::Array { elem, .. } => contains_bool(program, elem),
        Type::Struct(s) => program.structs[s]
            .fields
            .iter()
            .any(|f| contains_bool(program, f.ty)),
        _ => false,
    }
}

/// Converts a loaded buffer value to the HIR type `ty` (`u32` → `bool` as `!= 0`).
fn from_io(
    lw: &mut Lowerer<'_>,
    fb: &mut FnBuilder,
    v: Handle<Expression>,
    ty: TypeId,
) -> Result<Handle<Expression>, LowerError> {
    let u = naga::Span::UNDEFINED;
    match lw.program.types.get(ty) {
        Type::Scalar(ScalarKind::Bool)
        | Type::Vector {
            scalar: ScalarKind::Bool,
            ..
        } => {
            let width = lw.program.types.width(ty).unwrap_or(1);
            let zero = fb.literal(Literal::U32(0));
            let zero = match vector_size(width) {
                Some(size) => fb.splat(size, zero, u),
                None => zero,
            };
            Ok(fb.binary(naga::BinaryOperator::NotEqual, v, zero, u))
        }
        Type::Array { elem, len } if contains_bool(lw.program, elem) => {
            let mut parts = Vec::with_capacity(len as usize);
            for i in 0..len {
                let e = fb.access_index(v, i, u);
                parts.push(from_io(lw, fb, e, elem)?);
            }
            let t = lw.ty(ty)?;
            Ok(fb.compose(t, parts, u))
        }
        _ => Ok(v),
    }
}

/// Converts a value of HIR type `ty` to its buffer form (`bool` → `u32` 0 or 1).
fn to_io(
    lw: &mut Lowerer<'_>,
    fb: &mut FnBuilder,
    v: Handle<Expression>,
    ty: TypeId,
) -> Result<Handle<Expression>, LowerError> {
    let u = naga::Span::UNDEFINED;
    match lw.program.types.get(ty) {
        Type::Scalar(ScalarKind::Bool)
        | Type::Vector {
            scalar: ScalarKind::Bool,
            ..
        } => {
            let width = lw.program.types.width(ty).unwrap_or(1);
            let (zero, one) = (fb.literal(Literal::U32(0)), fb.literal(Literal::U32(1)));
            let (zero, one) = match vector_size(width) {
                Some(size) => (fb.splat(size, zero, u), fb.splat(size, one, u)),
                None => (zero, one),
            };
            Ok(fb.select(v, one, zero, u))
        }
        Type::Array { elem, len } if contains_bool(lw.program, elem) => {
            let mut parts = Vec::with_capacity(len as usize);
            for i in 0..len {
                let e = fb.access_index(v, i, u);
                parts.push(to_io(lw, fb, e, elem)?);
            }
            let t = io_type(lw, ty, Span::default())?;
            Ok(fb.compose(t, parts, u))
        }
        _ => Ok(v),
    }
}

/// The layout of an element struct whose members have HIR types `tys`.
fn io_layout(lw: &mut Lowerer<'_>, st: Handle<naga::Type>, tys: Vec<TypeId>) -> IoLayout {
    let layout = lw.layout(st);
    let members = match &lw.module.types[st].inner {
        TypeInner::Struct { members, .. } => members.clone(),
        _ => Vec::new(),
    };
    let mut out = Vec::with_capacity(members.len());
    for (m, ty) in members.iter().zip(tys) {
        let mut slots = Vec::new();
        scalar_slots(lw, m.ty, ty, m.offset, &mut slots);
        out.push(IoMember {
            name: m.name.clone().unwrap_or_default(),
            ty,
            offset: m.offset,
            size: lw.layout(m.ty).size,
            slots,
        });
    }
    IoLayout {
        stride: layout.alignment.round_up(layout.size),
        members: out,
    }
}

/// Appends the scalar slots of a value of naga type `nty` (HIR type `ty`) at `base`.
fn scalar_slots(
    lw: &mut Lowerer<'_>,
    nty: Handle<naga::Type>,
    ty: TypeId,
    base: u32,
    out: &mut Vec<IoSlot>,
) {
    let program = lw.program;
    let inner = lw.module.types[nty].inner.clone();
    match (inner, program.types.get(ty)) {
        (TypeInner::Scalar(_), _) => out.push(IoSlot {
            offset: base,
            kind: program.types.scalar_kind(ty).unwrap_or(ScalarKind::U32),
        }),
        (TypeInner::Vector { size, .. }, _) => {
            let kind = program.types.scalar_kind(ty).unwrap_or(ScalarKind::U32);
            for i in 0..size as u32 {
                out.push(IoSlot {
                    offset: base + 4 * i,
                    kind,
                });
            }
        }
        (TypeInner::Matrix { columns, rows, .. }, _) => {
            let column_stride = if rows == naga::VectorSize::Bi { 8 } else { 16 };
            for c in 0..columns as u32 {
                for r in 0..rows as u32 {
                    out.push(IoSlot {
                        offset: base + c * column_stride + 4 * r,
                        kind: ScalarKind::F32,
                    });
                }
            }
        }
        (
            TypeInner::Array {
                base: elem_t,
                size,
                stride,
            },
            Type::Array { elem, .. },
        ) => {
            let n = match size {
                naga::ArraySize::Constant(n) => n.get(),
                _ => 0,
            };
            for i in 0..n {
                scalar_slots(lw, elem_t, elem, base + i * stride, out);
            }
        }
        (TypeInner::Struct { members, .. }, Type::Struct(s)) => {
            for (m, f) in members.iter().zip(&program.structs[s].fields) {
                scalar_slots(lw, m.ty, f.ty, base + m.offset, out);
            }
        }
        _ => {}
    }
}
