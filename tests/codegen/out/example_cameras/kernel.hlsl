struct TileParams {
    uint2 origin;
    uint2 extent;
    uint2 image_size;
    uint tile_index;
    uint frame;
};

struct FrameUniforms {
    uint samples_per_pass;
    uint total_samples;
    uint seed;
    uint tlas_root;
    uint instance_count;
    uint light_count;
    uint light_table;
    uint medium_count;
    uint medium_table;
    uint camera_type;
    uint camera_offset;
    uint background_type;
    uint background_offset;
    uint path_slots;
    uint passes_per_dispatch;
};

struct PassSum {
    float3 sum;
    uint bad;
};

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

struct Pinhole {
    float3 position;
    int _pad1_0;
    float3 look_at;
    int _pad2_0;
    float3 up;
    float fov;
};

struct Candidate {
    float t;
    uint slot;
    uint primitive;
    int _pad3_0;
    float2 uv;
    int _pad4_0;
    int _pad4_1;
    float3 normal;
    int _end_pad_0;
};

struct GpuInstance {
    float4 world_to_object_0_;
    float4 world_to_object_1_;
    float4 world_to_object_2_;
    float4 object_to_world_0_;
    float4 object_to_world_1_;
    float4 object_to_world_2_;
    uint geometry_type;
    uint geometry_offset;
    uint material_type;
    uint material_offset;
    uint blas_root;
    uint triangle_offset;
    uint flags;
    uint object;
};

struct TriangleRay {
    float3 origin;
    uint kx;
    uint ky;
    uint kz;
    int _pad4_0;
    int _pad4_1;
    float3 shear;
    bool valid;
};

struct GpuNode {
    float3 min_;
    uint a;
    float3 max_;
    uint b;
};

