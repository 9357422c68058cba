//! `ps30 completions SHELL`: a shell-completion script generated from the
//! clap definitions, so it always matches the binary that printed it.

use super::io::print;
use super::ui::Ui;
use super::Outcome;
use clap::CommandFactory;

#[derive(clap::Args)]
pub struct Args {
    /// The shell to complete for.
    #[arg(value_enum, value_name = "SHELL")]
    shell: clap_complete::Shell,
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    let mut command = super::Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut command, "ps30", &mut script);
    print(&String::from_utf8_lossy(&script))?;
    Ok(Outcome::Ok)
}
