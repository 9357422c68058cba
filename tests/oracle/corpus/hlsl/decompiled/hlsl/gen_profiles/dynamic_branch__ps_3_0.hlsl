// ps_3_0 shader decompiled by ps30
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    if (0.5 < texcoord0.x) {
        r0 = float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx;
        oC0 = tex2Dlod(s, r0);
    } else {
        oC0 = texcoord0.yxyx;
    }
    return oC0;
}
