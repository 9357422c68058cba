//! Validation: expanded statements → [`Shader`] (program + [`Info`]), or
//! every error found.
//!
//! Each distinct source statement is lowered once ([`lower`]); REPEAT_BLOCK
//! copies reuse the result with their own [`Origin`](crate::core::ir::Origin). The program-level pass
//! then checks what needs context: the version line, declarations before
//! instructions and before use, block balance and nesting limits, `aL` only
//! inside `loop` (and every input `v[aL + n]` reads declared), read ports,
//! subroutine structure, outputs outside dynamic flow control; reads of
//! temporaries no earlier code writes ([`init`]); then, as warnings,
//! gradients under dynamic flow control ([`gradient`]). Rules are the
//! ps_3_0 rules of Microsoft's documentation; where sources disagree, the
//! choice is written next to the check.

pub mod caps;
pub mod gradient;
pub mod init;
pub mod limits;
pub mod lower;
pub mod nesting;
pub mod register;

use crate::core::diag::{codes, Diagnostic, Diagnostics, SourceFile};
use crate::core::front::ast::Stmt;
use crate::core::front::repeat::Expanded;
use crate::core::ir::{Info, Instruction, Program, Reg, RelIndex, Shader, Span, Src, SrcMod};
use crate::core::isa::{self, Class, Opcode, RegFile};
use crate::core::profile::{Profile, Stage};
use lower::Lowered;
use std::collections::{BTreeMap, BTreeSet};

/// Validates an expanded statement list.
pub fn validate(
    stmts: &[Stmt],
    expanded: &[Expanded],
    file: &SourceFile,
) -> Result<(Shader, Diagnostics), Diagnostics> {
    let mut diags = Diagnostics::default();
    let (body, profile) = check_version(stmts, expanded, &mut diags);
    let program = collect(stmts, body, file, profile, &mut diags);
    check_declarations(&program, &mut diags, file);
    let info = check_program(&program, &mut diags, file);
    // What the checks above cannot see: blocks inside subroutines on top of
    // those around their calls, break_comp and callnz p0 as dynamic levels,
    // and vs_2_0's depths of one.
    let nested = diags
        .items
        .iter()
        .any(|d| d.code.is_some_and(nesting::is_depth_code));
    if !nested && !diags.has_errors() {
        if let Some(d) = nesting::check(&program, nesting::Limits::of(program.profile), file) {
            diags.push(d);
        }
    }
    limits::check(&program, &info, &mut diags, file);
    if matches!(program.profile, Profile::Ps2_0 | Profile::Ps2X) {
        caps::swizzles(&program, program.profile == Profile::Ps2X, &mut diags);
    }
    nesting::own_codes(program.profile, &mut diags);
    // An instruction refused above is missing from the program, so the
    // registers it writes would read as never written: no cascade of
    // warnings about them until the errors are fixed.
    if !diags.has_errors() {
        init::check(&program, &info, &mut diags, file);
    }
    if diags.has_errors() {
        return Err(diags);
    }
    for w in gradient::warnings(&program, &info, file) {
        diags.push(w);
    }
    let warnings = diags;
    Ok((Shader::new_validated(program, info), warnings))
}

/// The profile a version statement names, when ps30 checks that profile
/// ([`Profile::checked`]); `None` for any other statement or profile.
pub fn checked_profile(stmt: &Stmt) -> Option<Profile> {
    match stmt {
        Stmt::Version { text, .. } => Profile::from_version_line(text).filter(|p| p.checked()),
        _ => None,
    }
}

/// The version line must come first; returns the statements after it (all
/// of them when it is missing) and the profile it names (ps_3_0 when it is
/// missing or refused, so the rest is judged by ps_3_0's rules).
fn check_version<'e>(
    stmts: &[Stmt],
    expanded: &'e [Expanded],
    diags: &mut Diagnostics,
) -> (&'e [Expanded], Profile) {
    let first = expanded.first().map(|e| &stmts[e.stmt]);
    if let Some(p) = first.and_then(checked_profile) {
        return (&expanded[1..], p);
    }
    let body = match first {
        Some(Stmt::Version { text, span, .. }) => {
            diags.push(version_refusal(text, *span));
            &expanded[1..]
        }
        Some(_) | None => {
            let span = expanded.first().map(|e| e.origin.span).unwrap_or_default();
            diags.push(
                Diagnostic::coded(
                    codes::VERSION,
                    Span::new(span.start as usize, span.start as usize),
                    "missing version line",
                )
                .with_label("expected `ps_3_0` here")
                .with_help("start the file with the line `ps_3_0`"),
            );
            expanded
        }
    };
    (body, Profile::Ps3_0)
}

/// The refusal of a version line `text` naming a profile ps30 does not
/// check (or no profile at all), with what ps30 knows of it: the one message
/// the loader and the validator give.
pub fn version_refusal(text: &str, span: Span) -> Diagnostic {
    let profile = Profile::from_version_line(text);
    let message = format!(
        "this is a {text} shader; ps30 reads ps_2_0, ps_2_x, ps_3_0, vs_2_0, vs_2_x, vs_3_0 and ps_1_1–ps_1_4"
    );
    let help = match profile {
        Some(p) if !p.assembles() => format!(
            "`{p}` is the name of an HLSL compile target, not a version line (Microsoft's assembler refuses it too, X2001); its shaders carry the {} version",
            Profile::from_token(p.version_token()).map_or("?", Profile::name)
        ),
        Some(p) => format!(
            "ps30 recognises {p} (docs/profiles.md) but does not check, count or assemble {p} shaders yet"
        ),
        None => "no Direct3D 9 profile has this version; the first line of a ps_3_0 shader is `ps_3_0`".to_string(),
    };
    Diagnostic::coded(codes::VERSION, span, message)
        .with_label("not a profile ps30 reads")
        .with_help(help)
}

