//! Every command's `--json` against `docs/json-schema/ps30.json`, the one
//! place the shapes are written down, and against the vocabulary rules every
//! command shares (see `src/present/json.rs`).
//!
//! The schema is standard JSON Schema (draft 2020-12), so any validator can
//! use it; the test checks it with the small validator below, which knows
//! the keywords the schema uses (`type`, `properties`, `required`, `items`,
//! `enum`, `$ref`, and the annotations) — and fails on any other keyword, so
//! that a constraint the validator would skip cannot slip into the schema.

use serde_json::Value;
use std::path::Path;

use crate::common::bin;

/// Keywords the validator checks, and annotations it may ignore.
const CHECKED: [&str; 6] = ["type", "properties", "required", "items", "enum", "$ref"];
const ANNOTATIONS: [&str; 5] = ["description", "title", "$schema", "$id", "$defs"];

fn schema() -> Value {
    let text = std::fs::read_to_string(bin::repo().join("docs/json-schema/ps30.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The schema at a local reference (`#/$defs/…`).
fn resolve<'a>(root: &'a Value, reference: &str) -> &'a Value {
    let path = reference.strip_prefix('#').expect("a local reference");
    root.pointer(path)
        .unwrap_or_else(|| panic!("{reference}: not in the schema"))
}

fn type_matches(t: &str, v: &Value) -> bool {
    match t {
        "object" => v.is_object(),
        "array" => v.is_array(),
        "string" => v.is_string(),
        "integer" => v.is_i64() || v.is_u64(),
        "number" => v.is_number(),
        "boolean" => v.is_boolean(),
        "null" => v.is_null(),
        other => panic!("unknown type {other}"),
    }
}

/// Problems of `v` against `s` (a schema inside `root`), at `at`.
fn validate(root: &Value, s: &Value, v: &Value, at: &str, out: &mut Vec<String>) {
    let s = s.as_object().expect("a schema is an object");
    for k in s.keys() {
        assert!(
            CHECKED.contains(&k.as_str()) || ANNOTATIONS.contains(&k.as_str()),
            "{at}: the schema uses `{k}`, which this validator does not check"
        );
    }
    if let Some(r) = s.get("$ref") {
        validate(root, resolve(root, r.as_str().unwrap()), v, at, out);
    }
    if let Some(t) = s.get("type") {
        let types: Vec<&str> = match t {
            Value::String(one) => vec![one.as_str()],
            Value::Array(many) => many.iter().map(|x| x.as_str().unwrap()).collect(),
            _ => panic!("{at}: type must be a string or a list"),
        };
        if !types.iter().any(|t| type_matches(t, v)) {
            out.push(format!("{at}: {v} is not {}", types.join(" or ")));
            return;
        }
    }
    if let Some(Value::Array(options)) = s.get("enum") {
        if !options.contains(v) {
            out.push(format!("{at}: {v} is not one of {options:?}"));
        }
    }
    if let Value::Object(o) = v {
        for r in s
            .get("required")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            let r = r.as_str().unwrap();
            if !o.contains_key(r) {
                out.push(format!("{at}: `{r}` is missing"));
            }
        }
        if let Some(Value::Object(props)) = s.get("properties") {
            for (k, sub) in props {
                if let Some(x) = o.get(k) {
                    validate(root, sub, x, &format!("{at}.{k}"), out);
                }
            }
        }
    }
    if let (Value::Array(xs), Some(items)) = (v, s.get("items")) {
        for (i, x) in xs.iter().enumerate() {
            validate(root, items, x, &format!("{at}[{i}]"), out);
        }
    }
}

