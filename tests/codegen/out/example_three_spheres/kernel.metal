// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size6;
    uint size7;
    uint size8;
    uint size12;
    uint size14;
    uint size18;
    uint size19;
};

struct TileParams {
    metal::uint2 origin;
    metal::uint2 extent;
    metal::uint2 image_size;
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
    metal::packed_float3 sum;
    uint bad;
};
struct Ray {
    metal::packed_float3 origin;
    float tmin;
    metal::packed_float3 dir;
    float tmax;
    uint depth;
    uint kind;
    uint medium;
    char _pad7[4];
};
struct type_4 {
    uint inner[15];
};
typedef uint type_5[1];
struct SupersampledPinhole {
    metal::float3 position;
    metal::float3 look_at;
    metal::packed_float3 up;
    float fov;
};
struct Candidate {
    float t;
    uint slot;
    uint primitive;
    char _pad3[4];
    metal::float2 uv;
    char _pad4[8];
    metal::float3 normal;
};
struct GpuInstance {
    metal::float4 world_to_object_0_;
    metal::float4 world_to_object_1_;
    metal::float4 world_to_object_2_;
    metal::float4 object_to_world_0_;
    metal::float4 object_to_world_1_;
    metal::float4 object_to_world_2_;
    uint geometry_type;
    uint geometry_offset;
    uint material_type;
    uint material_offset;
    uint blas_root;
    uint triangle_offset;
    uint flags;
    uint object;
};
typedef GpuInstance type_9[1];
struct TriangleRay {
    metal::packed_float3 origin;
    uint kx;
    uint ky;
    uint kz;
    char _pad4[8];
    metal::packed_float3 shear;
    bool valid;
    char _pad6[3];
};
struct GpuNode {
    metal::packed_float3 min;
    uint a;
    metal::packed_float3 max;
    uint b;
};
typedef GpuNode type_10[1];
struct BoxRay {
    metal::float3 step;
    metal::float3 start_lo;
    metal::packed_float3 start_hi;
    float tmin;
    float unit;
    char _pad5[12];
};
typedef metal::float4 type_12[1];
struct type_13 {
    uint inner[67];
};
struct BvhMesh {
    uint mesh;
};
struct Intersection {
    float t;
    char _pad1[12];
    metal::float3 normal;
    metal::float2 uv;
    char _pad3[8];
};
struct type_14 {
    uint inner[64];
};
struct type_15 {
    float inner[64];
};
struct BvhNode {
    metal::float3 min;
    metal::packed_float3 max;
    uint first;
    uint count;
    char _pad4[12];
};
struct Triangle {
    metal::float3 v0_;
    metal::float3 v1_;
    metal::float3 v2_;
};
struct Sphere {
    metal::packed_float3 center;
    float radius;
};
struct Hit {
    metal::packed_float3 position;
    float t;
    metal::float3 normal;
    metal::float3 geometric_normal;
    metal::float2 uv;
    bool front_face;
    char _pad6[3];
    uint instance;
    uint primitive;
    char _pad8[12];
};
typedef metal::uint4 type_17[1];
struct Skybox {
    uint image;
    float intensity;
    float rotation;
};
struct Lambert {
    metal::float3 albedo;
};
struct LightSample {
    metal::packed_float3 dir;
    float dist;
    metal::packed_float3 radiance;
    float pdf;
};
struct PointLight {
    metal::float3 position;
    metal::packed_float3 color;
    float intensity;
    float range;
    float inner_range;
    char _pad5[8];
};
struct type_20 {
    metal::float3 inner[1];
};
struct Frame {
    Ray ray;
    Hit hit;
    float error;
    uint slot;
    char _pad4[8];
    metal::float3 sum;
    type_20 dirs;
    type_20 weights;
    uint count;
    uint next;
    char _pad9[8];
};
struct type_21 {
    Frame inner[4];
};
typedef metal::atomic_uint type_24[1];
constant uint WORKGROUP_WIDTH = 8u;
constant uint WORKGROUP_HEIGHT = 8u;
constant uint NO_HIT = 4294967295u;
constant uint SCATTER = 1000003u;
constant uint SCRATCH_RNG_INDEX = 12u;
constant uint SCRATCH_RNG_SEED = 13u;
constant uint SUPERSAMPLING_GRID = 2u;
constant uint HALF_WORD_BITS = 16u;
constant uint RAY_CAMERA = 0u;
constant bool HAS_MEDIA = false;
constant uint MEDIUM_ENTRY_STRIDE = 1u;
constant uint MESH_GEOMETRY = 4294967295u;
constant uint NODE_LEAF_BIT = 2147483648u;
constant uint NODE_COUNT_SHIFT = 27u;
constant uint NODE_COUNT_MASK = 15u;
constant uint NODE_FIRST_MASK = 134217727u;
constant bool HAS_ANY_HIT = false;
constant uint BLAS_STACK = 64u;
constant uint TLAS_STACK = 3u;
constant uint BVH_MESH_STACK = 64u;
constant float TAU = 6.2831855;
constant float INV_PI = 0.31830987;
constant float POINT_ERROR = 0.0000019073486;
constant float GAMMA_1_ = 0.00000005960465;
constant float GAMMA_6_ = 0.0000003576281;
constant float GAMMA_4_ = 0.00000023841864;
constant bool HAS_SECONDARY_RAYS = false;
constant bool HAS_BACKGROUND = true;
constant uint TEXTURE_WRAP_MASK = 3u;
constant uint TEXTURE_WRAP_V_SHIFT = 2u;
constant uint TEXTURE_NEAREST = 16u;
constant uint TEXTURE_WRAP_MIRROR = 2u;
constant uint TEXTURE_WRAP_CLAMP = 1u;
constant uint TEXTURE_FORMAT_RGBA8_SRGB = 0u;
constant uint TEXTURE_FORMAT_RGBA8_UNORM = 2u;
constant uint RGBA16F_TEXEL_WORDS = 2u;
constant uint LIGHT_ENTRY_STRIDE = 2u;
constant uint SCRATCH_SHADOW_MODE = 14u;
constant uint SHADOW_UNOCCLUDED = 1u;
constant uint SHADOW_ABOVE = 2u;
constant float LIGHT_ERROR = 0.00000047683716;
constant uint RAY_SHADOW = 2u;
constant uint FLAG_MEDIUM = 4u;
constant uint FLAG_SECONDARY_RAYS = 2u;
constant uint MAX_DEPTH = 4u;
constant uint STACK_SIZE = 4u;
constant uint MAX_SPAWN = 1u;
constant uint RAY_SECONDARY = 1u;

