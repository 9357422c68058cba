// ps_3_0 shader decompiled by ps30
float4 lightCol[4] : register(c4);
float4 lightOn[4] : register(c0); // the table's type: bool[4]
int4 i1 : register(i1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = -lightOn[0].x >= 0.0 ? 0.0 : (lightCol[0] * texcoord0);
    r0 = -lightOn[1].x >= 0.0 ? r0 : (lightCol[1] * texcoord0 + r0);
    r0 = -lightOn[2].x >= 0.0 ? r0 : (lightCol[2] * texcoord0 + r0);
    r0 = -lightOn[3].x >= 0.0 ? r0 : (lightCol[3] * texcoord0 + r0);
    r1 = r0;
    for (int n0 = 0; n0 < i1.x; n0++) {
        r1 = r1 * 0.9;
    }
    oC0 = r1;
    return oC0;
}
