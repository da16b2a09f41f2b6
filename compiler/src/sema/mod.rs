//! Semantic analysis: modules and imports, name resolution, types, programs, scenes, recursion.
