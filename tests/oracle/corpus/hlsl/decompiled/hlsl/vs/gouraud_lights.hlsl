// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 ambient : register(c9);
float3 eye : register(c8);
float4 lightColor[2] : register(c6);
float4 lightDir[2] : register(c4); // the table's type: float3[2]
float shininess : register(c10);
float4x4 worldViewProj : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float4 color1 : COLOR1;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0)
{
    precise float4 oPos = 0, oD0 = 0, oD1 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    oPos = mul(position0, worldViewProj);
    r0.xyz = eye - position0.xyz;
    r1.xyz = normalize(r0.xyz);
    r0.zw = shininess;
    r2 = ambient;
    r3 = 0.0;
    for (int i = 0; i < 2; i++) {
        r0.y = dot(normal0.xyz, normalize((r1.xyz - lightDir[i].xyz)));
        r0.x = dot(normal0.xyz, -lightDir[i].xyz);
        r4 = lit(r0.x, r0.y, r0.w);
        r5 = r4.y * lightColor[i];
        r2 = r2 + r5;
        r3 = r4.z * lightColor[i] + r3;
    }
    oD0 = r2;
    oD1 = r3;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.color0 = oD0;
    result.color1 = oD1;
    return result;
}
