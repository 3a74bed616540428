//! Large buffers on transparent huge pages: an anonymous mapping that starts on a 2 MiB
//! boundary with huge pages requested (Linux `madvise(MADV_HUGEPAGE)`), so that the first
//! write to it takes one page fault per 2 MiB instead of one per 4 KiB. Page faults are
//! slow on the virtual machines softgl runs on (about 2.2 µs per 4 KiB page measured,
//! 0.6–0.7 ms to first touch 2 MiB against 0.07–0.2 ms on one huge page), and a one-frame
//! program first touches every buffer it draws into. Buffer objects' bytes
//! (the state's `Store`) and the framebuffer ([`HugeBuf`]) use it; small
//! buffers, other systems and every buffer whose mapping fails stay on the heap.

use std::ops::{Deref, DerefMut};
use std::ptr::NonNull;

/// The huge-page size the mappings are aligned to.
#[cfg(target_os = "linux")]
pub(crate) const HUGE: usize = 2 << 20;

/// A zeroed anonymous mapping on a huge-page boundary, unmapped when dropped.
pub(crate) struct Mapping {
    ptr: NonNull<u8>,
    #[cfg_attr(not(target_os = "linux"), allow(dead_code))]
    map_len: usize,
}

// SAFETY: a Mapping owns its memory alone (as a Vec does); nothing else refers to it.
unsafe impl Send for Mapping {}
// SAFETY: shared references only read through the pointer.
unsafe impl Sync for Mapping {}

impl Mapping {
    /// A zeroed mapping for `size` bytes starting on a huge-page boundary, when its length
    /// spans at least one whole huge page: `size` rounded up to whole huge pages when that
    /// at most doubles it (the rounding is resident once written, so 1–2 MiB take 2 MiB),
    /// else to whole pages (the part after the last whole huge page then takes ordinary
    /// pages). `None` for smaller sizes, off Linux, or when the mapping fails.
    #[cfg(target_os = "linux")]
    pub(crate) fn huge(size: usize) -> Option<Self> {
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
        let ptr = NonNull::new(aligned as *mut u8)?;
        Some(Mapping { ptr, map_len })
    }

    /// No mapping off Linux: every buffer stays on the heap.
    #[cfg(not(target_os = "linux"))]
    pub(crate) fn huge(_size: usize) -> Option<Self> {
        None
    }

    /// The first byte of the mapping (aligned to a huge page).
    #[inline]
    pub(crate) fn ptr(&self) -> NonNull<u8> {
        self.ptr
    }
}

impl Drop for Mapping {
    fn drop(&mut self) {
        #[cfg(target_os = "linux")]
        // SAFETY: the mapping was made by `huge` with this start and length and nothing
        // refers to it any more (its owner is being dropped).
        unsafe {
            libc::munmap(self.ptr.as_ptr().cast(), self.map_len);
        }
    }
}

/// Element types a [`HugeBuf`] holds: plain values for which all-zero bytes are a valid
/// value (a fresh mapping is zero).
///
/// # Safety
/// An implementor has no padding and no invalid bit patterns (all-zero bytes in
/// particular are a valid value), `ZERO` is the value whose bytes are all zero, and
/// `v == ZERO` holds exactly when `v`'s bytes are all zero: [`HugeBuf::filled`] leaves a
/// fresh mapping unwritten for such a value.
pub unsafe trait Plain: Copy + PartialEq + std::fmt::Debug + Send + Sync + 'static {
    /// The value whose bytes are all zero.
    const ZERO: Self;
}

// SAFETY: integers and byte arrays have no padding, every bit pattern is valid, and
// integer equality is equality of the bytes.
unsafe impl Plain for u8 {
    const ZERO: Self = 0;
}
// SAFETY: as for u8.
unsafe impl Plain for u32 {
    const ZERO: Self = 0;
}
// SAFETY: as for u8.
unsafe impl Plain for [u8; 4] {
    const ZERO: Self = [0; 4];
}

/// A fixed-length buffer of plain values (dereferences to the slice), on huge pages when
/// it is large ([`Mapping::huge`]), else a heap vector.
pub struct HugeBuf<T: Plain>(Inner<T>);

enum Inner<T> {
    Heap(Vec<T>),
    /// `len` values at the start of `map`.
    Mapped {
        map: Mapping,
        len: usize,
    },
}

impl<T: Plain> HugeBuf<T> {
    /// `len` copies of `value`. A mapped buffer is only written when `value` is not zero,
    /// so a zero buffer costs no page until it is used (as `vec![0; len]` from calloc).
    pub fn filled(len: usize, value: T) -> Self {
        Self::mapped(len, value).unwrap_or_else(|| HugeBuf(Inner::Heap(vec![value; len])))
    }

    /// `len` copies of `value` on a huge-page mapping, when the size takes one.
    fn mapped(len: usize, value: T) -> Option<Self> {
        let map = Mapping::huge(len.checked_mul(std::mem::size_of::<T>())?)?;
        let mut b = HugeBuf(Inner::Mapped { map, len });
        if value != T::ZERO {
            b.fill(value);
        }
        Some(b)
    }

    /// As [`HugeBuf::filled`], but `None` instead of aborting when the memory is not there
    /// (a renderbuffer's storage: GL_OUT_OF_MEMORY).
    pub fn try_filled(len: usize, value: T) -> Option<Self> {
        if let Some(b) = Self::mapped(len, value) {
            return Some(b);
        }
        let mut v = Vec::new();
        v.try_reserve_exact(len).ok()?;
        v.resize(len, value);
        Some(HugeBuf(Inner::Heap(v)))
    }

