//! PFM (Portable Float Map), read and written by hand: the format is a short
//! text header and raw f32 samples, too simple to need a crate, and easy to
//! get subtly wrong (byte order from the sign of the scale, rows stored
//! bottom-to-top).
//!
//! Layout: `PF` (RGB) or `Pf` (grey), whitespace, width, whitespace, height,
//! whitespace, scale, ONE whitespace byte, then `height` rows of `width`
//! pixels of 3 or 1 f32 samples, the BOTTOM row of the picture first. A
//! negative scale means little-endian samples, a positive one big-endian; its
//! magnitude is not applied to the samples.

use super::write_atomically;
use super::{HdrImage, ImageError, ImageLimits, RenderTarget};
use std::io::{self, BufRead, Read, Write};
use std::path::Path;

const FORMAT: &str = "PFM";

/// A header token longer than this is not a number we could use.
const MAX_TOKEN: usize = 64;

struct Header {
    width: u32,
    height: u32,
    channels: usize,
    little_endian: bool,
}

/// The size the header states, checked against `limits`.
pub(super) fn size(
    path: &Path,
    mut reader: impl BufRead,
    limits: &ImageLimits,
) -> Result<(u32, u32), ImageError> {
    let header = read_header(path, &mut reader)?;
    limits.check(path, FORMAT, header.width.into(), header.height.into())?;
    Ok((header.width, header.height))
}

pub(super) fn read(
    path: &Path,
    mut reader: impl BufRead,
    limits: &ImageLimits,
) -> Result<HdrImage, ImageError> {
    let header = read_header(path, &mut reader)?;
    limits.check(path, FORMAT, header.width.into(), header.height.into())?;
    let (width, height) = (header.width as usize, header.height as usize);
    let row_bytes = width * header.channels * 4;
    let expected = (row_bytes * height) as u64;

    let read_error = |e| ImageError::io(path, "read", e);
    let decode = |b: &[u8]| {
        let bytes = [b[0], b[1], b[2], b[3]];
        match header.little_endian {
            true => f32::from_le_bytes(bytes),
            false => f32::from_be_bytes(bytes),
        }
    };
    // Rows are decoded as they are read: the file is never held whole, and
    // memory grows with the bytes actually found.
    let mut pixels: Vec<[f32; 4]> = Vec::new();
    let mut row = Vec::with_capacity(row_bytes);
    for i in 0..height {
        row.clear();
        (&mut reader)
            .take(row_bytes as u64)
            .read_to_end(&mut row)
            .map_err(read_error)?;
        if row.len() < row_bytes {
            let found = (i * row_bytes + row.len()) as u64;
            let incomplete = height - i;
            return Err(ImageError::Truncated {
                path: path.to_path_buf(),
                format: FORMAT,
                missing: format!(
                    "pixel data ends after {found} of {expected} bytes; rows are stored \
                     bottom-to-top, so the top {incomplete} of the {height} rows of the picture \
                     are incomplete"
                ),
            });
        }
        pixels.extend(row.chunks_exact(header.channels * 4).map(|sample| {
            let r = decode(&sample[0..4]);
            match header.channels {
                3 => [r, decode(&sample[4..8]), decode(&sample[8..12]), 1.0],
                _ => [r, r, r, 1.0],
            }
        }));
    }
    // File row 0 is the bottom of the picture: swap rows end for end so that
    // pixels[0..width] is the top row.
    for i in 0..height / 2 {
        let (upper, lower) = pixels.split_at_mut((height - 1 - i) * width);
        upper[i * width..(i + 1) * width].swap_with_slice(&mut lower[..width]);
    }
    let extra = io::copy(&mut reader, &mut io::sink()).map_err(read_error)?;
    if extra > 0 {
        return Err(ImageError::TrailingData {
            path: path.to_path_buf(),
            format: FORMAT,
            extra_bytes: extra,
        });
    }
    Ok(HdrImage {
        width: header.width,
        height: header.height,
        pixels,
    })
}

fn read_header(path: &Path, reader: &mut impl BufRead) -> Result<Header, ImageError> {
    let mut token = |field: &'static str| next_token(path, reader, field);
    let channels = match token("magic")?.as_str() {
        "PF" => 3,
        "Pf" => 1,
        other => {
            let problem = format!("`{other}` is neither `PF` (RGB) nor `Pf` (grey)");
            return Err(ImageError::bad_header(path, FORMAT, "magic", problem));
        }
    };
    let width = parse_dimension(path, "width", &token("width")?)?;
    let height = parse_dimension(path, "height", &token("height")?)?;
    let scale_text = token("scale")?;
    let scale = match scale_text.parse::<f32>() {
        Ok(s) if s.is_finite() && s != 0.0 => s,
        _ => {
            let problem = format!(
                "`{scale_text}` is not a non-zero number (its sign gives the byte order: \
                 negative = little-endian)"
            );
            return Err(ImageError::bad_header(path, FORMAT, "scale", problem));
        }
    };
    Ok(Header {
        width,
        height,
        channels,
        little_endian: scale < 0.0,
    })
}

