// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
};

struct Input {
    int a;
    int b;
    float x;
};
struct Output {
    float result;
};
typedef Input type_2[1];
typedef Output type_3[1];

int naga_div(int lhs, int rhs) {
    return lhs / metal::select(rhs, 1, (lhs == (-2147483647 - 1) & rhs == -1) | (rhs == 0));
}

int div_i32_(
    int a,
    int b
) {
    bool by_zero = b == 0;
    int divisor = ((a == (-2147483647 - 1)) & (b == -1)) ? 1 : (by_zero ? 1 : b);
    return naga_div(a, divisor);
}

int rem_i32_(
    int a_1,
    int b_1
) {
    bool by_zero_1 = b_1 == 0;
    int divisor_1 = ((a_1 == (-2147483647 - 1)) & (b_1 == -1)) ? 1 : (by_zero_1 ? 1 : b_1);
    return by_zero_1 ? 0 : as_type<int>(as_type<uint>(a_1) - as_type<uint>(as_type<int>(as_type<uint>(divisor_1) * as_type<uint>(naga_div(a_1, divisor_1)))));
}

float test_fn(
    int a_2,
    int b_2,
    float x
) {
    int _e3 = div_i32_(a_2, b_2);
    int _e4 = rem_i32_(a_2, b_2);
    return (static_cast<float>(as_type<int>(as_type<uint>(_e3) + as_type<uint>(_e4))) * x) + metal::sqrt(metal::abs(x));
}

struct main_Input {
};
[[max_total_threads_per_threadgroup(64)]] kernel void main_(
  metal::uint3 id [[thread_position_in_grid]]
, device type_2 const& input [[buffer(0)]]
, device type_3& output [[buffer(1)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(2)]]
) {
    uint index = id.x;
    if (index >= (1 + (_buffer_sizes.size0 - 0 - 12) / 12)) {
        return;
    }
    int _e8 = input[index].a;
    int _e10 = input[index].b;
    float _e12 = input[index].x;
    float _e13 = test_fn(_e8, _e10, _e12);
    output[index].result = _e13;
}
