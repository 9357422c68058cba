//! Checks `ps30::core::image::load` and `ps30::jobs::luminance::reference` against independently
//! computed values (`assets/hdr/reference.json`: official OpenEXR library,
//! OpenCV, a plain PFM reader, numpy in f64) for every image in
//! `assets/hdr/`.
//!
//! How the tolerances are derived
//! ------------------------------
//! Inputs: our decoders return bit-identical f32 pixels to the independent
//! ones. This was measured, not assumed: every channel of every pixel of all
//! seven images was compared bitwise against OpenEXR 3.5.3 (Python
//! bindings), OpenCV 5.0 `imread` and a numpy PFM reader: 0 differing
//! pixels, including the lossy DWAB files (the `exr` crate's DWAB decoder
//! reproduces the official one exactly) and the RGBE file (both the `image`
//! crate and OpenCV decode `(m, e)` as `m * 2^(e-136)`).
//!
//! Luminance: both sides evaluate `0.27 R + 0.67 G + 0.06 B` in f64 in the
//! same order from the same f32 values, so they round identically; counts,
//! min and max are compared exactly.
//!
//! Sums: the remaining difference is rounding. For `n` terms `t_i` added in
//! ANY order (any addition tree; the reference used numpy, we add left to
//! right) the computed sum is within `(n-1) u sum|t_i|` of the exact one,
//! `u = 2^-53` (Higham, ASNA 2nd ed., 4.2), so the two sides differ by at
//! most `2 (n-1) u sum|t_i|`. Each term also comes from a different `log2`
//! (numpy's vs Rust's libm); each is within 2 ulp of the exact value, i.e.
//! within `4u|t|`, so terms differ by at most `8u|t|` and the sums by a
//! further `8u sum|t_i|`. Hence
//!
//! ```text
//! tol_sum = (2 (n-1) + 8) u sum|t_i|
//! ```
//!
//! with `n` the number of terms (pixels, or texels per block including
//! padding) and `sum|t_i|` from our side ([`Reference::magnitude_sum`],
//! [`BlockSums::magnitude_sums`]; its own relative rounding error, about
//! `n u`, changes the bound only in the second order).
//!
//! Log-averages `A = 2^(S/N)`: `dA/A = ln 2 * d(S/N)`. `d(S/N)` is
//! `tol_sum / N`, plus the rounding of the division on each side,
//! `2u |S/N|`; `exp2` adds at most 2 ulp = `4u` relative per side, so
//!
//! ```text
//! tol_rel = ln2 (tol_sum / N + 2u |S/N|) + 8u
//! ```
//!
//! These are worst-case bounds; the differences measured when this test was
//! written are 4-5 orders of magnitude smaller (totals: |dS| <= 8.5e-8
//! against tolerances of 1e-4 to 1.5e-3; blocks: at most 1% of their
//! tolerance; log-averages: relative 1.4e-13 against 1.4e-10 to 8e-10).
//! Run with `--nocapture` to see them.

use crate::common;
use ps30::core::image::{load, HdrImage, ImageLimits};
use ps30::jobs::luminance::reference::{block_sums, log_average, Policy, F64_UNIT_ROUNDOFF as U};
use serde::Deserialize;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

#[derive(Deserialize)]
struct ReferenceFile {
    images: BTreeMap<String, Expected>,
}

#[derive(Deserialize)]
struct Expected {
    width: u32,
    height: u32,
    delta: f64,
    negative_pixels: u64,
    nonfinite_pixels: u64,
    min_luminance: f64,
    max_luminance: f64,
    log2_sum_abs: f64,
    log_average_abs: f64,
    log_average_clamp: f64,
    blocks: BTreeMap<String, ExpectedBlocks>,
}

#[derive(Deserialize)]
struct ExpectedBlocks {
    nx: u32,
    ny: u32,
    padded_samples: u64,
    sums: Vec<Vec<f64>>,
}

fn assets() -> PathBuf {
    common::asset("")
}

