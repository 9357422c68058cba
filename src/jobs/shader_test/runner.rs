//! vkd3d's runner state machine (`run_shader_tests` and
//! `parse_test_directive` of `tests/shader_runner.c`) with the Direct3D 9
//! runner's choices: shader models 2.0–3.0, the capabilities `clip-planes`,
//! `fog` and `point-size` and no tags. It walks a file twice: once to learn
//! which shaders its draws compile ([`plan`]), once to run it ([`run`]).

use super::parse::{self, qualifier_args, Cursor, Kind, Section};
use super::resource;
use super::state::{Element, Fixed, Last, Mode, Rtv, Source, State, Stop};
use super::{CompileJob, FileReport, Probe, Settings, Verdict};
use crate::core::emu::{Address, Filter, MipFilter, SamplerState};
use crate::core::image::{RenderTarget, TargetFormat};
use std::collections::{BTreeMap, HashMap};

/// The default render target's size (vkd3d's RENDER_TARGET_WIDTH/HEIGHT).
pub(super) const DEFAULT_TARGET: (u32, u32) = (640, 480);

/// The compile jobs a file's draws need.
pub(super) fn plan(text: &str) -> Vec<CompileJob> {
    let mut s = State::new(Mode::Plan(Vec::new()), None);
    let _ = s.walk(text);
    match s.mode {
        Mode::Plan(jobs) => jobs,
        Mode::Run(_) => Vec::new(),
    }
}

/// Runs a file with its shaders compiled.
pub(super) fn run(
    path: &str,
    text: &str,
    compiled: &HashMap<CompileJob, Result<Vec<u8>, String>>,
    settings: &Settings,
) -> FileReport {
    let mut s = State::new(Mode::Run(compiled), Some(settings));
    s.report.path = path.to_string();
    if let Err(stop) = s.walk(text) {
        s.report.stopped = Some(stop.message);
        s.report.malformed = !stop.refused;
    }
    s.report
}

