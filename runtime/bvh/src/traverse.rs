//! CPU reference traversal over the GPU node layouts ([`GpuNode`], and a mesh's
//! [`QuantizedBvh`]): closest hit and any hit,
//! a robust slab test and a watertight triangle test. It is written to be read next to the GPU
//! kernel (one loop, a short explicit stack, no recursion), and the tests compare it with brute
//! force.
//!
//! # Semantics (the GPU kernel must match them)
//!
//! * **Rays.** A ray is `origin + t * dir` for `t` in `[tmin, tmax]`. The origin and direction
//!   must be finite and the direction non-zero, and `tmin <= tmax`; otherwise
//!   [`PreparedRay::new`] returns `None` and the ray hits nothing. The direction need not be
//!   normalised (`t` is in units of `dir`). Direction components below `f32::MIN_POSITIVE` in
//!   magnitude are flushed to zero, as a GPU that flushes denormals does.
//! * **Closest hit** is the hit with the smallest `(t, primitive index)` pair in lexicographic
//!   order: equal `t` is broken by the lower input index. The result therefore does not depend on
//!   the tree or the visiting order, and the BVH gives exactly the brute-force answer.
//! * **Slab test** ([`intersect_aabb`]). Axes where the direction is zero are decided by
//!   comparison only (origin inside the slab, boundary included: no constraint; outside: miss),
//!   so no `0 * inf` is ever used and no NaN reaches a decision. Following Ize 2013 ("Robust
//!   BVH Ray Traversal", JCGT 2(2)), the exit distance and the culling distance are scaled by
//!   `1 + 2 * gamma(3)` so that rounding can only make the test more permissive, never lose a
//!   box a hit lies in. The result is the entry distance, used to visit the nearer child first
//!   and to skip deferred nodes that lie behind the closest hit.
//! * **Triangle test** ([`intersect_triangle`]): watertight, after Woop, Benthin and Wald,
//!   "Watertight Ray/Triangle Intersection", JCGT 2(1) 2013: a ray through a shared edge or
//!   vertex hits at least one of the triangles. Both faces are hit (no culling). Degenerate
//!   triangles (zero area, or seen edge-on) are never hit. Barycentrics `(u, v)` weight
//!   vertices 1 and 2: the hit point is `(1 - u - v) * v0 + u * v1 + v * v2`.
//! * **Stack.** The near-first traversal pushes at most one deferred sibling per level, so a
//!   stack of [`crate::Bvh::max_depth`] entries suffices ([`MAX_DEPTH`] here).

use glam::{BVec3A, Vec3, Vec3A};

use crate::bvh::MAX_DEPTH;
use crate::gpu::GpuNode;
use crate::quantized::{Child, QuantizedBvh};

/// A ray segment: `origin + t * dir`, `t` in `[tmin, tmax]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin.
    pub origin: Vec3,
    /// Direction (not necessarily normalised; non-zero).
    pub dir: Vec3,
    /// Smallest accepted `t`.
    pub tmin: f32,
    /// Largest accepted `t`.
    pub tmax: f32,
}

impl Ray {
    /// A ray over `t` in `[0, inf]`.
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Self {
            origin,
            dir,
            tmin: 0.0,
            tmax: f32::INFINITY,
        }
    }
}

/// A ray/primitive intersection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray, in units of its direction.
    pub t: f32,
    /// Barycentric weight of vertex 1 (0 for non-triangles unless the callback sets it).
    pub u: f32,
    /// Barycentric weight of vertex 2.
    pub v: f32,
    /// Index of the primitive in the builder's input.
    pub prim: u32,
}

/// `1 + 2 * gamma(3)` with `gamma(n) = n u / (1 - n u)`, `u = 2^-24` (Ize 2013; pbrt's
/// `gamma`): the factor that makes the slab test conservative under rounding.
pub const SLAB_ROBUST_SCALE: f32 =
    1.0 + 2.0 * (3.0 * f32::EPSILON * 0.5) / (1.0 - 3.0 * f32::EPSILON * 0.5);

