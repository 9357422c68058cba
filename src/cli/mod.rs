//! The `ps30` command line: clap definitions and one module per subcommand.
//!
//! Each subcommand module holds its arguments (`Args`) and a `run` function
//! that calls the library and prints what the library returns; `main.rs`
//! only parses and dispatches. Nothing in the library imports from here.
//!
//! Exit codes: 0 ok; 1 the check found a problem (a limit exceeded, a claim
//! or cross-check that disagrees); 2 bad input or usage; 3 a tool the
//! command needs is missing (`decompile --verify` without the oracle). A closed stdout
//! (e.g. piping into `head`) counts as success. Interrupted by SIGINT,
//! SIGTERM or SIGHUP, the command removes its temporary output files and
//! exits with 130.

pub mod args;
pub mod asm;
pub mod check;
pub mod compare;
pub mod completions;
pub mod corpus;
pub mod decompile;
pub mod disasm;
pub mod expand;
pub mod io;
pub mod luminance;
pub mod man;
pub mod plan;
pub mod profile;
pub mod render;
pub mod run;
pub mod shader_test;
pub mod shaders;
pub mod study;
pub mod tonemap;
pub mod translate;
pub mod ui;
pub mod unroll;
pub mod verify;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "ps30",
    version,
    about = "Check, count, assemble, list, run, translate and decompile Direct3D 9 shaders (ps_1_1 to ps_3_0, vs_2_0 to vs_3_0)"
)]
pub struct Cli {
    /// Print only results and problems: no progress bars, notes or "wrote …" lines.
    #[arg(long, short, global = true)]
    pub quiet: bool,
    /// When to colour output: auto (a terminal, and NO_COLOR unset), always or never.
    #[arg(
        long,
        global = true,
        value_enum,
        value_name = "WHEN",
        default_value = "auto"
    )]
    pub color: ui::ColorWhen,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Count instruction slots and executed instructions against the limits.
    #[command(
        after_help = "Examples:\n  ps30 check asm/article/lum_pass1_loop.psh --int i1=128 --int i2=56\n  ps30 check asm/article/lum_pass2.psh -D xsize=11 -D ysize=8 --json"
    )]
    Check(check::Args),
    /// Write a shader as bytecode (REPEAT_BLOCK expanded, validated, written atomically).
    #[command(
        after_help = "The tokens are exactly those Microsoft's assembler emits for the program, in the order\nthe statements stand. A compiled shader given as input is written back as it is, its\nconstant table (CTAB) included.\n\nExamples:\n  ps30 asm asm/corrected/lum_pass2.psh -D xsize=11 -D ysize=8 -o p2.fxo\n  ps30 disasm p2.fxo | ps30 asm - -o again.fxo"
    )]
    Asm(asm::Args),
    /// Print a compiled shader as an assembly listing in the style of fxc's.
    #[command(
        after_help = "The listing shows the constant table as fxc does (parameters and registers) and keeps\nevery comment block as `//#comment` lines of hexadecimal tokens, so `ps30 asm` turns it\nback into the same bytes. Assembly given as input is assembled first.\n\nExamples:\n  ps30 disasm p2.fxo\n  ps30 disasm shader.fxo --json"
    )]
    Disasm(disasm::Args),
    /// Write a compiled shader as HLSL; --verify recompiles it with Microsoft's compiler and runs both.
    #[command(
        after_help = "Exit codes: 0 written (with --verify: the recompiled shader computes the same values,\nbit for bit); 1 --verify found a difference or the compiler refused the HLSL; 2 bad input\nor a shader the HLSL cannot express; 3 --verify without Microsoft's compiler installed.\n\nExamples:\n  ps30 decompile shader.fxo -o shader.hlsl\n  ps30 decompile shader.fxo --verify"
    )]
    Decompile(decompile::Args),
    /// Print the shader as plain assembly with every macro expanded.
    #[command(
        after_help = "Examples:\n  ps30 expand asm/article/lum_pass2.psh -D xsize=11 -D ysize=8\n  ps30 expand asm/article/lum_pass1_unrolled.psh -o unrolled.psh\n  ps30 expand asm/article/lum_pass2.psh -D xsize=11 -D ysize=8 --json"
    )]
    Expand(expand::Args),
    /// Run one pass of a shader over an image into a render target.
    #[command(
        after_help = "Pixel (x, y) of the target gets v0.xy = the centre of the top-left texel of its\nblock of the image (blocks of ceil(W/tw) x ceil(H/th) texels) and s0 = the image.\n\nExample:\n  ps30 run corrected:loop --image assets/hdr/forest.hdr --target 8x10 --int i1=128 --int i2=52 \\\n      --const c1=0.0009765625,0.001953125,0,1 --const c3=0.27,0.67,0.06,0.01 -o sums.exr"
    )]
    Run(run::Args),
    /// Run the two-pass luminance pipeline on an HDR image and cross-check it.
    #[command(
        after_help = "Shaders are files or bundled names: article:loop, article:unrolled, article:pass2,\ncorrected:loop, corrected:unrolled, corrected:pass2 (default: the corrected unrolled pair).\n\nExamples:\n  ps30 luminance assets/hdr/courtyard_1280x1024.exr\n  ps30 luminance assets/hdr/forest.exr --pass1 article:loop --pass2 article:pass2 --block 128x56\n  ps30 luminance assets/hdr/sunset.pfm --target-format f16 --json"
    )]
    Luminance(luminance::Args),
    /// Tone-map an HDR image with the article's operator, run in the emulator, into an 8-bit sRGB PNG.
    #[command(
        after_help = "L̄w comes from the luminance passes planned for the image's size (R32F). The shader is\nasm/tonemap/reinhard.psh; every pixel is cross-checked against the f64 reference within a\nbound derived from the shader's f32 arithmetic (exit 1 if any pixel is outside it).\n\nExamples:\n  ps30 tonemap assets/hdr/courtyard_1280x1024.exr -o courtyard.png\n  ps30 tonemap assets/hdr/city.exr -o city.png --key 0.36 --white 5000\n  ps30 tonemap assets/hdr/forest.hdr --white inf --json"
    )]
    Tonemap(tonemap::Args),
    /// Run a draw on the emulator and on a GPU and compare them pixel by pixel (--all: every bundled shader, into reports/gpu-crosscheck.md).
    #[command(
        after_help = "Per output channel: bit-identical pixels, a histogram of distances in ulp, NaN/∞\ndisagreements and the worst pixels with their inputs; --luminance adds L̄w from both\nbackends against the f64 reference. Needs a Vulkan device (exit 2 without one).\n\nExit codes: 0 every difference is explained (within the derived bounds, traced to\ninstructions the probes show differ); 1 a finding; 2 bad input or no GPU.\n\nExamples:\n  ps30 compare --luminance --image assets/hdr/courtyard_1280x1024.exr\n  ps30 compare --tonemap --image assets/hdr/forest.hdr --json\n  ps30 compare corrected:loop --image assets/hdr/forest.hdr --target 8x10 --int i1=128 --int i2=52 \\\n      --const c1=0.0009765625,0.001953125,0,1 --const c3=0.27,0.67,0.06,0.01 --target-format f32\n  ps30 compare --all"
    )]
    Compare(compare::Args),
    /// Translate a shader to WGSL, SPIR-V, GLSL, HLSL or MSL (through naga), with its binding layout.
    #[command(
        after_help = "The module passes naga's validator before it is written; the header names the source,\nthe float rules and where every c#, i#, b#, sampler, input and output is bound.\n\nExamples:\n  ps30 translate asm/corrected/lum_pass1_unrolled.psh --to wgsl\n  ps30 translate tonemap:reinhard --to glsl -o reinhard.frag\n  ps30 translate asm/article/lum_pass2.psh -D xsize=11 -D ysize=8 --to spirv -o pass2.spv\n  ps30 translate lights:select --to hlsl --float-rules ieee"
    )]
    Translate(translate::Args),
    /// Per-pixel and per-quad costs over an image, divergence, and gradients
    /// that rely on undefined behaviour.
    #[command(
        after_help = "Examples:\n  ps30 profile lights:select --gbuffer 64x64\n  ps30 profile lights:texld --gbuffer 64x64\n  ps30 profile corrected:loop --image assets/hdr/courtyard_1280x1024.exr --target 10x8 \\\n      --int i1=8 --int i2=8 --const c1=0.00078125,0.0009765625,0,1 --const c3=0.27,0.67,0.06,0.01"
    )]
    Profile(profile::Args),
    /// Run vkd3d's .shader_test files as its Direct3D 9 runner does, on the emulator.
    #[command(
        name = "shader-test",
        after_help = "Runs vkd3d's .shader_test files as vkd3d's Direct3D 9 runner does: the lowest shader model\nthe file's [require] allows within 2.0-3.0, its HLSL compiled by Microsoft's compiler\n(tools/oracle/setup.sh installs it; PS30_ORACLE names its folder), its draws on the\nemulator, every probe checked with its ulps. docs/shader-test.md says what is run.\n\nExit codes: 0 every probe that ran passed; 1 a probe failed; 2 bad input or no compiler.\n\nExamples:\n  ps30 shader-test tests/shader_test/uniforms.shader_test\n  ps30 shader-test vkd3d/tests/hlsl --json"
    )]
    ShaderTest(shader_test::Args),
    /// List the shaders bundled in the binary, or print one.
    #[command(
        after_help = "Every command that reads a shader takes a bundled name (family:variant) or a file path.\n\nExamples:\n  ps30 shaders\n  ps30 shaders article:loop\n  ps30 shaders --json"
    )]
    Shaders(shaders::Args),
    /// Run a draw list: clears, draws with blending and write masks, mip-chain reductions.
    #[command(
        after_help = "The draw list is JSON: named targets (size, D3D9 format), textures (images or the\nsynthetic G-buffer of asm/lights/), and steps: {\"clear\": T, \"color\": [r,g,b,a]},\n{\"draw\": T, \"shader\": S, \"inputs\", \"constants\", \"samplers\", \"blend\", \"write\"},\n{\"mips\": T, \"odd\": \"fold\"|\"bilinear\"}. A draw covers its whole target, or with\n\"geometry\" draws vertices (a vertex shader or positions as given, clipping, D3D9's\nrasterization rules, depth); the output merger blends in the target's precision.\ndocs/render.md and docs/draw.md have the format.\n\nExit codes: 0 ok; 1 a draw's executed count left the cost model's range; 2 bad input.\n\nExamples:\n  ps30 render drawlists/lights.json\n  ps30 render drawlists/log-lights.json -o out/ --every-step\n  ps30 render drawlists/lights.json --json"
    )]
    Render(render::Args),
    /// Measure the alternatives to the article's methods, and the article's own chain, with a report page.
    #[command(
        after_help = "Studies:\n  mip-luminance  log-luminance in 8-bit alpha averaged by the mip chain, on every bundled\n                 image and two odd-sized crops, against the truth and the article's two passes\n  log-lights     lights as exp2(-light) multiplied into RGBA8, against raw RGBA8 and\n                 A16B16G16R16F: brightness 0.1, 1, 2, 3 and 1 to 8 overlapping lights\n  article-chain  lights of asm/lights/ added into A16B16G16R16F, L̄w, tone map (-o PNG)\n\nEach prints its numbers and writes reports/NAME.md with its figures (--reports DIR\nelsewhere). Exit 1 when a result is outside its derived bound or a cross-check disagrees.\n\nExamples:\n  ps30 study log-lights\n  ps30 study mip-luminance --json\n  ps30 study article-chain -o frame.png"
    )]
    Study(study::Args),
    /// Check every figure the article states and write the report to reports/.
    #[command(
        after_help = "Also regenerates the shaders of asm/generated/ in memory and fails (exit 1) if a\ncommitted file is missing, stale or unexpected; --regenerate rewrites them instead.\n\nExample:\n  ps30 verify --json"
    )]
    Verify(verify::Args),
    /// Generate pass-1 (unrolled and loop), last-column and pass-2 luminance shaders that fit the limits.
    #[command(
        after_help = "--fit: unrolled form = the widest unroll that fits the slot limit and the tallest block\nthat fits the executed limit and the rep-count range, lowered to the smallest height with\nas many block rows for the frame; loop form = the plan's best loop block for the frame.\nEvery shader is checked (front end + cost model) before it is printed; its header states\nits slots, executed count and the constants the application sets.\n\nExit codes: 0 every requested shader fits; 1 something requested does not fit (the\nreasons are printed, in numbers); 2 bad input.\n\nExamples:\n  ps30 unroll --fit\n  ps30 unroll --fit --frame 1920x1080 -o shaders/\n  ps30 unroll --block 128x56 --form loop --only pass1\n  ps30 unroll --fit --max-slots 1024 --macro"
    )]
    Unroll(unroll::Args),
    /// Rank block sizes, intermediate targets and pass-2 forms for a frame, and recommend one.
    #[command(
        after_help = "Exit codes: 0 a two-pass plan fits; 1 none does (a third pass would be needed, or\nnothing fits the profile); 2 bad input.\n\nExamples:\n  ps30 plan --frame 1280x1024\n  ps30 plan --frame 1920x1080 --max-slots 1024 --json"
    )]
    Plan(plan::Args),
    /// Print a shell-completion script (bash, zsh, fish, elvish, powershell).
    #[command(
        after_help = "Examples:\n  ps30 completions bash > ~/.local/share/bash-completion/completions/ps30\n  ps30 completions zsh > ~/.zfunc/_ps30\n  ps30 completions fish > ~/.config/fish/completions/ps30.fish"
    )]
    Completions(completions::Args),
    /// Print the manual page (roff), of ps30 or of one subcommand.
    #[command(
        after_help = "Examples:\n  ps30 man > ps30.1 && man ./ps30.1\n  ps30 man check | man -l -\n  for c in check run luminance; do ps30 man $c > ps30-$c.1; done"
    )]
    Man(man::Args),
}

