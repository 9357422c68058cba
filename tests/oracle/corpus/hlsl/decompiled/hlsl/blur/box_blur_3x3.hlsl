// ps_3_0 shader decompiled by ps30
float2 pixelSize : register(c0);
sampler2D image : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = tex2D(image, (texcoord0.xy - pixelSize));
    r1.xy = pixelSize;
    r2 = r1.xyxy * float4(0.0, -1.0, 1.0, -1.0) + texcoord0.xyxy;
    r3 = tex2D(image, r2.xy);
    r0 = tex2D(image, r2.zw) + (r0 + r3);
    r2 = r1.xyxy * float4(-1.0, 0.0, 1.0, 0.0) + texcoord0.xyxy;
    r3 = tex2D(image, r2.xy);
    r0 = r0 + r3;
    r0 = tex2D(image, r2.zw) + (r0 + tex2D(image, texcoord0.xy));
    r1 = r1.xyxy * float4(-1.0, 1.0, 0.0, 1.0) + texcoord0.xyxy;
    r2 = tex2D(image, r1.xy);
    r0 = tex2D(image, r1.zw) + (r0 + r2);
    oC0 = (r0 + tex2D(image, (pixelSize + texcoord0.xy))) * 0.11111111;
    return oC0;
}
