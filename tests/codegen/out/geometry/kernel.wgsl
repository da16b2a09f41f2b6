struct Ray {
    origin: vec3<f32>,
    tmin: f32,
    dir: vec3<f32>,
    tmax: f32,
    depth: u32,
    kind: u32,
    medium: u32,
}

struct Triangle {
    v0_: vec3<f32>,
    v1_: vec3<f32>,
    v2_: vec3<f32>,
}

struct Intersection {
    t: f32,
    normal: vec3<f32>,
    uv: vec2<f32>,
}

struct Input {
    o: vec3<f32>,
    d: vec3<f32>,
}

struct Output {
    result: vec3<f32>,
}

var<private> F32_INF: u32 = 2139095040u;
var<private> F32_NEG_INF: u32 = 4286578688u;
@group(0) @binding(0) 
var<storage> input: array<Input>;
@group(0) @binding(1) 
var<storage, read_write> output: array<Output>;

fn normalize_vec3f(v: vec3<f32>) -> vec3<f32> {
    return select(vec3(0f), normalize(v), (dot(v, v) >= 0.000000000000000000000000000000000000011754944f));
}

fn intersect_triangle(ray: Ray, tri: Triangle) -> Intersection {
    let _e10 = vec3(2139095040u);
    let dir = select(ray.dir, vec3(0f), (abs(ray.dir) < vec3(0.000000000000000000000000000000000000011754944f)));
    let _e31 = abs(dir);
    let _e38 = (_e31.y > _e31.x);
    let kz = select(select(0u, 1u, _e38), 2u, (_e31.z > select(_e31.x, _e31.y, _e38)));
    let _e45 = select((kz + 1u), 0u, (kz == 2u));
    let _e49 = select((kz + 2u), (kz - 1u), (kz >= 1u));
    let dz = dir[kz];
    let _e52 = (dz < 0f);
    let kx = select(_e45, _e49, _e52);
    let ky = select(_e49, _e45, _e52);
    let sx = (dir[kx] / dz);
    let sy = (dir[ky] / dz);
    let sz = (1f / dz);
    let _e62 = (tri.v0_ - ray.origin);
    let _e68 = (_e62[kx] - (sx * _e62[kz]));
    let _e69 = (_e62[ky] - (sy * _e62[kz]));
    let _e71 = (tri.v1_ - ray.origin);
    let _e77 = (_e71[kx] - (sx * _e71[kz]));
    let _e78 = (_e71[ky] - (sy * _e71[kz]));
    let _e80 = (tri.v2_ - ray.origin);
    let _e86 = (_e80[kx] - (sx * _e80[kz]));
    let _e87 = (_e80[ky] - (sy * _e80[kz]));
    let u = ((_e86 * _e78) - (_e87 * _e77));
    let v_1 = ((_e68 * _e87) - (_e69 * _e86));
    let w = ((_e77 * _e69) - (_e78 * _e68));
    let det = ((u + v_1) + w);
    let _e112 = (1f / det);
    let t = ((((u * (sz * _e62[kz])) + (v_1 * (sz * _e71[kz]))) + (w * (sz * _e80[kz]))) * _e112);
    let hit = (((((all(((bitcast<vec3<u32>>(ray.origin) & vec3(2147483647u)) < _e10)) && all(((bitcast<vec3<u32>>(ray.dir) & vec3(2147483647u)) < _e10))) && (dz != 0f)) && !(((((u < 0f) || (v_1 < 0f)) || (w < 0f)) && (((u > 0f) || (v_1 > 0f)) || (w > 0f))))) && !((det == 0f))) && ((t >= ray.tmin) && (t <= ray.tmax)));
    let _e132 = normalize_vec3f(cross((tri.v1_ - tri.v0_), (tri.v2_ - tri.v0_)));
    let _e137 = F32_INF;
    return Intersection(select(bitcast<f32>(_e137), t, hit), select(vec3<f32>(0f, 0f, 1f), _e132, hit), select(vec2(0f), vec2<f32>((v_1 * _e112), (w * _e112)), hit));
}

fn intersect_aabb(ray_1: Ray, min_: vec3<f32>, max_: vec3<f32>) -> vec2<f32> {
    let parallel = (abs(ray_1.dir) < vec3(0.000000000000000000000000000000000000011754944f));
    let _e12 = vec3(1f);
    let inv_dir = (_e12 / select(ray_1.dir, _e12, parallel));
    let _e17 = ((min_ - ray_1.origin) * inv_dir);
    let _e18 = ((max_ - ray_1.origin) * inv_dir);
    let _e23 = ((min_ <= ray_1.origin) & (ray_1.origin <= max_));
    let _e25 = F32_INF;
    let _e27 = vec3(bitcast<f32>(_e25));
    let _e29 = F32_NEG_INF;
    let _e31 = vec3(bitcast<f32>(_e29));
    let near = select(min(_e17, _e18), select(_e27, _e31, _e23), parallel);
    let far = select(max(_e17, _e18), select(_e31, _e27, _e23), parallel);
    return vec2<f32>(max(max(max(near.x, near.y), near.z), ray_1.tmin), min(min(min(far.x, far.y), far.z), ray_1.tmax));
}

fn test_fn(o: vec3<f32>, d: vec3<f32>) -> vec3<f32> {
    let _e4 = F32_INF;
    let ray_2 = Ray(o, 0f, d, bitcast<f32>(_e4), 0u, 0u, 0u);
    let tri_1 = Triangle(vec3<f32>(-1f, -1f, 0f), vec3<f32>(1f, -1f, 0f), vec3<f32>(0f, 1f, 0f));
    let _e23 = intersect_triangle(ray_2, tri_1);
    let _e28 = intersect_aabb(ray_2, vec3(-1f), vec3(1f));
    return vec3<f32>(select(-1f, _e23.t, (_e23.t < 1000000000000000000000000000000f)), _e28.x, _e28.y);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let index = id.x;
    if (index >= arrayLength((&input))) {
        return;
    }
    let _e8 = input[index].o;
    let _e10 = input[index].d;
    let _e11 = test_fn(_e8, _e10);
    output[index].result = _e11;
}
