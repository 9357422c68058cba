//! `ps30 disasm`: a compiled shader as the listing Microsoft's
//! `D3DDisassemble` writes for it, byte for byte (`ps30 asm` reads it
//! back), or with `--annotated` as ps30's own listing, which keeps every
//! comment block and turns back into the same tokens, comments included.

use super::args::{InputArgs, SourceArgs};
use super::io::{exists, print, print_json, read_input, source_error};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::bytecode::{self, listing::listing, microsoft, read::read, write::to_bytes};
use ps30::core::load;
use ps30::present::disasm::disasm_json;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: ps_3_0 bytecode, or assembly (assembled first); `-` reads standard input.
    file: String,
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
    let options = args.source.options();
    let (name, mut bytes) = match ps30::jobs::bundled::listing(&args.file) {
        Some((name, text)) => (name.to_string(), text.as_bytes().to_vec()),
        None => {
            exists(&args.file, std::path::Path::new(&args.file))?;
            read_input(&args.file, args.input.max_input_bytes)?
        }
    };
    if !bytecode::is_bytecode(&bytes) {
        // Assembly: what ps30 asm would write.
        let file = load::source_file(&name, bytes, &options)?;
        let (_, tokens) = load::assemble(file, &options).map_err(|e| source_error(ui, &e))?;
        bytes = to_bytes(&tokens);
    }
    let module = read(&bytes, options.max_expanded).map_err(|error| {
        BadInput(
            load::NotASource::Bytecode {
                name: name.clone(),
                error,
            }
            .to_string(),
        )
    })?;
    if args.json {
        print_json(&disasm_json(&name, &module, bytes.len()))?;
    } else if args.annotated {
        print(&listing(&module).text)?;
    } else {
        print(&microsoft::listing(&module))?;
    }
    Ok(Outcome::Ok)
}
