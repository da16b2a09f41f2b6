//! The two modules the compiler generates for the framework kernel: `rtc:abi` and `rtc:config`.
//!
//! - `rtc:abi` declares, in the language, the GPU structs of [`crate::abi`] (so the kernel reads buffers
//!   with ordinary field access), the ABI's constants (node bits, instance flags, texture formats,
//!   counter indices, record strides) and one accessor per record field (`texture_width(t)`,
//!   `triangle_v1(slot)`, …; the lowering expands each call into its one load), and the framework
//!   intrinsics ([`Intrinsic`]) as functions with placeholder bodies (buffer
//!   loads, dispatch to the scene's programs, the spawn queue, the random-number state, accumulation).
//!   It is the same for every scene.
//! - `rtc:config` holds the scene's kernel constants ([`KernelConfig`]): stack sizes and which features
//!   the scene uses. The kernel decides every `if` on them at compile time.
//!
//! Both are generated from typed data (the ABI table, the link plan): they contain names from static
//! tables and numbers, never text that came from a user's source, so no escaping or mangling is needed.
//!
//! Invariant: the text is deterministic, and `rtc:abi` only changes when `abi.rs` does.

use crate::abi::{
    accessors, Accessor, Addressing, StructDesc, CONSTANTS, FRAME, INSTANCE, NODE, RECORDS, TILE,
};
use crate::link::KernelConfig;
use crate::sema::hir::ProgramKind;
use std::fmt::Write;

/// The import path of the generated ABI module.
pub const ABI_MODULE: &str = "rtc:abi";
/// The import path of the generated configuration module.
pub const CONFIG_MODULE: &str = "rtc:config";

/// The ABI structs `rtc:abi` declares, in order (the node record's `NodeHeader`/`NodeInner` views
/// are the host's; the kernel reads `GpuNode`).
const DECLARED_STRUCTS: [&StructDesc; 4] = [&TILE, &FRAME, &NODE, &INSTANCE];

fn write_struct(out: &mut String, s: &StructDesc) {
    let _ = writeln!(out, "/// {}", s.doc);
    let _ = writeln!(out, "struct {} {{", s.name);
    for f in s.fields {
        let _ = writeln!(out, "    {}: {},", f.name, f.ty.name());
    }
    let _ = writeln!(out, "}}\n");
}

