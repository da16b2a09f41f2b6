//! The on-disk pipeline cache: one file per adapter and driver holding the driver's
//! `VkPipelineCache` data (through wgpu's [`wgpu::PipelineCache`], Vulkan only) and the keys of
//! the kernels compiled into it.
//!
//! Where: `$RTC_PIPELINE_CACHE` if set (`off`, `0` or an empty value disables the cache; anything
//! else is the folder), else `$XDG_CACHE_HOME/rtc/pipelines`, else `~/.cache/rtc/pipelines`
//! (`%LOCALAPPDATA%\rtc\pipelines` on Windows). The file is named after wgpu's
//! [`wgpu::util::pipeline_cache_key`] (backend, vendor, device) and a hash of the driver's name and
//! version, so two drivers never share a file.
//!
//! File format (little-endian): the magic `RTCPIPE1`, the key count `n` (u32), the length of the
//! wgpu data (u64), an FNV-1a checksum (u64) of everything after the header, then `n` kernel keys
//! (u64 each), then the bytes [`wgpu::PipelineCache::get_data`] returned.
//!
//! Invariants:
//! - A file that is short, long, of another format or whose checksum does not match is ignored
//!   with a warning (and replaced by the next write); one that wgpu rejects (another driver
//!   version) likewise. Nothing here panics or fails the caller on a bad or unwritable file.
//! - Writes are atomic: a temporary file in the same folder (named after the process id) is
//!   renamed over the old one, so a reader sees the old file or the new one, never a mix.
//! - The keys say which kernels the data was written for; a kernel whose key is in the loaded
//!   file is reported as coming from the disk cache. Whether the driver then skips its compile is
//!   the driver's business: the accounting reports the time it took either way. The keys are the
//!   memory cache's hashes (std's `DefaultHasher` over the module's `Debug` form), which another
//!   build of rtc may compute differently; that only makes a kernel count as compiled.
//! - A driver may accept the cache and store nothing in it: lavapipe (Mesa 25.0) returns only
//!   the headers however many pipelines were created with it (measured: docs/bench/compile.md).
//!   The size of an empty cache's data is measured when the cache is opened; data no larger than
//!   that holds no pipeline, and then no kernel is reported as coming from the disk cache and the
//!   status says the driver keeps nothing ([`PipelineCacheStatus::Unsupported`]).

use std::collections::BTreeSet;
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, PoisonError};

/// The environment variable that moves or disables the pipeline cache.
pub const PIPELINE_CACHE_ENV: &str = "RTC_PIPELINE_CACHE";

const MAGIC: &[u8; 8] = b"RTCPIPE1";
const HEADER_LEN: usize = 8 + 4 + 8 + 8;

/// Where the pipeline cache lives, or that there is none.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PipelineCacheConfig {
    /// No on-disk cache.
    Off,
    /// The cache files live in this folder (created when first written).
    Dir(PathBuf),
}

impl PipelineCacheConfig {
    /// The configuration the environment asks for (see the module docs).
    pub fn from_env() -> Self {
        match std::env::var_os(PIPELINE_CACHE_ENV) {
            Some(v) if v.is_empty() || v == "off" || v == "0" => Self::Off,
            Some(v) => Self::Dir(PathBuf::from(v)),
            None => Self::default_dir().map_or(Self::Off, Self::Dir),
        }
    }

    /// The user's cache folder for rtc's pipelines, if the environment names one.
    pub fn default_dir() -> Option<PathBuf> {
        let nonempty = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty());
        let base = if cfg!(windows) {
            nonempty("LOCALAPPDATA").map(PathBuf::from)
        } else {
            nonempty("XDG_CACHE_HOME")
                .map(PathBuf::from)
                .or_else(|| nonempty("HOME").map(|h| PathBuf::from(h).join(".cache")))
        }?;
        Some(base.join("rtc").join("pipelines"))
    }
}

