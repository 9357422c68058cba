// oracle: target=vs_3_0
// vs_3_0: point lights in a uniform array over a loop of a uniform count (aL indexes the
// arrays), attenuation from dst(), and outputs declared as TEXCOORD semantics.
float4x4 worldViewProj;
float4 lightPos[8];
float4 lightColor[8];
float4 attenuation;
int count;

struct Out
{
    float4 pos : POSITION;
    float4 light : TEXCOORD0;
    float3 normal : TEXCOORD1;
};

Out main(float4 pos : POSITION, float3 n : NORMAL)
{
    float4 sum = 0;
    for (int i = 0; i < count; i++)
    {
        float3 d = lightPos[i].xyz - pos.xyz;
        float dd = dot(d, d);
        float4 dv = dst(dd, rsqrt(dd));
        float att = 1 / dot(dv, attenuation);
        sum += lightColor[i] * saturate(dot(n, d * dv.y)) * att;
    }
    Out o;
    o.pos = mul(pos, worldViewProj);
    o.light = sum;
    o.normal = n;
    return o;
}
