// Decal depth nudge: output depth from SV-less interpolant with a bias.
sampler2D decalTex;
float depthBias;

void main(float2 uv : TEXCOORD0, float4 pos : TEXCOORD1, out float4 col : COLOR0, out float z : DEPTH)
{
    col = tex2D(decalTex, uv);
    z = saturate(pos.z / pos.w - depthBias);
}
