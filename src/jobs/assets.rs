//! The bundled HDR images (`assets/hdr/`), compiled into the binary: `ps30
//! verify` and `ps30 study` read them from here, so an installed binary gives
//! the same results wherever it runs, with no source tree beside it.
//!
//! Commands that take an image path (`luminance`, `tonemap`, `run`, …) still
//! read the file the user names; these copies are the same bytes as the files
//! in `assets/hdr/` of the source tree the binary was built from.
//!
//! Two images are stored smaller than their files, and rebuilt the first
//! time they are asked for: `sunset.pfm` (6.3 MB of float32) as
//! `sunset.pfm.planes.deflate`, its pixel bytes regrouped into four planes
//! (byte 0 of every float, then byte 1, …), planes 1–3 stored as the
//! difference from the same byte three floats back (the previous pixel's
//! same channel), and deflated (2.0 MB), and `forest.hdr` (1.9 MB of
//! run-length RGBE) as `forest.hdr.planes.deflate` (1.4 MB): the file's run
//! and literal counts in order, then its pixels as planes (G; R − G and B − G,
//! each as the difference from the pixel before; E), deflated, from which the
//! file's scanlines are written again packet for packet. A test holds the
//! rebuilt bytes equal to the files'.

use crate::core::image::{self, HdrImage, ImageError, ImageLimits};
use std::path::Path;
use std::sync::OnceLock;

/// The folder of the bundled images in the source tree; images are named
/// `assets/hdr/NAME` in output, as in the repository.
pub const DIR: &str = "assets/hdr";

/// How a bundled image's bytes are compiled in.
enum Stored {
    /// The file's bytes as they are.
    Plain(&'static [u8]),
    /// A PFM: its header, then its pixel bytes as four byte planes (planes
    /// 1–3 as differences from three bytes back), deflated.
    Planes(&'static [u8], &'static [u8]),
    /// A Radiance RGBE file of run-length-encoded scanlines, `[width,
    /// height]` pixels: its header, then, deflated, the count byte of every
    /// packet in file order and the pixels as four planes (`rle_scanlines`).
    Rgbe(&'static [u8], [usize; 2], &'static [u8]),
}

/// Each bundled image's file name and how its bytes are stored (made by
/// `assets/hdr/README.md`'s commands).
const FILES: [(&str, Stored); 7] = [
    (
        "city.exr",
        Stored::Plain(include_bytes!("../../assets/hdr/city.exr")),
    ),
    (
        "courtyard.exr",
        Stored::Plain(include_bytes!("../../assets/hdr/courtyard.exr")),
    ),
    (
        "courtyard_1280x1024.exr",
        Stored::Plain(include_bytes!("../../assets/hdr/courtyard_1280x1024.exr")),
    ),
    (
        "forest.exr",
        Stored::Plain(include_bytes!("../../assets/hdr/forest.exr")),
    ),
    (
        "forest.hdr",
        Stored::Rgbe(
            b"#?RADIANCE\n# PFStools writer to Radiance RGBE format\nFORMAT=32-bit_rle_rgbe\n\n-Y 512 +X 1024\n",
            [1024, 512],
            include_bytes!("../../assets/hdr/forest.hdr.planes.deflate"),
        ),
    ),
    (
        "sunset.exr",
        Stored::Plain(include_bytes!("../../assets/hdr/sunset.exr")),
    ),
    (
        "sunset.pfm",
        Stored::Planes(
            b"PF\n1024 512\n-1\n",
            include_bytes!("../../assets/hdr/sunset.pfm.planes.deflate"),
        ),
    ),
];

/// The bytes of the `i`th bundled image, rebuilt once where they are
/// stored deflated.
fn file_bytes(i: usize) -> &'static [u8] {
    static REBUILT: [OnceLock<Vec<u8>>; 7] = [const { OnceLock::new() }; 7];
    // The stored bytes are compiled in and checked by a test: they inflate.
    let inflate = |d: &[u8]| {
        miniz_oxide::inflate::decompress_to_vec(d).expect("a compiled-in image inflates")
    };
    match FILES[i].1 {
        Stored::Plain(b) => b,
        Stored::Planes(header, d) => REBUILT[i].get_or_init(|| {
            let mut planes = inflate(d);
            let n = planes.len() / 4;
            // Planes 1–3 hold each byte minus the same byte of the previous
            // pixel's same channel (3 floats back): undo it in order.
            for plane in planes[n..].chunks_mut(n) {
                for k in 3..plane.len() {
                    plane[k] = plane[k].wrapping_add(plane[k - 3]);
                }
            }
            let mut out = Vec::with_capacity(header.len() + planes.len());
            out.extend_from_slice(header);
            out.extend((0..planes.len()).map(|k| planes[(k % 4) * n + k / 4]));
            out
        }),
        Stored::Rgbe(header, size, d) => REBUILT[i].get_or_init(|| {
            let mut out = header.to_vec();
            rle_scanlines(&inflate(d), size, &mut out);
            out
        }),
    }
}

