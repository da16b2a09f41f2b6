//! `manifest.json` is enough to read a scene's buffers: the thesis scene's buffers are built on the
//! CPU ([`Entities`], no GPU), and a decoder that knows only the JSON manifest (as a
//! `serde_json::Value`) and the raw bytes of each binding finds the right triangles (the OBJ file's
//! vertices), walks every BVH from the scene-level root through the manifest's bit fields to every
//! object, and reads the materials' and lights' fields at the offsets the manifest gives, comparing
//! them with the values written in `examples/thesis_scene/scene.rt`.
//!
//! The producer half ([`thesis_buffers`]) uses rtc's types; the decoder half ([`Decoder`] and the
//! tests' bodies) uses none of them, as a host in another language would.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};

use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene, manifest::manifest_json};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::scene::{Entities, EntityOptions};
use serde_json::Value;

fn thesis_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/thesis_scene")
}

/// The manifest and every binding's bytes, as rtc's runtime would upload them.
fn thesis_buffers() -> (Value, HashMap<&'static str, Vec<u8>>) {
    let path = thesis_dir().join("scene.rt");
    let compiled = compile_scene(&[path], None, &Options::default(), &LinkOptions::default())
        .unwrap_or_else(|_| panic!("the thesis scene compiles"));
    let program = compiled.checked.program.as_ref().expect("program");
    let e = Entities::build(
        program,
        &program.scenes[compiled.scene],
        &compiled.linked,
        &EntityOptions::default(),
    )
    .expect("entities");
    let frame = e.frame_uniforms(1, 1);
    let mut buffers = HashMap::new();
    buffers.insert("frame", bytemuck::bytes_of(&frame).to_vec());
    buffers.insert("nodes", bytemuck::cast_slice(e.nodes()).to_vec());
    buffers.insert("instances", bytemuck::cast_slice(e.instances()).to_vec());
    buffers.insert("triangles", bytemuck::cast_slice(e.triangles()).to_vec());
    buffers.insert("attributes", bytemuck::cast_slice(e.attributes()).to_vec());
    buffers.insert("params", bytemuck::cast_slice(e.params()).to_vec());
    buffers.insert("texels", bytemuck::cast_slice(e.texels()).to_vec());
    let json = manifest_json(&compiled);
    (
        serde_json::from_str(&json).expect("the manifest is JSON"),
        buffers,
    )
}

/// Reads buffers with nothing but the manifest.
struct Decoder<'a> {
    m: &'a Value,
    buffers: &'a HashMap<&'static str, Vec<u8>>,
}

fn named<'v>(list: &'v Value, name: &str) -> &'v Value {
    list.as_array()
        .and_then(|a| a.iter().find(|v| v["name"] == name))
        .unwrap_or_else(|| panic!("the manifest lists no `{name}`"))
}

fn num(v: &Value) -> usize {
    v.as_u64().unwrap_or_else(|| panic!("{v} is not a number")) as usize
}

