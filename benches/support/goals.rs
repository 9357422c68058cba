//! The speed goals, worked out from the luminance benchmark's own run: a
//! Markdown table, with the machine stated, that the benchmark prints after
//! criterion's summary and writes beside criterion's results. The README's
//! speed table is this table, pasted.
//!
//! Each goal is a ratio of two entries' typical times — criterion's slope
//! estimate, or its mean when it has no slope: the middle figure it prints
//! after `time:`. An entry counts only if its estimate was written after the
//! run began, so a filtered run never mixes in figures from an older one.
//! Peak memory is not a criterion figure; the README gives it apart.
//!
//! The goals on the CPU (all but the two against llvmpipe) get a second
//! table, from a paired measurement ([`paired`]): criterion times one entry
//! for seconds before the next, and on a shared machine the load drifts in
//! between, so the ratio of two estimates carries the drift. The paired
//! measurement alternates the goal's two workloads in one process, and each
//! ratio comes from two times taken a fraction of a second apart.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Instant, SystemTime};

/// The side of its bound a goal's ratio must lie on (the bound itself
/// included).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// numerator / denominator ≤ this.
    AtMost(f64),
    /// numerator / denominator ≥ this.
    AtLeast(f64),
}

impl Bound {
    fn holds(self, ratio: f64) -> bool {
        match self {
            Bound::AtMost(b) => ratio <= b,
            Bound::AtLeast(b) => ratio >= b,
        }
    }

    /// The bound as the tables state it: `≤ 1.5`, `≥ 1.7`.
    fn stated(self) -> String {
        match self {
            Bound::AtMost(b) => format!("≤ {b}"),
            Bound::AtLeast(b) => format!("≥ {b}"),
        }
    }

    /// `ratio` as the tables show it, with the bound and the verdict:
    /// `1.34 (≤ 1.5) | met`.
    fn judged(self, ratio: f64) -> String {
        let verdict = if self.holds(ratio) {
            "met"
        } else {
            "**not met**"
        };
        format!("{} ({}) | {verdict}", self.shown(ratio), self.stated())
    }

    /// `ratio` to two decimals, or to as many more (up to six) as it takes
    /// for the figure shown to fall on the same side of the bound as the
    /// ratio itself: 1.695 against ≥ 1.7 is not shown as a failing 1.70.
    fn shown(self, ratio: f64) -> String {
        let holds = self.holds(ratio);
        (2..=6)
            .map(|d| format!("{ratio:.d$}"))
            .find(|s| s.parse().is_ok_and(|r: f64| self.holds(r) == holds))
            .unwrap_or_else(|| format!("{ratio}"))
    }
}

/// One goal: the ratio of two benchmark entries and its bound.
pub struct Goal {
    /// The goal in words.
    pub what: &'static str,
    /// The entry on top of the ratio.
    pub numerator: &'static str,
    /// The entry below.
    pub denominator: &'static str,
    /// Where the ratio must lie.
    pub bound: Bound,
}

/// The goals, in the order the README lists them.
pub const GOALS: &[Goal] = &[
    Goal {
        what: "pass 1 at least as fast as llvmpipe's draw of it, one thread",
        numerator: "pass1/1t",
        denominator: "gpu/pass1-draw/1t",
        bound: Bound::AtMost(1.0),
    },
    Goal {
        what: "pass 1 at least as fast as llvmpipe's draw of it, two threads",
        numerator: "pass1/2t",
        denominator: "gpu/pass1-draw/2t",
        bound: Bound::AtMost(1.0),
    },
    Goal {
        what: "both passes at most the f64 reference",
        numerator: "emulate/unrolled",
        denominator: "reference/f64",
        bound: Bound::AtMost(1.0),
    },
    Goal {
        what: "both passes within 2× the native f32 floor",
        numerator: "emulate/unrolled",
        denominator: "native/f32",
        bound: Bound::AtMost(2.0),
    },
    Goal {
        what: "`luminance` on one thread within 1.5× its decoding",
        numerator: "command/luminance/1t",
        denominator: "phase/decode/1t",
        bound: Bound::AtMost(1.5),
    },
    Goal {
        what: "`luminance`: two threads at least 1.7× one",
        numerator: "command/luminance/1t",
        denominator: "command/luminance/2t",
        bound: Bound::AtLeast(1.7),
    },
    Goal {
        what: "`tonemap`: two threads at least 1.7× one",
        numerator: "command/tonemap/1t",
        denominator: "command/tonemap/2t",
        bound: Bound::AtLeast(1.7),
    },
    Goal {
        what: "`run`: two threads at least 1.7× one",
        numerator: "command/run/1t",
        denominator: "command/run/2t",
        bound: Bound::AtLeast(1.7),
    },
];

