//! Command-line values and the argument groups several subcommands share.
//!
//! Parsers for values (`WxH`, `cN=x,y,z,w` or `NAME=…`, `iN=…`, `bN=…`, `NAME=N`, δ, the
//! tone-mapping key and white point) and the flag groups (`-D`, constants,
//! limits, emulator bounds, sampler state) live here once, so that a value
//! means the same thing and fails with the same message wherever it is
//! given. Only the command line uses clap; the library sees plain values.

use super::BadInput;
use clap::Args;
use ps30::core::audit::Given;
use ps30::core::bytecode::ctab::{escape, ConstantTable, RegisterSet};
use ps30::core::cost::{Environment, Profile};
use ps30::core::emu::{self, Address, Constants, Filter, MipFilter, SamplerState};
use ps30::core::image::{MipChain, TargetFormat, TextureFile};
use ps30::core::input::DEFAULT_MAX_INPUT_BYTES;
use ps30::core::isa::SlotTable;
use ps30::core::load::Options;
use ps30::jobs::render::file;

/// `WxH` with both sides 1..=65536.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or("expected WxH, e.g. 64x64")?;
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

pub fn parse_finite(s: &str) -> Result<f32, String> {
    s.trim()
        .parse::<f32>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("`{s}` is not a finite number"))
}

/// One to four finite numbers separated by commas.
pub fn parse_float4(s: &str) -> Result<[f32; 4], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.is_empty() || parts.len() > 4 {
        return Err("expected one to four numbers separated by commas".into());
    }
    let mut v = [0f32; 4];
    for (slot, p) in v.iter_mut().zip(&parts) {
        *slot = parse_finite(p)?;
    }
    Ok(v)
}

pub fn parse_register(s: &str, prefix: char, count: u32) -> Result<u32, String> {
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

/// A constant on the command line: a register (`c3`) or the name of a
/// constant in the shader's constant table (`g_fKey`), resolved by
/// [`resolve`] once the shader is read.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstRef {
    Register(u32),
    Name(String),
}

/// `cN` (with its range checked) or a constant's name.
fn const_ref(s: &str, prefix: char, count: u32) -> Result<ConstRef, String> {
    let s = s.trim();
    if s.strip_prefix(prefix)
        .is_some_and(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()))
    {
        return parse_register(s, prefix, count).map(ConstRef::Register);
    }
    let name = s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_.[]".contains(c));
    if name {
        Ok(ConstRef::Name(s.to_string()))
    } else {
        Err(format!(
            "`{s}` is neither a register {prefix}N nor the name of a constant"
        ))
    }
}

/// `target=v,v,…`: the target and its comma-separated values, each read by
/// `value`; a register takes at most `per_register` values (a name takes as
/// many as its registers hold, checked by [`resolve`]).
fn const_values<T>(
    s: &str,
    prefix: char,
    count: u32,
    per_register: usize,
    value: impl Fn(&str) -> Result<T, String>,
) -> Result<(ConstRef, Vec<T>), String> {
    let (target, values) = s
        .split_once('=')
        .ok_or(format!("expected {prefix}N=… or NAME=…, e.g. {prefix}3=…"))?;
    let target = const_ref(target, prefix, count)?;
    let values = values
        .split(',')
        .map(|v| value(v.trim()))
        .collect::<Result<Vec<T>, String>>()?;
    if matches!(target, ConstRef::Register(_)) && values.len() > per_register {
        return Err(format!(
            "a register takes one to {per_register} value{}",
            if per_register == 1 { "" } else { "s" }
        ));
    }
    Ok((target, values))
}

/// `cN=X[,Y,Z,W]` or `NAME=X,…`.
pub fn parse_float_const(s: &str) -> Result<(ConstRef, Vec<f32>), String> {
    const_values(s, 'c', 224, 4, ps30::core::numbers::parse_constant)
}

/// `iN=X[,Y,Z,W]` or `NAME=X,…`.
pub fn parse_int_const(s: &str) -> Result<(ConstRef, Vec<i32>), String> {
    const_values(s, 'i', 16, 4, |v| {
        v.parse::<i32>()
            .map_err(|_| format!("`{v}` is not an integer"))
    })
}

