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

struct Sphere {
    float3 center_;
    float radius;
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

struct ConstantBackground {
    float3 color;
    int _end_pad_0;
};

struct PathDiffuse {
    float3 albedo;
    uint roulette_depth;
};

struct LightSample {
    float3 dir;
    float dist;
    float3 radiance;
    float pdf;
};

struct QuadLight {
    float3 corner;
    int _pad1_0;
    float3 edge_u;
    int _pad2_0;
    float3 edge_v;
    int _pad3_0;
    float3 color;
    float intensity;
    uint lamp;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct SphereLight {
    float3 position;
    float radius;
    float3 color;
    float intensity;
    uint lamp;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct QuadLamp {
    float3 color;
    float intensity;
    float area;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct SphereLamp {
    float3 color;
    float intensity;
    float radius;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct PathPbr {
    float3 base_color;
    float metallic;
    float roughness;
    int _pad3_0;
    int _pad3_1;
    int _pad3_2;
    float3 emissive;
    uint roulette_depth;
};

struct PathState {
    Ray ray;
    float3 beta;
    int _pad2_0;
    float3 radiance;
    bool live;
};

struct PbrSample {
    float3 dir;
    int _pad1_0;
    float3 weight;
    float pdf;
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
static const uint TLAS_STACK = 8u;
static const float TAU = 6.2831855;
static const float INV_PI = 0.31830987;
static const float POINT_ERROR = 1.9073486e-6;
static const float GAMMA_1_ = 5.960465e-8;
static const float GAMMA_6_ = 3.576281e-7;
static const float GAMMA_4_ = 2.3841864e-7;
static const bool HAS_SECONDARY_RAYS = true;
static const bool HAS_BACKGROUND = true;
static const uint SCRATCH_SHADOW_MODE = 14u;
static const uint SHADOW_ABOVE = 2u;
static const uint LIGHT_ENTRY_STRIDE = 2u;
static const uint SCRATCH_RESOLVED = 3u;
static const uint SCRATCH_LIGHT_BITS = 11u;
static const uint SCRATCH_QUERY = 2u;
static const uint SCRATCH_PENDING = 4u;
static const uint SHADOW_UNOCCLUDED = 1u;
static const uint LIGHT_QUERIES = 32u;
static const uint COUNTER_SHADOW_OVERFLOW = 3u;
static const uint SCRATCH_LIGHT_QUERY = 15u;
static const float LIGHT_ERROR = 4.7683716e-7;
static const uint RAY_SHADOW = 2u;
static const uint SHADOW_TRACED = 0u;
static const float MIS_BOUNCE_LENGTH = 3.0;
static const float PBR_MIN_ALPHA = 0.001;
static const uint FLAG_MEDIUM = 4u;
static const uint FLAG_SECONDARY_RAYS = 2u;
static const uint MAX_DEPTH = 5u;
static const uint ROULETTE_DEPTH = 2u;
static const float ROULETTE_THROUGHPUT = 0.5;
static const uint RAY_SECONDARY = 1u;

cbuffer tile : register(b1) { TileParams tile; }
cbuffer frame : register(b0) { FrameUniforms frame; }
static uint scratch[25] = (uint[25])0;
static uint rng_state = (uint)0;
ByteAddressBuffer params : register(t6);
static uint F32_INF = 2139095040u;
ByteAddressBuffer instances : register(t3);
ByteAddressBuffer nodes : register(t2);
ByteAddressBuffer triangles : register(t4);
static uint traversal_stack[72] = (uint[72])0;
static float hit_error = (float)0;
ByteAddressBuffer attributes : register(t5);
static uint ray_count = (uint)0;
RWByteAddressBuffer counters : register(u9);
static float3 spawn_dirs[1] = (float3[1])0;
static float3 spawn_weights[1] = (float3[1])0;
static uint spawn_count = (uint)0;
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
    scratch[min(uint(min(SCRATCH_RNG_INDEX, 24u)), 24u)] = sample_;
    const uint _e12 = pcg_hash(seed);
    const uint _e14 = pcg_hash((pixel.y ^ _e12));
    const uint _e16 = pcg_hash((pixel.x ^ _e14));
    scratch[min(uint(min(SCRATCH_RNG_SEED, 24u)), 24u)] = _e16;
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
    uint _e10 = scratch[min(uint(min(SCRATCH_RNG_SEED, 24u)), 24u)];
    const uint _e16 = pcg_hash((_e10 ^ ((d >> 1u) * 2654435769u)));
    uint _e22 = scratch[min(uint(min(SCRATCH_RNG_INDEX, 24u)), 24u)];
    const uint _e24 = laine_karras(reversebits(_e22), _e16);
    uint i_8 = reversebits(_e24);
    x_2 = i_8;
    if (((d & 1u) != 0u)) {
        const uint _e31 = sobol_second_reversed(i_8);
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
    const Ray ray_30 = ConstructRay(cam.position, 0.0, _e48, asfloat(_e52), 0u, 0u, 0u);
    return ray_30;
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uint2 pixel_3, uint sample_3)
{
    const Pinhole _e3 = load_Pinhole(offset_1);
    const Ray _e4 = pinhole_ray(_e3, pixel_3, sample_3);
    const Ray ray_31 = _e4;
    return ray_31;
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
    const Ray ray_32 = _e25;
    return ray_32;
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
    float m_6 = max(max(abs(ray_2.dir.x), abs(ray_2.dir.y)), abs(ray_2.dir.z));
    uint e = min(max(((asuint(m_6) >> 23u) & 255u), 1u), 253u);
    float3 d_3 = (ray_2.dir * (asfloat(((254u - e) << 23u))).xxx);
    float unit = asfloat((e << 23u));
    float3 floor_ = (9.094947e-13).xxx;
    float3 s_6 = ((d_3 < (0.0).xxx) ? (-1.0).xxx : (1.0).xxx);
    float3 inv = ((1.0).xxx / ((abs(d_3) < floor_) ? (s_6 * floor_) : d_3));
    float3 rel = (origin_2 - ray_2.origin);
    float3 start = (rel * inv);
    float3 pad = ((((9.536743e-7).xxx * abs(inv)) * ((extent + abs(rel)) + abs(origin_2))) * s_6);
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
    float3 c_8 = (_e29.xyz - r_1.origin);
    float ax = (a_4[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * a_4[min(uint(min(r_1.kz, 2u)), 2u)]));
    float ay = (a_4[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * a_4[min(uint(min(r_1.kz, 2u)), 2u)]));
    float bx = (b_7[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * b_7[min(uint(min(r_1.kz, 2u)), 2u)]));
    float by = (b_7[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * b_7[min(uint(min(r_1.kz, 2u)), 2u)]));
    float cx = (c_8[min(uint(min(r_1.kx, 2u)), 2u)] - (r_1.shear.x * c_8[min(uint(min(r_1.kz, 2u)), 2u)]));
    float cy = (c_8[min(uint(min(r_1.ky, 2u)), 2u)] - (r_1.shear.y * c_8[min(uint(min(r_1.kz, 2u)), 2u)]));
    float u_3 = ((cx * by) - (cy * bx));
    float v_6 = ((ax * cy) - (ay * cx));
    float w_1 = ((bx * ay) - (by * ax));
    bool outside = ((((u_3 < 0.0) || (v_6 < 0.0)) || (w_1 < 0.0)) && (((u_3 > 0.0) || (v_6 > 0.0)) || (w_1 > 0.0)));
    float det = ((u_3 + v_6) + w_1);
    float scaled = (((u_3 * (r_1.shear.z * a_4[min(uint(min(r_1.kz, 2u)), 2u)])) + (v_6 * (r_1.shear.z * b_7[min(uint(min(r_1.kz, 2u)), 2u)]))) + (w_1 * (r_1.shear.z * c_8[min(uint(min(r_1.kz, 2u)), 2u)])));
    if (occlusion) {
        float st = ((det < 0.0) ? -(scaled) : scaled);
        float ad_1 = abs(det);
        bool hit_12 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (st >= (tmin * ad_1))) && (st <= (tmax_1 * ad_1)));
        uint _e178 = F32_INF;
        return (hit_12 ? float3(tmin, 0.0, 0.0) : float3(asfloat(_e178), 0.0, 0.0));
    }
    float rcp_ = (1.0 / det);
    float t_4 = (scaled * rcp_);
    bool hit_13 = ((((r_1.valid && !(outside)) && !((det == 0.0))) && (t_4 >= tmin)) && (t_4 <= tmax_1));
    uint _e202 = F32_INF;
    return (hit_13 ? float3(t_4, (v_6 * rcp_), (w_1 * rcp_)) : float3(asfloat(_e202), 0.0, 0.0));
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
    float3 t1_1 = mad(hi, b_4.step_, b_4.start_hi);
    bool3 flip_1 = (asint(b_4.step_) < (int(0)).xxx);
    float3 near_2 = (flip_1 ? t1_1 : t0_);
    float3 far_2 = (flip_1 ? t0_ : t1_1);
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
    uint _e14 = traversal_stack[min(uint(min(((base + sp) - 1u), 71u)), 71u)];
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
    uint base_5 = inst_2.blas_root;
    GpuNode header_2 = ConstructGpuNode(asfloat(nodes.Load3(base_5*32+0)), asuint(nodes.Load(base_5*32+12)), asfloat(nodes.Load3(base_5*32+16)), asuint(nodes.Load(base_5*32+28)));
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
                    Candidate c_9 = ConstructCandidate(_e46.x, owner, prim, _e46.yz, (0.0).xxx);
                    const bool _e73 = accept(inst_2, world_ray, c_9);
                    if (_e73) {
                        best = c_9;
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
            GpuNode n_11 = ConstructGpuNode(asfloat(nodes.Load3((base_5 + _e78)*32+0)), asuint(nodes.Load((base_5 + _e78)*32+12)), asfloat(nodes.Load3((base_5 + _e78)*32+16)), asuint(nodes.Load((base_5 + _e78)*32+28)));
            float _e84 = best.t;
            const float2 _e85 = children_entry(n_11, _e12, _e84);
            float tl = _e85.x;
            float tr = _e85.y;
            uint _e89 = F32_INF;
            uint _e93 = F32_INF;
            if (((tl < asfloat(_e89)) && (tr < asfloat(_e93)))) {
                near = n_11.a;
                far = n_11.b;
                if (((tr < tl) != shadow)) {
                    near = n_11.b;
                    far = n_11.a;
                }
                uint _e105 = sp_1;
                if ((_e105 < BLAS_STACK)) {
                    uint _e109 = sp_1;
                    uint _e111 = far;
                    traversal_stack[min(uint(min((TLAS_STACK + _e109), 71u)), 71u)] = _e111;
                    uint _e116 = sp_1;
                    sp_1 = (_e116 + 1u);
                }
                uint _e119 = near;
                child = _e119;
                continue;
            }
            uint _e121 = F32_INF;
            if ((tl < asfloat(_e121))) {
                child = n_11.a;
                continue;
            }
            uint _e126 = F32_INF;
            if ((tr < asfloat(_e126))) {
                child = n_11.b;
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

Sphere ConstructSphere(float3 arg0, float arg1) {
    Sphere ret = (Sphere)0;
    ret.center_ = arg0;
    ret.radius = arg1;
    return ret;
}

Sphere load_Sphere(uint offset_2)
{
    uint _e5 = asuint(params.Load((offset_2 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_2 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_2 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_2 + 3u)*4));
    const Sphere sphere = ConstructSphere(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), asfloat(_e24));
    return sphere;
}

Intersection ConstructIntersection(float arg0, float3 arg1, float2 arg2) {
    Intersection ret = (Intersection)0;
    ret.t = arg0;
    ret.normal = arg1;
    ret.uv = arg2;
    return ret;
}

float2 ZeroValuefloat2() {
    return (float2)0;
}

Intersection sphere_intersect(Sphere s, Ray ray_5)
{
    float t = (float)0;

    float3 f_1 = (ray_5.origin - s.center_);
    float a_5 = dot(ray_5.dir, ray_5.dir);
    float b_8 = -(dot(f_1, ray_5.dir));
    float3 l_6 = (f_1 + (ray_5.dir * ((b_8 / a_5)).xxx));
    float r2_ = (s.radius * s.radius);
    float disc = (a_5 * (r2_ - dot(l_6, l_6)));
    if ((!((disc >= 0.0)) || !((a_5 > 0.0)))) {
        uint _e30 = F32_INF;
        const Intersection intersection = ConstructIntersection(asfloat(_e30), float3(0.0, 0.0, 1.0), ZeroValuefloat2());
        return intersection;
    }
    float q_1 = (b_8 + (((b_8 >= 0.0) ? 1.0 : -1.0) * sqrt(disc)));
    float t0_1 = ((dot(f_1, f_1) - r2_) / q_1);
    float t1_2 = (q_1 / a_5);
    t = min(t0_1, t1_2);
    float _e52 = t;
    if (!((_e52 >= ray_5.tmin))) {
        t = max(t0_1, t1_2);
    }
    float _e57 = t;
    float _e60 = t;
    if (!(((_e57 >= ray_5.tmin) && (_e60 <= ray_5.tmax)))) {
        uint _e66 = F32_INF;
        const Intersection intersection_1 = ConstructIntersection(asfloat(_e66), float3(0.0, 0.0, 1.0), ZeroValuefloat2());
        return intersection_1;
    }
    float _e76 = t;
    const float3 _e82 = normalize_vec3f(((ray_5.origin + (ray_5.dir * (_e76).xxx)) - s.center_));
    float u_4 = (((_e82.x == 0.0) && (_e82.z == 0.0)) ? 0.5 : (0.5 + (atan2(_e82.z, -(_e82.x)) / TAU)));
    float2 uv = float2(u_4, (acos(min(max(_e82.y, -1.0), 1.0)) * INV_PI));
    float _e109 = t;
    const Intersection intersection_2 = ConstructIntersection(_e109, _e82, uv);
    return intersection_2;
}

Intersection dispatch_intersection(uint type_id_1, uint offset_3, Ray ray_6)
{
    const Sphere _e2 = load_Sphere(offset_3);
    const Intersection _e3 = sphere_intersect(_e2, ray_6);
    const Intersection intersection_3 = _e3;
    return intersection_3;
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

Candidate intersect_object(uint slot_2, Ray ray_7, Candidate best_1, bool shadow_1)
{
    Ray r_2 = (Ray)0;

    GpuInstance inst_6 = ConstructGpuInstance(asfloat(instances.Load4(slot_2*128+0)), asfloat(instances.Load4(slot_2*128+16)), asfloat(instances.Load4(slot_2*128+32)), asfloat(instances.Load4(slot_2*128+48)), asfloat(instances.Load4(slot_2*128+64)), asfloat(instances.Load4(slot_2*128+80)), asuint(instances.Load(slot_2*128+96)), asuint(instances.Load(slot_2*128+100)), asuint(instances.Load(slot_2*128+104)), asuint(instances.Load(slot_2*128+108)), asuint(instances.Load(slot_2*128+112)), asuint(instances.Load(slot_2*128+116)), asuint(instances.Load(slot_2*128+120)), asuint(instances.Load(slot_2*128+124)));
    const Ray _e7 = to_object(inst_6, ray_7);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        const Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_7, _e14, best_1, shadow_1);
        const Candidate candidate_3 = _e15;
        return candidate_3;
    }
    Ray _e18 = r_2;
    const Intersection _e19 = dispatch_intersection(inst_6.geometry_type, inst_6.geometry_offset, _e18);
    float _e22 = r_2.tmin;
    float _e26 = r_2.tmax;
    uint _e31 = F32_INF;
    if ((((_e19.t >= _e22) && (_e19.t <= _e26)) && (_e19.t < asfloat(_e31)))) {
        Candidate c_10 = ConstructCandidate(_e19.t, slot_2, 0u, _e19.uv, _e19.normal);
        const bool _e40 = accept(inst_6, ray_7, c_10);
        if (_e40) {
            const Candidate candidate_4 = c_10;
            return candidate_4;
        }
    }
    const Candidate candidate_5 = best_1;
    return candidate_5;
}

float point_error(float3 origin_1, float3 along)
{
    float3 a_6 = (abs(origin_1) + abs(along));
    return (POINT_ERROR * max(max(a_6.x, a_6.y), a_6.z));
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
    float4 q_2 = float4(p_2, 1.0);
    return float3(dot(inst_3.object_to_world_0_, q_2), dot(inst_3.object_to_world_1_, q_2), dot(inst_3.object_to_world_2_, q_2));
}

float mesh_error(GpuInstance inst_4, float3 v0_, float3 db1_, float3 db2_, float3 p_3)
{
    float3 obj = (((GAMMA_1_).xxx * abs(v0_)) + ((GAMMA_6_).xxx * (abs(db1_) + abs(db2_))));
    float4 q_3 = float4(abs(p_3), 1.0);
    float4 r0_ = abs(inst_4.object_to_world_0_);
    float4 r1_ = abs(inst_4.object_to_world_1_);
    float4 r2_1 = abs(inst_4.object_to_world_2_);
    float3 rounding = ((GAMMA_4_).xxx * float3(dot(r0_, q_3), dot(r1_, q_3), dot(r2_1, q_3)));
    float3 carried = (((1.0 + GAMMA_4_)).xxx * float3(dot(r0_.xyz, obj), dot(r1_.xyz, obj), dot(r2_1.xyz, obj)));
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
        float2 s_7 = ((_e21.xy >= (0.0).xx) ? (1.0).xx : (-1.0).xx);
        float3 _e29 = n_1;
        float2 xy = (((1.0).xx - abs(_e29.yx)) * s_7);
        float _e37 = n_1.z;
        n_1 = float3(xy.x, xy.y, _e37);
    }
    float3 _e39 = n_1;
    const float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

float3 normal_to_world(GpuInstance inst_5, float3 n_2)
{
    float3 w_2 = (((inst_5.world_to_object_0_.xyz * (n_2.x).xxx) + (inst_5.world_to_object_1_.xyz * (n_2.y).xxx)) + (inst_5.world_to_object_2_.xyz * (n_2.z).xxx));
    const float3 _e19 = normalize_vec3f(w_2);
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

Hit finish_hit(Ray ray_8, Candidate c_1)
{
    Hit hit = (Hit)0;
    float3 n_geo = (float3)0;
    float3 n_shade = (float3)0;

    GpuInstance inst_7 = ConstructGpuInstance(asfloat(instances.Load4(c_1.slot*128+0)), asfloat(instances.Load4(c_1.slot*128+16)), asfloat(instances.Load4(c_1.slot*128+32)), asfloat(instances.Load4(c_1.slot*128+48)), asfloat(instances.Load4(c_1.slot*128+64)), asfloat(instances.Load4(c_1.slot*128+80)), asuint(instances.Load(c_1.slot*128+96)), asuint(instances.Load(c_1.slot*128+100)), asuint(instances.Load(c_1.slot*128+104)), asuint(instances.Load(c_1.slot*128+108)), asuint(instances.Load(c_1.slot*128+112)), asuint(instances.Load(c_1.slot*128+116)), asuint(instances.Load(c_1.slot*128+120)), asuint(instances.Load(c_1.slot*128+124)));
    const float _e11 = point_error(ray_8.origin, (ray_8.dir * (c_1.t).xxx));
    hit_error = _e11;
    hit = ConstructHit((ray_8.origin + (ray_8.dir * (c_1.t).xxx)), c_1.t, float3(0.0, 1.0, 0.0), float3(0.0, 1.0, 0.0), c_1.uv, true, inst_7.object, c_1.primitive);
    n_geo = c_1.normal;
    n_shade = c_1.normal;
    if ((inst_7.geometry_type == MESH_GEOMETRY)) {
        const Triangle _e42 = load_triangle(c_1.primitive);
        float2 b_9 = c_1.uv;
        float w_3 = ((1.0 - b_9.x) - b_9.y);
        float3 e1_ = (_e42.v1_ - _e42.v0_);
        float3 e2_ = (_e42.v2_ - _e42.v0_);
        float3 p_8 = (_e42.v0_ + ((e1_ * (b_9.x).xxx) + (e2_ * (b_9.y).xxx)));
        const float3 _e65 = point_to_world(inst_7, p_8);
        hit.position = _e65;
        const float _e73 = mesh_error(inst_7, _e42.v0_, (e1_ * (b_9.x).xxx), (e2_ * (b_9.y).xxx), p_8);
        hit_error = _e73;
        n_geo = cross(e1_, e2_);
        uint4 a0_ = asuint(attributes.Load4((c_1.primitive * 2u)*16));
        uint4 a1_ = asuint(attributes.Load4(((c_1.primitive * 2u) + 1u)*16));
        const float3 _e91 = decode_octahedral(a0_.x);
        const float3 _e95 = decode_octahedral(a0_.y);
        const float3 _e101 = decode_octahedral(a0_.z);
        n_shade = (((_e91 * (w_3).xxx) + (_e95 * (b_9.x).xxx)) + (_e101 * (b_9.y).xxx));
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
        hit.uv = (((uv0_ * (w_3).xx) + (uv1_ * (b_9.x).xx)) + (uv2_ * (b_9.y).xx));
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
    hit.front_face = (dot(ray_8.dir, _e147) < 0.0);
    Hit _e151 = hit;
    const Hit hit_14 = _e151;
    return hit_14;
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
    Ray ray_9 = (Ray)0;

    FrameUniforms frame_2 = frame;
    rng_seed(pixel_4, sample_4, frame_2.seed);
    const Ray _e7 = dispatch_ray_generation(frame_2.camera_type, frame_2.camera_offset, pixel_4, sample_4);
    ray_9 = _e7;
    ray_9.depth = 0u;
    ray_9.kind = RAY_CAMERA;
    float3 _e15 = ray_9.origin;
    const uint _e17 = medium_at(_e15, NO_HIT);
    ray_9.medium = _e17;
    Ray _e18 = ray_9;
    const Ray ray_33 = _e18;
    return ray_33;
}

float3 node_frame_bounds()
{
    return (65535.0).xxx;
}

Candidate intersect_scene(Ray ray_10, bool shadow_2)
{
    Candidate best_2 = (Candidate)0;
    uint sp_2 = (uint)0;
    uint child_1 = (uint)0;
    uint near_1 = (uint)0;
    uint far_1 = (uint)0;

    uint _e3 = ray_count;
    ray_count = (_e3 + 1u);
    const Candidate _e7 = no_candidate(ray_10.tmax);
    best_2 = _e7;
    FrameUniforms frame_3 = frame;
    if ((frame_3.instance_count == 0u)) {
        Candidate _e14 = best_2;
        const Candidate candidate_6 = _e14;
        return candidate_6;
    }
    uint base_6 = frame_3.tlas_root;
    GpuNode header_3 = ConstructGpuNode(asfloat(nodes.Load3(base_6*32+0)), asuint(nodes.Load(base_6*32+12)), asfloat(nodes.Load3(base_6*32+16)), asuint(nodes.Load(base_6*32+28)));
    const BoxRay _e19 = box_ray(header_3, ray_10);
    const float3 _e22 = node_frame_bounds();
    float _e24 = best_2.t;
    const float _e27 = slab_in_frame((0.0).xxx, _e22, _e19, (_e24 * _e19.unit));
    uint _e29 = F32_INF;
    if ((_e27 == asfloat(_e29))) {
        Candidate _e32 = best_2;
        const Candidate candidate_7 = _e32;
        return candidate_7;
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
                const Candidate _e55 = intersect_object((_e51 & NODE_FIRST_MASK), ray_10, _e54, shadow_2);
                best_2 = _e55;
                uint _e57 = best_2.slot;
                if ((shadow_2 && (_e57 != NO_HIT))) {
                    Candidate _e61 = best_2;
                    const Candidate candidate_8 = _e61;
                    return candidate_8;
                }
            }
        } else {
            uint _e62 = child_1;
            GpuNode n_12 = ConstructGpuNode(asfloat(nodes.Load3((base_6 + _e62)*32+0)), asuint(nodes.Load((base_6 + _e62)*32+12)), asfloat(nodes.Load3((base_6 + _e62)*32+16)), asuint(nodes.Load((base_6 + _e62)*32+28)));
            float _e68 = best_2.t;
            const float2 _e69 = children_entry(n_12, _e19, _e68);
            float tl_1 = _e69.x;
            float tr_1 = _e69.y;
            uint _e73 = F32_INF;
            uint _e77 = F32_INF;
            if (((tl_1 < asfloat(_e73)) && (tr_1 < asfloat(_e77)))) {
                near_1 = n_12.a;
                far_1 = n_12.b;
                if ((tr_1 < tl_1)) {
                    near_1 = n_12.b;
                    far_1 = n_12.a;
                }
                uint _e88 = sp_2;
                if ((_e88 < TLAS_STACK)) {
                    uint _e91 = sp_2;
                    uint _e92 = far_1;
                    traversal_stack[min(uint(min(_e91, 71u)), 71u)] = _e92;
                    uint _e97 = sp_2;
                    sp_2 = (_e97 + 1u);
                }
                uint _e100 = near_1;
                child_1 = _e100;
                continue;
            }
            uint _e102 = F32_INF;
            if ((tl_1 < asfloat(_e102))) {
                child_1 = n_12.a;
                continue;
            }
            uint _e107 = F32_INF;
            if ((tr_1 < asfloat(_e107))) {
                child_1 = n_12.b;
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
    const Candidate candidate_9 = _e119;
    return candidate_9;
}

ConstantBackground ConstructConstantBackground(float3 arg0) {
    ConstantBackground ret = (ConstantBackground)0;
    ret.color = arg0;
    return ret;
}

ConstantBackground load_ConstantBackground(uint offset_4)
{
    uint _e5 = asuint(params.Load((offset_4 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_4 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_4 + 2u)*4));
    const ConstantBackground constantbackground = ConstructConstantBackground(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)));
    return constantbackground;
}

float3 constant_background(ConstantBackground b_6, Ray ray_11)
{
    return b_6.color;
}

float3 dispatch_miss(uint type_id_2, uint offset_5, Ray ray_12)
{
    const ConstantBackground _e2 = load_ConstantBackground(offset_5);
    const float3 _e3 = constant_background(_e2, ray_12);
    return _e3;
}

float3 miss(Ray ray_13)
{
    if (!(HAS_BACKGROUND)) {
        return (0.0).xxx;
    }
    FrameUniforms frame_4 = frame;
    const float3 _e9 = dispatch_miss(frame_4.background_type, frame_4.background_offset, ray_13);
    return _e9;
}

PathDiffuse ConstructPathDiffuse(float3 arg0, uint arg1) {
    PathDiffuse ret = (PathDiffuse)0;
    ret.albedo = arg0;
    ret.roulette_depth = arg1;
    return ret;
}

PathDiffuse load_PathDiffuse(uint offset_6)
{
    uint _e5 = asuint(params.Load((offset_6 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_6 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_6 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_6 + 3u)*4));
    const PathDiffuse pathdiffuse = ConstructPathDiffuse(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), _e24);
    return pathdiffuse;
}

uint light_count_query()
{
    FrameUniforms _e1 = frame;
    return _e1.light_count;
}

QuadLight ConstructQuadLight(float3 arg0, float3 arg1, float3 arg2, float3 arg3, float arg4, uint arg5) {
    QuadLight ret = (QuadLight)0;
    ret.corner = arg0;
    ret.edge_u = arg1;
    ret.edge_v = arg2;
    ret.color = arg3;
    ret.intensity = arg4;
    ret.lamp = arg5;
    return ret;
}

QuadLight load_QuadLight(uint offset_7)
{
    uint _e5 = asuint(params.Load((offset_7 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_7 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_7 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_7 + 4u)*4));
    uint _e30 = asuint(params.Load((offset_7 + 5u)*4));
    uint _e36 = asuint(params.Load((offset_7 + 6u)*4));
    uint _e43 = asuint(params.Load((offset_7 + 8u)*4));
    uint _e49 = asuint(params.Load((offset_7 + 9u)*4));
    uint _e55 = asuint(params.Load((offset_7 + 10u)*4));
    uint _e62 = asuint(params.Load((offset_7 + 12u)*4));
    uint _e68 = asuint(params.Load((offset_7 + 13u)*4));
    uint _e74 = asuint(params.Load((offset_7 + 14u)*4));
    uint _e81 = asuint(params.Load((offset_7 + 15u)*4));
    uint _e87 = asuint(params.Load((offset_7 + 16u)*4));
    const QuadLight quadlight = ConstructQuadLight(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), float3(asfloat(_e24), asfloat(_e30), asfloat(_e36)), float3(asfloat(_e43), asfloat(_e49), asfloat(_e55)), float3(asfloat(_e62), asfloat(_e68), asfloat(_e74)), asfloat(_e81), _e87);
    return quadlight;
}

float shadow_preset(float3 normal, float3 dir)
{
    uint mode = scratch[min(uint(min(SCRATCH_SHADOW_MODE, 24u)), 24u)];
    if ((mode == SHADOW_UNOCCLUDED)) {
        return 1.0;
    }
    if (((mode == SHADOW_ABOVE) && !((dot(dir, normal) > 0.0)))) {
        return 0.0;
    }
    return -1.0;
}

void scratch_store3f(uint i_2, float3 v_2)
{
    uint3 b_10 = asuint(v_2);
    scratch[min(uint(min(i_2, 24u)), 24u)] = b_10.x;
    scratch[min(uint(min((i_2 + 1u), 24u)), 24u)] = b_10.y;
    scratch[min(uint(min((i_2 + 2u), 24u)), 24u)] = b_10.z;
    return;
}

float shadow_deferred(float3 position, float3 normal_1, float3 dir_1, float dist)
{
    const float _e4 = shadow_preset(normal_1, dir_1);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    uint i_9 = scratch[min(uint(min(SCRATCH_QUERY, 24u)), 24u)];
    scratch[min(uint(min(SCRATCH_QUERY, 24u)), 24u)] = (i_9 + 1u);
    uint _e25 = scratch[min(uint(min(SCRATCH_RESOLVED, 24u)), 24u)];
    if ((i_9 < _e25)) {
        uint _e32 = scratch[min(uint(min(SCRATCH_LIGHT_BITS, 24u)), 24u)];
        return float(((_e32 >> (i_9 & 31u)) & 1u));
    }
    uint _e44 = scratch[min(uint(min(SCRATCH_PENDING, 24u)), 24u)];
    if ((_e44 != 0u)) {
        return 1.0;
    }
    if ((i_9 >= LIGHT_QUERIES)) {
        counters.InterlockedAdd(min(COUNTER_SHADOW_OVERFLOW, 3u)*4, 1u);
        return 1.0;
    }
    scratch_store3f(SCRATCH_LIGHT_QUERY, position);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 3u), normal_1);
    scratch_store3f((SCRATCH_LIGHT_QUERY + 6u), dir_1);
    scratch[min(uint(min((SCRATCH_LIGHT_QUERY + 9u), 24u)), 24u)] = asuint(dist);
    scratch[min(uint(min(SCRATCH_PENDING, 24u)), 24u)] = 1u;
    return 1.0;
}

LightSample ConstructLightSample(float3 arg0, float arg1, float3 arg2, float arg3) {
    LightSample ret = (LightSample)0;
    ret.dir = arg0;
    ret.dist = arg1;
    ret.radiance = arg2;
    ret.pdf = arg3;
    return ret;
}

LightSample quad_light(QuadLight l, float3 position_1, float3 normal_2)
{
    float3 c_11 = cross(l.edge_u, l.edge_v);
    float area = length(c_11);
    const float2 _e7 = rand2_next();
    float3 to_light = (((l.corner + (l.edge_u * (_e7.x).xxx)) + (l.edge_v * (_e7.y).xxx)) - position_1);
    float dist2_ = dot(to_light, to_light);
    float dist_3 = sqrt(dist2_);
    float3 dir_9 = (to_light / (max(dist_3, 1e-20)).xxx);
    float cos_light = (-(dot(dir_9, c_11)) / max(area, 1e-30));
    if ((!((cos_light > 0.0)) || !((dist2_ > 0.0)))) {
        const LightSample lightsample = ConstructLightSample(dir_9, dist_3, (0.0).xxx, 0.0);
        return lightsample;
    }
    const float _e42 = shadow_deferred(position_1, normal_2, dir_9, dist_3);
    float strength = (((l.intensity * cos_light) * area) / dist2_);
    float pdf_1 = ((l.lamp == 1u) ? (dist2_ / (cos_light * area)) : 0.0);
    const LightSample lightsample_1 = ConstructLightSample(dir_9, dist_3, ((l.color * (strength).xxx) * (_e42).xxx), pdf_1);
    return lightsample_1;
}

SphereLight ConstructSphereLight(float3 arg0, float arg1, float3 arg2, float arg3, uint arg4) {
    SphereLight ret = (SphereLight)0;
    ret.position = arg0;
    ret.radius = arg1;
    ret.color = arg2;
    ret.intensity = arg3;
    ret.lamp = arg4;
    return ret;
}

SphereLight load_SphereLight(uint offset_8)
{
    uint _e5 = asuint(params.Load((offset_8 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_8 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_8 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_8 + 3u)*4));
    uint _e30 = asuint(params.Load((offset_8 + 4u)*4));
    uint _e36 = asuint(params.Load((offset_8 + 5u)*4));
    uint _e42 = asuint(params.Load((offset_8 + 6u)*4));
    uint _e49 = asuint(params.Load((offset_8 + 7u)*4));
    uint _e55 = asuint(params.Load((offset_8 + 8u)*4));
    const SphereLight spherelight = ConstructSphereLight(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), asfloat(_e24), float3(asfloat(_e30), asfloat(_e36), asfloat(_e42)), asfloat(_e49), _e55);
    return spherelight;
}

float3x3 orthonormal_basis(float3 n_3)
{
    float sign_ = (((asuint(n_3.z) & 2147483648u) != 0u) ? -1.0 : 1.0);
    float a_7 = (-1.0 / (sign_ + n_3.z));
    float b_11 = ((n_3.x * n_3.y) * a_7);
    float _e16 = (sign_ * n_3.x);
    return float3x3(float3((1.0 + ((_e16 * n_3.x) * a_7)), (sign_ * b_11), -(_e16)), float3(b_11, (sign_ + ((n_3.y * n_3.y) * a_7)), -(n_3.y)), n_3);
}

LightSample sphere_light(SphereLight l_1, float3 position_2, float3 normal_3)
{
    float3 to_center = (l_1.position - position_2);
    float d2_ = dot(to_center, to_center);
    float r2_2 = max((l_1.radius * l_1.radius), 1e-20);
    if ((d2_ <= r2_2)) {
        const LightSample lightsample_2 = ConstructLightSample(float3(0.0, 1.0, 0.0), 0.0, (0.0).xxx, 0.0);
        return lightsample_2;
    }
    float3 w_4 = (to_center * (rsqrt(d2_)).xxx);
    float s2_ = (r2_2 / d2_);
    float cos_max = sqrt((1.0 - s2_));
    float one_minus_cos_max = (s2_ / (1.0 + cos_max));
    const float2 _e31 = rand2_next();
    float cos_t = (1.0 - (_e31.x * one_minus_cos_max));
    float sin_t = sqrt(max((1.0 - (cos_t * cos_t)), 0.0));
    float phi = (TAU * _e31.y);
    const float3x3 _e45 = orthonormal_basis(w_4);
    const float3 _e52 = normalize_vec3f(mul(float3((cos(phi) * sin_t), (sin(phi) * sin_t), cos_t), _e45));
    float along_1 = dot(to_center, _e52);
    float dist_4 = max((along_1 - sqrt(max((r2_2 - (d2_ - (along_1 * along_1))), 0.0))), 0.0);
    float weight_4 = (((l_1.intensity * 2.0) * one_minus_cos_max) / r2_2);
    const float _e68 = shadow_deferred(position_2, normal_3, _e52, dist_4);
    float pdf_2 = ((l_1.lamp == 1u) ? (1.0 / (TAU * one_minus_cos_max)) : 0.0);
    const LightSample lightsample_3 = ConstructLightSample(_e52, dist_4, ((l_1.color * (weight_4).xxx) * (_e68).xxx), pdf_2);
    return lightsample_3;
}

LightSample ZeroValueLightSample() {
    return (LightSample)0;
}

LightSample dispatch_light(uint type_id_3, uint offset_9, float3 position_3, float3 normal_4)
{
    switch(type_id_3) {
        case 0u: {
            const QuadLight _e4 = load_QuadLight(offset_9);
            const LightSample _e5 = quad_light(_e4, position_3, normal_4);
            const LightSample lightsample_4 = _e5;
            return lightsample_4;
        }
        case 1u: {
            const SphereLight _e6 = load_SphereLight(offset_9);
            const LightSample _e7 = sphere_light(_e6, position_3, normal_4);
            const LightSample lightsample_5 = _e7;
            return lightsample_5;
        }
        default: {
            break;
        }
    }
    const LightSample lightsample_6 = ZeroValueLightSample();
    return lightsample_6;
}

float3 scratch_load3f(uint i_3)
{
    uint _e5 = scratch[min(uint(min(i_3, 24u)), 24u)];
    uint _e12 = scratch[min(uint(min((i_3 + 1u), 24u)), 24u)];
    uint _e19 = scratch[min(uint(min((i_3 + 2u), 24u)), 24u)];
    return asfloat(uint3(_e5, _e12, _e19));
}

float3 step_toward(float3 x_3, float3 s_1)
{
    uint3 bits_2 = asuint(x_3);
    bool3 up_1 = ((sign(x_3) * sign(s_1)) > (0.0).xxx);
    float3 stepped = asfloat((up_1 ? (bits_2 + (1u).xxx) : (bits_2 - (1u).xxx)));
    float3 from_zero = ((s_1 > (0.0).xxx) ? (1.1754944e-38).xxx : (-1.1754944e-38).xxx);
    float3 moved = ((x_3 == (0.0).xxx) ? from_zero : stepped);
    return (!((s_1 == (0.0).xxx)) ? moved : x_3);
}

float3 offset_origin(float3 p_5, float3 n_4, float error)
{
    float d_4 = ((2.0 * error) * ((abs(n_4.x) + abs(n_4.y)) + abs(n_4.z)));
    float3 offset_16 = (n_4 * (d_4).xxx);
    const float3 _e17 = step_toward((p_5 + offset_16), offset_16);
    return _e17;
}

Ray shadow_ray(float3 position_4, float3 normal_5, float3 dir_2, float dist_1)
{
    float3 n_5 = (float3)0;
    float tmax_4 = (float)0;

    n_5 = normal_5;
    float3 _e5 = n_5;
    if ((dot(dir_2, _e5) < 0.0)) {
        float3 _e9 = n_5;
        n_5 = -(_e9);
    }
    float3 a_8 = abs(position_4);
    float _e13 = hit_error;
    float error_3 = max(_e13, (GAMMA_4_ * max(max(a_8.x, a_8.y), a_8.z)));
    float3 _e22 = n_5;
    const float3 _e23 = offset_origin(position_4, _e22, error_3);
    uint _e25 = F32_INF;
    tmax_4 = asfloat(_e25);
    uint _e29 = F32_INF;
    if ((dist_1 < asfloat(_e29))) {
        float3 light = (position_4 + (dir_2 * (dist_1).xxx));
        float dd = dot(dir_2, dir_2);
        float along_2 = (dot((light - _e23), dir_2) / dd);
        float3 l_7 = (abs(position_4) + abs((dir_2 * (dist_1).xxx)));
        tmax_4 = ((along_2 * (1.0 - 1e-5)) - ((LIGHT_ERROR * max(max(l_7.x, l_7.y), l_7.z)) / sqrt(dd)));
    }
    float _e59 = tmax_4;
    const Ray ray_34 = ConstructRay(_e23, 0.0, dir_2, _e59, 0u, RAY_SHADOW, 0u);
    return ray_34;
}

float shadow_query(float3 position_5, float3 normal_6, float3 dir_3, float dist_2)
{
    const float _e4 = shadow_preset(normal_6, dir_3);
    if ((_e4 >= 0.0)) {
        return _e4;
    }
    const Ray _e7 = shadow_ray(position_5, normal_6, dir_3, dist_2);
    const Candidate _e9 = intersect_scene(_e7, true);
    return ((_e9.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample sample_light_deferred(uint i_4, float3 position_6, float3 normal_7)
{
    uint after = (uint)0;
    uint resolved = (uint)0;
    uint bits_1 = (uint)0;

    FrameUniforms frame_5 = frame;
    if ((i_4 >= frame_5.light_count)) {
        const LightSample lightsample_7 = ConstructLightSample(float3(0.0, 1.0, 0.0), 0.0, (0.0).xxx, 0.0);
        return lightsample_7;
    }
    uint entry = (frame_5.light_table + (i_4 * LIGHT_ENTRY_STRIDE));
    uint type_id_7 = asuint(params.Load(entry*4));
    uint offset_17 = asuint(params.Load((entry + 1u)*4));
    uint start_1 = rng_state;
    after = start_1;
    resolved = 0u;
    bits_1 = 0u;
    scratch[min(uint(min(SCRATCH_RESOLVED, 24u)), 24u)] = 0u;
    scratch[min(uint(min(SCRATCH_LIGHT_BITS, 24u)), 24u)] = 0u;
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        rng_state = start_1;
        scratch[min(uint(min(SCRATCH_QUERY, 24u)), 24u)] = 0u;
        scratch[min(uint(min(SCRATCH_PENDING, 24u)), 24u)] = 0u;
        const LightSample _e60 = dispatch_light(type_id_7, offset_17, position_6, normal_7);
        uint _e66 = scratch[min(uint(min(SCRATCH_PENDING, 24u)), 24u)];
        if ((_e66 == 0u)) {
            uint _e69 = resolved;
            if ((_e69 > 0u)) {
                uint _e72 = after;
                rng_state = _e72;
            }
            const LightSample lightsample_8 = _e60;
            return lightsample_8;
        }
        uint _e74 = resolved;
        if ((_e74 == 0u)) {
            uint _e78 = rng_state;
            after = _e78;
        }
        uint _e79 = after;
        rng_state = _e79;
        const float3 _e82 = scratch_load3f(SCRATCH_LIGHT_QUERY);
        const float3 _e85 = scratch_load3f((SCRATCH_LIGHT_QUERY + 3u));
        const float3 _e88 = scratch_load3f((SCRATCH_LIGHT_QUERY + 6u));
        uint _e95 = scratch[min(uint(min((SCRATCH_LIGHT_QUERY + 9u), 24u)), 24u)];
        const float _e97 = shadow_query(_e82, _e85, _e88, asfloat(_e95));
        uint _e99 = rng_state;
        after = _e99;
        if (!((_e97 == 0.0))) {
            uint _e108 = scratch[min(uint(min(SCRATCH_QUERY, 24u)), 24u)];
            uint _e109 = resolved;
            if ((_e108 == (_e109 + 1u))) {
                uint _e113 = after;
                rng_state = _e113;
                scratch[min(uint(min(SCRATCH_PENDING, 24u)), 24u)] = 0u;
                const LightSample lightsample_9 = _e60;
                return lightsample_9;
            }
            uint _e121 = bits_1;
            uint _e123 = resolved;
            bits_1 = (_e121 | (1u << (_e123 & 31u)));
        }
        uint _e128 = resolved;
        resolved = (_e128 + 1u);
        uint _e132 = bits_1;
        scratch[min(uint(min(SCRATCH_LIGHT_BITS, 24u)), 24u)] = _e132;
        uint _e138 = resolved;
        scratch[min(uint(min(SCRATCH_RESOLVED, 24u)), 24u)] = _e138;
    }
    const LightSample lightsample_10 = ZeroValueLightSample();
    return lightsample_10;
}

LightSample sample_light_above_deferred(uint i_5, float3 position_7, float3 normal_8)
{
    scratch[min(uint(min(SCRATCH_SHADOW_MODE, 24u)), 24u)] = SHADOW_ABOVE;
    const LightSample _e9 = sample_light_deferred(i_5, position_7, normal_8);
    scratch[min(uint(min(SCRATCH_SHADOW_MODE, 24u)), 24u)] = SHADOW_TRACED;
    const LightSample lightsample_11 = _e9;
    return lightsample_11;
}

float mis_weight(float p_6, float other)
{
    if (!((p_6 > 0.0))) {
        return 0.0;
    }
    float r_3 = (max(other, 0.0) / p_6);
    if (!((r_3 < 1e18))) {
        uint _e15 = F32_INF;
        uint _e19 = F32_INF;
        return (((p_6 == asfloat(_e15)) && (other < asfloat(_e19))) ? 1.0 : 0.0);
    }
    return (1.0 / (1.0 + (r_3 * r_3)));
}

float mis_light_weight(LightSample l_2, float bsdf_pdf)
{
    if (!((l_2.pdf > 0.0))) {
        return 1.0;
    }
    const float _e8 = mis_weight(l_2.pdf, bsdf_pdf);
    return _e8;
}

float3 path_diffuse_shade(PathDiffuse m, Ray ray_14, Hit hit_1, float3 secondary)
{
    float3 direct = (float3)0;
    uint i_6 = (uint)0;

    float3 n_13 = faceforward(hit_1.normal, ray_14.dir, hit_1.geometric_normal);
    float3 ng = faceforward(hit_1.geometric_normal, ray_14.dir, hit_1.geometric_normal);
    direct = (0.0).xxx;
    const uint _e16 = light_count_query();
    i_6 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e36 = i_6;
            i_6 = (_e36 + 1u);
        }
        loop_init_2 = false;
        uint _e18 = i_6;
        if ((_e18 >= _e16)) {
            break;
        }
        uint _e20 = i_6;
        const LightSample _e22 = sample_light_above_deferred(_e20, hit_1.position, ng);
        float c_12 = max(dot(n_13, _e22.dir), 0.0);
        float3 _e27 = direct;
        const float _e31 = mis_light_weight(_e22, (c_12 * INV_PI));
        direct = (_e27 + (_e22.radiance * ((c_12 * _e31)).xxx));
    }
    float3 _e43 = direct;
    return (((m.albedo * (INV_PI).xxx) * _e43) + secondary);
}

QuadLamp ConstructQuadLamp(float3 arg0, float arg1, float arg2) {
    QuadLamp ret = (QuadLamp)0;
    ret.color = arg0;
    ret.intensity = arg1;
    ret.area = arg2;
    return ret;
}

QuadLamp load_QuadLamp(uint offset_10)
{
    uint _e5 = asuint(params.Load((offset_10 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_10 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_10 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_10 + 3u)*4));
    uint _e30 = asuint(params.Load((offset_10 + 4u)*4));
    const QuadLamp quadlamp = ConstructQuadLamp(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), asfloat(_e24), asfloat(_e30));
    return quadlamp;
}

