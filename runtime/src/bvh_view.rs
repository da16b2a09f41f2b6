//! CPU-side pictures and figures of a scene's BVHs, for `rtc bvh` (the BVH visualizer of the thesis,
//! section 4.2.4, Figs. 17–18) and `rtc bench --bvh-presets`.
//!
//! - [`collect_boxes`] walks the scene-level BVH (TLAS) and, below each of its leaves, the
//!   object-level BVH (BLAS) of every mesh instance, as one tree: a TLAS node at depth `d` has
//!   level `d`, and the BLAS root of an instance in a TLAS leaf at depth `d` has level `d + 1`.
//!   With an object chosen, only that object's BLAS is walked and its root is level 0. BLAS boxes
//!   keep their object-space corners and the instance's world-to-object transform, so a box drawn
//!   in world space is the exact transformed box (a parallelepiped), not a looser world AABB.
//! - [`wireframe`] draws the boxes' edges for a set of camera rays, one per pixel (the debug
//!   kernel's `RayOrigin` and `RayDirection` modes give them): a pixel is an edge pixel of a box
//!   where its ray passes within `line_px / 2` pixel widths of one of the box's 12 edges (the
//!   closest approach of the ray to the edge segment). The pixel width at distance `t` is
//!   measured from the neighbouring pixels' rays, so any camera (perspective or orthographic)
//!   gets lines of the same width on screen.
//!   Edges are drawn whether or not geometry hides them (the thesis's pictures do the same).
//! - [`heatmap`] turns the debug kernel's per-pixel counts (nodes visited, primitives tested) into
//!   two false-colour panels with a colour bar and labels (`0` and the maximum) under each, and
//!   [`HeatStats`] (maximum, mean) to print beside it.
//! - [`sah_cost`] computes the surface-area-heuristic cost of a BVH in the GPU node buffer (the
//!   quantised layout of `rtc_bvh::quantized`), the figure `rtc_bvh::Bvh::sah_cost` reports for a
//!   canonical tree, over the quantised boxes (a little larger than the exact ones).
//!
//! Guarantees: nothing here panics on any scene or ray data (indices out of range, NaN, zero
//! direction components are skipped or handled); the traversals visit each reachable node once per
//! instance that references it and cannot loop (children always lie at larger indices or records).

use glam::Vec3;
use rtc_bvh::quantized::{Child, QuantizedHeader, QuantizedNode};
use rtc_bvh::{Aabb, NodeRecord};

use crate::image_out::{srgb_to_linear, LinearImage};
use crate::scene::{Entities, GpuInstance};

/// One box to draw: its corners in its own space, its level, and (for BLAS boxes) the transform
/// from world space into that space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewBox {
    /// Minimum corner.
    pub min: Vec3,
    /// Maximum corner.
    pub max: Vec3,
    /// Level in the combined tree (see the module docs).
    pub level: u32,
    /// Rows of the world-to-object affine transform for a BLAS box; `None` for a world-space box.
    pub world_to_object: Option<[[f32; 4]; 3]>,
}

/// Which levels to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Levels {
    /// Exactly this level.
    One(u32),
    /// Every level from 0 to this one, inclusive.
    UpTo(u32),
}

impl Levels {
    /// True when `level` is drawn.
    pub fn contains(self, level: u32) -> bool {
        match self {
            Levels::One(l) => level == l,
            Levels::UpTo(l) => level <= l,
        }
    }
}

/// The boxes chosen, and the deepest level the walked tree has (to explain an empty choice).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BoxSet {
    /// The boxes of the chosen levels.
    pub boxes: Vec<ViewBox>,
    /// Deepest level of the walked tree (0 for a lone root).
    pub deepest: u32,
    /// Nodes walked (all levels).
    pub nodes: u64,
}

/// Why the boxes could not be collected.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ViewError {
    /// `--object NAME` names no object.
    #[error("the scene has no object named `{name}`; its objects are: {}", list(.names))]
    UnknownObject {
        /// The name asked for.
        name: String,
        /// The scene's object names (unnamed objects as `#index`).
        names: Vec<String>,
    },
    /// The object has no triangle mesh, so it has no object-level BVH.
    #[error("object `{name}` has custom geometry, so it has no object-level BVH (its box is in the scene-level BVH)")]
    NoObjectBvh {
        /// The object's name.
        name: String,
    },
    /// The ray buffers do not match the image size.
    #[error("internal error: {got} camera rays for a {width}x{height} image")]
    RayCount {
        /// Rays given.
        got: usize,
        /// Image width.
        width: u32,
        /// Image height.
        height: u32,
    },
}

