//! Lowering of intrinsics for one scene's kernel: the [`KernelHooks`] given to the lowerer.
//!
//! - **Framework intrinsics** ([`Intrinsic`]) are functions of the generated `rtc:abi` module.
//!   Their bodies are placeholders; every call is replaced ([`Intrinsics::lower_call`]): `load_*`
//!   read the kernel's buffers, `rng_*`, the shaded hit's position error (`hit_error_*`, read by `shadow`), the spawn
//!   queue, the traversal stack (`stack_load`, `stack_store`), the ray count (`count_ray`, flushed
//!   to counter `COUNTER_RAYS` and zeroed by `flush_ray_count`) and a debug kernel's counters (`debug_count`,
//!   `debug_counts`) use private globals, `accumulate` and `write_bounds` write
//!   results, and `call_<kind>` calls the generated dispatcher of that program kind.
//! - **Record accessors** of `rtc:abi` (`mesh_slot_base(m)`, `triangle_v1(slot)`, …,
//!   [`abi::accessor`]) are expanded into the one load of their generated body, with no call. Its
//!   remaining functions, the quantised-box decoders (`node_box_lo`, …), are lowered as written.
//! - **User intrinsics** (spec/programs.md) become calls of the kernel's own functions written in the
//!   language (`rand()` → `rand_next`, `shadow(…)` → `shadow_query`, …), except `spawn`, which appends to
//!   the spawn queue.
//!
//! Invariants: the spawn queue never writes past `MAX_SPAWN` entries and `spawned_count` is clamped to
//! it; traversal stack indices are clamped to the stack; a dispatcher is built once per kind, after the programs and loaders it calls.

use super::dispatch::{abi_binding, kernel_error, Generated, LowerCx};
use super::generated::{Intrinsic, ABI_MODULE};
use crate::abi;
use crate::link::{KernelConfig, Linked};
use crate::lower::builder::{FnBuilder, TypeCache};
use crate::lower::{CallLowering, FunctionCall, IntrinsicCall, Intrinsics, LowerError};
use crate::sema::builtins::Builtin;
use crate::sema::hir::{FnId, Program, ProgramKind, Role};
use crate::sema::types::{TypeId, TypeTable};
use naga::{
    AtomicFunction, BinaryOperator, Expression, Handle, Literal, Scalar, Span, Statement,
    SwitchCase, SwitchValue, VectorSize,
};

/// The intrinsics hook of one scene's kernel.
pub struct KernelHooks<'a> {
    /// The checked program (user code, stdlib, kernel).
    pub program: &'a Program,
    /// The link plan.
    pub linked: &'a Linked,
    /// The kernel's constants.
    pub config: KernelConfig,
    /// Generated globals and functions.
    pub generated: Generated,
    /// `shadow(…)` is replayed rather than traced (the wavefront model's shade stage:
    /// `shadow_replay` instead of `shadow_query`, see `kernel::wavefront`).
    pub replay_shadows: bool,
    /// The kernel traces no ray: `ray_count_load()` is a literal 0 (a shade stage whose shadow
    /// stage traces its recorded queries; with `replay_shadows` and not this, the shade stage
    /// traces them itself, see `pending_step_waits`).
    pub traces_no_rays: bool,
    /// `sample_done(…)` is `wf_sample_accumulate` (a shade stage whose samples all end in their
    /// first shading step, when `accum` fits its bindings), else `wf_sample_done`.
    pub accumulates: bool,
}

/// Words of the private scratch registers (`scratch_load`, `scratch_store`; `stdlib/kernel/paths.rt`
/// names them), in a kernel that does not defer light programs' shadow queries.
pub const SCRATCH_WORDS: u32 = 15;

/// Words of the private scratch registers in a kernel that defers them: 10 more for the recorded
/// query (`SCRATCH_LIGHT_QUERY`).
pub const SCRATCH_WORDS_DEFERRING: u32 = 25;

/// The kernel function (from `stdlib/kernel/`) named `name`.
pub fn kernel_fn(program: &Program, name: &str) -> Result<FnId, LowerError> {
    program
        .functions
        .iter()
        .find(|(_, f)| {
            f.name == name
                && program.modules[f.module.index()]
                    .name
                    .starts_with("std/kernel/")
        })
        .map(|(id, _)| id)
        .ok_or_else(|| kernel_error(format!("the framework kernel has no function `{name}`")))
}

