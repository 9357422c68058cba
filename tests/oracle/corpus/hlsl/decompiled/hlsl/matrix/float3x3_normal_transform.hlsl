// ps_3_0 shader decompiled by ps30
float3x3 normalMatrix : register(c3);
float4 worldMatrix[3] : register(c0); // the table's type: float4x4

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1.xyz = normalize(mul(texcoord1.xyz, normalMatrix));
    r0.xyz = mul(normalMatrix, texcoord1.xyz) * r1.xyz;
    r1.x = dot(texcoord0.xyz, worldMatrix[0].xyz);
    r1.y = dot(texcoord0.xyz, worldMatrix[1].xyz);
    r1.z = dot(texcoord0.xyz, worldMatrix[2].xyz);
    r0.w = rsqrt(abs(dot(r1.xyz, r1.xyz)));
    oC0.xyz = r1.xyz * r0.w + r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
