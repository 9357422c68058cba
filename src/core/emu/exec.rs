//! The batch executor: one decode per op for [`LANES`] pixels, with per-lane
//! execution masks for divergent flow control and per-lane slot counting.
//!
//! This file holds the worker state, the dispatch loop (one match arm per
//! op, each a call to its handler) and flow control; the arithmetic handlers
//! are in `arith.rs`, the texture ones in `texop.rs`.
//!
//! Masks are `u64` bit sets, bit `l` = lane `l`:
//! * `live`: lanes of quads that touch the target that have not finished
//!   (`ret` in main). Lanes killed by `texkill` stay live: D3D9's texkill
//!   only marks the pixel discarded, the lane keeps executing (and paying,
//!   as in the cost model) and stays a valid neighbour for derivatives. Lanes outside the target in such a quad are *helper* lanes:
//!   they execute like the others (so a quad's `dsx`/`dsy` see real
//!   neighbour values, whatever other quads of the batch do) but are never
//!   reported; a helper lane exceeding the executed limit is dropped instead
//!   of failing the draw;
//! * `exec`: lanes executing the current op (`exec ⊆ live`). Lanes of `live`
//!   not in `exec` wait in a [`Frame`]: the other side of an `if`, lanes that
//!   left a loop by `break`, or lanes that did not take a `callnz`.
//!
//! When `exec == live` an op writes every lane without looking at masks (dead
//! lanes' registers are never read back) and its slots go to one batch-wide
//! counter (`uniform`), flushed into the per-lane counts whenever `live`
//! changes.

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::compile::{Cond, DstOp, Op, Pc, SamplerOp, SrcOp};
use super::math;
use super::planes::Planes;
use super::quad::{quads_all, quads_any, SiteBatch};
use super::{EmuError, InstructionCount, RunCtx, LANES};
use crate::core::isa::Compare;

/// A flow-control construct in progress.
#[derive(Clone, Copy, Debug)]
enum Frame {
    /// Lanes waiting for the other side of the `if`, and the `else` slots
    /// the else-side lanes pay when they reach `endif` (0 before `else`).
    If { pending: u64 },
    /// A rep or loop: lanes that broke out, iterations left after the current
    /// one, aL step, the aL to restore on exit, and the `endrep`/`endloop` op.
    Loop {
        broken: u64,
        remaining: u32,
        step: i32,
        prev_al: i32,
        end: u32,
    },
    /// A call: where to return, lanes that did not call (`callnz`), lanes that
    /// already returned.
    Call {
        ret: u32,
        waiting: u64,
        returned: u64,
    },
}

impl Frame {
    /// Lanes parked in this frame.
    fn parked(&self) -> u64 {
        match *self {
            Frame::If { pending, .. } => pending,
            Frame::Loop { broken, .. } => broken,
            Frame::Call { waiting, .. } => waiting,
        }
    }
}

/// What one batch produced besides its pixels and quads (those go straight
/// into the output: [`Planes`]).
pub(crate) struct BatchOut {
    /// Bit i: `oC#` written by some lane (bit 4: oDepth).
    pub written: u8,
    /// Executed slots summed over the batch's lanes, helpers included
    /// (saturating).
    pub executed: u64,
    /// What each gradient site saw ([`super::Compiled`]'s site order).
    pub sites: Vec<SiteBatch>,
    /// What ran each instruction (`Draw::count_instructions`; else empty).
    pub instructions: Vec<InstructionCount>,
}

/// Per-thread executor state, reused across batches (nothing is allocated
/// while a batch runs once the control stack has grown to its depth).
pub(crate) struct Worker<'c, 'a> {
    pub(super) ctx: &'c RunCtx<'c, 'a>,
    /// Register rows ([`super::compile::Layout`]).
    pub(super) rows: Vec<[f32; LANES]>,
    /// Result scratch: one row per destination component.
    pub(super) tmp: [[f32; LANES]; 4],
    /// Operand scratch (texture coordinates).
    pub(super) aux: [[f32; LANES]; 2],
    /// Per-lane level of detail scratch (texture instructions).
    pub(super) lod: [f32; LANES],
    /// Per gradient site, this batch.
    pub(super) sites: Vec<SiteBatch>,
    quad_counts: [u64; LANES / 4],
    /// Bit 4q: quad q has diverged.
    diverged: u64,
    /// p0, one lane mask per channel.
    pub(super) p: [u64; 4],
    pub(super) exec: u64,
    pub(super) live: u64,
    killed: u64,
    /// Lanes inside the target (reported; the others are helpers).
    target: u64,
    counts: [u64; LANES],
    /// Each lane's pixel index in the target (`y · width + x`; meaningful
    /// for the lanes in `target`), found once per batch.
    pixel: [usize; LANES],
    /// Slots charged to every lane of `live` since the last flush.
    uniform: u64,
    /// Upper bound of `counts` (for a cheap executed-limit check).
    bound: u64,
    /// Count what runs each instruction (`Draw::count_instructions`).
    counting: bool,
    /// This batch's counts per instruction, while `counting`.
    tally: Vec<InstructionCount>,
    stack: Vec<Frame>,
    calls: u32,
    pub(super) al: i32,
    pub(super) written: u8,
    batch: u64,
    /// Lanes `0..span` hold the batch's live quads, rounded up to a multiple
    /// of 16; ops compute only those (the rest of the rows is stale and never
    /// read back).
    span: usize,
}

