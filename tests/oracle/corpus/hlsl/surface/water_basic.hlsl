// Water: two scrolling normal maps, reflection and refraction textures, fresnel mix.
sampler2D WaveNormals    : register(s0);
sampler2D ReflectionRT   : register(s1);
sampler2D RefractionRT   : register(s2);
float  Time;
float2 WaveDir0 = float2(0.03, 0.01);
float2 WaveDir1 = float2(-0.02, 0.025);
float  Distortion = 0.02;
float3 WaterTint;
float3 SunDirection;
float3 CameraPos;

float4 main(float2 uv : TEXCOORD0, float4 clipPos : TEXCOORD1, float3 worldPos : TEXCOORD2) : COLOR
{
    float3 n0 = tex2D(WaveNormals, uv + WaveDir0 * Time).xzy * 2 - 1;
    float3 n1 = tex2D(WaveNormals, uv * 1.7 + WaveDir1 * Time).xzy * 2 - 1;
    float3 n = normalize(n0 + n1);

    float2 screen = clipPos.xy / clipPos.w * float2(0.5, -0.5) + 0.5;
    float2 offs = n.xz * Distortion;
    float3 refl = tex2D(ReflectionRT, screen + offs).rgb;
    float3 refr = tex2D(RefractionRT, screen - offs).rgb * WaterTint;

    float3 V = normalize(CameraPos - worldPos);
    float fresnel = 0.02 + 0.98 * pow(1 - saturate(dot(V, n)), 5);
    float3 H = normalize(V + SunDirection);
    float spec = pow(saturate(dot(n, H)), 256) * 4;
    return float4(lerp(refr, refl, fresnel) + spec, 1);
}
