//! Tests of the watch [`Session`] in process, without file events: the soak tests drive the part of
//! `rtc watch` that runs per edit ([`Session::reload`]) many times over, alternating valid and
//! invalid edits, and check that every reload ends as it should and that memory does not grow.

use super::{Preview, Session, Status};
use crate::cmd::render::Format;
use rtc_compiler::back::Target;
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::ExecModel;
use rtc_runtime::gpu::{AdapterChoice, Gpu};
use std::path::{Path, PathBuf};

/// Most the resident set may grow over a soak, after the warm-up.
const MAX_GROWTH_BYTES: u64 = 10 << 20;

/// The soak tests measure the resident set of the whole process: they run one at a time.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn scene(fov: &str) -> String {
    format!(
        r#"import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/lights/point.rt";
import "std/miss/gradient.rt";

scene soak {{
    settings {{ width: 32, height: 32, samples: 1, max_depth: 2 }}
    camera Pinhole {{ position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0), fov: {fov} }}
    background SkyGradient {{}}
    object floor {{ geometry: quad_mesh(), material: Lambert {{ albedo: vec3f(0.5) }}, transform: scale(10.0) }}
    object ball {{ geometry: sphere_mesh(1u), material: Lambert {{ albedo: vec3f(0.8, 0.2, 0.2) }} }}
    light key PointLight {{ position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }}
}}
"#
    )
}

/// The resident set of this process in bytes (`/proc/self/statm`, pages of 4 KiB), or `None`
/// where there is no such file.
fn resident_bytes() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-soak-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// A session watching `file` that writes WGSL to `dir/out`, with no preview.
fn wgsl_session(file: &Path, dir: &Path) -> Session {
    Session::new(
        file,
        None,
        &Options::default(),
        vec![Target::Wgsl],
        Some(dir.join("out")),
        None,
        false,
    )
}

/// A session (as [`wgsl_session`]) over a scene written in `dir` whose object's geometry is the
/// mesh `tri.obj` beside it (written by the caller), after its first build; with the mesh's
/// canonical path.
fn mesh_session(dir: &Path) -> (Session, PathBuf) {
    let file = dir.join("scene.rt");
    let text = scene("40.0").replace(
        "geometry: sphere_mesh(1u)",
        "geometry: load_mesh(\"tri.obj\")",
    );
    std::fs::write(&file, text).expect("write");
    let mut session = wgsl_session(&file, dir);
    let first = session.reload(&[]);
    assert_eq!(first.status, Status::Built, "{}", first.messages);
    let canon = dir.join("tri.obj").canonicalize().expect("canonical");
    (session, canon)
}

/// Runs `cycles` edits on `file`, even ones valid (a new field of view each time, so the content
/// always changes) and odd ones invalid; checks each reload's outcome. Returns the resident-set
/// growth from after `warmup` cycles to the end.
fn soak(session: &mut Session, file: &Path, cycles: u32, warmup: u32) -> Option<i64> {
    let mut base = None;
    for i in 0..cycles {
        if i == warmup {
            base = resident_bytes();
        }
        let valid = i % 2 == 0;
        let fov = format!("{}.5", 30 + i % 40);
        let text = if valid {
            scene(&fov)
        } else {
            scene(&format!("{fov} +"))
        };
        std::fs::write(file, text).expect("write");
        let r = session.reload(&[file.to_path_buf()]);
        let want = if valid { Status::Built } else { Status::Failed };
        assert_eq!(r.status, want, "cycle {i}: {}", r.messages);
        if !valid {
            assert!(
                r.messages.contains("error[E0201]"),
                "cycle {i}: {}",
                r.messages
            );
        }
    }
    let end = resident_bytes()?;
    Some(end as i64 - base? as i64)
}

