//! Lowering: typed HIR to one `naga::Module` (user programs, struct loaders, dispatch switches, the
//! framework kernel and its entry point). All IR construction goes through [`builder`].

pub mod builder;
