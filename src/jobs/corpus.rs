//! Corpus mode: many shaders in one run. `check`, `asm`, `disasm` and
//! `translate` take files and directories; this module finds the shaders
//! (directories walked recursively, in name order), runs a command's work on
//! each in parallel, a chunk at a time, and hands the results back in the
//! order the files were found, so that output is the same for any thread
//! count and memory holds one chunk, never the whole corpus. [`Summary`]
//! folds the results into the counts the run ends with.
//!
//! The work for one file is the command's (a closure from the command
//! line); what a file's result says is [`FileResult`], the same for every
//! command.

use rayon::prelude::*;
use serde::Serialize;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// The extensions a directory's files are taken by (lower case, compared
/// without regard to case): assembly (`psh`, `asm`), listings (`dis`, what
/// Microsoft's disassembler writes) and compiled shaders (`fxo`, `cso`,
/// `pso`). A file named on the command line is taken whatever its name.
pub const EXTENSIONS: &[&str] = &["psh", "asm", "dis", "fxo", "cso", "pso"];

/// How many files are worked on at once before their results are handed
/// back: enough to keep every thread busy, few enough that memory does not
/// grow with the corpus.
pub const CHUNK: usize = 512;

/// One shader of a corpus.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    /// What to load: the argument itself (a file, `-`, or a bundled name),
    /// or a file found in a directory.
    pub spec: String,
    /// Its path below the directory argument it was found in (a file
    /// argument: its file name): where its output goes below `-o DIR`.
    pub relative: PathBuf,
}

/// Whether a run of a command takes its arguments as a corpus: more than
/// one, or a directory.
pub fn is_corpus(args: &[String]) -> bool {
    args.len() > 1 || args.iter().any(|a| Path::new(a).is_dir())
}

/// Whether a file found in a directory is a shader by its extension
/// ([`EXTENSIONS`]).
pub fn has_shader_extension(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| EXTENSIONS.iter().any(|x| x.eq_ignore_ascii_case(e)))
}

/// The shaders of `args`, lazily, in order: each argument that is a
/// directory walked recursively (entries sorted by name, links to
/// directories not followed, `skip` — an output directory — left out), every
/// other argument as it is. A directory that cannot be read is an `Err`
/// naming it, in its place.
pub fn walk<'a>(
    args: &'a [String],
    skip: Option<&'a Path>,
) -> impl Iterator<Item = Result<Entry, String>> + 'a {
    args.iter()
        .flat_map(move |arg| -> Box<dyn Iterator<Item = _>> {
            let root = Path::new(arg);
            if !root.is_dir() {
                let relative = root
                    .file_name()
                    .map_or_else(|| PathBuf::from(ps30_name(arg)), PathBuf::from);
                return Box::new(std::iter::once(Ok(Entry {
                    spec: arg.clone(),
                    relative,
                })));
            }
            let walker = walkdir::WalkDir::new(root)
                .sort_by_file_name()
                .into_iter()
                .filter_entry(move |e| {
                    !e.file_type().is_dir() || skip.is_none_or(|s| !same_dir(e.path(), s))
                });
            Box::new(walker.filter_map(move |e| {
                match e {
                    Err(e) => Some(Err(e.to_string())),
                    Ok(e) if e.file_type().is_dir() => None,
                    Ok(e) if !has_shader_extension(e.path()) => None,
                    Ok(e) => Some(Ok(Entry {
                        spec: e.path().display().to_string(),
                        relative: e
                            .path()
                            .strip_prefix(root)
                            .unwrap_or(e.path())
                            .to_path_buf(),
                    })),
                }
            }))
        })
}

/// A bundled name (`article:loop`) as a file name (`article_loop`).
fn ps30_name(arg: &str) -> String {
    arg.replace([':', '/', '\\'], "_")
}

/// Whether `a` is the directory `b` (both resolved), so that an output
/// directory inside an input directory is never read back as input.
fn same_dir(a: &Path, b: &Path) -> bool {
    a.canonicalize().is_ok_and(|a| a == b)
}

/// Runs `work` on every entry, [`CHUNK`] at a time in parallel, and gives
/// each chunk's results to `each`, in the order of `entries`. Stops at the
/// first error `each` returns.
pub fn in_chunks<T: Send, E>(
    entries: impl Iterator<Item = Result<Entry, String>>,
    work: impl Fn(Result<Entry, String>) -> T + Sync,
    mut each: impl FnMut(Vec<T>) -> Result<(), E>,
) -> Result<(), E> {
    let mut entries = entries.peekable();
    while entries.peek().is_some() {
        let chunk: Vec<_> = entries.by_ref().take(CHUNK).collect();
        each(chunk.into_par_iter().map(&work).collect())?;
    }
    Ok(())
}

/// What became of one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Read, validated and (for `check`) within every limit.
    Accepted,
    /// Valid, but over a limit of the profile (`check` only).
    Over,
    /// Not a shader ps30 accepts: unreadable, not ps_3_0, or an error.
    Refused,
}

