//! Structure-aware fuzzing of glTF/GLB files and of scene files, time-bounded (like
//! `tests/fuzz.rs` for sources): neither may panic or hang, whatever the input.
//!
//! - [`gltf_structure_mutations_never_panic`]: a small but rich glTF document (sparse accessor,
//!   strided normalised uvs, embedded PNG, material, camera, spot light, node hierarchy) is
//!   mutated at the JSON level (a value replaced by one of another type, a huge count or offset,
//!   a hostile path; two values swapped; a key removed or added; an array element duplicated)
//!   and given to the loader as `.gltf` JSON or as a `.glb` with its binary chunk (sometimes with
//!   a byte flipped as well).
//! - [`scene_mutations_never_panic`]: the `scene` items of every example are mutated as text
//!   (numbers replaced by extremes, strings by hostile or wrong-kind paths, meshes swapped, lines
//!   deleted, duplicated or swapped) and run through the checker and, when it accepts them,
//!   through linking and the whole entity stage (assets, BVHs, parameter packing; no GPU).
//!
//! Each runs for `RTC_FUZZ_SECONDS / 2` seconds (default 2; CI sets `RTC_FUZZ_SECONDS=60`), each
//! input on its own thread with a 64 MiB stack and a 20 s limit. `RTC_FUZZ_SEED` fixes the seed;
//! a failure prints it and the input (also written under the system temp folder).

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions};
use serde_json::{json, Value};

use super::fuzz::rich_glb;
use super::TempDir;
use crate::assets::model::parse_gltf_with;
use crate::assets::AssetRoots;
use crate::scene::{Entities, EntityOptions};

/// The seconds each target runs.
fn budget() -> Duration {
    let secs = std::env::var("RTC_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.trim().parse::<u64>().ok())
        .map_or(2, |s| (s / 2).max(1));
    Duration::from_secs(secs)
}

fn seed() -> u64 {
    std::env::var("RTC_FUZZ_SEED")
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(1, |d| d.as_nanos() as u64)
        })
}

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Runs `work` on its own thread; panics (naming `input`) if it panics or outlives `limit`.
fn guarded<T: Send + 'static>(
    target: &str,
    seed: u64,
    input: &[u8],
    work: impl FnOnce() -> T + Send + 'static,
) -> T {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
            let _ = tx.send(result);
        })
        .expect("spawn");
    let failure = match rx.recv_timeout(Duration::from_secs(20)) {
        Ok(Ok(value)) => return value,
        Ok(Err(panic)) => {
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .unwrap_or_default();
            format!("panicked: {message}")
        }
        Err(_) => "took more than 20 s".to_owned(),
    };
    let saved = std::env::temp_dir().join(format!("rtc-fuzz-{target}-{seed}.input"));
    let _ = std::fs::write(&saved, input);
    panic!(
        "fuzz {target} (RTC_FUZZ_SEED={seed}): the input {failure}; it is saved in {}:\n{}",
        saved.display(),
        String::from_utf8_lossy(&input[..input.len().min(4000)])
    );
}

// ---- glTF ----

/// The JSON chunk and the binary chunk of a `.glb` this module built.
fn split(glb: &[u8]) -> (Value, Vec<u8>) {
    let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
    let json_len = word(12);
    let doc = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin_at = 20 + json_len;
    let bin_len = word(bin_at);
    (doc, glb[bin_at + 8..bin_at + 8 + bin_len].to_vec())
}

/// Values of every JSON type, with the counts, offsets and paths that hurt most.
fn hostile_value(rng: &mut Rng) -> Value {
    let palette = [
        Value::Null,
        json!(true),
        json!(-1),
        json!(0),
        json!(1),
        json!(3),
        json!(5126),
        json!(255),
        json!(4_294_967_295u64),
        json!(4_294_967_296u64),
        json!(u64::MAX),
        json!(i64::MIN),
        json!(1 << 24),
        json!((1 << 24) + 1),
        json!(1e308),
        json!(-1e308),
        json!(0.5),
        json!(""),
        json!("x"),
        json!("VEC3"),
        json!("SCALAR"),
        json!("MAT4"),
        json!("../outside.bin"),
        json!("/etc/hostname"),
        json!("%2e%2e/%2e%2e/etc/hostname"),
        json!("file:///etc/hostname"),
        json!("C:\\windows\\win.ini"),
        json!("data:application/octet-stream;base64,AAAA"),
        json!("data:image/png;base64,iVBORw0KGgo="),
        json!([]),
        json!({}),
        json!([0, 0, 0]),
        json!([1e30, -1e30, 0, 1]),
        json!([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]),
        json!({ "bufferView": 0, "byteOffset": 4_294_967_295u64 }),
        json!({ "count": 4_294_967_295u64, "indices": { "bufferView": 0, "componentType": 5125 }, "values": { "bufferView": 0 } }),
        json!({ "extras": [1, "two", null] }),
    ];
    rng.pick(&palette).clone()
}

