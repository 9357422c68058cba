//! Render targets: where an emulated pass writes its pixels, with the storage
//! rounding of the real D3D9 surface format, and from where the next pass
//! samples them. Without the format's rounding the emulator would compute
//! with more precision than the GPU keeps between passes.
//!
//! # The formats and what they store
//!
//! | format | channels | each channel |
//! |---|---|---|
//! | `D3DFMT_A8R8G8B8` | R, G, B, A | 8-bit UNORM: `c / 255` |
//! | `D3DFMT_R16F`, `D3DFMT_G16R16F`, `D3DFMT_A16B16G16R16F` | R; R, G; R, G, B, A | IEEE half |
//! | `D3DFMT_R32F`, `D3DFMT_G32R32F`, `D3DFMT_A32B32G32R32F` | R; R, G; R, G, B, A | IEEE single |
//!
//! Facts, with their sources:
//!
//! * **Channels a format lacks read back as 1.** "a DirectX 9.0 version
//!   driver should set the default values for the unused channels in the
//!   following DirectX 9.0 floating-point texture formats to 1.0f:
//!   D3DFMT_R16F, D3DFMT_G16R16F, D3DFMT_R32F, D3DFMT_G32R32F", and alpha to
//!   1.0 (Microsoft, "Recommended DirectX 9.0 Driver Support", Windows
//!   driver docs). So an R32F texel reads (R, 1, 1, 1), a G16R16F texel
//!   (R, G, 1, 1).
//! * **Float to 8-bit UNORM.** Direct3D 9 documents no conversion rule; the
//!   closest public definition is Direct3D 10's ("Data Conversion Rules",
//!   FLOAT → UNORM): NaN gives 0; values above 1 (+∞ included) give 1, below
//!   0 (−∞ included) give 0; then `c · (2ⁿ − 1)`, add 0.5 and drop the
//!   fraction. ps30 applies it exactly (in f64, where `c · 255` of an f32 is
//!   exact), so a value lands on code k + 1 exactly when it is at least
//!   (k + ½)/255: round half up. The D3D10 rule permits hardware a tolerance
//!   (0.6 ULP on the integer side); ps30 takes none. Reading back: `k / 255`
//!   ("UNORM → FLOAT"), rounded to f32.
//! * **Float to half.** Round to nearest, ties to even (what `half` and IEEE
//!   754 do): magnitudes from 65,520 up become ±∞, NaN stays NaN, tiny values
//!   become subnormals or 0. Direct3D 9 documents no rule. Direct3D 10's
//!   "Data Conversion Rules" page says the opposite for float-to-float
//!   conversions — round toward zero, and the largest finite value instead of
//!   ±∞ — so a D3D10-rule part would store 65,504 where ps30 stores ∞; ps30
//!   keeps the IEEE rule (see the README's finding 3, which depends on it).
//! * **Float to single**: exact.

use half::f16;

/// How one stored channel of a format is encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Encoding {
    /// 8-bit unsigned normalized: codes 0..=255 stand for k/255.
    Unorm8,
    /// IEEE 754 binary16.
    Half,
    /// IEEE 754 binary32.
    Float,
}

impl Encoding {
    /// The value a channel holds after `c` is written to it (see the module
    /// docs for each rule).
    pub fn store(self, c: f32) -> f32 {
        match self {
            Encoding::Unorm8 => unorm8_value(unorm8(c)),
            Encoding::Half => f16::from_f32(c).to_f32(),
            Encoding::Float => c,
        }
    }
}

