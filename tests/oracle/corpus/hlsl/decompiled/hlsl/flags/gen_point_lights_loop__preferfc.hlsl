// ps_3_0 shader decompiled by ps30
float4 LightColour[4] : register(c4);
float4 LightPosRange[4] : register(c0);
sampler2D BaseMap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = LightPosRange[1].xyz - texcoord1.xyz;
    r0.w = rsqrt(abs(dot(r0.xyz, r0.xyz)));
    r1.x = 1.0 / r0.w;
    r0.xyz = r0.w * r0.xyz;
    r2.x = 1.0;
    r0.w = saturate(r1.x * -LightPosRange[1].w + r2.x);
    r0.w = r0.w * r0.w;
    r1.xyz = normalize(texcoord2.xyz);
    r0.xyz = saturate(dot(r1.xyz, r0.xyz)) * LightColour[1].xyz;
    r0.xyz = r0.xyz * r0.w;
    r2.yzw = LightPosRange[0].xyz - texcoord1.xyz;
    r0.w = rsqrt(abs(dot(r2.yzw, r2.yzw)));
    r1.w = 1.0 / r0.w;
    r2.yzw = r0.w * r2.yzw;
    r2.yzw = saturate(dot(r1.xyz, r2.yzw)) * LightColour[0].xyz;
    r0.w = saturate(r1.w * -LightPosRange[0].w + r2.x);
    r0.w = r0.w * r0.w;
    r0.xyz = r0.w * r2.yzw + r0.xyz;
    r2.yzw = LightPosRange[2].xyz - texcoord1.xyz;
    r0.w = rsqrt(abs(dot(r2.yzw, r2.yzw)));
    r1.w = 1.0 / r0.w;
    r2.yzw = r0.w * r2.yzw;
    r2.yzw = saturate(dot(r1.xyz, r2.yzw)) * LightColour[2].xyz;
    r0.w = saturate(r1.w * -LightPosRange[2].w + r2.x);
    r0.w = r0.w * r0.w;
    r0.xyz = r0.w * r2.yzw + r0.xyz;
    r2.yzw = LightPosRange[3].xyz - texcoord1.xyz;
    r0.w = rsqrt(abs(dot(r2.yzw, r2.yzw)));
    r1.w = 1.0 / r0.w;
    r2.yzw = r0.w * r2.yzw;
    r1.xyz = saturate(dot(r1.xyz, r2.yzw)) * LightColour[3].xyz;
    r0.w = saturate(r1.w * -LightPosRange[3].w + r2.x);
    r0.w = r0.w * r0.w;
    r0.xyz = r0.w * r1.xyz + r0.xyz;
    oC0.xyz = r0.xyz * tex2D(BaseMap, texcoord0.xy).xyz;
    oC0.w = 1.0;
    return oC0;
}
