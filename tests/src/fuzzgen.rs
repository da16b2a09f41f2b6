//! Inputs for the robustness test (`fuzz.rs`): a small seeded PRNG, random bytes, token soups, deep
//! nestings, mutations of the existing `.rt` files, and the fixed degenerate inputs.
//!
//! Everything is a pure function of the seed, so an input can be regenerated from `RTC_FUZZ_SEED`
//! (the run also saves each failing input to `tests/fuzz/artifacts/`).

use std::path::PathBuf;

/// SplitMix64: small, fast, good enough to explore inputs (not for cryptography).
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator started from `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next_u64() % n as u64) as usize
        }
    }

    /// True with probability `1 / n`.
    pub fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    /// A random element (the slice must not be empty).
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    /// A length that is usually small and sometimes large: `0..max` on a log scale.
    pub fn length(&mut self, max: usize) -> usize {
        let bits = usize::BITS - max.max(1).leading_zeros();
        let cap = 1usize << self.below(bits as usize + 1);
        self.below(cap.min(max) + 1)
    }
}

/// The language's tokens and some near-misses: keywords, contextual keywords, punctuation, literals
/// (valid and malformed), type, built-in and framework names, attributes, comments, strings and odd
/// characters.
pub const TOKENS: &[&str] = &[
    // keywords
    "as",
    "break",
    "const",
    "continue",
    "else",
    "false",
    "fn",
    "for",
    "if",
    "import",
    "in",
    "let",
    "loop",
    "return",
    "scene",
    "struct",
    "true",
    "var",
    "while",
    // contextual keywords
    "settings",
    "camera",
    "background",
    "object",
    "light",
    "model",
    // punctuation
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    "<",
    ">",
    ",",
    ";",
    ":",
    ".",
    "..",
    "->",
    "@",
    "=",
    "+",
    "-",
    "*",
    "/",
    "%",
    "!",
    "~",
    "&",
    "|",
    "^",
    "&&",
    "||",
    "<<",
    ">>",
    "==",
    "!=",
    "<=",
    ">=",
    "+=",
    "-=",
    "*=",
    "/=",
    "%=",
    "&=",
    "|=",
    "^=",
    "<<=",
    ">>=",
    // literals, good and bad
    "0",
    "1",
    "42",
    "1_000",
    "0x7f800000u",
    "0b101",
    "1i",
    "1u",
    "4294967296u",
    "2147483648i",
    "99999999999999999999",
    "1.0",
    "0.5",
    "1e3",
    "1e3f",
    "1.5f",
    "1.0e-7",
    "0x",
    "1e",
    "1.0.0",
    "1q",
    "2.0u",
    "1.",
    ".5",
    "0b2",
    // strings
    "\"std/cameras/pinhole.rt\"",
    "\"std/lights/point.rt\"",
    "\"std/materials/lambert.rt\"",
    "\"x.rt\"",
    "\"\"",
    "\"a\\n\\t\\\"\\\\\"",
    "\"\\q\"",
    "\"",
    "\"unterminated",
    // types and names
    "f32",
    "i32",
    "u32",
    "bool",
    "vec2f",
    "vec3f",
    "vec4f",
    "vec2u",
    "vec3u",
    "vec2i",
    "mat3x3f",
    "mat4x4f",
    "array",
    "texture",
    "string",
    "Ray",
    "Hit",
    "Intersection",
    "Aabb",
    "LightSample",
    "PI",
    "INF",
    "EPSILON",
    "RAY_SHADOW",
    "dot",
    "max",
    "min",
    "normalize",
    "length",
    "cross",
    "mix",
    "clamp",
    "select",
    "sqrt",
    "pow",
    "abs",
    "reflect",
    "refract",
    "spawn",
    "shadow",
    "sample_light",
    "light_count",
    "random",
    "bitcast",
    "quad_mesh",
    "sphere_mesh",
    "cube_mesh",
    "load_mesh",
    "translate",
    "scale",
    "rotate_y",
    "x",
    "y",
    "z",
    "xyz",
    "rgb",
    "xx",
    "w",
    "a",
    "b",
    "i",
    "main",
    "_",
    "__",
    "Matte",
    "Pinhole",
    "Lambert",
    "Glass",
    "albedo",
    "position",
    "origin",
    "dir",
    // attributes
    "@camera",
    "@geometry",
    "@material",
    "@light",
    "@background",
    "@ray_generation",
    "@intersection",
    "@bounds",
    "@any_hit",
    "@closest_hit",
    "@secondary_rays",
    "@medium",
    "@miss",
    "@ray_generation(samples = 4)",
    "@unknown",
    // comments
    "//",
    "///",
    "//!",
    "/*",
    "*/",
    "/* a /* b */ c */",
    "//~ E0401",
    // odd characters
    "\\",
    "$",
    "#",
    "?",
    "'",
    "`",
    "é",
    "∞",
    "\u{0}",
    "\u{feff}",
    "\u{200b}",
    "\t",
    "\r",
    "\r\n",
];

