//! The file format of `counterexamples/` (see its README.md): the JSON map
//! format plus `claim`, `kind`, `note` and `meta`, written by `wai
//! search-extremes`, `wai check` and the fuzz targets' replay files.

use rug::Rational;
use serde_json::Value;
use wai_map::digest::sha256;
use wai_map::Map;

/// The text of a counterexample file for `map`: coordinates as exact
/// strings in the map's units, the fields in a fixed order, `meta`
/// indented, a final newline, and last a `digest` that seals it: the
/// map's ([`Map::digest`]) and the SHA-256 of the text before it. Reading
/// it back ([`verify`]) refuses a file edited since.
pub fn file_text(
    map: &Map,
    name: &str,
    source: &str,
    claim: &str,
    kind: &str,
    note: &str,
    meta: &Value,
) -> String {
    let fields = Fields {
        name,
        source,
        claim,
        kind,
        note,
        meta,
    };
    let body = body_text(map, &fields);
    format!(
        "{},\n  \"digest\": {{\"map\": \"{}\", \"content\": \"{}\"}}\n}}\n",
        body.trim_end().trim_end_matches('}').trim_end(),
        map.digest(),
        sha256(body.as_bytes())
    )
}

/// The fields of a counterexample file beside its map.
struct Fields<'a> {
    name: &'a str,
    source: &'a str,
    claim: &'a str,
    kind: &'a str,
    note: &'a str,
    meta: &'a Value,
}

/// The file's text without its digest.
fn body_text(map: &Map, f: &Fields<'_>) -> String {
    let field = |v: &str| serde_json::to_string(v).expect("a string is JSON");
    let unit = |c: i128| {
        wai_map::format_exact(&Rational::from((
            rug::Integer::from(c),
            map.scale().clone(),
        )))
    };
    let ring = |r: &[wai_exact::Point], indent: &str| -> String {
        r.iter()
            .map(|p| format!("{indent}[\"{}\", \"{}\"]", unit(p.x), unit(p.y)))
            .collect::<Vec<_>>()
            .join(",\n")
    };
    let outer = ring(map.outer(), "    ");
    let holes = if map.has_holes() {
        let rings: Vec<String> = map
            .holes()
            .map(|h| format!("    [\n{}\n    ]", ring(h, "      ")))
            .collect();
        format!("[\n{}\n  ]", rings.join(",\n"))
    } else {
        "[]".to_owned()
    };
    let meta_text = serde_json::to_string_pretty(f.meta)
        .expect("plain JSON values")
        .replace('\n', "\n  ");
    format!(
        "{{\n  \"name\": {},\n  \"source\": {},\n  \"claim\": {},\n  \"kind\": {},\n  \"note\": {},\n  \"outer\": [\n{outer}\n  ],\n  \"holes\": {holes},\n  \"meta\": {meta_text}\n}}\n",
        field(f.name),
        field(f.source),
        field(f.claim),
        field(f.kind),
        field(f.note),
    )
}

