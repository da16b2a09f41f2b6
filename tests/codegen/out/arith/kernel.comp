#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Input {
    int a;
    int b;
    float x;
};
struct Output {
    float result;
};
layout(std430, binding = 0) readonly buffer type_2_block_0Compute { Input _group_0_binding_0_cs[]; };

layout(std430, binding = 1) buffer type_3_block_1Compute { Output _group_0_binding_1_cs[]; };


int div_i32_(int a, int b) {
    bool by_zero = (b == 0);
    int divisor = (((a == -2147483648) && (b == -1)) ? 1 : (by_zero ? 1 : b));
    return (a / divisor);
}

int rem_i32_(int a_1, int b_1) {
    bool by_zero_1 = (b_1 == 0);
    int divisor_1 = (((a_1 == -2147483648) && (b_1 == -1)) ? 1 : (by_zero_1 ? 1 : b_1));
    return (by_zero_1 ? 0 : (a_1 - (divisor_1 * (a_1 / divisor_1))));
}

float test_fn(int a_2, int b_2, float x) {
    int _e3 = div_i32_(a_2, b_2);
    int _e4 = rem_i32_(a_2, b_2);
    return ((float((_e3 + _e4)) * x) + sqrt(abs(x)));
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint index = id.x;
    if ((index >= uint(_group_0_binding_0_cs.length()))) {
        return;
    }
    int _e8 = _group_0_binding_0_cs[index].a;
    int _e10 = _group_0_binding_0_cs[index].b;
    float _e12 = _group_0_binding_0_cs[index].x;
    float _e13 = test_fn(_e8, _e10, _e12);
    _group_0_binding_1_cs[index].result = _e13;
}

