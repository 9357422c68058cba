// Cel shading: lighting term looked up in a 1D ramp, rim from the view vector.
sampler1D rampTex;
sampler2D colorTex;
float3 lightDirWS;
float3 viewPos;
float4 rimColor;

float4 main(float2 uv : TEXCOORD0, float3 pos : TEXCOORD1, float3 nrm : TEXCOORD2) : COLOR
{
    float3 n = normalize(nrm);
    float3 v = normalize(viewPos - pos);
    float d = dot(n, lightDirWS) * 0.5 + 0.5;
    float3 ramp = tex1D(rampTex, d).rgb;
    float rim = step(0.7, 1 - saturate(dot(n, v)));
    return float4(tex2D(colorTex, uv).rgb * ramp + rimColor.rgb * rim * rimColor.a, 1);
}
