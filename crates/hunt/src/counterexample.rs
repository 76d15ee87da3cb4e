//! The file format of `counterexamples/` (see its README.md): the JSON map
//! format plus `claim`, `kind`, `note` and `meta`, written by `wai
//! search-extremes`, `wai check` and the fuzz targets' replay files.

use rug::Rational;
use serde_json::Value;
use wai_map::Map;

/// The text of a counterexample file for `map`: coordinates as exact
/// strings in the map's units, the fields in a fixed order, `meta`
/// indented, a final newline.
pub fn file_text(
    map: &Map,
    name: &str,
    source: &str,
    claim: &str,
    kind: &str,
    note: &str,
    meta: &Value,
) -> String {
    let field = |v: &str| serde_json::to_string(v).expect("a string is JSON");
    let unit = |c: i128| {
        wai_map::format_exact(&Rational::from((
            rug::Integer::from(c),
            map.scale().clone(),
        )))
    };
    let outer: Vec<String> = map
        .vertices()
        .iter()
        .map(|p| format!("    [\"{}\", \"{}\"]", unit(p.x), unit(p.y)))
        .collect();
    let meta_text = serde_json::to_string_pretty(meta)
        .expect("plain JSON values")
        .replace('\n', "\n  ");
    format!(
        "{{\n  \"name\": {},\n  \"source\": {},\n  \"claim\": {},\n  \"kind\": {},\n  \"note\": {},\n  \"outer\": [\n{}\n  ],\n  \"holes\": [],\n  \"meta\": {meta_text}\n}}\n",
        field(name),
        field(source),
        field(claim),
        field(kind),
        field(note),
        outer.join(",\n"),
    )
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
    }
}
