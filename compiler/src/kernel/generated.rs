//! The two modules the compiler generates for the framework kernel: `rtc:abi` and `rtc:config`.
//!
//! - `rtc:abi` declares, in the language, the GPU structs of [`crate::abi`] (so the kernel reads buffers
//!   with ordinary field access) and the framework intrinsics as functions with placeholder bodies (buffer
//!   loads, dispatch to the scene's programs, the spawn queue, the random-number state, accumulation).
//!   It is the same for every scene.
//! - `rtc:config` holds the scene's kernel constants ([`KernelConfig`]): stack sizes and which features
//!   the scene uses. The kernel decides every `if` on them at compile time.
//!
//! Both are generated from typed data (the ABI table, the link plan): they contain names from static
//! tables and numbers, never text that came from a user's source, so no escaping or mangling is needed.
//!
//! Invariant: the text is deterministic, and `rtc:abi` only changes when `abi.rs` does.

use crate::abi::{FieldType, StructDesc, FRAME, INSTANCE, NODE, TILE};
use crate::link::KernelConfig;
use std::fmt::Write;

/// The import path of the generated ABI module.
pub const ABI_MODULE: &str = "rtc:abi";
/// The import path of the generated configuration module.
pub const CONFIG_MODULE: &str = "rtc:config";

fn type_name(t: FieldType) -> &'static str {
    match t {
        FieldType::U32 => "u32",
        FieldType::F32 => "f32",
        FieldType::Vec2U32 => "vec2u",
        FieldType::Vec3F32 => "vec3f",
        FieldType::Vec4F32 => "vec4f",
        FieldType::Vec4U32 => "vec4u",
    }
}

fn write_struct(out: &mut String, s: &StructDesc) {
    let _ = writeln!(out, "/// {}", s.doc);
    let _ = writeln!(out, "struct {} {{", s.name);
    for f in s.fields {
        let _ = writeln!(out, "    {}: {},", f.name, type_name(f.ty));
    }
    let _ = writeln!(out, "}}\n");
}

/// The framework intrinsics: `(name, parameters, result)`; the lowering implements each.
pub const INTRINSICS: &[(&str, &str, &str)] = &[
    ("load_frame", "", "FrameUniforms"),
    ("load_tile", "", "TileParams"),
    ("load_node", "i: u32", "GpuNode"),
    ("load_instance", "i: u32", "GpuInstance"),
    ("load_triangle_vertex", "i: u32", "vec4f"),
    ("load_attribute", "i: u32", "vec4u"),
    ("load_param", "i: u32", "u32"),
    ("load_texel", "i: u32", "u32"),
    (
        "accumulate",
        "pixel: u32, value: vec4f, nonfinite: u32, fresh: bool",
        "",
    ),
    ("rng_load", "", "u32"),
    ("rng_store", "state: u32", ""),
    ("hit_error_load", "", "f32"),
    ("hit_error_store", "error: f32", ""),
    ("spawn_reset", "", ""),
    ("spawned_count", "", "u32"),
    ("spawned_dir", "i: u32", "vec3f"),
    ("spawned_weight", "i: u32", "vec3f"),
    (
        "call_ray_generation",
        "type_id: u32, offset: u32, pixel: vec2u, sample: u32",
        "Ray",
    ),
    (
        "call_intersection",
        "type_id: u32, offset: u32, ray: Ray",
        "Intersection",
    ),
    ("call_bounds", "type_id: u32, offset: u32", "Aabb"),
    (
        "call_any_hit",
        "type_id: u32, offset: u32, ray: Ray, hit: Hit",
        "bool",
    ),
    (
        "call_closest_hit",
        "type_id: u32, offset: u32, ray: Ray, hit: Hit, secondary: vec3f",
        "vec3f",
    ),
    (
        "call_secondary_rays",
        "type_id: u32, offset: u32, ray: Ray, hit: Hit",
        "",
    ),
    (
        "call_medium",
        "type_id: u32, offset: u32, ray: Ray, t: f32, radiance: vec3f",
        "vec3f",
    ),
    (
        "call_light",
        "type_id: u32, offset: u32, position: vec3f, normal: vec3f",
        "LightSample",
    ),
    ("call_miss", "type_id: u32, offset: u32, ray: Ray", "vec3f"),
    ("write_bounds", "i: u32, lo: vec3f, hi: vec3f", ""),
    ("stack_load", "i: u32", "u32"),
    ("stack_store", "i: u32, node: u32", ""),
    ("count_ray", "", ""),
    ("flush_ray_count", "", ""),
    ("debug_count", "nodes: u32, primitives: u32", ""),
    ("debug_counts", "", "vec2u"),
];

