//! Content digests of the files the workspace writes and reads back
//! (preprocessed localizers, run records, counterexample files): an edit
//! made after writing is refused on reading, not silently believed.

use crate::Map;

/// `sha256:` and the lowercase hex SHA-256 of `bytes`.
pub fn sha256(bytes: &[u8]) -> String {
    use sha2::{Digest, Sha256};
    let d = Sha256::digest(bytes);
    let hex: String = d.iter().map(|b| format!("{b:02x}")).collect();
    format!("sha256:{hex}")
}

impl Map {
    /// The digest of the map's geometry: its vertices in order as exact
    /// numbers in its units, one per line, each hole's after a line `hole`
    /// (so a map read back at another scale has the same digest; names and
    /// sources do not count; a map without holes digests as it always has).
    pub fn digest(&self) -> String {
        let exact = |c: i128| {
            crate::format_exact(&rug::Rational::from((
                rug::Integer::from(c),
                self.scale().clone(),
            )))
        };
        let mut text = String::new();
        for (i, p) in self.vertices().iter().enumerate() {
            if i > 0 && self.prev(i) != i - 1 {
                text.push_str("hole\n");
            }
            text.push_str(&format!("{} {}\n", exact(p.x), exact(p.y)));
        }
        sha256(text.as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    #[test]
    fn digests_are_sha256_and_follow_the_geometry() {
        assert_eq!(
            sha256(b"abc"),
            "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        let ring = |k: i128| {
            vec![
                Point::new(0, 0),
                Point::new(k, 0),
                Point::new(k, k),
                Point::new(0, k),
            ]
        };
        let (a, _) = Map::from_ring(ring(4)).unwrap();
        let (b, _) = Map::from_ring(ring(5)).unwrap();
        assert_eq!(a.digest(), a.clone().with_name("named").digest());
        assert_ne!(a.digest(), b.digest());
        // The same square in thousandths: the same map.
        let scaled = ring(4000);
        let (c, _) = Map::from_scaled_ring(scaled, rug::Integer::from(1000)).unwrap();
        assert_eq!(a.digest(), c.digest());
    }
}
