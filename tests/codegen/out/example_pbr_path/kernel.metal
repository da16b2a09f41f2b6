// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size6;
    uint size7;
    uint size8;
    uint size11;
    uint size13;
    uint size17;
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
    uint inner[25];
};
typedef uint type_5[1];
struct Pinhole {
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
    uint inner[72];
};
struct Sphere {
    metal::packed_float3 center;
    float radius;
};
struct Intersection {
    float t;
    char _pad1[12];
    metal::float3 normal;
    metal::float2 uv;
    char _pad3[8];
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
struct Triangle {
    metal::float3 v0_;
    metal::float3 v1_;
    metal::float3 v2_;
};
typedef metal::uint4 type_15[1];
struct ConstantBackground {
    metal::float3 color;
};
struct PathDiffuse {
    metal::packed_float3 albedo;
    uint roulette_depth;
};
struct LightSample {
    metal::packed_float3 dir;
    float dist;
    metal::packed_float3 radiance;
    float pdf;
};
struct QuadLight {
    metal::float3 corner;
    metal::float3 edge_u;
    metal::float3 edge_v;
    metal::packed_float3 color;
    float intensity;
    uint lamp;
    char _pad6[12];
};
typedef metal::atomic_uint type_17[1];
struct SphereLight {
    metal::packed_float3 position;
    float radius;
    metal::packed_float3 color;
    float intensity;
    uint lamp;
    char _pad5[12];
};
struct QuadLamp {
    metal::packed_float3 color;
    float intensity;
    float area;
    char _pad3[12];
};
struct SphereLamp {
    metal::packed_float3 color;
    float intensity;
    float radius;
    char _pad3[12];
};
struct PathPbr {
    metal::packed_float3 base_color;
    float metallic;
    float roughness;
    char _pad3[12];
    metal::packed_float3 emissive;
    uint roulette_depth;
};
struct PathState {
    Ray ray;
    metal::float3 beta;
    metal::packed_float3 radiance;
    bool live;
    char _pad4[3];
};
struct type_19 {
    metal::float3 inner[1];
};
struct PbrSample {
    metal::float3 dir;
    metal::packed_float3 weight;
    float pdf;
};
constant uint WORKGROUP_WIDTH = 8u;
constant uint WORKGROUP_HEIGHT = 8u;
constant uint NO_HIT = 4294967295u;
constant uint SCATTER = 1000003u;
constant uint SCRATCH_RNG_INDEX = 12u;
constant uint SCRATCH_RNG_SEED = 13u;
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
constant uint TLAS_STACK = 8u;
constant float TAU = 6.2831855;
constant float INV_PI = 0.31830987;
constant float POINT_ERROR = 0.0000019073486;
constant float GAMMA_1_ = 0.00000005960465;
constant float GAMMA_6_ = 0.0000003576281;
constant float GAMMA_4_ = 0.00000023841864;
constant bool HAS_SECONDARY_RAYS = true;
constant bool HAS_BACKGROUND = true;
constant uint SCRATCH_SHADOW_MODE = 14u;
constant uint SHADOW_ABOVE = 2u;
constant uint LIGHT_ENTRY_STRIDE = 2u;
constant uint SCRATCH_RESOLVED = 3u;
constant uint SCRATCH_LIGHT_BITS = 11u;
constant uint SCRATCH_QUERY = 2u;
constant uint SCRATCH_PENDING = 4u;
constant uint SHADOW_UNOCCLUDED = 1u;
constant uint LIGHT_QUERIES = 32u;
constant uint COUNTER_SHADOW_OVERFLOW = 3u;
constant uint SCRATCH_LIGHT_QUERY = 15u;
constant float LIGHT_ERROR = 0.00000047683716;
constant uint RAY_SHADOW = 2u;
constant uint SHADOW_TRACED = 0u;
constant float MIS_BOUNCE_LENGTH = 3.0;
constant float PBR_MIN_ALPHA = 0.001;
constant uint FLAG_MEDIUM = 4u;
constant uint FLAG_SECONDARY_RAYS = 2u;
constant uint MAX_DEPTH = 5u;
constant uint ROULETTE_DEPTH = 2u;
constant float ROULETTE_THROUGHPUT = 0.5;
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
    scratch.inner[metal::min(SCRATCH_RNG_INDEX, 24u)] = sample;
    uint _e12 = pcg_hash(seed);
    uint _e14 = pcg_hash(pixel.y ^ _e12);
    uint _e16 = pcg_hash(pixel.x ^ _e14);
    scratch.inner[metal::min(SCRATCH_RNG_SEED, 24u)] = _e16;
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

Pinhole load_Pinhole(
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
    return Pinhole {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), metal::float3(as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)), as_type<float>(_e62)};
}

metal::uint2 image_size_query(
    constant TileParams& tile
) {
    TileParams _e1 = tile;
    return _e1.image_size;
}