/// Lowers each distinct statement once and files the results into a
/// [`Program`], each with its own origin; declarations after the first
/// instruction are errors.
fn collect(
    stmts: &[Stmt],
    body: &[Expanded],
    file: &SourceFile,
    profile: Profile,
    diags: &mut Diagnostics,
) -> Program {
    let mut program = Program {
        profile,
        ..Program::default()
    };
    // Each statement's lowering, kept while copies of it (REPEAT_BLOCK)
    // remain: the last copy takes it instead of cloning it.
    let mut copies_left = vec![0usize; stmts.len()];
    for e in body {
        copies_left[e.stmt] += 1;
    }
    let mut lowerings: Vec<Option<Option<Lowered>>> = stmts.iter().map(|_| None).collect();
    let mut first_instr: Option<Span> = None;
    for e in body {
        let lowered = match &stmts[e.stmt] {
            Stmt::Instr(ast) => {
                let slot = &mut lowerings[e.stmt];
                let lowered = slot.get_or_insert_with(|| match lower::lower(ast, profile) {
                    Ok(l) => Some(l),
                    Err(d) => {
                        diags.push(d.in_origin(&e.origin, file));
                        None
                    }
                });
                copies_left[e.stmt] -= 1;
                if copies_left[e.stmt] == 0 {
                    slot.take().flatten()
                } else {
                    lowered.clone()
                }
            }
            Stmt::Version { span, .. } => {
                diags.push(
                    Diagnostic::coded(
                        codes::SYNTAX,
                        *span,
                        "the version line may appear only once, first",
                    )
                    .with_label("remove this line"),
                );
                None
            }
            Stmt::RepeatBegin { .. } | Stmt::RepeatEnd { .. } | Stmt::Comment { .. } => None,
        };
        let Some(lowered) = lowered else { continue };
        let is_decl = !matches!(lowered, Lowered::Instr(_));
        if is_decl {
            if let Some(first) = first_instr {
                let (what, code) = match lowered {
                    Lowered::Input(_) | Lowered::Sampler(_) => {
                        ("declarations", codes::DCL_TOO_LATE)
                    }
                    _ => ("constant definitions", codes::DEF_TOO_LATE),
                };
                diags.push(
                    Diagnostic::coded(
                        code,
                        e.origin.span,
                        format!("{what} must come before the first instruction"),
                    )
                    .with_label("too late")
                    .with_secondary(first, "first instruction")
                    .with_help("move it up, after the version line"),
                );
                continue;
            }
        }
        if let Lowered::Instr(_) = lowered {
            first_instr.get_or_insert(e.origin.span);
        }
        file_lowered(&mut program, lowered, e);
    }
    program
}

/// Adds one lowered statement to its list in `program`, with the origin of
/// this copy.
fn file_lowered(program: &mut Program, lowered: Lowered, e: &Expanded) {
    match lowered {
        Lowered::Instr(mut i) => {
            i.origin = e.origin.clone();
            program.instructions.push(i);
        }
        Lowered::Input(mut d) => {
            d.origin = e.origin.clone();
            program.inputs.push(d);
        }
        Lowered::Sampler(mut d) => {
            d.origin = e.origin.clone();
            program.samplers.push(d);
        }
        Lowered::Float(mut d) => {
            d.origin = e.origin.clone();
            program.float_defs.push(d);
        }
        Lowered::Int(mut d) => {
            d.origin = e.origin.clone();
            program.int_defs.push(d);
        }
        Lowered::Bool(mut d) => {
            d.origin = e.origin.clone();
            program.bool_defs.push(d);
        }
    }
}

/// Definitions: each register defined once, and every `defi` a valid loop
/// constant — Microsoft's validator checks the four values where they are
/// defined, whether a `rep` or `loop` uses them or not.
fn check_definitions(p: &Program, diags: &mut Diagnostics) {
    let spans = p
        .float_defs
        .iter()
        .map(|d| (RegFile::Const, d.index, d.origin.span))
        .chain(
            p.int_defs
                .iter()
                .map(|d| (RegFile::ConstInt, d.index, d.origin.span)),
        )
        .chain(
            p.bool_defs
                .iter()
                .map(|d| (RegFile::ConstBool, d.index, d.origin.span)),
        );
    let mut seen: BTreeMap<(RegFile, u32), Span> = BTreeMap::new();
    for (f, index, span) in spans {
        let Some(&first) = seen.get(&(f, index)) else {
            seen.insert((f, index), span);
            continue;
        };
        let code = match f {
            RegFile::Const => codes::DEF_TWICE,
            RegFile::ConstInt => codes::DEFI_TWICE,
            _ => codes::DEFB_TWICE,
        };
        diags.push(
            Diagnostic::coded(
                code,
                span,
                format!("{}{index} is defined twice", f.info().name),
            )
            .with_secondary(first, "first defined here")
            .with_help("define each constant once"),
        );
    }
    for d in &p.int_defs {
        let [x, y, z, w] = d.value;
        let max = isa::MAX_REP_COUNT;
        let problem = if x < 0 {
            Some((
                codes::COUNT_NEGATIVE,
                format!("the iteration count (.x = {x}) must be in 0..={max}"),
            ))
        } else if x > max {
            Some((
                codes::COUNT_TOO_LARGE,
                format!("the iteration count (.x = {x}) must be in 0..={max}"),
            ))
        } else if !(0..=255).contains(&y) {
            Some((
                codes::LOOP_START,
                format!("the loop start (.y = {y}) must be in 0..=255"),
            ))
        } else if !(-128..=127).contains(&z) {
            Some((
                codes::LOOP_STEP,
                format!("the loop step (.z = {z}) must be in -128..=127"),
            ))
        } else if w != 0 {
            Some((codes::LOOP_W, format!("the unused .w (= {w}) must be 0")))
        } else {
            None
        };
        if let Some((code, msg)) = problem {
            diags.push(
                Diagnostic::coded(code, d.origin.span, format!("i{} = {:?}: {msg}", d.index, d.value))
                    .with_label("out of range")
                    .with_note("an integer constant is a loop's count, start and step, checked where it is defined"),
            );
        }
    }
}

