//! The input stage: turns user primitives (triangles, indexed triangles or boxes) into the
//! primitive references the builders partition, and decides what to do with bad input.
//!
//! # Sanitising rules (the only place where input is judged)
//!
//! * **Triangles** whose vertices are not all finite, or that have a coordinate outside
//!   `[-MAX_COORD, MAX_COORD]` ([`MAX_COORD`] = 1.844e18, the same limit Embree applies, see
//!   `FLT_LARGE` in Embree's `common/math/constants.h`) are **skipped**: they get no primitive
//!   reference, so the BVH never returns them. Clamping them would be wrong, because their box
//!   would no longer hold the triangle, and a triangle test on such coordinates overflows
//!   anyway. Indexed triangles with an index out of range are skipped the same way.
//! * Zero-area and sliver triangles are **kept**: their (possibly flat or point) box is valid,
//!   and the watertight triangle test simply never reports a hit on them.
//! * **Boxes** with a NaN coordinate, or with `min > max` on some axis (an empty or inverted
//!   box), are **skipped**. Infinite and huge coordinates are **clamped** to
//!   `[-MAX_COORD, MAX_COORD]`: an instance or custom primitive with an infinite box (an
//!   infinite plane, say) stays hittable for every ray that reaches it within `MAX_COORD`.
//!
//! # Invariants of the output
//!
//! * Every `PrimRef` box is valid in the sense of [`crate::aabb`]: finite, inside
//!   `[-MAX_COORD, MAX_COORD]`, `min <= max`.
//! * References appear in input order; the reference's `id` is the index of the primitive in the
//!   user's input (for indexed triangles: the index of the index triple).
//! * `bounds` and `centroid_bounds` are the exact unions over the references (empty when there
//!   are none). Centroids are kept doubled (`min + max`), which saves a multiply everywhere and
//!   cannot overflow because `2 * MAX_COORD` is far below `f32::MAX`.

use bytemuck::Zeroable;
use glam::{BVec4A, Vec3, Vec3A, Vec4};
use rayon::prelude::*;

use crate::aabb::Aabb;

/// Largest coordinate magnitude the BVH accepts (Embree's `FLT_LARGE`). Keeps every half area
/// finite in `f32`. See the module docs for what happens to primitives beyond it.
pub const MAX_COORD: f32 = 1.844e18;

/// Inputs at least this long are prepared in parallel.
const PAR_INPUT_MIN: usize = 1 << 14;

/// The box of a triangle, or `None` when the triangle is skipped (non-finite or beyond
/// [`MAX_COORD`]). See the module docs.
#[inline]
pub fn triangle_aabb(tri: &[Vec3; 3]) -> Option<Aabb> {
    let b = Aabb::from_triangle(tri);
    let limit = Vec3A::splat(MAX_COORD);
    // `cmple` is false for NaN, so NaN fails both tests.
    let inside = (-limit).cmple(b.min) & b.max.cmple(limit);
    inside.all().then_some(b)
}

/// A user box made valid, or `None` when it is skipped (NaN, or `min > max` on some axis).
/// Infinite and huge coordinates are clamped to `[-MAX_COORD, MAX_COORD]`.
#[inline]
pub fn sanitize_aabb(b: &Aabb) -> Option<Aabb> {
    if b.min.is_nan_mask().any() || b.max.is_nan_mask().any() || b.is_empty() {
        return None;
    }
    let limit = Vec3A::splat(MAX_COORD);
    Some(Aabb {
        min: b.min.clamp(-limit, limit),
        max: b.max.clamp(-limit, limit),
    })
}

/// A primitive reference: a box and the index of the input primitive it bounds.
///
/// Stored as two `Vec4`s (32 bytes, 16-byte aligned) so that loading a corner is one aligned
/// SIMD load. Bit layout:
///
/// * `lo.xyz` = box minimum, `lo.w` = the input primitive index, as raw `u32` bits
///   (`f32::from_bits`). The `w` lane is never used in arithmetic.
/// * `hi.xyz` = box maximum, `hi.w` = the box's half area (0 when below `f32::MIN_POSITIVE`,
///   so the lane is never denormal), for the size split of [`mod@crate::build`].
#[derive(Clone, Copy, Debug, Zeroable)]
#[repr(C)]
pub(crate) struct PrimRef {
    lo: Vec4,
    hi: Vec4,
}