fn expected_values() -> BTreeMap<String, Expected> {
    let text = std::fs::read_to_string(assets().join("reference.json")).unwrap();
    serde_json::from_str::<ReferenceFile>(&text).unwrap().images
}

/// `(2 (n-1) + 8) u sum|t|`: see the module docs.
fn sum_tolerance(terms: u64, magnitude_sum: f64) -> f64 {
    (2.0 * (terms - 1) as f64 + 8.0) * U * magnitude_sum
}

/// `ln2 (tol_sum / N + 2u |S/N|) + 8u`: see the module docs.
fn log_average_tolerance(terms: u64, sum: f64, magnitude_sum: f64) -> f64 {
    let n = terms as f64;
    std::f64::consts::LN_2 * (sum_tolerance(terms, magnitude_sum) / n + 2.0 * U * (sum / n).abs())
        + 8.0 * U
}

fn check_within(what: &str, ours: f64, theirs: f64, tolerance: f64) {
    let difference = (ours - theirs).abs();
    assert!(
        difference <= tolerance,
        "{what}: ours {ours:e}, reference {theirs:e}, difference {difference:e} > tolerance \
         {tolerance:e}"
    );
}

fn check_image(name: &str) {
    let expected = expected_values()
        .remove(name)
        .unwrap_or_else(|| panic!("{name} has no entry in reference.json"));
    let image: HdrImage = load(&assets().join(name), &ImageLimits::default()).unwrap();
    let delta = expected.delta;

    // Exact: sizes and counts are integers; min/max are the same f64
    // expression of the same f32 values (module docs).
    assert_eq!(
        (image.width, image.height),
        (expected.width, expected.height),
        "{name}"
    );
    let abs = log_average(&image, delta, Policy::ABS);
    assert_eq!(abs.negative_pixels, expected.negative_pixels, "{name}");
    assert_eq!(abs.nonfinite_pixels, expected.nonfinite_pixels, "{name}");
    assert_eq!(
        abs.min_luminance, expected.min_luminance,
        "{name} min luminance"
    );
    assert_eq!(
        abs.max_luminance, expected.max_luminance,
        "{name} max luminance"
    );
    let stats = image.stats();
    assert_eq!(stats.negative_luminance, expected.negative_pixels, "{name}");
    assert_eq!(stats.non_finite, expected.nonfinite_pixels, "{name}");

    // No pixel is skipped here (no non-finite pixels), so N = W * H.
    assert_eq!(
        abs.samples,
        u64::from(image.width) * u64::from(image.height)
    );
    // Derived bound, not a tuned one: both sides round a sum of n = W*H
    // terms, each within (n-1) u sum|t| whatever the order, and their log2
    // implementations may differ by 8u|t| per term (module docs).
    let sum_tol = sum_tolerance(abs.samples, abs.magnitude_sum);
    check_within(
        &format!("{name} log2_sum_abs"),
        abs.log2_sum,
        expected.log2_sum_abs,
        sum_tol,
    );
    // 2^(S/N): the sum's tolerance scaled by ln2/N, plus the rounding of
    // S/N and of exp2 on both sides (module docs); compared relatively.
    let avg_tol = log_average_tolerance(abs.samples, abs.log2_sum, abs.magnitude_sum);
    let relative = |ours: f64, theirs: f64| (ours - theirs) / theirs;
    check_within(
        &format!("{name} log_average_abs (relative)"),
        relative(abs.log_average, expected.log_average_abs),
        0.0,
        avg_tol,
    );
    // The same derivation over the clamped terms (their own sum|t|).
    let clamp = log_average(&image, delta, Policy::CLAMP);
    let clamp_tol = log_average_tolerance(clamp.samples, clamp.log2_sum, clamp.magnitude_sum);
    check_within(
        &format!("{name} log_average_clamp (relative)"),
        relative(clamp.log_average, expected.log_average_clamp),
        0.0,
        clamp_tol,
    );
    println!(
        "{name}: log2_sum diff {:.3e} (tol {sum_tol:.3e}); log_average_abs rel diff {:.3e} \
         (tol {avg_tol:.3e}); log_average_clamp rel diff {:.3e} (tol {clamp_tol:.3e})",
        abs.log2_sum - expected.log2_sum_abs,
        relative(abs.log_average, expected.log_average_abs),
        relative(clamp.log_average, expected.log_average_clamp),
    );

    let sizes: Vec<&str> = expected.blocks.keys().map(String::as_str).collect();
    assert_eq!(sizes, ["125x128", "128x56"], "{name}: block sizes");
    for (size, expected_blocks) in &expected.blocks {
        let (bw, bh) = size.split_once('x').unwrap();
        let (bw, bh): (u32, u32) = (bw.parse().unwrap(), bh.parse().unwrap());
        let blocks = block_sums(&image, delta, Policy::ABS, bw, bh).unwrap();
        let what = format!("{name} {size}");
        assert_eq!(
            (blocks.nx, blocks.ny),
            (expected_blocks.nx, expected_blocks.ny),
            "{what}"
        );
        assert_eq!(
            blocks.padded_samples, expected_blocks.padded_samples,
            "{what}"
        );
        assert_eq!(
            expected_blocks.sums.len(),
            blocks.ny as usize,
            "{what} rows"
        );
        // Per block: n = bw * bh terms, padding included (each padding
        // texel is one more log2(delta) term on both sides), sum|t| of that
        // block; same derivation as for the total.
        let terms = u64::from(bw) * u64::from(bh);
        let (mut worst, mut worst_ratio) = (0.0f64, 0.0f64);
        for (row, expected_row) in expected_blocks.sums.iter().enumerate() {
            assert_eq!(expected_row.len(), blocks.nx as usize, "{what} row {row}");
            for (col, &theirs) in expected_row.iter().enumerate() {
                let ours = blocks.sums[row][col];
                let tol = sum_tolerance(terms, blocks.magnitude_sums[row][col]);
                check_within(&format!("{what} block ({row}, {col})"), ours, theirs, tol);
                worst = worst.max((ours - theirs).abs());
                worst_ratio = worst_ratio.max((ours - theirs).abs() / tol);
            }
        }
        println!("{what}: max block diff {worst:.3e}, max diff/tolerance {worst_ratio:.3e}");
    }
}