/// Small constructs that make a token soup reach deeper into the parser.
pub const SNIPPETS: &[&str] = &[
    "fn f(x: f32) -> f32 {",
    "fn g() {",
    "}",
    "struct S { a: f32, b: vec3f = vec3f(1.0), }",
    "@material struct M { albedo: vec3f = vec3f(0.5) }",
    "@closest_hit fn shade(m: M, ray: Ray, hit: Hit) -> vec3f {",
    "let v = vec3f(1.0, 2.0, 3.0);",
    "var i = 0u;",
    "for i in 0u..4u {",
    "while true {",
    "loop { break; }",
    "if a < b {",
    "} else {",
    "return x;",
    "const C: u32 = 3u;",
    "import \"std/miss/constant.rt\";",
    "scene s {",
    "settings { width: 8, height: 8, samples: 1 }",
    "camera Pinhole {}",
    "object o { geometry: quad_mesh(), material: M {} }",
    "array<vec3<f32>, 2>",
    "a.b.c[1].xyz",
    "S { a: 1.0 }",
];

/// How an input is fed to the checker.
#[derive(Clone, Debug)]
pub enum Feed {
    /// As text, through `check_text`.
    Text(String),
    /// As raw bytes in a file, through `check_paths` (reaches the invalid UTF-8 path).
    Bytes(Vec<u8>),
}

impl Feed {
    /// The input's bytes, to save it.
    pub fn bytes(&self) -> &[u8] {
        match self {
            Feed::Text(t) => t.as_bytes(),
            Feed::Bytes(b) => b,
        }
    }
}

/// Random bytes: mostly printable ASCII, sometimes anything.
pub fn random_bytes(rng: &mut Rng, max_len: usize) -> Vec<u8> {
    let len = rng.length(max_len);
    let ascii = !rng.one_in(3);
    (0..len)
        .map(|_| {
            if !ascii || rng.one_in(50) {
                rng.next_u64() as u8
            } else if rng.one_in(2) {
                const COMMON: &[u8] = b" \n\t(){}[];:.,=+-*/<>!&|^%@\"_azAZ09x";
                COMMON[rng.below(COMMON.len())]
            } else {
                32 + rng.below(95) as u8
            }
        })
        .collect()
}

/// A soup of tokens and snippets separated by spaces, newlines or nothing.
pub fn token_soup(rng: &mut Rng, max_tokens: usize) -> String {
    let n = rng.length(max_tokens);
    let mut out = String::new();
    for _ in 0..n {
        if rng.one_in(6) {
            out.push_str(rng.pick::<&str>(SNIPPETS));
        } else {
            out.push_str(rng.pick::<&str>(TOKENS));
        }
        match rng.below(8) {
            0 => {}
            1 => out.push('\n'),
            _ => out.push(' '),
        }
    }
    out
}

/// Openers that nest, each with its closer (closers may be left out to test recovery).
const NESTERS: &[(&str, &str)] = &[
    ("(", ")"),
    ("{", "}"),
    ("[", "]"),
    ("-", ""),
    ("!", ""),
    ("vec3f(", ")"),
    ("if true {", "}"),
    ("f(", ")"),
    ("a[", "]"),
    ("S { a: ", " }"),
    ("array<", ">"),
    ("/*", "*/"),
];

/// A function whose body nests random constructs up to `max_depth` deep, with junk in between.
pub fn deep_mix(rng: &mut Rng, max_depth: usize) -> String {
    let depth = rng.length(max_depth);
    let mut out = String::from("fn f() -> f32 { return ");
    let mut closers = Vec::with_capacity(depth);
    for _ in 0..depth {
        let (open, close) = *rng.pick(NESTERS);
        out.push_str(open);
        if rng.one_in(20) {
            out.push_str(rng.pick::<&str>(TOKENS));
            out.push(' ');
        }
        closers.push(close);
    }
    out.push('1');
    let drop_closers = rng.one_in(4);
    while let Some(close) = closers.pop() {
        if !(drop_closers && rng.one_in(3)) {
            out.push_str(close);
        }
    }
    out.push_str("; }\n");
    out
}