/// Duplicate or conflicting declarations.
fn check_declarations(p: &Program, diags: &mut Diagnostics, file: &SourceFile) {
    check_definitions(p, diags);
    let mut usages: BTreeMap<(&str, u32), Span> = BTreeMap::new();
    // ps_2_0 and ps_2_x declare v# without a usage: no two of them clash.
    for d in p
        .inputs
        .iter()
        .filter(|d| d.reg.file == RegFile::Input && !d.usage.is_empty())
    {
        let key = (d.usage.as_str(), d.usage_index);
        match usages.get(&key) {
            Some(&first) if first != d.origin.span => diags.push(
                Diagnostic::coded(
                    codes::DCL_USAGE_TWICE,
                    d.origin.span,
                    format!("{}{} is declared for two inputs", d.usage, d.usage_index),
                )
                .with_secondary(first, "first declared here")
                .with_help("each usage and index names one input"),
            ),
            _ => {
                usages.insert(key, d.origin.span);
            }
        }
    }
    let mut samplers: BTreeMap<u32, Span> = BTreeMap::new();
    for d in &p.samplers {
        if let Some(prev) = samplers.insert(d.index, d.origin.span) {
            if prev != d.origin.span {
                diags.push(
                    Diagnostic::coded(
                        codes::SAMPLER_TWICE,
                        d.origin.span,
                        format!("sampler s{} is declared twice", d.index),
                    )
                    .with_secondary(prev, "first declared here")
                    .in_origin(&d.origin, file),
                );
            }
        }
    }
    let mut inputs: BTreeMap<(RegFile, u32), (u8, Span)> = BTreeMap::new();
    for d in &p.inputs {
        let key = (d.reg.file, d.reg.index);
        let entry = inputs.entry(key).or_insert((0, d.origin.span));
        if entry.0 & d.mask.0 != 0 && entry.1 != d.origin.span {
            diags.push(
                Diagnostic::coded(
                    if d.reg.file == RegFile::Input {
                        codes::DCL_OVERLAP
                    } else {
                        codes::VPOS_TWICE
                    },
                    d.origin.span,
                    format!("components of {} are declared twice", d.reg),
                )
                .with_secondary(entry.1, "first declared here")
                .with_help("a register may be declared several times only with disjoint masks"),
            );
        }
        entry.0 |= d.mask.0;
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Block {
    Rep,
    Loop,
    IfStatic,
    IfDynamic,
}

struct Open {
    block: Block,
    index: usize,
    span: Span,
    seen_else: bool,
}

/// Structure, context rules and slot costs.
fn check_program(p: &Program, diags: &mut Diagnostics, file: &SourceFile) -> Info {
    let mut c = Checker::new(p, diags, file);
    for (idx, ins) in p.instructions.iter().enumerate() {
        c.owner[idx] = c.current;
        c.info.slots[idx] = p.slots_of(ins);
        c.check_declared(ins);
        c.check_components_declared(ins);
        c.check_read_ports(ins);
        c.check_relative(idx, ins);
        c.check_output(ins);
        c.check_reachable(ins);
        c.structure(idx, ins);
    }
    c.finish()
}

/// The program-level pass's state as it walks the instructions in order:
/// the open blocks, where main ends, the calls and which subroutine each
/// instruction belongs to.
struct Checker<'p, 'd> {
    p: &'p Program,
    diags: &'d mut Diagnostics,
    file: &'p SourceFile,
    info: Info,
    declared_inputs: BTreeSet<(RegFile, u32)>,
    stack: Vec<Open>,
    in_main: bool,
    calls: Vec<(usize, u32)>,
    /// The rep/loop depth at each call of `calls`.
    call_loops: Vec<u32>,
    /// The deepest rep/loop nesting inside each routine (None: main).
    own_loops: BTreeMap<Option<u32>, u32>,
    /// A block closed by the wrong instruction: Microsoft's validator stops
    /// there, so blocks left open by it are not reported as well.
    mismatched: bool,
    /// Instructions of subroutines that read through aL: allowed when
    /// every call to the subroutine runs inside a loop.
    sub_relative: Vec<usize>,
    /// Which subroutine (label number, or None for main) each index belongs to.
    owner: Vec<Option<u32>>,
    current: Option<u32>,
    /// The first constant read with `_abs`, and the first without.
    abs_consts: (Option<Span>, Option<Span>),
}

impl<'p, 'd> Checker<'p, 'd> {
    fn new(p: &'p Program, diags: &'d mut Diagnostics, file: &'p SourceFile) -> Self {
        let n = p.instructions.len();
        Checker {
            p,
            diags,
            file,
            info: Info {
                matching: vec![None; n],
                main_end: n as u32,
                slots: vec![Default::default(); n],
                ..Info::default()
            },
            declared_inputs: p.inputs.iter().map(|d| (d.reg.file, d.reg.index)).collect(),
            stack: Vec::new(),
            in_main: true,
            calls: Vec::new(),
            call_loops: Vec::new(),
            own_loops: BTreeMap::new(),
            mismatched: false,
            sub_relative: Vec::new(),
            owner: vec![None; n],
            current: None,
            abs_consts: (None, None),
        }
    }

    /// Reports `d` at instruction `ins` (with its REPEAT_BLOCK chain).
    fn err(&mut self, ins: &Instruction, d: Diagnostic) {
        self.diags.push(d.in_origin(&ins.origin, self.file));
    }

    /// Declarations before use; vFace only compared; which kind of constant
    /// read (`_abs` or not) came first.
    fn check_declared(&mut self, ins: &Instruction) {
        let span = ins.origin.span;
        for s in &ins.src {
            match s.reg.file {
                RegFile::Sampler if self.p.sampler_type(s.reg.index).is_none() => self.err(
                    ins,
                    Diagnostic::coded(
                        codes::UNDECLARED_SAMPLER,
                        span,
                        format!("sampler s{} is used but never declared", s.reg.index),
                    )
                    .with_label("undeclared sampler")
                    .with_help(format!(
                        "add `dcl_2d s{}` after the version line",
                        s.reg.index
                    )),
                ),
                RegFile::Input | RegFile::Position | RegFile::Face
                    if s.relative.is_none()
                        && !self.declared_inputs.contains(&(s.reg.file, s.reg.index)) =>
                {
                    let code = match s.reg.file {
                        RegFile::Position => codes::UNDECLARED_VPOS,
                        RegFile::Face => codes::UNDECLARED_VFACE,
                        _ => codes::UNDECLARED_INPUT,
                    };
                    self.err(
                        ins,
                        Diagnostic::coded(
                            code,
                            span,
                            format!("input {} is used but never declared", s.reg),
                        )
                        .with_label("undeclared input")
                        .with_help(match s.reg.file {
                            RegFile::Input => format!(
                                "add e.g. `dcl_texcoord{0} v{0}` after the version line",
                                s.reg.index
                            ),
                            _ => format!("add `dcl {}` after the version line", s.reg),
                        }),
                    )
                }
                _ => {}
            }
            // vFace is read only as the operand of setp_comp, if_comp and
            // break_comp (Microsoft's ps_3_0 register page) or as cmp's
            // condition, which Microsoft's validator allows too (and Wine's
            // dlls/d3d9/tests/visual.c, vface_register_test, draws `cmp r0,
            // vFace, c0, r1` on Windows drivers); anything else it refuses.
            let cmp_condition = ins.op == Opcode::Cmp && std::ptr::eq(s, &ins.src[0]);
            if s.reg.file == RegFile::Face
                && !cmp_condition
                && !matches!(ins.op, Opcode::Setp | Opcode::Ifc | Opcode::BreakC)
            {
                self.err(
                    ins,
                    Diagnostic::coded(
                        codes::VFACE_USE,
                        span,
                        "vFace is read only by setp_comp, if_comp, break_comp or as cmp's condition",
                    )
                    .with_label("vFace used as a value")
                    .with_help("select with it instead: cmp r0, vFace, c_front, c_back (only its sign is defined: negative is a back face)"),
                );
            }
            if s.reg.file == RegFile::Const {
                let abs = matches!(s.modifier, SrcMod::Abs | SrcMod::NegAbs);
                if abs {
                    self.abs_consts.0.get_or_insert(span);
                } else {
                    self.abs_consts.1.get_or_insert(span);
                }
            }
        }
        if ins.op == Opcode::TexKill {
            if let Some(d) = &ins.dst {
                if d.reg.file == RegFile::Input
                    && !self.declared_inputs.contains(&(d.reg.file, d.reg.index))
                {
                    self.err(
                        ins,
                        Diagnostic::coded(
                            codes::UNDECLARED_INPUT,
                            span,
                            format!("input {} is used but never declared", d.reg),
                        ),
                    );
                }
            }
        }
    }

    /// The components an instruction reads of v# and vPos must be declared
    /// (an undeclared register is [`Checker::check_declared`]'s): `dcl_texcoord0
    /// v0.xy` then `mov r0, v0` reads z and w, which nothing declares.
    fn check_components_declared(&mut self, ins: &Instruction) {
        for file in [RegFile::Input, RegFile::Position] {
            for (index, mut need) in init::reads_of(self.p, ins, file) {
                if ins.op == Opcode::Nrm {
                    // Microsoft's validator counts nrm as reading .xyz
                    // (Wine's test_nrm_instruction: dcl_texcoord0 v1.xyz,
                    // nrm r0, v1).
                    need &= 0b0111;
                }
                let declared = self
                    .p
                    .inputs
                    .iter()
                    .filter(|d| d.reg.file == file && d.reg.index == index)
                    .fold(0u8, |m, d| m | d.mask.0);
                let missing = need & !declared;
                // A register named as an operand and never declared is
                // reported by check_declared; the other rows a matrix
                // instruction reads (m3x3 r0.xyz, r1, v0 reads v0 … v2)
                // are reported here.
                let named = ins.src.iter().any(|s| s.reg == Reg { file, index })
                    || ins.dst.is_some_and(|d| d.reg == Reg { file, index });
                if missing == 0 || (declared == 0 && named) {
                    continue;
                }
                let name = Reg { file, index };
                let code = match file {
                    RegFile::Position if missing & 0b1100 != 0 => codes::VPOS_ZW,
                    RegFile::Position => codes::UNDECLARED_VPOS,
                    _ => codes::UNDECLARED_INPUT,
                };
                let letters: String = "xyzw"
                    .chars()
                    .enumerate()
                    .filter(|&(i, _)| missing & 1 << i != 0)
                    .map(|(_, c)| c)
                    .collect();
                self.err(
                    ins,
                    Diagnostic::coded(
                        code,
                        ins.origin.span,
                        format!("{name}.{letters} is read, but its declaration does not include it"),
                    )
                    .with_label("undeclared components")
                    .with_help(match file {
                        RegFile::Position => "vPos has only .x and .y; read them with a swizzle such as vPos.xyxy".to_string(),
                        _ => format!("declare the components read, or swizzle the read to the declared ones (e.g. {name}.xyxy)"),
                    }),
                );
            }
        }
    }

    /// Read ports: distinct registers per file (Microsoft's register table).
    fn check_read_ports(&mut self, ins: &Instruction) {
        // sincos's two extra sources before the 3_0 profiles are its
        // macro's constants, which Microsoft's assembler does not count.
        let src = match (ins.op, ins.src.as_slice()) {
            (Opcode::SinCos, [first, _, _]) => std::slice::from_ref(first),
            (_, all) => all,
        };
        // The files whose read ports are checked, in `RegFile`'s order (so
        // the diagnostics come in it). Distinct registers are counted
        // without a set: an instruction has a few sources, and this runs
        // for every instruction.
        let key = |s: &Src| (s.reg.file, s.reg.index, s.relative);
        if let Some(d) = mixed_relative_constants(src, self.p.profile, ins.origin.span) {
            self.err(ins, d);
            return;
        }
        let abs = |s: &Src| matches!(s.modifier, SrcMod::Abs | SrcMod::NegAbs);
        let mixed = src.iter().enumerate().any(|(i, s)| {
            s.reg.file == RegFile::Const
                && src[..i]
                    .iter()
                    .any(|e| key(e) == key(s) && abs(e) != abs(s))
        });
        if mixed {
            self.err(
                ins,
                Diagnostic::coded(
                    codes::ABS_MIXED_IN_INSTRUCTION,
                    ins.origin.span,
                    "one constant is read both with and without _abs in one instruction",
                )
                .with_label("_abs on some reads of the register only")
                .with_help("read it the same way in all of the instruction's sources, or copy it into r# first"),
            );
        }
        for f in &[RegFile::Temp, RegFile::Input, RegFile::Const] {
            let distinct = src
                .iter()
                .enumerate()
                .filter(|(i, s)| s.reg.file == *f && !src[..*i].iter().any(|e| key(e) == key(s)))
                .count();
            let ports = f.info().read_ports;
            if distinct as u32 > ports {
                let code = match (f, self.p.profile) {
                    (RegFile::Input, _) => codes::INPUT_PORTS,
                    (_, Profile::Ps2_0 | Profile::Ps2X) => codes::PS2_CONST_PORTS,
                    (_, Profile::Vs2_0 | Profile::Vs2X) => codes::VS2_CONST_PORTS,
                    (_, Profile::Vs3_0) => codes::VS3_CONST_PORTS,
                    _ => codes::CONST_PORTS,
                };
                self.err(
                    ins,
                    Diagnostic::coded(
                        code,
                        ins.origin.span,
                        format!(
                            "reads {} different {} registers; {} allows {}",
                            distinct,
                            f.info().name,
                            self.p.profile,
                            ports
                        ),
                    )
                    .with_label("too many read ports")
                    .with_help(format!(
                        "copy one of them into a temporary r# first (one {}# per instruction)",
                        f.info().name
                    )),
                );
            }
        }
    }

    /// aL and relative addressing only inside loop.
    fn check_relative(&mut self, idx: usize, ins: &Instruction) {
        let Some(innermost) = self.stack.iter().rev().find(|o| o.block == Block::Loop) else {
            // A subroutine may use aL when every call to it runs inside a
            // loop (judged once the calls are known).
            let uses_al = indexes_by_al(ins);
            if uses_al && self.current.is_some() {
                self.sub_relative.push(idx);
            }
            if self.current.is_none() && uses_al {
                self.err(
                    ins,
                    Diagnostic::coded(
                        al_outside_loop(self.p.profile),
                        ins.origin.span,
                        format!("{}[aL + n] used outside a loop", indexed_by_al(ins)),
                    )
                    .with_label("aL is only defined inside loop … endloop")
                    .with_help("wrap it in `loop aL, i#` … `endloop` (rep does not set aL)"),
                );
            }
            return;
        };
        let loop_at = innermost.index;
        let by_al = |s: &&Src| s.relative == Some(RelIndex::Loop) && s.reg.file == RegFile::Input;
        for s in ins.src.iter().filter(by_al) {
            if let Some(d) = self.undeclared_relative(s, loop_at, ins.origin.span) {
                self.err(ins, d);
                break;
            }
        }
    }

    /// An input read as `v[aL + n]` needs every register it reads declared
    /// (Microsoft's ps_3_0 register table: v# requires a declaration). With
    /// the loop's `i#` defined by `defi`, those are the registers of every
    /// value aL takes; otherwise the one named, `v{n}` (what aL = 0 reads).
    /// A value that lands outside v0 … v9 is not refused: Direct3D leaves
    /// such a read undefined rather than invalid, and the emulator reads 0.
    fn undeclared_relative(&self, s: &Src, loop_at: usize, span: Span) -> Option<Diagnostic> {
        let values = self.p.instructions[loop_at]
            .src
            .iter()
            .find(|c| c.reg.file == RegFile::ConstInt)
            .and_then(|c| self.p.int_def(c.reg.index))
            .filter(|[count, ..]| (0..=isa::MAX_REP_COUNT).contains(count))
            .map(|[count, start, step, _]| {
                (0..count as i64)
                    .map(|k| start as i64 + k * step as i64)
                    .collect::<Vec<_>>()
            })
            .unwrap_or_else(|| vec![0]);
        let count = RegFile::Input.info().count as i64;
        values.into_iter().find_map(|al| {
            let r = s.reg.index as i64 + al;
            let what = format!("v[aL + {}] with aL = {al}", s.reg.index);
            let undeclared = (0..count).contains(&r)
                && !self.declared_inputs.contains(&(RegFile::Input, r as u32));
            undeclared.then(|| {
                Diagnostic::documented_rule(span, format!("input v{r} is used but never declared"))
                    .with_label("undeclared input")
                    .with_note(format!("read as {what}"))
                    .with_note("Microsoft's documentation requires the declaration, its assembler does not check reads through aL; an undeclared input's value is undefined")
                    .with_help(format!(
                        "declare every input the loop reads, e.g. `dcl_texcoord{r} v{r}`"
                    ))
            })
        })
    }

    /// Outputs are not written under dynamic flow control or predication.
    fn check_output(&mut self, ins: &Instruction) {
        if let Some(d) = &ins.dst {
            if d.reg.file == RegFile::ColorOut && ins.op.class() != Class::Flow {
                let dynamic = self.stack.iter().any(|o| o.block == Block::IfDynamic);
                if dynamic || ins.predicate.is_some() {
                    self.err(ins, Diagnostic::documented_rule(ins.origin.span, format!("{} is written inside dynamic flow control or predication", d.reg))
                        .with_label("documented as not allowed in ps_3_0")
                        .with_note("Microsoft's assembler accepts it, its HLSL compiler emits it for an `if` that returns, and Direct3D 9 drivers run it; a pixel whose path writes no oC# gets an undefined colour")
                        .with_help("compute the value into r# inside the branch and write oC# once, outside it"));
                }
            }
        }
    }

    /// After main has ended, only subroutines (from a label on) have code.
    fn check_reachable(&mut self, ins: &Instruction) {
        if !self.in_main && self.current.is_none() && ins.op != Opcode::Label {
            self.err(
                ins,
                Diagnostic::coded(
                    codes::AFTER_RET,
                    ins.origin.span,
                    "instruction after the end of main and outside any subroutine",
                )
                .with_label("unreachable")
                .with_help("code after `ret` must start with `label l#`"),
            );
        }
    }

    /// Open blocks of the given kinds.
    fn depth(&self, blocks: &[Block]) -> u32 {
        self.stack
            .iter()
            .filter(|o| blocks.contains(&o.block))
            .count() as u32
    }

    /// Structure: blocks, their matching instructions and nesting limits,
    /// `break` placement, calls, the end of main and subroutines.
    fn structure(&mut self, idx: usize, ins: &Instruction) {
        let span = ins.origin.span;
        match ins.op {
            Opcode::Rep | Opcode::Loop => self.open_loop(idx, ins),
            Opcode::If | Opcode::Ifc => self.open_if(idx, ins),
            Opcode::Else => self.else_branch(idx, ins),
            Opcode::EndIf => match self.stack.last() {
                Some(o) if matches!(o.block, Block::IfStatic | Block::IfDynamic) => {
                    self.info.matching[o.index] = Some(idx as u32);
                    self.stack.pop();
                }
                other => {
                    let d = mismatch(span, "endif", "if", other);
                    self.mismatched = true;
                    self.err(ins, d)
                }
            },
            Opcode::EndRep | Opcode::EndLoop => self.close_loop(idx, ins),
            Opcode::Break | Opcode::BreakC | Opcode::BreakP
                if self.depth(&[Block::Rep, Block::Loop]) == 0 =>
            {
                self.err(
                    ins,
                    Diagnostic::coded(codes::BREAK_OUTSIDE, span, "break outside rep or loop")
                        .with_label("nothing to break out of"),
                );
            }
            Opcode::Call | Opcode::CallNz => {
                self.calls.push((idx, ins.src[0].reg.index));
                let depth = self.depth(&[Block::Rep, Block::Loop]);
                self.call_loops.push(depth);
            }
            Opcode::Ret => self.ret(idx, ins),
            Opcode::Label => self.label(idx, ins),
            _ => {}
        }
    }

    /// `rep` / `loop`: the nesting limit and the loop count's range.
    fn open_loop(&mut self, idx: usize, ins: &Instruction) {
        let span = ins.origin.span;
        if self.depth(&[Block::Rep, Block::Loop]) >= isa::MAX_LOOP_NESTING {
            self.err(
                ins,
                Diagnostic::coded(
                    codes::LOOP_DEPTH,
                    span,
                    format!("rep/loop nested more than {} deep", isa::MAX_LOOP_NESTING),
                )
                .with_label("too deep"),
            );
        }
        let block = if ins.op == Opcode::Rep {
            Block::Rep
        } else {
            Block::Loop
        };
        self.stack.push(Open {
            block,
            index: idx,
            span,
            seen_else: false,
        });
        let depth = self.depth(&[Block::Rep, Block::Loop]);
        let own = self.own_loops.entry(self.current).or_default();
        *own = (*own).max(depth);
    }

    /// `if` / `if_comp`: static (`if b#`) or dynamic, each with its nesting
    /// limit.
    fn open_if(&mut self, idx: usize, ins: &Instruction) {
        let span = ins.origin.span;
        let block = if ins.op == Opcode::If && ins.src[0].reg.file == RegFile::ConstBool {
            Block::IfStatic
        } else {
            Block::IfDynamic
        };
        let (max, kind) = if block == Block::IfStatic {
            (isa::MAX_STATIC_NESTING, "static")
        } else {
            (isa::MAX_DYNAMIC_NESTING, "dynamic")
        };
        if self.depth(&[block]) >= max {
            self.err(
                ins,
                Diagnostic::coded(
                    if block == Block::IfStatic {
                        codes::STATIC_IF_DEPTH
                    } else if ins.src[0].reg.file == RegFile::Predicate {
                        codes::PREDICATE_IF_DEPTH
                    } else {
                        codes::DYNAMIC_IF_DEPTH
                    },
                    span,
                    format!("{kind} if nested more than {max} deep"),
                )
                .with_label("too deep"),
            );
        }
        self.stack.push(Open {
            block,
            index: idx,
            span,
            seen_else: false,
        });
    }

    /// `else`: once per `if`; the `if` matches it, it matches the `endif`.
    fn else_branch(&mut self, idx: usize, ins: &Instruction) {
        let span = ins.origin.span;
        let d = match self.stack.last_mut() {
            Some(o) if matches!(o.block, Block::IfStatic | Block::IfDynamic) && !o.seen_else => {
                o.seen_else = true;
                self.info.matching[o.index] = Some(idx as u32);
                o.index = idx;
                return;
            }
            Some(o) if matches!(o.block, Block::IfStatic | Block::IfDynamic) => {
                Diagnostic::coded(codes::ELSE_TWICE, span, "second `else` for the same `if`")
                    .with_secondary(o.span, "this if")
            }
            other => mismatch(span, "else", "if", other.map(|o| &*o)),
        };
        self.mismatched = true;
        self.err(ins, d);
    }

    /// `endrep` / `endloop`: the loop and its end match each other.
    fn close_loop(&mut self, idx: usize, ins: &Instruction) {
        let (want, name, opener) = if ins.op == Opcode::EndRep {
            (Block::Rep, "endrep", "rep")
        } else {
            (Block::Loop, "endloop", "loop")
        };
        match self.stack.last() {
            Some(o) if o.block == want => {
                self.info.matching[o.index] = Some(idx as u32);
                self.info.matching[idx] = Some(o.index as u32);
                self.stack.pop();
            }
            other => {
                let d = mismatch(ins.origin.span, name, opener, other);
                self.mismatched = true;
                self.err(ins, d)
            }
        }
    }

    /// `ret`: no block open; the first one ends main.
    fn ret(&mut self, idx: usize, ins: &Instruction) {
        if let Some(o) = self.stack.last() {
            let d = Diagnostic::coded(
                codes::RET_IN_BLOCK,
                ins.origin.span,
                "ret inside an open block",
            )
            .with_secondary(o.span, "block opened here")
            .with_help("close the block before ret");
            self.err(ins, d);
        }
        if self.in_main {
            self.in_main = false;
            self.info.main_end = idx as u32 + 1;
        }
        self.current = None;
    }

    /// `label l#`: right after a `ret`, defined once; it starts a
    /// subroutine (and ends main if no `ret` did).
    fn label(&mut self, idx: usize, ins: &Instruction) {
        let span = ins.origin.span;
        let label = ins.src[0].reg.index;
        let after_ret = idx > 0 && self.p.instructions[idx - 1].op == Opcode::Ret;
        if !after_ret {
            self.err(
                ins,
                Diagnostic::coded(
                    codes::LABEL_PLACE,
                    span,
                    "label must immediately follow a ret",
                )
                .with_label("subroutines start after the end of main")
                .with_help("end main (or the previous subroutine) with ret"),
            );
        }
        if let Some(prev) = self.info.labels.insert(label, idx as u32) {
            self.err(
                ins,
                Diagnostic::coded(
                    codes::LABEL_TWICE,
                    span,
                    format!("label l{label} is defined twice"),
                )
                .with_secondary(
                    self.p.instructions[prev as usize].origin.span,
                    "first defined here",
                ),
            );
        }
        if self.in_main {
            self.in_main = false;
            self.info.main_end = idx as u32;
        }
        self.current = Some(label);
        self.owner[idx] = self.current;
    }

    /// A subroutine ends at its ret (Microsoft, `ret - ps`: the first ret
    /// is the end of the main program or subroutine; ret is optional only at
    /// the end of a shader without subroutines), so the last one must end
    /// with one too: the others are followed by a `label`, which must follow
    /// a ret.
    fn check_final_ret(&mut self) {
        let p = self.p;
        if let Some(label) = self.current {
            if p.instructions.last().map(|i| i.op) != Some(Opcode::Ret) {
                let at = self
                    .info
                    .labels
                    .get(&label)
                    .map(|&i| &p.instructions[i as usize]);
                if let Some(at) = at {
                    self.diags.push(
                        Diagnostic::coded(codes::SUBROUTINE_WITHOUT_RET,
                            at.origin.span,
                            format!("subroutine l{label} does not end with ret"),
                        )
                        .with_label("the subroutine starts here and runs to the end of the file")
                        .with_help("end every subroutine with ret; only a shader without subroutines may leave out the final ret")
                        .in_origin(&at.origin, self.file),
                    );
                }
            }
        }
    }

    /// After the last instruction: blocks never closed, a last subroutine
    /// without its ret, mixed `_abs` constant reads, the call graph; the
    /// total slot count.
    fn finish(mut self) -> Info {
        let p = self.p;
        let unclosed = if self.mismatched {
            &[][..]
        } else {
            &self.stack[..]
        };
        for o in unclosed.iter().rev() {
            let (what, close, code) = match o.block {
                Block::Rep => ("rep", "endrep", codes::LOOP_UNCLOSED),
                Block::Loop => ("loop", "endloop", codes::LOOP_UNCLOSED),
                _ => ("if", "endif", codes::IF_UNCLOSED),
            };
            self.diags.push(
                Diagnostic::coded(code, o.span, format!("`{what}` is never closed"))
                    .with_label("opened here")
                    .with_help(format!("add `{close}` at the end of the block"))
                    .in_origin(&p.instructions[o.index].origin, self.file),
            );
        }
        self.check_final_ret();
        if let (Some(a), Some(b)) = self.abs_consts {
            self.diags.push(
                Diagnostic::documented_rule(a.max(b), "constants are read both with and without _abs")
                    .with_secondary(a.min(b), "the other kind")
                    .with_note("Microsoft's documentation asks for one kind in a shader; its assembler and real hardware accept both (its HLSL compiler emits such shaders), and only one instruction reading the same c# both ways is refused")
                    .with_help("in ps_3_0 either every c# read uses _abs or none does"),
            );
        }
        check_calls(
            p,
            &self.info,
            &self.calls,
            &self.owner,
            self.diags,
            self.file,
        );
        self.check_call_order();
        self.info
    }
}

impl Checker<'_, '_> {
    /// What Microsoft's validator adds to the call graph: a call goes
    /// forward (to a label defined after it), every label is called, and
    /// the loops a call runs inside count toward the loop-nesting limit of
    /// the subroutine it calls.
    fn check_call_order(&mut self) {
        let p = self.p;
        let at = |i: usize| &p.instructions[i];
        let mut found: Vec<(usize, Diagnostic)> = Vec::new();
        let mut called = BTreeSet::new();
        for &(idx, label) in &self.calls {
            called.insert(label);
            if let Some(&def) = self.info.labels.get(&label) {
                if (def as usize) < idx {
                    let d = Diagnostic::coded(
                        codes::CALL_BACKWARD,
                        at(idx).origin.span,
                        format!("call to l{label}, which is defined before the call"),
                    )
                    .with_secondary(at(def as usize).origin.span, "defined here")
                    .with_help("a subroutine may call only subroutines defined after it");
                    found.push((idx, d));
                }
            }
        }
        for (&label, &def) in &self.info.labels {
            if !called.contains(&label) {
                let d = Diagnostic::coded(
                    codes::UNREFERENCED_LABEL,
                    at(def as usize).origin.span,
                    format!("subroutine l{label} is never called"),
                )
                .with_help("remove it, or call it");
                found.push((def as usize, d));
            }
        }
        // The deepest loop nesting a routine reaches, its calls included;
        // callees are defined later, so walking labels from the last one
        // knows each callee before its callers.
        let mut reach: BTreeMap<Option<u32>, u32> = BTreeMap::new();
        let mut routines: Vec<(u32, Option<u32>)> = self
            .info
            .labels
            .iter()
            .map(|(&l, &i)| (i, Some(l)))
            .collect();
        routines.sort_unstable();
        routines.insert(0, (0, None));
        for &(_, routine) in routines.iter().rev() {
            let mut deepest = self.own_loops.get(&routine).copied().unwrap_or(0);
            for (k, &(idx, label)) in self.calls.iter().enumerate() {
                if self.owner[idx] != routine {
                    continue;
                }
                let total = self.call_loops[k] + reach.get(&Some(label)).copied().unwrap_or(0);
                if total > isa::MAX_LOOP_NESTING {
                    let d = Diagnostic::coded(
                        codes::LOOP_DEPTH,
                        at(idx).origin.span,
                        format!(
                            "rep/loop nested {total} deep through this call; ps_3_0 allows {}",
                            isa::MAX_LOOP_NESTING
                        ),
                    )
                    .with_label("the subroutine's loops run inside this call's")
                    .with_help("loops in a subroutine count toward the nesting of every loop that calls it");
                    found.push((idx, d));
                }
                deepest = deepest.max(total);
            }
            reach.insert(routine, deepest);
        }
        // A subroutine runs inside a loop when every call to it does: from
        // inside a loop, or from a subroutine that does (callers are
        // defined before their callees).
        let mut in_loop: BTreeMap<u32, bool> = BTreeMap::new();
        for &(_, routine) in &routines {
            let Some(label) = routine else { continue };
            let mut sites = self
                .calls
                .iter()
                .enumerate()
                .filter(|(_, &(_, l))| l == label)
                .peekable();
            let called = sites.peek().is_some();
            let all = sites.all(|(k, &(idx, _))| {
                self.call_loops[k] > 0
                    || self.owner[idx].is_some_and(|o| in_loop.get(&o).copied().unwrap_or(false))
            });
            in_loop.insert(label, called && all);
        }
        for &idx in &self.sub_relative {
            let inside = self.owner[idx].is_some_and(|o| in_loop.get(&o).copied().unwrap_or(false));
            if !inside {
                found.push((
                    idx,
                    Diagnostic::coded(
                        al_outside_loop(self.p.profile),
                        at(idx).origin.span,
                        format!(
                            "{}[aL + n] in a subroutine that is not always called from inside a loop",
                            indexed_by_al(at(idx))
                        ),
                    )
                    .with_label("aL is only defined inside loop … endloop")
                    .with_help("call the subroutine only from inside `loop aL, i#` … `endloop`"),
                ));
            }
        }
        for (i, d) in found {
            self.err(at(i), d);
        }
    }
}

/// Constants read relatively beside different relative reads or plain ones
/// in one instruction, which Microsoft's vertex validator refuses before
/// it counts read ports (X5743, X5747; X5749 in vs_3_0).
fn mixed_relative_constants(src: &[Src], profile: Profile, span: Span) -> Option<Diagnostic> {
    let consts: Vec<&Src> = src
        .iter()
        .filter(|s| s.reg.file == RegFile::Const)
        .collect();
    let first = consts.iter().find(|s| s.relative.is_some())?;
    let key = |s: &Src| (s.reg.index, s.relative);
    if consts
        .iter()
        .any(|s| s.relative.is_some() && key(s) != key(first))
    {
        return Some(
            Diagnostic::coded(
                match profile {
                    Profile::Vs3_0 => codes::CONST_RELATIVE_DIFFERENT_3_0,
                    _ => codes::CONST_RELATIVE_DIFFERENT,
                },
                span,
                "two different relatively addressed constants in one instruction",
            )
            .with_label("one constant register per instruction")
            .with_help("copy one of them into a temporary r# first"),
        );
    }
    consts.iter().any(|s| s.relative.is_none()).then(|| {
        let code = match profile {
            Profile::Vs3_0 => codes::CONST_RELATIVE_ABSOLUTE_3_0,
            _ => codes::CONST_RELATIVE_ABSOLUTE,
        };
        Diagnostic::coded(
            code,
            span,
            "a relatively addressed constant beside a plain one in one instruction",
        )
        .with_label("one constant register per instruction")
        .with_help("copy one of them into a temporary r# first")
    })
}

/// Whether an instruction indexes a register by `aL` (`v[aL + n]`,
/// `c[aL + n]`, `o[aL + n]`).
fn indexes_by_al(ins: &Instruction) -> bool {
    let src = ins.src.iter().any(|s| s.relative == Some(RelIndex::Loop));
    src || ins.dst.is_some_and(|d| d.relative == Some(RelIndex::Loop))
}

/// The name of the file an instruction indexes by `aL` (`v`, `c`, `o`).
fn indexed_by_al(ins: &Instruction) -> &'static str {
    let by_al = ins
        .src
        .iter()
        .find(|s| s.relative == Some(RelIndex::Loop))
        .map(|s| s.reg.file);
    let file = by_al.or(ins.dst.filter(|d| d.relative.is_some()).map(|d| d.reg.file));
    file.map_or("v", |f| f.info().name)
}

/// Microsoft's code for `aL` outside a loop, which differs by stage.
fn al_outside_loop(profile: Profile) -> codes::Code {
    match profile.stage() {
        Stage::Vertex if profile == Profile::Vs3_0 => codes::AL_OUTSIDE_LOOP_VS_3_0,
        Stage::Vertex => codes::AL_OUTSIDE_LOOP_VS,
        _ => codes::AL_OUTSIDE_LOOP,
    }
}

fn mismatch(span: Span, closer: &str, opener: &str, open: Option<&Open>) -> Diagnostic {
    let code = match closer {
        "endif" => codes::ENDIF_MISMATCH,
        "else" => codes::ELSE_MISMATCH,
        "endrep" => codes::ENDREP_MISMATCH,
        _ => codes::ENDLOOP_MISMATCH,
    };
    let d = Diagnostic::coded(
        code,
        span,
        format!("`{closer}` without a matching `{opener}`"),
    )
    .with_label("nothing to close");
    match open {
        Some(o) => d
            .with_secondary(o.span, "the innermost open block is this one")
            .with_help("blocks must nest: close the inner block first"),
        None => d,
    }
}

/// The depth of the deepest call chain from main, or the first cycle met
/// (the path from main to the call that closes it). Depth first, without
/// recursion, remembering each subroutine's depth once it is known: the
/// work is linear in the call graph however many call paths run through it.
fn call_depth(graph: &BTreeMap<Option<u32>, BTreeSet<u32>>) -> Result<u32, Vec<u32>> {
    let none = BTreeSet::new();
    let callees = |n: Option<u32>| graph.get(&n).unwrap_or(&none).iter().copied();
    let mut known: BTreeMap<u32, u32> = BTreeMap::new();
    let mut path: Vec<u32> = Vec::new();
    let mut on_path: BTreeSet<u32> = BTreeSet::new();
    // One frame per subroutine on the path: its callees still to visit and
    // the depth of its deepest chain so far.
    let mut stack = vec![(callees(None), 0u32)];
    loop {
        let top = stack.len() - 1;
        match stack[top].0.next() {
            Some(c) if on_path.contains(&c) => {
                let mut cycle = path.clone();
                cycle.push(c);
                return Err(cycle);
            }
            Some(c) => match known.get(&c) {
                Some(&d) => stack[top].1 = stack[top].1.max(d + 1),
                None => {
                    path.push(c);
                    on_path.insert(c);
                    stack.push((callees(Some(c)), 0));
                }
            },
            None => {
                let (_, d) = stack.pop().expect("a frame is on the stack");
                let Some(done) = path.pop() else {
                    return Ok(d);
                };
                on_path.remove(&done);
                known.insert(done, d);
                let parent = stack.last_mut().expect("main's frame is below");
                parent.1 = parent.1.max(d + 1);
            }
        }
    }
}

/// Calls name defined labels; the call graph has no cycles and no chain
/// deeper than the call-nesting limit.
fn check_calls(
    p: &Program,
    info: &Info,
    calls: &[(usize, u32)],
    owner: &[Option<u32>],
    diags: &mut Diagnostics,
    file: &SourceFile,
) {
    let mut graph: BTreeMap<Option<u32>, BTreeSet<u32>> = BTreeMap::new();
    for &(idx, label) in calls {
        let ins = &p.instructions[idx];
        if !info.labels.contains_key(&label) {
            diags.push(
                Diagnostic::coded(
                    codes::UNDEFINED_LABEL,
                    ins.origin.span,
                    format!("call to undefined label l{label}"),
                )
                .with_label("no such label")
                .with_help(format!(
                    "define the subroutine after main with `label l{label}` … `ret`"
                ))
                .in_origin(&ins.origin, file),
            );
        }
        graph.entry(owner[idx]).or_default().insert(label);
    }
    let span = calls
        .first()
        .map(|&(i, _)| p.instructions[i].origin.span)
        .unwrap_or_default();
    match call_depth(&graph) {
        Err(cycle) => {
            let names: Vec<String> = cycle.iter().map(|l| format!("l{l}")).collect();
            // Point at the call that closes the cycle.
            let (caller, callee) = (cycle[cycle.len() - 2], cycle[cycle.len() - 1]);
            let span = calls
                .iter()
                .find(|&&(i, l)| l == callee && owner[i] == Some(caller))
                .map_or(span, |&(i, _)| p.instructions[i].origin.span);
            diags.push(
                Diagnostic::coded(
                    codes::CALL_BACKWARD,
                    span,
                    format!("recursive calls: {}", names.join(" → ")),
                )
                .with_label("ps_3_0 has no recursion"),
            );
        }
        Ok(d) if d > isa::MAX_CALL_NESTING => {
            diags.push(
                Diagnostic::coded(
                    codes::CALL_DEPTH,
                    span,
                    format!(
                        "calls nest {d} deep; ps_3_0 allows {}",
                        isa::MAX_CALL_NESTING
                    ),
                )
                .with_label("too deep"),
            );
        }
        Ok(_) => {}
    }
}
