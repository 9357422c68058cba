// ps_3_0 shader decompiled by ps30
float4 params : register(c0);
sampler2D backbuffer : register(s0);
sampler2D bumpTex : register(s1);
sampler2D maskTex : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = params.z * texcoord0.x;
    r0.y = texcoord0.y * params.z + params.y;
    r0.xy = tex2D(bumpTex, r0.xy).xy * 2.0 - 1.0;
    r0.xy = (r0.xy * params.x) * tex2D(maskTex, texcoord0.xy).x;
    r0.z = 1.0 / texcoord1.w;
    oC0 = tex2D(backbuffer, (texcoord1.xy * r0.z + r0.xy));
    return oC0;
}
