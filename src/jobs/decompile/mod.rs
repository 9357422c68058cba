//! `ps30 decompile --verify`: the decompiled HLSL compiled by Microsoft's
//! compiler ([`oracle`]), then the original and the recompiled shader run
//! in the emulator on the same inputs (random and edge-case constants,
//! mipmapped random textures of the declared types, random interpolants
//! with gradients, both faces) and every written value compared.
//!
//! The recompiled shader is the compiler's own register allocation: inputs
//! are matched by semantic (`TEXCOORD0` is whatever `v#` the compiler
//! chose), samplers and constants by the registers the HLSL binds.

pub mod bound;
pub mod oracle;
pub mod vertex;

pub use oracle::Oracle;

use crate::core::decompile::Decompiled;
use crate::core::emu::{
    self, Address, Constants, CubeMap, Draw, Face, Filter, LinearInput, MipChain, MipFilter,
    SamplerState, TextureLevels, VolumeChain,
};
use crate::core::image::{Texture, VolumeLevel};
use crate::core::ir::Shader;
use crate::core::isa::SamplerType;
use crate::core::load;
use crate::jobs::compare::stats::ulp_distance;
use serde::Serialize;
use std::collections::BTreeMap;

/// The outcome of a verification.
#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    /// Whether the two shaders computed the same pixels (see [`Kind`]).
    pub equivalent: bool,
    /// What was found.
    pub kind: Kind,
    /// The compiler's messages (warnings; the errors when it refused).
    pub compiler_messages: String,
    /// Draws run (each on both shaders).
    pub draws: u32,
    /// Pixels per draw (vertices, for a vertex shader).
    pub pixels: u64,
    /// Which stage ran: `pixel`, or `vertex` (then `pixels` counts vertices
    /// and a divergence's `x` is the vertex).
    pub stage: crate::core::profile::Stage,
    /// Output values compared (pixels × written components, over all draws).
    pub values: u64,
    /// Values whose bits differ (NaN counts as equal to NaN).
    pub differing: u64,
    /// Of those, values within the rounding bound derived from both
    /// shaders' arithmetic ([`bound`]).
    pub within_bound: u64,
    /// Of those, values beyond it (or where no bound was derived): a
    /// failure.
    pub unexplained: u64,
    /// The largest distance in ulp among differing values (0 when none).
    pub max_ulp: u64,
    /// The first value that differs most.
    pub worst: Option<Divergence>,
    /// The first value (in draw, row, column order) that differs beyond its
    /// bound.
    pub first_unexplained: Option<Divergence>,
    /// What the changed instructions are, in words (`mad split or fused:
    /// sums regrouped`, `lrp expanded`): the roundings that explain the
    /// differences within the bound.
    pub explained_by: Vec<String>,
    /// Instruction counts that differ between the original and the
    /// recompiled shader (`mnemonic: original → recompiled`): where a
    /// rounding difference comes from.
    pub changed_instructions: Vec<String>,
}

/// What a verification found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// Every value bit for bit.
    Identical,
    /// Values differ, each within the rounding bound derived from the two
    /// shaders' arithmetic: equivalent.
    WithinBound,
    /// Values differ beyond that bound: a failure.
    Different,
    /// Microsoft's compiler refused the HLSL: a failure.
    Refused,
}

/// One value that differs.
#[derive(Clone, Debug, Serialize)]
pub struct Divergence {
    /// Which draw (0-based).
    pub draw: u32,
    /// Pixel column.
    pub x: u32,
    /// Pixel row.
    pub y: u32,
    /// The output and component (`oC0.y`, `oDepth`, `texkill`).
    pub output: String,
    /// What the original shader wrote.
    pub original: f32,
    /// What the recompiled shader wrote.
    pub recompiled: f32,
    /// Their distance in ulp (`None`: one NaN or infinite, the other not).
    pub ulp: Option<u64>,
    /// The derived bound of their difference (the two shaders' bounds
    /// summed); `None` where none was derived.
    pub bound: Option<f32>,
}

/// Why a verification could not run.
#[derive(Clone, Debug)]
pub struct VerifyError(pub String);

