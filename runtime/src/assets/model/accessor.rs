//! A checked reader for glTF accessors (dense and sparse).
//!
//! Invariants: every byte range is computed with checked arithmetic and checked against the
//! buffer view before anything is read, so a lying accessor (offset, count or stride past the
//! end of its data, a stride smaller than an element, a sparse index past `count`) is an
//! [`AssetError`], never a panic or a wrong read. An accessor without a buffer view is zeros
//! (plus sparse substitutions), limited to [`MAX_VIEWLESS_ELEMENTS`] so that a tiny file cannot
//! demand gigabytes.
//!
//! Components are read as `f64` (which holds every `u32` and `f32` exactly) and normalised as the
//! glTF specification says (`u8 / 255`, `max(i8 / 127, -1)`, …) when the accessor says so.

use gltf::json::accessor::{ComponentType, Type};
use gltf::json::validation::Checked;

use super::buffers::{dangling, view_bytes};
use super::Ctx;
use crate::assets::{AssetError, CountProblem, GltfItem};

/// The largest `count` of an accessor that has no buffer view.
pub(super) const MAX_VIEWLESS_ELEMENTS: u64 = 1 << 24;

/// What element types a use of an accessor accepts.
pub(super) struct Expect {
    /// The use, for errors (`POSITION`).
    pub usage: &'static str,
    /// The accepted element types, for errors (`VEC3 of F32`).
    pub description: &'static str,
    /// The element type.
    pub ty: Type,
    /// Whether a component type (and the `normalized` flag) is accepted.
    pub component: fn(ComponentType, bool) -> bool,
}

/// Reads accessor `index` as `N`-component elements, converting each component with `convert`.
pub(super) fn read<T: Copy + Default, const N: usize>(
    ctx: &Ctx<'_>,
    index: usize,
    expect: &Expect,
    convert: fn(f64) -> T,
) -> Result<Vec<[T; N]>, AssetError> {
    let item = GltfItem::Accessor(index);
    let accessor = ctx
        .root
        .accessors
        .get(index)
        .ok_or_else(|| dangling(ctx, item))?;
    let (ty, component) = match (&accessor.type_, &accessor.component_type) {
        (Checked::Valid(ty), Checked::Valid(c)) => (*ty, c.0),
        _ => return Err(dangling(ctx, item)),
    };
    let normalized = accessor.normalized;
    if ty != expect.ty || ty.multiplicity() != N || !(expect.component)(component, normalized) {
        return Err(AssetError::AccessorFormat {
            path: ctx.path.to_owned(),
            item,
            usage: expect.usage,
            found: format!(
                "{ty:?} of {component:?}{}",
                if normalized { " (normalized)" } else { "" }
            ),
            expected: expect.description,
        });
    }
    let out_of_range = |needed: u64, available: u64| AssetError::AccessorOutOfRange {
        path: ctx.path.to_owned(),
        item,
        needed,
        available,
    };
    let bad_count = |problem| AssetError::AccessorCount {
        path: ctx.path.to_owned(),
        item,
        problem,
    };
    let count = accessor.count.0;
    let component_size = component.size();
    let element_size = component_size * N;
    let decode = |bytes: &[u8]| -> [T; N] {
        let mut out = [T::default(); N];
        for (k, slot) in out.iter_mut().enumerate() {
            let value = bytes
                .get(k * component_size..)
                .and_then(|b| component_value(b, component, normalized));
            *slot = convert(value.unwrap_or(0.0));
        }
        out
    };

    let mut elements: Vec<[T; N]> = match accessor.buffer_view {
        Some(view) => {
            let bytes = view_bytes(ctx, view.value())?;
            let stride = match ctx.root.buffer_views.get(view.value()) {
                Some(v) => v.byte_stride.map_or(element_size, |s| s.0),
                None => element_size,
            };
            if stride < element_size {
                return Err(AssetError::AccessorFormat {
                    path: ctx.path.to_owned(),
                    item,
                    usage: expect.usage,
                    found: format!("a byte stride of {stride}, less than the element size"),
                    expected: expect.description,
                });
            }
            let offset = accessor.byte_offset.map_or(0, |o| o.0);
            let needed = dense_end(offset, stride as u64, count, element_size as u64);
            let data = needed
                .and_then(|end| usize::try_from(end).ok())
                .and_then(|end| bytes.get(usize::try_from(offset).ok()?..end))
                .ok_or_else(|| out_of_range(needed.unwrap_or(u64::MAX), bytes.len() as u64))?;
            // `data` holds `count` elements, `stride` apart; the last may be shorter than a
            // stride, which `chunks` allows.
            data.chunks(stride).map(decode).collect()
        }
        None => {
            if count > MAX_VIEWLESS_ELEMENTS {
                return Err(bad_count(CountProblem::ViewlessTooLarge {
                    count,
                    max: MAX_VIEWLESS_ELEMENTS,
                }));
            }
            vec![[T::default(); N]; count as usize]
        }
    };

    if let Some(sparse) = &accessor.sparse {
        let n = sparse.count.0;
        if n > count {
            return Err(bad_count(CountProblem::SparseCount { sparse: n, count }));
        }
        let Checked::Valid(index_type) = &sparse.indices.component_type else {
            return Err(dangling(ctx, item));
        };
        let index_type = index_type.0;
        let index_size = index_type.size() as u64;
        let index_bytes = sparse_slice(
            ctx,
            &sparse.indices.buffer_view,
            sparse.indices.byte_offset.0,
            n,
            index_size,
            item,
        )?;
        let value_bytes = sparse_slice(
            ctx,
            &sparse.values.buffer_view,
            sparse.values.byte_offset.0,
            n,
            element_size as u64,
            item,
        )?;
        for (ib, vb) in index_bytes
            .chunks_exact(index_type.size())
            .zip(value_bytes.chunks_exact(element_size))
        {
            let target = component_value(ib, index_type, false).unwrap_or(f64::MAX);
            let slot = elements
                .get_mut(target as usize)
                .filter(|_| target >= 0.0 && target < count as f64)
                .ok_or_else(|| {
                    bad_count(CountProblem::SparseIndex {
                        index: target as u64,
                        count,
                    })
                })?;
            *slot = decode(vb);
        }
    }
    Ok(elements)
}

