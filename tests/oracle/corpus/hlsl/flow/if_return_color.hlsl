// Early return from an if: the compiler writes oC0 in both arms of a branch.
float4 colorA : register(c1);
float4 colorB : register(c2);
float threshold;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    [branch]
    if (uv.x < threshold)
        return colorA;
    return colorB;
}
