//! The errors of the asset stage.
//!
//! Invariants: every [`AssetError`] variant names the file it is about (`path`), and, for a file
//! referenced from another (a glTF buffer or image), the referenced file too. Variants carry typed
//! data; the message is formatted once, by `Display`. [`MeshError`] is the file-less error of
//! [`MeshData::validate`](super::MeshData::validate); loaders wrap it in [`AssetError::Mesh`].

use std::fmt;
use std::path::PathBuf;

use gltf::json::validation::Error as ValidationError;
pub use rtc_compiler::confine::PathProblem;

/// Why an asset could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum AssetError {
    /// The file itself could not be read.
    #[error("{}: cannot read the file: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// A file referenced by the asset (a glTF buffer or image) could not be read.
    #[error("{}: {item} refers to `{}`, which cannot be read: {source}", path.display(), file.display())]
    MissingFile {
        /// The referring file.
        path: PathBuf,
        /// What refers to it.
        item: GltfItem,
        /// The referenced file, as resolved against the referring file's folder.
        file: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The file is not in a format this loader reads.
    #[error("{}: unsupported format: {found}", path.display())]
    UnsupportedFormat {
        /// The file.
        path: PathBuf,
        /// What was found instead.
        found: String,
    },
    /// An OBJ file could not be parsed.
    #[error("{}{}: {source}", path.display(), line.map(|l| format!(":{l}")).unwrap_or_default())]
    Obj {
        /// The file.
        path: PathBuf,
        /// The 1-based line, when known.
        line: Option<usize>,
        /// The parser's error.
        source: tobj::LoadError,
    },
    /// An OBJ face refers to a vertex, texture coordinate or normal that does not exist.
    #[error(
        "{}:{line}: face index {index} refers to {kind} that does not exist (only {count} available)",
        path.display()
    )]
    ObjIndex {
        /// The file.
        path: PathBuf,
        /// The 1-based line.
        line: usize,
        /// The index as written (1-based, or negative for relative).
        index: i64,
        /// `"a position"`, `"a texture coordinate"` or `"a normal"`.
        kind: &'static str,
        /// How many of that kind there are (before this line, for a relative index).
        count: usize,
    },
    /// A glTF JSON document is not valid JSON, or does not have glTF's shape.
    #[error("{}:{}:{}: bad glTF JSON: {source}", path.display(), source.line(), source.column())]
    BadJson {
        /// The file.
        path: PathBuf,
        /// The JSON error (it knows its line and column).
        source: serde_json::Error,
    },
    /// A glTF document is well-formed JSON but breaks glTF's rules (index out of bounds, missing
    /// required property, unsupported required extension, …).
    #[error("{}: invalid glTF: {}", path.display(), ProblemList(problems))]
    InvalidGltf {
        /// The file.
        path: PathBuf,
        /// Each problem: the JSON path (`meshes[0].primitives[0].indices`) and what is wrong.
        problems: Vec<(String, ValidationError)>,
    },
    /// A `.glb` container is truncated or corrupt.
    #[error("{}: bad .glb file: {problem}", path.display())]
    Glb {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        problem: GlbProblem,
    },
    /// A glTF URI cannot be resolved.
    #[error("{}: {item}: bad URI `{uri}`: {problem}", path.display())]
    Uri {
        /// The file.
        path: PathBuf,
        /// The buffer or image with the URI.
        item: GltfItem,
        /// The URI, shortened to 64 characters.
        uri: String,
        /// What is wrong.
        problem: UriProblem,
    },
    /// A path a scene or glTF file names leads outside the folders assets may be read from
    /// (see `confine.rs`).
    #[error("{}", EscapeMessage { path, item: *item, written, problem })]
    Escape {
        /// The referring file (the glTF file, or the scene file for `load_mesh`/`load_image`/`model`).
        path: PathBuf,
        /// The glTF buffer or image with the URI; `None` for a scene path.
        item: Option<GltfItem>,
        /// The path or URI as written (shortened to 200 characters).
        written: String,
        /// What is wrong (boxed: it is the largest part of the error).
        problem: Box<PathProblem>,
    },
    /// A glTF buffer holds fewer bytes than its `byteLength`.
    #[error("{}: {item} declares {declared} bytes but has {actual}", path.display())]
    BufferTooShort {
        /// The file.
        path: PathBuf,
        /// The buffer (or buffer view).
        item: GltfItem,
        /// Bytes declared.
        declared: u64,
        /// Bytes present.
        actual: u64,
    },
    /// A glTF accessor or buffer view reaches outside the data it refers to.
    #[error("{}: {item} needs bytes up to {needed}, but only {available} are there", path.display())]
    AccessorOutOfRange {
        /// The file.
        path: PathBuf,
        /// The accessor, buffer view or image.
        item: GltfItem,
        /// The end of the byte range it needs.
        needed: u64,
        /// The bytes available.
        available: u64,
    },
    /// A glTF accessor's element counts do not fit: a sparse count above the accessor's count, a
    /// sparse index past its last element, or a view-less accessor with too many elements.
    #[error("{}: {item}: {problem}", path.display())]
    AccessorCount {
        /// The file.
        path: PathBuf,
        /// The accessor.
        item: GltfItem,
        /// What does not fit.
        problem: CountProblem,
    },
    /// A glTF accessor has the wrong element type for its use.
    #[error("{}: {item} used as {usage} has elements of type {found}, expected {expected}", path.display())]
    AccessorFormat {
        /// The file.
        path: PathBuf,
        /// The accessor.
        item: GltfItem,
        /// What it is used as (`POSITION`, `indices`, …).
        usage: &'static str,
        /// What it has (`VEC2 of U16`).
        found: String,
        /// What is accepted.
        expected: &'static str,
    },
    /// A glTF primitive's index refers to a vertex that does not exist.
    #[error("{}: {item}: index {index} is out of range ({vertex_count} vertices)", path.display())]
    IndexOutOfRange {
        /// The file.
        path: PathBuf,
        /// The primitive.
        item: GltfItem,
        /// The offending index.
        index: u32,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// A mesh failed [`MeshData::validate`](super::MeshData::validate).
    #[error("{}{}: {source}", path.display(), item.map(|i| format!(": {i}")).unwrap_or_default())]
    Mesh {
        /// The file.
        path: PathBuf,
        /// The glTF primitive, for meshes from glTF.
        item: Option<GltfItem>,
        /// What is wrong.
        source: MeshError,
    },
    /// An image is larger than [`MAX_TEXTURE_SIZE`](super::MAX_TEXTURE_SIZE) in a dimension.
    #[error("{}: the image is {width}x{height}, more than the limit of {max} texels per side", path.display())]
    ImageTooLarge {
        /// The file (for images inside a glTF file, `file.glb#images[i]`).
        path: PathBuf,
        /// Width in texels.
        width: u32,
        /// Height in texels.
        height: u32,
        /// The limit.
        max: u32,
    },
    /// An image could not be decoded (the codec's error, in words: never its debug text).
    #[error(
        "{}: cannot decode the image: {}",
        path.display(),
        super::texture::describe_image_error(source)
    )]
    ImageDecode {
        /// The file (for images inside a glTF file, `file.glb#images[i]`).
        path: PathBuf,
        /// The codec's error.
        source: image::ImageError,
    },
}

