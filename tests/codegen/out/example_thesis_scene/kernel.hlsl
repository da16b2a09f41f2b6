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
};

struct TileParams {
    uint2 origin;
    uint2 extent;
    uint2 image_size;
    uint tile_index;
    uint frame;
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

struct GpuNode {
    float3 min_;
    uint a;
    float3 max_;
    uint b;
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

struct ConstantBackground {
    float3 color;
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
    int _end_pad_0;
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
    uint slot;
    int _pad3_0;
    int _pad3_1;
    int _pad3_2;
    float3 sum;
    int _pad4_0;
    float3 dirs[1];
    int _pad5_0;
    float3 weights[1];
    int _pad6_0;
    uint count;
    uint next;
    int _end_pad_0;
    int _end_pad_1;
};

static const uint RAY_CAMERA = 0u;
static const bool HAS_MEDIA = false;
static const uint NO_HIT = 4294967295u;
static const uint MESH_GEOMETRY = 4294967295u;
static const uint LEAF_BIT = 2147483648u;
static const bool HAS_ANY_HIT = false;
static const uint FLAG_ANY_HIT = 1u;
static const uint BLAS_STACK = 64u;
static const bool HAS_SECONDARY_RAYS = false;
static const uint TLAS_STACK = 64u;
static const bool HAS_BACKGROUND = true;
static const uint FLAG_MEDIUM = 4u;
static const uint RAY_SHADOW = 2u;
static const float INV_PI = 0.31830987;
static const uint FLAG_SECONDARY = 2u;
static const uint MAX_DEPTH = 0u;
static const uint STACK_SIZE = 1u;
static const uint MAX_SPAWN = 1u;
static const uint RAY_SECONDARY = 1u;

cbuffer frame : register(b0) { FrameUniforms frame; }
cbuffer tile : register(b1) { TileParams tile; }
static uint rng_state = (uint)0;
ByteAddressBuffer params : register(t6);
static uint F32_INF = 2139095040u;
ByteAddressBuffer instances : register(t3);
ByteAddressBuffer nodes : register(t2);
ByteAddressBuffer triangles : register(t4);
ByteAddressBuffer attributes : register(t5);
static float3 spawn_dirs[1] = (float3[1])0;
static float3 spawn_weights[1] = (float3[1])0;
static uint spawn_count = (uint)0;
RWByteAddressBuffer accum : register(u8);
RWByteAddressBuffer counters : register(u9);

uint pcg_hash(uint x)
{
    uint state = ((x * 747796405u) + 2891336453u);
    uint word = (((state >> (((state >> 28u) + 4u) & 31u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

void rng_seed(uint2 pixel, uint sample_, uint seed)
{
    uint h = (uint)0;

    const uint _e5 = pcg_hash(seed);
    const uint _e7 = pcg_hash((sample_ ^ _e5));
    const uint _e9 = pcg_hash((pixel.y ^ _e7));
    const uint _e11 = pcg_hash((pixel.x ^ _e9));
    h = _e11;
    uint _e13 = h;
    if ((_e13 == 0u)) {
        h = 1u;
    }
    uint _e17 = h;
    rng_state = _e17;
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

float rand_next()
{
    uint _e1 = rng_state;
    uint s_1 = ((_e1 * 747796405u) + 2891336453u);
    rng_state = s_1;
    uint word_1 = (((s_1 >> (((s_1 >> 28u) + 4u) & 31u)) ^ s_1) * 277803737u);
    uint r_3 = ((word_1 >> 22u) ^ word_1);
    return (float((r_3 >> 8u)) * (1.0 / 16777216.0));
}

float2 rand2_next()
{
    const float _e0 = rand_next();
    const float _e1 = rand_next();
    return float2(_e0, _e1);
}

float3 normalize_vec3f(float3 v)
{
    return ((dot(v, v) >= 1.1754944e-38) ? normalize(v) : (0.0).xxx);
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

Ray pinhole_ray(Pinhole cam, uint2 pixel_1, uint sample_1)
{
    float2 jitter = (float2)0;

    const uint2 _e2 = image_size_query();
    float2 size = float2(_e2);
    jitter = (0.5).xx;
    const uint _e7 = samples_per_pixel_query();
    if ((_e7 > 1u)) {
        const float2 _e10 = rand2_next();
        jitter = _e10;
    }
    float2 _e12 = jitter;
    float2 ndc = ((((float2(pixel_1) + _e12) / size) * (2.0).xx) - (1.0).xx);
    const float3 _e24 = normalize_vec3f((cam.look_at - cam.position));
    const float3 _e27 = normalize_vec3f(cross(_e24, cam.up));
    float3 up = cross(_e27, _e24);
    float h_1 = tan((radians(cam.fov) * 0.5));
    float aspect = (size.x / size.y);
    const float3 _e48 = normalize_vec3f(((_e24 + (_e27 * (((ndc.x * h_1) * aspect)).xxx)) - (up * ((ndc.y * h_1)).xxx)));
    uint _e52 = F32_INF;
    const Ray ray_19 = ConstructRay(cam.position, 0.0, _e48, asfloat(_e52), 0u, 0u, 0u);
    return ray_19;
}

Ray dispatch_ray_generation(uint type_id, uint offset_1, uint2 pixel_2, uint sample_2)
{
    const Pinhole _e3 = load_Pinhole(offset_1);
    const Ray _e4 = pinhole_ray(_e3, pixel_2, sample_2);
    const Ray ray_20 = _e4;
    return ray_20;
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
    const Ray ray_21 = _e25;
    return ray_21;
}

float3 safe_inverse(float3 d)
{
    float3 tiny = (1e-30).xxx;
    float3 s_2 = ((d < (0.0).xxx) ? (-1.0).xxx : (1.0).xxx);
    float3 dd = ((abs(d) < tiny) ? (s_2 * tiny) : d);
    return ((1.0).xxx / dd);
}

Triangle ConstructTriangle(float3 arg0, float3 arg1, float3 arg2) {
    Triangle ret = (Triangle)0;
    ret.v0_ = arg0;
    ret.v1_ = arg1;
    ret.v2_ = arg2;
    return ret;
}

Triangle load_triangle(uint slot)
{
    float4 v0_ = asfloat(triangles.Load4((slot * 3u)*16));
    float4 v1_ = asfloat(triangles.Load4(((slot * 3u) + 1u)*16));
    float4 v2_ = asfloat(triangles.Load4(((slot * 3u) + 2u)*16));
    const Triangle triangle_ = ConstructTriangle(v0_.xyz, v1_.xyz, v2_.xyz);
    return triangle_;
}

Intersection ConstructIntersection(float arg0, float3 arg1, float2 arg2) {
    Intersection ret = (Intersection)0;
    ret.t = arg0;
    ret.normal = arg1;
    ret.uv = arg2;
    return ret;
}

Intersection intersect_triangle(Ray ray_1, Triangle tri)
{
    uint3 _e10 = (2139095040u).xxx;
    float3 dir_2 = ((abs(ray_1.dir) < (1.1754944e-38).xxx) ? (0.0).xxx : ray_1.dir);
    float3 _e31 = abs(dir_2);
    bool _e38 = (_e31.y > _e31.x);
    uint kz = ((_e31.z > (_e38 ? _e31.y : _e31.x)) ? 2u : (_e38 ? 1u : 0u));
    uint _e45 = ((kz == 2u) ? 0u : (kz + 1u));
    uint _e49 = ((kz >= 1u) ? (kz - 1u) : (kz + 2u));
    float dz = dir_2[min(uint(kz), 2u)];
    bool _e52 = (dz < 0.0);
    uint kx = (_e52 ? _e49 : _e45);
    uint ky = (_e52 ? _e45 : _e49);
    float sx = (dir_2[min(uint(kx), 2u)] / dz);
    float sy = (dir_2[min(uint(ky), 2u)] / dz);
    float sz = (1.0 / dz);
    float3 _e62 = (tri.v0_ - ray_1.origin);
    float _e68 = (_e62[min(uint(kx), 2u)] - (sx * _e62[min(uint(kz), 2u)]));
    float _e69 = (_e62[min(uint(ky), 2u)] - (sy * _e62[min(uint(kz), 2u)]));
    float3 _e71 = (tri.v1_ - ray_1.origin);
    float _e77 = (_e71[min(uint(kx), 2u)] - (sx * _e71[min(uint(kz), 2u)]));
    float _e78 = (_e71[min(uint(ky), 2u)] - (sy * _e71[min(uint(kz), 2u)]));
    float3 _e80 = (tri.v2_ - ray_1.origin);
    float _e86 = (_e80[min(uint(kx), 2u)] - (sx * _e80[min(uint(kz), 2u)]));
    float _e87 = (_e80[min(uint(ky), 2u)] - (sy * _e80[min(uint(kz), 2u)]));
    float u = ((_e86 * _e78) - (_e87 * _e77));
    float v_1 = ((_e68 * _e87) - (_e69 * _e86));
    float w = ((_e77 * _e69) - (_e78 * _e68));
    float det = ((u + v_1) + w);
    float _e112 = (1.0 / det);
    float t_2 = ((((u * (sz * _e62[min(uint(kz), 2u)])) + (v_1 * (sz * _e71[min(uint(kz), 2u)]))) + (w * (sz * _e80[min(uint(kz), 2u)]))) * _e112);
    bool hit_6 = (((((all(((asuint(ray_1.origin) & (2147483647u).xxx) < _e10)) && all(((asuint(ray_1.dir) & (2147483647u).xxx) < _e10))) && (dz != 0.0)) && !(((((u < 0.0) || (v_1 < 0.0)) || (w < 0.0)) && (((u > 0.0) || (v_1 > 0.0)) || (w > 0.0))))) && !((det == 0.0))) && ((t_2 >= ray_1.tmin) && (t_2 <= ray_1.tmax)));
    const float3 _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    uint _e137 = F32_INF;
    const Intersection intersection = ConstructIntersection((hit_6 ? t_2 : asfloat(_e137)), (hit_6 ? _e132 : float3(0.0, 0.0, 1.0)), (hit_6 ? float2((v_1 * _e112), (w * _e112)) : (0.0).xx));
    return intersection;
}

float3 point_to_world(GpuInstance inst_1, float3 p)
{
    float4 q = float4(p, 1.0);
    return float3(dot(inst_1.object_to_world_0_, q), dot(inst_1.object_to_world_1_, q), dot(inst_1.object_to_world_2_, q));
}

float3 decode_octahedral(uint bits)
{
    float3 n = (float3)0;

    float2 e = (float2(int2(bits << 16, bits) >> 16) / 32767.0);
    n = float3(e.x, e.y, ((1.0 - abs(e.x)) - abs(e.y)));
    float _e14 = n.z;
    if ((_e14 < 0.0)) {
        float3 _e21 = n;
        float2 s_3 = ((_e21.xy >= (0.0).xx) ? (1.0).xx : (-1.0).xx);
        float3 _e29 = n;
        float2 xy = (((1.0).xx - abs(_e29.yx)) * s_3);
        float _e37 = n.z;
        n = float3(xy.x, xy.y, _e37);
    }
    float3 _e39 = n;
    const float3 _e40 = normalize_vec3f(_e39);
    return _e40;
}

float3 normal_to_world(GpuInstance inst_2, float3 n_1)
{
    float3 w_1 = (((inst_2.world_to_object_0_.xyz * (n_1.x).xxx) + (inst_2.world_to_object_1_.xyz * (n_1.y).xxx)) + (inst_2.world_to_object_2_.xyz * (n_1.z).xxx));
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

Hit finish_hit(Ray ray_2, Candidate c)
{
    Hit hit = (Hit)0;
    float3 n_geo = (float3)0;
    float3 n_shade = (float3)0;

    GpuInstance inst_5 = ConstructGpuInstance(asfloat(instances.Load4(c.slot*128+0)), asfloat(instances.Load4(c.slot*128+16)), asfloat(instances.Load4(c.slot*128+32)), asfloat(instances.Load4(c.slot*128+48)), asfloat(instances.Load4(c.slot*128+64)), asfloat(instances.Load4(c.slot*128+80)), asuint(instances.Load(c.slot*128+96)), asuint(instances.Load(c.slot*128+100)), asuint(instances.Load(c.slot*128+104)), asuint(instances.Load(c.slot*128+108)), asuint(instances.Load(c.slot*128+112)), asuint(instances.Load(c.slot*128+116)), asuint(instances.Load(c.slot*128+120)), asuint(instances.Load(c.slot*128+124)));
    hit = ConstructHit((ray_2.origin + (ray_2.dir * (c.t).xxx)), c.t, float3(0.0, 1.0, 0.0), float3(0.0, 1.0, 0.0), c.uv, true, inst_5.object, c.primitive);
    n_geo = c.normal;
    n_shade = c.normal;
    if ((inst_5.geometry_type == MESH_GEOMETRY)) {
        const Triangle _e35 = load_triangle(c.primitive);
        float2 b_1 = c.uv;
        float w_2 = ((1.0 - b_1.x) - b_1.y);
        const float3 _e56 = point_to_world(inst_5, (((_e35.v0_ * (w_2).xxx) + (_e35.v1_ * (b_1.x).xxx)) + (_e35.v2_ * (b_1.y).xxx)));
        hit.position = _e56;
        n_geo = cross((_e35.v1_ - _e35.v0_), (_e35.v2_ - _e35.v0_));
        uint4 a0_ = asuint(attributes.Load4((c.primitive * 2u)*16));
        uint4 a1_ = asuint(attributes.Load4(((c.primitive * 2u) + 1u)*16));
        const float3 _e79 = decode_octahedral(a0_.x);
        const float3 _e83 = decode_octahedral(a0_.y);
        const float3 _e89 = decode_octahedral(a0_.z);
        n_shade = (((_e79 * (w_2).xxx) + (_e83 * (b_1.x).xxx)) + (_e89 * (b_1.y).xxx));
        float3 _e94 = n_shade;
        float3 _e95 = n_shade;
        if ((dot(_e94, _e95) < 1e-12)) {
            float3 _e99 = n_geo;
            n_shade = _e99;
        }
        uint _e100 = a0_.w;
        float2 uv0_ = float2(f16tof32(_e100), f16tof32((_e100) >> 16));
        uint _e102 = a1_.x;
        float2 uv1_ = float2(f16tof32(_e102), f16tof32((_e102) >> 16));
        uint _e104 = a1_.y;
        float2 uv2_ = float2(f16tof32(_e104), f16tof32((_e104) >> 16));
        hit.uv = (((uv0_ * (w_2).xx) + (uv1_ * (b_1.x).xx)) + (uv2_ * (b_1.y).xx));
        float4 _e123 = asfloat(triangles.Load4((c.primitive * 3u)*16));
        hit.primitive = asuint(_e123.w);
    }
    float3 _e127 = n_geo;
    const float3 _e128 = normal_to_world(inst_5, _e127);
    hit.geometric_normal = _e128;
    float3 _e130 = n_shade;
    const float3 _e131 = normal_to_world(inst_5, _e130);
    hit.normal = _e131;
    float3 _e135 = hit.geometric_normal;
    hit.front_face = (dot(ray_2.dir, _e135) < 0.0);
    Hit _e139 = hit;
    const Hit hit_7 = _e139;
    return hit_7;
}

bool ZeroValuebool() {
    return (bool)0;
}

bool dispatch_any_hit(uint type_id_1, uint offset_2, Ray ray_3, Hit hit_1)
{
    return ZeroValuebool();
}

bool accept(GpuInstance inst_3, Ray ray_4, Candidate c_1)
{
    if (!(HAS_ANY_HIT)) {
        return true;
    }
    if (((inst_3.flags & FLAG_ANY_HIT) == 0u)) {
        return true;
    }
    const Hit _e12 = finish_hit(ray_4, c_1);
    const bool _e15 = dispatch_any_hit(inst_3.material_type, inst_3.material_offset, ray_4, _e12);
    return _e15;
}

float slab(float3 lo, float3 hi, float3 origin, float3 inv_dir, float tmin, float tmax_1)
{
    float3 t0_ = ((lo - origin) * inv_dir);
    float3 t1_ = ((hi - origin) * inv_dir);
    float3 near_2 = min(t0_, t1_);
    float3 far_2 = max(t0_, t1_);
    float enter = max(max(near_2.x, near_2.y), max(near_2.z, tmin));
    float exit = min(min(far_2.x, far_2.y), min(far_2.z, tmax_1));
    if ((enter <= exit)) {
        return enter;
    }
    uint _e26 = F32_INF;
    return asfloat(_e26);
}

typedef uint ret_ZeroValuearray64_uint_[64];
ret_ZeroValuearray64_uint_ ZeroValuearray64_uint_() {
    return (uint[64])0;
}

GpuNode ConstructGpuNode(float3 arg0, uint arg1, float3 arg2, uint arg3) {
    GpuNode ret = (GpuNode)0;
    ret.min_ = arg0;
    ret.a = arg1;
    ret.max_ = arg2;
    ret.b = arg3;
    return ret;
}

Candidate intersect_mesh(GpuInstance inst_4, uint slot_1, Ray world_ray, Ray ray_5, Candidate best_in, bool shadow)
{
    Candidate best = (Candidate)0;
    uint stack[64] = (uint[64])0;
    uint sp = (uint)0;
    uint node = (uint)0;
    uint k = (uint)0;
    Ray r_1 = (Ray)0;
    uint near = (uint)0;
    uint far = (uint)0;

    best = best_in;
    const float3 _e8 = safe_inverse(ray_5.dir);
    uint base = inst_4.blas_root;
    stack = ZeroValuearray64_uint_();
    sp = 0u;
    node = base;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        uint _e15 = node;
        GpuNode n_5 = ConstructGpuNode(asfloat(nodes.Load3(_e15*32+0)), asuint(nodes.Load(_e15*32+12)), asfloat(nodes.Load3(_e15*32+16)), asuint(nodes.Load(_e15*32+28)));
        if (((n_5.b & LEAF_BIT) != 0u)) {
            uint count = (n_5.b & ~(LEAF_BIT));
            k = 0u;
            uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
            bool loop_init = true;
            while(true) {
                if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init) {
                    uint _e65 = k;
                    k = (_e65 + 1u);
                }
                loop_init = false;
                uint _e30 = k;
                if ((_e30 >= count)) {
                    break;
                }
                uint _e35 = k;
                uint prim = ((inst_4.triangle_offset + n_5.a) + _e35);
                r_1 = ray_5;
                float _e40 = best.t;
                r_1.tmax = _e40;
                Ray _e41 = r_1;
                const Triangle _e42 = load_triangle(prim);
                const Intersection _e43 = intersect_triangle(_e41, _e42);
                float _e46 = r_1.tmin;
                float _e50 = r_1.tmax;
                uint _e55 = F32_INF;
                if ((((_e43.t >= _e46) && (_e43.t <= _e50)) && (_e43.t < asfloat(_e55)))) {
                    Candidate c_4 = ConstructCandidate(_e43.t, slot_1, prim, _e43.uv, _e43.normal);
                    const bool _e63 = accept(inst_4, world_ray, c_4);
                    if (_e63) {
                        best = c_4;
                        if (shadow) {
                            Candidate _e64 = best;
                            const Candidate candidate_1 = _e64;
                            return candidate_1;
                        }
                    }
                }
            }
        } else {
            uint left = (base + n_5.a);
            uint right = (left + 1u);
            GpuNode l_1 = ConstructGpuNode(asfloat(nodes.Load3(left*32+0)), asuint(nodes.Load(left*32+12)), asfloat(nodes.Load3(left*32+16)), asuint(nodes.Load(left*32+28)));
            GpuNode rr = ConstructGpuNode(asfloat(nodes.Load3(right*32+0)), asuint(nodes.Load(right*32+12)), asfloat(nodes.Load3(right*32+16)), asuint(nodes.Load(right*32+28)));
            float _e83 = best.t;
            const float _e84 = slab(l_1.min_, l_1.max_, ray_5.origin, _e8, ray_5.tmin, _e83);
            float _e90 = best.t;
            const float _e91 = slab(rr.min_, rr.max_, ray_5.origin, _e8, ray_5.tmin, _e90);
            uint _e93 = F32_INF;
            uint _e97 = F32_INF;
            if (((_e84 < asfloat(_e93)) && (_e91 < asfloat(_e97)))) {
                near = left;
                far = right;
                if ((_e91 < _e84)) {
                    near = right;
                    far = left;
                }
                uint _e104 = sp;
                if ((_e104 < BLAS_STACK)) {
                    uint _e107 = sp;
                    uint _e111 = far;
                    stack[min(uint(min(_e107, 63u)), 63u)] = _e111;
                    uint _e112 = sp;
                    sp = (_e112 + 1u);
                }
                uint _e115 = near;
                node = _e115;
                continue;
            }
            uint _e117 = F32_INF;
            if ((_e84 < asfloat(_e117))) {
                node = left;
                continue;
            }
            uint _e121 = F32_INF;
            if ((_e91 < asfloat(_e121))) {
                node = right;
                continue;
            }
        }
        uint _e124 = sp;
        if ((_e124 == 0u)) {
            break;
        }
        uint _e127 = sp;
        sp = (_e127 - 1u);
        uint _e130 = sp;
        uint _e134 = stack[min(uint(min(_e130, 63u)), 63u)];
        node = _e134;
    }
    Candidate _e135 = best;
    const Candidate candidate_2 = _e135;
    return candidate_2;
}

Candidate intersect_object(uint slot_2, Ray ray_6, Candidate best_1, bool shadow_1)
{
    Ray r_2 = (Ray)0;

    GpuInstance inst_6 = ConstructGpuInstance(asfloat(instances.Load4(slot_2*128+0)), asfloat(instances.Load4(slot_2*128+16)), asfloat(instances.Load4(slot_2*128+32)), asfloat(instances.Load4(slot_2*128+48)), asfloat(instances.Load4(slot_2*128+64)), asfloat(instances.Load4(slot_2*128+80)), asuint(instances.Load(slot_2*128+96)), asuint(instances.Load(slot_2*128+100)), asuint(instances.Load(slot_2*128+104)), asuint(instances.Load(slot_2*128+108)), asuint(instances.Load(slot_2*128+112)), asuint(instances.Load(slot_2*128+116)), asuint(instances.Load(slot_2*128+120)), asuint(instances.Load(slot_2*128+124)));
    const Ray _e7 = to_object(inst_6, ray_6);
    r_2 = _e7;
    r_2.tmax = best_1.t;
    if ((inst_6.geometry_type == MESH_GEOMETRY)) {
        Ray _e14 = r_2;
        const Candidate _e15 = intersect_mesh(inst_6, slot_2, ray_6, _e14, best_1, shadow_1);
        const Candidate candidate_3 = _e15;
        return candidate_3;
    }
    const Candidate candidate_4 = best_1;
    return candidate_4;
}

uint medium_at(float3 p_1)
{
    uint i = (uint)0;

    if (!(HAS_MEDIA)) {
        return 0u;
    }
    FrameUniforms frame_1 = frame;
    const float3 _e11 = normalize_vec3f(float3(0.5773, 0.5774, 0.5775));
    uint _e13 = F32_INF;
    Ray probe = ConstructRay(p_1, 0.0, _e11, asfloat(_e13), 0u, 0u, 0u);
    uint end = frame_1.medium_count;
    i = 0u;
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e44 = i;
            i = (_e44 + 1u);
        }
        loop_init_1 = false;
        uint _e22 = i;
        if ((_e22 >= end)) {
            break;
        }
        uint _e25 = i;
        uint slot_3 = asuint(params.Load((frame_1.medium_table + _e25)*4));
        uint _e31 = F32_INF;
        const Candidate _e33 = no_candidate(asfloat(_e31));
        const Candidate _e35 = intersect_object(slot_3, probe, _e33, false);
        if ((_e35.slot != NO_HIT)) {
            const Hit _e39 = finish_hit(probe, _e35);
            if (!(_e39.front_face)) {
                return (slot_3 + 1u);
            }
        }
    }
    return 0u;
}

Candidate intersect_scene(Ray ray_7, bool shadow_2)
{
    Candidate best_2 = (Candidate)0;
    uint stack_1[64] = (uint[64])0;
    uint sp_1 = (uint)0;
    uint node_1 = (uint)0;
    uint k_1 = (uint)0;
    uint near_1 = (uint)0;
    uint far_1 = (uint)0;

    const Candidate _e3 = no_candidate(ray_7.tmax);
    best_2 = _e3;
    FrameUniforms frame_2 = frame;
    if ((frame_2.instance_count == 0u)) {
        Candidate _e10 = best_2;
        const Candidate candidate_5 = _e10;
        return candidate_5;
    }
    const float3 _e12 = safe_inverse(ray_7.dir);
    stack_1 = ZeroValuearray64_uint_();
    sp_1 = 0u;
    node_1 = frame_2.tlas_root;
    uint _e19 = node_1;
    GpuNode root = ConstructGpuNode(asfloat(nodes.Load3(_e19*32+0)), asuint(nodes.Load(_e19*32+12)), asfloat(nodes.Load3(_e19*32+16)), asuint(nodes.Load(_e19*32+28)));
    float _e28 = best_2.t;
    const float _e29 = slab(root.min_, root.max_, ray_7.origin, _e12, ray_7.tmin, _e28);
    uint _e31 = F32_INF;
    if ((_e29 == asfloat(_e31))) {
        Candidate _e34 = best_2;
        const Candidate candidate_6 = _e34;
        return candidate_6;
    }
    uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
        loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
        uint _e35 = node_1;
        GpuNode n_6 = ConstructGpuNode(asfloat(nodes.Load3(_e35*32+0)), asuint(nodes.Load(_e35*32+12)), asfloat(nodes.Load3(_e35*32+16)), asuint(nodes.Load(_e35*32+28)));
        if (((n_6.b & LEAF_BIT) != 0u)) {
            uint count_1 = (n_6.b & ~(LEAF_BIT));
            k_1 = 0u;
            uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
                loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e63 = k_1;
                    k_1 = (_e63 + 1u);
                }
                loop_init_2 = false;
                uint _e50 = k_1;
                if ((_e50 >= count_1)) {
                    break;
                }
                uint _e53 = k_1;
                Candidate _e55 = best_2;
                const Candidate _e56 = intersect_object((n_6.a + _e53), ray_7, _e55, shadow_2);
                best_2 = _e56;
                uint _e58 = best_2.slot;
                if ((shadow_2 && (_e58 != NO_HIT))) {
                    Candidate _e62 = best_2;
                    const Candidate candidate_7 = _e62;
                    return candidate_7;
                }
            }
        } else {
            uint left_1 = (frame_2.tlas_root + n_6.a);
            uint right_1 = (left_1 + 1u);
            GpuNode l_2 = ConstructGpuNode(asfloat(nodes.Load3(left_1*32+0)), asuint(nodes.Load(left_1*32+12)), asfloat(nodes.Load3(left_1*32+16)), asuint(nodes.Load(left_1*32+28)));
            GpuNode rr_1 = ConstructGpuNode(asfloat(nodes.Load3(right_1*32+0)), asuint(nodes.Load(right_1*32+12)), asfloat(nodes.Load3(right_1*32+16)), asuint(nodes.Load(right_1*32+28)));
            float _e82 = best_2.t;
            const float _e83 = slab(l_2.min_, l_2.max_, ray_7.origin, _e12, ray_7.tmin, _e82);
            float _e89 = best_2.t;
            const float _e90 = slab(rr_1.min_, rr_1.max_, ray_7.origin, _e12, ray_7.tmin, _e89);
            uint _e92 = F32_INF;
            uint _e96 = F32_INF;
            if (((_e83 < asfloat(_e92)) && (_e90 < asfloat(_e96)))) {
                near_1 = left_1;
                far_1 = right_1;
                if ((_e90 < _e83)) {
                    near_1 = right_1;
                    far_1 = left_1;
                }
                uint _e103 = sp_1;
                if ((_e103 < TLAS_STACK)) {
                    uint _e106 = sp_1;
                    uint _e110 = far_1;
                    stack_1[min(uint(min(_e106, 63u)), 63u)] = _e110;
                    uint _e111 = sp_1;
                    sp_1 = (_e111 + 1u);
                }
                uint _e114 = near_1;
                node_1 = _e114;
                continue;
            }
            uint _e116 = F32_INF;
            if ((_e83 < asfloat(_e116))) {
                node_1 = left_1;
                continue;
            }
            uint _e120 = F32_INF;
            if ((_e90 < asfloat(_e120))) {
                node_1 = right_1;
                continue;
            }
        }
        uint _e123 = sp_1;
        if ((_e123 == 0u)) {
            break;
        }
        uint _e126 = sp_1;
        sp_1 = (_e126 - 1u);
        uint _e129 = sp_1;
        uint _e133 = stack_1[min(uint(min(_e129, 63u)), 63u)];
        node_1 = _e133;
    }
    Candidate _e134 = best_2;
    const Candidate candidate_8 = _e134;
    return candidate_8;
}

ConstantBackground ConstructConstantBackground(float3 arg0) {
    ConstantBackground ret = (ConstantBackground)0;
    ret.color = arg0;
    return ret;
}

ConstantBackground load_ConstantBackground(uint offset_3)
{
    uint _e5 = asuint(params.Load((offset_3 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_3 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_3 + 2u)*4));
    const ConstantBackground constantbackground = ConstructConstantBackground(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)));
    return constantbackground;
}

float3 constant_background(ConstantBackground b, Ray ray_8)
{
    return b.color;
}

float3 dispatch_miss(uint type_id_2, uint offset_4, Ray ray_9)
{
    const ConstantBackground _e2 = load_ConstantBackground(offset_4);
    const float3 _e3 = constant_background(_e2, ray_9);
    return _e3;
}

float3 miss(Ray ray_10)
{
    if (!(HAS_BACKGROUND)) {
        return (0.0).xxx;
    }
    FrameUniforms frame_3 = frame;
    const float3 _e9 = dispatch_miss(frame_3.background_type, frame_3.background_offset, ray_10);
    return _e9;
}

float3 ZeroValuefloat3() {
    return (float3)0;
}

float3 dispatch_medium(uint type_id_3, uint offset_5, Ray ray_11, float t, float3 radiance)
{
    return ZeroValuefloat3();
}

float3 through_medium(Ray ray_12, float t_1, float3 radiance_1)
{
    if (!(HAS_MEDIA)) {
        return radiance_1;
    }
    if ((ray_12.medium == 0u)) {
        return radiance_1;
    }
    GpuInstance inst_7 = ConstructGpuInstance(asfloat(instances.Load4((ray_12.medium - 1u)*128+0)), asfloat(instances.Load4((ray_12.medium - 1u)*128+16)), asfloat(instances.Load4((ray_12.medium - 1u)*128+32)), asfloat(instances.Load4((ray_12.medium - 1u)*128+48)), asfloat(instances.Load4((ray_12.medium - 1u)*128+64)), asfloat(instances.Load4((ray_12.medium - 1u)*128+80)), asuint(instances.Load((ray_12.medium - 1u)*128+96)), asuint(instances.Load((ray_12.medium - 1u)*128+100)), asuint(instances.Load((ray_12.medium - 1u)*128+104)), asuint(instances.Load((ray_12.medium - 1u)*128+108)), asuint(instances.Load((ray_12.medium - 1u)*128+112)), asuint(instances.Load((ray_12.medium - 1u)*128+116)), asuint(instances.Load((ray_12.medium - 1u)*128+120)), asuint(instances.Load((ray_12.medium - 1u)*128+124)));
    if (((inst_7.flags & FLAG_MEDIUM) == 0u)) {
        return radiance_1;
    }
    const float3 _e21 = dispatch_medium(inst_7.material_type, inst_7.material_offset, ray_12, t_1, radiance_1);
    return _e21;
}

Lambert ConstructLambert(float3 arg0) {
    Lambert ret = (Lambert)0;
    ret.albedo = arg0;
    return ret;
}

Lambert load_Lambert(uint offset_6)
{
    uint _e5 = asuint(params.Load((offset_6 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_6 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_6 + 2u)*4));
    const Lambert lambert = ConstructLambert(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)));
    return lambert;
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