#[cfg(test)]
thread_local! {
    /// Tests set this to run the portable copy of the executor on a CPU
    /// with AVX2, to compare the two.
    pub(super) static PORTABLE_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether this thread must use the portable executor (tests only).
#[inline(always)]
fn portable_only() -> bool {
    #[cfg(test)]
    return PORTABLE_ONLY.with(|p| p.get());
    #[cfg(not(test))]
    false
}

fn malformed(pc: usize, reason: &str) -> EmuError {
    EmuError::Malformed {
        index: pc,
        reason: reason.to_string(),
    }
}

/// Component `c` of a primitive's per-pixel values into the first `n`
/// lanes of `row` for batch `batch` (a lane outside the quad grid keeps its
/// value: it is never live).
fn grid_values(
    ctx: &RunCtx,
    batch: u64,
    row: &mut [f32; LANES],
    values: &[[f32; 4]],
    c: usize,
    n: usize,
) {
    let grid = 2 * ctx.quads_x;
    for l in 0..n {
        let (x, y, _) = ctx.lane_pixel(batch, l);
        if let Some(v) = values.get((y * grid + x) as usize) {
            row[l] = v[c];
        }
    }
}

/// Lanes whose bit is set in `m`.
#[inline(always)]
fn lanes(mut m: u64) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        if m == 0 {
            None
        } else {
            let l = m.trailing_zeros() as usize;
            m &= m - 1;
            Some(l)
        }
    })
}

impl<'c, 'a> Worker<'c, 'a> {
    pub fn new(ctx: &'c RunCtx<'c, 'a>) -> Worker<'c, 'a> {
        let layout = &ctx.compiled.layout;
        let mut rows = vec![[0.0f32; LANES]; layout.rows];
        for (&(row, _), value) in layout.consts.iter().zip(&ctx.consts) {
            for c in 0..4 {
                rows[row as usize + c] = [value[c]; LANES];
            }
        }
        // vFace: the draw's facing in every component.
        for c in 0..4 {
            rows[layout.face as usize + c] = [ctx.face; LANES];
        }
        Worker {
            ctx,
            rows,
            tmp: [[0.0; LANES]; 4],
            aux: [[0.0; LANES]; 2],
            lod: [0.0; LANES],
            sites: vec![SiteBatch::default(); ctx.compiled.sites.len()],
            quad_counts: [0; LANES / 4],
            diverged: 0,
            p: [0; 4],
            exec: 0,
            live: 0,
            killed: 0,
            target: 0,
            counts: [0; LANES],
            pixel: [0; LANES],
            uniform: 0,
            bound: 0,
            counting: ctx.count_instructions,
            tally: Vec::new(),
            stack: Vec::with_capacity(16),
            calls: 0,
            al: 0,
            written: 0,
            batch: 0,
            span: LANES,
        }
    }

