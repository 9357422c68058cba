float4 A_very_long_parameter_name_that_goes_on_and_on;
float4 b;
sampler2D Z_sampler_with_long_name;
float4 main(float2 uv : TEXCOORD0) : COLOR { return A_very_long_parameter_name_that_goes_on_and_on + b + tex2D(Z_sampler_with_long_name, uv); }
