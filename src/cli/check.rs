//! `ps30 check`: slots and executed instructions against the limits.

use super::args::{ConstantArgs, InputArgs, LimitArgs, SlotsArg, SourceArgs};
use super::corpus::{self, refused, CorpusArgs, Done};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::bytecode::{self, write::to_bytes};
use ps30::core::cost::{self, Profile, Verdict};
use ps30::core::load::{self, Loaded};
use ps30::jobs::corpus::{is_corpus, Entry, FileResult, Status};
use ps30::present::check::{check_json, check_text, check_text_short};
use ps30::present::constants::{table_json, table_text};
use serde_json::Value;

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file (assembly or bytecode), `-` for standard input, or a
    /// bundled name such as article:loop (`ps30 shaders` lists them). Several, or a
    /// directory (walked recursively for .psh, .asm, .dis, .fxo, .cso and .pso files):
    /// corpus mode, one line per file and a summary.
    #[arg(value_name = "SHADER", required = true, num_args = 1..)]
    shaders: Vec<String>,
    #[command(flatten)]
    corpus: CorpusArgs,
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
    if is_corpus(&args.shaders) {
        return corpus::run(ui, &args.shaders, &args.corpus, args.json, None, |e| {
            check_one(&args, e)
        });
    }
    let loaded = load_shader(ui, &args.shaders[0], &args.source, &args.input)?;
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let found = audit(ui, &loaded, &resolved.given(&[], &args.source), false)?;
    let env = resolved.environment();
    let profile = profile(&args);
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

/// The limits and slot table of the command line.
fn profile(args: &Args) -> Profile {
    Profile {
        max_slots: args.limits.max_slots,
        max_executed: args.limits.max_executed,
        ps2x_caps: args.source.caps,
        ..Profile::ps_3_0().counting(args.slots.into())
    }
}

/// One file of a corpus: loaded, counted, and held against the limits
/// (nothing printed; the constants given apply to every file).
fn check_one(args: &Args, entry: &Entry) -> Done {
    let options = args.source.options();
    let loaded = match corpus::load_entry(entry, &options, args.input.max_input_bytes) {
        Ok(l) => l,
        Err(done) => return *done,
    };
    let analysis = args
        .constants
        .resolve(loaded.constants.as_ref())
        .map_err(|BadInput(m)| m)
        .and_then(|r| {
            let env = r.environment();
            cost::analyse(&loaded.shader, &loaded.file, &env, &profile(args))
                .map_err(|e| e.to_string())
        });
    let a = match analysis {
        Ok(a) => a,
        Err(m) => return refused(entry, format!("{}: {m}", entry.spec)),
    };
    let mut facts = serde_json::Map::new();
    facts.insert("slots".into(), a.slots.into());
    facts.insert(
        "executed".into(),
        serde_json::json!({"min": a.executed.min, "max": a.executed.max}),
    );
    let mut r = FileResult::accepted(&entry.spec, facts);
    if a.verdict != Verdict::Within {
        r.status = Status::Over;
        if a.slots > a.profile.max_slots {
            r.over.push("slots".into());
        }
        if a.executed.max > a.profile.max_executed {
            r.over.push("executed".into());
        }
    }
    (r, None)
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