struct BoxRay {
    float3 step_;
    int _pad1_0;
    float3 start_lo;
    int _pad2_0;
    float3 start_hi;
    float tmin;
    float unit;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct Hit {
    float3 position;
    float t;
    float3 normal;
    int _pad3_0;
    float3 geometric_normal;
    int _pad4_0;
    float2 uv;
    bool front_face;
    uint instance;
    uint primitive;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct Triangle {
    float3 v0_;
    int _pad1_0;
    float3 v1_;
    int _pad2_0;
    float3 v2_;
    int _end_pad_0;
};

struct SkyGradient {
    float3 zenith;
    int _pad1_0;
    float3 horizon;
    int _pad2_0;
    float3 ground;
    int _end_pad_0;
};

struct Lambert {
    float3 albedo;
    int _end_pad_0;
};

struct LightSample {
    float3 dir;
    float dist;
    float3 radiance;
    float pdf;
};

struct PointLight {
    float3 position;
    int _pad1_0;
    float3 color;
    float intensity;
    float range;
    float inner_range;
    int _end_pad_0;
    int _end_pad_1;
};

struct Frame {
    Ray ray;
    Hit hit;
    float error;
    uint slot;
    int _pad4_0;
    int _pad4_1;
    float3 sum;
    int _pad5_0;
    float3 dirs[1];
    int _pad6_0;
    float3 weights[1];
    int _pad7_0;
    uint count;
    uint next;
    int _end_pad_0;
    int _end_pad_1;
};

static const uint WORKGROUP_WIDTH = 8u;
static const uint WORKGROUP_HEIGHT = 8u;
static const uint NO_HIT = 4294967295u;
static const uint SCATTER = 1000003u;
static const uint SCRATCH_RNG_INDEX = 12u;
static const uint SCRATCH_RNG_SEED = 13u;
static const uint HALF_WORD_BITS = 16u;
static const uint RAY_CAMERA = 0u;
static const bool HAS_MEDIA = false;
static const uint MEDIUM_ENTRY_STRIDE = 1u;
static const uint MESH_GEOMETRY = 4294967295u;
static const uint NODE_LEAF_BIT = 2147483648u;
static const uint NODE_COUNT_SHIFT = 27u;
static const uint NODE_COUNT_MASK = 15u;
static const uint NODE_FIRST_MASK = 134217727u;
static const bool HAS_ANY_HIT = false;
static const uint BLAS_STACK = 64u;
static const uint TLAS_STACK = 4u;
static const float POINT_ERROR = 1.9073486e-6;
static const float GAMMA_1_ = 5.960465e-8;
static const float GAMMA_6_ = 3.576281e-7;
static const float GAMMA_4_ = 2.3841864e-7;
static const bool HAS_SECONDARY_RAYS = false;
static const bool HAS_BACKGROUND = true;
static const uint LIGHT_ENTRY_STRIDE = 2u;
static const uint SCRATCH_SHADOW_MODE = 14u;
static const uint SHADOW_UNOCCLUDED = 1u;
static const uint SHADOW_ABOVE = 2u;
static const float LIGHT_ERROR = 4.7683716e-7;
static const uint RAY_SHADOW = 2u;
static const float INV_PI = 0.31830987;
static const uint FLAG_MEDIUM = 4u;
static const uint FLAG_SECONDARY_RAYS = 2u;
static const uint MAX_DEPTH = 4u;
static const uint STACK_SIZE = 4u;
static const uint MAX_SPAWN = 1u;
static const uint RAY_SECONDARY = 1u;

cbuffer tile : register(b1) { TileParams tile; }
cbuffer frame : register(b0) { FrameUniforms frame; }
static uint scratch[15] = (uint[15])0;
static uint rng_state = (uint)0;
ByteAddressBuffer params : register(t6);
static uint F32_INF = 2139095040u;
ByteAddressBuffer instances : register(t3);
ByteAddressBuffer nodes : register(t2);
ByteAddressBuffer triangles : register(t4);
static uint traversal_stack[68] = (uint[68])0;
static float hit_error = (float)0;
ByteAddressBuffer attributes : register(t5);
static uint ray_count = (uint)0;
static float3 spawn_dirs[1] = (float3[1])0;
static float3 spawn_weights[1] = (float3[1])0;
static uint spawn_count = (uint)0;
RWByteAddressBuffer counters : register(u9);
RWByteAddressBuffer accum : register(u8);

uint2 naga_div(uint2 lhs, uint2 rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint2 div_vec2u(uint2 a, uint2 b)
{
    bool2 by_zero = (b == (0u).xx);
    uint2 divisor = (by_zero ? (1u).xx : b);
    return naga_div(a, divisor);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint rem_u32_(uint a_1, uint b_1)
{
    bool by_zero_1 = (b_1 == 0u);
    uint divisor_1 = (by_zero_1 ? 1u : b_1);
    return (by_zero_1 ? 0u : naga_mod(a_1, divisor_1));
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint div_u32_(uint a_2, uint b_2)
{
    bool by_zero_2 = (b_2 == 0u);
    uint divisor_2 = (by_zero_2 ? 1u : b_2);
    return naga_div(a_2, divisor_2);
}

uint2 naga_mod(uint2 lhs, uint2 rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint2 rem_vec2u(uint2 a_3, uint2 b_3)
{
    uint2 _e3 = (0u).xx;
    bool2 by_zero_3 = (b_3 == _e3);
    uint2 divisor_3 = (by_zero_3 ? (1u).xx : b_3);
    return (by_zero_3 ? _e3 : naga_mod(a_3, divisor_3));
}

uint2 scattered_local(uint2 id)
{
    TileParams tile_1 = tile;
    uint2 size = uint2(WORKGROUP_WIDTH, WORKGROUP_HEIGHT);
    const uint2 _e11 = div_vec2u(((tile_1.extent + size) - (1u).xx), size);
    uint count = (_e11.x * _e11.y);
    if ((count == 0u)) {
        return (NO_HIT).xx;
    }
    const uint2 _e19 = div_vec2u(id, size);
    uint order = ((_e19.y * _e11.x) + _e19.x);
    const uint _e26 = rem_u32_(SCATTER, count);
    const uint _e28 = rem_u32_((order * _e26), count);
    const uint _e30 = rem_u32_(_e28, _e11.x);
    const uint _e32 = div_u32_(_e28, _e11.x);
    const uint2 _e35 = rem_vec2u(id, size);
    return ((uint2(_e30, _e32) * size) + _e35);
}

uint pcg_hash(uint x)
{
    uint state_1 = ((x * 747796405u) + 2891336453u);
    uint word = (((state_1 >> (((state_1 >> 28u) + 4u) & 31u)) ^ state_1) * 277803737u);
    return ((word >> 22u) ^ word);
}

void rng_resume(uint2 pixel, uint sample_, uint seed, uint state)
{
    scratch[min(uint(min(SCRATCH_RNG_INDEX, 14u)), 14u)] = sample_;
    const uint _e12 = pcg_hash(seed);
    const uint _e14 = pcg_hash((pixel.y ^ _e12));
    const uint _e16 = pcg_hash((pixel.x ^ _e14));
    scratch[min(uint(min(SCRATCH_RNG_SEED, 14u)), 14u)] = _e16;
    rng_state = state;
    return;
}

void rng_seed(uint2 pixel_1, uint sample_1, uint seed_1)
{
    rng_resume(pixel_1, sample_1, seed_1, 0u);
    return;
}

Pinhole ConstructPinhole(float3 arg0, float3 arg1, float3 arg2, float arg3) {
    Pinhole ret = (Pinhole)0;
    ret.position = arg0;
    ret.look_at = arg1;
    ret.up = arg2;
    ret.fov = arg3;
    return ret;
}

Pinhole load_Pinhole(uint offset)
{
    uint _e5 = asuint(params.Load((offset + 0u)*4));
    uint _e11 = asuint(params.Load((offset + 1u)*4));
    uint _e17 = asuint(params.Load((offset + 2u)*4));
    uint _e24 = asuint(params.Load((offset + 4u)*4));
    uint _e30 = asuint(params.Load((offset + 5u)*4));
    uint _e36 = asuint(params.Load((offset + 6u)*4));
    uint _e43 = asuint(params.Load((offset + 8u)*4));
    uint _e49 = asuint(params.Load((offset + 9u)*4));
    uint _e55 = asuint(params.Load((offset + 10u)*4));
    uint _e62 = asuint(params.Load((offset + 11u)*4));
    const Pinhole pinhole = ConstructPinhole(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), float3(asfloat(_e24), asfloat(_e30), asfloat(_e36)), float3(asfloat(_e43), asfloat(_e49), asfloat(_e55)), asfloat(_e62));
    return pinhole;
}

uint2 image_size_query()
{
    TileParams _e1 = tile;
    return _e1.image_size;
}

uint samples_per_pixel_query()
{
    FrameUniforms _e1 = frame;
    return _e1.total_samples;
}

uint laine_karras(uint x_1, uint seed_2)
{
    uint v = (uint)0;

    v = (x_1 + seed_2);
    uint _e4 = v;
    uint _e5 = v;
    v = (_e4 ^ (_e5 * 1817228412u));
    uint _e9 = v;
    uint _e10 = v;
    v = (_e9 ^ (_e10 * 3090095698u));
    uint _e14 = v;
    uint _e15 = v;
    v = (_e14 ^ (_e15 * 3350193720u));
    uint _e19 = v;
    uint _e20 = v;
    v = (_e19 ^ (_e20 * 2367878886u));
    uint _e24 = v;
    return _e24;
}

uint sobol_second_reversed(uint i)
{
    uint f = (uint)0;

    f = i;
    uint _e2 = f;
    uint _e3 = f;
    f = (_e2 ^ ((_e3 >> 1u) & 1431655765u));
    uint _e9 = f;
    uint _e10 = f;
    f = (_e9 ^ ((_e10 >> 2u) & 858993459u));
    uint _e16 = f;
    uint _e17 = f;
    f = (_e16 ^ ((_e17 >> 4u) & 252645135u));
    uint _e23 = f;
    uint _e24 = f;
    f = (_e23 ^ ((_e24 >> 8u) & 16711935u));
    uint _e30 = f;
    uint _e31 = f;
    f = (_e30 ^ (_e31 >> (HALF_WORD_BITS & 31u)));
    uint _e37 = f;
    return _e37;
}

float rand_next()
{
    uint x_2 = (uint)0;

    uint d = rng_state;
    rng_state = (d + 1u);
    uint _e10 = scratch[min(uint(min(SCRATCH_RNG_SEED, 14u)), 14u)];
    const uint _e16 = pcg_hash((_e10 ^ ((d >> 1u) * 2654435769u)));
    uint _e22 = scratch[min(uint(min(SCRATCH_RNG_INDEX, 14u)), 14u)];
    const uint _e24 = laine_karras(reversebits(_e22), _e16);
    uint i_5 = reversebits(_e24);
    x_2 = i_5;
    if (((d & 1u) != 0u)) {
        const uint _e31 = sobol_second_reversed(i_5);
        x_2 = _e31;
    }
    uint scramble = (_e16 ^ (((2654435769u * (1u + (d & 1u))) + (_e16 << 6u)) + (_e16 >> 2u)));
    uint _e45 = x_2;
    const uint _e46 = laine_karras(_e45, scramble);
    return (float((reversebits(_e46) >> 8u)) * (1.0 / 16777216.0));
}

float2 rand2_next()
{
    const float _e0 = rand_next();
    const float _e1 = rand_next();
    return float2(_e0, _e1);
}

float3 normalize_vec3f(float3 v_1)
{
    return ((dot(v_1, v_1) >= 1.1754944e-38) ? normalize(v_1) : (0.0).xxx);
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

Ray pinhole_ray(Pinhole cam, uint2 pixel_2, uint sample_2)
{
    float2 jitter = (float2)0;

    const uint2 _e2 = image_size_query();
    float2 size_1 = float2(_e2);
    jitter = (0.5).xx;
    const uint _e7 = samples_per_pixel_query();
    if ((_e7 > 1u)) {
        const float2 _e10 = rand2_next();
        jitter = _e10;
    }
    float2 _e12 = jitter;
    float2 ndc = ((((float2(pixel_2) + _e12) / size_1) * (2.0).xx) - (1.0).xx);
    const float3 _e24 = normalize_vec3f((cam.look_at - cam.position));
    const float3 _e27 = normalize_vec3f(cross(_e24, cam.up));
    float3 up = cross(_e27, _e24);
    float h = tan((radians(cam.fov) * 0.5));
    float aspect = (size_1.x / size_1.y);
    const float3 _e48 = normalize_vec3f(((_e24 + (_e27 * (((ndc.x * h) * aspect)).xxx)) - (up * ((ndc.y * h)).xxx)));
    uint _e52 = F32_INF;
    const Ray ray_20 = ConstructRay(cam.position, 0.0, _e48, asfloat(_e52), 0u, 0u, 0u);
    return ray_20;
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uint2 pixel_3, uint sample_3)
{
    const Pinhole _e3 = load_Pinhole(offset_1);
    const Ray _e4 = pinhole_ray(_e3, pixel_3, sample_3);
    const Ray ray_21 = _e4;
    return ray_21;
}

Candidate ConstructCandidate(float arg0, uint arg1, uint arg2, float2 arg3, float3 arg4) {
    Candidate ret = (Candidate)0;
    ret.t = arg0;
    ret.slot = arg1;
    ret.primitive = arg2;
    ret.uv = arg3;
    ret.normal = arg4;
    return ret;
}

Candidate no_candidate(float tmax)
{
    const Candidate candidate = ConstructCandidate(tmax, NO_HIT, 0u, (0.0).xx, (0.0).xxx);
    return candidate;
}

Ray to_object(GpuInstance inst, Ray ray)
{
    Ray r = (Ray)0;

    r = ray;
    float4 o = float4(ray.origin, 1.0);
    float4 d_1 = float4(ray.dir, 0.0);
    r.origin = float3(dot(inst.world_to_object_0_, o), dot(inst.world_to_object_1_, o), dot(inst.world_to_object_2_, o));
    r.dir = float3(dot(inst.world_to_object_0_, d_1), dot(inst.world_to_object_1_, d_1), dot(inst.world_to_object_2_, d_1));
    Ray _e25 = r;
    const Ray ray_22 = _e25;
    return ray_22;
}

TriangleRay ConstructTriangleRay(float3 arg0, uint arg1, uint arg2, uint arg3, float3 arg4, bool arg5) {
    TriangleRay ret = (TriangleRay)0;
    ret.origin = arg0;
    ret.kx = arg1;
    ret.ky = arg2;
    ret.kz = arg3;
    ret.shear = arg4;
    ret.valid = arg5;
    return ret;
}

TriangleRay prepare_triangle_ray(Ray ray_1)
{
    float3 d_2 = ((abs(ray_1.dir) < (1.1754944e-38).xxx) ? (0.0).xxx : ray_1.dir);
    float3 ad = abs(d_2);
    bool y_gt = (ad.y > ad.x);
    uint kz = ((ad.z > (y_gt ? ad.y : ad.x)) ? 2u : (y_gt ? 1u : 0u));
    uint kx0_ = ((kz == 2u) ? 0u : (kz + 1u));
    uint ky0_ = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = d_2[min(uint(min(kz, 2u)), 2u)];
    bool flip = (dz < 0.0);
    uint kx = (flip ? ky0_ : kx0_);
    uint ky = (flip ? kx0_ : ky0_);
    uint3 inf_bits = (2139095040u).xxx;
    bool finite = (all(((asuint(ray_1.origin) & (2147483647u).xxx) < inf_bits)) && all(((asuint(d_2) & (2147483647u).xxx) < inf_bits)));
    const TriangleRay triangleray = ConstructTriangleRay(ray_1.origin, kx, ky, kz, float3((d_2[min(uint(min(kx, 2u)), 2u)] / dz), (d_2[min(uint(min(ky, 2u)), 2u)] / dz), (1.0 / dz)), (finite && !((dz == 0.0))));
    return triangleray;
}

float3 node_point(float3 origin, float3 scale, uint3 q)
{
    return (origin + (float3(q) * scale));
}

float3 node_frame_hi(GpuNode header)
{
    const float3 _e5 = node_point(header.min_, header.max_, (65535u).xxx);
    return _e5;
}

BoxRay ConstructBoxRay(float3 arg0, float3 arg1, float3 arg2, float arg3, float arg4) {
    BoxRay ret = (BoxRay)0;
    ret.step_ = arg0;
    ret.start_lo = arg1;
    ret.start_hi = arg2;
    ret.tmin = arg3;
    ret.unit = arg4;
    return ret;
}

BoxRay box_ray(GpuNode header_1, Ray ray_2)
{
    float3 origin_2 = header_1.min_;
    const float3 _e3 = node_frame_hi(header_1);
    float3 extent = (_e3 - origin_2);
    float m_1 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    uint e = min(max(((asuint(m_1) >> 23u) & 255u), 1u), 253u);
    float3 d_3 = (ray_2.dir * (asfloat(((254u - e) << 23u))).xxx);
    float unit = asfloat((e << 23u));
    float3 floor_ = (9.094947e-13).xxx;
    float3 s_3 = ((d_3 < (0.0).xxx) ? (-1.0).xxx : (1.0).xxx);
    float3 inv = ((1.0).xxx / ((abs(d_3) < floor_) ? (s_3 * floor_) : d_3));
    float3 rel = (origin_2 - ray_2.origin);
    float3 start = (rel * inv);
    float3 pad = ((((9.536743e-7).xxx * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_3);
    const BoxRay boxray = ConstructBoxRay((header_1.max_ * inv), (start - pad), (start + pad), (ray_2.tmin * unit), unit);
    return boxray;
}

float3 hit_triangle(TriangleRay r_1, uint slot, float tmin, float tmax_1, bool occlusion)
{
    float4 _e9 = asfloat(triangles.Load4((slot * 3u)*16));
    float3 a_4 = (_e9.xyz - r_1.origin);
    float4 _e19 = asfloat(triangles.Load4(((slot * 3u) + 1u)*16));
    float3 b_7 = (_e19.xyz - r_1.origin);
    float4 _e29 = asfloat(triangles.Load4(((slot * 3u) + 2u)*16));
    float3 c_5 = (_e29.xyz - r_1.origin);
    float ax = (a_4[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * a_4[min(uint(min(r_1.kz, 2u)), 2u)]));
    float ay = (a_4[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * a_4[min(uint(min(r_1.kz, 2u)), 2u)]));
    float bx = (b_7[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * b_7[min(uint(min(r_1.kz, 2u)), 2u)]));
    float by = (b_7[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * b_7[min(uint(min(r_1.kz, 2u)), 2u)]));
    float cx = (c_5[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * c_5[min(uint(min(r_1.kz, 2u)), 2u)]));
    float cy = (c_5[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * c_5[min(uint(min(r_1.kz, 2u)), 2u)]));
    float u = ((cx * by) - (cy * bx));
    float v_2 = ((ax * cy) - (ay * cx));
    float w = ((bx * ay) - (by * ax));
    bool outside = ((((u < 0.0) || (v_2 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_2 > 0.0)) || (w > 0.0)));
    float det = ((u + v_2) + w);
    float scaled = (((u * (r_1.shear.z * a_4[min(uint(min(r_1.kz, 2u)), 2u)])) + (v_2 * (r_1.shear.z * b_7[min(uint(min(r_1.kz, 2u)), 2u)]))) + (w * (r_1.shear.z * c_5[min(uint(min(r_1.kz, 2u)), 2u)])));
    if (occlusion) {
        float st = ((det < 0.0) ? -(scaled) : scaled);
        float ad_1 = abs(det);
        bool hit_7 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        uint _e178 = F32_INF;
        return (hit_7 ? float3(tmin, 0.0, 0.0) : float3(asfloat(_e178), 0.0, 0.0));
    }
    float rcp_ = (1.0 / det);
    float t_4 = (scaled * rcp_);
    bool hit_8 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (t_4 >= tmin)) && (t_4 <= tmax_1));
    uint _e202 = F32_INF;
    return (hit_8 ? float3(t_4, (v_2 * rcp_), (w * rcp_)) : float3(asfloat(_e202), 0.0, 0.0));
}

bool accept(GpuInstance inst_1, Ray ray_3, Candidate c)
{
    return true;
}

uint3 node_box_lo(uint3 p)
{
    return uint3((p.x & 65535u), (p.x >> 16u), (p.y & 65535u));
}

uint3 node_box_hi(uint3 p_1)
{
    return uint3((p_1.y >> 16u), (p_1.z & 65535u), (p_1.z >> 16u));
}

float slab_in_frame(float3 lo, float3 hi, BoxRay b_4, float tmax_2)
{
    float3 t0_ = mad(lo, b_4.step_, b_4.start_lo);
    float3 t1_ = mad(hi, b_4.step_, b_4.start_hi);
    bool3 flip_1 = (asint(b_4.step_) < (int(0)).xxx);
    float3 near_2 = (flip_1 ? t1_ : t0_);
    float3 far_2 = (flip_1 ? t0_ : t1_);
    float2 e_1 = ((near_2.xy < near_2.yz) ? near_2.yz : near_2.xy);
    float enter = ((e_1.x < e_1.y) ? e_1.y : e_1.x);
    float2 x_5 = ((far_2.yz < far_2.xy) ? far_2.yz : far_2.xy);
    float exit = ((x_5.y < x_5.x) ? x_5.y : x_5.x);
    float enter_t = ((enter < b_4.tmin) ? b_4.tmin : enter);
    float exit_t = ((tmax_2 < exit) ? tmax_2 : exit);
    if ((enter_t <= exit_t)) {
        return enter_t;
    }
    uint _e49 = F32_INF;
    return asfloat(_e49);
}

float2 children_entry(GpuNode n, BoxRay b_5, float tmax_3)
{
    uint3 lq = asuint(n.min_);
    uint3 rq = asuint(n.max_);
    float t_5 = (tmax_3 * b_5.unit);
    const uint3 _e9 = node_box_lo(lq);
    const uint3 _e11 = node_box_hi(lq);
    const float _e13 = slab_in_frame(float3(_e9), float3(_e11), b_5, t_5);
    const uint3 _e14 = node_box_lo(rq);
    const uint3 _e16 = node_box_hi(rq);
    const float _e18 = slab_in_frame(float3(_e14), float3(_e16), b_5, t_5);
    return float2(_e13, _e18);
}

uint2 pop(uint base, uint sp)
{
    if ((sp == 0u)) {
        return uint2(NO_HIT, 0u);
    }
    uint _e14 = traversal_stack[min(uint(min(((base + sp) - 1u), 67u)), 67u)];
    return uint2(_e14, (sp - 1u));
}

GpuNode ConstructGpuNode(float3 arg0, uint arg1, float3 arg2, uint arg3) {
    GpuNode ret = (GpuNode)0;
    ret.min_ = arg0;
    ret.a = arg1;
    ret.max_ = arg2;
    ret.b = arg3;
    return ret;
}

Candidate intersect_mesh(GpuInstance inst_2, uint slot_1, Ray world_ray, Ray ray_4, Candidate best_in, bool shadow)
{
    Candidate best = (Candidate)0;
    uint sp_1 = (uint)0;
    uint child = (uint)0;
    uint k = (uint)0;
    uint near = (uint)0;
    uint far = (uint)0;

    best = best_in;
    const TriangleRay _e7 = prepare_triangle_ray(ray_4);
    uint base_1 = inst_2.blas_root;
    GpuNode header_2 = ConstructGpuNode(asfloat(nodes.Load3(base_1*32+0)), asuint(nodes.Load(base_1*32+12)), asfloat(nodes.Load3(base_1*32+16)), asuint(nodes.Load(base_1*32+28)));
    const BoxRay _e12 = box_ray(header_2, ray_4);
    sp_1 = 0u;
    child = header_2.a;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e17 = child;
        if (((_e17 & NODE_LEAF_BIT) != 0u)) {
            uint _e22 = child;
            uint count_1 = ((_e22 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK);
            uint _e29 = child;
            uint first = (_e29 & NODE_FIRST_MASK);
            k = 0u;
            uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
            bool loop_init = true;
            while(true) {
                if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e75 = k;
                    k = (_e75 + 1u);
                }
                loop_init = false;
                uint _e34 = k;
                if ((_e34 >= count_1)) {
                    break;
                }
                uint _e38 = k;
                uint prim = ((inst_2.triangle_offset + first) + _e38);
                float _e42 = best.t;
                const float3 _e46 = hit_triangle(_e7, prim, ray_4.tmin, _e42, (shadow && !(HAS_ANY_HIT)));
                uint _e49 = F32_INF;
                if ((_e46.x < asfloat(_e49))) {
                    float4 _e58 = asfloat(triangles.Load4(((prim * 3u) + 1u)*16));
                    uint tag = asuint(_e58.w);
                    uint owner = ((tag != 0u) ? ((inst_2.object + tag) - 1u) : slot_1);
                    Candidate c_6 = ConstructCandidate(_e46.x, owner, prim, _e46.yz, (0.0).xxx);
                    const bool _e73 = accept(inst_2, world_ray, c_6);
                    if (_e73) {
                        best = c_6;
                        if (shadow) {
                            Candidate _e74 = best;
                            const Candidate candidate_1 = _e74;
                            return candidate_1;
                        }
                    }
                }
            }
        } else {
            uint _e78 = child;
            GpuNode n_6 = ConstructGpuNode(asfloat(nodes.Load3((base_1 + _e78)*32+0)), asuint(nodes.Load((base_1 + _e78)*32+12)), asfloat(nodes.Load3((base_1 + _e78)*32+16)), asuint(nodes.Load((base_1 + _e78)*32+28)));
            float _e84 = best.t;
            const float2 _e85 = children_entry(n_6, _e12, _e84);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if (((tl < asfloat(_e89)) && (tr < asfloat(_e93)))) {
                near = n_6.a;
                far = n_6.b;
                if (((tr < tl) != shadow)) {
                    near = n_6.b;
                    far = n_6.a;
                }
                uint _e105 = sp_1;
                if ((_e105 < BLAS_STACK)) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack[min(uint(min((TLAS_STACK + _e109), 67u)), 67u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if ((tl < asfloat(_e121))) {
                child = n_6.a;
                continue;
            }
            uint _e126 = F32_INF;
            if ((tr < asfloat(_e126))) {
                child = n_6.b;
                continue;
            }
        }
        uint _e131 = sp_1;
        const uint2 _e132 = pop(TLAS_STACK, _e131);
        if ((_e132.x == NO_HIT)) {
            break;
        }
        child = _e132.x;
        sp_1 = _e132.y;
    }
    Candidate _e138 = best;
    const Candidate candidate_2 = _e138;
    return candidate_2;
}

GpuInstance ConstructGpuInstance(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5, uint arg6, uint arg7, uint arg8, uint arg9, uint arg10, uint arg11, uint arg12, uint arg13) {
    GpuInstance ret = (GpuInstance)0;
    ret.world_to_object_0_ = arg0;
    ret.world_to_object_1_ = arg1;
    ret.world_to_object_2_ = arg2;
    ret.object_to_world_0_ = arg3;
    ret.object_to_world_1_ = arg4;
    ret.object_to_world_2_ = arg5;
    ret.geometry_type = arg6;
    ret.geometry_offset = arg7;
    ret.material_type = arg8;
    ret.material_offset = arg9;
    ret.blas_root = arg10;
    ret.triangle_offset = arg11;
    ret.flags = arg12;
    ret.object = arg13;
    return ret;
}

Candidate intersect_object(uint slot_2, Ray ray_5, Candidate best_1, bool shadow_1)
{
    Ray r_2 = (Ray)0;

    GpuInstance inst_6 = ConstructGpuInstance(asfloat(instances.Load4(slot_2*128+0)), asfloat(instances.Load4(slot_2*128+16)), asfloat(instances.Load4(slot_2*128+32)), asfloat(instances.Load4(slot_2*128+48)), asfloat(instances.Load4(slot_2*128+64)), asfloat(instances.Load4(slot_2*128+80)), asuint(instances.Load(slot_2*128+96)), asuint(instances.Load(slot_2*128+100)), asuint(instances.Load(slot_2*128+104)), asuint(instances.Load(slot_2*128+108)), asuint(instances.Load(slot_2*128+112)), asuint(instances.Load(slot_2*128+116)), asuint(instances.Load(slot_2*128+120)), asuint(instances.Load(slot_2*128+124)));
    const Ray _e7 = to_object(inst_6, ray_5);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        const Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_5, _e14, best_1, shadow_1);
        const Candidate candidate_3 = _e15;
        return candidate_3;
    }
    const Candidate candidate_4 = best_1;
    return candidate_4;
}

float point_error(float3 origin_1, float3 along)
{
    float3 a_5 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_5.x, a_5.y), a_5.z));
}

Triangle ConstructTriangle(float3 arg0, float3 arg1, float3 arg2) {
    Triangle ret = (Triangle)0;
    ret.v0_ = arg0;
    ret.v1_ = arg1;
    ret.v2_ = arg2;
    return ret;
}

Triangle load_triangle(uint slot_3)
{
    float4 v0_1 = asfloat(triangles.Load4((slot_3 * 3u)*16));
    float4 v1_ = asfloat(triangles.Load4(((slot_3 * 3u) + 1u)*16));
    float4 v2_ = asfloat(triangles.Load4(((slot_3 * 3u) + 2u)*16));
    const Triangle triangle_ = ConstructTriangle(v0_1.xyz, v1_.xyz, v2_.xyz);
    return triangle_;
}

float3 point_to_world(GpuInstance inst_3, float3 p_2)
{
    float4 q_1 = float4(p_2, 1.0);
    return float3(dot(inst_3.object_to_world_0_, q_1), dot(inst_3.object_to_world_1_, q_1), dot(inst_3.object_to_world_2_, q_1));
}

float mesh_error(GpuInstance inst_4, float3 v0_, float3 db1_, float3 db2_, float3 p_3)
{
    float3 obj = (((GAMMA_1_).xxx * abs(v0_)) + ((GAMMA_6_).xxx * (abs(db1_) + abs(db2_))));
    float4 q_2 = float4(abs(p_3), 1.0);
    float4 r0_ = abs(inst_4.object_to_world_0_);
    float4 r1_ = abs(inst_4.object_to_world_1_);
    float4 r2_ = abs(inst_4.object_to_world_2_);
    float3 rounding = ((GAMMA_4_).xxx * float3(dot(r0_, q_2), dot(r1_, q_2), dot(r2_, q_2)));
    float3 carried = (((1.0 + GAMMA_4_)).xxx * float3(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_.xyz, obj)));
    float3 e_2 = (rounding + carried);
    return max(max(e_2.x, e_2.y), e_2.z);
}

float3 decode_octahedral(uint bits)
{
    float3 n_1 = (float3)0;

    float2 e_3 = (float2(int2(bits << 16, bits) >> 16) / 32767.0);
    n_1 = float3(e_3.x, e_3.y, ((1.0 - abs(e_3.x)) - abs(e_3.y)));
    float _e14 = n_1.z;
    if ((_e14 < 0.0)) {
        float3 _e21 = n_1;
        float2 s_4 = ((_e21.xy >= (0.0).xx) ? (1.0).xx : (-1.0).xx);
        float3 _e29 = n_1;
        float2 xy = (((1.0).xx - abs(_e29.yx)) * s_4);
        float _e37 = n_1.z;
        n_1 = float3(xy.x, xy.y, _e37);
    }
    float3 _e39 = n_1;
    const float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

float3 normal_to_world(GpuInstance inst_5, float3 n_2)
{
    float3 w_1 = (((inst_5.world_to_object_0_.xyz * (n_2.x).xxx) + (inst_5.world_to_object_1_.xyz * (n_2.y).xxx)) + (inst_5.world_to_object_2_.xyz * (n_2.z).xxx));
    const float3 _e19 = normalize_vec3f(w_1);
    return _e19;
}

Hit ConstructHit(float3 arg0, float arg1, float3 arg2, float3 arg3, float2 arg4, bool arg5, uint arg6, uint arg7) {
    Hit ret = (Hit)0;
    ret.position = arg0;
    ret.t = arg1;
    ret.normal = arg2;
    ret.geometric_normal = arg3;
    ret.uv = arg4;
    ret.front_face = arg5;
    ret.instance = arg6;
    ret.primitive = arg7;
    return ret;
}

Hit finish_hit(Ray ray_6, Candidate c_1)
{
    Hit hit = (Hit)0;
    float3 n_geo = (float3)0;
    float3 n_shade = (float3)0;

    GpuInstance inst_7 = ConstructGpuInstance(asfloat(instances.Load4(c_1.slot*128+0)), asfloat(instances.Load4(c_1.slot*128+16)), asfloat(instances.Load4(c_1.slot*128+32)), asfloat(instances.Load4(c_1.slot*128+48)), asfloat(instances.Load4(c_1.slot*128+64)), asfloat(instances.Load4(c_1.slot*128+80)), asuint(instances.Load(c_1.slot*128+96)), asuint(instances.Load(c_1.slot*128+100)), asuint(instances.Load(c_1.slot*128+104)), asuint(instances.Load(c_1.slot*128+108)), asuint(instances.Load(c_1.slot*128+112)), asuint(instances.Load(c_1.slot*128+116)), asuint(instances.Load(c_1.slot*128+120)), asuint(instances.Load(c_1.slot*128+124)));
    const float _e11 = point_error(ray_6.origin, (ray_6.dir * (c_1.t).xxx));
    hit_error = _e11;
    hit = ConstructHit((ray_6.origin + (ray_6.dir * (c_1.t).xxx)), c_1.t, float3(0.0, 1.0, 0.0), float3(0.0, 1.0, 0.0), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if ((inst_7.geometry_type == MESH_GEOMETRY)) {
        const Triangle _e42 = load_triangle(c_1.primitive);
        float2 b_8 = c_1.uv;
        float w_2 = ((1.0 - b_8.x) - b_8.y);
        float3 e1_ = (_e42.v1_ - _e42.v0_);
        float3 e2_ = (_e42.v2_ - _e42.v0_);
        float3 p_7 = (_e42.v0_ + ((e1_ * (b_8.x).xxx) + (e2_ * (b_8.y).xxx)));
        const float3 _e65 = point_to_world(inst_7, p_7);
        hit.position = _e65;
        const float _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * (b_8.x).xxx), (e2_ * (b_8.y).xxx), p_7);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        uint4 a0_ = asuint(attributes.Load4((c_1.primitive * 2u)*16));
        uint4 a1_ = asuint(attributes.Load4(((c_1.primitive * 2u) + 1u)*16));
        const float3 _e91 = decode_octahedral(a0_.x);
        const float3 _e95 = decode_octahedral(a0_.y);
        const float3 _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * (w_2).xxx) + (_e95 * (b_8.x).xxx)) + (_e101 * (b_8.y).xxx));
        float3 _e106 = n_shade;
        float3 _e107 = n_shade;
        if ((dot(_e106, _e107) < 1e-12)) {
            float3 _e111 = n_geo;
            n_shade = _e111;
        }
        uint _e112 = a0_.w;
        float2 uv0_ = float2(f16tof32(_e112), f16tof32((_e112) >> 16));
        uint _e114 = a1_.x;
        float2 uv1_ = float2(f16tof32(_e114), f16tof32((_e114) >> 16));
        uint _e116 = a1_.y;
        float2 uv2_ = float2(f16tof32(_e116), f16tof32((_e116) >> 16));
        hit.uv = (((uv0_ * (w_2).xx) + (uv1_ * (b_8.x).xx)) + (uv2_ * (b_8.y).xx));
        float4 _e135 = asfloat(triangles.Load4((c_1.primitive * 3u)*16));
        hit.primitive = asuint(_e135.w);
    }
    float3 _e139 = n_geo;
    const float3 _e140 = normal_to_world(inst_7, _e139);
    hit.geometric_normal = _e140;
    float3 _e142 = n_shade;
    const float3 _e143 = normal_to_world(inst_7, _e142);
    hit.normal = _e143;
    float3 _e147 = hit.geometric_normal;
    hit.front_face = (dot(ray_6.dir, _e147) < 0.0);
    Hit _e151 = hit;
    const Hit hit_9 = _e151;
    return hit_9;
}