/// What became of the on-disk pipeline cache when the [`super::Gpu`] was created.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PipelineCacheStatus {
    /// Disabled ([`PipelineCacheConfig::Off`]).
    Off,
    /// The adapter cannot keep pipeline caches (not Vulkan, or no `PIPELINE_CACHE` feature).
    Unsupported {
        /// Why, for humans.
        reason: String,
    },
    /// In use: the file and how many kernels it held when loaded (0 for a new or ignored file).
    Active {
        /// The cache file.
        path: PathBuf,
        /// Kernels the loaded file was written for.
        kernels: usize,
        /// Bytes of driver data loaded.
        bytes: usize,
    },
}

impl fmt::Display for PipelineCacheStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Off => write!(f, "off ({PIPELINE_CACHE_ENV}=off)"),
            Self::Unsupported { reason } => write!(f, "unsupported: {reason}"),
            Self::Active {
                path,
                kernels,
                bytes,
            } => write!(
                f,
                "{} ({kernels} kernel{} and {bytes} bytes loaded)",
                path.display(),
                if *kernels == 1 { "" } else { "s" }
            ),
        }
    }
}

/// The open cache: wgpu's object, the file, and the kernel keys.
#[derive(Debug)]
pub(super) struct DiskCache {
    path: PathBuf,
    cache: wgpu::PipelineCache,
    /// Keys of the file as loaded.
    loaded: BTreeSet<u64>,
    /// Keys to write: the loaded ones and every kernel compiled with the cache since.
    keys: Mutex<BTreeSet<u64>>,
    /// Bytes of `get_data` for a cache without any pipeline.
    empty_len: usize,
    /// Set when the driver's data held no pipeline although kernels were compiled with it.
    stores_nothing: AtomicBool,
}

/// What [`DiskCache::open`] found.
pub(super) struct Opened {
    pub(super) cache: Option<DiskCache>,
    pub(super) status: PipelineCacheStatus,
    pub(super) warnings: Vec<String>,
}

impl DiskCache {
    /// Whether this adapter can keep a pipeline cache (the feature to request for the device).
    pub(super) fn supported(adapter: &wgpu::Adapter) -> Result<(), String> {
        let info = adapter.get_info();
        if wgpu::util::pipeline_cache_key(&info).is_none() {
            return Err(format!(
                "wgpu keeps pipeline caches for Vulkan only, and this adapter is {:?}",
                info.backend
            ));
        }
        if !adapter.features().contains(wgpu::Features::PIPELINE_CACHE) {
            return Err("the adapter lacks wgpu's PIPELINE_CACHE feature".to_string());
        }
        Ok(())
    }

    /// Loads the cache file for this adapter from `dir` (if any) and creates wgpu's cache from
    /// it. The device must have been created with `Features::PIPELINE_CACHE`.
    pub(super) fn open(gpu_device: &wgpu::Device, adapter: &wgpu::Adapter, dir: &Path) -> Opened {
        let info = adapter.get_info();
        let Some(name) = wgpu::util::pipeline_cache_key(&info) else {
            return Opened {
                cache: None,
                status: PipelineCacheStatus::Unsupported {
                    reason: format!("no pipeline cache for the {:?} backend", info.backend),
                },
                warnings: Vec::new(),
            };
        };
        let driver = fnv1a(format!("{}\0{}", info.driver, info.driver_info).as_bytes());
        let path = dir.join(format!("{name}_{driver:016x}.bin"));
        let mut warnings = Vec::new();
        let (keys, data) = match std::fs::read(&path) {
            Ok(bytes) => match decode(&bytes) {
                Ok((keys, data)) => (keys, Some(data.to_vec())),
                Err(why) => {
                    warnings.push(format!(
                        "ignoring the pipeline cache {}: {why}",
                        path.display()
                    ));
                    (BTreeSet::new(), None)
                }
            },
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => (BTreeSet::new(), None),
            Err(e) => {
                warnings.push(format!(
                    "ignoring the pipeline cache {}: {e}",
                    path.display()
                ));
                (BTreeSet::new(), None)
            }
        };
        let (cache, rejected) = match data.as_deref() {
            Some(bytes) => {
                let (cache, error) = super::scoped_on(gpu_device, || {
                    create_pipeline_cache(gpu_device, Some(bytes), false)
                });
                match error {
                    None => (cache, None),
                    Some(why) => (create_pipeline_cache(gpu_device, None, true), Some(why)),
                }
            }
            None => (create_pipeline_cache(gpu_device, None, true), None),
        };
        let (keys, bytes) = match rejected {
            Some(why) => {
                warnings.push(format!(
                    "ignoring the pipeline cache {}: wgpu rejected it: {why}",
                    path.display()
                ));
                (BTreeSet::new(), 0)
            }
            None => (keys, data.as_ref().map_or(0, Vec::len)),
        };
        let empty_len = create_pipeline_cache(gpu_device, None, true)
            .get_data()
            .map_or(0, |d| d.len());
        // A file written after compiling kernels whose data is no bigger than an empty cache's:
        // the driver keeps nothing, so nothing will come from the disk.
        let stores_nothing = !keys.is_empty() && bytes <= empty_len;
        let disk = DiskCache {
            path: path.clone(),
            cache,
            loaded: if stores_nothing {
                BTreeSet::new()
            } else {
                keys.clone()
            },
            keys: Mutex::new(keys),
            empty_len,
            stores_nothing: AtomicBool::new(stores_nothing),
        };
        let status = disk.status(bytes);
        Opened {
            cache: Some(disk),
            status,
            warnings,
        }
    }

