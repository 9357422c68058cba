//! The generator's promises, checked on the committed files.
//!
//! For every frame size of `asm/generated/`:
//!
//! * the files on disk are exactly what the generator writes now (nothing
//!   missing, stale or extra);
//! * every file loads, fits the ps_3_0 profile (slots, executed, rep range,
//!   nesting) and states its own slots and executed count truthfully;
//! * every configuration (pass 1 with BORDER padding + pass 2, and pass 1 +
//!   its last-column shader + pass 2) runs in the emulator on an image of
//!   the frame's size, and every block and L̄w agree with the f64 reference
//!   within the pipeline's derived bounds; the emulator's per-pixel counts
//!   equal the cost model's;
//! * every file is used by some configuration, so every file is run.
//!
//! The images: no bundled image has most of these sizes, so each test builds
//! one by mirrored tiling of `courtyard_1280x1024.exr` (the bundled image of
//! the article's frame size): pixel (x, y) is the source pixel at x and y
//! reflected back and forth across the source's edges. At 1280×1024 that is
//! the bundled image itself; at 640×480 a crop of it; the larger frames
//! repeat it mirrored, so there are no seams. Real HDR content everywhere,
//! every block of every frame different enough to catch a shader that reads
//! the wrong texels.

use ps30::core::cost::{self, Environment, Profile, Verdict};
use ps30::core::image::{load, HdrImage, ImageLimits};
use ps30::core::load::{self, Options};
use ps30::jobs::gen::set::{self, Bundle, Role};
use ps30::jobs::gen::{plan, Pass1Form};
use ps30::jobs::luminance::{run, run_with_last_column, Settings, ShaderSource};
use std::path::{Path, PathBuf};

// Only `asset` is used here; the shared image list serves the per-image suites.
#[allow(dead_code)]
use crate::common;
use common::asset;

fn generated_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(ps30::jobs::verify::GENERATED_DIR)
}

/// Reflects `i` into 0..n (… 2 1 0 | 0 1 2 … n−1 | n−1 n−2 …).
fn mirror(i: u32, n: u32) -> u32 {
    let period = 2 * n;
    let k = i % period;
    if k < n {
        k
    } else {
        period - 1 - k
    }
}

/// An image of `w × h` by mirrored tiling of the bundled 1280×1024 image.
fn frame_image(w: u32, h: u32) -> HdrImage {
    let src = load(&asset("courtyard_1280x1024.exr"), &ImageLimits::default()).unwrap();
    if (w, h) == (src.width, src.height) {
        return src;
    }
    let mut pixels = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            pixels.push(src.pixel(mirror(x, src.width), mirror(y, src.height)));
        }
    }
    HdrImage {
        width: w,
        height: h,
        pixels,
    }
}

/// The number after `label` in a header line such as `//   slots     511 of 512`.
fn header_number(text: &str, label: &str) -> u64 {
    let line = text
        .lines()
        .take_while(|l| l.starts_with("//"))
        .find(|l| l.trim_start_matches('/').trim_start().starts_with(label))
        .unwrap_or_else(|| panic!("no `{label}` line in the header"));
    let rest = line.trim_start_matches('/').trim_start()[label.len()..].trim_start();
    let digits: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == ',')
        .filter(|c| *c != ',')
        .collect();
    digits.parse().unwrap()
}

/// Loads a committed file and checks it against the ps_3_0 profile and its
/// own header.
fn check_file(rel: &str, text: &str) -> (u64, u64) {
    let loaded = load::load_str(rel, text, &Options::default())
        .unwrap_or_else(|e| panic!("{rel}: {}", e.diagnostics.render(&e.file)));
    let profile = Profile::ps_3_0();
    let a = cost::analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &profile,
    )
    .unwrap();
    assert_eq!(a.verdict, Verdict::Within, "{rel}");
    assert!(a.executed.is_exact(), "{rel}: {:?}", a.reasons);
    assert!(a.slots <= profile.max_slots && a.executed.max <= profile.max_executed);
    for l in &a.loops {
        assert!(l.iterations.max <= profile.max_rep_count as u64, "{rel}");
    }
    assert!(ps30::jobs::gen::loop_nesting(&loaded.shader) <= profile.max_loop_nesting);
    assert!(loaded.warnings.items.is_empty(), "{rel}: warnings");
    // The header tells the truth.
    assert_eq!(header_number(text, "slots"), a.slots, "{rel}: header slots");
    assert_eq!(
        header_number(text, "executed"),
        a.executed.max,
        "{rel}: header executed"
    );
    (a.slots, a.executed.max)
}

