//! `ps30 run VS --vertices FILE`: a vertex shader over a vertex list.

use super::super::args::{given_with, read_inputs, with_inputs};
use super::super::io::{audit, load_shader, print_json, say};
use super::super::ui::Ui;
use super::super::{BadInput, Outcome};
use super::Args;
use ps30::core::emu::vertex;
use ps30::core::output;
use ps30::jobs::vertices;
use ps30::present::vertices as present;
use std::path::Path;

pub(super) fn run(args: &Args, path: &Path, ui: &Ui) -> super::super::Result {
    if let Some(file) = &args.output {
        output::check(file, &[path, Path::new(&args.shader)]).map_err(BadInput)?;
    }
    let list = vertices::read(path).map_err(BadInput)?;
    let loaded = load_shader(ui, &args.shader, &args.source, &args.input)?;
    let profile = loaded.shader.program().profile;
    if !vertex::runs(profile) {
        return Err(BadInput(format!(
            "{}: a {profile} shader; --vertices runs vertex shaders (vs_2_0, vs_2_x, vs_3_0)",
            args.shader
        )));
    }
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let inputs = read_inputs(args.inputs.as_deref())?;
    // as the pixel path does: nothing runs on constants nobody set
    audit(
        ui,
        &loaded,
        &given_with(&resolved, &args.source, &inputs),
        true,
    )?;
    let (constants, textures) = with_inputs(&resolved, inputs);
    let backend = args.draw.open()?;
    let out = vertices::run_on(
        &backend,
        &loaded.shader,
        &loaded.file,
        constants,
        &textures,
        &list,
        args.draw.rules(),
        args.exec.limits().max_executed_per_pixel,
    )
    .map_err(|e| BadInput(format!("{}: {e}", args.shader)))?;
    if let Some(file) = &args.output {
        let text = serde_json::to_string_pretty(&vertices::outputs_json(&out)).unwrap_or_default();
        output::write_bytes(file, format!("{text}\n").as_bytes())
            .map_err(|e| BadInput(format!("{}: {e}", file.display())))?;
    }
    let name = args.shader.as_str();
    if args.exec.json {
        print_json(&present::json(name, profile.name(), &out))?;
    } else {
        say(ui, &present::text(name, profile.name(), &out))?;
    }
    Ok(Outcome::from_ok(true))
}