fn parse_dimension(path: &Path, field: &'static str, text: &str) -> Result<u32, ImageError> {
    match text.parse::<u32>() {
        Ok(n) if n > 0 => Ok(n),
        _ => {
            let problem = format!("`{text}` is not a whole number from 1 to {}", u32::MAX);
            Err(ImageError::bad_header(path, FORMAT, field, problem))
        }
    }
}

/// Skips whitespace, then reads one header token and the single whitespace
/// byte (or the end of the file) that ends it; a CR is refused (CR LF line
/// endings).
fn next_token(
    path: &Path,
    reader: &mut impl BufRead,
    field: &'static str,
) -> Result<String, ImageError> {
    let mut token = Vec::new();
    loop {
        let byte = match reader.fill_buf() {
            Ok([]) => None,
            Ok(buf) => Some(buf[0]),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(ImageError::io(path, "read", e)),
        };
        match byte {
            None if token.is_empty() => {
                return Err(ImageError::Truncated {
                    path: path.to_path_buf(),
                    format: FORMAT,
                    missing: format!("the header ends before the `{field}` field"),
                });
            }
            None => break,
            // A CR can only come from CR LF line endings: after the scale,
            // its LF would be read as the first byte of pixel data.
            Some(b'\r') => return Err(super::crlf_error(path, FORMAT)),
            Some(b) => {
                reader.consume(1);
                match (b.is_ascii_whitespace(), token.is_empty()) {
                    (true, true) => continue,
                    (true, false) => break,
                    (false, _) => token.push(b),
                }
            }
        }
        if token.len() > MAX_TOKEN {
            let problem = format!("longer than {MAX_TOKEN} bytes");
            return Err(ImageError::bad_header(path, FORMAT, field, problem));
        }
    }
    Ok(String::from_utf8_lossy(&token).into_owned())
}

