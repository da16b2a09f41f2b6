struct Ray {
    float3 origin;
    float tmin;
    float3 dir;
    float tmax;
    uint depth;
    uint kind;
    uint medium;
    int _end_pad_0;
};

struct Triangle {
    float3 v0_;
    int _pad1_0;
    float3 v1_;
    int _pad2_0;
    float3 v2_;
    int _end_pad_0;
};

struct Intersection {
    float t;
    int _pad1_0;
    int _pad1_1;
    int _pad1_2;
    float3 normal;
    int _pad2_0;
    float2 uv;
    int _end_pad_0;
    int _end_pad_1;
};

struct Input {
    float3 o;
    int _pad1_0;
    float3 d;
    int _end_pad_0;
};

struct Output {
    float3 result;
    int _end_pad_0;
};

static uint F32_INF = 2139095040u;
static uint F32_NEG_INF = 4286578688u;
ByteAddressBuffer input : register(t0);
RWByteAddressBuffer output : register(u1);

float3 normalize_vec3f(float3 v)
{
    return ((dot(v, v) >= 1.1754944e-38) ? normalize(v) : (0.0).xxx);
}

Intersection ConstructIntersection(float arg0, float3 arg1, float2 arg2) {
    Intersection ret = (Intersection)0;
    ret.t = arg0;
    ret.normal = arg1;
    ret.uv = arg2;
    return ret;
}

Intersection intersect_triangle(Ray ray, Triangle tri)
{
    uint3 _e10 = (2139095040u).xxx;
    float3 dir = ((abs(ray.dir) < (1.1754944e-38).xxx) ? (0.0).xxx : ray.dir);
    float3 _e31 = abs(dir);
    bool _e38 = (_e31.y > _e31.x);
    uint kz = ((_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u));
    uint _e45 = ((kz == 2u) ? 0u : (kz + 1u));
    uint _e49 = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = dir[min(uint(kz), 2u)];
    bool _e52 = (dz < 0.0);
    uint kx = (_e52 ? _e49 : _e45);
    uint ky = (_e52 ? _e45 : _e49);
    float sx = (dir[min(uint(kx), 2u)] / dz);
    float sy = (dir[min(uint(ky), 2u)] / dz);
    float sz = (1.0 / dz);
    float3 _e62 = (tri.v0_ - ray.origin);
    float _e68 = (_e62[min(uint(kx), 2u)] - (sx * _e62[min(uint(kz), 2u)]));
    float _e69 = (_e62[min(uint(ky), 2u)] - (sy * _e62[min(uint(kz), 2u)]));
    float3 _e71 = (tri.v1_ - ray.origin);
    float _e77 = (_e71[min(uint(kx), 2u)] - (sx * _e71[min(uint(kz), 2u)]));
    float _e78 = (_e71[min(uint(ky), 2u)] - (sy * _e71[min(uint(kz), 2u)]));
    float3 _e80 = (tri.v2_ - ray.origin);
    float _e86 = (_e80[min(uint(kx), 2u)] - (sx * _e80[min(uint(kz), 2u)]));
    float _e87 = (_e80[min(uint(ky), 2u)] - (sy * _e80[min(uint(kz), 2u)]));
    float u = ((_e86 * _e78) - (_e87 * _e77));
    float v_1 = ((_e68 * _e87) - (_e69 * _e86));
    float w = ((_e77 * _e69) - (_e78 * _e68));
    float det = ((u + v_1) + w);
    float _e112 = (1.0 / det);
    float t = ((((u * (sz * _e62[min(uint(kz), 2u)])) + (v_1 * (sz * _e71[min(uint(kz), 2u)]))) + (w * (sz * _e80[min(uint(kz), 2u)]))) * _e112);
    bool hit = (((((all(((asuint(ray.origin) & (2147483647u).xxx) < _e10)) && all(((asuint(ray.dir) & (2147483647u).xxx) < _e10))) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t >= ray.tmin) && (t <= ray.tmax)));
    const float3 _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    uint _e137 = F32_INF;
    const Intersection intersection = ConstructIntersection((hit ? t : asfloat(_e137)), (hit ? _e132 : float3(0.0, 0.0, 1.0)), (hit ? float2((v_1 * _e112), (w * _e112)) : (0.0).xx));
    return intersection;
}

float2 intersect_aabb(Ray ray_1, float3 min_, float3 max_)
{
    bool3 parallel = (abs(ray_1.dir) < (1.1754944e-38).xxx);
    float3 _e12 = (1.0).xxx;
    float3 inv_dir = (_e12 / (parallel ? _e12 : ray_1.dir));
    float3 _e17 = ((min_ - ray_1.origin) * inv_dir);
    float3 _e18 = ((max_ - ray_1.origin) * inv_dir);
    bool3 _e23 = ((min_ <= ray_1.origin) & (ray_1.origin <= max_));
    uint _e25 = F32_INF;
    float3 _e27 = (asfloat(_e25)).xxx;
    uint _e29 = F32_NEG_INF;
    float3 _e31 = (asfloat(_e29)).xxx;
    float3 near = (parallel ? (_e23 ? _e31 : _e27) : min(_e17, _e18));
    float3 far = (parallel ? (_e23 ? _e27 : _e31) : max(_e17, _e18));
    return float2(max(max(max(near.x, near.y), near.z), ray_1.tmin), min(min(min(far.x, far.y), far.z), ray_1.tmax));
}

Ray ConstructRay(float3 arg0, float arg1, float3 arg2, float arg3, uint arg4, uint arg5, uint arg6) {
    Ray ret = (Ray)0;
    ret.origin = arg0;
    ret.tmin = arg1;
    ret.dir = arg2;
    ret.tmax = arg3;
    ret.depth = arg4;
    ret.kind = arg5;
    ret.medium = arg6;
    return ret;
}

Triangle ConstructTriangle(float3 arg0, float3 arg1, float3 arg2) {
    Triangle ret = (Triangle)0;
    ret.v0_ = arg0;
    ret.v1_ = arg1;
    ret.v2_ = arg2;
    return ret;
}

float3 test_fn(float3 o, float3 d)
{
    uint _e4 = F32_INF;
    Ray ray_2 = ConstructRay(o, 0.0, d, asfloat(_e4), 0u, 0u, 0u);
    Triangle tri_1 = ConstructTriangle(float3(-1.0, -1.0, 0.0), float3(1.0, -1.0, 0.0), float3(0.0, 1.0, 0.0));
    const Intersection _e23 = intersect_triangle(ray_2, tri_1);
    const float2 _e28 = intersect_aabb(ray_2, (-1.0).xxx, (1.0).xxx);
    return float3(((_e23.t < 1e30) ? _e23.t : -1.0), _e28.x, _e28.y);
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
    float3 _e8 = asfloat(input.Load3(0+index*32));
    float3 _e10 = asfloat(input.Load3(16+index*32));
    const float3 _e11 = test_fn(_e8, _e10);
    output.Store3(0+index*16, asuint(_e11));
}
