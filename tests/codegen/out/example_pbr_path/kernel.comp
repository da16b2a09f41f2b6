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
struct Sphere {
    vec3 center;
    float radius;
};
struct Intersection {
    float t;
    vec3 normal;
    vec2 uv;
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
struct ConstantBackground {
    vec3 color;
};
struct PathDiffuse {
    vec3 albedo;
    uint roulette_depth;
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
struct SphereLight {
    vec3 position;
    float radius;
    vec3 color;
    float intensity;
    uint lamp;
};
struct QuadLamp {
    vec3 color;
    float intensity;
    float area;
};
struct SphereLamp {
    vec3 color;
    float intensity;
    float radius;
};
struct PathPbr {
    vec3 base_color;
    float metallic;
    float roughness;
    vec3 emissive;
    uint roulette_depth;
};
struct PathState {
    Ray ray;
    vec3 beta;
    vec3 radiance;
    bool live;
};
struct PbrSample {
    vec3 dir;
    vec3 weight;
    float pdf;
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
const uint TLAS_STACK = 8u;
const float TAU = 6.2831855;
const float INV_PI = 0.31830987;
const float POINT_ERROR = 1.9073486e-6;
const float GAMMA_1_ = 5.960465e-8;
const float GAMMA_6_ = 3.576281e-7;
const float GAMMA_4_ = 2.3841864e-7;
const bool HAS_SECONDARY_RAYS = true;
const bool HAS_BACKGROUND = true;
const uint SCRATCH_SHADOW_MODE = 14u;
const uint SHADOW_ABOVE = 2u;
const uint LIGHT_ENTRY_STRIDE = 2u;
const uint SCRATCH_RESOLVED = 3u;
const uint SCRATCH_LIGHT_BITS = 11u;
const uint SCRATCH_QUERY = 2u;
const uint SCRATCH_PENDING = 4u;
const uint SHADOW_UNOCCLUDED = 1u;
const uint LIGHT_QUERIES = 32u;
const uint COUNTER_SHADOW_OVERFLOW = 3u;
const uint SCRATCH_LIGHT_QUERY = 15u;
const float LIGHT_ERROR = 4.7683716e-7;
const uint RAY_SHADOW = 2u;
const uint SHADOW_TRACED = 0u;
const float MIS_BOUNCE_LENGTH = 3.0;
const float PBR_MIN_ALPHA = 0.001;
const uint FLAG_MEDIUM = 4u;
const uint FLAG_SECONDARY_RAYS = 2u;
const uint MAX_DEPTH = 5u;
const uint ROULETTE_DEPTH = 2u;
const float ROULETTE_THROUGHPUT = 0.5;
const uint RAY_SECONDARY = 1u;

layout(std140, binding = 1) uniform TileParams_block_0Compute { TileParams _group_0_binding_1_cs; };

layout(std140, binding = 0) uniform FrameUniforms_block_1Compute { FrameUniforms _group_0_binding_0_cs; };

uint scratch[25] = uint[25](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

uint rng_state = 0u;

layout(std430, binding = 6) readonly buffer type_5_block_2Compute { uint _group_0_binding_6_cs[]; };

uint F32_INF = 2139095040u;

layout(std430, binding = 3) readonly buffer type_9_block_3Compute { GpuInstance _group_0_binding_3_cs[]; };

layout(std430, binding = 2) readonly buffer type_10_block_4Compute { GpuNode _group_0_binding_2_cs[]; };

layout(std430, binding = 4) readonly buffer type_12_block_5Compute { vec4 _group_0_binding_4_cs[]; };

uint traversal_stack[72] = uint[72](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

float hit_error = 0.0;

layout(std430, binding = 5) readonly buffer type_15_block_6Compute { uvec4 _group_0_binding_5_cs[]; };

uint ray_count = 0u;

layout(std430, binding = 9) buffer type_17_block_7Compute { uint _group_0_binding_9_cs[]; };

vec3 spawn_dirs[1] = vec3[1](vec3(0.0));

vec3 spawn_weights[1] = vec3[1](vec3(0.0));

uint spawn_count = 0u;

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
    scratch[min(SCRATCH_RNG_INDEX, 24u)] = sample_;
    uint _e12 = pcg_hash(seed);
    uint _e14 = pcg_hash((pixel.y ^ _e12));
    uint _e16 = pcg_hash((pixel.x ^ _e14));
    scratch[min(SCRATCH_RNG_SEED, 24u)] = _e16;
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
    uint _e10 = scratch[min(SCRATCH_RNG_SEED, 24u)];
    uint _e16 = pcg_hash((_e10 ^ ((d >> 1u) * 2654435769u)));
    uint _e22 = scratch[min(SCRATCH_RNG_INDEX, 24u)];
    uint _e24 = laine_karras(bitfieldReverse(_e22), _e16);
    uint i_8 = bitfieldReverse(_e24);
    x_2 = i_8;
    if (((d & 1u) != 0u)) {
        uint _e31 = sobol_second_reversed(i_8);
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
    float m_6 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    uint e = min(max(((floatBitsToUint(m_6) >> 23u) & 255u), 1u), 253u);
    vec3 d_3 = (ray_2.dir * vec3(uintBitsToFloat(((254u - e) << 23u))));
    float unit = uintBitsToFloat((e << 23u));
    vec3 floor_ = vec3(9.094947e-13);
    vec3 s_6 = mix(vec3(1.0), vec3(-1.0), lessThan(d_3, vec3(0.0)));
    vec3 inv = (vec3(1.0) / mix(d_3, (s_6 * floor_), lessThan(abs(d_3), floor_)));
    vec3 rel = (origin_2 - ray_2.origin);
    vec3 start = (rel * inv);
    vec3 pad = (((vec3(9.536743e-7) * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_6);
    return BoxRay((header_1.max_ * inv), (start - pad), (start + pad), (ray_2.tmin * unit), unit);
}

vec3 hit_triangle(TriangleRay r_1, uint slot, float tmin, float tmax_1, bool occlusion) {
    vec4 _e9 = _group_0_binding_4_cs[(slot * 3u)];
    vec3 a_4 = (_e9.xyz - r_1.origin);
    vec4 _e19 = _group_0_binding_4_cs[((slot * 3u) + 1u)];
    vec3 b_7 = (_e19.xyz - r_1.origin);
    vec4 _e29 = _group_0_binding_4_cs[((slot * 3u) + 2u)];
    vec3 c_8 = (_e29.xyz - r_1.origin);
    float ax = (a_4[min(r_1.kx, 2u)] - (r_1.shear.x * a_4[min(r_1.kz, 2u)]));
    float ay = (a_4[min(r_1.ky, 2u)] - (r_1.shear.y * a_4[min(r_1.kz, 2u)]));
    float bx = (b_7[min(r_1.kx, 2u)] - (r_1.shear.x * b_7[min(r_1.kz, 2u)]));
    float by = (b_7[min(r_1.ky, 2u)] - (r_1.shear.y * b_7[min(r_1.kz, 2u)]));
    float cx = (c_8[min(r_1.kx, 2u)] - (r_1.shear.x * c_8[min(r_1.kz, 2u)]));
    float cy = (c_8[min(r_1.ky, 2u)] - (r_1.shear.y * c_8[min(r_1.kz, 2u)]));
    float u_3 = ((cx * by) - (cy * bx));
    float v_6 = ((ax * cy) - (ay * cx));
    float w_1 = ((bx * ay) - (by * ax));
    bool outside = ((((u_3 < 0.0) || (v_6 < 0.0)) || (w_1 < 0.0)) && (((u_3 > 0.0) || (v_6 > 0.0)) || (w_1 > 0.0)));
    float det = ((u_3 + v_6) + w_1);
    float scaled = (((u_3 * (r_1.shear.z * a_4[min(r_1.kz, 2u)])) + (v_6 * (r_1.shear.z * b_7[min(r_1.kz, 2u)]))) + (w_1 * (r_1.shear.z * c_8[min(r_1.kz, 2u)])));
    if (occlusion) {
        float st = ((det < 0.0) ? -(scaled) : scaled);
        float ad_1 = abs(det);
        bool hit_12 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        uint _e178 = F32_INF;
        return (hit_12 ? vec3(tmin, 0.0, 0.0) : vec3(uintBitsToFloat(_e178), 0.0, 0.0));
    }
    float rcp = (1.0 / det);
    float t_4 = (scaled * rcp);
    bool hit_13 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (t_4 >= tmin)) && (t_4 <= tmax_1));
    uint _e202 = F32_INF;
    return (hit_13 ? vec3(t_4, (v_6 * rcp), (w_1 * rcp)) : vec3(uintBitsToFloat(_e202), 0.0, 0.0));
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
    vec3 t1_1 = fma(hi, b_4.step_, b_4.start_hi);
    bvec3 flip_1 = lessThan(floatBitsToInt(b_4.step_), ivec3(0));
    vec3 near_2 = mix(t0_, t1_1, flip_1);
    vec3 far_2 = mix(t1_1, t0_, flip_1);
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
    float t_5 = (tmax_3 * b_5.unit);
    uvec3 _e9 = node_box_lo(lq);
    uvec3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(vec3(_e9), vec3(_e11), b_5, t_5);
    uvec3 _e14 = node_box_lo(rq);
    uvec3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(vec3(_e14), vec3(_e16), b_5, t_5);
    return vec2(_e13, _e18);
}

uvec2 pop(uint base, uint sp) {
    if ((sp == 0u)) {
        return uvec2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack[min(((base + sp) - 1u), 71u)];
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
    uint base_5 = inst_2.blas_root;
    GpuNode header_2 = _group_0_binding_2_cs[base_5];
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
                    Candidate c_9 = Candidate(_e46.x, owner, prim, _e46.yz, vec3(0.0));
                    bool _e73 = accept(inst_2, world_ray, c_9);
                    if (_e73) {
                        best = c_9;
                        if (shadow) {
                            Candidate _e74 = best;
                            return _e74;
                        }
                    }
                }
            }
        } else {
            uint _e78 = child;
            GpuNode n_11 = _group_0_binding_2_cs[(base_5 + _e78)];
            float _e84 = best.t;
            vec2 _e85 = children_entry(n_11, _e12, _e84);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if (((tl < uintBitsToFloat(_e89)) && (tr < uintBitsToFloat(_e93)))) {
                near = n_11.a;
                far = n_11.b;
                if (((tr < tl) != shadow)) {
                    near = n_11.b;
                    far = n_11.a;
                }
                uint _e105 = sp_1;
                if ((_e105 < BLAS_STACK)) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack[min((TLAS_STACK + _e109), 71u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if ((tl < uintBitsToFloat(_e121))) {
                child = n_11.a;
                continue;
            }
            uint _e126 = F32_INF;
            if ((tr < uintBitsToFloat(_e126))) {
                child = n_11.b;
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

Sphere load_Sphere(uint offset_2) {
    uint _e5 = _group_0_binding_6_cs[(offset_2 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_2 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_2 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_2 + 3u)];
    return Sphere(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24));
}

Intersection sphere_intersect(Sphere s, Ray ray_5) {
    float t = 0.0;
    vec3 f_1 = (ray_5.origin - s.center);
    float a_5 = dot(ray_5.dir, ray_5.dir);
    float b_8 = -(dot(f_1, ray_5.dir));
    vec3 l_6 = (f_1 + (ray_5.dir * vec3((b_8 / a_5))));
    float r2_ = (s.radius * s.radius);
    float disc = (a_5 * (r2_ - dot(l_6, l_6)));
    if ((!((disc >= 0.0)) || !((a_5 > 0.0)))) {
        uint _e30 = F32_INF;
        return Intersection(uintBitsToFloat(_e30), vec3(0.0, 0.0, 1.0), vec2(0.0));
    }
    float q_1 = (b_8 + (((b_8 >= 0.0) ? 1.0 : -1.0) * sqrt(disc)));
    float t0_1 = ((dot(f_1, f_1) - r2_) / q_1);
    float t1_2 = (q_1 / a_5);
    t = min(t0_1, t1_2);
    float _e52 = t;
    if (!((_e52 >= ray_5.tmin))) {
        t = max(t0_1, t1_2);
    }
    float _e57 = t;
    float _e60 = t;
    if (!(((_e57 >= ray_5.tmin) && (_e60 <= ray_5.tmax)))) {
        uint _e66 = F32_INF;
        return Intersection(uintBitsToFloat(_e66), vec3(0.0, 0.0, 1.0), vec2(0.0));
    }
    float _e76 = t;
    vec3 _e82 = normalize_vec3f(((ray_5.origin + (ray_5.dir * vec3(_e76))) - s.center));
    float u_4 = (((_e82.x == 0.0) && (_e82.z == 0.0)) ? 0.5 : (0.5 + (atan(_e82.z, -(_e82.x)) / TAU)));
    vec2 uv = vec2(u_4, (acos(min(max(_e82.y, -1.0), 1.0)) * INV_PI));
    float _e109 = t;
    return Intersection(_e109, _e82, uv);
}

Intersection dispatch_intersection(uint type_id_1, uint offset_3, Ray ray_6) {
    Sphere _e2 = load_Sphere(offset_3);
    Intersection _e3 = sphere_intersect(_e2, ray_6);
    return _e3;
}

Candidate intersect_object(uint slot_2, Ray ray_7, Candidate best_1, bool shadow_1) {
    Ray r_2 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    GpuInstance inst_6 = _group_0_binding_3_cs[slot_2];
    Ray _e7 = to_object(inst_6, ray_7);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_7, _e14, best_1, shadow_1);
        return _e15;
    }
    Ray _e18 = r_2;
    Intersection _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18);
    float _e22 = r_2.tmin;
    float _e26 = r_2.tmax;
    uint _e31 = F32_INF;
    if ((((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < uintBitsToFloat(_e31)))) {
        Candidate c_10 = Candidate(_e19.t, slot_2, 0u, _e19.uv, _e19.normal);
        bool _e40 = accept(inst_6, ray_7, c_10);
        if (_e40) {
            return c_10;
        }
    }
    return best_1;
}

float point_error(vec3 origin_1, vec3 along) {
    vec3 a_6 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_6.x, a_6.y), a_6.z));
}

Triangle load_triangle(uint slot_3) {
    vec4 v0_1 = _group_0_binding_4_cs[(slot_3 * 3u)];
    vec4 v1_ = _group_0_binding_4_cs[((slot_3 * 3u) + 1u)];
    vec4 v2_ = _group_0_binding_4_cs[((slot_3 * 3u) + 2u)];
    return Triangle(v0_1.xyz, v1_.xyz, v2_.xyz);
}

vec3 point_to_world(GpuInstance inst_3, vec3 p_2) {
    vec4 q_2 = vec4(p_2, 1.0);
    return vec3(dot(inst_3.object_to_world_0_, q_2), dot(inst_3.object_to_world_1_, q_2), dot(inst_3.object_to_world_2_, q_2));
}

float mesh_error(GpuInstance inst_4, vec3 v0_, vec3 db1_, vec3 db2_, vec3 p_3) {
    vec3 obj = ((vec3(GAMMA_1_) * abs(v0_)) + (vec3(GAMMA_6_) * (abs(db1_) + abs(db2_))));
    vec4 q_3 = vec4(abs(p_3), 1.0);
    vec4 r0_ = abs(inst_4.object_to_world_0_);
    vec4 r1_ = abs(inst_4.object_to_world_1_);
    vec4 r2_1 = abs(inst_4.object_to_world_2_);
    vec3 rounding = (vec3(GAMMA_4_) * vec3(dot(r0_, q_3), dot(r1_, q_3), dot(r2_1, q_3)));
    vec3 carried = (vec3((1.0 + GAMMA_4_)) * vec3(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_1.xyz, obj)));
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
        vec2 s_7 = mix(vec2(-1.0), vec2(1.0), greaterThanEqual(_e21.xy, vec2(0.0)));
        vec3 _e29 = n_1;
        vec2 xy = ((vec2(1.0) - abs(_e29.yx)) * s_7);
        float _e37 = n_1.z;
        n_1 = vec3(xy.x, xy.y, _e37);
    }
    vec3 _e39 = n_1;
    vec3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

vec3 normal_to_world(GpuInstance inst_5, vec3 n_2) {
    vec3 w_2 = (((inst_5.world_to_object_0_.xyz * vec3(n_2.x)) + (inst_5.world_to_object_1_.xyz * vec3(n_2.y))) + (inst_5.world_to_object_2_.xyz * vec3(n_2.z)));
    vec3 _e19 = normalize_vec3f(w_2);
    return _e19;
}

Hit finish_hit(Ray ray_8, Candidate c_1) {
    Hit hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    vec3 n_geo = vec3(0.0);
    vec3 n_shade = vec3(0.0);
    GpuInstance inst_7 = _group_0_binding_3_cs[c_1.slot];
    float _e11 = point_error(ray_8.origin, (ray_8.dir * vec3(c_1.t)));
    hit_error = _e11;
    hit = Hit((ray_8.origin + (ray_8.dir * vec3(c_1.t))), c_1.t, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if ((inst_7.geometry_type == MESH_GEOMETRY)) {
        Triangle _e42 = load_triangle(c_1.primitive);
        vec2 b_9 = c_1.uv;
        float w_3 = ((1.0 - b_9.x) - b_9.y);
        vec3 e1_ = (_e42.v1_ - _e42.v0_);
        vec3 e2_ = (_e42.v2_ - _e42.v0_);
        vec3 p_8 = (_e42.v0_ + ((e1_ * vec3(b_9.x)) + (e2_ * vec3(b_9.y))));
        vec3 _e65 = point_to_world(inst_7, p_8);
        hit.position = _e65;
        float _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * vec3(b_9.x)), (e2_ * vec3(b_9.y)), p_8);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        uvec4 a0_ = _group_0_binding_5_cs[(c_1.primitive * 2u)];
        uvec4 a1_ = _group_0_binding_5_cs[((c_1.primitive * 2u) + 1u)];
        vec3 _e91 = decode_octahedral(a0_.x);
        vec3 _e95 = decode_octahedral(a0_.y);
        vec3 _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * vec3(w_3)) + (_e95 * vec3(b_9.x))) + (_e101 * vec3(b_9.y)));
        vec3 _e106 = n_shade;
        vec3 _e107 = n_shade;
        if ((dot(_e106, _e107) < 1e-12)) {
            vec3 _e111 = n_geo;
            n_shade = _e111;
        }
        vec2 uv0_ = unpackHalf2x16(a0_.w);
        vec2 uv1_ = unpackHalf2x16(a1_.x);
        vec2 uv2_ = unpackHalf2x16(a1_.y);
        hit.uv = (((uv0_ * vec2(w_3)) + (uv1_ * vec2(b_9.x))) + (uv2_ * vec2(b_9.y)));
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
    hit.front_face = (dot(ray_8.dir, _e147) < 0.0);
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
    Ray ray_9 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    FrameUniforms frame_2 = _group_0_binding_0_cs;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_9 = _e7;
    ray_9.depth = 0u;
    ray_9.kind = RAY_CAMERA;
    vec3 _e15 = ray_9.origin;
    uint _e17 = medium_at(_e15, NO_HIT);
    ray_9.medium = _e17;
    Ray _e18 = ray_9;
    return _e18;
}

