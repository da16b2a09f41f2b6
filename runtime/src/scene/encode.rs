//! Encoding a mesh's triangles for the GPU: positions in BVH leaf order (`triangles`), and normals
//! and uvs compressed to 8 words per triangle (`attributes`).
//!
//! The records are the ABI's `TRIANGLE` and `ATTRIBUTE` (`rtc_compiler::abi`); `gpu_types.rs`
//! asserts at compile time that their strides and field offsets are the order written here.
//! Per triangle slot `s` of a mesh (slot `s` holds triangle `t = bvh.prim_indices()[s]` of the mesh):
//! - `triangles[3s..3s+3]`: `[v0.xyz, f32::from_bits(t)]`, `[v1.xyz, 0]`, `[v2.xyz, 0]`, object space;
//! - `attributes[2s]`: `[oct(n0), oct(n1), oct(n2), f16x2(uv0)]`, `attributes[2s+1]`:
//!   `[f16x2(uv1), f16x2(uv2), 0, 0]`.
//!
//! `oct` is the octahedral encoding of a unit vector (Cigolle et al., JCGT 2014) packed like WGSL's
//! `pack2x16snorm`; [`decode_octahedral`] is exactly the kernel's decoder, so the round trip is
//! tested on the CPU. `f16x2` is WGSL's `pack2x16float` ([`pack_f16x2`]).
//!
//! Invariants: every slot gets exactly 3 `triangles` entries and 2 `attributes` entries, whatever the
//! mesh holds (a mesh without normals gets its smooth normals, one without uvs gets zeros, an index
//! out of range reads the origin); nothing here panics.

use glam::Vec3;
use rtc_bvh::Bvh;

use crate::assets::texture::pack_f16x2;
use crate::assets::MeshData;

use super::gpu_types::record;

/// Packs two values in `[-1, 1]` like WGSL's `pack2x16snorm` (the first in the low 16 bits).
pub fn pack_snorm2x16(a: f32, b: f32) -> u32 {
    let one = |x: f32| {
        let x = if x.is_nan() { 0.0 } else { x.clamp(-1.0, 1.0) };
        // In [-32767, 32767] after the clamp, so the casts cannot wrap.
        u32::from((x * 32767.0).round() as i16 as u16)
    };
    one(a) | (one(b) << 16)
}

/// Unpacks [`pack_snorm2x16`] (WGSL's `unpack2x16snorm`).
pub fn unpack_snorm2x16(word: u32) -> [f32; 2] {
    let one = |bits: u32| (f32::from(bits as u16 as i16) / 32767.0).max(-1.0);
    [one(word & 0xffff), one(word >> 16)]
}

/// The octahedral encoding of a direction (need not be unit length). A zero or non-finite vector
/// encodes `+z`.
pub fn octahedral(n: [f32; 3]) -> u32 {
    let [x, y, z] = n;
    let l1 = x.abs() + y.abs() + z.abs();
    if !(l1 > 0.0 && l1.is_finite()) {
        return pack_snorm2x16(0.0, 0.0);
    }
    let (u, v) = (x / l1, y / l1);
    if z < 0.0 {
        let sign = |a: f32| if a >= 0.0 { 1.0 } else { -1.0 };
        pack_snorm2x16((1.0 - v.abs()) * sign(u), (1.0 - u.abs()) * sign(v))
    } else {
        pack_snorm2x16(u, v)
    }
}

/// Decodes [`octahedral`] exactly as the kernel's `decode_octahedral` does.
pub fn decode_octahedral(bits: u32) -> [f32; 3] {
    let [ex, ey] = unpack_snorm2x16(bits);
    let mut n = Vec3::new(ex, ey, 1.0 - ex.abs() - ey.abs());
    if n.z < 0.0 {
        let sign = |a: f32| if a >= 0.0 { 1.0 } else { -1.0 };
        n.x = (1.0 - ey.abs()) * sign(ex);
        n.y = (1.0 - ex.abs()) * sign(ey);
    }
    n.normalize_or_zero().to_array()
}

