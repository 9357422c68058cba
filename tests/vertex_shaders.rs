//! Vertex shaders run: shaders Microsoft's HLSL compiler wrote for vs_2_0
//! and vs_3_0 (`tests/oracle/corpus/hlsl/vertex/`, their bytecode the
//! oracle's fixtures) over small vertex lists, against outputs worked out
//! by hand beside each test. Every value is exact in f32 (sums and products
//! of small dyadic fractions), so the comparisons are exact. Hostile vertex
//! lists are refused with exit status 2 and a message naming the field.

use super::common::bin::{ps30, stderr, stdout};
use serde_json::Value;
use std::path::Path;

const FIXTURES: &str = "tests/oracle/fixtures/hlsl/vertex";

/// One vertex's output values, in the order of the outputs.
type Outputs = Vec<[f64; 4]>;

/// Runs `ps30 run SHADER --vertices LIST --json ARGS` on a bytecode fixture
/// with the vertex list `list` (JSON text): (register, semantic) of each
/// output and per vertex the output values.
fn run(shader: &str, list: &str, args: &[&str]) -> (Vec<(String, Value)>, Vec<Outputs>) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("vertices.json");
    std::fs::write(&path, list).unwrap();
    let fxo = super::common::bin::repo().join(FIXTURES).join(shader);
    let mut all = vec![
        "run",
        fxo.to_str().unwrap(),
        "--vertices",
        path.to_str().unwrap(),
        "--json",
    ];
    all.extend_from_slice(args);
    let o = ps30(&all, dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let slots = v["outputs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["register"].as_str().unwrap().to_string(),
                s["semantic"].clone(),
            )
        })
        .collect();
    let values = v["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|vx| {
            vx["outputs"]
                .as_array()
                .unwrap()
                .iter()
                .map(|o| std::array::from_fn(|c| o[c].as_f64().unwrap()))
                .collect()
        })
        .collect();
    (slots, values)
}

/// The same run on the GPU backend (`--backend gpu`), when a device exists:
/// every value here is exact in f32, so the translation must give the
/// emulator's outputs bit for bit (and the hand-worked values with them).
fn same_on_gpu(test: &str, shader: &str, list: &str, args: &[&str], emulated: &[Outputs]) {
    if super::common::gpu::gpu(test).is_none() {
        return;
    }
    let mut all = args.to_vec();
    all.extend(["--backend", "gpu"]);
    let (_, on_gpu) = run(shader, list, &all);
    assert_eq!(on_gpu, emulated, "{test}: the GPU backend's outputs");
}

#[test]
fn a_vs_2_0_transform_compiled_by_microsoft() {
    // transform.hlsl: oPos = mul(p, wvp) (dp4 with the columns c0-c3),
    // oD0 = saturate(dot(n, light)), oT0.xy = 2 uv.
    let list = r#"{"attributes": {
        "position0": [[1, 2, 3, 1], [0, 0, 0, 1]],
        "normal0": [[0.25, 0.5, 0], [-1, 0, 0]],
        "texcoord0": [[0.25, 0.75], [1, 1]]}}"#;
    let consts = [
        "--const",
        "c0=2,0,0,1",
        "--const",
        "c1=0,3,0,0",
        "--const",
        "c2=0,0,1,0",
        "--const",
        "c3=0,0,0,1",
        "--const",
        "c4=0.5,0.5,0.5,0",
    ];
    let (slots, v) = run("transform.hlsl.fxo", list, &consts);
    let names: Vec<&str> = slots.iter().map(|(r, _)| r.as_str()).collect();
    assert_eq!(names, ["oPos", "oD0", "oT0"]);
    assert_eq!(slots[1].1, "color0");
    // vertex 0: x = 2·1 + 1·1 = 3, y = 3·2 = 6, z = 3, w = 1;
    // dot((0.25, 0.5, 0), (0.5, 0.5, 0.5)) = 0.375; uv · 2 = (0.5, 1.5).
    assert_eq!(v[0][0], [3.0, 6.0, 3.0, 1.0]);
    assert_eq!(v[0][1], [0.375; 4]);
    assert_eq!(v[0][2][..2], [0.5, 1.5]);
    // vertex 1: x = 0 + 1 = 1; dot = -0.5, saturated to 0; uv · 2 = (2, 2).
    assert_eq!(v[1][0], [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(v[1][1], [0.0; 4]);
    assert_eq!(v[1][2][..2], [2.0, 2.0]);
    same_on_gpu("transform", "transform.hlsl.fxo", list, &consts, &v);
}

#[test]
fn vs_3_0_skinning_indexes_the_palette_through_a0() {
    // palette.hlsl: bone i is c[3i] … c[3i + 2] (the columns of a float4x3),
    // the index (int)BLENDINDICES, truncated; s = w·a + (1 − w)·b; vp = identity.
    let list = r#"{"vertices": [
        {"position0": [1, 1, 1, 1], "blendindices0": [1, 2], "blendweight0": [0.25], "texcoord0": [0.5, 0.25]},
        {"position0": [1, 1, 1, 1], "blendindices0": [0.9, 1.999], "blendweight0": [1], "texcoord0": [0, 1]}]}"#;
    let mut consts: Vec<String> = Vec::new();
    let rows = [
        "1,0,0,0", "0,1,0,0", "0,0,1,0", // bone 0: identity
        "1,0,0,4", "0,1,0,0", "0,0,1,0", // bone 1: translation by (4, 0, 0)
        "2,0,0,0", "0,2,0,0", "0,0,2,0", // bone 2: scale by 2
    ];
    for (i, r) in rows.iter().enumerate() {
        consts.extend(["--const".to_string(), format!("c{i}={r}")]);
    }
    for (i, r) in ["1,0,0,0", "0,1,0,0", "0,0,1,0", "0,0,0,1"]
        .iter()
        .enumerate()
    {
        consts.extend(["--const".to_string(), format!("c{}={r}", 24 + i)]);
    }
    let args: Vec<&str> = consts.iter().map(String::as_str).collect();
    let (slots, v) = run("palette.hlsl.fxo", list, &args);
    assert_eq!(slots[0], ("o0".to_string(), Value::from("position0")));
    // vertex 0: a = bone 1 · p = (5, 1, 1), b = bone 2 · p = (2, 2, 2);
    // 0.25·a + 0.75·b = (1.25 + 1.5, 0.25 + 1.5, 0.25 + 1.5) = (2.75, 1.75, 1.75).
    assert_eq!(v[0][0], [2.75, 1.75, 1.75, 1.0]);
    assert_eq!(v[0][1][..2], [0.5, 0.25]);
    // vertex 1: (int)0.9 = 0, so a = p (weight 1; b does not count).
    assert_eq!(v[1][0], [1.0, 1.0, 1.0, 1.0]);
    same_on_gpu("palette", "palette.hlsl.fxo", list, &args, &v);
}

