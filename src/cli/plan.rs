//! `ps30 plan`: block sizes, intermediate targets and pass-2 forms for a
//! frame, ranked, with a recommendation.

use super::args::{parse_delta, parse_size, ProfileArgs};
use super::io::{print, print_json};
use super::ui::Ui;
use super::Outcome;
use ps30::jobs::gen::plan::plan;
use ps30::present::plan::{plan_json, plan_text};

#[derive(clap::Args)]
pub struct Args {
    /// Frame size WxH.
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    frame: (u32, u32),
    /// The δ of log(δ + L), for the padding and f16 figures.
    #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    #[command(flatten)]
    profile: ProfileArgs,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    let plan = plan(args.frame, &args.profile.profile(), args.delta as f64)?;
    if args.json {
        print_json(&plan_json(&plan))?;
    } else {
        print(&plan_text(&plan))?;
    }
    Ok(Outcome::from_ok(plan.recommended.is_some()))
}