/// A ray with everything the box and triangle tests precompute.
#[derive(Clone, Copy, Debug)]
pub struct PreparedRay {
    /// Origin.
    pub origin: Vec3A,
    /// Direction, denormal components flushed to zero.
    pub dir: Vec3A,
    /// `1 / dir` on non-zero axes, 0 on zero axes (never infinite).
    pub inv_dir: Vec3A,
    /// Axes with a zero direction component.
    pub parallel: BVec3A,
    /// `parallel.any()`.
    pub any_parallel: bool,
    /// Smallest accepted `t`.
    pub tmin: f32,
    /// Largest accepted `t`.
    pub tmax: f32,
    /// Watertight test: the axis of the largest direction component (`kz`) and the two others
    /// (`kx`, `ky`, swapped when `dir[kz] < 0` to keep the winding).
    pub k: [usize; 3],
    /// Watertight test: shear constants `(dir[kx] / dir[kz], dir[ky] / dir[kz], 1 / dir[kz])`.
    pub shear: [f32; 3],
}

impl PreparedRay {
    /// Precomputes `ray`, or `None` for an invalid ray (see the module docs).
    pub fn new(ray: &Ray) -> Option<Self> {
        let valid = ray.origin.is_finite()
            && ray.dir.is_finite()
            && !ray.tmin.is_nan()
            && !ray.tmax.is_nan()
            && ray.tmin <= ray.tmax;
        if !valid {
            return None;
        }
        let mut dir = Vec3A::from(ray.dir);
        let tiny = dir.abs().cmplt(Vec3A::splat(f32::MIN_POSITIVE));
        dir = Vec3A::select(tiny, Vec3A::ZERO, dir);
        if tiny.all() {
            return None;
        }
        let inv_dir = Vec3A::select(tiny, Vec3A::ZERO, dir.recip());
        let kz = dir.abs().max_position();
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        if dir[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        Some(Self {
            origin: ray.origin.into(),
            dir,
            inv_dir,
            parallel: tiny,
            any_parallel: tiny.any(),
            tmin: ray.tmin,
            tmax: ray.tmax,
            k: [kx, ky, kz],
            shear: [dir[kx] / dir[kz], dir[ky] / dir[kz], 1.0 / dir[kz]],
        })
    }
}

/// Slab test of the box `[min, max]` against `ray` limited to `t <= t_limit`: the entry
/// distance (at least `ray.tmin`) if the ray may touch the box, else `None`. Conservative under
/// rounding; see the module docs.
#[inline(always)]
pub fn intersect_aabb(ray: &PreparedRay, min: Vec3A, max: Vec3A, t_limit: f32) -> Option<f32> {
    let t0 = (min - ray.origin) * ray.inv_dir;
    let t1 = (max - ray.origin) * ray.inv_dir;
    let mut near = t0.min(t1);
    let mut far = t0.max(t1);
    if ray.any_parallel {
        let inside = min.cmple(ray.origin) & ray.origin.cmple(max);
        let inf = Vec3A::splat(f32::INFINITY);
        near = Vec3A::select(ray.parallel, Vec3A::select(inside, -inf, inf), near);
        far = Vec3A::select(ray.parallel, Vec3A::select(inside, inf, -inf), far);
    }
    let entry = near.max_element().max(ray.tmin);
    let exit = (far.min_element() * SLAB_ROBUST_SCALE).min(t_limit * SLAB_ROBUST_SCALE);
    (entry <= exit).then_some(entry)
}

/// Watertight ray/triangle test (Woop, Benthin, Wald 2013). Returns `(t, u, v)` for a hit with
/// `ray.tmin <= t <= t_max`; see the module docs for the conventions.
#[inline(always)]
pub fn intersect_triangle(
    ray: &PreparedRay,
    tri: &[Vec3; 3],
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let [kx, ky, kz] = ray.k;
    let [sx, sy, sz] = ray.shear;
    // Vertices relative to the origin, then sheared so that the ray runs along +z.
    let a = Vec3A::from(tri[0]) - ray.origin;
    let b = Vec3A::from(tri[1]) - ray.origin;
    let c = Vec3A::from(tri[2]) - ray.origin;
    let (ax, ay) = (a[kx] - sx * a[kz], a[ky] - sy * a[kz]);
    let (bx, by) = (b[kx] - sx * b[kz], b[ky] - sy * b[kz]);
    let (cx, cy) = (c[kx] - sx * c[kz], c[ky] - sy * c[kz]);
    // Scaled barycentrics: signed edge functions of the 2D triangle at the origin.
    let mut u = cx * by - cy * bx;
    let mut v = ax * cy - ay * cx;
    let mut w = bx * ay - by * ax;
    if u == 0.0 || v == 0.0 || w == 0.0 {
        // On an edge in single precision: decide in double, as the paper prescribes.
        let d = |p: f32, q: f32, r: f32, s: f32| {
            (f64::from(p) * f64::from(q) - f64::from(r) * f64::from(s)) as f32
        };
        u = d(cx, by, cy, bx);
        v = d(ax, cy, ay, cx);
        w = d(bx, ay, by, ax);
    }
    if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
        return None;
    }
    let det = u + v + w;
    if det == 0.0 {
        return None;
    }
    let (az, bz, cz) = (sz * a[kz], sz * b[kz], sz * c[kz]);
    let rcp = 1.0 / det;
    let t = (u * az + v * bz + w * cz) * rcp;
    // Written so that a NaN `t` (overflowing coordinates) is a miss.
    if !(t >= ray.tmin && t <= t_max) {
        return None;
    }
    Some((t, v * rcp, w * rcp))
}

