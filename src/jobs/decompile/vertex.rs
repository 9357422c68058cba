//! `--verify` for vertex shaders: the original and the recompiled shader
//! run in the vertex stage (`emu::vertex`, as `ps30 run VS --vertices`
//! runs them) over the same vertices and constants, and every component
//! of every output the original has is compared with the recompiled
//! shader's output of the same semantic (the compiler chooses its own
//! `o#` in vs_3_0).
//!
//! Each of the three draws ([`super::DRAWS`]) has `count` vertices: every
//! attribute either shader declares gets random values in [−2, 2) (draw
//! 0), edge values (±0, ±1, 0.5, 2, ±10⁻³, ±100: draw 1) or random values
//! in [−100, 100) (draw 2), except `blendindices`, which are small
//! non-negative values (integers 0–3; quarters 0–3.75; random in [0, 4))
//! so that `c[a0.x + n]` reads inside the arrays they index: past an
//! array's end the original reads whatever its registers held (its own
//! `def`s, other uniforms), the recompiled shader what the compiler put
//! there, which no HLSL can promise to keep. Constants are the pixel
//! verification's (random in [−2, 2), edge values, random in [−100, 100))
//! over all 256 registers, vs_3_0's vertex textures the same mipmapped
//! random textures.
//!
//! Where bits differ, the bound shaders of both (`bound.rs`, the same
//! derivation as for pixel shaders, run in the vertex stage on the same
//! draw) give each output component's rounding bound, and a difference
//! within the sum of the two is explained, as for pixel shaders. A vertex
//! shader the bound does not cover (constants read at a run-time index,
//! outputs written at one) is compared bit for bit.

use super::{bound, note_value, refused, Inputs, Kind, Rng, Verdict, VerifyError, DRAWS, EDGES};
use crate::core::emu::vertex::{self, Attribute, VertexDraw, VertexOutput, Vertices};
use crate::core::ir::Shader;
use crate::core::isa::RegFile;

/// Compares two vertex shaders over three draws of `count` vertices.
pub fn equivalence(
    original: &Shader,
    recompiled: &Shader,
    count: usize,
) -> Result<Verdict, VerifyError> {
    let mut v = refused(String::new());
    v.kind = Kind::Identical;
    v.pixels = count as u64;
    v.stage = crate::core::profile::Stage::Vertex;
    let mut worst_key = (0u64, false);
    // the bound shaders' literals, at registers neither shader reads
    // directly; the draws hold them too (`bound::literals`)
    let k = bound::free_constants(&[original, recompiled]);
    // the bound shaders, made when some value differs
    let mut bounds: Option<[Option<Shader>; 2]> = None;
    for draw in 0..DRAWS {
        let inputs = Inputs::new(original, draw, 0);
        let mut constants = inputs.constants.clone();
        let mut rng = Rng(0x7e57_0000 + draw as u64);
        while constants.float.len() < vertex::VERTEX_CONSTANTS {
            let r = constants.float.len() as u32;
            let value = original
                .program()
                .float_def(r)
                .unwrap_or_else(|| std::array::from_fn(|_| constant(&mut rng, draw)));
            constants.float.push(value);
        }
        for (r, value) in k.map(bound::literals).into_iter().flatten() {
            constants.float[r as usize] = value;
        }
        let d = VertexDraw {
            constants,
            samplers: inputs.samplers(original),
            ..VertexDraw::default()
        };
        let verts = vertices(&[original, recompiled], draw, count);
        let run = |s: &Shader, which: &str| {
            vertex::run(s, &d, &verts)
                .map_err(|e| VerifyError(format!("the {which} shader, draw {draw}: {e}")))
        };
        let oa = run(original, "original")?;
        let ob = run(recompiled, "recompiled")?;
        // (slots in another order count as differing: the bounds are then
        // made and run for nothing)
        let bits = |o: &VertexOutput| -> Vec<u32> {
            o.values
                .iter()
                .flatten()
                .flatten()
                .map(|x| x.to_bits())
                .collect()
        };
        let differ = bits(&oa) != bits(&ob);
        if differ && bounds.is_none() {
            bounds = Some([original, recompiled].map(|s| bound::bound_shader_at(s, k?)));
        }
        let errors = [0, 1].map(|k| {
            if !differ {
                return None;
            }
            let b = bounds.as_ref()?[k].as_ref()?;
            vertex::run(b, &d, &verts).ok()
        });
        let pair = Pair {
            a: &oa,
            b: &ob,
            bounds: [errors[0].as_ref(), errors[1].as_ref()],
        };
        compare(&pair, draw, &mut v, &mut worst_key)?;
        v.draws += 1;
    }
    v.changed_instructions = super::changed(original, recompiled);
    if v.differing > 0 {
        v.explained_by = super::explanations(&v.changed_instructions);
    }
    if v.unexplained > 0 {
        v.kind = Kind::Different;
    } else if v.differing > 0 {
        v.kind = Kind::WithinBound;
    }
    v.equivalent = matches!(v.kind, Kind::Identical | Kind::WithinBound);
    Ok(v)
}

