//! The test lines (`parse_test_directive`) and the draws they make: the
//! runner's state becomes one draw list of [`crate::jobs::render`] — the
//! file's render targets with what earlier draws left in them, its
//! textures and sampler states, the vertex buffers read through the input
//! layout as D3DDECLTYPE_FLOAT1/2/4, the vertex shader and pixel shader as
//! Microsoft's compiler made them, the uniforms as `c#` of both — and the
//! list runs on the emulator.

use super::parse::{self, Cursor};
use super::state::{Element, Last, Mode, Op, State, Stop};
use super::CompileJob;
use crate::core::decltype::DeclType;
use crate::core::emu::vertex::{Attribute, Vertices};
use crate::core::emu::{Constants, SamplerState};
use crate::core::image::TargetFormat;
use crate::core::load;
use crate::core::merge::{self, ColorWrite, OutputState};
use crate::core::raster::fog::{Fog, FogMode};
use crate::core::raster::points::PointState;
use crate::core::raster::{Cull, Primitive, Viewport};
use crate::jobs::render::geometry::state::RasterState;
use crate::jobs::render::geometry::Geometry;
use crate::jobs::render::pixel_state::{AlphaTest, CmpFunc, PixelState};
use crate::jobs::render::{
    self, DrawList, DrawStep, ShaderSpec, Source, Step, TargetSpec, TargetState, TextureData,
};

/// A sampler's binding: `s#`, what it reads, its state.
type Bound = (u32, Source, SamplerState);

/// `draw quad`'s vertex shader when the file has none.
const QUAD_VS: &str = "float4 main(float4 pos : position) : sv_position\n{\n    return pos;\n}";

/// `draw quad`'s one triangle, covering the viewport.
const QUAD: [[f32; 2]; 3] = [[-2.0, -2.0], [-2.0, 4.0], [4.0, -2.0]];

/// D3DCMPFUNC names by vkd3d's spelling, in its matching order.
const FUNCS: [(&str, &str); 8] = [
    ("less equal", "LESSEQUAL"),
    ("not equal", "NOTEQUAL"),
    ("greater equal", "GREATEREQUAL"),
    ("never", "NEVER"),
    ("less", "LESS"),
    ("equal", "EQUAL"),
    ("greater", "GREATER"),
    ("always", "ALWAYS"),
];

fn cmp_func(c: &mut Cursor<'_>) -> Result<u32, String> {
    for (word, name) in FUNCS {
        if c.word(word) {
            let f = CmpFunc::from_name(name).expect("a D3DCMPFUNC name");
            return Ok(f as u32 + 1);
        }
    }
    Err(format!("unknown comparison func '{}'", c.rest))
}

/// One test line after its `todo`/`bug`/`if` qualifiers.
pub(super) fn directive(
    s: &mut State<'_>,
    n: usize,
    line: &str,
    mut c: Cursor<'_>,
) -> Result<(), Stop> {
    if c.word("dispatch") {
        return Err(Stop::refused("compute shaders are not supported"));
    }
    if c.word("clear rtv") {
        let slot = c
            .uint()
            .ok_or_else(|| format!("malformed rtv clear '{line}'"))?;
        let v: Vec<f32> = (0..4).map_while(|_| c.float()).collect();
        if v.len() < 4 {
            return Err(format!("malformed rtv clear '{line}'").into());
        }
        s.default_target();
        if !s.rtvs.contains_key(&slot) {
            return Err("resource not found".into());
        }
        // ColorFill with a D3DCOLOR: each channel × 255, truncated.
        let byte = |x: f32| (x * 255.0).clamp(0.0, 255.0) as u8;
        s.pending.push(Op::Clear(
            slot,
            [byte(v[0]), byte(v[1]), byte(v[2]), byte(v[3])],
        ));
        return Ok(());
    }
    if c.word("clear dsv") || c.word("depth-bounds") {
        return Err(Stop::refused("depth-stencil views are not supported"));
    }
    if c.word("depth") || c.word("sample mask") {
        // Without a depth-stencil view or multisampling the Direct3D 9
        // runner sets neither.
        return Ok(());
    }
    if c.word("draw quad") {
        return draw(s, n, None, 3);
    }
    if c.word("draw") {
        let topology = [
            ("triangle list", Primitive::TriangleList),
            ("triangle strip", Primitive::TriangleStrip),
            ("point list", Primitive::PointList),
        ]
        .into_iter()
        .find(|(w, _)| c.word(w))
        .map(|t| t.1)
        .ok_or_else(|| format!("unknown or unsupported primitive topology '{}'", c.rest))?;
        let count = c
            .uint()
            .ok_or_else(|| format!("malformed vertex count '{line}'"))?;
        if c.uint().is_some_and(|i| i > 1) {
            return Err(Stop::refused("instanced draws are not supported"));
        }
        return draw(s, n, Some(topology), count);
    }
    if c.word("copy") {
        s.note(
            n,
            "copy: the Direct3D 9 runner cannot copy (a failure there too)".into(),
        );
        return Ok(());
    }
    if c.word("uniform") {
        return uniform(s, line, c);
    }
    fixed(s, line, c)
}

