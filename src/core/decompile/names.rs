//! How each register a shader reads is spelled in HLSL: `def` values as
//! literals, uniforms by their constant-table name and type where every
//! read fits that type (arrays, row- and column-major matrices), `c#`,
//! `i#`, `b#` and `s#` bound by `: register(…)` where the table says
//! nothing, and the uniform declarations that go with those spellings.

use super::DecompileError;
use crate::core::bytecode::ctab::{Class, Constant, ConstantTable, RegisterSet};
use crate::core::ir::Program;
use crate::core::isa::SamplerType;
use std::collections::{BTreeMap, BTreeSet};

/// How one float constant register is spelled.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FloatName {
    /// A `def`: its value, written as literals.
    Literal([f32; 4]),
    /// A vector (or a row of a row-major matrix) of `width` components.
    Vector { base: String, width: u8 },
    /// Column `column` of a column-major matrix with `rows` rows: component
    /// `j` is `base._m{j}{column}`.
    Column { base: String, column: u8, rows: u8 },
}

/// The names of a shader's registers and the uniforms they need.
#[derive(Debug, Default)]
pub(crate) struct Names {
    /// Float constant registers.
    pub floats: BTreeMap<u32, FloatName>,
    /// Float arrays reachable by `c[aL + n]`: first register, length, name.
    pub arrays: Vec<(u32, u32, String)>,
    /// Integer registers: a literal `int4(…)` or a uniform's name.
    pub ints: BTreeMap<u32, String>,
    /// Boolean registers: `true`, `false` or a uniform's name.
    pub bools: BTreeMap<u32, String>,
    /// Samplers: name.
    pub samplers: BTreeMap<u32, String>,
    /// Uniform declarations, one line each, in register order.
    pub decls: Vec<String>,
    /// Arrays based at a `def` → the function that reads them
    /// (`arrays.rs`).
    pub readers: BTreeMap<String, String>,
    /// Those functions' text.
    pub functions: String,
}

/// What the shader reads of the constant files (from [`super::expr::reads`]).
#[derive(Debug, Default)]
pub(crate) struct Uses {
    /// Float register → components read (bits), direct reads.
    pub floats: BTreeMap<u32, u8>,
    /// First registers of `c[aL + n]` reads.
    pub relative: BTreeSet<u32>,
    /// Integer registers read.
    pub ints: BTreeSet<u32>,
    /// Boolean registers read.
    pub bools: BTreeSet<u32>,
    /// Samplers read.
    pub samplers: BTreeSet<u32>,
}

/// HLSL's reserved words and the names the decompiler itself uses, which
/// a uniform's name must not take.
const RESERVED: &[&str] = &[
    "main",
    "float",
    "float2",
    "float3",
    "float4",
    "int",
    "int4",
    "bool",
    "bool4",
    "half",
    "double",
    "static",
    "const",
    "uniform",
    "sampler",
    "sampler2D",
    "samplerCUBE",
    "sampler3D",
    "texture",
    "register",
    "return",
    "if",
    "else",
    "for",
    "while",
    "do",
    "break",
    "continue",
    "discard",
    "true",
    "false",
    "in",
    "out",
    "inout",
    "struct",
    "matrix",
    "vector",
    "void",
    "string",
    "row_major",
    "column_major",
    "p0",
    "vpos",
    "vface",
    "oDepth",
    "sampler1D",
    "shared",
    "extern",
    "volatile",
    "pass",
    "technique",
    "compile",
    "asm",
    "decl",
    "a0",
    "oPos",
    "oFog",
    "oPts",
    "result",
    "VS_OUTPUT",
];

/// A valid HLSL identifier made from a constant table's name, different
/// from every name in `taken` (which it joins).
pub(crate) fn identifier(raw: &str, taken: &mut BTreeSet<String>) -> String {
    let mut s: String = raw
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert(0, '_');
    }
    let clash = |s: &str, taken: &BTreeSet<String>| {
        taken.contains(s) || RESERVED.contains(&s) || is_register_name(s)
    };
    while clash(&s, taken) {
        s.push('_');
    }
    taken.insert(s.clone());
    s
}

/// Whether `s` spells a register or loop counter the decompiler names
/// itself (`r3`, `c10`, `oC0`, `label2`, `n1`).
fn is_register_name(s: &str) -> bool {
    let digits = s.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    let prefix = &s[..s.len() - digits.len()];
    !digits.is_empty()
        && digits.chars().all(|c| c.is_ascii_digit())
        && [
            "r", "c", "i", "b", "s", "oC", "label", "n", "v", "o", "oD", "oT",
        ]
        .contains(&prefix)
}

