struct Input {
    int a;
    int b;
    float x;
};

struct Output {
    float result;
};

ByteAddressBuffer input : register(t0);
RWByteAddressBuffer output : register(u1);

int naga_div(int lhs, int rhs) {
    return lhs / (((lhs == int(-2147483647 - 1) & rhs == -1) | (rhs == 0)) ? 1 : rhs);
}

int div_i32_(int a, int b)
{
    bool by_zero = (b == int(0));
    int divisor = (((a == int(-2147483647 - 1)) & (b == int(-1))) ? int(1) : (by_zero ? int(1) : b));
    return naga_div(a, divisor);
}

int rem_i32_(int a_1, int b_1)
{
    bool by_zero_1 = (b_1 == int(0));
    int divisor_1 = (((a_1 == int(-2147483647 - 1)) & (b_1 == int(-1))) ? int(1) : (by_zero_1 ? int(1) : b_1));
    return (by_zero_1 ? int(0) : asint(asuint(a_1) - asuint(asint(asuint(divisor_1) * asuint(naga_div(a_1, divisor_1))))));
}

float test_fn(int a_2, int b_2, float x)
{
    const int _e3 = div_i32_(a_2, b_2);
    const int _e4 = rem_i32_(a_2, b_2);
    return ((float(asint(asuint(_e3) + asuint(_e4))) * x) + sqrt(abs(x)));
}

uint NagaBufferLength(ByteAddressBuffer buffer)
{
    uint ret;
    buffer.GetDimensions(ret);
    return ret;
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint index = id.x;
    if ((index >= ((NagaBufferLength(input) - 0) / 12))) {
        return;
    }
    int _e8 = asint(input.Load(0+index*12));
    int _e10 = asint(input.Load(4+index*12));
    float _e12 = asfloat(input.Load(8+index*12));
    const float _e13 = test_fn(_e8, _e10, _e12);
    output.Store(0+index*4, asuint(_e13));
}
