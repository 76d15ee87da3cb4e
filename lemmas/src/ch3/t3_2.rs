//! Claim T3.2 (Theorem 3.2): if p and q have the same position relative to
//! the origins v0 of their skeletons, then V_p = V_q if and only if
//! V*_p = V*_q (polygons compared relative to v0).
//!
//! The constructive reading: V_p is determined by V*_p and p − v0 alone.
//!
//! ## Trust
//! Sampled viewpoints; every comparison is exact. For each map the checker
//! computes V_p with the production algorithm for
//! [`wai_study::sample::viewpoints`] and examines:
//! - **every viewpoint**: V*_p is built ([`wai_visibility::Skeleton::of`];
//!   failing to build it is a violation) and V_p is rebuilt from the
//!   skeleton key and p − v0 alone ([`wai_visibility::reconstruct`]); the
//!   rebuilt vertex sequence must equal V_p's, exactly, relative to v0;
//! - **every pair in different embeddings**: the sampled viewpoints are
//!   grouped by skeleton key; for p in a group and every other origin o of
//!   the group (o ≠ v0 of p), the translate q = p + (o − v0) must lie inside
//!   the map (p lies in ker V◇_p, Lemma 3.4, and V◇_p ⊆ V_p), and with V_q
//!   computed afresh both directions of the theorem are tested:
//!   V_q = V_p + (o − v0) (points, spurious flags and edge kinds) holds iff
//!   V*_q = V*_p with origin o. When neither holds, q is a point of the
//!   embedding's kernel that is no witness (Remark 3.4) and the instance
//!   holds trivially. V*_q is read off the expansion
//!   ([`wai_visibility::VisibilityIndex::skeleton_at`], tested equal to
//!   the skeleton of V_q); where its non-spurious vertices are not V*_p's
//!   translated, V_q ≠ V_p + t follows (Def 3.4 and the canonical origin
//!   depend on the polygon and the viewpoint alone) and V_q is not built;
//!   otherwise V_q is built and compared;
//! - **every translate onto another reflex map vertex**: the same test with
//!   v0 moved onto each other reflex vertex of M (the only candidates for an
//!   origin) that no sampled viewpoint of the group has as origin, whenever
//!   the translate lies inside the map. Mostly the skeletons differ and the
//!   "only if" direction is what is tested; where they agree, both.
//!
//! Pairs in different embeddings are rare on random maps; the thesis
//! families contribute them on purpose (`corridor-niches`: the viewpoint
//! deep in each niche has the same skeleton, Fig 3.12), because
//! [`wai_study::sample::viewpoints`] starts with a family's own viewpoints. What
//! is not covered: viewpoints outside the sample, and pairs of embeddings
//! the sample does not hit.
//!
//! ## Cases
//! The instances by kind: **rebuild** (V_p rebuilt from its skeleton), its
//! artificial edges by the edge they replace (**half edge**, with one end
//! on the label line, one spurious edge to rebuild; **partial edge**, two),
//! **across embeddings** (a pair of sampled viewpoints in different
//! embeddings of one skeleton) and **translate** (onto another reflex map
//! vertex); and each translated instance by the direction of the theorem it
//! tests: **if** (the skeletons are equal, so the polygons must be) or
//! **only if** (they differ, so the polygons must too).

use std::collections::BTreeMap;

use serde_json::json;
use wai_exact::{Containment, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{reconstruct, Skeleton, SkeletonKey, VisibilityIndex, VisibilityPolygon};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample::{self, translate};
use wai_study::Study;

const ID: &str = "T3.2";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: REBUILD,
        what: "V_p rebuilt from V*_p and p - v0 alone (the constructive proof of Thm 3.2)",
    },
    Case {
        name: HALF_EDGE,
        what: "an artificial edge of a rebuilt skeleton that replaces a half edge: one \
               spurious edge to rebuild (Thm 3.2's proof, Def 3.7 (3))",
    },
    Case {
        name: PARTIAL_EDGE,
        what: "an artificial edge of a rebuilt skeleton that replaces a partial edge: two \
               spurious edges to rebuild (Thm 3.2's proof, Def 3.7 (4))",
    },
    Case {
        name: ACROSS,
        what: "a viewpoint translated into another embedding of its skeleton met in the \
               sample (Fig 3.12)",
    },
    Case {
        name: TRANSLATE,
        what: "a viewpoint translated to put v0 on another reflex map vertex, inside the map",
    },
    Case {
        name: IF,
        what: "a translate with the same skeleton: the polygons must be equal (Thm 3.2, if)",
    },
    Case {
        name: ONLY_IF,
        what: "a translate with another skeleton: the polygons must differ (Thm 3.2, only if)",
    },
]);

