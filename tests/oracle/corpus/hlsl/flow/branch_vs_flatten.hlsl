// The same choice made twice: once [branch], once [flatten].
sampler2D a : register(s0);
sampler2D b : register(s1);
float k;

float4 main(float2 uv : TEXCOORD0, float sel : TEXCOORD1) : COLOR
{
    float4 r1, r2;
    [branch] if (sel > k) r1 = tex2Dlod(a, float4(uv, 0, 0)); else r1 = tex2Dlod(b, float4(uv, 0, 0));
    [flatten] if (sel > k) r2 = tex2D(a, uv * 2); else r2 = tex2D(b, uv * 2);
    return r1 + r2;
}
