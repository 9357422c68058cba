//! `ps30 check`: slots and executed instructions against the limits.

use super::args::{ConstantArgs, InputArgs, LimitArgs, SourceArgs};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::Outcome;
use ps30::core::cost::{self, Profile, Verdict};
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
        ..Profile::ps_3_0()
    };
    let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
    let name = &loaded.file.name;
    if args.json {
        let mut json = check_json(&loaded, &a, &found);
        json["constant_table"] = loaded.constants.as_ref().map_or(Value::Null, table_json);
        print_json(&json)?;
    } else if ui.quiet {
        say(ui, &check_text_short(name, &a))?;
    } else {
        let mut text = check_text(name, &a);
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
