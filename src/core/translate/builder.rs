//! A small builder for one naga function: expressions are appended to the
//! function's arena and statements to the innermost open block, and every
//! expression is covered by an `Emit` statement before any statement that
//! can use it — the bookkeeping naga's IR asks of every front end.
//!
//! Expressions naga evaluates up front (literals, constants, variables)
//! interrupt the emit range, as naga's own front ends do. An expression is
//! in scope only in the block that emitted it and the blocks nested in it,
//! so callers build fresh loads instead of caching values across blocks.

use naga::{Block, Expression, Function, Handle, Literal, LocalVariable, Span, Statement, Type};

pub(super) struct Fb {
    pub f: Function,
    /// Open blocks; the first is the function body.
    blocks: Vec<Block>,
    /// First expression not yet covered by an `Emit`.
    emit_start: Option<usize>,
}

pub(super) type Expr = Handle<Expression>;

impl Fb {
    pub fn new(name: &str) -> Fb {
        Fb {
            f: Function {
                name: Some(name.to_string()),
                ..Function::default()
            },
            blocks: vec![Block::new()],
            emit_start: None,
        }
    }

    /// Appends an expression (emitted at the next statement or block edge).
    pub fn add(&mut self, e: Expression) -> Expr {
        let pre = e.needs_pre_emit();
        if pre {
            self.flush();
        }
        let h = self.f.expressions.append(e, Span::UNDEFINED);
        if !pre && self.emit_start.is_none() {
            self.emit_start = Some(h.index());
        }
        h
    }

    /// The result of a call (defined by the `Call` statement that follows,
    /// never emitted).
    pub fn call_result(&mut self, function: Handle<naga::Function>) -> Expr {
        self.flush();
        self.f
            .expressions
            .append(Expression::CallResult(function), Span::UNDEFINED)
    }

    /// The result of an atomic operation (defined by the `Atomic`
    /// statement that follows, never emitted).
    pub fn atomic_result(&mut self, ty: Handle<Type>) -> Expr {
        self.flush();
        self.f.expressions.append(
            Expression::AtomicResult {
                ty,
                comparison: false,
            },
            Span::UNDEFINED,
        )
    }

    fn flush(&mut self) {
        if let Some(start) = self.emit_start.take() {
            let range = self.f.expressions.range_from(start);
            if let Some(b) = self.blocks.last_mut() {
                b.push(Statement::Emit(range), Span::UNDEFINED);
            }
        }
    }

    /// Appends a statement to the innermost open block.
    pub fn push(&mut self, s: Statement) {
        self.flush();
        if let Some(b) = self.blocks.last_mut() {
            b.push(s, Span::UNDEFINED);
        }
    }

    /// Opens a nested block (the body of an `if` or a loop).
    pub fn open(&mut self) {
        self.flush();
        self.blocks.push(Block::new());
    }

    /// Closes the innermost block and returns it.
    pub fn close(&mut self) -> Block {
        self.flush();
        self.blocks.pop().unwrap_or_default()
    }

    /// The finished function.
    pub fn finish(mut self) -> Function {
        self.flush();
        let body = self.blocks.drain(..).next().unwrap_or_default();
        self.f.body = body;
        self.f
    }

    pub fn local(&mut self, name: &str, ty: Handle<Type>) -> Expr {
        let v = self.f.local_variables.append(
            LocalVariable {
                name: Some(name.to_string()),
                ty,
                init: None,
            },
            Span::UNDEFINED,
        );
        self.add(Expression::LocalVariable(v))
    }

    pub fn f32(&mut self, v: f32) -> Expr {
        self.add(Expression::Literal(Literal::F32(v)))
    }

    pub fn i32(&mut self, v: i32) -> Expr {
        self.add(Expression::Literal(Literal::I32(v)))
    }

    pub fn u32(&mut self, v: u32) -> Expr {
        self.add(Expression::Literal(Literal::U32(v)))
    }

    pub fn bool(&mut self, v: bool) -> Expr {
        self.add(Expression::Literal(Literal::Bool(v)))
    }

    pub fn load(&mut self, pointer: Expr) -> Expr {
        self.add(Expression::Load { pointer })
    }

    pub fn store(&mut self, pointer: Expr, value: Expr) {
        self.push(Statement::Store { pointer, value });
    }

    pub fn index(&mut self, base: Expr, index: u32) -> Expr {
        self.add(Expression::AccessIndex { base, index })
    }

    pub fn binary(&mut self, op: naga::BinaryOperator, left: Expr, right: Expr) -> Expr {
        self.add(Expression::Binary { op, left, right })
    }

    pub fn math(&mut self, fun: naga::MathFunction, args: &[Expr]) -> Expr {
        self.add(Expression::Math {
            fun,
            arg: args[0],
            arg1: args.get(1).copied(),
            arg2: args.get(2).copied(),
            arg3: args.get(3).copied(),
        })
    }

    pub fn select(&mut self, condition: Expr, accept: Expr, reject: Expr) -> Expr {
        self.add(Expression::Select {
            condition,
            accept,
            reject,
        })
    }

    pub fn splat(&mut self, value: Expr, size: naga::VectorSize) -> Expr {
        self.add(Expression::Splat { size, value })
    }

    pub fn negate(&mut self, expr: Expr) -> Expr {
        self.add(Expression::Unary {
            op: naga::UnaryOperator::Negate,
            expr,
        })
    }

    pub fn not(&mut self, expr: Expr) -> Expr {
        self.add(Expression::Unary {
            op: naga::UnaryOperator::LogicalNot,
            expr,
        })
    }

    /// `if condition { accept }` with `accept` built by `body`.
    pub fn if_then(&mut self, condition: Expr, body: impl FnOnce(&mut Fb)) {
        self.open();
        body(self);
        let accept = self.close();
        self.push(Statement::If {
            condition,
            accept,
            reject: Block::new(),
        });
    }
}
