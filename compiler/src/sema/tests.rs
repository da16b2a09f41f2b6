//! Unit tests of semantic analysis on small programs: literal inference, constant evaluation,
//! overload resolution, name resolution, the HIR's invariants, programs and scenes, and the standard
//! library.

use crate::driver::{check_paths, check_text, Checked, Options};
use crate::sema::hir::{
    ConstValue, ExprKind, Function, Geometry, Interp, Literal, MeshAsset, Motion, Program,
    ProgramKind, Scalar, SceneChoiceError, TrackTarget,
};
use crate::sema::types::{Type, TypeTable};

fn check(src: &str) -> Checked {
    check_text("test.rt", src, &Options::default())
}

fn rendered(c: &Checked) -> String {
    crate::diag::render_human(&c.sources, &c.diagnostics, false)
}

/// Checks `src`, which must have no diagnostics at all, and returns its program.
fn program(src: &str) -> Program {
    let c = check(src);
    assert!(c.diagnostics.is_empty(), "{}", rendered(&c));
    c.program.expect("a program without errors")
}

fn codes(src: &str) -> Vec<&'static str> {
    check(src).diagnostics.iter().map(|d| d.code.0).collect()
}

fn function<'p>(p: &'p Program, name: &str) -> &'p Function {
    p.functions
        .values()
        .find(|f| f.name == name)
        .expect("function exists")
}

fn const_value(p: &Program, name: &str) -> ConstValue {
    p.consts
        .values()
        .find(|c| c.name == name)
        .map(|c| c.value.clone())
        .expect("constant exists")
}

/// Every literal of a function with its type.
fn literals(p: &Program, f: &str) -> Vec<(Literal, TyName)> {
    let f = function(p, f);
    f.body
        .exprs
        .values()
        .filter_map(|e| match &e.kind {
            ExprKind::Literal(l) => Some((l.clone(), TyName(p.type_name(e.ty)))),
            _ => None,
        })
        .collect()
}

/// A type's name, for comparisons in tests.
#[derive(Debug, PartialEq)]
struct TyName(String);

fn ty(s: &str) -> TyName {
    TyName(s.to_string())
}

#[test]
fn literal_inference_follows_the_context() {
    let p = program(
        "fn f(v: vec3f, k: u32, x: f32) -> vec3f {
            let n = 3;
            let m = k + 1;
            let w = 2 * v;
            let c = max(x, 0);
            let z: f32 = 4;
            return w * c * z + vec3f(f32(n), f32(m), 0);
        }",
    );
    let lits = literals(&p, "f");
    assert!(lits.contains(&(Literal::I32(3), ty("i32"))));
    assert!(lits.contains(&(Literal::U32(1), ty("u32"))));
    assert!(lits.contains(&(Literal::F32(2.0), ty("f32"))));
    assert!(lits.contains(&(Literal::F32(0.0), ty("f32"))));
    assert!(lits.contains(&(Literal::F32(4.0), ty("f32"))));
    assert!(lits.iter().all(|(_, t)| t.0 != "{error}"));
}

#[test]
fn literal_range_and_negation() {
    assert_eq!(
        codes("fn f() -> i32 { return -2147483648; }"),
        Vec::<&str>::new()
    );
    assert_eq!(codes("fn f() -> i32 { return 2147483648; }"), vec!["E0411"]);
    assert_eq!(codes("fn f() -> u32 { return -1; }"), vec!["E0411"]);
    assert_eq!(codes("fn f() -> i32 { return 1.5; }"), vec!["E0411"]);
}

