//! `ps30 check`: slots and executed instructions against the limits.

use super::args::{ConstantArgs, InputArgs, LimitArgs, SourceArgs};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::Outcome;
use ps30::core::cost::{self, Profile, Verdict};
use ps30::present::check::{check_json, check_text, check_text_short};

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file, or a bundled name such as article:loop (`ps30 shaders` lists them).
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
    let loaded = load_shader(
        ui,
        &args.shader,
        &args.source.options(),
        args.input.max_input_bytes,
    )?;
    let given = args.constants.given(&[], &args.source);
    let found = audit(ui, &loaded, &given, false)?;
    let env = args.constants.environment();
    let profile = Profile {
        max_slots: args.limits.max_slots,
        max_executed: args.limits.max_executed,
        ..Profile::ps_3_0()
    };
    let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
    if args.json {
        print_json(&check_json(&loaded, &a, &found))?;
    } else if ui.quiet {
        say(ui, &check_text_short(&loaded.file.name, &a))?;
    } else {
        say(ui, &check_text(&loaded.file.name, &a))?;
    }
    Ok(Outcome::from_ok(a.verdict == Verdict::Within))
}
