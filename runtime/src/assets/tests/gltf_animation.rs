//! glTF node animation (`model/animation.rs`): a generated file with translation, rotation and
//! scale channels under STEP, LINEAR and CUBICSPLINE, each node's world transform at sampled
//! times compared with matrices computed by hand from the keys (tolerance 1e-5 per matrix
//! element), a child following its animated parent, and the warnings for what is not played.

use std::path::Path;

use glam::{Mat4, Quat, Vec3};
use serde_json::json;

use super::gltf_builder::{triangle, Builder};
use crate::assets::model::animation::{sample, Interp, Path as Target};
use crate::assets::model::{parse_gltf, ModelScene};

/// Matrix elements agree to this.
const EPS: f32 = 1e-5;

/// A `SCALAR` of `F32` accessor with `min`/`max` (glTF requires them on sampler inputs).
fn times(b: &mut Builder, t: &[f32]) -> usize {
    let bytes: Vec<u8> = t.iter().flat_map(|x| x.to_le_bytes()).collect();
    let view = b.view(&bytes, None);
    b.accessor(json!({
        "bufferView": view, "componentType": 5126, "count": t.len(), "type": "SCALAR",
        "min": [t[0]], "max": [t[t.len() - 1]],
    }))
}

/// A `VEC4` of `F32` accessor.
fn vec4(b: &mut Builder, v: &[[f32; 4]]) -> usize {
    let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
    let view = b.view(&bytes, None);
    b.accessor(json!({
        "bufferView": view, "componentType": 5126, "count": v.len(), "type": "VEC4",
    }))
}

const S45: f32 = std::f32::consts::FRAC_1_SQRT_2;

/// Nodes: 0 (mesh; translation LINEAR, rotation LINEAR) with child 1 (mesh, static
/// translation (0, 2, 0)); 2 (mesh; scale STEP, translation CUBICSPLINE, rotation CUBICSPLINE);
/// 3 (mesh; rotation STEP, scale LINEAR starting at t = 1); 4 (mesh, never animated).
/// Animation 0 also has a `weights` channel; animation 1 exists and is not played.
fn animated_file() -> ModelScene {
    let (mut b, pos, idx) = triangle();
    let t012 = times(&mut b, &[0.0, 1.0, 2.0]);
    let t02 = times(&mut b, &[0.0, 2.0]);
    let t01 = times(&mut b, &[0.0, 1.0]);
    let t13 = times(&mut b, &[1.0, 3.0]);
    let trans0 = b.vec3(&[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 4.0, 0.0]]);
    let rot0 = vec4(&mut b, &[[0.0, 0.0, 0.0, 1.0], [0.0, S45, 0.0, S45]]);
    let scale2 = b.vec3(&[[1.0, 1.0, 1.0], [2.0, 3.0, 4.0]]);
    // in-tangent, value, out-tangent per key.
    let cubic_t2 = b.vec3(&[
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [0.0, 0.0, 0.0],
    ]);
    let cubic_r2 = vec4(
        &mut b,
        &[
            [0.0; 4],
            [0.0, 0.0, 0.0, 1.0],
            [0.0; 4],
            [0.0; 4],
            [S45, 0.0, 0.0, S45],
            [0.0; 4],
        ],
    );
    let rot3 = vec4(&mut b, &[[0.0, 0.0, 0.0, 1.0], [0.0, 0.0, S45, S45]]);
    let scale3 = b.vec3(&[[1.0, 1.0, 1.0], [3.0, 3.0, 3.0]]);
    let weights_in = times(&mut b, &[0.0]);
    let weights = {
        let bytes = 0.5f32.to_le_bytes();
        let view = b.view(&bytes, None);
        b.accessor(json!({"bufferView": view, "componentType": 5126, "count": 1, "type": "SCALAR"}))
    };
    let sampler = |input: usize, output: usize, interp: &str| json!({"input": input, "output": output, "interpolation": interp});
    let channel = |sampler: usize, node: usize, path: &str| json!({"sampler": sampler, "target": {"node": node, "path": path}});
    let doc = b.document(
        Some("data:application/octet-stream;base64,"),
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx }] }],
            "nodes": [
                { "name": "parent", "mesh": 0, "children": [1] },
                { "name": "child", "mesh": 0, "translation": [0.0, 2.0, 0.0] },
                { "mesh": 0, "translation": [9.0, 9.0, 9.0] },
                { "mesh": 0 },
                { "mesh": 0, "translation": [0.0, 0.0, -5.0] },
            ],
            "scenes": [{ "nodes": [0, 2, 3, 4] }],
            "scene": 0,
            "animations": [
                {
                    "name": "main",
                    "samplers": [
                        sampler(t012, trans0, "LINEAR"),
                        sampler(t02, rot0, "LINEAR"),
                        sampler(t01, scale2, "STEP"),
                        sampler(t02, cubic_t2, "CUBICSPLINE"),
                        sampler(t02, cubic_r2, "CUBICSPLINE"),
                        sampler(t01, rot3, "STEP"),
                        sampler(t13, scale3, "LINEAR"),
                        sampler(weights_in, weights, "LINEAR"),
                    ],
                    "channels": [
                        channel(0, 0, "translation"),
                        channel(1, 0, "rotation"),
                        channel(2, 2, "scale"),
                        channel(3, 2, "translation"),
                        channel(4, 2, "rotation"),
                        channel(5, 3, "rotation"),
                        channel(6, 3, "scale"),
                        channel(7, 4, "weights"),
                    ],
                },
                {
                    "name": "other",
                    "samplers": [sampler(t01, scale2, "STEP")],
                    "channels": [channel(0, 4, "scale")],
                },
            ],
        }),
    );
    // The buffer inline, as a data URI.
    let mut doc = doc;
    doc["buffers"][0]["uri"] = json!(format!(
        "data:application/octet-stream;base64,{}",
        super::gltf_builder::base64(&b.bin)
    ));
    parse_gltf(
        &serde_json::to_vec(&doc).expect("json"),
        Path::new("anim.gltf"),
    )
    .expect("the file loads")
}