impl AssetError {
    /// The file the error is about.
    pub fn path(&self) -> &std::path::Path {
        match self {
            Self::Read { path, .. }
            | Self::MissingFile { path, .. }
            | Self::UnsupportedFormat { path, .. }
            | Self::Obj { path, .. }
            | Self::ObjIndex { path, .. }
            | Self::BadJson { path, .. }
            | Self::InvalidGltf { path, .. }
            | Self::Glb { path, .. }
            | Self::Uri { path, .. }
            | Self::Escape { path, .. }
            | Self::BufferTooShort { path, .. }
            | Self::AccessorOutOfRange { path, .. }
            | Self::AccessorCount { path, .. }
            | Self::AccessorFormat { path, .. }
            | Self::IndexOutOfRange { path, .. }
            | Self::Mesh { path, .. }
            | Self::ImageTooLarge { path, .. }
            | Self::ImageDecode { path, .. } => path,
        }
    }
}

/// Shows the first few validation problems of [`AssetError::InvalidGltf`].
struct ProblemList<'a>(&'a [(String, ValidationError)]);

impl fmt::Display for ProblemList<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const SHOWN: usize = 4;
        for (i, (at, what)) in self.0.iter().take(SHOWN).enumerate() {
            if i > 0 {
                f.write_str("; ")?;
            }
            write!(f, "{at}: {what}")?;
        }
        if self.0.len() > SHOWN {
            write!(f, "; and {} more", self.0.len() - SHOWN)?;
        }
        Ok(())
    }
}

