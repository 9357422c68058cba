//! The vertex list as a capture tool sees a draw: a vertex declaration
//! (D3DVERTEXELEMENT9: stream, offset, type, method, usage, usage index)
//! and the raw bytes of the vertex buffers bound to its streams, decoded by
//! `core::decltype` into the vertex stage's [`Vertices`].
//!
//! ```json
//! {"declaration": [{"stream": 0, "offset": 0,  "type": "FLOAT3",   "usage": "position"},
//!                  {"stream": 0, "offset": 12, "type": "D3DCOLOR", "usage": "color"},
//!                  {"stream": 1, "offset": 0,  "type": "FLOAT16_2", "usage": "texcoord", "usage_index": 0}],
//!  "streams": [{"stream": 0, "file": "tri.vb", "stride": 16},
//!              {"stream": 1, "hex": "003c 0000  0000 003c  0000 0000", "stride": 4}],
//!  "count": 3}
//! ```
//!
//! Vertex v reads element e of stream s at `s.offset + v·s.stride +
//! e.offset` (SetStreamSource's OffsetInBytes and Stride, the element's
//! Offset). Every element must lie inside the stride; elements may
//! overlap (Direct3D 9 allows it), but no two may share a usage and usage
//! index. Without `count` the vertices are as many as every stream holds
//! whole (the fewest of any). Each stream's bytes must hold every vertex
//! asked for, checked against the file's size before anything is decoded;
//! every refusal names the element or stream and its field.

use super::{MAX_FILE_BYTES, MAX_VERTICES};
use crate::core::decltype::{self, DeclType};
use crate::core::emu::vertex::{Attribute, Vertices};
use crate::core::isa::USAGES;
use serde_json::{Map, Value};
use std::path::Path;

/// Direct3D 9's stream count (D3DCAPS9.MaxStreams is at most 16).
const STREAMS: u64 = 16;

/// MAXD3DDECLLENGTH: the most elements a declaration holds before its end.
const MAX_ELEMENTS: usize = 64;

/// The most decoded values (vertices × elements) one list may produce:
/// 64 MiB of floats, as much as a 64 MiB list of numbers could hold.
const MAX_VALUES: usize = 1 << 22;

/// One element of the declaration, checked.
struct Element {
    stream: u64,
    offset: u64,
    ty: DeclType,
    attribute: Attribute,
}

/// One stream's bytes and layout.
struct Stream {
    number: u64,
    bytes: Vec<u8>,
    stride: u64,
    offset: u64,
    at: String,
}

/// Reads `declaration`, `streams` and `count` from a vertex list's top
/// object; stream files are relative to `dir`.
pub(super) fn read(top: &Map<String, Value>, dir: &Path) -> Result<Vertices, String> {
    let decl = top
        .get("declaration")
        .ok_or("\"streams\" and \"count\" go with a \"declaration\"")?;
    let elements = declaration(decl)?;
    let Some(Value::Array(list)) = top.get("streams") else {
        return Err(
            "streams: expected an array of {\"stream\", \"file\" or \"hex\", \"stride\"}".into(),
        );
    };
    if list.len() as u64 > STREAMS {
        return Err(format!(
            "streams: {} streams; Direct3D 9 has {STREAMS}",
            list.len()
        ));
    }
    let mut streams: Vec<Stream> = Vec::new();
    for (i, s) in list.iter().enumerate() {
        let s = stream(s, i, dir)?;
        if let Some(first) = streams.iter().find(|o| o.number == s.number) {
            return Err(format!(
                "{}.stream: stream {} is given twice ({} too)",
                s.at, s.number, first.at
            ));
        }
        streams.push(s);
    }
    let count = count(top.get("count"), &elements, &streams)?;
    if count.saturating_mul(elements.len()) > MAX_VALUES {
        return Err(format!(
            "count: {count} vertices × {} elements; a list decodes at most {MAX_VALUES} values",
            elements.len()
        ));
    }
    let attributes = elements
        .iter()
        .map(|e| {
            let s = streams
                .iter()
                .find(|s| s.number == e.stream)
                .expect("checked in count");
            let values = (0..count as u64)
                .map(|v| {
                    let at = (s.offset + v * s.stride + e.offset) as usize;
                    e.ty.decode(&s.bytes[at..at + e.ty.size()])
                })
                .collect();
            (e.attribute.clone(), values)
        })
        .collect();
    Ok(Vertices { count, attributes })
}

