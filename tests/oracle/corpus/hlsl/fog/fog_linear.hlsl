// Linear distance fog.
sampler2D texDiffuse;
float4 fogColor;
float  fogStart = 10;
float  fogEnd = 200;

float4 main(float2 uv : TEXCOORD0, float dist : TEXCOORD1) : COLOR
{
    float f = saturate((fogEnd - dist) / (fogEnd - fogStart));
    float4 c = tex2D(texDiffuse, uv);
    return float4(lerp(fogColor.rgb, c.rgb, f), c.a);
}
