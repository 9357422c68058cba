// ps_3_0 shader decompiled by ps30
float4 scene[8] : register(c0); // the table's type: struct { struct { float4 diffuse; float4 specular; float power; } mat; struct { float3 color; float start; float end; } fog; float4 lights[2]; }

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = 1.0 / (scene[5].x - scene[4].x);
    r0.y = texcoord1.x - scene[4].x;
    r0.x = saturate(r0.x * r0.y);
    r1.xyz = normalize(texcoord0.xyz);
    r2 = saturate(dot(r1.xyz, scene[7].xyz)) * scene[0];
    r0.y = saturate(dot(r1.xyz, scene[6].xyz));
    r0.z = saturate(r1.z);
    r1 = scene[1] * pow(abs(r0.z), scene[2].x) + (scene[0] * r0.y + r2);
    r0.yzw = scene[3].xyz - r1.xyz;
    oC0.xyz = r0.x * r0.yzw + r1.xyz;
    oC0.w = r1.w;
    return oC0;
}
