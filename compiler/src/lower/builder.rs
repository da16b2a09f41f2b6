//! A small builder for naga functions: the one place that handles `Statement::Emit`.
//!
//! naga requires every expression that is not "pre-emitted" (literals, constants, arguments, globals,
//! locals, zero values; see `Expression::needs_pre_emit`) to be covered by exactly one `Emit` statement
//! before it is used, and `CallResult` expressions to be appended right before their `Call`. Getting this
//! wrong gives validation errors far from the cause, so all lowering goes through [`FnBuilder`]:
//! - [`FnBuilder::expr`] appends an expression; pre-emitted ones interrupt the running emitter so they
//!   are never inside an `Emit` range;
//! - [`FnBuilder::stmt`] first flushes the pending `Emit`, then pushes the statement;
//! - nested blocks (`if`, `loop`, `switch` bodies) are built with [`FnBuilder::push_block`] /
//!   [`FnBuilder::pop_block`], each with its own emitter scope.
//!
//! Invariant: between calls the emitter is running on the innermost open block, so every expression
//! appended is emitted in the block where it was appended, before any statement that follows it.
//!
//! [`TypeCache`] interns the handful of types lowering asks for again and again.

use naga::{
    proc::Emitter, Block, Expression, Function, FunctionArgument, FunctionResult, Handle,
    LocalVariable, Module, Scalar, Span, Statement, Type, TypeInner, VectorSize,
};

/// Builds one naga function.
pub struct FnBuilder {
    func: Function,
    emitter: Emitter,
    blocks: Vec<Block>,
}

impl FnBuilder {
    /// Starts a function with these arguments and result type.
    pub fn new(
        name: &str,
        args: &[(&str, Handle<Type>)],
        result: Option<Handle<Type>>,
    ) -> FnBuilder {
        let func = Function {
            name: Some(name.to_string()),
            arguments: args
                .iter()
                .map(|(n, ty)| FunctionArgument {
                    name: Some((*n).to_string()),
                    ty: *ty,
                    binding: None,
                })
                .collect(),
            result: result.map(|ty| FunctionResult { ty, binding: None }),
            ..Function::default()
        };
        let mut b = FnBuilder {
            func,
            emitter: Emitter::default(),
            blocks: vec![Block::new()],
        };
        b.emitter.start(&b.func.expressions);
        b
    }

    /// The function's `i`th argument.
    pub fn arg(&mut self, i: u32) -> Handle<Expression> {
        self.expr(Expression::FunctionArgument(i), Span::UNDEFINED)
    }

    /// The value of `h` when it is a `u32` literal.
    pub fn literal_u32(&self, h: Handle<Expression>) -> Option<u32> {
        match self.func.expressions[h] {
            Expression::Literal(naga::Literal::U32(v)) => Some(v),
            _ => None,
        }
    }

    /// Appends an expression in the current block.
    pub fn expr(&mut self, e: Expression, span: Span) -> Handle<Expression> {
        if e.needs_pre_emit() {
            self.end_emit();
            let h = self.func.expressions.append(e, span);
            self.emitter.start(&self.func.expressions);
            h
        } else {
            self.func.expressions.append(e, span)
        }
    }

    /// Ends the running `Emit` range, pushing it into the current block. The emitter is stopped after.
    fn end_emit(&mut self) {
        if let Some((emit, span)) = self.emitter.finish(&self.func.expressions) {
            self.current().push(emit, span);
        }
    }

    /// Ends the running `Emit` range and starts a new one.
    fn flush(&mut self) {
        self.end_emit();
        self.emitter.start(&self.func.expressions);
    }

    fn current(&mut self) -> &mut Block {
        // `blocks` always holds the function body at index 0.
        let last = self.blocks.len() - 1;
        &mut self.blocks[last]
    }

    /// Pushes a statement into the current block, after emitting the expressions appended so far.
    pub fn stmt(&mut self, s: Statement, span: Span) {
        self.flush();
        self.current().push(s, span);
    }

