//! The interned type table of a checked program.
//!
//! Every type is stored once in a [`TypeTable`] and referred to by a [`TypeId`]; two types are equal
//! exactly when their ids are equal (interning, as naga's `UniqueArena`). The common types (`f32`,
//! `vec3f`, …) are pre-interned at fixed ids so the checker can name them without a lookup.
//!
//! Invariants:
//! - [`TypeTable::ERROR`] is the type of an expression that already produced a diagnostic. Every rule
//!   accepts it silently and propagates it, so one mistake yields one diagnostic (no cascades). It never
//!   appears in a program without errors.
//! - [`TypeTable::VOID`] is the "type" of a call to a function that returns nothing; no value has it.
//! - Matrices are always of `f32`; vector sizes and matrix dimensions are 2, 3 or 4; array lengths are
//!   positive.

use super::hir::StructId;
use indexmap::IndexSet;

/// Handle of an interned type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TypeId(u32);

impl TypeId {
    /// The index of the type in its table (stable for the life of the program).
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ScalarKind {
    /// `bool`
    Bool,
    /// `i32`
    I32,
    /// `u32`
    U32,
    /// `f32`
    F32,
}

impl ScalarKind {
    /// The type's name.
    pub fn name(self) -> &'static str {
        match self {
            ScalarKind::Bool => "bool",
            ScalarKind::I32 => "i32",
            ScalarKind::U32 => "u32",
            ScalarKind::F32 => "f32",
        }
    }

    /// The suffix of the short vector names (`vec3f`).
    pub fn suffix(self) -> char {
        match self {
            ScalarKind::Bool => 'b',
            ScalarKind::I32 => 'i',
            ScalarKind::U32 => 'u',
            ScalarKind::F32 => 'f',
        }
    }

    /// Whether this is `i32` or `u32`.
    pub fn is_integer(self) -> bool {
        matches!(self, ScalarKind::I32 | ScalarKind::U32)
    }

    /// Whether this is a number (not `bool`).
    pub fn is_numeric(self) -> bool {
        self != ScalarKind::Bool
    }
}

/// A type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    /// The type of an erroneous expression (already reported).
    Error,
    /// No value: the result of calling a function without a return type.
    Void,
    /// `bool`, `i32`, `u32`, `f32`.
    Scalar(ScalarKind),
    /// `vecN<T>`.
    Vector {
        /// 2, 3 or 4.
        size: u8,
        /// The component type.
        scalar: ScalarKind,
    },
    /// `matCxR<f32>`, column-major.
    Matrix {
        /// Number of columns, 2..=4.
        cols: u8,
        /// Number of rows (the length of a column), 2..=4.
        rows: u8,
    },
    /// `array<T, N>`.
    Array {
        /// The element type.
        elem: TypeId,
        /// The number of elements, positive.
        len: u32,
    },
    /// A user or prelude struct.
    Struct(StructId),
    /// `texture`, a handle.
    Texture,
    /// `mesh`, a handle.
    Mesh,
    /// `string` (only in scenes, for asset paths).
    String,
}

/// All types of a program, interned.
#[derive(Clone, Debug)]
pub struct TypeTable {
    set: IndexSet<Type>,
}

impl Default for TypeTable {
    fn default() -> TypeTable {
        TypeTable::new()
    }
}

impl TypeTable {
    /// The error type.
    pub const ERROR: TypeId = TypeId(0);
    /// No value.
    pub const VOID: TypeId = TypeId(1);
    /// `bool`
    pub const BOOL: TypeId = TypeId(2);
    /// `i32`
    pub const I32: TypeId = TypeId(3);
    /// `u32`
    pub const U32: TypeId = TypeId(4);
    /// `f32`
    pub const F32: TypeId = TypeId(5);
    /// `texture`
    pub const TEXTURE: TypeId = TypeId(6);
    /// `mesh`
    pub const MESH: TypeId = TypeId(7);
    /// `string`
    pub const STRING: TypeId = TypeId(8);
    /// `vec2f`
    pub const VEC2F: TypeId = TypeId(9);
    /// `vec3f`
    pub const VEC3F: TypeId = TypeId(10);
    /// `vec4f`
    pub const VEC4F: TypeId = TypeId(11);
    /// `vec2u`
    pub const VEC2U: TypeId = TypeId(12);
    /// `mat3x3f`
    pub const MAT3: TypeId = TypeId(13);
    /// `mat4x4f`
    pub const MAT4: TypeId = TypeId(14);

    /// A table holding the pre-interned types.
    pub fn new() -> TypeTable {
        let mut set = IndexSet::with_capacity(64);
        for t in [
            Type::Error,
            Type::Void,
            Type::Scalar(ScalarKind::Bool),
            Type::Scalar(ScalarKind::I32),
            Type::Scalar(ScalarKind::U32),
            Type::Scalar(ScalarKind::F32),
            Type::Texture,
            Type::Mesh,
            Type::String,
            Type::Vector {
                size: 2,
                scalar: ScalarKind::F32,
            },
            Type::Vector {
                size: 3,
                scalar: ScalarKind::F32,
            },
            Type::Vector {
                size: 4,
                scalar: ScalarKind::F32,
            },
            Type::Vector {
                size: 2,
                scalar: ScalarKind::U32,
            },
            Type::Matrix { cols: 3, rows: 3 },
            Type::Matrix { cols: 4, rows: 4 },
        ] {
            set.insert(t);
        }
        TypeTable { set }
    }

