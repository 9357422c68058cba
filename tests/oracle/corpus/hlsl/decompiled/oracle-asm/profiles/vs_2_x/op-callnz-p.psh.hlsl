// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

static precise float4 oPos = 0;
static precise float4 r0 = 0, r1 = 0, r2 = 0;
static bool4 p0 = false;
static float4 position0;
void label0();

void label0()
{
}

VS_OUTPUT main(float4 in_position0 : POSITION0)
{
    position0 = in_position0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    p0 = r1 > r2;
    if (p0.x) label0();
    oPos = r0;
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
