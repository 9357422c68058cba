//! Flow-control nesting as Microsoft's validator counts it, per profile and
//! through calls.
//!
//! Each instruction adds to one or more depths (Microsoft's "Flow Control
//! Limitations" tables): `rep`/`loop` to the loop depth; `if b#` to the
//! static-`if` depth; `if_comp` and `if p0` to the dynamic depth; `call` and
//! `callnz` to the call depth, `callnz p0` to the dynamic depth as well
//! (until its `ret`); `break_comp` to the dynamic depth for itself alone. A
//! subroutine runs at the depths of the call that reaches it, so a block in
//! it counts on top of the blocks open around that call (measured: 24
//! nested `if_gt` around a `call` to a subroutine holding one more `if_gt`
//! are refused at that inner `if_gt`, in every profile with dynamic flow).
//! Microsoft's validator stops at the first depth exceeded ("Aborting
//! shader validation"), so [`check`] reports the first one in program
//! order, with the profile's own code: each profile numbers these refusals
//! apart ([`Codes::of`], measured on every profile that has flow control).

use crate::core::diag::codes::Code;
use crate::core::diag::{Diagnostic, Diagnostics, SourceFile};
use crate::core::ir::{Instruction, Program};
use crate::core::isa::{Opcode, RegFile};
use crate::core::profile::{Profile, Ps2xCaps};
use std::collections::BTreeMap;

/// The deepest each kind of block may nest; 0 for a kind the profile (or a
/// device's capabilities) lacks, which is refused elsewhere.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// `rep` and `loop`.
    pub loops: u32,
    /// `call` and `callnz`.
    pub calls: u32,
    /// `if b#`.
    pub static_ifs: u32,
    /// `if_comp`, `if p0`, `callnz p0` and, for itself, `break_comp`.
    pub dynamic: u32,
    /// Whether the depths are a device's capabilities (`--caps`) rather
    /// than the profile's: the refusal's text says which.
    pub caps: bool,
}

impl Limits {
    /// What Microsoft's assembler holds `profile` to (ps_2_x: every
    /// capability on, [`Ps2xCaps::ASSEMBLER`]).
    pub fn of(profile: Profile) -> Limits {
        match profile {
            Profile::Ps2X => Limits {
                caps: false,
                ..Limits::under(Ps2xCaps::ASSEMBLER)
            },
            // vs_2_0: one loop and one call deep (measured: X5829, X5861)
            Profile::Vs2_0 => Limits {
                loops: 1,
                calls: 1,
                static_ifs: 24,
                dynamic: 24,
                caps: false,
            },
            _ => Limits {
                loops: 4,
                calls: 4,
                static_ifs: 24,
                dynamic: 24,
                caps: false,
            },
        }
    }

    /// ps_2_x under a device's capabilities: `StaticFlowControlDepth`
    /// bounds loops and, apart, calls; static `if`s nest 24 deep wherever
    /// there is static flow control; `DynamicFlowControlDepth` bounds the
    /// dynamic depth.
    pub fn under(caps: Ps2xCaps) -> Limits {
        Limits {
            loops: caps.static_flow_depth,
            calls: caps.static_flow_depth,
            static_ifs: if caps.static_flow_depth > 0 { 24 } else { 0 },
            dynamic: caps.dynamic_flow_depth,
            caps: true,
        }
    }
}

/// A profile's codes for each depth exceeded.
#[derive(Clone, Copy, Debug)]
pub struct Codes {
    loops: Code,
    calls: Code,
    static_if: Code,
    predicate_if: Code,
    dynamic_if: Code,
    break_comp: Code,
    callnz_predicate: Code,
}

