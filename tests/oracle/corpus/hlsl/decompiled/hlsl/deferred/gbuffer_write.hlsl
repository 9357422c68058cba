// ps_3_0 shader decompiled by ps30
float FarClip : register(c0);
sampler2D DiffuseTex : register(s0);
sampler2D NormalTex : register(s1);
sampler2D SpecTex : register(s2);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3, float4 texcoord4 : TEXCOORD4, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2, out precise float4 oC3 : COLOR3)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC3 = 0;
    oC0 = tex2D(DiffuseTex, texcoord0.xy);
    r0.xyz = tex2D(NormalTex, texcoord0.xy).xyz * 2.0 - 1.0;
    r0.xyw = r0.x * texcoord1.xyz + (r0.y * texcoord2.xyz);
    oC1.xyz = normalize((r0.z * texcoord3.xyz + r0.xyw)) * 0.5 + 0.5;
    oC2.x = (1.0 / FarClip) * texcoord4.x;
    oC3 = tex2D(SpecTex, texcoord0.xy);
    oC1.w = 0.0;
    oC2.yzw = 0.0;
}
