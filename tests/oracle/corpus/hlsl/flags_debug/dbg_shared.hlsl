// oracle: flags=DEBUG
// Debug information when several variables name the same instruction.
float4 k;
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float x = v.x * k.x;
    float y = x;
    float z = y;
    float4 w = float4(x, y, z, 1);
    float4 u = w;
    return u;
}