impl Codes {
    /// Measured with `D3DAssemble` (one probe per kind and profile).
    pub fn of(profile: Profile) -> Codes {
        let c =
            |loops, calls, static_if, predicate_if, dynamic_if, break_comp, callnz_predicate| {
                Codes {
                    loops,
                    calls,
                    static_if,
                    predicate_if,
                    dynamic_if,
                    break_comp,
                    callnz_predicate,
                }
            };
        match profile {
            Profile::Ps2X => c(
                "X5493", "X5843", "X5847", "X5846", "X5849", "X5880", "X6048",
            ),
            Profile::Vs2_0 | Profile::Vs2X => c(
                "X5829", "X5861", "X5868", "X5865", "X5871", "X5557", "X6053",
            ),
            Profile::Vs3_0 => c(
                "X5830", "X5873", "X5878", "X5876", "X5575", "X5701", "X6055",
            ),
            _ => c(
                "X5827", "X5851", "X5856", "X5854", "X5858", "X5614", "X6050",
            ),
        }
    }
}

/// Gives the nesting refusals the validator words with ps_3_0's codes
/// (its depth checks within a function, loops and calls through calls) the
/// codes of `profile`, and their text the profile's name.
pub fn own_codes(profile: Profile, diags: &mut Diagnostics) {
    use crate::core::diag::codes;
    let own = Codes::of(profile);
    for d in &mut diags.items {
        d.code = d.code.map(|c| match c {
            codes::LOOP_DEPTH => own.loops,
            codes::CALL_DEPTH => own.calls,
            codes::STATIC_IF_DEPTH => own.static_if,
            codes::PREDICATE_IF_DEPTH => own.predicate_if,
            codes::DYNAMIC_IF_DEPTH => own.dynamic_if,
            other => other,
        });
        if profile != Profile::Ps3_0 {
            d.message = d
                .message
                .replace("ps_3_0 allows", &format!("{profile} allows"));
        }
    }
}

/// Whether `code` is one of the validator's own nesting refusals (before
/// [`own_codes`]).
pub fn is_depth_code(code: Code) -> bool {
    use crate::core::diag::codes;
    [
        codes::LOOP_DEPTH,
        codes::CALL_DEPTH,
        codes::STATIC_IF_DEPTH,
        codes::PREDICATE_IF_DEPTH,
        codes::DYNAMIC_IF_DEPTH,
    ]
    .contains(&code)
}

/// The depths open at a point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Depths {
    loops: u32,
    calls: u32,
    static_ifs: u32,
    dynamic: u32,
}

impl Depths {
    fn plus(self, o: Depths) -> Depths {
        Depths {
            loops: self.loops.saturating_add(o.loops),
            calls: self.calls.saturating_add(o.calls),
            static_ifs: self.static_ifs.saturating_add(o.static_ifs),
            dynamic: self.dynamic.saturating_add(o.dynamic),
        }
    }

    fn max(self, o: Depths) -> Depths {
        Depths {
            loops: self.loops.max(o.loops),
            calls: self.calls.max(o.calls),
            static_ifs: self.static_ifs.max(o.static_ifs),
            dynamic: self.dynamic.max(o.dynamic),
        }
    }
}

fn on_predicate(ins: &Instruction) -> bool {
    ins.src.iter().any(|s| s.reg.file == RegFile::Predicate)
}

/// What `ins` opens, as depths (an `if`'s kind, a loop, a call).
fn opens(ins: &Instruction) -> Depths {
    let one = Depths::default();
    match ins.op {
        Opcode::Rep | Opcode::Loop => Depths { loops: 1, ..one },
        Opcode::If if !on_predicate(ins) => Depths {
            static_ifs: 1,
            ..one
        },
        Opcode::If | Opcode::Ifc | Opcode::BreakC => Depths { dynamic: 1, ..one },
        Opcode::Call => Depths { calls: 1, ..one },
        Opcode::CallNz => Depths {
            calls: 1,
            dynamic: u32::from(on_predicate(ins)),
            ..one
        },
        _ => one,
    }
}