/// `bN=true|false` or `NAME=true|false,…`.
pub fn parse_bool_const(s: &str) -> Result<(ConstRef, Vec<bool>), String> {
    const_values(s, 'b', 16, 1, |v| match v {
        "true" | "1" => Ok(true),
        "false" | "0" => Ok(false),
        other => Err(format!("`{other}` is not true or false")),
    })
}

/// The flag that sets a register set, for messages.
fn flag_of(set: RegisterSet) -> &'static str {
    match set {
        RegisterSet::Float4 => "--const",
        RegisterSet::Int4 => "--int",
        RegisterSet::Bool => "--bool",
        RegisterSet::Sampler => "no flag (ps30 binds the samplers itself)",
    }
}

/// Constants given by register or by name, as registers with `N` values
/// each (missing values 0). Names are looked up in the shader's constant
/// table; a name fills its registers in order, `N` values per register.
pub fn resolve<T: Copy + Default, const N: usize>(
    given: &[(ConstRef, Vec<T>)],
    set: RegisterSet,
    table: Option<&ConstantTable>,
) -> Result<Vec<(u32, [T; N])>, BadInput> {
    let flag = flag_of(set);
    let mut out = Vec::new();
    for (target, values) in given {
        let (first, registers) = match target {
            ConstRef::Register(r) => (*r, 1),
            ConstRef::Name(name) => {
                let Some(t) = table else {
                    return Err(BadInput(format!(
                        "{flag} {name}: the shader has no constant table (CTAB) to look the name up in; give a register"
                    )));
                };
                let Some(c) = t.constants.iter().find(|c| &c.name == name) else {
                    // Names come from the file: escaped, so that none can
                    // drive the terminal or fake a line of output.
                    let names: Vec<String> = t.constants.iter().map(|c| escape(&c.name)).collect();
                    return Err(BadInput(format!(
                        "{flag} {name}: the shader's constant table has no `{name}` (it has {})",
                        names.join(", ")
                    )));
                };
                if c.set != set {
                    return Err(BadInput(format!(
                        "{flag} {name}: `{name}` is a {} constant ({}); set it with {}",
                        c.set.name(),
                        c.register(),
                        flag_of(c.set)
                    )));
                }
                (c.index as u32, c.count as usize)
            }
        };
        if values.len() > registers * N {
            return Err(BadInput(format!(
                "{flag}: {} values, but the target takes {registers} register{} of {N}",
                values.len(),
                if registers == 1 { "" } else { "s" }
            )));
        }
        for (k, chunk) in values.chunks(N).enumerate() {
            let mut v = [T::default(); N];
            v[..chunk.len()].copy_from_slice(chunk);
            out.push((first + k as u32, v));
        }
    }
    Ok(out)
}

/// `NAME=N`.
pub fn parse_define(s: &str) -> Result<(String, u64), String> {
    let (name, value) = s.split_once('=').ok_or("expected NAME=N, e.g. xsize=11")?;
    let valid = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(format!("`{name}` is not a valid name"));
    }
    let v = value
        .trim()
        .parse::<u64>()
        .map_err(|_| format!("`{value}` is not a non-negative integer"))?;
    Ok((name.to_string(), v))
}

/// δ of `log(δ + L)`: positive and finite.
pub fn parse_delta(s: &str) -> Result<f32, String> {
    let v: f32 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(format!("δ must be a positive finite number, not {s}"))
    }
}

/// The tone-mapping key a.
pub fn parse_key(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    ps30::jobs::tonemap::check_values(v, None)
        .map(|_| v)
        .map_err(|e| e.to_string())
}

