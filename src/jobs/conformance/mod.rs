//! The conformance corpus: Direct3D 9 draws that someone else wrote, with
//! the colours real drivers produced, set up and run through ps30.
//!
//! The corpus lives in `tests/conformance/` (its README says where the cases
//! come from and which were left out, and why). This job reads it and turns
//! each case into what a backend runs: for every draw, the triangles it
//! covers (`raster.rs`), and for each triangle an [`emu::Draw`] — the target
//! size, the inputs as planes, the constants, the samplers, the facing. A
//! backend is any function from a validated shader and a draw to a
//! [`DrawOutput`]: the emulator ([`emulate`]), and a GPU backend once one
//! exists. The job then does what the output merger does with blending off:
//! each covered, not discarded pixel of target `i` takes `oC<i>`, targets a
//! shader does not write keep their contents. The targets come back as f32
//! colours; converting them to the render target's format and comparing
//! with the expected D3DCOLORs is the caller's (the test harness,
//! `tests/conformance.rs`), so the rule is stated in one place.
//!
//! Not modelled, and so not in the corpus: depth and stencil tests,
//! blending, perspective-correct interpolation, points and lines,
//! multisampling, vertex shaders that compute (the vertex values a case
//! gives are what the vertex stage outputs).

pub mod case;
pub(crate) mod raster;

use crate::core::diag::SourceError;
use crate::core::emu::{self, Address, Constants, Draw, DrawOutput, Filter, SamplerState, Texture};
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use crate::core::load::{self, Loaded, Options};
use case::{
    AddressSpec, CaseSpec, ColorFormat, Constant, DrawSpec, FilterSpec, SamplerSpec, Shade,
    SuiteSpec,
};
use raster::{ScreenVertex, Triangle};
use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

/// Largest `cases.json` or shader file read (bytes).
const MAX_FILE_BYTES: u64 = 4 << 20;
/// Largest render target side: D3D9 devices of the era go to 4096.
const MAX_TARGET_SIDE: u32 = 4096;
/// Most vertices in one draw.
const MAX_VERTICES: usize = 65_536;

/// Something wrong with the corpus itself, or a backend that failed; the
/// place names the folder, case and draw.
#[derive(Clone, Debug, PartialEq)]
pub struct CorpusError {
    /// Where: a file or folder, or `function/case` and, where it matters, the draw.
    pub place: String,
    /// What is wrong, in one sentence.
    pub message: String,
}

impl fmt::Display for CorpusError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.place, self.message)
    }
}

impl std::error::Error for CorpusError {}

fn error(place: impl fmt::Display, message: impl Into<String>) -> CorpusError {
    CorpusError {
        place: place.to_string(),
        message: message.into(),
    }
}

/// A shader of the corpus as ps30 loads it.
#[derive(Clone, Debug)]
pub enum ShaderLoad {
    /// Validated and ready to draw.
    Loaded(Box<Loaded>),
    /// Refused, with the diagnostics ps30 gave; a case may expect that
    /// ([`case::RejectedSpec`]).
    Refused(Box<SourceError>),
}

/// One `cases.json` with its shaders loaded.
#[derive(Clone, Debug)]
pub struct Suite {
    /// The folder holding `cases.json` and the shaders.
    pub dir: PathBuf,
    /// The file as read.
    pub spec: SuiteSpec,
    /// Every shader of [`case::SuiteSpec::shaders`], loaded or refused.
    pub shaders: BTreeMap<String, ShaderLoad>,
}

fn read_text(path: &Path) -> Result<String, CorpusError> {
    let fail = |e: std::io::Error| error(path.display(), e.to_string());
    let len = std::fs::metadata(path).map_err(fail)?.len();
    if len > MAX_FILE_BYTES {
        return Err(error(
            path.display(),
            format!("{len} bytes, more than the {MAX_FILE_BYTES} a corpus file may have"),
        ));
    }
    std::fs::read_to_string(path).map_err(fail)
}

