//! Floating-point RGB images written band by band, top row first, so that a
//! job that renders an image in bands of rows (tone mapping) never holds its
//! whole result: each band goes to the file as it is made.
//!
//! The bytes are those of the whole-image writers ([`super::write_rgb_float`])
//! for the same pixels, whatever the bands: PFM stores its rows bottom row
//! first, so each band is written at its place in the file (the size of
//! every row is fixed); Radiance RGBE encodes each scan line on its own, so
//! the bands' lines follow one header; OpenEXR's blocks of scan lines are
//! compressed and written as they fill, on a thread of their own. The file
//! is staged and renamed over
//! the destination only by [`RgbBands::finish`] once every row was written
//! ([`crate::core::output::Staged`]); dropped before that, nothing is left.

use super::{ImageError, OutputFormat};
use crate::core::output::{Failure, Staged};
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// An RGB float image being written band by band (see the module docs).
pub struct RgbBands {
    path: PathBuf,
    format: OutputFormat,
    staged: Staged,
    width: u32,
    height: u32,
    /// Rows written so far (the next band starts here).
    rows: u32,
    /// Radiance: values RGBE cannot hold, counted over every band.
    unwritable: u64,
    /// The header's length in bytes (PFM: where the bottom row starts).
    header: u64,
    /// OpenEXR: the thread that compresses and writes the blocks.
    exr: Option<super::openexr::RgbScanLines>,
}

impl RgbBands {
    /// Starts writing `path` as the format its extension names: `.pfm`,
    /// `.hdr` or `.exr` (PNG is not a float format).
    pub fn create(path: &Path, width: u32, height: u32) -> Result<RgbBands, ImageError> {
        let format = OutputFormat::of(path)?;
        if format == OutputFormat::Png {
            return Err(ImageError::Unwritable {
                path: path.to_path_buf(),
                problem: "8-bit PNG holds no floating-point values".to_string(),
            });
        }
        let staged = Staged::create(path).map_err(|f| failure(path, format, f))?;
        let mut bands = RgbBands {
            path: path.to_path_buf(),
            format,
            staged,
            width,
            height,
            rows: 0,
            unwritable: 0,
            header: 0,
            exr: None,
        };
        let header = match format {
            OutputFormat::Pfm => format!("PF\n{width} {height}\n-1\n").into_bytes(),
            OutputFormat::Radiance => radiance_header(width, height),
            _ => {
                let file = bands.staged.writer().get_ref().try_clone();
                let file = file.map_err(|e| ImageError::io(path, "write", e))?;
                bands.exr = Some(super::openexr::RgbScanLines::start(file, width, height));
                Vec::new()
            }
        };
        bands.header = header.len() as u64;
        bands.put(&header)?;
        Ok(bands)
    }

    /// Writes the next whole rows, top row first (alpha is not written).
    pub fn write_rows(&mut self, pixels: &[[f32; 4]]) -> Result<(), ImageError> {
        let w = self.width as usize;
        let rows = pixels.len().checked_div(w).unwrap_or(0);
        if rows * w != pixels.len() || self.rows as usize + rows > self.height as usize {
            return Err(ImageError::DataLength {
                path: self.path.clone(),
                what: "a band of whole rows",
                expected: (self.height - self.rows) as u64 * w as u64,
                found: pixels.len() as u64,
            });
        }
        match self.format {
            OutputFormat::Pfm => self.pfm_rows(pixels, rows)?,
            OutputFormat::Radiance => self.radiance_rows(pixels, rows)?,
            _ => {
                let exr = self.exr.as_mut().map(|e| e.rows(pixels));
                exr.transpose().map_err(|e| self.encode_error(e))?;
            }
        }
        self.rows += rows as u32;
        Ok(())
    }

    /// Renames the complete file over the destination; refuses a file with
    /// rows missing, or RGBE values it could not hold (nothing is left then).
    pub fn finish(mut self) -> Result<(), ImageError> {
        if self.rows != self.height {
            return Err(ImageError::DataLength {
                path: self.path.clone(),
                what: "rows",
                expected: self.height as u64,
                found: self.rows as u64,
            });
        }
        if self.unwritable > 0 {
            return Err(super::save::radiance_refusal(
                &self.path,
                self.unwritable,
                self.width as u64 * self.height as u64 * 3,
            ));
        }
        if let Some(exr) = self.exr.take() {
            exr.finish().map_err(|e| self.encode_error(e))?;
        }
        let (path, format) = (self.path, self.format);
        self.staged.commit().map_err(|f| failure(&path, format, f))
    }

    /// PFM: the band's rows, bottom first, where they lie in the file.
    fn pfm_rows(&mut self, pixels: &[[f32; 4]], rows: usize) -> Result<(), ImageError> {
        let row_bytes = self.width as u64 * 12;
        let below = (self.height - self.rows) as u64 - rows as u64;
        let mut bytes = Vec::with_capacity(pixels.len() * 12);
        for row in pixels.chunks_exact(self.width.max(1) as usize).rev() {
            for p in row {
                for sample in &p[..3] {
                    bytes.extend_from_slice(&sample.to_le_bytes());
                }
            }
        }
        let at = self.header + below * row_bytes;
        let seek = self.staged.writer().seek(SeekFrom::Start(at));
        seek.map_err(|e| ImageError::io(&self.path, "write", e))?;
        self.put(&bytes)
    }