PointLight load_PointLight(uint offset_7)
{
    uint _e5 = asuint(params.Load((offset_7 + 0u)*4));
    uint _e11 = asuint(params.Load((offset_7 + 1u)*4));
    uint _e17 = asuint(params.Load((offset_7 + 2u)*4));
    uint _e24 = asuint(params.Load((offset_7 + 4u)*4));
    uint _e30 = asuint(params.Load((offset_7 + 5u)*4));
    uint _e36 = asuint(params.Load((offset_7 + 6u)*4));
    uint _e43 = asuint(params.Load((offset_7 + 7u)*4));
    uint _e49 = asuint(params.Load((offset_7 + 8u)*4));
    uint _e55 = asuint(params.Load((offset_7 + 9u)*4));
    const PointLight pointlight = ConstructPointLight(float3(asfloat(_e5), asfloat(_e11), asfloat(_e17)), float3(asfloat(_e24), asfloat(_e30), asfloat(_e36)), asfloat(_e43), asfloat(_e49), asfloat(_e55));
    return pointlight;
}

int3 naga_f2i32(float3 value) {
    return int3(clamp(value, -2147483600.0, 2147483500.0));
}

int3 vec3i_from_vec3f(float3 x_1)
{
    return (((asuint(x_1) & (2147483647u).xxx) > (2139095040u).xxx) ? (int(0)).xxx : naga_f2i32(min(max(x_1, (-2147483600.0).xxx), (2147483500.0).xxx)));
}