#[test]
fn every_asset_image_has_reference_values_and_a_test() {
    let on_disk: BTreeSet<String> = std::fs::read_dir(assets())
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| !name.ends_with(".json") && !name.ends_with(".md"))
        .collect();
    // A `.deflate` file (`.planes.deflate` too) is how the binary carries an
    // image of this folder (src/jobs/assets.rs, which checks it rebuilds the
    // image byte for byte): no image of its own, but its image must be here.
    let (packed, on_disk): (BTreeSet<String>, BTreeSet<String>) = on_disk
        .into_iter()
        .partition(|name| name.ends_with(".deflate"));
    for p in &packed {
        let image = p.trim_end_matches(".deflate").trim_end_matches(".planes");
        assert!(
            on_disk.contains(image),
            "{p} packs {image}, which is not in assets/hdr"
        );
    }
    let in_json: BTreeSet<String> = expected_values().into_keys().collect();
    let tested: BTreeSet<String> = TESTED.iter().map(|s| s.to_string()).collect();
    assert_eq!(on_disk, in_json, "images in assets/hdr vs reference.json");
    assert_eq!(on_disk, tested, "images in assets/hdr vs the tests below");
}

use common::IMAGES as TESTED;

#[test]
fn city_exr_dwab() {
    check_image("city.exr");
}

#[test]
fn courtyard_exr_dwab() {
    check_image("courtyard.exr");
}

#[test]
fn courtyard_1280x1024_exr_half_piz() {
    check_image("courtyard_1280x1024.exr");
}

#[test]
fn forest_exr_dwab() {
    check_image("forest.exr");
}

#[test]
fn forest_hdr_rgbe() {
    check_image("forest.hdr");
}

#[test]
fn sunset_exr_dwab() {
    check_image("sunset.exr");
}

#[test]
fn sunset_pfm() {
    check_image("sunset.pfm");
}