impl Suite {
    /// Reads `dir/cases.json` and loads every shader it names.
    pub fn load(dir: &Path) -> Result<Suite, CorpusError> {
        let path = dir.join("cases.json");
        let spec: SuiteSpec = serde_json::from_str(&read_text(&path)?)
            .map_err(|e| error(path.display(), e.to_string()))?;
        let mut shaders = BTreeMap::new();
        for (name, s) in &spec.shaders {
            if s.file.contains(['/', '\\']) || s.file.starts_with('.') {
                return Err(error(
                    path.display(),
                    format!("shader `{name}`: `{}` is not a file in the folder", s.file),
                ));
            }
            let file = dir.join(&s.file);
            let text = read_text(&file)?;
            let loaded = match load::load_str(&file.to_string_lossy(), &text, &Options::default()) {
                Ok(l) => ShaderLoad::Loaded(Box::new(l)),
                Err(e) => ShaderLoad::Refused(Box::new(e)),
            };
            shaders.insert(name.clone(), loaded);
        }
        Ok(Suite {
            dir: dir.to_path_buf(),
            spec,
            shaders,
        })
    }

    /// Every suite under `root` (each folder with a `cases.json`), by name.
    pub fn load_all(root: &Path) -> Result<Vec<Suite>, CorpusError> {
        let entries = std::fs::read_dir(root).map_err(|e| error(root.display(), e.to_string()))?;
        let mut dirs: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.join("cases.json").is_file())
            .collect();
        dirs.sort_unstable();
        dirs.iter().map(|d| Suite::load(d)).collect()
    }

    /// `function/case`, for messages.
    pub fn place(&self, case: &CaseSpec) -> String {
        format!("{}/{}", self.spec.function, case.name)
    }

    /// The validated shader `name`, or why there is none.
    pub fn shader(&self, name: &str) -> Result<&Loaded, String> {
        match self.shaders.get(name) {
            Some(ShaderLoad::Loaded(l)) => Ok(l),
            Some(ShaderLoad::Refused(e)) => Err(format!(
                "shader `{name}` does not load:\n{}",
                e.diagnostics.render(&e.file)
            )),
            None => Err(format!("no shader `{name}` in this suite")),
        }
    }
}

/// A render target after a case's draws: f32 colours as the shader wrote
/// them, `None` where nothing was written to a target never cleared.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetImage {
    /// The target's name, from its [`case::TargetSpec`].
    pub name: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The format the target stores (conversion to it is the caller's).
    pub format: ColorFormat,
    /// `width × height` colours, row-major.
    pub texels: Vec<Option<[f32; 4]>>,
}

impl TargetImage {
    /// The colour at pixel (x, y); `None` outside the target or where nothing
    /// was written to a target never cleared.
    pub fn texel(&self, x: u32, y: u32) -> Option<[f32; 4]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.texels[y as usize * self.width as usize + x as usize]
    }
}

/// What a case's draws left in its targets.
#[derive(Clone, Debug, PartialEq)]
pub struct Rendered {
    /// The case's targets, in its order.
    pub targets: Vec<TargetImage>,
    /// Backend draws run (one per triangle, or per run of triangles that
    /// share their planes and facing).
    pub backend_draws: usize,
    /// The loader's warnings for the shaders drawn, rendered.
    pub warnings: Vec<String>,
}

/// The emulator as a backend.
pub fn emulate(shader: &Shader, draw: &Draw) -> Result<DrawOutput, String> {
    let compiled = emu::compile(shader).map_err(|e| e.to_string())?;
    emu::run(&compiled, draw).map_err(|e| e.to_string())
}

/// Runs the draws of `case` on `backend` and returns the targets.
pub fn render(
    suite: &Suite,
    case: &CaseSpec,
    backend: &mut dyn FnMut(&Shader, &Draw) -> Result<DrawOutput, String>,
) -> Result<Rendered, CorpusError> {
    let place = suite.place(case);
    let (width, height) = target_size(case).map_err(|m| error(&place, m))?;
    let mut targets: Vec<TargetImage> = case
        .targets
        .iter()
        .map(|t| TargetImage {
            name: t.name.clone(),
            width,
            height,
            format: t.format,
            texels: vec![t.clear.map(|c| c.rgba()); (width * height) as usize],
        })
        .collect();
    let mut rendered = Rendered {
        targets: Vec::new(),
        backend_draws: 0,
        warnings: Vec::new(),
    };
    for (d, spec) in case.draws.iter().enumerate() {
        let place = format!("{place}, draw {d}");
        let loaded = suite.shader(&spec.shader).map_err(|m| error(&place, m))?;
        rendered.warnings.extend(
            loaded
                .warnings
                .warnings()
                .map(|w| format!("{}: {}", spec.shader, w.message)),
        );
        let set_up = DrawSetUp::new(loaded.shader.program(), spec, width, height)
            .map_err(|m| error(&place, m))?;
        for group in set_up.groups() {
            let draw = set_up.draw(&group[0]);
            let out = backend(&loaded.shader, &draw).map_err(|m| error(&place, m))?;
            let pixels = (width * height) as usize;
            if (out.width, out.height) != (width, height)
                || out.killed.len() != pixels
                || out.color.iter().flatten().any(|c| c.len() != pixels)
            {
                return Err(error(
                    &place,
                    format!(
                        "the backend returned a {}x{} result for a {width}x{height} draw",
                        out.width, out.height
                    ),
                ));
            }
            rendered.backend_draws += 1;
            merge(&mut targets, &out, &group);
        }
    }
    rendered.targets = targets;
    Ok(rendered)
}

