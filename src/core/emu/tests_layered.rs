//! Unit tests of cube and volume sampling through whole draws: face
//! selection on each face and on ties, clamping at face edges, per-face
//! mips through texldl, volume point and trilinear filtering. Expected
//! values are worked out by hand beside each test.

use super::testasm::shader;
use super::*;
use crate::core::image::VolumeLevel;

/// oC0 of a one-pixel draw of `text` with c0 = `c0` and `tex` on s0.
fn one_pixel(text: &str, c0: [f32; 4], tex: TextureLevels, state: SamplerState) -> [f32; 4] {
    let compiled = compile(&shader(text)).expect("compiles");
    let mut d = Draw::new(1, 1);
    d.constants.float = vec![c0];
    d.samplers.push((0, tex, state));
    run(&compiled, &d).expect("runs").color[0].as_ref().unwrap()[0]
}

/// A cube whose face f, level m, texel (x, y) is (f, m, x, y), `edge`
/// texels a side with `levels` levels.
fn labelled_cube(edge: u32, levels: usize) -> CubeMap {
    let faces = (0..6)
        .map(|f| {
            let chain = (0..levels)
                .map(|m| {
                    let e = (edge >> m).max(1);
                    let texels = (0..e * e)
                        .map(|i| [f as f32, m as f32, (i % e) as f32, (i / e) as f32])
                        .collect();
                    (e, e, texels)
                })
                .collect();
            MipChain::from_levels(chain).unwrap()
        })
        .collect();
    CubeMap::from_faces(faces).unwrap()
}

const CUBE: &str = "dcl_cube s0
     texld r0, c0, s0
     mov oC0, r0";

#[test]
fn every_face_and_its_table_coordinates() {
    let cube = labelled_cube(4, 1);
    // (direction, face, texel x, texel y): texel = ⌊s·4⌋, ⌊t·4⌋ with
    // s = (sc/|ma| + 1)/2 from the table in layered.rs.
    let cases = [
        // +X: sc = −z, tc = −y. z = 0.5 → s = 0.25 → x 1; y = −0.5 → t = 0.75 → y 3.
        ([1.0, -0.5, 0.5], 0, 1.0, 3.0),
        // −X: sc = +z → s = 0.75 → x 3; tc = −y = −0.5 → t 0.25 → y 1.
        ([-1.0, 0.5, 0.5], 1, 3.0, 1.0),
        // +Y: sc = +x = 0.5 → x 3; tc = +z = −0.5 → y 1.
        ([0.5, 1.0, -0.5], 2, 3.0, 1.0),
        // −Y: sc = +x = 0.5 → x 3; tc = −z = −0.5 → y 1.
        ([0.5, -1.0, 0.5], 3, 3.0, 1.0),
        // +Z: sc = +x = −0.5 → x 1; tc = −y = −0.5 → y 1.
        ([-0.5, 0.5, 1.0], 4, 1.0, 1.0),
        // −Z: sc = −x = −0.5 → x 1; tc = −y = 0.5 → y 3.
        ([0.5, -0.5, -1.0], 5, 1.0, 3.0),
    ];
    for (p, face, x, y) in cases {
        let got = one_pixel(
            CUBE,
            [p[0], p[1], p[2], 0.0],
            TextureLevels::Cube(&cube),
            SamplerState::default(),
        );
        assert_eq!(got, [face as f32, 0.0, x, y], "{p:?}");
    }
}

#[test]
fn ties_pick_z_then_y_and_scale_does_not_matter() {
    let cube = labelled_cube(4, 1);
    for (p, face) in [
        ([1.0, 1.0, 1.0], 4.0),
        ([-2.0, 2.0, -2.0], 5.0),
        ([3.0, -3.0, 1.0], 3.0),
        ([-1.0, 1.0, 0.0], 2.0),
    ] {
        let got = one_pixel(
            CUBE,
            [p[0], p[1], p[2], 0.0],
            TextureLevels::Cube(&cube),
            SamplerState::default(),
        );
        assert_eq!(got[0], face, "{p:?}");
    }
}

#[test]
fn bilinear_clamps_at_the_face_edge_whatever_the_address_mode() {
    // +Z face 2×2: left column 0, right column 1 (in .z of the label). At
    // s = 1 (x = 1, z = 1) the bilinear position is 2·1 − 0.5 = 1.5: taps
    // at x 1 and 2, 2 clamped to 1, so the result is column 1's value, not
    // a blend with column 0 (which WRAP would give).
    let cube = labelled_cube(2, 1);
    let state = SamplerState {
        address_u: Address::Wrap,
        address_v: Address::Wrap,
        ..SamplerState::filtered(Filter::Linear)
    };
    let got = one_pixel(
        CUBE,
        [1.0, 0.0, 1.0, 0.0],
        TextureLevels::Cube(&cube),
        state,
    );
    assert_eq!(got[0], 4.0);
    assert_eq!(got[2], 1.0);
}

#[test]
fn texldl_reads_each_faces_own_levels() {
    let cube = labelled_cube(8, 4);
    let text = "dcl_cube s0
         texldl r0, c0, s0
         mov oC0, r0";
    let state = SamplerState {
        mip_filter: MipFilter::Point,
        ..SamplerState::default()
    };
    for lod in 0..4 {
        let got = one_pixel(
            text,
            [0.0, -1.0, 0.0, lod as f32],
            TextureLevels::Cube(&cube),
            state,
        );
        assert_eq!((got[0], got[1]), (3.0, lod as f32), "lod {lod}");
    }
}

