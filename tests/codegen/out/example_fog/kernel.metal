// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size4;
    uint size6;
    uint size7;
    uint size8;
    uint size10;
    uint size16;
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
    uint inner[15];
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
typedef metal::uint4 type_14[1];
struct Fog {
    float density;
    char _pad1[12];
    metal::float3 albedo;
};
struct type_15 {
    uint inner[74];
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
struct type_16 {
    metal::float3 inner[1];
};
struct Frame {
    Ray ray;
    Hit hit;
    float error;
    uint slot;
    char _pad4[8];
    metal::float3 sum;
    type_16 dirs;
    type_16 weights;
    uint count;
    uint next;
    char _pad9[8];
};
struct type_17 {
    Frame inner[3];
};
typedef metal::atomic_uint type_20[1];
constant uint WORKGROUP_WIDTH = 8u;
constant uint WORKGROUP_HEIGHT = 8u;
constant uint NO_HIT = 4294967295u;
constant uint SCATTER = 1000003u;
constant uint SCRATCH_RNG_INDEX = 12u;
constant uint SCRATCH_RNG_SEED = 13u;
constant uint HALF_WORD_BITS = 16u;
constant uint RAY_CAMERA = 0u;
constant bool HAS_MEDIA = true;
constant uint MEDIUM_ENTRY_STRIDE = 1u;
constant uint MESH_GEOMETRY = 4294967295u;
constant uint NODE_LEAF_BIT = 2147483648u;
constant uint NODE_COUNT_SHIFT = 27u;
constant uint NODE_COUNT_MASK = 15u;
constant uint NODE_FIRST_MASK = 134217727u;
constant bool HAS_ANY_HIT = true;
constant uint FLAG_ANY_HIT = 1u;
constant float POINT_ERROR = 0.0000019073486;
constant float GAMMA_1_ = 0.00000005960465;
constant float GAMMA_6_ = 0.0000003576281;
constant float GAMMA_4_ = 0.00000023841864;
constant uint RAY_SHADOW = 2u;
constant uint SCRATCH_ABSORB = 5u;
constant uint SCRATCH_ABSORB_T = 6u;
constant bool HAS_ABSORB = true;
constant uint SCRATCH_DEPTH = 7u;
constant uint SCRATCH_NET = 8u;
constant uint SCRATCH_DENSITY_MAX = 9u;
constant uint BLAS_STACK = 64u;
constant uint TLAS_STACK = 10u;
constant bool HAS_SECONDARY_RAYS = true;
constant bool HAS_BACKGROUND = false;
constant uint SCRATCH_MEDIUM = 10u;
constant uint LIGHT_ENTRY_STRIDE = 2u;
constant uint SCRATCH_SHADOW_MODE = 14u;
constant uint SHADOW_UNOCCLUDED = 1u;
constant uint SHADOW_ABOVE = 2u;
constant float LIGHT_ERROR = 0.00000047683716;
constant float INV_PI = 0.31830987;
constant uint FLAG_MEDIUM = 4u;
constant uint SHADOW_TRACED = 0u;
constant float PI = 3.1415927;
constant uint FLAG_SECONDARY_RAYS = 2u;
constant uint MAX_DEPTH = 3u;
constant uint STACK_SIZE = 3u;
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
    uint d_1 = rng_state;
    rng_state = d_1 + 1u;
    uint _e10 = scratch.inner[metal::min(SCRATCH_RNG_SEED, 14u)];
    uint _e16 = pcg_hash(_e10 ^ ((d_1 >> 1u) * 2654435769u));
    uint _e22 = scratch.inner[metal::min(SCRATCH_RNG_INDEX, 14u)];
    uint _e24 = laine_karras(metal::reverse_bits(_e22), _e16);
    uint i_8 = metal::reverse_bits(_e24);
    x_2 = i_8;
    if ((d_1 & 1u) != 0u) {
        uint _e31 = sobol_second_reversed(i_8);
        x_2 = _e31;
    }
    uint scramble = _e16 ^ (((2654435769u * (1u + (d_1 & 1u))) + (_e16 << 6u)) + (_e16 >> 2u));
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
    metal::float4 o_1 = metal::float4(ray.origin, 1.0);
    metal::float4 d_2 = metal::float4(ray.dir, 0.0);
    r.origin = metal::float3(metal::dot(inst.world_to_object_0_, o_1), metal::dot(inst.world_to_object_1_, o_1), metal::dot(inst.world_to_object_2_, o_1));
    r.dir = metal::float3(metal::dot(inst.world_to_object_0_, d_2), metal::dot(inst.world_to_object_1_, d_2), metal::dot(inst.world_to_object_2_, d_2));
    Ray _e25 = r;
    return _e25;
}

TriangleRay prepare_triangle_ray(
    Ray ray_1
) {
    metal::float3 d_3 = metal::select(ray_1.dir, metal::float3(0.0), metal::abs(ray_1.dir) < metal::float3(0.000000000000000000000000000000000000011754944));
    metal::float3 ad = metal::abs(d_3);
    bool y_gt = ad.y > ad.x;
    uint kz = (ad.z > (y_gt ? ad.y : ad.x)) ? 2u : (y_gt ? 1u : 0u);
    uint kx0_ = (kz == 2u) ? 0u : (kz + 1u);
    uint ky0_ = (kz >= 1u) ? (kz - 1u) : (kz + 2u);
    float dz = d_3[metal::min(kz, 2u)];
    bool flip = dz < 0.0;
    uint kx = flip ? ky0_ : kx0_;
    uint ky = flip ? kx0_ : ky0_;
    metal::uint3 inf_bits = metal::uint3(2139095040u);
    bool finite = metal::all((as_type<metal::uint3>(ray_1.origin) & metal::uint3(2147483647u)) < inf_bits) && metal::all((as_type<metal::uint3>(d_3) & metal::uint3(2147483647u)) < inf_bits);
    return TriangleRay {ray_1.origin, kx, ky, kz, {}, metal::float3(d_3[metal::min(kx, 2u)] / dz, d_3[metal::min(ky, 2u)] / dz, 1.0 / dz), finite && !((dz == 0.0))};
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
    metal::float3 d_4 = ray_2.dir * metal::float3(as_type<float>((254u - e) << 23u));
    float unit = as_type<float>(e << 23u);
    metal::float3 floor = metal::float3(0.0000000000009094947);
    metal::float3 s_4 = metal::select(metal::float3(1.0), metal::float3(-1.0), d_4 < metal::float3(0.0));
    metal::float3 inv = metal::float3(1.0) / metal::select(d_4, s_4 * floor, metal::abs(d_4) < floor);
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
    metal::float3 a_4 = _e9.xyz - r_1.origin;
    metal::float4 _e19 = triangles[(slot * 3u) + 1u];
    metal::float3 b_6 = _e19.xyz - r_1.origin;
    metal::float4 _e29 = triangles[(slot * 3u) + 2u];
    metal::float3 c_5 = _e29.xyz - r_1.origin;
    float ax = a_4[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * a_4[metal::min(r_1.kz, 2u)]);
    float ay = a_4[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * a_4[metal::min(r_1.kz, 2u)]);
    float bx = b_6[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * b_6[metal::min(r_1.kz, 2u)]);
    float by = b_6[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * b_6[metal::min(r_1.kz, 2u)]);
    float cx = c_5[metal::min(r_1.kx, 2u)] - (r_1.shear[0] * c_5[metal::min(r_1.kz, 2u)]);
    float cy = c_5[metal::min(r_1.ky, 2u)] - (r_1.shear[1] * c_5[metal::min(r_1.kz, 2u)]);
    float u = (cx * by) - (cy * bx);
    float v_2 = (ax * cy) - (ay * cx);
    float w = (bx * ay) - (by * ax);
    bool outside = (((u < 0.0) || (v_2 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_2 > 0.0)) || (w > 0.0));
    float det = (u + v_2) + w;
    float scaled = ((u * (r_1.shear[2] * a_4[metal::min(r_1.kz, 2u)])) + (v_2 * (r_1.shear[2] * b_6[metal::min(r_1.kz, 2u)]))) + (w * (r_1.shear[2] * c_5[metal::min(r_1.kz, 2u)]));
    if (occlusion) {
        float st = (det < 0.0) ? -(scaled) : scaled;
        float ad_1 = metal::abs(det);
        bool hit_11 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1));
        uint _e178 = F32_INF;
        return hit_11 ? metal::float3(tmin, 0.0, 0.0) : metal::float3(as_type<float>(_e178), 0.0, 0.0);
    }
    float rcp = 1.0 / det;
    float t_5 = scaled * rcp;
    bool hit_12 = (((r_1.valid && !(outside)) && !((det == 0.0))) && (t_5 >= tmin)) && (t_5 <= tmax_1);
    uint _e202 = F32_INF;
    return hit_12 ? metal::float3(t_5, v_2 * rcp, w * rcp) : metal::float3(as_type<float>(_e202), 0.0, 0.0);
}

