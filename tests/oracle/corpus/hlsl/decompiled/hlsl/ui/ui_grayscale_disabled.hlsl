// ps_3_0 shader decompiled by ps30
float4 disabled : register(c0); // the table's type: bool
float hover : register(c1);
sampler2D buttonTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(buttonTex, texcoord0.xy);
    r1.x = dot(r0.xyz, float3(0.3, 0.59, 0.11));
    oC0.w = r0.w;
    oC0.xyz = -disabled.x >= 0.0 ? (hover * 0.15 + r0.xyz) : (r1.x * 0.6);
    return oC0;
}
