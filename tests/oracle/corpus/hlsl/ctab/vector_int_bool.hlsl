// int4 and bool4 uniforms, int2 and bool2 too, used as values (not as loop counts).
int4  iv;
int2  iv2;
bool4 bv;
bool2 bv2;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r = v * iv + float4(iv2, iv2);
    r = bv.x ? r : -r;
    r.xy += bv2.y ? 1 : 0;
    return r * (bv.w ? 2 : 1);
}
