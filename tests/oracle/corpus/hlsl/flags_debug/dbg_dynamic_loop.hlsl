// oracle: flags=DEBUG
// Debug information in a dynamic loop indexing constants through aL, optimised.
float4 lights[8];
int count;
float4 main(float3 n : TEXCOORD0, float4 base : COLOR0) : COLOR
{
    float3 acc = 0;
    [loop] for (int k = 0; k < count; k++)
    {
        float d = saturate(dot(n, lights[k].xyz));
        acc += d * lights[k].w;
    }
    return float4(acc, 1) * base;
}
