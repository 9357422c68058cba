//! Output images by extension: one rule, for every command that writes an
//! image, that picks the format from the file name and refuses a name it
//! cannot write — so `-o copy.png` never silently writes OpenEXR.
//!
//! | extension | format | what is written |
//! |---|---|---|
//! | `.exr` | OpenEXR | exact stored values: R32F one float channel, A16B16G16R16F four half channels |
//! | `.pfm` | PFM | exact f32 values: R32F grey (`Pf`), A16B16G16R16F RGB (`PF`, no alpha) |
//! | `.hdr` | Radiance RGBE | RGB with 8-bit mantissas and a shared exponent; negative or non-finite values are refused |
//! | `.png` | 8-bit PNG | each stored channel as a D3DFMT_A8R8G8B8 target stores it ([`super::unorm8`]: clamped to [0, 1], NaN to 0, times 255, rounded half up); one-channel formats as grey, two-channel ones as RGB with blue 0; the count of clamped values is reported |
//!
//! Extensions are matched without regard to case. Tone mapping writes its
//! own 8-bit sRGB PNG (see `jobs::tonemap`) and uses this rule for the
//! floating-point formats.

use super::{write_atomically, ImageError, RenderTarget, TargetFormat};
use std::path::Path;

/// An image file format ps30 writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// `.exr`
    OpenExr,
    /// `.pfm`
    Pfm,
    /// `.hdr`
    Radiance,
    /// `.png`
    Png,
}

impl OutputFormat {
    /// The format a path's extension names, or why there is none.
    pub fn of(path: &Path) -> Result<OutputFormat, ImageError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("exr") => Ok(OutputFormat::OpenExr),
            Some("pfm") => Ok(OutputFormat::Pfm),
            Some("hdr") => Ok(OutputFormat::Radiance),
            Some("png") => Ok(OutputFormat::Png),
            other => Err(ImageError::Unwritable {
                path: path.to_path_buf(),
                problem: format!(
                    "{}; ps30 writes .exr (OpenEXR), .pfm, .hdr (Radiance) and .png",
                    match other {
                        Some(e) => format!("cannot write a `.{e}` file"),
                        None => "the name has no extension to choose a format by".to_string(),
                    }
                ),
            }),
        }
    }

    /// The format's name, as messages give it.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::OpenExr => "OpenEXR",
            OutputFormat::Pfm => "PFM",
            OutputFormat::Radiance => "Radiance HDR",
            OutputFormat::Png => "8-bit PNG",
        }
    }
}

/// What a write did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Written {
    /// The format written (chosen by the extension).
    pub format: OutputFormat,
    /// PNG: stored values outside [0, 1] (or NaN) that were clamped.
    pub clamped: u64,
}

/// Writes a render target in the format its path's extension names (see the
/// module docs), atomically.
pub fn write_target(path: &Path, target: &RenderTarget) -> Result<Written, ImageError> {
    let format = OutputFormat::of(path)?;
    let channels = target.format.channels();
    let mut clamped = 0;
    match format {
        OutputFormat::OpenExr => super::write_exr(path, target)?,
        OutputFormat::Pfm => super::write_pfm(path, target)?,
        OutputFormat::Radiance => {
            let rgb: Vec<[f32; 3]> = target
                .texels
                .iter()
                .map(|t| {
                    if channels == 1 {
                        [t[0]; 3]
                    } else {
                        [t[0], t[1], t[2]]
                    }
                })
                .collect();
            write_radiance(path, target.width, target.height, &rgb)?;
        }
        OutputFormat::Png => {
            // Two channels (R, G) are written as RGB with blue 0: PNG's
            // two-channel type is grey and alpha.
            let written = if channels == 2 { 3 } else { channels };
            let mut bytes = Vec::with_capacity(target.texels.len() * written);
            for t in &target.texels {
                let stored = t[..channels].iter().chain(std::iter::repeat(&0.0));
                for &v in stored.take(written) {
                    clamped += u64::from(!(0.0..=1.0).contains(&v));
                    bytes.push(super::unorm8(v));
                }
            }
            super::png::write_png(path, target.width, target.height, written, &bytes)?;
        }
    }
    Ok(Written { format, clamped })
}

