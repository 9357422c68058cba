//! Depth-stencil formats as the depth test sees them (D3DFORMAT, "Depth
//! and stencil formats"): a depth is clamped to [0, 1] and stored as the
//! format stores it, and compared in that form.
//!
//! * Unsigned normalised depth of n bits, stored as round(z·(2ⁿ − 1)) /
//!   (2ⁿ − 1) (round to nearest, as every UNORM conversion): D3DFMT_D16 and
//!   D3DFMT_D16_LOCKABLE ("a 16-bit z-buffer bit depth"), D3DFMT_D15S1 ("15
//!   bits for the depth channel and 1 bit for the stencil channel"),
//!   D3DFMT_D24X8, D3DFMT_D24S8 and D3DFMT_D24X4S4 ("24 bits for the depth
//!   channel"), D3DFMT_D32 ("a 32-bit z-buffer bit depth").
//! * D3DFMT_D32F_LOCKABLE: "the depth value is represented as a standard
//!   IEEE floating-point value": the depth rounded to f32.
//! * The stencil bits beside the depth: 8 in D3DFMT_D24S8, 4 in
//!   D3DFMT_D24X4S4, 1 in D3DFMT_D15S1, none in the others (a stencil test
//!   needs one of the three). Its largest value, 2ⁿ − 1, is where INCRSAT
//!   stops and INCR wraps (`stencil`).
//! * D3DFMT_D24FS8 holds "24 bits of depth (in a 24-bit floating point
//!   format - 20e4)"; Direct3D 9 does not give the 20e4 format's exponent
//!   bias or rounding, so ps30 refuses it by name rather than guess.

use serde::Serialize;

/// A D3D9 depth-stencil format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum DepthFormat {
    /// D3DFMT_D16: 16-bit unsigned normalised depth.
    D16,
    /// D3DFMT_D16_LOCKABLE: the same 16 bits, lockable.
    D16Lockable,
    /// D3DFMT_D15S1: 15-bit depth, 1-bit stencil.
    D15S1,
    /// D3DFMT_D24X8: 24-bit depth, 8 bits unused.
    D24X8,
    /// D3DFMT_D24S8: 24-bit depth, 8-bit stencil.
    D24S8,
    /// D3DFMT_D24X4S4: 24-bit depth, 4-bit stencil, 4 bits unused.
    D24X4S4,
    /// D3DFMT_D32: 32-bit unsigned normalised depth.
    D32,
    /// D3DFMT_D32F_LOCKABLE: 32-bit float depth.
    D32F,
}

impl DepthFormat {
    /// Every format, with its D3D9 name.
    pub const ALL: [(&'static str, DepthFormat); 8] = [
        ("D16", DepthFormat::D16),
        ("D16_LOCKABLE", DepthFormat::D16Lockable),
        ("D15S1", DepthFormat::D15S1),
        ("D24X8", DepthFormat::D24X8),
        ("D24S8", DepthFormat::D24S8),
        ("D24X4S4", DepthFormat::D24X4S4),
        ("D32", DepthFormat::D32),
        ("D32F_LOCKABLE", DepthFormat::D32F),
    ];

    /// Bits of stencil beside the depth (0: none).
    pub fn stencil_bits(self) -> u32 {
        match self {
            DepthFormat::D24S8 => 8,
            DepthFormat::D24X4S4 => 4,
            DepthFormat::D15S1 => 1,
            _ => 0,
        }
    }

    /// The largest stencil value, 2ⁿ − 1 for n stencil bits (0 without).
    pub fn stencil_max(self) -> u8 {
        ((1u32 << self.stencil_bits()) - 1) as u8
    }

    /// The format a name stands for, with or without `D3DFMT_`.
    pub fn from_name(name: &str) -> Option<DepthFormat> {
        let n = name.strip_prefix("D3DFMT_").unwrap_or(name);
        let n = if n == "D32F" { "D32F_LOCKABLE" } else { n };
        Self::ALL.iter().find(|(k, _)| *k == n).map(|&(_, f)| f)
    }

    /// The D3D9 name.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(_, f)| *f == self)
            .map_or("", |(n, _)| n)
    }

    /// `z` as the format stores it (NaN stores 0).
    pub fn store(self, z: f64) -> f64 {
        let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
        let unorm = |bits: i32| {
            let max = 2f64.powi(bits) - 1.0;
            (z * max).round() / max
        };
        match self {
            DepthFormat::D16 | DepthFormat::D16Lockable => unorm(16),
            DepthFormat::D15S1 => unorm(15),
            DepthFormat::D24X8 | DepthFormat::D24S8 | DepthFormat::D24X4S4 => unorm(24),
            DepthFormat::D32 => unorm(32),
            DepthFormat::D32F => f64::from(z as f32),
        }
    }
}
