//! `ps30 man [COMMAND]`: the manual page (roff) generated from the clap
//! definitions — ps30(1), or ps30-COMMAND(1) for one subcommand.

use super::io::print;
use super::ui::Ui;
use super::{BadInput, Outcome};
use clap::CommandFactory;

#[derive(clap::Args)]
pub struct Args {
    /// A subcommand whose page to print (default: the page of ps30 itself).
    #[arg(value_name = "COMMAND")]
    command: Option<String>,
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    let top = super::Cli::command();
    let page = match &args.command {
        None => top,
        Some(name) => {
            let sub = top
                .find_subcommand(name)
                .ok_or_else(|| {
                    let names: Vec<&str> = top.get_subcommands().map(|c| c.get_name()).collect();
                    BadInput(format!(
                        "no subcommand `{name}` (there are {})",
                        ps30::core::numbers::list(&names)
                    ))
                })?
                .clone();
            let full = format!("ps30-{}", sub.get_name());
            sub.name(full)
        }
    };
    let mut roff = Vec::new();
    clap_mangen::Man::new(page).render(&mut roff)?;
    print(&String::from_utf8_lossy(&roff))?;
    Ok(Outcome::Ok)
}
