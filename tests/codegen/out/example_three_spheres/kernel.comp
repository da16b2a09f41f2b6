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
struct SupersampledPinhole {
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
struct BvhMesh {
    uint mesh;
};
struct Intersection {
    float t;
    vec3 normal;
    vec2 uv;
};
struct BvhNode {
    vec3 min_;
    vec3 max_;
    uint first;
    uint count;
};
struct Triangle {
    vec3 v0_;
    vec3 v1_;
    vec3 v2_;
};
struct Sphere {
    vec3 center;
    float radius;
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
struct Skybox {
    uint image;
    float intensity;
    float rotation;
};
struct Lambert {
    vec3 albedo;
};
struct LightSample {
    vec3 dir;
    float dist;
    vec3 radiance;
    float pdf;
};
struct PointLight {
    vec3 position;
    vec3 color;
    float intensity;
    float range;
    float inner_range;
};
struct Frame {
    Ray ray;
    Hit hit;
    float error;
    uint slot;
    vec3 sum;
    vec3 dirs[1];
    vec3 weights[1];
    uint count;
    uint next;
};
const uint WORKGROUP_WIDTH = 8u;
const uint WORKGROUP_HEIGHT = 8u;
const uint NO_HIT = 4294967295u;
const uint SCATTER = 1000003u;
const uint SCRATCH_RNG_INDEX = 12u;
const uint SCRATCH_RNG_SEED = 13u;
const uint SUPERSAMPLING_GRID = 2u;
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
const uint TLAS_STACK = 3u;
const uint BVH_MESH_STACK = 64u;
const float TAU = 6.2831855;
const float INV_PI = 0.31830987;
const float POINT_ERROR = 1.9073486e-6;
const float GAMMA_1_ = 5.960465e-8;
const float GAMMA_6_ = 3.576281e-7;
const float GAMMA_4_ = 2.3841864e-7;
const bool HAS_SECONDARY_RAYS = false;
const bool HAS_BACKGROUND = true;
const uint TEXTURE_WRAP_MASK = 3u;
const uint TEXTURE_WRAP_V_SHIFT = 2u;
const uint TEXTURE_NEAREST = 16u;
const uint TEXTURE_WRAP_MIRROR = 2u;
const uint TEXTURE_WRAP_CLAMP = 1u;
const uint TEXTURE_FORMAT_RGBA8_SRGB = 0u;
const uint TEXTURE_FORMAT_RGBA8_UNORM = 2u;
const uint RGBA16F_TEXEL_WORDS = 2u;
const uint LIGHT_ENTRY_STRIDE = 2u;
const uint SCRATCH_SHADOW_MODE = 14u;
const uint SHADOW_UNOCCLUDED = 1u;
const uint SHADOW_ABOVE = 2u;
const float LIGHT_ERROR = 4.7683716e-7;
const uint RAY_SHADOW = 2u;
const uint FLAG_MEDIUM = 4u;
const uint FLAG_SECONDARY_RAYS = 2u;
const uint MAX_DEPTH = 4u;
const uint STACK_SIZE = 4u;
const uint MAX_SPAWN = 1u;
const uint RAY_SECONDARY = 1u;

layout(std140, binding = 1) uniform TileParams_block_0Compute { TileParams _group_0_binding_1_cs; };

layout(std140, binding = 0) uniform FrameUniforms_block_1Compute { FrameUniforms _group_0_binding_0_cs; };

uint scratch[15] = uint[15](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

uint rng_state = 0u;

layout(std430, binding = 6) readonly buffer type_5_block_2Compute { uint _group_0_binding_6_cs[]; };

uint F32_INF = 2139095040u;

layout(std430, binding = 3) readonly buffer type_9_block_3Compute { GpuInstance _group_0_binding_3_cs[]; };

layout(std430, binding = 2) readonly buffer type_10_block_4Compute { GpuNode _group_0_binding_2_cs[]; };

layout(std430, binding = 4) readonly buffer type_12_block_5Compute { vec4 _group_0_binding_4_cs[]; };

uint traversal_stack[67] = uint[67](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

uint F32_NEG_INF = 4286578688u;

float hit_error = 0.0;

layout(std430, binding = 5) readonly buffer type_17_block_6Compute { uvec4 _group_0_binding_5_cs[]; };

uint ray_count = 0u;

layout(std430, binding = 7) readonly buffer type_5_block_7Compute { uint _group_0_binding_7_cs[]; };

vec3 spawn_dirs[1] = vec3[1](vec3(0.0));

vec3 spawn_weights[1] = vec3[1](vec3(0.0));

uint spawn_count = 0u;

layout(std430, binding = 9) buffer type_24_block_8Compute { uint _group_0_binding_9_cs[]; };

layout(std430, binding = 8) buffer type_12_block_9Compute { vec4 _group_0_binding_8_cs[]; };


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

SupersampledPinhole load_SupersampledPinhole(uint offset) {
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
    return SupersampledPinhole(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), vec3(uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55)), uintBitsToFloat(_e62));
}

uvec2 image_size_query() {
    TileParams _e1 = _group_0_binding_1_cs;
    return _e1.image_size;
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
    uint i_7 = bitfieldReverse(_e24);
    x_2 = i_7;
    if (((d & 1u) != 0u)) {
        uint _e31 = sobol_second_reversed(i_7);
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

Ray supersampled_ray(SupersampledPinhole cam, uvec2 pixel_2, uint sample_2) {
    uvec2 _e3 = image_size_query();
    vec2 size_1 = vec2(_e3);
    uint _e8 = rem_u32_(sample_2, (SUPERSAMPLING_GRID * SUPERSAMPLING_GRID));
    uint _e10 = rem_u32_(_e8, SUPERSAMPLING_GRID);
    uint _e13 = div_u32_(_e8, SUPERSAMPLING_GRID);
    vec2 stratum = vec2(float(_e10), float(_e13));
    vec2 _e16 = rand2_next();
    vec2 offset_13 = ((stratum + _e16) / vec2(float(SUPERSAMPLING_GRID)));
    vec2 ndc = ((((vec2(pixel_2) + offset_13) / size_1) * vec2(2.0)) - vec2(1.0));
    vec3 _e34 = normalize_vec3f((cam.look_at - cam.position));
    vec3 _e37 = normalize_vec3f(cross(_e34, cam.up));
    vec3 up = cross(_e37, _e34);
    float h = tan((radians(cam.fov) * 0.5));
    float aspect = (size_1.x / size_1.y);
    vec3 _e58 = normalize_vec3f(((_e34 + (_e37 * vec3(((ndc.x * h) * aspect)))) - (up * vec3((ndc.y * h)))));
    uint _e62 = F32_INF;
    return Ray(cam.position, 0.0, _e58, uintBitsToFloat(_e62), 0u, 0u, 0u);
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uvec2 pixel_3, uint sample_3) {
    SupersampledPinhole _e3 = load_SupersampledPinhole(offset_1);
    Ray _e4 = supersampled_ray(_e3, pixel_3, sample_3);
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
    vec3 a_5 = (_e9.xyz - r_1.origin);
    vec4 _e19 = _group_0_binding_4_cs[((slot * 3u) + 1u)];
    vec3 b_8 = (_e19.xyz - r_1.origin);
    vec4 _e29 = _group_0_binding_4_cs[((slot * 3u) + 2u)];
    vec3 c_6 = (_e29.xyz - r_1.origin);
    float ax = (a_5[min(r_1.kx, 2u)] - (r_1.shear.x * a_5[min(r_1.kz, 2u)]));
    float ay = (a_5[min(r_1.ky, 2u)] - (r_1.shear.y * a_5[min(r_1.kz, 2u)]));
    float bx = (b_8[min(r_1.kx, 2u)] - (r_1.shear.x * b_8[min(r_1.kz, 2u)]));
    float by = (b_8[min(r_1.ky, 2u)] - (r_1.shear.y * b_8[min(r_1.kz, 2u)]));
    float cx = (c_6[min(r_1.kx, 2u)] - (r_1.shear.x * c_6[min(r_1.kz, 2u)]));
    float cy = (c_6[min(r_1.ky, 2u)] - (r_1.shear.y * c_6[min(r_1.kz, 2u)]));
    float u = ((cx * by) - (cy * bx));
    float v_2 = ((ax * cy) - (ay * cx));
    float w = ((bx * ay) - (by * ax));
    bool outside = ((((u < 0.0) || (v_2 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_2 > 0.0)) || (w > 0.0)));
    float det = ((u + v_2) + w);
    float scaled = (((u * (r_1.shear.z * a_5[min(r_1.kz, 2u)])) + (v_2 * (r_1.shear.z * b_8[min(r_1.kz, 2u)]))) + (w * (r_1.shear.z * c_6[min(r_1.kz, 2u)])));
    if (occlusion) {
        float st = ((det < 0.0) ? -(scaled) : scaled);
        float ad_1 = abs(det);
        bool hit_7 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        uint _e178 = F32_INF;
        return (hit_7 ? vec3(tmin, 0.0, 0.0) : vec3(uintBitsToFloat(_e178), 0.0, 0.0));
    }
    float rcp = (1.0 / det);
    float t_7 = (scaled * rcp);
    bool hit_8 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (t_7 >= tmin)) && (t_7 <= tmax_1));
    uint _e202 = F32_INF;
    return (hit_8 ? vec3(t_7, (v_2 * rcp), (w * rcp)) : vec3(uintBitsToFloat(_e202), 0.0, 0.0));
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
    vec2 x_7 = mix(far_2.xy, far_2.yz, lessThan(far_2.yz, far_2.xy));
    float exit = ((x_7.y < x_7.x) ? x_7.y : x_7.x);
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
    float t_8 = (tmax_3 * b_5.unit);
    uvec3 _e9 = node_box_lo(lq);
    uvec3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(vec3(_e9), vec3(_e11), b_5, t_8);
    uvec3 _e14 = node_box_lo(rq);
    uvec3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(vec3(_e14), vec3(_e16), b_5, t_8);
    return vec2(_e13, _e18);
}

uvec2 pop(uint base, uint sp) {
    if ((sp == 0u)) {
        return uvec2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack[min(((base + sp) - 1u), 66u)];
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
                    Candidate c_7 = Candidate(_e46.x, owner, prim, _e46.yz, vec3(0.0));
                    bool _e73 = accept(inst_2, world_ray, c_7);
                    if (_e73) {
                        best = c_7;
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
                    traversal_stack[min((TLAS_STACK + _e109), 66u)] = _e111;
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

BvhMesh load_BvhMesh(uint offset_2) {
    uint _e5 = _group_0_binding_6_cs[(offset_2 + 0u)];
    return BvhMesh(_e5);
}

BvhNode mesh_node_query(uint m, uint i_1) {
    vec3 lo_1 = vec3(0.0);
    vec3 hi_1 = vec3(0.0);
    uint reference = 0u;
    uvec3 q_1 = uvec3(0u);
    uint base_2 = _group_0_binding_6_cs[m];
    GpuNode header_3 = _group_0_binding_2_cs[base_2];
    lo_1 = header_3.min_;
    vec3 _e10 = node_frame_hi(header_3);
    hi_1 = _e10;
    reference = header_3.a;
    if ((i_1 >= 2u)) {
        GpuNode n_9 = _group_0_binding_2_cs[(base_2 + (i_1 >> 1u))];
        q_1 = floatBitsToUint(n_9.min_);
        reference = n_9.a;
        if (((i_1 & 1u) != 0u)) {
            q_1 = floatBitsToUint(n_9.max_);
            reference = n_9.b;
        }
        uvec3 _e35 = q_1;
        uvec3 _e36 = node_box_lo(_e35);
        vec3 _e37 = node_point(header_3.min_, header_3.max_, _e36);
        lo_1 = _e37;
        uvec3 _e40 = q_1;
        uvec3 _e41 = node_box_hi(_e40);
        vec3 _e42 = node_point(header_3.min_, header_3.max_, _e41);
        hi_1 = _e42;
    }
    uint _e43 = reference;
    if (((_e43 & NODE_LEAF_BIT) == 0u)) {
        vec3 _e48 = lo_1;
        vec3 _e49 = hi_1;
        uint _e51 = reference;
        return BvhNode(_e48, _e49, (2u * _e51), 0u);
    }
    uint _e55 = reference;
    uint count_2 = ((_e55 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK);
    if ((count_2 == 0u)) {
        return BvhNode(uintBitsToFloat(uvec3(2139095039u)), uintBitsToFloat(uvec3(4286578687u)), 0u, 0u);
    }
    vec3 _e73 = lo_1;
    vec3 _e74 = hi_1;
    uint _e75 = reference;
    return BvhNode(_e73, _e74, (_e75 & NODE_FIRST_MASK), count_2);
}

vec2 intersect_aabb(Ray ray_5, vec3 min_, vec3 max_) {
    bvec3 parallel = lessThan(abs(ray_5.dir), vec3(1.1754944e-38));
    vec3 _e12 = vec3(1.0);
    vec3 inv_dir = (_e12 / mix(ray_5.dir, _e12, parallel));
    vec3 _e17 = ((min_ - ray_5.origin) * inv_dir);
    vec3 _e18 = ((max_ - ray_5.origin) * inv_dir);
    bvec3 _e23 = bvec3(lessThanEqual(min_, ray_5.origin).x && lessThanEqual(ray_5.origin, max_).x, lessThanEqual(min_, ray_5.origin).y && lessThanEqual(ray_5.origin, max_).y, lessThanEqual(min_, ray_5.origin).z && lessThanEqual(ray_5.origin, max_).z);
    uint _e25 = F32_INF;
    vec3 _e27 = vec3(uintBitsToFloat(_e25));
    uint _e29 = F32_NEG_INF;
    vec3 _e31 = vec3(uintBitsToFloat(_e29));
    vec3 near_3 = mix(min(_e17, _e18), mix(_e27, _e31, _e23), parallel);
    vec3 far_3 = mix(max(_e17, _e18), mix(_e31, _e27, _e23), parallel);
    return vec2(max(max(max(near_3.x, near_3.y), near_3.z), ray_5.tmin), min(min(min(far_3.x, far_3.y), far_3.z), ray_5.tmax));
}

float bvh_mesh_enter(Ray ray_6, BvhNode n_1, float tmax_4) {
    vec2 _e5 = intersect_aabb(ray_6, n_1.min_, n_1.max_);
    uint _e7 = F32_INF;
    return (((_e5.x <= _e5.y) && (_e5.x <= tmax_4)) ? _e5.x : uintBitsToFloat(_e7));
}

Triangle mesh_triangle_query(uint m_1, uint i_2) {
    uint _e6 = _group_0_binding_6_cs[(m_1 + 1u)];
    uint slot_4 = (_e6 + i_2);
    vec4 _e12 = _group_0_binding_4_cs[(slot_4 * 3u)];
    vec4 _e20 = _group_0_binding_4_cs[((slot_4 * 3u) + 1u)];
    vec4 _e28 = _group_0_binding_4_cs[((slot_4 * 3u) + 2u)];
    return Triangle(_e12.xyz, _e20.xyz, _e28.xyz);
}

Intersection intersect_triangle(Ray ray_7, Triangle tri) {
    uvec3 _e10 = uvec3(2139095040u);
    vec3 dir_5 = mix(ray_7.dir, vec3(0.0), lessThan(abs(ray_7.dir), vec3(1.1754944e-38)));
    vec3 _e31 = abs(dir_5);
    bool _e38 = (_e31.y > _e31.x);
    uint kz_1 = ((_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u));
    uint _e45 = ((kz_1 == 2u) ? 0u : (kz_1 + 1u));
    uint _e49 = ((kz_1 >= 1u) ? (kz_1 - 1u) : (kz_1 + 2u));
    float dz_1 = dir_5[kz_1];
    bool _e52 = (dz_1 < 0.0);
    uint kx_1 = (_e52 ? _e49 : _e45);
    uint ky_1 = (_e52 ? _e45 : _e49);
    float sx = (dir_5[kx_1] / dz_1);
    float sy = (dir_5[ky_1] / dz_1);
    float sz = (1.0 / dz_1);
    vec3 _e62 = (tri.v0_ - ray_7.origin);
    float _e68 = (_e62[kx_1] - (sx * _e62[kz_1]));
    float _e69 = (_e62[ky_1] - (sy * _e62[kz_1]));
    vec3 _e71 = (tri.v1_ - ray_7.origin);
    float _e77 = (_e71[kx_1] - (sx * _e71[kz_1]));
    float _e78 = (_e71[ky_1] - (sy * _e71[kz_1]));
    vec3 _e80 = (tri.v2_ - ray_7.origin);
    float _e86 = (_e80[kx_1] - (sx * _e80[kz_1]));
    float _e87 = (_e80[ky_1] - (sy * _e80[kz_1]));
    float u_1 = ((_e86 * _e78) - (_e87 * _e77));
    float v_3 = ((_e68 * _e87) - (_e69 * _e86));
    float w_1 = ((_e77 * _e69) - (_e78 * _e68));
    float det_1 = ((u_1 + v_3) + w_1);
    float _e112 = (1.0 / det_1);
    float t_9 = ((((u_1 * (sz * _e62[kz_1])) + (v_3 * (sz * _e71[kz_1]))) + (w_1 * (sz * _e80[kz_1]))) * _e112);
    bool hit_9 = (((((all(lessThan((floatBitsToUint(ray_7.origin) & uvec3(2147483647u)), _e10)) && all(lessThan((floatBitsToUint(ray_7.dir) & uvec3(2147483647u)), _e10))) && (dz_1 != 0.0)) && !(((((u_1 < 0.0) || (v_3 < 0.0)) || (w_1 < 0.0)) && (((u_1 > 0.0) || (v_3 > 0.0)) || (w_1 > 0.0))))) && !((det_1 == 0.0))) && ((t_9 >= ray_7.tmin) && (t_9 <= ray_7.tmax)));
    vec3 _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    uint _e137 = F32_INF;
    return Intersection((hit_9 ? t_9 : uintBitsToFloat(_e137)), (hit_9 ? _e132 : vec3(0.0, 0.0, 1.0)), (hit_9 ? vec2((v_3 * _e112), (w_1 * _e112)) : vec2(0.0)));
}

Intersection bvh_mesh_intersect(BvhMesh g, Ray ray_8) {
    Intersection best_1 = Intersection(0.0, vec3(0.0), vec2(0.0));
    Ray r_2 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    uint stack[64] = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    float stack_t[64] = float[64](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint sp_2 = 0u;
    BvhNode node = BvhNode(vec3(0.0), vec3(0.0), 0u, 0u);
    uint k_1 = 0u;
    bool found = false;
    uint _e3 = F32_INF;
    best_1 = Intersection(uintBitsToFloat(_e3), vec3(0.0, 0.0, 1.0), vec2(0.0));
    r_2 = ray_8;
    stack = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    stack_t = float[64](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    sp_2 = 0u;
    BvhNode _e21 = mesh_node_query(g.mesh, 0u);
    node = _e21;
    Ray _e23 = r_2;
    BvhNode _e24 = node;
    float _e26 = r_2.tmax;
    float _e27 = bvh_mesh_enter(_e23, _e24, _e26);
    uint _e29 = F32_INF;
    if ((_e27 == uintBitsToFloat(_e29))) {
        Intersection _e32 = best_1;
        return _e32;
    }
    while(true) {
        uint _e34 = node.count;
        if ((_e34 > 0u)) {
            uint end = node.count;
            k_1 = 0u;
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    uint _e57 = k_1;
                    k_1 = (_e57 + 1u);
                }
                loop_init_1 = false;
                uint _e41 = k_1;
                if ((_e41 >= end)) {
                    break;
                }
                Ray _e43 = r_2;
                uint _e46 = node.first;
                uint _e47 = k_1;
                Triangle _e49 = mesh_triangle_query(g.mesh, (_e46 + _e47));
                Intersection _e50 = intersect_triangle(_e43, _e49);
                float _e53 = best_1.t;
                if ((_e50.t < _e53)) {
                    best_1 = _e50;
                    r_2.tmax = _e50.t;
                }
            }
        } else {
            uint first_1 = node.first;
            BvhNode _e63 = mesh_node_query(g.mesh, first_1);
            BvhNode _e67 = mesh_node_query(g.mesh, (first_1 + 1u));
            Ray _e68 = r_2;
            float _e70 = r_2.tmax;
            float _e71 = bvh_mesh_enter(_e68, _e63, _e70);
            Ray _e72 = r_2;
            float _e74 = r_2.tmax;
            float _e75 = bvh_mesh_enter(_e72, _e67, _e74);
            uint _e78 = F32_INF;
            if ((min(_e71, _e75) < uintBitsToFloat(_e78))) {
                bool left_first = (_e71 <= _e75);
                uint _e84 = F32_INF;
                uint _e87 = sp_2;
                if (((max(_e71, _e75) < uintBitsToFloat(_e84)) && (_e87 < BVH_MESH_STACK))) {
                    uint _e91 = sp_2;
                    stack[min(_e91, 63u)] = (left_first ? (first_1 + 1u) : first_1);
                    uint _e98 = sp_2;
                    stack_t[min(_e98, 63u)] = max(_e71, _e75);
                    uint _e103 = sp_2;
                    sp_2 = (_e103 + 1u);
                }
                node = _e67;
                if (left_first) {
                    node = _e63;
                }
                continue;
            }
        }
        found = false;
        while(true) {
            uint _e108 = sp_2;
            bool _e111 = found;
            if (!(((_e108 > 0u) && !(_e111)))) {
                break;
            }
            uint _e115 = sp_2;
            sp_2 = (_e115 - 1u);
            uint _e118 = sp_2;
            float _e122 = stack_t[min(_e118, 63u)];
            float _e124 = r_2.tmax;
            found = (_e122 <= _e124);
        }
        bool _e126 = found;
        if (!(_e126)) {
            break;
        }
        uint _e129 = sp_2;
        uint _e133 = stack[min(_e129, 63u)];
        BvhNode _e134 = mesh_node_query(g.mesh, _e133);
        node = _e134;
    }
    Intersection _e135 = best_1;
    return _e135;
}

Sphere load_Sphere(uint offset_3) {
    uint _e5 = _group_0_binding_6_cs[(offset_3 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_3 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_3 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_3 + 3u)];
    return Sphere(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), uintBitsToFloat(_e24));
}

Intersection sphere_intersect(Sphere s, Ray ray_9) {
    float t = 0.0;
    vec3 f_2 = (ray_9.origin - s.center);
    float a_6 = dot(ray_9.dir, ray_9.dir);
    float b_9 = -(dot(f_2, ray_9.dir));
    vec3 l_1 = (f_2 + (ray_9.dir * vec3((b_9 / a_6))));
    float r2_ = (s.radius * s.radius);
    float disc = (a_6 * (r2_ - dot(l_1, l_1)));
    if ((!((disc >= 0.0)) || !((a_6 > 0.0)))) {
        uint _e30 = F32_INF;
        return Intersection(uintBitsToFloat(_e30), vec3(0.0, 0.0, 1.0), vec2(0.0));
    }
    float q_2 = (b_9 + (((b_9 >= 0.0) ? 1.0 : -1.0) * sqrt(disc)));
    float t0_1 = ((dot(f_2, f_2) - r2_) / q_2);
    float t1_1 = (q_2 / a_6);
    t = min(t0_1, t1_1);
    float _e52 = t;
    if (!((_e52 >= ray_9.tmin))) {
        t = max(t0_1, t1_1);
    }
    float _e57 = t;
    float _e60 = t;
    if (!(((_e57 >= ray_9.tmin) && (_e60 <= ray_9.tmax)))) {
        uint _e66 = F32_INF;
        return Intersection(uintBitsToFloat(_e66), vec3(0.0, 0.0, 1.0), vec2(0.0));
    }
    float _e76 = t;
    vec3 _e82 = normalize_vec3f(((ray_9.origin + (ray_9.dir * vec3(_e76))) - s.center));
    float u_2 = (((_e82.x == 0.0) && (_e82.z == 0.0)) ? 0.5 : (0.5 + (atan(_e82.z, -(_e82.x)) / TAU)));
    vec2 uv_1 = vec2(u_2, (acos(min(max(_e82.y, -1.0), 1.0)) * INV_PI));
    float _e109 = t;
    return Intersection(_e109, _e82, uv_1);
}

Intersection dispatch_intersection(uint type_id_1, uint offset_4, Ray ray_10) {
    switch(type_id_1) {
        case 0u: {
            BvhMesh _e3 = load_BvhMesh(offset_4);
            Intersection _e4 = bvh_mesh_intersect(_e3, ray_10);
            return _e4;
        }
        case 1u: {
            Sphere _e5 = load_Sphere(offset_4);
            Intersection _e6 = sphere_intersect(_e5, ray_10);
            return _e6;
        }
        default: {
            break;
        }
    }
    return Intersection(0.0, vec3(0.0), vec2(0.0));
}

Candidate intersect_object(uint slot_2, Ray ray_11, Candidate best_2, bool shadow_1) {
    Ray r_3 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    GpuInstance inst_6 = _group_0_binding_3_cs[slot_2];
    Ray _e7 = to_object(inst_6, ray_11);
    r_3 = _e7;
    r_3.tmax = best_2.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_3;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_11, _e14, best_2, shadow_1);
        return _e15;
    }
    Ray _e18 = r_3;
    Intersection _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18);
    float _e22 = r_3.tmin;
    float _e26 = r_3.tmax;
    uint _e31 = F32_INF;
    if ((((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < uintBitsToFloat(_e31)))) {
        Candidate c_8 = Candidate(_e19.t, slot_2, 0u, _e19.uv, _e19.normal);
        bool _e40 = accept(inst_6, ray_11, c_8);
        if (_e40) {
            return c_8;
        }
    }
    return best_2;
}

float point_error(vec3 origin_1, vec3 along) {
    vec3 a_7 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_7.x, a_7.y), a_7.z));
}

