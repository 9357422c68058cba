//! `reports/gpu-crosscheck.md`: every bundled shader on the emulator and on
//! one GPU, the device named, every difference with its explanation (the
//! page `ps30 compare --all` writes).

use crate::core::numbers::thousands;
use crate::jobs::compare::explain::{describe_probe, Explanation};
use crate::jobs::compare::stats::{ChannelStats, Worst};
use crate::jobs::compare::CrossCheck;

fn why(e: &Option<Explanation>) -> String {
    match e {
        Some(e) => {
            let word = if e.finding {
                "**FINDING**"
            } else if e.device {
                "**device**"
            } else {
                "explained"
            };
            format!("{word}: {}", e.text.replace('|', "\\|"))
        }
        None => String::new(),
    }
}

fn worst(w: Option<&Worst>) -> String {
    match w {
        Some(w) => format!("({}, {}): {:e} vs {:e}", w.x, w.y, w.emulator, w.gpu),
        None => "—".into(),
    }
}

fn identical(c: &ChannelStats) -> String {
    format!("{} of {}", thousands(c.identical), thousands(c.pixels))
}

/// The page.
pub fn page(x: &CrossCheck) -> String {
    let d = &x.device;
    let mut s = format!("# GPU cross-check: the emulator against {}\n\n", d.name);
    s.push_str(&format!(
        "Written by `ps30 compare --all` (the command prints the device first). Device: **{}** \
         ({} backend, {} device, vendor 0x{:04x}, device 0x{:04x}); driver: **{}** ({}). \
         Float rules: {}.\n\n",
        d.name,
        d.backend,
        d.device_type,
        d.vendor,
        d.device,
        d.driver,
        d.driver_info,
        x.float_rules
    ));
    s.push_str(
        "Every draw runs twice: on ps30's emulator and on the device, through the naga translation of \
         the same shader (`ps30 translate`), with bit-identical inputs (see `src/core/gpu/`). \
         \"Identical\" counts bit-identical values; distances are in units in the last place of f32. \
         A difference is *explained* when both backends stay within the bound the f32 arithmetic \
         allows against the f64 reference (the bounds of `ps30 luminance` and `ps30 tonemap`) and \
         the instruction probes below show which of the shader's instructions the device computes \
         differently; *device* when the difference goes beyond rounding but comes from something \
         this device does that Direct3D 9 hardware need not (flushing subnormals to zero, storing \
         f16 toward zero — both allowed by Vulkan); anything else is marked **FINDING**.\n\n",
    );

    s.push_str("## Instruction probes\n\n");
    s.push_str(
        "One instruction at a time over 4,096 inputs (16 special values, the rest spread over \
         magnitudes and signs), each result also compared with the correctly rounded value.\n\n",
    );
    s.push_str("| instruction | identical | max ulp apart | device from exact | emulator from exact | what it shows |\n|---|---|---|---|---|---|\n");
    for p in &x.probes {
        s.push_str(&format!(
            "| `{}` | {} of {} | {} | {} ulp | {} ulp | {} |\n",
            p.instruction,
            thousands(p.identical),
            thousands(p.inputs),
            thousands(p.max_ulp),
            thousands(p.gpu_max_ulp_exact),
            thousands(p.emulator_max_ulp_exact),
            describe_probe(p).replace('|', "\\|")
        ));
    }

    s.push_str("\n## Luminance pipeline\n\n");
    s.push_str(
        "Pass 1's block sums (its R32F target) compared block by block, and L̄w from both backends \
         against the f64 reference (every pixel once).\n\n",
    );
    s.push_str("| image | pass 1 | pass 2 | block | target | blocks identical | max ulp | worst block (emulator vs GPU) | L̄w GPU | L̄w emulator | L̄w f64 | blocks within bound (GPU, emulator) | why |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for c in &x.luminance {
        let pass1 = match &c.pass1_last {
            Some(l) => format!("`{}` + `{}`", c.pass1, l),
            None => format!("`{}`", c.pass1),
        };
        s.push_str(&format!(
            "| {} | {} | `{}` | {}×{} | {} | {} | {} | {} | {:.7} | {:.7} | {:.7} | {}, {} of {} | {} |\n",
            c.image,
            pass1,
            c.pass2,
            c.block.0,
            c.block.1,
            c.target_format,
            identical(&c.blocks),
            thousands(c.blocks.max_ulp),
            worst(c.blocks.worst.first()),
            c.log_average.gpu,
            c.log_average.emulator,
            c.log_average.reference,
            c.gpu_blocks_within,
            c.emulator_blocks_within,
            c.blocks.pixels,
            why(&c.explanation)
        ));
    }

    s.push_str("\n## Tone mapping\n\n");
    s.push_str(
        "`asm/tonemap/reinhard.psh` over every pixel with the same operator on both backends (the \
         emulator's L̄w), unrounded f32 targets; each backend's pixels also checked against the f64 \
         reference within their derived bound.\n\n",
    );
    s.push_str("| image | channel | identical | max ulp | worst pixel (emulator vs GPU) | pixels within bound (GPU, emulator) | why |\n|---|---|---|---|---|---|---|\n");
    for c in &x.tonemap {
        for (k, ch) in c.draw.channels.iter().enumerate() {
            let (within, reason) = if k == 0 {
                (
                    format!(
                        "{}, {} of {}",
                        thousands(c.gpu_within),
                        thousands(c.emulator_within),
                        thousands(c.pixels)
                    ),
                    why(&c.explanation),
                )
            } else {
                (String::new(), String::new())
            };
            s.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} | {} |\n",
                if k == 0 { c.image.as_str() } else { "" },
                ch.channel,
                identical(ch),
                thousands(ch.max_ulp),
                worst(ch.worst.first()),
                within,
                reason
            ));
        }
    }

    s.push_str("\n## Light models\n\n");
    s.push_str("The light-model shaders on their synthetic 256×256 G-buffer (`ps30 profile lights:select --gbuffer 256x256`), unrounded f32 targets.\n\n");
    s.push_str("| shader | channel | identical | max ulp | worst pixel (emulator vs GPU) | why |\n|---|---|---|---|---|---|\n");
    for c in &x.lights {
        for (k, ch) in c.channels.iter().enumerate() {
            s.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} |\n",
                if k == 0 { c.shader.as_str() } else { "" },
                ch.channel,
                identical(ch),
                thousands(ch.max_ulp),
                worst(ch.worst.first()),
                if k == 0 {
                    why(&c.explanation)
                } else {
                    String::new()
                }
            ));
        }
    }
    s.push_str(
        "\n## Reproduce\n\n```sh\ncargo run --release -- compare --all            # writes reports/gpu-crosscheck.md\n```\n\n\
         It needs a Vulkan device (Mesa's `mesa-vulkan-drivers` gives llvmpipe on the CPU); without \
         one it says so and exits with 2.\n",
    );
    s
}
