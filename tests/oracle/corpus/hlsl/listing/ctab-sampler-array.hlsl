sampler2D s[4];
sampler2D t : register(s9);
float4 main(float2 uv : TEXCOORD0) : COLOR { return tex2D(s[0], uv) + tex2D(s[3], uv) + tex2D(t, uv); }
