//! What `ps30 shaders` prints: the bundled shaders with their names,
//! repository paths and summaries.

use crate::jobs::bundled::{Bundled, ALL};
use serde_json::{json, Value};

/// The table of bundled shaders.
pub fn list_text() -> String {
    let width = ALL.iter().map(|b| b.name.len()).max().unwrap_or(0);
    let mut s = String::from(
        "Bundled shaders: every command that reads a shader takes these names as well as files.\n\n",
    );
    for b in ALL {
        s.push_str(&format!(
            "  {:<width$}  {}\n  {:<width$}  ({})\n",
            b.name, b.summary, "", b.path
        ));
    }
    s.push_str("\n`ps30 shaders NAME` prints one; `ps30 check NAME` counts it.\n");
    s
}

/// The list as JSON: `{"shaders": [{"name", "path", "summary"}]}`.
pub fn list_json() -> Value {
    json!({
        "shaders": ALL.iter().map(|b| json!({
            "name": b.name,
            "path": b.path,
            "summary": b.summary,
        })).collect::<Vec<_>>(),
    })
}

/// One shader as JSON, with its text.
pub fn shader_json(b: &Bundled) -> Value {
    json!({"name": b.name, "path": b.path, "summary": b.summary, "text": b.text})
}