    /// Radiance: the band encoded as an image of its own, without its header.
    fn radiance_rows(&mut self, pixels: &[[f32; 4]], rows: usize) -> Result<(), ImageError> {
        self.unwritable += pixels
            .iter()
            .flat_map(|p| &p[..3])
            .filter(|v| !(v.is_finite() && **v >= 0.0))
            .count() as u64;
        if self.unwritable > 0 {
            // Refused by `finish`; the values are not encoded.
            return Ok(());
        }
        let rgb: Vec<image::Rgb<f32>> = pixels
            .iter()
            .map(|p| image::Rgb([p[0], p[1], p[2]]))
            .collect();
        let mut encoded = Vec::new();
        image::codecs::hdr::HdrEncoder::new(&mut encoded)
            .encode(&rgb, self.width as usize, rows)
            .map_err(|e| self.encode_error(Box::new(e)))?;
        let header = radiance_header(self.width, rows as u32).len();
        self.put(&encoded[header..])
    }

    fn encode_error(&self, source: crate::core::output::ForeignError) -> ImageError {
        ImageError::Encode {
            path: self.path.clone(),
            format: self.format.name(),
            source,
        }
    }

    fn put(&mut self, bytes: &[u8]) -> Result<(), ImageError> {
        let written = self.staged.writer().write_all(bytes);
        written.map_err(|e| ImageError::io(&self.path, "write", e))
    }
}

/// The header the Radiance encoder writes for a `width`×`height` image: its
/// text up to the line giving the size, found by encoding an empty image
/// and completed with that line.
fn radiance_header(width: u32, height: u32) -> Vec<u8> {
    let mut empty = Vec::new();
    // An empty image writes its header only; encoding it cannot fail.
    let _ = image::codecs::hdr::HdrEncoder::new(&mut empty).encode(&[], 0, 0);
    let size = "-Y 0 +X 0\n";
    let text = empty.len().saturating_sub(size.len());
    let mut header = empty[..text].to_vec();
    header.extend(format!("-Y {height} +X {width}\n").bytes());
    header
}

fn failure(path: &Path, format: OutputFormat, f: Failure) -> ImageError {
    super::image_failure(path, format.name(), f)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::image::write_rgb_float;

    /// Pixels with every kind of value RGBE and PFM see: small, large,
    /// zero, and mantissas that round differently.
    fn pixels(width: u32, height: u32) -> Vec<[f32; 4]> {
        (0..width * height)
            .map(|i| {
                let f = i as f32;
                [
                    f * 0.37 % 5.0,
                    (f * 1.7).sin().abs() * 300.0,
                    1.0 / (1.0 + f),
                    1.0,
                ]
            })
            .collect()
    }

    /// Written band by band, in bands of any height, the file is the whole-image
    /// writer's byte for byte.
    #[test]
    fn bands_give_the_whole_image_writers_bytes() {
        let dir = tempfile::tempdir().unwrap();
        // Width 3 is below RGBE's run-length encoding's smallest line (8), 40 within it.
        // 33 and 40 rows are several of OpenEXR's 16-line ZIP blocks, the last one short.
        for (w, h) in [(3, 5), (40, 7), (1, 1), (9, 33), (5, 40)] {
            let px = pixels(w, h);
            for ext in ["pfm", "hdr", "exr"] {
                let whole = dir.path().join(format!("whole.{ext}"));
                let rgb: Vec<[f32; 3]> = px.iter().map(|p| [p[0], p[1], p[2]]).collect();
                write_rgb_float(&whole, w, h, &rgb).unwrap();
                let expected = std::fs::read(&whole).unwrap();
                for band in 1..=h {
                    let path = dir.path().join(format!("bands.{ext}"));
                    let mut out = RgbBands::create(&path, w, h).unwrap();
                    for rows in px.chunks(band as usize * w as usize) {
                        out.write_rows(rows).unwrap();
                    }
                    out.finish().unwrap();
                    let got = std::fs::read(&path).unwrap();
                    assert!(got == expected, "{w}x{h} .{ext} in bands of {band}");
                }
            }
        }
    }

    #[test]
    fn missing_rows_and_negative_rgbe_leave_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.pfm");
        let mut out = RgbBands::create(&path, 2, 2).unwrap();
        out.write_rows(&pixels(2, 1)).unwrap();
        let e = out.finish().unwrap_err();
        assert!(
            matches!(
                e,
                ImageError::DataLength {
                    expected: 2,
                    found: 1,
                    ..
                }
            ),
            "{e}"
        );
        let path = dir.path().join("a.hdr");
        let mut out = RgbBands::create(&path, 2, 1).unwrap();
        out.write_rows(&[[-1.0, 0.0, 0.0, 1.0], [0.5; 4]]).unwrap();
        let e = out.finish().unwrap_err().to_string();
        assert!(e.contains("1 of the 6 values"), "{e}");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
        let e = RgbBands::create(&dir.path().join("a.png"), 1, 1)
            .err()
            .unwrap();
        assert!(e.to_string().contains("floating-point"), "{e}");
    }
}
