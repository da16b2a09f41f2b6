//! The size of a kernel as a driver compiles it: its entry point's expressions with every call
//! inlined. Drivers for CPUs (lavapipe: NIR, then LLVM) inline every function, so a kernel's
//! compile time grows with this size rather than with its module's: a traversal called from four
//! places is compiled four times. rtc uses it to choose the execution model of a scene left at
//! `EXEC_AUTO` for a small render ([`super::KernelOptions::wavefront_min_weight`]).
//!
//! Guarantees: linear in the module (each function is measured once, in arena order, which naga's
//! validator makes callees-first), no recursion over calls or blocks, and saturating arithmetic, so
//! no user program can overflow it or the stack.

use naga::{Block, Function, Handle, Module, Statement};

/// The expressions of the entry point `entry` of `module` with every call inlined; `None` when the
/// module has no such entry point.
pub fn inlined_weight(module: &Module, entry: &str) -> Option<u64> {
    inlined_sum(
        module,
        entry,
        |function| function.expressions.len() as u64,
        |_, callee_sum| callee_sum,
    )
}

/// How many copies of the function named `name` the entry point `entry` of `module` holds with
/// every call inlined (a traversal called from two places, each called twice, is four copies);
/// `None` when the module has no such entry point.
pub fn inlined_copies(module: &Module, entry: &str, name: &str) -> Option<u64> {
    inlined_sum(
        module,
        entry,
        |_| 0,
        |callee, callee_sum| {
            if module.functions[callee].name.as_deref() == Some(name) {
                1
            } else {
                callee_sum
            }
        },
    )
}

/// A sum over the entry point `entry` of `module` with every call inlined: each function counts
/// `own(function)` plus, for every call it makes, `call(callee, the callee's sum)` (a callee not
/// yet summed, which a validated module cannot have, counts as 0); `None` without that entry.
fn inlined_sum(
    module: &Module,
    entry: &str,
    own: impl Fn(&Function) -> u64,
    call: impl Fn(Handle<Function>, u64) -> u64,
) -> Option<u64> {
    let entry_point = module.entry_points.iter().find(|e| e.name == entry)?;
    let sum_of = |function: &Function, sums: &[u64]| {
        let mut total = own(function);
        for_each_call(&function.body, |callee| {
            let callee_sum = sums.get(callee.index()).copied().unwrap_or(0);
            total = total.saturating_add(call(callee, callee_sum));
        });
        total
    };
    // A validated module calls only functions declared before the caller, so one pass in arena
    // order sees every callee's sum before its callers need it.
    let mut sums: Vec<u64> = Vec::with_capacity(module.functions.len());
    for (_, function) in module.functions.iter() {
        let n = sum_of(function, &sums);
        sums.push(n);
    }
    Some(sum_of(&entry_point.function, &sums))
}

/// Calls `visit` with the callee of every call statement in `block` and the blocks nested in it.
fn for_each_call(block: &Block, mut visit: impl FnMut(Handle<Function>)) {
    let mut stack = vec![block];
    while let Some(block) = stack.pop() {
        for statement in block.iter() {
            match statement {
                Statement::Call { function, .. } => visit(*function),
                Statement::Block(inner) => stack.push(inner),
                Statement::If { accept, reject, .. } => {
                    stack.push(accept);
                    stack.push(reject);
                }
                Statement::Switch { cases, .. } => stack.extend(cases.iter().map(|c| &c.body)),
                Statement::Loop {
                    body, continuing, ..
                } => {
                    stack.push(body);
                    stack.push(continuing);
                }
                _ => {}
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(wgsl: &str) -> Module {
        naga::front::wgsl::parse_str(wgsl).expect("valid WGSL")
    }

    #[test]
    fn a_function_called_twice_counts_twice() {
        let once = module(
            "fn f(x: f32) -> f32 { return x * x + 1.0; }
             @compute @workgroup_size(1) fn main() { var a = f(2.0); }",
        );
        let twice = module(
            "fn f(x: f32) -> f32 { return x * x + 1.0; }
             @compute @workgroup_size(1) fn main() { var a = f(2.0); if a > 1.0 { a = f(a); } }",
        );
        let (w1, w2) = (
            inlined_weight(&once, "main").expect("entry"),
            inlined_weight(&twice, "main").expect("entry"),
        );
        let f = once.functions.iter().next().expect("f").1.expressions.len() as u64;
        assert!(f >= 4, "f has {f} expressions");
        // The second call adds f's body again, plus the few expressions of the `if` and the call.
        assert!(w2 >= w1 + f && w2 <= w1 + f + 8, "{w1} then {w2}, f = {f}");
    }

    #[test]
    fn nested_calls_multiply() {
        let m = module(
            "fn g(x: f32) -> f32 { return x + 1.0; }
             fn f(x: f32) -> f32 { return g(x) + g(x * 2.0) + g(x * 3.0); }
             @compute @workgroup_size(1) fn main() { var a = f(1.0) + f(2.0); }",
        );
        let g = m.functions.iter().next().expect("g").1.expressions.len() as u64;
        let w = inlined_weight(&m, "main").expect("entry");
        assert!(w >= 6 * g, "weight {w}, g = {g}");
        assert_eq!(inlined_weight(&m, "nothing"), None);
    }

    #[test]
    fn inlined_copies_count_every_call_site_of_every_caller() {
        let m = module(
            "fn t(x: f32) -> f32 { return x; }
             fn s(x: f32) -> f32 { return t(x) + t(x * 2.0); }
             @compute @workgroup_size(1) fn main() { var a = s(1.0) + s(2.0) + t(3.0); }",
        );
        let copies = |name| inlined_copies(&m, "main", name);
        assert_eq!(copies("t"), Some(5));
        assert_eq!(copies("s"), Some(2));
        assert_eq!(copies("u"), Some(0));
        assert_eq!(inlined_copies(&m, "nothing", "t"), None);
    }
}
