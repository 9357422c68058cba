//! `ps30 shader-test`: vkd3d's `.shader_test` files run as its Direct3D 9
//! runner runs them, on the emulator, with Microsoft's compiler (the oracle
//! of `tools/oracle/`) compiling their HLSL; a line per file, a line per
//! probe that did not pass, and the totals.

use super::args::ExecArgs;
use super::io::{print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::jobs::decompile::oracle::{Job, Oracle};
use ps30::jobs::shader_test::{self as job, parse::MAX_FILE_BYTES, CompileJob};
use ps30::present::shader_test as show;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// The .shader_test files (a directory: every .shader_test file below it).
    #[arg(required = true, num_args = 1..)]
    files: Vec<PathBuf>,
    /// Also list the probes that passed and those ps30 cannot run.
    #[arg(long, short)]
    verbose: bool,
    #[command(flatten)]
    exec: ExecArgs,
}

/// The files named, directories walked (sorted), each read whole.
fn read_files(args: &Args) -> Result<Vec<(String, String)>, BadInput> {
    let mut paths = Vec::new();
    for p in &args.files {
        if p.is_dir() {
            let mut found: Vec<PathBuf> = walkdir::WalkDir::new(p)
                .into_iter()
                .filter_map(Result::ok)
                .map(|e| e.into_path())
                .filter(|q| q.extension().is_some_and(|e| e == "shader_test"))
                .collect();
            found.sort_unstable();
            paths.extend(found);
        } else {
            paths.push(p.clone());
        }
    }
    paths
        .into_iter()
        .map(|p| {
            let bytes = std::fs::read(&p).map_err(|e| BadInput(format!("{}: {e}", p.display())))?;
            if bytes.len() > MAX_FILE_BYTES {
                return Err(BadInput(format!(
                    "{}: {} bytes, over the {MAX_FILE_BYTES} a test file may have",
                    p.display(),
                    bytes.len()
                )));
            }
            let text = String::from_utf8(bytes)
                .map_err(|_| BadInput(format!("{}: not UTF-8 text", p.display())))?;
            Ok((p.display().to_string(), text))
        })
        .collect()
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    let files = read_files(&args)?;
    let oracle = Oracle::find().map_err(|e| BadInput(e.to_string()))?;
    let mut compile = |jobs: &[CompileJob]| {
        let batch: Vec<Job<'_>> = jobs
            .iter()
            .map(|j| Job {
                hlsl: &j.source,
                profile: &j.profile,
                flags: &j.flags,
            })
            .collect();
        let answers = oracle.compile_all(&batch)?;
        Ok(answers
            .into_iter()
            .map(|a| match a.bytecode {
                Some(b) if a.hresult == 0 => Ok(b),
                _ => Err(format!(
                    "hr {:#010x}: {}",
                    a.hresult,
                    a.messages.lines().next().unwrap_or("").trim()
                )),
            })
            .collect())
    };
    let settings = job::Settings {
        render: ps30::jobs::render::Settings {
            threads: args.exec.threads(),
            limits: args.exec.limits(),
            ..Default::default()
        },
    };
    let report = job::run_files(&files, &settings, &mut compile).map_err(BadInput)?;
    if args.exec.json {
        print_json(&report)?;
    } else if !ui.quiet {
        let mut out = String::new();
        for f in &report.files {
            out.push_str(&show::file_text(f, args.verbose));
        }
        out.push_str(&show::summary_text(&report));
        print(&out)?;
    }
    if report.files.iter().any(|f| f.malformed) {
        // Printed above: each such file's `stopped:` line names the place.
        return Ok(Outcome::Refused);
    }
    Ok(Outcome::from_ok(report.ok()))
}