#[test]
fn soak_1000_edits_alternating_valid_and_invalid() {
    let _serial = SERIAL
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let dir = temp_dir("code");
    let file = dir.join("scene.rt");
    std::fs::write(&file, scene("40.0")).expect("write");
    let mut session = Session::new(
        &file,
        None,
        &Options::default(),
        Target::ALL.to_vec(),
        Some(dir.join("out")),
        None,
        false,
    );
    assert_eq!(session.reload(&[]).status, Status::Built);
    let growth = soak(&mut session, &file, 1000, 100);
    eprintln!("resident set growth over 900 edit cycles: {growth:?} bytes");
    if let Some(growth) = growth {
        assert!(
            growth < MAX_GROWTH_BYTES as i64,
            "the resident set grew by {growth} bytes"
        );
    }
    assert!(dir.join("out").join("kernel.wgsl").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn soak_20_edits_with_previews() {
    let _serial = SERIAL
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Err(e) = Gpu::new(&AdapterChoice::default()) {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI needs a GPU adapter (lavapipe) for this test: {e}"
        );
        eprintln!("skipped: no GPU adapter here ({e})");
        return;
    }
    let dir = temp_dir("preview");
    let file = dir.join("scene.rt");
    let image = dir.join("preview.png");
    std::fs::write(&file, scene("40.0")).expect("write");
    let mut session = Session::new(
        &file,
        None,
        &Options::default(),
        vec![Target::Wgsl],
        Some(dir.join("out")),
        Some(Preview {
            path: image.clone(),
            format: Format::Png,
            size: Some([32, 32]),
            samples: Some(1),
            adapter: AdapterChoice::default(),
            asset_roots: Default::default(),
        }),
        false,
    );
    let first = session.reload(&[]);
    assert_eq!(first.status, Status::Built, "{}", first.messages);
    let before = std::fs::read(&image).expect("the first preview");
    let growth = soak(&mut session, &file, 20, 4);
    eprintln!("resident set growth over 16 edit cycles with previews: {growth:?} bytes");
    if let Some(growth) = growth {
        assert!(
            growth < MAX_GROWTH_BYTES as i64,
            "the resident set grew by {growth} bytes"
        );
    }
    // The last valid edit set another field of view: the preview shows it.
    let after = std::fs::read(&image).expect("the last preview");
    assert_ne!(before, after, "the preview was not rendered again");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_touch_without_a_change_does_nothing() {
    let dir = temp_dir("touch");
    let file = dir.join("scene.rt");
    std::fs::write(&file, scene("40.0")).expect("write");
    let mut session = wgsl_session(&file, &dir);
    assert_eq!(session.reload(&[]).status, Status::Built);
    std::fs::write(&file, scene("40.0")).expect("write");
    let r = session.reload(std::slice::from_ref(&file));
    assert_eq!(r.status, Status::Unchanged);
    assert_eq!(r.number, 1, "an unchanged reload is not counted");
    assert!(session.is_relevant(&file));
    assert!(!session.is_relevant(&dir.join("other.rt")));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn assets_are_watched_and_an_asset_edit_skips_the_compile() {
    let dir = temp_dir("asset");
    let mesh = dir.join("tri.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("write obj");
    let (mut session, canon) = mesh_session(&dir);
    assert!(
        session.watched().any(|p| *p == canon),
        "the mesh is watched"
    );
    assert!(session.is_relevant(&mesh));
    std::fs::write(&mesh, "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n").expect("edit obj");
    let r = session.reload(std::slice::from_ref(&mesh));
    assert_eq!(r.status, Status::Rerendered, "{}", r.messages);
    assert_eq!(r.changed, vec![canon]);
    assert_eq!(r.parsed, (0, 0), "nothing was compiled");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A reload reads again only the watched files whose length or modification time changed, so an
/// edit is not slowed down by hashing large assets; a file written less than `SETTLE` before it was
/// read is read again whatever its stamp, so that a rewrite within the same tick of the file
/// system's clock is still seen.
#[test]
fn a_reload_reads_only_files_whose_stamp_changed_unless_just_written() {
    use std::time::{Duration, SystemTime};
    let dir = temp_dir("stamp");
    let mesh = dir.join("tri.obj");
    // Two meshes of the same length.
    let small = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let large = "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n";
    let write = |text: &str, time: SystemTime| {
        std::fs::write(&mesh, text).expect("write obj");
        let f = std::fs::File::options()
            .write(true)
            .open(&mesh)
            .expect("open obj");
        f.set_modified(time).expect("set the time");
    };
    let minute_ago = SystemTime::now() - Duration::from_secs(60);
    write(small, minute_ago);
    let (mut session, canon) = mesh_session(&dir);
    let reload = |session: &mut Session| session.reload(std::slice::from_ref(&mesh));

    // Other content under the same length and time, settled when read: not read again.
    write(large, minute_ago);
    assert_eq!(reload(&mut session).status, Status::Unchanged);
    // A new time: read, and the change found.
    write(large, minute_ago + Duration::from_secs(1));
    let r = reload(&mut session);
    assert_eq!(r.status, Status::Rerendered, "{}", r.messages);
    assert_eq!(r.changed, vec![canon.clone()]);
    // Written just now: a rewrite under the same length and time is still read.
    let now = SystemTime::now();
    write(small, now);
    assert_eq!(reload(&mut session).changed, vec![canon.clone()]);
    write(large, now);
    let r = reload(&mut session);
    assert_eq!(r.status, Status::Rerendered, "{}", r.messages);
    assert_eq!(r.changed, vec![canon]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_change_before_a_folder_is_watched_is_found() {
    let dir = temp_dir("missed");
    let file = dir.join("scene.rt");
    let lib = dir.join("lib.rt");
    // The scene imports a file that does not exist yet: the first build fails.
    let text = scene("40.0").replace(
        "import \"std/miss/gradient.rt\";",
        "import \"std/miss/gradient.rt\";\nimport \"lib.rt\";",
    );
    std::fs::write(&file, text).expect("write");
    let mut session = wgsl_session(&file, &dir);
    let started = std::time::SystemTime::now();
    let first = session.reload(&[]);
    assert_eq!(first.status, Status::Failed, "{}", first.messages);
    let canon_dir = dir.canonicalize().expect("canonical");
    assert!(
        session
            .missed(std::slice::from_ref(&canon_dir), started)
            .is_empty(),
        "nothing was written after the build began"
    );
    // The import appears before `rtc watch` registers the folder: no event will come for it.
    std::fs::write(&lib, "// now it exists\n").expect("write lib");
    let canon_lib = lib.canonicalize().expect("canonical");
    assert!(
        session.missed(&[], started).is_empty(),
        "only new folders are looked at"
    );
    let missed = session.missed(std::slice::from_ref(&canon_dir), started);
    assert_eq!(missed, vec![canon_lib]);
    let second = session.reload(&missed);
    assert_eq!(second.status, Status::Built, "{}", second.messages);

    // A watched file edited before its folder is watched differs from what the build read.
    let started = std::time::SystemTime::now();
    std::fs::write(&file, scene("41.0")).expect("edit");
    let canon_file = file.canonicalize().expect("canonical");
    assert_eq!(session.missed(&[canon_dir], started), vec![canon_file]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_scene_left_at_exec_auto_runs_the_model_the_session_says() {
    let dir = temp_dir("auto");
    let file = dir.join("scene.rt");
    std::fs::write(&file, scene("40.0")).expect("write");
    // `rtc watch`: the wavefront model; `rtc view` sets the megakernel; `--exec` wins over both.
    for (auto, exec, want) in [
        (None, None, ExecModel::Wavefront),
        (Some(ExecModel::Megakernel), None, ExecModel::Megakernel),
        (
            Some(ExecModel::Megakernel),
            Some(ExecModel::Wavefront),
            ExecModel::Wavefront,
        ),
    ] {
        let mut session = wgsl_session(&file, &dir).with_exec(exec);
        if let Some(auto) = auto {
            session = session.with_auto(auto);
        }
        let r = session.reload(&[]);
        assert_eq!(r.status, Status::Built, "{}", r.messages);
        let compiled = session.last().expect("a build");
        assert_eq!(compiled.exec, want, "auto {auto:?}, --exec {exec:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
