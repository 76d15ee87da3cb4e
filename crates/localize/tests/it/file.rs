//! Save and load: the same structure back, and damaged files refused.

use wai_localize::{file, Localizer};

#[test]
fn a_saved_localizer_loads_back_equal() {
    for map in [
        wai_gen::family("corridor-niches", &[3]).unwrap(),
        wai_gen::random("special-orthogonal", 16, 4).unwrap(),
        wai_gen::layout("repeated-niches", 1).unwrap(),
    ] {
        let loc = Localizer::new(&map);
        let text = file::to_json(&loc);
        let back = file::from_json(text.as_bytes()).expect("loads");
        assert_eq!(back, loc);
        assert_eq!(file::to_json(&back), text);
    }
}

#[test]
fn damaged_files_are_refused_with_the_reason() {
    let loc = Localizer::new(&wai_gen::family("corridor-niches", &[2]).unwrap());
    let text = file::to_json(&loc);
    let err = |t: &str| file::from_json(t.as_bytes()).unwrap_err().to_string();
    assert!(err("{}").contains("format"));
    assert!(err(&text.replacen("\"version\":1", "\"version\":2", 1)).contains("version 2"));
    assert!(err(&text[..text.len() / 2]).contains("not JSON"));
    // A label pointing past the items.
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut bad = v.clone();
    let class = bad["classes"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|c| !c["slabs"].as_array().unwrap().is_empty())
        .unwrap();
    class["slabs"][0]["labels"][0] = serde_json::json!([999999]);
    assert!(err(&bad.to_string()).contains("out of range"));
    // A map that is not simple.
    let mut bad = v;
    bad["vertices"][1] = serde_json::json!(["-5", "7"]);
    bad["vertices"][2] = serde_json::json!(["5", "-7"]);
    assert!(
        err(&bad.to_string()).contains("map"),
        "{}",
        err(&bad.to_string())
    );
}