#[test]
fn vs_3_0_loop_over_a_uniform_count_reads_c_al() {
    // offsets.hlsl: o0 = p + c0 + … + c[count − 1]; o1 = sign(p).
    let list = r#"{"attributes": {"position0": [[1, -2, 0, 4]]}}"#;
    let args = [
        "--int",
        "i0=3,0,1,0",
        "--const",
        "c0=1,0,0,0",
        "--const",
        "c1=0,10,0,0",
        "--const",
        "c2=0,0,100,0",
        "--const",
        "c3=1000,1000,1000,1000",
    ];
    let (slots, v) = run("offsets.hlsl.fxo", list, &args);
    assert_eq!(slots[1], ("o1".to_string(), Value::from("texcoord1")));
    // three iterations: (1 + 1, −2 + 10, 0 + 100, 4); c3 is never added.
    assert_eq!(v[0][0], [2.0, 8.0, 100.0, 4.0]);
    assert_eq!(v[0][1], [1.0, -1.0, 0.0, 1.0]);
    same_on_gpu("offsets", "offsets.hlsl.fxo", list, &args, &v);
}

#[test]
fn profile_counts_each_vertex_as_the_cost_model_does() {
    let root = super::common::bin::repo();
    let o = ps30(
        &[
            "profile",
            "tests/oracle/fixtures/hlsl/vertex/offsets.hlsl.fxo",
            "--vertices",
            "asm/vs/skin.json",
            "--int",
            "i0=5,0,1,0",
            "--json",
        ],
        root,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    // mov, 5 × (loop 3 + add 1 + endloop 2), mov, slt, slt, add: 1 + 30 + 4.
    assert_eq!(v["executed_emulated"], serde_json::json!([35, 35, 35]));
    assert_eq!(v["executed"], serde_json::json!({"min": 35, "max": 35}));
    assert_eq!(v["counts_agree"], true);
}

/// The cost model and the run see the same constants: an `i#` the command
/// does not set is refused by name, never counted as if it were 0.
#[test]
fn profile_refuses_an_integer_constant_nobody_set() {
    let root = super::common::bin::repo();
    let o = ps30(
        &[
            "profile",
            "tests/oracle/fixtures/hlsl/vertex/offsets.hlsl.fxo",
            "--vertices",
            "asm/vs/skin.json",
            "--json",
        ],
        root,
    );
    assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
    assert!(stderr(&o).contains("i0"), "{}", stderr(&o));
}

#[test]
fn hostile_vertex_lists_are_refused_naming_the_field() {
    let dir = tempfile::tempdir().unwrap();
    let many = format!(
        r#"{{"attributes": {{"position0": [{}[0]]}}}}"#,
        "[0],".repeat(1 << 20)
    );
    let cases: [(&str, &str); 5] = [
        (
            r#"{"attributes": {"position0": [[1, 2]], "normal0": [[1], [2]]}}"#,
            "attributes.position0: 1 values, and the attributes before it have 2",
        ),
        (
            r#"{"attributes": {"position0": [[1, 2, 3, 4, 5]]}}"#,
            "attributes.position0[0]: 5 components",
        ),
        (r#"{"attributes": {"position0": [[NaN]]}}"#, "not JSON"),
        (
            r#"{"vertices": [{"position0": [1]}, {"position0": [1e39]}]}"#,
            "vertices[1].position0: component 0",
        ),
        (
            &many,
            "attributes.position0: 1048577 vertices; a list holds at most 1048576",
        ),
    ];
    let shader = Path::new(env!("CARGO_MANIFEST_DIR")).join("asm/vs/skin.vsh");
    for (i, (text, want)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("v{i}.json"));
        std::fs::write(&path, text).unwrap();
        let o = ps30(
            &[
                "run",
                shader.to_str().unwrap(),
                "--vertices",
                path.to_str().unwrap(),
            ],
            dir.path(),
        );
        assert_eq!(o.status.code(), Some(2), "case {i}");
        let e = stderr(&o);
        assert!(
            e.contains(want) && e.contains(&format!("v{i}.json")),
            "case {i}: {e}"
        );
    }
    // a list without the attribute a dcl reads
    let path = dir.path().join("short.json");
    std::fs::write(&path, r#"{"attributes": {"position0": [[0, 0, 0, 1]]}}"#).unwrap();
    let o = ps30(
        &[
            "run",
            shader.to_str().unwrap(),
            "--vertices",
            path.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("reads v1 (dcl_texcoord0) and the vertex list has no texcoord0"),
        "{}",
        stderr(&o)
    );
}
