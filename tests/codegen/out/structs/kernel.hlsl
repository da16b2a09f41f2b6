struct Pair {
    float3 a;
    float b;
};

struct Input {
    float4 v;
    uint i;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct Output {
    float4 result;
};

ByteAddressBuffer input : register(t0);
RWByteAddressBuffer output : register(u1);

float3 combine(Pair p, float3x3 m)
{
    return (mul(p.a, m) * (p.b).xxx);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

typedef float ret_Constructarray4_float_[4];
ret_Constructarray4_float_ Constructarray4_float_(float arg0, float arg1, float arg2, float arg3) {
    float ret[4] = { arg0, arg1, arg2, arg3 };
    return ret;
}

Pair ConstructPair(float3 arg0, float arg1) {
    Pair ret = (Pair)0;
    ret.a = arg0;
    ret.b = arg1;
    return ret;
}

float4 test_fn(float4 v, uint i)
{
    float table[4] = (float[4])0;

    table = Constructarray4_float_(1.0, 2.0, 3.0, 4.0);
    table[min(uint(min(naga_mod(i, 4u), 3u)), 3u)] = v.w;
    Pair p_1 = ConstructPair(v.xyz, 2.0);
    const float3 _e30 = combine(p_1, float3x3(float3(1.0, 0.0, 0.0), float3(0.0, 1.0, 0.0), float3(0.0, 0.0, 1.0)));
    float _e39 = table[min(uint(min(naga_mod((i + 1u), 4u), 3u)), 3u)];
    return float4(_e30.zyx, _e39);
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
    if ((index >= ((NagaBufferLength(input) - 0) / 32))) {
        return;
    }
    float4 _e8 = asfloat(input.Load4(0+index*32));
    uint _e10 = asuint(input.Load(16+index*32));
    const float4 _e11 = test_fn(_e8, _e10);
    output.Store4(0+index*16, asuint(_e11));
}
