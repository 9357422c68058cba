//! The cost model: static instruction slots and executed instruction slots,
//! computed from the validated IR (never from text).
//!
//! # The counting rule
//!
//! Microsoft's documentation gives each instruction a slot cost but does not
//! say how "executed instructions" (`MaxPShaderInstructionsExecuted`) are
//! counted. ps30 uses the rule that reproduces every figure of the article
//! (9 cycles per x pixel, 6 per y line, 64,853 for a 128×56 block):
//!
//! * every executed instruction is charged its static slots under the
//!   profile's [`SlotTable`] (Microsoft's count by default, or the documented
//!   table; predication adds one, and in the documented table cube samplers
//!   cost more — see [`crate::core::isa`]). Static slots and executed counts
//!   always use the same table (`Ctx::slots` is the one place it is read);
//! * `rep`/`loop` and `endrep`/`endloop` are charged **once per iteration**
//!   (3 + 2 slots), not once per entry; a loop that runs 0 times is charged
//!   its `rep`/`loop` slots once;
//! * `if` and `endif` are charged each time the `if` is reached, and so is
//!   `else` when there is one (both paths pass it) — except that a `break`
//!   inside a branch leaves before `endif` (and, from the then-branch,
//!   before `else`);
//! * a `break` that leaves a loop charges its own slots and skips the rest of
//!   that iteration, `endrep`/`endloop` included;
//! * `call` charges its slots, the callee and the callee's `ret`; `label` is
//!   free; `ret` in main charges 1 and ends the shader.
//!
//! The analysis is symbolic: a loop's cost is its per-iteration cost times its
//! count, and a subroutine is analysed once whatever the number of its call
//! sites (its entries are summed over them), so the running time does not
//! grow with iteration counts or call paths. Where the
//! count depends on data (dynamic branches, breaks, unknown constants) the
//! model gives the shortest and the longest path instead of one number.

use crate::core::diag::SourceFile;
use crate::core::ir::{Shader, SrcMod};
use crate::core::isa::{Opcode, RegFile, SlotCount, SlotTable};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// A budget: what a ps_3_0 part allows. In JSON it is a `limits` object,
/// `{"name", "slots", "executed", "rep_count", "loop_nesting"}`, the shape
/// every command uses for limits (`docs/json-schema/ps30.json`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Profile {
    /// The profile's name (`ps_3_0`).
    pub name: String,
    /// Static instruction slots.
    #[serde(rename = "slots")]
    pub max_slots: u64,
    /// Executed instruction slots per pixel.
    #[serde(rename = "executed")]
    pub max_executed: u64,
    /// rep/loop iteration count range (i#.x in 0..=max).
    #[serde(rename = "rep_count")]
    pub max_rep_count: u32,
    /// rep/loop nesting depth.
    #[serde(rename = "loop_nesting")]
    pub max_loop_nesting: u32,
    /// The per-instruction slot table counts use (static slots, executed
    /// counts, the verdict). Not part of the `limits` object: commands that
    /// report it name it beside.
    #[serde(skip)]
    pub slot_table: SlotTable,
    /// The capabilities a ps_2_x shader is held to (`--caps`): their slot
    /// count is a ps_2_x shader's budget, in place of the assembler's 512.
    #[serde(skip)]
    pub ps2x_caps: Option<crate::core::profile::Ps2xCaps>,
}

impl Profile {
    /// The article's ps_3_0 budget: 512 slots, 65,535 executed instructions.
    /// (Microsoft's ps_3_0 page says "at least 2^16" executed; the article and
    /// several drivers use 65,535.)
    pub fn ps_3_0() -> Profile {
        Profile {
            name: "ps_3_0".to_string(),
            max_slots: 512,
            max_executed: 65_535,
            max_rep_count: crate::core::isa::MAX_REP_COUNT as u32,
            max_loop_nesting: crate::core::isa::MAX_LOOP_NESTING,
            slot_table: SlotTable::default(),
            ps2x_caps: None,
        }
    }

    /// This budget for a shader of `p`: the profile's name, and its slot
    /// and executed limits where they are lower (ps_2_0's 96 slots,
    /// vs_2_0's 256 and 1,024 executed; a ps_2_x shader's slots those of
    /// [`Profile::ps2x_caps`] when set).
    pub fn for_profile(self, p: crate::core::profile::Profile) -> Profile {
        if p == crate::core::profile::Profile::Ps3_0 {
            return self;
        }
        let limits = p.limits();
        let lower = |ours: u64, theirs: Option<u32>| theirs.map_or(ours, |t| ours.min(t.into()));
        let slots = match (p, self.ps2x_caps) {
            (crate::core::profile::Profile::Ps2X, Some(caps)) => Some(caps.slots),
            _ => limits.slots,
        };
        Profile {
            name: p.name().to_string(),
            max_slots: lower(self.max_slots, slots),
            max_executed: lower(self.max_executed, limits.executed),
            ..self
        }
    }

