//! Builder settings as named presets, and the SAH cost model they share with the statistics.
//!
//! # Invariants
//!
//! * Every number that steers a build lives in [`BuildParams`], and the only sanctioned values are
//!   the ones [`BuildPreset::params`] and [`BuildPreset::single_leaf_params`] return. Code
//!   elsewhere never writes a bin count, a leaf size or a cost constant as a literal.
//! * Trees are compared by [`crate::Bvh::sah_cost`] with [`SahCost::STANDARD`] (traversal cost
//!   1 per inner node, intersection cost 1 per primitive, both weighted by surface area relative
//!   to the root), whatever their builder minimised. [`BuildPreset::Quality`] minimises exactly
//!   that. [`BuildPreset::Fast`] builds with [`SahCost::FAST_BUILD`] (traversal 1.5): leaves get
//!   a little larger and there are fewer nodes to split.
//!
//! # Why these presets (measured with `cargo bench -p rtc-bvh --bench build`, 2 cores)
//!
//! * Fast's traversal cost 1.5 instead of 1: builds 5-16% faster (dragon 177 -> 148 ms), the
//!   standard SAH rises by 0.0-1.0% (dragon 49.43 -> 49.76), and CPU trace speed does not
//!   change measurably.
//! * Fast sweeps small nodes along the widest axis only: about 10% less build time for +0.6%
//!   standard SAH.
//! * Quality = 32 bins, sweeps along every axis, spatial splits where object-split children
//!   overlap by more than 0.1% of the root's area: standard SAH -1.2% (bunny), -1.7%
//!   (armadillo), -3.4% (dragon) below Fast, at 2.5-5x its build time. A lower overlap threshold
//!   (1e-5, the paper's) gained another 0.5% on the dragon for 7x more time; reinsertion
//!   (obvhs's optimiser with batch ratio 1 applied to Fast's trees) gained only 0.1-0.9%.

/// Which builder settings to use. The default is [`BuildPreset::Fast`].
///
/// The settings of both were chosen by measurement; see the module docs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BuildPreset {
    /// Binned SAH (16 bins; exact sweeps for nodes of at most 16 references; a size split for
    /// nodes holding a primitive much larger than the rest) over primitive boxes: parallel over
    /// subtrees with rayon, in-place partitioning of the reference array. No spatial splits.
    #[default]
    Fast,
    /// Finer binning (32 bins, sweeps along every axis) plus spatial splits (SBVH, Stich et al.
    /// 2009) for triangles: lower SAH cost, mainly on scenes with large or long triangles, at a
    /// few times the build time. For box inputs (instances, custom geometry) spatial splits do
    /// not apply and only the finer binning is used.
    Quality,
}

impl BuildPreset {
    /// Every preset, for tests and benchmarks that cover them all.
    pub const ALL: [BuildPreset; 2] = [BuildPreset::Fast, BuildPreset::Quality];

    /// A short lowercase name (`fast`, `quality`).
    pub fn name(self) -> &'static str {
        match self {
            BuildPreset::Fast => "fast",
            BuildPreset::Quality => "quality",
        }
    }

    /// The settings of this preset.
    pub const fn params(self) -> BuildParams {
        match self {
            BuildPreset::Fast => BuildParams {
                bins: 16,
                max_leaf_size: 8,
                cost: SahCost::FAST_BUILD,
                sweep_all_axes: false,
                spatial_splits: None,
            },
            BuildPreset::Quality => BuildParams {
                bins: 32,
                max_leaf_size: 8,
                cost: SahCost::STANDARD,
                sweep_all_axes: true,
                spatial_splits: Some(SpatialSplits {
                    min_overlap: 1e-3,
                    max_duplication: 0.3,
                }),
            },
        }
    }

    /// The settings of this preset for a BVH over objects whose leaves must hold one object
    /// each (rtc's scene-level BVH: the kernel tests a leaf's one object without a loop, which
    /// on lavapipe made the thesis frame 3.8 % faster, and the one-object leaves about 2 % more).
    /// A node over more than one reference is always split, so every leaf of a non-empty input
    /// holds exactly one.
    pub const fn single_leaf_params(self) -> BuildParams {
        let mut params = self.params();
        params.max_leaf_size = 1;
        params
    }
}

/// Settings of one build. Obtain them from [`BuildPreset::params`] or
/// [`BuildPreset::single_leaf_params`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuildParams {
    /// Bins per axis for binned SAH, `2..=MAX_BINS` ([`crate::build::MAX_BINS`]).
    pub bins: usize,
    /// No leaf holds more references than this (`>= 1`). Below it, the SAH decides.
    pub max_leaf_size: u32,
    /// Cost model the builder minimises.
    pub cost: SahCost,
    /// Small nodes (at most 16 references) are split by an exact sweep over sorted centroids:
    /// along all three axes (`true`) or only the widest one (`false`, cheaper).
    pub sweep_all_axes: bool,
    /// Spatial splits for triangle input (`None`: object splits only).
    pub spatial_splits: Option<SpatialSplits>,
}

/// SBVH settings (Stich, Friedrich, Dietrich 2009, "Spatial Splits in Bounding Volume
/// Hierarchies").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialSplits {
    /// The paper's `alpha`: spatial splits are tried only where the children of the best object
    /// split overlap by more than this fraction of the root's surface area.
    pub min_overlap: f32,
    /// At most this many extra references, as a fraction of the primitive count, are created
    /// by splitting (a memory bound; Embree uses a similar split budget).
    pub max_duplication: f32,
}

/// The SAH cost model: cost of one traversal step and of one primitive test, each weighted by
/// the node's surface area relative to its parent (during building) or to the root (for a whole
/// tree, [`crate::Bvh::sah_cost`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SahCost {
    /// Cost of visiting an inner node (testing its two child boxes).
    pub traversal: f32,
    /// Cost of testing one primitive in a leaf.
    pub intersection: f32,
}

impl SahCost {
    /// The textbook constants: 1 per inner node, 1 per primitive. Every tree is reported with
    /// these.
    pub const STANDARD: SahCost = SahCost {
        traversal: 1.0,
        intersection: 1.0,
    };

    /// What [`BuildPreset::Fast`] builds with: a dearer traversal step makes slightly larger
    /// leaves and fewer nodes (see the module docs for the measurements).
    pub const FAST_BUILD: SahCost = SahCost {
        traversal: 1.5,
        intersection: 1.0,
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{build_with_params, Aabb, BuildInput, NodeKind};
    use glam::Vec3;

    #[test]
    fn single_leaf_params_give_one_reference_per_leaf_even_for_identical_boxes() {
        for preset in BuildPreset::ALL {
            // Six identical boxes (no split can separate them by position) and 40 in a row.
            let mut boxes = vec![Aabb::new(Vec3::ZERO, Vec3::ONE); 6];
            boxes.extend((0..40).map(|i| {
                let x = i as f32 * 0.5;
                Aabb::new(Vec3::new(x, 0.0, 0.0), Vec3::new(x + 2.0, 1.0, 1.0))
            }));
            let bvh = build_with_params(BuildInput::Aabbs(&boxes), &preset.single_leaf_params());
            let mut leaves = 0;
            for node in bvh.nodes() {
                if let NodeKind::Leaf { count, .. } = node.kind() {
                    assert_eq!(count, 1, "{preset:?}");
                    leaves += 1;
                }
            }
            assert_eq!(leaves, boxes.len(), "{preset:?}");
        }
    }
}
