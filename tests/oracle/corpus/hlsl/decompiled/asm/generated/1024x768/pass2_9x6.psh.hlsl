// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);
float4 c1 : register(c1);
sampler2D s0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r3 = 0;
    r0.xy = texcoord0.xy;
    r0.zw = c0.z;
    r3.yzw = texcoord0.x * c1.zwz + c1.yzx;
    [loop] for (int n0 = 0; n0 < 6; n0++) {
        [loop] for (int n1 = 0; n1 < 9; n1++) {
            r3.x = tex2D(s0, r0.xy).x;
            r0.xw = r0.xw + r3.wx;
        }
        r0.xy = r0.xy * c1.zw + r3.zy;
    }
    r0.x = r0.w * c0.x + c0.y;
    oC0 = exp2(r0.x);
    return oC0;
}