fn source(dir: &Path, file: &str) -> ShaderSource {
    let path = dir.join(file);
    ShaderSource::new(
        path.display().to_string(),
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())),
    )
}

/// Everything the module header promises, for one frame.
fn frame(w: u32, h: u32) {
    let (bundle, p) = set::frame_set((w, h)).unwrap();
    assert!(bundle.problems.is_empty(), "{:?}", bundle.problems);
    let dir = generated_dir().join(set::frame_dir((w, h)));

    // The files on disk are the generator's, all of them.
    let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".psh"))
        .collect();
    on_disk.sort();
    let mut expected: Vec<String> = bundle.shaders.iter().map(|g| g.file.clone()).collect();
    expected.sort();
    assert_eq!(
        on_disk,
        expected,
        "{}: run `ps30 verify --regenerate`",
        dir.display()
    );
    for g in &bundle.shaders {
        let text = std::fs::read_to_string(dir.join(&g.file)).unwrap();
        assert!(
            text == g.text,
            "{}/{} is stale: run `ps30 verify --regenerate`",
            dir.display(),
            g.file
        );
        let (slots, executed) = check_file(&g.file, &text);
        assert_eq!((slots, executed), (g.slots, g.executed), "{}", g.file);
    }

    // Every file is used by a configuration.
    for g in &bundle.shaders {
        let used = bundle.configs.iter().any(|c| {
            c.pass1 == g.file
                || c.last_column.as_deref() == Some(g.file.as_str())
                || c.pass2.as_deref() == Some(g.file.as_str())
        });
        assert!(used, "{} is not part of any configuration", g.file);
    }

    // The plan's recommendation is among the configurations.
    let rec = p.recommended.as_ref().unwrap();
    assert!(
        bundle
            .configs
            .iter()
            .any(|c| format!("{}-{}x{}", c.form.name(), c.block[0], c.block[1]) == *rec),
        "{rec}"
    );

    // Every configuration, run and cross-checked.
    let img = frame_image(w, h);
    for c in &bundle.configs {
        let settings = Settings {
            block: (c.block[0], c.block[1]),
            ..Settings::default()
        };
        let pass1 = source(&dir, &c.pass1);
        let pass2 = source(&dir, c.pass2.as_ref().unwrap());
        let shader = |f: &str| bundle.shaders.iter().find(|g| g.file == f).unwrap();
        let border = run(&img, &pass1, &pass2, &settings).unwrap();
        let what = format!("{w}×{h} {} {}×{}", c.form.name(), c.block[0], c.block[1]);
        assert!(
            border.all_agree(),
            "{what}: {}",
            ps30::present::luminance::run_text(
                &what,
                &border,
                &ps30::present::luminance::Choice::Given
            )
        );
        assert_eq!(border.targets, (c.targets[0], c.targets[1]));
        assert_eq!(border.padded_samples, c.padded_border, "{what}");
        let exact = |n: u64| cost::Range::exact(n);
        assert_eq!(
            border.pass1.executed_emulated,
            Some(exact(shader(&c.pass1).executed))
        );
        let p2 = shader(c.pass2.as_ref().unwrap());
        assert_eq!(border.pass2.executed_emulated, Some(exact(p2.executed)));
        assert_eq!(
            c.total_executed,
            Some(shader(&c.pass1).executed * (c.targets[0] * c.targets[1]) as u64 + p2.executed)
        );
        if let Some(last) = &c.last_column {
            let l =
                run_with_last_column(&img, &pass1, &source(&dir, last), &pass2, &settings).unwrap();
            assert!(
                l.all_agree(),
                "{what} with {last}: {}",
                ps30::present::luminance::run_text(
                    &what,
                    &l,
                    &ps30::present::luminance::Choice::Given
                )
            );
            // Padded samples in x become 0: only the padding in y is left.
            let covered_y = c.targets[1] as u64 * c.block[1] as u64;
            assert_eq!(
                l.padded_samples,
                w as u64 * covered_y - w as u64 * h as u64,
                "{what}"
            );
            assert_eq!(l.padded_samples, c.padded_last_column);
            assert!(l.padded_samples < border.padded_samples);
            let lc = l.pass1_last.as_ref().unwrap();
            assert_eq!(lc.executed_emulated, Some(exact(shader(last).executed)));
            // Both runs agree with the true L̄w, so with each other.
            assert!(
                (l.log_average - border.log_average).abs()
                    <= (l.relative_tolerance + border.relative_tolerance) * l.reference_log_average
            );
        }
    }
}