fn list(names: &[String]) -> String {
    if names.is_empty() {
        "(none)".to_string()
    } else {
        names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The names `--object` accepts, in object order (an unnamed object is `#index`).
pub fn object_names(entities: &Entities) -> Vec<String> {
    entities
        .objects()
        .iter()
        .enumerate()
        .map(|(i, o)| o.name.clone().unwrap_or_else(|| format!("#{i}")))
        .collect()
}

/// One node of a BVH as [`walk`] reports it: its box (`None` for an empty leaf), depth and, for
/// a leaf, its first slot and slot count.
#[derive(Clone, Copy, Debug)]
struct NodeView {
    bounds: Option<Aabb>,
    depth: u32,
    leaf: Option<(u32, u32)>,
}

/// Walks the BVH whose header record is `nodes[base]` (the quantised layout of
/// `rtc_bvh::quantized`), calling `visit` for every node, leaves included. The root's box is the
/// union of its children's (a leaf root gets the header's whole quantisation frame). Inner
/// children lie at larger records than their parent; anything else is a broken buffer and is not
/// followed.
fn walk(nodes: &[NodeRecord], base: u32, mut visit: impl FnMut(NodeView)) {
    let Some(&header) = nodes.get(base as usize) else {
        return;
    };
    let header: QuantizedHeader = bytemuck::cast(header);
    let mut stack = vec![(header.root, header.frame(), 0u32, 0u32)];
    while let Some((reference, bounds, depth, parent)) = stack.pop() {
        match Child::decode(reference) {
            Child::Leaf { first, count } => visit(NodeView {
                bounds: (count > 0).then_some(bounds).and_then(drawable),
                depth,
                leaf: Some((first, count)),
            }),
            Child::Inner(record) => {
                if record <= parent {
                    continue;
                }
                let Some(&n) = (base as usize)
                    .checked_add(record as usize)
                    .and_then(|i| nodes.get(i))
                else {
                    continue;
                };
                let n: QuantizedNode = bytemuck::cast(n);
                let (l, r) = (header.unpack(n.left_box), header.unpack(n.right_box));
                visit(NodeView {
                    bounds: drawable(if depth == 0 { l.union(&r) } else { bounds }),
                    depth,
                    leaf: None,
                });
                stack.push((n.right, r, depth + 1, record));
                stack.push((n.left, l, depth + 1, record));
            }
        }
    }
}

/// `b` when it is a finite, non-empty box.
fn drawable(b: Aabb) -> Option<Aabb> {
    (!b.is_empty() && b.is_finite()).then_some(b)
}

/// Collects the boxes of the chosen `levels`: of the whole scene (TLAS, then each instance's
/// BLAS below its leaf), or, with `object`, of that object's BLAS only (see the module docs).
pub fn collect_boxes(
    entities: &Entities,
    object: Option<&str>,
    levels: Levels,
) -> Result<BoxSet, ViewError> {
    let nodes = entities.nodes();
    let instances = entities.instances();
    let mut set = BoxSet::default();
    let blas = |set: &mut BoxSet, inst: &GpuInstance, base: u32| {
        walk(nodes, inst.blas_root, |n| {
            let level = base + n.depth;
            set.nodes += 1;
            set.deepest = set.deepest.max(level);
            if let (true, Some(b)) = (levels.contains(level), n.bounds) {
                set.boxes.push(ViewBox {
                    min: b.min.into(),
                    max: b.max.into(),
                    level,
                    world_to_object: Some(inst.world_to_object),
                });
            }
        });
    };
    if let Some(name) = object {
        let names = object_names(entities);
        let Some(index) = names.iter().position(|n| n == name) else {
            return Err(ViewError::UnknownObject {
                name: name.to_string(),
                names,
            });
        };
        let mut found = false;
        for inst in instances.iter().filter(|i| i.object as usize == index) {
            if inst.geometry_type == GpuInstance::MESH_GEOMETRY {
                found = true;
                blas(&mut set, inst, 0);
            }
        }
        if !found {
            return Err(ViewError::NoObjectBvh {
                name: name.to_string(),
            });
        }
        return Ok(set);
    }
    let mut leaves = Vec::new();
    walk(nodes, entities.tlas_root(), |n| {
        let d = n.depth;
        set.nodes += 1;
        set.deepest = set.deepest.max(d);
        if let (true, Some(b)) = (levels.contains(d), n.bounds) {
            set.boxes.push(ViewBox {
                min: b.min.into(),
                max: b.max.into(),
                level: d,
                world_to_object: None,
            });
        }
        if let Some((first, count)) = n.leaf {
            leaves.push((first, count, d));
        }
    });
    for (first, count, depth) in leaves {
        for slot in first..first.saturating_add(count) {
            if let Some(inst) = instances.get(slot as usize) {
                if inst.geometry_type == GpuInstance::MESH_GEOMETRY {
                    blas(&mut set, inst, depth + 1);
                }
            }
        }
    }
    Ok(set)
}

/// Surface-area-heuristic cost of the BVH whose header record is `nodes[base]` (the quantised
/// layout of `rtc_bvh::quantized`), over its quantised boxes: the sum over inner nodes of `A(n)`
/// plus the sum over leaves of `count · A(n)`, divided by `A(root)` (traversal and intersection
/// cost 1 each, `rtc_bvh::SahCost::STANDARD`). A root of zero area weighs each node by 1; an empty
/// tree costs 0.
pub fn sah_cost(nodes: &[NodeRecord], base: u32) -> f64 {
    let mut root_area = None;
    let mut total = 0.0f64;
    walk(nodes, base, |n| {
        let Some(b) = n.bounds else { return };
        let area = f64::from(b.half_area());
        let root = *root_area.get_or_insert(area);
        let w = if root > 0.0 { area / root } else { 1.0 };
        total += w * n.leaf.map_or(1.0, |(_, count)| f64::from(count));
    });
    total
}

/// Camera rays, one per pixel, row-major: the debug kernel's `RayOrigin` (`xyz` = origin) and
/// `RayDirection` (`xyz` = direction) outputs.
#[derive(Clone, Copy, Debug)]
pub struct CameraRays<'a> {
    /// Origins (`w` ignored).
    pub origins: &'a [[f32; 4]],
    /// Directions (`w` ignored; need not be unit length).
    pub dirs: &'a [[f32; 4]],
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
}

/// The edge a pixel shows: the box's level and the distance along the (unit) ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeHit {
    /// Level of the box whose edge it is.
    pub level: u32,
    /// Distance from the ray origin (unit direction).
    pub t: f32,
}

