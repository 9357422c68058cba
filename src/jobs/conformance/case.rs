//! The file format of the conformance corpus: one `cases.json` per test
//! function of the source suite, naming its shaders (a `.psh` file each,
//! with the token array the source gives) and its cases (render targets,
//! draws, probes with the expected D3DCOLOR and its tolerance).
//!
//! The format describes a Direct3D 9 draw the way an application sets it
//! up, not the way ps30 runs it: positions in clip space or pre-transformed
//! screen space, vertex values by semantic (`texcoord0`, `color1`, …) as the
//! vertex stage hands them to the rasteriser, cull and shade modes, sampler
//! states with D3D9's defaults. `raster.rs` turns that into the
//! emulator's draws. Unknown fields are errors, so a misspelt key cannot
//! silently fall back to a default.

use serde::{Deserialize, Deserializer};
use std::collections::BTreeMap;

/// A D3DCOLOR, written `"0xAARRGGBB"` in the files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct D3dColor(pub u32);

impl D3dColor {
    /// The colour as D3D9 hands it to a shader: (r, g, b, a), each byte / 255
    /// (D3DDECLTYPE_D3DCOLOR, "mapped to 0 to 1 range", and texture reads of
    /// D3DFMT_A8R8G8B8).
    pub fn rgba(self) -> [f32; 4] {
        let byte = |shift: u32| ((self.0 >> shift) & 0xff) as f32 / 255.0;
        [byte(16), byte(8), byte(0), byte(24)]
    }
}

impl std::fmt::Display for D3dColor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "0x{:08x}", self.0)
    }
}

/// Parses `0x` followed by one to eight hex digits.
pub fn parse_hex_u32(text: &str) -> Result<u32, String> {
    let digits = text
        .strip_prefix("0x")
        .ok_or_else(|| format!("`{text}` is not a hex number (0x…)"))?;
    if digits.is_empty() || digits.len() > 8 {
        return Err(format!("`{text}` is not a 32-bit hex number"));
    }
    u32::from_str_radix(digits, 16).map_err(|_| format!("`{text}` is not a hex number"))
}

impl<'de> Deserialize<'de> for D3dColor {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<D3dColor, D::Error> {
        let text = String::deserialize(d)?;
        parse_hex_u32(&text)
            .map(D3dColor)
            .map_err(serde::de::Error::custom)
    }
}

/// One DWORD of a token array, written `"0x…"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token(pub u32);

impl<'de> Deserialize<'de> for Token {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Token, D::Error> {
        let text = String::deserialize(d)?;
        parse_hex_u32(&text)
            .map(Token)
            .map_err(serde::de::Error::custom)
    }
}

/// A `cases.json`: the cases of one test function.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SuiteSpec {
    /// The test function of the source (`vface_register_test`).
    pub function: String,
    /// The source file, relative to the source tree.
    pub source: String,
    /// First and last line of the function.
    pub lines: [u32; 2],
    /// What the function tests, in a sentence or two.
    pub about: String,
    /// The shaders by the name cases use for them.
    pub shaders: BTreeMap<String, ShaderSpec>,
    /// The cases, in the source's order.
    pub cases: Vec<CaseSpec>,
}

/// A shader: its assembly file and the token array the source holds.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShaderSpec {
    /// The `.psh` file, relative to the `cases.json`.
    pub file: String,
    /// Lines of the token array(s) the shader is made of, in order.
    pub lines: Vec<u32>,
    /// The DWORDs of those arrays, concatenated: what the source hands to
    /// CreatePixelShader, against which the `.psh` file's assembly is checked.
    pub tokens: Vec<Token>,
}

/// One case: targets, the draws into them and what is read back — or a
/// shader the runtime must refuse.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseSpec {
    /// The case's name, unique in its file (`vface`, `texkill_ordering`).
    pub name: String,
    /// Source lines of the set-up and the checks.
    pub lines: Vec<u32>,
    /// What the case checks, and anything a reader should know about it.
    pub note: String,
    /// The render targets, bound as oC0, oC1, … in this order.
    #[serde(default)]
    pub targets: Vec<TargetSpec>,
    /// The draw calls, in order.
    #[serde(default)]
    pub draws: Vec<DrawSpec>,
    /// The pixels read back and what the source expects of them.
    #[serde(default)]
    pub probes: Vec<ProbeSpec>,
    /// Set for a case whose shader must fail to load.
    pub rejected: Option<RejectedSpec>,
}

/// A shader that CreatePixelShader refuses, and the start of the error
/// ps30 must give.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RejectedSpec {
    /// The name of the shader (a key of [`SuiteSpec::shaders`]).
    pub shader: String,
    /// The start of ps30's error message for it.
    pub message: String,
}

