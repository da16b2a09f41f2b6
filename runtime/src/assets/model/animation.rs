//! glTF node animation (`animations`) → [`NodeAnimation`]: the channels of the file's first
//! animation, read once at import, evaluated at any time as rigid node motion.
//!
//! What is imported: `translation`, `rotation` and `scale` channels with `STEP`, `LINEAR` and
//! `CUBICSPLINE` interpolation, exactly as the glTF 2.0 specification (§3.11, Appendix C)
//! defines them: before the first key the first value holds, after the last key the last; `LINEAR`
//! rotations are slerped along the shorter arc; `CUBICSPLINE` is the Hermite spline of the keys'
//! in- and out-tangents scaled by the key interval, its rotations normalised. What is not: `weights`
//! channels (morph targets are not imported), channels that target a node with a `matrix` (the
//! specification forbids it), nodes outside the rendered scene, and every animation after the
//! first (a file's animations are alternative clips; rtc plays the first). Each is a warning
//! naming the animation and channel.
//!
//! Invariants: [`NodeAnimation::evaluate`] is pure (the same time gives the same bits, whatever was
//! evaluated before), so frames can be rendered in any order or in several processes. A node's
//! world transform at time `t` is its parent's at `t` times its local one, the local one built from
//! the rest translation, rotation and scale with the animated ones replacing them; nodes that no
//! channel moves (and whose ancestors none moves) keep the world transform of the static import.
//! Key times are finite and strictly increasing and each output has the count its interpolation
//! needs (a sampler that breaks this is skipped with a warning, never a panic), so [`sample`] never
//! indexes out of range.

use glam::{Mat4, Quat, Vec3, Vec4};
use gltf::json;
use gltf::json::accessor::{ComponentType, Type};
use gltf::json::animation::{Interpolation as JsonInterp, Property};
use gltf::json::validation::Checked;

use super::accessor::{self, Expect};
use super::Ctx;

/// What a channel animates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Path {
    /// The node's translation (3 components).
    Translation,
    /// The node's rotation, a unit quaternion `x, y, z, w`.
    Rotation,
    /// The node's scale (3 components).
    Scale,
}

/// How a channel goes from one key to the next (glTF `interpolation`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// Each key's value holds until the next key.
    Step,
    /// Straight lines; rotations slerped.
    Linear,
    /// Hermite spline with the keys' tangents.
    CubicSpline,
}

/// One animated property of one node.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// The glTF node.
    pub node: usize,
    /// The property.
    pub path: Path,
    /// The interpolation.
    pub interp: Interp,
    /// Key times in seconds, finite and strictly increasing, at least one.
    pub times: Vec<f32>,
    /// Values (4 components; the 4th unused for translation and scale): one per key, or for
    /// [`Interp::CubicSpline`] three per key (in-tangent, value, out-tangent).
    pub values: Vec<[f32; 4]>,
}

/// A node's place in the hierarchy and its rest transform.
#[derive(Clone, Debug, PartialEq)]
struct NodeRest {
    parent: Option<usize>,
    /// `None` for a node given by `matrix` (which no channel may move).
    trs: Option<(Vec3, Quat, Vec3)>,
    /// The rest local transform.
    local: Mat4,
}

/// The file's first animation, ready to evaluate.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeAnimation {
    /// `animations[0] (`name`)`, for messages.
    pub label: String,
    /// The imported channels.
    pub channels: Vec<Channel>,
    /// The last key time of all channels, in seconds (0 for a single-key animation).
    pub duration: f32,
    /// Every glTF node (the scene's ones with their parent; others parentless, unused).
    nodes: Vec<NodeRest>,
    /// The scene's nodes in the walk's order (each after its parent).
    order: Vec<usize>,
    /// Whether each node's world transform depends on the animation (a channel moves it or an
    /// ancestor).
    moves: Vec<bool>,
}

impl NodeAnimation {
    /// Whether node `node`'s world transform changes over time.
    pub fn moves(&self, node: usize) -> bool {
        self.moves.get(node).copied().unwrap_or(false)
    }