/// The kernel function implementing a user intrinsic, if it is one.
fn user_intrinsic_fn(b: Builtin) -> Option<&'static str> {
    Some(match b {
        Builtin::Rand => "rand_next",
        Builtin::Rand2 => "rand2_next",
        Builtin::ImageSize => "image_size_query",
        Builtin::FrameIndex => "frame_index_query",
        Builtin::SamplesPerPixel => "samples_per_pixel_query",
        Builtin::Sample => "sample_texture",
        Builtin::TextureSize => "texture_size_query",
        Builtin::MeshNode => "mesh_node_query",
        Builtin::MeshTriangle => "mesh_triangle_query",
        Builtin::MeshTriangleCount => "mesh_triangle_count_query",
        Builtin::MeshBounds => "mesh_bounds_query",
        Builtin::LightCount => "light_count_query",
        Builtin::SampleLight => "sample_light_query",
        Builtin::SampleLightUnoccluded => "sample_light_unoccluded_query",
        Builtin::SampleLightAbove => "sample_light_above_query",
        Builtin::Shadow => "shadow_query",
        Builtin::Absorb => "absorb_query",
        _ => return None,
    })
}

fn lit_u32(fb: &mut FnBuilder, v: u32) -> Handle<Expression> {
    fb.expr(Expression::Literal(Literal::U32(v)), Span::UNDEFINED)
}

/// Shadow queries one light sample answers exactly when a light program's `shadow` calls are
/// deferred (`sample_light_deferred` in `stdlib/kernel/trace.rt`; the answers are bits of one
/// word); later ones are answered "unoccluded" and counted in `COUNTER_SHADOW_OVERFLOW`.
pub const LIGHT_QUERIES: u32 = 32;

impl KernelHooks<'_> {
    /// Whether `shadow(…)` calls written in `@light` programs are deferred to `sample_light`
    /// (`sample_light_deferred` in `stdlib/kernel/trace.rt`): in the megakernel, whose driver
    /// inlines every call, a light program's shadow traversal would otherwise be copied once for
    /// every light type at every `sample_light` call, that is once per material and light type
    /// (`lights`: 4 copies; `gltf_scene`: 4). Not with `absorb`, whose answers are transmittances
    /// rather than bits, nor in the wavefront model, which replays every `shadow` call anyway,
    /// nor with a single light type, whose program is one copy per material either way (there the
    /// deferral's loop only costs: thesis_scene compiled in 3.3 s deferred against 2.7 s).
    fn defers_light_shadows_at_all(&self) -> bool {
        let light_types = self.linked.types.get(&Role::Light).map_or(0, Vec::len);
        !self.replay_shadows && !self.config.has_absorb && light_types > 1
    }

    /// Whether a `shadow(…)` call in function `caller` is deferred: the caller is a `@light`
    /// program itself (a helper it calls traces in place, which is correct, only not shared).
    fn defers_light_shadows(&self, caller: FnId) -> bool {
        self.defers_light_shadows_at_all()
            && self.program.functions[caller].program == Some(ProgramKind::Light)
    }
}

impl Intrinsics for KernelHooks<'_> {
    fn lower(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        call: &IntrinsicCall<'_>,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        if call.builtin == Builtin::Spawn {
            let f = self.spawn_fn(cx)?;
            fb.call(f, call.args.to_vec(), false, call.span);
            return Ok(None);
        }
        let name = match call.builtin {
            Builtin::Shadow if self.replay_shadows => Some("shadow_replay"),
            Builtin::Shadow if self.defers_light_shadows(call.caller) => Some("shadow_deferred"),
            Builtin::SampleLight if self.defers_light_shadows_at_all() => {
                Some("sample_light_deferred")
            }
            Builtin::SampleLightAbove if self.defers_light_shadows_at_all() => {
                Some("sample_light_above_deferred")
            }
            b => user_intrinsic_fn(b),
        };
        let name = name.ok_or_else(|| {
            kernel_error(format!(
                "`{:?}` is not an intrinsic of the kernel",
                call.builtin
            ))
        })?;
        let id = kernel_fn(self.program, name)?;
        let f = cx.ensure_function(id, self)?;
        let has_result = self.program.functions[id].ret != TypeTable::VOID;
        Ok(fb.call(f, call.args.to_vec(), has_result, call.span))
    }

    fn lower_call(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        call: &FunctionCall<'_>,
    ) -> Result<CallLowering, LowerError> {
        let func = &self.program.functions[call.callee];
        if self.program.modules[func.module.index()].name != ABI_MODULE {
            return Ok(CallLowering::Default);
        }
        if let Some(intrinsic) = Intrinsic::from_name(&func.name) {
            return self
                .framework_call(cx, fb, intrinsic, call.callee, call.args, call.span)
                .map(CallLowering::Done);
        }
        if let Some(a) = abi::accessor(&func.name) {
            let r = call
                .args
                .first()
                .copied()
                .ok_or_else(|| kernel_error(format!("`{}` lacks its argument", func.name)))?;
            return self
                .record_field(cx, fb, a, r, call.span)
                .map(|v| CallLowering::Done(Some(v)));
        }
        // The node decoders (`node_box_lo`, …): ordinary functions.
        Ok(CallLowering::Default)
    }
}

