// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float fadeScale : register(c0);
sampler2D sprite : register(s0);
sampler2D sceneDepth : register(s1);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0, out precise float4 oC0 : COLOR0, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    oC0 = 0;
    oDepth = 0;
    r0 = tex2Dproj(sceneDepth, texcoord1);
    r2.xy = texcoord0.xy * 2.0 - 1.0;
    r2.x = max((dot(r2.xy, -r2.xy) + 1.0), 0.0);
    r0.y = (1.0 / rsqrt(abs(r2.x))) * 0.01;
    r0.z = 1.0 / texcoord1.w;
    r0.y = texcoord1.z * r0.z - r0.y;
    oDepth = r0.y;
    r0.x = saturate((r0.x - r0.y) * fadeScale);
    oC0 = (r0.x * (tex2D(sprite, texcoord0.xy) * color0));
}