metal::uint2 naga_div(metal::uint2 lhs, metal::uint2 rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

metal::uint2 div_vec2u(
    metal::uint2 a,
    metal::uint2 b
) {
    metal::bool2 by_zero = b == metal::uint2(0u);
    metal::uint2 divisor = metal::select(b, metal::uint2(1u), by_zero);
    return naga_div(a, divisor);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint rem_u32_(
    uint a_1,
    uint b_1
) {
    bool by_zero_1 = b_1 == 0u;
    uint divisor_1 = by_zero_1 ? 1u : b_1;
    return by_zero_1 ? 0u : naga_mod(a_1, divisor_1);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint div_u32_(
    uint a_2,
    uint b_2
) {
    bool by_zero_2 = b_2 == 0u;
    uint divisor_2 = by_zero_2 ? 1u : b_2;
    return naga_div(a_2, divisor_2);
}

metal::uint2 naga_mod(metal::uint2 lhs, metal::uint2 rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

metal::uint2 rem_vec2u(
    metal::uint2 a_3,
    metal::uint2 b_3
) {
    metal::uint2 _e3 = metal::uint2(0u);
    metal::bool2 by_zero_3 = b_3 == _e3;
    metal::uint2 divisor_3 = metal::select(b_3, metal::uint2(1u), by_zero_3);
    return metal::select(naga_mod(a_3, divisor_3), _e3, by_zero_3);
}

metal::uint2 scattered_local(
    metal::uint2 id,
    constant TileParams& tile
) {
    TileParams tile_1 = tile;
    metal::uint2 size = metal::uint2(WORKGROUP_WIDTH, WORKGROUP_HEIGHT);
    metal::uint2 _e11 = div_vec2u((tile_1.extent + size) - metal::uint2(1u), size);
    uint count = _e11.x * _e11.y;
    if (count == 0u) {
        return metal::uint2(NO_HIT);
    }
    metal::uint2 _e19 = div_vec2u(id, size);
    uint order = (_e19.y * _e11.x) + _e19.x;
    uint _e26 = rem_u32_(SCATTER, count);
    uint _e28 = rem_u32_(order * _e26, count);
    uint _e30 = rem_u32_(_e28, _e11.x);
    uint _e32 = div_u32_(_e28, _e11.x);
    metal::uint2 _e35 = rem_vec2u(id, size);
    return (metal::uint2(_e30, _e32) * size) + _e35;
}

uint pcg_hash(
    uint x
) {
    uint state_1 = (x * 747796405u) + 2891336453u;
    uint word = ((state_1 >> (((state_1 >> 28u) + 4u) & 31u)) ^ state_1) * 277803737u;
    return (word >> 22u) ^ word;
}

void rng_resume(
    metal::uint2 pixel,
    uint sample,
    uint seed,
    uint state,
    thread type_4& scratch,
    thread uint& rng_state
) {
    scratch.inner[metal::min(SCRATCH_RNG_INDEX, 14u)] = sample;
    uint _e12 = pcg_hash(seed);
    uint _e14 = pcg_hash(pixel.y ^ _e12);
    uint _e16 = pcg_hash(pixel.x ^ _e14);
    scratch.inner[metal::min(SCRATCH_RNG_SEED, 14u)] = _e16;
    rng_state = state;
    return;
}

void rng_seed(
    metal::uint2 pixel_1,
    uint sample_1,
    uint seed_1,
    thread type_4& scratch,
    thread uint& rng_state
) {
    rng_resume(pixel_1, sample_1, seed_1, 0u, scratch, rng_state);
    return;
}

SupersampledPinhole load_SupersampledPinhole(
    uint offset,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset + 0u];
    uint _e11 = params[offset + 1u];
    uint _e17 = params[offset + 2u];
    uint _e24 = params[offset + 4u];
    uint _e30 = params[offset + 5u];
    uint _e36 = params[offset + 6u];
    uint _e43 = params[offset + 8u];
    uint _e49 = params[offset + 9u];
    uint _e55 = params[offset + 10u];
    uint _e62 = params[offset + 11u];
    return SupersampledPinhole {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), metal::float3(as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)), as_type<float>(_e62)};
}

metal::uint2 image_size_query(
    constant TileParams& tile
) {
    TileParams _e1 = tile;
    return _e1.image_size;
}

uint laine_karras(
    uint x_1,
    uint seed_2
) {
    uint v = {};
    v = x_1 + seed_2;
    uint _e4 = v;
    uint _e5 = v;
    v = _e4 ^ (_e5 * 1817228412u);
    uint _e9 = v;
    uint _e10 = v;
    v = _e9 ^ (_e10 * 3090095698u);
    uint _e14 = v;
    uint _e15 = v;
    v = _e14 ^ (_e15 * 3350193720u);
    uint _e19 = v;
    uint _e20 = v;
    v = _e19 ^ (_e20 * 2367878886u);
    uint _e24 = v;
    return _e24;
}

uint sobol_second_reversed(
    uint i
) {
    uint f = {};
    f = i;
    uint _e2 = f;
    uint _e3 = f;
    f = _e2 ^ ((_e3 >> 1u) & 1431655765u);
    uint _e9 = f;
    uint _e10 = f;
    f = _e9 ^ ((_e10 >> 2u) & 858993459u);
    uint _e16 = f;
    uint _e17 = f;
    f = _e16 ^ ((_e17 >> 4u) & 252645135u);
    uint _e23 = f;
    uint _e24 = f;
    f = _e23 ^ ((_e24 >> 8u) & 16711935u);
    uint _e30 = f;
    uint _e31 = f;
    f = _e30 ^ (_e31 >> (HALF_WORD_BITS & 31u));
    uint _e37 = f;
    return _e37;
}

float rand_next(
    thread type_4& scratch,
    thread uint& rng_state
) {
    uint x_2 = {};
    uint d = rng_state;
    rng_state = d + 1u;
    uint _e10 = scratch.inner[metal::min(SCRATCH_RNG_SEED, 14u)];
    uint _e16 = pcg_hash(_e10 ^ ((d >> 1u) * 2654435769u));
    uint _e22 = scratch.inner[metal::min(SCRATCH_RNG_INDEX, 14u)];
    uint _e24 = laine_karras(metal::reverse_bits(_e22), _e16);
    uint i_7 = metal::reverse_bits(_e24);
    x_2 = i_7;
    if ((d & 1u) != 0u) {
        uint _e31 = sobol_second_reversed(i_7);
        x_2 = _e31;
    }
    uint scramble = _e16 ^ (((2654435769u * (1u + (d & 1u))) + (_e16 << 6u)) + (_e16 >> 2u));
    uint _e45 = x_2;
    uint _e46 = laine_karras(_e45, scramble);
    return static_cast<float>(metal::reverse_bits(_e46) >> 8u) * (1.0 / 16777216.0);
}

metal::float2 rand2_next(
    thread type_4& scratch,
    thread uint& rng_state
) {
    float _e0 = rand_next(scratch, rng_state);
    float _e1 = rand_next(scratch, rng_state);
    return metal::float2(_e0, _e1);
}

metal::float3 normalize_vec3f(
    metal::float3 v_1
) {
    return (metal::dot(v_1, v_1) >= 0.000000000000000000000000000000000000011754944) ? metal::normalize(v_1) : metal::float3(0.0);
}

Ray supersampled_ray(
    SupersampledPinhole cam,
    metal::uint2 pixel_2,
    uint sample_2,
    constant TileParams& tile,
    thread type_4& scratch,
    thread uint& rng_state,
    thread uint& F32_INF
) {
    metal::uint2 _e3 = image_size_query(tile);
    metal::float2 size_1 = static_cast<metal::float2>(_e3);
    uint _e8 = rem_u32_(sample_2, SUPERSAMPLING_GRID * SUPERSAMPLING_GRID);
    uint _e10 = rem_u32_(_e8, SUPERSAMPLING_GRID);
    uint _e13 = div_u32_(_e8, SUPERSAMPLING_GRID);
    metal::float2 stratum = metal::float2(static_cast<float>(_e10), static_cast<float>(_e13));
    metal::float2 _e16 = rand2_next(scratch, rng_state);
    metal::float2 offset_13 = (stratum + _e16) / metal::float2(static_cast<float>(SUPERSAMPLING_GRID));
    metal::float2 ndc = (((static_cast<metal::float2>(pixel_2) + offset_13) / size_1) * metal::float2(2.0)) - metal::float2(1.0);
    metal::float3 _e34 = normalize_vec3f(cam.look_at - cam.position);
    metal::float3 _e37 = normalize_vec3f(metal::cross(_e34, cam.up));
    metal::float3 up = metal::cross(_e37, _e34);
    float h = metal::tan(((cam.fov) * 0.017453292519943295474) * 0.5);
    float aspect = size_1.x / size_1.y;
    metal::float3 _e58 = normalize_vec3f((_e34 + (_e37 * metal::float3((ndc.x * h) * aspect))) - (up * metal::float3(ndc.y * h)));
    uint _e62 = F32_INF;
    return Ray {cam.position, 0.0, _e58, as_type<float>(_e62), 0u, 0u, 0u};
}

Ray dispatch_ray_generation(
    uint type_id,
    uint offset_1,
    metal::uint2 pixel_3,
    uint sample_3,
    constant TileParams& tile,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    SupersampledPinhole _e3 = load_SupersampledPinhole(offset_1, params, _buffer_sizes);
    Ray _e4 = supersampled_ray(_e3, pixel_3, sample_3, tile, scratch, rng_state, F32_INF);
    return _e4;
}

Candidate no_candidate(
    float tmax
) {
    return Candidate {tmax, NO_HIT, 0u, {}, metal::float2(0.0), {}, metal::float3(0.0)};
}

Ray to_object(
    GpuInstance inst,
    Ray ray
) {
    Ray r = {};
    r = ray;
    metal::float4 o = metal::float4(ray.origin, 1.0);
    metal::float4 d_1 = metal::float4(ray.dir, 0.0);
    r.origin = metal::float3(metal::dot(inst.world_to_object_0_, o), metal::dot(inst.world_to_object_1_, o), metal::dot(inst.world_to_object_2_, o));
    r.dir = metal::float3(metal::dot(inst.world_to_object_0_, d_1), metal::dot(inst.world_to_object_1_, d_1), metal::dot(inst.world_to_object_2_, d_1));
    Ray _e25 = r;
    return _e25;
}

TriangleRay prepare_triangle_ray(
    Ray ray_1
) {
    metal::float3 d_2 = metal::select(ray_1.dir, metal::float3(0.0), metal::abs(ray_1.dir) < metal::float3(0.000000000000000000000000000000000000011754944));
    metal::float3 ad = metal::abs(d_2);
    bool y_gt = ad.y > ad.x;
    uint kz = (ad.z > (y_gt ? ad.y : ad.x)) ? 2u : (y_gt ? 1u : 0u);
    uint kx0_ = (kz == 2u) ? 0u : (kz + 1u);
    uint ky0_ = (kz >= 1u) ? (kz - 1u) : (kz + 2u);
    float dz = d_2[metal::min(kz, 2u)];
    bool flip = dz < 0.0;
    uint kx = flip ? ky0_ : kx0_;
    uint ky = flip ? kx0_ : ky0_;
    metal::uint3 inf_bits = metal::uint3(2139095040u);
    bool finite = metal::all((as_type<metal::uint3>(ray_1.origin) & metal::uint3(2147483647u)) < inf_bits) && metal::all((as_type<metal::uint3>(d_2) & metal::uint3(2147483647u)) < inf_bits);
    return TriangleRay {ray_1.origin, kx, ky, kz, {}, metal::float3(d_2[metal::min(kx, 2u)] / dz, d_2[metal::min(ky, 2u)] / dz, 1.0 / dz), finite && !((dz == 0.0))};
}

metal::float3 node_point(
    metal::float3 origin,
    metal::float3 scale,
    metal::uint3 q
) {
    return origin + (static_cast<metal::float3>(q) * scale);
}

metal::float3 node_frame_hi(
    GpuNode header
) {
    metal::float3 _e5 = node_point(header.min, header.max, metal::uint3(65535u));
    return _e5;
}

BoxRay box_ray(
    GpuNode header_1,
    Ray ray_2
) {
    metal::float3 origin_2 = header_1.min;
    metal::float3 _e3 = node_frame_hi(header_1);
    metal::float3 extent = _e3 - origin_2;
    float m_3 = metal::max(metal::max(metal::abs(ray_2.dir[0]), metal::abs(ray_2.dir[1])), metal::abs(ray_2.dir[2]));
    uint e = metal::min(metal::max((as_type<uint>(m_3) >> 23u) & 255u, 1u), 253u);
    metal::float3 d_3 = ray_2.dir * metal::float3(as_type<float>((254u - e) << 23u));
    float unit = as_type<float>(e << 23u);
    metal::float3 floor = metal::float3(0.0000000000009094947);
    metal::float3 s_4 = metal::select(metal::float3(1.0), metal::float3(-1.0), d_3 < metal::float3(0.0));
    metal::float3 inv = metal::float3(1.0) / metal::select(d_3, s_4 * floor, metal::abs(d_3) < floor);
    metal::float3 rel = origin_2 - ray_2.origin;
    metal::float3 start = rel * inv;
    metal::float3 pad = ((metal::float3(0.0000009536743) * metal::abs(inv)) * ((extent + metal::abs(rel)) + metal::abs(origin_2))) * s_4;
    return BoxRay {header_1.max * inv, start - pad, start + pad, ray_2.tmin * unit, unit};
}

metal::float3 hit_triangle(
    TriangleRay r_1,
    uint slot,
    float tmin,
    float tmax_1,
    bool occlusion,
    thread uint& F32_INF,
    device type_12 const& triangles,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 _e9 = triangles[slot * 3u];
    metal::float3 a_5 = _e9.xyz - r_1.origin;
    metal::float4 _e19 = triangles[(slot * 3u) + 1u];
    metal::float3 b_8 = _e19.xyz - r_1.origin;
    metal::float4 _e29 = triangles[(slot * 3u) + 2u];
    metal::float3 c_6 = _e29.xyz - r_1.origin;
    float ax = a_5[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * a_5[metal::min(r_1.kz, 2u)]);
    float ay = a_5[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * a_5[metal::min(r_1.kz, 2u)]);
    float bx = b_8[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * b_8[metal::min(r_1.kz, 2u)]);
    float by = b_8[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * b_8[metal::min(r_1.kz, 2u)]);
    float cx = c_6[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * c_6[metal::min(r_1.kz, 2u)]);
    float cy = c_6[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * c_6[metal::min(r_1.kz, 2u)]);
    float u = (cx * by) - (cy * bx);
    float v_2 = (ax * cy) - (ay * cx);
    float w = (bx * ay) - (by * ax);
    bool outside = (((u < 0.0) || (v_2 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_2 > 0.0)) || (w > 0.0));
    float det = (u + v_2) + w;
    float scaled = ((u * (r_1.shear[2] * a_5[metal::min(r_1.kz, 2u)])) + (v_2 * (r_1.shear[2] * b_8[metal::min(r_1.kz, 2u)]))) + (w * (r_1.shear[2] * c_6[metal::min(r_1.kz, 2u)]));
    if (occlusion) {
        float st = (det < 0.0) ? -(scaled) : scaled;
        float ad_1 = metal::abs(det);
        bool hit_7 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1));
        uint _e178 = F32_INF;
        return hit_7 ? metal::float3(tmin, 0.0, 0.0) : metal::float3(as_type<float>(_e178), 0.0, 0.0);
    }
    float rcp = 1.0 / det;
    float t_7 = scaled * rcp;
    bool hit_8 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (t_7 >= tmin)) && (t_7 <= tmax_1);
    uint _e202 = F32_INF;
    return hit_8 ? metal::float3(t_7, v_2 * rcp, w * rcp) : metal::float3(as_type<float>(_e202), 0.0, 0.0);
}

