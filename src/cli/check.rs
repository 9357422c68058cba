//! `ps30 check`: slots and executed instructions against the limits.

use super::args::{ConstantArgs, InputArgs, LimitArgs, Resolved, SourceArgs};
use super::io::{load_file, print_json, say};
use super::ui::Ui;
use super::Outcome;
use ps30::core::cost::{self, Environment, Profile, Verdict};
use ps30::present::check::{check_json, check_text};
use ps30::present::constants::{table_json, table_text};
use serde_json::Value;

#[derive(clap::Args)]
pub struct Args {
    /// Shader: assembly or ps_3_0 bytecode (`-` reads standard input).
    file: String,
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
    let loaded = load_file(
        &args.file,
        &args.source.options(),
        args.input.max_input_bytes,
    )?;
    let given = Resolved::new(
        &[],
        &args.constants.ints,
        &args.constants.bools,
        loaded.constants.as_ref(),
    )?;
    let env = Environment {
        ints: given.ints.into_iter().collect(),
        bools: given.bools.into_iter().collect(),
    };
    for r in env.ints.keys() {
        if !ui.quiet && loaded.shader.program().int_def(*r).is_some() {
            eprintln!("note: i{r} is defined in the shader (defi), which overrides --int i{r}");
        }
    }
    let profile = Profile {
        max_slots: args.limits.max_slots,
        max_executed: args.limits.max_executed,
        ..Profile::ps_3_0()
    };
    let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
    let name = loaded.file.name.clone();
    if args.json {
        let warnings: Vec<String> = loaded
            .warnings
            .items
            .iter()
            .map(|w| w.to_string())
            .collect();
        let mut json = check_json(&name, &a, &warnings);
        json["constant_table"] = loaded.constants.as_ref().map_or(Value::Null, table_json);
        print_json(&json)?;
    } else {
        let mut text = check_text(&name, &a);
        if let Some(t) = &loaded.constants {
            text.push('\n');
            text.push_str(&table_text(t));
        }
        if loaded.file.is_compiled() {
            text.push_str(&format!(
                "(a compiled shader: lines are those of `ps30 disasm {name}`)\n"
            ));
        }
        say(ui, &text)?;
    }
    Ok(Outcome::from_ok(a.verdict == Verdict::Within))
}
