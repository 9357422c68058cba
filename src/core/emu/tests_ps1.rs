//! ps_1_x run through the emulator: each rule of `core/ps1/run.rs`, with
//! the expected value worked out by hand beside every case.

use crate::core::emu::{self, Draw, LinearInput, SamplerState, Texture};
use crate::core::load::{self, Options};
use crate::core::ps1::run::{bump_constants, BumpEnv};

fn options(max: f32) -> Options {
    Options {
        ps1_max_value: max,
        ..Options::default()
    }
}

/// The one pixel of a 1×1 draw `draw` sets up, under range `max`.
fn pixel_with(text: &str, max: f32, setup: impl FnOnce(&mut Draw)) -> emu::DrawOutput {
    let loaded = load::load_str("t.psh", text, &options(max)).expect("loads");
    let compiled = emu::compile(&loaded.shader).expect("compiles");
    let mut d = Draw::new(1, 1);
    setup(&mut d);
    emu::run(&compiled, &d).expect("runs")
}

fn colour(text: &str, setup: impl FnOnce(&mut Draw)) -> [f32; 4] {
    pixel_with(text, 8.0, setup).color[0].as_ref().expect("oC0")[0]
}

fn plain(text: &str) -> [f32; 4] {
    colour(text, |_| {})
}

/// What `body` leaves in r1, seen through the saturated output: the
/// shader ends `mad r0, r1, 1/32, 0.5`, which maps [-16, 16] into [0, 1]
/// exactly for the dyadic values below, and the test maps it back.
fn r1_with(version: &str, body: &str, max: f32, setup: impl FnOnce(&mut Draw)) -> [f32; 4] {
    let text = format!(
        "{version}\ndef c6, 0.5, 0.5, 0.5, 0.5\ndef c7, 0.03125, 0.03125, 0.03125, 0.03125\n\
         {body}mad r0, r1, c7, c6\n"
    );
    let out = pixel_with(&text, max, setup).color[0]
        .as_ref()
        .expect("oC0")[0];
    out.map(|v| (v - 0.5) * 32.0)
}

fn r1(version: &str, body: &str) -> [f32; 4] {
    r1_with(version, body, 8.0, |_| {})
}

/// v0 = (0.25, 0.75, 1, 0.5) at every pixel.
fn with_v0(d: &mut Draw) {
    d.inputs
        .push((0, LinearInput::constant([0.25, 0.75, 1.0, 0.5])));
}

#[test]
fn constants_read_as_minus_one_to_one() {
    // The rule Wine's constant_clamp_ps_test holds Windows to, with numbers
    // of ps30's own: (1.25, -0.5, -1.5, 1) + (-0.5, 1.25, 2, 1) reads (1, -0.5, -1, 1) + (-0.5, 1, 1, 1)
    // = (0.5, 0.5, 0, 2); 2 is inside the range (8).
    let got = r1_with("ps_1_1", "add r1, c0, c1\n", 8.0, |d| {
        d.constants.float = vec![[1.25, -0.5, -1.5, 1.0], [-0.5, 1.25, 2.0, 1.0]];
    });
    assert_eq!(got, [0.5, 0.5, 0.0, 2.0]);
    // `def` values too (the register holds [-1, 1], however it was set).
    let body = "def c0, 1.25, -0.5, -1.5, 1\ndef c1, -0.5, 1.25, 2, 1\nadd r1, c0, c1\n";
    assert_eq!(r1("ps_1_4", body), [0.5, 0.5, 0.0, 2.0]);
}

#[test]
fn the_colour_is_r0_saturated() {
    // The same sum written to r0: (0.5, 0.5, 0, 2) leaves the shader as
    // (0.5, 0.5, 0, 1); vkd3d's ps1-sampler probes (recorded on Windows)
    // read 0 where r0 holds -0.3.
    let text = "ps_1_1\ndef c0, 1.25, -0.5, -1.5, 1\ndef c1, -0.5, 1.25, 2, 1\nadd r0, c0, c1\n";
    assert_eq!(plain(text), [0.5, 0.5, 0.0, 1.0]);
    let text = "ps_1_1\ndef c0, -0.25, 0, 0, 0\nmov r0, c0\n";
    assert_eq!(plain(text), [0.0; 4]);
}