/// The tone-mapping white point: a positive luminance or `inf`.
pub fn parse_white(s: &str) -> Result<f64, String> {
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

/// `-D` and the expansion cap: how the front end reads a source.
#[derive(Args)]
pub struct SourceArgs {
    /// Bind a REPEAT_BLOCK count name, e.g. -D xsize=11.
    #[arg(short = 'D', value_name = "NAME=N", value_parser = parse_define)]
    pub define: Vec<(String, u64)>,
    /// Cap on the statements REPEAT_BLOCK expansion may produce.
    #[arg(long, value_name = "N", default_value_t = ps30::core::front::repeat::DEFAULT_MAX_EXPANDED)]
    pub max_expanded: u64,
    /// Refuse what Microsoft's documentation forbids but its assembler
    /// accepts (reads of unwritten temporaries, oC# written in branches,
    /// mixed _abs constant reads…): those warnings become errors.
    #[arg(long)]
    pub strict: bool,
    /// The capabilities a ps_2_x shader is held to, as a device has them:
    /// predication, gradients, arbitrary-swizzle, no-dependent-read-limit,
    /// no-texture-instruction-limit, temps=N, slots=N, static-flow=N,
    /// dynamic-flow=N (D3DPS20CAPS names too), from the least a ps_2_x device has;
    /// or a named set: assembler (the default: what Microsoft's assembler assumes),
    /// ps_2_a, ps_2_b, minimum.
    #[arg(long, value_name = "LIST", value_parser = ps30::core::profile::Ps2xCaps::parse)]
    pub caps: Option<ps30::core::profile::Ps2xCaps>,
    /// The range of a ps_1_x shader's registers when it runs:
    /// D3DCAPS9.PixelShader1xMaxValue, at least 1 (8 by default, what a
    /// ps_1_4 device must have).
    #[arg(long, value_name = "V", value_parser = parse_ps1_max, default_value_t = ps30::core::ps1::run::DEFAULT_MAX_VALUE)]
    pub ps1_max_value: f32,
}

/// `--ps1-max-value`: a finite number of at least 1 (Direct3D 9: "the value
/// is >= 1.0 for any hardware that supports pixel shaders").
fn parse_ps1_max(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(v) if v.is_finite() && v >= 1.0 => Ok(v),
        _ => Err(format!(
            "`{text}`: PixelShader1xMaxValue is a finite number of at least 1"
        )),
    }
}

impl SourceArgs {
    /// The front end's options.
    pub fn options(&self) -> Options {
        Options {
            defines: self.define.iter().cloned().collect(),
            max_expanded: self.max_expanded,
            strict: self.strict,
            caps: self.caps,
            ps1_max_value: self.ps1_max_value,
        }
    }
}

/// The cap on shader files read from disk.
#[derive(Args, Debug)]
pub struct InputArgs {
    /// Refuse shader files and draw lists larger than this many bytes.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_INPUT_BYTES, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_input_bytes: u64,
}

/// Float, integer and boolean constants set by the application.
#[derive(Args)]
pub struct ConstantArgs {
    /// Float constant set by the application, by register or by its name in the
    /// shader's constant table, e.g. --const c3=0.27,0.67,0.06,0.01. Any 32-bit
    /// pattern, as Direct3D 9 takes it: inf, -inf, nan or bits (0x7f800000).
    #[arg(long = "const", value_name = "cN|NAME=X[,Y,Z,W]", value_parser = parse_float_const)]
    pub floats: Vec<(ConstRef, Vec<f32>)>,
    /// Integer constant set by the application, by register or by its name in the
    /// shader's constant table, e.g. --int i1=128 or --int i0=16,0,1,0.
    #[arg(long = "int", value_name = "iN|NAME=X[,Y,Z,W]", value_parser = parse_int_const)]
    pub ints: Vec<(ConstRef, Vec<i32>)>,
    /// Boolean constant set by the application, by register or by name, e.g. --bool b0=true.
    #[arg(long = "bool", value_name = "bN|NAME=true|false", value_parser = parse_bool_const)]
    pub bools: Vec<(ConstRef, Vec<bool>)>,
}

impl ConstantArgs {
    /// The constants as registers, names looked up in the shader's table.
    pub fn resolve(&self, table: Option<&ConstantTable>) -> Result<Resolved, BadInput> {
        Resolved::new(&self.floats, &self.ints, &self.bools, table)
    }
}

/// Float, integer and boolean constants as registers (names resolved).
pub struct Resolved {
    pub floats: Vec<(u32, [f32; 4])>,
    pub ints: Vec<(u32, [i32; 4])>,
    pub bools: Vec<(u32, bool)>,
}

