// oracle: target=ps_2_0
// A projected shadow map and a projected spot-light cookie (tex2Dproj), with a depth
// comparison against the shadow map's value and a bias read with tex2Dbias.
sampler2D shadowMap : register(s0);
sampler2D cookie : register(s1);
sampler2D albedo : register(s2);
float depthBias;
float mipBias;

float4 main(float4 shadowPos : TEXCOORD0, float4 cookiePos : TEXCOORD1, float2 uv : TEXCOORD2) : COLOR
{
    float stored = tex2Dproj(shadowMap, shadowPos).r;
    float lit = (shadowPos.z / shadowPos.w - depthBias <= stored) ? 1 : 0.3;
    float3 light = tex2Dproj(cookie, cookiePos).rgb;
    float4 a = tex2Dbias(albedo, float4(uv, 0, mipBias));
    return float4(a.rgb * light * lit, a.a);
}
