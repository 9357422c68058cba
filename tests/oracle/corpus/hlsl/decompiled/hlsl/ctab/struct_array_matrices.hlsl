// ps_3_0 shader decompiled by ps30
float4 decals[18] : register(c0); // the table's type: struct { float4x4 worldToDecal; float4 tint; float2 fade; }[3]
sampler2D decalAtlas : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = dot(texcoord0, decals[0]);
    r0.y = dot(texcoord0, decals[1]);
    r0.z = dot(texcoord0, decals[2]);
    r1.xyz = abs(r0.xyz) - 1.0;
    r2 = tex2D(decalAtlas, (r0.xy * 0.5 + 0.5)) * decals[4];
    r0.x = saturate((1.0 - abs(r0.z)) * decals[5].x);
    r0.yzw = r1.xyz >= 0.0 ? 0.0 : 1.0;
    r0.y = r0.z * r0.y;
    r0.y = (r0.w * r0.y) * r2.w;
    r0 = r2 * (r0.x * r0.y);
    r1.x = dot(texcoord0, decals[6]);
    r1.y = dot(texcoord0, decals[7]);
    r1.z = dot(texcoord0, decals[8]);
    r2.xyz = abs(r1.xyz) - 1.0;
    r3 = tex2D(decalAtlas, (r1.xy * 0.5 + 0.5));
    r1.x = saturate((1.0 - abs(r1.z)) * decals[11].x);
    r1.yzw = r2.xyz >= 0.0 ? 0.0 : 1.0;
    r1.y = r1.z * r1.y;
    r1.y = r1.w * r1.y;
    r1.z = r3.w * decals[10].w;
    r1.y = r1.y * r1.z;
    r0 = (r1.x * r1.y) * (r3 * decals[10] - r0) + r0;
    r1.x = dot(texcoord0, decals[12]);
    r1.y = dot(texcoord0, decals[13]);
    r1.z = dot(texcoord0, decals[14]);
    r2.xyz = abs(r1.xyz) - 1.0;
    r3 = tex2D(decalAtlas, (r1.xy * 0.5 + 0.5));
    r1.x = saturate((1.0 - abs(r1.z)) * decals[17].x);
    r1.yzw = r2.xyz >= 0.0 ? 0.0 : 1.0;
    r1.y = r1.z * r1.y;
    r1.y = r1.w * r1.y;
    r1.z = r3.w * decals[16].w;
    r1.y = r1.y * r1.z;
    oC0 = (r1.x * r1.y) * (r3 * decals[16] - r0) + r0;
    return oC0;
}