impl<'a> State<'a> {
    fn new(mode: Mode<'a>, settings: Option<&'a Settings>) -> State<'a> {
        State {
            mode,
            settings,
            min_sm: 0,
            max_sm: 1,
            skip: false,
            flags: Vec::new(),
            shaders: BTreeMap::new(),
            fail_mask: 0,
            uniforms: Vec::new(),
            rtvs: BTreeMap::new(),
            srvs: BTreeMap::new(),
            vbs: BTreeMap::new(),
            samplers: BTreeMap::new(),
            layout: Vec::new(),
            fixed: Fixed {
                alpha_func: 8,
                alpha_ref: 0.0,
                flat: false,
                clip_mask: 0,
                clip_planes: [[0.0; 4]; 8],
                point_size: [1.0, 1.0, f32::MAX],
                point_sprite: false,
                fog: None,
                fog_colour: [0.0; 4],
                fog_start: 0.0,
                fog_end: 1.0,
                fog_density: 1.0,
                ortho_fog: false,
                viewports: false,
            },
            last: Last::Ok,
            pending: Vec::new(),
            report: FileReport::default(),
        }
    }

    pub fn planning(&self) -> bool {
        matches!(self.mode, Mode::Plan(_))
    }

    fn walk(&mut self, text: &str) -> Result<(), Stop> {
        let (before, sections) = parse::sections(text);
        if let Some((n, l)) = before.first() {
            return Err(format!("line {n}: '{l}' is outside any section").into());
        }
        for section in &sections {
            self.section(section).map_err(|e| e.at(section.line))?;
        }
        Ok(())
    }

    fn section(&mut self, s: &Section) -> Result<(), Stop> {
        match &s.kind {
            Kind::Require => self.require(s),
            Kind::Shader { stage, qualifiers } => self.shader(s, stage, qualifiers),
            Kind::Sampler(slot) => self.sampler(*slot, s),
            Kind::Resource { kind, slot } => self.resource(kind, *slot, s),
            Kind::InputLayout => {
                self.layout.clear();
                for (n, l) in &s.lines {
                    self.layout
                        .push(element(l).map_err(|e| Stop::from(e).at(*n))?);
                }
                Ok(())
            }
            Kind::Test => {
                for (n, l) in &s.lines {
                    if self.skip || self.fail_mask & (1 << self.min_sm) != 0 {
                        continue;
                    }
                    self.report.ran = true;
                    self.report.model = Some(parse::MODELS[self.min_sm]);
                    self.test_line(*n, l).map_err(|e| e.at(*n))?;
                }
                Ok(())
            }
            Kind::Preproc => Ok(()),
            Kind::Unknown(h) => Err(format!("unknown section '{h}'").into()),
        }
    }

    fn require(&mut self, s: &Section) -> Result<(), Stop> {
        self.min_sm = 0;
        self.max_sm = 1;
        self.flags.clear();
        let mut missing = false;
        for (_, l) in &s.lines {
            let mut c = Cursor::new(l);
            if c.word("shader model >=") || c.rest.trim_start().starts_with("shader model <") {
                let less = !l.contains(">=");
                let r = c
                    .rest
                    .trim_start()
                    .trim_start_matches("shader model <")
                    .trim_start();
                let (m, _) = parse::MODELS
                    .iter()
                    .enumerate()
                    .find(|(_, m)| r.starts_with(*m))
                    .ok_or_else(|| format!("unknown shader model '{r}'"))?;
                if less {
                    if m == 0 {
                        return Err(format!("shader model < '{r}' is invalid").into());
                    }
                    self.max_sm = self.max_sm.min(m - 1);
                } else {
                    self.min_sm = self.min_sm.max(m);
                }
            } else if c.word("options:") {
                // vkd3d matches the names once each, in this order, each
                // from where the last match ended: `column-major row-major`
                // sets column-major alone.
                for (word, flag) in [
                    ("none", ""),
                    ("row-major", "PACK_MATRIX_ROW_MAJOR"),
                    ("column-major", "PACK_MATRIX_COLUMN_MAJOR"),
                    ("backcompat", "ENABLE_BACKWARDS_COMPATIBILITY"),
                ] {
                    if c.word(word) && !flag.is_empty() {
                        self.flags.push(flag);
                    }
                }
            } else if c.word("format") {
                // Format capabilities (uav-load): Direct3D 9 has none.
                missing = true;
            } else {
                let cap = l.trim();
                if !["clip-planes", "fog", "point-size"].contains(&cap) {
                    const KNOWN: [&str; 9] = [
                        "depth-bounds",
                        "float64",
                        "geometry-shader",
                        "int64",
                        "native-16-bit",
                        "rov",
                        "rt-vp-array-index",
                        "tessellation-shader",
                        "wave-ops",
                    ];
                    if !KNOWN.contains(&cap) {
                        return Err(format!("unknown require directive '{cap}'").into());
                    }
                    missing = true;
                }
            }
        }
        self.skip = self.max_sm < self.min_sm || missing;
        Ok(())
    }

    fn shader(&mut self, s: &Section, stage: &str, qualifiers: &str) -> Result<(), Stop> {
        let mut fail = 0u32;
        let (mut hex, mut foreign) = (false, false);
        let mut c = Cursor::new(qualifiers);
        while !c.at_end() {
            if c.word("todo") {
                qualifier_args(&mut c, self.min_sm)?;
            } else if c.word("fail") || c.word("notimpl") {
                fail |= qualifier_args(&mut c, self.min_sm)?.1;
            } else if c.word("d3dbc-hex") {
                hex = true;
            } else if c.word("dxbc-tpf-hex") || c.word("dxbc-dxil-hex") {
                foreign = true;
            } else {
                return Err(format!("malformed shader header qualifiers '{qualifiers}'").into());
            }
        }
        self.fail_mask = fail;
        let mut text = String::new();
        for (_, l) in &s.lines {
            text.push_str(l);
            text.push('\n');
        }
        self.shaders
            .insert(stage.to_string(), Source { text, hex, foreign });
        Ok(())
    }

    fn sampler(&mut self, slot: u32, s: &Section) -> Result<(), Stop> {
        let mut state = SamplerState {
            mag_filter: Filter::Point,
            min_filter: Filter::Point,
            mip_filter: MipFilter::Point,
            address_u: Address::Clamp,
            address_v: Address::Clamp,
            address_w: Address::Clamp,
            border: [0.0; 4],
            ..SamplerState::default()
        };
        for (n, l) in &s.lines {
            sampler_line(&mut state, l).map_err(|e| Stop::from(e).at(*n))?;
        }
        self.samplers.insert(slot, state);
        Ok(())
    }

    fn resource(&mut self, kind: &str, slot: u32, s: &Section) -> Result<(), Stop> {
        let mut r = resource::ResourceText::default();
        for (n, l) in &s.lines {
            r.line(l).map_err(|e| Stop::from(e).at(*n))?;
        }
        if self.skip {
            return Ok(());
        }
        match kind {
            "rtv" => {
                let format = match r.format.as_deref() {
                    None | Some("r32g32b32a32-float") => TargetFormat::A32B32G32R32F,
                    Some("r32-float") => TargetFormat::R32F,
                    Some(f) => {
                        return Err(format!(
                            "render target format {f}: vkd3d's Direct3D 9 runner creates none"
                        )
                        .into())
                    }
                };
                let (w, h) = (r.width.max(1), r.height.max(1));
                resource::check_size(w, h)?;
                self.settle()?;
                self.rtvs.insert(
                    slot,
                    Rtv {
                        target: RenderTarget::new(w, h, format),
                    },
                );
            }
            "srv" => {
                self.srvs.insert(slot, r.texture());
            }
            "vb" => {
                self.vbs.insert(slot, r.data);
            }
            "uav" => return Err(Stop::refused("UAVs are not supported")),
            _ => return Err(Stop::refused("DSVs are not supported")),
        }
        Ok(())
    }

    /// Applies every pending clear and draw to the whole of each target
    /// (before a target is replaced, which the pending draws drew into).
    fn settle(&mut self) -> Result<(), Stop> {
        if self.pending.is_empty() {
            return Ok(());
        }
        let (w, h) = self.rtvs.values().fold((0, 0), |a, r| {
            (a.0.max(r.target.width), a.1.max(r.target.height))
        });
        match super::draw::replay(self, [0, 0, w, h]) {
            Ok(targets) => {
                for (k, t) in targets {
                    if let Some(r) = self.rtvs.get_mut(&k) {
                        r.target = t;
                    }
                }
            }
            Err(e) => self.last = Last::Unsupported(e),
        }
        self.pending.clear();
        Ok(())
    }

    pub fn note(&mut self, line: usize, what: String) {
        self.report.notes.push((line, what));
    }

    pub fn probe(&mut self, line: usize, text: &str, verdict: Verdict) {
        self.report.probes.push(Probe {
            line,
            text: text.to_string(),
            verdict,
        });
    }

    /// vkd3d's `set_default_target`: a 640 × 480 A32B32G32R32F target at
    /// slot 0 when the file made none.
    pub fn default_target(&mut self) {
        self.rtvs.entry(0).or_insert_with(|| Rtv {
            target: RenderTarget::new(
                DEFAULT_TARGET.0,
                DEFAULT_TARGET.1,
                TargetFormat::A32B32G32R32F,
            ),
        });
    }

    fn test_line(&mut self, n: usize, line: &str) -> Result<(), Stop> {
        let mut c = Cursor::new(line);
        loop {
            let before = c.rest;
            if c.word("todo") || c.word("bug") {
                // Native Windows ignores todo and bug: every check counts.
                qualifier_args(&mut c, self.min_sm)?;
                continue;
            }
            if c.word("if") {
                if !qualifier_args(&mut c, self.min_sm)?.0 {
                    return Ok(());
                }
                continue;
            }
            if before == c.rest {
                break;
            }
        }
        if c.word("probe") {
            if !self.planning() {
                let verdict = super::probe::probe(self, line, c)?;
                self.probe(n, line, verdict);
            }
            return Ok(());
        }
        super::draw::directive(self, n, line, c)
    }
}

