// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
};

struct Input {
    uint n;
    uint limit;
};
struct Output {
    uint result;
};
typedef Input type_1[1];
typedef Output type_2[1];

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint test_fn(
    uint n,
    uint limit
) {
    uint total = {};
    uint i = {};
    uint k = {};
    total = 0u;
    i = 0u;
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e27 = i;
            i = _e27 + 1u;
        }
        loop_init = false;
        uint _e6 = i;
        if (_e6 >= n) {
            break;
        }
        uint _e8 = i;
        uint _e13 = i;
        if ((naga_mod(_e8, 3u) == 0u) && (_e13 != 0u)) {
            continue;
        }
        uint _e17 = total;
        uint _e18 = i;
        total = _e17 + _e18;
        uint _e20 = total;
        uint _e22 = i;
        if ((_e20 > limit) || (_e22 > 100u)) {
            uint _e26 = total;
            return _e26;
        }
    }
    k = 0u;
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e32 = k;
        if (!((_e32 < 4u))) {
            break;
        }
        uint _e36 = k;
        k = _e36 + 1u;
    }
    uint _e39 = total;
    uint _e40 = k;
    return _e39 + _e40;
}

struct main_Input {
};
[[max_total_threads_per_threadgroup(64)]] kernel void main_(
  metal::uint3 id [[thread_position_in_grid]]
, device type_1 const& input [[buffer(0)]]
, device type_2& output [[buffer(1)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(2)]]
) {
    uint index = id.x;
    if (index >= (1 + (_buffer_sizes.size0 - 0 - 8) / 8)) {
        return;
    }
    uint _e8 = input[index].n;
    uint _e10 = input[index].limit;
    uint _e11 = test_fn(_e8, _e10);
    output[index].result = _e11;
}