#[test]
fn constants_are_evaluated_with_gpu_semantics() {
    let p = program(
        "const HALF: f32 = PI * 0.5;
         const AXIS: vec3f = normalize(vec3f(3.0, 0.0, 4.0));
         const DIV0: i32 = 7 / 0;
         const REM0: i32 = 7 % 0;
         const WRAP: u32 = 0u - 1u;
         const SHIFT: u32 = 1u << 33u;
         const M: mat4x4f = translate(vec3f(1.0, 2.0, 3.0)) * scale(2.0);
         const P: vec3f = transform_point(M, vec3f(1.0));
         const N: u32 = 4u;
         const TABLE: array<f32, N> = array<f32, N>(0.0, 1.0, 2.0, HALF);
         const PICK: f32 = TABLE[3];
         const BITS: u32 = bitcast<u32>(1.0);",
    );
    let f = |v: f32| ConstValue::Scalar(Scalar::F32(v));
    assert_eq!(const_value(&p, "HALF"), f(std::f32::consts::PI * 0.5));
    assert_eq!(
        const_value(&p, "AXIS"),
        crate::sema::consteval::vector_f32(&[0.6, 0.0, 0.8])
    );
    assert_eq!(const_value(&p, "DIV0"), ConstValue::Scalar(Scalar::I32(7)));
    assert_eq!(const_value(&p, "REM0"), ConstValue::Scalar(Scalar::I32(0)));
    assert_eq!(
        const_value(&p, "WRAP"),
        ConstValue::Scalar(Scalar::U32(u32::MAX))
    );
    assert_eq!(const_value(&p, "SHIFT"), ConstValue::Scalar(Scalar::U32(2)));
    assert_eq!(
        const_value(&p, "P"),
        crate::sema::consteval::vector_f32(&[3.0, 4.0, 5.0])
    );
    assert_eq!(const_value(&p, "PICK"), f(std::f32::consts::PI * 0.5));
    assert_eq!(
        const_value(&p, "BITS"),
        ConstValue::Scalar(Scalar::U32(0x3f80_0000))
    );
    assert_eq!(
        const_value(&p, "INF"),
        ConstValue::Scalar(Scalar::F32(f32::INFINITY))
    );
}

#[test]
fn overloads_pick_the_generic_instance() {
    let p = program(
        "fn f(a: vec3f, b: vec3f, i: vec2i) -> f32 {
            let m = mix(a, b, 0.5);
            let s = select(0.0, 1.0, a.x > b.x);
            let d = dot(i, i);
            return m.x + s + f32(d) + length(a);
        }",
    );
    let f = function(&p, "f");
    let builtin_types: Vec<String> = f
        .body
        .exprs
        .values()
        .filter(|e| matches!(e.kind, ExprKind::Builtin { .. }))
        .map(|e| p.type_name(e.ty))
        .collect();
    assert_eq!(builtin_types, vec!["vec3f", "f32", "i32", "f32"]);
    assert_eq!(
        codes("fn f(x: f32, n: u32) -> f32 { return max(x, n); }"),
        vec!["E0404"]
    );
    assert_eq!(
        codes("fn f(x: f32) -> f32 { return max(x); }"),
        vec!["E0403"]
    );
}

#[test]
fn splats_and_defaults_are_explicit() {
    let p = program(
        "fn f(v: vec3f, o: vec3f) -> Ray {
            let w = v * 2.0 + 1.0;
            return Ray { origin: o, dir: w };
        }",
    );
    let f = function(&p, "f");
    let splats = f
        .body
        .exprs
        .values()
        .filter(|e| matches!(e.kind, ExprKind::Splat { .. }))
        .count();
    assert_eq!(splats, 2);
    let ray = p.framework.ray.expect("Ray");
    let lit = f
        .body
        .exprs
        .values()
        .find(|e| p.types.get(e.ty) == Type::Struct(ray))
        .expect("the struct literal");
    let ExprKind::Compose { components } = &lit.kind else {
        panic!("a struct literal is a Compose")
    };
    assert_eq!(components.len(), p.structs[ray].fields.len());
    // `tmax` (the fourth field) was omitted: its default, INF, is filled in.
    assert!(matches!(
        &f.body.exprs[components[3]].kind,
        ExprKind::Value(ConstValue::Scalar(Scalar::F32(x))) if x.is_infinite()
    ));
}