bool after_nee_bounce(Ray ray_15)
{
    return (dot(ray_15.dir, ray_15.dir) > 2.0);
}

float bounce_pdf(Ray ray_16)
{
    float x_6 = (length(ray_16.dir) - MIS_BOUNCE_LENGTH);
    if (!((x_6 > -0.25))) {
        return 0.0;
    }
    return (exp((max(x_6, 0.0) * 90.0)) - 1.0);
}

float3 quad_lamp_shade(QuadLamp m_1, Ray ray_17, Hit hit_2)
{
    if (!(hit_2.front_face)) {
        return (0.0).xxx;
    }
    float3 le = (m_1.color * (m_1.intensity).xxx);
    const bool _e11 = after_nee_bounce(ray_17);
    if (!(_e11)) {
        return le;
    }
    const float _e13 = bounce_pdf(ray_17);
    float len = length(ray_17.dir);
    float dist_5 = (hit_2.t * len);
    float cos_l = (abs(dot(hit_2.geometric_normal, ray_17.dir)) / len);
    float pl = ((dist_5 * dist_5) / max((cos_l * m_1.area), 1e-30));
    const float _e29 = mis_weight(_e13, pl);
    return (le * (_e29).xxx);
}

SphereLamp ConstructSphereLamp(float3 arg0, float arg1, float arg2) {
    SphereLamp ret = (SphereLamp)0;
    ret.color = arg0;
    ret.intensity = arg1;
    ret.radius = arg2;
    return ret;
}