/// The tightly packed bytes of `n` sparse indices or values.
fn sparse_slice<'a>(
    ctx: &Ctx<'a>,
    view: &gltf::json::Index<gltf::json::buffer::View>,
    offset: u64,
    n: u64,
    element_size: u64,
    item: GltfItem,
) -> Result<&'a [u8], AssetError> {
    let bytes = view_bytes(ctx, view.value())?;
    let end = n
        .checked_mul(element_size)
        .and_then(|len| len.checked_add(offset));
    end.and_then(|e| usize::try_from(e).ok())
        .and_then(|e| bytes.get(usize::try_from(offset).ok()?..e))
        .ok_or(AssetError::AccessorOutOfRange {
            path: ctx.path.to_owned(),
            item,
            needed: end.unwrap_or(u64::MAX),
            available: bytes.len() as u64,
        })
}

/// The end of `count` elements of `size` bytes, `stride` apart, from `offset`; `None` on
/// overflow. Zero elements end at `offset`.
fn dense_end(offset: u64, stride: u64, count: u64, size: u64) -> Option<u64> {
    match count.checked_sub(1) {
        None => Some(offset),
        Some(last) => last
            .checked_mul(stride)?
            .checked_add(size)?
            .checked_add(offset),
    }
}

/// One component from the start of `bytes`, normalised if asked.
fn component_value(bytes: &[u8], ty: ComponentType, normalized: bool) -> Option<f64> {
    fn le<const K: usize>(bytes: &[u8]) -> Option<[u8; K]> {
        bytes.get(..K)?.try_into().ok()
    }
    Some(match ty {
        ComponentType::U8 => {
            let v = f64::from(u8::from_le_bytes(le(bytes)?));
            if normalized {
                v / 255.0
            } else {
                v
            }
        }
        ComponentType::I8 => {
            let v = f64::from(i8::from_le_bytes(le(bytes)?));
            if normalized {
                (v / 127.0).max(-1.0)
            } else {
                v
            }
        }
        ComponentType::U16 => {
            let v = f64::from(u16::from_le_bytes(le(bytes)?));
            if normalized {
                v / 65535.0
            } else {
                v
            }
        }
        ComponentType::I16 => {
            let v = f64::from(i16::from_le_bytes(le(bytes)?));
            if normalized {
                (v / 32767.0).max(-1.0)
            } else {
                v
            }
        }
        ComponentType::U32 => f64::from(u32::from_le_bytes(le(bytes)?)),
        ComponentType::F32 => f64::from(f32::from_le_bytes(le(bytes)?)),
    })
}
