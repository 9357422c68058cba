//! The CPU reference for the log-average luminance, in f64.
//!
//! The GPU passes that ps30 emulates compute, over an HDR image,
//! `2^(mean over pixels of log2(delta + L))` with luminance
//! `L = 0.27 R + 0.67 G + 0.06 B`, first as per-block partial sums, then as
//! one total. This module computes the same figures the plain way, in f64,
//! so that the emulated result (f32 arithmetic, f16 or f32 render targets)
//! can be judged against something obviously right. It is also checked
//! against independently computed values (`tests/reference_values.rs`).
//!
//! Two decisions the formula leaves open are explicit [`Policy`] choices:
//!
//! * negative luminance (real images have it: lossy compression rings below
//!   zero): [`NegativePolicy::Abs`] takes `log2|delta + L|`, which is what
//!   the ps_3_0 `log` instruction computes (it uses the absolute value of its
//!   operand); [`NegativePolicy::Clamp`] takes `log2(delta + max(L, 0))`.
//! * non-finite luminance (a NaN or infinite channel):
//!   [`NonFinitePolicy::Propagate`] lets IEEE arithmetic decide, as the GPU
//!   would: under `Abs` an infinity gives `+inf` and NaN gives NaN; under
//!   `Clamp`, `+inf` gives `+inf`, `-inf` clamps to 0 (term `log2(delta)`)
//!   and NaN stays NaN. Any such term makes the total non-finite.
//!   [`NonFinitePolicy::Skip`] leaves such pixels out of the sums and out of
//!   the sample count. Either way they are counted in
//!   [`Reference::nonfinite_pixels`].
//!
//! Summation is plain left-to-right f64 addition in row-major order. For `n`
//! terms its error is at most `(n - 1) * 2^-53 * sum|term|` (Higham,
//! "Accuracy and Stability of Numerical Algorithms", 2nd ed., section 4.2).
//! For a 1280x1024 image (1.3 M terms) that is a relative error of at most
//! about 1.5e-10 of `sum|term|`, far below anything the f32/f16 GPU
//! computation can resolve, so compensated or pairwise summation would add
//! code without adding meaning. Each result carries that bound
//! ([`Reference::rounding_bound`], [`BlockSums::rounding_bound`]).

use crate::core::image::luminance;
use crate::core::image::HdrImage;
use serde::Serialize;
use std::fmt;

/// The `delta` that keeps `log2(delta + L)` finite for black pixels.
pub const DEFAULT_DELTA: f64 = 1e-4;

/// The unit roundoff of f64, `2^-53`.
pub const F64_UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// What to do with pixels whose luminance is negative (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub enum NegativePolicy {
    /// `log2|delta + L|`: what the ps_3_0 `log` instruction computes.
    #[default]
    Abs,
    /// `log2(delta + max(L, 0))`.
    Clamp,
}

/// What to do with pixels whose luminance is NaN or infinite (see the module
/// docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub enum NonFinitePolicy {
    /// Compute the term with IEEE arithmetic like any other; the totals
    /// become non-finite.
    #[default]
    Propagate,
    /// Leave the pixel out of every sum and of the sample count.
    Skip,
}

/// The two policy decisions together.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub struct Policy {
    /// What a negative luminance contributes.
    pub negative: NegativePolicy,
    /// What a NaN or infinite luminance contributes.
    pub non_finite: NonFinitePolicy,
}

impl Policy {
    /// What the GPU computes: absolute value, non-finite values propagate.
    pub const ABS: Policy = Policy {
        negative: NegativePolicy::Abs,
        non_finite: NonFinitePolicy::Propagate,
    };
    /// Negative luminance clamped to 0, non-finite values propagate.
    pub const CLAMP: Policy = Policy {
        negative: NegativePolicy::Clamp,
        non_finite: NonFinitePolicy::Propagate,
    };

    /// The log2 term of a pixel with luminance `l`, or `None` if the policy
    /// skips it. `delta + L = 0` exactly gives `-inf`, as `log` of 0 does on
    /// the GPU.
    pub fn term(self, l: f64, delta: f64) -> Option<f64> {
        let (x, kept) = self.argument_flagged(l, delta);
        kept.then(|| x.log2())
    }

    /// What the term takes the `log2` of (`|delta + L|` or
    /// `delta + max(L, 0)`; NaN if the policy skips the pixel) and whether
    /// the policy keeps the pixel, worked out with selections, not
    /// branches, so that a loop over pixels becomes vector code.
    #[inline(always)]
    fn argument_flagged(self, l: f64, delta: f64) -> (f64, bool) {
        let kept = l.is_finite() | (self.non_finite != NonFinitePolicy::Skip);
        // `l < 0.0` is false for NaN, so NaN stays NaN (f64::max would turn
        // it into 0).
        let clamped = delta + if l < 0.0 { 0.0 } else { l };
        let x = match self.negative {
            NegativePolicy::Abs => (delta + l).abs(),
            NegativePolicy::Clamp => clamped,
        };
        (if kept { x } else { f64::NAN }, kept)
    }
}

/// The log-average luminance of an image and the figures behind it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Reference {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// δ of log2(δ + L).
    pub delta: f64,
    /// How negative and non-finite luminances were treated.
    pub policy: Policy,
    /// Terms in the sum: `width * height`, less the pixels the policy skips.
    pub samples: u64,
    /// The sum of the log2 terms.
    pub log2_sum: f64,
    /// The sum of the terms' magnitudes, which bounds the rounding error.
    pub magnitude_sum: f64,
    /// `2^(log2_sum / samples)`.
    pub log_average: f64,
    /// Pixels with finite negative luminance.
    pub negative_pixels: u64,
    /// Pixels with NaN or infinite luminance.
    pub nonfinite_pixels: u64,
    /// Smallest finite luminance (`+inf` if there is none).
    pub min_luminance: f64,
    /// Largest finite luminance (`-inf` if there is none).
    pub max_luminance: f64,
}

impl Reference {
    /// An upper bound on the rounding error of [`Reference::log2_sum`]
    /// (recursive summation, see the module docs); it does not include the
    /// error of each `log2`, at most one unit in the last place of the term.
    pub fn rounding_bound(&self) -> f64 {
        summation_bound(self.samples, self.magnitude_sum)
    }
}

