// ps_3_0 shader decompiled by ps30
float4 colBack : register(c1);
float4 colFront : register(c0);
sampler2D stipple : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float vface : VFACE, float2 vpos : VPOS, out precise float4 oC0 : COLOR0, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oDepth = 0;
    r0 = tex2D(stipple, (0.125 * vpos)).x - 0.5;
    clip(r0);
    oDepth = (1.0 / texcoord0.w) * texcoord0.z;
    oC0 = -(vface >= 0.0 ? 1.0 : -1.0) >= 0.0 ? colBack : colFront;
}