uint samples_per_pixel_query(
    constant FrameUniforms& frame
) {
    FrameUniforms _e1 = frame;
    return _e1.total_samples;
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
    uint _e10 = scratch.inner[metal::min(SCRATCH_RNG_SEED, 24u)];
    uint _e16 = pcg_hash(_e10 ^ ((d >> 1u) * 2654435769u));
    uint _e22 = scratch.inner[metal::min(SCRATCH_RNG_INDEX, 24u)];
    uint _e24 = laine_karras(metal::reverse_bits(_e22), _e16);
    uint i_8 = metal::reverse_bits(_e24);
    x_2 = i_8;
    if ((d & 1u) != 0u) {
        uint _e31 = sobol_second_reversed(i_8);
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

Ray pinhole_ray(
    Pinhole cam,
    metal::uint2 pixel_2,
    uint sample_2,
    constant TileParams& tile,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    thread uint& F32_INF
) {
    metal::float2 jitter = {};
    metal::uint2 _e2 = image_size_query(tile);
    metal::float2 size_1 = static_cast<metal::float2>(_e2);
    jitter = metal::float2(0.5);
    uint _e7 = samples_per_pixel_query(frame);
    if (_e7 > 1u) {
        metal::float2 _e10 = rand2_next(scratch, rng_state);
        jitter = _e10;
    }
    metal::float2 _e12 = jitter;
    metal::float2 ndc = (((static_cast<metal::float2>(pixel_2) + _e12) / size_1) * metal::float2(2.0)) - metal::float2(1.0);
    metal::float3 _e24 = normalize_vec3f(cam.look_at - cam.position);
    metal::float3 _e27 = normalize_vec3f(metal::cross(_e24, cam.up));
    metal::float3 up = metal::cross(_e27, _e24);
    float h = metal::tan(((cam.fov) * 0.017453292519943295474) * 0.5);
    float aspect = size_1.x / size_1.y;
    metal::float3 _e48 = normalize_vec3f((_e24 + (_e27 * metal::float3((ndc.x * h) * aspect))) - (up * metal::float3(ndc.y * h)));
    uint _e52 = F32_INF;
    return Ray {cam.position, 0.0, _e48, as_type<float>(_e52), 0u, 0u, 0u};
}

Ray dispatch_ray_generation(
    uint type_id,
    uint offset_1,
    metal::uint2 pixel_3,
    uint sample_3,
    constant TileParams& tile,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    Pinhole _e3 = load_Pinhole(offset_1, params, _buffer_sizes);
    Ray _e4 = pinhole_ray(_e3, pixel_3, sample_3, tile, frame, scratch, rng_state, F32_INF);
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
    float m_6 = metal::max(metal::max(metal::abs(ray_2.dir[0]), metal::abs(ray_2.dir[1])), metal::abs(ray_2.dir[2]));
    uint e = metal::min(metal::max((as_type<uint>(m_6) >> 23u) & 255u, 1u), 253u);
    metal::float3 d_3 = ray_2.dir * metal::float3(as_type<float>((254u - e) << 23u));
    float unit = as_type<float>(e << 23u);
    metal::float3 floor = metal::float3(0.0000000000009094947);
    metal::float3 s_6 = metal::select(metal::float3(1.0), metal::float3(-1.0), d_3 < metal::float3(0.0));
    metal::float3 inv = metal::float3(1.0) / metal::select(d_3, s_6 * floor, metal::abs(d_3) < floor);
    metal::float3 rel = origin_2 - ray_2.origin;
    metal::float3 start = rel * inv;
    metal::float3 pad = ((metal::float3(0.0000009536743) * metal::abs(inv)) * ((extent + metal::abs(rel)) + metal::abs(origin_2))) * s_6;
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
    metal::float3 a_4 = _e9.xyz - r_1.origin;
    metal::float4 _e19 = triangles[(slot * 3u) + 1u];
    metal::float3 b_7 = _e19.xyz - r_1.origin;
    metal::float4 _e29 = triangles[(slot * 3u) + 2u];
    metal::float3 c_8 = _e29.xyz - r_1.origin;
    float ax = a_4[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * a_4[metal::min(r_1.kz, 2u)]);
    float ay = a_4[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * a_4[metal::min(r_1.kz, 2u)]);
    float bx = b_7[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * b_7[metal::min(r_1.kz, 2u)]);
    float by = b_7[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * b_7[metal::min(r_1.kz, 2u)]);
    float cx = c_8[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * c_8[metal::min(r_1.kz, 2u)]);
    float cy = c_8[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * c_8[metal::min(r_1.kz, 2u)]);
    float u_3 = (cx * by) - (cy * bx);
    float v_6 = (ax * cy) - (ay * cx);
    float w_1 = (bx * ay) - (by * ax);
    bool outside = (((u_3 < 0.0) || (v_6 < 0.0)) || (w_1 < 0.0)) && (((u_3 > 0.0) || (v_6 > 0.0)) || (w_1 > 0.0));
    float det = (u_3 + v_6) + w_1;
    float scaled = ((u_3 * (r_1.shear[2] * a_4[metal::min(r_1.kz, 2u)])) + (v_6 * (r_1.shear[2] * b_7[metal::min(r_1.kz, 2u)]))) + (w_1 * (r_1.shear[2] * c_8[metal::min(r_1.kz, 2u)]));
    if (occlusion) {
        float st = (det < 0.0) ? -(scaled) : scaled;
        float ad_1 = metal::abs(det);
        bool hit_12 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1));
        uint _e178 = F32_INF;
        return hit_12 ? metal::float3(tmin, 0.0, 0.0) : metal::float3(as_type<float>(_e178), 0.0, 0.0);
    }
    float rcp = 1.0 / det;
    float t_4 = scaled * rcp;
    bool hit_13 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (t_4 >= tmin)) && (t_4 <= tmax_1);
    uint _e202 = F32_INF;
    return hit_13 ? metal::float3(t_4, v_6 * rcp, w_1 * rcp) : metal::float3(as_type<float>(_e202), 0.0, 0.0);
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
    metal::float3 t1_1 = metal::fma(hi, b_4.step, b_4.start_hi);
    metal::bool3 flip_1 = as_type<metal::int3>(b_4.step) < metal::int3(0);
    metal::float3 near_2 = metal::select(t0_, t1_1, flip_1);
    metal::float3 far_2 = metal::select(t1_1, t0_, flip_1);
    metal::float2 e_1 = metal::select(near_2.xy, near_2.yz, near_2.xy < near_2.yz);
    float enter = (e_1.x < e_1.y) ? e_1.y : e_1.x;
    metal::float2 x_5 = metal::select(far_2.xy, far_2.yz, far_2.yz < far_2.xy);
    float exit = (x_5.y < x_5.x) ? x_5.y : x_5.x;
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
    float t_5 = tmax_3 * b_5.unit;
    metal::uint3 _e9 = node_box_lo(lq);
    metal::uint3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(static_cast<metal::float3>(_e9), static_cast<metal::float3>(_e11), b_5, t_5, F32_INF);
    metal::uint3 _e14 = node_box_lo(rq);
    metal::uint3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(static_cast<metal::float3>(_e14), static_cast<metal::float3>(_e16), b_5, t_5, F32_INF);
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
    uint _e14 = traversal_stack.inner[metal::min((base + sp) - 1u, 71u)];
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
    uint base_5 = inst_2.blas_root;
    GpuNode header_2 = nodes[base_5];
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
                    Candidate c_9 = Candidate {_e46.x, owner, prim, {}, _e46.yz, {}, metal::float3(0.0)};
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
            GpuNode n_11 = nodes[base_5 + _e78];
            float _e84 = best.t;
            metal::float2 _e85 = children_entry(n_11, _e12, _e84, F32_INF);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if ((tl < as_type<float>(_e89)) && (tr < as_type<float>(_e93))) {
                near = n_11.a;
                far = n_11.b;
                if ((tr < tl) != shadow) {
                    near = n_11.b;
                    far = n_11.a;
                }
                uint _e105 = sp_1;
                if (_e105 < BLAS_STACK) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack.inner[metal::min(TLAS_STACK + _e109, 71u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = _e116 + 1u;
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if (tl < as_type<float>(_e121)) {
                child = n_11.a;
                continue;
            }
            uint _e126 = F32_INF;
            if (tr < as_type<float>(_e126)) {
                child = n_11.b;
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

Sphere load_Sphere(
    uint offset_2,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_2 + 0u];
    uint _e11 = params[offset_2 + 1u];
    uint _e17 = params[offset_2 + 2u];
    uint _e24 = params[offset_2 + 3u];
    return Sphere {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24)};
}

Intersection sphere_intersect(
    Sphere s,
    Ray ray_5,
    thread uint& F32_INF
) {
    float t = {};
    metal::float3 f_1 = ray_5.origin - s.center;
    float a_5 = metal::dot(ray_5.dir, ray_5.dir);
    float b_8 = -(metal::dot(f_1, ray_5.dir));
    metal::float3 l_6 = f_1 + (ray_5.dir * metal::float3(b_8 / a_5));
    float r2_ = s.radius * s.radius;
    float disc = a_5 * (r2_ - metal::dot(l_6, l_6));
    if (!((disc >= 0.0)) || !((a_5 > 0.0))) {
        uint _e30 = F32_INF;
        return Intersection {as_type<float>(_e30), {}, metal::float3(0.0, 0.0, 1.0), metal::float2 {}};
    }
    float q_1 = b_8 + (((b_8 >= 0.0) ? 1.0 : -1.0) * metal::sqrt(disc));
    float t0_1 = (metal::dot(f_1, f_1) - r2_) / q_1;
    float t1_2 = q_1 / a_5;
    t = metal::min(t0_1, t1_2);
    float _e52 = t;
    if (!((_e52 >= ray_5.tmin))) {
        t = metal::max(t0_1, t1_2);
    }
    float _e57 = t;
    float _e60 = t;
    if (!(((_e57 >= ray_5.tmin) && (_e60 <= ray_5.tmax)))) {
        uint _e66 = F32_INF;
        return Intersection {as_type<float>(_e66), {}, metal::float3(0.0, 0.0, 1.0), metal::float2 {}};
    }
    float _e76 = t;
    metal::float3 _e82 = normalize_vec3f((ray_5.origin + (ray_5.dir * metal::float3(_e76))) - s.center);
    float u_4 = ((_e82.x == 0.0) && (_e82.z == 0.0)) ? 0.5 : (0.5 + (metal::atan2(_e82.z, -(_e82.x)) / TAU));
    metal::float2 uv = metal::float2(u_4, metal::acos(metal::min(metal::max(_e82.y, -1.0), 1.0)) * INV_PI);
    float _e109 = t;
    return Intersection {_e109, {}, _e82, uv};
}

Intersection dispatch_intersection(
    uint type_id_1,
    uint offset_3,
    Ray ray_6,
    device type_5 const& params,
    thread uint& F32_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    Sphere _e2 = load_Sphere(offset_3, params, _buffer_sizes);
    Intersection _e3 = sphere_intersect(_e2, ray_6, F32_INF);
    return _e3;
}

Candidate intersect_object(
    uint slot_2,
    Ray ray_7,
    Candidate best_1,
    bool shadow_1,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray r_2 = {};
    GpuInstance inst_6 = instances[slot_2];
    Ray _e7 = to_object(inst_6, ray_7);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_7, _e14, best_1, shadow_1, F32_INF, nodes, triangles, traversal_stack, _buffer_sizes);
        return _e15;
    }
    Ray _e18 = r_2;
    Intersection _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18, params, F32_INF, _buffer_sizes);
    float _e22 = r_2.tmin;
    float _e26 = r_2.tmax;
    uint _e31 = F32_INF;
    if (((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < as_type<float>(_e31))) {
        Candidate c_10 = Candidate {_e19.t, slot_2, 0u, {}, _e19.uv, {}, _e19.normal};
        bool _e40 = accept(inst_6, ray_7, c_10);
        if (_e40) {
            return c_10;
        }
    }
    return best_1;
}

float point_error(
    metal::float3 origin_1,
    metal::float3 along
) {
    metal::float3 a_6 = metal::abs(origin_1) + metal::abs(along);
    return POINT_ERROR * metal::max(metal::max(a_6.x, a_6.y), a_6.z);
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
    metal::float4 q_2 = metal::float4(p_2, 1.0);
    return metal::float3(metal::dot(inst_3.object_to_world_0_, q_2), metal::dot(inst_3.object_to_world_1_, q_2), metal::dot(inst_3.object_to_world_2_, q_2));
}

float mesh_error(
    GpuInstance inst_4,
    metal::float3 v0_,
    metal::float3 db1_,
    metal::float3 db2_,
    metal::float3 p_3
) {
    metal::float3 obj = (metal::float3(GAMMA_1_) * metal::abs(v0_)) + (metal::float3(GAMMA_6_) * (metal::abs(db1_) + metal::abs(db2_)));
    metal::float4 q_3 = metal::float4(metal::abs(p_3), 1.0);
    metal::float4 r0_ = metal::abs(inst_4.object_to_world_0_);
    metal::float4 r1_ = metal::abs(inst_4.object_to_world_1_);
    metal::float4 r2_1 = metal::abs(inst_4.object_to_world_2_);
    metal::float3 rounding = metal::float3(GAMMA_4_) * metal::float3(metal::dot(r0_, q_3), metal::dot(r1_, q_3), metal::dot(r2_1, q_3));
    metal::float3 carried = metal::float3(1.0 + GAMMA_4_) * metal::float3(metal::dot(r0_.xyz, obj), metal::dot(r1_.xyz, obj), metal::dot(r2_1.xyz, obj));
    metal::float3 e_2 = rounding + carried;
    return metal::max(metal::max(e_2.x, e_2.y), e_2.z);
}

