//! What a map's coordinates measure: the map format's optional `"units"`
//! (`"m"`, `"lonlat"`, `"scale:K"` with K metres per unit), or, when a
//! file does not say, the guess the commands make.

use rug::Rational;

/// The units a map states.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Units {
    /// Metres.
    Metres,
    /// Longitude, latitude in degrees (WGS 84).
    LonLat,
    /// K metres per unit, K > 0 exact (a plan in centimetres: `scale:0.01`).
    Scale(Rational),
}

impl Units {
    /// Reads `"m"`, `"lonlat"` or `"scale:K"` (K an exact number > 0).
    pub fn parse(text: &str) -> Result<Units, String> {
        match text {
            "m" => Ok(Units::Metres),
            "lonlat" => Ok(Units::LonLat),
            _ => {
                let k = text
                    .strip_prefix("scale:")
                    .and_then(|k| crate::parse_exact(k).ok())
                    .filter(|k| *k > 0);
                k.map(Units::Scale).ok_or_else(|| {
                    format!(
                        "{text:?}: expected \"m\", \"lonlat\" or \"scale:K\" with K > 0 metres per unit"
                    )
                })
            }
        }
    }
}

impl std::fmt::Display for Units {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Units::Metres => write!(f, "m"),
            Units::LonLat => write!(f, "lonlat"),
            Units::Scale(k) => write!(f, "scale:{}", crate::format_exact(k)),
        }
    }
}

impl crate::Map {
    /// Whether the map looks like longitude/latitude: every coordinate
    /// within ±180 (x) and ±90 (y), spanning less than 0.1 in both (a
    /// building in degrees). What `auto` assumes when a map states no
    /// units.
    pub fn looks_lonlat(&self) -> bool {
        let (lo, hi) = self.bounding_box();
        let c = |v: i128| Rational::from((rug::Integer::from(v), self.scale().clone()));
        let (x0, y0, x1, y1) = (c(lo.x), c(lo.y), c(hi.x), c(hi.y));
        let within = x0 >= -180 && x1 <= 180 && y0 >= -90 && y1 <= 90;
        let tenth = Rational::from((1, 10));
        within && Rational::from(&x1 - &x0) < tenth && Rational::from(&y1 - &y0) < tenth
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_read_back_as_written() {
        for text in ["m", "lonlat", "scale:0.01", "scale:1/3"] {
            let u = Units::parse(text).unwrap();
            assert_eq!(Units::parse(&u.to_string()), Ok(u), "{text}");
        }
        for bad in ["metres", "scale:0", "scale:-1", "scale:", "scale:x", ""] {
            assert!(Units::parse(bad).unwrap_err().contains("expected"), "{bad}");
        }
    }
}
