//! Radiance RGBE (.hdr) input through the `image` crate's decoder, which
//! parses the header (and so the dimensions) before it touches any pixel, so
//! the size limit is checked before the pixel buffer exists.
//!
//! Two things the decoder lets through or reports vaguely are checked here,
//! under the policy of every reader: header lines ending in CR LF are
//! refused by name, and bytes after the last pixel are an error (as in PFM).
//!
//! RGBE stores an 8-bit mantissa per channel and one shared 8-bit exponent;
//! the decoder turns `(m, e)` into `m * 2^(e - 136)` exactly (no half-unit
//! offset), and `e = 0` into 0. The `EXPOSURE` header is not applied.

use super::{HdrImage, ImageError, ImageLimits};
use image::codecs::hdr::HdrDecoder;
use image::ImageDecoder;
use std::io::BufRead;
use std::path::Path;

const FORMAT: &str = "Radiance HDR";

fn decode_error(path: &Path, e: image::ImageError) -> ImageError {
    ImageError::Decode {
        path: path.to_path_buf(),
        format: FORMAT,
        source: Box::new(e),
    }
}

/// The header read by the decoder, its size checked against `limits`.
fn header<R: BufRead>(
    path: &Path,
    reader: R,
    limits: &ImageLimits,
) -> Result<HdrDecoder<R>, ImageError> {
    let mut reader = reader;
    let head = reader
        .fill_buf()
        .map_err(|e| ImageError::io(path, "read", e))?;
    if crlf_header(head) {
        return Err(super::crlf_error(path, FORMAT));
    }
    let decoder = HdrDecoder::new(reader).map_err(|e| decode_error(path, e))?;
    let (width, height) = decoder.dimensions();
    limits.check(path, FORMAT, width.into(), height.into())?;
    Ok(decoder)
}

/// The size the header states, checked against `limits`.
pub(super) fn size(
    path: &Path,
    reader: impl BufRead,
    limits: &ImageLimits,
) -> Result<(u32, u32), ImageError> {
    header(path, reader, limits).map(|d| d.dimensions())
}

pub(super) fn read(
    path: &Path,
    mut reader: impl BufRead,
    limits: &ImageLimits,
) -> Result<HdrImage, ImageError> {
    let decode_error = |e| decode_error(path, e);
    let decoder = header(path, &mut reader, limits)?;
    let (width, height) = decoder.dimensions();

    // The decoder writes RGB f32 in native byte order.
    let mut bytes = vec![0u8; width as usize * height as usize * 12];
    decoder.read_image(&mut bytes).map_err(decode_error)?;
    let extra = std::io::copy(&mut reader, &mut std::io::sink())
        .map_err(|e| ImageError::io(path, "read", e))?;
    if extra > 0 {
        return Err(ImageError::TrailingData {
            path: path.to_path_buf(),
            format: FORMAT,
            extra_bytes: extra,
        });
    }
    let pixels = bytes
        .chunks_exact(12)
        .map(|rgb| {
            let channel =
                |i: usize| f32::from_ne_bytes([rgb[i], rgb[i + 1], rgb[i + 2], rgb[i + 3]]);
            [channel(0), channel(4), channel(8), 1.0]
        })
        .collect();
    Ok(HdrImage {
        width,
        height,
        pixels,
    })
}

/// Whether a header line, up to the resolution line (`-Y 512 +X 768`),
/// ends in CR LF; `head` is the start of the file.
fn crlf_header(head: &[u8]) -> bool {
    for line in head.split(|&b| b == b'\n').take(64) {
        if line.ends_with(b"\r") {
            return true;
        }
        if line.starts_with(b"-Y") || line.starts_with(b"+Y") {
            break;
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::image::load;

    /// An uncompressed (flat) RGBE file: header, then 4 bytes per pixel,
    /// top row first.
    fn rgbe_file(width: u32, height: u32, pixels: &[[u8; 4]]) -> Vec<u8> {
        let mut bytes =
            format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n").into_bytes();
        for p in pixels {
            bytes.extend(p);
        }
        bytes
    }

    fn load_bytes(bytes: &[u8]) -> Result<HdrImage, ImageError> {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("test.hdr");
        std::fs::write(&path, bytes).unwrap();
        load(&path, &ImageLimits::default())
    }

    #[test]
    fn rgbe_decodes_as_mantissa_times_power_of_two() {
        // (128, 64, 0 | 129): 128 * 2^(129-136) = 1, 64 * 2^-7 = 0.5, 0.
        // Exponent 0 is black whatever the mantissas.
        let image = load_bytes(&rgbe_file(2, 1, &[[128, 64, 0, 129], [200, 200, 200, 0]])).unwrap();
        assert_eq!(
            image.pixels,
            vec![[1.0, 0.5, 0.0, 1.0], [0.0, 0.0, 0.0, 1.0]]
        );
    }

    #[test]
    fn rows_are_top_first() {
        let image = load_bytes(&rgbe_file(
            1,
            2,
            &[[128, 128, 128, 129], [128, 128, 128, 130]],
        ))
        .unwrap();
        assert_eq!(image.pixel(0, 0)[0], 1.0);
        assert_eq!(image.pixel(0, 1)[0], 2.0);
    }

    #[test]
    fn truncated_files_are_errors() {
        let full = rgbe_file(4, 4, &[[128, 128, 128, 129]; 16]);
        for len in [2, 12, 30, full.len() - 1] {
            let err = load_bytes(&full[..len]).unwrap_err();
            assert!(matches!(err, ImageError::Decode { .. }), "{len}: {err}");
            assert!(err.to_string().contains("test.hdr"), "{err}");
        }
    }

    #[test]
    fn absurd_size_is_refused_before_decoding() {
        let err = load_bytes(&rgbe_file(100_000, 100_000, &[])).unwrap_err();
        assert!(
            matches!(
                err,
                ImageError::TooLarge {
                    width: 100_000,
                    height: 100_000,
                    ..
                }
            ),
            "{err}"
        );
    }
}