/// The 8-bit render-target and texture formats of the corpus.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum ColorFormat {
    /// `D3DFMT_A8R8G8B8`.
    A8R8G8B8,
    /// `D3DFMT_X8R8G8B8`: alpha is not stored (reads as 1 from a texture,
    /// undefined in a readback).
    X8R8G8B8,
}

/// A render target bound at index `i` of the case's list (oC`i`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetSpec {
    /// The target's name, for messages.
    pub name: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The format the target stores; read-backs are compared in it.
    pub format: ColorFormat,
    /// The Clear colour; `null` for a target the application never clears
    /// (its texels are undefined until a draw writes them).
    pub clear: Option<D3dColor>,
}

/// D3DPRIMITIVETYPE: how the vertices make triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Primitive {
    /// D3DPT_TRIANGLELIST: every three vertices one triangle.
    TriangleList,
    /// D3DPT_TRIANGLESTRIP: each vertex after the second closes a triangle with
    /// the two before it, every other one wound the other way.
    TriangleStrip,
}

/// How vertex positions are given.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Positions {
    /// Clip space (x, y, z[, w]), as a pass-through vertex shader writes it;
    /// the viewport is the whole render target.
    Clip,
    /// Pre-transformed screen space (x, y, z, rhw), D3DDECLUSAGE_POSITIONT.
    Screen,
}

/// D3DRS_CULLMODE (the rasteriser's own type, `core/raster`).
pub use crate::core::raster::Cull;

/// D3DRS_SHADEMODE. The default is D3D9's, Gouraud.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shade {
    /// D3DSHADE_FLAT: colour inputs take the first vertex's value.
    Flat,
    /// D3DSHADE_GOURAUD: every input is interpolated.
    #[default]
    Gouraud,
}

/// One draw call.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DrawSpec {
    /// The name of the shader drawn (a key of [`SuiteSpec::shaders`]).
    pub shader: String,
    /// How the vertices make triangles.
    pub primitive: Primitive,
    /// Whether positions are in clip space or on screen.
    pub positions: Positions,
    /// Which facing is dropped.
    #[serde(default)]
    pub cull: Cull,
    /// Whether colours are interpolated or flat.
    #[serde(default)]
    pub shade: Shade,
    /// The vertices, in the primitive's order.
    pub vertices: Vec<Vertex>,
    /// `c#` (4 numbers), `i#` (4 integers), `b#` (true/false), as set with
    /// SetPixelShaderConstantF/I/B.
    #[serde(default)]
    pub constants: BTreeMap<String, Constant>,
    /// The textures bound and their sampler states; unnamed samplers have none.
    #[serde(default)]
    pub samplers: Vec<SamplerSpec>,
}

/// A vertex: its position and, by semantic (`texcoord0`, `color1`, …), the
/// values the vertex stage hands to the rasteriser.
#[derive(Clone, Debug, Deserialize)]
pub struct Vertex {
    /// 2 to 4 numbers in the draw's [`Positions`] convention.
    pub position: Vec<f64>,
    /// Every other key: a semantic (`texcoord0`, `color1`) and its value.
    #[serde(flatten)]
    pub attributes: BTreeMap<String, Attribute>,
}

/// A vertex value: 1 to 4 floats (D3DDECLTYPE_FLOAT1…4, the missing
/// components become (0, 0, 0, 1)) or a D3DCOLOR.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Attribute {
    /// A D3DCOLOR, each byte / 255, in (r, g, b, a) order.
    Color(D3dColor),
    /// 1 to 4 floats.
    Floats(Vec<f32>),
}

impl Attribute {
    /// The four components the pixel shader receives (D3DDECLTYPE
    /// expansion).
    pub fn expand(&self) -> Result<[f32; 4], String> {
        match self {
            Attribute::Color(c) => Ok(c.rgba()),
            Attribute::Floats(v) if (1..=4).contains(&v.len()) => {
                let mut out = [0.0, 0.0, 0.0, 1.0];
                out[..v.len()].copy_from_slice(v);
                Ok(out)
            }
            Attribute::Floats(v) => Err(format!("{} components; 1 to 4 expected", v.len())),
        }
    }
}

/// A shader constant set by the application.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Constant {
    /// `b#`: `true` or `false`.
    Bool(bool),
    /// `c#`: four numbers; `i#`: four integers.
    Vector(Vec<f64>),
}

/// D3DTEXTUREFILTERTYPE for MAG/MINFILTER.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FilterSpec {
    /// D3DTEXF_POINT: the nearest texel.
    #[default]
    Point,
    /// D3DTEXF_LINEAR: bilinear.
    Linear,
}