fn affine(m: &[[f32; 4]; 3], v: Vec3, w: f32) -> Vec3 {
    let row = |r: &[f32; 4]| r[0] * v.x + r[1] * v.y + r[2] * v.z + r[3] * w;
    Vec3::new(row(&m[0]), row(&m[1]), row(&m[2]))
}

/// Entry and exit distances of the ray `o + t d` through the box, or `None` when it misses.
/// Zero direction components are handled (the slab is then all or nothing).
fn slab(o: Vec3, d: Vec3, min: Vec3, max: Vec3) -> Option<(f32, f32)> {
    let mut t0 = f32::NEG_INFINITY;
    let mut t1 = f32::INFINITY;
    for a in 0..3 {
        let (oa, da, lo, hi) = (o[a], d[a], min[a], max[a]);
        if da == 0.0 {
            if oa < lo || oa > hi {
                return None;
            }
            continue;
        }
        let (ta, tb) = ((lo - oa) / da, (hi - oa) / da);
        t0 = t0.max(ta.min(tb));
        t1 = t1.min(ta.max(tb));
    }
    (t0 <= t1 && t1.is_finite() && t0.is_finite()).then_some((t0, t1))
}

/// The 12 edges of the box, as (start, end).
fn box_edges(min: Vec3, max: Vec3) -> [(Vec3, Vec3); 12] {
    let c = |i: u32| {
        Vec3::new(
            if i & 1 != 0 { max.x } else { min.x },
            if i & 2 != 0 { max.y } else { min.y },
            if i & 4 != 0 { max.z } else { min.z },
        )
    };
    [
        (c(0), c(1)),
        (c(2), c(3)),
        (c(4), c(5)),
        (c(6), c(7)),
        (c(0), c(2)),
        (c(1), c(3)),
        (c(4), c(6)),
        (c(5), c(7)),
        (c(0), c(4)),
        (c(1), c(5)),
        (c(2), c(6)),
        (c(3), c(7)),
    ]
}

