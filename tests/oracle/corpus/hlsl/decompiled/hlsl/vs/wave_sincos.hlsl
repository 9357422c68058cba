// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float time : register(c5);
float4 wave : register(c4);
float4x4 worldViewProj : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float psize0 : PSIZE0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 color0 : COLOR0)
{
    precise float4 oPos = 0, oD0 = 0, oPts = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = wave.y * time;
    r0.x = (position0.x * wave.x + r0.x);
    r1.xy = float2(cos(r0.x), sin(r0.x));
    r0.yz = r1.yx * wave.zw + position0.yz;
    r0.xw = position0.xw;
    oPos = mul(r0, worldViewProj);
    oPts = r1.y * 2.0 + 4.0;
    oD0 = (r1.x * 0.25 + 0.75) * color0;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.color0 = oD0;
    result.psize0 = oPts.x;
    return result;
}
