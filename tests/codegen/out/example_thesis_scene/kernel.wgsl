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
}

struct TileParams {
    origin: vec2<u32>,
    extent: vec2<u32>,
    image_size: vec2<u32>,
    tile_index: u32,
    frame: u32,
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

struct GpuNode {
    min: vec3<f32>,
    a: u32,
    max: vec3<f32>,
    b: u32,
}

struct Triangle {
    v0_: vec3<f32>,
    v1_: vec3<f32>,
    v2_: vec3<f32>,
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

struct ConstantBackground {
    color: vec3<f32>,
}

struct Lambert {
    albedo: vec3<f32>,
}

struct LightSample {
    dir: vec3<f32>,
    dist: f32,
    radiance: vec3<f32>,
}

struct PointLight {
    position: vec3<f32>,
    color: vec3<f32>,
    intensity: f32,
    range: f32,
    inner_range: f32,
}

struct Frame {
    ray: Ray,
    hit: Hit,
    slot: u32,
    sum: vec3<f32>,
    dirs: array<vec3<f32>, 1>,
    weights: array<vec3<f32>, 1>,
    count: u32,
    next: u32,
}

const RAY_CAMERA: u32 = 0u;
const HAS_MEDIA: bool = false;
const NO_HIT: u32 = 4294967295u;
const MESH_GEOMETRY: u32 = 4294967295u;
const LEAF_BIT: u32 = 2147483648u;
const HAS_ANY_HIT: bool = false;
const FLAG_ANY_HIT: u32 = 1u;
const BLAS_STACK: u32 = 64u;
const HAS_SECONDARY_RAYS: bool = false;
const TLAS_STACK: u32 = 64u;
const HAS_BACKGROUND: bool = true;
const FLAG_MEDIUM: u32 = 4u;
const RAY_SHADOW: u32 = 2u;
const INV_PI: f32 = 0.31830987f;
const FLAG_SECONDARY: u32 = 2u;
const MAX_DEPTH: u32 = 0u;
const STACK_SIZE: u32 = 1u;
const MAX_SPAWN: u32 = 1u;
const RAY_SECONDARY: u32 = 1u;

@group(0) @binding(0) 
var<uniform> frame: FrameUniforms;
@group(0) @binding(1) 
var<uniform> tile: TileParams;
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
@group(0) @binding(5) 
var<storage> attributes: array<vec4<u32>>;
var<private> spawn_dirs: array<vec3<f32>, 1>;
var<private> spawn_weights: array<vec3<f32>, 1>;
var<private> spawn_count: u32;
@group(0) @binding(8) 
var<storage, read_write> accum: array<vec4<f32>>;
@group(0) @binding(9) 
var<storage, read_write> counters: array<atomic<u32>>;

fn pcg_hash(x: u32) -> u32 {
    let state = ((x * 747796405u) + 2891336453u);
    let word = (((state >> (((state >> 28u) + 4u) & 31u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

fn rng_seed(pixel: vec2<u32>, sample: u32, seed: u32) {
    var h: u32;

    let _e5 = pcg_hash(seed);
    let _e7 = pcg_hash((sample ^ _e5));
    let _e9 = pcg_hash((pixel.y ^ _e7));
    let _e11 = pcg_hash((pixel.x ^ _e9));
    h = _e11;
    let _e13 = h;
    if (_e13 == 0u) {
        h = 1u;
    }
    let _e17 = h;
    rng_state = _e17;
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

fn rand_next() -> f32 {
    let _e1 = rng_state;
    let s_1 = ((_e1 * 747796405u) + 2891336453u);
    rng_state = s_1;
    let word_1 = (((s_1 >> (((s_1 >> 28u) + 4u) & 31u)) ^ s_1) * 277803737u);
    let r_3 = ((word_1 >> 22u) ^ word_1);
    return (f32((r_3 >> 8u)) * (1f / 16777216f));
}

fn rand2_next() -> vec2<f32> {
    let _e0 = rand_next();
    let _e1 = rand_next();
    return vec2<f32>(_e0, _e1);
}

fn normalize_vec3f(v: vec3<f32>) -> vec3<f32> {
    return select(vec3(0f), normalize(v), (dot(v, v) >= 0.000000000000000000000000000000000000011754944f));
}

fn pinhole_ray(cam: Pinhole, pixel_1: vec2<u32>, sample_1: u32) -> Ray {
    var jitter: vec2<f32>;

    let _e2 = image_size_query();
    let size = vec2<f32>(_e2);
    jitter = vec2(0.5f);
    let _e7 = samples_per_pixel_query();
    if (_e7 > 1u) {
        let _e10 = rand2_next();
        jitter = _e10;
    }
    let _e12 = jitter;
    let ndc = ((((vec2<f32>(pixel_1) + _e12) / size) * vec2(2f)) - vec2(1f));
    let _e24 = normalize_vec3f((cam.look_at - cam.position));
    let _e27 = normalize_vec3f(cross(_e24, cam.up));
    let up = cross(_e27, _e24);
    let h_1 = tan((radians(cam.fov) * 0.5f));
    let aspect = (size.x / size.y);
    let _e48 = normalize_vec3f(((_e24 + (_e27 * vec3(((ndc.x * h_1) * aspect)))) - (up * vec3((ndc.y * h_1)))));
    let _e52 = F32_INF;
    return Ray(cam.position, 0f, _e48, bitcast<f32>(_e52), 0u, 0u, 0u);
}

fn dispatch_ray_generation(type_id: u32, offset_1: u32, pixel_2: vec2<u32>, sample_2: u32) -> Ray {
    let _e3 = load_Pinhole(offset_1);
    let _e4 = pinhole_ray(_e3, pixel_2, sample_2);
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

fn safe_inverse(d: vec3<f32>) -> vec3<f32> {
    let tiny = vec3(0.000000000000000000000000000001f);
    let s_2 = select(vec3(1f), vec3(-1f), (d < vec3(0f)));
    let dd = select(d, (s_2 * tiny), (abs(d) < tiny));
    return (vec3(1f) / dd);
}

fn load_triangle(slot: u32) -> Triangle {
    let v0_ = triangles[(slot * 3u)];
    let v1_ = triangles[((slot * 3u) + 1u)];
    let v2_ = triangles[((slot * 3u) + 2u)];
    return Triangle(v0_.xyz, v1_.xyz, v2_.xyz);
}

fn intersect_triangle(ray_1: Ray, tri: Triangle) -> Intersection {
    let _e10 = vec3(2139095040u);
    let dir_2 = select(ray_1.dir, vec3(0f), (abs(ray_1.dir) < vec3(0.000000000000000000000000000000000000011754944f)));
    let _e31 = abs(dir_2);
    let _e38 = (_e31.y > _e31.x);
    let kz = select(select(0u, 1u, _e38), 2u, (_e31.z > select(_e31.x, _e31.y, _e38)));
    let _e45 = select((kz + 1u), 0u, (kz == 2u));
    let _e49 = select((kz + 2u), (kz - 1u), (kz >= 1u));
    let dz = dir_2[kz];
    let _e52 = (dz < 0f);
    let kx = select(_e45, _e49, _e52);
    let ky = select(_e49, _e45, _e52);
    let sx = (dir_2[kx] / dz);
    let sy = (dir_2[ky] / dz);
    let sz = (1f / dz);
    let _e62 = (tri.v0_ - ray_1.origin);
    let _e68 = (_e62[kx] - (sx * _e62[kz]));
    let _e69 = (_e62[ky] - (sy * _e62[kz]));
    let _e71 = (tri.v1_ - ray_1.origin);
    let _e77 = (_e71[kx] - (sx * _e71[kz]));
    let _e78 = (_e71[ky] - (sy * _e71[kz]));
    let _e80 = (tri.v2_ - ray_1.origin);
    let _e86 = (_e80[kx] - (sx * _e80[kz]));
    let _e87 = (_e80[ky] - (sy * _e80[kz]));
    let u = ((_e86 * _e78) - (_e87 * _e77));
    let v_1 = ((_e68 * _e87) - (_e69 * _e86));
    let w = ((_e77 * _e69) - (_e78 * _e68));
    let det = ((u + v_1) + w);
    let _e112 = (1f / det);
    let t_2 = ((((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112);
    let hit_6 = (((((all(((bitcast<vec3<u32>>(ray_1.origin) & vec3(2147483647u)) < _e10)) && all(((bitcast<vec3<u32>>(ray_1.dir) & vec3(2147483647u)) < _e10))) && (dz != 0f)) && !(((((u < 0f) || (v_1 < 0f)) || (w < 0f)) && (((u > 0f) || (v_1 > 0f)) || (w > 0f))))) && !((det == 0f))) && ((t_2 >= ray_1.tmin) && (t_2 <= ray_1.tmax)));
    let _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    let _e137 = F32_INF;
    return Intersection(select(bitcast<f32>(_e137), t_2, hit_6), select(vec3<f32>(0f, 0f, 1f), _e132, hit_6), select(vec2(0f), vec2<f32>((v_1 * _e112), (w * _e112)), hit_6));
}

fn point_to_world(inst_1: GpuInstance, p: vec3<f32>) -> vec3<f32> {
    let q = vec4<f32>(p, 1f);
    return vec3<f32>(dot(inst_1.object_to_world_0_, q), dot(inst_1.object_to_world_1_, q), dot(inst_1.object_to_world_2_, q));
}

fn decode_octahedral(bits: u32) -> vec3<f32> {
    var n: vec3<f32>;

    let e = unpack2x16snorm(bits);
    n = vec3<f32>(e.x, e.y, ((1f - abs(e.x)) - abs(e.y)));
    let _e14 = n.z;
    if (_e14 < 0f) {
        let _e21 = n;
        let s_3 = select(vec2(-1f), vec2(1f), (_e21.xy >= vec2(0f)));
        let _e29 = n;
        let xy = ((vec2(1f) - abs(_e29.yx)) * s_3);
        let _e37 = n.z;
        n = vec3<f32>(xy.x, xy.y, _e37);
    }
    let _e39 = n;
    let _e40 = normalize_vec3f(_e39);
    return _e40;
}

fn normal_to_world(inst_2: GpuInstance, n_1: vec3<f32>) -> vec3<f32> {
    let w_1 = (((inst_2.world_to_object_0_.xyz * vec3(n_1.x)) + (inst_2.world_to_object_1_.xyz * vec3(n_1.y))) + (inst_2.world_to_object_2_.xyz * vec3(n_1.z)));
    let _e19 = normalize_vec3f(w_1);
    return _e19;
}

fn finish_hit(ray_2: Ray, c: Candidate) -> Hit {
    var hit: Hit;
    var n_geo: vec3<f32>;
    var n_shade: vec3<f32>;

    let inst_5 = instances[c.slot];
    hit = Hit((ray_2.origin + (ray_2.dir * vec3(c.t))), c.t, vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 1f, 0f), c.uv, true, inst_5.object, c.primitive);
    n_geo = c.normal;
    n_shade = c.normal;
    if (inst_5.geometry_type == MESH_GEOMETRY) {
        let _e35 = load_triangle(c.primitive);
        let b_1 = c.uv;
        let w_2 = ((1f - b_1.x) - b_1.y);
        let _e56 = point_to_world(inst_5, (((_e35.v0_ * vec3(w_2)) + (_e35.v1_ * vec3(b_1.x))) + (_e35.v2_ * vec3(b_1.y))));
        hit.position = _e56;
        n_geo = cross((_e35.v1_ - _e35.v0_), (_e35.v2_ - _e35.v0_));
        let a0_ = attributes[(c.primitive * 2u)];
        let a1_ = attributes[((c.primitive * 2u) + 1u)];
        let _e79 = decode_octahedral(a0_.x);
        let _e83 = decode_octahedral(a0_.y);
        let _e89 = decode_octahedral(a0_.z);
        n_shade = (((_e79 * vec3(w_2)) + (_e83 * vec3(b_1.x))) + (_e89 * vec3(b_1.y)));
        let _e94 = n_shade;
        let _e95 = n_shade;
        if (dot(_e94, _e95) < 0.000000000001f) {
            let _e99 = n_geo;
            n_shade = _e99;
        }
        let uv0_ = unpack2x16float(a0_.w);
        let uv1_ = unpack2x16float(a1_.x);
        let uv2_ = unpack2x16float(a1_.y);
        hit.uv = (((uv0_ * vec2(w_2)) + (uv1_ * vec2(b_1.x))) + (uv2_ * vec2(b_1.y)));
        let _e123 = triangles[(c.primitive * 3u)];
        hit.primitive = bitcast<u32>(_e123.w);
    }
    let _e127 = n_geo;
    let _e128 = normal_to_world(inst_5, _e127);
    hit.geometric_normal = _e128;
    let _e130 = n_shade;
    let _e131 = normal_to_world(inst_5, _e130);
    hit.normal = _e131;
    let _e135 = hit.geometric_normal;
    hit.front_face = (dot(ray_2.dir, _e135) < 0f);
    let _e139 = hit;
    return _e139;
}

fn dispatch_any_hit(type_id_1: u32, offset_2: u32, ray_3: Ray, hit_1: Hit) -> bool {
    return bool();
}

fn accept(inst_3: GpuInstance, ray_4: Ray, c_1: Candidate) -> bool {
    if !(HAS_ANY_HIT) {
        return true;
    }
    if ((inst_3.flags & FLAG_ANY_HIT) == 0u) {
        return true;
    }
    let _e12 = finish_hit(ray_4, c_1);
    let _e15 = dispatch_any_hit(inst_3.material_type, inst_3.material_offset, ray_4, _e12);
    return _e15;
}

fn slab(lo: vec3<f32>, hi: vec3<f32>, origin: vec3<f32>, inv_dir: vec3<f32>, tmin: f32, tmax_1: f32) -> f32 {
    let t0_ = ((lo - origin) * inv_dir);
    let t1_ = ((hi - origin) * inv_dir);
    let near_2 = min(t0_, t1_);
    let far_2 = max(t0_, t1_);
    let enter = max(max(near_2.x, near_2.y), max(near_2.z, tmin));
    let exit = min(min(far_2.x, far_2.y), min(far_2.z, tmax_1));
    if (enter <= exit) {
        return enter;
    }
    let _e26 = F32_INF;
    return bitcast<f32>(_e26);
}

fn intersect_mesh(inst_4: GpuInstance, slot_1: u32, world_ray: Ray, ray_5: Ray, best_in: Candidate, shadow: bool) -> Candidate {
    var best: Candidate;
    var stack: array<u32, 64>;
    var sp: u32;
    var node: u32;
    var k: u32;
    var r_1: Ray;
    var near: u32;
    var far: u32;

    best = best_in;
    let _e8 = safe_inverse(ray_5.dir);
    let base = inst_4.blas_root;
    stack = array<u32, 64>();
    sp = 0u;
    node = base;
    loop {
        let _e15 = node;
        let n_5 = nodes[_e15];
        if ((n_5.b & LEAF_BIT) != 0u) {
            let count = (n_5.b & ~(LEAF_BIT));
            k = 0u;
            loop {
                let _e30 = k;
                if (_e30 >= count) {
                    break;
                }
                let _e35 = k;
                let prim = ((inst_4.triangle_offset + n_5.a) + _e35);
                r_1 = ray_5;
                let _e40 = best.t;
                r_1.tmax = _e40;
                let _e41 = r_1;
                let _e42 = load_triangle(prim);
                let _e43 = intersect_triangle(_e41, _e42);
                let _e46 = r_1.tmin;
                let _e50 = r_1.tmax;
                let _e55 = F32_INF;
                if (((_e43.t >= _e46) && (_e43.t <= _e50)) && (_e43.t < bitcast<f32>(_e55))) {
                    let c_4 = Candidate(_e43.t, slot_1, prim, _e43.uv, _e43.normal);
                    let _e63 = accept(inst_4, world_ray, c_4);
                    if _e63 {
                        best = c_4;
                        if shadow {
                            let _e64 = best;
                            return _e64;
                        }
                    }
                }
                continuing {
                    let _e65 = k;
                    k = (_e65 + 1u);
                }
            }
        } else {
            let left = (base + n_5.a);
            let right = (left + 1u);
            let l_1 = nodes[left];
            let rr = nodes[right];
            let _e83 = best.t;
            let _e84 = slab(l_1.min, l_1.max, ray_5.origin, _e8, ray_5.tmin, _e83);
            let _e90 = best.t;
            let _e91 = slab(rr.min, rr.max, ray_5.origin, _e8, ray_5.tmin, _e90);
            let _e93 = F32_INF;
            let _e97 = F32_INF;
            if ((_e84 < bitcast<f32>(_e93)) && (_e91 < bitcast<f32>(_e97))) {
                near = left;
                far = right;
                if (_e91 < _e84) {
                    near = right;
                    far = left;
                }
                let _e104 = sp;
                if (_e104 < BLAS_STACK) {
                    let _e107 = sp;
                    let _e111 = far;
                    stack[min(_e107, 63u)] = _e111;
                    let _e112 = sp;
                    sp = (_e112 + 1u);
                }
                let _e115 = near;
                node = _e115;
                continue;
            }
            let _e117 = F32_INF;
            if (_e84 < bitcast<f32>(_e117)) {
                node = left;
                continue;
            }
            let _e121 = F32_INF;
            if (_e91 < bitcast<f32>(_e121)) {
                node = right;
                continue;
            }
        }
        let _e124 = sp;
        if (_e124 == 0u) {
            break;
        }
        let _e127 = sp;
        sp = (_e127 - 1u);
        let _e130 = sp;
        let _e134 = stack[min(_e130, 63u)];
        node = _e134;
    }
    let _e135 = best;
    return _e135;
}

fn intersect_object(slot_2: u32, ray_6: Ray, best_1: Candidate, shadow_1: bool) -> Candidate {
    var r_2: Ray;

    let inst_6 = instances[slot_2];
    let _e7 = to_object(inst_6, ray_6);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        let _e14 = r_2;
        let _e15 = intersect_mesh(inst_6, slot_2, ray_6, _e14, best_1, shadow_1);
        return _e15;
    }
    return best_1;
}

fn medium_at(p_1: vec3<f32>) -> u32 {
    var i: u32;

    if !(HAS_MEDIA) {
        return 0u;
    }
    let frame_1 = frame;
    let _e11 = normalize_vec3f(vec3<f32>(0.5773f, 0.5774f, 0.5775f));
    let _e13 = F32_INF;
    let probe = Ray(p_1, 0f, _e11, bitcast<f32>(_e13), 0u, 0u, 0u);
    let end = frame_1.medium_count;
    i = 0u;
    loop {
        let _e22 = i;
        if (_e22 >= end) {
            break;
        }
        let _e25 = i;
        let slot_3 = params[(frame_1.medium_table + _e25)];
        let _e31 = F32_INF;
        let _e33 = no_candidate(bitcast<f32>(_e31));
        let _e35 = intersect_object(slot_3, probe, _e33, false);
        if (_e35.slot != NO_HIT) {
            let _e39 = finish_hit(probe, _e35);
            if !(_e39.front_face) {
                return (slot_3 + 1u);
            }
        }
        continuing {
            let _e44 = i;
            i = (_e44 + 1u);
        }
    }
    return 0u;
}

fn intersect_scene(ray_7: Ray, shadow_2: bool) -> Candidate {
    var best_2: Candidate;
    var stack_1: array<u32, 64>;
    var sp_1: u32;
    var node_1: u32;
    var k_1: u32;
    var near_1: u32;
    var far_1: u32;

    let _e3 = no_candidate(ray_7.tmax);
    best_2 = _e3;
    let frame_2 = frame;
    if (frame_2.instance_count == 0u) {
        let _e10 = best_2;
        return _e10;
    }
    let _e12 = safe_inverse(ray_7.dir);
    stack_1 = array<u32, 64>();
    sp_1 = 0u;
    node_1 = frame_2.tlas_root;
    let _e19 = node_1;
    let root = nodes[_e19];
    let _e28 = best_2.t;
    let _e29 = slab(root.min, root.max, ray_7.origin, _e12, ray_7.tmin, _e28);
    let _e31 = F32_INF;
    if (_e29 == bitcast<f32>(_e31)) {
        let _e34 = best_2;
        return _e34;
    }
    loop {
        let _e35 = node_1;
        let n_6 = nodes[_e35];
        if ((n_6.b & LEAF_BIT) != 0u) {
            let count_1 = (n_6.b & ~(LEAF_BIT));
            k_1 = 0u;
            loop {
                let _e50 = k_1;
                if (_e50 >= count_1) {
                    break;
                }
                let _e53 = k_1;
                let _e55 = best_2;
                let _e56 = intersect_object((n_6.a + _e53), ray_7, _e55, shadow_2);
                best_2 = _e56;
                let _e58 = best_2.slot;
                if (shadow_2 && (_e58 != NO_HIT)) {
                    let _e62 = best_2;
                    return _e62;
                }
                continuing {
                    let _e63 = k_1;
                    k_1 = (_e63 + 1u);
                }
            }
        } else {
            let left_1 = (frame_2.tlas_root + n_6.a);
            let right_1 = (left_1 + 1u);
            let l_2 = nodes[left_1];
            let rr_1 = nodes[right_1];
            let _e82 = best_2.t;
            let _e83 = slab(l_2.min, l_2.max, ray_7.origin, _e12, ray_7.tmin, _e82);
            let _e89 = best_2.t;
            let _e90 = slab(rr_1.min, rr_1.max, ray_7.origin, _e12, ray_7.tmin, _e89);
            let _e92 = F32_INF;
            let _e96 = F32_INF;
            if ((_e83 < bitcast<f32>(_e92)) && (_e90 < bitcast<f32>(_e96))) {
                near_1 = left_1;
                far_1 = right_1;
                if (_e90 < _e83) {
                    near_1 = right_1;
                    far_1 = left_1;
                }
                let _e103 = sp_1;
                if (_e103 < TLAS_STACK) {
                    let _e106 = sp_1;
                    let _e110 = far_1;
                    stack_1[min(_e106, 63u)] = _e110;
                    let _e111 = sp_1;
                    sp_1 = (_e111 + 1u);
                }
                let _e114 = near_1;
                node_1 = _e114;
                continue;
            }
            let _e116 = F32_INF;
            if (_e83 < bitcast<f32>(_e116)) {
                node_1 = left_1;
                continue;
            }
            let _e120 = F32_INF;
            if (_e90 < bitcast<f32>(_e120)) {
                node_1 = right_1;
                continue;
            }
        }
        let _e123 = sp_1;
        if (_e123 == 0u) {
            break;
        }
        let _e126 = sp_1;
        sp_1 = (_e126 - 1u);
        let _e129 = sp_1;
        let _e133 = stack_1[min(_e129, 63u)];
        node_1 = _e133;
    }
    let _e134 = best_2;
    return _e134;
}

fn load_ConstantBackground(offset_3: u32) -> ConstantBackground {
    let _e5 = params[(offset_3 + 0u)];
    let _e11 = params[(offset_3 + 1u)];
    let _e17 = params[(offset_3 + 2u)];
    return ConstantBackground(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)));
}

fn constant_background(b: ConstantBackground, ray_8: Ray) -> vec3<f32> {
    return b.color;
}

fn dispatch_miss(type_id_2: u32, offset_4: u32, ray_9: Ray) -> vec3<f32> {
    let _e2 = load_ConstantBackground(offset_4);
    let _e3 = constant_background(_e2, ray_9);
    return _e3;
}

fn miss(ray_10: Ray) -> vec3<f32> {
    if !(HAS_BACKGROUND) {
        return vec3(0f);
    }
    let frame_3 = frame;
    let _e9 = dispatch_miss(frame_3.background_type, frame_3.background_offset, ray_10);
    return _e9;
}

fn dispatch_medium(type_id_3: u32, offset_5: u32, ray_11: Ray, t: f32, radiance: vec3<f32>) -> vec3<f32> {
    return vec3<f32>();
}

fn through_medium(ray_12: Ray, t_1: f32, radiance_1: vec3<f32>) -> vec3<f32> {
    if !(HAS_MEDIA) {
        return radiance_1;
    }
    if (ray_12.medium == 0u) {
        return radiance_1;
    }
    let inst_7 = instances[(ray_12.medium - 1u)];
    if ((inst_7.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    let _e21 = dispatch_medium(inst_7.material_type, inst_7.material_offset, ray_12, t_1, radiance_1);
    return _e21;
}

fn load_Lambert(offset_6: u32) -> Lambert {
    let _e5 = params[(offset_6 + 0u)];
    let _e11 = params[(offset_6 + 1u)];
    let _e17 = params[(offset_6 + 2u)];
    return Lambert(vec3<f32>(bitcast<f32>(_e5), bitcast<f32>(_e11), bitcast<f32>(_e17)));
}

fn light_count_query() -> u32 {
    let _e1 = frame;
    return _e1.light_count;
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

fn vec3i_from_vec3f(x_1: vec3<f32>) -> vec3<i32> {
    return select(vec3<i32>(min(max(x_1, vec3(-2147483600f)), vec3(2147483500f))), vec3(0i), ((bitcast<vec3<u32>>(x_1) & vec3(2147483647u)) > vec3(2139095040u)));
}

fn offset_origin(p_2: vec3<f32>, n_2: vec3<f32>) -> vec3<f32> {
    let _e5 = vec3i_from_vec3f((n_2 * vec3(256f)));
    let pi = vec3<f32>(bitcast<f32>((bitcast<i32>(p_2.x) + select(_e5.x, -(_e5.x), (p_2.x < 0f)))), bitcast<f32>((bitcast<i32>(p_2.y) + select(_e5.y, -(_e5.y), (p_2.y < 0f)))), bitcast<f32>((bitcast<i32>(p_2.z) + select(_e5.z, -(_e5.z), (p_2.z < 0f)))));
    let small = (abs(p_2) < vec3((1f / 32f)));
    return select(pi, (p_2 + (n_2 * vec3((1f / 65536f)))), small);
}

fn shadow_query(position: vec3<f32>, normal: vec3<f32>, dir: vec3<f32>, dist: f32) -> f32 {
    var n_3: vec3<f32>;

    n_3 = normal;
    let _e5 = n_3;
    if (dot(dir, _e5) < 0f) {
        let _e9 = n_3;
        n_3 = -(_e9);
    }
    let _e11 = n_3;
    let _e12 = offset_origin(position, _e11);
    let ray_19 = Ray(_e12, 0f, dir, (dist * (1f - 0.00001f)), 0u, RAY_SHADOW, 0u);
    let _e23 = intersect_scene(ray_19, true);
    return select(1f, 0f, (_e23.slot != NO_HIT));
}

fn point_light(l: PointLight, position_1: vec3<f32>, normal_1: vec3<f32>) -> LightSample {
    var strength: f32;

    let to_light = (l.position - position_1);
    let dist_1 = length(to_light);
    let dir_3 = (to_light / vec3(max(dist_1, 0.00000000000000000001f)));
    strength = (l.intensity / max((dist_1 * dist_1), 0.00000000000000000001f));
    if (l.range > 0f) {
        let _e19 = strength;
        strength = (_e19 * (1f - smoothstep(l.inner_range, l.range, dist_1)));
    }
    let _e26 = shadow_query(position_1, normal_1, dir_3, dist_1);
    let _e28 = strength;
    return LightSample(dir_3, dist_1, ((l.color * vec3(_e28)) * vec3(_e26)));
}

fn dispatch_light(type_id_4: u32, offset_8: u32, position_2: vec3<f32>, normal_2: vec3<f32>) -> LightSample {
    let _e3 = load_PointLight(offset_8);
    let _e4 = point_light(_e3, position_2, normal_2);
    return _e4;
}

fn sample_light_query(i_1: u32, position_3: vec3<f32>, normal_3: vec3<f32>) -> LightSample {
    let frame_4 = frame;
    if (i_1 >= frame_4.light_count) {
        return LightSample(vec3<f32>(0f, 1f, 0f), 0f, vec3(0f));
    }
    let entry = (frame_4.light_table + (i_1 * 2u));
    let _e21 = params[entry];
    let _e26 = params[(entry + 1u)];
    let _e27 = dispatch_light(_e21, _e26, position_3, normal_3);
    return _e27;
}

fn lambert_shade(m: Lambert, ray_13: Ray, hit_2: Hit) -> vec3<f32> {
    var color: vec3<f32>;
    var i_2: u32;

    let n_7 = faceForward(hit_2.normal, ray_13.dir, hit_2.normal);
    color = vec3(0f);
    let _e11 = light_count_query();
    i_2 = 0u;
    loop {
        let _e13 = i_2;
        if (_e13 >= _e11) {
            break;
        }
        let _e15 = i_2;
        let _e18 = sample_light_query(_e15, hit_2.position, hit_2.geometric_normal);
        let _e19 = color;
        color = (_e19 + (((m.albedo * vec3(INV_PI)) * _e18.radiance) * vec3(max(dot(n_7, _e18.dir), 0f))));
        continuing {
            let _e33 = i_2;
            i_2 = (_e33 + 1u);
        }
    }
    let _e36 = color;
    return _e36;
}

fn dispatch_closest_hit(type_id_5: u32, offset_9: u32, ray_14: Ray, hit_3: Hit, secondary: vec3<f32>) -> vec3<f32> {
    let _e3 = load_Lambert(offset_9);
    let _e4 = lambert_shade(_e3, ray_14, hit_3);
    return _e4;
}

fn shade_direct(ray_15: Ray, c_2: Candidate) -> vec3<f32> {
    let inst_8 = instances[c_2.slot];
    let _e6 = finish_hit(ray_15, c_2);
    let _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_15, _e6, vec3(0f));
    return _e11;
}

fn dispatch_secondary_rays(type_id_6: u32, offset_10: u32, ray_16: Ray, hit_4: Hit) {
    return;
}

fn spawn_origin(hit_5: Hit, dir_1: vec3<f32>) -> vec3<f32> {
    var n_4: vec3<f32>;

    n_4 = hit_5.geometric_normal;
    let _e4 = n_4;
    if (dot(dir_1, _e4) < 0f) {
        let _e8 = n_4;
        n_4 = -(_e8);
    }
    let _e11 = n_4;
    let _e12 = offset_origin(hit_5.position, _e11);
    return _e12;
}

fn trace(camera_ray: Ray) -> vec3<f32> {
    var stack_2: array<Frame, 1>;
    var depth: u32;
    var ray_17: Ray;
    var value: vec3<f32>;
    var have_value: bool;
    var pushed: bool;
    var f: Frame;
    var i_3: u32;
    var medium: u32;

    if !(HAS_SECONDARY_RAYS) {
        let _e4 = intersect_scene(camera_ray, false);
        if (_e4.slot == NO_HIT) {
            let _e9 = F32_INF;
            let _e11 = miss(camera_ray);
            let _e12 = through_medium(camera_ray, bitcast<f32>(_e9), _e11);
            return _e12;
        }
        let _e14 = shade_direct(camera_ray, _e4);
        let _e15 = through_medium(camera_ray, _e4.t, _e14);
        return _e15;
    }
    stack_2 = array<Frame, 1>();
    depth = 0u;
    ray_17 = camera_ray;
    value = vec3(0f);
    have_value = false;
    loop {
        let _e26 = have_value;
        if !(_e26) {
            let _e28 = ray_17;
            let _e30 = intersect_scene(_e28, false);
            if (_e30.slot == NO_HIT) {
                let _e34 = ray_17;
                let _e36 = F32_INF;
                let _e38 = ray_17;
                let _e39 = miss(_e38);
                let _e40 = through_medium(_e34, bitcast<f32>(_e36), _e39);
                value = _e40;
                have_value = true;
            } else {
                let inst_9 = instances[_e30.slot];
                let _e46 = ray_17;
                let _e47 = finish_hit(_e46, _e30);
                pushed = false;
                let _e56 = ray_17.depth;
                let _e60 = depth;
                if ((((inst_9.flags & FLAG_SECONDARY) != 0u) && (_e56 < MAX_DEPTH)) && (_e60 < STACK_SIZE)) {
                    spawn_count = 0u;
                    let _e68 = ray_17;
                    dispatch_secondary_rays(inst_9.material_type, inst_9.material_offset, _e68, _e47);
                    let _e70 = spawn_count;
                    let n_8 = min(min(_e70, 1u), MAX_SPAWN);
                    if (n_8 > 0u) {
                        let _e77 = ray_17;
                        f = Frame(_e77, _e47, _e30.slot, vec3(0f), array<vec3<f32>, 1>(), array<vec3<f32>, 1>(), n_8, 0u);
                        i_3 = 0u;
                        loop {
                            let _e88 = i_3;
                            if (_e88 >= n_8) {
                                break;
                            }
                            let _e91 = i_3;
                            let _e95 = i_3;
                            let _e98 = spawn_dirs[_e95];
                            f.dirs[min(_e91, 0u)] = _e98;
                            let _e100 = i_3;
                            let _e104 = i_3;
                            let _e107 = spawn_weights[_e104];
                            f.weights[min(_e100, 0u)] = _e107;
                            continuing {
                                let _e108 = i_3;
                                i_3 = (_e108 + 1u);
                            }
                        }
                        let _e111 = depth;
                        let _e115 = f;
                        stack_2[min(_e111, 0u)] = _e115;
                        let _e116 = depth;
                        depth = (_e116 + 1u);
                        pushed = true;
                    }
                }
                let _e120 = pushed;
                if !(_e120) {
                    let _e124 = ray_17;
                    let _e127 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, _e124, _e47, vec3(0f));
                    let _e128 = ray_17;
                    let _e130 = through_medium(_e128, _e30.t, _e127);
                    value = _e130;
                    have_value = true;
                }
            }
        }
        let _e132 = have_value;
        if _e132 {
            let _e133 = depth;
            if (_e133 == 0u) {
                let _e136 = value;
                return _e136;
            }
            let _e137 = depth;
            let top = (_e137 - 1u);
            let _e144 = stack_2[min(top, 0u)].next;
            let child = (_e144 - 1u);
            let _e151 = stack_2[min(top, 0u)].sum;
            let _e159 = stack_2[min(top, 0u)].weights[min(child, 0u)];
            let _e160 = value;
            stack_2[min(top, 0u)].sum = (_e151 + (_e159 * _e160));
            have_value = false;
        }
        let _e164 = depth;
        let top_1 = (_e164 - 1u);
        let _e171 = stack_2[min(top_1, 0u)].next;
        let _e176 = stack_2[min(top_1, 0u)].count;
        if (_e171 < _e176) {
            let i_4 = stack_2[min(top_1, 0u)].next;
            stack_2[min(top_1, 0u)].next = (i_4 + 1u);
            let parent = stack_2[min(top_1, 0u)].ray;
            let hit_7 = stack_2[min(top_1, 0u)].hit;
            let dir_4 = stack_2[min(top_1, 0u)].dirs[min(i_4, 0u)];
            medium = parent.medium;
            let _e209 = spawn_origin(hit_7, dir_4);
            let _e212 = F32_INF;
            let _e218 = medium;
            ray_17 = Ray(_e209, 0f, dir_4, bitcast<f32>(_e212), (parent.depth + 1u), RAY_SECONDARY, _e218);
        } else {
            let _e224 = stack_2[min(top_1, 0u)].slot;
            let inst_10 = instances[_e224];
            let _e234 = stack_2[min(top_1, 0u)].ray;
            let _e239 = stack_2[min(top_1, 0u)].hit;
            let _e244 = stack_2[min(top_1, 0u)].sum;
            let _e245 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e234, _e239, _e244);
            let _e250 = stack_2[min(top_1, 0u)].ray;
            let _e256 = stack_2[min(top_1, 0u)].hit.t;
            let _e257 = through_medium(_e250, _e256, _e245);
            value = _e257;
            depth = top_1;
            have_value = true;
        }
    }
    return vec3<f32>();
}

fn is_finite_vec3f(x_2: vec3<f32>) -> vec3<bool> {
    return ((bitcast<vec3<u32>>(x_2) & vec3(2147483647u)) < vec3(2139095040u));
}

fn finite_or_zero(c_3: vec3<f32>) -> vec3<f32> {
    let _e3 = is_finite_vec3f(c_3);
    return select(vec3(0f), c_3, _e3);
}

fn render_pixel(pixel_3: vec2<u32>) {
    var sum: vec3<f32>;
    var bad: u32;
    var s: u32;
    var ray_18: Ray;

    let frame_5 = frame;
    let tile_1 = tile;
    sum = vec3(0f);
    bad = 0u;
    let end_1 = frame_5.samples_per_pass;
    s = 0u;
    loop {
        let _e13 = s;
        if (_e13 >= end_1) {
            break;
        }
        let _e18 = s;
        let sample_3 = ((tile_1.frame * frame_5.samples_per_pass) + _e18);
        rng_seed(pixel_3, sample_3, frame_5.seed);
        let _e23 = dispatch_ray_generation(frame_5.camera_type, frame_5.camera_offset, pixel_3, sample_3);
        ray_18 = _e23;
        ray_18.depth = 0u;
        ray_18.kind = RAY_CAMERA;
        let _e31 = ray_18.origin;
        let _e32 = medium_at(_e31);
        ray_18.medium = _e32;
        let _e33 = ray_18;
        let _e34 = trace(_e33);
        let _e35 = is_finite_vec3f(_e34);
        if all(_e35) {
            let _e37 = sum;
            sum = (_e37 + _e34);
        } else {
            let _e39 = sum;
            let _e40 = finite_or_zero(_e34);
            sum = (_e39 + _e40);
            let _e42 = bad;
            bad = (_e42 + 1u);
        }
        continuing {
            let _e45 = s;
            s = (_e45 + 1u);
        }
    }
    let _e54 = sum;
    let _e58 = bad;
    let _e61 = accum[((pixel_3.y * tile_1.image_size.x) + pixel_3.x)];
    accum[((pixel_3.y * tile_1.image_size.x) + pixel_3.x)] = (_e61 + vec4<f32>(_e54, f32(frame_5.samples_per_pass)));
    if (_e58 > 0u) {
        atomicAdd((&counters[0]), _e58);
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn render(@builtin(global_invocation_id) gid: vec3<u32>) {
    let _e2 = tile;
    let _e7 = vec2<u32>(gid.x, gid.y);
    if any((_e7 >= _e2.extent)) {
        return;
    }
    render_pixel((_e2.origin + _e7));
    return;
}
