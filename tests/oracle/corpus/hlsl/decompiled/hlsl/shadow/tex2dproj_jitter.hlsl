// ps_3_0 shader decompiled by ps30
float2 jitter[4] : register(c0);
float spread : register(c4);
sampler2D smap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = spread;
    r1.xy = (r0.x * jitter[0]) * texcoord0.w;
    r1.zw = 0.0;
    r1 = r1 + texcoord0;
    r2.xy = (r0.x * jitter[1]) * texcoord0.w;
    r2.zw = 0.0;
    r2 = r2 + texcoord0;
    r0.y = tex2Dproj(smap, r1).x + tex2Dproj(smap, r2).x;
    r1.xy = (r0.x * jitter[2]) * texcoord0.w;
    r1.zw = 0.0;
    r1 = r1 + texcoord0;
    r0.y = r0.y + tex2Dproj(smap, r1).x;
    r1.xy = (r0.x * jitter[3]) * texcoord0.w;
    r1.zw = 0.0;
    r1 = r1 + texcoord0;
    oC0 = (r0.y + tex2Dproj(smap, r1).x) * 0.25;
    return oC0;
}