/// A part of a glTF file, for error messages (`buffers[0]`, `meshes[2].primitives[1]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GltfItem {
    /// `buffers[i]`.
    Buffer(usize),
    /// `bufferViews[i]`.
    BufferView(usize),
    /// `accessors[i]`.
    Accessor(usize),
    /// `images[i]`.
    Image(usize),
    /// `textures[i]`.
    Texture(usize),
    /// `samplers[i]`.
    Sampler(usize),
    /// `materials[i]`.
    Material(usize),
    /// The base-colour image `images[image]` of `materials[material]`.
    BaseColorImage {
        /// The material.
        material: usize,
        /// The image.
        image: usize,
    },
    /// The image `images[image]` of texture `slot` of `materials[material]` (indices as `u32`,
    /// keeping errors small; a glTF file holds fewer than 2³² of either).
    MaterialImage {
        /// The material.
        material: u32,
        /// Which of its textures.
        slot: TextureSlot,
        /// The image.
        image: u32,
    },
    /// `meshes[mesh].primitives[primitive]`.
    Primitive {
        /// The mesh.
        mesh: usize,
        /// The primitive within it.
        primitive: usize,
    },
}

/// A texture of a glTF material other than the base colour (which has
/// [`GltfItem::BaseColorImage`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureSlot {
    /// `pbrMetallicRoughness.metallicRoughnessTexture`.
    MetallicRoughness,
    /// `emissiveTexture`.
    Emissive,
    /// `occlusionTexture`.
    Occlusion,
    /// `normalTexture`.
    Normal,
}

impl fmt::Display for TextureSlot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::MetallicRoughness => "metallic-roughness",
            Self::Emissive => "emissive",
            Self::Occlusion => "occlusion",
            Self::Normal => "normal",
        })
    }
}

impl fmt::Display for GltfItem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Buffer(i) => write!(f, "buffers[{i}]"),
            Self::BufferView(i) => write!(f, "bufferViews[{i}]"),
            Self::Accessor(i) => write!(f, "accessors[{i}]"),
            Self::Image(i) => write!(f, "images[{i}]"),
            Self::Texture(i) => write!(f, "textures[{i}]"),
            Self::Sampler(i) => write!(f, "samplers[{i}]"),
            Self::Material(i) => write!(f, "materials[{i}]"),
            Self::BaseColorImage { material, image } => {
                write!(
                    f,
                    "the base colour texture of materials[{material}] (images[{image}])"
                )
            }
            Self::MaterialImage {
                material,
                slot,
                image,
            } => {
                write!(
                    f,
                    "the {slot} texture of materials[{material}] (images[{image}])"
                )
            }
            Self::Primitive { mesh, primitive } => {
                write!(f, "meshes[{mesh}].primitives[{primitive}]")
            }
        }
    }
}

/// What is wrong with a `.glb` container.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GlbProblem {
    /// Shorter than the 12-byte header.
    #[error("the file has {0} bytes, shorter than the 12-byte header")]
    NoHeader(usize),
    /// A version other than 2.
    #[error("container version {0}, only version 2 is supported")]
    Version(u32),
    /// The header's length disagrees with the file.
    #[error("the header declares {declared} bytes but the file has {actual} (truncated?)")]
    Truncated {
        /// The length in the header.
        declared: u64,
        /// The file's length.
        actual: u64,
    },
    /// A chunk reaches past the end of the file.
    #[error("chunk {index} declares {declared} bytes but only {available} remain (truncated?)")]
    ChunkTooLong {
        /// The chunk's position (0 = the JSON chunk).
        index: usize,
        /// Its declared length.
        declared: u64,
        /// The bytes left.
        available: u64,
    },
    /// The first chunk is not the JSON chunk.
    #[error("the first chunk is not a JSON chunk")]
    NoJsonChunk,
}

