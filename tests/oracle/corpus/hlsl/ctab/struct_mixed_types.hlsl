// A uniform struct mixing bool, int, float, vectors and a row_major matrix.
struct Params
{
    bool     enabled;
    int      mode;
    float    scale;
    float3   offset;
    row_major float3x4 xform;
    float2x2 rot;
};
Params P;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r = float4(mul(P.xform, v), 1);
    r.xy = mul(P.rot, r.xy);
    if (P.enabled)
        r.xyz = r.xyz * P.scale + P.offset;
    return r * (P.mode + 1);
}
