struct TileParams {
    origin: vec2<u32>,
    extent: vec2<u32>,
    image_size: vec2<u32>,
    tile_index: u32,
    frame: u32,
}

struct FrameUniforms {
    samples_per_pass: u32,
    total_samples: u32,
    seed: u32,
    tlas_root: u32,
    instance_count: u32,
    light_count: u32,
    light_table: u32,
    medium_count: u32,
    medium_table: u32,
    camera_type: u32,
    camera_offset: u32,
    background_type: u32,
    background_offset: u32,
    path_slots: u32,
    passes_per_dispatch: u32,
}

struct PassSum {
    sum: vec3<f32>,
    bad: u32,
}

struct Ray {
    origin: vec3<f32>,
    tmin: f32,
    dir: vec3<f32>,
    tmax: f32,
    depth: u32,
    kind: u32,
    medium: u32,
}

struct Pinhole {
    position: vec3<f32>,
    look_at: vec3<f32>,
    up: vec3<f32>,
    fov: f32,
}

struct Candidate {
    t: f32,
    slot: u32,
    primitive: u32,
    uv: vec2<f32>,
    normal: vec3<f32>,
}

struct GpuInstance {
    world_to_object_0_: vec4<f32>,
    world_to_object_1_: vec4<f32>,
    world_to_object_2_: vec4<f32>,
    object_to_world_0_: vec4<f32>,
    object_to_world_1_: vec4<f32>,
    object_to_world_2_: vec4<f32>,
    geometry_type: u32,
    geometry_offset: u32,
    material_type: u32,
    material_offset: u32,
    blas_root: u32,
    triangle_offset: u32,
    flags: u32,
    object: u32,
}

struct TriangleRay {
    origin: vec3<f32>,
    kx: u32,
    ky: u32,
    kz: u32,
    shear: vec3<f32>,
    valid: bool,
}

struct GpuNode {
    min: vec3<f32>,
    a: u32,
    max: vec3<f32>,
    b: u32,
}

struct BoxRay {
    step: vec3<f32>,
    start_lo: vec3<f32>,
    start_hi: vec3<f32>,
    tmin: f32,
    unit: f32,
}

struct Sphere {
    center: vec3<f32>,
    radius: f32,
}

struct Intersection {
    t: f32,
    normal: vec3<f32>,
    uv: vec2<f32>,
}

struct Hit {
    position: vec3<f32>,
    t: f32,
    normal: vec3<f32>,
    geometric_normal: vec3<f32>,
    uv: vec2<f32>,
    front_face: bool,
    instance: u32,
    primitive: u32,
}

struct Triangle {
    v0_: vec3<f32>,
    v1_: vec3<f32>,
    v2_: vec3<f32>,
}

struct ConstantBackground {
    color: vec3<f32>,
}

struct PathDiffuse {
    albedo: vec3<f32>,
    roulette_depth: u32,
}

struct LightSample {
    dir: vec3<f32>,
    dist: f32,
    radiance: vec3<f32>,
    pdf: f32,
}

struct QuadLight {
    corner: vec3<f32>,
    edge_u: vec3<f32>,
    edge_v: vec3<f32>,
    color: vec3<f32>,
    intensity: f32,
    lamp: u32,
}

struct SphereLight {
    position: vec3<f32>,
    radius: f32,
    color: vec3<f32>,
    intensity: f32,
    lamp: u32,
}

struct QuadLamp {
    color: vec3<f32>,
    intensity: f32,
    area: f32,
}

struct SphereLamp {
    color: vec3<f32>,
    intensity: f32,
    radius: f32,
}

struct PathPbr {
    base_color: vec3<f32>,
    metallic: f32,
    roughness: f32,
    emissive: vec3<f32>,
    roulette_depth: u32,
}

struct PathState {
    ray: Ray,
    beta: vec3<f32>,
    radiance: vec3<f32>,
    live: bool,
}

struct PbrSample {
    dir: vec3<f32>,
    weight: vec3<f32>,
    pdf: f32,
}

const WORKGROUP_WIDTH: u32 = 8u;
const WORKGROUP_HEIGHT: u32 = 8u;
const NO_HIT: u32 = 4294967295u;
const SCATTER: u32 = 1000003u;
const SCRATCH_RNG_INDEX: u32 = 12u;
const SCRATCH_RNG_SEED: u32 = 13u;
const HALF_WORD_BITS: u32 = 16u;
const RAY_CAMERA: u32 = 0u;
const HAS_MEDIA: bool = false;
const MEDIUM_ENTRY_STRIDE: u32 = 1u;
const MESH_GEOMETRY: u32 = 4294967295u;
const NODE_LEAF_BIT: u32 = 2147483648u;
const NODE_COUNT_SHIFT: u32 = 27u;
const NODE_COUNT_MASK: u32 = 15u;
const NODE_FIRST_MASK: u32 = 134217727u;
const HAS_ANY_HIT: bool = false;
const BLAS_STACK: u32 = 64u;
const TLAS_STACK: u32 = 8u;
const TAU: f32 = 6.2831855f;
const INV_PI: f32 = 0.31830987f;
const POINT_ERROR: f32 = 0.0000019073486f;
const GAMMA_1_: f32 = 0.00000005960465f;
const GAMMA_6_: f32 = 0.0000003576281f;
const GAMMA_4_: f32 = 0.00000023841864f;
const HAS_SECONDARY_RAYS: bool = true;
const HAS_BACKGROUND: bool = true;
const SCRATCH_SHADOW_MODE: u32 = 14u;
const SHADOW_ABOVE: u32 = 2u;
const LIGHT_ENTRY_STRIDE: u32 = 2u;
const SCRATCH_RESOLVED: u32 = 3u;
const SCRATCH_LIGHT_BITS: u32 = 11u;
const SCRATCH_QUERY: u32 = 2u;
const SCRATCH_PENDING: u32 = 4u;
const SHADOW_UNOCCLUDED: u32 = 1u;
const LIGHT_QUERIES: u32 = 32u;
const COUNTER_SHADOW_OVERFLOW: u32 = 3u;
const SCRATCH_LIGHT_QUERY: u32 = 15u;
const LIGHT_ERROR: f32 = 0.00000047683716f;
const RAY_SHADOW: u32 = 2u;
const SHADOW_TRACED: u32 = 0u;
const MIS_BOUNCE_LENGTH: f32 = 3f;
const PBR_MIN_ALPHA: f32 = 0.001f;
const FLAG_MEDIUM: u32 = 4u;
const FLAG_SECONDARY_RAYS: u32 = 2u;
const MAX_DEPTH: u32 = 5u;
const ROULETTE_DEPTH: u32 = 2u;
const ROULETTE_THROUGHPUT: f32 = 0.5f;
const RAY_SECONDARY: u32 = 1u;

@group(0) @binding(1) 
var<uniform> tile: TileParams;
@group(0) @binding(0) 
var<uniform> frame: FrameUniforms;
var<private> scratch: array<u32, 25>;
var<private> rng_state: u32;
@group(0) @binding(6) 
var<storage> params: array<u32>;
var<private> F32_INF: u32 = 2139095040u;
@group(0) @binding(3) 
var<storage> instances: array<GpuInstance>;
@group(0) @binding(2) 
var<storage> nodes: array<GpuNode>;
@group(0) @binding(4) 
var<storage> triangles: array<vec4<f32>>;
var<private> traversal_stack: array<u32, 72>;
var<private> hit_error: f32;
@group(0) @binding(5) 
var<storage> attributes: array<vec4<u32>>;
var<private> ray_count: u32;
@group(0) @binding(9) 
var<storage, read_write> counters: array<atomic<u32>>;
var<private> spawn_dirs: array<vec3<f32>, 1>;
var<private> spawn_weights: array<vec3<f32>, 1>;
var<private> spawn_count: u32;
@group(0) @binding(8) 
var<storage, read_write> accum: array<vec4<f32>>;

fn div_vec2u(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let by_zero = (b == vec2(0u));
    let divisor = select(b, vec2(1u), by_zero);
    return (a / divisor);
}

fn rem_u32_(a_1: u32, b_1: u32) -> u32 {
    let by_zero_1 = (b_1 == 0u);
    let divisor_1 = select(b_1, 1u, by_zero_1);
    return select((a_1 % divisor_1), 0u, by_zero_1);
}

fn div_u32_(a_2: u32, b_2: u32) -> u32 {
    let by_zero_2 = (b_2 == 0u);
    let divisor_2 = select(b_2, 1u, by_zero_2);
    return (a_2 / divisor_2);
}

fn rem_vec2u(a_3: vec2<u32>, b_3: vec2<u32>) -> vec2<u32> {
    let _e3 = vec2(0u);
    let by_zero_3 = (b_3 == _e3);
    let divisor_3 = select(b_3, vec2(1u), by_zero_3);
    return select((a_3 % divisor_3), _e3, by_zero_3);
}

fn scattered_local(id: vec2<u32>) -> vec2<u32> {
    let tile_1 = tile;
    let size = vec2<u32>(WORKGROUP_WIDTH, WORKGROUP_HEIGHT);
    let _e11 = div_vec2u(((tile_1.extent + size) - vec2(1u)), size);
    let count = (_e11.x * _e11.y);
    if (count == 0u) {
        return vec2(NO_HIT);
    }
    let _e19 = div_vec2u(id, size);
    let order = ((_e19.y * _e11.x) + _e19.x);
    let _e26 = rem_u32_(SCATTER, count);
    let _e28 = rem_u32_((order * _e26), count);
    let _e30 = rem_u32_(_e28, _e11.x);
    let _e32 = div_u32_(_e28, _e11.x);
    let _e35 = rem_vec2u(id, size);
    return ((vec2<u32>(_e30, _e32) * size) + _e35);
}

fn pcg_hash(x: u32) -> u32 {
    let state_1 = ((x * 747796405u) + 2891336453u);
    let word = (((state_1 >> (((state_1 >> 28u) + 4u) & 31u)) ^ state_1) * 277803737u);
    return ((word >> 22u) ^ word);
}

fn rng_resume(pixel: vec2<u32>, sample: u32, seed: u32, state: u32) {
    scratch[min(SCRATCH_RNG_INDEX, 24u)] = sample;
    let _e12 = pcg_hash(seed);
    let _e14 = pcg_hash((pixel.y ^ _e12));
    let _e16 = pcg_hash((pixel.x ^ _e14));
    scratch[min(SCRATCH_RNG_SEED, 24u)] = _e16;
    rng_state = state;
    return;
}

fn rng_seed(pixel_1: vec2<u32>, sample_1: u32, seed_1: u32) {
    rng_resume(pixel_1, sample_1, seed_1, 0u);
    return;
}

