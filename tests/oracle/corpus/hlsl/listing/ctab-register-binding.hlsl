float4 c : register(c5);
float4 main(float2 uv : TEXCOORD0) : COLOR { return c * uv.x + 0.95; }