    /// Calls `function` with `args`; returns the result expression if the function has a result.
    pub fn call(
        &mut self,
        function: Handle<Function>,
        args: Vec<Handle<Expression>>,
        has_result: bool,
        span: Span,
    ) -> Option<Handle<Expression>> {
        self.end_emit();
        // A `CallResult` must not be covered by an `Emit`: append it while the emitter is stopped.
        let result = has_result.then(|| {
            self.func
                .expressions
                .append(Expression::CallResult(function), span)
        });
        self.emitter.start(&self.func.expressions);
        self.current().push(
            Statement::Call {
                function,
                arguments: args,
                result,
            },
            span,
        );
        result
    }

    /// Declares a function-local variable and returns the pointer expression to it.
    pub fn local(
        &mut self,
        name: &str,
        ty: Handle<Type>,
        init: Option<Handle<Expression>>,
    ) -> Handle<Expression> {
        let var = self.func.local_variables.append(
            LocalVariable {
                name: Some(name.to_string()),
                ty,
                init: None,
            },
            Span::UNDEFINED,
        );
        let ptr = self.expr(Expression::LocalVariable(var), Span::UNDEFINED);
        if let Some(value) = init {
            self.stmt(
                Statement::Store {
                    pointer: ptr,
                    value,
                },
                Span::UNDEFINED,
            );
        }
        ptr
    }

    /// The local variable behind a pointer made by [`FnBuilder::local`].
    pub fn local_handle(&self, ptr: Handle<Expression>) -> Option<Handle<LocalVariable>> {
        match self.func.expressions[ptr] {
            Expression::LocalVariable(v) => Some(v),
            _ => None,
        }
    }

    /// `*ptr`
    pub fn load(&mut self, pointer: Handle<Expression>, span: Span) -> Handle<Expression> {
        self.expr(Expression::Load { pointer }, span)
    }

    /// `*ptr = value;`
    pub fn store(&mut self, pointer: Handle<Expression>, value: Handle<Expression>, span: Span) {
        self.stmt(Statement::Store { pointer, value }, span);
    }

    /// Opens a nested block (the body of an `if`, `loop` or `switch` case).
    pub fn push_block(&mut self) {
        self.end_emit();
        self.blocks.push(Block::new());
        self.emitter.start(&self.func.expressions);
    }

    /// Closes the innermost nested block and returns it.
    pub fn pop_block(&mut self) -> Block {
        self.end_emit();
        let block = if self.blocks.len() > 1 {
            self.blocks.pop().unwrap_or_default()
        } else {
            Block::new()
        };
        self.emitter.start(&self.func.expressions);
        block
    }

    /// Whether the current block already ends in a statement that leaves it (`return`, `break`, …).
    pub fn terminated(&self) -> bool {
        self.blocks.last().and_then(|b| b.last()).is_some_and(|s| {
            matches!(
                s,
                Statement::Return { .. } | Statement::Break | Statement::Continue | Statement::Kill
            )
        })
    }

    /// Type of an expression, if the builder can tell without a module (only for locals/arguments).
    pub fn function(&self) -> &Function {
        &self.func
    }

    /// Gives an expression a name (a `let` in the written code). The first name given wins; naming a
    /// pre-emitted expression (a literal, an argument) has no visible effect in naga's writers.
    pub fn name(&mut self, expr: Handle<Expression>, name: &str) {
        self.func
            .named_expressions
            .entry(expr)
            .or_insert_with(|| name.to_string());
    }

    /// A literal (pre-emitted). Callers make sure it is finite: naga rejects NaN and infinite literals.
    pub fn literal(&mut self, value: naga::Literal) -> Handle<Expression> {
        self.expr(Expression::Literal(value), Span::UNDEFINED)
    }

