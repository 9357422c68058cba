//! Texture sampling for the texld family (facts sheet §5).
//!
//! Kept apart from the executor because the rules (texel centres, address
//! modes on integer texel indices, border colour, bilinear weights) are
//! independent of how lanes are scheduled, and because point + border — the
//! luminance pass default — gets its own tight lane loop.
//!
//! Conventions (MS-D9 "Directly Mapping Texels to Pixels", "Nearest-Point
//! Sampling", "Bilinear Texture Filtering"; integer address formulas from the
//! D3D11.3 functional spec §7.18.9, the closest public definition):
//! * texture coordinate (0,0) is the top-left *corner* of the texture, texel
//!   i's centre is at (i + 0.5)/n; row 0 of [`Texture::texels`] is the top;
//! * point: texel = floor(u·n), then the address mode on the integer index;
//! * bilinear: u' = u·n − 0.5, t0 = floor(u'), w1 = frac(u'); each of the four
//!   taps is addressed independently; a tap outside under BORDER is the border
//!   colour. Weights are applied as `(c00·(1−wx) + c10·wx)·(1−wy) +
//!   (c01·(1−wx) + c11·wx)·wy` in f32;
//! * only mip level 0 exists, so texldb's bias, texldl's LOD and texldd's
//!   gradients do not change the result.

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::{Address, Filter, SamplerState, Texture, LANES};

/// Largest texture side accepted (keeps texel coordinates below 2^23, where
/// [`floor_index`] is exact).
pub const MAX_TEXTURE_SIDE: u32 = 1 << 22;

/// Texel index meaning "border colour" (textures have fewer texels).
const BORDER: u32 = u32::MAX;

/// `floor` without a libm call (baseline x86-64 has no rounding
/// instruction): exact for every f32; NaN stays NaN. Only used for texel
/// indices, where the sign of a zero does not matter.
#[inline(always)]
fn floor(x: f32) -> f32 {
    if x.abs() < 8_388_608.0 {
        let t = x as i32 as f32;
        if t > x {
            t - 1.0
        } else {
            t
        }
    } else {
        x
    }
}

/// A bound texture with its sampler state, sizes precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Sampler<'a> {
    texels: &'a [[f32; 4]],
    w: usize,
    wi: i64,
    hi: i64,
    wf: f32,
    hf: f32,
    filter: Filter,
    au: Address,
    av: Address,
    border: [f32; 4],
}

/// Applies an address mode to an integer texel index; `None` = border.
#[inline(always)]
fn address(t: i64, n: i64, mode: Address) -> Option<i64> {
    match mode {
        Address::Wrap => Some(t.rem_euclid(n)),
        Address::Mirror => {
            // -(t + 1) cannot overflow for negative t.
            let t = if t < 0 { -(t + 1) } else { t };
            let flip = (t / n) & 1 == 1;
            let t = t % n;
            Some(if flip { n - 1 - t } else { t })
        }
        Address::Clamp => Some(t.clamp(0, n - 1)),
        Address::MirrorOnce => {
            let t = if t < 0 { -(t + 1) } else { t };
            Some(t.min(n - 1))
        }
        Address::Border => {
            if (0..n).contains(&t) {
                Some(t)
            } else {
                None
            }
        }
    }
}

/// floor(t) as an integer for 0 <= t < 2^23, using only float adds and bit
/// operations so that lane loops vectorise (Rust's saturating `as i32` does
/// not). Other inputs give unspecified values (callers discard them).
#[inline(always)]
fn floor_index(t: f32) -> u32 {
    const MAGIC: f32 = 8_388_608.0; // 2^23
                                    // Adding 2^23 rounds t to an integer (to nearest); step down if it went up.
    let r = (t + MAGIC) - MAGIC;
    let f = if r > t { r - 1.0 } else { r };
    (f + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits())
}