    /// The world transform of every node at `t` seconds (index = glTF node; nodes outside the
    /// scene get their local transform).
    pub fn evaluate(&self, t: f32) -> Vec<Mat4> {
        let mut local: Vec<Mat4> = self.nodes.iter().map(|n| n.local).collect();
        // The animated parts of each node's TRS, applied over its rest TRS.
        let mut trs: Vec<Option<(Vec3, Quat, Vec3)>> = vec![None; self.nodes.len()];
        for c in &self.channels {
            let Some(rest) = self.nodes.get(c.node).and_then(|n| n.trs) else {
                continue;
            };
            let Some(slot) = trs.get_mut(c.node) else {
                continue;
            };
            let (tr, r, s) = slot.get_or_insert(rest);
            let v = sample(c, t);
            match c.path {
                Path::Translation => *tr = Vec3::new(v[0], v[1], v[2]),
                Path::Scale => *s = Vec3::new(v[0], v[1], v[2]),
                Path::Rotation => *r = Quat::from_array(v).normalize(),
            }
        }
        for (l, parts) in local.iter_mut().zip(&trs) {
            if let Some((tr, r, s)) = parts {
                *l = Mat4::from_scale_rotation_translation(*s, *r, *tr);
            }
        }
        // Parents first (the walk's order), so a parent's world transform is final before its
        // children use it.
        let mut world = local;
        for &n in &self.order {
            let parent = self
                .nodes
                .get(n)
                .and_then(|r| r.parent)
                .and_then(|p| world.get(p).copied());
            if let (Some(p), Some(w)) = (parent, world.get_mut(n)) {
                *w = p * *w;
            }
        }
        world
    }
}

/// A channel's value at `t` (4 components; rotations are unit quaternions `x, y, z, w`).
pub fn sample(c: &Channel, t: f32) -> [f32; 4] {
    let n = c.times.len();
    let value = |k: usize| -> Vec4 {
        let i = if c.interp == Interp::CubicSpline {
            3 * k + 1
        } else {
            k
        };
        Vec4::from_array(c.values.get(i).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]))
    };
    let finish = |v: Vec4| -> [f32; 4] {
        if c.path == Path::Rotation {
            v.normalize_or(Vec4::W).to_array()
        } else {
            v.to_array()
        }
    };
    let (Some(&first), Some(&last)) = (c.times.first(), c.times.last()) else {
        return finish(value(0));
    };
    if t <= first {
        return finish(value(0));
    }
    if t >= last {
        return finish(value(n - 1));
    }
    // times[k] <= t < times[k + 1], with k + 1 < n.
    let k = c
        .times
        .partition_point(|&x| x <= t)
        .saturating_sub(1)
        .min(n.saturating_sub(2));
    let (t0, t1) = match (c.times.get(k), c.times.get(k + 1)) {
        (Some(&a), Some(&b)) => (a, b),
        _ => return finish(value(n - 1)),
    };
    let dt = t1 - t0;
    let u = ((t - t0) / dt).clamp(0.0, 1.0);
    match c.interp {
        Interp::Step => finish(value(k)),
        Interp::Linear => {
            let (a, b) = (value(k), value(k + 1));
            if c.path == Path::Rotation {
                slerp(a, b, u).to_array()
            } else {
                a.lerp(b, u).to_array()
            }
        }
        Interp::CubicSpline => {
            let get = |i: usize| Vec4::from_array(c.values.get(i).copied().unwrap_or([0.0; 4]));
            let (v0, b0) = (get(3 * k + 1), get(3 * k + 2));
            let (a1, v1) = (get(3 * (k + 1)), get(3 * (k + 1) + 1));
            let (u2, u3) = (u * u, u * u * u);
            let p = v0 * (2.0 * u3 - 3.0 * u2 + 1.0)
                + b0 * (dt * (u3 - 2.0 * u2 + u))
                + v1 * (-2.0 * u3 + 3.0 * u2)
                + a1 * (dt * (u3 - u2));
            finish(p)
        }
    }
}

