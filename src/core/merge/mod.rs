//! The output merger: what happens to a pixel shader's colour between the
//! shader and the render target — blending with the texel already there,
//! the colour write mask, discarded pixels — and clearing a target.
//!
//! It exists so that several draws can meet in one target, as the article's
//! lights do ("every light accumulates into it using standard additive
//! blending") and as the alternatives it is compared with do (multiplicative
//! blending into an 8-bit target; a log-luminance written into alpha only).
//! The emulator runs the shader and reports each pixel's `oC0` and whether
//! `texkill` discarded it ([`crate::core::emu::DrawOutput`]); this stage
//! takes those, plain slices, so any other backend that produces the same
//! can use it. Its state ([`OutputState`], [`BlendState`]) and the target
//! formats ([`crate::core::image::TargetFormat`]) are plain data.
//!
//! The rules, with their sources:
//!
//! * **Blending**: see [`blend`] (D3DBLEND, D3DBLENDOP, separate alpha, the
//!   precision of each target encoding).
//! * **`D3DRS_COLORWRITEENABLE`**: bit 0 red, 1 green, 2 blue, 3 alpha
//!   (`D3DCOLORWRITEENABLE_*`); a channel whose bit is clear keeps its texel.
//!   Default 0x0F. Channels the format does not store are never written.
//! * **Discarded pixels** (`texkill`) write nothing: no blend, no channel.
//!   A shader that writes no `oC0` leaves the target as it was ("unwritten
//!   oCn → render target not updated", ps_3_0 output-register page).
//! * **Clear** (`IDirect3DDevice9::Clear` with `D3DCLEAR_TARGET`): the colour
//!   is a `D3DCOLOR`, 8 bits a channel, so a float target clears to k/255
//!   and nothing above 1. ps30 clears every channel whatever the write mask:
//!   Direct3D 9 documents no interaction between `Clear` and
//!   `D3DRS_COLORWRITEENABLE`, and this is an assumption.

pub mod blend;

pub use blend::{BlendFactor, BlendOp, BlendState, Equation, Terms};

use crate::core::image::RenderTarget;

/// `D3DRS_COLORWRITEENABLE`: which of R, G, B, A a draw writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub struct ColorWrite(pub u8);

impl ColorWrite {
    /// The red channel's bit.
    pub const RED: u8 = 1;
    /// The green channel's bit.
    pub const GREEN: u8 = 2;
    /// The blue channel's bit.
    pub const BLUE: u8 = 4;
    /// The alpha channel's bit.
    pub const ALPHA: u8 = 8;
    /// Every channel (D3D9's default, 0x0F).
    pub const ALL: ColorWrite = ColorWrite(0x0F);

    /// Whether channel `c` (0 = R … 3 = A) is written.
    pub fn writes(self, c: usize) -> bool {
        self.0 & (1 << c) != 0
    }

    /// The mask from channel letters (`rgba`, `RGB`, `a`, any order; `xyzw`
    /// also), or `None` for another letter or a repeated one. An empty
    /// string writes nothing.
    pub fn from_letters(s: &str) -> Option<ColorWrite> {
        let mut mask = 0u8;
        for ch in s.chars() {
            let bit = match ch.to_ascii_lowercase() {
                'r' | 'x' => 1,
                'g' | 'y' => 2,
                'b' | 'z' => 4,
                'a' | 'w' => 8,
                _ => return None,
            };
            if mask & bit != 0 {
                return None;
            }
            mask |= bit;
        }
        Some(ColorWrite(mask))
    }

    /// The mask as letters, `rgba` order (`-` for none).
    pub fn letters(self) -> String {
        let s: String = "rgba"
            .chars()
            .enumerate()
            .filter(|&(c, _)| self.writes(c))
            .map(|(_, l)| l)
            .collect();
        if s.is_empty() {
            "-".into()
        } else {
            s
        }
    }
}

impl Default for ColorWrite {
    fn default() -> ColorWrite {
        ColorWrite::ALL
    }
}

/// The output-merger state of one draw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize)]
pub struct OutputState {
    /// How the colour is blended with the target.
    pub blend: BlendState,
    /// Which channels are written.
    pub write: ColorWrite,
}

/// What a merge did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct MergeStats {
    /// Pixels whose colour reached the target.
    pub written: u64,
    /// Pixels `texkill` discarded (nothing written).
    pub killed: u64,
}

/// Why a merge could not be made.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeError(pub String);

impl std::fmt::Display for MergeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for MergeError {}

/// Writes a draw's colours into `target` through the output merger: for
/// each pixel not in `killed`, the blended texel, channel by channel as the
/// write mask allows. `colors` and `killed` are row-major over the whole
/// target (the emulator's `DrawOutput::color[0]` and `killed`).
pub fn merge(
    target: &mut RenderTarget,
    colors: &[[f32; 4]],
    killed: &[bool],
    state: &OutputState,
) -> Result<MergeStats, MergeError> {
    let n = target.texels.len();
    if colors.len() != n || killed.len() != n {
        return Err(MergeError(format!(
            "a {}×{} target has {n} texels; the draw gave {} colours and {} discard flags",
            target.width,
            target.height,
            colors.len(),
            killed.len()
        )));
    }
    let format = target.format;
    let mut stats = MergeStats::default();
    for ((texel, &src), &dead) in target.texels.iter_mut().zip(colors).zip(killed) {
        if dead {
            stats.killed += 1;
            continue;
        }
        let blended = state.blend.apply(format, src, *texel);
        for (c, (t, b)) in texel.iter_mut().zip(blended).enumerate() {
            if format.stores(c) && state.write.writes(c) {
                *t = b;
            }
        }
        stats.written += 1;
    }
    Ok(stats)
}

/// `Clear(…, D3DCLEAR_TARGET, color, …)`: every texel becomes the D3DCOLOR
/// `color` (R, G, B, A bytes), k/255 as the format stores it.
pub fn clear(target: &mut RenderTarget, color: [u8; 4]) {
    let value = target.format.round(color.map(|k| k as f32 / 255.0));
    target.texels.fill(value);
}

#[cfg(test)]
mod tests;
