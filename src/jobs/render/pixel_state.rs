//! The per-draw state of a draw list that acts on pixels besides the
//! shader and the blend: the float rules the draw computes by, Direct3D 9's
//! alpha test (D3DRS_ALPHATESTENABLE, D3DRS_ALPHAFUNC, D3DRS_ALPHAREF) and
//! multiple render targets (oC1–oC3 bound to further targets, each with its
//! own D3DRS_COLORWRITEENABLE1–3 mask; one blend state for all, as
//! Direct3D 9 has it), user clip planes and flat shading.
//!
//! **Clip planes.** Direct3D 9 clips a triangle against each enabled plane
//! (D3DRS_CLIPPLANEENABLE): the plane's distance is computed per vertex and
//! interpolated linearly, and what lies where it is negative is not drawn.
//! A draw list's draw is a full-screen quad whose inputs are linear
//! functions of the pixel, so a clip plane is given the same way as an
//! input: the distance at pixel (x, y) is `base + x·ddx + y·ddy` (x, y the
//! pixel's column and row, as for `inputs`), and a pixel whose distance at
//! its centre is below 0 is discarded before blending, in every target. At
//! most 6 planes (the MaxUserClipPlanes of Direct3D 9 hardware).
//!
//! **Flat shading** (`"shade": "flat"`, D3DSHADE_FLAT): inputs declared
//! `dcl_color` take the first vertex's value instead of being interpolated
//! — all of color0, the rgb of color1 (specular alpha stays interpolated),
//! as Direct3D 9's fixed-function pipe and Wine's tests have it. The first
//! vertex of a draw list's quad is the target's top-left corner, half a
//! pixel up and left of pixel (0, 0)'s centre, so such a component holds
//! `base − ½·ddx − ½·ddy` over the whole target. Kept apart from `file.rs` so the fields' parsing and
//! their meaning sit in one place; `docs/pixel-rules.md` describes them
//! for users.
//!
//! ```json
//! { "draw": "t", "shader": "a.psh",
//!   "float_rules": "hardware",
//!   "alpha_test": { "func": "GREATEREQUAL", "ref": 128 },
//!   "outputs": { "oC1": "normals", "oC2": { "target": "depth", "write": "r" } } }
//! ```
//!
//! Every target of a draw has the draw target's size (Direct3D 9 requires
//! it of simultaneous render targets); each may have its own format
//! (D3DPMISCCAPS_MRTINDEPENDENTBITDEPTHS). The alpha test reads oC0's
//! alpha and discards the pixel in every target. An output the shader does
//! not write leaves its target unchanged.
//!
//! The alpha test compares oC0's alpha, unclamped, with ALPHAREF at the
//! precision of the draw target's format ([`AlphaPrecision`]), and discards
//! the pixel when the comparison fails, before blending. On a target of 8
//! bits per channel the alpha is scaled by 255 and rounded to the nearest
//! integer, halves to even, and compared with ALPHAREF (0–255); on a
//! half-float target at 15 bits (alpha × 32767 against ALPHAREF widened by
//! repeating its bits, `ref << 7 | ref >> 1`); on a 32-bit float target
//! the float alpha itself is compared with ALPHAREF/255. Nothing clamps the
//! alpha first: 1.5 passes GREATER 255 and fails EQUAL 255, and −0.5 passes
//! LESS 0 (vkd3d's `alpha-test.shader_test`, recorded on Windows with a
//! 32-bit float target; DXVK's alpha test, which widens the comparison by
//! the same table of formats to match NVIDIA's Direct3D 9 driver; Wine's
//! wined3d compares the unclamped float with (ALPHAREF & 0xff)/255). A
//! NaN alpha fails every comparison but NOTEQUAL (and ALWAYS).

use crate::core::emu::LinearInput;
use crate::core::float_rules::FloatRules;
use crate::core::image::{Encoding, TargetFormat};
use crate::core::ir::Program;
use crate::core::isa::RegFile;
use crate::core::merge::ColorWrite;
use serde::Deserialize;
use std::collections::BTreeMap;

/// Per-draw pixel state; the default is the command's float rules and no
/// alpha test.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PixelState {
    /// The draw's float rules (`None`: the list's, `ps30 render --float-rules`).
    pub float_rules: Option<FloatRules>,
    /// D3DRS_ALPHATESTENABLE with its function and reference (`None`: off).
    pub alpha_test: Option<AlphaTest>,
    /// Targets of oC1, oC2, oC3 (index into the list's targets) with their
    /// write masks; `None` where nothing is bound.
    pub outputs: Outputs,
    /// User clip planes as (base, ddx, ddy) of the distance per pixel.
    pub clip_planes: Vec<[f32; 3]>,
    /// D3DSHADE_FLAT: colour inputs hold the first vertex's value.
    pub flat: bool,
}

