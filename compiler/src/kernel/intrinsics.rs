//! Lowering of intrinsics: the framework's (declared in `rtc:abi`) and the user-facing ones.
//!
//! - Framework intrinsics read the kernel's buffers (`load_*`), keep per-invocation state in private
//!   globals (the random-number state and the spawn queue), accumulate, and call the generated
//!   dispatchers (`call_<kind>` → `dispatch_<kind>`).
//! - User intrinsics (spec/programs.md) become calls of the kernel's own functions written in the
//!   language (`rand()` → `rand_next`, `shadow(…)` → `shadow_query`, …), except `spawn`, which appends to
//!   the spawn queue.
//!
//! Invariant: the spawn queue never writes past `MAX_SPAWN` entries; `spawned_count` is clamped.

use super::dispatch::{abi_binding, Generated, LowerCx};
use crate::link::{KernelConfig, Linked};
use crate::lower::builder::{FnBuilder, TypeCache};
use crate::sema::builtins::Builtin;
use crate::sema::hir::{FnId, Program, ProgramKind};
use naga::{
    AtomicFunction, BinaryOperator, Expression, Handle, Literal, Scalar, Span, Statement,
    VectorSize,
};

/// Everything intrinsic lowering needs besides the lowerer.
pub struct KernelCx<'a> {
    /// The checked program (user code, stdlib, kernel).
    pub program: &'a Program,
    /// The link plan.
    pub linked: &'a Linked,
    /// The kernel's constants.
    pub config: KernelConfig,
    /// Generated globals and functions.
    pub generated: Generated,
}

/// The kernel function (from `stdlib/kernel/`) named `name`.
pub fn kernel_fn(program: &Program, name: &str) -> Result<FnId, String> {
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
        .ok_or_else(|| format!("the framework kernel has no function `{name}`"))
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
        Builtin::Shadow => "shadow_query",
        _ => return None,
    })
}

fn lit_u32(fb: &mut FnBuilder, v: u32) -> Handle<Expression> {
    fb.expr(Expression::Literal(Literal::U32(v)), Span::UNDEFINED)
}

