//! Front end and cost model speed: assembling the article's unrolled listing
//! (REPEAT_BLOCK expansion to 500 instructions, validation) and analysing it.
//! The symbolic count must not depend on iteration counts: compare
//! `analyse/i2=1` with `analyse/i2=255`.

use criterion::{criterion_group, criterion_main, Criterion};
use ps30::core::cost::{analyse, Environment, Profile};
use ps30::core::load::{load_str, Options};
use std::hint::black_box;

const UNROLLED: &str = include_str!("../asm/article/lum_pass1_unrolled.psh");

fn front_end(c: &mut Criterion) {
    c.bench_function("load/unrolled", |b| {
        b.iter(|| load_str("unrolled.psh", black_box(UNROLLED), &Options::default()).unwrap())
    });
    let loaded = load_str("unrolled.psh", UNROLLED, &Options::default()).unwrap();
    for i2 in [1, 255] {
        let mut env = Environment::default();
        env.ints.insert(2, [i2, 0, 0, 0]);
        c.bench_function(&format!("analyse/i2={i2}"), |b| {
            b.iter(|| {
                analyse(
                    &loaded.shader,
                    &loaded.file,
                    black_box(&env),
                    &Profile::ps_3_0(),
                )
                .unwrap()
            })
        });
    }
}

criterion_group!(benches, front_end);
criterion_main!(benches);
