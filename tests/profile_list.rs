//! `ps30 profile --list`: a draw of a draw list profiled as the list draws
//! it, on the lists of `tests/profile_list/`. The expected counts are
//! derived here by hand — which pixels each triangle covers (Direct3D 9's
//! integer pixel centres and top-left rule), which 2×2 quads they fall in,
//! which pixels take the branch — with the slot counts of each path taken
//! from the cost model's static range (`executed`), never from the
//! emulator's counts.

use crate::common::bin::{in_repo, stderr, stdout};
use serde_json::Value;

fn profile(args: &[&str]) -> (Option<i32>, Value) {
    let mut all = vec!["profile", "--json"];
    all.extend(args);
    let o = in_repo(&all);
    let v = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{all:?}: {e}: {}{}", stdout(&o), stderr(&o)));
    (o.status.code(), v)
}

fn u(v: &Value) -> u64 {
    v.as_u64().unwrap_or_else(|| panic!("{v} is not a count"))
}

#[test]
fn a_branch_that_splits_quads_inside_one_triangle() {
    // divergent.json: one triangle (0,0), (8,0), (0,8) over 8×8. A centre
    // (x, y) with x + y = 8 lies on the hypotenuse, the triangle's
    // bottom-right edge (excluded), so it covers x + y < 8: Σ (8 − x) = 36
    // pixels. Quad (qx, qy) holds a covered pixel when 2qx + 2qy < 8: the
    // ten quads with qx + qy ≤ 3. texcoord0.x = 1.1·x/8 < 0.3 for x ≤ 2:
    // columns 0–2 take the branch (the long path L, 21 pixels: 8 + 7 + 6),
    // the others skip it (the short path S, 15 pixels). Quads of columns
    // 0–1 (qx = 0: 4 quads) run L; of columns 2–3 (qx = 1, qy ≤ 2: 3
    // quads) split — divergent, and in lockstep they run L; the other 3
    // run S. Covered pixels per quad: qx = 0: 4, 4, 4, 3 (15); qx = 1: 4,
    // 4, 3 (11); the S quads: 4, 3, 3 (10). Lockstep efficiency: the
    // pixels' own slots over what their quads ran for them,
    // (21L + 15S)/(26L + 10S); in the divergent quads
    // (6L + 5S)/(11L) (columns 2 and 3 of rows 0–5: 6 and 5 pixels).
    // Edge quads: the four with 3 covered pixels; helper lanes 40 − 36 = 4.
    let (code, v) = profile(&["--list", "tests/profile_list/divergent.json"]);
    // A dsx of a temporary in a divergent quad is a finding: exit 1.
    assert_eq!(code, Some(1), "{v}");
    let (s, l) = (u(&v["executed"]["min"]), u(&v["executed"]["max"]));
    assert!(s < l, "{v}");
    assert_eq!(
        (v["step"].as_u64(), v["primitives"].as_u64()),
        (Some(1), Some(1))
    );
    assert_eq!(u(&v["per_pixel"]["count"]), 36);
    assert_eq!(
        (u(&v["per_pixel"]["min"]), u(&v["per_pixel"]["max"])),
        (s, l)
    );
    let mean = (21 * l + 15 * s) as f64 / 36.0;
    assert!((v["per_pixel"]["mean"].as_f64().unwrap() - mean).abs() < 1e-12);
    assert_eq!(u(&v["quads"]), 10);
    assert_eq!(u(&v["per_quad"]["count"]), 10);
    let quad_mean = (7 * l + 3 * s) as f64 / 10.0;
    assert!((v["per_quad"]["mean"].as_f64().unwrap() - quad_mean).abs() < 1e-12);
    assert_eq!(u(&v["divergent_quads"]), 3);
    let eff = (21 * l + 15 * s) as f64 / (26 * l + 10 * s) as f64;
    assert!((v["lockstep_efficiency"].as_f64().unwrap() - eff).abs() < 1e-12);
    let div = (6 * l + 5 * s) as f64 / (11 * l) as f64;
    assert!((v["divergent_efficiency"].as_f64().unwrap() - div).abs() < 1e-12);
    assert_eq!((u(&v["edge_quads"]), u(&v["helper_lanes"])), (4, 4));
    assert_eq!(v["counts_agree"], true);
    // The dsx site: run by the 7 quads of columns 0–3, 3 of them split.
    let dsx = v["gradients"]
        .as_array()
        .unwrap()
        .iter()
        .find(|g| g["op"] == "dsx")
        .expect("the dsx site");
    assert_eq!((u(&dsx["quads"]), u(&dsx["divergent_quads"])), (7, 3));
    assert!(v["vertex_shader"].is_null());
    assert_eq!(v["problem"], true);
}

