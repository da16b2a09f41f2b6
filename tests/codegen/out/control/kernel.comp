#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct Input {
    uint n;
    uint limit;
};
struct Output {
    uint result;
};
layout(std430, binding = 0) readonly buffer type_1_block_0Compute { Input _group_0_binding_0_cs[]; };

layout(std430, binding = 1) buffer type_2_block_1Compute { Output _group_0_binding_1_cs[]; };


uint test_fn(uint n, uint limit) {
    uint total = 0u;
    uint i = 0u;
    uint k = 0u;
    total = 0u;
    i = 0u;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e27 = i;
            i = (_e27 + 1u);
        }
        loop_init = false;
        uint _e6 = i;
        if ((_e6 >= n)) {
            break;
        }
        uint _e8 = i;
        uint _e13 = i;
        if ((((_e8 % 3u) == 0u) && (_e13 != 0u))) {
            continue;
        }
        uint _e17 = total;
        uint _e18 = i;
        total = (_e17 + _e18);
        uint _e20 = total;
        uint _e22 = i;
        if (((_e20 > limit) || (_e22 > 100u))) {
            uint _e26 = total;
            return _e26;
        }
    }
    k = 0u;
    while(true) {
        uint _e32 = k;
        if (!((_e32 < 4u))) {
            break;
        }
        uint _e36 = k;
        k = (_e36 + 1u);
    }
    uint _e39 = total;
    uint _e40 = k;
    return (_e39 + _e40);
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint index = id.x;
    if ((index >= uint(_group_0_binding_0_cs.length()))) {
        return;
    }
    uint _e8 = _group_0_binding_0_cs[index].n;
    uint _e10 = _group_0_binding_0_cs[index].limit;
    uint _e11 = test_fn(_e8, _e10);
    _group_0_binding_1_cs[index].result = _e11;
}

