//! Every file ps30 writes goes through here, under one set of rules, so
//! that no command replaces or removes anything the user did not ask for.
//!
//! The rules, checked before any work ([`check`], [`check_directory`]) and
//! again when writing:
//!
//! * an output names a file: `-o .`, `-o /` or `-o DIR/` are refused, and so
//!   is an existing directory;
//! * its directory must exist (a directory *output* — `unroll -o DIR`,
//!   `verify --reports DIR` — is created when missing, one level, its parent
//!   must exist);
//! * an existing output must be a regular file: FIFOs, devices and sockets
//!   are refused (nothing is written through them, nothing replaces them);
//! * a symbolic link is followed: the file it points to is replaced, the link
//!   stays; a link to nothing is refused;
//! * an output that is one of the command's inputs (the same file, by any
//!   path or link) is refused.
//!
//! Writing is atomic: the bytes go to a temporary `.NAME.PID.N.tmp` beside
//! the destination, which is renamed over it only when complete; a failure
//! removes the temporary file. [`Batch`] extends this to several files: all
//! are staged first and renamed only when every one was written, and a batch
//! dropped before [`Batch::commit`] removes its temporary files and the
//! directories it created. Temporary files still open when the process is
//! interrupted (SIGINT, SIGTERM, SIGHUP) are removed by
//! [`remove_temporaries`], which the binary calls from its signal handler; a
//! `kill -9` cannot be caught, and leaves at most those `.NAME.PID.N.tmp`
//! files, named after the process that left them.

use crate::core::bytecode::ctab::escape;
use std::error::Error;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// An error from a foreign encoder (the `exr` or `image` crate).
pub type ForeignError = Box<dyn Error + Send + Sync>;

/// Why an atomic write failed.
#[derive(Debug)]
pub enum Failure {
    /// The output path breaks one of the rules above.
    Refused(String),
    /// The file system refused `action` ("write", "rename …", ...).
    Io {
        /// What was being done ("write", "rename …").
        action: &'static str,
        /// What the file system said.
        source: io::Error,
    },
    /// The encoder failed.
    Encode(ForeignError),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Refused(why) => f.write_str(why),
            Failure::Io { action, source } => write!(f, "cannot {action} it: {source}"),
            Failure::Encode(e) => write!(f, "{e}"),
        }
    }
}

impl From<Failure> for io::Error {
    fn from(f: Failure) -> io::Error {
        match f {
            Failure::Refused(why) => io::Error::new(io::ErrorKind::InvalidInput, why),
            Failure::Io { source, .. } => source,
            Failure::Encode(e) => io::Error::other(e),
        }
    }
}

