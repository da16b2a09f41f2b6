//! The one table of diagnostic codes.
//!
//! A code never changes meaning once it has shipped; retired codes stay reserved. Ranges:
//! - `E01xx` lexical structure
//! - `E02xx` syntax
//! - `E03xx` modules, imports and name resolution
//! - `E04xx` types and expressions
//! - `E05xx` statements and control flow
//! - `E06xx` program attributes, signatures, struct roles and intrinsics
//! - `E07xx` scenes
//! - `E08xx` call graph (recursion) and static limits
//! - `E09xx` linking a scene (missing programs, assets)
//! - `W0xxx` warnings
//! - `ICE` internal compiler error (a bug in rtc)
//!
//! Every code here is documented in `spec/diagnostics.md`; a test checks that the two agree.

/// A stable diagnostic code such as `E0401`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Code(pub &'static str);

macro_rules! codes {
    ($($(#[$m:meta])* $name:ident => $summary:literal,)*) => {
        $( $(#[$m])* #[doc = $summary] pub const $name: Code = Code(stringify!($name)); )*
        /// Every code with its one-line summary, in table order.
        pub static ALL: &[(Code, &str)] = &[ $( ($name, $summary), )* ];
    };
}

codes! {
    // ---- lexical ----
    E0101 => "a character that cannot start a token",
    E0102 => "an unterminated block comment",
    E0103 => "an unterminated string literal",
    E0104 => "a malformed number literal",
    E0105 => "an integer literal out of range for its type",
    E0106 => "an unknown literal suffix",
    E0107 => "an invalid escape sequence in a string",
    E0108 => "the file is not valid UTF-8",

    // ---- syntax ----
    E0201 => "expected a token or construct that is not there",
    E0202 => "an expression is nested too deeply",
    E0203 => "an unknown attribute",
    E0204 => "a struct literal where it is not allowed (in a condition, without parentheses)",
    E0205 => "an invalid assignment target",
    E0206 => "an item that cannot appear here",

    // ---- modules, imports and names ----
    E0301 => "an import path that does not name a file",
    E0302 => "an import cycle",
    E0303 => "a name that is not defined",
    E0304 => "a name defined twice in one scope",
    E0305 => "a name imported from two modules (ambiguous)",
    E0306 => "a type name used as a value, or a value as a type",
    E0307 => "an unknown field of a struct",
    E0308 => "an import that is not at the top of the file",

    // ---- types and expressions ----
    E0401 => "mismatched types",
    E0402 => "an operator that does not apply to these operand types",
    E0403 => "a function called with the wrong number of arguments",
    E0404 => "no overload of a built-in function matches the arguments",
    E0405 => "an invalid swizzle",
    E0406 => "indexing a value that cannot be indexed, or a constant index out of range",
    E0407 => "a struct literal missing a field that has no default",
    E0408 => "a field given twice in a struct literal",
    E0409 => "an invalid type conversion or constructor",
    E0410 => "an array size that is not a positive constant",
    E0411 => "a literal that does not fit the type it is inferred to",
    E0412 => "an expression that is not constant where a constant is required",
    E0413 => "a type that cannot be used here",
    E0414 => "a call to something that is not a function",
    E0415 => "a constant operation on finite values whose `f32` result is infinite or NaN",
    E0416 => "a struct without fields",

    // ---- statements and control flow ----
    E0501 => "assignment to an immutable binding",
    E0502 => "`break` or `continue` outside a loop",
    E0503 => "a function that does not return a value on every path",
    E0504 => "`return` with a value in a function that returns nothing, or without one where a value is needed",
    E0505 => "a condition that is not `bool`",
    E0506 => "a `for` range whose bounds are not integers of one type",

    // ---- program attributes, signatures, roles, intrinsics ----
    E0601 => "a program whose signature does not match its attribute",
    E0602 => "an attribute on the wrong kind of item",
    E0603 => "a program whose first parameter is not a struct of the right role",
    E0604 => "an intrinsic used outside the programs that may call it",
    E0605 => "a field type that cannot be stored in scene data",
    E0606 => "an invalid attribute argument",
    E0607 => "two programs of one kind for the same type",
    E0608 => "two role attributes on one struct",

    // ---- scenes ----
    E0701 => "a scene entry that is not known",
    E0702 => "a scene value of the wrong role (e.g. a material where a geometry is expected)",
    E0703 => "a required scene entry is missing",
    E0704 => "a scene setting out of range",
    E0705 => "a scene entry given twice",
    E0706 => "more than one scene where one is expected",
    E0707 => "a procedural mesh parameter out of range (`sphere_mesh` subdivisions)",
    E0708 => "a transform that cannot be inverted in single precision (not affine, singular, or a scale whose inverse overflows `f32`)",
    E0709 => "a camera parameter that makes every ray invalid (a field of view, size or distance out of range, a zero-length view direction, `up` along the view direction)",
    E0710 => "an animation target that is not known (no such object, light or field)",
    E0711 => "animation keys that are missing, out of order, repeated or at a negative time",
    E0712 => "an animation value of the wrong type for its target, or a motion the target cannot take",

    // ---- call graph and static limits ----
    E0801 => "recursion (GPUs have no call stack)",
    E0802 => "a secondary-ray program whose number of spawned rays cannot be bounded",
    E0803 => "a type larger than the largest buffer binding (128 MiB)",
    E0804 => "a function's local values exceed the private-memory budget of one invocation",
    E0805 => "a constant array too large to evaluate",
    E0806 => "a function too large for a target's code writer",

    // ---- linking a scene ----
    E0901 => "a scene object whose material or geometry type has no program of a kind it needs",
    E0902 => "an asset (mesh, image, glTF file) that cannot be read",
    E0903 => "an asset path that leads outside the scene's folder and the asset roots",

    // ---- warnings ----
    W0001 => "an unused variable",
    W0002 => "an expression statement whose value is unused",
    W0003 => "unreachable code",
    W0004 => "`max_rays_per_hit` below the spawn bound of a `@secondary_rays` program the scene uses: rays are dropped",

    // ---- internal ----
    ICE => "internal compiler error: a bug in rtc, please report it",
}

#[cfg(test)]
mod tests {
    #[test]
    fn codes_are_unique() {
        let mut seen = std::collections::HashSet::new();
        for (code, _) in super::ALL {
            assert!(seen.insert(code.0), "duplicate code {}", code.0);
        }
    }
}
