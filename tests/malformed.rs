//! Malformed ps_3_0 sources: every one must be rejected, without a panic,
//! with its first error at the right line and column and a message that says
//! what is wrong.
//!
//! Why: the front end is the part of ps30 people meet first, and a wrong
//! column or a vague message costs them time. Each case is one line of a
//! table (source, expected message substring, line, column), so a new rule
//! or a new regression is a one-line addition. The expected positions were
//! worked out by hand from the text (columns count characters from 1), not
//! copied from the program's output.
//!
//! Besides the table: the help texts the user relies on (did-you-mean, `-D`),
//! REPEAT_BLOCK macro bombs (refused quickly and without allocating the
//! expansion), errors inside repetitions (named in a note), files with
//! several errors (all reported), and the ps_3_0 failure vectors of Wine's
//! assembler tests (dlls/d3dcompiler_43/tests/asm.c), copied in as literals.

use ps30::diag::{Diagnostic, SourceError};
use ps30::front::{self, Options};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

// ---------------------------------------------------------------------------
// A counting allocator, per thread, so the macro-bomb test can prove the
// expansion is refused before it is allocated.

struct Counting;

thread_local! {
    static ALLOCATED: Cell<u64> = const { Cell::new(0) };
}

fn note_alloc(bytes: usize) {
    let _ = ALLOCATED.try_with(|a| a.set(a.get() + bytes as u64));
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        System.alloc(layout)
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        System.alloc_zeroed(layout)
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_alloc(new_size);
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocated_by<T>(f: impl FnOnce() -> T) -> (T, u64) {
    let before = ALLOCATED.with(|a| a.get());
    let out = f();
    let after = ALLOCATED.with(|a| a.get());
    (out, after - before)
}

// ---------------------------------------------------------------------------
// Helpers.

const NAME: &str = "case.psh";

/// Loads `src`, catching panics; `Err(text)` describes what went wrong when
/// the source was not rejected cleanly.
fn reject(src: &str, options: &Options) -> Result<SourceError, String> {
    let result = std::panic::catch_unwind(|| front::load_str(NAME, src, options));
    match result {
        Err(_) => Err(format!("PANIC on {src:?}")),
        Ok(Ok(_)) => Err(format!("ACCEPTED {src:?}")),
        Ok(Err(e)) => Ok(e),
    }
}

fn first_error(e: &SourceError) -> &Diagnostic {
    e.diagnostics
        .errors()
        .next()
        .expect("a rejected source has at least one error")
}

/// Checks one table row; returns a description of every mismatch.
fn check(src: &str, msg: &str, line: usize, col: usize, options: &Options) -> Vec<String> {
    let e = match reject(src, options) {
        Ok(e) => e,
        Err(why) => return vec![why],
    };
    let mut problems = Vec::new();
    let d = first_error(&e);
    let at = e.file.line_col(d.span.start);
    if at != (line, col) {
        problems.push(format!(
            "{src:?}: first error `{}` at {}:{}, expected {line}:{col}",
            d.message, at.0, at.1
        ));
    }
    if !d.message.contains(msg) {
        problems.push(format!(
            "{src:?}: first error is `{}`, expected it to contain `{msg}`",
            d.message
        ));
    }
    let rendered = e.diagnostics.render(&e.file);
    let loc = format!("{NAME}:{line}:{col}");
    if !rendered.contains(&loc) {
        problems.push(format!("{src:?}: rendering lacks `{loc}`:\n{rendered}"));
    }
    if !rendered.contains('^') {
        problems.push(format!("{src:?}: rendering has no caret:\n{rendered}"));
    }
    problems
}

fn run_table(table: &[(&str, &str, usize, usize)]) {
    let mut problems = Vec::new();
    for &(src, msg, line, col) in table {
        problems.extend(check(src, msg, line, col, &Options::default()));
    }
    assert!(
        problems.is_empty(),
        "{} problem(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

fn load_err(src: &str) -> SourceError {
    reject(src, &Options::default()).unwrap_or_else(|why| panic!("{why}"))
}

// ---------------------------------------------------------------------------
// The table: (source, expected substring of the first error, line, column).

#[rustfmt::skip]
const CASES: &[(&str, &str, usize, usize)] = &[
    // --- mnemonics -----------------------------------------------------------
    // Per-instruction operand rules (Microsoft's crs, m#x#, nrm, pow, sincos pages).
    ("ps_3_0\nsincos r0.xyz, r1.x", "`sincos` needs the write mask .x, .y or .xy", 2, 8),
    ("ps_3_0\nsincos oC0.x, r1.x", "`sincos` writes a temporary register", 2, 8),
    ("ps_3_0\ncrs r0.xyzw, r1, r2", "`crs` needs the write mask within .xyz", 2, 5),
    ("ps_3_0\ncrs r0.xyz, r1.yzx, r2", "`crs` sources take no swizzle", 2, 13),
    ("ps_3_0\ncrs r1.xyz, r1, r2", "may not be one of its sources", 2, 5),
    ("ps_3_0\nm4x4 r0.xyz, r1, c0", "`m4x4` needs the write mask .xyzw", 2, 6),
    ("ps_3_0\nm3x2 r0, r1, c0", "`m3x2` needs the write mask .xy", 2, 6),
    ("ps_3_0\nm3x3 r0.xyz, r1, -c0", "takes no swizzle or modifier", 2, 18),
    ("ps_3_0\nm4x4 r1, r1, c0", "may not be its vector source", 2, 6),
    ("ps_3_0\nm4x4 r2, r0, r1", "may not be one of the matrix rows", 2, 6),
    ("ps_3_0\nm4x4 r0, r5, c222", "runs past the last register", 2, 14),
    ("ps_3_0\nnrm r0, r0", "may not be its source", 2, 5),
    ("ps_3_0\npow r0, r1.x, r0.y", "may not be its exponent source", 2, 5),
    ("ps_3_0\nmovv r0, c0", "unknown instruction `movv`", 2, 1),
    ("ps_3_0\n  texldx r0, r1, s0", "unknown instruction `texldx`", 2, 3),
    ("ps_3_0\nlit r0, c0", "unknown instruction `lit`", 2, 1),
    ("ps_3_0\nslt r0, c0, c1", "unknown instruction `slt`", 2, 1),
    ("ps_3_0\ndcl_2d s0\ntex r0", "unknown instruction `tex`", 3, 1),
    // --- operand counts and kinds -------------------------------------------
    // The span covers the operands, from the first one.
    ("ps_3_0\nadd r0, c0", "`add` takes 3 operands, found 2", 2, 5),
    ("ps_3_0\nmov r0, c0, c1", "`mov` takes 2 operands, found 3", 2, 5),
    ("ps_3_0\nnop r0", "`nop` takes 0 operands, found 1", 2, 5),
    ("ps_3_0\ndef c0, 1, 2, 3", "`def` takes 5 operands, found 4", 2, 1),
    ("ps_3_0\nmov r0, 1.0", "operand 2 of `mov` must be a register", 2, 9),
    ("ps_3_0\ndefb b0, 1", "expected true or false", 2, 10),
    ("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ntexld r0, v0, r1", "operand 3 of `texld` must be a sampler", 4, 15),
    // --- registers -----------------------------------------------------------
    ("ps_3_0\nmov r0, x0", "unknown register `x0`", 2, 9),
    ("ps_3_0\nmov r0, t0", "unknown register `t0`", 2, 9),
    ("ps_3_0\nmov r0, a0", "unknown register `a0`", 2, 9),
    ("ps_3_0\nmov o0, r0", "unknown register `o0`", 2, 5),
    ("ps_3_0\nmov r32, c0", "register `r32` is out of range", 2, 5),
    ("ps_3_0\nmov r0, c224", "register `c224` is out of range", 2, 9),
    ("ps_3_0\nmov r0, v10", "register `v10` is out of range", 2, 9),
    ("ps_3_0\ntexld r0, r1, s16", "register `s16` is out of range", 2, 15),
    ("ps_3_0\ndefi i16, 1, 0, 0, 0", "register `i16` is out of range", 2, 6),
    ("ps_3_0\ndefb b16, true", "register `b16` is out of range", 2, 6),
    ("ps_3_0\nmov oC4, r0", "register `oC4` is out of range", 2, 5),
    ("ps_3_0\ncall l2048\nret", "register `l2048` is out of range", 2, 6),
    ("ps_3_0\n(p1) mov r0, r1", "register `p1` is out of range", 2, 2),
    ("ps_3_0\nmov r, c0", "register `r` needs a number", 2, 5),
    ("ps_3_0\nmov r0, ü0", "expected a register", 2, 9),
    ("ps_3_0\nmov r0, c0[aL]", "`c` registers cannot be relatively addressed", 2, 11),
    ("ps_3_0\nmov vPos, r0", "`vPos` cannot be written", 2, 5),
    ("ps_3_0\nadd r0, s0, r1", "`s0` cannot be read here", 2, 9),
    // --- swizzles and write masks -------------------------------------------
    ("ps_3_0\nmov r0, r1.xyzq", "`q` is not a component", 2, 15),
    ("ps_3_0\nmov r0.q, r1", "`q` is not a component", 2, 8),
    ("ps_3_0\nmov r0, r1.xgba", "mixes xyzw and rgba", 2, 12),
    ("ps_3_0\nmov r0, r1.xyzwx", "more than four components", 2, 12),
    ("ps_3_0\nmov r0, r1.", "expected swizzle or write-mask letters", 2, 12),
    ("ps_3_0\nmov r0.yx, r1", "write mask `.yx` is not in x, y, z, w order", 2, 8),
    ("ps_3_0\nmov r0.xx, r1", "write mask `.xx` is not in x, y, z, w order", 2, 8),
    ("ps_3_0\nmov oDepth.x, r0.x", "oDepth takes no write mask", 2, 5),
    // --- replicate swizzles ----------------------------------------------------
    ("ps_3_0\nrcp r0, r1.xy", "`rcp` needs a replicate swizzle", 2, 9),
    ("ps_3_0\nlog r0, r1", "`log` needs a replicate swizzle", 2, 9),
    ("ps_3_0\nexp r0, r1.xz", "`exp` needs a replicate swizzle", 2, 9),
    ("ps_3_0\npow r0, r1.x, r2", "`pow` needs a replicate swizzle", 2, 15),
    ("ps_3_0\nif_gt r0, r1.x\nendif", "`if` needs a replicate swizzle", 2, 7),
    ("ps_3_0\nif_gt r0.x, r1.xy\nendif", "`if` needs a replicate swizzle", 2, 13),
    ("ps_3_0\nif p0\nendif", "a predicate condition selects one component", 2, 4),
    // --- instruction modifiers -------------------------------------------------
    ("ps_3_0\nfrc_sat r0, r1", "`_sat` is not allowed on `frc`", 2, 4),
    ("ps_3_0\ndcl_2d s0\ntexld_sat r0, r1, s0", "`_sat` is not allowed on `texld`", 3, 6),
    ("ps_3_0\nsincos_sat r0.xy, r1.x", "`_sat` is not allowed on `sincos`", 2, 7),
    ("ps_3_0\nmul_x2 r0, r1, r2", "shift modifier `_x2` does not exist", 2, 4),
    ("ps_3_0\nmov_d8 r0, r1", "shift modifier `_d8` does not exist", 2, 4),
    ("ps_3_0\nmov_foo r0, r1", "unknown instruction modifier `_foo`", 2, 4),
    ("ps_3_0\nadd_centroid r0, r1, r2", "`_centroid` is only allowed on texture instructions", 2, 4),
    ("ps_3_0\nmov_gt r0, r1", "`mov` takes no comparison suffix", 2, 4),
    ("ps_3_0\nsetp p0, r0, r1", "`setp` needs a comparison suffix", 2, 1),
    ("ps_3_0\nif_xx r0.x, r1.x\nendif", "unknown instruction modifier `_xx`", 2, 3),
    // --- source modifiers ----------------------------------------------------
    ("ps_3_0\nmov r0, r1_bx2", "source modifier `_bx2` does not exist", 2, 11),
    ("ps_3_0\nmov r0, r1_x2", "source modifier `_x2` does not exist", 2, 11),
    ("ps_3_0\nmov r0, !r1", "`!` only applies to b# and p0 conditions", 2, 9),
    ("ps_3_0\nmov r0, -!r1", "only one `-` or `!` may precede a register", 2, 10),
    ("ps_3_0\nmov -r0, r1", "a destination takes no modifier", 2, 5),
    ("ps_3_0\ndcl_2d s0\ntexld r0, r1, -s0", "a sampler operand takes no modifier", 3, 15),
    // --- read ports (the instruction is pointed at as a whole) ---------------
    ("ps_3_0\nadd r0, c0, c1", "reads 2 different c registers; ps_3_0 allows 1", 2, 1),
    ("ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord1 v1\nmad r0, v0, r1, v1", "reads 2 different v registers", 4, 1),
    ("ps_3_0\ndcl_texcoord0 v0\nmov r0, c0_abs\nmov r1, c1", "constants are read both with and without _abs", 4, 1),
    // --- aL and relative addressing -------------------------------------------
    ("ps_3_0\nloop aL, i0\nmov r0, aL\nendloop", "aL can only be used as an index", 3, 9),
    ("ps_3_0\ndcl_texcoord0 v0\nmov r0, v[aL]", "v[aL + n] used outside a loop", 3, 1),
    ("ps_3_0\nrep i0\nmov r0, v[aL + 1]\nendrep", "v[aL + n] used outside a loop", 3, 1),
    ("ps_3_0\nloop aL, i0\nmov r0, v[a0 + 1]\nendloop", "`a0` cannot index registers", 3, 10),
    ("ps_3_0\nloop aL, i0\nmov r0, v[aL.x]\nendloop", "aL is a scalar register: no swizzle", 3, 13),
    ("ps_3_0\nloop aL, i0\nmov r0, v[aL - 1]\nendloop", "negative offsets are not allowed", 3, 14),
    ("ps_3_0\nloop aL, i0\nmov r0, v[aL + 10]\nendloop", "base register v10 is out of range", 3, 10),
    // An offset that does not fit in 64 bits once added must not overflow.
    ("ps_3_0\nloop aL, i0\nmov r0, v9[aL + 9223372036854775807]\nendloop", "is out of range", 3, 11),
    ("ps_3_0\nloop aL, i0\nmov r0, v[aL + 99999999999999999999]\nendloop", "is out of range", 3, 10),
    // --- version line ----------------------------------------------------------
    ("mov r0, c0", "missing version line", 1, 1),
    ("", "missing version line", 1, 1),
    ("// only a comment\n", "missing version line", 1, 1),
    ("ps_2_0\nmov r0, c0", "`ps_2_0` is not supported", 1, 1),
    ("vs_3_0\nmov r0, c0", "`vs_3_0` is not supported", 1, 1),
    ("ps_3_0\nps_3_0\nmov r0, c0", "the version line may appear only once", 2, 1),
    // --- declarations and definitions ---------------------------------------
    ("ps_3_0\nmov r0, c0\ndcl_texcoord0 v0", "declarations must come before the first instruction", 3, 1),
    ("ps_3_0\nmov r0, c0\ndef c1, 1, 2, 3, 4", "constant definitions must come before the first instruction", 3, 1),
    ("ps_3_0\ntexld r0, r1, s0", "sampler s0 is used but never declared", 2, 1),
    ("ps_3_0\nmov r0, v0", "input v0 is used but never declared", 2, 1),
    ("ps_3_0\nsetp_gt p0, vFace, c0.x", "input vFace is used but never declared", 2, 1),
    ("ps_3_0\ndcl vFace\nmov r0, vFace", "vFace may only be compared", 3, 1),
    ("ps_3_0\ndcl v0", "ps_3_0 input declarations need a usage", 2, 1),
    ("ps_3_0\ndcl_1d s0", "1D samplers are not ps_3_0 sampler types", 2, 4),
    ("ps_3_0\ndcl s0", "a sampler declaration needs a type", 2, 1),
    ("ps_3_0\ndcl_texcoord16 v0", "usage index 16 is out of range", 2, 4),
    ("ps_3_0\ndcl_foo0 v0", "unknown input usage `foo`", 2, 4),
    ("ps_3_0\ndcl vPos.z", "vPos is declared with .x, .y or .xy", 2, 5),
    ("ps_3_0\ndcl_2d s0\ndcl_2d s0", "sampler s0 is declared twice", 3, 1),
    ("ps_3_0\ndcl_texcoord0 v0.xy\ndcl_texcoord1 v0.yz", "components of v0 are declared twice", 3, 1),
    ("ps_3_0\ndcl_color0 oC0", "ps_3_0 cannot declare output registers", 2, 12),
    ("ps_3_0\ndefi i0, 1.5, 0, 0, 0", "defi takes integers", 2, 10),
    ("ps_3_0\ndefi i0, 4294967296, 0, 0, 0", "integer does not fit in 32 bits", 2, 10),
    ("ps_3_0\ndef c0, 1e39, 0, 0, 0", "number does not fit in a 32-bit float", 2, 9),
    ("ps_3_0\ndef c0.xy, 1, 0, 0, 0", "definitions write the whole register", 2, 5),
    ("ps_3_0\ndefi c0, 1, 0, 0, 0", "`defi` defines i registers", 2, 6),
    // --- blocks -------------------------------------------------------------
    ("ps_3_0\nrep i0\nmov r0, c0", "`rep` is never closed", 2, 1),
    ("ps_3_0\nmov r0, c0\n  loop aL, i0\nmov r0, c0", "`loop` is never closed", 3, 3),
    ("ps_3_0\nif b0\nmov r0, c0", "`if` is never closed", 2, 1),
    ("ps_3_0\nendrep", "`endrep` without a matching `rep`", 2, 1),
    ("ps_3_0\nrep i0\nendrep\nendrep", "`endrep` without a matching `rep`", 4, 1),
    ("ps_3_0\nendif", "`endif` without a matching `if`", 2, 1),
    ("ps_3_0\nelse\nendif", "`else` without a matching `if`", 2, 1),
    ("ps_3_0\nif b0\nelse\nelse\nendif", "second `else` for the same `if`", 4, 1),
    ("ps_3_0\nrep i0\nendloop", "`rep` is never closed", 2, 1),
    ("ps_3_0\nrep i0\nrep i0\nrep i0\nrep i0\nrep i0\nendrep\nendrep\nendrep\nendrep\nendrep", "rep/loop nested more than 4 deep", 6, 1),
    ("ps_3_0\nrep i0\nloop aL, i1\nrep i0\nloop aL, i1\nloop aL, i1\nendloop\nendloop\nendrep\nendloop\nendrep", "rep/loop nested more than 4 deep", 6, 1),
    ("ps_3_0\nbreak", "break outside rep or loop", 2, 1),
    ("ps_3_0\nbreak_gt r0.x, r1.x", "break outside rep or loop", 2, 1),
    ("ps_3_0\n(p0.x) rep i0\nendrep", "`rep` cannot be predicated", 2, 2),
    ("ps_3_0\nif_gt r0.x, r1.x\nmov oC0, r0\nendif", "oC0 is written inside dynamic flow control or predication", 3, 1),
    ("ps_3_0\n(p0) mov oC0, r0", "oC0 is written inside dynamic flow control or predication", 2, 1),
    ("ps_3_0\ndefi i0, 300, 0, 0, 0\nrep i0\nendrep", "the iteration count (.x = 300) must be in 0..=255", 3, 1),
    ("ps_3_0\ndefi i0, 1, 0, 200, 0\nloop aL, i0\nendloop", "the loop step (.z = 200) must be in -128..=127", 3, 1),
    // --- subroutines ----------------------------------------------------------
    ("ps_3_0\nif b0\nret\nendif", "ret inside an open block", 3, 1),
    ("ps_3_0\nmov r0, c0\nlabel l0\nret", "label must immediately follow a ret", 3, 1),
    ("ps_3_0\nlabel l0\nret", "label must immediately follow a ret", 2, 1),
    ("ps_3_0\nmov r0, c0\nret\nmov r1, c0", "instruction after the end of main", 4, 1),
    ("ps_3_0\ncall l3\nret", "call to undefined label l3", 2, 1),
    ("ps_3_0\nret\nlabel l0\nret\nlabel l0\nret", "label l0 is defined twice", 5, 1),
    // The error points at the call that closes the cycle.
    ("ps_3_0\ncall l0\nret\nlabel l0\ncall l1\nret\nlabel l1\ncall l0\nret", "recursive calls: l0 → l1 → l0", 8, 1),
    ("ps_3_0\ncall l2\ncall l0\nret\nlabel l0\ncall l0\nret\nlabel l2\nret", "recursive calls: l0 → l0", 6, 1),
    ("ps_3_0\ncall l0\nret\nlabel l0\ncall l1\nret\nlabel l1\ncall l2\nret\nlabel l2\ncall l3\nret\nlabel l3\ncall l4\nret\nlabel l4\nret", "calls nest 5 deep; ps_3_0 allows 4", 2, 1),
    ("ps_3_0\ncallnz l0, c0\nret\nlabel l0\nret", "expected a condition", 2, 12),
    // --- texkill, setp ---------------------------------------------------------
    ("ps_3_0\ntexkill c0", "texkill takes a temporary r# or an input v#", 2, 9),
    ("ps_3_0\nsetp_gt r0, r1, r2", "setp writes the predicate register p0", 2, 9),
    ("ps_3_0\nbreakp p0\n", "a predicate condition selects one component", 2, 8),
    // --- REPEAT_BLOCK ---------------------------------------------------------
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(3)\nmov r0, c0", "BEGIN_REPEAT_BLOCK is never closed", 2, 1),
    ("ps_3_0\nmov r0, c0\nEND_REPEAT_BLOCK", "END_REPEAT_BLOCK without a matching BEGIN_REPEAT_BLOCK", 3, 1),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(ysize)\nmov r0, c0\nEND_REPEAT_BLOCK", "REPEAT_BLOCK count `ysize` is not defined", 2, 20),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(4294967296)\nmov r0, c0\nEND_REPEAT_BLOCK", "REPEAT_BLOCK count 4294967296 is absurdly large", 2, 20),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(99999999999999999999999)\nmov r0, c0\nEND_REPEAT_BLOCK", "REPEAT_BLOCK count is too large", 2, 20),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK 3\nmov r0, c0\nEND_REPEAT_BLOCK", "expected `(` after BEGIN_REPEAT_BLOCK", 2, 20),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(3\nmov r0, c0\nEND_REPEAT_BLOCK", "expected `)` after the repetition count", 2, 21),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK()\nmov r0, c0\nEND_REPEAT_BLOCK", "expected a repetition count", 2, 20),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(3) mov\nmov r0, c0\nEND_REPEAT_BLOCK", "unexpected text after BEGIN_REPEAT_BLOCK", 2, 23),
    // The bad END line is the first error, not a "never closed" on line 2.
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(3)\nmov r0, c0\nEND_REPEAT_BLOCK foo", "unexpected text after END_REPEAT_BLOCK: found `foo`", 4, 18),
    ("ps_3_0\nBEGIN_REPEAT_BLOCK(2)\nrep i0\nEND_REPEAT_BLOCK\nendrep", "`rep` is never closed", 3, 1),
    // --- lexical ----------------------------------------------------------------
    ("ps_3_0\ndef c0, 1.2.3, 0, 0, 0", "malformed number `1.2.3`", 2, 12),
    ("ps_3_0\ndef c0, 1.0x, 0, 0, 0", "malformed number `1.0x`", 2, 12),
    ("ps_3_0\nmov r0, 0x10", "malformed number `0x10`", 2, 10),
    ("ps_3_0\nadd r0, r1,", "expected an operand after `,`", 2, 12),
    ("ps_3_0\nmov r0 , c0 ,", "expected an operand after `,`", 2, 14),
    ("ps_3_0\nadd r0 r1, r2", "expected `,` or the end of the line, found `r1`", 2, 8),
    ("ps_3_0\nadd r0, r1 + r2", "expected `,` or the end of the line, found `+`", 2, 12),
    ("ps_3_0\n,mov r0, c0", "expected an instruction, found `,`", 2, 1),
    ("ps_3_0\nmovü r0, r1", "unexpected character after `mov`", 2, 4),
    ("ps_3_0\n(p0 mov r0, r1", "expected `)` to close the predicate", 2, 5),
    // --- columns: tabs, CRLF, leading blanks, multi-byte text before the error
    ("ps_3_0\n\tmov r0,\tq0", "unknown register `q0`", 2, 10),
    ("ps_3_0\r\nmov r0, q0\r\n", "unknown register `q0`", 2, 9),
    ("ps_3_0\n    mov r0, q0 ; trailing comment", "unknown register `q0`", 2, 13),
    ("ps_3_0 // héllo wörld\nmov r0, c0 // ünï\n  mov r0, q0", "unknown register `q0`", 3, 11),
];

#[test]
fn table_of_malformed_sources() {
    assert!(CASES.len() >= 45, "only {} cases", CASES.len());
    run_table(CASES);
}

// ---------------------------------------------------------------------------
// Help texts.

#[test]
fn unknown_instruction_suggests_the_nearest_mnemonic() {
    for (src, want) in [
        ("ps_3_0\nmovv r0, c0", "did you mean `mov`?"),
        ("ps_3_0\nmull r0, r1, r2", "did you mean `mul`?"),
        (
            "ps_3_0\ndcl_2d s0\ntexldll r0, r1, s0",
            "did you mean `texldl`?",
        ),
        ("ps_3_0\nendreep", "did you mean `endrep`?"),
    ] {
        let e = load_err(src);
        let d = first_error(&e);
        assert_eq!(d.help.as_deref(), Some(want), "{src:?}");
        assert!(e.diagnostics.render(&e.file).contains(want));
    }
    // Nothing close: no suggestion, a pointer to the list instead.
    let e = load_err("ps_3_0\nfrobnicate r0");
    let help = first_error(&e).help.clone().unwrap_or_default();
    assert!(!help.contains("did you mean"), "{help}");
}

#[test]
fn foreign_instructions_and_registers_explain_themselves() {
    for (src, want) in [
        ("ps_3_0\nlit r0, c0", "vertex-shader instruction"),
        ("ps_3_0\nslt r0, c0, c1", "vertex-shader instruction"),
        ("ps_3_0\nmov r0, t0", "dcl_texcoord0 v0"),
        ("ps_3_0\nmov r0, a0", "aL"),
        ("ps_3_0\nmov o0, r0", "oC0"),
        (
            "ps_3_0\nloop aL, i0\nmov r0, v[a0 + 1]\nendloop",
            "vertex shaders",
        ),
        ("ps_3_0\nmov r0, r1_bx2", "ps_1_x only"),
    ] {
        let e = load_err(src);
        let help = first_error(&e).help.clone().unwrap_or_default();
        assert!(help.contains(want), "{src:?}: help {help:?} lacks {want:?}");
    }
}

#[test]
fn undefined_repeat_count_tells_how_to_define_it() {
    let e = load_err("ps_3_0\nBEGIN_REPEAT_BLOCK(ysize)\nmov r0, c0\nEND_REPEAT_BLOCK");
    let d = first_error(&e);
    let help = d.help.as_deref().unwrap_or_default();
    assert!(help.contains("-D ysize="), "{help}");
    assert!(e.diagnostics.render(&e.file).contains("-D ysize="));

    // With the name bound, the same text loads.
    let mut options = Options::default();
    options.defines.insert("ysize".to_string(), 3);
    let loaded = front::load_str(
        NAME,
        "ps_3_0\nBEGIN_REPEAT_BLOCK(ysize)\nmov r0, c0\nEND_REPEAT_BLOCK",
        &options,
    )
    .expect("loads with -D ysize=3");
    assert_eq!(loaded.shader.instructions().len(), 3);
}

// ---------------------------------------------------------------------------
// REPEAT_BLOCK bombs and repetitions.

#[test]
fn nested_repeat_bomb_is_refused_quickly_without_allocating_it() {
    let src = "ps_3_0\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               BEGIN_REPEAT_BLOCK(1000)\n\
               mov r0, c0\n\
               END_REPEAT_BLOCK\n\
               END_REPEAT_BLOCK\n\
               END_REPEAT_BLOCK\n";
    let start = Instant::now();
    let (result, bytes) = allocated_by(|| reject(src, &Options::default()));
    let elapsed = start.elapsed();
    let e = result.unwrap_or_else(|why| panic!("{why}"));
    let d = first_error(&e);
    assert!(
        d.message
            .contains("would produce 1000000001 statements, over the cap of 100000"),
        "{}",
        d.message
    );
    assert_eq!(e.file.line_col(d.span.start), (2, 1));
    assert!(d
        .help
        .as_deref()
        .unwrap_or_default()
        .contains("--max-expanded"));
    // A billion expanded statements would be gigabytes; the refusal costs
    // the parse and a few messages.
    assert!(bytes < 1 << 20, "allocated {bytes} bytes");
    assert!(elapsed < Duration::from_secs(5), "took {elapsed:?}");

    // The count saturates instead of wrapping: 2^32 - 1 cubed is refused too.
    let src = "ps_3_0\n\
               BEGIN_REPEAT_BLOCK(4294967295)\nBEGIN_REPEAT_BLOCK(4294967295)\n\
               BEGIN_REPEAT_BLOCK(4294967295)\nBEGIN_REPEAT_BLOCK(4294967295)\n\
               mov r0, c0\n\
               END_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\n";
    let (result, bytes) = allocated_by(|| reject(src, &Options::default()));
    let e = result.unwrap_or_else(|why| panic!("{why}"));
    assert!(first_error(&e).message.contains("over the cap"));
    assert!(bytes < 1 << 20, "allocated {bytes} bytes");
}

#[test]
fn the_expansion_cap_is_an_option() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(10)\nmov r0, c0\nEND_REPEAT_BLOCK\n";
    let tight = Options {
        max_expanded: 10,
        ..Options::default()
    };
    // 10 movs plus the version line: 11 statements.
    let problems = check(
        src,
        "would produce 11 statements, over the cap of 10",
        2,
        1,
        &tight,
    );
    assert!(problems.is_empty(), "{problems:?}");
    let roomy = Options {
        max_expanded: 11,
        ..Options::default()
    };
    assert!(front::load_str(NAME, src, &roomy).is_ok());
}