fn load_Pinhole(offset: u32) -> Pinhole {
    let _e5 = params[(offset + 0u)];
    let _e11 = params[(offset + 1u)];
    let _e17 = params[(offset + 2u)];
    let _e24 = params[(offset + 4u)];
    let _e30 = params[(offset + 5u)];
    let _e36 = params[(offset + 6u)];
    let _e43 = params[(offset + 8u)];
    let _e49 = params[(offset + 9u)];
    let _e55 = params[(offset + 10u)];
    let _e62 = params[(offset + 11u)];
    return Pinhole(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), vec3<f32>(bitcast<f32>(_e24), bitcast<f32>(_e30), bitcast<f32>(_e36)), vec3<f32>(bitcast<f32>(_e43), bitcast<f32>(_e49), bitcast<f32>(_e55)), bitcast<f32>(_e62));
}

fn image_size_query() -> vec2<u32> {
    let _e1 = tile;
    return _e1.image_size;
}

fn samples_per_pixel_query() -> u32 {
    let _e1 = frame;
    return _e1.total_samples;
}

fn laine_karras(x_1: u32, seed_2: u32) -> u32 {
    var v: u32;

    v = (x_1 + seed_2);
    let _e4 = v;
    let _e5 = v;
    v = (_e4 ^ (_e5 * 1817228412u));
    let _e9 = v;
    let _e10 = v;
    v = (_e9 ^ (_e10 * 3090095698u));
    let _e14 = v;
    let _e15 = v;
    v = (_e14 ^ (_e15 * 3350193720u));
    let _e19 = v;
    let _e20 = v;
    v = (_e19 ^ (_e20 * 2367878886u));
    let _e24 = v;
    return _e24;
}

fn sobol_second_reversed(i: u32) -> u32 {
    var f: u32;

    f = i;
    let _e2 = f;
    let _e3 = f;
    f = (_e2 ^ ((_e3 >> 1u) & 1431655765u));
    let _e9 = f;
    let _e10 = f;
    f = (_e9 ^ ((_e10 >> 2u) & 858993459u));
    let _e16 = f;
    let _e17 = f;
    f = (_e16 ^ ((_e17 >> 4u) & 252645135u));
    let _e23 = f;
    let _e24 = f;
    f = (_e23 ^ ((_e24 >> 8u) & 16711935u));
    let _e30 = f;
    let _e31 = f;
    f = (_e30 ^ (_e31 >> (HALF_WORD_BITS & 31u)));
    let _e37 = f;
    return _e37;
}

fn rand_next() -> f32 {
    var x_2: u32;

    let d = rng_state;
    rng_state = (d + 1u);
    let _e10 = scratch[min(SCRATCH_RNG_SEED, 24u)];
    let _e16 = pcg_hash((_e10 ^ ((d >> 1u) * 2654435769u)));
    let _e22 = scratch[min(SCRATCH_RNG_INDEX, 24u)];
    let _e24 = laine_karras(reverseBits(_e22), _e16);
    let i_8 = reverseBits(_e24);
    x_2 = i_8;
    if ((d & 1u) != 0u) {
        let _e31 = sobol_second_reversed(i_8);
        x_2 = _e31;
    }
    let scramble = (_e16 ^ (((2654435769u * (1u + (d & 1u))) + (_e16 << 6u)) + (_e16 >> 2u)));
    let _e45 = x_2;
    let _e46 = laine_karras(_e45, scramble);
    return (f32((reverseBits(_e46) >> 8u)) * (1f / 16777216f));
}

fn rand2_next() -> vec2<f32> {
    let _e0 = rand_next();
    let _e1 = rand_next();
    return vec2<f32>(_e0, _e1);
}

fn normalize_vec3f(v_1: vec3<f32>) -> vec3<f32> {
    return select(vec3(0f), normalize(v_1), (dot(v_1, v_1) >= 0.000000000000000000000000000000000000011754944f));
}

fn pinhole_ray(cam: Pinhole, pixel_2: vec2<u32>, sample_2: u32) -> Ray {
    var jitter: vec2<f32>;

    let _e2 = image_size_query();
    let size_1 = vec2<f32>(_e2);
    jitter = vec2(0.5f);
    let _e7 = samples_per_pixel_query();
    if (_e7 > 1u) {
        let _e10 = rand2_next();
        jitter = _e10;
    }
    let _e12 = jitter;
    let ndc = ((((vec2<f32>(pixel_2) + _e12) / size_1) * vec2(2f)) - vec2(1f));
    let _e24 = normalize_vec3f((cam.look_at - cam.position));
    let _e27 = normalize_vec3f(cross(_e24, cam.up));
    let up = cross(_e27, _e24);
    let h = tan((radians(cam.fov) * 0.5f));
    let aspect = (size_1.x / size_1.y);
    let _e48 = normalize_vec3f(((_e24 + (_e27 * vec3(((ndc.x * h) * aspect)))) - (up * vec3((ndc.y * h)))));
    let _e52 = F32_INF;
    return Ray(cam.position, 0f, _e48, bitcast<f32>(_e52), 0u, 0u, 0u);
}

fn dispatch_ray_generation(type_id: u32, offset_1: u32, pixel_3: vec2<u32>, sample_3: u32) -> Ray {
    let _e3 = load_Pinhole(offset_1);
    let _e4 = pinhole_ray(_e3, pixel_3, sample_3);
    return _e4;
}

fn no_candidate(tmax: f32) -> Candidate {
    return Candidate(tmax, NO_HIT, 0u, vec2(0f), vec3(0f));
}

fn to_object(inst: GpuInstance, ray: Ray) -> Ray {
    var r: Ray;

    r = ray;
    let o = vec4<f32>(ray.origin, 1f);
    let d_1 = vec4<f32>(ray.dir, 0f);
    r.origin = vec3<f32>(dot(inst.world_to_object_0_, o), dot(inst.world_to_object_1_, o), dot(inst.world_to_object_2_, o));
    r.dir = vec3<f32>(dot(inst.world_to_object_0_, d_1), dot(inst.world_to_object_1_, d_1), dot(inst.world_to_object_2_, d_1));
    let _e25 = r;
    return _e25;
}

fn prepare_triangle_ray(ray_1: Ray) -> TriangleRay {
    let d_2 = select(ray_1.dir, vec3(0f), (abs(ray_1.dir) < vec3(0.000000000000000000000000000000000000011754944f)));
    let ad = abs(d_2);
    let y_gt = (ad.y > ad.x);
    let kz = select(select(0u, 1u, y_gt), 2u, (ad.z > select(ad.x, ad.y, y_gt)));
    let kx0_ = select((kz + 1u), 0u, (kz == 2u));
    let ky0_ = select((kz + 2u), (kz - 1u), (kz >= 1u));
    let dz = d_2[min(kz, 2u)];
    let flip = (dz < 0f);
    let kx = select(kx0_, ky0_, flip);
    let ky = select(ky0_, kx0_, flip);
    let inf_bits = vec3(2139095040u);
    let finite = (all(((bitcast<vec3<u32>>(ray_1.origin) & vec3(2147483647u)) < inf_bits)) && all(((bitcast<vec3<u32>>(d_2) & vec3(2147483647u)) < inf_bits)));
    return TriangleRay(ray_1.origin, kx, ky, kz, vec3<f32>((d_2[min(kx, 2u)] / dz), (d_2[min(ky, 2u)] / dz), (1f / dz)), (finite && !((dz == 0f))));
}

fn node_point(origin: vec3<f32>, scale: vec3<f32>, q: vec3<u32>) -> vec3<f32> {
    return (origin + (vec3<f32>(q) * scale));
}

fn node_frame_hi(header: GpuNode) -> vec3<f32> {
    let _e5 = node_point(header.min, header.max, vec3(65535u));
    return _e5;
}