uint medium_at(float3 p_4, uint exclude)
{
    uint inside = (uint)0;
    float nearest = (float)0;
    uint i_1 = (uint)0;

    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = frame;
    const float3 _e12 = normalize_vec3f(float3(0.5773, 0.5774, 0.5775));
    uint _e14 = F32_INF;
    Ray probe = ConstructRay(p_4, 0.0, _e12, asfloat(_e14), 0u, 0u, 0u);
    inside = 0u;
    uint _e23 = F32_INF;
    nearest = asfloat(_e23);
    uint end = frame_1.medium_count;
    i_1 = 0u;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e59 = i_1;
            i_1 = (_e59 + 1u);
        }
        loop_init_1 = false;
        uint _e29 = i_1;
        if ((_e29 >= end)) {
            break;
        }
        uint _e32 = i_1;
        uint slot_4 = asuint(params.Load((frame_1.medium_table + (_e32 * MEDIUM_ENTRY_STRIDE))*4));
        if ((slot_4 != exclude)) {
            uint _e41 = F32_INF;
            const Candidate _e43 = no_candidate(asfloat(_e41));
            const Candidate _e45 = intersect_object(slot_4, probe, _e43, false);
            float _e50 = nearest;
            if (((_e45.slot != NO_HIT) && (_e45.t < _e50))) {
                const Hit _e53 = finish_hit(probe, _e45);
                if (!(_e53.front_face)) {
                    inside = (slot_4 + 1u);
                    nearest = _e45.t;
                }
            }
        }
    }
    uint _e62 = inside;
    return _e62;
}

