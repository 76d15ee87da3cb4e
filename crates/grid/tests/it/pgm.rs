//! The image half: P5 and P2, 8 and 16 bits, and what is wrong with a file.

use wai_grid::pgm::{header, pixels, to_pgm, Image};

fn read(bytes: &[u8]) -> Result<Image, String> {
    pixels(bytes, &header(bytes)?)
}

#[test]
fn binary_and_plain_grey_maps() {
    let img = Image {
        width: 3,
        height: 2,
        maxval: 255,
        pixels: vec![0, 205, 254, 254, 254, 0],
    };
    assert_eq!(read(&to_pgm(&img)).unwrap(), img);
    let plain = b"P2\n# a comment\n3 2\n255\n0 205 254\n254 254 0\n";
    assert_eq!(read(plain).unwrap(), img);
    let wide = Image {
        maxval: 1000,
        pixels: vec![0, 500, 1000, 999, 1, 2],
        ..img.clone()
    };
    assert_eq!(read(&to_pgm(&wide)).unwrap(), wide);
    assert_eq!(img.at(2, 0), 254);
}

#[test]
fn bad_images_say_what_is_wrong() {
    let e = |b: &[u8]| read(b).unwrap_err();
    assert!(e(b"GIF89a").contains("no PGM magic number"));
    assert!(e(b"P6\n1 1\n255\n\0\0\0").contains("colour (PPM) image"));
    assert!(e(b"P5\n3\n").contains("no height"));
    assert!(e(b"P5\n0 2\n255\n").contains("an empty image"));
    assert!(e(b"P5\n1 1\n70000\n\0").contains("maxval 70000"));
    assert!(e(b"P5\n3 2\n255\n\0\0\0").contains("3 bytes of pixel data, 6 expected"));
    assert!(
        e(b"P2\n2 1\n100\n5 101\n").contains("pixel 1 (row 0, column 1) is 101, above maxval 100")
    );
    assert!(e(b"P2\n2 1\n100\n5\n").contains("pixel 1 of 2 is missing"));
}