/// True when `a` is a closer hit than `b` under the lexicographic `(t, prim)` rule.
#[inline(always)]
fn closer(a: &Hit, b: &Hit) -> bool {
    a.t < b.t || (a.t == b.t && a.prim < b.prim)
}

/// The traversal stack: node id and entry distance of each deferred node.
struct Stack {
    entries: [(u32, f32); MAX_DEPTH as usize],
    len: usize,
}

impl Stack {
    fn new() -> Self {
        Self {
            entries: [(0, 0.0); MAX_DEPTH as usize],
            len: 0,
        }
    }

    #[inline(always)]
    fn push(&mut self, node: u32, t: f32) {
        // Cannot overflow for valid trees (depth <= MAX_DEPTH, one push per level).
        self.entries[self.len] = (node, t);
        self.len += 1;
    }

    /// Pops the next deferred node whose entry distance does not exceed `t_limit`.
    #[inline(always)]
    fn pop_within(&mut self, t_limit: f32) -> Option<u32> {
        while self.len > 0 {
            self.len -= 1;
            let (node, t) = self.entries[self.len];
            if t <= t_limit * SLAB_ROBUST_SCALE {
                return Some(node);
            }
        }
        None
    }
}

/// One node as the traversal loop sees it.
enum Node {
    /// A leaf over `count` slots from `first`.
    Leaf { first: u32, count: u32 },
    /// An inner node: both children's boxes and ids, left first.
    Inner([(Vec3A, Vec3A, u32); 2]),
}

/// What the traversal loop reads of a node layout: the root's id (after any root-box test) and
/// each node by id.
trait Tree {
    /// The root's id, or `None` when the ray misses the whole tree.
    fn root(&self, ray: &PreparedRay) -> Option<u32>;
    /// Node `id`.
    fn node(&self, id: u32) -> Node;
}

/// [`GpuNode`]s: node `i`'s id is `i`; the root's box is tested first.
impl Tree for [GpuNode] {
    fn root(&self, ray: &PreparedRay) -> Option<u32> {
        let root = &self[0];
        intersect_aabb(ray, root.min.into(), root.max.into(), ray.tmax)?;
        Some(0)
    }

    #[inline(always)]
    fn node(&self, id: u32) -> Node {
        let n = &self[id as usize];
        if n.is_leaf() {
            return Node::Leaf {
                first: n.a,
                count: n.count(),
            };
        }
        // Both children are one 64-byte pair.
        let left = n.a;
        let (l, r) = (&self[left as usize], &self[left as usize + 1]);
        Node::Inner([
            (l.min.into(), l.max.into(), left),
            (r.min.into(), r.max.into(), left + 1),
        ])
    }
}

/// A [`QuantizedBvh`]: a node's id is its child reference; the kernel tests no root box.
impl Tree for QuantizedBvh {
    fn root(&self, _: &PreparedRay) -> Option<u32> {
        Some(self.header.root)
    }

    #[inline(always)]
    fn node(&self, id: u32) -> Node {
        match Child::decode(id) {
            Child::Leaf { first, count } => Node::Leaf { first, count },
            Child::Inner(record) => Node::Inner(
                self.children(record)
                    .map(|(b, c)| (b.min, b.max, c.encode())),
            ),
        }
    }
}