impl Encoding {
    /// [`Encoding::store`] of a value computed in f64, rounded once (no
    /// detour through f32, which could round twice).
    pub fn store_f64(self, c: f64) -> f32 {
        match self {
            Encoding::Unorm8 if c.is_nan() => 0.0,
            Encoding::Unorm8 => unorm8_value((c.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8),
            Encoding::Half => half_from_f64(c) as f32,
            Encoding::Float => c as f32,
        }
    }
}

/// `x` rounded once to the nearest half float (ties to even; from 65,520 up
/// ±∞; NaN stays NaN), returned as the f64 it equals. `half`'s own
/// `f16::from_f64` goes through f32 on x86 with F16C and can round twice
/// (331.87499999999994 becomes 332, not 331.75), so ps30 rounds here.
pub fn half_from_f64(x: f64) -> f64 {
    if x.is_nan() || x.is_infinite() || x == 0.0 {
        return x;
    }
    if x.abs() >= 65_520.0 {
        return f64::INFINITY.copysign(x);
    }
    // The binade of |x| from its exponent bits (x is a normal f64 here: the
    // smallest half subnormal is far above f64's subnormals).
    let exponent = (((x.to_bits() >> 52) & 0x7ff) as i32 - 1023).max(-14);
    let spacing = 2f64.powi(exponent - 10);
    (x / spacing).round_ties_even() * spacing
}

impl Encoding {
    /// The largest error of storing any value of magnitude at most `v`
    /// (within the encoding's range): half a code (½/255) for 8-bit UNORM
    /// values in [0, 1]; half the spacing of the grid at `v` for half and
    /// single floats (the spacing only grows with the magnitude), with the
    /// subnormal spacing as the floor; ∞ past the largest finite half.
    pub fn max_rounding_error(self, v: f64) -> f64 {
        let v = v.abs();
        let half_spacing = |bits: i32, min_exp: f64| {
            let e = if v > 0.0 { v.log2().floor() } else { min_exp }.max(min_exp);
            (e - bits as f64).exp2() / 2.0
        };
        match self {
            Encoding::Unorm8 => 0.5 / 255.0,
            Encoding::Half if v >= 65_520.0 => f64::INFINITY,
            Encoding::Half => half_spacing(10, -14.0),
            Encoding::Float => half_spacing(23, -126.0),
        }
    }
}

/// Direct3D 10's FLOAT → UNORM conversion for 8 bits: NaN → 0, clamp to
/// [0, 1], scale by 255, add ½ and drop the fraction (computed exactly).
pub fn unorm8(c: f32) -> u8 {
    if c.is_nan() {
        return 0;
    }
    let scaled = (c.clamp(0.0, 1.0) as f64) * 255.0;
    (scaled + 0.5).floor() as u8
}

/// The value an 8-bit UNORM code stands for, k/255 rounded to f32.
pub fn unorm8_value(code: u8) -> f32 {
    code as f32 / 255.0
}

/// The D3D9 surface formats ps30 renders to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum TargetFormat {
    /// `D3DFMT_A8R8G8B8`: four 8-bit UNORM channels.
    A8R8G8B8,
    /// `D3DFMT_R16F`: one half-float channel (red).
    R16F,
    /// `D3DFMT_G16R16F`: two half-float channels (red, green).
    G16R16F,
    /// `D3DFMT_A16B16G16R16F`: four half-float channels.
    Rgba16F,
    /// `D3DFMT_R32F`: one 32-bit float channel (red).
    R32F,
    /// `D3DFMT_G32R32F`: two 32-bit float channels (red, green).
    G32R32F,
    /// `D3DFMT_A32B32G32R32F`: four 32-bit float channels.
    A32B32G32R32F,
}

impl TargetFormat {
    /// Every format, 8-bit first, then half, then single.
    pub const ALL: [TargetFormat; 7] = [
        TargetFormat::A8R8G8B8,
        TargetFormat::R16F,
        TargetFormat::G16R16F,
        TargetFormat::Rgba16F,
        TargetFormat::R32F,
        TargetFormat::G32R32F,
        TargetFormat::A32B32G32R32F,
    ];

    /// How each stored channel is encoded.
    pub fn encoding(self) -> Encoding {
        match self {
            TargetFormat::A8R8G8B8 => Encoding::Unorm8,
            TargetFormat::R16F | TargetFormat::G16R16F | TargetFormat::Rgba16F => Encoding::Half,
            TargetFormat::R32F | TargetFormat::G32R32F | TargetFormat::A32B32G32R32F => {
                Encoding::Float
            }
        }
    }

    /// How many channels it stores: R; R, G; or R, G, B, A.
    pub fn channels(self) -> usize {
        match self {
            TargetFormat::R16F | TargetFormat::R32F => 1,
            TargetFormat::G16R16F | TargetFormat::G32R32F => 2,
            TargetFormat::A8R8G8B8 | TargetFormat::Rgba16F | TargetFormat::A32B32G32R32F => 4,
        }
    }

