// Height-based blending of two terrain layers (sharper transitions than linear).
sampler2D rockTex, grassTex, maskTex;
float blendDepth = 0.2;

float3 HeightBlend(float4 a, float wa, float4 b, float wb)
{
    float ma = max(a.a + wa, b.a + wb) - blendDepth;
    float ba = max(a.a + wa - ma, 0);
    float bb = max(b.a + wb - ma, 0);
    return (a.rgb * ba + b.rgb * bb) / (ba + bb);
}

float4 main(float2 uv : TEXCOORD0, float2 uvMask : TEXCOORD1) : COLOR
{
    float m = tex2D(maskTex, uvMask).r;
    float3 c = HeightBlend(tex2D(rockTex, uv), 1 - m, tex2D(grassTex, uv), m);
    return float4(c, 1);
}
