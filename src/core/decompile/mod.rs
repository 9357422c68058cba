//! Decompilation: a validated shader back to HLSL that Microsoft's
//! compiler accepts for the same profile and that computes the same
//! pixels.
//!
//! The HLSL keeps the shader's registers as variables (`r0`…, `oC0`…,
//! `p0`) and writes one statement per instruction that writes a value,
//! with the write mask and the source swizzles folded into the narrowest
//! expression; `def` constants become literals, the constant table names
//! and types the uniforms, and flow control becomes `if`/`else` and `for`.
//! Only forms that compile back to the same operation are used: where an
//! idiom is not exactly the instruction (`normalize` of a four-component
//! `nrm`), the plain arithmetic is written. What cannot be written exactly
//! is refused with [`DecompileError`], never approximated.
//!
//! The profile is a [`Target`]: ps_3_0 is the one the loader reads today;
//! another profile is another row there (its output semantics and
//! input spellings), with the same expressions.

mod arrays;
mod emit;
mod expr;
mod fold;
mod matrix;
mod names;
mod profiles;
mod ps1;
mod reduce;
mod repeat;
mod vertex;

use crate::core::bytecode::ctab::ConstantTable;
use crate::core::ir::{Instruction, RelIndex, Shader};
use crate::core::isa::{Opcode, RegFile};
use emit::Body;
use names::{Names, Uses};
pub use profiles::semantic as input_semantic;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
pub use vertex::{Halves, HALVES};

/// A profile the decompiler writes HLSL for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Target {
    /// The profile's name as `D3DCompile` takes it (`ps_3_0`).
    pub profile: &'static str,
}

/// ps_3_0, the profile of every [`Shader`] today.
pub const PS_3_0: Target = Target { profile: "ps_3_0" };

/// Why a shader was not decompiled.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub enum DecompileError {
    /// Something the HLSL cannot express exactly (yet).
    Unsupported(String),
    /// The same, at an instruction (0-based) with its mnemonic.
    At {
        /// Index of the instruction among the executable ones.
        instruction: usize,
        /// Its mnemonic.
        op: String,
        /// What could not be written.
        message: String,
    },
}

impl DecompileError {
    fn at(self, instruction: usize, op: Opcode) -> DecompileError {
        match self {
            DecompileError::Unsupported(message) => DecompileError::At {
                instruction,
                op: op.info().mnemonic.to_string(),
                message,
            },
            e => e,
        }
    }
}

impl fmt::Display for DecompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DecompileError::Unsupported(m) => write!(f, "cannot decompile: {m}"),
            DecompileError::At {
                instruction,
                op,
                message,
            } => write!(
                f,
                "cannot decompile instruction {} ({op}): {message}",
                instruction + 1
            ),
        }
    }
}

impl std::error::Error for DecompileError {}

/// A decompiled shader.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Decompiled {
    /// The profile it was written for.
    pub target: Target,
    /// The HLSL source; its entry point is `main`.
    pub hlsl: String,
    /// Executable instructions read.
    pub instructions: usize,
    /// Statements written (assignments, calls, `clip`, `break`, `return`).
    pub statements: usize,
    /// Uniforms declared from the constant table by name.
    pub named_uniforms: usize,
}

/// What the program reads and writes, gathered before anything is named.
#[derive(Default)]
struct Scan {
    uses: Uses,
    temps: BTreeSet<u32>,
    colors: BTreeSet<u32>,
    depth: bool,
    predicate: bool,
    /// `mova` writes `a0` (vertex shaders).
    address: bool,
}

