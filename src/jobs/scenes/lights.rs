//! The article's multiple light models on a synthetic G-buffer: the scene
//! `asm/lights/` runs on, and a CPU computation of what it should output.
//!
//! The G-buffer is what a deferred renderer's geometry pass would leave in
//! a `D3DFMT_A16B16G16R16F` target: xyz = a unit normal, w = the light-model
//! ID (0, 1 or 2 — exact in a half float, as the article notes). Every
//! channel goes through the format's rounding ([`TargetFormat::round`]).
//! The ID map has three regions whose borders run across quads at every
//! angle, so many 2×2 quads straddle two or three models — the divergence
//! the light shader pays for:
//!
//! * ID 2 inside a disc (centre (0.58, 0.45), radius 0.26 of the width and
//!   height), with the normals of a sphere;
//! * ID 1 where s + 0.6·t < 0.6 (the disc overlaps it, so some quads hold
//!   all three models);
//! * ID 0 elsewhere;
//!
//! where (s, t) is the pixel centre in [0, 1]². Outside the disc the normal
//! is normalize(s − ½, t − ½, 1). Only +, ×, ÷ and √ are used, so the scene
//! is the same bit for bit on every platform.
//!
//! The three material textures (one per model, 32×32, WRAP addressing,
//! point sampling) are deterministic patterns; pixel (x, y) reads texel
//! (x mod 32, y mod 32) of each, one texel per pixel (LOD 0).

use crate::core::emu::{
    Address, Compiled, Constants, Draw, DrawOutput, Filter, LinearInput, SamplerState, Texture,
};
use crate::core::image::TargetFormat;

/// Side of the material textures.
pub const MATERIAL_SIZE: u32 = 32;
/// Number of light models.
pub const MODELS: usize = 3;

/// The shader's constants (its `def`s), repeated here for the CPU
/// computation; [`Scene::check_constants`] verifies they match the shader.
const EPS_1: f32 = 0.99999;
const EPS_2: f32 = 1.99999;
const LIGHT: [f32; 3] = [0.48, 0.6, 0.64];
const HALF: [f32; 3] = [0.26504, 0.3313, 0.90554];
const WRAP: [f32; 2] = [0.6666667, 0.3333333];

/// A G-buffer and the material textures of the three light models.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The G-buffer's width in pixels.
    pub width: u32,
    /// Its height in pixels.
    pub height: u32,
    /// The G-buffer texels as stored (f16-rounded): xyz = N, w = ID.
    pub gbuffer: Vec<[f32; 4]>,
    /// Model 0, 1, 2 material textures, `MATERIAL_SIZE`² each.
    pub materials: [Vec<[f32; 4]>; MODELS],
}

/// Why a scene cannot be built.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError(pub String);

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SceneError {}

/// Largest side of a synthetic scene (4096² pixels is also the emulator's
/// default target limit).
pub const MAX_SIDE: u32 = 4096;

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / n, v[1] / n, v[2] / n]
}

fn materials() -> [Vec<[f32; 4]>; MODELS] {
    let n = MATERIAL_SIZE;
    let texel = |m: usize, x: u32, y: u32| -> [f32; 4] {
        // Small integers over powers of two: exact in f32.
        let a = ((x * 7 + y * 3 + m as u32 * 5) % 16) as f32 / 32.0;
        let b = ((x * 3 + y * 5) % 8) as f32 / 16.0;
        match m {
            0 => [0.5 + a, 0.25 + b, 0.125, 1.0],
            1 => [0.125, 0.5 + a, 0.25 + b, 1.0],
            _ => [0.25 + b, 0.125, 0.5 + a, 0.25 + a],
        }
    };
    std::array::from_fn(|m| {
        (0..n)
            .flat_map(|y| (0..n).map(move |x| (x, y)))
            .map(|(x, y)| texel(m, x, y))
            .collect()
    })
}