fn element(line: &str) -> Result<Element, String> {
    let mut c = Cursor::new(line);
    let slot = c
        .uint()
        .ok_or_else(|| format!("malformed input layout directive '{line}'"))?;
    let (format, size) = resource::format(&mut c)?;
    c.ws();
    let name_len = c.rest.find(char::is_whitespace).unwrap_or(c.rest.len());
    let name = c.rest[..name_len].to_string();
    c.rest = &c.rest[name_len..];
    let index = c.uint().unwrap_or(0);
    Ok(Element {
        slot,
        format,
        size,
        name,
        index,
    })
}

fn address(c: &mut Cursor<'_>) -> Result<Address, String> {
    for (w, a) in [
        ("border", Address::Border),
        ("clamp", Address::Clamp),
        ("mirror_once", Address::MirrorOnce),
        ("mirror", Address::Mirror),
        ("wrap", Address::Wrap),
    ] {
        if c.word(w) {
            return Ok(a);
        }
    }
    Err(format!("unknown sampler address mode '{}'", c.rest))
}

/// One `[sampler N]` line. The filter is set as vkd3d's Direct3D 9 runner
/// sets it from the D3D12_FILTER value: MINFILTER from bit 0x1 (D3D12's
/// mip bit), MAGFILTER from 0x4, MIPFILTER from 0x10 (D3D12's min bit),
/// POINT where the bit is clear — so `filter linear point point` is a
/// linear mip filter on Direct3D 9, and the expected pixels were recorded
/// that way.
fn sampler_line(state: &mut SamplerState, line: &str) -> Result<(), String> {
    let mut c = Cursor::new(line);
    if c.word("address") {
        state.address_u = address(&mut c)?;
        state.address_v = address(&mut c)?;
        state.address_w = address(&mut c)?;
        return Ok(());
    }
    if c.word("filter") {
        let words: Vec<&str> = c.rest.split_whitespace().take(3).collect();
        let lin = |w: &str| match w {
            "linear" => Ok(true),
            "point" => Ok(false),
            _ => Err(format!("unknown sampler filter '{line}'")),
        };
        if words.len() != 3 {
            return Err(format!("unknown sampler filter '{line}'"));
        }
        let (min, mag, mip) = (lin(words[0])?, lin(words[1])?, lin(words[2])?);
        let bits = u32::from(mip) | u32::from(mag) << 2 | u32::from(min) << 4;
        let f = |b: u32| {
            if bits & b != 0 {
                Filter::Linear
            } else {
                Filter::Point
            }
        };
        state.min_filter = f(0x1);
        state.mag_filter = f(0x4);
        state.mip_filter = if bits & 0x10 != 0 {
            MipFilter::Linear
        } else {
            MipFilter::Point
        };
        return Ok(());
    }
    if c.word("comparison") {
        // The Direct3D 9 runner sets no comparison: Direct3D 9 has none.
        return Ok(());
    }
    Err(format!("unknown sampler directive '{line}'"))
}