/// A framework intrinsic: a function of `rtc:abi` with a placeholder body that the lowering
/// replaces ([`super::intrinsics`] matches on this enum). The one list of them: the `rtc:abi` text
/// declares [`Intrinsic::ALL`] from [`Intrinsic::signature`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Intrinsic {
    /// `load_frame() -> FrameUniforms`
    LoadFrame,
    /// `load_tile() -> TileParams`
    LoadTile,
    /// `load_node(i) -> GpuNode`
    LoadNode,
    /// `load_instance(i) -> GpuInstance`
    LoadInstance,
    /// `load_triangle_vertex(i) -> vec4f` (element `i` of `triangles`)
    LoadTriangleVertex,
    /// `load_attribute(i) -> vec4u` (element `i` of `attributes`)
    LoadAttribute,
    /// `load_param(i) -> u32` (word `i` of `params`)
    LoadParam,
    /// `load_texel(i) -> u32` (word `i` of `texels`)
    LoadTexel,
    /// `accumulate(pixel, value, nonfinite, fresh)`
    Accumulate,
    /// `rng_load() -> u32`
    RngLoad,
    /// `rng_store(state)`
    RngStore,
    /// `hit_error_load() -> f32`
    HitErrorLoad,
    /// `hit_error_store(error)`
    HitErrorStore,
    /// `hit_extra_load() -> vec4u`: what `finish_hit` stored of the last mesh hit for its vertex
    /// extras (`[vertex_extra record or 0, barycentric b1 bits, b2 bits, instance slot]`)
    HitExtraLoad,
    /// `hit_extra_store(value)`
    HitExtraStore,
    /// `spawn_reset()`
    SpawnReset,
    /// `spawned_count() -> u32`
    SpawnedCount,
    /// `spawned_dir(i) -> vec3f`
    SpawnedDir,
    /// `spawned_weight(i) -> vec3f`
    SpawnedWeight,
    /// `call_<kind>(type_id, offset, …)`: dispatch to the scene's programs of one kind.
    Call(ProgramKind),
    /// `write_bounds(i, lo, hi)`
    WriteBounds,
    /// `stack_load(i) -> u32`
    StackLoad,
    /// `stack_store(i, node)`
    StackStore,
    /// `count_ray()`
    CountRay,
    /// `flush_ray_count()`
    FlushRayCount,
    /// `debug_count(nodes, primitives)`
    DebugCount,
    /// `debug_counts() -> vec2u`
    DebugCounts,
    /// `path_load(j, k) -> u32` (word `k` of the 4-word chunk `j` of `paths`, the wavefront
    /// model's path state)
    PathLoad,
    /// `path_store(j, k, value)`
    PathStore,
    /// `path_load4(j) -> vec4u` (the 4-word chunk `j` of `paths`, one load)
    PathLoad4,
    /// `path_store4(j, value)`
    PathStore4,
    /// `scratch_load(i) -> u32` (a private register of the invocation, `i < SCRATCH_WORDS`)
    ScratchLoad,
    /// `scratch_store(i, value)`
    ScratchStore,
    /// `counter_add(i, value)`: atomic add to `counters[i]`
    CounterAdd,
    /// `ray_count_load() -> u32`: the rays this invocation traced so far (`count_ray`)
    RayCountLoad,
    /// `pending_step_waits() -> bool`: what the wavefront shade stage does with a shading step
    /// that made shadow queries without a known answer: a call of `wf_trace_pending` in the shade
    /// stage that traces them itself (`wf_shade_replay_invocation`), else of
    /// `wf_wait_for_shadow_stage` (only the one lowered reaches the kernel)
    PendingStepWaits,
    /// `sample_done(value)`: how the wavefront shade stage ends a sample: a call of
    /// `wf_sample_accumulate` in a scene whose samples all end in their first shading step (no
    /// secondary rays and no shadow stage: the one that may add the sample to `accum` itself),
    /// else of `wf_sample_done` (only the one lowered reaches the kernel, so only such a shade
    /// stage binds `accum`)
    SampleDone,
}

impl Intrinsic {
    /// Every intrinsic, in the order `rtc:abi` declares them.
    pub const ALL: [Intrinsic; 45] = [
        Intrinsic::LoadFrame,
        Intrinsic::LoadTile,
        Intrinsic::LoadNode,
        Intrinsic::LoadInstance,
        Intrinsic::LoadTriangleVertex,
        Intrinsic::LoadAttribute,
        Intrinsic::LoadParam,
        Intrinsic::LoadTexel,
        Intrinsic::Accumulate,
        Intrinsic::RngLoad,
        Intrinsic::RngStore,
        Intrinsic::HitErrorLoad,
        Intrinsic::HitErrorStore,
        Intrinsic::HitExtraLoad,
        Intrinsic::HitExtraStore,
        Intrinsic::SpawnReset,
        Intrinsic::SpawnedCount,
        Intrinsic::SpawnedDir,
        Intrinsic::SpawnedWeight,
        Intrinsic::Call(ProgramKind::RayGeneration),
        Intrinsic::Call(ProgramKind::Intersection),
        Intrinsic::Call(ProgramKind::Bounds),
        Intrinsic::Call(ProgramKind::AnyHit),
        Intrinsic::Call(ProgramKind::ClosestHit),
        Intrinsic::Call(ProgramKind::SecondaryRays),
        Intrinsic::Call(ProgramKind::Medium),
        Intrinsic::Call(ProgramKind::Light),
        Intrinsic::Call(ProgramKind::Miss),
        Intrinsic::WriteBounds,
        Intrinsic::StackLoad,
        Intrinsic::StackStore,
        Intrinsic::CountRay,
        Intrinsic::FlushRayCount,
        Intrinsic::DebugCount,
        Intrinsic::DebugCounts,
        Intrinsic::PathLoad,
        Intrinsic::PathStore,
        Intrinsic::PathLoad4,
        Intrinsic::PathStore4,
        Intrinsic::ScratchLoad,
        Intrinsic::ScratchStore,
        Intrinsic::CounterAdd,
        Intrinsic::RayCountLoad,
        Intrinsic::PendingStepWaits,
        Intrinsic::SampleDone,
    ];

