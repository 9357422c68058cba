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
//! * mip selection (facts sheet §5; Microsoft's `texldl` page gives the
//!   reference device's rule, the D3D11.3 spec §7.18.10-11 the formula): the
//!   LOD λ comes from the executor (implicit gradients, texldb's bias,
//!   texldl's w, texldd's gradients) with D3DSAMP_MIPMAPLODBIAS added. λ ≤ 0
//!   (or NaN) reads the base level with the MAGFILTER; otherwise the
//!   MINFILTER is used and λ is raised to MAXMIPLEVEL: MIPFILTER NONE reads
//!   the base level, POINT the level round(λ) = ⌊λ + ½⌋, LINEAR blends
//!   levels ⌊λ⌋ and ⌊λ⌋ + 1 by frac(λ) (the reference device's pseudo-code
//!   blends by frac(src0.w), without the bias; ps30 uses frac(λ) as D3D11
//!   does). λ beyond the last level reads the last level. The *base level*
//!   is MAXMIPLEVEL clamped to the chain (D3D9 gives no rule for MAXMIPLEVEL
//!   with MIPFILTER NONE; ps30 treats it as the base level, as GL's
//!   BASE_LEVEL).

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::layered::{address, cube_face, finite_coordinate, Level3};
use super::{Address, Filter, MipFilter, SamplerState, Texture, TextureLevels, LANES};

pub use super::layered::MAX_TEXTURE_SIDE;

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

/// One mip level with its sizes and addressing precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Level<'a> {
    texels: &'a [[f32; 4]],
    w: usize,
    wi: i64,
    hi: i64,
    wf: f32,
    hf: f32,
    au: Address,
    av: Address,
    border: [f32; 4],
}

/// A bound texture (all its levels) with its sampler state.
#[derive(Clone, Debug)]
pub struct Sampler<'a> {
    levels: Vec<Level<'a>>,
    /// MAXMIPLEVEL clamped to the chain.
    base: usize,
    mag: Filter,
    min: Filter,
    mip: MipFilter,
    bias: f32,
    /// Whether the LOD can change a sample (see [`Sampler::lod_matters`]).
    lod_matters: bool,
    /// What the texture is besides its `levels`.
    shape: Shape<'a>,
}

