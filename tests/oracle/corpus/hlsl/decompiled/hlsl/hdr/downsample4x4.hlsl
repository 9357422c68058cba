// ps_3_0 shader decompiled by ps30
float2 offsets[16] : register(c0);
sampler2D srcTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(srcTex, (offsets[0] + texcoord0.xy)) + tex2D(srcTex, (offsets[1] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[2] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[3] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[4] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[5] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[6] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[7] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[8] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[9] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[10] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[11] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[12] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[13] + texcoord0.xy));
    r0 = r0 + tex2D(srcTex, (offsets[14] + texcoord0.xy));
    oC0 = (r0 + tex2D(srcTex, (offsets[15] + texcoord0.xy))) * 0.0625;
    return oC0;
}