const KEYS: [&str; 18] = [
    "extras",
    "bufferView",
    "byteOffset",
    "byteStride",
    "byteLength",
    "count",
    "sparse",
    "uri",
    "mode",
    "material",
    "indices",
    "children",
    "matrix",
    "scale",
    "normalized",
    "componentType",
    "source",
    "extensions",
];

/// Every value's location in `doc`, as a list of object keys and array indices.
fn locations(doc: &Value) -> Vec<Vec<Value>> {
    fn walk(v: &Value, at: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
        out.push(at.clone());
        match v {
            Value::Object(map) => {
                for (k, child) in map {
                    at.push(json!(k));
                    walk(child, at, out);
                    at.pop();
                }
            }
            Value::Array(items) => {
                for (i, child) in items.iter().enumerate() {
                    at.push(json!(i));
                    walk(child, at, out);
                    at.pop();
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(doc, &mut Vec::new(), &mut out);
    out
}

fn at_mut<'a>(doc: &'a mut Value, path: &[Value]) -> Option<&'a mut Value> {
    let mut v = doc;
    for seg in path {
        v = match seg {
            Value::String(k) => v.get_mut(k.as_str())?,
            Value::Number(i) => v.get_mut(i.as_u64()? as usize)?,
            _ => return None,
        };
    }
    Some(v)
}

/// One structural mutation of `doc`.
fn mutate_json(rng: &mut Rng, doc: &mut Value) {
    let spots = locations(doc);
    let spot = rng.pick(&spots).clone();
    match rng.below(6) {
        0 | 1 => {
            let value = hostile_value(rng);
            if let Some(v) = at_mut(doc, &spot) {
                *v = value;
            }
        }
        2 => {
            let other = rng.pick(&spots).clone();
            let (Some(a), Some(b)) = (at_mut(doc, &spot).cloned(), at_mut(doc, &other).cloned())
            else {
                return;
            };
            if let Some(v) = at_mut(doc, &spot) {
                *v = b;
            }
            if let Some(v) = at_mut(doc, &other) {
                *v = a;
            }
        }
        3 => match at_mut(doc, &spot) {
            Some(Value::Object(map)) if !map.is_empty() => {
                let key = map.keys().nth(rng.below(map.len())).cloned().unwrap();
                map.remove(&key);
            }
            Some(Value::Array(items)) if !items.is_empty() => {
                let i = rng.below(items.len());
                items.remove(i);
            }
            _ => {}
        },
        4 => {
            let key = *rng.pick(&KEYS);
            let value = hostile_value(rng);
            if let Some(Value::Object(map)) = at_mut(doc, &spot) {
                map.insert(key.to_owned(), value);
            }
        }
        _ => {
            if let Some(Value::Array(items)) = at_mut(doc, &spot) {
                if let Some(first) = items.first().cloned() {
                    for _ in 0..=rng.below(3) {
                        items.push(first.clone());
                    }
                }
            }
        }
    }
}

/// A `.glb` container of `doc` and `bin`.
fn glb_of(doc: &Value, bin: &[u8]) -> Vec<u8> {
    super::gltf_builder::glb_bytes(doc, Some(bin))
}

#[test]
fn gltf_structure_mutations_never_panic() {
    let seed = seed();
    let mut rng = Rng(seed);
    let (base, bin) = split(&rich_glb());
    let dir = TempDir::new("fuzz-gltf");
    let started = Instant::now();
    let (mut inputs, mut loaded) = (0usize, 0usize);
    while started.elapsed() < budget() || inputs < 50 {
        let mut doc = base.clone();
        for _ in 0..=rng.below(4) {
            mutate_json(&mut rng, &mut doc);
        }
        let mut bytes = if rng.below(2) == 0 {
            serde_json::to_vec(&doc).unwrap()
        } else {
            glb_of(&doc, &bin)
        };
        if rng.below(4) == 0 && !bytes.is_empty() {
            let at = rng.below(bytes.len());
            bytes[at] ^= 1 << rng.below(8);
        }
        let path = dir.path().join("m.gltf");
        let input = bytes.clone();
        let ok = guarded("gltf", seed, &input, move || {
            parse_gltf_with(&bytes, &path, &AssetRoots::none()).map(|scene| {
                // What loads satisfies the ModelScene invariants.
                for m in &scene.meshes {
                    assert!(m.validate().is_ok());
                }
                for i in &scene.instances {
                    assert!(i.mesh < scene.meshes.len() && i.material < scene.materials.len());
                    assert!(i.transform.is_finite());
                }
                for t in &scene.textures {
                    assert_eq!(t.words.len(), t.texel_count() * t.format.words_per_texel());
                }
            })
        });
        inputs += 1;
        loaded += usize::from(ok.is_ok());
    }
    eprintln!(
        "fuzz gltf: {inputs} mutated documents in {:.1?}, {loaded} loaded (seed {seed})",
        started.elapsed()
    );
    // The mutations must not all be rejected up front, or the importer is not being exercised.
    assert!(loaded > 0, "no mutated document loaded");
}

// ---- scenes ----

/// Every example's scene file and its text.
fn example_scenes() -> Vec<(PathBuf, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&root).unwrap() {
        let path = entry.unwrap().path().join("scene.rt");
        if let Ok(text) = std::fs::read_to_string(&path) {
            out.push((path, text));
        }
    }
    out.sort();
    assert!(
        !out.is_empty(),
        "no example scenes under {}",
        root.display()
    );
    out
}

const NUMBERS: [&str; 14] = [
    "0.0",
    "-0.0",
    "1e38",
    "3.4e38",
    "-3.4e38",
    "1e-45",
    "1e-30",
    "0u",
    "4294967295u",
    "65536u",
    "100000.0",
    "-1.0",
    "2147483647",
    "-2147483648",
];

const STRINGS: [&str; 11] = [
    "\"bunny-6k.obj\"",
    "\"checker.png\"",
    "\"scene.rt\"",
    "\"\"",
    "\"nope.obj\"",
    "\"../assets/bunny-6k.obj\"",
    "\"/etc/hostname\"",
    "\"file:///etc/hostname\"",
    "\"..\\\\..\\\\x\"",
    "\"%2e%2e/x\"",
    "\"model.glb\"",
];

const CALLS: [&str; 8] = [
    "quad_mesh()",
    "cube_mesh()",
    "sphere_mesh(0u)",
    // Not larger: `sphere_mesh(8u)` (and anything above, clamped to 8) is 1.3 M triangles, whose
    // BVH takes over 20 s in a debug build; that is size, not a hang.
    "sphere_mesh(3u)",
    "load_mesh(\"scene.rt\")",
    "load_mesh(\"checker.png\")",
    "load_image(\"bunny-6k.obj\")",
    "solid_texture(vec4f(1e38, -1e38, 0.0, 1.0))",
];

/// Byte ranges of the tokens in `text[from..]` that `is_start`/`is_part` describe.
fn tokens(
    text: &str,
    from: usize,
    is_start: fn(u8) -> bool,
    is_part: fn(u8) -> bool,
) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = from;
    while i < bytes.len() {
        let prev_ident = i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        if is_start(bytes[i]) && !prev_ident {
            let start = i;
            i += 1;
            while i < bytes.len() && is_part(bytes[i]) {
                i += 1;
            }
            out.push((start, i));
        } else {
            i += 1;
        }
    }
    out
}