    /// Runs batch `batch` from scratch, writing its pixels and quads into
    /// `planes`.
    pub fn run(&mut self, batch: u64, planes: &Planes) -> Result<BatchOut, EmuError> {
        let ctx = self.ctx;
        let layout = &ctx.compiled.layout;
        self.batch = batch;
        for r in layout.reset.clone() {
            self.rows[r] = [0.0; LANES];
        }
        let mut target = 0u64;
        let mut xs = [0.0f32; LANES];
        let mut ys = [0.0f32; LANES];
        let origin = ctx.pixels.map_or((0, 0), |p| p.origin);
        let positions = ctx.pixels.and_then(|p| p.positions.as_deref());
        let grid = 2 * ctx.quads_x;
        for l in 0..LANES {
            let (x, y, inside) = ctx.lane_pixel(batch, l);
            target |= (inside as u64) << l;
            // A packed draw's pixel sits where its window put it.
            let at = positions.and_then(|p| p.get((y * grid + x) as usize));
            let (px, py) = at.map_or(
                (x + u64::from(origin.0), y + u64::from(origin.1)),
                |&(px, py)| (u64::from(px), u64::from(py)),
            );
            xs[l] = px as f32;
            ys[l] = py as f32;
            self.pixel[l] = (y * ctx.width + x) as usize;
        }
        // Whole quads run when any of their pixels is inside the target.
        let mut live = 0u64;
        for q in (0..LANES).step_by(4) {
            if target & (0xf << q) != 0 {
                live |= 0xf << q;
            }
        }
        self.span = (LANES - live.leading_zeros() as usize).next_multiple_of(8);
        let n = self.span();
        let per_pixel = ctx.pixels.map_or(&[][..], |p| &p.values[..]);
        for (v, input) in ctx.inputs.iter().enumerate() {
            let given = per_pixel.iter().find(|(s, _)| *s as usize == v);
            if input.is_some() || given.is_some() {
                for c in 0..4 {
                    let row = &mut self.rows[layout.input as usize + 4 * v + c];
                    match (input, given) {
                        (Some(input), _) => {
                            for l in 0..n {
                                row[l] =
                                    input.base[c] + xs[l] * input.ddx[c] + ys[l] * input.ddy[c];
                            }
                        }
                        (None, Some((_, values))) => grid_values(ctx, batch, row, values, c, n),
                        (None, None) => {}
                    }
                    if ctx.compiled.clamped & (1 << v) != 0 {
                        // ps_2_x colours (core/pixel_inputs.rs).
                        for v in &mut row[..n] {
                            *v = super::math::sat(*v);
                        }
                    }
                    if ctx.rules.flush_denormals() {
                        for v in &mut row[..n] {
                            *v = crate::core::float_rules::flush(*v);
                        }
                    }
                }
            }
        }
        let pos = layout.pos as usize;
        self.rows[pos] = xs;
        self.rows[pos + 1] = ys;
        self.p = [0; 4];
        self.target = target;
        self.exec = live;
        self.live = live;
        self.killed = 0;
        self.counts = [0; LANES];
        self.quad_counts = [0; LANES / 4];
        self.diverged = 0;
        self.sites.fill(SiteBatch::default());
        self.uniform = 0;
        self.bound = 0;
        if self.counting {
            self.tally = vec![InstructionCount::default(); ctx.compiled.ops.len()];
        }
        self.stack.clear();
        self.calls = 0;
        self.al = 0;
        self.written = 0;

        if target != 0 {
            self.execute(planes)?;
        }
        self.flush();
        self.check_limit(true)?;
        self.save_outputs(self.live, planes);
        self.save_counts(planes);
        let ctx = self.ctx;
        let mut sites = self.sites.clone();
        for (st, info) in sites.iter_mut().zip(&ctx.compiled.sites) {
            let bias = info
                .sampler
                .and_then(|s| ctx.samplers.get(s as usize))
                .and_then(|s| s.as_ref())
                .map_or(0.0, |s| s.bias());
            st.finish(bias);
        }
        Ok(BatchOut {
            written: self.written,
            executed: self.counts.iter().fold(0u64, |a, &e| a.saturating_add(e)),
            sites,
            instructions: std::mem::take(&mut self.tally),
        })
    }

    /// Lanes the batch's ops compute: `0..span()`, at most [`LANES`] (so
    /// the lane loops need no bounds checks) and a multiple of 8, two quads
    /// (so they vectorise without a scalar remainder: eight f32 lanes are
    /// one AVX2 vector, two SSE ones).
    #[inline(always)]
    pub(super) fn span(&self) -> usize {
        self.span.min(LANES) & !7
    }

    // ----- counting -------------------------------------------------------

    /// Charges `slots` of instruction `at` to every lane of `mask`, and
    /// once to every quad with a lane in `mask`; a quad with some but not
    /// all four lanes in `mask` has diverged.
    #[inline(always)]
    pub(super) fn charge(&mut self, mask: u64, slots: u8, at: usize) {
        if self.counting {
            self.count(mask, at);
        }
        if mask == self.live {
            self.uniform += slots as u64;
        } else if mask != 0 {
            let s = slots as u64;
            self.bound += s;
            for l in lanes(mask) {
                self.counts[l] += s;
            }
            let any = quads_any(mask);
            self.diverged |= any & !quads_all(mask);
            for q in lanes(any) {
                self.quad_counts[q / 4] += s;
            }
        }
    }

