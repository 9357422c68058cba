//! The luminance benchmark's goals' table (`benches/support/goals.rs`):
//! which estimate it reads, which entries it trusts, and how it judges each
//! ratio against its bound.

// The benchmark uses all of it; these tests leave out what reads the
// machine and the environment.
#[allow(dead_code)]
#[path = "../benches/support/goals.rs"]
mod goals;

use goals::{measured, paired, paired_table, table, typical_ns, Paired, GOALS};
use std::time::{Duration, SystemTime};

/// An `estimates.json` as criterion writes it, cut to the fields read.
fn estimates(mean: f64, slope: Option<f64>) -> String {
    let slope = slope.map_or("null".to_string(), |s| {
        format!("{{\"point_estimate\":{s}}}")
    });
    format!("{{\"mean\":{{\"point_estimate\":{mean}}},\"slope\":{slope}}}")
}

#[test]
fn the_typical_time_is_the_slope_or_else_the_mean() {
    assert_eq!(typical_ns(&estimates(5.0, Some(4.0))), Some(4.0));
    assert_eq!(typical_ns(&estimates(5.0, None)), Some(5.0));
    assert_eq!(typical_ns("{}"), None);
    assert_eq!(typical_ns("not json"), None);
}

/// Writes one entry the way criterion lays it out, its estimate last
/// modified at `written`.
fn entry(root: &std::path::Path, dir: &str, id: &str, ns: f64, written: SystemTime) {
    let new = root.join("g").join(dir).join("new");
    std::fs::create_dir_all(&new).unwrap();
    let b = format!("{{\"group_id\":\"g\",\"function_id\":\"{id}\"}}");
    std::fs::write(new.join("benchmark.json"), b).unwrap();
    let e = new.join("estimates.json");
    std::fs::write(&e, estimates(ns, Some(ns))).unwrap();
    let f = std::fs::File::options().write(true).open(&e).unwrap();
    f.set_modified(written).unwrap();
}

#[test]
fn only_entries_written_since_the_run_began_count() {
    let d = tempfile::tempdir().unwrap();
    let since = SystemTime::now();
    entry(
        d.path(),
        "pass1_1t",
        "pass1/1t",
        2e6,
        since + Duration::from_secs(1),
    );
    entry(
        d.path(),
        "old",
        "reference/f64",
        9e6,
        since - Duration::from_secs(60),
    );
    entry(d.path(), "emulate_unrolled", "emulate/unrolled", 3e6, since);
    let got = measured(d.path(), "g", since);
    let want = [
        ("emulate/unrolled".to_string(), 3e6),
        ("pass1/1t".to_string(), 2e6),
    ];
    assert_eq!(got, want);
    assert!(measured(d.path(), "no such group", since).is_empty());
}

/// The table's row for the goal `what`.
fn row<'a>(t: &'a str, what: &str) -> &'a str {
    t.lines()
        .find(|l| l.starts_with(&format!("| {what} |")))
        .unwrap_or_else(|| panic!("no row for {what} in\n{t}"))
}

#[test]
fn each_ratio_is_judged_against_its_bound_the_bound_included() {
    let times: Vec<(String, f64)> = [
        ("emulate/unrolled", 6.0e6),
        ("reference/f64", 6.0e6), // exactly at ≤ 1: met
        ("native/f32", 2.9e6),    // 2.07 > 2: not met
        ("command/luminance/1t", 75.0e6),
        ("command/luminance/2t", 44.0e6), // 1.70: met
        ("command/run/1t", 55.99e6),
        ("command/run/2t", 33.03e6), // 1.6951… < 1.7: not met, though 1.70 to two decimals
        ("command/tonemap/1t", 0.0),
        ("command/tonemap/2t", 0.0), // 0 / 0: NaN passes no bound
    ]
    .map(|(n, t)| (n.to_string(), t))
    .into();
    let t = table("a test machine", &times);
    assert!(t.starts_with("Speed goals on a test machine"));
    let at_reference = row(&t, GOALS[2].what);
    assert!(
        at_reference.ends_with("| 1.00 (≤ 1) | met |"),
        "{at_reference}"
    );
    assert!(at_reference.contains("`emulate/unrolled` 6.00 ms / `reference/f64` 6.00 ms"));
    let floor = row(&t, GOALS[3].what);
    assert!(floor.ends_with("| 2.07 (≤ 2) | **not met** |"), "{floor}");
    assert!(row(&t, GOALS[5].what).ends_with("| 1.70 (≥ 1.7) | met |"));
    // Shown with the decimals that keep the figure on the ratio's side.
    let run = row(&t, GOALS[7].what);
    assert!(run.ends_with("| 1.695 (≥ 1.7) | **not met** |"), "{run}");
    assert!(row(&t, GOALS[6].what).ends_with("| NaN (≥ 1.7) | **not met** |"));
    // A goal with an entry missing from the run says so instead of a ratio.
    assert!(row(&t, GOALS[0].what).contains("not measured in this run"));
    assert!(row(&t, GOALS[4].what).contains("not measured in this run"));
    assert_eq!(
        t.lines().filter(|l| l.starts_with("| ")).count(),
        GOALS.len() + 1
    );
}

