//! `wai check --target CLAIM:CASE`: a hill climb ([`crate::climb`]) toward
//! maps that hit a case of a claim's proof that no run has hit yet.
//!
//! The score of a map is read off the claim's checker: first the
//! instances of the case on the map, then the checker's progress toward
//! it ([`wai_lemmas::Report::toward`], e.g. the largest k for "k ≥ 3"),
//! then the instances of the claim examined (more instances of the premise
//! give the case more chances). The climb stops at the first map that hits
//! the case.

use rug::Rational;
use serde_json::json;
use wai_lemmas::{Case, Checker};
use wai_map::Map;
use wai_study::Study;

use crate::climb::Evaluation;

/// A case of a claim to search for.
#[derive(Debug, Clone, Copy)]
pub struct Target {
    pub checker: Checker,
    pub case: Case,
}

impl Target {
    /// Parses `CLAIM:CASE` (the case as the checker names it).
    pub fn parse(spec: &str) -> Result<Target, String> {
        let (id, case) = spec
            .split_once(':')
            .ok_or_else(|| format!("--target {spec}: expected CLAIM:CASE, e.g. T5.15:k=3"))?;
        let checker = wai_lemmas::checker(id.trim())
            .ok_or_else(|| format!("--target {spec}: no checker of a claim {id:?}"))?;
        let case = checker
            .cases
            .iter()
            .find(|c| c.name == case.trim())
            .copied()
            .ok_or_else(|| {
                let names: Vec<&str> = checker.cases.iter().map(|c| c.name).collect();
                if names.is_empty() {
                    format!("--target {spec}: {id} names no cases")
                } else {
                    format!(
                        "--target {spec}: {id} has no case {case:?}; its cases are {}",
                        names.join(", ")
                    )
                }
            })?;
        Ok(Target { checker, case })
    }

    /// `CLAIM:CASE`.
    pub fn name(&self) -> String {
        format!("{}:{}", self.checker.id, self.case.name)
    }

    /// The score of `map`: (instances of the case, then progress toward it
    /// and instances of the claim as the guide).
    pub fn evaluate(&self, map: &Map) -> Evaluation {
        let report = self.checker.run(&Study::new(map));
        let hits = report.cases.get(self.case.name).copied().unwrap_or(0);
        let progress = report
            .toward
            .get(self.case.name)
            .cloned()
            .unwrap_or_default();
        // Progress first, the claim's instances as a tie-break below one
        // unit of progress: examined / (examined + 1) < 1.
        let guide = progress + Rational::from((report.examined, report.examined + 1));
        Evaluation {
            value: Rational::from(hits),
            guide,
            detail: json!({
                "hits": hits,
                "toward": report.toward.get(self.case.name).map(|p| p.to_string()),
                "examined": report.examined,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_parse_with_clear_errors() {
        let planted = Target::parse("T4.2");
        assert!(planted.unwrap_err().contains("expected CLAIM:CASE"));
        assert!(Target::parse("X1.1:a").unwrap_err().contains("no checker"));
    }
}
