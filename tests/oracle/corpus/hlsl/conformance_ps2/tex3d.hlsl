// oracle: target=ps_2_0
// ps_2_0 conformance: a volume-texture read at t7.xyz, the last texture coordinate.
sampler3D volume : register(s2);

float4 main(float3 t : TEXCOORD7) : COLOR
{
    return tex3D(volume, t);
}