#[test]
fn every_goal_names_two_entries_of_the_benchmark() {
    let bench = include_str!("../benches/luminance.rs");
    for g in GOALS {
        for entry in [g.numerator, g.denominator] {
            // Entries are named in the benchmark as literals or as
            // `format!("…/{t}t")` for t in 1 and 2.
            let templated = entry.replace("/1t", "/{t}t").replace("/2t", "/{t}t");
            assert!(
                bench.contains(&format!("\"{entry}\""))
                    || bench.contains(&format!("\"{templated}\"")),
                "{entry} is not an entry of benches/luminance.rs"
            );
        }
    }
}

#[test]
fn paired_ratios_are_summed_up_by_their_median_and_extremes() {
    let odd = Paired::of(vec![1.9, 1.6, 1.8]).unwrap();
    assert_eq!(
        (odd.median, odd.low, odd.high, odd.pairs),
        (1.8, 1.6, 1.9, 3)
    );
    // An even count: the mean of the middle two.
    let even = Paired::of(vec![1.0, 4.0, 2.0, 3.0]).unwrap();
    assert_eq!((even.median, even.low, even.high), (2.5, 1.0, 4.0));
    assert_eq!(Paired::of(Vec::new()), None);
    assert_eq!(Paired::of(vec![1.0, f64::NAN]), None);
}

/// The order the paired measurement runs its workloads in: one pair to warm
/// up, then the numerator first and the denominator first in turn.
#[test]
fn paired_workloads_take_turns_going_first() {
    let calls = std::cell::RefCell::new(String::new());
    // Each workload lasts until the clock has moved, so that no time is 0
    // and no ratio 0/0 (which would leave no summary).
    let tick = || {
        let start = std::time::Instant::now();
        while start.elapsed().is_zero() {}
    };
    let mut a = || {
        calls.borrow_mut().push('a');
        tick();
    };
    let mut b = || {
        calls.borrow_mut().push('b');
        tick();
    };
    let p = paired(4, &mut a, &mut b).unwrap();
    assert_eq!(
        calls.into_inner(),
        "ab".to_string() + "ab" + "ba" + "ab" + "ba"
    );
    assert_eq!(p.pairs, 4);
}

#[test]
fn the_paired_table_judges_each_median_against_its_bound() {
    let goal = |numerator: &str| GOALS.iter().find(|g| g.numerator == numerator).unwrap();
    let lum = goal("command/luminance/1t"); // ≤ 1.5 over decoding
    let run = goal("command/run/1t"); // ≥ 1.7 over two threads
    let rows = [
        (lum, Paired::of(vec![1.3, 1.6, 1.4]).unwrap()),
        (run, Paired::of(vec![1.65, 1.8, 1.695]).unwrap()),
    ];
    let t = paired_table(&rows);
    assert!(t.contains("3 times"), "{t}");
    assert!(
        t.contains(
            "| `command/luminance/1t` / `phase/decode/1t` | 1.30 – 1.60 | 1.40 (≤ 1.5) | met |"
        ),
        "{t}"
    );
    // A median of 1.695 is shown as it is, not rounded up to a passing 1.70.
    assert!(
        t.contains(
            "| `command/run/1t` / `command/run/2t` | 1.65 – 1.80 | 1.695 (≥ 1.7) | **not met** |"
        ),
        "{t}"
    );
    assert_eq!(paired_table(&[]), "");
}