/// Spherical linear interpolation of unit quaternions along the shorter arc (`f32` `acos`, not
/// an approximation, so that tests can hold it to a tight tolerance).
fn slerp(a: Vec4, b: Vec4, u: f32) -> Vec4 {
    let a = a.normalize_or(Vec4::W);
    let mut b = b.normalize_or(Vec4::W);
    let mut dot = a.dot(b);
    if dot < 0.0 {
        b = -b;
        dot = -dot;
    }
    if dot > 0.9995 {
        return a.lerp(b, u).normalize_or(Vec4::W);
    }
    let theta = dot.clamp(-1.0, 1.0).acos();
    let s = theta.sin();
    (a * ((1.0 - u) * theta).sin() / s + b * (u * theta).sin() / s).normalize_or(Vec4::W)
}

const INPUT: Expect = Expect {
    usage: "animation sampler input",
    description: "SCALAR of F32",
    ty: Type::Scalar,
    component: |c, _| c == ComponentType::F32,
};
const VEC3_OUTPUT: Expect = Expect {
    usage: "translation or scale animation output",
    description: "VEC3 of F32",
    ty: Type::Vec3,
    component: |c, _| c == ComponentType::F32,
};
const ROTATION_OUTPUT: Expect = Expect {
    usage: "rotation animation output",
    description: "VEC4 of F32, or of normalized I8, U8, I16 or U16",
    ty: Type::Vec4,
    component: |c, normalized| {
        c == ComponentType::F32
            || (normalized
                && matches!(
                    c,
                    ComponentType::I8 | ComponentType::U8 | ComponentType::I16 | ComponentType::U16
                ))
    },
};

/// Reads the file's first animation. `parents` and `order` come from the scene walk (each scene
/// node's parent, and the scene's nodes in the order visited, each after its parent). `None` when the file has no
/// animation or none of its channels could be imported (each reason a warning).
pub(super) fn read(
    ctx: &Ctx<'_>,
    parents: &[Option<usize>],
    order: &[usize],
    warnings: &mut Vec<String>,
) -> Option<NodeAnimation> {
    let root = ctx.root;
    let first = root.animations.first()?;
    let label = |i: usize, a: &json::Animation| match &a.name {
        Some(name) => format!("animations[{i}] (`{name}`)"),
        None => format!("animations[{i}]"),
    };
    let label0 = label(0, first);
    if root.animations.len() > 1 {
        let others: Vec<String> = root
            .animations
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, a)| label(i, a))
            .collect();
        warnings.push(format!(
            "{} not played: rtc plays a file's first animation ({label0})",
            others.join(", ")
        ));
    }

    let nodes: Vec<NodeRest> = root
        .nodes
        .iter()
        .enumerate()
        .map(|(n, node)| {
            let trs = if node.matrix.is_some() {
                None
            } else {
                let r = node.rotation.map_or(Quat::IDENTITY, |q| {
                    let q = Quat::from_array(q.0);
                    if q.is_finite() && q.length_squared() > 0.0 {
                        q.normalize()
                    } else {
                        Quat::IDENTITY
                    }
                });
                Some((
                    Vec3::from(node.translation.unwrap_or([0.0; 3])),
                    r,
                    Vec3::from(node.scale.unwrap_or([1.0; 3])),
                ))
            };
            let local = match (node.matrix, trs) {
                (Some(m), _) => Mat4::from_cols_array(&m),
                (None, Some((t, r, s))) => Mat4::from_scale_rotation_translation(s, r, t),
                (None, None) => Mat4::IDENTITY,
            };
            NodeRest {
                parent: parents.get(n).copied().flatten(),
                trs,
                local,
            }
        })
        .collect();

    let mut channels = Vec::new();
    for (c, channel) in first.channels.iter().enumerate() {
        let what = format!("{label0}.channels[{c}]");
        let node = channel.target.node.value();
        let path = match channel.target.path {
            Checked::Valid(Property::Translation) => Path::Translation,
            Checked::Valid(Property::Rotation) => Path::Rotation,
            Checked::Valid(Property::Scale) => Path::Scale,
            Checked::Valid(Property::MorphTargetWeights) => {
                warnings.push(format!(
                    "{what}: animates the morph target weights of nodes[{node}], which are not \
                     imported; skipped"
                ));
                continue;
            }
            Checked::Invalid => {
                warnings.push(format!("{what}: unknown target path, skipped"));
                continue;
            }
        };
        if !order.contains(&node) {
            warnings.push(format!(
                "{what}: nodes[{node}] is not in the rendered scene; skipped"
            ));
            continue;
        }
        if nodes.get(node).is_some_and(|n| n.trs.is_none()) {
            warnings.push(format!(
                "{what}: nodes[{node}] is given by a `matrix`, which glTF forbids animating; skipped"
            ));
            continue;
        }
        let Some(sampler) = first.samplers.get(channel.sampler.value()) else {
            continue; // validated: cannot happen
        };
        let interp = match sampler.interpolation {
            Checked::Valid(JsonInterp::Step) => Interp::Step,
            Checked::Valid(JsonInterp::Linear) => Interp::Linear,
            Checked::Valid(JsonInterp::CubicSpline) => Interp::CubicSpline,
            Checked::Invalid => {
                warnings.push(format!("{what}: unknown interpolation, skipped"));
                continue;
            }
        };
        match read_channel(ctx, sampler, node, path, interp) {
            Ok(ch) => channels.push(ch),
            Err(why) => warnings.push(format!("{what}: {why}; skipped")),
        }
    }
    if channels.is_empty() {
        return None;
    }

    let mut moves = vec![false; nodes.len()];
    for c in &channels {
        if let Some(m) = moves.get_mut(c.node) {
            *m = true;
        }
    }
    // Descendants follow (parents come first in `order`).
    for &n in order {
        let parent_moves = nodes
            .get(n)
            .and_then(|r| r.parent)
            .and_then(|p| moves.get(p).copied())
            .unwrap_or(false);
        if let (true, Some(m)) = (parent_moves, moves.get_mut(n)) {
            *m = true;
        }
    }
    let duration = channels
        .iter()
        .filter_map(|c| c.times.last().copied())
        .fold(0.0f32, f32::max);
    Some(NodeAnimation {
        label: label0,
        channels,
        duration,
        nodes,
        order: order.to_vec(),
        moves,
    })
}

