// DXT5nm normals (x in alpha, y in green); z reconstructed.
sampler2D bumpMap;
sampler2D diffuseMap;
float3 lightDirTS;   // already in tangent space from the vertex shader? no: per-pixel below

float4 main(float2 uv : TEXCOORD0, float3 L : TEXCOORD1, float3 H : TEXCOORD2) : COLOR
{
    float2 xy = tex2D(bumpMap, uv).ag * 2 - 1;
    float z = sqrt(saturate(1 - dot(xy, xy)));
    float3 n = float3(xy, z);
    float3 l = normalize(L);
    float3 h = normalize(H);
    float d = saturate(dot(n, l));
    float s = pow(saturate(dot(n, h)), 48) * d;
    return tex2D(diffuseMap, uv) * d + s;
}
