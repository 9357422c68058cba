//! The device's teardown, handed to a child process at exit.
//!
//! Closing a hardware device takes its driver 45–60 ms on an NVIDIA H200
//! (measured with a bare Vulkan program: `vkDestroyDevice` 24–29 ms,
//! `vkDestroyInstance` 20–23 ms, 12 ms more to free 266 MB of mapped
//! memory), and a process that leaves the device open pays the same in the
//! kernel while it exits — after its work is done and its output written,
//! but before its parent sees it end: a quarter of a 3840×2160 `luminance`
//! on the GPU (docs/speed.md). [`hand_off_at_exit`] moves that work out of
//! the command's time: just before the process ends, a child process is
//! made that shares its address space and holds its own copies of the open
//! files (the driver's among them), so the files stay open while the process
//! exits. The child waits on a pipe whose writing end only the process
//! holds: the pipe closes when the process's last thread has ended, and the
//! child then ends, and with it the device — the driver's teardown runs in
//! the child. (Waiting for the parent with `PR_SET_PDEATHSIG` instead would
//! end the child when the process's main thread ends, while other threads
//! may still hold the files: then the last of them pays the teardown, as
//! half of the runs on an H200 did.) The child closes its standard streams
//! first, so a reader of ps30's output sees the end of it when ps30 ends. A
//! CPU device (llvmpipe) has no kernel objects to tear
//! down and is left as it was.

use std::sync::atomic::{AtomicBool, Ordering};

/// Whether this process opened a device that is not a CPU one.
static HARDWARE: AtomicBool = AtomicBool::new(false);

/// Notes that a hardware device (not a CPU one) was opened.
pub(crate) fn note_hardware() {
    HARDWARE.store(true, Ordering::Relaxed);
}

/// Call as the last thing before the process ends with exit status `code`,
/// its output flushed: where a hardware device was opened, its teardown is
/// left to a child process (see the module's documentation) and the process
/// ends here, without running exit handlers (the driver's own among them);
/// otherwise this returns and the process ends as usual.
pub fn hand_off_at_exit(code: u8) {
    if !HARDWARE.load(Ordering::Relaxed) {
        return;
    }
    #[cfg(target_os = "linux")]
    if linux::hand_off() {
        // SAFETY: ends the process; every output was flushed by the caller.
        unsafe { libc::_exit(code as libc::c_int) };
    }
    #[cfg(not(target_os = "linux"))]
    let _ = code;
}

/// Leaves `value` to be freed with the process's address space where a
/// hardware device was opened, and drops it here otherwise: call it as a
/// command ends, with what it no longer needs. The address space is shared
/// with the teardown's child ([`hand_off_at_exit`]), so its pages go back
/// to the kernel after the command has ended, not before: freeing the
/// 133 MB of a decoded 3840×2160 image (tens of thousands of pages) is
/// work the command need not wait for (docs/speed.md). Without a device
/// there is no child, the process's exit would free the pages itself, and
/// dropping the value now costs the same.
pub fn leave_at_exit<T>(value: T) {
    if cfg!(target_os = "linux") && HARDWARE.load(Ordering::Relaxed) {
        std::mem::forget(value);
    }
}

#[cfg(target_os = "linux")]
mod linux {
    /// The child's stack: it calls a few system calls and nothing else.
    const STACK: usize = 64 * 1024;

    /// What the child does: closes its copies of the standard streams and of
    /// the pipe's writing end, waits until the pipe closes (the parent
    /// process has ended) and ends. It shares the parent's memory
    /// (`CLONE_VM`), so it touches nothing but its stack and makes only
    /// system calls.
    extern "C" fn child(pipe: *mut libc::c_void) -> libc::c_int {
        let [read, write] = unpack(pipe);
        // SAFETY: plain system calls on the child's own file table.
        unsafe {
            for fd in [0, 1, 2, write] {
                libc::syscall(libc::SYS_close, fd);
            }
            // Every signal blocked, so the read ends only with the pipe (or
            // with SIGKILL, which ends the child as well).
            let all = [!0u64; 1];
            libc::syscall(
                libc::SYS_rt_sigprocmask,
                libc::SIG_BLOCK,
                all.as_ptr(),
                0usize,
                8usize,
            );
            let mut byte = 0u8;
            libc::syscall(libc::SYS_read, read, &mut byte as *mut u8, 1usize);
            libc::syscall(libc::SYS_exit, 0);
        }
        0
    }

    /// The pipe's two descriptors, packed into the child's argument.
    fn pack([read, write]: [libc::c_int; 2]) -> *mut libc::c_void {
        ((read as u32 as usize) | ((write as u32 as usize) << 32)) as *mut libc::c_void
    }

    /// [`pack`] undone.
    fn unpack(arg: *mut libc::c_void) -> [libc::c_int; 2] {
        let v = arg as usize;
        [
            (v & 0xffff_ffff) as u32 as libc::c_int,
            (v >> 32) as u32 as libc::c_int,
        ]
    }

    /// Makes the child (see the module's documentation); whether it was
    /// made. Nothing is reported when it cannot be: the process then ends as
    /// it would have.
    pub(super) fn hand_off() -> bool {
        // SAFETY: the stack is mapped for the child and never unmapped (the
        // process is ending); `child` only makes system calls on it.
        unsafe {
            let stack = libc::mmap(
                std::ptr::null_mut(),
                STACK,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_STACK,
                -1,
                0,
            );
            if stack == libc::MAP_FAILED {
                return false;
            }
            let top = (stack as *mut u8).add(STACK) as *mut libc::c_void;
            let mut fds = [0 as libc::c_int; 2];
            if libc::pipe2(fds.as_mut_ptr(), libc::O_CLOEXEC) != 0 {
                return false;
            }
            libc::clone(child, top, libc::CLONE_VM | libc::SIGCHLD, pack(fds)) > 0
        }
    }
}
