// Writes DEPTH: impostor sphere ray-cast in the pixel shader.
float4x4 proj;
float4 sphereVS;   // centre, radius
float3 lightVS;

struct PSOut { float4 color : COLOR0; float depth : DEPTH; };

PSOut main(float3 rayVS : TEXCOORD0)
{
    PSOut o;
    float3 d = normalize(rayVS);
    float b = dot(d, sphereVS.xyz);
    float c = dot(sphereVS.xyz, sphereVS.xyz) - sphereVS.w * sphereVS.w;
    float h = b * b - c;
    clip(h);
    float t = b - sqrt(h);
    float3 p = d * t;
    float3 n = (p - sphereVS.xyz) / sphereVS.w;
    float4 cp = mul(float4(p, 1), proj);
    o.depth = cp.z / cp.w;
    o.color = float4(saturate(dot(n, lightVS)).xxx, 1);
    return o;
}
