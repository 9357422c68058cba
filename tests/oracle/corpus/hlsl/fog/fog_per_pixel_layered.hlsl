// Distance fog with a scrolling noise layer and sky blend at the far plane.
sampler2D sceneRT  : register(s0);
sampler2D depthRT  : register(s1);
sampler2D noiseTex : register(s2);
samplerCUBE skyCube : register(s3);
float4 fogParams;      // x start, y 1/(end-start), z noise scale, w time
float3 fogCol;
float3 camRight, camUp, camFwd;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float z = tex2D(depthRT, uv).r;
    float n = tex2D(noiseTex, uv * fogParams.z + fogParams.w * float2(0.01, 0.003)).r;
    float f = saturate((z - fogParams.x) * fogParams.y) * (0.8 + 0.4 * n);
    float3 dir = camFwd + (uv.x * 2 - 1) * camRight + (1 - uv.y * 2) * camUp;
    float3 sky = texCUBE(skyCube, dir).rgb;
    float3 far = z > 0.999 ? sky : fogCol;
    return float4(lerp(tex2D(sceneRT, uv).rgb, far, f), 1);
}