vec3 node_frame_bounds() {
    return vec3(65535.0);
}

Candidate intersect_scene(Ray ray_10, bool shadow_2) {
    Candidate best_2 = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint sp_2 = 0u;
    uint child_1 = 0u;
    uint near_1 = 0u;
    uint far_1 = 0u;
    uint _e3 = ray_count;
    ray_count = (_e3 + 1u);
    Candidate _e7 = no_candidate(ray_10.tmax);
    best_2 = _e7;
    FrameUniforms frame_3 = _group_0_binding_0_cs;
    if ((frame_3.instance_count == 0u)) {
        Candidate _e14 = best_2;
        return _e14;
    }
    uint base_6 = frame_3.tlas_root;
    GpuNode header_3 = _group_0_binding_2_cs[base_6];
    BoxRay _e19 = box_ray(header_3, ray_10);
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
                Candidate _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_10, _e54, shadow_2);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if ((shadow_2 && (_e57 != NO_HIT))) {
                    Candidate _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_12 = _group_0_binding_2_cs[(base_6 + _e62)];
            float _e68 = best_2.t;
            vec2 _e69 = children_entry(n_12, _e19, _e68);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if (((tl_1 < uintBitsToFloat(_e73)) && (tr_1 < uintBitsToFloat(_e77)))) {
                near_1 = n_12.a;
                far_1 = n_12.b;
                if ((tr_1 < tl_1)) {
                    near_1 = n_12.b;
                    far_1 = n_12.a;
                }
                uint _e88 = sp_2;
                if ((_e88 < TLAS_STACK)) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack[min(_e91, 71u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if ((tl_1 < uintBitsToFloat(_e102))) {
                child_1 = n_12.a;
                continue;
            }
            uint _e107 = F32_INF;
            if ((tr_1 < uintBitsToFloat(_e107))) {
                child_1 = n_12.b;
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

ConstantBackground load_ConstantBackground(uint offset_4) {
    uint _e5 = _group_0_binding_6_cs[(offset_4 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_4 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_4 + 2u)];
    return ConstantBackground(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)));
}

vec3 constant_background(ConstantBackground b_6, Ray ray_11) {
    return b_6.color;
}

vec3 dispatch_miss(uint type_id_2, uint offset_5, Ray ray_12) {
    ConstantBackground _e2 = load_ConstantBackground(offset_5);
    vec3 _e3 = constant_background(_e2, ray_12);
    return _e3;
}

vec3 miss(Ray ray_13) {
    if (!(HAS_BACKGROUND)) {
        return vec3(0.0);
    }
    FrameUniforms frame_4 = _group_0_binding_0_cs;
    vec3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_13);
    return _e9;
}

PathDiffuse load_PathDiffuse(uint offset_6) {
    uint _e5 = _group_0_binding_6_cs[(offset_6 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_6 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_6 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_6 + 3u)];
    return PathDiffuse(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), _e24);
}

uint light_count_query() {
    FrameUniforms _e1 = _group_0_binding_0_cs;
    return _e1.light_count;
}

QuadLight load_QuadLight(uint offset_7) {
    uint _e5 = _group_0_binding_6_cs[(offset_7 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_7 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_7 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_7 + 4u)];
    uint _e30 = _group_0_binding_6_cs[(offset_7 + 5u)];
    uint _e36 = _group_0_binding_6_cs[(offset_7 + 6u)];
    uint _e43 = _group_0_binding_6_cs[(offset_7 + 8u)];
    uint _e49 = _group_0_binding_6_cs[(offset_7 + 9u)];
    uint _e55 = _group_0_binding_6_cs[(offset_7 + 10u)];
    uint _e62 = _group_0_binding_6_cs[(offset_7 + 12u)];
    uint _e68 = _group_0_binding_6_cs[(offset_7 + 13u)];
    uint _e74 = _group_0_binding_6_cs[(offset_7 + 14u)];
    uint _e81 = _group_0_binding_6_cs[(offset_7 + 15u)];
    uint _e87 = _group_0_binding_6_cs[(offset_7 + 16u)];
    return QuadLight(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), vec3(uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55)), vec3(uintBitsToFloat(_e62), uintBitsToFloat(_e68), uintBitsToFloat(_e74)), uintBitsToFloat(_e81), _e87);
}

