//! A fast, deterministic hasher for the class tables, whose keys are
//! vectors of small integers (compact skeletons) built by the program, not
//! by an adversary: the multiply-rotate hash of rustc's `FxHasher`. SipHash,
//! the standard default, took a tenth of a decomposition's time.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A `HashMap` with [`FxHasher`].
pub(crate) type FxHashMap<K, V> = HashMap<K, V, BuildHasherDefault<FxHasher>>;

#[derive(Default, Clone, Copy)]
pub(crate) struct FxHasher {
    hash: u64,
}

const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl FxHasher {
    #[inline]
    fn add(&mut self, word: u64) {
        self.hash = (self.hash.rotate_left(5) ^ word).wrapping_mul(SEED);
    }
}

impl Hasher for FxHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            self.add(u64::from_le_bytes(c.try_into().expect("8 bytes")));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut buf = [0u8; 8];
            buf[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(buf));
        }
    }
    #[inline]
    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }
    #[inline]
    fn write_u32(&mut self, i: u32) {
        self.add(u64::from(i));
    }
    #[inline]
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }
    #[inline]
    fn write_u128(&mut self, i: u128) {
        self.add(i as u64);
        self.add((i >> 64) as u64);
    }
    #[inline]
    fn write_i128(&mut self, i: i128) {
        self.write_u128(i as u128);
    }
    #[inline]
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }
    #[inline]
    fn finish(&self) -> u64 {
        self.hash
    }
}

/// Ids filed under 64-bit hashes, for tables whose entries are told apart
/// by an exact comparison: the first id filed under each hash, and for
/// each id the next one filed under the same hash.
#[derive(Default)]
pub(crate) struct HashChains {
    first: FxHashMap<u64, usize>,
    next: Vec<usize>,
}

/// The end of a chain.
const END: usize = usize::MAX;

impl HashChains {
    /// The id filed under `h` for which `same` holds, if there is one;
    /// else `new` (larger than every id filed so far) is filed under `h`.
    pub(crate) fn find_or_file(
        &mut self,
        h: u64,
        new: usize,
        mut same: impl FnMut(usize) -> bool,
    ) -> Option<usize> {
        if self.next.len() <= new {
            self.next.resize(new + 1, END);
        }
        let mut at = *self.first.entry(h).or_insert(new);
        if at == new {
            return None;
        }
        loop {
            if same(at) {
                return Some(at);
            }
            if self.next[at] == END {
                break;
            }
            at = self.next[at];
        }
        self.next[at] = new;
        None
    }
}