    /// `(name, parameters, result)` as declared in `rtc:abi` (result `""`: none).
    pub fn signature(self) -> (&'static str, &'static str, &'static str) {
        use ProgramKind as K;
        match self {
            Intrinsic::LoadFrame => ("load_frame", "", "FrameUniforms"),
            Intrinsic::LoadTile => ("load_tile", "", "TileParams"),
            Intrinsic::LoadNode => ("load_node", "i: u32", "GpuNode"),
            Intrinsic::LoadInstance => ("load_instance", "i: u32", "GpuInstance"),
            Intrinsic::LoadTriangleVertex => ("load_triangle_vertex", "i: u32", "vec4f"),
            Intrinsic::LoadAttribute => ("load_attribute", "i: u32", "vec4u"),
            Intrinsic::LoadParam => ("load_param", "i: u32", "u32"),
            Intrinsic::LoadTexel => ("load_texel", "i: u32", "u32"),
            Intrinsic::Accumulate => (
                "accumulate",
                "pixel: u32, value: vec4f, nonfinite: u32, fresh: bool",
                "",
            ),
            Intrinsic::RngLoad => ("rng_load", "", "u32"),
            Intrinsic::RngStore => ("rng_store", "state: u32", ""),
            Intrinsic::HitErrorLoad => ("hit_error_load", "", "f32"),
            Intrinsic::HitErrorStore => ("hit_error_store", "error: f32", ""),
            Intrinsic::HitExtraLoad => ("hit_extra_load", "", "vec4u"),
            Intrinsic::HitExtraStore => ("hit_extra_store", "value: vec4u", ""),
            Intrinsic::SpawnReset => ("spawn_reset", "", ""),
            Intrinsic::SpawnedCount => ("spawned_count", "", "u32"),
            Intrinsic::SpawnedDir => ("spawned_dir", "i: u32", "vec3f"),
            Intrinsic::SpawnedWeight => ("spawned_weight", "i: u32", "vec3f"),
            Intrinsic::Call(K::RayGeneration) => (
                "call_ray_generation",
                "type_id: u32, offset: u32, pixel: vec2u, sample: u32",
                "Ray",
            ),
            Intrinsic::Call(K::Intersection) => (
                "call_intersection",
                "type_id: u32, offset: u32, ray: Ray",
                "Intersection",
            ),
            Intrinsic::Call(K::Bounds) => ("call_bounds", "type_id: u32, offset: u32", "Aabb"),
            Intrinsic::Call(K::AnyHit) => (
                "call_any_hit",
                "type_id: u32, offset: u32, ray: Ray, hit: Hit",
                "bool",
            ),
            Intrinsic::Call(K::ClosestHit) => (
                "call_closest_hit",
                "type_id: u32, offset: u32, ray: Ray, hit: Hit, secondary: vec3f",
                "vec3f",
            ),
            Intrinsic::Call(K::SecondaryRays) => (
                "call_secondary_rays",
                "type_id: u32, offset: u32, ray: Ray, hit: Hit",
                "",
            ),
            Intrinsic::Call(K::Medium) => (
                "call_medium",
                "type_id: u32, offset: u32, ray: Ray, t: f32, radiance: vec3f",
                "vec3f",
            ),
            Intrinsic::Call(K::Light) => (
                "call_light",
                "type_id: u32, offset: u32, position: vec3f, normal: vec3f",
                "LightSample",
            ),
            Intrinsic::Call(K::Miss) => {
                ("call_miss", "type_id: u32, offset: u32, ray: Ray", "vec3f")
            }
            Intrinsic::WriteBounds => ("write_bounds", "i: u32, lo: vec3f, hi: vec3f", ""),
            Intrinsic::StackLoad => ("stack_load", "i: u32", "u32"),
            Intrinsic::StackStore => ("stack_store", "i: u32, node: u32", ""),
            Intrinsic::CountRay => ("count_ray", "", ""),
            Intrinsic::FlushRayCount => ("flush_ray_count", "", ""),
            Intrinsic::DebugCount => ("debug_count", "nodes: u32, primitives: u32", ""),
            Intrinsic::DebugCounts => ("debug_counts", "", "vec2u"),
            Intrinsic::PathLoad => ("path_load", "j: u32, k: u32", "u32"),
            Intrinsic::PathStore => ("path_store", "j: u32, k: u32, value: u32", ""),
            Intrinsic::PathLoad4 => ("path_load4", "j: u32", "vec4u"),
            Intrinsic::PathStore4 => ("path_store4", "j: u32, value: vec4u", ""),
            Intrinsic::ScratchLoad => ("scratch_load", "i: u32", "u32"),
            Intrinsic::ScratchStore => ("scratch_store", "i: u32, value: u32", ""),
            Intrinsic::CounterAdd => ("counter_add", "i: u32, value: u32", ""),
            Intrinsic::RayCountLoad => ("ray_count_load", "", "u32"),
            Intrinsic::PendingStepWaits => ("pending_step_waits", "", "bool"),
            Intrinsic::SampleDone => ("sample_done", "value: vec3f", ""),
        }
    }

