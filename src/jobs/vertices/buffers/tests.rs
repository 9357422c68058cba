//! Vertex declarations and buffers read field by field: a mixed layout
//! decoded from bytes written here, and every malformed declaration or
//! stream refused naming its field.

use super::super::parse_in;
use std::path::Path;

fn parse(text: &str) -> Result<crate::core::emu::vertex::Vertices, String> {
    parse_in(text, Path::new("/nonexistent-ps30-dir"))
}

#[test]
fn a_mixed_stream_and_a_second_stream_decode_by_type() {
    // Stream 0, stride 12: FLOAT2 position at 0 (x, y), D3DCOLOR at 8.
    // Vertex 0: (0.5, −1) = 0x3F000000, 0xBF800000; colour 0xFF102030.
    // Vertex 1: (2, 0.25) = 0x40000000, 0x3E800000; colour 0x00FFFFFF.
    // Stream 1, offset 2, stride 4: SHORT2N texcoord1 (16384, −32767).
    let text = r#"{"declaration": [
        {"stream": 0, "offset": 0, "type": "FLOAT2", "usage": "position"},
        {"stream": 0, "offset": 8, "type": "D3DDECLTYPE_D3DCOLOR", "method": "DEFAULT", "usage": "D3DDECLUSAGE_COLOR"},
        {"stream": 1, "offset": 0, "type": 9, "usage": 5, "usage_index": 1},
        {"stream": 255, "offset": 0, "type": "UNUSED"}],
      "streams": [
        {"stream": 0, "hex": "0000003f 000080bf 302010ff  00000040 0000803e ffffff00", "stride": 12},
        {"stream": 1, "hex": "abcd 0040 0180  0040 0180", "stride": 4, "offset": 2}]}"#;
    let v = parse(text).unwrap();
    assert_eq!(
        v.count, 2,
        "stream 0 holds 24/12 = 2; stream 1 (10 − 2)/4 = 2"
    );
    let names: Vec<String> = v.attributes.iter().map(|(a, _)| a.to_string()).collect();
    assert_eq!(names, ["position0", "color0", "texcoord1"]);
    assert_eq!(
        v.attributes[0].1,
        [[0.5, -1.0, 0.0, 1.0], [2.0, 0.25, 0.0, 1.0]]
    );
    // 0xFF102030: R 0x10, G 0x20, B 0x30, A 0xFF.
    assert_eq!(
        v.attributes[1].1[0],
        [16.0 / 255.0, 32.0 / 255.0, 48.0 / 255.0, 1.0]
    );
    assert_eq!(v.attributes[1].1[1], [1.0, 1.0, 1.0, 0.0]);
    // 0x4000 = 16384, 0x8001 = −32767: 16384/32767 and −1.
    assert_eq!(v.attributes[2].1[1], [16384.0 / 32767.0, -1.0, 0.0, 1.0]);
}