    /// This profile, counting with `table`.
    pub fn counting(self, table: SlotTable) -> Profile {
        Profile {
            slot_table: table,
            ..self
        }
    }
}

/// Application-set constants the analysis may use (`--int`, `--bool`).
#[derive(Clone, Debug, Default)]
pub struct Environment {
    /// `i#` values by register number (x is the loop count).
    pub ints: BTreeMap<u32, [i32; 4]>,
    /// `b#` values by register number.
    pub bools: BTreeMap<u32, bool>,
}

/// A closed range of counts; `min == max` when exact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Range {
    /// The shortest path's count.
    pub min: u64,
    /// The longest path's count.
    pub max: u64,
}

impl Range {
    /// The range as `64,853` or `1,000–2,000`, saturated ends as
    /// [`count`](crate::core::numbers::count) spells them.
    pub fn text(self) -> String {
        use crate::core::numbers::count;
        if self.is_exact() {
            count(self.min)
        } else {
            format!("{}–{}", count(self.min), count(self.max))
        }
    }
}

impl Range {
    /// Nothing on every path.
    pub const ZERO: Range = Range { min: 0, max: 0 };

    /// The same count on every path.
    pub fn exact(v: u64) -> Range {
        Range { min: v, max: v }
    }

    /// Whether every path gives the same count.
    pub fn is_exact(self) -> bool {
        self.min == self.max
    }

    fn add(self, o: Range) -> Range {
        Range {
            min: self.min.saturating_add(o.min),
            max: self.max.saturating_add(o.max),
        }
    }

    fn mul(self, o: Range) -> Range {
        Range {
            min: self.min.saturating_mul(o.min),
            max: self.max.saturating_mul(o.max),
        }
    }

    fn union(self, o: Range) -> Range {
        Range {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }
}

/// How often the end of a sequence with `paths` is reached when it starts
/// `mult` times (what `Ctx::seq` leaves its multiplicity at).
fn reach(paths: &Paths, mult: Range) -> Range {
    match paths.fall {
        None => Range::ZERO,
        Some(_) if paths.brk.is_some() || paths.exit.is_some() => Range {
            min: 0,
            max: mult.max,
        },
        Some(_) => mult,
    }
}

fn add_opt(a: Option<Range>, b: Option<Range>) -> Option<Range> {
    Some(a?.add(b?))
}

fn union_opt(a: Option<Range>, b: Option<Range>) -> Option<Range> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.union(b)),
        (a, None) => a,
        (None, b) => b,
    }
}

/// Costs of the ways control can leave a piece of code.
#[derive(Clone, Copy, Debug)]
struct Paths {
    /// Falls through to what follows.
    fall: Option<Range>,
    /// Leaves the innermost loop through a break.
    brk: Option<Range>,
    /// Ends the shader (`ret` in main).
    exit: Option<Range>,
}

impl Paths {
    fn fall(r: Range) -> Paths {
        Paths {
            fall: Some(r),
            brk: None,
            exit: None,
        }
    }

    /// `self` followed by `next`.
    fn then(self, next: Paths) -> Paths {
        Paths {
            fall: add_opt(self.fall, next.fall),
            brk: union_opt(self.brk, add_opt(self.fall, next.brk)),
            exit: union_opt(self.exit, add_opt(self.fall, next.exit)),
        }
    }

    fn union(self, o: Paths) -> Paths {
        Paths {
            fall: union_opt(self.fall, o.fall),
            brk: union_opt(self.brk, o.brk),
            exit: union_opt(self.exit, o.exit),
        }
    }

    fn shift(self, r: Range) -> Paths {
        Paths {
            fall: self.fall.map(|f| f.add(r)),
            brk: self.brk.map(|f| f.add(r)),
            exit: self.exit.map(|f| f.add(r)),
        }
    }
}

/// The structured form of a flat instruction range.
#[derive(Clone, Debug)]
enum Node {
    Ins(usize),
    Loop {
        head: usize,
        end: usize,
        body: Vec<Node>,
    },
    If(IfNode),
}

