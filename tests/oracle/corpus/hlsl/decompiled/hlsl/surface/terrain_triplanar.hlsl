// ps_3_0 shader decompiled by ps30
float sharpness : register(c1);
float tiling : register(c0);
sampler2D cliff : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r1.x = log2(abs(r0.x));
    r1.y = log2(abs(r0.y));
    r1.z = log2(abs(r0.z));
    r0.xyz = r1.xyz * sharpness;
    r1.x = exp2(r0.x);
    r1.y = exp2(r0.y);
    r1.z = exp2(r0.z);
    r0.x = r1.z + (r1.y + r1.x);
    r0.xyz = (1.0 / r0.x) * r1.xyz;
    r1 = tiling * texcoord0.zyxz;
    r2 = tex2D(cliff, r1.zw);
    r1 = tex2D(cliff, r1.xy) * r0.x + (r0.y * r2);
    oC0 = tex2D(cliff, (tiling * texcoord0.xy)) * r0.z + r1;
    return oC0;
}
