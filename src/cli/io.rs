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
/// standard input for `-`.
pub fn read_input(spec: &str) -> Result<(String, Vec<u8>), BadInput> {
    if spec == "-" {
        let mut bytes = Vec::new();
        std::io::stdin()
            .lock()
            .read_to_end(&mut bytes)
            .map_err(|e| BadInput(format!("{STDIN_NAME}: {e}")))?;
        return Ok((STDIN_NAME.to_string(), bytes));
    }
    let bytes = std::fs::read(spec).map_err(|e| BadInput(format!("{spec}: {e}")))?;
    Ok((spec.to_string(), bytes))
}

/// A shader by bundled name, file path or `-` (standard input): assembly
/// text or ps_3_0 bytecode, told apart by content, not by name.
pub fn shader_file(spec: &str, options: &Options) -> Result<SourceFile, BadInput> {
    if let Some((name, text)) = ps30::jobs::bundled::listing(spec) {
        return Ok(SourceFile::new(name, text));
    }
    let (name, bytes) = read_input(spec)?;
    Ok(load::source_file(&name, bytes, options)?)
}

/// A shader to run, as [`shader_file`] reads it.
pub fn shader_source(spec: &str) -> Result<ShaderSource, BadInput> {
    Ok(ShaderSource::from_file(shader_file(
        spec,
        &Options::default(),
    )?))
}

/// Prints a source error's diagnostics to stderr; the error is a one-line
/// count (the diagnostics say the rest).
pub fn report(e: &SourceError) -> BadInput {
    for d in &e.diagnostics.items {
        d.emit(&e.file, color_stderr());
    }
    let n = e.diagnostics.errors().count();
    BadInput(format!(
        "{}: {n} error{}",
        e.file.name,
        if n == 1 { "" } else { "s" }
    ))
}

/// Loads a shader (see [`shader_file`]): warnings to stderr; on errors every
/// diagnostic to stderr and a one-line summary as the error.
pub fn load_file(spec: &str, options: &Options) -> Result<Loaded, BadInput> {
    let file = shader_file(spec, options)?;
    match load::load(file, options) {
        Ok(l) => {
            for w in &l.warnings.items {
                w.emit(&l.file, color_stderr());
            }
            Ok(l)
        }
        Err(e) => Err(report(&e)),
    }
}

/// Refuses an output path whose directory does not exist, before any work.
pub fn check_output_path(path: &Path) -> Result<(), BadInput> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !dir.is_dir() {
        return Err(BadInput(format!(
            "{}: the directory {} does not exist",
            path.display(),
            dir.display()
        )));
    }
    if path.is_dir() {
        return Err(BadInput(format!("{}: is a directory", path.display())));
    }
    Ok(())
}
