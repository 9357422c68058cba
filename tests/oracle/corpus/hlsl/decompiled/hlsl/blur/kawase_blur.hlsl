// ps_3_0 shader decompiled by ps30
float4 pixel : register(c0);
sampler2D src : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = pixel.z + 0.5;
    r1.xy = r0.x * pixel.xy;
    r1.zw = -r1.xy;
    r1 = r1.zyxw + texcoord0.xyxy;
    r2 = tex2D(src, r1.xy);
    r0.yz = pixel.xy * r0.x + texcoord0.xy;
    r3 = tex2D(src, (pixel.xy * -r0.x + texcoord0.xy));
    r0 = tex2D(src, r0.yz);
    r0 = tex2D(src, r1.zw) + (r2 + r0);
    oC0 = (r3 + r0) * 0.25;
    return oC0;
}