/// D3DTEXTUREADDRESS; D3D9's default is `wrap`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AddressSpec {
    /// D3DTADDRESS_WRAP: the texture repeats.
    #[default]
    Wrap,
    /// D3DTADDRESS_MIRROR: the texture repeats, every other copy mirrored.
    Mirror,
    /// D3DTADDRESS_CLAMP: coordinates clamp to the edge texels.
    Clamp,
    /// D3DTADDRESS_BORDER: texels outside read the border colour.
    Border,
    /// D3DTADDRESS_MIRRORONCE: mirrored once about 0, then clamped.
    MirrorOnce,
}

/// A 2D texture and the sampler states of `s#` that differ from D3D9's
/// defaults (point filters, no mips, WRAP, border 0).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SamplerSpec {
    /// The sampler register (`s#`).
    pub sampler: u32,
    /// The texture bound to it.
    pub texture: TextureSpec,
    /// D3DSAMP_MAGFILTER.
    #[serde(default)]
    pub mag_filter: FilterSpec,
    /// D3DSAMP_MINFILTER.
    #[serde(default)]
    pub min_filter: FilterSpec,
    /// D3DSAMP_ADDRESSU.
    #[serde(default)]
    pub address_u: AddressSpec,
    /// D3DSAMP_ADDRESSV.
    #[serde(default)]
    pub address_v: AddressSpec,
    /// D3DSAMP_BORDERCOLOR; `null` for D3D9's default, transparent black.
    pub border: Option<D3dColor>,
}

/// One mip level of texels, row 0 at the top.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TextureSpec {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// How the texels are stored (X8R8G8B8 reads alpha as 1).
    pub format: ColorFormat,
    /// `width × height` colours, row-major.
    pub texels: Vec<D3dColor>,
}

impl TextureSpec {
    /// The texels as the sampler returns them (X8R8G8B8: alpha 1).
    pub fn rgba(&self) -> Vec<[f32; 4]> {
        self.texels
            .iter()
            .map(|c| {
                let mut v = c.rgba();
                if self.format == ColorFormat::X8R8G8B8 {
                    v[3] = 1.0;
                }
                v
            })
            .collect()
    }
}

/// A pixel read back, with the colour the source expects there.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeSpec {
    /// Index into the case's targets.
    pub target: usize,
    /// Column, in pixels from the left.
    pub x: u32,
    /// Row, in pixels from the top.
    pub y: u32,
    /// The colour the source expects.
    pub expected: D3dColor,
    /// Largest difference allowed per channel, in 8-bit steps.
    pub tolerance: u8,
    /// Whether alpha is compared (the source masked it off when false).
    pub alpha: bool,
    /// Source line of the check.
    pub line: u32,
    /// Other results the source accepts, from particular drivers.
    #[serde(default)]
    pub alternatives: Vec<Alternative>,
}

/// A result the source accepts besides the expected one, and from whom.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Alternative {
    /// The colour accepted.
    pub expected: D3dColor,
    /// Largest difference allowed per channel, in 8-bit steps.
    pub tolerance: u8,
    /// Whose result it is (a driver or vendor, as the source names it).
    pub who: String,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_and_tokens_parse_from_hex_strings() {
        let c: D3dColor = serde_json::from_str("\"0x80ff4020\"").unwrap();
        assert_eq!(c, D3dColor(0x80ff4020));
        assert_eq!(c.rgba(), [1.0, 64.0 / 255.0, 32.0 / 255.0, 128.0 / 255.0]);
        assert_eq!(c.to_string(), "0x80ff4020");
        let t: Token = serde_json::from_str("\"0xffff0300\"").unwrap();
        assert_eq!(t, Token(0xffff0300));
        for bad in ["\"ff\"", "\"0x\"", "\"0x123456789\"", "\"0xzz\"", "12"] {
            assert!(serde_json::from_str::<D3dColor>(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn attributes_expand_as_vertex_declarations_do() {
        let a = |json: &str| serde_json::from_str::<Attribute>(json).unwrap().expand();
        assert_eq!(a("[0.5]").unwrap(), [0.5, 0.0, 0.0, 1.0]);
        assert_eq!(a("[1, 2]").unwrap(), [1.0, 2.0, 0.0, 1.0]);
        assert_eq!(a("[1, 2, 3, 4]").unwrap(), [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(a("\"0xff000000\"").unwrap(), [0.0, 0.0, 0.0, 1.0]);
        assert!(a("[]").is_err());
        assert!(a("[1, 2, 3, 4, 5]").is_err());
    }

    #[test]
    fn unknown_fields_are_errors() {
        let e = serde_json::from_str::<ProbeSpec>(
            r#"{"target": 0, "x": 1, "y": 2, "expected": "0x0", "tolerance": 1,
                "alpha": false, "line": 3, "tolerence": 2}"#,
        )
        .unwrap_err();
        assert!(e.to_string().contains("tolerence"), "{e}");
    }
}