/// Writes a render target as little-endian PFM: one-channel formats (R16F,
/// R32F) as grey (`Pf`), the others as RGB (`PF`; PFM has no alpha, so alpha
/// is dropped, and a two-channel format's B is the 1 it reads back as).
pub fn write_pfm(path: &Path, target: &RenderTarget) -> Result<(), ImageError> {
    let expected = target.width as u64 * target.height as u64;
    if target.texels.len() as u64 != expected {
        return Err(ImageError::DataLength {
            path: path.to_path_buf(),
            what: "render target",
            expected,
            found: target.texels.len() as u64,
        });
    }
    let (magic, channels) = match target.format.channels() {
        1 => ("Pf", 1),
        _ => ("PF", 3),
    };
    write_atomically(path, FORMAT, |w| {
        write!(w, "{magic}\n{} {}\n-1\n", target.width, target.height)?;
        let width = target.width as usize;
        if width > 0 {
            for row in target.texels.chunks_exact(width).rev() {
                for texel in row {
                    for sample in &texel[..channels] {
                        w.write_all(&sample.to_le_bytes())?;
                    }
                }
            }
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::image::load;
    use crate::core::image::TargetFormat;
    use std::path::PathBuf;

    /// A PFM file from its header text and samples, rows given in FILE order
    /// (bottom row first).
    fn pfm_bytes(header: &str, samples: &[f32], little_endian: bool) -> Vec<u8> {
        let mut bytes = header.as_bytes().to_vec();
        for s in samples {
            match little_endian {
                true => bytes.extend(s.to_le_bytes()),
                false => bytes.extend(s.to_be_bytes()),
            }
        }
        bytes
    }

    fn load_bytes(bytes: &[u8]) -> (tempfile::TempDir, PathBuf, Result<HdrImage, ImageError>) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("test.pfm");
        std::fs::write(&path, bytes).unwrap();
        let result = load(&path, &ImageLimits::default());
        (dir, path, result)
    }

    /// A 2x3 grey image whose file stores the bottom row (1, 2) first and
    /// the top row (5, 6) last.
    fn two_by_three(little_endian: bool) -> Vec<u8> {
        let scale = if little_endian { "-1.0" } else { "1.0" };
        let header = format!("Pf\n2 3\n{scale}\n");
        pfm_bytes(&header, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0], little_endian)
    }

    fn grey(v: f32) -> [f32; 4] {
        [v, v, v, 1.0]
    }

    #[test]
    fn rows_are_flipped_so_row_zero_is_the_top() {
        for little_endian in [true, false] {
            let (_dir, _, image) = load_bytes(&two_by_three(little_endian));
            let image = image.unwrap();
            assert_eq!((image.width, image.height), (2, 3));
            let expected: Vec<[f32; 4]> = [5.0, 6.0, 3.0, 4.0, 1.0, 2.0].map(grey).to_vec();
            assert_eq!(image.pixels, expected, "little_endian = {little_endian}");
        }
    }

    #[test]
    fn rgb_samples_keep_their_order_and_alpha_is_one() {
        let bytes = pfm_bytes("PF\n1 1\n-1\n", &[0.5, -2.0, f32::INFINITY], true);
        let (_dir, _, image) = load_bytes(&bytes);
        assert_eq!(image.unwrap().pixels, vec![[0.5, -2.0, f32::INFINITY, 1.0]]);
    }

    #[test]
    fn byte_order_comes_from_the_sign_of_the_scale() {
        // The little-endian file with a positive scale: the same bytes now
        // read as big-endian numbers.
        let mut bytes = two_by_three(true);
        let big_endian_header = b"Pf\n2 3\n+1.0\n";
        bytes[..big_endian_header.len()].copy_from_slice(big_endian_header);
        let (_dir, _, image) = load_bytes(&bytes);
        let bottom_left = image.unwrap().pixel(0, 2)[0];
        assert_eq!(bottom_left, f32::from_be_bytes(1f32.to_le_bytes()));
    }

    #[test]
    fn truncated_data_names_what_is_missing() {
        let mut bytes = two_by_three(true);
        bytes.truncate(bytes.len() - 6);
        let (_dir, path, image) = load_bytes(&bytes);
        let err = image.unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, ImageError::Truncated { .. }), "{text}");
        assert!(text.contains(&path.display().to_string()), "{text}");
        assert!(
            text.contains("18 of 24 bytes") && text.contains("top 1 of the 3"),
            "{text}"
        );
    }

    #[test]
    fn truncated_header_is_an_error() {
        for cut in [
            "",
            "P",
            "Pf",
            "Pf\n2",
            "Pf\n2 3",
            "Pf\n2 3\n-1",
            "Pf\n2 3\n-1\n",
        ] {
            let (_dir, _, image) = load_bytes(cut.as_bytes());
            let err = image.unwrap_err();
            let expected = match cut {
                "" | "P" => matches!(err, ImageError::UnknownFormat { .. }),
                _ => matches!(err, ImageError::Truncated { .. }),
            };
            assert!(expected, "{cut:?}: {err}");
        }
    }

    #[test]
    fn trailing_bytes_are_an_error() {
        let mut bytes = two_by_three(true);
        bytes.extend([0; 3]);
        let (_dir, _, image) = load_bytes(&bytes);
        let err = image.unwrap_err();
        assert!(
            matches!(err, ImageError::TrailingData { extra_bytes: 3, .. }),
            "{err}"
        );
    }

    #[test]
    fn bad_header_fields_are_named() {
        let cases = [
            ("PFx\n2 3\n-1\n", "magic"),
            ("PF\n0 3\n-1\n", "width"),
            ("PF\n2 -3\n-1\n", "height"),
            ("PF\n2 3\n0\n", "scale"),
            ("PF\n2 3\nnan\n", "scale"),
            ("PF\n99999999999 3\n-1\n", "width"),
        ];
        for (header, field) in cases {
            let (_dir, _, image) = load_bytes(header.as_bytes());
            match image.unwrap_err() {
                ImageError::BadHeader { field: f, .. } => assert_eq!(f, field, "{header:?}"),
                other => panic!("{header:?}: {other}"),
            }
        }
    }

    #[test]
    fn absurd_size_is_refused_before_reading_pixels() {
        let (_dir, _, image) = load_bytes(b"PF\n100000 100000\n-1\n");
        let err = image.unwrap_err();
        assert!(
            matches!(
                err,
                ImageError::TooLarge {
                    width: 100000,
                    height: 100000,
                    ..
                }
            ),
            "{err}"
        );
        assert!(err.to_string().contains("--max-pixels"), "{err}");
    }

    #[test]
    fn written_targets_read_back() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.pfm");
        let mut target = RenderTarget::new(2, 3, TargetFormat::Rgba16F);
        target.store(1, 0, [1.0, 2.0, 3.0, 0.5]);
        target.store(0, 2, [-4.0, 0.25, 65504.0, 1.0]);
        write_pfm(&path, &target).unwrap();
        let image = load(&path, &ImageLimits::default()).unwrap();
        assert_eq!((image.width, image.height), (2, 3));
        let rgb1 = |t: [f32; 4]| [t[0], t[1], t[2], 1.0];
        assert_eq!(
            image.pixels,
            target.texels.iter().map(|&t| rgb1(t)).collect::<Vec<_>>()
        );

        let mut target = RenderTarget::new(3, 2, TargetFormat::R32F);
        target.store(2, 0, [0.1, 0.0, 0.0, 0.0]);
        write_pfm(&path, &target).unwrap();
        let image = load(&path, &ImageLimits::default()).unwrap();
        assert_eq!(image.pixel(2, 0), grey(0.1));
        assert_eq!(image.pixel(0, 1), grey(0.0));
    }
}
