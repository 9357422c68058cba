//! `ps30 disasm`: a compiled shader as the listing Microsoft's
//! `D3DDisassemble` writes for it, byte for byte (`ps30 asm` reads it
//! back), or with `--annotated` as ps30's own listing, which keeps every
//! comment block and turns back into the same tokens, comments included.

use super::args::{InputArgs, SourceArgs};
use super::corpus::{self, refused, source_errors, CorpusArgs, Done, Outputs};
use super::io::{exists, print, print_json, read_input, source_error};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::bytecode::{self, listing::listing, microsoft, read::read, write::to_bytes};
use ps30::core::bytecode::{ItemKind, Module};
use ps30::core::diag::SourceError;
use ps30::core::load;
use ps30::core::ps1;
use ps30::jobs::corpus::{is_corpus, Entry, FileResult};
use ps30::present::disasm::{disasm_json, ps1_json};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: bytecode (ps_1_1 to ps_3_0, vs_2_0 to vs_3_0), or assembly (assembled first); `-` reads standard input.
    /// Several, or a directory (walked recursively for .psh, .asm, .dis, .fxo, .cso and
    /// .pso files): corpus mode, one line per file and a summary.
    #[arg(required = true, num_args = 1..)]
    files: Vec<String>,
    #[command(flatten)]
    corpus: CorpusArgs,
    /// Corpus mode: write each listing into this directory (created if missing), as its
    /// path below the argument it was found in, .dis appended to its name.
    #[arg(short, long, value_name = "DIR")]
    output: Option<PathBuf>,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    /// Print JSON (constant table, comment blocks, instructions with their offsets, both listings).
    #[arg(long)]
    json: bool,
    /// Print ps30's annotated listing instead of Microsoft's: comment blocks kept as
    /// `//#comment` token lines, constants spelled to parse back to the same bits.
    #[arg(long)]
    annotated: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if is_corpus(&args.files) {
        let outputs = args.output.as_deref().map(|dir| Outputs {
            dir,
            extension: "dis",
        });
        let write = outputs.is_some();
        return corpus::run(ui, &args.files, &args.corpus, args.json, outputs, |e| {
            disasm_one(&args, e, write)
        });
    }
    if args.output.is_some() {
        return Err(BadInput(
            "-o DIR is for several shaders or a directory; one listing goes to standard output"
                .into(),
        ));
    }
    let (name, module, len) = match module_of(&args, &args.files[0]) {
        Ok(m) => m,
        Err(Failed::Source(e)) => return Err(source_error(ui, &e)),
        Err(Failed::Bad(m)) => return Err(BadInput(m)),
    };
    match (&module, args.json) {
        (Listed::Stream(m), true) => print_json(&disasm_json(&name, m, len))?,
        (Listed::Ps1(p), true) => print_json(&ps1_json(&name, p, len))?,
        (_, false) => print(&text(&args, &module))?,
    }
    Ok(Outcome::Ok)
}

/// Why a shader has no listing.
enum Failed {
    /// It is assembly that does not assemble.
    Source(Box<SourceError>),
    /// It cannot be read, or is not bytecode ps30 reads.
    Bad(String),
}

/// A shader as read: a ps_2_0–ps_3_0 token stream, or a ps_1_x program
/// (another instruction set, `core::ps1`).
enum Listed {
    Stream(Module),
    Ps1(ps1::Program),
}

/// The listing the flags ask for (a ps_1_x program has one: Microsoft's,
/// which reads back).
fn text(args: &Args, module: &Listed) -> String {
    match module {
        Listed::Stream(m) if args.annotated => listing(m).text,
        Listed::Stream(m) => microsoft::listing(m),
        Listed::Ps1(p) => ps1::listing::listing(p),
    }
}

/// One file of a corpus disassembled (nothing printed): its size and
/// instruction count, and its listing when it is to be written.
fn disasm_one(args: &Args, entry: &Entry, write: bool) -> Done {
    match module_of(args, &entry.spec) {
        Ok((_, module, len)) => {
            let mut facts = serde_json::Map::new();
            facts.insert("bytes".into(), len.into());
            let instructions = match &module {
                Listed::Stream(m) => m
                    .items
                    .iter()
                    .filter(|i| matches!(i.kind, ItemKind::Instr(_)))
                    .count(),
                Listed::Ps1(p) => p.instrs.len(),
            };
            facts.insert("instructions".into(), instructions.into());
            (
                FileResult::accepted(&entry.spec, facts),
                write.then(|| text(args, &module).into_bytes()),
            )
        }
        Err(Failed::Source(e)) => (FileResult::refused(&entry.spec, source_errors(&e)), None),
        Err(Failed::Bad(m)) => refused(entry, m),
    }
}

/// A shader argument as a bytecode module: its name, the module, and the
/// bytecode's length.
fn module_of(args: &Args, spec: &str) -> Result<(String, Listed, usize), Failed> {
    let options = args.source.options();
    let bad = |BadInput(m)| Failed::Bad(m);
    let (name, mut bytes) = match ps30::jobs::bundled::listing(spec) {
        Some((name, text)) => (name.to_string(), text.as_bytes().to_vec()),
        None => {
            exists(spec, std::path::Path::new(spec)).map_err(bad)?;
            read_input(spec, args.input.max_input_bytes).map_err(bad)?
        }
    };
    if !bytecode::is_bytecode(&bytes) {
        // Assembly: what ps30 asm would write.
        let file =
            load::source_file(&name, bytes, &options).map_err(|e| Failed::Bad(e.to_string()))?;
        let (_, tokens) =
            load::assemble(file, &options).map_err(|e| Failed::Source(Box::new(e)))?;
        bytes = to_bytes(&tokens);
    }
    let bad = |error| {
        Failed::Bad(
            load::NotASource::Bytecode {
                name: name.clone(),
                error,
            }
            .to_string(),
        )
    };
    let module = if ps1::tokens::is_ps1(&bytes) {
        Listed::Ps1(ps1::tokens::decode(&bytes, options.max_expanded).map_err(bad)?)
    } else {
        Listed::Stream(read(&bytes, options.max_expanded).map_err(bad)?)
    };
    Ok((name, module, bytes.len()))
}
