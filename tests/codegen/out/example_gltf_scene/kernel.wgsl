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

struct Triangle {
    v0_: vec3<f32>,
    v1_: vec3<f32>,
    v2_: vec3<f32>,
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

struct GltfMaskedMaterial {
    base_color: vec4<f32>,
    base_texture: u32,
    metallic: f32,
    roughness: f32,
    emissive: vec3<f32>,
    alpha_cutoff: f32,
    blend: u32,
    double_sided: u32,
}

struct SkyGradient {
    zenith: vec3<f32>,
    horizon: vec3<f32>,
    ground: vec3<f32>,
}

struct LightSample {
    dir: vec3<f32>,
    dist: f32,
    radiance: vec3<f32>,
    pdf: f32,
}

struct DirectionalLight {
    direction: vec3<f32>,
    color: vec3<f32>,
    intensity: f32,
}

struct PointLight {
    position: vec3<f32>,
    color: vec3<f32>,
    intensity: f32,
    range: f32,
    inner_range: f32,
}

struct GltfMaterial {
    base_color: vec4<f32>,
    base_texture: u32,
    metallic: f32,
    roughness: f32,
    emissive: vec3<f32>,
}

struct Frame {
    ray: Ray,
    hit: Hit,
    error: f32,
    slot: u32,
    sum: vec3<f32>,
    dirs: array<vec3<f32>, 1>,
    weights: array<vec3<f32>, 1>,
    count: u32,
    next: u32,
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
const HAS_ANY_HIT: bool = true;
const FLAG_CULL_BACK: u32 = 8u;
const RAY_SHADOW: u32 = 2u;
const FLAG_ANY_HIT: u32 = 1u;
const POINT_ERROR: f32 = 0.0000019073486f;
const GAMMA_1_: f32 = 0.00000005960465f;
const GAMMA_6_: f32 = 0.0000003576281f;
const GAMMA_4_: f32 = 0.00000023841864f;
const TEXTURE_WRAP_MASK: u32 = 3u;
const TEXTURE_WRAP_V_SHIFT: u32 = 2u;
const TEXTURE_NEAREST: u32 = 16u;
const TEXTURE_WRAP_MIRROR: u32 = 2u;
const TEXTURE_WRAP_CLAMP: u32 = 1u;
const TEXTURE_FORMAT_RGBA8_SRGB: u32 = 0u;
const TEXTURE_FORMAT_RGBA8_UNORM: u32 = 2u;
const RGBA16F_TEXEL_WORDS: u32 = 2u;
const BLAS_STACK: u32 = 64u;
const TLAS_STACK: u32 = 64u;
const HAS_SECONDARY_RAYS: bool = false;
const HAS_BACKGROUND: bool = true;
const PBR_MIN_ALPHA: f32 = 0.001f;
const LIGHT_ENTRY_STRIDE: u32 = 2u;
const SCRATCH_RESOLVED: u32 = 3u;
const SCRATCH_LIGHT_BITS: u32 = 11u;
const SCRATCH_QUERY: u32 = 2u;
const SCRATCH_PENDING: u32 = 4u;
const SCRATCH_SHADOW_MODE: u32 = 14u;
const SHADOW_UNOCCLUDED: u32 = 1u;
const SHADOW_ABOVE: u32 = 2u;
const LIGHT_QUERIES: u32 = 32u;
const COUNTER_SHADOW_OVERFLOW: u32 = 3u;
const SCRATCH_LIGHT_QUERY: u32 = 15u;
const LIGHT_ERROR: f32 = 0.00000047683716f;
const INV_PI: f32 = 0.31830987f;
const FLAG_MEDIUM: u32 = 4u;
const FLAG_SECONDARY_RAYS: u32 = 2u;
const MAX_DEPTH: u32 = 4u;
const STACK_SIZE: u32 = 4u;
const MAX_SPAWN: u32 = 1u;
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
var<private> hit_error: f32;
@group(0) @binding(5) 
var<storage> attributes: array<vec4<u32>>;
@group(0) @binding(7) 
var<storage> texels: array<u32>;
var<private> traversal_stack: array<u32, 128>;
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
    let i_7 = reverseBits(_e24);
    x_2 = i_7;
    if ((d & 1u) != 0u) {
        let _e31 = sobol_second_reversed(i_7);
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
    let h_1 = tan((radians(cam.fov) * 0.5f));
    let aspect = (size_1.x / size_1.y);
    let _e48 = normalize_vec3f(((_e24 + (_e27 * vec3(((ndc.x * h_1) * aspect)))) - (up * vec3((ndc.y * h_1)))));
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
    let m_3 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    let e = min(max(((bitcast<u32>(m_3) >> 23u) & 255u), 1u), 253u);
    let d_3 = (ray_2.dir * vec3(bitcast<f32>(((254u - e) << 23u))));
    let unit = bitcast<f32>((e << 23u));
    let floor_ = vec3(0.0000000000009094947f);
    let s_3 = select(vec3(1f), vec3(-1f), (d_3 < vec3(0f)));
    let inv = (vec3(1f) / select(d_3, (s_3 * floor_), (abs(d_3) < floor_)));
    let rel = (origin_2 - ray_2.origin);
    let start = (rel * inv);
    let pad = (((vec3(0.0000009536743f) * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_3);
    return BoxRay((header_1.max * inv), (start - pad), (start + pad), (ray_2.tmin * unit), unit);
}

fn hit_triangle(r_1: TriangleRay, slot: u32, tmin: f32, tmax_1: f32, occlusion: bool) -> vec3<f32> {
    let _e9 = triangles[(slot * 3u)];
    let a_5 = (_e9.xyz - r_1.origin);
    let _e19 = triangles[((slot * 3u) + 1u)];
    let b_8 = (_e19.xyz - r_1.origin);
    let _e29 = triangles[((slot * 3u) + 2u)];
    let c_9 = (_e29.xyz - r_1.origin);
    let ax = (a_5[min(r_1.kx, 2u)] - (r_1.shear.x * a_5[min(r_1.kz, 2u)]));
    let ay = (a_5[min(r_1.ky, 2u)] - (r_1.shear.y * a_5[min(r_1.kz, 2u)]));
    let bx = (b_8[min(r_1.kx, 2u)] - (r_1.shear.x * b_8[min(r_1.kz, 2u)]));
    let by = (b_8[min(r_1.ky, 2u)] - (r_1.shear.y * b_8[min(r_1.kz, 2u)]));
    let cx = (c_9[min(r_1.kx, 2u)] - (r_1.shear.x * c_9[min(r_1.kz, 2u)]));
    let cy = (c_9[min(r_1.ky, 2u)] - (r_1.shear.y * c_9[min(r_1.kz, 2u)]));
    let u = ((cx * by) - (cy * bx));
    let v_3 = ((ax * cy) - (ay * cx));
    let w = ((bx * ay) - (by * ax));
    let outside = ((((u < 0f) || (v_3 < 0f)) || (w < 0f)) && (((u > 0f) || (v_3 > 0f)) || (w > 0f)));
    let det = ((u + v_3) + w);
    let scaled = (((u * (r_1.shear.z * a_5[min(r_1.kz, 2u)])) + (v_3 * (r_1.shear.z * b_8[min(r_1.kz, 2u)]))) + (w * (r_1.shear.z * c_9[min(r_1.kz, 2u)])));
    if occlusion {
        let st = select(scaled, -(scaled), (det < 0f));
        let ad_1 = abs(det);
        let hit_13 = ((((r_1.valid && !(outside)) && !((det == 0f))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        let _e178 = F32_INF;
        return select(vec3<f32>(bitcast<f32>(_e178), 0f, 0f), vec3<f32>(tmin, 0f, 0f), hit_13);
    }
    let rcp = (1f / det);
    let t_6 = (scaled * rcp);
    let hit_14 = ((((r_1.valid && !(outside)) && !((det == 0f))) && (t_6 >= tmin)) && (t_6 <= tmax_1));
    let _e202 = F32_INF;
    return select(vec3<f32>(bitcast<f32>(_e202), 0f, 0f), vec3<f32>(t_6, (v_3 * rcp), (w * rcp)), hit_14);
}

fn load_triangle(slot_1: u32) -> Triangle {
    let v0_1 = triangles[(slot_1 * 3u)];
    let v1_ = triangles[((slot_1 * 3u) + 1u)];
    let v2_ = triangles[((slot_1 * 3u) + 2u)];
    return Triangle(v0_1.xyz, v1_.xyz, v2_.xyz);
}

fn normal_to_world(inst_1: GpuInstance, n: vec3<f32>) -> vec3<f32> {
    let w_1 = (((inst_1.world_to_object_0_.xyz * vec3(n.x)) + (inst_1.world_to_object_1_.xyz * vec3(n.y))) + (inst_1.world_to_object_2_.xyz * vec3(n.z)));
    let _e19 = normalize_vec3f(w_1);
    return _e19;
}

fn single_sided_seen_front(ray_3: Ray, front_face: bool) -> bool {
    return (front_face != (ray_3.kind == RAY_SHADOW));
}

fn culled(inst_2: GpuInstance, ray_4: Ray, c: Candidate) -> bool {
    let _e4 = load_triangle(c.primitive);
    let _e12 = normal_to_world(inst_2, cross((_e4.v1_ - _e4.v0_), (_e4.v2_ - _e4.v0_)));
    let _e17 = single_sided_seen_front(ray_4, (dot(ray_4.dir, _e12) < 0f));
    return !(_e17);
}

fn point_error(origin_1: vec3<f32>, along: vec3<f32>) -> f32 {
    let a_6 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_6.x, a_6.y), a_6.z));
}

fn point_to_world(inst_3: GpuInstance, p: vec3<f32>) -> vec3<f32> {
    let q_1 = vec4<f32>(p, 1f);
    return vec3<f32>(dot(inst_3.object_to_world_0_, q_1), dot(inst_3.object_to_world_1_, q_1), dot(inst_3.object_to_world_2_, q_1));
}

fn mesh_error(inst_4: GpuInstance, v0_: vec3<f32>, db1_: vec3<f32>, db2_: vec3<f32>, p_1: vec3<f32>) -> f32 {
    let obj = ((vec3(GAMMA_1_) * abs(v0_)) + (vec3(GAMMA_6_) * (abs(db1_) + abs(db2_))));
    let q_2 = vec4<f32>(abs(p_1), 1f);
    let r0_ = abs(inst_4.object_to_world_0_);
    let r1_ = abs(inst_4.object_to_world_1_);
    let r2_ = abs(inst_4.object_to_world_2_);
    let rounding = (vec3(GAMMA_4_) * vec3<f32>(dot(r0_, q_2), dot(r1_, q_2), dot(r2_, q_2)));
    let carried = (vec3((1f + GAMMA_4_)) * vec3<f32>(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_.xyz, obj)));
    let e_1 = (rounding + carried);
    return max(max(e_1.x, e_1.y), e_1.z);
}

fn decode_octahedral(bits: u32) -> vec3<f32> {
    var n_1: vec3<f32>;

    let e_2 = unpack2x16snorm(bits);
    n_1 = vec3<f32>(e_2.x, e_2.y, ((1f - abs(e_2.x)) - abs(e_2.y)));
    let _e14 = n_1.z;
    if (_e14 < 0f) {
        let _e21 = n_1;
        let s_4 = select(vec2(-1f), vec2(1f), (_e21.xy >= vec2(0f)));
        let _e29 = n_1;
        let xy = ((vec2(1f) - abs(_e29.yx)) * s_4);
        let _e37 = n_1.z;
        n_1 = vec3<f32>(xy.x, xy.y, _e37);
    }
    let _e39 = n_1;
    let _e40 = normalize_vec3f(_e39);
    return _e40;
}

fn finish_hit(ray_5: Ray, c_1: Candidate) -> Hit {
    var hit: Hit;
    var n_geo: vec3<f32>;
    var n_shade: vec3<f32>;

    let inst_7 = instances[c_1.slot];
    let _e11 = point_error(ray_5.origin, (ray_5.dir * vec3(c_1.t)));
    hit_error = _e11;
    hit = Hit((ray_5.origin + (ray_5.dir * vec3(c_1.t))), c_1.t, vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 1f, 0f), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if (inst_7.geometry_type == MESH_GEOMETRY) {
        let _e42 = load_triangle(c_1.primitive);
        let b_9 = c_1.uv;
        let w_2 = ((1f - b_9.x) - b_9.y);
        let e1_ = (_e42.v1_ - _e42.v0_);
        let e2_ = (_e42.v2_ - _e42.v0_);
        let p_7 = (_e42.v0_ + ((e1_ * vec3(b_9.x)) + (e2_ * vec3(b_9.y))));
        let _e65 = point_to_world(inst_7, p_7);
        hit.position = _e65;
        let _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * vec3(b_9.x)), (e2_ * vec3(b_9.y)), p_7);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        let a0_ = attributes[(c_1.primitive * 2u)];
        let a1_ = attributes[((c_1.primitive * 2u) + 1u)];
        let _e91 = decode_octahedral(a0_.x);
        let _e95 = decode_octahedral(a0_.y);
        let _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * vec3(w_2)) + (_e95 * vec3(b_9.x))) + (_e101 * vec3(b_9.y)));
        let _e106 = n_shade;
        let _e107 = n_shade;
        if (dot(_e106, _e107) < 0.000000000001f) {
            let _e111 = n_geo;
            n_shade = _e111;
        }
        let uv0_ = unpack2x16float(a0_.w);
        let uv1_ = unpack2x16float(a1_.x);
        let uv2_ = unpack2x16float(a1_.y);
        hit.uv = (((uv0_ * vec2(w_2)) + (uv1_ * vec2(b_9.x))) + (uv2_ * vec2(b_9.y)));
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
    hit.front_face = (dot(ray_5.dir, _e147) < 0f);
    let _e151 = hit;
    return _e151;
}

