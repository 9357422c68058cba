//! The studies' numbers, asserted from ps30's own computation, each with the
//! bound or the derivation it is held to written beside it.

use crate::common::bin;

use bin::{ps30, repo};
use ps30::core::image::{self, HdrImage, OddSides};
use ps30::jobs::studies::log_lights::{self, Method, Study, SWEEP_BRIGHTNESS, WIDTH};
use ps30::jobs::studies::{article_chain, mip_luminance};

/// Half an 8-bit code.
const Q: f64 = 0.5 / 255.0;

fn log_study() -> Study {
    log_lights::study(&Default::default(), &|_, _| {}).unwrap()
}

fn find(s: &[log_lights::Summary], m: Method, lights: u32, b: f32) -> &log_lights::Summary {
    s.iter()
        .find(|x| x.method == m && x.lights == lights && x.brightness == b)
        .unwrap()
}

/// Every pixel of every configuration within its derived bound (the bounds
/// are derived in the module docs of `jobs/studies/log_lights.rs`), and the
/// seed's claims in numbers:
///
/// * **Range.** Raw RGBA8 holds sums up to 1 − K·q (one light: 1 − q);
///   past that a pixel is out of range. The swept ramp steps by
///   10/1024, so the first out-of-range pixel is within one step above
///   1 − q. A log buffer is out of range once q·2^S ≥ ½·(1 − ρ), i.e. from
///   S = log2(255·(1 − ρ)) ≈ log2(255) = 7.994 (ρ = 2⁻²¹ + 2⁻²⁴): again
///   within a step above. Half floats never leave their range below 10.
/// * **Dim lights.** Raw RGBA8 rounds to the nearest code: error ≤ q (plus
///   f32 roundings of 10⁻⁷). A log buffer near light x stores codes c with
///   −log2(c/255); neighbouring codes are 1/(255·ln 2·2^−x) apart in light,
///   so its error reaches half of that: up to q·2^0.1/ln 2 = 0.00303 below
///   0.1, more than raw RGBA8 can ever be off.
/// * **Levels.** Lights 0 … 0.1 come back as the codes k/255 ≤ 0.1 + q, k =
///   0 … 25: 26 levels raw; as −log2(c/255) for c = 238 … 255 (255·2^−0.1 =
///   237.9): 18 levels in the log buffer.
#[test]
fn log_lights_against_raw_and_half_accumulation() {
    let s = log_study();
    assert!(s.all_agree());
    let step = SWEEP_BRIGHTNESS as f64 / WIDTH as f64;
    let sweep = |m: Method| s.sweep.iter().find(|a| a.method == m).unwrap().summary();
    let raw_end = sweep(Method::Rgba8).range_ends_at.unwrap();
    assert!((1.0 - Q..=1.0 - Q + step).contains(&raw_end), "{raw_end}");
    let log_end = sweep(Method::LogRgba8).range_ends_at.unwrap();
    let rho = 2f64.powi(-21) + 2f64.powi(-24);
    let start = (255.0 * (1.0 - rho)).log2();
    assert!((start..=start + step).contains(&log_end), "{log_end}");
    assert_eq!(sweep(Method::Half).range_ends_at, None);

    let raw = find(&s.brightness, Method::Rgba8, 1, 0.1);
    let log = find(&s.brightness, Method::LogRgba8, 1, 0.1);
    assert!(
        raw.max_error_dim <= Q * (1.0 + 1e-4),
        "{}",
        raw.max_error_dim
    );
    let log_half_step = Q * 2f64.powf(0.1) / std::f64::consts::LN_2;
    assert!(log.max_error_dim > Q, "log lights are worse on dim lights");
    assert!(
        log.max_error_dim <= log_half_step * (1.0 + 1e-3),
        "{}",
        log.max_error_dim
    );
    assert_eq!((raw.levels_dim, log.levels_dim), (26, 18));

    // Brightness 2 and 3: raw RGBA8 misses everything above 1 (its largest
    // error is the peak minus 1); the log buffer stays within its range.
    for b in [2.0, 3.0] {
        let raw = find(&s.brightness, Method::Rgba8, 1, b);
        assert!((raw.max_error - (raw.peak - 1.0)).abs() <= Q, "b = {b}");
        assert_eq!(
            find(&s.brightness, Method::LogRgba8, 1, b).range_ends_at,
            None
        );
    }
    // K overlapping lights of brightness 1: 8 of them reach 7.996, past the
    // log buffer's range (its products fall to one code or less).
    let k8 = find(&s.overlaps, Method::LogRgba8, 8, 1.0);
    assert!(k8.range_ends_at.is_some_and(|e| e < 8.0));
    assert!(find(&s.overlaps, Method::LogRgba8, 4, 1.0)
        .range_ends_at
        .is_none());
}