impl std::fmt::Display for VerifyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Compiles `d` with `oracle` and compares the result with `original`
/// over draws of `size × size` pixels.
pub fn verify(
    original: &Shader,
    d: &Decompiled,
    oracle: &Oracle,
    size: u32,
) -> Result<Verdict, VerifyError> {
    let compiled = oracle
        .compile(&d.hlsl, d.target.profile)
        .map_err(VerifyError)?;
    let Some(bytes) = compiled.bytecode.filter(|_| compiled.hresult == 0) else {
        return Ok(refused(compiled.messages));
    };
    let mut v = equivalence_of_bytes(original, &bytes, size)?;
    v.compiler_messages = compiled.messages;
    Ok(v)
}

/// A verdict for HLSL the compiler refused.
fn refused(messages: String) -> Verdict {
    Verdict {
        equivalent: false,
        kind: Kind::Refused,
        compiler_messages: messages,
        draws: 0,
        pixels: 0,
        stage: crate::core::profile::Stage::Pixel,
        values: 0,
        differing: 0,
        within_bound: 0,
        unexplained: 0,
        max_ulp: 0,
        worst: None,
        first_unexplained: None,
        explained_by: Vec::new(),
        changed_instructions: Vec::new(),
    }
}

/// Compares `original` with the shader of `bytecode` (the compiler's
/// answer, from the oracle or from a committed fixture).
pub fn equivalence_of_bytes(
    original: &Shader,
    bytecode: &[u8],
    size: u32,
) -> Result<Verdict, VerifyError> {
    let options = load::Options::default();
    let file = load::source_file("recompiled", bytecode.to_vec(), &options)
        .map_err(|e| VerifyError(format!("the recompiled bytecode: {e}")))?;
    let loaded = load::load(file, &options).map_err(|e| {
        VerifyError(format!(
            "the recompiled bytecode does not load: {}",
            e.diagnostics
                .items
                .first()
                .map(|d| d.message.clone())
                .unwrap_or_default()
        ))
    })?;
    equivalence(original, &loaded.shader, size)
}

/// Runs both shaders on the same draws and compares every written value
/// (vertex shaders: over `size`² vertices, [`vertex::equivalence`]).
pub fn equivalence(
    original: &Shader,
    recompiled: &Shader,
    size: u32,
) -> Result<Verdict, VerifyError> {
    if original.program().profile.stage() == crate::core::profile::Stage::Vertex {
        return vertex::equivalence(original, recompiled, (size * size) as usize);
    }
    let a = emu::compile(original).map_err(|e| VerifyError(format!("the original: {e}")))?;
    let b =
        emu::compile(recompiled).map_err(|e| VerifyError(format!("the recompiled shader: {e}")))?;
    let mut v = refused(String::new());
    v.kind = Kind::Identical;
    v.pixels = size as u64 * size as u64;
    // the bound shaders run only on draws where some value differs
    let mut bounds = None;
    let mut worst_key = (0u64, false);
    for draw in 0..DRAWS {
        let inputs = Inputs::new(original, draw, size);
        let da = inputs.draw(original, draw, size);
        let db = inputs.draw(recompiled, draw, size);
        let oa = emu::run(&a, &da)
            .map_err(|e| VerifyError(format!("the original, draw {draw}: {e}")))?;
        let ob = emu::run(&b, &db)
            .map_err(|e| VerifyError(format!("the recompiled shader, draw {draw}: {e}")))?;
        let differ = oa.killed != ob.killed || !same_bits(&oa, &ob);
        if differ && bounds.is_none() {
            bounds = Some(
                // a ps_1_x shader's arithmetic is its lowering's
                [original, recompiled].map(|s| {
                    bound::bound_shader(s.runnable().unwrap_or(s))
                        .and_then(|b| emu::compile(&b).ok())
                }),
            );
        }
        let outs = [0, 1].map(|k| {
            if !differ {
                return None;
            }
            let c = bounds.as_ref()?[k].as_ref()?;
            emu::run(c, if k == 0 { &da } else { &db }).ok()
        });
        let pair = Pair {
            a: &oa,
            b: &ob,
            bounds: [outs[0].as_ref(), outs[1].as_ref()],
        };
        compare(&pair, draw, &mut v, &mut worst_key);
        v.draws += 1;
    }
    v.changed_instructions = changed(original, recompiled);
    if v.differing > 0 {
        v.explained_by = explanations(&v.changed_instructions);
    }
    if v.unexplained > 0 {
        v.kind = Kind::Different;
    } else if v.differing > 0 {
        v.kind = Kind::WithinBound;
    }
    v.equivalent = matches!(v.kind, Kind::Identical | Kind::WithinBound);
    Ok(v)
}

