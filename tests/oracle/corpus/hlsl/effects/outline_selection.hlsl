// Selection outline from a mask render target: dilate by eight taps, subtract the inside.
sampler2D selMask;
float2 texelSz;
float4 outlineCol;
float thickness = 2;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    static const float2 dirs[8] = { float2(1, 0), float2(-1, 0), float2(0, 1), float2(0, -1),
                                    float2(0.707, 0.707), float2(-0.707, 0.707), float2(0.707, -0.707), float2(-0.707, -0.707) };
    float m = 0;
    for (int i = 0; i < 8; i++)
        m = max(m, tex2D(selMask, uv + dirs[i] * texelSz * thickness).r);
    float inside = tex2D(selMask, uv).r;
    return outlineCol * saturate(m - inside);
}
