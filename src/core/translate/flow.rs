//! Flow control: D3D9's blocks become naga's structured statements.
//!
//! * `if b#`, `if p0.c`, `if_comp` … `else` … `endif` → `if`;
//! * `rep i#` → a loop with its own counter; `loop aL, i#` → the same with
//!   aL = i#.y, stepped by i#.z after each iteration and restored when the
//!   loop ends (nested loops see their own aL, as in the emulator);
//! * `break`, `break_comp`, `breakp` → `break` (alone or in an `if`): no
//!   other naga loop or switch is ever opened inside a D3D9 loop, so the
//!   innermost naga loop is the D3D9 one;
//! * `label l#` … `ret` → a function `l#` with no arguments (registers are
//!   globals); `call` → a call, `callnz` → a call in an `if`; `ret` →
//!   `return`. The validator refuses recursion, so every callee can be
//!   placed before its callers, as naga requires.
//!
//! Counts come from `i#` as the emulator reads them: the shader's `defi`,
//! else the application's value in the constant block. A count of 0 or
//! less runs no iteration.

use super::builder::Fb;
use super::lower::Lower;
use super::TranslateError;
use crate::core::ir::{Instruction, Src, SrcMod};
use crate::core::isa::{Class, Opcode, RegFile};
use naga::{BinaryOperator as B, Expression, Handle, Statement};
use std::collections::BTreeMap;

/// A straight run of plain instructions, cut into nested blocks of
/// [`Run::CHUNK`] after its first [`Run::CHUNK`]: a writer that keeps the
/// names of a block's values in one ordered map and removes them one by one
/// at the block's end (naga's MSL writer) then does work linear in the
/// shader's length instead of quadratic (40,000 instructions: 18 s before).
/// Each instruction loads its registers afresh, so no value crosses a cut;
/// shaders with shorter runs are lowered exactly as before.
#[derive(Default)]
struct Run {
    /// Plain instructions lowered in this run so far.
    count: usize,
    /// Whether a nested block is open for the current chunk.
    open: bool,
}

impl Run {
    const CHUNK: usize = 256;

    /// Whether `op` is lowered by `instruction` (not flow control).
    fn is_plain(op: Opcode) -> bool {
        op.class() != Class::Flow
    }

    /// Before the run's next instruction: opens a new chunk where one starts.
    fn next(&mut self, fb: &mut Fb) {
        if self.count >= Self::CHUNK && self.count.is_multiple_of(Self::CHUNK) {
            self.close(fb);
            fb.open();
            self.open = true;
        }
        self.count += 1;
    }

    fn close(&mut self, fb: &mut Fb) {
        if self.open {
            let block = fb.close();
            fb.push(Statement::Block(block));
            self.open = false;
        }
    }

    /// Ends the run (flow control, or the end of the range).
    fn end(&mut self, fb: &mut Fb) {
        self.close(fb);
        self.count = 0;
    }
}

/// Functions lowered so far, by label.
pub(super) type Functions = BTreeMap<u32, Handle<naga::Function>>;