/// The closest approach of the ray `o + t d` (`t >= 0`) to the segment `a`–`b`: the ray's `t`
/// there and the distance. `None` for a zero direction.
fn ray_segment(o: Vec3, d: Vec3, a: Vec3, b: Vec3) -> Option<(f32, f32)> {
    let e = b - a;
    let r = o - a;
    let (dd, ee, de) = (d.dot(d), e.dot(e), d.dot(e));
    let (dr, er) = (d.dot(r), e.dot(r));
    if dd <= 0.0 || !dd.is_finite() {
        return None;
    }
    let denom = dd * ee - de * de;
    let mut s = if denom > 1e-12 * dd * ee {
        ((er * dd - de * dr) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut t = (s * de - dr) / dd;
    if t < 0.0 {
        t = 0.0;
    }
    if ee > 0.0 {
        s = ((er + t * de) / ee).clamp(0.0, 1.0);
    }
    let dist = (r + d * t - e * s).length();
    (t.is_finite() && dist.is_finite()).then_some((t, dist))
}

/// The pixel width at distance `t` along pixel `i`'s ray: how far the neighbouring pixels' rays
/// are from it at that distance (the larger of the horizontal and vertical neighbour).
struct Footprint {
    o: Vec3,
    d: Vec3,
    neighbours: [(Vec3, Vec3); 2],
}

impl Footprint {
    fn at(&self, t: f32) -> f32 {
        let here = self.o + self.d * t;
        let mut w = 0.0f32;
        for (o, d) in &self.neighbours {
            w = w.max((*o + *d * t - here).length());
        }
        w
    }
}

fn ray(rays: &CameraRays<'_>, x: u32, y: u32) -> Option<(Vec3, Vec3)> {
    let i = y as usize * rays.width as usize + x as usize;
    let (o, d) = (rays.origins.get(i)?, rays.dirs.get(i)?);
    let o = Vec3::new(o[0], o[1], o[2]);
    let d = Vec3::new(d[0], d[1], d[2]).normalize_or_zero();
    (o.is_finite() && d != Vec3::ZERO).then_some((o, d))
}

/// For each pixel, the nearest box edge its ray passes within `line_px / 2` pixel widths of (see
/// the module docs), or `None`. Of edges at the same distance (within 0.1 %), such as a child's
/// edge on its parent's, the lower level's is kept.
pub fn wireframe(
    rays: &CameraRays<'_>,
    boxes: &[ViewBox],
    line_px: f32,
) -> Result<Vec<Option<EdgeHit>>, ViewError> {
    let (w, h) = (rays.width, rays.height);
    let pixels = w as usize * h as usize;
    if rays.origins.len() < pixels || rays.dirs.len() < pixels {
        return Err(ViewError::RayCount {
            got: rays.origins.len().min(rays.dirs.len()),
            width: w,
            height: h,
        });
    }
    let half = 0.5 * line_px.max(0.0);
    let mut out = vec![None; pixels];
    for y in 0..h {
        for x in 0..w {
            let Some((o, d)) = ray(rays, x, y) else {
                continue;
            };
            let nx = if x + 1 < w {
                x + 1
            } else {
                x.saturating_sub(1)
            };
            let ny = if y + 1 < h {
                y + 1
            } else {
                y.saturating_sub(1)
            };
            let neighbours = [
                ray(rays, nx, y).unwrap_or((o, d)),
                ray(rays, x, ny).unwrap_or((o, d)),
            ];
            let fp = Footprint { o, d, neighbours };
            let mut best: Option<EdgeHit> = None;
            for b in boxes {
                let (lo, ld, scale) = match &b.world_to_object {
                    Some(m) => {
                        let ld = affine(m, d, 0.0);
                        (affine(m, o, 1.0), ld, ld.length())
                    }
                    None => (o, d, 1.0),
                };
                // Cheap rejection: the ray must pass through the box grown by the line
                // half-width at the far end of the box.
                let far = (b.max - b.min).length() + (0.5 * (b.min + b.max) - lo).length();
                let grow = Vec3::splat(half * fp.at(far / scale.max(f32::MIN_POSITIVE)) * scale);
                let Some((_, t1)) = slab(lo, ld, b.min - grow, b.max + grow) else {
                    continue;
                };
                if t1 <= 0.0 {
                    continue;
                }
                for (a, e) in box_edges(b.min, b.max) {
                    let Some((t, dist)) = ray_segment(lo, ld, a, e) else {
                        continue;
                    };
                    if t <= 0.0 || dist > half * fp.at(t) * scale {
                        continue;
                    }
                    // The nearest edge wins; edges at the same distance (a child's edge lying
                    // on its parent's) go to the lower level, so shared edges keep one colour.
                    let better = match best {
                        None => true,
                        Some(h) if (t - h.t).abs() <= 1e-3 * t.max(h.t) => b.level < h.level,
                        Some(h) => t < h.t,
                    };
                    if better {
                        best = Some(EdgeHit { level: b.level, t });
                    }
                }
            }
            if let Some(slot) = out.get_mut(y as usize * w as usize + x as usize) {
                *slot = best;
            }
        }
    }
    Ok(out)
}

/// The level colours (sRGB) and their names: red, orange, yellow, green (thesis Fig. 17), then
/// cyan, blue, violet, magenta.
const PALETTE: [([f32; 3], &str); 8] = [
    ([1.0, 0.1, 0.1], "red"),
    ([1.0, 0.55, 0.0], "orange"),
    ([1.0, 0.95, 0.1], "yellow"),
    ([0.2, 0.9, 0.2], "green"),
    ([0.1, 0.9, 0.95], "cyan"),
    ([0.2, 0.4, 1.0], "blue"),
    ([0.6, 0.3, 1.0], "violet"),
    ([1.0, 0.3, 0.85], "magenta"),
];

/// The colour of a level (sRGB): red, orange, yellow, green (thesis Fig. 17), then cyan, blue,
/// violet, magenta, repeating.
pub fn level_colour(level: u32) -> [f32; 3] {
    PALETTE[level as usize % PALETTE.len()].0
}

/// The name of [`level_colour`]`(level)`.
pub fn level_colour_name(level: u32) -> &'static str {
    PALETTE[level as usize % PALETTE.len()].1
}

fn linear(c: [f32; 3]) -> [f32; 4] {
    [
        srgb_to_linear(c[0]),
        srgb_to_linear(c[1]),
        srgb_to_linear(c[2]),
        1.0,
    ]
}

/// Draws the edge pixels over `base` (linear; black when `None`) in their level's colour.
/// `base` must be `width × height`; a mismatch draws over black.
pub fn overlay(
    base: Option<&LinearImage>,
    edges: &[Option<EdgeHit>],
    width: u32,
    height: u32,
) -> LinearImage {
    let mut image = match base {
        Some(b) if (b.width(), b.height()) == (width, height) => b.clone(),
        _ => LinearImage::filled(width, height, [0.0, 0.0, 0.0, 1.0]),
    };
    for (p, e) in image.pixels_mut().iter_mut().zip(edges) {
        if let Some(e) = e {
            *p = linear(level_colour(e.level));
        }
    }
    image
}

/// Maximum and means of one per-pixel count.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HeatStats {
    /// Largest value.
    pub max: f32,
    /// Mean over all pixels.
    pub mean: f64,
    /// Mean over the pixels whose ray hit something.
    pub mean_hit: f64,
    /// Pixels whose ray hit something.
    pub hit_pixels: usize,
}