#[test]
fn an_error_inside_a_repetition_names_the_repetition() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(3)\nmov r0, v0\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    let errors: Vec<_> = e.diagnostics.errors().collect();
    // The same problem in three repetitions is reported once.
    assert_eq!(errors.len(), 1, "{}", e.diagnostics.render(&e.file));
    let d = errors[0];
    assert_eq!(e.file.line_col(d.span.start), (3, 1));
    assert!(d.message.contains("input v0 is used but never declared"));
    assert!(
        d.notes
            .iter()
            .any(|n| n.contains("in repetition 1 of 3") && n.contains("line 2")),
        "{:?}",
        d.notes
    );
    assert!(e
        .diagnostics
        .render(&e.file)
        .contains("in repetition 1 of 3"));

    // Nested: both levels are named, outermost first.
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(2)\nBEGIN_REPEAT_BLOCK(5)\nmov r0, q0\nEND_REPEAT_BLOCK\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    let d = first_error(&e);
    assert_eq!(e.file.line_col(d.span.start), (4, 9));
    assert_eq!(d.notes.len(), 2, "{:?}", d.notes);
    assert!(d.notes[0].contains("repetition 1 of 2") && d.notes[0].contains("line 2"));
    assert!(d.notes[1].contains("repetition 1 of 5") && d.notes[1].contains("line 3"));

    // A count of 0 drops the body: nothing inside is checked or reported.
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(0)\nmov r0, v0\nEND_REPEAT_BLOCK\nmov oC0, r0\n";
    assert!(front::load_str(NAME, src, &Options::default()).is_ok());
}