/// The vocabulary rules, over the whole value: no non-finite number spelled
/// as a string, no range spelled as `_min`/`_max` fields beside each other,
/// one name for the cost model's count (`executed`, not `executed_static`
/// or `static_executed`), no limit spelled `max_slots`/`max_executed`.
fn vocabulary(v: &Value, at: &str, out: &mut Vec<String>) {
    match v {
        Value::String(s)
            if ["inf", "-inf", "+inf", "nan", "infinity", "-infinity"]
                .contains(&s.to_lowercase().as_str()) =>
        {
            out.push(format!(
                "{at}: a non-finite number as the string {s:?} (null is the rule)"
            ));
        }
        Value::Object(o) => {
            for (k, x) in o {
                // One finding per pair (`max_error` alone is a maximum, not a range).
                if k.ends_with("_min") {
                    out.push(format!(
                        "{at}.{k}: a range as two fields ({{min, max}} is the rule)"
                    ));
                }
                if k == "executed_static" || k == "static_executed" {
                    out.push(format!(
                        "{at}.{k}: the cost model's count is `executed` (the emulator's `executed_emulated`)"
                    ));
                }
                if k == "max_slots" || k == "max_executed" {
                    out.push(format!("{at}.{k}: limits are {{name, slots, executed}}"));
                }
                vocabulary(x, &format!("{at}.{k}"), out);
            }
        }
        Value::Array(xs) => {
            for (i, x) in xs.iter().enumerate() {
                vocabulary(x, &format!("{at}[{i}]"), out);
            }
        }
        _ => {}
    }
}