fn box_ray(header_1: GpuNode, ray_2: Ray) -> BoxRay {
    let origin_2 = header_1.min;
    let _e3 = node_frame_hi(header_1);
    let extent = (_e3 - origin_2);
    let m_6 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    let e = min(max(((bitcast<u32>(m_6) >> 23u) & 255u), 1u), 253u);
    let d_3 = (ray_2.dir * vec3(bitcast<f32>(((254u - e) << 23u))));
    let unit = bitcast<f32>((e << 23u));
    let floor_ = vec3(0.0000000000009094947f);
    let s_6 = select(vec3(1f), vec3(-1f), (d_3 < vec3(0f)));
    let inv = (vec3(1f) / select(d_3, (s_6 * floor_), (abs(d_3) < floor_)));
    let rel = (origin_2 - ray_2.origin);
    let start = (rel * inv);
    let pad = (((vec3(0.0000009536743f) * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_6);
    return BoxRay((header_1.max * inv), (start - pad), (start + pad), (ray_2.tmin * unit), unit);
}

fn hit_triangle(r_1: TriangleRay, slot: u32, tmin: f32, tmax_1: f32, occlusion: bool) -> vec3<f32> {
    let _e9 = triangles[(slot * 3u)];
    let a_4 = (_e9.xyz - r_1.origin);
    let _e19 = triangles[((slot * 3u) + 1u)];
    let b_7 = (_e19.xyz - r_1.origin);
    let _e29 = triangles[((slot * 3u) + 2u)];
    let c_8 = (_e29.xyz - r_1.origin);
    let ax = (a_4[min(r_1.kx, 2u)] - (r_1.shear.x * a_4[min(r_1.kz, 2u)]));
    let ay = (a_4[min(r_1.ky, 2u)] - (r_1.shear.y * a_4[min(r_1.kz, 2u)]));
    let bx = (b_7[min(r_1.kx, 2u)] - (r_1.shear.x * b_7[min(r_1.kz, 2u)]));
    let by = (b_7[min(r_1.ky, 2u)] - (r_1.shear.y * b_7[min(r_1.kz, 2u)]));
    let cx = (c_8[min(r_1.kx, 2u)] - (r_1.shear.x * c_8[min(r_1.kz, 2u)]));
    let cy = (c_8[min(r_1.ky, 2u)] - (r_1.shear.y * c_8[min(r_1.kz, 2u)]));
    let u_3 = ((cx * by) - (cy * bx));
    let v_6 = ((ax * cy) - (ay * cx));
    let w_1 = ((bx * ay) - (by * ax));
    let outside = ((((u_3 < 0f) || (v_6 < 0f)) || (w_1 < 0f)) && (((u_3 > 0f) || (v_6 > 0f)) || (w_1 > 0f)));
    let det = ((u_3 + v_6) + w_1);
    let scaled = (((u_3 * (r_1.shear.z * a_4[min(r_1.kz, 2u)])) + (v_6 * (r_1.shear.z * b_7[min(r_1.kz, 2u)]))) + (w_1 * (r_1.shear.z * c_8[min(r_1.kz, 2u)])));
    if occlusion {
        let st = select(scaled, -(scaled), (det < 0f));
        let ad_1 = abs(det);
        let hit_12 = ((((r_1.valid && !(outside)) && !((det == 0f))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        let _e178 = F32_INF;
        return select(vec3<f32>(bitcast<f32>(_e178), 0f, 0f), vec3<f32>(tmin, 0f, 0f), hit_12);
    }
    let rcp = (1f / det);
    let t_4 = (scaled * rcp);
    let hit_13 = ((((r_1.valid && !(outside)) && !((det == 0f))) && (t_4 >= tmin)) && (t_4 <= tmax_1));
    let _e202 = F32_INF;
    return select(vec3<f32>(bitcast<f32>(_e202), 0f, 0f), vec3<f32>(t_4, (v_6 * rcp), (w_1 * rcp)), hit_13);
}

fn accept(inst_1: GpuInstance, ray_3: Ray, c: Candidate) -> bool {
    return true;
}

fn node_box_lo(p: vec3<u32>) -> vec3<u32> {
    return vec3<u32>((p.x & 65535u), (p.x >> 16u), (p.y & 65535u));
}

fn node_box_hi(p_1: vec3<u32>) -> vec3<u32> {
    return vec3<u32>((p_1.y >> 16u), (p_1.z & 65535u), (p_1.z >> 16u));
}

fn slab_in_frame(lo: vec3<f32>, hi: vec3<f32>, b_4: BoxRay, tmax_2: f32) -> f32 {
    let t0_ = fma(lo, b_4.step, b_4.start_lo);
    let t1_1 = fma(hi, b_4.step, b_4.start_hi);
    let flip_1 = (bitcast<vec3<i32>>(b_4.step) < vec3(0i));
    let near_2 = select(t0_, t1_1, flip_1);
    let far_2 = select(t1_1, t0_, flip_1);
    let e_1 = select(near_2.xy, near_2.yz, (near_2.xy < near_2.yz));
    let enter = select(e_1.x, e_1.y, (e_1.x < e_1.y));
    let x_5 = select(far_2.xy, far_2.yz, (far_2.yz < far_2.xy));
    let exit = select(x_5.x, x_5.y, (x_5.y < x_5.x));
    let enter_t = select(enter, b_4.tmin, (enter < b_4.tmin));
    let exit_t = select(exit, tmax_2, (tmax_2 < exit));
    if (enter_t <= exit_t) {
        return enter_t;
    }
    let _e49 = F32_INF;
    return bitcast<f32>(_e49);
}

fn children_entry(n: GpuNode, b_5: BoxRay, tmax_3: f32) -> vec2<f32> {
    let lq = bitcast<vec3<u32>>(n.min);
    let rq = bitcast<vec3<u32>>(n.max);
    let t_5 = (tmax_3 * b_5.unit);
    let _e9 = node_box_lo(lq);
    let _e11 = node_box_hi(lq);
    let _e13 = slab_in_frame(vec3<f32>(_e9), vec3<f32>(_e11), b_5, t_5);
    let _e14 = node_box_lo(rq);
    let _e16 = node_box_hi(rq);
    let _e18 = slab_in_frame(vec3<f32>(_e14), vec3<f32>(_e16), b_5, t_5);
    return vec2<f32>(_e13, _e18);
}

fn pop(base: u32, sp: u32) -> vec2<u32> {
    if (sp == 0u) {
        return vec2<u32>(NO_HIT, 0u);
    }
    let _e14 = traversal_stack[min(((base + sp) - 1u), 71u)];
    return vec2<u32>(_e14, (sp - 1u));
}

fn intersect_mesh(inst_2: GpuInstance, slot_1: u32, world_ray: Ray, ray_4: Ray, best_in: Candidate, shadow: bool) -> Candidate {
    var best: Candidate;
    var sp_1: u32;
    var child: u32;
    var k: u32;
    var near: u32;
    var far: u32;

    best = best_in;
    let _e7 = prepare_triangle_ray(ray_4);
    let base_5 = inst_2.blas_root;
    let header_2 = nodes[base_5];
    let _e12 = box_ray(header_2, ray_4);
    sp_1 = 0u;
    child = header_2.a;
    loop {
        let _e17 = child;
        if ((_e17 & NODE_LEAF_BIT) != 0u) {
            let _e22 = child;
            let count_1 = ((_e22 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK);
            let _e29 = child;
            let first = (_e29 & NODE_FIRST_MASK);
            k = 0u;
            loop {
                let _e34 = k;
                if (_e34 >= count_1) {
                    break;
                }
                let _e38 = k;
                let prim = ((inst_2.triangle_offset + first) + _e38);
                let _e42 = best.t;
                let _e46 = hit_triangle(_e7, prim, ray_4.tmin, _e42, (shadow && !(HAS_ANY_HIT)));
                let _e49 = F32_INF;
                if (_e46.x < bitcast<f32>(_e49)) {
                    let _e58 = triangles[((prim * 3u) + 1u)];
                    let tag = bitcast<u32>(_e58.w);
                    let owner = select(slot_1, ((inst_2.object + tag) - 1u), (tag != 0u));
                    let c_9 = Candidate(_e46.x, owner, prim, _e46.yz, vec3(0f));
                    let _e73 = accept(inst_2, world_ray, c_9);
                    if _e73 {
                        best = c_9;
                        if shadow {
                            let _e74 = best;
                            return _e74;
                        }
                    }
                }
                continuing {
                    let _e75 = k;
                    k = (_e75 + 1u);
                }
            }
        } else {
            let _e78 = child;
            let n_11 = nodes[(base_5 + _e78)];
            let _e84 = best.t;
            let _e85 = children_entry(n_11, _e12, _e84);
            let tl = _e85.x;
            let tr = _e85.y;
            let _e89 = F32_INF;
            let _e93 = F32_INF;
            if ((tl < bitcast<f32>(_e89)) && (tr < bitcast<f32>(_e93))) {
                near = n_11.a;
                far = n_11.b;
                if ((tr < tl) != shadow) {
                    near = n_11.b;
                    far = n_11.a;
                }
                let _e105 = sp_1;
                if (_e105 < BLAS_STACK) {
                    let _e109 = sp_1;
                    let _e111 = far;
                    traversal_stack[min((TLAS_STACK + _e109), 71u)] = _e111;
                    let _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                let _e119 = near;
                child = _e119;
                continue;
            }
            let _e121 = F32_INF;
            if (tl < bitcast<f32>(_e121)) {
                child = n_11.a;
                continue;
            }
            let _e126 = F32_INF;
            if (tr < bitcast<f32>(_e126)) {
                child = n_11.b;
                continue;
            }
        }
        let _e131 = sp_1;
        let _e132 = pop(TLAS_STACK, _e131);
        if (_e132.x == NO_HIT) {
            break;
        }
        child = _e132.x;
        sp_1 = _e132.y;
    }
    let _e138 = best;
    return _e138;
}

fn load_Sphere(offset_2: u32) -> Sphere {
    let _e5 = params[(offset_2 + 0u)];
    let _e11 = params[(offset_2 + 1u)];
    let _e17 = params[(offset_2 + 2u)];
    let _e24 = params[(offset_2 + 3u)];
    return Sphere(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), bitcast<f32>(_e24));
}

fn sphere_intersect(s: Sphere, ray_5: Ray) -> Intersection {
    var t: f32;

    let f_1 = (ray_5.origin - s.center);
    let a_5 = dot(ray_5.dir, ray_5.dir);
    let b_8 = -(dot(f_1, ray_5.dir));
    let l_6 = (f_1 + (ray_5.dir * vec3((b_8 / a_5))));
    let r2_ = (s.radius * s.radius);
    let disc = (a_5 * (r2_ - dot(l_6, l_6)));
    if (!((disc >= 0f)) || !((a_5 > 0f))) {
        let _e30 = F32_INF;
        return Intersection(bitcast<f32>(_e30), vec3<f32>(0f, 0f, 1f), vec2<f32>());
    }
    let q_1 = (b_8 + (select(-1f, 1f, (b_8 >= 0f)) * sqrt(disc)));
    let t0_1 = ((dot(f_1, f_1) - r2_) / q_1);
    let t1_2 = (q_1 / a_5);
    t = min(t0_1, t1_2);
    let _e52 = t;
    if !((_e52 >= ray_5.tmin)) {
        t = max(t0_1, t1_2);
    }
    let _e57 = t;
    let _e60 = t;
    if !(((_e57 >= ray_5.tmin) && (_e60 <= ray_5.tmax))) {
        let _e66 = F32_INF;
        return Intersection(bitcast<f32>(_e66), vec3<f32>(0f, 0f, 1f), vec2<f32>());
    }
    let _e76 = t;
    let _e82 = normalize_vec3f(((ray_5.origin + (ray_5.dir * vec3(_e76))) - s.center));
    let u_4 = select((0.5f + (atan2(_e82.z, -(_e82.x)) / TAU)), 0.5f, ((_e82.x == 0f) && (_e82.z == 0f)));
    let uv = vec2<f32>(u_4, (acos(min(max(_e82.y, -1f), 1f)) * INV_PI));
    let _e109 = t;
    return Intersection(_e109, _e82, uv);
}

fn dispatch_intersection(type_id_1: u32, offset_3: u32, ray_6: Ray) -> Intersection {
    let _e2 = load_Sphere(offset_3);
    let _e3 = sphere_intersect(_e2, ray_6);
    return _e3;
}

fn intersect_object(slot_2: u32, ray_7: Ray, best_1: Candidate, shadow_1: bool) -> Candidate {
    var r_2: Ray;

    let inst_6 = instances[slot_2];
    let _e7 = to_object(inst_6, ray_7);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        let _e14 = r_2;
        let _e15 = intersect_mesh(inst_6, slot_2, ray_7, _e14, best_1, shadow_1);
        return _e15;
    }
    let _e18 = r_2;
    let _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18);
    let _e22 = r_2.tmin;
    let _e26 = r_2.tmax;
    let _e31 = F32_INF;
    if (((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < bitcast<f32>(_e31))) {
        let c_10 = Candidate(_e19.t, slot_2, 0u, _e19.uv, _e19.normal);
        let _e40 = accept(inst_6, ray_7, c_10);
        if _e40 {
            return c_10;
        }
    }
    return best_1;
}

fn point_error(origin_1: vec3<f32>, along: vec3<f32>) -> f32 {
    let a_6 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_6.x, a_6.y), a_6.z));
}

fn load_triangle(slot_3: u32) -> Triangle {
    let v0_1 = triangles[(slot_3 * 3u)];
    let v1_ = triangles[((slot_3 * 3u) + 1u)];
    let v2_ = triangles[((slot_3 * 3u) + 2u)];
    return Triangle(v0_1.xyz, v1_.xyz, v2_.xyz);
}

fn point_to_world(inst_3: GpuInstance, p_2: vec3<f32>) -> vec3<f32> {
    let q_2 = vec4<f32>(p_2, 1f);
    return vec3<f32>(dot(inst_3.object_to_world_0_, q_2), dot(inst_3.object_to_world_1_, q_2), dot(inst_3.object_to_world_2_, q_2));
}

fn mesh_error(inst_4: GpuInstance, v0_: vec3<f32>, db1_: vec3<f32>, db2_: vec3<f32>, p_3: vec3<f32>) -> f32 {
    let obj = ((vec3(GAMMA_1_) * abs(v0_)) + (vec3(GAMMA_6_) * (abs(db1_) + abs(db2_))));
    let q_3 = vec4<f32>(abs(p_3), 1f);
    let r0_ = abs(inst_4.object_to_world_0_);
    let r1_ = abs(inst_4.object_to_world_1_);
    let r2_1 = abs(inst_4.object_to_world_2_);
    let rounding = (vec3(GAMMA_4_) * vec3<f32>(dot(r0_, q_3), dot(r1_, q_3), dot(r2_1, q_3)));
    let carried = (vec3((1f + GAMMA_4_)) * vec3<f32>(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_1.xyz, obj)));
    let e_2 = (rounding + carried);
    return max(max(e_2.x, e_2.y), e_2.z);
}

fn decode_octahedral(bits: u32) -> vec3<f32> {
    var n_1: vec3<f32>;

    let e_3 = unpack2x16snorm(bits);
    n_1 = vec3<f32>(e_3.x, e_3.y, ((1f - abs(e_3.x)) - abs(e_3.y)));
    let _e14 = n_1.z;
    if (_e14 < 0f) {
        let _e21 = n_1;
        let s_7 = select(vec2(-1f), vec2(1f), (_e21.xy >= vec2(0f)));
        let _e29 = n_1;
        let xy = ((vec2(1f) - abs(_e29.yx)) * s_7);
        let _e37 = n_1.z;
        n_1 = vec3<f32>(xy.x, xy.y, _e37);
    }
    let _e39 = n_1;
    let _e40 = normalize_vec3f(_e39);
    return _e40;
}

fn normal_to_world(inst_5: GpuInstance, n_2: vec3<f32>) -> vec3<f32> {
    let w_2 = (((inst_5.world_to_object_0_.xyz * vec3(n_2.x)) + (inst_5.world_to_object_1_.xyz * vec3(n_2.y))) + (inst_5.world_to_object_2_.xyz * vec3(n_2.z)));
    let _e19 = normalize_vec3f(w_2);
    return _e19;
}

fn finish_hit(ray_8: Ray, c_1: Candidate) -> Hit {
    var hit: Hit;
    var n_geo: vec3<f32>;
    var n_shade: vec3<f32>;

    let inst_7 = instances[c_1.slot];
    let _e11 = point_error(ray_8.origin, (ray_8.dir * vec3(c_1.t)));
    hit_error = _e11;
    hit = Hit((ray_8.origin + (ray_8.dir * vec3(c_1.t))), c_1.t, vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 1f, 0f), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if (inst_7.geometry_type == MESH_GEOMETRY) {
        let _e42 = load_triangle(c_1.primitive);
        let b_9 = c_1.uv;
        let w_3 = ((1f - b_9.x) - b_9.y);
        let e1_ = (_e42.v1_ - _e42.v0_);
        let e2_ = (_e42.v2_ - _e42.v0_);
        let p_8 = (_e42.v0_ + ((e1_ * vec3(b_9.x)) + (e2_ * vec3(b_9.y))));
        let _e65 = point_to_world(inst_7, p_8);
        hit.position = _e65;
        let _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * vec3(b_9.x)), (e2_ * vec3(b_9.y)), p_8);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        let a0_ = attributes[(c_1.primitive * 2u)];
        let a1_ = attributes[((c_1.primitive * 2u) + 1u)];
        let _e91 = decode_octahedral(a0_.x);
        let _e95 = decode_octahedral(a0_.y);
        let _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * vec3(w_3)) + (_e95 * vec3(b_9.x))) + (_e101 * vec3(b_9.y)));
        let _e106 = n_shade;
        let _e107 = n_shade;
        if (dot(_e106, _e107) < 0.000000000001f) {
            let _e111 = n_geo;
            n_shade = _e111;
        }
        let uv0_ = unpack2x16float(a0_.w);
        let uv1_ = unpack2x16float(a1_.x);
        let uv2_ = unpack2x16float(a1_.y);
        hit.uv = (((uv0_ * vec2(w_3)) + (uv1_ * vec2(b_9.x))) + (uv2_ * vec2(b_9.y)));
        let _e135 = triangles[(c_1.primitive * 3u)];
        hit.primitive = bitcast<u32>(_e135.w);
    }
    let _e139 = n_geo;
    let _e140 = normal_to_world(inst_7, _e139);
    hit.geometric_normal = _e140;
    let _e142 = n_shade;
    let _e143 = normal_to_world(inst_7, _e142);
    hit.normal = _e143;
    let _e147 = hit.geometric_normal;
    hit.front_face = (dot(ray_8.dir, _e147) < 0f);
    let _e151 = hit;
    return _e151;
}