/// The ratios of a goal's paired runs: their median, lowest and highest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Paired {
    /// The median (the mean of the middle two for an even count).
    pub median: f64,
    /// The lowest ratio.
    pub low: f64,
    /// The highest ratio.
    pub high: f64,
    /// How many ratios.
    pub pairs: usize,
}

impl Paired {
    /// The summary of `ratios` (None for none, or for one that is not a
    /// number).
    pub fn of(mut ratios: Vec<f64>) -> Option<Paired> {
        if ratios.is_empty() || ratios.iter().any(|r| r.is_nan()) {
            return None;
        }
        ratios.sort_by(f64::total_cmp);
        let n = ratios.len();
        let median = if n % 2 == 1 {
            ratios[n / 2]
        } else {
            (ratios[n / 2 - 1] + ratios[n / 2]) / 2.0
        };
        Some(Paired {
            median,
            low: ratios[0],
            high: ratios[n - 1],
            pairs: n,
        })
    }
}

/// Times `numerator` and `denominator` in turn, `pairs` times after one
/// pair that warms up: numerator first in even pairs, denominator first in
/// odd ones, so that neither always runs on the other's leftovers (caches,
/// freed memory). Each pair gives one ratio.
pub fn paired(
    pairs: usize,
    numerator: &mut dyn FnMut(),
    denominator: &mut dyn FnMut(),
) -> Option<Paired> {
    let time = |f: &mut dyn FnMut()| {
        let start = Instant::now();
        f();
        start.elapsed().as_secs_f64()
    };
    time(numerator);
    time(denominator);
    let ratios = (0..pairs)
        .map(|i| {
            if i % 2 == 0 {
                let a = time(numerator);
                a / time(denominator)
            } else {
                let b = time(denominator);
                time(numerator) / b
            }
        })
        .collect();
    Paired::of(ratios)
}

/// The typical time in nanoseconds from the text of criterion's
/// `estimates.json`: the slope's point estimate, or the mean's.
pub fn typical_ns(estimates: &str) -> Option<f64> {
    let v: serde_json::Value = serde_json::from_str(estimates).ok()?;
    let point = |k: &str| v.get(k)?.get("point_estimate")?.as_f64();
    point("slope").or_else(|| point("mean"))
}