Ray sample_camera_ray(uint2 pixel_4, uint sample_4)
{
    Ray ray_7 = (Ray)0;

    FrameUniforms frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    const Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_7 = _e7;
    ray_7.depth = 0u;
    ray_7.kind = RAY_CAMERA;
    float3 _e15 = ray_7.origin;
    const uint _e17 = medium_at(_e15, NO_HIT);
    ray_7.medium = _e17;
    Ray _e18 = ray_7;
    const Ray ray_23 = _e18;
    return ray_23;
}

float3 node_frame_bounds()
{
    return (65535.0).xxx;
}

Candidate intersect_scene(Ray ray_8, bool shadow_2)
{
    Candidate best_2 = (Candidate)0;
    uint sp_2 = (uint)0;
    uint child_1 = (uint)0;
    uint near_1 = (uint)0;
    uint far_1 = (uint)0;

    uint _e3 = ray_count;
    ray_count = (_e3 + 1u);
    const Candidate _e7 = no_candidate(ray_8.tmax);
    best_2 = _e7;
    FrameUniforms frame_3 = frame;
    if ((frame_3.instance_count == 0u)) {
        Candidate _e14 = best_2;
        const Candidate candidate_5 = _e14;
        return candidate_5;
    }
    uint base_2 = frame_3.tlas_root;
    GpuNode header_3 = ConstructGpuNode(asfloat(nodes.Load3(base_2*32+0)), asuint(nodes.Load(base_2*32+12)), asfloat(nodes.Load3(base_2*32+16)), asuint(nodes.Load(base_2*32+28)));
    const BoxRay _e19 = box_ray(header_3, ray_8);
    const float3 _e22 = node_frame_bounds();
    float _e24 = best_2.t;
    const float _e27 = slab_in_frame((0.0).xxx, _e22, _e19, (_e24 * _e19.unit));
    uint _e29 = F32_INF;
    if ((_e27 == asfloat(_e29))) {
        Candidate _e32 = best_2;
        const Candidate candidate_6 = _e32;
        return candidate_6;
    }
    sp_2 = 0u;
    child_1 = header_3.a;
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e37 = child_1;
        if (((_e37 & NODE_LEAF_BIT) != 0u)) {
            uint _e42 = child_1;
            if ((((_e42 >> (NODE_COUNT_SHIFT & 31u)) & NODE_COUNT_MASK) != 0u)) {
                uint _e51 = child_1;
                Candidate _e54 = best_2;
                const Candidate _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_8, _e54, shadow_2);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if ((shadow_2 && (_e57 != NO_HIT))) {
                    Candidate _e61 = best_2;
                    const Candidate candidate_7 = _e61;
                    return candidate_7;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_7 = ConstructGpuNode(asfloat(nodes.Load3((base_2 + _e62)*32+0)), asuint(nodes.Load((base_2 + _e62)*32+12)), asfloat(nodes.Load3((base_2 + _e62)*32+16)), asuint(nodes.Load((base_2 + _e62)*32+28)));
            float _e68 = best_2.t;
            const float2 _e69 = children_entry(n_7, _e19, _e68);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if (((tl_1 < asfloat(_e73)) && (tr_1 < asfloat(_e77)))) {
                near_1 = n_7.a;
                far_1 = n_7.b;
                if ((tr_1 < tl_1)) {
                    near_1 = n_7.b;
                    far_1 = n_7.a;
                }
                uint _e88 = sp_2;
                if ((_e88 < TLAS_STACK)) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack[min(uint(min(_e91, 67u)), 67u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if ((tl_1 < asfloat(_e102))) {
                child_1 = n_7.a;
                continue;
            }
            uint _e107 = F32_INF;
            if ((tr_1 < asfloat(_e107))) {
                child_1 = n_7.b;
                continue;
            }
        }
        uint _e112 = sp_2;
        const uint2 _e113 = pop(0u, _e112);
        if ((_e113.x == NO_HIT)) {
            break;
        }
        child_1 = _e113.x;
        sp_2 = _e113.y;
    }
    Candidate _e119 = best_2;
    const Candidate candidate_8 = _e119;
    return candidate_8;
}

SkyGradient ConstructSkyGradient(float3 arg0, float3 arg1, float3 arg2) {
    SkyGradient ret = (SkyGradient)0;
    ret.zenith = arg0;
    ret.horizon = arg1;
    ret.ground = arg2;
    return ret;
}

SkyGradient load_SkyGradient(uint offset_2)
{
    uint _e5 = asuint(params.Load((offset_2 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_2 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_2 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_2 + 4u)*4));
    uint _e30 = asuint(params.Load((offset_2 + 5u)*4));
    uint _e36 = asuint(params.Load((offset_2 + 6u)*4));
    uint _e43 = asuint(params.Load((offset_2 + 8u)*4));
    uint _e49 = asuint(params.Load((offset_2 + 9u)*4));
    uint _e55 = asuint(params.Load((offset_2 + 10u)*4));
    const SkyGradient skygradient = ConstructSkyGradient(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), float3(asfloat(_e24), asfloat(_e30), asfloat(_e36)), float3(asfloat(_e43), asfloat(_e49), asfloat(_e55)));
    return skygradient;
}

float3 sky_gradient(SkyGradient b_6, Ray ray_9)
{
    const float3 _e3 = normalize_vec3f(ray_9.dir);
    float y = _e3.y;
    if ((y < 0.0)) {
        return lerp(b_6.horizon, b_6.ground, (min((-(y) * 4.0), 1.0)).xxx);
    }
    return lerp(b_6.horizon, b_6.zenith, (sqrt(y)).xxx);
}

float3 dispatch_miss(uint type_id_1, uint offset_3, Ray ray_10)
{
    const SkyGradient _e2 = load_SkyGradient(offset_3);
    const float3 _e3 = sky_gradient(_e2, ray_10);
    return _e3;
}

float3 miss(Ray ray_11)
{
    if (!(HAS_BACKGROUND)) {
        return (0.0).xxx;
    }
    FrameUniforms frame_4 = frame;
    const float3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_11);
    return _e9;
}

Lambert ConstructLambert(float3 arg0) {
    Lambert ret = (Lambert)0;
    ret.albedo = arg0;
    return ret;
}

Lambert load_Lambert(uint offset_4)
{
    uint _e5 = asuint(params.Load((offset_4 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_4 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_4 + 2u)*4));
    const Lambert lambert = ConstructLambert(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)));
    return lambert;
}