#[test]
fn matrices_from_scalars_are_built_from_columns() {
    let p = program("fn f(x: f32) -> mat2x2f { return mat2x2f(x, 0.0, 0.0, x); }");
    let f = function(&p, "f");
    let columns = f
        .body
        .exprs
        .values()
        .filter(|e| p.type_name(e.ty) == "vec2f" && matches!(e.kind, ExprKind::Compose { .. }))
        .count();
    assert_eq!(columns, 2);
}

#[test]
fn names_shadow_and_resolve_in_order() {
    program(
        "fn f(v: vec3f) -> f32 {
            let length = length(v);
            let PI = 3.0;
            return length * PI;
        }",
    );
    assert_eq!(
        codes("fn f(v: vec3f) -> f32 { let length = 1.0; return length(v); }"),
        vec!["E0414"]
    );
    assert_eq!(codes("fn f() -> f32 { return nope; }"), vec!["E0303"]);
}

#[test]
fn function_order_puts_callees_first() {
    let p = program(
        "fn c() -> f32 { return 1.0; }
         fn a() -> f32 { return b() + c(); }
         fn b() -> f32 { return c(); }",
    );
    let pos = |n: &str| {
        p.fn_order
            .iter()
            .position(|f| p.functions[*f].name == n)
            .expect("in order")
    };
    assert!(pos("c") < pos("b") && pos("b") < pos("a"));
    assert_eq!(p.fn_order.len(), p.functions.len());
    assert_eq!(function(&p, "a").callees.len(), 2);
}

#[test]
fn programs_record_kind_struct_and_spawn_bound() {
    let p = program(
        "import \"std/materials/glass.rt\";
         @material
         struct Fan { n: u32 = 2u }
         fn two(n: vec3f) {
             spawn(n, vec3f(0.5));
             spawn(-n, vec3f(0.5));
         }
         @secondary_rays
         fn fan_rays(m: Fan, ray: Ray, hit: Hit) {
             for _i in 0..3 {
                 two(hit.normal);
             }
         }
         @closest_hit
         fn fan_shade(m: Fan, ray: Ray, hit: Hit) -> vec3f { return vec3f(0.0); }
         @camera
         struct Cam { fov: f32 = 45.0 }
         @ray_generation(samples = 8)
         fn cam_ray(c: Cam, pixel: vec2u, sample: u32) -> Ray {
             return Ray { origin: vec3f(0.0), dir: vec3f(0.0, 0.0, -1.0) };
         }",
    );
    let entry = |name: &str| {
        *p.programs
            .iter()
            .find(|e| p.functions[e.func].name == name)
            .expect("program")
    };
    assert_eq!(entry("fan_rays").spawn_bound, 6);
    // One branch spawns one ray, the other two: the bound is the larger branch.
    assert_eq!(entry("glass_rays").spawn_bound, 2);
    assert!(entry("glass_shade").wants_secondary);
    assert!(!entry("fan_shade").wants_secondary);
    assert_eq!(entry("cam_ray").samples, 8);
    assert_eq!(entry("cam_ray").kind, ProgramKind::RayGeneration);
    let fan = entry("fan_rays").struct_id;
    assert_eq!(
        p.structs[fan].program(ProgramKind::ClosestHit),
        Some(entry("fan_shade").func)
    );
}

