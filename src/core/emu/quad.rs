//! 2×2 quads in a 64-lane batch: which quads a lane mask touches, the
//! gradient lengths of a quad, and what one gradient site saw in a batch.
//!
//! Lane `4q + k` is corner `k` of quad `q` (0 top-left, 1 top-right,
//! 2 bottom-left, 3 bottom-right); bit `4q` of a quad mask stands for quad
//! `q`. The executor ([`super::exec`]) and the texld family
//! ([`super::texop`]) both build on these.

// Lane loops index several fixed-size rows with one lane index; that is
// clearer than zipped iterators and vectorises the same.
#![allow(clippy::needless_range_loop)]

use super::math;
use super::LANES;

/// Bit 4q set where quad q has any lane of `m` set.
#[inline(always)]
pub(super) fn quads_any(m: u64) -> u64 {
    (m | m >> 1 | m >> 2 | m >> 3) & 0x1111_1111_1111_1111
}

/// Bit 4q set where quad q has all four lanes of `m` set.
#[inline(always)]
pub(super) fn quads_all(m: u64) -> u64 {
    (m & m >> 1 & m >> 2 & m >> 3) & 0x1111_1111_1111_1111
}

/// λ from a squared gradient length in texels: ½·log2(len²), −∞ for 0,
/// +∞ for +∞, NaN for NaN.
#[inline(always)]
pub(super) fn lod_of_len2(len2: f32) -> f32 {
    if len2 == 0.0 {
        f32::NEG_INFINITY
    } else if len2.is_nan() || len2 == f32::INFINITY {
        len2
    } else {
        0.5 * math::log2(len2)
    }
}

/// Every quad's top-left lane bit (bit 4q).
const ALL_QUADS: u64 = 0x1111_1111_1111_1111;

/// The smallest and largest max(|dX|², |dY|²) (level-0 texels) over the
/// quads marked in `quads` (bit 4q = quad q, whose top-left lane is 4q) among
/// the first `n / 4`;
/// (+∞, −∞) when none is. Quads are taken four at a time with their corners
/// transposed into rows, which the compiler maps onto vector operations;
/// a batch's span may end halfway through the last four (`n` is a multiple
/// of 8), whose quads beyond it are never marked. The comparisons are plain
/// `<`/`>`, so a NaN length is skipped.
#[inline(always)]
pub(super) fn quad_len2_range(
    n: usize,
    u: &[f32; LANES],
    v: &[f32; LANES],
    wf: f32,
    hf: f32,
    quads: u64,
) -> (f32, f32) {
    #[inline(always)]
    fn range<const ALL: bool>(
        n: usize,
        u: &[f32; LANES],
        v: &[f32; LANES],
        wf: f32,
        hf: f32,
        quads: u64,
    ) -> (f32, f32) {
        let mut lo = [f32::INFINITY; 4];
        let mut hi = [f32::NEG_INFINITY; 4];
        for g in 0..n.min(LANES).div_ceil(16) {
            let mut c = [[0f32; 4]; 6];
            for k in 0..4 {
                let b = 16 * g + 4 * k;
                c[0][k] = u[b];
                c[1][k] = u[b + 1];
                c[2][k] = u[b + 2];
                c[3][k] = v[b];
                c[4][k] = v[b + 1];
                c[5][k] = v[b + 2];
            }
            for k in 0..4 {
                let (dxu, dxv) = ((c[1][k] - c[0][k]) * wf, (c[4][k] - c[3][k]) * hf);
                let (dyu, dyv) = ((c[2][k] - c[0][k]) * wf, (c[5][k] - c[3][k]) * hf);
                let (x, y) = (dxu * dxu + dxv * dxv, dyu * dyu + dyv * dyv);
                let l = if x > y { x } else { y };
                let on = ALL || (quads >> (16 * g + 4 * k)) & 1 != 0;
                lo[k] = if on && l < lo[k] { l } else { lo[k] };
                hi[k] = if on && l > hi[k] { l } else { hi[k] };
            }
        }
        let lo = lo
            .into_iter()
            .fold(f32::INFINITY, |a, b| if b < a { b } else { a });
        let hi = hi
            .into_iter()
            .fold(f32::NEG_INFINITY, |a, b| if b > a { b } else { a });
        (lo, hi)
    }
    if quads == ALL_QUADS {
        range::<true>(n, u, v, wf, hf, quads)
    } else {
        range::<false>(n, u, v, wf, hf, quads)
    }
}

/// max(|dX|², |dY|²) of quad `q` (level-0 texels).
#[inline(always)]
pub(super) fn quad_len2(u: &[f32; LANES], v: &[f32; LANES], wf: f32, hf: f32, q: usize) -> f32 {
    let b = 4 * q;
    let (dxu, dxv) = ((u[b + 1] - u[b]) * wf, (v[b + 1] - v[b]) * hf);
    let (dyu, dyv) = ((u[b + 2] - u[b]) * wf, (v[b + 2] - v[b]) * hf);
    let (x, y) = (dxu * dxu + dxv * dxv, dyu * dyu + dyv * dyv);
    if x > y || y.is_nan() {
        x
    } else {
        y
    }
}

/// What one gradient site saw in one batch (see [`super::GradientSite`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SiteBatch {
    /// Bit 4q: quad q executed the site.
    pub quads: u64,
    /// Bit 4q: quad q executed it with some but not all four lanes.
    pub divergent: u64,
    pub executions: u64,
    pub divergent_executions: u64,
    /// Smallest and largest λ seen (+∞ / −∞ before any).
    pub lod_min: f32,
    pub lod_max: f32,
    /// Smallest and largest squared gradient length seen where λ was not
    /// needed per lane: λ is monotonic in it, so it is turned into λ once per
    /// batch ([`SiteBatch::finish`]) instead of once per execution.
    pub len2_min: f32,
    pub len2_max: f32,
}

impl SiteBatch {
    /// Folds the squared-length range into the λ range (`bias`: the
    /// sampler's MIPMAPLODBIAS).
    pub fn finish(&mut self, bias: f32) {
        if self.len2_min <= self.len2_max {
            self.lod_min = self.lod_min.min(lod_of_len2(self.len2_min) + bias);
            self.lod_max = self.lod_max.max(lod_of_len2(self.len2_max) + bias);
            self.len2_min = f32::INFINITY;
            self.len2_max = f32::NEG_INFINITY;
        }
    }
}

impl Default for SiteBatch {
    fn default() -> SiteBatch {
        SiteBatch {
            quads: 0,
            divergent: 0,
            executions: 0,
            divergent_executions: 0,
            lod_min: f32::INFINITY,
            lod_max: f32::NEG_INFINITY,
            len2_min: f32::INFINITY,
            len2_max: f32::NEG_INFINITY,
        }
    }
}
