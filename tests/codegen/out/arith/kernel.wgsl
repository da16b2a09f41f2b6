struct Input {
    a: i32,
    b: i32,
    x: f32,
}

struct Output {
    result: f32,
}

@group(0) @binding(0) 
var<storage> input: array<Input>;
@group(0) @binding(1) 
var<storage, read_write> output: array<Output>;

fn div_i32_(a: i32, b: i32) -> i32 {
    let by_zero = (b == 0i);
    let divisor = select(select(b, 1i, by_zero), 1i, ((a == i32(-2147483648)) & (b == -1i)));
    return (a / divisor);
}

fn rem_i32_(a_1: i32, b_1: i32) -> i32 {
    let by_zero_1 = (b_1 == 0i);
    let divisor_1 = select(select(b_1, 1i, by_zero_1), 1i, ((a_1 == i32(-2147483648)) & (b_1 == -1i)));
    return select((a_1 - (divisor_1 * (a_1 / divisor_1))), 0i, by_zero_1);
}

fn test_fn(a_2: i32, b_2: i32, x: f32) -> f32 {
    let _e3 = div_i32_(a_2, b_2);
    let _e4 = rem_i32_(a_2, b_2);
    return ((f32((_e3 + _e4)) * x) + sqrt(abs(x)));
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let index = id.x;
    if (index >= arrayLength((&input))) {
        return;
    }
    let _e8 = input[index].a;
    let _e10 = input[index].b;
    let _e12 = input[index].x;
    let _e13 = test_fn(_e8, _e10, _e12);
    output[index].result = _e13;
}
