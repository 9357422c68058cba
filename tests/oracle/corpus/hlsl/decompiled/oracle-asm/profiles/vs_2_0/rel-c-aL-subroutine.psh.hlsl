// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 cr[223] : register(c1);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

static precise float4 oPos = 0;
static precise float4 r0 = 0, r1 = 0, r2 = 0;
static float4 position0;
static int aL;
void label0();

void label0()
{
    r0 = r0 + cr[aL];
}

VS_OUTPUT main(float4 in_position0 : POSITION0)
{
    position0 = in_position0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    for (int i = 0, ni = 0; ni < 2; ni++, i += 0) {
        aL = i;
        label0();
    }
    oPos = r0;
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
