//! Tone mapping: the shader in the emulator against the f64 reference on
//! every shared image, black and negative pixels, the white point, and the
//! `ps30 tonemap` command's exit codes and output.
//!
//! The bound every comparison uses is derived in `src/jobs/tonemap/mod.rs` from the
//! shader's f32 arithmetic; nothing here widens it. The tests that perturb
//! an output or the shader show that the check does fail when it should.

use crate::common;

use common::{asset, IMAGES};
use ps30::core::image::{HdrImage, ImageLimits};
use ps30::jobs::luminance::ShaderSource;
use ps30::jobs::tonemap::{self, Settings, WhiteSource};

fn load(name: &str) -> HdrImage {
    ps30::core::image::load(&asset(name), &ImageLimits::default()).unwrap()
}

fn run(image: &HdrImage, settings: &Settings) -> tonemap::ToneMapped {
    run_pixels(image, settings).0
}

/// The run and the tone-mapped pixels (linear RGBA, row-major).
fn run_pixels(image: &HdrImage, settings: &Settings) -> (tonemap::ToneMapped, Vec<[f32; 4]>) {
    tonemap::run(image, settings, &|_, _| {}).unwrap()
}

#[test]
fn the_shader_agrees_with_the_reference_on_every_shared_image() {
    for name in IMAGES {
        let img = load(name);
        let t = run(&img, &Settings::default());
        let c = &t.check;
        assert!(t.luminance.all_agree(), "{name}: L̄w disagrees");
        assert!(t.cost.counts_agree && t.cost.within_limits, "{name}");
        assert_eq!(
            t.cost.executed_emulated,
            Some(ps30::core::cost::Range::exact(17))
        );
        assert_eq!(c.outside_bound, 0, "{name}: {:?}", c.first_outside);
        assert_eq!(c.unexplained_8bit, 0, "{name}");
        assert_eq!(c.checked_pixels, img.pixels.len() as u64, "{name}");
        assert!(c.max_error <= c.max_error_bound, "{name}");
        assert!(c.largest_bound_fraction <= 1.0, "{name}");
        // Off-by-one codes are counted, and rare: each needs a linear value
        // within about 2e-6 of a rounding boundary.
        assert!(
            c.mismatched_8bit_pixels * 1000 < c.checked_pixels,
            "{name}: {} of {} pixels",
            c.mismatched_8bit_pixels,
            c.checked_pixels
        );
        assert!(t.all_agree(), "{name}");
        // The shader sees exactly the f32 L̄w of pass 2's target.
        assert_eq!(t.operator.log_average, t.luminance.log_average);
        assert_eq!(t.operator.white_source, WhiteSource::SceneMaximum);
        assert_eq!(Some(t.operator.white), tonemap::max_luminance(&img));
    }
}

#[test]
fn negative_luminance_pixels_of_the_shared_images_are_black() {
    // courtyard.exr has 354 pixels with negative luminance (DWAB ringing).
    let img = load("courtyard.exr");
    let (t, linear) = run_pixels(&img, &Settings::default());
    let mut negative = 0;
    for (p, o) in img.pixels.iter().zip(&linear) {
        if ps30::core::image::luminance(*p) < 0.0 {
            negative += 1;
            assert_eq!(&o[..3], &[0.0, 0.0, 0.0], "{p:?}");
        }
    }
    assert_eq!(negative, 354);
    assert_eq!(t.check.negative_luminance_pixels, 354);
}

/// One 125×128 block (no BORDER padding, so pass 1 sums real pixels only):
/// a grey ramp, black, negative, cancelling and very bright pixels, the
/// rest mid-grey.
fn synthetic() -> HdrImage {
    let mut pixels = Vec::new();
    for i in 0..64 {
        let v = 0.01 * 1.2f32.powi(i);
        pixels.push([v, v, v, 1.0]);
    }
    pixels.push([0.0, 0.0, 0.0, 1.0]); // black
    pixels.push([0.2, -0.5, 0.1, 1.0]); // negative luminance
    pixels.push([-0.06, 0.0, 0.27, 1.0]); // luminance ≈ 0 by cancellation
    pixels.push([8.0, 0.5, 0.1, 1.0]); // saturated red
    pixels.resize(125 * 128, [0.3, 0.3, 0.3, 1.0]);
    HdrImage {
        width: 125,
        height: 128,
        pixels,
    }
}

#[test]
fn black_and_negative_pixels_are_exactly_black() {
    let img = synthetic();
    let (t, linear) = run_pixels(&img, &Settings::default());
    assert!(t.all_agree(), "{:?}", t.check.first_outside);
    assert_eq!(&linear[64][..3], &[0.0; 3], "black");
    assert_eq!(&linear[65][..3], &[0.0; 3], "negative luminance");
    assert_eq!(t.check.zero_luminance_pixels, 1);
    assert_eq!(t.check.negative_luminance_pixels, 1);
    // The cancelling pixel: f32 cannot tell its luminance's sign, so black
    // and the scaled colour are both inside its bound.
    assert_eq!(t.check.sign_ambiguous_pixels, 1);
    // Alpha passes through, saturated.
    assert!(linear.iter().all(|p| p[3] == 1.0));
}