/// `(n - 1) u sum|t|`: Higham's bound for recursive summation of n terms.
fn summation_bound(terms: u64, magnitude_sum: f64) -> f64 {
    terms.saturating_sub(1) as f64 * F64_UNIT_ROUNDOFF * magnitude_sum
}

/// The log-average luminance of `image` with the given `delta` and policy.
/// An image without samples (empty, or every pixel skipped) gives NaN.
pub fn log_average(image: &HdrImage, delta: f64, policy: Policy) -> Reference {
    scan(image, delta, policy, |_| {})
}

/// Rows of the image with each pixel's term, as [`scan`] hands them out.
pub struct Band<'a> {
    /// The image row of the band's first row.
    pub y0: u32,
    /// Image width in pixels: the length of each of the band's rows.
    pub width: u32,
    /// The band's pixels, row-major.
    pub pixels: &'a [[f32; 4]],
    /// Each pixel's term, in the same layout (NaN where the policy skips
    /// the pixel).
    pub terms: &'a [f64],
    /// Whether the policy keeps each pixel: plain flags beside plain terms,
    /// so that the folds read both as vectors.
    pub kept: &'a [bool],
}

/// Pixels per band of [`scan`]: enough work to share between threads, and
/// small enough that the band's pixels and terms (25 bytes a pixel, 400 KB)
/// are still in the second-level cache when the blocks' folds read them
/// again after the terms' pass.
const BAND_PIXELS: usize = 1 << 14;

/// Extremes and counts over one row; merged in row order.
#[derive(Clone, Copy)]
struct RowStats {
    min: f64,
    max: f64,
    negative: u64,
    nonfinite: u64,
}

/// One image row for [`RowStats::row`]: its pixels, what it fills in for
/// them (each term and whether the policy keeps the pixel) and how.
struct Row<'a> {
    pixels: &'a [[f32; 4]],
    terms: &'a mut [f64],
    kept: &'a mut [bool],
    delta: f64,
    policy: Policy,
}

/// Pixels [`RowStats::row`] takes side by side, each with statistics of its
/// own: vector lanes, and no chain of comparisons from one pixel to the next.
const STAT_LANES: usize = 4;

impl RowStats {
    const EMPTY: RowStats = RowStats {
        min: f64::INFINITY,
        max: f64::NEG_INFINITY,
        negative: 0,
        nonfinite: 0,
    };

