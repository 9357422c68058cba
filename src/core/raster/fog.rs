//! Fixed-function fog after the pixel shader ("Fog (Direct3D 9)", "Fog
//! Formulas", "Fog Blending", "Vertex Fog", "Pixel Fog"):
//!
//! * D3DRS_FOGTABLEMODE NONE is vertex fog: the factor f is the vertex's
//!   own — a vertex shader's `oFog` (`dcl_fog` in vs_3_0), or, without a
//!   vertex shader, the specular colour's alpha (`color1`'s w) — interpolated
//!   across the primitive with perspective.
//! * LINEAR, EXP and EXP2 are pixel (table) fog from the pixel's depth d (the
//!   interpolated z, as "Pixel Fog" computes it from z): f = (end − d)/(end −
//!   start), 1/e^(d·density), 1/e^((d·density)²).
//! * Table fog's d is the pixel's z unless the projection matrix is a
//!   perspective one: "Direct3D checks the fourth column of the projection
//!   matrix. If the coefficients are [0,0,0,1] (for an affine projection)
//!   the system will use z-based depth values for fog"; otherwise it uses
//!   eye-relative depth, w ("Eye-Relative vs. Z-Based Depth"), interpolated
//!   with perspective (which gives the pixel's own w). The projection
//!   matrix matters to a shader's draw only for this choice, so a draw
//!   states it as the choice ([`Fog::w`]).
//! * f is clamped to [0, 1] and blends the colour: C = f·Cᵢ + (1 − f)·C_fog
//!   on red, green and blue; alpha is left as the shader wrote it.
//! * Only shaders below ps_3_0 are fogged: ps_3_0 has no fixed-function fog
//!   (its shader fogs itself; wined3d turns fog off for it), so fog states
//!   do nothing there.

use serde::Serialize;

/// D3DRS_FOGTABLEMODE.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum FogMode {
    /// D3DFOG_NONE: vertex fog.
    Vertex,
    /// D3DFOG_LINEAR.
    Linear,
    /// D3DFOG_EXP.
    Exp,
    /// D3DFOG_EXP2.
    Exp2,
}

/// The fog of a draw (D3DRS_FOGENABLE on).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Fog {
    /// Vertex or table fog.
    pub mode: FogMode,
    /// D3DRS_FOGCOLOR (red, green, blue; alpha unused).
    pub color: [f32; 4],
    /// D3DRS_FOGSTART (0 by default).
    pub start: f64,
    /// D3DRS_FOGEND (1 by default).
    pub end: f64,
    /// D3DRS_FOGDENSITY (1 by default).
    pub density: f64,
    /// Table fog from the pixel's w (eye-relative depth: D3DTS_PROJECTION's
    /// fourth column is not [0, 0, 0, 1]) rather than its z.
    pub w: bool,
}

impl Fog {
    /// The table-fog factor at depth `d` (vertex fog: `d` is the
    /// interpolated factor itself), clamped to [0, 1].
    pub fn factor(&self, d: f64) -> f64 {
        let f = match self.mode {
            FogMode::Vertex => d,
            FogMode::Linear => (self.end - d) / (self.end - self.start),
            FogMode::Exp => (-(d * self.density)).exp(),
            FogMode::Exp2 => (-(d * self.density).powi(2)).exp(),
        };
        if f.is_nan() {
            return 0.0;
        }
        f.clamp(0.0, 1.0)
    }

    /// `color` fogged by factor `f`.
    pub fn blend(&self, color: [f32; 4], f: f64) -> [f32; 4] {
        let mix = |c: f32, fog: f32| (f * f64::from(c) + (1.0 - f) * f64::from(fog)) as f32;
        [
            mix(color[0], self.color[0]),
            mix(color[1], self.color[1]),
            mix(color[2], self.color[2]),
            color[3],
        ]
    }
}
