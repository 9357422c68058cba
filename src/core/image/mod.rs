//! HDR images in, render targets out.
//!
//! ps30 checks a GPU log-average-luminance computation against a CPU
//! reference on real HDR photographs, so it must read the formats such images
//! come in (OpenEXR, Radiance RGBE, PFM) into one in-memory form,
//! [`HdrImage`], and write what the emulated passes produce
//! ([`RenderTarget`]s as OpenEXR, PFM, Radiance or PNG, chosen by the
//! output's extension: [`OutputFormat`]; tone-mapped results as PNG).
//!
//! Reading never trusts a header: the claimed size is checked against
//! [`ImageLimits`] before any pixel memory is allocated, and every failure is
//! an [`ImageError`] naming the file and the problem. Writing is atomic: a
//! failed write leaves no partial file behind.

mod bands;
mod dds;
mod error;
mod layered;
mod mip;
mod openexr;
mod pfm;
mod png;
mod radiance;
mod save;
mod target;

pub use bands::RgbBands;
pub use dds::{is_dds, TextureFile};
pub use error::{ForeignError, ImageError};
pub use layered::{CubeMap, VolumeChain, VolumeLevel};
pub use mip::{chain_weights, full_chain_levels, side_taps, weight_bound, MipChain, OddSides};
pub use openexr::{encode_exr, write_exr};
pub use pfm::write_pfm;
pub use png::{encode_png_rgb8, write_png_rgb8};
pub use save::{write_radiance, write_rgb_float, write_target, OutputFormat, Written};
pub use target::{
    half_from_f64, unorm8, unorm8_value, Encoding, RenderTarget, TargetFormat, Texture,
};

use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Read, Seek};
use std::path::Path;

/// The luminance weights of the article (and of the tone-mapping shader):
/// `L = 0.27 R + 0.67 G + 0.06 B`.
pub const LUMINANCE_WEIGHTS: [f64; 3] = [0.27, 0.67, 0.06];

/// The luminance of a pixel, computed in f64 as
/// `0.27 R + 0.67 G + 0.06 B` (evaluated left to right).
pub fn luminance(pixel: [f32; 4]) -> f64 {
    let [r, g, b] = LUMINANCE_WEIGHTS;
    r * f64::from(pixel[0]) + g * f64::from(pixel[1]) + b * f64::from(pixel[2])
}

/// [`crate::core::output::write_atomically`] with the failure told as an
/// [`ImageError`] naming the file and its `format`.
fn write_atomically(
    path: &Path,
    format: &'static str,
    encode: impl FnOnce(&mut BufWriter<File>) -> Result<(), ForeignError>,
) -> Result<(), ImageError> {
    crate::core::output::write_atomically(path, encode).map_err(|f| image_failure(path, format, f))
}

/// A failed atomic write of `path` as an [`ImageError`] naming the file and
/// its `format`.
fn image_failure(path: &Path, format: &'static str, f: crate::core::output::Failure) -> ImageError {
    use crate::core::output::Failure;
    match f {
        Failure::Refused(why) => ImageError::Refused {
            path: path.to_path_buf(),
            why,
        },
        Failure::Io { action, source } => ImageError::io(path, action, source),
        Failure::Encode(source) => ImageError::Encode {
            path: path.to_path_buf(),
            format,
            source,
        },
    }
}

/// The error for a text header whose lines end in CR LF (a Windows line
/// ending): the PFM and Radiance layouts end each header line with LF alone,
/// and a CR would be read as part of a field or as pixel data.
fn crlf_error(path: &Path, format: &'static str) -> ImageError {
    ImageError::bad_header(
        path,
        format,
        "line endings",
        "the header lines end in CR LF; this format ends each header line with LF alone (convert the header, e.g. with dos2unix on the header lines, or re-export the file)",
    )
}

/// An RGBA image with f32 channels, as loaded from a file.
///
/// Pixels are row-major and row 0 is the TOP row of the picture, whatever
/// order the file stores its rows in. Alpha is 1 when the file has none;
/// single-channel (grey) files load as R = G = B. Values are kept exactly as
/// decoded: negative and non-finite values are not touched (see
/// [`HdrImage::stats`]).
#[derive(Clone, Debug, PartialEq)]
pub struct HdrImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels.
    pub pixels: Vec<[f32; 4]>,
}

