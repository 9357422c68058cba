// ps_3_0 shader decompiled by ps30
float heightScale : register(c0);
sampler2D hMap : register(s0);
sampler2D dMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(hMap, texcoord0.xy);
    r0.x = (r0.w - 0.5) * heightScale;
    r0.x = r0.z * r0.x;
    r0.yz = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.xy;
    r0.xw = r0.x * r0.yz + texcoord0.xy;
    r1 = tex2D(hMap, r0.xw);
    r1.x = (r1.w - 0.5) * heightScale;
    r0.xw = (r1.z * r1.x) * r0.yz + r0.xw;
    r1 = tex2D(hMap, r0.xw);
    r1.x = (r1.w - 0.5) * heightScale;
    oC0 = tex2D(dMap, ((r1.z * r1.x) * r0.yz + r0.xw));
    return oC0;
}
