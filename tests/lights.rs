//! The article's multiple light models (asm/lights/) on the synthetic
//! G-buffer: every pixel against the CPU computation, what divergence costs
//! per quad (worked out by hand on a tiny ID map), the texld variant's
//! diagnostics, and `ps30 profile` on top of it all.

use ps30::core::emu::findings::FindingKind;
use ps30::core::emu::{self, Compiled};
use ps30::core::load::{load_str, Loaded, Options};
use ps30::jobs::profile::{self, CostStats, Input, Setup};
use ps30::jobs::scenes::lights::{self, Scene};

fn load(src: (&str, &str)) -> Loaded {
    load_str(src.0, src.1, &Options::default()).unwrap()
}

fn compiled(src: (&str, &str)) -> Compiled {
    emu::compile(&load(src).shader).unwrap()
}

#[test]
fn both_variants_match_the_cpu_computation_in_every_region() {
    for (w, h) in [(64, 64), (37, 23), (1, 1)] {
        let scene = Scene::synthetic(w, h).unwrap();
        for src in [
            ps30::jobs::bundled::LIGHTS_SELECT.listing(),
            ps30::jobs::bundled::LIGHTS_TEXLD.listing(),
        ] {
            Scene::check_constants(load(src).shader.program()).unwrap();
            let run = lights::run(&compiled(src), &scene, Some(1)).unwrap();
            assert!(run.all_match(), "{} {w}x{h}: {:?}", src.0, run.per_model);
            let total: u64 = run.per_model.iter().map(|m| m.0).sum();
            assert_eq!(total, (w * h) as u64);
        }
    }
    // At 64×64 every model has pixels, and some quads hold all three.
    let scene = Scene::synthetic(64, 64).unwrap();
    assert!(scene.pixels_per_model().iter().all(|&n| n > 100));
    let run = lights::run(
        &compiled(ps30::jobs::bundled::LIGHTS_SELECT.listing()),
        &scene,
        None,
    )
    .unwrap();
    let out = &run.output;
    assert!(
        out.quad_executed.contains(&34),
        "a quad with all three models"
    );
    assert!(out.quad_divergent.iter().filter(|&&d| d).count() > 20);
}

#[test]
fn the_ids_compare_with_the_articles_epsilon() {
    assert_eq!(lights::model_of(0.0), 0);
    assert_eq!(lights::model_of(0.99998), 0);
    assert_eq!(lights::model_of(0.99999), 1, "not below 1 - eps");
    assert_eq!(lights::model_of(1.0), 1);
    assert_eq!(lights::model_of(1.99999), 2);
    assert_eq!(lights::model_of(2.0), 2);
    // The G-buffer stores the IDs as halves: 0, 1, 2 survive exactly.
    let scene = Scene::from_ids(3, 1, &[0, 1, 2]).unwrap();
    assert_eq!(
        (0..3).map(|x| scene.id(x, 0)).collect::<Vec<_>>(),
        [0.0, 1.0, 2.0]
    );
    assert!(Scene::from_ids(2, 1, &[0, 3]).is_err());
    assert!(Scene::from_ids(2, 1, &[0]).is_err());
    assert!(Scene::synthetic(0, 4).is_err());
}

/// IDs of a 4×2 G-buffer: quad 0 holds models 0, 1, 2, 2; quad 1 model 0.
const TINY: [u8; 8] = [0, 1, 0, 0, 2, 2, 0, 0];

