// ps_3_0 shader decompiled by ps30
float4 LayerTiling : register(c0);
sampler2D SplatMap : register(s0);
sampler2D Layer0 : register(s1);
sampler2D Layer1 : register(s2);
sampler2D Layer2 : register(s3);
sampler2D Layer3 : register(s4);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = LayerTiling.xxyy * texcoord0.xyxy;
    r1 = tex2D(Layer1, r0.zw);
    r0 = tex2D(Layer0, r0.xy);
    r2 = tex2D(SplatMap, texcoord0.xy);
    r2 = (1.0 / dot(r2, float4(1.0, 1.0, 1.0, 1.0))) * r2;
    r0.xyz = r0.xyz * r2.x + (r1.xyz * r2.y);
    r1 = LayerTiling.zzww * texcoord0.xyxy;
    r3 = tex2D(Layer2, r1.xy);
    r0.xyz = tex2D(Layer3, r1.zw).xyz * r2.w + (r3.xyz * r2.z + r0.xyz);
    r0.w = saturate(texcoord1.x);
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
