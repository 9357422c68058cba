// ps_3_0 shader decompiled by ps30
float focusDist : register(c0);
float focusRange : register(c1);
float maxCoC : register(c2);
float2 texSize : register(c3);
sampler2D colorSamp : register(s0);
sampler2D depthSamp : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r1.x = tex2D(depthSamp, texcoord0.xy).x - focusDist;
    r1.y = 1.0 / focusRange;
    r1.x = saturate(r1.y * abs(r1.x));
    r1 = (r1.x * maxCoC) * texSize.xyxy;
    r2 = r1.zwzw * float4(-0.326, -0.406, -0.84, -0.074) + texcoord0.xyxy;
    r3 = tex2D(colorSamp, r2.xy);
    r0 = tex2D(colorSamp, r2.zw) + (tex2D(colorSamp, texcoord0.xy) + r3);
    r2 = r1.zwzw * float4(-0.696, 0.457, -0.203, 0.621) + texcoord0.xyxy;
    r3 = tex2D(colorSamp, r2.xy);
    r0 = tex2D(colorSamp, r2.zw) + (r0 + r3);
    r2 = r1.zwzw * float4(0.962, -0.195, 0.473, -0.48) + texcoord0.xyxy;
    r3 = tex2D(colorSamp, r2.xy);
    r0 = tex2D(colorSamp, r2.zw) + (r0 + r3);
    r2 = r1.zwzw * float4(0.519, 0.767, 0.185, -0.893) + texcoord0.xyxy;
    r3 = tex2D(colorSamp, r2.xy);
    r0 = tex2D(colorSamp, r2.zw) + (r0 + r3);
    r2 = r1.zwzw * float4(0.507, 0.064, 0.896, 0.412) + texcoord0.xyxy;
    r1 = r1 * float4(-0.322, -0.933, -0.792, -0.598) + texcoord0.xyxy;
    r3 = tex2D(colorSamp, r2.xy);
    r0 = tex2D(colorSamp, r2.zw) + (r0 + r3);
    r2 = tex2D(colorSamp, r1.xy);
    r0 = r0 + r2;
    oC0 = (tex2D(colorSamp, r1.zw) + r0) * 0.07692308;
    return oC0;
}