float shadow_preset(vec3 normal, vec3 dir) {
    uint mode = scratch[min(SCRATCH_SHADOW_MODE, 24u)];
    if ((mode == SHADOW_UNOCCLUDED)) {
        return 1.0;
    }
    if (((mode == SHADOW_ABOVE) && !((dot(dir, normal) > 0.0)))) {
        return 0.0;
    }
    return -1.0;
}

void scratch_store3f(uint i_2, vec3 v_2) {
    uvec3 b_10 = floatBitsToUint(v_2);
    scratch[min(i_2, 24u)] = b_10.x;
    scratch[min((i_2 + 1u), 24u)] = b_10.y;
    scratch[min((i_2 + 2u), 24u)] = b_10.z;
    return;
}

float shadow_deferred(vec3 position, vec3 normal_1, vec3 dir_1, float dist) {
    float _e4 = shadow_preset(normal_1, dir_1);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    uint i_9 = scratch[min(SCRATCH_QUERY, 24u)];
    scratch[min(SCRATCH_QUERY, 24u)] = (i_9 + 1u);
    uint _e25 = scratch[min(SCRATCH_RESOLVED, 24u)];
    if ((i_9 < _e25)) {
        uint _e32 = scratch[min(SCRATCH_LIGHT_BITS, 24u)];
        return float(((_e32 >> (i_9 & 31u)) & 1u));
    }
    uint _e44 = scratch[min(SCRATCH_PENDING, 24u)];
    if ((_e44 != 0u)) {
        return 1.0;
    }
    if ((i_9 >= LIGHT_QUERIES)) {
        atomicAdd(_group_0_binding_9_cs[min(COUNTER_SHADOW_OVERFLOW, 3u)], 1u);
        return 1.0;
    }
    scratch_store3f(SCRATCH_LIGHT_QUERY, position);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 3u), normal_1);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 6u), dir_1);
    scratch[min((SCRATCH_LIGHT_QUERY + 9u), 24u)] = floatBitsToUint(dist);
    scratch[min(SCRATCH_PENDING, 24u)] = 1u;
    return 1.0;
}

