//! The `ps30` binary: parses the command line and dispatches to one module
//! of [`cli`] per subcommand (exit codes are documented there).

// The binary writes only through `cli::io` (a closed stream is never a
// panic): no print macros.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod cli;

use clap::Parser;
use cli::{ui::Ui, BadInput, Cli, Command, Outcome};
use std::process::ExitCode;

fn main() -> ExitCode {
    ps30::core::phases::mark("start");
    let parsed = match Cli::try_parse() {
        Ok(parsed) => parsed,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    cli::clean_up_on_interrupt();
    let ui = Ui::new(parsed.quiet, parsed.color);
    let outcome = match parsed.command {
        Command::Asm(args) => cli::asm::run(args, &ui),
        Command::Check(args) => cli::check::run(args, &ui),
        Command::Disasm(args) => cli::disasm::run(args, &ui),
        Command::Decompile(args) => cli::decompile::run(args, &ui),
        Command::Expand(args) => cli::expand::run(args, &ui),
        Command::Run(args) => cli::run::run(args, &ui),
        Command::Luminance(args) => cli::luminance::run(args, &ui),
        Command::Tonemap(args) => cli::tonemap::run(args, &ui),
        Command::Compare(args) => cli::compare::run(args, &ui),
        Command::Translate(args) => cli::translate::run(args, &ui),
        Command::Profile(args) => cli::profile::run(args, &ui),
        Command::Shaders(args) => cli::shaders::run(args, &ui),
        Command::ShaderTest(args) => cli::shader_test::run(args, &ui),
        Command::Render(args) => cli::render::run(args, &ui),
        Command::Study(args) => cli::study::run(args, &ui),
        Command::Verify(args) => cli::verify::run(args, &ui),
        Command::Unroll(args) => cli::unroll::run(args, &ui),
        Command::Plan(args) => cli::plan::run(args, &ui),
        Command::Completions(args) => cli::completions::run(args, &ui),
        Command::Man(args) => cli::man::run(args, &ui),
    };
    ps30::core::phases::mark("command done");
    let code = match outcome {
        Ok(Outcome::Ok) => 0,
        Ok(Outcome::Problem) => 1,
        Ok(Outcome::Refused) => 2,
        Ok(Outcome::Unavailable) => 3,
        Err(BadInput(msg)) => {
            cli::io::eprint(&format!("error: {msg}\n"));
            2
        }
    };
    // Every write above was flushed as it was made (`cli::io`).
    ps30::core::gpu::hand_off_at_exit(code);
    ExitCode::from(code)
}
