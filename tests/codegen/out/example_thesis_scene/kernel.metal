// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size3;
    uint size5;
    uint size6;
    uint size7;
    uint size8;
    uint size12;
    uint size13;
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
};
struct TileParams {
    metal::uint2 origin;
    metal::uint2 extent;
    metal::uint2 image_size;
    uint tile_index;
    uint frame;
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
typedef uint type_4[1];
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
typedef GpuInstance type_8[1];
struct type_9 {
    uint inner[64];
};
struct GpuNode {
    metal::packed_float3 min;
    uint a;
    metal::packed_float3 max;
    uint b;
};
typedef GpuNode type_10[1];
struct Triangle {
    metal::float3 v0_;
    metal::float3 v1_;
    metal::float3 v2_;
};
typedef metal::float4 type_11[1];
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
typedef metal::uint4 type_13[1];
struct ConstantBackground {
    metal::float3 color;
};
struct Lambert {
    metal::float3 albedo;
};
struct LightSample {
    metal::packed_float3 dir;
    float dist;
    metal::float3 radiance;
};
struct PointLight {
    metal::float3 position;
    metal::packed_float3 color;
    float intensity;
    float range;
    float inner_range;
    char _pad5[8];
};
struct type_15 {
    metal::float3 inner[1];
};
struct Frame {
    Ray ray;
    Hit hit;
    uint slot;
    char _pad3[12];
    metal::float3 sum;
    type_15 dirs;
    type_15 weights;
    uint count;
    uint next;
    char _pad8[8];
};
struct type_16 {
    Frame inner[1];
};
typedef metal::atomic_uint type_19[1];
constant uint RAY_CAMERA = 0u;
constant bool HAS_MEDIA = false;
constant uint NO_HIT = 4294967295u;
constant uint MESH_GEOMETRY = 4294967295u;
constant uint LEAF_BIT = 2147483648u;
constant bool HAS_ANY_HIT = false;
constant uint FLAG_ANY_HIT = 1u;
constant uint BLAS_STACK = 64u;
constant bool HAS_SECONDARY_RAYS = false;
constant uint TLAS_STACK = 64u;
constant bool HAS_BACKGROUND = true;
constant uint FLAG_MEDIUM = 4u;
constant uint RAY_SHADOW = 2u;
constant float INV_PI = 0.31830987;
constant uint FLAG_SECONDARY = 2u;
constant uint MAX_DEPTH = 0u;
constant uint STACK_SIZE = 1u;
constant uint MAX_SPAWN = 1u;
constant uint RAY_SECONDARY = 1u;

uint pcg_hash(
    uint x
) {
    uint state = (x * 747796405u) + 2891336453u;
    uint word = ((state >> (((state >> 28u) + 4u) & 31u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

void rng_seed(
    metal::uint2 pixel,
    uint sample,
    uint seed,
    thread uint& rng_state
) {
    uint h = {};
    uint _e5 = pcg_hash(seed);
    uint _e7 = pcg_hash(sample ^ _e5);
    uint _e9 = pcg_hash(pixel.y ^ _e7);
    uint _e11 = pcg_hash(pixel.x ^ _e9);
    h = _e11;
    uint _e13 = h;
    if (_e13 == 0u) {
        h = 1u;
    }
    uint _e17 = h;
    rng_state = _e17;
    return;
}

Pinhole load_Pinhole(
    uint offset,
    device type_4 const& params,
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

float rand_next(
    thread uint& rng_state
) {
    uint _e1 = rng_state;
    uint s_1 = (_e1 * 747796405u) + 2891336453u;
    rng_state = s_1;
    uint word_1 = ((s_1 >> (((s_1 >> 28u) + 4u) & 31u)) ^ s_1) * 277803737u;
    uint r_3 = (word_1 >> 22u) ^ word_1;
    return static_cast<float>(r_3 >> 8u) * (1.0 / 16777216.0);
}

metal::float2 rand2_next(
    thread uint& rng_state
) {
    float _e0 = rand_next(rng_state);
    float _e1 = rand_next(rng_state);
    return metal::float2(_e0, _e1);
}

metal::float3 normalize_vec3f(
    metal::float3 v
) {
    return (metal::dot(v, v) >= 0.000000000000000000000000000000000000011754944) ? metal::normalize(v) : metal::float3(0.0);
}

Ray pinhole_ray(
    Pinhole cam,
    metal::uint2 pixel_1,
    uint sample_1,
    constant FrameUniforms& frame,
    constant TileParams& tile,
    thread uint& rng_state,
    thread uint& F32_INF
) {
    metal::float2 jitter = {};
    metal::uint2 _e2 = image_size_query(tile);
    metal::float2 size = static_cast<metal::float2>(_e2);
    jitter = metal::float2(0.5);
    uint _e7 = samples_per_pixel_query(frame);
    if (_e7 > 1u) {
        metal::float2 _e10 = rand2_next(rng_state);
        jitter = _e10;
    }
    metal::float2 _e12 = jitter;
    metal::float2 ndc = (((static_cast<metal::float2>(pixel_1) + _e12) / size) * metal::float2(2.0)) - metal::float2(1.0);
    metal::float3 _e24 = normalize_vec3f(cam.look_at - cam.position);
    metal::float3 _e27 = normalize_vec3f(metal::cross(_e24, cam.up));
    metal::float3 up = metal::cross(_e27, _e24);
    float h_1 = metal::tan(((cam.fov) * 0.017453292519943295474) * 0.5);
    float aspect = size.x / size.y;
    metal::float3 _e48 = normalize_vec3f((_e24 + (_e27 * metal::float3((ndc.x * h_1) * aspect))) - (up * metal::float3(ndc.y * h_1)));
    uint _e52 = F32_INF;
    return Ray {cam.position, 0.0, _e48, as_type<float>(_e52), 0u, 0u, 0u};
}

Ray dispatch_ray_generation(
    uint type_id,
    uint offset_1,
    metal::uint2 pixel_2,
    uint sample_2,
    constant FrameUniforms& frame,
    constant TileParams& tile,
    thread uint& rng_state,
    device type_4 const& params,
    thread uint& F32_INF,
    constant _mslBufferSizes& _buffer_sizes
) {
    Pinhole _e3 = load_Pinhole(offset_1, params, _buffer_sizes);
    Ray _e4 = pinhole_ray(_e3, pixel_2, sample_2, frame, tile, rng_state, F32_INF);
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

metal::float3 safe_inverse(
    metal::float3 d
) {
    metal::float3 tiny = metal::float3(0.000000000000000000000000000001);
    metal::float3 s_2 = metal::select(metal::float3(1.0), metal::float3(-1.0), d < metal::float3(0.0));
    metal::float3 dd = metal::select(d, s_2 * tiny, metal::abs(d) < tiny);
    return metal::float3(1.0) / dd;
}

Triangle load_triangle(
    uint slot,
    device type_11 const& triangles,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 v0_ = triangles[slot * 3u];
    metal::float4 v1_ = triangles[(slot * 3u) + 1u];
    metal::float4 v2_ = triangles[(slot * 3u) + 2u];
    return Triangle {v0_.xyz, v1_.xyz, v2_.xyz};
}

Intersection intersect_triangle(
    Ray ray_1,
    Triangle tri,
    thread uint& F32_INF
) {
    metal::uint3 _e10 = metal::uint3(2139095040u);
    metal::float3 dir_2 = metal::select(ray_1.dir, metal::float3(0.0), metal::abs(ray_1.dir) < metal::float3(0.000000000000000000000000000000000000011754944));
    metal::float3 _e31 = metal::abs(dir_2);
    bool _e38 = _e31.y > _e31.x;
    uint kz = (_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u);
    uint _e45 = (kz == 2u) ? 0u : (kz + 1u);
    uint _e49 = (kz >= 1u) ? (kz - 1u) : (kz + 2u);
    float dz = dir_2[kz];
    bool _e52 = dz < 0.0;
    uint kx = _e52 ? _e49 : _e45;
    uint ky = _e52 ? _e45 : _e49;
    float sx = dir_2[kx] / dz;
    float sy = dir_2[ky] / dz;
    float sz = 1.0 / dz;
    metal::float3 _e62 = tri.v0_ - ray_1.origin;
    float _e68 = _e62[kx] - (sx * _e62[kz]);
    float _e69 = _e62[ky] - (sy * _e62[kz]);
    metal::float3 _e71 = tri.v1_ - ray_1.origin;
    float _e77 = _e71[kx] - (sx * _e71[kz]);
    float _e78 = _e71[ky] - (sy * _e71[kz]);
    metal::float3 _e80 = tri.v2_ - ray_1.origin;
    float _e86 = _e80[kx] - (sx * _e80[kz]);
    float _e87 = _e80[ky] - (sy * _e80[kz]);
    float u = (_e86 * _e78) - (_e87 * _e77);
    float v_1 = (_e68 * _e87) - (_e69 * _e86);
    float w = (_e77 * _e69) - (_e78 * _e68);
    float det = (u + v_1) + w;
    float _e112 = 1.0 / det;
    float t_2 = (((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112;
    bool hit_6 = ((((metal::all((as_type<metal::uint3>(ray_1.origin) & metal::uint3(2147483647u)) < _e10) && metal::all((as_type<metal::uint3>(ray_1.dir) & metal::uint3(2147483647u)) < _e10)) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t_2 >= ray_1.tmin) && (t_2 <= ray_1.tmax));
    metal::float3 _e132 = normalize_vec3f(metal::cross(tri.v1_ - tri.v0_, tri.v2_ - tri.v0_));
    uint _e137 = F32_INF;
    return Intersection {hit_6 ? t_2 : as_type<float>(_e137), {}, hit_6 ? _e132 : metal::float3(0.0, 0.0, 1.0), hit_6 ? metal::float2(v_1 * _e112, w * _e112) : metal::float2(0.0)};
}

metal::float3 point_to_world(
    GpuInstance inst_1,
    metal::float3 p
) {
    metal::float4 q = metal::float4(p, 1.0);
    return metal::float3(metal::dot(inst_1.object_to_world_0_, q), metal::dot(inst_1.object_to_world_1_, q), metal::dot(inst_1.object_to_world_2_, q));
}

metal::float3 decode_octahedral(
    uint bits
) {
    metal::float3 n = {};
    metal::float2 e = metal::unpack_snorm2x16_to_float(bits);
    n = metal::float3(e.x, e.y, (1.0 - metal::abs(e.x)) - metal::abs(e.y));
    float _e14 = n.z;
    if (_e14 < 0.0) {
        metal::float3 _e21 = n;
        metal::float2 s_3 = metal::select(metal::float2(-1.0), metal::float2(1.0), _e21.xy >= metal::float2(0.0));
        metal::float3 _e29 = n;
        metal::float2 xy = (metal::float2(1.0) - metal::abs(_e29.yx)) * s_3;
        float _e37 = n.z;
        n = metal::float3(xy.x, xy.y, _e37);
    }
    metal::float3 _e39 = n;
    metal::float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

metal::float3 normal_to_world(
    GpuInstance inst_2,
    metal::float3 n_1
) {
    metal::float3 w_1 = ((inst_2.world_to_object_0_.xyz * metal::float3(n_1.x)) + (inst_2.world_to_object_1_.xyz * metal::float3(n_1.y))) + (inst_2.world_to_object_2_.xyz * metal::float3(n_1.z));
    metal::float3 _e19 = normalize_vec3f(w_1);
    return _e19;
}

Hit finish_hit(
    Ray ray_2,
    Candidate c,
    device type_8 const& instances,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Hit hit = {};
    metal::float3 n_geo = {};
    metal::float3 n_shade = {};
    GpuInstance inst_5 = instances[c.slot];
    hit = Hit {ray_2.origin + (ray_2.dir * metal::float3(c.t)), c.t, metal::float3(0.0, 1.0, 0.0), metal::float3(0.0, 1.0, 0.0), c.uv, true, {}, inst_5.object, c.primitive};
    n_geo = c.normal;
    n_shade = c.normal;
    if (inst_5.geometry_type == MESH_GEOMETRY) {
        Triangle _e35 = load_triangle(c.primitive, triangles, _buffer_sizes);
        metal::float2 b_1 = c.uv;
        float w_2 = (1.0 - c.uv.x) - c.uv.y;
        metal::float3 _e56 = point_to_world(inst_5, ((_e35.v0_ * metal::float3(w_2)) + (_e35.v1_ * metal::float3(c.uv.x))) + (_e35.v2_ * metal::float3(c.uv.y)));
        hit.position = _e56;
        n_geo = metal::cross(_e35.v1_ - _e35.v0_, _e35.v2_ - _e35.v0_);
        metal::uint4 a0_ = attributes[c.primitive * 2u];
        metal::uint4 a1_ = attributes[(c.primitive * 2u) + 1u];
        metal::float3 _e79 = decode_octahedral(a0_.x);
        metal::float3 _e83 = decode_octahedral(a0_.y);
        metal::float3 _e89 = decode_octahedral(a0_.z);
        n_shade = ((_e79 * metal::float3(w_2)) + (_e83 * metal::float3(c.uv.x))) + (_e89 * metal::float3(c.uv.y));
        metal::float3 _e94 = n_shade;
        metal::float3 _e95 = n_shade;
        if (metal::dot(_e94, _e95) < 0.000000000001) {
            metal::float3 _e99 = n_geo;
            n_shade = _e99;
        }
        metal::float2 uv0_ = float2(as_type<half2>(a0_.w));
        metal::float2 uv1_ = float2(as_type<half2>(a1_.x));
        metal::float2 uv2_ = float2(as_type<half2>(a1_.y));
        hit.uv = ((uv0_ * metal::float2(w_2)) + (uv1_ * metal::float2(c.uv.x))) + (uv2_ * metal::float2(c.uv.y));
        metal::float4 _e123 = triangles[c.primitive * 3u];
        hit.primitive = as_type<uint>(_e123.w);
    }
    metal::float3 _e127 = n_geo;
    metal::float3 _e128 = normal_to_world(inst_5, _e127);
    hit.geometric_normal = _e128;
    metal::float3 _e130 = n_shade;
    metal::float3 _e131 = normal_to_world(inst_5, _e130);
    hit.normal = _e131;
    metal::float3 _e135 = hit.geometric_normal;
    hit.front_face = metal::dot(ray_2.dir, _e135) < 0.0;
    Hit _e139 = hit;
    return _e139;
}

bool dispatch_any_hit(
    uint type_id_1,
    uint offset_2,
    Ray ray_3,
    Hit hit_1
) {
    return bool {};
}

bool accept(
    GpuInstance inst_3,
    Ray ray_4,
    Candidate c_1,
    device type_8 const& instances,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_ANY_HIT)) {
        return true;
    }
    if ((inst_3.flags & FLAG_ANY_HIT) == 0u) {
        return true;
    }
    Hit _e12 = finish_hit(ray_4, c_1, instances, triangles, attributes, _buffer_sizes);
    bool _e15 = dispatch_any_hit(inst_3.material_type, inst_3.material_offset, ray_4, _e12);
    return _e15;
}

float slab(
    metal::float3 lo,
    metal::float3 hi,
    metal::float3 origin,
    metal::float3 inv_dir,
    float tmin,
    float tmax_1,
    thread uint& F32_INF
) {
    metal::float3 t0_ = (lo - origin) * inv_dir;
    metal::float3 t1_ = (hi - origin) * inv_dir;
    metal::float3 near_2 = metal::min(t0_, t1_);
    metal::float3 far_2 = metal::max(t0_, t1_);
    float enter = metal::max(metal::max(near_2.x, near_2.y), metal::max(near_2.z, tmin));
    float exit = metal::min(metal::min(far_2.x, far_2.y), metal::min(far_2.z, tmax_1));
    if (enter <= exit) {
        return enter;
    }
    uint _e26 = F32_INF;
    return as_type<float>(_e26);
}

Candidate intersect_mesh(
    GpuInstance inst_4,
    uint slot_1,
    Ray world_ray,
    Ray ray_5,
    Candidate best_in,
    bool shadow,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best = {};
    type_9 stack = {};
    uint sp = {};
    uint node = {};
    uint k = {};
    Ray r_1 = {};
    uint near = {};
    uint far = {};
    best = best_in;
    metal::float3 _e8 = safe_inverse(ray_5.dir);
    uint base = inst_4.blas_root;
    stack = type_9 {};
    sp = 0u;
    node = base;
    uint2 loop_bound = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e15 = node;
        GpuNode n_5 = nodes[_e15];
        if ((n_5.b & LEAF_BIT) != 0u) {
            uint count = n_5.b & ~(LEAF_BIT);
            k = 0u;
            uint2 loop_bound_1 = uint2(4294967295u);
            bool loop_init = true;
            while(true) {
                if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e65 = k;
                    k = _e65 + 1u;
                }
                loop_init = false;
                uint _e30 = k;
                if (_e30 >= count) {
                    break;
                }
                uint _e35 = k;
                uint prim = (inst_4.triangle_offset + n_5.a) + _e35;
                r_1 = ray_5;
                float _e40 = best.t;
                r_1.tmax = _e40;
                Ray _e41 = r_1;
                Triangle _e42 = load_triangle(prim, triangles, _buffer_sizes);
                Intersection _e43 = intersect_triangle(_e41, _e42, F32_INF);
                float _e46 = r_1.tmin;
                float _e50 = r_1.tmax;
                uint _e55 = F32_INF;
                if (((_e43.t >= _e46) && (_e43.t <= _e50)) && (_e43.t < as_type<float>(_e55))) {
                    Candidate c_4 = Candidate {_e43.t, slot_1, prim, {}, _e43.uv, {}, _e43.normal};
                    bool _e63 = accept(inst_4, world_ray, c_4, instances, triangles, attributes, _buffer_sizes);
                    if (_e63) {
                        best = c_4;
                        if (shadow) {
                            Candidate _e64 = best;
                            return _e64;
                        }
                    }
                }
            }
        } else {
            uint left = base + n_5.a;
            uint right = left + 1u;
            GpuNode l_1 = nodes[left];
            GpuNode rr = nodes[right];
            float _e83 = best.t;
            float _e84 = slab(l_1.min, l_1.max, ray_5.origin, _e8, ray_5.tmin, _e83, F32_INF);
            float _e90 = best.t;
            float _e91 = slab(rr.min, rr.max, ray_5.origin, _e8, ray_5.tmin, _e90, F32_INF);
            uint _e93 = F32_INF;
            uint _e97 = F32_INF;
            if ((_e84 < as_type<float>(_e93)) && (_e91 < as_type<float>(_e97))) {
                near = left;
                far = right;
                if (_e91 < _e84) {
                    near = right;
                    far = left;
                }
                uint _e104 = sp;
                if (_e104 < BLAS_STACK) {
                    uint _e107 = sp;
                    uint _e111 = far;
                    stack.inner[metal::min(_e107, 63u)] = _e111;
                    uint _e112 = sp;
                    sp = _e112 + 1u;
                }
                uint _e115 = near;
                node = _e115;
                continue;
            }
            uint _e117 = F32_INF;
            if (_e84 < as_type<float>(_e117)) {
                node = left;
                continue;
            }
            uint _e121 = F32_INF;
            if (_e91 < as_type<float>(_e121)) {
                node = right;
                continue;
            }
        }
        uint _e124 = sp;
        if (_e124 == 0u) {
            break;
        }
        uint _e127 = sp;
        sp = _e127 - 1u;
        uint _e130 = sp;
        uint _e134 = stack.inner[metal::min(_e130, 63u)];
        node = _e134;
    }
    Candidate _e135 = best;
    return _e135;
}

Candidate intersect_object(
    uint slot_2,
    Ray ray_6,
    Candidate best_1,
    bool shadow_1,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Ray r_2 = {};
    GpuInstance inst_6 = instances[slot_2];
    Ray _e7 = to_object(inst_6, ray_6);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if (inst_6.geometry_type == MESH_GEOMETRY) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_6, _e14, best_1, shadow_1, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        return _e15;
    }
    return best_1;
}

uint medium_at(
    metal::float3 p_1,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint i = {};
    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = frame;
    metal::float3 _e11 = normalize_vec3f(metal::float3(0.5773, 0.5774, 0.5775));
    uint _e13 = F32_INF;
    Ray probe = Ray {p_1, 0.0, _e11, as_type<float>(_e13), 0u, 0u, 0u};
    uint end = frame_1.medium_count;
    i = 0u;
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e44 = i;
            i = _e44 + 1u;
        }
        loop_init_1 = false;
        uint _e22 = i;
        if (_e22 >= end) {
            break;
        }
        uint _e25 = i;
        uint slot_3 = params[frame_1.medium_table + _e25];
        uint _e31 = F32_INF;
        Candidate _e33 = no_candidate(as_type<float>(_e31));
        Candidate _e35 = intersect_object(slot_3, probe, _e33, false, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        if (_e35.slot != NO_HIT) {
            Hit _e39 = finish_hit(probe, _e35, instances, triangles, attributes, _buffer_sizes);
            if (!(_e39.front_face)) {
                return slot_3 + 1u;
            }
        }
    }
    return 0u;
}

Candidate intersect_scene(
    Ray ray_7,
    bool shadow_2,
    constant FrameUniforms& frame,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Candidate best_2 = {};
    type_9 stack_1 = {};
    uint sp_1 = {};
    uint node_1 = {};
    uint k_1 = {};
    uint near_1 = {};
    uint far_1 = {};
    Candidate _e3 = no_candidate(ray_7.tmax);
    best_2 = _e3;
    FrameUniforms frame_2 = frame;
    if (frame_2.instance_count == 0u) {
        Candidate _e10 = best_2;
        return _e10;
    }
    metal::float3 _e12 = safe_inverse(ray_7.dir);
    stack_1 = type_9 {};
    sp_1 = 0u;
    node_1 = frame_2.tlas_root;
    uint _e19 = node_1;
    GpuNode root = nodes[_e19];
    float _e28 = best_2.t;
    float _e29 = slab(root.min, root.max, ray_7.origin, _e12, ray_7.tmin, _e28, F32_INF);
    uint _e31 = F32_INF;
    if (_e29 == as_type<float>(_e31)) {
        Candidate _e34 = best_2;
        return _e34;
    }
    uint2 loop_bound_3 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_3 == uint2(0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e35 = node_1;
        GpuNode n_6 = nodes[_e35];
        if ((n_6.b & LEAF_BIT) != 0u) {
            uint count_1 = n_6.b & ~(LEAF_BIT);
            k_1 = 0u;
            uint2 loop_bound_4 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_4 == uint2(0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e63 = k_1;
                    k_1 = _e63 + 1u;
                }
                loop_init_2 = false;
                uint _e50 = k_1;
                if (_e50 >= count_1) {
                    break;
                }
                uint _e53 = k_1;
                Candidate _e55 = best_2;
                Candidate _e56 = intersect_object(n_6.a + _e53, ray_7, _e55, shadow_2, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
                best_2 = _e56;
                uint _e58 = best_2.slot;
                if (shadow_2 && (_e58 != NO_HIT)) {
                    Candidate _e62 = best_2;
                    return _e62;
                }
            }
        } else {
            uint left_1 = frame_2.tlas_root + n_6.a;
            uint right_1 = left_1 + 1u;
            GpuNode l_2 = nodes[left_1];
            GpuNode rr_1 = nodes[right_1];
            float _e82 = best_2.t;
            float _e83 = slab(l_2.min, l_2.max, ray_7.origin, _e12, ray_7.tmin, _e82, F32_INF);
            float _e89 = best_2.t;
            float _e90 = slab(rr_1.min, rr_1.max, ray_7.origin, _e12, ray_7.tmin, _e89, F32_INF);
            uint _e92 = F32_INF;
            uint _e96 = F32_INF;
            if ((_e83 < as_type<float>(_e92)) && (_e90 < as_type<float>(_e96))) {
                near_1 = left_1;
                far_1 = right_1;
                if (_e90 < _e83) {
                    near_1 = right_1;
                    far_1 = left_1;
                }
                uint _e103 = sp_1;
                if (_e103 < TLAS_STACK) {
                    uint _e106 = sp_1;
                    uint _e110 = far_1;
                    stack_1.inner[metal::min(_e106, 63u)] = _e110;
                    uint _e111 = sp_1;
                    sp_1 = _e111 + 1u;
                }
                uint _e114 = near_1;
                node_1 = _e114;
                continue;
            }
            uint _e116 = F32_INF;
            if (_e83 < as_type<float>(_e116)) {
                node_1 = left_1;
                continue;
            }
            uint _e120 = F32_INF;
            if (_e90 < as_type<float>(_e120)) {
                node_1 = right_1;
                continue;
            }
        }
        uint _e123 = sp_1;
        if (_e123 == 0u) {
            break;
        }
        uint _e126 = sp_1;
        sp_1 = _e126 - 1u;
        uint _e129 = sp_1;
        uint _e133 = stack_1.inner[metal::min(_e129, 63u)];
        node_1 = _e133;
    }
    Candidate _e134 = best_2;
    return _e134;
}

ConstantBackground load_ConstantBackground(
    uint offset_3,
    device type_4 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_3 + 0u];
    uint _e11 = params[offset_3 + 1u];
    uint _e17 = params[offset_3 + 2u];
    return ConstantBackground {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17))};
}

metal::float3 constant_background(
    ConstantBackground b,
    Ray ray_8
) {
    return b.color;
}

metal::float3 dispatch_miss(
    uint type_id_2,
    uint offset_4,
    Ray ray_9,
    device type_4 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    ConstantBackground _e2 = load_ConstantBackground(offset_4, params, _buffer_sizes);
    metal::float3 _e3 = constant_background(_e2, ray_9);
    return _e3;
}

metal::float3 miss(
    Ray ray_10,
    constant FrameUniforms& frame,
    device type_4 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_BACKGROUND)) {
        return metal::float3(0.0);
    }
    FrameUniforms frame_3 = frame;
    metal::float3 _e9 = dispatch_miss(frame_3.background_type, frame_3.background_offset, ray_10, params, _buffer_sizes);
    return _e9;
}

metal::float3 dispatch_medium(
    uint type_id_3,
    uint offset_5,
    Ray ray_11,
    float t,
    metal::float3 radiance
) {
    return metal::float3 {};
}

metal::float3 through_medium(
    Ray ray_12,
    float t_1,
    metal::float3 radiance_1,
    device type_8 const& instances,
    constant _mslBufferSizes& _buffer_sizes
) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if (ray_12.medium == 0u) {
        return radiance_1;
    }
    GpuInstance inst_7 = instances[ray_12.medium - 1u];
    if ((inst_7.flags & FLAG_MEDIUM) == 0u) {
        return radiance_1;
    }
    metal::float3 _e21 = dispatch_medium(inst_7.material_type, inst_7.material_offset, ray_12, t_1, radiance_1);
    return _e21;
}

