//! `ps30 plan`: block sizes, intermediate targets and pass-2 forms for a
//! frame, ranked, with a recommendation.

use super::args::{parse_delta, parse_size, ProfileArgs};
use super::io::{print, print_json};
use super::ui::Ui;
use super::Outcome;
use ps30::jobs::gen::plan::plan_with_range;
use ps30::present::plan::{plan_json, plan_text};

#[derive(clap::Args)]
pub struct Args {
    /// Frame size WxH.
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    frame: (u32, u32),
    /// The δ of log(δ + L), for the padding and f16 figures.
    #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    /// The range [2^-MIN, 2^MAX] of the mip-chain alternative's 8-bit
    /// log-luminance encoding, as MIN,MAX (stops below and above 1).
    #[arg(long, value_name = "MIN,MAX", value_parser = parse_log_range, default_value = "8,8")]
    log_range: (f64, f64),
    #[command(flatten)]
    profile: ProfileArgs,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// `MIN,MAX`: two finite numbers of stops with a positive sum, each at most 126.
fn parse_log_range(s: &str) -> Result<(f64, f64), String> {
    let (a, b) = s
        .split_once(',')
        .ok_or("expected MIN,MAX, e.g. 8,8 for [2^-8, 2^8]")?;
    let parse = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite() && x.abs() <= 126.0)
            .ok_or_else(|| format!("`{v}` is not a number of stops from -126 to 126"))
    };
    let (min, max) = (parse(a)?, parse(b)?);
    if min + max <= 0.0 {
        return Err(format!("[2^-{min}, 2^{max}] is empty"));
    }
    Ok((min, max))
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    let plan = plan_with_range(
        args.frame,
        &args.profile.profile(),
        args.delta as f64,
        args.log_range,
    )?;
    if args.json {
        print_json(&plan_json(&plan))?;
    } else {
        print(&plan_text(&plan))?;
    }
    Ok(Outcome::from_ok(plan.recommended.is_some()))
}
