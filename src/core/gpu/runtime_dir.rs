//! A runtime directory for the Vulkan driver. Opening a Vulkan instance
//! loads Mesa's drivers, whose window-system code asks libwayland for a
//! display; libwayland prints "error: XDG_RUNTIME_DIR is invalid or not set
//! in the environment." when that variable is unset or not an absolute
//! path — on every server, container and CI runner, where no session set
//! it — although nothing is wrong and ps30 draws off screen. Where it is
//! missing, ps30 sets it for its own process to a private directory
//! (`$TMPDIR/ps30-runtime-UID`, mode 0700, made once and kept), as a login
//! session would; a variable the user set is never changed, and every other
//! message of the driver still reaches stderr.

use std::path::{Path, PathBuf};
use std::sync::Once;

/// Sets `XDG_RUNTIME_DIR` for this process, once, before the first
/// instance, when it is unset or not an absolute directory (see the module
/// docs). Does nothing when no private directory can be had (then the
/// driver's message appears as before).
pub(super) fn ensure() {
    static DONE: Once = Once::new();
    DONE.call_once(|| {
        let set = std::env::var_os("XDG_RUNTIME_DIR")
            .is_some_and(|d| Path::new(&d).is_absolute() && Path::new(&d).is_dir());
        if set {
            return;
        }
        if let Some(dir) = private_dir() {
            // Set before the driver is loaded, from the one thread that
            // opens the device; no other code of ps30 reads it.
            std::env::set_var("XDG_RUNTIME_DIR", dir);
        }
    });
}

/// `$TMPDIR/ps30-runtime-UID`, made with mode 0700 if missing; `None` when
/// it cannot be made or is not a directory only this user can enter.
#[cfg(target_os = "linux")]
fn private_dir() -> Option<PathBuf> {
    use std::os::unix::fs::{DirBuilderExt, MetadataExt};
    let uid = std::fs::metadata("/proc/self").ok()?.uid();
    let dir = std::env::temp_dir().join(format!("ps30-runtime-{uid}"));
    let _ = std::fs::DirBuilder::new().mode(0o700).create(&dir);
    let meta = std::fs::symlink_metadata(&dir).ok()?;
    let private = meta.is_dir() && meta.uid() == uid && meta.mode() & 0o777 == 0o700;
    private.then_some(dir)
}

/// Elsewhere the variable means nothing to the drivers.
#[cfg(not(target_os = "linux"))]
fn private_dir() -> Option<PathBuf> {
    None
}