impl Decoder<'_> {
    fn constant(&self, name: &str) -> u32 {
        num(&named(&self.m["abi"]["constants"], name)["value"]) as u32
    }

    fn bits(&self, word: &str, field: &str) -> (u32, u32) {
        let f = named(&named(&self.m["abi"]["bit_fields"], word)["fields"], field);
        (num(&f["shift"]) as u32, num(&f["mask"]) as u32)
    }

    fn field(&self, word: u32, bits: (u32, u32)) -> u32 {
        (word >> bits.0) & bits.1
    }

    /// Byte offset of `field` in ABI struct `s`.
    fn struct_offset(&self, s: &str, field: &str) -> usize {
        num(&named(&named(&self.m["abi"]["structs"], s)["fields"], field)["offset"])
    }

    fn struct_size(&self, s: &str) -> usize {
        num(&named(&self.m["abi"]["structs"], s)["size"])
    }

    /// The render kernel's binding called `name`.
    fn binding(&self, name: &str) -> &Value {
        named(&self.m["kernels"][0]["bindings"], name)
    }

    fn u32_at(&self, binding: &str, byte: usize) -> u32 {
        let b = &self.buffers[binding];
        u32::from_le_bytes(b[byte..byte + 4].try_into().expect("4 bytes"))
    }

    fn f32_at(&self, binding: &str, byte: usize) -> f32 {
        f32::from_bits(self.u32_at(binding, byte))
    }

    fn vec3_at(&self, binding: &str, byte: usize) -> [f32; 3] {
        [0, 4, 8].map(|o| self.f32_at(binding, byte + o))
    }

    /// `frame.<field>`
    fn frame(&self, field: &str) -> u32 {
        let s = self.binding("frame")["element"]
            .as_str()
            .expect("struct name");
        self.u32_at("frame", self.struct_offset(s, field))
    }

    /// Element `i`'s field `field` of a struct-array binding.
    fn element_u32(&self, binding: &str, i: usize, field: &str) -> u32 {
        let b = self.binding(binding);
        let s = b["element"].as_str().expect("struct name");
        self.u32_at(
            binding,
            i * num(&b["element_size"]) + self.struct_offset(s, field),
        )
    }

    /// Byte offset of field `field` of record `record` at `address`.
    fn record_byte(&self, record: &str, address: usize, field: &str) -> usize {
        let r = named(&self.m["abi"]["records"], record);
        let element = num(&r["element_size"]);
        let offset = num(&named(&r["fields"], field)["offset"]);
        let index = match r["addressing"].as_str() {
            Some("word_offset") => address + offset,
            Some("slot") => address * num(&r["stride"]) + offset,
            other => panic!("unknown addressing {other:?}"),
        };
        index * element
    }

    fn record_u32(&self, record: &str, address: usize, field: &str) -> u32 {
        let r = named(&self.m["abi"]["records"], record);
        let binding = r["binding"].as_str().expect("binding").to_owned();
        self.u32_at(&binding, self.record_byte(record, address, field))
    }

    /// Every leaf `(first, count)` of the BVH whose header is record `base`, walked through the
    /// manifest's node views and reference bits.
    fn leaves(&self, base: usize) -> Vec<(u32, u32)> {
        let record = num(&self.binding("nodes")["element_size"]);
        assert_eq!(record, self.struct_size("NodeHeader"));
        assert_eq!(record, self.struct_size("NodeInner"));
        let leaf = self.bits("node_reference", "leaf");
        let first = self.bits("node_reference", "first");
        let count = self.bits("node_reference", "count");
        let root = self.u32_at(
            "nodes",
            base * record + self.struct_offset("NodeHeader", "root"),
        );
        let mut out = Vec::new();
        let mut stack = vec![root];
        while let Some(r) = stack.pop() {
            if self.field(r, leaf) != 0 {
                out.push((self.field(r, first), self.field(r, count)));
                continue;
            }
            assert!(r >= 1, "an inner reference is a record index >= 1");
            let at = (base + r as usize) * record;
            for side in ["left", "right"] {
                stack.push(self.u32_at("nodes", at + self.struct_offset("NodeInner", side)));
            }
        }
        out
    }

    /// The params layout of the type with id `id` and role `role`.
    fn layout(&self, role: &str, id: u32) -> &Value {
        self.m["params_layouts"]
            .as_array()
            .and_then(|a| {
                a.iter()
                    .find(|l| l["role"] == role && l["id"].as_u64() == Some(u64::from(id)))
            })
            .unwrap_or_else(|| panic!("no {role} layout with id {id}"))
    }

    /// Byte offset in `params` of field `field` of the instance at word `offset` of layout `l`.
    fn param_byte(&self, l: &Value, offset: u32, field: &str) -> usize {
        offset as usize * 4 + num(&named(&l["fields"], field)["offset"])
    }
}

/// The OBJ's vertices and triangles (the thesis bunny has only `v` and triangular `f` lines).
fn obj(path: &Path) -> (Vec<[f32; 3]>, Vec<[usize; 3]>) {
    let text = std::fs::read_to_string(path).expect("the OBJ file");
    let (mut v, mut f) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let mut w = line.split_whitespace();
        match w.next() {
            Some("v") => {
                let p: Vec<f32> = w.take(3).map(|x| x.parse().expect("a float")).collect();
                v.push([p[0], p[1], p[2]]);
            }
            Some("f") => {
                let i: Vec<usize> = w
                    .map(|x| {
                        x.split('/')
                            .next()
                            .expect("index")
                            .parse::<usize>()
                            .expect("an index")
                            - 1
                    })
                    .collect();
                assert_eq!(i.len(), 3, "a triangle");
                f.push([i[0], i[1], i[2]]);
            }
            _ => {}
        }
    }
    (v, f)
}