/// The two runs of one draw, with the bound shaders' outputs (slot for
/// slot the same as their shader's) where derived.
struct Pair<'a> {
    a: &'a VertexOutput,
    b: &'a VertexOutput,
    bounds: [Option<&'a VertexOutput>; 2],
}

impl Pair<'_> {
    /// The derived bound of `|a − b|` at vertex `i`, component `c` of the
    /// original's slot `k` and the recompiled shader's slot `j`.
    fn bound(&self, i: usize, [k, j]: [usize; 2], c: usize) -> Option<f32> {
        let one = |o: Option<&VertexOutput>, slot: usize| -> Option<f32> {
            let e = *o?.values.get(i)?.get(slot)?.get(c)?;
            (e.is_finite() && e < bound::UNBOUNDED).then_some(e)
        };
        Some((one(self.bounds[0], k)? + one(self.bounds[1], j)?) * bound::SLACK)
    }
}

/// One constant of draw `draw`, as the pixel verification draws them.
fn constant(rng: &mut Rng, draw: u32) -> f32 {
    match draw {
        1 => EDGES[(rng.next() % EDGES.len() as u64) as usize],
        2 => rng.range(-100.0, 100.0),
        _ => rng.range(-2.0, 2.0),
    }
}

/// The vertices of one draw: every attribute the shaders declare.
fn vertices(shaders: &[&Shader], draw: u32, count: usize) -> Vertices {
    let mut attributes: Vec<Attribute> = Vec::new();
    for s in shaders {
        for d in s
            .program()
            .inputs
            .iter()
            .filter(|d| d.reg.file == RegFile::Input)
        {
            let a = Attribute {
                usage: d.usage.clone(),
                index: d.usage_index,
            };
            if !attributes.contains(&a) {
                attributes.push(a);
            }
        }
    }
    attributes.sort_unstable();
    let columns = attributes
        .into_iter()
        .map(|a| {
            let seed = a.usage.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                (h ^ b as u64).wrapping_mul(0x100_0000_01b3)
            });
            let mut rng = Rng(seed ^ ((a.index as u64) << 32) ^ draw as u64);
            let indices = a.usage.eq_ignore_ascii_case("blendindices");
            let values = (0..count)
                .map(|_| {
                    std::array::from_fn(|_| match (indices, draw) {
                        (true, 0) => (rng.next() % 4) as f32,
                        (true, 1) => (rng.next() % 16) as f32 * 0.25,
                        (true, _) => rng.range(0.0, 4.0),
                        (false, _) => constant(&mut rng, draw),
                    })
                })
                .collect();
            (a, values)
        })
        .collect();
    Vertices {
        count,
        attributes: columns,
    }
}

/// Every component of every output of the original against the
/// recompiled shader's output of the same semantic (fog and point size:
/// their one component).
fn compare(
    p: &Pair,
    draw: u32,
    v: &mut Verdict,
    worst_key: &mut (u64, bool),
) -> Result<(), VerifyError> {
    let (a, b) = (p.a, p.b);
    for (k, slot) in a.slots.iter().enumerate() {
        let theirs = b
            .slots
            .iter()
            .position(|t| match (&slot.semantic, &t.semantic) {
                (Some(x), Some(y)) => x == y,
                (None, None) => t.register == slot.register,
                _ => false,
            });
        let Some(j) = theirs else {
            return Err(VerifyError(format!(
                "the recompiled shader has no output {} ({})",
                slot.register,
                slot.semantic
                    .as_ref()
                    .map_or("no semantic".into(), |s| s.to_string())
            )));
        };
        let scalar = slot
            .semantic
            .as_ref()
            .is_some_and(|s| s.usage == "fog" || s.usage == "psize");
        let comps = if scalar { 1 } else { 4 };
        for (i, (va, vb)) in a.values.iter().zip(&b.values).enumerate() {
            for c in 0..comps {
                let output = format!("{}.{}", slot.register, ['x', 'y', 'z', 'w'][c]);
                note_value(
                    v,
                    worst_key,
                    (draw, i as u32, 0),
                    output,
                    [va[k][c], vb[j][c]],
                    p.bound(i, [k, j], c),
                );
            }
        }
    }
    Ok(())
}
