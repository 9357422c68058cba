//! The conformance corpus (tests/conformance/, from Wine's Direct3D 9 tests):
//! every case run through ps30 and compared with the colours real drivers
//! produced.
//!
//! For each folder: the `.psh` files must assemble, through the product's
//! own writer, to Wine's token arrays token for token, and Wine's arrays
//! must read back through the product's reader and listing to the same
//! tokens; shaders Windows refuses must be refused with the recorded
//! message; every other case is drawn by each backend — the emulator
//! always; the GPU backend (`core/gpu`, the translated shader on a Vulkan
//! device) when there is an adapter, and always under `CI` — and every
//! probe converted to the render target's 8-bit format and compared.
//!
//! The conversion is the library's D3DFMT_A8R8G8B8 rule
//! (`ps30::core::image::unorm8`): D3D9 does not document how a shader's
//! float colour becomes an 8-bit UNORM channel, so ps30 uses Direct3D 10's
//! ("Data Conversion Rules", FLOAT → UNORM): NaN → 0, clamp to [0, 1],
//! × 255, add 0.5 and drop the fraction (round half up). X8R8G8B8 keeps no
//! alpha, so its probes never compare alpha.
//!
//! The tolerance is Wine's, per channel in 8-bit steps: ±1 (or ±2) where
//! Wine allows it, exact where Wine compares with `==`. ps30 adds no margin
//! of its own, and needs none. Each value a case computes is a few f32
//! operations on numbers of magnitude ≤ 4, so the emulator's result is
//! within 2⁻¹⁸ of the exact one: at most 2⁻¹⁸ · 255 < 0.001 of a step. That
//! can change the stored byte only when the exact value lies within 0.001
//! of a rounding boundary (k + ½ steps); in this corpus that happens where
//! the exact value sits on the boundary itself (0.5 · 255 = 127.5 in
//! nested_loop_test and test_dsy), and Wine allows ±1 there. The exact
//! comparisons (vFace, vPos, multiple render targets) store only 0 and 1.

use crate::common::gpu as gpu_device;

use ps30::core::bytecode::write;
use ps30::core::emu::{Draw, DrawOutput};
use ps30::core::ir::Shader;
use ps30::core::load::{self, Options};
use ps30::jobs::conformance::case::{CaseSpec, ColorFormat, D3dColor, ProbeSpec};
use ps30::jobs::conformance::{self, Rendered, ShaderLoad, Suite};
use std::path::PathBuf;

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/conformance")
}

fn corpus() -> Vec<Suite> {
    conformance::Suite::load_all(&corpus_dir()).unwrap_or_else(|e| panic!("{e}"))
}

/// A float colour channel as an 8-bit UNORM render target stores it
/// (Direct3D 10's FLOAT → UNORM rule; see the module comment).
fn unorm8(v: f32) -> u32 {
    u32::from(ps30::core::image::unorm8(v))
}

/// The D3DCOLOR a texel of an A8R8G8B8 / X8R8G8B8 target holds.
fn stored(rgba: [f32; 4]) -> D3dColor {
    let [r, g, b, a] = rgba.map(unorm8);
    D3dColor(a << 24 | r << 16 | g << 8 | b)
}

/// Whether `got` is within `tolerance` steps of `want` in every channel
/// compared (Wine's color_match).
fn matches(got: D3dColor, want: D3dColor, tolerance: u8, alpha: bool) -> bool {
    let channels = if alpha { 4 } else { 3 };
    (0..channels).all(|c| {
        let (g, w) = ((got.0 >> (8 * c)) & 0xff, (want.0 >> (8 * c)) & 0xff);
        g.abs_diff(w) <= u32::from(tolerance)
    })
}

#[test]
fn d3d10_unorm_conversion() {
    assert_eq!(unorm8(0.0), 0);
    assert_eq!(unorm8(1.0), 255);
    assert_eq!(unorm8(2.0), 255);
    assert_eq!(unorm8(-0.5), 0);
    assert_eq!(unorm8(f32::NAN), 0);
    assert_eq!(unorm8(f32::INFINITY), 255);
    assert_eq!(unorm8(0.5), 128); // 127.5: halves round up
    assert_eq!(unorm8(2.5 / 255.0), 3); // 2.5 (in f64: 2.5000000xx) rounds up
    assert_eq!(unorm8(1.5 / 255.0), 2); // 1.5 (in f64: 1.5000000xx) rounds up
    assert_eq!(stored([1.0, 0.5, 0.0, 0.25]), D3dColor(0x40ff8000));
    assert!(matches(
        D3dColor(0x00808c8c),
        D3dColor(0xff7f8d8c),
        1,
        false
    ));
    assert!(!matches(
        D3dColor(0x00808c8c),
        D3dColor(0xff7f8d8c),
        1,
        true
    ));
    assert!(!matches(
        D3dColor(0x00808c8c),
        D3dColor(0x00808c8e),
        1,
        false
    ));
}

