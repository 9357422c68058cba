//! The `ps30` command line: a thin layer over the library.
//!
//! Exit codes: 0 ok; 1 the check found a problem (a limit exceeded, a claim
//! or cross-check that disagrees); 2 bad input or usage. A closed stdout
//! (e.g. piping into `head`) counts as success.

use clap::{Args, Parser, Subcommand};
use ps30::cost::{self, Environment, Profile, Verdict};
use ps30::diag::SourceFile;
use ps30::front::{self, Options};
use ps30::report;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "ps30",
    version,
    about = "Parse, measure, run and generate Direct3D 9 ps_3_0 assembly"
)]
struct Cli {
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
        after_help = "Example:\n  ps30 expand asm/article/lum_pass2.psh -D xsize=11 -D ysize=8"
    )]
    Expand {
        file: PathBuf,
        #[command(flatten)]
        source: SourceArgs,
        /// Write to this file (atomically) instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
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
        /// Emulator threads (default: all cores).
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
        threads: Option<u32>,
        /// Refuse images with more pixels than this.
        #[arg(long, default_value_t = 1 << 26)]
        max_pixels: u64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Check every figure the article states and write the report to reports/.
    #[command(after_help = "Example:\n  ps30 verify --json")]
    Verify {
        /// Directory for the reports.
        #[arg(long, default_value = "reports")]
        reports: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum FormatArg {
    F32,
    F16,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum NegativeArg {
    Abs,
    Clamp,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WxH, e.g. 125x128")?;
    let parse = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (1..=1 << 16).contains(&n))
    };
    match (parse(w), parse(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(format!(
            "`{s}`: both sides must be integers from 1 to 65536"
        )),
    }
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

fn parse_define(s: &str) -> Result<(String, u64), String> {
    let (name, value) = s.split_once('=').ok_or("expected NAME=N, e.g. xsize=11")?;
    let valid_name = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid_name {
        return Err(format!("`{name}` is not a valid name"));
    }
    let v = value
        .trim()
        .parse::<u64>()
        .map_err(|_| format!("`{value}` is not a non-negative integer"))?;
    Ok((name.to_string(), v))
}

fn parse_register(s: &str, prefix: char, count: u32) -> Result<u32, String> {
    let n = s
        .strip_prefix(prefix)
        .and_then(|d| d.parse::<u32>().ok())
        .ok_or_else(|| format!("expected {prefix}0 … {prefix}{}", count - 1))?;
    if n >= count {
        return Err(format!(
            "{prefix}{n} does not exist ({prefix}0 … {prefix}{})",
            count - 1
        ));
    }
    Ok(n)
}

fn parse_int_const(s: &str) -> Result<(u32, [i32; 4]), String> {
    let (reg, value) = s
        .split_once('=')
        .ok_or("expected iN=X[,Y,Z,W], e.g. i1=128")?;
    let reg = parse_register(reg.trim(), 'i', 16)?;
    let parts: Vec<&str> = value.split(',').collect();
    if parts.is_empty() || parts.len() > 4 {
        return Err("expected one to four integers".into());
    }
    let mut v = [0i32; 4];
    for (slot, p) in v.iter_mut().zip(&parts) {
        *slot = p
            .trim()
            .parse::<i32>()
            .map_err(|_| format!("`{p}` is not an integer"))?;
    }
    Ok((reg, v))
}

fn parse_bool_const(s: &str) -> Result<(u32, bool), String> {
    let (reg, value) = s.split_once('=').ok_or("expected bN=true|false")?;
    let reg = parse_register(reg.trim(), 'b', 16)?;
    let v = match value.trim() {
        "true" | "1" => true,
        "false" | "0" => false,
        other => return Err(format!("`{other}` is not true or false")),
    };
    Ok((reg, v))
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
    std::env::var_os("NO_COLOR").is_none() && std::io::stderr().is_terminal()
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

fn print(out: &str) -> std::io::Result<()> {
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(out.as_bytes())?;
    stdout.flush()
}

fn run(cli: Cli) -> Result<Outcome, BadInput> {
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
                if loaded.shader.program().int_def(*r).is_some() {
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
                print(&report::check_text(&name, &a))?;
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
        } => {
            let loaded = load(&file, &source)?;
            let text = format!(
                "// expanded from {} by ps30 expand: {} instruction slots\n{}",
                loaded.file.name,
                loaded.shader.info().total_slots,
                ps30::writer::write_program(loaded.shader.program())
            );
            match output {
                Some(path) => report::write_atomic(&path, text.as_bytes())
                    .map_err(|e| BadInput(format!("{}: {e}", path.display())))?,
                None => print(&text)?,
            }
            Ok(Outcome::Ok)
        }
        Command::Luminance {
            image,
            pass1,
            pass2,
            block,
            delta,
            target_format,
            negative,
            threads,
            max_pixels,
            json,
        } => {
            let img = ps30::image::load(&image, &ps30::image::ImageLimits { max_pixels })?;
            let settings = ps30::pipeline::Settings {
                block,
                delta,
                format: match target_format {
                    FormatArg::F32 => ps30::image::TargetFormat::R32F,
                    FormatArg::F16 => ps30::image::TargetFormat::Rgba16F,
                },
                policy: match negative {
                    NegativeArg::Abs => ps30::reference::Policy::ABS,
                    NegativeArg::Clamp => ps30::reference::Policy::CLAMP,
                },
                threads: threads.map(|t| t as usize),
            };
            let run = ps30::pipeline::run(
                &img,
                &shader_source(&pass1)?,
                &shader_source(&pass2)?,
                &settings,
            )?;
            let name = image.display().to_string();
            if json {
                print(
                    &(serde_json::to_string_pretty(&ps30::pipeline::run_json(&name, &run))? + "\n"),
                )?;
            } else {
                print(&ps30::pipeline::run_text(&name, &run))?;
            }
            Ok(if run.all_agree() {
                Outcome::Ok
            } else {
                Outcome::Problem
            })
        }
        Command::Verify { reports, json } => {
            let claims = ps30::verify::article_claims().map_err(BadInput)?;
            let all = claims.iter().all(|c| c.agrees);
            let md = format!(
                "# The article's figures, recomputed\n\n\
                 Generated by `ps30 verify` from the listings in `asm/article/` \
                 (the article as printed, with transcription fixes only). \
                 Profile: ps_3_0, 512 instruction slots, 65,535 executed instructions.\n\n{}\n\
                 {} of {} claims reproduced.\n",
                ps30::verify::claims_markdown(&claims),
                claims.iter().filter(|c| c.agrees).count(),
                claims.len()
            );
            let path = reports.join("article-claims.md");
            report::write_atomic(&path, md.as_bytes())
                .map_err(|e| BadInput(format!("{}: {e}", path.display())))?;
            if json {
                print(
                    &(serde_json::to_string_pretty(
                        &serde_json::json!({ "claims": claims, "all_agree": all }),
                    )? + "\n"),
                )?;
            } else {
                print(&ps30::verify::claims_text(&claims))?;
                print(&format!(
                    "\n{} of {} claims reproduced; report written to {}\n",
                    claims.iter().filter(|c| c.agrees).count(),
                    claims.len(),
                    path.display()
                ))?;
            }
            Ok(if all { Outcome::Ok } else { Outcome::Problem })
        }
    }
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
        Err(BadInput(msg)) if msg.contains("Broken pipe") => ExitCode::SUCCESS,
        Err(BadInput(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
    }
}