/// Numbers a mutation puts in place of a numeric literal: zeros, extremes, denormals, integers
/// past `f32`'s exact range, the ends of `u32` and `i32`.
const EXTREME_NUMBERS: &[&str] = &[
    "0",
    "0.0",
    "-0.0",
    "1",
    "-1",
    "0.5",
    "1e-38",
    "1e-45",
    "3.4e38",
    "-3.4e38",
    "1e30",
    "16777217.0",
    "65536",
    "4294967295",
    "2147483647",
    "-2147483648",
    "0u",
    "4294967295u",
    "65536u",
];

/// Byte ranges `(start, end)` of words of a text.
type Spans = Vec<(usize, usize)>;

/// The byte ranges of the identifiers (`[A-Za-z_][A-Za-z0-9_]*`) and of the numeric literals
/// (starting with a digit) of `data`: `(identifiers, numbers)`.
fn word_spans(data: &[u8]) -> (Spans, Spans) {
    let (mut idents, mut numbers) = (Vec::new(), Vec::new());
    let mut i = 0;
    while i < data.len() {
        let c = data[i];
        let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
        if c.is_ascii_alphabetic() || c == b'_' || c.is_ascii_digit() {
            let start = i;
            while i < data.len() && (word(data[i]) || (c.is_ascii_digit() && data[i] == b'.')) {
                i += 1;
            }
            if c.is_ascii_digit() {
                numbers.push((start, i));
            } else {
                idents.push((start, i));
            }
        } else {
            i += 1;
        }
    }
    (idents, numbers)
}

/// Applies 1 to 8 random edits to `base`: byte flips, deletions, duplications, insertions of tokens,
/// splices from another corpus file, truncation, and two that keep a program well formed more often
/// and so reach the checker's later passes: an identifier replaced by another of the same file (a
/// type by another type, a struct named in its own fields), a number by an extreme one.
pub fn mutate(rng: &mut Rng, base: &[u8], corpus: &[(String, Vec<u8>)]) -> Vec<u8> {
    let mut data = base.to_vec();
    for _ in 0..1 + rng.below(8) {
        let len = data.len();
        match rng.below(9) {
            k @ (7 | 8) => {
                let (idents, numbers) = word_spans(&data);
                if k == 7 {
                    if idents.is_empty() {
                        continue;
                    }
                    let (a, b) = *rng.pick(&idents);
                    let (c, d) = *rng.pick(&idents);
                    let name = data[c..d].to_vec();
                    data.splice(a..b, name);
                } else {
                    if numbers.is_empty() {
                        continue;
                    }
                    let (a, b) = *rng.pick(&numbers);
                    data.splice(a..b, rng.pick(EXTREME_NUMBERS).bytes());
                }
            }
            0 if len > 0 => {
                let i = rng.below(len);
                data[i] ^= 1 << rng.below(8);
            }
            1 if len > 0 => {
                let at = rng.below(len);
                let n = rng.length(len - at);
                data.drain(at..at + n);
            }
            2 if len > 0 => {
                let at = rng.below(len);
                let n = rng.length((len - at).min(4096));
                let copy = data[at..at + n].to_vec();
                let to = rng.below(data.len() + 1);
                data.splice(to..to, copy);
            }
            3 => {
                let to = rng.below(len + 1);
                let tok = rng.pick(TOKENS).as_bytes().to_vec();
                data.splice(to..to, tok);
            }
            4 if !corpus.is_empty() => {
                let other = &rng.pick(corpus).1;
                if !other.is_empty() {
                    let at = rng.below(other.len());
                    let n = rng.length((other.len() - at).min(4096));
                    let to = rng.below(len + 1);
                    data.splice(to..to, other[at..at + n].iter().copied());
                }
            }
            5 if len > 0 => data.truncate(rng.below(len)),
            _ => {
                let to = rng.below(len + 1);
                let b = rng.next_u64() as u8;
                data.insert(to, b);
            }
        }
    }
    data
}

/// Every `.rt` file of `stdlib/`, `examples/` and `tests/ui/`, plus every ` ```rt ` block of the
/// spec, as `(name, bytes)`.
pub fn corpus() -> Vec<(String, Vec<u8>)> {
    let root = crate::paths::repo_root();
    let mut files: Vec<PathBuf> = crate::paths::stdlib_and_examples();
    files.extend(crate::paths::files_with_extension(
        &root.join("tests/ui"),
        "rt",
    ));
    let mut out: Vec<(String, Vec<u8>)> = files
        .iter()
        .filter_map(|p| Some((crate::paths::display_relative(p), std::fs::read(p).ok()?)))
        .collect();
    for md in crate::paths::files_with_extension(&root.join("spec"), "md") {
        let name = crate::paths::display_relative(&md);
        let text = std::fs::read_to_string(&md).unwrap_or_default();
        for block in crate::spec::extract(&name, &text).0 {
            out.push((block.name(), block.code.into_bytes()));
        }
    }
    out
}

