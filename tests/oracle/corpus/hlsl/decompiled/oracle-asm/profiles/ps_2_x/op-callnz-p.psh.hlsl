// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

static precise float4 oC0 = 0;
static precise float4 r0 = 0, r1 = 0, r2 = 0;
static bool4 p0 = false;
static float4 texcoord0;
void label0();

void label0()
{
}

float4 main(float4 in_texcoord0 : TEXCOORD0) : COLOR
{
    texcoord0 = in_texcoord0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    p0 = r1 > r2;
    if (p0.x) label0();
    oC0 = r0;
    return oC0;
}
