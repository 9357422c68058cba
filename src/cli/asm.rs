//! `ps30 asm`: a shader to ps_3_0 bytecode — REPEAT_BLOCK expanded,
//! validated, then written atomically, exactly as Microsoft's assembler
//! would write it.

use super::args::{InputArgs, SourceArgs};
use super::io::{
    check_output_path, emit, eprint, print, print_bytes, print_json, shader_file, source_error,
};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::bytecode::{self, write::to_bytes};
use ps30::core::isa::SlotTable;
use ps30::core::load;
use ps30::core::numbers::thousands;
use std::io::IsTerminal;
use std::path::Path;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: assembly or ps_3_0 bytecode (`-` reads standard input).
    file: String,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Where to write the bytecode (atomically); `-` writes it to standard output.
    #[arg(short, long, value_name = "FILE")]
    output: String,
    /// Print JSON (source, output, tokens, bytes, slots, instructions, crc32) instead of text.
    #[arg(long)]
    json: bool,
    /// Also print the CRC-32 of the bytecode written (eight hex digits, the
    /// name shader-replacement tools give a dumped shader); JSON always has it.
    #[arg(long)]
    crc32: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    let to_stdout = args.output == "-";
    if to_stdout && std::io::stdout().is_terminal() {
        return Err(BadInput(
            "-o -: standard output is a terminal; redirect it, or give -o FILE".into(),
        ));
    }
    if to_stdout && args.json {
        return Err(BadInput("--json and -o - both want standard output".into()));
    }
    if !to_stdout {
        check_output_path(Path::new(&args.output), &[Path::new(&args.file)])?;
    }
    let options = args.source.options();
    let file = shader_file(&args.file, &options, args.input.max_input_bytes)?;
    let (loaded, tokens) = load::assemble(file, &options).map_err(|e| source_error(ui, &e))?;
    if !ui.quiet {
        emit(ui, &loaded.warnings, &loaded.file);
    }
    let bytes = to_bytes(&tokens);
    if to_stdout {
        print_bytes(&bytes)?;
    } else {
        ps30::core::output::write_bytes(Path::new(&args.output), &bytes)
            .map_err(|e| BadInput(format!("{}: {e}", args.output)))?;
    }
    let slots = loaded.shader.info().total(SlotTable::Fxc).total();
    let crc = bytecode::crc32_hex(bytecode::crc32(&bytes));
    if args.json {
        print_json(&serde_json::json!({
            "source": loaded.file.name,
            "output": args.output,
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
            if to_stdout {
                "standard output"
            } else {
                &args.output
            },
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
