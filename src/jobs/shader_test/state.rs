//! The state vkd3d's runner keeps while it walks a file — targets,
//! textures, vertex buffers, fixed-function state, the draws not yet
//! replayed — and how a line ends the walk. Its own module so that the
//! runner, the draws and the probes all read it without reading each other.

use super::resource::Texture;
use super::{CompileJob, FileReport, Settings};
use crate::core::emu::SamplerState;
use crate::core::image::RenderTarget;
use crate::core::raster::fog::FogMode;
use crate::jobs::render::DrawList;
use std::collections::{BTreeMap, HashMap};

pub(super) enum Mode<'a> {
    Plan(Vec<CompileJob>),
    Run(&'a HashMap<CompileJob, Result<Vec<u8>, String>>),
}

/// A shader section's source.
#[derive(Clone, Debug)]
pub(super) struct Source {
    pub text: String,
    /// `d3dbc-hex`: bytecode written as hexadecimal words.
    pub hex: bool,
    /// `dxbc-tpf-hex`/`dxbc-dxil-hex`: bytecode of shader model 4 and above.
    pub foreign: bool,
}

/// A render target of the file (`[rtv N]` or the default one).
pub(super) struct Rtv {
    pub target: RenderTarget,
}

/// One `[input layout]` line.
#[derive(Clone, Debug)]
pub(super) struct Element {
    pub slot: u32,
    pub format: String,
    pub size: u32,
    pub name: String,
    pub index: u32,
}

/// The fixed-function state test lines set.
#[derive(Clone, Debug)]
pub(super) struct Fixed {
    pub alpha_func: u32,
    pub alpha_ref: f32,
    pub flat: bool,
    pub clip_mask: u8,
    pub clip_planes: [[f32; 4]; 8],
    pub point_size: [f32; 3],
    pub point_sprite: bool,
    /// `fog MODE`: D3DRS_FOGTABLEMODE (`none` is vertex fog); `None`:
    /// `fog disable` (D3DRS_FOGENABLE off).
    pub fog: Option<FogMode>,
    /// `fog-colour`: D3DRS_FOGCOLOR's channels (a D3DCOLOR: × 255, truncated).
    pub fog_colour: [f32; 4],
    /// D3DRS_FOGSTART, D3DRS_FOGEND, D3DRS_FOGDENSITY.
    pub fog_start: f32,
    pub fog_end: f32,
    pub fog_density: f32,
    /// `ortho`: the runner's projection matrix is the identity (z fog);
    /// `non-ortho` (the start) sets its _44 to 1.01, which gives w fog.
    pub ortho_fog: bool,
    pub viewports: bool,
}

/// How the last draw ended; probes after it inherit a failure.
#[derive(Clone, Debug)]
pub(super) enum Last {
    Ok,
    Failed(String),
    Unsupported(String),
}

/// A line vkd3d's runner ends the whole run at (`fatal_error`): either
/// something the Direct3D 9 runner refuses (UAVs, compute, viewports), or
/// a line that is malformed (bad input).
#[derive(Clone, Debug)]
pub(super) struct Stop {
    pub message: String,
    /// The Direct3D 9 runner's own refusal rather than malformed input.
    pub refused: bool,
}

impl Stop {
    /// What vkd3d's Direct3D 9 runner refuses, by name.
    pub fn refused(what: &str) -> Stop {
        Stop {
            message: format!("{what} (vkd3d's Direct3D 9 runner stops here)"),
            refused: true,
        }
    }

    /// The message with its line in front (once: the innermost line).
    pub(super) fn at(self, line: usize) -> Stop {
        if self.message.starts_with("line ") {
            return self;
        }
        Stop {
            message: format!("line {line}: {}", self.message),
            ..self
        }
    }
}

impl From<String> for Stop {
    fn from(message: String) -> Stop {
        Stop {
            message,
            refused: false,
        }
    }
}

impl From<&str> for Stop {
    fn from(message: &str) -> Stop {
        message.to_string().into()
    }
}

pub(super) struct State<'a> {
    pub mode: Mode<'a>,
    pub settings: Option<&'a Settings>,
    pub min_sm: usize,
    pub max_sm: usize,
    pub skip: bool,
    pub flags: Vec<&'static str>,
    pub shaders: BTreeMap<String, Source>,
    pub fail_mask: u32,
    pub uniforms: Vec<u32>,
    pub rtvs: BTreeMap<u32, Rtv>,
    pub srvs: BTreeMap<u32, Result<Texture, String>>,
    pub vbs: BTreeMap<u32, Vec<u8>>,
    pub samplers: BTreeMap<u32, SamplerState>,
    pub layout: Vec<Element>,
    pub fixed: Fixed,
    pub last: Last,
    /// Clears and draws not yet applied to `rtvs` ([`super::draw::replay`]).
    pub pending: Vec<Op>,
    pub report: FileReport,
}

/// What the targets go through after the file made them: clears and draws
/// in order. They run when a probe reads a target, each draw restricted to
/// the probe's rectangle by the scissor test: Direct3D 9 computes a pixel
/// from its own quad alone (helper pixels outside the rectangle still run
/// for gradients), so the pixels probed are those of the whole draw, and a
/// file's 640 × 480 draws cost what their probes read.
#[derive(Clone, Debug)]
pub(super) enum Op {
    /// `clear rtv N`: the slot and its D3DCOLOR bytes.
    Clear(u32, [u8; 4]),
    /// A draw and the render-target slots it was drawn with, in the list's order.
    Draw(Box<DrawList>, Vec<u32>),
}