    /// Fills `row.terms` and `row.kept` and returns the row's statistics.
    /// The `log2` calls come in a loop of their own: in the loop that works
    /// out their arguments, a call would make the compiler keep every other
    /// value in memory across it.
    fn row(mut row: Row<'_>) -> Self {
        #[cfg(target_arch = "x86_64")]
        let stats = if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above).
            unsafe { Self::arguments_avx2(&mut row) }
        } else {
            Self::arguments(&mut row)
        };
        #[cfg(not(target_arch = "x86_64"))]
        let stats = Self::arguments(&mut row);
        for term in row.terms {
            *term = term.log2();
        }
        stats
    }

    /// [`RowStats::row`] short of the `log2` calls: `row.terms` gets their
    /// arguments.
    #[inline(always)]
    fn arguments(row: &mut Row<'_>) -> Self {
        let (delta, policy) = (row.delta, row.policy);
        let mut lanes = [RowStats::EMPTY; STAT_LANES];
        let pixel_groups = row.pixels.chunks_exact(STAT_LANES);
        let term_groups = row.terms.chunks_exact_mut(STAT_LANES);
        let groups = pixel_groups.zip(term_groups);
        for ((p, t), k) in groups.zip(row.kept.chunks_exact_mut(STAT_LANES)) {
            for j in 0..STAT_LANES {
                (t[j], k[j]) = lanes[j].pixel(p[j], delta, policy);
            }
        }
        lanes[0].rest(row, row.pixels.len() / STAT_LANES * STAT_LANES);
        lanes.into_iter().fold(RowStats::EMPTY, RowStats::merge)
    }

    /// [`RowStats::arguments`] in AVX2 instructions: four pixels side by
    /// side in the four f64 lanes of a register, lane `j` doing what
    /// `arguments`' lane `j` does (pixels `4k + j`; the last few in lane 0)
    /// with the same operations in the same order (no fused multiply-add),
    /// so the results are the same bits. The compiler left `arguments`
    /// mostly scalar: one pixel's luminance, tests and counts at a time.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn arguments_avx2(row: &mut Row<'_>) -> Self {
        use std::arch::x86_64::*;
        let (delta, policy) = (row.delta, row.policy);
        let [wr, wg, wb] = crate::core::image::LUMINANCE_WEIGHTS;
        let (wr, wg, wb) = (_mm256_set1_pd(wr), _mm256_set1_pd(wg), _mm256_set1_pd(wb));
        let (vdelta, zero) = (_mm256_set1_pd(delta), _mm256_setzero_pd());
        let (inf, neg_inf) = (
            _mm256_set1_pd(f64::INFINITY),
            _mm256_set1_pd(f64::NEG_INFINITY),
        );
        let magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(i64::MAX));
        let skip = policy.non_finite == NonFinitePolicy::Skip;
        let abs = policy.negative == NegativePolicy::Abs;
        let (mut min, mut max) = (inf, neg_inf);
        // Counts are sums: which lane counts a pixel does not matter.
        let (mut negative, mut finite_count) = (0u64, 0u64);
        let groups = row.pixels.len() / STAT_LANES;
        for k in 0..groups {
            let i = k * STAT_LANES;
            // SAFETY: pixels i..i + 4 are in the row (k < groups), and each
            // pixel is four f32s.
            let p = row.pixels.as_ptr().add(i) as *const f32;
            let (mut c0, mut c1) = (_mm_loadu_ps(p), _mm_loadu_ps(p.add(4)));
            let (mut c2, mut c3) = (_mm_loadu_ps(p.add(8)), _mm_loadu_ps(p.add(12)));
            // Pixels in rows → channels in rows: c0 = the four R, c1 G, c2 B.
            _MM_TRANSPOSE4_PS(&mut c0, &mut c1, &mut c2, &mut c3);
            let (r, g, b) = (
                _mm256_cvtps_pd(c0),
                _mm256_cvtps_pd(c1),
                _mm256_cvtps_pd(c2),
            );
            // `luminance`: (wr·R + wg·G) + wb·B.
            let l = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(wr, r), _mm256_mul_pd(wg, g)),
                _mm256_mul_pd(wb, b),
            );
            // |l| < ∞ is false for NaN: `is_finite`.
            let finite = _mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_and_pd(l, magnitude), inf);
            let below_zero = _mm256_cmp_pd::<_CMP_LT_OQ>(l, zero);
            // `if low < min { low } else { min }` is what MINPD computes
            // (its first operand when less, else its second); MAXPD alike.
            min = _mm256_min_pd(_mm256_blendv_pd(inf, l, finite), min);
            max = _mm256_max_pd(_mm256_blendv_pd(neg_inf, l, finite), max);
            let finite_bits = _mm256_movemask_pd(finite) as u32;
            finite_count += u64::from(finite_bits.count_ones());
            negative +=
                u64::from((_mm256_movemask_pd(below_zero) as u32 & finite_bits).count_ones());
            // `Policy::argument_flagged`.
            let x = if abs {
                _mm256_and_pd(_mm256_add_pd(vdelta, l), magnitude)
            } else {
                _mm256_add_pd(vdelta, _mm256_blendv_pd(l, zero, below_zero))
            };
            let (x, kept_bits) = if skip {
                let nan = _mm256_set1_pd(f64::NAN);
                (_mm256_blendv_pd(nan, x, finite), finite_bits)
            } else {
                (x, 0b1111)
            };
            _mm256_storeu_pd(row.terms.as_mut_ptr().add(i), x);
            for (j, kept) in row.kept[i..i + STAT_LANES].iter_mut().enumerate() {
                *kept = kept_bits >> j & 1 != 0;
            }
        }
        let (mut mins, mut maxs) = ([0.0; STAT_LANES], [0.0; STAT_LANES]);
        _mm256_storeu_pd(mins.as_mut_ptr(), min);
        _mm256_storeu_pd(maxs.as_mut_ptr(), max);
        let mut lanes = [RowStats::EMPTY; STAT_LANES];
        for (lane, (min, max)) in lanes.iter_mut().zip(mins.into_iter().zip(maxs)) {
            (lane.min, lane.max) = (min, max);
        }
        lanes[0].negative = negative;
        lanes[0].nonfinite = (groups * STAT_LANES) as u64 - finite_count;
        lanes[0].rest(row, groups * STAT_LANES);
        lanes.into_iter().fold(RowStats::EMPTY, RowStats::merge)
    }

    /// Pixels `from..` of `row` one after another in this lane: the few
    /// left over after the groups of [`STAT_LANES`].
    #[inline(always)]
    fn rest(&mut self, row: &mut Row<'_>, from: usize) {
        let (delta, policy) = (row.delta, row.policy);
        let pixels = row.pixels[from..].iter().zip(&mut row.terms[from..]);
        for ((&p, t), k) in pixels.zip(&mut row.kept[from..]) {
            (*t, *k) = self.pixel(p, delta, policy);
        }
    }

    /// Counts `pixel`'s luminance (only finite values reach the extremes)
    /// and returns what its term takes the `log2` of (NaN if skipped) and
    /// whether the policy keeps it.
    #[inline(always)]
    fn pixel(&mut self, pixel: [f32; 4], delta: f64, policy: Policy) -> (f64, bool) {
        let l = luminance(pixel);
        let finite = l.is_finite();
        // Selections rather than `f64::min`: with no NaN to pass over, they
        // are plain vector comparisons.
        let low = if finite { l } else { f64::INFINITY };
        let high = if finite { l } else { f64::NEG_INFINITY };
        self.min = if low < self.min { low } else { self.min };
        self.max = if high > self.max { high } else { self.max };
        self.negative += u64::from(finite & (l < 0.0));
        self.nonfinite += u64::from(!finite);
        policy.argument_flagged(l, delta)
    }

    fn merge(self, other: RowStats) -> RowStats {
        RowStats {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
            negative: self.negative + other.negative,
            nonfinite: self.nonfinite + other.nonfinite,
        }
    }
}