/// Appends the triangle slots of `mesh`, in the leaf order of its BVH `bvh`, to `triangles` and
/// `attributes` (see the module docs for the layout).
pub fn encode_mesh(
    mesh: &MeshData,
    bvh: &Bvh,
    triangles: &mut Vec<[f32; 4]>,
    attributes: &mut Vec<[u32; 4]>,
) {
    let smooth;
    let normals: &[[f32; 3]] = match &mesh.normals {
        Some(n) if n.len() == mesh.positions.len() => n,
        _ => {
            smooth = mesh.smooth_normals();
            &smooth
        }
    };
    let uvs = mesh
        .uvs
        .as_deref()
        .filter(|u| u.len() == mesh.positions.len());
    let slots = bvh.prim_indices();
    triangles.reserve(slots.len() * record::TRIANGLE_VEC4S);
    attributes.reserve(slots.len() * record::ATTRIBUTE_VEC4S);
    for &t in slots {
        let idx = mesh
            .indices
            .get(t as usize)
            .copied()
            .unwrap_or([u32::MAX; 3]);
        let pos = |i: u32| mesh.positions.get(i as usize).copied().unwrap_or([0.0; 3]);
        let nrm = |i: u32| octahedral(normals.get(i as usize).copied().unwrap_or([0.0; 3]));
        let uv = |i: u32| {
            let [u, v] = uvs
                .and_then(|uvs| uvs.get(i as usize))
                .copied()
                .unwrap_or([0.0; 2]);
            pack_f16x2(u, v)
        };
        let [a, b, c] = idx;
        let [p0, p1, p2] = [pos(a), pos(b), pos(c)];
        triangles.push([p0[0], p0[1], p0[2], f32::from_bits(t)]);
        triangles.push([p1[0], p1[1], p1[2], 0.0]);
        triangles.push([p2[0], p2[1], p2[2], 0.0]);
        attributes.push([nrm(a), nrm(b), nrm(c), uv(a)]);
        attributes.push([uv(b), uv(c), 0, 0]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assets::texture::unpack_f16x2;
    use rtc_bvh::{build, BuildInput, BuildPreset};

    #[test]
    fn octahedral_round_trip_is_close_everywhere() {
        let mut worst = 0.0f32;
        let steps = 64;
        for i in 0..=steps {
            for j in 0..steps {
                let theta = std::f32::consts::PI * i as f32 / steps as f32;
                let phi = 2.0 * std::f32::consts::PI * j as f32 / steps as f32;
                let n = [
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                ];
                let d = Vec3::from(decode_octahedral(octahedral(n)));
                // atan2(|a × b|, a · b): accurate for tiny angles, unlike acos in f32.
                let a = Vec3::from(n);
                worst = worst.max(a.cross(d).length().atan2(a.dot(d)));
            }
        }
        // 16-bit snorm octahedral: about 1e-4 radians at worst.
        assert!(worst < 2e-4, "worst angular error {worst}");
        for axis in [
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ] {
            assert_eq!(decode_octahedral(octahedral(axis)), axis);
        }
        assert_eq!(decode_octahedral(octahedral([0.0; 3])), [0.0, 0.0, 1.0]);
        assert_eq!(
            decode_octahedral(octahedral([f32::NAN, 0.0, 1.0])),
            [0.0, 0.0, 1.0]
        );
    }

    #[test]
    fn snorm_packing_matches_wgsl() {
        assert_eq!(pack_snorm2x16(1.0, -1.0), 0x8001_7fff);
        assert_eq!(pack_snorm2x16(0.0, 2.0), 0x7fff_0000);
        assert_eq!(unpack_snorm2x16(0x8000_8000), [-1.0, -1.0]);
    }

    #[test]
    fn mesh_slots_follow_the_bvh_leaf_order() {
        let mesh = crate::assets::cube_mesh();
        let vertices: Vec<Vec3> = mesh.positions.iter().map(|&p| Vec3::from(p)).collect();
        let bvh = build(
            BuildInput::Indexed {
                vertices: &vertices,
                indices: &mesh.indices,
            },
            BuildPreset::Fast,
        );
        let (mut tris, mut attrs) = (Vec::new(), Vec::new());
        encode_mesh(&mesh, &bvh, &mut tris, &mut attrs);
        assert_eq!(tris.len(), bvh.prim_indices().len() * 3);
        assert_eq!(attrs.len(), bvh.prim_indices().len() * 2);
        let normals = mesh.normals.as_ref().expect("cube has normals");
        let uvs = mesh.uvs.as_ref().expect("cube has uvs");
        for (s, &t) in bvh.prim_indices().iter().enumerate() {
            let [a, b, c] = mesh.indices[t as usize];
            assert_eq!(tris[3 * s][3].to_bits(), t, "slot {s} names its triangle");
            assert_eq!(tris[3 * s][..3], mesh.positions[a as usize]);
            assert_eq!(tris[3 * s + 1][..3], mesh.positions[b as usize]);
            assert_eq!(tris[3 * s + 2][..3], mesh.positions[c as usize]);
            assert_eq!(decode_octahedral(attrs[2 * s][0]), normals[a as usize]);
            assert_eq!(decode_octahedral(attrs[2 * s][2]), normals[c as usize]);
            assert_eq!(unpack_f16x2(attrs[2 * s][3]), uvs[a as usize]);
            assert_eq!(unpack_f16x2(attrs[2 * s + 1][0]), uvs[b as usize]);
            assert_eq!(unpack_f16x2(attrs[2 * s + 1][1]), uvs[c as usize]);
            assert_eq!(attrs[2 * s + 1][2..], [0, 0]);
        }
    }
}