/// An `if` … [`else` …] `endif` block.
#[derive(Clone, Debug)]
struct IfNode {
    head: usize,
    else_at: Option<usize>,
    end: usize,
    then: Vec<Node>,
    els: Vec<Node>,
}

fn build(shader: &Shader, mut i: usize, stop: usize) -> (Vec<Node>, usize) {
    let info = shader.info();
    let ins = shader.instructions();
    let mut out = Vec::new();
    while i < stop {
        match ins[i].op {
            Opcode::Rep | Opcode::Loop => {
                let end = info.matching[i].map_or(stop, |e| e as usize);
                let (body, _) = build(shader, i + 1, end);
                out.push(Node::Loop { head: i, end, body });
                i = end + 1;
            }
            Opcode::If | Opcode::Ifc => {
                let first = info.matching[i].map_or(stop, |e| e as usize);
                let (then, _) = build(shader, i + 1, first);
                let (else_at, end, els) = if ins.get(first).map(|x| x.op) == Some(Opcode::Else) {
                    let end = info.matching[first].map_or(stop, |e| e as usize);
                    (Some(first), end, build(shader, first + 1, end).0)
                } else {
                    (None, first, Vec::new())
                };
                out.push(Node::If(IfNode {
                    head: i,
                    else_at,
                    end,
                    then,
                    els,
                }));
                i = end + 1;
            }
            _ => {
                out.push(Node::Ins(i));
                i += 1;
            }
        }
    }
    (out, i)
}

/// What is wrong with an integer constant used by `rep`/`loop`, if anything
/// (Microsoft's rep and loop pages: count 0..255, start 0..255, step −128..127).
pub fn int_constant_problem(op: Opcode, v: [i32; 4]) -> Option<String> {
    let max = crate::core::isa::MAX_REP_COUNT;
    if !(0..=max).contains(&v[0]) {
        return Some(format!(
            "the iteration count (.x = {}) must be in 0..={max}",
            v[0]
        ));
    }
    if op == Opcode::Loop {
        if !(0..=255).contains(&v[1]) {
            return Some(format!("the loop start (.y = {}) must be in 0..=255", v[1]));
        }
        if !(-128..=127).contains(&v[2]) {
            return Some(format!(
                "the loop step (.z = {}) must be in -128..=127",
                v[2]
            ));
        }
    }
    None
}

/// Cost of one source line.
#[derive(Clone, Debug, Serialize)]
pub struct LineCost {
    /// The line number (1-based).
    pub line: usize,
    /// The line's source text.
    pub text: String,
    /// Static slots of the instructions on this line (all REPEAT_BLOCK copies).
    pub slots: u64,
    /// How many instructions from this line run, in all.
    pub executions: Range,
    /// Executed slots charged to this line.
    pub executed: Range,
}

/// Cost of one rep/loop.
#[derive(Clone, Debug, Serialize)]
pub struct LoopCost {
    /// The line of the `rep`/`loop` (1-based).
    pub line: usize,
    /// `rep i2`, `loop aL, i0`.
    pub header: String,
    /// Iterations per entry.
    pub iterations: Range,
    /// How many times the loop is entered.
    pub entries: Range,
    /// One iteration including its own rep/endrep and nested loops.
    pub cost_per_iteration: Range,
    /// One iteration's own cost: rep + endrep + the body outside nested loops.
    pub own_cost_per_iteration: Range,
    /// Executed slots of the loop over the whole run.
    pub total: Range,
}

/// Whether the program fits its profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Every path fits both limits.
    Within,
    /// Some data-dependent path exceeds the executed limit.
    MayExceed,
    /// Even the shortest path, or the static slots, exceed a limit.
    Exceeds,
}

/// The full analysis of a shader under a profile.
#[derive(Clone, Debug, Serialize)]
pub struct Analysis {
    /// Static instruction slots under the profile's table.
    pub slots: u64,
    /// The same static slots split into texture and arithmetic, as
    /// Microsoft's listing splits them.
    pub split: SlotCount,
    /// Executed instruction slots per pixel, shortest and longest path.
    pub executed: Range,
    /// Whether the executed count depends on data (then `reasons` say why).
    pub data_dependent: bool,
    /// Why counts are ranges (unknown constants, dynamic branches, breaks).
    pub reasons: Vec<String>,
    /// Every source line with its cost.
    pub lines: Vec<LineCost>,
    /// Every rep/loop with its cost.
    pub loops: Vec<LoopCost>,
    /// The limits the shader was measured against.
    pub profile: Profile,
    /// Whether it fits them.
    pub verdict: Verdict,
    /// Executions of each instruction (index into the program).
    #[serde(skip)]
    pub executions: Vec<Range>,
}

