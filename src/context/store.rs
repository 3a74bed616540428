//! The bytes of a buffer object. A large store is mapped on its own at a 2 MiB boundary
//! with transparent huge pages requested (Linux `madvise(MADV_HUGEPAGE)`), so that filling
//! it takes one page fault per 2 MiB instead of one per 4 KiB; smaller stores, other
//! systems and every store whose mapping fails are ordinary heap vectors.

use std::ops::{Deref, DerefMut};

/// The huge-page size the mapped stores are aligned to.
#[cfg(target_os = "linux")]
const HUGE: usize = 2 << 20;

/// The memory for a store could not be had.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// A buffer object's bytes (dereferences to the byte slice).
#[derive(Default)]
pub struct Store(Inner);

#[derive(Default)]
enum Inner {
    #[default]
    Empty,
    Heap(Vec<u8>),
    /// `len` bytes at `ptr`, the start of an anonymous mapping of `map_len` bytes.
    #[cfg(target_os = "linux")]
    Mapped {
        ptr: std::ptr::NonNull<u8>,
        len: usize,
        map_len: usize,
    },
}

// SAFETY: a Store owns its memory alone (as a Vec does); nothing else refers to a mapping.
unsafe impl Send for Store {}
// SAFETY: shared references only read the bytes.
unsafe impl Sync for Store {}

impl Store {
    /// `size` zero bytes, or [`OutOfMemory`].
    pub fn zeroed(size: usize) -> Result<Self, OutOfMemory> {
        // A fresh mapping is zero already (and untouched until written).
        if let Some(s) = Self::map(size) {
            return Ok(s);
        }
        let mut v = Vec::new();
        v.try_reserve_exact(size).map_err(|_| OutOfMemory)?;
        v.resize(size, 0);
        Ok(Store(Inner::Heap(v)))
    }

    /// A copy of `data`, or [`OutOfMemory`].
    pub fn copy_of(data: &[u8]) -> Result<Self, OutOfMemory> {
        if let Some(mut s) = Self::map(data.len()) {
            s.copy_from_slice(data);
            return Ok(s);
        }
        let mut v = Vec::new();
        v.try_reserve_exact(data.len()).map_err(|_| OutOfMemory)?;
        v.extend_from_slice(data);
        Ok(Store(Inner::Heap(v)))
    }

    /// A zeroed mapping of `size` bytes starting on a huge-page boundary, when its length
    /// spans at least one whole huge page: `size` rounded up to whole huge pages when that
    /// at most doubles it (the rounding is resident once written, so a store of 1–2 MiB
    /// holds 2 MiB), else to whole pages (the part after the last whole huge page then
    /// takes ordinary pages). Measured (small_tris_200k, whose 1.6 MB vertex and 2.4 MB
    /// index stores got 4 KiB pages for all or part under a quarter rule): see the commit.
    #[cfg(target_os = "linux")]
    fn map(size: usize) -> Option<Self> {
        const PAGE: usize = 4096;
        let up = size.checked_next_multiple_of(HUGE)?;
        let map_len = if up - size <= size {
            up
        } else {
            size.checked_next_multiple_of(PAGE)?
        };
        if map_len < HUGE {
            return None;
        }
        let total = map_len.checked_add(HUGE)?;
        // SAFETY: a new anonymous private mapping; no existing memory is involved.
        let p = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                total,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            )
        };
        if p == libc::MAP_FAILED {
            return None;
        }
        let start = p as usize;
        let aligned = start.next_multiple_of(HUGE);
        let end = aligned + map_len;
        // SAFETY: the head [start, aligned) and the tail [end, start + total) lie inside
        // the mapping just made and are page-aligned; nothing refers to them. A failed
        // munmap only leaves address space mapped; a failed madvise only leaves ordinary
        // pages.
        unsafe {
            if aligned > start {
                libc::munmap(p, aligned - start);
            }
            if start + total > end {
                libc::munmap(end as *mut libc::c_void, start + total - end);
            }
            libc::madvise(aligned as *mut libc::c_void, map_len, libc::MADV_HUGEPAGE);
        }
        let ptr = std::ptr::NonNull::new(aligned as *mut u8)?;
        Some(Store(Inner::Mapped {
            ptr,
            len: size,
            map_len,
        }))
    }

    /// No mapping off Linux: every store is a heap vector.
    #[cfg(not(target_os = "linux"))]
    fn map(_size: usize) -> Option<Self> {
        None
    }
}

impl Deref for Store {
    type Target = [u8];
    #[inline]
    fn deref(&self) -> &[u8] {
        match &self.0 {
            Inner::Empty => &[],
            Inner::Heap(v) => v,
            // SAFETY: the mapping holds `len` initialised (zeroed or written) bytes and
            // lives as long as `self`.
            #[cfg(target_os = "linux")]
            Inner::Mapped { ptr, len, .. } => unsafe {
                std::slice::from_raw_parts(ptr.as_ptr(), *len)
            },
        }
    }
}

impl DerefMut for Store {
    #[inline]
    fn deref_mut(&mut self) -> &mut [u8] {
        match &mut self.0 {
            Inner::Empty => &mut [],
            Inner::Heap(v) => v,
            // SAFETY: as in `deref`, and `&mut self` makes the access unique.
            #[cfg(target_os = "linux")]
            Inner::Mapped { ptr, len, .. } => unsafe {
                std::slice::from_raw_parts_mut(ptr.as_ptr(), *len)
            },
        }
    }
}

impl Drop for Store {
    fn drop(&mut self) {
        #[cfg(target_os = "linux")]
        if let Inner::Mapped { ptr, map_len, .. } = self.0 {
            // SAFETY: the mapping was made by `map` with this start and length and
            // nothing refers to it any more.
            unsafe {
                libc::munmap(ptr.as_ptr().cast(), map_len);
            }
        }
    }
}

impl Clone for Store {
    fn clone(&self) -> Self {
        // Out of memory aborts, as cloning a Vec does.
        Self::copy_of(self).unwrap_or_else(|_| Store(Inner::Heap(self.to_vec())))
    }
}

impl std::fmt::Debug for Store {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Store({} bytes)", self.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stores_of_every_kind_hold_their_bytes() {
        for size in [0, 1, 4095, 1 << 20, (3 << 20) / 2, 2 << 20, (5 << 20) + 3] {
            let data: Vec<u8> = (0..size).map(|i| (i * 7 + i / 4096) as u8).collect();
            let s = Store::copy_of(&data).unwrap();
            assert_eq!(&s[..], &data[..]);
            let mut z = Store::zeroed(size).unwrap();
            assert_eq!(z.len(), size);
            assert!(z.iter().all(|&b| b == 0));
            if size > 0 {
                z[size - 1] = 9;
                let c = z.clone();
                drop(z);
                assert_eq!(c[size - 1], 9);
                assert!(c[..size - 1].iter().all(|&b| b == 0));
            }
        }
        assert!(Store::default().is_empty());
        #[cfg(target_os = "linux")]
        {
            // Large stores are mapped on a huge-page boundary.
            let s = Store::zeroed(4 << 20).unwrap();
            assert!(matches!(s.0, Inner::Mapped { .. }));
            assert_eq!(s.as_ptr() as usize % HUGE, 0);
            assert!(matches!(Store::zeroed(1000).unwrap().0, Inner::Heap(_)));
        }
    }
}
