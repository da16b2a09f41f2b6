//! `manifest.json`: what a host needs to run a compiled kernel without rtc's runtime.
//!
//! For the render kernel (and the bounds kernel, when there is one): every binding it declares (group,
//! binding, name, kind, and the element layout with member offsets and sizes as naga's layouter computes
//! them for the emitted code), every linked type and program with its kind, name and dispatch id, the
//! layouts of the role structs in `params`, the kernel's constants, the workgroup sizes, for a
//! scene with glTF `model` entries a `models` object (each entry's path as written, whether the
//! link step read its file and what it holds: light types, alpha modes, a perspective camera; and
//! the model types linked because of them), and a `left_out` list: programs, features and bindings the scene does not need, each with the reason;
//! last, `abi`: the whole ABI table ([`crate::abi`]): every struct (size, alignment, field offsets in
//! bytes), every record the host packs into an array binding (binding, addressing, stride, field
//! offsets in elements), the bit fields of BVH child references and quantised boxes, and every
//! constant (flags, `MESH_GEOMETRY`, texture formats, counter indices). With it and the
//! `params_layouts`, a host in another language fills every buffer without rtc's runtime (the test
//! `runtime/tests/manifest_decode.rs` decodes a scene's buffers from it alone).
//!
//! Format 2 added `abi`; `models` was added later without a new format number, as a member that
//! only scenes with `model` entries have and that readers of format 2 may ignore.
//!
//! Invariant: the manifest is deterministic (sorted, no hash-map order), so it can be a golden file.

use super::{CompiledScene, BOUNDS_ENTRY, BOUNDS_WORKGROUP, RENDER_ENTRY, RENDER_WORKGROUP};
use crate::abi;
use crate::back::ResourceKind;
use crate::layout;
use crate::link::ModelRead;
use serde::Serialize;

#[derive(Serialize)]
struct Member {
    name: String,
    offset: u32,
    size: u32,
}

#[derive(Serialize)]
struct Binding {
    group: u32,
    binding: u32,
    name: &'static str,
    kind: &'static str,
    element: String,
    element_size: u32,
    members: Vec<Member>,
    doc: &'static str,
}

#[derive(Serialize)]
struct Program {
    kind: &'static str,
    name: String,
    type_name: String,
    role: &'static str,
    id: u32,
}

#[derive(Serialize)]
struct ParamLayout {
    name: String,
    role: &'static str,
    id: u32,
    size_words: u32,
    fields: Vec<Member>,
}

#[derive(Serialize)]
struct LeftOut {
    kind: &'static str,
    name: String,
    reason: String,
}

/// A glTF `model` entry of the scene and what the link step found in its file.
#[derive(Serialize)]
struct ModelEntry {
    /// The path as the scene wrote it.
    path: String,
    /// Whether the file's metadata was read at compile time.
    read: bool,
    /// Why not (then every model type was linked for it).
    #[serde(skip_serializing_if = "Option::is_none")]
    not_read: Option<String>,
    /// What the file holds ([`crate::link::ModelPart::name`]), when read.
    holds: Vec<&'static str>,
}

/// The scene's models and the model types linked for them.
#[derive(Serialize)]
struct Models {
    entries: Vec<ModelEntry>,
    /// The standard-library types linked because of the models (their programs are in `programs`).
    linked: Vec<&'static str>,
}

#[derive(Serialize)]
struct Kernel {
    entry_point: &'static str,
    workgroup_size: [u32; 3],
    bindings: Vec<Binding>,
}

#[derive(Serialize)]
struct AbiField {
    name: &'static str,
    /// Bytes (structs) or elements of the binding (records).
    offset: u32,
    #[serde(rename = "type")]
    ty: &'static str,
    size: u32,
    #[serde(skip_serializing_if = "str::is_empty")]
    doc: &'static str,
}

#[derive(Serialize)]
struct AbiStruct {
    name: &'static str,
    size: u32,
    align: u32,
    fields: Vec<AbiField>,
    doc: &'static str,
}

#[derive(Serialize)]
struct AbiRecord {
    name: &'static str,
    binding: &'static str,
    /// `word_offset` (`params` records: addressed by their first word) or `slot`.
    addressing: &'static str,
    /// Elements of the binding per record.
    stride: u32,
    element_type: &'static str,
    element_size: u32,
    fields: Vec<AbiField>,
    doc: &'static str,
}