    /// Whether channel `c` (0 = R … 3 = A) is stored.
    pub fn stores(self, c: usize) -> bool {
        c < self.channels()
    }

    /// The value a texel of this format holds after `value` is written to it,
    /// as sampling it returns it: each stored channel through
    /// [`Encoding::store`], the others read as 1 (see the module docs).
    pub fn round(self, value: [f32; 4]) -> [f32; 4] {
        let e = self.encoding();
        std::array::from_fn(|c| {
            if self.stores(c) {
                e.store(value[c])
            } else {
                1.0
            }
        })
    }

    /// [`TargetFormat::round`] of a value computed in f64, each stored
    /// channel rounded once ([`Encoding::store_f64`]).
    pub fn round_f64(self, value: [f64; 4]) -> [f32; 4] {
        let e = self.encoding();
        std::array::from_fn(|c| {
            if self.stores(c) {
                e.store_f64(value[c])
            } else {
                1.0
            }
        })
    }

    /// The D3D9 name of the format.
    pub fn d3d_name(self) -> &'static str {
        match self {
            TargetFormat::A8R8G8B8 => "D3DFMT_A8R8G8B8",
            TargetFormat::R16F => "D3DFMT_R16F",
            TargetFormat::G16R16F => "D3DFMT_G16R16F",
            TargetFormat::Rgba16F => "D3DFMT_A16B16G16R16F",
            TargetFormat::R32F => "D3DFMT_R32F",
            TargetFormat::G32R32F => "D3DFMT_G32R32F",
            TargetFormat::A32B32G32R32F => "D3DFMT_A32B32G32R32F",
        }
    }

    /// The format named `name`: the D3D9 name with or without `D3DFMT_`, in
    /// any case (`A16B16G16R16F`, `d3dfmt_r32f`).
    pub fn from_name(name: &str) -> Option<TargetFormat> {
        let upper = name.trim().to_ascii_uppercase();
        let bare = upper.strip_prefix("D3DFMT_").unwrap_or(&upper);
        TargetFormat::ALL
            .into_iter()
            .find(|f| &f.d3d_name()["D3DFMT_".len()..] == bare)
    }
}

/// A render target: `width * height` texels, row-major, row 0 at the top,
/// each holding exactly what its [`TargetFormat`] can store.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderTarget {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// What each texel can store.
    pub format: TargetFormat,
    /// Every texel already rounded by `format` (see [`TargetFormat::round`]).
    pub texels: Vec<[f32; 4]>,
}