// ---------------------------------------------------------------------------
// Several errors in one file.

fn error_lines(e: &SourceError) -> Vec<(usize, usize)> {
    e.diagnostics
        .errors()
        .map(|d| e.file.line_col(d.span.start))
        .collect()
}

#[test]
fn every_syntax_error_is_reported() {
    let src = "ps_3_0\n\
               mov r0, r1_bx2\n\
               add r0 r1, r2\n\
               mov r0, c0\n\
               mov r0,\n\
               def c0, 1.2.3, 0, 0, 0\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        [(2, 11), (3, 8), (5, 8), (6, 12)],
        "{}",
        e.diagnostics.render(&e.file)
    );
    let rendered = e.diagnostics.render(&e.file);
    for loc in [
        "case.psh:2:11",
        "case.psh:3:8",
        "case.psh:5:8",
        "case.psh:6:12",
    ] {
        assert!(rendered.contains(loc), "{loc} missing:\n{rendered}");
    }
    assert!(e.to_string().contains("(4 errors in all)"), "{e}");
}

#[test]
fn every_validation_error_is_reported() {
    let src = "ps_3_0\n\
               dcl_2d s0\n\
               mov r0, q0\n\
               mul_x2 r0, r1, r2\n\
               texld r0, r1, s1\n\
               add r0, c0, c1\n\
               rcp r0, r1\n\
               break\n\
               mov r0, c0\n\
               dcl_texcoord0 v0\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        [(3, 9), (4, 4), (5, 1), (6, 1), (7, 9), (8, 1), (10, 1)],
        "{}",
        e.diagnostics.render(&e.file)
    );
}