fn scan(shader: &Shader, instructions: &[Instruction]) -> Scan {
    let mut s = Scan::default();
    let program = shader.program();
    for ins in instructions {
        let sampler = ins
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::Sampler)
            .and_then(|s| program.sampler_type(s.reg.index));
        for (k, src) in ins.src.iter().enumerate() {
            let mut note = |reg: u32, positions: &[usize]| {
                let bits = positions
                    .iter()
                    .fold(0u8, |b, &p| b | 1 << src.swizzle.0[p]);
                *s.uses.floats.entry(reg).or_default() |= bits;
            };
            // `a0` read before (or without) any `mova`: the variable, 0
            s.address |= matches!(src.relative, Some(RelIndex::Addr(_)));
            match src.reg.file {
                RegFile::Const if src.relative.is_some() => {
                    s.uses.relative.insert(src.reg.index);
                }
                RegFile::Const => {
                    let positions = expr::lanes(ins, k, sampler);
                    note(src.reg.index, &positions);
                    if k == 1 {
                        for row in 1..expr::matrix_rows(ins.op).unwrap_or(1) {
                            note(src.reg.index + row, &positions);
                        }
                    }
                }
                RegFile::ConstInt => {
                    s.uses.ints.insert(src.reg.index);
                }
                RegFile::ConstBool => {
                    s.uses.bools.insert(src.reg.index);
                }
                RegFile::Sampler => {
                    s.uses.samplers.insert(src.reg.index);
                }
                RegFile::Temp => {
                    s.temps.insert(src.reg.index);
                }
                RegFile::Predicate => s.predicate = true,
                _ => {}
            }
        }
        if let Some(d) = ins.dst {
            match d.reg.file {
                RegFile::Temp => {
                    s.temps.insert(d.reg.index);
                }
                RegFile::ColorOut => {
                    s.colors.insert(d.reg.index);
                }
                RegFile::DepthOut => s.depth = true,
                RegFile::Predicate => s.predicate = true,
                RegFile::Address => s.address = true,
                _ => {}
            }
        }
        if ins.predicate.is_some() {
            s.predicate = true;
        }
    }
    s
}

/// One input parameter: its declaration and the name the body reads.
struct Param {
    decl: String,
    name: String,
}

/// An input array: inputs read as `v[aL + n]` are the run of declarations
/// around `v#n` with one usage, consecutive usage indices and consecutive
/// registers, declared as one array parameter (`float4 texcoord[4] :
/// TEXCOORD0`) that the loop counter indexes.
pub(crate) struct InputArray {
    /// Its first register.
    pub first: u32,
    /// How many registers it spans.
    pub len: u32,
    /// The parameter's name.
    pub name: String,
}

/// Registers `v#` that instructions read relatively (`v[aL + n]`: `n`).
fn relative_inputs(shader: &Shader) -> BTreeSet<u32> {
    shader
        .instructions()
        .iter()
        .flat_map(|i| i.src.iter())
        .filter(|s| s.reg.file == RegFile::Input && s.relative.is_some())
        .map(|s| s.reg.index)
        .collect()
}

/// The runs of input declarations that relative reads need as arrays.
fn input_runs(shader: &Shader) -> Vec<(u32, u32)> {
    let bases = relative_inputs(shader);
    let mut decls: Vec<&crate::core::ir::InputDecl> = shader
        .program()
        .inputs
        .iter()
        .filter(|d| d.reg.file == RegFile::Input)
        .collect();
    decls.sort_by_key(|d| d.reg.index);
    let mut runs: Vec<(u32, u32)> = Vec::new();
    let mut k = 0;
    while k < decls.len() {
        let mut end = k + 1;
        while end < decls.len() {
            let (p, q) = (decls[end - 1], decls[end]);
            let follows = q.reg.index == p.reg.index + 1
                && q.usage == p.usage
                && q.usage_index == p.usage_index + 1
                && q.centroid == p.centroid;
            if !follows {
                break;
            }
            end += 1;
        }
        let (first, len) = (decls[k].reg.index, (end - k) as u32);
        if bases.iter().any(|&b| b >= first && b < first + len) {
            runs.push((first, len));
        }
        k = end;
    }
    runs
}

/// Whether a subroutine (`subroutines`: the instructions after `main`'s
/// `ret`) reads `aL` outside a `loop` of its own, so from its caller's.
fn reads_caller_counter(subroutines: &[Instruction]) -> bool {
    let mut depth = 0usize;
    subroutines.iter().any(|x| {
        match x.op {
            Opcode::Label => depth = 0,
            Opcode::Loop => depth += 1,
            Opcode::EndLoop => depth = depth.saturating_sub(1),
            _ => {}
        }
        let relative = x.src.iter().map(|s| s.relative);
        let mut relative = relative.chain(x.dst.as_ref().map(|d| d.relative));
        depth == 0 && relative.any(|r| r == Some(RelIndex::Loop))
    })
}