bool accept(
    GpuInstance inst_1,
    Ray ray_3,
    Candidate c
) {
    return true;
}

metal::uint3 node_box_lo(
    metal::uint3 p
) {
    return metal::uint3(p.x & 65535u, p.x >> 16u, p.y & 65535u);
}

metal::uint3 node_box_hi(
    metal::uint3 p_1
) {
    return metal::uint3(p_1.y >> 16u, p_1.z & 65535u, p_1.z >> 16u);
}

float slab_in_frame(
    metal::float3 lo,
    metal::float3 hi,
    BoxRay b_4,
    float tmax_2,
    thread uint& F32_INF
) {
    metal::float3 t0_ = metal::fma(lo, b_4.step, b_4.start_lo);
    metal::float3 t1_ = metal::fma(hi, b_4.step, b_4.start_hi);
    metal::bool3 flip_1 = as_type<metal::int3>(b_4.step) < metal::int3(0);
    metal::float3 near_2 = metal::select(t0_, t1_, flip_1);
    metal::float3 far_2 = metal::select(t1_, t0_, flip_1);
    metal::float2 e_1 = metal::select(near_2.xy, near_2.yz, near_2.xy < near_2.yz);
    float enter = (e_1.x < e_1.y) ? e_1.y : e_1.x;
    metal::float2 x_7 = metal::select(far_2.xy, far_2.yz, far_2.yz < far_2.xy);
    float exit = (x_7.y < x_7.x) ? x_7.y : x_7.x;
    float enter_t = (enter < b_4.tmin) ? b_4.tmin : enter;
    float exit_t = (tmax_2 < exit) ? tmax_2 : exit;
    if (enter_t <= exit_t) {
        return enter_t;
    }
    uint _e49 = F32_INF;
    return as_type<float>(_e49);
}

metal::float2 children_entry(
    GpuNode n,
    BoxRay b_5,
    float tmax_3,
    thread uint& F32_INF
) {
    metal::uint3 lq = as_type<metal::uint3>(n.min);
    metal::uint3 rq = as_type<metal::uint3>(n.max);
    float t_8 = tmax_3 * b_5.unit;
    metal::uint3 _e9 = node_box_lo(lq);
    metal::uint3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(static_cast<metal::float3>(_e9), static_cast<metal::float3>(_e11), b_5, t_8, F32_INF);
    metal::uint3 _e14 = node_box_lo(rq);
    metal::uint3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(static_cast<metal::float3>(_e14), static_cast<metal::float3>(_e16), b_5, t_8, F32_INF);
    return metal::float2(_e13, _e18);
}

metal::uint2 pop(
    uint base,
    uint sp,
    thread type_13& traversal_stack
) {
    if (sp == 0u) {
        return metal::uint2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack.inner[metal::min((base + sp) - 1u, 66u)];
    return metal::uint2(_e14, sp - 1u);
}

Candidate intersect_mesh(
    GpuInstance inst_2,
    uint slot_1,
    Ray world_ray,
    Ray ray_4,
    Candidate best_in,
    bool shadow,
    thread uint& F32_INF,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best = {};
    uint sp_1 = {};
    uint child = {};
    uint k = {};
    uint near = {};
    uint far = {};
    best = best_in;
    TriangleRay _e7 = prepare_triangle_ray(ray_4);
    uint base_1 = inst_2.blas_root;
    GpuNode header_2 = nodes[base_1];
    BoxRay _e12 = box_ray(header_2, ray_4);
    sp_1 = 0u;
    child = header_2.a;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e17 = child;
        if ((_e17 & NODE_LEAF_BIT) != 0u) {
            uint _e22 = child;
            uint count_1 = (_e22 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK;
            uint _e29 = child;
            uint first = _e29 & NODE_FIRST_MASK;
            k = 0u;
            uint2 loop_bound_1 = uint2(4294967295u);
            bool loop_init = true;
            while(true) {
                if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e75 = k;
                    k = _e75 + 1u;
                }
                loop_init = false;
                uint _e34 = k;
                if (_e34 >= count_1) {
                    break;
                }
                uint _e38 = k;
                uint prim = (inst_2.triangle_offset + first) + _e38;
                float _e42 = best.t;
                metal::float3 _e46 = hit_triangle(_e7, prim, ray_4.tmin, _e42, shadow && !(HAS_ANY_HIT), F32_INF, triangles, _buffer_sizes);
                uint _e49 = F32_INF;
                if (_e46.x < as_type<float>(_e49)) {
                    metal::float4 _e58 = triangles[(prim * 3u) + 1u];
                    uint tag = as_type<uint>(_e58.w);
                    uint owner = (tag != 0u) ? ((inst_2.object + tag) - 1u) : slot_1;
                    Candidate c_7 = Candidate {_e46.x, owner, prim, {}, _e46.yz, {}, metal::float3(0.0)};
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
            GpuNode n_8 = nodes[base_1 + _e78];
            float _e84 = best.t;
            metal::float2 _e85 = children_entry(n_8, _e12, _e84, F32_INF);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if ((tl < as_type<float>(_e89)) && (tr < as_type<float>(_e93))) {
                near = n_8.a;
                far = n_8.b;
                if ((tr < tl) != shadow) {
                    near = n_8.b;
                    far = n_8.a;
                }
                uint _e105 = sp_1;
                if (_e105 < BLAS_STACK) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack.inner[metal::min(TLAS_STACK + _e109, 66u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = _e116 + 1u;
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if (tl < as_type<float>(_e121)) {
                child = n_8.a;
                continue;
            }
            uint _e126 = F32_INF;
            if (tr < as_type<float>(_e126)) {
                child = n_8.b;
                continue;
            }
        }
        uint _e131 = sp_1;
        metal::uint2 _e132 = pop(TLAS_STACK, _e131, traversal_stack);
        if (_e132.x == NO_HIT) {
            break;
        }
        child = _e132.x;
        sp_1 = _e132.y;
    }
    Candidate _e138 = best;
    return _e138;
}

BvhMesh load_BvhMesh(
    uint offset_2,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_2 + 0u];
    return BvhMesh {_e5};
}

BvhNode mesh_node_query(
    uint m,
    uint i_1,
    device type_5 const& params,
    device type_10 const& nodes,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 lo_1 = {};
    metal::float3 hi_1 = {};
    uint reference = {};
    metal::uint3 q_1 = {};
    uint base_2 = params[m];
    GpuNode header_3 = nodes[base_2];
    lo_1 = header_3.min;
    metal::float3 _e10 = node_frame_hi(header_3);
    hi_1 = _e10;
    reference = header_3.a;
    if (i_1 >= 2u) {
        GpuNode n_9 = nodes[base_2 + (i_1 >> 1u)];
        q_1 = as_type<metal::uint3>(n_9.min);
        reference = n_9.a;
        if ((i_1 & 1u) != 0u) {
            q_1 = as_type<metal::uint3>(n_9.max);
            reference = n_9.b;
        }
        metal::uint3 _e35 = q_1;
        metal::uint3 _e36 = node_box_lo(_e35);
        metal::float3 _e37 = node_point(header_3.min, header_3.max, _e36);
        lo_1 = _e37;
        metal::uint3 _e40 = q_1;
        metal::uint3 _e41 = node_box_hi(_e40);
        metal::float3 _e42 = node_point(header_3.min, header_3.max, _e41);
        hi_1 = _e42;
    }
    uint _e43 = reference;
    if ((_e43 & NODE_LEAF_BIT) == 0u) {
        metal::float3 _e48 = lo_1;
        metal::float3 _e49 = hi_1;
        uint _e51 = reference;
        return BvhNode {_e48, _e49, 2u * _e51, 0u};
    }
    uint _e55 = reference;
    uint count_2 = (_e55 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK;
    if (count_2 == 0u) {
        return BvhNode {as_type<metal::float3>(metal::uint3(2139095039u)), as_type<metal::float3>(metal::uint3(4286578687u)), 0u, 0u};
    }
    metal::float3 _e73 = lo_1;
    metal::float3 _e74 = hi_1;
    uint _e75 = reference;
    return BvhNode {_e73, _e74, _e75 & NODE_FIRST_MASK, count_2};
}

metal::float2 intersect_aabb(
    Ray ray_5,
    metal::float3 min,
    metal::float3 max,
    thread uint& F32_INF,
    thread uint& F32_NEG_INF
) {
    metal::bool3 parallel = metal::abs(ray_5.dir) < metal::float3(0.000000000000000000000000000000000000011754944);
    metal::float3 _e12 = metal::float3(1.0);
    metal::float3 inv_dir = _e12 / metal::select(ray_5.dir, _e12, parallel);
    metal::float3 _e17 = (min - ray_5.origin) * inv_dir;
    metal::float3 _e18 = (max - ray_5.origin) * inv_dir;
    metal::bool3 _e23 = (min <= ray_5.origin) & (ray_5.origin <= max);
    uint _e25 = F32_INF;
    metal::float3 _e27 = metal::float3(as_type<float>(_e25));
    uint _e29 = F32_NEG_INF;
    metal::float3 _e31 = metal::float3(as_type<float>(_e29));
    metal::float3 near_3 = metal::select(metal::min(_e17, _e18), metal::select(_e27, _e31, _e23), parallel);
    metal::float3 far_3 = metal::select(metal::max(_e17, _e18), metal::select(_e31, _e27, _e23), parallel);
    return metal::float2(metal::max(metal::max(metal::max(near_3.x, near_3.y), near_3.z), ray_5.tmin), metal::min(metal::min(metal::min(far_3.x, far_3.y), far_3.z), ray_5.tmax));
}

float bvh_mesh_enter(
    Ray ray_6,
    BvhNode n_1,
    float tmax_4,
    thread uint& F32_INF,
    thread uint& F32_NEG_INF
) {
    metal::float2 _e5 = intersect_aabb(ray_6, n_1.min, n_1.max, F32_INF, F32_NEG_INF);
    uint _e7 = F32_INF;
    return ((_e5.x <= _e5.y) && (_e5.x <= tmax_4)) ? _e5.x : as_type<float>(_e7);
}

Triangle mesh_triangle_query(
    uint m_1,
    uint i_2,
    device type_5 const& params,
    device type_12 const& triangles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = params[m_1 + 1u];
    uint slot_4 = _e6 + i_2;
    metal::float4 _e12 = triangles[slot_4 * 3u];
    metal::float4 _e20 = triangles[(slot_4 * 3u) + 1u];
    metal::float4 _e28 = triangles[(slot_4 * 3u) + 2u];
    return Triangle {_e12.xyz, _e20.xyz, _e28.xyz};
}

Intersection intersect_triangle(
    Ray ray_7,
    Triangle tri,
    thread uint& F32_INF
) {
    metal::uint3 _e10 = metal::uint3(2139095040u);
    metal::float3 dir_5 = metal::select(ray_7.dir, metal::float3(0.0), metal::abs(ray_7.dir) < metal::float3(0.000000000000000000000000000000000000011754944));
    metal::float3 _e31 = metal::abs(dir_5);
    bool _e38 = _e31.y > _e31.x;
    uint kz_1 = (_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u);
    uint _e45 = (kz_1 == 2u) ? 0u : (kz_1 + 1u);
    uint _e49 = (kz_1 >= 1u) ? (kz_1 - 1u) : (kz_1 + 2u);
    float dz_1 = dir_5[kz_1];
    bool _e52 = dz_1 < 0.0;
    uint kx_1 = _e52 ? _e49 : _e45;
    uint ky_1 = _e52 ? _e45 : _e49;
    float sx = dir_5[kx_1] / dz_1;
    float sy = dir_5[ky_1] / dz_1;
    float sz = 1.0 / dz_1;
    metal::float3 _e62 = tri.v0_ - ray_7.origin;
    float _e68 = _e62[kx_1] - (sx * _e62[kz_1]);
    float _e69 = _e62[ky_1] - (sy * _e62[kz_1]);
    metal::float3 _e71 = tri.v1_ - ray_7.origin;
    float _e77 = _e71[kx_1] - (sx * _e71[kz_1]);
    float _e78 = _e71[ky_1] - (sy * _e71[kz_1]);
    metal::float3 _e80 = tri.v2_ - ray_7.origin;
    float _e86 = _e80[kx_1] - (sx * _e80[kz_1]);
    float _e87 = _e80[ky_1] - (sy * _e80[kz_1]);
    float u_1 = (_e86 * _e78) - (_e87 * _e77);
    float v_3 = (_e68 * _e87) - (_e69 * _e86);
    float w_1 = (_e77 * _e69) - (_e78 * _e68);
    float det_1 = (u_1 + v_3) + w_1;
    float _e112 = 1.0 / det_1;
    float t_9 = (((u_1 * (sz * _e62[kz_1])) + (v_3 * (sz * _e71[kz_1]))) + (w_1 * (sz * _e80[kz_1]))) * _e112;
    bool hit_9 = ((((metal::all((as_type<metal::uint3>(ray_7.origin) & metal::uint3(2147483647u)) < _e10) && metal::all((as_type<metal::uint3>(ray_7.dir) & metal::uint3(2147483647u)) < _e10)) && (dz_1 != 0.0)) && !(((((u_1 < 0.0) || (v_3 < 0.0)) || (w_1 < 0.0)) && (((u_1 > 0.0) || (v_3 > 0.0)) || (w_1 > 0.0))))) && !((det_1 == 0.0))) && ((t_9 >= ray_7.tmin) && (t_9 <= ray_7.tmax));
    metal::float3 _e132 = normalize_vec3f(metal::cross(tri.v1_ - tri.v0_, tri.v2_ - tri.v0_));
    uint _e137 = F32_INF;
    return Intersection {hit_9 ? t_9 : as_type<float>(_e137), {}, hit_9 ? _e132 : metal::float3(0.0, 0.0, 1.0), hit_9 ? metal::float2(v_3 * _e112, w_1 * _e112) : metal::float2(0.0)};
}

Intersection bvh_mesh_intersect(
    BvhMesh g,
    Ray ray_8,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread uint& F32_NEG_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    Intersection best_1 = {};
    Ray r_2 = {};
    type_14 stack = {};
    type_15 stack_t = {};
    uint sp_2 = {};
    BvhNode node = {};
    uint k_1 = {};
    bool found = {};
    uint _e3 = F32_INF;
    best_1 = Intersection {as_type<float>(_e3), {}, metal::float3(0.0, 0.0, 1.0), metal::float2 {}};
    r_2 = ray_8;
    stack = type_14 {};
    stack_t = type_15 {};
    sp_2 = 0u;
    BvhNode _e21 = mesh_node_query(g.mesh, 0u, params, nodes, _buffer_sizes);
    node = _e21;
    Ray _e23 = r_2;
    BvhNode _e24 = node;
    float _e26 = r_2.tmax;
    float _e27 = bvh_mesh_enter(_e23, _e24, _e26, F32_INF, F32_NEG_INF);
    uint _e29 = F32_INF;
    if (_e27 == as_type<float>(_e29)) {
        Intersection _e32 = best_1;
        return _e32;
    }
    uint2 loop_bound_2 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        uint _e34 = node.count;
        if (_e34 > 0u) {
            uint end = node.count;
            k_1 = 0u;
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_1) {
                    uint _e57 = k_1;
                    k_1 = _e57 + 1u;
                }
                loop_init_1 = false;
                uint _e41 = k_1;
                if (_e41 >= end) {
                    break;
                }
                Ray _e43 = r_2;
                uint _e46 = node.first;
                uint _e47 = k_1;
                Triangle _e49 = mesh_triangle_query(g.mesh, _e46 + _e47, params, triangles, _buffer_sizes);
                Intersection _e50 = intersect_triangle(_e43, _e49, F32_INF);
                float _e53 = best_1.t;
                if (_e50.t < _e53) {
                    best_1 = _e50;
                    r_2.tmax = _e50.t;
                }
            }
        } else {
            uint first_1 = node.first;
            BvhNode _e63 = mesh_node_query(g.mesh, first_1, params, nodes, _buffer_sizes);
            BvhNode _e67 = mesh_node_query(g.mesh, first_1 + 1u, params, nodes, _buffer_sizes);
            Ray _e68 = r_2;
            float _e70 = r_2.tmax;
            float _e71 = bvh_mesh_enter(_e68, _e63, _e70, F32_INF, F32_NEG_INF);
            Ray _e72 = r_2;
            float _e74 = r_2.tmax;
            float _e75 = bvh_mesh_enter(_e72, _e67, _e74, F32_INF, F32_NEG_INF);
            uint _e78 = F32_INF;
            if (metal::min(_e71, _e75) < as_type<float>(_e78)) {
                bool left_first = _e71 <= _e75;
                uint _e84 = F32_INF;
                uint _e87 = sp_2;
                if ((metal::max(_e71, _e75) < as_type<float>(_e84)) && (_e87 < BVH_MESH_STACK)) {
                    uint _e91 = sp_2;
                    stack.inner[metal::min(_e91, 63u)] = left_first ? (first_1 + 1u) : first_1;
                    uint _e98 = sp_2;
                    stack_t.inner[metal::min(_e98, 63u)] = metal::max(_e71, _e75);
                    uint _e103 = sp_2;
                    sp_2 = _e103 + 1u;
                }
                node = _e67;
                if (left_first) {
                    node = _e63;
                }
                continue;
            }
        }
        found = false;
        uint2 loop_bound_4 = uint2(4294967295u);
        while(true) {
            if (metal::all(loop_bound_4 == uint2(0u))) { break; }
            loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
            uint _e108 = sp_2;
            bool _e111 = found;
            if (!(((_e108 > 0u) && !(_e111)))) {
                break;
            }
            uint _e115 = sp_2;
            sp_2 = _e115 - 1u;
            uint _e118 = sp_2;
            float _e122 = stack_t.inner[metal::min(_e118, 63u)];
            float _e124 = r_2.tmax;
            found = _e122 <= _e124;
        }
        bool _e126 = found;
        if (!(_e126)) {
            break;
        }
        uint _e129 = sp_2;
        uint _e133 = stack.inner[metal::min(_e129, 63u)];
        BvhNode _e134 = mesh_node_query(g.mesh, _e133, params, nodes, _buffer_sizes);
        node = _e134;
    }
    Intersection _e135 = best_1;
    return _e135;
}

Sphere load_Sphere(
    uint offset_3,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_3 + 0u];
    uint _e11 = params[offset_3 + 1u];
    uint _e17 = params[offset_3 + 2u];
    uint _e24 = params[offset_3 + 3u];
    return Sphere {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24)};
}