/// One textual mutation of the scene item (everything after `scene`) of `text`.
fn mutate_scene(rng: &mut Rng, text: &mut String) {
    let from = text.find("\nscene ").unwrap_or(0);
    match rng.below(5) {
        0 => {
            let numbers = tokens(
                text,
                from,
                |b| b.is_ascii_digit(),
                |b| b.is_ascii_alphanumeric() || b == b'.' || b == b'_',
            );
            if !numbers.is_empty() {
                let (s, e) = *rng.pick(&numbers);
                let with: &str = NUMBERS[rng.below(NUMBERS.len())];
                text.replace_range(s..e, with);
            }
        }
        1 => {
            let strings: Vec<(usize, usize)> = text[from..]
                .match_indices('"')
                .map(|(i, _)| from + i)
                .collect::<Vec<_>>()
                .chunks_exact(2)
                .map(|p| (p[0], p[1] + 1))
                .collect();
            if !strings.is_empty() {
                let (s, e) = *rng.pick(&strings);
                let with: &str = STRINGS[rng.below(STRINGS.len())];
                text.replace_range(s..e, with);
            }
        }
        2 => {
            let calls: Vec<(usize, usize)> = [
                "quad_mesh()",
                "cube_mesh()",
                "load_mesh(",
                "sphere_mesh(",
                "load_image(",
                "solid_texture(",
            ]
            .iter()
            .flat_map(|name| text[from..].match_indices(name).map(|(i, n)| (i, n.len())))
            .filter_map(|(i, len)| {
                let s = from + i;
                // The call's end: its closing parenthesis at depth 0.
                let mut depth = 0i32;
                for (k, c) in text[s..].char_indices() {
                    match c {
                        '(' => depth += 1,
                        ')' => {
                            depth -= 1;
                            if depth == 0 {
                                return Some((s, s + k + 1));
                            }
                        }
                        _ => {}
                    }
                    if k > len + 200 {
                        break;
                    }
                }
                None
            })
            .collect();
            if !calls.is_empty() {
                let (s, e) = *rng.pick(&calls);
                let with: &str = CALLS[rng.below(CALLS.len())];
                text.replace_range(s..e, with);
            }
        }
        _ => {
            let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
            let first = text[..from].lines().count();
            if lines.len() <= first + 2 {
                return;
            }
            let a = first + 1 + rng.below(lines.len() - first - 2);
            let b = first + 1 + rng.below(lines.len() - first - 2);
            match rng.below(3) {
                0 => {
                    lines.remove(a);
                }
                1 => {
                    let line = lines[a].clone();
                    lines.insert(b, line);
                }
                _ => lines.swap(a, b),
            }
            *text = lines.join("\n");
        }
    }
}

