// ps_3_0 shader decompiled by ps30
float lutBlend : register(c1);
float lutSize : register(c0);
sampler2D sceneTex : register(s0);
sampler3D gradingLUT : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = lutSize - 1.0;
    r0.y = 1.0 / lutSize;
    r0.x = r0.y * r0.x;
    r0.y = r0.y * 0.5;
    r1 = tex2D(sceneTex, texcoord0.xy);
    r0 = tex3D(gradingLUT, (saturate(r1.xyz) * r0.x + r0.y));
    oC0.xyz = lutBlend * (r0.xyz - r1.xyz) + r1.xyz;
    oC0.w = r1.w;
    return oC0;
}