#[test]
fn source_modifiers() {
    // v0 = (0.25, 0.75, 1, 0.5).
    let run = |src: &str| r1_with("ps_1_1", &format!("mov r1, {src}\n"), 8.0, with_v0);
    // x - 0.5
    assert_eq!(run("v0_bias"), [-0.25, 0.25, 0.5, 0.0]);
    assert_eq!(run("-v0_bias"), [0.25, -0.25, -0.5, 0.0]);
    // 2x - 1
    assert_eq!(run("v0_bx2"), [-0.5, 0.5, 1.0, 0.0]);
    assert_eq!(run("-v0_bx2"), [0.5, -0.5, -1.0, 0.0]);
    // 1 - x
    assert_eq!(run("1-v0"), [0.75, 0.25, 0.0, 0.5]);
    assert_eq!(run("-v0"), [-0.25, -0.75, -1.0, -0.5]);
    // The selector comes first: v0.a = 0.5 everywhere, then 2x - 1 = 0.
    assert_eq!(run("v0_bx2.a"), [0.0; 4]);
}

#[test]
fn ps_1_4_x2_source_and_coordinates() {
    // t0 = (0.25, -0.5, 2, 4); texcrd copies x, y, z (it writes .rgb, its
    // fourth channel is undefined), `_x2` doubles: (0.5, -1, 4); alpha
    // from c0 (0).
    let t0 = |d: &mut Draw| {
        d.inputs
            .push((2, LinearInput::constant([0.25, -0.5, 2.0, 4.0])));
    };
    let body = "texcrd r2.rgb, t0\nmov r1.rgb, r2_x2\n+mov r1.a, c0\n";
    assert_eq!(r1_with("ps_1_4", body, 8.0, t0), [0.5, -1.0, 4.0, 0.0]);
    // `_dw` divides x and y by w (4): (0.0625, -0.125); texcrd with `_dw`
    // writes .rg.
    let body = "texcrd r1.rg, t0_dw\nmov r1.ba, c0\n";
    assert_eq!(r1_with("ps_1_4", body, 8.0, t0), [0.0625, -0.125, 0.0, 0.0]);
    // texcrd does not clamp to [0, 1] (texcoord does) but to the register
    // range: 12 reads 8.
    let body = "texcrd r1.rgb, t0\nmov r1.a, c0\n";
    let got = r1_with("ps_1_4", body, 8.0, |d| {
        d.inputs
            .push((2, LinearInput::constant([12.0, -12.0, 1.5, 0.0])));
    });
    assert_eq!(got, [8.0, -8.0, 1.5, 0.0]);
}

#[test]
fn shifts_saturation_and_the_register_range() {
    // c0 = (1, 0.5, -1, 0.25).
    let def = "def c0, 1, 0.5, -1, 0.25\n";
    let run = |line: &str, max: f32| r1_with("ps_1_4", &format!("{def}{line}\n"), max, |_| {});
    // ×8: (8, 4, -8, 2), inside ±8.
    assert_eq!(run("mov_x8 r1, c0", 8.0), [8.0, 4.0, -8.0, 2.0]);
    // (c0 + c0) × 8 = (16, 8, -16, 4): clamped to ±8 ...
    assert_eq!(run("add_x8 r1, c0, c0", 8.0), [8.0, 8.0, -8.0, 4.0]);
    // ... or not, under PixelShader1xMaxValue 16.
    assert_eq!(run("add_x8 r1, c0, c0", 16.0), [16.0, 8.0, -16.0, 4.0]);
    // ÷8: (0.125, 0.0625, -0.125, 0.03125).
    assert_eq!(run("mov_d8 r1, c0", 8.0), [0.125, 0.0625, -0.125, 0.03125]);
    // The shift before _sat: (2, 1, -2, 0.5) saturates to (1, 1, 0, 0.5);
    // saturating first would give (2, 1, 0, 0.5).
    assert_eq!(run("mov_x2_sat r1, c0", 8.0), [1.0, 1.0, 0.0, 0.5]);
    // Under the least range, 1: (c0 + c0) = (2, 1, -2, 0.5) → (1, 1, -1, 0.5).
    assert_eq!(run("add r1, c0, c0", 1.0), [1.0, 1.0, -1.0, 0.5]);
    // ps_1_1's _x4 and _d2: c0 × 4 = (4, 2, -4, 1); ÷2 = (2, 1, -2, 0.5).
    let body = format!("{def}mov_x4 r1, c0\nmov_d2 r1, r1\n");
    assert_eq!(r1("ps_1_1", &body), [2.0, 1.0, -2.0, 0.5]);
}

