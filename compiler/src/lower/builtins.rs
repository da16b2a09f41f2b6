//! Calls of built-in functions (spec/builtins.md): naga math and relational functions where naga's
//! meaning on every target is the spec's, polyfills ([`super::polyfill`]) where it is not, and the
//! [`super::Intrinsics`] hook for the framework intrinsics.
//!
//! Native: `abs sign min max saturate floor ceil round trunc fract sqrt inverse_sqrt pow exp exp2 log
//! log2 sin cos tan asin acos atan atan2 sinh cosh tanh radians degrees mix step smoothstep fma select
//! count_ones reverse_bits first_leading_bit first_trailing_bit dot cross length distance reflect
//! refract face_forward any all transpose determinant pack_unorm4x8 unpack_unorm4x8 pack_snorm2x16
//! unpack_snorm2x16 pack_half2x16 unpack_half2x16`, and `identity` (a constant).
//!
//! Lowered to other native operations: `clamp` is `min(max(x, lo), hi)` (the spec's definition; GLSL and
//! SPIR-V leave `clamp` undefined for `lo > hi`); `length`/`distance` of scalars are `abs`; a scalar
//! `t` of `mix` is splatted.
//!
//! Polyfilled: `is_nan is_inf is_finite normalize inverse transform_point transform_dir
//! orthonormal_basis intersect_triangle intersect_aabb sample_cosine_hemisphere sample_uniform_sphere
//! luminance translate scale rotate_x rotate_y rotate_z rotate`.
//!
//! Invariant: arguments are evaluated left to right before the call, whatever the lowering.

use super::expr::FnCx;
use super::types::vector_size;
use super::{IntrinsicCall, LowerError, Polyfill, Unsupported};
use crate::sema::builtins::Builtin;
use crate::sema::hir::{ExprId, Scalar};
use crate::sema::types::{ScalarKind, Type, TypeId};
use naga::{Expression, Handle, MathFunction as Mf, RelationalFunction as Rf};

/// Whether `b` is a framework intrinsic, lowered by the [`super::Intrinsics`] hook.
pub(super) fn is_intrinsic(b: Builtin) -> bool {
    use Builtin as B;
    matches!(
        b,
        B::Spawn
            | B::LightCount
            | B::SampleLight
            | B::SampleLightUnoccluded
            | B::SampleLightAbove
            | B::Shadow
            | B::Absorb
            | B::Rand
            | B::Rand2
            | B::ImageSize
            | B::FrameIndex
            | B::SamplesPerPixel
            | B::Sample
            | B::TextureSize
            | B::MeshNode
            | B::MeshTriangle
            | B::MeshTriangleCount
            | B::MeshBounds
    )
}

/// The naga math function that is the built-in `b` on every target, if there is one.
fn native(b: Builtin) -> Option<Mf> {
    use Builtin as B;
    Some(match b {
        B::Abs => Mf::Abs,
        B::Sign => Mf::Sign,
        B::Min => Mf::Min,
        B::Max => Mf::Max,
        B::Saturate => Mf::Saturate,
        B::Floor => Mf::Floor,
        B::Ceil => Mf::Ceil,
        B::Round => Mf::Round,
        B::Trunc => Mf::Trunc,
        B::Fract => Mf::Fract,
        B::Sqrt => Mf::Sqrt,
        B::InverseSqrt => Mf::InverseSqrt,
        B::Pow => Mf::Pow,
        B::Exp => Mf::Exp,
        B::Exp2 => Mf::Exp2,
        B::Log => Mf::Log,
        B::Log2 => Mf::Log2,
        B::Sin => Mf::Sin,
        B::Cos => Mf::Cos,
        B::Tan => Mf::Tan,
        B::Asin => Mf::Asin,
        B::Acos => Mf::Acos,
        B::Atan => Mf::Atan,
        B::Atan2 => Mf::Atan2,
        B::Sinh => Mf::Sinh,
        B::Cosh => Mf::Cosh,
        B::Tanh => Mf::Tanh,
        B::Radians => Mf::Radians,
        B::Degrees => Mf::Degrees,
        B::Step => Mf::Step,
        B::Smoothstep => Mf::SmoothStep,
        B::Fma => Mf::Fma,
        B::CountOnes => Mf::CountOneBits,
        B::ReverseBits => Mf::ReverseBits,
        B::FirstLeadingBit => Mf::FirstLeadingBit,
        B::FirstTrailingBit => Mf::FirstTrailingBit,
        B::Dot => Mf::Dot,
        B::Cross => Mf::Cross,
        B::Distance => Mf::Distance,
        B::Reflect => Mf::Reflect,
        B::Refract => Mf::Refract,
        B::FaceForward => Mf::FaceForward,
        B::Transpose => Mf::Transpose,
        B::Determinant => Mf::Determinant,
        B::PackUnorm4x8 => Mf::Pack4x8unorm,
        B::PackSnorm2x16 => Mf::Pack2x16snorm,
        B::PackHalf2x16 => Mf::Pack2x16float,
        B::UnpackUnorm4x8 => Mf::Unpack4x8unorm,
        B::UnpackSnorm2x16 => Mf::Unpack2x16snorm,
        B::UnpackHalf2x16 => Mf::Unpack2x16float,
        _ => return None,
    })
}