Intersection sphere_intersect(
    Sphere s,
    Ray ray_9,
    thread uint& F32_INF
) {
    float t = {};
    metal::float3 f_2 = ray_9.origin - s.center;
    float a_6 = metal::dot(ray_9.dir, ray_9.dir);
    float b_9 = -(metal::dot(f_2, ray_9.dir));
    metal::float3 l_1 = f_2 + (ray_9.dir * metal::float3(b_9 / a_6));
    float r2_ = s.radius * s.radius;
    float disc = a_6 * (r2_ - metal::dot(l_1, l_1));
    if (!((disc >= 0.0)) || !((a_6 > 0.0))) {
        uint _e30 = F32_INF;
        return Intersection {as_type<float>(_e30), {}, metal::float3(0.0, 0.0, 1.0), metal::float2 {}};
    }
    float q_2 = b_9 + (((b_9 >= 0.0) ? 1.0 : -1.0) * metal::sqrt(disc));
    float t0_1 = (metal::dot(f_2, f_2) - r2_) / q_2;
    float t1_1 = q_2 / a_6;
    t = metal::min(t0_1, t1_1);
    float _e52 = t;
    if (!((_e52 >= ray_9.tmin))) {
        t = metal::max(t0_1, t1_1);
    }
    float _e57 = t;
    float _e60 = t;
    if (!(((_e57 >= ray_9.tmin) && (_e60 <= ray_9.tmax)))) {
        uint _e66 = F32_INF;
        return Intersection {as_type<float>(_e66), {}, metal::float3(0.0, 0.0, 1.0), metal::float2 {}};
    }
    float _e76 = t;
    metal::float3 _e82 = normalize_vec3f((ray_9.origin + (ray_9.dir * metal::float3(_e76))) - s.center);
    float u_2 = ((_e82.x == 0.0) && (_e82.z == 0.0)) ? 0.5 : (0.5 + (metal::atan2(_e82.z, -(_e82.x)) / TAU));
    metal::float2 uv_1 = metal::float2(u_2, metal::acos(metal::min(metal::max(_e82.y, -1.0), 1.0)) * INV_PI);
    float _e109 = t;
    return Intersection {_e109, {}, _e82, uv_1};
}

Intersection dispatch_intersection(
    uint type_id_1,
    uint offset_4,
    Ray ray_10,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread uint& F32_NEG_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(type_id_1) {
        case 0u: {
            BvhMesh _e3 = load_BvhMesh(offset_4, params, _buffer_sizes);
            Intersection _e4 = bvh_mesh_intersect(_e3, ray_10, params, F32_INF, nodes, triangles, F32_NEG_INF, _buffer_sizes);
            return _e4;
        }
        case 1u: {
            Sphere _e5 = load_Sphere(offset_4, params, _buffer_sizes);
            Intersection _e6 = sphere_intersect(_e5, ray_10, F32_INF);
            return _e6;
        }
        default: {
            break;
        }
    }
    return Intersection {};
}

Candidate intersect_object(
    uint slot_2,
    Ray ray_11,
    Candidate best_2,
    bool shadow_1,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray r_3 = {};
    GpuInstance inst_6 = instances[slot_2];
    Ray _e7 = to_object(inst_6, ray_11);
    r_3 = _e7;
    r_3.tmax = best_2.t;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        Ray _e14 = r_3;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_11, _e14, best_2, shadow_1, F32_INF, nodes, triangles, traversal_stack, _buffer_sizes);
        return _e15;
    }
    Ray _e18 = r_3;
    Intersection _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18, params, F32_INF, nodes, triangles, F32_NEG_INF, _buffer_sizes);
    float _e22 = r_3.tmin;
    float _e26 = r_3.tmax;
    uint _e31 = F32_INF;
    if (((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < as_type<float>(_e31))) {
        Candidate c_8 = Candidate {_e19.t, slot_2, 0u, {}, _e19.uv, {}, _e19.normal};
        bool _e40 = accept(inst_6, ray_11, c_8);
        if (_e40) {
            return c_8;
        }
    }
    return best_2;
}

