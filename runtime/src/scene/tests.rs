//! Unit tests of the entity stage on scenes written in the language (checked and linked by the
//! compiler, no GPU): parameter packing, the light and medium tables, mesh and texture records,
//! instancing, rigid motion, the TLAS order of instance slots, custom-geometry bounds, and errors.
//!
//! The strongest check is [`trace`]: a CPU two-level traversal that reads only the buffers
//! (`nodes` from `tlas_root`, `instances` by slot, `triangles` from `triangle_offset`), exactly as
//! the kernel does, and must find the object and triangle a ray was aimed at.

use glam::{Mat4, Vec3, Vec4};
use rtc_bvh::quantized::QuantizedBvh;
use rtc_bvh::traverse::{closest_hit_quantized_with, intersect_triangle, Hit, Ray};
use rtc_bvh::{Aabb, BuildPreset, NodeRecord};
use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::layout;
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions, Linked};
use rtc_compiler::sema::hir::{Program, Role};

use super::entities::CustomBounds;
use super::*;
use crate::assets::texture::pack_f16x2;

/// Checks and links the only scene of `text` (as the file `name`).
fn compile_at(name: &str, text: &str) -> (Program, Linked) {
    let checked = check_text(name, text, &Options::default());
    assert!(
        !checked.has_errors(),
        "{}",
        rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false)
    );
    let program = checked.program.expect("a program without errors");
    let scene = program.select_scene(None).expect("one scene");
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .unwrap_or_else(|d| panic!("link: {d:?}"));
    (program, linked)
}

fn compile(text: &str) -> (Program, Linked) {
    compile_at("scene_test.rt", text)
}

fn build_with(p: &Program, l: &Linked, bvh: BuildPreset) -> Result<Entities, SceneError> {
    Entities::build(
        p,
        &p.scenes[l.scene],
        l,
        &EntityOptions {
            bvh,
            ..EntityOptions::default()
        },
    )
}

fn build_entities(p: &Program, l: &Linked) -> Entities {
    build_with(p, l, BuildPreset::Fast).expect("entities")
}

/// The id the link plan gave the struct called `name`.
fn id_of(p: &Program, l: &Linked, name: &str) -> u32 {
    l.types
        .values()
        .flatten()
        .find(|t| p.structs[t.struct_id].name == name)
        .map(|t| t.id)
        .unwrap_or_else(|| panic!("`{name}` is not linked"))
}