impl Resolved {
    /// Resolves `--const`, `--int` and `--bool` against a constant table.
    pub fn new(
        floats: &[(ConstRef, Vec<f32>)],
        ints: &[(ConstRef, Vec<i32>)],
        bools: &[(ConstRef, Vec<bool>)],
        table: Option<&ConstantTable>,
    ) -> Result<Resolved, BadInput> {
        Ok(Resolved {
            floats: resolve::<f32, 4>(floats, RegisterSet::Float4, table)?,
            ints: resolve::<i32, 4>(ints, RegisterSet::Int4, table)?,
            bools: resolve::<bool, 1>(bools, RegisterSet::Bool, table)?
                .into_iter()
                .map(|(r, [b])| (r, b))
                .collect(),
        })
    }

    /// The register files of a draw (registers nobody set stay 0, as in a
    /// draw; the audit refuses a run that reads one).
    pub fn constants(&self) -> Constants {
        constants(&self.floats, &self.ints, &self.bools)
    }

    /// What the application gives, for the audit: these registers, the
    /// `-D` names, and `preset_floats`, which the command sets itself.
    pub fn given(&self, preset_floats: &[u32], source: &SourceArgs) -> Given {
        Given {
            floats: self.floats.iter().map(|c| c.0).collect(),
            preset_floats: preset_floats.iter().copied().collect(),
            ints: self.ints.iter().map(|c| c.0).collect(),
            bools: self.bools.iter().map(|c| c.0).collect(),
            defines: source.define.iter().map(|(n, _)| n.clone()).collect(),
        }
    }

    /// The integer and boolean constants the cost model may use.
    pub fn environment(&self) -> Environment {
        Environment {
            ints: self.ints.iter().copied().collect(),
            bools: self.bools.iter().copied().collect(),
        }
    }
}

/// The register files of a draw from `--const`, `--int` and `--bool` values
/// (registers nobody set stay 0, as in a draw).
pub fn constants(
    floats: &[(u32, [f32; 4])],
    ints: &[(u32, [i32; 4])],
    bools: &[(u32, bool)],
) -> Constants {
    fn set<T: Copy>(file: &mut Vec<T>, zero: T, i: u32, v: T) {
        let i = i as usize;
        file.resize(file.len().max(i + 1), zero);
        file[i] = v;
    }
    let mut c = Constants::default();
    for &(i, v) in floats {
        set(&mut c.float, [0.0; 4], i, v);
    }
    for &(i, v) in ints {
        set(&mut c.int, [0; 4], i, v);
    }
    for &(i, v) in bools {
        set(&mut c.bool, false, i, v);
    }
    c
}

/// `ps30 check`'s limits.
#[derive(Args)]
pub struct LimitArgs {
    /// Instruction-slot limit (ps_3_0 guarantees 512).
    #[arg(long, value_name = "N", default_value_t = 512, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_slots: u64,
    /// Executed-instruction limit (65,535 in the article; Microsoft: at least 2^16).
    #[arg(long, value_name = "N", default_value_t = 65_535, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_executed: u64,
}

/// The limits of a ps_3_0 part, for `unroll` and `plan`.
#[derive(Args)]
pub struct ProfileArgs {
    /// Instruction slots (ps_3_0 guarantees 512; parts may have up to 32,768).
    #[arg(long, value_name = "N", default_value_t = 512, value_parser = clap::value_parser!(u64).range(1..=32_768))]
    pub max_slots: u64,
    /// Executed instructions per pixel (65,535 in the article).
    #[arg(long, value_name = "N", default_value_t = 65_535, value_parser = clap::value_parser!(u64).range(1..=4_294_967_295))]
    pub max_executed: u64,
    /// Largest rep count (ps_3_0 allows 0 to 255).
    #[arg(long, value_name = "N", default_value_t = 255, value_parser = clap::value_parser!(u32).range(1..=255))]
    pub max_rep_count: u32,
    /// Deepest rep/loop nesting (ps_3_0 allows 4).
    #[arg(long, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=4))]
    pub max_nesting: u32,
}

