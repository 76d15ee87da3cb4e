//! The file format of `counterexamples/` (see its README.md): the JSON map
//! format plus `claim`, `kind`, `note` and `meta`, written by `wai
//! search-extremes` and `wai check`.

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
