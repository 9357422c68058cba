int4 ii : register(i3);
bool b1 : register(b5);
float4 main(float2 uv : TEXCOORD0) : COLOR { float4 s = 0; [loop] for (int i = 0; i < ii.x; i++) s += uv.x; if (b1) s = 1; return s; }