impl HeatStats {
    /// The figures of channel `channel` of `counts` (`w` < 0 marks a miss, as the debug kernel's
    /// `Counts` mode writes).
    pub fn of(counts: &[[f32; 4]], channel: usize) -> HeatStats {
        let mut s = HeatStats::default();
        let (mut sum, mut sum_hit) = (0.0f64, 0.0f64);
        for c in counts {
            let v = c.get(channel).copied().unwrap_or(0.0);
            let v = if v.is_finite() { v.max(0.0) } else { 0.0 };
            s.max = s.max.max(v);
            sum += f64::from(v);
            if c[3] >= 0.0 {
                s.hit_pixels += 1;
                sum_hit += f64::from(v);
            }
        }
        s.mean = sum / counts.len().max(1) as f64;
        s.mean_hit = sum_hit / s.hit_pixels.max(1) as f64;
        s
    }
}

/// The heat colour of `x` in `[0, 1]` (sRGB), a perceptually ordered black–purple–red–yellow–
/// white ramp (close to matplotlib's "inferno").
pub fn heat_colour(x: f32) -> [f32; 3] {
    const STOPS: [[f32; 3]; 6] = [
        [0.0, 0.0, 0.02],
        [0.26, 0.04, 0.41],
        [0.58, 0.15, 0.40],
        [0.87, 0.32, 0.23],
        [0.99, 0.65, 0.04],
        [0.99, 1.0, 0.64],
    ];
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let f = x * (STOPS.len() - 1) as f32;
    let i = (f.floor() as usize).min(STOPS.len() - 2);
    let u = f - i as f32;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    [
        a[0] + (b[0] - a[0]) * u,
        a[1] + (b[1] - a[1]) * u,
        a[2] + (b[2] - a[2]) * u,
    ]
}