    /// `left op right`
    pub fn binary(
        &mut self,
        op: naga::BinaryOperator,
        left: Handle<Expression>,
        right: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::Binary { op, left, right }, span)
    }

    /// `op expr`
    pub fn unary(
        &mut self,
        op: naga::UnaryOperator,
        expr: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::Unary { op, expr }, span)
    }

    /// A math function applied to one to four arguments (extra arguments are ignored).
    pub fn math(
        &mut self,
        fun: naga::MathFunction,
        args: &[Handle<Expression>],
        span: Span,
    ) -> Handle<Expression> {
        let mut it = args.iter().copied();
        let arg = it
            .next()
            .unwrap_or_else(|| self.literal(naga::Literal::F32(0.0)));
        let (arg1, arg2, arg3) = (it.next(), it.next(), it.next());
        self.expr(
            Expression::Math {
                fun,
                arg,
                arg1,
                arg2,
                arg3,
            },
            span,
        )
    }

    /// `base.index` (a struct member, vector component or matrix column; also through pointers).
    pub fn access_index(
        &mut self,
        base: Handle<Expression>,
        index: u32,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::AccessIndex { base, index }, span)
    }

    /// `base[index]` with a computed index.
    pub fn access(
        &mut self,
        base: Handle<Expression>,
        index: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::Access { base, index }, span)
    }

    /// A value of type `ty` made of `components`.
    pub fn compose(
        &mut self,
        ty: Handle<Type>,
        components: Vec<Handle<Expression>>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::Compose { ty, components }, span)
    }

    /// A vector of `size` copies of the scalar `value`.
    pub fn splat(
        &mut self,
        size: VectorSize,
        value: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(Expression::Splat { size, value }, span)
    }

    /// `accept` where `condition` holds, else `reject` (both evaluated).
    pub fn select(
        &mut self,
        condition: Handle<Expression>,
        accept: Handle<Expression>,
        reject: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(
            Expression::Select {
                condition,
                accept,
                reject,
            },
            span,
        )
    }

    /// A conversion (`convert: Some(4)`) or a bit cast (`convert: None`) to `kind`.
    pub fn cast(
        &mut self,
        expr: Handle<Expression>,
        kind: naga::ScalarKind,
        convert: Option<u8>,
        span: Span,
    ) -> Handle<Expression> {
        self.expr(
            Expression::As {
                expr,
                kind,
                convert,
            },
            span,
        )
    }

    /// `return value;`
    pub fn ret(&mut self, value: Option<Handle<Expression>>, span: Span) {
        self.stmt(Statement::Return { value }, span);
    }

    /// Declares a local variable with a source span; returns the pointer expression to it.
    pub fn local_at(
        &mut self,
        name: &str,
        ty: Handle<Type>,
        init: Option<Handle<Expression>>,
        span: Span,
    ) -> Handle<Expression> {
        let var = self.func.local_variables.append(
            LocalVariable {
                name: Some(name.to_string()),
                ty,
                init: None,
            },
            span,
        );
        let ptr = self.expr(Expression::LocalVariable(var), span);
        if let Some(value) = init {
            self.stmt(
                Statement::Store {
                    pointer: ptr,
                    value,
                },
                span,
            );
        }
        ptr
    }

    /// The number of nested blocks open (0 in the function body).
    pub fn depth(&self) -> usize {
        self.blocks.len() - 1
    }

    /// Finishes the function.
    pub fn finish(mut self) -> Function {
        self.end_emit();
        while self.blocks.len() > 1 {
            let inner = self.blocks.pop().unwrap_or_default();
            self.current()
                .push(Statement::Block(inner), Span::UNDEFINED);
        }
        self.func.body = self.blocks.pop().unwrap_or_default();
        self.func
    }
}

/// Interned types that lowering uses often.
pub struct TypeCache;

