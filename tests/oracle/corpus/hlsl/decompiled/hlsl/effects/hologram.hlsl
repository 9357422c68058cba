// ps_3_0 shader decompiled by ps30
float4 holoColor : register(c0);
float scanDensity : register(c2);
float time : register(c1);
float3 viewPosW : register(c3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r1.xyz = normalize((viewPosW - texcoord0.xyz));
    r0.x = 1.0 - saturate(dot(normalize(texcoord1.xyz), r1.xyz));
    r0.x = dot(r0.xx, r0.xx) + 0.2;
    r1.x = texcoord0.y * scanDensity - (time + time);
    r1.x = 0.5 - frac(r1.x);
    r0 = (r0.x * holoColor) * (r1.x >= 0.0 ? 0.4 : 1.0);
    r1.xyz = float3(7.957747, 2.0690143, 0.5);
    r1.xy = time * r1.xy + r1.z;
    r1.xy = frac(r1.xy) * 6.2831855 - 3.1415927;
    r2.y = sin(r1.x);
    r3.y = sin(r1.y);
    oC0 = r0 * ((r2.y * 0.1) * r3.y + 0.9);
    return oC0;
}