metal::float3 decode_octahedral(
    uint bits
) {
    metal::float3 n_1 = {};
    metal::float2 e_3 = metal::unpack_snorm2x16_to_float(bits);
    n_1 = metal::float3(e_3.x, e_3.y, (1.0 - metal::abs(e_3.x)) - metal::abs(e_3.y));
    float _e14 = n_1.z;
    if (_e14 < 0.0) {
        metal::float3 _e21 = n_1;
        metal::float2 s_7 = metal::select(metal::float2(-1.0), metal::float2(1.0), _e21.xy >= metal::float2(0.0));
        metal::float3 _e29 = n_1;
        metal::float2 xy = (metal::float2(1.0) - metal::abs(_e29.yx)) * s_7;
        float _e37 = n_1.z;
        n_1 = metal::float3(xy.x, xy.y, _e37);
    }
    metal::float3 _e39 = n_1;
    metal::float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

metal::float3 normal_to_world(
    GpuInstance inst_5,
    metal::float3 n_2
) {
    metal::float3 w_2 = ((inst_5.world_to_object_0_.xyz * metal::float3(n_2.x)) + (inst_5.world_to_object_1_.xyz * metal::float3(n_2.y))) + (inst_5.world_to_object_2_.xyz * metal::float3(n_2.z));
    metal::float3 _e19 = normalize_vec3f(w_2);
    return _e19;
}

Hit finish_hit(
    Ray ray_8,
    Candidate c_1,
    device type_9 const& instances,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_15 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Hit hit = {};
    metal::float3 n_geo = {};
    metal::float3 n_shade = {};
    GpuInstance inst_7 = instances[c_1.slot];
    float _e11 = point_error(ray_8.origin, ray_8.dir * metal::float3(c_1.t));
    hit_error = _e11;
    hit = Hit {ray_8.origin + (ray_8.dir * metal::float3(c_1.t)), c_1.t, metal::float3(0.0, 1.0, 0.0), metal::float3(0.0, 1.0, 0.0), c_1.uv, true, {}, inst_7.object, c_1.primitive};
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if (inst_7.geometry_type == MESH_GEOMETRY) {
        Triangle _e42 = load_triangle(c_1.primitive, triangles, _buffer_sizes);
        metal::float2 b_9 = c_1.uv;
        float w_3 = (1.0 - c_1.uv.x) - c_1.uv.y;
        metal::float3 e1_ = _e42.v1_ - _e42.v0_;
        metal::float3 e2_ = _e42.v2_ - _e42.v0_;
        metal::float3 p_8 = _e42.v0_ + ((e1_ * metal::float3(c_1.uv.x)) + (e2_ * metal::float3(c_1.uv.y)));
        metal::float3 _e65 = point_to_world(inst_7, p_8);
        hit.position = _e65;
        float _e73 = mesh_error(inst_7, _e42.v0_, e1_ * metal::float3(c_1.uv.x), e2_ * metal::float3(c_1.uv.y), p_8);
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
    hit.front_face = metal::dot(ray_8.dir, _e147) < 0.0;
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
    thread float& hit_error,
    device type_15 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint inside = {};
    float nearest = {};
    uint i_1 = {};
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
    uint end = frame_1.medium_count;
    i_1 = 0u;
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e59 = i_1;
            i_1 = _e59 + 1u;
        }
        loop_init_1 = false;
        uint _e29 = i_1;
        if (_e29 >= end) {
            break;
        }
        uint _e32 = i_1;
        uint slot_4 = params[frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE)];
        if (slot_4 != exclude) {
            uint _e41 = F32_INF;
            Candidate _e43 = no_candidate(as_type<float>(_e41));
            Candidate _e45 = intersect_object(slot_4, probe, _e43, false, params, F32_INF, instances, nodes, triangles, traversal_stack, _buffer_sizes);
            float _e50 = nearest;
            if ((_e45.slot != NO_HIT) && (_e45.t < _e50)) {
                Hit _e53 = finish_hit(probe, _e45, instances, triangles, hit_error, attributes, _buffer_sizes);
                if (!(_e53.front_face)) {
                    inside = slot_4 + 1u;
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
    thread float& hit_error,
    device type_15 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray ray_9 = {};
    FrameUniforms frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed, scratch, rng_state);
    Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4, tile, frame, scratch, rng_state, params, F32_INF, _buffer_sizes);
    ray_9 = _e7;
    ray_9.depth = 0u;
    ray_9.kind = RAY_CAMERA;
    metal::float3 _e15 = ray_9.origin;
    uint _e17 = medium_at(_e15, NO_HIT, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, _buffer_sizes);
    ray_9.medium = _e17;
    Ray _e18 = ray_9;
    return _e18;
}

metal::float3 node_frame_bounds(
) {
    return metal::float3(65535.0);
}

Candidate intersect_scene(
    Ray ray_10,
    bool shadow_2,
    constant FrameUniforms& frame,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best_2 = {};
    uint sp_2 = {};
    uint child_1 = {};
    uint near_1 = {};
    uint far_1 = {};
    uint _e3 = ray_count;
    ray_count = _e3 + 1u;
    Candidate _e7 = no_candidate(ray_10.tmax);
    best_2 = _e7;
    FrameUniforms frame_3 = frame;
    if (frame_3.instance_count == 0u) {
        Candidate _e14 = best_2;
        return _e14;
    }
    uint base_6 = frame_3.tlas_root;
    GpuNode header_3 = nodes[base_6];
    BoxRay _e19 = box_ray(header_3, ray_10);
    metal::float3 _e22 = node_frame_bounds();
    float _e24 = best_2.t;
    float _e27 = slab_in_frame(metal::float3(0.0), _e22, _e19, _e24 * _e19.unit, F32_INF);
    uint _e29 = F32_INF;
    if (_e27 == as_type<float>(_e29)) {
        Candidate _e32 = best_2;
        return _e32;
    }
    sp_2 = 0u;
    child_1 = header_3.a;
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e37 = child_1;
        if ((_e37 & NODE_LEAF_BIT) != 0u) {
            uint _e42 = child_1;
            if (((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u) {
                uint _e51 = child_1;
                Candidate _e54 = best_2;
                Candidate _e55 = intersect_object(_e51 & NODE_FIRST_MASK, ray_10, _e54, shadow_2, params, F32_INF, instances, nodes, triangles, traversal_stack, _buffer_sizes);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if (shadow_2 && (_e57 != NO_HIT)) {
                    Candidate _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_12 = nodes[base_6 + _e62];
            float _e68 = best_2.t;
            metal::float2 _e69 = children_entry(n_12, _e19, _e68, F32_INF);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if ((tl_1 < as_type<float>(_e73)) && (tr_1 < as_type<float>(_e77))) {
                near_1 = n_12.a;
                far_1 = n_12.b;
                if (tr_1 < tl_1) {
                    near_1 = n_12.b;
                    far_1 = n_12.a;
                }
                uint _e88 = sp_2;
                if (_e88 < TLAS_STACK) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack.inner[metal::min(_e91, 71u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = _e97 + 1u;
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if (tl_1 < as_type<float>(_e102)) {
                child_1 = n_12.a;
                continue;
            }
            uint _e107 = F32_INF;
            if (tr_1 < as_type<float>(_e107)) {
                child_1 = n_12.b;
                continue;
            }
        }
        uint _e112 = sp_2;
        metal::uint2 _e113 = pop(0u, _e112, traversal_stack);
        if (_e113.x == NO_HIT) {
            break;
        }
        child_1 = _e113.x;
        sp_2 = _e113.y;
    }
    Candidate _e119 = best_2;
    return _e119;
}

ConstantBackground load_ConstantBackground(
    uint offset_4,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_4 + 0u];
    uint _e11 = params[offset_4 + 1u];
    uint _e17 = params[offset_4 + 2u];
    return ConstantBackground {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17))};
}

metal::float3 constant_background(
    ConstantBackground b_6,
    Ray ray_11
) {
    return b_6.color;
}

metal::float3 dispatch_miss(
    uint type_id_2,
    uint offset_5,
    Ray ray_12,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    ConstantBackground _e2 = load_ConstantBackground(offset_5, params, _buffer_sizes);
    metal::float3 _e3 = constant_background(_e2, ray_12);
    return _e3;
}

metal::float3 miss(
    Ray ray_13,
    constant FrameUniforms& frame,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_BACKGROUND)) {
        return metal::float3(0.0);
    }
    FrameUniforms frame_4 = frame;
    metal::float3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_13, params, _buffer_sizes);
    return _e9;
}

PathDiffuse load_PathDiffuse(
    uint offset_6,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_6 + 0u];
    uint _e11 = params[offset_6 + 1u];
    uint _e17 = params[offset_6 + 2u];
    uint _e24 = params[offset_6 + 3u];
    return PathDiffuse {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), _e24};
}

uint light_count_query(
    constant FrameUniforms& frame
) {
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

QuadLight load_QuadLight(
    uint offset_7,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_7 + 0u];
    uint _e11 = params[offset_7 + 1u];
    uint _e17 = params[offset_7 + 2u];
    uint _e24 = params[offset_7 + 4u];
    uint _e30 = params[offset_7 + 5u];
    uint _e36 = params[offset_7 + 6u];
    uint _e43 = params[offset_7 + 8u];
    uint _e49 = params[offset_7 + 9u];
    uint _e55 = params[offset_7 + 10u];
    uint _e62 = params[offset_7 + 12u];
    uint _e68 = params[offset_7 + 13u];
    uint _e74 = params[offset_7 + 14u];
    uint _e81 = params[offset_7 + 15u];
    uint _e87 = params[offset_7 + 16u];
    return QuadLight {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), metal::float3(as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)), metal::float3(as_type<float>(_e62), as_type<float>(_e68), as_type<float>(_e74)), as_type<float>(_e81), _e87};
}

float shadow_preset(
    metal::float3 normal,
    metal::float3 dir,
    thread type_4& scratch
) {
    uint mode = scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 24u)];
    if (mode == SHADOW_UNOCCLUDED) {
        return 1.0;
    }
    if ((mode == SHADOW_ABOVE) && !((metal::dot(dir, normal) > 0.0))) {
        return 0.0;
    }
    return -1.0;
}