#[test]
fn per_quad_costs_on_a_tiny_gbuffer_match_the_hand_count() {
    let scene = Scene::from_ids(4, 2, &TINY).unwrap();
    let run = lights::run(
        &compiled(ps30::jobs::bundled::LIGHTS_SELECT.listing()),
        &scene,
        Some(1),
    )
    .unwrap();
    assert!(run.all_match());
    let out = &run.output;
    // Shared: texld 1, mul 1, mov 1, dp3 1, if_lt 3 = 7; at the end mov 1, mov 1.
    // Model 0: texldl 2, max 1, mul 1 = 4, else 1, endif 1      → 7 + 4 + 2 + 2 = 15.
    // Model 1: else 1, if_lt 3, texldl 2 + mad_sat 1 + mul 1, else 1, endif 1, endif 1
    //                                                             → 7 + 10 + 1 + 2 = 20.
    // Model 2: else 1, if_lt 3, else 1, texldl 2 + dp3 + max + 4 mul + mul + mad = 10,
    //          endif 1, endif 1                                   → 7 + 17 + 2 = 26.
    assert_eq!(out.executed, [15, 20, 15, 15, 26, 26, 15, 15]);
    // Quad 0 runs all three bodies: 7 + 4 + else 1 + if 3 + 4 + else 1 + 10
    // + endif 1 + endif 1 + 2 = 34. Quad 1 pays what its pixels pay.
    assert_eq!(out.quad_executed, [34, 15]);
    assert_eq!(out.quad_divergent, [true, false]);
    let c = profile::quad_costs(out, 10);
    assert_eq!((c.per_quad.min, c.per_quad.max), (15, 34));
    assert_eq!(c.per_pixel.mean, (15.0 * 5.0 + 20.0 + 26.0 * 2.0) / 8.0);
    // Quad 0's pixels use 15 + 20 + 26 + 26 = 87 of 4 × 34 slot-pixels.
    assert_eq!(c.divergent_efficiency, 87.0 / 136.0);
    assert_eq!(c.lockstep_efficiency, (87.0 + 60.0) / (136.0 + 60.0));
}

#[test]
fn the_texld_variant_is_flagged_statically_and_counted_per_quad() {
    let l = load(ps30::jobs::bundled::LIGHTS_TEXLD.listing());
    let lines: Vec<usize> = l
        .warnings
        .items
        .iter()
        .map(|w| l.file.line_of(w.span.start))
        .collect();
    assert_eq!(lines, [34, 39, 43]);
    assert!(load(ps30::jobs::bundled::LIGHTS_SELECT.listing())
        .warnings
        .items
        .is_empty());

    let scene = Scene::from_ids(4, 2, &TINY).unwrap();
    let run = lights::run(
        &compiled(ps30::jobs::bundled::LIGHTS_TEXLD.listing()),
        &scene,
        Some(1),
    )
    .unwrap();
    let sites: Vec<(usize, bool, u64, u64)> = run
        .output
        .gradients
        .iter()
        .map(|g| {
            (
                l.file.line_of(g.span.start),
                g.temp_source,
                g.quads,
                g.divergent_quads,
            )
        })
        .collect();
    // The G-buffer read (v0, both quads, uniform); model 0's texld runs in
    // both quads, divergently in quad 0; models 1 and 2 only in quad 0.
    assert_eq!(
        sites,
        [
            (29, false, 2, 0),
            (34, true, 2, 1),
            (39, true, 1, 1),
            (43, true, 1, 1)
        ]
    );
    // With one level per material texture the undefined gradients change
    // nothing here: the variant still matches the CPU.
    assert!(run.all_match());
}

