// Heat haze / refraction distortion using a scrolling bump and a mask.
sampler2D backbuffer : register(s0);
sampler2D bumpTex    : register(s1);
sampler2D maskTex    : register(s2);
float4 params;       // x strength, y time, z tiling

float4 main(float2 uv : TEXCOORD0, float4 proj : TEXCOORD1) : COLOR
{
    float2 b = tex2D(bumpTex, uv * params.z + float2(0, params.y)).xy * 2 - 1;
    float m = tex2D(maskTex, uv).r;
    float2 s = proj.xy / proj.w + b * params.x * m;
    return tex2D(backbuffer, s);
}