#[track_caller]
fn assert_mat(got: Mat4, want: Mat4, what: &str) {
    assert!(
        got.abs_diff_eq(want, EPS),
        "{what}:\n got {got:?}\nwant {want:?}"
    );
}

/// Hermite basis at `u`: (h00, h10, h01, h11).
fn hermite(u: f32) -> (f32, f32, f32, f32) {
    let (u2, u3) = (u * u, u * u * u);
    (
        2.0 * u3 - 3.0 * u2 + 1.0,
        u3 - 2.0 * u2 + u,
        -2.0 * u3 + 3.0 * u2,
        u3 - u2,
    )
}

#[test]
fn every_channel_and_interpolation_at_sampled_times() {
    let scene = animated_file();
    let anim = scene.animation.as_ref().expect("an animation");
    assert_eq!(anim.label, "animations[0] (`main`)");
    assert_eq!(
        anim.channels.len(),
        7,
        "the weights channel is not imported"
    );
    assert_eq!(anim.duration, 3.0);
    for n in 0..4 {
        assert!(anim.moves(n), "nodes[{n}] moves");
    }
    assert!(!anim.moves(4), "nodes[4] is only targeted by weights");

    for t in [0.0f32, 0.25, 0.5, 0.99, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0] {
        let world = anim.evaluate(t);
        // Node 0: translation LINEAR through (0,0,0) at 0, (2,0,0) at 1, (2,4,0) at 2; rotation
        // LINEAR (slerp) from identity to 90° about y over 0..2, i.e. 45° per second.
        let tr = if t <= 1.0 {
            Vec3::new(2.0 * t, 0.0, 0.0)
        } else {
            Vec3::new(2.0, 4.0 * (t.min(2.0) - 1.0), 0.0)
        };
        let r = Quat::from_rotation_y((45.0 * t.min(2.0)).to_radians());
        let w0 = Mat4::from_rotation_translation(r, tr);
        assert_mat(world[0], w0, &format!("nodes[0] at {t}"));
        // Node 1 follows its parent.
        assert_mat(
            world[1],
            w0 * Mat4::from_translation(Vec3::new(0.0, 2.0, 0.0)),
            &format!("nodes[1] at {t}"),
        );
        // Node 2: scale STEP (1 until t = 1, then (2,3,4)); translation CUBICSPLINE replaces
        // the rest (9,9,9): x = 2·h10·1 + h01·4 on u = t/2 (tangents scaled by the interval 2);
        // rotation CUBICSPLINE with zero tangents: h00·q0 + h01·q1 normalised, about x with
        // half-angle atan2(h01·sin45°, h00 + h01·cos45°).
        let s = if t < 1.0 {
            Vec3::ONE
        } else {
            Vec3::new(2.0, 3.0, 4.0)
        };
        let u = (t / 2.0).min(1.0);
        let (h00, h10, h01, _) = hermite(u);
        let x = if t >= 2.0 { 4.0 } else { 2.0 * h10 + 4.0 * h01 };
        let half = (h01 * S45).atan2(h00 + h01 * S45);
        let r2 = Quat::from_rotation_x(2.0 * half);
        assert_mat(
            world[2],
            Mat4::from_scale_rotation_translation(s, r2, Vec3::new(x, 0.0, 0.0)),
            &format!("nodes[2] at {t}"),
        );
        // Node 3: rotation STEP (identity before 1, 90° about z from 1); scale LINEAR from 1 at
        // t = 1 to 3 at t = 3 (the first key holds before it).
        let r3 = if t < 1.0 {
            Quat::IDENTITY
        } else {
            Quat::from_rotation_z(90f32.to_radians())
        };
        let s3 = 1.0 + (t.clamp(1.0, 3.0) - 1.0);
        assert_mat(
            world[3],
            Mat4::from_scale_rotation_translation(Vec3::splat(s3), r3, Vec3::ZERO),
            &format!("nodes[3] at {t}"),
        );
        // Node 4 is not animated: its static transform.
        assert_mat(
            world[4],
            Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0)),
            &format!("nodes[4] at {t}"),
        );
    }

    // Spot values by hand: the cubic translation at t = 1 (u = 0.5): 2·0.125 + 4·0.5 = 2.25;
    // the cubic rotation at t = 1 is 45° about x.
    let cubic = anim
        .channels
        .iter()
        .find(|c| c.node == 2 && c.path == Target::Translation)
        .expect("cubic translation");
    assert_eq!(cubic.interp, Interp::CubicSpline);
    assert!((sample(cubic, 1.0)[0] - 2.25).abs() < EPS);
    let q = Quat::from_array(sample(
        anim.channels
            .iter()
            .find(|c| c.node == 2 && c.path == Target::Rotation)
            .expect("cubic rotation"),
        1.0,
    ));
    assert!(q.abs_diff_eq(Quat::from_rotation_x(45f32.to_radians()), EPS));

    // The static import is the rest pose (not the pose at t = 0): node 2 at (9, 9, 9).
    let rest = scene
        .instances
        .iter()
        .find(|i| i.node == 2)
        .expect("nodes[2]");
    assert_eq!(rest.transform.w_axis.truncate(), Vec3::splat(9.0));
}