#[test]
fn profile_reports_costs_and_findings() {
    let setup = Setup {
        input: Input::GBuffer(4, 2),
        defines: Vec::new(),
        constants: Default::default(),
        textures: Vec::new(),
        bins: 12,
        threads: Some(1),
        limits: Default::default(),
        float_rules: Default::default(),
    };
    // The tiny map is not what --gbuffer draws; check the synthetic one.
    let r = profile::profile(
        ps30::jobs::bundled::LIGHTS_SELECT.listing().0,
        ps30::jobs::bundled::LIGHTS_SELECT.listing().1,
        &setup,
    )
    .unwrap();
    assert_eq!((r.width, r.height), (4, 2));
    assert!(r.counts_agree);
    assert!(r.findings.is_empty());
    assert!(!r.problem());
    let r = profile::profile(
        ps30::jobs::bundled::LIGHTS_TEXLD.listing().0,
        ps30::jobs::bundled::LIGHTS_TEXLD.listing().1,
        &Setup {
            input: Input::GBuffer(64, 64),
            ..setup.clone()
        },
    )
    .unwrap();
    assert!(r.problem());
    let kinds: Vec<(FindingKind, usize)> =
        r.findings.iter().map(|f| (f.kind, f.site.line)).collect();
    assert_eq!(
        kinds,
        [
            (FindingKind::DivergentGradient, 34),
            (FindingKind::DivergentGradient, 39),
            (FindingKind::DivergentGradient, 43)
        ]
    );
    let text = ps30::present::profile::text(&r);
    assert!(text.contains("asm/lights/select_texld.psh:34:5"), "{text}");
    assert!(text.contains("4,096 of 4,096 pixels match bit for bit"));
    let json = ps30::present::profile::to_json(&r, &[]);
    assert_eq!(json["problem"], true);
    let kinds: Vec<&str> = json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["kind"].as_str().unwrap())
        .collect();
    assert_eq!(
        kinds.iter().filter(|k| **k == "divergent_gradient").count(),
        3,
        "{kinds:?}"
    );
    assert_eq!(json["per_quad"]["max"], r.costs.per_quad.max);
    // A shader that is not a light-model shader is refused for the scene.
    let other = ps30::jobs::bundled::CORRECTED_PASS2.listing();
    assert!(profile::profile(other.0, other.1, &setup).is_err());
}

#[test]
fn histograms_list_values_or_equal_bins() {
    let s = CostStats::of(&[3, 3, 5, 9], 4);
    assert_eq!((s.min, s.max, s.count), (3, 9, 4));
    assert_eq!(s.mean, 5.0);
    let bins: Vec<(u64, u64, u64)> = s.histogram.iter().map(|b| (b.lo, b.hi, b.count)).collect();
    assert_eq!(bins, [(3, 3, 2), (5, 5, 1), (9, 9, 1)]);
    // 1..=10 in 3 bins of width 4: 1-4, 5-8, 9-10.
    let v: Vec<u64> = (1..=10).collect();
    let s = CostStats::of(&v, 3);
    let bins: Vec<(u64, u64, u64)> = s.histogram.iter().map(|b| (b.lo, b.hi, b.count)).collect();
    assert_eq!(bins, [(1, 4, 4), (5, 8, 4), (9, 10, 2)]);
    let empty = CostStats::of(&[], 5);
    assert_eq!((empty.count, empty.min, empty.max), (0, 0, 0));
    assert!(empty.histogram.is_empty());
}

#[test]
fn the_luminance_pass_is_warned_about_its_level_of_detail() {
    // A 250×256 image in 125×128 blocks: a 2×2 target, one quad whose
    // neighbours sample 125 (x) and 128 (y) texels apart: λ = log2 128 = 7.
    let img = ps30::core::image::HdrImage {
        width: 250,
        height: 256,
        pixels: vec![[0.5, 0.5, 0.5, 1.0]; 250 * 256],
    };
    let (n1, t1) = ps30::jobs::bundled::listing("corrected:unrolled").unwrap();
    let (n2, t2) = ps30::jobs::bundled::listing("corrected:pass2").unwrap();
    let run = ps30::jobs::luminance::run(
        &img,
        &ps30::jobs::luminance::ShaderSource::new(n1, t1),
        &ps30::jobs::luminance::ShaderSource::new(n2, t2),
        &ps30::jobs::luminance::Settings::default(),
    )
    .unwrap();
    assert!(run.all_agree());
    let f = &run.pass1.findings;
    assert_eq!(f.len(), 1, "{f:?}");
    assert_eq!(f[0].kind, FindingKind::LodFarFromLevel0);
    assert_eq!(f[0].site.lod, Some((7.0, 7.0)));
    assert!(f[0].message.contains("LOD 7.00"), "{}", f[0].message);
    assert!(f[0].message.contains("s0 has one level"));
    // Pass 2 reads one texel per pixel of a 1×1 draw: no gradient at all.
    assert!(run.pass2.findings.is_empty());
    let text =
        ps30::present::luminance::run_text("img", &run, &ps30::present::luminance::Choice::Given);
    assert!(text
        .contains("warning: asm/corrected/lum_pass1_unrolled.psh:23:9: `texld` computes LOD 7.00"));
}

