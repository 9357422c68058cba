// A [branch] whose arms both carry loops.
float4 a[4], b[4];
float sel;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r = 0;
    [branch]
    if (v.w > sel)
    {
        [loop] for (int i = 0; i < 4; i++) r += a[i] * v;
    }
    else
    {
        [loop] for (int i = 0; i < 4; i++) r -= b[i] * v;
    }
    return r;
}