/// The fixed-function state lines.
fn fixed(s: &mut State<'_>, line: &str, mut c: Cursor<'_>) -> Result<(), Stop> {
    if c.word("alpha test") {
        s.fixed.alpha_func = cmp_func(&mut c)?;
        s.fixed.alpha_ref = c.float().unwrap_or(0.0);
    } else if c.word("shade mode") {
        s.fixed.flat = c.word("flat");
    } else if c.word("clip-plane") {
        let i = c
            .uint()
            .filter(|&i| i < 8)
            .ok_or_else(|| format!("malformed clip plane '{line}'"))?;
        if c.word("disable") {
            s.fixed.clip_mask &= !(1 << i);
        } else {
            let v: Vec<f32> = (0..4).map_while(|_| c.float()).collect();
            let v: [f32; 4] = v
                .try_into()
                .map_err(|_| format!("malformed clip plane '{line}'"))?;
            s.fixed.clip_planes[i as usize] = v;
            s.fixed.clip_mask |= 1 << i;
        }
    } else if c.word("point-size") {
        for k in 0..3 {
            s.fixed.point_size[k] = c.float().unwrap_or(0.0);
        }
    } else if c.word("point-sprite") {
        s.fixed.point_sprite = c.word("on");
    } else if c.word("fog") {
        fog(s, line, c)?;
    } else if c.word("fog-colour") {
        let v: Vec<f32> = (0..4).map_while(|_| c.float()).collect();
        s.fixed.fog_colour = v
            .try_into()
            .map_err(|_| format!("malformed float4 constant '{line}'"))?;
    } else if c.word("viewport") {
        s.fixed.viewports = true;
    } else {
        return Err(format!("unknown test directive '{line}'").into());
    }
    Ok(())
}

/// `fog MODE [ortho|non-ortho] CONSTANTS`, read as vkd3d reads it: the
/// mode (`disable`, `none`, `linear`, `exp`, `exp2`), the projection's
/// kind (kept from the line before when not given), then FOGSTART and
/// FOGEND for linear fog or FOGDENSITY for exp and exp2.
fn fog(s: &mut State<'_>, line: &str, mut c: Cursor<'_>) -> Result<(), Stop> {
    if c.word("disable") {
        s.fixed.fog = None;
        return Ok(());
    }
    let mode = [
        ("none", FogMode::Vertex),
        ("linear", FogMode::Linear),
        ("exp", FogMode::Exp),
        ("exp2", FogMode::Exp2),
    ]
    .into_iter()
    .find(|(w, _)| c.word(w))
    .map(|m| m.1)
    .ok_or_else(|| format!("invalid fog mode '{}'", c.rest))?;
    s.fixed.fog = Some(mode);
    if c.word("ortho") {
        s.fixed.ortho_fog = true;
    }
    if c.word("non-ortho") {
        s.fixed.ortho_fog = false;
    }
    let bad = || format!("malformed fog constants '{line}'");
    match mode {
        FogMode::Linear => {
            s.fixed.fog_start = c.float().ok_or_else(bad)?;
            s.fixed.fog_end = c.float().ok_or_else(bad)?;
        }
        FogMode::Exp | FogMode::Exp2 => s.fixed.fog_density = c.float().ok_or_else(bad)?,
        FogMode::Vertex => {}
    }
    Ok(())
}