/// Problems that make an analysis meaningless (bad command-line constants).
#[derive(Clone, Debug, PartialEq)]
pub struct CostError(pub String);

impl std::fmt::Display for CostError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CostError {}

struct Ctx<'a> {
    shader: &'a Shader,
    table: SlotTable,
    env: &'a Environment,
    reasons: Vec<String>,
    loops: Vec<LoopCost>,
    executions: Vec<Range>,
    subs: BTreeMap<u32, Vec<Node>>,
    file: &'a SourceFile,
    /// Paths of each loop body (by its head), which decide how many
    /// iterations run before the body's instructions are counted.
    body_paths: BTreeMap<usize, Paths>,
    /// Paths of each subroutine (by its label), computed once: they do not
    /// depend on how often it is called.
    sub_paths: BTreeMap<u32, Paths>,
    /// How often each subroutine is entered, summed over its call sites;
    /// its body is counted once with this total (see [`Ctx::count_subs`]).
    sub_entries: BTreeMap<u32, Range>,
    /// Above 0 while paths are computed without counting (loop bodies,
    /// subroutines): calls then record no entries.
    paths_only: u32,
}

impl Ctx<'_> {
    fn reason(&mut self, r: String) {
        if !self.reasons.contains(&r) {
            self.reasons.push(r);
        }
    }

    /// Instruction `i`'s slots under the profile's table: the only place
    /// the analysis reads a slot cost.
    fn slots(&self, i: usize) -> u64 {
        self.shader.info().slots(i, self.table) as u64
    }

    /// Iterations of the rep/loop at `head`.
    fn iterations(&mut self, head: usize) -> Result<Range, CostError> {
        let ins = &self.shader.instructions()[head];
        let reg = ins
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::ConstInt)
            .map(|s| s.reg.index)
            .unwrap_or(0);
        let value = self
            .shader
            .program()
            .int_def(reg)
            .or_else(|| self.env.ints.get(&reg).copied());
        match value {
            Some(v) => {
                if let Some(p) = int_constant_problem(ins.op, v) {
                    return Err(CostError(format!("i{reg}: {p}")));
                }
                Ok(Range::exact(v[0] as u64))
            }
            None => {
                self.reason(format!(
                    "i{reg} is neither defined in the shader (defi) nor given (--int i{reg}=N): its count is taken as 0..=255"
                ));
                Ok(Range { min: 0, max: 255 })
            }
        }
    }

    /// The value of a boolean condition, if known.
    fn condition(&mut self, i: usize) -> Option<bool> {
        let src = self.shader.instructions()[i]
            .src
            .iter()
            .find(|s| matches!(s.reg.file, RegFile::ConstBool | RegFile::Predicate))?;
        if src.reg.file != RegFile::ConstBool {
            return None;
        }
        let b = src.reg.index;
        let v = self
            .shader
            .program()
            .bool_def(b)
            .or_else(|| self.env.bools.get(&b).copied());
        if v.is_none() {
            self.reason(format!("b{b} is neither defined (defb) nor given (--bool b{b}=true): both branches considered"));
        }
        v.map(|v| v != (src.modifier == SrcMod::Not))
    }

    fn line(&self, i: usize) -> usize {
        self.file
            .line_of(self.shader.instructions()[i].origin.span.start)
    }

    fn seq(
        &mut self,
        nodes: &[Node],
        mult: Range,
        in_sub: bool,
    ) -> Result<(Paths, Range), CostError> {
        let mut acc = Paths::fall(Range::ZERO);
        let mut nested = Range::ZERO;
        let mut mult = mult;
        for node in nodes {
            let (p, n) = self.node(node, mult, in_sub)?;
            acc = acc.then(p);
            nested = nested.add(n);
            if acc.fall.is_none() {
                mult = Range::ZERO;
            } else if p.brk.is_some() || p.exit.is_some() {
                mult.min = 0;
            }
        }
        Ok((acc, nested))
    }

    /// The paths of a loop body, computed once per loop. Paths do not depend
    /// on multiplicities, so a pass with multiplicity 0 finds them without
    /// counting anything (its loop entries are dropped again).
    fn body_paths(&mut self, head: usize, body: &[Node], in_sub: bool) -> Result<Paths, CostError> {
        if let Some(p) = self.body_paths.get(&head) {
            return Ok(*p);
        }
        let p = self.paths_of(body, in_sub)?;
        self.body_paths.insert(head, p);
        Ok(p)
    }

    /// The paths of a subroutine, computed once per label.
    fn sub_paths(&mut self, label: u32) -> Result<Paths, CostError> {
        if let Some(p) = self.sub_paths.get(&label) {
            return Ok(*p);
        }
        let sub = self.subs.get(&label).cloned().unwrap_or_default();
        let p = self.paths_of(&sub, true)?;
        self.sub_paths.insert(label, p);
        Ok(p)
    }

    /// Paths of a sequence without counting anything: a pass with
    /// multiplicity 0 whose loop entries are dropped again.
    fn paths_of(&mut self, nodes: &[Node], in_sub: bool) -> Result<Paths, CostError> {
        let loops = self.loops.len();
        self.paths_only += 1;
        let result = self.seq(nodes, Range::ZERO, in_sub);
        self.paths_only -= 1;
        self.loops.truncate(loops);
        Ok(result?.0)
    }

    /// Counts every subroutine body once, with the entries its call sites
    /// gave it, callers before callees (the call graph has no cycles).
    /// Counting is linear in the multiplicity — every step adds, multiplies
    /// by a count, or drops the lower end to 0 — so one pass with the sum
    /// counts what a pass per call site would, in time linear in the
    /// program instead of in the number of call paths.
    fn count_subs(&mut self) -> Result<(), CostError> {
        for label in self.callers_first() {
            let Some(&entries) = self.sub_entries.get(&label) else {
                continue;
            };
            let sub = self.subs.get(&label).cloned().unwrap_or_default();
            self.seq(&sub, entries, true)?;
        }
        Ok(())
    }

    /// Subroutine labels in an order where every caller comes before its
    /// callees (reverse post-order of the call graph).
    fn callers_first(&self) -> Vec<u32> {
        let callees = |label: u32| -> Vec<u32> {
            let mut out = Vec::new();
            let mut stack: Vec<&Node> = self.subs.get(&label).into_iter().flatten().collect();
            while let Some(node) = stack.pop() {
                match node {
                    Node::Ins(i) => {
                        let ins = &self.shader.instructions()[*i];
                        if matches!(ins.op, Opcode::Call | Opcode::CallNz) {
                            out.push(ins.src[0].reg.index);
                        }
                    }
                    Node::If(n) => stack.extend(n.then.iter().chain(&n.els)),
                    Node::Loop { body, .. } => stack.extend(body),
                }
            }
            out
        };
        let mut done = BTreeSet::new();
        let mut order = Vec::new();
        for &root in self.subs.keys() {
            if done.contains(&root) {
                continue;
            }
            // Iterative depth-first search: (label, its callees, next index).
            let mut stack = vec![(root, callees(root), 0usize)];
            done.insert(root);
            while let Some((label, next, at)) = stack.last_mut() {
                if let Some(&c) = next.get(*at) {
                    *at += 1;
                    if done.insert(c) && self.subs.contains_key(&c) {
                        let cs = callees(c);
                        stack.push((c, cs, 0));
                    }
                } else {
                    order.push(*label);
                    stack.pop();
                }
            }
        }
        order.reverse();
        order
    }

    fn count(&mut self, i: usize, mult: Range) {
        self.executions[i] = self.executions[i].add(mult);
    }

    /// Paths of one node and the executed slots of loops nested directly in
    /// it (for "own cost per iteration").
    fn node(
        &mut self,
        node: &Node,
        mult: Range,
        in_sub: bool,
    ) -> Result<(Paths, Range), CostError> {
        match node {
            Node::Ins(i) => Ok((self.instruction(*i, mult, in_sub)?, Range::ZERO)),
            Node::If(n) => self.if_node(n, mult, in_sub),
            Node::Loop { head, end, body } => self.loop_node(*head, *end, body, mult, in_sub),
        }
    }

    /// Paths of one instruction outside any block: breaks, `ret` in main,
    /// calls; everything else falls through.
    fn instruction(&mut self, i: usize, mult: Range, in_sub: bool) -> Result<Paths, CostError> {
        self.count(i, mult);
        let s = Range::exact(self.slots(i));
        let ins = &self.shader.instructions()[i];
        Ok(match ins.op {
            Opcode::Break => Paths {
                fall: None,
                brk: Some(s),
                exit: None,
            },
            Opcode::BreakC | Opcode::BreakP => {
                self.reason(format!("line {}: a data-dependent break", self.line(i)));
                Paths {
                    fall: Some(s),
                    brk: Some(s),
                    exit: None,
                }
            }
            Opcode::Ret if !in_sub => Paths {
                fall: None,
                brk: None,
                exit: Some(s),
            },
            Opcode::Call | Opcode::CallNz => self.call(i, s, mult)?,
            _ => Paths::fall(s),
        })
    }

    /// `call` / `callnz` at `i` (slots `s`): the call, plus the callee's
    /// body when it is (or may be) taken.
    fn call(&mut self, i: usize, s: Range, mult: Range) -> Result<Paths, CostError> {
        let ins = &self.shader.instructions()[i];
        let label = ins.src[0].reg.index;
        let taken = if ins.op == Opcode::Call {
            Some(true)
        } else {
            self.condition(i)
        };
        let sub_mult = match taken {
            Some(true) => mult,
            Some(false) => Range::ZERO,
            None => Range {
                min: 0,
                max: mult.max,
            },
        };
        let p = self.sub_paths(label)?;
        if self.paths_only == 0 {
            let entries = self.sub_entries.entry(label).or_insert(Range::ZERO);
            *entries = entries.add(sub_mult);
        }
        let body = p.fall.unwrap_or(Range::ZERO);
        let called = Paths::fall(s.add(body));
        Ok(match taken {
            Some(true) => called,
            Some(false) => Paths::fall(s),
            None => {
                if ins.src.get(1).map(|c| c.reg.file) == Some(RegFile::Predicate) {
                    self.reason(format!("line {}: callnz on a predicate", self.line(i)));
                }
                called.union(Paths::fall(s))
            }
        })
    }

    /// An `if` block: each branch with its multiplicity (both, when the
    /// condition is not known), `else` and `endif` counted as the branches
    /// reach them.
    fn if_node(
        &mut self,
        n: &IfNode,
        mult: Range,
        in_sub: bool,
    ) -> Result<(Paths, Range), CostError> {
        let head = n.head;
        let known = match self.shader.instructions()[head].op {
            Opcode::If => self.condition(head),
            _ => None,
        };
        if known.is_none() && self.shader.instructions()[head].src[0].reg.file != RegFile::ConstBool
        {
            self.reason(format!("line {}: a dynamic branch", self.line(head)));
        }
        let (tm, em) = match known {
            Some(true) => (mult, Range::ZERO),
            Some(false) => (Range::ZERO, mult),
            None => (
                Range {
                    min: 0,
                    max: mult.max,
                },
                Range {
                    min: 0,
                    max: mult.max,
                },
            ),
        };
        self.count(head, mult);
        let (tp, tn) = self.seq(&n.then, tm, in_sub)?;
        let (ep, en) = self.seq(&n.els, em, in_sub)?;
        let (else_runs, end_runs) = else_end_runs(known, &tp, &ep, mult);
        self.count(n.end, end_runs);
        let else_s = match n.else_at {
            Some(e) => {
                self.count(e, else_runs);
                Range::exact(self.slots(e))
            }
            None => Range::ZERO,
        };
        let head_s = Range::exact(self.slots(head));
        let tail = else_s.add(Range::exact(self.slots(n.end)));
        let then_branch = Paths {
            fall: tp.fall.map(|f| f.add(tail)),
            brk: tp.brk,
            exit: tp.exit,
        };
        let else_branch = Paths {
            fall: ep.fall.map(|f| f.add(tail)),
            brk: ep.brk.map(|f| f.add(else_s)),
            exit: ep.exit.map(|f| f.add(else_s)),
        };
        let paths = match known {
            Some(true) => then_branch,
            Some(false) => else_branch,
            None => then_branch.union(else_branch),
        }
        .shift(head_s);
        let nested = match known {
            Some(true) => tn,
            Some(false) => en,
            None => tn.union(en),
        };
        Ok((paths, nested))
    }

    /// A rep/loop block: its body once per iteration that starts (fewer
    /// when it may break), the head and end as iterations reach them, and
    /// its entry in [`Analysis::loops`].
    fn loop_node(
        &mut self,
        head: usize,
        end: usize,
        body: &[Node],
        mult: Range,
        in_sub: bool,
    ) -> Result<(Paths, Range), CostError> {
        let n = self.iterations(head)?;
        let h = self.slots(head);
        let f = self.slots(end);
        let slot = self.loops.len();
        self.loops.push(LoopCost {
            line: self.line(head),
            header: String::new(),
            iterations: n,
            entries: mult,
            cost_per_iteration: Range::ZERO,
            own_cost_per_iteration: Range::ZERO,
            total: Range::ZERO,
        });
        let bp = self.body_paths(head, body, in_sub)?;
        let (runs, head_runs, end_runs) = loop_runs(&bp, n);
        let (b, nested) = self.seq(body, mult.mul(runs), in_sub)?;
        self.count(head, mult.mul(head_runs));
        self.count(end, mult.mul(end_runs));
        let hr = Range::exact(h);
        let full = b.fall.map(|bf| hr.add(bf).add(Range::exact(f)));
        let total = loop_total(full, b.brk, n, h);
        let per_iter = full.unwrap_or(hr);
        let ins = &self.shader.instructions()[head];
        let operands: Vec<String> = ins.src.iter().map(|s| s.reg.to_string()).collect();
        let entry = &mut self.loops[slot];
        entry.header = format!("{} {}", ins.op, operands.join(", "));
        entry.cost_per_iteration = per_iter;
        entry.own_cost_per_iteration = Range {
            min: per_iter.min.saturating_sub(nested.min),
            max: per_iter.max.saturating_sub(nested.max),
        };
        entry.total = total.mul(mult);
        Ok((Paths::fall(total), total))
    }
}