fn load(name: &str) -> HdrImage {
    image::load(&repo().join("assets/hdr").join(name), &Default::default()).unwrap()
}

/// The mip-chain method on a power-of-two frame and on the article's frame
/// with its crops:
///
/// * every 1×1 result within the quantisation bound (n + 1 half-codes plus
///   the shader's f32 error; derived in `jobs/studies/mip_luminance.rs`);
/// * a power-of-two frame weights every pixel 1/N: the weighted f64 mean is
///   the plain one;
/// * 1280 = 5·256: the folded chain's last step 5 → 2 → 1 gives two fifths
///   of the columns ¼·(1/256) and three fifths ⅙·(1/256), so
///   ½·Σ|w − 1/N| = ½·(0.4·(1.25 − 1) + 0.6·(1 − 5/6)) = 0.1 exactly;
/// * the 8-bit drift is upwards: a 2 × 2 average of codes ends in .5 for a
///   quarter of the residues and the FLOAT → UNORM rule rounds it up, so
///   with residues spread evenly each level adds ⅛ code on average —
///   n/8 = 1.25 codes for the 10 levels after the base (the crops have 9);
///   the mean drift over the runs is held to within a factor 2 of that;
/// * the article's two passes are more than ten times closer to the truth
///   than the mips with [2^−8, 2^8] on every uncropped frame;
/// * the clamped-pixel counts agree with a count made here from the image.
#[test]
fn mip_luminance_on_a_power_of_two_frame_and_the_articles_frame() {
    let images = vec![
        ("courtyard.exr".to_string(), load("courtyard.exr")),
        (
            "courtyard_1280x1024.exr".to_string(),
            load("courtyard_1280x1024.exr"),
        ),
    ];
    let s = mip_luminance::study(&images, 1e-4, &Default::default(), &|_, _| {}).unwrap();
    assert!(s.all_agree());
    assert_eq!(s.frames.len(), 2 + mip_luminance::CROPS.len());
    let runs: Vec<&mip_luminance::MipRun> = s
        .frames
        .iter()
        .flat_map(|f| f.runs.iter().chain(&f.bilinear))
        .chain(&s.sweep)
        .collect();
    let mean_drift = runs.iter().map(|r| r.quantisation_codes).sum::<f64>() / runs.len() as f64;
    assert!(runs.iter().all(|r| r.quantisation_codes > 0.0));
    assert!(
        (1.25 / 2.0..=1.25 * 2.0).contains(&mean_drift),
        "{mean_drift}"
    );

    let pow2 = &s.frames[0];
    assert!(pow2.bilinear.is_none() && pow2.weight_bound == 0.0);
    for r in &pow2.runs {
        assert!((r.ideal_weighted / r.ideal_uniform - 1.0).abs() < 1e-12);
    }
    let article = &s.frames[1];
    assert!(
        (article.weight_bound - 0.1).abs() < 1e-12,
        "{}",
        article.weight_bound
    );
    assert!((ps30::core::image::weight_bound(1280, 1024, OddSides::Fold) - 0.1).abs() < 1e-12);
    for f in &s.frames[..2] {
        let r = f.runs.iter().find(|r| r.range == (8.0, 8.0)).unwrap();
        assert!(f.article.agree);
        assert!(
            r.relative_error.abs() > 10.0 * f.article.relative_error.abs(),
            "{}",
            f.image
        );
    }
    // Clamped pixels, counted here: log2|δ + L| below −min or above max.
    let img = &images[0].1;
    for r in &pow2.runs {
        let (mut below, mut above) = (0u64, 0u64);
        for &p in &img.pixels {
            let l = (1e-4f32 as f64 + image::luminance(p)).abs().log2();
            if l < -r.range.0 {
                below += 1;
            } else if l > r.range.1 {
                above += 1;
            }
        }
        assert_eq!((r.below, r.above), (below, above), "{:?}", r.range);
    }
}