#[test]
fn the_thesis_scene_decodes_from_the_manifest_alone() {
    let (m, buffers) = thesis_buffers();
    let d = Decoder {
        m: &m,
        buffers: &buffers,
    };
    let instance_count = d.frame("instance_count") as usize;
    assert_eq!(instance_count, 18, "17 bunnies and the floor");
    assert_eq!(
        buffers["instances"].len(),
        instance_count * num(&d.binding("instances")["element_size"])
    );

    // Nodes: the scene-level BVH reaches every object exactly once.
    let mut reached = Vec::new();
    for (first, count) in d.leaves(d.frame("tlas_root") as usize) {
        reached.extend(first..first + count);
    }
    reached.sort_unstable();
    assert_eq!(reached, (0..instance_count as u32).collect::<Vec<_>>());

    // Triangles: each mesh BVH's slots hold the OBJ's triangles (the bunny) or the floor quad's.
    let (vertices, faces) = obj(&thesis_dir().join("bunny-6k.obj"));
    let mesh_geometry = d.constant("MESH_GEOMETRY");
    let (mut bunnies, mut floors) = (Vec::new(), Vec::new());
    for slot in 0..instance_count {
        assert_eq!(
            d.element_u32("instances", slot, "geometry_type"),
            mesh_geometry
        );
        let base = d.element_u32("instances", slot, "triangle_offset") as usize;
        let mut triangles = BTreeSet::new();
        for (first, count) in d.leaves(d.element_u32("instances", slot, "blas_root") as usize) {
            for s in first..first + count {
                let s = base + s as usize;
                // The triangle's index in its mesh: the bits of v0.w.
                let t = d.u32_at("triangles", d.record_byte("triangle", s, "v0") + 12);
                triangles.insert(t);
                // Its attributes are in the same slot of `attributes`.
                assert!(d.record_byte("attribute", s, "uv12") < buffers["attributes"].len());
            }
        }
        if triangles.len() == faces.len() {
            bunnies.push(slot);
        } else {
            assert_eq!(triangles.len(), 2, "the floor quad");
            floors.push(slot);
        }
    }
    assert_eq!((bunnies.len(), floors.len()), (17, 1));
    // A bunny's slots hold the OBJ's triangles: positions equal to its faces' vertices.
    let slot = bunnies[0];
    let base = d.element_u32("instances", slot, "triangle_offset") as usize;
    let mut matched = 0;
    for (first, count) in d.leaves(d.element_u32("instances", slot, "blas_root") as usize) {
        for s in first..first + count {
            let s = base + s as usize;
            let t = d.u32_at("triangles", d.record_byte("triangle", s, "v0") + 12) as usize;
            let v: Vec<[f32; 3]> = ["v0", "v1", "v2"]
                .iter()
                .map(|f| d.vec3_at("triangles", d.record_byte("triangle", s, f)))
                .collect();
            assert_eq!(v, faces[t].map(|i| vertices[i]), "slot {s}: triangle {t}");
            matched += 1;
        }
    }
    assert!(matched >= faces.len());

    // Materials: the bunnies' BlinnPhong and the floor's, at the offsets the manifest gives.
    let material = |slot: usize| {
        let id = d.element_u32("instances", slot, "material_type");
        let l = d.layout("material", id);
        assert_eq!(l["name"], "BlinnPhong");
        (l, d.element_u32("instances", slot, "material_offset"))
    };
    for &slot in &bunnies {
        let (l, at) = material(slot);
        assert_eq!(
            d.vec3_at("params", d.param_byte(l, at, "diffuse")),
            [0.75; 3]
        );
        assert_eq!(
            d.vec3_at("params", d.param_byte(l, at, "specular")),
            [0.15; 3]
        );
        assert_eq!(d.f32_at("params", d.param_byte(l, at, "shininess")), 40.0);
    }
    let (l, at) = material(floors[0]);
    assert_eq!(
        d.vec3_at("params", d.param_byte(l, at, "specular")),
        [0.05; 3]
    );
    assert_eq!(
        [0, 4].map(|o| d.f32_at("params", d.param_byte(l, at, "uv_scale") + o)),
        [20.0; 2]
    );
    // Its texture: the record the `texture` field names holds checker.png's size and format (the
    // 8-bit sRGB image stored decoded, as linear half floats: two words a texel), and its texels
    // lie inside `texels`.
    let texture = d.u32_at("params", d.param_byte(l, at, "texture")) as usize;
    let png = std::fs::read(thesis_dir().join("checker.png")).expect("checker.png");
    let be = |o: usize| u32::from_be_bytes(png[o..o + 4].try_into().expect("4 bytes"));
    assert_eq!(d.record_u32("texture", texture, "width"), be(16));
    assert_eq!(d.record_u32("texture", texture, "height"), be(20));
    assert_eq!(
        d.record_u32("texture", texture, "format"),
        d.constant("TEXTURE_FORMAT_RGBA16F")
    );
    let texel_base = d.record_u32("texture", texture, "texel_base") as usize;
    assert!((texel_base + 2 * (be(16) * be(20)) as usize) * 4 <= buffers["texels"].len());

    // Lights: the light table's entries name the two PointLights in scene order.
    assert_eq!(d.frame("light_count"), 2);
    let table = d.frame("light_table") as usize;
    let stride = num(&named(&m["abi"]["records"], "light_entry")["stride"]);
    let want = [([-0.8, 1.5, 0.8], 2.0), ([0.9, 1.2, -0.5], 2.0)];
    for (i, (position, intensity)) in want.into_iter().enumerate() {
        let entry = table + i * stride;
        let l = d.layout("light", d.record_u32("light_entry", entry, "type_id"));
        assert_eq!(l["name"], "PointLight");
        let at = d.record_u32("light_entry", entry, "offset");
        assert_eq!(
            d.vec3_at("params", d.param_byte(l, at, "position")),
            position
        );
        assert_eq!(
            d.f32_at("params", d.param_byte(l, at, "intensity")),
            intensity
        );
    }
}
