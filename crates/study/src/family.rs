//! Recognising the maps of a thesis family, for the checkers of `tight`
//! claims: such a claim is about a construction, so its checker examines
//! the maps that are that construction (whatever name they carry) and
//! confirms they reach what the construction promises.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use wai_exact::Point;
use wai_map::Map;

/// The largest family parameter a tight checker recognises.
pub const MAX_PARAMETER: u32 = 8;

/// `k` if `map` is exactly `wai_gen::family(id, &[k])` for some
/// `k ≤ MAX_PARAMETER` (same vertices in the same order).
///
/// The family's maps are generated once per process and kept, so a
/// checker that asks on every map compares vertex counts, and vertices
/// only where the counts agree.
pub fn parameter_of(map: &Map, id: &str) -> Option<u32> {
    let members = members(id);
    members
        .iter()
        .find(|(_, v)| v.len() == map.n() && v.as_slice() == map.vertices())
        .map(|&(k, _)| k)
}

/// The vertices of `wai_gen::family(id, &[k])` for every `k ≤
/// MAX_PARAMETER` the family has.
fn members(id: &str) -> Arc<Vec<(u32, Vec<Point>)>> {
    type Cache = Mutex<HashMap<String, Arc<Vec<(u32, Vec<Point>)>>>>;
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(m) = cache.lock().expect("not poisoned").get(id) {
        return Arc::clone(m);
    }
    let m: Arc<Vec<(u32, Vec<Point>)>> = Arc::new(
        (0..=MAX_PARAMETER)
            .filter_map(|k| {
                wai_gen::family(id, &[k])
                    .ok()
                    .map(|f| (k, f.vertices().to_vec()))
            })
            .collect(),
    );
    cache
        .lock()
        .expect("not poisoned")
        .insert(id.to_owned(), Arc::clone(&m));
    m
}

/// `(niches, chain)` if `map` is exactly `wai_gen::comb_convex_chain(niches,
/// chain)` (same vertices in the same order), at any size the family
/// builds. The two parameters follow from n = 4·niches + chain + 2 and
/// r = 2·niches, so one map is generated and compared.
pub fn comb_parameters(map: &Map) -> Option<(u32, u32)> {
    let r = map.reflex_vertices().len();
    if r == 0 || !r.is_multiple_of(2) {
        return None;
    }
    let niches = r / 2;
    let chain = map.n().checked_sub(4 * niches + 2)?;
    let (niches, chain) = (u32::try_from(niches).ok()?, u32::try_from(chain).ok()?);
    // The corridor's south wall runs from x = 0 to x = S·U: a cheap test
    // before the family's map is generated.
    let l = wai_gen::comb_layout(niches, chain);
    let (lo, hi) = map.bounding_box();
    if lo.x != 0 || hi.x != l.scale * l.u_max || chain < 2 {
        return None;
    }
    wai_gen::comb_convex_chain(niches, chain)
        .is_ok_and(|f| f.vertices() == map.vertices())
        .then_some((niches, chain))
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

    #[test]
    fn recognises_both_comb_parameters() {
        for (niches, chain) in [(1, 2), (3, 3), (2, 16), (12, 5)] {
            let m = wai_gen::family("comb-convex-chain", &[niches, chain])
                .unwrap()
                .with_name("renamed");
            assert_eq!(comb_parameters(&m), Some((niches, chain)));
        }
        let c = wai_gen::family("corridor-niches", &[3]).unwrap();
        assert_eq!(comb_parameters(&c), None);
    }
}
