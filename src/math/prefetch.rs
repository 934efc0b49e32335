//! A cache hint: ask the CPU to start loading memory that will be read
//! soon, so that several cache misses overlap instead of each waiting its
//! turn. It never changes a result; where Rust has no stable prefetch
//! instruction (everything but x86-64 here) it does nothing.

/// Hints that the `lines` 64-byte cache lines from `p` on will be read.
/// `p` need not be valid: a prefetch never faults.
#[inline(always)]
pub fn prefetch_lines<T>(p: *const T, lines: usize) {
    let p = p.cast::<u8>();
    for i in 0..lines {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: SSE is part of x86-64's base instruction set, and a
        // prefetch never faults, whatever the address.
        unsafe {
            use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
            _mm_prefetch::<_MM_HINT_T0>(p.wrapping_add(64 * i).cast());
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (p, i);
    }
}