    /// The status to report, with `bytes` of driver data loaded.
    pub(super) fn status(&self, bytes: usize) -> PipelineCacheStatus {
        if self.stores_nothing.load(Ordering::Relaxed) {
            let kernels = self
                .keys
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .len();
            return PipelineCacheStatus::Unsupported {
                reason: format!(
                    "the driver keeps no pipelines in it (its data stayed at the {} bytes of an \
                     empty cache after {kernels} kernel{} compiled with it; {})",
                    self.empty_len,
                    if kernels == 1 { "" } else { "s" },
                    self.path.display()
                ),
            };
        }
        PipelineCacheStatus::Active {
            path: self.path.clone(),
            kernels: self.loaded.len(),
            bytes,
        }
    }

    /// wgpu's cache object, for `ComputePipelineDescriptor::cache`.
    pub(super) fn wgpu_cache(&self) -> &wgpu::PipelineCache {
        &self.cache
    }

    /// Whether the file as loaded was written for a kernel with this key.
    pub(super) fn had(&self, key: u64) -> bool {
        self.loaded.contains(&key)
    }

    /// Notes that a kernel was compiled with the cache; true if its key is new.
    pub(super) fn record(&self, key: u64) -> bool {
        self.keys
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .insert(key)
    }

    /// Writes the driver's current data and the keys to the file, atomically.
    pub(super) fn save(&self) -> Result<(), String> {
        let Some(data) = self.cache.get_data() else {
            return Err("the driver returned no cache data".to_string());
        };
        if data.len() <= self.empty_len {
            self.stores_nothing.store(true, Ordering::Relaxed);
        }
        let keys = self
            .keys
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        let bytes = encode(&keys, &data);
        let write = || -> std::io::Result<()> {
            if let Some(dir) = self.path.parent() {
                std::fs::create_dir_all(dir)?;
            }
            let temp = self
                .path
                .with_extension(format!("tmp{}", std::process::id()));
            std::fs::write(&temp, &bytes)?;
            std::fs::rename(&temp, &self.path).inspect_err(|_| {
                let _ = std::fs::remove_file(&temp);
            })
        };
        write().map_err(|e| format!("cannot write {}: {e}", self.path.display()))
    }
}

/// wgpu's `create_pipeline_cache`, the one `unsafe` call of the runtime.
#[allow(unsafe_code)]
fn create_pipeline_cache(
    device: &wgpu::Device,
    data: Option<&[u8]>,
    fallback: bool,
) -> wgpu::PipelineCache {
    // SAFETY: wgpu requires `data` to come from `PipelineCache::get_data` of an adapter with the
    // same `pipeline_cache_key`. It does: the file is named after that key and the driver's
    // version, only `DiskCache::save` writes it (atomically), and `decode` checked that it holds
    // exactly what was written (length and checksum). wgpu then checks its own header (adapter,
    // driver validation key) and the Vulkan driver its header (vendor, device, cache UUID). What
    // remains is a file forged on purpose in the user's own cache folder, which wgpu's docs
    // leave to the application's choice of a private place, as this one is.
    unsafe {
        device.create_pipeline_cache(&wgpu::PipelineCacheDescriptor {
            label: Some("rtc pipeline cache"),
            data,
            fallback,
        })
    }
}

