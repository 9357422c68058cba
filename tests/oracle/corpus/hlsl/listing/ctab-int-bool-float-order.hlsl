float4 abcdefghijk;
float4 arr[20];
int n;
bool bb;
float4 main(float2 uv : TEXCOORD0) : COLOR { float4 s = 0; for (int i = 0; i < n; i++) s += arr[i]; if (bb) s += abcdefghijk; return s; }
