//! The bytes of a buffer object. A large store is mapped on its own on transparent huge
//! pages ([`crate::memory`]), so that filling it takes one page fault per 2 MiB instead of
//! one per 4 KiB; smaller stores, other systems and every store whose mapping fails are
//! ordinary heap vectors.

use crate::memory::Mapping;
use std::ops::{Deref, DerefMut};

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
    /// `len` bytes at the start of `map`.
    Mapped {
        map: Mapping,
        len: usize,
    },
}

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

    /// A zeroed store of `size` bytes on huge pages ([`Mapping::huge`]), when it is large
    /// enough. Measured (small_tris_200k, whose 1.6 MB vertex and 2.4 MB index stores got
    /// 4 KiB pages for all or part under an earlier rule): see commit 7b53836.
    fn map(size: usize) -> Option<Self> {
        Mapping::huge(size).map(|map| Store(Inner::Mapped { map, len: size }))
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
            Inner::Mapped { map, len } => unsafe {
                std::slice::from_raw_parts(map.ptr().as_ptr(), *len)
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
            Inner::Mapped { map, len } => unsafe {
                std::slice::from_raw_parts_mut(map.ptr().as_ptr(), *len)
            },
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
    #[cfg(target_os = "linux")]
    use crate::memory::HUGE;

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
