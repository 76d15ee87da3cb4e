#![allow(
    clippy::float_arithmetic,
    reason = "sensor settings are approximate; no geometric decision reads them"
)]
//! Parsers of the numeric options (clap `value_parser`s): NaN, infinities
//! (`1e400`), negative counts and values out of their documented range are
//! refused when the command line is read, with the option's name, the
//! value and what it accepts (clap prints "invalid value 'V' for
//! '--OPTION': …" and exits with status 2).
//!
//! Options that take these parsers also set `allow_negative_numbers`, so
//! that `--poses -5` reaches the parser and is refused as a negative count
//! instead of being read as an unknown flag `-5`.

/// A finite number.
pub fn finite(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("{s:?} is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{s} is not a finite number"))
    }
}

/// A finite number ≥ 0.
pub fn non_negative(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("{s} is negative; expected a number ≥ 0"))
    }
}

/// A finite number > 0.
pub fn positive(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("{s} is not > 0"))
    }
}

/// A field of view in degrees, in (0, 360].
pub fn fov_degrees(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 && v <= 360.0 {
        Ok(v)
    } else {
        Err(format!(
            "{s}° is not a field of view; expected degrees in (0, 360]"
        ))
    }
}

/// A fraction in (0, 1].
pub fn fraction(s: &str) -> Result<f64, String> {
    let v = finite(s)?;
    if v > 0.0 && v <= 1.0 {
        Ok(v)
    } else {
        Err(format!("{s} is not in (0, 1]"))
    }
}

/// A whole number ≥ 0.
pub fn count(s: &str) -> Result<usize, String> {
    whole(s, 0)
}

/// A whole number ≥ 1.
pub fn positive_count(s: &str) -> Result<usize, String> {
    whole(s, 1)
}

/// A whole number ≥ `min`, of the option's integer type.
fn whole<T>(s: &str, min: T) -> Result<T, String>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display,
{
    let t = s.trim();
    let expected = format!("expected a whole number ≥ {min}");
    if t.strip_prefix('-')
        .is_some_and(|rest| rest.parse::<u128>().is_ok())
    {
        return Err(format!("{s} is negative; {expected}"));
    }
    match t.parse::<T>() {
        Ok(n) if n >= min => Ok(n),
        Ok(n) => Err(format!("{n} is too small; {expected}")),
        Err(_) => Err(format!("{s:?} is not a whole number; {expected}")),
    }
}

/// A whole number ≥ 0, as a `u64` (seeds, counts of maps).
pub fn count_u64(s: &str) -> Result<u64, String> {
    whole(s, 0)
}

/// A size in bytes: a whole number with an optional binary suffix `K`,
/// `M`, `G` or `T` (KiB … TiB), e.g. `512M`, `2G`.
pub fn bytes(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (digits, shift) = match t.char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => {
            let shift = match c.to_ascii_uppercase() {
                'K' => 10,
                'M' => 20,
                'G' => 30,
                'T' => 40,
                _ => return Err(format!("{s:?}: expected a size such as 512M or 2G")),
            };
            (&t[..i], shift)
        }
        _ => (t, 0),
    };
    let n: u64 = digits
        .parse()
        .map_err(|_| format!("{s:?}: expected a size such as 512M or 2G"))?;
    match n.checked_mul(1 << shift) {
        Some(0) | None => Err(format!("{s}: expected a size above 0 and below 2^64 bytes")),
        Some(b) => Ok(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_name_the_value_and_the_range() {
        assert!(finite("NaN").unwrap_err().contains("not a finite number"));
        assert!(finite("1e400").unwrap_err().contains("not a finite number"));
        assert!(finite("inf").is_err() && finite("x").is_err());
        assert_eq!(finite(" -2.5 "), Ok(-2.5));
        assert!(non_negative("-1").unwrap_err().contains("negative"));
        assert_eq!(non_negative("0"), Ok(0.0));
        assert!(positive("0").is_err() && positive("-3").is_err());
        assert!(fov_degrees("0").is_err() && fov_degrees("361").is_err());
        assert_eq!(fov_degrees("90"), Ok(90.0));
        assert!(fraction("1.5").is_err() && fraction("0").is_err());
        assert!(count("-5").unwrap_err().contains("negative"));
        assert!(count("2.5").is_err() && count("").is_err());
        assert_eq!(count("0"), Ok(0));
        assert!(positive_count("0").unwrap_err().contains("≥ 1"));
        assert!(positive_count("-5")
            .unwrap_err()
            .contains("negative; expected a whole number ≥ 1"));
        assert_eq!(positive_count("7"), Ok(7));
        assert_eq!(bytes("512M"), Ok(512 << 20));
        assert_eq!(bytes("2g"), Ok(2 << 30));
        assert_eq!(bytes("4096"), Ok(4096));
        assert!(bytes("-1G").is_err() && bytes("1X").is_err() && bytes("0").is_err());
    }
}