/// The elements up to D3DDECL_END (a `"type": "UNUSED"` element) or the
/// list's end.
fn declaration(v: &Value) -> Result<Vec<Element>, String> {
    let Value::Array(list) = v else {
        return Err("declaration: expected an array of D3DVERTEXELEMENT9 objects".into());
    };
    let mut out: Vec<Element> = Vec::new();
    for (i, e) in list.iter().enumerate() {
        let at = format!("declaration[{i}]");
        let Some(element) = element(e, &at)? else {
            if i + 1 < list.len() {
                return Err(format!("{at}.type: UNUSED (D3DDECL_END) ends the declaration, and {} elements follow it", list.len() - i - 1));
            }
            break;
        };
        if out.len() == MAX_ELEMENTS {
            return Err(format!(
                "{at}: a declaration holds at most {MAX_ELEMENTS} elements (MAXD3DDECLLENGTH)"
            ));
        }
        if let Some(k) = out.iter().position(|o| o.attribute == element.attribute) {
            return Err(format!(
                "{at}.usage: {} is declared twice (declaration[{k}] too); each usage and index names one input",
                element.attribute
            ));
        }
        out.push(element);
    }
    if out.is_empty() {
        return Err("declaration: no elements".into());
    }
    Ok(out)
}

/// One D3DVERTEXELEMENT9; `None` for D3DDECL_END.
fn element(v: &Value, at: &str) -> Result<Option<Element>, String> {
    let Value::Object(map) = v else {
        return Err(format!(
            "{at}: expected an object (stream, offset, type, method, usage, usage_index)"
        ));
    };
    if let Some(k) = map.keys().find(|k| {
        !matches!(
            k.as_str(),
            "stream" | "offset" | "type" | "method" | "usage" | "usage_index"
        )
    }) {
        return Err(format!(
            "{at}: unknown field `{k}` (fields: stream, offset, type, method, usage, usage_index)"
        ));
    }
    let ty = match map.get("type") {
        None => {
            return Err(format!(
                "{at}.type: missing (a D3DDECLTYPE: FLOAT1 … FLOAT16_4, or UNUSED to end)"
            ))
        }
        Some(t) => decl_type(t).map_err(|e| format!("{at}.type: {e}"))?,
    };
    let Some(ty) = ty else { return Ok(None) };
    let stream =
        number(map.get("stream"), 0, STREAMS - 1).map_err(|e| format!("{at}.stream: {e}"))?;
    let offset = match map.get("offset") {
        None => {
            return Err(format!(
                "{at}.offset: missing (the element's byte offset in the vertex)"
            ))
        }
        o => number(o, 0, u64::from(u16::MAX)).map_err(|e| format!("{at}.offset: {e}"))?,
    };
    method(map.get("method")).map_err(|e| format!("{at}.method: {e}"))?;
    let usage = usage(map.get("usage")).map_err(|e| format!("{at}.usage: {e}"))?;
    let index =
        number(map.get("usage_index"), 0, 15).map_err(|e| format!("{at}.usage_index: {e}"))?;
    Ok(Some(Element {
        stream,
        offset,
        ty,
        attribute: Attribute {
            usage: usage.into(),
            index: index as u32,
        },
    }))
}