/// Targets of oC1, oC2, oC3 with their write masks (`None`: unbound).
pub type Outputs = [Option<(usize, ColorWrite)>; 3];

/// Finds a target by name as (index, width, height).
pub(crate) type TargetOf<'a> = &'a dyn Fn(&str) -> Option<(usize, u32, u32)>;

/// The components of input `v<reg>` that flat shading holds constant:
/// colour semantics — all of color0, the rgb of color1 (its alpha, the
/// specular alpha, stays interpolated).
pub fn flat_components(program: &Program, reg: u32) -> [bool; 4] {
    let mut flat = [false; 4];
    // ps_2_x's v0 and v1 are the colours, declared without a usage.
    let legacy = crate::core::pixel_inputs::clamped(program.profile) & (1 << reg) != 0;
    if legacy {
        for (c, f) in flat.iter_mut().enumerate() {
            *f = !(reg == 1 && c == 3);
        }
        return flat;
    }
    for d in program
        .inputs
        .iter()
        .filter(|d| d.reg.file == RegFile::Input && d.reg.index == reg && d.usage == "color")
    {
        for (c, f) in flat.iter_mut().enumerate() {
            *f |= d.mask.has(c) && !(d.usage_index == 1 && c == 3);
        }
    }
    flat
}

/// `inputs` as flat shading hands them to the shader: each flat component
/// holds its value at the quad's first vertex (the top-left corner).
pub fn flatten_inputs(program: &Program, inputs: &mut [(u32, LinearInput)]) {
    for (reg, input) in inputs.iter_mut() {
        let flat = flat_components(program, *reg);
        for c in (0..4).filter(|&c| flat[c]) {
            input.base[c] -= 0.5 * (input.ddx[c] + input.ddy[c]);
            input.ddx[c] = 0.0;
            input.ddy[c] = 0.0;
        }
    }
}

/// D3DCMPFUNC, the alpha test's comparison of the pixel's alpha code with
/// the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CmpFunc {
    /// D3DCMP_NEVER: every pixel fails.
    Never,
    /// D3DCMP_LESS.
    Less,
    /// D3DCMP_EQUAL.
    Equal,
    /// D3DCMP_LESSEQUAL.
    LessEqual,
    /// D3DCMP_GREATER.
    Greater,
    /// D3DCMP_NOTEQUAL.
    NotEqual,
    /// D3DCMP_GREATEREQUAL.
    GreaterEqual,
    /// D3DCMP_ALWAYS: every pixel passes (the default function).
    Always,
}

impl CmpFunc {
    const NAMES: [(&'static str, CmpFunc); 8] = [
        ("NEVER", CmpFunc::Never),
        ("LESS", CmpFunc::Less),
        ("EQUAL", CmpFunc::Equal),
        ("LESSEQUAL", CmpFunc::LessEqual),
        ("GREATER", CmpFunc::Greater),
        ("NOTEQUAL", CmpFunc::NotEqual),
        ("GREATEREQUAL", CmpFunc::GreaterEqual),
        ("ALWAYS", CmpFunc::Always),
    ];

    /// The function a D3DCMPFUNC name stands for, with or without `D3DCMP_`.
    pub fn from_name(name: &str) -> Option<CmpFunc> {
        let n = name.strip_prefix("D3DCMP_").unwrap_or(name);
        Self::NAMES.iter().find(|(k, _)| *k == n).map(|&(_, f)| f)
    }

    /// Whether `a FUNC b` holds.
    pub fn passes<T: PartialOrd>(self, a: T, b: T) -> bool {
        match self {
            CmpFunc::Never => false,
            CmpFunc::Less => a < b,
            CmpFunc::Equal => a == b,
            CmpFunc::LessEqual => a <= b,
            CmpFunc::Greater => a > b,
            CmpFunc::NotEqual => a != b,
            CmpFunc::GreaterEqual => a >= b,
            CmpFunc::Always => true,
        }
    }
}

/// The alpha test of a draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlphaTest {
    /// D3DRS_ALPHAFUNC.
    pub func: CmpFunc,
    /// D3DRS_ALPHAREF, 0–255.
    pub reference: u8,
    /// The precision of the comparison (the draw target's format's).
    pub precision: AlphaPrecision,
}

