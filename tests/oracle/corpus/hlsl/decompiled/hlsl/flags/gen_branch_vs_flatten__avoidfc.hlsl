// ps_3_0 shader decompiled by ps30
float k : register(c0);
sampler2D a : register(s0);
sampler2D b : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = k - texcoord1.x;
    if (k < texcoord1.x) {
        r1 = tex2Dlod(a, (float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx));
    } else {
        r2 = float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx;
        r1 = tex2Dlod(b, r2);
    }
    r0.yz = texcoord0.xy + texcoord0.xy;
    r2 = tex2D(a, r0.yz);
    r3 = tex2D(b, r0.yz);
    oC0 = (r0.x >= 0.0 ? r3 : r2) + r1;
    return oC0;
}