    /// The id of `ty`, interning it if new.
    pub fn intern(&mut self, ty: Type) -> TypeId {
        TypeId(self.set.insert_full(ty).0 as u32)
    }

    /// The type with this id. Ids come from this table, so the lookup cannot fail; an id from another
    /// table reads as [`Type::Error`].
    pub fn get(&self, id: TypeId) -> Type {
        self.set
            .get_index(id.index())
            .copied()
            .unwrap_or(Type::Error)
    }

    /// Every type with its id, in interning order.
    pub fn iter(&self) -> impl Iterator<Item = (TypeId, Type)> + '_ {
        self.set
            .iter()
            .enumerate()
            .map(|(i, t)| (TypeId(i as u32), *t))
    }

    /// Number of types.
    pub fn len(&self) -> usize {
        self.set.len()
    }

    /// Always false: the table holds the pre-interned types.
    pub fn is_empty(&self) -> bool {
        self.set.is_empty()
    }

    /// The scalar type of this kind.
    pub fn scalar(kind: ScalarKind) -> TypeId {
        match kind {
            ScalarKind::Bool => TypeTable::BOOL,
            ScalarKind::I32 => TypeTable::I32,
            ScalarKind::U32 => TypeTable::U32,
            ScalarKind::F32 => TypeTable::F32,
        }
    }

    /// `kind` for width 1, `vec{width}<kind>` otherwise.
    pub fn scalar_or_vector(&mut self, width: u8, kind: ScalarKind) -> TypeId {
        if width <= 1 {
            TypeTable::scalar(kind)
        } else {
            self.intern(Type::Vector {
                size: width,
                scalar: kind,
            })
        }
    }

    /// The scalar kind of a scalar or vector type.
    pub fn scalar_kind(&self, id: TypeId) -> Option<ScalarKind> {
        match self.get(id) {
            Type::Scalar(k) | Type::Vector { scalar: k, .. } => Some(k),
            Type::Matrix { .. } => Some(ScalarKind::F32),
            _ => None,
        }
    }

    /// 1 for scalars, the size for vectors, `None` otherwise.
    pub fn width(&self, id: TypeId) -> Option<u8> {
        match self.get(id) {
            Type::Scalar(_) => Some(1),
            Type::Vector { size, .. } => Some(size),
            _ => None,
        }
    }

    /// Whether this is the error type.
    pub fn is_error(id: TypeId) -> bool {
        id == TypeTable::ERROR
    }

    /// Whether values of this type may be constructed with `T(…)` and compared component-wise: scalars,
    /// vectors, matrices and arrays of those.
    pub fn is_constructible(&self, id: TypeId) -> bool {
        match self.get(id) {
            Type::Scalar(_) | Type::Vector { .. } | Type::Matrix { .. } => true,
            Type::Array { elem, .. } => self.is_constructible(elem),
            _ => false,
        }
    }

    /// The type's name as the user writes it: `f32`, `vec3f`, `mat4x4f`, `array<f32, 3>`, `Ray`.
    pub fn display(&self, id: TypeId, struct_name: &dyn Fn(StructId) -> String) -> String {
        match self.get(id) {
            Type::Error => "{error}".to_string(),
            Type::Void => "()".to_string(),
            Type::Scalar(k) => k.name().to_string(),
            Type::Vector { size, scalar } => format!("vec{size}{}", scalar.suffix()),
            Type::Matrix { cols, rows } => format!("mat{cols}x{rows}f"),
            Type::Array { elem, len } => {
                format!("array<{}, {len}>", self.display(elem, struct_name))
            }
            Type::Struct(s) => struct_name(s),
            Type::Texture => "texture".to_string(),
            Type::Mesh => "mesh".to_string(),
            Type::String => "string".to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interning_is_unique() {
        let mut t = TypeTable::new();
        let a = t.intern(Type::Vector {
            size: 3,
            scalar: ScalarKind::F32,
        });
        assert_eq!(a, TypeTable::VEC3F);
        let b = t.intern(Type::Array { elem: a, len: 4 });
        let c = t.intern(Type::Array { elem: a, len: 4 });
        assert_eq!(b, c);
        assert_eq!(t.get(TypeTable::MAT4), Type::Matrix { cols: 4, rows: 4 });
        assert_eq!(t.display(b, &|_| String::new()), "array<vec3f, 4>");
        assert_eq!(t.scalar_or_vector(1, ScalarKind::U32), TypeTable::U32);
        assert_eq!(t.scalar_or_vector(2, ScalarKind::U32), TypeTable::VEC2U);
    }
}