/// The HLSL spelling of an f32 that reads back as the same bits.
pub(crate) fn literal(v: f32) -> String {
    if v.is_finite() {
        let s = format!("{v:?}");
        if s.contains('e') && !s.contains('.') {
            // `1e-40` is a float literal in HLSL too, but keep a point for clarity
            let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
            return format!("{m}.0e{e}");
        }
        s
    } else {
        format!("asfloat(0x{:08x})", v.to_bits())
    }
}

impl Names {
    /// Names every register `uses` says the program reads.
    pub(crate) fn new(
        program: &Program,
        table: Option<&ConstantTable>,
        uses: &Uses,
        taken: &mut BTreeSet<String>,
    ) -> Result<Names, DecompileError> {
        let mut names = Names::default();
        let consts: Vec<&Constant> = table
            .map(|t| t.constants.iter().collect())
            .unwrap_or_default();
        names.name_floats(program, &consts, uses, taken)?;
        names.name_ints(program, &consts, uses, taken);
        names.name_bools(program, &consts, uses, taken);
        names.name_samplers(program, &consts, uses, taken);
        Ok(names)
    }

    /// The uniform declarations, one a line, then the functions that read
    /// the arrays based at a `def` (`arrays.rs`).
    pub(crate) fn preamble(&self) -> String {
        let mut text: String = self.decls.iter().map(|d| format!("{d}\n")).collect();
        text.push_str(&self.functions);
        text
    }

    fn name_floats(
        &mut self,
        program: &Program,
        consts: &[&Constant],
        uses: &Uses,
        taken: &mut BTreeSet<String>,
    ) -> Result<(), DecompileError> {
        for (&reg, _) in uses.floats.iter() {
            if let Some(v) = program.float_def(reg) {
                self.floats.insert(reg, FloatName::Literal(v));
            }
        }
        let mut named: BTreeSet<u32> = BTreeSet::new();
        for c in consts.iter().filter(|c| c.set == RegisterSet::Float4) {
            let (first, end) = (c.index as u32, c.index as u32 + c.count as u32);
            let read = |r: u32| uses.floats.contains_key(&r) && program.float_def(r).is_none();
            let relative = uses.relative.iter().any(|&r| r >= first && r < end);
            if !(first..end).any(read) && !relative {
                continue;
            }
            let name = identifier(&c.name, taken);
            let typed = !relative && self.typed(c, &name, uses, consts);
            if !typed {
                self.plain_float(c, &name);
            }
            if relative {
                self.arrays.push((first, c.count as u32, name.clone()));
            }
            named.extend(first..end);
        }
        // relative reads outside the table's arrays (`arrays.rs`)
        self.unnamed_arrays(program, consts, uses, &named, taken)?;
        for (&reg, _) in uses.floats.iter() {
            if !self.floats.contains_key(&reg) {
                let name = format!("c{reg}");
                taken.insert(name.clone());
                self.decls
                    .push(format!("float4 {name} : register(c{reg});"));
                self.floats.insert(
                    reg,
                    FloatName::Vector {
                        base: name,
                        width: 4,
                    },
                );
            }
        }
        Ok(())
    }

    /// A constant declared as `float4 name[count]` (or `float4 name`): every
    /// register one vector.
    fn plain_float(&mut self, c: &Constant, name: &str) {
        let note = if c.ty.class == Class::Vector && c.ty.columns == 4 && c.ty.rows == 1 {
            String::new()
        } else {
            format!(" // the table's type: {}{}", c.ty.hlsl(), c.ty.array())
        };
        let array = if c.count > 1 {
            format!("[{}]", c.count)
        } else {
            String::new()
        };
        self.decls.push(format!(
            "float4 {name}{array} : register(c{});{note}",
            c.index
        ));
        for k in 0..c.count as u32 {
            let base = if c.count > 1 {
                format!("{name}[{k}]")
            } else {
                name.to_string()
            };
            self.floats
                .entry(c.index as u32 + k)
                .or_insert(FloatName::Vector { base, width: 4 });
        }
    }

