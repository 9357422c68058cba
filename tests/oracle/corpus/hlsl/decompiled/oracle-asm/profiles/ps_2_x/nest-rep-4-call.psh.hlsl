// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

static precise float4 oC0 = 0;
static precise float4 r0 = 0, r1 = 0, r2 = 0;
static float4 texcoord0;
void label0();

void label0()
{
    r0 = r0 + float4(1.0, 0.5, 0.25, 2.0);
}

float4 main(float4 in_texcoord0 : TEXCOORD0) : COLOR
{
    texcoord0 = in_texcoord0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    for (int n0 = 0; n0 < int4(2, 0, 0, 0).x; n0++) {
        for (int n1 = 0; n1 < int4(2, 0, 0, 0).x; n1++) {
            for (int n2 = 0; n2 < int4(2, 0, 0, 0).x; n2++) {
                for (int n3 = 0; n3 < int4(2, 0, 0, 0).x; n3++) {
                    label0();
                }
            }
        }
    }
    oC0 = r0;
    return oC0;
}
