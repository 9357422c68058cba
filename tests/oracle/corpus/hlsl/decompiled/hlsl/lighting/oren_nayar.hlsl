// ps_3_0 shader decompiled by ps30
float4 diffuseColor : register(c3);
float3 lightDir : register(c0);
float sigma2 : register(c2);
float3 viewDir : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xyz = normalize(texcoord0.xyz);
    r0.w = dot(r0.xyz, viewDir);
    r1.x = ((abs(r0.w) * -0.0187293 + 0.074261) * abs(r0.w) - 0.2121144) * abs(r0.w) + 1.5707288;
    r1.y = 1.0 / rsqrt(abs((1.0 - abs(r0.w))));
    r1.x = r1.y * r1.x;
    r1.y = r1.x * -2.0 + 3.1415927;
    r1.z = r0.w >= 0.0 ? 0.0 : 1.0;
    r2.xyz = r0.xyz * -r0.w + viewDir;
    r0.w = r1.y * r1.z + r1.x;
    r1.x = dot(r0.xyz, lightDir);
    r0.xyz = r0.xyz * -r1.x + lightDir;
    r1.y = max(dot(r2.xyz, r0.xyz), 0.0);
    r0.x = ((abs(r1.x) * -0.0187293 + 0.074261) * abs(r1.x) - 0.2121144) * abs(r1.x) + 1.5707288;
    r0.y = 1.0 / rsqrt(abs((1.0 - abs(r1.x))));
    r0.x = r0.y * r0.x;
    r0.y = r0.x * -2.0 + 3.1415927;
    r0.z = r1.x >= 0.0 ? 0.0 : 1.0;
    r2.x = max(r1.x, 0.0);
    r0.x = r0.y * r0.z + r0.x;
    r1.x = max(r0.x, r0.w);
    r0.x = min(r0.w, r0.x);
    r3.xy = float2(cos(r0.x), sin(r0.x));
    r4.y = sin(r1.x);
    r0.x = sigma2;
    r0.yz = r0.x + float2(0.33, 0.09);
    r0.z = 1.0 / r0.z;
    r0.y = 1.0 / r0.y;
    r0.xw = r0.x * float2(0.5, 0.45);
    r0.z = r0.z * r0.w;
    r0.x = r0.x * -r0.y + 1.0;
    r0.y = r4.y * (r1.y * r0.z);
    r0.z = (1.0 / r3.x) * r3.y;
    r0.x = r0.y * r0.z + r0.x;
    oC0 = (r0.x * r2.x) * diffuseColor;
    return oC0;
}
