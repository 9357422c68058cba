//! What every subcommand does at its edges: reading a shader (a bundled name
//! or a file), printing to stdout (a closed pipe is success), writing to
//! stderr (a closed stderr is no reason to stop), emitting diagnostics, and
//! refusing an output path before any work.

use super::ui::Ui;
use super::BadInput;
use ps30::core::audit::{self, Finding, Given, Kind};
use ps30::core::diag::{Diagnostics, SourceFile};
use ps30::core::load::{self, Loaded, Options};
use ps30::jobs::bundled::{self, Named};
use ps30::jobs::luminance::ShaderSource;
use std::io::Write;
use std::path::Path;

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

/// Writes to stderr, ignoring failure: when stderr is closed or full
/// (`ps30 … 2>&1 | head`), messages have nowhere to go, and the command still
/// ends with the exit code its work earned. The only way the binary writes
/// to stderr (`eprintln!` would panic on a closed stream).
pub fn eprint(text: &str) {
    let mut stderr = std::io::stderr().lock();
    let _ = stderr
        .write_all(text.as_bytes())
        .and_then(|()| stderr.flush());
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

/// Diagnostics to stderr, compiler-style, coloured as `ui` says: identical
/// ones grouped, the first [`ps30::core::diag::MAX_SHOWN`] shown.
pub fn emit(ui: &Ui, diagnostics: &Diagnostics, file: &SourceFile) {
    eprint(&diagnostics.render_styled(file, ui.color_stderr));
}

/// A file's text, at most `max_bytes` long (`--max-input-bytes`): a longer
/// file (or `/dev/zero`) is refused after reading one byte past the cap.
/// Not UTF-8 is bad input naming the line and column of the first bad
/// byte; a UTF-8 byte-order mark at the start is dropped (see
/// [`SourceFile::new`]).
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
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let before = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
        BadInput(format!(
            "{}:{line}:{column}: not UTF-8 text (byte 0x{:02X} at offset {at} starts no UTF-8 character); save the file as UTF-8",
            path.display(),
            bytes[at]
        ))
    })
}

/// A shader argument, by the one rule of [`bundled::resolve`]: a bundled
/// name (`ps30 shaders` lists them) or a file (at most `max_bytes` long). A
/// file that does not exist gets the closest bundled name as a suggestion
/// when there is one.
pub fn shader_source(spec: &str, max_bytes: u64) -> Result<ShaderSource, BadInput> {
    let path = match bundled::resolve(spec) {
        Named::Bundled(b) => return Ok(ShaderSource::new(b.path, b.text)),
        Named::File(path) => Path::new(path),
    };
    if !path.exists() {
        let hint = match bundled::suggest(spec) {
            Some(name) => {
                format!("; did you mean `{name}`? (`ps30 shaders` lists the bundled shaders)")
            }
            None if spec.contains(':') => {
                "; no bundled shader has this name either (`ps30 shaders` lists them)".to_string()
            }
            None => String::new(),
        };
        return Err(BadInput(format!("{spec}: no such file{hint}")));
    }
    let text = read_text(path, max_bytes)?;
    Ok(ShaderSource::new(spec, text))
}

/// Loads a shader argument (bundled name or file): warnings to stderr; on
/// errors every diagnostic to stderr and a one-line summary as the error.
pub fn load_shader(
    ui: &Ui,
    spec: &str,
    options: &Options,
    max_bytes: u64,
) -> Result<Loaded, BadInput> {
    let src = shader_source(spec, max_bytes)?;
    let file = SourceFile::new(src.name, src.text);
    match load::load(file, options) {
        Ok(l) => {
            if !ui.quiet {
                emit(ui, &l.warnings, &l.file);
            }
            Ok(l)
        }
        Err(e) => Err(source_error(ui, &e)),
    }
}

/// A shader that did not load: its diagnostics to stderr, and the summary
/// line `main` prints after them.
pub fn source_error(ui: &Ui, e: &ps30::core::diag::SourceError) -> BadInput {
    emit(ui, &e.diagnostics, &e.file);
    let n = e.diagnostics.errors().count();
    BadInput(format!(
        "{}: {}",
        e.file.name,
        ps30::core::numbers::plural(n as u64, "error", "errors")
    ))
}

/// The constants given to a shader held against what it reads and defines
/// (see [`ps30::core::audit`]): warnings to stderr (unless quiet), and, when
/// the shader is about to `run`, bad input if it reads a register nobody
/// set — nothing runs on zeros nobody chose. A command that only counts
/// (`check`) passes `run = false`: its counts already give the range an
/// unset loop count allows.
pub fn audit(ui: &Ui, loaded: &Loaded, given: &Given, run: bool) -> Result<Vec<Finding>, BadInput> {
    let found: Vec<Finding> = audit::audit(&loaded.shader, &loaded.defines_used, given)
        .into_iter()
        .filter(|f| run || f.kind != Kind::Unset)
        .collect();
    if !ui.quiet {
        for f in found.iter().filter(|f| f.kind != Kind::Unset) {
            eprint(&render_finding(ui, &loaded.file, f));
        }
    }
    let Some(error) = audit::unset_diagnostic(&found) else {
        return Ok(found);
    };
    eprint(&error.render_styled(&loaded.file, ui.color_stderr));
    let unset = audit::unset_names(&found);
    Err(BadInput(format!(
        "{}: reads {} that nothing sets; nothing was run",
        loaded.file.name,
        ps30::core::numbers::list(&unset)
    )))
}

/// An audit finding as text: compiler-style where the shader mentions the
/// register, one line and its help where it does not.
fn render_finding(ui: &Ui, file: &SourceFile, f: &Finding) -> String {
    match f.span {
        Some(_) => f.diagnostic().render_styled(file, ui.color_stderr),
        None => format!("warning: {}\n  = help: {}\n", f.message(), f.help()),
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

/// [`check_output_path`] for an image, whose extension must also name a
/// format ps30 writes (see [`ps30::core::image::OutputFormat`]).
pub fn check_image_output(path: &Path, inputs: &[&Path]) -> Result<(), BadInput> {
    ps30::core::image::OutputFormat::of(path)?;
    check_output_path(path, inputs)
}