/// The precision the alpha test compares at, which the draw target's
/// format sets (the module docs give the rule and its sources).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlphaPrecision {
    /// An integer of this many bits: alpha × (2^bits − 1), rounded halves
    /// to even, against ALPHAREF widened to as many bits.
    Fixed(u32),
    /// The float alpha against ALPHAREF/255.
    Float,
}

impl AlphaPrecision {
    /// The precision of the alpha test on a target of `format`: 8 bits for
    /// 8-bit UNORM, 15 for half floats, the float itself for 32-bit floats.
    pub fn of(format: TargetFormat) -> AlphaPrecision {
        match format.encoding() {
            Encoding::Unorm8 => AlphaPrecision::Fixed(8),
            Encoding::Half => AlphaPrecision::Fixed(15),
            Encoding::Float => AlphaPrecision::Float,
        }
    }
}

impl AlphaTest {
    /// The test of `func` against `reference` on a target of `format`.
    pub fn new(func: CmpFunc, reference: u8, format: TargetFormat) -> AlphaTest {
        AlphaTest {
            func,
            reference,
            precision: AlphaPrecision::of(format),
        }
    }

    /// The two numbers the test compares for an oC0 alpha of `alpha`: the
    /// alpha and ALPHAREF, both at the test's precision (computed in f32,
    /// as the shader a driver appends computes them).
    pub fn compared(self, alpha: f32) -> (f32, f32) {
        match self.precision {
            AlphaPrecision::Float => (alpha, f32::from(self.reference) / 255.0),
            AlphaPrecision::Fixed(bits) => {
                let extra = bits.clamp(8, 16) - 8;
                let r = u32::from(self.reference);
                let reference = (r << extra) | (r >> (8 - extra));
                let scale = self.scale().unwrap_or(255) as f32;
                ((alpha * scale).round_ties_even(), reference as f32)
            }
        }
    }

    /// The integer scale of a fixed-point comparison (2^bits − 1 for
    /// 8 to 16 bits), `None` where the float alpha is compared.
    pub fn scale(self) -> Option<u32> {
        match self.precision {
            AlphaPrecision::Float => None,
            AlphaPrecision::Fixed(bits) => Some((256u32 << (bits.clamp(8, 16) - 8)) - 1),
        }
    }

    /// Whether a pixel whose oC0 alpha is `alpha` survives the test.
    pub fn passes(self, alpha: f32) -> bool {
        let (a, r) = self.compared(alpha);
        self.func.passes(a, r)
    }
}

impl PixelState {
    /// Marks in `killed` (row-major over a target `width` wide) the pixels
    /// that a clip plane removes or whose oC0 fails the alpha test (the
    /// alpha test leaves pixels without an oC0 alone: nothing of theirs is
    /// written).
    pub fn apply(&self, oc0: Option<&[[f32; 4]]>, killed: &mut [bool], width: u32) {
        for (i, k) in killed.iter_mut().enumerate() {
            let (x, y) = (
                (i as u32 % width.max(1)) as f32,
                (i as u32 / width.max(1)) as f32,
            );
            // The distance as the emulator evaluates inputs: base + x·ddx + y·ddy.
            *k |= self
                .clip_planes
                .iter()
                .any(|p| p[0] + x * p[1] + y * p[2] < 0.0);
        }
        let (Some(test), Some(colors)) = (self.alpha_test, oc0) else {
            return;
        };
        for (k, c) in killed.iter_mut().zip(colors) {
            *k |= !test.passes(c[3]);
        }
    }
}

/// `alpha_test` as the file gives it.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileAlphaTest {
    func: String,
    #[serde(rename = "ref")]
    reference: u8,
}

/// One entry of `outputs`: a target's name, or the name with a write mask.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub(crate) enum FileOutput {
    /// The target, written in full.
    Name(String),
    /// The target and its COLORWRITEENABLE letters.
    Masked {
        /// The target's name.
        target: String,
        /// Letters of r, g, b, a (default all).
        write: Option<String>,
    },
}

/// One clip plane as the file gives it: its distance's value at pixel
/// (0, 0) and its steps per pixel to the right and down.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileClipPlane {
    base: f64,
    #[serde(default)]
    ddx: f64,
    #[serde(default)]
    ddy: f64,
}