/// The whole ABI table: what a host needs to fill the buffers, whatever the scene.
#[derive(Serialize)]
struct Abi {
    structs: Vec<AbiStruct>,
    records: Vec<AbiRecord>,
    /// The table's own descriptors (they serialise as they are).
    bit_fields: &'static [&'static abi::BitFieldsDesc],
    constants: &'static [abi::Constant],
}

fn abi_table() -> Abi {
    let structs = abi::STRUCTS
        .iter()
        .map(|s| AbiStruct {
            name: s.name,
            size: abi::struct_size(s) as u32,
            align: abi::struct_align(s) as u32,
            fields: s
                .fields
                .iter()
                .enumerate()
                .map(|(i, f)| AbiField {
                    name: f.name,
                    offset: abi::field_offset_at(s, i) as u32,
                    ty: f.ty.name(),
                    size: abi::field_layout(f.ty).0 as u32,
                    doc: "",
                })
                .collect(),
            doc: s.doc,
        })
        .collect();
    let records = abi::RECORDS
        .iter()
        .map(|r| {
            let element = abi::binding(r.binding).map_or(abi::Element::Atomics, |b| b.element);
            let element_type = match element {
                abi::Element::Array(t) => t.name(),
                _ => "",
            };
            AbiRecord {
                name: r.name,
                binding: r.binding,
                addressing: match r.addressing {
                    abi::Addressing::WordOffset => "word_offset",
                    abi::Addressing::Slot => "slot",
                },
                stride: r.stride,
                element_type,
                element_size: abi::element_size(element) as u32,
                fields: r
                    .fields
                    .iter()
                    .map(|f| AbiField {
                        name: f.name,
                        offset: f.offset,
                        ty: f.ty.name(),
                        size: abi::field_layout(f.ty).0 as u32,
                        doc: f.doc,
                    })
                    .collect(),
                doc: r.doc,
            }
        })
        .collect();
    Abi {
        structs,
        records,
        bit_fields: abi::BIT_FIELDS,
        constants: abi::CONSTANTS,
    }
}

#[derive(Serialize)]
struct Manifest {
    format: u32,
    scene: String,
    kernels: Vec<Kernel>,
    programs: Vec<Program>,
    params_layouts: Vec<ParamLayout>,
    constants: std::collections::BTreeMap<&'static str, serde_json::Value>,
    /// Only for a scene with `model` entries.
    #[serde(skip_serializing_if = "Option::is_none")]
    models: Option<Models>,
    left_out: Vec<LeftOut>,
    abi: Abi,
}

fn kind_name(k: ResourceKind) -> &'static str {
    match k {
        ResourceKind::Uniform => "uniform",
        ResourceKind::StorageRead => "storage_read",
        ResourceKind::StorageReadWrite => "storage_read_write",
    }
}

/// The bindings a module declares, with layouts from naga's layouter.
fn bindings_of(module: &naga::Module) -> Vec<Binding> {
    let mut layouter = naga::proc::Layouter::default();
    let _ = layouter.update(module.to_ctx());
    let mut out = Vec::new();
    for (_, g) in module.global_variables.iter() {
        let Some(rb) = &g.binding else { continue };
        let Some(desc) = abi::BINDINGS.iter().find(|b| b.binding == rb.binding) else {
            continue;
        };
        // For runtime-sized arrays, describe the element.
        let mut ty = g.ty;
        if let naga::TypeInner::Array { base, .. } = module.types[ty].inner {
            ty = base;
        }
        let members = match &module.types[ty].inner {
            naga::TypeInner::Struct { members, .. } => members
                .iter()
                .map(|m| Member {
                    name: m.name.clone().unwrap_or_default(),
                    offset: m.offset,
                    size: layouter[m.ty].size,
                })
                .collect(),
            _ => Vec::new(),
        };
        let element = module.types[ty]
            .name
            .clone()
            .unwrap_or_else(|| format!("{:?}", module.types[ty].inner).to_lowercase());
        out.push(Binding {
            group: rb.group,
            binding: rb.binding,
            name: desc.name,
            kind: kind_name(desc.kind),
            element,
            element_size: layouter[ty].size,
            members,
            doc: desc.doc,
        });
    }
    out.sort_by_key(|b| b.binding);
    out
}

