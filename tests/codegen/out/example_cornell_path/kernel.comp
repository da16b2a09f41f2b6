#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

struct TileParams {
    uvec2 origin;
    uvec2 extent;
    uvec2 image_size;
    uint tile_index;
    uint frame;
};
struct FrameUniforms {
    uint samples_per_pass;
    uint total_samples;
    uint seed;
    uint tlas_root;
    uint instance_count;
    uint light_count;
    uint light_table;
    uint medium_count;
    uint medium_table;
    uint camera_type;
    uint camera_offset;
    uint background_type;
    uint background_offset;
    uint path_slots;
    uint passes_per_dispatch;
};
struct PassSum {
    vec3 sum;
    uint bad;
};
struct Ray {
    vec3 origin;
    float tmin;
    vec3 dir;
    float tmax;
    uint depth;
    uint kind;
    uint medium;
};
struct PathState {
    Ray ray;
    vec3 beta;
    vec3 radiance;
    bool live;
};
struct Pinhole {
    vec3 position;
    vec3 look_at;
    vec3 up;
    float fov;
};
struct Candidate {
    float t;
    uint slot;
    uint primitive;
    vec2 uv;
    vec3 normal;
};
struct GpuInstance {
    vec4 world_to_object_0_;
    vec4 world_to_object_1_;
    vec4 world_to_object_2_;
    vec4 object_to_world_0_;
    vec4 object_to_world_1_;
    vec4 object_to_world_2_;
    uint geometry_type;
    uint geometry_offset;
    uint material_type;
    uint material_offset;
    uint blas_root;
    uint triangle_offset;
    uint flags;
    uint object;
};
struct TriangleRay {
    vec3 origin;
    uint kx;
    uint ky;
    uint kz;
    vec3 shear;
    bool valid;
};
struct GpuNode {
    vec3 min_;
    uint a;
    vec3 max_;
    uint b;
};
struct BoxRay {
    vec3 step_;
    vec3 start_lo;
    vec3 start_hi;
    float tmin;
    float unit;
};
struct Hit {
    vec3 position;
    float t;
    vec3 normal;
    vec3 geometric_normal;
    vec2 uv;
    bool front_face;
    uint instance;
    uint primitive;
};
struct Triangle {
    vec3 v0_;
    vec3 v1_;
    vec3 v2_;
};
struct PathDiffuse {
    vec3 albedo;
    uint roulette_depth;
};
struct Emissive {
    vec3 color;
    float intensity;
    uint two_sided;
};
struct LightSample {
    vec3 dir;
    float dist;
    vec3 radiance;
    float pdf;
};
struct QuadLight {
    vec3 corner;
    vec3 edge_u;
    vec3 edge_v;
    vec3 color;
    float intensity;
    uint lamp;
};
const uint WORKGROUP_WIDTH = 8u;
const uint WORKGROUP_HEIGHT = 8u;
const uint NO_HIT = 4294967295u;
const uint SCATTER = 1000003u;
const uint SCRATCH_RNG_INDEX = 12u;
const uint SCRATCH_RNG_SEED = 13u;
const uint HALF_WORD_BITS = 16u;
const uint RAY_CAMERA = 0u;
const bool HAS_MEDIA = false;
const uint MEDIUM_ENTRY_STRIDE = 1u;
const uint MESH_GEOMETRY = 4294967295u;
const uint NODE_LEAF_BIT = 2147483648u;
const uint NODE_COUNT_SHIFT = 27u;
const uint NODE_COUNT_MASK = 15u;
const uint NODE_FIRST_MASK = 134217727u;
const bool HAS_ANY_HIT = false;
const uint BLAS_STACK = 64u;
const uint TLAS_STACK = 7u;
const float POINT_ERROR = 1.9073486e-6;
const float GAMMA_1_ = 5.960465e-8;
const float GAMMA_6_ = 3.576281e-7;
const float GAMMA_4_ = 2.3841864e-7;
const bool HAS_BACKGROUND = false;
const uint FLAG_SECONDARY_RAYS = 2u;
const uint MAX_DEPTH = 6u;
const float INV_PI = 0.31830987;
const float MIS_BOUNCE_LENGTH = 3.0;
const uint SCRATCH_SHADOW_MODE = 14u;
const uint SHADOW_ABOVE = 2u;
const uint LIGHT_ENTRY_STRIDE = 2u;
const uint SHADOW_UNOCCLUDED = 1u;
const float LIGHT_ERROR = 4.7683716e-7;
const uint RAY_SHADOW = 2u;
const uint SHADOW_TRACED = 0u;
const uint ROULETTE_DEPTH = 2u;
const float ROULETTE_THROUGHPUT = 0.5;
const uint RAY_SECONDARY = 1u;

layout(std140, binding = 1) uniform TileParams_block_0Compute { TileParams _group_0_binding_1_cs; };

layout(std140, binding = 0) uniform FrameUniforms_block_1Compute { FrameUniforms _group_0_binding_0_cs; };

uint scratch[15] = uint[15](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

uint rng_state = 0u;

layout(std430, binding = 6) readonly buffer type_6_block_2Compute { uint _group_0_binding_6_cs[]; };

uint F32_INF = 2139095040u;

layout(std430, binding = 3) readonly buffer type_9_block_3Compute { GpuInstance _group_0_binding_3_cs[]; };

layout(std430, binding = 2) readonly buffer type_10_block_4Compute { GpuNode _group_0_binding_2_cs[]; };

layout(std430, binding = 4) readonly buffer type_12_block_5Compute { vec4 _group_0_binding_4_cs[]; };

uint traversal_stack[71] = uint[71](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

float hit_error = 0.0;

layout(std430, binding = 5) readonly buffer type_15_block_6Compute { uvec4 _group_0_binding_5_cs[]; };

uint ray_count = 0u;

vec3 spawn_dirs[1] = vec3[1](vec3(0.0));

vec3 spawn_weights[1] = vec3[1](vec3(0.0));

uint spawn_count = 0u;

layout(std430, binding = 9) buffer type_20_block_7Compute { uint _group_0_binding_9_cs[]; };

layout(std430, binding = 8) buffer type_12_block_8Compute { vec4 _group_0_binding_8_cs[]; };


uvec2 div_vec2u(uvec2 a, uvec2 b) {
    bvec2 by_zero = equal(b, uvec2(0u));
    uvec2 divisor = mix(b, uvec2(1u), by_zero);
    return (a / divisor);
}

uint rem_u32_(uint a_1, uint b_1) {
    bool by_zero_1 = (b_1 == 0u);
    uint divisor_1 = (by_zero_1 ? 1u : b_1);
    return (by_zero_1 ? 0u : (a_1 % divisor_1));
}

uint div_u32_(uint a_2, uint b_2) {
    bool by_zero_2 = (b_2 == 0u);
    uint divisor_2 = (by_zero_2 ? 1u : b_2);
    return (a_2 / divisor_2);
}

uvec2 rem_vec2u(uvec2 a_3, uvec2 b_3) {
    uvec2 _e3 = uvec2(0u);
    bvec2 by_zero_3 = equal(b_3, _e3);
    uvec2 divisor_3 = mix(b_3, uvec2(1u), by_zero_3);
    return mix((a_3 % divisor_3), _e3, by_zero_3);
}

uvec2 scattered_local(uvec2 id) {
    TileParams tile_1 = _group_0_binding_1_cs;
    uvec2 size = uvec2(WORKGROUP_WIDTH, WORKGROUP_HEIGHT);
    uvec2 _e11 = div_vec2u(((tile_1.extent + size) - uvec2(1u)), size);
    uint count = (_e11.x * _e11.y);
    if ((count == 0u)) {
        return uvec2(NO_HIT);
    }
    uvec2 _e19 = div_vec2u(id, size);
    uint order = ((_e19.y * _e11.x) + _e19.x);
    uint _e26 = rem_u32_(SCATTER, count);
    uint _e28 = rem_u32_((order * _e26), count);
    uint _e30 = rem_u32_(_e28, _e11.x);
    uint _e32 = div_u32_(_e28, _e11.x);
    uvec2 _e35 = rem_vec2u(id, size);
    return ((uvec2(_e30, _e32) * size) + _e35);
}

uint pcg_hash(uint x) {
    uint state_1 = ((x * 747796405u) + 2891336453u);
    uint word = (((state_1 >> (((state_1 >> 28u) + 4u) & 31u)) ^ state_1) * 277803737u);
    return ((word >> 22u) ^ word);
}

void rng_resume(uvec2 pixel, uint sample_, uint seed, uint state) {
    scratch[min(SCRATCH_RNG_INDEX, 14u)] = sample_;
    uint _e12 = pcg_hash(seed);
    uint _e14 = pcg_hash((pixel.y ^ _e12));
    uint _e16 = pcg_hash((pixel.x ^ _e14));
    scratch[min(SCRATCH_RNG_SEED, 14u)] = _e16;
    rng_state = state;
    return;
}

void rng_seed(uvec2 pixel_1, uint sample_1, uint seed_1) {
    rng_resume(pixel_1, sample_1, seed_1, 0u);
    return;
}

Pinhole load_Pinhole(uint offset) {
    uint _e5 = _group_0_binding_6_cs[(offset + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset + 4u)];
    uint _e30 = _group_0_binding_6_cs[(offset + 5u)];
    uint _e36 = _group_0_binding_6_cs[(offset + 6u)];
    uint _e43 = _group_0_binding_6_cs[(offset + 8u)];
    uint _e49 = _group_0_binding_6_cs[(offset + 9u)];
    uint _e55 = _group_0_binding_6_cs[(offset + 10u)];
    uint _e62 = _group_0_binding_6_cs[(offset + 11u)];
    return Pinhole(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), vec3(uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55)), uintBitsToFloat(_e62));
}