/// The draw's fog: D3DRS_FOGENABLE with D3DRS_FOGTABLEMODE as the file
/// set it (D3DRS_FOGVERTEXMODE stays D3DFOG_NONE, so `none` is the vertex
/// shader's own fog), D3DRS_FOGCOLOR as a D3DCOLOR, and table fog from w
/// unless the runner's projection matrix is the identity (`ortho`).
fn fog_state(s: &State<'_>) -> Option<Fog> {
    let byte = |x: f32| f32::from((x * 255.0).clamp(0.0, 255.0) as u8) / 255.0;
    s.fixed.fog.map(|mode| Fog {
        mode,
        color: s.fixed.fog_colour.map(byte),
        start: f64::from(s.fixed.fog_start),
        end: f64::from(s.fixed.fog_end),
        density: f64::from(s.fixed.fog_density),
        w: !s.fixed.ortho_fog && mode != FogMode::Vertex,
    })
}

/// `uniform N TYPE values`: raw 32-bit words at word offset N; words the
/// array grows by are filled with 0x7f7f7f7f first.
fn uniform(s: &mut State<'_>, line: &str, mut c: Cursor<'_>) -> Result<(), Stop> {
    let offset = c
        .uint()
        .ok_or_else(|| format!("malformed uniform offset '{line}'"))? as usize;
    let bad = || format!("malformed uniform '{line}'");
    let mut words: Vec<u32> = Vec::new();
    if c.word("float4") || c.word("float") {
        let n = if line.contains("float4") { 4 } else { 1 };
        for _ in 0..n {
            words.push(c.float().ok_or_else(bad)?.to_bits());
        }
    } else if c.word("double2") {
        for _ in 0..2 {
            let (v, r) = parse::strtof(c.rest).ok_or_else(bad)?;
            c.rest = r;
            let d = (v as f64).to_bits();
            words.extend([d as u32, (d >> 32) as u32]);
        }
    } else if c.word("int4") || c.word("uint4") {
        for _ in 0..4 {
            words.push(c.uint().ok_or_else(bad)?);
        }
    } else if c.word("int") || c.word("uint") {
        words.push(c.uint().ok_or_else(bad)?);
    } else {
        return Err(format!("unsupported uniform type '{line}'").into());
    }
    if offset > 4096 {
        return Err(format!("uniform offset {offset} is past the constant registers").into());
    }
    let end = offset + words.len();
    let count = s.uniforms.len().max(end).div_ceil(4) * 4;
    s.uniforms.resize(count, 0x7f7f_7f7f);
    s.uniforms[offset..end].copy_from_slice(&words);
    Ok(())
}

/// The bytecode of one stage's shader at the file's model, or why there is
/// none. While planning, records the job and answers `None`.
fn shader(s: &mut State<'_>, stage: &str, fallback: Option<&str>) -> Result<Option<Vec<u8>>, Last> {
    let prefix = if stage == "pixel" { "ps" } else { "vs" };
    let profile = format!("{prefix}_{}_0", s.min_sm + 2);
    let source = match s.shaders.get(stage) {
        Some(src) if src.foreign => {
            return Err(Last::Unsupported("shader model 4 bytecode".into()))
        }
        Some(src) if src.hex => return hex(&src.text).map(Some).map_err(Last::Failed),
        Some(src) => src.text.clone(),
        None => match fallback {
            Some(f) => f.to_string(),
            None => return Err(Last::Failed(format!("no {stage} shader"))),
        },
    };
    let job = CompileJob {
        source,
        profile,
        flags: s.flags.clone(),
    };
    match &mut s.mode {
        Mode::Plan(jobs) => {
            jobs.push(job);
            Ok(None)
        }
        Mode::Run(done) => match done.get(&job) {
            Some(Ok(bytes)) => Ok(Some(bytes.clone())),
            Some(Err(e)) => Err(Last::Failed(format!(
                "the {} shader does not compile: {e}",
                job.profile
            ))),
            None => Err(Last::Failed("the shader was not compiled".into())),
        },
    }
}

