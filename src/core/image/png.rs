//! 8-bit PNG output, for looking at results with any image viewer:
//! tone-mapped images (sRGB) and render targets (see `save`).

use super::write_atomically;
use super::ImageError;
use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::path::Path;

/// Writes `rgb` (`width * height` pixels of 3 bytes, row-major, top row
/// first, already sRGB-encoded) as a PNG file, atomically.
pub fn write_png_rgb8(path: &Path, width: u32, height: u32, rgb: &[u8]) -> Result<(), ImageError> {
    write_png(path, width, height, 3, rgb)
}

/// Writes 8-bit samples, `channels` per pixel (1 grey, 2 grey + alpha, 3
/// RGB, 4 RGBA), row-major, top row first, as a PNG file, atomically.
pub(crate) fn write_png(
    path: &Path,
    width: u32,
    height: u32,
    channels: usize,
    samples: &[u8],
) -> Result<(), ImageError> {
    check_length(path, width, height, channels, samples)?;
    write_atomically(path, "PNG", |w| {
        PngEncoder::new(w).write_image(samples, width, height, colour_type(channels))?;
        Ok(())
    })
}

/// The PNG file [`write_png_rgb8`] writes, as bytes (for a
/// [`crate::core::output::Batch`]); `path` is only named in errors.
pub fn encode_png_rgb8(
    path: &Path,
    width: u32,
    height: u32,
    rgb: &[u8],
) -> Result<Vec<u8>, ImageError> {
    check_length(path, width, height, 3, rgb)?;
    let mut out = Vec::new();
    PngEncoder::new(&mut out)
        .write_image(rgb, width, height, ExtendedColorType::Rgb8)
        .map_err(|e| ImageError::Encode {
            path: path.to_path_buf(),
            format: "PNG",
            source: Box::new(e),
        })?;
    Ok(out)
}

fn colour_type(channels: usize) -> ExtendedColorType {
    match channels {
        1 => ExtendedColorType::L8,
        2 => ExtendedColorType::La8,
        3 => ExtendedColorType::Rgb8,
        _ => ExtendedColorType::Rgba8,
    }
}

fn check_length(
    path: &Path,
    width: u32,
    height: u32,
    channels: usize,
    samples: &[u8],
) -> Result<(), ImageError> {
    let expected = u64::from(width) * u64::from(height) * channels as u64;
    if samples.len() as u64 != expected {
        return Err(ImageError::DataLength {
            path: path.to_path_buf(),
            what: "the 8-bit sample buffer",
            expected,
            found: samples.len() as u64,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.png");
        let rgb: Vec<u8> = (0..2 * 3 * 3).map(|i| i as u8 * 10).collect();
        write_png_rgb8(&path, 2, 3, &rgb).unwrap();
        let decoded = image::open(&path).unwrap().to_rgb8();
        assert_eq!(decoded.dimensions(), (2, 3));
        assert_eq!(decoded.into_raw(), rgb);
    }

    #[test]
    fn wrong_length_is_refused_and_writes_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.png");
        let err = write_png_rgb8(&path, 2, 2, &[0; 11]).unwrap_err();
        assert!(
            matches!(
                err,
                ImageError::DataLength {
                    expected: 12,
                    found: 11,
                    ..
                }
            ),
            "{err}"
        );
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[test]
    fn missing_directory_leaves_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing/out.png");
        let err = write_png_rgb8(&path, 1, 1, &[1, 2, 3]).unwrap_err();
        assert!(matches!(err, ImageError::Refused { .. }), "{err}");
        assert!(err.to_string().contains("does not exist"), "{err}");
        assert!(!path.exists());
    }
}
