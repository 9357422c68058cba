//! A generator of random valid ps_3_0 programs with uniform control flow
//! (rep/loop nests, static ifs, breaks, REPEAT_BLOCKs, subroutines), driven
//! by a byte string so that proptest and libFuzzer can both shrink it.
//! Shared by tests/cost.rs and the fuzz targets in fuzz/.

/// Draws choices from a byte string; an exhausted string draws 0, the
/// simplest choice, so proptest shrinks programs by shrinking the bytes.
struct Chooser<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Chooser<'_> {
    fn below(&mut self, n: u32) -> u32 {
        let b = self.bytes.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        b as u32 % n
    }

    fn chance(&mut self, percent: u32) -> bool {
        self.below(100) < percent
    }
}

/// Straight-line instructions with a spread of costs; `aL` ones only
/// inside `loop`.
const BODY_LINES: &[&str] = &[
    "add r0, r0, c0",
    "mad r1, r0, c1, r2",
    "nop",
    // Gradients from an input: from a temporary, Microsoft's assembler
    // refuses them in a loop with any break (X6077).
    "texld r2, v0, s0",
    "texldl r3, r0, s1",
    "texldp r3, v0, s1",
    "texldb r4, v0, s0",
    "(p0.x) mul r4, r0, r1",
    // texldl: a predicated texld with a temporary coordinate is refused
    // by Microsoft's assembler (X6077, undefined gradients).
    "(!p0) texldl r5, r0, s1",
    "sincos r5.xy, r0.x",
    "nrm r6, r0",
    "lrp r7, r0, r1, r2",
    "setp_gt p0, r0, c0",
    "dsx r8, v0",
    "texkill r0",
    "m4x4 r9, r0, c4",
    "pow r10, r0.x, r1.y",
    "crs r11.xyz, r0, r1",
];

const LOOP_LINES: &[&str] = &["add r12, r12, v[aL]", "mov r13, v[aL + 1]"];

/// The temporaries [`BODY_LINES`] and [`LOOP_LINES`] read.
const READ_TEMPS: [u32; 4] = [0, 1, 2, 12];

struct Gen<'a, 'b> {
    c: &'b mut Chooser<'a>,
    out: Vec<String>,
    /// Labels defined after main (l0 … l{subs-1}).
    subs: u32,
}

#[derive(Clone, Copy)]
struct Ctx {
    /// rep/loop nesting in the current function.
    loops: u32,
    /// Inside a `loop` (aL defined).
    in_loop_al: bool,
    /// Static if nesting.
    ifs: u32,
    /// REPEAT_BLOCK nesting.
    repeats: u32,
    /// Subroutines callable from here: labels > this (main: none yet).
    first_callable: u32,
    /// Remaining statements allowed (keeps programs small).
    depth: u32,
}

impl Gen<'_, '_> {
    fn line(&mut self, s: impl Into<String>) {
        self.out.push(s.into());
    }

    fn block(&mut self, ctx: Ctx, max_items: u32) {
        let n = self.c.below(max_items + 1);
        for _ in 0..n {
            self.item(ctx);
        }
    }

    fn item(&mut self, ctx: Ctx) {
        let deeper = Ctx {
            depth: ctx.depth.saturating_sub(1),
            ..ctx
        };
        match self.c.below(12) {
            0 | 1 if ctx.depth > 0 && ctx.loops < 4 => {
                let reg = self.c.below(8);
                let is_loop = self.c.chance(40);
                self.line(if is_loop {
                    format!("loop aL, i{reg}")
                } else {
                    format!("rep i{reg}")
                });
                let inner = Ctx {
                    loops: ctx.loops + 1,
                    in_loop_al: is_loop || ctx.in_loop_al,
                    ..deeper
                };
                self.block(inner, 4);
                self.line(if is_loop { "endloop" } else { "endrep" });
            }
            2 if ctx.depth > 0 && ctx.ifs < 3 => {
                let b = self.c.below(4);
                let not = if self.c.chance(30) { "!" } else { "" };
                self.line(format!("if {not}b{b}"));
                let inner = Ctx {
                    ifs: ctx.ifs + 1,
                    ..deeper
                };
                self.block(inner, 3);
                if self.c.chance(50) {
                    self.line("else");
                    self.block(inner, 3);
                }
                self.line("endif");
            }
            3 if ctx.depth > 0 && ctx.repeats < 2 => {
                let count = self.c.below(4);
                self.line(format!("BEGIN_REPEAT_BLOCK({count})"));
                let inner = Ctx {
                    repeats: ctx.repeats + 1,
                    ..deeper
                };
                self.block(inner, 3);
                self.line("END_REPEAT_BLOCK");
            }
            4 if ctx.loops > 0 => self.line("break"),
            // Calls outside loops only: a subroutine's loops count toward
            // the nesting of the loops around its call (Microsoft's
            // validator, X5827).
            5 if ctx.first_callable < self.subs && ctx.loops == 0 => {
                let label = ctx.first_callable + self.c.below(self.subs - ctx.first_callable);
                if self.c.chance(50) {
                    self.line(format!("call l{label}"));
                } else {
                    let b = self.c.below(4);
                    let not = if self.c.chance(30) { "!" } else { "" };
                    self.line(format!("callnz l{label}, {not}b{b}"));
                }
            }
            6 if ctx.in_loop_al => {
                let i = self.c.below(LOOP_LINES.len() as u32) as usize;
                self.line(LOOP_LINES[i]);
            }
            _ => {
                let i = self.c.below(BODY_LINES.len() as u32) as usize;
                self.line(BODY_LINES[i]);
            }
        }
    }
}

/// A random static program from a byte string.
pub fn random_program(bytes: &[u8]) -> String {
    let mut c = Chooser { bytes, at: 0 };
    let mut head = vec!["ps_3_0".to_string()];
    // Every input, so that `v[aL]` is declared for any value aL takes.
    head.extend((0..10).map(|v| format!("dcl_texcoord{v} v{v}")));
    head.extend(["dcl_2d s0".to_string(), "dcl_cube s1".to_string()]);
    for i in 0..8 {
        // count 0..=6; loop start 0..=255 and step -128..=127 (unused here
        // except to be valid).
        let count = c.below(7);
        let start = c.below(256);
        let step = c.below(256) as i32 - 128;
        head.push(format!("defi i{i}, {count}, {start}, {step}, 0"));
    }
    for b in 0..4 {
        let v = if c.chance(50) { "true" } else { "false" };
        head.push(format!("defb b{b}, {v}"));
    }
    let subs = c.below(4);
    let mut gen = Gen {
        c: &mut c,
        out: Vec::new(),
        subs,
    };
    let main = Ctx {
        loops: 0,
        in_loop_al: false,
        ifs: 0,
        repeats: 0,
        first_callable: 0,
        depth: 4,
    };
    // The temporaries the lines read, written before anything reads them.
    for r in READ_TEMPS {
        gen.line(format!("mov r{r}, c0"));
    }
    gen.block(main, 6);
    // Every subroutine is called (Microsoft's validator refuses a label
    // never called, X5887).
    for label in 0..subs {
        gen.line(format!("call l{label}"));
    }
    gen.line("mov oC0, r0");
    if subs > 0 || gen.c.chance(50) {
        gen.line("ret");
    }
    for label in 0..subs {
        gen.line(format!("label l{label}"));
        let ctx = Ctx {
            first_callable: label + 1,
            depth: 3,
            ..main
        };
        gen.block(ctx, 4);
        gen.line("ret");
    }
    let body = gen.out;
    head.extend(body);
    head.join("\n") + "\n"
}