Triangle load_triangle(uint slot_3) {
    vec4 v0_1 = _group_0_binding_4_cs[(slot_3 * 3u)];
    vec4 v1_ = _group_0_binding_4_cs[((slot_3 * 3u) + 1u)];
    vec4 v2_ = _group_0_binding_4_cs[((slot_3 * 3u) + 2u)];
    return Triangle(v0_1.xyz, v1_.xyz, v2_.xyz);
}

vec3 point_to_world(GpuInstance inst_3, vec3 p_2) {
    vec4 q_3 = vec4(p_2, 1.0);
    return vec3(dot(inst_3.object_to_world_0_, q_3), dot(inst_3.object_to_world_1_, q_3), dot(inst_3.object_to_world_2_, q_3));
}

float mesh_error(GpuInstance inst_4, vec3 v0_, vec3 db1_, vec3 db2_, vec3 p_3) {
    vec3 obj = ((vec3(GAMMA_1_) * abs(v0_)) + (vec3(GAMMA_6_) * (abs(db1_) + abs(db2_))));
    vec4 q_4 = vec4(abs(p_3), 1.0);
    vec4 r0_ = abs(inst_4.object_to_world_0_);
    vec4 r1_ = abs(inst_4.object_to_world_1_);
    vec4 r2_1 = abs(inst_4.object_to_world_2_);
    vec3 rounding = (vec3(GAMMA_4_) * vec3(dot(r0_, q_4), dot(r1_, q_4), dot(r2_1, q_4)));
    vec3 carried = (vec3((1.0 + GAMMA_4_)) * vec3(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_1.xyz, obj)));
    vec3 e_2 = (rounding + carried);
    return max(max(e_2.x, e_2.y), e_2.z);
}