/// Every pixel's term computed once, band by band on rayon's current pool;
/// `visit` sees each band in order (block sums and bounds fold over it), and
/// the result is the whole-image [`Reference`], summed left to right in
/// row-major order whatever the thread count.
pub fn scan(
    image: &HdrImage,
    delta: f64,
    policy: Policy,
    mut visit: impl FnMut(&Band<'_>) + Send,
) -> Reference {
    use rayon::prelude::*;
    let mut result = Reference {
        width: image.width,
        height: image.height,
        delta,
        policy,
        samples: 0,
        log2_sum: 0.0,
        magnitude_sum: 0.0,
        log_average: f64::NAN,
        negative_pixels: 0,
        nonfinite_pixels: 0,
        min_luminance: f64::INFINITY,
        max_luminance: f64::NEG_INFINITY,
    };
    // Rows beyond `height`, and a last partial row (an inconsistent image),
    // are ignored.
    let width = image.width as usize;
    let rows = (image.pixels.len() / width.max(1)).min(image.height as usize);
    let pixels = &image.pixels[..width * rows];
    let band_rows = (BAND_PIXELS / width.max(1)).max(1);
    let band_len = (band_rows * width).min(pixels.len());
    let (mut terms, mut kept) = (vec![0.0; band_len], vec![false; band_len]);
    for (band, band_pixels) in pixels.chunks(band_rows * width.max(1)).enumerate() {
        let terms = &mut terms[..band_pixels.len()];
        let kept = &mut kept[..band_pixels.len()];
        let rows: Vec<RowStats> = band_pixels
            .par_chunks(width)
            .zip(terms.par_chunks_mut(width))
            .zip(kept.par_chunks_mut(width))
            .map(|((pixels, terms), kept)| {
                RowStats::row(Row {
                    pixels,
                    terms,
                    kept,
                    delta,
                    policy,
                })
            })
            .collect();
        let band_stats = rows.into_iter().fold(RowStats::EMPTY, RowStats::merge);
        result.min_luminance = result.min_luminance.min(band_stats.min);
        result.max_luminance = result.max_luminance.max(band_stats.max);
        result.negative_pixels += band_stats.negative;
        result.nonfinite_pixels += band_stats.nonfinite;
        let band = Band {
            y0: (band * band_rows) as u32,
            width: image.width,
            pixels: band_pixels,
            terms,
            kept,
        };
        // The whole image's sum is one chain in row-major order; the
        // blocks' folds are others: on two threads they run side by side.
        rayon::join(
            || {
                let (mut samples, mut sum, mut magnitude) =
                    (result.samples, result.log2_sum, result.magnitude_sum);
                for (&term, &kept) in band.terms.iter().zip(band.kept) {
                    // A skipped pixel adds +0, which changes no sum (see
                    // [`BlockFold::pixel`]).
                    let term = if kept { term } else { 0.0 };
                    samples += u64::from(kept);
                    sum += term;
                    magnitude += term.abs();
                }
                (result.samples, result.log2_sum, result.magnitude_sum) = (samples, sum, magnitude);
            },
            || visit(&band),
        );
    }
    result.log_average = (result.log2_sum / result.samples as f64).exp2();
    result
}

/// What is folded over one block's texels, in the shader's order: rows top
/// to bottom, each left to right, padding texels (outside the image, black)
/// after the row's pixels and in the rows below the image.
///
/// A pixel is folded in two steps. [`BlockFold::ahead`] works out what a
/// run of pixels contributes from the pixels alone, in a loop of its own: no
/// pixel waits on another there, so the processor takes several at once
/// (vector instructions, the divisions of an error bound among them).
/// [`BlockFold::pixel`] then adds each pixel's part to the running sums, one
/// after another in order, which is all that must stay serial. The results
/// are the same bits as one step per pixel: the same operations on the same
/// values.
///
/// Two folds over the same texels (a pair) run as one loop: each fold's
/// running sums are a chain of dependent additions, and in one loop the
/// processor overlaps the chains instead of waiting on each in turn.
pub trait BlockFold: Send + Copy {
    /// What [`BlockFold::ahead`] works out for a run of up to
    /// [`AHEAD_RUN`] pixels.
    type Run: Default;
    /// Fills `run` for `pixels` and their `terms` (at most [`AHEAD_RUN`];
    /// NaN for a skipped pixel); the fold's running sums are not read.
    fn ahead(&self, pixels: &[[f32; 4]], terms: &[f64], run: &mut Self::Run);
    /// Pixel `i` of the run, inside the image: its term and what
    /// [`BlockFold::ahead`] worked out for it.
    ///
    /// A fold may treat a skipped pixel (`None`) as a term of +0 in a sum of
    /// terms: no term is -0 (`log2` gives +0 for 1), so no such sum is ever
    /// -0, and adding +0 leaves every other value, NaN and infinities
    /// included, as it was.
    fn pixel(&mut self, run: &Self::Run, i: usize, term: Option<f64>);
    /// The end of one row inside the image: `padding` texels beyond the
    /// image's right edge.
    fn end_row(&mut self, padding: u32);
    /// `rows` rows of the block below the image, `read` texels each.
    fn rows_below(&mut self, rows: u32, read: u32);
}

/// Two folds over the same texels.
impl<A: BlockFold, B: BlockFold> BlockFold for (A, B) {
    type Run = (A::Run, B::Run);
    #[inline]
    fn ahead(&self, pixels: &[[f32; 4]], terms: &[f64], run: &mut Self::Run) {
        self.0.ahead(pixels, terms, &mut run.0);
        self.1.ahead(pixels, terms, &mut run.1);
    }
    #[inline]
    fn pixel(&mut self, run: &Self::Run, i: usize, term: Option<f64>) {
        self.0.pixel(&run.0, i, term);
        self.1.pixel(&run.1, i, term);
    }
    fn end_row(&mut self, padding: u32) {
        self.0.end_row(padding);
        self.1.end_row(padding);
    }
    fn rows_below(&mut self, rows: u32, read: u32) {
        self.0.rows_below(rows, read);
        self.1.rows_below(rows, read);
    }
}

/// Pixels whose [`BlockFold::ahead`] is worked out before they are added:
/// a few vectors' worth, small enough to stay in the first-level cache.
pub const AHEAD_RUN: usize = 32;

/// Folds one row of a block: `pixels`, their `terms` and `kept` flags, in
/// order, in runs of [`AHEAD_RUN`] (see [`BlockFold`]).
#[inline]
fn fold_span<F: BlockFold>(f: &mut F, pixels: &[[f32; 4]], terms: &[f64], kept: &[bool]) {
    let mut run = F::Run::default();
    let runs = pixels.chunks(AHEAD_RUN).zip(terms.chunks(AHEAD_RUN));
    for ((pixels, terms), kept) in runs.zip(kept.chunks(AHEAD_RUN)) {
        f.ahead(pixels, terms, &mut run);
        for (i, (&t, &k)) in terms.iter().zip(kept).enumerate() {
            f.pixel(&run, i, k.then_some(t));
        }
    }
}

/// How blocks tile the image: `block_width × block_height` from the top-left
/// corner, the last column reading `last_width` texels per line.
#[derive(Clone, Copy, Debug)]
pub struct Tiling {
    /// Block width in texels.
    pub block_width: u32,
    /// Block height in texels.
    pub block_height: u32,
    /// Texels per line the last column of blocks reads (`block_width` unless a
    /// last-column shader reads fewer).
    pub last_width: u32,
}

impl Tiling {
    /// The tiling of `image`, checked (see [`block_sums_last_width`]):
    /// returns `(nx, ny)`.
    pub fn blocks(&self, image: &HdrImage) -> Result<(u32, u32), ReferenceError> {
        let (block_width, block_height) = (self.block_width, self.block_height);
        if block_width == 0 || block_height == 0 {
            return Err(ReferenceError::ZeroBlockSize {
                block_width,
                block_height,
            });
        }
        let nx = image.width.div_ceil(block_width);
        let ny = image.height.div_ceil(block_height);
        let real_last = image
            .width
            .saturating_sub(nx.saturating_sub(1) * block_width);
        if self.last_width > block_width || self.last_width < real_last {
            return Err(ReferenceError::LastWidth {
                last_width: self.last_width,
                real_width: real_last,
                block_width,
            });
        }
        Ok((nx, ny))
    }

    /// Texels block column `bx` of `nx` reads per line.
    pub fn read(&self, bx: u32, nx: u32) -> u32 {
        if bx + 1 == nx {
            self.last_width
        } else {
            self.block_width
        }
    }
}

/// The whole-image reference and one fold per block (`folds[row][col]`,
/// made by `make(col, row)`) from a single [`scan`]: each pixel's term is
/// computed once, blocks of a band are folded in parallel.
pub fn fold_blocks<F: BlockFold>(
    image: &HdrImage,
    delta: f64,
    policy: Policy,
    tiling: Tiling,
    make: impl Fn(u32, u32) -> F,
) -> Result<(Reference, Vec<Vec<F>>), ReferenceError> {
    use rayon::prelude::*;
    let (nx, ny) = tiling.blocks(image)?;
    let (bw, bh) = (tiling.block_width, tiling.block_height);
    let mut folds: Vec<Vec<F>> = (0..ny)
        .map(|by| (0..nx).map(|bx| make(bx, by)).collect())
        .collect();
    let width = image.width;
    let reference = scan(image, delta, policy, |band| {
        let rows = band.pixels.len() as u32 / width.max(1);
        let mut y = band.y0;
        while y < band.y0 + rows {
            let by = y / bh;
            let end = ((by + 1) * bh).min(band.y0 + rows);
            folds[by as usize]
                .par_iter_mut()
                .enumerate()
                .for_each(|(bx, fold)| {
                    let bx = bx as u32;
                    let x0 = bx * bw;
                    let x1 = (x0 + tiling.read(bx, nx)).min(width);
                    let padding = x0 + tiling.read(bx, nx) - x1;
                    // A local copy keeps the running sums in registers.
                    let mut f = *fold;
                    for row in y..end {
                        let start = ((row - band.y0) * width) as usize;
                        let span = start + x0 as usize..start + x1 as usize;
                        let pixels = &band.pixels[span.clone()];
                        fold_span(&mut f, pixels, &band.terms[span.clone()], &band.kept[span]);
                        f.end_row(padding);
                    }
                    *fold = f;
                });
            y = end;
        }
    });
    if ny * bh > image.height {
        let below = ny * bh - image.height;
        for (bx, fold) in folds[ny as usize - 1].iter_mut().enumerate() {
            fold.rows_below(below, tiling.read(bx as u32, nx));
        }
    }
    Ok((reference, folds))
}

/// The block sums' fold: the terms in order, padding added once at the end.
#[derive(Clone, Copy)]
struct SumFold {
    sum: f64,
    magnitude: f64,
    /// Texels of the block inside the image.
    inside: u64,
    /// `read × block_height`.
    area: u64,
    /// The padding term, `log2(delta)` (the same under every policy).
    black: f64,
}

impl BlockFold for SumFold {
    type Run = ();
    #[inline]
    fn ahead(&self, _: &[[f32; 4]], _: &[f64], _: &mut ()) {}
    #[inline]
    fn pixel(&mut self, _: &(), _: usize, term: Option<f64>) {
        self.inside += 1;
        // A skipped pixel adds +0, which changes no sum (see
        // [`BlockFold::pixel`]): a selection, not a branch, so the running
        // sums stay in registers.
        let term = term.unwrap_or(0.0);
        self.sum += term;
        self.magnitude += term.abs();
    }
    fn end_row(&mut self, _padding: u32) {}
    fn rows_below(&mut self, _rows: u32, _read: u32) {}
}

impl SumFold {
    /// Adds the padding texels as `count × term` (skipped when 0: 0 ·
    /// log2(0) would be NaN for delta = 0); returns the padding count.
    fn finish(&mut self) -> u64 {
        let padded = self.area - self.inside;
        if padded > 0 {
            self.sum += padded as f64 * self.black;
            self.magnitude += padded as f64 * self.black.abs();
        }
        padded
    }
}

/// Per-block sums of the log2 terms, as the first reduction pass computes
/// them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BlockSums {
    /// Block width in texels.
    pub block_width: u32,
    /// Block height in texels.
    pub block_height: u32,
    /// Blocks per row: `ceil(width / block_width)`.
    pub nx: u32,
    /// Block rows: `ceil(height / block_height)`.
    pub ny: u32,
    /// Texels of the blocks that lie outside the image:
    /// `nx * block_width * ny * block_height - width * height`.
    pub padded_samples: u64,
    /// `sums[row][col]`: the sum over the block at block row `row`, block
    /// column `col`, counted from the top-left corner of the image.
    pub sums: Vec<Vec<f64>>,
    /// The sums of the terms' magnitudes, block by block.
    pub magnitude_sums: Vec<Vec<f64>>,
}