#[test]
fn cnd_cmp_lrp_dot_products() {
    let consts = "def c1, 1, 0.25, 0.5, 0.75\ndef c2, -1, 0, 0.125, 0.375\n";
    // cnd: r0.a > 0.5 ? c1 : c2. r0.a = 0.5 is not above 0.5: c2.
    let body = format!("def c0, 0, 0, 0, 0.5\n{consts}mov r0, c0\ncnd r1, r0.a, c1, c2\n");
    assert_eq!(r1("ps_1_1", &body), [-1.0, 0.0, 0.125, 0.375]);
    // r0.a = 0.5078125 (0.5 + 1/128) is: c1.
    let body = format!("def c0, 0, 0, 0, 0.5078125\n{consts}mov r0, c0\ncnd r1, r0.a, c1, c2\n");
    assert_eq!(r1("ps_1_1", &body), [1.0, 0.25, 0.5, 0.75]);
    // ps_1_4's cnd per component of any source: c0 = (0.75, 0.5, 0, 1):
    // x above → c1.x, y not → c2.y, z not → c2.z, w above → c1.w.
    let body = format!("def c0, 0.75, 0.5, 0, 1\n{consts}cnd r1, c0, c1, c2\n");
    assert_eq!(r1("ps_1_4", &body), [1.0, 0.0, 0.125, 0.75]);
    // cmp: c0 >= 0 ? c1 : c2 with c0 = (0, -0.25, 0.5, -1): (c1.x, c2.y,
    // c1.z, c2.w).
    let body = format!("def c0, 0, -0.25, 0.5, -1\n{consts}cmp r1, c0, c1, c2\n");
    assert_eq!(r1("ps_1_2", &body), [1.0, 0.0, 0.5, 0.375]);
    // lrp: c0·c1 + (1 − c0)·c2 with c0 = 0.25 everywhere:
    // x 0.25 − 0.75 = −0.5; y 0.0625 + 0 = 0.0625; z 0.125 + 0.09375 =
    // 0.21875; w 0.1875 + 0.28125 = 0.46875.
    let body = format!("def c0, 0.25, 0.25, 0.25, 0.25\n{consts}lrp r1, c0, c1, c2\n");
    assert_eq!(r1("ps_1_1", &body), [-0.5, 0.0625, 0.21875, 0.46875]);
    // dp3: 1·−1 + 0.25·0 + 0.5·0.125 = −0.9375, replicated; dp4 adds
    // 0.75·0.375 = 0.28125: −0.65625.
    assert_eq!(
        r1("ps_1_1", &format!("{consts}dp3 r1, c1, c2\n")),
        [-0.9375; 4]
    );
    assert_eq!(
        r1("ps_1_2", &format!("{consts}dp4 r1, c1, c2\n")),
        [-0.65625; 4]
    );
    // mad, sub: c1·c2 + c1 = (0, 0.25, 0.5625, 1.03125); c1 − c2 =
    // (2, 0.25, 0.375, 0.375).
    let got = r1("ps_1_1", &format!("{consts}mad r1, c1, c2, c1\n"));
    assert_eq!(got, [0.0, 0.25, 0.5625, 1.03125]);
    let got = r1("ps_1_1", &format!("{consts}sub r1, c1, c2\n"));
    assert_eq!(got, [2.0, 0.25, 0.375, 0.375]);
}

#[test]
fn a_co_issued_pair_reads_before_it_writes() {
    // r0 = (0.25, 0.5, 0.75, 1); the pair halves r0.rgb and copies r0.b
    // into r0.a. Read before the pair writes, r0.b is 0.75 (written one
    // after the other, it would be 0.375).
    let text = "ps_1_1\ndef c0, 0.25, 0.5, 0.75, 1\ndef c1, 0.5, 0.5, 0.5, 0.5\n\
                mov r0, c0\nmul r0.rgb, r0, c1\n+mov r0.a, r0.b\n";
    assert_eq!(plain(text), [0.125, 0.25, 0.375, 0.75]);
    // The pair costs one slot: three instructions, two slots executed.
    let out = pixel_with(text, 8.0, |_| {});
    assert_eq!(out.executed[0], 2);
}

