//! Reading JSON with located errors: each helper takes an object and a
//! key and says, on failure, where (`claims[3].examined`) and what was
//! found instead. Shared by the readers of run records
//! ([`crate::record`]) and of their shard entries ([`crate::shard`]).

use serde_json::{Map as Object, Value};

/// `key` of `o` if present: a non-negative integer.
pub fn optional_uint(
    o: &Object<String, Value>,
    key: &str,
    at: &str,
) -> Result<Option<u64>, String> {
    match o.get(key) {
        None => Ok(None),
        Some(_) => uint(o, key, at).map(Some),
    }
}

pub fn object<'a>(v: &'a Value, what: &str) -> Result<&'a Object<String, Value>, String> {
    v.as_object()
        .ok_or_else(|| format!("{what}: expected a JSON object, found {}", kind_of(v)))
}

pub fn field<'a>(o: &'a Object<String, Value>, key: &str, at: &str) -> Result<&'a Value, String> {
    o.get(key).ok_or_else(|| format!("{at}{key}: missing"))
}

pub fn string(o: &Object<String, Value>, key: &str, at: &str) -> Result<String, String> {
    match field(o, key, at)? {
        Value::String(s) => Ok(s.clone()),
        other => Err(format!("{at}{key}: expected a string, found {other}")),
    }
}

pub fn uint(o: &Object<String, Value>, key: &str, at: &str) -> Result<u64, String> {
    let v = field(o, key, at)?;
    v.as_u64()
        .ok_or_else(|| format!("{at}{key}: expected a non-negative integer, found {v}"))
}

pub fn array<'a>(
    o: &'a Object<String, Value>,
    key: &str,
    at: &str,
) -> Result<&'a Vec<Value>, String> {
    match field(o, key, at)? {
        Value::Array(a) => Ok(a),
        other => Err(format!("{at}{key}: expected an array, found {other}")),
    }
}

pub fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
