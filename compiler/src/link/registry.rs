//! The program registry: stable ids for types and programs, persisted next to the sources.
//!
//! This is the thesis's assets database (3.2.2 B–D): every camera, geometry, material, light and
//! background type, and every program, gets a small integer id that the generated dispatch switches
//! on and the runtime writes into instance records. Ids must not shuffle when a file is added, changed
//! or removed elsewhere, so they are kept in a JSON file (`rtc.registry.json` beside the scene) and only
//! changed by [`Registry::sync`]. The file holds one registry per scene, keyed by the declaring file's
//! name and the scene's (`scene.rt::thesis_scene`), so scenes that share a folder, or a file, keep
//! their ids apart and compiling one leaves the others' as they are ([`load_scene`], [`save_scene`];
//! a file of the first format, one registry for the folder, is read as the registry of whichever
//! scene loads it first). Within a scene's registry:
//! - a key seen before keeps its id;
//! - a new key gets the smallest id not in use in its namespace (new keys are assigned in sorted order,
//!   so the result does not depend on discovery order);
//! - a key no longer present is removed, and its id becomes free.
//!
//! Invariants: ids are unique within a namespace; the JSON is written with sorted keys, so the same
//! registry gives the same bytes; a missing or unreadable file is an empty registry (with a warning for
//! an unreadable one), never an error that stops a compile.

use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The file name of the registry, in the scene's folder.
pub const FILE_NAME: &str = "rtc.registry.json";

/// The format version of a scene's registry.
const VERSION: u32 = 1;

/// The format version of a registry file holding one registry per scene.
const FILE_VERSION: u32 = 2;

/// Ids per namespace, then per key.
type Namespaces = BTreeMap<String, BTreeMap<String, u32>>;

/// A registry file: one registry per scene, by scene key (see the module docs).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
struct RegistryFile {
    version: u32,
    scenes: BTreeMap<String, Namespaces>,
}

/// The key of a scene in its registry file: the declaring file's name and the scene's name.
pub fn scene_key(file_name: &str, scene: &str) -> String {
    format!("{file_name}::{scene}")
}

/// The text of the registry file at `path`: `None` for a missing file, and for an unreadable one
/// with a warning.
fn read_text(path: &Path) -> (Option<String>, Option<LoadWarning>) {
    match std::fs::read_to_string(path) {
        Ok(text) => (Some(text), None),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => (None, None),
        Err(e) => (None, Some(LoadWarning::Io(e))),
    }
}

/// Every scene's registry in a registry file's text (empty for none, and for an invalid one with
/// a warning); a file of the first format (one registry) is returned as `legacy`.
fn parse_file(text: Option<&str>) -> (RegistryFile, Option<Registry>, Option<LoadWarning>) {
    let empty = RegistryFile {
        version: FILE_VERSION,
        scenes: BTreeMap::new(),
    };
    let Some(text) = text else {
        return (empty, None, None);
    };
    if let Ok(file) = serde_json::from_str::<RegistryFile>(text) {
        if file.version != FILE_VERSION {
            let w = format!("version {} (expected {FILE_VERSION})", file.version);
            return (empty, None, Some(LoadWarning::Format(w)));
        }
        for (scene, namespaces) in &file.scenes {
            if let Err(LoadWarning::Format(e)) = validate(namespaces) {
                let w = format!("scene `{scene}`: {e}");
                return (empty, None, Some(LoadWarning::Format(w)));
            }
        }
        return (file, None, None);
    }
    match Registry::from_json(text) {
        Ok(legacy) => (empty, Some(legacy), None),
        Err(w) => (empty, None, Some(w)),
    }
}

/// Checks that no id is used twice in a namespace.
fn validate(namespaces: &Namespaces) -> Result<(), LoadWarning> {
    for (ns, ids) in namespaces {
        let mut seen = BTreeSet::new();
        if let Some((key, id)) = ids.iter().find(|(_, id)| !seen.insert(**id)) {
            return Err(LoadWarning::Format(format!(
                "id {id} of `{key}` is used twice in `{ns}`"
            )));
        }
    }
    Ok(())
}

/// The registry of scene `key` (see [`scene_key`]) in the file at `path`; missing (file or scene)
/// means empty, unreadable or invalid means empty with a warning.
pub fn load_scene(path: &Path, key: &str) -> (Registry, Option<LoadWarning>) {
    let (text, io_warning) = read_text(path);
    let (registry, warning) = load_scene_text(text.as_deref(), key);
    (registry, io_warning.or(warning))
}

