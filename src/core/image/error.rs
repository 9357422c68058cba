//! The one error type of image input and output, so that every failure names
//! the file it happened to and what exactly was wrong with it.

use std::error::Error;
use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

/// An error from a decoder or encoder that ps30 does not own (the `exr` and
/// `image` crates), kept as the error's source.
pub use crate::core::output::ForeignError;

/// Everything that can go wrong while reading or writing an image file. The
/// fields of each variant are what its message names (see its `Display`).
#[derive(Debug)]
#[allow(missing_docs)]
pub enum ImageError {
    /// The file system refused `action` ("open", "read", "rename", ...).
    Io {
        path: PathBuf,
        action: &'static str,
        source: io::Error,
    },
    /// The output path breaks a rule of [`crate::core::output`]; `why`
    /// names the path.
    Refused { path: PathBuf, why: String },
    /// The file starts with none of the magic numbers ps30 reads.
    UnknownFormat { path: PathBuf, first_bytes: Vec<u8> },
    /// The header promises more pixels than [`super::ImageLimits`] allows.
    TooLarge {
        path: PathBuf,
        width: u64,
        height: u64,
        limit: u64,
    },
    /// A header field is missing, malformed, or holds a value ps30 cannot use.
    BadHeader {
        path: PathBuf,
        format: &'static str,
        field: String,
        problem: String,
    },
    /// The file ends before the data its header promises.
    Truncated {
        path: PathBuf,
        format: &'static str,
        missing: String,
    },
    /// The file goes on after the last pixel its header promises.
    TrailingData {
        path: PathBuf,
        format: &'static str,
        extra_bytes: u64,
    },
    /// The `exr` or `image` crate rejected the file.
    Decode {
        path: PathBuf,
        format: &'static str,
        source: ForeignError,
    },
    /// The `exr` or `image` crate failed to encode the data.
    Encode {
        path: PathBuf,
        format: &'static str,
        source: ForeignError,
    },
    /// ps30 cannot write this file: its extension names no format ps30
    /// writes, or the format cannot hold the values.
    Unwritable { path: PathBuf, problem: String },
    /// A buffer handed to a writer does not hold `width * height` pixels.
    DataLength {
        path: PathBuf,
        what: &'static str,
        expected: u64,
        found: u64,
    },
}

impl ImageError {
    pub(crate) fn io(path: &Path, action: &'static str, source: io::Error) -> ImageError {
        ImageError::Io {
            path: path.to_path_buf(),
            action,
            source,
        }
    }

    pub(crate) fn bad_header(
        path: &Path,
        format: &'static str,
        field: impl Into<String>,
        problem: impl Into<String>,
    ) -> ImageError {
        ImageError::BadHeader {
            path: path.to_path_buf(),
            format,
            field: field.into(),
            problem: problem.into(),
        }
    }

    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            ImageError::Io { path, .. }
            | ImageError::Refused { path, .. }
            | ImageError::UnknownFormat { path, .. }
            | ImageError::TooLarge { path, .. }
            | ImageError::BadHeader { path, .. }
            | ImageError::Truncated { path, .. }
            | ImageError::TrailingData { path, .. }
            | ImageError::Decode { path, .. }
            | ImageError::Encode { path, .. }
            | ImageError::Unwritable { path, .. }
            | ImageError::DataLength { path, .. } => path,
        }
    }
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path = self.path().display();
        match self {
            ImageError::Io { action, source, .. } => {
                write!(f, "{path}: cannot {action}: {source}")
            }
            ImageError::Refused { why, .. } => f.write_str(why),
            ImageError::UnknownFormat { first_bytes, .. } => write!(
                f,
                "{path}: not an OpenEXR, Radiance HDR or PFM file (first bytes {first_bytes:02x?}; \
                 expected 76 2f 31 01, \"#?\" or \"PF\"/\"Pf\")"
            ),
            ImageError::TooLarge {
                width,
                height,
                limit,
                ..
            } => write!(
                f,
                "{path}: image is {width}x{height} = {} pixels, more than the limit of {limit} \
                 pixels; raise it with --max-pixels (ImageLimits::max_pixels) if this is intended",
                u128::from(*width) * u128::from(*height)
            ),
            ImageError::BadHeader {
                format,
                field,
                problem,
                ..
            } => write!(f, "{path}: bad {format} header field `{field}`: {problem}"),
            ImageError::Truncated {
                format, missing, ..
            } => write!(f, "{path}: truncated {format} file: {missing}"),
            ImageError::TrailingData {
                format,
                extra_bytes,
                ..
            } => write!(
                f,
                "{path}: {extra_bytes} unexpected bytes after the last pixel of the {format} file"
            ),
            ImageError::Decode { format, source, .. } => {
                write!(f, "{path}: cannot decode {format} file: {source}")
            }
            ImageError::Encode { format, source, .. } => {
                write!(f, "{path}: cannot encode {format} file: {source}")
            }
            ImageError::Unwritable { problem, .. } => write!(f, "{path}: {problem}"),
            ImageError::DataLength {
                what,
                expected,
                found,
                ..
            } => write!(
                f,
                "{path}: {what} holds {found} values, the image size needs {expected}"
            ),
        }
    }
}

impl Error for ImageError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            ImageError::Io { source, .. } => Some(source),
            ImageError::Decode { source, .. } | ImageError::Encode { source, .. } => {
                Some(source.as_ref())
            }
            _ => None,
        }
    }
}