/// A zero value of a type named in [`INTRINSICS`], as source text (the placeholder bodies).
fn zero_of(ty: &str) -> String {
    let abi_struct = [&TILE, &FRAME, &NODE, &INSTANCE]
        .into_iter()
        .find(|s| s.name == ty);
    if let Some(s) = abi_struct {
        let fields: Vec<String> = s
            .fields
            .iter()
            .map(|f| format!("{}: {}", f.name, zero_of(type_name(f.ty))))
            .collect();
        return format!("{} {{ {} }}", s.name, fields.join(", "));
    }
    match ty {
        "u32" => "0u".into(),
        "f32" => "0.0".into(),
        "bool" => "false".into(),
        "vec2u" => "vec2u(0u)".into(),
        "vec4u" => "vec4u(0u)".into(),
        "vec3f" => "vec3f(0.0)".into(),
        "vec4f" => "vec4f(0.0)".into(),
        "Ray" => "Ray { origin: vec3f(0.0), dir: vec3f(0.0) }".into(),
        "Intersection" => "Intersection {}".into(),
        "Aabb" => "Aabb { min: vec3f(0.0), max: vec3f(0.0) }".into(),
        "LightSample" => "LightSample { dir: vec3f(0.0), dist: 0.0, radiance: vec3f(0.0) }".into(),
        other => format!("{other}()"),
    }
}

/// The text of `rtc:abi`.
pub fn abi_module() -> String {
    let mut out = String::from(
        "//! Generated by rtc from compiler/src/abi.rs: the GPU structs and the framework intrinsics.\n\n",
    );
    for s in [&TILE, &FRAME, &NODE, &INSTANCE] {
        write_struct(&mut out, s);
    }
    // Each intrinsic is declared with a placeholder body that only makes it check; the lowering
    // replaces every call of a function of this module and never lowers the bodies.
    for (name, params, result) in INTRINSICS {
        if result.is_empty() {
            let _ = writeln!(out, "fn {name}({params}) {{\n}}\n");
        } else {
            let _ = writeln!(
                out,
                "fn {name}({params}) -> {result} {{\n    return {};\n}}\n",
                zero_of(result)
            );
        }
    }
    out
}

/// The text of `rtc:config` for one scene (a normal kernel, no debug output).
pub fn config_module(c: &KernelConfig) -> String {
    config_module_with(c, None)
}

/// The text of `rtc:config` for one scene, with the debug switches of `debug`
/// (`DEBUG`, `DEBUG_COUNTS`, `DEBUG_RAY_ORIGIN`, `DEBUG_RAY_DIRECTION`; all `false` for `None`).
pub fn config_module_with(c: &KernelConfig, debug: Option<super::DebugMode>) -> String {
    use super::DebugMode;
    let mut out = String::from("//! Generated by rtc for one scene: the kernel's constants.\n\n");
    let u = [
        ("MAX_DEPTH", c.max_depth),
        ("MAX_SPAWN", c.max_spawn),
        ("STACK_SIZE", c.stack_size),
        ("TLAS_STACK", c.tlas_stack),
        ("BLAS_STACK", c.blas_stack),
        ("TRAVERSAL_STACK", c.tlas_stack + c.blas_stack),
        ("WORKGROUP_WIDTH", super::RENDER_WORKGROUP[0]),
        ("WORKGROUP_HEIGHT", super::RENDER_WORKGROUP[1]),
    ];
    for (name, v) in u {
        let _ = writeln!(out, "const {name}: u32 = {v}u;");
    }
    let b = [
        ("HAS_SECONDARY_RAYS", c.has_secondary_rays),
        ("HAS_ANY_HIT", c.has_any_hit),
        ("HAS_CUSTOM_GEOMETRY", c.has_custom_geometry),
        ("HAS_MESHES", c.has_meshes),
        ("HAS_MEDIA", c.has_media),
        ("HAS_BACKGROUND", c.has_background),
        ("DEBUG", debug.is_some()),
        ("DEBUG_COUNTS", debug == Some(DebugMode::Counts)),
        ("DEBUG_RAY_ORIGIN", debug == Some(DebugMode::RayOrigin)),
        (
            "DEBUG_RAY_DIRECTION",
            debug == Some(DebugMode::RayDirection),
        ),
    ];
    for (name, v) in b {
        let _ = writeln!(out, "const {name}: bool = {v};");
    }
    out
}
