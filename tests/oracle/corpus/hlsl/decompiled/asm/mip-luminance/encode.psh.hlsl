// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);
float4 c1 : register(c1);
sampler2D s0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s0, texcoord0.xy);
    r0.w = c0.w;
    r1.x = log2(abs(dot(r0, c0)));
    oC0 = (r1.x * c1.x + c1.y);
    return oC0;
}
