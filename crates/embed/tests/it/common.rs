//! The maps the tests run on.

use wai_map::Map;

/// Every random kind at `n` vertices, seeds 0..3, and three thesis
/// families at parameter `p`: collinear walls and rays through several
/// vertices (orthogonal kinds, corridors, combs) as well as general
/// position.
pub fn maps(n: usize, p: u32) -> Vec<Map> {
    let mut maps = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for seed in 0..3 {
            maps.push(wai_gen::random(kind.id, n, seed).unwrap());
        }
    }
    for family in ["corridor-niches", "overlap-fan", "comb-convex-chain"] {
        let p = if family == "overlap-fan" { 0 } else { p };
        maps.push(wai_gen::family(family, &[p]).unwrap());
    }
    maps
}