vec3 decode_octahedral(uint bits) {
    vec3 n_2 = vec3(0.0);
    vec2 e_3 = unpackSnorm2x16(bits);
    n_2 = vec3(e_3.x, e_3.y, ((1.0 - abs(e_3.x)) - abs(e_3.y)));
    float _e14 = n_2.z;
    if ((_e14 < 0.0)) {
        vec3 _e21 = n_2;
        vec2 s_5 = mix(vec2(-1.0), vec2(1.0), greaterThanEqual(_e21.xy, vec2(0.0)));
        vec3 _e29 = n_2;
        vec2 xy = ((vec2(1.0) - abs(_e29.yx)) * s_5);
        float _e37 = n_2.z;
        n_2 = vec3(xy.x, xy.y, _e37);
    }
    vec3 _e39 = n_2;
    vec3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

vec3 normal_to_world(GpuInstance inst_5, vec3 n_3) {
    vec3 w_2 = (((inst_5.world_to_object_0_.xyz * vec3(n_3.x)) + (inst_5.world_to_object_1_.xyz * vec3(n_3.y))) + (inst_5.world_to_object_2_.xyz * vec3(n_3.z)));
    vec3 _e19 = normalize_vec3f(w_2);
    return _e19;
}

Hit finish_hit(Ray ray_12, Candidate c_1) {
    Hit hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    vec3 n_geo = vec3(0.0);
    vec3 n_shade = vec3(0.0);
    GpuInstance inst_7 = _group_0_binding_3_cs[c_1.slot];
    float _e11 = point_error(ray_12.origin, (ray_12.dir * vec3(c_1.t)));
    hit_error = _e11;
    hit = Hit((ray_12.origin + (ray_12.dir * vec3(c_1.t))), c_1.t, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if ((inst_7.geometry_type == MESH_GEOMETRY)) {
        Triangle _e42 = load_triangle(c_1.primitive);
        vec2 b_10 = c_1.uv;
        float w_3 = ((1.0 - b_10.x) - b_10.y);
        vec3 e1_ = (_e42.v1_ - _e42.v0_);
        vec3 e2_ = (_e42.v2_ - _e42.v0_);
        vec3 p_7 = (_e42.v0_ + ((e1_ * vec3(b_10.x)) + (e2_ * vec3(b_10.y))));
        vec3 _e65 = point_to_world(inst_7, p_7);
        hit.position = _e65;
        float _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * vec3(b_10.x)), (e2_ * vec3(b_10.y)), p_7);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        uvec4 a0_ = _group_0_binding_5_cs[(c_1.primitive * 2u)];
        uvec4 a1_ = _group_0_binding_5_cs[((c_1.primitive * 2u) + 1u)];
        vec3 _e91 = decode_octahedral(a0_.x);
        vec3 _e95 = decode_octahedral(a0_.y);
        vec3 _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * vec3(w_3)) + (_e95 * vec3(b_10.x))) + (_e101 * vec3(b_10.y)));
        vec3 _e106 = n_shade;
        vec3 _e107 = n_shade;
        if ((dot(_e106, _e107) < 1e-12)) {
            vec3 _e111 = n_geo;
            n_shade = _e111;
        }
        vec2 uv0_ = unpackHalf2x16(a0_.w);
        vec2 uv1_ = unpackHalf2x16(a1_.x);
        vec2 uv2_ = unpackHalf2x16(a1_.y);
        hit.uv = (((uv0_ * vec2(w_3)) + (uv1_ * vec2(b_10.x))) + (uv2_ * vec2(b_10.y)));
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
    hit.front_face = (dot(ray_12.dir, _e147) < 0.0);
    Hit _e151 = hit;
    return _e151;
}

