// Loop with a data-dependent break (break_comp in the output).
sampler2D tex;
float4 params;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = 0;
    float a = 0;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float4 s = tex2Dlod(tex, float4(uv + params.xy * i, 0, 0));
        c += s * (1 - a);
        a += s.a * (1 - a);
        if (a > 0.99) break;
    }
    return c;
}
