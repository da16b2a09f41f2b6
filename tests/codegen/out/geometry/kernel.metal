// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size2;
    uint size3;
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
struct Triangle {
    metal::float3 v0_;
    metal::float3 v1_;
    metal::float3 v2_;
};
struct Intersection {
    float t;
    char _pad1[12];
    metal::float3 normal;
    metal::float2 uv;
    char _pad3[8];
};
struct Input {
    metal::float3 o;
    metal::float3 d;
};
struct Output {
    metal::float3 result;
};
typedef Input type_4[1];
typedef Output type_5[1];

metal::float3 normalize_vec3f(
    metal::float3 v
) {
    return (metal::dot(v, v) >= 0.000000000000000000000000000000000000011754944) ? metal::normalize(v) : metal::float3(0.0);
}

Intersection intersect_triangle(
    Ray ray,
    Triangle tri,
    thread uint& F32_INF
) {
    metal::uint3 _e10 = metal::uint3(2139095040u);
    metal::float3 dir = metal::select(ray.dir, metal::float3(0.0), metal::abs(ray.dir) < metal::float3(0.000000000000000000000000000000000000011754944));
    metal::float3 _e31 = metal::abs(dir);
    bool _e38 = _e31.y > _e31.x;
    uint kz = (_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u);
    uint _e45 = (kz == 2u) ? 0u : (kz + 1u);
    uint _e49 = (kz >= 1u) ? (kz - 1u) : (kz + 2u);
    float dz = dir[kz];
    bool _e52 = dz < 0.0;
    uint kx = _e52 ? _e49 : _e45;
    uint ky = _e52 ? _e45 : _e49;
    float sx = dir[kx] / dz;
    float sy = dir[ky] / dz;
    float sz = 1.0 / dz;
    metal::float3 _e62 = tri.v0_ - ray.origin;
    float _e68 = _e62[kx] - (sx * _e62[kz]);
    float _e69 = _e62[ky] - (sy * _e62[kz]);
    metal::float3 _e71 = tri.v1_ - ray.origin;
    float _e77 = _e71[kx] - (sx * _e71[kz]);
    float _e78 = _e71[ky] - (sy * _e71[kz]);
    metal::float3 _e80 = tri.v2_ - ray.origin;
    float _e86 = _e80[kx] - (sx * _e80[kz]);
    float _e87 = _e80[ky] - (sy * _e80[kz]);
    float u = (_e86 * _e78) - (_e87 * _e77);
    float v_1 = (_e68 * _e87) - (_e69 * _e86);
    float w = (_e77 * _e69) - (_e78 * _e68);
    float det = (u + v_1) + w;
    float _e112 = 1.0 / det;
    float t = (((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112;
    bool hit = ((((metal::all((as_type<metal::uint3>(ray.origin) & metal::uint3(2147483647u)) < _e10) && metal::all((as_type<metal::uint3>(ray.dir) & metal::uint3(2147483647u)) < _e10)) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t >= ray.tmin) && (t <= ray.tmax));
    metal::float3 _e132 = normalize_vec3f(metal::cross(tri.v1_ - tri.v0_, tri.v2_ - tri.v0_));
    uint _e137 = F32_INF;
    return Intersection {hit ? t : as_type<float>(_e137), {}, hit ? _e132 : metal::float3(0.0, 0.0, 1.0), hit ? metal::float2(v_1 * _e112, w * _e112) : metal::float2(0.0)};
}

metal::float2 intersect_aabb(
    Ray ray_1,
    metal::float3 min,
    metal::float3 max,
    thread uint& F32_INF,
    thread uint& F32_NEG_INF
) {
    metal::bool3 parallel = metal::abs(ray_1.dir) < metal::float3(0.000000000000000000000000000000000000011754944);
    metal::float3 _e12 = metal::float3(1.0);
    metal::float3 inv_dir = _e12 / metal::select(ray_1.dir, _e12, parallel);
    metal::float3 _e17 = (min - ray_1.origin) * inv_dir;
    metal::float3 _e18 = (max - ray_1.origin) * inv_dir;
    metal::bool3 _e23 = (min <= ray_1.origin) & (ray_1.origin <= max);
    uint _e25 = F32_INF;
    metal::float3 _e27 = metal::float3(as_type<float>(_e25));
    uint _e29 = F32_NEG_INF;
    metal::float3 _e31 = metal::float3(as_type<float>(_e29));
    metal::float3 near = metal::select(metal::min(_e17, _e18), metal::select(_e27, _e31, _e23), parallel);
    metal::float3 far = metal::select(metal::max(_e17, _e18), metal::select(_e31, _e27, _e23), parallel);
    return metal::float2(metal::max(metal::max(metal::max(near.x, near.y), near.z), ray_1.tmin), metal::min(metal::min(metal::min(far.x, far.y), far.z), ray_1.tmax));
}

metal::float3 test_fn(
    metal::float3 o,
    metal::float3 d,
    thread uint& F32_INF,
    thread uint& F32_NEG_INF
) {
    uint _e4 = F32_INF;
    Ray ray_2 = Ray {o, 0.0, d, as_type<float>(_e4), 0u, 0u, 0u};
    Triangle tri_1 = Triangle {metal::float3(-1.0, -1.0, 0.0), metal::float3(1.0, -1.0, 0.0), metal::float3(0.0, 1.0, 0.0)};
    Intersection _e23 = intersect_triangle(ray_2, tri_1, F32_INF);
    metal::float2 _e28 = intersect_aabb(ray_2, metal::float3(-1.0), metal::float3(1.0), F32_INF, F32_NEG_INF);
    return metal::float3((_e23.t < 1000000000000000000000000000000.0) ? _e23.t : -1.0, _e28.x, _e28.y);
}

struct main_Input {
};
[[max_total_threads_per_threadgroup(64)]] kernel void main_(
  metal::uint3 id [[thread_position_in_grid]]
, device type_4 const& input [[buffer(0)]]
, device type_5& output [[buffer(1)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(2)]]
) {
    uint F32_INF = 2139095040u;
    uint F32_NEG_INF = 4286578688u;
    uint index = id.x;
    if (index >= (1 + (_buffer_sizes.size2 - 0 - 32) / 32)) {
        return;
    }
    metal::float3 _e8 = input[index].o;
    metal::float3 _e10 = input[index].d;
    metal::float3 _e11 = test_fn(_e8, _e10, F32_INF, F32_NEG_INF);
    output[index].result = _e11;
}
