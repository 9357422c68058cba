// Analytic height fog: density falls off exponentially with altitude.
float3 cameraPosition;
float  fogHeightFalloff = 0.2;
float  fogGlobalDensity = 0.02;
float3 fogInscatter;
float3 sunDir;
float3 sunFogColor;
sampler2D sceneColor;

float4 main(float2 uv : TEXCOORD0, float3 worldPos : TEXCOORD1) : COLOR
{
    float3 ray = worldPos - cameraPosition;
    float len = length(ray);
    float3 rd = ray / len;
    float fogAmount = fogGlobalDensity * exp(-cameraPosition.y * fogHeightFalloff)
                    * (1.0 - exp(-len * rd.y * fogHeightFalloff)) / (rd.y + 1e-5);
    float sunAmt = pow(max(dot(rd, sunDir), 0.0), 8.0);
    float3 fogCol = lerp(fogInscatter, sunFogColor, sunAmt);
    float3 c = tex2D(sceneColor, uv).rgb;
    return float4(lerp(c, fogCol, saturate(fogAmount)), 1);
}