fn medium_at(p_4: vec3<f32>, exclude: u32) -> u32 {
    var inside: u32;
    var nearest: f32;
    var i_1: u32;

    if !(HAS_MEDIA) {
        return 0u;
    }
    let frame_1 = frame;
    let _e12 = normalize_vec3f(vec3<f32>(0.5773f, 0.5774f, 0.5775f));
    let _e14 = F32_INF;
    let probe = Ray(p_4, 0f, _e12, bitcast<f32>(_e14), 0u, 0u, 0u);
    inside = 0u;
    let _e23 = F32_INF;
    nearest = bitcast<f32>(_e23);
    let end = frame_1.medium_count;
    i_1 = 0u;
    loop {
        let _e29 = i_1;
        if (_e29 >= end) {
            break;
        }
        let _e32 = i_1;
        let slot_4 = params[(frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE))];
        if (slot_4 != exclude) {
            let _e41 = F32_INF;
            let _e43 = no_candidate(bitcast<f32>(_e41));
            let _e45 = intersect_object(slot_4, probe, _e43, false);
            let _e50 = nearest;
            if ((_e45.slot != NO_HIT) && (_e45.t < _e50)) {
                let _e53 = finish_hit(probe, _e45);
                if !(_e53.front_face) {
                    inside = (slot_4 + 1u);
                    nearest = _e45.t;
                }
            }
        }
        continuing {
            let _e59 = i_1;
            i_1 = (_e59 + 1u);
        }
    }
    let _e62 = inside;
    return _e62;
}

fn sample_camera_ray(pixel_4: vec2<u32>, sample_4: u32) -> Ray {
    var ray_9: Ray;

    let frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    let _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_9 = _e7;
    ray_9.depth = 0u;
    ray_9.kind = RAY_CAMERA;
    let _e15 = ray_9.origin;
    let _e17 = medium_at(_e15, NO_HIT);
    ray_9.medium = _e17;
    let _e18 = ray_9;
    return _e18;
}

fn node_frame_bounds() -> vec3<f32> {
    return vec3(65535f);
}

fn intersect_scene(ray_10: Ray, shadow_2: bool) -> Candidate {
    var best_2: Candidate;
    var sp_2: u32;
    var child_1: u32;
    var near_1: u32;
    var far_1: u32;

    let _e3 = ray_count;
    ray_count = (_e3 + 1u);
    let _e7 = no_candidate(ray_10.tmax);
    best_2 = _e7;
    let frame_3 = frame;
    if (frame_3.instance_count == 0u) {
        let _e14 = best_2;
        return _e14;
    }
    let base_6 = frame_3.tlas_root;
    let header_3 = nodes[base_6];
    let _e19 = box_ray(header_3, ray_10);
    let _e22 = node_frame_bounds();
    let _e24 = best_2.t;
    let _e27 = slab_in_frame(vec3(0f), _e22, _e19, (_e24 * _e19.unit));
    let _e29 = F32_INF;
    if (_e27 == bitcast<f32>(_e29)) {
        let _e32 = best_2;
        return _e32;
    }
    sp_2 = 0u;
    child_1 = header_3.a;
    loop {
        let _e37 = child_1;
        if ((_e37 & NODE_LEAF_BIT) != 0u) {
            let _e42 = child_1;
            if (((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u) {
                let _e51 = child_1;
                let _e54 = best_2;
                let _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_10, _e54, shadow_2);
                best_2 = _e55;
                let _e57 = best_2.slot;
                if (shadow_2 && (_e57 != NO_HIT)) {
                    let _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            let _e62 = child_1;
            let n_12 = nodes[(base_6 + _e62)];
            let _e68 = best_2.t;
            let _e69 = children_entry(n_12, _e19, _e68);
            let tl_1 = _e69.x;
            let tr_1 = _e69.y;
            let _e73 = F32_INF;
            let _e77 = F32_INF;
            if ((tl_1 < bitcast<f32>(_e73)) && (tr_1 < bitcast<f32>(_e77))) {
                near_1 = n_12.a;
                far_1 = n_12.b;
                if (tr_1 < tl_1) {
                    near_1 = n_12.b;
                    far_1 = n_12.a;
                }
                let _e88 = sp_2;
                if (_e88 < TLAS_STACK) {
                    let _e91 = sp_2;
                    let _e92 = far_1;
                    traversal_stack[min(_e91, 71u)] = _e92;
                    let _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                let _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            let _e102 = F32_INF;
            if (tl_1 < bitcast<f32>(_e102)) {
                child_1 = n_12.a;
                continue;
            }
            let _e107 = F32_INF;
            if (tr_1 < bitcast<f32>(_e107)) {
                child_1 = n_12.b;
                continue;
            }
        }
        let _e112 = sp_2;
        let _e113 = pop(0u, _e112);
        if (_e113.x == NO_HIT) {
            break;
        }
        child_1 = _e113.x;
        sp_2 = _e113.y;
    }
    let _e119 = best_2;
    return _e119;
}

fn load_ConstantBackground(offset_4: u32) -> ConstantBackground {
    let _e5 = params[(offset_4 + 0u)];
    let _e11 = params[(offset_4 + 1u)];
    let _e17 = params[(offset_4 + 2u)];
    return ConstantBackground(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)));
}

fn constant_background(b_6: ConstantBackground, ray_11: Ray) -> vec3<f32> {
    return b_6.color;
}

fn dispatch_miss(type_id_2: u32, offset_5: u32, ray_12: Ray) -> vec3<f32> {
    let _e2 = load_ConstantBackground(offset_5);
    let _e3 = constant_background(_e2, ray_12);
    return _e3;
}

fn miss(ray_13: Ray) -> vec3<f32> {
    if !(HAS_BACKGROUND) {
        return vec3(0f);
    }
    let frame_4 = frame;
    let _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_13);
    return _e9;
}

fn load_PathDiffuse(offset_6: u32) -> PathDiffuse {
    let _e5 = params[(offset_6 + 0u)];
    let _e11 = params[(offset_6 + 1u)];
    let _e17 = params[(offset_6 + 2u)];
    let _e24 = params[(offset_6 + 3u)];
    return PathDiffuse(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), _e24);
}

fn light_count_query() -> u32 {
    let _e1 = frame;
    return _e1.light_count;
}

fn load_QuadLight(offset_7: u32) -> QuadLight {
    let _e5 = params[(offset_7 + 0u)];
    let _e11 = params[(offset_7 + 1u)];
    let _e17 = params[(offset_7 + 2u)];
    let _e24 = params[(offset_7 + 4u)];
    let _e30 = params[(offset_7 + 5u)];
    let _e36 = params[(offset_7 + 6u)];
    let _e43 = params[(offset_7 + 8u)];
    let _e49 = params[(offset_7 + 9u)];
    let _e55 = params[(offset_7 + 10u)];
    let _e62 = params[(offset_7 + 12u)];
    let _e68 = params[(offset_7 + 13u)];
    let _e74 = params[(offset_7 + 14u)];
    let _e81 = params[(offset_7 + 15u)];
    let _e87 = params[(offset_7 + 16u)];
    return QuadLight(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), vec3<f32>(bitcast<f32>(_e24), bitcast<f32>(_e30), bitcast<f32>(_e36)), vec3<f32>(bitcast<f32>(_e43), bitcast<f32>(_e49), bitcast<f32>(_e55)), vec3<f32>(bitcast<f32>(_e62), bitcast<f32>(_e68), bitcast<f32>(_e74)), bitcast<f32>(_e81), _e87);
}