/// The file's bytes for `keys` and the driver's `data`.
fn encode(keys: &BTreeSet<u64>, data: &[u8]) -> Vec<u8> {
    let mut body = Vec::with_capacity(keys.len() * 8 + data.len());
    for k in keys {
        body.extend_from_slice(&k.to_le_bytes());
    }
    body.extend_from_slice(data);
    let mut out = Vec::with_capacity(HEADER_LEN + body.len());
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&u32::try_from(keys.len()).unwrap_or(u32::MAX).to_le_bytes());
    out.extend_from_slice(&(data.len() as u64).to_le_bytes());
    out.extend_from_slice(&fnv1a(&body).to_le_bytes());
    out.extend_from_slice(&body);
    out
}

/// The keys and the driver's data of a file, or why it is not one of ours.
fn decode(bytes: &[u8]) -> Result<(BTreeSet<u64>, &[u8]), String> {
    let field = |at: usize, len: usize| bytes.get(at..at + len);
    let header = field(0, HEADER_LEN).ok_or("the file is shorter than its header")?;
    if header.get(..8) != Some(MAGIC.as_slice()) {
        return Err("not an rtc pipeline cache file (bad magic)".to_string());
    }
    let le_u64 = |at: usize| -> u64 {
        let mut b = [0u8; 8];
        if let Some(s) = header.get(at..at + 8) {
            b.copy_from_slice(s);
        }
        u64::from_le_bytes(b)
    };
    let mut count = [0u8; 4];
    if let Some(s) = header.get(8..12) {
        count.copy_from_slice(s);
    }
    let count = u32::from_le_bytes(count) as usize;
    let data_len = le_u64(12);
    let checksum = le_u64(20);
    let body = bytes.get(HEADER_LEN..).unwrap_or_default();
    let expected = (count as u64)
        .checked_mul(8)
        .and_then(|k| k.checked_add(data_len));
    if expected != Some(body.len() as u64) {
        return Err(format!(
            "its length does not match its header ({} bytes after the header)",
            body.len()
        ));
    }
    if fnv1a(body) != checksum {
        return Err("its checksum does not match (the file is corrupt)".to_string());
    }
    let (key_bytes, data) = body.split_at(count * 8);
    let keys = key_bytes
        .chunks_exact(8)
        .map(|c| {
            let mut b = [0u8; 8];
            b.copy_from_slice(c);
            u64::from_le_bytes(b)
        })
        .collect();
    Ok((keys, data))
}

/// 64-bit FNV-1a: a stable hash (the same in every process and Rust version) for checksums and
/// file names.
pub(super) fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let keys: BTreeSet<u64> = [3, 1, u64::MAX].into_iter().collect();
        let bytes = encode(&keys, b"driver data");
        let (k, d) = decode(&bytes).expect("decodes");
        assert_eq!(k, keys);
        assert_eq!(d, b"driver data");
    }

    #[test]
    fn damaged_files_are_refused() {
        let keys: BTreeSet<u64> = [7].into_iter().collect();
        let good = encode(&keys, b"0123456789");
        assert!(decode(&good[..good.len() - 1])
            .unwrap_err()
            .contains("length"));
        assert!(decode(&good[..10]).unwrap_err().contains("shorter"));
        let mut flipped = good.clone();
        let last = flipped.len() - 1;
        flipped[last] ^= 1;
        assert!(decode(&flipped).unwrap_err().contains("checksum"));
        let mut magic = good;
        magic[0] = b'X';
        assert!(decode(&magic).unwrap_err().contains("magic"));
        assert!(decode(b"").is_err());
        // A huge key count in the header must not overflow or allocate.
        let mut huge = encode(&BTreeSet::new(), b"");
        huge[8..12].copy_from_slice(&u32::MAX.to_le_bytes());
        assert!(decode(&huge).unwrap_err().contains("length"));
    }

    #[test]
    fn fnv_is_the_reference_function() {
        // Reference values of 64-bit FNV-1a.
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
