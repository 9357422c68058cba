//! The stencil test and its operations, as Direct3D 9 runs them per pixel
//! ("Stencil Buffer Techniques (Direct3D 9)", D3DSTENCILOP, D3DRENDERSTATETYPE):
//!
//! * The test is `(StencilRef & StencilMask) CompFunc (StencilBufferValue &
//!   StencilMask)`: the reference on the left, both masked by
//!   D3DRS_STENCILMASK.
//! * A pixel that fails it takes D3DRS_STENCILFAIL; one that passes it and
//!   fails the depth test D3DRS_STENCILZFAIL; one that passes both
//!   D3DRS_STENCILPASS. Only a pixel that passes both is written to the
//!   target (and its depth, with D3DRS_ZWRITEENABLE).
//! * The new value reaches the buffer through D3DRS_STENCILWRITEMASK:
//!   `(old & ~mask) | (new & mask)`.
//! * INCRSAT and DECRSAT clamp to 0 and 2ⁿ − 1, n the format's stencil
//!   bits ("clamping to the maximum value"); INCR and DECR wrap ("wrapping
//!   to zero if the new value exceeds the maximum value", "to the maximum
//!   value if the new value is less than zero"); INVERT flips the n bits;
//!   REPLACE writes the reference.
//! * Two-sided stencil (D3DRS_TWOSIDEDSTENCILMODE): counter-clockwise
//!   triangles (back faces under D3D9's clockwise front) take the
//!   D3DRS_CCW_STENCILFUNC, _STENCILFAIL, _STENCILZFAIL and _STENCILPASS
//!   states; clockwise ones, lines and points take the others.
//! * The order per pixel: the pixel shader (and `texkill`), the alpha test,
//!   then the stencil test and the depth test together — the stencil
//!   operation needs the depth test's result — then blending (the
//!   Direct3D 9 pipeline diagram, "Pixel Pipeline": alpha test, stencil
//!   test, depth test, alpha blending). A pixel the alpha test drops leaves
//!   the stencil buffer alone.

use serde::Serialize;

/// D3DSTENCILOP.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Default)]
pub enum StencilOp {
    /// D3DSTENCILOP_KEEP: the stored value stays (the default of each op).
    #[default]
    Keep,
    /// D3DSTENCILOP_ZERO.
    Zero,
    /// D3DSTENCILOP_REPLACE: the reference value.
    Replace,
    /// D3DSTENCILOP_INCRSAT: one more, at most 255.
    IncrSat,
    /// D3DSTENCILOP_DECRSAT: one less, at least 0.
    DecrSat,
    /// D3DSTENCILOP_INVERT: every bit flipped.
    Invert,
    /// D3DSTENCILOP_INCR: one more, 255 wrapping to 0.
    Incr,
    /// D3DSTENCILOP_DECR: one less, 0 wrapping to 255.
    Decr,
}

impl StencilOp {
    /// Every operation with its D3D9 name.
    pub const ALL: [(&'static str, StencilOp); 8] = [
        ("KEEP", StencilOp::Keep),
        ("ZERO", StencilOp::Zero),
        ("REPLACE", StencilOp::Replace),
        ("INCRSAT", StencilOp::IncrSat),
        ("DECRSAT", StencilOp::DecrSat),
        ("INVERT", StencilOp::Invert),
        ("INCR", StencilOp::Incr),
        ("DECR", StencilOp::Decr),
    ];

    /// The operation a name stands for, with or without `D3DSTENCILOP_`,
    /// in any case.
    pub fn from_name(name: &str) -> Option<StencilOp> {
        let upper = name.to_ascii_uppercase();
        let n = upper.strip_prefix("D3DSTENCILOP_").unwrap_or(&upper);
        Self::ALL.iter().find(|(k, _)| *k == n).map(|&(_, op)| op)
    }

    /// The value the operation makes of `stored`, before the write mask,
    /// in a stencil whose largest value is `max` (2ⁿ − 1).
    pub fn apply(self, stored: u8, reference: u8, max: u8) -> u8 {
        match self {
            StencilOp::Keep => stored,
            StencilOp::Zero => 0,
            StencilOp::Replace => reference & max,
            StencilOp::IncrSat => stored.saturating_add(1).min(max),
            StencilOp::DecrSat => stored.saturating_sub(1),
            StencilOp::Invert => !stored & max,
            StencilOp::Incr => stored.wrapping_add(1) & max,
            StencilOp::Decr => stored.wrapping_sub(1) & max,
        }
    }
}

/// The three operations of one facing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize)]
pub struct StencilOps {
    /// D3DRS_STENCILFAIL: the stencil test failed.
    pub fail: StencilOp,
    /// D3DRS_STENCILZFAIL: the stencil test passed, the depth test failed.
    pub zfail: StencilOp,
    /// D3DRS_STENCILPASS: both passed.
    pub pass: StencilOp,
}

/// What the stencil stage did at one pixel: a plain record a per-pixel
/// history can report.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct StencilOutcome {
    /// The stored value before.
    pub stored: u8,
    /// Whether the stencil test passed.
    pub passed: bool,
    /// Whether the depth test passed (false when the stencil test failed:
    /// it did not run).
    pub depth_passed: bool,
    /// The operation applied.
    pub op: StencilOp,
    /// The stored value after, through the write mask.
    pub written: u8,
}

impl StencilOutcome {
    /// Whether the pixel goes on to the output merger.
    pub fn survives(&self) -> bool {
        self.passed && self.depth_passed
    }
}

/// The stencil stage at one pixel whose stored value is `stored`:
/// `test(a, b)` is the comparison function's `a FUNC b`, `depth` runs the
/// depth test (only when the stencil test passes), and the chosen
/// operation's value is written through `write_mask`; `max` is the
/// stencil's largest value (2ⁿ − 1 for its n bits).
#[allow(clippy::too_many_arguments)]
pub fn run(
    stored: u8,
    test: impl Fn(u8, u8) -> bool,
    depth: impl FnOnce() -> bool,
    ops: &StencilOps,
    reference: u8,
    mask: u8,
    write_mask: u8,
    max: u8,
) -> StencilOutcome {
    let passed = test(reference & mask, stored & mask);
    let depth_passed = passed && depth();
    let op = match (passed, depth_passed) {
        (false, _) => ops.fail,
        (true, false) => ops.zfail,
        (true, true) => ops.pass,
    };
    let new = op.apply(stored, reference, max);
    StencilOutcome {
        stored,
        passed,
        depth_passed,
        op,
        written: ((stored & !write_mask) | (new & write_mask)) & max,
    }
}
