//! HDR images in, render targets out.
//!
//! ps30 checks a GPU log-average-luminance computation against a CPU
//! reference on real HDR photographs, so it must read the formats such images
//! come in (OpenEXR, Radiance RGBE, PFM) into one in-memory form,
//! [`HdrImage`], and write what the emulated passes produce
//! ([`RenderTarget`]s as OpenEXR or PFM, tone-mapped results as PNG).
//!
//! Reading never trusts a header: the claimed size is checked against
//! [`ImageLimits`] before any pixel memory is allocated, and every failure is
//! an [`ImageError`] naming the file and the problem. Writing is atomic: a
//! failed write leaves no partial file behind.

mod target;

pub use target::{RenderTarget, TargetFormat, Texture};

/// An RGBA image with f32 channels, as loaded from a file.
///
/// Pixels are row-major and row 0 is the TOP row of the picture, whatever
/// order the file stores its rows in. Alpha is 1 when the file has none;
/// single-channel (grey) files load as R = G = B. Values are kept exactly as
/// decoded: negative and non-finite values are not touched (see
/// [`HdrImage::stats`]).
#[derive(Clone, Debug, PartialEq)]
pub struct HdrImage {
    pub width: u32,
    pub height: u32,
    /// `width * height` pixels.
    pub pixels: Vec<[f32; 4]>,
}

/// Counts of pixels that need a policy decision in the reference.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct PixelStats {
    /// Pixels whose luminance (see [`crate::reference::luminance`]) is finite
    /// and below zero.
    pub negative_luminance: u64,
    /// Pixels whose luminance is NaN or infinite (some R, G or B channel is).
    pub non_finite: u64,
}

impl HdrImage {
    /// The pixel in column `x` of row `y` (row 0 at the top).
    ///
    /// # Panics
    /// If `x >= width` or `y >= height`.
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// How many pixels have negative or non-finite luminance.
    pub fn stats(&self) -> PixelStats {
        let mut stats = PixelStats::default();
        for &pixel in &self.pixels {
            let l = crate::reference::luminance(pixel);
            if !l.is_finite() {
                stats.non_finite += 1;
            } else if l < 0.0 {
                stats.negative_luminance += 1;
            }
        }
        stats
    }
}