    /// Its name in `rtc:abi`.
    pub fn name(self) -> &'static str {
        self.signature().0
    }

    /// The intrinsic called `name`.
    pub fn from_name(name: &str) -> Option<Intrinsic> {
        Intrinsic::ALL.into_iter().find(|i| i.name() == name)
    }
}

/// The load intrinsic that reads one element of an array binding of the ABI.
pub fn load_intrinsic_of(binding: &str) -> Option<Intrinsic> {
    Some(match binding {
        "triangles" => Intrinsic::LoadTriangleVertex,
        "attributes" => Intrinsic::LoadAttribute,
        "params" => Intrinsic::LoadParam,
        "texels" => Intrinsic::LoadTexel,
        _ => return None,
    })
}

/// The text of a record accessor: `<record>_<field>(r)` reads one element (see
/// [`crate::abi::records`]). The lowering expands a call into exactly this body's load.
fn write_accessor(out: &mut String, a: Accessor) {
    let r = a.record;
    let load = load_intrinsic_of(r.binding).map_or("load_param", Intrinsic::name);
    let index = match (r.addressing, a.field.offset) {
        (Addressing::WordOffset, 0) => "r".to_string(),
        (Addressing::WordOffset, o) => format!("r + {o}u"),
        (Addressing::Slot, 0) => format!("r * {}u", r.stride),
        (Addressing::Slot, o) => format!("r * {}u + {o}u", r.stride),
    };
    let _ = writeln!(out, "/// `{}.{}`: {}", r.name, a.field.name, a.field.doc);
    let _ = writeln!(
        out,
        "fn {}(r: u32) -> {} {{\n    return {load}({index});\n}}\n",
        a.name(),
        a.field.ty.name()
    );
}

