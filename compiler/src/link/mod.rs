//! Linking a scene: which programs, types and bindings the kernel for one scene needs, with stable ids.
//!
//! Planned: from the checked program and a scene, collect the used types and programs, give them ids
//! from the [`registry`], derive the kernel configuration (stack depth, spawn bounds, which features the
//! scene uses) and record what was left out for `manifest.json`.

pub mod registry;