/// The parameters of `main` for the shader's input declarations, the
/// register → name maps expressions read (`v#`; ps_2_0's `t#`), and the
/// input arrays.
type Inputs = (
    Vec<Param>,
    BTreeMap<u32, String>,
    BTreeMap<u32, String>,
    Vec<InputArray>,
);

/// [`Inputs`] of `shader`.
fn inputs(shader: &Shader, taken: &mut BTreeSet<String>) -> Result<Inputs, DecompileError> {
    let mut params = Vec::new();
    let mut map = BTreeMap::new();
    let mut texcoords = BTreeMap::new();
    let runs = input_runs(shader);
    let mut arrays = Vec::new();
    // vs_3_0's output declarations are the output struct's (`vertex.rs`)
    for d in shader
        .program()
        .inputs
        .iter()
        .filter(|d| d.reg.file != RegFile::Output)
    {
        let run = runs.iter().find(|(f, n)| {
            d.reg.file == RegFile::Input && d.reg.index >= *f && d.reg.index < f + n
        });
        if let Some(&(first, len)) = run {
            if d.reg.index != first {
                continue;
            }
            let usage = d.usage.to_ascii_lowercase();
            let name = names::identifier(&usage, taken);
            let centroid = if d.centroid { "_centroid" } else { "" };
            for k in 0..len {
                map.insert(first + k, format!("{name}[{k}]"));
            }
            params.push(Param {
                decl: format!(
                    "float4 {name}[{len}] : {}{}{centroid}",
                    usage.to_ascii_uppercase(),
                    d.usage_index
                ),
                name: name.clone(),
            });
            arrays.push(InputArray { first, len, name });
            continue;
        }
        let (ty, name, semantic) = match d.reg.file {
            RegFile::Position => ("float2", "vpos".to_string(), "VPOS".to_string()),
            RegFile::Face => ("float", "vface".to_string(), "VFACE".to_string()),
            _ => {
                let (usage, usage_index) = profiles::semantic(d);
                let usage = usage.to_ascii_lowercase();
                let name = names::identifier(&format!("{usage}{usage_index}"), taken);
                let centroid = if d.centroid { "_centroid" } else { "" };
                (
                    "float4",
                    name,
                    format!("{}{usage_index}{centroid}", usage.to_ascii_uppercase()),
                )
            }
        };
        if d.reg.file == RegFile::Texture {
            texcoords.insert(d.reg.index, name.clone());
        }
        if d.reg.file == RegFile::Input && map.insert(d.reg.index, name.clone()).is_some() {
            return Err(DecompileError::Unsupported(format!(
                "v{} is declared twice (packed inputs)",
                d.reg.index
            )));
        }
        params.push(Param {
            decl: format!("{ty} {name} : {semantic}"),
            name,
        });
    }
    Ok((params, map, texcoords, arrays))
}

/// How many of the constant table's uniforms are declared by name.
fn named_uniforms(table: Option<&ConstantTable>, names: &Names) -> usize {
    table.map_or(0, |t| {
        t.constants
            .iter()
            .filter(|c| {
                names
                    .decls
                    .iter()
                    .any(|d| d.contains(&format!(" {}", c.name)))
            })
            .count()
    })
}

/// Decompiles `shader` (ps_1_1–ps_1_4, ps_2_0, ps_2_x, ps_3_0, vs_2_0,
/// vs_2_x or vs_3_0) with the names of its constant table; a ps_1_x
/// shader as the program ps30 runs for it (`ps1.rs`).
pub fn decompile(
    shader: &Shader,
    table: Option<&ConstantTable>,
) -> Result<Decompiled, DecompileError> {
    if shader.program().profile.is_ps1() {
        let (lowered, plan) = ps1::plan(shader)?;
        return write(lowered, table, Some(&plan));
    }
    write(shader, table, None)
}

