//! Phase timestamps for speed work: where a command's wall time goes, read
//! on the machine it runs on without a profiler (the GPU machines measured
//! in docs/speed.md have none).
//!
//! With the environment variable `PS30_PHASES` set, each [`mark`] writes
//! one line to stderr: milliseconds since the first mark of the process,
//! the thread, and what just finished. Without it a mark costs one load
//! of a cached flag.

use std::io::Write;
use std::sync::OnceLock;
use std::time::Instant;

/// The first mark's time, or `None` when `PS30_PHASES` is not set.
fn origin() -> Option<Instant> {
    static ORIGIN: OnceLock<Option<Instant>> = OnceLock::new();
    *ORIGIN.get_or_init(|| std::env::var_os("PS30_PHASES").map(|_| Instant::now()))
}

/// Writes `label` with the time since the first mark, if `PS30_PHASES` is set.
pub fn mark(label: &str) {
    if let Some(t0) = origin() {
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        let thread = std::thread::current();
        let name = thread.name().unwrap_or("-");
        let _ = writeln!(
            std::io::stderr().lock(),
            "phase {ms:9.2} ms [{name}] {label}"
        );
    }
}

/// Whether marks are written (to skip building their labels).
pub fn on() -> bool {
    origin().is_some()
}
