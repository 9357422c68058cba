//! Cube, volume and DXT textures from DDS files through the command line:
//! `run --inputs`, draw lists, and hostile texture files. Expected values
//! come from the bytes `tools/textures/make.py` writes (worked out beside
//! each test), not from the emulator.

use crate::common::bin;

use bin::{in_repo, repo, stderr, stdout};
use ps30::jobs::render::file;

/// `ps30 run SHADER --inputs INPUTS --target 1x1 --target-format f16
/// --json`: oC0's stored channels (half precision).
fn run_json(shader: &str, inputs: &str) -> Vec<f64> {
    let o = in_repo(&[
        "run",
        shader,
        "--inputs",
        inputs,
        "--target",
        "1x1",
        "--target-format",
        "f16",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    v["outputs"][0]["stored"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["mean"].as_f64().unwrap())
        .collect()
}

/// `x` rounded to half precision, as the f16 target stores it.
fn half(x: f64) -> f64 {
    half::f16::from_f64(x).to_f64()
}

#[test]
fn run_inputs_reads_a_cube_face_from_a_dds_file() {
    // Direction (0, −1, 0): face −Y (index 3), level 0 = (40·4, 0, 0)/255.
    let c = run_json("asm/textures/cube-lod.psh", "asm/textures/cube.json");
    assert_eq!(c, [half(160.0 / 255.0), 0.0, 0.0, 1.0]);
}

#[test]
fn run_inputs_volume_linear_at_the_centre_is_the_mean_of_eight_texels() {
    // Red 20·(x + 2y + 4z) over the eight texels: mean 20·3.5 = 70; green
    // 255·z: mean 127.5. All weights are ½, exact in f32.
    let c = run_json("asm/textures/volume.psh", "asm/textures/volume.json");
    assert_eq!(c, [half(70.0 / 255.0), half(0.5), 0.0, 1.0]);
}

#[test]
fn run_inputs_dxt1_texel_is_the_two_thirds_blend() {
    // Texel (2, 0) has index 2: ⅔·red + ⅓·blue = (170, 0, 85).
    let c = run_json("asm/textures/dxt1.psh", "asm/textures/dxt1.json");
    assert_eq!(c, [half(170.0 / 255.0), 0.0, half(85.0 / 255.0), 1.0]);
}

#[test]
fn a_draw_list_reads_dds_cubes_and_volumes_with_their_states() {
    let loaded = file::read(
        &repo().join("drawlists/textures.json"),
        &file::FileLimits::default(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let kinds: Vec<_> = loaded
        .list
        .textures
        .iter()
        .map(|t| t.file.as_ref().map(|f| (f.kind(), f.levels())))
        .collect();
    assert_eq!(kinds, [Some(("cube", 2)), Some(("volume", 1))]);
    let o = in_repo(&["render", "drawlists/textures.json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    // −Z face (index 5), level 1 authored as (0, 40·6, 0): G = 240/255.
    assert!(out.contains("G 0.941176…0.941176"), "{out}");
    assert!(out.contains("R 0.27451…0.27451"), "{out}");
}

#[test]
fn hostile_texture_files_are_refused_with_the_place() {
    let dir = tempfile_dir();
    // A cube header claiming 2 levels of 2×2 faces, with the texels cut.
    let bytes = std::fs::read(repo().join("assets/textures/faces.dds")).unwrap();
    std::fs::write(dir.join("cut.dds"), &bytes[..bytes.len() - 7]).unwrap();
    std::fs::write(
        dir.join("in.json"),
        r#"{"samplers": {"s0": {"texture": "cut.dds"}}}"#,
    )
    .unwrap();
    let o = in_repo(&[
        "run",
        "asm/textures/cube-lod.psh",
        "--inputs",
        dir.join("in.json").to_str().unwrap(),
        "--target",
        "1x1",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("samplers.s0.texture") && e.contains("cut.dds") && e.contains("120 bytes"),
        "{e}"
    );
    // A 2D texture on a dcl_cube sampler.
    let o = in_repo(&[
        "run",
        "asm/textures/cube-lod.psh",
        "--inputs",
        repo().join("asm/textures/dxt1.json").to_str().unwrap(),
        "--target",
        "1x1",
        "--const",
        "c0=1,0,0,0",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
    assert!(stderr(&o).contains("declared dcl_cube"), "{}", stderr(&o));
}

/// A fresh directory under target/ for one test's files.
fn tempfile_dir() -> std::path::PathBuf {
    let d = repo()
        .join("target/test-textures")
        .join(format!("{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}
