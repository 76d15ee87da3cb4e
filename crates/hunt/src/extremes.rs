//! The worst-case search of `wai search-extremes`: a hill climb
//! ([`crate::climb`]) that maximises one chapter 5 ratio, read off the
//! report of the claim's own checker (never recomputed here).

use rug::Rational;
use serde_json::{json, Value};
use wai_lemmas::ch5::{t5_12, t5_15, t5_16, t5_17};
use wai_lemmas::{Checker, Report};
use wai_map::Map;
use wai_study::Study;

use crate::climb::Evaluation;

/// The ratio a search maximises.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ratio {
    /// Theorem 5.17: max |EC| / (n + r²).
    Ec,
    /// Theorem 5.12: max over classes of |C_mult| / r.
    Cmult,
    /// Theorem 5.16: max over classes of W / r².
    Wedge,
    /// Theorem 5.15: k, the most valid embeddings of one skeleton in which
    /// map edge e is a valid candidate edge of one artificial edge and f a
    /// valid multiple candidate edge of another.
    K,
}

impl Ratio {
    /// Every ratio.
    pub const ALL: [Ratio; 4] = [Ratio::Ec, Ratio::Cmult, Ratio::Wedge, Ratio::K];

    /// The id used on the command line.
    pub fn id(self) -> &'static str {
        match self {
            Ratio::Ec => "ec",
            Ratio::Cmult => "cmult",
            Ratio::Wedge => "wedge",
            Ratio::K => "k",
        }
    }

    /// The ratio named `id`.
    pub fn named(id: &str) -> Option<Ratio> {
        Ratio::ALL.into_iter().find(|r| r.id() == id)
    }

    /// The checker whose report measures it.
    pub fn checker(self) -> Checker {
        match self {
            Ratio::Ec => t5_17::CHECKER,
            Ratio::Cmult => t5_12::CHECKER,
            Ratio::Wedge => t5_16::CHECKER,
            Ratio::K => t5_15::CHECKER,
        }
    }

    /// The claim of `CLAIMS.md` whose quantity it is.
    pub fn claim(self) -> &'static str {
        self.checker().id
    }

    /// What is measured, in the thesis's terms.
    pub fn measure(self) -> &'static str {
        match self {
            Ratio::Ec => "max |EC| / (n + r²) (Theorem 5.17)",
            Ratio::Cmult => "max over skeletons of |C_mult| / r (Theorem 5.12)",
            Ratio::Wedge => "max over classes of W / r² (Theorem 5.16)",
            Ratio::K => {
                "Theorem 5.15's k: the most valid embeddings of one skeleton in which map edge e \
                 is a valid candidate edge of one artificial edge and f a valid multiple \
                 candidate edge (|C_{i,j}| > 1) of another"
            }
        }
    }

    /// The claim's ceiling (for `k`, the theorem's bound
    /// [`t5_15::BOUND`]).
    pub fn ceiling(self) -> Rational {
        match self {
            Ratio::K => Rational::from(t5_15::BOUND),
            _ => self.checker().ceiling().expect("a bound has a ceiling"),
        }
    }

    /// The ratio on `map`, exactly, from its checker's report.
    pub fn evaluate(self, map: &Map) -> Evaluation {
        self.of_report(&self.checker().run(&Study::new(map)))
    }

    /// The ratio as `report` (of [`Ratio::checker`]) measured it: its
    /// largest ratio (0 when the map has nothing to measure) and where it
    /// was reached; for `k`, k itself (the report measures k/6) with the
    /// premise count as the guide on the plateaus of k.
    pub fn of_report(self, report: &Report) -> Evaluation {
        let (ratio, at) = report
            .largest
            .as_ref()
            .map_or((Rational::new(), Value::Null), |l| {
                (l.ratio.clone(), l.at.clone())
            });
        match self {
            Ratio::K => {
                let count = |name| report.counts.get(name).copied().unwrap_or(0);
                let premise = count("premise_embeddings");
                let mut detail = if at.is_object() { at } else { json!({}) };
                detail["premise_embeddings"] = json!(premise);
                Evaluation {
                    value: ratio * Rational::from(t5_15::BOUND),
                    guide: Rational::from(premise),
                    detail,
                }
            }
            _ => Evaluation::of(ratio, at),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::climb::{search, start_maps, Config, Starts};
    use wai_gen::mutate::Limits;

    #[test]
    fn a_real_ratio_search_is_deterministic() {
        let limits = Limits {
            max_n: 20,
            ..Limits::default()
        };
        let s: Vec<(String, Map)> = start_maps(Starts::Both, 3, &limits)
            .into_iter()
            .step_by(5)
            .take(3)
            .collect();
        let config = Config {
            seed: 5,
            evals: Some(12),
            budget: None,
            limits,
            pool: 3,
            keep: 2,
            stall: 10,
            min_r: 0,
            goal: None,
        };
        let run = || search(&s, &config, &|m| Ratio::Cmult.evaluate(m), &mut |_| {});
        let key = |o: &crate::climb::Outcome| -> Vec<(Vec<wai_exact::Point>, Rational)> {
            o.best
                .iter()
                .map(|f| (f.map.vertices().to_vec(), f.eval.value.clone()))
                .collect()
        };
        assert_eq!(key(&run()), key(&run()));
    }

    #[test]
    fn k_on_the_bottles_of_fig_4_31() {
        // Fig 4.31: the artificial edges across the necks have two valid
        // candidate edges each, in both valid embeddings.
        let map = wai_gen::bottled_niches(0);
        let e = Ratio::K.evaluate(&map);
        assert_eq!((e.value, e.guide), (Rational::from(1), Rational::from(2)));
        assert_eq!(e.detail["k"], 1);
    }

    #[test]
    fn ec_is_the_checkers_ratio() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        // max |EC| = 20, n = 12, r = 4 (the snapshot counts).
        assert_eq!(Ratio::Ec.evaluate(&map).value, Rational::from((20, 28)));
        for r in Ratio::ALL {
            assert_eq!(Ratio::named(r.id()), Some(r));
        }
    }
}