impl Scene {
    /// The synthetic scene of the module docs, `width × height` pixels.
    pub fn synthetic(width: u32, height: u32) -> Result<Scene, SceneError> {
        check_size(width, height)?;
        let mut ids = Vec::with_capacity(width as usize * height as usize);
        let mut normals = Vec::with_capacity(ids.capacity());
        for y in 0..height {
            for x in 0..width {
                let s = (x as f64 + 0.5) / width as f64;
                let t = (y as f64 + 0.5) / height as f64;
                let (dx, dy) = ((s - 0.58) / 0.26, (t - 0.45) / 0.26);
                let r2 = dx * dx + dy * dy;
                if r2 < 1.0 {
                    ids.push(2u8);
                    normals.push([dx, dy, (1.0 - r2).sqrt()]);
                } else {
                    ids.push(if s + 0.6 * t < 0.6 { 1 } else { 0 });
                    normals.push(normalize([s - 0.5, t - 0.5, 1.0]));
                }
            }
        }
        Ok(Scene::build(width, height, &ids, &normals))
    }

    /// A scene with the given IDs (row-major) and the normal (0, 0, 1)
    /// everywhere: for tests and hand-computed cases.
    pub fn from_ids(width: u32, height: u32, ids: &[u8]) -> Result<Scene, SceneError> {
        check_size(width, height)?;
        if ids.len() != width as usize * height as usize {
            return Err(SceneError(format!(
                "{width}x{height} needs {} IDs, got {}",
                width as usize * height as usize,
                ids.len()
            )));
        }
        if let Some(bad) = ids.iter().find(|&&i| i as usize >= MODELS) {
            return Err(SceneError(format!(
                "light-model ID {bad} does not exist (0, 1, 2)"
            )));
        }
        let normals = vec![[0.0, 0.0, 1.0]; ids.len()];
        Ok(Scene::build(width, height, ids, &normals))
    }

    fn build(width: u32, height: u32, ids: &[u8], normals: &[[f64; 3]]) -> Scene {
        let gbuffer = ids
            .iter()
            .zip(normals)
            .map(|(&id, n)| {
                TargetFormat::Rgba16F.round([n[0] as f32, n[1] as f32, n[2] as f32, id as f32])
            })
            .collect();
        Scene {
            width,
            height,
            gbuffer,
            materials: materials(),
        }
    }

    /// The light-model ID of pixel (x, y), as stored.
    pub fn id(&self, x: u32, y: u32) -> f32 {
        self.gbuffer[(y * self.width + x) as usize][3]
    }

    /// Pixels per light model (by the ID the shader's comparisons see).
    pub fn pixels_per_model(&self) -> [u64; MODELS] {
        let mut n = [0u64; MODELS];
        for t in &self.gbuffer {
            n[model_of(t[3])] += 1;
        }
        n
    }

    /// The G-buffer texel coordinate of each pixel: v0 = ((x + ½)/W, (y + ½)/H).
    pub fn texcoord(&self) -> LinearInput {
        let (w, h) = (self.width as f32, self.height as f32);
        LinearInput {
            base: [0.5 / w, 0.5 / h, 0.0, 0.0],
            ddx: [1.0 / w, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / h, 0.0, 0.0],
        }
    }

    /// c4: material uv per G-buffer uv, so one pixel steps one material texel.
    pub fn material_scale(&self) -> [f32; 4] {
        let m = MATERIAL_SIZE as f32;
        [self.width as f32 / m, self.height as f32 / m, 0.0, 0.0]
    }