/// Writes the run-length-encoded scanlines of a `Stored::Rgbe` image after
/// its header: `stored` is the packets' count bytes, then the pixels'
/// planes (G; R − G and B − G as differences from the pixel before; E).
/// Each scanline is its 4-byte start (2, 2, width), then its R, G, B and E
/// bytes, each as packets: a count over 128 repeats one byte `count − 128`
/// times, a count up to 128 is followed by that many bytes.
fn rle_scanlines(stored: &[u8], [width, height]: [usize; 2], out: &mut Vec<u8>) {
    // The four planes are the last bytes; the counts come before them.
    let pixels = width * height;
    let (counts, planes) = stored.split_at(stored.len() - 4 * pixels);
    let g = &planes[..pixels];
    // A running sum undoes the differences from the pixel before; G is
    // added back after it.
    let from_g = |plane: &[u8]| -> Vec<u8> {
        let mut sum = 0u8;
        let undo = |(d, g): (&u8, &u8)| {
            sum = sum.wrapping_add(*d);
            sum.wrapping_add(*g)
        };
        plane.iter().zip(g).map(undo).collect()
    };
    let r = from_g(&planes[pixels..2 * pixels]);
    let b = from_g(&planes[2 * pixels..3 * pixels]);
    let channels = [&r[..], g, &b[..], &planes[3 * pixels..]];
    // At most: each scanline's start, a count per packet, every pixel byte.
    out.reserve(4 * height + counts.len() + 4 * pixels);
    let mut counts = counts.iter().copied();
    for y in 0..height {
        out.extend_from_slice(&[2, 2, (width >> 8) as u8, width as u8]);
        for channel in channels {
            let row = &channel[y * width..(y + 1) * width];
            let mut x = 0;
            while x < width {
                let count = usize::from(counts.next().expect("a count per packet"));
                out.push(count as u8);
                if count > 128 {
                    out.push(row[x]);
                    x += count - 128;
                } else {
                    out.extend_from_slice(&row[x..x + count]);
                    x += count;
                }
            }
        }
    }
}

/// The bundled images' file names, in the order reports show them.
pub const IMAGES: [&str; 7] = {
    let mut names = [""; 7];
    let mut i = 0;
    while i < FILES.len() {
        names[i] = FILES[i].0;
        i += 1;
    }
    names
};

/// The bytes of the bundled image `name` (`forest.exr` or
/// `assets/hdr/forest.exr`), or `None` when no bundled image has that name.
pub fn bytes(name: &str) -> Option<&'static [u8]> {
    let file = name
        .strip_prefix(DIR)
        .map_or(name, |n| n.trim_start_matches('/'));
    FILES.iter().position(|(n, _)| *n == file).map(file_bytes)
}

/// The bundled image `name` (`forest.exr` or `assets/hdr/forest.exr`),
/// decoded; an unknown name is an error that lists the bundled ones.
pub fn load(name: &str) -> Result<HdrImage, String> {
    let Some(b) = bytes(name) else {
        return Err(format!(
            "{name}: no bundled image has this name (bundled: {})",
            IMAGES.join(", ")
        ));
    };
    let shown = Path::new(DIR).join(Path::new(name).file_name().unwrap_or_default());
    image::load_bytes(&shown, b, &ImageLimits::default()).map_err(|e: ImageError| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The compiled-in copies are the files of the source tree.
    #[test]
    fn the_copies_are_the_files() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(DIR);
        for name in IMAGES {
            let on_disk = std::fs::read(root.join(name)).unwrap();
            assert!(bytes(name) == Some(&on_disk[..]), "{name}");
            assert!(bytes(&format!("{DIR}/{name}")).is_some(), "{name}");
        }
        assert_eq!(bytes("nope.exr"), None);
        assert!(load("nope.exr").unwrap_err().contains("city.exr"));
        let img = load("assets/hdr/city.exr").unwrap();
        assert!(img.width > 0 && img.height > 0);
    }
}
