//! The maps a search goes through: a [`Stream`].
//!
//! A stream is either **generated** — map i of a list of [`MapKind`]s taken
//! round robin, kind `kinds[i mod K]` with seed `seed + i` and, for kinds
//! with a size, n (or the family parameter) cycling through the kind's
//! range — or **fixed**: a list of maps (the corpus, files). Map i of a
//! generated stream is a function of i and the seed alone.

use std::ops::RangeInclusive;

use wai_map::Map;

/// One kind of generated map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapKind {
    /// A random kind of [`wai_gen::RANDOM_KINDS`], with about n vertices.
    Random(&'static str),
    /// A layout of [`wai_gen::LAYOUTS`] (its seed is its only parameter).
    Layout(&'static str),
    /// Every family of [`wai_gen::FAMILIES`] in turn, at parameter k.
    Family,
    /// [`wai_gen::bytes::map_from_seed`]: the fuzz targets' maps, shaped
    /// from random bytes.
    Bytes,
    /// A random kind with holes of [`wai_gen::HOLED_KINDS`], about n outer
    /// vertices and 1 to 3 holes asked. Not in `all`: the claims of
    /// chapters 3–5 assume a map without holes (thesis sec. 2.1), and runs
    /// with holes test what the assumption does (group `holes`).
    Holed(&'static str),
}

impl MapKind {
    /// The name used by `--maps`.
    pub fn id(&self) -> &'static str {
        match self {
            MapKind::Random(id) | MapKind::Layout(id) | MapKind::Holed(id) => id,
            MapKind::Family => "family",
            MapKind::Bytes => "bytes",
        }
    }

    /// The size range used when `--maps` gives none: n for random kinds,
    /// the parameter k for families, ignored by layouts and bytes.
    pub fn default_range(&self) -> RangeInclusive<usize> {
        match self {
            MapKind::Random(_) => 8..=30,
            MapKind::Holed(_) => 6..=20,
            MapKind::Family => 1..=4,
            MapKind::Layout(_) | MapKind::Bytes => 0..=0,
        }
    }

    /// Every kind, in the order `all` cycles through them.
    pub fn all() -> Vec<MapKind> {
        let mut kinds: Vec<MapKind> = wai_gen::RANDOM_KINDS
            .iter()
            .map(|k| MapKind::Random(k.id))
            .collect();
        kinds.extend(wai_gen::LAYOUTS.iter().map(|l| MapKind::Layout(l.id)));
        kinds.push(MapKind::Family);
        kinds.push(MapKind::Bytes);
        kinds
    }

    /// The n a random kind accepts, with or without holes (`None` for
    /// layouts, families and bytes).
    pub fn n_range(&self) -> Option<(usize, usize)> {
        match self {
            MapKind::Random(id) => wai_gen::RANDOM_KINDS
                .iter()
                .find(|k| k.id == *id)
                .map(|k| (k.min_n, k.max_n)),
            MapKind::Holed(id) => wai_gen::HOLED_KINDS
                .iter()
                .find(|k| k.id == *id)
                .map(|k| (k.min_n, k.max_n)),
            _ => None,
        }
    }

    /// The kinds with holes, the group `holes`; outside [`MapKind::all`].
    pub fn with_holes() -> Vec<MapKind> {
        wai_gen::HOLED_KINDS
            .iter()
            .map(|k| MapKind::Holed(k.id))
            .collect()
    }

    /// The kind named `id`.
    pub fn named(id: &str) -> Option<MapKind> {
        MapKind::all()
            .into_iter()
            .chain(MapKind::with_holes())
            .find(|k| k.id() == id)
    }

    /// Holes asked of map `round` of a kind with holes: 1, 2, 3 in turn.
    pub fn holes_asked(round: u64) -> usize {
        1 + (round % 3) as usize
    }
}

/// A kind with the sizes to cycle through.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KindSpec {
    pub kind: MapKind,
    pub sizes: RangeInclusive<usize>,
}

