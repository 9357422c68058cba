// Video playback: three planes (Y, Cr, Cb) converted to RGB, alpha plane optional.
sampler2D texY  : register(s0);
sampler2D texCr : register(s1);
sampler2D texCb : register(s2);
sampler2D texA  : register(s3);
bool hasAlpha;
float4 tor = float4(1.595, -0.813, 0, 0);
float4 tog = float4(0, -0.391, 2.017, 0);
float4 consts = float4(1.164, 0.0625, 0.5, 0);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float y = (tex2D(texY, uv).r - consts.y) * consts.x;
    float cr = tex2D(texCr, uv).r - consts.z;
    float cb = tex2D(texCb, uv).r - consts.z;
    float4 c;
    c.r = y + tor.x * cr;
    c.g = y + tor.y * cr - 0.391 * cb;
    c.b = y + tog.z * cb;
    c.a = hasAlpha ? tex2D(texA, uv).r : 1;
    return c;
}
