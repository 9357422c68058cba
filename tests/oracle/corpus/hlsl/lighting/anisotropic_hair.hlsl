// Kajiya-Kay style hair highlight along the tangent, with a shift texture.
sampler2D hairDiffuse;
sampler2D hairShift;
float3 lightVec;
float3 eyeVec;
float primaryShift = 0.1;
float specExp1 = 80;
float specExp2 = 12;

float StrandSpec(float3 T, float3 H, float e)
{
    float th = dot(T, H);
    float sinTH = sqrt(1 - th * th);
    float dirAtten = smoothstep(-1, 0, th);
    return dirAtten * pow(sinTH, e);
}

float4 main(float2 uv : TEXCOORD0, float3 T : TEXCOORD1, float3 N : TEXCOORD2) : COLOR
{
    float shift = tex2D(hairShift, uv).r - 0.5;
    float3 t1 = normalize(T + N * (primaryShift + shift));
    float3 t2 = normalize(T + N * (primaryShift * -2 + shift));
    float3 H = normalize(lightVec + eyeVec);
    float s = StrandSpec(t1, H, specExp1) + 0.5 * StrandSpec(t2, H, specExp2);
    float4 base = tex2D(hairDiffuse, uv);
    return float4(base.rgb * saturate(dot(N, lightVec)) + s, base.a);
}
