//! Axis-aligned bounding boxes, the one box type used by the builders, the canonical BVH and
//! the statistics.
//!
//! # Invariants
//!
//! * A box is either *empty* ([`Aabb::EMPTY`]: `min = +f32::MAX`, `max = -f32::MAX` on every
//!   axis, so that [`Aabb::union`] with it is the identity) or *valid*: `min <= max` on every
//!   axis, every coordinate finite and inside `[-MAX_COORD, MAX_COORD]`
//!   ([`crate::MAX_COORD`]). The input stage ([`crate::input`]) establishes this for every
//!   primitive box, and union and intersection preserve it, so no box in a built BVH is NaN or
//!   infinite.
//! * Because every valid coordinate lies in `[-MAX_COORD, MAX_COORD]`, [`Aabb::half_area`] of a
//!   valid box is finite (at most `3 * (2 * MAX_COORD)^2 ≈ 4.1e37 < f32::MAX`). The half area of
//!   the empty box is `+inf`; callers never weigh an empty box (a set of zero primitives costs
//!   nothing).
//! * Flat boxes (zero extent on one or more axes, e.g. the box of an axis-aligned triangle) are
//!   valid and have a well-defined, possibly zero, half area.

use bytemuck::Zeroable;
use glam::{Vec3, Vec3A};

/// An axis-aligned bounding box. See the module docs for the empty/valid invariant.
#[derive(Clone, Copy, Debug, PartialEq, Zeroable)]
pub struct Aabb {
    /// Lower corner.
    pub min: Vec3A,
    /// Upper corner.
    pub max: Vec3A,
}

impl Default for Aabb {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl Aabb {
    /// The empty box: the identity of [`Aabb::union`]. Inverted, so that every ray misses it.
    pub const EMPTY: Aabb = Aabb {
        min: Vec3A::splat(f32::MAX),
        max: Vec3A::splat(-f32::MAX),
    };

    /// A box from two corners (taken as given; see [`crate::input`] for sanitising user boxes).
    #[inline]
    pub fn new(min: Vec3, max: Vec3) -> Self {
        Self {
            min: min.into(),
            max: max.into(),
        }
    }

    /// The smallest box holding the three points.
    #[inline]
    pub fn from_triangle(v: &[Vec3; 3]) -> Self {
        let (a, b, c) = (Vec3A::from(v[0]), Vec3A::from(v[1]), Vec3A::from(v[2]));
        Self {
            min: a.min(b).min(c),
            max: a.max(b).max(c),
        }
    }

    /// True for a box holding nothing (any axis with `min > max`).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// The smallest box holding both.
    #[inline]
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Grows `self` to hold `other`.
    #[inline]
    pub fn grow(&mut self, other: &Aabb) {
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }

    /// Grows `self` to hold the point `p`.
    #[inline]
    pub fn grow_point(&mut self, p: Vec3A) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// The overlap of two boxes (possibly empty: then some axis has `min > max`).
    #[inline]
    pub fn intersection(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(other.min),
            max: self.max.min(other.max),
        }
    }

    /// `max - min`.
    #[inline]
    pub fn extent(&self) -> Vec3A {
        self.max - self.min
    }

    /// Half the surface area, `xy + yz + zx`: the SAH weight. Finite for every valid box.
    #[inline]
    pub fn half_area(&self) -> f32 {
        let e = self.extent();
        e.x * e.y + e.y * e.z + e.z * e.x
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> Vec3A {
        (self.min + self.max) * 0.5
    }

    /// True when every coordinate is finite (no NaN, no infinity).
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// True when `other` lies inside `self` (inclusive).
    #[inline]
    pub fn contains(&self, other: &Aabb) -> bool {
        self.min.cmple(other.min).all() && other.max.cmple(self.max).all()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_is_union_identity() {
        let b = Aabb::new(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 3.0));
        assert_eq!(Aabb::EMPTY.union(&b), b);
        assert!(Aabb::EMPTY.is_empty());
        assert!(!b.is_empty());
        // A flat box has a finite, non-negative half area.
        assert_eq!(b.half_area(), 2.0);
    }

    #[test]
    fn largest_valid_box_has_finite_area() {
        let m = crate::MAX_COORD;
        let b = Aabb::new(Vec3::splat(-m), Vec3::splat(m));
        assert!(b.half_area().is_finite());
    }
}