fn shadow_preset(normal: vec3<f32>, dir: vec3<f32>) -> f32 {
    let mode = scratch[min(SCRATCH_SHADOW_MODE, 24u)];
    if (mode == SHADOW_UNOCCLUDED) {
        return 1f;
    }
    if ((mode == SHADOW_ABOVE) && !((dot(dir, normal) > 0f))) {
        return 0f;
    }
    return -1f;
}

fn scratch_store3f(i_2: u32, v_2: vec3<f32>) {
    let b_10 = bitcast<vec3<u32>>(v_2);
    scratch[min(i_2, 24u)] = b_10.x;
    scratch[min((i_2 + 1u), 24u)] = b_10.y;
    scratch[min((i_2 + 2u), 24u)] = b_10.z;
    return;
}

fn shadow_deferred(position: vec3<f32>, normal_1: vec3<f32>, dir_1: vec3<f32>, dist: f32) -> f32 {
    let _e4 = shadow_preset(normal_1, dir_1);
    if (_e4 >= 0f) {
        return _e4;
    }
    let i_9 = scratch[min(SCRATCH_QUERY, 24u)];
    scratch[min(SCRATCH_QUERY, 24u)] = (i_9 + 1u);
    let _e25 = scratch[min(SCRATCH_RESOLVED, 24u)];
    if (i_9 < _e25) {
        let _e32 = scratch[min(SCRATCH_LIGHT_BITS, 24u)];
        return f32(((_e32 >> (i_9 & 31u)) & 1u));
    }
    let _e44 = scratch[min(SCRATCH_PENDING, 24u)];
    if (_e44 != 0u) {
        return 1f;
    }
    if (i_9 >= LIGHT_QUERIES) {
        atomicAdd((&counters[min(COUNTER_SHADOW_OVERFLOW, 3u)]), 1u);
        return 1f;
    }
    scratch_store3f(SCRATCH_LIGHT_QUERY, position);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 3u), normal_1);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 6u), dir_1);
    scratch[min((SCRATCH_LIGHT_QUERY + 9u), 24u)] = bitcast<u32>(dist);
    scratch[min(SCRATCH_PENDING, 24u)] = 1u;
    return 1f;
}

fn quad_light(l: QuadLight, position_1: vec3<f32>, normal_2: vec3<f32>) -> LightSample {
    let c_11 = cross(l.edge_u, l.edge_v);
    let area = length(c_11);
    let _e7 = rand2_next();
    let to_light = (((l.corner + (l.edge_u * vec3(_e7.x))) + (l.edge_v * vec3(_e7.y))) - position_1);
    let dist2_ = dot(to_light, to_light);
    let dist_3 = sqrt(dist2_);
    let dir_9 = (to_light / vec3(max(dist_3, 0.00000000000000000001f)));
    let cos_light = (-(dot(dir_9, c_11)) / max(area, 0.000000000000000000000000000001f));
    if (!((cos_light > 0f)) || !((dist2_ > 0f))) {
        return LightSample(dir_9, dist_3, vec3(0f), 0f);
    }
    let _e42 = shadow_deferred(position_1, normal_2, dir_9, dist_3);
    let strength = (((l.intensity * cos_light) * area) / dist2_);
    let pdf_1 = select(0f, (dist2_ / (cos_light * area)), (l.lamp == 1u));
    return LightSample(dir_9, dist_3, ((l.color * vec3(strength)) * vec3(_e42)), pdf_1);
}

fn load_SphereLight(offset_8: u32) -> SphereLight {
    let _e5 = params[(offset_8 + 0u)];
    let _e11 = params[(offset_8 + 1u)];
    let _e17 = params[(offset_8 + 2u)];
    let _e24 = params[(offset_8 + 3u)];
    let _e30 = params[(offset_8 + 4u)];
    let _e36 = params[(offset_8 + 5u)];
    let _e42 = params[(offset_8 + 6u)];
    let _e49 = params[(offset_8 + 7u)];
    let _e55 = params[(offset_8 + 8u)];
    return SphereLight(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), bitcast<f32>(_e24), vec3<f32>(bitcast<f32>(_e30), bitcast<f32>(_e36), bitcast<f32>(_e42)), bitcast<f32>(_e49), _e55);
}

fn orthonormal_basis(n_3: vec3<f32>) -> mat3x3<f32> {
    let sign_ = select(1f, -1f, ((bitcast<u32>(n_3.z) & 2147483648u) != 0u));
    let a_7 = (-1f / (sign_ + n_3.z));
    let b_11 = ((n_3.x * n_3.y) * a_7);
    let _e16 = (sign_ * n_3.x);
    return mat3x3<f32>(vec3<f32>((1f + ((_e16 * n_3.x) * a_7)), (sign_ * b_11), -(_e16)), vec3<f32>(b_11, (sign_ + ((n_3.y * n_3.y) * a_7)), -(n_3.y)), n_3);
}

fn sphere_light(l_1: SphereLight, position_2: vec3<f32>, normal_3: vec3<f32>) -> LightSample {
    let to_center = (l_1.position - position_2);
    let d2_ = dot(to_center, to_center);
    let r2_2 = max((l_1.radius * l_1.radius), 0.00000000000000000001f);
    if (d2_ <= r2_2) {
        return LightSample(vec3<f32>(0f, 1f, 0f), 0f, vec3(0f), 0f);
    }
    let w_4 = (to_center * vec3(inverseSqrt(d2_)));
    let s2_ = (r2_2 / d2_);
    let cos_max = sqrt((1f - s2_));
    let one_minus_cos_max = (s2_ / (1f + cos_max));
    let _e31 = rand2_next();
    let cos_t = (1f - (_e31.x * one_minus_cos_max));
    let sin_t = sqrt(max((1f - (cos_t * cos_t)), 0f));
    let phi = (TAU * _e31.y);
    let _e45 = orthonormal_basis(w_4);
    let _e52 = normalize_vec3f((_e45 * vec3<f32>((cos(phi) * sin_t), (sin(phi) * sin_t), cos_t)));
    let along_1 = dot(to_center, _e52);
    let dist_4 = max((along_1 - sqrt(max((r2_2 - (d2_ - (along_1 * along_1))), 0f))), 0f);
    let weight_4 = (((l_1.intensity * 2f) * one_minus_cos_max) / r2_2);
    let _e68 = shadow_deferred(position_2, normal_3, _e52, dist_4);
    let pdf_2 = select(0f, (1f / (TAU * one_minus_cos_max)), (l_1.lamp == 1u));
    return LightSample(_e52, dist_4, ((l_1.color * vec3(weight_4)) * vec3(_e68)), pdf_2);
}

fn dispatch_light(type_id_3: u32, offset_9: u32, position_3: vec3<f32>, normal_4: vec3<f32>) -> LightSample {
    switch type_id_3 {
        case 0u: {
            let _e4 = load_QuadLight(offset_9);
            let _e5 = quad_light(_e4, position_3, normal_4);
            return _e5;
        }
        case 1u: {
            let _e6 = load_SphereLight(offset_9);
            let _e7 = sphere_light(_e6, position_3, normal_4);
            return _e7;
        }
        default: {
        }
    }
    return LightSample();
}

fn scratch_load3f(i_3: u32) -> vec3<f32> {
    let _e5 = scratch[min(i_3, 24u)];
    let _e12 = scratch[min((i_3 + 1u), 24u)];
    let _e19 = scratch[min((i_3 + 2u), 24u)];
    return bitcast<vec3<f32>>(vec3<u32>(_e5, _e12, _e19));
}

fn step_toward(x_3: vec3<f32>, s_1: vec3<f32>) -> vec3<f32> {
    let bits_2 = bitcast<vec3<u32>>(x_3);
    let up_1 = ((sign(x_3) * sign(s_1)) > vec3(0f));
    let stepped = bitcast<vec3<f32>>(select((bits_2 - vec3(1u)), (bits_2 + vec3(1u)), up_1));
    let from_zero = select(vec3(-0.000000000000000000000000000000000000011754944f), vec3(0.000000000000000000000000000000000000011754944f), (s_1 > vec3(0f)));
    let moved = select(stepped, from_zero, (x_3 == vec3(0f)));
    return select(x_3, moved, !((s_1 == vec3(0f))));
}

fn offset_origin(p_5: vec3<f32>, n_4: vec3<f32>, error: f32) -> vec3<f32> {
    let d_4 = ((2f * error) * ((abs(n_4.x) + abs(n_4.y)) + abs(n_4.z)));
    let offset_16 = (n_4 * vec3(d_4));
    let _e17 = step_toward((p_5 + offset_16), offset_16);
    return _e17;
}

fn shadow_ray(position_4: vec3<f32>, normal_5: vec3<f32>, dir_2: vec3<f32>, dist_1: f32) -> Ray {
    var n_5: vec3<f32>;
    var tmax_4: f32;

    n_5 = normal_5;
    let _e5 = n_5;
    if (dot(dir_2, _e5) < 0f) {
        let _e9 = n_5;
        n_5 = -(_e9);
    }
    let a_8 = abs(position_4);
    let _e13 = hit_error;
    let error_3 = max(_e13, (GAMMA_4_ * max(max(a_8.x, a_8.y), a_8.z)));
    let _e22 = n_5;
    let _e23 = offset_origin(position_4, _e22, error_3);
    let _e25 = F32_INF;
    tmax_4 = bitcast<f32>(_e25);
    let _e29 = F32_INF;
    if (dist_1 < bitcast<f32>(_e29)) {
        let light = (position_4 + (dir_2 * vec3(dist_1)));
        let dd = dot(dir_2, dir_2);
        let along_2 = (dot((light - _e23), dir_2) / dd);
        let l_7 = (abs(position_4) + abs((dir_2 * vec3(dist_1))));
        tmax_4 = ((along_2 * (1f - 0.00001f)) - ((LIGHT_ERROR * max(max(l_7.x, l_7.y), l_7.z)) / sqrt(dd)));
    }
    let _e59 = tmax_4;
    return Ray(_e23, 0f, dir_2, _e59, 0u, RAY_SHADOW, 0u);
}

