//! Vertex lists: the JSON file a person writes (or a capture tool emits)
//! for `ps30 run VS --vertices FILE`, read field by field into the vertex
//! stage's [`Vertices`], and the outputs written back in the same form.
//!
//! The format (`docs/vertex-shaders.md`): one object, with the attributes
//! either as columns or as rows —
//!
//! ```json
//! {"attributes": {"position0": [[0, 0, 0, 1], [1, 0, 0, 1]], "texcoord0": [[0, 0], [1, 0]]}}
//! {"vertices": [{"position0": [0, 0, 0, 1], "texcoord0": [0, 0]},
//!               {"position0": [1, 0, 0, 1], "texcoord0": [1, 0]}]}
//! ```
//!
//! An attribute is named by its declaration usage and index (`position0`,
//! `texcoord3`, `color1`; `normal` alone is `normal0`) and holds one to
//! four numbers per vertex, filled as Direct3D 9 fills a short vertex
//! format: (x, 0, 0, 1), or a D3DCOLOR `"0xAARRGGBB"` (D3DDECLTYPE_D3DCOLOR:
//! the shader reads (R, G, B, A), each byte over 255). Every value must be a JSON number that single
//! precision holds (no NaN, no infinity, nothing past ±3.4e38); every
//! vertex has every attribute; at most [`MAX_VERTICES`] vertices. Each
//! refusal names the file and the field (`attributes.texcoord0[2]`).
//!
//! A third form is what a capture tool records of a draw: a vertex
//! declaration and the raw bytes of its vertex buffers (`buffers.rs`),
//! decoded by every D3DDECLTYPE's rule (`core::decltype`).

mod buffers;

use crate::core::cost::{self, Range, Verdict};
use crate::core::diag::SourceFile;
use crate::core::emu::vertex::{self, Attribute, VertexDraw, VertexError, VertexOutput, Vertices};
use crate::core::emu::{Constants, SamplerState};
use crate::core::float_rules::FloatRules;
use crate::core::image::TextureFile;
use crate::core::ir::Shader;
use crate::core::isa::USAGES;
use serde_json::{Map, Value};
use std::path::Path;

/// The most vertices a file may list.
pub const MAX_VERTICES: usize = 1 << 20;

/// The largest vertex file read, in bytes.
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// Reads and checks a vertex-list file.
pub fn read(path: &Path) -> Result<Vertices, String> {
    let name = path.display();
    let bytes = read_capped(path, "a vertex list")?;
    let text = String::from_utf8(bytes).map_err(|e| format!("{name}: not UTF-8 text: {e}"))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    parse_in(&text, dir).map_err(|e| format!("{name}: {e}"))
}

/// The bytes of `path` (`what` names the file in the refusal), at most
/// [`MAX_FILE_BYTES`]: the size is checked before the file is read, and the
/// read stops there whatever the file turns out to hold (`/dev/zero`).
fn read_capped(path: &Path, what: &str) -> Result<Vec<u8>, String> {
    use std::io::Read;
    let name = path.display();
    let size = std::fs::metadata(path)
        .map_err(|e| format!("{name}: {e}"))?
        .len();
    if size > MAX_FILE_BYTES {
        return Err(format!(
            "{name}: {size} bytes; {what} is at most {MAX_FILE_BYTES} bytes"
        ));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES).read_to_end(&mut bytes))
        .map_err(|e| format!("{name}: {e}"))?;
    Ok(bytes)
}

/// Parses a vertex list's text (see the module docs); vertex-buffer files
/// are relative to the working directory.
pub fn parse(text: &str) -> Result<Vertices, String> {
    parse_in(text, Path::new("."))
}

/// [`parse`], vertex-buffer files relative to `dir` (the list's own folder).
pub fn parse_in(text: &str, dir: &Path) -> Result<Vertices, String> {
    let v: Value = serde_json::from_str(text).map_err(|e| format!("not JSON: {e}"))?;
    let Value::Object(top) = v else {
        return Err(
            "expected an object with \"attributes\", \"vertices\" or \"declaration\"".into(),
        );
    };
    const FIELDS: &str = "attributes, vertices, declaration, streams, count, description";
    if let Some(k) = top
        .keys()
        .find(|k| !FIELDS.split(", ").any(|f| f == k.as_str()))
    {
        return Err(format!("unknown field `{k}` (fields: {FIELDS})"));
    }
    let buffers = ["declaration", "streams", "count"]
        .iter()
        .any(|k| top.contains_key(*k));
    match (top.get("attributes"), top.get("vertices"), buffers) {
        (Some(a), None, false) => columns(a),
        (None, Some(v), false) => rows(v),
        (None, None, true) => buffers::read(&top, dir),
        (None, None, false) => Err(
            "expected \"attributes\" (columns), \"vertices\" (rows) or \"declaration\" with \"streams\" (vertex buffers)"
                .into(),
        ),
        _ => Err("give one of \"attributes\", \"vertices\" or \"declaration\"".into()),
    }
}