fn load_GltfMaskedMaterial(offset_2: u32) -> GltfMaskedMaterial {
    let _e5 = params[(offset_2 + 0u)];
    let _e11 = params[(offset_2 + 1u)];
    let _e17 = params[(offset_2 + 2u)];
    let _e23 = params[(offset_2 + 3u)];
    let _e30 = params[(offset_2 + 4u)];
    let _e35 = params[(offset_2 + 5u)];
    let _e41 = params[(offset_2 + 6u)];
    let _e47 = params[(offset_2 + 8u)];
    let _e53 = params[(offset_2 + 9u)];
    let _e59 = params[(offset_2 + 10u)];
    let _e66 = params[(offset_2 + 11u)];
    let _e72 = params[(offset_2 + 12u)];
    let _e77 = params[(offset_2 + 13u)];
    return GltfMaskedMaterial(vec4<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17), bitcast<f32>(_e23)), _e30, bitcast<f32>(_e35), bitcast<f32>(_e41), vec3<f32>(bitcast<f32>(_e47), bitcast<f32>(_e53), bitcast<f32>(_e59)), bitcast<f32>(_e66), _e72, _e77);
}

fn i32_from_f32_(x_3: f32) -> i32 {
    return select(i32(min(max(x_3, -2147483600f), 2147483500f)), 0i, ((bitcast<u32>(x_3) & 2147483647u) > 2139095040u));
}

