//! The kernels' entry points, built in IR: thin wrappers that turn the invocation id into the work
//! item and call the kernel function written in the language.
//!
//! - `render` (`@workgroup_size(8, 8)`): one invocation per pixel of the dispatch's tile; calls
//!   `render_invocation(gid.xy)` (`stdlib/kernel/trace.rt`), which picks the pixel.
//! - `wf_count`, `wf_compact`, `wf_trace`, `wf_shade`, `wf_shadow` (in a scene whose
//!   shade stage replays its shadow rays), `wf_finish`
//!   (`@workgroup_size(8, 8)`): the wavefront model's stages (`kernel::wavefront`), each calling its
//!   `wf_*_invocation(gid.xy)`, which finds its work item from the id (a pixel of the tile, a block
//!   of slots, or an entry of the list of running paths: `kernel::wavefront::StageDispatch`).
//! - `bounds` (`@workgroup_size(64)`): one invocation per object; calls `compute_bounds(gid.x)`, which
//!   checks the object count itself.

use super::dispatch::LowerCx;
use super::{BOUNDS_ENTRY, BOUNDS_WORKGROUP, RENDER_ENTRY, RENDER_WORKGROUP};
use crate::lower::builder::{FnBuilder, TypeCache};
use crate::lower::LowerError;
use naga::{Expression, Handle, Scalar, Span, Statement, VectorSize};

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

/// The `render` entry point calling `render_invocation(gid.xy)`.
pub fn render_entry(
    cx: &mut LowerCx<'_>,
    render_invocation: Handle<naga::Function>,
) -> Result<(), LowerError> {
    pixel_entry(cx, RENDER_ENTRY, render_invocation)
}

/// A wavefront stage's entry point `name` (`wf_trace`, …) calling its `wf_*_invocation(gid.xy)`,
/// with the render kernel's workgroup size: one invocation per pixel of the tile.
pub fn stage_entry(
    cx: &mut LowerCx<'_>,
    name: &str,
    invocation: Handle<naga::Function>,
) -> Result<(), LowerError> {
    pixel_entry(cx, name, invocation)
}

/// An entry point `name` calling `invocation(gid.xy)`, `@workgroup_size(8, 8)`.
fn pixel_entry(
    cx: &mut LowerCx<'_>,
    name: &str,
    render_invocation: Handle<naga::Function>,
) -> Result<(), LowerError> {
    let v2u = TypeCache::vector(cx.module_mut(), VectorSize::Bi, Scalar::U32);
    let mut fb = compute_fn(cx, name);
    let s = Span::UNDEFINED;
    let gid = fb.arg(0);
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
    let id = fb.expr(
        Expression::Compose {
            ty: v2u,
            components: vec![gx, gy],
        },
        s,
    );
    fb.call(render_invocation, vec![id], false, s);
    fb.stmt(Statement::Return { value: None }, s);
    push_entry(cx, name, fb, [RENDER_WORKGROUP[0], RENDER_WORKGROUP[1], 1]);
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