impl ProfileArgs {
    /// The profile these flags describe (named "custom" unless it is ps_3_0's),
    /// counting with the generator's slot table (`gen::FIT_TABLE`).
    pub fn profile(&self) -> Profile {
        let base = ps30::jobs::gen::fitting_profile();
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

/// Options of every command that loads an image and runs the emulator.
#[derive(Args, Debug)]
pub struct ExecArgs {
    /// Threads for all of the command's work: decoding, emulation, cross-checks (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    pub threads: Option<u32>,
    /// Refuse images with more pixels than this.
    #[arg(long, value_name = "N", default_value_t = ps30::core::image::ImageLimits::MAX_PIXELS, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_pixels: u64,
    /// Stop a pixel that executes more instruction slots than this.
    #[arg(long, value_name = "N", default_value_t = emu::EmuLimits::MAX_EXECUTED_PER_PIXEL, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_executed_per_pixel: u64,
    /// Refuse render targets with more pixels than this.
    #[arg(long, value_name = "N", default_value_t = emu::EmuLimits::MAX_TARGET_PIXELS, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_target_pixels: u64,
    /// Stop a draw that executes more instruction slots than this, all pixels together.
    #[arg(long, value_name = "N", default_value_t = emu::EmuLimits::MAX_EXECUTED_TOTAL, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_executed_total: u64,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

impl ExecArgs {
    /// The emulator's bounds.
    pub fn limits(&self) -> emu::EmuLimits {
        emu::EmuLimits {
            max_executed_per_pixel: self.max_executed_per_pixel,
            max_target_pixels: self.max_target_pixels,
            max_executed_total: self.max_executed_total,
        }
    }

    /// The image loader's bounds.
    pub fn image_limits(&self) -> ps30::core::image::ImageLimits {
        ps30::core::image::ImageLimits {
            max_pixels: self.max_pixels,
        }
    }

    /// Emulator threads, `None` for all cores.
    pub fn threads(&self) -> Option<usize> {
        self.threads.map(|t| t as usize)
    }
}

/// s0's sampler state for commands that draw over an image.
#[derive(Args)]
pub struct SamplerArgs {
    /// s0's MAGFILTER and MINFILTER: point (nearest texel) or linear (bilinear).
    #[arg(long, value_enum, default_value = "point")]
    pub filter: FilterArg,
    /// s0's ADDRESSU and ADDRESSV: what a read outside [0, 1] returns.
    #[arg(long, value_enum, value_name = "MODE", default_value = "border")]
    pub address: AddressArg,
    /// Border colour R,G,B,A for --address border.
    #[arg(long, value_name = "R,G,B,A", value_parser = parse_float4, default_value = "0,0,0,0", allow_negative_numbers = true)]
    pub border: [f32; 4],
}

impl SamplerArgs {
    /// The sampler state these flags describe (no mips).
    pub fn state(&self) -> SamplerState {
        let address = self.address.into();
        SamplerState {
            address_u: address,
            address_v: address,
            address_w: address,
            border: self.border,
            ..SamplerState::filtered(self.filter.into())
        }
    }
}

/// Which slot table `--slots` chooses for a verdict.
#[derive(Clone, Copy, Debug, Default, clap::ValueEnum)]
pub enum SlotsArg {
    /// Microsoft's count, as D3DDisassemble and fxc print it.
    #[default]
    Fxc,
    /// The per-instruction table of Microsoft's ps_3_0 documentation.
    Documented,
}

impl From<SlotsArg> for SlotTable {
    fn from(s: SlotsArg) -> Self {
        match s {
            SlotsArg::Fxc => SlotTable::Fxc,
            SlotsArg::Documented => SlotTable::Documented,
        }
    }
}

/// Render-target formats.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum FormatArg {
    /// D3DFMT_R32F: one 32-bit float channel (red).
    F32,
    /// D3DFMT_A16B16G16R16F: four half-float channels, ±65,504 at most.
    F16,
}

impl From<FormatArg> for TargetFormat {
    fn from(f: FormatArg) -> Self {
        match f {
            FormatArg::F32 => TargetFormat::R32F,
            FormatArg::F16 => TargetFormat::Rgba16F,
        }
    }
}

/// MAGFILTER / MINFILTER.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum FilterArg {
    /// The nearest texel.
    Point,
    /// Bilinear: the four nearest texels, weighted.
    Linear,
}

impl From<FilterArg> for Filter {
    fn from(f: FilterArg) -> Self {
        match f {
            FilterArg::Point => Filter::Point,
            FilterArg::Linear => Filter::Linear,
        }
    }
}

/// MIPFILTER.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum MipFilterArg {
    /// Level 0 only.
    None,
    /// The nearest level.
    Point,
    /// A blend of the two nearest levels.
    Linear,
}