#[test]
fn a_strip_through_a_vertex_shader_and_the_quads_on_its_diagonal() {
    // strip.json: four clip-space vertices at the corners of a 4×4
    // viewport, a strip of two triangles split along the diagonal from
    // screen (4, 0) to (0, 4). Centres with x + y = 4 lie on it: the
    // bottom-right edge of triangle 0 (excluded) and the top-left edge of
    // triangle 1 (included). Triangle 0 covers x + y < 4 (10 pixels) in
    // quads (0,0) 4, (1,0) 3, (0,1) 3; triangle 1 covers x + y ≥ 4 (6) in
    // quads (1,0) 1, (0,1) 1, (1,1) 4. Six quad runs, four at an edge, 8
    // helper lanes. color.psh has one path: every pixel and quad costs the
    // same, nothing diverges. pass.vsh runs once per vertex: 4 runs, each
    // the cost model's count (one path).
    let (code, v) = profile(&["--list", "tests/profile_list/strip.json"]);
    assert_eq!(code, Some(0), "{v}");
    let c = u(&v["executed"]["min"]);
    assert_eq!(u(&v["executed"]["max"]), c);
    assert_eq!(
        (v["step"].as_u64(), v["primitives"].as_u64()),
        (Some(0), Some(2))
    );
    assert_eq!(u(&v["per_pixel"]["count"]), 16);
    assert_eq!(
        (u(&v["per_pixel"]["min"]), u(&v["per_pixel"]["max"])),
        (c, c)
    );
    assert_eq!(u(&v["quads"]), 6);
    assert_eq!(u(&v["divergent_quads"]), 0);
    assert_eq!(v["lockstep_efficiency"], 1.0);
    assert_eq!((u(&v["edge_quads"]), u(&v["helper_lanes"])), (4, 8));
    let vs = &v["vertex_shader"];
    assert_eq!(vs["runs"], 4);
    let model = u(&vs["executed"]["min"]);
    assert_eq!(u(&vs["executed"]["max"]), model);
    for e in vs["executed_emulated"].as_array().unwrap() {
        assert_eq!(u(e), model);
    }
    assert_eq!(v["problem"], false);
    // The text says the same.
    let o = in_repo(&["profile", "--list", "tests/profile_list/strip.json"]);
    let text = stdout(&o);
    assert!(
        text.starts_with("tests/profile_list/strip.json: step 0, ")
            && text.contains(" over 2 primitives (16 covered pixels in 6 quads)\n"),
        "{text}"
    );
    assert!(
        text.contains(
            "quads at primitive edges: 4 of 6, with 8 helper lanes (run for gradients only)\n"
        ),
        "{text}"
    );
    assert!(text.contains("): 4 runs, "), "{text}");
}

