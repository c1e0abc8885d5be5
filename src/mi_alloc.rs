//! The global allocator of the `lucent` binary and of the learner-loop benchmark
//! (`examples/learner_loop.rs` includes this file): mimalloc, called through its unaligned
//! entry points (`mi_malloc`, `mi_zalloc`, `mi_realloc`) whenever the requested alignment is at
//! most 8, and through the aligned ones otherwise. Not part of the library, which leaves the
//! choice of allocator to its clients and has no `unsafe` code.
//!
//! Why not `mimalloc::MiMalloc`: that wrapper calls `mi_malloc_aligned` for every request,
//! whose alignment checks cost ~20 instructions per allocation on mimalloc v3; a
//! parse-ground-solve call makes ~2,700 allocations (learner loop: 49 -> 30 instructions per
//! allocation, 3% of the call; docs/bench/learner-loop-2026-12-06.md).
//!
//! Invariant: every block mimalloc hands out is aligned to at least 8 bytes (its size classes
//! are multiples of the word size), so the unaligned entry points satisfy any layout with
//! alignment at most 8; `dealloc` is `mi_free` for both kinds of block.

use std::alloc::{GlobalAlloc, Layout};
use std::ffi::{c_int, c_long, c_void};

use libmimalloc_sys as mi;

/// The largest alignment served by the unaligned entry points.
const WORD: usize = 8;

/// mimalloc as a global allocator (see the module documentation).
pub struct Mi;

/// `mi_option_purge_delay` in the vendored mimalloc v3 (`mimalloc.h`, enum `mi_option_e`; the
/// `libmimalloc-sys` crate names no constant for it). A test checks its default (1000 ms) so a
/// renumbered enum is caught.
const PURGE_DELAY: c_int = 15;

extern "C" {
    fn mi_option_set(option: c_int, value: c_long);
    #[cfg(test)]
    fn mi_option_get(option: c_int) -> c_long;
}

/// Makes mimalloc give freed memory back to the OS at once instead of after its purge delay
/// (1 s, 10 s for arenas, in v3): with the delay, memory freed between grounding and solving
/// stays resident and peak RSS was 1.6-1.9x clingo's on the transitive-closure rows and 2-4x on
/// the labyrinth rows (glibc's malloc: 0.8-1.6x); CPU time unchanged within noise
/// (docs/bench/memory-2026-12-07.md). Called first thing by each client of this allocator.
pub fn purge_at_once() {
    // SAFETY: `mi_option_set` only stores the value; any value is valid for this option.
    unsafe { mi_option_set(PURGE_DELAY, 0) }
}

// SAFETY: mimalloc's functions are thread-safe; the aligned variants honour any power-of-two
// alignment and the unaligned ones return blocks aligned to at least `WORD` (module invariant),
// so every returned block satisfies its layout; `mi_free` and `mi_realloc*` accept blocks from
// either kind of call.
unsafe impl GlobalAlloc for Mi {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if layout.align() <= WORD {
            mi::mi_malloc(layout.size()) as *mut u8
        } else {
            mi::mi_malloc_aligned(layout.size(), layout.align()) as *mut u8
        }
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if layout.align() <= WORD {
            mi::mi_zalloc(layout.size()) as *mut u8
        } else {
            mi::mi_zalloc_aligned(layout.size(), layout.align()) as *mut u8
        }
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, _layout: Layout) {
        mi::mi_free(ptr as *mut c_void)
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if layout.align() <= WORD {
            mi::mi_realloc(ptr as *mut c_void, new_size) as *mut u8
        } else {
            mi::mi_realloc_aligned(ptr as *mut c_void, new_size, layout.align()) as *mut u8
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `PURGE_DELAY` names the purge delay: its default is v3's 1000 ms, and setting it reads
    /// back.
    #[test]
    fn purge_delay_is_the_option_set() {
        // SAFETY: reading an option has no precondition.
        let before = unsafe { mi_option_get(PURGE_DELAY) };
        if std::env::var_os("MIMALLOC_PURGE_DELAY").is_none() {
            assert_eq!(
                before, 1000,
                "mimalloc's option numbering moved: see mimalloc.h"
            );
        }
        purge_at_once();
        assert_eq!(unsafe { mi_option_get(PURGE_DELAY) }, 0);
    }

    /// Every size and alignment mix gets a block aligned as asked, zeroed when asked, and keeps
    /// its contents through a reallocation.
    #[test]
    fn blocks_are_aligned_zeroed_and_kept() {
        for align in [1, 2, 4, 8, 16, 32, 64, 4096] {
            for size in [1, 3, 8, 13, 16, 24, 40, 100, 1000, 70_000] {
                let layout = Layout::from_size_align(size, align).unwrap();
                unsafe {
                    let p = Mi.alloc(layout);
                    assert!(!p.is_null());
                    assert_eq!(p as usize % align, 0, "size {size} align {align}");
                    for i in 0..size {
                        *p.add(i) = (i % 251) as u8;
                    }
                    let q = Mi.realloc(p, layout, size * 3);
                    assert_eq!(q as usize % align, 0);
                    for i in 0..size {
                        assert_eq!(*q.add(i), (i % 251) as u8);
                    }
                    Mi.dealloc(q, Layout::from_size_align(size * 3, align).unwrap());
                    let z = Mi.alloc_zeroed(layout);
                    assert_eq!(z as usize % align, 0);
                    assert!((0..size).all(|i| *z.add(i) == 0));
                    Mi.dealloc(z, layout);
                }
            }
        }
    }
}
