bool bb;
float4 main(float2 uv : TEXCOORD0) : COLOR { float4 s = uv.xyxy * bb; [branch] if (bb) s += 1; return s; }
