//! The draw-list file a user writes: JSON with named targets, textures and
//! steps, read into a checked [`DrawList`]. Every problem is reported with
//! the file and where in it (`steps[3].samplers.s0.texture: …`, or the line
//! and column for JSON syntax), before anything runs.
//!
//! ```json
//! {
//!   "description": "two lights added into a half-float target",
//!   "targets":  [ { "name": "light", "size": "64x64", "format": "A16B16G16R16F" } ],
//!   "textures": [ { "name": "gbuffer", "synthetic": "lights-gbuffer", "size": "64x64" } ],
//!   "steps": [
//!     { "clear": "light", "color": [0, 0, 0, 0] },
//!     { "draw": "light", "shader": "lights:directional",
//!       "inputs": { "v0": "texcoord" },
//!       "constants": { "c5": [0.48, 0.6, 0.64, 0], "c7": [1, 1, 1, 1] },
//!       "samplers": { "s0": { "texture": "gbuffer", "address": "clamp" } },
//!       "blend": { "src": "ONE", "dest": "ONE", "op": "ADD" } },
//!     { "mips": "light" }
//!   ]
//! }
//! ```
//!
//! * **targets**: `name`, `size` (`WxH`), `format` (a D3D9 name, with or
//!   without `D3DFMT_`). Targets start cleared to 0.
//! * **textures**: `name` and either `image` (an OpenEXR, Radiance, PFM or
//!   DDS file — DDS with its cube faces, volume slices and authored mips —
//!   relative to the draw-list file) or `synthetic`:
//!   `lights-gbuffer` (with `size`) or `lights-material-0` … `-2`, the inputs
//!   of `asm/lights/` ([`crate::jobs::scenes::lights`]).
//! * **steps**, each one of:
//!   * `{"clear": TARGET, "color": [R, G, B, A]}` — a D3DCOLOR, bytes 0–255
//!     (default 0, 0, 0, 0);
//!   * `{"draw": TARGET, "shader": …, …}` — `shader` is a bundled name or a
//!     file; `defines` (REPEAT_BLOCK counts), `inputs` (`"v0": "texcoord"` for
//!     pixel centres in [0, 1], or `{"base": […], "ddx": […], "ddy": […]}`;
//!     an input is named by register — `v#`, and `t#` in ps_2_0/ps_2_x —
//!     or by semantic, `texcoordN`/`colorN`: `core/pixel_inputs.rs`),
//!     `constants` (`"c5": [x, y, z, w]`, a component a number or a string
//!     for any bit pattern: `"inf"`, `"-inf"`, `"nan"`, `"0x7f800000"`), `ints`, `bools`, `samplers`
//!     (`"s0": {"texture": NAME, "filter": "point"|"linear", "mip":
//!     "none"|"point"|"linear", "address": "wrap"|"mirror"|"clamp"|"border"|
//!     "mirroronce", "border": [r, g, b, a], "lod_bias": B, "max_mip_level":
//!     N}`, with `address_u`, `address_v`, `address_w`, `min_filter` and
//!     `mag_filter` to set one axis or filter apart, and `bump_matrix`,
//!     `bump_lscale`, `bump_loffset` for the stage's bump-environment state
//!     (ps_1_x; written to c12–c23, `core/ps1/run.rs`) (`render/textures.rs`);
//!     NAME is a texture or an earlier target; unset states take
//!     Direct3D 9's defaults: point, no mips, wrap), `blend` (`src`, `dest`,
//!     `op`, optional `alpha` with its own `src`, `dest`, `op` for
//!     SEPARATEALPHABLENDENABLE, optional `factor` bytes; absent: blending
//!     off), `write` (COLORWRITEENABLE letters, default `rgba`), and the
//!     pixel state of `pixel_state.rs`: `float_rules`, `alpha_test`
//!     (`{"func": "GREATEREQUAL", "ref": 128}`), `outputs` (`{"oC1":
//!     TARGET, "oC2": {"target": TARGET, "write": "rg"}}`), `clip_planes`
//!     (`[{"base": B, "ddx": X, "ddy": Y}]`) and `shade` (`"flat"`);
//!   * `{"mips": TARGET, "odd": "fold"|"bilinear"}` — reduce the target
//!     through its mip chain (default `fold`).

use super::input_values::Given;
use super::textures::FileSampler;
use super::{DrawList, DrawStep, ShaderSpec, Source, Step, TargetSpec, TextureData};
use crate::core::emu::{Constants, Filter, LinearInput, MipFilter, SamplerState};
use crate::core::image::{ImageLimits, OddSides, TargetFormat};
use crate::core::load::{self, Options};
use crate::core::merge::{BlendFactor, BlendOp, BlendState, ColorWrite, Equation, OutputState};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Bounds on what a file may ask for, checked before anything is allocated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileLimits {
    /// Pixels of every target and texture together (16 bytes each).
    pub max_pixels: u64,
    /// Steps in the list.
    pub max_steps: usize,
    /// Bytes of the list itself and of every shader file it names
    /// (`--max-input-bytes`, the cap every shader file is read under).
    pub max_input_bytes: u64,
}

impl Default for FileLimits {
    /// As many pixels as one image may have ([`ImageLimits::MAX_PIXELS`]),
    /// 10,000 steps.
    fn default() -> FileLimits {
        FileLimits {
            max_pixels: ImageLimits::MAX_PIXELS,
            max_steps: 10_000,
            max_input_bytes: crate::core::input::DEFAULT_MAX_INPUT_BYTES,
        }
    }
}