impl TypeCache {
    /// A scalar type.
    pub fn scalar(module: &mut Module, scalar: Scalar) -> Handle<Type> {
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Scalar(scalar),
            },
            Span::UNDEFINED,
        )
    }

    /// A vector type.
    pub fn vector(module: &mut Module, size: VectorSize, scalar: Scalar) -> Handle<Type> {
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Vector { size, scalar },
            },
            Span::UNDEFINED,
        )
    }

    /// A matrix of f32 with `columns` columns of `rows` rows.
    pub fn matrix(module: &mut Module, columns: VectorSize, rows: VectorSize) -> Handle<Type> {
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Matrix {
                    columns,
                    rows,
                    scalar: Scalar::F32,
                },
            },
            Span::UNDEFINED,
        )
    }

    /// A fixed-size array (stride computed with naga's layouter rules for its element).
    pub fn array(module: &mut Module, base: Handle<Type>, len: u32) -> Handle<Type> {
        let stride = Self::stride(module, base);
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Array {
                    base,
                    size: naga::ArraySize::Constant(
                        std::num::NonZeroU32::new(len.max(1)).unwrap_or(std::num::NonZeroU32::MIN),
                    ),
                    stride,
                },
            },
            Span::UNDEFINED,
        )
    }

    /// A runtime-sized array (only for storage buffer bindings).
    pub fn runtime_array(module: &mut Module, base: Handle<Type>) -> Handle<Type> {
        let stride = Self::stride(module, base);
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Array {
                    base,
                    size: naga::ArraySize::Dynamic,
                    stride,
                },
            },
            Span::UNDEFINED,
        )
    }

    /// The array stride of `ty`: its size rounded up to its alignment.
    pub fn stride(module: &Module, ty: Handle<Type>) -> u32 {
        let mut layouter = naga::proc::Layouter::default();
        if layouter.update(module.to_ctx()).is_err() {
            return 4;
        }
        let layout = layouter[ty];
        layout.alignment.round_up(layout.size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use naga::{BinaryOperator, Literal};

    /// `fn add(a: f32, b: f32) -> f32 { var acc = a; if a < b { acc = acc + b; } return acc; }` and a
    /// caller, built with the builder, must validate.
    #[test]
    fn built_functions_validate() {
        let mut module = Module::default();
        let f32_ty = TypeCache::scalar(&mut module, Scalar::F32);
        let mut b = FnBuilder::new("add", &[("a", f32_ty), ("b", f32_ty)], Some(f32_ty));
        let a = b.arg(0);
        let bb = b.arg(1);
        let acc = b.local("acc", f32_ty, Some(a));
        let cond = b.expr(
            Expression::Binary {
                op: BinaryOperator::Less,
                left: a,
                right: bb,
            },
            Span::UNDEFINED,
        );
        b.push_block();
        let cur = b.load(acc, Span::UNDEFINED);
        let sum = b.expr(
            Expression::Binary {
                op: BinaryOperator::Add,
                left: cur,
                right: bb,
            },
            Span::UNDEFINED,
        );
        b.store(acc, sum, Span::UNDEFINED);
        let accept = b.pop_block();
        b.stmt(
            Statement::If {
                condition: cond,
                accept,
                reject: Block::new(),
            },
            Span::UNDEFINED,
        );
        let result = b.load(acc, Span::UNDEFINED);
        b.stmt(
            Statement::Return {
                value: Some(result),
            },
            Span::UNDEFINED,
        );
        let add = module.functions.append(b.finish(), Span::UNDEFINED);

        let mut c = FnBuilder::new("caller", &[], Some(f32_ty));
        let one = c.expr(Expression::Literal(Literal::F32(1.0)), Span::UNDEFINED);
        let two = c.expr(Expression::Literal(Literal::F32(2.0)), Span::UNDEFINED);
        let r = c.call(add, vec![one, two], true, Span::UNDEFINED).unwrap();
        let neg = c.expr(
            Expression::Unary {
                op: naga::UnaryOperator::Negate,
                expr: r,
            },
            Span::UNDEFINED,
        );
        c.stmt(Statement::Return { value: Some(neg) }, Span::UNDEFINED);
        module.functions.append(c.finish(), Span::UNDEFINED);

        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{e:?}"));
    }

    #[test]
    fn array_stride_follows_layout_rules() {
        let mut module = Module::default();
        let v3 = TypeCache::vector(&mut module, VectorSize::Tri, Scalar::F32);
        let arr = TypeCache::array(&mut module, v3, 4);
        match module.types[arr].inner {
            TypeInner::Array { stride, .. } => assert_eq!(stride, 16),
            ref other => panic!("{other:?}"),
        }
    }
}