int naga_neg(int val) {
    return asint(-asuint(val));
}

float3 offset_origin(float3 p_2, float3 n_2)
{
    const int3 _e5 = vec3i_from_vec3f((n_2 * (256.0).xxx));
    float3 pi = float3(asfloat(asint(asuint(asint(p_2.x)) + asuint(((p_2.x < 0.0) ? naga_neg(_e5.x) : _e5.x)))), asfloat(asint(asuint(asint(p_2.y)) + asuint(((p_2.y < 0.0) ? naga_neg(_e5.y) : _e5.y)))), asfloat(asint(asuint(asint(p_2.z)) + asuint(((p_2.z < 0.0) ? naga_neg(_e5.z) : _e5.z)))));
    bool3 small = (abs(p_2) < ((1.0 / 32.0)).xxx);
    return (small ? (p_2 + (n_2 * ((1.0 / 65536.0)).xxx)) : pi);
}

float shadow_query(float3 position, float3 normal, float3 dir, float dist)
{
    float3 n_3 = (float3)0;

    n_3 = normal;
    float3 _e5 = n_3;
    if ((dot(dir, _e5) < 0.0)) {
        float3 _e9 = n_3;
        n_3 = -(_e9);
    }
    float3 _e11 = n_3;
    const float3 _e12 = offset_origin(position, _e11);
    Ray ray_22 = ConstructRay(_e12, 0.0, dir, (dist * (1.0 - 1e-5)), 0u, RAY_SHADOW, 0u);
    const Candidate _e23 = intersect_scene(ray_22, true);
    return ((_e23.slot != NO_HIT) ? 0.0 : 1.0);
}

