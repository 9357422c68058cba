//! The article's multiple light models (asm/lights/) on the synthetic
//! G-buffer: every pixel against the CPU computation, what divergence costs
//! per quad (worked out by hand on a tiny ID map), the texld variant's
//! diagnostics.

use ps30::emu::{self, Compiled};
use ps30::front::{load_str, Loaded, Options};
use ps30::lights::{self, Scene};

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
        for src in [lights::SELECT, lights::SELECT_TEXLD] {
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
    let run = lights::run(&compiled(lights::SELECT), &scene, None).unwrap();
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
    let run = lights::run(&compiled(lights::SELECT), &scene, Some(1)).unwrap();
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
}

#[test]
fn the_texld_variant_is_flagged_statically_and_counted_per_quad() {
    let l = load(lights::SELECT_TEXLD);
    let lines: Vec<usize> = l
        .warnings
        .items
        .iter()
        .map(|w| l.file.line_of(w.span.start))
        .collect();
    assert_eq!(lines, [34, 39, 43]);
    assert!(load(lights::SELECT).warnings.items.is_empty());

    let scene = Scene::from_ids(4, 2, &TINY).unwrap();
    let run = lights::run(&compiled(lights::SELECT_TEXLD), &scene, Some(1)).unwrap();
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