fn is_scene_only(b: Builtin) -> bool {
    use Builtin as B;
    matches!(
        b,
        B::LoadMesh | B::QuadMesh | B::CubeMesh | B::SphereMesh | B::LoadImage | B::SolidTexture
    )
}

impl FnCx<'_, '_> {
    /// Lowers a built-in call expression `id` (`ret` is its type).
    pub fn builtin(
        &mut self,
        b: Builtin,
        args: &[ExprId],
        ret: TypeId,
        id: ExprId,
    ) -> Result<Option<Handle<Expression>>, LowerError> {
        let hspan = self.hir_span(id);
        let span = self.lw.span(hspan);
        if is_scene_only(b) {
            return Err(LowerError::Unsupported {
                what: Unsupported::SceneOnly(b),
                span: hspan,
            });
        }
        let mut a = Vec::with_capacity(args.len());
        for arg in args {
            a.push(self.expr(*arg)?);
        }
        let arg_types: Vec<TypeId> = args.iter().map(|e| self.hir_ty(*e)).collect();
        if is_intrinsic(b) {
            let call = IntrinsicCall {
                builtin: b,
                args: &a,
                arg_types: &arg_types,
                ret,
                caller: self.fn_id,
                span,
            };
            return self.hooks.lower(self.lw, &mut self.fb, &call);
        }
        let arg0_ty = arg_types.first().copied().unwrap_or(ret);
        let arity_error = LowerError::InvalidHir {
            what: "a built-in call with the wrong number of arguments",
            span: hspan,
        };
        if a.len() != b.info().overloads.first().map_or(0, |o| o.params.len()) {
            return Err(arity_error);
        }
        let width = self.types().width(arg0_ty).unwrap_or(1);
        let is_vector = matches!(self.types().get(arg0_ty), Type::Vector { .. });
        // `abs` of unsigned integers is the identity (naga's GLSL writer casts to `int` first).
        if b == Builtin::Abs && self.types().scalar_kind(arg0_ty) == Some(ScalarKind::U32) {
            return Ok(a.first().copied());
        }
        if let Some(fun) = native(b) {
            return Ok(Some(self.fb.math(fun, &a, span)));
        }
        use Builtin as B;
        let math = |cx: &mut Self, fun: Mf| Some(cx.fb.math(fun, &a, span));
        let poly = |cx: &mut Self, p: Polyfill| cx.call_polyfill(p, a.clone(), span).map(Some);
        Ok(match b {
            B::Clamp => {
                let lo = self.fb.math(Mf::Max, &[a[0], a[1]], span);
                Some(self.fb.math(Mf::Min, &[lo, a[2]], span))
            }
            B::Mix => {
                let t_scalar = arg_types
                    .get(2)
                    .is_some_and(|t| self.types().width(*t) == Some(1));
                let t = match (is_vector, t_scalar, vector_size(width)) {
                    (true, true, Some(size)) => self.fb.splat(size, a[2], span),
                    _ => a[2],
                };
                Some(self.fb.math(Mf::Mix, &[a[0], a[1], t], span))
            }
            B::Select => Some(self.fb.select(a[2], a[1], a[0], span)),
            B::IsNan => poly(self, Polyfill::IsNan(width))?,
            B::IsInf => poly(self, Polyfill::IsInf(width))?,
            B::IsFinite => poly(self, Polyfill::IsFinite(width))?,
            B::Length if !is_vector => math(self, Mf::Abs),
            B::Length => math(self, Mf::Length),
            B::Distance if !is_vector => {
                let d = self
                    .fb
                    .binary(naga::BinaryOperator::Subtract, a[0], a[1], span);
                Some(self.fb.math(Mf::Abs, &[d], span))
            }
            B::Normalize => poly(self, Polyfill::Normalize(width))?,
            B::Any | B::All => {
                let fun = if b == B::Any { Rf::Any } else { Rf::All };
                Some(self.fb.expr(
                    Expression::Relational {
                        fun,
                        argument: a[0],
                    },
                    span,
                ))
            }
            B::Inverse => match self.types().get(arg0_ty) {
                Type::Matrix { cols, .. } => poly(self, Polyfill::Inverse(cols))?,
                _ => return Err(arity_error),
            },
            B::TransformPoint => poly(self, Polyfill::TransformPoint)?,
            B::TransformDir => poly(self, Polyfill::TransformDir)?,
            B::OrthonormalBasis => poly(self, Polyfill::OrthonormalBasis)?,
            B::IntersectTriangle => poly(self, Polyfill::IntersectTriangle)?,
            B::IntersectAabb => poly(self, Polyfill::IntersectAabb)?,
            B::SampleCosineHemisphere => poly(self, Polyfill::SampleCosineHemisphere)?,
            B::SampleUniformSphere => poly(self, Polyfill::SampleUniformSphere)?,
            B::Luminance => poly(self, Polyfill::Luminance)?,
            B::Identity => Some(self.identity4(span)?),
            B::Translate => poly(self, Polyfill::Translate)?,
            B::Scale if is_vector => poly(self, Polyfill::Scale)?,
            B::Scale => {
                let v = self.fb.splat(naga::VectorSize::Tri, a[0], span);
                Some(self.call_polyfill(Polyfill::Scale, vec![v], span)?)
            }
            B::RotateX => poly(self, Polyfill::RotateX)?,
            B::RotateY => poly(self, Polyfill::RotateY)?,
            B::RotateZ => poly(self, Polyfill::RotateZ)?,
            B::Rotate => poly(self, Polyfill::Rotate)?,
            // Native, intrinsic and scene-only built-ins returned above; the test
            // `every_builtin_has_a_lowering` checks that every other one has an arm.
            _ => {
                return Err(LowerError::Unsupported {
                    what: Unsupported::Intrinsic(b),
                    span: hspan,
                })
            }
        })
    }