fn shadow_query(position_5: vec3<f32>, normal_6: vec3<f32>, dir_3: vec3<f32>, dist_2: f32) -> f32 {
    let _e4 = shadow_preset(normal_6, dir_3);
    if (_e4 >= 0f) {
        return _e4;
    }
    let _e7 = shadow_ray(position_5, normal_6, dir_3, dist_2);
    let _e9 = intersect_scene(_e7, true);
    return select(1f, 0f, (_e9.slot != NO_HIT));
}

fn sample_light_deferred(i_4: u32, position_6: vec3<f32>, normal_7: vec3<f32>) -> LightSample {
    var after: u32;
    var resolved: u32;
    var bits_1: u32;

    let frame_5 = frame;
    if (i_4 >= frame_5.light_count) {
        return LightSample(vec3<f32>(0f, 1f, 0f), 0f, vec3(0f), 0f);
    }
    let entry = (frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE));
    let type_id_7 = params[entry];
    let offset_17 = params[(entry + 1u)];
    let start_1 = rng_state;
    after = start_1;
    resolved = 0u;
    bits_1 = 0u;
    scratch[min(SCRATCH_RESOLVED, 24u)] = 0u;
    scratch[min(SCRATCH_LIGHT_BITS, 24u)] = 0u;
    loop {
        rng_state = start_1;
        scratch[min(SCRATCH_QUERY, 24u)] = 0u;
        scratch[min(SCRATCH_PENDING, 24u)] = 0u;
        let _e60 = dispatch_light(type_id_7, offset_17, position_6, normal_7);
        let _e66 = scratch[min(SCRATCH_PENDING, 24u)];
        if (_e66 == 0u) {
            let _e69 = resolved;
            if (_e69 > 0u) {
                let _e72 = after;
                rng_state = _e72;
            }
            return _e60;
        }
        let _e74 = resolved;
        if (_e74 == 0u) {
            let _e78 = rng_state;
            after = _e78;
        }
        let _e79 = after;
        rng_state = _e79;
        let _e82 = scratch_load3f(SCRATCH_LIGHT_QUERY);
        let _e85 = scratch_load3f((SCRATCH_LIGHT_QUERY + 3u));
        let _e88 = scratch_load3f((SCRATCH_LIGHT_QUERY + 6u));
        let _e95 = scratch[min((SCRATCH_LIGHT_QUERY + 9u), 24u)];
        let _e97 = shadow_query(_e82, _e85, _e88, bitcast<f32>(_e95));
        let _e99 = rng_state;
        after = _e99;
        if !((_e97 == 0f)) {
            let _e108 = scratch[min(SCRATCH_QUERY, 24u)];
            let _e109 = resolved;
            if (_e108 == (_e109 + 1u)) {
                let _e113 = after;
                rng_state = _e113;
                scratch[min(SCRATCH_PENDING, 24u)] = 0u;
                return _e60;
            }
            let _e121 = bits_1;
            let _e123 = resolved;
            bits_1 = (_e121 | (1u << (_e123 & 31u)));
        }
        let _e128 = resolved;
        resolved = (_e128 + 1u);
        let _e132 = bits_1;
        scratch[min(SCRATCH_LIGHT_BITS, 24u)] = _e132;
        let _e138 = resolved;
        scratch[min(SCRATCH_RESOLVED, 24u)] = _e138;
    }
    return LightSample();
}

fn sample_light_above_deferred(i_5: u32, position_7: vec3<f32>, normal_8: vec3<f32>) -> LightSample {
    scratch[min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_ABOVE;
    let _e9 = sample_light_deferred(i_5, position_7, normal_8);
    scratch[min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_TRACED;
    return _e9;
}

fn mis_weight(p_6: f32, other: f32) -> f32 {
    if !((p_6 > 0f)) {
        return 0f;
    }
    let r_3 = (max(other, 0f) / p_6);
    if !((r_3 < 1000000000000000000f)) {
        let _e15 = F32_INF;
        let _e19 = F32_INF;
        return select(0f, 1f, ((p_6 == bitcast<f32>(_e15)) && (other < bitcast<f32>(_e19))));
    }
    return (1f / (1f + (r_3 * r_3)));
}

fn mis_light_weight(l_2: LightSample, bsdf_pdf: f32) -> f32 {
    if !((l_2.pdf > 0f)) {
        return 1f;
    }
    let _e8 = mis_weight(l_2.pdf, bsdf_pdf);
    return _e8;
}

fn path_diffuse_shade(m: PathDiffuse, ray_14: Ray, hit_1: Hit, secondary: vec3<f32>) -> vec3<f32> {
    var direct: vec3<f32>;
    var i_6: u32;

    let n_13 = faceForward(hit_1.normal, ray_14.dir, hit_1.geometric_normal);
    let ng = faceForward(hit_1.geometric_normal, ray_14.dir, hit_1.geometric_normal);
    direct = vec3(0f);
    let _e16 = light_count_query();
    i_6 = 0u;
    loop {
        let _e18 = i_6;
        if (_e18 >= _e16) {
            break;
        }
        let _e20 = i_6;
        let _e22 = sample_light_above_deferred(_e20, hit_1.position, ng);
        let c_12 = max(dot(n_13, _e22.dir), 0f);
        let _e27 = direct;
        let _e31 = mis_light_weight(_e22, (c_12 * INV_PI));
        direct = (_e27 + (_e22.radiance * vec3((c_12 * _e31))));
        continuing {
            let _e36 = i_6;
            i_6 = (_e36 + 1u);
        }
    }
    let _e43 = direct;
    return (((m.albedo * vec3(INV_PI)) * _e43) + secondary);
}

fn load_QuadLamp(offset_10: u32) -> QuadLamp {
    let _e5 = params[(offset_10 + 0u)];
    let _e11 = params[(offset_10 + 1u)];
    let _e17 = params[(offset_10 + 2u)];
    let _e24 = params[(offset_10 + 3u)];
    let _e30 = params[(offset_10 + 4u)];
    return QuadLamp(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), bitcast<f32>(_e24), bitcast<f32>(_e30));
}

fn after_nee_bounce(ray_15: Ray) -> bool {
    return (dot(ray_15.dir, ray_15.dir) > 2f);
}

fn bounce_pdf(ray_16: Ray) -> f32 {
    let x_6 = (length(ray_16.dir) - MIS_BOUNCE_LENGTH);
    if !((x_6 > -0.25f)) {
        return 0f;
    }
    return (exp((max(x_6, 0f) * 90f)) - 1f);
}

fn quad_lamp_shade(m_1: QuadLamp, ray_17: Ray, hit_2: Hit) -> vec3<f32> {
    if !(hit_2.front_face) {
        return vec3(0f);
    }
    let le = (m_1.color * vec3(m_1.intensity));
    let _e11 = after_nee_bounce(ray_17);
    if !(_e11) {
        return le;
    }
    let _e13 = bounce_pdf(ray_17);
    let len = length(ray_17.dir);
    let dist_5 = (hit_2.t * len);
    let cos_l = (abs(dot(hit_2.geometric_normal, ray_17.dir)) / len);
    let pl = ((dist_5 * dist_5) / max((cos_l * m_1.area), 0.000000000000000000000000000001f));
    let _e29 = mis_weight(_e13, pl);
    return (le * vec3(_e29));
}

fn load_SphereLamp(offset_11: u32) -> SphereLamp {
    let _e5 = params[(offset_11 + 0u)];
    let _e11 = params[(offset_11 + 1u)];
    let _e17 = params[(offset_11 + 2u)];
    let _e24 = params[(offset_11 + 3u)];
    let _e30 = params[(offset_11 + 4u)];
    return SphereLamp(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), bitcast<f32>(_e24), bitcast<f32>(_e30));
}

fn sphere_lamp_shade(m_2: SphereLamp, ray_18: Ray, hit_3: Hit) -> vec3<f32> {
    if !(hit_3.front_face) {
        return vec3(0f);
    }
    let r2_3 = max((m_2.radius * m_2.radius), 0.00000000000000000001f);
    let le_1 = (m_2.color * vec3(((m_2.intensity * INV_PI) / r2_3)));
    let _e19 = after_nee_bounce(ray_18);
    if !(_e19) {
        return le_1;
    }
    let _e21 = bounce_pdf(ray_18);
    let center = (hit_3.position - (hit_3.normal * vec3(m_2.radius)));
    let to_center_1 = (center - ray_18.origin);
    let s2_1 = (r2_3 / max(dot(to_center_1, to_center_1), r2_3));
    let one_minus_cos_max_1 = (s2_1 / (1f + sqrt((1f - s2_1))));
    let pl_1 = (1f / max((TAU * one_minus_cos_max_1), 0.000000000000000000000000000001f));
    let _e45 = mis_weight(_e21, pl_1);
    return (le_1 * vec3(_e45));
}

fn load_PathPbr(offset_12: u32) -> PathPbr {
    let _e5 = params[(offset_12 + 0u)];
    let _e11 = params[(offset_12 + 1u)];
    let _e17 = params[(offset_12 + 2u)];
    let _e24 = params[(offset_12 + 3u)];
    let _e30 = params[(offset_12 + 4u)];
    let _e36 = params[(offset_12 + 8u)];
    let _e42 = params[(offset_12 + 9u)];
    let _e48 = params[(offset_12 + 10u)];
    let _e55 = params[(offset_12 + 11u)];
    return PathPbr(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), bitcast<f32>(_e24), bitcast<f32>(_e30), vec3<f32>(bitcast<f32>(_e36), bitcast<f32>(_e42), bitcast<f32>(_e48)), _e55);
}

fn path_pbr_ng(ray_19: Ray, hit_4: Hit) -> vec3<f32> {
    return faceForward(hit_4.geometric_normal, ray_19.dir, hit_4.geometric_normal);
}

fn path_pbr_n(ray_20: Ray, hit_5: Hit) -> vec3<f32> {
    let _e2 = path_pbr_ng(ray_20, hit_5);
    let n_14 = faceForward(hit_5.normal, -(_e2), hit_5.normal);
    return select(_e2, n_14, (dot(n_14, ray_20.dir) < 0f));
}

fn pbr_alpha2_(roughness: f32) -> f32 {
    let a_9 = max((saturate(roughness) * saturate(roughness)), PBR_MIN_ALPHA);
    return (a_9 * a_9);
}

fn pbr_fresnel(f0_: vec3<f32>, c_2: f32) -> vec3<f32> {
    let k_1 = (1f - saturate(c_2));
    let k2_ = (k_1 * k_1);
    return (f0_ + ((vec3(1f) - f0_) * vec3(((k2_ * k2_) * k_1))));
}

fn pbr_ggx_d(ndh: f32, a2_: f32) -> f32 {
    let d_5 = (((ndh * ndh) * (a2_ - 1f)) + 1f);
    return ((a2_ * INV_PI) / (d_5 * d_5));
}