/// The traversal loop shared by both layouts, closest and any hit. `leaf(slot, ray, t_limit)`
/// tests one primitive slot and returns a hit within `t_limit`; `stop_at_first` ends at the first
/// hit.
#[inline(always)]
fn traverse<T, F>(tree: &T, ray: &Ray, stop_at_first: bool, mut leaf: F) -> Option<Hit>
where
    T: Tree + ?Sized,
    F: FnMut(u32, &PreparedRay, f32) -> Option<Hit>,
{
    let r = PreparedRay::new(ray)?;
    let mut node = tree.root(&r)?;
    let mut best: Option<Hit> = None;
    let mut t_best = r.tmax;
    let mut stack = Stack::new();
    loop {
        match tree.node(node) {
            Node::Leaf { first, count } => {
                for slot in first..first + count {
                    if let Some(h) = leaf(slot, &r, t_best) {
                        if best.as_ref().is_none_or(|b| closer(&h, b)) {
                            t_best = h.t;
                            best = Some(h);
                            if stop_at_first {
                                return best;
                            }
                        }
                    }
                }
            }
            Node::Inner([(lmin, lmax, l), (rmin, rmax, rr)]) => {
                // Test both children, go to the nearer, defer the farther.
                let hl = intersect_aabb(&r, lmin, lmax, t_best);
                let hr = intersect_aabb(&r, rmin, rmax, t_best);
                match (hl, hr) {
                    (Some(tl), Some(tr)) => {
                        let (near, far, t_far) = if tl <= tr { (l, rr, tr) } else { (rr, l, tl) };
                        stack.push(far, t_far);
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = l;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = rr;
                        continue;
                    }
                    (None, None) => {}
                }
            }
        }
        match stack.pop_within(t_best) {
            Some(next) => node = next,
            None => return best,
        }
    }
}

/// [`closest_hit_with`] over a mesh's quantised BVH ([`crate::quantized`]).
pub fn closest_hit_quantized_with<F>(bvh: &QuantizedBvh, ray: &Ray, intersect: F) -> Option<Hit>
where
    F: FnMut(u32, &PreparedRay, f32) -> Option<Hit>,
{
    traverse(bvh, ray, false, intersect)
}

/// [`closest_hit`] over a mesh's quantised BVH.
pub fn closest_hit_quantized(
    bvh: &QuantizedBvh,
    prim_indices: &[u32],
    tris: &[[Vec3; 3]],
    ray: &Ray,
) -> Option<Hit> {
    traverse(bvh, ray, false, triangle_leaf(prim_indices, tris))
}

/// [`any_hit`] over a mesh's quantised BVH.
pub fn any_hit_quantized(
    bvh: &QuantizedBvh,
    prim_indices: &[u32],
    tris: &[[Vec3; 3]],
    ray: &Ray,
) -> bool {
    traverse(bvh, ray, true, triangle_leaf(prim_indices, tris)).is_some()
}

/// Closest hit over arbitrary primitives: `intersect(slot, ray, t_max)` tests leaf slot `slot`
/// (primitive `prim_indices[slot]`, or entry `slot` of a reordered primitive buffer) and
/// returns a hit with `ray.tmin <= t <= t_max` and `prim` set to the input index.
pub fn closest_hit_with<F>(nodes: &[GpuNode], ray: &Ray, intersect: F) -> Option<Hit>
where
    F: FnMut(u32, &PreparedRay, f32) -> Option<Hit>,
{
    traverse(nodes, ray, false, intersect)
}

/// True when any primitive is hit in `[ray.tmin, ray.tmax]` (shadow rays); `intersect` as for
/// [`closest_hit_with`].
pub fn any_hit_with<F>(nodes: &[GpuNode], ray: &Ray, intersect: F) -> bool
where
    F: FnMut(u32, &PreparedRay, f32) -> Option<Hit>,
{
    traverse(nodes, ray, true, intersect).is_some()
}

/// Closest hit over triangles in input order (`tris[prim_indices[slot]]`).
pub fn closest_hit(
    nodes: &[GpuNode],
    prim_indices: &[u32],
    tris: &[[Vec3; 3]],
    ray: &Ray,
) -> Option<Hit> {
    closest_hit_with(nodes, ray, triangle_leaf(prim_indices, tris))
}