/// The size every target of a case shares (D3D9 binds render targets of one
/// size together).
fn target_size(case: &CaseSpec) -> Result<(u32, u32), String> {
    let first = case
        .targets
        .first()
        .ok_or("a case that draws needs at least one target")?;
    let size = (first.width, first.height);
    for t in &case.targets {
        if (t.width, t.height) != size {
            return Err(format!(
                "target `{}` is {}x{}, `{}` is {}x{}: targets bound together have one size",
                t.name, t.width, t.height, first.name, size.0, size.1
            ));
        }
    }
    if size.0 == 0 || size.1 == 0 || size.0 > MAX_TARGET_SIDE || size.1 > MAX_TARGET_SIDE {
        return Err(format!(
            "a {}x{} target; sides go from 1 to {MAX_TARGET_SIDE}",
            size.0, size.1
        ));
    }
    if case.targets.len() > 4 {
        return Err(format!(
            "{} targets; a ps_3_0 shader writes at most 4",
            case.targets.len()
        ));
    }
    Ok(size)
}

/// Stores what one backend draw wrote where its triangles cover the target.
fn merge(targets: &mut [TargetImage], out: &DrawOutput, group: &[Triangle]) {
    let width = out.width;
    let height = out.height;
    for tri in group {
        for i in tri.pixels(width, height) {
            if out.killed[i] {
                continue;
            }
            for (target, colour) in targets.iter_mut().zip(&out.color) {
                if let Some(colour) = colour {
                    target.texels[i] = Some(colour[i]);
                }
            }
        }
    }
}

/// One draw call resolved against its shader: the screen triangles with
/// their values per input register, and everything the emulator's draws of
/// it share.
struct DrawSetUp {
    width: u32,
    height: u32,
    /// Input registers the shader declares (v#), in the order of each
    /// vertex's `values`.
    registers: Vec<u32>,
    /// Per register, the components flat shading holds constant.
    flat: Vec<[bool; 4]>,
    triangles: Vec<Triangle>,
    constants: Constants,
    samplers: Vec<Binding>,
}

/// A texture bound to `s#`, owned by the set-up so that draws can borrow it.
struct Binding {
    sampler: u32,
    width: u32,
    height: u32,
    texels: Vec<[f32; 4]>,
    state: SamplerState,
}

impl DrawSetUp {
    fn new(
        program: &crate::core::ir::Program,
        spec: &DrawSpec,
        width: u32,
        height: u32,
    ) -> Result<DrawSetUp, String> {
        if spec.vertices.len() > MAX_VERTICES {
            return Err(format!(
                "{} vertices, more than {MAX_VERTICES}",
                spec.vertices.len()
            ));
        }
        let mut registers: Vec<u32> = program
            .inputs
            .iter()
            .filter(|d| d.reg.file == RegFile::Input)
            .map(|d| d.reg.index)
            .collect();
        registers.sort_unstable();
        registers.dedup();
        let flat = registers
            .iter()
            .map(|&r| flat_components(program, r, spec.shade))
            .collect();
        let mut vertices = Vec::with_capacity(spec.vertices.len());
        for (n, v) in spec.vertices.iter().enumerate() {
            let (x, y) = raster::to_screen(&v.position, spec.positions, width, height)
                .map_err(|m| format!("vertex {n}: {m}"))?;
            let values = registers
                .iter()
                .map(|&r| register_value(program, r, v))
                .collect::<Result<_, _>>()
                .map_err(|m| format!("vertex {n}: {m}"))?;
            vertices.push(ScreenVertex { x, y, values });
        }
        let triangles = raster::assemble(&vertices, spec.primitive, spec.cull)?;
        Ok(DrawSetUp {
            width,
            height,
            registers,
            flat,
            triangles,
            constants: constants(&spec.constants)?,
            samplers: spec
                .samplers
                .iter()
                .map(sampler)
                .collect::<Result<_, _>>()?,
        })
    }