#[test]
fn a_2d_texture_on_a_cube_sampler_is_refused() {
    let compiled = compile(&shader(CUBE)).unwrap();
    let texels = [[0.0; 4]];
    let mut d = Draw::new(1, 1);
    d.samplers.push((
        0,
        Texture {
            width: 1,
            height: 1,
            texels: &texels,
        }
        .into(),
        SamplerState::default(),
    ));
    let e = run(&compiled, &d).unwrap_err().to_string();
    assert!(
        e.contains("declared dcl_cube") && e.contains("2D texture"),
        "{e}"
    );
}

/// A 2×2×2 volume whose texel (x, y, z) is x + 2y + 4z in .x.
fn counting_volume() -> VolumeChain {
    let texels = (0..8).map(|i| [i as f32, 0.0, 0.0, 1.0]).collect();
    VolumeChain::from_levels(vec![VolumeLevel {
        width: 2,
        height: 2,
        depth: 2,
        texels,
    }])
    .unwrap()
}

const VOLUME: &str = "dcl_volume s0
     texld r0, c0, s0
     mov oC0, r0";

#[test]
fn volume_point_addresses_three_axes() {
    let vol = counting_volume();
    for (p, want) in [
        ([0.25, 0.25, 0.25], 0.0),
        ([0.75, 0.25, 0.25], 1.0),
        ([0.25, 0.75, 0.25], 2.0),
        ([0.25, 0.25, 0.75], 4.0),
        ([0.75, 0.75, 0.75], 7.0),
        // WRAP on w: 1.25 → 0.25.
        ([0.75, 0.75, 1.25], 3.0),
    ] {
        let got = one_pixel(
            VOLUME,
            [p[0], p[1], p[2], 0.0],
            TextureLevels::Volume(&vol),
            SamplerState {
                address_u: Address::Wrap,
                address_v: Address::Wrap,
                address_w: Address::Wrap,
                ..SamplerState::default()
            },
        );
        assert_eq!(got[0], want, "{p:?}");
    }
}

#[test]
fn volume_linear_blends_eight_texels_and_address_w_is_its_own() {
    let vol = counting_volume();
    // At the centre (0.5, 0.5, 0.5) every weight is ½: the mean 3.5.
    let state = SamplerState {
        address_u: Address::Clamp,
        address_v: Address::Clamp,
        address_w: Address::Border,
        border: [100.0, 0.0, 0.0, 0.0],
        ..SamplerState::filtered(Filter::Linear)
    };
    let got = one_pixel(
        VOLUME,
        [0.5, 0.5, 0.5, 0.0],
        TextureLevels::Volume(&vol),
        state,
    );
    assert_eq!(got[0], 3.5);
    // w = 1: position 2·1 − 0.5 = 1.5, taps at slice 1 and 2 (border) by
    // ½: (slice-1 mean 5.5 + 100)/2 = 52.75.
    let got = one_pixel(
        VOLUME,
        [0.5, 0.5, 1.0, 0.0],
        TextureLevels::Volume(&vol),
        state,
    );
    assert_eq!(got[0], 52.75);
}

#[test]
fn volume_trilinear_blends_levels() {
    // Level 0: 2×2×2 of 0; level 1: 1×1×1 of 8. texldl at λ = 0.25 with
    // MIPFILTER LINEAR: 0·0.75 + 8·0.25 = 2.
    let vol = VolumeChain::from_levels(vec![
        VolumeLevel {
            width: 2,
            height: 2,
            depth: 2,
            texels: vec![[0.0; 4]; 8],
        },
        VolumeLevel {
            width: 1,
            height: 1,
            depth: 1,
            texels: vec![[8.0; 4]],
        },
    ])
    .unwrap();
    let text = "dcl_volume s0
         texldl r0, c0, s0
         mov oC0, r0";
    let state = SamplerState {
        mip_filter: MipFilter::Linear,
        ..SamplerState::filtered(Filter::Linear)
    };
    let got = one_pixel(
        text,
        [0.5, 0.5, 0.5, 0.25],
        TextureLevels::Volume(&vol),
        state,
    );
    assert_eq!(got[0], 2.0);
}

#[test]
fn cube_implicit_lod_comes_from_face_coordinates() {
    // A 2×2 target: directions (x, y, 1) with x = −0.75 + 0.5·px·k… here
    // the +Z face with s = (x + 1)/2, so ∂s/∂x = ½·ddx. With ddx = 0.5 on a
    // 8-texel edge, ∂s·E = 0.25·8 = 2 → λ = 1: level 1 under MIPFILTER POINT.
    let cube = labelled_cube(8, 4);
    let compiled = compile(&shader(
        "dcl_texcoord0 v0
         dcl_cube s0
         texld r0, v0, s0
         mov oC0, r0",
    ))
    .unwrap();
    let mut d = Draw::new(2, 2);
    d.inputs.push((
        0,
        LinearInput {
            base: [-0.25, -0.25, 1.0, 1.0],
            ddx: [0.5, 0.0, 0.0, 0.0],
            ddy: [0.0, 0.5, 0.0, 0.0],
        },
    ));
    d.samplers.push((
        0,
        TextureLevels::Cube(&cube),
        SamplerState {
            mip_filter: MipFilter::Point,
            min_filter: Filter::Point,
            ..SamplerState::default()
        },
    ));
    let out = run(&compiled, &d).unwrap();
    let c = out.color[0].as_ref().unwrap();
    for px in c {
        assert_eq!((px[0], px[1]), (4.0, 1.0), "{px:?}");
    }
}
