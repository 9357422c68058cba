// oracle: target=ps_2_0
// A lightmapped surface: base texture times a lightmap on the second coordinate set, with
// the vertex colour as tint and a detail texture at a scaled coordinate.
sampler2D baseMap : register(s0);
sampler2D lightMap : register(s1);
sampler2D detailMap : register(s2);
float detailScale;
float4 ambient;

float4 main(float2 uv : TEXCOORD0, float2 luv : TEXCOORD1, float4 tint : COLOR0) : COLOR
{
    float4 base = tex2D(baseMap, uv);
    float3 light = tex2D(lightMap, luv).rgb * 2 + ambient.rgb;
    float3 detail = tex2D(detailMap, uv * detailScale).rgb * 2;
    return float4(base.rgb * light * detail * tint.rgb, base.a * tint.a);
}
