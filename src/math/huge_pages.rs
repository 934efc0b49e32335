//! A memory hint: back a large array with 2 MiB pages instead of 4 KiB
//! ones, so that reading it at random misses the TLB far less often.
//!
//! Every load translates its virtual address through the TLB; a miss
//! costs a page-table walk of several dependent memory reads. The second-
//! level TLB of a current x86-64 core holds a few thousand entries, which
//! with 4 KiB pages cover about 8-12 MiB. The wide BVH of the benchmark's
//! million triangles is 55 MiB of nodes and triangle packs, read at
//! scattered places by every ray, so nearly every level of a traversal
//! below the top ones paid a page walk on top of its cache miss. With
//! 2 MiB pages the same entries cover gigabytes.
//!
//! Linux gives 2 MiB pages to anonymous memory by itself ("transparent
//! huge pages", kernel documentation `admin-guide/mm/transhuge`), but many
//! systems set it to `madvise`: only ranges marked with
//! `madvise(MADV_HUGEPAGE)` get them. [`advise`] marks the whole 2 MiB
//! pages inside a vector's allocation; do it before the vector is
//! written, since pages are chosen when first touched. It is only a hint:
//! it never changes what the memory holds, failure is ignored, and on
//! other systems it does nothing.

/// Asks for huge pages under `v`'s allocation (its capacity, not only
/// its length). Call it right after `Vec::with_capacity`.
pub fn advise<T>(v: &Vec<T>) {
    #[cfg(target_os = "linux")]
    {
        const HUGE: usize = 2 << 20;
        let start = v.as_ptr() as usize;
        let end = start + v.capacity() * std::mem::size_of::<T>();
        // The 2 MiB-aligned pages that lie wholly inside the allocation.
        let (first, last) = (start.next_multiple_of(HUGE), end / HUGE * HUGE);
        if last > first {
            // SAFETY: the range lies inside `v`'s allocation, which stays
            // mapped while `v` lives; the advice changes how pages are
            // backed, never their contents.
            unsafe {
                libc::madvise(
                    first as *mut libc::c_void,
                    last - first,
                    libc::MADV_HUGEPAGE,
                );
            }
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = v;
}
