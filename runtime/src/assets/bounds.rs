//! Axis-aligned bounding boxes of asset geometry, used to frame a model with a camera.
//!
//! Invariants: a [`Bounds`] is either empty ([`Bounds::EMPTY`], `min > max` on every axis, the
//! identity of [`Bounds::union`]) or has `min <= max` on every axis; growing by a non-finite
//! point leaves it unchanged, so bounds stay finite.

use glam::{Mat4, Vec3};

/// An axis-aligned box, `min..=max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// The lower corner.
    pub min: Vec3,
    /// The upper corner.
    pub max: Vec3,
}

impl Bounds {
    /// The empty box, which contains nothing.
    pub const EMPTY: Self = Self {
        min: Vec3::INFINITY,
        max: Vec3::NEG_INFINITY,
    };

    /// The smallest box containing `points` (empty for no points); non-finite points are
    /// skipped.
    pub fn from_points(points: impl IntoIterator<Item = Vec3>) -> Self {
        points.into_iter().fold(Self::EMPTY, Self::grow)
    }

    /// Whether the box contains no point.
    pub fn is_empty(&self) -> bool {
        !(self.min.cmple(self.max).all())
    }

    /// The box grown to contain `p` (unchanged if `p` is not finite).
    #[must_use]
    pub fn grow(self, p: Vec3) -> Self {
        if !p.is_finite() {
            return self;
        }
        Self {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The smallest box containing both.
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        if other.is_empty() {
            return self;
        }
        if self.is_empty() {
            return other;
        }
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The box around the eight transformed corners (empty stays empty).
    #[must_use]
    pub fn transformed(self, m: &Mat4) -> Self {
        if self.is_empty() {
            return self;
        }
        let (lo, hi) = (self.min, self.max);
        Self::from_points((0..8u8).map(|i| {
            let corner = Vec3::new(
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            );
            m.transform_point3(corner)
        }))
    }

    /// The centre (NaN-free only for non-empty boxes).
    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// The edge lengths (`Vec3::ZERO` for an empty box).
    pub fn size(&self) -> Vec3 {
        if self.is_empty() {
            Vec3::ZERO
        } else {
            self.max - self.min
        }
    }
}

impl Default for Bounds {
    fn default() -> Self {
        Self::EMPTY
    }
}
