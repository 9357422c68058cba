// ps_3_0 shader decompiled by ps30
float middleGrey : register(c0);
float whitePoint : register(c1);
sampler2D hdrScene : register(s0);
sampler2D avgLum : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / (whitePoint * whitePoint);
    r0.y = 1.0 / (tex2D(avgLum, float2(0.5, 0.5)).x + 0.001);
    r1 = tex2D(hdrScene, texcoord0.xy);
    r0.z = dot(r1.xyz, float3(0.2126, 0.7152, 0.0722));
    r0.w = r0.z * middleGrey;
    r1.w = r0.y * r0.w;
    r0.y = 1.0 / (r0.w * r0.y + 1.0);
    r0.x = (r1.w * r0.x + 1.0) * r1.w;
    r0.x = r0.y * r0.x;
    r0.y = r0.z - 1.0e-5;
    r0.z = 1.0 / r0.z;
    r0.y = r0.y >= 0.0 ? r0.z : 100000.0;
    oC0.xyz = (r0.y * r0.x) * r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
