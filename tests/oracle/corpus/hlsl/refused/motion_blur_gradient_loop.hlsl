// Refused by D3DCompile: the trip count is a uniform, so the loop must stay a loop with an exit
// test, where the compiler will not compute tex2D's gradients (warning X3553); it tries to
// unroll the loop instead and gives up (X3511). blur/motion_blur.hlsl uses tex2Dlod and compiles.
// Camera motion blur: velocity from current and previous clip position.
sampler2D frame : register(s0);
sampler2D depth : register(s1);
float4x4 currInvViewProj;
float4x4 prevViewProj;
int numSamples = 8;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float z = tex2D(depth, uv).r;
    float4 H = float4(uv.x * 2 - 1, (1 - uv.y) * 2 - 1, z, 1);
    float4 D = mul(H, currInvViewProj);
    float4 world = D / D.w;
    float4 prev = mul(world, prevViewProj);
    prev /= prev.w;
    float2 vel = (H.xy - prev.xy) / 2.0;
    vel.y = -vel.y;
    float4 c = tex2D(frame, uv);
    float2 t = uv;
    for (int i = 1; i < numSamples; ++i)
    {
        t += vel / numSamples;
        c += tex2D(frame, t);
    }
    return c / numSamples;
}