/// A D3DDECLTYPE by name (`FLOAT3`, `D3DDECLTYPE_FLOAT3`) or number;
/// `None` for UNUSED.
fn decl_type(v: &Value) -> Result<Option<DeclType>, String> {
    let names = || {
        let mut n: Vec<&str> = decltype::ALL.iter().map(|(n, _)| *n).collect();
        n.push("UNUSED");
        n.join(", ")
    };
    match v {
        Value::String(s) => {
            let upper = s.to_ascii_uppercase();
            if upper.trim_start_matches("D3DDECLTYPE_") == "UNUSED" {
                return Ok(None);
            }
            DeclType::from_name(s)
                .map(Some)
                .ok_or_else(|| format!("`{s}` is not a D3DDECLTYPE ({})", names()))
        }
        Value::Number(n) => match n.as_u64() {
            Some(k) if k == u64::from(decltype::UNUSED) => Ok(None),
            Some(k) if k < u64::from(decltype::UNUSED) => Ok(DeclType::from_value(k as u32)),
            _ => Err(format!("{n} is not a D3DDECLTYPE (0 to 17)")),
        },
        _ => Err(format!(
            "expected a D3DDECLTYPE name ({}) or number",
            names()
        )),
    }
}

/// D3DDECLMETHOD: only DEFAULT (0) reaches a vertex shader unchanged; the
/// others drive the tessellator and displacement mapping.
fn method(v: Option<&Value>) -> Result<(), String> {
    match v {
        None => Ok(()),
        Some(Value::Number(n)) if n.as_u64() == Some(0) => Ok(()),
        Some(Value::String(s)) if s.eq_ignore_ascii_case("DEFAULT") || s.eq_ignore_ascii_case("D3DDECLMETHOD_DEFAULT") => Ok(()),
        Some(m) => Err(format!("{m}: only DEFAULT is read; the other D3DDECLMETHODs feed the tessellator (N-patches, displacement maps), which ps30 does not run")),
    }
}

/// A D3DDECLUSAGE by name (`texcoord`, `D3DDECLUSAGE_TEXCOORD`) or number.
fn usage(v: Option<&Value>) -> Result<&'static str, String> {
    let list = || USAGES.join(", ");
    match v {
        None => Err(format!("missing (a D3DDECLUSAGE: {})", list())),
        Some(Value::String(s)) => {
            let lower = s.to_ascii_lowercase();
            let short = lower.strip_prefix("d3ddeclusage_").unwrap_or(&lower);
            USAGES
                .iter()
                .find(|u| **u == short)
                .copied()
                .ok_or_else(|| {
                    format!(
                        "`{s}` is not a D3DDECLUSAGE ({}; the index goes in usage_index)",
                        list()
                    )
                })
        }
        Some(Value::Number(n)) => n
            .as_u64()
            .and_then(|k| USAGES.get(k as usize))
            .copied()
            .ok_or_else(|| format!("{n} is not a D3DDECLUSAGE (0 to {})", USAGES.len() - 1)),
        Some(other) => Err(format!("{other}: expected a D3DDECLUSAGE name or number")),
    }
}

/// An optional whole number from 0 to `max` (`default` when absent).
fn number(v: Option<&Value>, default: u64, max: u64) -> Result<u64, String> {
    match v {
        None => Ok(default),
        Some(x) => x
            .as_u64()
            .filter(|&n| n <= max)
            .ok_or_else(|| format!("{x} is not a whole number from 0 to {max}")),
    }
}