/// One file's result, as a table line or one JSON line.
#[derive(Clone, Debug, Serialize)]
pub struct FileResult {
    /// The file (or bundled name).
    pub path: String,
    /// Accepted, over a limit, or refused.
    pub status: Status,
    /// Microsoft's code of the first error, when it has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code: Option<String>,
    /// The first error (`file:line:col: message`), when refused.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// Every error of a refused file, `[code] message` (what the summary's
    /// most frequent diagnostics count).
    #[serde(skip)]
    pub errors: Vec<String>,
    /// The limits it is over (`slots`, `executed`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub over: Vec<String>,
    /// What the command found, as name and value (`slots`, `executed`,
    /// `bytes`, `crc32`, …), in the order shown.
    #[serde(flatten)]
    pub facts: serde_json::Map<String, serde_json::Value>,
    /// The file written, with `-o DIR`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub output: Option<String>,
}

impl FileResult {
    /// An accepted file with its facts.
    pub fn accepted(path: &str, facts: serde_json::Map<String, serde_json::Value>) -> FileResult {
        FileResult {
            path: path.to_string(),
            status: Status::Accepted,
            code: None,
            error: None,
            errors: Vec::new(),
            over: Vec::new(),
            facts,
            output: None,
        }
    }

    /// A refused file: `errors` as `(code, one-line message)`, the first one
    /// shown.
    pub fn refused(path: &str, errors: Vec<(Option<String>, String)>) -> FileResult {
        let mut r = FileResult::accepted(path, serde_json::Map::new());
        r.status = Status::Refused;
        if let Some((code, message)) = errors.first() {
            r.code = code.clone();
            r.error = Some(message.clone());
        }
        r.errors = errors
            .iter()
            .map(|(_, message)| strip_location(path, message).to_string())
            .collect();
        r
    }
}

/// A message without the `file:line:col: ` (or `file: `) it starts with,
/// so that the same error in many files counts once per kind.
fn strip_location<'a>(path: &str, message: &'a str) -> &'a str {
    match message.find(": error") {
        Some(i) => &message[i + 2..],
        None => message
            .strip_prefix(path)
            .and_then(|m| m.strip_prefix(": "))
            .unwrap_or(message),
    }
}

/// How many distinct errors the summary counts apart; the rest are counted
/// as [`OTHERS`].
pub const MAX_DISTINCT: usize = 10_000;

/// What errors past [`MAX_DISTINCT`] kinds are counted as.
pub const OTHERS: &str = "(other errors)";

/// How many diagnostics the summary lists.
pub const TOP_DIAGNOSTICS: usize = 5;

/// The counts a corpus run ends with.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Summary {
    /// Files seen.
    pub files: u64,
    /// Files accepted.
    pub accepted: u64,
    /// Files over a limit.
    pub over: u64,
    /// Files refused.
    pub refused: u64,
    /// Refused files by the code of their first error (`none`: an error
    /// without a code, such as a file that cannot be read).
    pub refused_by_code: BTreeMap<String, u64>,
    /// Files over each limit.
    pub over_by_limit: BTreeMap<String, u64>,
    /// The most frequent errors of refused files, most frequent first
    /// (ties by text), with their counts; filled by [`Summary::finish`].
    pub most_frequent: Vec<(String, u64)>,
    /// Every error's count, while the run goes on (distinct messages only,
    /// at most [`MAX_DISTINCT`] of them: bounded, whatever the files).
    #[serde(skip)]
    counts: HashMap<String, u64>,
}

impl Summary {
    /// Counts one file's result.
    pub fn add(&mut self, r: &FileResult) {
        self.files += 1;
        match r.status {
            Status::Accepted => self.accepted += 1,
            Status::Over => {
                self.over += 1;
                for l in &r.over {
                    *self.over_by_limit.entry(l.clone()).or_default() += 1;
                }
            }
            Status::Refused => {
                self.refused += 1;
                let code = r.code.clone().unwrap_or_else(|| "none".into());
                *self.refused_by_code.entry(code).or_default() += 1;
                for e in &r.errors {
                    // Past MAX_DISTINCT kinds, new ones are counted together,
                    // so that memory does not grow with the corpus.
                    let key = if self.counts.len() < MAX_DISTINCT || self.counts.contains_key(e) {
                        e.clone()
                    } else {
                        OTHERS.to_string()
                    };
                    *self.counts.entry(key).or_default() += 1;
                }
            }
        }
    }

    /// Picks the most frequent diagnostics once every file is counted.
    pub fn finish(&mut self) {
        let mut all: Vec<(String, u64)> = self.counts.drain().collect();
        all.sort_unstable_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        all.truncate(TOP_DIAGNOSTICS);
        self.most_frequent = all;
    }

    /// The exit code the run earns: 0 every file accepted, 1 some file over
    /// a limit and none refused, 2 some file refused.
    pub fn exit_code(&self) -> u8 {
        if self.refused > 0 {
            2
        } else if self.over > 0 {
            1
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extensions_and_summary() {
        assert!(has_shader_extension(Path::new("a/B.PSH")));
        assert!(!has_shader_extension(Path::new("a/b.json")));
        let mut s = Summary::default();
        s.add(&FileResult::accepted("a", serde_json::Map::new()));
        let r = FileResult::refused(
            "b",
            vec![(Some("X2005".into()), "b:1:1: error[X2005]: bad".into())],
        );
        s.add(&r);
        s.add(&r);
        s.finish();
        assert_eq!((s.files, s.accepted, s.refused), (3, 1, 2));
        assert_eq!(s.refused_by_code["X2005"], 2);
        assert_eq!(s.most_frequent, vec![("error[X2005]: bad".to_string(), 2)]);
        assert_eq!(s.exit_code(), 2);
    }
}
