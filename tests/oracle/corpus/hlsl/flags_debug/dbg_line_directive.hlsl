// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information across #line directives: two file names and a line that goes back.
float4 a;
float4 b;
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 x = v * a;
#line 200 "other_file.hlsl"
    float4 y = x + b;
#line 50
    float4 z = y * y;
#line 12 "C:\flags_debug\dbg_line_directive.hlsl"
    float4 w = z - v;
    return w.wzyx;
}
