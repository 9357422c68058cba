// Nested static branches with else arms.
bool hasTexture;
bool alphaTest;
sampler2D s;
float4 constantColor;
float ref;

float4 main(float2 uv : TEXCOORD0, float4 vcol : COLOR0) : COLOR
{
    float4 c;
    if (hasTexture)
    {
        c = tex2D(s, uv) * vcol;
        if (alphaTest)
            clip(c.a - ref);
    }
    else
        c = constantColor * vcol;
    return c;
}