SphereLamp load_SphereLamp(uint offset_11)
{
    uint _e5 = asuint(params.Load((offset_11 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_11 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_11 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_11 + 3u)*4));
    uint _e30 = asuint(params.Load((offset_11 + 4u)*4));
    const SphereLamp spherelamp = ConstructSphereLamp(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), asfloat(_e24), asfloat(_e30));
    return spherelamp;
}

float3 sphere_lamp_shade(SphereLamp m_2, Ray ray_18, Hit hit_3)
{
    if (!(hit_3.front_face)) {
        return (0.0).xxx;
    }
    float r2_3 = max((m_2.radius * m_2.radius), 1e-20);
    float3 le_1 = (m_2.color * (((m_2.intensity * INV_PI) / r2_3)).xxx);
    const bool _e19 = after_nee_bounce(ray_18);
    if (!(_e19)) {
        return le_1;
    }
    const float _e21 = bounce_pdf(ray_18);
    float3 center_ = (hit_3.position - (hit_3.normal * (m_2.radius).xxx));
    float3 to_center_1 = (center_ - ray_18.origin);
    float s2_1 = (r2_3 / max(dot(to_center_1, to_center_1), r2_3));
    float one_minus_cos_max_1 = (s2_1 / (1.0 + sqrt((1.0 - s2_1))));
    float pl_1 = (1.0 / max((TAU * one_minus_cos_max_1), 1e-30));
    const float _e45 = mis_weight(_e21, pl_1);
    return (le_1 * (_e45).xxx);
}

