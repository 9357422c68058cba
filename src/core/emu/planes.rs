//! The draw's output arrays, written in place by the threads that run its
//! batches.
//!
//! Why it exists: a batch's results used to be copied into a buffer of its
//! own and then, on one thread, into the output, which cost as much as the
//! shader on a large target and did not scale with threads. Here each worker
//! writes its pixels and quads straight into the output.
//!
//! Why it is sound: a draw runs every batch exactly once, on one thread, and
//! a batch writes only its own pixels and quads — lane `l` of batch `b` is
//! quad `b·batch_quads + l/4` and pixel `(l & 1, l >> 1)` of that quad, so no
//! two batches share an element. No element is read while the draw runs.
//! [`Plane::set`] checks its index, so the only thing its callers promise is
//! that one element is written by one batch.

use super::DrawOutput;
use std::marker::PhantomData;
use std::ptr::NonNull;

/// A slice that several threads write at distinct indices.
pub(crate) struct Plane<'o, T> {
    ptr: NonNull<T>,
    len: usize,
    _slice: PhantomData<&'o mut [T]>,
}

// SAFETY: a plane is written only through `set`, whose callers write each
// index from one thread (module docs); the values are plain `Copy + Send`
// data, so handing them to another thread is sound.
unsafe impl<T: Copy + Send> Send for Plane<'_, T> {}
// SAFETY: as above; `&Plane` only allows `set`.
unsafe impl<T: Copy + Send> Sync for Plane<'_, T> {}

impl<'o, T: Copy> Plane<'o, T> {
    fn new(slice: &'o mut [T]) -> Plane<'o, T> {
        Plane {
            len: slice.len(),
            ptr: NonNull::from(slice).cast(),
            _slice: PhantomData,
        }
    }

    /// Writes element `i` (panics when out of bounds).
    ///
    /// # Safety
    /// No other thread accesses element `i` while the plane lives.
    #[inline]
    pub unsafe fn set(&self, i: usize, value: T) {
        assert!(i < self.len, "plane index {i} out of {}", self.len);
        // SAFETY: `i` is in bounds of the borrowed slice, and the caller
        // promises that no other thread accesses element `i`.
        unsafe { self.ptr.as_ptr().add(i).write(value) }
    }
}

/// The per-pixel and per-quad arrays of a [`DrawOutput`], borrowed for the
/// draw's batches.
pub(crate) struct Planes<'o> {
    pub color: [Option<Plane<'o, [f32; 4]>>; 4],
    pub depth: Option<Plane<'o, f32>>,
    pub killed: Plane<'o, bool>,
    pub executed: Plane<'o, u64>,
    pub quad_executed: Plane<'o, u64>,
    pub quad_divergent: Plane<'o, bool>,
}

impl<'o> Planes<'o> {
    pub fn new(out: &'o mut DrawOutput) -> Planes<'o> {
        let mut color = out.color.iter_mut();
        Planes {
            color: std::array::from_fn(|_| {
                color.next().and_then(|c| c.as_deref_mut()).map(Plane::new)
            }),
            depth: out.depth.as_deref_mut().map(Plane::new),
            killed: Plane::new(&mut out.killed),
            executed: Plane::new(&mut out.executed),
            quad_executed: Plane::new(&mut out.quad_executed),
            quad_divergent: Plane::new(&mut out.quad_divergent),
        }
    }
}