#[test]
fn without_the_cmp_negative_pixels_light_up_and_the_check_fails() {
    // The shader's explicit Lw ≤ 0 rule is needed: drop it and courtyard's
    // negative pixels show colour, which the reference (black) refuses.
    let (name, text) = ps30::jobs::bundled::TONEMAP_REINHARD.listing();
    let without = text.replace("cmp r2.z, -r2.x, c0.z, r2.z", "mov r2.z, r2.z");
    assert_ne!(without, text);
    let settings = Settings {
        shader: ShaderSource::new(name, without),
        ..Settings::default()
    };
    let t = run(&load("courtyard.exr"), &settings);
    assert!(t.check.outside_bound > 0);
    assert!(!t.all_agree());
}

#[test]
fn a_perturbed_output_is_caught() {
    let img = synthetic();
    let (t, mut linear) = run_pixels(&img, &Settings::default());
    // A mid-grey channel moved by 1e-5: far beyond its ~1e-6 bound.
    let i = 30;
    assert!(linear[i][1] > 0.05 && linear[i][1] < 0.95);
    linear[i][1] += 1e-5;
    let c = tonemap::crosscheck(&t.operator, &img, &linear);
    assert_eq!(c.outside_bound, 1);
    assert!(!c.agree());
}

#[test]
fn the_white_point_maps_to_white() {
    let img = synthetic();
    // Default: the scene's largest luminance (the saturated red pixel).
    let t = run(&img, &Settings::default());
    let max = tonemap::max_luminance(&img).unwrap();
    assert_eq!(t.operator.white, max);
    // Given: the grey pixel whose luminance is W is white (to within the
    // bound, and in 8 bits exactly), brighter ones are exactly 1 and
    // darker ones are below 1 (the ramp's steps are 20 % apart).
    let white = ps30::core::image::luminance(img.pixels[40]);
    let (t, linear) = run_pixels(
        &img,
        &Settings {
            white: Some(white),
            ..Settings::default()
        },
    );
    assert!(t.all_agree());
    assert_eq!(t.operator.white_source, WhiteSource::Given);
    assert!((linear[40][0] - 1.0).abs() < 1e-5, "{:?}", linear[40]);
    assert_eq!(tonemap::srgb8(linear[40][0] as f64), 255);
    for (i, p) in linear.iter().enumerate().take(64).skip(41) {
        assert_eq!(&p[..3], &[1.0; 3], "pixel {i} is brighter than W");
    }
    for (i, p) in linear.iter().enumerate().take(40) {
        assert!(p[0] < 0.999, "pixel {i}: {p:?}");
    }
    // Infinite: L / (1 + L) never reaches 1 in the reference.
    let t = run(
        &img,
        &Settings {
            white: Some(f64::INFINITY),
            ..Settings::default()
        },
    );
    assert!(t.all_agree());
    assert_eq!(t.operator.c0y(), 0.0);
    let brightest = ps30::jobs::tonemap::reference_pixel(&t.operator, img.pixels[63]);
    assert!(brightest[0] < 1.0 && brightest[0] > 0.9, "{brightest:?}");
}

#[test]
fn results_do_not_depend_on_bands_or_threads() {
    let img = load("sunset.pfm");
    let (a, a_linear) = run_pixels(&img, &Settings::default());
    let (b, b_linear) = run_pixels(
        &img,
        &Settings {
            band_rows: 2,
            threads: Some(1),
            ..Settings::default()
        },
    );
    assert!(a_linear == b_linear);
    // The cross-check, made band by band, is the same scan whatever the bands.
    assert_eq!(format!("{:?}", a.check), format!("{:?}", b.check));
}

#[test]
fn nan_pixels_are_refused_not_a_panic() {
    let mut img = synthetic();
    img.pixels[3] = [f32::NAN, 0.0, 0.0, 1.0];
    let err = tonemap::run(&img, &Settings::default(), &|_, _| {}).unwrap_err();
    assert!(
        matches!(err, tonemap::TonemapError::LogAverage { .. }),
        "{err}"
    );
}

// ---- the command ----

use crate::common::bin;
use bin::{ps30, repo, stderr};