fn rem_i32_(a_4: i32, b_4: i32) -> i32 {
    let by_zero_4 = (b_4 == 0i);
    let divisor_4 = select(select(b_4, 1i, by_zero_4), 1i, ((a_4 == i32(-2147483648)) & (b_4 == -1i)));
    return select((a_4 - (divisor_4 * (a_4 / divisor_4))), 0i, by_zero_4);
}

fn wrap_texel_pair(x_4: i32, n_2: i32, mode: u32) -> vec2<i32> {
    var m0_: i32;

    let period = (2i * n_2);
    let _e5 = rem_i32_(x_4, period);
    m0_ = _e5;
    let _e7 = m0_;
    let _e8 = m0_;
    let _e10 = m0_;
    m0_ = select(_e7, (_e8 + period), (_e10 < 0i));
    let _e14 = m0_;
    let _e18 = m0_;
    let m1_ = select((_e14 + 1i), 0i, ((_e18 + 1i) == period));
    let _e23 = m0_;
    let _e24 = m0_;
    let _e26 = m0_;
    let r0_1 = select(_e23, (_e24 - n_2), (_e26 >= n_2));
    let r1_1 = select(m1_, (m1_ - n_2), (m1_ >= n_2));
    let _e32 = m0_;
    let _e35 = m0_;
    let _e37 = m0_;
    let mirror = vec2<i32>(select(_e32, ((period - 1i) - _e35), (_e37 >= n_2)), select(m1_, ((period - 1i) - m1_), (m1_ >= n_2)));
    let wrapped = select(vec2<i32>(r0_1, r1_1), mirror, (mode == TEXTURE_WRAP_MIRROR));
    return select(wrapped, min(max(vec2<i32>(x_4, (x_4 + 1i)), vec2(0i)), vec2((n_2 - 1i))), (mode == TEXTURE_WRAP_CLAMP));
}

fn srgb_channel(c_2: f32) -> f32 {
    if (c_2 <= 0.04045f) {
        return (c_2 / 12.92f);
    }
    return pow(((c_2 + 0.055f) / 1.055f), 2.4f);
}

fn texel_at(t: u32, xi: u32, yi: u32) -> vec4<f32> {
    let base_1 = params[t];
    let _e10 = params[(t + 1u)];
    let index_1 = ((yi * max(_e10, 1u)) + xi);
    let format = params[(t + 3u)];
    if (format == TEXTURE_FORMAT_RGBA8_SRGB) {
        let _e25 = texels[(base_1 + index_1)];
        let c_10 = unpack4x8unorm(_e25);
        let _e28 = srgb_channel(c_10.x);
        let _e30 = srgb_channel(c_10.y);
        let _e32 = srgb_channel(c_10.z);
        return vec4<f32>(_e28, _e30, _e32, c_10.w);
    }
    if (format == TEXTURE_FORMAT_RGBA8_UNORM) {
        let _e40 = texels[(base_1 + index_1)];
        return unpack4x8unorm(_e40);
    }
    let _e47 = texels[(base_1 + (index_1 * RGBA16F_TEXEL_WORDS))];
    let rg = unpack2x16float(_e47);
    let _e56 = texels[((base_1 + (index_1 * RGBA16F_TEXEL_WORDS)) + 1u)];
    let ba = unpack2x16float(_e56);
    return vec4<f32>(rg, ba);
}

fn sample_texture(t_1: u32, uv: vec2<f32>) -> vec4<f32> {
    let _e6 = params[(t_1 + 1u)];
    let wi = i32(max(_e6, 1u));
    let _e14 = params[(t_1 + 2u)];
    let hi_1 = i32(max(_e14, 1u));
    let sampler_ = params[(t_1 + 4u)];
    let mu = (sampler_ & TEXTURE_WRAP_MASK);
    let mv = ((sampler_ >> (TEXTURE_WRAP_V_SHIFT & 31u)) & TEXTURE_WRAP_MASK);
    let q_3 = (uv * vec2<f32>(f32(wi), f32(hi_1)));
    let p_8 = select((q_3 - vec2(0.5f)), floor(q_3), ((sampler_ & TEXTURE_NEAREST) != 0u));
    let f_2 = floor(p_8);
    let fr = (p_8 - f_2);
    let _e47 = i32_from_f32_(f_2.x);
    let _e49 = i32_from_f32_(f_2.y);
    let _e50 = wrap_texel_pair(_e47, wi, mu);
    let xs = vec2<u32>(_e50);
    let _e52 = wrap_texel_pair(_e49, hi_1, mv);
    let ys = vec2<u32>(_e52);
    let x0_ = xs.x;
    let x1_ = xs.y;
    let y0_ = ys.x;
    let y1_ = ys.y;
    let _e58 = texel_at(t_1, x0_, y0_);
    let _e59 = texel_at(t_1, x1_, y0_);
    let a_7 = mix(_e58, _e59, vec4(fr.x));
    let _e63 = texel_at(t_1, x0_, y1_);
    let _e64 = texel_at(t_1, x1_, y1_);
    let b_10 = mix(_e63, _e64, vec4(fr.x));
    return mix(a_7, b_10, vec4(fr.y));
}

fn frame_index_query() -> u32 {
    let _e5 = scratch[min(SCRATCH_RNG_INDEX, 24u)];
    let _e7 = frame;
    let _e9 = div_u32_(_e5, _e7.samples_per_pass);
    return _e9;
}

fn gltf_pcg(x_5: u32) -> u32 {
    let state_2 = ((x_5 * 747796405u) + 2891336453u);
    let word_1 = (((state_2 >> (((state_2 >> 28u) + 4u) & 31u)) ^ state_2) * 277803737u);
    return ((word_1 >> 22u) ^ word_1);
}

fn gltf_coverage(ray_6: Ray, hit_1: Hit) -> f32 {
    var h: u32;

    let o_1 = bitcast<vec3<u32>>(ray_6.origin);
    let d_4 = bitcast<vec3<u32>>(ray_6.dir);
    h = (((o_1.x ^ (o_1.y * 2654435769u)) ^ (o_1.z * 2246822507u)) ^ (d_4.x * 3266489909u));
    let _e20 = h;
    h = (((_e20 ^ (d_4.y * 668265263u)) ^ (d_4.z * 374761393u)) ^ (hit_1.primitive * 3550635116u));
    let _e33 = h;
    let _e38 = frame_index_query();
    h = ((_e33 ^ (hit_1.instance * 4251993797u)) ^ (_e38 * 3042594569u));
    let _e42 = h;
    let _e43 = gltf_pcg(_e42);
    let _e44 = gltf_pcg(_e43);
    h = _e44;
    let _e45 = h;
    return (f32((_e45 >> 8u)) * (1f / 16777216f));
}