impl BlockSums {
    /// An upper bound on the rounding error of `sums[row][col]`
    /// (see [`Reference::rounding_bound`]).
    pub fn rounding_bound(&self, row: usize, col: usize) -> f64 {
        let terms = u64::from(self.block_width) * u64::from(self.block_height);
        summation_bound(terms, self.magnitude_sums[row][col])
    }
}

/// Why block sums cannot be computed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReferenceError {
    /// A block side is 0.
    ZeroBlockSize {
        /// The block width asked for.
        block_width: u32,
        /// The block height asked for.
        block_height: u32,
    },
    /// The last column's read width does not cover the frame's real width
    /// there, or exceeds the block width.
    LastWidth {
        /// Texels per line the last column reads.
        last_width: u32,
        /// The image's texels in the last column: `W − (nx − 1)·bw`.
        real_width: u32,
        /// The block width.
        block_width: u32,
    },
}

impl fmt::Display for ReferenceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReferenceError::ZeroBlockSize {
                block_width,
                block_height,
            } => write!(
                f,
                "block size {block_width}x{block_height} has a zero side; both must be at least 1"
            ),
            ReferenceError::LastWidth {
                last_width,
                real_width,
                block_width,
            } => write!(
                f,
                "the last column reads {last_width} texels per line, but the frame has {real_width} there and blocks are {block_width} wide"
            ),
        }
    }
}

impl std::error::Error for ReferenceError {}