/// What is wrong with the element counts of a glTF accessor (counts of elements, not bytes).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CountProblem {
    /// `sparse.count` is larger than the accessor's `count`.
    #[error("sparse.count is {sparse} elements, more than the accessor's {count} elements")]
    SparseCount {
        /// `sparse.count`.
        sparse: u64,
        /// The accessor's `count`.
        count: u64,
    },
    /// A sparse index names an element past the accessor's end.
    #[error(
        "sparse index {index} is past the accessor's last element (it has {count} elements, \
         indices 0 to {})",
        count.saturating_sub(1)
    )]
    SparseIndex {
        /// The index.
        index: u64,
        /// The accessor's `count`.
        count: u64,
    },
    /// An accessor without a `bufferView` (all zeros) with more elements than allowed.
    #[error(
        "it has no bufferView (all zeros) and {count} elements, more than the {max} such an \
         accessor may have"
    )]
    ViewlessTooLarge {
        /// The accessor's `count`.
        count: u64,
        /// The limit.
        max: u64,
    },
}

/// What is wrong with a glTF URI.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UriProblem {
    /// A `data:` URI that is not base64 or has bad base64.
    #[error("bad base64 data in a data: URI")]
    BadBase64,
    /// A scheme other than `data:` or a relative path.
    #[error("only relative paths and data: URIs are supported")]
    UnsupportedScheme,
    /// A `%xx` escape that is malformed or decodes to invalid UTF-8.
    #[error("bad percent-encoding")]
    BadPercentEncoding,
    /// A `.gltf` buffer without a URI (only `.glb` files have an embedded binary chunk).
    #[error("no URI and no .glb binary chunk to take the data from")]
    NoData,
}

/// How [`AssetError::Escape`] reads.
struct EscapeMessage<'a> {
    path: &'a PathBuf,
    item: Option<GltfItem>,
    written: &'a str,
    problem: &'a PathProblem,
}

impl fmt::Display for EscapeMessage<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.path.display())?;
        if let Some(item) = self.item {
            write!(f, "{item} ")?;
        }
        write!(
            f,
            "names `{}`, which {}; assets must be inside ",
            self.written, self.problem
        )?;
        let allowed = self.problem.allowed();
        if allowed.is_empty() {
            write!(
                f,
                "the folder of `{}` or a folder given with --asset-root",
                self.path.display()
            )
        } else {
            for (i, a) in allowed.iter().enumerate() {
                if i > 0 {
                    f.write_str(if i + 1 == allowed.len() { " or " } else { ", " })?;
                }
                write!(f, "`{}`", display_folder(a))?;
            }
            Ok(())
        }
    }
}

/// A folder for messages (`.` for the empty path).
pub(crate) fn display_folder(p: &std::path::Path) -> String {
    if p.as_os_str().is_empty() {
        ".".to_owned()
    } else {
        p.display().to_string()
    }
}

/// Why a [`MeshData`](super::MeshData) is invalid.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// A triangle refers to a vertex that does not exist.
    #[error(
        "triangle {triangle} refers to vertex {index}, but there are only {vertex_count} vertices"
    )]
    IndexOutOfRange {
        /// The triangle.
        triangle: usize,
        /// The vertex index.
        index: u32,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// A vertex position is NaN or infinite.
    #[error("vertex {vertex} has a non-finite position {position:?}")]
    NonFinitePosition {
        /// The vertex.
        vertex: usize,
        /// Its position.
        position: [f32; 3],
    },
    /// A per-vertex attribute has a different length than the positions.
    #[error("{attribute} has {found} entries for {expected} vertices")]
    AttributeCount {
        /// `"normals"` or `"uvs"`.
        attribute: &'static str,
        /// The number of positions.
        expected: usize,
        /// The attribute's length.
        found: usize,
    },
    /// More vertices than `u32` indices can address.
    #[error("{0} vertices are more than 32-bit indices can address")]
    TooManyVertices(usize),
}