fn gltf_counts(alpha: f32, cutoff: f32, blend: u32, double_sided: u32, ray_7: Ray, hit_2: Hit) -> bool {
    if ((double_sided == 0u) && (hit_2.front_face == (ray_7.kind == RAY_SHADOW))) {
        return false;
    }
    if (blend != 0u) {
        let _e17 = gltf_coverage(ray_7, hit_2);
        return (_e17 < alpha);
    }
    return (alpha >= cutoff);
}

fn gltf_masked_any_hit(m: GltfMaskedMaterial, ray_8: Ray, hit_3: Hit) -> bool {
    let _e7 = sample_texture(m.base_texture, hit_3.uv);
    let alpha_1 = (m.base_color.w * _e7.w);
    let _e13 = gltf_counts(alpha_1, m.alpha_cutoff, m.blend, m.double_sided, ray_8, hit_3);
    return _e13;
}

fn dispatch_any_hit(type_id_1: u32, offset_3: u32, ray_9: Ray, hit_4: Hit) -> bool {
    let _e3 = load_GltfMaskedMaterial(offset_3);
    let _e4 = gltf_masked_any_hit(_e3, ray_9, hit_4);
    return _e4;
}

fn accept(inst_5: GpuInstance, ray_10: Ray, c_3: Candidate) -> bool {
    var short_circuit: bool;

    let _e7 = ((inst_5.flags & FLAG_CULL_BACK) != 0u);
    short_circuit = _e7;
    if _e7 {
        let _e9 = culled(inst_5, ray_10, c_3);
        short_circuit = _e9;
    }
    let _e10 = short_circuit;
    if _e10 {
        return false;
    }
    if ((inst_5.flags & FLAG_ANY_HIT) != 0u) {
        let shaded = hit_error;
        let _e19 = finish_hit(ray_10, c_3);
        hit_error = shaded;
        let _e23 = dispatch_any_hit(inst_5.material_type, inst_5.material_offset, ray_10, _e19);
        return _e23;
    }
    return true;
}

fn node_box_lo(p_2: vec3<u32>) -> vec3<u32> {
    return vec3<u32>((p_2.x & 65535u), (p_2.x >> 16u), (p_2.y & 65535u));
}

fn node_box_hi(p_3: vec3<u32>) -> vec3<u32> {
    return vec3<u32>((p_3.y >> 16u), (p_3.z & 65535u), (p_3.z >> 16u));
}

fn slab_in_frame(lo: vec3<f32>, hi: vec3<f32>, b_5: BoxRay, tmax_2: f32) -> f32 {
    let t0_ = fma(lo, b_5.step, b_5.start_lo);
    let t1_ = fma(hi, b_5.step, b_5.start_hi);
    let flip_1 = (bitcast<vec3<i32>>(b_5.step) < vec3(0i));
    let near_2 = select(t0_, t1_, flip_1);
    let far_2 = select(t1_, t0_, flip_1);
    let e_3 = select(near_2.xy, near_2.yz, (near_2.xy < near_2.yz));
    let enter = select(e_3.x, e_3.y, (e_3.x < e_3.y));
    let x_8 = select(far_2.xy, far_2.yz, (far_2.yz < far_2.xy));
    let exit = select(x_8.x, x_8.y, (x_8.y < x_8.x));
    let enter_t = select(enter, b_5.tmin, (enter < b_5.tmin));
    let exit_t = select(exit, tmax_2, (tmax_2 < exit));
    if (enter_t <= exit_t) {
        return enter_t;
    }
    let _e49 = F32_INF;
    return bitcast<f32>(_e49);
}

fn children_entry(n_3: GpuNode, b_6: BoxRay, tmax_3: f32) -> vec2<f32> {
    let lq = bitcast<vec3<u32>>(n_3.min);
    let rq = bitcast<vec3<u32>>(n_3.max);
    let t_7 = (tmax_3 * b_6.unit);
    let _e9 = node_box_lo(lq);
    let _e11 = node_box_hi(lq);
    let _e13 = slab_in_frame(vec3<f32>(_e9), vec3<f32>(_e11), b_6, t_7);
    let _e14 = node_box_lo(rq);
    let _e16 = node_box_hi(rq);
    let _e18 = slab_in_frame(vec3<f32>(_e14), vec3<f32>(_e16), b_6, t_7);
    return vec2<f32>(_e13, _e18);
}

fn pop(base: u32, sp: u32) -> vec2<u32> {
    if (sp == 0u) {
        return vec2<u32>(NO_HIT, 0u);
    }
    let _e14 = traversal_stack[min(((base + sp) - 1u), 127u)];
    return vec2<u32>(_e14, (sp - 1u));
}