PathPbr ConstructPathPbr(float3 arg0, float arg1, float arg2, float3 arg3, uint arg4) {
    PathPbr ret = (PathPbr)0;
    ret.base_color = arg0;
    ret.metallic = arg1;
    ret.roughness = arg2;
    ret.emissive = arg3;
    ret.roulette_depth = arg4;
    return ret;
}

PathPbr load_PathPbr(uint offset_12)
{
    uint _e5 = asuint(params.Load((offset_12 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_12 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_12 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_12 + 3u)*4));
    uint _e30 = asuint(params.Load((offset_12 + 4u)*4));
    uint _e36 = asuint(params.Load((offset_12 + 8u)*4));
    uint _e42 = asuint(params.Load((offset_12 + 9u)*4));
    uint _e48 = asuint(params.Load((offset_12 + 10u)*4));
    uint _e55 = asuint(params.Load((offset_12 + 11u)*4));
    const PathPbr pathpbr = ConstructPathPbr(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), asfloat(_e24), asfloat(_e30), float3(asfloat(_e36), asfloat(_e42), asfloat(_e48)), _e55);
    return pathpbr;
}

float3 path_pbr_ng(Ray ray_19, Hit hit_4)
{
    return faceforward(hit_4.geometric_normal, ray_19.dir, hit_4.geometric_normal);
}

