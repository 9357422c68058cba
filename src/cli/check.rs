//! `ps30 check`: slots and executed instructions against the limits.

use super::args::{ConstantArgs, InputArgs, LimitArgs, SlotsArg, SourceArgs};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::Outcome;
use ps30::core::bytecode::{self, write::to_bytes};
use ps30::core::cost::{self, Profile, Verdict};
use ps30::core::load::{self, Loaded};
use ps30::present::check::{check_json, check_text, check_text_short};
use ps30::present::constants::{table_json, table_text};
use serde_json::Value;

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file (assembly or ps_3_0 bytecode), `-` for standard input, or a
    /// bundled name such as article:loop (`ps30 shaders` lists them).
    #[arg(value_name = "SHADER")]
    shader: String,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    constants: ConstantArgs,
    #[command(flatten)]
    limits: LimitArgs,
    /// The slot table the counts and the verdict use: Microsoft's count (what
    /// fxc and D3DDisassemble print) or the ps_3_0 documentation's
    /// per-instruction table. The other is shown beside it where they differ.
    #[arg(long, value_enum, value_name = "TABLE", default_value = "fxc")]
    slots: SlotsArg,
    #[command(flatten)]
    input: InputArgs,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    let loaded = load_shader(ui, &args.shader, &args.source, &args.input)?;
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let found = audit(ui, &loaded, &resolved.given(&[], &args.source), false)?;
    let env = resolved.environment();
    let profile = Profile {
        max_slots: args.limits.max_slots,
        max_executed: args.limits.max_executed,
        ..Profile::ps_3_0().counting(args.slots.into())
    };
    let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
    let name = &loaded.file.name;
    if args.json {
        let crc = crc32_of(&loaded, &args.source);
        let mut json = check_json(&loaded, &a, &found, crc);
        json.insert(
            "constant_table",
            loaded.constants.as_ref().map_or(Value::Null, table_json),
        );
        print_json(&json)?;
    } else if ui.quiet {
        say(ui, &check_text_short(name, &loaded.shader, &a))?;
    } else {
        let mut text = check_text(name, &loaded.shader, &a);
        if let Some(t) = &loaded.constants {
            text.push('\n');
            text.push_str(&table_text(t));
        }
        if loaded.file.is_compiled() {
            text.push_str(&format!(
                "(a compiled shader: lines are those of `ps30 disasm --annotated {name}`)\n"
            ));
        }
        say(ui, &text)?;
    }
    Ok(Outcome::from_ok(a.verdict == Verdict::Within))
}

/// The CRC-32 `check --json` names the shader by: of a compiled input's
/// bytes as given, or of the bytecode ps30 assembles from text (what
/// `ps30 asm` writes; none if the writer refuses what validated, which
/// `ps30 asm` would then report).
fn crc32_of(loaded: &Loaded, source: &SourceArgs) -> Option<u32> {
    if let Some(crc) = loaded.file.bytecode_crc32() {
        return Some(crc);
    }
    let (_, tokens) = load::assemble(loaded.file.clone(), &source.options()).ok()?;
    Some(bytecode::crc32(&to_bytes(&tokens)))
}
