// ps_3_0 shader decompiled by ps30
float4 alphaTest : register(c0); // the table's type: bool
float4 constantColor : register(c1);
float ref : register(c2);
bool hasTexture : register(b0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    if (hasTexture) {
        r0 = tex2D(s, texcoord0.xy);
        r1 = r0 * color0;
        r0 = (r0.w * color0.w - ref) * alphaTest.x;
        clip(r0);
        oC0 = r1;
    } else {
        oC0 = constantColor * color0;
    }
    return oC0;
}
