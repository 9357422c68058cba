//! Blending: how a pixel's shader output and the texel already in the render
//! target combine, channel by channel, in the precision the target stores.
//!
//! `result = op(source · source factor, destination · destination factor)`,
//! with the factors and operations Direct3D 9 defines (pages `D3DBLEND` and
//! `D3DBLENDOP`, Direct3D 9 reference; `D3DRENDERSTATETYPE` for the render
//! states). Subscript s is the shader's output, d the target's texel as it
//! reads back (a format without alpha reads Ad = 1):
//!
//! | D3DBLEND | factor |
//! |---|---|
//! | ZERO, ONE | (0, 0, 0, 0), (1, 1, 1, 1) |
//! | SRCCOLOR, INVSRCCOLOR | (Rs, Gs, Bs, As), (1 − Rs, 1 − Gs, 1 − Bs, 1 − As) |
//! | SRCALPHA, INVSRCALPHA | (As, As, As, As), (1 − As, …) |
//! | DESTALPHA, INVDESTALPHA | (Ad, Ad, Ad, Ad), (1 − Ad, …) |
//! | DESTCOLOR, INVDESTCOLOR | (Rd, Gd, Bd, Ad), (1 − Rd, 1 − Gd, 1 − Bd, 1 − Ad) |
//! | SRCALPHASAT | (f, f, f, 1), f = min(As, 1 − Ad) |
//! | BLENDFACTOR, INVBLENDFACTOR | D3DRS_BLENDFACTOR, a D3DCOLOR: (R, G, B, A)/255, and 1 minus it |
//!
//! D3DBLENDOP: ADD `S + D`, SUBTRACT `S − D`, REVSUBTRACT `D − S`, MIN
//! `min(Source, Destination)`, MAX `max(…)`. The D3D9 page defines MIN and
//! MAX on "the color of the source pixel" and of the destination, not on the
//! weighted terms, so the factors do not apply to them (as in OpenGL and
//! Vulkan, which D3D9 translation layers map these operations to).
//!
//! With `D3DRS_SEPARATEALPHABLENDENABLE` the alpha channel uses
//! `D3DRS_SRCBLENDALPHA`, `D3DRS_DESTBLENDALPHA` and `D3DRS_BLENDOPALPHA`
//! instead; otherwise alpha blends with the colour's factors (a `…COLOR`
//! factor then supplies its alpha component). Defaults: ONE, ZERO, ADD, for
//! colour and alpha; blending off; the blend factor 0xFFFFFFFF.
//!
//! # Precision
//!
//! Direct3D 9 does not say in what precision the blender works. ps30 blends
//! in the precision the target stores, one rounding per operation — each
//! factor `1 − x`, each product and the final operation:
//!
//! * half targets: every operation correctly rounded to half (ties to even).
//!   This is Direct3D 10.1's requirement ("The precision of float16 blending
//!   has increased to 0.5 ULP", Direct3D 10.1 Features), the closest public
//!   definition. The shader's f32 output is first converted to half, as the
//!   target would store it. Computed in f64, where a product or sum of two
//!   halves is exact, then rounded once to half
//!   ([`crate::core::image::half_from_f64`]).
//! * single-float targets: every operation in f32 (IEEE).
//! * 8-bit UNORM targets: the source is clamped to [0, 1] (NaN to 0), the
//!   operations run in f32, and the result is clamped and quantised once, on
//!   the store, by the FLOAT → UNORM rule ([`crate::core::image::unorm8`]).
//!   The source is not quantised before blending; a part that does so adds
//!   up to half a code per blend.

use crate::core::image::{Encoding, TargetFormat};
use half::f16;