float point_error(
    metal::float3 origin_1,
    metal::float3 along
) {
    metal::float3 a_5 = metal::abs(origin_1) + metal::abs(along);
    return POINT_ERROR * metal::max(metal::max(a_5.x, a_5.y), a_5.z);
}

Triangle load_triangle(
    uint slot_1,
    device type_12 const& triangles,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 v0_1 = triangles[slot_1 * 3u];
    metal::float4 v1_ = triangles[(slot_1 * 3u) + 1u];
    metal::float4 v2_ = triangles[(slot_1 * 3u) + 2u];
    return Triangle {v0_1.xyz, v1_.xyz, v2_.xyz};
}

metal::float3 point_to_world(
    GpuInstance inst_1,
    metal::float3 p
) {
    metal::float4 q_1 = metal::float4(p, 1.0);
    return metal::float3(metal::dot(inst_1.object_to_world_0_, q_1), metal::dot(inst_1.object_to_world_1_, q_1), metal::dot(inst_1.object_to_world_2_, q_1));
}

float mesh_error(
    GpuInstance inst_2,
    metal::float3 v0_,
    metal::float3 db1_,
    metal::float3 db2_,
    metal::float3 p_1
) {
    metal::float3 obj = (metal::float3(GAMMA_1_) * metal::abs(v0_)) + (metal::float3(GAMMA_6_) * (metal::abs(db1_) + metal::abs(db2_)));
    metal::float4 q_2 = metal::float4(metal::abs(p_1), 1.0);
    metal::float4 r0_ = metal::abs(inst_2.object_to_world_0_);
    metal::float4 r1_ = metal::abs(inst_2.object_to_world_1_);
    metal::float4 r2_ = metal::abs(inst_2.object_to_world_2_);
    metal::float3 rounding = metal::float3(GAMMA_4_) * metal::float3(metal::dot(r0_, q_2), metal::dot(r1_, q_2), metal::dot(r2_, q_2));
    metal::float3 carried = metal::float3(1.0 + GAMMA_4_) * metal::float3(metal::dot(r0_.xyz, obj), metal::dot(r1_.xyz, obj), metal::dot(r2_.xyz, obj));
    metal::float3 e_1 = rounding + carried;
    return metal::max(metal::max(e_1.x, e_1.y), e_1.z);
}

metal::float3 decode_octahedral(
    uint bits
) {
    metal::float3 n = {};
    metal::float2 e_2 = metal::unpack_snorm2x16_to_float(bits);
    n = metal::float3(e_2.x, e_2.y, (1.0 - metal::abs(e_2.x)) - metal::abs(e_2.y));
    float _e14 = n.z;
    if (_e14 < 0.0) {
        metal::float3 _e21 = n;
        metal::float2 s_5 = metal::select(metal::float2(-1.0), metal::float2(1.0), _e21.xy >= metal::float2(0.0));
        metal::float3 _e29 = n;
        metal::float2 xy = (metal::float2(1.0) - metal::abs(_e29.yx)) * s_5;
        float _e37 = n.z;
        n = metal::float3(xy.x, xy.y, _e37);
    }
    metal::float3 _e39 = n;
    metal::float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

metal::float3 normal_to_world(
    GpuInstance inst_3,
    metal::float3 n_1
) {
    metal::float3 w_1 = ((inst_3.world_to_object_0_.xyz * metal::float3(n_1.x)) + (inst_3.world_to_object_1_.xyz * metal::float3(n_1.y))) + (inst_3.world_to_object_2_.xyz * metal::float3(n_1.z));
    metal::float3 _e19 = normalize_vec3f(w_1);
    return _e19;
}

Hit finish_hit(
    Ray ray_3,
    Candidate c,
    device type_9 const& instances,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Hit hit = {};
    metal::float3 n_geo = {};
    metal::float3 n_shade = {};
    GpuInstance inst_6 = instances[c.slot];
    float _e11 = point_error(ray_3.origin, ray_3.dir * metal::float3(c.t));
    hit_error = _e11;
    hit = Hit {ray_3.origin + (ray_3.dir * metal::float3(c.t)), c.t, metal::float3(0.0, 1.0, 0.0), metal::float3(0.0, 1.0, 0.0), c.uv, true, {}, inst_6.object, c.primitive};
    n_geo = c.normal;
    n_shade = c.normal;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        Triangle _e42 = load_triangle(c.primitive, triangles, _buffer_sizes);
        metal::float2 b_7 = c.uv;
        float w_2 = (1.0 - c.uv.x) - c.uv.y;
        metal::float3 e1_ = _e42.v1_ - _e42.v0_;
        metal::float3 e2_ = _e42.v2_ - _e42.v0_;
        metal::float3 p_7 = _e42.v0_ + ((e1_ * metal::float3(c.uv.x)) + (e2_ * metal::float3(c.uv.y)));
        metal::float3 _e65 = point_to_world(inst_6, p_7);
        hit.position = _e65;
        float _e73 = mesh_error(inst_6, _e42.v0_, e1_ * metal::float3(c.uv.x), e2_ * metal::float3(c.uv.y), p_7);
        hit_error = _e73;
        n_geo = metal::cross(e1_, e2_);
        metal::uint4 a0_ = attributes[c.primitive * 2u];
        metal::uint4 a1_ = attributes[(c.primitive * 2u) + 1u];
        metal::float3 _e91 = decode_octahedral(a0_.x);
        metal::float3 _e95 = decode_octahedral(a0_.y);
        metal::float3 _e101 = decode_octahedral(a0_.z);
        n_shade = ((_e91 * metal::float3(w_2)) + (_e95 * metal::float3(c.uv.x))) + (_e101 * metal::float3(c.uv.y));
        metal::float3 _e106 = n_shade;
        metal::float3 _e107 = n_shade;
        if (metal::dot(_e106, _e107) < 0.000000000001) {
            metal::float3 _e111 = n_geo;
            n_shade = _e111;
        }
        metal::float2 uv0_ = float2(as_type<half2>(a0_.w));
        metal::float2 uv1_ = float2(as_type<half2>(a1_.x));
        metal::float2 uv2_ = float2(as_type<half2>(a1_.y));
        hit.uv = ((uv0_ * metal::float2(w_2)) + (uv1_ * metal::float2(c.uv.x))) + (uv2_ * metal::float2(c.uv.y));
        metal::float4 _e135 = triangles[c.primitive * 3u];
        hit.primitive = as_type<uint>(_e135.w);
    }
    metal::float3 _e139 = n_geo;
    metal::float3 _e140 = normal_to_world(inst_6, _e139);
    hit.geometric_normal = _e140;
    metal::float3 _e142 = n_shade;
    metal::float3 _e143 = normal_to_world(inst_6, _e142);
    hit.normal = _e143;
    metal::float3 _e147 = hit.geometric_normal;
    hit.front_face = metal::dot(ray_3.dir, _e147) < 0.0;
    Hit _e151 = hit;
    return _e151;
}