    /// Counts the lanes and quads of `mask` running instruction `at`
    /// (kept out of line: only draws that count instructions call it).
    #[inline(never)]
    fn count(&mut self, mask: u64, at: usize) {
        let target = self.target;
        if let Some(c) = self.tally.get_mut(at).filter(|_| mask != 0) {
            let any = quads_any(mask);
            c.pixels += u64::from((mask & target).count_ones());
            c.helpers += u64::from((mask & !target).count_ones());
            c.quads += u64::from(any.count_ones());
            c.divergent += u64::from((any & !quads_all(mask)).count_ones());
        }
    }

    /// Charges the executing lanes with instruction `at`'s `slots`; false
    /// if there are none (skip the op).
    #[inline(always)]
    pub(super) fn begin(&mut self, slots: u8, at: usize) -> bool {
        if self.exec == 0 {
            return false;
        }
        self.charge(self.exec, slots, at);
        true
    }

    fn flush(&mut self) {
        if self.uniform != 0 {
            for l in lanes(self.live) {
                self.counts[l] += self.uniform;
            }
            for q in lanes(quads_any(self.live)) {
                self.quad_counts[q / 4] += self.uniform;
            }
            self.bound += self.uniform;
            self.uniform = 0;
        }
    }

    /// Fails if a pixel exceeded the executed-slot limit (helper lanes over
    /// it are dropped). Cheap unless the bound says a lane might be over;
    /// `exact` forces the per-lane check.
    fn check_limit(&mut self, exact: bool) -> Result<(), EmuError> {
        let cap = self.ctx.cap;
        if !exact && self.bound + self.uniform <= cap {
            return Ok(());
        }
        let mut over = 0u64;
        for l in 0..LANES {
            let own = if self.live & (1 << l) != 0 {
                self.uniform
            } else {
                0
            };
            let total = self.counts[l] + own;
            if total > cap {
                if self.target & (1 << l) != 0 {
                    let (x, y, _) = self.ctx.lane_pixel(self.batch, l);
                    return Err(EmuError::ExecutedLimit {
                        x: x as u32,
                        y: y as u32,
                        executed: total,
                        limit: cap,
                    });
                }
                over |= 1 << l;
            }
        }
        if over & self.live != 0 {
            self.flush();
            self.live &= !over;
            self.exec &= !over;
        }
        self.bound = (0..LANES)
            .filter(|&l| self.live & (1 << l) != 0)
            .map(|l| self.counts[l])
            .max()
            .unwrap_or(0);
        Ok(())
    }

    // ----- lanes leaving --------------------------------------------------

    /// `ret` in main: the lanes finish now; their outputs are saved because
    /// later full-mask ops may overwrite their (no longer live) rows.
    fn retire(&mut self, mask: u64, planes: &Planes) {
        if mask != 0 {
            self.flush();
            self.save_outputs(mask, planes);
            self.live &= !mask;
            self.exec &= !mask;
        }
    }