LightSample ConstructLightSample(float3 arg0, float arg1, float3 arg2) {
    LightSample ret = (LightSample)0;
    ret.dir = arg0;
    ret.dist = arg1;
    ret.radiance = arg2;
    return ret;
}

LightSample point_light(PointLight l, float3 position_1, float3 normal_1)
{
    float strength = (float)0;

    float3 to_light = (l.position - position_1);
    float dist_1 = length(to_light);
    float3 dir_3 = (to_light / (max(dist_1, 1e-20)).xxx);
    strength = (l.intensity / max((dist_1 * dist_1), 1e-20));
    if ((l.range > 0.0)) {
        float _e19 = strength;
        strength = (_e19 * (1.0 - smoothstep(l.inner_range, l.range, dist_1)));
    }
    const float _e26 = shadow_query(position_1, normal_1, dir_3, dist_1);
    float _e28 = strength;
    const LightSample lightsample = ConstructLightSample(dir_3, dist_1, ((l.color * (_e28).xxx) * (_e26).xxx));
    return lightsample;
}

LightSample dispatch_light(uint type_id_4, uint offset_8, float3 position_2, float3 normal_2)
{
    const PointLight _e3 = load_PointLight(offset_8);
    const LightSample _e4 = point_light(_e3, position_2, normal_2);
    const LightSample lightsample_1 = _e4;
    return lightsample_1;
}

