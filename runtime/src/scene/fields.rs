//! Field writes by name: one field of a role-struct instance (the camera's `position`, a light's
//! `intensity`, an object's material `color`) set to a new value, packed exactly as the scene
//! build packed it and written in place ([`Entities::set_field`]).
//!
//! Invariants: a value is written only when it has the field's type exactly (scalars of the same
//! kind, vectors of the same length and kind, matrices of the same shape, arrays of the same
//! length, structs of the same struct); asset handles (`mesh`, `texture`) are refused, since
//! changing one means loading an asset (rebuild the scene instead). Nothing is written on an
//! error.

use rtc_compiler::layout::{self, Handles};
use rtc_compiler::sema::hir::{ConstValue, Instance, MeshAsset, Program, Scalar, TextureAsset};
use rtc_compiler::sema::types::{ScalarKind, Type, TypeId};

use super::entities::{Entities, FieldTarget};
use super::params::struct_type;
use super::SceneError;

/// Handles are refused before packing; this only satisfies the packer's signature.
struct NoHandles;

impl Handles for NoHandles {
    fn mesh(&mut self, _: &MeshAsset) -> u32 {
        0
    }
    fn texture(&mut self, _: &TextureAsset) -> u32 {
        0
    }
}

fn kind_of(s: &Scalar) -> ScalarKind {
    match s {
        Scalar::Bool(_) => ScalarKind::Bool,
        Scalar::I32(_) => ScalarKind::I32,
        Scalar::U32(_) => ScalarKind::U32,
        Scalar::F32(_) => ScalarKind::F32,
    }
}

/// Why `value` cannot be stored in a `ty`, or `None` when it can.
fn mismatch(program: &Program, ty: TypeId, value: &ConstValue) -> Option<String> {
    let name = |t: TypeId| program.type_name(t);
    let wrong = || Some(format!("the value is not a `{}`", name(ty)));
    match (program.types.get(ty), value) {
        (Type::Scalar(k), ConstValue::Scalar(s)) if kind_of(s) == k => None,
        (Type::Vector { size, scalar }, ConstValue::Vector { len, comps })
            if *len == size
                && comps
                    .iter()
                    .take(size as usize)
                    .all(|c| kind_of(c) == scalar) =>
        {
            None
        }
        (
            Type::Matrix { cols, rows },
            ConstValue::Matrix {
                cols: c, rows: r, ..
            },
        ) if *c == cols && *r == rows => None,
        (Type::Array { elem, len }, ConstValue::Array(items)) => {
            if items.len() != len as usize {
                return Some(format!(
                    "it holds {len} elements, the value {}",
                    items.len()
                ));
            }
            items.iter().find_map(|item| mismatch(program, elem, item))
        }
        (Type::Struct(s), ConstValue::Struct { id, fields }) if *id == s => program.structs[s]
            .fields
            .iter()
            .zip(fields)
            .find_map(|(f, v)| mismatch(program, f.ty, v)),
        (Type::Mesh | Type::Texture, _) => Some(
            "asset handles cannot be changed in place; edit the scene and rebuild it".to_owned(),
        ),
        _ => wrong(),
    }
}

/// Whether a type holds an asset handle anywhere.
fn holds_handle(program: &Program, ty: TypeId) -> bool {
    match program.types.get(ty) {
        Type::Mesh | Type::Texture => true,
        Type::Array { elem, .. } => holds_handle(program, elem),
        Type::Struct(s) => program.structs[s]
            .fields
            .iter()
            .any(|f| holds_handle(program, f.ty)),
        _ => false,
    }
}

impl Entities {
    /// Sets field `field` of `target`'s instance to `value` (see the module docs), in place;
    /// only its words are marked for upload. `program` is the one the entities were built from.
    pub fn set_field(
        &mut self,
        program: &Program,
        target: FieldTarget,
        field: &str,
        value: &ConstValue,
    ) -> Result<(), SceneError> {
        let inst = self.instance(target)?;
        let Some(sid) = inst.struct_id else {
            return Err(SceneError::NoSuchInstance {
                what: format!("instance for {target:?}"),
            });
        };
        let s = &program.structs[sid];
        let Some((index, f)) = s.fields.iter().enumerate().find(|(_, f)| f.name == field) else {
            return Err(SceneError::NoSuchField {
                ty: s.name.clone(),
                field: field.to_owned(),
                fields: s.fields.iter().map(|f| f.name.clone()).collect(),
            });
        };
        let problem = if holds_handle(program, f.ty) {
            Some("asset handles cannot be changed in place; edit the scene and rebuild it".into())
        } else {
            mismatch(program, f.ty, value)
        };
        if let Some(problem) = problem {
            return Err(SceneError::FieldValue {
                ty: s.name.clone(),
                field: field.to_owned(),
                expected: program.type_name(f.ty),
                problem,
            });
        }
        let ty = struct_type(program, sid)?;
        let at = layout::field_offsets(program, ty)
            .get(index)
            .copied()
            .unwrap_or(0)
            / 4;
        let words = layout::pack(program, f.ty, value, &mut NoHandles);
        self.write_instance(target, at, &words)
    }

    /// Sets every field of `target`'s instance that holds no asset handle to `inst`'s, which
    /// must be of the same struct (a kernel holds the types it was compiled with).
    pub fn set_instance(
        &mut self,
        program: &Program,
        target: FieldTarget,
        inst: &Instance,
    ) -> Result<(), SceneError> {
        let current = self.instance(target)?;
        if current.struct_id != Some(inst.struct_id) {
            return Err(SceneError::FieldValue {
                ty: current
                    .struct_id
                    .map_or_else(String::new, |s| program.structs[s].name.clone()),
                field: "*".into(),
                expected: "the same struct".into(),
                problem: format!(
                    "the new instance is a `{}`; a kernel holds the types it was compiled with, so \
                     another type needs a recompile",
                    program.structs[inst.struct_id].name
                ),
            });
        }
        for (f, v) in program.structs[inst.struct_id]
            .fields
            .iter()
            .zip(&inst.fields)
        {
            if !holds_handle(program, f.ty) {
                self.set_field(program, target, &f.name, v)?;
            }
        }
        Ok(())
    }
}