/// A 2×1 texture: left texel (0.25, 0.5, 0.75, 1), right (1, 0, 0.5, 0).
const TEXELS: [[f32; 4]; 2] = [[0.25, 0.5, 0.75, 1.0], [1.0, 0.0, 0.5, 0.0]];

fn bind(d: &mut Draw, stage: u32) {
    d.samplers.push((
        stage,
        Texture {
            width: 2,
            height: 1,
            texels: &TEXELS,
        }
        .into(),
        SamplerState::default(),
    ));
}

#[test]
fn tex_texcoord_and_texkill() {
    // tex t1 samples stage 1 at coordinate 1: u = 0.75 is the right texel
    // (point filtering); texcoord t0 is t0 clamped to [0, 1] with alpha 1:
    // (1, 0, 0.5, 1) from (1.5, -0.25, 0.5, 7).
    let got = r1_with(
        "ps_1_1",
        "texcoord t0\ntex t1\nadd r1, t0, t1\n",
        8.0,
        |d| {
            d.inputs
                .push((2, LinearInput::constant([1.5, -0.25, 0.5, 7.0])));
            d.inputs
                .push((3, LinearInput::constant([0.75, 0.5, 0.0, 1.0])));
            bind(d, 1);
        },
    );
    // (1, 0, 0.5, 1) + (1, 0, 0.5, 0)
    assert_eq!(got, [2.0, 0.0, 1.0, 1.0]);
    // texkill looks at x, y, z of the coordinate, not w.
    let kill = |t0: [f32; 4]| {
        let text = "ps_1_1\ntexkill t0\nmov r0, v0\n";
        pixel_with(text, 8.0, |d| {
            d.inputs.push((2, LinearInput::constant(t0)));
            with_v0(d);
        })
        .killed[0]
    };
    assert!(kill([0.0, 0.0, -0.5, 1.0]));
    assert!(!kill([0.0, 0.0, 0.0, -1.0]));
}

#[test]
fn ps_1_4_texld_phases_and_texdepth() {
    // `_dz` (on an r#, after the phase marker) divides x and y by z:
    // (0.5, 0.25, 2) samples at (0.25, 0.125), the left texel; without it
    // u = 0.5 would be the right one.
    let text = "ps_1_4\ntexcrd r1.rgb, t0\nphase\ntexld r0, r1_dz\n";
    let got = colour(text, |d| {
        d.inputs
            .push((2, LinearInput::constant([0.5, 0.25, 2.0, 1.0])));
        bind(d, 0);
    });
    assert_eq!(got, TEXELS[0]);
    // Phase 1: texcrd r1 = t0 = (0.25, 0.5, 0, 1); phase 2: texld r2, r1
    // samples stage 2 at (0.25, 0.5): the left texel (0.25, 0.5, 0.75, 1);
    // texld r0, t1 samples stage 0 at t1 = (0.75, 0.5): the right texel.
    let body = "texcrd r1.rgb, t0\nphase\ntexld r2, r1\ntexld r0, t1\nadd r1, r0, r2\n";
    let got = r1_with("ps_1_4", body, 8.0, |d| {
        d.inputs
            .push((2, LinearInput::constant([0.25, 0.5, 0.0, 1.0])));
        d.inputs
            .push((3, LinearInput::constant([0.75, 0.5, 0.0, 1.0])));
        bind(d, 0);
        bind(d, 2);
    });
    assert_eq!(got, [1.25, 0.5, 1.25, 1.0]);
    // texdepth: r5.r / r5.g = 0.25 / 0.5 = 0.5; r5.g = 0 gives 1; a ratio
    // above 1 is clamped to 1, below 0 to 0.
    let depth = |r: f32, g: f32| {
        let text =
            format!("ps_1_4\ndef c0, {r}, {g}, 0, 0\nmov r5, c0\nphase\ntexdepth r5\nmov r0, c0\n");
        pixel_with(&text, 8.0, |_| {}).depth.expect("depth")[0]
    };
    assert_eq!(depth(0.25, 0.5), 0.5);
    assert_eq!(depth(0.25, 0.0), 1.0);
    assert_eq!(depth(1.0, 0.5), 1.0);
    assert_eq!(depth(-0.25, 0.5), 0.0);
}

