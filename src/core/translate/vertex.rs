//! Vertex shaders (vs_2_0, vs_2_x, vs_3_0) lowered to naga, so that the GPU
//! backend runs them with the same semantics as the emulator's vertex stage
//! (`core/emu/vertex`).
//!
//! The body is lowered by the same code as a pixel shader's (`lower.rs`,
//! `flow.rs`: registers as private globals, subroutines as functions) into
//! `ps_main`; what only vertex shaders have is here:
//!
//! * the address register `a0` (an `ivec4`) written by `mova`, rounded to
//!   the nearest integer with halves to even by naga's `round` (WGSL's
//!   `round`, SPIR-V's RoundEven), converted saturating, NaN to 0, as
//!   `emu::math::mova` states the rule;
//! * relative reads `c[a0.x + n]`, `c[aL + n]` (c0–c255 in the constant
//!   block) and `v[aL + n]` (v0–v15), zeros past the file, and the relative
//!   write `o[aL + n]`, dropped past o11 — the emulator's choices, both in
//!   `docs/vertex-shaders.md`;
//! * the output registers as one private array in the emulator's row order
//!   (o0–o11, oPos, oD0–oD1, oT0–oT7, oFog, oPts: `emu::vertex::output_row`),
//!   plus one row that catches the writes the emulator drops;
//! * the vs-only instructions: `mova`, `slt`, `sge`, `sgn`, `lit`, `dst`,
//!   `expp` and `logp` (full precision, as the emulator computes them).
//!
//! The entry point is a compute shader, `ps30_vertices`: one invocation per
//! vertex, inputs read from a storage buffer (16 `vec4`s per vertex, `v#` at
//! `16·vertex + #`) and all output rows written to another (25 per vertex),
//! so that the outputs come back unrounded and unrasterized. The lowered
//! body `ps_main` does not depend on that entry point: a vertex stage of a
//! render pipeline can wrap the same body, copying attributes in and
//! returning the rows it needs.

use super::builder::{Expr, Fb};
use super::lower::{Lower, Value};
use super::module::{self, Ctx};
use super::{Entry, Interface, Specialisation, TranslateError, Translation};
use crate::core::emu::vertex::output_row;
use crate::core::float_rules::FloatRules;
use crate::core::ir::{Dst, Instruction, Reg, RelIndex, Shader};
use crate::core::isa::{Opcode, RegFile};
use naga::{
    AddressSpace, ArraySize, BinaryOperator as B, Binding, BuiltIn, Expression, Handle,
    MathFunction as M, Module, Statement, StorageAccess, TypeInner,
};

pub use super::module::{VertexVars, VERTEX_FLOATS as FLOATS};

/// Byte offset of `i0` in a vertex shader's constant block.
pub const INTS_OFFSET: u32 = FLOATS * 16;
/// Byte offset of `b0` in a vertex shader's constant block.
pub const BOOLS_OFFSET: u32 = INTS_OFFSET + 16 * 16;
/// Byte offset of `s0`'s sampler record (after the booleans, as in the
/// pixel block).
pub const SAMPLERS_OFFSET: u32 = BOOLS_OFFSET + 16 * 16;
/// Bytes of a vertex shader's constant block (the sampler records
/// included).
pub const CONSTANTS_SIZE: u32 = SAMPLERS_OFFSET + 16 * super::interface::SAMPLER_STATE_SIZE;
/// Binding of the input storage buffer: 16 `vec4<f32>` per vertex.
pub const INPUTS_BINDING: u32 = 41;
/// Binding of the output storage buffer: [`ROWS`] `vec4<f32>` per vertex.
pub const OUTPUTS_BINDING: u32 = 42;
/// Input registers per vertex in the input buffer (v0–v15).
pub const INPUT_ROWS: u32 = 16;
/// Output rows per vertex in the output buffer (the emulator's rows).
pub const ROWS: u32 = super::module::VERTEX_ROWS;
/// Vertices per workgroup of `ps30_vertices`.
pub const WORKGROUP: u32 = 64;
/// The compute entry point's name.
pub const ENTRY: &str = "ps30_vertices";