/// Checks `text` as the file `path` and, when it checks, links its scene and builds the entities.
/// Returns how far it got: 0 errors in checking, 1 link failure, 2 entity error, 3 built.
fn run_scene(path: &Path, text: &str) -> u8 {
    let checked = check_text(&path.display().to_string(), text, &Options::default());
    if checked.has_errors() {
        return 0;
    }
    let Some(program) = checked.program else {
        return 0;
    };
    let Ok(scene) = program.select_scene(None) else {
        return 0;
    };
    let Ok(linked) = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    ) else {
        return 1;
    };
    match Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions::default(),
    ) {
        Ok(entities) => {
            // A scene error of any kind must still make a message, never a panic.
            let _ = entities.stats();
            3
        }
        Err(e) => {
            let _ = (e.to_string(), e.to_diagnostic());
            2
        }
    }
}

#[test]
fn scene_mutations_never_panic() {
    let seed = seed();
    let mut rng = Rng(seed);
    let scenes = example_scenes();
    let started = Instant::now();
    let mut outcomes = [0usize; 4];
    let mut inputs = 0usize;
    while started.elapsed() < budget() || inputs < 20 {
        let (path, base) = rng.pick(&scenes).clone();
        let mut text = base;
        for _ in 0..=rng.below(3) {
            mutate_scene(&mut rng, &mut text);
        }
        let input = text.clone().into_bytes();
        let outcome = guarded("scene", seed, &input, move || run_scene(&path, &text));
        outcomes[usize::from(outcome)] += 1;
        inputs += 1;
    }
    eprintln!(
        "fuzz scenes: {inputs} mutated scenes in {:.1?}: {} rejected by the checker, {} by the \
         link, {} by the entity stage, {} built (seed {seed})",
        started.elapsed(),
        outcomes[0],
        outcomes[1],
        outcomes[2],
        outcomes[3]
    );
    assert!(outcomes[3] > 0, "no mutated scene got through to entities");
}