/// How often an if's `else` and `endif` run, given the paths of its then
/// (`tp`) and else (`ep`) branches. `else` is passed at the end of the
/// then-branch and on entering the else-branch; `endif` at the end of
/// either. A branch that breaks out passes neither after it.
fn else_end_runs(known: Option<bool>, tp: &Paths, ep: &Paths, mult: Range) -> (Range, Range) {
    let always_reaches = |p: &Paths| p.fall.is_some() && p.brk.is_none() && p.exit.is_none();
    match known {
        Some(true) => (reach(tp, mult), reach(tp, mult)),
        Some(false) => (mult, reach(ep, mult)),
        None => (
            Range {
                min: if always_reaches(tp) { mult.min } else { 0 },
                max: mult.max,
            },
            Range {
                min: if always_reaches(tp) && always_reaches(ep) {
                    mult.min
                } else {
                    0
                },
                max: if tp.fall.is_some() || ep.fall.is_some() {
                    mult.max
                } else {
                    0
                },
            },
        ),
    }
}

/// For a loop of `n` iterations whose body has paths `bp`: how many
/// iterations start, how often the rep/loop is charged and how often the
/// end is reached. A body that always breaks runs (at most) once, one that
/// may break runs between once and n times.
fn loop_runs(bp: &Paths, n: Range) -> (Range, Range, Range) {
    match (bp.fall, bp.brk) {
        (_, None) => (
            n,
            // charged once per iteration, or once if it runs 0 times
            Range {
                min: n.min.max(1),
                max: n.max.max(1),
            },
            n,
        ),
        (None, Some(_)) => (
            Range {
                min: n.min.min(1),
                max: n.max.min(1),
            },
            Range::exact(1),
            Range::ZERO,
        ),
        (Some(_), Some(_)) => (
            Range {
                min: n.min.min(1),
                max: n.max,
            },
            Range {
                min: 1,
                max: n.max.max(1),
            },
            Range { min: 0, max: n.max },
        ),
    }
}