#[test]
fn tonemap_writes_the_png_the_library_computes() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("city.png");
    let o = ps30(
        &[
            "tonemap",
            "assets/hdr/city.exr",
            "-o",
            out.to_str().unwrap(),
            "--json",
        ],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for key in [
        "log_average",
        "key",
        "white",
        "pixels",
        "max_error",
        "max_error_bound",
        "mismatched_8bit_channels",
        "negative_luminance_pixels",
        "agree",
    ] {
        assert!(!v[key].is_null(), "missing {key}");
    }
    assert_eq!(v["agree"], true);
    assert_eq!(v["key"], 0.18);
    assert_eq!(v["pixels"], 1024 * 512);
    assert_eq!(v["white_source"], "scene_maximum");
    let decoded = image::open(&out).unwrap().to_rgb8();
    assert_eq!(decoded.dimensions(), (1024, 512));
    let (t, linear) = run_pixels(&load("city.exr"), &Settings::default());
    assert_eq!(decoded.into_raw(), tonemap::to_srgb8(&linear));
    assert_eq!(v["log_average"], t.luminance.log_average);
    // Nothing on stderr: no progress bar without a terminal.
    assert_eq!(stderr(&o), "");
}

/// The float outputs, written band by band while the image is drawn, are
/// the whole-image writer's files of the library's result, byte for byte.
#[test]
fn tonemap_float_outputs_are_the_whole_image_writers_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let (t, linear) = run_pixels(&load("sunset.pfm"), &Settings::default());
    let rgb: Vec<[f32; 3]> = linear.iter().map(|p| [p[0], p[1], p[2]]).collect();
    for ext in ["exr", "pfm", "hdr"] {
        let out = dir.path().join(format!("banded.{ext}"));
        let o = ps30(
            &[
                "tonemap",
                "assets/hdr/sunset.pfm",
                "-o",
                out.to_str().unwrap(),
            ],
            repo(),
        );
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let whole = dir.path().join(format!("whole.{ext}"));
        ps30::core::image::write_rgb_float(&whole, t.width, t.height, &rgb).unwrap();
        let (a, b) = (std::fs::read(&out).unwrap(), std::fs::read(&whole).unwrap());
        assert!(a == b, ".{ext}: {} against {} bytes", a.len(), b.len());
    }
}

#[test]
fn tonemap_text_names_the_cross_check_and_has_no_colour_codes_in_a_pipe() {
    let o = ps30(
        &["tonemap", "assets/hdr/forest.hdr", "--key", "0.36"],
        repo(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("key a = 0.36"), "{out}");
    assert!(
        out.contains("cross-check against the f64 reference"),
        "{out}"
    );
    assert!(out.contains(": agree"), "{out}");
    assert!(!out.contains('\x1b'), "{out}");
}

#[test]
fn tonemap_bad_values_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.png");
    let img = asset("sunset.exr");
    let img = img.to_str().unwrap();
    for args in [
        vec!["--key", "0"],
        vec!["--key", "nan"],
        vec!["--key", "-0.18"],
        vec!["--key", "inf"],
        vec!["--white", "-1"],
        vec!["--white", "0"],
        vec!["--white", "nan"],
        vec!["--white", "1e-30"],
        vec!["--shader", "missing.psh"],
    ] {
        let mut all = vec!["tonemap", img, "-o", out.to_str().unwrap()];
        all.extend(&args);
        let o = ps30(&all, dir.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
        assert!(!out.exists(), "{args:?} wrote a file");
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn tonemap_unwritable_output_exits_2_without_a_partial_file() {
    let dir = tempfile::tempdir().unwrap();
    let img = asset("sunset.exr");
    let img = img.to_str().unwrap();
    // A missing directory, and a path that is a directory.
    let missing = dir.path().join("no/such/dir/x.png");
    let o = ps30(
        &["tonemap", img, "-o", missing.to_str().unwrap()],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("does not exist"), "{}", stderr(&o));
    let o = ps30(
        &["tonemap", img, "-o", dir.path().to_str().unwrap()],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn tonemap_exits_1_when_a_shader_disagrees_with_the_reference() {
    let dir = tempfile::tempdir().unwrap();
    // Forget the final scale by a / L̄w: every lit pixel is wrong.
    let wrong = ps30::jobs::bundled::TONEMAP_REINHARD.listing().1.replace(
        "mul r2.z, r2.z, r0.y        // Ld / Lw = k · Ld / L",
        "mov r2.z, r2.z",
    );
    assert_ne!(wrong, ps30::jobs::bundled::TONEMAP_REINHARD.listing().1);
    std::fs::write(dir.path().join("wrong.psh"), wrong).unwrap();
    let out = dir.path().join("wrong.png");
    let o = ps30(
        &[
            "tonemap",
            asset("forest.exr").to_str().unwrap(),
            "--shader",
            "wrong.psh",
            "-o",
            out.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("DISAGREE"), "{text}");
    assert!(text.contains("outside their bound"), "{text}");
}

#[test]
fn tonemap_quiet_prints_nothing_on_success() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("q.png");
    let o = ps30(
        &[
            "tonemap",
            asset("sunset.pfm").to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--quiet",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
    assert!(out.exists());
}