/// Lowers a vertex shader into a module with the compute entry point
/// [`ENTRY`], validated. Every constant is read from the constant block at
/// run time (its `def`s as literals where read directly; the block holds
/// them too, for relative reads). vs_3_0's `texldl` samples `s0`–`s3` at
/// its explicit level, each sampler's state read from its record in the
/// block as a pixel shader's general translation reads it.
pub fn translate_vertex(shader: &Shader, rules: FloatRules) -> Result<Translation, TranslateError> {
    let profile = shader.program().profile;
    if !crate::core::emu::vertex::runs(profile) {
        return Err(TranslateError::Unsupported(format!(
            "a {profile} shader as a vertex shader: ps30 translates vs_2_0, vs_2_x and vs_3_0"
        )));
    }
    let spec = Specialisation::general();
    let mut module = naga::Module::default();
    let mut cx = Ctx::new(&mut module, shader, &spec)?;
    cx.border = super::texture::add_border_function(&mut module, shader, &cx.t, &spec);
    let functions = super::lower_functions(&mut module, &cx, shader, rules)?;
    let main = *functions
        .get(&super::MAIN)
        .ok_or(TranslateError::Internal("main was not lowered"))?;
    entry_point(&mut module, &cx, main)?;
    let info = super::validate(&module).map_err(TranslateError::Invalid)?;
    Ok(Translation {
        module,
        info,
        interface: Interface::of(shader),
        rules,
        entry: Entry::Draw,
        derivative_uniformity_off: false,
        notes: Vec::new(),
    })
}