#[test]
fn statement_errors_are_reported_alongside_syntax_errors() {
    // Line 3 does not parse, so the program as a whole cannot be checked,
    // but the lines that did parse still get their own checks.
    let src = "ps_3_0\n\
               mov r0, q0\n\
               add r0 r1, r2\n\
               frc_sat r0, r1\n";
    let e = load_err(src);
    assert_eq!(
        error_lines(&e),
        [(2, 9), (3, 8), (4, 4)],
        "{}",
        e.diagnostics.render(&e.file)
    );
}

#[test]
fn unknown_input_is_reported_once_per_statement_not_per_repetition() {
    let src = "ps_3_0\nBEGIN_REPEAT_BLOCK(50)\nmov r0, q0\nmov r1, v3\nEND_REPEAT_BLOCK\n";
    let e = load_err(src);
    assert_eq!(error_lines(&e), [(3, 9), (4, 1)]);
}

// ---------------------------------------------------------------------------
// Wine's failure vectors (dlls/d3dcompiler_43/tests/asm.c, LGPL-2.1): every
// ps_3_0 shader there must be rejected. The expected message and position
// are ps30's, for the reason Wine gives.

#[rustfmt::skip]
const WINE_PS30_FAILURES: &[(&str, &str, &str, usize, usize)] = &[
    // (Wine's name and reason, source, expected message, line, column)
    ("failure_test shader 0: instruction modifier not allowed",
     "ps_3_0\ndcl_2d s2\ntexldd_x2 r0, v1, s2, v3, v4\n", "shift modifier `_x2`", 3, 7),
    ("failure_test shader 4: register a0 doesn't exist in pixel shaders",
     "ps_3_0\nmov r0, v[ a0 + 12 ]\n", "`a0` cannot index registers", 2, 10),
    ("failure_test shader 6: aL is a scalar register, no swizzles allowed",
     "ps_3_0\nmov r0, v[ aL.x + 12 ]\n", "aL is a scalar register", 2, 14),
    ("failure_test shader 7: tn doesn't exist in ps_3_0",
     "ps_3_0\ndcl_2d s2\ntexldd r0, t1, s2, v3, v4\n", "unknown register `t1`", 3, 12),
    ("failure_test shader 23: can't declare output registers in a pixel shader",
     "ps_3_0\ndcl_positiont o0\n", "unknown register `o0`", 2, 15),
    ("failure_test shader 25: _x4 instruction modified not allowed in > ps_1_x",
     "ps_3_0\nadd_x4 r0, r0, r1\n", "shift modifier `_x4`", 2, 4),
    ("failure_test shader 27: oC3 is the max in >= ps_2_0",
     "ps_3_0\nadd oC4, r0, r1\n", "register `oC4` is out of range", 2, 5),
    ("failure_test shader 31: s20 register does not exist",
     "ps_3_0\ntexld r0, r1, s20\n", "register `s20` is out of range", 2, 15),
    ("failure_test shader 37: no a0 register in ps_3_0",
     "ps_3_0\nadd r0, v[ a0.x ], r1\n", "`a0` cannot index registers", 2, 10),
    ("failure_test shader 39: invalid modifier for dcl instruction",
     "ps_3_0\ndcl_texcoord0_sat v0\n", "`_sat` is not allowed on a declaration", 2, 14),
    ("failure_test shader 40: shift not allowed",
     "ps_3_0\ndcl_texcoord0_x2 v0\n", "unexpected `_x2` in declaration", 2, 14),
];