#[test]
fn scenes_are_evaluated() {
    let p = program(
        "import \"std/cameras/pinhole.rt\";
         import \"std/materials/lambert.rt\";
         import \"std/lights/point.rt\";
         scene s {
             settings { width: 64, height: 32, samples: 4 }
             camera Pinhole { fov: 30.0 }
             let grey = Lambert { albedo: vec3f(0.5) };
             object floor { geometry: quad_mesh(), material: grey, transform: scale(4.0) }
             object ball { geometry: load_mesh(\"ball.obj\"), material: grey }
             light PointLight { position: vec3f(0.0, 3.0, 0.0) }
         }",
    );
    let id = p.select_scene(None).expect("one scene");
    let s = &p.scenes[id];
    assert_eq!(
        (s.settings.width, s.settings.height, s.settings.samples),
        (64, 32, 4)
    );
    assert_eq!(s.settings.max_depth, 4);
    let cam = s.camera.as_ref().expect("camera");
    let fov = p.structs[cam.struct_id].field_index("fov").expect("fov");
    assert_eq!(cam.fields[fov], ConstValue::Scalar(Scalar::F32(30.0)));
    assert_eq!(s.objects.len(), 2);
    assert_eq!(s.objects[0].geometry, Geometry::Mesh(MeshAsset::Quad));
    assert_eq!(s.objects[0].transform[0][0], 4.0);
    assert_eq!(s.objects[1].transform, crate::sema::hir::IDENTITY);
    match &s.objects[1].geometry {
        Geometry::Mesh(MeshAsset::File { path, .. }) => assert!(path.ends_with("ball.obj")),
        g => panic!("unexpected geometry {g:?}"),
    }
    assert_eq!(s.lights.len(), 1);
    assert_eq!(
        p.select_scene(Some("t")),
        Err(SceneChoiceError::NotFound {
            name: "t".to_string(),
            available: vec!["s".to_string()]
        })
    );
}

#[test]
fn animate_entries_become_tracks() {
    let p = program(
        "import \"std/cameras/pinhole.rt\";
         import \"std/materials/lambert.rt\";
         import \"std/lights/point.rt\";
         scene s {
             settings { fps: 10 }
             animate ball spin(vec3f(0.0, 2.0, 0.0), 90.0)
             camera Pinhole {}
             object floor { geometry: quad_mesh(), material: Lambert {} }
             object ball { geometry: cube_mesh(), material: Lambert {} }
             light PointLight { position: vec3f(0.0, 3.0, 0.0) }
             light key PointLight { position: vec3f(0.0, 3.0, 0.0) }
             animate key.intensity keys step { 0.0: 1.0, 2.5: 2.0 }
             animate camera.fov keys smooth { 0.5: 40.0, 1.0: 50.0 }
         }",
    );
    let s = &p.scenes[p.select_scene(None).expect("one scene")];
    assert_eq!(s.settings.frames, 26, "2.5 s at 10 fps, frame 25 included");
    let targets: Vec<&TrackTarget> = s.animation.iter().map(|t| &t.target).collect();
    let pinhole = s.camera.as_ref().expect("camera").struct_id;
    let fov = p.structs[pinhole].field_index("fov").expect("fov");
    assert!(matches!(targets[0], TrackTarget::Object(1)), "{targets:?}");
    assert!(
        matches!(targets[1], TrackTarget::Light { light: 1, name, .. } if name == "intensity"),
        "{targets:?}"
    );
    assert!(
        matches!(targets[2], TrackTarget::Camera { field, .. } if *field == fov),
        "{targets:?}"
    );
    assert_eq!(
        s.animation[0].motion,
        Motion::Spin {
            axis: [0.0, 1.0, 0.0],
            degrees_per_second: 90.0,
            pivot: [0.0; 3]
        }
    );
    match &s.animation[2].motion {
        Motion::Keys {
            times,
            values,
            interp,
        } => {
            assert_eq!(
                (times.as_slice(), *interp),
                (&[0.5, 1.0][..], Interp::Smooth)
            );
            assert_eq!(values[1], ConstValue::Scalar(Scalar::F32(50.0)));
        }
        m => panic!("unexpected motion {m:?}"),
    }
    let listing = crate::sema::hir::print::program(&p);
    assert!(
        listing.contains("animation { fps: 10, frames: 26 }"),
        "{listing}"
    );
    assert!(
        listing.contains("animate light#1.intensity keys step { 0.0: 1.0, 2.5: 2.0 }"),
        "{listing}"
    );
}

#[test]
fn several_scenes_need_a_name() {
    let p = program(
        "import \"std/cameras/pinhole.rt\";
         scene a { camera Pinhole {} }
         scene b { camera Pinhole {} }",
    );
    let err = p.select_scene(None).expect_err("ambiguous");
    assert!(matches!(err, SceneChoiceError::Ambiguous { .. }));
    assert_eq!(err.to_diagnostic().map(|d| d.code.0), Some("E0706"));
    assert!(p.select_scene(Some("b")).is_ok());
}

#[test]
fn errors_do_not_cascade() {
    // One undefined name used many times gives one diagnostic per use, and nothing else.
    assert_eq!(
        codes(
            "fn f() -> vec3f { let a = nope * 2.0; let b = a + vec3f(1.0); return normalize(b); }"
        ),
        vec!["E0303"]
    );
}

#[test]
fn invalid_utf8_is_reported_at_the_first_bad_byte() {
    let dir = std::env::temp_dir().join(format!("rtc-sema-utf8-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("bad.rt");
    std::fs::write(&file, b"fn f() {}\n// \xff\xfe\n").expect("write");
    let c = check_paths(&[file], &Options::default());
    let d = &c.diagnostics[0];
    assert_eq!(d.code.0, "E0108");
    assert_eq!(d.primary.span.lo, 13);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_stdlib_is_typed_and_ordered() {
    let dir = Options::default().stdlib_dir;
    let mut files = Vec::new();
    for sub in std::fs::read_dir(&dir).expect("stdlib") {
        let p = sub.expect("entry").path();
        if p.is_dir() {
            files.extend(
                std::fs::read_dir(&p)
                    .expect("dir")
                    .map(|f| f.expect("entry").path()),
            );
        }
    }
    let c = check_paths(&files, &Options::default());
    assert!(c.diagnostics.is_empty(), "{}", rendered(&c));
    let p = c.program.expect("program");
    // Every expression is typed and nothing is an error.
    for f in p.functions.values() {
        for e in f.body.exprs.values() {
            assert!(
                !TypeTable::is_error(e.ty),
                "untyped expression in {}",
                f.name
            );
            assert!(!matches!(e.kind, ExprKind::Error));
        }
    }
    // Callees come before callers.
    for (i, f) in p.fn_order.iter().enumerate() {
        for c in &p.functions[*f].callees {
            let at = p
                .fn_order
                .iter()
                .position(|x| x == c)
                .expect("callee ordered");
            assert!(at < i);
        }
    }
    assert!(p.programs.len() >= 9);
}

#[test]
fn closest_hits_additive_in_secondary_are_recognised() {
    // `E + secondary`, `secondary + E` and `secondary` on every return are additive; scaling it,
    // reading it in `E`, passing it on or a return without it are not.
    let mut src = String::new();
    let cases = [
        ("plus", "return m.a + secondary;", true),
        (
            "plus_left",
            "if ray.depth > 0u { return secondary + m.a; } return vec3f(1.0) + secondary;",
            true,
        ),
        ("alone", "return secondary;", true),
        ("scaled", "return m.a * secondary;", false),
        ("read_twice", "return secondary.x * m.a + secondary;", false),
        ("passed", "return id(secondary);", false),
        (
            "one_return_without",
            "if ray.depth > 0u { return m.a; } return m.a + secondary;",
            false,
        ),
        ("let_first", "let s = secondary; return m.a + s;", false),
    ];
    src.push_str("fn id(v: vec3f) -> vec3f { return v; }\n");
    for (name, body, _) in cases {
        src.push_str(&format!(
            "@material struct M_{name} {{ a: vec3f = vec3f(0.5) }}
             @closest_hit fn {name}(m: M_{name}, ray: Ray, hit: Hit, secondary: vec3f) -> vec3f {{ {body} }}\n"
        ));
    }
    let p = program(&src);
    for (name, _, want) in cases {
        let entry = p
            .programs
            .iter()
            .find(|e| p.functions[e.func].name == name)
            .expect("program");
        assert_eq!(entry.additive_secondary, want, "{name}");
    }
}