fn pbr_smith_v(ndl: f32, ndv: f32, a2_1: f32) -> f32 {
    let gv = (ndl * sqrt((((ndv * ndv) * (1f - a2_1)) + a2_1)));
    let gl = (ndv * sqrt((((ndl * ndl) * (1f - a2_1)) + a2_1)));
    return (0.5f / max((gv + gl), 0.00000000000000000001f));
}

fn pbr_eval(base_1: vec3<f32>, metallic: f32, roughness_1: f32, n_6: vec3<f32>, v_3: vec3<f32>, l_3: vec3<f32>) -> vec3<f32> {
    let ndv_3 = dot(n_6, v_3);
    let ndl_1 = dot(n_6, l_3);
    if (!((ndv_3 > 0f)) || !((ndl_1 > 0f))) {
        return vec3(0f);
    }
    let metal = saturate(metallic);
    let _e18 = pbr_alpha2_(roughness_1);
    let f0_1 = mix(vec3(0.04f), base_1, vec3(metal));
    let _e24 = normalize_vec3f((v_3 + l_3));
    let _e26 = pbr_fresnel(f0_1, dot(v_3, _e24));
    let _e29 = pbr_ggx_d(saturate(dot(n_6, _e24)), _e18);
    let _e30 = pbr_smith_v(ndl_1, ndv_3, _e18);
    let spec = (_e26 * vec3((_e29 * _e30)));
    let diffuse = (((vec3(1f) - _e26) * base_1) * vec3(((1f - metal) * INV_PI)));
    return ((diffuse + spec) * vec3(ndl_1));
}