void scratch_store3f(
    uint i_2,
    metal::float3 v_2,
    thread type_4& scratch
) {
    metal::uint3 b_10 = as_type<metal::uint3>(v_2);
    scratch.inner[metal::min(i_2, 24u)] = b_10.x;
    scratch.inner[metal::min(i_2 + 1u, 24u)] = b_10.y;
    scratch.inner[metal::min(i_2 + 2u, 24u)] = b_10.z;
    return;
}

float shadow_deferred(
    metal::float3 position,
    metal::float3 normal_1,
    metal::float3 dir_1,
    float dist,
    thread type_4& scratch,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = shadow_preset(normal_1, dir_1, scratch);
    if (_e4 >= 0.0) {
        return _e4;
    }
    uint i_9 = scratch.inner[metal::min(SCRATCH_QUERY, 24u)];
    scratch.inner[metal::min(SCRATCH_QUERY, 24u)] = i_9 + 1u;
    uint _e25 = scratch.inner[metal::min(SCRATCH_RESOLVED, 24u)];
    if (i_9 < _e25) {
        uint _e32 = scratch.inner[metal::min(SCRATCH_LIGHT_BITS, 24u)];
        return static_cast<float>((_e32 >> (i_9 & 31u)) & 1u);
    }
    uint _e44 = scratch.inner[metal::min(SCRATCH_PENDING, 24u)];
    if (_e44 != 0u) {
        return 1.0;
    }
    if (i_9 >= LIGHT_QUERIES) {
        metal::atomic_fetch_add_explicit(&counters[metal::min(COUNTER_SHADOW_OVERFLOW, 3u)], 1u, metal::memory_order_relaxed);
        return 1.0;
    }
    scratch_store3f(SCRATCH_LIGHT_QUERY, position, scratch);
    scratch_store3f(SCRATCH_LIGHT_QUERY + 3u, normal_1, scratch);
    scratch_store3f(SCRATCH_LIGHT_QUERY + 6u, dir_1, scratch);
    scratch.inner[metal::min(SCRATCH_LIGHT_QUERY + 9u, 24u)] = as_type<uint>(dist);
    scratch.inner[metal::min(SCRATCH_PENDING, 24u)] = 1u;
    return 1.0;
}

LightSample quad_light(
    QuadLight l,
    metal::float3 position_1,
    metal::float3 normal_2,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 c_11 = metal::cross(l.edge_u, l.edge_v);
    float area = metal::length(c_11);
    metal::float2 _e7 = rand2_next(scratch, rng_state);
    metal::float3 to_light = ((l.corner + (l.edge_u * metal::float3(_e7.x))) + (l.edge_v * metal::float3(_e7.y))) - position_1;
    float dist2_ = metal::dot(to_light, to_light);
    float dist_3 = metal::sqrt(dist2_);
    metal::float3 dir_9 = to_light / metal::float3(metal::max(dist_3, 0.00000000000000000001));
    float cos_light = -(metal::dot(dir_9, c_11)) / metal::max(area, 0.000000000000000000000000000001);
    if (!((cos_light > 0.0)) || !((dist2_ > 0.0))) {
        return LightSample {dir_9, dist_3, metal::float3(0.0), 0.0};
    }
    float _e42 = shadow_deferred(position_1, normal_2, dir_9, dist_3, scratch, counters, _buffer_sizes);
    float strength = ((l.intensity * cos_light) * area) / dist2_;
    float pdf_1 = (l.lamp == 1u) ? (dist2_ / (cos_light * area)) : 0.0;
    return LightSample {dir_9, dist_3, (l.color * metal::float3(strength)) * metal::float3(_e42), pdf_1};
}

SphereLight load_SphereLight(
    uint offset_8,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_8 + 0u];
    uint _e11 = params[offset_8 + 1u];
    uint _e17 = params[offset_8 + 2u];
    uint _e24 = params[offset_8 + 3u];
    uint _e30 = params[offset_8 + 4u];
    uint _e36 = params[offset_8 + 5u];
    uint _e42 = params[offset_8 + 6u];
    uint _e49 = params[offset_8 + 7u];
    uint _e55 = params[offset_8 + 8u];
    return SphereLight {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24), metal::float3(as_type<float>(_e30), as_type<float>(_e36), as_type<float>(_e42)), as_type<float>(_e49), _e55};
}

metal::float3x3 orthonormal_basis(
    metal::float3 n_3
) {
    float sign = ((as_type<uint>(n_3.z) & 2147483648u) != 0u) ? -1.0 : 1.0;
    float a_7 = -1.0 / (sign + n_3.z);
    float b_11 = (n_3.x * n_3.y) * a_7;
    float _e16 = sign * n_3.x;
    return metal::float3x3(metal::float3(1.0 + ((_e16 * n_3.x) * a_7), sign * b_11, -(_e16)), metal::float3(b_11, sign + ((n_3.y * n_3.y) * a_7), -(n_3.y)), n_3);
}

LightSample sphere_light(
    SphereLight l_1,
    metal::float3 position_2,
    metal::float3 normal_3,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 to_center = l_1.position - position_2;
    float d2_ = metal::dot(to_center, to_center);
    float r2_2 = metal::max(l_1.radius * l_1.radius, 0.00000000000000000001);
    if (d2_ <= r2_2) {
        return LightSample {metal::float3(0.0, 1.0, 0.0), 0.0, metal::float3(0.0), 0.0};
    }
    metal::float3 w_4 = to_center * metal::float3(metal::rsqrt(d2_));
    float s2_ = r2_2 / d2_;
    float cos_max = metal::sqrt(1.0 - s2_);
    float one_minus_cos_max = s2_ / (1.0 + cos_max);
    metal::float2 _e31 = rand2_next(scratch, rng_state);
    float cos_t = 1.0 - (_e31.x * one_minus_cos_max);
    float sin_t = metal::sqrt(metal::max(1.0 - (cos_t * cos_t), 0.0));
    float phi = TAU * _e31.y;
    metal::float3x3 _e45 = orthonormal_basis(w_4);
    metal::float3 _e52 = normalize_vec3f(_e45 * metal::float3(metal::cos(phi) * sin_t, metal::sin(phi) * sin_t, cos_t));
    float along_1 = metal::dot(to_center, _e52);
    float dist_4 = metal::max(along_1 - metal::sqrt(metal::max(r2_2 - (d2_ - (along_1 * along_1)), 0.0)), 0.0);
    float weight_4 = ((l_1.intensity * 2.0) * one_minus_cos_max) / r2_2;
    float _e68 = shadow_deferred(position_2, normal_3, _e52, dist_4, scratch, counters, _buffer_sizes);
    float pdf_2 = (l_1.lamp == 1u) ? (1.0 / (TAU * one_minus_cos_max)) : 0.0;
    return LightSample {_e52, dist_4, (l_1.color * metal::float3(weight_4)) * metal::float3(_e68), pdf_2};
}

LightSample dispatch_light(
    uint type_id_3,
    uint offset_9,
    metal::float3 position_3,
    metal::float3 normal_4,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(type_id_3) {
        case 0u: {
            QuadLight _e4 = load_QuadLight(offset_9, params, _buffer_sizes);
            LightSample _e5 = quad_light(_e4, position_3, normal_4, scratch, rng_state, counters, _buffer_sizes);
            return _e5;
        }
        case 1u: {
            SphereLight _e6 = load_SphereLight(offset_9, params, _buffer_sizes);
            LightSample _e7 = sphere_light(_e6, position_3, normal_4, scratch, rng_state, counters, _buffer_sizes);
            return _e7;
        }
        default: {
            break;
        }
    }
    return LightSample {};
}

metal::float3 scratch_load3f(
    uint i_3,
    thread type_4& scratch
) {
    uint _e5 = scratch.inner[metal::min(i_3, 24u)];
    uint _e12 = scratch.inner[metal::min(i_3 + 1u, 24u)];
    uint _e19 = scratch.inner[metal::min(i_3 + 2u, 24u)];
    return as_type<metal::float3>(metal::uint3(_e5, _e12, _e19));
}

metal::float3 step_toward(
    metal::float3 x_3,
    metal::float3 s_1
) {
    metal::uint3 bits_2 = as_type<metal::uint3>(x_3);
    metal::bool3 up_1 = (metal::sign(x_3) * metal::sign(s_1)) > metal::float3(0.0);
    metal::float3 stepped = as_type<metal::float3>(metal::select(bits_2 - metal::uint3(1u), bits_2 + metal::uint3(1u), up_1));
    metal::float3 from_zero = metal::select(metal::float3(-0.000000000000000000000000000000000000011754944), metal::float3(0.000000000000000000000000000000000000011754944), s_1 > metal::float3(0.0));
    metal::float3 moved = metal::select(stepped, from_zero, x_3 == metal::float3(0.0));
    return metal::select(x_3, moved, !((s_1 == metal::float3(0.0))));
}

metal::float3 offset_origin(
    metal::float3 p_5,
    metal::float3 n_4,
    float error
) {
    float d_4 = (2.0 * error) * ((metal::abs(n_4.x) + metal::abs(n_4.y)) + metal::abs(n_4.z));
    metal::float3 offset_16 = n_4 * metal::float3(d_4);
    metal::float3 _e17 = step_toward(p_5 + offset_16, offset_16);
    return _e17;
}

