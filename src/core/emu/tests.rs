//! Unit tests of the emulator: special values, operand handling,
//! flow control, executed-slot counting, determinism and errors.

use super::testasm::shader;
use super::*;

fn compiled(text: &str) -> Compiled {
    compile(&shader(text)).expect("compiles")
}

pub(super) fn run_text(text: &str, draw: &Draw) -> DrawOutput {
    run(&compiled(text), draw).expect("runs")
}

/// oC0 and executed slots of a single-pixel draw.
fn pixel_exec(text: &str) -> ([f32; 4], u64) {
    let out = run_text(text, &Draw::new(1, 1));
    (
        out.color[0].as_ref().expect("oC0 written")[0],
        out.executed[0],
    )
}

fn pixel(text: &str) -> [f32; 4] {
    pixel_exec(text).0
}

/// A draw whose v0 is the pixel position (x, y, 0, 1).
fn pos_draw<'a>(w: u32, h: u32) -> Draw<'a> {
    let mut d = Draw::new(w, h);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.0, 0.0, 0.0, 1.0],
            ddx: [1.0, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0, 0.0, 0.0],
        },
    ));
    d
}

/// A `w × h` draw with v0 interpolated by `input` and `texture` on s0
/// under `state`.
fn textured<'a>(
    w: u32,
    h: u32,
    input: LinearInput,
    texture: Texture<'a>,
    state: SamplerState,
) -> Draw<'a> {
    let mut d = Draw::new(w, h);
    d.inputs.push((0, input));
    d.samplers.push((0, texture.into(), state));
    d
}

fn bits(v: [f32; 4]) -> [u32; 4] {
    v.map(f32::to_bits)
}

/// Bit-exact comparison of two outputs (NaN and -0.0 aware).
fn same_bits(a: &DrawOutput, b: &DrawOutput) -> bool {
    let colors = |o: &DrawOutput| -> Vec<Option<Vec<[u32; 4]>>> {
        o.color
            .iter()
            .map(|c| c.as_ref().map(|v| v.iter().map(|&p| bits(p)).collect()))
            .collect()
    };
    let depth = |o: &DrawOutput| -> Option<Vec<u32>> {
        o.depth
            .as_ref()
            .map(|d| d.iter().map(|x| x.to_bits()).collect())
    };
    a.width == b.width
        && a.height == b.height
        && colors(a) == colors(b)
        && depth(a) == depth(b)
        && a.killed == b.killed
        && a.executed == b.executed
}

// ----- structure ------------------------------------------------------------

#[test]
fn micro_op_is_small() {
    assert!(
        std::mem::size_of::<MicroOp>() <= 20,
        "MicroOp is {} bytes",
        std::mem::size_of::<MicroOp>()
    );
    assert_eq!(Compiled::op_size(), std::mem::size_of::<MicroOp>());
}

#[test]
fn compile_resolves_jumps_and_keeps_slots() {
    let c = compiled(
        "defi i0, 2, 0, 0, 0
         rep i0
           mov r0, c0
         endrep
         mov oC0, r0",
    );
    assert_eq!(c.op_count(), 5); // 4 instructions + end sentinel
    let slots: Vec<u8> = c.ops.iter().map(|m| m.slots).collect();
    assert_eq!(slots, [3, 1, 2, 1, 0]);
    assert!(matches!(c.ops[0].op, compile::Op::Rep { end, .. } if end.get() == 2));
    assert!(matches!(c.ops[2].op, compile::Op::EndRep { start } if start.get() == 0));
}

// ----- special values -------------------------------------------------------

#[test]
fn log_special_values() {
    let r = pixel(
        "def c0, 0, -8, 8, 0.5
         log r0.x, c0.x
         log r0.y, c0.y
         log r0.z, c0.z
         log r0.w, c0.w
         mov oC0, r0",
    );
    assert_eq!(r[0], -f32::MAX, "log(0) is -FLT_MAX, not -inf");
    assert_eq!(r[1], 3.0, "log(-8) = log2(|-8|)");
    assert_eq!(r[2], 3.0);
    assert_eq!(r[3], -1.0);
    // Scalar result replicated to every written component.
    let r = pixel("def c0, 4, 0, 0, 0\nlog oC0, c0.x");
    assert_eq!(r, [2.0; 4]);
}

#[test]
fn exp_rcp_rsq_special_values() {
    let r = pixel(
        "def c0, 3, -1, 0, 200
         exp r0.x, c0.x
         exp r0.y, c0.y
         exp r0.z, c0.z
         exp r0.w, c0.w
         mov oC0, r0",
    );
    assert_eq!(r, [8.0, 0.5, 1.0, f32::INFINITY]);
    let r = pixel(
        "def c0, 0, 1, 4, -0.0
         rcp r0.x, c0.x
         rcp r0.y, c0.y
         rcp r0.z, c0.z
         rcp r0.w, c0.w
         mov oC0, r0",
    );
    assert_eq!(r, [f32::INFINITY, 1.0, 0.25, f32::NEG_INFINITY]);
    let r = pixel(
        "def c0, -4, 0, 1, -0.0
         rsq r0.x, c0.x
         rsq r0.y, c0.y
         rsq r0.z, c0.z
         rsq r0.w, c0.w
         mov oC0, r0",
    );
    assert_eq!(r, [0.5, f32::INFINITY, 1.0, f32::INFINITY]);
}

#[test]
fn nrm_of_zero_scales_by_flt_max() {
    let r = pixel("def c0, 0, 0, 0, 0.5\nnrm r0, c0\nmov oC0, r0");
    assert_eq!(r, [0.0, 0.0, 0.0, 0.5 * f32::MAX]);
    let r = pixel("def c0, 3, 0, 4, 10\nnrm r0, c0\nmov oC0, r0");
    assert_eq!(r, [0.6, 0.0, 0.8, 2.0]);
}

#[test]
fn frc_of_negatives_stays_below_one() {
    let r = pixel(
        "def c0, -0.25, 1.75, -1e-9, -3
         frc r0, c0
         mov oC0, r0",
    );
    assert_eq!(r[0], 0.75);
    assert_eq!(r[1], 0.75);
    assert!(r[2] < 1.0 && r[2] > 0.99, "frc(-1e-9) = {}", r[2]);
    assert_eq!(r[3], 0.0);
}

#[test]
fn cmp_treats_negative_zero_as_not_below_zero() {
    let r = pixel(
        "def c0, -0.0, 0, -1e-30, 1
         def c1, 1, 1, 1, 1
         def c2, 2, 2, 2, 2
         cmp oC0, c0, c1, c2",
    );
    assert_eq!(r, [1.0, 1.0, 2.0, 1.0]);
}

#[test]
fn sat_clamps_and_maps_nan_to_zero() {
    let r = pixel(
        "def c0, -0.5, 0.25, 2, 0
         mov_sat oC0, c0",
    );
    assert_eq!(r, [0.0, 0.25, 1.0, 0.0]);
    // NaN = 0 * inf.
    let r = pixel(
        "def c0, 0, 0, 0, 0
         rcp r1.x, c0.x
         mul_sat oC0, r1.x, c0.x",
    );
    assert_eq!(r, [0.0; 4]);
}

#[test]
fn pow_uses_absolute_base() {
    let r = pixel(
        "def c0, -2, 3, 0, 0.5
         def c1, 4, 0, 0, 0
         pow r0.x, c0.x, c0.y
         pow r0.y, c0.z, c0.z
         pow r0.z, c1.x, c0.w
         pow r0.w, c0.z, -c0.y
         mov oC0, r0",
    );
    assert_eq!(r, [8.0, 1.0, 2.0, f32::INFINITY]);
}

#[test]
fn arithmetic_ops() {
    let r = pixel(
        "def c0, 1, 2, 3, 4
         def c1, 0.5, -1, 2, 0
         def c2, 10, 20, 30, 40
         mad r0, c0, c1, c2
         mov oC0, r0",
    );
    assert_eq!(r, [10.5, 18.0, 36.0, 40.0]);
    let r = pixel(
        "def c0, 1, 2, 3, 4
         def c1, 0.5, -1, 2, 0
         dp3 r0.x, c0, c1
         dp4 r0.y, c0, c0
         dp2add r0.z, c0, c1, c0.w
         sub r0.w, c0.x, c1.y
         mov oC0, r0",
    );
    assert_eq!(r, [4.5, 30.0, 2.5, 2.0]);
    let r = pixel(
        "def c0, 0.25, 0.5, 1, 0
         def c1, 4, 8, 2, 1
         def c2, 0, 0, 6, 3
         lrp r0, c0, c1, c2
         min r1, c1, c2
         max r2, c1, c2
         add r0.w, r1.w, r2.w
         mov oC0, r0",
    );
    assert_eq!(r, [1.0, 4.0, 2.0, 4.0]);
    let r = pixel(
        "def c0, 1, 0, 0, 7
         def c1, 0, 1, 0, 7
         def c5, 9, 9, 9, 9
         mov r0, c5
         crs r0.xyz, c0, c1
         mov oC0, r0",
    );
    assert_eq!(r, [0.0, 0.0, 1.0, 9.0]);
    let r = pixel(
        "def c0, 0, 0, 0, 0
         sincos r0.xy, c0.x
         mov oC0, r0",
    );
    assert_eq!(r, [1.0, 0.0, 0.0, 0.0]);
    let r = pixel(
        "def c0, -3, 2, -0.5, 0
         abs oC0, c0",
    );
    assert_eq!(r, [3.0, 2.0, 0.5, 0.0]);
}