fn luminance(c_3: vec3<f32>) -> f32 {
    return dot(c_3, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn pbr_specular_chance(base_2: vec3<f32>, metallic_1: f32, ndv_1: f32) -> f32 {
    let metal_1 = saturate(metallic_1);
    let _e8 = pbr_fresnel(mix(vec3(0.04f), base_2, vec3(metal_1)), ndv_1);
    let _e9 = luminance(_e8);
    let _e18 = luminance(((base_2 * vec3((1f - metal_1))) * (vec3(1f) - _e8)));
    if !((_e18 > 0f)) {
        return 1f;
    }
    if !((_e9 > 0f)) {
        return 0f;
    }
    return min(max((_e9 / (_e9 + _e18)), 0.1f), 0.9f);
}

fn pbr_specular_pdf(ndh_1: f32, ndv_2: f32, a2_2: f32) -> f32 {
    let _e3 = pbr_ggx_d(ndh_1, a2_2);
    return ((_e3 * 0.5f) / (ndv_2 + sqrt((a2_2 + (((1f - a2_2) * ndv_2) * ndv_2)))));
}

fn pbr_pdf(base_3: vec3<f32>, metallic_2: f32, roughness_2: f32, n_7: vec3<f32>, v_4: vec3<f32>, l_4: vec3<f32>) -> f32 {
    let ndv_4 = dot(n_7, v_4);
    let ndl_2 = dot(n_7, l_4);
    if (!((ndv_4 > 0f)) || !((ndl_2 > 0f))) {
        return 0f;
    }
    let _e16 = pbr_alpha2_(roughness_2);
    let _e17 = pbr_specular_chance(base_3, metallic_2, ndv_4);
    let _e19 = normalize_vec3f((v_4 + l_4));
    let _e22 = pbr_specular_pdf(saturate(dot(n_7, _e19)), ndv_4, _e16);
    return ((_e17 * _e22) + (((1f - _e17) * ndl_2) * INV_PI));
}

fn path_pbr_shade(m_3: PathPbr, ray_21: Ray, hit_6: Hit, secondary_1: vec3<f32>) -> vec3<f32> {
    var direct_1: vec3<f32>;
    var i_7: u32;
    var w: f32;

    let _e4 = path_pbr_n(ray_21, hit_6);
    let _e6 = normalize_vec3f(ray_21.dir);
    let v_7 = -(_e6);
    direct_1 = vec3(0f);
    let _e11 = path_pbr_ng(ray_21, hit_6);
    let _e13 = light_count_query();
    i_7 = 0u;
    loop {
        let _e15 = i_7;
        if (_e15 >= _e13) {
            break;
        }
        let _e17 = i_7;
        let _e19 = sample_light_above_deferred(_e17, hit_6.position, _e11);
        if any((_e19.radiance > vec3(0f))) {
            let _e29 = pbr_eval(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
            w = 1f;
            if (_e19.pdf > 0f) {
                let _e40 = pbr_pdf(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
                let _e41 = mis_weight(_e19.pdf, _e40);
                w = _e41;
            }
            let _e42 = direct_1;
            let _e45 = w;
            direct_1 = (_e42 + ((_e19.radiance * _e29) * vec3(_e45)));
        }
        continuing {
            let _e49 = i_7;
            i_7 = (_e49 + 1u);
        }
    }
    let _e53 = direct_1;
    return ((m_3.emissive + _e53) + secondary_1);
}

fn dispatch_closest_hit(type_id_4: u32, offset_13: u32, ray_22: Ray, hit_7: Hit, secondary_2: vec3<f32>) -> vec3<f32> {
    switch type_id_4 {
        case 0u: {
            let _e5 = load_PathDiffuse(offset_13);
            let _e6 = path_diffuse_shade(_e5, ray_22, hit_7, secondary_2);
            return _e6;
        }
        case 1u: {
            let _e7 = load_QuadLamp(offset_13);
            let _e8 = quad_lamp_shade(_e7, ray_22, hit_7);
            return _e8;
        }
        case 2u: {
            let _e9 = load_SphereLamp(offset_13);
            let _e10 = sphere_lamp_shade(_e9, ray_22, hit_7);
            return _e10;
        }
        case 3u: {
            let _e11 = load_PathPbr(offset_13);
            let _e12 = path_pbr_shade(_e11, ray_22, hit_7, secondary_2);
            return _e12;
        }
        default: {
        }
    }
    return vec3<f32>();
}

fn shade_direct(ray_23: Ray, c_4: Candidate) -> vec3<f32> {
    let inst_8 = instances[c_4.slot];
    let _e6 = finish_hit(ray_23, c_4);
    let _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_23, _e6, vec3(0f));
    return _e11;
}

fn dispatch_medium(type_id_5: u32, offset_14: u32, ray_24: Ray, t_1: f32, radiance: vec3<f32>) -> vec3<f32> {
    return vec3<f32>();
}

fn through_medium(ray_25: Ray, t_2: f32, radiance_1: vec3<f32>) -> vec3<f32> {
    if !(HAS_MEDIA) {
        return radiance_1;
    }
    if (ray_25.medium == 0u) {
        return radiance_1;
    }
    let inst_9 = instances[(ray_25.medium - 1u)];
    if ((inst_9.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    let _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_25, t_2, radiance_1);
    return _e21;
}

fn start_path(ray_26: Ray) -> PathState {
    return PathState(ray_26, vec3(1f), vec3(0f), true);
}

fn sample_cosine_hemisphere(n_8: vec3<f32>, u: vec2<f32>) -> vec3<f32> {
    let r_4 = sqrt(u.x);
    let phi_1 = (6.2831855f * u.y);
    let local = vec3<f32>((r_4 * cos(phi_1)), (r_4 * sin(phi_1)), sqrt(max((1f - u.x), 0f)));
    let _e17 = orthonormal_basis(n_8);
    return (_e17 * local);
}

fn mis_bounce_dir(dir_4: vec3<f32>, pdf: f32) -> vec3<f32> {
    let x_7 = min((log((1f + max(pdf, 0f))) * (1f / 90f)), 0.999f);
    return (dir_4 * vec3((MIS_BOUNCE_LENGTH + x_7)));
}

fn rt_spawn(dir_5: vec3<f32>, weight: vec3<f32>) {
    let _e3 = spawn_count;
    if (_e3 < 1u) {
        spawn_dirs[_e3] = dir_5;
        spawn_weights[_e3] = weight;
        spawn_count = (_e3 + 1u);
    }
}

fn path_diffuse_rays(m_4: PathDiffuse, ray_27: Ray, hit_8: Hit) {
    var weight_1: vec3<f32>;

    let ng_1 = select(-(hit_8.geometric_normal), hit_8.geometric_normal, hit_8.front_face);
    let n_15 = faceForward(hit_8.normal, -(ng_1), hit_8.normal);
    let _e12 = rand2_next();
    let _e13 = sample_cosine_hemisphere(n_15, _e12);
    weight_1 = m_4.albedo;
    if (ray_27.depth >= m_4.roulette_depth) {
        let q_4 = saturate(max(m_4.albedo.x, max(m_4.albedo.y, m_4.albedo.z)));
        let _e28 = rand_next();
        if (_e28 >= q_4) {
            return;
        }
        weight_1 = (m_4.albedo / vec3(q_4));
    }
    if (dot(_e13, ng_1) > 0f) {
        let _e41 = mis_bounce_dir(_e13, (max(dot(n_15, _e13), 0f) * INV_PI));
        let _e42 = weight_1;
        rt_spawn(_e41, _e42);
    }
    return;
}

fn pbr_sample_vndf(ve: vec3<f32>, alpha: f32, u_1: vec2<f32>) -> vec3<f32> {
    var t1_: vec3<f32>;

    let _e9 = normalize_vec3f(vec3<f32>((alpha * ve.x), (alpha * ve.y), ve.z));
    let lensq = ((_e9.x * _e9.x) + (_e9.y * _e9.y));
    t1_ = vec3<f32>(1f, 0f, 0f);
    if (lensq > 0f) {
        t1_ = (vec3<f32>(-(_e9.y), _e9.x, 0f) * vec3(inverseSqrt(lensq)));
    }
    let _e32 = t1_;
    let t2_ = cross(_e9, _e32);
    let r_5 = sqrt(u_1.x);
    let phi_2 = (TAU * u_1.y);
    let p1_ = (r_5 * cos(phi_2));
    let s_8 = (0.5f * (1f + _e9.z));
    let p2_ = (((1f - s_8) * sqrt(max((1f - (p1_ * p1_)), 0f))) + ((s_8 * r_5) * sin(phi_2)));
    let _e59 = t1_;
    let nh = (((_e59 * vec3(p1_)) + (t2_ * vec3(p2_))) + (_e9 * vec3(sqrt(max(((1f - (p1_ * p1_)) - (p2_ * p2_)), 0f)))));
    let _e84 = normalize_vec3f(vec3<f32>((alpha * nh.x), (alpha * nh.y), max(nh.z, 0f)));
    return _e84;
}

fn pbr_sample(base_4: vec3<f32>, metallic_3: f32, roughness_3: f32, n_9: vec3<f32>, v_5: vec3<f32>, u_2: vec3<f32>) -> PbrSample {
    var l_5: vec3<f32>;

    let ndv_5 = dot(n_9, v_5);
    if !((ndv_5 > 0f)) {
        return PbrSample(n_9, vec3(0f), 0f);
    }
    let _e14 = pbr_specular_chance(base_4, metallic_3, ndv_5);
    l_5 = vec3(0f);
    if (u_2.x < _e14) {
        let _e20 = orthonormal_basis(n_9);
        let _e21 = pbr_alpha2_(roughness_3);
        let _e26 = pbr_sample_vndf((transpose(_e20) * v_5), sqrt(_e21), u_2.yz);
        let h_1 = (_e20 * _e26);
        l_5 = reflect(-(v_5), h_1);
    } else {
        let _e31 = sample_cosine_hemisphere(n_9, u_2.yz);
        l_5 = _e31;
    }
    let _e32 = l_5;
    let _e33 = pbr_pdf(base_4, metallic_3, roughness_3, n_9, v_5, _e32);
    if !((_e33 > 0f)) {
        let _e37 = l_5;
        return PbrSample(_e37, vec3(0f), 0f);
    }
    let _e42 = l_5;
    let _e43 = pbr_eval(base_4, metallic_3, roughness_3, n_9, v_5, _e42);
    let weight_5 = (_e43 / vec3(_e33));
    let _e46 = l_5;
    return PbrSample(_e46, weight_5, _e33);
}

fn path_pbr_rays(m_5: PathPbr, ray_28: Ray, hit_9: Hit) {
    var weight_2: vec3<f32>;

    let _e3 = path_pbr_ng(ray_28, hit_9);
    let _e4 = path_pbr_n(ray_28, hit_9);
    let _e6 = normalize_vec3f(ray_28.dir);
    let v_8 = -(_e6);
    let _e11 = rand_next();
    let _e12 = rand2_next();
    let _e14 = pbr_sample(m_5.base_color, m_5.metallic, m_5.roughness, _e4, v_8, vec3<f32>(_e11, _e12));
    if (!((_e14.pdf > 0f)) || !((dot(_e14.dir, _e3) > 0f))) {
        return;
    }
    weight_2 = _e14.weight;
    if (ray_28.depth >= m_5.roulette_depth) {
        let _e31 = weight_2.x;
        let _e33 = weight_2.y;
        let _e35 = weight_2.z;
        let q_5 = min(max(_e31, max(_e33, _e35)), 1f);
        let _e40 = rand_next();
        if !((_e40 < q_5)) {
            return;
        }
        let _e43 = weight_2;
        weight_2 = (_e43 / vec3(q_5));
    }
    let _e48 = mis_bounce_dir(_e14.dir, _e14.pdf);
    let _e49 = weight_2;
    rt_spawn(_e48, _e49);
    return;
}

fn dispatch_secondary_rays(type_id_6: u32, offset_15: u32, ray_29: Ray, hit_10: Hit) {
    switch type_id_6 {
        case 0u: {
            let _e4 = load_PathDiffuse(offset_15);
            path_diffuse_rays(_e4, ray_29, hit_10);
            return;
        }
        case 3u: {
            let _e5 = load_PathPbr(offset_15);
            path_pbr_rays(_e5, ray_29, hit_10);
            return;
        }
        default: {
        }
    }
    return;
}

fn spawn_origin_at(position_8: vec3<f32>, normal_9: vec3<f32>, error_1: f32, dir_6: vec3<f32>) -> vec3<f32> {
    var n_10: vec3<f32>;

    n_10 = normal_9;
    let _e5 = n_10;
    if (dot(dir_6, _e5) < 0f) {
        let _e9 = n_10;
        n_10 = -(_e9);
    }
    let _e11 = n_10;
    let _e12 = offset_origin(position_8, _e11, error_1);
    return _e12;
}

fn spawn_origin(hit_11: Hit, error_2: f32, dir_7: vec3<f32>) -> vec3<f32> {
    let _e5 = spawn_origin_at(hit_11.position, hit_11.geometric_normal, error_2, dir_7);
    return _e5;
}

fn path_step(s_2: PathState, c_5: Candidate) -> PathState {
    var out: PathState;
    var spawned: bool;
    var dir_8: vec3<f32>;
    var weight_3: vec3<f32>;
    var beta: vec3<f32>;

    let ray_30 = s_2.ray;
    out = s_2;
    out.live = false;
    if (c_5.slot == NO_HIT) {
        hit_error = 0f;
        let _e14 = miss(ray_30);
        out.radiance = (s_2.radiance + (s_2.beta * _e14));
        let _e17 = out;
        return _e17;
    }
    let inst_10 = instances[c_5.slot];
    let _e22 = finish_hit(ray_30, c_5);
    let error_4 = hit_error;
    spawned = false;
    dir_8 = vec3(0f);
    weight_3 = vec3(0f);
    if (((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u) && (ray_30.depth < MAX_DEPTH)) {
        spawn_count = 0u;
        dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, ray_30, _e22);
        let _e47 = spawn_count;
        if (min(_e47, 1u) > 0u) {
            spawned = true;
            let _e56 = spawn_dirs[0u];
            dir_8 = _e56;
            let _e60 = spawn_weights[0u];
            weight_3 = _e60;
        }
    }
    let _e68 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, ray_30, _e22, vec3(0f));
    out.radiance = (s_2.radiance + (s_2.beta * _e68));
    let _e71 = spawned;
    if !(_e71) {
        let _e73 = out;
        return _e73;
    }
    let _e75 = weight_3;
    beta = (s_2.beta * _e75);
    let _e79 = beta.x;
    let _e81 = beta.y;
    let _e83 = beta.z;
    let q_6 = max(_e79, max(_e81, _e83));
    if !((q_6 > 0f)) {
        let _e89 = out;
        return _e89;
    }
    if (((ROULETTE_DEPTH > 0u) && ((ray_30.depth + 1u) >= ROULETTE_DEPTH)) && (q_6 < ROULETTE_THROUGHPUT)) {
        let survive = (q_6 / ROULETTE_THROUGHPUT);
        let _e104 = rand_next();
        if (_e104 >= survive) {
            let _e106 = out;
            return _e106;
        }
        let _e107 = beta;
        beta = (_e107 / vec3(survive));
    }
    let _e111 = beta;
    out.beta = _e111;
    let _e113 = dir_8;
    let _e114 = spawn_origin(_e22, error_4, _e113);
    let _e116 = dir_8;
    let _e118 = F32_INF;
    out.ray = Ray(_e114, 0f, _e116, bitcast<f32>(_e118), (ray_30.depth + 1u), RAY_SECONDARY, ray_30.medium);
    out.live = true;
    let _e128 = out;
    return _e128;
}

fn trace_path(camera_ray: Ray) -> vec3<f32> {
    var s_3: PathState;

    let _e1 = start_path(camera_ray);
    s_3 = _e1;
    loop {
        let _e3 = s_3;
        let _e5 = s_3.ray;
        let _e7 = intersect_scene(_e5, false);
        let _e8 = path_step(_e3, _e7);
        s_3 = _e8;
        let _e10 = s_3.live;
        if !(_e10) {
            let _e13 = s_3.radiance;
            return _e13;
        }
    }
    return vec3<f32>();
}

fn trace(camera_ray_1: Ray) -> vec3<f32> {
    var radiance_2: vec3<f32>;
    var t_3: f32;

    if !(HAS_SECONDARY_RAYS) {
        let _e4 = intersect_scene(camera_ray_1, false);
        radiance_2 = vec3(0f);
        let _e9 = F32_INF;
        t_3 = bitcast<f32>(_e9);
        if (_e4.slot == NO_HIT) {
            hit_error = 0f;
            let _e17 = miss(camera_ray_1);
            radiance_2 = _e17;
        } else {
            let _e18 = shade_direct(camera_ray_1, _e4);
            radiance_2 = _e18;
            t_3 = _e4.t;
        }
        let _e20 = t_3;
        let _e21 = radiance_2;
        let _e22 = through_medium(camera_ray_1, _e20, _e21);
        return _e22;
    }
    let _e23 = trace_path(camera_ray_1);
    return _e23;
}

fn is_finite_vec3f(x_4: vec3<f32>) -> vec3<bool> {
    return ((bitcast<vec3<u32>>(x_4) & vec3(2147483647u)) < vec3(2139095040u));
}

fn finite_or_zero(c_6: vec3<f32>) -> vec3<f32> {
    let _e3 = is_finite_vec3f(c_6);
    return select(vec3(0f), c_6, _e3);
}

fn add_sample(p_7: PassSum, c_7: vec3<f32>, s_4: u32, index: u32, first_pass: u32, per_pass: u32) -> PassSum {
    var next: PassSum;

    next = p_7;
    let _e7 = is_finite_vec3f(c_7);
    if all(_e7) {
        let _e10 = next.sum;
        next.sum = (_e10 + c_7);
    } else {
        let _e13 = next.sum;
        let _e14 = finite_or_zero(c_7);
        next.sum = (_e13 + _e14);
        let _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    let _e22 = rem_u32_((s_4 + 1u), per_pass);
    if (_e22 != 0u) {
        let _e25 = next;
        return _e25;
    }
    let _e27 = ray_count;
    atomicAdd((&counters[1]), _e27);
    ray_count = 0u;
    let _e31 = div_u32_(s_4, per_pass);
    let pass_ = (first_pass + _e31);
    let _e34 = next.sum;
    let _e36 = vec4<f32>(_e34, f32(per_pass));
    let _e38 = next.bad;
    if (pass_ == 0u) {
        accum[index] = _e36;
    } else {
        let _e43 = accum[index];
        accum[index] = (_e43 + _e36);
    }
    if (_e38 > 0u) {
        atomicAdd((&counters[0]), _e38);
    }
    return PassSum(vec3(0f), 0u);
}

fn render_pixel(pixel_5: vec2<u32>) {
    var sums: PassSum;
    var s_5: u32;

    let frame_6 = frame;
    let tile_2 = tile;
    let index_1 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    let per_pass_1 = frame_6.samples_per_pass;
    let first_1 = (tile_2.frame * per_pass_1);
    let count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = PassSum(vec3(0f), 0u);
    s_5 = 0u;
    loop {
        let _e25 = s_5;
        if (_e25 >= count_2) {
            break;
        }
        let _e27 = sums;
        let _e28 = s_5;
        let _e30 = sample_camera_ray(pixel_5, (first_1 + _e28));
        let _e31 = trace(_e30);
        let _e32 = s_5;
        let _e34 = add_sample(_e27, _e31, _e32, index_1, tile_2.frame, per_pass_1);
        sums = _e34;
        continuing {
            let _e35 = s_5;
            s_5 = (_e35 + 1u);
        }
    }
    return;
}

fn render_invocation(id_1: vec2<u32>) {
    let tile_3 = tile;
    let _e3 = scattered_local(id_1);
    if any((_e3 >= tile_3.extent)) {
        return;
    }
    render_pixel((tile_3.origin + _e3));
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn render(@builtin(global_invocation_id) gid: vec3<u32>) {
    render_invocation(vec2<u32>(gid.x, gid.y));
    return;
}
