//! `ps30 profile`: per-pixel and per-quad costs over an image or the
//! light-model G-buffer, divergence, and gradients that rely on undefined
//! behaviour.

use super::args::{
    parse_bool_const, parse_define, parse_finite, parse_float4, parse_float_const, parse_int_const,
    parse_size, AddressArg, ConstRef, ExecArgs, FilterArg, InputArgs, MipFilterArg, Resolved,
};
use super::io::{color_stderr, print, print_json, shader_source};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::emu::SamplerState;
use ps30::core::image;
use ps30::core::load;
use ps30::jobs::profile::{profile_file, Input, Setup};
use ps30::present::profile::{text, to_json};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Shader file or bundled name (corrected:unrolled, lights:select, lights:texld, …).
    shader: String,
    /// Run on the synthetic G-buffer of the light-model shaders (asm/lights/), WxH pixels.
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with_all = ["image", "target"], required_unless_present = "image")]
    gbuffer: Option<(u32, u32)>,
    /// Image sampled by s0; pixel (x, y) of the target gets v0.xy = the centre of the
    /// top-left texel of its block of the image, as in `ps30 run`.
    #[arg(long, requires = "target")]
    image: Option<std::path::PathBuf>,
    /// Render-target size WxH (with --image).
    #[arg(long, value_name = "WxH", value_parser = parse_size, requires = "image")]
    target: Option<(u32, u32)>,
    /// Bind a REPEAT_BLOCK count name, e.g. -D xsize=11.
    #[arg(short = 'D', value_name = "NAME=N", value_parser = parse_define)]
    define: Vec<(String, u64)>,
    /// Integer constant, by register or by name, e.g. --int i2=128 or --int i0=16,0,1,0.
    #[arg(long = "int", value_name = "iN|NAME=X[,Y,Z,W]", value_parser = parse_int_const)]
    ints: Vec<(ConstRef, Vec<i32>)>,
    /// Boolean constant, by register or by name, e.g. --bool b0=true.
    #[arg(long = "bool", value_name = "bN|NAME=true|false", value_parser = parse_bool_const)]
    bools: Vec<(ConstRef, Vec<bool>)>,
    /// Float constant, by register or by its name in the shader's constant table,
    /// e.g. --const c3=0.27,0.67,0.06,0.01 or --const g_fKey=0.18.
    #[arg(long = "const", value_name = "cN|NAME=X[,Y,Z,W]", value_parser = parse_float_const)]
    floats: Vec<(ConstRef, Vec<f32>)>,
    /// s0's MAGFILTER and MINFILTER (with --image).
    #[arg(long, value_enum, default_value = "point")]
    filter: FilterArg,
    /// s0's addressing (with --image).
    #[arg(long, value_enum, default_value = "border")]
    address: AddressArg,
    /// Border colour R,G,B,A for --address border.
    #[arg(long, value_parser = parse_float4, default_value = "0,0,0,0")]
    border: [f32; 4],
    /// Give s0 a full box-filtered mip chain (with --image).
    #[arg(long)]
    mips: bool,
    /// s0's MIPFILTER.
    #[arg(long, value_enum, default_value = "none")]
    mip_filter: MipFilterArg,
    /// s0's MIPMAPLODBIAS.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true, value_parser = parse_finite)]
    lod_bias: f32,
    /// s0's MAXMIPLEVEL (the most detailed level allowed).
    #[arg(long, default_value_t = 0)]
    max_mip_level: u32,
    /// Histogram bins.
    #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u64).range(1..=1000))]
    bins: u64,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    input: InputArgs,
}

impl Args {
    /// s0's sampler state from the flags.
    fn sampler(&self) -> SamplerState {
        let address = self.address.into();
        SamplerState {
            mip_filter: self.mip_filter.into(),
            mip_lod_bias: self.lod_bias,
            max_mip_level: self.max_mip_level,
            address_u: address,
            address_v: address,
            border: self.border,
            ..SamplerState::filtered(self.filter.into())
        }
    }

    fn input(&self) -> Result<Input, BadInput> {
        Ok(match (self.gbuffer, &self.image, self.target) {
            (Some((w, h)), _, _) => Input::GBuffer(w, h),
            (None, Some(path), Some(target)) => Input::Image {
                image: image::load(path, &self.exec.image_limits())?,
                name: path.display().to_string(),
                target,
                sampler: self.sampler(),
                mips: self.mips,
            },
            _ => {
                return Err(BadInput(
                    "give --gbuffer WxH, or --image IMG with --target WxH".into(),
                ))
            }
        })
    }
}

/// Validator warnings to stderr, the report to stdout; exit 1 when the run
/// found a problem.
pub fn run(args: Args, _ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    let src = shader_source(&args.shader, args.input.max_input_bytes)?;
    let setup = Setup {
        input: args.input()?,
        defines: args.define.clone(),
        constants: Resolved::new(
            &args.floats,
            &args.ints,
            &args.bools,
            load::constant_table_of(&src.file).as_ref(),
        )?
        .constants(),
        bins: args.bins as usize,
        threads: args.exec.threads(),
        limits: args.exec.limits(),
    };
    let r = profile_file(src.file, &setup).map_err(BadInput)?;
    r.warnings.emit(&r.file, color_stderr());
    if args.exec.json {
        print_json(&to_json(&r))?;
    } else {
        print(&text(&r))?;
    }
    Ok(Outcome::from_ok(!r.problem()))
}
