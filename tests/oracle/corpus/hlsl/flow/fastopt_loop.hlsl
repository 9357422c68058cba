// [fastopt] on a loop plus [loop] on an inner one.
sampler2D src;
float4 dirs[4];

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 s = 0;
    [fastopt]
    for (int i = 0; i < 4; i++)
    {
        [loop]
        for (int j = 1; j <= 3; j++)
            s += tex2Dlod(src, float4(uv + dirs[i].xy * j, 0, 0));
    }
    return s / 12;
}