/// Whether a counterexample file read back is as it was written: if it
/// carries a `digest` (every file `wai check`, `wai search-extremes` and
/// the fuzz targets write), its map and its content must still match it.
/// A file without one (a figure drawn by hand) is taken as it is: `Ok(false)`.
pub fn verify(bytes: &[u8]) -> Result<bool, String> {
    let v: Value = serde_json::from_slice(wai_map::json::strip_bom(bytes))
        .map_err(|e| format!("not JSON: {e}"))?;
    let Some(digest) = v.get("digest") else {
        return Ok(false);
    };
    let stored = |key: &str| -> Result<&str, String> {
        digest
            .get(key)
            .and_then(Value::as_str)
            .ok_or_else(|| format!("digest.{key}: expected a string"))
    };
    let map = wai_map::json::from_json(bytes)
        .map_err(|e| format!("{e}"))?
        .map;
    if map.digest() != stored("map")? {
        return Err(format!(
            "digest.map: the map was changed after the file was written (the file says {}, its map has {}); the counterexample no longer describes this map",
            stored("map")?,
            map.digest()
        ));
    }
    let text = |key: &str| -> Result<&str, String> {
        v.get(key)
            .and_then(Value::as_str)
            .ok_or_else(|| format!("{key}: expected a string in a sealed counterexample file"))
    };
    let fields = Fields {
        name: text("name")?,
        source: text("source")?,
        claim: text("claim")?,
        kind: text("kind")?,
        note: text("note")?,
        meta: v.get("meta").unwrap_or(&Value::Null),
    };
    let body = body_text(&map, &fields);
    let content = sha256(body.as_bytes());
    if content != stored("content")? {
        return Err(format!(
            "digest.content: the file was changed after it was written (the file says {}, its content has {content})",
            stored("content")?
        ));
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_reads_back_as_the_map_with_its_fields() {
        let map = wai_gen::family("corridor-niches", &[1]).expect("family");
        let meta = serde_json::json!({ "check": { "planted": null } });
        let text = file_text(
            &map,
            "m",
            "by hand",
            "T4.2",
            "violation",
            "not known yet",
            &meta,
        );
        assert!(text.ends_with("}\n") && !text.ends_with("\n\n"));
        let back = wai_map::json::from_json(text.as_bytes()).expect("a map");
        assert_eq!(back.map.vertices(), map.vertices());
        let v: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(
            (v["claim"].as_str(), v["kind"].as_str()),
            (Some("T4.2"), Some("violation"))
        );
        assert_eq!(v["meta"], meta);
        assert_eq!(verify(text.as_bytes()), Ok(true));
    }

    #[test]
    fn a_map_with_holes_keeps_its_holes_in_the_file() {
        let map = wai_gen::random_with_holes("orthogonal-pillars", 8, 2, 3).expect("holed map");
        assert!(map.has_holes());
        let meta = serde_json::json!({});
        let text = file_text(&map, "m", "by hand", "T4.2", "violation", "", &meta);
        let back = wai_map::json::from_json(text.as_bytes())
            .expect("a map")
            .map;
        assert_eq!(back.hole_count(), map.hole_count());
        assert_eq!(back.vertices(), map.vertices());
        assert_eq!(back.digest(), map.digest());
        assert_eq!(verify(text.as_bytes()), Ok(true));
    }

    #[test]
    fn edited_files_are_refused() {
        let map = wai_gen::family("corridor-niches", &[1]).expect("family");
        let meta = serde_json::json!({ "check": { "seed": 7 } });
        let text = file_text(&map, "m", "wai check", "T4.2", "violation", "", &meta);
        // Layout is free: the same fields reformatted still verify.
        let v: Value = serde_json::from_str(&text).unwrap();
        let compact = serde_json::to_string(&v).unwrap();
        assert_eq!(verify(compact.as_bytes()), Ok(true));
        // A vertex moved (the map is still valid).
        let first = map.vertices()[0];
        let moved = text.replacen(
            &format!("[\"{}\", \"{}\"]", first.x, first.y),
            &format!("[\"{}\", \"{}\"]", first.x, first.y - 1),
            1,
        );
        assert_ne!(moved, text);
        let err = verify(moved.as_bytes()).unwrap_err();
        assert!(err.starts_with("digest.map:"), "{err}");
        // The claim, the kind or the meta changed.
        for (from, to) in [
            ("\"T4.2\"", "\"T4.3\""),
            ("\"violation\"", "\"figure\""),
            ("\"seed\": 7", "\"seed\": 8"),
        ] {
            let edited = text.replacen(from, to, 1);
            assert_ne!(edited, text, "{from}");
            let err = verify(edited.as_bytes()).unwrap_err();
            assert!(err.starts_with("digest.content:"), "{from}: {err}");
        }
        // Without a digest: a hand-made figure, taken as it is.
        let mut bare = v.clone();
        bare.as_object_mut().unwrap().remove("digest");
        assert_eq!(verify(bare.to_string().as_bytes()), Ok(false));
    }
}