/// Counts of pixels that need a policy decision in the reference.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct PixelStats {
    /// Pixels whose luminance (see [`luminance`]) is finite
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
            let l = luminance(pixel);
            if !l.is_finite() {
                stats.non_finite += 1;
            } else if l < 0.0 {
                stats.negative_luminance += 1;
            }
        }
        stats
    }
}

/// How large an image [`load`] accepts. A header can claim any size; this
/// limit is checked before pixel memory is allocated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageLimits {
    /// Largest accepted `width * height`.
    pub max_pixels: u64,
}

impl ImageLimits {
    /// Default of `max_pixels`: 4 Mpixel (2048×2048, 64 MiB as RGBA f32),
    /// three times the largest bundled image; a command on an image this
    /// large stays within a few hundred megabytes (see the README).
    pub const MAX_PIXELS: u64 = 1 << 22;
}

impl Default for ImageLimits {
    fn default() -> ImageLimits {
        ImageLimits {
            max_pixels: ImageLimits::MAX_PIXELS,
        }
    }
}

impl ImageLimits {
    /// Refuses empty images and images over the limit.
    fn check(
        &self,
        path: &Path,
        format: &'static str,
        width: u64,
        height: u64,
    ) -> Result<(), ImageError> {
        for (field, value) in [("width", width), ("height", height)] {
            if value == 0 {
                return Err(ImageError::bad_header(path, format, field, "is zero"));
            }
        }
        // u64 * u64 can overflow; u128 cannot.
        if u128::from(width) * u128::from(height) > u128::from(self.max_pixels) {
            return Err(ImageError::TooLarge {
                path: path.to_path_buf(),
                width,
                height,
                limit: self.max_pixels,
            });
        }
        Ok(())
    }
}

/// The file formats [`load`] reads, told apart by their first bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    OpenExr,
    Radiance,
    Pfm,
}

impl Format {
    fn detect(magic: &[u8]) -> Option<Format> {
        match magic {
            [0x76, 0x2f, 0x31, 0x01, ..] => Some(Format::OpenExr),
            [b'#', b'?', ..] => Some(Format::Radiance),
            [b'P', b'F' | b'f', ..] => Some(Format::Pfm),
            _ => None,
        }
    }
}

/// Reads an HDR image, choosing the decoder by the file's magic number (not
/// its extension): OpenEXR (`76 2f 31 01`), Radiance RGBE (`#?`) or PFM
/// (`PF` colour, `Pf` grey).
pub fn load(path: &Path, limits: &ImageLimits) -> Result<HdrImage, ImageError> {
    let file = File::open(path).map_err(|e| ImageError::io(path, "open", e))?;
    decode(path, BufReader::new(file), limits)
}

/// Reads a texture file: DDS (by its magic `DDS `: 2D, cube or volume, with
/// the levels it stores) or any image [`load`] reads (a 2D texture of one
/// level). The file is read whole under `max_bytes`; `limits` bounds the
/// texels of every level, face and slice together.
pub fn load_texture(
    path: &Path,
    limits: &ImageLimits,
    max_bytes: u64,
) -> Result<TextureFile, ImageError> {
    let file = File::open(path).map_err(|e| ImageError::io(path, "open", e))?;
    let mut bytes = Vec::new();
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| ImageError::io(path, "read", e))?;
    if bytes.len() as u64 > max_bytes {
        return Err(ImageError::bad_header(
            path,
            "texture",
            "file size",
            format!("is more than {max_bytes} bytes"),
        ));
    }
    if is_dds(&bytes) {
        return dds::read(path, &bytes, limits);
    }
    let img = load_bytes(path, &bytes, limits)?;
    MipChain::from_levels(vec![(img.width, img.height, img.pixels)])
        .map(TextureFile::Flat)
        .map_err(|e| ImageError::bad_header(path, "texture", "size", e))
}

/// Decodes an HDR image held in memory, as [`load`] reads a file; `name`
/// names it in errors.
pub fn load_bytes(name: &Path, bytes: &[u8], limits: &ImageLimits) -> Result<HdrImage, ImageError> {
    decode(name, std::io::Cursor::new(bytes), limits)
}