impl From<MipFilterArg> for MipFilter {
    fn from(f: MipFilterArg) -> Self {
        match f {
            MipFilterArg::None => MipFilter::None,
            MipFilterArg::Point => MipFilter::Point,
            MipFilterArg::Linear => MipFilter::Linear,
        }
    }
}

/// ADDRESSU / ADDRESSV.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum AddressArg {
    /// The border colour (--border).
    Border,
    /// The nearest edge texel.
    Clamp,
    /// Repeat the image.
    Wrap,
    /// Repeat, every other copy mirrored.
    Mirror,
    /// Mirror once about 0, then clamp.
    Mirroronce,
}

impl From<AddressArg> for Address {
    fn from(a: AddressArg) -> Self {
        match a {
            AddressArg::Border => Address::Border,
            AddressArg::Clamp => Address::Clamp,
            AddressArg::Wrap => Address::Wrap,
            AddressArg::Mirror => Address::Mirror,
            AddressArg::Mirroronce => Address::MirrorOnce,
        }
    }
}

/// `--float-rules`: the special values the emulator and the translation
/// compute (see `ps30::core::float_rules`).
#[derive(Clone, Copy, Debug, Default, clap::ValueEnum)]
pub enum FloatRulesArg {
    /// Microsoft's instruction pages: log(0) = -FLT_MAX, |x| in log and rsq, nrm(0) scaled by FLT_MAX.
    D3d9,
    /// Plain IEEE results.
    Ieee,
    /// d3d9, and a product with a zero factor is 0 (0 × inf = 0).
    D3d9ZeroMul,
    /// What Direct3D 9 hardware computes (the default): d3d9-zero-mul, and denormals flushed to zero in and out.
    #[default]
    Hardware,
}

impl From<FloatRulesArg> for ps30::core::float_rules::FloatRules {
    fn from(r: FloatRulesArg) -> Self {
        use ps30::core::float_rules::FloatRules;
        match r {
            FloatRulesArg::D3d9 => FloatRules::D3d9,
            FloatRulesArg::Ieee => FloatRules::Ieee,
            FloatRulesArg::D3d9ZeroMul => FloatRules::D3d9ZeroMul,
            FloatRulesArg::Hardware => FloatRules::Hardware,
        }
    }
}

/// `--backend`: who draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum BackendArg {
    /// The CPU emulator.
    #[default]
    Emulator,
    /// A GPU through Vulkan (Mesa's llvmpipe is one, on the CPU).
    Gpu,
}

/// Who draws, and with which float rules (run, luminance, tonemap).
#[derive(Args)]
pub struct BackendArgs {
    /// Draw on the emulator (default) or on a GPU through Vulkan, with the translated shader.
    #[arg(long, value_enum, default_value = "emulator")]
    pub backend: BackendArg,
    /// Special values: hardware (what Direct3D 9 hardware computes, the default), d3d9 (Microsoft's pages), ieee, or d3d9-zero-mul.
    #[arg(long, value_enum, default_value = "hardware")]
    pub float_rules: FloatRulesArg,
}

impl BackendArgs {
    /// The backend; opening a GPU that is not there is bad input (exit 2),
    /// with a message that says how to get one.
    pub fn open(&self) -> Result<ps30::jobs::backend::Backend, super::BadInput> {
        use ps30::jobs::backend::Backend;
        Ok(match self.backend {
            BackendArg::Emulator => Backend::Emulator,
            BackendArg::Gpu => Backend::Gpu(open_kept()?),
        })
    }