uint medium_at(vec3 p_4, uint exclude) {
    uint inside = 0u;
    float nearest = 0.0;
    uint i_3 = 0u;
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
    uint end_1 = frame_1.medium_count;
    i_3 = 0u;
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e59 = i_3;
            i_3 = (_e59 + 1u);
        }
        loop_init_2 = false;
        uint _e29 = i_3;
        if ((_e29 >= end_1)) {
            break;
        }
        uint _e32 = i_3;
        uint slot_5 = _group_0_binding_6_cs[(frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE))];
        if ((slot_5 != exclude)) {
            uint _e41 = F32_INF;
            Candidate _e43 = no_candidate(uintBitsToFloat(_e41));
            Candidate _e45 = intersect_object(slot_5, probe, _e43, false);
            float _e50 = nearest;
            if (((_e45.slot != NO_HIT) && (_e45.t < _e50))) {
                Hit _e53 = finish_hit(probe, _e45);
                if (!(_e53.front_face)) {
                    inside = (slot_5 + 1u);
                    nearest = _e45.t;
                }
            }
        }
    }
    uint _e62 = inside;
    return _e62;
}

Ray sample_camera_ray(uvec2 pixel_4, uint sample_4) {
    Ray ray_13 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    FrameUniforms frame_2 = _group_0_binding_0_cs;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_13 = _e7;
    ray_13.depth = 0u;
    ray_13.kind = RAY_CAMERA;
    vec3 _e15 = ray_13.origin;
    uint _e17 = medium_at(_e15, NO_HIT);
    ray_13.medium = _e17;
    Ray _e18 = ray_13;
    return _e18;
}

