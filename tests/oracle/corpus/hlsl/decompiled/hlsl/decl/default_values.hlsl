// ps_3_0 shader decompiled by ps30
float3 Colour : register(c10);
float4 Count : register(c12); // the table's type: int
float4 Enabled : register(c13); // the table's type: bool
float4x4 Ident : register(c0);
float2 Pair : register(c9);
float Scalar : register(c8);
float Soft : register(c14);
float Table[4] : register(c4);
float4 Vec : register(c11);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r1.xyz = Pair.y * Colour;
    r1.w = Pair.y * Pair.x;
    r0 = (mul(texcoord0, Ident) * Vec) * Scalar + r1;
    r0 = -Count.x >= 0.0 ? r0 : (r0 + Table[0]);
    r2.x = -Count.x >= 0.0 ? 0.0 : 1.0;
    r2.y = r2.x - Count.x;
    r2.x = r2.y >= 0.0 ? r2.x : 2.0;
    r0 = r2.y >= 0.0 ? r0 : (r0 + Table[1]);
    r2.z = (r2.x - Count.x) >= 0.0 ? -0.0 : -1.0;
    r2.y = r2.y >= 0.0 ? -0.0 : r2.z;
    r0 = r2.y >= 0.0 ? r0 : (r0 + Table[2]);
    r2.x = (r2.y >= 0.0 ? r2.x : 3.0) - Count.x;
    r0 = (r2.x >= 0.0 ? -0.0 : r2.y) >= 0.0 ? r0 : (r0 + Table[3]);
    oC0 = -Enabled.x >= 0.0 ? r0 : (r0 * Soft);
    return oC0;
}
