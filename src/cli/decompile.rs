//! `ps30 decompile`: a ps_1_1–ps_1_4, ps_2_0, ps_2_x, ps_3_0, vs_2_0, vs_2_x
//! or vs_3_0 shader (bytecode or assembly) as HLSL, and with `--verify` the proof
//! that the HLSL means what the shader meant: Microsoft's compiler
//! compiles it and both run in the emulator (pixel or vertex stage) on the
//! same inputs.

use super::args::{InputArgs, SourceArgs};
use super::corpus::{self, refused, CorpusArgs, Done, Outputs};
use super::io::{eprint, load_shader, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::decompile;
use ps30::jobs::corpus::{is_corpus, Entry, FileResult};
use ps30::jobs::decompile::{self as job, Verdict};
use ps30::present::decompile as present;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: ps_1_1–ps_1_4, ps_2_0, ps_2_x, ps_3_0, vs_2_0, vs_2_x or vs_3_0 bytecode or
    /// assembly, a bundled name, or `-` for standard input (ps_1_x as HLSL for ps_2_0, or
    /// ps_2_a where ps_2_0's budgets are too small, under --ps1-max-value).
    /// Several, or a directory (walked recursively for .psh, .asm, .dis, .fxo, .cso and .pso
    /// files): corpus mode, one line per file and a summary.
    #[arg(required = true, num_args = 1..)]
    shaders: Vec<String>,
    #[command(flatten)]
    corpus: CorpusArgs,
    /// Write the HLSL to this file (atomically) instead of standard output. In corpus mode a
    /// directory (created if missing): each file's HLSL as its path below the argument it was
    /// found in, with .hlsl appended.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Compile the HLSL with Microsoft's compiler (tools/oracle/setup.sh installs it into
    /// target/oracle, or name its folder with PS30_ORACLE) and run both shaders in the
    /// emulator (vertex shaders in the vertex stage) on the same random and edge-case inputs. Exit 1 when they differ, 3 when the
    /// compiler is not installed. One shader at a time (not in corpus mode).
    #[arg(long)]
    verify: bool,
    /// Pixels per verification draw (the side of a square target); a vertex shader's draws
    /// have its square of vertices.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(2..=512))]
    verify_size: u32,
    /// Print JSON (the HLSL, its counts, and with --verify the verdict) instead of the HLSL.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if is_corpus(&args.shaders) {
        if args.verify {
            return Err(BadInput(
                "--verify takes one shader: it compiles and runs each decompilation; give the files one at a time".into(),
            ));
        }
        let outputs = args.output.as_deref().map(|dir| Outputs {
            dir,
            extension: "hlsl",
        });
        let write = outputs.is_some();
        return corpus::run(ui, &args.shaders, &args.corpus, args.json, outputs, |e| {
            decompile_one(&args, e, write)
        });
    }
    let shader = &args.shaders[0];
    if let Some(out) = &args.output {
        super::io::check_output_path(out, &[std::path::Path::new(shader)])?;
    }
    let loaded = load_shader(ui, shader, &args.source, &args.input)?;
    let d = decompile::decompile(&loaded.shader, loaded.constants.as_ref())
        .map_err(|e| BadInput(format!("{}: {e}", loaded.file.name)))?;
    if let Some(path) = &args.output {
        ps30::core::output::write_bytes(path, d.hlsl.as_bytes())
            .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
        if !ui.quiet && !args.json {
            eprint(&format!(
                "wrote {} ({} lines of HLSL)\n",
                path.display(),
                d.hlsl.lines().count()
            ));
        }
    }
    let verdict = if args.verify {
        let oracle = job::Oracle::find().map_err(|e| BadInput(e.to_string()));
        let oracle = match oracle {
            Ok(o) => o,
            Err(e) => {
                eprint(&format!("ps30: {}\n", e.0));
                return Ok(Outcome::Unavailable);
            }
        };
        Some(
            job::verify(&loaded.shader, &d, &oracle, args.verify_size)
                .map_err(|e| BadInput(format!("{}: {e}", loaded.file.name)))?,
        )
    } else {
        None
    };
    if args.json {
        print_json(&present::json(&loaded.file.name, &d, verdict.as_ref()))?;
    } else {
        if args.output.is_none() {
            print(&d.hlsl)?;
        }
        if let Some(v) = &verdict {
            print(&present::verdict_text(v))?;
        }
    }
    Ok(match verdict {
        Some(Verdict {
            equivalent: false, ..
        }) => Outcome::Problem,
        _ => Outcome::Ok,
    })
}

/// One file of a corpus decompiled (nothing printed): the counts, and the
/// HLSL when it is to be written.
fn decompile_one(args: &Args, entry: &Entry, write: bool) -> Done {
    let options = args.source.options();
    let loaded = match corpus::load_entry(entry, &options, args.input.max_input_bytes) {
        Ok(l) => l,
        Err(done) => return *done,
    };
    let d = match decompile::decompile(&loaded.shader, loaded.constants.as_ref()) {
        Ok(d) => d,
        Err(e) => return refused(entry, format!("{}: {e}", entry.spec)),
    };
    let mut facts = serde_json::Map::new();
    facts.insert("instructions".into(), d.instructions.into());
    facts.insert("statements".into(), d.statements.into());
    facts.insert("bytes".into(), d.hlsl.len().into());
    (
        FileResult::accepted(&entry.spec, facts),
        write.then(|| d.hlsl.into_bytes()),
    )
}
