// One sampler of every type in one table, out of declaration order.
samplerCUBE cubeS : register(s3);
sampler1D   rampS;
sampler3D   volS;
sampler2D   flatS : register(s0);

float4 main(float4 t : TEXCOORD0) : COLOR
{
    return tex2D(flatS, t.xy) + tex1D(rampS, t.x) + tex3D(volS, t.xyz) + texCUBE(cubeS, t.xyz);
}