/// The fields of a draw step this module reads.
pub(crate) struct FileFields<'a> {
    /// `clip_planes`.
    pub clip_planes: Option<&'a [FileClipPlane]>,
    /// `shade`: `"flat"` or `"gouraud"`.
    pub shade: Option<&'a str>,
    /// `float_rules`.
    pub float_rules: Option<&'a str>,
    /// `alpha_test`.
    pub alpha_test: Option<&'a FileAlphaTest>,
    /// `outputs`: `oC1`–`oC3` to targets.
    pub outputs: Option<&'a BTreeMap<String, FileOutput>>,
}

/// The targets of `outputs` checked against the list: `target_of` finds a
/// target by name as (index, width, height); `draw` is the draw's own
/// target (index, width, height) and `sampled` the targets its samplers
/// read.
fn outputs(
    given: &BTreeMap<String, FileOutput>,
    target_of: TargetOf<'_>,
    draw: (usize, u32, u32),
    sampled: &[usize],
) -> Result<Outputs, (String, String)> {
    let (main, w, h) = draw;
    let mut out = [None; 3];
    for (name, o) in given {
        let field = format!("outputs.{name}");
        let k = match name.as_str() {
            "oC1" => 0,
            "oC2" => 1,
            "oC3" => 2,
            _ => {
                return Err((
                    field,
                    "the outputs are oC1, oC2 and oC3 (oC0 goes to the draw's own target)".into(),
                ))
            }
        };
        let (target, write) = match o {
            FileOutput::Name(t) => (t.as_str(), None),
            FileOutput::Masked { target, write } => (target.as_str(), write.as_deref()),
        };
        let (t, tw, th) = target_of(target)
            .ok_or_else(|| (field.clone(), format!("no target named `{target}`")))?;
        if (tw, th) != (w, h) {
            return Err((field, format!("`{target}` is {tw}×{th} and the draw's target {w}×{h}: Direct3D 9's simultaneous render targets share one size")));
        }
        if t == main || out.iter().flatten().any(|&(u, _)| u == t) {
            return Err((
                field,
                format!("`{target}` is already a target of this draw"),
            ));
        }
        if sampled.contains(&t) {
            return Err((
                field,
                format!("`{target}` is sampled by this draw (Direct3D 9 does not allow it)"),
            ));
        }
        let write = match write {
            None => ColorWrite::ALL,
            Some(l) => ColorWrite::from_letters(l).ok_or_else(|| {
                (
                    format!("{field}.write"),
                    format!("`{l}` is not a set of the letters r, g, b, a"),
                )
            })?,
        };
        out[k] = Some((t, write));
    }
    Ok(out)
}

