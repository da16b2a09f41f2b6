//! Encoding a mesh's triangles for the GPU: positions in BVH leaf order (`triangles`), and normals
//! and uvs compressed to 8 words per triangle (`attributes`).
//!
//! The records are the ABI's `TRIANGLE` and `ATTRIBUTE` (`rtc_compiler::abi`); `gpu_types.rs`
//! asserts at compile time that their strides and field offsets are the order written here.
//! Per triangle slot `s` of a mesh (slot `s` holds triangle `t = bvh.prim_indices()[s]` of the mesh):
//! - `triangles[3s..3s+3]`: `[v0.xyz, f32::from_bits(t)]`, `[v1.xyz, 0]`, `[v2.xyz, 0]`, object space
//!   (`flatten.rs` writes the member tag of a flattened group's slots into `v1.w`);
//! - `attributes[2s]`: `[oct(n0), oct(n1), oct(n2), f16x2(uv0)]`, `attributes[2s+1]`:
//!   `[f16x2(uv1), f16x2(uv2), extra, 0]`;
//! - for a mesh with [`VertexExtras`] only, 3 `VERTEX_EXTRA` entries per slot in `extras`:
//!   `[oct(t0), oct(t1), oct(t2), flags]` (flags: bit k = tangent k's w is negative, bit 3 + k =
//!   vertex k has a tangent), `[f16x2(uv1_0), f16x2(uv1_1), f16x2(uv1_2), 0]`,
//!   `[rgba8(c0), rgba8(c1), rgba8(c2), 0]` (white without colours). `extra` is 0 for a mesh
//!   without extras (so its encoding is what it always was); otherwise 1 + the index of the slot's
//!   first entry in the mesh's `extras`, which [`link_extras`] turns into the index in the
//!   scene's `attributes` once all meshes are placed (extras go after every slot's records).
//!
//! `oct` is the octahedral encoding of a unit vector (Cigolle et al., JCGT 2014) packed like WGSL's
//! `pack2x16snorm`; [`decode_octahedral`] is exactly the kernel's decoder, so the round trip is
//! tested on the CPU. `f16x2` is WGSL's `pack2x16float` ([`pack_f16x2`]).
//!
//! Invariants: every slot gets exactly 3 `triangles` entries and 2 `attributes` entries (and 3
//! `extras` entries when the mesh has extras), whatever the
//! mesh holds (a mesh without normals gets its smooth normals, one without uvs gets zeros, an index
//! out of range reads the origin); nothing here panics.

use glam::Vec3;
use rtc_bvh::Bvh;

use crate::assets::texture::pack_f16x2;
use crate::assets::{MeshData, VertexExtras};

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

/// Packs a linear RGBA colour as 4 unorm8s (WGSL's `pack4x8unorm`, red in the low byte).
pub fn pack_unorm4x8(c: [f32; 4]) -> u32 {
    c.iter().enumerate().fold(0, |word, (k, &x)| {
        let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        // In [0, 255] after the clamp.
        word | (u32::from((x * 255.0).round() as u8) << (8 * k))
    })
}

/// The 3 `VERTEX_EXTRA` entries of triangle `t` (vertices `idx`) of a mesh with `extras`.
fn extra_entries(extras: &VertexExtras, t: u32, idx: [u32; 3]) -> [[u32; 4]; 3] {
    let mut tangents = [0u32; 3];
    let mut flags = 0u32;
    if let Some(corners) = extras.tangents.as_ref().and_then(|c| c.get(t as usize)) {
        for ((k, &[x, y, z, w]), word) in corners.iter().enumerate().zip(&mut tangents) {
            let has =
                [x, y, z].iter().any(|&c| c != 0.0) && [x, y, z].iter().all(|c| c.is_finite());
            if has {
                *word = octahedral([x, y, z]);
                flags |= 1 << (3 + k);
                if w < 0.0 {
                    flags |= 1 << k;
                }
            }
        }
    }
    let [t0, t1, t2] = tangents;
    let tangents = [t0, t1, t2, flags];
    let uv = |i: u32| {
        let [u, v] = extras
            .uvs1
            .as_ref()
            .and_then(|u| u.get(i as usize))
            .copied()
            .unwrap_or([0.0; 2]);
        pack_f16x2(u, v)
    };
    let color = |i: u32| {
        extras
            .colors
            .as_ref()
            .and_then(|c| c.get(i as usize))
            .map_or(u32::MAX, |&c| pack_unorm4x8(c))
    };
    let [a, b, c] = idx;
    [
        tangents,
        [uv(a), uv(b), uv(c), 0],
        [color(a), color(b), color(c), 0],
    ]
}

/// Turns the mesh-relative `extra` words of `attributes[range]` (a mesh whose `extras` go at
/// index `base` of the scene's `attributes`) into absolute indices.
pub fn link_extras(attributes: &mut [[u32; 4]], base: u32) {
    for pair in attributes.chunks_exact_mut(record::ATTRIBUTE_VEC4S) {
        if let Some(second) = pair.get_mut(1) {
            if second[2] != 0 {
                second[2] = base + (second[2] - 1);
            }
        }
    }
}

/// Appends the triangle slots of `mesh`, in the leaf order of its BVH `bvh`, to `triangles` and
/// `attributes`, and their extras (only for a mesh with [`VertexExtras`]) to `extras` (see the
/// module docs for the layout).
pub fn encode_mesh(
    mesh: &MeshData,
    bvh: &Bvh,
    triangles: &mut Vec<[f32; 4]>,
    attributes: &mut Vec<[u32; 4]>,
    extras: &mut Vec<[u32; 4]>,
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
        let extra = match &mesh.extras {
            Some(x) => {
                let at = u32::try_from(extras.len() + 1).unwrap_or(0);
                extras.extend(extra_entries(x, t, idx));
                at
            }
            None => 0,
        };
        attributes.push([uv(b), uv(c), extra, 0]);
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
        let (mut tris, mut attrs, mut extras) = (Vec::new(), Vec::new(), Vec::new());
        encode_mesh(&mesh, &bvh, &mut tris, &mut attrs, &mut extras);
        assert!(extras.is_empty(), "a mesh without extras has none");
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
