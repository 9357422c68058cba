//! The bundled HDR images (`assets/hdr/`), compiled into the binary: `ps30
//! verify` and `ps30 study` read them from here, so an installed binary gives
//! the same results wherever it runs, with no source tree beside it.
//!
//! Commands that take an image path (`luminance`, `tonemap`, `run`, …) still
//! read the file the user names; these copies are the same bytes as the files
//! in `assets/hdr/` of the source tree the binary was built from.
//!
//! One image is stored smaller than its file: `sunset.pfm` (6.3 MB of
//! float32) is compiled in as `sunset.pfm.planes.deflate`, its pixel bytes
//! regrouped into four planes (byte 0 of every float, then byte 1, …) and
//! deflated (2.5 MB), and rebuilt the first time it is asked for. A test
//! holds the rebuilt bytes equal to the file's.

use crate::core::image::{self, HdrImage, ImageError, ImageLimits};
use std::path::Path;

/// The folder of the bundled images in the source tree; images are named
/// `assets/hdr/NAME` in output, as in the repository.
pub const DIR: &str = "assets/hdr";

/// Each bundled image's file name and bytes (`sunset.pfm`'s are empty here:
/// [`sunset_pfm`] rebuilds them).
const FILES: [(&str, &[u8]); 7] = [
    ("city.exr", include_bytes!("../../assets/hdr/city.exr")),
    (
        "courtyard.exr",
        include_bytes!("../../assets/hdr/courtyard.exr"),
    ),
    (
        "courtyard_1280x1024.exr",
        include_bytes!("../../assets/hdr/courtyard_1280x1024.exr"),
    ),
    ("forest.exr", include_bytes!("../../assets/hdr/forest.exr")),
    ("forest.hdr", include_bytes!("../../assets/hdr/forest.hdr")),
    ("sunset.exr", include_bytes!("../../assets/hdr/sunset.exr")),
    ("sunset.pfm", &[]),
];

/// `sunset.pfm`'s header; its pixels follow as four deflated byte planes.
const SUNSET_PFM_HEADER: &[u8] = b"PF\n1024 512\n-1\n";

/// `sunset.pfm`'s pixel bytes as byte planes, deflated (see the module docs;
/// made by `assets/hdr/README.md`'s command).
const SUNSET_PFM_PLANES: &[u8] = include_bytes!("../../assets/hdr/sunset.pfm.planes.deflate");

/// The bytes of `sunset.pfm`, rebuilt once from its byte planes.
fn sunset_pfm() -> &'static [u8] {
    static BYTES: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    BYTES.get_or_init(|| {
        // The planes are compiled in and checked by a test: they inflate.
        let planes = miniz_oxide::inflate::decompress_to_vec(SUNSET_PFM_PLANES)
            .expect("the compiled-in planes of sunset.pfm inflate");
        let n = planes.len() / 4;
        let mut out = Vec::with_capacity(SUNSET_PFM_HEADER.len() + planes.len());
        out.extend_from_slice(SUNSET_PFM_HEADER);
        out.extend((0..planes.len()).map(|i| planes[(i % 4) * n + i / 4]));
        out
    })
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
    match file {
        "sunset.pfm" => Some(sunset_pfm()),
        _ => FILES.iter().find(|(n, _)| *n == file).map(|(_, b)| *b),
    }
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