    /// The triangles in runs that one emulator draw can serve: the same
    /// planes and the same facing.
    fn groups(&self) -> Vec<Vec<Triangle>> {
        let mut out: Vec<Vec<Triangle>> = Vec::new();
        for t in &self.triangles {
            match out.last_mut() {
                Some(g) if self.same_draw(&g[0], t) => g.push(t.clone()),
                _ => out.push(vec![t.clone()]),
            }
        }
        out
    }

    fn same_draw(&self, a: &Triangle, b: &Triangle) -> bool {
        a.face == b.face
            && (0..self.registers.len())
                .all(|k| a.plane(k, self.flat[k]) == b.plane(k, self.flat[k]))
    }

    /// The emulator's draw for `tri` (and the triangles grouped with it).
    fn draw(&self, tri: &Triangle) -> Draw<'_> {
        let mut draw = Draw::new(self.width, self.height);
        draw.face = tri.face;
        draw.constants = self.constants.clone();
        draw.inputs = self
            .registers
            .iter()
            .enumerate()
            .map(|(k, &r)| (r, tri.plane(k, self.flat[k])))
            .collect();
        draw.samplers = self
            .samplers
            .iter()
            .map(|b| {
                let texture = Texture {
                    width: b.width,
                    height: b.height,
                    texels: &b.texels,
                };
                (b.sampler, texture.into(), b.state)
            })
            .collect();
        draw
    }
}

/// The value input register `v<reg>` holds at vertex `v`: each declaration
/// of the register fills the components of its mask from the attribute of
/// its semantic; components no declaration covers come from the first one
/// (what the vertex stage wrote to the whole register).
fn register_value(
    program: &crate::core::ir::Program,
    reg: u32,
    v: &case::Vertex,
) -> Result<[f32; 4], String> {
    let mut out: Option<[f32; 4]> = None;
    for d in program
        .inputs
        .iter()
        .filter(|d| d.reg.file == RegFile::Input && d.reg.index == reg)
    {
        let semantic = format!("{}{}", d.usage, d.usage_index);
        let value = v
            .attributes
            .get(&semantic)
            .ok_or_else(|| format!("no `{semantic}`, which the shader declares for v{reg}"))?
            .expand()
            .map_err(|m| format!("`{semantic}`: {m}"))?;
        let slot = out.get_or_insert(value);
        for c in 0..4 {
            if d.mask.has(c) {
                slot[c] = value[c];
            }
        }
    }
    out.ok_or_else(|| format!("v{reg} is not declared"))
}

/// The components of `v<reg>` that D3DSHADE_FLAT holds constant (the
/// draw lists' rule: [`crate::jobs::render::pixel_state::flat_components`]).
fn flat_components(program: &crate::core::ir::Program, reg: u32, shade: Shade) -> [bool; 4] {
    if shade == Shade::Gouraud {
        return [false; 4];
    }
    crate::jobs::render::pixel_state::flat_components(program, reg)
}

/// The application's constants, by register name.
fn constants(given: &BTreeMap<String, Constant>) -> Result<Constants, String> {
    let mut out = Constants::default();
    for (name, value) in given {
        let (file, index) = name.split_at(1);
        let index: usize = index
            .parse()
            .map_err(|_| format!("constant `{name}`: expected c#, i# or b#"))?;
        let bad = || format!("constant `{name}`: {value:?} does not fit");
        match (file, value) {
            ("c", Constant::Vector(v)) if v.len() == 4 && index < 224 => {
                if out.float.len() <= index {
                    out.float.resize(index + 1, [0.0; 4]);
                }
                out.float[index] = [v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32];
            }
            ("i", Constant::Vector(v))
                if v.len() == 4
                    && index < 16
                    && v.iter().all(|x| x.fract() == 0.0 && x.abs() < 1e9) =>
            {
                if out.int.len() <= index {
                    out.int.resize(index + 1, [0; 4]);
                }
                out.int[index] = [v[0] as i32, v[1] as i32, v[2] as i32, v[3] as i32];
            }
            ("b", Constant::Bool(b)) if index < 16 => {
                if out.bool.len() <= index {
                    out.bool.resize(index + 1, false);
                }
                out.bool[index] = *b;
            }
            _ => return Err(bad()),
        }
    }
    Ok(out)
}

