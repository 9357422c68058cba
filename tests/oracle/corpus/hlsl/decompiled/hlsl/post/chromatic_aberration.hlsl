// ps_3_0 shader decompiled by ps30
float caStrength : register(c0);
float frame : register(c2);
float grainAmount : register(c1);
float scanlines : register(c3);
sampler2D image : register(s0);
sampler2D grain : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xy = float2(0.37, 0.71) * frame;
    r0.xy = vpos * 0.015625 + frac(r0.xy);
    r0.x = tex2D(grain, r0.xy).x - 0.5;
    r1 = tex2D(image, texcoord0.xy);
    r0.yz = texcoord0.xy - 0.5;
    r2.xy = r0.yz * caStrength + texcoord0.xy;
    r1.z = tex2D(image, (r0.yz * -caStrength + texcoord0.xy)).z;
    r1.x = tex2D(image, r2.xy).x;
    r0.xyz = r0.x * grainAmount + r1.xyz;
    r0.w = frac(abs((0.5 * vpos.y)));
    r0.w = vpos.y >= 0.0 ? r0.w : -r0.w;
    r0.w = (r0.w - 0.5) >= 0.0 ? 1.0 : (1.0 - scanlines);
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
