// ps_3_0 shader decompiled by ps30
float3 light_dir : register(c0);
sampler2D main_tex : register(s0);

void main(float4 color0 : COLOR0, float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oC1 = 0;
    r0 = tex2D(main_tex, texcoord0.xy) * color0;
    r1.xyz = normalize(texcoord1.xyz);
    oC1.xyz = r1.xyz * 0.5 + 0.5;
    oC0.xyz = r0.xyz * saturate(dot(r1.xyz, light_dir));
    oC0.w = r0.w;
    oC1.w = 1.0;
}