float3 shading_normal(Ray ray_12, Hit hit_1)
{
    float3 ng = faceforward(hit_1.geometric_normal, ray_12.dir, hit_1.geometric_normal);
    return faceforward(hit_1.normal, -(ng), hit_1.normal);
}

uint light_count_query()
{
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

PointLight ConstructPointLight(float3 arg0, float3 arg1, float arg2, float arg3, float arg4) {
    PointLight ret = (PointLight)0;
    ret.position = arg0;
    ret.color = arg1;
    ret.intensity = arg2;
    ret.range = arg3;
    ret.inner_range = arg4;
    return ret;
}

PointLight load_PointLight(uint offset_5)
{
    uint _e5 = asuint(params.Load((offset_5 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_5 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_5 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_5 + 4u)*4));
    uint _e30 = asuint(params.Load((offset_5 + 5u)*4));
    uint _e36 = asuint(params.Load((offset_5 + 6u)*4));
    uint _e43 = asuint(params.Load((offset_5 + 7u)*4));
    uint _e49 = asuint(params.Load((offset_5 + 8u)*4));
    uint _e55 = asuint(params.Load((offset_5 + 9u)*4));
    const PointLight pointlight = ConstructPointLight(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), float3(asfloat(_e24), asfloat(_e30), asfloat(_e36)), asfloat(_e43), asfloat(_e49), asfloat(_e55));
    return pointlight;
}