LightSample quad_light(QuadLight l, vec3 position_1, vec3 normal_2) {
    vec3 c_11 = cross(l.edge_u, l.edge_v);
    float area = length(c_11);
    vec2 _e7 = rand2_next();
    vec3 to_light = (((l.corner + (l.edge_u * vec3(_e7.x))) + (l.edge_v * vec3(_e7.y))) - position_1);
    float dist2_ = dot(to_light, to_light);
    float dist_3 = sqrt(dist2_);
    vec3 dir_9 = (to_light / vec3(max(dist_3, 1e-20)));
    float cos_light = (-(dot(dir_9, c_11)) / max(area, 1e-30));
    if ((!((cos_light > 0.0)) || !((dist2_ > 0.0)))) {
        return LightSample(dir_9, dist_3, vec3(0.0), 0.0);
    }
    float _e42 = shadow_deferred(position_1, normal_2, dir_9, dist_3);
    float strength = (((l.intensity * cos_light) * area) / dist2_);
    float pdf_1 = ((l.lamp == 1u) ? (dist2_ / (cos_light * area)) : 0.0);
    return LightSample(dir_9, dist_3, ((l.color * vec3(strength)) * vec3(_e42)), pdf_1);
}

SphereLight load_SphereLight(uint offset_8) {
    uint _e5 = _group_0_binding_6_cs[(offset_8 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_8 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_8 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_8 + 3u)];
    uint _e30 = _group_0_binding_6_cs[(offset_8 + 4u)];
    uint _e36 = _group_0_binding_6_cs[(offset_8 + 5u)];
    uint _e42 = _group_0_binding_6_cs[(offset_8 + 6u)];
    uint _e49 = _group_0_binding_6_cs[(offset_8 + 7u)];
    uint _e55 = _group_0_binding_6_cs[(offset_8 + 8u)];
    return SphereLight(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24), vec3(uintBitsToFloat(_e30), uintBitsToFloat(_e36), uintBitsToFloat(_e42)), uintBitsToFloat(_e49), _e55);
}

mat3x3 orthonormal_basis(vec3 n_3) {
    float sign_ = (((floatBitsToUint(n_3.z) & 2147483648u) != 0u) ? -1.0 : 1.0);
    float a_7 = (-1.0 / (sign_ + n_3.z));
    float b_11 = ((n_3.x * n_3.y) * a_7);
    float _e16 = (sign_ * n_3.x);
    return mat3x3(vec3((1.0 + ((_e16 * n_3.x) * a_7)), (sign_ * b_11), -(_e16)), vec3(b_11, (sign_ + ((n_3.y * n_3.y) * a_7)), -(n_3.y)), n_3);
}

LightSample sphere_light(SphereLight l_1, vec3 position_2, vec3 normal_3) {
    vec3 to_center = (l_1.position - position_2);
    float d2_ = dot(to_center, to_center);
    float r2_2 = max((l_1.radius * l_1.radius), 1e-20);
    if ((d2_ <= r2_2)) {
        return LightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0);
    }
    vec3 w_4 = (to_center * vec3(inversesqrt(d2_)));
    float s2_ = (r2_2 / d2_);
    float cos_max = sqrt((1.0 - s2_));
    float one_minus_cos_max = (s2_ / (1.0 + cos_max));
    vec2 _e31 = rand2_next();
    float cos_t = (1.0 - (_e31.x * one_minus_cos_max));
    float sin_t = sqrt(max((1.0 - (cos_t * cos_t)), 0.0));
    float phi = (TAU * _e31.y);
    mat3x3 _e45 = orthonormal_basis(w_4);
    vec3 _e52 = normalize_vec3f((_e45 * vec3((cos(phi) * sin_t), (sin(phi) * sin_t), cos_t)));
    float along_1 = dot(to_center, _e52);
    float dist_4 = max((along_1 - sqrt(max((r2_2 - (d2_ - (along_1 * along_1))), 0.0))), 0.0);
    float weight_4 = (((l_1.intensity * 2.0) * one_minus_cos_max) / r2_2);
    float _e68 = shadow_deferred(position_2, normal_3, _e52, dist_4);
    float pdf_2 = ((l_1.lamp == 1u) ? (1.0 / (TAU * one_minus_cos_max)) : 0.0);
    return LightSample(_e52, dist_4, ((l_1.color * vec3(weight_4)) * vec3(_e68)), pdf_2);
}

LightSample dispatch_light(uint type_id_3, uint offset_9, vec3 position_3, vec3 normal_4) {
    switch(type_id_3) {
        case 0u: {
            QuadLight _e4 = load_QuadLight(offset_9);
            LightSample _e5 = quad_light(_e4, position_3, normal_4);
            return _e5;
        }
        case 1u: {
            SphereLight _e6 = load_SphereLight(offset_9);
            LightSample _e7 = sphere_light(_e6, position_3, normal_4);
            return _e7;
        }
        default: {
            break;
        }
    }
    return LightSample(vec3(0.0), 0.0, vec3(0.0), 0.0);
}

vec3 scratch_load3f(uint i_3) {
    uint _e5 = scratch[min(i_3, 24u)];
    uint _e12 = scratch[min((i_3 + 1u), 24u)];
    uint _e19 = scratch[min((i_3 + 2u), 24u)];
    return uintBitsToFloat(uvec3(_e5, _e12, _e19));
}

vec3 step_toward(vec3 x_3, vec3 s_1) {
    uvec3 bits_2 = floatBitsToUint(x_3);
    bvec3 up_1 = greaterThan((sign(x_3) * sign(s_1)), vec3(0.0));
    vec3 stepped = uintBitsToFloat(mix((bits_2 - uvec3(1u)), (bits_2 + uvec3(1u)), up_1));
    vec3 from_zero = mix(vec3(-1.1754944e-38), vec3(1.1754944e-38), greaterThan(s_1, vec3(0.0)));
    vec3 moved = mix(stepped, from_zero, equal(x_3, vec3(0.0)));
    return mix(x_3, moved, not(equal(s_1, vec3(0.0))));
}

vec3 offset_origin(vec3 p_5, vec3 n_4, float error) {
    float d_4 = ((2.0 * error) * ((abs(n_4.x) + abs(n_4.y)) + abs(n_4.z)));
    vec3 offset_16 = (n_4 * vec3(d_4));
    vec3 _e17 = step_toward((p_5 + offset_16), offset_16);
    return _e17;
}

