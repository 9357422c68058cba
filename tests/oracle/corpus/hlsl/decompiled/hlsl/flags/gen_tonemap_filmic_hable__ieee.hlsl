// ps_3_0 shader decompiled by ps30
float exposure : register(c0);
sampler2D sceneTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = tex2D(sceneTex, texcoord0.xy).xyz * exposure;
    r1.xyz = r0.xyz * 0.15;
    r2.xyz = r1.xyz + 0.05;
    r1.xyz = r0.xyz * (r1.xyz + 0.5);
    r0.xyz = r0.xyz * r2.xyz;
    r1.xyz = r1.xyz + 0.06;
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    r0.xyz = (r0.xyz + 0.004) * r2.xyz;
    r0.xyz = (r0.xyz - 0.06666667) * 1.3790643;
    r1.x = log2(abs(r0.x));
    r1.y = log2(abs(r0.y));
    r1.z = log2(abs(r0.z));
    r0.xyz = r1.xyz * 0.45454547;
    oC0.x = exp2(r0.x);
    oC0.y = exp2(r0.y);
    oC0.z = exp2(r0.z);
    oC0.w = 1.0;
    return oC0;
}