static_assertions::assert_eq_size!(PrimRef, [u8; 32]);

/// Lane mask selecting x, y, z.
const XYZ: BVec4A = BVec4A::new(true, true, true, false);

impl PrimRef {
    #[inline]
    pub(crate) fn new(b: &Aabb, id: u32) -> Self {
        let area = b.half_area();
        let area = if area >= f32::MIN_POSITIVE { area } else { 0.0 };
        Self {
            lo: b.min.extend(f32::from_bits(id)),
            hi: b.max.extend(area),
        }
    }

    /// The box minimum. The `w` lane (the id bits, a denormal float for small ids) is cleared
    /// first: denormal lanes would make every SIMD operation on the box take a slow microcode
    /// path.
    #[inline]
    pub(crate) fn min(&self) -> Vec3A {
        Vec3A::from_vec4(Vec4::select(XYZ, self.lo, Vec4::ZERO))
    }

    /// The box maximum (`w` lane cleared, like [`PrimRef::min`]).
    #[inline]
    pub(crate) fn max(&self) -> Vec3A {
        Vec3A::from_vec4(Vec4::select(XYZ, self.hi, Vec4::ZERO))
    }

    /// Half area of the box.
    #[inline]
    pub(crate) fn area(&self) -> f32 {
        self.hi.w
    }

    #[inline]
    pub(crate) fn aabb(&self) -> Aabb {
        Aabb {
            min: self.min(),
            max: self.max(),
        }
    }

    /// The doubled centroid `min + max`.
    #[inline]
    pub(crate) fn centroid2(&self) -> Vec3A {
        self.min() + self.max()
    }

    /// Index of the input primitive.
    #[inline]
    pub(crate) fn id(&self) -> u32 {
        self.lo.w.to_bits()
    }
}

/// The prepared input of a build.
pub(crate) struct Prims {
    /// One reference per accepted primitive, in input order.
    pub refs: Vec<PrimRef>,
    /// Union of the reference boxes.
    pub bounds: Aabb,
    /// Union of the doubled centroids (a box of points).
    pub centroid_bounds: Aabb,
    /// Number of primitives in the input, accepted or not.
    pub input_count: usize,
}

/// Bounds and doubled-centroid bounds of `refs`.
pub(crate) fn ref_bounds(refs: &[PrimRef]) -> (Aabb, Aabb) {
    let fold = |(mut b, mut c): (Aabb, Aabb), r: &PrimRef| {
        b.grow(&r.aabb());
        c.grow_point(r.centroid2());
        (b, c)
    };
    let merge = |(b0, c0): (Aabb, Aabb), (b1, c1): (Aabb, Aabb)| (b0.union(&b1), c0.union(&c1));
    let empty = (Aabb::EMPTY, Aabb::EMPTY);
    if refs.len() < PAR_INPUT_MIN {
        refs.iter().fold(empty, fold)
    } else {
        refs.par_iter()
            .with_min_len(PAR_INPUT_MIN / 4)
            .fold(|| empty, fold)
            .reduce(|| empty, merge)
    }
}