/// Writes linear RGB floats as Radiance RGBE, refusing what RGBE cannot
/// hold (negative or non-finite values).
pub fn write_radiance(
    path: &Path,
    width: u32,
    height: u32,
    rgb: &[[f32; 3]],
) -> Result<(), ImageError> {
    let bad = rgb
        .iter()
        .flatten()
        .filter(|v| !(v.is_finite() && **v >= 0.0))
        .count();
    if bad > 0 {
        return Err(radiance_refusal(path, bad as u64, rgb.len() as u64 * 3));
    }
    let pixels: Vec<image::Rgb<f32>> = rgb.iter().map(|&p| image::Rgb(p)).collect();
    write_atomically(path, "Radiance HDR", |w| {
        image::codecs::hdr::HdrEncoder::new(w).encode(&pixels, width as usize, height as usize)?;
        Ok(())
    })
}

/// Why `bad` of an image's `total` values cannot be written as RGBE.
pub(super) fn radiance_refusal(path: &Path, bad: u64, total: u64) -> ImageError {
    ImageError::Unwritable {
        path: path.to_path_buf(),
        problem: format!(
            "Radiance RGBE holds only finite values ≥ 0, and {} of the {} values are negative or not finite; write .exr or .pfm instead",
            crate::core::numbers::thousands(bad),
            crate::core::numbers::thousands(total)
        ),
    }
}

/// Writes linear RGB floats (e.g. a tone-mapped image before its sRGB
/// encoding) as OpenEXR, PFM or Radiance by extension; PNG is the caller's
/// (its encoding is a choice of the job).
pub fn write_rgb_float(
    path: &Path,
    width: u32,
    height: u32,
    rgb: &[[f32; 3]],
) -> Result<OutputFormat, ImageError> {
    let format = OutputFormat::of(path)?;
    let target = || RenderTarget {
        width,
        height,
        format: TargetFormat::Rgba16F,
        texels: rgb.iter().map(|p| [p[0], p[1], p[2], 1.0]).collect(),
    };
    match format {
        OutputFormat::Radiance => write_radiance(path, width, height, rgb)?,
        OutputFormat::OpenExr => super::openexr::write_rgb_f32(path, width, height, rgb)?,
        OutputFormat::Pfm => super::write_pfm(path, &target())?,
        OutputFormat::Png => {
            return Err(ImageError::Unwritable {
                path: path.to_path_buf(),
                problem: "this output is written as PNG by its own encoding".to_string(),
            })
        }
    }
    Ok(format)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn target(format: TargetFormat, values: &[[f32; 4]]) -> RenderTarget {
        let mut t = RenderTarget::new(values.len() as u32, 1, format);
        for (x, v) in values.iter().enumerate() {
            t.store(x as u32, 0, *v);
        }
        t
    }

    #[test]
    fn the_extension_chooses_the_format() {
        let dir = tempfile::tempdir().unwrap();
        let t = target(
            TargetFormat::R32F,
            &[[0.25, 0.0, 0.0, 0.0], [2.0, 0.0, 0.0, 0.0]],
        );
        for (name, magic) in [
            ("a.exr", &[0x76u8, 0x2f, 0x31, 0x01][..]),
            ("a.PFM", b"Pf"),
            ("a.hdr", b"#?"),
            ("a.png", &[0x89, b'P', b'N', b'G']),
        ] {
            let path = dir.path().join(name);
            write_target(&path, &t).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert!(bytes.starts_with(magic), "{name}");
        }
        let png = image::open(dir.path().join("a.png")).unwrap().to_luma8();
        assert_eq!(
            png.into_raw(),
            vec![64, 255],
            "0.25 → round(63.75) = 64; 2 clamps to 255"
        );
    }

    #[test]
    fn unknown_extensions_and_negative_rgbe_are_refused_and_write_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let t = target(TargetFormat::R32F, &[[-1.0, 0.0, 0.0, 0.0]]);
        for name in ["a.jpg", "a", "a.hdr"] {
            let path = dir.path().join(name);
            let e = write_target(&path, &t).unwrap_err().to_string();
            assert!(e.contains(".exr"), "{e}");
            assert!(!path.exists());
        }
        let w = write_target(&dir.path().join("a.png"), &t).unwrap();
        assert_eq!(w.clamped, 1);
    }
}
