//! Atomic file output shared by every writer (images, reports, generated
//! shaders): a reader of the destination sees either the old file or the
//! complete new one, never a partial write, and a failed write leaves nothing
//! behind.

use std::error::Error;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// An error from a foreign encoder (the `exr` or `image` crate).
pub type ForeignError = Box<dyn Error + Send + Sync>;

/// Why an atomic write failed.
#[derive(Debug)]
pub enum Failure {
    /// The file system refused `action` ("write", "rename …", ...).
    Io {
        action: &'static str,
        source: io::Error,
    },
    /// The encoder failed.
    Encode(ForeignError),
}

impl From<Failure> for io::Error {
    fn from(f: Failure) -> io::Error {
        match f {
            Failure::Io { source, .. } => source,
            Failure::Encode(e) => io::Error::other(e),
        }
    }
}

/// Writes `path` by running `encode` on a temporary file in the same
/// directory, then renaming it over `path`. If anything fails, the temporary
/// file is removed and `path` is untouched.
pub fn write_atomically(
    path: &Path,
    encode: impl FnOnce(&mut BufWriter<File>) -> Result<(), ForeignError>,
) -> Result<(), Failure> {
    let io = |action| move |source| Failure::Io { action, source };
    let (file, temp) = create_temporary(path)?;
    let mut writer = BufWriter::new(file);
    encode(&mut writer).map_err(Failure::Encode)?;
    let file = writer
        .into_inner()
        .map_err(|e| io("write")(e.into_error()))?;
    file.sync_all().map_err(io("write"))?;
    temp.rename_to(path)
        .map_err(io("rename the temporary file to"))
}

/// Writes bytes atomically, creating the directory first if it is missing
/// (the behaviour of report and generated-shader output).
pub fn write_bytes(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    fs::create_dir_all(dir)?;
    write_atomically(path, |w| Ok(w.write_all(bytes)?)).map_err(io::Error::from)
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
fn create_temporary(path: &Path) -> Result<(File, Temporary), Failure> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().ok_or_else(|| {
        let source = io::Error::new(io::ErrorKind::InvalidInput, "the path has no file name");
        Failure::Io {
            action: "write",
            source,
        }
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
            Err(source) => {
                return Err(Failure::Io {
                    action: "create a temporary file for",
                    source,
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let err = write_atomically(&path, |w| {
            w.write_all(&[1u8; 100_000])?;
            Err("encoder gave up".into())
        })
        .unwrap_err();
        assert!(matches!(err, Failure::Encode(_)), "{err:?}");
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn failed_encode_keeps_the_old_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        fs::write(&path, b"old").unwrap();
        write_atomically(&path, |_| Err("no".into())).unwrap_err();
        assert_eq!(fs::read(&path).unwrap(), b"old");
        assert_eq!(names_in(dir.path()), vec!["out.bin".to_string()]);
    }

    #[test]
    fn success_replaces_the_file_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        fs::write(&path, b"old").unwrap();
        write_atomically(&path, |w| Ok(w.write_all(b"new")?)).unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new");
        assert_eq!(names_in(dir.path()), vec!["out.bin".to_string()]);
    }

    #[test]
    fn missing_directory_is_an_io_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/dir/out.bin");
        let err = write_atomically(&path, |_| Ok(())).unwrap_err();
        assert!(matches!(err, Failure::Io { .. }), "{err:?}");
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }
}