vec3 node_frame_bounds() {
    return vec3(65535.0);
}

Candidate intersect_scene(Ray ray_14, bool shadow_2) {
    Candidate best_3 = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint sp_3 = 0u;
    uint child_1 = 0u;
    uint near_1 = 0u;
    uint far_1 = 0u;
    uint _e3 = ray_count;
    ray_count = (_e3 + 1u);
    Candidate _e7 = no_candidate(ray_14.tmax);
    best_3 = _e7;
    FrameUniforms frame_3 = _group_0_binding_0_cs;
    if ((frame_3.instance_count == 0u)) {
        Candidate _e14 = best_3;
        return _e14;
    }
    uint base_3 = frame_3.tlas_root;
    GpuNode header_4 = _group_0_binding_2_cs[base_3];
    BoxRay _e19 = box_ray(header_4, ray_14);
    vec3 _e22 = node_frame_bounds();
    float _e24 = best_3.t;
    float _e27 = slab_in_frame(vec3(0.0), _e22, _e19, (_e24 * _e19.unit));
    uint _e29 = F32_INF;
    if ((_e27 == uintBitsToFloat(_e29))) {
        Candidate _e32 = best_3;
        return _e32;
    }
    sp_3 = 0u;
    child_1 = header_4.a;
    while(true) {
        uint _e37 = child_1;
        if (((_e37 & NODE_LEAF_BIT) != 0u)) {
            uint _e42 = child_1;
            if ((((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u)) {
                uint _e51 = child_1;
                Candidate _e54 = best_3;
                Candidate _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_14, _e54, shadow_2);
                best_3 = _e55;
                uint _e57 = best_3.slot;
                if ((shadow_2 && (_e57 != NO_HIT))) {
                    Candidate _e61 = best_3;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_10 = _group_0_binding_2_cs[(base_3 + _e62)];
            float _e68 = best_3.t;
            vec2 _e69 = children_entry(n_10, _e19, _e68);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if (((tl_1 < uintBitsToFloat(_e73)) && (tr_1 < uintBitsToFloat(_e77)))) {
                near_1 = n_10.a;
                far_1 = n_10.b;
                if ((tr_1 < tl_1)) {
                    near_1 = n_10.b;
                    far_1 = n_10.a;
                }
                uint _e88 = sp_3;
                if ((_e88 < TLAS_STACK)) {
                    uint _e91 = sp_3;
                    uint _e92 = far_1;
                    traversal_stack[min(_e91, 66u)] = _e92;
                    uint _e97 = sp_3;
                    sp_3 = (_e97 + 1u);
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if ((tl_1 < uintBitsToFloat(_e102))) {
                child_1 = n_10.a;
                continue;
            }
            uint _e107 = F32_INF;
            if ((tr_1 < uintBitsToFloat(_e107))) {
                child_1 = n_10.b;
                continue;
            }
        }
        uint _e112 = sp_3;
        uvec2 _e113 = pop(0u, _e112);
        if ((_e113.x == NO_HIT)) {
            break;
        }
        child_1 = _e113.x;
        sp_3 = _e113.y;
    }
    Candidate _e119 = best_3;
    return _e119;
}

Skybox load_Skybox(uint offset_5) {
    uint _e5 = _group_0_binding_6_cs[(offset_5 + 0u)];
    uint _e10 = _group_0_binding_6_cs[(offset_5 + 1u)];
    uint _e16 = _group_0_binding_6_cs[(offset_5 + 2u)];
    return Skybox(_e5, uintBitsToFloat(_e10), uintBitsToFloat(_e16));
}

int i32_from_f32_(float x_3) {
    return (((floatBitsToUint(x_3) & 2147483647u) > 2139095040u) ? 0 : int(min(max(x_3, -2147483600.0), 2147483500.0)));
}

int rem_i32_(int a_4, int b_6) {
    bool by_zero_4 = (b_6 == 0);
    int divisor_4 = (((a_4 == -2147483648) && (b_6 == -1)) ? 1 : (by_zero_4 ? 1 : b_6));
    return (by_zero_4 ? 0 : (a_4 - (divisor_4 * (a_4 / divisor_4))));
}

ivec2 wrap_texel_pair(int x_4, int n_4, uint mode) {
    int m0_ = 0;
    int period = (2 * n_4);
    int _e5 = rem_i32_(x_4, period);
    m0_ = _e5;
    int _e7 = m0_;
    int _e8 = m0_;
    int _e10 = m0_;
    m0_ = ((_e10 < 0) ? (_e8 + period) : _e7);
    int _e14 = m0_;
    int _e18 = m0_;
    int m1_ = (((_e18 + 1) == period) ? 0 : (_e14 + 1));
    int _e23 = m0_;
    int _e24 = m0_;
    int _e26 = m0_;
    int r0_1 = ((_e26 >= n_4) ? (_e24 - n_4) : _e23);
    int r1_1 = ((m1_ >= n_4) ? (m1_ - n_4) : m1_);
    int _e32 = m0_;
    int _e35 = m0_;
    int _e37 = m0_;
    ivec2 mirror = ivec2(((_e37 >= n_4) ? ((period - 1) - _e35) : _e32), ((m1_ >= n_4) ? ((period - 1) - m1_) : m1_));
    ivec2 wrapped = ((mode == TEXTURE_WRAP_MIRROR) ? mirror : ivec2(r0_1, r1_1));
    return ((mode == TEXTURE_WRAP_CLAMP) ? min(max(ivec2(x_4, (x_4 + 1)), ivec2(0)), ivec2((n_4 - 1))) : wrapped);
}

float srgb_channel(float c_2) {
    if ((c_2 <= 0.04045)) {
        return (c_2 / 12.92);
    }
    return pow(((c_2 + 0.055) / 1.055), 2.4);
}

vec4 texel_at(uint t_1, uint xi, uint yi) {
    uint base_4 = _group_0_binding_6_cs[t_1];
    uint _e10 = _group_0_binding_6_cs[(t_1 + 1u)];
    uint index_1 = ((yi * max(_e10, 1u)) + xi);
    uint format = _group_0_binding_6_cs[(t_1 + 3u)];
    if ((format == TEXTURE_FORMAT_RGBA8_SRGB)) {
        uint _e25 = _group_0_binding_7_cs[(base_4 + index_1)];
        vec4 c_9 = unpackUnorm4x8(_e25);
        float _e28 = srgb_channel(c_9.x);
        float _e30 = srgb_channel(c_9.y);
        float _e32 = srgb_channel(c_9.z);
        return vec4(_e28, _e30, _e32, c_9.w);
    }
    if ((format == TEXTURE_FORMAT_RGBA8_UNORM)) {
        uint _e40 = _group_0_binding_7_cs[(base_4 + index_1)];
        return unpackUnorm4x8(_e40);
    }
    uint _e47 = _group_0_binding_7_cs[(base_4 + (index_1 * RGBA16F_TEXEL_WORDS))];
    vec2 rg = unpackHalf2x16(_e47);
    uint _e56 = _group_0_binding_7_cs[((base_4 + (index_1 * RGBA16F_TEXEL_WORDS)) + 1u)];
    vec2 ba = unpackHalf2x16(_e56);
    return vec4(rg, ba);
}

vec4 sample_texture(uint t_2, vec2 uv) {
    uint _e6 = _group_0_binding_6_cs[(t_2 + 1u)];
    int wi = int(max(_e6, 1u));
    uint _e14 = _group_0_binding_6_cs[(t_2 + 2u)];
    int hi_2 = int(max(_e14, 1u));
    uint sampler_ = _group_0_binding_6_cs[(t_2 + 4u)];
    uint mu = (sampler_ & TEXTURE_WRAP_MASK);
    uint mv = ((sampler_ >> (TEXTURE_WRAP_V_SHIFT & 31u)) & TEXTURE_WRAP_MASK);
    vec2 q_5 = (uv * vec2(float(wi), float(hi_2)));
    vec2 p_8 = (((sampler_ & TEXTURE_NEAREST) != 0u) ? floor(q_5) : (q_5 - vec2(0.5)));
    vec2 f_3 = floor(p_8);
    vec2 fr = (p_8 - f_3);
    int _e47 = i32_from_f32_(f_3.x);
    int _e49 = i32_from_f32_(f_3.y);
    ivec2 _e50 = wrap_texel_pair(_e47, wi, mu);
    uvec2 xs = uvec2(_e50);
    ivec2 _e52 = wrap_texel_pair(_e49, hi_2, mv);
    uvec2 ys = uvec2(_e52);
    uint x0_ = xs.x;
    uint x1_ = xs.y;
    uint y0_ = ys.x;
    uint y1_ = ys.y;
    vec4 _e58 = texel_at(t_2, x0_, y0_);
    vec4 _e59 = texel_at(t_2, x1_, y0_);
    vec4 a_8 = mix(_e58, _e59, vec4(fr.x));
    vec4 _e63 = texel_at(t_2, x0_, y1_);
    vec4 _e64 = texel_at(t_2, x1_, y1_);
    vec4 b_11 = mix(_e63, _e64, vec4(fr.x));
    return mix(a_8, b_11, vec4(fr.y));
}

vec3 skybox(Skybox b_7, Ray ray_15) {
    vec3 _e3 = normalize_vec3f(ray_15.dir);
    bool pole = ((_e3.x == 0.0) && (_e3.z == 0.0));
    float longitude = ((pole ? 0.0 : atan(_e3.x, -(_e3.z))) - radians(b_7.rotation));
    float latitude = acos(min(max(_e3.y, -1.0), 1.0));
    vec2 uv_2 = vec2((0.5 + (longitude / TAU)), (latitude * INV_PI));
    vec4 _e34 = sample_texture(b_7.image, uv_2);
    return (_e34.xyz * vec3(b_7.intensity));
}

vec3 dispatch_miss(uint type_id_2, uint offset_6, Ray ray_16) {
    Skybox _e2 = load_Skybox(offset_6);
    vec3 _e3 = skybox(_e2, ray_16);
    return _e3;
}

vec3 miss(Ray ray_17) {
    if (!(HAS_BACKGROUND)) {
        return vec3(0.0);
    }
    FrameUniforms frame_4 = _group_0_binding_0_cs;
    vec3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_17);
    return _e9;
}

Lambert load_Lambert(uint offset_7) {
    uint _e5 = _group_0_binding_6_cs[(offset_7 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_7 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_7 + 2u)];
    return Lambert(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)));
}

vec3 shading_normal(Ray ray_18, Hit hit_1) {
    vec3 ng = faceforward(hit_1.geometric_normal, ray_18.dir, hit_1.geometric_normal);
    return faceforward(hit_1.normal, -(ng), hit_1.normal);
}

uint light_count_query() {
    FrameUniforms _e1 = _group_0_binding_0_cs;
    return _e1.light_count;
}

PointLight load_PointLight(uint offset_8) {
    uint _e5 = _group_0_binding_6_cs[(offset_8 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_8 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_8 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_8 + 4u)];
    uint _e30 = _group_0_binding_6_cs[(offset_8 + 5u)];
    uint _e36 = _group_0_binding_6_cs[(offset_8 + 6u)];
    uint _e43 = _group_0_binding_6_cs[(offset_8 + 7u)];
    uint _e49 = _group_0_binding_6_cs[(offset_8 + 8u)];
    uint _e55 = _group_0_binding_6_cs[(offset_8 + 9u)];
    return PointLight(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55));
}

float shadow_preset(vec3 normal, vec3 dir) {
    uint mode_1 = scratch[min(SCRATCH_SHADOW_MODE, 14u)];
    if ((mode_1 == SHADOW_UNOCCLUDED)) {
        return 1.0;
    }
    if (((mode_1 == SHADOW_ABOVE) && !((dot(dir, normal) > 0.0)))) {
        return 0.0;
    }
    return -1.0;
}

vec3 step_toward(vec3 x_5, vec3 s_1) {
    uvec3 bits_1 = floatBitsToUint(x_5);
    bvec3 up_1 = greaterThan((sign(x_5) * sign(s_1)), vec3(0.0));
    vec3 stepped = uintBitsToFloat(mix((bits_1 - uvec3(1u)), (bits_1 + uvec3(1u)), up_1));
    vec3 from_zero = mix(vec3(-1.1754944e-38), vec3(1.1754944e-38), greaterThan(s_1, vec3(0.0)));
    vec3 moved = mix(stepped, from_zero, equal(x_5, vec3(0.0)));
    return mix(x_5, moved, not(equal(s_1, vec3(0.0))));
}

vec3 offset_origin(vec3 p_5, vec3 n_5, float error) {
    float d_4 = ((2.0 * error) * ((abs(n_5.x) + abs(n_5.y)) + abs(n_5.z)));
    vec3 offset_14 = (n_5 * vec3(d_4));
    vec3 _e17 = step_toward((p_5 + offset_14), offset_14);
    return _e17;
}

Ray shadow_ray(vec3 position, vec3 normal_1, vec3 dir_1, float dist) {
    vec3 n_6 = vec3(0.0);
    float tmax_5 = 0.0;
    n_6 = normal_1;
    vec3 _e5 = n_6;
    if ((dot(dir_1, _e5) < 0.0)) {
        vec3 _e9 = n_6;
        n_6 = -(_e9);
    }
    vec3 a_9 = abs(position);
    float _e13 = hit_error;
    float error_3 = max(_e13, (GAMMA_4_ * max(max(a_9.x, a_9.y), a_9.z)));
    vec3 _e22 = n_6;
    vec3 _e23 = offset_origin(position, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_5 = uintBitsToFloat(_e25);
    uint _e29 = F32_INF;
    if ((dist < uintBitsToFloat(_e29))) {
        vec3 light = (position + (dir_1 * vec3(dist)));
        float dd = dot(dir_1, dir_1);
        float along_1 = (dot((light - _e23), dir_1) / dd);
        vec3 l_2 = (abs(position) + abs((dir_1 * vec3(dist))));
        tmax_5 = ((along_1 * (1.0 - 1e-5)) - ((LIGHT_ERROR * max(max(l_2.x, l_2.y), l_2.z)) / sqrt(dd)));
    }
    float _e59 = tmax_5;
    return Ray(_e23, 0.0, dir_1, _e59, 0u, RAY_SHADOW, 0u);
}

float shadow_query(vec3 position_1, vec3 normal_2, vec3 dir_2, float dist_1) {
    float _e4 = shadow_preset(normal_2, dir_2);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_1, normal_2, dir_2, dist_1);
    Candidate _e9 = intersect_scene(_e7, true);
    return ((_e9.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample point_light(PointLight l, vec3 position_2, vec3 normal_3) {
    float strength = 0.0;
    vec3 to_light = (l.position - position_2);
    float dist_2 = length(to_light);
    vec3 dir_6 = (to_light / vec3(max(dist_2, 1e-20)));
    strength = (l.intensity / max((dist_2 * dist_2), 1e-20));
    if ((l.range > 0.0)) {
        float _e19 = strength;
        strength = (_e19 * (1.0 - smoothstep(l.inner_range, l.range, dist_2)));
    }
    float _e26 = shadow_query(position_2, normal_3, dir_6, dist_2);
    float _e28 = strength;
    return LightSample(dir_6, dist_2, ((l.color * vec3(_e28)) * vec3(_e26)), 0.0);
}

LightSample dispatch_light(uint type_id_3, uint offset_9, vec3 position_3, vec3 normal_4) {
    PointLight _e3 = load_PointLight(offset_9);
    LightSample _e4 = point_light(_e3, position_3, normal_4);
    return _e4;
}

LightSample sample_light_query(uint i_4, vec3 position_4, vec3 normal_5) {
    FrameUniforms frame_5 = _group_0_binding_0_cs;
    if ((i_4 >= frame_5.light_count)) {
        return LightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0), 0.0);
    }
    uint entry = (frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE));
    uint _e22 = _group_0_binding_6_cs[entry];
    uint _e27 = _group_0_binding_6_cs[(entry + 1u)];
    LightSample _e28 = dispatch_light(_e22, _e27, position_4, normal_5);
    return _e28;
}

vec3 lambert_shade(Lambert m_2, Ray ray_19, Hit hit_2) {
    vec3 color = vec3(0.0);
    uint i_5 = 0u;
    vec3 _e3 = shading_normal(ray_19, hit_2);
    color = vec3(0.0);
    uint _e8 = light_count_query();
    i_5 = 0u;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e30 = i_5;
            i_5 = (_e30 + 1u);
        }
        loop_init_3 = false;
        uint _e10 = i_5;
        if ((_e10 >= _e8)) {
            break;
        }
        uint _e12 = i_5;
        LightSample _e15 = sample_light_query(_e12, hit_2.position, hit_2.geometric_normal);
        vec3 _e16 = color;
        color = (_e16 + (((m_2.albedo * vec3(INV_PI)) * _e15.radiance) * vec3(max(dot(_e3, _e15.dir), 0.0))));
    }
    vec3 _e33 = color;
    return _e33;
}

