// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 attenuation : register(c20);
float4 lightColor[8] : register(c8);
float4 lightPos[8] : register(c0);
float4x4 worldViewProj : register(c16);
int4 count : register(i0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord0 : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.y = 1.0;
    r1.z = 1.0;
    r2.x = 1.0;
    r3 = 0.0;
    for (int i = 0; i < count.x; i++) {
        r4.xyz = lightPos[i].xyz - position0.xyz;
        r0.x = dot(r4.xyz, r4.xyz);
        r1.yw = rsqrt(abs(r0.x));
        r2.yzw = r0.xxy * r1.yzw;
        r0.x = 1.0 / dot(r2, attenuation);
        r1.xyw = r2.y * r4.xyz;
        r0.z = saturate(dot(normal0.xyz, r1.xyw));
        r4 = r0.z * lightColor[i];
        r3 = r4 * r0.x + r3;
    }
    o1 = r3;
    o0 = mul(position0, worldViewProj);
    o2.xyz = normal0.xyz;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    result.texcoord1 = o2;
    return result;
}