/// The HLSL of `shader`; `ps1`: how a ps_1_x shader's lowering is written.
fn write(
    shader: &Shader,
    table: Option<&ConstantTable>,
    ps1: Option<&ps1::Plan>,
) -> Result<Decompiled, DecompileError> {
    // sin and cos read as the calls the compiler lowered (`reduce.rs`)
    let ins = reduce::read_back(shader);
    let mut s = scan(shader, &ins);
    // the compiler takes colour outputs only from COLOR0 on (X4538): the
    // ones below the highest written are written too, as zeros
    if let Some(&last) = s.colors.last() {
        s.colors.extend(0..last);
    }
    let mut taken: BTreeSet<String> = BTreeSet::from([vertex::ROUND.to_string()]);
    let target = match ps1 {
        Some(p) => p.target,
        None => profiles::target(shader.program().profile)?,
    };
    let vertex = shader.program().profile.stage() == crate::core::profile::Stage::Vertex;
    let fields = if vertex {
        vertex::fields(shader)?
    } else {
        Vec::new()
    };
    let (params, input_map, texcoords, input_arrays) = inputs(shader, &mut taken)?;
    let saturated = match ps1 {
        Some(_) => ps1::saturated_inputs(&input_map),
        None => Vec::new(),
    };
    let names = Names::new(shader.program(), table, &s.uses, &mut taken)?;
    // runs of dot products over a whole matrix read as `mul` (`matrix.rs`)
    let ins = matrix::group(ins, &names);
    let named_uniforms = named_uniforms(table, &names);
    let info = shader.info();
    let n = shader.instructions().len();
    let main_end = (info.main_end as usize).min(n);
    let mut ctx = expr::Ctx {
        names: &names,
        inputs: input_map,
        texcoords,
        input_arrays,
        counters: Vec::new(),
        from_zero: Vec::new(),
        caller_counter: reads_caller_counter(&shader.instructions()[main_end..]),
        pending: Default::default(),
        clamps: ps1.is_some(),
    };
    let labels: Vec<(u32, usize)> = info.labels.iter().map(|(&l, &i)| (l, i as usize)).collect();
    let subroutines = !labels.is_empty();
    let mut text = String::new();
    match ps1 {
        Some(p) => text.push_str(&p.header),
        None => text.push_str(&profiles::header(shader.program().profile, target)),
    }
    text.push_str(&names.preamble());
    if vertex {
        text.push_str(&vertex::rounding(shader));
        text.push_str(&vertex::declaration(&fields));
    }
    // a ps_1_x shader's `lrp` is written as arithmetic (`expr.rs`)
    let precise = match ps1.is_none() && imprecise(shader) {
        true => "",
        false => "precise ",
    };
    let locals = locals(&s, &fields, precise);
    let mut statements = 0;
    if subroutines {
        statements +=
            subroutine_functions(&mut ctx, shader, &ins, &labels, &locals, &params, &mut text)?;
    }
    let single = !vertex && s.colors.iter().copied().eq([0]) && !s.depth;
    let sig = signature(&params, &s, single, subroutines, precise);
    let mut body = Body::new(1);
    if subroutines {
        for p in &params {
            body.line(format!("{0} = in_{0};", p.name));
        }
    } else {
        for l in &locals {
            if single || !l.contains("oC") && !l.contains("oDepth") {
                body.line(l.clone());
            }
        }
    }
    if !single {
        for &c in &s.colors {
            if !subroutines {
                body.line(format!("oC{c} = 0;"));
            }
        }
        if s.depth && !subroutines {
            body.line("oDepth = 0;");
        }
    }
    saturated.into_iter().for_each(|l| body.line(l));
    let head = body.lines.len();
    emit::statements(&mut ctx, shader, &ins, 0..main_end, true, &mut body)?;
    statements += body.lines.len() - head;
    if ps1.is_some() {
        ps1::prune_temporaries(&mut body.lines);
    }
    if vertex {
        vertex::epilogue(&fields)
            .into_iter()
            .for_each(|l| body.line(l));
    } else if single {
        body.line("return oC0;");
    } else if subroutines {
        for &c in &s.colors {
            body.line(format!("out_oC{c} = oC{c};"));
        }
        if s.depth {
            body.line("out_oDepth = oDepth;");
        }
    }
    let ret = match (vertex, single) {
        (true, _) => vertex::STRUCT,
        (_, true) => "float4",
        _ => "void",
    };
    let semantic = if single { " : COLOR" } else { "" };
    text.push_str(&format!("\n{ret} main({}){semantic}\n{{\n", sig.join(", ")));
    for line in body.lines {
        text.push_str(&line);
        text.push('\n');
    }
    text.push_str("}\n");
    Ok(Decompiled {
        target,
        hlsl: text,
        instructions: n,
        statements,
        named_uniforms,
    })
}

