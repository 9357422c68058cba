// Literal constants that exercise def formatting: tiny, huge, negative zero, thirds, pi.
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 a = v * float4(0.333333333, 3.14159265, 1e-7, 12345678.0);
    float4 b = v.wzyx * float4(-0.0, 0.1, 1e20, -2.5e-3);
    float4 c = v.yxwz * float4(0.7, 0.95, 1.0 / 3.0, 6.02214076e23);
    return a + b + c;
}