LightSample sample_light_query(uint i_1, float3 position_3, float3 normal_3)
{
    FrameUniforms frame_4 = frame;
    if ((i_1 >= frame_4.light_count)) {
        const LightSample lightsample_2 = ConstructLightSample(float3(0.0, 1.0, 0.0), 0.0, (0.0).xxx);
        return lightsample_2;
    }
    uint entry = (frame_4.light_table + (i_1 * 2u));
    uint _e21 = asuint(params.Load(entry*4));
    uint _e26 = asuint(params.Load((entry + 1u)*4));
    const LightSample _e27 = dispatch_light(_e21, _e26, position_3, normal_3);
    const LightSample lightsample_3 = _e27;
    return lightsample_3;
}

float3 lambert_shade(Lambert m, Ray ray_13, Hit hit_2)
{
    float3 color = (float3)0;
    uint i_2 = (uint)0;

    float3 n_7 = faceforward(hit_2.normal, ray_13.dir, hit_2.normal);
    color = (0.0).xxx;
    const uint _e11 = light_count_query();
    i_2 = 0u;
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e33 = i_2;
            i_2 = (_e33 + 1u);
        }
        loop_init_3 = false;
        uint _e13 = i_2;
        if ((_e13 >= _e11)) {
            break;
        }
        uint _e15 = i_2;
        const LightSample _e18 = sample_light_query(_e15, hit_2.position, hit_2.geometric_normal);
        float3 _e19 = color;
        color = (_e19 + (((m.albedo * (INV_PI).xxx) * _e18.radiance) * (max(dot(n_7, _e18.dir), 0.0)).xxx));
    }
    float3 _e36 = color;
    return _e36;
}