/// Whether every colour and depth value of two runs has the same bits.
fn same_bits(a: &emu::DrawOutput, b: &emu::DrawOutput) -> bool {
    let bits = |o: &emu::DrawOutput| -> Vec<u32> {
        let colors = o.color.iter().flatten().flatten().flatten();
        colors
            .chain(o.depth.iter().flatten())
            .map(|x| x.to_bits())
            .collect()
    };
    bits(a) == bits(b)
}

/// The roundings that the changed instruction counts stand for.
fn explanations(changed: &[String]) -> Vec<String> {
    let has = |ops: &[&str]| {
        changed
            .iter()
            .any(|c| ops.iter().any(|o| c.starts_with(&format!("{o}:"))))
    };
    let mut out = Vec::new();
    let rows: [(&[&str], &str); 6] = [
        (&["mad", "mul", "add"], "mad split or fused: sums regrouped"),
        (&["dp2add", "dp3", "dp4"], "dot products regrouped"),
        (&["lrp"], "lrp expanded"),
        (&["cmp", "min", "max"], "selections rewritten"),
        (&["frc", "sincos"], "range reduction rewritten"),
        (
            &["rcp", "rsq", "nrm", "exp", "log", "pow"],
            "reciprocals, roots, powers rewritten",
        ),
    ];
    for (ops, words) in rows {
        if has(ops) {
            out.push(words.to_string());
        }
    }
    out
}

/// The two runs of one draw, with the bound shaders' outputs when derived.
struct Pair<'a> {
    a: &'a emu::DrawOutput,
    b: &'a emu::DrawOutput,
    bounds: [Option<&'a emu::DrawOutput>; 2],
}

impl Pair<'_> {
    /// The derived bound of `|a − b|` at pixel `i` of colour `t` (4: depth)
    /// component `c`.
    fn bound(&self, i: usize, t: usize, c: usize) -> Option<f32> {
        let one = |o: Option<&emu::DrawOutput>| -> Option<f32> {
            let o = o?;
            let e = if t == 4 {
                o.depth.as_ref()?.get(i).copied()?
            } else {
                o.color.get(t)?.as_ref()?.get(i)?[c]
            };
            (e.is_finite() && e < bound::UNBOUNDED).then_some(e)
        };
        Some((one(self.bounds[0])? + one(self.bounds[1])?) * bound::SLACK)
    }
}

/// Draws per verification: random constants on the front face, edge-case
/// constants on the back face, and random constants of larger magnitude.
pub const DRAWS: u32 = 3;

fn compare(p: &Pair, draw: u32, v: &mut Verdict, worst_key: &mut (u64, bool)) {
    let (oa, ob) = (p.a, p.b);
    let w = oa.width;
    let mut note =
        |i: usize, output: String, x: f32, y: f32, bound: Option<f32>, v: &mut Verdict| {
            let at = (draw, i as u32 % w, i as u32 / w);
            note_value(v, worst_key, at, output, [x, y], bound);
        };
    for i in 0..oa.killed.len() {
        let (ka, kb) = (oa.killed[i], ob.killed.get(i).copied().unwrap_or(false));
        if ka != kb {
            note(
                i,
                "texkill".into(),
                ka as u8 as f32,
                kb as u8 as f32,
                None,
                v,
            );
            continue;
        }
        if ka {
            continue;
        }
        for (t, (ca, cb)) in oa.color.iter().zip(ob.color.iter()).enumerate() {
            if let (Some(ca), Some(cb)) = (ca, cb) {
                for c in 0..4 {
                    note(
                        i,
                        format!("oC{t}.{}", ['x', 'y', 'z', 'w'][c]),
                        ca[i][c],
                        cb[i][c],
                        p.bound(i, t, c),
                        v,
                    );
                }
            }
        }
        if let (Some(da), Some(db)) = (&oa.depth, &ob.depth) {
            note(i, "oDepth".into(), da[i], db[i], p.bound(i, 4, 0), v);
        }
    }
}