Ray shadow_ray(vec3 position_4, vec3 normal_5, vec3 dir_2, float dist_1) {
    vec3 n_5 = vec3(0.0);
    float tmax_4 = 0.0;
    n_5 = normal_5;
    vec3 _e5 = n_5;
    if ((dot(dir_2, _e5) < 0.0)) {
        vec3 _e9 = n_5;
        n_5 = -(_e9);
    }
    vec3 a_8 = abs(position_4);
    float _e13 = hit_error;
    float error_3 = max(_e13, (GAMMA_4_ * max(max(a_8.x, a_8.y), a_8.z)));
    vec3 _e22 = n_5;
    vec3 _e23 = offset_origin(position_4, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = uintBitsToFloat(_e25);
    uint _e29 = F32_INF;
    if ((dist_1 < uintBitsToFloat(_e29))) {
        vec3 light = (position_4 + (dir_2 * vec3(dist_1)));
        float dd = dot(dir_2, dir_2);
        float along_2 = (dot((light - _e23), dir_2) / dd);
        vec3 l_7 = (abs(position_4) + abs((dir_2 * vec3(dist_1))));
        tmax_4 = ((along_2 * (1.0 - 1e-5)) - ((LIGHT_ERROR * max(max(l_7.x, l_7.y), l_7.z)) / sqrt(dd)));
    }
    float _e59 = tmax_4;
    return Ray(_e23, 0.0, dir_2, _e59, 0u, RAY_SHADOW, 0u);
}

float shadow_query(vec3 position_5, vec3 normal_6, vec3 dir_3, float dist_2) {
    float _e4 = shadow_preset(normal_6, dir_3);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_5, normal_6, dir_3, dist_2);
    Candidate _e9 = intersect_scene(_e7, true);
    return ((_e9.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample sample_light_deferred(uint i_4, vec3 position_6, vec3 normal_7) {
    uint after = 0u;
    uint resolved = 0u;
    uint bits_1 = 0u;
    FrameUniforms frame_5 = _group_0_binding_0_cs;
    if ((i_4 >= frame_5.light_count)) {
        return LightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0);
    }
    uint entry = (frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE));
    uint type_id_7 = _group_0_binding_6_cs[entry];
    uint offset_17 = _group_0_binding_6_cs[(entry + 1u)];
    uint start_1 = rng_state;
    after = start_1;
    resolved = 0u;
    bits_1 = 0u;
    scratch[min(SCRATCH_RESOLVED, 24u)] = 0u;
    scratch[min(SCRATCH_LIGHT_BITS, 24u)] = 0u;
    while(true) {
        rng_state = start_1;
        scratch[min(SCRATCH_QUERY, 24u)] = 0u;
        scratch[min(SCRATCH_PENDING, 24u)] = 0u;
        LightSample _e60 = dispatch_light(type_id_7, offset_17, position_6, normal_7);
        uint _e66 = scratch[min(SCRATCH_PENDING, 24u)];
        if ((_e66 == 0u)) {
            uint _e69 = resolved;
            if ((_e69 > 0u)) {
                uint _e72 = after;
                rng_state = _e72;
            }
            return _e60;
        }
        uint _e74 = resolved;
        if ((_e74 == 0u)) {
            uint _e78 = rng_state;
            after = _e78;
        }
        uint _e79 = after;
        rng_state = _e79;
        vec3 _e82 = scratch_load3f(SCRATCH_LIGHT_QUERY);
        vec3 _e85 = scratch_load3f((SCRATCH_LIGHT_QUERY + 3u));
        vec3 _e88 = scratch_load3f((SCRATCH_LIGHT_QUERY + 6u));
        uint _e95 = scratch[min((SCRATCH_LIGHT_QUERY + 9u), 24u)];
        float _e97 = shadow_query(_e82, _e85, _e88, uintBitsToFloat(_e95));
        uint _e99 = rng_state;
        after = _e99;
        if (!((_e97 == 0.0))) {
            uint _e108 = scratch[min(SCRATCH_QUERY, 24u)];
            uint _e109 = resolved;
            if ((_e108 == (_e109 + 1u))) {
                uint _e113 = after;
                rng_state = _e113;
                scratch[min(SCRATCH_PENDING, 24u)] = 0u;
                return _e60;
            }
            uint _e121 = bits_1;
            uint _e123 = resolved;
            bits_1 = (_e121 | (1u << (_e123 & 31u)));
        }
        uint _e128 = resolved;
        resolved = (_e128 + 1u);
        uint _e132 = bits_1;
        scratch[min(SCRATCH_LIGHT_BITS, 24u)] = _e132;
        uint _e138 = resolved;
        scratch[min(SCRATCH_RESOLVED, 24u)] = _e138;
    }
    return LightSample(vec3(0.0), 0.0, vec3(0.0), 0.0);
}

LightSample sample_light_above_deferred(uint i_5, vec3 position_7, vec3 normal_8) {
    scratch[min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_ABOVE;
    LightSample _e9 = sample_light_deferred(i_5, position_7, normal_8);
    scratch[min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_TRACED;
    return _e9;
}

float mis_weight(float p_6, float other) {
    if (!((p_6 > 0.0))) {
        return 0.0;
    }
    float r_3 = (max(other, 0.0) / p_6);
    if (!((r_3 < 1e18))) {
        uint _e15 = F32_INF;
        uint _e19 = F32_INF;
        return (((p_6 == uintBitsToFloat(_e15)) && (other < uintBitsToFloat(_e19))) ? 1.0 : 0.0);
    }
    return (1.0 / (1.0 + (r_3 * r_3)));
}

float mis_light_weight(LightSample l_2, float bsdf_pdf) {
    if (!((l_2.pdf > 0.0))) {
        return 1.0;
    }
    float _e8 = mis_weight(l_2.pdf, bsdf_pdf);
    return _e8;
}

vec3 path_diffuse_shade(PathDiffuse m, Ray ray_14, Hit hit_1, vec3 secondary) {
    vec3 direct = vec3(0.0);
    uint i_6 = 0u;
    vec3 n_13 = faceforward(hit_1.normal, ray_14.dir, hit_1.geometric_normal);
    vec3 ng = faceforward(hit_1.geometric_normal, ray_14.dir, hit_1.geometric_normal);
    direct = vec3(0.0);
    uint _e16 = light_count_query();
    i_6 = 0u;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e36 = i_6;
            i_6 = (_e36 + 1u);
        }
        loop_init_2 = false;
        uint _e18 = i_6;
        if ((_e18 >= _e16)) {
            break;
        }
        uint _e20 = i_6;
        LightSample _e22 = sample_light_above_deferred(_e20, hit_1.position, ng);
        float c_12 = max(dot(n_13, _e22.dir), 0.0);
        vec3 _e27 = direct;
        float _e31 = mis_light_weight(_e22, (c_12 * INV_PI));
        direct = (_e27 + (_e22.radiance * vec3((c_12 * _e31))));
    }
    vec3 _e43 = direct;
    return (((m.albedo * vec3(INV_PI)) * _e43) + secondary);
}

QuadLamp load_QuadLamp(uint offset_10) {
    uint _e5 = _group_0_binding_6_cs[(offset_10 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_10 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_10 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_10 + 3u)];
    uint _e30 = _group_0_binding_6_cs[(offset_10 + 4u)];
    return QuadLamp(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24), uintBitsToFloat(_e30));
}

bool after_nee_bounce(Ray ray_15) {
    return (dot(ray_15.dir, ray_15.dir) > 2.0);
}

float bounce_pdf(Ray ray_16) {
    float x_6 = (length(ray_16.dir) - MIS_BOUNCE_LENGTH);
    if (!((x_6 > -0.25))) {
        return 0.0;
    }
    return (exp((max(x_6, 0.0) * 90.0)) - 1.0);
}

vec3 quad_lamp_shade(QuadLamp m_1, Ray ray_17, Hit hit_2) {
    if (!(hit_2.front_face)) {
        return vec3(0.0);
    }
    vec3 le = (m_1.color * vec3(m_1.intensity));
    bool _e11 = after_nee_bounce(ray_17);
    if (!(_e11)) {
        return le;
    }
    float _e13 = bounce_pdf(ray_17);
    float len = length(ray_17.dir);
    float dist_5 = (hit_2.t * len);
    float cos_l = (abs(dot(hit_2.geometric_normal, ray_17.dir)) / len);
    float pl = ((dist_5 * dist_5) / max((cos_l * m_1.area), 1e-30));
    float _e29 = mis_weight(_e13, pl);
    return (le * vec3(_e29));
}

SphereLamp load_SphereLamp(uint offset_11) {
    uint _e5 = _group_0_binding_6_cs[(offset_11 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_11 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_11 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_11 + 3u)];
    uint _e30 = _group_0_binding_6_cs[(offset_11 + 4u)];
    return SphereLamp(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24), uintBitsToFloat(_e30));
}

