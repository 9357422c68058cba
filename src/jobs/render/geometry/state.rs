//! The render states of a draw of geometry beyond the first set (`mod.rs`):
//! lines (D3DRS_LASTPIXEL), point sizes and sprites (D3DRS_POINTSIZE_MIN,
//! _MAX, D3DRS_POINTSPRITEENABLE, D3DRS_POINTSCALEENABLE with its A, B, C),
//! the fill mode (D3DRS_FILLMODE), fog (D3DRS_FOGENABLE, FOGTABLEMODE,
//! FOGCOLOR, FOGSTART, FOGEND, FOGDENSITY) and the stencil test (D3DRS_STENCILENABLE
//! and the states it reads, two-sided included). This module reads their
//! fields into a plain [`RasterState`]; the rules themselves live in
//! `core/raster` (`line`, `points`, `stencil`).
//!
//! ```json
//! "geometry": { "primitive": "line_strip", "last_pixel": false,
//!   "point_size_min": 1, "point_size_max": 64, "point_sprite": true,
//!   "fill_mode": "wireframe",
//!   "stencil": { "func": "EQUAL", "ref": 1, "mask": 255, "write_mask": 255,
//!                "fail": "KEEP", "zfail": "KEEP", "pass": "INCRSAT",
//!                "ccw": { "func": "ALWAYS", "pass": "DECRSAT" }, "clear": 0 } }
//! ```

use super::super::pixel_state::CmpFunc;
use super::Problem;
use crate::core::raster::fog::{Fog, FogMode};
use crate::core::raster::points::PointState;
use crate::core::raster::stencil::{StencilOp, StencilOps};
use serde::Deserialize;

/// D3DRS_FILLMODE.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FillMode {
    /// D3DFILL_POINT: each triangle's vertices drawn as points.
    Point,
    /// D3DFILL_WIREFRAME: each triangle's edges drawn as lines.
    Wireframe,
    /// D3DFILL_SOLID (the default).
    #[default]
    Solid,
}

/// One facing's stencil function and operations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StencilSide {
    /// D3DRS_STENCILFUNC (or D3DRS_CCW_STENCILFUNC).
    pub func: CmpFunc,
    /// The fail, z-fail and pass operations.
    pub ops: StencilOps,
}

/// The stencil test (D3DRS_STENCILENABLE on).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StencilState {
    /// Clockwise triangles, lines and points (all of them without
    /// two-sided stencil).
    pub cw: StencilSide,
    /// D3DRS_TWOSIDEDSTENCILMODE on: counter-clockwise triangles' side.
    pub ccw: Option<StencilSide>,
    /// D3DRS_STENCILREF.
    pub reference: u8,
    /// D3DRS_STENCILMASK (the stencil's eight bits of it).
    pub mask: u8,
    /// D3DRS_STENCILWRITEMASK (its eight bits).
    pub write_mask: u8,
    /// Clear(D3DCLEAR_STENCIL) to this value before the draw; a surface
    /// never cleared starts at 0.
    pub clear: Option<u8>,
}

/// The states of this module, resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterState {
    /// D3DRS_LASTPIXEL (default TRUE).
    pub last_pixel: bool,
    /// Point size, its clamps, scaling and sprites.
    pub points: PointState,
    /// D3DRS_FILLMODE.
    pub fill: FillMode,
    /// The stencil test; `None`: D3DRS_STENCILENABLE off.
    pub stencil: Option<StencilState>,
    /// Fixed-function fog; `None`: D3DRS_FOGENABLE off.
    pub fog: Option<Fog>,
}

impl Default for RasterState {
    fn default() -> RasterState {
        RasterState {
            last_pixel: true,
            points: PointState::default(),
            fill: FillMode::Solid,
            stencil: None,
            fog: None,
        }
    }
}

/// `stencil` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileStencil {
    func: Option<String>,
    #[serde(rename = "ref")]
    reference: Option<u32>,
    mask: Option<u32>,
    write_mask: Option<u32>,
    fail: Option<String>,
    zfail: Option<String>,
    pass: Option<String>,
    ccw: Option<FileSide>,
    clear: Option<u32>,
}