float point_error(
    metal::float3 origin_1,
    metal::float3 along
) {
    metal::float3 a_7 = metal::abs(origin_1) + metal::abs(along);
    return POINT_ERROR * metal::max(metal::max(a_7.x, a_7.y), a_7.z);
}

Triangle load_triangle(
    uint slot_3,
    device type_12 const& triangles,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 v0_1 = triangles[slot_3 * 3u];
    metal::float4 v1_ = triangles[(slot_3 * 3u) + 1u];
    metal::float4 v2_ = triangles[(slot_3 * 3u) + 2u];
    return Triangle {v0_1.xyz, v1_.xyz, v2_.xyz};
}

metal::float3 point_to_world(
    GpuInstance inst_3,
    metal::float3 p_2
) {
    metal::float4 q_3 = metal::float4(p_2, 1.0);
    return metal::float3(metal::dot(inst_3.object_to_world_0_, q_3), metal::dot(inst_3.object_to_world_1_, q_3), metal::dot(inst_3.object_to_world_2_, q_3));
}

float mesh_error(
    GpuInstance inst_4,
    metal::float3 v0_,
    metal::float3 db1_,
    metal::float3 db2_,
    metal::float3 p_3
) {
    metal::float3 obj = (metal::float3(GAMMA_1_) * metal::abs(v0_)) + (metal::float3(GAMMA_6_) * (metal::abs(db1_) + metal::abs(db2_)));
    metal::float4 q_4 = metal::float4(metal::abs(p_3), 1.0);
    metal::float4 r0_ = metal::abs(inst_4.object_to_world_0_);
    metal::float4 r1_ = metal::abs(inst_4.object_to_world_1_);
    metal::float4 r2_1 = metal::abs(inst_4.object_to_world_2_);
    metal::float3 rounding = metal::float3(GAMMA_4_) * metal::float3(metal::dot(r0_, q_4), metal::dot(r1_, q_4), metal::dot(r2_1, q_4));
    metal::float3 carried = metal::float3(1.0 + GAMMA_4_) * metal::float3(metal::dot(r0_.xyz, obj), metal::dot(r1_.xyz, obj), metal::dot(r2_1.xyz, obj));
    metal::float3 e_2 = rounding + carried;
    return metal::max(metal::max(e_2.x, e_2.y), e_2.z);
}

metal::float3 decode_octahedral(
    uint bits
) {
    metal::float3 n_2 = {};
    metal::float2 e_3 = metal::unpack_snorm2x16_to_float(bits);
    n_2 = metal::float3(e_3.x, e_3.y, (1.0 - metal::abs(e_3.x)) - metal::abs(e_3.y));
    float _e14 = n_2.z;
    if (_e14 < 0.0) {
        metal::float3 _e21 = n_2;
        metal::float2 s_5 = metal::select(metal::float2(-1.0), metal::float2(1.0), _e21.xy >= metal::float2(0.0));
        metal::float3 _e29 = n_2;
        metal::float2 xy = (metal::float2(1.0) - metal::abs(_e29.yx)) * s_5;
        float _e37 = n_2.z;
        n_2 = metal::float3(xy.x, xy.y, _e37);
    }
    metal::float3 _e39 = n_2;
    metal::float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

metal::float3 normal_to_world(
    GpuInstance inst_5,
    metal::float3 n_3
) {
    metal::float3 w_2 = ((inst_5.world_to_object_0_.xyz * metal::float3(n_3.x)) + (inst_5.world_to_object_1_.xyz * metal::float3(n_3.y))) + (inst_5.world_to_object_2_.xyz * metal::float3(n_3.z));
    metal::float3 _e19 = normalize_vec3f(w_2);
    return _e19;
}

Hit finish_hit(
    Ray ray_12,
    Candidate c_1,
    device type_9 const& instances,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_17 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Hit hit = {};
    metal::float3 n_geo = {};
    metal::float3 n_shade = {};
    GpuInstance inst_7 = instances[c_1.slot];
    float _e11 = point_error(ray_12.origin, ray_12.dir * metal::float3(c_1.t));
    hit_error = _e11;
    hit = Hit {ray_12.origin + (ray_12.dir * metal::float3(c_1.t)), c_1.t, metal::float3(0.0, 1.0, 0.0), metal::float3(0.0, 1.0, 0.0), c_1.uv, true, {}, inst_7.object, c_1.primitive};
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if (inst_7.geometry_type == MESH_GEOMETRY) {
        Triangle _e42 = load_triangle(c_1.primitive, triangles, _buffer_sizes);
        metal::float2 b_10 = c_1.uv;
        float w_3 = (1.0 - c_1.uv.x) - c_1.uv.y;
        metal::float3 e1_ = _e42.v1_ - _e42.v0_;
        metal::float3 e2_ = _e42.v2_ - _e42.v0_;
        metal::float3 p_7 = _e42.v0_ + ((e1_ * metal::float3(c_1.uv.x)) + (e2_ * metal::float3(c_1.uv.y)));
        metal::float3 _e65 = point_to_world(inst_7, p_7);
        hit.position = _e65;
        float _e73 = mesh_error(inst_7, _e42.v0_, e1_ * metal::float3(c_1.uv.x), e2_ * metal::float3(c_1.uv.y), p_7);
        hit_error = _e73;
        n_geo = metal::cross(e1_, e2_);
        metal::uint4 a0_ = attributes[c_1.primitive * 2u];
        metal::uint4 a1_ = attributes[(c_1.primitive * 2u) + 1u];
        metal::float3 _e91 = decode_octahedral(a0_.x);
        metal::float3 _e95 = decode_octahedral(a0_.y);
        metal::float3 _e101 = decode_octahedral(a0_.z);
        n_shade = ((_e91 * metal::float3(w_3)) + (_e95 * metal::float3(c_1.uv.x))) + (_e101 * metal::float3(c_1.uv.y));
        metal::float3 _e106 = n_shade;
        metal::float3 _e107 = n_shade;
        if (metal::dot(_e106, _e107) < 0.000000000001) {
            metal::float3 _e111 = n_geo;
            n_shade = _e111;
        }
        metal::float2 uv0_ = float2(as_type<half2>(a0_.w));
        metal::float2 uv1_ = float2(as_type<half2>(a1_.x));
        metal::float2 uv2_ = float2(as_type<half2>(a1_.y));
        hit.uv = ((uv0_ * metal::float2(w_3)) + (uv1_ * metal::float2(c_1.uv.x))) + (uv2_ * metal::float2(c_1.uv.y));
        metal::float4 _e135 = triangles[c_1.primitive * 3u];
        hit.primitive = as_type<uint>(_e135.w);
    }
    metal::float3 _e139 = n_geo;
    metal::float3 _e140 = normal_to_world(inst_7, _e139);
    hit.geometric_normal = _e140;
    metal::float3 _e142 = n_shade;
    metal::float3 _e143 = normal_to_world(inst_7, _e142);
    hit.normal = _e143;
    metal::float3 _e147 = hit.geometric_normal;
    hit.front_face = metal::dot(ray_12.dir, _e147) < 0.0;
    Hit _e151 = hit;
    return _e151;
}

uint medium_at(
    metal::float3 p_4,
    uint exclude,
    constant FrameUniforms& frame,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint inside = {};
    float nearest = {};
    uint i_3 = {};
    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = frame;
    metal::float3 _e12 = normalize_vec3f(metal::float3(0.5773, 0.5774, 0.5775));
    uint _e14 = F32_INF;
    Ray probe = Ray {p_4, 0.0, _e12, as_type<float>(_e14), 0u, 0u, 0u};
    inside = 0u;
    uint _e23 = F32_INF;
    nearest = as_type<float>(_e23);
    uint end_1 = frame_1.medium_count;
    i_3 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e59 = i_3;
            i_3 = _e59 + 1u;
        }
        loop_init_2 = false;
        uint _e29 = i_3;
        if (_e29 >= end_1) {
            break;
        }
        uint _e32 = i_3;
        uint slot_5 = params[frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE)];
        if (slot_5 != exclude) {
            uint _e41 = F32_INF;
            Candidate _e43 = no_candidate(as_type<float>(_e41));
            Candidate _e45 = intersect_object(slot_5, probe, _e43, false, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, _buffer_sizes);
            float _e50 = nearest;
            if ((_e45.slot != NO_HIT) && (_e45.t < _e50)) {
                Hit _e53 = finish_hit(probe, _e45, instances, triangles, hit_error, attributes, _buffer_sizes);
                if (!(_e53.front_face)) {
                    inside = slot_5 + 1u;
                    nearest = _e45.t;
                }
            }
        }
    }
    uint _e62 = inside;
    return _e62;
}

Ray sample_camera_ray(
    metal::uint2 pixel_4,
    uint sample_4,
    constant TileParams& tile,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray ray_13 = {};
    FrameUniforms frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed, scratch, rng_state);
    Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4, tile, scratch, rng_state, params, F32_INF, _buffer_sizes);
    ray_13 = _e7;
    ray_13.depth = 0u;
    ray_13.kind = RAY_CAMERA;
    metal::float3 _e15 = ray_13.origin;
    uint _e17 = medium_at(_e15, NO_HIT, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, _buffer_sizes);
    ray_13.medium = _e17;
    Ray _e18 = ray_13;
    return _e18;
}

metal::float3 node_frame_bounds(
) {
    return metal::float3(65535.0);
}

