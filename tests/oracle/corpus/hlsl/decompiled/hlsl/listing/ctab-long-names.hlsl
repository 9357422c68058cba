// ps_3_0 shader decompiled by ps30
float4 A_very_long_parameter_name_that_goes_on_and_on : register(c0);
float4 b : register(c1);
sampler2D Z_sampler_with_long_name : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = (A_very_long_parameter_name_that_goes_on_and_on + b) + tex2D(Z_sampler_with_long_name, texcoord0.xy);
    return oC0;
}