fn intersect_mesh(inst_6: GpuInstance, slot_2: u32, world_ray: Ray, ray_11: Ray, best_in: Candidate, shadow: bool) -> Candidate {
    var best: Candidate;
    var sp_1: u32;
    var child: u32;
    var k: u32;
    var near: u32;
    var far: u32;

    best = best_in;
    let _e7 = prepare_triangle_ray(ray_11);
    let base_2 = inst_6.blas_root;
    let header_2 = nodes[base_2];
    let _e12 = box_ray(header_2, ray_11);
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
                let prim = ((inst_6.triangle_offset + first) + _e38);
                let _e42 = best.t;
                let _e46 = hit_triangle(_e7, prim, ray_11.tmin, _e42, (shadow && !(HAS_ANY_HIT)));
                let _e49 = F32_INF;
                if (_e46.x < bitcast<f32>(_e49)) {
                    let _e58 = triangles[((prim * 3u) + 1u)];
                    let tag = bitcast<u32>(_e58.w);
                    let owner = select(slot_2, ((inst_6.object + tag) - 1u), (tag != 0u));
                    let c_11 = Candidate(_e46.x, owner, prim, _e46.yz, vec3(0f));
                    let _e73 = accept(inst_6, world_ray, c_11);
                    if _e73 {
                        best = c_11;
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
            let n_7 = nodes[(base_2 + _e78)];
            let _e84 = best.t;
            let _e85 = children_entry(n_7, _e12, _e84);
            let tl = _e85.x;
            let tr = _e85.y;
            let _e89 = F32_INF;
            let _e93 = F32_INF;
            if ((tl < bitcast<f32>(_e89)) && (tr < bitcast<f32>(_e93))) {
                near = n_7.a;
                far = n_7.b;
                if ((tr < tl) != shadow) {
                    near = n_7.b;
                    far = n_7.a;
                }
                let _e105 = sp_1;
                if (_e105 < BLAS_STACK) {
                    let _e109 = sp_1;
                    let _e111 = far;
                    traversal_stack[min((TLAS_STACK + _e109), 127u)] = _e111;
                    let _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                let _e119 = near;
                child = _e119;
                continue;
            }
            let _e121 = F32_INF;
            if (tl < bitcast<f32>(_e121)) {
                child = n_7.a;
                continue;
            }
            let _e126 = F32_INF;
            if (tr < bitcast<f32>(_e126)) {
                child = n_7.b;
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

fn intersect_object(slot_3: u32, ray_12: Ray, best_1: Candidate, shadow_1: bool) -> Candidate {
    var r_2: Ray;

    let inst_8 = instances[slot_3];
    let _e7 = to_object(inst_8, ray_12);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_8.geometry_type == MESH_GEOMETRY) {
        let _e14 = r_2;
        let _e15 = intersect_mesh(inst_8, slot_3, ray_12, _e14, best_1, shadow_1);
        return _e15;
    }
    return best_1;
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
    var ray_13: Ray;

    let frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    let _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_13 = _e7;
    ray_13.depth = 0u;
    ray_13.kind = RAY_CAMERA;
    let _e15 = ray_13.origin;
    let _e17 = medium_at(_e15, NO_HIT);
    ray_13.medium = _e17;
    let _e18 = ray_13;
    return _e18;
}

fn node_frame_bounds() -> vec3<f32> {
    return vec3(65535f);
}

fn intersect_scene(ray_14: Ray, shadow_2: bool) -> Candidate {
    var best_2: Candidate;
    var sp_2: u32;
    var child_1: u32;
    var near_1: u32;
    var far_1: u32;

    let _e3 = ray_count;
    ray_count = (_e3 + 1u);
    let _e7 = no_candidate(ray_14.tmax);
    best_2 = _e7;
    let frame_3 = frame;
    if (frame_3.instance_count == 0u) {
        let _e14 = best_2;
        return _e14;
    }
    let base_3 = frame_3.tlas_root;
    let header_3 = nodes[base_3];
    let _e19 = box_ray(header_3, ray_14);
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
                let _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_14, _e54, shadow_2);
                best_2 = _e55;
                let _e57 = best_2.slot;
                if (shadow_2 && (_e57 != NO_HIT)) {
                    let _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            let _e62 = child_1;
            let n_8 = nodes[(base_3 + _e62)];
            let _e68 = best_2.t;
            let _e69 = children_entry(n_8, _e19, _e68);
            let tl_1 = _e69.x;
            let tr_1 = _e69.y;
            let _e73 = F32_INF;
            let _e77 = F32_INF;
            if ((tl_1 < bitcast<f32>(_e73)) && (tr_1 < bitcast<f32>(_e77))) {
                near_1 = n_8.a;
                far_1 = n_8.b;
                if (tr_1 < tl_1) {
                    near_1 = n_8.b;
                    far_1 = n_8.a;
                }
                let _e88 = sp_2;
                if (_e88 < TLAS_STACK) {
                    let _e91 = sp_2;
                    let _e92 = far_1;
                    traversal_stack[min(_e91, 127u)] = _e92;
                    let _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                let _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            let _e102 = F32_INF;
            if (tl_1 < bitcast<f32>(_e102)) {
                child_1 = n_8.a;
                continue;
            }
            let _e107 = F32_INF;
            if (tr_1 < bitcast<f32>(_e107)) {
                child_1 = n_8.b;
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

fn load_SkyGradient(offset_4: u32) -> SkyGradient {
    let _e5 = params[(offset_4 + 0u)];
    let _e11 = params[(offset_4 + 1u)];
    let _e17 = params[(offset_4 + 2u)];
    let _e24 = params[(offset_4 + 4u)];
    let _e30 = params[(offset_4 + 5u)];
    let _e36 = params[(offset_4 + 6u)];
    let _e43 = params[(offset_4 + 8u)];
    let _e49 = params[(offset_4 + 9u)];
    let _e55 = params[(offset_4 + 10u)];
    return SkyGradient(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), vec3<f32>(bitcast<f32>(_e24), bitcast<f32>(_e30), bitcast<f32>(_e36)), vec3<f32>(bitcast<f32>(_e43), bitcast<f32>(_e49), bitcast<f32>(_e55)));
}

fn sky_gradient(b_7: SkyGradient, ray_15: Ray) -> vec3<f32> {
    let _e3 = normalize_vec3f(ray_15.dir);
    let y = _e3.y;
    if (y < 0f) {
        return mix(b_7.horizon, b_7.ground, vec3(min((-(y) * 4f), 1f)));
    }
    return mix(b_7.horizon, b_7.zenith, vec3(sqrt(y)));
}

fn dispatch_miss(type_id_2: u32, offset_5: u32, ray_16: Ray) -> vec3<f32> {
    let _e2 = load_SkyGradient(offset_5);
    let _e3 = sky_gradient(_e2, ray_16);
    return _e3;
}

fn miss(ray_17: Ray) -> vec3<f32> {
    if !(HAS_BACKGROUND) {
        return vec3(0f);
    }
    let frame_4 = frame;
    let _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_17);
    return _e9;
}

fn shading_normal(ray_18: Ray, hit_5: Hit) -> vec3<f32> {
    let ng = faceForward(hit_5.geometric_normal, ray_18.dir, hit_5.geometric_normal);
    return faceForward(hit_5.normal, -(ng), hit_5.normal);
}

fn pbr_alpha2_(roughness: f32) -> f32 {
    let a_8 = max((saturate(roughness) * saturate(roughness)), PBR_MIN_ALPHA);
    return (a_8 * a_8);
}

fn light_count_query() -> u32 {
    let _e1 = frame;
    return _e1.light_count;
}

fn load_DirectionalLight(offset_6: u32) -> DirectionalLight {
    let _e5 = params[(offset_6 + 0u)];
    let _e11 = params[(offset_6 + 1u)];
    let _e17 = params[(offset_6 + 2u)];
    let _e24 = params[(offset_6 + 4u)];
    let _e30 = params[(offset_6 + 5u)];
    let _e36 = params[(offset_6 + 6u)];
    let _e43 = params[(offset_6 + 7u)];
    return DirectionalLight(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), vec3<f32>(bitcast<f32>(_e24), bitcast<f32>(_e30), bitcast<f32>(_e36)), bitcast<f32>(_e43));
}

fn shadow_preset(normal: vec3<f32>, dir: vec3<f32>) -> f32 {
    let mode_1 = scratch[min(SCRATCH_SHADOW_MODE, 24u)];
    if (mode_1 == SHADOW_UNOCCLUDED) {
        return 1f;
    }
    if ((mode_1 == SHADOW_ABOVE) && !((dot(dir, normal) > 0f))) {
        return 0f;
    }
    return -1f;
}

fn scratch_store3f(i_2: u32, v_2: vec3<f32>) {
    let b_11 = bitcast<vec3<u32>>(v_2);
    scratch[min(i_2, 24u)] = b_11.x;
    scratch[min((i_2 + 1u), 24u)] = b_11.y;
    scratch[min((i_2 + 2u), 24u)] = b_11.z;
    return;
}

fn shadow_deferred(position: vec3<f32>, normal_1: vec3<f32>, dir_1: vec3<f32>, dist: f32) -> f32 {
    let _e4 = shadow_preset(normal_1, dir_1);
    if (_e4 >= 0f) {
        return _e4;
    }
    let i_8 = scratch[min(SCRATCH_QUERY, 24u)];
    scratch[min(SCRATCH_QUERY, 24u)] = (i_8 + 1u);
    let _e25 = scratch[min(SCRATCH_RESOLVED, 24u)];
    if (i_8 < _e25) {
        let _e32 = scratch[min(SCRATCH_LIGHT_BITS, 24u)];
        return f32(((_e32 >> (i_8 & 31u)) & 1u));
    }
    let _e44 = scratch[min(SCRATCH_PENDING, 24u)];
    if (_e44 != 0u) {
        return 1f;
    }
    if (i_8 >= LIGHT_QUERIES) {
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

fn directional_light(l: DirectionalLight, position_1: vec3<f32>, normal_2: vec3<f32>) -> LightSample {
    let _e4 = normalize_vec3f(l.direction);
    let dir_6 = -(_e4);
    if (dot(dir_6, dir_6) == 0f) {
        let _e14 = F32_INF;
        return LightSample(vec3<f32>(0f, 1f, 0f), bitcast<f32>(_e14), vec3(0f), 0f);
    }
    let _e21 = F32_INF;
    let _e23 = shadow_deferred(position_1, normal_2, dir_6, bitcast<f32>(_e21));
    let _e25 = F32_INF;
    return LightSample(dir_6, bitcast<f32>(_e25), ((l.color * vec3(l.intensity)) * vec3(_e23)), 0f);
}

fn load_PointLight(offset_7: u32) -> PointLight {
    let _e5 = params[(offset_7 + 0u)];
    let _e11 = params[(offset_7 + 1u)];
    let _e17 = params[(offset_7 + 2u)];
    let _e24 = params[(offset_7 + 4u)];
    let _e30 = params[(offset_7 + 5u)];
    let _e36 = params[(offset_7 + 6u)];
    let _e43 = params[(offset_7 + 7u)];
    let _e49 = params[(offset_7 + 8u)];
    let _e55 = params[(offset_7 + 9u)];
    return PointLight(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)), vec3<f32>(bitcast<f32>(_e24), bitcast<f32>(_e30), bitcast<f32>(_e36)), bitcast<f32>(_e43), bitcast<f32>(_e49), bitcast<f32>(_e55));
}

fn point_light(l_1: PointLight, position_2: vec3<f32>, normal_3: vec3<f32>) -> LightSample {
    var strength: f32;

    let to_light = (l_1.position - position_2);
    let dist_3 = length(to_light);
    let dir_7 = (to_light / vec3(max(dist_3, 0.00000000000000000001f)));
    strength = (l_1.intensity / max((dist_3 * dist_3), 0.00000000000000000001f));
    if (l_1.range > 0f) {
        let _e19 = strength;
        strength = (_e19 * (1f - smoothstep(l_1.inner_range, l_1.range, dist_3)));
    }
    let _e26 = shadow_deferred(position_2, normal_3, dir_7, dist_3);
    let _e28 = strength;
    return LightSample(dir_7, dist_3, ((l_1.color * vec3(_e28)) * vec3(_e26)), 0f);
}

fn dispatch_light(type_id_3: u32, offset_8: u32, position_3: vec3<f32>, normal_4: vec3<f32>) -> LightSample {
    switch type_id_3 {
        case 0u: {
            let _e4 = load_DirectionalLight(offset_8);
            let _e5 = directional_light(_e4, position_3, normal_4);
            return _e5;
        }
        case 1u: {
            let _e6 = load_PointLight(offset_8);
            let _e7 = point_light(_e6, position_3, normal_4);
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

fn step_toward(x_6: vec3<f32>, s: vec3<f32>) -> vec3<f32> {
    let bits_2 = bitcast<vec3<u32>>(x_6);
    let up_1 = ((sign(x_6) * sign(s)) > vec3(0f));
    let stepped = bitcast<vec3<f32>>(select((bits_2 - vec3(1u)), (bits_2 + vec3(1u)), up_1));
    let from_zero = select(vec3(-0.000000000000000000000000000000000000011754944f), vec3(0.000000000000000000000000000000000000011754944f), (s > vec3(0f)));
    let moved = select(stepped, from_zero, (x_6 == vec3(0f)));
    return select(x_6, moved, !((s == vec3(0f))));
}

fn offset_origin(p_5: vec3<f32>, n_4: vec3<f32>, error: f32) -> vec3<f32> {
    let d_5 = ((2f * error) * ((abs(n_4.x) + abs(n_4.y)) + abs(n_4.z)));
    let offset_13 = (n_4 * vec3(d_5));
    let _e17 = step_toward((p_5 + offset_13), offset_13);
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
    let a_9 = abs(position_4);
    let _e13 = hit_error;
    let error_3 = max(_e13, (GAMMA_4_ * max(max(a_9.x, a_9.y), a_9.z)));
    let _e22 = n_5;
    let _e23 = offset_origin(position_4, _e22, error_3);
    let _e25 = F32_INF;
    tmax_4 = bitcast<f32>(_e25);
    let _e29 = F32_INF;
    if (dist_1 < bitcast<f32>(_e29)) {
        let light = (position_4 + (dir_2 * vec3(dist_1)));
        let dd = dot(dir_2, dir_2);
        let along_1 = (dot((light - _e23), dir_2) / dd);
        let l_2 = (abs(position_4) + abs((dir_2 * vec3(dist_1))));
        tmax_4 = ((along_1 * (1f - 0.00001f)) - ((LIGHT_ERROR * max(max(l_2.x, l_2.y), l_2.z)) / sqrt(dd)));
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
    let offset_14 = params[(entry + 1u)];
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
        let _e60 = dispatch_light(type_id_7, offset_14, position_6, normal_7);
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

fn pbr_fresnel(f0_: vec3<f32>, c_4: f32) -> vec3<f32> {
    let k_1 = (1f - saturate(c_4));
    let k2_ = (k_1 * k_1);
    return (f0_ + ((vec3(1f) - f0_) * vec3(((k2_ * k2_) * k_1))));
}

fn pbr_ggx_d(ndh: f32, a2_: f32) -> f32 {
    let d_6 = (((ndh * ndh) * (a2_ - 1f)) + 1f);
    return ((a2_ * INV_PI) / (d_6 * d_6));
}

fn pbr_smith_v(ndl: f32, ndv: f32, a2_1: f32) -> f32 {
    let gv = (ndl * sqrt((((ndv * ndv) * (1f - a2_1)) + a2_1)));
    let gl = (ndv * sqrt((((ndl * ndl) * (1f - a2_1)) + a2_1)));
    return (0.5f / max((gv + gl), 0.00000000000000000001f));
}

fn gltf_radiance(c_5: vec3<f32>, metallic: f32, roughness_1: f32, occlusion_1: f32, emissive: vec3<f32>, ray_19: Ray, hit_6: Hit) -> vec3<f32> {
    var color: vec3<f32>;
    var i_5: u32;

    let _e7 = shading_normal(ray_19, hit_6);
    let _e9 = normalize_vec3f(ray_19.dir);
    let v_4 = -(_e9);
    let metal = saturate(metallic);
    let _e12 = pbr_alpha2_(roughness_1);
    let f0_1 = mix(vec3(0.04f), c_5, vec3(metal));
    let ndv_1 = max(dot(_e7, v_4), 0.0001f);
    color = emissive;
    let _e22 = light_count_query();
    i_5 = 0u;
    loop {
        let _e24 = i_5;
        if (_e24 >= _e22) {
            break;
        }
        let _e26 = i_5;
        let _e29 = sample_light_deferred(_e26, hit_6.position, hit_6.geometric_normal);
        let ndl_1 = max(dot(_e7, _e29.dir), 0f);
        let _e36 = normalize_vec3f((_e29.dir + v_4));
        let _e38 = pbr_fresnel(f0_1, dot(v_4, _e36));
        let _e41 = pbr_ggx_d(saturate(dot(_e7, _e36)), _e12);
        let _e42 = pbr_smith_v(ndl_1, ndv_1, _e12);
        let spec = (_e38 * vec3((_e41 * _e42)));
        let diffuse = (((vec3(1f) - _e38) * c_5) * vec3(((1f - metal) * INV_PI)));
        let _e56 = color;
        color = (_e56 + (((_e29.radiance * vec3(ndl_1)) * (diffuse + spec)) * vec3(occlusion_1)));
        continuing {
            let _e65 = i_5;
            i_5 = (_e65 + 1u);
        }
    }
    let _e68 = color;
    return _e68;
}

fn gltf_masked_shade(m_1: GltfMaskedMaterial, ray_20: Ray, hit_7: Hit) -> vec3<f32> {
    let _e7 = sample_texture(m_1.base_texture, hit_7.uv);
    let c_12 = (m_1.base_color.xyz * _e7.xyz);
    let _e14 = gltf_radiance(c_12, m_1.metallic, m_1.roughness, 1f, m_1.emissive, ray_20, hit_7);
    return _e14;
}

fn load_GltfMaterial(offset_9: u32) -> GltfMaterial {
    let _e5 = params[(offset_9 + 0u)];
    let _e11 = params[(offset_9 + 1u)];
    let _e17 = params[(offset_9 + 2u)];
    let _e23 = params[(offset_9 + 3u)];
    let _e30 = params[(offset_9 + 4u)];
    let _e35 = params[(offset_9 + 5u)];
    let _e41 = params[(offset_9 + 6u)];
    let _e47 = params[(offset_9 + 8u)];
    let _e53 = params[(offset_9 + 9u)];
    let _e59 = params[(offset_9 + 10u)];
    return GltfMaterial(vec4<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17), bitcast<f32>(_e23)), _e30, bitcast<f32>(_e35), bitcast<f32>(_e41), vec3<f32>(bitcast<f32>(_e47), bitcast<f32>(_e53), bitcast<f32>(_e59)));
}

fn gltf_shade(m_2: GltfMaterial, ray_21: Ray, hit_8: Hit) -> vec3<f32> {
    let _e7 = sample_texture(m_2.base_texture, hit_8.uv);
    let c_13 = (m_2.base_color.xyz * _e7.xyz);
    let _e14 = gltf_radiance(c_13, m_2.metallic, m_2.roughness, 1f, m_2.emissive, ray_21, hit_8);
    return _e14;
}

fn dispatch_closest_hit(type_id_4: u32, offset_10: u32, ray_22: Ray, hit_9: Hit, secondary: vec3<f32>) -> vec3<f32> {
    switch type_id_4 {
        case 0u: {
            let _e4 = load_GltfMaskedMaterial(offset_10);
            let _e5 = gltf_masked_shade(_e4, ray_22, hit_9);
            return _e5;
        }
        case 1u: {
            let _e6 = load_GltfMaterial(offset_10);
            let _e7 = gltf_shade(_e6, ray_22, hit_9);
            return _e7;
        }
        default: {
        }
    }
    return vec3<f32>();
}

fn shade_direct(ray_23: Ray, c_6: Candidate) -> vec3<f32> {
    let inst_9 = instances[c_6.slot];
    let _e6 = finish_hit(ray_23, c_6);
    let _e11 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, ray_23, _e6, vec3(0f));
    return _e11;
}

fn dispatch_medium(type_id_5: u32, offset_11: u32, ray_24: Ray, t_2: f32, radiance: vec3<f32>) -> vec3<f32> {
    return vec3<f32>();
}

fn through_medium(ray_25: Ray, t_3: f32, radiance_1: vec3<f32>) -> vec3<f32> {
    if !(HAS_MEDIA) {
        return radiance_1;
    }
    if (ray_25.medium == 0u) {
        return radiance_1;
    }
    let inst_10 = instances[(ray_25.medium - 1u)];
    if ((inst_10.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    let _e21 = dispatch_medium(inst_10.material_type, inst_10.material_offset, ray_25, t_3, radiance_1);
    return _e21;
}

fn dispatch_secondary_rays(type_id_6: u32, offset_12: u32, ray_26: Ray, hit_10: Hit) {
    return;
}

fn spawn_origin_at(position_7: vec3<f32>, normal_8: vec3<f32>, error_1: f32, dir_4: vec3<f32>) -> vec3<f32> {
    var n_6: vec3<f32>;

    n_6 = normal_8;
    let _e5 = n_6;
    if (dot(dir_4, _e5) < 0f) {
        let _e9 = n_6;
        n_6 = -(_e9);
    }
    let _e11 = n_6;
    let _e12 = offset_origin(position_7, _e11, error_1);
    return _e12;
}

fn spawn_origin(hit_11: Hit, error_2: f32, dir_5: vec3<f32>) -> vec3<f32> {
    let _e5 = spawn_origin_at(hit_11.position, hit_11.geometric_normal, error_2, dir_5);
    return _e5;
}

fn trace(camera_ray: Ray) -> vec3<f32> {
    var radiance_2: vec3<f32>;
    var t_4: f32;
    var stack: array<Frame, 4>;
    var depth: u32;
    var ray_27: Ray;
    var value: vec3<f32>;
    var have_value: bool;
    var s_ray: Ray;
    var s_c: Candidate;
    var s_hit: Hit;
    var s_error: f32;
    var s_sum: vec3<f32>;
    var fresh: bool;
    var waiting: bool;
    var pushed: bool;
    var radiance_3: vec3<f32>;
    var t_5: f32;
    var hit_12: Hit;
    var f_1: Frame;
    var i_6: u32;
    var medium: u32;

    if !(HAS_SECONDARY_RAYS) {
        let _e4 = intersect_scene(camera_ray, false);
        radiance_2 = vec3(0f);
        let _e9 = F32_INF;
        t_4 = bitcast<f32>(_e9);
        if (_e4.slot == NO_HIT) {
            hit_error = 0f;
            let _e17 = miss(camera_ray);
            radiance_2 = _e17;
        } else {
            let _e18 = shade_direct(camera_ray, _e4);
            radiance_2 = _e18;
            t_4 = _e4.t;
        }
        let _e20 = t_4;
        let _e21 = radiance_2;
        let _e22 = through_medium(camera_ray, _e20, _e21);
        return _e22;
    }
    stack = array<Frame, 4>();
    depth = 0u;
    ray_27 = camera_ray;
    value = vec3(0f);
    have_value = false;
    s_ray = camera_ray;
    let _e35 = F32_INF;
    let _e37 = no_candidate(bitcast<f32>(_e35));
    s_c = _e37;
    s_hit = Hit(vec3(0f), 0f, vec3(0f), vec3(0f), vec2(0f), true, 0u, 0u);
    s_error = 0f;
    s_sum = vec3(0f);
    fresh = false;
    waiting = false;
    loop {
        let _e62 = have_value;
        let _e64 = waiting;
        if (!(_e62) && !(_e64)) {
            let _e67 = ray_27;
            let _e69 = intersect_scene(_e67, false);
            s_c = _e69;
            let _e70 = ray_27;
            s_ray = _e70;
            s_sum = vec3(0f);
            fresh = true;
            waiting = true;
        }
        let _e75 = waiting;
        if _e75 {
            waiting = false;
            pushed = false;
            radiance_3 = vec3(0f);
            let _e83 = F32_INF;
            t_5 = bitcast<f32>(_e83);
            let _e87 = s_c.slot;
            if (_e87 == NO_HIT) {
                hit_error = 0f;
                let _e92 = s_ray;
                let _e93 = miss(_e92);
                radiance_3 = _e93;
            } else {
                let _e95 = s_c.slot;
                let inst_11 = instances[_e95];
                let _e99 = s_hit;
                hit_12 = _e99;
                let _e101 = fresh;
                if _e101 {
                    let _e102 = s_ray;
                    let _e103 = s_c;
                    let _e104 = finish_hit(_e102, _e103);
                    hit_12 = _e104;
                    let _e106 = hit_error;
                    s_error = _e106;
                } else {
                    let _e107 = s_error;
                    hit_error = _e107;
                }
                let _e110 = hit_12.t;
                t_5 = _e110;
                let _e111 = fresh;
                let _e119 = s_ray.depth;
                let _e123 = depth;
                if (((_e111 && ((inst_11.flags & FLAG_SECONDARY_RAYS) != 0u)) && (_e119 < MAX_DEPTH)) && (_e123 < STACK_SIZE)) {
                    spawn_count = 0u;
                    let _e131 = s_ray;
                    let _e132 = hit_12;
                    dispatch_secondary_rays(inst_11.material_type, inst_11.material_offset, _e131, _e132);
                    let _e134 = spawn_count;
                    let n_9 = min(min(_e134, 1u), MAX_SPAWN);
                    if (n_9 > 0u) {
                        let _e141 = s_ray;
                        let _e142 = hit_12;
                        let _e143 = s_error;
                        let _e145 = s_c.slot;
                        f_1 = Frame(_e141, _e142, _e143, _e145, vec3(0f), array<vec3<f32>, 1>(), array<vec3<f32>, 1>(), n_9, 0u);
                        i_6 = 0u;
                        loop {
                            let _e155 = i_6;
                            if (_e155 >= n_9) {
                                break;
                            }
                            let _e158 = i_6;
                            let _e162 = i_6;
                            let _e165 = spawn_dirs[_e162];
                            f_1.dirs[min(_e158, 0u)] = _e165;
                            let _e167 = i_6;
                            let _e171 = i_6;
                            let _e174 = spawn_weights[_e171];
                            f_1.weights[min(_e167, 0u)] = _e174;
                            continuing {
                                let _e175 = i_6;
                                i_6 = (_e175 + 1u);
                            }
                        }
                        let _e178 = depth;
                        let _e182 = f_1;
                        stack[min(_e178, 3u)] = _e182;
                        let _e183 = depth;
                        depth = (_e183 + 1u);
                        pushed = true;
                    }
                }
                let _e187 = pushed;
                if !(_e187) {
                    let _e191 = s_ray;
                    let _e192 = hit_12;
                    let _e193 = s_sum;
                    let _e194 = dispatch_closest_hit(inst_11.material_type, inst_11.material_offset, _e191, _e192, _e193);
                    radiance_3 = _e194;
                }
            }
            let _e195 = pushed;
            if !(_e195) {
                let _e197 = s_ray;
                let _e198 = t_5;
                let _e199 = radiance_3;
                let _e200 = through_medium(_e197, _e198, _e199);
                value = _e200;
                have_value = true;
            }
        }
        let _e202 = have_value;
        if _e202 {
            let _e203 = depth;
            if (_e203 == 0u) {
                let _e206 = value;
                return _e206;
            }
            let _e207 = depth;
            let top = (_e207 - 1u);
            let _e214 = stack[min(top, 3u)].next;
            let child_2 = (_e214 - 1u);
            let _e221 = stack[min(top, 3u)].sum;
            let _e229 = stack[min(top, 3u)].weights[min(child_2, 0u)];
            let _e230 = value;
            stack[min(top, 3u)].sum = (_e221 + (_e229 * _e230));
            have_value = false;
        }
        let _e234 = depth;
        let top_1 = (_e234 - 1u);
        let _e241 = stack[min(top_1, 3u)].next;
        let _e246 = stack[min(top_1, 3u)].count;
        if (_e241 < _e246) {
            let i_9 = stack[min(top_1, 3u)].next;
            stack[min(top_1, 3u)].next = (i_9 + 1u);
            let parent = stack[min(top_1, 3u)].ray;
            let hit_15 = stack[min(top_1, 3u)].hit;
            let dir_8 = stack[min(top_1, 3u)].dirs[min(i_9, 0u)];
            medium = parent.medium;
            let _e283 = stack[min(top_1, 3u)].error;
            let _e284 = spawn_origin(hit_15, _e283, dir_8);
            let _e287 = F32_INF;
            let _e293 = medium;
            ray_27 = Ray(_e284, 0f, dir_8, bitcast<f32>(_e287), (parent.depth + 1u), RAY_SECONDARY, _e293);
        } else {
            let _e299 = stack[min(top_1, 3u)].ray;
            s_ray = _e299;
            let _e304 = stack[min(top_1, 3u)].hit;
            s_hit = _e304;
            let _e309 = stack[min(top_1, 3u)].error;
            s_error = _e309;
            let _e315 = stack[min(top_1, 3u)].slot;
            s_c.slot = _e315;
            let _e320 = stack[min(top_1, 3u)].sum;
            s_sum = _e320;
            fresh = false;
            waiting = true;
            depth = top_1;
        }
    }
    return vec3<f32>();
}

fn is_finite_vec3f(x_7: vec3<f32>) -> vec3<bool> {
    return ((bitcast<vec3<u32>>(x_7) & vec3(2147483647u)) < vec3(2139095040u));
}

fn finite_or_zero(c_7: vec3<f32>) -> vec3<f32> {
    let _e3 = is_finite_vec3f(c_7);
    return select(vec3(0f), c_7, _e3);
}

fn add_sample(p_6: PassSum, c_8: vec3<f32>, s_1: u32, index: u32, first_pass: u32, per_pass: u32) -> PassSum {
    var next: PassSum;

    next = p_6;
    let _e7 = is_finite_vec3f(c_8);
    if all(_e7) {
        let _e10 = next.sum;
        next.sum = (_e10 + c_8);
    } else {
        let _e13 = next.sum;
        let _e14 = finite_or_zero(c_8);
        next.sum = (_e13 + _e14);
        let _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    let _e22 = rem_u32_((s_1 + 1u), per_pass);
    if (_e22 != 0u) {
        let _e25 = next;
        return _e25;
    }
    let _e27 = ray_count;
    atomicAdd((&counters[1]), _e27);
    ray_count = 0u;
    let _e31 = div_u32_(s_1, per_pass);
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
    var s_2: u32;

    let frame_6 = frame;
    let tile_2 = tile;
    let index_2 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    let per_pass_1 = frame_6.samples_per_pass;
    let first_1 = (tile_2.frame * per_pass_1);
    let count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = PassSum(vec3(0f), 0u);
    s_2 = 0u;
    loop {
        let _e25 = s_2;
        if (_e25 >= count_2) {
            break;
        }
        let _e27 = sums;
        let _e28 = s_2;
        let _e30 = sample_camera_ray(pixel_5, (first_1 + _e28));
        let _e31 = trace(_e30);
        let _e32 = s_2;
        let _e34 = add_sample(_e27, _e31, _e32, index_2, tile_2.frame, per_pass_1);
        sums = _e34;
        continuing {
            let _e35 = s_2;
            s_2 = (_e35 + 1u);
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