vec3 sphere_lamp_shade(SphereLamp m_2, Ray ray_18, Hit hit_3) {
    if (!(hit_3.front_face)) {
        return vec3(0.0);
    }
    float r2_3 = max((m_2.radius * m_2.radius), 1e-20);
    vec3 le_1 = (m_2.color * vec3(((m_2.intensity * INV_PI) / r2_3)));
    bool _e19 = after_nee_bounce(ray_18);
    if (!(_e19)) {
        return le_1;
    }
    float _e21 = bounce_pdf(ray_18);
    vec3 center = (hit_3.position - (hit_3.normal * vec3(m_2.radius)));
    vec3 to_center_1 = (center - ray_18.origin);
    float s2_1 = (r2_3 / max(dot(to_center_1, to_center_1), r2_3));
    float one_minus_cos_max_1 = (s2_1 / (1.0 + sqrt((1.0 - s2_1))));
    float pl_1 = (1.0 / max((TAU * one_minus_cos_max_1), 1e-30));
    float _e45 = mis_weight(_e21, pl_1);
    return (le_1 * vec3(_e45));
}

PathPbr load_PathPbr(uint offset_12) {
    uint _e5 = _group_0_binding_6_cs[(offset_12 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_12 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_12 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_12 + 3u)];
    uint _e30 = _group_0_binding_6_cs[(offset_12 + 4u)];
    uint _e36 = _group_0_binding_6_cs[(offset_12 + 8u)];
    uint _e42 = _group_0_binding_6_cs[(offset_12 + 9u)];
    uint _e48 = _group_0_binding_6_cs[(offset_12 + 10u)];
    uint _e55 = _group_0_binding_6_cs[(offset_12 + 11u)];
    return PathPbr(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24), uintBitsToFloat(_e30), vec3(uintBitsToFloat(_e36), uintBitsToFloat(_e42), uintBitsToFloat(_e48)), _e55);
}

vec3 path_pbr_ng(Ray ray_19, Hit hit_4) {
    return faceforward(hit_4.geometric_normal, ray_19.dir, hit_4.geometric_normal);
}

vec3 path_pbr_n(Ray ray_20, Hit hit_5) {
    vec3 _e2 = path_pbr_ng(ray_20, hit_5);
    vec3 n_14 = faceforward(hit_5.normal, -(_e2), hit_5.normal);
    return ((dot(n_14, ray_20.dir) < 0.0) ? n_14 : _e2);
}

float pbr_alpha2_(float roughness) {
    float a_9 = max((clamp(roughness, 0.0, 1.0) * clamp(roughness, 0.0, 1.0)), PBR_MIN_ALPHA);
    return (a_9 * a_9);
}

vec3 pbr_fresnel(vec3 f0_, float c_2) {
    float k_1 = (1.0 - clamp(c_2, 0.0, 1.0));
    float k2_ = (k_1 * k_1);
    return (f0_ + ((vec3(1.0) - f0_) * vec3(((k2_ * k2_) * k_1))));
}

float pbr_ggx_d(float ndh, float a2_) {
    float d_5 = (((ndh * ndh) * (a2_ - 1.0)) + 1.0);
    return ((a2_ * INV_PI) / (d_5 * d_5));
}

float pbr_smith_v(float ndl, float ndv, float a2_1) {
    float gv = (ndl * sqrt((((ndv * ndv) * (1.0 - a2_1)) + a2_1)));
    float gl = (ndv * sqrt((((ndl * ndl) * (1.0 - a2_1)) + a2_1)));
    return (0.5 / max((gv + gl), 1e-20));
}

vec3 pbr_eval(vec3 base_1, float metallic, float roughness_1, vec3 n_6, vec3 v_3, vec3 l_3) {
    float ndv_3 = dot(n_6, v_3);
    float ndl_1 = dot(n_6, l_3);
    if ((!((ndv_3 > 0.0)) || !((ndl_1 > 0.0)))) {
        return vec3(0.0);
    }
    float metal = clamp(metallic, 0.0, 1.0);
    float _e18 = pbr_alpha2_(roughness_1);
    vec3 f0_1 = mix(vec3(0.04), base_1, vec3(metal));
    vec3 _e24 = normalize_vec3f((v_3 + l_3));
    vec3 _e26 = pbr_fresnel(f0_1, dot(v_3, _e24));
    float _e29 = pbr_ggx_d(clamp(dot(n_6, _e24), 0.0, 1.0), _e18);
    float _e30 = pbr_smith_v(ndl_1, ndv_3, _e18);
    vec3 spec = (_e26 * vec3((_e29 * _e30)));
    vec3 diffuse = (((vec3(1.0) - _e26) * base_1) * vec3(((1.0 - metal) * INV_PI)));
    return ((diffuse + spec) * vec3(ndl_1));
}

float luminance(vec3 c_3) {
    return dot(c_3, vec3(0.2126, 0.7152, 0.0722));
}

float pbr_specular_chance(vec3 base_2, float metallic_1, float ndv_1) {
    float metal_1 = clamp(metallic_1, 0.0, 1.0);
    vec3 _e8 = pbr_fresnel(mix(vec3(0.04), base_2, vec3(metal_1)), ndv_1);
    float _e9 = luminance(_e8);
    float _e18 = luminance(((base_2 * vec3((1.0 - metal_1))) * (vec3(1.0) - _e8)));
    if (!((_e18 > 0.0))) {
        return 1.0;
    }
    if (!((_e9 > 0.0))) {
        return 0.0;
    }
    return min(max((_e9 / (_e9 + _e18)), 0.1), 0.9);
}

float pbr_specular_pdf(float ndh_1, float ndv_2, float a2_2) {
    float _e3 = pbr_ggx_d(ndh_1, a2_2);
    return ((_e3 * 0.5) / (ndv_2 + sqrt((a2_2 + (((1.0 - a2_2) * ndv_2) * ndv_2)))));
}

float pbr_pdf(vec3 base_3, float metallic_2, float roughness_2, vec3 n_7, vec3 v_4, vec3 l_4) {
    float ndv_4 = dot(n_7, v_4);
    float ndl_2 = dot(n_7, l_4);
    if ((!((ndv_4 > 0.0)) || !((ndl_2 > 0.0)))) {
        return 0.0;
    }
    float _e16 = pbr_alpha2_(roughness_2);
    float _e17 = pbr_specular_chance(base_3, metallic_2, ndv_4);
    vec3 _e19 = normalize_vec3f((v_4 + l_4));
    float _e22 = pbr_specular_pdf(clamp(dot(n_7, _e19), 0.0, 1.0), ndv_4, _e16);
    return ((_e17 * _e22) + (((1.0 - _e17) * ndl_2) * INV_PI));
}

vec3 path_pbr_shade(PathPbr m_3, Ray ray_21, Hit hit_6, vec3 secondary_1) {
    vec3 direct_1 = vec3(0.0);
    uint i_7 = 0u;
    float w = 0.0;
    vec3 _e4 = path_pbr_n(ray_21, hit_6);
    vec3 _e6 = normalize_vec3f(ray_21.dir);
    vec3 v_7 = -(_e6);
    direct_1 = vec3(0.0);
    vec3 _e11 = path_pbr_ng(ray_21, hit_6);
    uint _e13 = light_count_query();
    i_7 = 0u;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e49 = i_7;
            i_7 = (_e49 + 1u);
        }
        loop_init_3 = false;
        uint _e15 = i_7;
        if ((_e15 >= _e13)) {
            break;
        }
        uint _e17 = i_7;
        LightSample _e19 = sample_light_above_deferred(_e17, hit_6.position, _e11);
        if (any(greaterThan(_e19.radiance, vec3(0.0)))) {
            vec3 _e29 = pbr_eval(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
            w = 1.0;
            if ((_e19.pdf > 0.0)) {
                float _e40 = pbr_pdf(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
                float _e41 = mis_weight(_e19.pdf, _e40);
                w = _e41;
            }
            vec3 _e42 = direct_1;
            float _e45 = w;
            direct_1 = (_e42 + ((_e19.radiance * _e29) * vec3(_e45)));
        }
    }
    vec3 _e53 = direct_1;
    return ((m_3.emissive + _e53) + secondary_1);
}

