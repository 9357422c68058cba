// Element and row access: _m00 style, [row][col], and swizzles of matrix members.
float4x4 proj;
row_major float3x4 rm3x4;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float a = proj._m00 * v.x + proj._11 * v.y;
    float4 row2 = proj[2];
    float3 diag = proj._m00_m11_m22;
    float b = rm3x4[1][3];
    return float4(a, b, dot(row2, v), 0) + diag.xyzz + rm3x4[0];
}