/// The first depth exceeded, with the profile's code (see the module
/// docs), or `None`.
pub fn check(p: &Program, limits: Limits, file: &SourceFile) -> Option<Diagnostic> {
    let codes = Codes::of(p.profile);
    // Pass 1: each instruction's routine (None for main), the depths open
    // around it within its routine, and the calls.
    let mut owner: Option<u32> = None;
    // the blocks open (each with what it added) and their sum
    let mut stack: Vec<Depths> = Vec::new();
    let mut around = Depths::default();
    let mut local = Vec::with_capacity(p.instructions.len());
    let mut routines: Vec<Option<u32>> = vec![None];
    for ins in &p.instructions {
        if ins.op == Opcode::Label {
            owner = ins.src.first().map(|s| s.reg.index);
            routines.push(owner);
            (stack, around) = (Vec::new(), Depths::default());
        }
        local.push((owner, around));
        match ins.op {
            Opcode::Rep | Opcode::Loop | Opcode::If | Opcode::Ifc => {
                stack.push(opens(ins));
                around = around.plus(opens(ins));
            }
            Opcode::EndRep | Opcode::EndLoop | Opcode::EndIf => {
                if let Some(d) = stack.pop() {
                    around = Depths {
                        loops: around.loops - d.loops,
                        calls: around.calls - d.calls,
                        static_ifs: around.static_ifs - d.static_ifs,
                        dynamic: around.dynamic - d.dynamic,
                    };
                }
            }
            _ => {}
        }
    }
    // Pass 2: the depths each routine starts at, from its callers (defined
    // before it: calls go forward, and a backward one is refused elsewhere).
    let mut sites: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
    for (i, ins) in p.instructions.iter().enumerate() {
        if let (Opcode::Call | Opcode::CallNz, Some(s)) = (ins.op, ins.src.first()) {
            sites.entry(s.reg.index).or_default().push(i);
        }
    }
    let mut entry: BTreeMap<Option<u32>, Depths> = BTreeMap::new();
    entry.insert(None, Depths::default());
    for &routine in &routines[1..] {
        let mut at = Depths::default();
        for &i in routine.and_then(|l| sites.get(&l)).into_iter().flatten() {
            let (o, around) = local[i];
            if let Some(&start) = entry.get(&o) {
                at = at.max(start.plus(around).plus(opens(&p.instructions[i])));
            }
        }
        entry.entry(routine).or_insert(at);
    }
    // Pass 3: the first instruction that takes a depth past its limit.
    for (ins, &(o, around)) in p.instructions.iter().zip(&local) {
        let start = entry.get(&o).copied().unwrap_or_default();
        let open = opens(ins);
        let d = start.plus(around).plus(open);
        let predicate = on_predicate(ins);
        let exceeded = [
            (open.loops, d.loops, limits.loops, codes.loops, "loop"),
            (
                open.calls,
                d.calls,
                limits.calls,
                codes.calls,
                "subroutine call",
            ),
            (
                open.static_ifs,
                d.static_ifs,
                limits.static_ifs,
                codes.static_if,
                "static 'if'",
            ),
            (
                open.dynamic,
                d.dynamic,
                limits.dynamic,
                match ins.op {
                    Opcode::BreakC => codes.break_comp,
                    Opcode::CallNz => codes.callnz_predicate,
                    _ if predicate => codes.predicate_if,
                    _ => codes.dynamic_if,
                },
                "dynamic 'if'",
            ),
        ]
        .into_iter()
        .find(|&(opened, depth, limit, _, _)| opened > 0 && limit > 0 && depth > limit);
        if let Some((_, depth, limit, code, what)) = exceeded {
            let why = match ins.op {
                Opcode::BreakC => " (a break_comp counts as one more dynamic level)",
                Opcode::CallNz if predicate && what == "dynamic 'if'" => {
                    " (a callnz on p0 counts as a dynamic level)"
                }
                _ => "",
            };
            let through = if start != Depths::default() {
                ", counting the blocks open around the calls that reach this subroutine"
            } else {
                ""
            };
            return Some(
                Diagnostic::coded(
                    code,
                    ins.origin.span,
                    format!(
                        "{what} nesting {depth} deep{why}; {} {limit}",
                        if limits.caps {
                            "the capabilities allow".to_string()
                        } else {
                            format!("{} allows", p.profile)
                        }
                    ),
                )
                .with_label(format!("too deep{through}"))
                .in_origin(&ins.origin, file),
            );
        }
    }
    None
}
