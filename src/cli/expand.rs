//! `ps30 expand`: the shader as plain assembly with every macro expanded.

use super::args::{InputArgs, SourceArgs};
use super::io::{audit, check_output_path, load_shader, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::audit::Given;
use ps30::core::front::print::write_program;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file (assembly or bytecode), `-` for standard input, or a
    /// bundled name such as article:pass2 (`ps30 shaders` lists them).
    #[arg(value_name = "SHADER")]
    shader: String,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Write to this file (atomically) instead of stdout.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Print JSON (source, slots, instructions, output, assembly) instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if let Some(path) = &args.output {
        check_output_path(path, &[Path::new(&args.shader)])?;
    }
    let loaded = load_shader(ui, &args.shader, &args.source, &args.input)?;
    let given = Given {
        defines: args.source.define.iter().map(|(n, _)| n.clone()).collect(),
        ..Given::default()
    };
    let found = audit(ui, &loaded, &given, false)?;
    let text = format!(
        "// expanded from {} by ps30 expand: {} instruction slots (Microsoft's count)\n{}",
        loaded.file.name,
        loaded
            .shader
            .info()
            .total(ps30::core::isa::SlotTable::Fxc)
            .total(),
        write_program(loaded.shader.program())
    );
    if let Some(path) = &args.output {
        ps30::core::output::write_bytes(path, text.as_bytes())
            .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
    }
    if args.json {
        print_json(&ps30::present::check::expand_json(
            &loaded,
            &found,
            args.output.as_deref(),
            &text,
        ))?;
    } else if args.output.is_none() {
        print(&text)?;
    } else if let Some(path) = args.output.as_ref().filter(|_| !ui.quiet) {
        print(&format!("wrote {}\n", path.display()))?;
    }
    Ok(Outcome::Ok)
}