/// Word offset of field `field` of struct `name`, from the compiler's layout.
fn field_word(p: &Program, name: &str, field: &str) -> usize {
    let (s, st) = p
        .structs
        .iter()
        .find(|(_, s)| s.name == name)
        .expect("struct exists");
    let ty = super::params::struct_type(p, s).expect("struct type");
    let index = st.field_index(field).expect("field exists");
    (layout::field_offsets(p, ty)[index] / 4) as usize
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

const HEADER: &str = r#"
import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/lights/point.rt";
import "std/miss/constant.rt";
"#;

#[test]
fn params_hold_every_instance_at_the_compilers_offsets() {
    let text = format!(
        "{HEADER}
scene s {{
    settings {{ width: 64, height: 32, samples: 8, seed: 7 }}
    camera Pinhole {{ fov: 30.0 }}
    background ConstantBackground {{ color: vec3f(0.1, 0.2, 0.3) }}
    object a {{ geometry: cube_mesh(), material: Lambert {{ albedo: vec3f(0.25, 0.5, 0.75) }} }}
    light key PointLight {{ position: vec3f(1.0, 2.0, 3.0), intensity: 5.0 }}
    light PointLight {{ position: vec3f(-1.0, 2.0, 3.0), color: vec3f(0.5) }}
}}"
    );
    let (p, l) = compile(&text);
    let e = build_entities(&p, &l);
    let w = e.params();

    // The material: albedo at word 0 of its instance, which starts on a 16-byte boundary.
    let obj = &e.objects()[0];
    assert_eq!(obj.material.type_id, id_of(&p, &l, "Lambert"));
    let m = obj.material.offset as usize;
    assert_eq!(m % 4, 0);
    assert_eq!(w[m..m + 3], bits(&[0.25, 0.5, 0.75]));

    // The camera: fov after three vec3f fields, each 16-byte aligned: word 11.
    assert_eq!(field_word(&p, "Pinhole", "fov"), 11);
    let c = e.camera().offset as usize;
    assert_eq!(e.camera().type_id, id_of(&p, &l, "Pinhole"));
    assert_eq!(w[c + 11], 30f32.to_bits());
    assert_eq!(w[c..c + 3], bits(&[0.0, 0.0, 5.0]), "default position");

    // The background.
    let bg = e.background().expect("a background");
    assert_eq!(bg.type_id, id_of(&p, &l, "ConstantBackground"));
    assert_eq!(
        w[bg.offset as usize..bg.offset as usize + 3],
        bits(&[0.1, 0.2, 0.3])
    );

    // The light table: [type_id, offset] per light, in scene order.
    let t = e.light_table() as usize;
    let point = id_of(&p, &l, "PointLight");
    let intensity = field_word(&p, "PointLight", "intensity");
    let color = field_word(&p, "PointLight", "color");
    assert_eq!((color, intensity), (4, 7));
    assert_eq!(w[t], point);
    assert_eq!(w[t + 2], point);
    let (l0, l1) = (w[t + 1] as usize, w[t + 3] as usize);
    assert_eq!(w[l0..l0 + 3], bits(&[1.0, 2.0, 3.0]));
    assert_eq!(w[l0 + intensity], 5f32.to_bits());
    assert_eq!(
        w[l0 + color..l0 + color + 3],
        bits(&[1.0, 1.0, 1.0]),
        "default colour"
    );
    assert_eq!(w[l1..l1 + 3], bits(&[-1.0, 2.0, 3.0]));
    assert_eq!(w[l1 + color..l1 + color + 3], bits(&[0.5, 0.5, 0.5]));
    assert_eq!(w[l1 + intensity], 1f32.to_bits(), "default intensity");

    // The frame uniforms point at all of it.
    let f = e.frame_uniforms(2, 8);
    assert_eq!(
        f,
        FrameUniforms {
            samples_per_pass: 2,
            total_samples: 8,
            seed: 7,
            tlas_root: e.tlas_root(),
            instance_count: 1,
            light_count: 2,
            light_table: t as u32,
            medium_count: 0,
            medium_table: e.medium_table().0,
            camera_type: e.camera().type_id,
            camera_offset: c as u32,
            background_type: bg.type_id,
            background_offset: bg.offset,
            path_slots: 0,
            passes_per_dispatch: 1,
        }
    );
    assert_eq!(e.settings().width, 64);
}

#[test]
fn identical_instances_are_stored_once() {
    let text = format!(
        "{HEADER}
scene s {{
    camera Pinhole {{}}
    let grey = Lambert {{ albedo: vec3f(0.5) }};
    object a {{ geometry: cube_mesh(), material: grey }}
    object b {{ geometry: cube_mesh(), material: grey, transform: translate(vec3f(3.0, 0.0, 0.0)) }}
    object c {{ geometry: cube_mesh(), material: Lambert {{ albedo: vec3f(0.5) }} }}
    object d {{ geometry: cube_mesh(), material: Lambert {{ albedo: vec3f(0.6) }} }}
}}"
    );
    let (p, l) = compile(&text);
    let e = build_entities(&p, &l);
    let offsets: Vec<u32> = e.objects().iter().map(|o| o.material.offset).collect();
    assert_eq!(offsets[0], offsets[1]);
    assert_eq!(offsets[0], offsets[2], "equal values share words");
    assert_ne!(offsets[0], offsets[3]);
}

const TEXTURED: &str = r#"
/// A material reading a texture and a mesh, to exercise handle records.
@material
struct Textured {
    tex: texture,
    shape: mesh,
    tint: vec3f = vec3f(1.0),
}

@closest_hit
fn textured(m: Textured, ray: Ray, hit: Hit) -> vec3f {
    let n = f32(mesh_triangle_count(m.shape));
    return sample(m.tex, hit.uv).xyz * m.tint * n;
}
"#;

#[test]
fn mesh_and_texture_records_point_into_nodes_triangles_and_texels() {
    let text = format!(
        "{HEADER}{TEXTURED}
scene s {{
    camera Pinhole {{}}
    object a {{
        geometry: sphere_mesh(1u),
        material: Textured {{ tex: solid_texture(vec4f(0.25, 0.5, 1.0, 1.0)), shape: cube_mesh() }},
    }}
    object b {{
        geometry: cube_mesh(),
        material: Textured {{ tex: solid_texture(vec4f(0.25, 0.5, 1.0, 1.0)), shape: sphere_mesh(1u) }},
    }}
    object c {{
        geometry: cube_mesh(),
        material: Textured {{ tex: solid_texture(vec4f(2.0, 0.0, 0.0, 1.0)), shape: cube_mesh() }},
    }}
}}"
    );
    let (p, l) = compile(&text);
    let e = build_entities(&p, &l);
    // Two distinct meshes (sphere first: first use), two distinct textures.
    assert_eq!(e.meshes().len(), 2);
    assert_eq!(e.stats().blas_builds, 2);
    assert_eq!(e.textures().len(), 2);
    let w = e.params();
    let tex_word = field_word(&p, "Textured", "tex");
    let mesh_word = field_word(&p, "Textured", "shape");

    for (obj, (mesh, texture)) in e.objects().iter().zip([(1, 0), (0, 0), (1, 1)]) {
        let m = obj.material.offset as usize;
        // Mesh record: [node_base, triangle_base, slot_count, 0].
        let rec = w[m + mesh_word] as usize;
        let me = &e.meshes()[mesh];
        assert_eq!(
            w[rec..rec + 4],
            [me.node_base, me.triangle_base, me.slots, 0]
        );
        // node_base is the BLAS's header: its quantisation frame starts at the mesh box's
        // minimum and covers its maximum.
        let records = &e.nodes()[me.node_base as usize..][..me.node_count as usize];
        let blas = QuantizedBvh::from_records(records).expect("header");
        assert_eq!(Vec3::from(blas.header.origin), Vec3::from(me.bounds.min));
        assert!(blas
            .header
            .point([0xffff; 3])
            .cmpge(Vec3::from(me.bounds.max))
            .all());
        // Texture record: [texel_base, width, height, format]; solid textures are rgba16f.
        let rec = w[m + tex_word] as usize;
        let te = &e.textures()[texture];
        assert_eq!(w[rec..rec + 4], [te.texel_base, 1, 1, 1]);
    }
    let t0 = e.textures()[0].texel_base as usize;
    let t1 = e.textures()[1].texel_base as usize;
    assert_eq!(
        e.texels()[t0..t0 + 2],
        [pack_f16x2(0.25, 0.5), pack_f16x2(1.0, 1.0)]
    );
    assert_eq!(
        e.texels()[t1..t1 + 2],
        [pack_f16x2(2.0, 0.0), pack_f16x2(0.0, 1.0)]
    );
    // The object using the sphere as geometry points at the same BLAS as the record.
    let sphere = &e.meshes()[0];
    let inst = e.instances_in_object_order()[0];
    assert_eq!(
        (inst.blas_root, inst.triangle_offset),
        (sphere.node_base, sphere.triangle_base)
    );
    assert_eq!(inst.geometry_type, GpuInstance::MESH_GEOMETRY);
}

/// Object `o`'s instance, read from the buffers as the kernel reads them.
fn world_to_object(inst: &GpuInstance) -> Mat4 {
    let [r0, r1, r2] = inst.world_to_object;
    Mat4::from_cols_array_2d(&[r0, r1, r2, [0.0, 0.0, 0.0, 1.0]]).transpose()
}

/// Two-level closest hit over the buffers only: `(object, triangle, t)`.
fn trace(e: &Entities, origin: Vec3, dir: Vec3) -> Option<(u32, u32, f32)> {
    let nodes = e.nodes();
    let tlas = QuantizedBvh::from_records(&nodes[e.tlas_root() as usize..]).expect("header");
    let tris = e.triangles();
    // The closest triangle found in each object (by object index).
    let mut triangle_of = vec![0u32; e.objects().len()];
    let hit = closest_hit_quantized_with(&tlas, &Ray::new(origin, dir), |slot, _, t_max| {
        let inst = e.instances()[slot as usize];
        let m = world_to_object(&inst);
        let ray = Ray {
            origin: m.transform_point3(origin),
            dir: m.transform_vector3(dir),
            tmin: 0.0,
            tmax: t_max,
        };
        // A BVH's records are addressed from its header; those after it are never reached.
        let blas = QuantizedBvh::from_records(&nodes[inst.blas_root as usize..]).expect("header");
        // The first `triangles` entry of the last slot hit (the closest: each hit lowers `t_max`).
        let mut slot_of_hit = 0;
        let h = closest_hit_quantized_with(&blas, &ray, |s, r, tm| {
            let k = (inst.triangle_offset + s) as usize * 3;
            let v = |i: usize| Vec3::from_slice(&tris[k + i][..3]);
            let hit = intersect_triangle(r, &[v(0), v(1), v(2)], tm).map(|(t, u, v)| Hit {
                t,
                u,
                v,
                prim: tris[k][3].to_bits(),
            });
            if hit.is_some() {
                slot_of_hit = k;
            }
            hit
        })?;
        // As the kernel's `intersect_mesh`: a flattened object's slot names its member record.
        let tag = tris[slot_of_hit + 1][3].to_bits();
        let owner = if tag == 0 {
            inst
        } else {
            e.instances()[(inst.object + tag - 1) as usize]
        };
        triangle_of[owner.object as usize] = h.prim;
        Some(Hit {
            prim: owner.object,
            ..h
        })
    })?;
    Some((hit.prim, triangle_of[hit.prim as usize], hit.t))
}

/// A row of `n` cubes along x, each 4 units apart, every second one scaled.
fn cube_row(n: usize) -> String {
    let mut objects = String::new();
    for i in 0..n {
        let scale = if i % 2 == 0 { "1.0" } else { "0.5" };
        objects.push_str(&format!(
            "    object o{i} {{ geometry: cube_mesh(), material: Lambert {{ albedo: vec3f({}.0) }}, \
             transform: translate(vec3f({}.0, 0.0, 0.0)) * scale({scale}) }}\n",
            i % 3,
            4 * i
        ));
    }
    format!("{HEADER}\nscene row {{\n    camera Pinhole {{}}\n{objects}}}")
}

#[test]
fn instance_slots_follow_the_tlas_leaf_order() {
    let (p, l) = compile(&cube_row(24));
    for preset in BuildPreset::ALL {
        let e = build_with(&p, &l, preset).expect("entities");
        let order = e.tlas_order().expect("TLAS built");
        assert_eq!(order.len(), 24);
        assert_eq!(e.instances().len(), 24);
        for (slot, inst) in e.instances().iter().enumerate() {
            assert_eq!(
                inst.object, order[slot],
                "slot {slot} holds the TLAS's primitive"
            );
            let obj = &e.objects()[inst.object as usize];
            let t = obj.transform.col(3);
            assert_eq!(
                inst.object_to_world.map(|r| r[3]),
                [t.x, t.y, t.z],
                "translation in w"
            );
            let back = world_to_object(inst) * obj.transform;
            assert!(
                back.abs_diff_eq(Mat4::IDENTITY, 1e-6),
                "rows of the inverse"
            );
        }
        // Every leaf's slots lie inside the leaf's box.
        let tlas = QuantizedBvh::from_records(&e.nodes()[e.tlas_root() as usize..]).unwrap();
        for (b, first, count) in tlas.leaves() {
            for slot in first..first + count {
                let x = 4.0 * e.instances()[slot as usize].object as f32;
                assert!(b.min.x <= x && x <= b.max.x);
            }
        }
        // Aim at every cube's centre from above: the two-level traversal finds exactly it.
        for i in 0..24u32 {
            let x = 4.0 * i as f32;
            let (object, triangle, t) =
                trace(&e, Vec3::new(x, 10.0, 0.1), -Vec3::Y).expect("a hit");
            assert_eq!(object, i);
            let half = if i % 2 == 0 { 1.0 } else { 0.5 };
            assert!((t - (10.0 - half)).abs() < 1e-5, "t {t}");
            // The cube's +y face is its third face: triangles 4 and 5.
            assert!(triangle == 4 || triangle == 5, "triangle {triangle}");
        }
        assert_eq!(trace(&e, Vec3::new(2.0, 10.0, 0.0), -Vec3::Y), None);
    }
}

fn build_flat(p: &Program, l: &Linked) -> Entities {
    Entities::build(
        p,
        &p.scenes[l.scene],
        l,
        &EntityOptions {
            flatten: true,
            ..EntityOptions::default()
        },
    )
    .expect("entities")
}

#[test]
fn static_objects_are_flattened_into_one_world_space_bvh_that_reports_each_object() {
    // Six cubes (one shared 12-triangle mesh) and a mirrored seventh, which keeps its own BVH.
    let text = cube_row(6).replace(
        "}\n}",
        "}\n    object mirrored { geometry: cube_mesh(), material: Lambert {}, \
         transform: translate(vec3f(0.0, 8.0, 0.0)) * scale(vec3f(-1.0, 1.0, 1.0)) }\n}",
    );
    let (p, l) = compile(&text);
    let plain = build_entities(&p, &l);
    let mut e = build_flat(&p, &l);
    assert_eq!(e.objects().len(), 7);
    assert_eq!((e.stats().flattened_objects, e.stats().flat_bvhs), (6, 1));
    // Two scene-level leaves (the group and the mirrored cube), then the group's six members.
    assert_eq!(e.instances().len(), 2 + 6);
    let order = e.tlas_order().expect("TLAS").to_vec();
    assert_eq!(&order[2..], &[0, 1, 2, 3, 4, 5]);
    let group = order
        .iter()
        .position(|&o| o == u32::MAX)
        .expect("a group slot");
    assert_eq!(
        e.instances()[group].object,
        2,
        "the group points at its first member's record"
    );
    assert!(
        order[..2].contains(&6),
        "the mirrored cube has a leaf of its own"
    );
    for (k, inst) in e.instances()[2..].iter().enumerate() {
        assert_eq!(inst.object, k as u32);
        assert_eq!(
            inst.world_to_object,
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0]
            ]
        );
        assert_eq!(inst.object_to_world, inst.world_to_object);
        let own = plain
            .instances()
            .iter()
            .find(|i| i.object == k as u32)
            .expect("object");
        assert_eq!(
            (inst.material_type, inst.material_offset),
            (own.material_type, own.material_offset)
        );
    }
    // Every ray finds the object and the mesh triangle it finds without flattening, at the same
    // distance up to the rounding of the baked vertices.
    let mut rays = Vec::new();
    for i in 0..7 {
        let target = if i == 6 {
            Vec3::new(0.3, 8.2, 0.1)
        } else {
            Vec3::new(4.0 * i as f32 + 0.2, 0.1, -0.15)
        };
        rays.push((
            target + Vec3::new(0.0, 0.0, 10.0),
            Vec3::new(0.0, 0.0, -1.0),
        ));
        rays.push((
            target + Vec3::new(0.0, 10.0, 0.0),
            Vec3::new(0.0, -1.0, 0.0),
        ));
    }
    for (origin, dir) in rays {
        let a = trace(&plain, origin, dir).expect("a hit without flattening");
        let b = trace(&e, origin, dir).expect("a hit with flattening");
        assert_eq!((a.0, a.1), (b.0, b.1), "object and triangle from {origin}");
        assert!((a.2 - b.2).abs() <= 1e-5 * a.2, "t {} against {}", a.2, b.2);
    }

    // Moving a flattened cube undoes the flattening: every object has its leaf again, no BVH is
    // built, and the moved cube is found where it went.
    let blas = e.stats().blas_builds;
    e.set_transform(3, Mat4::from_translation(Vec3::new(12.0, 5.0, 0.0)))
        .expect("move");
    assert!(e.refresh().expect("TLAS"));
    assert_eq!(e.stats().blas_builds, blas);
    assert_eq!((e.stats().flattened_objects, e.stats().flat_bvhs), (0, 0));
    assert_eq!(e.instances().len(), 7);
    let hit = trace(&e, Vec3::new(12.2, 5.1, 10.0), Vec3::new(0.0, 0.0, -1.0)).expect("moved cube");
    assert_eq!(hit.0, 3);
    assert!(trace(&e, Vec3::new(12.2, 0.1, 10.0), Vec3::new(0.0, 0.0, -1.0)).is_none());
}