/// A sampler binding with its texture and D3D9 sampler states.
fn sampler(s: &SamplerSpec) -> Result<Binding, String> {
    let t = &s.texture;
    if t.width == 0 || t.height == 0 || t.width > MAX_TARGET_SIDE || t.height > MAX_TARGET_SIDE {
        return Err(format!(
            "s{}: a {}x{} texture",
            s.sampler, t.width, t.height
        ));
    }
    if t.texels.len() != (t.width * t.height) as usize {
        return Err(format!(
            "s{}: a {}x{} texture needs {} texels, not {}",
            s.sampler,
            t.width,
            t.height,
            t.width * t.height,
            t.texels.len()
        ));
    }
    let filter = |f: FilterSpec| match f {
        FilterSpec::Point => Filter::Point,
        FilterSpec::Linear => Filter::Linear,
    };
    let address = |a: AddressSpec| match a {
        AddressSpec::Wrap => Address::Wrap,
        AddressSpec::Mirror => Address::Mirror,
        AddressSpec::Clamp => Address::Clamp,
        AddressSpec::Border => Address::Border,
        AddressSpec::MirrorOnce => Address::MirrorOnce,
    };
    let state = SamplerState {
        mag_filter: filter(s.mag_filter),
        min_filter: filter(s.min_filter),
        address_u: address(s.address_u),
        address_v: address(s.address_v),
        border: s.border.map_or([0.0; 4], |c| c.rgba()),
        ..SamplerState::default()
    };
    Ok(Binding {
        sampler: s.sampler,
        width: t.width,
        height: t.height,
        texels: t.rgba(),
        state,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A suite in memory: `shaders` as (name, text), `cases` as the JSON
    /// list of cases.
    fn suite(shaders: &[(&str, &str)], cases: &str) -> Suite {
        let names: Vec<String> = shaders
            .iter()
            .map(|(n, _)| format!(r#""{n}": {{"file": "{n}.psh", "lines": [1], "tokens": []}}"#))
            .collect();
        let json = format!(
            r#"{{"function": "f", "source": "s", "lines": [1, 2], "about": "",
                "shaders": {{{}}}, "cases": {cases}}}"#,
            names.join(", ")
        );
        let spec: SuiteSpec = serde_json::from_str(&json).unwrap();
        let shaders = shaders
            .iter()
            .map(|(n, text)| {
                let l = load::load_str(n, text, &Options::default());
                let l = match l {
                    Ok(l) => ShaderLoad::Loaded(Box::new(l)),
                    Err(e) => ShaderLoad::Refused(Box::new(e)),
                };
                (n.to_string(), l)
            })
            .collect();
        Suite {
            dir: PathBuf::from("."),
            spec,
            shaders,
        }
    }

    const TEXCOORD: &str = "ps_3_0\ndcl_texcoord0 v0\ndef c1, 0, 0, 0, 0\nif_lt v0.x, c1.x\ntexkill v0\nendif\nmov oC0, v0\n";

    /// A left-half triangle pair over an 8×2 target whose texcoord0.x is
    /// the clip-space x: negative on the left, where the shader kills.
    fn half_quad_case(extra_target: bool, texcoord: &str) -> String {
        let target = r#"{"name": "t", "width": 8, "height": 2, "format": "A8R8G8B8", "clear": "0xff0000ff"}"#;
        let targets = if extra_target {
            format!("{target}, {target}")
        } else {
            target.to_string()
        };
        format!(
            r#"[{{"name": "c", "lines": [], "note": "", "targets": [{targets}],
                "draws": [{{"shader": "s", "primitive": "triangle_strip", "positions": "clip",
                  "vertices": [
                    {{"position": [-1, -1, 0], "texcoord0": {texcoord}}},
                    {{"position": [-1, 1, 0], "texcoord0": {texcoord}}},
                    {{"position": [0.5, -1, 0], "texcoord0": [0.5, 1, 0, 1]}},
                    {{"position": [0.5, 1, 0], "texcoord0": [0.5, 1, 0, 1]}}]}}]}}]"#
        )
    }

    #[test]
    fn covered_pixels_take_the_shader_and_the_rest_keep_the_clear_colour() {
        let s = suite(&[("s", TEXCOORD)], &half_quad_case(true, "[-1, 1, 0, 1]"));
        let r = render(&s, &s.spec.cases[0], &mut emulate).unwrap();
        assert_eq!(r.backend_draws, 1, "both triangles share their planes");
        let blue = Some([0.0, 0.0, 1.0, 1.0]);
        // Screen x of the vertices: 0 and 6; texcoord0.x = x/4 - 1.
        for x in 0..8u32 {
            let want = match x {
                0..=3 => blue, // killed: x/4 - 1 < 0
                4..=5 => Some([x as f32 / 4.0 - 1.0, 1.0, 0.0, 1.0]),
                _ => blue, // not covered
            };
            assert_eq!(r.targets[0].texel(x, 0), want, "x = {x}");
            // oC1 is never written: the second target keeps its clear.
            assert_eq!(r.targets[1].texel(x, 1), blue);
        }
        assert_eq!(r.targets[0].texel(8, 0), None);
    }

    #[test]
    fn bad_cases_are_errors_that_name_the_case_and_draw() {
        let err = |shaders: &[(&str, &str)], cases: &str| {
            let s = suite(shaders, cases);
            render(&s, &s.spec.cases[0], &mut emulate).unwrap_err()
        };
        let e = err(
            &[("s", "ps_3_0\ndcl_texcoord1 v0\nmov oC0, v0\n")],
            &half_quad_case(false, "[0, 0]"),
        );
        assert_eq!(e.place, "f/c, draw 0");
        assert!(e.message.contains("no `texcoord1`"), "{e}");
        let e = err(
            &[("s", TEXCOORD)],
            &half_quad_case(false, "[1, 2, 3, 4, 5]"),
        );
        assert!(e.message.contains("5 components"), "{e}");
        let cases = half_quad_case(false, "[0, 0]").replace("[-1, -1, 0]", "[-1, -1, 0, 2]");
        let e = err(&[("s", TEXCOORD)], &cases);
        assert!(e.message.contains("w = 2"), "{e}");
        let cases = half_quad_case(true, "[0, 0]").replacen("\"width\": 8", "\"width\": 4", 1);
        let e = err(&[("s", TEXCOORD)], &cases);
        assert!(e.message.contains("one size"), "{e}");
        let e = err(
            &[("s", "ps_3_0\nmov oC0, v0\n")],
            &half_quad_case(false, "[0, 0]"),
        );
        assert!(e.message.contains("does not load"), "{e}");
        let cases = half_quad_case(false, "[0, 0]").replace("\"draws\"", "\"targets2\"");
        assert!(serde_json::from_str::<SuiteSpec>(&cases).is_err());
    }

    #[test]
    fn a_backend_that_returns_the_wrong_size_is_an_error() {
        let s = suite(&[("s", TEXCOORD)], &half_quad_case(false, "[0, 0]"));
        let mut small = |shader: &Shader, draw: &Draw| {
            let mut d = draw.clone();
            d.target_width = 2;
            emulate(shader, &d)
        };
        let e = render(&s, &s.spec.cases[0], &mut small).unwrap_err();
        assert!(e.message.contains("2x2 result for a 8x2 draw"), "{e}");
    }

    #[test]
    fn shader_files_stay_in_the_suites_folder() {
        let dir = std::env::temp_dir().join(format!("ps30-conformance-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("cases.json"),
            r#"{"function": "f", "source": "s", "lines": [1, 2], "about": "",
                "shaders": {"s": {"file": "../s.psh", "lines": [1], "tokens": []}}, "cases": []}"#,
        )
        .unwrap();
        let e = Suite::load(&dir).unwrap_err();
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(e.message.contains("not a file in the folder"), "{e}");
    }
}
