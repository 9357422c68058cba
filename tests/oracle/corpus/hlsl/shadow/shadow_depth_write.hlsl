// Shadow caster pass writing linear depth and its square (for VSM), with alpha test.
sampler2D alphaTex;
float alphaRef = 0.5;
float invFar;

float4 main(float2 uv : TEXCOORD0, float dist : TEXCOORD1) : COLOR
{
    clip(tex2D(alphaTex, uv).a - alphaRef);
    float d = dist * invFar;
    float dx = ddx(d), dy = ddy(d);
    return float4(d, d * d + 0.25 * (dx * dx + dy * dy), 0, 1);
}