Lambert load_Lambert(
    uint offset_6,
    device type_4 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_6 + 0u];
    uint _e11 = params[offset_6 + 1u];
    uint _e17 = params[offset_6 + 2u];
    return Lambert {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17))};
}

uint light_count_query(
    constant FrameUniforms& frame
) {
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

PointLight load_PointLight(
    uint offset_7,
    device type_4 const& params,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = params[offset_7 + 0u];
    uint _e11 = params[offset_7 + 1u];
    uint _e17 = params[offset_7 + 2u];
    uint _e24 = params[offset_7 + 4u];
    uint _e30 = params[offset_7 + 5u];
    uint _e36 = params[offset_7 + 6u];
    uint _e43 = params[offset_7 + 7u];
    uint _e49 = params[offset_7 + 8u];
    uint _e55 = params[offset_7 + 9u];
    return PointLight {metal::float3(as_type<float>(_e5), as_type<float>(_e11), as_type<float>(_e17)), metal::float3(as_type<float>(_e24), as_type<float>(_e30), as_type<float>(_e36)), as_type<float>(_e43), as_type<float>(_e49), as_type<float>(_e55)};
}

metal::int3 naga_f2i32(metal::float3 value) {
    return static_cast<metal::int3>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

metal::int3 vec3i_from_vec3f(
    metal::float3 x_1
) {
    return metal::select(naga_f2i32(metal::min(metal::max(x_1, metal::float3(-2147483600.0)), metal::float3(2147483500.0))), metal::int3(0), (as_type<metal::uint3>(x_1) & metal::uint3(2147483647u)) > metal::uint3(2139095040u));
}

int naga_neg(int val) {
    return as_type<int>(-as_type<uint>(val));
}

metal::float3 offset_origin(
    metal::float3 p_2,
    metal::float3 n_2
) {
    metal::int3 _e5 = vec3i_from_vec3f(n_2 * metal::float3(256.0));
    metal::float3 pi = metal::float3(as_type<float>(as_type<int>(as_type<uint>(as_type<int>(p_2.x)) + as_type<uint>((p_2.x < 0.0) ? naga_neg(_e5.x) : _e5.x))), as_type<float>(as_type<int>(as_type<uint>(as_type<int>(p_2.y)) + as_type<uint>((p_2.y < 0.0) ? naga_neg(_e5.y) : _e5.y))), as_type<float>(as_type<int>(as_type<uint>(as_type<int>(p_2.z)) + as_type<uint>((p_2.z < 0.0) ? naga_neg(_e5.z) : _e5.z))));
    metal::bool3 small = metal::abs(p_2) < metal::float3(1.0 / 32.0);
    return metal::select(pi, p_2 + (n_2 * metal::float3(1.0 / 65536.0)), small);
}

float shadow_query(
    metal::float3 position,
    metal::float3 normal,
    metal::float3 dir,
    float dist,
    constant FrameUniforms& frame,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 n_3 = {};
    n_3 = normal;
    metal::float3 _e5 = n_3;
    if (metal::dot(dir, _e5) < 0.0) {
        metal::float3 _e9 = n_3;
        n_3 = -(_e9);
    }
    metal::float3 _e11 = n_3;
    metal::float3 _e12 = offset_origin(position, _e11);
    Ray ray_19 = Ray {_e12, 0.0, dir, dist * (1.0 - 0.00001), 0u, RAY_SHADOW, 0u};
    Candidate _e23 = intersect_scene(ray_19, true, frame, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    return (_e23.slot != NO_HIT) ? 0.0 : 1.0;
}

LightSample point_light(
    PointLight l,
    metal::float3 position_1,
    metal::float3 normal_1,
    constant FrameUniforms& frame,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    float strength = {};
    metal::float3 to_light = l.position - position_1;
    float dist_1 = metal::length(to_light);
    metal::float3 dir_3 = to_light / metal::float3(metal::max(dist_1, 0.00000000000000000001));
    strength = l.intensity / metal::max(dist_1 * dist_1, 0.00000000000000000001);
    if (l.range > 0.0) {
        float _e19 = strength;
        strength = _e19 * (1.0 - metal::smoothstep(l.inner_range, l.range, dist_1));
    }
    float _e26 = shadow_query(position_1, normal_1, dir_3, dist_1, frame, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    float _e28 = strength;
    return LightSample {dir_3, dist_1, (l.color * metal::float3(_e28)) * metal::float3(_e26)};
}

LightSample dispatch_light(
    uint type_id_4,
    uint offset_8,
    metal::float3 position_2,
    metal::float3 normal_2,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    PointLight _e3 = load_PointLight(offset_8, params, _buffer_sizes);
    LightSample _e4 = point_light(_e3, position_2, normal_2, frame, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    return _e4;
}

LightSample sample_light_query(
    uint i_1,
    metal::float3 position_3,
    metal::float3 normal_3,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    FrameUniforms frame_4 = frame;
    if (i_1 >= frame_4.light_count) {
        return LightSample {metal::float3(0.0, 1.0, 0.0), 0.0, metal::float3(0.0)};
    }
    uint entry = frame_4.light_table + (i_1 * 2u);
    uint _e21 = params[entry];
    uint _e26 = params[entry + 1u];
    LightSample _e27 = dispatch_light(_e21, _e26, position_3, normal_3, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    return _e27;
}

metal::float3 lambert_shade(
    Lambert m,
    Ray ray_13,
    Hit hit_2,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 color = {};
    uint i_2 = {};
    metal::float3 n_7 = metal::faceforward(hit_2.normal, ray_13.dir, hit_2.normal);
    color = metal::float3(0.0);
    uint _e11 = light_count_query(frame);
    i_2 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e33 = i_2;
            i_2 = _e33 + 1u;
        }
        loop_init_3 = false;
        uint _e13 = i_2;
        if (_e13 >= _e11) {
            break;
        }
        uint _e15 = i_2;
        LightSample _e18 = sample_light_query(_e15, hit_2.position, hit_2.geometric_normal, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        metal::float3 _e19 = color;
        color = _e19 + (((m.albedo * metal::float3(INV_PI)) * _e18.radiance) * metal::float3(metal::max(metal::dot(n_7, _e18.dir), 0.0)));
    }
    metal::float3 _e36 = color;
    return _e36;
}

metal::float3 dispatch_closest_hit(
    uint type_id_5,
    uint offset_9,
    Ray ray_14,
    Hit hit_3,
    metal::float3 secondary,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    Lambert _e3 = load_Lambert(offset_9, params, _buffer_sizes);
    metal::float3 _e4 = lambert_shade(_e3, ray_14, hit_3, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    return _e4;
}

metal::float3 shade_direct(
    Ray ray_15,
    Candidate c_2,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    constant _mslBufferSizes& _buffer_sizes
) {
    GpuInstance inst_8 = instances[c_2.slot];
    Hit _e6 = finish_hit(ray_15, c_2, instances, triangles, attributes, _buffer_sizes);
    metal::float3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_15, _e6, metal::float3(0.0), frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
    return _e11;
}

void dispatch_secondary_rays(
    uint type_id_6,
    uint offset_10,
    Ray ray_16,
    Hit hit_4
) {
    return;
}

metal::float3 spawn_origin(
    Hit hit_5,
    metal::float3 dir_1
) {
    metal::float3 n_4 = {};
    n_4 = hit_5.geometric_normal;
    metal::float3 _e4 = n_4;
    if (metal::dot(dir_1, _e4) < 0.0) {
        metal::float3 _e8 = n_4;
        n_4 = -(_e8);
    }
    metal::float3 _e11 = n_4;
    metal::float3 _e12 = offset_origin(hit_5.position, _e11);
    return _e12;
}

metal::float3 trace(
    Ray camera_ray,
    constant FrameUniforms& frame,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    thread type_15& spawn_dirs,
    thread type_15& spawn_weights,
    thread uint& spawn_count,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_16 stack_2 = {};
    uint depth = {};
    Ray ray_17 = {};
    metal::float3 value = {};
    bool have_value = {};
    bool pushed = {};
    Frame f = {};
    uint i_3 = {};
    uint medium = {};
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray, false, frame, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        if (_e4.slot == NO_HIT) {
            uint _e9 = F32_INF;
            metal::float3 _e11 = miss(camera_ray, frame, params, _buffer_sizes);
            metal::float3 _e12 = through_medium(camera_ray, as_type<float>(_e9), _e11, instances, _buffer_sizes);
            return _e12;
        }
        metal::float3 _e14 = shade_direct(camera_ray, _e4, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        metal::float3 _e15 = through_medium(camera_ray, _e4.t, _e14, instances, _buffer_sizes);
        return _e15;
    }
    stack_2 = type_16 {};
    depth = 0u;
    ray_17 = camera_ray;
    value = metal::float3(0.0);
    have_value = false;
    uint2 loop_bound_6 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        bool _e26 = have_value;
        if (!(_e26)) {
            Ray _e28 = ray_17;
            Candidate _e30 = intersect_scene(_e28, false, frame, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
            if (_e30.slot == NO_HIT) {
                Ray _e34 = ray_17;
                uint _e36 = F32_INF;
                Ray _e38 = ray_17;
                metal::float3 _e39 = miss(_e38, frame, params, _buffer_sizes);
                metal::float3 _e40 = through_medium(_e34, as_type<float>(_e36), _e39, instances, _buffer_sizes);
                value = _e40;
                have_value = true;
            } else {
                GpuInstance inst_9 = instances[_e30.slot];
                Ray _e46 = ray_17;
                Hit _e47 = finish_hit(_e46, _e30, instances, triangles, attributes, _buffer_sizes);
                pushed = false;
                uint _e56 = ray_17.depth;
                uint _e60 = depth;
                if ((((inst_9.flags & FLAG_SECONDARY) != 0u) && (_e56 < MAX_DEPTH)) && (_e60 < STACK_SIZE)) {
                    spawn_count = 0u;
                    Ray _e68 = ray_17;
                    dispatch_secondary_rays(inst_9.material_type, inst_9.material_offset, _e68, _e47);
                    uint _e70 = spawn_count;
                    uint n_8 = metal::min(metal::min(_e70, 1u), MAX_SPAWN);
                    if (n_8 > 0u) {
                        Ray _e77 = ray_17;
                        f = Frame {_e77, _e47, _e30.slot, {}, metal::float3(0.0), type_15 {}, type_15 {}, n_8, 0u};
                        i_3 = 0u;
                        uint2 loop_bound_7 = uint2(4294967295u);
                        bool loop_init_4 = true;
                        while(true) {
                            if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                            if (!loop_init_4) {
                                uint _e108 = i_3;
                                i_3 = _e108 + 1u;
                            }
                            loop_init_4 = false;
                            uint _e88 = i_3;
                            if (_e88 >= n_8) {
                                break;
                            }
                            uint _e91 = i_3;
                            uint _e95 = i_3;
                            metal::float3 _e98 = spawn_dirs.inner[_e95];
                            f.dirs.inner[metal::min(_e91, 0u)] = _e98;
                            uint _e100 = i_3;
                            uint _e104 = i_3;
                            metal::float3 _e107 = spawn_weights.inner[_e104];
                            f.weights.inner[metal::min(_e100, 0u)] = _e107;
                        }
                        uint _e111 = depth;
                        Frame _e115 = f;
                        stack_2.inner[metal::min(_e111, 0u)] = _e115;
                        uint _e116 = depth;
                        depth = _e116 + 1u;
                        pushed = true;
                    }
                }
                bool _e120 = pushed;
                if (!(_e120)) {
                    Ray _e124 = ray_17;
                    metal::float3 _e127 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, _e124, _e47, metal::float3(0.0), frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
                    Ray _e128 = ray_17;
                    metal::float3 _e130 = through_medium(_e128, _e30.t, _e127, instances, _buffer_sizes);
                    value = _e130;
                    have_value = true;
                }
            }
        }
        bool _e132 = have_value;
        if (_e132) {
            uint _e133 = depth;
            if (_e133 == 0u) {
                metal::float3 _e136 = value;
                return _e136;
            }
            uint _e137 = depth;
            uint top = _e137 - 1u;
            uint _e144 = stack_2.inner[metal::min(top, 0u)].next;
            uint child = _e144 - 1u;
            metal::float3 _e151 = stack_2.inner[metal::min(top, 0u)].sum;
            metal::float3 _e159 = stack_2.inner[metal::min(top, 0u)].weights.inner[metal::min(child, 0u)];
            metal::float3 _e160 = value;
            stack_2.inner[metal::min(top, 0u)].sum = _e151 + (_e159 * _e160);
            have_value = false;
        }
        uint _e164 = depth;
        uint top_1 = _e164 - 1u;
        uint _e171 = stack_2.inner[metal::min(top_1, 0u)].next;
        uint _e176 = stack_2.inner[metal::min(top_1, 0u)].count;
        if (_e171 < _e176) {
            uint i_4 = stack_2.inner[metal::min(top_1, 0u)].next;
            stack_2.inner[metal::min(top_1, 0u)].next = i_4 + 1u;
            Ray parent = stack_2.inner[metal::min(top_1, 0u)].ray;
            Hit hit_7 = stack_2.inner[metal::min(top_1, 0u)].hit;
            metal::float3 dir_4 = stack_2.inner[metal::min(top_1, 0u)].dirs.inner[metal::min(i_4, 0u)];
            medium = parent.medium;
            metal::float3 _e209 = spawn_origin(hit_7, dir_4);
            uint _e212 = F32_INF;
            uint _e218 = medium;
            ray_17 = Ray {_e209, 0.0, dir_4, as_type<float>(_e212), parent.depth + 1u, RAY_SECONDARY, _e218};
        } else {
            uint _e224 = stack_2.inner[metal::min(top_1, 0u)].slot;
            GpuInstance inst_10 = instances[_e224];
            Ray _e234 = stack_2.inner[metal::min(top_1, 0u)].ray;
            Hit _e239 = stack_2.inner[metal::min(top_1, 0u)].hit;
            metal::float3 _e244 = stack_2.inner[metal::min(top_1, 0u)].sum;
            metal::float3 _e245 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e234, _e239, _e244, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
            Ray _e250 = stack_2.inner[metal::min(top_1, 0u)].ray;
            float _e256 = stack_2.inner[metal::min(top_1, 0u)].hit.t;
            metal::float3 _e257 = through_medium(_e250, _e256, _e245, instances, _buffer_sizes);
            value = _e257;
            depth = top_1;
            have_value = true;
        }
    }
    return metal::float3 {};
}

metal::bool3 is_finite_vec3f(
    metal::float3 x_2
) {
    return (as_type<metal::uint3>(x_2) & metal::uint3(2147483647u)) < metal::uint3(2139095040u);
}

metal::float3 finite_or_zero(
    metal::float3 c_3
) {
    metal::bool3 _e3 = is_finite_vec3f(c_3);
    return metal::select(metal::float3(0.0), c_3, _e3);
}

void render_pixel(
    metal::uint2 pixel_3,
    constant FrameUniforms& frame,
    constant TileParams& tile,
    thread uint& rng_state,
    device type_4 const& params,
    thread uint& F32_INF,
    device type_8 const& instances,
    device type_10 const& nodes,
    device type_11 const& triangles,
    device type_13 const& attributes,
    thread type_15& spawn_dirs,
    thread type_15& spawn_weights,
    thread uint& spawn_count,
    device type_11& accum,
    device type_19& counters,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 sum = {};
    uint bad = {};
    uint s = {};
    Ray ray_18 = {};
    FrameUniforms frame_5 = frame;
    TileParams tile_1 = tile;
    sum = metal::float3(0.0);
    bad = 0u;
    uint end_1 = frame_5.samples_per_pass;
    s = 0u;
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e45 = s;
            s = _e45 + 1u;
        }
        loop_init_5 = false;
        uint _e13 = s;
        if (_e13 >= end_1) {
            break;
        }
        uint _e18 = s;
        uint sample_3 = (tile_1.frame * frame_5.samples_per_pass) + _e18;
        rng_seed(pixel_3, sample_3, frame_5.seed, rng_state);
        Ray _e23 = dispatch_ray_generation(frame_5.camera_type, frame_5.camera_offset, pixel_3, sample_3, frame, tile, rng_state, params, F32_INF, _buffer_sizes);
        ray_18 = _e23;
        ray_18.depth = 0u;
        ray_18.kind = RAY_CAMERA;
        metal::float3 _e31 = ray_18.origin;
        uint _e32 = medium_at(_e31, frame, params, F32_INF, instances, nodes, triangles, attributes, _buffer_sizes);
        ray_18.medium = _e32;
        Ray _e33 = ray_18;
        metal::float3 _e34 = trace(_e33, frame, params, F32_INF, instances, nodes, triangles, attributes, spawn_dirs, spawn_weights, spawn_count, _buffer_sizes);
        metal::bool3 _e35 = is_finite_vec3f(_e34);
        if (metal::all(_e35)) {
            metal::float3 _e37 = sum;
            sum = _e37 + _e34;
        } else {
            metal::float3 _e39 = sum;
            metal::float3 _e40 = finite_or_zero(_e34);
            sum = _e39 + _e40;
            uint _e42 = bad;
            bad = _e42 + 1u;
        }
    }
    metal::float3 _e54 = sum;
    uint _e58 = bad;
    metal::float4 _e61 = accum[(pixel_3.y * tile_1.image_size.x) + pixel_3.x];
    accum[(pixel_3.y * tile_1.image_size.x) + pixel_3.x] = _e61 + metal::float4(_e54, static_cast<float>(frame_5.samples_per_pass));
    if (_e58 > 0u) {
        metal::atomic_fetch_add_explicit(&counters[0], _e58, metal::memory_order_relaxed);
    }
    return;
}

struct renderInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void render(
  metal::uint3 gid [[thread_position_in_grid]]
, constant FrameUniforms& frame [[buffer(0)]]
, constant TileParams& tile [[buffer(1)]]
, device type_4 const& params [[buffer(6)]]
, device type_8 const& instances [[buffer(3)]]
, device type_10 const& nodes [[buffer(2)]]
, device type_11 const& triangles [[buffer(4)]]
, device type_13 const& attributes [[buffer(5)]]
, device type_11& accum [[buffer(8)]]
, device type_19& counters [[buffer(9)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(10)]]
) {
    uint rng_state = {};
    uint F32_INF = 2139095040u;
    type_15 spawn_dirs = {};
    type_15 spawn_weights = {};
    uint spawn_count = {};
    TileParams _e2 = tile;
    metal::uint2 _e7 = metal::uint2(gid.x, gid.y);
    if (metal::any(_e7 >= _e2.extent)) {
        return;
    }
    render_pixel(_e2.origin + _e7, frame, tile, rng_state, params, F32_INF, instances, nodes, triangles, attributes, spawn_dirs, spawn_weights, spawn_count, accum, counters, _buffer_sizes);
    return;
}
