// Uniform parameters of main (uniform keyword) rather than globals.
float4 main(float2 uv : TEXCOORD0,
            uniform sampler2D img,
            uniform float4 scale,
            uniform float bias) : COLOR
{
    return tex2D(img, uv) * scale + bias;
}