/// Exit code of a run interrupted by a signal (128 + SIGINT, as shells
/// report a Ctrl-C).
pub const INTERRUPTED: i32 = 130;

/// On SIGINT, SIGTERM or SIGHUP: remove the temporary files of outputs
/// being written (nothing half-written stays behind) and exit with
/// [`INTERRUPTED`].
pub fn clean_up_on_interrupt() {
    // Without a handler (one cannot be installed) the default action still
    // ends the process; only its temporary files may stay.
    let _ = ctrlc::set_handler(|| {
        ps30::core::output::remove_temporaries();
        std::process::exit(INTERRUPTED);
    });
}

/// Bounds all of a command's parallel work — decoding, emulation,
/// cross-checks — to `threads` (`None`: all cores) by sizing rayon's global
/// pool, which the library's parallel code runs on. Called once, before any
/// work.
pub fn bound_threads(threads: Option<usize>) -> std::result::Result<(), BadInput> {
    match threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .map_err(|e| BadInput(format!("cannot start {n} worker threads: {e}"))),
        None => Ok(()),
    }
}

/// How a command ended.
pub enum Outcome {
    Ok,
    /// The check found a problem (exit 1).
    Problem,
    /// Some input was refused and its reasons are already printed (exit 2,
    /// corpus mode's mixed results).
    Refused,
    /// A tool the command needs is not installed (exit 3).
    Unavailable,
}

impl Outcome {
    /// `Ok` when `ok`, else `Problem`.
    pub fn from_ok(ok: bool) -> Outcome {
        if ok {
            Outcome::Ok
        } else {
            Outcome::Problem
        }
    }
}

/// A failure with exit code 2 (bad input or usage). Diagnostics were
/// already printed when `message` is empty.
pub struct BadInput(pub String);

impl<E: std::fmt::Display> From<E> for BadInput {
    fn from(e: E) -> Self {
        BadInput(e.to_string())
    }
}

/// What a subcommand's `run` returns.
pub type Result = std::result::Result<Outcome, BadInput>;