/// Any hit over triangles in input order.
pub fn any_hit(nodes: &[GpuNode], prim_indices: &[u32], tris: &[[Vec3; 3]], ray: &Ray) -> bool {
    any_hit_with(nodes, ray, triangle_leaf(prim_indices, tris))
}

fn triangle_leaf<'a>(
    prim_indices: &'a [u32],
    tris: &'a [[Vec3; 3]],
) -> impl FnMut(u32, &PreparedRay, f32) -> Option<Hit> + 'a {
    move |slot, r, t_max| {
        let prim = prim_indices[slot as usize];
        intersect_triangle(r, &tris[prim as usize], t_max).map(|(t, u, v)| Hit { t, u, v, prim })
    }
}

/// Closest hit by testing every triangle: the oracle the BVH traversal is checked against.
pub fn closest_hit_brute_force(tris: &[[Vec3; 3]], ray: &Ray) -> Option<Hit> {
    let r = PreparedRay::new(ray)?;
    let mut best: Option<Hit> = None;
    for (i, tri) in tris.iter().enumerate() {
        let t_max = best.map_or(r.tmax, |b| b.t);
        if let Some((t, u, v)) = intersect_triangle(&r, tri, t_max) {
            let h = Hit {
                t,
                u,
                v,
                prim: i as u32,
            };
            if best.as_ref().is_none_or(|b| closer(&h, b)) {
                best = Some(h);
            }
        }
    }
    best
}