/// `{"position0": [[…], …], …}`.
fn columns(a: &Value) -> Result<Vertices, String> {
    let Value::Object(map) = a else {
        return Err("attributes: expected an object of attribute: [values]".into());
    };
    let mut out = Vertices::default();
    let mut count = None;
    for (key, values) in map {
        let attribute = attribute(key).map_err(|e| format!("attributes.{key}: {e}"))?;
        let Value::Array(list) = values else {
            return Err(format!("attributes.{key}: expected an array of values"));
        };
        bounded(list.len(), &format!("attributes.{key}"))?;
        if let Some(n) = count.filter(|&n| n != list.len()) {
            return Err(format!(
                "attributes.{key}: {} values, and the attributes before it have {n}",
                list.len()
            ));
        }
        count = Some(list.len());
        let vals = list
            .iter()
            .enumerate()
            .map(|(i, v)| value(v).map_err(|e| format!("attributes.{key}[{i}]: {e}")))
            .collect::<Result<Vec<_>, _>>()?;
        out.attributes.push((attribute, vals));
    }
    out.count = count.unwrap_or(0);
    Ok(out)
}

/// `[{"position0": […], …}, …]`.
fn rows(v: &Value) -> Result<Vertices, String> {
    let Value::Array(list) = v else {
        return Err("vertices: expected an array of vertex objects".into());
    };
    bounded(list.len(), "vertices")?;
    let mut out = Vertices {
        count: list.len(),
        attributes: Vec::new(),
    };
    let empty = Map::new();
    let first = list.first().and_then(Value::as_object).unwrap_or(&empty);
    for key in first.keys() {
        let attribute = attribute(key).map_err(|e| format!("vertices[0].{key}: {e}"))?;
        out.attributes
            .push((attribute, Vec::with_capacity(list.len())));
    }
    for (i, vertex) in list.iter().enumerate() {
        let Value::Object(fields) = vertex else {
            return Err(format!(
                "vertices[{i}]: expected an object of attribute: value"
            ));
        };
        if let Some(k) = fields.keys().find(|k| !first.contains_key(*k)) {
            return Err(format!(
                "vertices[{i}].{k}: vertex 0 has no such attribute (every vertex has the same ones)"
            ));
        }
        for (key, (_, values)) in first.keys().zip(out.attributes.iter_mut()) {
            let Some(v) = fields.get(key) else {
                return Err(format!("vertices[{i}]: no `{key}` (vertex 0 has it)"));
            };
            values.push(value(v).map_err(|e| format!("vertices[{i}].{key}: {e}"))?);
        }
    }
    Ok(out)
}

/// At most [`MAX_VERTICES`].
fn bounded(n: usize, at: &str) -> Result<(), String> {
    if n > MAX_VERTICES {
        return Err(format!(
            "{at}: {n} vertices; a list holds at most {MAX_VERTICES}"
        ));
    }
    Ok(())
}

/// `texcoord3` → (texcoord, 3); `normal` → (normal, 0).
fn attribute(key: &str) -> Result<Attribute, String> {
    let usage = key.trim_end_matches(|c: char| c.is_ascii_digit());
    let digits = &key[usage.len()..];
    if !USAGES.contains(&usage) {
        return Err(format!(
            "`{usage}` is not a declaration usage ({})",
            USAGES.join(", ")
        ));
    }
    let index = match digits {
        "" => 0,
        d => d
            .parse::<u32>()
            .ok()
            .filter(|&i| i <= 15)
            .ok_or_else(|| format!("usage index `{d}` is not 0 to 15"))?,
    };
    Ok(Attribute {
        usage: usage.to_string(),
        index,
    })
}

/// One to four finite single-precision numbers, filled to (x, 0, 0, 1).
fn value(v: &Value) -> Result<[f32; 4], String> {
    if let Value::String(text) = v {
        return d3dcolor(text);
    }
    let Value::Array(list) = v else {
        return Err("expected an array of 1 to 4 numbers, or a D3DCOLOR \"0xAARRGGBB\"".into());
    };
    if list.is_empty() || list.len() > 4 {
        return Err(format!(
            "{} components; an attribute has 1 to 4",
            list.len()
        ));
    }
    let mut out = [0.0, 0.0, 0.0, 1.0];
    for (c, x) in list.iter().enumerate() {
        let n = x
            .as_f64()
            .ok_or_else(|| format!("component {c} is not a number: {x}"))?;
        let f = n as f32;
        if !f.is_finite() {
            return Err(format!("component {c} ({n}) is outside single precision"));
        }
        out[c] = f;
    }
    Ok(out)
}

