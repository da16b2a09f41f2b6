//! `rtc-bvh`: bounding volume hierarchies for rtc. Object-level BVHs over triangles (in object
//! space) or boxes (custom geometry), and the scene-level BVH over instance boxes, all built into
//! one canonical binary tree and flattened into one GPU node layout.
//!
//! # The pipeline, one module per step
//!
//! ```text
//!  triangles / indexed mesh / boxes
//!      │  input      sanitise (skip NaN/inf/huge triangles, clamp huge boxes) → PrimRefs
//!      ▼
//!  build(input, BuildPreset)           binned SAH (+ spatial splits for Quality), rayon
//!      ▼
//!  Bvh   canonical: nodes in depth-first sibling-pair order + primitive index list
//!      │  stats, sah_cost, max_depth, validate, reorder
//!      ▼
//!  flatten(&Bvh) → Vec<GpuNode>        32-byte #[repr(C)] full-precision nodes (CPU reference)
//!  quantized::quantize(&Bvh)           the GPU layout: one 32-byte NodeRecord per inner node, 16-bit child boxes
//!      ▼
//!  traverse::{closest_hit, any_hit,    CPU reference of the GPU kernel, over either layout
//!            closest_hit_quantized, any_hit_quantized}
//! ```
//!
//! Building, converting and traversing are kept apart: builders know nothing of
//! the GPU layouts, [`flatten`] and [`quantized::quantize`] are the only converters, and the
//! traversal reads only the converted nodes. Builder settings exist only as named presets ([`BuildPreset::Fast`], the
//! default, and [`BuildPreset::Quality`]).
//!
//! # Crate-wide invariants
//!
//! * No NaN or infinite box ever enters a BVH, and no degenerate input panics (empty input, one
//!   primitive, equal centroids, zero-area triangles, flat boxes, huge or non-finite
//!   coordinates): see [`input`] for the sanitising rules.
//! * Every BVH satisfies the layout invariants of [`bvh`], checked by [`Bvh::validate`].
//! * A build is deterministic: the same input and preset give the same tree on any number of
//!   threads.
//! * The reference traversal returns the brute-force closest hit (same `t`, same primitive, ties
//!   broken by the lower primitive index): its box test is conservative within the rounding
//!   bounds of Ize 2013, and the tests check the equality bit for bit on random, axis-aligned and
//!   grazing rays, for every preset.
//!
//! # Example
//!
//! ```
//! use glam::Vec3;
//! use rtc_bvh::{build, flatten, traverse, BuildInput, BuildPreset};
//!
//! let tris = [[Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)]];
//! let bvh = build(BuildInput::Triangles(&tris), BuildPreset::Fast);
//! let nodes = flatten(&bvh);
//! let ray = traverse::Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
//! let hit = traverse::closest_hit(&nodes, bvh.prim_indices(), &tris, &ray).unwrap();
//! assert_eq!((hit.t, hit.prim), (5.0, 0));
//! assert!(bvh.max_depth() <= rtc_bvh::MAX_DEPTH);
//! ```

pub mod aabb;
pub mod build;
pub mod bvh;
pub mod gpu;
pub mod input;
pub mod preset;
pub mod quantized;
pub mod traverse;

pub use aabb::Aabb;
pub use build::{build, build_with_params, BuildInput};
pub use bvh::{Bvh, BvhNode, BvhStats, LayoutError, NodeKind, MAX_DEPTH};
pub use gpu::{flatten, GpuNode};
pub use input::MAX_COORD;
pub use preset::{BuildParams, BuildPreset, SahCost, SpatialSplits};
pub use quantized::NodeRecord;
