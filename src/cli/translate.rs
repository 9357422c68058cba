//! `ps30 translate`: a shader in WGSL, SPIR-V, GLSL, HLSL or MSL, through
//! naga, with a header naming the source and the binding layout.

use super::args::{FloatRulesArg, InputArgs, SourceArgs};
use super::corpus::{self, refused, CorpusArgs, Done, Outputs};
use super::io::{eprint, load_shader, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::translate::{self, header, Entry, Target, Written};
use ps30::jobs::corpus::{is_corpus, FileResult};
use std::io::IsTerminal;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Shader file or bundled name (see `ps30 luminance --help`). Several, or a
    /// directory (walked recursively for .psh, .asm, .dis, .fxo, .cso and .pso files):
    /// corpus mode, one line per file and a summary.
    #[arg(required = true, num_args = 1..)]
    shaders: Vec<String>,
    #[command(flatten)]
    corpus: CorpusArgs,
    /// Target language.
    #[arg(long, value_enum)]
    to: TargetArg,
    /// Write to this file (atomically) instead of stdout. In corpus mode a directory
    /// (created if missing): each translation as its file's path below the argument it
    /// was found in, the target's extension (.wgsl, .spv, .glsl, .hlsl, .metal) appended.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Special values: hardware (what Direct3D 9 hardware computes, the default), d3d9 (Microsoft's pages), ieee, or d3d9-zero-mul.
    #[arg(long, value_enum, default_value = "hardware")]
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
    if is_corpus(&args.shaders) {
        let target: Target = args.to.into();
        let outputs = args.output.as_deref().map(|dir| Outputs {
            dir,
            extension: extension(target),
        });
        let write = outputs.is_some();
        return corpus::run(ui, &args.shaders, &args.corpus, args.json, outputs, |e| {
            translate_one(&args, e, write)
        });
    }
    single(args, ui)
}

/// The extension of a translation's file in corpus mode.
fn extension(target: Target) -> &'static str {
    match target {
        Target::Wgsl => "wgsl",
        Target::SpirV => "spv",
        Target::Glsl => "glsl",
        Target::Hlsl => "hlsl",
        Target::Msl => "metal",
    }
}

/// One file of a corpus translated (nothing printed): the translation's
/// size, and its bytes when they are to be written.
fn translate_one(args: &Args, entry: &ps30::jobs::corpus::Entry, write: bool) -> Done {
    let options = args.source.options();
    let loaded = match corpus::load_entry(entry, &options, args.input.max_input_bytes) {
        Ok(l) => l,
        Err(done) => return *done,
    };
    let target: Target = args.to.into();
    let written = translate::translate(&loaded.shader, args.float_rules.into(), Entry::Application)
        .map_err(|e| e.to_string())
        .and_then(|t| {
            let head = header::comment(&loaded.file.name, &t, target);
            translate::write(&t, target, &head).map_err(|e| e.to_string())
        });
    let bytes = match written {
        Ok(Written::Text(t)) => t.into_bytes(),
        Ok(Written::Binary(b)) => b,
        Err(m) => return refused(entry, format!("{}: {m}", entry.spec)),
    };
    let mut facts = serde_json::Map::new();
    facts.insert("target".into(), target.name().into());
    facts.insert("bytes".into(), bytes.len().into());
    (
        FileResult::accepted(&entry.spec, facts),
        write.then_some(bytes),
    )
}

/// One shader translated, to standard output or one file.
fn single(args: Args, ui: &Ui) -> super::Result {
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
        super::io::check_output_path(out, &[std::path::Path::new(&args.shaders[0])])?;
    }
    let loaded = load_shader(ui, &args.shaders[0], &args.source, &args.input)?;
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