float3 path_pbr_n(Ray ray_20, Hit hit_5)
{
    const float3 _e2 = path_pbr_ng(ray_20, hit_5);
    float3 n_14 = faceforward(hit_5.normal, -(_e2), hit_5.normal);
    return ((dot(n_14, ray_20.dir) < 0.0) ? n_14 : _e2);
}

float pbr_alpha2_(float roughness)
{
    float a_9 = max((saturate(roughness) * saturate(roughness)), PBR_MIN_ALPHA);
    return (a_9 * a_9);
}

float3 pbr_fresnel(float3 f0_, float c_2)
{
    float k_1 = (1.0 - saturate(c_2));
    float k2_ = (k_1 * k_1);
    return (f0_ + (((1.0).xxx - f0_) * (((k2_ * k2_) * k_1)).xxx));
}

float pbr_ggx_d(float ndh, float a2_)
{
    float d_5 = (((ndh * ndh) * (a2_ - 1.0)) + 1.0);
    return ((a2_ * INV_PI) / (d_5 * d_5));
}

float pbr_smith_v(float ndl, float ndv, float a2_1)
{
    float gv = (ndl * sqrt((((ndv * ndv) * (1.0 - a2_1)) + a2_1)));
    float gl = (ndv * sqrt((((ndl * ndl) * (1.0 - a2_1)) + a2_1)));
    return (0.5 / max((gv + gl), 1e-20));
}