vec3 dispatch_closest_hit(uint type_id_4, uint offset_10, Ray ray_20, Hit hit_3, vec3 secondary) {
    Lambert _e3 = load_Lambert(offset_10);
    vec3 _e4 = lambert_shade(_e3, ray_20, hit_3);
    return _e4;
}

vec3 shade_direct(Ray ray_21, Candidate c_3) {
    GpuInstance inst_8 = _group_0_binding_3_cs[c_3.slot];
    Hit _e6 = finish_hit(ray_21, c_3);
    vec3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_21, _e6, vec3(0.0));
    return _e11;
}

vec3 dispatch_medium(uint type_id_5, uint offset_11, Ray ray_22, float t_3, vec3 radiance) {
    return vec3(0.0);
}

vec3 through_medium(Ray ray_23, float t_4, vec3 radiance_1) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_23.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_9 = _group_0_binding_3_cs[(ray_23.medium - 1u)];
    if (((inst_9.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    vec3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_23, t_4, radiance_1);
    return _e21;
}

void dispatch_secondary_rays(uint type_id_6, uint offset_12, Ray ray_24, Hit hit_4) {
    return;
}

vec3 spawn_origin_at(vec3 position_5, vec3 normal_6, float error_1, vec3 dir_3) {
    vec3 n_7 = vec3(0.0);
    n_7 = normal_6;
    vec3 _e5 = n_7;
    if ((dot(dir_3, _e5) < 0.0)) {
        vec3 _e9 = n_7;
        n_7 = -(_e9);
    }
    vec3 _e11 = n_7;
    vec3 _e12 = offset_origin(position_5, _e11, error_1);
    return _e12;
}

vec3 spawn_origin(Hit hit_5, float error_2, vec3 dir_4) {
    vec3 _e5 = spawn_origin_at(hit_5.position, hit_5.geometric_normal, error_2, dir_4);
    return _e5;
}

vec3 trace(Ray camera_ray) {
    vec3 radiance_2 = vec3(0.0);
    float t_5 = 0.0;
    Frame stack_1[4] = Frame[4](Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u));
    uint depth = 0u;
    Ray ray_25 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    vec3 value = vec3(0.0);
    bool have_value = false;
    Ray s_ray = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    Candidate s_c = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    Hit s_hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    float s_error = 0.0;
    vec3 s_sum = vec3(0.0);
    bool fresh = false;
    bool waiting = false;
    bool pushed = false;
    vec3 radiance_3 = vec3(0.0);
    float t_6 = 0.0;
    Hit hit_6 = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    Frame f_1 = Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u);
    uint i_6 = 0u;
    uint medium = 0u;
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray, false);
        radiance_2 = vec3(0.0);
        uint _e9 = F32_INF;
        t_5 = uintBitsToFloat(_e9);
        if ((_e4.slot == NO_HIT)) {
            hit_error = 0.0;
            vec3 _e17 = miss(camera_ray);
            radiance_2 = _e17;
        } else {
            vec3 _e18 = shade_direct(camera_ray, _e4);
            radiance_2 = _e18;
            t_5 = _e4.t;
        }
        float _e20 = t_5;
        vec3 _e21 = radiance_2;
        vec3 _e22 = through_medium(camera_ray, _e20, _e21);
        return _e22;
    }
    stack_1 = Frame[4](Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u), Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0.0, 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u));
    depth = 0u;
    ray_25 = camera_ray;
    value = vec3(0.0);
    have_value = false;
    s_ray = camera_ray;
    uint _e35 = F32_INF;
    Candidate _e37 = no_candidate(uintBitsToFloat(_e35));
    s_c = _e37;
    s_hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), true, 0u, 0u);
    s_error = 0.0;
    s_sum = vec3(0.0);
    fresh = false;
    waiting = false;
    while(true) {
        bool _e62 = have_value;
        bool _e64 = waiting;
        if ((!(_e62) && !(_e64))) {
            Ray _e67 = ray_25;
            Candidate _e69 = intersect_scene(_e67, false);
            s_c = _e69;
            Ray _e70 = ray_25;
            s_ray = _e70;
            s_sum = vec3(0.0);
            fresh = true;
            waiting = true;
        }
        bool _e75 = waiting;
        if (_e75) {
            waiting = false;
            pushed = false;
            radiance_3 = vec3(0.0);
            uint _e83 = F32_INF;
            t_6 = uintBitsToFloat(_e83);
            uint _e87 = s_c.slot;
            if ((_e87 == NO_HIT)) {
                hit_error = 0.0;
                Ray _e92 = s_ray;
                vec3 _e93 = miss(_e92);
                radiance_3 = _e93;
            } else {
                uint _e95 = s_c.slot;
                GpuInstance inst_10 = _group_0_binding_3_cs[_e95];
                Hit _e99 = s_hit;
                hit_6 = _e99;
                bool _e101 = fresh;
                if (_e101) {
                    Ray _e102 = s_ray;
                    Candidate _e103 = s_c;
                    Hit _e104 = finish_hit(_e102, _e103);
                    hit_6 = _e104;
                    float _e106 = hit_error;
                    s_error = _e106;
                } else {
                    float _e107 = s_error;
                    hit_error = _e107;
                }
                float _e110 = hit_6.t;
                t_6 = _e110;
                bool _e111 = fresh;
                uint _e119 = s_ray.depth;
                uint _e123 = depth;
                if ((((_e111 && ((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u)) && (_e119 < MAX_DEPTH)) && (_e123 < STACK_SIZE))) {
                    spawn_count = 0u;
                    Ray _e131 = s_ray;
                    Hit _e132 = hit_6;
                    dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, _e131, _e132);
                    uint _e134 = spawn_count;
                    uint n_11 = min(min(_e134, 1u), MAX_SPAWN);
                    if ((n_11 > 0u)) {
                        Ray _e141 = s_ray;
                        Hit _e142 = hit_6;
                        float _e143 = s_error;
                        uint _e145 = s_c.slot;
                        f_1 = Frame(_e141, _e142, _e143, _e145, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), n_11, 0u);
                        i_6 = 0u;
                        bool loop_init_4 = true;
                        while(true) {
                            if (!loop_init_4) {
                                uint _e175 = i_6;
                                i_6 = (_e175 + 1u);
                            }
                            loop_init_4 = false;
                            uint _e155 = i_6;
                            if ((_e155 >= n_11)) {
                                break;
                            }
                            uint _e158 = i_6;
                            uint _e162 = i_6;
                            vec3 _e165 = spawn_dirs[_e162];
                            f_1.dirs[min(_e158, 0u)] = _e165;
                            uint _e167 = i_6;
                            uint _e171 = i_6;
                            vec3 _e174 = spawn_weights[_e171];
                            f_1.weights[min(_e167, 0u)] = _e174;
                        }
                        uint _e178 = depth;
                        Frame _e182 = f_1;
                        stack_1[min(_e178, 3u)] = _e182;
                        uint _e183 = depth;
                        depth = (_e183 + 1u);
                        pushed = true;
                    }
                }
                bool _e187 = pushed;
                if (!(_e187)) {
                    Ray _e191 = s_ray;
                    Hit _e192 = hit_6;
                    vec3 _e193 = s_sum;
                    vec3 _e194 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e191, _e192, _e193);
                    radiance_3 = _e194;
                }
            }
            bool _e195 = pushed;
            if (!(_e195)) {
                Ray _e197 = s_ray;
                float _e198 = t_6;
                vec3 _e199 = radiance_3;
                vec3 _e200 = through_medium(_e197, _e198, _e199);
                value = _e200;
                have_value = true;
            }
        }
        bool _e202 = have_value;
        if (_e202) {
            uint _e203 = depth;
            if ((_e203 == 0u)) {
                vec3 _e206 = value;
                return _e206;
            }
            uint _e207 = depth;
            uint top = (_e207 - 1u);
            uint _e214 = stack_1[min(top, 3u)].next;
            uint child_2 = (_e214 - 1u);
            vec3 _e221 = stack_1[min(top, 3u)].sum;
            vec3 _e229 = stack_1[min(top, 3u)].weights[min(child_2, 0u)];
            vec3 _e230 = value;
            stack_1[min(top, 3u)].sum = (_e221 + (_e229 * _e230));
            have_value = false;
        }
        uint _e234 = depth;
        uint top_1 = (_e234 - 1u);
        uint _e241 = stack_1[min(top_1, 3u)].next;
        uint _e246 = stack_1[min(top_1, 3u)].count;
        if ((_e241 < _e246)) {
            uint i_8 = stack_1[min(top_1, 3u)].next;
            stack_1[min(top_1, 3u)].next = (i_8 + 1u);
            Ray parent = stack_1[min(top_1, 3u)].ray;
            Hit hit_10 = stack_1[min(top_1, 3u)].hit;
            vec3 dir_7 = stack_1[min(top_1, 3u)].dirs[min(i_8, 0u)];
            medium = parent.medium;
            float _e283 = stack_1[min(top_1, 3u)].error;
            vec3 _e284 = spawn_origin(hit_10, _e283, dir_7);
            uint _e287 = F32_INF;
            uint _e293 = medium;
            ray_25 = Ray(_e284, 0.0, dir_7, uintBitsToFloat(_e287), (parent.depth + 1u), RAY_SECONDARY, _e293);
        } else {
            Ray _e299 = stack_1[min(top_1, 3u)].ray;
            s_ray = _e299;
            Hit _e304 = stack_1[min(top_1, 3u)].hit;
            s_hit = _e304;
            float _e309 = stack_1[min(top_1, 3u)].error;
            s_error = _e309;
            uint _e315 = stack_1[min(top_1, 3u)].slot;
            s_c.slot = _e315;
            vec3 _e320 = stack_1[min(top_1, 3u)].sum;
            s_sum = _e320;
            fresh = false;
            waiting = true;
            depth = top_1;
        }
    }
    return vec3(0.0);
}