/// The article's chain at a small size: every channel of the accumulated
/// lights within its half-float rounding bound, L̄w and the tone map within
/// theirs, every draw's count equal to the cost model's.
#[test]
fn the_articles_chain_end_to_end() {
    let r = article_chain::run(
        (256, 192),
        &article_chain::default_lights(),
        &Default::default(),
        &Default::default(),
        &|_, _| {},
    )
    .unwrap();
    assert!(r.all_agree());
    assert_eq!(r.sum.channels, 256 * 192 * 3);
    assert!(r.sum.largest_fraction <= 1.0 && r.sum.max_error > 0.0);
    assert_eq!(r.steps.len(), 1 + article_chain::default_lights().len());
}

/// `ps30 plan`'s mip-chain candidate, by hand: 1280×1024 has 11 levels (10
/// after the base); its 8-bit bound is 11 half-codes of 16 stops,
/// 11·0.5/255·16 = 0.34510 stops; its odd sides move the mean by at most
/// 0.1 (above) × 16 = 1.6 stops. 1024×512 has no odd sides.
#[test]
fn the_plan_lists_the_mip_method_with_its_predicted_error() {
    use ps30::core::cost::Profile;
    use ps30::jobs::gen::plan;
    let p = plan::plan((1280, 1024), &Profile::ps_3_0(), 1e-4).unwrap();
    let m = &p.approximate;
    assert_eq!((m.levels, m.slots, m.executed_per_pixel), (10, 6, 6));
    assert_eq!(m.total_executed, 6 * 1280 * 1024);
    assert!((m.quantisation_stops - 11.0 * 0.5 / 255.0 * 16.0).abs() < 1e-12);
    assert!((m.odd_sides_stops - 1.6).abs() < 1e-12);
    let q = plan::plan_with_range((1024, 512), &Profile::ps_3_0(), 1e-4, (4.0, 12.0)).unwrap();
    assert_eq!(q.approximate.odd_sides_stops, 0.0);
    assert!(
        (q.approximate.predicted_relative_error - (q.approximate.quantisation_stops).exp2() + 1.0)
            .abs()
            < 1e-12
    );
    // The exact forms are still ranked and recommended without it.
    assert!(p.recommended.is_some());
    let o = ps30(
        &["plan", "--frame", "1280x1024", "--log-range", "8,8"],
        repo(),
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("approximate alternative (not ranked)"),
        "{text}"
    );
    assert!(text.contains("0.345 stops from 8-bit steps"), "{text}");
    let o = ps30(&["plan", "--frame", "64x64", "--log-range", "3,-3"], repo());
    assert_eq!(o.status.code(), Some(2));
}

/// `ps30 study` writes its page and figures, byte for byte the same with
/// one thread and with two.
#[test]
fn study_pages_are_the_same_for_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    for (name, extra) in [
        ("log-lights", vec![]),
        ("article-chain", vec!["--size", "96x64"]),
    ] {
        let mut outs = Vec::new();
        for threads in ["1", "2"] {
            let d = dir.path().join(format!("{name}-{threads}"));
            let mut args = vec![
                "study",
                name,
                "--reports",
                d.to_str().unwrap(),
                "--threads",
                threads,
            ];
            args.extend(&extra);
            let o = ps30(&args, repo());
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            outs.push(d);
        }
        let page = format!("{name}.md");
        let read = |d: &std::path::Path, f: &str| std::fs::read(d.join(f)).unwrap();
        assert_eq!(read(&outs[0], &page), read(&outs[1], &page), "{page}");
        for f in std::fs::read_dir(outs[0].join("figures")).unwrap() {
            let f = format!("figures/{}", f.unwrap().file_name().to_string_lossy());
            assert_eq!(read(&outs[0], &f), read(&outs[1], &f), "{f}");
        }
    }
}

/// `study article-chain -o FRAME.png` writes the frame where the user named
/// it (here the working directory, outside the reports folder), beside the page.
#[test]
fn study_frame_goes_where_o_says() {
    let dir = tempfile::tempdir().unwrap();
    let reports = dir.path().join("reports");
    let o = ps30(
        &[
            "study",
            "article-chain",
            "--size",
            "32x32",
            "--reports",
            reports.to_str().unwrap(),
            "-o",
            "frame.png",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let png = std::fs::read(dir.path().join("frame.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    assert!(reports.join("article-chain.md").is_file());
    assert!(!reports.join("frame.png").exists());
}
