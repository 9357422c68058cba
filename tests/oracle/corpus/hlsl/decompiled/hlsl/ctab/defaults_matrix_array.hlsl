// ps_3_0 shader decompiled by ps30
float3x3 ColourMatrix : register(c0);
float4 W[3] : register(c6); // the table's type: struct { float amp; float freq; float2 dir; }
float4 Weights[3] : register(c3);
sampler2D Image : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1.y = sin((W[1].x * texcoord0.x));
    r0 = tex2D(Image, ((r1.y * W[2].xy) * W[0].x + texcoord0.xy));
    r1.xyz = mul(r0.xyz, ColourMatrix);
    r0 = Weights[1] * texcoord0.x + Weights[0];
    r1.w = 1.0;
    oC0 = (Weights[2] * texcoord0.y + r0) * r1;
    return oC0;
}