bvec3 is_finite_vec3f(vec3 x_6) {
    return lessThan((floatBitsToUint(x_6) & uvec3(2147483647u)), uvec3(2139095040u));
}

vec3 finite_or_zero(vec3 c_4) {
    bvec3 _e3 = is_finite_vec3f(c_4);
    return mix(vec3(0.0), c_4, _e3);
}

PassSum add_sample(PassSum p_6, vec3 c_5, uint s_2, uint index, uint first_pass, uint per_pass) {
    PassSum next = PassSum(vec3(0.0), 0u);
    next = p_6;
    bvec3 _e7 = is_finite_vec3f(c_5);
    if (all(_e7)) {
        vec3 _e10 = next.sum;
        next.sum = (_e10 + c_5);
    } else {
        vec3 _e13 = next.sum;
        vec3 _e14 = finite_or_zero(c_5);
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
    FrameUniforms frame_6 = _group_0_binding_0_cs;
    TileParams tile_2 = _group_0_binding_1_cs;
    uint index_2 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_2 = (tile_2.frame * per_pass_1);
    uint count_3 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = PassSum(vec3(0.0), 0u);
    s_3 = 0u;
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e35 = s_3;
            s_3 = (_e35 + 1u);
        }
        loop_init_5 = false;
        uint _e25 = s_3;
        if ((_e25 >= count_3)) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_3;
        Ray _e30 = sample_camera_ray(pixel_5, (first_2 + _e28));
        vec3 _e31 = trace(_e30);
        uint _e32 = s_3;
        PassSum _e34 = add_sample(_e27, _e31, _e32, index_2, tile_2.frame, per_pass_1);
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