    /// The backend, a GPU opening on a thread of its own while `work`
    /// (decoding the image) and whatever the command does before its first
    /// draw run on this one: a GPU driver takes a large part of a second to
    /// start. A device that fails to open fails the first draw; the command
    /// then reports it as [`open`](Self::open) does ([`opening_failed`]).
    pub fn open_beside<T>(
        &self,
        work: impl FnOnce() -> T,
    ) -> (Result<ps30::jobs::backend::Backend, super::BadInput>, T) {
        use ps30::jobs::backend::Backend;
        if matches!(self.backend, BackendArg::Emulator) {
            return (self.open(), work());
        }
        let opening = ps30::core::gpu::Opening::start(open_kept);
        let done = work();
        (Ok(Backend::Opening(std::sync::Arc::new(opening))), done)
    }

    pub fn rules(&self) -> ps30::core::float_rules::FloatRules {
        self.float_rules.into()
    }
}

/// A GPU opened for the rest of the process: it lives until the process
/// ends, and the OS takes it back then — closing it first (the driver
/// freeing a 4K frame's buffers) took 40 ms of a 3840×2160 tone map on an
/// H100 (docs/speed.md).
fn open_kept() -> Result<std::sync::Arc<ps30::core::gpu::Gpu>, ps30::core::gpu::GpuError> {
    let g = std::sync::Arc::new(ps30::core::gpu::Gpu::open()?);
    std::mem::forget(g.clone());
    Ok(g)
}

/// A job's error, or the device's when the backend failed to open (the job
/// stopped at its first draw): the message and exit code of
/// [`BackendArgs::open`].
pub fn opening_failed(
    backend: &ps30::jobs::backend::Backend,
    job: impl std::fmt::Display,
) -> BadInput {
    match backend.open_error() {
        Some(e) => BadInput::from(e),
        None => BadInput::from(job),
    }
}

/// Reads `--inputs FILE` (constants, textures and sampler states in the
/// draw-list step format), if given.
pub fn read_inputs(path: Option<&std::path::Path>) -> Result<Option<file::Inputs>, BadInput> {
    path.map(|p| {
        file::read_inputs(p, &file::FileLimits::default()).map_err(|e| BadInput(e.to_string()))
    })
    .transpose()
}

/// What the application gives, for the audit: the flags' registers and the
/// inputs file's.
pub fn given_with(flags: &Resolved, source: &SourceArgs, inputs: &Option<file::Inputs>) -> Given {
    let mut given = flags.given(&[], source);
    if let Some(i) = inputs {
        given.floats.extend(&i.given[0]);
        given.ints.extend(&i.given[1]);
        given.bools.extend(&i.given[2]);
    }
    given
}

/// The inputs file's constants under the command line's (`--const`,
/// `--int`, `--bool` win where both set a register), and its textures.
pub fn with_inputs(
    flags: &Resolved,
    inputs: Option<file::Inputs>,
) -> (Constants, Vec<(u32, TextureFile, SamplerState)>) {
    let Some(inputs) = inputs else {
        return (flags.constants(), Vec::new());
    };
    let mut c = inputs.constants;
    fn set<T: Copy + Default>(file: &mut Vec<T>, i: u32, v: T) {
        let i = i as usize;
        if file.len() <= i {
            file.resize(i + 1, T::default());
        }
        file[i] = v;
    }
    for &(i, v) in &flags.floats {
        set(&mut c.float, i, v);
    }
    for &(i, v) in &flags.ints {
        set(&mut c.int, i, v);
    }
    for &(i, v) in &flags.bools {
        set(&mut c.bool, i, v);
    }
    let textures = inputs
        .samplers
        .into_iter()
        .map(|(s, t, state)| {
            let file = t.file.unwrap_or_else(|| {
                TextureFile::Flat(
                    MipChain::from_levels(vec![(t.width, t.height, t.texels)])
                        .expect("a loaded image is a valid level"),
                )
            });
            (s, file, state)
        })
        .collect();
    (c, textures)
}
