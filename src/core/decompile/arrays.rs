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
//! A vertex shader's relative read based past its 256 constants
//! (`c[a0.x + 2047]`, a limit probe's) reads an array based there, up to
//! c8191, the last register the compiler binds: the compiler writes the
//! same relative read back (`c2047[a0.x]`), or, where it knows the index,
//! the register it names (`c2048`), and the emulator reads (0, 0, 0, 0)
//! past c255 for both.

use super::names::{identifier, FloatName, Names, Uses};
use super::DecompileError;
use crate::core::bytecode::ctab::{Constant, RegisterSet};
use crate::core::ir::Program;
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
            if program.float_def(first).is_some() {
                return Err(DecompileError::Unsupported(format!(
                    "c[a0 + {first}] starts at c{first}, which the shader defines (def): \
                     HLSL writes a def as a literal, so no uniform array holds it; a read that \
                     chooses between the literals and the array is not written yet"
                )));
            }
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
            let end = (first + 1..limit).find(|&r| owned(r)).unwrap_or(limit);
            if first >= limit {
                return Err(DecompileError::Unsupported(format!(
                    "c[a0 + {first}] reads past c{end_all}, where the compiler's literals go"
                )));
            }
            let name = identifier(if first == 0 { "c" } else { "cr" }, taken);
            let len = end - first;
            self.decls
                .push(format!("float4 {name}[{len}] : register(c{first});"));
            for r in first..end {
                self.floats.insert(
                    r,
                    FloatName::Vector {
                        base: format!("{name}[{}]", r - first),
                        width: 4,
                    },
                );
            }
            self.arrays.push((first, len, name));
            while k < bases.len() && bases[k] < end {
                k += 1;
            }
        }
        Ok(())
    }
}