#[test]
fn frame_640x480() {
    frame(640, 480);
}

#[test]
fn frame_1024x768() {
    frame(1024, 768);
}

#[test]
fn frame_1280x1024() {
    frame(1280, 1024);
}

#[test]
fn frame_1920x1080() {
    frame(1920, 1080);
}

#[test]
fn frame_2560x1440() {
    frame(2560, 1440);
}

#[test]
fn frame_3840x2160() {
    frame(3840, 2160);
}

#[test]
fn the_committed_set_has_no_other_files() {
    let all = set::generated_set().unwrap();
    let stale = set::stale_files(&generated_dir(), &all);
    assert!(stale.is_empty(), "{stale:#?}");
    let frames: Vec<String> = std::fs::read_dir(generated_dir())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(frames.len(), set::FRAMES.len(), "{frames:?}");
    // verify's planning claims, from the same set.
    let claims = ps30::jobs::verify::planning_claims(&all).unwrap();
    assert_eq!(claims.len(), 5);
    for c in &claims {
        assert!(
            c.agrees,
            "{} — article {}, ps30 {}",
            c.claim, c.article, c.ps30
        );
    }
}

#[test]
fn stale_missing_and_extra_files_are_named() {
    let all = set::generated_set().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let (written, removed) = set::write_set(dir.path(), &all).unwrap();
    assert_eq!(written.len(), all.files.len());
    assert!(removed.is_empty());
    assert!(set::stale_files(dir.path(), &all).is_empty());
    let (first, _) = &all.files[0];
    let (second, _) = &all.files[1];
    std::fs::write(dir.path().join(first), "ps_3_0\n").unwrap();
    std::fs::remove_file(dir.path().join(second)).unwrap();
    // One file the generator once wrote (its header) and one it did not.
    let old = format!("{} an older shader\nps_3_0\n", set::MARK);
    std::fs::write(dir.path().join("640x480/extra.psh"), old).unwrap();
    std::fs::write(dir.path().join("640x480/mine.psh"), "ps_3_0\n").unwrap();
    let problems = set::stale_files(dir.path(), &all);
    assert_eq!(problems.len(), 4, "{problems:#?}");
    assert!(problems[0].contains(first.as_str()) && problems[0].contains("stale"));
    assert!(problems[1].contains(second.as_str()) && problems[1].contains("missing"));
    assert!(problems[2].contains("extra.psh") && problems[2].contains("to remove it"));
    assert!(problems[3].contains("mine.psh") && problems[3].contains("remove it yourself"));
    // Regenerating repairs the first three and leaves the foreign file.
    let (written, removed) = set::write_set(dir.path(), &all).unwrap();
    assert_eq!((written.len(), removed.len()), (2, 1));
    let left = set::stale_files(dir.path(), &all);
    assert_eq!(left.len(), 1, "{left:#?}");
    assert!(dir.path().join("640x480/mine.psh").exists());
    // Every generated file starts with the mark regeneration trusts.
    assert!(all.files.iter().all(|(_, t)| t.starts_with(set::MARK)));
}