/// Runs `ps30 ARGS` in `dir` and checks its JSON against the schema of
/// `command`; returns the JSON.
fn check(command: &str, args: &[&str], dir: &Path, codes: &[i32]) -> Value {
    let o = bin::ps30(args, dir);
    let code = o.status.code().unwrap();
    assert!(
        codes.contains(&code),
        "{args:?}: exit {code}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: Value =
        serde_json::from_slice(&o.stdout).unwrap_or_else(|e| panic!("{args:?}: not JSON ({e})"));
    let root = schema();
    let mut problems = Vec::new();
    validate(
        &root,
        resolve(&root, &format!("#/$defs/commands/{command}")),
        &v,
        command,
        &mut problems,
    );
    vocabulary(&v, command, &mut problems);
    assert!(problems.is_empty(), "{args:?}:\n{}", problems.join("\n"));
    v
}

#[test]
fn every_command_matches_the_schema() {
    let repo = bin::repo();
    let tmp = tempfile::tempdir().unwrap();
    let t = |name: &str| tmp.path().join(name).to_str().unwrap().to_string();

    let v = check("check", &["check", "article:loop", "--json"], repo, &[1]);
    assert_eq!(v["limits"]["slots"], 512);
    assert_eq!(v["slot_table"], "fxc");
    assert_eq!(v["slots"], v["fxc_slots"]["total"]);
    // Every instruction of the article's shaders costs the same in both tables.
    assert_eq!(v["documented_slots"], v["slots"]);
    assert_eq!(v["slot_differences"], serde_json::json!([]));
    // A shader the tables count differently says which instructions differ.
    let two = t("two.psh");
    std::fs::write(
        &two,
        "ps_3_0\ndcl_texcoord0 v0\ndcl_cube s0\ntexldb r0, v0, s0\nlrp r1, v0, r0, c0\nlrp r2, v0, r1, c0\nmov oC0, r2\n",
    )
    .unwrap();
    let v = check(
        "check",
        &["check", &two, "--json", "--slots", "documented"],
        repo,
        &[0],
    );
    assert_eq!(v["slot_table"], "documented");
    assert_eq!(
        v["fxc_slots"],
        serde_json::json!({"total": 4, "texture": 1, "arithmetic": 3})
    );
    assert_eq!(
        (&v["slots"], &v["documented_slots"]),
        (&serde_json::json!(11), &serde_json::json!(11))
    );
    assert_eq!(
        v["slot_differences"],
        serde_json::json!([
            {"instruction": "texldb", "count": 1, "each": 5},
            {"instruction": "lrp", "count": 2, "each": 1}
        ])
    );
    assert_eq!(v["crc32"].as_str().map(str::len), Some(8));
    let out = t("two.fxo");
    let a = check("asm", &["asm", &two, "-o", &out, "--json"], repo, &[0]);
    // ps_1_x (core::ps1): the same shapes from check, asm and disasm.
    let ps1 = t("phases.pso");
    let c = check(
        "check",
        &["check", "asm/ps1x/phases.psh", "--json"],
        repo,
        &[0],
    );
    assert_eq!(c["slots"], 6);
    check(
        "asm",
        &["asm", "asm/ps1x/phases.psh", "-o", &ps1, "--json"],
        repo,
        &[0],
    );
    // disasm's own JSON has no schema entry (its corpus lines do): its fields.
    let o = bin::ps30(&["disasm", &ps1, "--json"], repo);
    let l: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(l["version"], "ps_1_4");
    assert_eq!(l["slots"]["texture"], 4);
    let d = check("decompile", &["decompile", &two, "--json"], repo, &[0]);
    assert!(d["hlsl"].as_str().unwrap().contains("texCUBEbias("), "{d}");
    assert_eq!(a["crc32"], v["crc32"]);
    check(
        "check",
        &["check", "article:unrolled", "--int", "i2=128", "--json"],
        repo,
        &[0],
    );
    // A value the shader never reads is a warning among the diagnostics.
    let v = check(
        "check",
        &["check", "article:loop", "--const", "c9=1,1,1,1", "--json"],
        repo,
        &[1],
    );
    let d = &v["diagnostics"][0];
    assert_eq!(
        (&d["severity"], d["file"].is_null()),
        (&serde_json::json!("warning"), true)
    );
    // Bad input (exit 2) is reported on stderr and prints no JSON at all.
    let bad = t("bad.psh");
    std::fs::write(&bad, "ps_3_0\nadd r1, r1\n").unwrap();
    let o = bin::ps30(&["check", &bad, "--json"], repo);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty() && String::from_utf8_lossy(&o.stderr).contains("bad.psh:2:"));
    check(
        "expand",
        &["expand", "article:unrolled", "--json"],
        repo,
        &[0],
    );
    let run = bin::loop_args("assets/hdr/forest.hdr", &["--json"]);
    check("run", &run, repo, &[0]);
    let vs = "tests/oracle/fixtures/hlsl/vertex/offsets.hlsl.fxo";
    let v = check(
        "run_vertices",
        &[
            "run",
            vs,
            "--vertices",
            "asm/vs/skin.json",
            "--int",
            "i0=2,0,1,0",
            "--json",
        ],
        repo,
        &[0],
    );
    assert_eq!(v["outputs"][1]["semantic"], "texcoord1");
    let v = check(
        "profile_vertices",
        &[
            "profile",
            vs,
            "--vertices",
            "asm/vs/skin.json",
            "--int",
            "i0=2,0,1,0",
            "--json",
        ],
        repo,
        &[0],
    );
    assert_eq!(v["limits"]["slots"], 512);
    let v = check(
        "luminance",
        &["luminance", "assets/hdr/city.exr", "--json"],
        repo,
        &[0],
    );
    assert_eq!(
        v["delta"],
        serde_json::json!(0.0001),
        "δ as the shortest decimal"
    );
    check(
        "tonemap",
        &["tonemap", "assets/hdr/city.exr", "--json"],
        repo,
        &[0],
    );
    check(
        "profile",
        &["profile", "lights:select", "--gbuffer", "16x16", "--json"],
        repo,
        &[0],
    );
    let v = check(
        "profile_list",
        &[
            "profile",
            "--list",
            "tests/profile_list/strip.json",
            "--json",
        ],
        repo,
        &[0],
    );
    assert_eq!(v["vertex_shader"]["runs"], 4);
    check("shaders", &["shaders", "--json"], repo, &[0]);
    check(
        "plan",
        &["plan", "--frame", "1280x1024", "--json"],
        repo,
        &[0],
    );
    check(
        "unroll",
        &["unroll", "--frame", "64x64", "--fit", "--json"],
        repo,
        &[0],
    );
    check(
        "render",
        &[
            "render",
            "drawlists/lights.json",
            "-o",
            &t("render"),
            "--json",
        ],
        repo,
        &[0],
    );
    // A pixel's history (`--pixel`) adds `pixels`.
    check(
        "render",
        &[
            "render",
            "tests/pixel_history/blend.json",
            "--pixel",
            "1,1",
            "--json",
        ],
        repo,
        &[0],
    );
    // The same kind of list with its shaders on a GPU: `executed_emulated`
    // is null there. Without a Vulkan device (outside CI) the run is bad
    // input, and there is no JSON to check.
    let o = bin::ps30(
        &[
            "render",
            "drawlists/pixel-rules.json",
            "--backend",
            "gpu",
            "--json",
        ],
        repo,
    );
    if o.status.code() == Some(0) || std::env::var_os("CI").is_some() {
        let v = check(
            "render",
            &[
                "render",
                "drawlists/pixel-rules.json",
                "--backend",
                "gpu",
                "--json",
            ],
            repo,
            &[0],
        );
        let draws: Vec<&Value> = v["steps"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|s| s["kind"] == "draw")
            .collect();
        assert!(!draws.is_empty());
        for d in draws {
            assert_eq!(d["detail"]["executed_emulated"], Value::Null, "{d}");
        }
    }
    let v = check(
        "study",
        &["study", "log-lights", "--reports", &t("study"), "--json"],
        repo,
        &[0],
    );
    assert_eq!(v["brightness"][0]["brightness"], serde_json::json!(0.1));
    check(
        "verify",
        &["verify", "--reports", &t("reports"), "--json"],
        repo,
        &[0],
    );
}