/// A loop's executed slots: `n` iterations of `full` (head, body, end; None
/// when the body never falls through), ended early by a break costing `brk`
/// after the head; `h` alone when it runs 0 times.
fn loop_total(full: Option<Range>, brk: Option<Range>, n: Range, h: u64) -> Range {
    let hr = Range::exact(h);
    match (full, brk) {
        (Some(full), None) => {
            let t = full.mul(n);
            // n = 0: the rep/loop instruction alone.
            Range {
                min: if n.min == 0 { h } else { t.min },
                max: if n.max == 0 { h } else { t.max },
            }
        }
        (full, Some(brk)) => {
            let first_break = hr.add(brk);
            let all = full.map(|full| full.mul(n));
            let min = match all {
                Some(a) if n.min > 0 => a.min.min(first_break.min),
                _ if n.min == 0 => h,
                _ => first_break.min,
            };
            let max = match full {
                Some(full) if n.max > 0 => {
                    let last_break = full
                        .max
                        .saturating_mul(n.max - 1)
                        .saturating_add(first_break.max);
                    last_break.max(full.max.saturating_mul(n.max))
                }
                None if n.max > 0 => first_break.max,
                _ => h,
            };
            Range { min, max }
        }
        (None, None) => Range::exact(h),
    }
}

/// Analyses a validated shader under an environment and profile.
pub fn analyse(
    shader: &Shader,
    file: &SourceFile,
    env: &Environment,
    profile: &Profile,
) -> Result<Analysis, CostError> {
    let own = profile.clone().for_profile(shader.program().profile);
    let profile = &own;
    for (reg, v) in &env.ints {
        if *reg >= 16 {
            return Err(CostError(format!("i{reg} does not exist (i0 … i15)")));
        }
        let _ = v;
    }
    let info = shader.info();
    let main_end = info.main_end as usize;
    let (main, _) = build(shader, 0, main_end);
    let mut subs = BTreeMap::new();
    for (&label, &at) in &info.labels {
        let start = at as usize + 1;
        let stop = shader.instructions()[start..]
            .iter()
            .position(|i| i.op == Opcode::Label)
            .map_or(shader.instructions().len(), |p| start + p);
        subs.insert(label, build(shader, start, stop).0);
    }
    let mut ctx = Ctx {
        shader,
        table: profile.slot_table,
        env,
        reasons: Vec::new(),
        loops: Vec::new(),
        executions: vec![Range::ZERO; shader.instructions().len()],
        subs,
        file,
        body_paths: BTreeMap::new(),
        sub_paths: BTreeMap::new(),
        sub_entries: BTreeMap::new(),
        paths_only: 0,
    };
    let (paths, _) = ctx.seq(&main, Range::exact(1), false)?;
    ctx.count_subs()?;
    // Subroutines are counted after main: list loops in source order.
    ctx.loops.sort_by_key(|l| l.line);
    let executed = union_opt(paths.fall, paths.exit).unwrap_or(Range::ZERO);
    // Per-line totals.
    let mut lines: BTreeMap<usize, LineCost> = BTreeMap::new();
    for (i, ins) in shader.instructions().iter().enumerate() {
        let line = file.line_of(ins.origin.span.start);
        let e = ctx.executions[i];
        let s = ctx.slots(i);
        let entry = lines.entry(line).or_insert_with(|| LineCost {
            line,
            text: file.text[ins.origin.span.range()].to_string(),
            slots: 0,
            executions: Range::ZERO,
            executed: Range::ZERO,
        });
        entry.slots += s;
        entry.executions = entry.executions.add(e);
        entry.executed = entry.executed.add(e.mul(Range::exact(s)));
    }
    let split = info.total(profile.slot_table);
    let slots = u64::from(split.total());
    let verdict = if slots > profile.max_slots || executed.min > profile.max_executed {
        Verdict::Exceeds
    } else if executed.max > profile.max_executed {
        Verdict::MayExceed
    } else {
        Verdict::Within
    };
    Ok(Analysis {
        slots,
        split,
        executed,
        data_dependent: !executed.is_exact(),
        reasons: ctx.reasons,
        lines: lines.into_values().collect(),
        loops: ctx.loops,
        profile: profile.clone(),
        verdict,
        executions: ctx.executions,
    })
}

