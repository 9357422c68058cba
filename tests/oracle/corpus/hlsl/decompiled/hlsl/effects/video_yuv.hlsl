// ps_3_0 shader decompiled by ps30
float4 consts : register(c3);
float4 hasAlpha : register(c0); // the table's type: bool
float4 tog : register(c2);
float4 tor : register(c1);
sampler2D texY : register(s0);
sampler2D texCr : register(s1);
sampler2D texCb : register(s2);
sampler2D texA : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = (tex2D(texCr, texcoord0.xy).x - consts.z) * tor.xy;
    r0.z = tex2D(texY, texcoord0.xy).x - consts.y;
    oC0.x = r0.z * consts.x + r0.x;
    r0.x = r0.z * consts.x + r0.y;
    r0.y = r0.z * consts.x;
    r0.z = tex2D(texCb, texcoord0.xy).x - consts.z;
    oC0.y = r0.z * -0.391 + r0.x;
    oC0.z = tog.z * r0.z + r0.y;
    r0 = tex2D(texA, texcoord0.xy);
    r0.y = 1.0;
    oC0.w = -hasAlpha.x >= 0.0 ? r0.y : r0.x;
    return oC0;
}