/// A `D3DBLEND` value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum BlendFactor {
    /// D3DBLEND_ZERO: (0, 0, 0, 0).
    Zero,
    /// D3DBLEND_ONE: (1, 1, 1, 1).
    One,
    /// D3DBLEND_SRCCOLOR: the source colour.
    SrcColor,
    /// D3DBLEND_INVSRCCOLOR: 1 − the source colour.
    InvSrcColor,
    /// D3DBLEND_SRCALPHA: the source alpha.
    SrcAlpha,
    /// D3DBLEND_INVSRCALPHA: 1 − the source alpha.
    InvSrcAlpha,
    /// D3DBLEND_DESTALPHA: the destination alpha.
    DestAlpha,
    /// D3DBLEND_INVDESTALPHA: 1 − the destination alpha.
    InvDestAlpha,
    /// D3DBLEND_DESTCOLOR: the destination colour.
    DestColor,
    /// D3DBLEND_INVDESTCOLOR: 1 − the destination colour.
    InvDestColor,
    /// D3DBLEND_SRCALPHASAT: min(source alpha, 1 − destination alpha), alpha 1.
    SrcAlphaSat,
    /// D3DBLEND_BLENDFACTOR: the constant D3DRS_BLENDFACTOR.
    Constant,
    /// D3DBLEND_INVBLENDFACTOR.
    InvConstant,
}

impl BlendFactor {
    /// Every factor, in `D3DBLEND` order.
    pub const ALL: [BlendFactor; 13] = [
        BlendFactor::Zero,
        BlendFactor::One,
        BlendFactor::SrcColor,
        BlendFactor::InvSrcColor,
        BlendFactor::SrcAlpha,
        BlendFactor::InvSrcAlpha,
        BlendFactor::DestAlpha,
        BlendFactor::InvDestAlpha,
        BlendFactor::DestColor,
        BlendFactor::InvDestColor,
        BlendFactor::SrcAlphaSat,
        BlendFactor::Constant,
        BlendFactor::InvConstant,
    ];

    /// The name after `D3DBLEND_`.
    pub fn d3d_name(self) -> &'static str {
        match self {
            BlendFactor::Zero => "ZERO",
            BlendFactor::One => "ONE",
            BlendFactor::SrcColor => "SRCCOLOR",
            BlendFactor::InvSrcColor => "INVSRCCOLOR",
            BlendFactor::SrcAlpha => "SRCALPHA",
            BlendFactor::InvSrcAlpha => "INVSRCALPHA",
            BlendFactor::DestAlpha => "DESTALPHA",
            BlendFactor::InvDestAlpha => "INVDESTALPHA",
            BlendFactor::DestColor => "DESTCOLOR",
            BlendFactor::InvDestColor => "INVDESTCOLOR",
            BlendFactor::SrcAlphaSat => "SRCALPHASAT",
            BlendFactor::Constant => "BLENDFACTOR",
            BlendFactor::InvConstant => "INVBLENDFACTOR",
        }
    }

    /// The factor named `name`, with or without `D3DBLEND_`, in any case.
    pub fn from_name(name: &str) -> Option<BlendFactor> {
        let upper = name.trim().to_ascii_uppercase();
        let bare = upper.strip_prefix("D3DBLEND_").unwrap_or(&upper);
        BlendFactor::ALL.into_iter().find(|f| f.d3d_name() == bare)
    }
}

/// A `D3DBLENDOP` value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum BlendOp {
    /// D3DBLENDOP_ADD: source × factor + destination × factor.
    Add,
    /// D3DBLENDOP_SUBTRACT: source term − destination term.
    Subtract,
    /// D3DBLENDOP_REVSUBTRACT: destination term − source term.
    RevSubtract,
    /// D3DBLENDOP_MIN: the smaller of source and destination (factors ignored).
    Min,
    /// D3DBLENDOP_MAX: the larger of source and destination (factors ignored).
    Max,
}

impl BlendOp {
    /// Every operation.
    pub const ALL: [BlendOp; 5] = [
        BlendOp::Add,
        BlendOp::Subtract,
        BlendOp::RevSubtract,
        BlendOp::Min,
        BlendOp::Max,
    ];

    /// The name after `D3DBLENDOP_`.
    pub fn d3d_name(self) -> &'static str {
        match self {
            BlendOp::Add => "ADD",
            BlendOp::Subtract => "SUBTRACT",
            BlendOp::RevSubtract => "REVSUBTRACT",
            BlendOp::Min => "MIN",
            BlendOp::Max => "MAX",
        }
    }

    /// The operation named `name`, with or without `D3DBLENDOP_`, in any case.
    pub fn from_name(name: &str) -> Option<BlendOp> {
        let upper = name.trim().to_ascii_uppercase();
        let bare = upper.strip_prefix("D3DBLENDOP_").unwrap_or(&upper);
        BlendOp::ALL.into_iter().find(|o| o.d3d_name() == bare)
    }
}