uvec2 image_size_query() {
    TileParams _e1 = _group_0_binding_1_cs;
    return _e1.image_size;
}

uint samples_per_pixel_query() {
    FrameUniforms _e1 = _group_0_binding_0_cs;
    return _e1.total_samples;
}

uint laine_karras(uint x_1, uint seed_2) {
    uint v = 0u;
    v = (x_1 + seed_2);
    uint _e4 = v;
    uint _e5 = v;
    v = (_e4 ^ (_e5 * 1817228412u));
    uint _e9 = v;
    uint _e10 = v;
    v = (_e9 ^ (_e10 * 3090095698u));
    uint _e14 = v;
    uint _e15 = v;
    v = (_e14 ^ (_e15 * 3350193720u));
    uint _e19 = v;
    uint _e20 = v;
    v = (_e19 ^ (_e20 * 2367878886u));
    uint _e24 = v;
    return _e24;
}

uint sobol_second_reversed(uint i) {
    uint f = 0u;
    f = i;
    uint _e2 = f;
    uint _e3 = f;
    f = (_e2 ^ ((_e3 >> 1u) & 1431655765u));
    uint _e9 = f;
    uint _e10 = f;
    f = (_e9 ^ ((_e10 >> 2u) & 858993459u));
    uint _e16 = f;
    uint _e17 = f;
    f = (_e16 ^ ((_e17 >> 4u) & 252645135u));
    uint _e23 = f;
    uint _e24 = f;
    f = (_e23 ^ ((_e24 >> 8u) & 16711935u));
    uint _e30 = f;
    uint _e31 = f;
    f = (_e30 ^ (_e31 >> (HALF_WORD_BITS & 31u)));
    uint _e37 = f;
    return _e37;
}

float rand_next() {
    uint x_2 = 0u;
    uint d = rng_state;
    rng_state = (d + 1u);
    uint _e10 = scratch[min(SCRATCH_RNG_SEED, 14u)];
    uint _e16 = pcg_hash((_e10 ^ ((d >> 1u) * 2654435769u)));
    uint _e22 = scratch[min(SCRATCH_RNG_INDEX, 14u)];
    uint _e24 = laine_karras(bitfieldReverse(_e22), _e16);
    uint i_5 = bitfieldReverse(_e24);
    x_2 = i_5;
    if (((d & 1u) != 0u)) {
        uint _e31 = sobol_second_reversed(i_5);
        x_2 = _e31;
    }
    uint scramble = (_e16 ^ (((2654435769u * (1u + (d & 1u))) + (_e16 << 6u)) + (_e16 >> 2u)));
    uint _e45 = x_2;
    uint _e46 = laine_karras(_e45, scramble);
    return (float((bitfieldReverse(_e46) >> 8u)) * (1.0 / 16777216.0));
}

vec2 rand2_next() {
    float _e0 = rand_next();
    float _e1 = rand_next();
    return vec2(_e0, _e1);
}

vec3 normalize_vec3f(vec3 v_1) {
    return ((dot(v_1, v_1) >= 1.1754944e-38) ? normalize(v_1) : vec3(0.0));
}

Ray pinhole_ray(Pinhole cam, uvec2 pixel_2, uint sample_2) {
    vec2 jitter = vec2(0.0);
    uvec2 _e2 = image_size_query();
    vec2 size_1 = vec2(_e2);
    jitter = vec2(0.5);
    uint _e7 = samples_per_pixel_query();
    if ((_e7 > 1u)) {
        vec2 _e10 = rand2_next();
        jitter = _e10;
    }
    vec2 _e12 = jitter;
    vec2 ndc = ((((vec2(pixel_2) + _e12) / size_1) * vec2(2.0)) - vec2(1.0));
    vec3 _e24 = normalize_vec3f((cam.look_at - cam.position));
    vec3 _e27 = normalize_vec3f(cross(_e24, cam.up));
    vec3 up = cross(_e27, _e24);
    float h = tan((radians(cam.fov) * 0.5));
    float aspect = (size_1.x / size_1.y);
    vec3 _e48 = normalize_vec3f(((_e24 + (_e27 * vec3(((ndc.x * h) * aspect)))) - (up * vec3((ndc.y * h)))));
    uint _e52 = F32_INF;
    return Ray(cam.position, 0.0, _e48, uintBitsToFloat(_e52), 0u, 0u, 0u);
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uvec2 pixel_3, uint sample_3) {
    Pinhole _e3 = load_Pinhole(offset_1);
    Ray _e4 = pinhole_ray(_e3, pixel_3, sample_3);
    return _e4;
}

Candidate no_candidate(float tmax) {
    return Candidate(tmax, NO_HIT, 0u, vec2(0.0), vec3(0.0));
}

Ray to_object(GpuInstance inst, Ray ray) {
    Ray r = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    r = ray;
    vec4 o = vec4(ray.origin, 1.0);
    vec4 d_1 = vec4(ray.dir, 0.0);
    r.origin = vec3(dot(inst.world_to_object_0_, o), dot(inst.world_to_object_1_, o), dot(inst.world_to_object_2_, o));
    r.dir = vec3(dot(inst.world_to_object_0_, d_1), dot(inst.world_to_object_1_, d_1), dot(inst.world_to_object_2_, d_1));
    Ray _e25 = r;
    return _e25;
}

