// oracle: target=vs_3_0
// vs_3_0: a camera-facing billboard from the corner in TEXCOORD1, the camera's right and up
// vectors, a rotation by sincos, and a colour faded by distance.
float4x4 viewProj;
float3 right;
float3 up;
float3 eye;
float fadeDistance;

struct Out
{
    float4 pos : POSITION;
    float2 uv : TEXCOORD0;
    float4 color : COLOR0;
};

Out main(float4 center : POSITION, float2 corner : TEXCOORD1, float4 params : TEXCOORD2, float4 color : COLOR0)
{
    float s, c;
    sincos(params.y, s, c);
    float2 r = float2(corner.x * c - corner.y * s, corner.x * s + corner.y * c) * params.x;
    float3 world = center.xyz + right * r.x + up * r.y;
    Out o;
    o.pos = mul(float4(world, 1), viewProj);
    o.uv = corner * 0.5 + 0.5;
    o.color = color * saturate(1 - distance(world, eye) / fadeDistance);
    return o;
}
