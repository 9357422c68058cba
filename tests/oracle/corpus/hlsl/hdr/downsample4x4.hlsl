// Quarter-size downsample: 16 taps averaged through offsets in a constant array.
sampler2D srcTex : register(s0);
float2 offsets[16] : register(c0);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 s = 0;
    for (int i = 0; i < 16; i++)
        s += tex2D(srcTex, uv + offsets[i]);
    return s * (1.0 / 16);
}
