//! The cost model: static slots of every instruction, and executed slots
//! checked against a brute-force interpreter.
//!
//! Why: the slot and executed-instruction counts are ps30's headline numbers
//! (the article's 512 / 65,535 budgets), so each must be pinned to a source
//! the code cannot drift from. The slot counts of both
//! tables are written here as literals — the documented one from
//! Microsoft's ps_3_0 instruction page (via the project's fact sheet),
//! Microsoft's count as `D3DDisassemble`'s listing prints it for
//! one-instruction probes — not read back from `isa::TABLE`, and every table
//! row is exercised by a minimal shader under both. The executed counts are compared with a small
//! interpreter in this file that walks the flat instruction list with a
//! program counter and a loop stack, applying the counting rule of
//! `cost.rs`'s module docs literally, on random nests of rep/loop, static
//! ifs, breaks, subroutines and REPEAT_BLOCKs: the symbolic totals and the
//! per-instruction execution counts must equal the interpreter's exactly.
//! Data-dependent programs (dynamic branches, data-dependent breaks,
//! unknown constants) must give the right shortest and longest paths, and
//! a 255⁴ nest must be analysed by formula, not by walking it.

use proptest::prelude::*;
use ps30::core::cost::{self, Analysis, Environment, Profile, Range, Verdict};
use ps30::core::ir::{Shader, SrcMod};
use ps30::core::isa::{Class, Opcode, RegFile, SlotTable, TABLE};
use ps30::core::load::{self, Loaded, Options};

// ---------------------------------------------------------------------------
// Slot counts, the documented table: Microsoft ps_3_0 instruction table ("Instruction slots"
// column of learn.microsoft.com/windows/win32/direct3dhlsl/
// dx9-graphics-reference-asm-ps-instructions-ps-3-0, as transcribed in the
// project's ps_3_0 fact sheet §1). Cube-map samplers: texld 1 + 3,
// texldp 3 + 1, texldl 2 + 3 (same table). Predication adds 1 (Microsoft's
// setp_comp page). Declarations, definitions and label cost nothing.

#[rustfmt::skip]
const DOCUMENTED_SLOTS: &[(&str, u64)] = &[
    ("nop", 1), ("mov", 1), ("add", 1), ("sub", 1), ("mad", 1), ("mul", 1),
    ("rcp", 1), ("rsq", 1), ("dp3", 1), ("dp4", 1), ("min", 1), ("max", 1),
    ("exp", 1), ("log", 1), ("lrp", 2), ("frc", 1),
    ("m4x4", 4), ("m4x3", 3), ("m3x4", 4), ("m3x3", 3), ("m3x2", 2),
    ("pow", 3), ("crs", 2), ("abs", 1), ("nrm", 3), ("sincos", 8), ("cmp", 1),
    ("dp2add", 2), ("dsx", 2), ("dsy", 2),
    ("texkill", 2), ("texld", 1), ("texldp", 3), ("texldb", 6), ("texldl", 2), ("texldd", 3),
    ("setp", 1),
    ("call", 2), ("callnz", 3), ("loop", 3), ("ret", 1), ("endloop", 2), ("label", 0),
    ("rep", 3), ("endrep", 2), ("if", 3), ("if_comp", 3), ("else", 1), ("endif", 1),
    ("break", 1), ("break_comp", 3), ("breakp", 3),
    ("def", 0), ("defi", 0), ("defb", 0), ("dcl", 0),
];

/// The documented cube-sampler costs (same table).
const DOCUMENTED_CUBE_SLOTS: &[(&str, u64)] = &[("texld", 4), ("texldp", 4), ("texldl", 5)];

// Microsoft's count: the change in `D3DDisassemble`'s `// approximately N
// instruction slots used` line when one instruction is added to a shader
// (d3dcompiler_47.dll, on 2D, cube and volume samplers alike, predicated or
// not). Only these rows differ from the documented table.
#[rustfmt::skip]
const FXC_DIFFERENT: &[(&str, u64)] = &[
    ("nop", 0), ("lrp", 1), ("texkill", 1), ("texldp", 1), ("texldb", 1),
];

/// The slot count of one source line (`(p0) texld_pp r0, ...`) under
/// Microsoft's table, with predication; `cube` when its sampler is a cube map.
fn literal_slots(line: &str, cube: bool) -> u64 {
    literal_slots_under(line, cube, SlotTable::Fxc)
}

/// [`literal_slots`] under either table.
fn literal_slots_under(line: &str, cube: bool, slot_table: SlotTable) -> u64 {
    let line = line.trim();
    let (predicated, rest) = match line.strip_prefix('(') {
        Some(r) => (true, r.split_once(')').expect("closing paren").1.trim()),
        None => (false, line),
    };
    let word = rest.split_whitespace().next().unwrap_or("");
    let mut parts = word.split('_');
    let base = parts.next().unwrap().to_ascii_lowercase();
    let compared = parts.any(|s| matches!(s, "gt" | "lt" | "ge" | "le" | "eq" | "ne"));
    let name = match (base.as_str(), compared) {
        ("if", true) => "if_comp".to_string(),
        ("break", true) => "break_comp".to_string(),
        _ => base,
    };
    let cube_rows = match (cube, slot_table) {
        (true, SlotTable::Documented) => DOCUMENTED_CUBE_SLOTS,
        _ => &[],
    };
    let fxc_rows = match slot_table {
        SlotTable::Fxc => FXC_DIFFERENT,
        SlotTable::Documented => &[],
    };
    let (_, slots) = cube_rows
        .iter()
        .chain(fxc_rows)
        .chain(DOCUMENTED_SLOTS)
        .find(|(m, _)| *m == name)
        .unwrap_or_else(|| panic!("no slot count for `{name}`"));
    slots + predicated as u64
}

/// The rows of the instruction table ps_3_0 has.
fn ps_3_0_rows() -> impl Iterator<Item = &'static ps30::core::isa::OpInfo> {
    TABLE
        .iter()
        .filter(|r| r.op.profiles().has(ps30::core::profile::Profile::Ps3_0))
}

