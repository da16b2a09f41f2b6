#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

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
    uvec2 origin;
    uvec2 extent;
    uvec2 image_size;
    uint tile_index;
    uint frame;
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
struct GpuNode {
    vec3 min_;
    uint a;
    vec3 max_;
    uint b;
};
struct Triangle {
    vec3 v0_;
    vec3 v1_;
    vec3 v2_;
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
struct ConstantBackground {
    vec3 color;
};
struct Lambert {
    vec3 albedo;
};
struct LightSample {
    vec3 dir;
    float dist;
    vec3 radiance;
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
    uint slot;
    vec3 sum;
    vec3 dirs[1];
    vec3 weights[1];
    uint count;
    uint next;
};
const uint RAY_CAMERA = 0u;
const bool HAS_MEDIA = false;
const uint NO_HIT = 4294967295u;
const uint MESH_GEOMETRY = 4294967295u;
const uint LEAF_BIT = 2147483648u;
const bool HAS_ANY_HIT = false;
const uint FLAG_ANY_HIT = 1u;
const uint BLAS_STACK = 64u;
const bool HAS_SECONDARY_RAYS = false;
const uint TLAS_STACK = 64u;
const bool HAS_BACKGROUND = true;
const uint FLAG_MEDIUM = 4u;
const uint RAY_SHADOW = 2u;
const float INV_PI = 0.31830987;
const uint FLAG_SECONDARY = 2u;
const uint MAX_DEPTH = 0u;
const uint STACK_SIZE = 1u;
const uint MAX_SPAWN = 1u;
const uint RAY_SECONDARY = 1u;

layout(std140, binding = 0) uniform FrameUniforms_block_0Compute { FrameUniforms _group_0_binding_0_cs; };

layout(std140, binding = 1) uniform TileParams_block_1Compute { TileParams _group_0_binding_1_cs; };

uint rng_state = 0u;

layout(std430, binding = 6) readonly buffer type_4_block_2Compute { uint _group_0_binding_6_cs[]; };

uint F32_INF = 2139095040u;

layout(std430, binding = 3) readonly buffer type_8_block_3Compute { GpuInstance _group_0_binding_3_cs[]; };

layout(std430, binding = 2) readonly buffer type_10_block_4Compute { GpuNode _group_0_binding_2_cs[]; };

layout(std430, binding = 4) readonly buffer type_11_block_5Compute { vec4 _group_0_binding_4_cs[]; };

layout(std430, binding = 5) readonly buffer type_13_block_6Compute { uvec4 _group_0_binding_5_cs[]; };

vec3 spawn_dirs[1] = vec3[1](vec3(0.0));

vec3 spawn_weights[1] = vec3[1](vec3(0.0));

uint spawn_count = 0u;

layout(std430, binding = 8) buffer type_11_block_7Compute { vec4 _group_0_binding_8_cs[]; };

layout(std430, binding = 9) buffer type_19_block_8Compute { uint _group_0_binding_9_cs[]; };


uint pcg_hash(uint x) {
    uint state = ((x * 747796405u) + 2891336453u);
    uint word = (((state >> (((state >> 28u) + 4u) & 31u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

void rng_seed(uvec2 pixel, uint sample_, uint seed) {
    uint h = 0u;
    uint _e5 = pcg_hash(seed);
    uint _e7 = pcg_hash((sample_ ^ _e5));
    uint _e9 = pcg_hash((pixel.y ^ _e7));
    uint _e11 = pcg_hash((pixel.x ^ _e9));
    h = _e11;
    uint _e13 = h;
    if ((_e13 == 0u)) {
        h = 1u;
    }
    uint _e17 = h;
    rng_state = _e17;
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

float rand_next() {
    uint _e1 = rng_state;
    uint s_1 = ((_e1 * 747796405u) + 2891336453u);
    rng_state = s_1;
    uint word_1 = (((s_1 >> (((s_1 >> 28u) + 4u) & 31u)) ^ s_1) * 277803737u);
    uint r_3 = ((word_1 >> 22u) ^ word_1);
    return (float((r_3 >> 8u)) * (1.0 / 16777216.0));
}

vec2 rand2_next() {
    float _e0 = rand_next();
    float _e1 = rand_next();
    return vec2(_e0, _e1);
}

vec3 normalize_vec3f(vec3 v) {
    return ((dot(v, v) >= 1.1754944e-38) ? normalize(v) : vec3(0.0));
}

Ray pinhole_ray(Pinhole cam, uvec2 pixel_1, uint sample_1) {
    vec2 jitter = vec2(0.0);
    uvec2 _e2 = image_size_query();
    vec2 size = vec2(_e2);
    jitter = vec2(0.5);
    uint _e7 = samples_per_pixel_query();
    if ((_e7 > 1u)) {
        vec2 _e10 = rand2_next();
        jitter = _e10;
    }
    vec2 _e12 = jitter;
    vec2 ndc = ((((vec2(pixel_1) + _e12) / size) * vec2(2.0)) - vec2(1.0));
    vec3 _e24 = normalize_vec3f((cam.look_at - cam.position));
    vec3 _e27 = normalize_vec3f(cross(_e24, cam.up));
    vec3 up = cross(_e27, _e24);
    float h_1 = tan((radians(cam.fov) * 0.5));
    float aspect = (size.x / size.y);
    vec3 _e48 = normalize_vec3f(((_e24 + (_e27 * vec3(((ndc.x * h_1) * aspect)))) - (up * vec3((ndc.y * h_1)))));
    uint _e52 = F32_INF;
    return Ray(cam.position, 0.0, _e48, uintBitsToFloat(_e52), 0u, 0u, 0u);
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uvec2 pixel_2, uint sample_2) {
    Pinhole _e3 = load_Pinhole(offset_1);
    Ray _e4 = pinhole_ray(_e3, pixel_2, sample_2);
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

vec3 safe_inverse(vec3 d) {
    vec3 tiny = vec3(1e-30);
    vec3 s_2 = mix(vec3(1.0), vec3(-1.0), lessThan(d, vec3(0.0)));
    vec3 dd = mix(d, (s_2 * tiny), lessThan(abs(d), tiny));
    return (vec3(1.0) / dd);
}

Triangle load_triangle(uint slot) {
    vec4 v0_ = _group_0_binding_4_cs[(slot * 3u)];
    vec4 v1_ = _group_0_binding_4_cs[((slot * 3u) + 1u)];
    vec4 v2_ = _group_0_binding_4_cs[((slot * 3u) + 2u)];
    return Triangle(v0_.xyz, v1_.xyz, v2_.xyz);
}

Intersection intersect_triangle(Ray ray_1, Triangle tri) {
    uvec3 _e10 = uvec3(2139095040u);
    vec3 dir_2 = mix(ray_1.dir, vec3(0.0), lessThan(abs(ray_1.dir), vec3(1.1754944e-38)));
    vec3 _e31 = abs(dir_2);
    bool _e38 = (_e31.y > _e31.x);
    uint kz = ((_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u));
    uint _e45 = ((kz == 2u) ? 0u : (kz + 1u));
    uint _e49 = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = dir_2[kz];
    bool _e52 = (dz < 0.0);
    uint kx = (_e52 ? _e49 : _e45);
    uint ky = (_e52 ? _e45 : _e49);
    float sx = (dir_2[kx] / dz);
    float sy = (dir_2[ky] / dz);
    float sz = (1.0 / dz);
    vec3 _e62 = (tri.v0_ - ray_1.origin);
    float _e68 = (_e62[kx] - (sx * _e62[kz]));
    float _e69 = (_e62[ky] - (sy * _e62[kz]));
    vec3 _e71 = (tri.v1_ - ray_1.origin);
    float _e77 = (_e71[kx] - (sx * _e71[kz]));
    float _e78 = (_e71[ky] - (sy * _e71[kz]));
    vec3 _e80 = (tri.v2_ - ray_1.origin);
    float _e86 = (_e80[kx] - (sx * _e80[kz]));
    float _e87 = (_e80[ky] - (sy * _e80[kz]));
    float u = ((_e86 * _e78) - (_e87 * _e77));
    float v_1 = ((_e68 * _e87) - (_e69 * _e86));
    float w = ((_e77 * _e69) - (_e78 * _e68));
    float det = ((u + v_1) + w);
    float _e112 = (1.0 / det);
    float t_2 = ((((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112);
    bool hit_6 = (((((all(lessThan((floatBitsToUint(ray_1.origin) & uvec3(2147483647u)), _e10)) && all(lessThan((floatBitsToUint(ray_1.dir) & uvec3(2147483647u)), _e10))) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t_2 >= ray_1.tmin) && (t_2 <= ray_1.tmax)));
    vec3 _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    uint _e137 = F32_INF;
    return Intersection((hit_6 ? t_2 : uintBitsToFloat(_e137)), (hit_6 ? _e132 : vec3(0.0, 0.0, 1.0)), (hit_6 ? vec2((v_1 * _e112), (w * _e112)) : vec2(0.0)));
}

vec3 point_to_world(GpuInstance inst_1, vec3 p) {
    vec4 q = vec4(p, 1.0);
    return vec3(dot(inst_1.object_to_world_0_, q), dot(inst_1.object_to_world_1_, q), dot(inst_1.object_to_world_2_, q));
}

vec3 decode_octahedral(uint bits) {
    vec3 n = vec3(0.0);
    vec2 e = unpackSnorm2x16(bits);
    n = vec3(e.x, e.y, ((1.0 - abs(e.x)) - abs(e.y)));
    float _e14 = n.z;
    if ((_e14 < 0.0)) {
        vec3 _e21 = n;
        vec2 s_3 = mix(vec2(-1.0), vec2(1.0), greaterThanEqual(_e21.xy, vec2(0.0)));
        vec3 _e29 = n;
        vec2 xy = ((vec2(1.0) - abs(_e29.yx)) * s_3);
        float _e37 = n.z;
        n = vec3(xy.x, xy.y, _e37);
    }
    vec3 _e39 = n;
    vec3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

vec3 normal_to_world(GpuInstance inst_2, vec3 n_1) {
    vec3 w_1 = (((inst_2.world_to_object_0_.xyz * vec3(n_1.x)) + (inst_2.world_to_object_1_.xyz * vec3(n_1.y))) + (inst_2.world_to_object_2_.xyz * vec3(n_1.z)));
    vec3 _e19 = normalize_vec3f(w_1);
    return _e19;
}

Hit finish_hit(Ray ray_2, Candidate c) {
    Hit hit = Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u);
    vec3 n_geo = vec3(0.0);
    vec3 n_shade = vec3(0.0);
    GpuInstance inst_5 = _group_0_binding_3_cs[c.slot];
    hit = Hit((ray_2.origin + (ray_2.dir * vec3(c.t))), c.t, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), c.uv, true, inst_5.object, c.primitive);
    n_geo = c.normal;
    n_shade = c.normal;
    if ((inst_5.geometry_type == MESH_GEOMETRY)) {
        Triangle _e35 = load_triangle(c.primitive);
        vec2 b_1 = c.uv;
        float w_2 = ((1.0 - b_1.x) - b_1.y);
        vec3 _e56 = point_to_world(inst_5, (((_e35.v0_ * vec3(w_2)) + (_e35.v1_ * vec3(b_1.x))) + (_e35.v2_ * vec3(b_1.y))));
        hit.position = _e56;
        n_geo = cross((_e35.v1_ - _e35.v0_), (_e35.v2_ - _e35.v0_));
        uvec4 a0_ = _group_0_binding_5_cs[(c.primitive * 2u)];
        uvec4 a1_ = _group_0_binding_5_cs[((c.primitive * 2u) + 1u)];
        vec3 _e79 = decode_octahedral(a0_.x);
        vec3 _e83 = decode_octahedral(a0_.y);
        vec3 _e89 = decode_octahedral(a0_.z);
        n_shade = (((_e79 * vec3(w_2)) + (_e83 * vec3(b_1.x))) + (_e89 * vec3(b_1.y)));
        vec3 _e94 = n_shade;
        vec3 _e95 = n_shade;
        if ((dot(_e94, _e95) < 1e-12)) {
            vec3 _e99 = n_geo;
            n_shade = _e99;
        }
        vec2 uv0_ = unpackHalf2x16(a0_.w);
        vec2 uv1_ = unpackHalf2x16(a1_.x);
        vec2 uv2_ = unpackHalf2x16(a1_.y);
        hit.uv = (((uv0_ * vec2(w_2)) + (uv1_ * vec2(b_1.x))) + (uv2_ * vec2(b_1.y)));
        vec4 _e123 = _group_0_binding_4_cs[(c.primitive * 3u)];
        hit.primitive = floatBitsToUint(_e123.w);
    }
    vec3 _e127 = n_geo;
    vec3 _e128 = normal_to_world(inst_5, _e127);
    hit.geometric_normal = _e128;
    vec3 _e130 = n_shade;
    vec3 _e131 = normal_to_world(inst_5, _e130);
    hit.normal = _e131;
    vec3 _e135 = hit.geometric_normal;
    hit.front_face = (dot(ray_2.dir, _e135) < 0.0);
    Hit _e139 = hit;
    return _e139;
}

bool dispatch_any_hit(uint type_id_1, uint offset_2, Ray ray_3, Hit hit_1) {
    return false;
}

bool accept(GpuInstance inst_3, Ray ray_4, Candidate c_1) {
    if (!(HAS_ANY_HIT)) {
        return true;
    }
    if (((inst_3.flags & FLAG_ANY_HIT) == 0u)) {
        return true;
    }
    Hit _e12 = finish_hit(ray_4, c_1);
    bool _e15 = dispatch_any_hit(inst_3.material_type, inst_3.material_offset, ray_4, _e12);
    return _e15;
}

float slab(vec3 lo, vec3 hi, vec3 origin, vec3 inv_dir, float tmin, float tmax_1) {
    vec3 t0_ = ((lo - origin) * inv_dir);
    vec3 t1_ = ((hi - origin) * inv_dir);
    vec3 near_2 = min(t0_, t1_);
    vec3 far_2 = max(t0_, t1_);
    float enter = max(max(near_2.x, near_2.y), max(near_2.z, tmin));
    float exit = min(min(far_2.x, far_2.y), min(far_2.z, tmax_1));
    if ((enter <= exit)) {
        return enter;
    }
    uint _e26 = F32_INF;
    return uintBitsToFloat(_e26);
}

Candidate intersect_mesh(GpuInstance inst_4, uint slot_1, Ray world_ray, Ray ray_5, Candidate best_in, bool shadow) {
    Candidate best = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint stack[64] = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint sp = 0u;
    uint node = 0u;
    uint k = 0u;
    Ray r_1 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    uint near = 0u;
    uint far = 0u;
    best = best_in;
    vec3 _e8 = safe_inverse(ray_5.dir);
    uint base = inst_4.blas_root;
    stack = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    sp = 0u;
    node = base;
    while(true) {
        uint _e15 = node;
        GpuNode n_5 = _group_0_binding_2_cs[_e15];
        if (((n_5.b & LEAF_BIT) != 0u)) {
            uint count = (n_5.b & ~(LEAF_BIT));
            k = 0u;
            bool loop_init = true;
            while(true) {
                if (!loop_init) {
                    uint _e65 = k;
                    k = (_e65 + 1u);
                }
                loop_init = false;
                uint _e30 = k;
                if ((_e30 >= count)) {
                    break;
                }
                uint _e35 = k;
                uint prim = ((inst_4.triangle_offset + n_5.a) + _e35);
                r_1 = ray_5;
                float _e40 = best.t;
                r_1.tmax = _e40;
                Ray _e41 = r_1;
                Triangle _e42 = load_triangle(prim);
                Intersection _e43 = intersect_triangle(_e41, _e42);
                float _e46 = r_1.tmin;
                float _e50 = r_1.tmax;
                uint _e55 = F32_INF;
                if ((((_e43.t >= _e46) && (_e43.t <= _e50)) && (_e43.t < uintBitsToFloat(_e55)))) {
                    Candidate c_4 = Candidate(_e43.t, slot_1, prim, _e43.uv, _e43.normal);
                    bool _e63 = accept(inst_4, world_ray, c_4);
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
            uint left = (base + n_5.a);
            uint right = (left + 1u);
            GpuNode l_1 = _group_0_binding_2_cs[left];
            GpuNode rr = _group_0_binding_2_cs[right];
            float _e83 = best.t;
            float _e84 = slab(l_1.min_, l_1.max_, ray_5.origin, _e8, ray_5.tmin, _e83);
            float _e90 = best.t;
            float _e91 = slab(rr.min_, rr.max_, ray_5.origin, _e8, ray_5.tmin, _e90);
            uint _e93 = F32_INF;
            uint _e97 = F32_INF;
            if (((_e84 < uintBitsToFloat(_e93)) && (_e91 < uintBitsToFloat(_e97)))) {
                near = left;
                far = right;
                if ((_e91 < _e84)) {
                    near = right;
                    far = left;
                }
                uint _e104 = sp;
                if ((_e104 < BLAS_STACK)) {
                    uint _e107 = sp;
                    uint _e111 = far;
                    stack[min(_e107, 63u)] = _e111;
                    uint _e112 = sp;
                    sp = (_e112 + 1u);
                }
                uint _e115 = near;
                node = _e115;
                continue;
            }
            uint _e117 = F32_INF;
            if ((_e84 < uintBitsToFloat(_e117))) {
                node = left;
                continue;
            }
            uint _e121 = F32_INF;
            if ((_e91 < uintBitsToFloat(_e121))) {
                node = right;
                continue;
            }
        }
        uint _e124 = sp;
        if ((_e124 == 0u)) {
            break;
        }
        uint _e127 = sp;
        sp = (_e127 - 1u);
        uint _e130 = sp;
        uint _e134 = stack[min(_e130, 63u)];
        node = _e134;
    }
    Candidate _e135 = best;
    return _e135;
}

Candidate intersect_object(uint slot_2, Ray ray_6, Candidate best_1, bool shadow_1) {
    Ray r_2 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    GpuInstance inst_6 = _group_0_binding_3_cs[slot_2];
    Ray _e7 = to_object(inst_6, ray_6);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_6, _e14, best_1, shadow_1);
        return _e15;
    }
    return best_1;
}

uint medium_at(vec3 p_1) {
    uint i = 0u;
    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = _group_0_binding_0_cs;
    vec3 _e11 = normalize_vec3f(vec3(0.5773, 0.5774, 0.5775));
    uint _e13 = F32_INF;
    Ray probe = Ray(p_1, 0.0, _e11, uintBitsToFloat(_e13), 0u, 0u, 0u);
    uint end = frame_1.medium_count;
    i = 0u;
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e44 = i;
            i = (_e44 + 1u);
        }
        loop_init_1 = false;
        uint _e22 = i;
        if ((_e22 >= end)) {
            break;
        }
        uint _e25 = i;
        uint slot_3 = _group_0_binding_6_cs[(frame_1.medium_table + _e25)];
        uint _e31 = F32_INF;
        Candidate _e33 = no_candidate(uintBitsToFloat(_e31));
        Candidate _e35 = intersect_object(slot_3, probe, _e33, false);
        if ((_e35.slot != NO_HIT)) {
            Hit _e39 = finish_hit(probe, _e35);
            if (!(_e39.front_face)) {
                return (slot_3 + 1u);
            }
        }
    }
    return 0u;
}

Candidate intersect_scene(Ray ray_7, bool shadow_2) {
    Candidate best_2 = Candidate(0.0, 0u, 0u, vec2(0.0), vec3(0.0));
    uint stack_1[64] = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    uint sp_1 = 0u;
    uint node_1 = 0u;
    uint k_1 = 0u;
    uint near_1 = 0u;
    uint far_1 = 0u;
    Candidate _e3 = no_candidate(ray_7.tmax);
    best_2 = _e3;
    FrameUniforms frame_2 = _group_0_binding_0_cs;
    if ((frame_2.instance_count == 0u)) {
        Candidate _e10 = best_2;
        return _e10;
    }
    vec3 _e12 = safe_inverse(ray_7.dir);
    stack_1 = uint[64](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    sp_1 = 0u;
    node_1 = frame_2.tlas_root;
    uint _e19 = node_1;
    GpuNode root = _group_0_binding_2_cs[_e19];
    float _e28 = best_2.t;
    float _e29 = slab(root.min_, root.max_, ray_7.origin, _e12, ray_7.tmin, _e28);
    uint _e31 = F32_INF;
    if ((_e29 == uintBitsToFloat(_e31))) {
        Candidate _e34 = best_2;
        return _e34;
    }
    while(true) {
        uint _e35 = node_1;
        GpuNode n_6 = _group_0_binding_2_cs[_e35];
        if (((n_6.b & LEAF_BIT) != 0u)) {
            uint count_1 = (n_6.b & ~(LEAF_BIT));
            k_1 = 0u;
            bool loop_init_2 = true;
            while(true) {
                if (!loop_init_2) {
                    uint _e63 = k_1;
                    k_1 = (_e63 + 1u);
                }
                loop_init_2 = false;
                uint _e50 = k_1;
                if ((_e50 >= count_1)) {
                    break;
                }
                uint _e53 = k_1;
                Candidate _e55 = best_2;
                Candidate _e56 = intersect_object((n_6.a + _e53), ray_7, _e55, shadow_2);
                best_2 = _e56;
                uint _e58 = best_2.slot;
                if ((shadow_2 && (_e58 != NO_HIT))) {
                    Candidate _e62 = best_2;
                    return _e62;
                }
            }
        } else {
            uint left_1 = (frame_2.tlas_root + n_6.a);
            uint right_1 = (left_1 + 1u);
            GpuNode l_2 = _group_0_binding_2_cs[left_1];
            GpuNode rr_1 = _group_0_binding_2_cs[right_1];
            float _e82 = best_2.t;
            float _e83 = slab(l_2.min_, l_2.max_, ray_7.origin, _e12, ray_7.tmin, _e82);
            float _e89 = best_2.t;
            float _e90 = slab(rr_1.min_, rr_1.max_, ray_7.origin, _e12, ray_7.tmin, _e89);
            uint _e92 = F32_INF;
            uint _e96 = F32_INF;
            if (((_e83 < uintBitsToFloat(_e92)) && (_e90 < uintBitsToFloat(_e96)))) {
                near_1 = left_1;
                far_1 = right_1;
                if ((_e90 < _e83)) {
                    near_1 = right_1;
                    far_1 = left_1;
                }
                uint _e103 = sp_1;
                if ((_e103 < TLAS_STACK)) {
                    uint _e106 = sp_1;
                    uint _e110 = far_1;
                    stack_1[min(_e106, 63u)] = _e110;
                    uint _e111 = sp_1;
                    sp_1 = (_e111 + 1u);
                }
                uint _e114 = near_1;
                node_1 = _e114;
                continue;
            }
            uint _e116 = F32_INF;
            if ((_e83 < uintBitsToFloat(_e116))) {
                node_1 = left_1;
                continue;
            }
            uint _e120 = F32_INF;
            if ((_e90 < uintBitsToFloat(_e120))) {
                node_1 = right_1;
                continue;
            }
        }
        uint _e123 = sp_1;
        if ((_e123 == 0u)) {
            break;
        }
        uint _e126 = sp_1;
        sp_1 = (_e126 - 1u);
        uint _e129 = sp_1;
        uint _e133 = stack_1[min(_e129, 63u)];
        node_1 = _e133;
    }
    Candidate _e134 = best_2;
    return _e134;
}

ConstantBackground load_ConstantBackground(uint offset_3) {
    uint _e5 = _group_0_binding_6_cs[(offset_3 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_3 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_3 + 2u)];
    return ConstantBackground(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)));
}

vec3 constant_background(ConstantBackground b, Ray ray_8) {
    return b.color;
}

vec3 dispatch_miss(uint type_id_2, uint offset_4, Ray ray_9) {
    ConstantBackground _e2 = load_ConstantBackground(offset_4);
    vec3 _e3 = constant_background(_e2, ray_9);
    return _e3;
}

vec3 miss(Ray ray_10) {
    if (!(HAS_BACKGROUND)) {
        return vec3(0.0);
    }
    FrameUniforms frame_3 = _group_0_binding_0_cs;
    vec3 _e9 = dispatch_miss(frame_3.background_type, frame_3.background_offset, ray_10);
    return _e9;
}

vec3 dispatch_medium(uint type_id_3, uint offset_5, Ray ray_11, float t, vec3 radiance) {
    return vec3(0.0);
}

vec3 through_medium(Ray ray_12, float t_1, vec3 radiance_1) {
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_12.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_7 = _group_0_binding_3_cs[(ray_12.medium - 1u)];
    if (((inst_7.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    vec3 _e21 = dispatch_medium(inst_7.material_type, inst_7.material_offset, ray_12, t_1, radiance_1);
    return _e21;
}

Lambert load_Lambert(uint offset_6) {
    uint _e5 = _group_0_binding_6_cs[(offset_6 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_6 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_6 + 2u)];
    return Lambert(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)));
}

uint light_count_query() {
    FrameUniforms _e1 = _group_0_binding_0_cs;
    return _e1.light_count;
}

PointLight load_PointLight(uint offset_7) {
    uint _e5 = _group_0_binding_6_cs[(offset_7 + 0u)];
    uint _e11 = _group_0_binding_6_cs[(offset_7 + 1u)];
    uint _e17 = _group_0_binding_6_cs[(offset_7 + 2u)];
    uint _e24 = _group_0_binding_6_cs[(offset_7 + 4u)];
    uint _e30 = _group_0_binding_6_cs[(offset_7 + 5u)];
    uint _e36 = _group_0_binding_6_cs[(offset_7 + 6u)];
    uint _e43 = _group_0_binding_6_cs[(offset_7 + 7u)];
    uint _e49 = _group_0_binding_6_cs[(offset_7 + 8u)];
    uint _e55 = _group_0_binding_6_cs[(offset_7 + 9u)];
    return PointLight(vec3(uintBitsToFloat(_e5), uintBitsToFloat(_e11), uintBitsToFloat(_e17)), vec3(uintBitsToFloat(_e24), uintBitsToFloat(_e30), uintBitsToFloat(_e36)), uintBitsToFloat(_e43), uintBitsToFloat(_e49), uintBitsToFloat(_e55));
}

ivec3 vec3i_from_vec3f(vec3 x_1) {
    return mix(ivec3(min(max(x_1, vec3(-2147483600.0)), vec3(2147483500.0))), ivec3(0), greaterThan((floatBitsToUint(x_1) & uvec3(2147483647u)), uvec3(2139095040u)));
}

vec3 offset_origin(vec3 p_2, vec3 n_2) {
    ivec3 _e5 = vec3i_from_vec3f((n_2 * vec3(256.0)));
    vec3 pi = vec3(intBitsToFloat((floatBitsToInt(p_2.x) + ((p_2.x < 0.0) ? -(_e5.x) : _e5.x))), intBitsToFloat((floatBitsToInt(p_2.y) + ((p_2.y < 0.0) ? -(_e5.y) : _e5.y))), intBitsToFloat((floatBitsToInt(p_2.z) + ((p_2.z < 0.0) ? -(_e5.z) : _e5.z))));
    bvec3 small = lessThan(abs(p_2), vec3((1.0 / 32.0)));
    return mix(pi, (p_2 + (n_2 * vec3((1.0 / 65536.0)))), small);
}

float shadow_query(vec3 position, vec3 normal, vec3 dir, float dist) {
    vec3 n_3 = vec3(0.0);
    n_3 = normal;
    vec3 _e5 = n_3;
    if ((dot(dir, _e5) < 0.0)) {
        vec3 _e9 = n_3;
        n_3 = -(_e9);
    }
    vec3 _e11 = n_3;
    vec3 _e12 = offset_origin(position, _e11);
    Ray ray_19 = Ray(_e12, 0.0, dir, (dist * (1.0 - 1e-5)), 0u, RAY_SHADOW, 0u);
    Candidate _e23 = intersect_scene(ray_19, true);
    return ((_e23.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample point_light(PointLight l, vec3 position_1, vec3 normal_1) {
    float strength = 0.0;
    vec3 to_light = (l.position - position_1);
    float dist_1 = length(to_light);
    vec3 dir_3 = (to_light / vec3(max(dist_1, 1e-20)));
    strength = (l.intensity / max((dist_1 * dist_1), 1e-20));
    if ((l.range > 0.0)) {
        float _e19 = strength;
        strength = (_e19 * (1.0 - smoothstep(l.inner_range, l.range, dist_1)));
    }
    float _e26 = shadow_query(position_1, normal_1, dir_3, dist_1);
    float _e28 = strength;
    return LightSample(dir_3, dist_1, ((l.color * vec3(_e28)) * vec3(_e26)));
}

LightSample dispatch_light(uint type_id_4, uint offset_8, vec3 position_2, vec3 normal_2) {
    PointLight _e3 = load_PointLight(offset_8);
    LightSample _e4 = point_light(_e3, position_2, normal_2);
    return _e4;
}

LightSample sample_light_query(uint i_1, vec3 position_3, vec3 normal_3) {
    FrameUniforms frame_4 = _group_0_binding_0_cs;
    if ((i_1 >= frame_4.light_count)) {
        return LightSample(vec3(0.0, 1.0, 0.0), 0.0, vec3(0.0));
    }
    uint entry = (frame_4.light_table + (i_1 * 2u));
    uint _e21 = _group_0_binding_6_cs[entry];
    uint _e26 = _group_0_binding_6_cs[(entry + 1u)];
    LightSample _e27 = dispatch_light(_e21, _e26, position_3, normal_3);
    return _e27;
}

vec3 lambert_shade(Lambert m, Ray ray_13, Hit hit_2) {
    vec3 color = vec3(0.0);
    uint i_2 = 0u;
    vec3 n_7 = faceforward(hit_2.normal, ray_13.dir, hit_2.normal);
    color = vec3(0.0);
    uint _e11 = light_count_query();
    i_2 = 0u;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e33 = i_2;
            i_2 = (_e33 + 1u);
        }
        loop_init_3 = false;
        uint _e13 = i_2;
        if ((_e13 >= _e11)) {
            break;
        }
        uint _e15 = i_2;
        LightSample _e18 = sample_light_query(_e15, hit_2.position, hit_2.geometric_normal);
        vec3 _e19 = color;
        color = (_e19 + (((m.albedo * vec3(INV_PI)) * _e18.radiance) * vec3(max(dot(n_7, _e18.dir), 0.0))));
    }
    vec3 _e36 = color;
    return _e36;
}

vec3 dispatch_closest_hit(uint type_id_5, uint offset_9, Ray ray_14, Hit hit_3, vec3 secondary) {
    Lambert _e3 = load_Lambert(offset_9);
    vec3 _e4 = lambert_shade(_e3, ray_14, hit_3);
    return _e4;
}

vec3 shade_direct(Ray ray_15, Candidate c_2) {
    GpuInstance inst_8 = _group_0_binding_3_cs[c_2.slot];
    Hit _e6 = finish_hit(ray_15, c_2);
    vec3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_15, _e6, vec3(0.0));
    return _e11;
}

void dispatch_secondary_rays(uint type_id_6, uint offset_10, Ray ray_16, Hit hit_4) {
    return;
}

vec3 spawn_origin(Hit hit_5, vec3 dir_1) {
    vec3 n_4 = vec3(0.0);
    n_4 = hit_5.geometric_normal;
    vec3 _e4 = n_4;
    if ((dot(dir_1, _e4) < 0.0)) {
        vec3 _e8 = n_4;
        n_4 = -(_e8);
    }
    vec3 _e11 = n_4;
    vec3 _e12 = offset_origin(hit_5.position, _e11);
    return _e12;
}

vec3 trace(Ray camera_ray) {
    Frame stack_2[1] = Frame[1](Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u));
    uint depth = 0u;
    Ray ray_17 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    vec3 value = vec3(0.0);
    bool have_value = false;
    bool pushed = false;
    Frame f = Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u);
    uint i_3 = 0u;
    uint medium = 0u;
    if (!(HAS_SECONDARY_RAYS)) {
        Candidate _e4 = intersect_scene(camera_ray, false);
        if ((_e4.slot == NO_HIT)) {
            uint _e9 = F32_INF;
            vec3 _e11 = miss(camera_ray);
            vec3 _e12 = through_medium(camera_ray, uintBitsToFloat(_e9), _e11);
            return _e12;
        }
        vec3 _e14 = shade_direct(camera_ray, _e4);
        vec3 _e15 = through_medium(camera_ray, _e4.t, _e14);
        return _e15;
    }
    stack_2 = Frame[1](Frame(Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u), Hit(vec3(0.0), 0.0, vec3(0.0), vec3(0.0), vec2(0.0), false, 0u, 0u), 0u, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), 0u, 0u));
    depth = 0u;
    ray_17 = camera_ray;
    value = vec3(0.0);
    have_value = false;
    while(true) {
        bool _e26 = have_value;
        if (!(_e26)) {
            Ray _e28 = ray_17;
            Candidate _e30 = intersect_scene(_e28, false);
            if ((_e30.slot == NO_HIT)) {
                Ray _e34 = ray_17;
                uint _e36 = F32_INF;
                Ray _e38 = ray_17;
                vec3 _e39 = miss(_e38);
                vec3 _e40 = through_medium(_e34, uintBitsToFloat(_e36), _e39);
                value = _e40;
                have_value = true;
            } else {
                GpuInstance inst_9 = _group_0_binding_3_cs[_e30.slot];
                Ray _e46 = ray_17;
                Hit _e47 = finish_hit(_e46, _e30);
                pushed = false;
                uint _e56 = ray_17.depth;
                uint _e60 = depth;
                if (((((inst_9.flags & FLAG_SECONDARY) != 0u) && (_e56 < MAX_DEPTH)) && (_e60 < STACK_SIZE))) {
                    spawn_count = 0u;
                    Ray _e68 = ray_17;
                    dispatch_secondary_rays(inst_9.material_type, inst_9.material_offset, _e68, _e47);
                    uint _e70 = spawn_count;
                    uint n_8 = min(min(_e70, 1u), MAX_SPAWN);
                    if ((n_8 > 0u)) {
                        Ray _e77 = ray_17;
                        f = Frame(_e77, _e47, _e30.slot, vec3(0.0), vec3[1](vec3(0.0)), vec3[1](vec3(0.0)), n_8, 0u);
                        i_3 = 0u;
                        bool loop_init_4 = true;
                        while(true) {
                            if (!loop_init_4) {
                                uint _e108 = i_3;
                                i_3 = (_e108 + 1u);
                            }
                            loop_init_4 = false;
                            uint _e88 = i_3;
                            if ((_e88 >= n_8)) {
                                break;
                            }
                            uint _e91 = i_3;
                            uint _e95 = i_3;
                            vec3 _e98 = spawn_dirs[_e95];
                            f.dirs[min(_e91, 0u)] = _e98;
                            uint _e100 = i_3;
                            uint _e104 = i_3;
                            vec3 _e107 = spawn_weights[_e104];
                            f.weights[min(_e100, 0u)] = _e107;
                        }
                        uint _e111 = depth;
                        Frame _e115 = f;
                        stack_2[min(_e111, 0u)] = _e115;
                        uint _e116 = depth;
                        depth = (_e116 + 1u);
                        pushed = true;
                    }
                }
                bool _e120 = pushed;
                if (!(_e120)) {
                    Ray _e124 = ray_17;
                    vec3 _e127 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, _e124, _e47, vec3(0.0));
                    Ray _e128 = ray_17;
                    vec3 _e130 = through_medium(_e128, _e30.t, _e127);
                    value = _e130;
                    have_value = true;
                }
            }
        }
        bool _e132 = have_value;
        if (_e132) {
            uint _e133 = depth;
            if ((_e133 == 0u)) {
                vec3 _e136 = value;
                return _e136;
            }
            uint _e137 = depth;
            uint top = (_e137 - 1u);
            uint _e144 = stack_2[min(top, 0u)].next;
            uint child = (_e144 - 1u);
            vec3 _e151 = stack_2[min(top, 0u)].sum;
            vec3 _e159 = stack_2[min(top, 0u)].weights[min(child, 0u)];
            vec3 _e160 = value;
            stack_2[min(top, 0u)].sum = (_e151 + (_e159 * _e160));
            have_value = false;
        }
        uint _e164 = depth;
        uint top_1 = (_e164 - 1u);
        uint _e171 = stack_2[min(top_1, 0u)].next;
        uint _e176 = stack_2[min(top_1, 0u)].count;
        if ((_e171 < _e176)) {
            uint i_4 = stack_2[min(top_1, 0u)].next;
            stack_2[min(top_1, 0u)].next = (i_4 + 1u);
            Ray parent = stack_2[min(top_1, 0u)].ray;
            Hit hit_7 = stack_2[min(top_1, 0u)].hit;
            vec3 dir_4 = stack_2[min(top_1, 0u)].dirs[min(i_4, 0u)];
            medium = parent.medium;
            vec3 _e209 = spawn_origin(hit_7, dir_4);
            uint _e212 = F32_INF;
            uint _e218 = medium;
            ray_17 = Ray(_e209, 0.0, dir_4, uintBitsToFloat(_e212), (parent.depth + 1u), RAY_SECONDARY, _e218);
        } else {
            uint _e224 = stack_2[min(top_1, 0u)].slot;
            GpuInstance inst_10 = _group_0_binding_3_cs[_e224];
            Ray _e234 = stack_2[min(top_1, 0u)].ray;
            Hit _e239 = stack_2[min(top_1, 0u)].hit;
            vec3 _e244 = stack_2[min(top_1, 0u)].sum;
            vec3 _e245 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e234, _e239, _e244);
            Ray _e250 = stack_2[min(top_1, 0u)].ray;
            float _e256 = stack_2[min(top_1, 0u)].hit.t;
            vec3 _e257 = through_medium(_e250, _e256, _e245);
            value = _e257;
            depth = top_1;
            have_value = true;
        }
    }
    return vec3(0.0);
}

bvec3 is_finite_vec3f(vec3 x_2) {
    return lessThan((floatBitsToUint(x_2) & uvec3(2147483647u)), uvec3(2139095040u));
}

vec3 finite_or_zero(vec3 c_3) {
    bvec3 _e3 = is_finite_vec3f(c_3);
    return mix(vec3(0.0), c_3, _e3);
}

void render_pixel(uvec2 pixel_3) {
    vec3 sum = vec3(0.0);
    uint bad = 0u;
    uint s = 0u;
    Ray ray_18 = Ray(vec3(0.0), 0.0, vec3(0.0), 0.0, 0u, 0u, 0u);
    FrameUniforms frame_5 = _group_0_binding_0_cs;
    TileParams tile_1 = _group_0_binding_1_cs;
    sum = vec3(0.0);
    bad = 0u;
    uint end_1 = frame_5.samples_per_pass;
    s = 0u;
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e45 = s;
            s = (_e45 + 1u);
        }
        loop_init_5 = false;
        uint _e13 = s;
        if ((_e13 >= end_1)) {
            break;
        }
        uint _e18 = s;
        uint sample_3 = ((tile_1.frame * frame_5.samples_per_pass) + _e18);
        rng_seed(pixel_3, sample_3, frame_5.seed);
        Ray _e23 = dispatch_ray_generation(frame_5.camera_type, frame_5.camera_offset, pixel_3, sample_3);
        ray_18 = _e23;
        ray_18.depth = 0u;
        ray_18.kind = RAY_CAMERA;
        vec3 _e31 = ray_18.origin;
        uint _e32 = medium_at(_e31);
        ray_18.medium = _e32;
        Ray _e33 = ray_18;
        vec3 _e34 = trace(_e33);
        bvec3 _e35 = is_finite_vec3f(_e34);
        if (all(_e35)) {
            vec3 _e37 = sum;
            sum = (_e37 + _e34);
        } else {
            vec3 _e39 = sum;
            vec3 _e40 = finite_or_zero(_e34);
            sum = (_e39 + _e40);
            uint _e42 = bad;
            bad = (_e42 + 1u);
        }
    }
    vec3 _e54 = sum;
    uint _e58 = bad;
    vec4 _e61 = _group_0_binding_8_cs[((pixel_3.y * tile_1.image_size.x) + pixel_3.x)];
    _group_0_binding_8_cs[((pixel_3.y * tile_1.image_size.x) + pixel_3.x)] = (_e61 + vec4(_e54, float(frame_5.samples_per_pass)));
    if ((_e58 > 0u)) {
        atomicAdd(_group_0_binding_9_cs[0], _e58);
    }
    return;
}

void main() {
    uvec3 gid = gl_GlobalInvocationID;
    TileParams _e2 = _group_0_binding_1_cs;
    uvec2 _e7 = uvec2(gid.x, gid.y);
    if (any(greaterThanEqual(_e7, _e2.extent))) {
        return;
    }
    render_pixel((_e2.origin + _e7));
    return;
}