/// Every entry of `group` under criterion's output directory `root` whose
/// estimate was written at or after `since`: its name (criterion's function
/// id) and typical time in nanoseconds.
pub fn measured(root: &Path, group: &str, since: SystemTime) -> Vec<(String, f64)> {
    let Ok(dirs) = std::fs::read_dir(root.join(group)) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for dir in dirs.flatten() {
        let new = dir.path().join("new");
        let estimates = new.join("estimates.json");
        let fresh = std::fs::metadata(&estimates)
            .and_then(|m| m.modified())
            .is_ok_and(|t| t >= since);
        let read = |f: &str| std::fs::read_to_string(new.join(f)).ok();
        let id = read("benchmark.json")
            .and_then(|b| serde_json::from_str::<serde_json::Value>(&b).ok())
            .and_then(|b| Some(b.get("function_id")?.as_str()?.to_string()));
        if let (true, Some(id), Some(ns)) = (
            fresh,
            id,
            read("estimates.json").and_then(|e| typical_ns(&e)),
        ) {
            out.push((id, ns));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// Where criterion may have written its results, in the order it chooses
/// them: `$CRITERION_HOME`, `$CARGO_TARGET_DIR/criterion`, the target
/// directory the benchmark was built in (when cargo runs it), and
/// `./target/criterion`. [`measured`]'s freshness test tells which one this
/// run wrote.
pub fn criterion_dirs() -> Vec<PathBuf> {
    let mut dirs = Vec::new();
    dirs.extend(std::env::var_os("CRITERION_HOME").map(PathBuf::from));
    if let Some(t) = std::env::var_os("CARGO_TARGET_DIR") {
        dirs.push(PathBuf::from(t).join("criterion"));
    }
    // target/<profile>/deps/<benchmark>
    if let Ok(exe) = std::env::current_exe() {
        dirs.extend(exe.ancestors().nth(3).map(|t| t.join("criterion")));
    }
    dirs.push(PathBuf::from("target/criterion"));
    dirs
}

/// A duration in nanoseconds as milliseconds to three or four figures.
fn ms(ns: f64) -> String {
    let ms = ns / 1e6;
    if ms >= 100.0 {
        format!("{ms:.1} ms")
    } else {
        format!("{ms:.2} ms")
    }
}

/// The goals' table for the entries `times` measured on `machine`.
pub fn table(machine: &str, times: &[(String, f64)]) -> String {
    let time = |name: &str| times.iter().find(|(n, _)| n == name).map(|&(_, t)| t);
    let mut out = format!(
        "Speed goals on {machine} (criterion's typical times, one run):\n\n\
         | goal | measured | ratio | |\n|---|---|---|---|\n"
    );
    for g in GOALS {
        let row = match (time(g.numerator), time(g.denominator)) {
            (Some(a), Some(b)) => format!(
                "`{}` {} / `{}` {} | {}",
                g.numerator,
                ms(a),
                g.denominator,
                ms(b),
                g.bound.judged(a / b)
            ),
            _ => format!(
                "`{}` / `{}` not measured in this run | | —",
                g.numerator, g.denominator
            ),
        };
        let _ = writeln!(out, "| {} | {row} |", g.what);
    }
    out
}

/// The paired measurement's table: each goal's lowest and highest ratio,
/// and the median judged against its bound.
pub fn paired_table(rows: &[(&Goal, Paired)]) -> String {
    let Some(pairs) = rows.first().map(|(_, p)| p.pairs) else {
        return String::new();
    };
    let mut out = format!(
        "The goals on the CPU, paired: each goal's two workloads timed in turn in one \
         process, {pairs} times (the lowest and highest of the {pairs} ratios, and their median, \
         judged):\n\n| goal | workloads | lowest – highest | median | |\n|---|---|---|---|---|\n"
    );
    for (g, p) in rows {
        let _ = writeln!(
            out,
            "| {} | `{}` / `{}` | {:.2} – {:.2} | {} |",
            g.what,
            g.numerator,
            g.denominator,
            p.low,
            p.high,
            g.bound.judged(p.median)
        );
    }
    out
}

/// The machine in one line: the processor, its logical CPUs, AVX2 when the
/// emulator's vector paths can use it, and the peer's device (`peer`: the
/// CPU adapter's name, if one was opened).
pub fn machine(peer: Option<&str>) -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|c| {
            let line = c.lines().find(|l| l.starts_with("model name"))?;
            Some(line.split_once(':')?.1.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string());
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    #[cfg(target_arch = "x86_64")]
    let avx2 = if std::arch::is_x86_feature_detected!("avx2") {
        " with AVX2"
    } else {
        " without AVX2"
    };
    #[cfg(not(target_arch = "x86_64"))]
    let avx2 = "";
    let peer = peer.map_or("no CPU Vulkan adapter for the peer".to_string(), |p| {
        format!("the peer: the GPU backend on {p}")
    });
    format!("{cpu}, {cpus} logical CPUs{avx2}; {peer}")
}