    /// An empty buffer (for a buffer the framebuffer does not have).
    pub fn empty() -> Self {
        HugeBuf(Inner::Heap(Vec::new()))
    }

    /// Whether the values live on a huge-page mapping (for tests and measurements).
    pub fn is_mapped(&self) -> bool {
        matches!(self.0, Inner::Mapped { .. })
    }

    /// The same memory as values of another plain type of the same size (a depth texture's
    /// texels, u32 depths in little-endian bytes, lent to a working copy's depth buffer),
    /// without a copy; `Err(self)` for a heap buffer that holds values (its allocation's
    /// alignment is `T`'s, and a vector of `U` would free it with `U`'s).
    pub fn cast<U: Plain>(self) -> Result<HugeBuf<U>, Self> {
        if std::mem::size_of::<U>() != std::mem::size_of::<T>() {
            return Err(self);
        }
        match self.0 {
            Inner::Mapped { map, len } => Ok(HugeBuf(Inner::Mapped { map, len })),
            Inner::Heap(v) if v.is_empty() => Ok(HugeBuf::empty()),
            inner => Err(HugeBuf(inner)),
        }
    }
}

impl<T: Plain> Deref for HugeBuf<T> {
    type Target = [T];
    #[inline]
    fn deref(&self) -> &[T] {
        match &self.0 {
            Inner::Heap(v) => v,
            // SAFETY: the mapping holds `len` values (its length was computed from
            // `len * size_of::<T>()`), all initialised: zero bytes are a valid `T` (the
            // `Plain` contract), and the mapping is aligned to 2 MiB, more than any `T` needs. It
            // lives as long as `self`.
            Inner::Mapped { map, len } => unsafe {
                std::slice::from_raw_parts(map.ptr().as_ptr().cast::<T>(), *len)
            },
        }
    }
}

impl<T: Plain> DerefMut for HugeBuf<T> {
    #[inline]
    fn deref_mut(&mut self) -> &mut [T] {
        match &mut self.0 {
            Inner::Heap(v) => v,
            // SAFETY: as in `deref`, and `&mut self` makes the access unique.
            Inner::Mapped { map, len } => unsafe {
                std::slice::from_raw_parts_mut(map.ptr().as_ptr().cast::<T>(), *len)
            },
        }
    }
}

impl<T: Plain> Clone for HugeBuf<T> {
    fn clone(&self) -> Self {
        let mut b = HugeBuf::filled(self.len(), T::ZERO);
        b.copy_from_slice(self);
        b
    }
}

impl<T: Plain> From<Vec<T>> for HugeBuf<T> {
    /// The vector's values, left on the heap where they are.
    fn from(v: Vec<T>) -> Self {
        HugeBuf(Inner::Heap(v))
    }
}

impl<T: Plain> FromIterator<T> for HugeBuf<T> {
    fn from_iter<I: IntoIterator<Item = T>>(it: I) -> Self {
        HugeBuf(Inner::Heap(it.into_iter().collect()))
    }
}

impl<T: Plain> PartialEq for HugeBuf<T> {
    fn eq(&self, other: &Self) -> bool {
        self[..] == other[..]
    }
}

impl<T: Plain> std::fmt::Debug for HugeBuf<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "HugeBuf({} values)", self.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn buffers_of_every_size_hold_their_values() {
        for len in [0usize, 1, 1000, 1 << 18, (1 << 18) + 5, 1 << 20, 3 << 19] {
            for value in [[0u8; 4], [1, 2, 3, 255]] {
                let mut b = HugeBuf::filled(len, value);
                assert_eq!(b.len(), len);
                assert!(b.iter().all(|&v| v == value));
                if len > 0 {
                    b[len - 1] = [9; 4];
                    b[0] = [7; 4];
                }
                let c = b.clone();
                drop(b);
                assert_eq!(c.len(), len);
                if len > 1 {
                    assert_eq!((c[0], c[len - 1]), ([7; 4], [9; 4]));
                    assert!(c[1..len - 1].iter().all(|&v| v == value));
                }
            }
        }
        assert!(HugeBuf::<u32>::empty().is_empty());
        #[cfg(target_os = "linux")]
        {
            // 1 MiB and more go on a huge-page boundary; 256 KiB stays on the heap.
            let b = HugeBuf::filled(1 << 18, 0u32);
            assert!(b.is_mapped());
            assert_eq!(b.as_ptr() as usize % HUGE, 0);
            assert!(!HugeBuf::filled(1 << 16, 0u32).is_mapped());
        }
    }

    #[test]
    fn a_mapped_buffer_casts_without_a_copy_and_a_heap_one_does_not() {
        let mut b = HugeBuf::filled(1 << 20, [0u8; 4]);
        b[5] = 0x1234_5678u32.to_le_bytes();
        if b.is_mapped() {
            let at = b.as_ptr() as usize;
            let d = b.cast::<u32>().expect("a mapping casts");
            assert_eq!(
                (d.as_ptr() as usize, d.len(), d[5], d[4]),
                (at, 1 << 20, 0x1234_5678, 0)
            );
            let back = d.cast::<[u8; 4]>().expect("and back");
            assert_eq!(back[5], 0x1234_5678u32.to_le_bytes());
        }
        let heap: HugeBuf<[u8; 4]> = vec![[1, 2, 3, 4]; 3].into();
        let heap = heap
            .cast::<u32>()
            .expect_err("a heap vector keeps its type");
        assert_eq!(heap[..], [[1, 2, 3, 4]; 3]);
        assert!(HugeBuf::<[u8; 4]>::empty()
            .cast::<u32>()
            .is_ok_and(|e| e.is_empty()));
        assert!(HugeBuf::filled(4, 0u32).cast::<u8>().is_err());
    }
}
