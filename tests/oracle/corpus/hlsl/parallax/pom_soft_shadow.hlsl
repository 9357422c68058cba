// POM with fixed 16 steps (unrolled, no break) followed by a self-shadow march.
sampler2D hgt;
sampler2D col;
float depthScale;
float3 lightTS;

float4 main(float2 uv : TEXCOORD0, float3 v : TEXCOORD1) : COLOR
{
    const int STEPS = 16;
    float2 dUV = -normalize(v).xy * depthScale / STEPS;
    float2 dx = ddx(uv), dy = ddy(uv);
    float layer = 0, depthAt = 1 - tex2Dgrad(hgt, uv, dx, dy).r;
    float2 t = uv;
    [unroll]
    for (int i = 0; i < STEPS; i++)
    {
        float still = layer < depthAt;
        t += dUV * still;
        layer += still / STEPS;
        depthAt = 1 - tex2Dgrad(hgt, t, dx, dy).r;
    }
    float3 l = normalize(lightTS);
    float sh = 1;
    float h0 = 1 - depthAt;
    [unroll]
    for (int k = 1; k <= 4; k++)
    {
        float2 s = t + l.xy * depthScale * k / 8;
        float hk = tex2Dgrad(hgt, s, dx, dy).r;
        sh = min(sh, 1 - saturate((hk - h0 - k / 8.0) * 8));
    }
    return tex2Dgrad(col, t, dx, dy) * (0.4 + 0.6 * sh);
}