/// `stencil.ccw` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileSide {
    func: Option<String>,
    fail: Option<String>,
    zfail: Option<String>,
    pass: Option<String>,
}

/// The fields of this module as the `geometry` object holds them.
pub(crate) struct Fields<'a> {
    pub last_pixel: Option<bool>,
    pub point_size: f64,
    pub point_size_min: Option<f64>,
    pub point_size_max: Option<f64>,
    pub point_sprite: Option<bool>,
    pub point_scale: Option<[f64; 3]>,
    pub fill_mode: Option<&'a str>,
    pub stencil: Option<&'a FileStencil>,
    pub fog: Option<&'a FileFog>,
}

/// `fog` as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileFog {
    mode: Option<String>,
    color: Option<Vec<f32>>,
    start: Option<f64>,
    end: Option<f64>,
    density: Option<f64>,
    depth: Option<String>,
}

fn fog(f: &FileFog) -> Result<Fog, Problem> {
    let mode = match f.mode.as_deref().map(str::to_ascii_uppercase).as_deref() {
        None | Some("VERTEX") | Some("NONE") | Some("D3DFOG_NONE") => FogMode::Vertex,
        Some("LINEAR") | Some("D3DFOG_LINEAR") => FogMode::Linear,
        Some("EXP") | Some("D3DFOG_EXP") => FogMode::Exp,
        Some("EXP2") | Some("D3DFOG_EXP2") => FogMode::Exp2,
        Some(_) => {
            return Err(problem(
                "fog.mode",
                "\"vertex\" (D3DFOG_NONE), \"linear\", \"exp\" or \"exp2\"",
            ))
        }
    };
    let mut color = [0.0, 0.0, 0.0, 1.0];
    match f.color.as_deref() {
        None => {}
        Some(c) if (3..=4).contains(&c.len()) && c.iter().all(|x| x.is_finite()) => {
            color[..c.len()].copy_from_slice(c)
        }
        Some(_) => {
            return Err(problem(
                "fog.color",
                "3 or 4 finite numbers (red, green, blue, alpha)",
            ))
        }
    }
    let fog = Fog {
        mode,
        color,
        start: f.start.unwrap_or(0.0),
        end: f.end.unwrap_or(1.0),
        density: f.density.unwrap_or(1.0),
        w: match f.depth.as_deref().map(str::to_ascii_lowercase).as_deref() {
            None | Some("z") => false,
            Some("w") if mode != FogMode::Vertex => true,
            Some("w") => return Err(problem("fog.depth", "vertex fog reads no depth")),
            Some(_) => {
                return Err(problem(
                    "fog.depth",
                    "\"z\" or \"w\" (w where the projection matrix's fourth column is not [0, 0, 0, 1])",
                ))
            }
        },
    };
    if ![fog.start, fog.end, fog.density]
        .iter()
        .all(|x| x.is_finite())
    {
        return Err(problem("fog", "start, end and density must be finite"));
    }
    if mode == FogMode::Linear && fog.start == fog.end {
        return Err(problem("fog.end", "linear fog needs end ≠ start"));
    }
    Ok(fog)
}

fn problem(field: &str, message: impl Into<String>) -> Problem {
    (field.to_string(), message.into())
}