TriangleRay prepare_triangle_ray(Ray ray_1) {
    vec3 d_2 = mix(ray_1.dir, vec3(0.0), lessThan(abs(ray_1.dir), vec3(1.1754944e-38)));
    vec3 ad = abs(d_2);
    bool y_gt = (ad.y > ad.x);
    uint kz = ((ad.z > (y_gt ? ad.y : ad.x)) ? 2u : (y_gt ? 1u : 0u));
    uint kx0_ = ((kz == 2u) ? 0u : (kz + 1u));
    uint ky0_ = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = d_2[min(kz, 2u)];
    bool flip = (dz < 0.0);
    uint kx = (flip ? ky0_ : kx0_);
    uint ky = (flip ? kx0_ : ky0_);
    uvec3 inf_bits = uvec3(2139095040u);
    bool finite = (all(lessThan((floatBitsToUint(ray_1.origin) & uvec3(2147483647u)), inf_bits)) && all(lessThan((floatBitsToUint(d_2) & uvec3(2147483647u)), inf_bits)));
    return TriangleRay(ray_1.origin, kx, ky, kz, vec3((d_2[min(kx, 2u)] / dz), (d_2[min(ky, 2u)] / dz), (1.0 / dz)), (finite && !((dz == 0.0))));
}

vec3 node_point(vec3 origin, vec3 scale, uvec3 q) {
    return (origin + (vec3(q) * scale));
}

vec3 node_frame_hi(GpuNode header) {
    vec3 _e5 = node_point(header.min_, header.max_, uvec3(65535u));
    return _e5;
}

BoxRay box_ray(GpuNode header_1, Ray ray_2) {
    vec3 origin_2 = header_1.min_;
    vec3 _e3 = node_frame_hi(header_1);
    vec3 extent = (_e3 - origin_2);
    float m_3 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    uint e = min(max(((floatBitsToUint(m_3) >> 23u) & 255u), 1u), 253u);
    vec3 d_3 = (ray_2.dir * vec3(uintBitsToFloat(((254u - e) << 23u))));
    float unit = uintBitsToFloat((e << 23u));
    vec3 floor_ = vec3(9.094947e-13);
    vec3 s_4 = mix(vec3(1.0), vec3(-1.0), lessThan(d_3, vec3(0.0)));
    vec3 inv = (vec3(1.0) / mix(d_3, (s_4 * floor_), lessThan(abs(d_3), floor_)));
    vec3 rel = (origin_2 - ray_2.origin);
    vec3 start = (rel * inv);
    vec3 pad = (((vec3(9.536743e-7) * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_4);
    return BoxRay((header_1.max_ * inv), (start - pad), (start + pad), (ray_2.tmin * unit), unit);
}

vec3 hit_triangle(TriangleRay r_1, uint slot, float tmin, float tmax_1, bool occlusion) {
    vec4 _e9 = _group_0_binding_4_cs[(slot * 3u)];
    vec3 a_4 = (_e9.xyz - r_1.origin);
    vec4 _e19 = _group_0_binding_4_cs[((slot * 3u) + 1u)];
    vec3 b_6 = (_e19.xyz - r_1.origin);
    vec4 _e29 = _group_0_binding_4_cs[((slot * 3u) + 2u)];
    vec3 c_5 = (_e29.xyz - r_1.origin);
    float ax = (a_4[min(r_1.kx, 2u)] - (r_1.shear.x * a_4[min(r_1.kz, 2u)]));
    float ay = (a_4[min(r_1.ky, 2u)] - (r_1.shear.y * a_4[min(r_1.kz, 2u)]));
    float bx = (b_6[min(r_1.kx, 2u)] - (r_1.shear.x * b_6[min(r_1.kz, 2u)]));
    float by = (b_6[min(r_1.ky, 2u)] - (r_1.shear.y * b_6[min(r_1.kz, 2u)]));
    float cx = (c_5[min(r_1.kx, 2u)] - (r_1.shear.x * c_5[min(r_1.kz, 2u)]));
    float cy = (c_5[min(r_1.ky, 2u)] - (r_1.shear.y * c_5[min(r_1.kz, 2u)]));
    float u_1 = ((cx * by) - (cy * bx));
    float v_2 = ((ax * cy) - (ay * cx));
    float w = ((bx * ay) - (by * ax));
    bool outside = ((((u_1 < 0.0) || (v_2 < 0.0)) || (w < 0.0)) && (((u_1 > 0.0) || (v_2 > 0.0)) || (w > 0.0)));
    float det = ((u_1 + v_2) + w);
    float scaled = (((u_1 * (r_1.shear.z * a_4[min(r_1.kz, 2u)])) + (v_2 * (r_1.shear.z * b_6[min(r_1.kz, 2u)]))) + (w * (r_1.shear.z * c_5[min(r_1.kz, 2u)])));
    if (occlusion) {
        float st = ((det < 0.0) ? -(scaled) : scaled);
        float ad_1 = abs(det);
        bool hit_7 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        uint _e178 = F32_INF;
        return (hit_7 ? vec3(tmin, 0.0, 0.0) : vec3(uintBitsToFloat(_e178), 0.0, 0.0));
    }
    float rcp = (1.0 / det);
    float t = (scaled * rcp);
    bool hit_8 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (t >= tmin)) && (t <= tmax_1));
    uint _e202 = F32_INF;
    return (hit_8 ? vec3(t, (v_2 * rcp), (w * rcp)) : vec3(uintBitsToFloat(_e202), 0.0, 0.0));
}

bool accept(GpuInstance inst_1, Ray ray_3, Candidate c) {
    return true;
}

uvec3 node_box_lo(uvec3 p) {
    return uvec3((p.x & 65535u), (p.x >> 16u), (p.y & 65535u));
}

uvec3 node_box_hi(uvec3 p_1) {
    return uvec3((p_1.y >> 16u), (p_1.z & 65535u), (p_1.z >> 16u));
}

float slab_in_frame(vec3 lo, vec3 hi, BoxRay b_4, float tmax_2) {
    vec3 t0_ = fma(lo, b_4.step_, b_4.start_lo);
    vec3 t1_ = fma(hi, b_4.step_, b_4.start_hi);
    bvec3 flip_1 = lessThan(floatBitsToInt(b_4.step_), ivec3(0));
    vec3 near_2 = mix(t0_, t1_, flip_1);
    vec3 far_2 = mix(t1_, t0_, flip_1);
    vec2 e_1 = mix(near_2.xy, near_2.yz, lessThan(near_2.xy, near_2.yz));
    float enter = ((e_1.x < e_1.y) ? e_1.y : e_1.x);
    vec2 x_5 = mix(far_2.xy, far_2.yz, lessThan(far_2.yz, far_2.xy));
    float exit = ((x_5.y < x_5.x) ? x_5.y : x_5.x);
    float enter_t = ((enter < b_4.tmin) ? b_4.tmin : enter);
    float exit_t = ((tmax_2 < exit) ? tmax_2 : exit);
    if ((enter_t <= exit_t)) {
        return enter_t;
    }
    uint _e49 = F32_INF;
    return uintBitsToFloat(_e49);
}