/// Case: V_p rebuilt from its skeleton.
pub const REBUILD: &str = "rebuild";
/// Case: an artificial edge replacing a half edge, rebuilt.
pub const HALF_EDGE: &str = "half edge";
/// Case: an artificial edge replacing a partial edge, rebuilt.
pub const PARTIAL_EDGE: &str = "partial edge";
/// Case: a viewpoint translated into another embedding met in the sample.
pub const ACROSS: &str = "across embeddings";
/// Case: a viewpoint translated onto another reflex map vertex.
pub const TRANSLATE: &str = "translate";
/// Case: a translate with the same skeleton.
pub const IF: &str = "if";
/// Case: a translate with another skeleton.
pub const ONLY_IF: &str = "only if";

/// Checks T3.2 on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_viewpoints(study, sample::VIEWPOINTS)
}

/// The check on the study's `viewpoints` sampled viewpoints (their V_p
/// shared with the other chapter 3 checkers).
pub fn check_viewpoints(study: &Study<'_>, viewpoints: usize) -> Report {
    let map = study.map();
    let index = study.index();
    let mut report = Report::new(ID);
    let mut groups: BTreeMap<SkeletonKey, Vec<(usize, Point)>> = BTreeMap::new();
    let vps = study.sampled_polygons(viewpoints);
    let mut skeletons: Vec<Option<(Skeleton, SkeletonKey)>> = Vec::with_capacity(vps.len());
    for (k, vp) in vps.iter().enumerate() {
        let (r, skeleton) = rebuild(map, vp);
        report.absorb(r);
        report.hit(REBUILD);
        skeletons.push(skeleton.map(|sk| {
            let key = sk.key();
            (sk, key)
        }));
        if let Some((sk, key)) = &skeletons[k] {
            let key = key.clone();
            for (s, label) in key.labels.iter().enumerate() {
                let Some(l) = label else { continue };
                let ends = [key.offsets[s], key.offsets[(s + 1) % key.offsets.len()]];
                let on_line = ends.iter().any(|&(x, y)| l.contains(x, y));
                report.hit(if on_line { HALF_EDGE } else { PARTIAL_EDGE });
            }
            groups.entry(key).or_default().push((k, sk.origin()));
        }
    }
    let reflex: Vec<Point> = map
        .reflex_vertices()
        .iter()
        .map(|&m| map.vertices()[m])
        .collect();
    let direction = |same: Option<bool>| match same {
        Some(true) => Some(IF),
        Some(false) => Some(ONLY_IF),
        None => None,
    };
    for members in groups.values() {
        let mut origins: Vec<Point> = members.iter().map(|&(_, o)| o).collect();
        origins.sort_by_key(|o| (o.x, o.y));
        origins.dedup();
        for &(k, own) in members {
            // Other embeddings of the skeleton met in the sample.
            let (sk, key) = skeletons[k].as_ref().expect("grouped by its skeleton");
            for &o in origins.iter().filter(|&&o| o != own) {
                let (r, outcome) = check_translated_with(index, &vps[k], sk, key, o, true);
                report.absorb(r);
                report.hit(ACROSS);
                if let Some(case) = direction(outcome) {
                    report.hit(case);
                }
            }
            // Every other reflex map vertex as a would-be origin: the
            // "only if" direction, and the "if" direction where the
            // skeleton happens to be the same.
            for &o in reflex
                .iter()
                .filter(|&&o| o != own && !origins.contains(&o))
            {
                let (r, outcome) = check_translated_with(index, &vps[k], sk, key, o, false);
                report.absorb(r);
                if let Some(case) = direction(outcome) {
                    report.hit(TRANSLATE);
                    report.hit(case);
                }
            }
        }
    }
    report
}

