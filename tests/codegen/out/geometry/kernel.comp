#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Ray {
    vec3 origin;
    float tmin;
    vec3 dir;
    float tmax;
    uint depth;
    uint kind;
    uint medium;
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
struct Input {
    vec3 o;
    vec3 d;
};
struct Output {
    vec3 result;
};
uint F32_INF = 2139095040u;

uint F32_NEG_INF = 4286578688u;

layout(std430, binding = 0) readonly buffer type_4_block_0Compute { Input _group_0_binding_0_cs[]; };

layout(std430, binding = 1) buffer type_5_block_1Compute { Output _group_0_binding_1_cs[]; };


vec3 normalize_vec3f(vec3 v) {
    return ((dot(v, v) >= 1.1754944e-38) ? normalize(v) : vec3(0.0));
}

Intersection intersect_triangle(Ray ray, Triangle tri) {
    uvec3 _e10 = uvec3(2139095040u);
    vec3 dir = mix(ray.dir, vec3(0.0), lessThan(abs(ray.dir), vec3(1.1754944e-38)));
    vec3 _e31 = abs(dir);
    bool _e38 = (_e31.y > _e31.x);
    uint kz = ((_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u));
    uint _e45 = ((kz == 2u) ? 0u : (kz + 1u));
    uint _e49 = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = dir[kz];
    bool _e52 = (dz < 0.0);
    uint kx = (_e52 ? _e49 : _e45);
    uint ky = (_e52 ? _e45 : _e49);
    float sx = (dir[kx] / dz);
    float sy = (dir[ky] / dz);
    float sz = (1.0 / dz);
    vec3 _e62 = (tri.v0_ - ray.origin);
    float _e68 = (_e62[kx] - (sx * _e62[kz]));
    float _e69 = (_e62[ky] - (sy * _e62[kz]));
    vec3 _e71 = (tri.v1_ - ray.origin);
    float _e77 = (_e71[kx] - (sx * _e71[kz]));
    float _e78 = (_e71[ky] - (sy * _e71[kz]));
    vec3 _e80 = (tri.v2_ - ray.origin);
    float _e86 = (_e80[kx] - (sx * _e80[kz]));
    float _e87 = (_e80[ky] - (sy * _e80[kz]));
    float u = ((_e86 * _e78) - (_e87 * _e77));
    float v_1 = ((_e68 * _e87) - (_e69 * _e86));
    float w = ((_e77 * _e69) - (_e78 * _e68));
    float det = ((u + v_1) + w);
    float _e112 = (1.0 / det);
    float t = ((((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112);
    bool hit = (((((all(lessThan((floatBitsToUint(ray.origin) & uvec3(2147483647u)), _e10)) && all(lessThan((floatBitsToUint(ray.dir) & uvec3(2147483647u)), _e10))) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t >= ray.tmin) && (t <= ray.tmax)));
    vec3 _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    uint _e137 = F32_INF;
    return Intersection((hit ? t : uintBitsToFloat(_e137)), (hit ? _e132 : vec3(0.0, 0.0, 1.0)), (hit ? vec2((v_1 * _e112), (w * _e112)) : vec2(0.0)));
}

vec2 intersect_aabb(Ray ray_1, vec3 min_, vec3 max_) {
    bvec3 parallel = lessThan(abs(ray_1.dir), vec3(1.1754944e-38));
    vec3 _e12 = vec3(1.0);
    vec3 inv_dir = (_e12 / mix(ray_1.dir, _e12, parallel));
    vec3 _e17 = ((min_ - ray_1.origin) * inv_dir);
    vec3 _e18 = ((max_ - ray_1.origin) * inv_dir);
    bvec3 _e23 = bvec3(lessThanEqual(min_, ray_1.origin).x && lessThanEqual(ray_1.origin, max_).x, lessThanEqual(min_, ray_1.origin).y && lessThanEqual(ray_1.origin, max_).y, lessThanEqual(min_, ray_1.origin).z && lessThanEqual(ray_1.origin, max_).z);
    uint _e25 = F32_INF;
    vec3 _e27 = vec3(uintBitsToFloat(_e25));
    uint _e29 = F32_NEG_INF;
    vec3 _e31 = vec3(uintBitsToFloat(_e29));
    vec3 near = mix(min(_e17, _e18), mix(_e27, _e31, _e23), parallel);
    vec3 far = mix(max(_e17, _e18), mix(_e31, _e27, _e23), parallel);
    return vec2(max(max(max(near.x, near.y), near.z), ray_1.tmin), min(min(min(far.x, far.y), far.z), ray_1.tmax));
}

vec3 test_fn(vec3 o, vec3 d) {
    uint _e4 = F32_INF;
    Ray ray_2 = Ray(o, 0.0, d, uintBitsToFloat(_e4), 0u, 0u, 0u);
    Triangle tri_1 = Triangle(vec3(-1.0, -1.0, 0.0), vec3(1.0, -1.0, 0.0), vec3(0.0, 1.0, 0.0));
    Intersection _e23 = intersect_triangle(ray_2, tri_1);
    vec2 _e28 = intersect_aabb(ray_2, vec3(-1.0), vec3(1.0));
    return vec3(((_e23.t < 1e30) ? _e23.t : -1.0), _e28.x, _e28.y);
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint index = id.x;
    if ((index >= uint(_group_0_binding_0_cs.length()))) {
        return;
    }
    vec3 _e8 = _group_0_binding_0_cs[index].o;
    vec3 _e10 = _group_0_binding_0_cs[index].d;
    vec3 _e11 = test_fn(_e8, _e10);
    _group_0_binding_1_cs[index].result = _e11;
}