/// A read-only view of texels that a pass can sample: what the emulator
/// consumes, whether the texels come from a loaded image or a previous pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture<'a> {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
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
    fn unorm8_rounds_half_up_at_each_code_boundary() {
        // (k + 1/2)/255 is not an f32; the f32 just below it stays on k, the
        // one just above moves to k + 1 (c · 255 is exact in f64).
        for k in [0u8, 127, 254] {
            let boundary = (k as f64 + 0.5) / 255.0;
            let below = boundary as f32;
            let (below, above) = if (below as f64) < boundary {
                (below, f32::from_bits(below.to_bits() + 1))
            } else {
                (f32::from_bits(below.to_bits() - 1), below)
            };
            assert_eq!(unorm8(below), k, "just below (k + 1/2)/255, k = {k}");
            assert_eq!(unorm8(above), k + 1, "just above, k = {k}");
        }
        // A value exactly on a half step rounds up: 0.5 · 255 = 127.5 → 128.
        assert_eq!(unorm8(0.5), 128);
        assert_eq!(unorm8(0.0), 0);
        assert_eq!(unorm8(-0.0), 0);
        assert_eq!(unorm8(1.0), 255);
        assert_eq!(unorm8(-3.0), 0);
        assert_eq!(unorm8(7.0), 255);
        assert_eq!(unorm8(f32::INFINITY), 255);
        assert_eq!(unorm8(f32::NEG_INFINITY), 0);
        assert_eq!(unorm8(f32::NAN), 0);
        assert_eq!(unorm8_value(255), 1.0);
        assert_eq!(unorm8_value(0), 0.0);
        assert_eq!(unorm8_value(51), 0.2);
    }

    #[test]
    fn the_rounding_bound_holds_at_grid_ends() {
        let h = Encoding::Half;
        // Halves in [1, 2) are 2^-10 apart; in [2048, 4096) 2 apart.
        assert_eq!(h.max_rounding_error(1.0), 2f64.powi(-11));
        assert_eq!(h.max_rounding_error(1.999), 2f64.powi(-11));
        assert_eq!(h.max_rounding_error(3000.0), 1.0);
        assert_eq!(
            h.max_rounding_error(1e-9),
            2f64.powi(-25),
            "subnormal spacing 2^-24"
        );
        assert_eq!(h.max_rounding_error(0.0), 2f64.powi(-25));
        assert_eq!(h.max_rounding_error(70_000.0), f64::INFINITY);
        assert_eq!(Encoding::Float.max_rounding_error(1.5), 2f64.powi(-24));
        assert_eq!(Encoding::Unorm8.max_rounding_error(0.3), 0.5 / 255.0);
        // And it does bound the real rounding, on a sweep of values.
        for i in 1..2000 {
            let v = i as f64 * 0.731 + 1e-3;
            let stored = half_from_f64(v);
            assert!((stored - v).abs() <= h.max_rounding_error(v), "{v}");
        }
    }

    #[test]
    fn half_from_f64_rounds_once() {
        // Just below the tie 331.875 between the halves 331.75 and 332.
        let below = f64::from_bits(331.875f64.to_bits() - 1);
        assert_eq!(half_from_f64(below), 331.75);
        assert_eq!(
            half_from_f64(331.875),
            332.0,
            "the tie goes to the even 332"
        );
        assert_eq!(half_from_f64(2049.0), 2048.0);
        assert_eq!(half_from_f64(2051.0), 2052.0);
        assert_eq!(half_from_f64(65_519.99), 65_504.0);
        assert_eq!(half_from_f64(65_520.0), f64::INFINITY);
        assert_eq!(half_from_f64(-70_000.0), f64::NEG_INFINITY);
        assert_eq!(
            half_from_f64(3f64 * 2f64.powi(-26)),
            2f64.powi(-24),
            "1.5 subnormal steps → 2 (even)"
        );
        assert_eq!(half_from_f64(2f64.powi(-26)), 0.0);
        assert!(half_from_f64(f64::NAN).is_nan());
        // Agrees with the f32 path wherever f32 holds the value exactly.
        for i in 0..5000u32 {
            let v = (i as f32 * 0.37 + 0.001) * if i % 2 == 0 { 1.0 } else { -1.0 };
            assert_eq!(half_from_f64(v as f64), f16::from_f32(v).to_f64(), "{v}");
        }
    }

    #[test]
    fn a8r8g8b8_stores_codes_in_every_channel() {
        let out = stored(TargetFormat::A8R8G8B8, [0.5, 2.0, -1.0, 0.1]);
        assert_eq!(out, [128.0 / 255.0, 1.0, 0.0, 26.0 / 255.0]);
        // Storing a stored value changes nothing.
        assert_eq!(stored(TargetFormat::A8R8G8B8, out), out);
    }

    #[test]
    fn missing_channels_read_one() {
        let v = [0.1f32, 0.2, 0.3, 0.4];
        let h = |x: f32| f16::from_f32(x).to_f32();
        assert_eq!(stored(TargetFormat::R16F, v), [h(0.1), 1.0, 1.0, 1.0]);
        assert_eq!(stored(TargetFormat::G16R16F, v), [h(0.1), h(0.2), 1.0, 1.0]);
        assert_eq!(stored(TargetFormat::G32R32F, v), [0.1, 0.2, 1.0, 1.0]);
        assert_eq!(stored(TargetFormat::A32B32G32R32F, v), v);
        for f in TargetFormat::ALL {
            assert_eq!(
                (0..4).filter(|&c| f.stores(c)).count(),
                f.channels(),
                "{f:?}"
            );
        }
    }

    #[test]
    fn formats_are_found_by_their_d3d_names() {
        for f in TargetFormat::ALL {
            assert_eq!(TargetFormat::from_name(f.d3d_name()), Some(f));
            let bare = f.d3d_name().trim_start_matches("D3DFMT_").to_lowercase();
            assert_eq!(TargetFormat::from_name(&bare), Some(f));
        }
        assert_eq!(TargetFormat::from_name("R8G8B8"), None);
        assert_eq!(TargetFormat::from_name(""), None);
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