/// Makes the reference of every input index `i` for which `f(i)` accepts a box, in input
/// order, and the bounds, in one pass (parallel over chunks for large inputs).
///
/// The reference array is allocated zeroed (`calloc`: the pages are zeroed lazily by the OS as
/// the chunks first touch them) and written in place, so there is no collect-and-concatenate
/// copy. Rejected slots are marked by an empty box and compacted away afterwards, which only
/// costs anything when some primitive was actually rejected.
fn collect_refs<F>(n: usize, f: F) -> Prims
where
    F: Fn(usize) -> Option<Aabb> + Sync,
{
    assert!(
        u32::try_from(n).is_ok(),
        "rtc-bvh: at most 2^32 - 1 primitives per BVH"
    );
    // (bounds, centroid bounds, rejected count) of a chunk starting at input index `start`.
    let fill = |start: usize, chunk: &mut [PrimRef]| {
        let (mut b, mut c, mut rejected) = (Aabb::EMPTY, Aabb::EMPTY, 0usize);
        for (k, slot) in chunk.iter_mut().enumerate() {
            let i = start + k;
            match f(i) {
                Some(aabb) => {
                    *slot = PrimRef::new(&aabb, i as u32);
                    b.grow(&aabb);
                    c.grow_point(aabb.min + aabb.max);
                }
                None => {
                    *slot = PrimRef::new(&Aabb::EMPTY, i as u32);
                    rejected += 1;
                }
            }
        }
        (b, c, rejected)
    };
    let mut refs: Vec<PrimRef> = bytemuck::zeroed_vec(n);
    let (bounds, centroid_bounds, rejected) = if n < PAR_INPUT_MIN {
        fill(0, &mut refs)
    } else {
        refs.par_chunks_mut(PAR_INPUT_CHUNK)
            .enumerate()
            .map(|(k, chunk)| fill(k * PAR_INPUT_CHUNK, chunk))
            .reduce(
                || (Aabb::EMPTY, Aabb::EMPTY, 0),
                |(b0, c0, r0), (b1, c1, r1)| (b0.union(&b1), c0.union(&c1), r0 + r1),
            )
    };
    if rejected > 0 {
        refs.retain(|r| !r.aabb().is_empty());
    }
    Prims {
        refs,
        bounds,
        centroid_bounds,
        input_count: n,
    }
}

/// Chunk size of parallel input preparation.
const PAR_INPUT_CHUNK: usize = 1 << 13;

/// References for a triangle soup.
pub(crate) fn triangle_refs(tris: &[[Vec3; 3]]) -> Prims {
    collect_refs(tris.len(), |i| triangle_aabb(&tris[i]))
}

/// The three vertices of indexed triangle `i`, or `None` if an index is out of range.
#[inline]
pub(crate) fn indexed_triangle(
    vertices: &[Vec3],
    indices: &[[u32; 3]],
    i: usize,
) -> Option<[Vec3; 3]> {
    let [a, b, c] = indices[i];
    Some([
        *vertices.get(a as usize)?,
        *vertices.get(b as usize)?,
        *vertices.get(c as usize)?,
    ])
}

/// References for an indexed triangle mesh.
pub(crate) fn indexed_refs(vertices: &[Vec3], indices: &[[u32; 3]]) -> Prims {
    collect_refs(indices.len(), |i| {
        indexed_triangle(vertices, indices, i).and_then(|t| triangle_aabb(&t))
    })
}

/// References for arbitrary boxes.
pub(crate) fn aabb_refs(boxes: &[Aabb]) -> Prims {
    collect_refs(boxes.len(), |i| sanitize_aabb(&boxes[i]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prim_ref_round_trips() {
        let b = Aabb::new(Vec3::new(-1.0, 2.0, 3.0), Vec3::new(4.0, 5.0, 6.0));
        for id in [0, 1, 12345, u32::MAX - 1, 0x7fc0_0001] {
            let r = PrimRef::new(&b, id);
            assert_eq!(r.id(), id);
            assert_eq!(r.aabb(), b);
        }
    }

    #[test]
    fn sanitising() {
        let nan = f32::NAN;
        let inf = f32::INFINITY;
        assert!(triangle_aabb(&[Vec3::ZERO, Vec3::X, Vec3::new(nan, 0.0, 0.0)]).is_none());
        assert!(triangle_aabb(&[Vec3::ZERO, Vec3::X, Vec3::new(inf, 0.0, 0.0)]).is_none());
        assert!(triangle_aabb(&[Vec3::ZERO, Vec3::X, Vec3::splat(1e30)]).is_none());
        assert!(triangle_aabb(&[Vec3::ZERO, Vec3::ZERO, Vec3::ZERO]).is_some());
        let b = sanitize_aabb(&Aabb::new(Vec3::splat(-inf), Vec3::splat(inf))).unwrap();
        assert!(b.is_finite() && b.half_area().is_finite());
        assert!(sanitize_aabb(&Aabb::new(Vec3::ONE, Vec3::ZERO)).is_none());
        assert!(sanitize_aabb(&Aabb::new(Vec3::ZERO, Vec3::new(1.0, nan, 1.0))).is_none());
    }
}