vec3 dispatch_closest_hit(uint type_id_4, uint offset_13, Ray ray_22, Hit hit_7, vec3 secondary_2) {
    switch(type_id_4) {
        case 0u: {
            PathDiffuse _e5 = load_PathDiffuse(offset_13);
            vec3 _e6 = path_diffuse_shade(_e5, ray_22, hit_7, secondary_2);
            return _e6;
        }
        case 1u: {
            QuadLamp _e7 = load_QuadLamp(offset_13);
            vec3 _e8 = quad_lamp_shade(_e7, ray_22, hit_7);
            return _e8;
        }
        case 2u: {
            SphereLamp _e9 = load_SphereLamp(offset_13);
            vec3 _e10 = sphere_lamp_shade(_e9, ray_22, hit_7);
            return _e10;
        }
        case 3u: {
            PathPbr _e11 = load_PathPbr(offset_13);
            vec3 _e12 = path_pbr_shade(_e11, ray_22, hit_7, secondary_2);
            return _e12;
        }
        default: {
            break;
        }
    }
    return vec3(0.0);
}

vec3 shade_direct(Ray ray_23, Candidate c_4) {
    GpuInstance inst_8 = _group_0_binding_3_cs[c_4.slot];
    Hit _e6 = finish_hit(ray_23, c_4);
    vec3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_23, _e6, vec3(0.0));
    return _e11;
}

vec3 dispatch_medium(uint type_id_5, uint offset_14, Ray ray_24, float t_1, vec3 radiance) {
    return vec3(0.0);
}

vec3 through_medium(Ray ray_25, float t_2, vec3 radiance_1) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_25.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_9 = _group_0_binding_3_cs[(ray_25.medium - 1u)];
    if (((inst_9.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    vec3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_25, t_2, radiance_1);
    return _e21;
}

PathState start_path(Ray ray_26) {
    return PathState(ray_26, vec3(1.0), vec3(0.0), true);
}

vec3 sample_cosine_hemisphere(vec3 n_8, vec2 u) {
    float r_4 = sqrt(u.x);
    float phi_1 = (6.2831855 * u.y);
    vec3 local = vec3((r_4 * cos(phi_1)), (r_4 * sin(phi_1)), sqrt(max((1.0 - u.x), 0.0)));
    mat3x3 _e17 = orthonormal_basis(n_8);
    return (_e17 * local);
}

vec3 mis_bounce_dir(vec3 dir_4, float pdf) {
    float x_7 = min((log((1.0 + max(pdf, 0.0))) * (1.0 / 90.0)), 0.999);
    return (dir_4 * vec3((MIS_BOUNCE_LENGTH + x_7)));
}

void rt_spawn(vec3 dir_5, vec3 weight) {
    uint _e3 = spawn_count;
    if ((_e3 < 1u)) {
        spawn_dirs[_e3] = dir_5;
        spawn_weights[_e3] = weight;
        spawn_count = (_e3 + 1u);
    }
}

void path_diffuse_rays(PathDiffuse m_4, Ray ray_27, Hit hit_8) {
    vec3 weight_1 = vec3(0.0);
    vec3 ng_1 = (hit_8.front_face ? hit_8.geometric_normal : -(hit_8.geometric_normal));
    vec3 n_15 = faceforward(hit_8.normal, -(ng_1), hit_8.normal);
    vec2 _e12 = rand2_next();
    vec3 _e13 = sample_cosine_hemisphere(n_15, _e12);
    weight_1 = m_4.albedo;
    if ((ray_27.depth >= m_4.roulette_depth)) {
        float q_4 = clamp(max(m_4.albedo.x, max(m_4.albedo.y, m_4.albedo.z)), 0.0, 1.0);
        float _e28 = rand_next();
        if ((_e28 >= q_4)) {
            return;
        }
        weight_1 = (m_4.albedo / vec3(q_4));
    }
    if ((dot(_e13, ng_1) > 0.0)) {
        vec3 _e41 = mis_bounce_dir(_e13, (max(dot(n_15, _e13), 0.0) * INV_PI));
        vec3 _e42 = weight_1;
        rt_spawn(_e41, _e42);
    }
    return;
}

vec3 pbr_sample_vndf(vec3 ve, float alpha, vec2 u_1) {
    vec3 t1_ = vec3(0.0);
    vec3 _e9 = normalize_vec3f(vec3((alpha * ve.x), (alpha * ve.y), ve.z));
    float lensq = ((_e9.x * _e9.x) + (_e9.y * _e9.y));
    t1_ = vec3(1.0, 0.0, 0.0);
    if ((lensq > 0.0)) {
        t1_ = (vec3(-(_e9.y), _e9.x, 0.0) * vec3(inversesqrt(lensq)));
    }
    vec3 _e32 = t1_;
    vec3 t2_ = cross(_e9, _e32);
    float r_5 = sqrt(u_1.x);
    float phi_2 = (TAU * u_1.y);
    float p1_ = (r_5 * cos(phi_2));
    float s_8 = (0.5 * (1.0 + _e9.z));
    float p2_ = (((1.0 - s_8) * sqrt(max((1.0 - (p1_ * p1_)), 0.0))) + ((s_8 * r_5) * sin(phi_2)));
    vec3 _e59 = t1_;
    vec3 nh = (((_e59 * vec3(p1_)) + (t2_ * vec3(p2_))) + (_e9 * vec3(sqrt(max(((1.0 - (p1_ * p1_)) - (p2_ * p2_)), 0.0)))));
    vec3 _e84 = normalize_vec3f(vec3((alpha * nh.x), (alpha * nh.y), max(nh.z, 0.0)));
    return _e84;
}

PbrSample pbr_sample(vec3 base_4, float metallic_3, float roughness_3, vec3 n_9, vec3 v_5, vec3 u_2) {
    vec3 l_5 = vec3(0.0);
    float ndv_5 = dot(n_9, v_5);
    if (!((ndv_5 > 0.0))) {
        return PbrSample(n_9, vec3(0.0), 0.0);
    }
    float _e14 = pbr_specular_chance(base_4, metallic_3, ndv_5);
    l_5 = vec3(0.0);
    if ((u_2.x < _e14)) {
        mat3x3 _e20 = orthonormal_basis(n_9);
        float _e21 = pbr_alpha2_(roughness_3);
        vec3 _e26 = pbr_sample_vndf((transpose(_e20) * v_5), sqrt(_e21), u_2.yz);
        vec3 h_1 = (_e20 * _e26);
        l_5 = reflect(-(v_5), h_1);
    } else {
        vec3 _e31 = sample_cosine_hemisphere(n_9, u_2.yz);
        l_5 = _e31;
    }
    vec3 _e32 = l_5;
    float _e33 = pbr_pdf(base_4, metallic_3, roughness_3, n_9, v_5, _e32);
    if (!((_e33 > 0.0))) {
        vec3 _e37 = l_5;
        return PbrSample(_e37, vec3(0.0), 0.0);
    }
    vec3 _e42 = l_5;
    vec3 _e43 = pbr_eval(base_4, metallic_3, roughness_3, n_9, v_5, _e42);
    vec3 weight_5 = (_e43 / vec3(_e33));
    vec3 _e46 = l_5;
    return PbrSample(_e46, weight_5, _e33);
}

void path_pbr_rays(PathPbr m_5, Ray ray_28, Hit hit_9) {
    vec3 weight_2 = vec3(0.0);
    vec3 _e3 = path_pbr_ng(ray_28, hit_9);
    vec3 _e4 = path_pbr_n(ray_28, hit_9);
    vec3 _e6 = normalize_vec3f(ray_28.dir);
    vec3 v_8 = -(_e6);
    float _e11 = rand_next();
    vec2 _e12 = rand2_next();
    PbrSample _e14 = pbr_sample(m_5.base_color, m_5.metallic, m_5.roughness, _e4, v_8, vec3(_e11, _e12));
    if ((!((_e14.pdf > 0.0)) || !((dot(_e14.dir, _e3) > 0.0)))) {
        return;
    }
    weight_2 = _e14.weight;
    if ((ray_28.depth >= m_5.roulette_depth)) {
        float _e31 = weight_2.x;
        float _e33 = weight_2.y;
        float _e35 = weight_2.z;
        float q_5 = min(max(_e31, max(_e33, _e35)), 1.0);
        float _e40 = rand_next();
        if (!((_e40 < q_5))) {
            return;
        }
        vec3 _e43 = weight_2;
        weight_2 = (_e43 / vec3(q_5));
    }
    vec3 _e48 = mis_bounce_dir(_e14.dir, _e14.pdf);
    vec3 _e49 = weight_2;
    rt_spawn(_e48, _e49);
    return;
}

void dispatch_secondary_rays(uint type_id_6, uint offset_15, Ray ray_29, Hit hit_10) {
    switch(type_id_6) {
        case 0u: {
            PathDiffuse _e4 = load_PathDiffuse(offset_15);
            path_diffuse_rays(_e4, ray_29, hit_10);
            return;
        }
        case 3u: {
            PathPbr _e5 = load_PathPbr(offset_15);
            path_pbr_rays(_e5, ray_29, hit_10);
            return;
        }
        default: {
            break;
        }
    }
    return;
}

vec3 spawn_origin_at(vec3 position_8, vec3 normal_9, float error_1, vec3 dir_6) {
    vec3 n_10 = vec3(0.0);
    n_10 = normal_9;
    vec3 _e5 = n_10;
    if ((dot(dir_6, _e5) < 0.0)) {
        vec3 _e9 = n_10;
        n_10 = -(_e9);
    }
    vec3 _e11 = n_10;
    vec3 _e12 = offset_origin(position_8, _e11, error_1);
    return _e12;
}

vec3 spawn_origin(Hit hit_11, float error_2, vec3 dir_7) {
    vec3 _e5 = spawn_origin_at(hit_11.position, hit_11.geometric_normal, error_2, dir_7);
    return _e5;
}

PathState path_step(PathState s_2, Candidate c_5) {
    PathState out_ = PathState(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), vec3(0.0), vec3(0.0), false);
    bool spawned = false;
    vec3 dir_8 = vec3(0.0);
    vec3 weight_3 = vec3(0.0);
    vec3 beta = vec3(0.0);
    Ray ray_30 = s_2.ray;
    out_ = s_2;
    out_.live = false;
    if ((c_5.slot == NO_HIT)) {
        hit_error = 0.0;
        vec3 _e14 = miss(ray_30);
        out_.radiance = (s_2.radiance + (s_2.beta * _e14));
        PathState _e17 = out_;
        return _e17;
    }
    GpuInstance inst_10 = _group_0_binding_3_cs[c_5.slot];
    Hit _e22 = finish_hit(ray_30, c_5);
    float error_4 = hit_error;
    spawned = false;
    dir_8 = vec3(0.0);
    weight_3 = vec3(0.0);
    if ((((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u) && (ray_30.depth < MAX_DEPTH))) {
        spawn_count = 0u;
        dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, ray_30, _e22);
        uint _e47 = spawn_count;
        if ((min(_e47, 1u) > 0u)) {
            spawned = true;
            vec3 _e56 = spawn_dirs[0u];
            dir_8 = _e56;
            vec3 _e60 = spawn_weights[0u];
            weight_3 = _e60;
        }
    }
    vec3 _e68 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, ray_30, _e22, vec3(0.0));
    out_.radiance = (s_2.radiance + (s_2.beta * _e68));
    bool _e71 = spawned;
    if (!(_e71)) {
        PathState _e73 = out_;
        return _e73;
    }
    vec3 _e75 = weight_3;
    beta = (s_2.beta * _e75);
    float _e79 = beta.x;
    float _e81 = beta.y;
    float _e83 = beta.z;
    float q_6 = max(_e79, max(_e81, _e83));
    if (!((q_6 > 0.0))) {
        PathState _e89 = out_;
        return _e89;
    }
    if ((((ROULETTE_DEPTH > 0u) && ((ray_30.depth + 1u) >= ROULETTE_DEPTH)) && (q_6 < ROULETTE_THROUGHPUT))) {
        float survive = (q_6 / ROULETTE_THROUGHPUT);
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
    vec3 _e113 = dir_8;
    vec3 _e114 = spawn_origin(_e22, error_4, _e113);
    vec3 _e116 = dir_8;
    uint _e118 = F32_INF;
    out_.ray = Ray(_e114, 0.0, _e116, uintBitsToFloat(_e118), (ray_30.depth + 1u), RAY_SECONDARY, ray_30.medium);
    out_.live = true;
    PathState _e128 = out_;
    return _e128;
}