/// Parses `--maps`: comma-separated `KIND[:a-b]` (or `KIND:a`), where KIND
/// is a name of [`MapKind::all`] or a group: `all` (every kind), `random`
/// (every random kind), `layouts` (every layout). Random kinds' ranges are
/// clamped to what the kind accepts.
pub fn parse_kinds(spec: &str) -> Result<Vec<KindSpec>, String> {
    let mut out = Vec::new();
    for part in spec.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let (name, range) = match part.split_once(':') {
            Some((name, range)) => (name, Some(range)),
            None => (part, None),
        };
        let kinds = if name == "all" {
            MapKind::all()
        } else if name == "random" {
            let all = MapKind::all();
            all.into_iter()
                .filter(|k| matches!(k, MapKind::Random(_)))
                .collect()
        } else if name == "holes" {
            MapKind::with_holes()
        } else if name == "layouts" {
            let all = MapKind::all();
            all.into_iter()
                .filter(|k| matches!(k, MapKind::Layout(_)))
                .collect()
        } else {
            vec![MapKind::named(name).ok_or_else(|| {
                let names: Vec<&str> = MapKind::all()
                    .iter()
                    .chain(&MapKind::with_holes())
                    .map(MapKind::id)
                    .collect();
                format!(
                    "unknown map kind {name:?}; the kinds are {}, the groups all, random, \
                     layouts and holes (the kinds with holes, outside all), and the fixed \
                     stream corpus",
                    names.join(", ")
                )
            })?]
        };
        for kind in kinds {
            let sizes = match range {
                None => kind.default_range(),
                Some(r) => parse_range(r).map_err(|e| format!("--maps {part}: {e}"))?,
            };
            let sizes = match kind {
                MapKind::Random(id) | MapKind::Holed(id) => {
                    let (min, max) = kind.n_range().expect("a generated kind has an n range");
                    let (a, b) = ((*sizes.start()).max(min), (*sizes.end()).min(max));
                    if a > b {
                        return Err(format!("--maps {part}: {id} takes n from {min} to {max}"));
                    }
                    a..=b
                }
                MapKind::Family if *sizes.start() == 0 => {
                    return Err(format!("--maps {part}: family parameters start at 1"))
                }
                _ => sizes,
            };
            out.push(KindSpec { kind, sizes });
        }
    }
    if out.is_empty() {
        return Err("--maps names no kind".into());
    }
    Ok(out)
}

fn parse_range(r: &str) -> Result<RangeInclusive<usize>, String> {
    let num = |s: &str| {
        s.trim()
            .parse::<usize>()
            .map_err(|_| format!("{s:?} is not a size"))
    };
    let (a, b) = match r.split_once('-') {
        Some((a, b)) => (num(a)?, num(b)?),
        None => (num(r)?, num(r)?),
    };
    if a > b {
        return Err(format!("the range {a}-{b} is empty"));
    }
    Ok(a..=b)
}

/// The maps of the `family` kind over parameters `sizes`: (family, k) for
/// each k in turn and each family of [`wai_gen::FAMILIES`] that accepts k
/// (`comb-convex-chain` needs k ≥ 2), each once.
pub fn family_maps(sizes: &RangeInclusive<usize>) -> Vec<(&'static str, u32)> {
    sizes
        .clone()
        .flat_map(|k| {
            wai_gen::FAMILIES
                .iter()
                .filter(move |f| wai_gen::family(f.id, &[k as u32]).is_ok())
                .map(move |f| (f.id, k as u32))
        })
        .collect()
}

/// Where the maps come from.
#[derive(Debug, Clone)]
pub enum Stream {
    /// Map i: kind `kinds[i mod K]`, seed `seed + i`.
    Generated { kinds: Vec<KindSpec>, seed: u64 },
    /// These maps, each with the name of its kind.
    Fixed(Vec<(String, Map)>),
    /// The fixed maps first, then the generated stream: map `fixed.len() +
    /// i` is map i of `Generated { kinds, seed }`.
    Mixed {
        fixed: Vec<(String, Map)>,
        kinds: Vec<KindSpec>,
        seed: u64,
    },
}

/// One lane of a stream: the indices `start + j·step` for `j < len` (or
/// every j when `len` is `None`), the maps of one kind (or the fixed
/// maps). A budgeted search gives every lane an equal share of the time.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lane {
    /// The kind's name (`fixed` for the fixed maps).
    pub name: String,
    pub start: u64,
    pub step: u64,
    pub len: Option<u64>,
}