float3 dispatch_closest_hit(uint type_id_5, uint offset_9, Ray ray_14, Hit hit_3, float3 secondary)
{
    const Lambert _e3 = load_Lambert(offset_9);
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

void dispatch_secondary_rays(uint type_id_6, uint offset_10, Ray ray_16, Hit hit_4)
{
    return;
}

float3 spawn_origin(Hit hit_5, float3 dir_1)
{
    float3 n_4 = (float3)0;

    n_4 = hit_5.geometric_normal;
    float3 _e4 = n_4;
    if ((dot(dir_1, _e4) < 0.0)) {
        float3 _e8 = n_4;
        n_4 = -(_e8);
    }
    float3 _e11 = n_4;
    const float3 _e12 = offset_origin(hit_5.position, _e11);
    return _e12;
}

Frame ConstructFrame(Ray arg0, Hit arg1, uint arg2, float3 arg3, float3 arg4[1], float3 arg5[1], uint arg6, uint arg7) {
    Frame ret = (Frame)0;
    ret.ray = arg0;
    ret.hit = arg1;
    ret.slot = arg2;
    ret.sum = arg3;
    ret.dirs = arg4;
    ret.weights = arg5;
    ret.count = arg6;
    ret.next = arg7;
    return ret;
}

typedef Frame ret_ZeroValuearray1_Frame_[1];
ret_ZeroValuearray1_Frame_ ZeroValuearray1_Frame_() {
    return (Frame[1])0;
}

typedef float3 ret_ZeroValuearray1_float3_[1];
ret_ZeroValuearray1_float3_ ZeroValuearray1_float3_() {
    return (float3[1])0;
}

float3 trace(Ray camera_ray)
{
    Frame stack_2[1] = (Frame[1])0;
    uint depth = (uint)0;
    Ray ray_17 = (Ray)0;
    float3 value = (float3)0;
    bool have_value = (bool)0;
    bool pushed = (bool)0;
    Frame f = (Frame)0;
    uint i_3 = (uint)0;
    uint medium = (uint)0;

    if (!(HAS_SECONDARY_RAYS)) {
        const Candidate _e4 = intersect_scene(camera_ray, false);
        if ((_e4.slot == NO_HIT)) {
            uint _e9 = F32_INF;
            const float3 _e11 = miss(camera_ray);
            const float3 _e12 = through_medium(camera_ray, asfloat(_e9), _e11);
            return _e12;
        }
        const float3 _e14 = shade_direct(camera_ray, _e4);
        const float3 _e15 = through_medium(camera_ray, _e4.t, _e14);
        return _e15;
    }
    stack_2 = ZeroValuearray1_Frame_();
    depth = 0u;
    ray_17 = camera_ray;
    value = (0.0).xxx;
    have_value = false;
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        bool _e26 = have_value;
        if (!(_e26)) {
            Ray _e28 = ray_17;
            const Candidate _e30 = intersect_scene(_e28, false);
            if ((_e30.slot == NO_HIT)) {
                Ray _e34 = ray_17;
                uint _e36 = F32_INF;
                Ray _e38 = ray_17;
                const float3 _e39 = miss(_e38);
                const float3 _e40 = through_medium(_e34, asfloat(_e36), _e39);
                value = _e40;
                have_value = true;
            } else {
                GpuInstance inst_9 = ConstructGpuInstance(asfloat(instances.Load4(_e30.slot*128+0)), asfloat(instances.Load4(_e30.slot*128+16)), asfloat(instances.Load4(_e30.slot*128+32)), asfloat(instances.Load4(_e30.slot*128+48)), asfloat(instances.Load4(_e30.slot*128+64)), asfloat(instances.Load4(_e30.slot*128+80)), asuint(instances.Load(_e30.slot*128+96)), asuint(instances.Load(_e30.slot*128+100)), asuint(instances.Load(_e30.slot*128+104)), asuint(instances.Load(_e30.slot*128+108)), asuint(instances.Load(_e30.slot*128+112)), asuint(instances.Load(_e30.slot*128+116)), asuint(instances.Load(_e30.slot*128+120)), asuint(instances.Load(_e30.slot*128+124)));
                Ray _e46 = ray_17;
                const Hit _e47 = finish_hit(_e46, _e30);
                pushed = false;
                uint _e56 = ray_17.depth;
                uint _e60 = depth;
                if (((((inst_9.flags & FLAG_SECONDARY) != 0u) && (_e56 < MAX_DEPTH)) && (_e60 < STACK_SIZE))) {
                    spawn_count = 0u;
                    Ray _e68 = ray_17;
                    dispatch_secondary_rays(inst_9.material_type, inst_9.material_offset, _e68, _e47);
                    uint _e70 = spawn_count;
                    uint n_8 = min(min(_e70, 1u), MAX_SPAWN);
                    if ((n_8 > 0u)) {
                        Ray _e77 = ray_17;
                        f = ConstructFrame(_e77, _e47, _e30.slot, (0.0).xxx, ZeroValuearray1_float3_(), ZeroValuearray1_float3_(), n_8, 0u);
                        i_3 = 0u;
                        uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
                        bool loop_init_4 = true;
                        while(true) {
                            if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                            loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                            if (!loop_init_4) {
                                uint _e108 = i_3;
                                i_3 = (_e108 + 1u);
                            }
                            loop_init_4 = false;
                            uint _e88 = i_3;
                            if ((_e88 >= n_8)) {
                                break;
                            }
                            uint _e91 = i_3;
                            uint _e95 = i_3;
                            float3 _e98 = spawn_dirs[min(uint(_e95), 0u)];
                            f.dirs[min(uint(min(_e91, 0u)), 0u)] = _e98;
                            uint _e100 = i_3;
                            uint _e104 = i_3;
                            float3 _e107 = spawn_weights[min(uint(_e104), 0u)];
                            f.weights[min(uint(min(_e100, 0u)), 0u)] = _e107;
                        }
                        uint _e111 = depth;
                        Frame _e115 = f;
                        stack_2[min(uint(min(_e111, 0u)), 0u)] = _e115;
                        uint _e116 = depth;
                        depth = (_e116 + 1u);
                        pushed = true;
                    }
                }
                bool _e120 = pushed;
                if (!(_e120)) {
                    Ray _e124 = ray_17;
                    const float3 _e127 = dispatch_closest_hit(inst_9.material_type, inst_9.material_offset, _e124, _e47, (0.0).xxx);
                    Ray _e128 = ray_17;
                    const float3 _e130 = through_medium(_e128, _e30.t, _e127);
                    value = _e130;
                    have_value = true;
                }
            }
        }
        bool _e132 = have_value;
        if (_e132) {
            uint _e133 = depth;
            if ((_e133 == 0u)) {
                float3 _e136 = value;
                return _e136;
            }
            uint _e137 = depth;
            uint top = (_e137 - 1u);
            uint _e144 = stack_2[min(uint(min(top, 0u)), 0u)].next;
            uint child = (_e144 - 1u);
            float3 _e151 = stack_2[min(uint(min(top, 0u)), 0u)].sum;
            float3 _e159 = stack_2[min(uint(min(top, 0u)), 0u)].weights[min(uint(min(child, 0u)), 0u)];
            float3 _e160 = value;
            stack_2[min(uint(min(top, 0u)), 0u)].sum = (_e151 + (_e159 * _e160));
            have_value = false;
        }
        uint _e164 = depth;
        uint top_1 = (_e164 - 1u);
        uint _e171 = stack_2[min(uint(min(top_1, 0u)), 0u)].next;
        uint _e176 = stack_2[min(uint(min(top_1, 0u)), 0u)].count;
        if ((_e171 < _e176)) {
            uint i_4 = stack_2[min(uint(min(top_1, 0u)), 0u)].next;
            stack_2[min(uint(min(top_1, 0u)), 0u)].next = (i_4 + 1u);
            Ray parent = stack_2[min(uint(min(top_1, 0u)), 0u)].ray;
            Hit hit_8 = stack_2[min(uint(min(top_1, 0u)), 0u)].hit;
            float3 dir_4 = stack_2[min(uint(min(top_1, 0u)), 0u)].dirs[min(uint(min(i_4, 0u)), 0u)];
            medium = parent.medium;
            const float3 _e209 = spawn_origin(hit_8, dir_4);
            uint _e212 = F32_INF;
            uint _e218 = medium;
            ray_17 = ConstructRay(_e209, 0.0, dir_4, asfloat(_e212), (parent.depth + 1u), RAY_SECONDARY, _e218);
        } else {
            uint _e224 = stack_2[min(uint(min(top_1, 0u)), 0u)].slot;
            GpuInstance inst_10 = ConstructGpuInstance(asfloat(instances.Load4(_e224*128+0)), asfloat(instances.Load4(_e224*128+16)), asfloat(instances.Load4(_e224*128+32)), asfloat(instances.Load4(_e224*128+48)), asfloat(instances.Load4(_e224*128+64)), asfloat(instances.Load4(_e224*128+80)), asuint(instances.Load(_e224*128+96)), asuint(instances.Load(_e224*128+100)), asuint(instances.Load(_e224*128+104)), asuint(instances.Load(_e224*128+108)), asuint(instances.Load(_e224*128+112)), asuint(instances.Load(_e224*128+116)), asuint(instances.Load(_e224*128+120)), asuint(instances.Load(_e224*128+124)));
            Ray _e234 = stack_2[min(uint(min(top_1, 0u)), 0u)].ray;
            Hit _e239 = stack_2[min(uint(min(top_1, 0u)), 0u)].hit;
            float3 _e244 = stack_2[min(uint(min(top_1, 0u)), 0u)].sum;
            const float3 _e245 = dispatch_closest_hit(inst_10.material_type, inst_10.material_offset, _e234, _e239, _e244);
            Ray _e250 = stack_2[min(uint(min(top_1, 0u)), 0u)].ray;
            float _e256 = stack_2[min(uint(min(top_1, 0u)), 0u)].hit.t;
            const float3 _e257 = through_medium(_e250, _e256, _e245);
            value = _e257;
            depth = top_1;
            have_value = true;
        }
    }
    return ZeroValuefloat3();
}

