//! Static resource limits: the size of types (E0803) and the private memory a function's arrays
//! and structs need, with those of its callees (E0804). Constant values have their own bound,
//! [`consteval::MAX_CONST_SCALARS`](super::consteval::MAX_CONST_SCALARS) (E0805).
//!
//! Sizes follow WGSL's layout rules (spec/types.md, "Size limits"): scalars and handles 4 bytes,
//! `vec2` 8 (aligned to 8), `vec3` 12 (aligned to 16), `vec4` 16, a matrix is its columns at the
//! column vector's alignment, an array is its element stride (the size rounded up to the
//! alignment) times its length, a struct its fields at their alignments, rounded up to the largest.
//! Arithmetic saturates, so any size, however absurd, is a number and never overflows.
//!
//! Guarantees: every type the checker accepts is at most [`MAX_TYPE_BYTES`], so every size naga
//! computes fits its `u32`s; every user function, with the deepest chain of functions it calls,
//! keeps at most [`PRIVATE_MEMORY_BUDGET`] bytes of arrays and structs in locals and parameters.

use super::hir::{FnId, Struct};
use super::types::{Type, TypeId, TypeTable};
use super::Ctx;
use crate::source::Span;
use la_arena::Arena;

/// The largest type: 128 MiB, WebGPU's default `maxStorageBufferBindingSize`, the limit of the
/// `params` buffer that holds every instance of the scene (and far beyond any private memory).
pub const MAX_TYPE_BYTES: u64 = 128 << 20;

/// Private memory of one invocation (one pixel sample) that user code may use: 8 KiB for the arrays
/// and structs held in the locals and parameters of a function and of the deepest chain of
/// functions it calls. We count 16 KiB per invocation in all, half of it reserved for the kernel's
/// own BVH traversal stacks and secondary-ray frames (`stdlib/kernel/trace.rt`), which are not
/// counted here. GPU stacks spill private memory to slow scratch memory well before this on most
/// devices, and lavapipe keeps it on the CPU thread's stack.
pub const PRIVATE_MEMORY_BUDGET: u64 = 8 << 10;

/// Size and alignment in bytes of a type (structs as their fields are known so far; a struct that
/// contains itself, an error of its own (E0801), counts as empty inside itself).
pub fn layout(types: &TypeTable, structs: &Arena<Struct>, ty: TypeId) -> (u64, u64) {
    layout_in(types, structs, ty, &mut Vec::new())
}

fn layout_in(
    types: &TypeTable,
    structs: &Arena<Struct>,
    ty: TypeId,
    open: &mut Vec<super::hir::StructId>,
) -> (u64, u64) {
    match types.get(ty) {
        Type::Void | Type::Error => (0, 1),
        Type::Scalar(_) | Type::Texture | Type::Mesh | Type::String => (4, 4),
        Type::Vector { size, .. } => vector(size),
        Type::Matrix { cols, rows } => {
            let (s, a) = vector(rows);
            (u64::from(cols) * round_up(s, a), a)
        }
        Type::Array { elem, len } => {
            let (s, a) = layout_in(types, structs, elem, open);
            (round_up(s, a).saturating_mul(u64::from(len)), a)
        }
        Type::Struct(id) if open.contains(&id) => (0, 4),
        Type::Struct(id) => {
            open.push(id);
            let (mut size, mut align) = (0u64, 4u64);
            for f in &structs[id].fields {
                let (s, a) = layout_in(types, structs, f.ty, open);
                size = round_up(size, a).saturating_add(s);
                align = align.max(a);
            }
            open.pop();
            (round_up(size, align), align)
        }
    }
}

fn vector(size: u8) -> (u64, u64) {
    match size {
        2 => (8, 8),
        3 => (12, 16),
        _ => (16, 16),
    }
}

fn round_up(x: u64, a: u64) -> u64 {
    x.div_ceil(a.max(1)).saturating_mul(a.max(1))
}