    /// The target's pixel index of each lane in `mask` that is inside the
    /// target.
    fn pixels(&self, mask: u64) -> impl Iterator<Item = (usize, usize)> + '_ {
        lanes(mask & self.target).map(|l| (l, self.pixel[l]))
    }

    /// Writes the outputs the shader writes (no others are kept) of the
    /// lanes in `mask` inside the target from their rows.
    fn save_outputs(&self, mask: u64, planes: &Planes) {
        let base = self.ctx.compiled.layout.output as usize;
        for (k, plane) in planes.color.iter().enumerate() {
            let Some(plane) = plane else { continue };
            let r = base + 4 * k;
            for (l, i) in self.pixels(mask) {
                // SAFETY: pixel `i` belongs to this batch alone (`Planes`).
                unsafe { plane.set(i, std::array::from_fn(|c| self.rows[r + c][l])) };
            }
        }
        if let Some(plane) = &planes.depth {
            for (l, i) in self.pixels(mask) {
                // SAFETY: as above.
                unsafe { plane.set(i, self.rows[base + 16][l]) };
            }
        }
    }

    /// Writes the batch's discarded pixels (zeros), per-pixel counts and
    /// per-quad counts.
    fn save_counts(&self, planes: &Planes) {
        // SAFETY (every `set` here): pixel `i` and quad `quad` belong to
        // this batch alone (`Planes`).
        for (_, i) in self.pixels(self.killed) {
            for plane in planes.color.iter().flatten() {
                unsafe { plane.set(i, [0.0; 4]) };
            }
            if let Some(plane) = &planes.depth {
                unsafe { plane.set(i, 0.0) };
            }
        }
        for (l, i) in self.pixels(!0) {
            unsafe { planes.executed.set(i, self.counts[l]) };
            unsafe { planes.killed.set(i, self.killed & (1 << l) != 0) };
        }
        let ctx = self.ctx;
        for q in 0..ctx.batch_quads as usize {
            let quad = self.batch * ctx.batch_quads + q as u64;
            if quad < ctx.quads {
                let quad = quad as usize;
                unsafe { planes.quad_executed.set(quad, self.quad_counts[q]) };
                let divergent = (self.diverged >> (4 * q)) & 1 != 0;
                unsafe { planes.quad_divergent.set(quad, divergent) };
            }
        }
    }

    /// The first executing lane's pixel (for error messages).
    fn first_pixel(&self) -> (u32, u32) {
        let l = if self.exec != 0 {
            self.exec.trailing_zeros() as usize
        } else {
            0
        };
        let (x, y, _) = self.ctx.lane_pixel(self.batch, l);
        (x as u32, y as u32)
    }

    // ----- aL ---------------------------------------------------------------

    fn set_al(&mut self, al: i32) {
        self.al = al;
        if self.ctx.compiled.reads_al {
            let r = self.ctx.compiled.layout.al as usize;
            for c in 0..4 {
                self.rows[r + c] = [al as f32; LANES];
            }
        }
    }

    /// Pops frames above `keep` (exclusive), restoring aL of popped loops.
    fn unwind_to(&mut self, keep: usize) {
        while self.stack.len() > keep {
            if let Some(Frame::Loop { prev_al, .. }) = self.stack.pop() {
                self.set_al(prev_al);
            }
        }
    }

    // ----- conditions -------------------------------------------------------

    #[inline(always)]
    fn cond_mask(&self, cond: Cond) -> u64 {
        match cond {
            Cond::Bool { index, not } => {
                if (self.ctx.bools >> index) & 1 != 0 && !not
                    || (self.ctx.bools >> index) & 1 == 0 && not
                {
                    !0
                } else {
                    0
                }
            }
            Cond::Pred { chan, not } => self.p[chan as usize & 3] ^ if not { !0 } else { 0 },
        }
    }

    // ----- the dispatch loop ----------------------------------------------

    /// Runs the ops from pc 0 until main ends, compiled for AVX2 when the CPU
    /// has it (detected at run time, so the portable binary gets 8-lane
    /// vector arithmetic). The AVX2 copy computes the same values: it adds
    /// wider vectors only, and Rust never fuses a multiply and an add unless
    /// told to (no `mul_add` in the emulator), so every op rounds as before.
    fn execute(&mut self, planes: &Planes) -> Result<(), EmuError> {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") && !portable_only() {
            // SAFETY: the CPU supports AVX2 (checked just above).
            return unsafe { self.execute_avx2(planes) };
        }
        self.execute_ops(planes)
    }

    /// [`Worker::execute_ops`] with AVX2 enabled; the hot handlers are
    /// `#[inline(always)]`, so they are compiled into this copy.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn execute_avx2(&mut self, planes: &Planes) -> Result<(), EmuError> {
        self.execute_ops(planes)
    }

    /// Runs one arithmetic or `texld`-family op for the executing lanes;
    /// flow control and `texldd` (which can fail) are run by
    /// [`Worker::execute_ops`] and never reach here.
    #[inline(always)]
    fn compute(&mut self, op: Op) {
        match op {
            Op::Mov { d, a } => self.map1(d, a, |x| x),
            Op::Add { d, a, b } => self.map2(d, a, b, |x, y| x + y),
            Op::Sub { d, a, b } => self.map2(d, a, b, |x, y| x - y),
            Op::Mul { d, a, b } => self.mul(d, a, b),
            Op::Mad { d, a, b, c } => self.mad(d, a, b, c),
            Op::Min { d, a, b } => self.map2(d, a, b, math::min),
            Op::Max { d, a, b } => self.map2(d, a, b, math::max),
            Op::Lrp { d, a, b, c } => self.lrp(d, a, b, c),
            Op::Cmp { d, a, b, c } => self.map3(d, a, b, c, math::cmp),
            Op::Frc { d, a } => self.frc(d, a),
            Op::Abs { d, a } => self.map1(d, a, f32::abs),
            Op::Rcp { d, a } => self.scalar1(d, a, math::rcp),
            Op::Rsq { d, a } => self.rsq(d, a),
            Op::Exp { d, a } => self.scalar1(d, a, math::exp),
            Op::Log { d, a } => self.log(d, a),
            Op::Pow { d, a, b } => self.pow(d, a, b),
            Op::Dp3 { d, a, b } => self.dp::<3>(d, a, b),
            Op::Dp4 { d, a, b } => self.dp::<4>(d, a, b),
            Op::Dp2Add { d, a, b, c } => self.dp2add(d, a, b, c),
            Op::Mat { d, a, b, n, dims } => self.matrix(d, a, b, n, dims),
            Op::Crs { d, a, b } => self.crs(d, a, b),
            Op::Nrm { d, a } => self.nrm(d, a),
            Op::SinCos { d, a } => self.sincos(d, a),
            Op::Dsx { d, a, site } => self.derivative(d, a, site, 1),
            Op::Dsy { d, a, site } => self.derivative(d, a, site, 2),
            Op::Setp { d, a, b, cmp } => self.setp(d, a, b, cmp),
            Op::TexKill { d } => self.killed |= self.texkill(d),
            Op::Tex {
                d,
                a,
                s,
                kind,
                site,
            } => self.texld(d, a, s, kind, site),
            _ => debug_assert!(false, "{op:?} is run by execute_ops"),
        }
    }

    /// Runs the ops from pc 0 until main ends: one match per op, flow
    /// control handled below, the rest by [`Worker::compute`] (arithmetic
    /// in `arith.rs`, texture in `texop.rs`).
    #[inline(always)]
    fn execute_ops(&mut self, planes: &Planes) -> Result<(), EmuError> {
        let ops = &self.ctx.compiled.ops[..];
        let mut pc = 0usize;
        loop {
            let Some(&m) = ops.get(pc) else {
                return Err(malformed(pc, "jump past the end of the program"));
            };
            let at = pc;
            pc += 1;
            let s = m.slots;
            match m.op {
                Op::Nop => {
                    self.begin(s, at);
                }
                Op::TexD {
                    d,
                    a,
                    s: smp,
                    grads,
                } => {
                    if self.begin(s, at) {
                        self.texldd_at(at, d, a, smp, grads)?
                    }
                }

                // ----- flow control ----------------------------------------
                Op::If { cond, target } => pc = self.if_cond(cond, s, pc, target),
                Op::Ifc { cmp, a, b, target } => pc = self.if_compare(cmp, a, b, s, pc, target),
                Op::Else { target } => pc = self.else_side(target, s, pc, at)?,
                Op::EndIf => self.end_if(s, at)?,
                Op::Rep { int, end } => pc = self.enter_loop(int, end, false, s, pc),
                Op::Loop { int, end } => pc = self.enter_loop(int, end, true, s, pc),
                Op::EndRep { start } | Op::EndLoop { start } => {
                    pc = self.end_loop(start, s, pc, at)?
                }
                Op::Break => pc = self.break_when(s, pc, at, |_| !0)?,
                Op::BreakC { cmp, a, b } => {
                    pc = self.break_when(s, pc, at, |w| w.compare(cmp, a, b))?
                }
                Op::BreakP { chan, not } => {
                    pc = self.break_when(s, pc, at, |w| w.cond_mask(Cond::Pred { chan, not }))?
                }
                Op::Call { target } => pc = self.call_when(!0, target, s, pc, at)?,
                Op::CallNz { cond, target } => {
                    pc = self.call_when(self.cond_mask(cond), target, s, pc, at)?
                }
                Op::Ret => {
                    let Some(next) = self.ret_op(s, pc, planes)? else {
                        return Ok(());
                    };
                    pc = next;
                }
                Op::Label => {
                    // Falling into a label (or off the end): the function ends.
                    if self.calls == 0 {
                        return Ok(());
                    }
                    pc = self.ret(pc, true)?;
                }
                // ----- arithmetic and texld ---------------------------------
                op => {
                    if self.begin(s, at) {
                        self.compute(op);
                    }
                }
            }
        }
    }

    /// `texldd` with the gradient sources of entry `grads`.
    #[inline(always)]
    fn texldd_at(
        &mut self,
        at: usize,
        d: DstOp,
        a: SrcOp,
        smp: SamplerOp,
        grads: u16,
    ) -> Result<(), EmuError> {
        let Some(&(gx, gy)) = self.ctx.compiled.grads.get(grads as usize) else {
            return Err(malformed(at, "texldd gradients missing"));
        };
        self.texldd(d, a, smp, gx, gy);
        Ok(())
    }

    // ----- if / else / endif ----------------------------------------------

    /// `if b#` / `if p0.c`; returns the next pc.
    #[inline(always)]
    fn if_cond(&mut self, cond: Cond, slots: u8, pc: usize, target: Pc) -> usize {
        let entry = self.exec;
        let taken = entry & self.cond_mask(cond);
        self.enter_if(entry, taken, slots, pc, target.get())
    }

    /// `if_comp a, b`; returns the next pc.
    #[inline(always)]
    fn if_compare(
        &mut self,
        cmp: Compare,
        a: SrcOp,
        b: SrcOp,
        slots: u8,
        pc: usize,
        target: Pc,
    ) -> usize {
        let entry = self.exec;
        let taken = if entry == 0 {
            0
        } else {
            entry & self.compare(cmp, a, b)
        };
        self.enter_if(entry, taken, slots, pc, target.get())
    }

    /// Enters an if whose entry lanes are `entry` and whose taken lanes are
    /// `taken`; returns the next pc.
    #[inline(always)]
    fn enter_if(&mut self, entry: u64, taken: u64, slots: u8, pc: usize, target: usize) -> usize {
        self.charge(entry, slots, pc - 1);
        self.stack.push(Frame::If {
            pending: entry & !taken,
        });
        self.exec = taken;
        if taken == 0 {
            target
        } else {
            pc
        }
    }

    /// `else`: the lanes waiting in the if run now, the then-side waits;
    /// returns the next pc (`target`, the `endif`, when nobody runs the else
    /// side).
    #[inline(always)]
    fn else_side(
        &mut self,
        target: Pc,
        slots: u8,
        pc: usize,
        at: usize,
    ) -> Result<usize, EmuError> {
        // Both sides pay `else`, as the cost model charges it:
        // then-side lanes as they reach it, else-side lanes as
        // they enter their branch (so a lane that later breaks
        // out of the else-side has paid it, and a lane that
        // broke out of the then-side has not).
        let Some(Frame::If { pending }) = self.stack.last_mut() else {
            return Err(malformed(at, "else without if"));
        };
        let other = *pending;
        *pending = self.exec;
        let then_side = self.exec;
        self.exec = other;
        self.charge(then_side | other, slots, at);
        Ok(if self.exec == 0 { target.get() } else { pc })
    }

    /// `endif`: both sides run on together.
    #[inline(always)]
    fn end_if(&mut self, slots: u8, at: usize) -> Result<(), EmuError> {
        let Some(Frame::If { pending }) = self.stack.pop() else {
            return Err(malformed(at, "endif without if"));
        };
        self.exec |= pending;
        self.charge(self.exec, slots, at);
        Ok(())
    }

    // ----- rep / loop / break ---------------------------------------------

    /// `rep i#` / `loop aL, i#` (`is_loop`): pushes the loop's frame, or
    /// skips past `end` when no lane enters or the count is not positive;
    /// returns the next pc.
    #[inline(always)]
    fn enter_loop(&mut self, int: u8, end: Pc, is_loop: bool, slots: u8, pc: usize) -> usize {
        let entry = self.exec;
        if entry == 0 {
            return end.get() + 1;
        }
        self.charge(entry, slots, pc - 1);
        // Checked at draw setup: count and start 0..=255, step
        // -128..=127.
        let i = self.ctx.ints[int as usize & 15];
        if i[0] <= 0 {
            return end.get() + 1;
        }
        self.stack.push(Frame::Loop {
            broken: 0,
            remaining: (i[0] - 1) as u32,
            step: if is_loop { i[2] } else { 0 },
            prev_al: self.al,
            end: end.get() as u32,
        });
        if is_loop {
            self.set_al(i[1]);
        }
        pc
    }

    /// `endrep` / `endloop`: back to the op after `start` (paying the
    /// `rep`/`loop` again) while iterations remain and some lane runs, else
    /// out of the loop with the lanes that broke; returns the next pc.
    #[inline(always)]
    fn end_loop(&mut self, start: Pc, slots: u8, pc: usize, at: usize) -> Result<usize, EmuError> {
        let Some(&Frame::Loop {
            broken,
            remaining,
            step,
            prev_al,
            ..
        }) = self.stack.last()
        else {
            return Err(malformed(at, "endrep/endloop without rep/loop"));
        };
        self.charge(self.exec, slots, at);
        if remaining > 0 && self.exec != 0 {
            self.check_limit(false)?;
            if let Some(Frame::Loop { remaining, .. }) = self.stack.last_mut() {
                *remaining -= 1;
            }
            if step != 0 {
                self.set_al(self.al.wrapping_add(step));
            }
            let head = self
                .ctx
                .compiled
                .ops
                .get(start.get())
                .ok_or_else(|| malformed(at, "loop start out of range"))?;
            self.charge(self.exec, head.slots, start.get());
            Ok(start.get() + 1)
        } else {
            self.stack.pop();
            self.exec |= broken;
            if self.al != prev_al {
                self.set_al(prev_al);
            }
            Ok(pc)
        }
    }

    /// `break`, `break_comp`, `breakp`: the executing lanes of
    /// `leaving(self)` leave the innermost loop; returns the next pc.
    #[inline(always)]
    fn break_when(
        &mut self,
        slots: u8,
        pc: usize,
        at: usize,
        leaving: impl FnOnce(&Self) -> u64,
    ) -> Result<usize, EmuError> {
        if !self.begin(slots, at) {
            return Ok(pc);
        }
        let leaving = self.exec & leaving(self);
        self.leave_loop(leaving, pc, at)
    }

    /// Moves `leaving` lanes out of the innermost loop; returns the next pc
    /// (the loop's end op when nobody is left to run the rest of the body).
    fn leave_loop(&mut self, leaving: u64, pc: usize, at: usize) -> Result<usize, EmuError> {
        if leaving == 0 {
            return Ok(pc);
        }
        let mut parked = 0u64;
        let mut found = None;
        for (i, f) in self.stack.iter().enumerate().rev() {
            match f {
                Frame::Loop { .. } => {
                    found = Some(i);
                    break;
                }
                Frame::Call { .. } => break,
                Frame::If { pending, .. } => parked |= pending,
            }
        }
        let Some(li) = found else {
            return Err(malformed(at, "break outside rep/loop"));
        };
        let mut end = pc;
        if let Frame::Loop { broken, end: e, .. } = &mut self.stack[li] {
            *broken |= leaving;
            end = *e as usize;
        }
        self.exec &= !leaving;
        if self.exec == 0 && parked == 0 {
            // Nobody runs the rest of this iteration: go straight to the end
            // op, which sees no lanes and leaves the loop.
            self.unwind_to(li + 1);
            return Ok(end);
        }
        Ok(pc)
    }

    // ----- call / ret ------------------------------------------------------

    /// `call` (`cond` all lanes) / `callnz`: the executing lanes of `cond`
    /// call `target`; returns the next pc.
    #[inline(always)]
    fn call_when(
        &mut self,
        cond: u64,
        target: Pc,
        slots: u8,
        pc: usize,
        at: usize,
    ) -> Result<usize, EmuError> {
        if !self.begin(slots, at) {
            return Ok(pc);
        }
        let calling = self.exec & cond;
        if calling == 0 {
            return Ok(pc);
        }
        self.call(calling, pc, at, target.get())
    }

    /// `ret`: in main the executing lanes finish (`None` once no lane is
    /// live), in a subroutine they return; returns the next pc.
    #[inline(always)]
    fn ret_op(&mut self, slots: u8, pc: usize, planes: &Planes) -> Result<Option<usize>, EmuError> {
        self.charge(self.exec, slots, pc - 1);
        if self.calls == 0 {
            // ret in main ends the shader for these lanes.
            self.retire(self.exec, planes);
            Ok((self.live != 0).then_some(pc))
        } else {
            self.ret(pc, false).map(Some)
        }
    }

    fn call(
        &mut self,
        calling: u64,
        pc: usize,
        at: usize,
        target: usize,
    ) -> Result<usize, EmuError> {
        if self.calls >= crate::core::isa::MAX_CALL_NESTING {
            let (x, y) = self.first_pixel();
            return Err(EmuError::CallDepth { x, y, index: at });
        }
        self.stack.push(Frame::Call {
            ret: pc as u32,
            waiting: self.exec & !calling,
            returned: 0,
        });
        self.calls += 1;
        self.exec = calling;
        Ok(target)
    }

    /// `ret` (or falling into the next label) inside a subroutine: the
    /// executing lanes return. The call completes once no lane of the
    /// function is parked in a frame above it (always, for a `ret` at the
    /// function's top level); `implicit` forces completion.
    fn ret(&mut self, pc: usize, implicit: bool) -> Result<usize, EmuError> {
        let mut parked = 0u64;
        let mut found = None;
        for (i, f) in self.stack.iter().enumerate().rev() {
            if let Frame::Call { .. } = f {
                found = Some(i);
                break;
            }
            parked |= f.parked();
        }
        let Some(ci) = found else {
            return Err(malformed(pc - 1, "ret without call"));
        };
        let exec = self.exec;
        if let Frame::Call { returned, .. } = &mut self.stack[ci] {
            *returned |= exec;
        }
        self.exec = 0;
        if parked != 0 && !implicit {
            return Ok(pc);
        }
        self.unwind_to(ci + 1);
        match self.stack.pop() {
            Some(Frame::Call {
                ret,
                waiting,
                returned,
            }) => {
                self.calls -= 1;
                self.exec = returned | waiting;
                Ok(ret as usize)
            }
            _ => Err(malformed(pc - 1, "ret without call")),
        }
    }
}
