// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r1 = 0, r2 = 0;
    r2.x = texcoord0.y * 8.0;
    r1 = 0.0;
    if (texcoord0.x > 0.5) {
        r1.x = 1.0;
    } else {
        r1.x = 0.5;
    }
    for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
        if (r1.y >= r2.x) break;
        r1.y = r1.y + 1.0;
    }
    r1.y = r1.y * 0.125;
    r1.zw = 0.0;
    oC0 = r1;
    return oC0;
}