bool3 is_finite_vec3f(float3 x_2)
{
    return ((asuint(x_2) & (2147483647u).xxx) < (2139095040u).xxx);
}

float3 finite_or_zero(float3 c_3)
{
    const bool3 _e3 = is_finite_vec3f(c_3);
    return (_e3 ? c_3 : (0.0).xxx);
}

void render_pixel(uint2 pixel_3)
{
    float3 sum = (float3)0;
    uint bad = (uint)0;
    uint s = (uint)0;
    Ray ray_18 = (Ray)0;

    FrameUniforms frame_5 = frame;
    TileParams tile_1 = tile;
    sum = (0.0).xxx;
    bad = 0u;
    uint end_1 = frame_5.samples_per_pass;
    s = 0u;
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e45 = s;
            s = (_e45 + 1u);
        }
        loop_init_5 = false;
        uint _e13 = s;
        if ((_e13 >= end_1)) {
            break;
        }
        uint _e18 = s;
        uint sample_3 = ((tile_1.frame * frame_5.samples_per_pass) + _e18);
        rng_seed(pixel_3, sample_3, frame_5.seed);
        const Ray _e23 = dispatch_ray_generation(frame_5.camera_type, frame_5.camera_offset, pixel_3, sample_3);
        ray_18 = _e23;
        ray_18.depth = 0u;
        ray_18.kind = RAY_CAMERA;
        float3 _e31 = ray_18.origin;
        const uint _e32 = medium_at(_e31);
        ray_18.medium = _e32;
        Ray _e33 = ray_18;
        const float3 _e34 = trace(_e33);
        const bool3 _e35 = is_finite_vec3f(_e34);
        if (all(_e35)) {
            float3 _e37 = sum;
            sum = (_e37 + _e34);
        } else {
            float3 _e39 = sum;
            const float3 _e40 = finite_or_zero(_e34);
            sum = (_e39 + _e40);
            uint _e42 = bad;
            bad = (_e42 + 1u);
        }
    }
    float3 _e54 = sum;
    uint _e58 = bad;
    float4 _e61 = asfloat(accum.Load4(((pixel_3.y * tile_1.image_size.x) + pixel_3.x)*16));
    accum.Store4(((pixel_3.y * tile_1.image_size.x) + pixel_3.x)*16, asuint((_e61 + float4(_e54, float(frame_5.samples_per_pass)))));
    if ((_e58 > 0u)) {
        counters.InterlockedAdd(0, _e58);
    }
    return;
}

[numthreads(8, 8, 1)]
void render(uint3 gid : SV_DispatchThreadID)
{
    TileParams _e2 = tile;
    uint2 _e7 = uint2(gid.x, gid.y);
    if (any((_e7 >= _e2.extent))) {
        return;
    }
    render_pixel((_e2.origin + _e7));
    return;
}
