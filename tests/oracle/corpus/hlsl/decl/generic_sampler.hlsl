// The untyped 'sampler' keyword used with tex2D and texCUBE (type inferred from use).
sampler s2d;
sampler sCube;
sampler sVol;

float4 main(float2 uv : TEXCOORD0, float3 d : TEXCOORD1) : COLOR
{
    return tex2D(s2d, uv) + texCUBE(sCube, d) + tex3D(sVol, d);
}