/// What kind of thing a non-regular file is, for messages.
fn kind(meta: &fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if meta.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

/// Where the bytes for `path` go: `path` itself, or the file its symbolic
/// link points to. Refuses what the rules refuse.
pub fn destination(path: &Path) -> Result<PathBuf, String> {
    let shown = path.display();
    if !matches!(path.components().next_back(), Some(Component::Normal(_)))
        || path.as_os_str().to_string_lossy().ends_with('/')
    {
        return Err(format!(
            "{shown}: names a directory, not a file; give the output a file name"
        ));
    }
    let real = match fs::symlink_metadata(path) {
        Ok(meta) if meta.file_type().is_symlink() => match fs::canonicalize(path) {
            Ok(target) => target,
            Err(_) => {
                let to = fs::read_link(path).unwrap_or_default();
                return Err(format!(
                    "{shown}: is a symbolic link to {}, which does not exist; ps30 does not create files through links",
                    to.display()
                ));
            }
        },
        _ => path.to_path_buf(),
    };
    match fs::metadata(&real) {
        Ok(meta) if meta.is_file() => {}
        Ok(meta) => {
            return Err(format!(
                "{shown}: is {}, not a regular file; ps30 writes only regular files",
                kind(&meta)
            ))
        }
        Err(_) => {}
    }
    let dir = parent(&real);
    if !dir.is_dir() {
        return Err(format!(
            "{shown}: the directory {} does not exist",
            dir.display()
        ));
    }
    Ok(real)
}

/// The directory a file path lies in (`.` for a bare name).
fn parent(path: &Path) -> &Path {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// Checks an output file before any work: the rules of [`destination`],
/// and not one of `inputs`.
pub fn check(path: &Path, inputs: &[&Path]) -> Result<(), String> {
    let real = destination(path)?;
    if let Some(input) = inputs.iter().find(|i| same_file(&real, i)) {
        return Err(format!(
            "{}: is also the input {}; write the output to another file",
            path.display(),
            input.display()
        ));
    }
    Ok(())
}

/// Whether two paths name the same existing file (through links too).
fn same_file(a: &Path, b: &Path) -> bool {
    match (fs::metadata(a), fs::metadata(b)) {
        #[cfg(unix)]
        (Ok(x), Ok(y)) => {
            use std::os::unix::fs::MetadataExt;
            x.dev() == y.dev() && x.ino() == y.ino()
        }
        #[cfg(not(unix))]
        (Ok(_), Ok(_)) => fs::canonicalize(a).ok() == fs::canonicalize(b).ok(),
        _ => false,
    }
}

/// Checks a directory output before any work: an existing directory (a link
/// to one is followed), or a missing one whose parent exists.
pub fn check_directory(dir: &Path) -> Result<(), String> {
    let shown = dir.display();
    match fs::metadata(dir) {
        Ok(meta) if meta.is_dir() => Ok(()),
        Ok(meta) => Err(format!(
            "{shown}: is {}, not a directory",
            if meta.is_file() {
                "a file"
            } else {
                kind(&meta)
            }
        )),
        Err(_) if fs::symlink_metadata(dir).is_ok() => Err(format!(
            "{shown}: is a symbolic link to nothing; ps30 does not create directories through links"
        )),
        Err(_) => {
            let up = parent(dir);
            if up.is_dir() {
                Ok(())
            } else {
                Err(format!(
                    "{shown}: cannot be created, the directory {} does not exist",
                    up.display()
                ))
            }
        }
    }
}

/// Writes `path` by running `encode` on a temporary file beside its
/// destination, then renaming it over the destination. If anything fails,
/// the temporary file is removed and the destination is untouched.
pub fn write_atomically(
    path: &Path,
    encode: impl FnOnce(&mut BufWriter<File>) -> Result<(), ForeignError>,
) -> Result<(), Failure> {
    let mut staged = Staged::create(path)?;
    encode(staged.writer()).map_err(Failure::Encode)?;
    staged.commit()
}

/// Writes bytes atomically (the rules of [`destination`] apply: the
/// directory must exist).
pub fn write_bytes(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomically(path, |w| Ok(w.write_all(bytes)?)).map_err(io::Error::from)
}

/// A file being written atomically a piece at a time, for an encoder that
/// is fed as its data is made (an image written band by band): the bytes go
/// to the temporary file, and [`Staged::commit`] renames it over the
/// destination. Dropped before that, it removes the temporary file and
/// leaves the destination untouched.
pub struct Staged {
    writer: BufWriter<File>,
    temp: Temporary,
    real: PathBuf,
}

impl Staged {
    /// Creates the temporary file for `path` (the rules of [`destination`]
    /// apply).
    pub fn create(path: &Path) -> Result<Staged, Failure> {
        Staged::at(destination(path).map_err(Failure::Refused)?)
    }

    /// The temporary file for `real`, a destination already resolved.
    fn at(real: PathBuf) -> Result<Staged, Failure> {
        let (file, temp) = create_temporary(&real)?;
        Ok(Staged {
            writer: BufWriter::new(file),
            temp,
            real,
        })
    }

    /// Where the bytes go (buffered; seeking flushes the buffer).
    pub fn writer(&mut self) -> &mut BufWriter<File> {
        &mut self.writer
    }

    /// Flushes and syncs the file, then renames it over the destination.
    pub fn commit(self) -> Result<(), Failure> {
        let (temp, real) = self.finish()?;
        temp.rename_to(&real).map_err(|source| Failure::Io {
            action: "rename the temporary file to",
            source,
        })
    }

    /// The complete temporary file, synced to disk, and its destination.
    fn finish(self) -> Result<(Temporary, PathBuf), Failure> {
        let io = |action| move |source| Failure::Io { action, source };
        let file = self
            .writer
            .into_inner()
            .map_err(|e| io("write")(e.into_error()))?;
        file.sync_all().map_err(io("write"))?;
        Ok((self.temp, self.real))
    }
}

/// A complete temporary file for `real`, synced to disk.
fn stage(
    real: &Path,
    encode: impl FnOnce(&mut BufWriter<File>) -> Result<(), ForeignError>,
) -> Result<Temporary, Failure> {
    let mut staged = Staged::at(real.to_path_buf())?;
    encode(staged.writer()).map_err(Failure::Encode)?;
    Ok(staged.finish()?.0)
}

/// Whether `name` may be a file name that ps30 derives from data a user
/// wrote (a draw-list target's name becomes `NAME.exr`): one plain path
/// component — not empty, not `.` or `..`, no `/` or `\\`, no control
/// characters, at most 200 bytes. Errors say which rule it breaks.
pub fn plain_name(name: &str) -> Result<(), String> {
    let why = if name.is_empty() {
        "it is empty"
    } else if name == "." || name == ".." {
        "it names a directory"
    } else if name.contains(['/', '\\']) {
        "it contains a path separator"
    } else if name.chars().any(char::is_control) {
        "it contains a control character"
    } else if name.len() > 200 {
        "it is longer than 200 bytes"
    } else {
        return Ok(());
    };
    Err(format!("`{}` cannot be a file name: {why}", escape(name)))
}

/// Several files written all or nothing: each is staged as a temporary file
/// beside its destination, and [`Batch::commit`] renames them all once every
/// one is complete. Dropped before that (an error, a panic), the batch
/// removes its temporary files and the directories it created.
#[derive(Default)]
pub struct Batch {
    staged: Vec<(Temporary, PathBuf)>,
    /// Directories this batch created, outermost first.
    created: Vec<PathBuf>,
    /// The directories it writes into ([`Batch::new`], [`Batch::directory`]):
    /// a file anywhere else is refused.
    dirs: Vec<PathBuf>,
}

impl Batch {
    /// A batch writing into `dir`, created (one level) if missing.
    pub fn new(dir: &Path) -> Result<Batch, String> {
        let mut b = Batch::default();
        b.directory(dir)?;
        Ok(b)
    }

    /// Makes `dir` exist (checked by [`check_directory`]); removed again if
    /// the batch is dropped uncommitted and it created it.
    pub fn directory(&mut self, dir: &Path) -> Result<(), String> {
        check_directory(dir)?;
        self.dirs.push(dir.to_path_buf());
        if !dir.is_dir() {
            fs::create_dir(dir).map_err(|e| format!("{}: cannot create it: {e}", dir.display()))?;
            self.created.push(dir.to_path_buf());
            live_dirs().push(dir.to_path_buf());
        }
        Ok(())
    }

    /// Stages `bytes` for `path`, which must name a plain file ([`plain_name`])
    /// directly in one of the batch's directories: a name made from user data
    /// (`../x`, `/etc/x`) can never reach outside the folder asked for.
    pub fn write_bytes(&mut self, path: &Path, bytes: &[u8]) -> Result<(), String> {
        let failed = |e: Failure| format!("{}: {e}", path.display());
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        let inside = path
            .parent()
            .is_some_and(|p| self.dirs.iter().any(|d| d == p));
        if !inside || plain_name(name).is_err() {
            return Err(format!(
                "{}: outside the output folder{} (a file name made from a name in the input must be a plain name)",
                escape(&path.display().to_string()),
                match self.dirs.first() {
                    Some(d) => format!(" {}", d.display()),
                    None => String::new(),
                }
            ));
        }
        let real = destination(path)?;
        if self.staged.iter().any(|(_, p)| *p == real) {
            return Err(format!("{}: written twice in one batch", path.display()));
        }
        let temp = stage(&real, |w| Ok(w.write_all(bytes)?)).map_err(failed)?;
        self.staged.push((temp, real));
        Ok(())
    }

    /// Renames every staged file over its destination. A rename that fails
    /// (the file system changed under the run) stops there: the files before
    /// it are in place, the rest are removed, and the error says which.
    pub fn commit(mut self) -> Result<(), String> {
        let staged = std::mem::take(&mut self.staged);
        let total = staged.len();
        // Temporary files after a failed rename are dropped, so removed.
        for (done, (temp, real)) in staged.into_iter().enumerate() {
            if let Err(e) = temp.rename_to(&real) {
                return Err(format!(
                    "{}: cannot rename the temporary file to it: {e} ({done} of {total} files were written)",
                    real.display()
                ));
            }
        }
        self.forget_created();
        Ok(())
    }

    /// The directories it created stay: they are no longer the batch's to
    /// remove, on an error or an interruption.
    fn forget_created(&mut self) {
        let created = std::mem::take(&mut self.created);
        live_dirs().retain(|d| !created.contains(d));
    }
}

impl Drop for Batch {
    fn drop(&mut self) {
        self.staged.clear();
        for dir in self.created.iter().rev() {
            let _ = fs::remove_dir(dir);
        }
        self.forget_created();
    }
}

/// Temporary files that exist right now, for [`remove_temporaries`].
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

/// Directories that uncommitted batches created, for [`remove_temporaries`].
static LIVE_DIRS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live_dirs() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    LIVE_DIRS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Removes every temporary file this process has open, then the directories
/// uncommitted batches created (innermost first; only empty ones: nothing
/// else is removed); the binary calls it when interrupted, before it exits.
pub fn remove_temporaries() {
    for path in live().drain(..) {
        let _ = fs::remove_file(path);
    }
    for dir in live_dirs().drain(..).rev() {
        let _ = fs::remove_dir(dir);
    }
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
        live().retain(|p| *p != self.path);
        Ok(())
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = fs::remove_file(&self.path);
            live().retain(|p| *p != self.path);
        }
    }
}

