//! End-to-end tests of the `rtc` binary: exit codes (0 clean, 1 user errors, 2 usage errors, 101 only
//! for an internal error), the summary line, `--message-format json`, `--color`, `--version`, `help`,
//! and that no bad input (every UI case, garbage, invalid UTF-8, deep nesting) ever reaches the
//! internal-error path.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

#[path = "../../runtime/tests/common/scratch.rs"]
mod scratch;

use scratch::Scratch;

fn rtc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .env_remove("NO_COLOR")
        .output()
        .expect("run rtc")
}

fn code(out: &Output) -> i32 {
    out.status.code().unwrap_or(-1)
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the cli crate is in the repository")
        .to_path_buf()
}

/// A scratch folder for this test process.
fn scratch(name: &str) -> Scratch {
    Scratch::new(&format!("cli-{}-{name}", std::process::id()))
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

#[test]
fn version_and_help() {
    let out = rtc(&["--version"]);
    assert_eq!(code(&out), 0);
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        format!("rtc {}\n", env!("CARGO_PKG_VERSION"))
    );
    let out = rtc(&["help"]);
    assert_eq!(code(&out), 0);
    assert!(String::from_utf8_lossy(&out.stdout).contains("check"));
    let out = rtc(&["help", "check"]);
    assert_eq!(code(&out), 0);
    assert!(String::from_utf8_lossy(&out.stdout).contains("--message-format"));
}

#[test]
fn usage_errors_exit_with_2() {
    let empty = scratch("empty");
    let cases: &[&[&str]] = &[
        &[],
        &["check"],
        &["frobnicate"],
        &["check", "--bogus", "x.rt"],
        &["check", "--color", "sometimes", "x.rt"],
        &["check", "--message-format", "xml", "x.rt"],
        &["check", "definitely/not/here.rt"],
        &["check", s(&empty)],
    ];
    for args in cases {
        let out = rtc(args);
        assert_eq!(code(&out), 2, "rtc {args:?}: {}", stderr(&out));
        assert!(!stderr(&out).is_empty(), "rtc {args:?} said nothing");
    }
}

#[test]
fn clean_input_exits_0() {
    let out = rtc(&["check", s(&repo().join("stdlib"))]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(!stderr(&out).contains("error"), "{}", stderr(&out));
}

#[test]
fn errors_exit_1_with_a_summary_line() {
    let dir = scratch("errors");
    let file = dir.join("bad.rt");
    std::fs::write(&file, "fn f() -> f32 { return $; }\n").expect("write");
    let out = rtc(&["--color", "never", "check", s(&file)]);
    let err = stderr(&out);
    assert_eq!(code(&out), 1, "{err}");
    assert!(err.contains("error[E"), "{err}");
    let last = err.lines().last().unwrap_or_default();
    assert!(last.starts_with("error: could not check: "), "{err}");
}

#[test]
fn json_lines_on_stdout() {
    let dir = scratch("json");
    let file = dir.join("bad.rt");
    std::fs::write(&file, "fn f() -> f32 { return $; }\n").expect("write");
    let out = rtc(&["check", "--message-format", "json", s(&file)]);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(!stdout.is_empty());
    for line in stdout.lines() {
        let v: serde_json::Value = serde_json::from_str(line).expect("each line is JSON");
        for key in ["severity", "code", "message", "primary", "rendered"] {
            assert!(v.get(key).is_some(), "no `{key}` in {line}");
        }
    }
    // Only the summary goes to stderr.
    assert!(stderr(&out).starts_with("error: could not check: "));
}

#[test]
fn color_follows_the_flag_and_no_color() {
    let missing = "definitely/not/here.rt";
    let always = rtc(&["--color", "always", "check", missing]);
    assert!(stderr(&always).contains("\x1b["), "{}", stderr(&always));
    let never = rtc(&["--color", "never", "check", missing]);
    assert!(!stderr(&never).contains('\x1b'));
    // `auto` with stderr not a terminal (a pipe here): no colour.
    let auto = rtc(&["check", missing]);
    assert!(!stderr(&auto).contains('\x1b'));
    let no_color = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["--color", "auto", "check", missing])
        .env("NO_COLOR", "1")
        .output()
        .expect("run rtc");
    assert!(!stderr(&no_color).contains('\x1b'));
}