/// One blend equation: source factor, destination factor, operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub struct Equation {
    /// The factor of the source (the shader's output).
    pub src: BlendFactor,
    /// The factor of the destination (what the target holds).
    pub dest: BlendFactor,
    /// How the two terms combine.
    pub op: BlendOp,
}

impl Equation {
    /// D3D9's default: ONE, ZERO, ADD (the source replaces the texel).
    pub const REPLACE: Equation = Equation {
        src: BlendFactor::One,
        dest: BlendFactor::Zero,
        op: BlendOp::Add,
    };
    /// ONE, ONE, ADD: the article's "standard additive blending".
    pub const ADDITIVE: Equation = Equation {
        src: BlendFactor::One,
        dest: BlendFactor::One,
        op: BlendOp::Add,
    };
    /// DESTCOLOR, ZERO, ADD: multiplicative blending (the log lights').
    pub const MULTIPLY: Equation = Equation {
        src: BlendFactor::DestColor,
        dest: BlendFactor::Zero,
        op: BlendOp::Add,
    };
}

/// The blend render states of one draw: `D3DRS_ALPHABLENDENABLE`,
/// `SRCBLEND`/`DESTBLEND`/`BLENDOP`, `SEPARATEALPHABLENDENABLE` with
/// `SRCBLENDALPHA`/`DESTBLENDALPHA`/`BLENDOPALPHA`, and `BLENDFACTOR`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub struct BlendState {
    /// `D3DRS_ALPHABLENDENABLE`; off, the source replaces the texel.
    pub enabled: bool,
    /// For R, G, B (and A without a separate alpha equation).
    pub color: Equation,
    /// `Some` when `D3DRS_SEPARATEALPHABLENDENABLE` is on.
    pub alpha: Option<Equation>,
    /// `D3DRS_BLENDFACTOR` as (R, G, B, A) bytes of the D3DCOLOR.
    pub factor: [u8; 4],
}

impl Default for BlendState {
    fn default() -> BlendState {
        BlendState::OFF
    }
}

impl BlendState {
    /// D3D9's defaults: blending off.
    pub const OFF: BlendState = BlendState {
        enabled: false,
        color: Equation::REPLACE,
        alpha: None,
        factor: [255; 4],
    };

    /// Blending on with one equation for all four channels.
    pub fn with(equation: Equation) -> BlendState {
        BlendState {
            enabled: true,
            color: equation,
            ..BlendState::OFF
        }
    }

    /// The equation channel `c` (0 = R … 3 = A) uses.
    pub fn equation(&self, c: usize) -> Equation {
        match self.alpha {
            Some(a) if c == 3 => a,
            _ => self.color,
        }
    }

    /// The texel that results from writing `src` over `dst` (a texel as
    /// `format` stores it), before the write mask: every channel of the
    /// returned value is already rounded as `format` stores it.
    pub fn apply(&self, format: TargetFormat, src: [f32; 4], dst: [f32; 4]) -> [f32; 4] {
        if !self.enabled {
            return format.round(src);
        }
        let p = Precision::of(format.encoding());
        let s = src.map(|c| p.source(c));
        let d = dst.map(f64::from);
        let k = self.factor.map(|b| p.round(b as f64 / 255.0));
        let out: [f64; 4] = std::array::from_fn(|c| {
            let eq = self.equation(c);
            match eq.op {
                BlendOp::Min => s[c].min(d[c]),
                BlendOp::Max => s[c].max(d[c]),
                op => {
                    let fs = p.factor(eq.src, c, &s, &d, &k);
                    let fd = p.factor(eq.dest, c, &s, &d, &k);
                    let (ts, td) = (p.round(s[c] * fs), p.round(d[c] * fd));
                    p.round(match op {
                        BlendOp::Add => ts + td,
                        BlendOp::Subtract => ts - td,
                        _ => td - ts,
                    })
                }
            }
        });
        format.round(out.map(|v| v as f32))
    }
}