/// The subroutines' declarations and functions (registers and inputs as
/// `static` globals, prototypes, one `labelN()` per `label`), appended to
/// `text`; the statements they hold.
fn subroutine_functions(
    ctx: &mut expr::Ctx,
    shader: &Shader,
    ins: &[Instruction],
    labels: &[(u32, usize)],
    locals: &[String],
    params: &[Param],
    text: &mut String,
) -> Result<usize, DecompileError> {
    let n = shader.instructions().len();
    let mut statements = 0;
    text.push('\n');
    for l in locals {
        text.push_str(&format!("static {l}\n"));
    }
    for p in params {
        text.push_str(&format!(
            "static {};\n",
            p.decl.split(" : ").next().unwrap_or(&p.decl)
        ));
    }
    if ctx.caller_counter {
        text.push_str(&format!("static int {};\n", expr::CALLER_COUNTER));
    }
    for (l, _) in labels {
        text.push_str(&format!("void label{l}();\n"));
    }
    for (k, &(l, start)) in labels.iter().enumerate() {
        let end = labels.get(k + 1).map_or(n, |&(_, e)| e);
        let mut body = Body::new(1);
        emit::statements(
            ctx,
            shader,
            ins,
            start + 1..end.max(start + 1),
            false,
            &mut body,
        )?;
        statements += body.lines.len();
        text.push_str(&format!("\nvoid label{l}()\n{{\n"));
        for line in body.lines {
            text.push_str(&line);
            text.push('\n');
        }
        text.push_str("}\n");
    }
    Ok(statements)
}

/// Whether the variables go without `precise`. `precise` makes the
/// compiler keep the arithmetic as written (no regrouped sums or
/// products), but not where `lerp` is, which it then expands; and in
/// vs_2_0 a shader with a `precise` variable and a loop over an `int`
/// uniform is refused (X4509: the compiler wants the int bound to a `c`
/// register too, measured).
fn imprecise(shader: &Shader) -> bool {
    let p = shader.program();
    let uniform_loop = |x: &Instruction| {
        x.op == Opcode::Loop
            && x.src
                .iter()
                .any(|s| s.reg.file == RegFile::ConstInt && p.int_def(s.reg.index).is_none())
    };
    shader.instructions().iter().any(|x| x.op == Opcode::Lrp)
        || p.profile == crate::core::profile::Profile::Vs2_0
            && shader.instructions().iter().any(uniform_loop)
}

/// The parameters of `main`: the inputs (`in_` copies where subroutines
/// share them as globals) and, unless `oC0` alone is returned, an `out`
/// parameter per output (`precise` as the locals are).
fn signature(
    params: &[Param],
    s: &Scan,
    single: bool,
    subroutines: bool,
    precise: &str,
) -> Vec<String> {
    let mut sig: Vec<String> = params
        .iter()
        .map(|p| {
            if subroutines {
                p.decl
                    .replacen(&format!(" {}", p.name), &format!(" in_{}", p.name), 1)
            } else {
                p.decl.clone()
            }
        })
        .collect();
    if !single {
        let out = if subroutines { "out_" } else { "" };
        for &c in &s.colors {
            sig.push(format!("out {precise}float4 {out}oC{c} : COLOR{c}"));
        }
        if s.depth {
            sig.push(format!("out {precise}float {out}oDepth : DEPTH"));
        }
    }
    sig
}

/// The declarations of the registers the body writes, each starting at 0
/// (what the emulator, and Direct3D's reference rasteriser, give a register
/// before its first write), `precise` (`"precise "`) or not (`""`).
fn locals(s: &Scan, fields: &[vertex::Field], precise: &str) -> Vec<String> {
    let mut out = vertex::locals(fields, s.address, precise);
    for &c in &s.colors {
        out.push(format!("{precise}float4 oC{c} = 0;"));
    }
    if s.depth {
        out.push(format!("{precise}float oDepth = 0;"));
    }
    if !s.temps.is_empty() {
        let list: Vec<String> = s.temps.iter().map(|t| format!("r{t} = 0")).collect();
        out.push(format!("{precise}float4 {};", list.join(", ")));
    }
    if s.predicate {
        out.push("bool4 p0 = false;".into());
    }
    out
}