/// T3.2 on one V_p of `map`: rebuild it from (V*_p, p − v0) and compare.
/// One instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    rebuild(map, vp).0
}

/// [`check_polygon`] with V_p rebuilt from `key_of(V*_p's key)` instead of
/// the key itself: how [`crate::planted`] feeds the checker a wrong key, to
/// show that the search finds and shrinks the violations this causes.
pub fn check_polygon_with_key(
    map: &Map,
    vp: &VisibilityPolygon,
    key_of: fn(SkeletonKey) -> SkeletonKey,
) -> Report {
    rebuild_keyed(map, vp, key_of).0
}

fn violation(
    map: &Map,
    vp: &VisibilityPolygon,
    what: String,
    extra: serde_json::Value,
) -> Violation {
    let mut data = sample::replay(map, vp);
    data.insert("instance".into(), extra);
    Violation::with_data(
        format!(
            "map {}, viewpoint {}: {what}",
            sample::map_name(map),
            vp.viewpoint()
        ),
        data.into(),
    )
}

/// The rebuild instance, and the skeleton if it could be built.
fn rebuild(map: &Map, vp: &VisibilityPolygon) -> (Report, Option<Skeleton>) {
    rebuild_keyed(map, vp, |key| key)
}

/// [`rebuild`] from `key_of` of the skeleton's key.
fn rebuild_keyed(
    map: &Map,
    vp: &VisibilityPolygon,
    key_of: fn(SkeletonKey) -> SkeletonKey,
) -> (Report, Option<Skeleton>) {
    let mut report = Report::new(ID);
    let sk = match Skeleton::of(map, vp) {
        Ok(sk) => sk,
        Err(e) => {
            report.record(Some(violation(
                map,
                vp,
                format!("V*_p cannot be built: {e}"),
                json!({"skeleton_error": e.to_string()}),
            )));
            return (report, None);
        }
    };
    let o = sk.origin();
    let rebuilt = reconstruct(&key_of(sk.key()), &translate(vp.viewpoint(), -o.x, -o.y));
    let points = vp.points();
    let expected = points
        .iter()
        .position(|q| *q == RatPoint::from(o))
        .map(|start| {
            let mut rel: Vec<RatPoint> = points.iter().map(|q| translate(q, -o.x, -o.y)).collect();
            rel.rotate_left(start);
            rel
        });
    let ok = expected.as_ref() == Some(&rebuilt);
    report.record((!ok).then(|| {
        let show = |v: &[RatPoint]| v.iter().map(ToString::to_string).collect::<Vec<_>>();
        violation(
            map,
            vp,
            format!(
                "V_p rebuilt from V*_p and p - v0 (v0 = {o:?}) differs from V_p{}",
                if expected.is_none() {
                    ": v0 is not a vertex of V_p"
                } else {
                    ""
                }
            ),
            json!({"origin": [o.x.to_string(), o.y.to_string()],
                   "rebuilt_relative": show(&rebuilt),
                   "vp_relative": expected.as_deref().map(show)}),
        )
    }));
    (report, Some(sk))
}

/// T3.2 across embeddings, one instance: translate the viewpoint of `vp` by
/// `target − v0` (v0 the origin of V*_p) and test that V_q equals the
/// translate of V_p iff V*_q equals V*_p with origin `target`. Returns the
/// report and, if an instance was examined, whether the skeletons were
/// equal (the premise held).
///
/// If `embedding` is true, `target` is the origin of another embedding of
/// V*_p (the origin of a sampled viewpoint with the same skeleton), and the
/// translate must lie inside the map: a translate outside is a violation.
/// Otherwise a translate that is not inside the map is no instance.
///
/// `vp` must be a visibility polygon of `index`'s map whose skeleton can be
/// built.
pub fn check_translated(
    index: &VisibilityIndex<'_>,
    vp: &VisibilityPolygon,
    target: Point,
    embedding: bool,
) -> (Report, Option<bool>) {
    let sk = Skeleton::of(index.map(), vp).expect("the caller built this skeleton");
    let key = sk.key();
    check_translated_with(index, vp, &sk, &key, target, embedding)
}

