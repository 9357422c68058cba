// ps_3_0 shader decompiled by ps30
float3 FogColour : register(c0);
float FogDensity : register(c1);
float4 UseExp2 : register(c2); // the table's type: bool
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz)));
    r0.y = r0.x * FogDensity;
    r0.x = -r0.x * FogDensity;
    r0.x = exp2((r0.x * 1.442695));
    r0.y = r0.y * -r0.y;
    r0.y = exp2((r0.y * 1.442695));
    r0.x = saturate(-UseExp2.x >= 0.0 ? r0.x : r0.y);
    r1 = tex2D(tex, texcoord0.xy);
    r0.yzw = r1.xyz - FogColour;
    oC0.w = r1.w;
    oC0.xyz = r0.x * r0.yzw + FogColour;
    return oC0;
}