/// The decoders of quantised BVH boxes ([`crate::abi::NODE_BOUND`]), ordinary functions whose
/// numbers come from the table (written as literals, so the kernel's code is what it was when they
/// were written by hand: a shift by a literal needs no `& 31u`).
fn write_node_decoders(out: &mut String) {
    let max = crate::abi::NODE_BOUND_MAX;
    let bits = crate::abi::NODE_BOUND_BITS;
    let _ = write!(
        out,
        "/// Bounds `q` of a quantised box as a point: `origin + q * scale` on each axis.
fn node_point(origin: vec3f, scale: vec3f, q: vec3u) -> vec3f {{
    return origin + vec3f(q) * scale;
}}

/// The high corner of a BVH's quantisation frame (bounds NODE_BOUND_MAX from its header's `origin`
/// in `min` and step size in `max`): with `min`, a box holding the BVH's root box.
fn node_frame_hi(header: GpuNode) -> vec3f {{
    return node_point(header.min, header.max, vec3u({max}u));
}}

/// The bounds of a quantisation frame's high corner (NODE_BOUND_MAX on each axis; its low
/// corner's are 0): the box of a BVH's root in its own frame.
fn node_frame_bounds() -> vec3f {{
    return vec3f({max}.0);
}}

/// The low corner's bounds of a packed quantised box (`[lo.x | lo.y << 16, lo.z | hi.x << 16,
/// hi.y | hi.z << 16]`).
fn node_box_lo(p: vec3u) -> vec3u {{
    return vec3u(p.x & {max}u, p.x >> {bits}u, p.y & {max}u);
}}

/// The high corner's bounds of a packed quantised box.
fn node_box_hi(p: vec3u) -> vec3u {{
    return vec3u(p.y >> {bits}u, p.z & {max}u, p.z >> {bits}u);
}}

"
    );
}

