float4 arr[8];
float4 main(float2 uv[4] : TEXCOORD0) : COLOR {
  float4 s = 0;
  [loop] for (int i = 0; i < 4; i++) s += arr[i+2] * abs(uv[i].x);
  return s;
}
