//! An orbit camera over a scene's camera instance: the `position` and `look_at` fields of the
//! standard library's pinhole and thin-lens cameras (any `@camera` struct with both as `vec3f`),
//! turned around the point looked at, panned across the view and zoomed, for interactive viewers
//! (`rtc view`, the web playground).
//!
//! Guarantees: the orbit keeps the distance to `look_at` and never passes the poles (the view
//! never flips); pan moves both points alike; zoom keeps the direction. [`apply`] writes the two
//! fields into a live [`Renderer`] (12 bytes each, and the accumulation restarts), and
//! [`write_orbit`] into a compiled scene (what a renderer built later reads); a camera without the
//! two fields has no orbit ([`read_orbit`] is `None`) and is never written.

use rtc_compiler::kernel::CompiledScene;
use rtc_compiler::sema::hir::{ConstValue, Scalar};

use crate::render::{FieldTarget, RenderError, Renderer};

/// An orbit camera: `position` and `look_at`, as the scene's camera fields.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// Where the camera is.
    pub position: [f32; 3],
    /// The point it looks at, which it turns around.
    pub look_at: [f32; 3],
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: [f32; 3], s: f32) -> [f32; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn length(a: [f32; 3]) -> f32 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

fn normalize(a: [f32; 3]) -> [f32; 3] {
    let l = length(a);
    if l > 0.0 {
        scale(a, 1.0 / l)
    } else {
        a
    }
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl Orbit {
    /// Turns around `look_at`: `yaw` about the world's y axis, `pitch` up and down (kept off the
    /// poles), in radians.
    pub fn orbit(&mut self, yaw: f32, pitch: f32) {
        let d = sub(self.position, self.look_at);
        let r = length(d).max(1e-4);
        let mut theta = d[2].atan2(d[0]) + yaw;
        let mut phi = (d[1] / r).clamp(-1.0, 1.0).asin() + pitch;
        phi = phi.clamp(-1.5, 1.5);
        if !theta.is_finite() {
            theta = 0.0;
        }
        self.position = add(
            self.look_at,
            [
                r * phi.cos() * theta.cos(),
                r * phi.sin(),
                r * phi.cos() * theta.sin(),
            ],
        );
    }

    /// Moves both points across the view: `dx`, `dy` in units of the distance to `look_at`.
    pub fn pan(&mut self, dx: f32, dy: f32) {
        let d = sub(self.look_at, self.position);
        let r = length(d);
        let forward = normalize(d);
        let right = normalize(cross(forward, [0.0, 1.0, 0.0]));
        let up = cross(right, forward);
        let shift = add(scale(right, -dx * r), scale(up, dy * r));
        self.position = add(self.position, shift);
        self.look_at = add(self.look_at, shift);
    }

    /// Moves towards `look_at` by `factor` of the distance (below 1 zooms in).
    pub fn zoom(&mut self, factor: f32) {
        let d = sub(self.position, self.look_at);
        let r = length(d);
        let target = (r * factor).clamp(1e-3, 1e6);
        self.position = add(self.look_at, scale(normalize(d), target));
    }
}

/// The indices of the `position` and `look_at` fields of the scene's camera, if it has both.
fn camera_fields(compiled: &CompiledScene) -> Option<(usize, usize)> {
    let program = compiled.checked.program.as_ref()?;
    let camera = program.scenes[compiled.scene].camera.as_ref()?;
    let s = &program.structs[camera.struct_id];
    Some((s.field_index("position")?, s.field_index("look_at")?))
}

fn vec3(v: &ConstValue) -> Option<[f32; 3]> {
    match v {
        ConstValue::Vector { len: 3, comps } => {
            let mut out = [0.0; 3];
            for (o, c) in out.iter_mut().zip(comps) {
                *o = match c {
                    Scalar::F32(x) => *x,
                    _ => return None,
                };
            }
            Some(out)
        }
        _ => None,
    }
}

fn const_vec3(v: [f32; 3]) -> ConstValue {
    ConstValue::Vector {
        len: 3,
        comps: [
            Scalar::F32(v[0]),
            Scalar::F32(v[1]),
            Scalar::F32(v[2]),
            Scalar::F32(0.0),
        ],
    }
}

/// The scene's camera as an orbit, if it has `position` and `look_at`.
pub fn read_orbit(compiled: &CompiledScene) -> Option<Orbit> {
    let (p, l) = camera_fields(compiled)?;
    let program = compiled.checked.program.as_ref()?;
    let camera = program.scenes[compiled.scene].camera.as_ref()?;
    Some(Orbit {
        position: vec3(camera.fields.get(p)?)?,
        look_at: vec3(camera.fields.get(l)?)?,
    })
}

/// Puts `orbit` into the compiled scene's camera (what the runtime reads to build the frame).
pub fn write_orbit(compiled: &mut CompiledScene, orbit: Orbit) {
    let Some((p, l)) = camera_fields(compiled) else {
        return;
    };
    let scene = compiled.scene;
    let Some(program) = compiled.checked.program.as_mut() else {
        return;
    };
    if let Some(camera) = program.scenes[scene].camera.as_mut() {
        if let Some(f) = camera.fields.get_mut(p) {
            *f = const_vec3(orbit.position);
        }
        if let Some(f) = camera.fields.get_mut(l) {
            *f = const_vec3(orbit.look_at);
        }
    }
}

/// Writes `orbit` into `renderer`'s camera (its `position` and `look_at` fields, in place); the
/// running accumulation restarts.
pub fn apply(renderer: &mut Renderer<'_>, orbit: Orbit) -> Result<(), RenderError> {
    renderer.set_field(FieldTarget::Camera, "position", &const_vec3(orbit.position))?;
    renderer.set_field(FieldTarget::Camera, "look_at", &const_vec3(orbit.look_at))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rtc_compiler::driver::Options;
    use rtc_compiler::kernel::compile_scene;
    use rtc_compiler::link::LinkOptions;

    fn close(a: [f32; 3], b: [f32; 3]) -> bool {
        length(sub(a, b)) < 1e-4
    }

    #[test]
    fn orbit_keeps_the_distance_pan_moves_both_zoom_scales() {
        let start = Orbit {
            position: [0.0, 1.0, 5.0],
            look_at: [0.0, 1.0, 0.0],
        };
        let mut o = start;
        o.orbit(0.7, 0.3);
        assert!((length(sub(o.position, o.look_at)) - 5.0).abs() < 1e-4);
        assert!(!close(o.position, start.position));
        assert!(close(o.look_at, start.look_at));
        // Far past the pole it stops short of it (the view never flips).
        o.orbit(0.0, 10.0);
        let d = normalize(sub(o.position, o.look_at));
        assert!(d[1] < 0.9999 && d[1] > 0.99, "pitch clamped: {d:?}");

        let mut p = start;
        p.pan(0.1, 0.0);
        let moved = sub(p.position, start.position);
        assert!(close(moved, sub(p.look_at, start.look_at)));
        assert!((length(moved) - 0.5).abs() < 1e-4, "0.1 of the distance 5");

        let mut z = start;
        z.zoom(0.5);
        assert!(close(z.position, [0.0, 1.0, 2.5]));
    }

    #[test]
    fn the_camera_round_trips_through_the_compiled_scene() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/hello/scene.rt");
        let Ok(mut compiled) =
            compile_scene(&[path], None, &Options::default(), &LinkOptions::default())
        else {
            panic!("examples/hello compiles");
        };
        let orbit = read_orbit(&compiled).expect("a pinhole camera");
        assert!(close(orbit.position, [0.0, 1.5, 5.0]));
        assert!(close(orbit.look_at, [0.0, 0.5, 0.0]));
        let moved = Orbit {
            position: [1.0, 2.0, 3.0],
            look_at: [0.5, 0.5, 0.5],
        };
        write_orbit(&mut compiled, moved);
        assert_eq!(read_orbit(&compiled), Some(moved));
    }
}
