//! A small writer of glTF test files: a binary buffer with accessors, the JSON around it, and
//! `.gltf` + `.bin` or `.glb` output.

use std::path::PathBuf;

use serde_json::{json, Map, Value};

use super::TempDir;

/// Accumulates one binary buffer and its buffer views and accessors.
#[derive(Default)]
pub(super) struct Builder {
    pub bin: Vec<u8>,
    pub views: Vec<Value>,
    pub accessors: Vec<Value>,
}

impl Builder {
    /// Appends `bytes` (4-byte aligned) as a buffer view; returns its index.
    pub fn view(&mut self, bytes: &[u8], stride: Option<usize>) -> usize {
        while self.bin.len() % 4 != 0 {
            self.bin.push(0);
        }
        let mut view =
            json!({ "buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len() });
        if let Some(stride) = stride {
            view["byteStride"] = json!(stride);
        }
        self.bin.extend_from_slice(bytes);
        self.views.push(view);
        self.views.len() - 1
    }

    /// Appends an accessor as given; returns its index.
    pub fn accessor(&mut self, accessor: Value) -> usize {
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    /// A `VEC3` of `F32` accessor (with the `min`/`max` glTF requires for positions).
    pub fn vec3(&mut self, data: &[[f32; 3]]) -> usize {
        let bytes: Vec<u8> = data
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let view = self.view(&bytes, None);
        let mut min = [f32::INFINITY; 3];
        let mut max = [f32::NEG_INFINITY; 3];
        for p in data {
            for k in 0..3 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        self.accessor(json!({
            "bufferView": view, "componentType": 5126, "count": data.len(), "type": "VEC3",
            "min": min, "max": max,
        }))
    }

    /// A `VEC2` of `F32` accessor.
    pub fn vec2(&mut self, data: &[[f32; 2]]) -> usize {
        let bytes: Vec<u8> = data
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let view = self.view(&bytes, None);
        self.accessor(json!({
            "bufferView": view, "componentType": 5126, "count": data.len(), "type": "VEC2",
        }))
    }

    /// A `SCALAR` of `U16` index accessor.
    pub fn indices_u16(&mut self, data: &[u16]) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|c| c.to_le_bytes()).collect();
        let view = self.view(&bytes, None);
        self.accessor(json!({
            "bufferView": view, "componentType": 5123, "count": data.len(), "type": "SCALAR",
        }))
    }

    /// The JSON document: `rest` (meshes, nodes, …) plus asset, buffer, views and accessors.
    /// `uri` is the buffer's URI (`None` in a `.glb`).
    pub fn document(&self, uri: Option<&str>, rest: Value) -> Value {
        let mut buffer = json!({ "byteLength": self.bin.len() });
        if let Some(uri) = uri {
            buffer["uri"] = json!(uri);
        }
        let mut doc = Map::new();
        doc.insert(
            "asset".into(),
            json!({ "version": "2.0", "generator": "rtc tests" }),
        );
        if !self.bin.is_empty() {
            doc.insert("buffers".into(), json!([buffer]));
            doc.insert("bufferViews".into(), Value::Array(self.views.clone()));
            doc.insert("accessors".into(), Value::Array(self.accessors.clone()));
        }
        if let Value::Object(rest) = rest {
            doc.extend(rest);
        }
        Value::Object(doc)
    }

    /// Writes `name.gltf` and `name.bin` into `dir`; returns the `.gltf` path.
    pub fn write_gltf(&self, dir: &TempDir, name: &str, rest: Value) -> PathBuf {
        let bin_name = format!("{name}.bin");
        dir.write(&bin_name, &self.bin);
        let doc = self.document(Some(&bin_name), rest);
        dir.write(
            &format!("{name}.gltf"),
            serde_json::to_vec_pretty(&doc).unwrap(),
        )
    }

    /// The `.glb` bytes of the document with the buffer as the binary chunk.
    pub fn glb(&self, rest: Value) -> Vec<u8> {
        glb_bytes(&self.document(None, rest), Some(&self.bin))
    }
}

/// A `.glb` container around a JSON document and an optional binary chunk.
pub(super) fn glb_bytes(doc: &Value, bin: Option<&[u8]>) -> Vec<u8> {
    let mut json = serde_json::to_vec(doc).unwrap();
    while json.len() % 4 != 0 {
        json.push(b' ');
    }
    let mut chunks = Vec::new();
    chunks.extend_from_slice(&(json.len() as u32).to_le_bytes());
    chunks.extend_from_slice(b"JSON");
    chunks.extend_from_slice(&json);
    if let Some(bin) = bin {
        let mut bin = bin.to_vec();
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        chunks.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        chunks.extend_from_slice(b"BIN\0");
        chunks.extend_from_slice(&bin);
    }
    let mut out = Vec::new();
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&((12 + chunks.len()) as u32).to_le_bytes());
    out.extend_from_slice(&chunks);
    out
}

/// Standard base64 with padding, for `data:` URIs.
pub(super) fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The triangle (0,0,0), (1,0,0), (0,1,0) with `u16` indices: (builder, POSITION, indices).
pub(super) fn triangle() -> (Builder, usize, usize) {
    let mut b = Builder::default();
    let pos = b.vec3(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let idx = b.indices_u16(&[0, 1, 2]);
    (b, pos, idx)
}

/// A document with one mesh (given primitives) on one node in one scene.
pub(super) fn one_node(primitives: Value) -> Value {
    json!({
        "meshes": [{ "name": "m", "primitives": primitives }],
        "nodes": [{ "mesh": 0 }],
        "scenes": [{ "nodes": [0] }],
        "scene": 0,
    })
}

/// A small PNG: 2×1, red then half-transparent green.
pub(super) fn small_png() -> Vec<u8> {
    let img: image::RgbaImage =
        image::ImageBuffer::from_raw(2, 1, vec![255, 0, 0, 255, 0, 255, 0, 128]).unwrap();
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .unwrap();
    bytes
}

/// The words of [`small_png`].
pub(super) const SMALL_PNG_WORDS: [u32; 2] = [0xff00_00ff, 0x8000_ff00];