#[test]
fn matrix_ops_read_consecutive_registers() {
    let r = pixel(
        "def c0, 1, 2, 3, 4
         def c10, 1, 0, 0, 0
         def c11, 0, 1, 0, 1
         def c12, 1, 1, 1, 1
         def c13, 0, 0, 0, 2
         m4x4 r0, c0, c10
         mov oC0, r0",
    );
    assert_eq!(r, [1.0, 6.0, 10.0, 8.0]);
    let r = pixel(
        "def c0, 1, 2, 3, 4
         def c10, 1, 0, 0, 0
         def c11, 0, 1, 0, 1
         def c5, 7, 7, 7, 7
         mov r0, c5
         m3x2 r0.xy, c0, c10
         mov oC0, r0",
    );
    assert_eq!(r, [1.0, 2.0, 7.0, 7.0], "m3x2 leaves z and w alone");
    let r = pixel(
        "def c0, 1, 2, 3, 4
         mov r1, c0
         mov r2, c0
         mov r3, c0
         def c5, 7, 7, 7, 7
         mov r0, c5
         m4x3 r0.xyz, c0, r1
         mov oC0, r0",
    );
    assert_eq!(r, [30.0, 30.0, 30.0, 7.0]);
}

#[test]
fn mad_is_not_fused() {
    // a*b rounds to 1 in f32; fused would keep 2^-48.
    let a = 1.0f32 + f32::EPSILON;
    let b = 1.0f32 - f32::EPSILON / 2.0;
    let text = format!(
        "def c0, {:e}, {:e}, -1, 0
         mad oC0, c0.x, c0.y, c0.z",
        a, b
    );
    let r = pixel(&text);
    assert_eq!(r[0], a * b - 1.0);
    assert_eq!(r[0], (a * b) + -1.0);
}

// ----- operands -------------------------------------------------------------

#[test]
fn swizzle_mask_and_modifiers() {
    let r = pixel(
        "def c0, 1, -2, 3, -4
         def c1, 10, 10, 10, 10
         mov r0, c1
         add r0.yw, -c0_abs.wzyx, c0.x
         mov oC0, r0",
    );
    // y = -|c0.z| + 1 = -2, w = -|c0.x| + 1 = 0
    assert_eq!(r, [10.0, -2.0, 10.0, 0.0]);
    let r = pixel(
        "def c0, 1, -2, 3, -4
         mov r0, c0.yx
         mov r1, -c0
         mov r2, c0_abs.w
         mov r3, r0
         add r3, r3.wzyx, r3
         mov oC0.x, r0.y
         mov oC0.y, r1.w
         mov oC0.z, r2.y
         mov oC0.w, r3.x",
    );
    // r0 = (-2, 1, 1, 1); r3 = r0.wzyx + r0 = (1-2, 1+1, 1+1, -2+1)
    assert_eq!(r, [1.0, 4.0, 4.0, -1.0]);
    // A source aliasing the destination is read before it is written.
    let r = pixel(
        "def c0, 1, 2, 3, 4
         mov r0, c0
         mov r0, r0.wzyx
         mov oC0, r0",
    );
    assert_eq!(r, [4.0, 3.0, 2.0, 1.0]);
}

#[test]
fn negative_zero_from_negation() {
    let r = pixel("def c0, 0, 0, 0, 0\nmov oC0, -c0");
    assert_eq!(bits(r), [0x8000_0000; 4]);
}

#[test]
fn inputs_vpos_and_vface() {
    let text = "dcl_texcoord0 v0
         dcl vPos.xy
         dcl vFace
         mov r0.xy, vPos
         mov r0.z, v0.z
         mov r0.w, vFace.x
         mov oC0, r0";
    let mut d = Draw::new(3, 3);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.0, 0.0, 5.0, 0.0],
            ddx: [0.0, 0.0, 1.0, 0.0],
            ddy: [0.0, 0.0, 10.0, 0.0],
        },
    ));
    let out = run_text(text, &d);
    let c = out.color[0].as_ref().unwrap();
    for y in 0..3 {
        for x in 0..3 {
            let (xf, yf) = (x as f32, y as f32);
            assert_eq!(c[y * 3 + x], [xf, yf, 5.0 + xf + 10.0 * yf, 1.0]);
        }
    }
    assert_eq!(out.executed, vec![4; 9]);
}

#[test]
fn vpos_of_packed_windows_is_each_pixels_given_position() {
    // A 4×2 draw of two 2×2 windows packed side by side: the left one is
    // the target's (10, 20)–(11, 21), the right one (100, 6)–(101, 7).
    // `positions` names each pixel's place; `origin` is not read then.
    let text = "dcl vPos.xy
         mov r0, vPos
         mov oC0, r0";
    let at = |x: u32, y: u32| match x < 2 {
        true => (10 + x, 20 + y),
        false => (100 + x - 2, 6 + y),
    };
    let p = PixelInputs {
        origin: (50, 50),
        covered: vec![true; 8],
        values: Vec::new(),
        positions: Some((0..8).map(|i| at(i % 4, i / 4)).collect()),
    };
    let mut d = Draw::new(4, 2);
    d.pixels = Some(&p);
    let out = run_text(text, &d);
    let c = out.color[0].as_ref().unwrap();
    for (i, got) in c.iter().enumerate() {
        let (x, y) = at(i as u32 % 4, i as u32 / 4);
        assert_eq!(*got, [x as f32, y as f32, 0.0, 0.0], "pixel {i}");
    }
    // Positions that do not cover the quad grid are refused by name.
    let short = PixelInputs {
        positions: Some(vec![(0, 0); 7]),
        ..p.clone()
    };
    d.pixels = Some(&short);
    let err = run(&compiled(text), &d).expect_err("refused");
    assert!(
        err.to_string().contains("7 positions for a quad grid of 8"),
        "{err}"
    );
}

#[test]
fn vface_holds_the_sign_of_the_draws_face() {
    // Every component is ±1; `cmp` (a ≥ 0) and `if_lt` see the sign.
    let text = "def c0, 0, 1, 0, 0
         def c1, 1, 0, 0, 0
         dcl vFace
         cmp r0, vFace, c0, c1
         mov r0.w, vFace.y
         if_lt vFace, c0.x
           mov r0.z, c1.x
         endif
         mov oC0, r0";
    for (face, want) in [
        (Face::Front, [0.0, 1.0, 0.0, 1.0]),
        (Face::Back, [1.0, 0.0, 1.0, -1.0]),
    ] {
        let mut d = Draw::new(2, 2);
        d.face = face;
        let out = run_text(text, &d);
        assert_eq!(out.color[0].as_ref().unwrap(), &vec![want; 4], "{face:?}");
    }
    assert_eq!(Draw::new(1, 1).face, Face::Front);
}

#[test]
fn application_constants_and_def_override() {
    let text = "def c1, 5, 5, 5, 5
         add oC0, c0, c1";
    let mut d = Draw::new(1, 1);
    d.constants.float = vec![[1.0, 2.0, 3.0, 4.0], [100.0; 4]];
    let out = run_text(text, &d);
    assert_eq!(out.color[0].as_ref().unwrap()[0], [6.0, 7.0, 8.0, 9.0]);
}

#[test]
fn dsx_dsy_are_coarse_quad_differences() {
    let text = "dcl_texcoord0 v0
         dsx r0, v0
         dsy r1, v0
         mov oC0, r0
         mov oC1, r1";
    let mut d = Draw::new(4, 4);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.0; 4],
            ddx: [2.0, 0.0, 1.0, 0.0],
            ddy: [0.0, 3.0, 1.0, 0.0],
        },
    ));
    let out = run_text(text, &d);
    assert!(out.color[0]
        .as_ref()
        .unwrap()
        .iter()
        .all(|&p| p == [2.0, 0.0, 1.0, 0.0]));
    assert!(out.color[1]
        .as_ref()
        .unwrap()
        .iter()
        .all(|&p| p == [0.0, 3.0, 1.0, 0.0]));
    // Edge quads of an odd target use their (outside) helper lanes.
    d.target_width = 3;
    d.target_height = 3;
    let out = run_text(text, &d);
    assert!(out.color[0]
        .as_ref()
        .unwrap()
        .iter()
        .all(|&p| p == [2.0, 0.0, 1.0, 0.0]));
}