Ray shadow_ray(
    metal::float3 position_4,
    metal::float3 normal_5,
    metal::float3 dir_2,
    float dist_1,
    thread uint& F32_INF,
    thread float& hit_error
) {
    metal::float3 n_5 = {};
    float tmax_4 = {};
    n_5 = normal_5;
    metal::float3 _e5 = n_5;
    if (metal::dot(dir_2, _e5) < 0.0) {
        metal::float3 _e9 = n_5;
        n_5 = -(_e9);
    }
    metal::float3 a_8 = metal::abs(position_4);
    float _e13 = hit_error;
    float error_3 = metal::max(_e13, GAMMA_4_ * metal::max(metal::max(a_8.x, a_8.y), a_8.z));
    metal::float3 _e22 = n_5;
    metal::float3 _e23 = offset_origin(position_4, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = as_type<float>(_e25);
    uint _e29 = F32_INF;
    if (dist_1 < as_type<float>(_e29)) {
        metal::float3 light = position_4 + (dir_2 * metal::float3(dist_1));
        float dd = metal::dot(dir_2, dir_2);
        float along_2 = metal::dot(light - _e23, dir_2) / dd;
        metal::float3 l_7 = metal::abs(position_4) + metal::abs(dir_2 * metal::float3(dist_1));
        tmax_4 = (along_2 * (1.0 - 0.00001)) - ((LIGHT_ERROR * metal::max(metal::max(l_7.x, l_7.y), l_7.z)) / metal::sqrt(dd));
    }
    float _e59 = tmax_4;
    return Ray {_e23, 0.0, dir_2, _e59, 0u, RAY_SHADOW, 0u};
}

float shadow_query(
    metal::float3 position_5,
    metal::float3 normal_6,
    metal::float3 dir_3,
    float dist_2,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = shadow_preset(normal_6, dir_3, scratch);
    if (_e4 >= 0.0) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_5, normal_6, dir_3, dist_2, F32_INF, hit_error);
    Candidate _e9 = intersect_scene(_e7, true, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, ray_count, _buffer_sizes);
    return (_e9.slot != NO_HIT) ? 0.0 : 1.0;
}

LightSample sample_light_deferred(
    uint i_4,
    metal::float3 position_6,
    metal::float3 normal_7,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint after = {};
    uint resolved = {};
    uint bits_1 = {};
    FrameUniforms frame_5 = frame;
    if (i_4 >= frame_5.light_count) {
        return LightSample {metal::float3(0.0, 1.0, 0.0), 0.0, metal::float3(0.0), 0.0};
    }
    uint entry = frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE);
    uint type_id_7 = params[entry];
    uint offset_17 = params[entry + 1u];
    uint start_1 = rng_state;
    after = start_1;
    resolved = 0u;
    bits_1 = 0u;
    scratch.inner[metal::min(SCRATCH_RESOLVED, 24u)] = 0u;
    scratch.inner[metal::min(SCRATCH_LIGHT_BITS, 24u)] = 0u;
    uint2 loop_bound_4 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        rng_state = start_1;
        scratch.inner[metal::min(SCRATCH_QUERY, 24u)] = 0u;
        scratch.inner[metal::min(SCRATCH_PENDING, 24u)] = 0u;
        LightSample _e60 = dispatch_light(type_id_7, offset_17, position_6, normal_7, scratch, rng_state, params, counters, _buffer_sizes);
        uint _e66 = scratch.inner[metal::min(SCRATCH_PENDING, 24u)];
        if (_e66 == 0u) {
            uint _e69 = resolved;
            if (_e69 > 0u) {
                uint _e72 = after;
                rng_state = _e72;
            }
            return _e60;
        }
        uint _e74 = resolved;
        if (_e74 == 0u) {
            uint _e78 = rng_state;
            after = _e78;
        }
        uint _e79 = after;
        rng_state = _e79;
        metal::float3 _e82 = scratch_load3f(SCRATCH_LIGHT_QUERY, scratch);
        metal::float3 _e85 = scratch_load3f(SCRATCH_LIGHT_QUERY + 3u, scratch);
        metal::float3 _e88 = scratch_load3f(SCRATCH_LIGHT_QUERY + 6u, scratch);
        uint _e95 = scratch.inner[metal::min(SCRATCH_LIGHT_QUERY + 9u, 24u)];
        float _e97 = shadow_query(_e82, _e85, _e88, as_type<float>(_e95), frame, scratch, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, _buffer_sizes);
        uint _e99 = rng_state;
        after = _e99;
        if (!((_e97 == 0.0))) {
            uint _e108 = scratch.inner[metal::min(SCRATCH_QUERY, 24u)];
            uint _e109 = resolved;
            if (_e108 == (_e109 + 1u)) {
                uint _e113 = after;
                rng_state = _e113;
                scratch.inner[metal::min(SCRATCH_PENDING, 24u)] = 0u;
                return _e60;
            }
            uint _e121 = bits_1;
            uint _e123 = resolved;
            bits_1 = _e121 | (1u << (_e123 & 31u));
        }
        uint _e128 = resolved;
        resolved = _e128 + 1u;
        uint _e132 = bits_1;
        scratch.inner[metal::min(SCRATCH_LIGHT_BITS, 24u)] = _e132;
        uint _e138 = resolved;
        scratch.inner[metal::min(SCRATCH_RESOLVED, 24u)] = _e138;
    }
    return LightSample {};
}

LightSample sample_light_above_deferred(
    uint i_5,
    metal::float3 position_7,
    metal::float3 normal_8,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_ABOVE;
    LightSample _e9 = sample_light_deferred(i_5, position_7, normal_8, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
    scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 24u)] = SHADOW_TRACED;
    return _e9;
}

float mis_weight(
    float p_6,
    float other,
    thread uint& F32_INF
) {
    if (!((p_6 > 0.0))) {
        return 0.0;
    }
    float r_3 = metal::max(other, 0.0) / p_6;
    if (!((r_3 < 1000000000000000000.0))) {
        uint _e15 = F32_INF;
        uint _e19 = F32_INF;
        return ((p_6 == as_type<float>(_e15)) && (other < as_type<float>(_e19))) ? 1.0 : 0.0;
    }
    return 1.0 / (1.0 + (r_3 * r_3));
}

float mis_light_weight(
    LightSample l_2,
    float bsdf_pdf,
    thread uint& F32_INF
) {
    if (!((l_2.pdf > 0.0))) {
        return 1.0;
    }
    float _e8 = mis_weight(l_2.pdf, bsdf_pdf, F32_INF);
    return _e8;
}

metal::float3 path_diffuse_shade(
    PathDiffuse m,
    Ray ray_14,
    Hit hit_1,
    metal::float3 secondary,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 direct = {};
    uint i_6 = {};
    metal::float3 n_13 = metal::faceforward(hit_1.normal, ray_14.dir, hit_1.geometric_normal);
    metal::float3 ng = metal::faceforward(hit_1.geometric_normal, ray_14.dir, hit_1.geometric_normal);
    direct = metal::float3(0.0);
    uint _e16 = light_count_query(frame);
    i_6 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e36 = i_6;
            i_6 = _e36 + 1u;
        }
        loop_init_2 = false;
        uint _e18 = i_6;
        if (_e18 >= _e16) {
            break;
        }
        uint _e20 = i_6;
        LightSample _e22 = sample_light_above_deferred(_e20, hit_1.position, ng, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
        float c_12 = metal::max(metal::dot(n_13, _e22.dir), 0.0);
        metal::float3 _e27 = direct;
        float _e31 = mis_light_weight(_e22, c_12 * INV_PI, F32_INF);
        direct = _e27 + (_e22.radiance * metal::float3(c_12 * _e31));
    }
    metal::float3 _e43 = direct;
    return ((m.albedo * metal::float3(INV_PI)) * _e43) + secondary;
}

QuadLamp load_QuadLamp(
    uint offset_10,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_10 + 0u];
    uint _e11 = params[offset_10 + 1u];
    uint _e17 = params[offset_10 + 2u];
    uint _e24 = params[offset_10 + 3u];
    uint _e30 = params[offset_10 + 4u];
    return QuadLamp {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24), as_type<float>(_e30)};
}

bool after_nee_bounce(
    Ray ray_15
) {
    return metal::dot(ray_15.dir, ray_15.dir) > 2.0;
}

float bounce_pdf(
    Ray ray_16
) {
    float x_6 = metal::length(ray_16.dir) - MIS_BOUNCE_LENGTH;
    if (!((x_6 > -0.25))) {
        return 0.0;
    }
    return metal::exp(metal::max(x_6, 0.0) * 90.0) - 1.0;
}

metal::float3 quad_lamp_shade(
    QuadLamp m_1,
    Ray ray_17,
    Hit hit_2,
    thread uint& F32_INF
) {
    if (!(hit_2.front_face)) {
        return metal::float3(0.0);
    }
    metal::float3 le = m_1.color * metal::float3(m_1.intensity);
    bool _e11 = after_nee_bounce(ray_17);
    if (!(_e11)) {
        return le;
    }
    float _e13 = bounce_pdf(ray_17);
    float len = metal::length(ray_17.dir);
    float dist_5 = hit_2.t * len;
    float cos_l = metal::abs(metal::dot(hit_2.geometric_normal, ray_17.dir)) / len;
    float pl = (dist_5 * dist_5) / metal::max(cos_l * m_1.area, 0.000000000000000000000000000001);
    float _e29 = mis_weight(_e13, pl, F32_INF);
    return le * metal::float3(_e29);
}

SphereLamp load_SphereLamp(
    uint offset_11,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_11 + 0u];
    uint _e11 = params[offset_11 + 1u];
    uint _e17 = params[offset_11 + 2u];
    uint _e24 = params[offset_11 + 3u];
    uint _e30 = params[offset_11 + 4u];
    return SphereLamp {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24), as_type<float>(_e30)};
}