impl<'a> Sampler<'a> {
    /// Checks the texture's shape and precomputes sizes.
    pub fn new(tex: &Texture<'a>, state: &SamplerState) -> Result<Sampler<'a>, String> {
        if tex.width == 0 || tex.height == 0 {
            return Err(format!("size {}x{} is empty", tex.width, tex.height));
        }
        if tex.width > MAX_TEXTURE_SIDE || tex.height > MAX_TEXTURE_SIDE {
            return Err(format!(
                "size {}x{} exceeds {} per side",
                tex.width, tex.height, MAX_TEXTURE_SIDE
            ));
        }
        let want = tex.width as usize * tex.height as usize;
        if want as u64 >= BORDER as u64 {
            return Err(format!(
                "size {}x{} has too many texels",
                tex.width, tex.height
            ));
        }
        if tex.texels.len() != want {
            return Err(format!(
                "{}x{} needs {} texels, got {}",
                tex.width,
                tex.height,
                want,
                tex.texels.len()
            ));
        }
        Ok(Sampler {
            texels: tex.texels,
            w: tex.width as usize,
            wi: tex.width as i64,
            hi: tex.height as i64,
            wf: tex.width as f32,
            hf: tex.height as f32,
            filter: state.filter,
            au: state.address_u,
            av: state.address_v,
            border: state.border,
        })
    }

    #[inline(always)]
    fn fetch(&self, x: Option<i64>, y: Option<i64>) -> [f32; 4] {
        match (x, y) {
            (Some(x), Some(y)) => self
                .texels
                .get(y as usize * self.w + x as usize)
                .copied()
                .unwrap_or(self.border),
            _ => self.border,
        }
    }

    /// Point sampling with any address mode.
    #[inline(always)]
    pub fn point(&self, u: f32, v: f32) -> [f32; 4] {
        // `as` saturates (NaN gives 0), so any coordinate is safe.
        let x = floor(u * self.wf) as i64;
        let y = floor(v * self.hf) as i64;
        self.fetch(address(x, self.wi, self.au), address(y, self.hi, self.av))
    }

    /// Texel index for point sampling with BORDER on both axes (the
    /// luminance-pass default), or [`BORDER`]. NaN fails the comparisons.
    #[inline(always)]
    fn point_border_index(&self, u: f32, v: f32) -> u32 {
        let x = u * self.wf;
        let y = v * self.hf;
        let inside = x >= 0.0 && x < self.wf && y >= 0.0 && y < self.hf;
        let i = floor_index(y)
            .wrapping_mul(self.w as u32)
            .wrapping_add(floor_index(x));
        if inside {
            i
        } else {
            BORDER
        }
    }

    /// Bilinear sampling.
    pub fn linear(&self, u: f32, v: f32) -> [f32; 4] {
        let fu = u * self.wf - 0.5;
        let fv = v * self.hf - 0.5;
        let (tu, tv) = (floor(fu), floor(fv));
        let (wx, wy) = (fu - tu, fv - tv);
        let (x0, y0) = (tu as i64, tv as i64);
        let x = [
            address(x0, self.wi, self.au),
            address(x0.saturating_add(1), self.wi, self.au),
        ];
        let y = [
            address(y0, self.hi, self.av),
            address(y0.saturating_add(1), self.hi, self.av),
        ];
        let c00 = self.fetch(x[0], y[0]);
        let c10 = self.fetch(x[1], y[0]);
        let c01 = self.fetch(x[0], y[1]);
        let c11 = self.fetch(x[1], y[1]);
        let mut out = [0.0; 4];
        for c in 0..4 {
            let top = c00[c] * (1.0 - wx) + c10[c] * wx;
            let bottom = c01[c] * (1.0 - wx) + c11[c] * wx;
            out[c] = top * (1.0 - wy) + bottom * wy;
        }
        out
    }

    /// Samples every lane; `out[c]` receives sampled component `swz(c)`.
    pub fn sample_lanes(
        &self,
        u: &[f32; LANES],
        v: &[f32; LANES],
        swz: [usize; 4],
        out: &mut [[f32; LANES]; 4],
    ) {
        match (self.filter, self.au, self.av) {
            (Filter::Point, Address::Border, Address::Border) => {
                // Indices first (vectorises), then the gather.
                let mut idx = [BORDER; LANES];
                for l in 0..LANES {
                    idx[l] = self.point_border_index(u[l], v[l]);
                }
                if swz == [0, 1, 2, 3] {
                    for l in 0..LANES {
                        let t = self.texels.get(idx[l] as usize).unwrap_or(&self.border);
                        for c in 0..4 {
                            out[c][l] = t[c];
                        }
                    }
                } else {
                    for l in 0..LANES {
                        let t = self.texels.get(idx[l] as usize).unwrap_or(&self.border);
                        for c in 0..4 {
                            out[c][l] = t[swz[c]];
                        }
                    }
                }
            }
            (Filter::Point, _, _) => {
                for l in 0..LANES {
                    let t = self.point(u[l], v[l]);
                    for c in 0..4 {
                        out[c][l] = t[swz[c]];
                    }
                }
            }
            (Filter::Linear, _, _) => {
                for l in 0..LANES {
                    let t = self.linear(u[l], v[l]);
                    for c in 0..4 {
                        out[c][l] = t[swz[c]];
                    }
                }
            }
        }
    }
}

/// The value of an unbound sampler: (0, 0, 0, 1) (MS `texldl---ps`).
pub const UNBOUND: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
