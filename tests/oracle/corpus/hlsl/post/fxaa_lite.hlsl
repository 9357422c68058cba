// Cut-down FXAA: luma edges from a 3x3 cross, blend along the edge direction.
sampler2D tex : register(s0);
float2 rcpFrame;

float Luma(float3 c) { return dot(c, float3(0.299, 0.587, 0.114)); }

float4 main(float2 pos : TEXCOORD0) : COLOR
{
    float3 rgbNW = tex2D(tex, pos + float2(-1, -1) * rcpFrame).rgb;
    float3 rgbNE = tex2D(tex, pos + float2( 1, -1) * rcpFrame).rgb;
    float3 rgbSW = tex2D(tex, pos + float2(-1,  1) * rcpFrame).rgb;
    float3 rgbSE = tex2D(tex, pos + float2( 1,  1) * rcpFrame).rgb;
    float3 rgbM  = tex2D(tex, pos).rgb;
    float lNW = Luma(rgbNW), lNE = Luma(rgbNE), lSW = Luma(rgbSW), lSE = Luma(rgbSE), lM = Luma(rgbM);
    float lMin = min(lM, min(min(lNW, lNE), min(lSW, lSE)));
    float lMax = max(lM, max(max(lNW, lNE), max(lSW, lSE)));
    float2 dir = float2(-((lNW + lNE) - (lSW + lSE)), (lNW + lSW) - (lNE + lSE));
    float reduce = max((lNW + lNE + lSW + lSE) * 0.03125, 1.0 / 128);
    float rcpMin = 1 / (min(abs(dir.x), abs(dir.y)) + reduce);
    dir = clamp(dir * rcpMin, -8, 8) * rcpFrame;
    float3 a = 0.5 * (tex2D(tex, pos + dir * (1.0 / 3 - 0.5)).rgb + tex2D(tex, pos + dir * (2.0 / 3 - 0.5)).rgb);
    float3 b = a * 0.5 + 0.25 * (tex2D(tex, pos - dir * 0.5).rgb + tex2D(tex, pos + dir * 0.5).rgb);
    float lB = Luma(b);
    return float4((lB < lMin || lB > lMax) ? a : b, 1);
}
