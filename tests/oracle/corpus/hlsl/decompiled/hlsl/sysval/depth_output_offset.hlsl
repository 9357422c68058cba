// ps_3_0 shader decompiled by ps30
float depthBias : register(c0);
sampler2D decalTex : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, out precise float4 oC0 : COLOR0, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0;
    oC0 = 0;
    oDepth = 0;
    oC0 = tex2D(decalTex, texcoord0.xy);
    oDepth = texcoord1.z * (1.0 / texcoord1.w) - depthBias;
}