metal::float3 sphere_lamp_shade(
    SphereLamp m_2,
    Ray ray_18,
    Hit hit_3,
    thread uint& F32_INF
) {
    if (!(hit_3.front_face)) {
        return metal::float3(0.0);
    }
    float r2_3 = metal::max(m_2.radius * m_2.radius, 0.00000000000000000001);
    metal::float3 le_1 = m_2.color * metal::float3((m_2.intensity * INV_PI) / r2_3);
    bool _e19 = after_nee_bounce(ray_18);
    if (!(_e19)) {
        return le_1;
    }
    float _e21 = bounce_pdf(ray_18);
    metal::float3 center = hit_3.position - (hit_3.normal * metal::float3(m_2.radius));
    metal::float3 to_center_1 = center - ray_18.origin;
    float s2_1 = r2_3 / metal::max(metal::dot(to_center_1, to_center_1), r2_3);
    float one_minus_cos_max_1 = s2_1 / (1.0 + metal::sqrt(1.0 - s2_1));
    float pl_1 = 1.0 / metal::max(TAU * one_minus_cos_max_1, 0.000000000000000000000000000001);
    float _e45 = mis_weight(_e21, pl_1, F32_INF);
    return le_1 * metal::float3(_e45);
}

PathPbr load_PathPbr(
    uint offset_12,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_12 + 0u];
    uint _e11 = params[offset_12 + 1u];
    uint _e17 = params[offset_12 + 2u];
    uint _e24 = params[offset_12 + 3u];
    uint _e30 = params[offset_12 + 4u];
    uint _e36 = params[offset_12 + 8u];
    uint _e42 = params[offset_12 + 9u];
    uint _e48 = params[offset_12 + 10u];
    uint _e55 = params[offset_12 + 11u];
    return PathPbr {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), as_type<float>(_e24), as_type<float>(_e30), {}, metal::float3(as_type<float>(_e36), as_type<float>(_e42), as_type<float>(_e48)), _e55};
}

metal::float3 path_pbr_ng(
    Ray ray_19,
    Hit hit_4
) {
    return metal::faceforward(hit_4.geometric_normal, ray_19.dir, hit_4.geometric_normal);
}

metal::float3 path_pbr_n(
    Ray ray_20,
    Hit hit_5
) {
    metal::float3 _e2 = path_pbr_ng(ray_20, hit_5);
    metal::float3 n_14 = metal::faceforward(hit_5.normal, -(_e2), hit_5.normal);
    return (metal::dot(n_14, ray_20.dir) < 0.0) ? n_14 : _e2;
}

float pbr_alpha2_(
    float roughness
) {
    float a_9 = metal::max(metal::saturate(roughness) * metal::saturate(roughness), PBR_MIN_ALPHA);
    return a_9 * a_9;
}

metal::float3 pbr_fresnel(
    metal::float3 f0_,
    float c_2
) {
    float k_1 = 1.0 - metal::saturate(c_2);
    float k2_ = k_1 * k_1;
    return f0_ + ((metal::float3(1.0) - f0_) * metal::float3((k2_ * k2_) * k_1));
}

float pbr_ggx_d(
    float ndh,
    float a2_
) {
    float d_5 = ((ndh * ndh) * (a2_ - 1.0)) + 1.0;
    return (a2_ * INV_PI) / (d_5 * d_5);
}

float pbr_smith_v(
    float ndl,
    float ndv,
    float a2_1
) {
    float gv = ndl * metal::sqrt(((ndv * ndv) * (1.0 - a2_1)) + a2_1);
    float gl = ndv * metal::sqrt(((ndl * ndl) * (1.0 - a2_1)) + a2_1);
    return 0.5 / metal::max(gv + gl, 0.00000000000000000001);
}

metal::float3 pbr_eval(
    metal::float3 base_1,
    float metallic,
    float roughness_1,
    metal::float3 n_6,
    metal::float3 v_3,
    metal::float3 l_3
) {
    float ndv_3 = metal::dot(n_6, v_3);
    float ndl_1 = metal::dot(n_6, l_3);
    if (!((ndv_3 > 0.0)) || !((ndl_1 > 0.0))) {
        return metal::float3(0.0);
    }
    float metal_ = metal::saturate(metallic);
    float _e18 = pbr_alpha2_(roughness_1);
    metal::float3 f0_1 = metal::mix(metal::float3(0.04), base_1, metal::float3(metal_));
    metal::float3 _e24 = normalize_vec3f(v_3 + l_3);
    metal::float3 _e26 = pbr_fresnel(f0_1, metal::dot(v_3, _e24));
    float _e29 = pbr_ggx_d(metal::saturate(metal::dot(n_6, _e24)), _e18);
    float _e30 = pbr_smith_v(ndl_1, ndv_3, _e18);
    metal::float3 spec = _e26 * metal::float3(_e29 * _e30);
    metal::float3 diffuse = ((metal::float3(1.0) - _e26) * base_1) * metal::float3((1.0 - metal_) * INV_PI);
    return (diffuse + spec) * metal::float3(ndl_1);
}

float luminance(
    metal::float3 c_3
) {
    return metal::dot(c_3, metal::float3(0.2126, 0.7152, 0.0722));
}

float pbr_specular_chance(
    metal::float3 base_2,
    float metallic_1,
    float ndv_1
) {
    float metal_1 = metal::saturate(metallic_1);
    metal::float3 _e8 = pbr_fresnel(metal::mix(metal::float3(0.04), base_2, metal::float3(metal_1)), ndv_1);
    float _e9 = luminance(_e8);
    float _e18 = luminance((base_2 * metal::float3(1.0 - metal_1)) * (metal::float3(1.0) - _e8));
    if (!((_e18 > 0.0))) {
        return 1.0;
    }
    if (!((_e9 > 0.0))) {
        return 0.0;
    }
    return metal::min(metal::max(_e9 / (_e9 + _e18), 0.1), 0.9);
}

float pbr_specular_pdf(
    float ndh_1,
    float ndv_2,
    float a2_2
) {
    float _e3 = pbr_ggx_d(ndh_1, a2_2);
    return (_e3 * 0.5) / (ndv_2 + metal::sqrt(a2_2 + (((1.0 - a2_2) * ndv_2) * ndv_2)));
}

float pbr_pdf(
    metal::float3 base_3,
    float metallic_2,
    float roughness_2,
    metal::float3 n_7,
    metal::float3 v_4,
    metal::float3 l_4
) {
    float ndv_4 = metal::dot(n_7, v_4);
    float ndl_2 = metal::dot(n_7, l_4);
    if (!((ndv_4 > 0.0)) || !((ndl_2 > 0.0))) {
        return 0.0;
    }
    float _e16 = pbr_alpha2_(roughness_2);
    float _e17 = pbr_specular_chance(base_3, metallic_2, ndv_4);
    metal::float3 _e19 = normalize_vec3f(v_4 + l_4);
    float _e22 = pbr_specular_pdf(metal::saturate(metal::dot(n_7, _e19)), ndv_4, _e16);
    return (_e17 * _e22) + (((1.0 - _e17) * ndl_2) * INV_PI);
}

