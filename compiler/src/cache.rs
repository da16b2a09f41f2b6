//! A content-hash cache of parsed modules, for compiling the same files again and again (`rtc watch`,
//! `rtc view`): a file whose text did not change since the last compile is not parsed again.
//!
//! The cache is opt-in: [`Options::cache`](crate::driver::Options::cache) holds one
//! [`ModuleCache`], shared (through an `Arc`) by every check run with those options. Without it the
//! driver parses every file, as before.
//!
//! Guarantees:
//! - A hit gives exactly what parsing would: the key is the file's id in the source map (spans in the
//!   tree carry it) and a 64-bit hash of the text, and on a hash match the stored text is compared with
//!   the new one byte for byte, so a collision is a miss, never a wrong tree.
//! - Memory stays bounded: an entry not used by any of the last [`KEEP_CHECKS`] checks is dropped at
//!   the end of a check, so editing a file over and over does not pile up old versions.
//! - Everything is behind one mutex; a poisoned lock (a panic elsewhere while holding it) is treated
//!   as an empty cache, never as a panic here.
//!
//! Semantic analysis runs over the whole module graph at once (names, types and the call graph cross
//! modules), so it is not cached per module; what it costs is reported in the compile's timings.

use crate::diag::Diagnostic;
use crate::source::FileId;
use crate::syntax::ast;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex};

/// Entries unused by this many consecutive checks are dropped.
pub const KEEP_CHECKS: u64 = 4;

/// Parsed modules by file id and content hash. Cheap to share: wrap it in an `Arc`.
#[derive(Default)]
pub struct ModuleCache {
    inner: Mutex<Inner>,
}

#[derive(Default)]
struct Inner {
    entries: HashMap<(FileId, u64), Entry>,
    /// Checks finished so far.
    generation: u64,
    /// Counters since the last [`ModuleCache::take_stats`].
    stats: CacheStats,
}

struct Entry {
    text: Arc<str>,
    ast: ast::Module,
    diagnostics: Vec<Diagnostic>,
    last_used: u64,
}

/// How the cache did since the last [`ModuleCache::take_stats`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheStats {
    /// Files whose tree came from the cache.
    pub hits: u32,
    /// Files parsed.
    pub misses: u32,
    /// Entries in the cache now.
    pub entries: u32,
}

impl std::fmt::Debug for ModuleCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let entries = self.inner.lock().map(|i| i.entries.len()).unwrap_or(0);
        f.debug_struct("ModuleCache")
            .field("entries", &entries)
            .finish()
    }
}

/// The 64-bit content hash the cache keys on.
pub fn content_hash(text: &str) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    text.hash(&mut h);
    h.finish()
}

impl ModuleCache {
    /// An empty cache.
    pub fn new() -> ModuleCache {
        ModuleCache::default()
    }

    /// The parse of `text` as file `file`: from the cache when the same text was parsed as the same
    /// file before, else by `parse` (and then remembered).
    pub fn parse_with(
        &self,
        file: FileId,
        text: &str,
        parse: impl FnOnce() -> (ast::Module, Vec<Diagnostic>),
    ) -> (ast::Module, Vec<Diagnostic>) {
        let key = (file, content_hash(text));
        if let Ok(mut inner) = self.inner.lock() {
            let generation = inner.generation;
            let hit = match inner.entries.get_mut(&key) {
                Some(e) if *e.text == *text => {
                    e.last_used = generation;
                    Some((e.ast.clone(), e.diagnostics.clone()))
                }
                _ => None,
            };
            if let Some(found) = hit {
                inner.stats.hits += 1;
                return found;
            }
        }
        let (ast, diagnostics) = parse();
        if let Ok(mut inner) = self.inner.lock() {
            inner.stats.misses += 1;
            let last_used = inner.generation;
            inner.entries.insert(
                key,
                Entry {
                    text: Arc::from(text),
                    ast: ast.clone(),
                    diagnostics: diagnostics.clone(),
                    last_used,
                },
            );
        }
        (ast, diagnostics)
    }

    /// Ends one check: drops what the last [`KEEP_CHECKS`] checks did not use.
    pub fn finish_check(&self) {
        if let Ok(mut inner) = self.inner.lock() {
            let generation = inner.generation;
            inner
                .entries
                .retain(|_, e| generation.saturating_sub(e.last_used) < KEEP_CHECKS);
            inner.generation += 1;
        }
    }

    /// The counters since the last call, and the number of entries now; resets the counters.
    pub fn take_stats(&self) -> CacheStats {
        match self.inner.lock() {
            Ok(mut inner) => {
                let mut stats = std::mem::take(&mut inner.stats);
                stats.entries = inner.entries.len() as u32;
                stats
            }
            Err(_) => CacheStats::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::driver::{check_text, Options};

    fn parse_count(cache: &ModuleCache, file: FileId, text: &str, parsed: &mut u32) {
        let _ = cache.parse_with(file, text, || {
            *parsed += 1;
            crate::syntax::parse(file, text)
        });
    }

    #[test]
    fn same_text_same_file_is_parsed_once() {
        let cache = ModuleCache::new();
        let mut parsed = 0;
        let a = FileId::default();
        parse_count(&cache, a, "fn f() {}", &mut parsed);
        parse_count(&cache, a, "fn f() {}", &mut parsed);
        assert_eq!(parsed, 1);
        parse_count(&cache, a, "fn g() {}", &mut parsed);
        assert_eq!(parsed, 2);
        let s = cache.take_stats();
        assert_eq!((s.hits, s.misses, s.entries), (1, 2, 2));
    }

    #[test]
    fn unused_entries_are_dropped_after_a_few_checks() {
        let cache = ModuleCache::new();
        let mut parsed = 0;
        let a = FileId::default();
        parse_count(&cache, a, "fn f() {}", &mut parsed);
        for i in 0..KEEP_CHECKS + 1 {
            cache.finish_check();
            parse_count(&cache, a, &format!("fn g{i}() {{}}"), &mut parsed);
        }
        // Only the versions of the last KEEP_CHECKS checks are kept.
        assert!(cache.take_stats().entries <= KEEP_CHECKS as u32 + 1);
        parse_count(&cache, a, "fn f() {}", &mut parsed);
        assert_eq!(
            parsed,
            KEEP_CHECKS as u32 + 3,
            "the first version was dropped"
        );
    }

    #[test]
    fn a_cached_check_gives_the_same_diagnostics() {
        let text = "fn f() -> i32 { return 1.0; }\nfn g() { let x = 1; }\n";
        let plain = check_text("t.rt", text, &Options::default());
        let options = Options {
            cache: Some(Arc::new(ModuleCache::new())),
            ..Options::default()
        };
        let first = check_text("t.rt", text, &options);
        let second = check_text("t.rt", text, &options);
        assert!(plain.has_errors());
        assert_eq!(plain.diagnostics, first.diagnostics);
        assert_eq!(plain.diagnostics, second.diagnostics);
        let stats = options
            .cache
            .as_ref()
            .map(|c| c.take_stats())
            .unwrap_or_default();
        assert!(stats.hits >= 2, "the second check parsed again: {stats:?}");
    }
}
