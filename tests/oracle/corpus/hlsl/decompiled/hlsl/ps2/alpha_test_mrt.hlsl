// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float alphaRef : register(c0);
float farPlane : register(c1);
sampler2D leaves : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    r0 = tex2D(leaves, texcoord0.xy);
    r1 = r0.w - alphaRef;
    oC0 = r0;
    clip(r1);
    r0.xyz = normalize(texcoord1.xyz) * 0.5 + 0.5;
    r0.w = 1.0;
    oC1 = r0;
    oC2 = ((1.0 / farPlane) * texcoord2.x).xxxx;
}
