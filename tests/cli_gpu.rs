//! The GPU commands from the outside: `translate`, `compare`, and
//! `--backend gpu` with and without a Vulkan adapter (exit codes, messages).

use crate::common::bin;
use crate::common::gpu as gpu_device;

use bin::{ps30, repo};
use std::process::Command;

#[test]
fn translate_prints_wgsl_that_parses_back() {
    let out = ps30(
        &[
            "translate",
            "asm/corrected/lum_pass1_unrolled.psh",
            "--to",
            "wgsl",
        ],
        repo(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let wgsl = String::from_utf8(out.stdout).unwrap();
    assert!(wgsl.starts_with("// asm/corrected/lum_pass1_unrolled.psh: Direct3D 9 ps_3_0"));
    let module = naga::front::wgsl::parse_str(&wgsl).unwrap();
    assert_eq!(module.entry_points.len(), 1);
}

#[test]
fn translate_writes_every_target_to_a_file() {
    let dir = tempfile::tempdir().unwrap();
    for (to, file) in [
        ("wgsl", "a.wgsl"),
        ("spirv", "a.spv"),
        ("glsl", "a.frag"),
        ("hlsl", "a.hlsl"),
        ("msl", "a.metal"),
    ] {
        let path = dir.path().join(file);
        let out = ps30(
            &[
                "translate",
                "tonemap:reinhard",
                "--to",
                to,
                "-o",
                path.to_str().unwrap(),
                "-q",
            ],
            repo(),
        );
        assert_eq!(
            out.status.code(),
            Some(0),
            "{to}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(out.stdout.is_empty());
        let bytes = std::fs::read(&path).unwrap();
        if to == "spirv" {
            assert_eq!(&bytes[..4], &[0x03, 0x02, 0x23, 0x07]);
        } else {
            assert!(String::from_utf8(bytes)
                .unwrap()
                .contains("asm/tonemap/reinhard.psh"));
        }
    }
}

#[test]
fn translate_refuses_bad_input_with_exit_2() {
    let out = ps30(&["translate", "no/such.psh", "--to", "wgsl"], repo());
    assert_eq!(out.status.code(), Some(2));
    let out = ps30(
        &[
            "translate",
            "corrected:loop",
            "--to",
            "wgsl",
            "-o",
            "no/dir/x.wgsl",
        ],
        repo(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("does not exist"));
    let out = ps30(&["compare"], repo());
    assert_eq!(out.status.code(), Some(2));
}

/// Without a Vulkan driver (none is found when the loader is pointed at
/// nothing) the GPU commands say how to get one and exit with 2.
#[test]
fn without_an_adapter_the_gpu_commands_say_how_to_get_one() {
    let reports = tempfile::tempdir().unwrap();
    let reports = reports.path().to_str().unwrap();
    for args in [
        &["luminance", "assets/hdr/forest.hdr", "--backend", "gpu"][..],
        &["compare", "--all", "--reports", reports][..],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_ps30"))
            .args(args)
            .current_dir(repo())
            .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
            .env("VK_DRIVER_FILES", "/nonexistent/icd.json")
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains("no GPU adapter") && err.contains("mesa-vulkan-drivers"),
            "{err}"
        );
    }
}

#[test]
fn compare_on_the_luminance_pipeline_names_the_device() {
    if gpu_device::gpu("compare_on_the_luminance_pipeline_names_the_device").is_none() {
        return;
    }
    let out = ps30(
        &[
            "compare",
            "--luminance",
            "--image",
            "assets/hdr/forest.hdr",
            "--json",
        ],
        repo(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["device"]["name"].as_str().is_some_and(|n| !n.is_empty()));
    assert_eq!(v["comparison"]["gpu_agrees"], true);
    assert_eq!(v["comparison"]["emulator_agrees"], true);
    assert_eq!(v["comparison"]["explanation"]["finding"], false);
}

#[test]
fn luminance_on_the_gpu_prints_the_device_and_agrees() {
    if gpu_device::gpu("luminance_on_the_gpu_prints_the_device_and_agrees").is_none() {
        return;
    }
    let out = ps30(
        &["luminance", "assets/hdr/forest.hdr", "--backend", "gpu"],
        repo(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("drawn on the GPU: "), "{text}");
    assert!(text.contains("not counted: drawn on the GPU"), "{text}");
    assert!(text.contains(": agree"), "{text}");
}

#[test]
fn a_gpu_draw_is_held_to_the_per_pixel_cap() {
    if gpu_device::gpu("a_gpu_draw_is_held_to_the_per_pixel_cap").is_none() {
        return;
    }
    // Three nested rep 255: 16,581,375 additions a pixel, past the default
    // cap of 10,000,000 executed slots. The emulator stops the pixel; a GPU
    // cannot, and a driver may cut the loops short (llvmpipe gave 65,025),
    // so the GPU draw is refused up front.
    let dir = tempfile::tempdir().unwrap();
    let shader = dir.path().join("rep3.psh");
    std::fs::write(
        &shader,
        "ps_3_0\ndefi i0, 255, 0, 0, 0\ndef c0, 1, 0, 0, 0\nmov r0, c0.y\nrep i0\nrep i0\nrep i0\nadd r0, r0, c0\nendrep\nendrep\nendrep\nmov oC0, r0\n",
    )
    .unwrap();
    let shader = shader.to_str().unwrap();
    let image = "assets/hdr/forest.hdr";
    let run = |backend: &str| {
        ps30(
            &[
                "run",
                shader,
                "--image",
                image,
                "--target",
                "1x1",
                "--backend",
                backend,
            ],
            repo(),
        )
    };
    for backend in ["emulator", "gpu"] {
        let out = run(backend);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{backend}: {err}");
        assert!(err.contains("--max-executed-per-pixel"), "{backend}: {err}");
    }
}

/// A passing `--backend gpu` run prints no "error:" line on a machine
/// without a login session (no XDG_RUNTIME_DIR): the driver's Wayland probe
/// finds the private runtime directory ps30 sets (`core/gpu/runtime_dir.rs`).
#[test]
fn a_gpu_run_without_a_session_prints_no_error() {
    if gpu_device::gpu("a_gpu_run_without_a_session_prints_no_error").is_none() {
        return;
    }
    let out = Command::new(env!("CARGO_BIN_EXE_ps30"))
        .args([
            "run",
            "corrected:loop",
            "--image",
            "assets/hdr/forest.hdr",
            "--target",
            "8x10",
            "--int",
            "i1=128",
            "--int",
            "i2=52",
            "--const",
            "c0=0,0,0,0",
            "--const",
            "c1=0.0009765625,0.001953125,0,1",
            "--const",
            "c3=0.27,0.67,0.06,0.01",
            "--backend",
            "gpu",
        ])
        .current_dir(repo())
        .env_remove("XDG_RUNTIME_DIR")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}