/// The sums of the log2 terms over blocks of `block_width x block_height`
/// texels that tile the image from its top-left corner. Texels of a block
/// that lie outside the image count as black, as BORDER texture addressing
/// returns 0 there: each adds `log2(delta)`.
pub fn block_sums(
    image: &HdrImage,
    delta: f64,
    policy: Policy,
    block_width: u32,
    block_height: u32,
) -> Result<BlockSums, ReferenceError> {
    block_sums_last_width(image, delta, policy, block_width, block_height, block_width)
}

/// [`block_sums`] when the last column of blocks reads only `last_width`
/// texels per line (a separate "last column" shader, the article's
/// alternative to BORDER addressing): its blocks are padded to
/// `last_width × block_height` instead of `block_width × block_height`.
/// `last_width` must cover the frame's real width in that column
/// (`width − (nx − 1) · block_width`) and be at most `block_width`.
pub fn block_sums_last_width(
    image: &HdrImage,
    delta: f64,
    policy: Policy,
    block_width: u32,
    block_height: u32,
    last_width: u32,
) -> Result<BlockSums, ReferenceError> {
    let tiling = Tiling {
        block_width,
        block_height,
        last_width,
    };
    Ok(fold_blocks_with_sums(image, delta, policy, tiling, |_, _| ())?.1)
}

/// [`fold_blocks`] with the block sums folded beside `make`'s folds:
/// returns the whole-image reference, the block sums and the other folds.
pub fn fold_blocks_with_sums<F: BlockFold>(
    image: &HdrImage,
    delta: f64,
    policy: Policy,
    tiling: Tiling,
    make: impl Fn(u32, u32) -> F,
) -> Result<(Reference, BlockSums, Vec<Vec<F>>), ReferenceError> {
    let (nx, _) = tiling.blocks(image)?;
    let black = policy.term(0.0, delta).unwrap_or(0.0);
    let (reference, folds) = fold_blocks(image, delta, policy, tiling, |bx, by| {
        let sums = SumFold {
            sum: 0.0,
            magnitude: 0.0,
            inside: 0,
            area: u64::from(tiling.read(bx, nx)) * u64::from(tiling.block_height),
            black,
        };
        (sums, make(bx, by))
    })?;
    let mut padded_samples = 0;
    let (mut sums, mut magnitude_sums, mut others) = (Vec::new(), Vec::new(), Vec::new());
    for row in folds {
        let (mut s, mut m, mut o) = (Vec::new(), Vec::new(), Vec::new());
        for (mut sum, other) in row {
            padded_samples += sum.finish();
            s.push(sum.sum);
            m.push(sum.magnitude);
            o.push(other);
        }
        sums.push(s);
        magnitude_sums.push(m);
        others.push(o);
    }
    let blocks = BlockSums {
        block_width: tiling.block_width,
        block_height: tiling.block_height,
        nx,
        ny: sums.len() as u32,
        padded_samples,
        sums,
        magnitude_sums,
    };
    Ok((reference, blocks, others))
}

/// No fold: [`block_sums_last_width`] folds only the sums.
impl BlockFold for () {
    type Run = ();
    fn ahead(&self, _: &[[f32; 4]], _: &[f64], _: &mut ()) {}
    fn pixel(&mut self, _: &(), _: usize, _: Option<f64>) {}
    fn end_row(&mut self, _: u32) {}
    fn rows_below(&mut self, _: u32, _: u32) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four policies: either negative rule with either non-finite rule.
    fn every_policy() -> impl Iterator<Item = Policy> {
        [NegativePolicy::Abs, NegativePolicy::Clamp]
            .into_iter()
            .flat_map(|negative| {
                [NonFinitePolicy::Propagate, NonFinitePolicy::Skip].map(|non_finite| Policy {
                    negative,
                    non_finite,
                })
            })
    }