    /// The draw the light shaders expect: v0, s0 = G-buffer (point, CLAMP),
    /// s1..s3 = materials ([`material_state`], no mips), c4 =
    /// [`Scene::material_scale`].
    pub fn draw(&self) -> Draw<'_> {
        let mut d = Draw::new(self.width, self.height);
        d.inputs.push((0, self.texcoord()));
        d.constants = Constants {
            float: vec![
                [0.0; 4],
                [0.0; 4],
                [0.0; 4],
                [0.0; 4],
                self.material_scale(),
            ],
            ..Constants::default()
        };
        d.samplers.push((
            0,
            Texture {
                width: self.width,
                height: self.height,
                texels: &self.gbuffer,
            }
            .into(),
            SamplerState {
                address_u: Address::Clamp,
                address_v: Address::Clamp,
                address_w: Address::Clamp,
                ..SamplerState::filtered(Filter::Point)
            },
        ));
        for (m, texels) in self.materials.iter().enumerate() {
            d.samplers.push((
                m as u32 + 1,
                Texture {
                    width: MATERIAL_SIZE,
                    height: MATERIAL_SIZE,
                    texels,
                }
                .into(),
                material_state(),
            ));
        }
        d
    }

    /// What the light shaders compute at pixel (x, y), in f32 with the
    /// shader's operation order (dp3 summed left to right, mad and mad_sat
    /// unfused, the specular power by four squarings).
    pub fn expected(&self, x: u32, y: u32) -> [f32; 4] {
        self.shade(x, y, LIGHT, HALF)
    }

    /// What `asm/lights/directional.psh` computes at pixel (x, y) for
    /// `light`: [`Scene::expected`]'s models with the light's L and H, times
    /// its colour, in the same f32 operation order.
    pub fn expected_light(&self, x: u32, y: u32, light: &Light) -> [f32; 4] {
        let v = self.shade(x, y, light.direction, light.half);
        let c = light.color;
        [v[0] * c[0], v[1] * c[1], v[2] * c[2], 1.0]
    }

    fn shade(&self, x: u32, y: u32, l: [f32; 3], h: [f32; 3]) -> [f32; 4] {
        let g = self.gbuffer[(y * self.width + x) as usize];
        let v0 = self.texcoord().at(x as f32, y as f32);
        let c4 = self.material_scale();
        let (u, v) = (v0[0] * c4[0], v0[1] * c4[1]);
        let model = model_of(g[3]);
        let m = self.material(model, u, v);
        let dot = |a: [f32; 4], b: [f32; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let ndl = dot(g, l);
        match model {
            0 => {
                let k = ndl.max(0.0);
                [m[0] * k, m[1] * k, m[2] * k, 1.0]
            }
            1 => {
                // mad_sat: unfused, then clamped as the emulator's _sat
                // (which maps NaN to 0, unlike f32::clamp).
                #[allow(clippy::manual_clamp)]
                let k = (ndl * WRAP[0] + WRAP[1]).max(0.0).min(1.0);
                [m[0] * k, m[1] * k, m[2] * k, 1.0]
            }
            _ => {
                let k = ndl.max(0.0);
                let mut s = dot(g, h).max(0.0);
                for _ in 0..4 {
                    s *= s;
                }
                let spec = s * m[3];
                [m[0] * k + spec, m[1] * k + spec, m[2] * k + spec, 1.0]
            }
        }
    }

    /// Point sample of material `model` at (u, v) with WRAP (texel
    /// ⌊u·32⌋ mod 32).
    fn material(&self, model: usize, u: f32, v: f32) -> [f32; 4] {
        let n = MATERIAL_SIZE as f32;
        let x = ((u * n).floor() as i64).rem_euclid(MATERIAL_SIZE as i64);
        let y = ((v * n).floor() as i64).rem_euclid(MATERIAL_SIZE as i64);
        self.materials[model][(y * MATERIAL_SIZE as i64 + x) as usize]
    }

    /// Checks that a light shader defines the constants [`Scene::expected`]
    /// assumes (c0..c3), so the CPU computation and the shader cannot drift
    /// apart silently.
    pub fn check_constants(program: &crate::core::ir::Program) -> Result<(), SceneError> {
        let want: [(u32, [f32; 4]); 4] = [
            (0, [EPS_1, EPS_2, 0.0, 1.0]),
            (1, [LIGHT[0], LIGHT[1], LIGHT[2], 0.0]),
            (2, [HALF[0], HALF[1], HALF[2], 0.0]),
            (3, [WRAP[0], WRAP[1], 0.0, 0.0]),
        ];
        let list = |v: [f32; 4]| format!("{}, {}, {}, {}", v[0], v[1], v[2], v[3]);
        for (c, v) in want {
            match program.float_def(c) {
                Some(d) if d == v => {}
                Some(d) => {
                    return Err(SceneError(format!(
                        "the shader defines c{c} = ({}), but the scene's CPU computation assumes ({})",
                        list(d),
                        list(v)
                    )))
                }
                None => {
                    return Err(SceneError(format!(
                        "the shader does not define c{c} with `def`; the scene's CPU computation assumes c{c} = ({})",
                        list(v)
                    )))
                }
            }
        }
        Ok(())
    }
}

