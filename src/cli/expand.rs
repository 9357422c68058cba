//! `ps30 expand`: the shader as plain assembly with every macro expanded.

use super::args::{InputArgs, SourceArgs};
use super::io::{check_output_path, load_file, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::front::print::write_program;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Shader: assembly or ps_3_0 bytecode (`-` reads standard input).
    file: String,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Write to this file (atomically) instead of stdout.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Print JSON (source, slots, instructions, output, assembly) instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    if let Some(path) = &args.output {
        check_output_path(path, &[Path::new(&args.file)])?;
    }
    let loaded = load_file(
        &args.file,
        &args.source.options(),
        args.input.max_input_bytes,
    )?;
    let text = format!(
        "// expanded from {} by ps30 expand: {} instruction slots\n{}",
        loaded.file.name,
        loaded.shader.info().total_slots,
        write_program(loaded.shader.program())
    );
    if let Some(path) = &args.output {
        ps30::core::output::write_bytes(path, text.as_bytes())
            .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
    }
    if args.json {
        print_json(&serde_json::json!({
            "source": loaded.file.name,
            "slots": loaded.shader.info().total_slots,
            "instructions": loaded.shader.instructions().len(),
            "output": args.output.as_ref().map(|p| p.display().to_string()),
            "assembly": text,
        }))?;
    } else if args.output.is_none() {
        print(&text)?;
    }
    Ok(Outcome::Ok)
}
