struct Input {
    uint n;
    uint limit;
};

struct Output {
    uint result;
};

ByteAddressBuffer input : register(t0);
RWByteAddressBuffer output : register(u1);

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint test_fn(uint n, uint limit)
{
    uint total = (uint)0;
    uint i = (uint)0;
    uint k = (uint)0;

    total = 0u;
    i = 0u;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
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
        if (((naga_mod(_e8, 3u) == 0u) && (_e13 != 0u))) {
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
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
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
    if ((index >= ((NagaBufferLength(input) - 0) / 8))) {
        return;
    }
    uint _e8 = asuint(input.Load(0+index*8));
    uint _e10 = asuint(input.Load(4+index*8));
    const uint _e11 = test_fn(_e8, _e10);
    output.Store(0+index*4, asuint(_e11));
}
