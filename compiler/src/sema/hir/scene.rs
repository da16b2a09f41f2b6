//! The checked scene description: what a `scene` item evaluates to (spec/scenes.md).
//!
//! Invariants (in a program without errors): every [`Instance`] is of a struct whose role fits its
//! place (camera, background, light, material, custom geometry), with every field evaluated in
//! declaration order; transforms are column-major object-to-world matrices; asset paths are resolved
//! relative to the scene's file.

use super::{ConstValue, MeshAsset, ModuleId, StructId, TextureAsset};
use crate::source::Span;
use std::collections::BTreeSet;
use std::path::PathBuf;

/// A role struct's instance in a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// The struct.
    pub struct_id: StructId,
    /// Every field's value, in declaration order (defaults filled in).
    pub fields: Vec<ConstValue>,
    /// Where the instance was written.
    pub span: Span,
}

/// A scene's settings, with defaults filled in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// Samples per pixel, in total.
    pub samples: u32,
    /// Generations of secondary rays below a camera ray.
    pub max_depth: u32,
    /// Rays one `@secondary_rays` call may spawn.
    pub max_rays_per_hit: u32,
    /// Depth of the first ray that the path loop's Russian roulette may end (0: never).
    pub roulette_depth: u32,
    /// Seed of the random numbers.
    pub seed: u32,
    /// The execution model: `EXEC_AUTO` (0), `EXEC_MEGAKERNEL` (1) or `EXEC_WAVEFRONT` (2), the
    /// prelude's constants.
    pub exec: u32,
    /// Frames per second of the scene's animation (spec/animation.md).
    pub fps: u32,
    /// Frames of the animation: as written, else enough to reach its last key (at least 1).
    pub frames: u32,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            width: 512,
            height: 512,
            samples: 1,
            max_depth: 4,
            max_rays_per_hit: 4,
            roulette_depth: 2,
            seed: 0,
            exec: 0,
            fps: 24,
            frames: 1,
        }
    }
}

/// An object's geometry.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// A triangle mesh (built-in geometry).
    Mesh(MeshAsset),
    /// An instance of a `@geometry` struct.
    Custom(Instance),
}

/// An object of a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Its name, if given.
    pub name: Option<String>,
    /// Its geometry.
    pub geometry: Geometry,
    /// Its material.
    pub material: Instance,
    /// Object to world, column-major (`transform[c][r]`).
    pub transform: [[f32; 4]; 4],
    /// The entry.
    pub span: Span,
}

/// A glTF file imported by a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    /// The path, resolved relative to the scene's file.
    pub path: PathBuf,
    /// Applied to the whole file, column-major.
    pub transform: [[f32; 4]; 4],
    /// The string in the scene.
    pub span: Span,
}

/// A checked, evaluated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// Its name.
    pub name: String,
    /// The module declaring it.
    pub module: ModuleId,
    /// The span of its name.
    pub span: Span,
    /// Settings.
    pub settings: Settings,
    /// The camera; `None` only when a `model` is expected to bring one.
    pub camera: Option<Instance>,
    /// The background, if any.
    pub background: Option<Instance>,
    /// Objects in order.
    pub objects: Vec<Object>,
    /// Lights in order.
    pub lights: Vec<Instance>,
    /// glTF models in order.
    pub models: Vec<Model>,
    /// The animation's tracks, in the order of the `animate` entries (spec/animation.md).
    pub animation: Vec<Track>,
}

impl SceneDesc {
    /// Every file the scene loads at render time: meshes, images and glTF models, as the
    /// compiler resolved them (relative to the scene's folder, not yet confined). The files a
    /// glTF model names itself are not among them.
    pub fn asset_files(&self) -> BTreeSet<PathBuf> {
        fn value(v: &ConstValue, out: &mut BTreeSet<PathBuf>) {
            match v {
                ConstValue::Mesh(MeshAsset::File { path, .. })
                | ConstValue::Texture(TextureAsset::File { path, .. }) => {
                    out.insert(path.clone());
                }
                ConstValue::Array(items) => items.iter().for_each(|i| value(i, out)),
                ConstValue::Struct { fields, .. } => fields.iter().for_each(|f| value(f, out)),
                _ => {}
            }
        }
        let mut out = BTreeSet::new();
        let instances = self
            .camera
            .iter()
            .chain(&self.background)
            .chain(&self.lights)
            .chain(self.objects.iter().map(|o| &o.material));
        for i in instances {
            i.fields.iter().for_each(|f| value(f, &mut out));
        }
        for o in &self.objects {
            match &o.geometry {
                Geometry::Mesh(MeshAsset::File { path, .. }) => {
                    out.insert(path.clone());
                }
                Geometry::Custom(i) => i.fields.iter().for_each(|f| value(f, &mut out)),
                Geometry::Mesh(_) => {}
            }
        }
        out.extend(self.models.iter().map(|m| m.path.clone()));
        out
    }
}

/// What a [`Track`] moves or changes.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackTarget {
    /// Object `objects[i]`'s transform.
    Object(usize),
    /// A field of the camera, by index in its struct.
    Camera {
        /// The field's index.
        field: usize,
        /// Its name.
        name: String,
    },
    /// A field of the background, by index in its struct.
    Background {
        /// The field's index.
        field: usize,
        /// Its name.
        name: String,
    },
    /// A field of `lights[light]`.
    Light {
        /// The light's index.
        light: usize,
        /// The field's index.
        field: usize,
        /// Its name.
        name: String,
    },
}

/// How a keyed track goes from one key to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// Straight lines (transforms: translation and scale lerped, rotation slerped).
    Linear,
    /// Each key's value holds until the next key.
    Step,
    /// Catmull-Rom curves through the keys (transforms: the rotation slerped on an eased
    /// parameter).
    Smooth,
}

/// A track's change over time.
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// Values at times: at least one key, times finite, `>= 0` and strictly increasing; every
    /// value of the target's type (a `mat4x4f` motion for an object). Before the first key the
    /// first value holds, after the last the last.
    Keys {
        /// Seconds.
        times: Vec<f32>,
        /// One value per time.
        values: Vec<ConstValue>,
        /// Between keys.
        interp: Interp,
    },
    /// Turning about `axis` (unit length) through the object's `pivot`: `degrees_per_second × t`.
    Spin {
        /// Unit axis, world space.
        axis: [f32; 3],
        /// Degrees per second.
        degrees_per_second: f32,
        /// The point the axis goes through, in object space (the origin unless given).
        pivot: [f32; 3],
    },
    /// Moving by `velocity × t` (an object's position, or a `vec3f` field's value).
    Move {
        /// Units per second.
        velocity: [f32; 3],
    },
}

/// One `animate` entry: a target and its motion.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// What it changes.
    pub target: TrackTarget,
    /// How.
    pub motion: Motion,
    /// The entry.
    pub span: Span,
}

/// The identity transform.
pub const IDENTITY: [[f32; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// Why [`Program::select_scene`](crate::sema::hir::Program::select_scene) found no single scene.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneChoiceError {
    /// No scene in the checked files.
    NoScene,
    /// Several scenes and no name (E0706).
    Ambiguous {
        /// Every scene's name and span.
        scenes: Vec<(String, Span)>,
    },
    /// No scene with that name (E0706).
    NotFound {
        /// The name asked for.
        name: String,
        /// Every scene's name.
        available: Vec<String>,
    },
}
