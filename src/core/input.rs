//! Every file ps30 reads as a whole — shaders, draw lists, wherever they are
//! named — read under one cap on its size, so that a large file, a device
//! such as `/dev/zero` or a pipe that never ends costs at most the cap plus
//! one byte of memory and stops with an error that names the file and the
//! flag that raises the cap. (Images are bounded by their pixel counts,
//! checked against the header before any pixel memory exists: `core/image`.)

use std::io::Read;
use std::path::Path;

/// The default cap: 1 MiB holds a listing of more than 100,000 lines, far
/// past the 32,768 slots of any ps_3_0 part, and a draw list of thousands
/// of steps.
pub const DEFAULT_MAX_INPUT_BYTES: u64 = 1 << 20;

/// Reads all of `reader` if it holds at most `max_bytes` bytes; reads one
/// byte past the cap to tell, never more. The error does not name the input
/// (callers put its name before it): "larger than the cap of N bytes for a
/// WHAT (raise it with --max-input-bytes)", or the system's reason.
pub fn read_capped(reader: impl Read, what: &str, max_bytes: u64) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    reader
        .take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > max_bytes {
        return Err(format!(
            "larger than the cap of {} bytes for a {what} (raise it with --max-input-bytes)",
            crate::core::numbers::thousands(max_bytes)
        ));
    }
    Ok(bytes)
}

/// [`read_capped`] on a file, the error naming it (`PATH: …`).
pub fn read_file(path: &Path, what: &str, max_bytes: u64) -> Result<Vec<u8>, String> {
    std::fs::File::open(path)
        .map_err(|e| e.to_string())
        .and_then(|f| read_capped(f, what, max_bytes))
        .map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reader_past_the_cap_is_refused_after_one_byte_more() {
        let endless = std::io::repeat(7);
        let e = read_capped(endless, "shader", 1000).unwrap_err();
        assert!(
            e.starts_with("larger than the cap of 1,000 bytes for a shader"),
            "{e}"
        );
        assert_eq!(
            read_capped(&[1u8, 2, 3][..], "shader", 3).unwrap(),
            vec![1, 2, 3]
        );
        assert!(read_capped(&[1u8, 2, 3, 4][..], "shader", 3).is_err());
    }
}
