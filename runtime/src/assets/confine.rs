//! Where assets may be read from, and reading them (from the disk or from memory): the rules of
//! `rtc_compiler::confine`, re-exported.
//!
//! The paths a scene (`load_mesh`, `load_image`, `model`) or a glTF file (buffer and image URIs)
//! names are confined to the referring file's folder and the folders the user names
//! (`--asset-root DIR`, [`AssetRoots`]); the rules are stated in the compiler's module, which
//! the link step uses too when it reads a `model` file's metadata, so both readers find the same
//! file or refuse the same path.

pub use rtc_compiler::confine::{
    has_scheme, read, resolve, resolve_scene_path, AssetRoots, Search,
};
