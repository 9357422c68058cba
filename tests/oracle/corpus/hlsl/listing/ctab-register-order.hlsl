struct S { float4 a; sampler2D smp; };
float4 x[2] : register(c3);
float4 y : register(c0);
float4 main(float2 uv : TEXCOORD0) : COLOR { return x[1] + y; }
