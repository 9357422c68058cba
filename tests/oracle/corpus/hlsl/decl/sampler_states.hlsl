// Effect-style sampler_state blocks and texture objects (ignored by D3DCompile for the shader,
// but present in real game sources).
texture DiffuseTexture;
sampler2D DiffuseSampler = sampler_state
{
    Texture = <DiffuseTexture>;
    MinFilter = Linear; MagFilter = Linear; MipFilter = Linear;
    AddressU = Wrap; AddressV = Wrap;
};
texture EnvTexture;
samplerCUBE EnvSampler = sampler_state { Texture = <EnvTexture>; };

float4 main(float2 uv : TEXCOORD0, float3 r : TEXCOORD1) : COLOR
{
    return tex2D(DiffuseSampler, uv) + texCUBE(EnvSampler, r) * 0.25;
}