#[test]
fn count_takes_the_vertices_asked_for_and_the_fewest_otherwise() {
    // Stride 8, FLOAT1 at 0: 20 bytes hold vertices at 0, 8, 16 (the last
    // needs bytes 16–19 only): 3 — the padding of the last vertex is not
    // required.
    let list = |count: &str| {
        format!(
            r#"{{"declaration": [{{"offset": 0, "type": "FLOAT1", "usage": "psize"}}],
               "streams": [{{"hex": "{}", "stride": 8}}]{count}}}"#,
            "0000803f".repeat(5)
        )
    };
    assert_eq!(parse(&list("")).unwrap().count, 3);
    assert_eq!(parse(&list(r#", "count": 2"#)).unwrap().count, 2);
    let e = parse(&list(r#", "count": 4"#)).unwrap_err();
    assert!(e.contains("streams[0]: 20 bytes hold 3 vertices"), "{e}");
    assert!(e.contains("count 4 needs 28"), "{e}");
}

#[test]
fn hostile_declarations_and_streams_are_refused_naming_the_field() {
    let decl = r#"[{"offset": 0, "type": "FLOAT4", "usage": "position"}]"#;
    let ok_stream = r#"[{"hex": "00000000000000000000000000000000", "stride": 16}]"#;
    let with = |decl: &str, streams: &str, extra: &str| {
        format!(r#"{{"declaration": {decl}, "streams": {streams}{extra}}}"#)
    };
    let cases = [
        (with(decl, ok_stream, ""), ""),
        (
            with(decl, r#"[{"hex": "00", "stride": 0}]"#, ""),
            "streams[0].stride: 0",
        ),
        (
            with(r#"[{"offset": 4, "type": "FLOAT4", "usage": "position"}]"#, ok_stream, ""),
            "declaration[0].offset: 4 (FLOAT4, 16 bytes) reaches byte 20, past the stride of 16",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT5", "usage": "position"}]"#, ok_stream, ""),
            "declaration[0].type: `FLOAT5` is not a D3DDECLTYPE",
        ),
        (
            with(r#"[{"offset": 0, "type": 18, "usage": "position"}]"#, ok_stream, ""),
            "declaration[0].type: 18",
        ),
        (
            with(
                r#"[{"offset": 0, "type": "FLOAT1", "usage": "texcoord", "usage_index": 2},
                    {"offset": 4, "type": "FLOAT1", "usage": "TEXCOORD", "usage_index": 2}]"#,
                ok_stream,
                "",
            ),
            "declaration[1].usage: texcoord2 is declared twice (declaration[0] too)",
        ),
        (
            with(
                r#"[{"offset": 0, "type": "UNUSED"}, {"offset": 0, "type": "FLOAT1", "usage": "position"}]"#,
                ok_stream,
                "",
            ),
            "declaration[0].type: UNUSED (D3DDECL_END) ends the declaration, and 1 elements follow it",
        ),
        (
            with(r#"[{"offset": 0, "type": "UNUSED"}]"#, ok_stream, ""),
            "declaration: no elements",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "colour"}]"#, ok_stream, ""),
            "declaration[0].usage: `colour`",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "color", "usage_index": 16}]"#, ok_stream, ""),
            "declaration[0].usage_index: 16",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "color", "method": "UV"}]"#, ok_stream, ""),
            "declaration[0].method",
        ),
        (
            with(r#"[{"type": "FLOAT1", "usage": "color"}]"#, ok_stream, ""),
            "declaration[0].offset: missing",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "color", "stream": 16}]"#, ok_stream, ""),
            "declaration[0].stream: 16",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "color", "stream": 1}]"#, ok_stream, ""),
            "declaration[0].stream: stream 1 has no entry",
        ),
        (
            with(r#"[{"offset": 0, "type": "FLOAT1", "usage": "color", "size": 4}]"#, ok_stream, ""),
            "declaration[0]: unknown field `size`",
        ),
        (
            with(decl, r#"[{"hex": "000", "stride": 16}]"#, ""),
            "streams[0].hex: 3 hex digits",
        ),
        (
            with(decl, r#"[{"hex": "zz", "stride": 16}]"#, ""),
            "streams[0].hex: byte 0: `zz`",
        ),
        (
            with(decl, r#"[{"stride": 16}]"#, ""),
            "streams[0]: no bytes",
        ),
        (
            with(decl, r#"[{"hex": "00", "file": "a.vb", "stride": 16}]"#, ""),
            "not both",
        ),
        (
            with(decl, r#"[{"file": "missing.vb", "stride": 16}]"#, ""),
            "streams[0].file: /nonexistent-ps30-dir/missing.vb",
        ),
        (
            with(decl, r#"[{"hex": "00", "stride": 16}, {"stream": 0, "hex": "00", "stride": 16}]"#, ""),
            "streams[1].stream: stream 0 is given twice",
        ),
        (
            with(decl, r#"[{"hex": "00", "stride": 16, "offset": 18446744073709551615}]"#, ""),
            "streams[0].offset",
        ),
        (
            with(decl, r#"[{"hex": "00", "stride": 16, "offset": 4}]"#, r#", "count": 1"#),
            "streams[0]: 1 bytes hold 0 vertices",
        ),
        (
            with(decl, ok_stream, r#", "count": 1099511627776"#),
            "count: 1099511627776 is not a whole number from 0 to 1048576",
        ),
        (
            with(decl, ok_stream, r#", "count": 1048576"#),
            "streams[0]: 16 bytes hold 1 vertices",
        ),
        (
            r#"{"streams": [], "count": 3}"#.to_string(),
            "\"streams\" and \"count\" go with a \"declaration\"",
        ),
        (
            format!(r#"{{"declaration": {decl}, "attributes": {{}}}}"#),
            "give one of",
        ),
    ];
    for (text, want) in &cases {
        match parse(text) {
            Ok(v) => assert!(want.is_empty(), "{text}: read {} vertices", v.count),
            Err(e) => assert!(!want.is_empty() && e.contains(want), "{text}: {e}"),
        }
    }
}

#[test]
fn many_overlapping_elements_cannot_multiply_memory() {
    // 64 elements overlapping on a 4-byte stride (allowed) over a buffer of
    // 65,536 vertices would decode 4,194,304 values: the most allowed; one
    // vertex more is refused before anything is decoded.
    let usages = ["texcoord", "color", "normal", "tangent"];
    let elements: Vec<String> = (0..64)
        .map(|k| {
            format!(
                r#"{{"offset": 0, "type": "D3DCOLOR", "usage": "{}", "usage_index": {}}}"#,
                usages[k / 16],
                k % 16
            )
        })
        .collect();
    let list = |n: usize| {
        format!(
            r#"{{"declaration": [{}], "streams": [{{"hex": "{}", "stride": 4}}]}}"#,
            elements.join(","),
            "00".repeat(4 * n)
        )
    };
    assert_eq!(parse(&list(65_536)).unwrap().count, 65_536);
    let e = parse(&list(65_537)).unwrap_err();
    assert!(e.starts_with("count: 65537 vertices × 64 elements"), "{e}");
}