/// `d3dbc-hex`: 32-bit words in hexadecimal, `%` starting a comment.
fn hex(text: &str) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    for line in text.lines() {
        let line = line.split('%').next().unwrap_or("");
        for w in line.split_whitespace() {
            let v = u32::from_str_radix(w, 16).map_err(|_| format!("malformed hex word '{w}'"))?;
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    Ok(out)
}

/// A draw: `topology` `None` is `draw quad`.
fn draw(s: &mut State<'_>, n: usize, topology: Option<Primitive>, count: u32) -> Result<(), Stop> {
    if s.fixed.viewports {
        return Err(Stop::refused("viewports are not supported"));
    }
    s.default_target();
    if topology.is_none() {
        // The quad replaces the input layout and vertex buffer 0.
        s.layout = vec![Element {
            slot: 0,
            format: "r32g32-float".into(),
            size: 8,
            name: "position".into(),
            index: 0,
        }];
        s.vbs.insert(
            0,
            QUAD.iter()
                .flatten()
                .flat_map(|v| v.to_le_bytes())
                .collect(),
        );
    }
    let quad_vs = topology.is_none().then_some(QUAD_VS);
    let vs = shader(s, "vertex", quad_vs);
    let ps = shader(s, "pixel", None);
    let outcome = match (vs, ps) {
        (Ok(Some(vs)), Ok(Some(ps))) => run_draw(
            s,
            topology.unwrap_or(Primitive::TriangleList),
            count,
            &vs,
            &ps,
        ),
        (Ok(None), _) | (_, Ok(None)) => return Ok(()),
        (Err(e), _) | (_, Err(e)) => e,
    };
    match &outcome {
        Last::Ok => {}
        Last::Failed(why) => s.note(n, format!("draw failed: {why}")),
        Last::Unsupported(why) => s.note(n, format!("draw unsupported: {why}")),
    }
    s.last = outcome;
    Ok(())
}

fn loaded(name: &str, bytes: &[u8]) -> Result<load::Loaded, Last> {
    let options = load::Options::default();
    let file = load::source_file(name, bytes.to_vec(), &options)
        .map_err(|e| Last::Unsupported(format!("ps30 cannot read the compiled {name}: {e}")))?;
    load::load(file, &options).map_err(|e| {
        let first = e.to_string().lines().next().unwrap_or("").to_string();
        Last::Unsupported(format!("ps30 refuses the compiled {name}: {first}"))
    })
}

fn run_draw(s: &mut State<'_>, topology: Primitive, count: u32, vs: &[u8], ps: &[u8]) -> Last {
    if s.rtvs.keys().any(|&k| k > 3) {
        return Last::Unsupported("render targets past slot 3".into());
    }
    let (vs, ps) = match (loaded("vertex shader", vs), loaded("pixel shader", ps)) {
        (Ok(v), Ok(p)) => (v, p),
        (Err(e), _) | (_, Err(e)) => return e,
    };
    let list = match build(s, topology, count, vs, ps) {
        Ok(list) => list,
        Err(e) => return e,
    };
    if overwrites_everything(s, &list) {
        s.pending.clear();
    }
    let slots: Vec<u32> = s.rtvs.keys().copied().collect();
    s.pending.push(Op::Draw(Box::new(list), slots));
    Last::Ok
}

/// Whether a draw replaces every pixel of every target, so that what came
/// before it can never be read: `draw quad` with the default vertex shader
/// into one target, without alpha test, clip planes or `texkill`.
fn overwrites_everything(s: &State<'_>, list: &DrawList) -> bool {
    let Some(Step::Draw(d)) = list.steps.first() else {
        return false;
    };
    let quad = d.geometry.as_ref().is_some_and(|g| {
        g.vertices.count == 3 && g.clip_planes.is_empty() && g.primitive == Primitive::TriangleList
    });
    let kills = list.shaders[0]
        .loaded
        .shader
        .program()
        .instructions
        .iter()
        .any(|i| i.op == crate::core::isa::Opcode::TexKill);
    quad && !kills
        && !s.shaders.contains_key("vertex")
        && d.pixel.alpha_test.is_none()
        && s.rtvs.len() == 1
}

/// The targets as the pending clears and draws leave them within `rect`
/// (`[left, top, right, bottom]`; the rest of each target is stale).
pub(super) fn replay(
    s: &State<'_>,
    rect: [u32; 4],
) -> Result<std::collections::BTreeMap<u32, crate::core::image::RenderTarget>, String> {
    let mut targets: std::collections::BTreeMap<u32, _> =
        s.rtvs.iter().map(|(k, r)| (*k, r.target.clone())).collect();
    let settings = s.settings.map(|x| x.render.clone()).unwrap_or_default();
    for op in &s.pending {
        match op {
            Op::Clear(slot, color) => {
                if let Some(t) = targets.get_mut(slot) {
                    merge::clear(t, *color);
                }
            }
            Op::Draw(list, slots) => {
                let mut list = (**list).clone();
                if let Some(Step::Draw(d)) = list.steps.first_mut() {
                    if let Some(g) = d.geometry.as_mut() {
                        g.scissor = Some(crate::core::raster::Rect {
                            left: rect[0],
                            top: rect[1],
                            right: rect[2],
                            bottom: rect[3],
                        });
                    }
                }
                let states: Vec<TargetState> = slots
                    .iter()
                    .filter_map(|k| targets.get(k))
                    .map(|t| TargetState {
                        target: t.clone(),
                        mips: None,
                        depth: None,
                    })
                    .collect();
                let (_, after) = render::run_on(&list, &settings, states, &mut |_, _| {}, None)
                    .map_err(|e| {
                        format!(
                            "the draw list refuses the draw: {}",
                            first_words(&e.to_string())
                        )
                    })?;
                for (k, st) in slots.iter().zip(after) {
                    targets.insert(*k, st.target);
                }
            }
        }
    }
    Ok(targets)
}

/// A message without its numbers and places, for counting reasons.
fn first_words(message: &str) -> String {
    message.chars().take(160).collect()
}

/// The draw list of one draw.
fn build(
    s: &State<'_>,
    topology: Primitive,
    count: u32,
    vs: load::Loaded,
    ps: load::Loaded,
) -> Result<DrawList, Last> {
    let slots: Vec<u32> = s.rtvs.keys().copied().collect();
    let targets: Vec<TargetSpec> = slots
        .iter()
        .map(|k| {
            let t = &s.rtvs[k].target;
            TargetSpec {
                name: format!("rtv{k}"),
                width: t.width,
                height: t.height,
                format: t.format,
            }
        })
        .collect();
    let fb = targets.iter().fold((u32::MAX, u32::MAX), |a, t| {
        (a.0.min(t.width), a.1.min(t.height))
    });
    let main = slots
        .iter()
        .position(|&k| k == 0)
        .ok_or_else(|| Last::Unsupported("no render target at slot 0".into()))?;
    let declared: Vec<u32> = ps
        .shader
        .program()
        .samplers
        .iter()
        .map(|d| d.index)
        .collect();
    let (textures, samplers) = textures(s, &declared)?;
    let vertices = vertices(s, topology, count)?;
    let constants = Constants {
        float: s
            .uniforms
            .chunks(4)
            .map(|c| std::array::from_fn(|i| f32::from_bits(c.get(i).copied().unwrap_or(0))))
            .collect(),
        ..Constants::default()
    };
    let mut pixel_constants = constants.clone();
    pixel_constants.float.truncate(224);
    let mut outputs: crate::jobs::render::pixel_state::Outputs = [None; 3];
    for (i, k) in slots.iter().enumerate() {
        if (1..=3).contains(k) {
            outputs[*k as usize - 1] = Some((i, ColorWrite::ALL));
        }
    }
    let alpha = alpha_test(s.fixed.alpha_func, s.fixed.alpha_ref, targets[main].format);
    let geometry = Geometry {
        vertices,
        indices: None,
        primitive: topology,
        vertex_shader: Some(1),
        vertex_constants: constants,
        vertex_samplers: Vec::new(),
        viewport: Some(Viewport {
            x: 0,
            y: 0,
            width: fb.0,
            height: fb.1,
            min_z: 0.0,
            max_z: 1.0,
        }),
        scissor: None,
        cull: Cull::None,
        clip_planes: (0..6)
            .filter(|i| s.fixed.clip_mask & (1 << i) != 0)
            .map(|i| s.fixed.clip_planes[i].map(f64::from))
            .collect(),
        depth: None,
        state: RasterState {
            points: PointState {
                size: f64::from(s.fixed.point_size[0]),
                min: f64::from(s.fixed.point_size[1]),
                max: f64::from(s.fixed.point_size[2]),
                sprite: s.fixed.point_sprite,
                scale: None,
            },
            fog: fog_state(s),
            ..RasterState::default()
        },
    };
    let step = DrawStep {
        target: main,
        shader: 0,
        inputs: Vec::new(),
        constants: pixel_constants,
        samplers,
        output: OutputState::default(),
        pixel: Box::new(PixelState {
            alpha_test: alpha,
            outputs,
            flat: s.fixed.flat,
            ..PixelState::default()
        }),
        geometry: Some(Box::new(geometry)),
    };
    Ok(DrawList {
        targets,
        textures,
        shaders: vec![
            ShaderSpec {
                name: "pixel shader".into(),
                loaded: ps,
            },
            ShaderSpec {
                name: "vertex shader".into(),
                loaded: vs,
            },
        ],
        steps: vec![Step::Draw(step)],
    })
}

/// D3DRS_ALPHAFUNC and D3DRS_ALPHAREF = (DWORD)(ref × 255.0) on a target
/// of `format`; ALWAYS is the same as no test.
fn alpha_test(func: u32, reference: f32, format: TargetFormat) -> Option<AlphaTest> {
    let name = [
        "NEVER",
        "LESS",
        "EQUAL",
        "LESSEQUAL",
        "GREATER",
        "NOTEQUAL",
        "GREATEREQUAL",
        "ALWAYS",
    ]
    .get(func.checked_sub(1)? as usize)?;
    let func = CmpFunc::from_name(name)?;
    let reference = (f64::from(reference) * 255.0).clamp(0.0, 255.0) as u8;
    (func != CmpFunc::Always).then(|| AlphaTest::new(func, reference, format))
}

/// The file's textures the pixel shader declares a sampler for, with the
/// sampler state of their slot: the file's `[sampler N]`, else Direct3D
/// 9's defaults (WRAP, POINT, no mips).
fn textures(s: &State<'_>, declared: &[u32]) -> Result<(Vec<TextureData>, Vec<Bound>), Last> {
    let mut textures = Vec::new();
    let mut samplers = Vec::new();
    for (slot, t) in s.srvs.iter().filter(|(k, _)| declared.contains(k)) {
        let t = t.as_ref().map_err(|e| Last::Unsupported(e.clone()))?;
        if *slot >= 16 {
            return Err(Last::Unsupported("sampler slots past s15".into()));
        }
        let state = s.samplers.get(slot).copied().unwrap_or(SamplerState {
            address_u: crate::core::emu::Address::Wrap,
            address_v: crate::core::emu::Address::Wrap,
            address_w: crate::core::emu::Address::Wrap,
            border: [0.0; 4],
            ..SamplerState::default()
        });
        samplers.push((*slot, Source::Texture(textures.len()), state));
        textures.push(TextureData {
            name: format!("srv{slot}"),
            width: t.width,
            height: t.height,
            texels: Vec::new(),
            file: Some(t.file.clone()),
        });
    }
    Ok((textures, samplers))
}

/// The vertices a draw reads: each input-layout element from its vertex
/// buffer at its offset (the elements of one slot packed in order), as
/// D3DDECLTYPE_FLOAT1/2/4 expand them ([`DeclType::decode`]: missing y, z
/// as 0, w as 1).
fn vertices(s: &State<'_>, topology: Primitive, count: u32) -> Result<Vertices, Last> {
    let count = match topology {
        Primitive::TriangleList => count / 3 * 3,
        _ => count,
    } as usize;
    if count > crate::jobs::render::geometry::MAX_VERTICES {
        return Err(Last::Unsupported(format!("{count} vertices")));
    }
    let mut attributes: Vec<(Attribute, Vec<[f32; 4]>)> = Vec::new();
    for (i, e) in s.layout.iter().enumerate() {
        let decl = match e.format.as_str() {
            "r32-float" => DeclType::Float1,
            "r32g32-float" => DeclType::Float2,
            "r32g32b32a32-float" => DeclType::Float4,
            f => {
                return Err(Last::Unsupported(format!(
                    "vertex format {f} (vkd3d's Direct3D 9 runner stops there)"
                )))
            }
        };
        let usage = match e.name.to_ascii_lowercase().as_str() {
            "position" | "sv_position" => "position",
            "color" => "color",
            "psize" => "psize",
            "texcoord" => "texcoord",
            other => {
                return Err(Last::Unsupported(format!(
                    "vertex usage {other} (vkd3d's Direct3D 9 runner stops there)"
                )))
            }
        };
        let offset: u32 = s.layout[..i]
            .iter()
            .filter(|o| o.slot == e.slot)
            .map(|o| o.size)
            .sum();
        let stride: u32 = s
            .layout
            .iter()
            .filter(|o| o.slot == e.slot)
            .map(|o| o.size)
            .sum();
        let data = s.vbs.get(&e.slot).map(Vec::as_slice).unwrap_or(&[]);
        let mut values = Vec::with_capacity(count);
        for v in 0..count {
            let at = (v as u64 * u64::from(stride) + u64::from(offset)) as usize;
            let bytes = data.get(at..at + decl.size()).ok_or_else(|| {
                Last::Failed(format!(
                    "vertex buffer {} holds {} bytes, too few for {count} vertices",
                    e.slot,
                    data.len()
                ))
            })?;
            values.push(decl.decode(bytes));
        }
        attributes.push((
            Attribute {
                usage: usage.into(),
                index: e.index,
            },
            values,
        ));
    }
    Ok(Vertices { count, attributes })
}
