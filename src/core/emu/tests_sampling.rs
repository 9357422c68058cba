//! Unit tests of 2D sampling through whole draws: the address modes under
//! point and linear filtering, point sampling at texel centres, `texldp`,
//! the sampler swizzle and an unbound sampler. Expected values are worked
//! out by hand beside each test.

use super::tests::run_text;
use super::*;

/// A 4×1 texture whose texel i is (i + 1, 0, 0, 1).
const ROW4: [[f32; 4]; 4] = [
    [1.0, 0.0, 0.0, 1.0],
    [2.0, 0.0, 0.0, 1.0],
    [3.0, 0.0, 0.0, 1.0],
    [4.0, 0.0, 0.0, 1.0],
];

fn sample_row4(u: f32, filter: Filter, mode: Address) -> f32 {
    let text = "dcl_2d s0
         texld r0, c0, s0
         mov oC0, r0";
    let mut d = Draw::new(1, 1);
    d.constants.float = vec![[u, 0.5, 0.0, 1.0]];
    d.samplers.push((
        0,
        Texture {
            width: 4,
            height: 1,
            texels: &ROW4,
        }
        .into(),
        SamplerState {
            address_u: mode,
            address_v: mode,
            address_w: mode,
            border: [10.0, 0.0, 0.0, 0.0],
            ..SamplerState::filtered(filter)
        },
    ));
    run_text(text, &d).color[0].as_ref().unwrap()[0][0]
}

#[test]
fn address_modes_point() {
    use Address::*;
    let us = [-0.1, 0.0, 1.0, 1.1];
    let table = [
        (Wrap, [4.0, 1.0, 1.0, 1.0]),
        (Mirror, [1.0, 1.0, 4.0, 4.0]),
        (Clamp, [1.0, 1.0, 4.0, 4.0]),
        (Border, [10.0, 1.0, 10.0, 10.0]),
        (MirrorOnce, [1.0, 1.0, 4.0, 4.0]),
    ];
    for (mode, want) in table {
        for (u, w) in us.iter().zip(want) {
            assert_eq!(sample_row4(*u, Filter::Point, mode), w, "{mode:?} u={u}");
        }
    }
}

#[test]
fn address_modes_linear() {
    use Address::*;
    let us = [-0.1, 0.0, 1.0, 1.1];
    // u' = 4u - 0.5: taps (-1, 0) w 0.1; (-1, 0) w 0.5; (3, 4) w 0.5; (3, 4) w 0.9.
    let table = [
        (Wrap, [3.7, 2.5, 2.5, 1.3]),
        (Mirror, [1.0, 1.0, 4.0, 4.0]),
        (Clamp, [1.0, 1.0, 4.0, 4.0]),
        (Border, [9.1, 5.5, 7.0, 9.4]),
        (MirrorOnce, [1.0, 1.0, 4.0, 4.0]),
    ];
    for (mode, want) in table {
        for (u, w) in us.iter().zip(want) {
            let got = sample_row4(*u, Filter::Linear, mode);
            assert!((got - w).abs() < 1e-5, "{mode:?} u={u}: {got} != {w}");
        }
    }
}

#[test]
fn point_sampling_hits_texel_centres() {
    // 4×3 texture, texel (x, y) = (x, y, x + 10y, 1); one pixel per texel.
    let texels: Vec<[f32; 4]> = (0..12)
        .map(|i| {
            let (x, y) = ((i % 4) as f32, (i / 4) as f32);
            [x, y, x + 10.0 * y, 1.0]
        })
        .collect();
    let text = "dcl_texcoord0 v0.xy
         dcl_2d s0
         texld r0, v0, s0
         mov oC0, r0";
    let mut d = Draw::new(4, 3);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.125, 1.0 / 6.0, 0.0, 0.0],
            ddx: [0.25, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / 3.0, 0.0, 0.0],
        },
    ));
    for filter in [Filter::Point, Filter::Linear] {
        d.samplers = vec![(
            0,
            Texture {
                width: 4,
                height: 3,
                texels: &texels,
            }
            .into(),
            SamplerState::filtered(filter),
        )];
        let out = run_text(text, &d);
        let c = out.color[0].as_ref().unwrap();
        for (i, t) in texels.iter().enumerate() {
            for k in 0..4 {
                assert!(
                    (c[i][k] - t[k]).abs() < 1e-5,
                    "{filter:?} pixel {i}: {:?}",
                    c[i]
                );
            }
        }
        if filter == Filter::Point {
            assert_eq!(c, &texels);
        }
    }
}

#[test]
fn texldp_sampler_swizzle_and_unbound_sampler() {
    let text = "dcl_2d s0
         dcl_2d s1
         texldp r0, c0, s0.yxwz
         texld r1, c0, s1
         mov oC0, r0
         mov oC1, r1";
    let tex = [[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]];
    let mut d = Draw::new(1, 1);
    // (0.5, 1) would hit texel 1; divided by w = 2 it hits texel 0.
    d.constants.float = vec![[0.5, 1.0, 0.0, 2.0]];
    d.samplers.push((
        0,
        Texture {
            width: 2,
            height: 1,
            texels: &tex,
        }
        .into(),
        SamplerState::default(),
    ));
    let out = run_text(text, &d);
    assert_eq!(out.color[0].as_ref().unwrap()[0], [2.0, 1.0, 4.0, 3.0]);
    assert_eq!(out.color[1].as_ref().unwrap()[0], [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn point_sampling_at_texel_boundaries() {
    // u·n exactly on a boundary belongs to the texel on its right; just
    // below it to the left one.
    let below = |u: f32| f32::from_bits(u.to_bits() - 1);
    for (u, want) in [
        (0.25, 2.0),
        (below(0.25), 1.0),
        (0.5, 3.0),
        (below(0.5), 2.0),
        (0.75, 4.0),
        (below(1.0), 4.0),
        (-0.0, 1.0),
        (-f32::MIN_POSITIVE, 10.0),
        // NaN is read as 0 (docs/textures.md, "Non-finite coordinates"),
        // +∞ as 2: past the far edge, so the border colour.
        (f32::NAN, 1.0),
        (f32::INFINITY, 10.0),
        (1e30, 10.0),
    ] {
        assert_eq!(
            sample_row4(u, Filter::Point, Address::Border),
            want,
            "u={u:e}"
        );
    }
    assert_eq!(sample_row4(f32::NAN, Filter::Point, Address::Wrap), 1.0);
    assert_eq!(sample_row4(-1e30, Filter::Point, Address::Mirror), 1.0);
    assert_eq!(sample_row4(1e30, Filter::Linear, Address::Clamp), 4.0);
}
