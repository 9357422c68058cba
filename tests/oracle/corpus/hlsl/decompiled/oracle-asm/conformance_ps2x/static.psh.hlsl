// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
int4 i1 : register(i1);
bool b0 : register(b0);
bool b1 : register(b1);

static precise float4 oC0 = 0;
static precise float4 r0 = 0;
static float4 texcoord0;
void label0();

void label0()
{
    r0 = r0 + float4(0.0, 0.0, 1.0, 0.5);
}

float4 main(float4 in_texcoord0 : TEXCOORD0) : COLOR
{
    texcoord0 = in_texcoord0;
    r0 = 0.0;
    for (int n0 = 0; n0 < i1.x; n0++) {
        r0 = r0 + float4(0.25, 0.5, 0.0, 0.0);
    }
    if (b0) {
        r0 = r0 + r0;
    }
    if (b1) label0();
    oC0 = r0;
    return oC0;
}
