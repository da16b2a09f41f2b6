#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Pair {
    vec3 a;
    float b;
};
struct Input {
    vec4 v;
    uint i;
};
struct Output {
    vec4 result;
};
layout(std430, binding = 0) readonly buffer type_6_block_0Compute { Input _group_0_binding_0_cs[]; };

layout(std430, binding = 1) buffer type_7_block_1Compute { Output _group_0_binding_1_cs[]; };


vec3 combine(Pair p, mat3x3 m) {
    return ((m * p.a) * vec3(p.b));
}

vec4 test_fn(vec4 v, uint i) {
    float table[4] = float[4](0.0, 0.0, 0.0, 0.0);
    table = float[4](1.0, 2.0, 3.0, 4.0);
    table[min((i % 4u), 3u)] = v.w;
    Pair p_1 = Pair(v.xyz, 2.0);
    vec3 _e30 = combine(p_1, mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0)));
    float _e39 = table[min(((i + 1u) % 4u), 3u)];
    return vec4(_e30.zyx, _e39);
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint index = id.x;
    if ((index >= uint(_group_0_binding_0_cs.length()))) {
        return;
    }
    vec4 _e8 = _group_0_binding_0_cs[index].v;
    uint _e10 = _group_0_binding_0_cs[index].i;
    vec4 _e11 = test_fn(_e8, _e10);
    _group_0_binding_1_cs[index].result = _e11;
}