/// One light of `asm/lights/directional.psh`: the constants c5 (L), c6 (H)
/// and c7 (colour) of its draw.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Light {
    /// L: unit vector towards the light.
    pub direction: [f32; 3],
    /// H = normalize(L + (0, 0, 1)), for a viewer on +z.
    pub half: [f32; 3],
    /// Colour and intensity (HDR: any value ≥ 0).
    pub color: [f32; 3],
}

impl Light {
    /// A light towards `towards` (normalised here, in f64) with `color`.
    pub fn new(towards: [f64; 3], color: [f32; 3]) -> Light {
        let l = normalize(towards);
        let h = normalize([l[0], l[1], l[2] + 1.0]);
        Light {
            direction: l.map(|c| c as f32),
            half: h.map(|c| c as f32),
            color,
        }
    }

    /// c5, c6, c7 of the light's draw (w = 0).
    pub fn constants(&self) -> [[f32; 4]; 3] {
        let four = |v: [f32; 3]| [v[0], v[1], v[2], 0.0];
        [four(self.direction), four(self.half), four(self.color)]
    }
}

/// The model the shader's epsilon comparisons choose for an ID.
pub fn model_of(id: f32) -> usize {
    if id < EPS_1 {
        0
    } else if id < EPS_2 {
        1
    } else {
        2
    }
}

/// Sampler state of the material textures: point, WRAP.
pub fn material_state() -> SamplerState {
    SamplerState {
        address_u: Address::Wrap,
        address_v: Address::Wrap,
        address_w: Address::Wrap,
        ..SamplerState::filtered(Filter::Point)
    }
}

fn check_size(width: u32, height: u32) -> Result<(), SceneError> {
    if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
        return Err(SceneError(format!(
            "G-buffer size {width}x{height}: each side must be 1 to {MAX_SIDE}"
        )));
    }
    Ok(())
}

/// A run of a light shader on a scene, checked pixel by pixel against
/// [`Scene::expected`].
#[derive(Clone, Debug)]
pub struct LightsRun {
    /// What the draw wrote.
    pub output: DrawOutput,
    /// Pixels per model, and how many of them match the CPU bit for bit.
    pub per_model: [(u64, u64); MODELS],
}

impl LightsRun {
    /// Whether every pixel of every model matches the CPU bit for bit.
    pub fn all_match(&self) -> bool {
        self.per_model.iter().all(|&(n, ok)| n == ok)
    }
}

/// Pixels per model of `scene` and how many of them `out` (a draw of
/// [`Scene::draw`]) gets bit for bit as [`Scene::expected`].
pub fn compare(scene: &Scene, out: &DrawOutput) -> [(u64, u64); MODELS] {
    let mut per_model = [(0u64, 0u64); MODELS];
    let color = out.color.first().and_then(|c| c.as_ref());
    for y in 0..scene.height {
        for x in 0..scene.width {
            let i = (y * scene.width + x) as usize;
            let m = model_of(scene.id(x, y));
            per_model[m].0 += 1;
            let want = scene.expected(x, y).map(f32::to_bits);
            if color.and_then(|c| c.get(i)).map(|p| p.map(f32::to_bits)) == Some(want) {
                per_model[m].1 += 1;
            }
        }
    }
    per_model
}

/// Runs a compiled light shader over `scene` and compares every pixel.
pub fn run(
    compiled: &Compiled,
    scene: &Scene,
    threads: Option<usize>,
) -> Result<LightsRun, crate::core::emu::EmuError> {
    let draw = scene.draw();
    let output = match threads {
        Some(t) => crate::core::emu::run_with_threads(compiled, &draw, t)?,
        None => crate::core::emu::run(compiled, &draw)?,
    };
    let per_model = compare(scene, &output);
    Ok(LightsRun { output, per_model })
}