/// [`load_scene`] from a registry file's text (`None`: no file).
pub fn load_scene_text(text: Option<&str>, key: &str) -> (Registry, Option<LoadWarning>) {
    let (mut file, legacy, warning) = parse_file(text);
    if let Some(legacy) = legacy {
        return (legacy, None);
    }
    let namespaces = file.scenes.remove(key).unwrap_or_default();
    (
        Registry {
            version: VERSION,
            namespaces,
        },
        warning,
    )
}

/// Stores `registry` as scene `key`'s in the file at `path`, keeping every other scene's, and
/// writes the file only if its text changes. A file of the first format is replaced.
pub fn save_scene(path: &Path, key: &str, registry: &Registry) -> std::io::Result<()> {
    let (old, _) = read_text(path);
    let (mut file, _, _) = parse_file(old.as_deref());
    if registry.namespaces.is_empty() {
        file.scenes.remove(key);
    } else {
        file.scenes
            .insert(key.to_string(), registry.namespaces.clone());
    }
    let mut text = serde_json::to_string_pretty(&file).unwrap_or_default();
    text.push('\n');
    if old.as_deref() == Some(text.as_str()) {
        return Ok(());
    }
    std::fs::write(path, text)
}

/// Ids per namespace (one namespace per struct role and one per program kind), keyed by a stable
/// name such as `material:std/materials/lambert.rt::Lambert`.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Registry {
    version: u32,
    namespaces: Namespaces,
}

/// What [`Registry::sync`] changed in one namespace.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Changes {
    /// Keys that got a new id.
    pub added: Vec<(String, u32)>,
    /// Keys that were removed, with the id they had.
    pub removed: Vec<(String, u32)>,
}

impl Changes {
    /// Whether nothing changed.
    pub fn is_empty(&self) -> bool {
        self.added.is_empty() && self.removed.is_empty()
    }
}

/// Why a registry file could not be used (it is then treated as empty).
#[derive(Debug)]
pub enum LoadWarning {
    /// The file could not be read.
    Io(std::io::Error),
    /// The file is not a registry.
    Format(String),
}

impl std::fmt::Display for LoadWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LoadWarning::Io(e) => write!(f, "cannot read the registry: {e}"),
            LoadWarning::Format(e) => write!(
                f,
                "the registry is not valid ({e}); ids are assigned afresh"
            ),
        }
    }
}

impl Registry {
    /// An empty registry.
    pub fn new() -> Registry {
        Registry {
            version: VERSION,
            namespaces: BTreeMap::new(),
        }
    }

    /// Reads a registry from JSON text.
    pub fn from_json(text: &str) -> Result<Registry, LoadWarning> {
        let reg: Registry =
            serde_json::from_str(text).map_err(|e| LoadWarning::Format(e.to_string()))?;
        if reg.version != VERSION {
            return Err(LoadWarning::Format(format!(
                "version {} (expected {VERSION})",
                reg.version
            )));
        }
        validate(&reg.namespaces)?;
        Ok(reg)
    }