/// One channel's keys, checked: times finite, non-negative and strictly increasing, values finite
/// and as many as the interpolation needs.
fn read_channel(
    ctx: &Ctx<'_>,
    sampler: &json::animation::Sampler,
    node: usize,
    path: Path,
    interp: Interp,
) -> Result<Channel, String> {
    let times: Vec<f32> =
        accessor::read::<f32, 1>(ctx, sampler.input.value(), &INPUT, |x| x as f32)
            .map_err(|e| e.to_string())?
            .into_iter()
            .map(|[t]| t)
            .collect();
    if times.is_empty() {
        return Err("its sampler has no keys".to_owned());
    }
    if times.iter().any(|t| !t.is_finite() || *t < 0.0)
        || times.iter().zip(times.iter().skip(1)).any(|(a, b)| a >= b)
    {
        return Err("its key times are not finite, non-negative and increasing".to_owned());
    }
    let output = sampler.output.value();
    let values: Vec<[f32; 4]> = match path {
        Path::Rotation => accessor::read::<f32, 4>(ctx, output, &ROTATION_OUTPUT, |x| x as f32),
        Path::Translation | Path::Scale => {
            accessor::read::<f32, 3>(ctx, output, &VEC3_OUTPUT, |x| x as f32)
                .map(|v| v.into_iter().map(|[x, y, z]| [x, y, z, 0.0]).collect())
        }
    }
    .map_err(|e| e.to_string())?;
    let per_key = if interp == Interp::CubicSpline { 3 } else { 1 };
    if values.len() != times.len() * per_key {
        return Err(format!(
            "its sampler has {} output values for {} keys (expected {})",
            values.len(),
            times.len(),
            times.len() * per_key
        ));
    }
    if values.iter().flatten().any(|x| !x.is_finite()) {
        return Err("its output holds NaN or infinite values".to_owned());
    }
    Ok(Channel {
        node,
        path,
        interp,
        times,
        values,
    })
}