vec2 children_entry(GpuNode n, BoxRay b_5, float tmax_3) {
    uvec3 lq = floatBitsToUint(n.min_);
    uvec3 rq = floatBitsToUint(n.max_);
    float t_1 = (tmax_3 * b_5.unit);
    uvec3 _e9 = node_box_lo(lq);
    uvec3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(vec3(_e9), vec3(_e11), b_5, t_1);
    uvec3 _e14 = node_box_lo(rq);
    uvec3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(vec3(_e14), vec3(_e16), b_5, t_1);
    return vec2(_e13, _e18);
}

uvec2 pop(uint base, uint sp) {
    if ((sp == 0u)) {
        return uvec2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack[min(((base + sp) - 1u), 70u)];
    return uvec2(_e14, (sp - 1u));
}

Candidate intersect_mesh(GpuInstance inst_2, uint slot_1, Ray world_ray, Ray ray_4, Candidate best_in, bool shadow) {
    Candidate best = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint sp_1 = 0u;
    uint child = 0u;
    uint k = 0u;
    uint near = 0u;
    uint far = 0u;
    best = best_in;
    TriangleRay _e7 = prepare_triangle_ray(ray_4);
    uint base_1 = inst_2.blas_root;
    GpuNode header_2 = _group_0_binding_2_cs[base_1];
    BoxRay _e12 = box_ray(header_2, ray_4);
    sp_1 = 0u;
    child = header_2.a;
    while(true) {
        uint _e17 = child;
        if (((_e17 & NODE_LEAF_BIT) != 0u)) {
            uint _e22 = child;
            uint count_1 = ((_e22 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK);
            uint _e29 = child;
            uint first = (_e29 & NODE_FIRST_MASK);
            k = 0u;
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    uint _e75 = k;
                    k = (_e75 + 1u);
                }
                loop_init = false;
                uint _e34 = k;
                if ((_e34 >= count_1)) {
                    break;
                }
                uint _e38 = k;
                uint prim = ((inst_2.triangle_offset + first) + _e38);
                float _e42 = best.t;
                vec3 _e46 = hit_triangle(_e7, prim, ray_4.tmin, _e42, (shadow && !(HAS_ANY_HIT)));
                uint _e49 = F32_INF;
                if ((_e46.x < uintBitsToFloat(_e49))) {
                    vec4 _e58 = _group_0_binding_4_cs[((prim * 3u) + 1u)];
                    uint tag = floatBitsToUint(_e58.w);
                    uint owner = ((tag != 0u) ? ((inst_2.object + tag) - 1u) : slot_1);
                    Candidate c_6 = Candidate(_e46.x, owner, prim, _e46.yz, vec3(0.0));
                    bool _e73 = accept(inst_2, world_ray, c_6);
                    if (_e73) {
                        best = c_6;
                        if (shadow) {
                            Candidate _e74 = best;
                            return _e74;
                        }
                    }
                }
            }
        } else {
            uint _e78 = child;
            GpuNode n_8 = _group_0_binding_2_cs[(base_1 + _e78)];
            float _e84 = best.t;
            vec2 _e85 = children_entry(n_8, _e12, _e84);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if (((tl < uintBitsToFloat(_e89)) && (tr < uintBitsToFloat(_e93)))) {
                near = n_8.a;
                far = n_8.b;
                if (((tr < tl) != shadow)) {
                    near = n_8.b;
                    far = n_8.a;
                }
                uint _e105 = sp_1;
                if ((_e105 < BLAS_STACK)) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack[min((TLAS_STACK + _e109), 70u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if ((tl < uintBitsToFloat(_e121))) {
                child = n_8.a;
                continue;
            }
            uint _e126 = F32_INF;
            if ((tr < uintBitsToFloat(_e126))) {
                child = n_8.b;
                continue;
            }
        }
        uint _e131 = sp_1;
        uvec2 _e132 = pop(TLAS_STACK, _e131);
        if ((_e132.x == NO_HIT)) {
            break;
        }
        child = _e132.x;
        sp_1 = _e132.y;
    }
    Candidate _e138 = best;
    return _e138;
}

Candidate intersect_object(uint slot_2, Ray ray_5, Candidate best_1, bool shadow_1) {
    Ray r_2 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    GpuInstance inst_6 = _group_0_binding_3_cs[slot_2];
    Ray _e7 = to_object(inst_6, ray_5);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_5, _e14, best_1, shadow_1);
        return _e15;
    }
    return best_1;
}

float point_error(vec3 origin_1, vec3 along) {
    vec3 a_5 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_5.x, a_5.y), a_5.z));
}

Triangle load_triangle(uint slot_3) {
    vec4 v0_1 = _group_0_binding_4_cs[(slot_3 * 3u)];
    vec4 v1_ = _group_0_binding_4_cs[((slot_3 * 3u) + 1u)];
    vec4 v2_ = _group_0_binding_4_cs[((slot_3 * 3u) + 2u)];
    return Triangle(v0_1.xyz, v1_.xyz, v2_.xyz);
}

vec3 point_to_world(GpuInstance inst_3, vec3 p_2) {
    vec4 q_1 = vec4(p_2, 1.0);
    return vec3(dot(inst_3.object_to_world_0_, q_1), dot(inst_3.object_to_world_1_, q_1), dot(inst_3.object_to_world_2_, q_1));
}

float mesh_error(GpuInstance inst_4, vec3 v0_, vec3 db1_, vec3 db2_, vec3 p_3) {
    vec3 obj = ((vec3(GAMMA_1_) * abs(v0_)) + (vec3(GAMMA_6_) * (abs(db1_) + abs(db2_))));
    vec4 q_2 = vec4(abs(p_3), 1.0);
    vec4 r0_ = abs(inst_4.object_to_world_0_);
    vec4 r1_ = abs(inst_4.object_to_world_1_);
    vec4 r2_ = abs(inst_4.object_to_world_2_);
    vec3 rounding = (vec3(GAMMA_4_) * vec3(dot(r0_, q_2), dot(r1_, q_2), dot(r2_, q_2)));
    vec3 carried = (vec3((1.0 + GAMMA_4_)) * vec3(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_.xyz, obj)));
    vec3 e_2 = (rounding + carried);
    return max(max(e_2.x, e_2.y), e_2.z);
}