vec3 trace_path(Ray camera_ray) {
    PathState s_3 = PathState(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), vec3(0.0), vec3(0.0), false);
    PathState _e1 = start_path(camera_ray);
    s_3 = _e1;
    while(true) {
        PathState _e3 = s_3;
        Ray _e5 = s_3.ray;
        Candidate _e7 = intersect_scene(_e5, false);
        PathState _e8 = path_step(_e3, _e7);
        s_3 = _e8;
        bool _e10 = s_3.live;
        if (!(_e10)) {
            vec3 _e13 = s_3.radiance;
            return _e13;
        }
    }
    return vec3(0.0);
}

vec3 trace(Ray camera_ray_1) {
    vec3 radiance_2 = vec3(0.0);
    float t_3 = 0.0;
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray_1, false);
        radiance_2 = vec3(0.0);
        uint _e9 = F32_INF;
        t_3 = uintBitsToFloat(_e9);
        if ((_e4.slot == NO_HIT)) {
            hit_error = 0.0;
            vec3 _e17 = miss(camera_ray_1);
            radiance_2 = _e17;
        } else {
            vec3 _e18 = shade_direct(camera_ray_1, _e4);
            radiance_2 = _e18;
            t_3 = _e4.t;
        }
        float _e20 = t_3;
        vec3 _e21 = radiance_2;
        vec3 _e22 = through_medium(camera_ray_1, _e20, _e21);
        return _e22;
    }
    vec3 _e23 = trace_path(camera_ray_1);
    return _e23;
}

bvec3 is_finite_vec3f(vec3 x_4) {
    return lessThan((floatBitsToUint(x_4) & uvec3(2147483647u)), uvec3(2139095040u));
}

vec3 finite_or_zero(vec3 c_6) {
    bvec3 _e3 = is_finite_vec3f(c_6);
    return mix(vec3(0.0), c_6, _e3);
}

PassSum add_sample(PassSum p_7, vec3 c_7, uint s_4, uint index, uint first_pass, uint per_pass) {
    PassSum next = PassSum(vec3(0.0), 0u);
    next = p_7;
    bvec3 _e7 = is_finite_vec3f(c_7);
    if (all(_e7)) {
        vec3 _e10 = next.sum;
        next.sum = (_e10 + c_7);
    } else {
        vec3 _e13 = next.sum;
        vec3 _e14 = finite_or_zero(c_7);
        next.sum = (_e13 + _e14);
        uint _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    uint _e22 = rem_u32_((s_4 + 1u), per_pass);
    if ((_e22 != 0u)) {
        PassSum _e25 = next;
        return _e25;
    }
    uint _e27 = ray_count;
    atomicAdd(_group_0_binding_9_cs[1], _e27);
    ray_count = 0u;
    uint _e31 = div_u32_(s_4, per_pass);
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
    uint s_5 = 0u;
    FrameUniforms frame_6 = _group_0_binding_0_cs;
    TileParams tile_2 = _group_0_binding_1_cs;
    uint index_1 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = (tile_2.frame * per_pass_1);
    uint count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = PassSum(vec3(0.0), 0u);
    s_5 = 0u;
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e35 = s_5;
            s_5 = (_e35 + 1u);
        }
        loop_init_4 = false;
        uint _e25 = s_5;
        if ((_e25 >= count_2)) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_5;
        Ray _e30 = sample_camera_ray(pixel_5, (first_1 + _e28));
        vec3 _e31 = trace(_e30);
        uint _e32 = s_5;
        PassSum _e34 = add_sample(_e27, _e31, _e32, index_1, tile_2.frame, per_pass_1);
        sums = _e34;
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