/// The step's pixel state from its `float_rules`, `alpha_test` and
/// `outputs` fields; an error names the field (relative to the step) and
/// the problem. `target_of` finds a target by name as (index, width,
/// height); `draw` is the draw's own target as the same triple and
/// `format` its format (the alpha test's precision).
pub(crate) fn read(
    f: &FileFields<'_>,
    target_of: TargetOf<'_>,
    draw: (usize, u32, u32),
    format: TargetFormat,
    sampled: &[usize],
) -> Result<PixelState, (String, String)> {
    let (float_rules, alpha_test) = (f.float_rules, f.alpha_test);
    let outputs = match f.outputs {
        None => [None; 3],
        Some(o) => outputs(o, target_of, draw, sampled)?,
    };
    let float_rules = match float_rules {
        None => None,
        Some(n) => Some(FloatRules::from_name(n).ok_or_else(|| {
            let names: Vec<&str> = FloatRules::ALL.iter().map(|r| r.name()).collect();
            (
                "float_rules".to_string(),
                format!("`{n}` is not one of {}", names.join(", ")),
            )
        })?),
    };
    let alpha_test = match alpha_test {
        None => None,
        Some(a) => Some(AlphaTest::new(
            CmpFunc::from_name(&a.func).ok_or_else(|| {
                (
                    "alpha_test.func".to_string(),
                    format!("`{}` is not a D3DCMPFUNC (NEVER, LESS, EQUAL, LESSEQUAL, GREATER, NOTEQUAL, GREATEREQUAL, ALWAYS)", a.func),
                )
            })?,
            a.reference,
            format,
        )),
    };
    let flat = match f.shade {
        None | Some("gouraud") => false,
        Some("flat") => true,
        Some(other) => {
            return Err((
                "shade".into(),
                format!("`{other}` is not \"flat\" or \"gouraud\""),
            ))
        }
    };
    let planes = f.clip_planes.unwrap_or_default();
    if planes.len() > 6 {
        return Err((
            "clip_planes".into(),
            format!("{} planes; Direct3D 9 hardware has at most 6", planes.len()),
        ));
    }
    let mut clip_planes = Vec::with_capacity(planes.len());
    for (i, p) in planes.iter().enumerate() {
        let v = [p.base, p.ddx, p.ddy].map(|x| x as f32);
        if v.iter().any(|x| !x.is_finite()) {
            return Err((
                format!("clip_planes[{i}]"),
                "base, ddx and ddy must be finite f32s".into(),
            ));
        }
        clip_planes.push(v);
    }
    Ok(PixelState {
        float_rules,
        alpha_test,
        outputs,
        clip_planes,
        flat,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_test_at_the_reference_boundary() {
        // 8-bit target: 0.5 × 255 = 127.5, halves to even: 128.
        let t = AlphaTest::new(CmpFunc::GreaterEqual, 128, TargetFormat::A8R8G8B8);
        assert!(t.passes(0.5));
        assert!(t.passes(128.0 / 255.0));
        // 127.49/255 × 255 rounds to 127: fails.
        assert!(!t.passes(127.49 / 255.0));
        // 1.5/255 × 255 = 1.5 (to within an ulp of 1.5: 1.5/255 rounds to
        // f32 and back, 1.5 exactly here) → 2; 2.5 → 2, not 3.
        let eq2 = AlphaTest::new(CmpFunc::Equal, 2, TargetFormat::A8R8G8B8);
        assert_eq!(eq2.compared(1.5 / 255.0), (2.0, 2.0));
        assert_eq!(eq2.compared(2.5 / 255.0), (2.0, 2.0));
        // NaN fails every comparison but NOTEQUAL.
        let eq0 = AlphaTest::new(CmpFunc::Equal, 0, TargetFormat::A8R8G8B8);
        assert!(!eq0.passes(f32::NAN));
        assert!(AlphaTest::new(CmpFunc::NotEqual, 0, TargetFormat::A8R8G8B8).passes(f32::NAN));
        // Nothing clamps: −1 → −255, which is not 0 and is LESS than 0.
        assert!(!eq0.passes(-1.0));
        assert!(AlphaTest::new(CmpFunc::Less, 0, TargetFormat::A8R8G8B8).passes(-0.5));
        assert_eq!(CmpFunc::from_name("D3DCMP_LESS"), Some(CmpFunc::Less));
        let mut killed = vec![false, false];
        PixelState {
            alpha_test: Some(t),
            ..Default::default()
        }
        .apply(
            Some(&[[0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 0.25]]),
            &mut killed,
            2,
        );
        assert_eq!(killed, vec![false, true]);
    }

    #[test]
    fn alpha_test_is_unclamped_at_every_precision() {
        // vkd3d's alpha-test.shader_test (Windows, A32B32G32R32F target,
        // ALPHAREF = 1.0 × 255): alphas 0.5, 1.0, 1.5 against 1.0.
        let float = |f: &str| {
            AlphaTest::new(
                CmpFunc::from_name(f).unwrap(),
                255,
                TargetFormat::A32B32G32R32F,
            )
        };
        let row = |f: &str| [0.5f32, 1.0, 1.5].map(|a| float(f).passes(a));
        assert_eq!(row("EQUAL"), [false, true, false]);
        assert_eq!(row("NOTEQUAL"), [true, false, true]);
        assert_eq!(row("GREATER"), [false, false, true]);
        assert_eq!(row("GREATEREQUAL"), [false, true, true]);
        assert_eq!(row("LESSEQUAL"), [true, true, false]);
        assert_eq!(row("LESS"), [true, false, false]);
        // The same on 8-bit and half targets: 1.5 × 255 = 382.5 → 382
        // (even) > 255; 1.5 × 32767 = 49150.5 → 49150 > 255·128 + 127 =
        // 32767.
        for format in [TargetFormat::A8R8G8B8, TargetFormat::Rgba16F] {
            let t = AlphaTest::new(CmpFunc::Greater, 255, format);
            assert!(t.passes(1.5) && !t.passes(1.0), "{format:?}");
        }
        let half = AlphaTest::new(CmpFunc::Equal, 255, TargetFormat::Rgba16F);
        assert_eq!(half.compared(1.5), (49150.0, 32767.0));
        // ALPHAREF 128 on a half target: 128·128 + 64 = 16448, and alpha
        // 16448/32767 compares equal.
        let h = AlphaTest::new(CmpFunc::Equal, 128, TargetFormat::Rgba16F);
        assert_eq!(h.compared(16448.0 / 32767.0), (16448.0, 16448.0));
    }
}