fn request(frame: (u32, u32), picks: Vec<(Pass1Form, set::BlockChoice)>) -> set::Request {
    set::Request {
        frame,
        picks,
        macros: false,
        delta: 1e-4,
        last_columns: true,
    }
}

#[test]
fn plan_1280x1024_lists_the_articles_choices_with_the_articles_counts() {
    let p = plan::plan((1280, 1024), &Profile::ps_3_0(), 1e-4).unwrap();
    // The article's own listings, analysed: its executed counts.
    let (_, loop_a) = ps30::jobs::verify::analyse_listing(
        ps30::jobs::bundled::ARTICLE_LOOP.listing(),
        &[],
        &[(1, 128), (2, 56)],
    )
    .unwrap();
    let (_, unrolled_a) = ps30::jobs::verify::analyse_listing(
        ps30::jobs::bundled::ARTICLE_UNROLLED.listing(),
        &[],
        &[(2, 128)],
    )
    .unwrap();
    for (form, block, targets, article) in [
        (Pass1Form::Loop, [128, 56], [10, 19], loop_a),
        (Pass1Form::Unrolled, [125, 128], [11, 8], unrolled_a),
    ] {
        let c = p
            .candidates
            .iter()
            .find(|c| c.variant == form && c.block == block)
            .unwrap_or_else(|| panic!("{block:?} missing"));
        assert_eq!(c.targets, targets);
        assert!(c.article);
        assert_eq!(c.passes, 2);
        // The generated listing, with the line-end fix, costs what the
        // article's listing costs.
        assert_eq!(c.executed_per_pixel[0], Some(article.executed.max));
        assert_eq!(c.slots[0], Some(article.slots));
        // Listed by the enumeration rule, not only as the article's.
        assert!(c.listed_as.len() >= 2, "{:?}", c.listed_as);
    }
    // The recommendation follows the stated rule: fewest executed for the
    // frame among two-pass candidates.
    let rec = p
        .candidates
        .iter()
        .find(|c| Some(&c.name) == p.recommended.as_ref())
        .unwrap();
    let best = p
        .candidates
        .iter()
        .filter(|c| c.passes == 2)
        .map(|c| c.total_executed.unwrap())
        .min()
        .unwrap();
    assert_eq!(rec.total_executed, Some(best));
    assert_eq!(p.candidates[0].name, rec.name);
    // Totals are pass 1 × targets + pass 2.
    for c in &p.candidates {
        assert_eq!(
            c.total_executed,
            Some(
                c.executed_per_pixel[0].unwrap() * (c.targets[0] * c.targets[1]) as u64
                    + c.executed_per_pixel[1].unwrap()
            )
        );
        let n = 1280.0 * 1024.0;
        let factor = (c.padded_samples as f64 * 1e-4f64.log2() / n).exp2();
        assert_eq!(c.uncorrected_factor, factor);
    }
    // The article's 97,280 padded samples and its × 0.5048.
    let art = p
        .candidates
        .iter()
        .find(|c| c.name == "unrolled-125x128")
        .unwrap();
    assert_eq!(art.padded_samples, 97_280);
    assert!((art.uncorrected_factor - 0.5048).abs() < 1e-4);
    assert!(!art.f16_safe);
}

#[test]
fn more_slots_change_the_fitted_unroll_and_the_plan() {
    let wide = Profile {
        name: "custom".into(),
        max_slots: 1024,
        ..Profile::ps_3_0()
    };
    let fit = |p: &Profile| {
        let b = set::generate(
            &request(
                (1280, 1024),
                vec![(Pass1Form::Unrolled, set::BlockChoice::Fit)],
            ),
            p,
        )
        .unwrap();
        (b.configs[0].block, b.shaders[0].slots)
    };
    assert_eq!(fit(&Profile::ps_3_0()), ([125, 128], 511));
    let (block, slots) = fit(&wide);
    assert_eq!(block[0], 253);
    assert!(slots <= 1024);
    let a = plan::plan((1280, 1024), &Profile::ps_3_0(), 1e-4).unwrap();
    let b = plan::plan((1280, 1024), &wide, 1e-4).unwrap();
    assert_ne!(a.recommended, b.recommended);
    let total = |p: &plan::Plan| {
        p.candidates
            .iter()
            .find(|c| Some(&c.name) == p.recommended.as_ref())
            .unwrap()
            .total_executed
            .unwrap()
    };
    assert!(total(&b) <= total(&a));
}