vec3 decode_octahedral(uint bits) {
    vec3 n_1 = vec3(0.0);
    vec2 e_3 = unpackSnorm2x16(bits);
    n_1 = vec3(e_3.x, e_3.y, ((1.0 - abs(e_3.x)) - abs(e_3.y)));
    float _e14 = n_1.z;
    if ((_e14 < 0.0)) {
        vec3 _e21 = n_1;
        vec2 s_5 = mix(vec2(-1.0), vec2(1.0), greaterThanEqual(_e21.xy, vec2(0.0)));
        vec3 _e29 = n_1;
        vec2 xy = ((vec2(1.0) - abs(_e29.yx)) * s_5);
        float _e37 = n_1.z;
        n_1 = vec3(xy.x, xy.y, _e37);
    }
    vec3 _e39 = n_1;
    vec3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

vec3 normal_to_world(GpuInstance inst_5, vec3 n_2) {
    vec3 w_1 = (((inst_5.world_to_object_0_.xyz * vec3(n_2.x)) + (inst_5.world_to_object_1_.xyz * vec3(n_2.y))) + (inst_5.world_to_object_2_.xyz * vec3(n_2.z)));
    vec3 _e19 = normalize_vec3f(w_1);
    return _e19;
}

Hit finish_hit(Ray ray_6, Candidate c_1) {
    Hit hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    vec3 n_geo = vec3(0.0);
    vec3 n_shade = vec3(0.0);
    GpuInstance inst_7 = _group_0_binding_3_cs[c_1.slot];
    float _e11 = point_error(ray_6.origin, (ray_6.dir * vec3(c_1.t)));
    hit_error = _e11;
    hit = Hit((ray_6.origin + (ray_6.dir * vec3(c_1.t))), c_1.t, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if ((inst_7.geometry_type == MESH_GEOMETRY)) {
        Triangle _e42 = load_triangle(c_1.primitive);
        vec2 b_7 = c_1.uv;
        float w_2 = ((1.0 - b_7.x) - b_7.y);
        vec3 e1_ = (_e42.v1_ - _e42.v0_);
        vec3 e2_ = (_e42.v2_ - _e42.v0_);
        vec3 p_8 = (_e42.v0_ + ((e1_ * vec3(b_7.x)) + (e2_ * vec3(b_7.y))));
        vec3 _e65 = point_to_world(inst_7, p_8);
        hit.position = _e65;
        float _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * vec3(b_7.x)), (e2_ * vec3(b_7.y)), p_8);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        uvec4 a0_ = _group_0_binding_5_cs[(c_1.primitive * 2u)];
        uvec4 a1_ = _group_0_binding_5_cs[((c_1.primitive * 2u) + 1u)];
        vec3 _e91 = decode_octahedral(a0_.x);
        vec3 _e95 = decode_octahedral(a0_.y);
        vec3 _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * vec3(w_2)) + (_e95 * vec3(b_7.x))) + (_e101 * vec3(b_7.y)));
        vec3 _e106 = n_shade;
        vec3 _e107 = n_shade;
        if ((dot(_e106, _e107) < 1e-12)) {
            vec3 _e111 = n_geo;
            n_shade = _e111;
        }
        vec2 uv0_ = unpackHalf2x16(a0_.w);
        vec2 uv1_ = unpackHalf2x16(a1_.x);
        vec2 uv2_ = unpackHalf2x16(a1_.y);
        hit.uv = (((uv0_ * vec2(w_2)) + (uv1_ * vec2(b_7.x))) + (uv2_ * vec2(b_7.y)));
        vec4 _e135 = _group_0_binding_4_cs[(c_1.primitive * 3u)];
        hit.primitive = floatBitsToUint(_e135.w);
    }
    vec3 _e139 = n_geo;
    vec3 _e140 = normal_to_world(inst_7, _e139);
    hit.geometric_normal = _e140;
    vec3 _e142 = n_shade;
    vec3 _e143 = normal_to_world(inst_7, _e142);
    hit.normal = _e143;
    vec3 _e147 = hit.geometric_normal;
    hit.front_face = (dot(ray_6.dir, _e147) < 0.0);
    Hit _e151 = hit;
    return _e151;
}

uint medium_at(vec3 p_4, uint exclude) {
    uint inside = 0u;
    float nearest = 0.0;
    uint i_1 = 0u;
    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = _group_0_binding_0_cs;
    vec3 _e12 = normalize_vec3f(vec3(0.5773, 0.5774, 0.5775));
    uint _e14 = F32_INF;
    Ray probe = Ray(p_4, 0.0, _e12, uintBitsToFloat(_e14), 0u, 0u, 0u);
    inside = 0u;
    uint _e23 = F32_INF;
    nearest = uintBitsToFloat(_e23);
    uint end = frame_1.medium_count;
    i_1 = 0u;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e59 = i_1;
            i_1 = (_e59 + 1u);
        }
        loop_init_1 = false;
        uint _e29 = i_1;
        if ((_e29 >= end)) {
            break;
        }
        uint _e32 = i_1;
        uint slot_4 = _group_0_binding_6_cs[(frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE))];
        if ((slot_4 != exclude)) {
            uint _e41 = F32_INF;
            Candidate _e43 = no_candidate(uintBitsToFloat(_e41));
            Candidate _e45 = intersect_object(slot_4, probe, _e43, false);
            float _e50 = nearest;
            if (((_e45.slot != NO_HIT) && (_e45.t < _e50))) {
                Hit _e53 = finish_hit(probe, _e45);
                if (!(_e53.front_face)) {
                    inside = (slot_4 + 1u);
                    nearest = _e45.t;
                }
            }
        }
    }
    uint _e62 = inside;
    return _e62;
}

Ray sample_camera_ray(uvec2 pixel_4, uint sample_4) {
    Ray ray_7 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    FrameUniforms frame_2 = _group_0_binding_0_cs;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_7 = _e7;
    ray_7.depth = 0u;
    ray_7.kind = RAY_CAMERA;
    vec3 _e15 = ray_7.origin;
    uint _e17 = medium_at(_e15, NO_HIT);
    ray_7.medium = _e17;
    Ray _e18 = ray_7;
    return _e18;
}

PathState start_path(Ray ray_8) {
    return PathState(ray_8, vec3(1.0), vec3(0.0), true);
}

vec3 node_frame_bounds() {
    return vec3(65535.0);
}