float3 pbr_eval(float3 base_1, float metallic, float roughness_1, float3 n_6, float3 v_3, float3 l_3)
{
    float ndv_3 = dot(n_6, v_3);
    float ndl_1 = dot(n_6, l_3);
    if ((!((ndv_3 > 0.0)) || !((ndl_1 > 0.0)))) {
        return (0.0).xxx;
    }
    float metal = saturate(metallic);
    const float _e18 = pbr_alpha2_(roughness_1);
    float3 f0_1 = lerp((0.04).xxx, base_1, (metal).xxx);
    const float3 _e24 = normalize_vec3f((v_3 + l_3));
    const float3 _e26 = pbr_fresnel(f0_1, dot(v_3, _e24));
    const float _e29 = pbr_ggx_d(saturate(dot(n_6, _e24)), _e18);
    const float _e30 = pbr_smith_v(ndl_1, ndv_3, _e18);
    float3 spec = (_e26 * ((_e29 * _e30)).xxx);
    float3 diffuse = ((((1.0).xxx - _e26) * base_1) * (((1.0 - metal) * INV_PI)).xxx);
    return ((diffuse + spec) * (ndl_1).xxx);
}

float luminance(float3 c_3)
{
    return dot(c_3, float3(0.2126, 0.7152, 0.0722));
}

float pbr_specular_chance(float3 base_2, float metallic_1, float ndv_1)
{
    float metal_1 = saturate(metallic_1);
    const float3 _e8 = pbr_fresnel(lerp((0.04).xxx, base_2, (metal_1).xxx), ndv_1);
    const float _e9 = luminance(_e8);
    const float _e18 = luminance(((base_2 * ((1.0 - metal_1)).xxx) * ((1.0).xxx - _e8)));
    if (!((_e18 > 0.0))) {
        return 1.0;
    }
    if (!((_e9 > 0.0))) {
        return 0.0;
    }
    return min(max((_e9 / (_e9 + _e18)), 0.1), 0.9);
}

float pbr_specular_pdf(float ndh_1, float ndv_2, float a2_2)
{
    const float _e3 = pbr_ggx_d(ndh_1, a2_2);
    return ((_e3 * 0.5) / (ndv_2 + sqrt((a2_2 + (((1.0 - a2_2) * ndv_2) * ndv_2)))));
}

float pbr_pdf(float3 base_3, float metallic_2, float roughness_2, float3 n_7, float3 v_4, float3 l_4)
{
    float ndv_4 = dot(n_7, v_4);
    float ndl_2 = dot(n_7, l_4);
    if ((!((ndv_4 > 0.0)) || !((ndl_2 > 0.0)))) {
        return 0.0;
    }
    const float _e16 = pbr_alpha2_(roughness_2);
    const float _e17 = pbr_specular_chance(base_3, metallic_2, ndv_4);
    const float3 _e19 = normalize_vec3f((v_4 + l_4));
    const float _e22 = pbr_specular_pdf(saturate(dot(n_7, _e19)), ndv_4, _e16);
    return ((_e17 * _e22) + (((1.0 - _e17) * ndl_2) * INV_PI));
}

float3 path_pbr_shade(PathPbr m_3, Ray ray_21, Hit hit_6, float3 secondary_1)
{
    float3 direct_1 = (float3)0;
    uint i_7 = (uint)0;
    float w = (float)0;

    const float3 _e4 = path_pbr_n(ray_21, hit_6);
    const float3 _e6 = normalize_vec3f(ray_21.dir);
    float3 v_7 = -(_e6);
    direct_1 = (0.0).xxx;
    const float3 _e11 = path_pbr_ng(ray_21, hit_6);
    const uint _e13 = light_count_query();
    i_7 = 0u;
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e49 = i_7;
            i_7 = (_e49 + 1u);
        }
        loop_init_3 = false;
        uint _e15 = i_7;
        if ((_e15 >= _e13)) {
            break;
        }
        uint _e17 = i_7;
        const LightSample _e19 = sample_light_above_deferred(_e17, hit_6.position, _e11);
        if (any((_e19.radiance > (0.0).xxx))) {
            const float3 _e29 = pbr_eval(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
            w = 1.0;
            if ((_e19.pdf > 0.0)) {
                const float _e40 = pbr_pdf(m_3.base_color, m_3.metallic, m_3.roughness, _e4, v_7, _e19.dir);
                const float _e41 = mis_weight(_e19.pdf, _e40);
                w = _e41;
            }
            float3 _e42 = direct_1;
            float _e45 = w;
            direct_1 = (_e42 + ((_e19.radiance * _e29) * (_e45).xxx));
        }
    }
    float3 _e53 = direct_1;
    return ((m_3.emissive + _e53) + secondary_1);
}

float3 ZeroValuefloat3() {
    return (float3)0;
}

float3 dispatch_closest_hit(uint type_id_4, uint offset_13, Ray ray_22, Hit hit_7, float3 secondary_2)
{
    switch(type_id_4) {
        case 0u: {
            const PathDiffuse _e5 = load_PathDiffuse(offset_13);
            const float3 _e6 = path_diffuse_shade(_e5, ray_22, hit_7, secondary_2);
            return _e6;
        }
        case 1u: {
            const QuadLamp _e7 = load_QuadLamp(offset_13);
            const float3 _e8 = quad_lamp_shade(_e7, ray_22, hit_7);
            return _e8;
        }
        case 2u: {
            const SphereLamp _e9 = load_SphereLamp(offset_13);
            const float3 _e10 = sphere_lamp_shade(_e9, ray_22, hit_7);
            return _e10;
        }
        case 3u: {
            const PathPbr _e11 = load_PathPbr(offset_13);
            const float3 _e12 = path_pbr_shade(_e11, ray_22, hit_7, secondary_2);
            return _e12;
        }
        default: {
            break;
        }
    }
    return ZeroValuefloat3();
}

