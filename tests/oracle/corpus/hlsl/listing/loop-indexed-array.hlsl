float4 arr[8];
int n;
float4 main(float2 uv : TEXCOORD0) : COLOR {
  float4 s = 0;
  [loop] for (int i = 0; i < 8; i++) s += arr[i] * uv.x;
  return s;
}
