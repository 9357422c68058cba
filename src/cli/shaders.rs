//! `ps30 shaders`: the shaders bundled in the binary, by the names every
//! command accepts, or the text of one of them.

use super::io::{print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::jobs::bundled;

#[derive(clap::Args)]
pub struct Args {
    /// Print this bundled shader's assembly (e.g. article:loop) instead of the list.
    #[arg(value_name = "NAME")]
    name: Option<String>,
    /// Print JSON (name, path, summary and, with NAME, the text) instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, _ui: &Ui) -> super::Result {
    let Some(name) = &args.name else {
        if args.json {
            print_json(&ps30::present::shaders::list_json())?;
        } else {
            print(&ps30::present::shaders::list_text())?;
        }
        return Ok(Outcome::Ok);
    };
    let Some(b) = bundled::find(name) else {
        let hint = bundled::suggest(name)
            .map(|n| format!("; did you mean `{n}`?"))
            .unwrap_or_default();
        return Err(BadInput(format!(
            "no bundled shader is called `{name}`{hint} (`ps30 shaders` lists them)"
        )));
    };
    if args.json {
        print_json(&ps30::present::shaders::shader_json(&b))?;
    } else {
        print(b.text)?;
    }
    Ok(Outcome::Ok)
}
