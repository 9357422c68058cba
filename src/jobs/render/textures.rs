//! Texture files and per-axis sampler states of draw lists: a texture named
//! by `image` may be a DDS file (2D, cube or volume, with its own mip
//! levels) as well as an OpenEXR, Radiance or PFM image, and a sampler may
//! set ADDRESSU/V/W and MIN/MAGFILTER one by one, and its texture stage's
//! bump-environment state (ps_1_x's `texbem`, `texbeml`, `bem`).
//!
//! Kept apart from `file.rs` so that what a texture file means for a draw
//! (which sampler type it answers, how many texels it holds against the
//! list's budget) is in one place, shared with `run`'s `--inputs`.

use crate::core::emu::{Address, Filter, SamplerState};
use crate::core::image::{self, ImageLimits, TextureFile};
use crate::core::ps1::run::BumpEnv;
use std::path::Path;

/// A loaded texture: its level-0 size, its texels when it is a plain 2D
/// image of one level, or the whole file otherwise.
pub struct Loaded {
    /// Width of level 0.
    pub width: u32,
    /// Height of level 0.
    pub height: u32,
    /// Level 0's texels, for a 2D texture of one level (else empty).
    pub texels: Vec<[f32; 4]>,
    /// The file's levels, faces and slices when it has more than one level
    /// 0 image.
    pub file: Option<TextureFile>,
    /// Texels of every level, face and slice together.
    pub texel_count: u64,
}

/// Reads a texture file under a budget of `max_texels` texels (the file
/// itself may be at most 16 bytes a texel plus its headers).
pub fn load(path: &Path, max_texels: u64) -> Result<Loaded, String> {
    let limits = ImageLimits {
        max_pixels: max_texels.max(1),
    };
    let max_bytes = max_texels.saturating_mul(16).saturating_add(1 << 16);
    let file = image::load_texture(path, &limits, max_bytes).map_err(|e| e.to_string())?;
    let (width, height) = file.size();
    let texel_count = texels_of(&file);
    match file {
        TextureFile::Flat(c) if c.len() == 1 => {
            let texels = c.level(0).map(|l| l.texels.to_vec()).unwrap_or_default();
            Ok(Loaded {
                width,
                height,
                texels,
                file: None,
                texel_count,
            })
        }
        file => Ok(Loaded {
            width,
            height,
            texels: Vec::new(),
            file: Some(file),
            texel_count,
        }),
    }
}

/// Texels of every level, face and slice of `file`.
pub fn texels_of(file: &TextureFile) -> u64 {
    let chain = |c: &image::MipChain| {
        c.views()
            .iter()
            .map(|l| l.width as u64 * l.height as u64)
            .sum::<u64>()
    };
    match file {
        TextureFile::Flat(c) => chain(c),
        TextureFile::Cube(c) => (0..6).map(|f| chain(c.face(f))).sum(),
        TextureFile::Volume(v) => (0..v.len())
            .filter_map(|i| v.level(i))
            .map(|l| l.width as u64 * l.height as u64 * l.depth as u64)
            .sum(),
    }
}

/// An address mode by its draw-list name.
pub fn address(v: &str) -> Result<Address, String> {
    Ok(match v {
        "wrap" => Address::Wrap,
        "mirror" => Address::Mirror,
        "clamp" => Address::Clamp,
        "border" => Address::Border,
        "mirroronce" => Address::MirrorOnce,
        v => {
            return Err(format!(
                "`{v}` is not one of wrap, mirror, clamp, border, mirroronce"
            ))
        }
    })
}

/// A filter by its draw-list name.
pub fn filter(v: &str) -> Result<Filter, String> {
    match v {
        "point" => Ok(Filter::Point),
        "linear" => Ok(Filter::Linear),
        v => Err(format!("`{v}` is not one of point, linear")),
    }
}

/// The per-axis and per-filter overrides of a sampler: `address_u`,
/// `address_v`, `address_w`, `min_filter`, `mag_filter` (each `None` keeps
/// what `address`/`filter` set). Errors name the field.
pub fn overrides(
    state: &mut SamplerState,
    axes: [Option<&str>; 3],
    filters: [Option<&str>; 2],
) -> Result<(), (String, String)> {
    for (i, (name, a)) in ["address_u", "address_v", "address_w"]
        .iter()
        .zip(axes)
        .enumerate()
    {
        if let Some(a) = a {
            let m = address(a).map_err(|e| (name.to_string(), e))?;
            match i {
                0 => state.address_u = m,
                1 => state.address_v = m,
                _ => state.address_w = m,
            }
        }
    }
    if let Some(f) = filters[0] {
        state.min_filter = filter(f).map_err(|e| ("min_filter".to_string(), e))?;
    }
    if let Some(f) = filters[1] {
        state.mag_filter = filter(f).map_err(|e| ("mag_filter".to_string(), e))?;
    }
    Ok(())
}

/// A sampler as a draw list writes it (a draw's `samplers` entry, or its
/// geometry's `vertex_samplers`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileSampler {
    pub(crate) texture: String,
    pub(crate) filter: Option<String>,
    pub(crate) mip: Option<String>,
    pub(crate) address: Option<String>,
    pub(crate) border: Option<[f64; 4]>,
    pub(crate) lod_bias: Option<f64>,
    pub(crate) max_mip_level: Option<u32>,
    pub(crate) address_u: Option<String>,
    pub(crate) address_v: Option<String>,
    pub(crate) address_w: Option<String>,
    pub(crate) min_filter: Option<String>,
    pub(crate) mag_filter: Option<String>,
    /// D3DTSS_BUMPENVMAT00, 01, 10, 11 of the stage (ps_1_x).
    pub(crate) bump_matrix: Option<[f64; 4]>,
    /// D3DTSS_BUMPENVLSCALE.
    pub(crate) bump_lscale: Option<f64>,
    /// D3DTSS_BUMPENVLOFFSET.
    pub(crate) bump_loffset: Option<f64>,
}

impl FileSampler {
    /// The stage's bump-environment state, `None` where the entry sets
    /// none of it; unset parts take Direct3D 9's default, 0. Each value
    /// must be a finite f32; an error names the field.
    pub(crate) fn bump_env(&self) -> Result<Option<BumpEnv>, (String, String)> {
        if self.bump_matrix.is_none() && self.bump_lscale.is_none() && self.bump_loffset.is_none() {
            return Ok(None);
        }
        let finite = |field: &str, x: f64| {
            let f = x as f32;
            if f.is_finite() {
                Ok(f)
            } else {
                Err((field.to_string(), format!("{x:e} is not a finite f32")))
            }
        };
        let mut env = BumpEnv::default();
        for (i, &x) in self.bump_matrix.iter().flatten().enumerate() {
            env.matrix[i] = finite("bump_matrix", x)?;
        }
        if let Some(x) = self.bump_lscale {
            env.lscale = finite("bump_lscale", x)?;
        }
        if let Some(x) = self.bump_loffset {
            env.loffset = finite("bump_loffset", x)?;
        }
        Ok(Some(env))
    }
}