/// Stage 0: one texel S = (0.375, 0.75, 0.5, 0.25) read at t0; stage
/// `stage` (if the shader samples one more): the 2×1 texture; coordinates
/// 1–3 as given.
fn address(version: &str, body: &str, stage: Option<u32>, coordinates: &[[f32; 4]]) -> [f32; 4] {
    address_with(version, body, stage, coordinates, |_| {})
}

/// [`address`] with more set up by `more`.
fn address_with(
    version: &str,
    body: &str,
    stage: Option<u32>,
    coordinates: &[[f32; 4]],
    more: impl FnOnce(&mut Draw),
) -> [f32; 4] {
    const S: [[f32; 4]; 1] = [[0.375, 0.75, 0.5, 0.25]];
    r1_with(version, body, 8.0, |d| {
        d.inputs
            .push((2, LinearInput::constant([0.5, 0.5, 0.0, 1.0])));
        for (i, c) in coordinates.iter().enumerate() {
            d.inputs.push((3 + i as u32, LinearInput::constant(*c)));
        }
        d.samplers.push((
            0,
            Texture {
                width: 1,
                height: 1,
                texels: &S,
            }
            .into(),
            SamplerState::default(),
        ));
        if let Some(stage) = stage {
            bind(d, stage);
        }
        more(d);
    })
}

#[test]
fn texreg2_samples_at_the_registers_components() {
    // (a, r) = (0.25, 0.375): u = 0.25 is the left texel of the 2×1
    // texture; (g, b) = (0.75, 0.5): the right one; (r, g, b): u = 0.375,
    // the left.
    let left = TEXELS[0];
    let right = TEXELS[1];
    let run = |op: &str, version: &str| {
        address(
            version,
            &format!("tex t0\n{op} t1, t0\nmov r1, t1\n"),
            Some(1),
            &[],
        )
    };
    assert_eq!(run("texreg2ar", "ps_1_1"), left);
    assert_eq!(run("texreg2gb", "ps_1_1"), right);
    assert_eq!(run("texreg2rgb", "ps_1_2"), left);
}

#[test]
fn texm_and_texdp3_take_dot_products_with_the_coordinates() {
    let (left, right) = (TEXELS[0], TEXELS[1]);
    let (x, y, z) = (
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    );
    // texm3x2: u = t1·S.rgb, v = t2·S.rgb. t1 = x: u = 0.375, the left
    // texel; t1 = y: u = 0.75, the right one (v = 0.5 in both).
    let body = "tex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmov r1, t2\n";
    assert_eq!(address("ps_1_1", body, Some(2), &[x, z]), left);
    assert_eq!(address("ps_1_1", body, Some(2), &[y, z]), right);
    // texm3x3: the rows are (x·S, y·S, z·S) = (0.375, 0.75, 0.5), alpha 1;
    // texm3x3tex samples at u = 0.375.
    let body = "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\nmov r1, t3\n";
    assert_eq!(
        address("ps_1_2", body, None, &[x, y, z]),
        [0.375, 0.75, 0.5, 1.0]
    );
    let body = "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\nmov r1, t3\n";
    assert_eq!(address("ps_1_1", body, Some(3), &[x, y, z]), left);
    // texdp3: t1 = (1, 2, 0.5): 0.375 + 1.5 + 0.25 = 2.125 everywhere;
    // texdp3tex samples at (t1·S, 0): t1 = y gives u = 0.75, the right texel.
    let body = "tex t0\ntexdp3 t1, t0\nmov r1, t1\n";
    assert_eq!(
        address("ps_1_2", body, None, &[[1.0, 2.0, 0.5, 0.0]]),
        [2.125; 4]
    );
    let body = "tex t0\ntexdp3tex t1, t0\nmov r1, t1\n";
    assert_eq!(address("ps_1_2", body, Some(1), &[y]), right);
}