#[test]
fn nested_pass2_and_the_macro_form_run_and_agree() {
    // A part with 40 slots: 32×32 blocks of a 640×480 frame give a 20×15
    // target that neither unrolls (600 texld) nor fits as unrolled rows.
    let small = Profile {
        name: "custom".into(),
        max_slots: 40,
        ..Profile::ps_3_0()
    };
    let mut req = request(
        (640, 480),
        vec![(Pass1Form::Loop, set::BlockChoice::Given(32, 32))],
    );
    let b: Bundle = set::generate(&req, &small).unwrap();
    assert!(b.problems.is_empty(), "{:?}", b.problems);
    let p2 = b.shaders.iter().find(|g| g.role == Role::Pass2).unwrap();
    assert_eq!(p2.form, "nested loops");
    let p1 = b.shaders.iter().find(|g| g.role == Role::Pass1).unwrap();
    let img = frame_image(640, 480);
    let r = run(
        &img,
        &ShaderSource::new(&p1.file, &p1.text),
        &ShaderSource::new(&p2.file, &p2.text),
        &Settings {
            block: (32, 32),
            ..Settings::default()
        },
    )
    .unwrap();
    assert!(
        r.all_agree(),
        "{}",
        ps30::present::luminance::run_text("nested", &r, &ps30::present::luminance::Choice::Given)
    );
    assert_eq!(
        r.pass2.executed_emulated,
        Some(cost::Range::exact(p2.executed))
    );

    // --macro keeps REPEAT_BLOCK and loads to the same program.
    req.picks = vec![(Pass1Form::Unrolled, set::BlockChoice::Fit)];
    let plain = set::generate(&req, &Profile::ps_3_0()).unwrap();
    req.macros = true;
    let macros = set::generate(&req, &Profile::ps_3_0()).unwrap();
    assert_eq!(plain.shaders.len(), macros.shaders.len());
    for (a, m) in plain.shaders.iter().zip(&macros.shaders) {
        assert_eq!(a.file, m.file);
        assert!(!a.text.contains("REPEAT_BLOCK"));
        if a.role == Role::Pass1 || a.form == "unrolled" {
            assert!(m.text.contains("BEGIN_REPEAT_BLOCK"), "{}", m.file);
        }
        let program = |t: &str| {
            let l = load::load_str("x", t, &Options::default()).unwrap();
            ps30::core::front::print::write_program(l.shader.program())
        };
        assert_eq!(program(&a.text), program(&m.text), "{}", a.file);
        assert_eq!((a.slots, a.executed), (m.slots, m.executed));
    }
}

#[test]
fn a_frame_too_large_for_two_passes_says_so() {
    let p = plan::plan((65_536, 65_536), &Profile::ps_3_0(), 1e-4).unwrap();
    assert!(p.recommended.is_none());
    assert!(p.candidates.iter().all(|c| c.passes == 3));
    assert!(p
        .candidates
        .iter()
        .all(|c| c.total_executed.is_none() && c.note.as_deref().unwrap().contains("third pass")));
    let b = set::generate(
        &request(
            (65_536, 65_536),
            vec![(Pass1Form::Unrolled, set::BlockChoice::Fit)],
        ),
        &Profile::ps_3_0(),
    )
    .unwrap();
    assert!(b.problems.iter().any(|p| p.contains("third pass")));
    assert!(b.shaders.iter().all(|g| g.role != Role::Pass2));
}