impl KernelCx<'_> {
    /// Lowers a call of a user-facing intrinsic. `Ok(None)` for a call without a value; `Err` if `b` is
    /// not an intrinsic this kernel implements.
    pub fn lower_user_intrinsic(
        &mut self,
        cx: &mut dyn LowerCx,
        fb: &mut FnBuilder,
        b: Builtin,
        args: &[Handle<Expression>],
        span: Span,
    ) -> Result<Option<Handle<Expression>>, String> {
        if b == Builtin::Spawn {
            let f = self.spawn_fn(cx)?;
            fb.call(f, args.to_vec(), false, span);
            return Ok(None);
        }
        let name = user_intrinsic_fn(b).ok_or_else(|| format!("`{b:?}` is not an intrinsic"))?;
        let id = kernel_fn(self.program, name)?;
        let f = cx.lower_function(id)?;
        let has_result = self.program.functions[id].ret != crate::sema::types::TypeTable::VOID;
        Ok(fb.call(f, args.to_vec(), has_result, span))
    }

    /// `rt_spawn(dir, weight)`: appends to the spawn queue (dropping rays beyond `MAX_SPAWN`).
    fn spawn_fn(&mut self, cx: &mut dyn LowerCx) -> Result<Handle<naga::Function>, String> {
        let max = self.config.max_spawn;
        let (dirs, weights, count) = self.spawn_queue(cx);
        self.generated.helper("rt_spawn", |_| {
            let v3 = TypeCache::vector(cx.module(), VectorSize::Tri, Scalar::F32);
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
            Ok(cx.module().functions.append(fb.finish(), Span::UNDEFINED))
        })
    }

    /// The private globals of the spawn queue: directions, weights, count.
    fn spawn_queue(
        &mut self,
        cx: &mut dyn LowerCx,
    ) -> (
        Handle<naga::GlobalVariable>,
        Handle<naga::GlobalVariable>,
        Handle<naga::GlobalVariable>,
    ) {
        let v3 = TypeCache::vector(cx.module(), VectorSize::Tri, Scalar::F32);
        let arr = TypeCache::array(cx.module(), v3, self.config.max_spawn.max(1));
        let u = TypeCache::scalar(cx.module(), Scalar::U32);
        let dirs = self.generated.private(cx, "spawn_dirs", arr);
        let weights = self.generated.private(cx, "spawn_weights", arr);
        let count = self.generated.private(cx, "spawn_count", u);
        (dirs, weights, count)
    }

    /// Lowers a call of a framework intrinsic (a function of `rtc:abi`) named `name`.
    pub fn lower_framework_call(
        &mut self,
        cx: &mut dyn LowerCx,
        fb: &mut FnBuilder,
        callee: FnId,
        args: &[Handle<Expression>],
        span: Span,
    ) -> Result<Option<Handle<Expression>>, String> {
        let program = self.program;
        let func = &program.functions[callee];
        let name = func.name.as_str();
        let load_binding = |this: &mut Self,
                            cx: &mut dyn LowerCx,
                            fb: &mut FnBuilder,
                            binding: &str,
                            index: Option<Handle<Expression>>| {
            let g = this.generated.binding(cx, program, abi_binding(binding)?)?;
            let gp = fb.expr(Expression::GlobalVariable(g), span);
            let ptr = match index {
                Some(i) => fb.expr(Expression::Access { base: gp, index: i }, span),
                None => gp,
            };
            Ok::<_, String>(fb.load(ptr, span))
        };
        let arg = |i: usize| {
            args.get(i)
                .copied()
                .ok_or_else(|| format!("`{name}` lacks argument {i}"))
        };
        let value = match name {
            "load_frame" => load_binding(self, cx, fb, "frame", None)?,
            "load_tile" => load_binding(self, cx, fb, "tile", None)?,
            "load_node" => load_binding(self, cx, fb, "nodes", Some(arg(0)?))?,
            "load_instance" => load_binding(self, cx, fb, "instances", Some(arg(0)?))?,
            "load_triangle_vertex" => load_binding(self, cx, fb, "triangles", Some(arg(0)?))?,
            "load_attribute" => load_binding(self, cx, fb, "attributes", Some(arg(0)?))?,
            "load_param" => load_binding(self, cx, fb, "params", Some(arg(0)?))?,
            "load_texel" => load_binding(self, cx, fb, "texels", Some(arg(0)?))?,
            "accumulate" => {
                self.accumulate(cx, fb, arg(0)?, arg(1)?, arg(2)?, span)?;
                return Ok(None);
            }
            "write_bounds" => {
                self.write_bounds(cx, fb, arg(0)?, arg(1)?, arg(2)?, span)?;
                return Ok(None);
            }
            "rng_load" | "rng_store" => {
                let u = TypeCache::scalar(cx.module(), Scalar::U32);
                let g = self.generated.private(cx, "rng_state", u);
                let p = fb.expr(Expression::GlobalVariable(g), span);
                if name == "rng_store" {
                    fb.store(p, arg(0)?, span);
                    return Ok(None);
                }
                fb.load(p, span)
            }
            "spawn_reset" => {
                let (_, _, count) = self.spawn_queue(cx);
                let p = fb.expr(Expression::GlobalVariable(count), span);
                let zero = lit_u32(fb, 0);
                fb.store(p, zero, span);
                return Ok(None);
            }
            "spawned_count" => {
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
            "spawned_dir" | "spawned_weight" => {
                let (dirs, weights, _) = self.spawn_queue(cx);
                let g = if name == "spawned_dir" { dirs } else { weights };
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
            _ => {
                let Some(kind) = name.strip_prefix("call_").and_then(ProgramKind::from_name) else {
                    return Err(format!("unknown framework intrinsic `{name}`"));
                };
                let params: Vec<_> = func.params[2..]
                    .iter()
                    .map(|&l| (func.body.locals[l].name.clone(), func.body.locals[l].ty))
                    .collect();
                let ret = (func.ret != crate::sema::types::TypeTable::VOID).then_some(func.ret);
                let d = self
                    .generated
                    .dispatcher(cx, program, self.linked, kind, &params, ret)?;
                return Ok(fb.call(d, args.to_vec(), ret.is_some(), span));
            }
        };
        Ok(Some(value))
    }

    fn accumulate(
        &mut self,
        cx: &mut dyn LowerCx,
        fb: &mut FnBuilder,
        pixel: Handle<Expression>,
        value: Handle<Expression>,
        nonfinite: Handle<Expression>,
        span: Span,
    ) -> Result<(), String> {
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
        let first = fb.expr(Expression::AccessIndex { base: c, index: 0 }, span);
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
        cx: &mut dyn LowerCx,
        fb: &mut FnBuilder,
        index: Handle<Expression>,
        min: Handle<Expression>,
        max: Handle<Expression>,
        span: Span,
    ) -> Result<(), String> {
        let program = self.program;
        let accum = self.generated.binding(cx, program, abi_binding("accum")?)?;
        let v4 = TypeCache::vector(cx.module(), VectorSize::Quad, Scalar::F32);
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
