// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
};

struct type_3 {
    float inner[4];
};
struct Pair {
    metal::packed_float3 a;
    float b;
};
struct Input {
    metal::float4 v;
    uint i;
    char _pad2[12];
};
struct Output {
    metal::float4 result;
};
typedef Input type_6[1];
typedef Output type_7[1];

metal::float3 combine(
    Pair p,
    metal::float3x3 m
) {
    return (m * metal::float3(p.a)) * metal::float3(p.b);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

metal::float4 test_fn(
    metal::float4 v,
    uint i
) {
    type_3 table = {};
    table = type_3 {{1.0, 2.0, 3.0, 4.0}};
    table.inner[metal::min(naga_mod(i, 4u), 3u)] = v.w;
    Pair p_1 = Pair {v.xyz, 2.0};
    metal::float3 _e30 = combine(p_1, metal::float3x3(metal::float3(1.0, 0.0, 0.0), metal::float3(0.0, 1.0, 0.0), metal::float3(0.0, 0.0, 1.0)));
    float _e39 = table.inner[metal::min(naga_mod(i + 1u, 4u), 3u)];
    return metal::float4(_e30.zyx, _e39);
}

struct main_Input {
};
[[max_total_threads_per_threadgroup(64)]] kernel void main_(
  metal::uint3 id [[thread_position_in_grid]]
, device type_6 const& input [[buffer(0)]]
, device type_7& output [[buffer(1)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(2)]]
) {
    uint index = id.x;
    if (index >= (1 + (_buffer_sizes.size0 - 0 - 32) / 32)) {
        return;
    }
    metal::float4 _e8 = input[index].v;
    uint _e10 = input[index].i;
    metal::float4 _e11 = test_fn(_e8, _e10);
    output[index].result = _e11;
}
