//! Constant arrays the constant table does not give: a relative read
//! (`c[a0.x + n]`, `c[aL + n]`) at a register no array of the table covers
//! — a shader without a table, an assembly shader — reads an array that
//! starts at its lowest such `n`. Where it ends is not in the bytecode (the
//! index is known only when the shader runs); the array reaches up to the
//! first register something else owns: a `def` (written as literals, which
//! the compiler then places after the array), a constant of the table, or
//! 32 registers before the end of the file (c224 in vertex shaders,
//! c192 in ps_3_0), which leaves the compiler room for its own literals. Direct reads of registers inside it are its elements, so that no
//! two declarations bind one register.
//!
//! A relative read based at a `def` reads the literal where the index names
//! the `def`, the uniform elsewhere: the array starts there and reaches past
//! the run of `def`s, and a function of the HLSL, `c_at(i)`, chooses by the
//! index — `[branch] if (i == k) return literal;` per `def`, which the
//! compiler writes as `if` and exact `mov`s; in vs_2_0, which has no branch
//! (X3528), `v = v * (1 - s) + literal * s` with `s = i == k ? 1 : 0` under
//! `precise`, exact but for the sign of a zero (`-0 * 1 + 0` is `+0`) and
//! infinite constants. `i == 0 ? literal : c[i]` is not exact: the
//! compiler writes it `c + s·(literal − c)` (measured).
//!
//! A vertex shader's relative read based past its 256 constants
//! (`c[a0.x + 2047]`, a limit probe's) reads an array based there, up to
//! c8191, the last register the compiler binds: the compiler writes the
//! same relative read back (`c2047[a0.x]`), or, where it knows the index,
//! the register it names (`c2048`), and the emulator reads (0, 0, 0, 0)
//! past c255 for both.

use super::expr::vector_literal;
use super::names::{identifier, FloatName, Names, Uses};
use super::DecompileError;
use crate::core::bytecode::ctab::{Constant, RegisterSet};
use crate::core::ir::Program;
use crate::core::profile::Profile;
use std::collections::BTreeSet;

/// Where an array the table does not give ends at the latest: 32
/// registers before the end of the vertex shaders' 256 and ps_3_0's 224.
fn end_of(program: &Program) -> u32 {
    match program.profile.stage() {
        crate::core::profile::Stage::Vertex => 224,
        crate::core::profile::Stage::Pixel => 192,
    }
}

/// A vertex shader's float constants: reads past them are (0, 0, 0, 0) in
/// the emulator.
const VERTEX_CONSTANTS: u32 = 256;

/// The constant registers Microsoft's compiler binds (c0–c8191; c8192 is
/// X4509, "target has 8192 slots", measured for vs_2_0 and vs_3_0).
const REGISTERS: u32 = 8192;

impl Names {
    /// Declares the arrays of the relative reads in `uses` at registers
    /// outside `named` (the table's constants).
    pub(super) fn unnamed_arrays(
        &mut self,
        program: &Program,
        consts: &[&Constant],
        uses: &Uses,
        named: &BTreeSet<u32>,
        taken: &mut BTreeSet<String>,
    ) -> Result<(), DecompileError> {
        let bases: Vec<u32> = uses
            .relative
            .iter()
            .copied()
            .filter(|r| !named.contains(r))
            .collect();
        let end_all = end_of(program);
        let vertex = program.profile.stage() == crate::core::profile::Stage::Vertex;
        let mut k = 0;
        while k < bases.len() {
            let first = bases[k];
            let owned = |r: u32| {
                program.float_def(r).is_some()
                    || consts.iter().any(|c| {
                        c.set == RegisterSet::Float4
                            && r >= c.index as u32
                            && r < c.index as u32 + c.count as u32
                    })
            };
            // past a vertex shader's 256 constants the compiler's literals
            // are not in the way: the array reaches up to the first owned
            // register or the compiler's last (c8191)
            let past = vertex && first >= VERTEX_CONSTANTS;
            let limit = if past { REGISTERS } else { end_all };
            if first >= limit {
                return Err(DecompileError::Unsupported(format!(
                    "c[a0 + {first}] reads past c{end_all}, where the compiler's literals go"
                )));
            }
            // a read based at a `def` reaches the run of defs there, whose
            // literals a function chooses by the index, then the uniforms
            // (past c255 the emulator drops a def: it reads 0, as the array)
            let defs: Vec<[f32; 4]> = (first..limit)
                .map_while(|r| program.float_def(r).filter(|_| !past))
                .collect();
            let uniforms = first + defs.len() as u32;
            let end = (uniforms.max(first + 1)..limit)
                .find(|&r| owned(r))
                .unwrap_or(limit);
            let name = identifier(if first == 0 { "c" } else { "cr" }, taken);
            let len = end - first;
            self.decls
                .push(format!("float4 {name}[{len}] : register(c{first});"));
            for r in uniforms..end {
                self.floats.insert(
                    r,
                    FloatName::Vector {
                        base: format!("{name}[{}]", r - first),
                        width: 4,
                    },
                );
            }
            if !defs.is_empty() {
                self.reader(program, &name, &defs, taken);
            }
            self.arrays.push((first, len, name));
            while k < bases.len() && bases[k] < end {
                k += 1;
            }
        }
        Ok(())
    }

    /// The function that reads array `name` (based at a `def`, whose
    /// literals `defs` are its first elements) as the shader does: the
    /// literal where the index names a def, the uniform elsewhere.
    fn reader(
        &mut self,
        program: &Program,
        name: &str,
        defs: &[[f32; 4]],
        taken: &mut BTreeSet<String>,
    ) {
        let f = identifier(&format!("{name}_at"), taken);
        let last = defs.len() - 1;
        let which = if last == 0 {
            format!("{name}[0] is the shader's literal (def)")
        } else {
            format!("{name}[0]–{name}[{last}] are the shader's literals (def)")
        };
        let mut text = format!(
            "\n// {name}[i] as the shader reads it: {which}, the others the application's\n\
             float4 {f}(float i)\n{{\n"
        );
        if program.profile == Profile::Vs2_0 {
            // no branch in vs_2_0: the choice is arithmetic (module text)
            text.push_str(&format!("    precise float4 v = {name}[i];\n"));
            for (k, v) in defs.iter().enumerate() {
                text.push_str(&format!(
                    "    float s{k} = i == {k} ? 1 : 0;\n    \
                     v = v * (1 - s{k}) + {} * s{k};\n",
                    vector_literal(v)
                ));
            }
            text.push_str("    return v;\n}\n");
        } else {
            for (k, v) in defs.iter().enumerate() {
                text.push_str(&format!(
                    "    [branch] if (i == {k})\n        return {};\n",
                    vector_literal(v)
                ));
            }
            text.push_str(&format!("    return {name}[i];\n}}\n"));
        }
        self.readers.insert(name.to_string(), f);
        self.functions.push_str(&text);
    }
}
