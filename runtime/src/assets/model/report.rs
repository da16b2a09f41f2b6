//! The import report of a glTF file (`rtc render model.glb --report`): what became part of the
//! scene and what did not, as plain text, one line per item.
//!
//! Guarantees: the report is a pure function of the [`ModelScene`] (the same file gives the same
//! text, byte for byte, so it can be a golden file); it lists every mesh, material (with each
//! texture it samples), light, camera and the animation that were imported, with the glTF index
//! and name the file gives them; and under "not imported" every warning of the import, each of
//! which names the material, mesh, node, animation or extension it concerns. Numbers are
//! printed with fixed precision (3 decimals) so that the text does not depend on float
//! formatting details.

use std::fmt::Write;

use super::animation::{Interp, Path as Target};
use super::{AlphaMode, GltfMaterial, LightKind, ModelScene, Projection};

/// The import report of `scene`, read from the file called `name`.
pub fn report(name: &str, scene: &ModelScene) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "import report of {name}");

    let triangles: usize = scene.meshes.iter().map(|m| m.indices.len()).sum();
    let _ = writeln!(
        out,
        "  meshes: {} triangle mesh(es), {triangles} triangle(s), placed {} time(s)",
        scene.meshes.len(),
        scene.instances.len()
    );
    for (i, mesh) in scene.meshes.iter().enumerate() {
        let label = scene.mesh_labels.get(i).map_or("?", String::as_str);
        // What the mesh carries (normals may have been computed from the faces on import).
        let mut attributes = vec!["positions"];
        if mesh.normals.is_some() {
            attributes.push("normals");
        }
        if mesh.uvs.is_some() {
            attributes.push("uvs");
        }
        if let Some(x) = &mesh.extras {
            if x.uvs1.is_some() {
                attributes.push("second uvs");
            }
            if x.colors.is_some() {
                attributes.push("colours");
            }
            if x.tangents.is_some() {
                attributes.push("tangents");
            }
        }
        let nodes: Vec<String> = scene
            .instances
            .iter()
            .filter(|x| x.mesh == i)
            .map(|x| format!("nodes[{}]", x.node))
            .collect();
        let _ = writeln!(
            out,
            "    {label}: {} triangle(s), {} vertices ({}), on {}",
            mesh.indices.len(),
            mesh.positions.len(),
            attributes.join(", "),
            nodes.join(", ")
        );
    }

    let _ = writeln!(out, "  materials: {}", scene.materials.len());
    for (i, m) in scene.materials.iter().enumerate() {
        let label = scene.material_labels.get(i).map_or("?", String::as_str);
        let mut texture = textures_of(m)
            .into_iter()
            .enumerate()
            .filter_map(|(k, (what, t))| {
                let t = scene.textures.get(t?)?;
                let set = (m.uv_sets >> k) & 1;
                let scale = if k == 4 {
                    format!(" scale {:.3}", m.normal_scale)
                } else {
                    String::new()
                };
                Some(format!(
                    ", {what} texture {}×{} (TEXCOORD_{set}){scale}",
                    t.width, t.height
                ))
            })
            .collect::<String>();
        if m.vertex_colors {
            texture.push_str(", times COLOR_0");
        }
        let alpha = match m.alpha_mode {
            AlphaMode::Opaque => "OPAQUE".to_owned(),
            AlphaMode::Mask => format!("MASK below {:.3}", m.alpha_cutoff),
            AlphaMode::Blend => "BLEND".to_owned(),
        };
        let alpha = if m.transmission > 0.0 {
            format!(
                "{alpha}, transmission {:.3} (ior {:.3})",
                m.transmission, m.ior
            )
        } else {
            alpha
        };
        let _ = writeln!(
            out,
            "    {label}: base colour {}, metallic {:.3}, roughness {:.3}, emissive {}{texture}, \
             alpha {alpha}, {}",
            fmt(&m.base_color),
            m.metallic,
            m.roughness,
            fmt(&m.emissive),
            if m.double_sided {
                "double-sided"
            } else {
                "single-sided"
            }
        );
    }

    let _ = writeln!(out, "  lights: {}", scene.lights.len());
    for l in &scene.lights {
        let name = l
            .name
            .as_deref()
            .map(|n| format!(" `{n}`"))
            .unwrap_or_default();
        let what = match l.kind {
            LightKind::Point => format!(
                "point at {}, {:.3} cd",
                fmt(&l.position.to_array()),
                l.intensity
            ),
            LightKind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => format!(
                "spot at {} along {}, cone {:.3}°..{:.3}°, {:.3} cd",
                fmt(&l.position.to_array()),
                fmt(&l.direction.to_array()),
                inner_cone_angle.to_degrees(),
                outer_cone_angle.to_degrees(),
                l.intensity
            ),
            LightKind::Directional => format!(
                "directional along {}, {:.3} lx",
                fmt(&l.direction.to_array()),
                l.intensity
            ),
        };
        let _ = writeln!(
            out,
            "    KHR_lights_punctual{name}: {what}, colour {}",
            fmt(&l.color)
        );
    }

    let _ = writeln!(out, "  cameras: {}", scene.cameras.len());
    for (i, c) in scene.cameras.iter().enumerate() {
        let name = c
            .name
            .as_deref()
            .map(|n| format!(" `{n}`"))
            .unwrap_or_default();
        let what = match c.projection {
            Projection::Perspective { yfov, .. } => format!(
                "perspective, {:.3}° vertical field of view{}",
                yfov.to_degrees(),
                if i == 0 { " (the default camera)" } else { "" }
            ),
            Projection::Orthographic { xmag, ymag, .. } => {
                format!("orthographic {xmag:.3}×{ymag:.3} (not imported as a camera)")
            }
        };
        let _ = writeln!(
            out,
            "    camera{name} at {} looking along {}: {what}",
            fmt(&c.position().to_array()),
            fmt(&c.forward().to_array())
        );
    }

    match &scene.animation {
        None => {
            let _ = writeln!(out, "  animation: none");
        }
        Some(a) => {
            let _ = writeln!(
                out,
                "  animation: {}, {} channel(s), {:.3} s",
                a.label,
                a.channels.len(),
                a.duration
            );
            for c in &a.channels {
                let path = match c.path {
                    Target::Translation => "translation",
                    Target::Rotation => "rotation",
                    Target::Scale => "scale",
                };
                let interp = match c.interp {
                    Interp::Step => "STEP",
                    Interp::Linear => "LINEAR",
                    Interp::CubicSpline => "CUBICSPLINE",
                };
                let _ = writeln!(
                    out,
                    "    nodes[{}] {path} {interp}, {} key(s)",
                    c.node,
                    c.times.len()
                );
            }
        }
    }

    if scene.warnings.is_empty() {
        let _ = writeln!(out, "  not imported: nothing");
    } else {
        let _ = writeln!(
            out,
            "  not imported or approximated: {}",
            scene.warnings.len()
        );
        for w in &scene.warnings {
            let _ = writeln!(out, "    {w}");
        }
    }
    out
}

/// Each texture slot of a material the import fills, by name, and its index into
/// [`ModelScene::textures`] (the report lists the filled ones, in this order).
fn textures_of(m: &GltfMaterial) -> Vec<(&'static str, Option<usize>)> {
    vec![
        ("base colour", m.base_color_texture),
        ("metallic-roughness", m.metallic_roughness_texture),
        ("emissive", m.emissive_texture),
        ("occlusion", m.occlusion_texture),
        ("normal", m.normal_texture),
    ]
}

/// `(a, b, c)` with 3 decimals.
fn fmt(v: &[f32]) -> String {
    // `+ 0.0` turns -0 into 0, so that no `-0.000` appears.
    let parts: Vec<String> = v.iter().map(|x| format!("{:.3}", x + 0.0)).collect();
    format!("({})", parts.join(", "))
}
