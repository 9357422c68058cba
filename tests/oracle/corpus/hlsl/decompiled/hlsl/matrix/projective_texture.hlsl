// ps_3_0 shader decompiled by ps30
float4x4 projectorViewProj : register(c0);
sampler2D projTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = mul(texcoord0, projectorViewProj);
    r1 = r0 * float4(0.5, -0.5, 1.0, 1.0) + (r0.w * float4(0.5, 0.5, 0.0, 0.0));
    oC0 = -r0.w >= 0.0 ? 0.0 : tex2Dproj(projTex, r1);
    return oC0;
}