/// Gap between panels and around the colour bar, pixels.
const GAP: u32 = 6;
/// Colour bar height, pixels.
const BAR: u32 = 10;
/// Glyph scale of the labels (3×5 glyphs, so labels are 10 pixels high).
const GLYPH: u32 = 2;

/// Two heat-map panels side by side (nodes visited | primitives tested), each scaled from 0 to its
/// own maximum, with a colour bar under it labelled `0` and the maximum, and a title row.
/// Returns the image and the two channels' figures.
pub fn heatmap(
    counts: &[[f32; 4]],
    width: u32,
    height: u32,
) -> (LinearImage, HeatStats, HeatStats) {
    let nodes = HeatStats::of(counts, 0);
    let prims = HeatStats::of(counts, 1);
    let label_h = 5 * GLYPH;
    let top = label_h + GAP;
    let total_w = 2 * width + 3 * GAP;
    let total_h = top + height + GAP + BAR + GAP + label_h + GAP;
    let mut image = LinearImage::filled(total_w, total_h, [0.0, 0.0, 0.0, 1.0]);
    let bg = linear([0.12, 0.12, 0.12]);
    image.pixels_mut().fill(bg);
    let white = linear([1.0, 1.0, 1.0]);
    for (panel, (stats, channel, title)) in [(nodes, 0usize, "NODES"), (prims, 1, "PRIMS")]
        .into_iter()
        .enumerate()
    {
        let x0 = GAP + panel as u32 * (width + GAP);
        let max = stats.max.max(1.0);
        draw_text(&mut image, x0, GAP / 2, title, white);
        for y in 0..height {
            for x in 0..width {
                let v = counts
                    .get(y as usize * width as usize + x as usize)
                    .and_then(|c| c.get(channel))
                    .copied()
                    .unwrap_or(0.0);
                set(&mut image, x0 + x, top + y, linear(heat_colour(v / max)));
            }
        }
        let bar_y = top + height + GAP;
        for x in 0..width {
            let c = linear(heat_colour(x as f32 / (width.max(2) - 1) as f32));
            for y in 0..BAR {
                set(&mut image, x0 + x, bar_y + y, c);
            }
        }
        let label_y = bar_y + BAR + GAP / 2;
        draw_text(&mut image, x0, label_y, "0", white);
        let text = format!("{}", stats.max.round() as u64);
        let tw = text_width(&text);
        draw_text(
            &mut image,
            (x0 + width).saturating_sub(tw),
            label_y,
            &text,
            white,
        );
    }
    (image, nodes, prims)
}

fn set(image: &mut LinearImage, x: u32, y: u32, c: [f32; 4]) {
    let w = image.width();
    if x < w {
        if let Some(p) = image
            .pixels_mut()
            .get_mut(y as usize * w as usize + x as usize)
        {
            *p = c;
        }
    }
}

/// 3×5 glyphs, one row per `u8` (bit 2 = left column).
fn glyph(c: char) -> [u8; 5] {
    match c {
        '0' => [7, 5, 5, 5, 7],
        '1' => [2, 6, 2, 2, 7],
        '2' => [7, 1, 7, 4, 7],
        '3' => [7, 1, 7, 1, 7],
        '4' => [5, 5, 7, 1, 1],
        '5' => [7, 4, 7, 1, 7],
        '6' => [7, 4, 7, 5, 7],
        '7' => [7, 1, 1, 1, 1],
        '8' => [7, 5, 7, 5, 7],
        '9' => [7, 5, 7, 1, 7],
        'D' => [6, 5, 5, 5, 6],
        'E' => [7, 4, 6, 4, 7],
        'I' => [7, 2, 2, 2, 7],
        'M' => [5, 7, 7, 5, 5],
        'N' => [6, 5, 5, 5, 5],
        'O' => [7, 5, 5, 5, 7],
        'P' => [7, 5, 7, 4, 4],
        'R' => [7, 5, 6, 5, 5],
        'S' => [7, 4, 7, 1, 7],
        _ => [0; 5],
    }
}

