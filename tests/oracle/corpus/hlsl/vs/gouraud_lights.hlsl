// oracle: target=vs_2_0
// Per-vertex lighting: ambient plus two directional lights with lit() for the diffuse and
// specular terms, to the two colour outputs.
float4x4 worldViewProj;
float3 eye;
float3 lightDir[2];
float4 lightColor[2];
float4 ambient;
float shininess;

struct Out
{
    float4 pos : POSITION;
    float4 diffuse : COLOR0;
    float4 specular : COLOR1;
};

Out main(float4 pos : POSITION, float3 n : NORMAL)
{
    Out o;
    o.pos = mul(pos, worldViewProj);
    float3 v = normalize(eye - pos.xyz);
    float4 d = ambient, s = 0;
    for (int i = 0; i < 2; i++)
    {
        float3 h = normalize(v - lightDir[i]);
        float4 l = lit(dot(n, -lightDir[i]), dot(n, h), shininess);
        d += l.y * lightColor[i];
        s += l.z * lightColor[i];
    }
    o.diffuse = d;
    o.specular = s;
    return o;
}