/// A D3DCOLOR written as `"0xAARRGGBB"`, as D3DDECLTYPE_D3DCOLOR hands it
/// to the shader: "expanded to (R, G, B, A)", each byte over 255.
fn d3dcolor(text: &str) -> Result<[f32; 4], String> {
    let hex = text
        .strip_prefix("0x")
        .or_else(|| text.strip_prefix("0X"))
        .filter(|h| h.len() == 8)
        .and_then(|h| u32::from_str_radix(h, 16).ok())
        .ok_or_else(|| format!("`{text}` is not a D3DCOLOR \"0xAARRGGBB\""))?;
    let byte = |shift: u32| ((hex >> shift) & 0xFF) as f32 / 255.0;
    Ok([byte(16), byte(8), byte(0), byte(24)])
}

/// The vertex draw of `constants` and `textures` (vs_3_0's `s0`–`s3`).
fn vertex_draw(
    constants: Constants,
    textures: &[(u32, TextureFile, SamplerState)],
    float_rules: FloatRules,
    max_executed_per_vertex: u64,
) -> VertexDraw<'_> {
    VertexDraw {
        constants,
        samplers: textures
            .iter()
            .map(|(s, t, state)| (*s, t.into(), *state))
            .collect(),
        float_rules,
        max_executed_per_vertex,
    }
}

/// Runs a vertex shader over `vertices` with the application's constants
/// and vs_3_0's vertex textures (`s0`–`s3`, for `texldl`).
pub fn run(
    shader: &Shader,
    constants: Constants,
    textures: &[(u32, TextureFile, SamplerState)],
    vertices: &Vertices,
    float_rules: FloatRules,
    max_executed_per_vertex: u64,
) -> Result<VertexOutput, VertexError> {
    let draw = vertex_draw(constants, textures, float_rules, max_executed_per_vertex);
    vertex::run(shader, &draw, vertices)
}

/// [`run`] on `backend`: the emulator, or the GPU through the translation
/// (`core::gpu::run_vertices`), whose outputs are the same registers
/// without executed counts. A GPU cannot stop a vertex part way, so a draw
/// whose cost-model longest path passes `max_executed_per_vertex` is
/// refused there, as the pixel path refuses it (`jobs::backend`).
#[allow(clippy::too_many_arguments)]
pub fn run_on(
    backend: &crate::jobs::backend::Backend,
    shader: &Shader,
    file: &SourceFile,
    constants: Constants,
    textures: &[(u32, TextureFile, SamplerState)],
    vertices: &Vertices,
    float_rules: FloatRules,
    max_executed_per_vertex: u64,
) -> Result<VertexOutput, String> {
    let gpu = match backend.gpu().map_err(|e| e.to_string())? {
        None => {
            return run(
                shader,
                constants,
                textures,
                vertices,
                float_rules,
                max_executed_per_vertex,
            )
            .map_err(|e| e.to_string())
        }
        Some(g) => g,
    };
    let env = crate::jobs::backend::environment(&constants);
    if let Ok(a) = cost::analyse(shader, file, &env, &cost::Profile::ps_3_0()) {
        if a.executed.max > max_executed_per_vertex {
            return Err(format!(
                "a vertex may execute up to {} instruction slots (the cost model's longest path for these constants), over the cap of {}: a GPU cannot stop a vertex part way, so ps30 does not run it there (the emulator stops the first vertex that passes the cap)",
                crate::core::numbers::thousands(a.executed.max),
                crate::core::numbers::thousands(max_executed_per_vertex)
            ));
        }
    }
    let draw = vertex_draw(constants, textures, float_rules, max_executed_per_vertex);
    crate::core::gpu::run_vertices(gpu, shader, &draw, vertices).map_err(|e| e.to_string())
}

/// A vertex shader's costs over a vertex list: the cost model's (slots,
/// executed range) beside what each vertex executed.
#[derive(Clone, Debug, PartialEq)]
pub struct VertexProfile {
    /// The profile's name.
    pub profile: String,
    /// Static slots (Microsoft's count).
    pub slots: u64,
    /// The profile's slot limit.
    pub max_slots: u64,
    /// The profile's executed limit per vertex.
    pub max_executed: u64,
    /// The cost model's executed range for one vertex.
    pub model: Range,
    /// Executed slots of each vertex, as the vertex stage counted them.
    pub executed: Vec<u64>,
    /// Whether the model's verdict is within the limits.
    pub within_limits: bool,
    /// Whether every vertex's count lies in the model's range.
    pub counts_agree: bool,
    /// What each source line cost over the vertices.
    pub lines: Vec<crate::core::emu::lines::LineRuns>,
}