// ----- flow control and executed slots --------------------------------------

#[test]
fn rep_charges_per_iteration() {
    let (r, n) = pixel_exec(
        "defi i0, 128, 0, 0, 0
         def c0, 1, 0, 0, 0
         mov r0, c0.y
         rep i0
           add r0.x, r0.x, c0.x
           add r0.y, r0.y, c0.x
           add r0.z, r0.z, c0.x
           add r0.w, r0.w, c0.x
         endrep
         mov oC0, r0",
    );
    assert_eq!(r, [128.0; 4]);
    assert_eq!(n, 1 + 128 * (3 + 4 + 2) + 1);
}

#[test]
fn zero_iteration_loops_charge_the_header_once() {
    let (r, n) = pixel_exec(
        "defi i0, 0, 0, 0, 0
         def c0, 1, 0, 0, 0
         mov r0, c0
         rep i0
           add r0, r0, c0
         endrep
         loop aL, i0
           add r0, r0, c0
         endloop
         mov oC0, r0",
    );
    assert_eq!(r, [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(n, 1 + 3 + 3 + 1);
}

#[test]
fn loop_al_with_negative_step() {
    let (r, n) = pixel_exec(
        "defi i0, 3, 10, -2, 0
         def c0, 0, 0, 0, 0
         mov r0, c0
         loop aL, i0
           add r0.x, r0.x, aL
           add r0.y, r0.y, c0.x
         endloop
         mov r0.z, aL
         mov oC0, r0",
    );
    assert_eq!(r[0], 10.0 + 8.0 + 6.0);
    assert_eq!(r[2], 0.0, "aL outside loops reads 0");
    assert_eq!(n, 1 + 3 * (3 + 2 + 2) + 1 + 1);
}

#[test]
fn nested_loops_and_relative_inputs() {
    // v[aL] walks v0..v2; the outer loop's aL is restored after the inner one.
    let text = "dcl_texcoord0 v0
         dcl_texcoord1 v1
         dcl_texcoord2 v2
         defi i0, 3, 0, 1, 0
         defi i1, 2, 5, 1, 0
         def c0, 0, 0, 0, 0
         mov r0, c0
         mov r1, c0
         loop aL, i0
           add r0, r0, v[aL]
           loop aL, i1
             add r1.x, r1.x, aL
           endloop
           add r1.y, r1.y, aL
         endloop
         mov r0.w, r1.x
         mov r0.z, r1.y
         mov oC0, r0";
    let mut d = Draw::new(1, 1);
    for v in 0..3u32 {
        let x = 10f32.powi(v as i32);
        d.inputs
            .push((v, LinearInput::constant([x, 2.0 * x, 0.0, 0.0])));
    }
    let out = run_text(text, &d);
    // r1.x: 3 × (5 + 6); r1.y: 0 + 1 + 2.
    assert_eq!(out.color[0].as_ref().unwrap()[0], [111.0, 222.0, 3.0, 33.0]);
    let inner = 2 * (3 + 1 + 2);
    assert_eq!(out.executed[0], 2 + 3 * (3 + 1 + inner + 1 + 2) + 3);
}

#[test]
fn relative_input_out_of_range_reads_zero() {
    let text = "dcl_texcoord0 v0
         defi i0, 1, 12, 1, 0
         loop aL, i0
           mov r0, v[aL]
         endloop
         mov oC0, r0";
    let mut d = Draw::new(1, 1);
    d.inputs.push((0, LinearInput::constant([1.0; 4])));
    let out = run_text(text, &d);
    assert_eq!(out.color[0].as_ref().unwrap()[0], [0.0; 4]);
}

#[test]
fn nested_rep_with_break_out_of_inner() {
    let (r, n) = pixel_exec(
        "def c0, 1, 2, 0, 0
         defi i0, 3, 0, 0, 0
         defi i1, 5, 0, 0, 0
         mov r0, c0.z
         rep i0
           mov r1, c0.z
           rep i1
             add r1.x, r1.x, c0.x
             add r0.x, r0.x, c0.x
             break_ge r1.x, c0.y
           endrep
         endrep
         mov oC0, r0",
    );
    assert_eq!(r[0], 6.0);
    // inner: (3+1+1+3+2) + (3+1+1+3) = 18; outer iteration 3+1+18+2 = 24.
    assert_eq!(n, 1 + 3 * 24 + 1);
}

#[test]
fn divergent_break_keeps_per_lane_counts() {
    // Lane x breaks after x + 1 iterations of a rep 4.
    let text = "dcl_texcoord0 v0
         def c0, 1, 0, 0, 0
         defi i0, 4, 0, 0, 0
         mov r0, c0.y
         rep i0
           add r0.x, r0.x, c0.x
           break_gt r0.x, v0.x
         endrep
         mov oC0, r0";
    let out = run_text(text, &pos_draw(4, 1));
    let c = out.color[0].as_ref().unwrap();
    for (x, p) in c.iter().enumerate() {
        assert_eq!(p[0], x as f32 + 1.0);
        let k = x as u64 + 1;
        // k iterations of rep+add+break; the breaking one pays no endrep.
        assert_eq!(
            out.executed[x],
            1 + k * (3 + 1 + 3) + (k - 1) * 2 + 1,
            "lane {x}"
        );
    }
}

#[test]
fn breakp_uses_the_predicate_per_lane() {
    let text = "dcl_texcoord0 v0
         def c0, 1, 0, 2, 0
         defi i0, 10, 0, 0, 0
         mov r0, c0.y
         rep i0
           add r0.x, r0.x, c0.x
           setp_ge p0.x, r0.x, v0.x
           breakp p0.x
         endrep
         mov oC0, r0";
    let out = run_text(text, &pos_draw(4, 1));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(
        c.iter().map(|p| p[0]).collect::<Vec<_>>(),
        [1.0, 1.0, 2.0, 3.0]
    );
}

#[test]
fn if_else_divergence_within_a_quad() {
    let text = "dcl vPos.xy
         def c0, 1, 0, 0, 0
         if_lt vPos.x, c0.x
           mov r0, c0.x
           add r0, r0, c0.x
         else
           mov r0, c0.y
         endif
         mov oC0, r0";
    let out = run_text(text, &Draw::new(2, 2));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(c[0], [2.0; 4]);
    assert_eq!(c[1], [0.0; 4]);
    assert_eq!(c[2], [2.0; 4]);
    assert_eq!(c[3], [0.0; 4]);
    // then: if 3 + 2 + else 1 + endif 1 + mov 1; else side: 3 + 1 + 1 + 1 + 1.
    assert_eq!(out.executed, vec![8, 7, 8, 7]);
}

#[test]
fn uniform_if_charges_if_else_endif() {
    for (b, want_r, want_n) in [
        ("true", 1.0, 3 + 1 + 1 + 1 + 1),
        ("false", 2.0, 3 + 1 + 1 + 1 + 1),
    ] {
        let text = format!(
            "defb b0, {b}
             def c0, 1, 2, 0, 0
             if b0
               mov r0, c0.x
             else
               mov r0, c0.y
             endif
             mov oC0, r0"
        );
        let (r, n) = pixel_exec(&text);
        assert_eq!(r[0], want_r);
        assert_eq!(n, want_n);
    }
    // No else, condition false: if + endif only.
    let (r, n) = pixel_exec(
        "def c0, 1, 2, 0, 0
         mov r0, c0.y
         if_gt c0.x, c0.y
           mov r0, c0.x
           mov r0, c0.x
         endif
         mov oC0, r0",
    );
    assert_eq!(r[0], 2.0);
    assert_eq!(n, 1 + 3 + 1 + 1);
}

#[test]
fn nested_divergent_ifs() {
    // x = 0..3: outer x < 2, inner x odd.
    let text = "dcl_texcoord0 v0
         def c0, 2, 0.5, 0, 1
         mov r0, c0.z
         if_lt v0.x, c0.x
           frc r1.x, v0.x
           mov r1.y, v0.x
           mul r1.y, r1.y, c0.y
           frc r1.y, r1.y
           if_gt r1.y, c0.z
             mov r0.x, c0.w
           else
             mov r0.y, c0.w
           endif
         else
           mov r0.z, c0.w
         endif
         mov oC0, r0";
    let out = run_text(text, &pos_draw(4, 1));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(c[0], [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(c[1], [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(c[2], [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(c[3], [0.0, 0.0, 1.0, 0.0]);
    let inner = 3 + 1 + 1 + 1; // if, one mov, else, endif
    assert_eq!(out.executed[0], 1 + 3 + 4 + inner + 1 + 1 + 1);
    assert_eq!(out.executed[1], 1 + 3 + 4 + inner + 1 + 1 + 1);
    assert_eq!(out.executed[2], 1 + 3 + 1 + 1 + 1 + 1);
}

#[test]
fn break_or_ret_inside_an_if_skips_its_else_and_endif() {
    // As in the cost model: endif is paid only by lanes that leave the if
    // normally; `else` by lanes that pass it, so a lane breaking out of the
    // then-side pays neither and one breaking out of the else-side pays
    // `else` only.
    let text = "dcl_texcoord0 v0
         def c0, 1, 0, 0, 0
         defi i0, 3, 0, 0, 0
         mov r0, c0.y
         rep i0
           add r0.x, r0.x, c0.x
           if_lt v0.x, c0.x
             break
           else
             break
           endif
         endrep
         mov oC0, r0";
    let out = run_text(text, &pos_draw(2, 1));
    // mov + rep 3 + add 1 + if 3 + break 1 + mov 1, plus else on the
    // else-side.
    assert_eq!(out.executed, vec![10, 11]);
    let text = "dcl_texcoord0 v0
         def c0, 1, 0, 0, 0
         mov oC0, c0
         if_lt v0.x, c0.x
           mov r0, c0
         else
           ret
         endif
         mov oC0, c0.y";
    let out = run_text(text, &pos_draw(2, 1));
    assert_eq!(out.executed, vec![1 + 3 + 1 + 1 + 1 + 1, 1 + 3 + 1 + 1]);
    assert_eq!(out.color[0].as_ref().unwrap()[1], [1.0, 0.0, 0.0, 0.0]);
}

#[test]
fn invalid_int_constants_are_refused() {
    for (text, reason) in [
        (
            "defi i0, 256, 0, 0, 0\nrep i0\nendrep\nmov oC0, c0",
            "0..=255",
        ),
        (
            "defi i0, -1, 0, 0, 0\nrep i0\nendrep\nmov oC0, c0",
            "0..=255",
        ),
        (
            "defi i2, 1, 0, 200, 0\nloop aL, i2\nendloop\nmov oC0, c0",
            "-128..=127",
        ),
        (
            "defi i2, 1, 300, 1, 0\nloop aL, i2\nendloop\nmov oC0, c0",
            "start",
        ),
    ] {
        let e = run(&compiled(text), &Draw::new(1, 1)).unwrap_err();
        assert!(
            matches!(e, EmuError::InvalidIntConstant { .. }) && e.to_string().contains(reason),
            "{text}: {e}"
        );
    }
    // Application-set values are checked too; unused registers are not.
    let c = compiled("rep i1\nendrep\nmov oC0, c0");
    let mut d = Draw::new(1, 1);
    d.constants.int = vec![[999, 999, 999, 999], [1000, 0, 0, 0]];
    assert!(matches!(
        run(&c, &d).unwrap_err(),
        EmuError::InvalidIntConstant { register: 1, .. }
    ));
    d.constants.int[1] = [2, 0, 0, 0];
    assert_eq!(run(&c, &d).unwrap().executed, vec![3 + 2 + 3 + 2 + 1]);
}

#[test]
fn call_and_ret() {
    let (r, n) = pixel_exec(
        "def c0, 1, 0, 0, 0
         mov r0, c0.y
         call l0
         call l0
         mov oC0, r0
         ret
         label l0
         add r0, r0, c0.x
         ret",
    );
    assert_eq!(r, [2.0; 4]);
    assert_eq!(n, 1 + 2 * (2 + 1 + 1) + 1 + 1);
}

#[test]
fn callnz_with_predicate_diverges() {
    let text = "dcl_texcoord0 v0
         def c0, 1, 0, 10, 0
         mov r0, c0.y
         setp_ge p0.x, v0.x, c0.x
         callnz l3, p0.x
         callnz l3, !b2
         mov oC0, r0
         ret
         label l3
         add r0, r0, c0.z
         ret";
    let out = run_text(text, &pos_draw(2, 1));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(c[0][0], 10.0);
    assert_eq!(c[1][0], 20.0);
    assert_eq!(out.executed[0], 1 + 1 + 3 + 3 + 2 + 1 + 1);
    assert_eq!(out.executed[1], 1 + 1 + 3 + 2 + 3 + 2 + 1 + 1);
}

#[test]
fn nested_calls_and_call_depth_limit() {
    let (r, _) = pixel_exec(
        "def c0, 1, 0, 0, 0
         mov r0, c0.y
         call l1
         mov oC0, r0
         ret
         label l1
         call l2
         add r0, r0, c0.x
         ret
         label l2
         add r0, r0, c0.x
         ret",
    );
    assert_eq!(r, [2.0; 4]);
    let c = compiled(
        "call l0
         mov oC0, c0
         ret
         label l0
         call l0
         ret",
    );
    let err = run(&c, &Draw::new(2, 2)).unwrap_err();
    assert!(
        matches!(
            err,
            EmuError::CallDepth {
                x: 0,
                y: 0,
                index: 4
            }
        ),
        "{err}"
    );
}

#[test]
fn ret_in_main_ends_lanes_and_keeps_their_outputs() {
    let text = "dcl vPos.xy
         def c0, 1, 1, 1, 1
         def c1, 1, 0, 0, 0
         def c2, 2, 2, 2, 2
         mov oC0, c0
         if_lt vPos.x, c1.x
           ret
         endif
         mov oC0, c2
         mov r0, c2";
    let out = run_text(text, &Draw::new(2, 2));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(c[0], [1.0; 4]);
    assert_eq!(c[1], [2.0; 4]);
    assert_eq!(c[2], [1.0; 4]);
    assert_eq!(c[3], [2.0; 4]);
    assert_eq!(out.executed, vec![1 + 3 + 1, 1 + 3 + 1 + 1 + 1, 5, 7]);
}

#[test]
fn predication_masks_writes_per_component() {
    let r = pixel(
        "def c0, 1, -1, 1, -1
         def c1, 0, 0, 0, 0
         def c2, 5, 5, 5, 5
         def c3, 7, 7, 7, 7
         mov r0, c1
         setp_gt p0, c0, c1
         (p0) mov r0, c2
         (!p0.x) mov r0.x, c3
         (!p0.y) add r0.y, r0.y, c3
         mov oC0, r0",
    );
    assert_eq!(r, [5.0, 7.0, 5.0, 0.0]);
    // +1 slot for each predicated instruction.
    let (_, n) = pixel_exec(
        "def c0, 1, 0, 0, 0
         setp_gt p0.x, c0.x, c0.y
         (p0.x) mov r0, c0
         mov oC0, r0",
    );
    assert_eq!(n, 1 + 2 + 1);
}

#[test]
fn predication_per_lane() {
    let text = "dcl_texcoord0 v0
         def c0, 1.5, 0, 9, 0
         mov r0, c0.y
         setp_gt p0.x, v0.x, c0.x
         (p0.x) mov r0, c0.z
         mov oC0, r0";
    let out = run_text(text, &pos_draw(4, 1));
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(
        c.iter().map(|p| p[0]).collect::<Vec<_>>(),
        [0.0, 0.0, 9.0, 9.0]
    );
}

#[test]
fn texkill_discards_pixels_that_keep_running() {
    // Killed lanes keep executing and paying (the cost model ignores
    // texkill) and stay valid quad neighbours: dsx in the surviving lanes
    // still sees the killed lanes' values.
    let text = "dcl_texcoord0 v0
         def c0, -0.5, 0.5, 0.5, 1
         add r0, v0, c0
         texkill r0
         mov oC0, c0.w
         dsx r1, v0
         mov oC1, r1";
    let out = run_text(text, &pos_draw(2, 2));
    assert_eq!(out.killed, vec![true, false, true, false]);
    // add 1, texkill 1 (Microsoft's count), mov 1, dsx 2, mov 1.
    assert_eq!(out.executed, vec![1 + 1 + 1 + 2 + 1; 4]);
    let c = out.color[0].as_ref().unwrap();
    assert_eq!(c[0], [0.0; 4], "discarded pixels report zero");
    assert_eq!(c[1], [1.0; 4]);
    assert_eq!(out.color[1].as_ref().unwrap()[1], [1.0, 0.0, 0.0, 0.0]);
}

#[test]
fn texkill_tests_w_and_kills_everything() {
    // ps_2_0 and later kill on any of x, y, z, w below zero: w alone kills.
    let c = compiled("def c0, 1, 1, 1, -1\nmov r0, c0\ntexkill r0\nmov oC0, r0");
    let out = run(&c, &Draw::new(1, 1)).unwrap();
    assert_eq!(out.killed, vec![true]);
    // ... unless the operand's mask leaves w out.
    let c = compiled("def c0, 1, 1, 1, -1\nmov r0, c0\ntexkill r0.xyz\nmov oC0, r0");
    let out = run(&c, &Draw::new(1, 1)).unwrap();
    assert_eq!(out.killed, vec![false]);
    let c = compiled("def c0, 1, -1, 1, 1\nmov r0, c0\ntexkill r0\nmov oC0, r0");
    let out = run(&c, &Draw::new(3, 3)).unwrap();
    assert_eq!(out.killed, vec![true; 9]);
    // mov 1, texkill 1 (Microsoft's count), mov 1.
    assert_eq!(out.executed, vec![3; 9]);
    assert_eq!(out.color[0].as_ref().unwrap(), &vec![[0.0; 4]; 9]);
    // Predicated texkill: only lanes whose predicate holds are tested.
    let c = compiled(
        "def c0, -1, -1, -1, -1
         mov r0, c0
         setp_gt p0.x, c0.x, c0.x
         (p0.x) texkill r0
         mov oC0, c0",
    );
    assert_eq!(run(&c, &Draw::new(1, 1)).unwrap().killed, vec![false]);
}

#[test]
fn unwritten_outputs_are_none() {
    let out = run_text("def c0, 1, 1, 1, 1\nmov oC2, c0", &Draw::new(2, 1));
    assert!(out.color[0].is_none());
    assert!(out.color[1].is_none());
    assert_eq!(out.color[2].as_ref().unwrap(), &vec![[1.0; 4]; 2]);
    assert!(out.depth.is_none());
    let out = run_text("def c0, 0.5, 1, 1, 1\nmov oDepth, c0.x", &Draw::new(2, 1));
    assert_eq!(out.depth, Some(vec![0.5, 0.5]));
}

// ----- batches, threads, limits ---------------------------------------------

/// A shader with texture reads, divergent loops and branches.
const BUSY: &str = "dcl_texcoord0 v0
     dcl_2d s0
     def c0, 0.25, 1, 0, 3
     defi i0, 6, 0, 0, 0
     mov r0, c0.z
     mov r1, v0
     rep i0
       texld r2, r1, s0
       dp4 r3.x, r2, r2
       log r3.y, r3.x
       add r0, r0, r3.y
       add r1.xy, r1, c0.x
       frc r4.x, r1.x
       break_gt r4.x, v0.z
     endrep
     if_lt r0.x, c0.w
       mul r0, r0, c0.w
     else
       rsq r0.y, r0.x
     endif
     mov oC0, r0
     mov oC1, r1";

fn busy_draw(texels: &[[f32; 4]], w: u32, h: u32) -> Draw<'_> {
    textured(
        w,
        h,
        LinearInput {
            base: [0.01, 0.02, 0.3, 1.0],
            ddx: [0.013, 0.007, 0.011, 0.0],
            ddy: [0.005, 0.017, 0.023, 0.0],
        },
        Texture {
            width: 5,
            height: 3,
            texels,
        },
        SamplerState {
            address_u: Address::Wrap,
            address_v: Address::Mirror,
            address_w: Address::Mirror,
            border: [0.0; 4],
            ..SamplerState::filtered(Filter::Linear)
        },
    )
}

/// Runs `f` with the portable executor forced on this thread.
fn portable<T>(f: impl FnOnce() -> T) -> T {
    exec::PORTABLE_ONLY.with(|p| p.set(true));
    let r = f();
    exec::PORTABLE_ONLY.with(|p| p.set(false));
    r
}

/// Every arithmetic op on operands from tiny (subnormal) to huge, negative,
/// zero and through the special cases of log, rcp, rsq, pow and nrm.
const EVERY_OP: &str = "dcl_texcoord0 v0
     def c0, 1e-40, 3e38, -0.5, 0.1
     mul r0, v0, v0
     mad r1, r0, c0.y, -v0
     mul r2, v0, c0.x
     log r3.x, r0.x
     log r3.y, r2.y
     exp r3.z, v0.z
     rcp r3.w, r2.x
     rsq r4.x, v0.y
     pow r4.y, v0.x, v0.w
     frc r4.z, r1.z
     lrp r4.w, c0.w, r0.x, r1.y
     nrm r5.xyz, r2
     sincos r6.xy, c0.w
     dp2add r6.z, v0, r1, c0.z
     dp3 r6.w, r1, r0
     cmp r7, -v0, r0, r1
     min r8, r1, r2
     max r9, r1, r3
     dsx r10, r1
     dsy r11, r3
     add r0, r0, r3
     add r0, r0, r4
     add r0, r0, r5
     add r0, r0, r6
     add r7, r7, r8
     add r7, r7, r9
     add r7, r7, r10
     add r7, r7, r11
     mov_sat r12, r1
     mov oC0, r0
     mov oC1, r7
     mov oC2, r12";

/// Pass 1's shape on a point-sampled BORDER texture: a masked `texld` that
/// every lane runs (it gathers straight into the destination), and one
/// with a swizzled mask that only some lanes run (through the scratch rows).
const POINT_BORDER: &str = "dcl_texcoord0 v0
     dcl_2d s0
     def c0, 0.27, 0.67, 0.06, 0.01
     def c1, 0.11, -0.07, 0, 0.5
     defi i0, 7, 0, 0, 0
     mov r1, v0
     mov r2, c1.w
     mov r4, c1.w
     mov r5, c1.z
     rep i0
       texld r2.xyz, r1, s0
       dp4 r3.x, r2, c0
       log r3.y, r3.x
       add r5.xw, r5.xwww, r3.yyyy
       if_lt r3.x, c0.y
         mov r6, r1.yxzw
         texld r4.yw, r6, s0
         add r5.y, r5.y, r4.w
       endif
       add r1.xy, r1, c1.xy
     endrep
     mov oC0, r5
     mov oC1, r2
     mov oC2, r4";

/// A 37×23 draw of [`POINT_BORDER`] over a 5×3 texture, its coordinates
/// starting left of and above it and leaving it on the right and below.
fn point_border_draw(texels: &[[f32; 4]]) -> Draw<'_> {
    textured(
        37,
        23,
        LinearInput {
            base: [-0.05, -0.03, 0.0, 0.0],
            ddx: [0.031, 0.007, 0.0, 0.0],
            ddy: [0.004, 0.049, 0.0, 0.0],
        },
        Texture {
            width: 5,
            height: 3,
            texels,
        },
        SamplerState {
            address_u: Address::Border,
            address_v: Address::Border,
            address_w: Address::Border,
            border: [0.25, 0.5, 0.75, 2.0],
            ..SamplerState::filtered(Filter::Point)
        },
    )
}

#[test]
fn masked_texld_writes_only_its_components() {
    let texels: Vec<[f32; 4]> = (0..15)
        .map(|i| [i as f32, 10.0 + i as f32, 0.5, 9.0])
        .collect();
    // Pixel (0, 0) reads texel (3, 1), number 8, at (0.7, 0.5) = (3.5/5,
    // 1.5/3); swapped, (0.5, 0.7) is texel (2, 2), number 12; 0.8 further
    // right is beyond the texture: the border colour. Its quad's helper
    // lanes (v0.x = 0.9) skip the `if`, so the `texld` there runs on part
    // of the lanes.
    let text = "dcl_texcoord0 v0
         dcl_2d s0
         def c0, -1, -2, -3, -4
         def c1, 0.8, 0, 0, 0
         mov r0, c0
         mov r1, c0
         mov r2, c0
         mov r3, v0.yxzw
         mov r4, c0
         add r5, v0, c1.x
         texld r0.xz, v0, s0
         texld r2.yw, r3, s0
         texld r4.zw, r5, s0
         if_lt v0.x, c1.x
           texld r1.y, v0, s0
         endif
         mov oC0, r0
         mov oC1, r1
         mov oC2, r2
         mov oC3, r4";
    let d = textured(
        1,
        1,
        LinearInput {
            base: [0.7, 0.5, 0.0, 0.0],
            ddx: [0.2, 0.0, 0.0, 0.0],
            ddy: [0.0; 4],
        },
        Texture {
            width: 5,
            height: 3,
            texels: &texels,
        },
        SamplerState {
            address_u: Address::Border,
            address_v: Address::Border,
            address_w: Address::Border,
            border: [0.25, 0.5, 0.75, 2.0],
            ..SamplerState::filtered(Filter::Point)
        },
    );
    let out = run_text(text, &d);
    let c = |k: usize| out.color[k].as_ref().unwrap()[0];
    assert_eq!(bits(c(0)), bits([8.0, -2.0, 0.5, -4.0]));
    assert_eq!(bits(c(1)), bits([-1.0, 18.0, -3.0, -4.0]));
    assert_eq!(bits(c(2)), bits([-1.0, 22.0, -3.0, 9.0]));
    assert_eq!(bits(c(3)), bits([-1.0, -2.0, 0.75, 2.0]));
}

#[test]
fn the_avx2_executor_matches_the_portable_one_bit_for_bit() {
    let texels: Vec<[f32; 4]> = (0..15)
        .map(|i| {
            let f = i as f32;
            [f * 0.1, 1.0 - f * 0.05, f * f * 0.01, 0.5]
        })
        .collect();
    let busy = compiled(BUSY);
    let every = compiled(EVERY_OP);
    let border = compiled(POINT_BORDER);
    let mut wide = Draw::new(37, 23);
    wide.inputs.push((
        0,
        LinearInput {
            base: [-3.0e-20, -7.5, 0.0, -1.0e30],
            ddx: [1.3e-19, 0.71, -0.37, 3.1e28],
            ddy: [-2.1e-21, -1.9, 2.3, -7.7e27],
        },
    ));
    let cases = [
        (&busy, busy_draw(&texels, 37, 23)),
        (&every, wide),
        (&border, point_border_draw(&texels)),
    ];
    for (c, d) in cases {
        let fast = run_with_threads(c, &d, 1).unwrap();
        let slow = portable(|| run_with_threads(c, &d, 1).unwrap());
        assert!(same_bits(&fast, &slow), "the two executors differ");
    }
}

/// A texld's LOD statistic covers every quad of every batch, whatever the
/// batch's size: batches of 2, 6 or 10 quads end halfway through the four
/// quads the statistic takes at a time. The coordinate is interpolated, so
/// every quad has the same gradients (`busy_draw`'s): dX = (0.013·5,
/// 0.007·3) and dY = (0.005·5, 0.017·3) texels on a 5×3 texture, and
/// λ = ½·log2(max(|dX|², |dY|²)), worked out here in f64. Tolerance: the coordinates stay below
/// 0.5, so each f32 value is within 2^-25 of its exact value and each
/// difference of two within 2^-24 = 6e-8 of the exact gradient (≥ 0.005 per
/// pixel): a relative 1.2e-5 on each component, 2.4e-5 on the squared
/// length, ½·2.4e-5/ln 2 = 1.8e-5 on λ, plus the emulator's log2 (within
/// 2^-21 relative, below 2e-6 here); 1e-4 holds all of it.
#[test]
fn lod_statistic_covers_every_quad_of_small_batches() {
    let texels = vec![[0.5f32; 4]; 15];
    let c = compiled(
        "dcl_texcoord0 v0
         dcl_2d s0
         texld r0, v0, s0
         mov oC0, r0",
    );
    let (du, dv) = (0.013 * 5.0, 0.007 * 3.0);
    let (eu, ev) = (0.005 * 5.0, 0.017 * 3.0);
    let len2 = f64::max(du * du + dv * dv, eu * eu + ev * ev);
    let expected = 0.5 * len2.log2();
    for (w, h) in [(1, 1), (3, 3), (10, 8), (11, 8), (5, 6), (17, 2)] {
        let mut d = busy_draw(&texels, w, h);
        d.record_lod = true;
        for threads in 1..=7 {
            let out = run_with_threads(&c, &d, threads).unwrap();
            let (lo, hi) = out.gradients[0]
                .lod
                .unwrap_or_else(|| panic!("{w}x{h}, {threads} threads: no LOD recorded"));
            for l in [lo, hi] {
                assert!(
                    (l as f64 - expected).abs() < 1e-4,
                    "{w}x{h}, {threads} threads: λ {l} against {expected}"
                );
            }
            let quads = u64::from(w.div_ceil(2) * h.div_ceil(2));
            assert_eq!(out.gradients[0].quads, quads, "{w}x{h}, {threads} threads");
        }
    }
}

#[test]
fn small_targets_split_over_threads_with_identical_results() {
    let texels: Vec<[f32; 4]> = (0..15).map(|i| [i as f32 * 0.3, 0.5, 0.25, 1.0]).collect();
    let c = compiled(BUSY);
    // 11×8 is pass 1's target shape: 24 quads, 2 full batches on one
    // thread (16 + 8 quads), cut into 12 + 12, 8 + 8 + 8, four of 6... on more;
    // 10×8 (20 quads) into 10 + 10, batches whose lanes end mid-vector of
    // 16 (40 lanes).
    for (w, h) in [(11, 8), (10, 8), (3, 3), (1, 1), (17, 2)] {
        let d = busy_draw(&texels, w, h);
        let one = run_with_threads(&c, &d, 1).unwrap();
        for threads in 2..=7 {
            let other = run_with_threads(&c, &d, threads).unwrap();
            assert!(same_bits(&one, &other), "{w}x{h}: {threads} threads differ");
        }
    }
    assert_eq!(batch_quads(24, 1), 16);
    assert_eq!(batch_quads(24, 2), 12);
    assert_eq!(batch_quads(24, 3), 8);
    assert_eq!(batch_quads(24, 4), 6);
    assert_eq!(batch_quads(24, 8), 4);
    assert_eq!(batch_quads(20, 2), 10);
    assert_eq!(batch_quads(1, 4), 2);
    assert_eq!(batch_quads(10_000, 2), 16);
}

#[test]
fn results_are_identical_for_any_thread_count() {
    let texels: Vec<[f32; 4]> = (0..15)
        .map(|i| {
            let f = i as f32;
            [f * 0.1, 1.0 - f * 0.05, f * f * 0.01, 0.5]
        })
        .collect();
    let c = compiled(BUSY);
    let d = busy_draw(&texels, 37, 23);
    let one = run_with_threads(&c, &d, 1).unwrap();
    assert!(
        one.executed.iter().any(|&n| n != one.executed[0]),
        "diverges"
    );
    for threads in [2, 3, 0] {
        let other = run_with_threads(&c, &d, threads).unwrap();
        assert!(same_bits(&one, &other), "{threads} threads differ");
    }
    // Each pixel is independent of the target size it is rendered in.
    let small = run_with_threads(&c, &busy_draw(&texels, 5, 4), 2).unwrap();
    for y in 0..4 {
        for x in 0..5 {
            let (i, j) = (y * 5 + x, y * 37 + x);
            assert_eq!(small.executed[i], one.executed[j]);
            assert_eq!(
                bits(small.color[0].as_ref().unwrap()[i]),
                bits(one.color[0].as_ref().unwrap()[j])
            );
        }
    }
}

/// A target of more than one chunk of batches (16,761 quads: 1,048 batches
/// of 16), odd in both sizes, with lanes leaving early three ways: every
/// pixel, count and quad lands where it belongs, on any thread count.
#[test]
fn every_pixel_of_a_large_target_lands_in_place() {
    let text = "dcl vPos.xy
         def c0, 0.25, -0.5, 0, 1
         def c1, 2, 0, 0, 0
         mul r0.xy, vPos, c0.x
         frc r1.xy, r0
         mov r3, c0.zzzw
         mov r3.xy, vPos
         if_lt r1.y, c0.x
           mov oC0, -r3
           ret
         endif
         add r2, r1.x, c0.y
         texkill r2
         mov r3.z, c1.x
         mov oC0, r3";
    let c = compiled(text);
    let (w, h) = (301u32, 221u32);
    let d = Draw::new(w, h);
    let one = run_with_threads(&c, &d, 1).unwrap();
    let color = one.color[0].as_ref().unwrap();
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            let (xf, yf) = (x as f32, y as f32);
            // Rows y % 4 = 0 return early; elsewhere x % 4 < 2 is killed.
            let (want, killed) = if y % 4 == 0 {
                ([-xf, -yf, -0.0, -1.0], false)
            } else if x % 4 < 2 {
                ([0.0; 4], true)
            } else {
                ([xf, yf, 2.0, 1.0], false)
            };
            assert_eq!(bits(color[i]), bits(want), "pixel ({x}, {y})");
            assert_eq!(one.killed[i], killed, "pixel ({x}, {y})");
        }
    }
    // A quad diverges where its top row returns and its bottom row goes
    // on (quad rows 0, 2, 4...); killing takes whole quads (x = 2k, 2k + 1).
    assert_eq!(one.quad_executed.len(), 151 * 111);
    assert!(one.quad_executed.iter().all(|&n| n > 0));
    for (q, &divergent) in one.quad_divergent.iter().enumerate() {
        assert_eq!(divergent, (q / 151) % 2 == 0, "quad {q}");
    }
    for threads in [2, 3] {
        let other = run_with_threads(&c, &d, threads).unwrap();
        assert!(same_bits(&one, &other), "{threads} threads differ");
        assert_eq!(one.quad_executed, other.quad_executed);
        assert_eq!(one.quad_divergent, other.quad_divergent);
    }
}

#[test]
fn partial_batches_cover_odd_targets() {
    let text = "dcl vPos.xy
         mov oC0, vPos";
    for (w, h) in [(1, 1), (3, 5), (11, 8), (10, 19), (33, 1)] {
        let out = run_text(text, &Draw::new(w, h));
        let c = out.color[0].as_ref().unwrap();
        for y in 0..h {
            for x in 0..w {
                let p = c[(y * w + x) as usize];
                assert_eq!((p[0], p[1]), (x as f32, y as f32));
            }
        }
        assert!(out.executed.iter().all(|&n| n == 1));
    }
    let out = run_text(text, &Draw::new(0, 7));
    assert!(out.executed.is_empty());
}

#[test]
fn executed_limit_names_the_pixel() {
    let text = "dcl_texcoord0 v0
         defi i0, 200, 0, 0, 0
         def c0, 1, 0, 0, 0
         mov r0, c0.y
         rep i0
           add r0, r0, c0.x
           break_gt r0.x, v0.x
         endrep
         mov oC0, r0";
    let c = compiled(text);
    // Pixel x runs k = x + 1 iterations: 1 + 7k + 2(k - 1) + 1 = 9k slots.
    let mut d = pos_draw(100, 3);
    d.limits.max_executed_per_pixel = 1202;
    let out = run(&c, &d).unwrap();
    assert_eq!(out.executed[99], 900);
    d.target_width = 160;
    for threads in [1, 2] {
        let err = run_with_threads(&c, &d, threads).unwrap_err();
        match err {
            EmuError::ExecutedLimit { x, y, limit, .. } => {
                assert_eq!((x, y, limit), (133, 0, 1202)); // 9 * 134 > 1202
            }
            other => panic!("unexpected {other}"),
        }
        assert!(err.to_string().contains("pixel (133, 0)"));
    }
}

#[test]
fn draw_errors_are_typed() {
    let c = compiled("dcl_texcoord0 v0\ndcl_2d s0\ntexld r0, v0, s0\nmov oC0, r0");
    let tex = [[0.0f32; 4]; 4];
    let good = |d: &mut Draw| {
        d.inputs = vec![(0, LinearInput::default())];
    };
    let mut d = Draw::new(2, 2);
    assert_eq!(
        run(&c, &d).unwrap_err(),
        EmuError::MissingInput {
            input: 0,
            register: "v0".into()
        }
    );
    good(&mut d);
    d.inputs.push((1, LinearInput::default()));
    assert_eq!(
        run(&c, &d).unwrap_err(),
        EmuError::InputNotDeclared {
            input: 1,
            register: "v1".into()
        }
    );
    good(&mut d);
    d.samplers.push((
        3,
        Texture {
            width: 2,
            height: 2,
            texels: &tex,
        }
        .into(),
        SamplerState::default(),
    ));
    assert_eq!(
        run(&c, &d).unwrap_err(),
        EmuError::SamplerNotDeclared { sampler: 3 }
    );
    d.samplers = vec![(
        0,
        Texture {
            width: 3,
            height: 2,
            texels: &tex,
        }
        .into(),
        SamplerState::default(),
    )];
    assert!(matches!(
        run(&c, &d).unwrap_err(),
        EmuError::InvalidTexture { sampler: 0, .. }
    ));
    d.samplers.clear();
    d.limits.max_target_pixels = 3;
    let e = run(&c, &d).unwrap_err();
    assert!(matches!(e, EmuError::TargetTooLarge { .. }));
    assert!(e.to_string().contains("2x2"));
    d.limits = EmuLimits::default();
    d.constants.float = vec![[0.0; 4]; 225];
    assert!(matches!(
        run(&c, &d).unwrap_err(),
        EmuError::TooManyConstants { .. }
    ));
    // Unbound but declared sampler is fine.
    d.constants.float.clear();
    assert_eq!(
        run(&c, &d).unwrap().color[0].as_ref().unwrap()[0],
        [0.0, 0.0, 0.0, 1.0]
    );
    // A 2D texture on a cube sampler is refused.
    let cube = compiled("dcl_cube s1\ntexld r0, c0, s1\nmov oC0, r0");
    let mut d = Draw::new(1, 1);
    d.samplers.push((
        1,
        Texture {
            width: 2,
            height: 2,
            texels: &tex,
        }
        .into(),
        SamplerState::default(),
    ));
    assert!(matches!(
        run(&cube, &d).unwrap_err(),
        EmuError::SamplerTypeMismatch { sampler: 1, .. }
    ));
}

#[test]
fn application_int_and_bool_constants() {
    let text = "def c0, 1, 0, 0, 0
         mov r0, c0.y
         rep i1
           add r0.x, r0.x, c0.x
         endrep
         if b3
           add r0.y, r0.y, c0.x
         endif
         defb b4, true
         if !b4
           add r0.z, r0.z, c0.x
         endif
         mov oC0, r0";
    let mut d = Draw::new(1, 1);
    d.constants.int = vec![[0; 4], [7, 0, 0, 0]];
    d.constants.bool = vec![false, false, false, true, false];
    let out = run_text(text, &d);
    assert_eq!(out.color[0].as_ref().unwrap()[0], [7.0, 1.0, 0.0, 0.0]);
}

#[test]
fn compile_errors_are_typed() {
    let e = compile(&shader("dcl_texcoord0 v8\nm4x4 r0, c0, v8\nmov oC0, r0")).unwrap_err();
    assert!(matches!(e, EmuError::Malformed { index: 0, .. }), "{e}");
    let e = compile(&shader("texld r0, c0, s2\nmov oC0, r0")).unwrap_err();
    assert_eq!(
        e,
        EmuError::MissingSamplerDecl {
            index: 0,
            sampler: 2
        }
    );
    assert!(e.to_string().contains("s2"));
    // Info that does not describe the program.
    let p = super::testasm::program("mov oC0, c0");
    let bad = crate::core::ir::Shader::new_validated(p, crate::core::ir::Info::default());
    assert!(matches!(
        compile(&bad).unwrap_err(),
        EmuError::Malformed { .. }
    ));
}

// ----- timing (run with --release --ignored --nocapture) --------------------

/// The typical luminance workload: rep 128 around 125 unrolled
/// texld/dp4/log/add groups, ~64.7k executed slots per pixel.
fn heavy_text(copies: usize) -> String {
    let mut t = String::from(
        "dcl_texcoord0 v0.xy
         dcl_2d s0
         def c0, 0, 0.001, 0, 0
         def c1, 0.2126, 0.7152, 0.0722, 0
         def c2, 0.0001, 0, 0, 0
         defi i0, 128, 0, 0, 0
         mov r0, c0.x
         mov r1, v0
         rep i0\n",
    );
    for k in 0..copies {
        let dst = if k % 2 == 0 { "r2" } else { "r4" };
        t += &format!(
            "texld {dst}, r1, s0\ndp4 r3.x, {dst}, c1\nlog r3.y, r3.x\nadd r0.x, r0.x, r3.y\n"
        );
    }
    t += "add r1.xy, r1, c0.y\nendrep\nmov oC0, r0\n";
    t
}

/// Nested reps (32 × 16) around a few texture reads and arithmetic.
fn nested_text() -> String {
    String::from(
        "dcl_texcoord0 v0.xy
         dcl_2d s0
         def c0, 0, 0.002, 0.5, 1
         def c1, 0.2126, 0.7152, 0.0722, 0
         defi i0, 32, 0, 0, 0
         defi i1, 16, 0, 0, 0
         mov r0, c0.x
         mov r1, v0
         rep i0
           rep i1
             texld r2, r1, s0
             dp3 r3.x, r2, c1
             mad r3.y, r3.x, c0.z, c0.w
             log r3.z, r3.y
             add r0.x, r0.x, r3.z
             add r1.xy, r1, c0.y
           endrep
           mul r0.y, r0.x, c0.z
         endrep
         mov oC0, r0",
    )
}

/// Prints the draw's best time over 30 runs on one and two threads, and
/// its throughput (minimum over runs: the machine may be shared).
fn print_speed(label: &str, c: &Compiled, d: &Draw) {
    for threads in [1, 2] {
        let mut dt = std::time::Duration::MAX;
        let mut out = None;
        for _ in 0..30 {
            let t = std::time::Instant::now();
            out = Some(run_with_threads(c, d, threads).unwrap());
            dt = dt.min(t.elapsed());
        }
        let out = out.unwrap();
        let slots: u64 = out.executed.iter().sum();
        println!(
            "{label}{threads} thread(s): {:?} per draw, {} slots/pixel, {:.1} M slot-lanes/s",
            dt,
            out.executed[0],
            slots as f64 / dt.as_secs_f64() / 1e6
        );
    }
}

#[test]
#[ignore]
fn perf_nested_workload() {
    let c = compiled(&nested_text());
    let texels: Vec<[f32; 4]> = (0..64 * 64)
        .map(|i| [(i % 5) as f32 * 0.2 + 0.01, 0.5, 0.25, 1.0])
        .collect();
    let d = textured(
        10,
        19,
        LinearInput {
            base: [0.0; 4],
            ddx: [0.1, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / 19.0, 0.0, 0.0],
        },
        Texture {
            width: 64,
            height: 64,
            texels: &texels,
        },
        SamplerState::default(),
    );
    print_speed("nested, ", &c, &d);
}

#[test]
#[ignore]
fn perf_heavy_workload() {
    let c = compiled(&heavy_text(125));
    let texels: Vec<[f32; 4]> = (0..64 * 64)
        .map(|i| [(i % 7) as f32 * 0.1 + 0.01, 0.5, 0.25, 1.0])
        .collect();
    let d = textured(
        11,
        8,
        LinearInput {
            base: [0.0, 0.0, 0.0, 0.0],
            ddx: [1.0 / 11.0, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / 8.0, 0.0, 0.0],
        },
        Texture {
            width: 64,
            height: 64,
            texels: &texels,
        },
        SamplerState::default(),
    );
    print_speed("", &c, &d);
}

#[test]
fn helper_lanes_follow_their_own_flow_control() {
    // A 3×1 target: pixel (2, 0)'s quad has helpers (3, 0), (2, 1), (3, 1).
    // The branch makes lanes diverge; the helper at x = 3 still computes
    // inside the branch, so dsx of the edge quad is the same as it would be
    // in a 4-wide target. A second, unrelated quad diverging differently must
    // not change that.
    let text = "dcl_texcoord0 v0
         def c0, 1.5, 0, 0, 0
         mov r0, c0.y
         if_gt v0.x, c0.x
           mul r0.x, v0.x, v0.x
         endif
         dsx r1, r0
         mov oC0, r1";
    let narrow = run_text(text, &pos_draw(3, 1));
    let wide = run_text(text, &pos_draw(4, 1));
    assert_eq!(narrow.color[0].as_ref().unwrap()[2][0], 9.0 - 4.0);
    assert_eq!(wide.color[0].as_ref().unwrap()[2][0], 9.0 - 4.0);
    assert_eq!(narrow.executed, wide.executed[..3]);
}

#[test]
fn log2_is_within_one_ulp() {
    use super::math::log;
    // Distance in ulps between an f32 and the exact (f64) value.
    fn ulps(got: f32, exact: f64) -> f64 {
        let e = exact as f32;
        let ulp = (f32::from_bits(e.abs().to_bits() + 1) - e.abs()) as f64;
        (got as f64 - exact).abs() / ulp
    }
    let mut worst = 0.0f64;
    let mut state = 0x1234_5678_9abc_def0u64;
    let mut check = |x: f32| {
        let got = log(x);
        let exact = (x.abs() as f64).log2();
        let u = ulps(got, exact);
        assert!(u <= 1.0, "log({x:e}) = {got:e}, exact {exact:e}, {u} ulp");
        worst = worst.max(u);
    };
    for _ in 0..200_000 {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let bits = (state >> 33) as u32 & 0x7f7f_ffff;
        if bits != 0 {
            check(f32::from_bits(bits));
        }
    }
    // Around 1, where the result is small, and subnormals.
    for i in 1..20_000u32 {
        check(f32::from_bits(0x3f80_0000 + i));
        check(f32::from_bits(0x3f80_0000 - i));
        check(f32::from_bits(i * 419));
    }
    for e in -149..128i32 {
        let p = if e >= -126 {
            f32::from_bits(((e + 127) as u32) << 23)
        } else {
            f32::from_bits(1 << (e + 149))
        };
        assert_eq!(log(p), e as f32, "log(2^{e})");
    }
    assert_eq!(log(1.0).to_bits(), 0);
    assert_eq!(log(f32::INFINITY), f32::INFINITY);
    assert!(log(f32::NAN).is_nan());
    assert!(worst > 0.0);
    println!("log2: worst error {worst:.3} ulp");
}

#[test]
fn texld_into_outputs_and_inside_divergent_branches() {
    let tex = [[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]];
    let text = "dcl_texcoord0 v0
         dcl_2d s0
         def c0, 0.5, 0, 0, 0
         def c1, 9, 9, 9, 9
         texld oC2, v0, s0
         mov r0, c1
         if_lt v0.x, c0.x
           texld r0, v0, s0
         endif
         mov oC0, r0";
    let d = textured(
        4,
        1,
        LinearInput {
            base: [0.125, 0.5, 0.0, 0.0],
            ddx: [0.25, 0.0, 0.0, 0.0],
            ddy: [0.0; 4],
        },
        Texture {
            width: 2,
            height: 1,
            texels: &tex,
        },
        SamplerState::default(),
    );
    let out = run_text(text, &d);
    let c2 = out.color[2].as_ref().unwrap();
    assert_eq!(c2, &vec![tex[0], tex[0], tex[1], tex[1]]);
    let c0 = out.color[0].as_ref().unwrap();
    assert_eq!(c0, &vec![tex[0], tex[0], [9.0; 4], [9.0; 4]]);
}

#[test]
fn hardware_rules_flush_denormals_and_zero_products() {
    use crate::core::float_rules::FloatRules;
    // c0.x is the smallest denormal (2^-149), c0.y = 2^-126 (the smallest
    // normal), c0.z = +inf, c0.w = 0. By hand: under `hardware` the denormal
    // constant reads as 0; 2^-126 × 0.5 = 2^-127 is a denormal result,
    // written as 0; 0 × inf = 0. Under `d3d9` all three keep IEEE values.
    let text = "mov r0.x, c0.x
                mov r1, c1
mul r0.y, c0.y, r1.x
                mul r0.z, c0.z, c0.w
                mov r0.w, c1.x
                mov oC0, r0";
    let mut d = Draw::new(1, 1);
    d.constants.float = vec![
        [f32::from_bits(1), f32::MIN_POSITIVE, f32::INFINITY, 0.0],
        [0.5, 0.0, 0.0, 0.0],
    ];
    d.float_rules = FloatRules::Hardware;
    let hw = run_text(text, &d).color[0].as_ref().unwrap()[0];
    assert_eq!(hw.map(f32::to_bits), [0, 0, 0, 0.5f32.to_bits()]);
    d.float_rules = FloatRules::D3d9;
    let ms = run_text(text, &d).color[0].as_ref().unwrap()[0];
    assert_eq!(ms[0].to_bits(), 1);
    assert_eq!(ms[1].to_bits(), 1 << 22, "2^-127 as a denormal");
    assert!(ms[2].is_nan());
}

#[test]
fn hardware_rules_flush_products_inside_mad_and_dot_products() {
    use crate::core::float_rules::FloatRules;
    // c0 = (2^-70, 2^-70, 2^-126, 0): the product 2^-140 is a denormal.
    // By hand: `mad r0.x, c0.x, c0.y, c0.z` is 2^-126 + 2^-140 under `d3d9`
    // (exact: 2^-126·(1 + 2^-14) has 15 significant bits) and 2^-126 under
    // `hardware`, whose product is flushed before the add. `dp3 r0.y, c0,
    // c1` with c1 = (2^-70, 0, 1, 0) is 2^-140 + 0 + 2^-126: the same two
    // values. `dp2add r0.z, c0, c0, c0.z` is 2·2^-140 + 2^-126 under
    // `d3d9`, 2^-126 under `hardware`. `m3x2 r1.xy, c0, c1` is dp3 with c1
    // and with c2 = (0, 2^-70, 0, 0): 2^-140 alone, 0 under `hardware`.
    let text = "mad r0.x, c0.x, c0.y, c0.z
                dp3 r0.y, c0, c1
                dp2add r0.z, c0, c0, c0.z
                mov r0.w, c1.z
                m3x2 r1.xy, c0, c1
                mov r1.zw, c1.z
                mov oC0, r0
                mov oC1, r1";
    let p70 = 2f32.powi(-70);
    let p126 = f32::MIN_POSITIVE;
    let mut d = Draw::new(1, 1);
    d.constants.float = vec![
        [p70, p70, p126, 0.0],
        [p70, 0.0, 1.0, 0.0],
        [0.0, p70, 0.0, 0.0],
    ];
    let p140 = f64::powi(2.0, -140);
    let exact = |v: f64| v as f32;
    d.float_rules = FloatRules::D3d9;
    let out = run_text(text, &d);
    let ms = out.color[0].as_ref().unwrap()[0];
    assert_eq!(ms[0], exact(f64::from(p126) + p140));
    assert_eq!(ms[1], exact(f64::from(p126) + p140));
    assert_eq!(ms[2], exact(f64::from(p126) + 2.0 * p140));
    let ms1 = out.color[1].as_ref().unwrap()[0];
    assert_eq!(
        [ms1[0], ms1[1]],
        [exact(f64::from(p126) + p140), exact(p140)]
    );
    d.float_rules = FloatRules::Hardware;
    let out = run_text(text, &d);
    let hw = out.color[0].as_ref().unwrap()[0];
    let p126_bits = p126.to_bits();
    assert_eq!(
        hw.map(f32::to_bits),
        [p126_bits, p126_bits, p126_bits, 1f32.to_bits()]
    );
    let hw1 = out.color[1].as_ref().unwrap()[0];
    assert_eq!([hw1[0].to_bits(), hw1[1].to_bits()], [p126_bits, 0]);
}