/// Whether values of this type take memory rather than registers (arrays and structs).
fn is_aggregate(types: &TypeTable, ty: TypeId) -> bool {
    matches!(types.get(ty), Type::Array { .. } | Type::Struct(_))
}

impl Ctx<'_> {
    /// The size of `ty` in bytes, resolving the fields of the structs it contains first.
    pub fn type_size(&mut self, ty: TypeId) -> u64 {
        self.ensure_struct_fields_in(ty);
        layout(&self.p.types, &self.p.structs, ty).0
    }

    fn ensure_struct_fields_in(&mut self, ty: TypeId) {
        match self.p.types.get(ty) {
            Type::Array { elem, .. } => self.ensure_struct_fields_in(elem),
            Type::Struct(s) => self.ensure_fields(s),
            _ => {}
        }
    }

    /// Whether `array<elem, len>` is within [`MAX_TYPE_BYTES`]; E0803 at `span` if not.
    pub fn check_array_size(&mut self, elem: TypeId, len: u32, span: Span) -> bool {
        let ty = self.p.types.intern(Type::Array { elem, len });
        let bytes = self.type_size(ty);
        if bytes > MAX_TYPE_BYTES {
            self.err(super::error::LimitError::TypeTooLarge { span, ty, bytes });
            return false;
        }
        true
    }
}

/// Bytes of arrays and structs in the locals and parameters (copies too) of a function, and the
/// local that crosses the budget, with the bytes up to it, if one does.
fn own_memory(cx: &Ctx, f: FnId) -> (u64, Option<(Span, u64)>) {
    let func = &cx.p.functions[f];
    let mut total = 0u64;
    let mut crossing = None;
    for (_, l) in func.body.locals.iter() {
        if TypeTable::is_error(l.ty) || !is_aggregate(&cx.p.types, l.ty) {
            continue;
        }
        total = total.saturating_add(layout(&cx.p.types, &cx.p.structs, l.ty).0);
        if total > PRIVATE_MEMORY_BUDGET && crossing.is_none() {
            crossing = Some((l.span, total));
        }
    }
    (total, crossing)
}

/// E0804: for each function in callee-first `order`, its own aggregate locals plus the heaviest
/// chain of callees; reported at the lowest function of a chain that crosses the budget (at its
/// local that crosses it, or at the call that does), never for the framework kernel
/// (`std/kernel/…` and the generated `rtc:` modules), whose stacks are budgeted apart.
pub(crate) fn private_memory(cx: &mut Ctx, order: &[FnId], calls: &[Vec<(FnId, Span)>]) {
    let n = cx.p.functions.len();
    let mut total = vec![0u64; n];
    let mut over = vec![false; n];
    let mut errors = Vec::new();
    for &f in order {
        let i = super::ix(f);
        let (own, crossing) = own_memory(cx, f);
        let mut worst: Option<(FnId, Span, u64)> = None;
        for &(c, span) in &calls[i] {
            let t = total[super::ix(c)];
            if worst.is_none_or(|(_, _, w)| t > w) {
                worst = Some((c, span, t));
            }
        }
        let chain = worst.map_or(0, |(_, _, t)| t);
        total[i] = own.saturating_add(chain);
        let callee_over = calls[i].iter().any(|(c, _)| over[super::ix(*c)]);
        over[i] = total[i] > PRIVATE_MEMORY_BUDGET;
        let module = &cx.src[cx.p.functions[f].module.index()];
        let framework = module.name.starts_with("std/kernel/") || module.name.starts_with("rtc:");
        if !over[i] || callee_over || framework {
            continue;
        }
        let function = cx.p.functions[f].name.clone();
        errors.push(match (crossing, worst) {
            (Some((span, bytes)), _) => super::error::LimitError::PrivateMemory {
                span,
                function,
                bytes,
                callee: None,
            },
            (None, Some((c, span, t))) => super::error::LimitError::PrivateMemory {
                span,
                function,
                bytes: total[i],
                callee: Some((cx.p.functions[c].name.clone(), t)),
            },
            (None, None) => continue,
        });
    }
    cx.errors.extend(errors.into_iter().map(Into::into));
}