float shadow_preset(float3 normal, float3 dir)
{
    uint mode = scratch[min(uint(min(SCRATCH_SHADOW_MODE, 14u)), 14u)];
    if ((mode == SHADOW_UNOCCLUDED)) {
        return 1.0;
    }
    if (((mode == SHADOW_ABOVE) && !((dot(dir, normal) > 0.0)))) {
        return 0.0;
    }
    return -1.0;
}

float3 step_toward(float3 x_3, float3 s)
{
    uint3 bits_1 = asuint(x_3);
    bool3 up_1 = ((sign(x_3) * sign(s)) > (0.0).xxx);
    float3 stepped = asfloat((up_1 ? (bits_1 + (1u).xxx) : (bits_1 - (1u).xxx)));
    float3 from_zero = ((s > (0.0).xxx) ? (1.1754944e-38).xxx : (-1.1754944e-38).xxx);
    float3 moved = ((x_3 == (0.0).xxx) ? from_zero : stepped);
    return (!((s == (0.0).xxx)) ? moved : x_3);
}

float3 offset_origin(float3 p_5, float3 n_3, float error)
{
    float d_4 = ((2.0 * error) * ((abs(n_3.x) + abs(n_3.y)) + abs(n_3.z)));
    float3 offset_10 = (n_3 * (d_4).xxx);
    const float3 _e17 = step_toward((p_5 + offset_10), offset_10);
    return _e17;
}