#[test]
fn executed_slots_are_the_programs() {
    // Four instructions with modifiers, a shift and a co-issued pair: 1
    // (tex) + 1 (mul) + 1 (the pair) = 3 slots executed, as `check` counts.
    let text = "ps_1_1\ntex t0\nmul_x2 r0, t0_bx2, v0\nadd r0.rgb, r0, 1-v0\n+mov r0.a, v0_bias\n";
    let out = pixel_with(text, 8.0, |d| {
        with_v0(d);
        d.inputs.push((2, LinearInput::constant([0.0; 4])));
        bind(d, 0);
    });
    assert_eq!(out.executed[0], 3);
}

#[test]
fn per_line_counts_find_every_instruction() {
    // Six lines of a 1×1 draw: each runs once; texcrd and the pair's first
    // half execute one slot, the nops, the phase and the pair's second
    // half none.
    let text = "ps_1_4\ntexcrd r1.rgb, t0\nnop\nphase\nnop\nmov r0.rgb, r1\n+mov r0.a, c0\n";
    let loaded = load::load_str("t.psh", text, &Options::default()).expect("loads");
    let compiled = emu::compile(&loaded.shader).expect("compiles");
    let mut d = Draw::new(1, 1);
    d.count_instructions = true;
    d.inputs.push((2, LinearInput::constant([0.5; 4])));
    let out = emu::run(&compiled, &d).expect("runs");
    let lines = emu::lines::pixel_lines(&loaded.shader, &loaded.file, &out.instructions);
    let runs: Vec<(usize, u64, u64)> = lines.iter().map(|l| (l.line, l.runs, l.executed)).collect();
    assert_eq!(
        runs,
        [
            (2, 1, 1),
            (3, 1, 0),
            (4, 1, 0),
            (5, 1, 0),
            (6, 1, 1),
            (7, 1, 0)
        ]
    );
}

/// Stage `stage`'s bump-environment state as a draw sets it.
fn set_bump(d: &mut Draw, stage: u32, env: BumpEnv) {
    for (register, value) in bump_constants(stage, &env).expect("a ps_1_x stage") {
        let i = register as usize;
        if d.constants.float.len() <= i {
            d.constants.float.resize(i + 1, [0.0; 4]);
        }
        d.constants.float[i] = value;
    }
}

fn matrix(m: [f32; 4]) -> BumpEnv {
    BumpEnv {
        matrix: m,
        ..BumpEnv::default()
    }
}

#[test]
fn texbem_moves_the_coordinate_by_the_destination_stages_matrix() {
    // texbem's page: u' = u + M00·t0.r + M10·t0.g, v' = v + M01·t0.r +
    // M11·t0.g, M of stage 1 (the destination's). t0 = S = (0.375, 0.75,
    // 0.5, 0.25); coordinate 1 = (0.125, 0.5). The 2×1 texture is BORDER
    // addressed (border 0): u in [0, 0.5) is the left texel, [0.5, 1) the
    // right, v outside [0, 1) the border.
    let (left, right, border) = (TEXELS[0], TEXELS[1], [0.0; 4]);
    let body = "tex t0\ntexbem t1, t0\nmov r1, t1\n";
    let run = |stage: u32, m: [f32; 4]| {
        address_with("ps_1_1", body, Some(1), &[[0.125, 0.5, 0.0, 1.0]], |d| {
            set_bump(d, stage, matrix(m))
        })
    };
    // Direct3D 9's default matrix is 0: u' = 0.125, the left texel.
    assert_eq!(run(1, [0.0; 4]), left);
    // M00 = 2: u' = 0.125 + 2·0.375 = 0.875, the right texel.
    assert_eq!(run(1, [2.0, 0.0, 0.0, 0.0]), right);
    // M10 = 1: u' = 0.125 + 0.75 (green) = 0.875.
    assert_eq!(run(1, [0.0, 0.0, 1.0, 0.0]), right);
    // M01 = 2: v' = 0.5 + 0.75 = 1.25, past the edge: the border; u' stays.
    assert_eq!(run(1, [0.0, 2.0, 0.0, 0.0]), border);
    // M11 = 1: v' = 0.5 + 0.75 = 1.25.
    assert_eq!(run(1, [0.0, 0.0, 0.0, 1.0]), border);
    // M00 = -1: u' = 0.125 - 0.375 = -0.25, the border (the sign is kept).
    assert_eq!(run(1, [-1.0, 0.0, 0.0, 0.0]), border);
    // Stage 0's matrix (the source's) is not read: u' = 0.125.
    assert_eq!(run(0, [2.0, 0.0, 0.0, 0.0]), left);
    // ps_1_2 and ps_1_3 run it the same way.
    let got = address_with("ps_1_3", body, Some(1), &[[0.125, 0.5, 0.0, 1.0]], |d| {
        set_bump(d, 1, matrix([2.0, 0.0, 0.0, 0.0]))
    });
    assert_eq!(got, right);
}

