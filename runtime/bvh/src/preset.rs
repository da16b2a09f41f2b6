//! Builder settings as named presets, and the SAH cost model they share with the statistics.
//!
//! # Invariants
//!
//! * Every number that steers a build lives in [`BuildParams`], and the only sanctioned values are
//!   the ones [`BuildPreset::params`] returns. Code elsewhere never writes a bin count, a leaf size
//!   or a cost constant as a literal.
//! * The builders and [`crate::Bvh::sah_cost`] use the same [`SahCost`], so a tree's reported
//!   cost is the quantity its builder minimised (for [`SahCost::STANDARD`]: traversal cost 1 per
//!   inner node, intersection cost 1 per primitive, both weighted by surface area relative to the
//!   root).

/// Which builder settings to use. The default is [`BuildPreset::Fast`].
///
/// The choice between the two is made by measurement (`cargo bench -p rtc-bvh --bench build`);
/// see the crate docs for the figures that justified the quality preset.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BuildPreset {
    /// Binned SAH over primitive boxes: parallel over subtrees with rayon, in-place partitioning
    /// of the reference array. Fast enough to rebuild every frame for moderate meshes.
    #[default]
    Fast,
    /// Finer binning plus spatial splits (SBVH, Stich et al. 2009) for triangles: lower SAH cost
    /// and faster tracing, mainly on scenes with large or long triangles, at a few times the
    /// build time. For box inputs (instances, custom geometry) spatial splits do not apply and
    /// only the finer binning is used.
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
                cost: SahCost::STANDARD,
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
}

/// Settings of one build. Obtain them from [`BuildPreset::params`].
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
    /// The textbook constants: 1 per inner node, 1 per primitive.
    pub const STANDARD: SahCost = SahCost {
        traversal: 1.0,
        intersection: 1.0,
    };
}