/// `ps30_vertices`: vertex `global_invocation_id.x` (none past the input
/// buffer's end) copies its inputs into `v`, runs `ps_main` and writes
/// every output row.
fn entry_point(
    m: &mut Module,
    cx: &Ctx,
    main: Handle<naga::Function>,
) -> Result<(), TranslateError> {
    let vars = cx.vertex.as_ref().ok_or(TranslateError::Internal(
        "a vertex entry without vertex registers",
    ))?;
    let t = &cx.t;
    let runtime = module::ty(
        m,
        None,
        TypeInner::Array {
            base: t.vec4,
            size: ArraySize::Dynamic,
            stride: 16,
        },
    );
    let storage = |access| AddressSpace::Storage { access };
    let inputs = module::global(
        m,
        "ps30_vertex_in",
        storage(StorageAccess::LOAD),
        Some(INPUTS_BINDING),
        runtime,
    );
    let outputs = module::global(
        m,
        "ps30_vertex_out",
        storage(StorageAccess::LOAD | StorageAccess::STORE),
        Some(OUTPUTS_BINDING),
        runtime,
    );
    let uvec3 = module::ty(
        m,
        None,
        TypeInner::Vector {
            size: naga::VectorSize::Tri,
            scalar: naga::Scalar::U32,
        },
    );
    let mut fb = Fb::new(ENTRY);
    fb.f.arguments.push(naga::FunctionArgument {
        name: Some("id".into()),
        ty: uvec3,
        binding: Some(Binding::BuiltIn(BuiltIn::GlobalInvocationId)),
    });
    let id = fb.add(Expression::FunctionArgument(0));
    let vertex = fb.index(id, 0);
    let in_ptr = fb.add(Expression::GlobalVariable(inputs));
    let len = fb.add(Expression::ArrayLength(in_ptr));
    let per = fb.u32(INPUT_ROWS);
    let count = fb.binary(B::Divide, len, per);
    let past = fb.binary(B::GreaterEqual, vertex, count);
    fb.if_then(past, |fb| fb.push(Statement::Return { value: None }));
    let base = fb.binary(B::Multiply, vertex, per);
    for r in 0..INPUT_ROWS {
        let k = fb.u32(r);
        let at = fb.binary(B::Add, base, k);
        let buf = fb.add(Expression::GlobalVariable(inputs));
        let p = fb.add(Expression::Access {
            base: buf,
            index: at,
        });
        let value = fb.load(p);
        let v = cx.var(&mut fb, cx.inputs);
        let slot = fb.index(v, r);
        fb.store(slot, value);
    }
    fb.push(Statement::Call {
        function: main,
        arguments: Vec::new(),
        result: None,
    });
    let rows = fb.u32(ROWS);
    let base = fb.binary(B::Multiply, vertex, rows);
    for r in 0..ROWS {
        let o = cx.var(&mut fb, vars.o);
        let row = fb.index(o, r);
        let value = fb.load(row);
        let k = fb.u32(r);
        let at = fb.binary(B::Add, base, k);
        let buf = fb.add(Expression::GlobalVariable(outputs));
        let p = fb.add(Expression::Access {
            base: buf,
            index: at,
        });
        fb.store(p, value);
    }
    let function = fb.finish();
    m.entry_points.push(naga::EntryPoint {
        name: ENTRY.into(),
        stage: naga::ShaderStage::Compute,
        early_depth_test: None,
        workgroup_size: [WORKGROUP, 1, 1],
        workgroup_size_overrides: None,
        function,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
    Ok(())
}

impl Lower<'_> {
    fn vertex_vars(&self) -> Result<&VertexVars, TranslateError> {
        self.cx.vertex.as_ref().ok_or(TranslateError::Internal(
            "a vertex register in a pixel shader",
        ))
    }

    /// The index register's value: `aL` or a component of `a0`.
    fn index_register(&mut self, rel: RelIndex) -> Result<Expr, TranslateError> {
        Ok(match rel {
            RelIndex::Loop => self.al(),
            RelIndex::Addr(c) => {
                let a0 = self.vertex_vars()?.a0;
                let p = self.cx.var(&mut self.fb, a0);
                let v = self.fb.load(p);
                self.fb.index(v, u32::from(c & 3))
            }
        })
    }

    /// `reg.index` plus the index register, as an `i32`. The sum wraps
    /// where the emulator's (in i64) passes i32::MAX; the wrapped value is
    /// negative, so both read past the file.
    fn relative_index(&mut self, reg: Reg, rel: RelIndex) -> Result<Expr, TranslateError> {
        let r = self.index_register(rel)?;
        let n = self.fb.i32(reg.index as i32);
        Ok(self.fb.binary(B::Add, r, n))
    }

    /// `c[a0.x + n]`, `c[aL + n]`, `v[aL + n]`: the register, or zeros past
    /// the file (c0–c255, v0–v15), flushed under `hardware` as the
    /// emulator flushes constants and inputs where they enter.
    pub(super) fn vertex_relative(
        &mut self,
        reg: Reg,
        rel: RelIndex,
    ) -> Result<Expr, TranslateError> {
        let i = self.relative_index(reg, rel)?;
        let (base, last) = match reg.file {
            RegFile::Const => (self.cx.block(&mut self.fb, 0), FLOATS - 1),
            RegFile::Input => (self.cx.var(&mut self.fb, self.cx.inputs), INPUT_ROWS - 1),
            _ => {
                return Err(TranslateError::Unsupported(format!(
                    "relative addressing of {reg}"
                )))
            }
        };
        let (lo, hi) = (self.fb.i32(0), self.fb.i32(last as i32));
        let clamped = self.fb.math(M::Clamp, &[i, lo, hi]);
        let p = self.fb.add(Expression::Access {
            base,
            index: clamped,
        });
        let value = self.fb.load(p);
        let inside = self.fb.binary(B::Equal, i, clamped);
        let zero = self.zero4();
        let v = self.fb.select(inside, value, zero);
        Ok(if self.rules.flush_denormals() {
            self.flush(v, Some(naga::VectorSize::Quad))
        } else {
            v
        })
    }

    /// A pointer to the output row `d` writes: `o[aL + n]` past o11, and
    /// registers the emulator has no row for, write the spare row.
    pub(super) fn vertex_output(&mut self, d: &Dst) -> Result<Expr, TranslateError> {
        let o = self.vertex_vars()?.o;
        let spare = ROWS;
        let row = match d.relative {
            None => {
                let row = output_row(d.reg.file, d.reg.index).map_or(spare, |r| r as u32);
                let base = self.cx.var(&mut self.fb, o);
                return Ok(self.fb.index(base, row));
            }
            Some(rel) if d.reg.file == RegFile::Output => {
                let i = self.relative_index(d.reg, rel)?;
                let (lo, hi) = (self.fb.i32(0), self.fb.i32(11));
                let clamped = self.fb.math(M::Clamp, &[i, lo, hi]);
                let inside = self.fb.binary(B::Equal, i, clamped);
                let spare = self.fb.i32(spare as i32);
                self.fb.select(inside, clamped, spare)
            }
            Some(_) => {
                return Err(TranslateError::Unsupported(format!(
                    "a relative write to {}",
                    d.reg
                )))
            }
        };
        let base = self.cx.var(&mut self.fb, o);
        Ok(self.fb.add(Expression::Access { base, index: row }))
    }

    /// `mova a0.mask, x` after `_sat` and the flush: each component as
    /// `emu::math::mova` computes it; predication as for any write.
    pub(super) fn write_address(
        &mut self,
        ins: &Instruction,
        value: Value,
        mask: u8,
    ) -> Result<(), TranslateError> {
        let a0 = self.vertex_vars()?.a0;
        for c in 0..4u32 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let x = self.component(value, c);
            let mut v = self.round_to_int(x);
            if let Some(p) = self.predicate(ins, c as usize) {
                let ptr = self.cx.var(&mut self.fb, a0);
                let target = self.fb.index(ptr, c);
                let old = self.fb.load(target);
                v = self.fb.select(p, v, old);
            }
            let ptr = self.cx.var(&mut self.fb, a0);
            let target = self.fb.index(ptr, c);
            self.fb.store(target, v);
        }
        Ok(())
    }

    /// `emu::math::mova(x)` in naga: rounded to nearest, halves to even
    /// (naga's `Round` is WGSL's `round` and SPIR-V's RoundEven), then
    /// converted as Rust's `as i32` converts.
    fn round_to_int(&mut self, x: Expr) -> Expr {
        let r = self.fb.math(M::Round, &[x]);
        // i32's range: −2^31 is a float, 2147483520 the largest below 2^31.
        let (lo, hi) = (self.fb.f32(-2_147_483_648.0), self.fb.f32(2_147_483_520.0));
        let clamped = self.fb.math(M::Clamp, &[r, lo, hi]);
        let i = self.fb.add(Expression::As {
            expr: clamped,
            kind: naga::ScalarKind::Sint,
            convert: Some(4),
        });
        let top = self.fb.f32(2_147_483_648.0);
        let big = self.fb.binary(B::GreaterEqual, r, top);
        let max = self.fb.i32(i32::MAX);
        let i = self.fb.select(big, max, i);
        let nan = self.fb.binary(B::NotEqual, r, r);
        let zero = self.fb.i32(0);
        self.fb.select(nan, zero, i)
    }

    /// The instructions only vertex shaders have, as `emu/vertex/exec.rs`
    /// computes them.
    pub(super) fn vertex_instruction(
        &mut self,
        ins: &Instruction,
        op: Opcode,
    ) -> Result<(), TranslateError> {
        match op {
            Opcode::Mova => {
                let a = self.src(ins, 0)?;
                self.write(ins, a, 0b1111)
            }
            Opcode::Slt | Opcode::Sge => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let test = if op == Opcode::Slt {
                    B::Less
                } else {
                    B::GreaterEqual
                };
                let holds = self.fb.binary(test, a, b);
                let (one, zero) = (self.fb.f32(1.0), self.fb.f32(0.0));
                let (one, zero) = (self.splat4(one), self.splat4(zero));
                let v = self.fb.select(holds, one, zero);
                self.write(ins, v, 0b1111)
            }
            Opcode::Sgn => {
                // −1, 0 or 1; NaN gives 0 (neither test holds).
                let a = self.src(ins, 0)?;
                let zero = self.zero4();
                let (one, minus) = (self.fb.f32(1.0), self.fb.f32(-1.0));
                let (one, minus) = (self.splat4(one), self.splat4(minus));
                let below = self.fb.binary(B::Less, a, zero);
                let above = self.fb.binary(B::Greater, a, zero);
                let v = self.fb.select(above, one, zero);
                let v = self.fb.select(below, minus, v);
                self.write(ins, v, 0b1111)
            }
            Opcode::Expp => {
                let x = self.scalar_src(ins, 0)?;
                let v = self.fb.math(M::Exp2, &[x]);
                self.write_scalar(ins, v)
            }
            Opcode::Logp => {
                let x = self.scalar_src(ins, 0)?;
                let v = if self.rules.d3d9_specials() {
                    self.log(x)
                } else {
                    self.fb.math(M::Log2, &[x])
                };
                self.write_scalar(ins, v)
            }
            Opcode::Lit => {
                let a = self.src(ins, 0)?;
                let v = self.lit(a);
                self.write(ins, v, 0b1111)
            }
            Opcode::Dst => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let (ay, by) = (self.comp(a, 1), self.comp(b, 1));
                let y = self.mul(ay, by, None);
                let one = self.fb.f32(1.0);
                let parts = [one, y, self.comp(a, 2), self.comp(b, 3)];
                let v = self.compose4(parts);
                self.write(ins, v, 0b1111)
            }
            _ => Err(TranslateError::Unsupported(format!(
                "`{op}` in a vertex shader"
            ))),
        }
    }

    /// `lit` (MS `lit---vs`): (1, x if x > 0, y^w if x > 0 and y > 0, 1),
    /// the power w clamped to ±127.9961; y^0 and 1^w are 1, as `powf`
    /// gives them (the base is positive here, so no other pin applies).
    fn lit(&mut self, s: Expr) -> Expr {
        let (x, y, w) = (self.comp(s, 0), self.comp(s, 1), self.comp(s, 3));
        let (lo, hi) = (self.fb.f32(-127.9961), self.fb.f32(127.9961));
        let power = self.fb.math(M::Clamp, &[w, lo, hi]);
        let (zero, one) = (self.fb.f32(0.0), self.fb.f32(1.0));
        let x_pos = self.fb.binary(B::Greater, x, zero);
        let y_pos = self.fb.binary(B::Greater, y, zero);
        let both = self.fb.binary(B::LogicalAnd, x_pos, y_pos);
        let p = self.fb.math(M::Pow, &[y, power]);
        let p_zero = self.fb.binary(B::Equal, power, zero);
        let y_one = self.fb.binary(B::Equal, y, one);
        let unit = self.fb.binary(B::LogicalOr, p_zero, y_one);
        let p = self.fb.select(unit, one, p);
        let out_y = self.fb.select(x_pos, x, zero);
        let out_z = self.fb.select(both, p, zero);
        self.compose4([one, out_y, out_z, one])
    }
}
