fn main() {
    for kind in ["random-simple-star", "random-orthogonal", "special-orthogonal", "special-comb", "special-chamfer"] {
        for n in [4096usize, 10_000, 20_000] {
            let t = std::time::Instant::now();
            let m = wai_gen::random(kind, n, 1).unwrap();
            println!("{kind} n={n} -> {} in {:?}", m.n(), t.elapsed());
        }
    }
}
