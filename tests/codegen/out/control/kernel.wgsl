struct Input {
    n: u32,
    limit: u32,
}

struct Output {
    result: u32,
}

@group(0) @binding(0) 
var<storage> input: array<Input>;
@group(0) @binding(1) 
var<storage, read_write> output: array<Output>;

fn test_fn(n: u32, limit: u32) -> u32 {
    var total: u32;
    var i: u32;
    var k: u32;

    total = 0u;
    i = 0u;
    loop {
        let _e6 = i;
        if (_e6 >= n) {
            break;
        }
        let _e8 = i;
        let _e13 = i;
        if (((_e8 % 3u) == 0u) && (_e13 != 0u)) {
            continue;
        }
        let _e17 = total;
        let _e18 = i;
        total = (_e17 + _e18);
        let _e20 = total;
        let _e22 = i;
        if ((_e20 > limit) || (_e22 > 100u)) {
            let _e26 = total;
            return _e26;
        }
        continuing {
            let _e27 = i;
            i = (_e27 + 1u);
        }
    }
    k = 0u;
    loop {
        let _e32 = k;
        if !((_e32 < 4u)) {
            break;
        }
        let _e36 = k;
        k = (_e36 + 1u);
    }
    let _e39 = total;
    let _e40 = k;
    return (_e39 + _e40);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let index = id.x;
    if (index >= arrayLength((&input))) {
        return;
    }
    let _e8 = input[index].n;
    let _e10 = input[index].limit;
    let _e11 = test_fn(_e8, _e10);
    output[index].result = _e11;
}
