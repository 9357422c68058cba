// oracle: target=vs_2_0
// A vertex transform as games write it: the position by a float4x4, a diffuse term from the
// normal and a light direction into COLOR0, the texture coordinates scaled into TEXCOORD0.
float4x4 wvp : register(c0);
float3 light : register(c4);

struct VOut {
    float4 pos : POSITION;
    float4 col : COLOR0;
    float2 uv : TEXCOORD0;
};

VOut main(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {
    VOut o;
    o.pos = mul(p, wvp);
    o.col = saturate(dot(n, light));
    o.uv = uv * 2;
    return o;
}