Candidate intersect_scene(
    Ray ray_14,
    bool shadow_2,
    constant FrameUniforms& frame,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best_3 = {};
    uint sp_3 = {};
    uint child_1 = {};
    uint near_1 = {};
    uint far_1 = {};
    uint _e3 = ray_count;
    ray_count = _e3 + 1u;
    Candidate _e7 = no_candidate(ray_14.tmax);
    best_3 = _e7;
    FrameUniforms frame_3 = frame;
    if (frame_3.instance_count == 0u) {
        Candidate _e14 = best_3;
        return _e14;
    }
    uint base_3 = frame_3.tlas_root;
    GpuNode header_4 = nodes[base_3];
    BoxRay _e19 = box_ray(header_4, ray_14);
    metal::float3 _e22 = node_frame_bounds();
    float _e24 = best_3.t;
    float _e27 = slab_in_frame(metal::float3(0.0), _e22, _e19, _e24 * _e19.unit, F32_INF);
    uint _e29 = F32_INF;
    if (_e27 == as_type<float>(_e29)) {
        Candidate _e32 = best_3;
        return _e32;
    }
    sp_3 = 0u;
    child_1 = header_4.a;
    uint2 loop_bound_6 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        uint _e37 = child_1;
        if ((_e37 & NODE_LEAF_BIT) != 0u) {
            uint _e42 = child_1;
            if (((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u) {
                uint _e51 = child_1;
                Candidate _e54 = best_3;
                Candidate _e55 = intersect_object(_e51 & NODE_FIRST_MASK, ray_14, _e54, shadow_2, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, _buffer_sizes);
                best_3 = _e55;
                uint _e57 = best_3.slot;
                if (shadow_2 && (_e57 != NO_HIT)) {
                    Candidate _e61 = best_3;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_10 = nodes[base_3 + _e62];
            float _e68 = best_3.t;
            metal::float2 _e69 = children_entry(n_10, _e19, _e68, F32_INF);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if ((tl_1 < as_type<float>(_e73)) && (tr_1 < as_type<float>(_e77))) {
                near_1 = n_10.a;
                far_1 = n_10.b;
                if (tr_1 < tl_1) {
                    near_1 = n_10.b;
                    far_1 = n_10.a;
                }
                uint _e88 = sp_3;
                if (_e88 < TLAS_STACK) {
                    uint _e91 = sp_3;
                    uint _e92 = far_1;
                    traversal_stack.inner[metal::min(_e91, 66u)] = _e92;
                    uint _e97 = sp_3;
                    sp_3 = _e97 + 1u;
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if (tl_1 < as_type<float>(_e102)) {
                child_1 = n_10.a;
                continue;
            }
            uint _e107 = F32_INF;
            if (tr_1 < as_type<float>(_e107)) {
                child_1 = n_10.b;
                continue;
            }
        }
        uint _e112 = sp_3;
        metal::uint2 _e113 = pop(0u, _e112, traversal_stack);
        if (_e113.x == NO_HIT) {
            break;
        }
        child_1 = _e113.x;
        sp_3 = _e113.y;
    }
    Candidate _e119 = best_3;
    return _e119;
}

Skybox load_Skybox(
    uint offset_5,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_5 + 0u];
    uint _e10 = params[offset_5 + 1u];
    uint _e16 = params[offset_5 + 2u];
    return Skybox {_e5, as_type<float>(_e10), as_type<float>(_e16)};
}

int naga_f2i32(float value) {
    return static_cast<int>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

int i32_from_f32_(
    float x_3
) {
    return ((as_type<uint>(x_3) & 2147483647u) > 2139095040u) ? 0 : naga_f2i32(metal::min(metal::max(x_3, -2147483600.0), 2147483500.0));
}

int naga_div(int lhs, int rhs) {
    return lhs / metal::select(rhs, 1, (lhs == (-2147483647 - 1) & rhs == -1) | (rhs == 0));
}

int rem_i32_(
    int a_4,
    int b_6
) {
    bool by_zero_4 = b_6 == 0;
    int divisor_4 = ((a_4 == (-2147483647 - 1)) & (b_6 == -1)) ? 1 : (by_zero_4 ? 1 : b_6);
    return by_zero_4 ? 0 : as_type<int>(as_type<uint>(a_4) - as_type<uint>(as_type<int>(as_type<uint>(divisor_4) * as_type<uint>(naga_div(a_4, divisor_4)))));
}

metal::int2 wrap_texel_pair(
    int x_4,
    int n_4,
    uint mode
) {
    int m0_ = {};
    int period = as_type<int>(as_type<uint>(2) * as_type<uint>(n_4));
    int _e5 = rem_i32_(x_4, period);
    m0_ = _e5;
    int _e7 = m0_;
    int _e8 = m0_;
    int _e10 = m0_;
    m0_ = (_e10 < 0) ? as_type<int>(as_type<uint>(_e8) + as_type<uint>(period)) : _e7;
    int _e14 = m0_;
    int _e18 = m0_;
    int m1_ = (as_type<int>(as_type<uint>(_e18) + as_type<uint>(1)) == period) ? 0 : as_type<int>(as_type<uint>(_e14) + as_type<uint>(1));
    int _e23 = m0_;
    int _e24 = m0_;
    int _e26 = m0_;
    int r0_1 = (_e26 >= n_4) ? as_type<int>(as_type<uint>(_e24) - as_type<uint>(n_4)) : _e23;
    int r1_1 = (m1_ >= n_4) ? as_type<int>(as_type<uint>(m1_) - as_type<uint>(n_4)) : m1_;
    int _e32 = m0_;
    int _e35 = m0_;
    int _e37 = m0_;
    metal::int2 mirror = metal::int2((_e37 >= n_4) ? as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(period) - as_type<uint>(1))) - as_type<uint>(_e35)) : _e32, (m1_ >= n_4) ? as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(period) - as_type<uint>(1))) - as_type<uint>(m1_)) : m1_);
    metal::int2 wrapped = (mode == TEXTURE_WRAP_MIRROR) ? mirror : metal::int2(r0_1, r1_1);
    return (mode == TEXTURE_WRAP_CLAMP) ? metal::min(metal::max(metal::int2(x_4, as_type<int>(as_type<uint>(x_4) + as_type<uint>(1))), metal::int2(0)), metal::int2(as_type<int>(as_type<uint>(n_4) - as_type<uint>(1)))) : wrapped;
}

float srgb_channel(
    float c_2
) {
    if (c_2 <= 0.04045) {
        return c_2 / 12.92;
    }
    return metal::pow((c_2 + 0.055) / 1.055, 2.4);
}

metal::float4 texel_at(
    uint t_1,
    uint xi,
    uint yi,
    device type_5 const& params,
    device type_5 const& texels,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint base_4 = params[t_1];
    uint _e10 = params[t_1 + 1u];
    uint index_1 = (yi * metal::max(_e10, 1u)) + xi;
    uint format = params[t_1 + 3u];
    if (format == TEXTURE_FORMAT_RGBA8_SRGB) {
        uint _e25 = texels[base_4 + index_1];
        metal::float4 c_9 = metal::unpack_unorm4x8_to_float(_e25);
        float _e28 = srgb_channel(c_9.x);
        float _e30 = srgb_channel(c_9.y);
        float _e32 = srgb_channel(c_9.z);
        return metal::float4(_e28, _e30, _e32, c_9.w);
    }
    if (format == TEXTURE_FORMAT_RGBA8_UNORM) {
        uint _e40 = texels[base_4 + index_1];
        return metal::unpack_unorm4x8_to_float(_e40);
    }
    uint _e47 = texels[base_4 + (index_1 * RGBA16F_TEXEL_WORDS)];
    metal::float2 rg = float2(as_type<half2>(_e47));
    uint _e56 = texels[(base_4 + (index_1 * RGBA16F_TEXEL_WORDS)) + 1u];
    metal::float2 ba = float2(as_type<half2>(_e56));
    return metal::float4(rg, ba);
}

metal::float4 sample_texture(
    uint t_2,
    metal::float2 uv,
    device type_5 const& params,
    device type_5 const& texels,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = params[t_2 + 1u];
    int wi = static_cast<int>(metal::max(_e6, 1u));
    uint _e14 = params[t_2 + 2u];
    int hi_2 = static_cast<int>(metal::max(_e14, 1u));
    uint sampler = params[t_2 + 4u];
    uint mu = sampler & TEXTURE_WRAP_MASK;
    uint mv = (sampler >> (TEXTURE_WRAP_V_SHIFT & 31u)) & TEXTURE_WRAP_MASK;
    metal::float2 q_5 = uv * metal::float2(static_cast<float>(wi), static_cast<float>(hi_2));
    metal::float2 p_8 = ((sampler & TEXTURE_NEAREST) != 0u) ? metal::floor(q_5) : (q_5 - metal::float2(0.5));
    metal::float2 f_3 = metal::floor(p_8);
    metal::float2 fr = p_8 - f_3;
    int _e47 = i32_from_f32_(f_3.x);
    int _e49 = i32_from_f32_(f_3.y);
    metal::int2 _e50 = wrap_texel_pair(_e47, wi, mu);
    metal::uint2 xs = static_cast<metal::uint2>(_e50);
    metal::int2 _e52 = wrap_texel_pair(_e49, hi_2, mv);
    metal::uint2 ys = static_cast<metal::uint2>(_e52);
    uint x0_ = xs.x;
    uint x1_ = xs.y;
    uint y0_ = ys.x;
    uint y1_ = ys.y;
    metal::float4 _e58 = texel_at(t_2, x0_, y0_, params, texels, _buffer_sizes);
    metal::float4 _e59 = texel_at(t_2, x1_, y0_, params, texels, _buffer_sizes);
    metal::float4 a_8 = metal::mix(_e58, _e59, metal::float4(fr.x));
    metal::float4 _e63 = texel_at(t_2, x0_, y1_, params, texels, _buffer_sizes);
    metal::float4 _e64 = texel_at(t_2, x1_, y1_, params, texels, _buffer_sizes);
    metal::float4 b_11 = metal::mix(_e63, _e64, metal::float4(fr.x));
    return metal::mix(a_8, b_11, metal::float4(fr.y));
}

metal::float3 skybox(
    Skybox b_7,
    Ray ray_15,
    device type_5 const& params,
    device type_5 const& texels,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 _e3 = normalize_vec3f(ray_15.dir);
    bool pole = (_e3.x == 0.0) && (_e3.z == 0.0);
    float longitude = (pole ? 0.0 : metal::atan2(_e3.x, -(_e3.z))) - ((b_7.rotation) * 0.017453292519943295474);
    float latitude = metal::acos(metal::min(metal::max(_e3.y, -1.0), 1.0));
    metal::float2 uv_2 = metal::float2(0.5 + (longitude / TAU), latitude * INV_PI);
    metal::float4 _e34 = sample_texture(b_7.image, uv_2, params, texels, _buffer_sizes);
    return _e34.xyz * metal::float3(b_7.intensity);
}

metal::float3 dispatch_miss(
    uint type_id_2,
    uint offset_6,
    Ray ray_16,
    device type_5 const& params,
    device type_5 const& texels,
    constant _mslBufferSizes& _buffer_sizes
) {
    Skybox _e2 = load_Skybox(offset_6, params, _buffer_sizes);
    metal::float3 _e3 = skybox(_e2, ray_16, params, texels, _buffer_sizes);
    return _e3;
}

metal::float3 miss(
    Ray ray_17,
    constant FrameUniforms& frame,
    device type_5 const& params,
    device type_5 const& texels,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_BACKGROUND)) {
        return metal::float3(0.0);
    }
    FrameUniforms frame_4 = frame;
    metal::float3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_17, params, texels, _buffer_sizes);
    return _e9;
}

Lambert load_Lambert(
    uint offset_7,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_7 + 0u];
    uint _e11 = params[offset_7 + 1u];
    uint _e17 = params[offset_7 + 2u];
    return Lambert {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17))};
}

metal::float3 shading_normal(
    Ray ray_18,
    Hit hit_1
) {
    metal::float3 ng = metal::faceforward(hit_1.geometric_normal, ray_18.dir, hit_1.geometric_normal);
    return metal::faceforward(hit_1.normal, -(ng), hit_1.normal);
}

uint light_count_query(
    constant FrameUniforms& frame
) {
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

PointLight load_PointLight(
    uint offset_8,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_8 + 0u];
    uint _e11 = params[offset_8 + 1u];
    uint _e17 = params[offset_8 + 2u];
    uint _e24 = params[offset_8 + 4u];
    uint _e30 = params[offset_8 + 5u];
    uint _e36 = params[offset_8 + 6u];
    uint _e43 = params[offset_8 + 7u];
    uint _e49 = params[offset_8 + 8u];
    uint _e55 = params[offset_8 + 9u];
    return PointLight {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)};
}