// ----- the command line ----------------------------------------------------------

use crate::common::bin::in_repo as ps30;

#[test]
fn profile_command_exit_codes_and_output() {
    let o = ps30(&["profile", "lights:select", "--gbuffer", "32x32"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(
        out.contains("static paths (cost model): shortest 15, longest 26"),
        "{out}"
    );
    assert!(out.contains("per quad"));
    // The texld variant: static warnings on stderr, runtime findings on
    // stdout, exit 1.
    let o = ps30(&[
        "profile",
        "asm/lights/select_texld.psh",
        "--gbuffer",
        "32x32",
    ]);
    let (out, err) = (
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr),
    );
    assert_eq!(o.status.code(), Some(1), "{out}{err}");
    assert!(err.contains("under dynamic flow control"), "{err}");
    assert!(out.contains("ran in divergent quads"), "{out}");
    let o = ps30(&["profile", "lights:texld", "--gbuffer", "16x16", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["target"], serde_json::json!([16, 16]));
    assert!(v["per_pixel"]["histogram"].as_array().is_some());
    assert_eq!(v["models"][0]["pixels"], v["models"][0]["match"]);
    // Bad input exits 2.
    for args in [
        &["profile", "lights:select"][..],
        &["profile", "lights:select", "--gbuffer", "0x4"],
        &["profile", "nope.psh", "--gbuffer", "4x4"],
        &["profile", "corrected:pass2", "--gbuffer", "4x4"],
        &["profile", "lights:select", "--image", "x.exr"],
    ] {
        assert_eq!(ps30(args).status.code(), Some(2), "{args:?}");
    }
}

#[test]
fn profile_on_an_image_with_mips() {
    // The corrected loop pass over the bundled image, 10×8 target: blocks of
    // 128×128 texels, so λ = 7; with a mip chain and mip point it reads
    // level 7 and nothing warns, without one it warns.
    let args = [
        "profile",
        "corrected:loop",
        "--image",
        "assets/hdr/courtyard_1280x1024.exr",
        "--target",
        "10x8",
        "--int",
        "i1=8",
        "--int",
        "i2=8",
        "--const",
        "c0=0,0,0,0",
        "--const",
        "c1=0.00078125,0.0009765625,0,1",
        "--const",
        "c3=0.27,0.67,0.06,0.01",
        "--json",
    ];
    let o = ps30(&args);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let lod_findings = |v: &serde_json::Value| -> Vec<serde_json::Value> {
        v["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|d| d["kind"] == "lod_far_from_level0")
            .cloned()
            .collect()
    };
    assert_eq!(lod_findings(&v).len(), 1, "{v}");
    // 128/1280 is not a binary fraction: the f32 coordinates are 128.00006
    // texels apart, λ = 7 + 7e-7.
    let lod = v["gradients"][0]["lod"]["max"].as_f64().unwrap();
    assert!((lod - 7.0).abs() < 1e-5, "{lod}");
    assert_eq!(o.status.code(), Some(0), "LOD findings are warnings");
    let mut with_mips = args.to_vec();
    with_mips.extend(["--mips", "--mip-filter", "point"]);
    let o = ps30(&with_mips);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(lod_findings(&v).is_empty(), "{v}");
    assert!(v["input"].as_str().unwrap().contains("11 levels"), "{v}");
}