/// The ps_2_0 failures of the same list: rejected by ps30 for their version
/// line already, whatever else is wrong with them.
const WINE_PS20_FAILURES: &[&str] = &[
    "ps_2_0\ntexld r0, t0, s0\nadd r0.rgb, r0, r1\n+add r0.a, r0, v1\n",
    "ps_2_0\nmov r2, 1 - r0\n",
    "ps_2_0\nmov r0, r1_x2\n",
    "ps_2_0\nadd r0, v[ aL ], r1\n",
    "ps_2_0\nadd r0, v[ r0 ], r1\n",
    "ps_2_0\ntexm3x3vspec t3, t0\n",
];

#[test]
fn wine_ps_3_0_failure_vectors_are_rejected() {
    let mut problems = Vec::new();
    for &(name, src, msg, line, col) in WINE_PS30_FAILURES {
        for p in check(src, msg, line, col, &Options::default()) {
            problems.push(format!("{name}: {p}"));
        }
    }
    for src in WINE_PS20_FAILURES {
        if let Err(why) = reject(src, &Options::default()) {
            problems.push(why);
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

// ---------------------------------------------------------------------------
// No input makes the front end panic: every prefix of every case, and every
// case with each line dropped in turn, is either accepted or rejected.

#[test]
fn truncated_and_mangled_cases_never_panic() {
    let mut sources: BTreeMap<String, ()> = BTreeMap::new();
    for &(src, ..) in CASES {
        for (i, _) in src.char_indices() {
            sources.insert(src[..i].to_string(), ());
        }
        let lines: Vec<&str> = src.lines().collect();
        for skip in 0..lines.len() {
            let s: Vec<&str> = lines
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != skip)
                .map(|(_, l)| *l)
                .collect();
            sources.insert(s.join("\n"), ());
        }
    }
    let mut panics = Vec::new();
    for src in sources.keys() {
        let r = std::panic::catch_unwind(|| front::load_str(NAME, src, &Options::default()));
        match r {
            Err(_) => panics.push(src.clone()),
            Ok(Err(e)) => {
                // Every rejection has at least one error with a location.
                let d = first_error(&e);
                let _ = e.file.line_col(d.span.start);
                let _ = e.diagnostics.render(&e.file);
            }
            Ok(Ok(_)) => {}
        }
    }
    assert!(panics.is_empty(), "panics on: {panics:#?}");
}
