//! The GPU backend against the emulator on small draws.

#[path = "common/gpu.rs"]
mod gpu_device;

use gpu_device::gpu;
use ps30::core::emu::{self, Draw, LinearInput};
use ps30::core::gpu::{self as backend, TargetKind};
use ps30::core::load::{load_str, Options};

fn shader(src: &str) -> ps30::core::ir::Shader {
    load_str("test.psh", src, &Options::default())
        .unwrap()
        .shader
}

#[test]
fn inputs_and_vpos_arrive_as_the_emulator_computes_them() {
    let Some(g) = gpu("inputs_and_vpos_arrive_as_the_emulator_computes_them") else {
        return;
    };
    let s = shader("ps_3_0\ndcl_texcoord0 v0\ndcl vPos.xy\nmov oC0, v0\nmov oC1.xy, vPos\n");
    let mut d = Draw::new(7, 5);
    d.inputs.push((
        0,
        LinearInput {
            base: [0.1, 0.2, 0.3, 0.4],
            ddx: [1.0 / 3.0, 0.0, 1e-3, 2.0],
            ddy: [0.0, 1.0 / 7.0, 1e-3, -2.0],
        },
    ));
    let e = emu::run(&emu::compile(&s).unwrap(), &d).unwrap();
    let o = backend::run(g, &s, &d, TargetKind::Raw).unwrap();
    assert_eq!(o.color[0], e.color[0]);
    assert_eq!(
        o.color[1]
            .as_ref()
            .map(|c| c.iter().map(|p| [p[0], p[1]]).collect::<Vec<_>>()),
        e.color[1]
            .as_ref()
            .map(|c| c.iter().map(|p| [p[0], p[1]]).collect::<Vec<_>>())
    );
}
