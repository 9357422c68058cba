//! `ps30 asm`: a shader to ps_3_0 bytecode — REPEAT_BLOCK expanded,
//! validated, then written atomically, exactly as Microsoft's assembler
//! would write it.

use super::args::{InputArgs, SourceArgs};
use super::corpus::{self, refused, source_errors, CorpusArgs, Done, Outputs};
use super::io::{
    check_output_path, emit, eprint, print, print_bytes, print_json, shader_file, source_error,
};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::bytecode::{self, write::to_bytes};
use ps30::core::isa::SlotTable;
use ps30::core::load;
use ps30::core::numbers::thousands;
use ps30::jobs::corpus::{is_corpus, Entry, FileResult};
use std::io::IsTerminal;
use std::path::Path;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: assembly or bytecode (`-` reads standard input). Several, or a
    /// directory (walked recursively for .psh, .asm, .dis, .fxo, .cso and .pso files):
    /// corpus mode, one line per file and a summary.
    #[arg(required = true, num_args = 1..)]
    files: Vec<String>,
    #[command(flatten)]
    corpus: CorpusArgs,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Where to write the bytecode (atomically); `-` writes it to standard output.
    /// In corpus mode a directory (created if missing): each file's bytecode as
    /// its path below the argument it was found in, .fxo appended to its name.
    #[arg(short, long, value_name = "FILE")]
    output: Option<String>,
    /// Print JSON (source, output, tokens, bytes, slots, instructions, crc32) instead of text.
    #[arg(long)]
    json: bool,
    /// Also print the CRC-32 of the bytecode written (eight hex digits, the
    /// name shader-replacement tools give a dumped shader); JSON always has it.
    #[arg(long)]
    crc32: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if is_corpus(&args.files) {
        let outputs = args.output.as_deref().map(|dir| Outputs {
            dir: Path::new(dir),
            extension: "fxo",
        });
        let write = outputs.is_some();
        return corpus::run(ui, &args.files, &args.corpus, args.json, outputs, |e| {
            asm_one(&args, e, write)
        });
    }
    let Some(output) = args.output.clone() else {
        return Err(BadInput(
            "give -o FILE for the bytecode (-o - writes it to standard output)".into(),
        ));
    };
    single(args, &output, ui)
}

/// One file of a corpus assembled (nothing printed): its tokens, bytes,
/// slots and CRC-32, and its bytes when they are to be written.
fn asm_one(args: &Args, entry: &Entry, write: bool) -> Done {
    let options = args.source.options();
    let file = match shader_file(&entry.spec, &options, args.input.max_input_bytes) {
        Ok(f) => f,
        Err(BadInput(m)) => return refused(entry, m),
    };
    let (loaded, tokens) = match load::assemble(file, &options) {
        Ok(done) => done,
        Err(e) => return (FileResult::refused(&entry.spec, source_errors(&e)), None),
    };
    let bytes = to_bytes(&tokens);
    let mut facts = serde_json::Map::new();
    facts.insert("bytes".into(), bytes.len().into());
    let slots = loaded.shader.info().total(SlotTable::Fxc).total();
    facts.insert("slots".into(), slots.into());
    let crc = bytecode::crc32_hex(bytecode::crc32(&bytes));
    facts.insert("crc32".into(), crc.into());
    (
        FileResult::accepted(&entry.spec, facts),
        write.then_some(bytes),
    )
}

/// One shader to one file (or standard output).
fn single(args: Args, output: &str, ui: &Ui) -> super::Result {
    let to_stdout = output == "-";
    if to_stdout && std::io::stdout().is_terminal() {
        return Err(BadInput(
            "-o -: standard output is a terminal; redirect it, or give -o FILE".into(),
        ));
    }
    if to_stdout && args.json {
        return Err(BadInput("--json and -o - both want standard output".into()));
    }
    if !to_stdout {
        check_output_path(Path::new(output), &[Path::new(&args.files[0])])?;
    }
    let options = args.source.options();
    let file = shader_file(&args.files[0], &options, args.input.max_input_bytes)?;
    let (loaded, tokens) = load::assemble(file, &options).map_err(|e| source_error(ui, &e))?;
    if !ui.quiet {
        emit(ui, &loaded.warnings, &loaded.file);
    }
    let bytes = to_bytes(&tokens);
    if to_stdout {
        print_bytes(&bytes)?;
    } else {
        ps30::core::output::write_bytes(Path::new(output), &bytes)
            .map_err(|e| BadInput(format!("{output}: {e}")))?;
    }
    let slots = loaded.shader.info().total(SlotTable::Fxc).total();
    let crc = bytecode::crc32_hex(bytecode::crc32(&bytes));
    if args.json {
        print_json(&serde_json::json!({
            "source": loaded.file.name,
            "output": output,
            "tokens": tokens.len(),
            "bytes": bytes.len(),
            "slots": slots,
            "instructions": loaded.shader.instructions().len(),
            "crc32": crc,
        }))?;
    } else if !ui.quiet {
        let crc_text = if args.crc32 {
            format!(", CRC32 {crc}")
        } else {
            String::new()
        };
        let line = format!(
            "wrote {}: {} tokens ({} bytes), {} instruction slots{crc_text}",
            if to_stdout { "standard output" } else { output },
            thousands(tokens.len() as u64),
            thousands(bytes.len() as u64),
            thousands(slots as u64)
        );
        if to_stdout {
            eprint(&format!("{line}\n"));
        } else {
            print(&format!("{line}\n"))?;
        }
    } else if args.crc32 {
        // --quiet --crc32: the CRC alone, for scripts that name files by it.
        if to_stdout {
            eprint(&format!("{crc}\n"));
        } else {
            print(&format!("{crc}\n"))?;
        }
    }
    Ok(Outcome::Ok)
}
