//! Render targets: where an emulated pass writes its pixels, with the storage
//! rounding of the real D3D9 surface format, and from where the next pass
//! samples them. Without the format's rounding the emulator would compute
//! with more precision than the GPU keeps between passes.

use half::f16;

/// The D3D9 surface formats ps30's passes render to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum TargetFormat {
    /// `D3DFMT_R32F`: one 32-bit float channel (red).
    R32F,
    /// `D3DFMT_A16B16G16R16F`: four IEEE half-float channels.
    Rgba16F,
}

impl TargetFormat {
    /// The value a texel of this format holds after `value` is written to it,
    /// as sampling it returns it.
    ///
    /// * `R32F` keeps red exactly; sampling returns G = B = A = 1, D3D9's
    ///   default for channels a format lacks.
    /// * `Rgba16F` rounds each channel to the nearest half (ties to even, as
    ///   `half::f16::from_f32` does): magnitudes from 65520 up become
    ///   infinite, 65504 (the largest half) and anything that rounds to it
    ///   stays finite, NaN stays NaN, tiny values become half subnormals or 0.
    pub fn round(self, value: [f32; 4]) -> [f32; 4] {
        match self {
            TargetFormat::R32F => [value[0], 1.0, 1.0, 1.0],
            TargetFormat::Rgba16F => value.map(|c| f16::from_f32(c).to_f32()),
        }
    }

    /// The D3D9 name of the format.
    pub fn d3d_name(self) -> &'static str {
        match self {
            TargetFormat::R32F => "D3DFMT_R32F",
            TargetFormat::Rgba16F => "D3DFMT_A16B16G16R16F",
        }
    }
}

/// A render target: `width * height` texels, row-major, row 0 at the top,
/// each holding exactly what its [`TargetFormat`] can store.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderTarget {
    pub width: u32,
    pub height: u32,
    pub format: TargetFormat,
    /// Every texel already rounded by `format` (see [`TargetFormat::round`]).
    pub texels: Vec<[f32; 4]>,
}

/// A read-only view of texels that a pass can sample: what the emulator
/// consumes, whether the texels come from a loaded image or a previous pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture<'a> {
    pub width: u32,
    pub height: u32,
    /// `width * height` texels, row-major, row 0 at the top.
    pub texels: &'a [[f32; 4]],
}

impl RenderTarget {
    /// A target cleared to black (as the format stores black: R32F reads
    /// back as (0, 1, 1, 1)).
    pub fn new(width: u32, height: u32, format: TargetFormat) -> RenderTarget {
        let len = width as usize * height as usize;
        RenderTarget {
            width,
            height,
            format,
            texels: vec![format.round([0.0; 4]); len],
        }
    }

    fn index(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "texel ({x}, {y}) outside the {}x{} target",
            self.width,
            self.height
        );
        y as usize * self.width as usize + x as usize
    }

    /// Writes `value` to texel (`x`, `y`), rounded as the format stores it.
    ///
    /// # Panics
    /// If `x >= width` or `y >= height` (the caller's loop is wrong).
    pub fn store(&mut self, x: u32, y: u32, value: [f32; 4]) {
        let i = self.index(x, y);
        self.texels[i] = self.format.round(value);
    }

    /// The texel at (`x`, `y`) as sampling returns it.
    ///
    /// # Panics
    /// If `x >= width` or `y >= height`.
    pub fn texel(&self, x: u32, y: u32) -> [f32; 4] {
        self.texels[self.index(x, y)]
    }

    /// The target as a texture for the next pass.
    pub fn as_texture(&self) -> Texture<'_> {
        Texture {
            width: self.width,
            height: self.height,
            texels: &self.texels,
        }
    }
}

impl super::HdrImage {
    /// The image as a texture for the first pass.
    pub fn as_texture(&self) -> Texture<'_> {
        Texture {
            width: self.width,
            height: self.height,
            texels: &self.pixels,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stored(format: TargetFormat, value: [f32; 4]) -> [f32; 4] {
        let mut target = RenderTarget::new(2, 1, format);
        target.store(1, 0, value);
        target.as_texture().texels[1]
    }

    #[test]
    fn rgba16f_rounds_to_nearest_half() {
        // Halves near 1 are 2^-10 apart: 1.0001 is nearer 1 than 1 + 2^-10.
        assert_eq!(stored(TargetFormat::Rgba16F, [1.0001; 4]), [1.0; 4]);
        let above = 1.0 + 0.75 * 2f32.powi(-10);
        assert_eq!(
            stored(TargetFormat::Rgba16F, [above; 4]),
            [1.0 + 2f32.powi(-10); 4]
        );
        // A tie rounds to the even neighbour: 1 + 2^-11 lies halfway
        // between 1 (even mantissa) and 1 + 2^-10 (odd).
        let tie = 1.0 + 2f32.powi(-11);
        assert_eq!(stored(TargetFormat::Rgba16F, [tie; 4]), [1.0; 4]);
    }

    #[test]
    fn rgba16f_range_ends() {
        let out = stored(TargetFormat::Rgba16F, [65504.0, 70000.0, -70000.0, 65519.0]);
        // 65504 is the largest half; 65519 is below the rounding midpoint
        // 65520 to the next (infinite) step, so it rounds down to 65504.
        assert_eq!(out, [65504.0, f32::INFINITY, f32::NEG_INFINITY, 65504.0]);
        let out = stored(TargetFormat::Rgba16F, [65520.0, f32::NAN, 1e-8, -0.0]);
        assert_eq!(out[0], f32::INFINITY);
        assert!(out[1].is_nan());
        assert_eq!(
            out[2], 0.0,
            "1e-8 is below half the smallest half subnormal"
        );
        assert!(out[3] == 0.0 && out[3].is_sign_negative());
    }

    #[test]
    fn rgba16f_keeps_subnormals() {
        let tiny = 2f32.powi(-24); // the smallest half subnormal
        assert_eq!(stored(TargetFormat::Rgba16F, [tiny; 4]), [tiny; 4]);
    }

    #[test]
    fn r32f_keeps_red_exactly_and_reads_one_elsewhere() {
        let red = 1.000_000_1_f32;
        assert_eq!(
            stored(TargetFormat::R32F, [red, 5.0, 6.0, 7.0]),
            [red, 1.0, 1.0, 1.0]
        );
        assert_eq!(stored(TargetFormat::R32F, [1e30, 0.0, 0.0, 0.0])[0], 1e30);
        assert!(stored(TargetFormat::R32F, [f32::NAN, 0.0, 0.0, 0.0])[0].is_nan());
    }

    #[test]
    fn new_targets_hold_black_as_the_format_stores_it() {
        assert_eq!(
            RenderTarget::new(1, 1, TargetFormat::R32F).texel(0, 0),
            [0.0, 1.0, 1.0, 1.0]
        );
        assert_eq!(
            RenderTarget::new(1, 1, TargetFormat::Rgba16F).texel(0, 0),
            [0.0; 4]
        );
    }

    #[test]
    fn store_addresses_row_major_from_the_top() {
        let mut target = RenderTarget::new(3, 2, TargetFormat::R32F);
        target.store(2, 1, [9.0; 4]);
        assert_eq!(target.texels[5][0], 9.0);
        assert_eq!(target.texel(2, 1)[0], 9.0);
        let texture = target.as_texture();
        assert_eq!(
            (texture.width, texture.height, texture.texels.len()),
            (3, 2, 6)
        );
    }

    #[test]
    #[should_panic(expected = "outside")]
    fn store_outside_panics() {
        RenderTarget::new(2, 2, TargetFormat::R32F).store(2, 0, [0.0; 4]);
    }
}
