// Luminance pass 1 (asm/corrected/lum_pass1_unrolled.psh) written by hand in
// WGSL: the reference that ps30's translation of the same shader is measured
// against (`cargo bench --bench gpu`). The same computation, sample for
// sample: for each of the block's i2.x rows, i1.x point samples of s0 one
// texel apart starting at v0.xy; each adds log2|dot(texel.rgb, c3.rgb) +
// c3.w²| to the sum (texel.w is replaced by c3.w, √δ, as the listing does
// with r1.w); oC0 is the sum in every channel. The bindings are those the
// GPU backend gives the translation (`core/translate/interface.rs`): the
// constant block at 0, s0 at 1 and 2, the draw's inputs at 40.

struct Constants {
    c: array<vec4<f32>, 224>,
    i: array<vec4<i32>, 16>,
}

@group(0) @binding(0) var<uniform> k: Constants;
@group(0) @binding(1) var s0_texture: texture_2d<f32>;
@group(0) @binding(2) var s0_sampler: sampler;
@group(0) @binding(40) var inputs: texture_2d_array<f32>;

@fragment
fn ps30_draw(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let v0 = textureLoad(inputs, vec2<i32>(position.xy - vec2(0.5)), 0, 0);
    let step = k.c[1].x;
    let dv = k.c[1].y;
    let w = k.c[3];
    var uv = v0.xy;
    var sum = 0.0;
    for (var row = 0; row < k.i[2].x; row++) {
        for (var col = 0; col < 125; col++) {
            let t = textureSample(s0_texture, s0_sampler, uv);
            sum += log2(abs(dot(vec4(t.xyz, w.w), w)));
            uv.x += step;
        }
        uv = vec2(v0.x, uv.y + dv);
    }
    return vec4(sum);
}