    /// The same bits, or NaNs both (their payloads aside).
    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan()
    }

    /// Grey pixels: the weights sum to 1, so L = v up to f64 rounding.
    fn image(width: u32, height: u32, values: &[f32]) -> HdrImage {
        let pixels = values.iter().map(|&v| [v, v, v, 1.0]).collect();
        HdrImage {
            width,
            height,
            pixels,
        }
    }

    /// Equal up to the few f64 roundings of L and of a short sum.
    fn assert_close(a: f64, b: f64) {
        assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} != {b}");
    }

    fn t(v: f64, delta: f64) -> f64 {
        (delta + v).log2()
    }

    /// The AVX2 arguments against the portable ones, bit for bit: the
    /// bound's awkward pixels, then channels drawn from every f32 bit
    /// pattern (NaNs, infinities, subnormals, both zeros, both signs), in
    /// rows of 1 to 13 pixels so that every remainder after the groups of
    /// four comes up. Compared: each argument (NaNs by kind, their payload
    /// aside), each kept flag, the extremes' bits and the counts.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn avx2_arguments_are_the_portable_ones_bit_for_bit() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            eprintln!("no AVX2 on this CPU: the AVX2 arguments are never used here");
            return;
        }
        // Zeros of both signs one after another in each lane: which zero
        // an extreme keeps depends on the order of MINPD's operands.
        let (zero, negative_zero) = ([0.0; 4], [-0.0; 4]);
        let mut pixels = [vec![zero; 4], vec![negative_zero; 8], vec![zero; 4]].concat();
        pixels.extend(crate::jobs::luminance::tests::awkward_pixels());
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut bits = || {
            // xorshift64*: a fixed sequence, the same every run.
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 32) as u32
        };
        for _ in 0..4000 {
            pixels.push([0; 4].map(|_| f32::from_bits(bits())));
        }
        // Ordinary pixels too (random bits are mostly huge or tiny).
        for _ in 0..2000 {
            pixels.push([0; 4].map(|_| (bits() as f32 / u32::MAX as f32 - 0.1) * 8.0));
        }
        for policy in every_policy() {
            for width in 1..=13 {
                for row_pixels in pixels.chunks(width) {
                    let n = row_pixels.len();
                    let run = |avx2: bool| {
                        let (mut terms, mut kept) = (vec![0.0; n], vec![false; n]);
                        let mut row = Row {
                            pixels: row_pixels,
                            terms: &mut terms,
                            kept: &mut kept,
                            delta: 1e-4,
                            policy,
                        };
                        // SAFETY: the CPU supports AVX2 (checked above).
                        let stats = if avx2 {
                            unsafe { RowStats::arguments_avx2(&mut row) }
                        } else {
                            RowStats::arguments(&mut row)
                        };
                        (stats, terms, kept)
                    };
                    let (s, terms, kept) = run(true);
                    let (p, terms_p, kept_p) = run(false);
                    let what = format!("{policy:?}, row {row_pixels:?}");
                    assert!(
                        terms.iter().zip(&terms_p).all(|(&a, &b)| same(a, b)),
                        "{what}"
                    );
                    assert_eq!(kept, kept_p, "{what}");
                    assert_eq!(s.min.to_bits(), p.min.to_bits(), "{what}");
                    assert_eq!(s.max.to_bits(), p.max.to_bits(), "{what}");
                    assert_eq!(
                        (s.negative, s.nonfinite),
                        (p.negative, p.nonfinite),
                        "{what}"
                    );
                }
            }
        }
    }

    #[test]
    fn luminance_weights() {
        assert_eq!(luminance([1.0, 0.0, 0.0, 9.0]), 0.27);
        assert_eq!(luminance([0.0, 1.0, 0.0, 9.0]), 0.67);
        assert_eq!(luminance([0.0, 0.0, 1.0, 9.0]), 0.06);
    }

    #[test]
    fn log_average_of_a_uniform_image_is_its_luminance() {
        let r = log_average(&image(3, 2, &[4.0; 6]), 0.0, Policy::ABS);
        assert_eq!(r.samples, 6);
        assert_close(r.log_average, 4.0);
        assert_close(r.log2_sum, 12.0);
    }

    #[test]
    fn log_average_is_the_geometric_mean_of_delta_plus_l() {
        // (0.5 + 1.5) * (0.5 + 7.5) = 16, geometric mean 4.
        let r = log_average(&image(2, 1, &[1.5, 7.5]), 0.5, Policy::CLAMP);
        assert_close(r.log_average, 4.0);
        assert_close(r.min_luminance, 1.5);
        assert_close(r.max_luminance, 7.5);
    }

    #[test]
    fn negative_policies() {
        let delta = 1e-4;
        let img = image(2, 1, &[-0.5, 1.0]);
        let abs = log_average(&img, delta, Policy::ABS);
        let clamp = log_average(&img, delta, Policy::CLAMP);
        assert_eq!((abs.negative_pixels, clamp.negative_pixels), (1, 1));
        assert_close(abs.log2_sum, (0.5 - delta).log2() + t(1.0, delta));
        assert_close(clamp.log2_sum, delta.log2() + t(1.0, delta));
        assert_close(abs.min_luminance, -0.5);
    }

    #[test]
    fn non_finite_policies() {
        let delta = 1e-4;
        let with = |values: &[f32], policy| {
            log_average(&image(values.len() as u32, 1, values), delta, policy)
        };
        let skip = |negative| Policy {
            negative,
            non_finite: NonFinitePolicy::Skip,
        };

        let r = with(&[1.0, f32::INFINITY], Policy::ABS);
        assert_eq!(
            (r.nonfinite_pixels, r.samples, r.log2_sum),
            (1, 2, f64::INFINITY)
        );
        assert_close(r.max_luminance, 1.0); // min and max are over finite pixels
        assert!(with(&[1.0, f32::NAN], Policy::ABS).log2_sum.is_nan());
        assert!(with(&[1.0, f32::NAN], Policy::CLAMP).log2_sum.is_nan());
        assert_eq!(
            with(&[f32::NEG_INFINITY], Policy::ABS).log2_sum,
            f64::INFINITY
        );
        assert_eq!(
            with(&[f32::NEG_INFINITY], Policy::CLAMP).log2_sum,
            delta.log2()
        );

        for negative in [NegativePolicy::Abs, NegativePolicy::Clamp] {
            let r = with(&[4.0, f32::NAN, f32::INFINITY, 4.0], skip(negative));
            assert_eq!((r.nonfinite_pixels, r.samples), (2, 2));
            assert_close(r.log2_sum, 2.0 * t(4.0, delta));
            assert_close(r.log_average, 4.0 + delta);
        }
    }

    /// The scan works out terms and statistics four pixels at a time, with
    /// selections where the plain way branches; it must give the plain
    /// way's bits, and the plain way's sums of the terms in row-major order,
    /// under every policy. Widths of 1 to 9 leave every remainder of a
    /// group of four; the pixels are the bound's awkward ones (zero,
    /// negative, subnormal, huge, infinite and NaN channels).
    #[test]
    fn scan_is_the_plain_loop_bit_for_bit() {
        let pixels = crate::jobs::luminance::tests::awkward_pixels();
        let delta = 1e-4;
        let mut compared = 0;
        for policy in every_policy() {
            for width in 1..=9 {
                let height = (pixels.len() / width) as u32;
                let image = HdrImage {
                    width: width as u32,
                    height,
                    pixels: pixels[..width * height as usize].to_vec(),
                };
                let (mut samples, mut sum, mut magnitude) = (0, 0.0, 0.0);
                let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
                let (mut negatives, mut nonfinite) = (0, 0);
                for &p in &image.pixels {
                    let l = luminance(p);
                    if l.is_finite() {
                        min = min.min(l);
                        max = max.max(l);
                        negatives += u64::from(l < 0.0);
                    } else {
                        nonfinite += 1;
                    }
                    if let Some(t) = policy.term(l, delta) {
                        samples += 1;
                        sum += t;
                        magnitude += t.abs();
                    }
                }
                let r = log_average(&image, delta, policy);
                let what = format!("{policy:?}, width {width}");
                assert_eq!(r.samples, samples, "{what}");
                // NaN sums (a NaN term under Propagate) compare by kind;
                // under Skip the sums are finite and compare by bits.
                assert!(
                    same(r.log2_sum, sum),
                    "{what}: {} against {sum}",
                    r.log2_sum
                );
                assert!(same(r.magnitude_sum, magnitude), "{what}");
                // By value: which zero is the extreme when both are
                // there is left open (as `f64::min` leaves it).
                assert_eq!(r.min_luminance, min, "{what}");
                assert_eq!(r.max_luminance, max, "{what}");
                assert_eq!(
                    (r.negative_pixels, r.nonfinite_pixels),
                    (negatives, nonfinite)
                );
                // The blocks' sums (2x3 blocks, padded with black), the
                // plain way: a skipped pixel adds nothing.
                let blocks = block_sums(&image, delta, policy, 2, 3).unwrap();
                for (by, row) in blocks.sums.iter().enumerate() {
                    for (bx, &got) in row.iter().enumerate() {
                        let (x0, y0) = (2 * bx as u32, 3 * by as u32);
                        let (mut sum, mut inside) = (0.0, 0);
                        for y in y0..(y0 + 3).min(height) {
                            for x in x0..(x0 + 2).min(width as u32) {
                                let p = image.pixels[(y * width as u32 + x) as usize];
                                inside += 1;
                                if let Some(t) = policy.term(luminance(p), delta) {
                                    sum += t;
                                }
                            }
                        }
                        if inside < 6 {
                            sum += (6 - inside) as f64 * delta.log2();
                        }
                        let at = format!("{what}, block ({bx}, {by})");
                        assert!(same(got, sum), "{at}: {got} against {sum}");
                    }
                }
                compared += 1;
            }
        }
        assert_eq!(compared, 36);
    }

    #[test]
    fn blocks_tile_from_the_top_left_and_pad_with_black() {
        let delta = 1e-4;
        // 3x2 image, 2x2 blocks: nx = 2, ny = 1; the right block has one
        // column inside the image and one of padding.
        let img = image(3, 2, &[1.0, 2.0, 4.0, 8.0, 16.0, 32.0]);
        let b = block_sums(&img, delta, Policy::ABS, 2, 2).unwrap();
        assert_eq!((b.nx, b.ny, b.padded_samples), (2, 1, 2));
        let t = |v| t(v, delta);
        assert_close(b.sums[0][0], t(1.0) + t(2.0) + t(8.0) + t(16.0));
        assert_close(b.sums[0][1], t(4.0) + t(32.0) + 2.0 * delta.log2());

        let total = log_average(&img, delta, Policy::ABS).log2_sum;
        let blocks: f64 = b.sums.iter().flatten().sum();
        assert_close(blocks - 2.0 * delta.log2(), total);
    }

    #[test]
    fn a_last_column_that_reads_the_real_width_has_no_padding_in_x() {
        let delta = 1e-4;
        // 3x3 image, 2x2 blocks, last column reading 1 texel per line: only
        // the bottom row of blocks is padded (one line each: 2 + 1 texels).
        let img = image(3, 3, &[1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 1.0, 1.0, 1.0]);
        let b = block_sums_last_width(&img, delta, Policy::ABS, 2, 2, 1).unwrap();
        assert_eq!((b.nx, b.ny, b.padded_samples), (2, 2, 3));
        let t = |v| t(v, delta);
        assert_close(b.sums[0][1], t(4.0) + t(32.0));
        assert_close(b.sums[1][1], t(1.0) + delta.log2());
        assert_close(b.sums[1][0], 2.0 * t(1.0) + 2.0 * delta.log2());
        // Reading less than the real width, or more than a block, is refused.
        assert!(block_sums_last_width(&img, delta, Policy::ABS, 2, 2, 0).is_err());
        assert!(block_sums_last_width(&img, delta, Policy::ABS, 2, 2, 3).is_err());
        assert_eq!(
            block_sums_last_width(&img, delta, Policy::ABS, 2, 2, 2).unwrap(),
            block_sums(&img, delta, Policy::ABS, 2, 2).unwrap()
        );
    }

    #[test]
    fn block_rows_come_first() {
        let img = image(1, 3, &[1.0, 2.0, 4.0]);
        let b = block_sums(&img, 0.0, Policy::ABS, 1, 1).unwrap();
        assert_eq!((b.nx, b.ny, b.padded_samples), (1, 3, 0));
        for (row, expected) in [0.0, 1.0, 2.0].into_iter().enumerate() {
            assert_eq!(b.sums[row].len(), 1);
            assert_close(b.sums[row][0], expected);
        }
    }

    #[test]
    fn full_blocks_with_delta_zero_have_no_padding_term() {
        let b = block_sums(&image(2, 2, &[1.0; 4]), 0.0, Policy::ABS, 2, 2).unwrap();
        assert_eq!(b.padded_samples, 0);
        assert!(b.sums[0][0].abs() < 1e-12, "{}", b.sums[0][0]);
    }

    #[test]
    fn blocks_larger_than_the_image() {
        let img = image(2, 2, &[1.0; 4]);
        let b = block_sums(&img, 1.0, Policy::ABS, 5, 3).unwrap();
        assert_eq!((b.nx, b.ny, b.padded_samples), (1, 1, 11));
        // log2(1 + 1) per pixel, log2(1 + 0) = 0 per padding texel.
        assert_close(b.sums[0][0], 4.0);
    }

    #[test]
    fn empty_image() {
        let img = image(0, 0, &[]);
        assert!(log_average(&img, 1e-4, Policy::ABS).log_average.is_nan());
        let b = block_sums(&img, 1e-4, Policy::ABS, 8, 8).unwrap();
        assert_eq!((b.nx, b.ny, b.padded_samples), (0, 0, 0));
    }

    #[test]
    fn zero_block_size_is_an_error() {
        let img = image(1, 1, &[1.0]);
        let err = block_sums(&img, 1e-4, Policy::ABS, 0, 4).unwrap_err();
        let expected = ReferenceError::ZeroBlockSize {
            block_width: 0,
            block_height: 4,
        };
        assert_eq!(err, expected);
        assert!(err.to_string().contains("0x4"));
    }

    #[test]
    fn rounding_bound_is_n_minus_one_units_of_the_magnitudes() {
        // delta 1 and L = 2^k - 1: terms 1, 2, 3, 4 (L rounding aside).
        let r = log_average(&image(4, 1, &[1.0, 3.0, 7.0, 15.0]), 1.0, Policy::ABS);
        assert_close(r.magnitude_sum, 10.0);
        assert_close(r.rounding_bound(), 3.0 * 10.0 * 2f64.powi(-53));
    }
}
