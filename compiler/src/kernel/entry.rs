//! The kernels' entry points, built in IR: thin wrappers that turn the invocation id into the work
//! item and call the kernel function written in the language.
//!
//! - `render` (`@workgroup_size(8, 8)`): one invocation per pixel of the dispatch's tile; returns early
//!   outside the tile's extent, else calls `render_pixel(tile.origin + gid.xy)`.
//! - `bounds` (`@workgroup_size(64)`): one invocation per object; calls `compute_bounds(gid.x)`, which
//!   checks the object count itself.

use super::dispatch::{abi_binding, LowerCx};
use super::intrinsics::KernelHooks;
use super::{BOUNDS_ENTRY, BOUNDS_WORKGROUP, RENDER_ENTRY, RENDER_WORKGROUP};
use crate::lower::builder::{FnBuilder, TypeCache};
use crate::lower::LowerError;
use naga::{BinaryOperator, Expression, Handle, Scalar, Span, Statement, VectorSize};

/// A compute function taking `@builtin(global_invocation_id) gid: vec3<u32>`.
fn compute_fn(cx: &mut LowerCx<'_>, name: &str) -> FnBuilder {
    let v3u = TypeCache::vector(cx.module_mut(), VectorSize::Tri, Scalar::U32);
    FnBuilder::new(name, &[("gid", v3u)], None)
}

fn push_entry(cx: &mut LowerCx<'_>, name: &str, fb: FnBuilder, workgroup_size: [u32; 3]) {
    let mut function = fb.finish();
    if let Some(arg) = function.arguments.first_mut() {
        arg.binding = Some(naga::Binding::BuiltIn(naga::BuiltIn::GlobalInvocationId));
    }
    cx.module_mut().entry_points.push(naga::EntryPoint {
        name: name.to_string(),
        stage: naga::ShaderStage::Compute,
        early_depth_test: None,
        workgroup_size,
        workgroup_size_overrides: None,
        function,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
}

/// The `render` entry point calling `render_pixel`.
pub fn render_entry(
    cx: &mut LowerCx<'_>,
    hooks: &mut KernelHooks<'_>,
    render_pixel: Handle<naga::Function>,
) -> Result<(), LowerError> {
    let program = hooks.program;
    let tile_global = hooks.generated.binding(cx, program, abi_binding("tile")?)?;
    let v2u = TypeCache::vector(cx.module_mut(), VectorSize::Bi, Scalar::U32);
    let mut fb = compute_fn(cx, RENDER_ENTRY);
    let s = Span::UNDEFINED;
    let gid = fb.arg(0);
    let g = fb.expr(Expression::GlobalVariable(tile_global), s);
    let tile = fb.load(g, s);
    // TileParams: origin (0), extent (1).
    let origin = fb.expr(
        Expression::AccessIndex {
            base: tile,
            index: 0,
        },
        s,
    );
    let extent = fb.expr(
        Expression::AccessIndex {
            base: tile,
            index: 1,
        },
        s,
    );
    let gx = fb.expr(
        Expression::AccessIndex {
            base: gid,
            index: 0,
        },
        s,
    );
    let gy = fb.expr(
        Expression::AccessIndex {
            base: gid,
            index: 1,
        },
        s,
    );
    let local = fb.expr(
        Expression::Compose {
            ty: v2u,
            components: vec![gx, gy],
        },
        s,
    );
    let outside = fb.expr(
        Expression::Binary {
            op: BinaryOperator::GreaterEqual,
            left: local,
            right: extent,
        },
        s,
    );
    let any = fb.expr(
        Expression::Relational {
            fun: naga::RelationalFunction::Any,
            argument: outside,
        },
        s,
    );
    fb.push_block();
    fb.stmt(Statement::Return { value: None }, s);
    let accept = fb.pop_block();
    fb.stmt(
        Statement::If {
            condition: any,
            accept,
            reject: naga::Block::new(),
        },
        s,
    );
    let pixel = fb.expr(
        Expression::Binary {
            op: BinaryOperator::Add,
            left: origin,
            right: local,
        },
        s,
    );
    fb.call(render_pixel, vec![pixel], false, s);
    fb.stmt(Statement::Return { value: None }, s);
    push_entry(
        cx,
        RENDER_ENTRY,
        fb,
        [RENDER_WORKGROUP[0], RENDER_WORKGROUP[1], 1],
    );
    Ok(())
}

/// The `bounds` entry point calling `compute_bounds`.
pub fn bounds_entry(
    cx: &mut LowerCx<'_>,
    compute_bounds: Handle<naga::Function>,
) -> Result<(), LowerError> {
    let mut fb = compute_fn(cx, BOUNDS_ENTRY);
    let s = Span::UNDEFINED;
    let gid = fb.arg(0);
    let i = fb.expr(
        Expression::AccessIndex {
            base: gid,
            index: 0,
        },
        s,
    );
    fb.call(compute_bounds, vec![i], false, s);
    fb.stmt(Statement::Return { value: None }, s);
    push_entry(cx, BOUNDS_ENTRY, fb, [BOUNDS_WORKGROUP, 1, 1]);
    Ok(())
}