metal::float3 path_pbr_shade(
    PathPbr m_3,
    Ray ray_21,
    Hit hit_6,
    metal::float3 secondary_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 direct_1 = {};
    uint i_7 = {};
    float w = {};
    metal::float3 _e4 = path_pbr_n(ray_21, hit_6);
    metal::float3 _e6 = normalize_vec3f(ray_21.dir);
    metal::float3 v_7 = -(_e6);
    direct_1 = metal::float3(0.0);
    metal::float3 _e11 = path_pbr_ng(ray_21, hit_6);
    uint _e13 = light_count_query(frame);
    i_7 = 0u;
    uint2 loop_bound_6 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e49 = i_7;
            i_7 = _e49 + 1u;
        }
        loop_init_3 = false;
        uint _e15 = i_7;
        if (_e15 >= _e13) {
            break;
        }
        uint _e17 = i_7;
        LightSample _e19 = sample_light_above_deferred(_e17, hit_6.position, _e11, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
        if (metal::any(_e19.radiance > metal::float3(0.0))) {
            metal::float3 _e29 = pbr_eval(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
            w = 1.0;
            if (_e19.pdf > 0.0) {
                float _e40 = pbr_pdf(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
                float _e41 = mis_weight(_e19.pdf, _e40, F32_INF);
                w = _e41;
            }
            metal::float3 _e42 = direct_1;
            float _e45 = w;
            direct_1 = _e42 + ((_e19.radiance * _e29) * metal::float3(_e45));
        }
    }
    metal::float3 _e53 = direct_1;
    return (m_3.emissive + _e53) + secondary_1;
}

metal::float3 dispatch_closest_hit(
    uint type_id_4,
    uint offset_13,
    Ray ray_22,
    Hit hit_7,
    metal::float3 secondary_2,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(type_id_4) {
        case 0u: {
            PathDiffuse _e5 = load_PathDiffuse(offset_13, params, _buffer_sizes);
            metal::float3 _e6 = path_diffuse_shade(_e5, ray_22, hit_7, secondary_2, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
            return _e6;
        }
        case 1u: {
            QuadLamp _e7 = load_QuadLamp(offset_13, params, _buffer_sizes);
            metal::float3 _e8 = quad_lamp_shade(_e7, ray_22, hit_7, F32_INF);
            return _e8;
        }
        case 2u: {
            SphereLamp _e9 = load_SphereLamp(offset_13, params, _buffer_sizes);
            metal::float3 _e10 = sphere_lamp_shade(_e9, ray_22, hit_7, F32_INF);
            return _e10;
        }
        case 3u: {
            PathPbr _e11 = load_PathPbr(offset_13, params, _buffer_sizes);
            metal::float3 _e12 = path_pbr_shade(_e11, ray_22, hit_7, secondary_2, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
            return _e12;
        }
        default: {
            break;
        }
    }
    return metal::float3 {};
}

metal::float3 shade_direct(
    Ray ray_23,
    Candidate c_4,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuInstance inst_8 = instances[c_4.slot];
    Hit _e6 = finish_hit(ray_23, c_4, instances, triangles, hit_error, attributes, _buffer_sizes);
    metal::float3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_23, _e6, metal::float3(0.0), frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
    return _e11;
}

metal::float3 dispatch_medium(
    uint type_id_5,
    uint offset_14,
    Ray ray_24,
    float t_1,
    metal::float3 radiance
) {
    return metal::float3 {};
}

metal::float3 through_medium(
    Ray ray_25,
    float t_2,
    metal::float3 radiance_1,
    device type_9 const& instances,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if (ray_25.medium == 0u) {
        return radiance_1;
    }
    GpuInstance inst_9 = instances[ray_25.medium - 1u];
    if ((inst_9.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    metal::float3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_25, t_2, radiance_1);
    return _e21;
}

PathState start_path(
    Ray ray_26
) {
    return PathState {ray_26, metal::float3(1.0), metal::float3(0.0), true};
}

metal::float3 sample_cosine_hemisphere(
    metal::float3 n_8,
    metal::float2 u
) {
    float r_4 = metal::sqrt(u.x);
    float phi_1 = 6.2831855 * u.y;
    metal::float3 local = metal::float3(r_4 * metal::cos(phi_1), r_4 * metal::sin(phi_1), metal::sqrt(metal::max(1.0 - u.x, 0.0)));
    metal::float3x3 _e17 = orthonormal_basis(n_8);
    return _e17 * local;
}

metal::float3 mis_bounce_dir(
    metal::float3 dir_4,
    float pdf
) {
    float x_7 = metal::min(metal::log(1.0 + metal::max(pdf, 0.0)) * (1.0 / 90.0), 0.999);
    return dir_4 * metal::float3(MIS_BOUNCE_LENGTH + x_7);
}

void rt_spawn(
    metal::float3 dir_5,
    metal::float3 weight,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count
) {
    uint _e3 = spawn_count;
    if (_e3 < 1u) {
        spawn_dirs.inner[_e3] = dir_5;
        spawn_weights.inner[_e3] = weight;
        spawn_count = _e3 + 1u;
    }
}

void path_diffuse_rays(
    PathDiffuse m_4,
    Ray ray_27,
    Hit hit_8,
    thread type_4& scratch,
    thread uint& rng_state,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count
) {
    metal::float3 weight_1 = {};
    metal::float3 ng_1 = hit_8.front_face ? hit_8.geometric_normal : -(hit_8.geometric_normal);
    metal::float3 n_15 = metal::faceforward(hit_8.normal, -(ng_1), hit_8.normal);
    metal::float2 _e12 = rand2_next(scratch, rng_state);
    metal::float3 _e13 = sample_cosine_hemisphere(n_15, _e12);
    weight_1 = m_4.albedo;
    if (ray_27.depth >= m_4.roulette_depth) {
        float q_4 = metal::saturate(metal::max(m_4.albedo[0], metal::max(m_4.albedo[1], m_4.albedo[2])));
        float _e28 = rand_next(scratch, rng_state);
        if (_e28 >= q_4) {
            return;
        }
        weight_1 = m_4.albedo / metal::float3(q_4);
    }
    if (metal::dot(_e13, ng_1) > 0.0) {
        metal::float3 _e41 = mis_bounce_dir(_e13, metal::max(metal::dot(n_15, _e13), 0.0) * INV_PI);
        metal::float3 _e42 = weight_1;
        rt_spawn(_e41, _e42, spawn_dirs, spawn_weights, spawn_count);
    }
    return;
}

metal::float3 pbr_sample_vndf(
    metal::float3 ve,
    float alpha,
    metal::float2 u_1
) {
    metal::float3 t1_ = {};
    metal::float3 _e9 = normalize_vec3f(metal::float3(alpha * ve.x, alpha * ve.y, ve.z));
    float lensq = (_e9.x * _e9.x) + (_e9.y * _e9.y);
    t1_ = metal::float3(1.0, 0.0, 0.0);
    if (lensq > 0.0) {
        t1_ = metal::float3(-(_e9.y), _e9.x, 0.0) * metal::float3(metal::rsqrt(lensq));
    }
    metal::float3 _e32 = t1_;
    metal::float3 t2_ = metal::cross(_e9, _e32);
    float r_5 = metal::sqrt(u_1.x);
    float phi_2 = TAU * u_1.y;
    float p1_ = r_5 * metal::cos(phi_2);
    float s_8 = 0.5 * (1.0 + _e9.z);
    float p2_ = ((1.0 - s_8) * metal::sqrt(metal::max(1.0 - (p1_ * p1_), 0.0))) + ((s_8 * r_5) * metal::sin(phi_2));
    metal::float3 _e59 = t1_;
    metal::float3 nh = ((_e59 * metal::float3(p1_)) + (t2_ * metal::float3(p2_))) + (_e9 * metal::float3(metal::sqrt(metal::max((1.0 - (p1_ * p1_)) - (p2_ * p2_), 0.0))));
    metal::float3 _e84 = normalize_vec3f(metal::float3(alpha * nh.x, alpha * nh.y, metal::max(nh.z, 0.0)));
    return _e84;
}

PbrSample pbr_sample(
    metal::float3 base_4,
    float metallic_3,
    float roughness_3,
    metal::float3 n_9,
    metal::float3 v_5,
    metal::float3 u_2
) {
    metal::float3 l_5 = {};
    float ndv_5 = metal::dot(n_9, v_5);
    if (!((ndv_5 > 0.0))) {
        return PbrSample {n_9, metal::float3(0.0), 0.0};
    }
    float _e14 = pbr_specular_chance(base_4, metallic_3, ndv_5);
    l_5 = metal::float3(0.0);
    if (u_2.x < _e14) {
        metal::float3x3 _e20 = orthonormal_basis(n_9);
        float _e21 = pbr_alpha2_(roughness_3);
        metal::float3 _e26 = pbr_sample_vndf(metal::transpose(_e20) * v_5, metal::sqrt(_e21), u_2.yz);
        metal::float3 h_1 = _e20 * _e26;
        l_5 = metal::reflect(-(v_5), h_1);
    } else {
        metal::float3 _e31 = sample_cosine_hemisphere(n_9, u_2.yz);
        l_5 = _e31;
    }
    metal::float3 _e32 = l_5;
    float _e33 = pbr_pdf(base_4, metallic_3, roughness_3, n_9, v_5, _e32);
    if (!((_e33 > 0.0))) {
        metal::float3 _e37 = l_5;
        return PbrSample {_e37, metal::float3(0.0), 0.0};
    }
    metal::float3 _e42 = l_5;
    metal::float3 _e43 = pbr_eval(base_4, metallic_3, roughness_3, n_9, v_5, _e42);
    metal::float3 weight_5 = _e43 / metal::float3(_e33);
    metal::float3 _e46 = l_5;
    return PbrSample {_e46, weight_5, _e33};
}

void path_pbr_rays(
    PathPbr m_5,
    Ray ray_28,
    Hit hit_9,
    thread type_4& scratch,
    thread uint& rng_state,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count
) {
    metal::float3 weight_2 = {};
    metal::float3 _e3 = path_pbr_ng(ray_28, hit_9);
    metal::float3 _e4 = path_pbr_n(ray_28, hit_9);
    metal::float3 _e6 = normalize_vec3f(ray_28.dir);
    metal::float3 v_8 = -(_e6);
    float _e11 = rand_next(scratch, rng_state);
    metal::float2 _e12 = rand2_next(scratch, rng_state);
    PbrSample _e14 = pbr_sample(m_5.base_color, m_5.metallic, m_5.roughness, _e4, v_8, metal::float3(_e11, _e12));
    if (!((_e14.pdf > 0.0)) || !((metal::dot(_e14.dir, _e3) > 0.0))) {
        return;
    }
    weight_2 = _e14.weight;
    if (ray_28.depth >= m_5.roulette_depth) {
        float _e31 = weight_2.x;
        float _e33 = weight_2.y;
        float _e35 = weight_2.z;
        float q_5 = metal::min(metal::max(_e31, metal::max(_e33, _e35)), 1.0);
        float _e40 = rand_next(scratch, rng_state);
        if (!((_e40 < q_5))) {
            return;
        }
        metal::float3 _e43 = weight_2;
        weight_2 = _e43 / metal::float3(q_5);
    }
    metal::float3 _e48 = mis_bounce_dir(_e14.dir, _e14.pdf);
    metal::float3 _e49 = weight_2;
    rt_spawn(_e48, _e49, spawn_dirs, spawn_weights, spawn_count);
    return;
}

void dispatch_secondary_rays(
    uint type_id_6,
    uint offset_15,
    Ray ray_29,
    Hit hit_10,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(type_id_6) {
        case 0u: {
            PathDiffuse _e4 = load_PathDiffuse(offset_15, params, _buffer_sizes);
            path_diffuse_rays(_e4, ray_29, hit_10, scratch, rng_state, spawn_dirs, spawn_weights, spawn_count);
            return;
        }
        case 3u: {
            PathPbr _e5 = load_PathPbr(offset_15, params, _buffer_sizes);
            path_pbr_rays(_e5, ray_29, hit_10, scratch, rng_state, spawn_dirs, spawn_weights, spawn_count);
            return;
        }
        default: {
            break;
        }
    }
    return;
}

metal::float3 spawn_origin_at(
    metal::float3 position_8,
    metal::float3 normal_9,
    float error_1,
    metal::float3 dir_6
) {
    metal::float3 n_10 = {};
    n_10 = normal_9;
    metal::float3 _e5 = n_10;
    if (metal::dot(dir_6, _e5) < 0.0) {
        metal::float3 _e9 = n_10;
        n_10 = -(_e9);
    }
    metal::float3 _e11 = n_10;
    metal::float3 _e12 = offset_origin(position_8, _e11, error_1);
    return _e12;
}

metal::float3 spawn_origin(
    Hit hit_11,
    float error_2,
    metal::float3 dir_7
) {
    metal::float3 _e5 = spawn_origin_at(hit_11.position, hit_11.geometric_normal, error_2, dir_7);
    return _e5;
}

PathState path_step(
    PathState s_2,
    Candidate c_5,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    PathState out = {};
    bool spawned = {};
    metal::float3 dir_8 = {};
    metal::float3 weight_3 = {};
    metal::float3 beta = {};
    Ray ray_30 = s_2.ray;
    out = s_2;
    out.live = false;
    if (c_5.slot == NO_HIT) {
        hit_error = 0.0;
        metal::float3 _e14 = miss(ray_30, frame, params, _buffer_sizes);
        out.radiance = s_2.radiance + (s_2.beta * _e14);
        PathState _e17 = out;
        return _e17;
    }
    GpuInstance inst_10 = instances[c_5.slot];
    Hit _e22 = finish_hit(ray_30, c_5, instances, triangles, hit_error, attributes, _buffer_sizes);
    float error_4 = hit_error;
    spawned = false;
    dir_8 = metal::float3(0.0);
    weight_3 = metal::float3(0.0);
    if (((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u) && (s_2.ray.depth < MAX_DEPTH)) {
        spawn_count = 0u;
        dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, ray_30, _e22, scratch, rng_state, params, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        uint _e47 = spawn_count;
        if (metal::min(_e47, 1u) > 0u) {
            spawned = true;
            metal::float3 _e56 = spawn_dirs.inner[0u];
            dir_8 = _e56;
            metal::float3 _e60 = spawn_weights.inner[0u];
            weight_3 = _e60;
        }
    }
    metal::float3 _e68 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, ray_30, _e22, metal::float3(0.0), frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, ray_count, counters, _buffer_sizes);
    out.radiance = s_2.radiance + (s_2.beta * _e68);
    bool _e71 = spawned;
    if (!(_e71)) {
        PathState _e73 = out;
        return _e73;
    }
    metal::float3 _e75 = weight_3;
    beta = s_2.beta * _e75;
    float _e79 = beta.x;
    float _e81 = beta.y;
    float _e83 = beta.z;
    float q_6 = metal::max(_e79, metal::max(_e81, _e83));
    if (!((q_6 > 0.0))) {
        PathState _e89 = out;
        return _e89;
    }
    if (((ROULETTE_DEPTH > 0u) && ((s_2.ray.depth + 1u) >= ROULETTE_DEPTH)) && (q_6 < ROULETTE_THROUGHPUT)) {
        float survive = q_6 / ROULETTE_THROUGHPUT;
        float _e104 = rand_next(scratch, rng_state);
        if (_e104 >= survive) {
            PathState _e106 = out;
            return _e106;
        }
        metal::float3 _e107 = beta;
        beta = _e107 / metal::float3(survive);
    }
    metal::float3 _e111 = beta;
    out.beta = _e111;
    metal::float3 _e113 = dir_8;
    metal::float3 _e114 = spawn_origin(_e22, error_4, _e113);
    metal::float3 _e116 = dir_8;
    uint _e118 = F32_INF;
    out.ray = Ray {_e114, 0.0, _e116, as_type<float>(_e118), s_2.ray.depth + 1u, RAY_SECONDARY, s_2.ray.medium};
    out.live = true;
    PathState _e128 = out;
    return _e128;
}

metal::float3 trace_path(
    Ray camera_ray,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    PathState s_3 = {};
    PathState _e1 = start_path(camera_ray);
    s_3 = _e1;
    uint2 loop_bound_7 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        PathState _e3 = s_3;
        Ray _e5 = s_3.ray;
        Candidate _e7 = intersect_scene(_e5, false, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, ray_count, _buffer_sizes);
        PathState _e8 = path_step(_e3, _e7, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        s_3 = _e8;
        bool _e10 = s_3.live;
        if (!(_e10)) {
            metal::float3 _e13 = s_3.radiance;
            return _e13;
        }
    }
    return metal::float3 {};
}

metal::float3 trace(
    Ray camera_ray_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread type_13& traversal_stack,
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 radiance_2 = {};
    float t_3 = {};
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray_1, false, frame, params, F32_INF, instances, nodes, triangles, traversal_stack, ray_count, _buffer_sizes);
        radiance_2 = metal::float3(0.0);
        uint _e9 = F32_INF;
        t_3 = as_type<float>(_e9);
        if (_e4.slot == NO_HIT) {
            hit_error = 0.0;
            metal::float3 _e17 = miss(camera_ray_1, frame, params, _buffer_sizes);
            radiance_2 = _e17;
        } else {
            metal::float3 _e18 = shade_direct(camera_ray_1, _e4, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, _buffer_sizes);
            radiance_2 = _e18;
            t_3 = _e4.t;
        }
        float _e20 = t_3;
        metal::float3 _e21 = radiance_2;
        metal::float3 _e22 = through_medium(camera_ray_1, _e20, _e21, instances, _buffer_sizes);
        return _e22;
    }
    metal::float3 _e23 = trace_path(camera_ray_1, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
    return _e23;
}

metal::bool3 is_finite_vec3f(
    metal::float3 x_4
) {
    return (as_type<metal::uint3>(x_4) & metal::uint3(2147483647u)) < metal::uint3(2139095040u);
}

metal::float3 finite_or_zero(
    metal::float3 c_6
) {
    metal::bool3 _e3 = is_finite_vec3f(c_6);
    return metal::select(metal::float3(0.0), c_6, _e3);
}

PassSum add_sample(
    PassSum p_7,
    metal::float3 c_7,
    uint s_4,
    uint index,
    uint first_pass,
    uint per_pass,
    thread uint& ray_count,
    device type_17& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum next = {};
    next = p_7;
    metal::bool3 _e7 = is_finite_vec3f(c_7);
    if (metal::all(_e7)) {
        metal::float3 _e10 = next.sum;
        next.sum = _e10 + c_7;
    } else {
        metal::float3 _e13 = next.sum;
        metal::float3 _e14 = finite_or_zero(c_7);
        next.sum = _e13 + _e14;
        uint _e17 = next.bad;
        next.bad = _e17 + 1u;
    }
    uint _e22 = rem_u32_(s_4 + 1u, per_pass);
    if (_e22 != 0u) {
        PassSum _e25 = next;
        return _e25;
    }
    uint _e27 = ray_count;
    metal::atomic_fetch_add_explicit(&counters[1], _e27, metal::memory_order_relaxed);
    ray_count = 0u;
    uint _e31 = div_u32_(s_4, per_pass);
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
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum sums = {};
    uint s_5 = {};
    FrameUniforms frame_6 = frame;
    TileParams tile_2 = tile;
    uint index_1 = (pixel_5.y * tile_2.image_size.x) + pixel_5.x;
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = tile_2.frame * per_pass_1;
    uint count_2 = per_pass_1 * metal::max(frame_6.passes_per_dispatch, 1u);
    sums = PassSum {metal::float3(0.0), 0u};
    s_5 = 0u;
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e35 = s_5;
            s_5 = _e35 + 1u;
        }
        loop_init_4 = false;
        uint _e25 = s_5;
        if (_e25 >= count_2) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_5;
        Ray _e30 = sample_camera_ray(pixel_5, first_1 + _e28, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, _buffer_sizes);
        metal::float3 _e31 = trace(_e30, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        uint _e32 = s_5;
        PassSum _e34 = add_sample(_e27, _e31, _e32, index_1, tile_2.frame, per_pass_1, ray_count, counters, accum, _buffer_sizes);
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
    thread float& hit_error,
    device type_15 const& attributes,
    thread uint& ray_count,
    device type_17& counters,
    thread type_19& spawn_dirs,
    thread type_19& spawn_weights,
    thread uint& spawn_count,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    TileParams tile_3 = tile;
    metal::uint2 _e3 = scattered_local(id_1, tile);
    if (metal::any(_e3 >= tile_3.extent)) {
        return;
    }
    render_pixel(tile_3.origin + _e3, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, spawn_dirs, spawn_weights, spawn_count, accum, _buffer_sizes);
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
, device type_15 const& attributes [[buffer(5)]]
, device type_17& counters [[buffer(9)]]
, device type_12& accum [[buffer(8)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(10)]]
) {
    type_4 scratch = {};
    uint rng_state = {};
    uint F32_INF = 2139095040u;
    type_13 traversal_stack = {};
    float hit_error = {};
    uint ray_count = {};
    type_19 spawn_dirs = {};
    type_19 spawn_weights = {};
    uint spawn_count = {};
    render_invocation(metal::uint2(gid.x, gid.y), tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, traversal_stack, hit_error, attributes, ray_count, counters, spawn_dirs, spawn_weights, spawn_count, accum, _buffer_sizes);
    return;
}