/// A zero value of a result type of an [`Intrinsic`], as source text (the placeholder bodies).
fn zero_of(ty: &str) -> String {
    let abi_struct = DECLARED_STRUCTS.into_iter().find(|s| s.name == ty);
    if let Some(s) = abi_struct {
        let fields: Vec<String> = s
            .fields
            .iter()
            .map(|f| format!("{}: {}", f.name, zero_of(f.ty.name())))
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
        "//! Generated by rtc from compiler/src/abi.rs: the GPU structs, the ABI's constants and record\n\
         //! accessors, and the framework intrinsics.\n\n",
    );
    for s in DECLARED_STRUCTS {
        write_struct(&mut out, s);
    }
    for c in CONSTANTS {
        let _ = writeln!(out, "/// {}\nconst {}: u32 = {}u;", c.doc, c.name, c.value);
    }
    for r in RECORDS {
        let _ = writeln!(
            out,
            "/// Elements of `{}` per {} record.\nconst {}: u32 = {}u;",
            r.binding,
            r.name,
            r.stride_const(),
            r.stride
        );
    }
    out.push('\n');
    for a in accessors() {
        write_accessor(&mut out, a);
    }
    write_node_decoders(&mut out);
    // Each intrinsic is declared with a placeholder body that only makes it check; the lowering
    // replaces every call of a function of this module and never lowers the bodies.
    for i in Intrinsic::ALL {
        let (name, params, result) = i.signature();
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
        ("ROULETTE_DEPTH", c.roulette_depth),
        ("TRAVERSAL_STACK", c.tlas_stack + c.blas_stack),
        ("WORKGROUP_WIDTH", super::RENDER_WORKGROUP[0]),
        ("WORKGROUP_HEIGHT", super::RENDER_WORKGROUP[1]),
        ("LIGHT_QUERIES", super::intrinsics::LIGHT_QUERIES),
    ];
    for (name, v) in u.into_iter().chain(super::wavefront::config_constants(c)) {
        let _ = writeln!(out, "const {name}: u32 = {v}u;");
    }
    let b = [
        ("HAS_SECONDARY_RAYS", c.has_secondary_rays),
        ("PATH_LOOP", c.path_loop),
        ("REGENERATE_PATHS", c.regenerate_paths),
        ("HAS_ANY_HIT", c.has_any_hit),
        ("HAS_CUSTOM_GEOMETRY", c.has_custom_geometry),
        ("HAS_MESHES", c.has_meshes),
        ("HAS_VERTEX_EXTRAS", c.has_vertex_extras),
        ("HAS_MEDIA", c.has_media),
        ("HAS_ABSORB", c.has_absorb),
        ("HAS_BACKGROUND", c.has_background),
        ("CULL_BACK_FACES", c.cull_back_faces),
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

/// Reading the generated `rtc:abi` text back: its `u32` constants and its record accessors, for the
/// tests that compare them with the ABI table (here) and with the runtime's encoders
/// (`rtc-runtime`'s `gpu_types`).
pub mod parse {
    /// Every `const NAME: u32 = Vu;` of `text`, in order.
    pub fn constants(text: &str) -> Vec<(String, u32)> {
        text.lines()
            .filter_map(|l| {
                let rest = l.strip_prefix("const ")?;
                let (name, value) = rest.split_once(": u32 = ")?;
                let value = value.strip_suffix("u;")?.parse().ok()?;
                Some((name.to_string(), value))
            })
            .collect()
    }

    /// A record accessor as written: `fn NAME(r: u32) -> TYPE { return LOAD(r [* STRIDE] [+ OFFSET]); }`.
    #[derive(Clone, Debug, PartialEq, Eq)]
    pub struct AccessorText {
        /// The function's name.
        pub name: String,
        /// Its result type.
        pub ty: String,
        /// The load intrinsic it calls.
        pub load: String,
        /// The multiplier of `r` (1 when there is none).
        pub stride: u32,
        /// The constant added (0 when there is none).
        pub offset: u32,
    }

    /// Every function of `text` taking `r: u32` whose body is one load of `r`'s element.
    pub fn accessors(text: &str) -> Vec<AccessorText> {
        let lines: Vec<&str> = text.lines().collect();
        let mut out = Vec::new();
        for pair in lines.windows(2) {
            let Some(head) = pair[0].strip_prefix("fn ") else {
                continue;
            };
            let Some((name, ty)) = head.split_once("(r: u32) -> ") else {
                continue;
            };
            let Some(ty) = ty.strip_suffix(" {") else {
                continue;
            };
            let Some(body) = pair[1]
                .trim()
                .strip_prefix("return ")
                .and_then(|b| b.strip_suffix(");"))
            else {
                continue;
            };
            let Some((load, index)) = body.split_once('(') else {
                continue;
            };
            let (product, offset) = match index.split_once(" + ") {
                Some((p, o)) => (p, o.strip_suffix('u').and_then(|o| o.parse().ok())),
                None => (index, Some(0)),
            };
            let stride = match product.split_once(" * ") {
                Some(("r", s)) => s.strip_suffix('u').and_then(|s| s.parse().ok()),
                None if product == "r" => Some(1),
                _ => None,
            };
            if let (Some(stride), Some(offset)) = (stride, offset) {
                out.push(AccessorText {
                    name: name.to_string(),
                    ty: ty.to_string(),
                    load: load.to_string(),
                    stride,
                    offset,
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::abi;

    #[test]
    fn every_abi_constant_is_generated_with_its_value_and_nothing_else() {
        let text = abi_module();
        let got = parse::constants(&text);
        let mut want: Vec<(String, u32)> = abi::CONSTANTS
            .iter()
            .map(|c| (c.name.to_string(), c.value))
            .collect();
        want.extend(RECORDS.iter().map(|r| (r.stride_const(), r.stride)));
        assert_eq!(got, want);
    }

    #[test]
    fn every_record_field_has_an_accessor_reading_its_element() {
        let text = abi_module();
        let got = parse::accessors(&text);
        let want: Vec<parse::AccessorText> = accessors()
            .map(|a| parse::AccessorText {
                name: a.name(),
                ty: a.field.ty.name().to_string(),
                load: load_intrinsic_of(a.record.binding)
                    .expect("a load intrinsic")
                    .name()
                    .to_string(),
                stride: match a.record.addressing {
                    Addressing::WordOffset => 1,
                    Addressing::Slot => a.record.stride,
                },
                offset: a.field.offset,
            })
            .collect();
        assert_eq!(got, want);
        // Each binding's load intrinsic returns the binding's element type.
        for a in &got {
            let i = Intrinsic::from_name(&a.load).expect("an intrinsic");
            assert_eq!(i.signature().2, a.ty, "{}", a.name);
        }
    }

    #[test]
    fn every_function_is_an_intrinsic_an_accessor_or_a_node_decoder() {
        let text = abi_module();
        let decoders = [
            "node_point",
            "node_frame_hi",
            "node_frame_bounds",
            "node_box_lo",
            "node_box_hi",
        ];
        let mut intrinsics = 0;
        for name in text
            .lines()
            .filter_map(|l| l.strip_prefix("fn "))
            .filter_map(|l| l.split_once('(').map(|(n, _)| n))
        {
            if Intrinsic::from_name(name).is_some() {
                intrinsics += 1;
            } else {
                assert!(
                    abi::accessor(name).is_some() || decoders.contains(&name),
                    "`{name}` is in rtc:abi but in no table"
                );
            }
        }
        assert_eq!(intrinsics, Intrinsic::ALL.len());
        for i in Intrinsic::ALL {
            assert_eq!(Intrinsic::from_name(i.name()), Some(i));
        }
    }

    #[test]
    fn the_node_decoders_use_the_table_numbers() {
        let text = abi_module();
        let max = format!("& {}u", abi::NODE_BOUND_MAX);
        let shift = format!(">> {}u", abi::NODE_BOUND_BITS);
        assert_eq!(text.matches(&max).count(), 3);
        assert_eq!(text.matches(&shift).count(), 3);
        assert_eq!(abi::NODE_BOUND_MAX, 0xffff);
        assert_eq!(abi::NODE_BOUND_BITS, 16);
    }

    /// `stdlib/kernel/*.rt` without `//` comments.
    fn kernel_sources() -> Vec<(String, String)> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../stdlib/kernel");
        let mut out = Vec::new();
        for entry in std::fs::read_dir(&dir).expect("stdlib/kernel") {
            let path = entry.expect("an entry").path();
            if path.extension().is_some_and(|e| e == "rt") {
                let text = std::fs::read_to_string(&path).expect("a kernel file");
                let code: Vec<&str> = text
                    .lines()
                    .map(|l| l.split_once("//").map_or(l, |(code, _)| code))
                    .collect();
                out.push((path.display().to_string(), code.join("\n")));
            }
        }
        assert!(out.len() >= 2, "trace.rt and support.rt");
        out
    }

    /// No number the ABI defines is written in the framework kernel: records are read through the
    /// accessors (no raw `load_param`/`load_triangle_vertex`/`load_attribute`, whose index would be
    /// a hand-written offset or stride), no ABI constant is redefined, and the distinctive values
    /// (node bits and masks, the bound mask, shifts by a field position) appear nowhere. Small values
    /// like the flags (1, 2, 4) are too common to search for; they are covered by the first two
    /// rules, since a flag is only ever tested on `GpuInstance.flags` by name. `0xffffffff` is
    /// also the kernel's own `NO_HIT`, so `MESH_GEOMETRY` is covered by the redefinition rule only.
    #[test]
    fn no_abi_number_is_written_in_the_kernel() {
        for (file, code) in kernel_sources() {
            for raw in ["load_param(", "load_triangle_vertex(", "load_attribute("] {
                assert!(
                    !code.contains(raw),
                    "{file} calls `{raw}…)`: read the record through its rtc:abi accessor"
                );
            }
            for c in abi::CONSTANTS {
                assert!(
                    !code.contains(&format!("const {}:", c.name)),
                    "{file} redefines {}",
                    c.name
                );
            }
            for r in RECORDS {
                assert!(!code.contains(&format!("const {}:", r.stride_const())));
            }
            let mut forbidden = Vec::new();
            for v in [
                abi::NODE_LEAF_BIT,
                abi::NODE_FIRST_MASK,
                abi::NODE_BOUND_MAX,
            ] {
                forbidden.push(format!("{v}u"));
                forbidden.push(format!("0x{v:x}u"));
            }
            forbidden.push(format!(">> {}u", abi::NODE_COUNT_SHIFT));
            forbidden.push(format!(">> {}u", abi::NODE_BOUND_BITS));
            forbidden.push(format!("& {}u", abi::NODE_COUNT_MASK));
            for f in &forbidden {
                assert!(
                    !code.contains(f.as_str()),
                    "{file} writes `{f}`, a number of the ABI"
                );
            }
        }
    }
}
