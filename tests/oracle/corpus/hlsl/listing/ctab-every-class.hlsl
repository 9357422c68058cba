float4 g_Color;
float g_fKey = 0.18;
float3x3 g_M33;
row_major float4x4 g_RowMat;
float4x3 g_M43;
float4 g_Arr[3];
sampler2D s2d;
samplerCUBE scube;
sampler3D s3d;
sampler1D s1d;
bool g_b;
int g_i;
struct S { float4 a; float2 b; } g_s;
float4 main(float2 uv : TEXCOORD0, float3 n : TEXCOORD1_centroid, float4 col : COLOR0) : COLOR0 {
  float4 r = tex2D(s2d, uv) * g_Color + g_fKey;
  r.xyz += mul(n, g_M33) + mul(float4(n,1), g_RowMat).xyz + mul(float4(n,1), g_M43);
  r += g_Arr[(int)uv.x] + texCUBE(scube, n) + tex3D(s3d, n) + tex1D(s1d, uv.x);
  if (g_b) r *= g_i;
  r += g_s.a + g_s.b.xyxy;
  return r * col;
}