/// Runs `ps30 ARGS` (corpus mode) in `dir` and checks every JSON line: one
/// `corpus_line` per file, then one `corpus_summary`; returns the lines.
fn check_lines(args: &[&str], dir: &Path, codes: &[i32]) -> Vec<Value> {
    let o = bin::ps30(args, dir);
    let code = o.status.code().unwrap();
    assert!(
        codes.contains(&code),
        "{args:?}: exit {code}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let text = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{args:?}: {l:?} ({e})")))
        .collect();
    let root = schema();
    let mut problems = Vec::new();
    for (i, v) in lines.iter().enumerate() {
        let def = if i + 1 == lines.len() {
            "corpus_summary"
        } else {
            "corpus_line"
        };
        let at = format!("{}[{i}]", args[0]);
        validate(
            &root,
            resolve(&root, &format!("#/$defs/{def}")),
            v,
            &at,
            &mut problems,
        );
        vocabulary(v, &at, &mut problems);
    }
    assert!(problems.is_empty(), "{args:?}:\n{}", problems.join("\n"));
    lines
}

/// Corpus mode's JSON Lines (check, asm, disasm, translate, decompile over a folder
/// holding an accepted, an over-limit and a refused shader) match the schema.
#[test]
fn corpus_mode_json_lines_match_the_schema() {
    let repo = bin::repo();
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("in");
    std::fs::create_dir(&dir).unwrap();
    std::fs::write(dir.join("good.psh"), "ps_3_0\nmov oC0, c0\n").unwrap();
    std::fs::write(dir.join("bad.psh"), "ps_3_0\nadd r0, r1\n").unwrap();
    let over = std::fs::read_to_string(repo.join("asm/article/lum_pass1_loop.psh")).unwrap();
    std::fs::write(dir.join("over.psh"), over).unwrap();
    let p = |name: &str| tmp.path().join(name).to_str().unwrap().to_string();
    let input = p("in");

    // A refused file makes the run's exit code 2 (bad input), whatever the others.
    let lines = check_lines(&["check", &input, "--json"], repo, &[2]);
    let statuses: Vec<&str> = lines[..3]
        .iter()
        .map(|l| l["status"].as_str().unwrap())
        .collect();
    assert_eq!(statuses, ["refused", "accepted", "over"]);
    assert_eq!(lines[0]["code"], "X2000");
    assert_eq!(lines[3]["summary"]["files"], 3);

    let fxo = p("fxo");
    let lines = check_lines(&["asm", &input, "-o", &fxo, "--json"], repo, &[2]);
    assert_eq!(lines[1]["crc32"].as_str().map(str::len), Some(8));
    let lines = check_lines(&["disasm", &fxo, "--json"], repo, &[0]);
    assert_eq!(lines[2]["summary"]["accepted"], 2);
    let wgsl = p("wgsl");
    let lines = check_lines(
        &["translate", &input, "--to", "wgsl", "-o", &wgsl, "--json"],
        repo,
        &[2],
    );
    assert_eq!(lines[1]["target"], "wgsl");
    let hlsl = p("hlsl");
    let lines = check_lines(&["decompile", &input, "-o", &hlsl, "--json"], repo, &[2]);
    assert!(lines[1]["statements"].as_u64().is_some_and(|n| n > 0));
    assert!(std::path::Path::new(&hlsl).join("good.psh.hlsl").is_file());
    // --verify compiles and runs one decompilation: not a corpus's.
    let o = bin::ps30(&["decompile", &input, "--verify"], repo);
    assert_eq!(o.status.code(), Some(2));
}

