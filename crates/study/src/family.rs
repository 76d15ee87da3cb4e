//! Recognising the maps of a thesis family, for the checkers of `tight`
//! claims: such a claim is about a construction, so its checker examines
//! the maps that are that construction (whatever name they carry) and
//! confirms they reach what the construction promises.

use wai_map::Map;

/// The largest family parameter a tight checker recognises.
pub const MAX_PARAMETER: u32 = 8;

/// `k` if `map` is exactly `wai_gen::family(id, &[k])` for some
/// `k ≤ MAX_PARAMETER` (same vertices in the same order).
pub fn parameter_of(map: &Map, id: &str) -> Option<u32> {
    (0..=MAX_PARAMETER).find(|&k| {
        wai_gen::family(id, &[k]).is_ok_and(|f| f.n() == map.n() && f.vertices() == map.vertices())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recognises_family_members_only() {
        let m = wai_gen::family("overlap-fan", &[2])
            .unwrap()
            .with_name("renamed");
        assert_eq!(parameter_of(&m, "overlap-fan"), Some(2));
        assert_eq!(parameter_of(&m, "corridor-niches"), None);
        let r = wai_gen::random("random-orthogonal", 12, 0).unwrap();
        assert_eq!(parameter_of(&r, "overlap-fan"), None);
    }
}