/// Creates `.NAME.PID.N.tmp` next to `path`, with a name no other writer in
/// this process or another one uses.
fn create_temporary(path: &Path) -> Result<(File, Temporary), Failure> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().ok_or_else(|| {
        Failure::Refused(format!("{}: the path has no file name", path.display()))
    })?;
    let dir = path.parent().unwrap_or(Path::new(""));
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".{}.{n}.tmp", std::process::id()));
        let temp = dir.join(temp_name);
        // Registered before it exists, so an interrupt never misses it.
        live().push(temp.clone());
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => {
                let temp = Temporary {
                    path: temp,
                    renamed: false,
                };
                return Ok((file, temp));
            }
            Err(e) => {
                live().retain(|p| *p != temp);
                if e.kind() == io::ErrorKind::AlreadyExists {
                    continue;
                }
                return Err(Failure::Io {
                    action: "create a temporary file for",
                    source: e,
                });
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
        // Not registered any more (other tests' writes may be, meanwhile).
        assert!(!live().iter().any(|p| p.starts_with(dir.path())));
    }

    #[test]
    fn missing_directory_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/dir/out.bin");
        let err = write_atomically(&path, |_| Ok(())).unwrap_err();
        assert!(matches!(err, Failure::Refused(_)), "{err:?}");
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }

    #[cfg(unix)]
    #[test]
    fn a_link_is_followed_and_stays_a_link() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("real.bin");
        let link = dir.path().join("link.bin");
        fs::write(&target, b"old").unwrap();
        std::os::unix::fs::symlink("real.bin", &link).unwrap();
        write_bytes(&link, b"new").unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read(&target).unwrap(), b"new");
    }

    #[test]
    fn directories_and_dots_are_not_files() {
        for p in [".", "/", "..", "some/dir/"] {
            assert!(destination(Path::new(p)).is_err(), "{p}");
        }
    }

    #[test]
    fn a_dropped_batch_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("new");
        let mut b = Batch::new(&out).unwrap();
        b.write_bytes(&out.join("a"), b"a").unwrap();
        assert!(b.write_bytes(&out.join("no/b"), b"b").is_err());
        drop(b);
        assert_eq!(names_in(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn a_committed_batch_writes_every_file() {
        let dir = tempfile::tempdir().unwrap();
        let mut b = Batch::new(dir.path()).unwrap();
        b.write_bytes(&dir.path().join("a"), b"a").unwrap();
        b.write_bytes(&dir.path().join("b"), b"b").unwrap();
        b.commit().unwrap();
        assert_eq!(names_in(dir.path()), vec!["a".to_string(), "b".to_string()]);
    }
}