/// A minimal valid shader with one instance of `op`: declarations, then the
/// instruction lines, the first of which is the instance itself. What the
/// instance reads is the input v0 (declared in every minimal shader) or a
/// constant, never a temporary no instruction has written.
fn minimal(op: Opcode) -> (&'static str, Vec<&'static str>) {
    use Opcode::*;
    let plain = |line| ("", vec![line]);
    match op {
        Nop => plain("nop"),
        Mov => plain("mov r0, c0"),
        Add => plain("add r0, v0, c0"),
        Sub => plain("sub r0, v0, c0"),
        Mad => plain("mad r0, v0, c0, v0"),
        Mul => plain("mul r0, v0, c0"),
        Rcp => plain("rcp r0, v0.x"),
        Rsq => plain("rsq r0, v0.x"),
        Dp3 => plain("dp3 r0, v0, c0"),
        Dp4 => plain("dp4 r0, v0, c0"),
        Min => plain("min r0, v0, c0"),
        Max => plain("max r0, v0, c0"),
        Exp => plain("exp r0, v0.x"),
        Log => plain("log r0, v0.x"),
        Lrp => plain("lrp r0, v0, v0, c0"),
        Frc => plain("frc r0, v0"),
        M4x4 => plain("m4x4 r0, v0, c0"),
        M4x3 => plain("m4x3 r0.xyz, v0, c0"),
        M3x4 => plain("m3x4 r0, v0, c0"),
        M3x3 => plain("m3x3 r0.xyz, v0, c0"),
        M3x2 => plain("m3x2 r0.xy, v0, c0"),
        Pow => plain("pow r0, v0.x, c0.y"),
        Crs => plain("crs r0.xyz, v0, v0"),
        Abs => plain("abs r0, v0"),
        Nrm => plain("nrm r0, v0"),
        SinCos => plain("sincos r0.xy, v0.x"),
        Cmp => plain("cmp r0, v0, v0, c0"),
        Dp2Add => plain("dp2add r0, v0, v0, c0.x"),
        Dsx => plain("dsx r0, v0"),
        Dsy => plain("dsy r0, v0"),
        TexKill => plain("texkill v0"),
        TexLd => ("dcl_2d s0", vec!["texld r0, v0, s0"]),
        TexLdP => ("dcl_2d s0", vec!["texldp r0, v0, s0"]),
        TexLdB => ("dcl_2d s0", vec!["texldb r0, v0, s0"]),
        TexLdL => ("dcl_2d s0", vec!["texldl r0, v0, s0"]),
        TexLdD => ("dcl_2d s0", vec!["texldd r0, v0, s0, v0, v0"]),
        Setp => plain("setp_gt p0, v0, c0"),
        Call => ("", vec!["call l0", "ret", "label l0", "ret"]),
        CallNz => ("", vec!["callnz l0, b0", "ret", "label l0", "ret"]),
        Loop => ("", vec!["loop aL, i0", "endloop"]),
        Ret => plain("ret"),
        EndLoop => ("", vec!["endloop", "loop aL, i0"]),
        // Called, as Microsoft's validator requires of every label (X5887).
        Label => ("", vec!["label l0", "call l0", "ret", "ret"]),
        Rep => ("", vec!["rep i0", "endrep"]),
        EndRep => ("", vec!["endrep", "rep i0"]),
        If => ("", vec!["if b0", "endif"]),
        Ifc => ("", vec!["if_gt v0.x, c0.y", "endif"]),
        Else => ("", vec!["else", "if b0", "endif"]),
        EndIf => ("", vec!["endif", "if b0"]),
        Break => ("", vec!["break", "rep i0", "endrep"]),
        BreakC => ("", vec!["break_ne v0.x, c0.y", "rep i0", "endrep"]),
        BreakP => ("", vec!["breakp !p0.z", "rep i0", "endrep"]),
        Def | DefI | DefB | Dcl => unreachable!("declarations have no instance"),
        Mova | Lit | Dst | Expp | Logp | Slt | Sge | Sgn => {
            unreachable!("vertex-shader instructions are not ps_3_0's")
        }
        op if op.is_ps1_only() => unreachable!("ps_1_x instructions are not ps_3_0's"),
        _ => unreachable!("every ps_3_0 row has its instance above"),
    }
}

/// The source text of a minimal shader: the lines are listed instance
/// first, but some need their scaffolding before them in the file.
fn minimal_source(op: Opcode, decls: &str, lines: &[&str]) -> String {
    use Opcode::*;
    let ordered: Vec<&str> = match op {
        // closer after its opener
        EndLoop | EndRep | EndIf => vec![lines[1], lines[0]],
        Else => vec![lines[1], lines[0], lines[2]],
        Break | BreakC | BreakP => vec![lines[1], lines[0], lines[2]],
        Label => vec![lines[1], lines[2], lines[0], lines[3]],
        _ => lines.to_vec(),
    };
    format!(
        "ps_3_0\ndcl_texcoord0 v0\n{decls}\n{}\n",
        ordered.join("\n")
    )
}

fn load(name: &str, src: &str) -> Loaded {
    load_with(name, src, &Options::default())
}

fn load_with(name: &str, src: &str, options: &Options) -> Loaded {
    load::load_str(name, src, options).unwrap_or_else(|e| {
        panic!(
            "{name} does not load:\n{}\n{src}",
            e.diagnostics.render(&e.file)
        )
    })
}

fn analyse(l: &Loaded) -> Analysis {
    analyse_in(l, &Environment::default())
}

fn analyse_in(l: &Loaded, env: &Environment) -> Analysis {
    analyse_under(l, env, SlotTable::Fxc)
}

fn analyse_under(l: &Loaded, env: &Environment, table: SlotTable) -> Analysis {
    let profile = Profile::ps_3_0().counting(table);
    cost::analyse(&l.shader, &l.file, env, &profile).expect("analysis")
}

/// The index of the instruction written on `line` (1-based) of the file.
fn index_on_line(l: &Loaded, line: usize) -> usize {
    l.shader
        .instructions()
        .iter()
        .position(|i| l.file.line_of(i.origin.span.start) == line)
        .unwrap_or_else(|| panic!("no instruction on line {line}"))
}

