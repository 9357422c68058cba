// Soft particles: fade where the sprite meets scene depth.
sampler2D particleTex : register(s0);
sampler2D sceneDepth  : register(s1);
float softness = 0.5;
float2 nearFar;

float LinearDepth(float z) { return nearFar.x * nearFar.y / (nearFar.y - z * (nearFar.y - nearFar.x)); }

float4 main(float2 uv : TEXCOORD0, float4 proj : TEXCOORD1, float4 vc : COLOR0) : COLOR
{
    float4 c = tex2D(particleTex, uv) * vc;
    float scene = LinearDepth(tex2Dproj(sceneDepth, proj).r);
    float self = LinearDepth(proj.z / proj.w);
    c.a *= saturate((scene - self) / softness);
    return c;
}