#[test]
fn flattening_leaves_out_what_must_keep_its_own_bvh() {
    // One object alone is no group, and neither is an object that an animation moves.
    let (p, l) = compile(&cube_row(1));
    assert_eq!(build_flat(&p, &l).stats().flattened_objects, 0);
    let text = cube_row(3).replace("}\n}", "}\n    animate o1 move(vec3f(0.0, 1.0, 0.0))\n}");
    let (p, l) = compile(&text);
    let e = build_flat(&p, &l);
    assert_eq!(e.stats().flattened_objects, 2);
    let order = e.tlas_order().expect("TLAS");
    assert_eq!(&order[order.len() - 2..], &[0, 2]);
}

#[test]
fn objects_sharing_a_mesh_share_one_blas() {
    let dir = std::env::temp_dir().join(format!("rtc-scene-instancing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(
        dir.join("tri.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n",
    )
    .expect("obj");
    let text = format!(
        "{HEADER}
scene s {{
    camera Pinhole {{}}
    object a {{ geometry: load_mesh(\"tri.obj\"), material: Lambert {{}} }}
    object b {{ geometry: load_mesh(\"tri.obj\"), material: Lambert {{}}, transform: translate(vec3f(5.0, 0.0, 0.0)) }}
    object c {{ geometry: cube_mesh(), material: Lambert {{}} }}
    object d {{ geometry: cube_mesh(), material: Lambert {{}}, transform: rotate_y(30.0) }}
    object e {{ geometry: load_mesh(\"tri.obj\"), material: Lambert {{}}, transform: scale(2.0) }}
}}"
    );
    let name = dir.join("scene.rt");
    let (p, l) = compile_at(&name.display().to_string(), &text);
    let e = build_entities(&p, &l);
    assert_eq!(e.meshes().len(), 2, "one OBJ load, one cube");
    assert_eq!(e.stats().blas_builds, 2, "one BLAS per distinct mesh");
    assert_eq!(e.stats().triangles, 2 + 12);
    assert_eq!(e.stats().instanced_triangles, 3 * 2 + 2 * 12);
    let inst = e.instances_in_object_order();
    let shared = |a: usize, b: usize| {
        (inst[a].blas_root, inst[a].triangle_offset) == (inst[b].blas_root, inst[b].triangle_offset)
    };
    assert!(shared(0, 1) && shared(0, 4) && shared(2, 3));
    assert!(!shared(0, 2));
    // Slots of the triangles are in the buffers once per mesh.
    let slots: u32 = e.meshes().iter().map(|m| m.slots).sum();
    assert_eq!(e.triangles().len(), 3 * slots as usize);
    assert_eq!(e.attributes().len(), 2 * slots as usize);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn moving_an_object_rebuilds_only_the_tlas() {
    let (p, l) = compile(&cube_row(6));
    let mut e = build_entities(&p, &l);
    let before = e.versions();
    let blas: Vec<_> = e.nodes()[..e.tlas_root() as usize].to_vec();
    let (builds, tlas_builds) = (e.stats().blas_builds, e.stats().tlas_builds);
    assert!(!e.refresh().expect("refresh"), "nothing moved");
    assert_eq!(e.stats().tlas_builds, tlas_builds);

    let target = Mat4::from_translation(Vec3::new(0.0, 0.0, 40.0));
    e.set_transform(2, target).expect("move");
    assert!(e.refresh().expect("refresh"));
    assert_eq!(e.stats().blas_builds, builds, "no BLAS rebuilt");
    assert_eq!(e.stats().tlas_builds, tlas_builds + 1);
    // Compared as bits: quantised records hold integers in their float fields.
    assert_eq!(
        bytemuck::cast_slice::<NodeRecord, u32>(&e.nodes()[..e.tlas_root() as usize]),
        bytemuck::cast_slice::<NodeRecord, u32>(&blas),
        "BLASes untouched"
    );
    let after = e.versions();
    assert_ne!(after.nodes, before.nodes);
    assert_ne!(after.instances, before.instances);
    assert_eq!(
        (
            after.triangles,
            after.attributes,
            after.params,
            after.texels
        ),
        (
            before.triangles,
            before.attributes,
            before.params,
            before.texels
        )
    );
    // The cube is where it was moved to, and no longer where it was.
    assert_eq!(
        trace(&e, Vec3::new(0.0, 10.0, 40.0), -Vec3::Y).map(|h| h.0),
        Some(2)
    );
    assert_eq!(trace(&e, Vec3::new(8.0, 10.0, 0.0), -Vec3::Y), None);
    assert_eq!(
        trace(&e, Vec3::new(12.0, 10.0, 0.0), -Vec3::Y).map(|h| h.0),
        Some(3)
    );

    let singular = Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0));
    assert!(matches!(
        e.set_transform(1, singular),
        Err(SceneError::BadTransform { object: 1, .. })
    ));
    let projective = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, Vec4::new(0.0, 0.0, 1.0, 0.5));
    assert!(matches!(
        e.set_transform(1, projective.transpose()),
        Err(SceneError::BadTransform { .. })
    ));
    assert!(matches!(
        e.set_transform(99, Mat4::IDENTITY),
        Err(SceneError::NoSuchObject {
            object: 99,
            count: 6
        })
    ));
}

const SHAPES: &str = r#"
/// An analytic sphere (custom geometry).
@geometry
struct Ball {
    radius: f32 = 1.0,
}

@intersection
fn ball_hit(b: Ball, ray: Ray) -> Intersection {
    let a = dot(ray.dir, ray.dir);
    let h = dot(ray.origin, ray.dir);
    let c = dot(ray.origin, ray.origin) - b.radius * b.radius;
    let d = h * h - a * c;
    if d < 0.0 {
        return Intersection {};
    }
    let t = (-h - sqrt(d)) / a;
    return Intersection { t: t, normal: normalize(ray.origin + ray.dir * t) };
}

@bounds
fn ball_bounds(b: Ball) -> Aabb {
    return Aabb { min: vec3f(-b.radius), max: vec3f(b.radius) };
}

/// A participating medium with an any-hit program.
@material
struct Fog {
    density: f32 = 0.5,
}

@closest_hit
fn fog_shade(m: Fog, ray: Ray, hit: Hit) -> vec3f {
    return vec3f(0.0);
}

@any_hit
fn fog_any(m: Fog, ray: Ray, hit: Hit) -> bool {
    return true;
}

@medium
fn fog_medium(m: Fog, ray: Ray, t: f32, radiance: vec3f) -> vec3f {
    return radiance * exp(-m.density * t);
}
"#;

#[test]
fn custom_geometry_waits_for_bounds_and_media_are_listed_by_slot() {
    let text = format!(
        "{HEADER}{SHAPES}
scene s {{
    camera Pinhole {{}}
    object ball {{ geometry: Ball {{ radius: 2.0 }}, material: Fog {{}}, transform: translate(vec3f(10.0, 0.0, 0.0)) }}
    object floor {{ geometry: quad_mesh(), material: Lambert {{}} }}
    object fog {{ geometry: cube_mesh(), material: Fog {{ density: 0.25 }}, transform: translate(vec3f(-10.0, 0.0, 0.0)) }}
    object lost {{ geometry: Ball {{}}, material: Lambert {{}} }}
}}"
    );
    let (p, l) = compile(&text);
    let mut e = build_entities(&p, &l);
    assert!(e.needs_bounds() && e.has_custom_geometry());
    assert!(
        e.tlas_order().is_none(),
        "no TLAS before the bounds are known"
    );
    assert!(matches!(
        e.rebuild_tlas(),
        Err(SceneError::MissingBounds { object: 0 })
    ));
    let ball = id_of(&p, &l, "Ball");
    let inst = e.instances_in_object_order();
    assert_eq!(inst[0].geometry_type, ball);
    assert_eq!(
        e.params()[inst[0].geometry_offset as usize],
        2f32.to_bits(),
        "radius"
    );
    let all = GpuInstance::FLAG_ANY_HIT | GpuInstance::FLAG_MEDIUM;
    assert_eq!(
        inst.iter().map(|i| i.flags).collect::<Vec<_>>(),
        [all, 0, all, 0]
    );
    assert_eq!(
        inst.iter().map(|i| i.object).collect::<Vec<_>>(),
        [0, 1, 2, 3]
    );

    let r = Vec3::splat(2.0);
    e.set_custom_bounds(0, Some(Aabb::new(-r, r)))
        .expect("object 0");
    // A program that returned garbage leaves its object out of the scene.
    e.set_custom_bounds(3, Some(Aabb::new(Vec3::splat(f32::NAN), Vec3::ONE)))
        .expect("object 3");
    assert!(matches!(
        e.objects()[3].geometry,
        ObjectGeometry::Custom {
            bounds: CustomBounds::Invalid,
            ..
        }
    ));
    assert!(!e.needs_bounds());
    assert!(e.refresh().expect("TLAS"));
    assert_eq!(
        e.instances().len(),
        3,
        "the object without bounds is left out"
    );
    let order = e.tlas_order().expect("TLAS").to_vec();
    assert!(!order.contains(&3));
    let (table, count) = e.medium_table();
    assert_eq!(count, 2);
    let slots = e.params()[table as usize..(table + count) as usize].to_vec();
    let objects: Vec<u32> = slots
        .iter()
        .map(|&s| e.instances()[s as usize].object)
        .collect();
    assert_eq!(
        objects,
        [0, 2],
        "medium objects, by instance slot, in object order"
    );
    // The ball's world box is its bounds moved by its transform.
    assert_eq!(e.tlas_bounds().max.x, 12.0);
    assert_eq!(e.tlas_bounds().min.x, -11.0);

    // Moving a medium object re-sorts the table only when the slots change.
    let params_version = e.versions().params;
    e.set_transform(1, Mat4::from_translation(Vec3::new(0.0, 0.5, 0.0)))
        .expect("move");
    e.refresh().expect("TLAS");
    let slots_now: Vec<u32> = e.params()[table as usize..].to_vec();
    let same = slots_now == slots;
    assert_eq!(e.versions().params == params_version, same);
}

#[test]
fn scene_errors_are_typed() {
    // A glTF model that cannot be read: E0902 at the model's string.
    let text = format!(
        "{HEADER}
scene s {{
    camera Pinhole {{}}
    model \"missing.glb\" {{}}
}}"
    );
    let (p, l) = compile(&text);
    let err = Entities::build(&p, &p.scenes[l.scene], &l, &EntityOptions::default())
        .expect_err("the model is missing");
    assert!(
        matches!(err, SceneError::Asset { span: Some(_), .. }),
        "{err}"
    );
    let diag = err.to_diagnostic().expect("a diagnostic");
    assert_eq!(diag.code.0, "E0902");
    assert!(diag.message.contains("missing.glb"), "{}", diag.message);

    // An OBJ that cannot be read: E0902 at the string.
    let text = format!(
        "{HEADER}
scene s {{
    camera Pinhole {{}}
    object o {{ geometry: load_mesh(\"no/such/file.obj\"), material: Lambert {{}} }}
}}"
    );
    let (p, l) = compile(&text);
    let err = Entities::build(&p, &p.scenes[l.scene], &l, &EntityOptions::default())
        .expect_err("missing file");
    assert!(matches!(err, SceneError::Asset { span: Some(_), .. }));
    let diag = err.to_diagnostic().expect("a diagnostic");
    assert_eq!(diag.code.0, "E0902");
    assert!(diag.message.contains("file.obj"), "{}", diag.message);

    // A transform that flattens the object (the compiler refuses it in a scene, E0708, so it is
    // put in afterwards, as a glTF node's could come).
    let text = format!(
        "{HEADER}
scene s {{
    camera Pinhole {{}}
    object flat {{ geometry: cube_mesh(), material: Lambert {{}} }}
}}"
    );
    let (mut p, l) = compile(&text);
    p.scenes[l.scene].objects[0].transform[1][1] = 0.0;
    let err = Entities::build(&p, &p.scenes[l.scene], &l, &EntityOptions::default())
        .expect_err("singular");
    assert!(
        matches!(&err, SceneError::BadTransform { object: 0, name: Some(n), .. } if n == "flat"),
        "{err}"
    );

    // A link plan that is not this scene's.
    let (p, mut l) = compile(&cube_row(1));
    l.types.remove(&Role::Material);
    let err = Entities::build(&p, &p.scenes[l.scene], &l, &EntityOptions::default())
        .expect_err("unlinked");
    assert!(matches!(err, SceneError::Unlinked { ref name } if name == "Lambert"));
}

#[test]
fn an_empty_scene_has_an_empty_tlas() {
    let text = format!("{HEADER}\nscene s {{ camera Pinhole {{}} }}");
    let (p, l) = compile(&text);
    let e = build_entities(&p, &l);
    assert_eq!(e.tlas_root(), 0);
    assert_eq!(e.nodes().len(), 1, "one empty leaf");
    assert!(e.instances().is_empty());
    assert_eq!(e.frame_uniforms(1, 1).instance_count, 0);
    assert!(e.triangles().is_empty() && e.params().len() >= 4);
}

#[test]
fn srgb_textures_are_decoded_in_order_while_all_texels_fit_the_budget() {
    use super::entities::textures_to_decode;
    let plan =
        |textures: &[(bool, u64)], budget| textures_to_decode(textures.iter().copied(), budget);
    // 30 bytes in all: decoding the first sRGB texture (10) makes 40, the second (4) then 44.
    let textures = [(true, 10), (false, 16), (true, 4)];
    assert_eq!(plan(&textures, 44), [true, false, true]);
    // At 43 the first still fits (40) and the second no longer (44); at 39 the first does not
    // fit (40), the smaller second does (34).
    assert_eq!(plan(&textures, 43), [true, false, false]);
    assert_eq!(plan(&textures, 39), [false, false, true]);
    // A budget of 0 (`SrgbTextures::Encoded`) decodes nothing; other formats never are.
    assert_eq!(plan(&textures, 0), [false, false, false]);
    assert_eq!(plan(&[(false, 1)], u64::MAX), [false]);
    assert!(plan(&[], 0).is_empty());
}

/// A scene whose object `a` is a cube textured with `t.png` (next to the scene), then `more`.
fn png_scene(more: &str) -> String {
    format!(
        "{HEADER}{TEXTURED}
scene s {{
    camera Pinhole {{}}
    object a {{
        geometry: cube_mesh(),
        material: Textured {{ tex: load_image(\"t.png\"), shape: cube_mesh() }},
    }}{more}
}}"
    )
}

/// A store keeps what it decoded: rebuilding the entities of an unchanged scene (what
/// `Renderer::replace_kernel` does after a program edit) decodes no texture again and shares the
/// same texels (one allocation, not a copy); a new image in the same file is decoded and
/// concatenated once more.
#[test]
fn a_store_decodes_an_unchanged_srgb_texture_once_over_rebuilds() {
    let dir = std::env::temp_dir().join(format!("rtc_srgb_store_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let save = |pixels: Vec<u8>, width: u32| {
        let png: image::RgbaImage = image::ImageBuffer::from_raw(width, 1, pixels).unwrap();
        png.save(dir.join("t.png")).unwrap();
    };
    save(vec![0, 64, 128, 255, 255, 200, 100, 7], 2);
    let (p, l) = compile_at(dir.join("s.rt").to_str().unwrap(), &png_scene(""));
    let options = EntityOptions::default();
    let mut store = AssetStore::new();
    let build = |store: &mut AssetStore| {
        let e = Entities::build_with_store(&p, &p.scenes[l.scene], &l, &options, store)
            .expect("entities");
        assert_eq!(e.stats().decoded_textures, 1, "stored decoded");
        (e.texels().to_vec(), e.texels().as_ptr() as usize)
    };
    let (first, at) = build(&mut store);
    assert_eq!(store.counters().textures_decoded, 1);
    assert_eq!(store.counters().texel_concatenations, 1);
    let image = crate::assets::load_image(dir.join("t.png")).unwrap();
    assert_eq!(first, image.decoded_srgb().unwrap().words);
    for _ in 0..2 {
        assert_eq!(
            build(&mut store),
            (first.clone(), at),
            "the same texels, shared"
        );
        assert_eq!(store.counters().textures_decoded, 1, "not decoded again");
        assert_eq!(store.counters().texel_concatenations, 1, "not copied again");
    }
    // A new image (three texels, so the file's length changes) is read and decoded again.
    save(vec![10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120], 3);
    let (edited, _) = build(&mut store);
    assert_eq!(
        store.counters().textures_decoded,
        2,
        "the new image decoded"
    );
    assert_eq!(store.counters().texel_concatenations, 2);
    let image = crate::assets::load_image(dir.join("t.png")).unwrap();
    assert_eq!(edited, image.decoded_srgb().unwrap().words);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn scene_textures_from_8_bit_srgb_images_are_stored_decoded_unless_kept_encoded() {
    let dir = std::env::temp_dir().join(format!("rtc_srgb_entities_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png: image::RgbaImage =
        image::ImageBuffer::from_raw(2, 1, vec![0, 64, 128, 255, 255, 200, 100, 7]).unwrap();
    png.save(dir.join("t.png")).unwrap();
    let object_b = "
    object b {
        geometry: cube_mesh(),
        material: Textured { tex: solid_texture(vec4f(0.5)), shape: cube_mesh() },
    }";
    let (p, l) = compile_at(dir.join("s.rt").to_str().unwrap(), &png_scene(object_b));
    let tex_word = field_word(&p, "Textured", "tex");
    let image = crate::assets::load_image(dir.join("t.png")).unwrap();
    for (mode, decoded) in [(SrgbTextures::Decoded, 1), (SrgbTextures::Encoded, 0)] {
        let options = EntityOptions {
            srgb_textures: mode,
            ..EntityOptions::default()
        };
        let e = Entities::build(&p, &p.scenes[l.scene], &l, &options).expect("entities");
        assert_eq!(e.stats().decoded_textures, decoded, "{mode:?}");
        // Object a's texture record: [texel_base, width, height, format].
        let rec = e.params()[e.objects()[0].material.offset as usize + tex_word] as usize;
        let [base, w, h, format] = e.params()[rec..rec + 4] else {
            unreachable!()
        };
        let (want_format, want) = match mode {
            SrgbTextures::Decoded => (1, image.decoded_srgb().unwrap().words),
            SrgbTextures::Encoded => (0, image.words.clone()),
        };
        assert_eq!((w, h, format), (2, 1, want_format), "{mode:?}");
        assert_eq!(
            e.texels()[base as usize..][..want.len()],
            want[..],
            "{mode:?}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
