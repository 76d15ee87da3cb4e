use rug::Rational;
use wai_map::{format_exact, parse_exact, NumberError};

fn check(text: &str, expect: Result<(i64, i64), NumberError>) {
    let got = parse_exact(text);
    let want = expect.map(|(p, q)| Rational::from((p, q)));
    assert_eq!(got, want, "parsing {text:?}");
}

#[test]
fn accepted_syntax() {
    check("0", Ok((0, 1)));
    check("-0", Ok((0, 1)));
    check("+17", Ok((17, 1)));
    check("384.333333333", Ok((384_333_333_333, 1_000_000_000)));
    check("-2.50", Ok((-5, 2)));
    check("7/1", Ok((7, 1)));
    check("-95/4", Ok((-95, 4)));
    check("6/4", Ok((3, 2)));
    check("007", Ok((7, 1)));
}

#[test]
fn rejected_syntax() {
    check("", Err(NumberError::Empty));
    check("1e3", Err(NumberError::Exponent));
    check("1.5E-3", Err(NumberError::Exponent));
    check("NaN", Err(NumberError::NotFinite));
    check("-inf", Err(NumberError::NotFinite));
    check("Infinity", Err(NumberError::NotFinite));
    check("1/0", Err(NumberError::ZeroDenominator));
    check(
        "1/-2",
        Err(NumberError::Unexpected {
            found: '-',
            position: 2,
        }),
    );
    check(
        " 1",
        Err(NumberError::Unexpected {
            found: ' ',
            position: 0,
        }),
    );
    check("1.", Err(NumberError::Empty));
    check(
        ".5",
        Err(NumberError::Unexpected {
            found: '.',
            position: 0,
        }),
    );
    check(
        "0x10",
        Err(NumberError::Unexpected {
            found: 'x',
            position: 1,
        }),
    );
    check(
        "1.2.3",
        Err(NumberError::Unexpected {
            found: '.',
            position: 3,
        }),
    );
    check(
        "--1",
        Err(NumberError::Unexpected {
            found: '-',
            position: 1,
        }),
    );
    check(&"9".repeat(1001), Err(NumberError::TooLong { max: 1000 }));
}

#[test]
fn format_reads_back() {
    for (p, q, text) in [
        (3, 2, "1.5"),
        (-1, 8, "-0.125"),
        (1, 3, "1/3"),
        (-7, 1, "-7"),
        (1, 20, "0.05"),
        (-3, 1000, "-0.003"),
        (5, 6, "5/6"),
    ] {
        let v = Rational::from((p, q));
        assert_eq!(format_exact(&v), text);
        assert_eq!(parse_exact(text).unwrap(), v);
    }
}

proptest::proptest! {
    #[test]
    fn format_parse_round_trip(p in -10_000_000i64..10_000_000, q in 1i64..100_000) {
        let v = Rational::from((p, q));
        proptest::prop_assert_eq!(parse_exact(&format_exact(&v)).unwrap(), v);
    }
}
