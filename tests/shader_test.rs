//! `ps30 shader-test` on the project's own `.shader_test` files
//! (`tests/shader_test/`, one per kind of section: uniforms, textures and
//! samplers, vertex buffers with an input layout and a vertex shader, the
//! shader model and qualifiers, clears with the alpha test and a second
//! target). Each expected value is derived by hand in a comment beside its
//! probe. They need Microsoft's compiler (`tools/oracle/setup.sh`); without
//! it these tests say so and pass, except under CI (which installs it).

use crate::common::bin::{in_repo, repo, stderr, stdout};
use serde_json::Value;
use std::path::PathBuf;

/// Whether the oracle is installed where `ps30` looks for it; says so when
/// not (and fails where `PS30_REQUIRE_ORACLE` says it must be there).
fn oracle_installed(test: &str) -> bool {
    let dir = std::env::var_os("PS30_ORACLE")
        .map(PathBuf::from)
        .unwrap_or_else(|| repo().join("target/oracle"));
    let ok = ["harness.exe", "d3dcompiler_47.dll", "prefix/system.reg"]
        .iter()
        .all(|f| dir.join(f).is_file());
    if !ok {
        assert!(
            std::env::var_os("PS30_REQUIRE_ORACLE").is_none(),
            "{test}: Microsoft's compiler is not installed in {} (tools/oracle/setup.sh)",
            dir.display()
        );
        eprintln!(
            "{test}: skipped: Microsoft's compiler is not installed in {} (tools/oracle/setup.sh)",
            dir.display()
        );
    }
    ok
}

/// A scratch file under target/ holding `text`.
fn scratch(name: &str, text: &str) -> PathBuf {
    let dir = repo().join("target/shader-test-scratch");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn the_projects_own_files_pass_probe_by_probe() {
    if !oracle_installed("the_projects_own_files_pass_probe_by_probe") {
        return;
    }
    let o = in_repo(&["shader-test", "tests/shader_test", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    // (file, probe lines that run): `if(sm>=4)` and the lines after a
    // shader that fails to compile do not run.
    let want: [(&str, &[u64]); 7] = [
        (
            "fog",
            &[42, 46, 47, 51, 52, 53, 54, 62, 67, 82, 104, 105, 106, 109],
        ),
        ("geometry", &[37, 38, 39, 51, 52]),
        ("models", &[20, 21, 23, 54]),
        (
            "points",
            &[
                39, 40, 41, 42, 43, 44, 49, 50, 51, 59, 60, 61, 62, 90, 91, 92, 93, 94, 95, 101,
                102, 103, 104, 105, 106,
            ],
        ),
        ("state", &[24, 29, 30, 33, 35, 36]),
        ("textures", &[35, 53]),
        ("uniforms", &[22, 26, 31]),
    ];
    let files = v["files"].as_array().unwrap();
    assert_eq!(files.len(), want.len());
    for (f, (name, lines)) in files.iter().zip(want) {
        assert!(f["path"]
            .as_str()
            .unwrap()
            .ends_with(&format!("{name}.shader_test")));
        let probes = f["probes"].as_array().unwrap();
        let got: Vec<u64> = probes.iter().map(|p| p["line"].as_u64().unwrap()).collect();
        assert_eq!(got, lines, "{name}");
        for p in probes {
            assert_eq!(p["verdict"], "pass", "{name}: {p}");
        }
        assert!(f["stopped"].is_null(), "{name}: {}", f["stopped"]);
    }
    assert_eq!(v["passed"], 59);
    assert_eq!(v["failed"], 0);
}

#[test]
fn a_wrong_expectation_fails_with_exit_1_and_the_pixel() {
    if !oracle_installed("a_wrong_expectation_fails_with_exit_1_and_the_pixel") {
        return;
    }
    let path = scratch(
        "wrong.shader_test",
        "[pixel shader]\nfloat4 main() : sv_target\n{\n    return float4(0.5, 0.25, 0.0, 1.0);\n}\n\n[rtv 0]\nsize (2d, 2, 2)\n\n[test]\ndraw quad\nprobe (1, 1) rgba (0.5, 0.25, 0.0, 1.0)\nprobe (0, 0, 2, 2) rgba (0.5, 0.25, 0.0, 0.5)\n",
    );
    let o = in_repo(&["shader-test", path.to_str().unwrap()]);
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{out}{}", stderr(&o));
    assert!(
        out.contains("2 probes: 1 passed, 1 failed, 0 unsupported"),
        "{out}"
    );
    assert!(
        out.contains("13: FAIL: probe (0, 0, 2, 2) rgba (0.5, 0.25, 0.0, 0.5): got (5.00000000e-1, 2.50000000e-1, 0.00000000e0, 1.00000000e0), expected (5.00000000e-1, 2.50000000e-1, 0.00000000e0, 5.00000000e-1) at (0, 0)"),
        "{out}"
    );
}

#[test]
fn what_ps30_cannot_draw_is_named_and_not_failed() {
    if !oracle_installed("what_ps30_cannot_draw_is_named_and_not_failed") {
        return;
    }
    // A fifth render target: Direct3D 9 has four.
    let path = scratch(
        "rtv4.shader_test",
        "[pixel shader]\nfloat4 main() : sv_target\n{\n    return 1.0;\n}\n\n[rtv 0]\nsize (2d, 2, 2)\n\n[test]\ndraw quad\nprobe (0, 0) rgba (1.0, 1.0, 1.0, 1.0)\n\n[rtv 4]\nsize (2d, 2, 2)\n\n[test]\ndraw quad\nprobe (0, 0) rgba (1.0, 1.0, 1.0, 1.0)\n",
    );
    let o = in_repo(&["shader-test", path.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let probes = &v["files"][0]["probes"];
    assert_eq!(probes[0]["verdict"], "pass");
    assert_eq!(probes[1]["verdict"], "unsupported");
    assert_eq!(probes[1]["reason"], "render targets past slot 3");
    assert_eq!(v["unsupported_reasons"][0][0], "render targets past slot 3");
}

#[test]
fn a_malformed_line_is_bad_input_with_its_place() {
    if !oracle_installed("a_malformed_line_is_bad_input_with_its_place") {
        return;
    }
    let path = scratch(
        "malformed.shader_test",
        "[pixel shader]\nfloat4 main() : sv_target\n{\n    return 1.0;\n}\n\n[test]\nfrobnicate the quad\n",
    );
    let o = in_repo(&["shader-test", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("stopped: line 8: unknown test directive 'frobnicate the quad'"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn without_the_compiler_it_says_what_is_missing_and_exits_2() {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args(["shader-test", "tests/shader_test/uniforms.shader_test"])
        .current_dir(repo())
        .env("PS30_ORACLE", repo().join("target/no-such-oracle"))
        .output()
        .unwrap();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("Microsoft's compiler is not installed"),
        "{err}"
    );
    assert!(err.contains("tools/oracle/setup.sh"), "{err}");
}