fn hex(tokens: &[u32]) -> String {
    let t: Vec<String> = tokens.iter().map(|t| format!("{t:08x}")).collect();
    t.join(" ")
}

/// Bytes → tokens the way `ps30 asm` makes them (text or bytecode; the
/// program must validate).
fn assemble(name: &str, bytes: Vec<u8>) -> Result<Vec<u32>, String> {
    let file = load::source_file(name, bytes, &Options::default()).map_err(|e| e.to_string())?;
    load::assemble(file, &Options::default())
        .map(|(_, tokens)| tokens)
        .map_err(|e| e.diagnostics.render(&e.file))
}

#[test]
fn every_shader_assembles_to_wines_tokens_and_reads_back_from_them() {
    let mut problems = Vec::new();
    let mut checked = 0;
    for suite in corpus() {
        for (name, spec) in &suite.spec.shaders {
            let theirs: Vec<u32> = spec.tokens.iter().map(|t| t.0).collect();
            let place = format!("{}/{}", suite.spec.function, spec.file);
            if let ShaderLoad::Refused(_) = &suite.shaders[name] {
                // Refused shaders are checked by the case that expects it.
                continue;
            }
            let text = std::fs::read(suite.dir.join(&spec.file)).unwrap();
            match assemble(&place, text) {
                Ok(ours) if ours == theirs => {}
                Ok(ours) => problems.push(format!(
                    "{place}: the writer:\n  Wine: {}\n  ps30: {}",
                    hex(&theirs),
                    hex(&ours)
                )),
                Err(e) => problems.push(format!("{place}: {e}")),
            }
            match assemble(
                &format!("{place} (Wine's tokens)"),
                write::to_bytes(&theirs),
            ) {
                Ok(again) if again == theirs => {}
                Ok(again) => problems.push(format!(
                    "{place}: the reader:\n  Wine: {}\n  ps30: {}",
                    hex(&theirs),
                    hex(&again)
                )),
                Err(e) => problems.push(format!("{place}: Wine's tokens: {e}")),
            }
            checked += 1;
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(checked >= 30, "only {checked} shaders checked");
}

/// One backend's verdict on one probe.
#[derive(Debug)]
enum Verdict {
    Expected,
    /// Only an alternative the source accepts from some driver.
    Alternative(String),
    Wrong,
}

fn judge(probe: &ProbeSpec, got: D3dColor) -> Verdict {
    if matches(got, probe.expected, probe.tolerance, probe.alpha) {
        return Verdict::Expected;
    }
    match probe
        .alternatives
        .iter()
        .find(|a| matches(got, a.expected, a.tolerance, probe.alpha))
    {
        Some(a) => Verdict::Alternative(a.who.clone()),
        None => Verdict::Wrong,
    }
}

/// Checks one rendered case; returns a report line per probe, and the
/// problems.
fn check_probes(suite: &Suite, case: &CaseSpec, r: &Rendered) -> (Vec<String>, Vec<String>) {
    let (mut lines, mut problems) = (Vec::new(), Vec::new());
    for p in &case.probes {
        let place = format!("{}:{} ({}, {})", suite.place(case), p.line, p.x, p.y);
        let Some(target) = r.targets.get(p.target) else {
            problems.push(format!("{place}: no target {}", p.target));
            continue;
        };
        if p.alpha && target.format == ColorFormat::X8R8G8B8 {
            problems.push(format!(
                "{place}: an X8R8G8B8 target has no alpha to compare"
            ));
            continue;
        }
        let Some(texel) = target.texel(p.x, p.y) else {
            problems.push(format!(
                "{place}: texel of `{}` is outside it or never written",
                target.name
            ));
            continue;
        };
        let got = stored(texel);
        let mask = if p.alpha { 0xffff_ffff } else { 0x00ff_ffff };
        let shown = D3dColor(got.0 & mask);
        let verdict = judge(p, got);
        lines.push(format!(
            "  {:<5} {place}: {shown} want {} ±{}{}",
            if matches!(verdict, Verdict::Expected) {
                "ok"
            } else {
                "FAIL"
            },
            p.expected,
            p.tolerance,
            match &verdict {
                Verdict::Alternative(who) => format!(" (matches only {who})"),
                _ => String::new(),
            }
        ));
        if !matches!(verdict, Verdict::Expected) {
            problems.push(format!(
                "{place}: {shown} (from {texel:?}), expected {} ±{} ({verdict:?})",
                p.expected, p.tolerance
            ));
        }
    }
    (lines, problems)
}

type Backend = Box<dyn FnMut(&Shader, &Draw) -> Result<DrawOutput, String>>;

/// The backends the corpus runs on, and those it could not run on, with
/// the reason.
struct Backends {
    run: Vec<(&'static str, Backend)>,
    not_run: Vec<(&'static str, &'static str)>,
}

fn backends() -> Backends {
    let mut run: Vec<(&'static str, Backend)> = vec![("emulator", Box::new(conformance::emulate))];
    let mut not_run = Vec::new();
    match gpu_device::gpu("every_case_gives_the_colours_wine_expects") {
        Some(g) => run.push((
            "GPU",
            Box::new(move |shader: &Shader, draw: &Draw| {
                ps30::core::gpu::run(&g, shader, draw, ps30::core::gpu::TargetKind::Raw)
                    .map(|o| o.into_draw_output())
                    .map_err(|e| e.to_string())
            }),
        )),
        None => not_run.push(("GPU", "not run: no GPU adapter (see the line above)")),
    }
    Backends { run, not_run }
}

#[test]
fn every_case_gives_the_colours_wine_expects() {
    let suites = corpus();
    let Backends { mut run, not_run } = backends();
    let (mut report, mut problems) = (Vec::new(), Vec::new());
    let (mut cases, mut probes) = (0, 0);
    for (backend, draw) in &mut run {
        for suite in &suites {
            for case in &suite.spec.cases {
                if case.rejected.is_some() {
                    continue;
                }
                cases += 1;
                probes += case.probes.len();
                match conformance::render(suite, case, draw) {
                    Ok(r) => {
                        report.push(format!(
                            "{backend} {}: {} backend draw(s){}",
                            suite.place(case),
                            r.backend_draws,
                            r.warnings
                                .iter()
                                .map(|w| format!("; warning {w}"))
                                .collect::<String>()
                        ));
                        let (lines, bad) = check_probes(suite, case, &r);
                        report.extend(lines);
                        problems.extend(bad.into_iter().map(|p| format!("{backend}: {p}")));
                    }
                    Err(e) => problems.push(format!("{backend}: {e}")),
                }
            }
        }
    }
    for (backend, why) in &not_run {
        report.push(format!("{backend}: {why}"));
    }
    println!("{}", report.join("\n"));
    println!("{cases} cases, {probes} probes per backend");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(cases >= 30, "only {cases} cases drawn");
}

#[test]
fn shaders_windows_refuses_are_refused() {
    let mut seen = 0;
    for suite in corpus() {
        for case in &suite.spec.cases {
            let Some(r) = &case.rejected else { continue };
            seen += 1;
            assert!(
                case.targets.is_empty() && case.draws.is_empty() && case.probes.is_empty(),
                "{}: a refused shader is not drawn",
                suite.place(case)
            );
            match &suite.shaders[&r.shader] {
                ShaderLoad::Refused(e) => {
                    let first = e.diagnostics.errors().next().expect("an error");
                    assert!(
                        first.message.starts_with(&r.message),
                        "{}: `{}`, expected `{}`",
                        suite.place(case),
                        first.message,
                        r.message
                    );
                }
                ShaderLoad::Loaded(_) => panic!("{}: `{}` loads", suite.place(case), r.shader),
            }
        }
    }
    assert!(seen >= 1);
}

#[test]
fn the_readme_lists_every_case() {
    let readme = std::fs::read_to_string(corpus_dir().join("README.md")).unwrap();
    let mut missing = Vec::new();
    let mut total = 0;
    for suite in corpus() {
        for case in &suite.spec.cases {
            total += 1;
            let name = format!("`{}`", suite.place(case));
            if !readme.contains(&name) {
                missing.push(name);
            }
        }
    }
    assert!(missing.is_empty(), "README.md does not list {missing:?}");
    let claim = format!("**{total} cases**");
    assert!(readme.contains(&claim), "README.md should say {claim}");
}