Fog load_Fog(
    uint offset_2,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_2 + 0u];
    uint _e11 = params[offset_2 + 4u];
    uint _e17 = params[offset_2 + 5u];
    uint _e23 = params[offset_2 + 6u];
    return Fog {as_type<float>(_e5), {}, metal::float3(as_type<float>(_e11), as_type<float>(_e17), as_type<float>(_e23))};
}

bool is_finite_f32_(
    float x_3
) {
    return (as_type<uint>(x_3) & 2147483647u) < 2139095040u;
}

void absorb_query(
    float density,
    thread type_4& scratch
) {
    float sigma = {};
    if (!(HAS_ABSORB)) {
        return;
    }
    uint side = scratch.inner[metal::min(SCRATCH_ABSORB, 14u)];
    if (side == 0u) {
        return;
    }
    sigma = 0.0;
    bool _e13 = is_finite_f32_(density);
    if (_e13 && (density > 0.0)) {
        sigma = density;
    }
    uint _e22 = scratch.inner[metal::min(SCRATCH_ABSORB_T, 14u)];
    float t_6 = as_type<float>(_e22);
    float _e24 = sigma;
    float _e25 = sigma;
    float s_6 = (side == 2u) ? -(_e25) : _e24;
    uint _e35 = scratch.inner[metal::min(SCRATCH_DEPTH, 14u)];
    float depth_2 = as_type<float>(_e35) - (s_6 * t_6);
    scratch.inner[metal::min(SCRATCH_DEPTH, 14u)] = as_type<uint>(depth_2);
    uint _e50 = scratch.inner[metal::min(SCRATCH_NET, 14u)];
    float net = as_type<float>(_e50) + s_6;
    scratch.inner[metal::min(SCRATCH_NET, 14u)] = as_type<uint>(net);
    uint _e64 = scratch.inner[metal::min(SCRATCH_DENSITY_MAX, 14u)];
    float _e66 = sigma;
    float most = metal::max(as_type<float>(_e64), _e66);
    scratch.inner[metal::min(SCRATCH_DENSITY_MAX, 14u)] = as_type<uint>(most);
    return;
}

bool fog_any_hit(
    Fog m,
    Ray ray_4,
    Hit hit_1,
    thread type_4& scratch
) {
    absorb_query(m.density, scratch);
    return ray_4.kind != RAY_SHADOW;
}

bool dispatch_any_hit(
    uint type_id_1,
    uint offset_3,
    Ray ray_5,
    Hit hit_2,
    thread type_4& scratch,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    Fog _e3 = load_Fog(offset_3, params, _buffer_sizes);
    bool _e4 = fog_any_hit(_e3, ray_5, hit_2, scratch);
    return _e4;
}

bool accept(
    GpuInstance inst_4,
    Ray ray_6,
    Candidate c_1,
    thread type_4& scratch,
    device type_5 const& params,
    device type_9 const& instances,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    if ((inst_4.flags & FLAG_ANY_HIT) != 0u) {
        float shaded = hit_error;
        Hit _e10 = finish_hit(ray_6, c_1, instances, triangles, hit_error, attributes, _buffer_sizes);
        hit_error = shaded;
        if (ray_6.kind == RAY_SHADOW) {
            scratch.inner[metal::min(SCRATCH_ABSORB, 14u)] = _e10.front_face ? 1u : 2u;
            scratch.inner[metal::min(SCRATCH_ABSORB_T, 14u)] = as_type<uint>(c_1.t * metal::length(ray_6.dir));
        }
        bool _e36 = dispatch_any_hit(inst_4.material_type, inst_4.material_offset, ray_6, _e10, scratch, params, _buffer_sizes);
        scratch.inner[metal::min(SCRATCH_ABSORB, 14u)] = 0u;
        return _e36;
    }
    return true;
}

metal::uint3 node_box_lo(
    metal::uint3 p_2
) {
    return metal::uint3(p_2.x & 65535u, p_2.x >> 16u, p_2.y & 65535u);
}

metal::uint3 node_box_hi(
    metal::uint3 p_3
) {
    return metal::uint3(p_3.y >> 16u, p_3.z & 65535u, p_3.z >> 16u);
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
    metal::float2 e_3 = metal::select(near_2.xy, near_2.yz, near_2.xy < near_2.yz);
    float enter = (e_3.x < e_3.y) ? e_3.y : e_3.x;
    metal::float2 x_6 = metal::select(far_2.xy, far_2.yz, far_2.yz < far_2.xy);
    float exit = (x_6.y < x_6.x) ? x_6.y : x_6.x;
    float enter_t = (enter < b_4.tmin) ? b_4.tmin : enter;
    float exit_t = (tmax_2 < exit) ? tmax_2 : exit;
    if (enter_t <= exit_t) {
        return enter_t;
    }
    uint _e49 = F32_INF;
    return as_type<float>(_e49);
}

metal::float2 children_entry(
    GpuNode n_2,
    BoxRay b_5,
    float tmax_3,
    thread uint& F32_INF
) {
    metal::uint3 lq = as_type<metal::uint3>(n_2.min);
    metal::uint3 rq = as_type<metal::uint3>(n_2.max);
    float t_7 = tmax_3 * b_5.unit;
    metal::uint3 _e9 = node_box_lo(lq);
    metal::uint3 _e11 = node_box_hi(lq);
    float _e13 = slab_in_frame(static_cast<metal::float3>(_e9), static_cast<metal::float3>(_e11), b_5, t_7, F32_INF);
    metal::uint3 _e14 = node_box_lo(rq);
    metal::uint3 _e16 = node_box_hi(rq);
    float _e18 = slab_in_frame(static_cast<metal::float3>(_e14), static_cast<metal::float3>(_e16), b_5, t_7, F32_INF);
    return metal::float2(_e13, _e18);
}

