//! What every subcommand does at its edges: reading a shader (a file, `-`
//! for standard input, or a bundled name; assembly text or ps_3_0 bytecode,
//! recognised by content), printing to stdout (a closed pipe is success),
//! emitting diagnostics, and refusing an output path before any work.

use super::ui::Ui;
use super::BadInput;
use ps30::core::diag::{SourceError, SourceFile};
use ps30::core::load::{self, Loaded, Options};
use ps30::jobs::luminance::ShaderSource;
use std::io::{IsTerminal, Read, Write};
use std::path::Path;

/// Whether diagnostics on stderr take colour: a terminal, and `NO_COLOR`
/// unset or empty (no-color.org).
pub fn color_stderr() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()) && std::io::stderr().is_terminal()
}

/// Writes to stdout. A reader that went away (`ps30 … | head`) is not an
/// error: there is nobody left to tell anything, so the command ends with
/// success, as a Unix filter does (every file it writes was written
/// atomically before it printed).
pub fn print(out: &str) -> std::io::Result<()> {
    print_bytes(out.as_bytes())
}

/// Writes bytes (bytecode) to stdout, a closed pipe being success as in
/// [`print`].
pub fn print_bytes(out: &[u8]) -> std::io::Result<()> {
    let mut stdout = std::io::stdout().lock();
    match stdout.write_all(out).and_then(|()| stdout.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        other => other,
    }
}

/// Prints human-readable text, its status words coloured when stdout
/// takes colour (JSON and assembly go through [`print`] untouched).
pub fn say(ui: &Ui, out: &str) -> std::io::Result<()> {
    print(&ui.highlight(out))
}

/// Prints a value as pretty JSON and a newline.
pub fn print_json(v: &impl serde::Serialize) -> Result<(), BadInput> {
    print(&(serde_json::to_string_pretty(v)? + "\n"))?;
    Ok(())
}

/// What messages call standard input.
pub const STDIN_NAME: &str = "<stdin>";

/// The bytes of a shader argument, with the name messages use: a file, or
/// standard input for `-`, at most `max_bytes` long (`--max-input-bytes`): a
/// longer input (or `/dev/zero`) is refused after reading one byte past the
/// cap.
pub fn read_input(spec: &str, max_bytes: u64) -> Result<(String, Vec<u8>), BadInput> {
    let name = if spec == "-" { STDIN_NAME } else { spec };
    let failed = |e: std::io::Error| BadInput(format!("{name}: {e}"));
    let mut bytes = Vec::new();
    let cap = max_bytes.saturating_add(1);
    if spec == "-" {
        std::io::stdin().lock().take(cap).read_to_end(&mut bytes)
    } else {
        std::fs::File::open(spec).and_then(|f| f.take(cap).read_to_end(&mut bytes))
    }
    .map_err(failed)?;
    if bytes.len() as u64 > max_bytes {
        return Err(BadInput(format!(
            "{name}: larger than the cap of {} bytes for a shader (raise it with --max-input-bytes)",
            ps30::core::numbers::thousands(max_bytes)
        )));
    }
    Ok((name.to_string(), bytes))
}

/// A shader by bundled name, file path or `-` (standard input): assembly
/// text or ps_3_0 bytecode, told apart by content, not by name.
pub fn shader_file(spec: &str, options: &Options, max_bytes: u64) -> Result<SourceFile, BadInput> {
    if let Some((name, text)) = ps30::jobs::bundled::listing(spec) {
        return Ok(SourceFile::new(name, text));
    }
    let (name, bytes) = read_input(spec, max_bytes)?;
    Ok(load::source_file(&name, bytes, options)?)
}

/// A shader to run, as [`shader_file`] reads it.
pub fn shader_source(spec: &str, max_bytes: u64) -> Result<ShaderSource, BadInput> {
    Ok(ShaderSource::from_file(shader_file(
        spec,
        &Options::default(),
        max_bytes,
    )?))
}

/// Prints a source error's diagnostics to stderr; the error is a one-line
/// count (the diagnostics say the rest).
pub fn report(e: &SourceError) -> BadInput {
    e.diagnostics.emit(&e.file, color_stderr());
    let n = e.diagnostics.errors().count();
    BadInput(format!(
        "{}: {n} error{}",
        e.file.name,
        if n == 1 { "" } else { "s" }
    ))
}

/// Loads a shader (see [`shader_file`]): warnings to stderr; on errors every
/// diagnostic to stderr and a one-line summary as the error.
pub fn load_file(spec: &str, options: &Options, max_bytes: u64) -> Result<Loaded, BadInput> {
    let file = shader_file(spec, options, max_bytes)?;
    match load::load(file, options) {
        Ok(l) => {
            l.warnings.emit(&l.file, color_stderr());
            Ok(l)
        }
        Err(e) => Err(report(&e)),
    }
}

/// Refuses an output file before any work, by the rules of
/// [`ps30::core::output`] (one of them: it is not one of `inputs`).
pub fn check_output_path(path: &Path, inputs: &[&Path]) -> Result<(), BadInput> {
    ps30::core::output::check(path, inputs).map_err(BadInput)
}

/// Refuses an output directory before any work, by the same rules.
pub fn check_output_dir(dir: &Path) -> Result<(), BadInput> {
    ps30::core::output::check_directory(dir).map_err(BadInput)
}
