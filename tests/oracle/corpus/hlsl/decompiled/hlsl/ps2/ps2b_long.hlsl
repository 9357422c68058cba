// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
float4 curve[4] : register(c0);
float exposure : register(c4);
sampler2D hdr : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(hdr, texcoord0.xy);
    r1.xyz = r0.xyz * exposure;
    r0.w = 1.0;
    r0.xyz = r0.xyz * exposure + r0.w;
    r2.x = 1.0 / r0.x;
    r2.y = 1.0 / r0.y;
    r2.z = 1.0 / r0.z;
    r0.xyz = r1.xyz * r2.xyz;
    r1.xyz = curve[0].xyz * r0.xyz + curve[1].xyz;
    r0.xyz = (r1.xyz * r0.xyz + curve[2].xyz) * r0.xyz + curve[3].xyz;
    r1.y = sin((dot(texcoord0.xy, float2(12.9898, 78.233)) + 0.0));
    r0.w = frac((r1.y * 43758.547));
    r1.xyz = r0.xyz * 1.0 + (r0.w * 0.001);
    r0.xyz = r0.xyz * 0.03;
    [loop] for (int n0 = 0; n0 < 4; n0++) {
        r1.xyz = r0.w * 0.001 + (r1.xyz * 0.97 + r0.xyz);
    }
    r0.xyz = r1.xyz * 0.97 + r0.xyz;
    r0.xyz = saturate(r0.w * 0.001 + r0.xyz);
    r0.w = 1.0;
    oC0 = r0;
    return oC0;
}