#[test]
fn texbeml_scales_rgb_by_the_luminance() {
    // texbeml's page: after the texbem sample, rgb ·= t0.b · LSCALE +
    // LOFFSET (stage 1's), alpha as sampled, nothing saturated. Matrix 0:
    // the left texel (0.25, 0.5, 0.75, 1); t0.b = S.b = 0.5.
    let body = "tex t0\ntexbeml t1, t0\nmov r1, t1\n";
    let run = |lscale: f32, loffset: f32| {
        address_with("ps_1_1", body, Some(1), &[[0.125, 0.5, 0.0, 1.0]], |d| {
            let env = BumpEnv {
                lscale,
                loffset,
                ..BumpEnv::default()
            };
            set_bump(d, 1, env)
        })
    };
    // 0.5·2 + 0.25 = 1.25: (0.3125, 0.625, 0.9375, 1).
    assert_eq!(run(2.0, 0.25), [0.3125, 0.625, 0.9375, 1.0]);
    // 0.5·(-4) + 0 = -2: (-0.5, -1, -1.5, 1), not clamped to [0, 1].
    assert_eq!(run(-4.0, 0.0), [-0.5, -1.0, -1.5, 1.0]);
    // Direct3D 9's defaults (0, 0) give factor 0: black, alpha 1.
    assert_eq!(run(0.0, 0.0), [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn bem_reads_the_destination_registers_stage() {
    // bem's page (n the destination's number): r = src0.r + M00·src1.r +
    // M10·src1.g, g = src0.g + M01·src1.r + M11·src1.g. src0 = c0 =
    // (0.25, 0.5), src1 = r0 = t0 = (0.5, -0.25); stage 1's M = (1, 2,
    // -4, 0.5): r = 0.25 + 0.5 + 1 = 1.75, g = 0.5 + 1 - 0.125 = 1.375.
    let body = "def c0, 0.25, 0.5, 0, 0\ntexcrd r0.rgb, t0\nbem r1.rg, c0, r0\nmov r1.ba, c0.b\n";
    let run = |stage: u32| {
        r1_with("ps_1_4", body, 8.0, |d| {
            d.inputs
                .push((2, LinearInput::constant([0.5, -0.25, 0.0, 1.0])));
            set_bump(d, stage, matrix([1.0, 2.0, -4.0, 0.5]));
        })
    };
    assert_eq!(run(1), [1.75, 1.375, 0.0, 0.0]);
    // The matrix on stage 0 (src1's number) or 2: stage 1 keeps its
    // default 0, r1.rg = c0.rg.
    assert_eq!(run(0), [0.25, 0.5, 0.0, 0.0]);
    assert_eq!(run(2), [0.25, 0.5, 0.0, 0.0]);
}

#[test]
fn texm3x2depth_writes_z_over_w() {
    // texm3x2depth's page: z = t1·t0.rgb (the pad), w = t2·t0.rgb, depth
    // z / w, 1 where w = 0; ps30 saturates it as it does texdepth's (the
    // page: outside [0, 1] the stored depth is undefined). t0 = S =
    // (0.375, 0.75, 0.5).
    let depth = |t1: [f32; 4], t2: [f32; 4]| {
        let text = "ps_1_3\ndef c0, 0, 0, 0, 0\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmov r0, c0\n";
        pixel_with(text, 8.0, |d| {
            const S: [[f32; 4]; 1] = [[0.375, 0.75, 0.5, 0.25]];
            let t = Texture {
                width: 1,
                height: 1,
                texels: &S,
            };
            d.samplers.push((0, t.into(), SamplerState::default()));
            d.inputs.push((2, LinearInput::constant([0.5; 4])));
            d.inputs.push((3, LinearInput::constant(t1)));
            d.inputs.push((4, LinearInput::constant(t2)));
        })
        .depth
        .expect("depth")[0]
    };
    let (x, z) = ([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]);
    // z = 0.375, w = 0.5: 0.75.
    assert_eq!(depth(x, z), 0.75);
    // w = 0: 1.
    assert_eq!(depth(x, [0.0; 4]), 1.0);
    // z = 0.5, w = 0.375: 1.33…, saturated to 1; z = -0.375: 0.
    assert_eq!(depth(z, x), 1.0);
    assert_eq!(depth([-1.0, 0.0, 0.0, 0.0], z), 0.0);
}

/// Four texels across: u in [i/4, (i + 1)/4) reads (i/4, 1 - i/4, 0.5, 1).
const QUARTERS: [[f32; 4]; 4] = [
    [0.0, 1.0, 0.5, 1.0],
    [0.25, 0.75, 0.5, 1.0],
    [0.5, 0.5, 0.5, 1.0],
    [0.75, 0.25, 0.5, 1.0],
];

#[test]
fn texm3x3spec_and_vspec_reflect_the_eye_ray() {
    // The pages: N = the rows (t1·S, t2·S, t3·S), R = 2·[(N·E)/(N·N)]·N − E,
    // stage 3 sampled at R. S = t0 = (0.375, 0.75, 0.5); a coordinate
    // (0, 0, 2) gives the row 2·0.5 = 1, (0, 0, 4) gives 2.
    // N = (1, 1, 0), E = (0.125, 0.875, 0): N·E = 1, N·N = 2, R = (1, 1, 0)
    // − E = (0.875, 0.125, 0): the fourth texel. Forgetting the 2 gives
    // u = 0.375, the sign of E 1.125, the border.
    // N = (2, 2, 0): N·E = 2, N·N = 8, 2·2/8 = 0.5, R = (1, 1, 0) − E:
    // the same texel (without the division by N·N it would be the border).
    let sample = |body: &str, rows: f32, w: [f32; 3]| {
        let coordinates = [
            [0.0, 0.0, 2.0 * rows, w[0]],
            [0.0, 0.0, 2.0 * rows, w[1]],
            [0.0, 0.0, 0.0, w[2]],
        ];
        address_with("ps_1_1", body, None, &coordinates, |d| {
            let t = Texture {
                width: 4,
                height: 1,
                texels: &QUARTERS,
            };
            d.samplers.push((3, t.into(), SamplerState::default()));
        })
    };
    let spec = "def c0, 0.125, 0.875, 0, 0\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\n\
                texm3x3spec t3, t0, c0\nmov r1, t3\n";
    assert_eq!(sample(spec, 1.0, [0.0; 3]), QUARTERS[3]);
    assert_eq!(sample(spec, 2.0, [0.0; 3]), QUARTERS[3]);
    // vspec: E = the w of coordinates 1, 2, 3.
    let vspec = "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\nmov r1, t3\n";
    assert_eq!(sample(vspec, 1.0, [0.125, 0.875, 0.0]), QUARTERS[3]);
    assert_eq!(sample(vspec, 2.0, [0.125, 0.875, 0.0]), QUARTERS[3]);
    // E = (0.625, 0.375, 0): R = (0.375, 0.625, 0), the second texel.
    assert_eq!(sample(vspec, 1.0, [0.625, 0.375, 0.0]), QUARTERS[1]);
}

#[test]
fn hostile_bump_matrices_do_not_panic() {
    // NaN, ±∞ and f32::MAX in the matrix and luminance: the coordinate is
    // non-finite or huge; the sample follows ps30's rule for such
    // coordinates (docs/textures.md) and the draw ends.
    let body = "tex t0\ntexbeml t1, t0\nmov r1, t1\n";
    for v in [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        -f32::MAX,
    ] {
        let env = BumpEnv {
            matrix: [v; 4],
            lscale: v,
            loffset: v,
        };
        let got = address_with("ps_1_1", body, Some(1), &[[0.125, 0.5, 0.0, 1.0]], |d| {
            set_bump(d, 1, env)
        });
        assert_eq!(got.len(), 4);
    }
}