/// The texture type of a [`Sampler`].
#[derive(Clone, Debug)]
enum Shape<'a> {
    /// A 2D texture: `levels` is all of it.
    Flat,
    /// A cube: `[face][level]`, addressed with CLAMP on each face (face 0
    /// is also `levels`).
    Cube(Vec<Vec<Level<'a>>>),
    /// A volume: its levels (`levels` holds their first slices, for the
    /// sizes and the level count).
    Volume(Vec<Level3<'a>>),
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

impl<'a> Level<'a> {
    /// Checks the texture's shape and precomputes sizes.
    pub(super) fn new(tex: &Texture<'a>, state: &SamplerState) -> Result<Level<'a>, String> {
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
        Ok(Level {
            texels: tex.texels,
            w: tex.width as usize,
            wi: tex.width as i64,
            hi: tex.height as i64,
            wf: tex.width as f32,
            hf: tex.height as f32,
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
        let (u, v) = (finite_coordinate(u), finite_coordinate(v));
        // `as` saturates (a finite u·n past i64 stays past the edge).
        let x = floor(u * self.wf) as i64;
        let y = floor(v * self.hf) as i64;
        self.fetch(address(x, self.wi, self.au), address(y, self.hi, self.av))
    }

    /// Texel index for point sampling with BORDER on both axes (the
    /// luminance-pass default), or [`BORDER`]. NaN fails the comparisons.
    #[inline(always)]
    fn point_border_index(&self, u: f32, v: f32) -> u32 {
        let (u, v) = (finite_coordinate(u), finite_coordinate(v));
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
    #[inline(always)]
    pub fn linear(&self, u: f32, v: f32) -> [f32; 4] {
        let (u, v) = (finite_coordinate(u), finite_coordinate(v));
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

    /// One sample with `filter`.
    #[inline(always)]
    pub(super) fn sample(&self, filter: Filter, u: f32, v: f32) -> [f32; 4] {
        match filter {
            Filter::Point => self.point(u, v),
            Filter::Linear => self.linear(u, v),
        }
    }

    /// The texels at `idx` (or the border colour) of lanes `0..n`, the
    /// components of `MASK` unswizzled (a constant, so that the lane loop
    /// tests no mask).
    #[inline(always)]
    fn gather<const MASK: u8>(&self, n: usize, idx: &[u32; LANES], out: &mut [[f32; LANES]; 4]) {
        for l in 0..n.min(LANES) {
            prefetch_ahead(self.texels, idx[l]);
            let t = self.texels.get(idx[l] as usize).unwrap_or(&self.border);
            for c in 0..4 {
                if MASK & (1 << c) != 0 {
                    out[c][l] = t[c];
                }
            }
        }
    }

    /// Samples lanes `0..n` with `filter`; `out[c]` receives sampled
    /// component `swz(c)` for the components `c` of `mask` (the others are
    /// left as they are).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)] // one sampling request, spelled out
    fn sample_lanes(
        &self,
        filter: Filter,
        n: usize,
        u: &[f32; LANES],
        v: &[f32; LANES],
        swz: [usize; 4],
        mask: u8,
        out: &mut [[f32; LANES]; 4],
    ) {
        let n = n.min(LANES);
        let put = |out: &mut [[f32; LANES]; 4], l: usize, t: &[f32; 4]| {
            for c in 0..4 {
                if mask & (1 << c) != 0 {
                    out[c][l] = t[swz[c]];
                }
            }
        };
        match (filter, self.au, self.av) {
            (Filter::Point, Address::Border, Address::Border) => {
                // Indices first (vectorises), then the gather.
                let mut idx = [BORDER; LANES];
                for l in 0..n {
                    idx[l] = self.point_border_index(u[l], v[l]);
                }
                match (swz == [0, 1, 2, 3], mask) {
                    (true, 0xf) => self.gather::<0xf>(n, &idx, out),
                    (true, 0x7) => self.gather::<0x7>(n, &idx, out),
                    _ => {
                        for l in 0..n {
                            put(
                                out,
                                l,
                                self.texels.get(idx[l] as usize).unwrap_or(&self.border),
                            );
                        }
                    }
                }
            }
            (Filter::Point, _, _) => {
                for l in 0..n {
                    put(out, l, &self.point(u[l], v[l]));
                }
            }
            (Filter::Linear, _, _) => {
                for l in 0..n {
                    put(out, l, &self.linear(u[l], v[l]));
                }
            }
        }
    }
}

/// Texels a lane's gather asks the cache for ahead of the one it reads: four
/// 64-byte lines of RGBA f32.
const PREFETCH_TEXELS: usize = 16;

/// Asks the processor to bring into cache the texel [`PREFETCH_TEXELS`]
/// after `index` in the same row. Shaders that walk a row (the luminance
/// passes read texel after texel) keep one stream of reads per lane, more
/// streams than the hardware prefetcher follows; this keeps them ahead. A
/// hint only: no result depends on it, and an address past the texture is
/// never read.
#[inline(always)]
fn prefetch_ahead(texels: &[[f32; 4]], index: u32) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let p = texels
            .as_ptr()
            .wrapping_add((index as usize).wrapping_add(PREFETCH_TEXELS));
        // SAFETY: a prefetch is a hint; it does not fault or read the
        // address into the program, whatever the address.
        unsafe { _mm_prefetch::<_MM_HINT_T0>(p as *const i8) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (texels, index);
}

impl<'a> Sampler<'a> {
    /// The levels of one 2D chain (a 2D texture, a cube face).
    fn levels_of(views: &[Texture<'a>], state: &SamplerState) -> Result<Vec<Level<'a>>, String> {
        let mut levels = Vec::with_capacity(views.len());
        for (i, t) in views.iter().enumerate() {
            levels.push(Level::new(t, state).map_err(|e| {
                if views.len() == 1 {
                    e
                } else {
                    format!("mip level {i}: {e}")
                }
            })?);
        }
        Ok(levels)
    }

    /// Checks every level's shape and precomputes sizes.
    pub fn new(tex: &TextureLevels<'a>, state: &SamplerState) -> Result<Sampler<'a>, String> {
        let (levels, shape) = match tex {
            TextureLevels::Cube(c) => {
                // D3D9 hardware filters within a face: each face is
                // addressed with CLAMP whatever ADDRESSU/V say.
                let face_state = SamplerState {
                    address_u: Address::Clamp,
                    address_v: Address::Clamp,
                    ..*state
                };
                let faces = (0..6)
                    .map(|f| {
                        Self::levels_of(&c.face(f).views(), &face_state)
                            .map_err(|e| format!("cube face {f}: {e}"))
                    })
                    .collect::<Result<Vec<_>, String>>()?;
                (faces[0].clone(), Shape::Cube(faces))
            }
            TextureLevels::Volume(v) => {
                let mut vol = Vec::with_capacity(v.len());
                for i in 0..v.len() {
                    let l = v.level(i).expect("level below len");
                    vol.push(Level3::new(l, state).map_err(|e| format!("mip level {i}: {e}"))?);
                }
                (Self::levels_of(&tex.views(), state)?, Shape::Volume(vol))
            }
            _ => (Self::levels_of(&tex.views(), state)?, Shape::Flat),
        };
        if levels.is_empty() {
            return Err("no texture levels".into());
        }
        if !state.mip_lod_bias.is_finite() {
            return Err(format!("LOD bias {} is not finite", state.mip_lod_bias));
        }
        let base = (state.max_mip_level as usize).min(levels.len() - 1);
        let lod_matters = state.mag_filter != state.min_filter
            || (state.mip_filter != MipFilter::None && levels.len() - base > 1);
        Ok(Sampler {
            levels,
            base,
            mag: state.mag_filter,
            min: state.min_filter,
            mip: state.mip_filter,
            bias: state.mip_lod_bias,
            lod_matters,
            shape,
        })
    }

    /// Whether this is a cube or volume texture (sampled with three
    /// coordinates by [`Sampler::sample_3d`]).
    #[inline(always)]
    pub fn is_3d(&self) -> bool {
        !matches!(self.shape, Shape::Flat)
    }

    /// Whether this is a cube texture.
    #[inline(always)]
    pub fn is_cube(&self) -> bool {
        matches!(self.shape, Shape::Cube(_))
    }

    /// Depth of level 0 (1 for 2D and cube textures).
    #[inline(always)]
    pub fn depth(&self) -> f32 {
        match &self.shape {
            Shape::Volume(v) => v[0].depth(),
            _ => 1.0,
        }
    }

    /// One sample of a cube (direction x, y, z) or volume (u, v, w) at LOD
    /// `lod` (bias already added); a 2D texture reads (x, y).
    pub fn sample_3d(&self, p: [f32; 3], lod: f32) -> [f32; 4] {
        let (a, b, t, filter) = self.select(lod);
        let one = |i: usize| match &self.shape {
            Shape::Flat => self.levels[i].sample(filter, p[0], p[1]),
            Shape::Cube(faces) => {
                let (f, s, tc) = cube_face(p.map(finite_coordinate));
                faces[f][i].sample(filter, s, tc)
            }
            Shape::Volume(v) => v[i].sample(filter, p),
        };
        let c0 = one(a);
        if t == 0.0 {
            return c0;
        }
        let c1 = one(b);
        std::array::from_fn(|c| c0[c] * (1.0 - t) + c1[c] * t)
    }

    /// Whether a sample's LOD can change its value: false for one usable
    /// level (or MIPFILTER NONE) with MINFILTER = MAGFILTER, where every
    /// sample reads the base level with the same filter.
    #[inline(always)]
    pub fn lod_matters(&self) -> bool {
        self.lod_matters
    }

    /// Width and height of level 0 as floats (gradients are scaled by them).
    #[inline(always)]
    pub fn size(&self) -> (f32, f32) {
        (self.levels[0].wf, self.levels[0].hf)
    }

    /// D3DSAMP_MIPMAPLODBIAS.
    #[inline(always)]
    pub fn bias(&self) -> f32 {
        self.bias
    }

    /// Samples lanes `0..n` at the base level, ignoring the LOD (valid when
    /// [`Sampler::lod_matters`] is false), into the components of `mask`.
    #[inline(always)]
    pub fn sample_lanes(
        &self,
        n: usize,
        u: &[f32; LANES],
        v: &[f32; LANES],
        swz: [usize; 4],
        mask: u8,
        out: &mut [[f32; LANES]; 4],
    ) {
        self.levels[self.base].sample_lanes(self.mag, n, u, v, swz, mask, out);
    }

    /// Level(s), blend weight of the second and filter for LOD `lod` (bias
    /// already added); see the module docs.
    #[inline(always)]
    pub fn select(&self, lod: f32) -> (usize, usize, f32, Filter) {
        let base = self.base;
        // NaN is not above 0: magnification on the base level.
        if lod.is_nan() || lod <= 0.0 {
            return (base, base, 0.0, self.mag);
        }
        let last = self.levels.len() - 1;
        let l = lod.max(base as f32);
        match self.mip {
            MipFilter::None => (base, base, 0.0, self.min),
            MipFilter::Point => {
                let r = floor(l + 0.5);
                let i = if r >= last as f32 { last } else { r as usize };
                (i, i, 0.0, self.min)
            }
            MipFilter::Linear => {
                if l >= last as f32 {
                    return (last, last, 0.0, self.min);
                }
                let f = floor(l);
                let i = f as usize;
                (i, i + 1, l - f, self.min)
            }
        }
    }

    /// One sample at LOD `lod` (bias already added).
    #[inline(always)]
    pub fn sample_lod(&self, u: f32, v: f32, lod: f32) -> [f32; 4] {
        let (a, b, t, filter) = self.select(lod);
        let c0 = self.levels[a].sample(filter, u, v);
        if t == 0.0 {
            return c0;
        }
        let c1 = self.levels[b].sample(filter, u, v);
        std::array::from_fn(|c| c0[c] * (1.0 - t) + c1[c] * t)
    }

    /// Samples lanes `0..n` at their own LODs (`lod[l]`, bias already
    /// added).
    #[inline(always)]
    pub fn sample_lanes_lod(
        &self,
        n: usize,
        u: &[f32; LANES],
        v: &[f32; LANES],
        lod: &[f32; LANES],
        swz: [usize; 4],
        out: &mut [[f32; LANES]; 4],
    ) {
        let n = n.min(LANES);
        for l in 0..n {
            let t = self.sample_lod(u[l], v[l], lod[l]);
            for c in 0..4 {
                out[c][l] = t[swz[c]];
            }
        }
    }
}

/// The value of an unbound sampler: (0, 0, 0, 1) (MS `texldl---ps`).
pub const UNBOUND: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