Ray shadow_ray(float3 position, float3 normal_1, float3 dir_1, float dist)
{
    float3 n_4 = (float3)0;
    float tmax_4 = (float)0;

    n_4 = normal_1;
    float3 _e5 = n_4;
    if ((dot(dir_1, _e5) < 0.0)) {
        float3 _e9 = n_4;
        n_4 = -(_e9);
    }
    float3 a_6 = abs(position);
    float _e13 = hit_error;
    float error_3 = max(_e13, (GAMMA_4_ * max(max(a_6.x, a_6.y), a_6.z)));
    float3 _e22 = n_4;
    const float3 _e23 = offset_origin(position, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = asfloat(_e25);
    uint _e29 = F32_INF;
    if ((dist < asfloat(_e29))) {
        float3 light = (position + (dir_1 * (dist).xxx));
        float dd = dot(dir_1, dir_1);
        float along_1 = (dot((light - _e23), dir_1) / dd);
        float3 l_1 = (abs(position) + abs((dir_1 * (dist).xxx)));
        tmax_4 = ((along_1 * (1.0 - 1e-5)) - ((LIGHT_ERROR * max(max(l_1.x, l_1.y), l_1.z)) / sqrt(dd)));
    }
    float _e59 = tmax_4;
    const Ray ray_24 = ConstructRay(_e23, 0.0, dir_1, _e59, 0u, RAY_SHADOW, 0u);
    return ray_24;
}

float shadow_query(float3 position_1, float3 normal_2, float3 dir_2, float dist_1)
{
    const float _e4 = shadow_preset(normal_2, dir_2);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    const Ray _e7 = shadow_ray(position_1, normal_2, dir_2, dist_1);
    const Candidate _e9 = intersect_scene(_e7, true);
    return ((_e9.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample ConstructLightSample(float3 arg0, float arg1, float3 arg2, float arg3) {
    LightSample ret = (LightSample)0;
    ret.dir = arg0;
    ret.dist = arg1;
    ret.radiance = arg2;
    ret.pdf = arg3;
    return ret;
}

LightSample point_light(PointLight l, float3 position_2, float3 normal_3)
{
    float strength = (float)0;

    float3 to_light = (l.position - position_2);
    float dist_2 = length(to_light);
    float3 dir_5 = (to_light / (max(dist_2, 1e-20)).xxx);
    strength = (l.intensity / max((dist_2 * dist_2), 1e-20));
    if ((l.range > 0.0)) {
        float _e19 = strength;
        strength = (_e19 * (1.0 - smoothstep(l.inner_range, l.range, dist_2)));
    }
    const float _e26 = shadow_query(position_2, normal_3, dir_5, dist_2);
    float _e28 = strength;
    const LightSample lightsample = ConstructLightSample(dir_5, dist_2, ((l.color * (_e28).xxx) * (_e26).xxx), 0.0);
    return lightsample;
}

LightSample dispatch_light(uint type_id_2, uint offset_6, float3 position_3, float3 normal_4)
{
    const PointLight _e3 = load_PointLight(offset_6);
    const LightSample _e4 = point_light(_e3, position_3, normal_4);
    const LightSample lightsample_1 = _e4;
    return lightsample_1;
}

LightSample sample_light_query(uint i_2, float3 position_4, float3 normal_5)
{
    FrameUniforms frame_5 = frame;
    if ((i_2 >= frame_5.light_count)) {
        const LightSample lightsample_2 = ConstructLightSample(float3(0.0, 1.0, 0.0), 0.0, (0.0).xxx, 0.0);
        return lightsample_2;
    }
    uint entry = (frame_5.light_table + (i_2 * LIGHT_ENTRY_STRIDE));
    uint _e22 = asuint(params.Load(entry*4));
    uint _e27 = asuint(params.Load((entry + 1u)*4));
    const LightSample _e28 = dispatch_light(_e22, _e27, position_4, normal_5);
    const LightSample lightsample_3 = _e28;
    return lightsample_3;
}

float3 lambert_shade(Lambert m, Ray ray_13, Hit hit_2)
{
    float3 color = (float3)0;
    uint i_3 = (uint)0;

    const float3 _e3 = shading_normal(ray_13, hit_2);
    color = (0.0).xxx;
    const uint _e8 = light_count_query();
    i_3 = 0u;
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e30 = i_3;
            i_3 = (_e30 + 1u);
        }
        loop_init_2 = false;
        uint _e10 = i_3;
        if ((_e10 >= _e8)) {
            break;
        }
        uint _e12 = i_3;
        const LightSample _e15 = sample_light_query(_e12, hit_2.position, hit_2.geometric_normal);
        float3 _e16 = color;
        color = (_e16 + (((m.albedo * (INV_PI).xxx) * _e15.radiance) * (max(dot(_e3, _e15.dir), 0.0)).xxx));
    }
    float3 _e33 = color;
    return _e33;
}

float3 dispatch_closest_hit(uint type_id_3, uint offset_7, Ray ray_14, Hit hit_3, float3 secondary)
{
    const Lambert _e3 = load_Lambert(offset_7);
    const float3 _e4 = lambert_shade(_e3, ray_14, hit_3);
    return _e4;
}

float3 shade_direct(Ray ray_15, Candidate c_2)
{
    GpuInstance inst_8 = ConstructGpuInstance(asfloat(instances.Load4(c_2.slot*128+0)), asfloat(instances.Load4(c_2.slot*128+16)), asfloat(instances.Load4(c_2.slot*128+32)), asfloat(instances.Load4(c_2.slot*128+48)), asfloat(instances.Load4(c_2.slot*128+64)), asfloat(instances.Load4(c_2.slot*128+80)), asuint(instances.Load(c_2.slot*128+96)), asuint(instances.Load(c_2.slot*128+100)), asuint(instances.Load(c_2.slot*128+104)), asuint(instances.Load(c_2.slot*128+108)), asuint(instances.Load(c_2.slot*128+112)), asuint(instances.Load(c_2.slot*128+116)), asuint(instances.Load(c_2.slot*128+120)), asuint(instances.Load(c_2.slot*128+124)));
    const Hit _e6 = finish_hit(ray_15, c_2);
    const float3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_15, _e6, (0.0).xxx);
    return _e11;
}

float3 ZeroValuefloat3() {
    return (float3)0;
}

float3 dispatch_medium(uint type_id_4, uint offset_8, Ray ray_16, float t, float3 radiance)
{
    return ZeroValuefloat3();
}

float3 through_medium(Ray ray_17, float t_1, float3 radiance_1)
{
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_17.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_9 = ConstructGpuInstance(asfloat(instances.Load4((ray_17.medium - 1u)*128+0)), asfloat(instances.Load4((ray_17.medium - 1u)*128+16)), asfloat(instances.Load4((ray_17.medium - 1u)*128+32)), asfloat(instances.Load4((ray_17.medium - 1u)*128+48)), asfloat(instances.Load4((ray_17.medium - 1u)*128+64)), asfloat(instances.Load4((ray_17.medium - 1u)*128+80)), asuint(instances.Load((ray_17.medium - 1u)*128+96)), asuint(instances.Load((ray_17.medium - 1u)*128+100)), asuint(instances.Load((ray_17.medium - 1u)*128+104)), asuint(instances.Load((ray_17.medium - 1u)*128+108)), asuint(instances.Load((ray_17.medium - 1u)*128+112)), asuint(instances.Load((ray_17.medium - 1u)*128+116)), asuint(instances.Load((ray_17.medium - 1u)*128+120)), asuint(instances.Load((ray_17.medium - 1u)*128+124)));
    if (((inst_9.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    const float3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_17, t_1, radiance_1);
    return _e21;
}

void dispatch_secondary_rays(uint type_id_5, uint offset_9, Ray ray_18, Hit hit_4)
{
    return;
}

float3 spawn_origin_at(float3 position_5, float3 normal_6, float error_1, float3 dir_3)
{
    float3 n_5 = (float3)0;

    n_5 = normal_6;
    float3 _e5 = n_5;
    if ((dot(dir_3, _e5) < 0.0)) {
        float3 _e9 = n_5;
        n_5 = -(_e9);
    }
    float3 _e11 = n_5;
    const float3 _e12 = offset_origin(position_5, _e11, error_1);
    return _e12;
}

float3 spawn_origin(Hit hit_5, float error_2, float3 dir_4)
{
    const float3 _e5 = spawn_origin_at(hit_5.position, hit_5.geometric_normal, error_2, dir_4);
    return _e5;
}

Frame ConstructFrame(Ray arg0, Hit arg1, float arg2, uint arg3, float3 arg4, float3 arg5[1], float3 arg6[1], uint arg7, uint arg8) {
    Frame ret = (Frame)0;
    ret.ray = arg0;
    ret.hit = arg1;
    ret.error = arg2;
    ret.slot = arg3;
    ret.sum = arg4;
    ret.dirs = arg5;
    ret.weights = arg6;
    ret.count = arg7;
    ret.next = arg8;
    return ret;
}

typedef Frame ret_ZeroValuearray4_Frame_[4];
ret_ZeroValuearray4_Frame_ ZeroValuearray4_Frame_() {
    return (Frame[4])0;
}

typedef float3 ret_ZeroValuearray1_float3_[1];
ret_ZeroValuearray1_float3_ ZeroValuearray1_float3_() {
    return (float3[1])0;
}

float3 trace(Ray camera_ray)
{
    float3 radiance_2 = (float3)0;
    float t_2 = (float)0;
    Frame stack[4] = (Frame[4])0;
    uint depth = (uint)0;
    Ray ray_19 = (Ray)0;
    float3 value = (float3)0;
    bool have_value = (bool)0;
    Ray s_ray = (Ray)0;
    Candidate s_c = (Candidate)0;
    Hit s_hit = (Hit)0;
    float s_error = (float)0;
    float3 s_sum = (float3)0;
    bool fresh = (bool)0;
    bool waiting = (bool)0;
    bool pushed = (bool)0;
    float3 radiance_3 = (float3)0;
    float t_3 = (float)0;
    Hit hit_6 = (Hit)0;
    Frame f_1 = (Frame)0;
    uint i_4 = (uint)0;
    uint medium = (uint)0;

    if (!(HAS_SECONDARY_RAYS)) {
        const Candidate _e4 = intersect_scene(camera_ray, false);
        radiance_2 = (0.0).xxx;
        uint _e9 = F32_INF;
        t_2 = asfloat(_e9);
        if ((_e4.slot == NO_HIT)) {
            hit_error = 0.0;
            const float3 _e17 = miss(camera_ray);
            radiance_2 = _e17;
        } else {
            const float3 _e18 = shade_direct(camera_ray, _e4);
            radiance_2 = _e18;
            t_2 = _e4.t;
        }
        float _e20 = t_2;
        float3 _e21 = radiance_2;
        const float3 _e22 = through_medium(camera_ray, _e20, _e21);
        return _e22;
    }
    stack = ZeroValuearray4_Frame_();
    depth = 0u;
    ray_19 = camera_ray;
    value = (0.0).xxx;
    have_value = false;
    s_ray = camera_ray;
    uint _e35 = F32_INF;
    const Candidate _e37 = no_candidate(asfloat(_e35));
    s_c = _e37;
    s_hit = ConstructHit((0.0).xxx, 0.0, (0.0).xxx, (0.0).xxx, (0.0).xx, true, 0u, 0u);
    s_error = 0.0;
    s_sum = (0.0).xxx;
    fresh = false;
    waiting = false;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        bool _e62 = have_value;
        bool _e64 = waiting;
        if ((!(_e62) && !(_e64))) {
            Ray _e67 = ray_19;
            const Candidate _e69 = intersect_scene(_e67, false);
            s_c = _e69;
            Ray _e70 = ray_19;
            s_ray = _e70;
            s_sum = (0.0).xxx;
            fresh = true;
            waiting = true;
        }
        bool _e75 = waiting;
        if (_e75) {
            waiting = false;
            pushed = false;
            radiance_3 = (0.0).xxx;
            uint _e83 = F32_INF;
            t_3 = asfloat(_e83);
            uint _e87 = s_c.slot;
            if ((_e87 == NO_HIT)) {
                hit_error = 0.0;
                Ray _e92 = s_ray;
                const float3 _e93 = miss(_e92);
                radiance_3 = _e93;
            } else {
                uint _e95 = s_c.slot;
                GpuInstance inst_10 = ConstructGpuInstance(asfloat(instances.Load4(_e95*128+0)), asfloat(instances.Load4(_e95*128+16)), asfloat(instances.Load4(_e95*128+32)), asfloat(instances.Load4(_e95*128+48)), asfloat(instances.Load4(_e95*128+64)), asfloat(instances.Load4(_e95*128+80)), asuint(instances.Load(_e95*128+96)), asuint(instances.Load(_e95*128+100)), asuint(instances.Load(_e95*128+104)), asuint(instances.Load(_e95*128+108)), asuint(instances.Load(_e95*128+112)), asuint(instances.Load(_e95*128+116)), asuint(instances.Load(_e95*128+120)), asuint(instances.Load(_e95*128+124)));
                Hit _e99 = s_hit;
                hit_6 = _e99;
                bool _e101 = fresh;
                if (_e101) {
                    Ray _e102 = s_ray;
                    Candidate _e103 = s_c;
                    const Hit _e104 = finish_hit(_e102, _e103);
                    hit_6 = _e104;
                    float _e106 = hit_error;
                    s_error = _e106;
                } else {
                    float _e107 = s_error;
                    hit_error = _e107;
                }
                float _e110 = hit_6.t;
                t_3 = _e110;
                bool _e111 = fresh;
                uint _e119 = s_ray.depth;
                uint _e123 = depth;
                if ((((_e111 && ((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u)) && (_e119 < MAX_DEPTH)) && (_e123 < STACK_SIZE))) {
                    spawn_count = 0u;
                    Ray _e131 = s_ray;
                    Hit _e132 = hit_6;
                    dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, _e131, _e132);
                    uint _e134 = spawn_count;
                    uint n_8 = min(min(_e134, 1u), MAX_SPAWN);
                    if ((n_8 > 0u)) {
                        Ray _e141 = s_ray;
                        Hit _e142 = hit_6;
                        float _e143 = s_error;
                        uint _e145 = s_c.slot;
                        f_1 = ConstructFrame(_e141, _e142, _e143, _e145, (0.0).xxx, ZeroValuearray1_float3_(), ZeroValuearray1_float3_(), n_8, 0u);
                        i_4 = 0u;
                        uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                        bool loop_init_3 = true;
                        while(true) {
                            if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                            loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                            if (!loop_init_3) {
                                uint _e175 = i_4;
                                i_4 = (_e175 + 1u);
                            }
                            loop_init_3 = false;
                            uint _e155 = i_4;
                            if ((_e155 >= n_8)) {
                                break;
                            }
                            uint _e158 = i_4;
                            uint _e162 = i_4;
                            float3 _e165 = spawn_dirs[min(uint(_e162), 0u)];
                            f_1.dirs[min(uint(min(_e158, 0u)), 0u)] = _e165;
                            uint _e167 = i_4;
                            uint _e171 = i_4;
                            float3 _e174 = spawn_weights[min(uint(_e171), 0u)];
                            f_1.weights[min(uint(min(_e167, 0u)), 0u)] = _e174;
                        }
                        uint _e178 = depth;
                        Frame _e182 = f_1;
                        stack[min(uint(min(_e178, 3u)), 3u)] = _e182;
                        uint _e183 = depth;
                        depth = (_e183 + 1u);
                        pushed = true;
                    }
                }
                bool _e187 = pushed;
                if (!(_e187)) {
                    Ray _e191 = s_ray;
                    Hit _e192 = hit_6;
                    float3 _e193 = s_sum;
                    const float3 _e194 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e191, _e192, _e193);
                    radiance_3 = _e194;
                }
            }
            bool _e195 = pushed;
            if (!(_e195)) {
                Ray _e197 = s_ray;
                float _e198 = t_3;
                float3 _e199 = radiance_3;
                const float3 _e200 = through_medium(_e197, _e198, _e199);
                value = _e200;
                have_value = true;
            }
        }
        bool _e202 = have_value;
        if (_e202) {
            uint _e203 = depth;
            if ((_e203 == 0u)) {
                float3 _e206 = value;
                return _e206;
            }
            uint _e207 = depth;
            uint top = (_e207 - 1u);
            uint _e214 = stack[min(uint(min(top, 3u)), 3u)].next;
            uint child_2 = (_e214 - 1u);
            float3 _e221 = stack[min(uint(min(top, 3u)), 3u)].sum;
            float3 _e229 = stack[min(uint(min(top, 3u)), 3u)].weights[min(uint(min(child_2, 0u)), 0u)];
            float3 _e230 = value;
            stack[min(uint(min(top, 3u)), 3u)].sum = (_e221 + (_e229 * _e230));
            have_value = false;
        }
        uint _e234 = depth;
        uint top_1 = (_e234 - 1u);
        uint _e241 = stack[min(uint(min(top_1, 3u)), 3u)].next;
        uint _e246 = stack[min(uint(min(top_1, 3u)), 3u)].count;
        if ((_e241 < _e246)) {
            uint i_6 = stack[min(uint(min(top_1, 3u)), 3u)].next;
            stack[min(uint(min(top_1, 3u)), 3u)].next = (i_6 + 1u);
            Ray parent = stack[min(uint(min(top_1, 3u)), 3u)].ray;
            Hit hit_10 = stack[min(uint(min(top_1, 3u)), 3u)].hit;
            float3 dir_6 = stack[min(uint(min(top_1, 3u)), 3u)].dirs[min(uint(min(i_6, 0u)), 0u)];
            medium = parent.medium;
            float _e283 = stack[min(uint(min(top_1, 3u)), 3u)].error;
            const float3 _e284 = spawn_origin(hit_10, _e283, dir_6);
            uint _e287 = F32_INF;
            uint _e293 = medium;
            ray_19 = ConstructRay(_e284, 0.0, dir_6, asfloat(_e287), (parent.depth + 1u), RAY_SECONDARY, _e293);
        } else {
            Ray _e299 = stack[min(uint(min(top_1, 3u)), 3u)].ray;
            s_ray = _e299;
            Hit _e304 = stack[min(uint(min(top_1, 3u)), 3u)].hit;
            s_hit = _e304;
            float _e309 = stack[min(uint(min(top_1, 3u)), 3u)].error;
            s_error = _e309;
            uint _e315 = stack[min(uint(min(top_1, 3u)), 3u)].slot;
            s_c.slot = _e315;
            float3 _e320 = stack[min(uint(min(top_1, 3u)), 3u)].sum;
            s_sum = _e320;
            fresh = false;
            waiting = true;
            depth = top_1;
        }
    }
    return ZeroValuefloat3();
}

bool3 is_finite_vec3f(float3 x_4)
{
    return ((asuint(x_4) & (2147483647u).xxx) < (2139095040u).xxx);
}

float3 finite_or_zero(float3 c_3)
{
    const bool3 _e3 = is_finite_vec3f(c_3);
    return (_e3 ? c_3 : (0.0).xxx);
}

PassSum ConstructPassSum(float3 arg0, uint arg1) {
    PassSum ret = (PassSum)0;
    ret.sum = arg0;
    ret.bad = arg1;
    return ret;
}

PassSum add_sample(PassSum p_6, float3 c_4, uint s_1, uint index, uint first_pass, uint per_pass)
{
    PassSum next = (PassSum)0;

    next = p_6;
    const bool3 _e7 = is_finite_vec3f(c_4);
    if (all(_e7)) {
        float3 _e10 = next.sum;
        next.sum = (_e10 + c_4);
    } else {
        float3 _e13 = next.sum;
        const float3 _e14 = finite_or_zero(c_4);
        next.sum = (_e13 + _e14);
        uint _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    const uint _e22 = rem_u32_((s_1 + 1u), per_pass);
    if ((_e22 != 0u)) {
        PassSum _e25 = next;
        const PassSum passsum = _e25;
        return passsum;
    }
    uint _e27 = ray_count;
    counters.InterlockedAdd(4, _e27);
    ray_count = 0u;
    const uint _e31 = div_u32_(s_1, per_pass);
    uint pass_ = (first_pass + _e31);
    float3 _e34 = next.sum;
    float4 _e36 = float4(_e34, float(per_pass));
    uint _e38 = next.bad;
    if ((pass_ == 0u)) {
        accum.Store4(index*16, asuint(_e36));
    } else {
        float4 _e43 = asfloat(accum.Load4(index*16));
        accum.Store4(index*16, asuint((_e43 + _e36)));
    }
    if ((_e38 > 0u)) {
        counters.InterlockedAdd(0, _e38);
    }
    const PassSum passsum_1 = ConstructPassSum((0.0).xxx, 0u);
    return passsum_1;
}

void render_pixel(uint2 pixel_5)
{
    PassSum sums = (PassSum)0;
    uint s_2 = (uint)0;

    FrameUniforms frame_6 = frame;
    TileParams tile_2 = tile;
    uint index_1 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = (tile_2.frame * per_pass_1);
    uint count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = ConstructPassSum((0.0).xxx, 0u);
    s_2 = 0u;
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e35 = s_2;
            s_2 = (_e35 + 1u);
        }
        loop_init_4 = false;
        uint _e25 = s_2;
        if ((_e25 >= count_2)) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_2;
        const Ray _e30 = sample_camera_ray(pixel_5, (first_1 + _e28));
        const float3 _e31 = trace(_e30);
        uint _e32 = s_2;
        const PassSum _e34 = add_sample(_e27, _e31, _e32, index_1, tile_2.frame, per_pass_1);
        sums = _e34;
    }
    return;
}

void render_invocation(uint2 id_1)
{
    TileParams tile_3 = tile;
    const uint2 _e3 = scattered_local(id_1);
    if (any((_e3 >= tile_3.extent))) {
        return;
    }
    render_pixel((tile_3.origin + _e3));
    return;
}

[numthreads(8, 8, 1)]
void render(uint3 gid : SV_DispatchThreadID)
{
    render_invocation(uint2(gid.x, gid.y));
    return;
}