#[test]
fn evaluation_is_pure() {
    let scene = animated_file();
    let anim = scene.animation.as_ref().expect("an animation");
    let a = anim.evaluate(0.7);
    let _ = anim.evaluate(2.9);
    assert_eq!(a, anim.evaluate(0.7));
}

#[test]
fn what_is_not_played_is_named() {
    let scene = animated_file();
    let w = scene.warnings.join("\n");
    assert!(
        w.contains(
            "animations[0] (`main`).channels[7]: animates the morph target weights of nodes[4], \
             which are not imported; skipped"
        ),
        "{w}"
    );
    assert!(
        w.contains(
            "animations[1] (`other`) not played: rtc plays a file's first animation \
             (animations[0] (`main`))"
        ),
        "{w}"
    );
}

#[test]
fn broken_samplers_are_skipped_with_a_warning() {
    let (mut b, pos, idx) = triangle();
    let bad_times = times(&mut b, &[1.0, 0.5]);
    let out = b.vec3(&[[0.0; 3], [1.0; 3]]);
    let short = b.vec3(&[[0.0; 3]]);
    let good = times(&mut b, &[0.0, 1.0]);
    let mut doc = b.document(
        None,
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx }] }],
            "nodes": [{ "mesh": 0 }, { "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "mesh": 0 }],
            "scenes": [{ "nodes": [0, 1] }],
            "animations": [{
                "samplers": [
                    { "input": bad_times, "output": out },
                    { "input": good, "output": short, "interpolation": "CUBICSPLINE" },
                    { "input": good, "output": out },
                ],
                "channels": [
                    { "sampler": 0, "target": { "node": 0, "path": "translation" } },
                    { "sampler": 1, "target": { "node": 0, "path": "scale" } },
                    { "sampler": 2, "target": { "node": 1, "path": "translation" } },
                ],
            }],
        }),
    );
    doc["buffers"][0]["uri"] = json!(format!(
        "data:application/octet-stream;base64,{}",
        super::gltf_builder::base64(&b.bin)
    ));
    let scene = parse_gltf(
        &serde_json::to_vec(&doc).expect("json"),
        Path::new("b.gltf"),
    )
    .expect("a broken animation does not stop the import");
    assert!(scene.animation.is_none(), "no channel was usable");
    assert_eq!(
        scene.warnings,
        [
            "animations[0].channels[0]: its key times are not finite, non-negative and increasing; skipped",
            "animations[0].channels[1]: its sampler has 1 output values for 2 keys (expected 6); skipped",
            "animations[0].channels[2]: nodes[1] is given by a `matrix`, which glTF forbids animating; skipped",
        ]
    );
}