impl Lane {
    /// The stream index of the lane's j-th map, if the lane has one.
    pub fn index(&self, j: u64) -> Option<u64> {
        if self.len.is_some_and(|len| j >= len) {
            return None;
        }
        Some(self.start + j * self.step)
    }
}

impl Stream {
    /// How many maps the stream holds (`None`: unbounded).
    pub fn len(&self) -> Option<u64> {
        match self {
            Stream::Generated { .. } | Stream::Mixed { .. } => None,
            Stream::Fixed(maps) => Some(maps.len() as u64),
        }
    }

    /// The lanes of the stream: the fixed maps (if any), then one lane per
    /// generated kind, kind `k` of `K` holding the indices ≡ k (mod K) of
    /// the generated part. A kind without seeds (`family`: the thesis
    /// families at each parameter of its range) holds its distinct maps
    /// only, once each.
    pub fn lanes(&self) -> Vec<Lane> {
        let generated = |kinds: &[KindSpec], shift: u64| -> Vec<Lane> {
            let k = kinds.len() as u64;
            kinds
                .iter()
                .enumerate()
                .map(|(i, spec)| Lane {
                    name: spec.kind.id().to_owned(),
                    start: shift + i as u64,
                    step: k,
                    len: match spec.kind {
                        MapKind::Family => Some(family_maps(&spec.sizes).len() as u64),
                        _ => None,
                    },
                })
                .collect()
        };
        let fixed_lane = |fixed: &[(String, Map)]| Lane {
            name: "fixed".to_owned(),
            start: 0,
            step: 1,
            len: Some(fixed.len() as u64),
        };
        match self {
            Stream::Fixed(maps) => vec![fixed_lane(maps)],
            Stream::Generated { kinds, .. } => generated(kinds, 0),
            Stream::Mixed { fixed, kinds, .. } => {
                let mut lanes = vec![fixed_lane(fixed)];
                lanes.extend(generated(kinds, fixed.len() as u64));
                lanes.retain(|l| l.len != Some(0));
                lanes
            }
        }
    }

    /// True for a fixed stream without maps.
    pub fn is_empty(&self) -> bool {
        self.len() == Some(0)
    }

