// Mixed directional/point lights: a type selector per light in w.
struct Light { float4 pos; float4 color; };
Light lights[6];
int numLights = 3;
sampler2D tex0;

float3 Evaluate(Light lt, float3 P, float3 N)
{
    // w == 0: directional (pos.xyz is the direction), else point light
    float3 L = lt.pos.w == 0 ? lt.pos.xyz : normalize(lt.pos.xyz - P);
    return lt.color.rgb * saturate(dot(N, L));
}

float4 main(float2 uv : TEXCOORD0, float3 P : TEXCOORD1, float3 N : TEXCOORD2) : COLOR
{
    float3 n = normalize(N), c = 0;
    for (int k = 0; k < numLights; k++)
        c += Evaluate(lights[k], P, n);
    return tex2D(tex0, uv) * float4(c, 1);
}
