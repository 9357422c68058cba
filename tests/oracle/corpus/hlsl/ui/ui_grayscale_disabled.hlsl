// Button: greys out when disabled (bool uniform), highlights on hover.
sampler2D buttonTex;
bool  disabled;
float hover;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = tex2D(buttonTex, uv);
    if (disabled)
        c.rgb = dot(c.rgb, float3(0.3, 0.59, 0.11)) * 0.6;
    else
        c.rgb += hover * 0.15;
    return c;
}
