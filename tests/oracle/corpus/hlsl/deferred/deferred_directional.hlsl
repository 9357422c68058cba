// Full-screen directional light pass reading the G-buffer.
sampler2D gAlbedo : register(s0);
sampler2D gNormal : register(s1);
sampler2D gDepth  : register(s2);
float3 lightDirVS;
float3 lightColor;
float4x4 invProj;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 alb = tex2D(gAlbedo, uv);
    float3 n = tex2D(gNormal, uv).xyz * 2 - 1;
    float depth = tex2D(gDepth, uv).r;
    float4 clip = float4(uv.x * 2 - 1, 1 - uv.y * 2, depth, 1);
    float4 vp = mul(clip, invProj);
    vp /= vp.w;
    float3 v = normalize(-vp.xyz);
    float3 h = normalize(v + lightDirVS);
    float d = saturate(dot(n, lightDirVS));
    float s = pow(saturate(dot(n, h)), alb.a * 255) * d;
    return float4(lightColor * (alb.rgb * d + s), 1);
}