/// The validator itself finds what it should: a missing field, a wrong
/// type, a value outside an enum, inside arrays and through references.
#[test]
fn the_validator_finds_what_is_wrong() {
    let root = schema();
    let d = resolve(&root, "#/$defs/commands/check");
    let mut p = Vec::new();
    validate(
        &root,
        d,
        &serde_json::json!({"executed": {"min": 1}, "verdict": "fine", "slots": "7"}),
        "c",
        &mut p,
    );
    let all = p.join("\n");
    assert!(all.contains("c: `shader` is missing"), "{all}");
    assert!(all.contains("c.executed: `max` is missing"), "{all}");
    assert!(all.contains("c.verdict: \"fine\" is not one of"), "{all}");
    assert!(all.contains("c.slots: \"7\" is not integer"), "{all}");
    let mut p = Vec::new();
    vocabulary(
        &serde_json::json!({"a": [{"x": "-inf", "executed_min": 1, "executed_max": 2}]}),
        "v",
        &mut p,
    );
    assert_eq!(p.len(), 2, "{p:?}");
}

/// `check --json` of a long shader is written as it is serialised: its
/// per-line costs (one entry per source line, most of the output) are not
/// built as a tree of JSON values first, which cost about 4.7 KB a line
/// (471 MB for 100,000 lines). Making the output and serialising it to a
/// sink may allocate for the few fields beside the lines, not per line: under 16 bytes a line on
/// 20,000 lines (a tree of values takes hundreds a line: five maps and their
/// keys for every entry).
#[test]
fn check_json_serialises_its_lines_without_a_tree_per_line() {
    use crate::common::counting::allocated_by;
    use ps30::core::cost::{analyse, Environment, Profile};
    use ps30::core::load::{self, Options};
    let lines = 20_000u64;
    let text = format!(
        "ps_3_0\ndef c0, 1, 2, 3, 4\nmov r0, c0\n{}mov oC0, r0\n",
        "add r0, r0, c0\n".repeat(lines as usize)
    );
    let options = Options {
        max_expanded: 100_000,
        ..Options::default()
    };
    let loaded = load::load_str("long.psh", &text, &options).unwrap();
    let a = analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &Profile::ps_3_0(),
    )
    .unwrap();
    let (written, bytes) = allocated_by(|| {
        let json = ps30::present::check::check_json(&loaded, &a, &[], None);
        serde_json::to_writer_pretty(std::io::sink(), &json)
    });
    written.unwrap();
    assert!(
        bytes < 16 * lines,
        "{bytes} bytes allocated serialising {lines} lines"
    );
}
