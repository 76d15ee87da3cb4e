//! Netpbm grey-map images (PGM): binary `P5` and plain `P2`, 8 or 16 bits
//! per pixel, as `map_saver` and most occupancy-grid tools write them.

/// A grey-map image, row 0 at the top.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    /// The value of white.
    pub maxval: u16,
    /// Row after row from the top, `width` values each.
    pub pixels: Vec<u16>,
}

impl Image {
    /// The value of the pixel in column `c` of row `r` (from the top).
    pub fn at(&self, c: usize, r: usize) -> u16 {
        self.pixels[r * self.width + c]
    }
}

/// What the header says, before any pixel is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    pub binary: bool,
    pub width: usize,
    pub height: usize,
    pub maxval: u16,
    /// Where the pixel data starts.
    pub data: usize,
}

/// The header of a PGM file.
pub fn header(bytes: &[u8]) -> Result<Header, String> {
    let binary = match bytes.get(..2) {
        Some(b"P5") => true,
        Some(b"P2") => false,
        Some(b"P6") | Some(b"P3") => {
            return Err("a colour (PPM) image; save the grid as a grey map (PGM)".into())
        }
        _ => return Err("no PGM magic number (P5 or P2) at the start".into()),
    };
    let mut pos = 2;
    let mut fields = [0u64; 3];
    for (k, name) in ["width", "height", "maxval"].iter().enumerate() {
        skip_space_and_comments(bytes, &mut pos);
        fields[k] =
            read_decimal(bytes, &mut pos).ok_or_else(|| format!("no {name} in the header"))?;
    }
    // One whitespace byte separates the header from binary data.
    match bytes.get(pos) {
        Some(c) if c.is_ascii_whitespace() => pos += 1,
        _ => return Err("no whitespace after maxval".into()),
    }
    let [width, height, maxval] = fields;
    if width == 0 || height == 0 {
        return Err(format!("an empty image ({width} × {height})"));
    }
    if !(1..=65535).contains(&maxval) {
        return Err(format!("maxval {maxval} is not in 1..=65535"));
    }
    Ok(Header {
        binary,
        width: usize::try_from(width).map_err(|_| "width too large")?,
        height: usize::try_from(height).map_err(|_| "height too large")?,
        maxval: maxval as u16,
        data: pos,
    })
}

/// The pixels of a PGM file whose [`header`] was read.
pub fn pixels(bytes: &[u8], h: &Header) -> Result<Image, String> {
    let count = h
        .width
        .checked_mul(h.height)
        .ok_or("width × height overflows")?;
    let mut pixels = Vec::with_capacity(count);
    let wide = h.maxval > 255;
    if h.binary {
        let per = if wide { 2 } else { 1 };
        let need = count * per;
        let data = &bytes[h.data..];
        if data.len() < need {
            return Err(format!(
                "{} bytes of pixel data, {need} expected for {} × {} pixels of {per} byte(s)",
                data.len(),
                h.width,
                h.height
            ));
        }
        if wide {
            pixels.extend(
                data[..need]
                    .chunks(2)
                    .map(|b| u16::from_be_bytes([b[0], b[1]])),
            );
        } else {
            pixels.extend(data[..need].iter().map(|&b| u16::from(b)));
        }
    } else {
        let mut pos = h.data;
        for k in 0..count {
            skip_space_and_comments(bytes, &mut pos);
            let v = read_decimal(bytes, &mut pos)
                .ok_or_else(|| format!("pixel {k} of {count} is missing or not a number"))?;
            pixels.push(v.min(u64::from(u16::MAX)) as u16);
        }
    }
    if let Some(k) = pixels.iter().position(|&v| v > h.maxval) {
        return Err(format!(
            "pixel {k} (row {}, column {}) is {}, above maxval {}",
            k / h.width,
            k % h.width,
            pixels[k],
            h.maxval
        ));
    }
    Ok(Image {
        width: h.width,
        height: h.height,
        maxval: h.maxval,
        pixels,
    })
}

/// A PGM image written in binary form (for tests and tools).
pub fn to_pgm(image: &Image) -> Vec<u8> {
    let mut out = format!("P5\n{} {}\n{}\n", image.width, image.height, image.maxval).into_bytes();
    for &v in &image.pixels {
        if image.maxval > 255 {
            out.extend(v.to_be_bytes());
        } else {
            out.push(v as u8);
        }
    }
    out
}

fn skip_space_and_comments(bytes: &[u8], pos: &mut usize) {
    while let Some(&c) = bytes.get(*pos) {
        if c == b'#' {
            while bytes.get(*pos).is_some_and(|&c| c != b'\n') {
                *pos += 1;
            }
        } else if c.is_ascii_whitespace() {
            *pos += 1;
        } else {
            break;
        }
    }
}

fn read_decimal(bytes: &[u8], pos: &mut usize) -> Option<u64> {
    let start = *pos;
    let mut v: u64 = 0;
    while let Some(&c) = bytes.get(*pos) {
        if !c.is_ascii_digit() {
            break;
        }
        v = v.checked_mul(10)?.checked_add(u64::from(c - b'0'))?;
        *pos += 1;
    }
    (*pos > start).then_some(v)
}