#[test]
fn a_step_that_is_not_a_draw_is_bad_input() {
    let o = in_repo(&[
        "profile",
        "--list",
        "tests/profile_list/divergent.json",
        "--step",
        "0",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("step 0 is not a draw"),
        "{}",
        stderr(&o)
    );
    let o = in_repo(&[
        "profile",
        "--list",
        "tests/profile_list/divergent.json",
        "--step",
        "9",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("step 9 is past the list's 2 steps"),
        "{}",
        stderr(&o)
    );
}

/// The `lines` of a profile as (line, slots, runs, helpers, quads,
/// divergent), checking on the way that each line's executed and lockstep
/// slots are its runs and quad runs times its slots.
fn lines(v: &Value) -> Vec<[u64; 6]> {
    v.as_array()
        .unwrap_or_else(|| panic!("{v} is not a list of lines"))
        .iter()
        .map(|l| {
            let slots = u(&l["slots"]);
            assert_eq!(u(&l["executed"]), u(&l["runs"]) * slots, "{l}");
            assert_eq!(u(&l["lockstep"]), u(&l["quads"]) * slots, "{l}");
            [
                u(&l["line"]),
                slots,
                u(&l["runs"]),
                u(&l["helpers"]),
                u(&l["quads"]),
                u(&l["divergent"]),
            ]
        })
        .collect()
}

#[test]
fn per_line_counts_at_a_triangle_edge_with_a_branch_that_splits_quads() {
    // divergent.json, as derived above: 36 covered pixels in 10 quads, the
    // 4 quads on the hypotenuse (qx + qy = 3) with one helper lane each, at
    // their bottom-right corner (2qx + 1, 2qy + 1), where x + y = 8. A
    // helper runs as its quad does, with texcoord0.x = 1.1·x/8 extended
    // past the edge: the helper of quad (0, 3) has x = 1 and takes the
    // branch; those of quads (1, 2), (2, 1), (3, 0) have x = 3, 5, 7 and
    // do not. Every lane runs lines 5, 6 (the `if_lt` is paid by every lane
    // that reaches it), 9 and 10: 36 runs, 4 helper runs, 10 quad runs, none
    // split. Lines 7 and 8 run in the branch: columns 0–2, 21 covered
    // pixels and that one helper; quads of columns 0–1 (4) and of columns
    // 2–3 (3, rows 0–5) — the latter split, column 3 idle: 7 quad runs, 3
    // divergent. Slots are Microsoft's count (`ps30 check`): mov 1,
    // if_lt 3, dsx 2, endif 1.
    let (_, v) = profile(&["--list", "tests/profile_list/divergent.json"]);
    assert_eq!(
        lines(&v["lines"]),
        vec![
            [5, 1, 36, 4, 10, 0],
            [6, 3, 36, 4, 10, 0],
            [7, 2, 21, 1, 7, 3],
            [8, 1, 21, 1, 7, 3],
            [9, 1, 36, 4, 10, 0],
            [10, 1, 36, 4, 10, 0],
        ]
    );
    // The lines add up to the pixels' and the quads' own totals.
    let sum = |key: &str| -> u64 {
        v["lines"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| u(&l[key]))
            .sum()
    };
    let pixels = v["per_pixel"]["mean"].as_f64().unwrap() * 36.0;
    let quads = v["per_quad"]["mean"].as_f64().unwrap() * 10.0;
    assert_eq!(sum("executed") as f64, pixels.round());
    assert_eq!(sum("lockstep") as f64, quads.round());
    // The text table under --lines.
    let o = in_repo(&[
        "profile",
        "--list",
        "tests/profile_list/divergent.json",
        "--lines",
    ]);
    let text = stdout(&o);
    assert!(
        text.contains("\n    7  dsx r1, r0            2         21         42          1          7          3         14\n"),
        "{text}"
    );
}

#[test]
fn per_line_counts_of_both_shaders_of_a_strip() {
    // strip.json: color.psh's one line runs on the 16 pixels, in 6 quad
    // runs with 8 helper lanes (derived above), none split; pass.vsh's
    // three lines run once per vertex, 4 runs each, 1 slot each.
    let (_, v) = profile(&["--list", "tests/profile_list/strip.json"]);
    assert_eq!(lines(&v["lines"]), vec![[4, 1, 16, 8, 6, 0]]);
    assert_eq!(
        lines(&v["vertex_shader"]["lines"]),
        vec![[6, 1, 4, 0, 0, 0], [7, 1, 4, 0, 0, 0], [8, 1, 4, 0, 0, 0]]
    );
}

#[test]
fn multisampling_and_antialiased_lines_are_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let shader = crate::common::bin::repo().join("tests/profile_list/color.psh");
    let verts = r#"{"attributes": {"positiont0": [[0, 0, 0, 1], [4, 0, 0, 1], [0, 4, 0, 1]], "texcoord0": [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]}}"#;
    let run = |target: &str, geometry: &str| {
        let list = format!(
            r#"{{"targets": [{{"name": "t", "size": "4x4", "format": "A8R8G8B8"{target}}}],
                "steps": [{{"draw": "t", "shader": {shader:?},
                            "geometry": {{"primitive": "line_strip", "vertices": {verts}{geometry}}}}}]}}"#
        );
        let path = dir.path().join("list.json");
        std::fs::write(&path, list).unwrap();
        crate::common::bin::ps30(
            &[
                "render",
                path.to_str().unwrap(),
                "-o",
                dir.path().to_str().unwrap(),
            ],
            dir.path(),
        )
    };
    // One sample per pixel and aliased lines are what ps30 draws.
    let o = run(
        r#", "multisample": "D3DMULTISAMPLE_NONE", "multisample_quality": 0"#,
        r#", "antialiased_lines": false"#,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for (target, geometry, want) in [
        (
            r#", "multisample": "D3DMULTISAMPLE_4_SAMPLES""#,
            "",
            "targets[0].multisample: D3DMULTISAMPLE_4_SAMPLES is not drawn: Direct3D 9 leaves the sample positions to the hardware",
        ),
        (
            r#", "multisample": 1"#,
            "",
            "targets[0].multisample: D3DMULTISAMPLE_NONMASKABLE is not drawn",
        ),
        (
            r#", "multisample_quality": 2"#,
            "",
            "targets[0].multisample_quality: quality 2 needs a multisampled target",
        ),
        (
            "",
            r#", "antialiased_lines": true"#,
            "steps[0].geometry.antialiased_lines: D3DRS_ANTIALIASEDLINEENABLE is not drawn: Direct3D 9 leaves an antialiased line's coverage to the hardware",
        ),
    ] {
        let o = run(target, geometry);
        assert_eq!(o.status.code(), Some(2), "{target}{geometry}");
        assert!(stderr(&o).contains(want), "{}", stderr(&o));
    }
}
