// Reinhard's tone map (asm/tonemap/reinhard.psh) written by hand in WGSL: the
// reference that ps30's translation of the same shader is measured against
// (`cargo bench --bench gpu`). The same computation: L̄w from s1 at c2.xy,
// k = c0.x / L̄w, Lw = dot(hdr.rgb, c1.rgb), the factor
// k · (1 + Lw · L̄w · c0.y) / (1 + k · Lw) (0 where Lw ≤ 0), the colour
// hdr.rgb · factor with hdr.a, saturated. The bindings are those the GPU
// backend gives the translation (`core/translate/interface.rs`).

struct Constants {
    c: array<vec4<f32>, 224>,
}

@group(0) @binding(0) var<uniform> k: Constants;
@group(0) @binding(1) var s0_texture: texture_2d<f32>;
@group(0) @binding(2) var s0_sampler: sampler;
@group(0) @binding(3) var s1_texture: texture_2d<f32>;
@group(0) @binding(4) var s1_sampler: sampler;
@group(0) @binding(40) var inputs: texture_2d_array<f32>;

@fragment
fn ps30_draw(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let v0 = textureLoad(inputs, vec2<i32>(position.xy - vec2(0.5)), 0, 0);
    let c0 = k.c[0];
    let lw_bar = textureSample(s1_texture, s1_sampler, k.c[2].xy).x;
    let scale = (1.0 / lw_bar) * c0.x;
    let white = lw_bar * c0.y;
    let hdr = textureSample(s0_texture, s0_sampler, v0.xy);
    let lw = dot(hdr.xyz, k.c[1].xyz);
    var factor = (lw * white + c0.w) * (1.0 / (lw * scale + c0.w)) * scale;
    if (-lw >= 0.0) {
        factor = c0.z;
    }
    return saturate(vec4(hdr.xyz * factor, hdr.w));
}