    /// The 4×4 identity matrix.
    fn identity4(&mut self, span: naga::Span) -> Result<Handle<Expression>, LowerError> {
        let mat = self.lw.ty(crate::sema::types::TypeTable::MAT4)?;
        let vec4 = self.lw.ty(crate::sema::types::TypeTable::VEC4F)?;
        let mut cols = Vec::with_capacity(4);
        for c in 0..4 {
            let comps = (0..4)
                .map(|r| self.scalar_const(Scalar::F32(if r == c { 1.0 } else { 0.0 })))
                .collect();
            cols.push(self.fb.compose(vec4, comps, span));
        }
        Ok(self.fb.compose(mat, cols, span))
    }
}

/// The built-ins [`FnCx::builtin`] lowers with code of their own (not a native function).
#[cfg(test)]
const SPECIAL: &[Builtin] = &[
    Builtin::All,
    Builtin::Any,
    Builtin::Clamp,
    Builtin::Distance,
    Builtin::Identity,
    Builtin::IntersectAabb,
    Builtin::IntersectTriangle,
    Builtin::Inverse,
    Builtin::IsFinite,
    Builtin::IsInf,
    Builtin::IsNan,
    Builtin::Length,
    Builtin::Luminance,
    Builtin::Mix,
    Builtin::Normalize,
    Builtin::OrthonormalBasis,
    Builtin::Rotate,
    Builtin::RotateX,
    Builtin::RotateY,
    Builtin::RotateZ,
    Builtin::SampleCosineHemisphere,
    Builtin::SampleUniformSphere,
    Builtin::Scale,
    Builtin::Select,
    Builtin::TransformDir,
    Builtin::TransformPoint,
    Builtin::Translate,
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sema::builtins::ALL;

    #[test]
    fn every_builtin_has_a_lowering() {
        for &b in ALL {
            assert!(
                native(b).is_some() || is_intrinsic(b) || is_scene_only(b) || SPECIAL.contains(&b),
                "no lowering for `{}`",
                b.name()
            );
        }
    }
}
