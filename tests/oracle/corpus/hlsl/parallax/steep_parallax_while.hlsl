// Steep parallax written with a while loop and explicit counter.
sampler2D heightTex;
sampler2D albedoTex;
float scale;

float4 main(float2 uv : TEXCOORD0, float3 viewDir : TEXCOORD1) : COLOR
{
    float3 v = normalize(viewDir);
    float numLayers = lerp(24.0, 8.0, abs(v.z));
    float layerDepth = 1.0 / numLayers;
    float2 P = v.xy * scale;
    float2 deltaUV = P / numLayers;
    float2 cur = uv;
    float curLayer = 0;
    float mapDepth = 1 - tex2Dlod(heightTex, float4(cur, 0, 0)).r;
    int guard = 0;
    [loop]
    while (curLayer < mapDepth && guard < 32)
    {
        cur -= deltaUV;
        mapDepth = 1 - tex2Dlod(heightTex, float4(cur, 0, 0)).r;
        curLayer += layerDepth;
        guard++;
    }
    return tex2D(albedoTex, cur);
}
