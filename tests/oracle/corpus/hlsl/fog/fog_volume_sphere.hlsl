// Fog sphere: thickness of a sphere along the view ray, compared with scene depth.
sampler2D depthTexture : register(s0);
float4 sphere;          // xyz centre, w radius
float3 eye;
float4 fogTint;

float4 main(float4 scr : TEXCOORD0, float3 world : TEXCOORD1) : COLOR
{
    float3 d = normalize(world - eye);
    float3 oc = eye - sphere.xyz;
    float b = dot(oc, d);
    float c = dot(oc, oc) - sphere.w * sphere.w;
    float disc = b * b - c;
    clip(disc);
    float s = sqrt(disc);
    float t0 = max(-b - s, 0);
    float t1 = min(-b + s, tex2Dproj(depthTexture, scr).r);
    float thickness = max(t1 - t0, 0) / (2 * sphere.w);
    return float4(fogTint.rgb, fogTint.a * thickness * thickness);
}