/// The manifest of a compiled scene, as pretty JSON.
pub fn manifest_json(c: &CompiledScene) -> String {
    let Some(program) = c.checked.program.as_ref() else {
        return "{}\n".to_string();
    };
    let mut kernels = vec![Kernel {
        entry_point: RENDER_ENTRY,
        workgroup_size: [RENDER_WORKGROUP[0], RENDER_WORKGROUP[1], 1],
        bindings: bindings_of(&c.render),
    }];
    if let Some(b) = &c.bounds {
        kernels.push(Kernel {
            entry_point: BOUNDS_ENTRY,
            workgroup_size: [BOUNDS_WORKGROUP, 1, 1],
            bindings: bindings_of(b),
        });
    }
    let mut programs = Vec::new();
    let mut params_layouts = Vec::new();
    for t in c.linked.types.values().flatten() {
        let st = &program.structs[t.struct_id];
        for (kind, f) in &t.programs {
            programs.push(Program {
                kind: kind.name(),
                name: program.functions[*f].name.clone(),
                type_name: st.name.clone(),
                role: t.role.name(),
                id: t.id,
            });
        }
        if let Ok(ty) = super::dispatch::struct_type_id(program, t.struct_id) {
            let offsets = layout::field_offsets(program, ty);
            params_layouts.push(ParamLayout {
                name: st.name.clone(),
                role: t.role.name(),
                id: t.id,
                size_words: layout::layout(program, ty).size / 4,
                fields: st
                    .fields
                    .iter()
                    .zip(offsets)
                    .map(|(f, off)| Member {
                        name: f.name.clone(),
                        offset: off,
                        size: layout::layout(program, f.ty).size,
                    })
                    .collect(),
            });
        }
    }
    let cfg = c.linked.config;
    let mut constants = std::collections::BTreeMap::new();
    for (k, v) in [
        ("max_depth", cfg.max_depth),
        ("max_spawn", cfg.max_spawn),
        ("stack_size", cfg.stack_size),
        ("tlas_stack", cfg.tlas_stack),
        ("blas_stack", cfg.blas_stack),
        ("roulette_depth", cfg.roulette_depth),
        ("samples_per_pass", c.samples_per_pass),
    ] {
        constants.insert(k, serde_json::json!(v));
    }
    for (k, v) in [
        ("has_secondary_rays", cfg.has_secondary_rays),
        ("path_loop", cfg.path_loop),
        ("regenerate_paths", cfg.regenerate_paths),
        ("has_any_hit", cfg.has_any_hit),
        ("has_custom_geometry", cfg.has_custom_geometry),
        ("has_meshes", cfg.has_meshes),
        ("has_media", cfg.has_media),
        ("has_absorb", cfg.has_absorb),
        ("has_background", cfg.has_background),
        ("cull_back_faces", cfg.cull_back_faces),
    ] {
        constants.insert(k, serde_json::json!(v));
    }
    let mut left_out: Vec<LeftOut> = c
        .linked
        .left_out
        .iter()
        .map(|l| LeftOut {
            kind: l.kind,
            name: l.name.clone(),
            reason: l.reason.clone(),
        })
        .collect();
    for b in abi::BINDINGS {
        if !c.bindings.iter().any(|u| u.binding == b.binding) {
            left_out.push(LeftOut {
                kind: "binding",
                name: b.name.to_string(),
                reason: "nothing the scene's kernel runs reads it".to_string(),
            });
        }
    }
    let models = (!c.linked.models.is_empty()).then(|| Models {
        entries: c
            .linked
            .models
            .iter()
            .map(|m| match &m.read {
                ModelRead::Read(parts) => ModelEntry {
                    path: m.path.clone(),
                    read: true,
                    not_read: None,
                    holds: parts.iter().map(|p| p.name()).collect(),
                },
                ModelRead::NotRead(why) => ModelEntry {
                    path: m.path.clone(),
                    read: false,
                    not_read: Some(why.clone()),
                    holds: Vec::new(),
                },
            })
            .collect(),
        linked: c.linked.model_types.clone(),
    });
    let m = Manifest {
        format: 2,
        scene: program.scenes[c.scene].name.clone(),
        kernels,
        programs,
        params_layouts,
        constants,
        models,
        left_out,
        abi: abi_table(),
    };
    let mut s = serde_json::to_string_pretty(&m).unwrap_or_default();
    s.push('\n');
    s
}
