// ps_3_0 shader decompiled by ps30
float angle : register(c0);
sampler2D decal : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = float2(0.15915494, 0.5);
    r0.x = angle * r0.x + r0.y;
    r0.x = frac(r0.x) * 6.2831855 - 3.1415927;
    r1.xy = float2(cos(r0.x), sin(r0.x));
    r0.xy = r1.xy * float2(1.0, -1.0);
    r0.zw = texcoord0.xy - 0.5;
    r0.x = dot(r0.xy, r0.zw) + 0.0;
    r0.y = dot(r1.yx, r0.zw) + 0.0;
    r0.xy = r0.xy + 0.5;
    r1.x = texcoord1.z;
    r1.y = texcoord2.z;
    r1.z = texcoord3.z;
    r1.xyz = r1.xyz * 0.5 + 0.5;
    r1.w = 1.0;
    oC0 = tex2D(decal, r0.xy) * r1;
    return oC0;
}