float shadow_preset(
    metal::float3 normal,
    metal::float3 dir,
    thread type_4& scratch
) {
    uint mode_1 = scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 14u)];
    if (mode_1 == SHADOW_UNOCCLUDED) {
        return 1.0;
    }
    if ((mode_1 == SHADOW_ABOVE) && !((metal::dot(dir, normal) > 0.0))) {
        return 0.0;
    }
    return -1.0;
}

metal::float3 step_toward(
    metal::float3 x_5,
    metal::float3 s_1
) {
    metal::uint3 bits_1 = as_type<metal::uint3>(x_5);
    metal::bool3 up_1 = (metal::sign(x_5) * metal::sign(s_1)) > metal::float3(0.0);
    metal::float3 stepped = as_type<metal::float3>(metal::select(bits_1 - metal::uint3(1u), bits_1 + metal::uint3(1u), up_1));
    metal::float3 from_zero = metal::select(metal::float3(-0.000000000000000000000000000000000000011754944), metal::float3(0.000000000000000000000000000000000000011754944), s_1 > metal::float3(0.0));
    metal::float3 moved = metal::select(stepped, from_zero, x_5 == metal::float3(0.0));
    return metal::select(x_5, moved, !((s_1 == metal::float3(0.0))));
}

metal::float3 offset_origin(
    metal::float3 p_5,
    metal::float3 n_5,
    float error
) {
    float d_4 = (2.0 * error) * ((metal::abs(n_5.x) + metal::abs(n_5.y)) + metal::abs(n_5.z));
    metal::float3 offset_14 = n_5 * metal::float3(d_4);
    metal::float3 _e17 = step_toward(p_5 + offset_14, offset_14);
    return _e17;
}

Ray shadow_ray(
    metal::float3 position,
    metal::float3 normal_1,
    metal::float3 dir_1,
    float dist,
    thread uint& F32_INF,
    thread float& hit_error
) {
    metal::float3 n_6 = {};
    float tmax_5 = {};
    n_6 = normal_1;
    metal::float3 _e5 = n_6;
    if (metal::dot(dir_1, _e5) < 0.0) {
        metal::float3 _e9 = n_6;
        n_6 = -(_e9);
    }
    metal::float3 a_9 = metal::abs(position);
    float _e13 = hit_error;
    float error_3 = metal::max(_e13, GAMMA_4_ * metal::max(metal::max(a_9.x, a_9.y), a_9.z));
    metal::float3 _e22 = n_6;
    metal::float3 _e23 = offset_origin(position, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_5 = as_type<float>(_e25);
    uint _e29 = F32_INF;
    if (dist < as_type<float>(_e29)) {
        metal::float3 light = position + (dir_1 * metal::float3(dist));
        float dd = metal::dot(dir_1, dir_1);
        float along_1 = metal::dot(light - _e23, dir_1) / dd;
        metal::float3 l_2 = metal::abs(position) + metal::abs(dir_1 * metal::float3(dist));
        tmax_5 = (along_1 * (1.0 - 0.00001)) - ((LIGHT_ERROR * metal::max(metal::max(l_2.x, l_2.y), l_2.z)) / metal::sqrt(dd));
    }
    float _e59 = tmax_5;
    return Ray {_e23, 0.0, dir_1, _e59, 0u, RAY_SHADOW, 0u};
}

float shadow_query(
    metal::float3 position_1,
    metal::float3 normal_2,
    metal::float3 dir_2,
    float dist_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = shadow_preset(normal_2, dir_2, scratch);
    if (_e4 >= 0.0) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_1, normal_2, dir_2, dist_1, F32_INF, hit_error);
    Candidate _e9 = intersect_scene(_e7, true, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, ray_count, _buffer_sizes);
    return (_e9.slot != NO_HIT) ? 0.0 : 1.0;
}

LightSample point_light(
    PointLight l,
    metal::float3 position_2,
    metal::float3 normal_3,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float strength = {};
    metal::float3 to_light = l.position - position_2;
    float dist_2 = metal::length(to_light);
    metal::float3 dir_6 = to_light / metal::float3(metal::max(dist_2, 0.00000000000000000001));
    strength = l.intensity / metal::max(dist_2 * dist_2, 0.00000000000000000001);
    if (l.range > 0.0) {
        float _e19 = strength;
        strength = _e19 * (1.0 - metal::smoothstep(l.inner_range, l.range, dist_2));
    }
    float _e26 = shadow_query(position_2, normal_3, dir_6, dist_2, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
    float _e28 = strength;
    return LightSample {dir_6, dist_2, (l.color * metal::float3(_e28)) * metal::float3(_e26), 0.0};
}

LightSample dispatch_light(
    uint type_id_3,
    uint offset_9,
    metal::float3 position_3,
    metal::float3 normal_4,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    PointLight _e3 = load_PointLight(offset_9, params, _buffer_sizes);
    LightSample _e4 = point_light(_e3, position_3, normal_4, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
    return _e4;
}

LightSample sample_light_query(
    uint i_4,
    metal::float3 position_4,
    metal::float3 normal_5,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    FrameUniforms frame_5 = frame;
    if (i_4 >= frame_5.light_count) {
        return LightSample {metal::float3(0.0, 1.0, 0.0), 0.0, metal::float3(0.0), 0.0};
    }
    uint entry = frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE);
    uint _e22 = params[entry];
    uint _e27 = params[entry + 1u];
    LightSample _e28 = dispatch_light(_e22, _e27, position_4, normal_5, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
    return _e28;
}

metal::float3 lambert_shade(
    Lambert m_2,
    Ray ray_19,
    Hit hit_2,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 color = {};
    uint i_5 = {};
    metal::float3 _e3 = shading_normal(ray_19, hit_2);
    color = metal::float3(0.0);
    uint _e8 = light_count_query(frame);
    i_5 = 0u;
    uint2 loop_bound_7 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e30 = i_5;
            i_5 = _e30 + 1u;
        }
        loop_init_3 = false;
        uint _e10 = i_5;
        if (_e10 >= _e8) {
            break;
        }
        uint _e12 = i_5;
        LightSample _e15 = sample_light_query(_e12, hit_2.position, hit_2.geometric_normal, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
        metal::float3 _e16 = color;
        color = _e16 + (((m_2.albedo * metal::float3(INV_PI)) * _e15.radiance) * metal::float3(metal::max(metal::dot(_e3, _e15.dir), 0.0)));
    }
    metal::float3 _e33 = color;
    return _e33;
}

metal::float3 dispatch_closest_hit(
    uint type_id_4,
    uint offset_10,
    Ray ray_20,
    Hit hit_3,
    metal::float3 secondary,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    Lambert _e3 = load_Lambert(offset_10, params, _buffer_sizes);
    metal::float3 _e4 = lambert_shade(_e3, ray_20, hit_3, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
    return _e4;
}

metal::float3 shade_direct(
    Ray ray_21,
    Candidate c_3,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuInstance inst_8 = instances[c_3.slot];
    Hit _e6 = finish_hit(ray_21, c_3, instances, triangles, hit_error, attributes, _buffer_sizes);
    metal::float3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_21, _e6, metal::float3(0.0), frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
    return _e11;
}

metal::float3 dispatch_medium(
    uint type_id_5,
    uint offset_11,
    Ray ray_22,
    float t_3,
    metal::float3 radiance
) {
    return metal::float3 {};
}

metal::float3 through_medium(
    Ray ray_23,
    float t_4,
    metal::float3 radiance_1,
    device type_9 const& instances,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if (ray_23.medium == 0u) {
        return radiance_1;
    }
    GpuInstance inst_9 = instances[ray_23.medium - 1u];
    if ((inst_9.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    metal::float3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_23, t_4, radiance_1);
    return _e21;
}

void dispatch_secondary_rays(
    uint type_id_6,
    uint offset_12,
    Ray ray_24,
    Hit hit_4
) {
    return;
}

metal::float3 spawn_origin_at(
    metal::float3 position_5,
    metal::float3 normal_6,
    float error_1,
    metal::float3 dir_3
) {
    metal::float3 n_7 = {};
    n_7 = normal_6;
    metal::float3 _e5 = n_7;
    if (metal::dot(dir_3, _e5) < 0.0) {
        metal::float3 _e9 = n_7;
        n_7 = -(_e9);
    }
    metal::float3 _e11 = n_7;
    metal::float3 _e12 = offset_origin(position_5, _e11, error_1);
    return _e12;
}

metal::float3 spawn_origin(
    Hit hit_5,
    float error_2,
    metal::float3 dir_4
) {
    metal::float3 _e5 = spawn_origin_at(hit_5.position, hit_5.geometric_normal, error_2, dir_4);
    return _e5;
}

metal::float3 trace(
    Ray camera_ray,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    thread uint& ray_count,
    device type_5 const& texels,
    thread type_20& spawn_dirs,
    thread type_20& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 radiance_2 = {};
    float t_5 = {};
    type_21 stack_1 = {};
    uint depth = {};
    Ray ray_25 = {};
    metal::float3 value = {};
    bool have_value = {};
    Ray s_ray = {};
    Candidate s_c = {};
    Hit s_hit = {};
    float s_error = {};
    metal::float3 s_sum = {};
    bool fresh = {};
    bool waiting = {};
    bool pushed = {};
    metal::float3 radiance_3 = {};
    float t_6 = {};
    Hit hit_6 = {};
    Frame f_1 = {};
    uint i_6 = {};
    uint medium = {};
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray, false, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, ray_count, _buffer_sizes);
        radiance_2 = metal::float3(0.0);
        uint _e9 = F32_INF;
        t_5 = as_type<float>(_e9);
        if (_e4.slot == NO_HIT) {
            hit_error = 0.0;
            metal::float3 _e17 = miss(camera_ray, frame, params, texels, _buffer_sizes);
            radiance_2 = _e17;
        } else {
            metal::float3 _e18 = shade_direct(camera_ray, _e4, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, ray_count, _buffer_sizes);
            radiance_2 = _e18;
            t_5 = _e4.t;
        }
        float _e20 = t_5;
        metal::float3 _e21 = radiance_2;
        metal::float3 _e22 = through_medium(camera_ray, _e20, _e21, instances, _buffer_sizes);
        return _e22;
    }
    stack_1 = type_21 {};
    depth = 0u;
    ray_25 = camera_ray;
    value = metal::float3(0.0);
    have_value = false;
    s_ray = camera_ray;
    uint _e35 = F32_INF;
    Candidate _e37 = no_candidate(as_type<float>(_e35));
    s_c = _e37;
    s_hit = Hit {metal::float3(0.0), 0.0, metal::float3(0.0), metal::float3(0.0), metal::float2(0.0), true, {}, 0u, 0u};
    s_error = 0.0;
    s_sum = metal::float3(0.0);
    fresh = false;
    waiting = false;
    uint2 loop_bound_8 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        bool _e62 = have_value;
        bool _e64 = waiting;
        if (!(_e62) && !(_e64)) {
            Ray _e67 = ray_25;
            Candidate _e69 = intersect_scene(_e67, false, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, ray_count, _buffer_sizes);
            s_c = _e69;
            Ray _e70 = ray_25;
            s_ray = _e70;
            s_sum = metal::float3(0.0);
            fresh = true;
            waiting = true;
        }
        bool _e75 = waiting;
        if (_e75) {
            waiting = false;
            pushed = false;
            radiance_3 = metal::float3(0.0);
            uint _e83 = F32_INF;
            t_6 = as_type<float>(_e83);
            uint _e87 = s_c.slot;
            if (_e87 == NO_HIT) {
                hit_error = 0.0;
                Ray _e92 = s_ray;
                metal::float3 _e93 = miss(_e92, frame, params, texels, _buffer_sizes);
                radiance_3 = _e93;
            } else {
                uint _e95 = s_c.slot;
                GpuInstance inst_10 = instances[_e95];
                Hit _e99 = s_hit;
                hit_6 = _e99;
                bool _e101 = fresh;
                if (_e101) {
                    Ray _e102 = s_ray;
                    Candidate _e103 = s_c;
                    Hit _e104 = finish_hit(_e102, _e103, instances, triangles, hit_error, attributes, _buffer_sizes);
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
                if (((_e111 && ((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u)) && (_e119 < MAX_DEPTH)) && (_e123 < STACK_SIZE)) {
                    spawn_count = 0u;
                    Ray _e131 = s_ray;
                    Hit _e132 = hit_6;
                    dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, _e131, _e132);
                    uint _e134 = spawn_count;
                    uint n_11 = metal::min(metal::min(_e134, 1u), MAX_SPAWN);
                    if (n_11 > 0u) {
                        Ray _e141 = s_ray;
                        Hit _e142 = hit_6;
                        float _e143 = s_error;
                        uint _e145 = s_c.slot;
                        f_1 = Frame {_e141, _e142, _e143, _e145, {}, metal::float3(0.0), type_20 {}, type_20 {}, n_11, 0u};
                        i_6 = 0u;
                        uint2 loop_bound_9 = uint2(4294967295u);
                        bool loop_init_4 = true;
                        while(true) {
                            if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                            loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                            if (!loop_init_4) {
                                uint _e175 = i_6;
                                i_6 = _e175 + 1u;
                            }
                            loop_init_4 = false;
                            uint _e155 = i_6;
                            if (_e155 >= n_11) {
                                break;
                            }
                            uint _e158 = i_6;
                            uint _e162 = i_6;
                            metal::float3 _e165 = spawn_dirs.inner[_e162];
                            f_1.dirs.inner[metal::min(_e158, 0u)] = _e165;
                            uint _e167 = i_6;
                            uint _e171 = i_6;
                            metal::float3 _e174 = spawn_weights.inner[_e171];
                            f_1.weights.inner[metal::min(_e167, 0u)] = _e174;
                        }
                        uint _e178 = depth;
                        Frame _e182 = f_1;
                        stack_1.inner[metal::min(_e178, 3u)] = _e182;
                        uint _e183 = depth;
                        depth = _e183 + 1u;
                        pushed = true;
                    }
                }
                bool _e187 = pushed;
                if (!(_e187)) {
                    Ray _e191 = s_ray;
                    Hit _e192 = hit_6;
                    metal::float3 _e193 = s_sum;
                    metal::float3 _e194 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e191, _e192, _e193, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, ray_count, _buffer_sizes);
                    radiance_3 = _e194;
                }
            }
            bool _e195 = pushed;
            if (!(_e195)) {
                Ray _e197 = s_ray;
                float _e198 = t_6;
                metal::float3 _e199 = radiance_3;
                metal::float3 _e200 = through_medium(_e197, _e198, _e199, instances, _buffer_sizes);
                value = _e200;
                have_value = true;
            }
        }
        bool _e202 = have_value;
        if (_e202) {
            uint _e203 = depth;
            if (_e203 == 0u) {
                metal::float3 _e206 = value;
                return _e206;
            }
            uint _e207 = depth;
            uint top = _e207 - 1u;
            uint _e214 = stack_1.inner[metal::min(top, 3u)].next;
            uint child_2 = _e214 - 1u;
            metal::float3 _e221 = stack_1.inner[metal::min(top, 3u)].sum;
            metal::float3 _e229 = stack_1.inner[metal::min(top, 3u)].weights.inner[metal::min(child_2, 0u)];
            metal::float3 _e230 = value;
            stack_1.inner[metal::min(top, 3u)].sum = _e221 + (_e229 * _e230);
            have_value = false;
        }
        uint _e234 = depth;
        uint top_1 = _e234 - 1u;
        uint _e241 = stack_1.inner[metal::min(top_1, 3u)].next;
        uint _e246 = stack_1.inner[metal::min(top_1, 3u)].count;
        if (_e241 < _e246) {
            uint i_8 = stack_1.inner[metal::min(top_1, 3u)].next;
            stack_1.inner[metal::min(top_1, 3u)].next = i_8 + 1u;
            Ray parent = stack_1.inner[metal::min(top_1, 3u)].ray;
            Hit hit_10 = stack_1.inner[metal::min(top_1, 3u)].hit;
            metal::float3 dir_7 = stack_1.inner[metal::min(top_1, 3u)].dirs.inner[metal::min(i_8, 0u)];
            medium = parent.medium;
            float _e283 = stack_1.inner[metal::min(top_1, 3u)].error;
            metal::float3 _e284 = spawn_origin(hit_10, _e283, dir_7);
            uint _e287 = F32_INF;
            uint _e293 = medium;
            ray_25 = Ray {_e284, 0.0, dir_7, as_type<float>(_e287), parent.depth + 1u, RAY_SECONDARY, _e293};
        } else {
            Ray _e299 = stack_1.inner[metal::min(top_1, 3u)].ray;
            s_ray = _e299;
            Hit _e304 = stack_1.inner[metal::min(top_1, 3u)].hit;
            s_hit = _e304;
            float _e309 = stack_1.inner[metal::min(top_1, 3u)].error;
            s_error = _e309;
            uint _e315 = stack_1.inner[metal::min(top_1, 3u)].slot;
            s_c.slot = _e315;
            metal::float3 _e320 = stack_1.inner[metal::min(top_1, 3u)].sum;
            s_sum = _e320;
            fresh = false;
            waiting = true;
            depth = top_1;
        }
    }
    return metal::float3 {};
}