Candidate intersect_scene(Ray ray_9, bool shadow_2) {
    Candidate best_2 = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint sp_2 = 0u;
    uint child_1 = 0u;
    uint near_1 = 0u;
    uint far_1 = 0u;
    uint _e3 = ray_count;
    ray_count = (_e3 + 1u);
    Candidate _e7 = no_candidate(ray_9.tmax);
    best_2 = _e7;
    FrameUniforms frame_3 = _group_0_binding_0_cs;
    if ((frame_3.instance_count == 0u)) {
        Candidate _e14 = best_2;
        return _e14;
    }
    uint base_2 = frame_3.tlas_root;
    GpuNode header_3 = _group_0_binding_2_cs[base_2];
    BoxRay _e19 = box_ray(header_3, ray_9);
    vec3 _e22 = node_frame_bounds();
    float _e24 = best_2.t;
    float _e27 = slab_in_frame(vec3(0.0), _e22, _e19, (_e24 * _e19.unit));
    uint _e29 = F32_INF;
    if ((_e27 == uintBitsToFloat(_e29))) {
        Candidate _e32 = best_2;
        return _e32;
    }
    sp_2 = 0u;
    child_1 = header_3.a;
    while(true) {
        uint _e37 = child_1;
        if (((_e37 & NODE_LEAF_BIT) != 0u)) {
            uint _e42 = child_1;
            if ((((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u)) {
                uint _e51 = child_1;
                Candidate _e54 = best_2;
                Candidate _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_9, _e54, shadow_2);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if ((shadow_2 && (_e57 != NO_HIT))) {
                    Candidate _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_9 = _group_0_binding_2_cs[(base_2 + _e62)];
            float _e68 = best_2.t;
            vec2 _e69 = children_entry(n_9, _e19, _e68);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if (((tl_1 < uintBitsToFloat(_e73)) && (tr_1 < uintBitsToFloat(_e77)))) {
                near_1 = n_9.a;
                far_1 = n_9.b;
                if ((tr_1 < tl_1)) {
                    near_1 = n_9.b;
                    far_1 = n_9.a;
                }
                uint _e88 = sp_2;
                if ((_e88 < TLAS_STACK)) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack[min(_e91, 70u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if ((tl_1 < uintBitsToFloat(_e102))) {
                child_1 = n_9.a;
                continue;
            }
            uint _e107 = F32_INF;
            if ((tr_1 < uintBitsToFloat(_e107))) {
                child_1 = n_9.b;
                continue;
            }
        }
        uint _e112 = sp_2;
        uvec2 _e113 = pop(0u, _e112);
        if ((_e113.x == NO_HIT)) {
            break;
        }
        child_1 = _e113.x;
        sp_2 = _e113.y;
    }
    Candidate _e119 = best_2;
    return _e119;
}

vec3 dispatch_miss(uint type_id_1, uint offset_2, Ray ray_10) {
    return vec3(0.0);
}

vec3 miss(Ray ray_11) {
    if (!(HAS_BACKGROUND)) {
        return vec3(0.0);
    }
    FrameUniforms frame_4 = _group_0_binding_0_cs;
    vec3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_11);
    return _e9;
}

PathDiffuse load_PathDiffuse(uint offset_3) {
    uint _e5 = _group_0_binding_6_cs[(offset_3 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_3 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_3 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_3 + 3u)];
    return PathDiffuse(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), _e24);
}

mat3x3 orthonormal_basis(vec3 n_3) {
    float sign_ = (((floatBitsToUint(n_3.z) & 2147483648u) != 0u) ? -1.0 : 1.0);
    float a_6 = (-1.0 / (sign_ + n_3.z));
    float b_8 = ((n_3.x * n_3.y) * a_6);
    float _e16 = (sign_ * n_3.x);
    return mat3x3(vec3((1.0 + ((_e16 * n_3.x) * a_6)), (sign_ * b_8), -(_e16)), vec3(b_8, (sign_ + ((n_3.y * n_3.y) * a_6)), -(n_3.y)), n_3);
}

vec3 sample_cosine_hemisphere(vec3 n_4, vec2 u) {
    float r_3 = sqrt(u.x);
    float phi = (6.2831855 * u.y);
    vec3 local = vec3((r_3 * cos(phi)), (r_3 * sin(phi)), sqrt(max((1.0 - u.x), 0.0)));
    mat3x3 _e17 = orthonormal_basis(n_4);
    return (_e17 * local);
}

vec3 mis_bounce_dir(vec3 dir, float pdf) {
    float x_6 = min((log((1.0 + max(pdf, 0.0))) * (1.0 / 90.0)), 0.999);
    return (dir * vec3((MIS_BOUNCE_LENGTH + x_6)));
}

void rt_spawn(vec3 dir_1, vec3 weight) {
    uint _e3 = spawn_count;
    if ((_e3 < 1u)) {
        spawn_dirs[_e3] = dir_1;
        spawn_weights[_e3] = weight;
        spawn_count = (_e3 + 1u);
    }
}

void path_diffuse_rays(PathDiffuse m, Ray ray_12, Hit hit_1) {
    vec3 weight_1 = vec3(0.0);
    vec3 ng = (hit_1.front_face ? hit_1.geometric_normal : -(hit_1.geometric_normal));
    vec3 n_10 = faceforward(hit_1.normal, -(ng), hit_1.normal);
    vec2 _e12 = rand2_next();
    vec3 _e13 = sample_cosine_hemisphere(n_10, _e12);
    weight_1 = m.albedo;
    if ((ray_12.depth >= m.roulette_depth)) {
        float q_3 = clamp(max(m.albedo.x, max(m.albedo.y, m.albedo.z)), 0.0, 1.0);
        float _e28 = rand_next();
        if ((_e28 >= q_3)) {
            return;
        }
        weight_1 = (m.albedo / vec3(q_3));
    }
    if ((dot(_e13, ng) > 0.0)) {
        vec3 _e41 = mis_bounce_dir(_e13, (max(dot(n_10, _e13), 0.0) * INV_PI));
        vec3 _e42 = weight_1;
        rt_spawn(_e41, _e42);
    }
    return;
}

void dispatch_secondary_rays(uint type_id_2, uint offset_4, Ray ray_13, Hit hit_2) {
    PathDiffuse _e3 = load_PathDiffuse(offset_4);
    path_diffuse_rays(_e3, ray_13, hit_2);
    return;
}

Emissive load_Emissive(uint offset_5) {
    uint _e5 = _group_0_binding_6_cs[(offset_5 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_5 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_5 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_5 + 3u)];
    uint _e30 = _group_0_binding_6_cs[(offset_5 + 4u)];
    return Emissive(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24), _e30);
}

bool after_nee_bounce(Ray ray_14) {
    return (dot(ray_14.dir, ray_14.dir) > 2.0);
}

vec3 emissive_shade(Emissive m_1, Ray ray_15, Hit hit_3) {
    bool _e3 = after_nee_bounce(ray_15);
    if ((_e3 || (!(hit_3.front_face) && (m_1.two_sided == 0u)))) {
        return vec3(0.0);
    }
    return (m_1.color * vec3(m_1.intensity));
}

uint light_count_query() {
    FrameUniforms _e1 = _group_0_binding_0_cs;
    return _e1.light_count;
}

QuadLight load_QuadLight(uint offset_6) {
    uint _e5 = _group_0_binding_6_cs[(offset_6 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_6 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_6 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_6 + 4u)];
    uint _e30 = _group_0_binding_6_cs[(offset_6 + 5u)];
    uint _e36 = _group_0_binding_6_cs[(offset_6 + 6u)];
    uint _e43 = _group_0_binding_6_cs[(offset_6 + 8u)];
    uint _e49 = _group_0_binding_6_cs[(offset_6 + 9u)];
    uint _e55 = _group_0_binding_6_cs[(offset_6 + 10u)];
    uint _e62 = _group_0_binding_6_cs[(offset_6 + 12u)];
    uint _e68 = _group_0_binding_6_cs[(offset_6 + 13u)];
    uint _e74 = _group_0_binding_6_cs[(offset_6 + 14u)];
    uint _e81 = _group_0_binding_6_cs[(offset_6 + 15u)];
    uint _e87 = _group_0_binding_6_cs[(offset_6 + 16u)];
    return QuadLight(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), vec3(uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55)), vec3(uintBitsToFloat(_e62), uintBitsToFloat(_e68), uintBitsToFloat(_e74)), uintBitsToFloat(_e81), _e87);
}

float shadow_preset(vec3 normal, vec3 dir_2) {
    uint mode = scratch[min(SCRATCH_SHADOW_MODE, 14u)];
    if ((mode == SHADOW_UNOCCLUDED)) {
        return 1.0;
    }
    if (((mode == SHADOW_ABOVE) && !((dot(dir_2, normal) > 0.0)))) {
        return 0.0;
    }
    return -1.0;
}

vec3 step_toward(vec3 x_3, vec3 s) {
    uvec3 bits_1 = floatBitsToUint(x_3);
    bvec3 up_1 = greaterThan((sign(x_3) * sign(s)), vec3(0.0));
    vec3 stepped = uintBitsToFloat(mix((bits_1 - uvec3(1u)), (bits_1 + uvec3(1u)), up_1));
    vec3 from_zero = mix(vec3(-1.1754944e-38), vec3(1.1754944e-38), greaterThan(s, vec3(0.0)));
    vec3 moved = mix(stepped, from_zero, equal(x_3, vec3(0.0)));
    return mix(x_3, moved, not(equal(s, vec3(0.0))));
}

vec3 offset_origin(vec3 p_5, vec3 n_5, float error) {
    float d_4 = ((2.0 * error) * ((abs(n_5.x) + abs(n_5.y)) + abs(n_5.z)));
    vec3 offset_9 = (n_5 * vec3(d_4));
    vec3 _e17 = step_toward((p_5 + offset_9), offset_9);
    return _e17;
}

Ray shadow_ray(vec3 position, vec3 normal_1, vec3 dir_3, float dist) {
    vec3 n_6 = vec3(0.0);
    float tmax_4 = 0.0;
    n_6 = normal_1;
    vec3 _e5 = n_6;
    if ((dot(dir_3, _e5) < 0.0)) {
        vec3 _e9 = n_6;
        n_6 = -(_e9);
    }
    vec3 a_7 = abs(position);
    float _e13 = hit_error;
    float error_3 = max(_e13, (GAMMA_4_ * max(max(a_7.x, a_7.y), a_7.z)));
    vec3 _e22 = n_6;
    vec3 _e23 = offset_origin(position, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = uintBitsToFloat(_e25);
    uint _e29 = F32_INF;
    if ((dist < uintBitsToFloat(_e29))) {
        vec3 light = (position + (dir_3 * vec3(dist)));
        float dd = dot(dir_3, dir_3);
        float along_1 = (dot((light - _e23), dir_3) / dd);
        vec3 l_2 = (abs(position) + abs((dir_3 * vec3(dist))));
        tmax_4 = ((along_1 * (1.0 - 1e-5)) - ((LIGHT_ERROR * max(max(l_2.x, l_2.y), l_2.z)) / sqrt(dd)));
    }
    float _e59 = tmax_4;
    return Ray(_e23, 0.0, dir_3, _e59, 0u, RAY_SHADOW, 0u);
}

float shadow_query(vec3 position_1, vec3 normal_2, vec3 dir_4, float dist_1) {
    float _e4 = shadow_preset(normal_2, dir_4);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_1, normal_2, dir_4, dist_1);
    Candidate _e9 = intersect_scene(_e7, true);
    return ((_e9.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample quad_light(QuadLight l, vec3 position_2, vec3 normal_3) {
    vec3 c_7 = cross(l.edge_u, l.edge_v);
    float area = length(c_7);
    vec2 _e7 = rand2_next();
    vec3 to_light = (((l.corner + (l.edge_u * vec3(_e7.x))) + (l.edge_v * vec3(_e7.y))) - position_2);
    float dist2_ = dot(to_light, to_light);
    float dist_2 = sqrt(dist2_);
    vec3 dir_8 = (to_light / vec3(max(dist_2, 1e-20)));
    float cos_light = (-(dot(dir_8, c_7)) / max(area, 1e-30));
    if ((!((cos_light > 0.0)) || !((dist2_ > 0.0)))) {
        return LightSample(dir_8, dist_2, vec3(0.0), 0.0);
    }
    float _e42 = shadow_query(position_2, normal_3, dir_8, dist_2);
    float strength = (((l.intensity * cos_light) * area) / dist2_);
    float pdf_1 = ((l.lamp == 1u) ? (dist2_ / (cos_light * area)) : 0.0);
    return LightSample(dir_8, dist_2, ((l.color * vec3(strength)) * vec3(_e42)), pdf_1);
}

LightSample dispatch_light(uint type_id_3, uint offset_7, vec3 position_3, vec3 normal_4) {
    QuadLight _e3 = load_QuadLight(offset_7);
    LightSample _e4 = quad_light(_e3, position_3, normal_4);
    return _e4;
}

LightSample sample_light_query(uint i_2, vec3 position_4, vec3 normal_5) {
    FrameUniforms frame_5 = _group_0_binding_0_cs;
    if ((i_2 >= frame_5.light_count)) {
        return LightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0);
    }
    uint entry = (frame_5.light_table + (i_2 * LIGHT_ENTRY_STRIDE));
    uint _e22 = _group_0_binding_6_cs[entry];
    uint _e27 = _group_0_binding_6_cs[(entry + 1u)];
    LightSample _e28 = dispatch_light(_e22, _e27, position_4, normal_5);
    return _e28;
}

LightSample sample_light_above_query(uint i_3, vec3 position_5, vec3 normal_6) {
    scratch[min(SCRATCH_SHADOW_MODE, 14u)] = SHADOW_ABOVE;
    LightSample _e9 = sample_light_query(i_3, position_5, normal_6);
    scratch[min(SCRATCH_SHADOW_MODE, 14u)] = SHADOW_TRACED;
    return _e9;
}

float mis_weight(float p_6, float other) {
    if (!((p_6 > 0.0))) {
        return 0.0;
    }
    float r_4 = (max(other, 0.0) / p_6);
    if (!((r_4 < 1e18))) {
        uint _e15 = F32_INF;
        uint _e19 = F32_INF;
        return (((p_6 == uintBitsToFloat(_e15)) && (other < uintBitsToFloat(_e19))) ? 1.0 : 0.0);
    }
    return (1.0 / (1.0 + (r_4 * r_4)));
}

float mis_light_weight(LightSample l_1, float bsdf_pdf) {
    if (!((l_1.pdf > 0.0))) {
        return 1.0;
    }
    float _e8 = mis_weight(l_1.pdf, bsdf_pdf);
    return _e8;
}

vec3 path_diffuse_shade(PathDiffuse m_2, Ray ray_16, Hit hit_4, vec3 secondary) {
    vec3 direct = vec3(0.0);
    uint i_4 = 0u;
    vec3 n_11 = faceforward(hit_4.normal, ray_16.dir, hit_4.geometric_normal);
    vec3 ng_1 = faceforward(hit_4.geometric_normal, ray_16.dir, hit_4.geometric_normal);
    direct = vec3(0.0);
    uint _e16 = light_count_query();
    i_4 = 0u;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e36 = i_4;
            i_4 = (_e36 + 1u);
        }
        loop_init_2 = false;
        uint _e18 = i_4;
        if ((_e18 >= _e16)) {
            break;
        }
        uint _e20 = i_4;
        LightSample _e22 = sample_light_above_query(_e20, hit_4.position, ng_1);
        float c_8 = max(dot(n_11, _e22.dir), 0.0);
        vec3 _e27 = direct;
        float _e31 = mis_light_weight(_e22, (c_8 * INV_PI));
        direct = (_e27 + (_e22.radiance * vec3((c_8 * _e31))));
    }
    vec3 _e43 = direct;
    return (((m_2.albedo * vec3(INV_PI)) * _e43) + secondary);
}

vec3 dispatch_closest_hit(uint type_id_4, uint offset_8, Ray ray_17, Hit hit_5, vec3 secondary_1) {
    switch(type_id_4) {
        case 0u: {
            Emissive _e5 = load_Emissive(offset_8);
            vec3 _e6 = emissive_shade(_e5, ray_17, hit_5);
            return _e6;
        }
        case 1u: {
            PathDiffuse _e7 = load_PathDiffuse(offset_8);
            vec3 _e8 = path_diffuse_shade(_e7, ray_17, hit_5, secondary_1);
            return _e8;
        }
        default: {
            break;
        }
    }
    return vec3(0.0);
}

vec3 spawn_origin_at(vec3 position_6, vec3 normal_7, float error_1, vec3 dir_5) {
    vec3 n_7 = vec3(0.0);
    n_7 = normal_7;
    vec3 _e5 = n_7;
    if ((dot(dir_5, _e5) < 0.0)) {
        vec3 _e9 = n_7;
        n_7 = -(_e9);
    }
    vec3 _e11 = n_7;
    vec3 _e12 = offset_origin(position_6, _e11, error_1);
    return _e12;
}

vec3 spawn_origin(Hit hit_6, float error_2, vec3 dir_6) {
    vec3 _e5 = spawn_origin_at(hit_6.position, hit_6.geometric_normal, error_2, dir_6);
    return _e5;
}

PathState path_step(PathState s_1, Candidate c_2) {
    PathState out_ = PathState(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), vec3(0.0), vec3(0.0), false);
    bool spawned = false;
    vec3 dir_7 = vec3(0.0);
    vec3 weight_2 = vec3(0.0);
    vec3 beta = vec3(0.0);
    Ray ray_18 = s_1.ray;
    out_ = s_1;
    out_.live = false;
    if ((c_2.slot == NO_HIT)) {
        hit_error = 0.0;
        vec3 _e14 = miss(ray_18);
        out_.radiance = (s_1.radiance + (s_1.beta * _e14));
        PathState _e17 = out_;
        return _e17;
    }
    GpuInstance inst_8 = _group_0_binding_3_cs[c_2.slot];
    Hit _e22 = finish_hit(ray_18, c_2);
    float error_4 = hit_error;
    spawned = false;
    dir_7 = vec3(0.0);
    weight_2 = vec3(0.0);
    if ((((inst_8.flags & FLAG_SECONDARY_RAYS) != 0u) && (ray_18.depth < MAX_DEPTH))) {
        spawn_count = 0u;
        dispatch_secondary_rays(inst_8.material_type, inst_8.material_offset, ray_18, _e22);
        uint _e47 = spawn_count;
        if ((min(_e47, 1u) > 0u)) {
            spawned = true;
            vec3 _e56 = spawn_dirs[0u];
            dir_7 = _e56;
            vec3 _e60 = spawn_weights[0u];
            weight_2 = _e60;
        }
    }
    vec3 _e68 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_18, _e22, vec3(0.0));
    out_.radiance = (s_1.radiance + (s_1.beta * _e68));
    bool _e71 = spawned;
    if (!(_e71)) {
        PathState _e73 = out_;
        return _e73;
    }
    vec3 _e75 = weight_2;
    beta = (s_1.beta * _e75);
    float _e79 = beta.x;
    float _e81 = beta.y;
    float _e83 = beta.z;
    float q_4 = max(_e79, max(_e81, _e83));
    if (!((q_4 > 0.0))) {
        PathState _e89 = out_;
        return _e89;
    }
    if ((((ROULETTE_DEPTH > 0u) && ((ray_18.depth + 1u) >= ROULETTE_DEPTH)) && (q_4 < ROULETTE_THROUGHPUT))) {
        float survive = (q_4 / ROULETTE_THROUGHPUT);
        float _e104 = rand_next();
        if ((_e104 >= survive)) {
            PathState _e106 = out_;
            return _e106;
        }
        vec3 _e107 = beta;
        beta = (_e107 / vec3(survive));
    }
    vec3 _e111 = beta;
    out_.beta = _e111;
    vec3 _e113 = dir_7;
    vec3 _e114 = spawn_origin(_e22, error_4, _e113);
    vec3 _e116 = dir_7;
    uint _e118 = F32_INF;
    out_.ray = Ray(_e114, 0.0, _e116, uintBitsToFloat(_e118), (ray_18.depth + 1u), RAY_SECONDARY, ray_18.medium);
    out_.live = true;
    PathState _e128 = out_;
    return _e128;
}

