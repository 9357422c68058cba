//! `ps30 translate`: a shader in WGSL, SPIR-V, GLSL, HLSL or MSL, through
//! naga, with a header naming the source and the binding layout.

use super::args::{FloatRulesArg, InputArgs, SourceArgs};
use super::io::{eprint, load_shader, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::translate::{self, header, Entry, Target, Written};
use std::io::IsTerminal;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Shader file or bundled name (see `ps30 luminance --help`).
    shader: String,
    /// Target language.
    #[arg(long, value_enum)]
    to: TargetArg,
    /// Write to this file (atomically) instead of stdout.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Special values: d3d9 (Microsoft's pages, the default), ieee, d3d9-zero-mul, or hardware.
    #[arg(long, value_enum, default_value = "d3d9")]
    float_rules: FloatRulesArg,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Print JSON (source, target, float_rules, interface, notes, output, text) instead of the translation.
    #[arg(long)]
    json: bool,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum TargetArg {
    Wgsl,
    Spirv,
    Glsl,
    Hlsl,
    Msl,
}

impl From<TargetArg> for Target {
    fn from(t: TargetArg) -> Self {
        match t {
            TargetArg::Wgsl => Target::Wgsl,
            TargetArg::Spirv => Target::SpirV,
            TargetArg::Glsl => Target::Glsl,
            TargetArg::Hlsl => Target::Hlsl,
            TargetArg::Msl => Target::Msl,
        }
    }
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    let target: Target = args.to.into();
    if target == Target::SpirV
        && args.output.is_none()
        && !args.json
        && std::io::stdout().is_terminal()
    {
        return Err(BadInput(
            "SPIR-V is binary: give -o FILE (or redirect stdout)".into(),
        ));
    }
    if let Some(out) = &args.output {
        super::io::check_output_path(out, &[std::path::Path::new(&args.shader)])?;
    }
    let loaded = load_shader(ui, &args.shader, &args.source, &args.input)?;
    let translation =
        translate::translate(&loaded.shader, args.float_rules.into(), Entry::Application)
            .map_err(|e| BadInput(format!("{}: {e}", loaded.file.name)))?;
    let head = header::comment(&loaded.file.name, &translation, target);
    let written = translate::write(&translation, target, &head)
        .map_err(|e| BadInput(format!("{}: {e}", loaded.file.name)))?;
    let bytes: &[u8] = match &written {
        Written::Text(t) => t.as_bytes(),
        Written::Binary(b) => b,
    };
    if let Some(path) = &args.output {
        ps30::core::output::write_bytes(path, bytes)
            .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
        if !ui.quiet && !args.json {
            eprint(&format!(
                "wrote {} ({}, {} bytes)\n",
                path.display(),
                target.describe(),
                bytes.len()
            ));
        }
    }
    if args.json {
        print_json(&serde_json::json!({
            "source": loaded.file.name,
            "target": target.name(),
            "float_rules": translation.rules.name(),
            "interface": translation.interface,
            "derivative_uniformity_off": translation.derivative_uniformity_off,
            "notes": translation.notes,
            "output": args.output.as_ref().map(|p| p.display().to_string()),
            "text": match &written {
                Written::Text(t) => serde_json::Value::String(t.clone()),
                Written::Binary(_) => serde_json::Value::Null,
            },
        }))?;
    } else if args.output.is_none() {
        match written {
            Written::Text(t) => print(&t)?,
            Written::Binary(b) => super::io::print_bytes(&b)?,
        }
    }
    Ok(Outcome::Ok)
}