/// One `streams` entry: its bytes (a file relative to `dir`, or hex), stride
/// and offset.
fn stream(v: &Value, i: usize, dir: &Path) -> Result<Stream, String> {
    let at = format!("streams[{i}]");
    let Value::Object(map) = v else {
        return Err(format!(
            "{at}: expected an object (stream, file or hex, stride, offset)"
        ));
    };
    if let Some(k) = map
        .keys()
        .find(|k| !matches!(k.as_str(), "stream" | "file" | "hex" | "stride" | "offset"))
    {
        return Err(format!(
            "{at}: unknown field `{k}` (fields: stream, file, hex, stride, offset)"
        ));
    }
    let number_of = |k: &str, default: u64, max: u64| {
        number(map.get(k), default, max).map_err(|e| format!("{at}.{k}: {e}"))
    };
    let number = number_of("stream", i as u64, STREAMS - 1)?;
    let stride = match map.get("stride") {
        None => {
            return Err(format!(
                "{at}.stride: missing (bytes from one vertex to the next)"
            ))
        }
        Some(_) => number_of("stride", 0, u64::from(u16::MAX))?,
    };
    if stride == 0 {
        return Err(format!("{at}.stride: 0; every vertex would read the same bytes (give the vertex size in bytes)"));
    }
    let offset = number_of("offset", 0, MAX_FILE_BYTES)?;
    let bytes = match (map.get("file"), map.get("hex")) {
        (Some(Value::String(f)), None) => super::read_capped(&dir.join(f), "a vertex buffer")
            .map_err(|e| format!("{at}.file: {e}"))?,
        (None, Some(Value::String(h))) => hex(h).map_err(|e| format!("{at}.hex: {e}"))?,
        (Some(_), Some(_)) => return Err(format!("{at}: give \"file\" or \"hex\", not both")),
        (None, None) => {
            return Err(format!(
                "{at}: no bytes: give \"file\" (a binary file) or \"hex\""
            ))
        }
        _ => return Err(format!("{at}: \"file\" and \"hex\" are strings")),
    };
    Ok(Stream {
        number,
        bytes,
        stride,
        offset,
        at,
    })
}

/// Hex digits, two per byte, with any white space between bytes.
fn hex(text: &str) -> Result<Vec<u8>, String> {
    let digits: Vec<u8> = text.bytes().filter(|b| !b.is_ascii_whitespace()).collect();
    if digits.len() % 2 == 1 {
        return Err(format!("{} hex digits; a byte is two", digits.len()));
    }
    digits
        .chunks(2)
        .enumerate()
        .map(|(k, pair)| {
            std::str::from_utf8(pair)
                .ok()
                .and_then(|p| u8::from_str_radix(p, 16).ok())
                .ok_or_else(|| {
                    format!(
                        "byte {k}: `{}` is not two hex digits",
                        String::from_utf8_lossy(pair)
                    )
                })
        })
        .collect()
}

/// The vertex count: `count` checked against every stream's size, or the
/// most every stream holds whole. Vertex v of a stream needs bytes up to
/// `offset + v·stride + end`, `end` the furthest any of its elements reaches.
fn count(v: Option<&Value>, elements: &[Element], streams: &[Stream]) -> Result<usize, String> {
    let asked = match v {
        None => None,
        Some(c) => {
            Some(number(Some(c), 0, MAX_VERTICES as u64).map_err(|e| format!("count: {e}"))?)
        }
    };
    let mut fits = u64::MAX;
    for (k, e) in elements.iter().enumerate() {
        let at = format!("declaration[{k}]");
        let Some(s) = streams.iter().find(|s| s.number == e.stream) else {
            return Err(format!(
                "{at}.stream: stream {} has no entry in \"streams\"",
                e.stream
            ));
        };
        let end = e.offset + e.ty.size() as u64;
        if end > s.stride {
            return Err(format!(
                "{at}.offset: {} ({}, {} bytes) reaches byte {end}, past the stride of {} of stream {}",
                e.offset,
                e.ty.name(),
                e.ty.size(),
                s.stride,
                s.number
            ));
        }
        let len = s.bytes.len() as u64;
        let held = match len.checked_sub(s.offset + end) {
            None => 0,
            Some(rest) => rest / s.stride + 1,
        };
        if let Some(n) = asked.filter(|&n| n > held) {
            let need = s.offset + (n - 1) * s.stride + end;
            return Err(format!(
                "{}: {len} bytes hold {held} vertices for {at} ({}); count {n} needs {need} (offset {} + {} × stride {} + {end})",
                s.at,
                e.attribute,
                s.offset,
                n - 1,
                s.stride
            ));
        }
        fits = fits.min(held);
    }
    let n = asked.unwrap_or(fits);
    if n > MAX_VERTICES as u64 {
        return Err(format!(
            "the streams hold {n} vertices; a list holds at most {MAX_VERTICES} (give \"count\")"
        ));
    }
    Ok(n as usize)
}

#[cfg(test)]
mod tests;
