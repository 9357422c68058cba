// Hologram: scanlines in world height, rim glow, flicker, additive.
float4 holoColor;
float  time;
float  scanDensity = 80;
float3 viewPosW;

float4 main(float3 P : TEXCOORD0, float3 N : TEXCOORD1) : COLOR
{
    float rim = 1 - saturate(dot(normalize(N), normalize(viewPosW - P)));
    float scan = frac(P.y * scanDensity - time * 2) > 0.5 ? 1 : 0.4;
    float flicker = 0.9 + 0.1 * sin(time * 50) * sin(time * 13);
    return holoColor * (pow(rim, 2) * 2 + 0.2) * scan * flicker;
}