#[test]
fn a_panic_becomes_an_ice_with_101() {
    let out = rtc(&["--debug-force-ice", "check", "x.rt"]);
    assert_eq!(code(&out), 101);
    let err = stderr(&out);
    assert!(err.contains("error[ICE]: internal compiler error"), "{err}");
    assert!(err.contains("please report it"), "{err}");
}

/// Normal bad inputs end in diagnostics (exit 1) or success, never in the internal-error path.
#[test]
fn bad_inputs_never_reach_the_ice_path() {
    let dir = scratch("bad");
    let mut inputs: Vec<PathBuf> = Vec::new();
    let mut write = |name: &str, bytes: &[u8]| {
        let p = dir.join(name);
        std::fs::write(&p, bytes).expect("write");
        inputs.push(p);
    };
    write("empty.rt", b"");
    write(
        "garbage.rt",
        b"@@@ $$$ fn ( { [ \"unterminated\n/* never closed",
    );
    write(
        "invalid_utf8.rt",
        &[0x66, 0x6e, 0x20, 0xff, 0xfe, 0x80, 0x28, 0x29],
    );
    write("nul.rt", b"fn f() {\0}");
    write(
        "deep_parens.rt",
        format!(
            "fn f() -> f32 {{ return {}1{}; }}",
            "(".repeat(100_000),
            ")".repeat(100_000)
        )
        .as_bytes(),
    );
    write(
        "deep_blocks.rt",
        format!(
            "fn f() {{ {}{} }}",
            "{".repeat(100_000),
            "}".repeat(100_000)
        )
        .as_bytes(),
    );
    write(
        "bad_import.rt",
        b"import \"std/nothing/here.rt\";\nimport \"../../../../../../etc\";\n",
    );
    write("self_import.rt", b"import \"self_import.rt\";\n");
    // Found by the fuzz test: a role struct that contains itself.
    write("self_struct.rt", b"@material\nstruct M { m: M }\n");
    write(
        "mutual_structs.rt",
        b"struct A { b: B }\nstruct B { a: A }\nfn f(a: A) {}\n",
    );
    let ui = repo().join("tests/ui");
    inputs.extend(rt_files(&ui));
    inputs.push(ui.clone());
    let mut failures = Vec::new();
    for input in &inputs {
        let out = rtc(&["--color", "never", "check", s(input)]);
        let c = code(&out);
        if !(0..=2).contains(&c) || stderr(&out).contains("internal compiler error") {
            failures.push(format!(
                "{}: {}\n{}",
                input.display(),
                out.status,
                stderr(&out)
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn rt_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                out.extend(rt_files(&p));
            } else if p.extension().is_some_and(|x| x == "rt") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// `rtc compile` of a file with two scenes and no `--scene`: E0706 with the scene names.
#[test]
fn compile_with_two_scenes_needs_a_choice() {
    let dir = scratch("two-scenes");
    let file = dir.join("two.rt");
    std::fs::write(
        &file,
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
         scene a { camera Pinhole {} object o { geometry: cube_mesh(), material: Lambert {} } }\n\
         scene b { camera Pinhole {} object o { geometry: cube_mesh(), material: Lambert {} } }\n",
    )
    .unwrap();
    let out = rtc(&["compile", s(&file), "--out", s(&dir.join("out"))]);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("error[E0706]") && err.contains("--scene"),
        "{err}"
    );
    let out = rtc(&[
        "compile",
        s(&file),
        "--scene",
        "b",
        "--out",
        s(&dir.join("out")),
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(dir.join("out/kernel.wgsl").is_file() && dir.join("out/manifest.json").is_file());
}

/// `rtc compile` of a scene whose material type has no `@closest_hit` program: E0901 at the object.
#[test]
fn compile_reports_a_missing_program() {
    let dir = scratch("missing-program");
    let file = dir.join("scene.rt");
    std::fs::write(
        &file,
        "import \"std/cameras/pinhole.rt\";\n@material struct Bare { a: f32 = 1.0 }\n\
         scene s { camera Pinhole {} object o { geometry: cube_mesh(), material: Bare {} } }\n",
    )
    .unwrap();
    let out = rtc(&["compile", s(&file), "--out", s(&dir.join("out"))]);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("error[E0901]") && err.contains("@closest_hit"),
        "{err}"
    );
}

/// A scene in a scratch folder that checks (for tests that must fail on their arguments only).
fn good_scene(dir: &Path) -> PathBuf {
    let file = dir.join("scene.rt");
    std::fs::write(
        &file,
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
         scene a { camera Pinhole {} object o { geometry: cube_mesh(), material: Lambert {} } }\n",
    )
    .unwrap();
    file
}

/// `--spp` above a scene's `samples` limit (2^20), 0 or not a number is a usage error (exit 2) at
/// once, in every command that takes it, before anything is compiled or rendered; so are bench's
/// sample lists and a `--size` side above 16384.
#[test]
fn sample_counts_and_sizes_are_bounded_like_the_scene_settings() {
    let dir = scratch("spp-bounds");
    let scene = good_scene(&dir);
    let png = dir.join("x.png");
    let cases: Vec<Vec<&str>> = vec![
        vec!["render", s(&scene), "-o", s(&png), "--spp", "1048577"],
        vec!["bvh", s(&scene), "-o", s(&png), "--spp", "1048577"],
        vec!["view", s(&scene), "--spp", "1048577"],
        vec!["watch", s(&scene), "--spp", "1048577"],
        vec!["bench", s(&scene), "--spp-list", "1,4,1048577"],
        vec!["bench", s(&scene), "--reference-spp", "1048577"],
        vec![
            "bench",
            s(&scene),
            "--bvh-presets",
            "--preset-spp",
            "1048577",
        ],
    ];
    for args in &cases {
        let started = std::time::Instant::now();
        let out = rtc(args);
        let err = stderr(&out);
        assert_eq!(code(&out), 2, "{args:?}: {err}");
        assert!(
            err.contains("`1048577` samples per pixel is more than rtc renders: at most 1048576"),
            "{args:?}: {err}"
        );
        // Refused from the arguments alone: nothing was compiled (a compile takes seconds).
        assert!(started.elapsed().as_secs() < 30, "{args:?}");
    }
    for bad in ["0", "-1", "lots"] {
        let out = rtc(&["render", s(&scene), "-o", s(&png), "--spp", bad]);
        assert_eq!(code(&out), 2, "--spp {bad}: {}", stderr(&out));
    }
    let out = rtc(&["render", s(&scene), "-o", s(&png), "--size", "16385x16"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("from 1 to 16384"), "{}", stderr(&out));
    let out = rtc(&["watch", s(&scene), "--debounce-ms", "86400000"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(!png.exists());
}

/// An output that cannot be written (a missing folder, a folder, a wrong extension) is a usage
/// error before anything is compiled or rendered: render, bvh, bench's --csv/--json/--plot.
#[test]
fn outputs_are_checked_before_rendering() {
    let dir = scratch("outputs");
    let scene = good_scene(&dir);
    let missing = dir.join("no/such/dir/x.png");
    let (csv_missing, json_txt) = (dir.join("no/t.csv"), dir.join("t.txt"));
    let folder = dir.join("folder.png");
    std::fs::create_dir_all(&folder).unwrap();
    let (csv_json, svg_missing) = (dir.join("t.json"), dir.join("none/p.svg"));
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["render", s(&scene), "-o", s(&missing)],
            "does not exist",
        ),
        (
            vec!["render", s(&scene), "-o", s(&folder)],
            "it is a folder",
        ),
        (
            vec!["render", s(&scene), "-o", "x.jpg"],
            "must end in `.png` or `.exr`",
        ),
        (vec!["bvh", s(&scene), "-o", s(&missing)], "does not exist"),
        (
            vec!["bench", s(&scene), "--csv", s(&csv_missing)],
            "does not exist",
        ),
        (
            vec!["bench", s(&scene), "--json", s(&json_txt)],
            "must end in `.json`",
        ),
        (
            vec!["bench", s(&scene), "--csv", s(&csv_json)],
            "must end in `.csv`",
        ),
        (
            vec!["bench", s(&scene), "--plot", s(&svg_missing)],
            "does not exist",
        ),
        (
            vec!["watch", s(&scene), "-o", s(&missing)],
            "does not exist",
        ),
    ];
    for (args, expected) in &cases {
        let started = std::time::Instant::now();
        let out = rtc(args);
        let err = stderr(&out);
        assert_eq!(code(&out), 2, "{args:?}: {err}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert!(started.elapsed().as_secs() < 30, "{args:?}");
    }
    assert!(!dir.join("no").exists());
}

/// An unknown `--scene` and a folder without a scene are reported in the user's files (never at
/// `std/prelude.rt`), naming the scenes there are.
#[test]
fn scene_choice_errors_point_at_the_users_files() {
    let dir = scratch("scene-choice");
    let scene = good_scene(&dir);
    let out = rtc(&[
        "compile",
        s(&scene),
        "--scene",
        "nope",
        "--out",
        s(&dir.join("out")),
    ]);
    let err = stderr(&out);
    assert_eq!(code(&out), 1, "{err}");
    assert!(err.contains("error[E0706]: no scene named `nope`"), "{err}");
    assert!(err.contains("scene.rt:3:7"), "{err}");
    assert!(err.contains("the scenes are `a`"), "{err}");
    assert!(!err.contains("prelude"), "{err}");

    let lib = dir.join("lib");
    std::fs::create_dir_all(&lib).unwrap();
    std::fs::write(lib.join("util.rt"), "fn f() -> f32 { return 1.0; }\n").unwrap();
    let out = rtc(&["compile", s(&lib), "--out", s(&dir.join("out"))]);
    let err = stderr(&out);
    assert_eq!(code(&out), 1, "{err}");
    assert!(
        err.contains("error[E0703]: there is no scene to compile"),
        "{err}"
    );
    assert!(err.contains("util.rt:1:1"), "{err}");
    assert!(!err.contains("prelude"), "{err}");

    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let out = rtc(&["compile", s(&empty), "--out", s(&dir.join("out"))]);
    let err = stderr(&out);
    assert_eq!(code(&out), 1, "{err}");
    assert!(err.contains("holds no `.rt` file"), "{err}");
    assert!(err.contains(s(&empty)), "{err}");
    assert!(!err.contains("prelude"), "{err}");
}

/// `--emit hir` prints the whole checked program as typed text and `--emit naga` the render kernel
/// as the WGSL `--target wgsl` writes, with handle comments; neither writes files.
#[test]
fn emit_prints_readable_listings() {
    let dir = scratch("emit");
    let scene = repo().join("examples/hello/scene.rt");
    let out_dir = dir.join("out");
    let emit = |what: &str| {
        let out = rtc(&["compile", s(&scene), "--emit", what, "--out", s(&out_dir)]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
        String::from_utf8(out.stdout).expect("UTF-8")
    };
    let hir = emit("hir");
    assert!(
        hir.starts_with("// module std/prelude.rt (prelude)\n"),
        "{hir}"
    );
    assert!(hir.contains("\nscene hello {\n"), "{hir}");
    assert!(
        hir.contains("\nfn render_invocation("),
        "the kernel is listed"
    );
    let naga = emit("naga");
    assert!(naga.starts_with("// naga module: types "), "{naga}");
    assert!(naga.contains("\n// entry point [0]\n@compute"), "{naga}");
    assert!(!out_dir.exists(), "--emit writes no files");

    let out = rtc(&[
        "compile",
        s(&scene),
        "--target",
        "wgsl",
        "--out",
        s(&out_dir),
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let wgsl = std::fs::read_to_string(out_dir.join("kernel.wgsl")).expect("kernel.wgsl");
    let code_only: Vec<&str> = naga
        .lines()
        .skip(3)
        .filter(|l| !l.starts_with("// "))
        .collect();
    let wgsl_lines: Vec<&str> = wgsl.lines().collect();
    assert_eq!(
        code_only, wgsl_lines,
        "the listing is the WGSL output plus comments"
    );
}
