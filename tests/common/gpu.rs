//! The GPU for tests that draw on one: opened once per test binary. Without
//! an adapter a test says on the terminal that it was skipped and why;
//! with `CI` set a missing adapter fails it instead (CI installs Mesa's
//! Vulkan drivers, so there must be one).

use ps30::core::gpu::Gpu;
use std::io::Write;
use std::sync::{Arc, OnceLock};

/// The device, or `None` (after saying so) when there is none.
pub fn gpu(test: &str) -> Option<Arc<Gpu>> {
    static GPU: OnceLock<Result<Arc<Gpu>, String>> = OnceLock::new();
    match GPU.get_or_init(|| Gpu::open().map(Arc::new).map_err(|e| e.to_string())) {
        Ok(g) => Some(g.clone()),
        Err(e) if std::env::var_os("CI").is_some() => {
            panic!("{test}: CI is set, so the GPU tests need an adapter: {e}")
        }
        Err(e) => {
            // Written to the terminal directly: the test harness captures
            // print! and eprint!, and a skip must be seen.
            let _ = writeln!(std::io::stderr(), "{test}: skipped: {e}");
            None
        }
    }
}
