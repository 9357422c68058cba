//! What every subcommand does at its edges: reading a shader (a file or a
//! bundled name), printing to stdout (a closed pipe is success), emitting
//! diagnostics, and refusing an output path before any work.

use super::ui::Ui;
use super::BadInput;
use ps30::core::diag::SourceFile;
use ps30::core::load::{self, Loaded, Options};
use ps30::jobs::luminance::ShaderSource;
use std::io::{IsTerminal, Write};
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
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(out.as_bytes())
        .and_then(|()| stdout.flush())
    {
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

/// A file's text, at most `max_bytes` long (`--max-input-bytes`): a longer
/// file (or `/dev/zero`) is refused after reading one byte past the cap.
/// Not UTF-8 is bad input, with the offset of the first bad byte.
pub fn read_text(path: &Path, max_bytes: u64) -> Result<String, BadInput> {
    use std::io::Read;
    let failed = |e: std::io::Error| BadInput(format!("{}: {e}", path.display()));
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(max_bytes.saturating_add(1)).read_to_end(&mut bytes))
        .map_err(failed)?;
    if bytes.len() as u64 > max_bytes {
        return Err(BadInput(format!(
            "{}: larger than the cap of {} bytes for a shader (raise it with --max-input-bytes)",
            path.display(),
            ps30::core::numbers::thousands(max_bytes)
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        BadInput(format!(
            "{}: not UTF-8 text (invalid byte at offset {})",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
    })
}

/// A shader by bundled name or file path (at most `max_bytes` long).
pub fn shader_source(spec: &str, max_bytes: u64) -> Result<ShaderSource, BadInput> {
    if let Some((name, text)) = ps30::jobs::bundled::listing(spec) {
        return Ok(ShaderSource::new(name, text));
    }
    let text = read_text(Path::new(spec), max_bytes)?;
    Ok(ShaderSource::new(spec, text))
}

/// Loads a shader file: warnings to stderr; on errors every diagnostic to
/// stderr and a one-line summary as the error.
pub fn load_file(path: &Path, options: &Options, max_bytes: u64) -> Result<Loaded, BadInput> {
    let text = read_text(path, max_bytes)?;
    let file = SourceFile::new(path.display().to_string(), text);
    match load::load(file, options) {
        Ok(l) => {
            l.warnings.emit(&l.file, color_stderr());
            Ok(l)
        }
        Err(e) => {
            e.diagnostics.emit(&e.file, color_stderr());
            let n = e.diagnostics.errors().count();
            Err(BadInput(format!(
                "{}: {n} error{}",
                e.file.name,
                if n == 1 { "" } else { "s" }
            )))
        }
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