fn text_width(text: &str) -> u32 {
    (text.chars().count() as u32 * 4).saturating_sub(1) * GLYPH
}

fn draw_text(image: &mut LinearImage, x0: u32, y0: u32, text: &str, c: [f32; 4]) {
    for (k, ch) in text.chars().enumerate() {
        let rows = glyph(ch);
        for (ry, bits) in rows.iter().enumerate() {
            for rx in 0..3u32 {
                if bits & (4 >> rx) != 0 {
                    for sy in 0..GLYPH {
                        for sx in 0..GLYPH {
                            set(
                                image,
                                x0 + (k as u32 * 4 + rx) * GLYPH + sx,
                                y0 + ry as u32 * GLYPH + sy,
                                c,
                            );
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pinhole rays as `std/cameras/pinhole.rt` makes them (pixel centres).
    fn pinhole(
        width: u32,
        height: u32,
        pos: Vec3,
        look: Vec3,
        fov: f32,
    ) -> (Vec<[f32; 4]>, Vec<[f32; 4]>) {
        let forward = (look - pos).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        let h = (fov.to_radians() * 0.5).tan();
        let aspect = width as f32 / height as f32;
        let mut o = Vec::new();
        let mut d = Vec::new();
        for y in 0..height {
            for x in 0..width {
                let nx = (x as f32 + 0.5) / width as f32 * 2.0 - 1.0;
                let ny = (y as f32 + 0.5) / height as f32 * 2.0 - 1.0;
                let dir = (forward + right * (nx * h * aspect) - up * (ny * h)).normalize();
                o.push([pos.x, pos.y, pos.z, 0.0]);
                d.push([dir.x, dir.y, dir.z, f32::INFINITY]);
            }
        }
        (o, d)
    }

    /// Projects a world point to pixel coordinates for the same camera.
    fn project(width: u32, height: u32, pos: Vec3, look: Vec3, fov: f32, p: Vec3) -> [f32; 2] {
        let forward = (look - pos).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        let h = (fov.to_radians() * 0.5).tan();
        let aspect = width as f32 / height as f32;
        let v = p - pos;
        let z = v.dot(forward);
        let nx = v.dot(right) / z / (h * aspect);
        let ny = -v.dot(up) / z / h;
        [
            (nx + 1.0) * 0.5 * width as f32,
            (ny + 1.0) * 0.5 * height as f32,
        ]
    }

    fn seg_dist(p: [f32; 2], a: [f32; 2], b: [f32; 2]) -> f32 {
        let (ax, ay, bx, by) = (a[0], a[1], b[0], b[1]);
        let (dx, dy) = (bx - ax, by - ay);
        let len2 = dx * dx + dy * dy;
        let u = if len2 > 0.0 {
            (((p[0] - ax) * dx + (p[1] - ay) * dy) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        ((p[0] - ax - u * dx).powi(2) + (p[1] - ay - u * dy).powi(2)).sqrt()
    }

    fn cube_edges() -> Vec<(Vec3, Vec3)> {
        let c = |i: u32| {
            Vec3::new(
                if i & 1 != 0 { 1.0 } else { -1.0 },
                if i & 2 != 0 { 1.0 } else { -1.0 },
                if i & 4 != 0 { 1.0 } else { -1.0 },
            )
        };
        let mut edges = Vec::new();
        for i in 0..8u32 {
            for bit in [1, 2, 4] {
                if i & bit == 0 {
                    edges.push((c(i), c(i | bit)));
                }
            }
        }
        edges
    }

    /// Edge pixels lie on the projected box edges (within 1.5 px) and every projected edge is
    /// drawn (its sampled points have an edge pixel within 1.5 px), for a world box and for the
    /// same box given as a scaled BLAS box.
    #[test]
    fn wireframe_pixels_are_the_projected_edges() {
        let (w, h) = (96u32, 72u32);
        let (pos, look, fov) = (Vec3::new(2.5, 1.8, 4.0), Vec3::ZERO, 50.0);
        let (o, d) = pinhole(w, h, pos, look, fov);
        let rays = CameraRays {
            origins: &o,
            dirs: &d,
            width: w,
            height: h,
        };
        let world = ViewBox {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
            level: 0,
            world_to_object: None,
        };
        // Object space is world scaled by 2 (object-to-world = scale 0.5), box [-2, 2]^3.
        let blas = ViewBox {
            min: Vec3::splat(-2.0),
            max: Vec3::splat(2.0),
            level: 3,
            world_to_object: Some([
                [2.0, 0.0, 0.0, 0.0],
                [0.0, 2.0, 0.0, 0.0],
                [0.0, 0.0, 2.0, 0.0],
            ]),
        };
        let edges2d: Vec<_> = cube_edges()
            .into_iter()
            .map(|(a, b)| {
                (
                    project(w, h, pos, look, fov, a),
                    project(w, h, pos, look, fov, b),
                )
            })
            .collect();
        for b in [world, blas] {
            let hits = wireframe(&rays, &[b], 1.5).expect("rays match");
            let mut drawn = Vec::new();
            for (i, e) in hits.iter().enumerate() {
                let Some(e) = e else { continue };
                assert_eq!(e.level, b.level);
                let p = [(i as u32 % w) as f32 + 0.5, (i as u32 / w) as f32 + 0.5];
                let dist = edges2d
                    .iter()
                    .map(|&(a, b)| seg_dist(p, a, b))
                    .fold(f32::INFINITY, f32::min);
                assert!(dist <= 1.5, "edge pixel {p:?} is {dist} px from every edge");
                drawn.push(p);
            }
            assert!(drawn.len() > 100, "only {} edge pixels", drawn.len());
            for &(a, b) in &edges2d {
                for k in 0..=10 {
                    let u = k as f32 / 10.0;
                    let q = [a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u];
                    if q[0] < 1.0 || q[1] < 1.0 || q[0] > w as f32 - 1.0 || q[1] > h as f32 - 1.0 {
                        continue;
                    }
                    let near = drawn
                        .iter()
                        .any(|p| (p[0] - q[0]).abs() <= 1.5 && (p[1] - q[1]).abs() <= 1.5);
                    assert!(near, "no edge pixel near {q:?} on edge {a:?}-{b:?}");
                }
            }
        }
    }

    #[test]
    fn slab_handles_zero_direction_components() {
        let (min, max) = (Vec3::splat(-1.0), Vec3::splat(1.0));
        assert_eq!(
            slab(
                Vec3::new(0.0, 0.0, 5.0),
                Vec3::new(0.0, 0.0, -1.0),
                min,
                max
            ),
            Some((4.0, 6.0))
        );
        assert_eq!(
            slab(
                Vec3::new(2.0, 0.0, 5.0),
                Vec3::new(0.0, 0.0, -1.0),
                min,
                max
            ),
            None
        );
        assert_eq!(slab(Vec3::ZERO, Vec3::ZERO, min, max), None);
    }

    #[test]
    fn heat_stats_and_colours() {
        let counts = [
            [10.0, 4.0, 1.0, 0.0],
            [2.0, 0.0, -1.0, -1.0],
            [0.0, 0.0, -1.0, -1.0],
            [f32::NAN, 0.0, -1.0, -1.0],
        ];
        let s = HeatStats::of(&counts, 0);
        assert_eq!(s.max, 10.0);
        assert!((s.mean - 3.0).abs() < 1e-9);
        assert_eq!(s.hit_pixels, 1);
        assert!((s.mean_hit - 10.0).abs() < 1e-9);
        // The ramp gets brighter from 0 to 1.
        let lum = |c: [f32; 3]| c[0] + c[1] + c[2];
        for k in 0..10 {
            assert!(lum(heat_colour(k as f32 / 10.0)) < lum(heat_colour((k + 1) as f32 / 10.0)));
        }
        let (image, n, p) = heatmap(&counts, 2, 2);
        assert_eq!((n.max, p.max), (10.0, 4.0));
        assert_eq!(image.width(), 2 * 2 + 3 * GAP);
    }
}