/// Reads the fields into a [`RasterState`].
pub(crate) fn read(f: &Fields) -> Result<RasterState, Problem> {
    let size = |v: Option<f64>, field: &str, default: f64| match v {
        None => Ok(default),
        Some(s) if (0.0..=8192.0).contains(&s) => Ok(s),
        Some(_) => Err(problem(field, "a size in pixels from 0 to 8192")),
    };
    let min = size(f.point_size_min, "point_size_min", 1.0)?;
    let max = size(f.point_size_max, "point_size_max", 64.0)?;
    if min > max {
        return Err(problem(
            "point_size_min",
            format!("{min} is above point_size_max {max}"),
        ));
    }
    if let Some(s) = f.point_scale {
        if s.iter().any(|c| !c.is_finite() || *c < 0.0) || s == [0.0; 3] {
            return Err(problem(
                "point_scale",
                "[A, B, C]: finite, none negative, not all 0",
            ));
        }
    }
    let fill = match f.fill_mode.map(str::to_ascii_lowercase).as_deref() {
        None | Some("solid") | Some("d3dfill_solid") => FillMode::Solid,
        Some("wireframe") | Some("d3dfill_wireframe") => FillMode::Wireframe,
        Some("point") | Some("d3dfill_point") => FillMode::Point,
        Some(_) => {
            return Err(problem(
                "fill_mode",
                "not \"solid\", \"wireframe\" or \"point\"",
            ))
        }
    };
    Ok(RasterState {
        last_pixel: f.last_pixel.unwrap_or(true),
        points: PointState {
            size: f.point_size,
            min,
            max,
            sprite: f.point_sprite.unwrap_or(false),
            scale: f.point_scale,
        },
        fill,
        stencil: f.stencil.map(stencil).transpose()?,
        fog: f.fog.map(fog).transpose()?,
    })
}

fn func(name: Option<&String>, field: &str) -> Result<CmpFunc, Problem> {
    match name {
        None => Ok(CmpFunc::Always),
        Some(f) => CmpFunc::from_name(&f.to_ascii_uppercase())
            .ok_or_else(|| problem(field, format!("`{f}` is not a D3DCMPFUNC"))),
    }
}

fn op(name: Option<&String>, field: &str) -> Result<StencilOp, Problem> {
    match name {
        None => Ok(StencilOp::Keep),
        Some(o) => StencilOp::from_name(o).ok_or_else(|| {
            let names: Vec<&str> = StencilOp::ALL.iter().map(|(n, _)| *n).collect();
            problem(
                field,
                format!("`{o}` is not a D3DSTENCILOP ({})", names.join(", ")),
            )
        }),
    }
}

fn side(
    (f, fail, zfail, pass): (
        Option<&String>,
        Option<&String>,
        Option<&String>,
        Option<&String>,
    ),
    at: &str,
) -> Result<StencilSide, Problem> {
    Ok(StencilSide {
        func: func(f, &format!("{at}func"))?,
        ops: StencilOps {
            fail: op(fail, &format!("{at}fail"))?,
            zfail: op(zfail, &format!("{at}zfail"))?,
            pass: op(pass, &format!("{at}pass"))?,
        },
    })
}

fn stencil(s: &FileStencil) -> Result<StencilState, Problem> {
    let byte = |v: Option<u32>, field: &str, default: u8| match v {
        None => Ok(default),
        Some(v) => u8::try_from(v)
            .map_err(|_| problem(field, format!("{v}: D3DFMT_D24S8's stencil holds 0 to 255"))),
    };
    // The masks are DWORDs (0xFFFFFFFF by default); the stencil's eight
    // bits are what they mask.
    let mask = |v: Option<u32>| v.map_or(0xFF, |m| (m & 0xFF) as u8);
    Ok(StencilState {
        cw: side(
            (
                s.func.as_ref(),
                s.fail.as_ref(),
                s.zfail.as_ref(),
                s.pass.as_ref(),
            ),
            "stencil.",
        )?,
        ccw: s
            .ccw
            .as_ref()
            .map(|c| {
                side(
                    (
                        c.func.as_ref(),
                        c.fail.as_ref(),
                        c.zfail.as_ref(),
                        c.pass.as_ref(),
                    ),
                    "stencil.ccw.",
                )
            })
            .transpose()?,
        reference: byte(s.reference, "stencil.ref", 0)?,
        mask: mask(s.mask),
        write_mask: mask(s.write_mask),
        clear: s
            .clear
            .map(|c| byte(Some(c), "stencil.clear", 0))
            .transpose()?,
    })
}
