//! Atomic file output shared by every writer: a reader of the destination
//! sees either the old file or the complete new one, never a partial write,
//! and a failed write leaves nothing behind.

use super::{ForeignError, ImageError};
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Writes `path` by running `encode` on a temporary file in the same
/// directory, then renaming it over `path`. If anything fails, the temporary
/// file is removed and `path` is untouched. `format` names the file type in
/// errors from `encode`.
pub(crate) fn write_atomically(
    path: &Path,
    format: &'static str,
    encode: impl FnOnce(&mut BufWriter<File>) -> Result<(), ForeignError>,
) -> Result<(), ImageError> {
    let (file, temp) = create_temporary(path)?;
    let mut writer = BufWriter::new(file);
    encode(&mut writer).map_err(|source| ImageError::Encode {
        path: path.to_path_buf(),
        format,
        source,
    })?;
    let file = writer
        .into_inner()
        .map_err(|e| ImageError::io(path, "write", e.into_error()))?;
    file.sync_all()
        .map_err(|e| ImageError::io(path, "write", e))?;
    temp.rename_to(path)
        .map_err(|e| ImageError::io(path, "rename the temporary file to", e))
}

/// A temporary file that is deleted when dropped (on every error path),
/// unless it was renamed to its destination.
struct Temporary {
    path: PathBuf,
    renamed: bool,
}

impl Temporary {
    fn rename_to(mut self, destination: &Path) -> io::Result<()> {
        fs::rename(&self.path, destination)?;
        self.renamed = true;
        Ok(())
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = fs::remove_file(&self.path);
        }
    }
}

/// Creates `.NAME.PID.N.tmp` next to `path`, with a name no other writer in
/// this process or another one uses.
fn create_temporary(path: &Path) -> Result<(File, Temporary), ImageError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().ok_or_else(|| {
        let e = io::Error::new(io::ErrorKind::InvalidInput, "the path has no file name");
        ImageError::io(path, "write", e)
    })?;
    let dir = path.parent().unwrap_or(Path::new(""));
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".{}.{n}.tmp", std::process::id()));
        let temp = dir.join(temp_name);
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => {
                let temp = Temporary {
                    path: temp,
                    renamed: false,
                };
                return Ok((file, temp));
            }
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(ImageError::io(path, "create a temporary file for", e)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn names_in(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn failed_encode_leaves_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        let err = write_atomically(&path, "test", |w| {
            w.write_all(&[1u8; 100_000])?;
            Err("encoder gave up".into())
        })
        .unwrap_err();
        assert!(matches!(err, ImageError::Encode { .. }), "{err}");
        assert!(err.to_string().contains("out.bin"), "{err}");
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn failed_encode_keeps_the_old_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        fs::write(&path, b"old").unwrap();
        write_atomically(&path, "test", |_| Err("no".into())).unwrap_err();
        assert_eq!(fs::read(&path).unwrap(), b"old");
        assert_eq!(names_in(dir.path()), vec!["out.bin".to_string()]);
    }

    #[test]
    fn success_replaces_the_file_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        fs::write(&path, b"old").unwrap();
        write_atomically(&path, "test", |w| Ok(w.write_all(b"new")?)).unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new");
        assert_eq!(names_in(dir.path()), vec!["out.bin".to_string()]);
    }

    #[test]
    fn missing_directory_is_an_io_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/dir/out.bin");
        let err = write_atomically(&path, "test", |_| Ok(())).unwrap_err();
        assert!(matches!(err, ImageError::Io { .. }), "{err}");
        assert!(err.to_string().contains("no/such/dir/out.bin"), "{err}");
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }
}
