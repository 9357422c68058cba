float4 main(float2 uv : TEXCOORD0) : COLOR { return uv.xyxy * 1e-10 + float4(1e20, -0.5, 123456789, 3.14159265); }