/// One compared value, at `(draw, x, y)`: counted, and when its bits
/// differ, recorded as within its bound or not (NaN equals NaN).
fn note_value(
    v: &mut Verdict,
    worst_key: &mut (u64, bool),
    (draw, px, py): (u32, u32, u32),
    output: String,
    [x, y]: [f32; 2],
    bound: Option<f32>,
) {
    v.values += 1;
    let same = x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
    if same {
        return;
    }
    v.differing += 1;
    let ulp = ulp_distance(x, y);
    let within = x.is_finite() && y.is_finite() && bound.is_some_and(|e| (x - y).abs() <= e);
    let here = Divergence {
        draw,
        x: px,
        y: py,
        output,
        original: x,
        recompiled: y,
        ulp,
        bound,
    };
    if within {
        v.within_bound += 1;
    } else {
        v.unexplained += 1;
        if v.first_unexplained.is_none() {
            v.first_unexplained = Some(here.clone());
        }
    }
    let key = (ulp.unwrap_or(u64::MAX), true);
    v.max_ulp = v.max_ulp.max(ulp.unwrap_or(u64::MAX));
    if key.0 > worst_key.0 || !worst_key.1 {
        *worst_key = key;
        v.worst = Some(here);
    }
}

/// `mnemonic: n → m` for each instruction whose count differs.
fn changed(a: &Shader, b: &Shader) -> Vec<String> {
    let count = |s: &Shader| {
        let mut m: BTreeMap<&'static str, usize> = BTreeMap::new();
        for i in s.instructions() {
            *m.entry(i.op.info().mnemonic).or_default() += 1;
        }
        m
    };
    let (ca, cb) = (count(a), count(b));
    let mut keys: Vec<&&str> = ca.keys().chain(cb.keys()).collect();
    keys.sort_unstable();
    keys.dedup();
    keys.into_iter()
        .filter(|k| ca.get(**k) != cb.get(**k))
        .map(|k| {
            format!(
                "{k}: {} → {}",
                ca.get(*k).copied().unwrap_or(0),
                cb.get(*k).copied().unwrap_or(0)
            )
        })
        .collect()
}

/// A small deterministic generator (SplitMix64): the same draws on every
/// machine and run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * ((self.next() >> 40) as f32 / (1u64 << 24) as f32)
    }
}

/// Values worth meeting at the edges of the arithmetic.
const EDGES: [f32; 10] = [0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-3, -1e-3, 100.0, -100.0];

/// The textures and values of one draw, shared by both shaders.
struct Inputs {
    constants: Constants,
    textures: BTreeMap<u32, Texture3>,
}

/// A texture of any declared type.
enum Texture3 {
    Flat(MipChain),
    Cube(CubeMap),
    Volume(VolumeChain),
}

fn random_texels(rng: &mut Rng, n: usize) -> Vec<[f32; 4]> {
    (0..n)
        .map(|_| std::array::from_fn(|_| rng.range(0.0, 1.0)))
        .collect()
}

fn chain(rng: &mut Rng, side: u32) -> MipChain {
    let texels = random_texels(rng, (side * side) as usize);
    MipChain::build(
        Texture {
            width: side,
            height: side,
            texels: &texels,
        },
        None,
    )
    .expect("a square power-of-two texture has a chain")
}