/// [`run`], with the cost model's analysis under the same integer and
/// boolean constants.
pub fn profile(
    shader: &Shader,
    file: &SourceFile,
    constants: Constants,
    textures: &[(u32, TextureFile, SamplerState)],
    vertices: &Vertices,
    float_rules: FloatRules,
    max_executed_per_vertex: u64,
) -> Result<VertexProfile, String> {
    let env = crate::jobs::backend::environment(&constants);
    let analysis =
        cost::analyse(shader, file, &env, &cost::Profile::ps_3_0()).map_err(|e| e.to_string())?;
    let draw = vertex_draw(constants, textures, float_rules, max_executed_per_vertex);
    let (out, runs) = vertex::run_counted(shader, &draw, vertices).map_err(|e| e.to_string())?;
    let model = analysis.executed;
    Ok(VertexProfile {
        profile: analysis.profile.name.clone(),
        slots: analysis.slots,
        max_slots: analysis.profile.max_slots,
        max_executed: analysis.profile.max_executed,
        model,
        counts_agree: out
            .executed
            .iter()
            .all(|&e| model.min <= e && e <= model.max),
        executed: out.executed,
        within_limits: analysis.verdict == Verdict::Within,
        lines: crate::core::emu::lines::vertex_lines(shader, file, &runs),
    })
}

/// A vertex stage's outputs in the vertex-list form (`{"attributes": …}`),
/// each output under its semantic (or its register when it has none), so
/// that they can be read back as a vertex list.
pub fn outputs_json(out: &VertexOutput) -> Value {
    let mut attributes = Map::new();
    for (k, slot) in out.slots.iter().enumerate() {
        let key = slot
            .semantic
            .as_ref()
            .map_or(slot.register.clone(), |s| s.to_string());
        let values: Vec<Value> = out
            .values
            .iter()
            .map(|v| {
                let number = |x: f32| {
                    serde_json::Number::from_f64(f64::from(x)).map_or(Value::Null, Value::Number)
                };
                Value::from(v[k].map(number).to_vec())
            })
            .collect();
        attributes.insert(key, Value::Array(values));
    }
    serde_json::json!({ "attributes": attributes })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_and_rows_read_the_same_vertices() {
        let a = parse(r#"{"attributes": {"position0": [[1, 2, 3, 4], [5, 6]], "texcoord1": [[0.5], [0.25, 1]]}}"#).unwrap();
        let b = parse(r#"{"vertices": [{"position0": [1, 2, 3, 4], "texcoord1": [0.5]}, {"position0": [5, 6], "texcoord1": [0.25, 1]}]}"#).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.count, 2);
        // short formats are filled as Direct3D 9 fills them: (x, 0, 0, 1)
        assert_eq!(a.attributes[0].1[1], [5.0, 6.0, 0.0, 1.0]);
        assert_eq!(a.attributes[1].1[0], [0.5, 0.0, 0.0, 1.0]);
        assert_eq!(a.attributes[1].0.to_string(), "texcoord1");
    }

    #[test]
    fn hostile_lists_are_refused_naming_the_field() {
        let cases = [
            (
                r#"{"attributes": {"position0": [[1], [2]], "color0": [[1]]}}"#,
                "attributes.position0: 2 values",
            ),
            (
                r#"{"attributes": {"position0": [[1, 2, 3, 4, 5]]}}"#,
                "attributes.position0[0]: 5 components",
            ),
            (
                r#"{"attributes": {"position0": [[1e39]]}}"#,
                "attributes.position0[0]: component 0",
            ),
            (
                r#"{"attributes": {"position0": [["nan"]]}}"#,
                "component 0 is not a number",
            ),
            (
                r#"{"attributes": {"colour0": [[1]]}}"#,
                "attributes.colour0: `colour`",
            ),
            (
                r#"{"attributes": {"texcoord16": [[1]]}}"#,
                "usage index `16`",
            ),
            (
                r#"{"vertices": [{"position0": [1]}, {"normal0": [1]}]}"#,
                "vertices[1].normal0",
            ),
            (
                r#"{"vertices": [{"position0": [1]}, {}]}"#,
                "vertices[1]: no `position0`",
            ),
            (r#"{"vertices": [1]}"#, "vertices[0]"),
            (r#"{"positions": []}"#, "unknown field `positions`"),
            ("[NaN]", "not JSON"),
        ];
        for (text, want) in cases {
            let e = parse(text).unwrap_err();
            assert!(e.contains(want), "{text}: {e}");
        }
    }
}