/// Any hit by testing every triangle.
pub fn any_hit_brute_force(tris: &[[Vec3; 3]], ray: &Ray) -> bool {
    PreparedRay::new(ray).is_some_and(|r| {
        tris.iter()
            .any(|t| intersect_triangle(&r, t, r.tmax).is_some())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prep(o: Vec3, d: Vec3) -> PreparedRay {
        PreparedRay::new(&Ray::new(o, d)).unwrap()
    }

    fn unit_box() -> (Vec3A, Vec3A) {
        (Vec3A::ZERO, Vec3A::ONE)
    }

    #[test]
    fn slab_entry_distance() {
        let (lo, hi) = unit_box();
        let r = prep(Vec3::new(0.5, 0.5, -2.0), Vec3::Z);
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), Some(2.0));
        // Limited before the box: miss; limit exactly at the entry: hit (inclusive).
        assert_eq!(intersect_aabb(&r, lo, hi, 1.5), None);
        assert_eq!(intersect_aabb(&r, lo, hi, 2.0), Some(2.0));
        // Origin inside: entry is tmin.
        let r = prep(Vec3::splat(0.5), Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), Some(0.0));
        // Behind the origin: miss.
        let r = prep(Vec3::new(0.5, 0.5, 2.0), Vec3::Z);
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), None);
    }

    #[test]
    fn slab_with_zero_direction_components() {
        let (lo, hi) = unit_box();
        // Parallel to x and y, inside both slabs.
        let r = prep(Vec3::new(0.5, 0.5, -1.0), Vec3::Z);
        assert!(r.any_parallel);
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), Some(1.0));
        // Parallel to x, outside the x slab: miss, whatever the other axes say.
        let r = prep(Vec3::new(1.5, 0.5, -1.0), Vec3::Z);
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), None);
        // Exactly on the boundary plane x = 1: inside (boundary included), no NaN.
        let r = prep(Vec3::new(1.0, 0.5, -1.0), Vec3::Z);
        assert_eq!(intersect_aabb(&r, lo, hi, f32::INFINITY), Some(1.0));
        // A flat box (zero extent in y) seen edge-on from within its plane.
        let flat = (Vec3A::new(0.0, 0.0, 0.0), Vec3A::new(1.0, 0.0, 1.0));
        let r = prep(Vec3::new(-1.0, 0.0, 0.5), Vec3::X);
        assert_eq!(intersect_aabb(&r, flat.0, flat.1, f32::INFINITY), Some(1.0));
        // The same flat box crossed perpendicularly.
        let r = prep(Vec3::new(0.5, 3.0, 0.5), -Vec3::Y);
        assert_eq!(intersect_aabb(&r, flat.0, flat.1, f32::INFINITY), Some(3.0));
        // The empty box is always missed.
        let r = prep(Vec3::ZERO, Vec3::X);
        let e = crate::Aabb::EMPTY;
        assert_eq!(intersect_aabb(&r, e.min, e.max, f32::INFINITY), None);
    }

    #[test]
    fn invalid_rays_are_rejected() {
        assert!(PreparedRay::new(&Ray::new(Vec3::ZERO, Vec3::ZERO)).is_none());
        assert!(PreparedRay::new(&Ray::new(Vec3::ZERO, Vec3::splat(1e-40))).is_none());
        assert!(PreparedRay::new(&Ray::new(Vec3::NAN, Vec3::X)).is_none());
        let r = PreparedRay::new(&Ray::new(Vec3::ZERO, Vec3::new(1e-40, 0.0, 1.0))).unwrap();
        assert_eq!(r.dir.x, 0.0, "denormal components are flushed");
    }

    #[test]
    fn triangle_hits_both_faces_with_barycentrics() {
        let tri = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let front = prep(Vec3::new(0.25, 0.25, -1.0), Vec3::Z);
        let (t, u, v) = intersect_triangle(&front, &tri, f32::INFINITY).unwrap();
        assert_eq!((t, u, v), (1.0, 0.25, 0.25));
        let back = prep(Vec3::new(0.25, 0.25, 1.0), -Vec3::Z);
        assert_eq!(
            intersect_triangle(&back, &tri, f32::INFINITY).map(|h| h.0),
            Some(1.0)
        );
        // At vertex 1: u = 1, v = 0.
        let r = prep(Vec3::new(1.0, 0.0, -1.0), Vec3::Z);
        let (_, u, v) = intersect_triangle(&r, &tri, f32::INFINITY).unwrap();
        assert_eq!((u, v), (1.0, 0.0));
        // Outside, and beyond t_max.
        assert!(intersect_triangle(
            &prep(Vec3::new(0.8, 0.8, -1.0), Vec3::Z),
            &tri,
            f32::INFINITY
        )
        .is_none());
        assert!(intersect_triangle(&front, &tri, 0.5).is_none());
        // Degenerate triangles are never hit, even head-on.
        let line = [Vec3::ZERO, Vec3::X, Vec3::new(2.0, 0.0, 0.0)];
        assert!(intersect_triangle(
            &prep(Vec3::new(1.0, 0.0, -1.0), Vec3::Z),
            &line,
            f32::INFINITY
        )
        .is_none());
        // Edge-on: the ray lies in the triangle's plane.
        assert!(intersect_triangle(
            &prep(Vec3::new(-1.0, 0.1, 0.0), Vec3::X),
            &tri,
            f32::INFINITY
        )
        .is_none());
    }

    #[test]
    fn shared_edges_and_vertices_are_watertight() {
        // A quad split along its diagonal, in an awkward orientation; rays crossing the diagonal
        // at many points must hit at least one of the two triangles.
        let q = [
            Vec3::new(0.1, -0.3, 0.7),
            Vec3::new(1.3, 0.2, 0.9),
            Vec3::new(1.1, 1.4, 0.4),
            Vec3::new(-0.2, 0.9, 0.3),
        ];
        let (t0, t1) = ([q[0], q[1], q[2]], [q[0], q[2], q[3]]);
        let o = Vec3::new(0.3, 0.4, -2.0);
        // Interior points of the diagonal (its end points are corners of the quad).
        for i in 1..1000 {
            let p = q[0].lerp(q[2], i as f32 / 1000.0);
            let r = prep(o, p - o);
            let hit = intersect_triangle(&r, &t0, f32::INFINITY).is_some()
                || intersect_triangle(&r, &t1, f32::INFINITY).is_some();
            assert!(hit, "ray {i} through the shared edge fell through");
        }
        // Through the centre vertex of a closed fan of six triangles.
        let c = Vec3::new(0.35, 0.45, 0.6);
        let ring: Vec<Vec3> = (0..6)
            .map(|k| {
                let a = k as f32 * std::f32::consts::TAU / 6.0;
                c + Vec3::new(a.cos(), a.sin(), 0.3 * a.sin())
            })
            .collect();
        let fan: Vec<[Vec3; 3]> = (0..6).map(|k| [c, ring[k], ring[(k + 1) % 6]]).collect();
        for o in [o, Vec3::new(-1.0, 2.0, 3.0), Vec3::new(0.35, 0.45, -5.0)] {
            let r = prep(o, c - o);
            assert!(fan
                .iter()
                .any(|t| intersect_triangle(&r, t, f32::INFINITY).is_some()));
        }
    }
}