float3 shade_direct(Ray ray_23, Candidate c_4)
{
    GpuInstance inst_8 = ConstructGpuInstance(asfloat(instances.Load4(c_4.slot*128+0)), asfloat(instances.Load4(c_4.slot*128+16)), asfloat(instances.Load4(c_4.slot*128+32)), asfloat(instances.Load4(c_4.slot*128+48)), asfloat(instances.Load4(c_4.slot*128+64)), asfloat(instances.Load4(c_4.slot*128+80)), asuint(instances.Load(c_4.slot*128+96)), asuint(instances.Load(c_4.slot*128+100)), asuint(instances.Load(c_4.slot*128+104)), asuint(instances.Load(c_4.slot*128+108)), asuint(instances.Load(c_4.slot*128+112)), asuint(instances.Load(c_4.slot*128+116)), asuint(instances.Load(c_4.slot*128+120)), asuint(instances.Load(c_4.slot*128+124)));
    const Hit _e6 = finish_hit(ray_23, c_4);
    const float3 _e11 = dispatch_closest_hit(inst_8.material_type, inst_8.material_offset, ray_23, _e6, (0.0).xxx);
    return _e11;
}

float3 dispatch_medium(uint type_id_5, uint offset_14, Ray ray_24, float t_1, float3 radiance)
{
    return ZeroValuefloat3();
}