/// One blend of one texel, term by term: what [`BlendState::apply`]
/// computes, kept for a person to read (`ps30 render --pixel`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Terms {
    /// The source as the blender takes it (half-rounded, f32, or clamped
    /// to [0, 1] for an 8-bit target).
    pub source: [f64; 4],
    /// The destination texel as the target stores it.
    pub dest: [f64; 4],
    /// Each channel's source factor (`None` for MIN and MAX, which take
    /// none).
    pub source_factor: [Option<f64>; 4],
    /// Each channel's destination factor.
    pub dest_factor: [Option<f64>; 4],
    /// The blended texel, rounded as the target stores it (before the
    /// write mask); equal to [`BlendState::apply`]'s.
    pub result: [f32; 4],
}

impl BlendState {
    /// [`BlendState::apply`] with its terms; `None` when blending is off
    /// (the source replaces the texel).
    pub fn terms(&self, format: TargetFormat, src: [f32; 4], dst: [f32; 4]) -> Option<Terms> {
        if !self.enabled {
            return None;
        }
        let p = Precision::of(format.encoding());
        let s = src.map(|c| p.source(c));
        let d = dst.map(f64::from);
        let k = self.factor.map(|b| p.round(b as f64 / 255.0));
        let factor = |f: fn(&Equation) -> BlendFactor, c: usize| {
            let eq = self.equation(c);
            (!matches!(eq.op, BlendOp::Min | BlendOp::Max)).then(|| p.factor(f(&eq), c, &s, &d, &k))
        };
        Some(Terms {
            source: s,
            dest: d,
            source_factor: std::array::from_fn(|c| factor(|e| e.src, c)),
            dest_factor: std::array::from_fn(|c| factor(|e| e.dest, c)),
            result: self.apply(format, src, dst),
        })
    }
}

/// The arithmetic of one target encoding (see the module docs).
#[derive(Clone, Copy, Debug)]
enum Precision {
    Half,
    Single,
    /// f32 arithmetic on a source clamped to [0, 1].
    Unorm,
}

impl Precision {
    fn of(e: Encoding) -> Precision {
        match e {
            Encoding::Half => Precision::Half,
            Encoding::Float => Precision::Single,
            Encoding::Unorm8 => Precision::Unorm,
        }
    }

    /// `x` rounded to the working precision.
    fn round(self, x: f64) -> f64 {
        match self {
            Precision::Half => crate::core::image::half_from_f64(x),
            Precision::Single | Precision::Unorm => x as f32 as f64,
        }
    }

    /// The shader's output as the blender takes it.
    fn source(self, c: f32) -> f64 {
        match self {
            Precision::Half => f16::from_f32(c).to_f64(),
            Precision::Single => c as f64,
            Precision::Unorm if c.is_nan() => 0.0,
            Precision::Unorm => c.clamp(0.0, 1.0) as f64,
        }
    }

    /// The factor `f` for channel `c`.
    fn factor(self, f: BlendFactor, c: usize, s: &[f64; 4], d: &[f64; 4], k: &[f64; 4]) -> f64 {
        let inv = |x: f64| self.round(1.0 - x);
        match f {
            BlendFactor::Zero => 0.0,
            BlendFactor::One => 1.0,
            BlendFactor::SrcColor => s[c],
            BlendFactor::InvSrcColor => inv(s[c]),
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::InvSrcAlpha => inv(s[3]),
            BlendFactor::DestAlpha => d[3],
            BlendFactor::InvDestAlpha => inv(d[3]),
            BlendFactor::DestColor => d[c],
            BlendFactor::InvDestColor => inv(d[c]),
            BlendFactor::SrcAlphaSat if c == 3 => 1.0,
            BlendFactor::SrcAlphaSat => s[3].min(inv(d[3])),
            BlendFactor::Constant => k[c],
            BlendFactor::InvConstant => inv(k[c]),
        }
    }
}