impl Lower<'_> {
    /// Lowers instructions `start..end` of `ins` into the current block.
    pub fn range(
        &mut self,
        ins: &[Instruction],
        matching: &[Option<u32>],
        functions: &Functions,
        start: usize,
        end: usize,
    ) -> Result<(), TranslateError> {
        let mut i = start;
        let mut run = Run::default();
        while i < end {
            let x = &ins[i];
            if Run::is_plain(x.op) {
                run.next(&mut self.fb);
                self.instruction(x)?;
                i += 1;
                continue;
            }
            run.end(&mut self.fb);
            let next = |i: usize| -> Result<usize, TranslateError> {
                matching
                    .get(i)
                    .copied()
                    .flatten()
                    .map(|m| m as usize)
                    .ok_or(TranslateError::Internal("an unmatched block"))
            };
            match x.op {
                Opcode::If | Opcode::Ifc => {
                    let m = next(i)?;
                    let cond = self.condition(x)?;
                    self.fb.open();
                    self.range(ins, matching, functions, i + 1, m)?;
                    let accept = self.fb.close();
                    self.fb.open();
                    let after = if ins[m].op == Opcode::Else {
                        let endif = next(m)?;
                        self.range(ins, matching, functions, m + 1, endif)?;
                        endif
                    } else {
                        m
                    };
                    let reject = self.fb.close();
                    self.fb.push(Statement::If {
                        condition: cond,
                        accept,
                        reject,
                    });
                    i = after + 1;
                    continue;
                }
                Opcode::Rep | Opcode::Loop => {
                    let m = next(i)?;
                    self.repeat(x, ins, matching, functions, i + 1, m)?;
                    i = m + 1;
                    continue;
                }
                Opcode::Break => self.fb.push(Statement::Break),
                Opcode::BreakC | Opcode::BreakP => {
                    let cond = self.condition(x)?;
                    self.fb.if_then(cond, |fb| fb.push(Statement::Break));
                }
                Opcode::Call | Opcode::CallNz => {
                    let label = x
                        .src
                        .first()
                        .ok_or(TranslateError::Internal("call without a label"))?
                        .reg
                        .index;
                    let function = *functions
                        .get(&label)
                        .ok_or(TranslateError::Internal("a call to a missing label"))?;
                    let call = Statement::Call {
                        function,
                        arguments: Vec::new(),
                        result: None,
                    };
                    if x.op == Opcode::Call {
                        self.fb.push(call);
                    } else {
                        let cond = self.condition(x)?;
                        self.fb.if_then(cond, |fb| fb.push(call));
                    }
                }
                Opcode::Ret => self.fb.push(Statement::Return { value: None }),
                Opcode::Label => {}
                Opcode::Else | Opcode::EndIf | Opcode::EndRep | Opcode::EndLoop => {
                    return Err(TranslateError::Internal("a block end outside its block"))
                }
                _ => unreachable!("plain instructions are lowered above"),
            }
            i += 1;
        }
        run.end(&mut self.fb);
        Ok(())
    }

    /// The boolean of `if`, `if_comp`, `break_comp`, `breakp`, `callnz`.
    fn condition(&mut self, x: &Instruction) -> Result<naga::Handle<Expression>, TranslateError> {
        if let Some(cmp) = x.compare {
            let (a, b) = (self.scalar_src(x, 0)?, self.scalar_src(x, 1)?);
            return Ok(self.compare(cmp, a, b));
        }
        let c: &Src = match x.op {
            Opcode::CallNz => x.src.get(1),
            _ => x.src.first(),
        }
        .ok_or(TranslateError::Internal("a condition without an operand"))?;
        let value = match c.reg.file {
            RegFile::ConstBool => match self.cx.bool_defs.get(&c.reg.index) {
                Some(&b) => self.fb.bool(b),
                None => {
                    let b = self.cx.block(&mut self.fb, 2);
                    let p = self.fb.index(b, c.reg.index);
                    let v = self.fb.load(p);
                    let x = self.comp(v, 0);
                    let zero = self.fb.u32(0);
                    self.fb.binary(B::NotEqual, x, zero)
                }
            },
            RegFile::Predicate => {
                let p = self.cx.var(&mut self.fb, self.cx.p0);
                let v = self.fb.load(p);
                self.comp(v, c.swizzle.0[0] as u32)
            }
            _ => {
                return Err(TranslateError::Unsupported(format!(
                    "condition on {}",
                    c.reg
                )))
            }
        };
        Ok(if c.modifier == SrcMod::Not {
            self.fb.not(value)
        } else {
            value
        })
    }

    /// Component `c` of `i#` (the shader's `defi`, else the constant block).
    fn int_const(&mut self, index: u32, c: u32) -> naga::Handle<Expression> {
        let v = match self.cx.int_defs.get(&index) {
            Some(&k) => self.fb.add(Expression::Constant(k)),
            None => {
                let block = self.cx.block(&mut self.fb, 1);
                let p = self.fb.index(block, index);
                self.fb.load(p)
            }
        };
        self.comp(v, c)
    }

    /// `rep i#` / `loop aL, i#` over the body `start..end`.
    fn repeat(
        &mut self,
        x: &Instruction,
        ins: &[Instruction],
        matching: &[Option<u32>],
        functions: &Functions,
        start: usize,
        end: usize,
    ) -> Result<(), TranslateError> {
        let int = x
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::ConstInt)
            .ok_or(TranslateError::Internal("rep/loop without i#"))?
            .reg
            .index;
        let is_loop = x.op == Opcode::Loop;
        let n = self.loops;
        self.loops += 1;
        let t = &self.cx.t;
        let (i32_ty,) = (t.i32,);
        let counter = self.fb.local(&format!("loop{n}_left"), i32_ty);
        let count = self.int_const(int, 0);
        self.fb.store(counter, count);
        let saved = if is_loop {
            let saved = self.fb.local(&format!("loop{n}_saved_aL"), i32_ty);
            let al = self.al();
            self.fb.store(saved, al);
            let start_al = self.int_const(int, 1);
            let p = self.cx.var(&mut self.fb, self.cx.al);
            self.fb.store(p, start_al);
            Some(saved)
        } else {
            None
        };

        self.fb.open();
        let left = self.fb.load(counter);
        let zero = self.fb.i32(0);
        let done = self.fb.binary(B::LessEqual, left, zero);
        self.fb.if_then(done, |fb| fb.push(Statement::Break));
        let left = self.fb.load(counter);
        let one = self.fb.i32(1);
        let fewer = self.fb.binary(B::Subtract, left, one);
        self.fb.store(counter, fewer);
        self.range(ins, matching, functions, start, end)?;
        let body = self.fb.close();

        self.fb.open();
        if is_loop {
            let step = self.int_const(int, 2);
            let al = self.al();
            let next = self.fb.binary(B::Add, al, step);
            let p = self.cx.var(&mut self.fb, self.cx.al);
            self.fb.store(p, next);
        }
        let continuing = self.fb.close();
        self.fb.push(Statement::Loop {
            body,
            continuing,
            break_if: None,
        });
        if let Some(saved) = saved {
            let v = self.fb.load(saved);
            let p = self.cx.var(&mut self.fb, self.cx.al);
            self.fb.store(p, v);
        }
        Ok(())
    }
}
