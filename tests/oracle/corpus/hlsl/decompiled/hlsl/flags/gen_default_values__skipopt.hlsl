// ps_3_0 shader decompiled by ps30
float3 Colour : register(c10);
float4 Count : register(c12); // the table's type: int
float4x4 Ident : register(c0);
float2 Pair : register(c9);
float Scalar : register(c8);
float Soft : register(c13);
float Table[4] : register(c4);
float4 Vec : register(c11);
bool Enabled : register(b0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = mul(texcoord0, Ident) * Vec;
    r1.xyz = Pair.y * Colour;
    r1.w = Pair.y * Pair.x;
    r0 = (r0 * Scalar) + r1;
    r1.x = 0.0;
    r2 = r0;
    r1.y = r1.x;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        r1.z = -Count.x;
        r1.z = (r1.z + r1.y) >= 0.0 ? 0.0 : 1.0;
        r1.w = -r1.z;
        r1.z = -r1.z;
        r1.z = (r1.z + r1.w) >= 0.0 ? 1.0 : 0.0;
        if (r1.z != -r1.z) break;
        r3 = abs((r1.y + float4(-0.0, -1.0, -2.0, -3.0)));
        r4 = -r3;
        r3 = -r3;
        r3 = (r3 + r4) >= 0.0 ? 1.0 : 0.0;
        r1.z = -r3.x;
        r3.x = 0.0;
        r1.z = r1.z >= 0.0 ? r3.x : Table[0];
        r1.w = -r3.y;
        r1.z = r1.w >= 0.0 ? r1.z : Table[1];
        r1.w = -r3.z;
        r1.z = r1.w >= 0.0 ? r1.z : Table[2];
        r1.w = -r3.w;
        r1.z = r1.w >= 0.0 ? r1.z : Table[3];
        r2 = r1.z + r2;
        r1.y = r1.y + 1.0;
    }
    if (Enabled) {
        r2 = r2 * Soft;
    }
    oC0 = r2;
    return oC0;
}
