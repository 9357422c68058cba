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
    pub negative: NegativePolicy,
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
        if !l.is_finite() && self.non_finite == NonFinitePolicy::Skip {
            return None;
        }
        Some(match self.negative {
            NegativePolicy::Abs => (delta + l).abs().log2(),
            // `l < 0.0` is false for NaN, so NaN stays NaN (f64::max would
            // turn it into 0).
            NegativePolicy::Clamp => (delta + if l < 0.0 { 0.0 } else { l }).log2(),
        })
    }
}

/// The log-average luminance of an image and the figures behind it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Reference {
    pub width: u32,
    pub height: u32,
    pub delta: f64,
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
    for &pixel in &image.pixels {
        let l = luminance(pixel);
        if l.is_finite() {
            result.min_luminance = result.min_luminance.min(l);
            result.max_luminance = result.max_luminance.max(l);
            if l < 0.0 {
                result.negative_pixels += 1;
            }
        } else {
            result.nonfinite_pixels += 1;
        }
        if let Some(term) = policy.term(l, delta) {
            result.samples += 1;
            result.log2_sum += term;
            result.magnitude_sum += term.abs();
        }
    }
    result.log_average = (result.log2_sum / result.samples as f64).exp2();
    result
}

/// Per-block sums of the log2 terms, as the first reduction pass computes
/// them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BlockSums {
    pub block_width: u32,
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
    ZeroBlockSize { block_width: u32, block_height: u32 },
    /// The last column's read width does not cover the frame's real width
    /// there, or exceeds the block width.
    LastWidth {
        last_width: u32,
        real_width: u32,
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
    if block_width == 0 || block_height == 0 {
        return Err(ReferenceError::ZeroBlockSize {
            block_width,
            block_height,
        });
    }
    let (width, height) = (image.width, image.height);
    let nx = width.div_ceil(block_width);
    let ny = height.div_ceil(block_height);
    let real_last = width.saturating_sub(nx.saturating_sub(1) * block_width);
    if last_width > block_width || last_width < real_last {
        return Err(ReferenceError::LastWidth {
            last_width,
            real_width: real_last,
            block_width,
        });
    }
    let mut sums = vec![vec![0.0; nx as usize]; ny as usize];
    let mut magnitude_sums = sums.clone();
    let mut inside = vec![vec![0u64; nx as usize]; ny as usize];

    // Rows beyond `height` (an inconsistent image) are ignored; an image
    // of width 0 has no rows and no blocks.
    if width > 0 {
        let rows = image
            .pixels
            .chunks_exact(width as usize)
            .take(height as usize);
        for (y, row) in rows.enumerate() {
            let block_row = y / block_height as usize;
            for (x, &pixel) in row.iter().enumerate() {
                let block_col = x / block_width as usize;
                inside[block_row][block_col] += 1;
                if let Some(term) = policy.term(luminance(pixel), delta) {
                    sums[block_row][block_col] += term;
                    magnitude_sums[block_row][block_col] += term.abs();
                }
            }
        }
    }

    // Padding texels are black: luminance 0, one term log2(delta) each
    // (the same under every policy), added once per block as count * term.
    let black = policy.term(0.0, delta).unwrap_or(0.0);
    let mut padded_samples = 0;
    for row in 0..ny as usize {
        for col in 0..nx as usize {
            let read_width = if col + 1 == nx as usize {
                last_width
            } else {
                block_width
            };
            let block_area = u64::from(read_width) * u64::from(block_height);
            let padded = block_area - inside[row][col];
            padded_samples += padded;
            // Skipped when 0: 0 * log2(0) would be NaN for delta = 0.
            if padded > 0 {
                sums[row][col] += padded as f64 * black;
                magnitude_sums[row][col] += padded as f64 * black.abs();
            }
        }
    }
    Ok(BlockSums {
        block_width,
        block_height,
        nx,
        ny,
        padded_samples,
        sums,
        magnitude_sums,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