/// A problem in a draw-list file: the file, where in it, and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    /// The draw-list file.
    pub path: PathBuf,
    /// Where in it: `line L column C` for JSON errors, the field path
    /// (`textures[0].size`) for the rest; empty when the whole file is at fault.
    pub at: String,
    /// What is wrong, in one sentence.
    pub message: String,
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.at.is_empty() {
            write!(f, "{}: {}", self.path.display(), self.message)
        } else {
            write!(f, "{}: {}: {}", self.path.display(), self.at, self.message)
        }
    }
}

impl std::error::Error for FileError {}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileList {
    #[serde(default)]
    description: Option<String>,
    targets: Vec<FileTarget>,
    #[serde(default)]
    textures: Vec<FileTexture>,
    steps: Vec<FileStep>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileTarget {
    name: String,
    size: String,
    format: String,
    /// Refused beyond one sample (`super::multisample`).
    multisample: Option<serde_json::Value>,
    multisample_quality: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileTexture {
    name: String,
    image: Option<String>,
    synthetic: Option<String>,
    size: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileStep {
    clear: Option<String>,
    color: Option<[u8; 4]>,
    draw: Option<String>,
    shader: Option<String>,
    defines: Option<BTreeMap<String, u64>>,
    inputs: Option<BTreeMap<String, FileInput>>,
    constants: Option<BTreeMap<String, Vec<super::floats::FileFloat>>>,
    ints: Option<BTreeMap<String, Vec<i32>>>,
    bools: Option<BTreeMap<String, bool>>,
    samplers: Option<BTreeMap<String, FileSampler>>,
    blend: Option<FileBlend>,
    write: Option<String>,
    float_rules: Option<String>,
    alpha_test: Option<super::pixel_state::FileAlphaTest>,
    outputs: Option<BTreeMap<String, super::pixel_state::FileOutput>>,
    clip_planes: Option<Vec<super::pixel_state::FileClipPlane>>,
    shade: Option<String>,
    geometry: Option<super::geometry::FileGeometry>,
    mips: Option<String>,
    odd: Option<String>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum FileInput {
    Named(String),
    Linear {
        base: Vec<f64>,
        #[serde(default)]
        ddx: Vec<f64>,
        #[serde(default)]
        ddy: Vec<f64>,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileEquation {
    src: String,
    dest: String,
    #[serde(default)]
    op: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileBlend {
    src: String,
    dest: String,
    #[serde(default)]
    op: Option<String>,
    alpha: Option<FileEquation>,
    factor: Option<[u8; 4]>,
}

/// A draw list read from a file, with its description.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The file's `description`, if it has one.
    pub description: Option<String>,
    /// The list, ready to run: images read, shaders loaded.
    pub list: DrawList,
    /// The files it read besides itself (images, shaders): a command must not
    /// write over them.
    pub sources: Vec<PathBuf>,
    /// Warnings of the constants audit (see [`crate::core::audit`]): values
    /// a draw gives that its shader's `def` overrides or never reads, `-D`
    /// names it never uses, each prefixed with the step's field.
    pub warnings: Vec<String>,
}

/// Reads and checks a draw-list file. Images and shader files are read
/// relative to the file's directory.
pub fn read(path: &Path, limits: &FileLimits) -> Result<Loaded, FileError> {
    let fail = |at: &str, message: String| FileError {
        path: path.to_path_buf(),
        at: at.to_string(),
        message,
    };
    let mut bytes = std::fs::File::open(path)
        .map_err(|e| e.to_string())
        .and_then(|f| crate::core::input::read_capped(f, "draw list", limits.max_input_bytes))
        .map_err(|e| fail("", e))?;
    // A UTF-8 byte-order mark (editors on Windows write one) is not JSON,
    // but it says nothing the text does not: it is dropped.
    if bytes.starts_with(b"\xEF\xBB\xBF") {
        bytes.drain(..3);
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        fail(
            "",
            format!(
                "not UTF-8 text (invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            ),
        )
    })?;
    parse(&text, path, limits)
}

/// Constants, textures and sampler states for one draw, read from a file in
/// the draw-list step format (`ps30 run --inputs FILE`): `constants`,
/// `ints`, `bools`, `samplers`, where a sampler's `texture` is an image
/// or DDS file relative to the inputs file, and `inputs` (named as in a
/// draw list: `t0`, `texcoord0`, `v1`, `color1`).
#[derive(Clone, Debug)]
pub struct Inputs {
    /// The application's `c#`, `i#`, `b#`.
    pub constants: Constants,
    /// `(s#, texture, state)`; the texture's name is its file as written.
    pub samplers: Vec<(u32, TextureData, SamplerState)>,
    /// Input values by the names the file gives them (`t0`, `texcoord0`,
    /// `v1`), resolved against the shader when it runs
    /// ([`super::input_values::resolve_all`]).
    pub inputs: Vec<(String, Given)>,
    /// The files it read besides itself.
    pub sources: Vec<PathBuf>,
    /// The registers it sets: `c#`, `i#`, `b#`.
    pub given: [Vec<u32>; 3],
}

/// Reads an inputs file (see [`Inputs`]); errors name the file and field.
pub fn read_inputs(path: &Path, limits: &FileLimits) -> Result<Inputs, FileError> {
    let fail = |at: &str, message: String| FileError {
        path: path.to_path_buf(),
        at: at.to_string(),
        message,
    };
    let bytes = std::fs::File::open(path)
        .map_err(|e| e.to_string())
        .and_then(|f| crate::core::input::read_capped(f, "inputs file", limits.max_input_bytes))
        .map_err(|e| fail("", e))?;
    let text =
        String::from_utf8_lossy(bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&bytes)).into_owned();
    let step: FileStep = serde_json::from_str(&text).map_err(|e| {
        fail(
            &format!("line {} column {}", e.line(), e.column()),
            e.to_string()
                .split(" at line ")
                .next()
                .unwrap_or("")
                .to_string(),
        )
    })?;
    let draw_only = [
        ("clear", step.clear.is_some()),
        ("draw", step.draw.is_some()),
        ("shader", step.shader.is_some()),
        ("blend", step.blend.is_some()),
        ("mips", step.mips.is_some()),
        ("defines", step.defines.is_some()),
    ];
    if let Some((name, _)) = draw_only.iter().find(|(_, set)| *set) {
        return Err(fail(
            name,
            "an inputs file gives only `constants`, `ints`, `bools`, `samplers` and `inputs`"
                .into(),
        ));
    }
    let mut r = Resolver::new(path, limits);
    let constants = r.constants("", &step).map_err(|mut e| {
        e.at = e.at.trim_start_matches('.').to_string();
        e
    })?;
    let mut samplers = Vec::new();
    for (name, fs) in step.samplers.iter().flatten() {
        let field = format!("samplers.{name}");
        let reg = register(name, 's', 16).map_err(|m| r.err(&field, m))?;
        let texture = FileTexture {
            name: format!("s{reg}"),
            image: Some(fs.texture.clone()),
            synthetic: None,
            size: None,
        };
        r.texture(samplers.len(), &texture)
            .map_err(|e| r.err(&format!("{field}.texture"), e.message))?;
        let mut data = r.list.textures.pop().expect("texture just read");
        data.name = fs.texture.clone();
        samplers.push((reg, data, r.sampler_state(&field, fs)?));
    }
    let mut values = Vec::new();
    for (name, input) in step.inputs.iter().flatten() {
        let field = format!("inputs.{name}");
        values.push((name.clone(), r.input_value(&field, input)?));
    }
    // The shader an inputs file serves is not known here: the state goes
    // where ps_1_x's lowering reads it, c12–c23 (which the file may then not
    // set itself); a shader of another profile would read it there.
    let mut constants = constants;
    for (reg, v) in r.bump_state(
        "samplers",
        step.samplers.as_ref(),
        &regs(&step.constants, 'c'),
    )? {
        set(&mut constants.float, [0.0; 4], reg, v);
    }
    Ok(Inputs {
        constants,
        samplers,
        inputs: values,
        sources: r.sources,
        given: [
            regs(&step.constants, 'c'),
            regs(&step.ints, 'i'),
            regs(&step.bools, 'b'),
        ],
    })
}

/// [`read`] on text already in memory; `path` names it in errors and is
/// where relative paths start from.
pub fn parse(text: &str, path: &Path, limits: &FileLimits) -> Result<Loaded, FileError> {
    let file: FileList = serde_json::from_str(text).map_err(|e| FileError {
        path: path.to_path_buf(),
        at: format!("line {} column {}", e.line(), e.column()),
        message: e
            .to_string()
            .split(" at line ")
            .next()
            .unwrap_or("")
            .to_string(),
    })?;
    let mut r = Resolver::new(path, limits);
    if file.steps.len() > limits.max_steps {
        return Err(r.err(
            "steps",
            format!(
                "{} steps, more than the limit of {}",
                file.steps.len(),
                limits.max_steps
            ),
        ));
    }
    for (i, t) in file.targets.iter().enumerate() {
        r.target(i, t)?;
    }
    for (i, t) in file.textures.iter().enumerate() {
        r.texture(i, t)?;
    }
    for (i, s) in file.steps.iter().enumerate() {
        let step = r.step(i, s)?;
        r.list.steps.push(step);
    }
    Ok(Loaded {
        description: file.description,
        list: r.list,
        sources: r.sources,
        warnings: r.warnings,
    })
}

struct Resolver {
    path: PathBuf,
    dir: PathBuf,
    limits: FileLimits,
    /// Pixels of targets and textures so far.
    pixels: u64,
    list: DrawList,
    /// (shader spec, defines) of each loaded shader, to load each once.
    shader_keys: Vec<(String, BTreeMap<String, u64>)>,
    /// Files read (images, shader files).
    sources: Vec<PathBuf>,
    /// Audit warnings so far.
    warnings: Vec<String>,
}

impl Resolver {
    /// A resolver for the file at `path` (names in it are relative to its
    /// folder), with nothing resolved yet.
    fn new(path: &Path, limits: &FileLimits) -> Resolver {
        Resolver {
            path: path.to_path_buf(),
            dir: path.parent().unwrap_or(Path::new("")).to_path_buf(),
            limits: *limits,
            pixels: 0,
            list: DrawList {
                targets: Vec::new(),
                textures: Vec::new(),
                shaders: Vec::new(),
                steps: Vec::new(),
            },
            shader_keys: Vec::new(),
            sources: Vec::new(),
            warnings: Vec::new(),
        }
    }
}

fn size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("`{s}` is not a size WxH"))?;
    let side = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (1..=65_536).contains(&n))
    };
    match (side(w), side(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(format!(
            "`{s}`: both sides must be integers from 1 to 65536"
        )),
    }
}

/// `v` as 1 to 4 finite f32s (missing components 0).
fn vec4(v: &[f64]) -> Result<[f32; 4], String> {
    if v.is_empty() || v.len() > 4 {
        return Err(format!("expected 1 to 4 numbers, got {}", v.len()));
    }
    let mut out = [0f32; 4];
    for (o, &x) in out.iter_mut().zip(v) {
        let f = x as f32;
        if !f.is_finite() {
            return Err(format!("{x} is not a finite f32"));
        }
        *o = f;
    }
    Ok(out)
}

/// The register numbers a `constants`, `ints` or `bools` map names.
fn regs<V>(m: &Option<BTreeMap<String, V>>, letter: char) -> Vec<u32> {
    m.iter()
        .flatten()
        .filter_map(|(name, _)| name.strip_prefix(letter)?.parse().ok())
        .collect()
}

/// `c5` → 5 for register letter `c` with `count` registers.
fn register(name: &str, letter: char, count: u32) -> Result<u32, String> {
    name.strip_prefix(letter)
        .and_then(|n| n.parse::<u32>().ok())
        .filter(|&n| n < count)
        .ok_or_else(|| {
            format!(
                "`{name}` is not a register {letter}0 … {letter}{}",
                count - 1
            )
        })
}

fn set<T: Copy>(file: &mut Vec<T>, zero: T, i: u32, v: T) {
    let i = i as usize;
    file.resize(file.len().max(i + 1), zero);
    file[i] = v;
}

impl Resolver {
    fn err(&self, at: &str, message: String) -> FileError {
        FileError {
            path: self.path.clone(),
            at: at.to_string(),
            message,
        }
    }

    fn spend(&mut self, at: &str, w: u32, h: u32) -> Result<(), FileError> {
        self.pixels += w as u64 * h as u64;
        if self.pixels > self.limits.max_pixels {
            return Err(self.err(
                at,
                format!(
                    "targets and textures would hold {} pixels, more than the limit of {} (raise it with --max-pixels)",
                    self.pixels, self.limits.max_pixels
                ),
            ));
        }
        Ok(())
    }

    fn name_free(&self, at: &str, name: &str) -> Result<(), FileError> {
        // A target's name becomes the file names `-o DIR` writes (NAME.exr,
        // NNN-NAME.png), so every name obeys the one rule for file names
        // made from user data; textures share the namespace, and the rule.
        crate::core::output::plain_name(name).map_err(|m| self.err(at, m))?;
        let taken = self.list.targets.iter().any(|t| t.name == name)
            || self.list.textures.iter().any(|t| t.name == name);
        if taken {
            return Err(self.err(
                at,
                format!("the name `{name}` is already used by a target or texture"),
            ));
        }
        Ok(())
    }

    fn target(&mut self, i: usize, t: &FileTarget) -> Result<(), FileError> {
        let at = format!("targets[{i}]");
        self.name_free(&format!("{at}.name"), &t.name)?;
        let (width, height) = size(&t.size).map_err(|m| self.err(&format!("{at}.size"), m))?;
        super::multisample::check_target(t.multisample.as_ref(), t.multisample_quality).map_err(
            |(quality, m)| {
                let field = if quality {
                    "multisample_quality"
                } else {
                    "multisample"
                };
                self.err(&format!("{at}.{field}"), m)
            },
        )?;
        let format = TargetFormat::from_name(&t.format).ok_or_else(|| {
            let known: Vec<&str> = TargetFormat::ALL.iter().map(|f| f.d3d_name()).collect();
            self.err(
                &format!("{at}.format"),
                format!(
                    "unknown format `{}` (one of {})",
                    t.format,
                    known.join(", ")
                ),
            )
        })?;
        self.spend(&at, width, height)?;
        self.list.targets.push(TargetSpec {
            name: t.name.clone(),
            width,
            height,
            format,
        });
        Ok(())
    }

    fn texture(&mut self, i: usize, t: &FileTexture) -> Result<(), FileError> {
        let at = format!("textures[{i}]");
        self.name_free(&format!("{at}.name"), &t.name)?;
        let mut file_levels = None;
        let (width, height, texels) = match (&t.image, &t.synthetic) {
            (Some(file), None) => {
                let budget = self.limits.max_pixels.saturating_sub(self.pixels).max(1);
                let path = self.dir.join(file);
                let img = super::textures::load(&path, budget)
                    .map_err(|e| self.err(&format!("{at}.image"), e))?;
                self.sources.push(path);
                if img.file.is_some() {
                    // Levels, faces and slices count against the budget.
                    let n = u32::try_from(img.texel_count).unwrap_or(u32::MAX);
                    self.spend(&at, n, 1)?;
                    file_levels = img.file;
                }
                (img.width, img.height, img.texels)
            }
            (None, Some(kind)) => self.synthetic(&at, kind, t.size.as_deref())?,
            _ => {
                return Err(self.err(
                    &at,
                    "give either `image` (a file) or `synthetic` (lights-gbuffer, lights-material-0 … -2)".into(),
                ))
            }
        };
        if file_levels.is_none() {
            self.spend(&at, width, height)?;
        }
        self.list.textures.push(TextureData {
            name: t.name.clone(),
            width,
            height,
            texels,
            file: file_levels,
        });
        Ok(())
    }

    fn synthetic(
        &self,
        at: &str,
        kind: &str,
        size_text: Option<&str>,
    ) -> Result<(u32, u32, Vec<[f32; 4]>), FileError> {
        use crate::jobs::scenes::lights::{Scene, MATERIAL_SIZE};
        match kind {
            "lights-gbuffer" => {
                let text = size_text
                    .ok_or_else(|| self.err(at, "lights-gbuffer needs a `size`".into()))?;
                let (w, h) = size(text).map_err(|m| self.err(&format!("{at}.size"), m))?;
                let scene =
                    Scene::synthetic(w, h).map_err(|e| self.err(&format!("{at}.size"), e.0))?;
                Ok((w, h, scene.gbuffer))
            }
            _ => {
                let m = kind
                    .strip_prefix("lights-material-")
                    .and_then(|m| m.parse::<usize>().ok())
                    .filter(|&m| m < 3)
                    .ok_or_else(|| {
                        self.err(
                            &format!("{at}.synthetic"),
                            format!("unknown synthetic texture `{kind}` (lights-gbuffer, lights-material-0, -1, -2)"),
                        )
                    })?;
                let scene = Scene::from_ids(1, 1, &[0]).map_err(|e| self.err(at, e.0))?;
                let texels = scene.materials[m].clone();
                Ok((MATERIAL_SIZE, MATERIAL_SIZE, texels))
            }
        }
    }

    fn step(&mut self, i: usize, s: &FileStep) -> Result<Step, FileError> {
        let at = format!("steps[{i}]");
        let kinds = [&s.clear, &s.draw, &s.mips];
        if kinds.iter().filter(|k| k.is_some()).count() != 1 {
            return Err(self.err(
                &at,
                "a step is exactly one of {\"clear\": TARGET}, {\"draw\": TARGET, …}, {\"mips\": TARGET}".into(),
            ));
        }
        let draw_fields = s.shader.is_some()
            || s.defines.is_some()
            || s.inputs.is_some()
            || s.constants.is_some()
            || s.ints.is_some()
            || s.bools.is_some()
            || s.samplers.is_some()
            || s.blend.is_some()
            || s.write.is_some()
            || s.float_rules.is_some()
            || s.alpha_test.is_some()
            || s.outputs.is_some()
            || s.clip_planes.is_some()
            || s.shade.is_some()
            || s.geometry.is_some();
        let target = |name: &str, field: &str| {
            self.list.target(name).ok_or_else(|| {
                self.err(
                    &format!("{at}.{field}"),
                    format!("no target named `{name}`"),
                )
            })
        };
        if let Some(name) = &s.clear {
            if draw_fields || s.odd.is_some() {
                return Err(self.err(&at, "a clear takes only `color`".into()));
            }
            return Ok(Step::Clear {
                target: target(name, "clear")?,
                color: s.color.unwrap_or([0; 4]),
            });
        }
        if let Some(name) = &s.mips {
            if draw_fields || s.color.is_some() {
                return Err(self.err(&at, "a mips step takes only `odd`".into()));
            }
            let odd = match s.odd.as_deref().unwrap_or("fold") {
                "fold" => OddSides::Fold,
                "bilinear" => OddSides::Bilinear,
                other => {
                    return Err(self.err(
                        &format!("{at}.odd"),
                        format!("`{other}` is not fold or bilinear"),
                    ))
                }
            };
            return Ok(Step::Mips {
                target: target(name, "mips")?,
                odd,
            });
        }
        if s.color.is_some() || s.odd.is_some() {
            return Err(self.err(
                &at,
                "`color` belongs to a clear, `odd` to a mips step".into(),
            ));
        }
        let name = s.draw.as_deref().unwrap_or_default();
        let target = target(name, "draw")?;
        self.draw(&at, target, s).map(Step::Draw)
    }

    /// One input's value as the file gives it (`"texcoord"` or `{"base": …}`).
    fn input_value(&self, field: &str, input: &FileInput) -> Result<Given, FileError> {
        Ok(match input {
            FileInput::Named(n) if n == "texcoord" => Given::Texcoord,
            FileInput::Named(n) => {
                return Err(self.err(
                    field,
                    format!("`{n}` is not \"texcoord\" or {{\"base\": …}}"),
                ))
            }
            FileInput::Linear { base, ddx, ddy } => {
                let four = |v: &[f64], part: &str| -> Result<[f32; 4], FileError> {
                    if v.is_empty() {
                        return Ok([0.0; 4]);
                    }
                    vec4(v).map_err(|m| self.err(&format!("{field}.{part}"), m))
                };
                Given::Linear(LinearInput {
                    base: four(base, "base")?,
                    ddx: four(ddx, "ddx")?,
                    ddy: four(ddy, "ddy")?,
                })
            }
        })
    }

    fn draw(&mut self, at: &str, target: usize, s: &FileStep) -> Result<DrawStep, FileError> {
        let spec = s
            .shader
            .as_deref()
            .ok_or_else(|| self.err(at, "a draw needs a `shader`".into()))?;
        let shader = self.shader(
            &format!("{at}.shader"),
            spec,
            s.defines.clone().unwrap_or_default(),
        )?;
        let t = &self.list.targets[target];
        let (w, h) = (t.width, t.height);
        let mut inputs = Vec::new();
        for (name, input) in s.inputs.iter().flatten() {
            let field = format!("{at}.inputs.{name}");
            let program = self.list.shaders[shader].loaded.shader.program();
            let v = crate::core::pixel_inputs::resolve(program, name)
                .map_err(|m| self.err(&field, m))?;
            let value = match self.input_value(&field, input)? {
                Given::Texcoord => super::texcoord(w, h),
                Given::Linear(l) => l,
            };
            inputs.push((v, value));
        }
        let mut constants = self.constants(at, s)?;
        let samplers = self.samplers(&format!("{at}.samplers"), s.samplers.as_ref(), 16, target)?;
        let ps1 = self.list.shaders[shader]
            .loaded
            .shader
            .program()
            .profile
            .is_ps1();
        let given = regs(&s.constants, 'c');
        let bumps = self.bump_state(&format!("{at}.samplers"), s.samplers.as_ref(), &given)?;
        if !bumps.is_empty() && !ps1 {
            self.warnings.push(format!(
                "{at}.samplers: bump-environment state is read only by ps_1_x's texbem, texbeml and bem; this shader does not read it"
            ));
        } else {
            for (r, v) in bumps {
                set(&mut constants.float, [0.0; 4], r, v);
            }
        }
        let blend = match &s.blend {
            None => BlendState::OFF,
            Some(b) => self.blend(&format!("{at}.blend"), b)?,
        };
        let write = match &s.write {
            None => ColorWrite::ALL,
            Some(letters) => ColorWrite::from_letters(letters).ok_or_else(|| {
                self.err(
                    &format!("{at}.write"),
                    format!("`{letters}` is not a set of the letters r, g, b, a"),
                )
            })?,
        };
        self.audit(at, shader, s)?;
        let fields = super::pixel_state::FileFields {
            float_rules: s.float_rules.as_deref(),
            alpha_test: s.alpha_test.as_ref(),
            outputs: s.outputs.as_ref(),
            clip_planes: s.clip_planes.as_deref(),
            shade: s.shade.as_deref(),
        };
        let targets = &self.list.targets;
        let target_of = |name: &str| {
            let i = targets.iter().position(|t| t.name == name)?;
            Some((i, targets[i].width, targets[i].height))
        };
        let vertex_samplers = match &s.geometry {
            Some(g)
                if !self
                    .bump_state("", g.vertex_samplers.as_ref(), &[])?
                    .is_empty() =>
            {
                return Err(self.err(
                    &format!("{at}.geometry.vertex_samplers"),
                    "a vertex texture sampler has no bump-environment state (it belongs to ps_1_x's texture stages)".into(),
                ));
            }
            Some(g) => self.samplers(
                &format!("{at}.geometry.vertex_samplers"),
                g.vertex_samplers.as_ref(),
                4,
                target,
            )?,
            None => Vec::new(),
        };
        let sampled: Vec<usize> = samplers
            .iter()
            .chain(&vertex_samplers)
            .filter_map(|&(_, src, _)| match src {
                Source::Target(t) => Some(t),
                Source::Texture(_) => None,
            })
            .collect();
        let pixel = super::pixel_state::read(
            &fields,
            &target_of,
            (target, w, h),
            targets[target].format,
            &sampled,
        )
        .map_err(|(field, m)| self.err(&format!("{at}.{field}"), m))?;
        let geometry = match &s.geometry {
            None => None,
            Some(g) => {
                let mut g = self.geometry(at, g, s, (w, h))?;
                g.vertex_samplers = vertex_samplers;
                Some(Box::new(g))
            }
        };
        self.pixel_stage(&format!("{at}.shader"), shader)?;
        Ok(DrawStep {
            geometry,
            pixel: Box::new(pixel),
            target,
            shader,
            inputs,
            constants,
            samplers,
            output: OutputState { blend, write },
        })
    }

    /// The draw's constants held against what its shader reads: a register
    /// read that neither the shader nor the step sets is an error naming the
    /// step; the other findings become warnings.
    fn audit(&mut self, at: &str, shader: usize, s: &FileStep) -> Result<(), FileError> {
        use crate::core::audit::{self, Given, Kind};
        fn regs<V>(
            m: &Option<BTreeMap<String, V>>,
            letter: char,
        ) -> std::collections::BTreeSet<u32> {
            m.iter()
                .flatten()
                .filter_map(|(name, _)| name.strip_prefix(letter)?.parse().ok())
                .collect()
        }
        let given = Given {
            floats: regs(&s.constants, 'c'),
            ints: regs(&s.ints, 'i'),
            bools: regs(&s.bools, 'b'),
            defines: s.defines.iter().flatten().map(|(n, _)| n.clone()).collect(),
            ..Given::default()
        };
        let loaded = &self.list.shaders[shader].loaded;
        let found = audit::audit(&loaded.shader, &loaded.defines_used, &given);
        let unset = audit::unset_names(&found);
        if !unset.is_empty() {
            let message = format!(
                "{} reads {}, which neither the shader nor this step sets (give them in `constants`, `ints` or `bools`, zeros too if zeros are meant)",
                loaded.file.name,
                crate::core::numbers::list(&unset)
            );
            return Err(self.err(at, message));
        }
        for f in found.iter().filter(|f| f.kind != Kind::Unset) {
            self.warnings
                .push(format!("{at}: {} ({})", f.message(), f.help()));
        }
        Ok(())
    }

    fn constants(&self, at: &str, s: &FileStep) -> Result<Constants, FileError> {
        let mut c = Constants::default();
        for (name, v) in s.constants.iter().flatten() {
            let field = format!("{at}.constants.{name}");
            let reg = register(name, 'c', 224).map_err(|m| self.err(&field, m))?;
            let value = super::floats::constant4(v).map_err(|m| self.err(&field, m))?;
            set(&mut c.float, [0.0; 4], reg, value);
        }
        for (name, v) in s.ints.iter().flatten() {
            let field = format!("{at}.ints.{name}");
            let reg = register(name, 'i', 16).map_err(|m| self.err(&field, m))?;
            if v.is_empty() || v.len() > 4 {
                return Err(self.err(&field, "expected 1 to 4 integers".into()));
            }
            let mut value = [0i32; 4];
            value[..v.len()].copy_from_slice(v);
            set(&mut c.int, [0; 4], reg, value);
        }
        for (name, &v) in s.bools.iter().flatten() {
            let field = format!("{at}.bools.{name}");
            let reg = register(name, 'b', 16).map_err(|m| self.err(&field, m))?;
            set(&mut c.bool, false, reg, v);
        }
        Ok(c)
    }

    /// The constants that carry the bump-environment state of a draw's
    /// `samplers` (`at` their field) to ps_1_x's lowering
    /// ([`crate::core::ps1::run::bump_constants`]): stages s0–s5 only, and
    /// none of the registers `taken` (the step's own `constants`).
    fn bump_state(
        &self,
        at: &str,
        given: Option<&BTreeMap<String, FileSampler>>,
        taken: &[u32],
    ) -> Result<Vec<(u32, [f32; 4])>, FileError> {
        let mut out = Vec::new();
        for (name, fs) in given.into_iter().flatten() {
            let field = format!("{at}.{name}");
            let env = fs
                .bump_env()
                .map_err(|(part, m)| self.err(&format!("{field}.{part}"), m))?;
            let Some(env) = env else { continue };
            let stage = register(name, 's', 16).map_err(|m| self.err(&field, m))?;
            let regs = crate::core::ps1::run::bump_constants(stage, &env).ok_or_else(|| {
                self.err(
                    &field,
                    format!(
                        "`{name}` has no bump-environment state: ps_1_x's texture stages are s0–s5"
                    ),
                )
            })?;
            if let Some((r, _)) = regs.iter().find(|(r, _)| taken.contains(r)) {
                return Err(self.err(
                    &field,
                    format!("its bump-environment state is c{r}, which `constants` sets too"),
                ));
            }
            out.extend(regs);
        }
        Ok(out)
    }

    fn sampler_state(&self, field: &str, fs: &FileSampler) -> Result<SamplerState, FileError> {
        let bad = |part: &str, v: &str, allowed: &str| {
            self.err(
                &format!("{field}.{part}"),
                format!("`{v}` is not one of {allowed}"),
            )
        };
        let filter = match fs.filter.as_deref().unwrap_or("point") {
            "point" => Filter::Point,
            "linear" => Filter::Linear,
            v => return Err(bad("filter", v, "point, linear")),
        };
        let mip_filter = match fs.mip.as_deref().unwrap_or("none") {
            "none" => MipFilter::None,
            "point" => MipFilter::Point,
            "linear" => MipFilter::Linear,
            v => return Err(bad("mip", v, "none, point, linear")),
        };
        let address = super::textures::address(fs.address.as_deref().unwrap_or("wrap"))
            .map_err(|m| self.err(&format!("{field}.address"), m))?;
        let border = match fs.border {
            Some(b) => vec4(&b).map_err(|m| self.err(&format!("{field}.border"), m))?,
            None => [0.0; 4],
        };
        let lod_bias = fs.lod_bias.unwrap_or(0.0) as f32;
        if !lod_bias.is_finite() {
            return Err(self.err(&format!("{field}.lod_bias"), "not a finite f32".into()));
        }
        let mut state = SamplerState {
            mag_filter: filter,
            min_filter: filter,
            mip_filter,
            mip_lod_bias: lod_bias,
            max_mip_level: fs.max_mip_level.unwrap_or(0),
            address_u: address,
            address_v: address,
            address_w: address,
            border,
        };
        super::textures::overrides(
            &mut state,
            [
                fs.address_u.as_deref(),
                fs.address_v.as_deref(),
                fs.address_w.as_deref(),
            ],
            [fs.min_filter.as_deref(), fs.mag_filter.as_deref()],
        )
        .map_err(|(part, m)| self.err(&format!("{field}.{part}"), m))?;
        Ok(state)
    }

    fn equation(
        &self,
        field: &str,
        src: &str,
        dest: &str,
        op: Option<&str>,
    ) -> Result<Equation, FileError> {
        let factor = |part: &str, name: &str| {
            BlendFactor::from_name(name).ok_or_else(|| {
                let known: Vec<&str> = BlendFactor::ALL.iter().map(|f| f.d3d_name()).collect();
                self.err(
                    &format!("{field}.{part}"),
                    format!(
                        "unknown blend factor `{name}` (one of {})",
                        known.join(", ")
                    ),
                )
            })
        };
        let op = match op {
            None => BlendOp::Add,
            Some(name) => BlendOp::from_name(name).ok_or_else(|| {
                self.err(
                    &format!("{field}.op"),
                    format!(
                        "unknown blend operation `{name}` (ADD, SUBTRACT, REVSUBTRACT, MIN, MAX)"
                    ),
                )
            })?,
        };
        Ok(Equation {
            src: factor("src", src)?,
            dest: factor("dest", dest)?,
            op,
        })
    }

    fn blend(&self, field: &str, b: &FileBlend) -> Result<BlendState, FileError> {
        let color = self.equation(field, &b.src, &b.dest, b.op.as_deref())?;
        let alpha = match &b.alpha {
            None => None,
            Some(a) => {
                Some(self.equation(&format!("{field}.alpha"), &a.src, &a.dest, a.op.as_deref())?)
            }
        };
        Ok(BlendState {
            enabled: true,
            color,
            alpha,
            factor: b.factor.unwrap_or([255; 4]),
        })
    }

    /// A draw's `samplers` (or its geometry's `vertex_samplers`, `count`
    /// of them): each register with the texture or target it reads — never
    /// the draw's own `target` — and its states.
    fn samplers(
        &self,
        at: &str,
        given: Option<&BTreeMap<String, FileSampler>>,
        count: u32,
        target: usize,
    ) -> Result<Vec<(u32, Source, SamplerState)>, FileError> {
        let mut samplers = Vec::new();
        for (name, fs) in given.into_iter().flatten() {
            let field = format!("{at}.{name}");
            let reg = register(name, 's', count).map_err(|m| self.err(&field, m))?;
            let source = match self.list.target(&fs.texture) {
                Some(t) if t == target => {
                    return Err(self.err(
                        &format!("{field}.texture"),
                        format!(
                        "`{}` is the target this draw renders to (Direct3D 9 does not allow it)",
                        fs.texture
                    ),
                    ))
                }
                Some(t) => Source::Target(t),
                None => Source::Texture(
                    self.list
                        .textures
                        .iter()
                        .position(|t| t.name == fs.texture)
                        .ok_or_else(|| {
                            self.err(
                                &format!("{field}.texture"),
                                format!("no texture or target named `{}`", fs.texture),
                            )
                        })?,
                ),
            };
            samplers.push((reg, source, self.sampler_state(&field, fs)?));
        }
        Ok(samplers)
    }

    /// A draw's `geometry`, its vertex shader loaded.
    fn geometry(
        &mut self,
        at: &str,
        g: &super::geometry::FileGeometry,
        s: &FileStep,
        size: (u32, u32),
    ) -> Result<super::geometry::Geometry, FileError> {
        if s.inputs.is_some() || s.clip_planes.is_some() {
            return Err(self.err(
                at,
                "a draw of geometry takes its inputs from its vertices and its clip planes in `geometry.clip_planes`".into(),
            ));
        }
        let (mut geometry, vs) =
            super::geometry::read(g, &self.dir, self.limits.max_input_bytes, size)
                .map_err(|(field, m)| self.err(&format!("{at}.geometry.{field}"), m))?;
        if let Some(spec) = vs {
            let field = format!("{at}.geometry.vertex_shader");
            let index = self.shader(&field, &spec, BTreeMap::new())?;
            let profile = self.list.shaders[index].loaded.shader.program().profile;
            if !crate::core::emu::vertex::runs(profile) {
                return Err(self.err(
                    &field,
                    format!("a {profile} shader; the vertex stage runs vs_2_0, vs_2_x and vs_3_0"),
                ));
            }
            geometry.vertex_shader = Some(index);
        }
        Ok(geometry)
    }

    /// Refuses a draw whose `shader` is no pixel shader.
    fn pixel_stage(&self, field: &str, shader: usize) -> Result<(), FileError> {
        let profile = self.list.shaders[shader].loaded.shader.program().profile;
        if profile.stage() == crate::core::profile::Stage::Vertex {
            return Err(self.err(
                field,
                format!("a {profile} shader; a draw's `shader` is its pixel shader (a vertex shader goes in `geometry.vertex_shader`)"),
            ));
        }
        Ok(())
    }

    fn shader(
        &mut self,
        field: &str,
        spec: &str,
        defines: BTreeMap<String, u64>,
    ) -> Result<usize, FileError> {
        let key = (spec.to_string(), defines);
        if let Some(i) = self.shader_keys.iter().position(|k| *k == key) {
            return Ok(i);
        }
        let options = Options {
            defines: key.1.clone(),
            ..Options::default()
        };
        // A file is assembly or ps_3_0 bytecode, told apart by content.
        let source = match crate::jobs::bundled::resolve(spec) {
            crate::jobs::bundled::Named::Bundled(b) => {
                crate::core::diag::SourceFile::new(b.path, b.text)
            }
            crate::jobs::bundled::Named::File(_) => {
                let file = self.dir.join(spec);
                let cap = self.limits.max_input_bytes;
                let bytes = crate::core::input::read_file(&file, "shader", cap).map_err(|e| {
                    let hint = crate::jobs::bundled::suggest(spec)
                        .map(|n| format!("; did you mean the bundled `{n}`?"))
                        .unwrap_or_default();
                    self.err(field, format!("{e}{hint}"))
                })?;
                self.sources.push(file.clone());
                load::source_file(&file.display().to_string(), bytes, &options)
                    .map_err(|e| self.err(field, e.to_string()))?
            }
        };
        let name = source.name.clone();
        let loaded = load::load(source, &options).map_err(|e| self.err(field, e.to_string()))?;
        self.list.shaders.push(ShaderSpec { name, loaded });
        self.shader_keys.push(key);
        Ok(self.list.shaders.len() - 1)
    }
}
