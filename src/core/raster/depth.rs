//! Depth-stencil formats as the depth test sees them: a depth is clamped to
//! [0, 1] and stored as the format stores it — D16 and D24 as unsigned
//! normalised integers (D3DFMT_D16, D3DFMT_D24X8, D3DFMT_D24S8: "z-buffer
//! bit depth" 16 or 24, round to nearest as for every UNORM conversion),
//! D32F as a float (D3DFMT_D32F_LOCKABLE) — and compared in that form.

use serde::Serialize;

/// A D3D9 depth-stencil format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum DepthFormat {
    /// D3DFMT_D16: 16-bit unsigned normalised depth.
    D16,
    /// D3DFMT_D24X8: 24-bit depth, 8 bits unused.
    D24X8,
    /// D3DFMT_D24S8: 24-bit depth, 8-bit stencil (the stencil is not modelled).
    D24S8,
    /// D3DFMT_D32F_LOCKABLE: 32-bit float depth.
    D32F,
}

impl DepthFormat {
    /// Every format, with its D3D9 name.
    pub const ALL: [(&'static str, DepthFormat); 4] = [
        ("D16", DepthFormat::D16),
        ("D24X8", DepthFormat::D24X8),
        ("D24S8", DepthFormat::D24S8),
        ("D32F_LOCKABLE", DepthFormat::D32F),
    ];

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
            DepthFormat::D16 => unorm(16),
            DepthFormat::D24X8 | DepthFormat::D24S8 => unorm(24),
            DepthFormat::D32F => f64::from(z as f32),
        }
    }
}