    /// The registry as pretty JSON with sorted keys (deterministic): a file of the first format,
    /// which the tests write (files are written per scene by [`save_scene`]).
    #[cfg(test)]
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).unwrap_or_default();
        s.push('\n');
        s
    }

    /// The id of `key` in `namespace`, if it has one.
    pub fn id(&self, namespace: &str, key: &str) -> Option<u32> {
        self.namespaces.get(namespace)?.get(key).copied()
    }

    /// Makes `namespace` hold exactly `present` (create, update, delete), keeping existing ids.
    pub fn sync<'a>(
        &mut self,
        namespace: &str,
        present: impl IntoIterator<Item = &'a str>,
    ) -> Changes {
        let present: BTreeSet<&str> = present.into_iter().collect();
        let ids = self.namespaces.entry(namespace.to_string()).or_default();
        let mut changes = Changes::default();
        ids.retain(|key, id| {
            let keep = present.contains(key.as_str());
            if !keep {
                changes.removed.push((key.clone(), *id));
            }
            keep
        });
        let mut used: BTreeSet<u32> = ids.values().copied().collect();
        let mut next_free = 0u32;
        for key in present {
            if ids.contains_key(key) {
                continue;
            }
            while used.contains(&next_free) {
                next_free += 1;
            }
            ids.insert(key.to_string(), next_free);
            used.insert(next_free);
            changes.added.push((key.to_string(), next_free));
        }
        if ids.is_empty() {
            self.namespaces.remove(namespace);
        }
        changes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_stable_across_additions_and_removals() {
        let mut reg = Registry::new();
        let c = reg.sync("material", ["b", "a", "c"]);
        assert_eq!(
            c.added,
            vec![("a".into(), 0), ("b".into(), 1), ("c".into(), 2)]
        );
        // Remove `b`; `a` and `c` keep their ids.
        let c = reg.sync("material", ["a", "c"]);
        assert_eq!(c.removed, vec![("b".into(), 1)]);
        assert_eq!(
            (reg.id("material", "a"), reg.id("material", "c")),
            (Some(0), Some(2))
        );
        // A new key takes the freed id; nothing else moves.
        let c = reg.sync("material", ["a", "c", "d"]);
        assert_eq!(c.added, vec![("d".into(), 1)]);
        assert!(reg.sync("material", ["a", "c", "d"]).is_empty());
    }

    #[test]
    fn namespaces_are_independent() {
        let mut reg = Registry::new();
        reg.sync("material", ["m"]);
        reg.sync("light", ["l"]);
        assert_eq!(reg.id("material", "m"), Some(0));
        assert_eq!(reg.id("light", "l"), Some(0));
    }

    #[test]
    fn json_round_trip_is_byte_identical() {
        let mut reg = Registry::new();
        reg.sync("material", ["x", "y"]);
        reg.sync("camera", ["p"]);
        let json = reg.to_json();
        let back = Registry::from_json(&json).unwrap();
        assert_eq!(back, reg);
        assert_eq!(back.to_json(), json);
    }

    #[test]
    fn scenes_sharing_a_file_keep_their_ids_apart() {
        let dir = std::env::temp_dir().join(format!("rtc-registry-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(FILE_NAME);
        // A file of the first format is read as the first loader's registry.
        let mut legacy = Registry::new();
        legacy.sync("material", ["lambert"]);
        std::fs::write(&path, legacy.to_json()).unwrap();
        let (a0, warn) = load_scene(&path, "a.rt::a");
        assert!(warn.is_none());
        assert_eq!(a0, legacy);
        // Two scenes with different types, each compiled in turn: each keeps its own ids, and
        // compiling either again changes nothing in the file.
        let mut a = a0;
        a.sync("material", ["lambert", "mirror"]);
        save_scene(&path, "a.rt::a", &a).unwrap();
        let (mut b, _) = load_scene(&path, "b.rt::b");
        assert_eq!(b, Registry::new());
        b.sync("material", ["glass"]);
        save_scene(&path, "b.rt::b", &b).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        for key in ["a.rt::a", "b.rt::b"] {
            let (mut reg, warn) = load_scene(&path, key);
            assert!(warn.is_none());
            let present: Vec<String> = reg.namespaces["material"].keys().cloned().collect();
            assert!(reg
                .sync("material", present.iter().map(String::as_str))
                .is_empty());
            save_scene(&path, key, &reg).unwrap();
            assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
        }
        assert_eq!(
            load_scene(&path, "a.rt::a").0.id("material", "mirror"),
            Some(1)
        );
        assert_eq!(
            load_scene(&path, "b.rt::b").0.id("material", "glass"),
            Some(0)
        );
        // A duplicate id inside a scene's section is a warning and an empty registry.
        let bad = r#"{"version":2,"scenes":{"a.rt::a":{"material":{"x":0,"y":0}}}}"#;
        std::fs::write(&path, bad).unwrap();
        let (reg, warn) = load_scene(&path, "a.rt::a");
        assert!(matches!(warn, Some(LoadWarning::Format(_))));
        assert_eq!(reg, Registry::new());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn invalid_files_are_warnings() {
        assert!(matches!(
            Registry::from_json("{"),
            Err(LoadWarning::Format(_))
        ));
        let dup = r#"{"version":1,"namespaces":{"material":{"a":0,"b":0}}}"#;
        assert!(matches!(
            Registry::from_json(dup),
            Err(LoadWarning::Format(_))
        ));
        let (reg, warn) = load_scene(Path::new("/nonexistent/rtc.registry.json"), "a.rt::a");
        assert!(warn.is_none());
        assert_eq!(reg, Registry::new());
    }
}