    /// Map `i` and its kind's name; the map's name says how to make it
    /// again. `None` past the end of a fixed stream.
    pub fn map(&self, i: u64) -> Option<(String, Map)> {
        match self {
            Stream::Fixed(maps) => maps.get(i as usize).cloned(),
            Stream::Mixed { fixed, kinds, seed } => match fixed.get(i as usize) {
                Some(m) => Some(m.clone()),
                None => Stream::Generated {
                    kinds: kinds.clone(),
                    seed: *seed,
                }
                .map(i - fixed.len() as u64),
            },
            Stream::Generated { kinds, seed } => {
                let k = kinds.len() as u64;
                let spec = &kinds[(i % k) as usize];
                let round = i / k;
                let span = (*spec.sizes.end() - *spec.sizes.start() + 1) as u64;
                let size = *spec.sizes.start() + (round % span) as usize;
                let seed = seed.wrapping_add(i);
                let map = match spec.kind {
                    MapKind::Random(id) => wai_gen::random(id, size, seed)
                        .expect("sizes are clamped to the kind's range")
                        .with_name(format!("{id} n={size} seed={seed}")),
                    MapKind::Layout(id) => wai_gen::layout(id, seed)
                        .expect("a layout of LAYOUTS")
                        .with_name(format!("{id} seed={seed}")),
                    MapKind::Family => {
                        let pairs = family_maps(&spec.sizes);
                        let (id, k) = pairs[(round % pairs.len() as u64) as usize];
                        wai_gen::family(id, &[k])
                            .expect("family_maps lists accepted parameters")
                            .with_name(format!("{id} k={k}"))
                    }
                    MapKind::Bytes => wai_gen::bytes::map_from_seed(seed),
                    MapKind::Holed(id) => {
                        let holes = MapKind::holes_asked(round);
                        wai_gen::random_with_holes(id, size, holes, seed)
                            .expect("sizes are clamped to the kind's range")
                            .with_name(format!("{id} n={size} holes={holes} seed={seed}"))
                    }
                };
                Some((spec.kind.id().to_owned(), map))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_with_holes_are_a_group_outside_all() {
        let holes = parse_kinds("holes").unwrap();
        assert_eq!(holes.len(), wai_gen::HOLED_KINDS.len());
        assert!(MapKind::all()
            .iter()
            .all(|k| !matches!(k, MapKind::Holed(_))));
        let stream = Stream::Generated {
            kinds: holes,
            seed: 3,
        };
        for i in 0..6 {
            let (_, map) = stream.map(i).unwrap();
            let name = map.name().unwrap_or_default();
            assert!(map.has_holes(), "{name}");
            assert!(name.contains(" holes="), "{name}");
        }
        assert!(parse_kinds("orthogonal-pillars:2-3").is_err());
    }

    #[test]
    fn kinds_parse_with_ranges_and_clamp() {
        let k = parse_kinds("random-orthogonal:2-12, family:2").unwrap();
        assert_eq!(k[0].kind, MapKind::Random("random-orthogonal"));
        assert_eq!(k[0].sizes, 4..=12);
        assert_eq!((k[1].kind, k[1].sizes.clone()), (MapKind::Family, 2..=2));
        assert_eq!(parse_kinds("all").unwrap().len(), MapKind::all().len());
        assert_eq!(
            parse_kinds("random").unwrap().len(),
            wai_gen::RANDOM_KINDS.len()
        );
        assert_eq!(
            parse_kinds("layouts:3").unwrap().len(),
            wai_gen::LAYOUTS.len()
        );
        for bad in ["nope", "family:0", "random-orthogonal:9-3", "bytes:x", ""] {
            assert!(parse_kinds(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn lanes_partition_the_stream_by_kind() {
        let kinds = parse_kinds("random-orthogonal,family:1-2,bytes").unwrap();
        let fixed = vec![(
            "fixed".to_owned(),
            wai_gen::family("corridor-niches", &[1]).unwrap(),
        )];
        let stream = Stream::Mixed {
            fixed,
            kinds: kinds.clone(),
            seed: 5,
        };
        let lanes = stream.lanes();
        let names: Vec<&str> = lanes.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(names, ["fixed", "random-orthogonal", "family", "bytes"]);
        assert_eq!(lanes[0].len, Some(1));
        // The family lane holds each family map at parameters 1 and 2 once
        // (comb-convex-chain has no k = 1).
        let family = &lanes[2];
        assert_eq!(family.len, Some(2 * wai_gen::FAMILIES.len() as u64 - 1));
        let maps: Vec<Map> = (0..family.len.unwrap())
            .map(|j| stream.map(family.index(j).unwrap()).unwrap().1)
            .collect();
        for (a, m) in maps.iter().enumerate() {
            assert!(
                maps[..a].iter().all(|o| o.vertices() != m.vertices()),
                "{a}"
            );
        }
        assert_eq!(family.index(family.len.unwrap()), None);
        // Lane k's maps are the generated stream's maps of kind k.
        let generated = Stream::Generated { kinds, seed: 5 };
        for (k, lane) in lanes[1..].iter().enumerate() {
            for j in 0..3 {
                let (kind, a) = stream.map(lane.index(j).unwrap()).unwrap();
                let (_, b) = generated.map(j * 3 + k as u64).unwrap();
                assert_eq!((kind.as_str(), &a), (lane.name.as_str(), &b));
            }
        }
    }

    #[test]
    fn a_generated_stream_is_a_function_of_the_index() {
        let stream = Stream::Generated {
            kinds: parse_kinds("all").unwrap(),
            seed: 7,
        };
        for i in 0..2 * MapKind::all().len() as u64 {
            let (kind, a) = stream.map(i).unwrap();
            let (_, b) = stream.map(i).unwrap();
            assert_eq!(a, b);
            assert_eq!(kind, MapKind::all()[i as usize % MapKind::all().len()].id());
        }
    }
}