bvec3 is_finite_vec3f(vec3 x_4) {
    return lessThan((floatBitsToUint(x_4) & uvec3(2147483647u)), uvec3(2139095040u));
}

vec3 finite_or_zero(vec3 c_3) {
    bvec3 _e3 = is_finite_vec3f(c_3);
    return mix(vec3(0.0), c_3, _e3);
}

PassSum add_sample(PassSum p_7, vec3 c_4, uint s_2, uint index, uint first_pass, uint per_pass) {
    PassSum next = PassSum(vec3(0.0), 0u);
    next = p_7;
    bvec3 _e7 = is_finite_vec3f(c_4);
    if (all(_e7)) {
        vec3 _e10 = next.sum;
        next.sum = (_e10 + c_4);
    } else {
        vec3 _e13 = next.sum;
        vec3 _e14 = finite_or_zero(c_4);
        next.sum = (_e13 + _e14);
        uint _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    uint _e22 = rem_u32_((s_2 + 1u), per_pass);
    if ((_e22 != 0u)) {
        PassSum _e25 = next;
        return _e25;
    }
    uint _e27 = ray_count;
    atomicAdd(_group_0_binding_9_cs[1], _e27);
    ray_count = 0u;
    uint _e31 = div_u32_(s_2, per_pass);
    uint pass = (first_pass + _e31);
    vec3 _e34 = next.sum;
    vec4 _e36 = vec4(_e34, float(per_pass));
    uint _e38 = next.bad;
    if ((pass == 0u)) {
        _group_0_binding_8_cs[index] = _e36;
    } else {
        vec4 _e43 = _group_0_binding_8_cs[index];
        _group_0_binding_8_cs[index] = (_e43 + _e36);
    }
    if ((_e38 > 0u)) {
        atomicAdd(_group_0_binding_9_cs[0], _e38);
    }
    return PassSum(vec3(0.0), 0u);
}

void render_pixel(uvec2 pixel_5) {
    PassSum sums = PassSum(vec3(0.0), 0u);
    uint s_3 = 0u;
    PathState path = PathState(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), vec3(0.0), vec3(0.0), false);
    FrameUniforms frame_6 = _group_0_binding_0_cs;
    TileParams tile_2 = _group_0_binding_1_cs;
    uint index_1 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = (tile_2.frame * per_pass_1);
    uint count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = PassSum(vec3(0.0), 0u);
    s_3 = 0u;
    Ray _e25 = sample_camera_ray(pixel_5, first_1);
    PathState _e26 = start_path(_e25);
    path = _e26;
    while(true) {
        PathState _e28 = path;
        Ray _e30 = path.ray;
        Candidate _e32 = intersect_scene(_e30, false);
        PathState _e33 = path_step(_e28, _e32);
        path = _e33;
        bool _e35 = path.live;
        if (!(_e35)) {
            PassSum _e37 = sums;
            vec3 _e39 = path.radiance;
            uint _e40 = s_3;
            PassSum _e42 = add_sample(_e37, _e39, _e40, index_1, tile_2.frame, per_pass_1);
            sums = _e42;
            uint _e43 = s_3;
            s_3 = (_e43 + 1u);
            uint _e46 = s_3;
            if ((_e46 >= count_2)) {
                break;
            }
            uint _e48 = s_3;
            Ray _e50 = sample_camera_ray(pixel_5, (first_1 + _e48));
            PathState _e51 = start_path(_e50);
            path = _e51;
        }
    }
    return;
}

void render_invocation(uvec2 id_1) {
    TileParams tile_3 = _group_0_binding_1_cs;
    uvec2 _e3 = scattered_local(id_1);
    if (any(greaterThanEqual(_e3, tile_3.extent))) {
        return;
    }
    render_pixel((tile_3.origin + _e3));
    return;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    render_invocation(uvec2(gid.x, gid.y));
    return;
}

