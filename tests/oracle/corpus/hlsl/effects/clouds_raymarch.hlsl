// Volumetric cloud slab: fixed-step march through a 3D noise texture with early out.
sampler3D noiseVol;
float3 camPos;
float2 slab;          // bottom, top heights
float  coverage, densityScale;
float3 sunDirW;

float4 main(float3 wpos : TEXCOORD0) : COLOR
{
    float3 rd = normalize(wpos - camPos);
    float t0 = (slab.x - camPos.y) / rd.y;
    float t1 = (slab.y - camPos.y) / rd.y;
    float stepLen = (t1 - t0) / 24;
    float trans = 1, light = 0;
    [loop]
    for (int i = 0; i < 24; i++)
    {
        float3 p = camPos + rd * (t0 + stepLen * (i + 0.5));
        float den = saturate(tex3Dlod(noiseVol, float4(p * 0.001, 0)).r - coverage) * densityScale;
        float sd = tex3Dlod(noiseVol, float4((p + sunDirW * 50) * 0.001, 0)).r;
        light += trans * den * exp(-sd * densityScale);
        trans *= exp(-den * stepLen);
        if (trans < 0.01) break;
    }
    return float4(light.xxx, 1 - trans);
}
