// Point light shadow from a cube map storing distance to the light.
samplerCUBE distCube : register(s0);
float3 lightPosition;
float  lightRangeInv;
float3 lightCol;

float4 main(float3 wpos : TEXCOORD0, float3 wnrm : TEXCOORD1) : COLOR
{
    float3 toFrag = wpos - lightPosition;
    float dist = length(toFrag) * lightRangeInv;
    float stored = texCUBE(distCube, toFrag).r;
    float shadow = dist - 0.01 < stored;
    float ndl = saturate(dot(normalize(wnrm), -toFrag / length(toFrag)));
    return float4(lightCol * ndl * shadow * (1 - dist), 1);
}
