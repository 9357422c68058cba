//! The size of a point and a point sprite's texture coordinates
//! ("Point Sprites (Direct3D 9)", D3DRENDERSTATETYPE):
//!
//! * A point's size is the vertex's own (a vertex shader's `oPts` or
//!   `dcl_psize` output; without one, the vertex's D3DDECLUSAGE_PSIZE) or
//!   else D3DRS_POINTSIZE (1 by default).
//! * With D3DRS_POINTSCALEENABLE, and only when the fixed-function pipeline
//!   transforms the vertex, the size in pixels is Ss = Vh · Si ·
//!   √(1 / (A + B·De + C·De²)), Vh the viewport's height, De the vertex's
//!   distance from the eye (D3DRS_POINTSCALE_A, _B, _C; 1, 0, 0 by
//!   default).
//! * The size is then clamped to [D3DRS_POINTSIZE_MIN, D3DRS_POINTSIZE_MAX]
//!   (1 and 64 by default).
//! * With D3DRS_POINTSPRITEENABLE every texture coordinate of the point is
//!   replaced so that the whole texture covers it: (0, 0) at its top-left
//!   corner, (1, 1) at its bottom-right, linear between ("when TRUE, texture
//!   coordinates of point primitives are set so that full textures are
//!   mapped on each point"); the third and fourth components read 0 and 1
//!   (OpenGL's point-sprite coordinate replacement, through which wined3d
//!   draws them). Without it the vertex's own coordinates fill the point.

use serde::Serialize;

/// The point state of a draw.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PointState {
    /// D3DRS_POINTSIZE.
    pub size: f64,
    /// D3DRS_POINTSIZE_MIN.
    pub min: f64,
    /// D3DRS_POINTSIZE_MAX.
    pub max: f64,
    /// D3DRS_POINTSPRITEENABLE.
    pub sprite: bool,
    /// D3DRS_POINTSCALEENABLE with (A, B, C); `None`: off.
    pub scale: Option<[f64; 3]>,
}

impl Default for PointState {
    fn default() -> PointState {
        PointState {
            size: 1.0,
            min: 1.0,
            max: 64.0,
            sprite: false,
            scale: None,
        }
    }
}

impl PointState {
    /// The size in pixels of a point whose vertex gives `own` (its PSIZE,
    /// if any); `eye` is its eye-space position and `viewport_height` Vh
    /// when point scaling applies (fixed-function vertices).
    pub fn size_of(&self, own: Option<f64>, eye: Option<([f64; 3], f64)>) -> f64 {
        let mut s = own.unwrap_or(self.size);
        if let (Some([a, b, c]), Some((p, vh))) = (self.scale, eye) {
            let de = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            s = vh * s * (1.0 / (a + b * de + c * de * de)).sqrt();
        }
        if s.is_nan() {
            return self.min;
        }
        s.clamp(self.min, self.max.max(self.min))
    }
}

/// A point sprite's texture coordinates at its corners: top-left,
/// top-right, bottom-left, bottom-right.
pub const SPRITE_CORNERS: [[f64; 4]; 4] = [
    [0.0, 0.0, 0.0, 1.0],
    [1.0, 0.0, 0.0, 1.0],
    [0.0, 1.0, 0.0, 1.0],
    [1.0, 1.0, 0.0, 1.0],
];