    /// Declares `c` with its own type when every read of its registers
    /// fits that type and the registers the type takes are its own.
    fn typed(&mut self, c: &Constant, name: &str, uses: &Uses, consts: &[&Constant]) -> bool {
        let t = &c.ty;
        if t.base != "float"
            || !matches!(
                t.class,
                Class::Scalar | Class::Vector | Class::MatrixRows | Class::MatrixColumns
            )
        {
            return false;
        }
        let (per, width) = match t.class {
            Class::MatrixColumns => (t.columns as u32, t.rows as u32),
            Class::MatrixRows => (t.rows as u32, t.columns as u32),
            _ => (1, t.columns as u32),
        };
        let elements = (t.elements as u32).max(1);
        let size = per * elements;
        let first = c.index as u32;
        if size < c.count as u32 || width == 0 || width > 4 || per == 0 || per > 4 {
            return false;
        }
        // the registers past the table's count must be nobody else's
        let theirs = |r: u32| {
            consts.iter().any(|o| {
                !std::ptr::eq(*o, c)
                    && o.set == RegisterSet::Float4
                    && r >= o.index as u32
                    && r < o.index as u32 + o.count as u32
            }) || (r >= first + c.count as u32 && uses.floats.contains_key(&r))
        };
        if (first + c.count as u32..first + size).any(theirs) {
            return false;
        }
        let mut spellings = Vec::new();
        for k in 0..c.count as u32 {
            let reg = first + k;
            let read = uses.floats.get(&reg).copied().unwrap_or(0);
            if read >> width != 0 {
                return false;
            }
            let (e, row) = (k / per, k % per);
            let element = if t.elements > 1 {
                format!("{name}[{e}]")
            } else {
                name.to_string()
            };
            let spelling = match t.class {
                Class::MatrixColumns => FloatName::Column {
                    base: element,
                    column: row as u8,
                    rows: width as u8,
                },
                Class::MatrixRows => FloatName::Vector {
                    base: format!("{element}[{row}]"),
                    width: width as u8,
                },
                _ => FloatName::Vector {
                    base: element,
                    width: width as u8,
                },
            };
            spellings.push((reg, spelling));
        }
        for (reg, s) in spellings {
            self.floats.entry(reg).or_insert(s);
        }
        self.decls.push(format!(
            "{} {name}{} : register(c{first});",
            t.hlsl(),
            t.array()
        ));
        true
    }

    fn name_ints(
        &mut self,
        program: &Program,
        consts: &[&Constant],
        uses: &Uses,
        taken: &mut BTreeSet<String>,
    ) {
        for &reg in &uses.ints {
            if let Some(v) = program.int_def(reg) {
                self.ints
                    .insert(reg, format!("int4({}, {}, {}, {})", v[0], v[1], v[2], v[3]));
                continue;
            }
            let name = table_name(consts, RegisterSet::Int4, reg)
                .map(|n| identifier(n, taken))
                .unwrap_or_else(|| {
                    taken.insert(format!("i{reg}"));
                    format!("i{reg}")
                });
            self.decls.push(format!("int4 {name} : register(i{reg});"));
            self.ints.insert(reg, name);
        }
    }

    fn name_bools(
        &mut self,
        program: &Program,
        consts: &[&Constant],
        uses: &Uses,
        taken: &mut BTreeSet<String>,
    ) {
        for &reg in &uses.bools {
            if let Some(v) = program.bool_def(reg) {
                self.bools.insert(reg, v.to_string());
                continue;
            }
            let name = table_name(consts, RegisterSet::Bool, reg)
                .map(|n| identifier(n, taken))
                .unwrap_or_else(|| {
                    taken.insert(format!("b{reg}"));
                    format!("b{reg}")
                });
            self.decls.push(format!("bool {name} : register(b{reg});"));
            self.bools.insert(reg, name);
        }
    }

    fn name_samplers(
        &mut self,
        program: &Program,
        consts: &[&Constant],
        uses: &Uses,
        taken: &mut BTreeSet<String>,
    ) {
        for &reg in &uses.samplers {
            let ty = match program.sampler_type(reg) {
                Some(SamplerType::Cube) => "samplerCUBE",
                Some(SamplerType::Volume) => "sampler3D",
                _ => "sampler2D",
            };
            let name = table_name(consts, RegisterSet::Sampler, reg)
                .map(|n| identifier(n, taken))
                .unwrap_or_else(|| {
                    taken.insert(format!("s{reg}"));
                    format!("s{reg}")
                });
            self.decls.push(format!("{ty} {name} : register(s{reg});"));
            self.samplers.insert(reg, name);
        }
    }
}

/// The name the table gives the one-register constant at `reg` of `set`
/// (integer, boolean and sampler constants take their first register).
fn table_name<'a>(consts: &[&'a Constant], set: RegisterSet, reg: u32) -> Option<&'a str> {
    consts
        .iter()
        .find(|c| c.set == set && c.index as u32 == reg && c.count == 1)
        .map(|c| c.name.as_str())
}
