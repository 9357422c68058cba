// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);
float4 c1 : register(c1);
float4 c3 : register(c3);
sampler2D s0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r3 = 0;
    r0.xy = texcoord0.xy;
    r0.zw = c0.z;
    r1.w = c3.w;
    r3.yzw = texcoord0.x * c1.zwz + c1.yzx;
    for (int n0 = 0; n0 < int4(120, 0, 0, 0).x; n0++) {
        [loop] for (int n1 = 0; n1 < 107; n1++) {
            r1.xyz = tex2D(s0, r0.xy).xyz;
            r3.x = log2(abs(dot(r1, c3)));
            r0.xw = r0.xw + r3.wx;
        }
        r0.xy = r0.xy * c1.zw + r3.zy;
    }
    oC0 = r0.w;
    return oC0;
}
