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
    assert!(err(&text.replacen("\"version\":2", "\"version\":1", 1)).contains("version 1"));
    assert!(err(&text[..text.len() / 2]).contains("not JSON"));
}

/// The first class of file `f` whose array `key` is not empty.
fn first_with<'a>(f: &'a mut serde_json::Value, key: &str) -> &'a mut serde_json::Value {
    f["classes"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|c| !c[key].as_array().unwrap().is_empty())
        .unwrap()
}

/// Every kind of edit is refused, saying which digest no longer matches:
/// one vertex moved by one unit, one class offset, one slab label, the
/// name, and a digest itself. (With the digests recomputed, the structural
/// checks refuse the same edits: `file`'s unit tests.)
#[test]
fn edited_files_are_refused() {
    let loc = Localizer::new(&wai_gen::family("corridor-niches", &[2]).unwrap());
    let text = file::to_json(&loc);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let refused = |edit: &dyn Fn(&mut serde_json::Value), needle: &str| {
        let mut bad = v.clone();
        edit(&mut bad);
        let e = file::from_json(bad.to_string().as_bytes())
            .expect_err("an edited file is refused")
            .to_string();
        assert!(e.contains(needle), "{needle}: {e}");
        assert!(e.contains("edited or damaged"), "{e}");
    };
    let bump = |s: &serde_json::Value| {
        let n: i128 = s.as_str().unwrap().parse().unwrap();
        serde_json::json!((n + 1).to_string())
    };
    refused(
        &|f| {
            let x = bump(&f["vertices"][3][0]);
            f["vertices"][3][0] = x;
        },
        "map digest",
    );
    refused(
        &|f| {
            let class = first_with(f, "offsets");
            let last = class["offsets"].as_array().unwrap().len() - 1;
            let x = bump(&class["offsets"][last][0]);
            class["offsets"][last][0] = x;
        },
        "content digest",
    );
    refused(
        &|f| {
            let class = first_with(f, "slabs");
            class["slabs"][0]["labels"][0] = serde_json::json!([0]);
        },
        "content digest",
    );
    refused(
        &|f| f["name"] = serde_json::json!("another"),
        "content digest",
    );
    refused(
        &|f| f["digest"]["content"] = serde_json::json!("sha256:00"),
        "content digest",
    );
}
