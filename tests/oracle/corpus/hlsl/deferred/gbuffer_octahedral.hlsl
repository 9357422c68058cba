// G-buffer with octahedron-encoded normals in two channels.
sampler2D albedoMap;
float roughnessValue;
float metalness;

float2 OctWrap(float2 v) { return (1.0 - abs(v.yx)) * (v.xy >= 0.0 ? 1.0 : -1.0); }

float2 EncodeNormal(float3 n)
{
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    n.xy = n.z >= 0.0 ? n.xy : OctWrap(n.xy);
    return n.xy * 0.5 + 0.5;
}

void main(float2 uv : TEXCOORD0, float3 nrm : TEXCOORD1,
          out float4 rt0 : COLOR0, out float4 rt1 : COLOR1)
{
    rt0 = float4(tex2D(albedoMap, uv).rgb, metalness);
    rt1 = float4(EncodeNormal(normalize(nrm)), roughnessValue, 1);
}
