//! Exact numbers from text, and back.

use crate::error::{MapError, NumberError};
use rug::{Integer, Rational};
use wai_exact::{Point, MAX_COORD_BITS};

/// The longest number text accepted. A coordinate within
/// [`MAX_COORD_BITS`] needs about 31 decimal digits; the limit leaves room
/// for long decimal fractions and keeps hostile input cheap.
pub const MAX_NUMBER_LEN: usize = 1000;

/// Parse an exact number: an integer (`-12`), a decimal (`384.25`) or a
/// fraction (`-7/4`). A leading `+` or `-` is allowed; nothing else is: no
/// white space, exponents, `NaN` or infinities.
///
/// ```
/// use rug::Rational;
/// use wai_map::parse_exact;
/// assert_eq!(parse_exact("0.125").unwrap(), Rational::from((1, 8)));
/// assert_eq!(parse_exact("-6/4").unwrap(), Rational::from((-3, 2)));
/// assert!(parse_exact("1e3").is_err());
/// assert!(parse_exact("1/0").is_err());
/// ```
pub fn parse_exact(text: &str) -> Result<Rational, NumberError> {
    if text.is_empty() {
        return Err(NumberError::Empty);
    }
    if text.len() > MAX_NUMBER_LEN {
        return Err(NumberError::TooLong {
            max: MAX_NUMBER_LEN,
        });
    }
    let lower = text.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if ["nan", "inf", "infinity"].contains(&lower.as_str()) {
        return Err(NumberError::NotFinite);
    }
    let (negative, body, offset) = match text.as_bytes()[0] {
        b'-' => (true, &text[1..], 1),
        b'+' => (false, &text[1..], 1),
        _ => (false, text, 0),
    };
    let unexpected = |position: usize| {
        let found = text[position..].chars().next().unwrap_or(' ');
        if found == 'e' || found == 'E' {
            NumberError::Exponent
        } else {
            NumberError::Unexpected { found, position }
        }
    };
    let digits = |s: &str, at: usize| -> Result<Integer, NumberError> {
        if s.is_empty() {
            return Err(if at < text.len() {
                unexpected(at)
            } else {
                NumberError::Empty
            });
        }
        match s.bytes().position(|b| !b.is_ascii_digit()) {
            Some(i) => Err(unexpected(at + i)),
            None => Ok(s.parse::<Integer>().expect("ASCII digits parse")),
        }
    };
    let value = if let Some(slash) = body.find('/') {
        let p = digits(&body[..slash], offset)?;
        let q = digits(&body[slash + 1..], offset + slash + 1)?;
        if q == 0 {
            return Err(NumberError::ZeroDenominator);
        }
        Rational::from((p, q))
    } else if let Some(dot) = body.find('.') {
        let whole = digits(&body[..dot], offset)?;
        let frac_text = &body[dot + 1..];
        let frac = digits(frac_text, offset + dot + 1)?;
        let den = Integer::from(Integer::u_pow_u(10, frac_text.len() as u32));
        Rational::from((whole * &den + frac, den))
    } else {
        Rational::from(digits(body, offset)?)
    };
    Ok(if negative { -value } else { value })
}

/// Format an exact number the way [`parse_exact`] reads it back: an integer,
/// a finite decimal when the denominator divides a power of ten, else `p/q`.
pub fn format_exact(v: &Rational) -> String {
    let den = v.denom();
    if *den == 1 {
        return v.numer().to_string();
    }
    let mut d = den.clone();
    let twos = d.remove_factor_mut(&Integer::from(2));
    let fives = d.remove_factor_mut(&Integer::from(5));
    if d == 1 {
        let k = twos.max(fives);
        let scaled = v.numer() * Integer::from(Integer::u_pow_u(10, k)) / den;
        let sign = if scaled < 0 { "-" } else { "" };
        let digits = scaled.abs().to_string();
        let k = k as usize;
        let padded = format!("{digits:0>width$}", width = k + 1);
        let (int, frac) = padded.split_at(padded.len() - k);
        return format!("{sign}{int}.{frac}");
    }
    format!("{}/{}", v.numer(), v.denom())
}

/// What rounding coordinates to a grid changed ([`crate::json::ReadOptions`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rounding {
    /// The grid: multiples of `2^-bits`.
    pub bits: u32,
    /// How many coordinates were not on the grid and moved.
    pub moved: usize,
    /// The largest distance a coordinate moved (0 if none did), in input
    /// units; below `2^-(bits+1)`, or equal to it at a tie.
    pub largest: Rational,
}

/// Round every coordinate to the nearest multiple of `2^-bits` (a tie away
/// from zero). The same monotone map on every coordinate: equal coordinates
/// stay equal (an orthogonal map stays orthogonal) and the order of
/// coordinates more than `2^-bits` apart is kept.
pub(crate) fn round_to_grid(coords: &mut [RawCoord], bits: u32) -> Rounding {
    let unit = Rational::from((Integer::from(1), Integer::from(1) << bits));
    let mut moved = 0;
    let mut largest = Rational::new();
    for c in coords.iter_mut() {
        let steps = Rational::from(&c.value / &unit).round();
        let rounded = Rational::from(&unit * &steps);
        if rounded != c.value {
            moved += 1;
            let d = Rational::from(&rounded - &c.value).abs();
            if d > largest {
                largest = d;
            }
            c.value = rounded;
        }
    }
    Rounding {
        bits,
        moved,
        largest,
    }
}

/// A coordinate read from input, with the path that names it in errors.
pub(crate) struct RawCoord {
    pub path: String,
    pub value: Rational,
}

/// Scale exact coordinates to integers by their least common denominator.
///
/// Returns the integer points (pairs of consecutive coordinates) and the
/// scale, or every coordinate that ends up beyond [`MAX_COORD_BITS`].
pub(crate) fn scale_to_integers(
    coords: &[RawCoord],
) -> Result<(Vec<Point>, Integer), Vec<MapError>> {
    let mut lcm = Integer::from(1);
    let max_den_bits = coords
        .iter()
        .map(|c| c.value.denom().significant_bits())
        .max();
    // Any non-zero coordinate scales to at least lcm / its denominator, so a
    // common denominator beyond 2^(MAX + max denominator bits) cannot fit.
    let lcm_cap = u64::from(MAX_COORD_BITS) + u64::from(max_den_bits.unwrap_or(0)) + 1;
    for c in coords {
        lcm.lcm_mut(c.value.denom());
        if u64::from(lcm.significant_bits()) > lcm_cap {
            return Err(vec![MapError::CoordinateTooLarge {
                path: c.path.clone(),
                bits: u64::from(lcm.significant_bits()),
                max: MAX_COORD_BITS,
            }]);
        }
    }
    let mut errors = Vec::new();
    let mut ints = Vec::with_capacity(coords.len());
    for c in coords {
        let v = c.value.numer() * Integer::from(&lcm / c.value.denom());
        let bits = v.significant_bits();
        if bits > MAX_COORD_BITS {
            errors.push(MapError::CoordinateTooLarge {
                path: c.path.clone(),
                bits: u64::from(bits),
                max: MAX_COORD_BITS,
            });
            ints.push(0);
        } else {
            ints.push(v.to_i128().expect("within MAX_COORD_BITS"));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let points = ints.chunks(2).map(|xy| Point::new(xy[0], xy[1])).collect();
    Ok((points, lcm))
}
