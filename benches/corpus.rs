//! Corpus mode's speed and memory: 15,000 typical listings checked by one
//! `ps30 check DIR` on two threads. The listings are Microsoft's compiler
//! output for the HLSL corpus of `tests/oracle/` (the `.dis` fixtures, real
//! `D3DDisassemble` listings of shaders written the way games write them),
//! copied round-robin into 15,000 files of a temporary directory at set-up.
//! The goal: under 10 s on a 2-core machine. After criterion's estimate the
//! benchmark prints the goal's line with the machine, and the peak memory of
//! the same run over 1,500 and 15,000 files (it must not grow with the
//! number of files).

use criterion::{criterion_group, criterion_main, Criterion};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// Files in the corpus.
const FILES: usize = 15_000;
/// The goal, seconds for the whole corpus.
const GOAL_S: f64 = 10.0;

/// Every `.dis` fixture of the HLSL corpus.
fn listings() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/oracle/fixtures/hlsl");
    let mut out = Vec::new();
    let mut dirs = vec![root];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|x| x == "dis") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// `n` files copied round-robin from the listings, 1,000 to a folder.
fn corpus(dir: &Path, n: usize) {
    let src = listings();
    assert!(
        !src.is_empty(),
        "no listings under tests/oracle/fixtures/hlsl"
    );
    let texts: Vec<Vec<u8>> = src.iter().map(|p| std::fs::read(p).unwrap()).collect();
    for i in 0..n {
        let sub = dir.join(format!("{:02}", i / 1000));
        if i % 1000 == 0 {
            std::fs::create_dir_all(&sub).unwrap();
        }
        std::fs::write(sub.join(format!("{i:05}.dis")), &texts[i % texts.len()]).unwrap();
    }
}

/// `ps30 check DIR --threads 2 -q`, its wall time and peak resident memory
/// in KB; the run must succeed (exit 0 or 1: listings over a limit count
/// as results, not failures).
fn check(dir: &Path) -> (Duration, i64) {
    let start = Instant::now();
    // Waited for by wait4 below (for its resource usage), not by Child::wait.
    #[allow(clippy::zombie_processes)]
    let child = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(["check", "--threads", "2", "-q"])
        .arg(dir)
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("run ps30");
    let mut status = 0;
    // SAFETY: an all-zero rusage is a valid value; wait4 fills it for the
    // child just spawned, which nothing else waits for.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let pid = unsafe { libc::wait4(child.id() as i32, &mut status, 0, &mut usage) };
    let took = start.elapsed();
    assert_eq!(pid, child.id() as i32, "wait4");
    let code = libc::WEXITSTATUS(status);
    assert!(code == 0 || code == 1, "ps30 check exited {code}");
    (took, usage.ru_maxrss)
}

/// The machine, as the goal's line names it.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|c| {
            c.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_string())
        })
        .unwrap_or_else(|| "an unknown CPU".into());
    let n = std::thread::available_parallelism().map_or(0, |n| n.get());
    format!("{cpu}, {n} logical CPUs")
}

fn corpus_check(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    corpus(dir.path(), FILES);
    let mut group = c.benchmark_group("corpus");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(30));
    let mut times = Vec::new();
    group.bench_function("check/15000/2t", |b| {
        b.iter_custom(|iters| {
            let mut total = Duration::ZERO;
            for _ in 0..iters {
                let (t, _) = check(dir.path());
                times.push(t.as_secs_f64());
                total += t;
            }
            total
        })
    });
    group.finish();
    times.sort_by(f64::total_cmp);
    let median = times[times.len() / 2];
    let small = tempfile::tempdir().unwrap();
    corpus(small.path(), FILES / 10);
    let (_, rss_small) = check(small.path());
    let (_, rss_large) = check(dir.path());
    println!(
        "\nCorpus mode on {}: `ps30 check` of {FILES} listings on 2 threads, median of {} runs: {median:.2} s ({:.2} of the {GOAL_S} s goal: {})",
        machine(),
        times.len(),
        median / GOAL_S,
        if median < GOAL_S { "met" } else { "missed" }
    );
    println!(
        "peak memory: {rss_small} KB for {} files, {rss_large} KB for {FILES} ({:.2}×)",
        FILES / 10,
        rss_large as f64 / rss_small as f64
    );
}

criterion_group!(benches, corpus_check);
criterion_main!(benches);