#[test]
fn every_instruction_costs_its_slots_under_both_tables() {
    let mut problems = Vec::new();
    let mut covered = 0;
    for row in ps_3_0_rows() {
        if row.class == Class::Declaration {
            continue;
        }
        covered += 1;
        let (decls, lines) = minimal(row.op);
        let src = minimal_source(row.op, decls, &lines);
        let l = load(row.mnemonic, &src);
        // The instance is the only instruction of its opcode.
        let at = l
            .shader
            .instructions()
            .iter()
            .position(|i| i.op == row.op)
            .expect("the instance");
        for table in SlotTable::ALL {
            let a = analyse_under(&l, &Environment::default(), table);
            let own = l.shader.info().slots(at, table) as u64;
            let want_own = literal_slots_under(lines[0], false, table);
            let want_total: u64 = lines
                .iter()
                .map(|s| literal_slots_under(s, false, table))
                .sum();
            if own != want_own || a.slots != want_total || a.split.total() as u64 != a.slots {
                problems.push(format!(
                    "{:?} ({table}): instruction {own} slots (expected {want_own}), shader {} (expected {want_total})\n{src}",
                    row.op, a.slots
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // Every executable row of the table was exercised.
    assert_eq!(
        covered,
        ps_3_0_rows()
            .filter(|r| r.class != Class::Declaration)
            .count()
    );
    assert_eq!(covered, 52);
}

#[test]
fn the_articles_instructions_cost_the_same_in_both_tables() {
    // So every figure of the article (slots and executed counts) is the same
    // under either table, and `ps30 verify` holds under both.
    for (name, text) in [
        ("loop", include_str!("../asm/article/lum_pass1_loop.psh")),
        (
            "unrolled",
            include_str!("../asm/article/lum_pass1_unrolled.psh"),
        ),
        ("pass2", include_str!("../asm/article/lum_pass2.psh")),
    ] {
        let mut options = Options::default();
        options.defines.insert("xsize".into(), 11);
        options.defines.insert("ysize".into(), 8);
        let l = load_with(name, text, &options);
        let info = l.shader.info();
        for (i, ins) in l.shader.instructions().iter().enumerate() {
            assert_eq!(
                info.slots(i, SlotTable::Fxc),
                info.slots(i, SlotTable::Documented),
                "{name}: {}",
                ins.op
            );
        }
        let mut env = Environment::default();
        env.ints.insert(1, [128, 0, 0, 0]);
        env.ints.insert(2, [56, 0, 0, 0]);
        let [a, b] = SlotTable::ALL.map(|t| analyse_under(&l, &env, t));
        assert_eq!((a.slots, a.executed), (b.slots, b.executed), "{name}");
    }
}

#[test]
fn declarations_and_definitions_cost_nothing() {
    let l = load(
        "decls.psh",
        "ps_3_0\ndef c0, 1, 2, 3, 4\ndefi i0, 1, 0, 0, 0\ndefb b0, true\n\
         dcl_texcoord0 v0\ndcl_2d s0\ndcl vPos.xy\ndcl vFace\nmov oC0, c0\n",
    );
    let a = analyse(&l);
    assert_eq!(a.slots, literal_slots("mov oC0, c0", false));
    for d in ["def", "defi", "defb", "dcl"] {
        assert_eq!(literal_slots(d, false), 0);
    }
}

#[test]
fn cube_samplers_cost_more_for_texld_texldp_and_texldl_only_in_the_documented_table() {
    for (ty, cube) in [("2d", false), ("volume", false), ("cube", true)] {
        for line in [
            "texld r0, v0, s0",
            "texldp r0, v0, s0",
            "texldl r0, v0, s0",
            "texldb r0, v0, s0",
            "texldd r0, v0, s0, v0, v0",
            "(p0.x) texld r0, v0, s0",
            "(!p0) texldl_pp r0, v0, s0",
        ] {
            let l = load(
                line,
                &format!("ps_3_0\ndcl_texcoord0 v0\ndcl_{ty} s0\n{line}\n"),
            );
            for table in SlotTable::ALL {
                let a = analyse_under(&l, &Environment::default(), table);
                let want = literal_slots_under(line, cube, table);
                assert_eq!(a.slots, want, "{line} with dcl_{ty} ({table})");
                assert_eq!(a.executed, Range::exact(want), "{line} with dcl_{ty}");
            }
        }
    }
    // The numbers themselves, for the record.
    let doc = |line| literal_slots_under(line, true, SlotTable::Documented);
    assert_eq!(doc("texld r0, r1, s0"), 4);
    assert_eq!(doc("texldp r0, r1, s0"), 4);
    assert_eq!(doc("texldl r0, r1, s0"), 5);
    assert_eq!(doc("texldb r0, r1, s0"), 6);
    // Microsoft's tools ignore the sampler type.
    assert_eq!(literal_slots("texld r0, r1, s0", true), 1);
    assert_eq!(literal_slots("texldl r0, r1, s0", true), 2);
}

#[test]
fn predication_adds_one_slot_to_every_predicable_instruction() {
    let mut problems = Vec::new();
    for row in ps_3_0_rows().filter(|r| r.predicable) {
        let (decls, lines) = minimal(row.op);
        let mut lines: Vec<&str> = lines.to_vec();
        let predicated = format!("(!p0.y) {}", lines[0]);
        lines[0] = &predicated;
        let src = minimal_source(row.op, decls, &lines);
        let l = load(row.mnemonic, &src);
        for table in SlotTable::ALL {
            let a = analyse_under(&l, &Environment::default(), table);
            let want: u64 = lines
                .iter()
                .map(|s| literal_slots_under(s, false, table))
                .sum();
            let plain = literal_slots_under(&predicated[8..], false, table);
            if a.slots != want || want != plain + 1 {
                problems.push(format!(
                    "{:?} ({table}): {} slots, expected {want}",
                    row.op, a.slots
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // Flow control cannot be predicated at all.
    for row in ps_3_0_rows().filter(|r| r.class == Class::Flow) {
        assert!(!row.predicable, "{}", row.mnemonic);
    }
}

// ---------------------------------------------------------------------------
// The brute-force interpreter.

/// Runs a program without data-dependent flow, charging each executed
/// instruction its static slots under Microsoft's table (`Info::slots`,
/// whose values the tests above pin to the literal tables). The counting rule of cost.rs, read
/// literally: rep/loop is charged on every iteration it starts (once when
/// it runs 0 times), endrep/endloop on every iteration it ends; if, else
/// and endif each time control passes them (a false `if` jumps to its
/// `else`, which is passed, or to its `endif`; the end of a then-branch
/// passes `else` and jumps to `endif`); a break charges itself and leaves
/// its loop without passing endrep/endloop; call charges itself, the
/// callee body and its ret; label is never executed (calls enter after
/// it); `ret` in main ends the shader.
///
/// Returns the total and the execution count of each instruction.
fn brute_force(shader: &Shader) -> (u64, Vec<u64>) {
    brute_force_within(shader, u64::MAX).expect("no budget")
}

/// [`brute_force`], giving up (`None`) after `budget` executed instructions.
fn brute_force_within(shader: &Shader, budget: u64) -> Option<(u64, Vec<u64>)> {
    let ins = shader.instructions();
    let info = shader.info();
    let program = shader.program();
    let mut counts = vec![0u64; ins.len()];
    let mut total = 0u64;
    struct Frame {
        head: usize,
        left: u64,
    }
    let mut loops: Vec<Frame> = Vec::new();
    let mut calls: Vec<usize> = Vec::new();
    let condition = |i: usize| -> bool {
        let src = ins[i]
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::ConstBool)
            .expect("a static condition");
        let value = program.bool_def(src.reg.index).expect("defb");
        value != (src.modifier == SrcMod::Not)
    };
    let mut pc = 0usize;
    let mut steps = 0u64;
    loop {
        steps += 1;
        if steps > budget {
            return None;
        }
        if calls.is_empty() && pc >= info.main_end as usize {
            break;
        }
        let mut charge = |i: usize| {
            counts[i] += 1;
            total += info.slots(i, SlotTable::Fxc) as u64;
        };
        match ins[pc].op {
            Opcode::Rep | Opcode::Loop => {
                charge(pc);
                let reg = ins[pc]
                    .src
                    .iter()
                    .find(|s| s.reg.file == RegFile::ConstInt)
                    .unwrap()
                    .reg
                    .index;
                let n = program.int_def(reg).expect("defi")[0] as u64;
                if n == 0 {
                    pc = info.matching[pc].unwrap() as usize + 1;
                } else {
                    loops.push(Frame { head: pc, left: n });
                    pc += 1;
                }
            }
            Opcode::EndRep | Opcode::EndLoop => {
                charge(pc);
                let frame = loops.last_mut().expect("open loop");
                frame.left -= 1;
                if frame.left > 0 {
                    let head = frame.head;
                    charge(head);
                    pc = head + 1;
                } else {
                    loops.pop();
                    pc += 1;
                }
            }
            Opcode::Break => {
                charge(pc);
                let frame = loops.pop().expect("break in a loop");
                pc = info.matching[frame.head].unwrap() as usize + 1;
            }
            Opcode::If => {
                charge(pc);
                if condition(pc) {
                    pc += 1;
                } else {
                    let next = info.matching[pc].unwrap() as usize;
                    if ins[next].op == Opcode::Else {
                        charge(next);
                        pc = next + 1;
                    } else {
                        pc = next;
                    }
                }
            }
            Opcode::Else => {
                // Reached at the end of the then-branch.
                charge(pc);
                pc = info.matching[pc].unwrap() as usize;
            }
            Opcode::Call | Opcode::CallNz => {
                charge(pc);
                if ins[pc].op == Opcode::Call || condition(pc) {
                    calls.push(pc + 1);
                    pc = info.labels[&ins[pc].src[0].reg.index] as usize + 1;
                } else {
                    pc += 1;
                }
            }
            Opcode::Ret => {
                charge(pc);
                match calls.pop() {
                    Some(back) => pc = back,
                    None => break,
                }
            }
            Opcode::Label => unreachable!("labels are entered after"),
            Opcode::Ifc | Opcode::BreakC | Opcode::BreakP => {
                unreachable!("data-dependent flow")
            }
            _ => {
                charge(pc);
                pc += 1;
            }
        }
    }
    Some((total, counts))
}

/// Executed instructions the property test lets the interpreter walk.
const BUDGET: u64 = 20_000_000;

fn assert_matches_brute_force(name: &str, l: &Loaded) -> Result<(), String> {
    let a = analyse(l);
    let Some((total, counts)) = brute_force_within(&l.shader, BUDGET) else {
        // Too long to walk: every instruction costs at least one slot, so
        // the model must say more than the budget too.
        return if a.executed.min > BUDGET {
            Err(String::new())
        } else {
            Err(format!("{name}: the interpreter ran past {BUDGET} instructions but the model says {:?}\n{}", a.executed, l.file.text))
        };
    };
    let mut problems = Vec::new();
    if a.executed != Range::exact(total) {
        problems.push(format!("executed {:?}, brute force {total}", a.executed));
    }
    for (i, (got, want)) in a.executions.iter().zip(&counts).enumerate() {
        if *got != Range::exact(*want) {
            let line = l.file.line_of(l.shader.instructions()[i].origin.span.start);
            problems.push(format!(
                "instruction {i} (line {line}: `{}`): executions {got:?}, brute force {want}",
                l.file.line_text(line).trim()
            ));
        }
    }
    if a.data_dependent || a.verdict == Verdict::MayExceed {
        problems.push("reported as data dependent".to_string());
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!("{name}:\n{}\n{}", problems.join("\n"), l.file.text))
    }
}

// ---------------------------------------------------------------------------
// Hand-written static programs for the brute-force comparison (each of
// them one of the counting rule's cases).

#[rustfmt::skip]
const STATIC_PROGRAMS: &[(&str, &str)] = &[
    ("doc example", "ps_3_0\ndefi i0, 128, 0, 0, 0\nmov r0, c0\nrep i0\n  add r0, r0, r0\nendrep\nmov oC0, r0\n"),
    ("zero-count rep", "ps_3_0\ndefi i0, 0, 0, 0, 0\nmov r0, c0\nrep i0\n  add r0, r0, r0\nendrep\nmov oC0, r0\n"),
    ("nested loops", "ps_3_0\ndefi i0, 3, 0, 0, 0\ndefi i1, 4, 1, 2, 0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\ndcl_texcoord3 v3\ndcl_texcoord5 v5\ndcl_texcoord7 v7\nmov r0, c0\nrep i0\n  loop aL, i1\n    add r0, r0, v[aL]\n  endloop\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("static if/else", "ps_3_0\ndefb b0, true\ndefb b1, false\nmov r1, c0\nmov r2, c0\nmov r3, c0\nif b0\n  nrm r0, r1\nelse\n  sincos r0.xy, r1.x\nendif\nif !b0\n  lrp r0, r1, r2, r3\nelse\n  pow r0, r1.x, r2.x\nendif\nif b1\n  mov r0, c0\nendif\nmov oC0, r0\n"),
    ("unconditional break", "ps_3_0\ndefi i0, 5, 0, 0, 0\nmov r0, c0\nrep i0\n  add r0, r0, c0\n  break\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("static break in the then-branch", "ps_3_0\ndefi i0, 5, 0, 0, 0\ndefb b0, true\nmov r0, c0\nrep i0\n  add r0, r0, c0\n  if b0\n    break\n  endif\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("static break in the else-branch", "ps_3_0\ndefi i0, 5, 0, 0, 0\ndefb b0, false\nmov r0, c0\nrep i0\n  add r0, r0, c0\n  if b0\n    nop\n  else\n    break\n  endif\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("static break not taken", "ps_3_0\ndefi i0, 5, 0, 0, 0\ndefb b0, false\nmov r0, c0\nrep i0\n  if b0\n    break\n  endif\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("break in an inner loop", "ps_3_0\ndefi i0, 3, 0, 0, 0\ndefi i1, 4, 0, 0, 0\nmov r0, c0\nrep i0\n  rep i1\n    add r0, r0, c0\n    break\n  endrep\n  mul r0, r0, c0\nendrep\nmov oC0, r0\n"),
    ("subroutines", "ps_3_0\ndefi i0, 2, 0, 0, 0\ndefb b0, true\ndefb b1, false\nmov r0, c0\nrep i0\n  call l0\n  callnz l1, b0\n  callnz l1, b1\nendrep\nmov oC0, r0\nret\nlabel l0\n  add r0, r0, c0\n  call l1\nret\nlabel l1\n  rep i0\n    mul r0, r0, c0\n  endrep\nret\n"),
    ("REPEAT_BLOCK in a loop", "ps_3_0\ndefi i0, 3, 0, 0, 0\nmov r0, c0\nrep i0\nBEGIN_REPEAT_BLOCK(4)\n  add r0, r0, c0\n  texkill r0\nEND_REPEAT_BLOCK\nendrep\nmov oC0, r0\n"),
    ("predication and cube", "ps_3_0\ndefi i0, 7, 0, 0, 0\ndcl_cube s0\nmov r1, c0\nrep i0\n  (p0.x) texld r0, r1, s0\n  texldl r0, r1, s0\nendrep\nmov oC0, r0\n"),
    ("ret at the end of main", "ps_3_0\nmov oC0, c0\nret\n"),
];

#[test]
fn hand_written_static_programs_match_the_brute_force_count() {
    let mut problems = Vec::new();
    for &(name, src) in STATIC_PROGRAMS {
        if let Err(p) = assert_matches_brute_force(name, &load(name, src)) {
            problems.push(if p.is_empty() {
                format!("{name}: too long")
            } else {
                p
            });
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n\n"));
}

#[test]
fn the_doc_example_and_the_article_figures() {
    // lib.rs: mov, then rep 3 + add 1 + endrep 2 per iteration, 128
    // times, then mov.
    let l = load("doc.psh", STATIC_PROGRAMS[0].1);
    let a = analyse(&l);
    assert_eq!(a.slots, 1 + 3 + 1 + 2 + 1);
    assert_eq!(a.executed, Range::exact(1 + 128 * 6 + 1));

    // The article's loop version with i1 = 128 (x) and i2 = 56 (y):
    // 4 + 56 * (3 + 128 * (3 + 1 + 1 + 1 + 1 + 2) + 1 + 2) + 1 = 64,853.
    let l = load(
        "lum_pass1_loop.psh",
        include_str!("../asm/article/lum_pass1_loop.psh"),
    );
    let mut env = Environment::default();
    env.ints.insert(1, [128, 0, 0, 0]);
    env.ints.insert(2, [56, 0, 0, 0]);
    let a = analyse_in(&l, &env);
    assert_eq!(a.executed, Range::exact(64_853));
    assert_eq!(a.verdict, Verdict::Within);
    let inner = a.loops.iter().find(|lp| lp.header == "rep i1").unwrap();
    assert_eq!(inner.cost_per_iteration, Range::exact(9));
    let outer = a.loops.iter().find(|lp| lp.header == "rep i2").unwrap();
    assert_eq!(outer.own_cost_per_iteration, Range::exact(6));

    // The unrolled version with i2 = 128: 5 + 128 * (3 + 125 * 4 + 1 + 2).
    let l = load(
        "lum_pass1_unrolled.psh",
        include_str!("../asm/article/lum_pass1_unrolled.psh"),
    );
    let mut env = Environment::default();
    env.ints.insert(2, [128, 0, 0, 0]);
    let a = analyse_in(&l, &env);
    assert_eq!(a.executed, Range::exact(64_773));
    assert_eq!(a.slots, 4 + 3 + 500 + 1 + 2 + 1);
}

// ---------------------------------------------------------------------------
// Random static programs.

use crate::common::program_gen;
use program_gen::random_program;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn symbolic_counts_equal_the_brute_force_counts(
        bytes in prop::collection::vec(any::<u8>(), 0..300)
    ) {
        let src = random_program(&bytes);
        let l = match load::load_str("random.psh", &src, &Options::default()) {
            Ok(l) => l,
            Err(e) => {
                return Err(TestCaseError::fail(format!(
                    "the generator made an invalid program:\n{}\n{src}",
                    e.diagnostics.render(&e.file)
                )))
            }
        };
        match assert_matches_brute_force("random", &l) {
            Ok(()) => {}
            // Too long to walk (and the model agrees): not a test case.
            Err(p) if p.is_empty() => return Err(TestCaseError::reject("too long")),
            Err(p) => return Err(TestCaseError::fail(p)),
        }
    }
}

// ---------------------------------------------------------------------------
// Data-dependent programs: shortest and longest paths.

#[test]
fn a_dynamic_branch_gives_both_paths() {
    let src = "ps_3_0
dcl_texcoord0 v0
if_gt v0.x, c0.x
  add r1, v0, v0
  add r1, r1, r1
  nrm r2, r1
else
  mov r1, c1
endif
mov oC0, r1
";
    let l = load("ifgt.psh", src);
    let a = analyse(&l);
    // Both paths pass if (3), else (1) and endif (1), then mov (1):
    // the else path adds mov (1), the then path add, add, nrm (5).
    assert_eq!(a.executed, Range { min: 7, max: 11 });
    assert!(a.data_dependent);
    assert!(
        a.reasons
            .iter()
            .any(|r| r.contains("line 3") && r.contains("dynamic branch")),
        "{:?}",
        a.reasons
    );
    assert_eq!(a.executions[index_on_line(&l, 4)], Range { min: 0, max: 1 });
    assert_eq!(a.executions[index_on_line(&l, 8)], Range { min: 0, max: 1 });
    assert_eq!(a.executions[index_on_line(&l, 3)], Range::exact(1));
    assert_eq!(a.executions[index_on_line(&l, 9)], Range::exact(1));
    assert_eq!(a.verdict, Verdict::Within);

    // The same on a predicate.
    let src = "ps_3_0\ndcl_texcoord0 v0\nsetp_gt p0.x, v0, c0\nif p0.x\n  sincos r1.xy, v0.x\nendif\nmov oC0.xy, r1\n";
    let a = analyse(&load("ifp.psh", src));
    assert_eq!(
        a.executed,
        Range {
            min: 1 + 3 + 1 + 1,
            max: 1 + 3 + 8 + 1 + 1
        }
    );
}

#[test]
fn a_data_dependent_break_gives_the_shortest_and_longest_path() {
    let src = "ps_3_0
defi i0, 5, 0, 0, 0
rep i0
  add r0, c0, c0
  break_gt r0.x, c1.x
  mul r1, r0, r0
endrep
mov oC0, r1
";
    let l = load("breakc.psh", src);
    let a = analyse(&l);
    // A full iteration: rep 3 + add 1 + break_gt 3 + mul 1 + endrep 2 = 10.
    // Breaking in an iteration: rep 3 + add 1 + break_gt 3 = 7.
    // Shortest: break at once, 7 + mov 1. Longest: never break, 5 * 10 + 1
    // (breaking in the last iteration gives 4 * 10 + 7 + 1 = 48, less).
    assert_eq!(a.executed, Range { min: 8, max: 51 });
    assert!(a.data_dependent);
    assert!(a.reasons.iter().any(|r| r.contains("data-dependent break")));
    let lp = &a.loops[0];
    assert_eq!(lp.iterations, Range::exact(5));
    assert_eq!(lp.cost_per_iteration, Range::exact(10));
    assert_eq!(lp.total, Range { min: 7, max: 50 });
    // Each instruction runs between its shortest and longest path count:
    // rep and add from once (a break in the first iteration) to 5 times,
    // mul and endrep from never to 5 times.
    assert_eq!(a.executions[index_on_line(&l, 3)], Range { min: 1, max: 5 });
    assert_eq!(a.executions[index_on_line(&l, 4)], Range { min: 1, max: 5 });
    assert_eq!(a.executions[index_on_line(&l, 5)], Range { min: 1, max: 5 });
    assert_eq!(a.executions[index_on_line(&l, 6)], Range { min: 0, max: 5 });
    assert_eq!(a.executions[index_on_line(&l, 7)], Range { min: 0, max: 5 });
    assert_eq!(a.executions[index_on_line(&l, 8)], Range::exact(1));

    // breakp the same way, with a body that is cheap after the break.
    let src =
        "ps_3_0\ndefi i0, 3, 0, 0, 0\nrep i0\n  breakp p0.x\n  nrm r0, c0\nendrep\nmov oC0, r0\n";
    let a = analyse(&load("breakp.psh", src));
    // Full: 3 + 3 + 3 + 2 = 11; break: 3 + 3 = 6.
    assert_eq!(
        a.executed,
        Range {
            min: 6 + 1,
            max: 3 * 11 + 1
        }
    );
}

#[test]
fn a_break_inside_a_dynamic_branch() {
    // In the then-branch: a breaking iteration is rep 3 + if 3 + break 1 = 7;
    // a full one rep 3 + if 3 + else 1 + add 1 + endif 1 + endrep 2 = 11.
    let src = "ps_3_0
defi i0, 4, 0, 0, 0
dcl_texcoord0 v0
rep i0
  if_gt v0.x, c0.x
    break
  else
    add r0, v0, c1
  endif
endrep
mov oC0, r0
";
    let l = load("then_break.psh", src);
    let a = analyse(&l);
    assert_eq!(
        a.executed,
        Range {
            min: 7 + 1,
            max: 4 * 11 + 1
        }
    );
    assert_eq!(a.executions[index_on_line(&l, 7)], Range { min: 0, max: 4 }); // else
    assert_eq!(a.executions[index_on_line(&l, 9)], Range { min: 0, max: 4 }); // endif

    // In the else-branch: the breaking path passes `else` before the break,
    // rep 3 + if 3 + else 1 + break 1 = 8.
    let src = "ps_3_0
defi i0, 4, 0, 0, 0
dcl_texcoord0 v0
rep i0
  if_gt v0.x, c0.x
    add r0, v0, c1
  else
    break
  endif
endrep
mov oC0, r0
";
    let l = load("else_break.psh", src);
    let a = analyse(&l);
    assert_eq!(
        a.executed,
        Range {
            min: 8 + 1,
            max: 4 * 11 + 1
        }
    );
    assert_eq!(a.executions[index_on_line(&l, 7)], Range { min: 1, max: 4 }); // else
    assert_eq!(a.executions[index_on_line(&l, 9)], Range { min: 0, max: 4 }); // endif
    assert_eq!(a.executions[index_on_line(&l, 4)], Range { min: 1, max: 4 }); // rep
}

#[test]
fn unknown_constants_give_ranges_and_say_how_to_fix_them() {
    let src = "ps_3_0\nrep i3\n  add r0, c0, c0\nendrep\nmov oC0, r0\n";
    let l = load("unknown.psh", src);
    let a = analyse(&l);
    // 0 iterations: rep charged once (3) + mov (1); 255: 255 * 6 + 1.
    assert_eq!(
        a.executed,
        Range {
            min: 4,
            max: 255 * 6 + 1
        }
    );
    assert!(a.data_dependent);
    assert!(
        a.reasons
            .iter()
            .any(|r| r.contains("i3") && r.contains("--int")),
        "{:?}",
        a.reasons
    );
    // Given on the command line, the count is exact.
    let mut env = Environment::default();
    env.ints.insert(3, [10, 0, 0, 0]);
    let a = analyse_in(&l, &env);
    assert_eq!(a.executed, Range::exact(10 * 6 + 1));
    assert!(a.reasons.is_empty(), "{:?}", a.reasons);
    // A defi in the shader wins over the environment.
    let l = load(
        "defined.psh",
        "ps_3_0\ndefi i3, 2, 0, 0, 0\nrep i3\n  add r0, c0, c0\nendrep\nmov oC0, r0\n",
    );
    assert_eq!(analyse_in(&l, &env).executed, Range::exact(2 * 6 + 1));
    // An out-of-range constant from the environment is an error.
    let mut env = Environment::default();
    env.ints.insert(3, [256, 0, 0, 0]);
    let l = load("unknown.psh", src);
    let e = cost::analyse(&l.shader, &l.file, &env, &Profile::ps_3_0()).unwrap_err();
    assert!(e.0.contains("i3"), "{e}");

    // An unknown b# considers both branches and says --bool.
    let src = "ps_3_0\nif b2\n  nrm r0, c0\nendif\nmov oC0, r0\n";
    let l = load("unknown_b.psh", src);
    let a = analyse(&l);
    assert_eq!(
        a.executed,
        Range {
            min: 3 + 1 + 1,
            max: 3 + 3 + 1 + 1
        }
    );
    assert!(
        a.reasons
            .iter()
            .any(|r| r.contains("b2") && r.contains("--bool")),
        "{:?}",
        a.reasons
    );
    let mut env = Environment::default();
    env.bools.insert(2, true);
    assert_eq!(analyse_in(&l, &env).executed, Range::exact(8));
    env.bools.insert(2, false);
    assert_eq!(analyse_in(&l, &env).executed, Range::exact(5));
}

// ---------------------------------------------------------------------------
// Big counts by formula.

#[test]
fn a_four_deep_nest_of_rep_255_is_counted_by_formula() {
    let src = "ps_3_0
defi i0, 255, 0, 0, 0
rep i0
  rep i0
    rep i0
      rep i0
        add r0, c0, c0
      endrep
    endrep
  endrep
endrep
mov oC0, r0
";
    let l = load("nest.psh", src);
    let a = analyse(&l);
    let n: u64 = 255;
    // Innermost loop: n iterations of rep 3 + add 1 + endrep 2.
    let t1 = n * 6;
    // Each outer level: n iterations of rep 3 + inner loop + endrep 2.
    let t2 = n * (3 + t1 + 2);
    let t3 = n * (3 + t2 + 2);
    let t4 = n * (3 + t3 + 2);
    assert_eq!(a.executed, Range::exact(t4 + 1));
    assert_eq!(t4 + 1, 25_452_737_026);
    assert_eq!(a.slots, 4 * 3 + 1 + 4 * 2 + 1);
    assert_eq!(a.executions[index_on_line(&l, 7)], Range::exact(n.pow(4)));
    assert_eq!(a.executions[index_on_line(&l, 6)], Range::exact(n.pow(4)));
    assert_eq!(a.executions[index_on_line(&l, 3)], Range::exact(n));
    assert_eq!(a.verdict, Verdict::Exceeds);

    // The same nest written with REPEAT_BLOCK bodies and a loop: still
    // closed-form, still exact.
    let src = "ps_3_0
defi i0, 255, 0, 0, 0
defi i1, 255, 0, 1, 0
dcl_texcoord0 v0
dcl_texcoord1 v1
dcl_texcoord2 v2
dcl_texcoord3 v3
dcl_texcoord4 v4
dcl_texcoord5 v5
dcl_texcoord6 v6
dcl_texcoord7 v7
dcl_texcoord8 v8
dcl_texcoord9 v9
loop aL, i1
  rep i0
    rep i0
      rep i0
        BEGIN_REPEAT_BLOCK(3)
        add r0, c0, v[aL]
        END_REPEAT_BLOCK
      endrep
    endrep
  endrep
endloop
mov oC0, r0
";
    let a = analyse(&load("nest2.psh", src));
    let t1 = n * (3 + 3 + 2);
    let t2 = n * (3 + t1 + 2);
    let t3 = n * (3 + t2 + 2);
    let t4 = n * (3 + t3 + 2);
    assert_eq!(a.executed, Range::exact(t4 + 1));
}

#[test]
fn the_deepest_nesting_counts_exactly_and_deeper_is_refused() {
    // rep 255 four deep in main and in each of four nested subroutines
    // would run the innermost nop 255^20 times, far beyond u64; Microsoft's
    // validator counts the loops around a call toward the subroutine's
    // nesting (X5827), so such a shader is refused and counts stay exact.
    let mut src = String::from("ps_3_0\ndefi i0, 255, 0, 0, 0\n");
    for _ in 0..4 {
        src.push_str("rep i0\n");
    }
    src.push_str("call l0\n");
    for _ in 0..4 {
        src.push_str("endrep\n");
    }
    src.push_str("ret\n");
    for label in 0..4 {
        src.push_str(&format!("label l{label}\n"));
        for _ in 0..4 {
            src.push_str("rep i0\n");
        }
        if label < 3 {
            src.push_str(&format!("call l{}\n", label + 1));
        } else {
            src.push_str("nop\n");
        }
        for _ in 0..4 {
            src.push_str("endrep\n");
        }
        src.push_str("ret\n");
    }
    let e = ps30::core::load::load_str("huge.psh", &src, &Options::default())
        .expect_err("loops nested 20 deep through calls");
    assert_eq!(e.diagnostics.errors().next().unwrap().code, Some("X5827"));
    // The deepest allowed: four loops of 255 around a chain of calls.
    let src = "ps_3_0\ndefi i0, 255, 0, 0, 0\nrep i0\nrep i0\nrep i0\nrep i0\ncall l0\nendrep\nendrep\nendrep\nendrep\nret\nlabel l0\ncall l1\nret\nlabel l1\nnop\nret\n";
    let a = analyse(&load("deep.psh", src));
    assert!(a.executed.max > u64::from(u32::MAX), "{:?}", a.executed);
    assert_eq!(a.executed.min, a.executed.max);
    assert_eq!(a.verdict, Verdict::Exceeds);
}

/// The interpreter itself agrees with numbers worked out by hand, so a
/// mismatch in the property test is the model's.
#[test]
fn the_brute_force_interpreter_agrees_with_hand_counts() {
    // Each program starts with a `mov` (1) that writes the temporaries it
    // reads.
    let cases: &[(&str, u64)] = &[
        // mov 1, 128 * (3 + 1 + 2), mov 1
        (STATIC_PROGRAMS[0].1, 770),
        // mov 1, rep once (3), mov (1)
        (STATIC_PROGRAMS[1].1, 5),
        // mov 1, rep 3 + add 1 + break 1, then mov 1
        (STATIC_PROGRAMS[4].1, 7),
        // mov 1, rep 3 + add 1 + if 3 + break 1, then mov 1
        (STATIC_PROGRAMS[5].1, 10),
        // mov 1, rep 3 + add 1 + if 3 + else 1 + break 1, then mov 1
        (STATIC_PROGRAMS[6].1, 11),
        // three movs (3);
        // if b0 (true): if 3 + nrm 3 + else 1 + endif 1 = 8;
        // if !b0 (false): if 3 + else 1 + pow 3 + endif 1 = 8;
        // if b1 (false, no else): if 3 + endif 1 = 4; mov 1.
        (STATIC_PROGRAMS[3].1, 24),
        // mov 1, 3 * (rep 3 + inner (rep 3 + add 1 + break 1) + mul 1 + endrep 2) + mov 1
        (STATIC_PROGRAMS[8].1, 1 + 3 * (3 + 5 + 1 + 2) + 1),
    ];
    for &(src, want) in cases {
        let l = load("hand.psh", src);
        assert_eq!(brute_force(&l.shader).0, want, "{src}");
    }
}

// ---------------------------------------------------------------------------
// The emulator counts what the cost model counts.

/// Runs a shader on a 2×2 target with every declared input and sampler
/// bound, and returns each pixel's executed slots.
fn emulated_counts(l: &Loaded) -> Result<Vec<u64>, String> {
    use ps30::core::emu::{self, Draw, LinearInput, SamplerState, Texture};
    let compiled = emu::compile(&l.shader).map_err(|e| e.to_string())?;
    let mut draw = Draw::new(2, 2);
    for d in &l.shader.program().inputs {
        if d.reg.file == ps30::core::isa::RegFile::Input {
            draw.inputs
                .push((d.reg.index, LinearInput::constant([0.25, 0.5, 0.75, 1.0])));
        }
    }
    let texels = [[0.5f32; 4]; 4];
    // Only 2D textures are emulated; other samplers stay unbound and read
    // (0, 0, 0, 1), which does not change any count.
    for s in l
        .shader
        .program()
        .samplers
        .iter()
        .filter(|s| s.ty == ps30::core::isa::SamplerType::Tex2d)
    {
        let tex = Texture {
            width: 2,
            height: 2,
            texels: &texels,
        };
        draw.samplers
            .push((s.index, tex.into(), SamplerState::default()));
    }
    let out = emu::run_with_threads(&compiled, &draw, 1).map_err(|e| e.to_string())?;
    Ok(out.executed)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn the_emulator_counts_what_the_cost_model_counts(
        bytes in prop::collection::vec(any::<u8>(), 0..300)
    ) {
        let src = random_program(&bytes);
        let l = load::load_str("random.psh", &src, &Options::default())
            .map_err(|e| TestCaseError::fail(e.diagnostics.render(&e.file)))?;
        let a = analyse(&l);
        prop_assume!(a.executed.max <= 2_000_000);
        let counts = emulated_counts(&l).map_err(TestCaseError::fail)?;
        for c in counts {
            prop_assert!(
                a.executed.min <= c && c <= a.executed.max,
                "emulator counted {c}, cost model {:?}\n{src}",
                a.executed
            );
            if a.executed.is_exact() {
                prop_assert_eq!(c, a.executed.min, "{}", src);
            }
        }
    }
}

#[test]
fn a_break_in_the_else_branch_costs_the_same_in_both_counters() {
    let l = load(
        "else_break.psh",
        "ps_3_0\ndef c0, 1, 1, 1, 1\ndefi i0, 3, 0, 0, 0\ndefb b0, false\nrep i0\n  if b0\n    add r0, c0, c0\n  else\n    break\n  endif\n  add r0, r0, c0\nendrep\nmov oC0, r0\n",
    );
    // rep 3 + if 3 + else 1 + break 1, once; then mov 1.
    assert_eq!(analyse(&l).executed.max, 9);
    assert_eq!(emulated_counts(&l).unwrap(), vec![9; 4]);
}