/// Reads `path` with [`load`] while `beside` runs on the image's width and
/// height, read from the header first (and checked against `limits`), on
/// the current rayon pool: work that needs only the size (planning the
/// luminance passes) takes no time of its own on two threads or more. On
/// one thread the image is decoded first, then `beside` runs, as one after
/// the other would. A header that does not read leaves the error to
/// [`load`], which meets it again.
pub fn load_beside<T: Send>(
    path: &Path,
    limits: &ImageLimits,
    beside: impl FnOnce(u32, u32) -> T + Send,
) -> Result<(HdrImage, T), ImageError> {
    match size(path, limits) {
        Ok((width, height)) => {
            let (image, t) = rayon::join(|| load(path, limits), || beside(width, height));
            Ok((image?, t))
        }
        Err(_) => {
            let image = load(path, limits)?;
            let t = beside(image.width, image.height);
            Ok((image, t))
        }
    }
}

/// The width and height an image file's header states, checked against
/// `limits`; no pixel is read.
pub fn size(path: &Path, limits: &ImageLimits) -> Result<(u32, u32), ImageError> {
    let file = File::open(path).map_err(|e| ImageError::io(path, "open", e))?;
    let mut reader = BufReader::new(file);
    match detect(path, &mut reader)? {
        Format::OpenExr => openexr::size(path, reader, limits),
        Format::Radiance => radiance::size(path, reader, limits),
        Format::Pfm => pfm::size(path, reader, limits),
    }
}

/// The format `reader`'s first bytes name; `reader` is left at the start.
fn detect(path: &Path, reader: &mut (impl BufRead + Seek)) -> Result<Format, ImageError> {
    let mut magic = Vec::with_capacity(4);
    reader
        .take(4)
        .read_to_end(&mut magic)
        .and_then(|_| reader.rewind())
        .map_err(|e| ImageError::io(path, "read", e))?;
    Format::detect(&magic).ok_or_else(|| ImageError::UnknownFormat {
        path: path.to_path_buf(),
        first_bytes: magic,
    })
}

/// Decodes from `reader` with the decoder its magic number names.
fn decode(
    path: &Path,
    mut reader: impl BufRead + Seek + Send,
    limits: &ImageLimits,
) -> Result<HdrImage, ImageError> {
    match detect(path, &mut reader)? {
        Format::OpenExr => openexr::read(path, reader, limits),
        Format::Radiance => radiance::read(path, reader, limits),
        Format::Pfm => pfm::read(path, reader, limits),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn bundled() -> Vec<PathBuf> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/hdr");
        ["courtyard.exr", "forest.hdr", "sunset.pfm"]
            .iter()
            .map(|name| dir.join(name))
            .collect()
    }

    /// The header's size is the decoded image's, and a limit the image
    /// exceeds refuses both alike.
    #[test]
    fn size_is_what_load_decodes() {
        for path in bundled() {
            let image = load(&path, &ImageLimits::default()).unwrap();
            let stated = size(&path, &ImageLimits::default()).unwrap();
            assert_eq!(stated, (image.width, image.height), "{}", path.display());
            let tight = ImageLimits {
                max_pixels: u64::from(image.width) * u64::from(image.height) - 1,
            };
            let refused = size(&path, &tight).unwrap_err().to_string();
            assert_eq!(refused, load(&path, &tight).unwrap_err().to_string());
        }
    }

    /// `beside` gets the image's size and runs once; the image is `load`'s,
    /// on one thread and on two.
    #[test]
    fn load_beside_hands_the_size_over_and_decodes_alike() {
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            for path in bundled() {
                let alone = load(&path, &ImageLimits::default()).unwrap();
                let runs = std::sync::atomic::AtomicU32::new(0);
                let (image, size) = pool
                    .install(|| {
                        load_beside(&path, &ImageLimits::default(), |w, h| {
                            runs.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            (w, h)
                        })
                    })
                    .unwrap();
                assert_eq!(size, (alone.width, alone.height));
                assert_eq!(runs.into_inner(), 1);
                let bits =
                    |p: &[[f32; 4]]| p.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
                assert!(
                    bits(&image.pixels) == bits(&alone.pixels),
                    "{}",
                    path.display()
                );
            }
        }
    }

    /// A file whose header does not read gives `load`'s error, and `beside`
    /// never runs on a size nobody read.
    #[test]
    fn load_beside_of_a_bad_header_is_loads_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("bad.pfm");
        std::fs::write(&path, b"PF\n12 x\n-1\n").unwrap();
        let alone = load(&path, &ImageLimits::default())
            .unwrap_err()
            .to_string();
        let beside = load_beside(&path, &ImageLimits::default(), |_, _| {
            panic!("beside ran without a size")
        });
        assert_eq!(beside.unwrap_err().to_string(), alone);
    }
}