/// Instructions of one kind that the two slot tables count differently in a
/// shader: what `check` prints beside the count its verdict used.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct TableDifference {
    /// The instruction as the output names it: its mnemonic, with
    /// " on a cube sampler" where the sampler type is what differs.
    pub instruction: String,
    /// How many of the shader's instructions are of this kind.
    pub count: u32,
    /// The documented table's slots minus Microsoft's, for each one.
    pub each: i64,
}

/// Where the documented table and Microsoft's count differ for a shader,
/// kind by kind in order of first appearance; empty when they agree. The
/// totals differ by the sum of `count × each`.
pub fn table_differences(shader: &Shader) -> Vec<TableDifference> {
    let info = shader.info();
    let mut out: Vec<TableDifference> = Vec::new();
    for (i, ins) in shader.instructions().iter().enumerate() {
        let s = info.slots[i];
        let each = i64::from(s.documented.total()) - i64::from(s.fxc.total());
        if each == 0 {
            continue;
        }
        let row = ins.op.info();
        let on_cube = row.cube_slots.is_some()
            && s.documented.total() != row.slots_of(false, ins.predicate.is_some());
        let instruction = if on_cube {
            format!("{} on a cube sampler", row.mnemonic)
        } else {
            row.mnemonic.to_string()
        };
        match out
            .iter_mut()
            .find(|d| d.instruction == instruction && d.each == each)
        {
            Some(d) => d.count += 1,
            None => out.push(TableDifference {
                instruction,
                count: 1,
                each,
            }),
        }
    }
    out
}
