//! Corpus mode on the command line: `check`, `asm`, `disasm`, `translate` and `decompile`
//! given several shaders or a directory. Each command says what it does with
//! one file (a closure returning its [`FileResult`] and, with `-o DIR`, the
//! bytes to write); this module walks the arguments, runs the files in
//! parallel within `--threads`, prints one line per file as the results
//! arrive (JSON Lines with `--json`), writes outputs into a mirror of the
//! input tree, and ends with the summary.
//!
//! Exit codes: 0 every file accepted; 1 some file over a limit (`check`) and
//! none refused; 2 some file refused, or bad usage.

use super::io::{eprint, print};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::diag::SourceError;
use ps30::core::output::{self, Batch};
use ps30::jobs::corpus::{self, Entry, FileResult, Summary};
use ps30::present::corpus::{json_line, line, summary_json, summary_text};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// Corpus mode's flags, shared by the five commands.
#[derive(clap::Args, Debug)]
pub struct CorpusArgs {
    /// Threads for the files of a corpus (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    pub threads: Option<u32>,
}

/// Where a corpus run writes: `-o DIR`, each file as its path below the
/// argument it was found in, `.extension` appended to its name (`a/b.psh`
/// gives `DIR/a/b.psh.fxo`, so that `b.psh` and `b.dis` never meet).
pub struct Outputs<'a> {
    /// The directory given (created if missing, one level, as every `-o DIR`).
    pub dir: &'a Path,
    /// The extension of the files written (`fxo`, `dis`, `wgsl`, …).
    pub extension: &'a str,
}

/// One file's work: its result, and the bytes to write with `-o DIR`.
pub type Done = (FileResult, Option<Vec<u8>>);

/// The errors of a shader that did not load, as [`FileResult::refused`]
/// takes them.
pub fn source_errors(e: &SourceError) -> Vec<(Option<String>, String)> {
    e.diagnostics
        .errors()
        .map(|d| {
            (
                d.code.map(String::from),
                format!("{}: {d}", d.location(&e.file)),
            )
        })
        .collect()
}

/// One corpus file read and loaded with `options`, or its refusal.
pub fn load_entry(
    entry: &Entry,
    options: &ps30::core::load::Options,
    max_input_bytes: u64,
) -> Result<ps30::core::load::Loaded, Box<Done>> {
    let file = match super::io::shader_file(&entry.spec, options, max_input_bytes) {
        Ok(f) => f,
        Err(BadInput(m)) => return Err(Box::new(refused(entry, m))),
    };
    ps30::core::load::load(file, options)
        .map_err(|e| Box::new((FileResult::refused(&entry.spec, source_errors(&e)), None)))
}

/// A refusal without a diagnostic (unreadable, not a shader).
pub fn refused(entry: &Entry, message: String) -> Done {
    (
        FileResult::refused(&entry.spec, vec![(None, message)]),
        None,
    )
}

/// Runs `work` on every shader of `args` and prints the results and the
/// summary; the exit code as the module docs say.
pub fn run(
    ui: &Ui,
    args: &[String],
    corpus_args: &CorpusArgs,
    json: bool,
    outputs: Option<Outputs>,
    work: impl Fn(&Entry) -> Done + Sync,
) -> super::Result {
    super::bound_threads(corpus_args.threads.map(|t| t as usize))?;
    let skip = match &outputs {
        Some(o) => {
            output::check_directory(o.dir)?;
            if !o.dir.is_dir() {
                std::fs::create_dir(o.dir)
                    .map_err(|e| BadInput(format!("{}: cannot create it: {e}", o.dir.display())))?;
            }
            Some(o.dir.canonicalize()?)
        }
        None => None,
    };
    let started = std::time::SystemTime::now();
    let mut summary = Summary::default();
    let entries = corpus::walk(args, skip.as_deref());
    let each = |chunk: Vec<(Option<Entry>, Done)>| -> Result<(), BadInput> {
        let mut batch = outputs.as_ref().map(|o| Batch::new(o.dir)).transpose()?;
        let mut dirs = HashSet::new();
        for (entry, (mut result, bytes)) in chunk {
            if let (Some(o), Some(b), Some(e), Some(batch)) = (&outputs, bytes, entry, &mut batch) {
                match stage(batch, &mut dirs, o, &e, &b, started) {
                    Ok(to) => result.output = Some(to.display().to_string()),
                    Err(message) => result = refused(&e, message).0,
                }
            }
            summary.add(&result);
            print(&if json {
                json_line(&result)
            } else {
                line(&result)
            })?;
        }
        if let Some(batch) = batch {
            batch.commit().map_err(BadInput)?;
        }
        Ok(())
    };
    corpus::in_chunks(
        entries,
        |e| match e {
            Ok(entry) => {
                let done = work(&entry);
                (Some(entry), done)
            }
            Err(message) => (None, (FileResult::refused("", vec![(None, message)]), None)),
        },
        each,
    )?;
    summary.finish();
    if json {
        print(&summary_json(&summary))?;
    } else {
        print(&summary_text(&summary))?;
    }
    if !ui.quiet && summary.files == 0 {
        eprint("warning: no shader files found (extensions taken from directories: psh, asm, dis, fxo, cso, pso)\n");
    }
    Ok(match summary.exit_code() {
        0 => Outcome::Ok,
        1 => Outcome::Problem,
        _ => Outcome::Refused,
    })
}

/// Stages one output in the chunk's batch: `DIR/RELATIVE` with the output's
/// extension, the directories below `DIR` made as needed; never an input,
/// and never a file this run already wrote (two inputs that differ only in
/// their extension): that file is refused, with the reason.
fn stage(
    batch: &mut Batch,
    dirs: &mut HashSet<PathBuf>,
    o: &Outputs,
    e: &Entry,
    bytes: &[u8],
    started: std::time::SystemTime,
) -> Result<PathBuf, String> {
    let mut name = e.relative.file_name().unwrap_or_default().to_os_string();
    name.push(".");
    name.push(o.extension);
    let to = o.dir.join(&e.relative).with_file_name(name);
    let mut dir = o.dir.to_path_buf();
    if let Some(parent) = e.relative.parent() {
        for part in parent.components() {
            dir.push(part);
            if dirs.insert(dir.clone()) {
                batch.directory(&dir)?;
            }
        }
    }
    output::check(&to, &[Path::new(&e.spec)])?;
    let written_now = std::fs::metadata(&to)
        .and_then(|m| m.modified())
        .is_ok_and(|t| t >= started);
    if written_now {
        return Err(format!(
            "{}: another input of this run was already written there; rename one of them",
            to.display()
        ));
    }
    batch.write_bytes(&to, bytes)?;
    Ok(to)
}
