//! What every subcommand does at its edges: reading a shader (a bundled
//! name, a file, or `-` for standard input; assembly text or ps_3_0
//! bytecode, recognised by content), printing to stdout (a closed pipe is
//! success), writing to stderr (a closed stderr is no reason to stop),
//! emitting diagnostics, and refusing an output path before any work.

use super::args::{InputArgs, SourceArgs};
use super::ui::Ui;
use super::BadInput;
use ps30::core::audit::{self, Finding, Given, Kind};
use ps30::core::diag::{Diagnostics, SourceFile};
use ps30::core::input;
use ps30::core::load::{self, Loaded, Options};
use ps30::jobs::bundled::{self, Named};
use ps30::jobs::luminance::ShaderSource;
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once stdout's reader has gone away: later output is dropped.
static STDOUT_GONE: AtomicBool = AtomicBool::new(false);

/// Writes to stdout. A reader that went away (`ps30 … | head`) is not an
/// error: there is nobody left to read the rest, so the rest is dropped and
/// the command goes on to the exit code its work earns — `ps30 check
/// OVER.psh | head -1` still exits 1 (a verdict is never lost to a closed
/// pipe; `$?` of a pipeline is the last command's, so `set -o pipefail`
/// shows it).
pub fn print(out: &str) -> std::io::Result<()> {
    print_bytes(out.as_bytes())
}

/// Writes bytes (bytecode) to stdout, a closed pipe dropping them as in
/// [`print`].
pub fn print_bytes(out: &[u8]) -> std::io::Result<()> {
    if STDOUT_GONE.load(Ordering::Relaxed) {
        return Ok(());
    }
    let mut stdout = std::io::stdout().lock();
    match stdout.write_all(out).and_then(|()| stdout.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            STDOUT_GONE.store(true, Ordering::Relaxed);
            Ok(())
        }
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

/// Prints a value as pretty JSON and a newline, streamed: the text is
/// written as it is made, never held whole (`check --json` of a long shader
/// is tens of megabytes). A closed pipe drops the rest as [`print`] does.
pub fn print_json(v: &impl serde::Serialize) -> Result<(), BadInput> {
    if STDOUT_GONE.load(Ordering::Relaxed) {
        return Ok(());
    }
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = serde_json::to_writer_pretty(&mut out, v)
        .map_err(std::io::Error::from)
        .and_then(|()| out.write_all(b"\n"))
        .and_then(|()| out.flush());
    match written {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            STDOUT_GONE.store(true, Ordering::Relaxed);
            Ok(())
        }
        other => Ok(other?),
    }
}

/// Diagnostics to stderr, compiler-style, coloured as `ui` says: identical
/// ones grouped, the first [`ps30::core::diag::MAX_SHOWN`] shown.
pub fn emit(ui: &Ui, diagnostics: &Diagnostics, file: &SourceFile) {
    eprint(&diagnostics.render_styled(file, ui.color_stderr));
}

/// What messages call standard input.
pub const STDIN_NAME: &str = "<stdin>";

/// The bytes of a shader argument, with the name messages use: a file, or
/// standard input for `-`, at most `max_bytes` long (`--max-input-bytes`): a
/// longer input (or `/dev/zero`) is refused after reading one byte past the
/// cap.
pub fn read_input(spec: &str, max_bytes: u64) -> Result<(String, Vec<u8>), BadInput> {
    let name = if spec == "-" { STDIN_NAME } else { spec };
    let bytes = if spec == "-" {
        input::read_capped(std::io::stdin().lock(), "shader", max_bytes)
            .map_err(|e| format!("{name}: {e}"))
    } else {
        input::read_file(Path::new(spec), "shader", max_bytes)
    }
    .map_err(BadInput)?;
    Ok((name.to_string(), bytes))
}

/// A shader argument, by the one rule of [`bundled::resolve`]: a bundled
/// name (`ps30 shaders` lists them), `-` (standard input) or a file (at most
/// `max_bytes` long), assembly text or ps_3_0 bytecode told apart by
/// content (see [`load::source_file`]: not UTF-8 is named by line and
/// column, a byte-order mark is dropped). A file that does not exist gets
/// the closest bundled name as a suggestion when there is one.
pub fn shader_file(spec: &str, options: &Options, max_bytes: u64) -> Result<SourceFile, BadInput> {
    let path = match bundled::resolve(spec) {
        Named::Bundled(b) => return Ok(SourceFile::new(b.path, b.text)),
        Named::File(path) => Path::new(path),
    };
    exists(spec, path)?;
    let (name, bytes) = read_input(spec, max_bytes)?;
    Ok(load::source_file(&name, bytes, options)?)
}

/// Bad input when a shader argument names no file (`-` always exists):
/// with the closest bundled name as a suggestion when there is one.
pub fn exists(spec: &str, path: &Path) -> Result<(), BadInput> {
    if spec == "-" || path.exists() {
        return Ok(());
    }
    let hint = match bundled::suggest(spec) {
        Some(name) => {
            format!("; did you mean `{name}`? (`ps30 shaders` lists the bundled shaders)")
        }
        None if spec.contains(':') => {
            "; no bundled shader has this name either (`ps30 shaders` lists them)".to_string()
        }
        None => String::new(),
    };
    Err(BadInput(format!("{spec}: no such file{hint}")))
}

/// A shader to run, as [`shader_file`] reads it.
pub fn shader_source(spec: &str, max_bytes: u64) -> Result<ShaderSource, BadInput> {
    Ok(ShaderSource::from_file(shader_file(
        spec,
        &Options::default(),
        max_bytes,
    )?))
}

/// Loads a shader argument (see [`shader_file`]) with the command's `-D`,
/// expansion cap and input cap: warnings to stderr; on errors every
/// diagnostic to stderr and a one-line summary as the error.
pub fn load_shader(
    ui: &Ui,
    spec: &str,
    source: &SourceArgs,
    input: &InputArgs,
) -> Result<Loaded, BadInput> {
    let options = source.options();
    let file = shader_file(spec, &options, input.max_input_bytes)?;
    match load::load(file, &options) {
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