metal::bool3 is_finite_vec3f(
    metal::float3 x_6
) {
    return (as_type<metal::uint3>(x_6) & metal::uint3(2147483647u)) < metal::uint3(2139095040u);
}

metal::float3 finite_or_zero(
    metal::float3 c_4
) {
    metal::bool3 _e3 = is_finite_vec3f(c_4);
    return metal::select(metal::float3(0.0), c_4, _e3);
}

PassSum add_sample(
    PassSum p_6,
    metal::float3 c_5,
    uint s_2,
    uint index,
    uint first_pass,
    uint per_pass,
    thread uint& ray_count,
    device type_24& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum next = {};
    next = p_6;
    metal::bool3 _e7 = is_finite_vec3f(c_5);
    if (metal::all(_e7)) {
        metal::float3 _e10 = next.sum;
        next.sum = _e10 + c_5;
    } else {
        metal::float3 _e13 = next.sum;
        metal::float3 _e14 = finite_or_zero(c_5);
        next.sum = _e13 + _e14;
        uint _e17 = next.bad;
        next.bad = _e17 + 1u;
    }
    uint _e22 = rem_u32_(s_2 + 1u, per_pass);
    if (_e22 != 0u) {
        PassSum _e25 = next;
        return _e25;
    }
    uint _e27 = ray_count;
    metal::atomic_fetch_add_explicit(&counters[1], _e27, metal::memory_order_relaxed);
    ray_count = 0u;
    uint _e31 = div_u32_(s_2, per_pass);
    uint pass = first_pass + _e31;
    metal::float3 _e34 = next.sum;
    metal::float4 _e36 = metal::float4(_e34, static_cast<float>(per_pass));
    uint _e38 = next.bad;
    if (pass == 0u) {
        accum[index] = _e36;
    } else {
        metal::float4 _e43 = accum[index];
        accum[index] = _e43 + _e36;
    }
    if (_e38 > 0u) {
        metal::atomic_fetch_add_explicit(&counters[0], _e38, metal::memory_order_relaxed);
    }
    return PassSum {metal::float3(0.0), 0u};
}

void render_pixel(
    metal::uint2 pixel_5,
    constant TileParams& tile,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    thread uint& ray_count,
    device type_5 const& texels,
    thread type_20& spawn_dirs,
    thread type_20& spawn_weights,
    thread uint& spawn_count,
    device type_24& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum sums = {};
    uint s_3 = {};
    FrameUniforms frame_6 = frame;
    TileParams tile_2 = tile;
    uint index_2 = (pixel_5.y * tile_2.image_size.x) + pixel_5.x;
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_2 = tile_2.frame * per_pass_1;
    uint count_3 = per_pass_1 * metal::max(frame_6.passes_per_dispatch, 1u);
    sums = PassSum {metal::float3(0.0), 0u};
    s_3 = 0u;
    uint2 loop_bound_10 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e35 = s_3;
            s_3 = _e35 + 1u;
        }
        loop_init_5 = false;
        uint _e25 = s_3;
        if (_e25 >= count_3) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_3;
        Ray _e30 = sample_camera_ray(pixel_5, first_2 + _e28, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, _buffer_sizes);
        metal::float3 _e31 = trace(_e30, frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, ray_count, texels, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        uint _e32 = s_3;
        PassSum _e34 = add_sample(_e27, _e31, _e32, index_2, tile_2.frame, per_pass_1, ray_count, counters, accum, _buffer_sizes);
        sums = _e34;
    }
    return;
}

void render_invocation(
    metal::uint2 id_1,
    constant TileParams& tile,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& F32_NEG_INF,
    thread float& hit_error,
    device type_17 const& attributes,
    thread uint& ray_count,
    device type_5 const& texels,
    thread type_20& spawn_dirs,
    thread type_20& spawn_weights,
    thread uint& spawn_count,
    device type_24& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    TileParams tile_3 = tile;
    metal::uint2 _e3 = scattered_local(id_1, tile);
    if (metal::any(_e3 >= tile_3.extent)) {
        return;
    }
    render_pixel(tile_3.origin + _e3, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, ray_count, texels, spawn_dirs, spawn_weights, spawn_count, counters, accum, _buffer_sizes);
    return;
}

struct renderInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void render(
  metal::uint3 gid [[thread_position_in_grid]]
, constant TileParams& tile [[buffer(1)]]
, constant FrameUniforms& frame [[buffer(0)]]
, device type_5 const& params [[buffer(6)]]
, device type_9 const& instances [[buffer(3)]]
, device type_10 const& nodes [[buffer(2)]]
, device type_12 const& triangles [[buffer(4)]]
, device type_17 const& attributes [[buffer(5)]]
, device type_5 const& texels [[buffer(7)]]
, device type_24& counters [[buffer(9)]]
, device type_12& accum [[buffer(8)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(10)]]
) {
    type_4 scratch = {};
    uint rng_state = {};
    uint F32_INF = 2139095040u;
    type_13 traversal_stack = {};
    uint F32_NEG_INF = 4286578688u;
    float hit_error = {};
    uint ray_count = {};
    type_20 spawn_dirs = {};
    type_20 spawn_weights = {};
    uint spawn_count = {};
    render_invocation(metal::uint2(gid.x, gid.y), tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, F32_NEG_INF, hit_error, attributes, ray_count, texels, spawn_dirs, spawn_weights, spawn_count, counters, accum, _buffer_sizes);
    return;
}