impl Inputs {
    fn new(original: &Shader, draw: u32, _size: u32) -> Inputs {
        let mut rng = Rng(0x5eed_0000 + draw as u64);
        let p = original.program();
        let float: Vec<[f32; 4]> = (0..224u32)
            .map(|r| {
                p.float_def(r).unwrap_or_else(|| {
                    std::array::from_fn(|_| match draw {
                        1 => EDGES[(rng.next() % EDGES.len() as u64) as usize],
                        2 => rng.range(-100.0, 100.0),
                        _ => rng.range(-2.0, 2.0),
                    })
                })
            })
            .collect();
        let int: Vec<[i32; 4]> = (0..16u32)
            .map(|r| {
                p.int_def(r)
                    .unwrap_or([1 + (rng.next() % 4) as i32, (rng.next() % 3) as i32, 1, 0])
            })
            .collect();
        let bool: Vec<bool> = (0..16u32)
            .map(|r| p.bool_def(r).unwrap_or(rng.next() % 2 == 1))
            .collect();
        let mut textures = BTreeMap::new();
        for s in &p.samplers {
            let t = match s.ty {
                SamplerType::Tex2d => Texture3::Flat(chain(&mut rng, 16)),
                SamplerType::Cube => Texture3::Cube(
                    CubeMap::from_faces((0..6).map(|_| chain(&mut rng, 8)).collect())
                        .expect("six equal faces"),
                ),
                SamplerType::Volume => Texture3::Volume(
                    VolumeChain::from_levels(
                        (0..4u32)
                            .map(|l| {
                                let side = 8 >> l;
                                VolumeLevel {
                                    width: side,
                                    height: side,
                                    depth: side,
                                    texels: random_texels(&mut rng, (side * side * side) as usize),
                                }
                            })
                            .collect(),
                    )
                    .expect("halving levels"),
                ),
            };
            textures.insert(s.index, t);
        }
        Inputs {
            constants: Constants { float, int, bool },
            textures,
        }
    }

    /// The draw for `shader`: its inputs by their semantics.
    fn draw<'a>(&'a self, shader: &Shader, draw: u32, size: u32) -> Draw<'a> {
        let mut d = Draw::new(size, size);
        d.constants = self.constants.clone();
        d.face = if draw == 1 { Face::Back } else { Face::Front };
        let profile = shader.program().profile;
        for dcl in &shader.program().inputs {
            // ps_2_0's t# and v# by the semantics the HLSL gives them
            let Some(slot) = crate::core::pixel_inputs::slot(profile, dcl.reg.file, dcl.reg.index)
            else {
                continue;
            };
            let (usage, index) = crate::core::decompile::input_semantic(dcl);
            d.inputs.push((slot, interpolant(&usage, index, draw)));
        }
        d.samplers = self.samplers(shader);
        d
    }

    /// The textures bound to the samplers `shader` declares, each filtered
    /// linearly (mipmaps too) and wrapped on every axis.
    fn samplers(&self, shader: &Shader) -> Vec<(u32, TextureLevels<'_>, SamplerState)> {
        let state = SamplerState {
            mag_filter: Filter::Linear,
            min_filter: Filter::Linear,
            mip_filter: MipFilter::Linear,
            address_u: Address::Wrap,
            address_v: Address::Wrap,
            address_w: Address::Wrap,
            ..SamplerState::default()
        };
        let mut out = Vec::new();
        for s in &shader.program().samplers {
            let levels = match self.textures.get(&s.index) {
                Some(Texture3::Flat(c)) => TextureLevels::Chain(c),
                Some(Texture3::Cube(c)) => TextureLevels::Cube(c),
                Some(Texture3::Volume(v)) => TextureLevels::Volume(v),
                None => continue,
            };
            out.push((s.index, levels, state));
        }
        out
    }
}

/// The interpolant of one semantic in one draw: a value at the target's
/// corner in [-2, 2) and gradients in [-1/16, 1/16) per pixel.
fn interpolant(usage: &str, index: u32, draw: u32) -> LinearInput {
    let seed = usage.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x100_0000_01b3)
    });
    let mut rng = Rng(seed ^ ((index as u64) << 32) ^ draw as u64);
    LinearInput {
        base: std::array::from_fn(|_| rng.range(-2.0, 2.0)),
        ddx: std::array::from_fn(|_| rng.range(-0.0625, 0.0625)),
        ddy: std::array::from_fn(|_| rng.range(-0.0625, 0.0625)),
    }
}
