// ps_3_0 shader decompiled by ps30
float4 x : register(c0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.z = texcoord0.z;
    if (texcoord1.z < r0.z) {
        oC0 = tex2D(s, texcoord0.xy);
    } else {
        oC0 = x;
    }
    return oC0;
}