metal::uint2 pop(
    uint base,
    uint sp,
    thread type_15& traversal_stack
) {
    if (sp == 0u) {
        return metal::uint2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack.inner[metal::min((base + sp) - 1u, 73u)];
    return metal::uint2(_e14, sp - 1u);
}

Candidate intersect_mesh(
    GpuInstance inst_5,
    uint slot_2,
    Ray world_ray,
    Ray ray_7,
    Candidate best_in,
    bool shadow,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best = {};
    uint sp_1 = {};
    uint child = {};
    uint k = {};
    uint near = {};
    uint far = {};
    best = best_in;
    TriangleRay _e7 = prepare_triangle_ray(ray_7);
    uint base_1 = inst_5.blas_root;
    GpuNode header_2 = nodes[base_1];
    BoxRay _e12 = box_ray(header_2, ray_7);
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
                uint prim = (inst_5.triangle_offset + first) + _e38;
                float _e42 = best.t;
                metal::float3 _e46 = hit_triangle(_e7, prim, ray_7.tmin, _e42, shadow && !(HAS_ANY_HIT), F32_INF, triangles, _buffer_sizes);
                uint _e49 = F32_INF;
                if (_e46.x < as_type<float>(_e49)) {
                    metal::float4 _e58 = triangles[(prim * 3u) + 1u];
                    uint tag = as_type<uint>(_e58.w);
                    uint owner = (tag != 0u) ? ((inst_5.object + tag) - 1u) : slot_2;
                    Candidate c_6 = Candidate {_e46.x, owner, prim, {}, _e46.yz, {}, metal::float3(0.0)};
                    bool _e73 = accept(inst_5, world_ray, c_6, scratch, params, instances, triangles, hit_error, attributes, _buffer_sizes);
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
            GpuNode n_6 = nodes[base_1 + _e78];
            float _e84 = best.t;
            metal::float2 _e85 = children_entry(n_6, _e12, _e84, F32_INF);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if ((tl < as_type<float>(_e89)) && (tr < as_type<float>(_e93))) {
                near = n_6.a;
                far = n_6.b;
                if ((tr < tl) != shadow) {
                    near = n_6.b;
                    far = n_6.a;
                }
                uint _e105 = sp_1;
                if (_e105 < BLAS_STACK) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack.inner[metal::min(TLAS_STACK + _e109, 73u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = _e116 + 1u;
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if (tl < as_type<float>(_e121)) {
                child = n_6.a;
                continue;
            }
            uint _e126 = F32_INF;
            if (tr < as_type<float>(_e126)) {
                child = n_6.b;
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

Candidate intersect_object(
    uint slot_3,
    Ray ray_8,
    Candidate best_1,
    bool shadow_1,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray r_2 = {};
    GpuInstance inst_7 = instances[slot_3];
    Ray _e7 = to_object(inst_7, ray_8);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_7.geometry_type == MESH_GEOMETRY) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_7, slot_3, ray_8, _e14, best_1, shadow_1, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
        return _e15;
    }
    return best_1;
}

uint medium_at(
    metal::float3 p_4,
    uint exclude,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
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
            Candidate _e45 = intersect_object(slot_4, probe, _e43, false, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
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
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
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
    uint _e17 = medium_at(_e15, NO_HIT, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
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
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
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
    uint base_2 = frame_3.tlas_root;
    GpuNode header_3 = nodes[base_2];
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
                Candidate _e55 = intersect_object(_e51 & NODE_FIRST_MASK, ray_10, _e54, shadow_2, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if (shadow_2 && (_e57 != NO_HIT)) {
                    Candidate _e61 = best_2;
                    return _e61;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_7 = nodes[base_2 + _e62];
            float _e68 = best_2.t;
            metal::float2 _e69 = children_entry(n_7, _e19, _e68, F32_INF);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if ((tl_1 < as_type<float>(_e73)) && (tr_1 < as_type<float>(_e77))) {
                near_1 = n_7.a;
                far_1 = n_7.b;
                if (tr_1 < tl_1) {
                    near_1 = n_7.b;
                    far_1 = n_7.a;
                }
                uint _e88 = sp_2;
                if (_e88 < TLAS_STACK) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack.inner[metal::min(_e91, 73u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = _e97 + 1u;
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if (tl_1 < as_type<float>(_e102)) {
                child_1 = n_7.a;
                continue;
            }
            uint _e107 = F32_INF;
            if (tr_1 < as_type<float>(_e107)) {
                child_1 = n_7.b;
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

metal::float3 dispatch_miss(
    uint type_id_2,
    uint offset_4,
    Ray ray_11
) {
    return metal::float3 {};
}

metal::float3 miss(
    Ray ray_12,
    constant FrameUniforms& frame
) {
    if (!(HAS_BACKGROUND)) {
        return metal::float3(0.0);
    }
    FrameUniforms frame_4 = frame;
    metal::float3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_12);
    return _e9;
}

void shading_medium(
    uint medium,
    thread type_4& scratch
) {
    scratch.inner[metal::min(SCRATCH_MEDIUM, 14u)] = medium;
    return;
}

metal::float3 fog_shade(
    Fog m_1,
    Ray ray_13,
    Hit hit_3,
    metal::float3 secondary
) {
    return secondary;
}

Lambert load_Lambert(
    uint offset_5,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_5 + 0u];
    uint _e11 = params[offset_5 + 1u];
    uint _e17 = params[offset_5 + 2u];
    return Lambert {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17))};
}

metal::float3 shading_normal(
    Ray ray_14,
    Hit hit_4
) {
    metal::float3 ng = metal::faceforward(hit_4.geometric_normal, ray_14.dir, hit_4.geometric_normal);
    return metal::faceforward(hit_4.normal, -(ng), hit_4.normal);
}

uint light_count_query(
    constant FrameUniforms& frame
) {
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

PointLight load_PointLight(
    uint offset_6,
    device type_5 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_6 + 0u];
    uint _e11 = params[offset_6 + 1u];
    uint _e17 = params[offset_6 + 2u];
    uint _e24 = params[offset_6 + 4u];
    uint _e30 = params[offset_6 + 5u];
    uint _e36 = params[offset_6 + 6u];
    uint _e43 = params[offset_6 + 7u];
    uint _e49 = params[offset_6 + 8u];
    uint _e55 = params[offset_6 + 9u];
    return PointLight {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)};
}

float shadow_preset(
    metal::float3 normal,
    metal::float3 dir,
    thread type_4& scratch
) {
    uint mode = scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 14u)];
    if (mode == SHADOW_UNOCCLUDED) {
        return 1.0;
    }
    if ((mode == SHADOW_ABOVE) && !((metal::dot(dir, normal) > 0.0))) {
        return 0.0;
    }
    return -1.0;
}

metal::float3 step_toward(
    metal::float3 x_4,
    metal::float3 s
) {
    metal::uint3 bits_1 = as_type<metal::uint3>(x_4);
    metal::bool3 up_1 = (metal::sign(x_4) * metal::sign(s)) > metal::float3(0.0);
    metal::float3 stepped = as_type<metal::float3>(metal::select(bits_1 - metal::uint3(1u), bits_1 + metal::uint3(1u), up_1));
    metal::float3 from_zero = metal::select(metal::float3(-0.000000000000000000000000000000000000011754944), metal::float3(0.000000000000000000000000000000000000011754944), s > metal::float3(0.0));
    metal::float3 moved = metal::select(stepped, from_zero, x_4 == metal::float3(0.0));
    return metal::select(x_4, moved, !((s == metal::float3(0.0))));
}

metal::float3 offset_origin(
    metal::float3 p_5,
    metal::float3 n_3,
    float error
) {
    float d_5 = (2.0 * error) * ((metal::abs(n_3.x) + metal::abs(n_3.y)) + metal::abs(n_3.z));
    metal::float3 offset_11 = n_3 * metal::float3(d_5);
    metal::float3 _e17 = step_toward(p_5 + offset_11, offset_11);
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
    metal::float3 n_4 = {};
    float tmax_4 = {};
    n_4 = normal_1;
    metal::float3 _e5 = n_4;
    if (metal::dot(dir_1, _e5) < 0.0) {
        metal::float3 _e9 = n_4;
        n_4 = -(_e9);
    }
    metal::float3 a_6 = metal::abs(position);
    float _e13 = hit_error;
    float error_3 = metal::max(_e13, GAMMA_4_ * metal::max(metal::max(a_6.x, a_6.y), a_6.z));
    metal::float3 _e22 = n_4;
    metal::float3 _e23 = offset_origin(position, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = as_type<float>(_e25);
    uint _e29 = F32_INF;
    if (dist < as_type<float>(_e29)) {
        metal::float3 light_1 = position + (dir_1 * metal::float3(dist));
        float dd = metal::dot(dir_1, dir_1);
        float along_1 = metal::dot(light_1 - _e23, dir_1) / dd;
        metal::float3 l_1 = metal::abs(position) + metal::abs(dir_1 * metal::float3(dist));
        tmax_4 = (along_1 * (1.0 - 0.00001)) - ((LIGHT_ERROR * metal::max(metal::max(l_1.x, l_1.y), l_1.z)) / metal::sqrt(dd));
    }
    float _e59 = tmax_4;
    return Ray {_e23, 0.0, dir_1, _e59, 0u, RAY_SHADOW, 0u};
}

float shadow_transmittance(
    Ray ray_15,
    uint medium_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float depth = {};
    scratch.inner[metal::min(SCRATCH_ABSORB, 14u)] = 0u;
    scratch.inner[metal::min(SCRATCH_DEPTH, 14u)] = 0u;
    scratch.inner[metal::min(SCRATCH_NET, 14u)] = 0u;
    scratch.inner[metal::min(SCRATCH_DENSITY_MAX, 14u)] = 0u;
    if (HAS_MEDIA && HAS_ANY_HIT) {
        if (medium_1 != 0u) {
            GpuInstance inst_8 = instances[medium_1 - 1u];
            if ((inst_8.flags & FLAG_ANY_HIT) != 0u) {
                Hit start_1 = Hit {ray_15.origin, 0.0, -(ray_15.dir), -(ray_15.dir), metal::float2(0.0), true, {}, inst_8.object, 0u};
                scratch.inner[metal::min(SCRATCH_ABSORB, 14u)] = 1u;
                scratch.inner[metal::min(SCRATCH_ABSORB_T, 14u)] = 0u;
                bool _e67 = dispatch_any_hit(inst_8.material_type, inst_8.material_offset, ray_15, start_1, scratch, params, _buffer_sizes);
                scratch.inner[metal::min(SCRATCH_ABSORB, 14u)] = 0u;
            }
        }
    }
    Candidate _e75 = intersect_scene(ray_15, true, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    if (_e75.slot != NO_HIT) {
        return 0.0;
    }
    uint _e85 = scratch.inner[metal::min(SCRATCH_DEPTH, 14u)];
    depth = as_type<float>(_e85);
    uint _e93 = scratch.inner[metal::min(SCRATCH_NET, 14u)];
    float net_1 = as_type<float>(_e93);
    uint _e101 = scratch.inner[metal::min(SCRATCH_DENSITY_MAX, 14u)];
    if (net_1 > (0.000001 * as_type<float>(_e101))) {
        uint _e107 = F32_INF;
        if (ray_15.tmax == as_type<float>(_e107)) {
            return 0.0;
        }
        float _e111 = depth;
        depth = _e111 + (net_1 * (ray_15.tmax * metal::length(ray_15.dir)));
    }
    float _e118 = depth;
    return metal::exp(-(metal::max(_e118, 0.0)));
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
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = shadow_preset(normal_2, dir_2, scratch);
    if (_e4 >= 0.0) {
        return _e4;
    }
    Ray _e7 = shadow_ray(position_1, normal_2, dir_2, dist_1, F32_INF, hit_error);
    uint _e13 = scratch.inner[metal::min(SCRATCH_MEDIUM, 14u)];
    float _e14 = shadow_transmittance(_e7, _e13, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e14;
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
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float strength = {};
    metal::float3 to_light = l.position - position_2;
    float dist_2 = metal::length(to_light);
    metal::float3 dir_7 = to_light / metal::float3(metal::max(dist_2, 0.00000000000000000001));
    strength = l.intensity / metal::max(dist_2 * dist_2, 0.00000000000000000001);
    if (l.range > 0.0) {
        float _e19 = strength;
        strength = _e19 * (1.0 - metal::smoothstep(l.inner_range, l.range, dist_2));
    }
    float _e26 = shadow_query(position_2, normal_3, dir_7, dist_2, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    float _e28 = strength;
    return LightSample {dir_7, dist_2, (l.color * metal::float3(_e28)) * metal::float3(_e26), 0.0};
}

LightSample dispatch_light(
    uint type_id_3,
    uint offset_7,
    metal::float3 position_3,
    metal::float3 normal_4,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    PointLight _e3 = load_PointLight(offset_7, params, _buffer_sizes);
    LightSample _e4 = point_light(_e3, position_3, normal_4, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e4;
}

LightSample sample_light_query(
    uint i_2,
    metal::float3 position_4,
    metal::float3 normal_5,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    FrameUniforms frame_5 = frame;
    if (i_2 >= frame_5.light_count) {
        return LightSample {metal::float3(0.0, 1.0, 0.0), 0.0, metal::float3(0.0), 0.0};
    }
    uint entry = frame_5.light_table + (i_2 * LIGHT_ENTRY_STRIDE);
    uint _e22 = params[entry];
    uint _e27 = params[entry + 1u];
    LightSample _e28 = dispatch_light(_e22, _e27, position_4, normal_5, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e28;
}

metal::float3 lambert_shade(
    Lambert m_2,
    Ray ray_16,
    Hit hit_5,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 color = {};
    uint i_3 = {};
    metal::float3 _e3 = shading_normal(ray_16, hit_5);
    color = metal::float3(0.0);
    uint _e8 = light_count_query(frame);
    i_3 = 0u;
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e30 = i_3;
            i_3 = _e30 + 1u;
        }
        loop_init_2 = false;
        uint _e10 = i_3;
        if (_e10 >= _e8) {
            break;
        }
        uint _e12 = i_3;
        LightSample _e15 = sample_light_query(_e12, hit_5.position, hit_5.geometric_normal, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
        metal::float3 _e16 = color;
        color = _e16 + (((m_2.albedo * metal::float3(INV_PI)) * _e15.radiance) * metal::float3(metal::max(metal::dot(_e3, _e15.dir), 0.0)));
    }
    metal::float3 _e33 = color;
    return _e33;
}

metal::float3 dispatch_closest_hit(
    uint type_id_4,
    uint offset_8,
    Ray ray_17,
    Hit hit_6,
    metal::float3 secondary_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    switch(type_id_4) {
        case 0u: {
            Fog _e5 = load_Fog(offset_8, params, _buffer_sizes);
            metal::float3 _e6 = fog_shade(_e5, ray_17, hit_6, secondary_1);
            return _e6;
        }
        case 1u: {
            Lambert _e7 = load_Lambert(offset_8, params, _buffer_sizes);
            metal::float3 _e8 = lambert_shade(_e7, ray_17, hit_6, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
            return _e8;
        }
        default: {
            break;
        }
    }
    return metal::float3 {};
}

metal::float3 shade_direct(
    Ray ray_18,
    Candidate c_2,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuInstance inst_9 = instances[c_2.slot];
    Hit _e6 = finish_hit(ray_18, c_2, instances, triangles, hit_error, attributes, _buffer_sizes);
    shading_medium(ray_18.medium, scratch);
    metal::float3 _e12 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, ray_18, _e6, metal::float3(0.0), frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e12;
}

LightSample sample_light_unoccluded_query(
    uint i_4,
    metal::float3 position_5,
    metal::float3 normal_6,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 14u)] = SHADOW_UNOCCLUDED;
    LightSample _e9 = sample_light_query(i_4, position_5, normal_6, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    scratch.inner[metal::min(SCRATCH_SHADOW_MODE, 14u)] = SHADOW_TRACED;
    return _e9;
}

metal::float3 fog_inscatter(
    Fog m_3,
    uint i_5,
    metal::float3 o,
    metal::float3 dir_3,
    float d,
    float trans,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    float s_1 = {};
    float sigma_1 = m_3.density;
    bool tiny = (sigma_1 * d) < 0.001;
    LightSample _e12 = sample_light_unoccluded_query(i_5, o, metal::float3(0.0), frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    metal::float3 c_7 = _e12.dir * metal::float3(_e12.dist);
    float delta = metal::dot(c_7, dir_3);
    float h_1 = metal::length(c_7 - (dir_3 * metal::float3(delta)));
    bool _e22 = is_finite_f32_(h_1);
    bool equi = _e22 && (h_1 > 0.00000000000000000001);
    float ta = metal::atan2(-(delta), h_1);
    uint _e34 = F32_INF;
    float tb = (d == as_type<float>(_e34)) ? (0.5 * PI) : metal::atan2(d - delta, h_1);
    float w_3 = equi ? 0.5 : 0.0;
    metal::float2 _e41 = rand2_next(scratch, rng_state);
    s_1 = -(metal::log(1.0 - (_e41.y * (1.0 - trans)))) / sigma_1;
    if (tiny) {
        s_1 = _e41.y * d;
    }
    if (_e41.x < w_3) {
        s_1 = delta + (h_1 * metal::tan(metal::mix(ta, tb, _e41.y)));
    }
    float _e61 = s_1;
    s_1 = metal::min(metal::max(_e61, 0.0), d);
    float _e66 = s_1;
    float e_4 = metal::exp(-(sigma_1) * _e66);
    float p_free = tiny ? (1.0 / d) : ((sigma_1 * e_4) / (1.0 - trans));
    float _e76 = s_1;
    float r_3 = _e76 - delta;
    float pdf = ((1.0 - w_3) * p_free) + (equi ? ((w_3 * h_1) / ((tb - ta) * ((h_1 * h_1) + (r_3 * r_3)))) : 0.0);
    float _e91 = s_1;
    LightSample _e97 = sample_light_query(i_5, o + (dir_3 * metal::float3(_e91)), metal::float3(0.0), frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e97.radiance * metal::float3((sigma_1 * e_4) / pdf);
}

metal::float3 fog_medium(
    Fog m_4,
    Ray ray_19,
    float t,
    metal::float3 radiance,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 light = {};
    uint i_6 = {};
    float len = metal::length(ray_19.dir);
    if (!((m_4.density > 0.0)) || !((len > 0.0))) {
        return radiance;
    }
    float d_6 = t * len;
    float trans_1 = metal::exp(-(m_4.density) * d_6);
    light = metal::float3(0.0);
    uint _e23 = light_count_query(frame);
    i_6 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e35 = i_6;
            i_6 = _e35 + 1u;
        }
        loop_init_3 = false;
        uint _e25 = i_6;
        if (_e25 >= _e23) {
            break;
        }
        metal::float3 _e27 = light;
        uint _e28 = i_6;
        metal::float3 _e33 = fog_inscatter(m_4, _e28, ray_19.origin, ray_19.dir / metal::float3(len), d_6, trans_1, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
        light = _e27 + _e33;
    }
    metal::float3 _e46 = light;
    return (radiance * metal::float3(trans_1)) + ((m_4.albedo * metal::float3(0.25 * INV_PI)) * _e46);
}

metal::float3 dispatch_medium(
    uint type_id_5,
    uint offset_9,
    Ray ray_20,
    float t_1,
    metal::float3 radiance_1,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    Fog _e4 = load_Fog(offset_9, params, _buffer_sizes);
    metal::float3 _e5 = fog_medium(_e4, ray_20, t_1, radiance_1, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e5;
}

metal::float3 through_medium(
    Ray ray_21,
    float t_2,
    metal::float3 radiance_2,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_MEDIA)) {
        return radiance_2;
    }
    if (ray_21.medium == 0u) {
        return radiance_2;
    }
    GpuInstance inst_10 = instances[ray_21.medium - 1u];
    if ((inst_10.flags & FLAG_MEDIUM) == 0u) {
        return radiance_2;
    }
    shading_medium(ray_21.medium, scratch);
    metal::float3 _e22 = dispatch_medium(inst_10.material_type, inst_10.material_offset, ray_21, t_2, radiance_2, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
    return _e22;
}

void rt_spawn(
    metal::float3 dir_4,
    metal::float3 weight,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count
) {
    uint _e3 = spawn_count;
    if (_e3 < 1u) {
        spawn_dirs.inner[_e3] = dir_4;
        spawn_weights.inner[_e3] = weight;
        spawn_count = _e3 + 1u;
    }
}

void fog_rays(
    Fog m_5,
    Ray ray_22,
    Hit hit_7,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count
) {
    rt_spawn(ray_22.dir, metal::float3(1.0), spawn_dirs, spawn_weights, spawn_count);
    return;
}

void dispatch_secondary_rays(
    uint type_id_6,
    uint offset_10,
    Ray ray_23,
    Hit hit_8,
    device type_5 const& params,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    Fog _e3 = load_Fog(offset_10, params, _buffer_sizes);
    fog_rays(_e3, ray_23, hit_8, spawn_dirs, spawn_weights, spawn_count);
    return;
}

metal::float3 spawn_origin_at(
    metal::float3 position_6,
    metal::float3 normal_7,
    float error_1,
    metal::float3 dir_5
) {
    metal::float3 n_5 = {};
    n_5 = normal_7;
    metal::float3 _e5 = n_5;
    if (metal::dot(dir_5, _e5) < 0.0) {
        metal::float3 _e9 = n_5;
        n_5 = -(_e9);
    }
    metal::float3 _e11 = n_5;
    metal::float3 _e12 = offset_origin(position_6, _e11, error_1);
    return _e12;
}

metal::float3 spawn_origin(
    Hit hit_9,
    float error_2,
    metal::float3 dir_6
) {
    metal::float3 _e5 = spawn_origin_at(hit_9.position, hit_9.geometric_normal, error_2, dir_6);
    return _e5;
}

metal::float3 trace(
    Ray camera_ray,
    constant FrameUniforms& frame,
    thread type_4& scratch,
    thread uint& rng_state,
    device type_5 const& params,
    thread uint& F32_INF,
    device type_9 const& instances,
    device type_10 const& nodes,
    device type_12 const& triangles,
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 radiance_3 = {};
    float t_3 = {};
    type_17 stack = {};
    uint depth_1 = {};
    Ray ray_24 = {};
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
    metal::float3 radiance_4 = {};
    float t_4 = {};
    Hit hit_10 = {};
    Frame f_1 = {};
    uint i_7 = {};
    uint medium_2 = {};
    bool found = {};
    uint k_1 = {};
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray, false, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
        radiance_3 = metal::float3(0.0);
        uint _e9 = F32_INF;
        t_3 = as_type<float>(_e9);
        if (_e4.slot == NO_HIT) {
            hit_error = 0.0;
            metal::float3 _e17 = miss(camera_ray, frame);
            radiance_3 = _e17;
        } else {
            metal::float3 _e18 = shade_direct(camera_ray, _e4, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
            radiance_3 = _e18;
            t_3 = _e4.t;
        }
        float _e20 = t_3;
        metal::float3 _e21 = radiance_3;
        metal::float3 _e22 = through_medium(camera_ray, _e20, _e21, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
        return _e22;
    }
    stack = type_17 {};
    depth_1 = 0u;
    ray_24 = camera_ray;
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
    uint2 loop_bound_6 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        bool _e62 = have_value;
        bool _e64 = waiting;
        if (!(_e62) && !(_e64)) {
            Ray _e67 = ray_24;
            Candidate _e69 = intersect_scene(_e67, false, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
            s_c = _e69;
            Ray _e70 = ray_24;
            s_ray = _e70;
            s_sum = metal::float3(0.0);
            fresh = true;
            waiting = true;
        }
        bool _e75 = waiting;
        if (_e75) {
            waiting = false;
            pushed = false;
            radiance_4 = metal::float3(0.0);
            uint _e83 = F32_INF;
            t_4 = as_type<float>(_e83);
            uint _e87 = s_c.slot;
            if (_e87 == NO_HIT) {
                hit_error = 0.0;
                Ray _e92 = s_ray;
                metal::float3 _e93 = miss(_e92, frame);
                radiance_4 = _e93;
            } else {
                uint _e95 = s_c.slot;
                GpuInstance inst_11 = instances[_e95];
                Hit _e99 = s_hit;
                hit_10 = _e99;
                bool _e101 = fresh;
                if (_e101) {
                    Ray _e102 = s_ray;
                    Candidate _e103 = s_c;
                    Hit _e104 = finish_hit(_e102, _e103, instances, triangles, hit_error, attributes, _buffer_sizes);
                    hit_10 = _e104;
                    float _e106 = hit_error;
                    s_error = _e106;
                } else {
                    float _e107 = s_error;
                    hit_error = _e107;
                }
                float _e110 = hit_10.t;
                t_4 = _e110;
                bool _e111 = fresh;
                uint _e119 = s_ray.depth;
                uint _e123 = depth_1;
                if (((_e111 && ((inst_11.flags & FLAG_SECONDARY_RAYS) != 0u)) && (_e119 < MAX_DEPTH)) && (_e123 < STACK_SIZE)) {
                    spawn_count = 0u;
                    Ray _e131 = s_ray;
                    Hit _e132 = hit_10;
                    dispatch_secondary_rays(inst_11.material_type, inst_11.material_offset, _e131, _e132, params, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
                    uint _e134 = spawn_count;
                    uint n_8 = metal::min(metal::min(_e134, 1u), MAX_SPAWN);
                    if (n_8 > 0u) {
                        Ray _e141 = s_ray;
                        Hit _e142 = hit_10;
                        float _e143 = s_error;
                        uint _e145 = s_c.slot;
                        f_1 = Frame {_e141, _e142, _e143, _e145, {}, metal::float3(0.0), type_16 {}, type_16 {}, n_8, 0u};
                        i_7 = 0u;
                        uint2 loop_bound_7 = uint2(4294967295u);
                        bool loop_init_4 = true;
                        while(true) {
                            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                            if (!loop_init_4) {
                                uint _e175 = i_7;
                                i_7 = _e175 + 1u;
                            }
                            loop_init_4 = false;
                            uint _e155 = i_7;
                            if (_e155 >= n_8) {
                                break;
                            }
                            uint _e158 = i_7;
                            uint _e162 = i_7;
                            metal::float3 _e165 = spawn_dirs.inner[_e162];
                            f_1.dirs.inner[metal::min(_e158, 0u)] = _e165;
                            uint _e167 = i_7;
                            uint _e171 = i_7;
                            metal::float3 _e174 = spawn_weights.inner[_e171];
                            f_1.weights.inner[metal::min(_e167, 0u)] = _e174;
                        }
                        uint _e178 = depth_1;
                        Frame _e182 = f_1;
                        stack.inner[metal::min(_e178, 2u)] = _e182;
                        uint _e183 = depth_1;
                        depth_1 = _e183 + 1u;
                        pushed = true;
                    }
                }
                bool _e187 = pushed;
                if (!(_e187)) {
                    uint _e190 = s_ray.medium;
                    shading_medium(_e190, scratch);
                    Ray _e193 = s_ray;
                    Hit _e194 = hit_10;
                    metal::float3 _e195 = s_sum;
                    metal::float3 _e196 = dispatch_closest_hit(inst_11.material_type, inst_11.material_offset, _e193, _e194, _e195, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
                    radiance_4 = _e196;
                }
            }
            bool _e197 = pushed;
            if (!(_e197)) {
                Ray _e199 = s_ray;
                float _e200 = t_4;
                metal::float3 _e201 = radiance_4;
                metal::float3 _e202 = through_medium(_e199, _e200, _e201, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, _buffer_sizes);
                value = _e202;
                have_value = true;
            }
        }
        bool _e204 = have_value;
        if (_e204) {
            uint _e205 = depth_1;
            if (_e205 == 0u) {
                metal::float3 _e208 = value;
                return _e208;
            }
            uint _e209 = depth_1;
            uint top = _e209 - 1u;
            uint _e216 = stack.inner[metal::min(top, 2u)].next;
            uint child_2 = _e216 - 1u;
            metal::float3 _e223 = stack.inner[metal::min(top, 2u)].sum;
            metal::float3 _e231 = stack.inner[metal::min(top, 2u)].weights.inner[metal::min(child_2, 0u)];
            metal::float3 _e232 = value;
            stack.inner[metal::min(top, 2u)].sum = _e223 + (_e231 * _e232);
            have_value = false;
        }
        uint _e236 = depth_1;
        uint top_1 = _e236 - 1u;
        uint _e243 = stack.inner[metal::min(top_1, 2u)].next;
        uint _e248 = stack.inner[metal::min(top_1, 2u)].count;
        if (_e243 < _e248) {
            uint i_9 = stack.inner[metal::min(top_1, 2u)].next;
            stack.inner[metal::min(top_1, 2u)].next = i_9 + 1u;
            Ray parent = stack.inner[metal::min(top_1, 2u)].ray;
            Hit hit_13 = stack.inner[metal::min(top_1, 2u)].hit;
            metal::float3 dir_8 = stack.inner[metal::min(top_1, 2u)].dirs.inner[metal::min(i_9, 0u)];
            medium_2 = parent.medium;
            if (metal::dot(dir_8, hit_13.geometric_normal) < 0.0) {
                uint _e289 = stack.inner[metal::min(top_1, 2u)].slot;
                medium_2 = _e289 + 1u;
            } else {
                uint _e297 = stack.inner[metal::min(top_1, 2u)].slot;
                if (parent.medium == (_e297 + 1u)) {
                    found = false;
                    medium_2 = 0u;
                    k_1 = top_1;
                    uint2 loop_bound_8 = uint2(4294967295u);
                    while(true) {
                        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
                        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
                        uint _e305 = k_1;
                        if (_e305 == 0u) {
                            break;
                        }
                        uint _e308 = k_1;
                        k_1 = _e308 - 1u;
                        uint _e311 = k_1;
                        uint _e316 = stack.inner[metal::min(_e311, 2u)].slot;
                        uint _e321 = stack.inner[metal::min(top_1, 2u)].slot;
                        uint _e323 = k_1;
                        uint _e329 = stack.inner[metal::min(_e323, 2u)].ray.medium;
                        uint _e333 = k_1;
                        uint _e341 = stack.inner[metal::min(_e333 + 1u, 2u)].ray.medium;
                        if (((_e316 == _e321) && (_e329 != parent.medium)) && (_e341 == parent.medium)) {
                            uint _e345 = k_1;
                            uint _e351 = stack.inner[metal::min(_e345, 2u)].ray.medium;
                            medium_2 = _e351;
                            found = true;
                            break;
                        }
                    }
                    bool _e353 = found;
                    if (!(_e353)) {
                        float _e359 = stack.inner[metal::min(top_1, 2u)].error;
                        metal::float3 _e360 = spawn_origin(hit_13, _e359, dir_8);
                        uint _e365 = stack.inner[metal::min(top_1, 2u)].slot;
                        uint _e366 = medium_at(_e360, _e365, frame, scratch, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
                        medium_2 = _e366;
                    }
                }
            }
            float _e371 = stack.inner[metal::min(top_1, 2u)].error;
            metal::float3 _e372 = spawn_origin(hit_13, _e371, dir_8);
            uint _e375 = F32_INF;
            uint _e381 = medium_2;
            ray_24 = Ray {_e372, 0.0, dir_8, as_type<float>(_e375), parent.depth + 1u, RAY_SECONDARY, _e381};
        } else {
            Ray _e387 = stack.inner[metal::min(top_1, 2u)].ray;
            s_ray = _e387;
            Hit _e392 = stack.inner[metal::min(top_1, 2u)].hit;
            s_hit = _e392;
            float _e397 = stack.inner[metal::min(top_1, 2u)].error;
            s_error = _e397;
            uint _e403 = stack.inner[metal::min(top_1, 2u)].slot;
            s_c.slot = _e403;
            metal::float3 _e408 = stack.inner[metal::min(top_1, 2u)].sum;
            s_sum = _e408;
            fresh = false;
            waiting = true;
            depth_1 = top_1;
        }
    }
    return metal::float3 {};
}

metal::bool3 is_finite_vec3f(
    metal::float3 x_5
) {
    return (as_type<metal::uint3>(x_5) & metal::uint3(2147483647u)) < metal::uint3(2139095040u);
}

metal::float3 finite_or_zero(
    metal::float3 c_3
) {
    metal::bool3 _e3 = is_finite_vec3f(c_3);
    return metal::select(metal::float3(0.0), c_3, _e3);
}

PassSum add_sample(
    PassSum p_6,
    metal::float3 c_4,
    uint s_2,
    uint index,
    uint first_pass,
    uint per_pass,
    thread uint& ray_count,
    device type_20& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum next = {};
    next = p_6;
    metal::bool3 _e7 = is_finite_vec3f(c_4);
    if (metal::all(_e7)) {
        metal::float3 _e10 = next.sum;
        next.sum = _e10 + c_4;
    } else {
        metal::float3 _e13 = next.sum;
        metal::float3 _e14 = finite_or_zero(c_4);
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
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count,
    device type_20& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    PassSum sums = {};
    uint s_3 = {};
    FrameUniforms frame_6 = frame;
    TileParams tile_2 = tile;
    uint index_1 = (pixel_5.y * tile_2.image_size.x) + pixel_5.x;
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = tile_2.frame * per_pass_1;
    uint count_2 = per_pass_1 * metal::max(frame_6.passes_per_dispatch, 1u);
    sums = PassSum {metal::float3(0.0), 0u};
    s_3 = 0u;
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e35 = s_3;
            s_3 = _e35 + 1u;
        }
        loop_init_5 = false;
        uint _e25 = s_3;
        if (_e25 >= count_2) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_3;
        Ray _e30 = sample_camera_ray(pixel_5, first_1 + _e28, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, _buffer_sizes);
        metal::float3 _e31 = trace(_e30, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        uint _e32 = s_3;
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
    thread float& hit_error,
    device type_14 const& attributes,
    thread type_15& traversal_stack,
    thread uint& ray_count,
    thread type_16& spawn_dirs,
    thread type_16& spawn_weights,
    thread uint& spawn_count,
    device type_20& counters,
    device type_12& accum,
    constant _mslBufferSizes& _buffer_sizes
) {
    TileParams tile_3 = tile;
    metal::uint2 _e3 = scattered_local(id_1, tile);
    if (metal::any(_e3 >= tile_3.extent)) {
        return;
    }
    render_pixel(tile_3.origin + _e3, tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, spawn_dirs, spawn_weights, spawn_count, counters, accum, _buffer_sizes);
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
, device type_14 const& attributes [[buffer(5)]]
, device type_20& counters [[buffer(9)]]
, device type_12& accum [[buffer(8)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(10)]]
) {
    type_4 scratch = {};
    uint rng_state = {};
    uint F32_INF = 2139095040u;
    float hit_error = {};
    type_15 traversal_stack = {};
    uint ray_count = {};
    type_16 spawn_dirs = {};
    type_16 spawn_weights = {};
    uint spawn_count = {};
    render_invocation(metal::uint2(gid.x, gid.y), tile, frame, scratch, rng_state, params, F32_INF, instances, nodes, triangles, hit_error, attributes, traversal_stack, ray_count, spawn_dirs, spawn_weights, spawn_count, counters, accum, _buffer_sizes);
    return;
}