float3 through_medium(Ray ray_25, float t_2, float3 radiance_1)
{
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_25.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_9 = ConstructGpuInstance(asfloat(instances.Load4((ray_25.medium - 1u)*128+0)), asfloat(instances.Load4((ray_25.medium - 1u)*128+16)), asfloat(instances.Load4((ray_25.medium - 1u)*128+32)), asfloat(instances.Load4((ray_25.medium - 1u)*128+48)), asfloat(instances.Load4((ray_25.medium - 1u)*128+64)), asfloat(instances.Load4((ray_25.medium - 1u)*128+80)), asuint(instances.Load((ray_25.medium - 1u)*128+96)), asuint(instances.Load((ray_25.medium - 1u)*128+100)), asuint(instances.Load((ray_25.medium - 1u)*128+104)), asuint(instances.Load((ray_25.medium - 1u)*128+108)), asuint(instances.Load((ray_25.medium - 1u)*128+112)), asuint(instances.Load((ray_25.medium - 1u)*128+116)), asuint(instances.Load((ray_25.medium - 1u)*128+120)), asuint(instances.Load((ray_25.medium - 1u)*128+124)));
    if (((inst_9.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    const float3 _e21 = dispatch_medium(inst_9.material_type, inst_9.material_offset, ray_25, t_2, radiance_1);
    return _e21;
}

PathState ConstructPathState(Ray arg0, float3 arg1, float3 arg2, bool arg3) {
    PathState ret = (PathState)0;
    ret.ray = arg0;
    ret.beta = arg1;
    ret.radiance = arg2;
    ret.live = arg3;
    return ret;
}

PathState start_path(Ray ray_26)
{
    const PathState pathstate = ConstructPathState(ray_26, (1.0).xxx, (0.0).xxx, true);
    return pathstate;
}

float3 sample_cosine_hemisphere(float3 n_8, float2 u)
{
    float r_4 = sqrt(u.x);
    float phi_1 = (6.2831855 * u.y);
    float3 local = float3((r_4 * cos(phi_1)), (r_4 * sin(phi_1)), sqrt(max((1.0 - u.x), 0.0)));
    const float3x3 _e17 = orthonormal_basis(n_8);
    return mul(local, _e17);
}

float3 mis_bounce_dir(float3 dir_4, float pdf)
{
    float x_7 = min((log((1.0 + max(pdf, 0.0))) * (1.0 / 90.0)), 0.999);
    return (dir_4 * ((MIS_BOUNCE_LENGTH + x_7)).xxx);
}

void rt_spawn(float3 dir_5, float3 weight)
{
    uint _e3 = spawn_count;
    if ((_e3 < 1u)) {
        spawn_dirs[min(uint(_e3), 0u)] = dir_5;
        spawn_weights[min(uint(_e3), 0u)] = weight;
        spawn_count = (_e3 + 1u);
    }
}

void path_diffuse_rays(PathDiffuse m_4, Ray ray_27, Hit hit_8)
{
    float3 weight_1 = (float3)0;

    float3 ng_1 = (hit_8.front_face ? hit_8.geometric_normal : -(hit_8.geometric_normal));
    float3 n_15 = faceforward(hit_8.normal, -(ng_1), hit_8.normal);
    const float2 _e12 = rand2_next();
    const float3 _e13 = sample_cosine_hemisphere(n_15, _e12);
    weight_1 = m_4.albedo;
    if ((ray_27.depth >= m_4.roulette_depth)) {
        float q_4 = saturate(max(m_4.albedo.x, max(m_4.albedo.y, m_4.albedo.z)));
        const float _e28 = rand_next();
        if ((_e28 >= q_4)) {
            return;
        }
        weight_1 = (m_4.albedo / (q_4).xxx);
    }
    if ((dot(_e13, ng_1) > 0.0)) {
        const float3 _e41 = mis_bounce_dir(_e13, (max(dot(n_15, _e13), 0.0) * INV_PI));
        float3 _e42 = weight_1;
        rt_spawn(_e41, _e42);
    }
    return;
}

float3 pbr_sample_vndf(float3 ve, float alpha, float2 u_1)
{
    float3 t1_ = (float3)0;

    const float3 _e9 = normalize_vec3f(float3((alpha * ve.x), (alpha * ve.y), ve.z));
    float lensq = ((_e9.x * _e9.x) + (_e9.y * _e9.y));
    t1_ = float3(1.0, 0.0, 0.0);
    if ((lensq > 0.0)) {
        t1_ = (float3(-(_e9.y), _e9.x, 0.0) * (rsqrt(lensq)).xxx);
    }
    float3 _e32 = t1_;
    float3 t2_ = cross(_e9, _e32);
    float r_5 = sqrt(u_1.x);
    float phi_2 = (TAU * u_1.y);
    float p1_ = (r_5 * cos(phi_2));
    float s_8 = (0.5 * (1.0 + _e9.z));
    float p2_ = (((1.0 - s_8) * sqrt(max((1.0 - (p1_ * p1_)), 0.0))) + ((s_8 * r_5) * sin(phi_2)));
    float3 _e59 = t1_;
    float3 nh = (((_e59 * (p1_).xxx) + (t2_ * (p2_).xxx)) + (_e9 * (sqrt(max(((1.0 - (p1_ * p1_)) - (p2_ * p2_)), 0.0))).xxx));
    const float3 _e84 = normalize_vec3f(float3((alpha * nh.x), (alpha * nh.y), max(nh.z, 0.0)));
    return _e84;
}

PbrSample ConstructPbrSample(float3 arg0, float3 arg1, float arg2) {
    PbrSample ret = (PbrSample)0;
    ret.dir = arg0;
    ret.weight = arg1;
    ret.pdf = arg2;
    return ret;
}

PbrSample pbr_sample(float3 base_4, float metallic_3, float roughness_3, float3 n_9, float3 v_5, float3 u_2)
{
    float3 l_5 = (float3)0;

    float ndv_5 = dot(n_9, v_5);
    if (!((ndv_5 > 0.0))) {
        const PbrSample pbrsample = ConstructPbrSample(n_9, (0.0).xxx, 0.0);
        return pbrsample;
    }
    const float _e14 = pbr_specular_chance(base_4, metallic_3, ndv_5);
    l_5 = (0.0).xxx;
    if ((u_2.x < _e14)) {
        const float3x3 _e20 = orthonormal_basis(n_9);
        const float _e21 = pbr_alpha2_(roughness_3);
        const float3 _e26 = pbr_sample_vndf(mul(v_5, transpose(_e20)), sqrt(_e21), u_2.yz);
        float3 h_1 = mul(_e26, _e20);
        l_5 = reflect(-(v_5), h_1);
    } else {
        const float3 _e31 = sample_cosine_hemisphere(n_9, u_2.yz);
        l_5 = _e31;
    }
    float3 _e32 = l_5;
    const float _e33 = pbr_pdf(base_4, metallic_3, roughness_3, n_9, v_5, _e32);
    if (!((_e33 > 0.0))) {
        float3 _e37 = l_5;
        const PbrSample pbrsample_1 = ConstructPbrSample(_e37, (0.0).xxx, 0.0);
        return pbrsample_1;
    }
    float3 _e42 = l_5;
    const float3 _e43 = pbr_eval(base_4, metallic_3, roughness_3, n_9, v_5, _e42);
    float3 weight_5 = (_e43 / (_e33).xxx);
    float3 _e46 = l_5;
    const PbrSample pbrsample_2 = ConstructPbrSample(_e46, weight_5, _e33);
    return pbrsample_2;
}

void path_pbr_rays(PathPbr m_5, Ray ray_28, Hit hit_9)
{
    float3 weight_2 = (float3)0;

    const float3 _e3 = path_pbr_ng(ray_28, hit_9);
    const float3 _e4 = path_pbr_n(ray_28, hit_9);
    const float3 _e6 = normalize_vec3f(ray_28.dir);
    float3 v_8 = -(_e6);
    const float _e11 = rand_next();
    const float2 _e12 = rand2_next();
    const PbrSample _e14 = pbr_sample(m_5.base_color, m_5.metallic, m_5.roughness, _e4, v_8, float3(_e11, _e12));
    if ((!((_e14.pdf > 0.0)) || !((dot(_e14.dir, _e3) > 0.0)))) {
        return;
    }
    weight_2 = _e14.weight;
    if ((ray_28.depth >= m_5.roulette_depth)) {
        float _e31 = weight_2.x;
        float _e33 = weight_2.y;
        float _e35 = weight_2.z;
        float q_5 = min(max(_e31, max(_e33, _e35)), 1.0);
        const float _e40 = rand_next();
        if (!((_e40 < q_5))) {
            return;
        }
        float3 _e43 = weight_2;
        weight_2 = (_e43 / (q_5).xxx);
    }
    const float3 _e48 = mis_bounce_dir(_e14.dir, _e14.pdf);
    float3 _e49 = weight_2;
    rt_spawn(_e48, _e49);
    return;
}

void dispatch_secondary_rays(uint type_id_6, uint offset_15, Ray ray_29, Hit hit_10)
{
    switch(type_id_6) {
        case 0u: {
            const PathDiffuse _e4 = load_PathDiffuse(offset_15);
            path_diffuse_rays(_e4, ray_29, hit_10);
            return;
        }
        case 3u: {
            const PathPbr _e5 = load_PathPbr(offset_15);
            path_pbr_rays(_e5, ray_29, hit_10);
            return;
        }
        default: {
            break;
        }
    }
    return;
}

float3 spawn_origin_at(float3 position_8, float3 normal_9, float error_1, float3 dir_6)
{
    float3 n_10 = (float3)0;

    n_10 = normal_9;
    float3 _e5 = n_10;
    if ((dot(dir_6, _e5) < 0.0)) {
        float3 _e9 = n_10;
        n_10 = -(_e9);
    }
    float3 _e11 = n_10;
    const float3 _e12 = offset_origin(position_8, _e11, error_1);
    return _e12;
}

float3 spawn_origin(Hit hit_11, float error_2, float3 dir_7)
{
    const float3 _e5 = spawn_origin_at(hit_11.position, hit_11.geometric_normal, error_2, dir_7);
    return _e5;
}

PathState path_step(PathState s_2, Candidate c_5)
{
    PathState out_ = (PathState)0;
    bool spawned = (bool)0;
    float3 dir_8 = (float3)0;
    float3 weight_3 = (float3)0;
    float3 beta = (float3)0;

    Ray ray_35 = s_2.ray;
    out_ = s_2;
    out_.live = false;
    if ((c_5.slot == NO_HIT)) {
        hit_error = 0.0;
        const float3 _e14 = miss(ray_35);
        out_.radiance = (s_2.radiance + (s_2.beta * _e14));
        PathState _e17 = out_;
        const PathState pathstate_1 = _e17;
        return pathstate_1;
    }
    GpuInstance inst_10 = ConstructGpuInstance(asfloat(instances.Load4(c_5.slot*128+0)), asfloat(instances.Load4(c_5.slot*128+16)), asfloat(instances.Load4(c_5.slot*128+32)), asfloat(instances.Load4(c_5.slot*128+48)), asfloat(instances.Load4(c_5.slot*128+64)), asfloat(instances.Load4(c_5.slot*128+80)), asuint(instances.Load(c_5.slot*128+96)), asuint(instances.Load(c_5.slot*128+100)), asuint(instances.Load(c_5.slot*128+104)), asuint(instances.Load(c_5.slot*128+108)), asuint(instances.Load(c_5.slot*128+112)), asuint(instances.Load(c_5.slot*128+116)), asuint(instances.Load(c_5.slot*128+120)), asuint(instances.Load(c_5.slot*128+124)));
    const Hit _e22 = finish_hit(ray_35, c_5);
    float error_4 = hit_error;
    spawned = false;
    dir_8 = (0.0).xxx;
    weight_3 = (0.0).xxx;
    if ((((inst_10.flags & FLAG_SECONDARY_RAYS) != 0u) && (ray_35.depth < MAX_DEPTH))) {
        spawn_count = 0u;
        dispatch_secondary_rays(inst_10.material_type, inst_10.material_offset, ray_35, _e22);
        uint _e47 = spawn_count;
        if ((min(_e47, 1u) > 0u)) {
            spawned = true;
            float3 _e56 = spawn_dirs[0u];
            dir_8 = _e56;
            float3 _e60 = spawn_weights[0u];
            weight_3 = _e60;
        }
    }
    const float3 _e68 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, ray_35, _e22, (0.0).xxx);
    out_.radiance = (s_2.radiance + (s_2.beta * _e68));
    bool _e71 = spawned;
    if (!(_e71)) {
        PathState _e73 = out_;
        const PathState pathstate_2 = _e73;
        return pathstate_2;
    }
    float3 _e75 = weight_3;
    beta = (s_2.beta * _e75);
    float _e79 = beta.x;
    float _e81 = beta.y;
    float _e83 = beta.z;
    float q_6 = max(_e79, max(_e81, _e83));
    if (!((q_6 > 0.0))) {
        PathState _e89 = out_;
        const PathState pathstate_3 = _e89;
        return pathstate_3;
    }
    if ((((ROULETTE_DEPTH > 0u) && ((ray_35.depth + 1u) >= ROULETTE_DEPTH)) && (q_6 < ROULETTE_THROUGHPUT))) {
        float survive = (q_6 / ROULETTE_THROUGHPUT);
        const float _e104 = rand_next();
        if ((_e104 >= survive)) {
            PathState _e106 = out_;
            const PathState pathstate_4 = _e106;
            return pathstate_4;
        }
        float3 _e107 = beta;
        beta = (_e107 / (survive).xxx);
    }
    float3 _e111 = beta;
    out_.beta = _e111;
    float3 _e113 = dir_8;
    const float3 _e114 = spawn_origin(_e22, error_4, _e113);
    float3 _e116 = dir_8;
    uint _e118 = F32_INF;
    out_.ray = ConstructRay(_e114, 0.0, _e116, asfloat(_e118), (ray_35.depth + 1u), RAY_SECONDARY, ray_35.medium);
    out_.live = true;
    PathState _e128 = out_;
    const PathState pathstate_5 = _e128;
    return pathstate_5;
}

float3 trace_path(Ray camera_ray)
{
    PathState s_3 = (PathState)0;

    const PathState _e1 = start_path(camera_ray);
    s_3 = _e1;
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        PathState _e3 = s_3;
        Ray _e5 = s_3.ray;
        const Candidate _e7 = intersect_scene(_e5, false);
        const PathState _e8 = path_step(_e3, _e7);
        s_3 = _e8;
        bool _e10 = s_3.live;
        if (!(_e10)) {
            float3 _e13 = s_3.radiance;
            return _e13;
        }
    }
    return ZeroValuefloat3();
}

float3 trace(Ray camera_ray_1)
{
    float3 radiance_2 = (float3)0;
    float t_3 = (float)0;

    if (!(HAS_SECONDARY_RAYS)) {
        const Candidate _e4 = intersect_scene(camera_ray_1, false);
        radiance_2 = (0.0).xxx;
        uint _e9 = F32_INF;
        t_3 = asfloat(_e9);
        if ((_e4.slot == NO_HIT)) {
            hit_error = 0.0;
            const float3 _e17 = miss(camera_ray_1);
            radiance_2 = _e17;
        } else {
            const float3 _e18 = shade_direct(camera_ray_1, _e4);
            radiance_2 = _e18;
            t_3 = _e4.t;
        }
        float _e20 = t_3;
        float3 _e21 = radiance_2;
        const float3 _e22 = through_medium(camera_ray_1, _e20, _e21);
        return _e22;
    }
    const float3 _e23 = trace_path(camera_ray_1);
    return _e23;
}

bool3 is_finite_vec3f(float3 x_4)
{
    return ((asuint(x_4) & (2147483647u).xxx) < (2139095040u).xxx);
}

float3 finite_or_zero(float3 c_6)
{
    const bool3 _e3 = is_finite_vec3f(c_6);
    return (_e3 ? c_6 : (0.0).xxx);
}

PassSum ConstructPassSum(float3 arg0, uint arg1) {
    PassSum ret = (PassSum)0;
    ret.sum = arg0;
    ret.bad = arg1;
    return ret;
}

PassSum add_sample(PassSum p_7, float3 c_7, uint s_4, uint index, uint first_pass, uint per_pass)
{
    PassSum next = (PassSum)0;

    next = p_7;
    const bool3 _e7 = is_finite_vec3f(c_7);
    if (all(_e7)) {
        float3 _e10 = next.sum;
        next.sum = (_e10 + c_7);
    } else {
        float3 _e13 = next.sum;
        const float3 _e14 = finite_or_zero(c_7);
        next.sum = (_e13 + _e14);
        uint _e17 = next.bad;
        next.bad = (_e17 + 1u);
    }
    const uint _e22 = rem_u32_((s_4 + 1u), per_pass);
    if ((_e22 != 0u)) {
        PassSum _e25 = next;
        const PassSum passsum = _e25;
        return passsum;
    }
    uint _e27 = ray_count;
    counters.InterlockedAdd(4, _e27);
    ray_count = 0u;
    const uint _e31 = div_u32_(s_4, per_pass);
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
    uint s_5 = (uint)0;

    FrameUniforms frame_6 = frame;
    TileParams tile_2 = tile;
    uint index_1 = ((pixel_5.y * tile_2.image_size.x) + pixel_5.x);
    uint per_pass_1 = frame_6.samples_per_pass;
    uint first_1 = (tile_2.frame * per_pass_1);
    uint count_2 = (per_pass_1 * max(frame_6.passes_per_dispatch, 1u));
    sums = ConstructPassSum((0.0).xxx, 0u);
    s_5 = 0u;
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e35 = s_5;
            s_5 = (_e35 + 1u);
        }
        loop_init_4 = false;
        uint _e25 = s_5;
        if ((_e25 >= count_2)) {
            break;
        }
        PassSum _e27 = sums;
        uint _e28 = s_5;
        const Ray _e30 = sample_camera_ray(pixel_5, (first_1 + _e28));
        const float3 _e31 = trace(_e30);
        uint _e32 = s_5;
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