/// `fn f() -> f32 { return ((…(1)…)); }` with `depth` parentheses.
pub fn deep_parens(depth: usize) -> String {
    format!(
        "fn f() -> f32 {{ return {}1{}; }}\n",
        "(".repeat(depth),
        ")".repeat(depth)
    )
}

/// `fn f() -> i32 { return - - … 1; }` with `depth` unary minuses.
pub fn deep_unary(depth: usize) -> String {
    format!("fn f() -> i32 {{ return {}1; }}\n", "- ".repeat(depth))
}

/// `fn f() { {{…}} }` with `depth` nested blocks.
pub fn deep_blocks(depth: usize) -> String {
    format!("fn f() {{ {}{} }}\n", "{".repeat(depth), "}".repeat(depth))
}

/// At least `bytes` bytes of valid code: one small function after another, each with its own name.
pub fn big_valid(bytes: usize) -> String {
    let mut out = String::with_capacity(bytes + 256);
    let mut i = 0usize;
    while out.len() < bytes {
        out.push_str(&format!(
            "/// Function number {i}.\nfn f_{i}(x: f32, v: vec3f) -> f32 {{\n    let y = x * 2.0 + 1.0;\n    \
             var acc = dot(v, vec3f(y));\n    for k in 0u..4u {{\n        acc += f32(k) * y;\n    }}\n    \
             if acc > 10.0 {{\n        return acc;\n    }}\n    return max(acc, 0.5);\n}}\n\n"
        ));
        i += 1;
    }
    out
}

/// `bytes` random bytes (any values, so mostly invalid UTF-8 as a file).
pub fn big_random(rng: &mut Rng, bytes: usize) -> Vec<u8> {
    let mut out = Vec::with_capacity(bytes + 8);
    while out.len() < bytes {
        out.extend_from_slice(&rng.next_u64().to_le_bytes());
    }
    out.truncate(bytes);
    out
}

/// `bytes` random printable ASCII and newlines (valid UTF-8, so it reaches the lexer and parser).
pub fn big_random_text(rng: &mut Rng, bytes: usize) -> String {
    (0..bytes)
        .map(|_| {
            let r = rng.below(100);
            if r < 3 {
                '\n'
            } else {
                (32 + rng.below(95) as u8) as char
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generators_are_deterministic_and_bounded() {
        let mut a = Rng::new(7);
        let mut b = Rng::new(7);
        assert_eq!(token_soup(&mut a, 50), token_soup(&mut b, 50));
        for _ in 0..200 {
            assert!(random_bytes(&mut a, 100).len() <= 100);
            assert!(a.length(10) <= 10);
        }
        assert_eq!(deep_parens(2), "fn f() -> f32 { return ((1)); }\n");
        assert!(big_valid(1000).len() >= 1000);
        assert_eq!(big_random(&mut a, 13).len(), 13);
    }

    #[test]
    fn word_mutations_find_identifiers_and_numbers() {
        let text = b"struct S { a: array<f32, 4u> = x_1 * 2.5, }";
        let (idents, numbers) = word_spans(text);
        let words = |spans: &[(usize, usize)]| -> Vec<String> {
            spans
                .iter()
                .map(|&(a, b)| String::from_utf8_lossy(&text[a..b]).into_owned())
                .collect()
        };
        assert_eq!(words(&idents), ["struct", "S", "a", "array", "f32", "x_1"]);
        assert_eq!(words(&numbers), ["4u", "2.5"]);
        // Over many seeds, an identifier swap yields a struct named in its own field.
        let recursive = (0..2000).any(|seed| {
            let out = mutate(&mut Rng::new(seed), text, &[]);
            out.starts_with(b"struct S { a: array<S, 4u>")
        });
        assert!(recursive, "no identifier swap gave `array<S, 4u>`");
    }

    #[test]
    fn corpus_has_the_stdlib_and_spec_blocks() {
        let corpus = corpus();
        assert!(corpus.iter().any(|(n, _)| n == "stdlib/prelude.rt"));
        assert!(corpus.iter().any(|(n, _)| n.starts_with("spec/README.md:")));
    }
}
