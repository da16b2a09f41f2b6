struct Pair {
    a: vec3<f32>,
    b: f32,
}

struct Input {
    v: vec4<f32>,
    i: u32,
}

struct Output {
    result: vec4<f32>,
}

@group(0) @binding(0) 
var<storage> input: array<Input>;
@group(0) @binding(1) 
var<storage, read_write> output: array<Output>;

fn combine(p: Pair, m: mat3x3<f32>) -> vec3<f32> {
    return ((m * p.a) * vec3(p.b));
}

fn test_fn(v: vec4<f32>, i: u32) -> vec4<f32> {
    var table: array<f32, 4>;

    table = array<f32, 4>(1f, 2f, 3f, 4f);
    table[min((i % 4u), 3u)] = v.w;
    let p_1 = Pair(v.xyz, 2f);
    let _e30 = combine(p_1, mat3x3<f32>(vec3<f32>(1f, 0f, 0f), vec3<f32>(0f, 1f, 0f), vec3<f32>(0f, 0f, 1f)));
    let _e39 = table[min(((i + 1u) % 4u), 3u)];
    return vec4<f32>(_e30.zyx, _e39);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let index = id.x;
    if (index >= arrayLength((&input))) {
        return;
    }
    let _e8 = input[index].v;
    let _e10 = input[index].i;
    let _e11 = test_fn(_e8, _e10);
    output[index].result = _e11;
}