/// [`check_translated`] with V*_p and its key already built.
///
/// V*_q is read off the expansion
/// ([`VisibilityIndex::skeleton_at`], tested equal to [`Skeleton::of`] on
/// V_q). Where it differs from V*_p with origin `target` and its
/// non-spurious vertices are not V*_p's translated, V_q ≠ V_p + t follows
/// without building V_q: Def 3.4 makes a vertex spurious by the polygon
/// and the viewpoint alone, and the canonical origin is chosen by the
/// polygon alone, so equal polygons (with the viewpoint) have the same
/// non-spurious vertices from the same origin. Otherwise V_q is built and
/// compared vertex by vertex.
fn check_translated_with(
    index: &VisibilityIndex<'_>,
    vp: &VisibilityPolygon,
    sk: &Skeleton,
    key: &SkeletonKey,
    target: Point,
    embedding: bool,
) -> (Report, Option<bool>) {
    let map = index.map();
    let mut report = Report::new(ID);
    let o = sk.origin();
    let (dx, dy) = (target.x - o.x, target.y - o.y);
    let q = translate(vp.viewpoint(), dx, dy);
    // A violation's data, built only for a violation.
    let base = || {
        json!({"origin": [o.x.to_string(), o.y.to_string()],
               "target_origin": [target.x.to_string(), target.y.to_string()],
               "translated_viewpoint": q.to_string(),
               "translated_viewpoint_file_units": sample::point_json(map, &q)})
    };
    if map.locate(&q) != Containment::Inside {
        if !embedding {
            return (report, None);
        }
        report.record(Some(violation(
            map,
            vp,
            format!(
                "the translate {q} of p into the embedding at {target:?} is not inside the map"
            ),
            base(),
        )));
        return (report, Some(false));
    }
    let v = map.vertices();
    let fresh = index.skeleton_at(&q).ok();
    let same_skeleton = fresh
        .as_ref()
        .is_some_and(|f| v[f.origin()] == target && f.is(map, f.origin(), key));
    let same_support = fresh.as_ref().is_some_and(|f| {
        f.vertices.len() == sk.vertices().len()
            && f.vertices
                .iter()
                .zip(sk.vertices())
                .all(|(&m, u)| v[m] == Point::new(u.x + dx, u.y + dy))
    });
    if !same_skeleton && !same_support && fresh.is_some() {
        // Different non-spurious vertices: different polygons, as the
        // theorem's "only if" requires.
        report.record(None);
        return (report, Some(false));
    }
    let vq = index
        .visibility_polygon(&q)
        .expect("an interior point has a visibility polygon");
    let translated: Vec<RatPoint> = vp.points().iter().map(|x| translate(x, dx, dy)).collect();
    let same_polygon = vq.points() == translated
        && vq
            .vertices()
            .iter()
            .zip(vp.vertices())
            .all(|(a, b)| a.spurious == b.spurious)
        && vq
            .edges()
            .iter()
            .zip(vp.edges())
            .all(|(a, b)| a.kind == b.kind);
    report.record((same_skeleton != same_polygon).then(|| {
        let mut extra = base();
        extra["same_skeleton"] = json!(same_skeleton);
        extra["same_polygon"] = json!(same_polygon);
        extra["vq"] = json!(vq
            .points()
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>());
        violation(
            map,
            vp,
            format!(
                "translated to {q} (embedding at {target:?}): V*_q = V*_p is {same_skeleton} \
                 but V_q = V_p + t is {same_polygon}"
            ),
            extra,
        )
    }));
    (report, Some(same_skeleton))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corridor(k: u32) -> (Map, Vec<RatPoint>) {
        let map = wai_gen::family("corridor-niches", &[k]).unwrap();
        let views = wai_gen::corridor_niches_viewpoints(k)
            .into_iter()
            .map(RatPoint::from)
            .collect();
        (map, views)
    }

    #[test]
    fn a_correct_polygon_passes() {
        let (map, views) = corridor(3);
        let index = VisibilityIndex::new(&map);
        let vp = index.visibility_polygon(&views[0]).unwrap();
        let r = check_polygon(&map, &vp);
        assert_eq!(
            (r.examined, r.violations.len()),
            (1, 0),
            "{:?}",
            r.violations
        );
        let r = CHECKER.run(&Study::new(&map));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let case = |c: &str| r.cases.get(c).copied().unwrap_or(0);
        // Every niche viewpoint is translated into the two other niches.
        assert!(case(ACROSS) >= 6, "{:?}", r.cases);
        assert!(case(IF) >= 6, "{:?}", r.cases);
        assert_eq!(r.examined, case(REBUILD) + case(ACROSS) + case(TRANSLATE));
        assert_eq!(case(IF) + case(ONLY_IF), case(ACROSS) + case(TRANSLATE));
        assert!(case(TRANSLATE) > 0 && case(ONLY_IF) > 0, "{:?}", r.cases);
        // The niche viewpoint's skeleton closes the niche by one artificial
        // edge through both mouth corners' blocking rays: a partial edge.
        assert!(case(PARTIAL_EDGE) > 0, "{:?}", r.cases);
    }

    /// V_p of the first niche viewpoint with its first spurious vertex
    /// moved one unit along its edge direction.
    fn moved_spurious_vertex(vp: &VisibilityPolygon) -> VisibilityPolygon {
        let mut vertices = vp.vertices().to_vec();
        let s = vertices
            .iter()
            .position(|v| v.spurious)
            .expect("a spurious vertex");
        vertices[s].point = translate(&vertices[s].point, 1, 0);
        VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, vp.edges().to_vec())
    }

    #[test]
    fn a_moved_vertex_is_reported() {
        let (map, views) = corridor(3);
        let vp = VisibilityIndex::new(&map)
            .visibility_polygon(&views[0])
            .unwrap();
        let r = check_polygon(&map, &moved_spurious_vertex(&vp));
        assert_eq!(r.violations.len(), 1);
        let v = &r.violations[0];
        assert_eq!(v.data["map"], "corridor-niches/k=3");
        assert_eq!(v.data["viewpoint"], json!(["5", "-3"]));
        assert!(v.data["instance"]["rebuilt_relative"].is_array());
        // Moving a non-spurious vertex: the skeleton keeps the map vertex,
        // so the rebuilt polygon differs from the moved one.
        let mut vertices = vp.vertices().to_vec();
        let k = vertices.iter().position(|v| !v.spurious).unwrap();
        vertices[k].point = translate(&vertices[k].point, 0, 1);
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, vp.edges().to_vec());
        assert_eq!(check_polygon(&map, &broken).violations.len(), 1);
    }

    #[test]
    fn a_moved_vertex_is_reported_across_embeddings() {
        let (map, views) = corridor(3);
        let index = VisibilityIndex::new(&map);
        let vp = index.visibility_polygon(&views[0]).unwrap();
        let other = Skeleton::of(&map, &index.visibility_polygon(&views[2]).unwrap())
            .unwrap()
            .origin();
        let (r, same) = check_translated(&index, &vp, other, true);
        assert!(
            same == Some(true) && r.violations.is_empty(),
            "{:?}",
            r.violations
        );
        let (r, same) = check_translated(&index, &moved_spurious_vertex(&vp), other, true);
        assert_eq!(same, Some(true), "the skeleton ignores spurious vertices");
        assert_eq!(r.violations.len(), 1, "{:?}", r.violations);
        let v = &r.violations[0];
        assert_eq!(v.data["instance"]["same_skeleton"], true);
        assert_eq!(v.data["instance"]["same_polygon"], false);
        assert_eq!(v.data["instance"]["translated_viewpoint"], "(13, -3)");
    }
}
