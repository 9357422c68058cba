//! The `ps30` command line: a thin layer over the library.
//!
//! Exit codes: 0 ok; 1 the check found a problem (a limit exceeded, a claim
//! or cross-check that disagrees); 2 bad input or usage. A closed stdout
//! (e.g. piping into `head`) counts as success.

use clap::{Args, Parser, Subcommand};
use ps30::args::{
    parse_bool_const, parse_define, parse_float4, parse_float_const, parse_int_const, parse_size,
};
use ps30::cost::{self, Environment, Profile, Verdict};
use ps30::diag::SourceFile;
use ps30::front::{self, Options};
use ps30::report;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;

mod ui;
use ui::Ui;

#[derive(Parser)]
#[command(
    name = "ps30",
    version,
    about = "Parse, measure, run and generate Direct3D 9 ps_3_0 assembly"
)]
struct Cli {
    /// Print only results and problems: no progress bars, notes or "wrote …" lines.
    #[arg(long, short, global = true)]
    quiet: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Count instruction slots and executed instructions against the limits.
    #[command(
        after_help = "Examples:\n  ps30 check asm/article/lum_pass1_loop.psh --int i1=128 --int i2=56\n  ps30 check asm/article/lum_pass2.psh -D xsize=11 -D ysize=8 --json"
    )]
    Check {
        file: PathBuf,
        #[command(flatten)]
        source: SourceArgs,
        #[command(flatten)]
        constants: ConstantArgs,
        #[command(flatten)]
        limits: LimitArgs,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Print the shader as plain ps_3_0 assembly with every macro expanded.
    #[command(
        after_help = "Examples:\n  ps30 expand asm/article/lum_pass2.psh -D xsize=11 -D ysize=8\n  ps30 expand asm/article/lum_pass1_unrolled.psh -o unrolled.psh\n  ps30 expand asm/article/lum_pass2.psh -D xsize=11 -D ysize=8 --json"
    )]
    Expand {
        file: PathBuf,
        #[command(flatten)]
        source: SourceArgs,
        /// Write to this file (atomically) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Print JSON (source, slots, instructions, output, assembly) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Run one pass of a shader over an image into a render target.
    #[command(
        after_help = "Pixel (x, y) of the target gets v0.xy = the centre of the top-left texel of its\nblock of the image (blocks of ceil(W/tw) x ceil(H/th) texels) and s0 = the image.\n\nExample:\n  ps30 run corrected:loop --image assets/hdr/forest.hdr --target 8x10 --int i1=128 --int i2=52 \\\n      --const c1=0.0009765625,0.001953125,0,1 --const c3=0.27,0.67,0.06,0.01 -o sums.exr"
    )]
    Run {
        /// Shader file or bundled name (see `ps30 luminance --help`).
        shader: String,
        #[arg(long)]
        image: PathBuf,
        /// Render-target size WxH.
        #[arg(long, value_name = "WxH", value_parser = parse_size)]
        target: (u32, u32),
        #[command(flatten)]
        source: SourceArgs,
        #[command(flatten)]
        constants: ConstantArgs,
        /// Float constant set by the application, e.g. --const c3=0.27,0.67,0.06,0.01.
        #[arg(long = "const", value_name = "cN=X[,Y,Z,W]", value_parser = parse_float_const)]
        floats: Vec<(u32, [f32; 4])>,
        #[arg(long, value_enum, default_value = "point")]
        filter: FilterArg,
        #[arg(long, value_enum, default_value = "border")]
        address: AddressArg,
        /// Border colour R,G,B,A for --address border.
        #[arg(long, value_parser = parse_float4, default_value = "0,0,0,0")]
        border: [f32; 4],
        #[arg(long, value_enum, default_value = "f32")]
        target_format: FormatArg,
        /// Write the target here (.exr or .pfm), atomically.
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        exec: ExecArgs,
    },
    /// Run the two-pass luminance pipeline on an HDR image and cross-check it.
    #[command(
        after_help = "Shaders are files or bundled names: article:loop, article:unrolled, article:pass2,\ncorrected:loop, corrected:unrolled, corrected:pass2 (default: the corrected unrolled pair).\n\nExamples:\n  ps30 luminance assets/hdr/courtyard_1280x1024.exr\n  ps30 luminance assets/hdr/forest.exr --pass1 article:loop --pass2 article:pass2 --block 128x56\n  ps30 luminance assets/hdr/sunset.pfm --target-format f16 --json"
    )]
    Luminance {
        image: PathBuf,
        /// Pass-1 shader (file or bundled name).
        #[arg(long, default_value = "corrected:unrolled")]
        pass1: String,
        /// Pass-2 shader (file or bundled name).
        #[arg(long, default_value = "corrected:pass2")]
        pass2: String,
        /// A pass-1 shader for the last column of blocks that reads only the
        /// frame's real width there (see `ps30 unroll`); without it, BORDER
        /// addressing pads the last column.
        #[arg(long, value_name = "SHADER")]
        last_column: Option<String>,
        /// Block size WxH (an unrolled shader fixes W to its REPEAT_BLOCK count).
        #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "125x128")]
        block: (u32, u32),
        /// The δ of log(δ + L).
        #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
        delta: f32,
        /// Render-target format: f32 (D3DFMT_R32F) or f16 (D3DFMT_A16B16G16R16F).
        #[arg(long, value_enum, default_value = "f32")]
        target_format: FormatArg,
        /// Reference policy for negative luminance: abs (what `log` does) or clamp.
        #[arg(long, value_enum, default_value = "abs")]
        negative: NegativeArg,
        #[command(flatten)]
        exec: ExecArgs,
    },
    /// Tone-map an HDR image with the article's operator, run in the emulator, into an 8-bit sRGB PNG.
    #[command(
        after_help = "L̄w comes from the corrected luminance passes (125x128 blocks, R32F). The shader is\nasm/tonemap/reinhard.psh; every pixel is cross-checked against the f64 reference within a\nbound derived from the shader's f32 arithmetic (exit 1 if any pixel is outside it).\n\nExamples:\n  ps30 tonemap assets/hdr/courtyard_1280x1024.exr -o courtyard.png\n  ps30 tonemap assets/hdr/city.exr -o city.png --key 0.36 --white 5000\n  ps30 tonemap assets/hdr/forest.hdr --white inf --json"
    )]
    Tonemap {
        image: PathBuf,
        /// Write the tone-mapped image here as an 8-bit sRGB PNG (atomically).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// The key a: the scene's log-average luminance L̄w is mapped to a.
        #[arg(long, default_value_t = ps30::tonemap::DEFAULT_KEY, value_parser = parse_key, allow_negative_numbers = true)]
        key: f64,
        /// White point: the HDR luminance shown as pure white (default: the scene's largest; inf: none).
        #[arg(long, value_name = "W", value_parser = parse_white, allow_negative_numbers = true)]
        white: Option<f64>,
        /// Tone-mapping shader (file, or the bundled tonemap:reinhard) with the same inputs.
        #[arg(long, default_value = "tonemap:reinhard")]
        shader: String,
        #[command(flatten)]
        exec: ExecArgs,
    },
    /// Per-pixel and per-quad costs over an image, divergence, and gradients
    /// that rely on undefined behaviour.
    #[command(
        after_help = "Examples:\n  ps30 profile lights:select --gbuffer 64x64\n  ps30 profile lights:texld --gbuffer 64x64\n  ps30 profile corrected:loop --image assets/hdr/courtyard_1280x1024.exr --target 10x8 \\\n      --int i1=8 --int i2=8 --const c1=0.00078125,0.0009765625,0,1 --const c3=0.27,0.67,0.06,0.01"
    )]
    Profile(ps30::profile::ProfileArgs),
    /// Check every figure the article states and write the report to reports/.
    #[command(
        after_help = "Also regenerates the shaders of asm/generated/ in memory and fails (exit 1) if a\ncommitted file is missing, stale or unexpected; --regenerate rewrites them instead.\n\nExample:\n  ps30 verify --json"
    )]
    Verify {
        /// Directory for the reports.
        #[arg(long, default_value = "reports")]
        reports: PathBuf,
        /// Directory of the committed generated shaders (default: asm/generated
        /// of the source tree).
        #[arg(long, value_name = "DIR")]
        generated: Option<PathBuf>,
        /// Rewrite the generated shaders instead of failing when they are stale.
        #[arg(long)]
        regenerate: bool,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Generate pass-1 (unrolled and loop), last-column and pass-2 luminance shaders that fit the limits.
    #[command(
        after_help = "--fit: unrolled form = the widest unroll that fits the slot limit and the tallest block\nthat fits the executed limit and the rep-count range, lowered to the smallest height with\nas many block rows for the frame; loop form = the plan's best loop block for the frame.\nEvery shader is checked (front end + cost model) before it is printed; its header states\nits slots, executed count and the constants the application sets.\n\nExit codes: 0 every requested shader fits; 1 something requested does not fit (the\nreasons are printed, in numbers); 2 bad input.\n\nExamples:\n  ps30 unroll --fit\n  ps30 unroll --fit --frame 1920x1080 -o shaders/\n  ps30 unroll --block 128x56 --form loop --only pass1\n  ps30 unroll --fit --max-slots 1024 --macro"
    )]
    Unroll {
        /// Block size WxH (texels per line × lines) for every form.
        #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with = "fit", required_unless_present = "fit")]
        block: Option<(u32, u32)>,
        /// Fit the block to the profile (see below).
        #[arg(long)]
        fit: bool,
        /// Frame size WxH: sets the intermediate target, pass 2, the last column and the constants.
        #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "1280x1024")]
        frame: (u32, u32),
        /// Which pass-1 forms to generate.
        #[arg(long, value_enum, default_value = "both")]
        form: FormsArg,
        /// Keep BEGIN_REPEAT_BLOCK/END_REPEAT_BLOCK instead of expanding them.
        #[arg(long = "macro")]
        macros: bool,
        /// Print only one shader's text.
        #[arg(long, value_enum)]
        only: Option<OnlyArg>,
        /// Write each shader (atomically) into this directory instead of printing it.
        #[arg(short, long, value_name = "DIR")]
        output: Option<PathBuf>,
        /// The δ of log(δ + L), for the constants quoted in the headers.
        #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
        delta: f32,
        #[command(flatten)]
        profile: ProfileArgs,
        /// Print JSON (figures and texts) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Rank block sizes, intermediate targets and pass-2 forms for a frame, and recommend one.
    #[command(
        after_help = "Exit codes: 0 a two-pass plan fits; 1 none does (a third pass would be needed, or\nnothing fits the profile); 2 bad input.\n\nExamples:\n  ps30 plan --frame 1280x1024\n  ps30 plan --frame 1920x1080 --max-slots 1024 --json"
    )]
    Plan {
        /// Frame size WxH.
        #[arg(long, value_name = "WxH", value_parser = parse_size)]
        frame: (u32, u32),
        /// The δ of log(δ + L), for the padding and f16 figures.
        #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
        delta: f32,
        #[command(flatten)]
        profile: ProfileArgs,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// The limits of a ps_3_0 part, for `unroll` and `plan`.
#[derive(Args)]
struct ProfileArgs {
    /// Instruction slots (ps_3_0 guarantees 512; parts may have up to 32,768).
    #[arg(long, value_name = "N", default_value_t = 512, value_parser = clap::value_parser!(u64).range(1..=32_768))]
    max_slots: u64,
    /// Executed instructions per pixel (65,535 in the article).
    #[arg(long, value_name = "N", default_value_t = 65_535, value_parser = clap::value_parser!(u64).range(1..=4_294_967_295))]
    max_executed: u64,
    /// Largest rep count (ps_3_0 allows 0 to 255).
    #[arg(long, value_name = "N", default_value_t = 255, value_parser = clap::value_parser!(u32).range(1..=255))]
    max_rep_count: u32,
    /// Deepest rep/loop nesting (ps_3_0 allows 4).
    #[arg(long, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=4))]
    max_nesting: u32,
}

impl ProfileArgs {
    fn profile(&self) -> Profile {
        let base = Profile::ps_3_0();
        let p = Profile {
            max_slots: self.max_slots,
            max_executed: self.max_executed,
            max_rep_count: self.max_rep_count,
            max_loop_nesting: self.max_nesting,
            ..base.clone()
        };
        if p == base {
            p
        } else {
            Profile {
                name: "custom".into(),
                ..p
            }
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum FormsArg {
    Unrolled,
    Loop,
    Both,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum OnlyArg {
    Pass1,
    LastColumn,
    Pass2,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum FormatArg {
    F32,
    F16,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum FilterArg {
    Point,
    Linear,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum AddressArg {
    Border,
    Clamp,
    Wrap,
    Mirror,
    Mirroronce,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum NegativeArg {
    Abs,
    Clamp,
}

impl From<FormatArg> for ps30::image::TargetFormat {
    fn from(f: FormatArg) -> Self {
        match f {
            FormatArg::F32 => ps30::image::TargetFormat::R32F,
            FormatArg::F16 => ps30::image::TargetFormat::Rgba16F,
        }
    }
}

fn parse_key(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    ps30::tonemap::check_values(v, None)
        .map(|_| v)
        .map_err(|e| e.to_string())
}

fn parse_white(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!(
            "the white point must be a positive luminance or inf, not {s}"
        ))
    }
}

/// Refuses an output path whose directory does not exist, before any work.
fn check_output_path(path: &std::path::Path) -> Result<(), BadInput> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
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

fn parse_delta(s: &str) -> Result<f32, String> {
    let v: f32 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(format!("δ must be a positive finite number, not {s}"))
    }
}

/// A shader by bundled name or file path.
fn shader_source(spec: &str) -> Result<ps30::pipeline::ShaderSource, BadInput> {
    if let Some((name, text)) = ps30::verify::bundled(spec) {
        return Ok(ps30::pipeline::ShaderSource::new(name, text));
    }
    let text = read_text(&PathBuf::from(spec))?;
    Ok(ps30::pipeline::ShaderSource::new(spec, text))
}

fn read_text(path: &PathBuf) -> Result<String, BadInput> {
    let bytes = std::fs::read(path).map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
    String::from_utf8(bytes).map_err(|e| {
        BadInput(format!(
            "{}: not UTF-8 text (invalid byte at offset {})",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
    })
}

/// Options of every command that loads an image and runs the emulator.
#[derive(Args)]
struct ExecArgs {
    /// Emulator threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    threads: Option<u32>,
    /// Refuse images with more pixels than this.
    #[arg(long, default_value_t = 1 << 26, value_parser = clap::value_parser!(u64).range(1..))]
    max_pixels: u64,
    /// Stop a pixel that executes more instruction slots than this.
    #[arg(long, default_value_t = 10_000_000, value_parser = clap::value_parser!(u64).range(1..))]
    max_executed_per_pixel: u64,
    /// Refuse render targets with more pixels than this.
    #[arg(long, default_value_t = 1 << 24, value_parser = clap::value_parser!(u64).range(1..))]
    max_target_pixels: u64,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

impl ExecArgs {
    fn limits(&self) -> ps30::emu::EmuLimits {
        ps30::emu::EmuLimits {
            max_executed_per_pixel: self.max_executed_per_pixel,
            max_target_pixels: self.max_target_pixels,
        }
    }
}

#[derive(Args)]
struct SourceArgs {
    /// Bind a REPEAT_BLOCK count name, e.g. -D xsize=11.
    #[arg(short = 'D', value_name = "NAME=N", value_parser = parse_define)]
    define: Vec<(String, u64)>,
    /// Cap on the statements REPEAT_BLOCK expansion may produce.
    #[arg(long, value_name = "N", default_value_t = front::repeat::DEFAULT_MAX_EXPANDED)]
    max_expanded: u64,
}

#[derive(Args)]
struct ConstantArgs {
    /// Integer constant set by the application, e.g. --int i1=128 or --int i0=16,0,1,0.
    #[arg(long = "int", value_name = "iN=X[,Y,Z,W]", value_parser = parse_int_const)]
    ints: Vec<(u32, [i32; 4])>,
    /// Boolean constant set by the application, e.g. --bool b0=true.
    #[arg(long = "bool", value_name = "bN=true|false", value_parser = parse_bool_const)]
    bools: Vec<(u32, bool)>,
}

#[derive(Args)]
struct LimitArgs {
    /// Instruction-slot limit (ps_3_0 guarantees 512).
    #[arg(long, value_name = "N", default_value_t = 512, value_parser = clap::value_parser!(u64).range(1..))]
    max_slots: u64,
    /// Executed-instruction limit (65,535 in the article; Microsoft: at least 2^16).
    #[arg(long, value_name = "N", default_value_t = 65_535, value_parser = clap::value_parser!(u64).range(1..))]
    max_executed: u64,
}

/// How a command ended.
enum Outcome {
    Ok,
    /// The check found a problem (exit 1).
    Problem,
}

/// A failure with exit code 2 (bad input or usage). Diagnostics were
/// already printed when `message` is empty.
struct BadInput(String);

impl<E: std::fmt::Display> From<E> for BadInput {
    fn from(e: E) -> Self {
        BadInput(e.to_string())
    }
}

fn color_stderr() -> bool {
    // NO_COLOR counts when it is set and not empty (no-color.org).
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()) && std::io::stderr().is_terminal()
}

fn load(path: &PathBuf, source: &SourceArgs) -> Result<front::Loaded, BadInput> {
    let text = read_text(path)?;
    let options = Options {
        defines: source.define.iter().cloned().collect(),
        max_expanded: source.max_expanded,
    };
    let file = SourceFile::new(path.display().to_string(), text);
    match front::load(file, &options) {
        Ok(l) => {
            for w in &l.warnings.items {
                w.emit(&l.file, color_stderr());
            }
            Ok(l)
        }
        Err(e) => {
            for d in &e.diagnostics.items {
                d.emit(&e.file, color_stderr());
            }
            let n = e.diagnostics.errors().count();
            Err(BadInput(format!(
                "{}: {n} error{}",
                e.file.name,
                if n == 1 { "" } else { "s" }
            )))
        }
    }
}

/// Writes to stdout. A reader that went away (`ps30 … | head`) is not an
/// error: there is nobody left to tell anything, so the command ends with
/// success, as a Unix filter does (every file it writes was written
/// atomically before it printed).
fn print(out: &str) -> std::io::Result<()> {
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
fn say(ui: &Ui, out: &str) -> std::io::Result<()> {
    print(&ui.highlight(out))
}

fn run(cli: Cli) -> Result<Outcome, BadInput> {
    let ui = Ui::new(cli.quiet);
    match cli.command {
        Command::Check {
            file,
            source,
            constants,
            limits,
            json,
        } => {
            let loaded = load(&file, &source)?;
            let env = Environment {
                ints: constants.ints.into_iter().collect(),
                bools: constants.bools.into_iter().collect(),
            };
            for r in env.ints.keys() {
                if !ui.quiet && loaded.shader.program().int_def(*r).is_some() {
                    eprintln!(
                        "note: i{r} is defined in the shader (defi), which overrides --int i{r}"
                    );
                }
            }
            let profile = Profile {
                max_slots: limits.max_slots,
                max_executed: limits.max_executed,
                ..Profile::ps_3_0()
            };
            let a = cost::analyse(&loaded.shader, &loaded.file, &env, &profile)?;
            let name = loaded.file.name.clone();
            if json {
                let warnings: Vec<String> = loaded
                    .warnings
                    .items
                    .iter()
                    .map(|w| w.to_string())
                    .collect();
                let v = report::check_json(&name, &a, &warnings);
                print(&(serde_json::to_string_pretty(&v)? + "\n"))?;
            } else {
                say(&ui, &report::check_text(&name, &a))?;
            }
            Ok(if a.verdict == Verdict::Within {
                Outcome::Ok
            } else {
                Outcome::Problem
            })
        }
        Command::Expand {
            file,
            source,
            output,
            json,
        } => {
            let loaded = load(&file, &source)?;
            let text = format!(
                "// expanded from {} by ps30 expand: {} instruction slots\n{}",
                loaded.file.name,
                loaded.shader.info().total_slots,
                ps30::writer::write_program(loaded.shader.program())
            );
            if let Some(path) = &output {
                report::write_atomic(path, text.as_bytes())
                    .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
            }
            if json {
                let v = serde_json::json!({
                    "source": loaded.file.name,
                    "slots": loaded.shader.info().total_slots,
                    "instructions": loaded.shader.instructions().len(),
                    "output": output.as_ref().map(|p| p.display().to_string()),
                    "assembly": text,
                });
                print(&(serde_json::to_string_pretty(&v)? + "\n"))?;
            } else if output.is_none() {
                print(&text)?;
            }
            Ok(Outcome::Ok)
        }
        Command::Run {
            shader,
            image,
            target,
            source,
            constants,
            floats,
            filter,
            address,
            border,
            target_format,
            output,
            exec,
        } => {
            let (threads, max_pixels, json) = (exec.threads, exec.max_pixels, exec.json);
            let src = shader_source(&shader)?;
            let options = Options {
                defines: source.define.iter().cloned().collect(),
                max_expanded: source.max_expanded,
            };
            let loaded = match front::load(SourceFile::new(src.name.clone(), src.text), &options) {
                Ok(l) => l,
                Err(e) => {
                    for d in &e.diagnostics.items {
                        d.emit(&e.file, color_stderr());
                    }
                    return Err(BadInput(e.to_string()));
                }
            };
            let img = ps30::image::load(&image, &ps30::image::ImageLimits { max_pixels })?;
            let mut consts = ps30::emu::Constants::default();
            for (i, v) in floats {
                let i = i as usize;
                consts.float.resize(consts.float.len().max(i + 1), [0.0; 4]);
                consts.float[i] = v;
            }
            for (i, v) in constants.ints {
                let i = i as usize;
                consts.int.resize(consts.int.len().max(i + 1), [0; 4]);
                consts.int[i] = v;
            }
            for (i, v) in constants.bools {
                let i = i as usize;
                consts.bool.resize(consts.bool.len().max(i + 1), false);
                consts.bool[i] = v;
            }
            let address = match address {
                AddressArg::Border => ps30::emu::Address::Border,
                AddressArg::Clamp => ps30::emu::Address::Clamp,
                AddressArg::Wrap => ps30::emu::Address::Wrap,
                AddressArg::Mirror => ps30::emu::Address::Mirror,
                AddressArg::Mirroronce => ps30::emu::Address::MirrorOnce,
            };
            let setup = ps30::pipeline::PassSetup {
                target,
                constants: consts,
                sampler: ps30::emu::SamplerState {
                    address_u: address,
                    address_v: address,
                    border,
                    ..ps30::emu::SamplerState::filtered(match filter {
                        FilterArg::Point => ps30::emu::Filter::Point,
                        FilterArg::Linear => ps30::emu::Filter::Linear,
                    })
                },
                format: target_format.into(),
                threads: threads.map(|t| t as usize),
                limits: exec.limits(),
            };
            let out = {
                let _spinner = ui.spinner("running the shader");
                ps30::pipeline::run_pass(&loaded, &img, &setup)?
            };
            if let Some(path) = &output {
                let is_pfm = path
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("pfm"));
                if is_pfm {
                    ps30::image::write_pfm(path, &out.target)?;
                } else {
                    ps30::image::write_exr(path, &out.target)?;
                }
            }
            let text = ps30::pipeline::pass_text(
                &loaded.file.name,
                &image.display().to_string(),
                &out,
                output.as_deref().filter(|_| !ui.quiet),
            );
            if json {
                print(&(serde_json::to_string_pretty(&ps30::pipeline::pass_json(&out))? + "\n"))?;
            } else {
                say(&ui, &text)?;
            }
            Ok(if out.cost.within_limits && out.cost.counts_agree {
                Outcome::Ok
            } else {
                Outcome::Problem
            })
        }
        Command::Luminance {
            image,
            pass1,
            pass2,
            last_column,
            block,
            delta,
            target_format,
            negative,
            exec,
        } => {
            let (threads, max_pixels, json) = (exec.threads, exec.max_pixels, exec.json);
            let img = ps30::image::load(&image, &ps30::image::ImageLimits { max_pixels })?;
            let settings = ps30::pipeline::Settings {
                block,
                delta,
                format: target_format.into(),
                policy: match negative {
                    NegativeArg::Abs => ps30::reference::Policy::ABS,
                    NegativeArg::Clamp => ps30::reference::Policy::CLAMP,
                },
                threads: threads.map(|t| t as usize),
                limits: exec.limits(),
            };
            let (pass1, pass2) = (shader_source(&pass1)?, shader_source(&pass2)?);
            let run = {
                let _spinner = ui.spinner("running both passes");
                match &last_column {
                    Some(last) => ps30::pipeline::run_with_last_column(
                        &img,
                        &pass1,
                        &shader_source(last)?,
                        &pass2,
                        &settings,
                    )?,
                    None => ps30::pipeline::run(&img, &pass1, &pass2, &settings)?,
                }
            };
            let name = image.display().to_string();
            if json {
                print(
                    &(serde_json::to_string_pretty(&ps30::pipeline::run_json(&name, &run))? + "\n"),
                )?;
            } else {
                say(&ui, &ps30::pipeline::run_text(&name, &run))?;
            }
            // A non-finite L̄w is a problem even when the reference agrees.
            Ok(if run.all_agree() && run.finite() {
                Outcome::Ok
            } else {
                Outcome::Problem
            })
        }
        Command::Tonemap {
            image,
            output,
            key,
            white,
            shader,
            exec,
        } => {
            let (threads, max_pixels, json) = (exec.threads, exec.max_pixels, exec.json);
            if let Some(out) = &output {
                check_output_path(out)?;
            }
            let shader = if shader == "tonemap:reinhard" {
                ps30::pipeline::ShaderSource::new(ps30::tonemap::SHADER.0, ps30::tonemap::SHADER.1)
            } else {
                shader_source(&shader)?
            };
            let img = ps30::image::load(&image, &ps30::image::ImageLimits { max_pixels })?;
            let settings = ps30::tonemap::Settings {
                key,
                white,
                threads: threads.map(|t| t as usize),
                band_rows: 0,
                shader,
                limits: exec.limits(),
            };
            let result = {
                let bar = std::cell::RefCell::new(ui.bar("tone mapping", img.height as u64));
                ps30::tonemap::run(&img, &settings, &|done, total| {
                    bar.borrow_mut().set(None, done, total)
                })?
            };
            let written = match &output {
                Some(out) => {
                    ps30::image::write_png_rgb8(out, result.width, result.height, &result.srgb8())?;
                    Some(out.display().to_string())
                }
                None => None,
            };
            let name = image.display().to_string();
            let ok = result.all_agree();
            if json {
                let v = ps30::tonemap::json(&name, &result, written.as_deref());
                print(&(serde_json::to_string_pretty(&v)? + "\n"))?;
            } else if !(ui.quiet && ok) {
                say(
                    &ui,
                    &ps30::tonemap::text(&name, &result, written.as_deref()),
                )?;
            }
            Ok(if ok { Outcome::Ok } else { Outcome::Problem })
        }
        Command::Profile(args) => Ok(match ps30::profile::command(args, color_stderr()) {
            Ok(false) => Outcome::Ok,
            Ok(true) => Outcome::Problem,
            Err(e) => return Err(BadInput(e)),
        }),
        Command::Verify {
            reports,
            generated,
            regenerate,
            json,
        } => {
            let bar = std::cell::RefCell::new(ui.bar("article claims", 12));
            let source_tree = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
            let mut claims = ps30::verify::article_claims().map_err(BadInput)?;
            let set = ps30::gen::set::generated_set()?;
            claims.extend(ps30::verify::planning_claims(&set).map_err(BadInput)?);
            bar.borrow_mut().set(Some("luminance cross-check"), 1, 12);
            let image_path = source_tree.join(ps30::verify::CROSSCHECK_IMAGE);
            let image_path = if image_path.exists() {
                image_path
            } else {
                PathBuf::from(ps30::verify::CROSSCHECK_IMAGE)
            };
            let img = ps30::image::load(&image_path, &ps30::image::ImageLimits::default())?;
            let rows = ps30::verify::crosscheck(&img).map_err(BadInput)?;
            // The committed generated shaders: compared, or rewritten.
            let generated_shown = generated
                .as_ref()
                .map_or(ps30::verify::GENERATED_DIR.to_string(), |d| {
                    d.display().to_string()
                });
            let generated = generated.unwrap_or_else(|| {
                let in_tree = source_tree.join(ps30::verify::GENERATED_DIR);
                if in_tree.exists() {
                    in_tree
                } else {
                    PathBuf::from(ps30::verify::GENERATED_DIR)
                }
            });
            let mut rewritten = Vec::new();
            let stale = if regenerate {
                let (written, removed) = ps30::gen::set::write_set(&generated, &set)
                    .map_err(|e| BadInput(format!("{}: {e}", generated.display())))?;
                rewritten.extend(written.into_iter().map(|p| format!("wrote {p}")));
                rewritten.extend(removed.into_iter().map(|p| format!("removed {p}")));
                Vec::new()
            } else {
                ps30::gen::set::stale_files(&generated, &set)
            };
            let claims_path = reports.join("article-claims.md");
            let cross_path = reports.join("luminance-crosscheck.md");
            let gen_path = reports.join("generated-shaders.md");
            for (path, text) in [
                (&claims_path, ps30::verify::claims_report(&claims)),
                (&cross_path, ps30::verify::crosscheck_report(&rows)),
                (&gen_path, ps30::gen::set::summary_report(&set)),
            ] {
                report::write_atomic(path, text.as_bytes())
                    .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
            }
            // The repository root the bundled images were found under.
            let root = image_path
                .parent()
                .and_then(std::path::Path::parent)
                .and_then(std::path::Path::parent)
                .unwrap_or(std::path::Path::new(""));
            let figures =
                ps30::report_dir::generate(&reports, root, None, &|stage, done, total| {
                    bar.borrow_mut().set(Some(stage), done + 2, total + 2)
                })
                .map_err(BadInput)?;
            drop(bar);
            let ok = claims.iter().all(|c| c.agrees)
                && rows.iter().all(|r| r.as_expected())
                && figures.all_agree()
                && stale.is_empty();
            if json {
                let v = serde_json::json!({
                    "claims": claims,
                    "crosscheck": rows,
                    "tonemap": figures.tonemap,
                    "budgets": figures.budgets,
                    "block_figures": figures.block_figures,
                    "files": figures.files,
                    "generated": {
                        "directory": generated.display().to_string(),
                        "files": set.files.iter().map(|(f, _)| f).collect::<Vec<_>>(),
                        "stale": stale,
                        "rewritten": rewritten,
                    },
                    "all_agree": ok,
                });
                print(&(serde_json::to_string_pretty(&v)? + "\n"))?;
            } else if !(ui.quiet && ok) {
                say(&ui, &ps30::verify::claims_text(&claims))?;
                say(
                    &ui,
                    &format!(
                        "\n{} of {} claims reproduced\n\ncross-check on {} ({}):\n",
                        claims.iter().filter(|c| c.agrees).count(),
                        claims.len(),
                        ps30::verify::CROSSCHECK_IMAGE,
                        "emulated two-pass L̄w against the f64 reference"
                    ),
                )?;
                for r in &rows {
                    say(
                        &ui,
                        &format!(
                            "  {:<8} {} + {} {}×{} {}: {}\n",
                            if r.as_expected() { "ok" } else { "UNEXPECTED" },
                            r.pass1,
                            r.pass2,
                            r.block.0,
                            r.block.1,
                            r.format,
                            r.finding
                        ),
                    )?;
                }
                say(&ui, &verify_tonemap_text(&figures))?;
                say(
                    &ui,
                    &format!(
                        "\ngenerated shaders: {} files for {} frame sizes in {}: {}\n",
                        set.files.len(),
                        set.frames.len(),
                        generated_shown,
                        if regenerate {
                            format!("regenerated ({} changed)", rewritten.len())
                        } else if stale.is_empty() {
                            "up to date".to_string()
                        } else {
                            format!("{} PROBLEMS", stale.len())
                        }
                    ),
                )?;
                for r in &rewritten {
                    print(&format!("  {r}\n"))?;
                }
                for p in &stale {
                    print(&format!("  {p}\n"))?;
                }
                print(&format!(
                    "\nreports written to {}, {} and {}\n",
                    claims_path.display(),
                    cross_path.display(),
                    gen_path.display()
                ))?;
                print(&format!(
                    "figures and pages: {} (index: {})\n",
                    figures.files.len(),
                    reports.join("README.md").display()
                ))?;
            }
            Ok(if ok { Outcome::Ok } else { Outcome::Problem })
        }
        Command::Unroll {
            block,
            fit,
            frame,
            form,
            macros,
            only,
            output,
            delta,
            profile,
            json,
        } => {
            use ps30::gen::set::{self, BlockChoice, Role};
            use ps30::gen::Pass1Form;
            let choice = match (block, fit) {
                (Some((w, h)), _) => BlockChoice::Given(w, h),
                (None, _) => BlockChoice::Fit,
            };
            let forms = match form {
                FormsArg::Unrolled => vec![Pass1Form::Unrolled],
                FormsArg::Loop => vec![Pass1Form::Loop],
                FormsArg::Both => vec![Pass1Form::Unrolled, Pass1Form::Loop],
            };
            let profile = profile.profile();
            let bundle = set::generate(
                &set::Request {
                    frame,
                    picks: forms.into_iter().map(|f| (f, choice)).collect(),
                    macros,
                    delta: delta as f64,
                },
                &profile,
            )?;
            let outcome = if bundle.problems.is_empty() {
                Outcome::Ok
            } else {
                Outcome::Problem
            };
            if let Some(kind) = only {
                let role = match kind {
                    OnlyArg::Pass1 => Role::Pass1,
                    OnlyArg::LastColumn => Role::LastColumn,
                    OnlyArg::Pass2 => Role::Pass2,
                };
                let matching: Vec<_> = bundle.shaders.iter().filter(|g| g.role == role).collect();
                match matching.as_slice() {
                    [one] => print(&one.text)?,
                    [] => {
                        eprint!("{}", set::summary_text(&bundle));
                        return Err(BadInput(
                            "no such shader was generated (see the summary above)".into(),
                        ));
                    }
                    many => {
                        return Err(BadInput(format!(
                            "--only matches {} shaders ({}); choose one with --form unrolled or --form loop",
                            many.len(),
                            many.iter().map(|g| g.file.as_str()).collect::<Vec<_>>().join(", ")
                        )))
                    }
                }
                if !bundle.problems.is_empty() {
                    for p in &bundle.problems {
                        eprintln!("does not fit: {p}");
                    }
                }
                return Ok(outcome);
            }
            if let Some(dir) = &output {
                for g in &bundle.shaders {
                    let path = dir.join(&g.file);
                    report::write_atomic(&path, g.text.as_bytes())
                        .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
                }
            }
            if json {
                print(&(serde_json::to_string_pretty(&bundle)? + "\n"))?;
            } else {
                print(&set::summary_text(&bundle))?;
                match &output {
                    Some(dir) => print(&format!(
                        "\nwrote {} files to {}\n",
                        bundle.shaders.len(),
                        dir.display()
                    ))?,
                    None => {
                        for g in &bundle.shaders {
                            print(&format!("\n// ---- {} ----\n{}", g.file, g.text))?;
                        }
                    }
                }
            }
            Ok(outcome)
        }
        Command::Plan {
            frame,
            delta,
            profile,
            json,
        } => {
            let plan = ps30::gen::plan::plan(frame, &profile.profile(), delta as f64)?;
            if json {
                print(&(serde_json::to_string_pretty(&ps30::gen::plan::plan_json(&plan))? + "\n"))?;
            } else {
                print(&ps30::gen::plan::plan_text(&plan))?;
            }
            Ok(if plan.recommended.is_some() {
                Outcome::Ok
            } else {
                Outcome::Problem
            })
        }
    }
}

/// The tone-mapping lines of `ps30 verify`'s text output.
fn verify_tonemap_text(g: &ps30::report_dir::Generated) -> String {
    let mut s = String::from(
        "\ntone mapping (asm/tonemap/reinhard.psh in the emulator against the f64 reference, every pixel):\n",
    );
    for r in &g.tonemap {
        s.push_str(&format!(
            "  {:<8} {}: L̄w {:.6}, largest difference {:.1e} (bound there {:.1e}, at most {:.0}% of a bound), 8-bit codes off by one: {}\n",
            if r.agree { "ok" } else { "DISAGREE" },
            r.image,
            r.log_average,
            r.max_error,
            r.max_error_bound,
            100.0 * r.largest_bound_fraction,
            r.mismatched_8bit_channels
        ));
    }
    s
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    match run(cli) {
        Ok(Outcome::Ok) => ExitCode::SUCCESS,
        Ok(Outcome::Problem) => ExitCode::from(1),
        Err(BadInput(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
    }
}