impl KernelHooks<'_> {
    /// `rt_spawn(dir, weight)`: appends to the spawn queue (dropping rays beyond `MAX_SPAWN`).
    fn spawn_fn(&mut self, cx: &mut LowerCx<'_>) -> Result<Handle<naga::Function>, LowerError> {
        let max = self.config.max_spawn;
        let (dirs, weights, count) = self.spawn_queue(cx);
        self.generated.helper("rt_spawn", |_| {
            let v3 = TypeCache::vector(cx.module_mut(), VectorSize::Tri, Scalar::F32);
            let mut fb = FnBuilder::new("rt_spawn", &[("dir", v3), ("weight", v3)], None);
            let dir = fb.arg(0);
            let weight = fb.arg(1);
            let count_ptr = fb.expr(Expression::GlobalVariable(count), Span::UNDEFINED);
            let n = fb.load(count_ptr, Span::UNDEFINED);
            let limit = lit_u32(&mut fb, max);
            let fits = fb.expr(
                Expression::Binary {
                    op: BinaryOperator::Less,
                    left: n,
                    right: limit,
                },
                Span::UNDEFINED,
            );
            fb.push_block();
            let d = fb.expr(Expression::GlobalVariable(dirs), Span::UNDEFINED);
            let dp = fb.expr(Expression::Access { base: d, index: n }, Span::UNDEFINED);
            fb.store(dp, dir, Span::UNDEFINED);
            let w = fb.expr(Expression::GlobalVariable(weights), Span::UNDEFINED);
            let wp = fb.expr(Expression::Access { base: w, index: n }, Span::UNDEFINED);
            fb.store(wp, weight, Span::UNDEFINED);
            let one = lit_u32(&mut fb, 1);
            let next = fb.expr(
                Expression::Binary {
                    op: BinaryOperator::Add,
                    left: n,
                    right: one,
                },
                Span::UNDEFINED,
            );
            fb.store(count_ptr, next, Span::UNDEFINED);
            let accept = fb.pop_block();
            fb.stmt(
                Statement::If {
                    condition: fits,
                    accept,
                    reject: naga::Block::new(),
                },
                Span::UNDEFINED,
            );
            Ok(cx
                .module_mut()
                .functions
                .append(fb.finish(), Span::UNDEFINED))
        })
    }

    /// The private globals of the spawn queue: directions, weights, count.
    fn spawn_queue(
        &mut self,
        cx: &mut LowerCx<'_>,
    ) -> (
        Handle<naga::GlobalVariable>,
        Handle<naga::GlobalVariable>,
        Handle<naga::GlobalVariable>,
    ) {
        let v3 = TypeCache::vector(cx.module_mut(), VectorSize::Tri, Scalar::F32);
        let arr = TypeCache::array(cx.module_mut(), v3, self.config.max_spawn.max(1));
        let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        let dirs = self.generated.private(cx, "spawn_dirs", arr);
        let weights = self.generated.private(cx, "spawn_weights", arr);
        let count = self.generated.private(cx, "spawn_count", u);
        (dirs, weights, count)
    }

    /// Entries of the traversal stack: the scene-level and the object-level parts.
    fn traversal_stack_len(&self) -> u32 {
        (self.config.tlas_stack + self.config.blas_stack).max(1)
    }

    /// The traversal stack, a private global of `u32` node indices. A private global is zeroed
    /// once per invocation, where a local array is zeroed at every call of the function that
    /// declares it (once per ray), which on CPU drivers costs more than the traversal itself.
    fn traversal_stack(&mut self, cx: &mut LowerCx<'_>) -> Handle<naga::GlobalVariable> {
        let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        let arr = TypeCache::array(cx.module_mut(), u, self.traversal_stack_len());
        self.generated.private(cx, "traversal_stack", arr)
    }

    /// The private count of rays this invocation traced.
    fn ray_count(&mut self, cx: &mut LowerCx<'_>) -> Handle<naga::GlobalVariable> {
        let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        self.generated.private(cx, "ray_count", u)
    }

    /// The private globals of a debug kernel's counters: nodes visited, primitives tested (zero at
    /// the start of each invocation, which renders one pixel).
    fn debug_counters(
        &mut self,
        cx: &mut LowerCx<'_>,
    ) -> (Handle<naga::GlobalVariable>, Handle<naga::GlobalVariable>) {
        let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        let nodes = self.generated.private(cx, "debug_nodes", u);
        let prims = self.generated.private(cx, "debug_primitives", u);
        (nodes, prims)
    }

    /// Loads element `index` (or the whole value) of an ABI binding.
    fn load_binding(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        binding: &str,
        index: Option<Handle<Expression>>,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let g = self
            .generated
            .binding(cx, self.program, abi_binding(binding)?)?;
        let gp = fb.expr(Expression::GlobalVariable(g), span);
        let ptr = match index {
            Some(i) => fb.expr(Expression::Access { base: gp, index: i }, span),
            None => gp,
        };
        Ok(fb.load(ptr, span))
    }

    /// A record accessor of `rtc:abi` (`texture_width(t)`, `triangle_v1(slot)`, …): the one load
    /// its generated body makes, built as the lowering of that body's expression would build it
    /// (`r + offset` or `r * stride + offset`, literals only where not 0), so the kernel's code is
    /// the same as with the load written out.
    fn record_field(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        a: abi::Accessor,
        r: Handle<Expression>,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let rec = a.record;
        let mut index = r;
        if rec.addressing == abi::Addressing::Slot {
            let stride = lit_u32(fb, rec.stride);
            index = fb.binary(BinaryOperator::Multiply, index, stride, span);
        }
        if a.field.offset != 0 {
            let offset = lit_u32(fb, a.field.offset);
            index = fb.binary(BinaryOperator::Add, index, offset, span);
        }
        self.load_binding(cx, fb, rec.binding, Some(index), span)
    }

    /// Lowers a call of a framework intrinsic (a function of `rtc:abi`).
    fn framework_call(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        intrinsic: Intrinsic,
        callee: FnId,
        args: &[Handle<Expression>],
        span: Span,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        let program = self.program;
        let func = &program.functions[callee];
        let name = intrinsic.name();
        let arg = |i: usize| {
            args.get(i)
                .copied()
                .ok_or_else(|| kernel_error(format!("`{name}` lacks argument {i}")))
        };
        use Intrinsic as I;
        let value = match intrinsic {
            I::LoadFrame => self.load_binding(cx, fb, "frame", None, span)?,
            I::LoadTile => self.load_binding(cx, fb, "tile", None, span)?,
            I::LoadNode => self.load_binding(cx, fb, "nodes", Some(arg(0)?), span)?,
            I::LoadInstance => self.load_binding(cx, fb, "instances", Some(arg(0)?), span)?,
            I::LoadTriangleVertex => self.load_binding(cx, fb, "triangles", Some(arg(0)?), span)?,
            I::LoadAttribute => self.load_binding(cx, fb, "attributes", Some(arg(0)?), span)?,
            I::LoadParam => self.load_binding(cx, fb, "params", Some(arg(0)?), span)?,
            I::LoadTexel => self.load_binding(cx, fb, "texels", Some(arg(0)?), span)?,
            I::Accumulate => {
                self.accumulate(cx, fb, [arg(0)?, arg(1)?, arg(2)?, arg(3)?], span)?;
                return Ok(None);
            }
            I::WriteBounds => {
                self.write_bounds(cx, fb, arg(0)?, arg(1)?, arg(2)?, span)?;
                return Ok(None);
            }
            I::RngLoad | I::RngStore => {
                let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
                let g = self.generated.private(cx, "rng_state", u);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                if intrinsic == I::RngStore {
                    fb.store(p, arg(0)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            I::HitErrorLoad | I::HitErrorStore => {
                let f = TypeCache::scalar(cx.module_mut(), Scalar::F32);
                let g = self.generated.private(cx, "hit_error", f);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                if intrinsic == I::HitErrorStore {
                    fb.store(p, arg(0)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            I::HitExtraLoad | I::HitExtraStore => {
                let u = TypeCache::vector(cx.module_mut(), naga::VectorSize::Quad, Scalar::U32);
                let g = self.generated.private(cx, "hit_extra", u);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                if intrinsic == I::HitExtraStore {
                    fb.store(p, arg(0)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            I::StackLoad | I::StackStore => {
                let g = self.traversal_stack(cx);
                let base = fb.expr(Expression::GlobalVariable(g), span);
                // Clamped like every array index of the language: never outside the stack.
                let last = lit_u32(fb, self.traversal_stack_len() - 1);
                let i = fb.expr(
                    Expression::Math {
                        fun: naga::MathFunction::Min,
                        arg: arg(0)?,
                        arg1: Some(last),
                        arg2: None,
                        arg3: None,
                    },
                    span,
                );
                let p = fb.expr(Expression::Access { base, index: i }, span);
                if intrinsic == I::StackStore {
                    fb.store(p, arg(1)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            I::PathLoad | I::PathStore | I::PathLoad4 | I::PathStore4 => {
                // `paths` is an array of `vec4u` chunks: a chunk is one access, a word the
                // chunk's component `k`.
                let program = self.program;
                let paths = self.generated.binding(cx, program, abi_binding("paths")?)?;
                let g = fb.expr(Expression::GlobalVariable(paths), span);
                let mut p = fb.expr(
                    Expression::Access {
                        base: g,
                        index: arg(0)?,
                    },
                    span,
                );
                let word = matches!(intrinsic, I::PathLoad | I::PathStore);
                if word {
                    // A literal component is a constant index: the driver then reads or writes
                    // that word alone (Mesa may lower a dynamic one to a whole-chunk access).
                    let k = arg(1)?;
                    p = match fb.literal_u32(k) {
                        Some(index) if index < 4 => {
                            fb.expr(Expression::AccessIndex { base: p, index }, span)
                        }
                        _ => fb.expr(Expression::Access { base: p, index: k }, span),
                    };
                }
                match intrinsic {
                    I::PathStore => {
                        fb.store(p, arg(2)?, span);
                        return Ok(None);
                    }
                    I::PathStore4 => {
                        fb.store(p, arg(1)?, span);
                        return Ok(None);
                    }
                    _ => fb.load(p, span),
                }
            }
            I::ScratchLoad | I::ScratchStore => {
                let u = TypeCache::scalar(cx.module_mut(), Scalar::U32);
                let words = if self.defers_light_shadows_at_all() {
                    SCRATCH_WORDS_DEFERRING
                } else {
                    SCRATCH_WORDS
                };
                let arr = TypeCache::array(cx.module_mut(), u, words);
                let g = self.generated.private(cx, "scratch", arr);
                let base = fb.expr(Expression::GlobalVariable(g), span);
                let last = lit_u32(fb, words - 1);
                let i = fb.expr(
                    Expression::Math {
                        fun: naga::MathFunction::Min,
                        arg: arg(0)?,
                        arg1: Some(last),
                        arg2: None,
                        arg3: None,
                    },
                    span,
                );
                let p = fb.expr(Expression::Access { base, index: i }, span);
                if intrinsic == I::ScratchStore {
                    fb.store(p, arg(1)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            I::CounterAdd => {
                let program = self.program;
                let counters = self
                    .generated
                    .binding(cx, program, abi_binding("counters")?)?;
                let c = fb.expr(Expression::GlobalVariable(counters), span);
                let last = lit_u32(fb, abi::COUNTER_WORDS - 1);
                let i = fb.expr(
                    Expression::Math {
                        fun: naga::MathFunction::Min,
                        arg: arg(0)?,
                        arg1: Some(last),
                        arg2: None,
                        arg3: None,
                    },
                    span,
                );
                let p = fb.expr(Expression::Access { base: c, index: i }, span);
                fb.stmt(
                    Statement::Atomic {
                        pointer: p,
                        fun: AtomicFunction::Add,
                        value: arg(1)?,
                        result: None,
                    },
                    span,
                );
                return Ok(None);
            }
            // A shade stage whose shadow stage traces its queries traces none: its count is 0, a
            // literal (a load of the never-written counter measurably slowed pbr_path's shade
            // stage).
            I::RayCountLoad if self.traces_no_rays => lit_u32(fb, 0),
            I::PendingStepWaits => {
                let name = if self.replay_shadows && !self.traces_no_rays {
                    "wf_trace_pending"
                } else {
                    "wf_wait_for_shadow_stage"
                };
                let id = kernel_fn(program, name)?;
                let f = cx.ensure_function(id, self)?;
                return Ok(fb.call(f, Vec::new(), true, span));
            }
            I::SampleDone => {
                let name = if self.accumulates {
                    "wf_sample_accumulate"
                } else {
                    "wf_sample_done"
                };
                let id = kernel_fn(program, name)?;
                let f = cx.ensure_function(id, self)?;
                fb.call(f, vec![arg(0)?], false, span);
                return Ok(None);
            }
            I::RayCountLoad => {
                let g = self.ray_count(cx);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                fb.load(p, span)
            }
            I::CountRay => {
                let g = self.ray_count(cx);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                let old = fb.load(p, span);
                let one = lit_u32(fb, 1);
                let new = fb.expr(
                    Expression::Binary {
                        op: BinaryOperator::Add,
                        left: old,
                        right: one,
                    },
                    span,
                );
                fb.store(p, new, span);
                return Ok(None);
            }
            I::FlushRayCount => {
                let program = self.program;
                let g = self.ray_count(cx);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                let n = fb.load(p, span);
                let counters = self
                    .generated
                    .binding(cx, program, abi_binding("counters")?)?;
                let c = fb.expr(Expression::GlobalVariable(counters), span);
                let second = fb.expr(
                    Expression::AccessIndex {
                        base: c,
                        index: abi::COUNTER_RAYS,
                    },
                    span,
                );
                fb.stmt(
                    Statement::Atomic {
                        pointer: second,
                        fun: AtomicFunction::Add,
                        value: n,
                        result: None,
                    },
                    span,
                );
                // Zeroed, so a later flush adds only the rays traced after this one.
                let zero = lit_u32(fb, 0);
                fb.store(p, zero, span);
                return Ok(None);
            }
            I::DebugCount => {
                let (nodes, prims) = self.debug_counters(cx);
                for (g, i) in [(nodes, 0), (prims, 1)] {
                    let p = fb.expr(Expression::GlobalVariable(g), span);
                    let old = fb.load(p, span);
                    let new = fb.expr(
                        Expression::Binary {
                            op: BinaryOperator::Add,
                            left: old,
                            right: arg(i)?,
                        },
                        span,
                    );
                    fb.store(p, new, span);
                }
                return Ok(None);
            }
            I::DebugCounts => {
                let (nodes, prims) = self.debug_counters(cx);
                let pn = fb.expr(Expression::GlobalVariable(nodes), span);
                let n = fb.load(pn, span);
                let pp = fb.expr(Expression::GlobalVariable(prims), span);
                let p = fb.load(pp, span);
                let v2 = TypeCache::vector(cx.module_mut(), VectorSize::Bi, Scalar::U32);
                fb.expr(
                    Expression::Compose {
                        ty: v2,
                        components: vec![n, p],
                    },
                    span,
                )
            }
            I::SpawnReset => {
                let (_, _, count) = self.spawn_queue(cx);
                let p = fb.expr(Expression::GlobalVariable(count), span);
                let zero = lit_u32(fb, 0);
                fb.store(p, zero, span);
                return Ok(None);
            }
            I::SpawnedCount => {
                let (_, _, count) = self.spawn_queue(cx);
                let p = fb.expr(Expression::GlobalVariable(count), span);
                let n = fb.load(p, span);
                let max = lit_u32(fb, self.config.max_spawn);
                fb.expr(
                    Expression::Math {
                        fun: naga::MathFunction::Min,
                        arg: n,
                        arg1: Some(max),
                        arg2: None,
                        arg3: None,
                    },
                    span,
                )
            }
            I::SpawnedDir | I::SpawnedWeight => {
                let (dirs, weights, _) = self.spawn_queue(cx);
                let g = if intrinsic == I::SpawnedDir {
                    dirs
                } else {
                    weights
                };
                let p = fb.expr(Expression::GlobalVariable(g), span);
                let e = fb.expr(
                    Expression::Access {
                        base: p,
                        index: arg(0)?,
                    },
                    span,
                );
                fb.load(e, span)
            }
            I::Call(kind) => {
                let params: Vec<(String, TypeId)> = func
                    .params
                    .iter()
                    .skip(2)
                    .map(|&l| (func.body.locals[l].name.clone(), func.body.locals[l].ty))
                    .collect();
                let ret = (func.ret != TypeTable::VOID).then_some(func.ret);
                let d = self.dispatcher(cx, kind, &params, ret)?;
                return Ok(fb.call(d, args.to_vec(), ret.is_some(), span));
            }
        };
        Ok(Some(value))
    }

    /// The dispatcher of a program kind for the linked scene: `dispatch_<kind>(type_id, offset, args…)`.
    ///
    /// `params` are its parameters after `type_id` and `offset`, as the framework intrinsic
    /// `call_<kind>` declares them; `result` its result type. A kind with one program is a direct
    /// call; with none, the dispatcher returns zero.
    fn dispatcher(
        &mut self,
        cx: &mut LowerCx<'_>,
        kind: ProgramKind,
        params: &[(String, TypeId)],
        result: Option<TypeId>,
    ) -> Result<Handle<naga::Function>, LowerError> {
        if let Some(&f) = self.generated.dispatchers.get(&kind) {
            return Ok(f);
        }
        let program = self.program;
        // Lower the programs and their loaders first: callees must precede the dispatcher.
        let mut cases = Vec::new();
        let programs: Vec<_> = self
            .linked
            .programs()
            .filter(|(k, _, _)| *k == kind)
            .map(|(_, f, t)| (f, t.struct_id, t.id))
            .collect();
        for (func, struct_id, id) in programs {
            let loader = self.generated.loader(cx, program, struct_id)?;
            let f = cx.ensure_function(func, self)?;
            let arity = program.functions[func].params.len();
            cases.push((id, loader, f, arity));
        }
        let u32_ty = TypeCache::scalar(cx.module_mut(), Scalar::U32);
        let mut args: Vec<(String, Handle<naga::Type>)> =
            vec![("type_id".into(), u32_ty), ("offset".into(), u32_ty)];
        for (n, t) in params {
            args.push((n.clone(), cx.ty(*t)?));
        }
        let result_ty = match result {
            Some(t) => Some(cx.ty(t)?),
            None => None,
        };
        let arg_refs: Vec<(&str, Handle<naga::Type>)> =
            args.iter().map(|(n, t)| (n.as_str(), *t)).collect();
        let mut fb = FnBuilder::new(&format!("dispatch_{}", kind.name()), &arg_refs, result_ty);
        let type_id = fb.arg(0);
        let offset = fb.arg(1);
        let rest: Vec<_> = (0..params.len() as u32).map(|i| fb.arg(i + 2)).collect();
        let call_case = |fb: &mut FnBuilder, loader, f, arity: usize| {
            let instance = fb.call(loader, vec![offset], true, Span::UNDEFINED);
            let mut call_args: Vec<_> = instance.into_iter().collect();
            call_args.extend(rest.iter().copied().take(arity.saturating_sub(1)));
            let r = fb.call(f, call_args, result_ty.is_some(), Span::UNDEFINED);
            fb.stmt(Statement::Return { value: r }, Span::UNDEFINED);
        };
        match cases.as_slice() {
            [] => {}
            [(_, loader, f, arity)] => call_case(&mut fb, *loader, *f, *arity),
            many => {
                let mut switch_cases = Vec::new();
                for (id, loader, f, arity) in many {
                    fb.push_block();
                    call_case(&mut fb, *loader, *f, *arity);
                    let body = fb.pop_block();
                    switch_cases.push(SwitchCase {
                        value: SwitchValue::U32(*id),
                        body,
                        fall_through: false,
                    });
                }
                switch_cases.push(SwitchCase {
                    value: SwitchValue::Default,
                    body: naga::Block::new(),
                    fall_through: false,
                });
                fb.stmt(
                    Statement::Switch {
                        selector: type_id,
                        cases: switch_cases,
                    },
                    Span::UNDEFINED,
                );
            }
        }
        if !fb.terminated() {
            let zero = result_ty.map(|t| fb.expr(Expression::ZeroValue(t), Span::UNDEFINED));
            fb.stmt(Statement::Return { value: zero }, Span::UNDEFINED);
        }
        let f = cx
            .module_mut()
            .functions
            .append(fb.finish(), Span::UNDEFINED);
        self.generated.dispatchers.insert(kind, f);
        Ok(f)
    }

    /// `accumulate(pixel, value, nonfinite, fresh)`: `accum[pixel] += value`, or `= value` when
    /// `fresh` (the pass is the first after the buffer was zeroed, so the old value, a cache miss
    /// per pixel, need not be read); counter 0 `+= nonfinite`.
    fn accumulate(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        [pixel, value, nonfinite, fresh]: [Handle<Expression>; 4],
        span: Span,
    ) -> Result<(), LowerError> {
        let program = self.program;
        let accum = self.generated.binding(cx, program, abi_binding("accum")?)?;
        let g = fb.expr(Expression::GlobalVariable(accum), span);
        let p = fb.expr(
            Expression::Access {
                base: g,
                index: pixel,
            },
            span,
        );
        fb.push_block();
        fb.store(p, value, span);
        let first = fb.pop_block();
        fb.push_block();
        let old = fb.load(p, span);
        let sum = fb.expr(
            Expression::Binary {
                op: BinaryOperator::Add,
                left: old,
                right: value,
            },
            span,
        );
        fb.store(p, sum, span);
        let later = fb.pop_block();
        fb.stmt(
            Statement::If {
                condition: fresh,
                accept: first,
                reject: later,
            },
            span,
        );
        let counters = self
            .generated
            .binding(cx, program, abi_binding("counters")?)?;
        let zero = lit_u32(fb, 0);
        let any = fb.expr(
            Expression::Binary {
                op: BinaryOperator::Greater,
                left: nonfinite,
                right: zero,
            },
            span,
        );
        fb.push_block();
        let c = fb.expr(Expression::GlobalVariable(counters), span);
        let first = fb.expr(
            Expression::AccessIndex {
                base: c,
                index: abi::COUNTER_NONFINITE,
            },
            span,
        );
        fb.stmt(
            Statement::Atomic {
                pointer: first,
                fun: AtomicFunction::Add,
                value: nonfinite,
                result: None,
            },
            span,
        );
        let accept = fb.pop_block();
        fb.stmt(
            Statement::If {
                condition: any,
                accept,
                reject: naga::Block::new(),
            },
            span,
        );
        Ok(())
    }

    fn write_bounds(
        &mut self,
        cx: &mut LowerCx<'_>,
        fb: &mut FnBuilder,
        index: Handle<Expression>,
        min: Handle<Expression>,
        max: Handle<Expression>,
        span: Span,
    ) -> Result<(), LowerError> {
        let program = self.program;
        let accum = self.generated.binding(cx, program, abi_binding("accum")?)?;
        let v4 = TypeCache::vector(cx.module_mut(), VectorSize::Quad, Scalar::F32);
        let one = fb.expr(Expression::Literal(Literal::F32(1.0)), span);
        let two = lit_u32(fb, 2);
        let at = fb.expr(
            Expression::Binary {
                op: BinaryOperator::Multiply,
                left: index,
                right: two,
            },
            span,
        );
        let k1 = lit_u32(fb, 1);
        let at1 = fb.expr(
            Expression::Binary {
                op: BinaryOperator::Add,
                left: at,
                right: k1,
            },
            span,
        );
        for (slot, v) in [(at, min), (at1, max)] {
            let value = fb.expr(
                Expression::Compose {
                    ty: v4,
                    components: vec![v, one],
                },
                span,
            );
            let g = fb.expr(Expression::GlobalVariable(accum), span);
            let p = fb.expr(
                Expression::Access {
                    base: g,
                    index: slot,
                },
                span,
            );
            fb.store(p, value, span);
        }
        Ok(())
    }
}
